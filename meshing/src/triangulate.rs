//! Graded constrained-Delaunay zoning of a domain into triangles (spade 2.15).
//!
//! The local target edge length grows linearly away from the excavations,
//! `h(p) = min(h_far, h_exc + g · d(p))`, where d is the distance to the nearest hole wall and g the
//! grading. Boundaries are split once for all blocks (`spacing`: to h, finer across thin blocks and
//! near vertices), rings of points at spacing h are laid around each hole, and spade's Ruppert
//! refinement (angle limit, global maximum area from h_far, outer faces excluded, the split
//! boundary kept whole) fills the rest; see the meshing note of `design.md`.

use crate::{Map, Set};

use spade::{
    AngleLimit, ConstrainedDelaunayTriangulation, Point2, RefinementParameters, Triangulation,
};

use crate::blocks::{Block, ring_segments};
use crate::domain::Domain;
use crate::error::MeshError;
use crate::geometry::Polygon;
use crate::geometry::{Point, distance, orient, segment_distance, segments_intersect};
use crate::joints::EdgeKind;
use crate::pinch::split_pinches;
use crate::segment_grid::SegmentGrid;
use crate::spacing::{BoundarySpacing, Key, constrained_rings, key};

/// Zoning controls. Lengths in metres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Zoning {
    /// Target zone edge length on excavation walls, m.
    pub h_excavation: f64,
    /// Target (maximum) zone edge length far from excavations, m.
    pub h_far: f64,
    /// Growth of the edge length per metre of distance from the nearest excavation (dimensionless).
    pub grading: f64,
    /// Depth from the excavation walls over which the edge length stays `h_excavation` before it
    /// grades, m (0: grading starts at the wall).
    pub fine_depth: f64,
    /// Depth from the excavation walls where the rock is expected to yield, m (0: none): zones
    /// there are `PLASTIC_SCALE` of the graded size, and grade on from that size beyond it.
    pub plastic_depth: f64,
    /// Minimum interior angle the refinement aims for, degrees (at most 33).
    pub min_angle_deg: f64,
    /// Upper bound on the number of triangles; exceeding it is an error rather than a runaway.
    pub max_zones: usize,
}

/// A boundary edge of the mesh, oriented with the material on its left (outward normal to the right).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundaryEdge {
    pub nodes: [u32; 2],
    /// What the edge lies on: a region edge, an excavation wall or a joint.
    pub kind: EdgeKind,
}

/// Mesh quality figures.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshStats {
    pub zones: usize,
    pub nodes: usize,
    /// Smallest interior angle, degrees.
    pub min_angle_deg: f64,
    /// Shortest and longest edge, m.
    pub min_edge: f64,
    pub max_edge: f64,
    /// Total zone area, m².
    pub area: f64,
}

/// A triangle mesh: nodes, counter-clockwise triangles and labelled boundary edges.
#[derive(Debug, Clone)]
pub struct TriMesh {
    pub points: Vec<Point>,
    pub triangles: Vec<[u32; 3]>,
    pub boundary: Vec<BoundaryEdge>,
    /// Minimum angle the refinement aimed at, degrees (below `Zoning::min_angle_deg` where the
    /// refinement at that angle did not end; 0 for an outline).
    pub angle_limit_deg: f64,
}

/// Share of the graded zone size kept within `Zoning::plastic_depth` of a wall.
pub const PLASTIC_SCALE: f64 = 0.5;

impl Zoning {
    /// Target zone edge length at distance `d` (m) from the nearest excavation wall, m:
    /// h(d) = min(h_far, g(d) − (1 − k) g(min(d, D_p))) with the graded size
    /// g(d) = h_exc + grading · max(0, d − fine_depth), k = `PLASTIC_SCALE` and D_p the plastic
    /// depth: k g(d) within the plastic zone, growing on by the grading (continuous) beyond it.
    pub fn size_at(&self, d: f64) -> f64 {
        let graded = |d: f64| self.h_excavation + self.grading * (d - self.fine_depth).max(0.0);
        let refined = if self.plastic_depth > 0.0 {
            (1.0 - PLASTIC_SCALE) * graded(d.min(self.plastic_depth))
        } else {
            0.0
        };
        (graded(d) - refined).min(self.h_far)
    }

    fn check(&self) -> Result<(), MeshError> {
        let bad = |what: &str| Err(MeshError::Zoning(what.into()));
        if !(self.h_excavation > 0.0 && self.h_excavation.is_finite()) {
            return bad("edge length at the excavation must be positive");
        }
        if !(self.h_far >= self.h_excavation && self.h_far.is_finite()) {
            return bad("far edge length must be finite and at least the excavation edge length");
        }
        if !(self.grading > 0.0 && self.grading <= 2.0) {
            return bad("grading must be in (0, 2]");
        }
        if !(self.fine_depth >= 0.0 && self.fine_depth.is_finite()) {
            return bad("fine depth must be finite and not negative");
        }
        if !(self.plastic_depth >= 0.0 && self.plastic_depth.is_finite()) {
            return bad("plastic depth must be finite and not negative");
        }
        if !(self.min_angle_deg > 0.0 && self.min_angle_deg <= 33.0) {
            return bad("minimum angle must be in (0, 33] degrees");
        }
        Ok(())
    }
}

/// The constraint vertices and edges of a block's rings, each ring edge split by `spacing` (the
/// same points as the block across the edge; `split_alone` if the block `shares` no edge).
/// A point where rings meet (a hole touching the outer ring, the two faces of a joint piece
/// ending inside the block, a slit ring a → b → a) is one vertex, and an edge two rings share, or
/// a slit's two faces, is split once and constrained once: split
/// separately, the two faces of a slit got split points a rounding apart, whose constraint edges
/// overlapped, and spade refused them as crossing (17 of 30 realizations of the tunnel model's
/// joint sets shifted by up to 2 m).
fn ring_constraints(
    block: &Block,
    spacing: &BoundarySpacing,
    shares: bool,
) -> (Vec<Point2<f64>>, Vec<[usize; 2]>) {
    let mut vertices: Vec<Point2<f64>> = Vec::new();
    let mut index: Map<(u64, u64), usize> = Map::default();
    let mut vertex = |p: Point, vertices: &mut Vec<Point2<f64>>| {
        // +0.0 for −0.0, so the two zeros are one key.
        let p = [p[0] + 0.0, p[1] + 0.0];
        *index.entry(key(p)).or_insert_with(|| {
            vertices.push(Point2::new(p[0], p[1]));
            vertices.len() - 1
        })
    };
    // Split points of each undirected ring edge, from its lower end (`BoundarySpacing::split`).
    let mut splits: Map<(Key, Key), (Key, Vec<usize>)> = Map::default();
    let mut edges: Set<[usize; 2]> = Set::default();
    let mut ordered: Vec<[usize; 2]> = Vec::new();
    // A hole of no area is a joint piece ending inside the block, absorbed (both its faces are
    // the block's): constrained, its single edge would flip spade's inside/outside parity.
    for (ring, _) in constrained_rings(block) {
        for i in 0..ring.len() {
            let (a, b) = ring.edge(i);
            let (ka, kb) = (key(a), key(b));
            if ka == kb {
                continue;
            }
            let ia = vertex(a, &mut vertices);
            let (from, chain) = splits.entry((ka.min(kb), ka.max(kb))).or_insert_with(|| {
                let points = if shares {
                    spacing.split(a, b)
                } else {
                    spacing.split_alone(a, b)
                };
                let chain = points
                    .into_iter()
                    .map(|m| {
                        vertices.push(Point2::new(m[0], m[1]));
                        vertices.len() - 1
                    })
                    .collect();
                (ka, chain)
            });
            let mut inner = chain.clone();
            if *from != ka {
                inner.reverse();
            }
            let ib = vertex(b, &mut vertices);
            let path: Vec<usize> = std::iter::once(ia)
                .chain(inner)
                .chain(std::iter::once(ib))
                .collect();
            for w in path.windows(2) {
                let e = [w[0].min(w[1]), w[0].max(w[1])];
                if edges.insert(e) {
                    ordered.push(e);
                }
            }
        }
    }
    (vertices, ordered)
}

/// Mesh `domain` (one block: the region with its excavations as holes) with the given zoning.
pub fn triangulate(domain: &Domain, zoning: &Zoning) -> Result<TriMesh, MeshError> {
    let excavations: Vec<Polygon> = domain.holes.iter().map(|h| h.polygon.clone()).collect();
    triangulate_block(&Block::from_domain(domain), &excavations, zoning)
}

/// Mesh one block on its own, grading the zone size from the excavation walls `excavations`.
pub fn triangulate_block(
    block: &Block,
    excavations: &[Polygon],
    zoning: &Zoning,
) -> Result<TriMesh, MeshError> {
    let mut meshes = triangulate_blocks(std::slice::from_ref(block), &[true], excavations, zoning)?;
    Ok(meshes.remove(0))
}

/// Rounds of `BoundarySpacing::split_encroached` at most (the zones it mends are few: in the
/// jointed tunnel of the tests below, 20 of 1 651 zones under 20° before the first round).
const ENCROACHED_ROUNDS: usize = 4;

/// Zone the blocks of `blocks` that are `zoned` (the others get their outline: rigid or simple
/// blocks), grading from `excavations`, so that two zoned blocks put their nodes at the same places
/// along the edge between them: one `BoundarySpacing` for all, then rounds in which the pieces of
/// edge that zones the refinement could not mend encroach are split for both sides and those
/// blocks zoned again. Blocks are zoned in parallel; the result does not depend on the threads.
pub fn triangulate_blocks(
    blocks: &[Block],
    zoned: &[bool],
    excavations: &[Polygon],
    zoning: &Zoning,
) -> Result<Vec<TriMesh>, MeshError> {
    use rayon::prelude::*;
    zoning.check()?;
    let mut spacing = BoundarySpacing::new(blocks, zoned, excavations, zoning);
    let zone = |spacing: &BoundarySpacing, which: &[bool]| {
        (blocks.par_iter().zip(zoned).zip(which).enumerate())
            .map(|(i, ((b, &z), &w))| {
                let mesh = match (w, z) {
                    (false, _) => return Ok(None),
                    (true, true) => triangulate_spaced(b, spacing.shares_an_edge(i), spacing),
                    (true, false) => triangulate_outline(b),
                };
                mesh.map(Some).map_err(|e| e.in_block(i))
            })
            .collect::<Result<Vec<Option<TriMesh>>, MeshError>>()
    };
    let mut meshes: Vec<TriMesh> = zone(&spacing, &vec![true; blocks.len()])?
        .into_iter()
        .flatten()
        .collect();
    for _ in 0..ENCROACHED_ROUNDS {
        let of_zoned: Vec<Option<&TriMesh>> = (meshes.iter().zip(zoned))
            .map(|(m, &z)| z.then_some(m))
            .collect();
        let again = spacing.split_encroached(blocks, &of_zoned);
        if !again.contains(&true) {
            break;
        }
        for (i, mesh) in zone(&spacing, &again)?.into_iter().enumerate() {
            if let Some(mesh) = mesh {
                meshes[i] = mesh;
            }
        }
    }
    Ok(meshes)
}

/// Mesh one block of several, its boundary split by `spacing` (made for all of them, so the
/// blocks on either side of a joint put their nodes at the same places) and, if it shares an edge
/// with another zoned block (`keep`), kept whole by the refinement, which then adds vertices only
/// inside the block.
fn triangulate_spaced(
    block: &Block,
    keep: bool,
    spacing: &BoundarySpacing,
) -> Result<TriMesh, MeshError> {
    let (zoning, excavations) = (spacing.zoning(), spacing.excavations());
    let (mut vertices, edges) = ring_constraints(block, spacing, keep);
    let boundary_vertices = vertices.len();
    vertices.extend(
        graded_rings(block, excavations, zoning)
            .into_iter()
            .map(|p| Point2::new(p[0], p[1])),
    );
    // spade splits an edge of the triangulation's convex hull that a vertex encroaches even when
    // told to keep constraint edges, and a convex block's edges are that hull (a 0.03 m² block of
    // the jointed terrain got split points 4e-5 m apart, zones of 0°, and a joint node its
    // neighbour had not): four corners well outside the block make the hull theirs. The faces
    // between them and the block are outer faces, neither refined nor kept.
    if keep {
        let (lo, hi) = block.outer.bounds();
        let margin = 0.5 * distance(lo, hi);
        vertices.extend([
            Point2::new(lo[0] - margin, lo[1] - margin),
            Point2::new(hi[0] + margin, lo[1] - margin),
            Point2::new(hi[0] + margin, hi[1] + margin),
            Point2::new(lo[0] - margin, hi[1] + margin),
        ]);
    }

    let budget = zoning.max_zones.max(16 * boundary_vertices);
    let attempt = |angle: f64| {
        let params = |exclude: bool| {
            let p = RefinementParameters::<f64>::new()
                .exclude_outer_faces(exclude)
                .with_angle_limit(AngleLimit::from_deg(angle))
                .with_max_allowed_area(0.5 * zoning.h_far * zoning.h_far)
                .with_max_additional_vertices(budget);
            if keep { p.keep_constraint_edges() } else { p }
        };
        constrained_mesh(
            block,
            vertices.clone(),
            edges.clone(),
            &params,
            Some(budget),
        )
    };
    // Ruppert refinement is only sure to end where constraints meet at 60° or more; where it runs
    // out of vertices the block is zoned again aiming 10° lower (to 0°: the sizes alone), and
    // the mesh says what it aimed at.
    let mut angle = zoning.min_angle_deg;
    let mut mesh = attempt(angle);
    while matches!(mesh, Err(MeshError::Refinement(_))) && angle > 0.0 {
        angle = if angle > 10.0 { angle - 10.0 } else { 0.0 };
        mesh = attempt(angle);
    }
    let mut mesh = mesh?;
    mesh.angle_limit_deg = angle;
    if mesh.triangles.len() > zoning.max_zones {
        return Err(MeshError::TooManyZones {
            zones: mesh.triangles.len(),
            limit: zoning.max_zones,
        });
    }
    Ok(mesh)
}

/// Triangles over one block's own vertices, with no vertex added: the outline of a rigid or simple
/// block (drawn in the output; such blocks have no zones).
pub fn triangulate_outline(block: &Block) -> Result<TriMesh, MeshError> {
    let mut vertices: Vec<Point2<f64>> = Vec::new();
    let mut edges: Vec<[usize; 2]> = Vec::new();
    for ring in std::iter::once(&block.outer).chain(&block.holes) {
        let first = vertices.len();
        vertices.extend(ring.vertices.iter().map(|v| Point2::new(v[0], v[1])));
        let last = vertices.len();
        edges.extend((first..last).map(|k| [k, if k + 1 == last { first } else { k + 1 }]));
    }
    let params = |exclude: bool| {
        RefinementParameters::<f64>::new()
            .exclude_outer_faces(exclude)
            .with_angle_limit(AngleLimit::from_deg(0.0))
            .with_max_additional_vertices(0)
    };
    constrained_mesh(block, vertices, edges, &params, None)
}

/// Constrained Delaunay triangulation of the block rings `edges` over `vertices`, refined by
/// `params(exclude_outer_faces)`; `budget` (when given) is the vertex budget whose exhaustion is an
/// error. spade's outer-face exclusion decides inside and outside by crossing constraint edges,
/// which can fail for a block with many holes touching each other or its outer ring at a vertex;
/// when the kept triangles do not cover the block's area, the triangulation is redone refining the
/// whole hull and the triangles are kept by where their centroids lie.
fn constrained_mesh(
    block: &Block,
    vertices: Vec<Point2<f64>>,
    edges: Vec<[usize; 2]>,
    params: &dyn Fn(bool) -> RefinementParameters<f64>,
    budget: Option<usize>,
) -> Result<TriMesh, MeshError> {
    let mesh = constrained_mesh_with(
        block,
        vertices.clone(),
        edges.clone(),
        params(true),
        budget,
        false,
    )?;
    let area = block.area();
    if (mesh.stats().area - area).abs() <= 1e-9 * area.abs().max(f64::MIN_POSITIVE) {
        return Ok(mesh);
    }
    constrained_mesh_with(block, vertices, edges, params(false), budget, true)
}

/// What the block's ring edges that touch or cross the segment pa–pb lie on (each kind once): the
/// joints, walls or region edges of a crossing.
fn kinds_near(block: &Block, pa: Point, pb: Point) -> Vec<EdgeKind> {
    let tol = 1e-9 * block.outer.size();
    let rings = std::iter::once((&block.outer, &block.outer_kinds))
        .chain(block.holes.iter().zip(&block.hole_kinds));
    let mut kinds: Vec<EdgeKind> = Vec::new();
    for (ring, ring_kinds) in rings {
        for (i, &kind) in ring_kinds.iter().enumerate().take(ring.len()) {
            let (p, q) = ring.edge(i);
            let near = segment_distance(pa, p, q) <= tol
                || segment_distance(pb, p, q) <= tol
                || segments_intersect(pa, pb, p, q);
            if near && !kinds.contains(&kind) {
                kinds.push(kind);
            }
        }
    }
    kinds
}

/// One triangulation of `constrained_mesh` (`triangulate_once`), with spade's own panics (its
/// point location can fail on inputs it considers degenerate: "Failed to locate position") turned
/// into `MeshError::Triangulation`: the engine reports the block, never aborts.
fn constrained_mesh_with(
    block: &Block,
    vertices: Vec<Point2<f64>>,
    edges: Vec<[usize; 2]>,
    params: RefinementParameters<f64>,
    budget: Option<usize>,
    by_centroid: bool,
) -> Result<TriMesh, MeshError> {
    guarded(|| triangulate_once(block, vertices, edges, params, budget, by_centroid))
}

/// `f`'s result, or a `MeshError::Triangulation` carrying its panic message if it panicked.
/// Panics raised inside spade are kept off stderr (`quiet_spade_panics`); any other panic is
/// reported by the hook as before.
pub(crate) fn guarded<T>(f: impl FnOnce() -> Result<T, MeshError>) -> Result<T, MeshError> {
    quiet_spade_panics();
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).unwrap_or_else(|payload| {
        let message = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown failure".into());
        Err(MeshError::Triangulation(format!(
            "the triangulator failed on this block ({message}); joints too close to each other \
             or to a wall are the usual cause"
        )))
    })
}

/// Install, once, a panic hook that stays silent for panics raised in spade's source (they are
/// caught by `guarded` and become errors) and passes every other panic to the previous hook.
fn quiet_spade_panics() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            let in_spade = info.location().is_some_and(|l| l.file().contains("spade"));
            if !in_spade {
                previous(info);
            }
        }));
    });
}

/// One triangulation of `constrained_mesh`: faces excluded by spade, or (`by_centroid`) faces whose
/// centroid is outside the block's outer ring or inside one of its holes.
fn triangulate_once(
    block: &Block,
    vertices: Vec<Point2<f64>>,
    edges: Vec<[usize; 2]>,
    params: RefinementParameters<f64>,
    budget: Option<usize>,
    by_centroid: bool,
) -> Result<TriMesh, MeshError> {
    // Vertices inserted one by one, then the ring edges in their given order: the triangulation
    // depends on the input alone. (spade's bulk load re-inserts the vertices and edges its sweep
    // skipped in a std HashSet's order, seeded per process, so the same block meshed twice could
    // differ.) Crossing constraint edges (a degenerate block ring) are reported, not a panic.
    let mut cdt = ConstrainedDelaunayTriangulation::<Point2<f64>>::new();
    let mut handles = Vec::with_capacity(vertices.len());
    for v in vertices {
        let handle = cdt
            .insert(v)
            .map_err(|e| MeshError::Triangulation(format!("{e:?}")))?;
        handles.push(handle);
    }
    for [a, b] in edges {
        let (ha, hb) = (handles[a], handles[b]);
        if ha == hb || !cdt.try_add_constraint(ha, hb).is_empty() {
            continue;
        }
        let position = |h| {
            let p = cdt.vertex(h).position();
            [p.x, p.y]
        };
        let (pa, pb) = (position(ha), position(hb));
        return Err(MeshError::Crossing {
            message: format!(
                "block boundary crosses itself between ({:.4}, {:.4}) and ({:.4}, {:.4}) m; joints \
                 too close to each other or to a wall",
                pa[0], pa[1], pb[0], pb[1]
            ),
            kinds: kinds_near(block, pa, pb),
        });
    }
    let result = cdt.refine(params);
    if let (false, Some(budget)) = (result.refinement_complete, budget) {
        return Err(MeshError::Refinement(format!(
            "refinement did not complete within {budget} added vertices; coarsen the zoning or lower the minimum angle"
        )));
    }
    let excluded: Set<_> = result.excluded_faces.iter().copied().collect();
    let in_block = |p: Point| block.outer.contains(p) && !block.holes.iter().any(|h| h.contains(p));
    let mut tris: Vec<[usize; 3]> = cdt
        .inner_faces()
        .filter(|f| {
            if by_centroid {
                let c = f.center();
                in_block([c.x, c.y])
            } else {
                !excluded.contains(&f.fix())
            }
        })
        .map(|f| f.vertices().map(|v| v.fix().index()))
        .collect();
    let pos: Vec<Point> = cdt
        .vertices()
        .map(|v| [v.position().x, v.position().y])
        .collect();
    sort_by_morton(&mut tris, &pos);
    let (mut points, mut triangles) = renumber(&tris, &pos);
    let mut boundary = label_boundary(block, &points, &triangles)?;
    split_pinches(&mut points, &mut triangles, &mut boundary);
    Ok(TriMesh {
        points,
        triangles,
        boundary,
        angle_limit_deg: 0.0,
    })
}

/// Points on rings around each excavation, at the graded spacing, up to where h reaches h_far or
/// the rings leave the block's bounding box;
/// only those inside `block` and at least 0.6 h from its boundary, each ring's points only on the
/// side of its own excavation (nearer to it than to any other).
fn graded_rings(block: &Block, excavations: &[Polygon], z: &Zoning) -> Vec<Point> {
    let (lo, hi) = block.outer.bounds();
    let reach = distance(lo, hi);
    let rings: Vec<&Polygon> = std::iter::once(&block.outer).chain(&block.holes).collect();
    // Each ring's centre and radius (every vertex within it of the centre): a point farther
    // than d + radius from the centre is at least d from the ring, and outside a hole, so the
    // exact distances and containments below are taken only where that bound cannot decide.
    let circle = |q: &Polygon| {
        let c = q.centroid();
        (
            c,
            q.vertices
                .iter()
                .map(|&v| distance(v, c))
                .fold(0.0, f64::max),
        )
    };
    let ring_circles: Vec<(Point, f64)> = rings.iter().map(|q| circle(q)).collect();
    let mut out = Vec::new();
    let mut distances = vec![0.0; excavations.len()];
    for (j, hole) in excavations.iter().enumerate() {
        let (c, r0) = circle(hole);
        let mut d = 0.0;
        let mut ring = 0;
        loop {
            let h = z.size_at(d);
            d += h;
            if h >= z.h_far || d > reach + distance(c, lo).max(distance(c, hi)) {
                break;
            }
            ring += 1;
            let r = r0 + d;
            let hr = z.size_at(d);
            let m = ((std::f64::consts::TAU * r / hr).ceil() as usize).max(6);
            let shift = if ring % 2 == 1 { 0.5 } else { 0.0 };
            for k in 0..m {
                let t = std::f64::consts::TAU * (k as f64 + shift) / m as f64;
                let p = [c[0] + r * t.cos(), c[1] + r * t.sin()];
                if p[0] < lo[0] || p[0] > hi[0] || p[1] < lo[1] || p[1] > hi[1] {
                    continue;
                }
                let in_hole = (block.holes.iter().zip(&ring_circles[1..]))
                    .any(|(h, (hc, hr))| distance(p, *hc) <= *hr && h.contains(p));
                if !block.outer.contains(p) || in_hole {
                    continue;
                }
                for (dist, h) in distances.iter_mut().zip(excavations) {
                    *dist = h.boundary_distance(p);
                }
                // `target_size`, from the distances just taken.
                let nearest = distances.iter().copied().fold(f64::INFINITY, f64::min);
                let hp = if nearest.is_finite() {
                    z.size_at(nearest)
                } else {
                    z.h_far
                };
                let own = distances[j];
                let nearest_other = (distances.iter().enumerate())
                    .filter(|&(i, _)| i != j)
                    .map(|(_, &v)| v)
                    .fold(f64::INFINITY, f64::min);
                let near_ring = (rings.iter().zip(&ring_circles)).any(|(q, (qc, qr))| {
                    distance(p, *qc) - qr < 0.6 * hp && q.boundary_distance(p) < 0.6 * hp
                });
                if nearest_other < own || near_ring {
                    continue;
                }
                out.push(p);
            }
        }
    }
    out
}

/// Order triangles along a Morton (Z-order) curve of their centroids, for memory locality.
fn sort_by_morton(tris: &mut [[usize; 3]], pos: &[Point]) {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in pos {
        for d in 0..2 {
            lo[d] = lo[d].min(p[d]);
            hi[d] = hi[d].max(p[d]);
        }
    }
    let span = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(f64::MIN_POSITIVE);
    let key = |t: &[usize; 3]| {
        let mut code = 0u64;
        let q = |d: usize| {
            let c = (pos[t[0]][d] + pos[t[1]][d] + pos[t[2]][d]) / 3.0;
            (((c - lo[d]) / span) * 65535.0) as u64
        };
        let (x, y) = (q(0), q(1));
        for b in 0..16 {
            code |= ((x >> b) & 1) << (2 * b) | ((y >> b) & 1) << (2 * b + 1);
        }
        code
    };
    tris.sort_by_cached_key(key);
}

/// Keep only used vertices, numbered in order of first use.
fn renumber(tris: &[[usize; 3]], pos: &[Point]) -> (Vec<Point>, Vec<[u32; 3]>) {
    let mut map = vec![u32::MAX; pos.len()];
    let mut points = Vec::new();
    let triangles = tris
        .iter()
        .map(|t| {
            t.map(|v| {
                if map[v] == u32::MAX {
                    map[v] = points.len() as u32;
                    points.push(pos[v]);
                }
                map[v]
            })
        })
        .collect();
    (points, triangles)
}

/// Find the mesh edges used by one triangle only and label each with the kind of the block edge
/// it lies on.
fn label_boundary(
    block: &Block,
    points: &[Point],
    triangles: &[[u32; 3]],
) -> Result<Vec<BoundaryEdge>, MeshError> {
    let mut count: Map<(u32, u32), (u32, [u32; 2])> = Map::default();
    for t in triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            count.entry((a.min(b), a.max(b))).or_insert((0, [a, b])).0 += 1;
        }
    }
    let tol = 1e-9 * block.outer.size();
    // On the ring edge pq: its middle on the edge and both ends on its line. An edge of the
    // triangulation may span two ring edges in line: a ring vertex a round-off outside the line of
    // its neighbours is left to an outer sliver (an unzoned block's ring, where a joint's trace
    // ended on another's, 1e-15 m off the chord of its two edges, failed the block's zoning).
    let on = |a: Point, b: Point, p: Point, q: Point| {
        let middle = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
        let line = |r: Point| orient(p, q, r).abs() <= tol * distance(p, q);
        segment_distance(middle, p, q) <= tol && line(a) && line(b)
    };
    // The block's ring edges in ring order, found through a grid by each boundary edge's middle.
    let ring_edges = ring_segments(block.rings());
    let grid = SegmentGrid::new(&ring_edges, tol);
    let mut edges: Vec<BoundaryEdge> = Vec::new();
    for &(n, nodes) in count.values() {
        if n != 1 {
            continue;
        }
        let (a, b) = (points[nodes[0] as usize], points[nodes[1] as usize]);
        let middle = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
        let kind = grid.at(middle).iter().find_map(|&e| {
            let e = &ring_edges[e as usize];
            on(a, b, e.a, e.b).then_some(e.kind)
        });
        let Some(kind) = kind else {
            return Err(MeshError::Triangulation(format!(
                "boundary edge ({}, {})–({}, {}) lies on no block edge",
                a[0], a[1], b[0], b[1]
            )));
        };
        edges.push(BoundaryEdge { nodes, kind });
    }
    edges.sort_by_key(|e| e.nodes);
    Ok(edges)
}

impl TriMesh {
    /// Quality statistics of the mesh.
    pub fn stats(&self) -> MeshStats {
        let mut min_angle = f64::INFINITY;
        let (mut min_edge, mut max_edge, mut area) = (f64::INFINITY, 0.0f64, 0.0);
        for t in &self.triangles {
            let p = t.map(|v| self.points[v as usize]);
            min_angle = min_angle.min(smallest_angle(p));
            for k in 0..3 {
                let a = distance(p[k], p[(k + 1) % 3]);
                min_edge = min_edge.min(a);
                max_edge = max_edge.max(a);
            }
            area += 0.5 * crate::geometry::orient(p[0], p[1], p[2]);
        }
        MeshStats {
            zones: self.triangles.len(),
            nodes: self.points.len(),
            min_angle_deg: min_angle,
            min_edge,
            max_edge,
            area,
        }
    }

    /// The zone with the smallest angle: that angle (degrees) and the zone's centroid (m).
    pub fn sharpest_zone(&self) -> Option<(f64, Point)> {
        self.triangles
            .iter()
            .map(|t| {
                let p = t.map(|v| self.points[v as usize]);
                let c = [
                    (p[0][0] + p[1][0] + p[2][0]) / 3.0,
                    (p[0][1] + p[1][1] + p[2][1]) / 3.0,
                ];
                (smallest_angle(p), c)
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
    }
}

/// Smallest interior angle of the triangle `p`, degrees, by the law of cosines.
pub fn smallest_angle(p: [Point; 3]) -> f64 {
    let l = [
        distance(p[1], p[2]),
        distance(p[2], p[0]),
        distance(p[0], p[1]),
    ];
    (0..3)
        .map(|k| {
            let (a, b, c) = (l[k], l[(k + 1) % 3], l[(k + 2) % 3]);
            ((b * b + c * c - a * a) / (2.0 * b * c))
                .clamp(-1.0, 1.0)
                .acos()
                .to_degrees()
        })
        .fold(f64::INFINITY, f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::domain::Hole;
    use crate::geometry::Polygon;
    use crate::joints::Segment;
    use approx::assert_relative_eq;

    fn kirsch_domain() -> Domain {
        let outer = Polygon::new(vec![
            [-20.0, -20.0],
            [20.0, -20.0],
            [20.0, 20.0],
            [-20.0, 20.0],
        ]);
        let names = ["bottom", "right", "top", "left"]
            .map(String::from)
            .to_vec();
        let hole = Hole {
            name: "tunnel".into(),
            polygon: Polygon::circle([0.0, 0.0], 1.0, 64),
        };
        Domain::new(outer, names, vec![hole]).unwrap()
    }

    /// A joint piece ending inside a block leaves a hole of no area (a slit a → b → a). Graded from
    /// an excavation, its two faces were split at points a rounding apart, whose constraint edges
    /// overlapped and were refused as crossing (30 of these 40 slits); now it is left out of the
    /// constraints (the piece is absorbed into the block) and the block zones over its whole area.
    #[test]
    fn a_joint_piece_ending_inside_a_block_does_not_stop_its_zoning() {
        let z = Zoning {
            h_excavation: 0.05,
            h_far: 1.0,
            grading: 0.3,
            fine_depth: 0.0,
            plastic_depth: 0.0,
            min_angle_deg: 30.0,
            max_zones: 1_000_000,
        };
        let grading_from = [Polygon::circle([2.0, 5.0], 0.5, 32)];
        for k in 0..40 {
            let t = k as f64 * 0.37;
            let a = [4.0 + t.sin(), 3.0 + (1.3 * t).cos()];
            let b = [6.5 + (0.7 * t).cos(), 6.0 + (0.9 * t).sin()];
            let block = Block {
                outer: Polygon::new(vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]),
                outer_kinds: vec![EdgeKind::Region(0); 4],
                holes: vec![Polygon::new(vec![a, b])],
                hole_kinds: vec![vec![EdgeKind::Joint(0); 2]],
            };
            let mesh = triangulate_block(&block, &grading_from, &z).unwrap();
            assert_relative_eq!(mesh.stats().area, 100.0, max_relative = 1e-9);
            assert_eq!(mesh.angle_limit_deg, 30.0);
        }
    }

    fn zoning() -> Zoning {
        Zoning {
            h_excavation: 0.1,
            h_far: 3.0,
            grading: 0.25,
            fine_depth: 0.0,
            plastic_depth: 0.0,
            min_angle_deg: 28.0,
            max_zones: 1_000_000,
        }
    }

    #[test]
    fn a_panic_in_the_triangulator_is_an_error() {
        let r: Result<(), MeshError> =
            guarded(|| panic!("Failed to locate position. This is a bug in spade."));
        let e = r.unwrap_err().to_string();
        assert!(e.contains("Failed to locate position"), "{e}");
        assert_eq!(guarded(|| Ok(3)).unwrap(), 3);
    }

    #[test]
    fn graded_mesh_covers_domain_with_good_angles() {
        let d = kirsch_domain();
        let mesh = triangulate(&d, &zoning()).unwrap();
        let s = mesh.stats();
        assert_relative_eq!(s.area, d.area(), max_relative = 1e-9);
        assert!(s.min_angle_deg >= 27.0, "min angle {}", s.min_angle_deg);
        assert!(s.min_edge > 0.02 && s.max_edge < 6.0, "{s:?}");
        for t in &mesh.triangles {
            let p = t.map(|v| mesh.points[v as usize]);
            assert!(
                crate::geometry::orient(p[0], p[1], p[2]) > 0.0,
                "triangles are counter-clockwise"
            );
        }
    }

    #[test]
    fn outline_uses_only_the_block_vertices() {
        let d = kirsch_domain();
        let block = Block::from_domain(&d);
        let mesh = triangulate_outline(&block).unwrap();
        let s = mesh.stats();
        assert_eq!(mesh.points.len(), 4 + 64);
        assert_relative_eq!(s.area, d.area(), max_relative = 1e-9);
        assert_eq!(mesh.boundary.len(), 4 + 64);
    }

    #[test]
    fn boundary_edges_are_labelled_and_close() {
        let d = kirsch_domain();
        let mesh = triangulate(&d, &zoning()).unwrap();
        let mut hole_len = 0.0;
        let mut outer_len = [0.0; 4];
        for e in &mesh.boundary {
            let l = distance(
                mesh.points[e.nodes[0] as usize],
                mesh.points[e.nodes[1] as usize],
            );
            match e.kind {
                EdgeKind::Excavation(0) => hole_len += l,
                EdgeKind::Region(i) => outer_len[i as usize] += l,
                other => panic!("unexpected part {other:?}"),
            }
        }
        assert_relative_eq!(
            hole_len,
            64.0 * 2.0 * (std::f64::consts::PI / 64.0).sin(),
            max_relative = 1e-9
        );
        for l in outer_len {
            assert_relative_eq!(l, 40.0, max_relative = 1e-12);
        }
    }

    /// `plastic_depth` halves the graded size out to that depth and grades on from the halved
    /// size beyond it, continuously; 0 leaves the graded size.
    #[test]
    fn plastic_depth_halves_the_graded_size() {
        let graded = Zoning {
            fine_depth: 0.4,
            ..zoning()
        };
        let refined = Zoning {
            plastic_depth: 2.0,
            ..graded
        };
        for d in [0.0, 0.3, 1.0, 1.999] {
            assert_relative_eq!(refined.size_at(d), PLASTIC_SCALE * graded.size_at(d));
        }
        let at = refined.size_at(2.0);
        assert_relative_eq!(
            at,
            PLASTIC_SCALE * graded.size_at(2.0),
            max_relative = 1e-12
        );
        assert_relative_eq!(
            refined.size_at(3.0),
            at + graded.grading,
            max_relative = 1e-12
        );
        assert_eq!(refined.size_at(1e3), graded.h_far);
        let bad = Zoning {
            plastic_depth: f64::NAN,
            ..graded
        };
        assert!(bad.check().is_err());
    }

    /// `fine_depth` keeps the wall's edge length out to that depth, and grading starts there:
    /// the zones within it are as small as the wall's, those beyond as large as `size_at` says.
    #[test]
    fn fine_depth_holds_the_wall_size() {
        let d = kirsch_domain();
        let longest_within = |z: &Zoning, r0: f64, r1: f64| {
            let mesh = triangulate(&d, z).unwrap();
            let mut longest: f64 = 0.0;
            for t in &mesh.triangles {
                let p = t.map(|n| mesh.points[n as usize]);
                let c = [
                    (p[0][0] + p[1][0] + p[2][0]) / 3.0,
                    (p[0][1] + p[1][1] + p[2][1]) / 3.0,
                ];
                let r = c[0].hypot(c[1]);
                if r > r0 && r < r1 {
                    for k in 0..3 {
                        longest = longest.max(distance(p[k], p[(k + 1) % 3]));
                    }
                }
            }
            (longest, mesh.triangles.len())
        };
        let graded = zoning();
        let held = Zoning {
            fine_depth: 1.5,
            ..zoning()
        };
        assert_eq!(held.size_at(1.2), held.h_excavation);
        assert_relative_eq!(held.size_at(2.5), 0.1 + 0.25 * 1.0);
        let (near_graded, n_graded) = longest_within(&graded, 1.0, 2.2);
        let (near_held, n_held) = longest_within(&held, 1.0, 2.2);
        assert!(near_held < 1.6 * held.h_excavation, "{near_held}");
        assert!(near_graded > 2.0 * graded.h_excavation, "{near_graded}");
        assert!(n_held > n_graded, "{n_held} {n_graded}");
        let (far_held, _) = longest_within(&held, 6.0, 8.0);
        let expected = held.size_at(5.0);
        assert!(far_held > 0.8 * expected, "{far_held} {expected}");
        let bad = Zoning {
            fine_depth: -1.0,
            ..zoning()
        };
        assert!(matches!(triangulate(&d, &bad), Err(MeshError::Zoning(_))));
    }

    #[test]
    fn bad_zoning_is_an_error() {
        let d = kirsch_domain();
        let z = Zoning {
            h_far: 0.01,
            ..zoning()
        };
        assert!(matches!(triangulate(&d, &z), Err(MeshError::Zoning(_))));
    }

    /// The sharpest corner of block `b`, degrees: of its rings, and where rings touch (a joint
    /// merged onto a hole's vertex: a joint tangent to the tunnel) the sharpest wedge between any
    /// two of the edges that meet there, a cusp no zoning can beat.
    fn sharpest_corner_deg(b: &Block) -> f64 {
        let rings = || std::iter::once(&b.outer).chain(&b.holes);
        let corners = rings().map(smallest_corner_deg).fold(180.0, f64::min);
        let mut at: Map<Key, Vec<Point>> = Map::default();
        for ring in rings() {
            for i in 0..ring.len() {
                let (a, c) = ring.edge(i);
                at.entry(key(a))
                    .or_default()
                    .push([c[0] - a[0], c[1] - a[1]]);
                at.entry(key(c))
                    .or_default()
                    .push([a[0] - c[0], a[1] - c[1]]);
            }
        }
        let wedges = (at.values().filter(|dirs| dirs.len() > 2))
            .flat_map(|dirs| {
                (0..dirs.len())
                    .flat_map(move |i| (i + 1..dirs.len()).map(move |j| (i, j)))
                    .map(|(i, j)| angle_deg(dirs[i], dirs[j]))
            })
            .fold(180.0, f64::min);
        corners.min(wedges)
    }

    fn smallest_corner_deg(p: &Polygon) -> f64 {
        let n = p.len();
        (0..n)
            .map(|i| {
                let (a, b, c) = (
                    p.vertices[(i + n - 1) % n],
                    p.vertices[i],
                    p.vertices[(i + 1) % n],
                );
                angle_deg([a[0] - b[0], a[1] - b[1]], [c[0] - b[0], c[1] - b[1]])
            })
            .fold(180.0, f64::min)
    }

    /// The angle between directions `u` and `v`, degrees.
    fn angle_deg(u: Point, v: Point) -> f64 {
        let cos = (u[0] * v[0] + u[1] * v[1]) / (u[0].hypot(u[1]) * v[0].hypot(v[1]));
        cos.clamp(-1.0, 1.0).acos().to_degrees()
    }

    /// Zone the blocks `joints` cut `d` into together (`triangulate_blocks`), its excavations
    /// `filled` with rock or not (`cut_blocks_filled`), and check that each block covers its area
    /// with zones no sharper than `cap` (degrees) or `share` of the block's sharpest corner, and
    /// that the
    /// two blocks beside each joint (and each filled excavation's wall) put their nodes at the
    /// same places: every node on one, other than the blocks' own corners, is a node of exactly
    /// two blocks, and each joint trace is a boundary of the blocks on both of its sides. Returns
    /// the count of such nodes.
    fn zoned_alike(
        d: &Domain,
        joints: &[Segment],
        filled: bool,
        (cap, share): (f64, f64),
    ) -> Result<usize, String> {
        // Snapping within 0.3 h keeps joints from cutting slivers off the excavation's segments.
        let tol = 0.3 * zoning().h_excavation;
        let filled_holes = vec![filled; d.holes.len()];
        let blocking = crate::blocks::cut_blocks_filled(d, &filled_holes, joints, tol)
            .map_err(|e| e.to_string())?;
        let excavations: Vec<Polygon> = d.holes.iter().map(|h| h.polygon.clone()).collect();
        let (mut area, mut joint_len) = (0.0, 0.0);
        let zoned = vec![true; blocking.blocks.len()];
        let meshes = triangulate_blocks(&blocking.blocks, &zoned, &excavations, &zoning())
            .map_err(|e| e.to_string())?;
        for (i, (b, mesh)) in blocking.blocks.iter().zip(&meshes).enumerate() {
            let s = mesh.stats();
            if (s.area - b.area()).abs() > 1e-9 * b.area() {
                return Err(format!(
                    "block {i}: zones cover {} m² of {} m²",
                    s.area,
                    b.area()
                ));
            }
            // Refinement cannot beat a sharp corner of the block itself.
            let corner = sharpest_corner_deg(b);
            if s.min_angle_deg < cap.min(share * corner) {
                return Err(format!(
                    "block {i}: a zone of {:.2}° where its sharpest corner is {corner:.2}°",
                    s.min_angle_deg
                ));
            }
            area += s.area;
            joint_len += (mesh.boundary.iter())
                .filter(|e| matches!(e.kind, EdgeKind::Joint(_)))
                .map(|e| e.nodes.map(|n| mesh.points[n as usize]))
                .map(|[p, q]| distance(p, q))
                .sum::<f64>();
        }
        // A filled excavation's rock is zoned too.
        let rock = if filled {
            d.outer.signed_area()
        } else {
            d.area()
        };
        if (area - rock).abs() > 1e-9 * rock {
            return Err(format!("zones cover {area} m² of {rock} m²"));
        }
        let corners: Set<Key> = (blocking.blocks.iter())
            .flat_map(constrained_rings)
            .flat_map(|(ring, _)| ring.vertices.iter().map(|&v| key(v)))
            .collect();
        let shared = |kind: EdgeKind| match kind {
            EdgeKind::Joint(_) => true,
            EdgeKind::Excavation(_) => filled,
            EdgeKind::Region(_) => false,
        };
        let mut on_joints: Map<Key, usize> = Map::default();
        for mesh in &meshes {
            let mut mine: Vec<Key> = (mesh.boundary.iter())
                .filter(|e| shared(e.kind))
                .flat_map(|e| e.nodes.map(|n| key(mesh.points[n as usize])))
                .filter(|k| !corners.contains(k))
                .collect();
            mine.sort_unstable();
            mine.dedup();
            for k in mine {
                *on_joints.entry(k).or_default() += 1;
            }
        }
        let unmatched = on_joints.values().filter(|&&n| n != 2).count();
        if unmatched > 0 {
            return Err(format!(
                "{unmatched} of {} joint nodes unmatched",
                on_joints.len()
            ));
        }
        let traces: f64 = (blocking.blocks.iter())
            .flat_map(|b| ring_segments(constrained_rings(b)))
            .filter(|e| matches!(e.kind, EdgeKind::Joint(_)))
            .map(|e| distance(e.a, e.b))
            .sum();
        if (joint_len - traces).abs() > 1e-9 * traces {
            return Err(format!(
                "zones' joint edges {joint_len} m, blocks' {traces} m"
            ));
        }
        Ok(on_joints.len())
    }

    /// One joint set of the tunnel's box (`kirsch_domain`).
    fn set(dip: f64, spacing: f64, origin: Point, trace: Option<f64>, k: u32) -> Vec<Segment> {
        crate::joints::JointSet {
            dip_deg: dip,
            spacing,
            origin,
            trace,
            gap: 2.0,
            spread_dip_deg: 0.0,
            spread_spacing: 0.0,
            seed: 0,
        }
        .segments([-20.0, -20.0], [20.0, 20.0], EdgeKind::Joint(k))
    }

    /// The blocks of a jointed tunnel zone alike along their joints (`zoned_alike`), with zones
    /// no sharper than 20° or 0.9 of their block's sharpest corner.
    #[test]
    fn the_blocks_of_a_jointed_tunnel_zone_alike_along_their_joints() {
        let mut joints = set(40.0, 3.0, [0.2, 0.1], None, 0);
        joints.extend(set(-50.0, 4.0, [0.2, 0.1], None, 1));
        let nodes = zoned_alike(&kirsch_domain(), &joints, false, (20.0, 0.9)).unwrap();
        assert!(nodes > 100, "{nodes} joint nodes");
    }

    proptest::proptest! {
        // A fixed seed: the same 64 tunnels on every machine (change it to explore others).
        #![proptest_config(proptest::prelude::ProptestConfig {
            cases: 64,
            rng_seed: proptest::test_runner::RngSeed::Fixed(20261125),
            failure_persistence: None,
            ..proptest::prelude::ProptestConfig::default()
        })]
        /// So do those of tunnels cut by two sets at any dips, spacings and origins, persistent
        /// or not, the tunnel excavated or still filled with rock (a staged excavation), with
        /// zones no sharper than a quarter of 20° or of their block's sharpest corner. That floor
        /// is below what the zoning can do: over 400 draws, 150 had a zone under 0.9 of that
        /// angle, 6 under 0.5, the worst 0.45; this test's draws, shrunk from failures, found 0.35
        /// and 0.30 (5.1° at a 17.3° corner, whose first piece on one edge the encroached-piece
        /// rounds had halved twice while the other edge's stayed 4× as long). Zoned each on their
        /// own, as before the blocks were zoned alike, the blocks of 100 of the 400 draws gave 76
        /// under 0.9 and a worst of 0.03.
        #[test]
        fn any_jointed_tunnel_zones_alike_along_its_joints(
            dip1 in -90.0f64..90.0, dip2 in -90.0f64..90.0,
            sp1 in 1.5f64..5.0, sp2 in 1.5f64..5.0,
            ox in -2.0f64..2.0, oy in -2.0f64..2.0,
            trace1 in proptest::option::of(3.0f64..15.0),
            trace2 in proptest::option::of(3.0f64..15.0),
            filled in proptest::bool::ANY,
        ) {
            let mut joints = set(dip1, sp1, [ox, oy], trace1, 0);
            joints.extend(set(dip2, sp2, [oy, ox], trace2, 1));
            let checked = zoned_alike(&kirsch_domain(), &joints, filled, (5.0, 0.25));
            proptest::prop_assert!(checked.is_ok(), "{}", checked.unwrap_err());
        }
    }
}
