//! Direct shear of a Coulomb joint and of a continuously yielding one.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::direct_shear;

pub struct DirectShear;

impl Case for DirectShear {
    fn name(&self) -> &'static str {
        "direct_shear"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let shear = direct_shear::run(0.0625)?;
        print_row(&shear);
        let yielding = direct_shear::run_yielding(0.0625)?;
        print_row(&yielding);
        let _ = writeln!(md, "\n## Jointed rock: direct shear\n");
        let _ = writeln!(
            md,
            "A 1 m × 0.5 m block on a longer fixed block, joined by a Coulomb joint (kn = 1e10 Pa/m, \
         ks = 1e9 Pa/m, c = 0.2 MPa, φ = 30°, ψ = 5°), under σn = 1 MPa on its top and driven sideways \
         without rotating (a guided shear box) to 3 mm. Errors: peak shear stress against c + σn tan φ, \
         residual against σn tan φ (cohesion is lost once the joint fails), pre-peak secant stiffness \
         against ks (the blocks' own elasticity is in series), and the rise of the block per unit slip \
         against tan ψ. The coarse twin of `cargo test` (zones of 0.125 m) is within 2 % on peak, residual and stiffness and \
         5 % low on the dilation rate: the contacts at the two ends of the joint, which lose and gain partners as the block moves, \
         dilate less, and weigh more on a coarse mesh.\n"
        );
        table(&mut md, std::slice::from_ref(&shear));
        let _ = writeln!(
            md,
            "\nThe same test with a continuously yielding joint (Cundall & Hart 1984; kn = 1e10, ks = 1e9 Pa/m, \
         φ = φm0 = 30°, so the asperities do not wear): under constant σn its average shear stress must follow \
         τ = τm (1 − exp(−ks u/τm)), τm = σn tan φ, against the joint's mean slip u. `shear_curve` is the \
         largest deviation over the curve relative to τm (3.1 % on the coarse twin of `cargo test`, zones of \
         0.125 m: the end contacts lag).\n"
        );
        table(&mut md, std::slice::from_ref(&yielding));
        Ok(Section {
            markdown: md,
            rows: vec![shear, yielding],

            ..Default::default()
        })
    }
}
