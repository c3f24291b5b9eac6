//! Plane geometry on `[f64; 2]` points: polygon area, containment, segment intersection and
//! distances, all in metres.

use crate::joints::{EdgeKind, Segment};
use crate::segment_grid::SegmentGrid;

/// A point in the plane, (x, y) in metres.
pub type Point = [f64; 2];

/// A simple polygon given by its vertices in order (either orientation), metres.
#[derive(Debug, Clone, PartialEq)]
pub struct Polygon {
    pub vertices: Vec<Point>,
}

impl Polygon {
    pub fn new(vertices: Vec<Point>) -> Self {
        Polygon { vertices }
    }

    /// A regular polygon inscribed in the circle of `radius` (m) about `center`, `segments` vertices,
    /// the first at angle 0 (on the +x axis), counter-clockwise.
    pub fn circle(center: Point, radius: f64, segments: usize) -> Self {
        let vertices = (0..segments)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / segments as f64;
                [center[0] + radius * t.cos(), center[1] + radius * t.sin()]
            })
            .collect();
        Polygon { vertices }
    }

    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    pub fn is_empty(&self) -> bool {
        self.vertices.is_empty()
    }

    /// Edge `i` as its two end points (from vertex i to vertex i+1, wrapping).
    pub fn edge(&self, i: usize) -> (Point, Point) {
        let n = self.vertices.len();
        (self.vertices[i], self.vertices[(i + 1) % n])
    }

    /// Signed area (m²) by the shoelace formula, positive when counter-clockwise.
    pub fn signed_area(&self) -> f64 {
        let n = self.vertices.len();
        (0..n)
            .map(|i| {
                let (a, b) = self.edge(i);
                a[0] * b[1] - b[0] * a[1]
            })
            .sum::<f64>()
            * 0.5
    }

    /// Perimeter (m): the sum of the edge lengths.
    pub fn perimeter(&self) -> f64 {
        (0..self.vertices.len())
            .map(|i| {
                let (a, b) = self.edge(i);
                distance(a, b)
            })
            .sum()
    }

    /// Centroid of the enclosed area (m).
    pub fn centroid(&self) -> Point {
        let n = self.vertices.len();
        let (mut cx, mut cy) = (0.0, 0.0);
        for i in 0..n {
            let (a, b) = self.edge(i);
            let c = a[0] * b[1] - b[0] * a[1];
            cx += (a[0] + b[0]) * c;
            cy += (a[1] + b[1]) * c;
        }
        let a6 = 6.0 * self.signed_area();
        [cx / a6, cy / a6]
    }

    /// Largest extent of the polygon's bounding box (m), used as a length scale for tolerances.
    pub fn size(&self) -> f64 {
        let (lo, hi) = self.bounds();
        (hi[0] - lo[0]).max(hi[1] - lo[1])
    }

    /// Bounding box as (min corner, max corner), m.
    pub fn bounds(&self) -> (Point, Point) {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in &self.vertices {
            for d in 0..2 {
                lo[d] = lo[d].min(p[d]);
                hi[d] = hi[d].max(p[d]);
            }
        }
        (lo, hi)
    }

    /// Whether `p` is strictly inside (even–odd ray crossing; points on the boundary are unreliable).
    pub fn contains(&self, p: Point) -> bool {
        let n = self.vertices.len();
        let mut inside = false;
        let mut j = n - 1;
        for i in 0..n {
            let (a, b) = (self.vertices[i], self.vertices[j]);
            if (a[1] > p[1]) != (b[1] > p[1]) {
                let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                if p[0] < x {
                    inside = !inside;
                }
            }
            j = i;
        }
        inside
    }

    /// Distance (m) from `p` to the polygon's boundary.
    pub fn boundary_distance(&self, p: Point) -> f64 {
        (0..self.len())
            .map(|i| {
                let (a, b) = self.edge(i);
                segment_distance(p, a, b)
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// The first pair (i < j, by i then j) of non-adjacent edges that intersect, if any; pairs
    /// come from a grid of the edges, so a 100 000-vertex region is checked in well under a second.
    pub fn self_intersection(&self) -> Option<(usize, usize)> {
        let n = self.len();
        let grid = SegmentGrid::new(&self.segments(), 1e-9 * self.size());
        let mut near = Vec::new();
        for i in 0..n {
            grid.candidates(i, &mut near);
            for j in near.iter().map(|&j| j as usize).filter(|&j| j > i) {
                let adjacent = j == i + 1 || (i == 0 && j == n - 1);
                let ((a, b), (c, d)) = (self.edge(i), self.edge(j));
                if !adjacent && segments_intersect(a, b, c, d) {
                    return Some((i, j));
                }
            }
        }
        None
    }

    /// Whether segment ab has a point inside or on the polygon: an end inside, or a crossing of
    /// an edge.
    pub fn meets_segment(&self, a: Point, b: Point) -> bool {
        self.contains(a)
            || self.contains(b)
            || (0..self.len()).any(|i| {
                let (c, d) = self.edge(i);
                segments_intersect(a, b, c, d)
            })
    }

    /// Whether the boundaries of `self` and `other` share a point (touching counts).
    pub fn touches(&self, other: &Polygon) -> bool {
        let mut segs = self.segments();
        segs.extend(other.segments());
        let grid = SegmentGrid::new(&segs, 1e-9 * self.size().max(other.size()));
        let mut near = Vec::new();
        (0..self.len()).any(|i| {
            grid.candidates(i, &mut near);
            near.iter()
                .map(|&j| j as usize)
                .filter(|&j| j >= self.len())
                .any(|j| {
                    let ((a, b), (c, d)) = (self.edge(i), other.edge(j - self.len()));
                    segments_intersect(a, b, c, d)
                })
        })
    }

    /// The edges as segments (edge i of kind `Region(i)`, a placeholder), for a `SegmentGrid`.
    fn segments(&self) -> Vec<Segment> {
        (0..self.len())
            .map(|i| {
                let (a, b) = self.edge(i);
                Segment {
                    a,
                    b,
                    kind: EdgeKind::Region(i as u32),
                }
            })
            .collect()
    }
}

/// Cross product (b − a) × (c − a), m².
pub fn orient(a: Point, b: Point, c: Point) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Whether closed segments ab and cd share a point (touching counts). Segments on one line (to
/// round-off) are compared by their extents along it, so nearly collinear disjoint pieces of one
/// joint are not mistaken for crossing ones.
pub fn segments_intersect(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (d1, d2) = (orient(c, d, a), orient(c, d, b));
    let (d3, d4) = (orient(a, b, c), orient(a, b, d));
    let lcd = distance(c, d);
    let reach = lcd + distance(a, c) + distance(b, c);
    if d1.abs() + d2.abs() <= 1e-12 * lcd * reach {
        // Collinear: overlap of the parameter ranges along cd.
        let e = [(d[0] - c[0]) / lcd, (d[1] - c[1]) / lcd];
        let t = |p: Point| (p[0] - c[0]) * e[0] + (p[1] - c[1]) * e[1];
        let (ta, tb) = (t(a), t(b));
        let tol = 1e-12 * reach;
        return ta.min(tb) <= lcd + tol && ta.max(tb) >= -tol;
    }
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
    {
        return true;
    }
    let on = |p: Point, q: Point, r: Point, o: f64| {
        o == 0.0
            && r[0] >= p[0].min(q[0])
            && r[0] <= p[0].max(q[0])
            && r[1] >= p[1].min(q[1])
            && r[1] <= p[1].max(q[1])
    };
    on(c, d, a, d1) || on(c, d, b, d2) || on(a, b, c, d3) || on(a, b, d, d4)
}

/// Distance (m) from point `p` to the closed segment ab.
pub fn segment_distance(p: Point, a: Point, b: Point) -> f64 {
    let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
    let len2 = ex * ex + ey * ey;
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let (dx, dy) = (a[0] + t * ex - p[0], a[1] + t * ey - p[1]);
    (dx * dx + dy * dy).sqrt()
}

/// Euclidean distance (m).
pub fn distance(a: Point, b: Point) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn square_area_centroid_and_containment() {
        let sq = Polygon::new(vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]);
        assert_relative_eq!(sq.signed_area(), 4.0);
        assert_eq!(sq.centroid(), [1.0, 1.0]);
        assert!(sq.contains([1.0, 1.5]));
        assert!(!sq.contains([2.5, 1.0]));
        assert!(sq.self_intersection().is_none());
    }

    #[test]
    fn bow_tie_is_self_intersecting() {
        let bow = Polygon::new(vec![[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]]);
        assert_eq!(bow.self_intersection(), Some((0, 2)));
    }

    #[test]
    fn collinear_segments_touch_only_when_they_overlap() {
        // Two pieces of one inclined line, far apart: not intersecting, whatever the round-off.
        let (a, b) = (
            [1.677469769677792, -4.90181328573331],
            [0.9974121890959609, -4.291005041840997],
        );
        let (c, d) = (
            [-8.523393939049665, 4.260310372651376],
            [-9.203451519631496, 4.871118616543689],
        );
        assert!(!segments_intersect(a, b, c, d));
        assert!(segments_intersect(
            [0.0, 0.0],
            [2.0, 0.0],
            [1.0, 0.0],
            [3.0, 0.0]
        ));
        assert!(segments_intersect(
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 0.0],
            [3.0, 0.0]
        ));
        assert!(!segments_intersect(
            [0.0, 0.0],
            [1.0, 0.0],
            [1.5, 0.0],
            [3.0, 0.0]
        ));
    }

    #[test]
    fn circle_area_converges() {
        let c = Polygon::circle([0.0, 0.0], 1.0, 256);
        assert_relative_eq!(c.signed_area(), std::f64::consts::PI, max_relative = 1e-3);
    }
}
