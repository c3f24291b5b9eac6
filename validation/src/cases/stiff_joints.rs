//! Stiff joints between soft blocks: the stress and settlement of nine blocks under load.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::report::CaseReport;
use crate::stiff_joints;

pub struct StiffJoints;

impl Case for StiffJoints {
    fn name(&self) -> &'static str {
        "stiff_joints"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let stiff_cases: Vec<CaseReport> = [
            (100.0, "coulomb"),
            (100.0, "glued"),
            (1000.0, "coulomb"),
            (1000.0, "glued"),
        ]
        .iter()
        .map(|&(r, law)| stiff_joints::run(r, law))
        .collect::<anyhow::Result<_>>()?;
        for r in &stiff_cases {
            print_row(r);
        }
        let _ = writeln!(md, "\n## Stability: stiff joints, soft blocks (issue 5)\n");
        let _ = writeln!(
            md,
            "A 2 m square cut into nine blocks by joints every 2/3 m (zones of 0.2 m, E = 10 GPa, so \
         E/h = 5e10 Pa/m) under 1 MPa on top, with joint normal stiffness 100× and 1000× E/h, Coulomb \
         (friction 45°, no slip) or glued. Exact: uniform σyy = −1 MPa, and a top settlement of \
         σH(1 − ν²)/E + 2σ/kn. The Gershgorin step includes the contact springs (the limiting node sits on \
         a joint); the stiffer the joints, the more cycles the mass-scaled solve needs. `stress`: largest \
         zone deviation over 1 MPa (the zones beside joint crossings); `settlement`: relative error.\n"
        );
        table(&mut md, &stiff_cases);
        Ok(Section {
            markdown: md,
            rows: stiff_cases,

            ..Default::default()
        })
    }
}
