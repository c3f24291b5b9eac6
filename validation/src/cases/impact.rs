//! A block striking a base through a joint must leave at the speed it came in.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::impact;
use crate::report::CaseReport;

pub struct Impact;

impl Case for Impact {
    fn name(&self) -> &'static str {
        "impact"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let impact_cases: Vec<CaseReport> = ["rigid", "simple", "deformable"]
            .iter()
            .map(|m| impact::run(m))
            .collect::<anyhow::Result<_>>()?;
        let settle_cycles: Vec<(&str, u64)> = ["rigid", "simple", "deformable"]
            .iter()
            .map(|&m| impact::settles(m).map(|c| (m, c)))
            .collect::<anyhow::Result<_>>()?;
        for r in &impact_cases {
            print_row(r);
        }
        let _ = writeln!(md, "\n## Stability: impact (issue 5)\n");
        let _ = writeln!(
            md,
            "A 1 m × 0.5 m block strikes a 2 m × 0.5 m deformable base (fixed at its bottom) at 1 m/s through a \
         joint with kn = ks = 1e10 Pa/m, no gravity, no damping: the contact is a spring and the block must \
         leave at the speed it came in. `energy_loss`: 1 − its kinetic energy 2 ms after it has left over \
         its energy before; the rest stays in the base's (and a deformable block's own) vibration. With \
         gravity and local damping (static solve) the block comes to rest on the base: {}.\n",
            settle_cycles
                .iter()
                .map(|(m, c)| format!("{m} in {c} cycles"))
                .collect::<Vec<_>>()
                .join(", ")
        );
        table(&mut md, &impact_cases);
        Ok(Section {
            markdown: md,
            rows: impact_cases,

            ..Default::default()
        })
    }
}
