//! A column under its own weight, and one initialised with the in-situ gradient that must stay at rest.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::gravity;

pub struct Gravity;

impl Case for Gravity {
    fn name(&self) -> &'static str {
        "gravity"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let gravity_cases = vec![
            gravity::self_weight(1.0)?,
            gravity::self_weight(0.5)?,
            gravity::in_situ_equilibrium(0.5)?,
        ];
        for r in &gravity_cases {
            print_row(r);
        }
        let _ = writeln!(md, "\n## Gravity\n");
        let _ = writeln!(
            md,
            "A 5 m × 20 m column on a fixed base with its sides on rollers, loaded by its own weight from zero \
         stress (ρ = 2500 kg/m³, g = 9.81 m/s²): zone σyy against −ρg(H − y) (`stress_l2`) and node settlement \
         against ρg(Hy − y²/2)/M (`settlement`, relative to the top settlement). Then the same column \
         initialised with the in-situ stress gradient that balances gravity: it must stay at rest \
         (`displacement`: largest displacement relative to the self-weight settlement of the top).\n"
        );
        table(&mut md, &gravity_cases);
        Ok(Section {
            markdown: md,
            rows: gravity_cases,

            ..Default::default()
        })
    }
}
