//! Near-incompressible rock: Lamé's cylinder and Kirsch's hole as ν → 0.5, plain and mixed zones.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::incompressible;
use crate::kirsch_case::KirschResult;

pub struct Incompressible;

impl Case for Incompressible {
    fn name(&self) -> &'static str {
        "incompressible"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let mut incompressible_cases = Vec::new();
        for nu in [0.45, 0.49, 0.499] {
            for mixed in [false, true] {
                incompressible_cases.push(incompressible::run(nu, mixed, 0.06)?);
            }
        }
        let kirsch_nu: Vec<KirschResult> = [0.45, 0.49, 0.499]
            .iter()
            .flat_map(|&nu| [(nu, false), (nu, true)])
            .map(|(nu, mixed)| incompressible::kirsch(nu, mixed, 1.0))
            .collect::<anyhow::Result<_>>()?;
        for r in &incompressible_cases {
            print_row(r);
        }
        for r in &kirsch_nu {
            print_row(&r.report());
        }
        let _ = writeln!(md, "\n## Stability: near-incompressible rock (issue 5)\n");
        let _ = writeln!(
            md,
            "A thick cylinder (a = 1 m, b = 2 m, E = 1 GPa) under 1 MPa of internal pressure, against Lamé's \
         plane-strain solution; `bore_displacement`: mean radial displacement of the bore relative to the \
         closed form. Plain constant-strain triangles lock as ν → 0.5; with `zoning.mixed` each zone takes \
         the volumetric strain averaged over its nodes' patches (average nodal pressure triangle). The \
         cycles grow with the bulk-to-shear ratio (the explicit scheme's price for near-incompressibility).\n"
        );
        table(&mut md, &incompressible_cases);
        let _ = writeln!(
            md,
            "\nThe Kirsch problem (shipped model, exact Kirsch traction on the outer \
         boundary) at the same ν, errors as in the Kirsch section: the stresses do not depend on ν, so \
         plain triangles' growing error is locking alone.\n"
        );
        table(
            &mut md,
            &kirsch_nu
                .iter()
                .map(KirschResult::report)
                .collect::<Vec<_>>(),
        );
        let mut rows = incompressible_cases;
        rows.extend(kirsch_nu.iter().map(KirschResult::report));
        Ok(Section {
            markdown: md,
            rows,

            ..Default::default()
        })
    }
}
