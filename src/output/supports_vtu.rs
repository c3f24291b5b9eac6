//! Supports as line cells (`_supports_NNNN.vtu`): one cell per cable segment and per liner
//! element at original positions, with `axial_force` (N/m, tension positive) and `moment` (N·m/m,
//! the liner's internal bending moment at the element's middle, positive when its excavation
//! face is in tension; 0 for cables), `bolt_force_n` (a bolt segment's force per bolt, N: the
//! force per metre times the bolts' spacing; 0 for liners), `bolt_utilization` (|N| over the
//! bolt's yield force; 0 for liners), `shear_force_n_per_m` (a liner element's shear, N/m; 0 for
//! cables), `liner_utilization` (1 over the element's factor of safety against its thrust, moment
//! and shear, `support::liner_capacity`: 1 on its capacity envelope; 0 for cables and for liners
//! without strengths), `kind` (0 bolt, 1 liner), `installed` and `yielded` per cell, and the
//! rock's `displacement` (m) at each point.

use vtkio::model::{Attribute, Attributes, CellType, Cells, UnstructuredGridPiece, VertexNumbers};

use super::vtu::{Labels, xml_of};
use crate::model::Model;

/// The supports of `model` as XML text.
pub fn supports_vtu(model: &Model, labels: &Labels) -> Result<Vec<u8>, vtkio::Error> {
    let (c, l) = (&model.supports.cables, &model.supports.liners);
    let nodes = &model.nodes;
    let rock = |n: u32| {
        let (u, o) = (nodes.disp[n as usize], nodes.origin[n as usize]);
        [u[0] - o[0], u[1] - o[1]]
    };
    let mut points = Vec::new();
    let mut displacement = Vec::new();
    for n in 0..c.nodes() {
        points.extend([c.pos[n][0], c.pos[n][1], 0.0]);
        let mut u = [0.0; 2];
        for (&h, w) in c.host[n].iter().zip(c.weight[n]) {
            let r = rock(h);
            u = [u[0] + w * r[0], u[1] + w * r[1]];
        }
        displacement.extend([u[0], u[1], 0.0]);
    }
    let first_liner = c.nodes() as u64;
    // Each liner node shows the rock displacement of its first linked wall node.
    let mut first_link = vec![None; l.nodes()];
    for (k, &n) in l.link_node.iter().enumerate() {
        first_link[n as usize].get_or_insert(k);
    }
    for (n, link) in first_link.into_iter().enumerate() {
        points.extend([l.pos[n][0], l.pos[n][1], 0.0]);
        let u = link.map_or([0.0; 2], |k| rock(l.link_rock[k]));
        displacement.extend([u[0], u[1], 0.0]);
    }
    let segments = c.segment.len();
    let cells = segments + l.element.len();
    let connectivity: Vec<u64> = c
        .segment
        .iter()
        .flat_map(|s| s.map(u64::from))
        .chain(
            l.element
                .iter()
                .flat_map(|e| e.map(|n| first_liner + n as u64)),
        )
        .collect();
    let axial: Vec<f64> = c.axial.iter().chain(&l.axial).copied().collect();
    let per_bolt: Vec<f64> = (0..segments)
        .map(|s| c.bolt_force(s))
        .chain(std::iter::repeat_n(0.0, l.element.len()))
        .collect();
    let utilization: Vec<f64> = (0..segments)
        .map(|s| c.utilization(s))
        .chain(std::iter::repeat_n(0.0, l.element.len()))
        .collect();
    let moment: Vec<f64> = std::iter::repeat_n(0.0, segments)
        .chain(l.moment.iter().map(|m| 0.5 * (m[0] + m[1])))
        .collect();
    let shear: Vec<f64> = std::iter::repeat_n(0.0, segments)
        .chain((0..l.element.len()).map(|e| l.shear(e)))
        .collect();
    let liner_utilization: Vec<f64> = std::iter::repeat_n(0.0, segments)
        .chain((0..l.element.len()).map(|e| l.utilization(e)))
        .collect();
    let kind: Vec<i32> = std::iter::repeat_n(0, segments)
        .chain(std::iter::repeat_n(1, l.element.len()))
        .collect();
    let installed: Vec<i32> = (c.segment_group.iter().map(|&g| c.active[g as usize]))
        .chain(l.element_group.iter().map(|&g| l.active[g as usize]))
        .map(i32::from)
        .collect();
    let yielded: Vec<i32> = c
        .plastic
        .iter()
        .map(|&p| i32::from(p != 0.0))
        .chain(std::iter::repeat_n(0, l.element.len()))
        .collect();
    let piece = UnstructuredGridPiece {
        points: points.into(),
        cells: Cells {
            cell_verts: VertexNumbers::XML {
                connectivity,
                offsets: (1..=cells as u64).map(|k| 2 * k).collect(),
            },
            types: vec![CellType::Line; cells],
        },
        data: Attributes {
            point: vec![Attribute::generic("displacement", 3).with_data(displacement)],
            cell: vec![
                Attribute::generic("axial_force", 1).with_data(axial),
                Attribute::generic("bolt_force_n", 1).with_data(per_bolt),
                Attribute::generic("bolt_utilization", 1).with_data(utilization),
                Attribute::generic("moment", 1).with_data(moment),
                Attribute::generic("shear_force_n_per_m", 1).with_data(shear),
                Attribute::generic("liner_utilization", 1).with_data(liner_utilization),
                Attribute::generic("kind", 1).with_data(kind),
                Attribute::generic("installed", 1).with_data(installed),
                Attribute::generic("yielded", 1).with_data(yielded),
            ],
        },
    };
    xml_of(piece, labels)
}
