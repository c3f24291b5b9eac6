//! A run made unstable on purpose must stop within a few cycles, naming the node and the cause.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::report::CaseReport;
use crate::unstable;

pub struct Unstable;

impl Case for Unstable {
    fn name(&self) -> &'static str {
        "unstable"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let forced_cases: Vec<CaseReport> =
            vec![unstable::run(3.0)?.report(), unstable::run(1.0)?.report()];
        for r in &forced_cases {
            print_row(r);
        }
        let _ = writeln!(
            md,
            "\n## Stability: a run made unstable on purpose (issue 5)\n"
        );
        let _ = writeln!(
            md,
            "The Kirsch model with zones three times the shipped size, solved statically with its step \
         forced to 3× the stable one, and at its derived step (`validation/src/unstable.rs`): the \
         forced run stops within a few cycles naming the node and the cause; a stopped scene run \
         writes its summary with status `failed` and no zone grid.\n"
        );
        table(&mut md, &forced_cases);
        Ok(Section {
            markdown: md,
            rows: forced_cases,

            ..Default::default()
        })
    }
}
