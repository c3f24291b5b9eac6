//! A grouted bolt pulled out of a block against the shear-lag solution.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::plot::{Curve, curves};
use crate::pullout;
use plotters::style::RGBColor;

pub struct Pullout;

impl Case for Pullout {
    fn name(&self) -> &'static str {
        "pullout"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let root = &cx.root;
        let mut md = String::new();
        let mut pullout_cases = Vec::new();
        let mut profiles = Vec::new();
        for (fraction, segment) in [(0.25, 0.1), (0.6, 0.1), (0.25, 0.05), (0.6, 0.05)] {
            let (r, profile) = pullout::run(fraction, segment)?;
            pullout_cases.push(r);
            if segment == 0.1 {
                profiles.push((fraction, profile));
            }
        }
        for r in &pullout_cases {
            print_row(r);
        }
        let (blue, red) = (RGBColor(31, 119, 180), RGBColor(214, 39, 40));
        let pull_curves: Vec<Curve> = profiles
            .iter()
            .zip([blue, red])
            .flat_map(|((fraction, profile), color)| {
                let pts = |f: fn(&pullout::ProfilePoint) -> f64| {
                    profile.iter().map(|p| (p.x, f(p))).collect::<Vec<_>>()
                };
                [
                    Curve {
                        label: format!("shear-lag, {:.0} % of s·L", 100.0 * fraction),
                        points: pts(|p| p.exact),
                        color,
                        dots: false,
                    },
                    Curve {
                        label: format!("adit, {:.0} % of s·L", 100.0 * fraction),
                        points: pts(|p| p.computed),
                        color,
                        dots: true,
                    },
                ]
            })
            .collect();
        curves(
            &root.join("docs/img/bolt_pullout.png"),
            "grouted bolt pulled out of a block",
            ("distance from the head (m)", "axial force (N/m)"),
            &pull_curves,
        )?;
        let _ = writeln!(md, "\n## Supports: grouted bolt pull-out\n");
        let _ = writeln!(
            md,
            "A 3 m bolt (EA = 98 MN, grout k = 100 MN/m/m, bond strength s = 50 kN/m) grouted into a block that \
         hardly moves (E = 1000 GPa, outline fixed), pulled at its head, against the shear-lag solution \
         N(x) = P sinh(λ(L−x))/sinh(λL), λ = √(k/EA), and, once the grout slips at the head \
         (P > s tanh(λL)/λ = {:.1} kN), the slipped length a with (P − s a) λ coth(λ(L−a)) = s. `axial`: \
         largest |N_h − N| over the segments relative to P. Beyond s·L the bolt pulls out \
         (`the_bolt_pulls_out_beyond_its_bond_capacity` in `validation/src/pullout.rs`). A bolt across an open \
         joint carries the block hanging on it to 3 % (`tests/engine/supports.rs`).\n",
            pullout::CASE.first_slip() / 1e3
        );
        table(&mut md, &pullout_cases);
        let _ = writeln!(
            md,
            "\n![axial force along the bolt, computed and closed form](img/bolt_pullout.png)\n"
        );
        Ok(Section {
            markdown: md,
            rows: pullout_cases,

            ..Default::default()
        })
    }
}
