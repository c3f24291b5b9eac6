//! Supports as line cells (`_supports_NNNN.vtu`): one cell per cable segment and per liner
//! element at original positions, with `axial_force` (N/m, tension positive) and `moment` (N·m/m,
//! the liner's internal bending moment at the element's middle, positive when its excavation
//! face is in tension; 0 for cables), `bolt_force_n` (a bolt segment's force per bolt, N: the
//! force per metre times the bolts' spacing; 0 for liners), `bolt_utilization` (|N| over the
//! bolt's yield force; 0 for liners), `shear_force_n_per_m` (a liner element's shear, N/m; 0 for
//! cables), `liner_utilization` (1 over the element's factor of safety against its thrust, moment
//! and shear, `support::liner_capacity`: 1 on its capacity envelope; 0 for cables and for liners
//! without strengths), `kind` (0 bolt, 1 liner), `installed` and `yielded` per cell, and the
//! rock's `displacement` (m) at each point. Only the supports installed so far are written (a
//! step before any is installed writes no file): a branch of a run that bolts differently later
//! writes the same files up to its branching stage.

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
    let kept = Kept::of(&installed, &connectivity, points.len() / 3);
    let cells = kept.cells;
    let piece = UnstructuredGridPiece {
        points: kept.points(&points).into(),
        cells: Cells {
            cell_verts: VertexNumbers::XML {
                connectivity: kept.connectivity(&connectivity),
                offsets: (1..=cells as u64).map(|k| 2 * k).collect(),
            },
            types: vec![CellType::Line; cells],
        },
        data: Attributes {
            point: vec![
                Attribute::generic("displacement", 3).with_data(kept.points(&displacement)),
            ],
            cell: vec![
                Attribute::generic("axial_force", 1).with_data(kept.cell(&axial)),
                Attribute::generic("bolt_force_n", 1).with_data(kept.cell(&per_bolt)),
                Attribute::generic("bolt_utilization", 1).with_data(kept.cell(&utilization)),
                Attribute::generic("moment", 1).with_data(kept.cell(&moment)),
                Attribute::generic("shear_force_n_per_m", 1).with_data(kept.cell(&shear)),
                Attribute::generic("liner_utilization", 1).with_data(kept.cell(&liner_utilization)),
                Attribute::generic("kind", 1).with_data(kept.cell(&kind)),
                Attribute::generic("installed", 1).with_data(kept.cell(&installed)),
                Attribute::generic("yielded", 1).with_data(kept.cell(&yielded)),
            ],
        },
    };
    xml_of(piece, labels)
}

/// The installed cells of the supports' grid and the points they use, renumbered in order.
struct Kept {
    keep: Vec<bool>,
    /// New number of each old point (`u64::MAX`: not used by a kept cell).
    renumber: Vec<u64>,
    cells: usize,
}

impl Kept {
    /// The cells whose `installed` flag is set, of line cells `connectivity` over `points`.
    fn of(installed: &[i32], connectivity: &[u64], points: usize) -> Kept {
        let keep: Vec<bool> = installed.iter().map(|&i| i != 0).collect();
        let mut used = vec![false; points];
        for (cell, ends) in connectivity.chunks(2).enumerate() {
            if keep[cell] {
                ends.iter().for_each(|&p| used[p as usize] = true);
            }
        }
        let mut next = 0;
        let renumber = used
            .iter()
            .map(|&u| {
                if u {
                    next += 1;
                    next - 1
                } else {
                    u64::MAX
                }
            })
            .collect();
        let cells = keep.iter().filter(|&&k| k).count();
        Kept {
            keep,
            renumber,
            cells,
        }
    }

    fn cell<T: Copy>(&self, values: &[T]) -> Vec<T> {
        values
            .iter()
            .zip(&self.keep)
            .filter(|(_, k)| **k)
            .map(|(v, _)| *v)
            .collect()
    }

    /// Point values, three per point.
    fn points(&self, values: &[f64]) -> Vec<f64> {
        (values.chunks(3).zip(&self.renumber))
            .filter(|(_, n)| **n != u64::MAX)
            .flat_map(|(v, _)| v.iter().copied())
            .collect()
    }

    fn connectivity(&self, connectivity: &[u64]) -> Vec<u64> {
        (connectivity.chunks(2).zip(&self.keep))
            .filter(|(_, k)| **k)
            .flat_map(|(ends, _)| ends.iter().map(|&p| self.renumber[p as usize]))
            .collect()
    }
}
