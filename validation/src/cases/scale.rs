//! Builds at scale: large regions and many joints set up in seconds.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section};
use crate::scale;

/// Builds at scale (issue 14): a terrain region of 20 000 and 100 000 vertices and the tunnel with
/// about 10 000 joint traces, with their build times and whether their zones tile the rock.
fn scale_section(md: &mut String, rows: &[scale::Row]) {
    let _ = writeln!(md, "\n## Builds at scale (issue 14)\n");
    let _ = writeln!(
        md,
        "Each scene cut, meshed and given its blocks and contacts (`adit::setup::setup`, one run, wall \
         seconds). The terrain region (`validation/src/scale.rs`) is a 5 km slope section whose ground \
         surface has the given number of vertices, with a 6 m horseshoe tunnel 300 m down; jointed, it \
         has two sets 25 m apart in traces of 100 m. The cutter pairs segments, the polygon checks find \
         crossings and the mesher labels boundary edges through grids, and containment tests on a large \
         polygon go through an index of its edges in strips: before, the 20 000-vertex region took 17 s \
         and the 100 000-vertex one 8.4 min. Tiling: zoned area over the rock's area (the region less the \
         excavations open from the start).\n"
    );
    let _ = writeln!(
        md,
        "| scene | region vertices | joint traces | blocks | zones | tiling − 1 | build (s) |\n|---|---:|---:|---:|---:|---:|---:|"
    );
    for r in rows {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {:.1e} | {:.2} |",
            r.what,
            r.region_vertices,
            r.traces,
            r.blocks,
            r.zones,
            r.tiling - 1.0,
            r.seconds
        );
    }
}

pub struct Scale;

impl Case for Scale {
    fn name(&self) -> &'static str {
        "scale"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let mut md = String::new();
        let scale_rows = scale::rows()?;
        scale_section(&mut md, &scale_rows);
        Ok(Section {
            markdown: md,
            rows: vec![],

            ..Default::default()
        })
    }
}
