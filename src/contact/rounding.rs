//! Corner rounding of rigid and simple blocks (UDEC's `round`): each convex corner is replaced by
//! a circular arc of radius d tangent to its two edges, whose centre lies on the inward bisector at
//! d / sin(θ/2) from the vertex (θ the interior angle). A rounded corner touches a face at the
//! distance of its centre minus d and another rounded corner at the distance between centres minus
//! both radii, along the line of centres: corner-to-corner contacts get a well-defined normal
//! that turns smoothly, instead of jamming on the choice of an edge (Cundall 1988, "Formulation of
//! a three-dimensional distinct element model — Part I", on rounding).

use crate::model::blocks::{Blocks, NO_EDGE};

/// The corner at a node: its position, the unit directions of its incoming and outgoing boundary
/// edges (m, unitless) and their lengths (m).
struct Corner {
    p: [f64; 2],
    e1: [f64; 2],
    e2: [f64; 2],
    lengths: [f64; 2],
}

impl Corner {
    /// The corner at node `n`, or `None` if the node is not on a closed ring.
    fn at(blocks: &Blocks, x: &impl Fn(u32) -> [f64; 2], n: u32) -> Option<Corner> {
        let [inc, out] = blocks.node_edges[n as usize];
        if inc == NO_EDGE || out == NO_EDGE {
            return None;
        }
        let dir = |e: u32| {
            let [a, b] = blocks.edges[e as usize].map(x);
            let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
            let l = (dx * dx + dy * dy).sqrt();
            ([dx / l, dy / l], l)
        };
        let ((e1, l1), (e2, l2)) = (dir(inc), dir(out));
        Some(Corner {
            p: x(n),
            e1,
            e2,
            lengths: [l1, l2],
        })
    }

    /// The radius of its arc for a requested `d`, m: d at a convex corner, reduced where needed so
    /// that the arc's tangent points stay within a quarter of each edge (tangent length
    /// d / tan(θ/2)); 0 at straight and reflex corners.
    fn radius(&self, d: f64) -> f64 {
        let (e1, e2) = (self.e1, self.e2);
        let sin_turn = e1[0] * e2[1] - e1[1] * e2[0];
        if sin_turn <= 1e-6 {
            return 0.0;
        }
        let tan_half = (1.0 + e1[0] * e2[0] + e1[1] * e2[1]) / sin_turn;
        d.min(0.25 * self.lengths[0].min(self.lengths[1]) * tan_half)
    }

    /// The centre of its arc of radius `d`, m: c = x − 2d (n1 + n2)/|n1 + n2|², n1, n2 the
    /// outward normals of its edges (|n1 + n2| = 2 sin(θ/2)); the node itself when d = 0.
    fn centre(&self, d: f64) -> [f64; 2] {
        let p = self.p;
        if d == 0.0 {
            return p;
        }
        let s = [self.e1[1] + self.e2[1], -(self.e1[0] + self.e2[0])];
        let s2 = s[0] * s[0] + s[1] * s[1];
        [p[0] - 2.0 * d * s[0] / s2, p[1] - 2.0 * d * s[1] / s2]
    }
}

/// Centre of node n's rounding arc of radius `d`, m (`Corner::centre`), `x` giving current node
/// positions; the node itself when d = 0 or the node is on no closed ring.
pub fn centre(blocks: &Blocks, x: &impl Fn(u32) -> [f64; 2], n: u32, d: f64) -> [f64; 2] {
    match Corner::at(blocks, x, n) {
        Some(c) => c.centre(d),
        None => x(n),
    }
}

/// Rounding radius of each node, m: `d` at the convex corners of the blocks `rounded(b)` selects,
/// reduced where needed (`Corner::radius`); 0 elsewhere (deformable blocks, straight and reflex
/// corners).
pub fn radii(blocks: &Blocks, x: &[[f64; 2]], d: f64, rounded: impl Fn(usize) -> bool) -> Vec<f64> {
    let at = |v: u32| x[v as usize];
    let mut r = vec![0.0; x.len()];
    for b in (0..blocks.len()).filter(|&b| rounded(b)) {
        for e in blocks.edge_range(b) {
            let n = blocks.edges[e][0];
            r[n as usize] = Corner::at(blocks, &at, n).map_or(0.0, |c| c.radius(d));
        }
    }
    r
}

/// The arc a corner-to-corner contact at node `n` meets along the line of centres: its centre (m)
/// and radius (m), the node's rounding, or at a sharp node (round 0) the arc its corner would have
/// if rounded by `Blocks::sharp_round` (`Corner::radius`; none, the node itself, where straight or
/// reflex). Sharp corners so meet corners as rounded ones do (a normal along the line of centres,
/// turning smoothly as they pass each other; a gap between the arcs) while their faces stay sharp.
pub fn contact_arc(blocks: &Blocks, x: &impl Fn(u32) -> [f64; 2], n: u32) -> ([f64; 2], f64) {
    let Some(c) = Corner::at(blocks, x, n) else {
        return (x(n), 0.0);
    };
    let r = blocks.round_of(n);
    let r = if r > 0.0 {
        r
    } else {
        c.radius(blocks.sharp_round)
    };
    (c.centre(r), r)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit square ring, counter-clockwise.
    fn square() -> (Blocks, Vec<[f64; 2]>) {
        let x = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let blocks = Blocks {
            node_start: vec![0, 4],
            zone_start: vec![0, 0],
            edge_start: vec![0, 4],
            edges: vec![[0, 1], [1, 2], [2, 3], [3, 0]],
            edge_kind: vec![adit_meshing::EdgeKind::Region(0); 4],
            node_edges: vec![[3, 0], [0, 1], [1, 2], [2, 3]],
            edge_across: vec![],
            round: vec![],
            sharp_round: 0.0,
            removed: vec![],
        };
        (blocks, x)
    }

    #[test]
    fn square_corner_centre_is_inset_by_the_radius_on_both_edges() {
        let (b, x) = square();
        let c = centre(&b, &|v: u32| x[v as usize], 0, 0.1);
        assert!(
            (c[0] - 0.1).abs() < 1e-15 && (c[1] - 0.1).abs() < 1e-15,
            "{c:?}"
        );
        let r = radii(&b, &x, 0.1, |_| true);
        assert_eq!(r, vec![0.1; 4]);
        // Capped at a quarter of the edge for a right angle (tan 45° = 1).
        assert_eq!(radii(&b, &x, 0.5, |_| true), vec![0.25; 4]);
    }
}
