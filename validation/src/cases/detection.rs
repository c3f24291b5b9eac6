//! Contact detection against block count: the cost per block of one full detection.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section};
use crate::scaling;

pub struct Detection;

impl Case for Detection {
    fn name(&self) -> &'static str {
        "detection"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let threads = cx.threads;
        let mut md = String::new();
        let detection: Vec<scaling::DetectionCost> = [32, 64, 128]
            .iter()
            .map(|&n| scaling::measure(n))
            .collect::<anyhow::Result<_>>()?;
        for d in &detection {
            println!(
                "detection: {:>6} blocks {:>7} contacts {:>9.4} s ({:.0} ns/block), build {:.2} s",
                d.blocks, d.contacts, d.detect_s, d.ns_per_block, d.build_s
            );
        }
        let _ = writeln!(md, "\n## Contact detection against block count\n");
        let _ = writeln!(
            md,
            "Square regions cut by two orthogonal persistent joint sets into n × n blocks (two zones each); one \
         full detection (uniform-grid broad phase over block boxes, node-to-edge narrow phase), best of \
         three, {threads} threads. Near-linear growth shows as a steady cost per block.\n"
        );
        let _ = writeln!(
            md,
            "| blocks | contacts | detection s | ns per block | cut + zone + build s |"
        );
        let _ = writeln!(md, "|---:|---:|---:|---:|---:|");
        for d in &detection {
            let _ = writeln!(
                md,
                "| {} | {} | {:.4} | {:.0} | {:.2} |",
                d.blocks, d.contacts, d.detect_s, d.ns_per_block, d.build_s
            );
        }
        Ok(Section {
            markdown: md,
            rows: vec![],
            files: vec![(
                "detection_scaling.json".into(),
                serde_json::to_string_pretty(&detection)?,
            )],
            ..Default::default()
        })
    }
}
