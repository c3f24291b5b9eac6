//! Candidate pairs of segments by a uniform grid of their boxes: the cutter splits each segment
//! where it meets others, and testing every pair was O(n²) (11 000 joint traces took 18 s).

use std::collections::HashMap;

use crate::joints::Segment;

/// Each segment's box, widened by a tolerance, entered in every grid cell it covers.
pub struct SegmentGrid {
    /// Cell size, m.
    cell: f64,
    cells: HashMap<(i64, i64), Vec<u32>>,
    /// The cell range [x0, y0, x1, y1] each segment covers.
    range: Vec<[i64; 4]>,
}

impl SegmentGrid {
    /// The grid of `segs` with boxes widened by `tol` (m); cells of the mean segment length (at
    /// least 4 `tol`), so a segment covers few cells and a cell holds few segments unless they are
    /// long and many (persistent sets, whose pairs all cross anyway).
    pub fn new(segs: &[Segment], tol: f64) -> SegmentGrid {
        let mean = segs
            .iter()
            .map(|s| (s.b[0] - s.a[0]).hypot(s.b[1] - s.a[1]))
            .sum::<f64>()
            / segs.len().max(1) as f64;
        let cell = mean.max(4.0 * tol).max(f64::MIN_POSITIVE);
        let mut grid = SegmentGrid {
            cell,
            cells: HashMap::new(),
            range: Vec::with_capacity(segs.len()),
        };
        for (i, s) in segs.iter().enumerate() {
            let r = grid.cells_of(s, tol);
            for cx in r[0]..=r[2] {
                for cy in r[1]..=r[3] {
                    grid.cells.entry((cx, cy)).or_default().push(i as u32);
                }
            }
            grid.range.push(r);
        }
        grid
    }

    fn cells_of(&self, s: &Segment, tol: f64) -> [i64; 4] {
        let c = |v: f64| (v / self.cell).floor() as i64;
        [
            c(s.a[0].min(s.b[0]) - tol),
            c(s.a[1].min(s.b[1]) - tol),
            c(s.a[0].max(s.b[0]) + tol),
            c(s.a[1].max(s.b[1]) + tol),
        ]
    }

    /// The segments (ascending) whose widened boxes may hold point `p`: those entered in its cell.
    pub fn at(&self, p: crate::geometry::Point) -> &[u32] {
        let c = |v: f64| (v / self.cell).floor() as i64;
        self.cells
            .get(&(c(p[0]), c(p[1])))
            .map_or(&[][..], Vec::as_slice)
    }

    /// Into `out`, in increasing order and once each, the segments sharing a cell with segment
    /// `i` (itself included): a superset of those whose widened boxes overlap its own.
    pub fn candidates(&self, i: usize, out: &mut Vec<u32>) {
        out.clear();
        let r = self.range[i];
        for cx in r[0]..=r[2] {
            for cy in r[1]..=r[3] {
                out.extend(self.cells.get(&(cx, cy)).into_iter().flatten());
            }
        }
        out.sort_unstable();
        out.dedup();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::joints::EdgeKind;

    /// Every pair whose boxes overlap is a candidate, on random segments of mixed lengths.
    #[test]
    fn candidates_hold_every_overlapping_pair() {
        let mut rng = crate::joints::SplitMix(7);
        let mut u = |a: f64, b: f64| a + (b - a) * (rng.next_u64() as f64 / u64::MAX as f64);
        let segs: Vec<Segment> = (0..400)
            .map(|k| {
                let (x, y) = (u(-50.0, 50.0), u(-50.0, 50.0));
                let len = if k % 10 == 0 { 60.0 } else { u(0.1, 5.0) };
                let dip = u(0.0, std::f64::consts::PI);
                Segment {
                    a: [x, y],
                    b: [x + len * dip.cos(), y + len * dip.sin()],
                    kind: EdgeKind::Joint(0),
                }
            })
            .collect();
        let tol = 0.05;
        let grid = SegmentGrid::new(&segs, tol);
        let mut near = Vec::new();
        for (i, s) in segs.iter().enumerate() {
            grid.candidates(i, &mut near);
            for (j, o) in segs.iter().enumerate() {
                if crate::blocks::bbox_overlap(s, o, tol) {
                    assert!(near.binary_search(&(j as u32)).is_ok(), "{i} {j}");
                }
            }
        }
    }
}
