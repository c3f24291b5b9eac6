//! Glued joints: the Kirsch model cut into blocks whose glued joints must give back the intact answer.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::glued;
use crate::kirsch_case::KirschResult;

pub struct Glued;

impl Case for Glued {
    fn name(&self) -> &'static str {
        "glued"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let scene = &cx.kirsch;
        let mut md = String::new();
        let glued: Vec<KirschResult> = [1e11, 1e12]
            .iter()
            .map(|&k| {
                let r = glued::run_glued(scene, k)?;
                print_row(&r.report());
                Ok(r)
            })
            .collect::<anyhow::Result<_>>()?;

        let _ = writeln!(md, "\n## Jointed rock: glued joints\n");
        let _ = writeln!(
            md,
            "The shipped Kirsch model cut into about a hundred blocks by two joint sets (dips 30° and 120°, \
         spacings 4 m and 5 m) whose joints are glued (`law: glued`: springs of normal and shear stiffness kn \
         that never slip or open). The blocks interact only through their contacts; as kn grows the \
         intact solution must come back. Errors against the Kirsch closed form as above.\n"
        );
        table(
            &mut md,
            &glued.iter().map(KirschResult::report).collect::<Vec<_>>(),
        );
        let glued_pass = glued.iter().all(|r| r.stress_l2 <= 0.05);
        let _ = writeln!(
            md,
            "\nBar: stress L2 ≤ 5 % with glued joints: **{}**. Stiff joints make the mass-scaled nodes on the \
         joints heavier, so convergence takes more cycles.\n",
            if glued_pass { "met" } else { "NOT met" }
        );
        Ok(Section {
            markdown: md,
            rows: glued.iter().map(KirschResult::report).collect(),

            ..Default::default()
        })
    }
}
