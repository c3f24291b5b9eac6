//! Point queries on a polygon with many vertices in time independent of its size: containment by
//! horizontal strips of its edges, and nearness to its boundary by a grid. A region traced from a
//! terrain model (100 000 vertices) is asked about every block, joint piece and hole of the cut;
//! each `Polygon::contains` walked all its edges.

use crate::geometry::{Point, Polygon, segment_distance};
use crate::joints::{EdgeKind, Segment};
use crate::segment_grid::SegmentGrid;

/// A polygon's edges in horizontal strips (each edge in every strip its y range meets) and in a
/// `SegmentGrid` of half-width `tol`.
pub struct PolygonIndex<'a> {
    polygon: &'a Polygon,
    /// Bottom of the first strip, m.
    y0: f64,
    /// Strip height, m.
    height: f64,
    /// Edges (i: vertex i−1 → i, as `Polygon::contains` walks them) of each strip.
    strips: Vec<Vec<u32>>,
    near: SegmentGrid,
    /// Distance within which a point is near the boundary, m.
    tol: f64,
}

impl<'a> PolygonIndex<'a> {
    /// Index `polygon` for `contains` and for `near_boundary` within `tol` (m). Strips are as high
    /// as the polygon's total rise and fall over 3 n (but at least its height over n), so the
    /// strips hold at most 4 n entries however the boundary winds.
    pub fn new(polygon: &'a Polygon, tol: f64) -> PolygonIndex<'a> {
        let n = polygon.len().max(1);
        let (lo, hi) = polygon.bounds();
        let rise: f64 = (0..polygon.len())
            .map(|i| {
                let (a, b) = polygon.edge(i);
                (b[1] - a[1]).abs()
            })
            .sum();
        let height = ((hi[1] - lo[1]) / n as f64)
            .max(rise / (3 * n) as f64)
            .max(f64::MIN_POSITIVE);
        let strip = |y: f64| ((y - lo[1]) / height).floor().max(0.0) as usize;
        let mut strips = vec![Vec::new(); strip(hi[1]) + 1];
        let v = &polygon.vertices;
        for i in 0..polygon.len() {
            let (a, b) = (v[i], v[(i + polygon.len() - 1) % polygon.len()]);
            for s in strips
                .iter_mut()
                .take(strip(a[1].max(b[1])) + 1)
                .skip(strip(a[1].min(b[1])))
            {
                s.push(i as u32);
            }
        }
        let segments: Vec<Segment> = (0..polygon.len())
            .map(|i| {
                let (a, b) = polygon.edge(i);
                Segment {
                    a,
                    b,
                    kind: EdgeKind::Region(i as u32),
                }
            })
            .collect();
        PolygonIndex {
            polygon,
            y0: lo[1],
            height,
            strips,
            near: SegmentGrid::new(&segments, tol),
            tol,
        }
    }

    /// `Polygon::contains(p)`, exactly: the same crossings, counted over the edges of `p`'s strip
    /// (an edge can cross p's ray only if its y range holds p's y, so it is in that strip).
    pub fn contains(&self, p: Point) -> bool {
        if p[1].is_nan() || p[1] < self.y0 {
            return false;
        }
        let Some(edges) = self
            .strips
            .get(((p[1] - self.y0) / self.height).floor() as usize)
        else {
            return false;
        };
        let v = &self.polygon.vertices;
        let n = v.len();
        let mut inside = false;
        for &i in edges {
            let i = i as usize;
            let (a, b) = (v[i], v[(i + n - 1) % n]);
            if (a[1] > p[1]) != (b[1] > p[1]) {
                let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                if p[0] < x {
                    inside = !inside;
                }
            }
        }
        inside
    }

    /// Whether `p` lies within `tol` of the boundary (`boundary_distance(p) <= tol`).
    pub fn near_boundary(&self, p: Point) -> bool {
        self.near.at(p).iter().any(|&i| {
            let (a, b) = self.polygon.edge(i as usize);
            segment_distance(p, a, b) <= self.tol
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::joints::SplitMix;

    /// On random star-shaped polygons (a few hundred vertices, some boundaries winding hard) and
    /// random points, some on vertices and edges: the index answers exactly as the polygon does.
    #[test]
    fn answers_as_the_polygon_does() {
        let mut rng = SplitMix(11);
        let mut u = |a: f64, b: f64| a + (b - a) * (rng.next_u64() as f64 / u64::MAX as f64);
        for case in 0..40 {
            let n = 3 + (u(0.0, 400.0) as usize);
            let wild = case % 3 == 0;
            let vertices: Vec<Point> = (0..n)
                .map(|k| {
                    let t = std::f64::consts::TAU * k as f64 / n as f64;
                    let r = if wild { u(0.1, 10.0) } else { u(4.0, 5.0) };
                    [1.0 + r * t.cos(), -2.0 + r * t.sin()]
                })
                .collect();
            let poly = Polygon::new(vertices);
            let tol = 0.05;
            let index = PolygonIndex::new(&poly, tol);
            for k in 0..500 {
                let p = match k % 5 {
                    0 => poly.vertices[k % n],
                    1 => {
                        let (a, b) = poly.edge(k % n);
                        let s = u(0.0, 1.0);
                        [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])]
                    }
                    _ => [u(-10.0, 12.0), u(-13.0, 9.0)],
                };
                assert_eq!(
                    index.contains(p),
                    poly.contains(p),
                    "case {case} point {p:?}"
                );
                assert_eq!(
                    index.near_boundary(p),
                    poly.boundary_distance(p) <= tol,
                    "case {case} point {p:?}"
                );
            }
        }
    }
}
