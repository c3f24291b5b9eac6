//! Patch tests and uniaxial compression: every zone must follow a linear field to round-off.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::patch;

pub struct Patch;

impl Case for Patch {
    fn name(&self) -> &'static str {
        "patch"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let patches = vec![
            patch::linear_displacement(0.1)?,
            patch::uniform_stress(0.1)?,
            patch::uniaxial(0.25)?,
        ];
        for r in &patches {
            print_row(r);
        }
        let _ = writeln!(md, "## Patch tests and uniaxial compression\n");
        let _ = writeln!(
            md,
            "On an irregular pentagon mesh: boundary nodes driven along a linear displacement field (interior nodes \
         and zone stresses must follow it), and a uniform stress applied as boundary traction (every zone must \
         carry it). One square block in plane-strain uniaxial compression against Hooke's law. All must hold to \
         round-off.\n"
        );
        table(&mut md, &patches);
        Ok(Section {
            markdown: md,
            rows: patches,

            ..Default::default()
        })
    }
}
