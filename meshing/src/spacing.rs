//! Where the nodes of the zoned blocks go along their boundaries, decided once for all blocks, so
//! that the two blocks on either side of a joint put their nodes at the same places.
//!
//! Zoned each on its own, the two sides of a joint got nodes in different places: the refinement
//! split a thin block's edges where the block across kept them whole. Each contact stands for half
//! of its node's edges, which loads a node as its zones' stress does only where the nodes of the
//! two sides face each other; elsewhere a node was loaded by up to its edge's whole stress too much
//! or too little (1.9e7 N/m at 29 MPa), and no jointed model was at rest in its in-situ stress
//! (`models/tunnel.json` settled for 1 970 cycles before anything was excavated).
//!
//! So every block edge is split here, by a rule that sees only the edge and the blocks beside it,
//! from its lower end (by coordinates), and the refinement then keeps the split edges whole. The
//! spacing at a point p of an edge is
//!
//! `s(p) = max(min(h(p), f(p)), h_exc / 4)`,
//!
//! with h the graded target size of the zoning and f the local feature size: the distance from p to
//! the nearest edge of the blocks beside the edge that does not share one of its ends (the far face
//! of a thin block, the next joint across it). Spaced at most f, a split edge is encroached by no
//! vertex across the block (Ruppert's refinement splits an edge whose diametral circle holds a
//! vertex; Shewchuk, *Delaunay refinement algorithms for triangular mesh generation*, 2002, §3), so
//! keeping it whole costs the refinement little there. The floor h_exc / 4 bounds the work where
//! two edges come closer than that (a block thinner than h_exc / 2 is warned of, and the scene's
//! `blocks.thin` can take it out of the zoning). Near each vertex the pieces start from the
//! shortest first piece of any edge there (`split`). Where a zone the refinement could not mend
//! still encroaches a piece (its circumcentre, which Ruppert's rule would not insert but split the
//! piece for), the piece is split for both blocks beside it and they are zoned again
//! (`split_encroached`, `triangulate::triangulate_blocks`).
//!
//! A block that shares no edge with another zoned block (an unjointed model) is zoned as before:
//! its edges split to h from the end its ring meets first, and refined freely (`split_alone`).

use crate::Map;

use crate::blocks::{Block, ring_segments};
use crate::geometry::{Point, Polygon, distance, segment_distance};
use crate::joints::Segment;
use crate::segment_grid::SegmentGrid;
use crate::triangulate::{TriMesh, Zoning, smallest_angle};

/// A vertex's key: its coordinates' bits (−0.0 taken as +0.0), the same in every block that has it.
pub type Key = (u64, u64);

/// The key of point `p`.
pub fn key(p: Point) -> Key {
    ((p[0] + 0.0).to_bits(), (p[1] + 0.0).to_bits())
}

/// A block's corner sharper than this, degrees, makes zones that splitting its edges does not
/// mend (two zones of half its angle at best, under a 28° aim below 56°).
const SHARP_CORNER: f64 = 60.0;

/// Zones at or above this angle, degrees, split no piece of edge that two zoned blocks share
/// (`split_encroached`): the split costs both blocks zones.
const MENDED: f64 = 20.0;

/// No block (the second owner of an edge only one zoned block has).
const NONE: u32 = u32::MAX;

/// The split points of every zoned block's edges: the zoning, the walls it grades from, and the
/// zoned blocks' edges with the blocks that own them.
pub struct BoundarySpacing {
    zoning: Zoning,
    excavations: Vec<Polygon>,
    /// Every edge of every zoned block (an edge two blocks share, twice), m.
    edges: Vec<Segment>,
    /// The block of each of `edges`.
    block: Vec<u32>,
    /// `edges` by the cells they pass through.
    grid: SegmentGrid,
    /// The (at most two) zoned blocks that own each undirected edge, by its ends' keys (lower first).
    owners: Map<(Key, Key), [u32; 2]>,
    /// Whether each block shares an edge with another zoned block (`shares_an_edge`), by index.
    shares: Vec<bool>,
    /// The first piece of every edge at each vertex, m (`split`).
    corner: Map<Key, f64>,
    /// Points added on edges where a zoning's refinement wanted to split them
    /// (`split_encroached`), by the edge's ends' keys (lower first).
    extra: Map<(Key, Key), Vec<Point>>,
}

impl BoundarySpacing {
    /// The spacing for the blocks `blocks` of which `zoned` are zoned (the others are rigid or
    /// simple: their nodes are their corners whatever is done here), graded from `excavations`.
    pub fn new(
        blocks: &[Block],
        zoned: &[bool],
        excavations: &[Polygon],
        zoning: &Zoning,
    ) -> BoundarySpacing {
        let mut edges = Vec::new();
        let mut block = Vec::new();
        let mut owners: Map<(Key, Key), [u32; 2]> = Map::default();
        for (b, blk) in blocks.iter().enumerate().filter(|&(b, _)| zoned[b]) {
            for edge in ring_segments(constrained_rings(blk)) {
                let (ka, kc) = (key(edge.a), key(edge.b));
                if ka == kc {
                    continue;
                }
                edges.push(edge);
                block.push(b as u32);
                let own = owners.entry((ka.min(kc), ka.max(kc))).or_insert([NONE; 2]);
                if own[0] == NONE || own[0] == b as u32 {
                    own[0] = b as u32;
                } else {
                    own[1] = b as u32;
                }
            }
        }
        let mut shares = vec![false; blocks.len()];
        for own in owners.values().filter(|o| o[1] != NONE) {
            for &b in own {
                shares[b as usize] = true;
            }
        }
        // Cells of at least h_far / 8: a search stops within 9 rings of cells.
        let grid = SegmentGrid::new(&edges, zoning.h_far / 32.0);
        let mut spacing = BoundarySpacing {
            zoning: *zoning,
            excavations: excavations.to_vec(),
            edges,
            block,
            grid,
            owners,
            shares,
            corner: Map::default(),
            extra: Map::default(),
        };
        let mut corner: Map<Key, f64> = Map::default();
        for e in &spacing.edges {
            let len = distance(e.a, e.b);
            for p in [e.a, e.b] {
                let piece = spacing.edge_size(p, e.a, e.b).min(len);
                let c = corner.entry(key(p)).or_insert(f64::INFINITY);
                *c = c.min(piece);
            }
        }
        spacing.corner = corner;
        spacing
    }

    /// Whether block `b` shares an edge with another zoned block: its zoning must keep its edges
    /// as split here (a block that shares none is refined freely, as Ruppert's refinement splits
    /// edges).
    pub fn shares_an_edge(&self, b: usize) -> bool {
        self.shares[b]
    }

    /// The zoning the spacing was made for.
    pub fn zoning(&self) -> &Zoning {
        &self.zoning
    }

    /// The excavation walls the zone size grades from.
    pub fn excavations(&self) -> &[Polygon] {
        &self.excavations
    }

    /// Target zone edge length at `p`, m, graded from the excavation walls:
    /// `Zoning::size_at` of the distance d(p) to the nearest wall.
    pub fn target(&self, p: Point) -> f64 {
        let z = &self.zoning;
        let d = self
            .excavations
            .iter()
            .map(|h| h.boundary_distance(p))
            .fold(f64::INFINITY, f64::min);
        if d.is_finite() { z.size_at(d) } else { z.h_far }
    }

    /// The split points of the edge a–b of a block that shares no edge with another zoned block,
    /// in order from a: pieces of the graded size h (`target`), from a. (Split from a, and refined
    /// freely, such a block is zoned as before the blocks' zonings were made alike: an unjointed
    /// model's zones did not change.)
    pub fn split_alone(&self, a: Point, b: Point) -> Vec<Point> {
        split_segment(a, b, |p| self.target(p))
    }

    /// The split points of the edge a–b, in order from a: the same points, in reverse order, as
    /// those of b–a, whichever block asks. Pieces are `edge_size` long, and near each end v no
    /// longer than `c(v) + |p − v| / 2`, where c(v) is the shortest first piece of any edge at v
    /// (`corner`): the edges meeting at a vertex are split at the same distance from it and grow
    /// alike, so none is encroached by its neighbour's first split point (Ruppert's concentric
    /// shells; Shewchuk 2002, §4), which the refinement, keeping the edges whole, could not mend.
    pub fn split(&self, a: Point, b: Point) -> Vec<Point> {
        if key(b) < key(a) {
            let mut points = self.split(b, a);
            points.reverse();
            return points;
        }
        let corner = |v: Point| self.corner.get(&key(v)).copied().unwrap_or(f64::INFINITY);
        let (ca, cb) = (corner(a), corner(b));
        let mut points = split_segment(a, b, |p| {
            let graded = (ca + 0.5 * distance(p, a)).min(cb + 0.5 * distance(p, b));
            self.edge_size(p, a, b).min(graded)
        });
        if let Some(extra) = self.extra.get(&(key(a), key(b))) {
            points.extend(extra);
            points.sort_by(|p, q| distance(a, *p).total_cmp(&distance(a, *q)));
        }
        points
    }

    /// Split, for the zonings `meshes` of `blocks` (`None` for a block not zoned), each boundary
    /// piece a zone the refinement could not mend encroaches: a zone under the angle its zoning
    /// aimed at whose circumcentre lies within the piece's diametral circle (on a piece two zoned
    /// blocks share, whose split both take, only a zone under `MENDED` as well). Keeping the edges
    /// whole, the refinement does not add such a circumcentre (Ruppert's rule would split the
    /// piece instead); here the piece is split at its middle for both blocks beside it, the same
    /// point for each. A zone whose smallest angle is at a corner of the block sharper than
    /// `SHARP_CORNER` is left (such a corner makes zones no split mends: split, the pieces at a joint
    /// that left a wall at a grazing angle put nodes where the contacts of the wedge between them
    /// no longer balance the in-situ stress), and so are pieces shorter than `h_exc / 8`.
    /// Returns the blocks to zone again.
    pub fn split_encroached(&mut self, blocks: &[Block], meshes: &[Option<&TriMesh>]) -> Vec<bool> {
        let mut again = vec![false; blocks.len()];
        for (b, (block, mesh)) in blocks.iter().zip(meshes).enumerate() {
            // A block that shares no edge was refined freely: Ruppert's refinement split its edges.
            let Some(mesh) = mesh.filter(|_| self.shares_an_edge(b)) else {
                continue;
            };
            let ring = RingEdges::of(block);
            // A piece of edge only this block has is split where a vertex lies within its
            // diametral circle (the angle facing it over 90°), as Ruppert's refinement splits it.
            let apex: Map<(u32, u32), u32> = (mesh.triangles.iter())
                .flat_map(|t| (0..3).map(move |k| ((t[k], t[(k + 1) % 3]), t[(k + 2) % 3])))
                .collect();
            for e in &mesh.boundary {
                let [q, r] = e.nodes.map(|n| mesh.points[n as usize]);
                let Some(&v) = apex
                    .get(&(e.nodes[0], e.nodes[1]))
                    .or_else(|| apex.get(&(e.nodes[1], e.nodes[0])))
                else {
                    continue;
                };
                let v = mesh.points[v as usize];
                let facing = (q[0] - v[0]) * (r[0] - v[0]) + (q[1] - v[1]) * (r[1] - v[1]);
                if facing < 0.0 {
                    self.split_piece(&ring, q, r, false, &mut again);
                }
            }
            for t in &mesh.triangles {
                let p = t.map(|v| mesh.points[v as usize]);
                let angle = smallest_angle(p);
                let aim = mesh.angle_limit_deg - 0.5;
                if angle >= aim || ring.corner_at(sharpest(p)) < SHARP_CORNER {
                    continue;
                }
                let c = circumcentre(p);
                for e in &mesh.boundary {
                    let [q, r] = e.nodes.map(|n| mesh.points[n as usize]);
                    let mid = [0.5 * (q[0] + r[0]), 0.5 * (q[1] + r[1])];
                    if distance(c, mid) < 0.5 * distance(q, r) {
                        self.split_piece(&ring, q, r, angle < MENDED, &mut again);
                    }
                }
            }
        }
        again
    }

    /// Split the piece q–r of a block edge (`ring`) at its middle, if it is no shorter than
    /// `h_exc / 8` and, when two zoned blocks share it, `shared_too`; mark its blocks in `again`.
    fn split_piece(
        &mut self,
        ring: &RingEdges,
        q: Point,
        r: Point,
        shared_too: bool,
        again: &mut [bool],
    ) {
        let mid = [0.5 * (q[0] + r[0]), 0.5 * (q[1] + r[1])];
        if distance(q, r) < self.zoning.h_excavation / 8.0 {
            return;
        }
        let Some(edge) = ring.under(mid) else {
            return;
        };
        let owners = self.owners.get(&edge).copied().unwrap_or([NONE; 2]);
        if owners[1] != NONE && !shared_too {
            return;
        }
        let points = self.extra.entry(edge).or_default();
        if points.iter().any(|&m| key(m) == key(mid)) {
            return;
        }
        points.push(mid);
        for o in owners.into_iter().filter(|&o| o != NONE) {
            again[o as usize] = true;
        }
    }

    /// The spacing at `p` on the edge a–b, m: `max(min(h(p), f(p)), h_exc / 4)`, with f the
    /// distance to the nearest edge of the zoned blocks beside a–b that shares neither of its ends
    /// (at most h(p) looked for).
    fn edge_size(&self, p: Point, a: Point, b: Point) -> f64 {
        let (ka, kb) = (key(a), key(b));
        let owners = self
            .owners
            .get(&(ka.min(kb), ka.max(kb)))
            .copied()
            .unwrap_or([NONE; 2]);
        let h = self.target(p);
        let mut f = h;
        // Rings of cells outward from p, until they lie farther than the nearest edge found.
        let mut k = 0;
        while (k - 1) as f64 * self.grid.cell() <= f {
            self.grid.ring(p, k, |e| {
                let (e, owner) = (&self.edges[e as usize], self.block[e as usize]);
                if !owners.contains(&owner) {
                    return;
                }
                let (ke, kf) = (key(e.a), key(e.b));
                if ke == ka || ke == kb || kf == ka || kf == kb {
                    return;
                }
                f = f.min(segment_distance(p, e.a, e.b));
            });
            k += 1;
        }
        f.max((0.25 * self.zoning.h_excavation).min(h))
    }
}

/// The constrained edges of a block, to find the one under a point.
struct RingEdges {
    edges: Vec<Segment>,
    grid: SegmentGrid,
    tol: f64,
    /// The block's angle at each of its corners, degrees (the least where rings touch).
    corners: Map<Key, f64>,
}

impl RingEdges {
    fn of(block: &Block) -> RingEdges {
        let edges = ring_segments(constrained_rings(block));
        let tol = 1e-9 * block.outer.size();
        let grid = SegmentGrid::new(&edges, tol);
        let mut corners: Map<Key, f64> = Map::default();
        for (ring, _) in constrained_rings(block) {
            let n = ring.len();
            for i in 0..n {
                let (prev, v, next) = (
                    ring.vertices[(i + n - 1) % n],
                    ring.vertices[i],
                    ring.vertices[(i + 1) % n],
                );
                // The material lies left of each ring's direction: the block's angle at v turns
                // anticlockwise from the next edge to the previous one.
                let (u, w) = (
                    [next[0] - v[0], next[1] - v[1]],
                    [prev[0] - v[0], prev[1] - v[1]],
                );
                let turn = (u[0] * w[1] - u[1] * w[0]).atan2(u[0] * w[0] + u[1] * w[1]);
                let angle = turn.rem_euclid(std::f64::consts::TAU).to_degrees();
                let c = corners.entry(key(v)).or_insert(f64::INFINITY);
                *c = c.min(angle);
            }
        }
        RingEdges {
            edges,
            grid,
            tol,
            corners,
        }
    }

    /// The block's angle at `p`, degrees: infinite if `p` is no corner of it.
    fn corner_at(&self, p: Point) -> f64 {
        self.corners.get(&key(p)).copied().unwrap_or(f64::INFINITY)
    }

    /// The edge `p` lies on (within a billionth of the block's size), by its ends' keys.
    fn under(&self, p: Point) -> Option<(Key, Key)> {
        self.grid.at(p).iter().find_map(|&i| {
            let e = &self.edges[i as usize];
            let (ka, kb) = (key(e.a), key(e.b));
            (ka != kb && segment_distance(p, e.a, e.b) <= self.tol)
                .then_some((ka.min(kb), ka.max(kb)))
        })
    }
}

/// The corner of the triangle `p` with the smallest angle (opposite its shortest side).
fn sharpest(p: [Point; 3]) -> Point {
    let side = |k: usize| distance(p[(k + 1) % 3], p[(k + 2) % 3]);
    let k = (0..3)
        .min_by(|&i, &j| side(i).total_cmp(&side(j)))
        .unwrap_or(0);
    p[k]
}

/// The centre of the circle through the triangle `p`'s corners, m.
fn circumcentre(p: [Point; 3]) -> Point {
    let (b, c) = (
        [p[1][0] - p[0][0], p[1][1] - p[0][1]],
        [p[2][0] - p[0][0], p[2][1] - p[0][1]],
    );
    let d = 2.0 * (b[0] * c[1] - b[1] * c[0]);
    let (b2, c2) = (b[0] * b[0] + b[1] * b[1], c[0] * c[0] + c[1] * c[1]);
    [
        p[0][0] + (c[1] * b2 - b[1] * c2) / d,
        p[0][1] + (b[0] * c2 - c[0] * b2) / d,
    ]
}

/// The rings of `block` the zoning constrains, with their edge kinds: the outer ring and every
/// hole of some area (a hole of no area is a joint piece ending inside the block, absorbed: both
/// its faces are the block's).
pub(crate) fn constrained_rings(
    block: &Block,
) -> impl Iterator<Item = (&Polygon, &[crate::joints::EdgeKind])> {
    let mut rings = block.rings();
    let outer = rings.next();
    outer
        .into_iter()
        .chain(rings.filter(|(hole, _)| hole.signed_area() != 0.0))
}

/// Split segment ab into pieces of the local size `size` (m); returns the interior split points.
fn split_segment(a: Point, b: Point, size: impl Fn(Point) -> f64) -> Vec<Point> {
    let len = distance(a, b);
    let at = |s: f64| {
        [
            a[0] + (b[0] - a[0]) * s / len,
            a[1] + (b[1] - a[1]) * s / len,
        ]
    };
    let mut marks = vec![0.0];
    let mut s = 0.0;
    while s < len {
        s += size(at(s)).min(len);
        marks.push(s);
    }
    let n = marks.len() - 1;
    // Rescale so the last piece ends exactly at b; drop a last piece shorter than half its target.
    let n = if n > 1 && (len - marks[n - 1]) < 0.5 * (marks[n] - marks[n - 1]) {
        n - 1
    } else {
        n
    };
    let total = marks[n];
    (1..n).map(|k| at(marks[k] * len / total)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::joints::EdgeKind;

    fn zoning() -> Zoning {
        Zoning {
            h_excavation: 0.1,
            h_far: 2.0,
            grading: 0.25,
            fine_depth: 0.0,
            plastic_depth: 0.0,
            min_angle_deg: 28.0,
            max_zones: 1_000_000,
        }
    }

    fn block(vertices: Vec<Point>) -> Block {
        let n = vertices.len();
        Block {
            outer: Polygon::new(vertices),
            outer_kinds: vec![EdgeKind::Joint(0); n],
            holes: vec![],
            hole_kinds: vec![],
        }
    }

    /// Two blocks across a joint from (0, 0) to (10, 0): a 0.3 m strip below and a 10 m square
    /// above. The joint's split points are the same asked from either end, spaced by the strip's
    /// width (its far face is the nearest feature), while the square's own top is split at h_far.
    #[test]
    fn a_joint_is_split_alike_from_both_sides_at_the_thinner_blocks_width() {
        let strip = block(vec![[0.0, -0.3], [10.0, -0.3], [10.0, 0.0], [0.0, 0.0]]);
        let square = block(vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]);
        let s = BoundarySpacing::new(&[strip, square], &[true, true], &[], &zoning());
        let forward = s.split([0.0, 0.0], [10.0, 0.0]);
        let mut backward = s.split([10.0, 0.0], [0.0, 0.0]);
        backward.reverse();
        assert_eq!(forward, backward);
        let gaps: Vec<f64> = std::iter::once([0.0, 0.0])
            .chain(forward.iter().copied())
            .chain(std::iter::once([10.0, 0.0]))
            .collect::<Vec<_>>()
            .windows(2)
            .map(|w| distance(w[0], w[1]))
            .collect();
        assert!(gaps.iter().all(|&g| (0.29..=0.31).contains(&g)), "{gaps:?}");
        let top = s.split([0.0, 10.0], [10.0, 10.0]);
        assert_eq!(top.len(), 4, "{top:?}");
        // Zoned alone, the square splits the joint at h_far too.
        let alone = BoundarySpacing::new(
            &[block(vec![
                [0.0, 0.0],
                [10.0, 0.0],
                [10.0, 10.0],
                [0.0, 10.0],
            ])],
            &[true],
            &[],
            &zoning(),
        );
        assert_eq!(alone.split([0.0, 0.0], [10.0, 0.0]).len(), 4);
    }

    /// A rigid strip (not zoned) is no feature of the zoned square beside it.
    #[test]
    fn a_block_that_is_not_zoned_does_not_refine_its_neighbour() {
        let strip = block(vec![[0.0, -0.3], [10.0, -0.3], [10.0, 0.0], [0.0, 0.0]]);
        let square = block(vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]);
        let s = BoundarySpacing::new(&[strip, square], &[false, true], &[], &zoning());
        assert_eq!(s.split([0.0, 0.0], [10.0, 0.0]).len(), 4);
    }
}
