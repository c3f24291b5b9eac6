//! Sliver repair (issue 14): a joint that meets a wall, the region's edge or another joint at a
//! tiny angle, or runs closer to one than the zoning can follow, leaves a block whose zones are
//! needles; one zone under `zoning.accept_angle` would set a tiny time step. Instead of refusing
//! the scene, the piece of that joint between its two crossings nearest the needle is dropped (its
//! trace then ends at those crossings, as a joint may), the region is cut and zoned again, and the
//! repair is reported as a warning. Walls and region edges never move.

use adit_meshing::geometry::{orient, segment_distance};
use adit_meshing::{Block, Domain, EdgeKind, Point, Segment};

/// Most joint pieces dropped for one scene; past it the sharpest zone is refused as before.
pub const MAX_REPAIRS: usize = 64;

/// Parameter t ∈ (0, 1) along ab where it properly crosses cd, if it does.
fn crossing(a: Point, b: Point, c: Point, d: Point) -> Option<f64> {
    let (d1, d2) = (orient(c, d, a), orient(c, d, b));
    let (d3, d4) = (orient(a, b, c), orient(a, b, d));
    let opposite = |x: f64, y: f64| (x > 0.0 && y < 0.0) || (x < 0.0 && y > 0.0);
    (opposite(d1, d2) && opposite(d3, d4)).then(|| d1 / (d1 - d2))
}

/// Point at parameter t along ab.
fn lerp(a: Point, b: Point, t: f64) -> Point {
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
}

/// How much farther than the block's nearest edge a joint edge may be from a needle zone and still
/// be taken as what made it (a needle between a joint and a wall lies close to both).
const BESIDE: f64 = 4.0;

/// The joint that made a needle zone at `at` in `block`: the kind of the block's nearest joint
/// edge, if it lies within `BESIDE` times the distance of the block's nearest edge of any kind
/// (a needle between two walls, or inside the block, has none), and the index of the segment of
/// that joint nearest `at`.
pub fn joint_beside(block: &Block, joints: &[Segment], at: Point) -> Option<usize> {
    let rings = std::iter::once((&block.outer, &block.outer_kinds))
        .chain(block.holes.iter().zip(&block.hole_kinds));
    let edges = rings.flat_map(|(p, kinds)| (0..p.len()).map(move |k| (p.edge(k), kinds[k])));
    let (mut nearest, mut joint) = (f64::INFINITY, None::<(f64, EdgeKind)>);
    for ((a, b), kind) in edges {
        let d = segment_distance(at, a, b);
        nearest = nearest.min(d);
        if matches!(kind, EdgeKind::Joint(_)) && joint.is_none_or(|(dj, _)| d < dj) {
            joint = Some((d, kind));
        }
    }
    let (d, kind) = joint?;
    if d > BESIDE * nearest + 1e-12 {
        return None;
    }
    joints
        .iter()
        .enumerate()
        .filter(|(_, s)| s.kind == kind)
        .map(|(i, s)| (i, segment_distance(at, s.a, s.b)))
        .min_by(|x, y| x.1.total_cmp(&y.1))
        .map(|(i, _)| i)
}

/// Remove from joint `i` the piece between its crossings (with the other joints, the region's
/// edges and the holes' walls) that holds the point of the joint nearest `at`; what remains of
/// the trace on either side stays. Returns the dropped piece's ends.
pub fn drop_piece(joints: &mut Vec<Segment>, i: usize, at: Point, domain: &Domain) -> [Point; 2] {
    let s = joints[i];
    let (a, b) = (s.a, s.b);
    let walls = std::iter::once(&domain.outer)
        .chain(domain.holes.iter().map(|h| &h.polygon))
        .flat_map(|p| (0..p.len()).map(|k| p.edge(k)));
    let others = joints
        .iter()
        .enumerate()
        .filter(|&(k, _)| k != i)
        .map(|(_, o)| (o.a, o.b));
    let mut ts: Vec<f64> = walls
        .chain(others)
        .filter_map(|(c, d)| crossing(a, b, c, d))
        .collect();
    ts.sort_by(f64::total_cmp);
    let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
    let len2 = (ex * ex + ey * ey).max(f64::MIN_POSITIVE);
    let t = (((at[0] - a[0]) * ex + (at[1] - a[1]) * ey) / len2).clamp(0.0, 1.0);
    let lo = ts.iter().copied().filter(|&x| x <= t).fold(0.0, f64::max);
    let hi = ts.iter().copied().filter(|&x| x > t).fold(1.0, f64::min);
    let (pa, pb) = (lerp(a, b, lo), lerp(a, b, hi));
    joints.swap_remove(i);
    if lo > 0.0 {
        joints.push(Segment { b: pa, ..s });
    }
    if hi < 1.0 {
        joints.push(Segment { a: pb, ..s });
    }
    [pa, pb]
}

#[cfg(test)]
mod tests {
    use super::*;
    use adit_meshing::Polygon;

    fn joint(a: Point, b: Point, k: u32) -> Segment {
        Segment {
            a,
            b,
            kind: EdgeKind::Joint(k),
        }
    }

    /// A joint crossing a box and two others loses only the piece between the crossings around
    /// the point; the other joints and the pieces beyond stay.
    #[test]
    fn only_the_piece_between_crossings_is_dropped() {
        let domain = Domain {
            outer: Polygon::new(vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]),
            outer_edge_names: vec![],
            holes: vec![],
        };
        let mut joints = vec![
            joint([-1.0, 5.0], [11.0, 5.0], 0),
            joint([3.0, 0.0], [3.0, 10.0], 1),
            joint([6.0, 0.0], [6.0, 10.0], 1),
        ];
        let [pa, pb] = drop_piece(&mut joints, 0, [4.5, 5.01], &domain);
        assert!(
            (pa[0] - 3.0).abs() < 1e-12 && (pb[0] - 6.0).abs() < 1e-12,
            "{pa:?} {pb:?}"
        );
        assert_eq!(joints.len(), 4);
        let horizontal: Vec<&Segment> = joints.iter().filter(|s| s.a[1] == s.b[1]).collect();
        assert_eq!(horizontal.len(), 2);
        assert!(
            horizontal
                .iter()
                .all(|s| s.b[0] <= 3.0 + 1e-12 || s.a[0] >= 6.0 - 1e-12)
        );
    }
}
