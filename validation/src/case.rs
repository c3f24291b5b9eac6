//! A validation case: it runs against its closed form or published result and writes its own
//! section of the report (the prose that explains it, its tables and plots). `main.rs` runs the
//! cases in the report's order, or those whose name a filter picks.

use std::fmt::Write as _;
use std::path::PathBuf;

use crate::readme::ModelRow;
use crate::report::{CaseReport, StepInfo};

/// What every case may use.
pub struct Context {
    /// The repository root (scenes in `models/`, plots into `docs/img/`).
    pub root: PathBuf,
    /// Threads the run uses (named in the prose beside speeds).
    pub threads: usize,
    /// `models/kirsch.json`, which several cases start from.
    pub kirsch: adit::Scene,
}

/// What a case gives the report.
#[derive(Default)]
pub struct Section {
    /// Its part of `docs/validation.md`: heading, prose, tables and plot links.
    pub markdown: String,
    /// Its rows for `target/validation/report.json` and the console.
    pub rows: Vec<CaseReport>,
    /// Rows of the README's models table it measured.
    pub models: Vec<ModelRow>,
    /// The bars it misses, in words: the report is written, then the run fails.
    pub missed: Vec<String>,
    /// Further files for `target/validation/`: name and contents.
    pub files: Vec<(String, String)>,
}

/// One section of the report.
pub trait Case {
    /// A short name, what the command-line filter matches (`kirsch`, `salencon`, …).
    fn name(&self) -> &'static str;
    /// Run it and write its section.
    fn run(&self, cx: &Context) -> anyhow::Result<Section>;
}

/// A markdown table of report rows.
pub fn table(md: &mut String, rows: &[CaseReport]) {
    let _ = writeln!(
        md,
        "| case | zones | cycles | wall s | zone-cycles/s | critical step, limited by | errors |"
    );
    let _ = writeln!(md, "|---|---:|---:|---:|---:|---|---|");
    for r in rows {
        let errors: Vec<String> = r
            .errors
            .iter()
            .map(|(k, v)| format!("{k} = {v:.2e}"))
            .collect();
        let _ = writeln!(
            md,
            "| {} | {} | {} | {:.3} | {:.2e} | {} | {} |",
            r.case,
            r.zones,
            r.cycles,
            r.wall_s,
            r.zone_cycles_per_s,
            r.step.as_ref().map_or("–".to_string(), StepInfo::label),
            errors.join(", ")
        );
    }
}

/// A section's bar line: `met`, or `missed by` the cases that missed it, `; ` between them.
pub fn verdict(missed: &[String]) -> String {
    if missed.is_empty() {
        "met".to_string()
    } else {
        format!("missed by {}", missed.join("; "))
    }
}

/// One row on the console.
pub fn print_row(r: &CaseReport) {
    let errors: Vec<String> = r
        .errors
        .iter()
        .map(|(k, v)| format!("{k} {v:.3e}"))
        .collect();
    println!(
        "{:<40} {:>7} zones {:>7} cycles {:>8.2} s {:>9.2e} zc/s  {}",
        r.case,
        r.zones,
        r.cycles,
        r.wall_s,
        r.zone_cycles_per_s,
        errors.join(", ")
    );
}
