//! Cutting a region into blocks: the planar arrangement of region edges, excavation walls and joint
//! traces. All segments are split at their intersections (vertices closer than a tolerance are
//! merged), joint pieces with a free end are pruned repeatedly (a joint that ends inside a block
//! becomes part of the block, as in UDEC), and the faces of the remaining graph are traced with
//! half-edges; faces inside the region and outside every excavation are the blocks. A component
//! floating inside a face (an isolated excavation, a closed joint loop) is a hole of that face.

use crate::Map;

use crate::domain::Domain;
use crate::error::MeshError;
use crate::geometry::{Point, Polygon, distance, orient, segment_distance};
use crate::joints::{EdgeKind, Segment};
use crate::polygon_index::PolygonIndex;
use crate::segment_grid::SegmentGrid;

/// One block: an outer ring (counter-clockwise) and holes (clockwise), each edge with its kind.
#[derive(Debug, Clone, PartialEq)]
pub struct Block {
    pub outer: Polygon,
    /// Kind of outer edge i (vertex i → i+1).
    pub outer_kinds: Vec<EdgeKind>,
    pub holes: Vec<Polygon>,
    pub hole_kinds: Vec<Vec<EdgeKind>>,
}

impl Block {
    /// The whole domain as one block: region edges `Region(i)`, excavation walls `Excavation(j)`.
    pub fn from_domain(domain: &Domain) -> Block {
        Block {
            outer: domain.outer.clone(),
            outer_kinds: (0..domain.outer.len() as u32)
                .map(EdgeKind::Region)
                .collect(),
            holes: domain.holes.iter().map(|h| h.polygon.clone()).collect(),
            hole_kinds: (0..domain.holes.len())
                .map(|j| vec![EdgeKind::Excavation(j as u32); domain.holes[j].polygon.len()])
                .collect(),
        }
    }

    /// Whether every vertex of the block lies inside `polygon` or within `tol` of its boundary.
    /// (Not how a block is found to fill an excavation: a sliver of rock along the wall passes
    /// this too; `adit` weighs where the block's area lies.)
    pub fn within(&self, polygon: &Polygon, tol: f64) -> bool {
        self.outer
            .vertices
            .iter()
            .all(|&v| polygon.contains(v) || polygon.boundary_distance(v) <= tol)
    }

    /// Net area, m².
    pub fn area(&self) -> f64 {
        self.outer.signed_area() + self.holes.iter().map(|h| h.signed_area()).sum::<f64>()
    }

    /// Every ring of the block, outer first, with the kinds of its edges.
    pub fn rings(&self) -> impl Iterator<Item = (&Polygon, &[EdgeKind])> {
        std::iter::once((&self.outer, &self.outer_kinds[..]))
            .chain((self.holes.iter().zip(&self.hole_kinds)).map(|(h, k)| (h, &k[..])))
    }
}

/// The edges of `rings` (a block's rings with their edge kinds) as segments, ring by ring in order.
pub(crate) fn ring_segments<'a>(
    rings: impl Iterator<Item = (&'a Polygon, &'a [EdgeKind])>,
) -> Vec<Segment> {
    rings
        .flat_map(|(ring, kinds)| {
            (0..ring.len()).map(move |i| {
                let (a, b) = ring.edge(i);
                Segment {
                    a,
                    b,
                    kind: kinds[i],
                }
            })
        })
        .collect()
}

/// The blocks of a region and what the cutting found.
#[derive(Debug, Clone, PartialEq)]
pub struct Blocking {
    pub blocks: Vec<Block>,
    /// Total length of joint traces inside the rock that ended inside a block and were absorbed
    /// into it, m.
    pub absorbed_joint_length: f64,
    /// Blocks smaller than `1e-6` of the region's area or thinner than the tolerance
    /// (area / longest edge), by index: kept, but worth a warning.
    pub slivers: Vec<usize>,
    /// The vertices the cutter moved onto another within the tolerance.
    pub merges: Merges,
    /// Joints the cutter laid onto a wall, one entry per joint feature, in feature order.
    pub onto_walls: Vec<OntoWall>,
}

/// Joint traces of one feature (a joint set or line) that lay along a wall (a region edge or an
/// excavation's) within the tolerance, off it by more than a thousandth of it: merging moved their
/// vertices onto the wall's, and the pieces then ran along the wall and were dropped, so there the
/// joint is the wall and carries no joint law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OntoWall {
    pub kind: EdgeKind,
    /// Length of the pieces dropped, m.
    pub length: f64,
    /// The largest distance of a dropped piece's midpoint from its joint trace, m, and that
    /// midpoint.
    pub offset: f64,
    pub at: Point,
}

/// Vertices merged into another one within the tolerance by more than a thousandth of it (a
/// crossing computed twice, from each of its segments, moves by round-off only and is not
/// counted): joint ends snapped onto a joint or a wall, crossings onto a corner.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Merges {
    pub count: usize,
    /// The largest move, m, and where it went.
    pub largest: f64,
    pub at: Point,
}

/// The joints laid onto walls so far, by feature.
#[derive(Default)]
struct OntoWalls(Vec<OntoWall>);

impl OntoWalls {
    /// Note that the piece a–b (m) of joint segment `s` lies along a wall, if merging moved it
    /// there (its midpoint off `s` by more than a thousandth of `tol`).
    fn note(&mut self, s: &Segment, a: Point, b: Point, tol: f64) {
        let mid = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
        let offset = segment_distance(mid, s.a, s.b);
        if offset <= 1e-3 * tol {
            return;
        }
        let i = match self.0.iter().position(|o| o.kind == s.kind) {
            Some(i) => i,
            None => {
                let (kind, at) = (s.kind, mid);
                self.0.push(OntoWall {
                    kind,
                    length: 0.0,
                    offset,
                    at,
                });
                self.0.len() - 1
            }
        };
        let o = &mut self.0[i];
        o.length += distance(a, b);
        if offset > o.offset {
            (o.offset, o.at) = (offset, mid);
        }
    }

    fn into_sorted(mut self) -> Vec<OntoWall> {
        self.0.sort_by_key(|o| o.kind);
        self.0
    }
}

/// Merges points closer than the tolerance (uniform hash grid). A point merges into the nearest
/// wall vertex within the tolerance (a region or excavation corner, or a point where a wall was
/// split), else into the nearest other vertex: taking the first one found let a joint's crossing
/// with a wall merge into a joint–joint crossing just off the wall while the wall's own split
/// merged into its corner, and the joint piece then crossed the wall.
struct VertexPool {
    pts: Vec<Point>,
    /// Whether each vertex lies on a wall (inserted while the walls were split).
    wall: Vec<bool>,
    grid: Map<(i64, i64), Vec<u32>>,
    tol: f64,
    merges: Merges,
}

impl VertexPool {
    fn cell(&self, p: Point) -> (i64, i64) {
        (
            (p[0] / self.tol).floor() as i64,
            (p[1] / self.tol).floor() as i64,
        )
    }

    fn insert(&mut self, p: Point, on_wall: bool) -> u32 {
        let (cx, cy) = self.cell(p);
        let mut best: Option<(bool, f64, u32)> = None;
        for dx in -1..=1 {
            for dy in -1..=1 {
                for &v in self.grid.get(&(cx + dx, cy + dy)).into_iter().flatten() {
                    let d = distance(self.pts[v as usize], p);
                    if d > self.tol {
                        continue;
                    }
                    // Wall vertices first, then the nearest; ties to the lower id (deterministic).
                    let key = (!self.wall[v as usize], d, v);
                    if best.is_none_or(|b| key < b) {
                        best = Some(key);
                    }
                }
            }
        }
        if let Some((_, d, v)) = best {
            if d > 1e-3 * self.tol {
                let m = &mut self.merges;
                m.count += 1;
                if d > m.largest {
                    (m.largest, m.at) = (d, self.pts[v as usize]);
                }
            }
            return v;
        }
        let id = self.pts.len() as u32;
        self.pts.push(p);
        self.wall.push(on_wall);
        self.grid.entry((cx, cy)).or_default().push(id);
        id
    }
}

/// Parameters along `s` (0..1) where it meets `o`: a proper or touching crossing, and the ends of
/// `o` lying on `s` (within `tol`), so that collinear overlaps split too.
fn split_params(s: &Segment, o: &Segment, tol: f64, out: &mut Vec<f64>) {
    let (ax, ay, dx, dy) = (s.a[0], s.a[1], s.b[0] - s.a[0], s.b[1] - s.a[1]);
    let (ex, ey) = (o.b[0] - o.a[0], o.b[1] - o.a[1]);
    let len2 = dx * dx + dy * dy;
    let project = |p: Point| ((p[0] - ax) * dx + (p[1] - ay) * dy) / len2;
    for p in [o.a, o.b] {
        if segment_distance(p, s.a, s.b) <= tol {
            out.push(project(p).clamp(0.0, 1.0));
        }
    }
    let den = dx * ey - dy * ex;
    if den.abs() <= 1e-14 * len2.sqrt() * (ex * ex + ey * ey).sqrt() {
        return;
    }
    let (wx, wy) = (o.a[0] - ax, o.a[1] - ay);
    let t = (wx * ey - wy * ex) / den;
    let u = (wx * dy - wy * dx) / den;
    let (lt, lu) = (tol / len2.sqrt(), tol / (ex * ex + ey * ey).sqrt());
    if t >= -lt && t <= 1.0 + lt && u >= -lu && u <= 1.0 + lu {
        out.push(t.clamp(0.0, 1.0));
    }
}

/// Whether the boxes of `s` and `o`, widened by `tol` (m), overlap.
pub(crate) fn bbox_overlap(s: &Segment, o: &Segment, tol: f64) -> bool {
    (0..2).all(|k| {
        s.a[k].min(s.b[k]) <= o.a[k].max(o.b[k]) + tol
            && o.a[k].min(o.b[k]) <= s.a[k].max(s.b[k]) + tol
    })
}

/// Cut `domain` into blocks along `joints`. `tol` (m) merges nearly coincident vertices; a fraction
/// (≈ 0.3) of the smallest zone size keeps joints from cutting sliver edges that no mesh refinement
/// can grade well (a joint meeting an excavation's polygon just beside one of its vertices).
pub fn cut_blocks(domain: &Domain, joints: &[Segment], tol: f64) -> Result<Blocking, MeshError> {
    cut_blocks_filled(domain, &vec![false; domain.holes.len()], joints, tol)
}

/// `cut_blocks` with some excavations still filled (`filled[j]`, staged excavations): their walls
/// cut blocks like joints (edges of kind `Excavation(j)`) and the rock inside them is kept as
/// blocks, to be removed when the excavation happens.
pub fn cut_blocks_filled(
    domain: &Domain,
    filled: &[bool],
    joints: &[Segment],
    tol: f64,
) -> Result<Blocking, MeshError> {
    let holes: Vec<PolygonIndex> = domain
        .holes
        .iter()
        .map(|h| PolygonIndex::new(&h.polygon, 0.0))
        .collect();
    let open = |p: Point| holes.iter().zip(filled).any(|(h, &f)| !f && h.contains(p));
    let mut segs: Vec<Segment> = Vec::new();
    for i in 0..domain.outer.len() {
        let (a, b) = domain.outer.edge(i);
        segs.push(Segment {
            a,
            b,
            kind: EdgeKind::Region(i as u32),
        });
    }
    for (j, h) in domain.holes.iter().enumerate() {
        for i in 0..h.polygon.len() {
            let (a, b) = h.polygon.edge(i);
            segs.push(Segment {
                a,
                b,
                kind: EdgeKind::Excavation(j as u32),
            });
        }
    }
    let walls = segs.len();
    segs.extend(joints.iter().filter(|s| distance(s.a, s.b) > tol).copied());

    // Split every segment at every meeting point; deduplicate edges, boundary kinds first.
    let mut pool = VertexPool {
        pts: Vec::new(),
        wall: Vec::new(),
        grid: Map::default(),
        tol,
        merges: Merges::default(),
    };
    // The region's and excavations' corners go in first, so that a crossing within the tolerance
    // of a corner merges into it and never the corner into the crossing (which would tilt the
    // wall and could leave a block outside the region).
    for s in &segs[..walls] {
        pool.insert(s.a, true);
    }
    let mut edges: Map<(u32, u32), EdgeKind> = Map::default();
    // The joint segment each joint edge came from first (how far merging moved it).
    let mut source: Map<(u32, u32), u32> = Map::default();
    let mut onto_walls = OntoWalls::default();
    let mut params = Vec::new();
    let grid = SegmentGrid::new(&segs, tol);
    let mut near = Vec::new();
    for (i, s) in segs.iter().enumerate() {
        params.clear();
        params.extend([0.0, 1.0]);
        grid.candidates(i, &mut near);
        for &j in &near {
            let o = &segs[j as usize];
            if j as usize != i && bbox_overlap(s, o, tol) {
                split_params(s, o, tol, &mut params);
            }
        }
        params.sort_by(f64::total_cmp);
        let mut prev: Option<u32> = None;
        for &t in params.iter() {
            let v = pool.insert(
                [
                    s.a[0] + t * (s.b[0] - s.a[0]),
                    s.a[1] + t * (s.b[1] - s.a[1]),
                ],
                i < walls,
            );
            if let Some(u) = prev.filter(|&u| u != v) {
                let key = (u.min(v), u.max(v));
                let kind = edges.entry(key).or_insert(s.kind);
                if matches!(s.kind, EdgeKind::Joint(_)) {
                    if matches!(kind, EdgeKind::Joint(_)) {
                        source.entry(key).or_insert(i as u32);
                    } else {
                        let (a, b) = (pool.pts[u as usize], pool.pts[v as usize]);
                        onto_walls.note(s, a, b, tol);
                    }
                }
                *kind = (*kind).min(s.kind);
            }
            prev = Some(v);
        }
    }
    let (pts, merges) = (pool.pts, pool.merges);

    // Merging can leave a joint piece running along a wall between two wall vertices, doubling the
    // wall's own pieces there; drop it, so that every wall keeps its exact path.
    let wall_pieces: Vec<Segment> = edges
        .iter()
        .filter(|(_, k)| !matches!(k, EdgeKind::Joint(_)))
        .map(|(&(u, v), &kind)| Segment {
            a: pts[u as usize],
            b: pts[v as usize],
            kind,
        })
        .collect();
    let eps = 1e-9 * domain.outer.size();
    let wall_grid = SegmentGrid::new(&wall_pieces, eps);
    let along_wall = |a: Point, b: Point| {
        let m = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
        wall_grid.at(m).iter().any(|&w| {
            let w = &wall_pieces[w as usize];
            segment_distance(m, w.a, w.b) <= eps
        })
    };
    edges.retain(|&(u, v), &mut kind| {
        let (a, b) = (pts[u as usize], pts[v as usize]);
        if !matches!(kind, EdgeKind::Joint(_)) || !along_wall(a, b) {
            return true;
        }
        if let Some(&i) = source.get(&(u, v)) {
            onto_walls.note(&segs[i as usize], a, b, tol);
        }
        false
    });

    split_at_vertices_on_joints(&pts, &mut edges, tol);
    split_crossings(&pts, &mut edges, tol);

    // Prune free joint ends until every vertex has degree ≥ 2: from each vertex of degree 1, along
    // its one edge, and on from the other end if that is left with one.
    let mut degree = vec![0u32; pts.len()];
    let mut incident: Vec<Vec<(u32, u32)>> = vec![Vec::new(); pts.len()];
    for &(u, v) in edges.keys() {
        for w in [u, v] {
            degree[w as usize] += 1;
            incident[w as usize].push((u, v));
        }
    }
    let outer = PolygonIndex::new(&domain.outer, 0.0);
    let in_rock = |p: Point| outer.contains(p) && !open(p);
    let mut absorbed = 0.0;
    let mut free: Vec<u32> = (0..pts.len() as u32)
        .filter(|&v| degree[v as usize] == 1)
        .collect();
    free.reverse();
    while let Some(end) = free.pop() {
        let Some(key) = incident[end as usize]
            .iter()
            .copied()
            .find(|k| edges.contains_key(k))
        else {
            continue;
        };
        let kind = edges.remove(&key).expect("found above");
        if !matches!(kind, EdgeKind::Joint(_)) {
            return Err(MeshError::Triangulation(format!(
                "a {kind} edge has a free end at ({}, {}); the region or an excavation is not closed",
                pts[end as usize][0], pts[end as usize][1]
            )));
        }
        // Only pieces inside the rock count: traces beyond the region are just cut off.
        let (a, b) = (pts[key.0 as usize], pts[key.1 as usize]);
        let mid = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
        if in_rock(mid) {
            absorbed += distance(a, b);
        }
        for w in [key.0, key.1] {
            degree[w as usize] -= 1;
            if degree[w as usize] == 1 {
                free.push(w);
            }
        }
    }

    let faces = trace_faces(&pts, &edges);
    let blocking = assemble_blocks(domain, &in_rock, &pts, faces, tol, absorbed)?;
    Ok(Blocking {
        merges,
        onto_walls: onto_walls.into_sorted(),
        ..blocking
    })
}

/// How near a joint edge, as a fraction of the merge tolerance, a vertex splits it
/// (`split_at_vertices_on_joints`): the overlap merging left ran through the vertex (to
/// round-off; the tolerance was 0.059 m), and a vertex further off makes a sliver the repairs of
/// `zoning.accept_angle` deal with. Splitting at up to the whole tolerance moved the bundled
/// models' joints (the jointed tunnel lost 42 of its 2 433 zones).
const ON_EDGE: f64 = 0.01;

/// Split each joint edge at the vertices merging left on it (within `ON_EDGE` × `tol`, m, of it
/// and not within `tol` of its ends), until none is. Merging moves a vertex by up to `tol`, and so
/// can bring a vertex onto a joint edge it was not split at: two joints crossing at a few degrees
/// with a third joint's end between them merged into one vertex that left a piece of one joint
/// running through a vertex of the other, along its two pieces: a block of no area whose boundary
/// crossed itself. Split there, the pieces coincide and count once (the lower kind, as for any
/// edge met twice).
fn split_at_vertices_on_joints(pts: &[Point], edges: &mut Map<(u32, u32), EdgeKind>, tol: f64) {
    // Each pass splits edges at vertices they did not end at; bounded by the vertices there are.
    for _ in 0..=pts.len() {
        let mut joint_edges = sorted(edges);
        joint_edges.retain(|(_, k)| matches!(k, EdgeKind::Joint(_)));
        let segs = segments_of(pts, &joint_edges);
        let grid = SegmentGrid::new(&segs, tol);
        let mut used = vec![false; pts.len()];
        for &(u, v) in edges.keys() {
            used[u as usize] = true;
            used[v as usize] = true;
        }
        // Each edge split at the first vertex (in order) on it.
        let mut splits: Vec<(usize, u32)> = Vec::new();
        let mut split = vec![false; segs.len()];
        for (w, &p) in pts.iter().enumerate().filter(|&(w, _)| used[w]) {
            for &e in grid.at(p) {
                let ((u, v), _) = joint_edges[e as usize];
                let (a, b) = (pts[u as usize], pts[v as usize]);
                if split[e as usize]
                    || w as u32 == u
                    || w as u32 == v
                    || distance(p, a) <= tol
                    || distance(p, b) <= tol
                    || segment_distance(p, a, b) > ON_EDGE * tol
                {
                    continue;
                }
                split[e as usize] = true;
                splits.push((e as usize, w as u32));
            }
        }
        if splits.is_empty() {
            return;
        }
        for (e, w) in splits {
            split_edge(edges, joint_edges[e], w);
        }
    }
}

/// Split the joint edges that merging left crossing another edge with no vertex between them, each
/// at the other edge's end nearest the crossing when that is within `tol` (m) of it, until none
/// crosses. Merging puts a crossing where a vertex within `tol` already was, and so two joints'
/// crossing could go to a vertex on one joint but another on the other: each passed the other's
/// vertex by 0.047 and 0.059 m and their pieces crossed, a block whose boundary crossed itself.
/// One split at a time, the lowest crossing pair first: the result does not depend on the map's
/// order.
fn split_crossings(pts: &[Point], edges: &mut Map<(u32, u32), EdgeKind>, tol: f64) {
    let mut near = Vec::new();
    // Each split adds a vertex to a joint; bounded by the edges there were (a crossing left is
    // the triangulation's to report).
    for _ in 0..=edges.len() {
        let list = sorted(edges);
        let segs = segments_of(pts, &list);
        let grid = SegmentGrid::new(&segs, tol);
        let mut split = None;
        'pairs: for i in 0..segs.len() {
            grid.candidates(i, &mut near);
            for &j in near.iter().filter(|&&j| j as usize > i) {
                let ((a, b), (c, d)) = (list[i].0, list[j as usize].0);
                if a == c || a == d || b == c || b == d {
                    continue;
                }
                let (s, o) = (&segs[i], &segs[j as usize]);
                let (d1, d2) = (orient(o.a, o.b, s.a), orient(o.a, o.b, s.b));
                let (d3, d4) = (orient(s.a, s.b, o.a), orient(s.a, s.b, o.b));
                if d1 * d2 >= 0.0 || d3 * d4 >= 0.0 {
                    continue;
                }
                let t = d1 / (d1 - d2);
                let x = [
                    s.a[0] + t * (s.b[0] - s.a[0]),
                    s.a[1] + t * (s.b[1] - s.a[1]),
                ];
                // Each end of one edge, as a place to split the other (a joint edge) at.
                let options = [(c, i), (d, i), (a, j as usize), (b, j as usize)];
                let best = options
                    .into_iter()
                    .filter(|&(_, e)| matches!(list[e].1, EdgeKind::Joint(_)))
                    .map(|(w, e)| (distance(pts[w as usize], x), w, e))
                    .filter(|&(gap, _, _)| gap <= tol)
                    .min_by(|p, q| p.0.total_cmp(&q.0));
                if let Some((_, w, e)) = best {
                    split = Some((list[e], w));
                    break 'pairs;
                }
            }
        }
        let Some((edge, w)) = split else {
            return;
        };
        split_edge(edges, edge, w);
    }
}

/// The edges of the arrangement in the order of their vertex numbers (not the map's).
fn sorted(edges: &Map<(u32, u32), EdgeKind>) -> Vec<((u32, u32), EdgeKind)> {
    let mut list: Vec<((u32, u32), EdgeKind)> = edges.iter().map(|(&k, &v)| (k, v)).collect();
    list.sort_unstable_by_key(|&(key, _)| key);
    list
}

/// The segments of `edges` between the points `pts`, m.
fn segments_of(pts: &[Point], edges: &[((u32, u32), EdgeKind)]) -> Vec<Segment> {
    edges
        .iter()
        .map(|&((u, v), kind)| Segment {
            a: pts[u as usize],
            b: pts[v as usize],
            kind,
        })
        .collect()
}

/// Replace edge (u, v) of `kind` by its two pieces at vertex `w`; a piece already there keeps the
/// lower kind, as any edge met twice.
fn split_edge(
    edges: &mut Map<(u32, u32), EdgeKind>,
    ((u, v), kind): ((u32, u32), EdgeKind),
    w: u32,
) {
    edges.remove(&(u, v));
    for key in [(u.min(w), u.max(w)), (v.min(w), v.max(w))] {
        let k = edges.entry(key).or_insert(kind);
        *k = (*k).min(kind);
    }
}

/// A closed cycle of the arrangement: its vertices and edge kinds, face on the left.
struct Cycle {
    verts: Vec<u32>,
    kinds: Vec<EdgeKind>,
    area: f64,
}

/// Trace every face of the planar graph with half-edges (face on the left of each half-edge).
fn trace_faces(pts: &[Point], edges: &Map<(u32, u32), EdgeKind>) -> Vec<Cycle> {
    let mut list: Vec<((u32, u32), EdgeKind)> = edges.iter().map(|(&k, &v)| (k, v)).collect();
    list.sort_unstable_by_key(|e| e.0);
    // Half-edge 2e runs u→v, 2e+1 runs v→u.
    let origin = |h: usize| {
        if h.is_multiple_of(2) {
            list[h / 2].0.0
        } else {
            list[h / 2].0.1
        }
    };
    let target = |h: usize| {
        if h.is_multiple_of(2) {
            list[h / 2].0.1
        } else {
            list[h / 2].0.0
        }
    };
    let mut out: Map<u32, Vec<usize>> = Map::default();
    for h in 0..2 * list.len() {
        out.entry(origin(h)).or_default().push(h);
    }
    let angle = |h: usize| {
        let (p, q) = (pts[origin(h) as usize], pts[target(h) as usize]);
        (q[1] - p[1]).atan2(q[0] - p[0])
    };
    let mut slot = vec![0usize; 2 * list.len()];
    for hs in out.values_mut() {
        hs.sort_by(|&a, &b| angle(a).total_cmp(&angle(b)));
        for (k, &h) in hs.iter().enumerate() {
            slot[h] = k;
        }
    }
    let next = |h: usize| {
        let twin = h ^ 1;
        let around = &out[&target(h)];
        around[(slot[twin] + around.len() - 1) % around.len()]
    };
    let mut seen = vec![false; 2 * list.len()];
    let mut cycles = Vec::new();
    for start in 0..2 * list.len() {
        if seen[start] {
            continue;
        }
        let (mut verts, mut kinds) = (Vec::new(), Vec::new());
        let mut h = start;
        while !seen[h] {
            seen[h] = true;
            verts.push(origin(h));
            kinds.push(list[h / 2].1);
            h = next(h);
        }
        for (verts, kinds) in split_pinches(verts, kinds) {
            let area = Polygon::new(verts.iter().map(|&v| pts[v as usize]).collect()).signed_area();
            cycles.push(Cycle { verts, kinds, area });
        }
    }
    cycles
}

/// Split a cycle that passes through a vertex more than once (two lobes touching at a point, or a
/// hole touching the outer ring) into simple cycles; `kinds[i]` belongs to the edge leaving
/// `verts[i]`.
fn split_pinches(verts: Vec<u32>, kinds: Vec<EdgeKind>) -> Vec<(Vec<u32>, Vec<EdgeKind>)> {
    let mut out = Vec::new();
    let (mut sv, mut sk): (Vec<u32>, Vec<EdgeKind>) = (Vec::new(), Vec::new());
    let mut at: Map<u32, usize> = Map::default();
    for (v, k) in verts.into_iter().zip(kinds) {
        if let Some(&j) = at.get(&v) {
            let (lv, lk) = (sv.split_off(j), sk.split_off(j));
            for u in &lv {
                at.remove(u);
            }
            out.push((lv, lk));
        }
        at.insert(v, sv.len());
        sv.push(v);
        sk.push(k);
    }
    out.push((sv, sk));
    out
}

/// Keep the faces whose inside is rock (`in_rock`: inside the region, outside the open excavations);
/// attach floating components as holes.
fn assemble_blocks(
    domain: &Domain,
    in_rock: &dyn Fn(Point) -> bool,
    pts: &[Point],
    cycles: Vec<Cycle>,
    tol: f64,
    absorbed_joint_length: f64,
) -> Result<Blocking, MeshError> {
    let polygon = |c: &Cycle| Polygon::new(c.verts.iter().map(|&v| pts[v as usize]).collect());
    let mut blocks: Vec<Block> = Vec::new();
    let mut floating = Vec::new();
    for c in &cycles {
        if c.area <= 0.0 {
            floating.push(c);
            continue;
        }
        // A point just left of the midpoint of the longest edge lies inside the face.
        let poly = polygon(c);
        let n = poly.len();
        let k = (0..n).max_by(|&i, &j| {
            let (a, b) = poly.edge(i);
            let (c2, d) = poly.edge(j);
            distance(a, b).total_cmp(&distance(c2, d))
        });
        let (a, b) = poly.edge(k.unwrap_or(0));
        let len = distance(a, b);
        let eps = (1e-6 * len).min(0.1 * c.area / len);
        let probe = [
            0.5 * (a[0] + b[0]) - eps * (b[1] - a[1]) / len,
            0.5 * (a[1] + b[1]) + eps * (b[0] - a[0]) / len,
        ];
        if in_rock(probe) {
            blocks.push(Block {
                outer: poly,
                outer_kinds: c.kinds.clone(),
                holes: vec![],
                hole_kinds: vec![],
            });
        }
    }
    // A floating component has a vertex strictly inside its host's outer ring; the region's own
    // outer cycle is inside no block. A host's box holds the component's box, which leaves few
    // blocks to ask, each through an index of its outer ring built once.
    let boxes: Vec<(Point, Point)> = blocks.iter().map(|b| b.outer.bounds()).collect();
    let mut indexes: Map<usize, PolygonIndex> = Map::default();
    let mut holes_of: Vec<(usize, &Cycle)> = Vec::new();
    for c in floating {
        let hole = polygon(c);
        let (lo, hi) = hole.bounds();
        let mut host: Option<usize> = None;
        for b in 0..blocks.len() {
            let (blo, bhi) = boxes[b];
            let holds = (0..2).all(|k| blo[k] - tol <= lo[k] && hi[k] <= bhi[k] + tol);
            if !holds
                || host
                    .is_some_and(|h| blocks[h].outer.signed_area() <= blocks[b].outer.signed_area())
            {
                continue;
            }
            let index = indexes
                .entry(b)
                .or_insert_with(|| PolygonIndex::new(&blocks[b].outer, tol));
            let strictly_inside = hole
                .vertices
                .iter()
                .any(|&p| !index.near_boundary(p) && index.contains(p));
            if strictly_inside {
                host = Some(b);
            }
        }
        if let Some(b) = host {
            holes_of.push((b, c));
        }
    }
    drop(indexes);
    for (b, c) in holes_of {
        blocks[b].holes.push(polygon(c));
        blocks[b].hole_kinds.push(c.kinds.clone());
    }
    let region_area = domain.outer.signed_area();
    let slivers = blocks
        .iter()
        .enumerate()
        .filter(|(_, b)| {
            let longest = (0..b.outer.len()).map(|i| {
                let (p, q) = b.outer.edge(i);
                distance(p, q)
            });
            let longest = longest.fold(0.0, f64::max);
            b.area() < 1e-6 * region_area || b.area() / longest < tol
        })
        .map(|(i, _)| i)
        .collect();
    Ok(Blocking {
        blocks,
        absorbed_joint_length,
        slivers,
        merges: Merges::default(),
        onto_walls: Vec::new(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::domain::Hole;
    use crate::joints::JointSet;
    use approx::assert_relative_eq;

    fn square(h: f64) -> Domain {
        let p = Polygon::new(vec![[0.0, 0.0], [h, 0.0], [h, h], [0.0, h]]);
        Domain::new(p, (0..4).map(|i| format!("e{i}")).collect(), vec![]).unwrap()
    }

    fn set(dip: f64, spacing: f64, origin: Point) -> JointSet {
        JointSet {
            dip_deg: dip,
            spacing,
            origin,
            trace: None,
            gap: 0.0,
            spread_dip_deg: 0.0,
            spread_spacing: 0.0,
            seed: 0,
        }
    }

    fn total_area(b: &Blocking) -> f64 {
        b.blocks.iter().map(Block::area).sum()
    }

    #[test]
    fn two_orthogonal_sets_make_a_grid_of_blocks() {
        let d = square(10.0);
        let mut joints =
            set(0.0, 2.5, [0.0, 0.0]).segments([0.0, 0.0], [10.0, 10.0], EdgeKind::Joint(0));
        joints.extend(set(90.0, 2.5, [0.0, 0.0]).segments(
            [0.0, 0.0],
            [10.0, 10.0],
            EdgeKind::Joint(1),
        ));
        let b = cut_blocks(&d, &joints, 1e-9).unwrap();
        assert_eq!(b.blocks.len(), 16);
        for blk in &b.blocks {
            assert_relative_eq!(blk.area(), 6.25, max_relative = 1e-12);
            assert_eq!(blk.outer.len(), 4);
        }
        assert!(b.slivers.is_empty());
        // Interior blocks have four joint edges; corner blocks two region and two joint edges.
        let joint_edges: usize = b
            .blocks
            .iter()
            .map(|k| {
                k.outer_kinds
                    .iter()
                    .filter(|e| matches!(e, EdgeKind::Joint(_)))
                    .count()
            })
            .sum();
        assert_eq!(joint_edges, 2 * 2 * 3 * 4);
    }

    #[test]
    fn inclined_set_with_a_tunnel_conserves_area() {
        let outer = Polygon::new(vec![
            [-10.0, -10.0],
            [10.0, -10.0],
            [10.0, 10.0],
            [-10.0, 10.0],
        ]);
        let hole = Hole {
            name: "t".into(),
            polygon: Polygon::circle([0.3, -0.2], 2.0, 64),
        };
        let d = Domain::new(outer, (0..4).map(|i| format!("e{i}")).collect(), vec![hole]).unwrap();
        let mut joints =
            set(35.0, 1.7, [0.1, 0.0]).segments([-10.0, -10.0], [10.0, 10.0], EdgeKind::Joint(0));
        joints.extend(set(-60.0, 2.3, [0.0, 0.4]).segments(
            [-10.0, -10.0],
            [10.0, 10.0],
            EdgeKind::Joint(1),
        ));
        let b = cut_blocks(&d, &joints, 1e-9).unwrap();
        assert_relative_eq!(total_area(&b), d.area(), max_relative = 1e-10);
        assert!(b.blocks.len() > 100);
        assert!(
            b.blocks
                .iter()
                .any(|k| k.outer_kinds.contains(&EdgeKind::Excavation(0)))
        );
        assert!(b.blocks.iter().all(|k| k.holes.is_empty()));
    }

    /// A filled (staged) tunnel keeps its rock as blocks of its own, bounded by its wall: the
    /// blocks tile the whole square.
    #[test]
    fn filled_tunnel_keeps_its_rock_as_blocks() {
        let outer = Polygon::new(vec![[-5.0, -5.0], [5.0, -5.0], [5.0, 5.0], [-5.0, 5.0]]);
        let hole = Hole {
            name: "t".into(),
            polygon: Polygon::circle([0.0, 0.0], 2.0, 48),
        };
        let d = Domain::new(outer, (0..4).map(|i| format!("e{i}")).collect(), vec![hole]).unwrap();
        let joints =
            set(10.0, 3.0, [0.0, 0.5]).segments([-5.0, -5.0], [5.0, 5.0], EdgeKind::Joint(0));
        let b = cut_blocks_filled(&d, &[true], &joints, 1e-9).unwrap();
        assert_relative_eq!(total_area(&b), 100.0, max_relative = 1e-10);
        let inside = |k: &Block| k.within(&d.holes[0].polygon, 1e-9);
        let fill: Vec<&Block> = b.blocks.iter().filter(|k| inside(k)).collect();
        assert!(fill.len() >= 2, "the joint cuts the fill");
        let fill_area: f64 = fill.iter().map(|k| k.area()).sum();
        assert_relative_eq!(
            fill_area,
            d.holes[0].polygon.signed_area().abs(),
            max_relative = 1e-10
        );
    }

    #[test]
    fn isolated_tunnel_is_a_hole_of_its_block() {
        let outer = Polygon::new(vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]);
        let hole = Hole {
            name: "t".into(),
            polygon: Polygon::circle([2.5, 2.5], 1.0, 32),
        };
        let d = Domain::new(outer, (0..4).map(|i| format!("e{i}")).collect(), vec![hole]).unwrap();
        let joints =
            set(0.0, 5.0, [0.0, 0.0]).segments([0.0, 0.0], [10.0, 10.0], EdgeKind::Joint(0));
        let b = cut_blocks(&d, &joints, 1e-9).unwrap();
        assert_eq!(b.blocks.len(), 2);
        assert_eq!(b.blocks.iter().map(|k| k.holes.len()).sum::<usize>(), 1);
        assert_relative_eq!(total_area(&b), d.area(), max_relative = 1e-12);
    }

    #[test]
    fn joints_ending_inside_a_block_are_absorbed() {
        let d = square(10.0);
        // One persistent horizontal joint, and a vertical trace from the bottom edge ending mid-block.
        let joints = vec![
            Segment {
                a: [0.0, 5.0],
                b: [10.0, 5.0],
                kind: EdgeKind::Joint(0),
            },
            Segment {
                a: [3.0, 0.0],
                b: [3.0, 8.0],
                kind: EdgeKind::Joint(1),
            },
            Segment {
                a: [6.0, 6.0],
                b: [8.0, 7.0],
                kind: EdgeKind::Joint(2),
            },
        ];
        let b = cut_blocks(&d, &joints, 1e-9).unwrap();
        // The vertical trace splits the lower half (it reaches y = 5), its upper part is absorbed.
        assert_eq!(b.blocks.len(), 3);
        assert_relative_eq!(
            b.absorbed_joint_length,
            3.0 + 5f64.sqrt(),
            max_relative = 1e-12
        );
        assert_relative_eq!(total_area(&b), 100.0, max_relative = 1e-12);
    }

    #[test]
    fn l_shaped_region_and_a_joint_through_a_vertex() {
        let l = Polygon::new(vec![
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 2.0],
            [2.0, 2.0],
            [2.0, 4.0],
            [0.0, 4.0],
        ]);
        let d = Domain::new(l, (0..6).map(|i| format!("e{i}")).collect(), vec![]).unwrap();
        // The diagonal passes through the re-entrant corner (2, 2) and crosses the notch outside.
        let joints = vec![Segment {
            a: [0.0, 0.0],
            b: [4.0, 4.0],
            kind: EdgeKind::Joint(0),
        }];
        let b = cut_blocks(&d, &joints, 1e-9).unwrap();
        assert_eq!(b.blocks.len(), 2);
        assert_relative_eq!(total_area(&b), 12.0, max_relative = 1e-12);
        // A joint along a region edge adds nothing.
        let along = vec![Segment {
            a: [0.0, 0.0],
            b: [4.0, 0.0],
            kind: EdgeKind::Joint(0),
        }];
        let b = cut_blocks(&d, &along, 1e-9).unwrap();
        assert_eq!(b.blocks.len(), 1);
        assert!(
            b.blocks[0]
                .outer_kinds
                .iter()
                .all(|k| matches!(k, EdgeKind::Region(_)))
        );
    }

    #[test]
    fn a_joint_loop_touching_the_boundary_at_one_point_is_a_block_of_its_own() {
        let d = square(2.0);
        let j = |a: Point, b: Point| Segment {
            a,
            b,
            kind: EdgeKind::Joint(0),
        };
        let joints = vec![
            j([1.0, 0.0], [0.5, 1.0]),
            j([0.5, 1.0], [1.5, 1.0]),
            j([1.5, 1.0], [1.0, 0.0]),
        ];
        let b = cut_blocks(&d, &joints, 1e-9).unwrap();
        assert_eq!(b.blocks.len(), 2);
        assert_relative_eq!(total_area(&b), 4.0, max_relative = 1e-12);
        assert!(
            b.blocks
                .iter()
                .all(|k| k.outer.self_intersection().is_none())
        );
    }

    #[test]
    fn region_corners_stay_put_when_a_joint_crosses_within_the_tolerance() {
        // The joint crosses the top and bottom edges 0.5 tol from the corners (0, 10) and (0, 0):
        // the crossings merge into the corners, never the corners into the crossings (which
        // would tilt the left edge and leave a block outside the region).
        let d = square(10.0);
        let joints = vec![Segment {
            a: [0.05, -1.0],
            b: [0.05, 11.0],
            kind: EdgeKind::Joint(0),
        }];
        let b = cut_blocks(&d, &joints, 0.1).unwrap();
        assert_relative_eq!(total_area(&b), 100.0, max_relative = 1e-12);
        for k in &b.blocks {
            assert!(k.within(&d.outer, 1e-12), "a block leaves the region");
        }
        let corners = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]];
        for c in corners {
            assert!(
                b.blocks.iter().any(|k| k.outer.vertices.contains(&c)),
                "corner {c:?} moved"
            );
        }
    }

    /// A joint along a side within the tolerance is merged into the side and reported with its
    /// length and how far it was off; one on the side, or beyond the tolerance, is not.
    #[test]
    fn a_joint_merged_into_a_wall_is_reported() {
        let d = square(10.0);
        let cut = |y: f64| {
            let joints = [
                Segment {
                    a: [-1.0, y],
                    b: [11.0, y],
                    kind: EdgeKind::Joint(0),
                },
                Segment {
                    a: [5.0, -1.0],
                    b: [5.0, 11.0],
                    kind: EdgeKind::Joint(1),
                },
            ];
            cut_blocks(&d, &joints, 0.1).unwrap()
        };
        let b = cut(0.05);
        assert_eq!(b.blocks.len(), 2, "the joint 0.05 m off the side is gone");
        assert_eq!(b.onto_walls.len(), 1);
        let o = b.onto_walls[0];
        assert_eq!(o.kind, EdgeKind::Joint(0));
        assert_relative_eq!(o.length, 10.0, max_relative = 1e-12);
        assert_relative_eq!(o.offset, 0.05, max_relative = 1e-9);
        assert_relative_eq!(o.at[1], 0.0);
        assert!(
            cut(0.0).onto_walls.is_empty(),
            "a joint on the side is the side"
        );
        let beyond = cut(0.2);
        assert_eq!(beyond.blocks.len(), 4);
        assert!(beyond.onto_walls.is_empty());
    }

    #[test]
    fn near_parallel_sets_report_slivers_without_failing() {
        let d = square(10.0);
        let mut joints =
            set(0.0, 1.0, [0.0, 0.05]).segments([0.0, 0.0], [10.0, 10.0], EdgeKind::Joint(0));
        joints.extend(set(3.0, 1.0, [0.0, 0.0]).segments(
            [0.0, 0.0],
            [10.0, 10.0],
            EdgeKind::Joint(1),
        ));
        let b = cut_blocks(&d, &joints, 1e-6).unwrap();
        assert_relative_eq!(total_area(&b), 100.0, max_relative = 1e-9);
        assert!(b.blocks.len() > 20);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// Whatever the joint sets, the blocks tile the domain: areas sum to its area and every
        /// block is a simple polygon of positive area.
        #[test]
        fn blocks_tile_the_domain(
            dip1 in -90.0f64..90.0, dip2 in -90.0f64..90.0,
            sp1 in 0.7f64..4.0, sp2 in 0.7f64..4.0,
            ox in -1.0f64..1.0, oy in -1.0f64..1.0,
            hole in proptest::bool::ANY,
            trace in proptest::option::of(1.0f64..6.0),
        ) {
            let outer = Polygon::new(vec![[-10.0, -8.0], [10.0, -8.0], [10.0, 8.0], [-10.0, 8.0]]);
            let holes = if hole {
                vec![Hole { name: "t".into(), polygon: Polygon::circle([ox, oy], 2.0, 48) }]
            } else {
                vec![]
            };
            let d = Domain::new(outer, (0..4).map(|i| format!("e{i}")).collect(), holes).unwrap();
            let (lo, hi) = ([-10.0, -8.0], [10.0, 8.0]);
            let mut joints = set(dip1, sp1, [ox, oy]).segments(lo, hi, EdgeKind::Joint(0));
            let second = JointSet { trace, gap: 0.5, ..set(dip2, sp2, [oy, ox]) };
            joints.extend(second.segments(lo, hi, EdgeKind::Joint(1)));
            let b = cut_blocks(&d, &joints, 1e-9).unwrap();
            let total: f64 = b.blocks.iter().map(Block::area).sum();
            proptest::prop_assert!((total - d.area()).abs() <= 1e-9 * d.area(), "{} vs {}", total, d.area());
            for k in &b.blocks {
                proptest::prop_assert!(k.area() > 0.0);
                proptest::prop_assert!(k.outer.self_intersection().is_none());
            }
        }

        /// A set nearly along the bottom side, one of its joints within a few tolerances of it,
        /// crossed by a second set, around a tunnel or not, cut at a tolerance of 0.2 m: the
        /// blocks tile the domain, and what is reported merged into a wall is of a joint that
        /// exists, no longer than its traces, and moved by more than a thousandth of the
        /// tolerance and at most the tolerance.
        #[test]
        fn joints_merged_into_walls_are_reported_within_the_tolerance(
            dip1 in -3.0f64..3.0, off in -0.6f64..0.6,
            dip2 in -90.0f64..90.0, sp2 in 0.9f64..4.0,
            ox in -1.0f64..1.0, hole in proptest::bool::ANY,
        ) {
            let tol = 0.2;
            let outer = Polygon::new(vec![[-10.0, -8.0], [10.0, -8.0], [10.0, 8.0], [-10.0, 8.0]]);
            let holes = if hole {
                vec![Hole { name: "t".into(), polygon: Polygon::circle([ox, 0.0], 2.0, 48) }]
            } else {
                vec![]
            };
            let d = Domain::new(outer, (0..4).map(|i| format!("e{i}")).collect(), holes).unwrap();
            let (lo, hi) = ([-10.0, -8.0], [10.0, 8.0]);
            let mut joints = set(dip1, 3.0, [0.0, -8.0 + off]).segments(lo, hi, EdgeKind::Joint(0));
            joints.extend(set(dip2, sp2, [ox, 0.3]).segments(lo, hi, EdgeKind::Joint(1)));
            let b = cut_blocks(&d, &joints, tol).unwrap();
            let total: f64 = b.blocks.iter().map(Block::area).sum();
            proptest::prop_assert!((total - d.area()).abs() <= 1e-9 * d.area(), "{} vs {}", total, d.area());
            for o in &b.onto_walls {
                let traces: f64 = (joints.iter().filter(|s| s.kind == o.kind))
                    .map(|s| distance(s.a, s.b))
                    .sum();
                proptest::prop_assert!(o.length > 0.0 && o.length <= traces, "{:?}", o);
                proptest::prop_assert!(o.offset > 1e-3 * tol && o.offset <= tol * (1.0 + 1e-9), "{:?}", o);
            }
        }
    }
}
