//! The implicit static path against the explicit one (issue 17): Kirsch's hole with the exact
//! traction on its outer boundary, at the shipped zoning and at a finer one, solved both ways.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::kirsch_case::{KirschResult, OuterLoad, run, scaled};
use adit::scene::SolveMethod;

pub struct Implicit;

impl Case for Implicit {
    fn name(&self) -> &'static str {
        "implicit"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let mut pairs: Vec<(f64, KirschResult, KirschResult)> = Vec::new();
        for factor in [1.0, 0.6] {
            let explicit = scaled(&cx.kirsch, factor);
            let mut implicit = explicit.clone();
            implicit.solve.method = SolveMethod::Implicit;
            let tag = |m: &str| format!("kirsch ×{factor} exact traction, {m}");
            let e = run(&explicit, &tag("explicit"), OuterLoad::Exact)?;
            let i = run(&implicit, &tag("implicit"), OuterLoad::Exact)?;
            print_row(&e.report());
            print_row(&i.report());
            pairs.push((factor, e, i));
        }
        let _ = writeln!(md, "\n## Implicit static solve (issue 17)\n");
        let _ = writeln!(
            md,
            "`solve.method: implicit` (`src/implicit/`, `docs/theory.md`): the stiffness of the zones \
             (and of the contacts, with their joints' elastic stiffness) factorized by faer's sparse \
             Cholesky, each iteration solving K Δu = R for the out-of-balance force of the explicit \
             force stages and moving the model through the same laws, to the same unbalanced-force \
             ratio. Kirsch's hole as in the first section with the exact traction on the outer \
             boundary, at the shipped zoning (×1) and finer (×0.6), the explicit path to the shipped \
             ratio {:e}. Cycles are the explicit cycles or the implicit iterations; the seconds \
             include meshing and setting up.\n",
            cx.kirsch.solve.ratio
        );
        let rows: Vec<_> = pairs
            .iter()
            .flat_map(|(_, e, i)| [e.report(), i.report()])
            .collect();
        table(&mut md, &rows);
        let _ = writeln!(
            md,
            "\n| zoning | zones | explicit cycles | explicit s | implicit iterations | implicit s | speed-up | stress L2, explicit − implicit |\n|---|---:|---:|---:|---:|---:|---:|---:|"
        );
        for (factor, e, i) in &pairs {
            let _ = writeln!(
                md,
                "| ×{factor} | {} | {} | {:.2} | {} | {:.2} | {:.1}× | {:+.2e} |",
                e.zones,
                e.cycles,
                e.wall_s,
                i.cycles,
                i.wall_s,
                e.wall_s / i.wall_s,
                e.stress_l2 - i.stress_l2
            );
        }
        Ok(Section {
            markdown: md,
            rows,
            ..Default::default()
        })
    }
}
