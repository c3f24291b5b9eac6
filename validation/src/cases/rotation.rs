//! Large rotation: a spinning block and a prestressed block turned by 90°.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::report::CaseReport;
use crate::rotation;

pub struct Rotation;

impl Case for Rotation {
    fn name(&self) -> &'static str {
        "rotation"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let rotation_cases: Vec<CaseReport> = vec![
            rotation::spin(true, 3.0)?.report(),
            rotation::spin(false, 0.25)?.report(),
            rotation::turned(true)?.report(),
            rotation::turned(false)?.report(),
        ];
        for r in &rotation_cases {
            print_row(r);
        }
        let _ = writeln!(md, "\n## Stability: large rotation (issue 5)\n");
        let _ = writeln!(
            md,
            "A 1 m square of soft rock (E = 1 MPa, ρ = 1000 kg/m³, zones of 0.2 m), dynamic and undamped, \
         started spinning at 1 rad/s: it should carry only its centripetal stress, below 2ρω²r² = 1 kPa \
         (a thousandth of E), and keep its shape. The same block prestressed by σxx = −1 kPa and turned \
         by 90° in 400 steps should carry σyy = −1 kPa, σxx = σxy = 0; `stress` is the largest departure \
         over 1 kPa (`validation/src/rotation.rs`). Small-strain zones fail both, as they must: they read \
         the spin as no strain (the nodes fly off along their tangents) and the quarter turn as a \
         compressive strain of 1.\n"
        );
        table(&mut md, &rotation_cases);
        Ok(Section {
            markdown: md,
            rows: rotation_cases,

            ..Default::default()
        })
    }
}
