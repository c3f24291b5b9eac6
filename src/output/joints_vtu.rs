//! Joints as line cells (`_joints_NNNN.vtu`): the block boundary edges in contact, so that slipping
//! and open joints show as coloured traces, as UDEC draws them.
//!
//! A boundary edge of block A is drawn when both its nodes touch another block through a contact
//! (`Contacts::node`), and only from the side of the block with the lower number (each joint has
//! contacts from both sides; drawing one side keeps the traces from overlapping). Each line's data
//! is the mean over the contacts of its two nodes: `normal_stress` and `shear_stress` (Pa, tension
//! positive), `shear_displacement` (m), `aperture` (m: the opening max(uₙ, 0), joints starting
//! closed), `jrc_mobilized` (the Barton–Bandis law's mobilized roughness, 0 for the other laws),
//! and `state` the worse of the two ends (0 elastic, 1 slipping, 2 open), `material` the
//! joint material of the first node's contact (names in the field data).

use vtkio::model::{Attribute, Attributes, CellType, Cells, UnstructuredGridPiece, VertexNumbers};

use super::vtu::{Labels, state_code, xml_of};
use crate::model::Model;

/// What a node's contacts carry, summed, for the mean of a line.
#[derive(Debug, Clone, Copy, Default)]
struct End {
    count: u32,
    normal: f64,
    shear: f64,
    slip: f64,
    opening: f64,
    jrc: f64,
    state: i32,
    material: u32,
    /// The lowest block number of the contacts' other blocks.
    other: u32,
}

/// The joints of `model` as XML text.
pub fn joints_vtu(model: &Model, labels: &Labels) -> Result<Vec<u8>, vtkio::Error> {
    let (c, blocks) = (&model.contacts, &model.blocks);
    let mut ends = vec![End::default(); model.nodes.len()];
    for k in 0..c.len() {
        let n = c.node[k] as usize;
        let s = &c.state[k];
        let e = &mut ends[n];
        if e.count == 0 {
            e.material = c.material[k];
            e.other = c.block[k];
        }
        e.count += 1;
        e.normal += s.normal;
        e.shear += s.shear;
        e.slip += s.shear_displacement;
        e.opening += s.normal_displacement.max(0.0);
        e.jrc += s.jrc_mobilized;
        e.state = e.state.max(state_code(s));
        e.other = e.other.min(c.block[k]);
    }
    let mut points = Vec::new();
    let mut lines = 0u64;
    let (mut normal, mut shear, mut slip, mut aperture) = (vec![], vec![], vec![], vec![]);
    let mut jrc = vec![];
    let (mut state, mut material, mut block) = (vec![], vec![], vec![]);
    for b in 0..blocks.len() {
        if blocks.is_removed(b) {
            continue;
        }
        for e in blocks.edge_range(b) {
            let [p, q] = blocks.edges[e].map(|n| ends[n as usize]);
            if p.count == 0 || q.count == 0 || p.other.min(q.other) < b as u32 {
                continue;
            }
            for n in blocks.edges[e] {
                let x = model.nodes.pos[n as usize];
                points.extend([x[0], x[1], 0.0]);
            }
            lines += 1;
            let mean = |f: fn(&End) -> f64| 0.5 * (f(&p) / p.count as f64 + f(&q) / q.count as f64);
            normal.push(mean(|e| e.normal));
            shear.push(mean(|e| e.shear));
            slip.push(mean(|e| e.slip));
            aperture.push(mean(|e| e.opening));
            jrc.push(mean(|e| e.jrc));
            state.push(p.state.max(q.state));
            material.push(p.material as i32);
            block.push(b as i32);
        }
    }
    let n = lines;
    let piece = UnstructuredGridPiece {
        points: points.into(),
        cells: Cells {
            cell_verts: VertexNumbers::XML {
                connectivity: (0..2 * n).collect(),
                offsets: (1..=n).map(|k| 2 * k).collect(),
            },
            types: vec![CellType::Line; n as usize],
        },
        data: Attributes {
            point: vec![],
            cell: vec![
                Attribute::generic("normal_stress", 1).with_data(normal),
                Attribute::generic("shear_stress", 1).with_data(shear),
                Attribute::generic("shear_displacement", 1).with_data(slip),
                Attribute::generic("aperture", 1).with_data(aperture),
                Attribute::generic("jrc_mobilized", 1).with_data(jrc),
                Attribute::generic("state", 1).with_data(state),
                Attribute::generic("material", 1).with_data(material),
                Attribute::generic("block", 1).with_data(block),
            ],
        },
    };
    xml_of(piece, labels)
}
