//! Candidate pairs of segments by a uniform grid: the cutter splits each segment where it meets
//! others, the polygon checks look for crossings, and the mesher finds the block edge under each
//! boundary edge; testing every pair was O(n²) (11 000 joint traces took 18 s; a 20 000-vertex
//! region 17 s). A segment is entered only in the cells its band of half-width `tol` covers, so a
//! long diagonal segment costs cells in proportion to its length, not to its bounding box's area.

use crate::Map;

use crate::geometry::Point;
use crate::joints::Segment;

/// Each segment entered in every grid cell within `tol` of it.
pub struct SegmentGrid {
    /// Cell size, m.
    cell: f64,
    /// Half-width of each segment's band, m.
    tol: f64,
    cells: Map<(i64, i64), Vec<u32>>,
    /// Each segment's end points, m.
    ends: Vec<[Point; 2]>,
}

impl SegmentGrid {
    /// The grid of `segs` with bands of half-width `tol` (m); cells of the mean segment length (at
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
            tol,
            cells: Map::default(),
            ends: segs.iter().map(|s| [s.a, s.b]).collect(),
        };
        let mut cells = Map::<(i64, i64), Vec<u32>>::default();
        for i in 0..segs.len() {
            grid.each_cell(i, |c| cells.entry(c).or_default().push(i as u32));
        }
        grid.cells = cells;
        grid
    }

    /// Visit every cell holding a point within `tol` of segment `i`, column by column: in the
    /// column [x0, x1] the band's points come from segment points with x in [x0 − tol, x1 + tol],
    /// whose y range, widened by `tol`, bounds the cells.
    fn each_cell(&self, i: usize, mut visit: impl FnMut((i64, i64))) {
        let [a, b] = self.ends[i];
        let (tol, cell) = (self.tol, self.cell);
        let c = |v: f64| (v / cell).floor() as i64;
        let (xmin, xmax) = (a[0].min(b[0]), a[0].max(b[0]));
        let (ymin, ymax) = (a[1].min(b[1]), a[1].max(b[1]));
        let y_at = |x: f64| {
            if b[0] == a[0] {
                None
            } else {
                Some((a[1] + (x - a[0]) * (b[1] - a[1]) / (b[0] - a[0])).clamp(ymin, ymax))
            }
        };
        for cx in c(xmin - tol)..=c(xmax + tol) {
            let lo = (cx as f64 * cell - tol).max(xmin);
            let hi = ((cx + 1) as f64 * cell + tol).min(xmax);
            let (y0, y1) = match (y_at(lo), y_at(hi)) {
                (Some(p), Some(q)) => (p.min(q), p.max(q)),
                _ => (ymin, ymax),
            };
            for cy in c(y0 - tol)..=c(y1 + tol) {
                visit((cx, cy));
            }
        }
    }

    /// The segments (ascending) whose bands may hold point `p`: those entered in its cell.
    pub fn at(&self, p: Point) -> &[u32] {
        let c = |v: f64| (v / self.cell).floor() as i64;
        self.cells
            .get(&(c(p[0]), c(p[1])))
            .map_or(&[][..], Vec::as_slice)
    }

    /// The cell size, m.
    pub fn cell(&self) -> f64 {
        self.cell
    }

    /// Visit the segments entered in the cells k cells away from `p`'s (the square ring of cells
    /// at Chebyshev distance k; k = 0 is `p`'s own): every point of those cells is at least
    /// (k − 1) cells from `p`, so a nearest-segment search may stop at the ring beyond its best
    /// distance. A segment in several cells is visited once per cell.
    pub fn ring(&self, p: Point, k: i64, mut visit: impl FnMut(u32)) {
        let c = |v: f64| (v / self.cell).floor() as i64;
        let (cx, cy) = (c(p[0]), c(p[1]));
        let mut cell = |x: i64, y: i64| {
            for &e in self.cells.get(&(x, y)).into_iter().flatten() {
                visit(e);
            }
        };
        if k == 0 {
            cell(cx, cy);
            return;
        }
        for i in -k..=k {
            cell(cx + i, cy - k);
            cell(cx + i, cy + k);
        }
        for j in (1 - k)..k {
            cell(cx - k, cy + j);
            cell(cx + k, cy + j);
        }
    }

    /// Into `out`, in increasing order and once each, the segments sharing a cell with segment
    /// `i` (itself included): a superset of those with a point within `tol` of both.
    pub fn candidates(&self, i: usize, out: &mut Vec<u32>) {
        out.clear();
        self.each_cell(i, |c| out.extend(self.cells.get(&c).into_iter().flatten()));
        out.sort_unstable();
        out.dedup();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::segment_distance;
    use crate::joints::EdgeKind;

    /// Distance between two segments, m (they do not cross in these tests unless it is 0).
    fn gap(s: &Segment, o: &Segment) -> f64 {
        if crate::geometry::segments_intersect(s.a, s.b, o.a, o.b) {
            return 0.0;
        }
        [
            segment_distance(s.a, o.a, o.b),
            segment_distance(s.b, o.a, o.b),
            segment_distance(o.a, s.a, s.b),
            segment_distance(o.b, s.a, s.b),
        ]
        .into_iter()
        .fold(f64::INFINITY, f64::min)
    }

    /// The ring search finds the nearest segment: stopping at the first ring of cells beyond the
    /// best distance so far gives the distance every segment gives, at random points among random
    /// segments.
    #[test]
    fn rings_of_cells_find_the_nearest_segment() {
        let mut rng = crate::joints::SplitMix(11);
        let mut u = |a: f64, b: f64| a + (b - a) * (rng.next_u64() as f64 / u64::MAX as f64);
        let segs: Vec<Segment> = (0..300)
            .map(|_| {
                let (x, y, dip, len) = (u(-30.0, 30.0), u(-30.0, 30.0), u(0.0, 3.2), u(0.05, 4.0));
                Segment {
                    a: [x, y],
                    b: [x + len * dip.cos(), y + len * dip.sin()],
                    kind: EdgeKind::Joint(0),
                }
            })
            .collect();
        let grid = SegmentGrid::new(&segs, 0.3);
        for _ in 0..200 {
            let p = [u(-40.0, 40.0), u(-40.0, 40.0)];
            let exact = (segs.iter())
                .map(|s| segment_distance(p, s.a, s.b))
                .fold(f64::INFINITY, f64::min);
            let mut found = f64::INFINITY;
            let mut k = 0;
            while (k - 1) as f64 * grid.cell() <= found.min(1e3) {
                grid.ring(p, k, |e| {
                    let s = &segs[e as usize];
                    found = found.min(segment_distance(p, s.a, s.b));
                });
                k += 1;
            }
            assert_eq!(found, exact);
        }
    }

    /// Every pair of segments within 2 `tol` of each other (so some point lies within `tol` of
    /// both) is a candidate, on random segments of mixed lengths and directions; a long diagonal
    /// is entered in cells along its length only.
    #[test]
    fn candidates_hold_every_near_pair() {
        let mut rng = crate::joints::SplitMix(7);
        let mut u = |a: f64, b: f64| a + (b - a) * (rng.next_u64() as f64 / u64::MAX as f64);
        let segs: Vec<Segment> = (0..400)
            .map(|k| {
                let (x, y) = (u(-50.0, 50.0), u(-50.0, 50.0));
                let len = if k % 10 == 0 { 60.0 } else { u(0.1, 5.0) };
                let dip = if k % 50 == 1 {
                    0.5 * std::f64::consts::PI
                } else {
                    u(0.0, std::f64::consts::PI)
                };
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
                if gap(s, o) <= 2.0 * tol {
                    assert!(near.binary_search(&(j as u32)).is_ok(), "{i} {j}");
                }
            }
        }
        // One 100 m diagonal among 1 m segments: about 2 × 100 / cell columns' worth of cells
        // (its box would hold 100² / cell²).
        let mut long = segs[..1].to_vec();
        long[0] = Segment {
            a: [0.0, 0.0],
            b: [100.0, 100.0],
            kind: EdgeKind::Joint(0),
        };
        long.extend((0..99).map(|k| Segment {
            a: [k as f64, -5.0],
            b: [k as f64 + 1.0, -5.0],
            kind: EdgeKind::Joint(1),
        }));
        let grid = SegmentGrid::new(&long, 0.01);
        let mut cells = 0;
        grid.each_cell(0, |_| cells += 1);
        assert!(cells <= 400, "{cells} cells");
    }
}
