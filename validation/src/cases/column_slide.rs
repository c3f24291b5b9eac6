//! A jointed column driven by a boundary load (issue 48): the upper block's slide on a joint at
//! 35° and 40° in every block mode, against the rigid-block closed form.

use std::fmt::Write as _;

use adit::scene::BlockMode;

use crate::case::{Case, Context, Section, print_row, table, verdict};
use crate::column_slide::{Start, run};

/// Joint angle and friction, degrees.
const ANGLES: [(f64, f64); 2] = [(35.0, 30.0), (40.0, 35.0)];
/// Zone size, m, and simulated time, s.
const EDGE: f64 = 0.1;
const DURATION: f64 = 0.1;
/// Bar (issue 48): the slide within 3 % of the closed form, damped.
const BAR: f64 = 0.03;

pub struct ColumnSlide;

impl Case for ColumnSlide {
    fn name(&self) -> &'static str {
        "column_slide"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let (mut barred, mut undamped, mut missed) = (Vec::new(), Vec::new(), Vec::new());
        for angles in ANGLES {
            for mode in [BlockMode::Rigid, BlockMode::Simple, BlockMode::Deformable] {
                for start in [Start::Settled, Start::FromRest] {
                    let r = run(angles, start, true, DURATION, EDGE, mode)?;
                    print_row(&r);
                    if r.errors["slide"] > BAR {
                        missed.push(format!("{}: {:.2e}", r.case, r.errors["slide"]));
                    }
                    barred.push(r);
                }
                let r = run(angles, Start::Settled, false, DURATION, EDGE, mode)?;
                print_row(&r);
                undamped.push(r);
            }
        }
        let mut md = String::new();
        let _ = writeln!(
            md,
            "\n## Jointed rock: a column driven by a boundary load (issue 48)\n"
        );
        let _ = writeln!(
            md,
            "A 1 m × 2 m column (ρ = 2 500 kg/m³) on a fixed base, cut through its centre by one \
             joint at α (kn = ks = 1e10 Pa/m, no cohesion), loaded by 1 MPa on its top and by its \
             weight, both blocks in one mode (`validation/src/column_slide.rs`). With φ < α the \
             upper block slides down the joint as a rigid body, s(t) = ½ a t², a = (P + W)(sin α − \
             cos α tan φ)/m, without rotating: the reaction's resultant lies 0.08 m from the joint's \
             centre at 35°, within its 0.61 m half-length. Solved dynamically for {DURATION} s \
             (a slide of about 0.2 m), the block either settled first on a joint that holds \
             (φ = 80°) and then released, or started from rest on an unstressed joint with the \
             load applied at once. Errors: `slide`, the largest |s_h − s| over 20 samples over s \
             at the end (s_h the mean displacement of the block's nodes along the joint); `final` \
             the same at the end, signed; `rotation`, the top edge's largest rotation times its \
             half-width over s. Damped: stiffness-proportional Rayleigh damping, ξ = 5 % at the \
             frequency of the block bouncing on its joint (√(kn L/m)/2π, about 330 Hz), which does \
             not resist the rigid slide.\n"
        );
        table(&mut md, &barred);
        let _ = writeln!(
            md,
            "\nBar (issue 48): every mode at both angles within {} % of the closed form: {}.\n\n\
             Undamped, after the same settle: the rigid block slides as the closed form; at 35° \
             simple and deformable blocks, and at 40° the deformable one, slide further, and \
             further the longer they slide (at 35°, \
             simple 6 % after 0.05 s, 18 % after 0.1 s, 29 % after 0.15 s; deformable 15 %, 33 %, \
             39 %), the same with the time step halved and quartered (deformable after 0.05 s: \
             15.3 %, 15.1 %, 15.1 %): their steady sliding is unstable, a vibration of the block on \
             its joint growing as it slides and lowering the mean friction (friction-induced \
             flutter, as on the incline above), which the rigid closed form excludes and the 5 % \
             damping removes. Issue 48 reported the opposite: the rigid block 57 % too far, \
             rotating 7 mrad, with deformable and simple blocks within 3–7 %; that scene is not \
             in the repository, and this one, written from its description, does not reproduce \
             it (rigid: 0.07 % settled, 1.7–3.1 % from rest undamped, and a rotation of 2e-4 of \
             the slide).\n",
            100.0 * BAR,
            verdict(&missed)
        );
        table(&mut md, &undamped);
        let mut rows = barred;
        rows.extend(undamped);
        Ok(Section {
            markdown: md,
            rows,
            missed,
            ..Default::default()
        })
    }
}
