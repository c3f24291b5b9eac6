//! A column of blocks under gravity (figures from the tests in `tests/engine/blocks.rs`).

use std::fmt::Write as _;

use crate::case::{Case, Context, Section};

pub struct Column;

impl Case for Column {
    fn name(&self) -> &'static str {
        "column"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let _ = writeln!(md, "\n## Jointed rock: column of blocks\n");
        let _ = writeln!(
            md,
            "Three 1 m blocks stacked under gravity (test `column_of_blocks_carries_the_weight_above_each_joint` \
         in `tests/engine/blocks.rs`, run for deformable, simple and rigid blocks): the normal force across each joint \
         equals the weight above it to 6e-7 (deformable) and 6e-8 (simple, rigid). Two free blocks colliding \
         (`tests/engine/blocks.rs`) conserve momentum to 1e-15 (deformable and rigid); rigid ones exchange their \
         velocities to 0.09 %; a free rigid block spun through 3 turns keeps its shape to 1e-12 m.\n"
        );
        Ok(Section {
            markdown: md,
            rows: vec![],

            ..Default::default()
        })
    }
}
