//! Contact detection. Broad phase: a uniform grid over block bounding boxes (linear in the number
//! of blocks). Narrow phase: each boundary node of one block against the nearest boundary
//! edge of the other, both ways. Contacts that persist (same node, same opposite block) keep their
//! joint state.

use adit_meshing::EdgeKind;
use rayon::prelude::*;

use super::edge_grid::{EdgeGrid, MIN_EDGES};
use super::rounding;
use crate::joint::JointState;
use crate::model::Contacts;
use crate::model::blocks::{Blocks, NO_EDGE};

/// What detection needs to know.
pub struct Detection<'a> {
    pub blocks: &'a Blocks,
    /// Current node positions, m.
    pub x: &'a [[f64; 2]],
    /// Largest gap that makes a contact, m.
    pub tolerance: f64,
    /// Joint material of each joint feature (`EdgeKind::Joint(k)` → `joint_material[k]`).
    pub joint_material: &'a [u32],
    /// Joint material of each hole's wall (`EdgeKind::Excavation(j)` edges between blocks: the
    /// fill of a staged excavation, an inclusion), `NO_MATERIAL` for a hole that is empty.
    pub hole_material: &'a [u32],
}

impl<'a> Detection<'a> {
    /// Detection on `model`'s blocks and joint materials at positions `x` (m).
    pub fn of(model: &'a crate::model::Model, x: &'a [[f64; 2]]) -> Detection<'a> {
        Detection {
            blocks: &model.blocks,
            x,
            tolerance: model.contact_tolerance,
            joint_material: &model.materials.feature,
            hole_material: &model.materials.hole,
        }
    }
}

/// Marks a hole whose wall makes no contacts (an excavation from the start).
pub const NO_MATERIAL: u32 = u32::MAX;

/// Geometry of a new contact, handed to the caller to choose its initial joint state.
#[derive(Debug, Clone, Copy)]
pub struct Touch {
    /// Contact point on the edge, m.
    pub point: [f64; 2],
    /// Unit outward normal of the edge (pointing from block B towards the node).
    pub normal: [f64; 2],
    /// Signed gap, m (negative: overlap).
    pub gap: f64,
    /// Whether the node's boundary runs along the other block (a face contact) rather than only
    /// touching it at a point (a corner contact, as between diagonal blocks at a joint crossing).
    pub(crate) face: bool,
}

/// A node and an edge make a contact only if the outward normal of one of the node's edges and the
/// edge's are at more than about 107° (cosine below −0.3).
const MIN_FACING: f64 = 0.3;

/// Length of (x, y), m (a plain square root: `hypot`'s overflow care costs more than it buys here).
fn norm(x: f64, y: f64) -> f64 {
    (x * x + y * y).sqrt()
}

/// Dot product of two plane vectors.
fn dot(u: [f64; 2], v: [f64; 2]) -> f64 {
    u[0] * v[0] + u[1] * v[1]
}

/// Bounding box of block b over its boundary nodes, m.
fn bounds(blocks: &Blocks, x: &[[f64; 2]], b: usize) -> ([f64; 2], [f64; 2]) {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for e in blocks.edge_range(b) {
        let p = x[blocks.edges[e][0] as usize];
        for d in 0..2 {
            lo[d] = lo[d].min(p[d]);
            hi[d] = hi[d].max(p[d]);
        }
    }
    (lo, hi)
}

/// Pairs of blocks whose boxes, grown by `tol`, overlap. Broad phase on a uniform grid of cells
/// twice the mean box size: each box is listed in the cells it covers and only boxes sharing a cell
/// are compared, so the cost grows linearly with the number of blocks (a sort-and-sweep along one
/// axis degrades to N^1.5 when blocks line up in columns, as joint sets make them).
pub fn candidate_pairs(blocks: &Blocks, x: &[[f64; 2]], tol: f64) -> Vec<(u32, u32)> {
    let n = blocks.len();
    if n < 2 {
        return Vec::new();
    }
    let boxes: Vec<_> = (0..n).map(|b| bounds(blocks, x, b)).collect();
    let live = |b: usize| !blocks.is_removed(b);
    let (mut lo, mut extent) = ([f64::INFINITY; 2], 0.0);
    for (blo, bhi) in &boxes {
        lo = [lo[0].min(blo[0]), lo[1].min(blo[1])];
        extent += (bhi[0] - blo[0]).max(bhi[1] - blo[1]);
    }
    let cell = (2.0 * extent / n as f64)
        .max(4.0 * tol)
        .max(f64::MIN_POSITIVE);
    let index = |v: f64, d: usize| ((v - lo[d]) / cell).floor() as i64;
    let overlap = |a: usize, b: usize| {
        let ((alo, ahi), (blo, bhi)) = (boxes[a], boxes[b]);
        (0..2).all(|d| blo[d] <= ahi[d] + tol && alo[d] <= bhi[d] + tol)
    };
    let mut pairs = Vec::new();
    // (cell, block) entries, sorted so that each cell's blocks are contiguous. A box over more
    // than LARGE_CELLS cells (a block that spans the model, or one whose nodes ran away) is
    // compared with every box instead, so the entries stay within LARGE_CELLS a block.
    const LARGE_CELLS: f64 = 1024.0;
    let mut entries: Vec<((i64, i64), u32)> = Vec::new();
    for (b, (blo, bhi)) in boxes.iter().enumerate().filter(|(b, _)| live(*b)) {
        let cells = |d: usize| ((bhi[d] - blo[d] + 2.0 * tol) / cell).floor() + 1.0;
        let count = cells(0) * cells(1);
        if count.is_nan() || count > LARGE_CELLS {
            let others = (0..n).filter(|&o| o != b && live(o) && overlap(b, o));
            pairs.extend(others.map(|o| (b.min(o) as u32, b.max(o) as u32)));
            continue;
        }
        for cx in index(blo[0] - tol, 0)..=index(bhi[0] + tol, 0) {
            for cy in index(blo[1] - tol, 1)..=index(bhi[1] + tol, 1) {
                entries.push(((cx, cy), b as u32));
            }
        }
    }
    entries.sort_unstable();
    for group in entries.chunk_by(|p, q| p.0 == q.0) {
        for (k, &(_, a)) in group.iter().enumerate() {
            for &(_, b) in &group[k + 1..] {
                if overlap(a as usize, b as usize) {
                    pairs.push((a.min(b), a.max(b)));
                }
            }
        }
    }
    pairs.sort_unstable();
    pairs.dedup();
    pairs
}

/// A node of one block against an edge of another.
#[derive(Clone, Copy)]
struct Found {
    node: u32,
    edge: u32,
    /// Where along the edge, 0..1.
    xi: f64,
    touch: Touch,
    /// Rounded corner against rounded corner.
    corner: bool,
    /// The other edge of a node that meets two edges of the block at one of its corners (each of
    /// the node's faces against one of them), else `NO_EDGE`.
    partner: u32,
    /// The second of such a pair: it keeps only its own edge's state.
    second: bool,
}

impl Found {
    fn single(node: u32, edge: u32, xi: f64, touch: Touch, corner: bool) -> Found {
        Found {
            node,
            edge,
            xi,
            touch,
            corner,
            partner: NO_EDGE,
            second: false,
        }
    }
}

/// A node's faces lie against an edge when their outward normals are within about 25° of
/// opposite (cosine below −0.9).
const AGAINST: f64 = 0.9;

/// Two edges meeting at a corner are one face, not two, when their normals are within about 14°.
const SAME_FACE: f64 = 0.97;

/// A node meets the two edges of another block's corner each with a contact of its own when they
/// turn by more than about half a degree (`corner_partner`): at a kink of a joint (where the cutter
/// merged a vertex) or a vertex of a filled excavation's wall (7.5° on a 48-gon), one contact
/// carried both its faces' stress along one normal, a node at rest loaded by the stress times the
/// turn (5.5e4 N/m at 1 MPa across a 4.9° kink).
const KINK: f64 = 0.99996;

/// One detected contact: node, edge, block B, ξ, length, material, corner, joint state.
type Record = (u32, u32, u32, f64, f64, u32, bool, JointState);

/// Nodes of block `a` touching edges of block `b`. A rounded node (a convex corner of a rigid or
/// simple block) measures from its rounding centre, less its radius; a rounded node that meets no
/// edge of b face-on may meet a rounded corner of b, along the line of the two centres. A node at a
/// corner of b whose two faces lie against b's two edges there (a wedge's apex in a notch of b, or
/// b's apex in a notch of a) makes a contact with each, as UDEC's corner does with both edges of a
/// concave corner: one contact would carry the stress of both faces along one normal.
/// `grid`, when block b has one, gives the edges each node can touch (`EdgeGrid`); the edges are
/// then taken in the same order as without it, so the contacts are the same. `held(node, edge)`
/// and `touched(node, block)` tell whether the node had a contact on the edge, with the block,
/// before this detection.
fn node_to_edge(
    d: &Detection,
    a: usize,
    b: usize,
    grid: Option<&EdgeGrid>,
    held: &dyn Fn(u32, u32) -> bool,
    touched: &dyn Fn(u32, u32) -> bool,
) -> Vec<Found> {
    let (blo, bhi) = bounds(d.blocks, d.x, b);
    let tol = d.tolerance;
    let mut found = Vec::new();
    for ea in d.blocks.edge_range(a) {
        let n = d.blocks.edges[ea][0];
        let p = d.x[n as usize];
        if p[0] < blo[0] - tol || p[0] > bhi[0] + tol || p[1] < blo[1] - tol || p[1] > bhi[1] + tol
        {
            continue;
        }
        let r = d.blocks.round_of(n);
        let at = |v: u32| d.x[v as usize];
        let (own, owned) = edge_normals_at(d, n);
        let node = Node {
            id: n,
            centre: rounding::centre(d.blocks, &at, n, r),
            radius: r,
            own,
            owned,
            past_ends: r == 0.0 && touched(n, b as u32),
        };
        let mut depth = None;
        // An edge the node lies beside before one it lies beyond the end of; the edge it held
        // before, while it still lies beside it (a node pressed into b near a corner is as near
        // the corner's other edge, and there it would be pushed the wrong way); then the nearest;
        // among equally near ones (a node at a corner of B), the one facing the node.
        let mut best: Option<Candidate> = None;
        let (listed, all) = match grid {
            Some(g) => (g.near(node.centre), 0..0),
            None => (&[][..], d.blocks.edge_range(b)),
        };
        // And for each of the node's two faces, the best edge that face lies against.
        let mut against: [Option<Candidate>; 2] = [None, None];
        for eb in listed.iter().map(|&e| e as usize).chain(all) {
            let Some(mut c) = facing_edge(d, b, &node, eb as u32, &mut depth) else {
                continue;
            };
            c.held = held(n, eb as u32);
            if node.owned == 2 {
                for (o, slot) in against.iter_mut().enumerate() {
                    if dot(node.own[o], c.found.touch.normal) < -AGAINST
                        && slot.as_ref().is_none_or(|s| c.better_than(s))
                    {
                        *slot = Some(c);
                    }
                }
            }
            if best.as_ref().is_none_or(|best| c.better_than(best)) {
                best = Some(c);
            }
        }
        match best.map(|c| on_own_place(d, &node, c.found)) {
            Some(f) => {
                match corner_partner(d, b, &node, &f, other_face(&node, &f, &against), &mut depth) {
                    Some(g) => found.extend([
                        Found {
                            partner: g.edge,
                            ..f
                        },
                        Found {
                            partner: f.edge,
                            second: true,
                            ..g
                        },
                    ]),
                    None => found.extend(sharp_corner(d, &node, &f).unwrap_or(Some(f))),
                }
            }
            None if r > 0.0 => found.extend(corner_to_corner(d, n, node.centre, r, b)),
            None => {}
        }
    }
    found
}

/// The edge the node's face that does not lie against `f` lies against (`against`: the best
/// candidate of each face), if it is another edge.
fn other_face(node: &Node, f: &Found, against: &[Option<Candidate>; 2]) -> Option<u32> {
    let facing_f = |o: usize| dot(node.own[o], f.touch.normal) < -AGAINST;
    let o = match (facing_f(0), facing_f(1)) {
        (true, false) => 1,
        (false, true) => 0,
        _ => return None,
    };
    against[o]
        .as_ref()
        .map(|c| c.found.edge)
        .filter(|&e| e != f.edge)
}

/// A node looking for edges: its id, rounding centre (m) and radius (m), the outward normals of
/// its own edges, and whether it reaches past the ends of edges (a sharp node that touched the
/// block before).
struct Node {
    id: u32,
    centre: [f64; 2],
    radius: f64,
    /// The outward normals of its edges, the first `owned` of them (no allocation per node).
    own: [[f64; 2]; 2],
    owned: usize,
    past_ends: bool,
}

impl Node {
    /// The outward normals of the node's edges (two, or one at a free end).
    fn normals(&self) -> &[[f64; 2]] {
        &self.own[..self.owned]
    }
}

/// An edge a node may touch.
#[derive(Clone, Copy)]
struct Candidate {
    /// Whether the node lies beyond an end of the edge (by less than the tolerance).
    beyond: bool,
    /// Distance from the edge's line, m.
    dist: f64,
    /// How squarely one of the node's faces meets the edge: the smallest cosine between normals.
    facing: f64,
    /// Distances closer than this are equal, m (1e-9 of the edge's length).
    eps: f64,
    /// Whether the node had a contact on this edge before.
    held: bool,
    found: Found,
}

impl Candidate {
    /// Beside before beyond, held before, then nearer, then (equally near) more squarely faced.
    fn better_than(&self, other: &Candidate) -> bool {
        if self.beyond != other.beyond {
            return !self.beyond;
        }
        if self.held != other.held {
            return self.held;
        }
        self.dist < other.dist - self.eps
            || (self.dist <= other.dist + self.eps && self.facing < other.facing)
    }
}

/// Node `n` against edge `eb` of block `b`: the candidate contact, if the node is within the
/// tolerance of the edge, not deep inside b beyond it, and faces it. `depth` caches the node's
/// depth inside b.
fn facing_edge(
    d: &Detection,
    b: usize,
    n: &Node,
    eb: u32,
    depth: &mut Option<Option<f64>>,
) -> Option<Candidate> {
    let (c, r, tol) = (n.centre, n.radius, d.tolerance);
    let [j, k] = d.blocks.edges[eb as usize];
    let (pj, pk) = (d.x[j as usize], d.x[k as usize]);
    let t = [pk[0] - pj[0], pk[1] - pj[1]];
    let len = norm(t[0], t[1]);
    // A sharp node that touched b before still meets an edge it lies up to the tolerance beyond
    // the end of, when it meets no edge it lies beside: a node at a corner of b (where joints end
    // or cross, nodes of both sides coincide) otherwise loses its contact, and with it its stress,
    // as soon as it moves off the corner; as with UDEC's rounded corners, a face ends in the
    // tolerance's reach. A rounded node has its own reach past corners (`corner_to_corner`).
    let slack = if n.past_ends { tol / len } else { 1e-9 };
    let xi = ((c[0] - pj[0]) * t[0] + (c[1] - pj[1]) * t[1]) / (len * len);
    if !(-slack..=1.0 + slack).contains(&xi) {
        return None;
    }
    let beyond = !(-1e-9..=1.0 + 1e-9).contains(&xi);
    let xi = xi.clamp(0.0, 1.0);
    let q = [pj[0] + xi * t[0], pj[1] + xi * t[1]];
    let normal = [t[1] / len, -t[0] / len];
    let gap = (c[0] - q[0]) * normal[0] + (c[1] - q[1]) * normal[1] - r;
    if gap > tol || gap < -0.5 * len {
        return None;
    }
    // Deeper than the tolerance behind the edge's line is an overlap only if the node (its
    // rounding centre) is inside b and b's boundary is no nearer elsewhere: a node beside
    // a narrow block, behind the line of its far edge, is not in it, and a node just inside
    // a corner of b is not deep behind the line of the corner's other edge.
    if gap < -tol {
        let depth = *depth.get_or_insert_with(|| depth_in_block(d, b, c));
        if depth.is_none_or(|depth| -(gap + r) > depth + 1e-9 * len) {
            return None;
        }
    }
    // One of the node's edges must face the edge: a node of a flat surface beside the end of
    // an edge at right angles to it (a base node ahead of a sliding block's front face) is
    // no contact, or the block would snag on it.
    let facing = n
        .normals()
        .iter()
        .map(|&o| dot(normal, o))
        .fold(1.0, f64::min);
    if facing > -MIN_FACING {
        return None;
    }
    // A node whose own face runs on past the edge's end, on the edge's line, lies side by side
    // with it (where a joint meets the model's boundary or an excavation's wall, both blocks'
    // faces on one line): it cannot press into the edge, and a contact there would push it along
    // that surface. Nodes where joints meet the jointed tunnel's outer boundary took such an edge
    // when re-detection found them a micrometre past the end of their joint's edge, and got the
    // joint's normal stress turned along the boundary (6.6 MN on one node).
    if runs_on(d, n, xi, pj, t, normal) {
        return None;
    }
    let touch = Touch {
        point: q,
        normal,
        gap,
        face: false,
    };
    Some(Candidate {
        beyond,
        dist: gap.abs(),
        facing,
        eps: 1e-9 * len,
        held: false,
        found: Found::single(n.id, eb, acting_at(d, n, pj, t, xi), touch, false),
    })
}

/// Where along the edge from `pj` along `t` (m) node `n`'s contact acts, 0..1: at the node's own
/// place, projected, for a rounded node (whose gap is measured from its rounding centre, which
/// projects `xi`, up to a rounding radius from it), so that the force on the node and its reaction
/// on the edge lie on one line. The node's force acts at the node (a block's vertex); its reaction
/// at the centre's projection made each contact a couple of about the normal force times the
/// rounding radius, and two blocks of a joint, their vertices coinciding, did not start at rest in
/// their in-situ stress (simple and rigid blocks: an unbalanced moment on the blocks where joints
/// meet the model's boundary, a ratio of 1.2e-2 in `models/jointed_tunnel.json`).
fn acting_at(d: &Detection, n: &Node, pj: [f64; 2], t: [f64; 2], xi: f64) -> f64 {
    if n.radius == 0.0 {
        return xi;
    }
    let p = d.x[n.id as usize];
    (((p[0] - pj[0]) * t[0] + (p[1] - pj[1]) * t[1]) / dot(t, t)).clamp(0.0, 1.0)
}

/// A rounded node's contact `f` moved to the edge of b beside which the node itself lies. Its
/// rounding centre lies r / sin(θ/2) from the apex of a wedge of angle θ (11 r at 10.6°), so
/// against a zoned block it projects onto an edge one or more zones on,
/// and the contact acted at that edge's end, a zone away from the node: the node's force and its
/// reaction on different nodes of b. The walk goes on through b's edges in line with f's (their
/// normals within [`SAME_FACE`]) as far as the node lies beyond them, and never back.
fn on_own_place(d: &Detection, n: &Node, mut f: Found) -> Found {
    if n.radius == 0.0 {
        return f;
    }
    let p = d.x[n.id as usize];
    let normal = edge_normal(d, f.edge);
    let mut came = NO_EDGE;
    for _ in 0..d.blocks.edges.len() {
        let along = along_edge(d, p, f.edge);
        let [j, k] = d.blocks.edges[f.edge as usize];
        let next = if along < 0.0 {
            d.blocks.node_edges[j as usize][0]
        } else if along > 1.0 {
            d.blocks.node_edges[k as usize][1]
        } else {
            break;
        };
        if next == NO_EDGE || next == came || dot(edge_normal(d, next), normal) <= SAME_FACE {
            break;
        }
        came = f.edge;
        f.edge = next;
        f.xi = along_edge(d, p, next).clamp(0.0, 1.0);
    }
    f
}

/// Whether one of node `n`'s own faces continues the edge from `pj` along `t` (m) past the end
/// the node is at (`xi`, its place along the edge, 0..1): the face's outward normal within
/// [`SAME_FACE`] of the edge's `normal`, its far end beyond that end of the edge, and where it
/// passes that end, on the edge's line (within the tolerance). (A sliver's tip faces the block
/// across its joint with one face and has the other nearly parallel to it too, but that face runs
/// under the edge, or past the end of a short one off its line: a simple wedge of 10.6° beside a
/// zoned block lost its contact with it, and the zoned block's node at its apex half its stress.)
fn runs_on(d: &Detection, n: &Node, xi: f64, pj: [f64; 2], t: [f64; 2], normal: [f64; 2]) -> bool {
    let own = d.blocks.node_edges[n.id as usize];
    let mut faces = own.iter().filter(|&&e| e != NO_EDGE).zip(n.normals());
    faces.any(|(&e, &o)| {
        if dot(o, normal) <= SAME_FACE {
            return false;
        }
        let [a, b] = d.blocks.edges[e as usize];
        let q = d.x[if a == n.id { b } else { a } as usize];
        let p = d.x[n.id as usize];
        let along = |v: [f64; 2]| ((v[0] - pj[0]) * t[0] + (v[1] - pj[1]) * t[1]) / dot(t, t);
        let (from, to) = (along(p), along(q));
        let end = if xi < 0.5 { 0.0 } else { 1.0 };
        let past = if xi < 0.5 { to < 0.0 } else { to > 1.0 };
        // Where the face passes the edge's end it lies on the edge's line (within the
        // tolerance): a wedge's apex against a short edge has its other face nearly parallel and
        // past the edge's end too, but off its line.
        let s = ((end - from) / (to - from)).clamp(0.0, 1.0);
        let at_end = [p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])];
        let off = ((at_end[0] - pj[0]) * normal[0] + (at_end[1] - pj[1]) * normal[1]).abs();
        past && off <= d.tolerance
    })
}

/// The second edge of block `b` a node meets at a corner of b, beside the edge of its nearest
/// contact `f`: the edge sharing f's nearer end, or else `other` (the nearest edge of b that the
/// node's other face lies against: where joints cross and one block takes two opposite corners
/// of the crossing, each a node of its own, a wedge's tip lies against an edge of each), if the
/// node is within the tolerance of it too, the two edges turn by more than [`KINK`], and
/// each of the node's two faces lies against one of them: its outward normal within about 25° of
/// opposite ([`AGAINST`]) and the edge running along it, within the tolerance for as far as the
/// shorter of the two reaches (diagonal blocks at a joint crossing face each other's edges but
/// run along their neighbours'), and no third block sharing the face's edge (`Blocks::across`).
fn corner_partner(
    d: &Detection,
    b: usize,
    n: &Node,
    f: &Found,
    other: Option<u32>,
    depth: &mut Option<Option<f64>>,
) -> Option<Found> {
    if n.owned < 2 {
        return None;
    }
    let [j, k] = d.blocks.edges[f.edge as usize];
    let beside = if f.xi < 0.5 {
        d.blocks.node_edges[j as usize][0]
    } else {
        d.blocks.node_edges[k as usize][1]
    };
    let own = d.blocks.node_edges[n.id as usize];
    let against = |o: usize, m: [f64; 2], e: u32| {
        dot(n.own[o], m) < -AGAINST
            && runs_along(d, n.id, own[o], e)
            && !against_third(d, own[o], b)
    };
    let mut partner = |e: u32| {
        if e == NO_EDGE || e == f.edge {
            return None;
        }
        let g = facing_edge(d, b, n, e, depth)?.found;
        let (m1, m2) = (f.touch.normal, g.touch.normal);
        let each = (against(0, m1, f.edge) && against(1, m2, g.edge))
            || (against(1, m1, f.edge) && against(0, m2, g.edge));
        (dot(m1, m2) < KINK && each).then_some(g)
    };
    partner(beside).or_else(|| other.filter(|&e| e != beside).and_then(partner))
}

/// A sharp node at a convex corner of the block of its contact `f` (the end of f's edge it is
/// nearer), neither of whose faces runs along that corner's edges, meets the corner as rounded
/// corners meet: along the line of their arcs' centres, across the gap between the arcs
/// (`rounding::contact_arc`, arcs of `Blocks::sharp_round`; the corners of diagonal blocks at a
/// joint crossing, which coincide, lie apart by 2d(1/sin(θ/2) − 1), as in UDEC, and carry no
/// stress until they close it), on the corner's outgoing edge at ξ = 0, while that line points between
/// the normals of the corner's two edges; beyond them the nearer face's normal takes over, so the
/// normal turns continuously. Diagonal blocks at a joint crossing meet so, and a corner pressed on
/// a corner. Choosing one of the corner's two edges instead turned the normal by the corner's
/// angle when the node moved a micrometre: in the jointed tunnel, 75° and a 1.2 MN kick at a
/// re-detection. `None` where the rule does not apply (f stands), else the corner's contact if
/// the arcs lie within the tolerance.
fn sharp_corner(d: &Detection, n: &Node, f: &Found) -> Option<Option<Found>> {
    if n.radius > 0.0 || d.blocks.sharp_round <= 0.0 {
        return None;
    }
    let [j, k] = d.blocks.edges[f.edge as usize];
    let v = if f.xi < 0.5 { j } else { k };
    let [into, out] = d.blocks.node_edges[v as usize];
    if into == NO_EDGE || out == NO_EDGE {
        return None;
    }
    let (m1, m2) = (edge_normal(d, into), edge_normal(d, out));
    let cross = |a: [f64; 2], b: [f64; 2]| a[0] * b[1] - a[1] * b[0];
    if cross(m1, m2) <= 1e-6 {
        return None;
    }
    let own = d.blocks.node_edges[n.id as usize];
    let alongside = own
        .iter()
        .filter(|&&o| o != NO_EDGE)
        .any(|&o| runs_along(d, n.id, o, into) || runs_along(d, n.id, o, out));
    if alongside {
        return None;
    }
    let at = |u: u32| d.x[u as usize];
    let ((ci, ri), (cv, rv)) = (
        rounding::contact_arc(d.blocks, &at, n.id),
        rounding::contact_arc(d.blocks, &at, v),
    );
    let line = [ci[0] - cv[0], ci[1] - cv[1]];
    if cross(m1, line) <= 0.0 || cross(line, m2) <= 0.0 {
        return None;
    }
    let len = norm(line[0], line[1]);
    let normal = [line[0] / len, line[1] / len];
    let gap = len - ri - rv;
    if gap > d.tolerance {
        return Some(None);
    }
    let touch = Touch {
        point: at(v),
        normal,
        gap,
        face: false,
    };
    Some(Some(Found::single(n.id, out, 0.0, touch, true)))
}

/// Whether a node's own edge `e` lies against a block other than `b`: one whose zoning shares the
/// edge (`Blocks::across`), however near b's edge runs to it. A joint meeting a filled wall at
/// 21° left the fill's wedge between the rock's face and the other rock's wall edge, and the
/// rock's node counted that face in its contact with the other rock.
fn against_third(d: &Detection, e: u32, b: usize) -> bool {
    d.blocks.across(e).is_some_and(|c| c != b)
}

/// Whether node `n`'s boundary edge `own` runs along edge `e` of another block: the point of
/// `own` half the shorter edge's length away from n lies within the tolerance of `e`.
fn runs_along(d: &Detection, n: u32, own: u32, e: u32) -> bool {
    let [a, b] = d.blocks.edges[own as usize];
    let (p, q) = (d.x[n as usize], d.x[if a == n { b } else { a } as usize]);
    let [j, k] = d.blocks.edges[e as usize].map(|v| d.x[v as usize]);
    let (own_len, len) = (
        norm(q[0] - p[0], q[1] - p[1]),
        norm(k[0] - j[0], k[1] - j[1]),
    );
    let s = 0.5 * own_len.min(len) / own_len;
    let point = [p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])];
    distance_to_edge(d, point, e) <= d.tolerance
}

/// The rounded corner of block `b` nearest to node n's rounding centre `c` (radius `r`), if the
/// arcs are within the tolerance: normal along the line of centres, contact on the corner's
/// outgoing edge at ξ = 0.
fn corner_to_corner(d: &Detection, n: u32, c: [f64; 2], r: f64, b: usize) -> Option<Found> {
    d.blocks
        .edge_range(b)
        .filter_map(|eb| {
            let j = d.blocks.edges[eb][0];
            let rj = d.blocks.round_of(j);
            if rj == 0.0 {
                return None;
            }
            let cj = rounding::centre(d.blocks, &|v: u32| d.x[v as usize], j, rj);
            let (dx, dy) = (c[0] - cj[0], c[1] - cj[1]);
            let dist = norm(dx, dy);
            let gap = dist - r - rj;
            (gap <= d.tolerance && dist > 0.0).then(|| {
                let normal = [dx / dist, dy / dist];
                let touch = Touch {
                    point: d.x[j as usize],
                    normal,
                    gap,
                    face: false,
                };
                (gap, Found::single(n, eb as u32, 0.0, touch, true))
            })
        })
        .min_by(|p, q| p.0.total_cmp(&q.0))
        .map(|(_, f)| f)
}

/// No node: what `contact_length`'s stretches skip when they skip none.
const NO_NODE: u32 = u32::MAX;

/// Length of joint a contact at `node` against `edge` of block `b` stands for, m, and whether it
/// is a face contact. The joint between the two blocks, cut at the nodes of both sides, is a
/// chain of pieces; each piece's length goes half to the contact at either end, shared by the
/// two contacts there where both blocks have a node (the trapezoidal rule of the traction on
/// either side's edges, which their contacts' forces load as the zones' stress loads their nodes:
/// a block in a uniform stress starts at rest, whatever the two zonings). So the node takes, of
/// each of its boundary edges that runs along b, the stretch up to the nearest node of b on the
/// edge (or its whole length), halved, and halved again where b has a node at its own place;
/// sliding off that node, the node passes from the one to the other over the contact tolerance.
/// An edge runs along b when the middle of that stretch lies within the tolerance of b's boundary
/// (the contact edge and its two neighbours are tried first, then all of b's edges, which a long
/// edge against a finely zoned block needs). A corner contact, whose edges both leave the other
/// block (diagonal blocks at a joint crossing, a corner against a face), takes a quarter of its
/// shorter edge, halved likewise. Of a node with two contacts at a corner of b (`partner` the
/// other contact's edge), each takes only the node's edge that lies more squarely against its
/// own. An edge of the node that a third block's zoning shares (`Blocks::across`) lies against
/// that block and counts for no other.
///
/// Two zoned blocks put their nodes at the same places along a joint (`adit_meshing::spacing`):
/// each node takes a quarter of each edge. A zoned block beside a simple or rigid one, whose edge
/// spans several of its nodes, and a block's face where two others meet at a node in its middle
/// (a joint ending on a joint) are where the pieces differ: the node without a partner takes its
/// pieces whole. Taking a quarter there too, as each node did before, left the zoned block's
/// middle nodes with half their stress and its nodes at the ends of the other's edge with half
/// as much again (2.7e7 N/m where simple blocks met zoned ones, in random boxes at 25 MPa).
fn contact_length(d: &Detection, node: u32, edge: u32, partner: u32, b: usize) -> (f64, bool) {
    let [j, k] = d.blocks.edges[edge as usize];
    let near = [
        edge,
        d.blocks.node_edges[j as usize][0],
        d.blocks.node_edges[k as usize][1],
    ];
    // The nodes of b beside the contact, each with the edge of b that leads to it from the
    // contact edge (none for that edge's own ends): the nearest node of b along either of the
    // node's edges is one of them (the ends of the contact edge, or beyond one the node sits on).
    let beside = [
        Some((j, NO_EDGE)),
        Some((k, NO_EDGE)),
        (near[1] != NO_EDGE).then(|| (d.blocks.edges[near[1] as usize][0], near[1])),
        (near[2] != NO_EDGE).then(|| (d.blocks.edges[near[2] as usize][1], near[2])),
    ];
    let here = d.x[node as usize];
    let tol = d.tolerance;
    // Whether edge `via` of b runs along the node's edge `e` on the joint between them: its
    // middle lies within the tolerance of e, and the two face each other (outward normals
    // opposed). A sliver thinner than the tolerance between a joint and the boundary has the
    // next node of its free side, and a block whose joint meets a filled tunnel's wall at a
    // grazing angle the next node of the wall, within the tolerance of the joint's line; neither
    // is on the joint.
    let leads_along = |via: u32, e: u32| {
        let [p, q] = d.blocks.edges[via as usize].map(|n| d.x[n as usize]);
        distance_to_edge(d, [0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])], e) <= tol
            && dot(edge_normal(d, via), edge_normal(d, e)) < 0.0
    };
    // The end of the contact edge nearest to this node, and how far it is, m: a node of b at the
    // node's own place is one of them (the node projects onto the edge at its end).
    let gap_to = |v: u32| norm(d.x[v as usize][0] - here[0], d.x[v as usize][1] - here[1]);
    let (nearest, apart) = if gap_to(k) < gap_to(j) {
        (k, gap_to(k))
    } else {
        (j, gap_to(j))
    };
    let normals = (partner != NO_EDGE).then(|| (edge_normal(d, edge), edge_normal(d, partner)));
    let mine = |e: u32| {
        normals.is_none_or(|(this, other)| {
            let o = edge_normal(d, e);
            dot(o, this) <= dot(o, other)
        })
    };
    // A node's edge on the region's boundary lies against a joint of b only at a sliver (a joint
    // meeting the boundary at an angle under the contact's reach, within the tolerance of b's
    // face for a few centimetres): the boundary's load is its own, and a contact there as well
    // loaded the sliver's corner twice. (Fallen on b's own boundary, it may well touch b.)
    let outer_against_joint = |e: u32| {
        matches!(d.blocks.edge_kind[e as usize], EdgeKind::Region(_))
            && !matches!(d.blocks.edge_kind[edge as usize], EdgeKind::Region(_))
    };
    // Of each edge running along b, half the stretch from `origin` up to the nearest node of b
    // on it but `skip` (or to the edge's end): the node's share alone (from its own place), and,
    // from its partner's place (the nearest end of the contact edge) skipping it, what it shares
    // with the partner while they coincide (`paired`, halved) and what it would take alone the
    // moment they part (`parting`: nothing of an edge the partner then lies on).
    let partner = d.x[nearest as usize];
    let (mut alone, mut paired, mut parting, mut shortest) = (0.0, 0.0, 0.0, f64::INFINITY);
    for &e in d.blocks.node_edges[node as usize]
        .iter()
        .filter(|&&e| e != NO_EDGE)
    {
        let [p, q] = d.blocks.edges[e as usize];
        let far = d.x[if p == node { q } else { p } as usize];
        let len = norm(far[0] - here[0], far[1] - here[1]);
        shortest = shortest.min(len);
        if !mine(e) || outer_against_joint(e) || against_third(d, e, b) {
            continue;
        }
        let along_e = [(far[0] - here[0]) / len, (far[1] - here[1]) / len];
        // Where `v` lies along e from `origin`, m, if within the tolerance of e's line.
        let place = |origin: [f64; 2], v: [f64; 2]| {
            let r = [v[0] - origin[0], v[1] - origin[1]];
            ((r[0] * along_e[1] - r[1] * along_e[0]).abs() <= tol).then(|| dot(r, along_e))
        };
        let stretch = |origin: [f64; 2], skip: u32| {
            let end = dot([far[0] - origin[0], far[1] - origin[1]], along_e);
            // A node reached through a neighbouring edge of b counts where that edge runs along
            // e: across a block thinner than the tolerance (a sliver between a joint and the
            // boundary), the node on its far side lies within the tolerance of e's line too.
            let reach = beside
                .iter()
                .flatten()
                .filter(|&&(v, via)| v != skip && (via == NO_EDGE || leads_along(via, e)))
                .filter_map(|&(v, _)| place(origin, d.x[v as usize]))
                .filter(|&s| s > 0.0 && s < end)
                .fold(end, f64::min);
            let mid = [
                origin[0] + 0.5 * reach * along_e[0],
                origin[1] + 0.5 * reach * along_e[1],
            ];
            // The stretch lies along b where its middle lies beside one of b's edges: within the
            // tolerance of it, and not past its ends (a node of b just beyond the end of a block
            // sliding on b, where the block's corner has left it, holds no joint).
            let within = |e: u32| beside_edge(d, mid, e) <= tol;
            let along = near.iter().filter(|&&e| e != NO_EDGE).any(|&e| within(e))
                || d.blocks.edge_range(b).any(|e| within(e as u32));
            if along && reach > 0.0 {
                0.5 * reach
            } else {
                0.0
            }
        };
        alone += stretch(here, NO_NODE);
        let shared = stretch(partner, nearest);
        paired += 0.5 * shared;
        let ahead = place(here, partner).is_some_and(|s| s > 0.0 && s < len);
        if !ahead {
            parting += shared;
        }
    }
    // Sliding apart from its partner, a node's share passes from paired to alone over the
    // tolerance: alone, plus what pairing adds to it at the moment of parting, fading. Where it
    // adds nothing (a node inside a joint, whose two neighbours' halves still cover it), the
    // length is alone's, the trapezoidal rule over both sides' nodes at any slip; at a block's
    // corner leaving a node of b it adds a quarter of an edge, which would otherwise be lost at
    // once (a block sliding on a slope 1° steeper than its joint's friction, its corner leaving
    // the base's node, was kicked into slips of 6 % of its slide).
    let fading = 1.0 - (apart / tol).min(1.0);
    let shared = alone + fading * (paired - parting);
    if shared > 0.0 {
        (shared, true)
    } else {
        (0.5 * 0.25 * shortest, false)
    }
}

/// How deep `p` lies inside block `b`, m (its distance to b's boundary), or `None` if it lies
/// outside (crossing number over all of b's boundary rings).
fn depth_in_block(d: &Detection, b: usize, p: [f64; 2]) -> Option<f64> {
    let inside = d.blocks.edge_range(b).fold(false, |inside, e| {
        let [a, c] = d.blocks.edges[e].map(|n| d.x[n as usize]);
        let crosses = (a[1] > p[1]) != (c[1] > p[1])
            && p[0] < a[0] + (p[1] - a[1]) * (c[0] - a[0]) / (c[1] - a[1]);
        inside != crosses
    });
    inside.then(|| {
        d.blocks
            .edge_range(b)
            .map(|e| distance_to_edge(d, p, e as u32))
            .fold(f64::INFINITY, f64::min)
    })
}

/// Distance from `p` to the line of edge `e`, m, where p projects onto the edge (between its
/// ends, to 1e-9 of its length); infinite beyond its ends.
fn beside_edge(d: &Detection, p: [f64; 2], e: u32) -> f64 {
    if !(-1e-9..=1.0 + 1e-9).contains(&along_edge(d, p, e)) {
        return f64::INFINITY;
    }
    let [a, c] = d.blocks.edges[e as usize].map(|n| d.x[n as usize]);
    let t = [c[0] - a[0], c[1] - a[1]];
    ((p[0] - a[0]) * t[1] - (p[1] - a[1]) * t[0]).abs() / norm(t[0], t[1])
}

/// Where `p` projects along boundary edge `e`: 0 at its first node, 1 at its second (unbounded).
fn along_edge(d: &Detection, p: [f64; 2], e: u32) -> f64 {
    let [a, c] = d.blocks.edges[e as usize].map(|n| d.x[n as usize]);
    let t = [c[0] - a[0], c[1] - a[1]];
    ((p[0] - a[0]) * t[0] + (p[1] - a[1]) * t[1]) / (t[0] * t[0] + t[1] * t[1])
}

/// Distance from `p` to boundary edge `e`, m.
fn distance_to_edge(d: &Detection, p: [f64; 2], e: u32) -> f64 {
    let [a, c] = d.blocks.edges[e as usize].map(|n| d.x[n as usize]);
    let t = [c[0] - a[0], c[1] - a[1]];
    let s = along_edge(d, p, e).clamp(0.0, 1.0);
    norm(p[0] - a[0] - s * t[0], p[1] - a[1] - s * t[1])
}

/// Outward unit normals of the (up to two) boundary edges meeting at node `n`, and how many.
fn edge_normals_at(d: &Detection, n: u32) -> ([[f64; 2]; 2], usize) {
    let mut out = [[0.0; 2]; 2];
    let mut k = 0;
    for &e in &d.blocks.node_edges[n as usize] {
        if e != NO_EDGE {
            out[k] = edge_normal(d, e);
            k += 1;
        }
    }
    (out, k)
}

/// Outward unit normal of boundary edge `e` (blocks run anticlockwise: the edge's direction
/// turned clockwise).
fn edge_normal(d: &Detection, e: u32) -> [f64; 2] {
    let [a, b] = d.blocks.edges[e as usize];
    let (p, q) = (d.x[a as usize], d.x[b as usize]);
    let len = norm(q[0] - p[0], q[1] - p[1]);
    [(q[1] - p[1]) / len, -(q[0] - p[0]) / len]
}

/// Joint material of a contact: the joint its edge lies on, else a joint at the node, else 0.
fn material_of(d: &Detection, node: u32, edge: u32) -> u32 {
    let of = |e: u32| match d.blocks.edge_kind[e as usize] {
        EdgeKind::Joint(k) => d.joint_material.get(k as usize).copied(),
        EdgeKind::Excavation(j) => d
            .hole_material
            .get(j as usize)
            .copied()
            .filter(|&m| m != NO_MATERIAL),
        EdgeKind::Region(_) => None,
    };
    of(edge)
        .or_else(|| {
            d.blocks.node_edges[node as usize]
                .iter()
                .filter(|&&e| e != NO_EDGE)
                .find_map(|&e| of(e))
        })
        .unwrap_or(0)
}

/// Detect all contacts. A contact already in `previous` (same node, same opposite block) keeps its
/// joint state; a new one takes `fresh(touch)`.
pub fn detect(
    d: &Detection,
    previous: &Contacts,
    fresh: &(dyn Fn(&Touch) -> JointState + Sync),
) -> Contacts {
    detect_gridded(d, previous, fresh, MIN_EDGES)
}

/// `detect`, with an edge grid for every block of at least `min_edges` edges.
fn detect_gridded(
    d: &Detection,
    previous: &Contacts,
    fresh: &(dyn Fn(&Touch) -> JointState + Sync),
    min_edges: usize,
) -> Contacts {
    // The previous contacts of each node (compressed rows, a counting sort), to find a persisting
    // one's state without hashing.
    let mut start = vec![0u32; d.x.len() + 1];
    for &n in &previous.node {
        start[n as usize + 1] += 1;
    }
    for i in 0..d.x.len() {
        start[i + 1] += start[i];
    }
    let mut fill = start.clone();
    let mut by_node = vec![0u32; previous.len()];
    for (c, &n) in previous.node.iter().enumerate() {
        by_node[fill[n as usize] as usize] = c as u32;
        fill[n as usize] += 1;
    }
    // The previous contact of the node with the block on the same edge; else, for a node's only
    // or first contact, one on another edge (the node slid onto the next edge) that is not its
    // partner's; the second of a corner pair is new unless its edge had one.
    let previous_of = |node: u32| {
        by_node[start[node as usize] as usize..start[node as usize + 1] as usize]
            .iter()
            .map(|&c| c as usize)
    };
    let persisting = |f: &Found, block: u32| {
        let mine = || previous_of(f.node).filter(move |&c| previous.block[c] == block);
        mine().find(|&c| previous.edge[c] == f.edge).or_else(|| {
            (!f.second)
                .then(|| mine().find(|&c| previous.edge[c] != f.partner))
                .flatten()
        })
    };
    let held = |node: u32, edge: u32| previous_of(node).any(|c| previous.edge[c] == edge);
    let touched = |node: u32, block: u32| previous_of(node).any(|c| previous.block[c] == block);
    let pairs = candidate_pairs(d.blocks, d.x, d.tolerance);
    let near = d.tolerance + d.blocks.round.iter().copied().fold(0.0, f64::max);
    let grids: Vec<Option<EdgeGrid>> = (0..d.blocks.len())
        .into_par_iter()
        .map(|b| {
            (d.blocks.edge_range(b).len() >= min_edges && !d.blocks.is_removed(b))
                .then(|| EdgeGrid::new(d.blocks, d.x, b, near))
        })
        .collect();
    let per_pair: Vec<Vec<Record>> = pairs
        .par_iter()
        .map(|&(a, b)| {
            let (a, b) = (a as usize, b as usize);
            let both = node_to_edge(d, a, b, grids[b].as_ref(), &held, &touched)
                .into_iter()
                .map(|f| (f, b as u32))
                .chain(
                    node_to_edge(d, b, a, grids[a].as_ref(), &held, &touched)
                        .into_iter()
                        .map(|f| (f, a as u32)),
                );
            both.filter_map(|(f, block_b)| {
                let (length, face) = contact_length(d, f.node, f.edge, f.partner, block_b as usize);
                let touch = Touch { face, ..f.touch };
                let state = match persisting(&f, block_b) {
                    Some(c) => previous.state[c],
                    // Blocks are detected before they touch (detection reruns whenever anything
                    // may have moved half the tolerance), so a new contact deeper than the
                    // tolerance is a node behind an edge it never crossed: no contact.
                    None if !previous.is_empty() && touch.gap < -d.tolerance => return None,
                    None => fresh(&touch),
                };
                let material = material_of(d, f.node, f.edge);
                Some((
                    f.node, f.edge, block_b, f.xi, length, material, f.corner, state,
                ))
            })
            .collect()
        })
        .collect();
    let mut out = Contacts::default();
    for (node, edge, block, xi, length, material, corner, state) in per_pair.into_iter().flatten() {
        out.node.push(node);
        out.edge.push(edge);
        out.block.push(block);
        out.xi.push(xi);
        out.length.push(length);
        out.material.push(material);
        out.corner.push(corner);
        out.state.push(state);
    }
    out.indexed(d.x.len(), &d.blocks.edges)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two unit squares side by side (x ∈ [0,1] and [1,2]), each a ring of 4 edges.
    fn two_squares() -> (Blocks, Vec<[f64; 2]>) {
        let x = vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [0.0, 1.0],
            [1.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [1.0, 1.0],
        ];
        let mut blocks = two_quadrilaterals(EdgeKind::Region(0));
        blocks.edge_kind[1] = EdgeKind::Joint(0);
        blocks.edge_kind[7] = EdgeKind::Joint(0);
        (blocks, x)
    }

    /// Two blocks of four nodes each (0–3 and 4–7), each a ring of 4 edges of `kind`.
    fn two_quadrilaterals(kind: EdgeKind) -> Blocks {
        let edges = vec![
            [0, 1],
            [1, 2],
            [2, 3],
            [3, 0],
            [4, 5],
            [5, 6],
            [6, 7],
            [7, 4],
        ];
        let mut node_edges = vec![[NO_EDGE; 2]; 8];
        for (e, &[a, b]) in edges.iter().enumerate() {
            node_edges[a as usize][1] = e as u32;
            node_edges[b as usize][0] = e as u32;
        }
        Blocks {
            node_start: vec![0, 4, 8],
            zone_start: vec![0, 2, 4],
            edge_start: vec![0, 4, 8],
            edges,
            edge_kind: vec![kind; 8],
            node_edges,
            edge_across: vec![],
            round: vec![],
            sharp_round: 0.0,
            removed: vec![],
        }
    }

    /// Detection over the squares at positions `x`, 1 mm tolerance.
    fn at<'a>(blocks: &'a Blocks, x: &'a [[f64; 2]]) -> Detection<'a> {
        Detection {
            blocks,
            x,
            tolerance: 1e-3,
            joint_material: &[0],
            hole_material: &[],
        }
    }

    /// A wedge's apex in a notch of another block (a chevron over a diamond, nodes coinciding) and
    /// the notch's corner against the wedge each make a contact with both edges there, each
    /// carrying its own face: one contact would push both faces along one normal.
    #[test]
    fn a_wedge_in_a_notch_meets_both_faces() {
        let x = vec![
            [0.0, 0.0],
            [1.0, 1.0],
            [2.0, 0.0],
            [1.0, 3.0],
            [0.0, 0.0],
            [1.0, -1.0],
            [2.0, 0.0],
            [1.0, 1.0],
        ];
        let blocks = two_quadrilaterals(EdgeKind::Joint(0));
        let c = detect(&at(&blocks, &x), &Contacts::default(), &|_| {
            JointState::default()
        });
        let quarter = 0.25 * 2f64.sqrt();
        for (node, block, edges) in [(7, 0, [0, 1]), (1, 1, [6, 7])] {
            let mine: Vec<usize> = (0..c.len())
                .filter(|&i| c.node[i] == node && c.block[i] == block)
                .collect();
            let mut found: Vec<u32> = mine.iter().map(|&i| c.edge[i]).collect();
            found.sort();
            assert_eq!(found, edges, "node {node}");
            for &i in &mine {
                assert!((c.length[i] - quarter).abs() < 1e-12, "{}", c.length[i]);
            }
        }
    }

    /// A node at a corner of the other block keeps its contact, and the contact its stress, when
    /// it moves off the corner by less than the tolerance: the top corner of the left square slides
    /// 0.5 mm up past the end of the right square's face.
    #[test]
    fn a_node_just_past_a_corner_keeps_its_stress() {
        let (blocks, mut x) = two_squares();
        let d = at(&blocks, &x);
        let loaded = |_: &Touch| JointState {
            normal: -1e6,
            ..Default::default()
        };
        let before = detect(&d, &Contacts::default(), &loaded);
        let of_node_2 = |c: &Contacts| (0..c.len()).find(|&i| c.node[i] == 2 && c.block[i] == 1);
        assert!(of_node_2(&before).is_some());
        x[2] = [1.0, 1.0005];
        let after = detect(&at(&blocks, &x), &before, &|_| JointState::default());
        let i = of_node_2(&after).expect("contact kept");
        assert_eq!((after.edge[i], after.state[i].normal), (7, -1e6));
    }

    /// A wedge (block 0: tip, node 0, at the origin, its free face down x = 0) against the block
    /// across its joint (block 1: the joint from its node 4 at the origin to (1, −3) m, its free
    /// face up x = 0 from the origin), m.
    fn wedge_and_block() -> Vec<[f64; 2]> {
        vec![
            [0.0, 0.0],
            [0.0, -3.0],
            [0.5, -3.0],
            [1.0, -3.0],
            [0.0, 0.0],
            [1.0, -3.0],
            [3.0, -3.0],
            [0.0, 3.0],
        ]
    }

    /// A wedge's tip pressed into the block across its joint, near that block's corner on a free
    /// face at a shallow angle to the joint (18°), stays on the joint: the free face is nearer and
    /// faced too, and choosing it would push the tip along the free face's normal, out of the
    /// model (a realization of the tunnel model ran away so). The free face runs on in the
    /// wedge's own free face (both on x = 0), so it is no contact for the tip even when detection
    /// starts afresh; it was, until the tip's earlier edge was preferred.
    #[test]
    fn a_pressed_wedge_tip_keeps_its_joint() {
        let mut x = wedge_and_block();
        let blocks = two_quadrilaterals(EdgeKind::Joint(0));
        let fresh = |_: &Touch| JointState::default();
        let tip = |c: &Contacts| {
            let i = (0..c.len()).find(|&i| c.node[i] == 0 && c.block[i] == 1);
            c.edge[i.expect("tip contact")]
        };
        let before = detect(&at(&blocks, &x), &Contacts::default(), &fresh);
        assert_eq!(tip(&before), 4);
        x[0] = [0.0007, 0.0002];
        assert_eq!(
            tip(&detect(&at(&blocks, &x), &Contacts::default(), &fresh)),
            4
        );
        assert_eq!(tip(&detect(&at(&blocks, &x), &before, &fresh)), 4);
    }

    /// A node where a joint meets the model's boundary, a micrometre past the end of its joint's
    /// edge (the joint has slid), stays on the joint: the other block's boundary edge is beside it
    /// and faced by its joint face, but the node's own boundary face runs on past that edge's
    /// end, side by side with it. Re-detection of the jointed tunnel took that edge and turned the
    /// joint's in-situ stress along the boundary.
    #[test]
    fn a_node_where_a_joint_meets_the_boundary_keeps_its_joint() {
        let mut x = wedge_and_block();
        let blocks = two_quadrilaterals(EdgeKind::Joint(0));
        let loaded = |_: &Touch| JointState {
            normal: -1e6,
            ..JointState::default()
        };
        let before = detect(&at(&blocks, &x), &Contacts::default(), &loaded);
        let tip = |c: &Contacts| {
            let i = (0..c.len()).find(|&i| c.node[i] == 0 && c.block[i] == 1);
            let i = i.expect("tip contact");
            (c.edge[i], c.state[i].normal)
        };
        assert_eq!(tip(&before), (4, -1e6));
        // Along the joint, past its end at the boundary (x = 0).
        let s = 1e-6 / 10f64.sqrt();
        x[0] = [-s, 3.0 * s];
        let after = detect(&at(&blocks, &x), &before, &|_| JointState::default());
        assert_eq!(tip(&after), (4, -1e6));
    }

    /// The edge grids change nothing: the tunnel model (its non-persistent joints leave large
    /// blocks with hundreds of boundary edges) gives the same contacts searched edge by edge, with
    /// grids on its large blocks, and with grids on nearly all.
    #[test]
    fn edge_grids_find_the_same_contacts() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/tunnel.json");
        let scene = crate::Scene::load(std::path::Path::new(path)).unwrap();
        let model = crate::setup::setup(&scene).unwrap().model;
        let x = model.nodes.current();
        let d = Detection::of(&model, &x);
        let largest = (0..model.blocks.len())
            .map(|b| model.blocks.edge_range(b).len())
            .max()
            .unwrap();
        assert!(largest >= 4 * MIN_EDGES, "{largest}");
        let fresh = |_: &Touch| JointState::default();
        let plain = detect_gridded(&d, &Contacts::default(), &fresh, usize::MAX);
        assert!(plain.len() > 1000, "{}", plain.len());
        for min_edges in [MIN_EDGES, 4] {
            let gridded = detect_gridded(&d, &Contacts::default(), &fresh, min_edges);
            assert_eq!(plain.node, gridded.node);
            assert_eq!(plain.edge, gridded.edge);
            assert_eq!(plain.block, gridded.block);
            assert_eq!(plain.xi, gridded.xi);
            assert_eq!(plain.length, gridded.length);
        }
    }

    /// Two unit squares meeting corner to corner at (1, 1), as diagonal blocks do where joints
    /// cross: their corners meet as rounded ones of radius `sharp_round`, along the diagonal,
    /// 2d(√2 − 1) apart, and the normal stays on the diagonal when a corner moves a micrometre
    /// across the other (an edge of the other corner would turn it by 90°).
    #[test]
    fn diagonal_corners_meet_along_the_line_of_their_arcs() {
        let mut blocks = two_quadrilaterals(EdgeKind::Joint(0));
        blocks.sharp_round = 1e-3;
        let square = |x0: f64, y0: f64| {
            [
                [x0, y0],
                [x0 + 1.0, y0],
                [x0 + 1.0, y0 + 1.0],
                [x0, y0 + 1.0],
            ]
        };
        let fresh = |t: &Touch| JointState {
            normal_displacement: t.gap,
            ..Default::default()
        };
        for shift in [-1e-6, 0.0, 1e-6] {
            let x: Vec<[f64; 2]> = square(0.0, 0.0)
                .into_iter()
                .chain(square(1.0 + shift, 1.0))
                .collect();
            let c = detect(&at(&blocks, &x), &Contacts::default(), &fresh);
            assert_eq!(c.len(), 2, "shift {shift}: {:?}", c.node);
            for k in 0..2 {
                assert!(c.corner[k]);
                let n = crate::cycle::contact_normal(
                    &blocks,
                    &|v: u32| x[v as usize],
                    c.node[k],
                    c.edge[k],
                    true,
                );
                // From the other block's corner to the node's: (−1, −1)/√2 for A's node 2.
                let sign = if c.node[k] == 2 { -1.0 } else { 1.0 };
                let turned = (n[0] * sign + n[1] * sign) / 2f64.sqrt();
                assert!(
                    turned > 0.999_999,
                    "shift {shift}: node {} normal {n:?}",
                    c.node[k]
                );
                let gap = c.state[k].normal_displacement;
                assert!((gap - 2e-3 * (2f64.sqrt() - 1.0)).abs() < 2e-6, "gap {gap}");
            }
        }
        // Without rounding the corners take an edge of each other, and which one flips with the
        // micrometre.
        blocks.sharp_round = 0.0;
        let x: Vec<[f64; 2]> = square(0.0, 0.0)
            .into_iter()
            .chain(square(1.0, 1.0))
            .collect();
        let c = detect(&at(&blocks, &x), &Contacts::default(), &fresh);
        assert!(c.corner.iter().all(|&k| !k));
    }

    #[test]
    fn touching_squares_make_four_contacts_on_the_shared_face() {
        let (blocks, x) = two_squares();
        let d = at(&blocks, &x);
        let c = detect(&d, &Contacts::default(), &|t: &Touch| JointState {
            normal_displacement: t.gap,
            ..Default::default()
        });
        assert_eq!(c.len(), 4);
        // Each corner node stands for half its edge on the face, halved for the two sides: ¼ m;
        // together the contacts cover the 1 m face once.
        assert!(c.length.iter().all(|&l| (l - 0.25).abs() < 1e-12));
        // Corner nodes pick the facing edge (the shared face), not the neighbour's bottom or top.
        assert!(c.edge.iter().all(|&e| e == 1 || e == 7), "{:?}", c.edge);
        assert_eq!(candidate_pairs(&blocks, &x, 1e-3), [(0, 1)]);
    }

    #[test]
    fn distant_squares_make_none_and_history_survives_redetection() {
        let (blocks, mut x) = two_squares();
        for p in &mut x[4..] {
            p[0] += 0.5;
        }
        let d = at(&blocks, &x);
        assert!(detect(&d, &Contacts::default(), &|_: &Touch| JointState::default()).is_empty());
        let (blocks, x) = two_squares();
        let d = at(&blocks, &x);
        let first = detect(&d, &Contacts::default(), &|_: &Touch| JointState {
            shear: 7.0,
            ..Default::default()
        });
        let again = detect(&d, &first, &|_: &Touch| JointState::default());
        assert!(again.state.iter().all(|s| s.shear == 7.0));
    }

    /// A square beside a narrow diagonal block, inside its bounding box and behind the line of its
    /// far edge (within half that edge's length), with its corners facing that edge: no contact.
    #[test]
    fn a_node_behind_the_far_edge_of_a_narrow_block_is_not_inside_it() {
        let x = vec![
            [0.0, 0.0],
            [4.0, 4.0],
            [3.6, 4.4],
            [-0.4, 0.4],
            [1.0, 3.0],
            [1.0, 2.8],
            [1.2, 2.8],
            [1.2, 3.0],
        ];
        let blocks = two_quadrilaterals(EdgeKind::Joint(0));
        let c = detect(&at(&blocks, &x), &Contacts::default(), &|_: &Touch| {
            JointState::default()
        });
        assert!(c.is_empty(), "{c:?}");
        // Pressed 2 mm (beyond the 1 mm tolerance) into the narrow block, its nearest corner is inside.
        let mut pressed = x.clone();
        for p in &mut pressed[4..] {
            let push = 0.4 + 2e-3 * std::f64::consts::FRAC_1_SQRT_2;
            p[0] += push;
            p[1] -= push;
        }
        let c = detect(
            &at(&blocks, &pressed),
            &Contacts::default(),
            &|t: &Touch| JointState {
                normal_displacement: t.gap,
                ..Default::default()
            },
        );
        let k = c.node.iter().position(|&n| n == 6).expect("node 6 inside");
        assert_eq!(c.edge[k], 2);
        assert!(
            (c.state[k].normal_displacement + 2e-3).abs() < 1e-9,
            "{c:?}"
        );
    }

    /// Two rigid squares meeting corner to corner (the second moved diagonally by s from sharing
    /// its face): rounded with radius r, each corner touches the other along the diagonal line of
    /// the rounding centres when their arcs are within the tolerance.
    #[test]
    fn rounded_corners_meet_along_the_line_of_centres() {
        let (mut blocks, mut x) = two_squares();
        let r = 0.05;
        // Arcs 0.2 mm apart: √2 (s + 2r) − 2r = 0.2 mm.
        let s = (2.0 * r + 0.2e-3) / std::f64::consts::SQRT_2 - 2.0 * r;
        for p in &mut x[4..] {
            p[0] += s;
            p[1] += 1.0 + s;
        }
        let fresh = |t: &Touch| JointState {
            normal_displacement: t.gap,
            ..Default::default()
        };
        blocks.round = crate::contact::rounding::radii(&blocks, &x, r, |_| true);
        let rounded = detect(&at(&blocks, &x), &Contacts::default(), &fresh);
        // Node 2 (top right of the first square) against node 4 (bottom left of the second), both ways.
        assert_eq!(rounded.len(), 2, "{rounded:?}");
        for k in 0..2 {
            assert!(rounded.corner[k]);
            assert_eq!(rounded.xi[k], 0.0);
            assert!((rounded.state[k].normal_displacement - 0.2e-3).abs() < 1e-12);
        }
    }
}
