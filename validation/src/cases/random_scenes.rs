//! Random scenes: boxes cut by random joint sets must end converged, at their limit, or stopped as a mechanism.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table};
use crate::random_scenes;

/// Random scenes in the report's sweep (64 in `cargo test`).
const RANDOM_SCENES: usize = 1000;

pub struct RandomScenes;

impl Case for RandomScenes {
    fn name(&self) -> &'static str {
        "random"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let random_sweep = random_scenes::sweep(RANDOM_SCENES, 7)?.report();
        print_row(&random_sweep);
        let _ = writeln!(md, "\n## Stability: random scenes (issue 5)\n");
        let _ = writeln!(
            md,
            "Boxes 2–4 m wide cut by one or two joint sets at random dips (the second at least 3° from \
         the first) and spacings of 0.5–1.5 m, kn = 1e10–1e12 Pa/m, φ = 10–45°, blocks deformable, \
         simple or rigid, base fixed, sides on rollers, up to 2 MPa on top, with or without gravity, \
         3000 cycles at most (`validation/src/random_scenes.rs`, proptest strategies from a fixed \
         seed; `cargo test` runs 64 of them as a shrinking property). Every run must end converged, \
         at its cycle limit, or stopped as a mechanism by the runaway check, never with NaN, an \
         unstable step or interpenetration; every overlap stays within its contact length, and a \
         stopped run writes no zone grid. The step column gives the tightest critical step met.\n"
        );
        table(&mut md, std::slice::from_ref(&random_sweep));
        Ok(Section {
            markdown: md,
            rows: vec![random_sweep],

            ..Default::default()
        })
    }
}
