//! Scene geometry to meshes: the domain, the joint traces, the blocks they cut, and each block's
//! zones. Errors name the scene field.

use adit_meshing::{
    Block, Blocking, Domain, EdgeKind, Hole, JointSet, MeshError, MeshStats, Polygon, Segment,
    TriMesh, Zoning, cut_blocks_filled, geometry::distance, triangulate_blocks,
    voronoi::voronoi_segments,
};

use super::plastic_depth::plastic_depth;
use super::repair::{MAX_REPAIRS, drop_piece, joint_beside};
use crate::scene::{BlockMode, DEFAULT_MERGE, Scene, SceneError, Shape};

/// The polygon of an excavation's or an inclusion's shape.
pub fn outline(shape: Shape) -> Polygon {
    match shape {
        Shape::Circle(c) => Polygon::circle(c.center, c.radius, c.segments),
        Shape::Polygon(p) => Polygon::new(p.to_vec()),
        Shape::Horseshoe(h) => Polygon::new(h.polygon()),
    }
}

/// The domain a scene describes: the region with its excavations, then its inclusions, as holes
/// (hole j ≥ the number of excavations is inclusion j − that number). Errors name the scene field.
pub fn domain(scene: &Scene) -> anyhow::Result<Domain> {
    let mut holes = Vec::with_capacity(scene.excavations.len() + scene.inclusions.len());
    for (i, e) in scene.excavations.iter().enumerate() {
        holes.push(Hole {
            name: e.name.clone(),
            polygon: outline(e.shape(&format!("excavations[{i}]"))?),
        });
    }
    for (i, inc) in scene.inclusions.iter().enumerate() {
        holes.push(Hole {
            name: inc.name.clone(),
            polygon: outline(inc.shape(&format!("inclusions[{i}]"))?),
        });
    }
    let outer = Polygon::new(scene.region.polygon.clone());
    Domain::new(outer, scene.edge_names(), holes)
        .map_err(|e| anyhow::anyhow!("{}: {e}", field_of(scene, &e)))
}

/// Joint traces of the scene over the region's bounding box: joint sets first (feature k = set
/// index), then explicit joints (k = number of sets + index), then Voronoi grain boundaries (the
/// last k).
pub fn joint_segments(scene: &Scene, domain: &Domain) -> Result<Vec<Segment>, MeshError> {
    let (lo, hi) = domain.outer.bounds();
    let mut out = Vec::new();
    for k in 0..scene.joint_sets.len() {
        let js = scene.realized_set(k);
        let set = JointSet {
            dip_deg: js.dip,
            spacing: js.spacing,
            origin: js.origin,
            trace: js.trace,
            gap: js.gap,
            spread_dip_deg: js.spread_dip,
            spread_spacing: js.spread_spacing,
            seed: js.seed,
        };
        out.extend(set.segments(lo, hi, EdgeKind::Joint(k as u32)));
    }
    let sets = scene.joint_sets.len();
    for (i, j) in scene.joints.iter().enumerate() {
        out.push(Segment {
            a: j.from,
            b: j.to,
            kind: EdgeKind::Joint((sets + i) as u32),
        });
    }
    if let Some(v) = &scene.voronoi {
        let kind = EdgeKind::Joint((sets + scene.joints.len()) as u32);
        out.extend(voronoi_segments(lo, hi, v.size, v.seed, kind)?);
    }
    Ok(out)
}

/// Zoning controls of a scene, with its plastic depth (estimated for `"auto"`).
pub fn zoning(scene: &Scene) -> Result<Zoning, SceneError> {
    let z = &scene.zoning;
    Ok(Zoning {
        h_excavation: z.edge_at_excavation,
        h_far: z.edge_far,
        grading: z.grading,
        fine_depth: z.fine_depth,
        plastic_depth: plastic_depth(scene)?,
        min_angle_deg: z.min_angle,
        max_zones: z.max_zones,
    })
}

/// A scene's geometry, cut into blocks and zoned.
pub struct Meshed {
    pub domain: Domain,
    pub blocking: Blocking,
    /// One mesh per block, in block order (the outline only for rigid and simple blocks).
    pub(crate) meshes: Vec<TriMesh>,
    /// Mode of each block.
    pub modes: Vec<BlockMode>,
    /// For each block, the staged excavation whose rock it is (index into the excavations), or
    /// `NOT_FILL` for the rock that stays.
    pub fill: Vec<u32>,
    /// For each block, the inclusion it lies in (index into the inclusions), or `NOT_FILL`.
    pub inclusion: Vec<u32>,
    /// The joint pieces dropped to keep zones above `zoning.accept_angle`, in words (warnings).
    pub repairs: Vec<String>,
    /// The blocks too thin to zone at the finest size asked for (`Thin`), whatever their mode now.
    pub(crate) thin: Vec<Thin>,
    /// Rock outside a filled hole's profile that fills it (warnings).
    pub(crate) fill_outside: Vec<FillOutside>,
    /// The joint sets none of whose traces reaches the region (warnings).
    pub(crate) sets_outside: Vec<usize>,
    /// The distance within which the cutter merged vertices, m.
    pub merge_tolerance: f64,
}

/// A deformable block thinner than half `zoning.edge_at_excavation`, the finest zone the scene
/// asks for: its zones must be finer still, and the time step falls with them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Thin {
    pub block: usize,
    /// Its thickness 2 A / P (area over half the perimeter; the width of a long strip), m.
    pub thickness: f64,
}

/// Thickness of `b` as a strip: 2 A / P, m.
fn thickness(b: &Block) -> f64 {
    let perimeter = b.outer.perimeter() + b.holes.iter().map(Polygon::perimeter).sum::<f64>();
    2.0 * b.area() / perimeter
}

/// The deformable blocks (by `modes`) thinner than half the finest zone size; each takes
/// `blocks.thin` as its mode.
fn thin_blocks(
    scene: &Scene,
    blocks: &[Block],
    zoning: &Zoning,
    modes: &mut [BlockMode],
) -> Vec<Thin> {
    let mut thin = Vec::new();
    for (block, b) in blocks.iter().enumerate() {
        let thickness = thickness(b);
        if modes[block] == BlockMode::Deformable && thickness < 0.5 * zoning.h_excavation {
            thin.push(Thin { block, thickness });
            modes[block] = scene.blocks.thin;
        }
    }
    thin
}

impl Meshed {
    /// The sharpest zone of the deformable blocks: its smallest angle (degrees), where (m), and its
    /// block.
    pub fn sharpest_zone(&self) -> Option<(f64, [f64; 2], usize)> {
        self.meshes
            .iter()
            .enumerate()
            .filter(|(b, _)| self.modes[*b] == BlockMode::Deformable)
            .filter_map(|(b, m)| m.sharpest_zone().map(|(angle, at)| (angle, at, b)))
            .min_by(|x, y| x.0.total_cmp(&y.0))
    }
}

impl Meshed {
    /// Why the sharpest zone is sharper than `min_angle` (degrees), for `adit check` and the run's
    /// console: the corner of its block's boundary nearest to it, when that corner is itself
    /// sharper (refinement cannot make a zone's angle exceed the corner it sits in), else that
    /// refinement stopped there. Empty when no zone is sharper than `min_angle`.
    pub fn min_angle_note(&self, min_angle: f64) -> String {
        let Some((angle, at, b)) = self.sharpest_zone() else {
            return String::new();
        };
        if !sharper_than(angle, min_angle) {
            return String::new();
        }
        let corner = self.blocking.blocks[b]
            .rings()
            .flat_map(|(ring, _)| {
                let v = &ring.vertices;
                (0..v.len()).map(move |i| {
                    (
                        v[i],
                        corner_angle(v[(i + v.len() - 1) % v.len()], v[i], v[(i + 1) % v.len()]),
                    )
                })
            })
            .min_by(|(p, _), (q, _)| dist(*p, at).total_cmp(&dist(*q, at)));
        match corner {
            Some((p, c)) if c < min_angle => format!(
                " (block {b}'s boundary meets at {c:.1}° at ({:.3}, {:.3}) m, where joints or \
                 walls cross: zoning.min_angle = {min_angle}° holds everywhere but in such corners)",
                p[0], p[1]
            ),
            _ => format!(
                " (in block {b} near ({:.3}, {:.3}) m: refinement to zoning.min_angle = \
                 {min_angle}° stopped there, where its constraints lie close together)",
                at[0], at[1]
            ),
        }
    }
}

/// Whether a zone angle `angle` (degrees, as reported to 0.1°) falls short of `min_angle`.
pub fn sharper_than(angle: f64, min_angle: f64) -> bool {
    angle < min_angle - 0.05
}

/// The angle at `v` between the edges to `a` and `b`, degrees (0 to 180).
fn corner_angle(a: [f64; 2], v: [f64; 2], b: [f64; 2]) -> f64 {
    let (p, q) = ([a[0] - v[0], a[1] - v[1]], [b[0] - v[0], b[1] - v[1]]);
    (p[0] * q[1] - p[1] * q[0])
        .abs()
        .atan2(p[0] * q[0] + p[1] * q[1])
        .to_degrees()
}

fn dist(p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

/// Marks a block that is no excavation's fill.
pub const NOT_FILL: u32 = u32::MAX;

impl Meshed {
    /// Mesh statistics over the zones of the deformable blocks (rigid and simple blocks have none).
    pub fn stats(&self) -> MeshStats {
        let all: Vec<MeshStats> = self
            .meshes
            .iter()
            .zip(&self.modes)
            .filter(|(_, m)| **m == BlockMode::Deformable)
            .map(|(mesh, _)| mesh.stats())
            .collect();
        MeshStats {
            zones: all.iter().map(|s| s.zones).sum(),
            nodes: all.iter().map(|s| s.nodes).sum(),
            min_angle_deg: finite_or_zero(
                all.iter()
                    .map(|s| s.min_angle_deg)
                    .fold(f64::INFINITY, f64::min),
            ),
            min_edge: finite_or_zero(all.iter().map(|s| s.min_edge).fold(f64::INFINITY, f64::min)),
            max_edge: all.iter().map(|s| s.max_edge).fold(0.0, f64::max),
            area: all.iter().map(|s| s.area).sum(),
        }
    }
}

/// 0 for the empty minimum (no deformable block).
fn finite_or_zero(v: f64) -> f64 {
    if v.is_finite() { v } else { 0.0 }
}

/// The scene field a meshing error is about: `region.polygon` or `excavations[i]`.
fn field_of(scene: &Scene, err: &MeshError) -> String {
    let shape = match err {
        MeshError::Degenerate { shape, .. }
        | MeshError::SelfIntersecting { shape, .. }
        | MeshError::HoleOutside { shape, .. } => shape.as_str(),
        MeshError::HolesOverlap { a, .. } => a.as_str(),
        MeshError::Zoning(_) | MeshError::Triangulation(_) | MeshError::Refinement(_) => {
            return "zoning".into();
        }
        MeshError::TooManyZones { .. } => return "zoning.max_zones".into(),
        MeshError::JointsTooClose { set, .. } => return format!("joint_sets[{set}].spacing"),
        // Under the first joint that made the crossing, else the zoning.
        MeshError::Crossing { kinds, .. } => {
            return kinds
                .iter()
                .find(|k| matches!(k, EdgeKind::Joint(_)))
                .map_or("zoning".into(), |&k| edge_source(scene, k));
        }
    };
    if let Some(i) = scene.excavations.iter().position(|e| e.name == shape) {
        return format!("excavations[{i}]");
    }
    match scene.inclusions.iter().position(|e| e.name == shape) {
        Some(i) => format!("inclusions[{i}]"),
        None => "region.polygon".into(),
    }
}

/// The scene field a block edge of `kind` comes from: a region edge, an excavation wall, a joint
/// set, an explicit joint or the Voronoi grains.
pub(super) fn edge_source(scene: &Scene, kind: EdgeKind) -> String {
    let sets = scene.joint_sets.len();
    match kind {
        EdgeKind::Region(i) => format!("region.polygon edge {i}"),
        EdgeKind::Excavation(j) => format!("excavations[{j}]"),
        EdgeKind::Joint(k) if (k as usize) < sets => format!("joint_sets[{k}]"),
        EdgeKind::Joint(k) if (k as usize) < sets + scene.joints.len() => {
            format!("joints[{}]", k as usize - sets)
        }
        EdgeKind::Joint(_) => "voronoi".into(),
    }
}

/// Cut the scene's region into blocks and zone each; errors name the scene field (and, for a block
/// boundary that crosses itself, the joints, walls or region edges there).
pub fn mesh(scene: &Scene) -> anyhow::Result<Meshed> {
    let domain = domain(scene)?;
    let zoning = zoning(scene)?;
    mesh_blocks(scene, domain, &zoning).map_err(|e| {
        let field = field_of(scene, &e);
        match &e {
            MeshError::Crossing { kinds, .. } if !kinds.is_empty() => {
                let edges: Vec<String> = kinds.iter().map(|&k| edge_source(scene, k)).collect();
                anyhow::anyhow!("{field}: {e} (edges there: {})", edges.join(", "))
            }
            _ => anyhow::anyhow!("{field}: {e}"),
        }
    })
}

/// Cut and zone, dropping the piece of a joint that leaves a zone under `zoning.accept_angle`
/// (`repair`) and cutting again, at most `MAX_REPAIRS` times; each repair is in `Meshed::repairs`.
fn mesh_blocks(scene: &Scene, domain: Domain, zoning: &Zoning) -> Result<Meshed, MeshError> {
    let tolerance = merge_tolerance(scene, &domain);
    for set in 0..scene.joint_sets.len() {
        let spacing = scene.realized_set(set).spacing;
        if spacing < tolerance {
            return Err(MeshError::JointsTooClose {
                set,
                spacing,
                tolerance,
            });
        }
    }
    let mut joints = joint_segments(scene, &domain)?;
    let sets_outside = sets_outside(scene, &domain, &joints);
    let mut repairs = Vec::new();
    loop {
        let mut meshed = cut_and_zone(scene, domain.clone(), &joints, tolerance, zoning)?;
        let accept = scene.zoning.accept_angle;
        let needle = meshed
            .sharpest_zone()
            .filter(|&(angle, _, _)| angle < accept);
        let repairable = needle.and_then(|(angle, at, b)| {
            (repairs.len() < MAX_REPAIRS)
                .then(|| joint_beside(&meshed.blocking.blocks[b], &joints, at))
                .flatten()
                .map(|i| (i, angle, at))
        });
        let Some((i, angle, at)) = repairable else {
            meshed.repairs = repairs;
            meshed.sets_outside = sets_outside;
            return Ok(meshed);
        };
        let field = edge_source(scene, joints[i].kind);
        let [a, b] = drop_piece(&mut joints, i, at, &domain);
        repairs.push(format!(
            "{field}: dropped the piece from ({:.3}, {:.3}) to ({:.3}, {:.3}) m ({:.3} m), which \
             left a zone of {angle:.2}° near ({:.3}, {:.3}) m, below zoning.accept_angle = {accept}°",
            a[0],
            a[1],
            b[0],
            b[1],
            distance(a, b),
            at[0],
            at[1]
        ));
    }
}

/// The joint sets none of whose traces `joints` reaches the region (a set the region's box
/// holds but a region of another shape misses, or sparse traces drawn around it).
fn sets_outside(scene: &Scene, domain: &Domain, joints: &[Segment]) -> Vec<usize> {
    let mut reaches = vec![false; scene.joint_sets.len()];
    for s in joints {
        if let EdgeKind::Joint(k) = s.kind
            && let Some(r) = reaches.get_mut(k as usize)
            && !*r
        {
            *r = domain.outer.meets_segment(s.a, s.b);
        }
    }
    (0..reaches.len()).filter(|&k| !reaches[k]).collect()
}

/// The distance, m, within which the cutter merges vertices: `zoning.merge_tolerance`, by default
/// `DEFAULT_MERGE` × `edge_at_excavation`, within the bounds below. Vertices closer than 0.3 of the
/// finest zone merge, so joints cut no sliver edges; with
/// Voronoi grains, never more than 2 % of the grain size, whose many short edges would
/// otherwise collapse; and below the shortest edge of the region and the walls, whose
/// vertices never move (`cut_blocks_filled`) and so must not merge into each other: a hole of
/// 47 segments of 0.067 m (below 0.075 m) cut by a joint through a vertex lost a sliver of
/// 0.0034 m² to each block beside it.
fn merge_tolerance(scene: &Scene, domain: &Domain) -> f64 {
    let grain = scene.voronoi.as_ref().map_or(f64::INFINITY, |v| v.size);
    let fixed_edge = std::iter::once(&domain.outer)
        .chain(domain.holes.iter().map(|h| &h.polygon))
        .flat_map(|p| (0..p.len()).map(|i| p.edge(i)))
        .map(|(a, b)| distance(a, b))
        .fold(f64::INFINITY, f64::min);
    let asked = scene
        .zoning
        .merge_tolerance
        .unwrap_or(DEFAULT_MERGE * scene.zoning.edge_at_excavation);
    asked.min(0.02 * grain).min(0.9 * fixed_edge)
}

/// Cut `domain` by `joints` into blocks, merging vertices within `tol` (m), and zone each.
fn cut_and_zone(
    scene: &Scene,
    domain: Domain,
    joints: &[Segment],
    tol: f64,
    zoning: &Zoning,
) -> Result<Meshed, MeshError> {
    let filled: Vec<bool> = scene
        .excavations
        .iter()
        .map(|e| scene.is_staged(&e.name))
        .chain(scene.inclusions.iter().map(|_| true))
        .collect();
    let blocking = if joints.is_empty() && !filled.contains(&true) {
        Blocking {
            blocks: vec![Block::from_domain(&domain)],
            absorbed_joint_length: 0.0,
            slivers: vec![],
            merges: Default::default(),
            onto_walls: Vec::new(),
        }
    } else {
        cut_blocks_filled(&domain, &filled, joints, tol)?
    };
    let excavations: Vec<Polygon> = domain.holes.iter().map(|h| h.polygon.clone()).collect();
    let mut modes = block_modes(scene, &blocking.blocks);
    let thin = thin_blocks(scene, &blocking.blocks, zoning, &mut modes);
    // Two zoned blocks put their nodes at the same places along the joint between them.
    let zoned: Vec<bool> = modes.iter().map(|&m| m == BlockMode::Deformable).collect();
    let meshes = triangulate_blocks(&blocking.blocks, &zoned, &excavations, zoning)?;
    let (hole, fill_outside) = holes_filled(&blocking.blocks, &meshes, &excavations, &filled);
    let excavations = scene.excavations.len() as u32;
    let fill = hole
        .iter()
        .map(|&j| if j < excavations { j } else { NOT_FILL })
        .collect();
    let inclusion = hole
        .iter()
        .map(|&j| {
            if j == NOT_FILL || j < excavations {
                NOT_FILL
            } else {
                j - excavations
            }
        })
        .collect();
    Ok(Meshed {
        domain,
        blocking,
        meshes,
        modes,
        fill,
        inclusion,
        repairs: vec![],
        thin,
        fill_outside,
        sets_outside: Vec::new(),
        merge_tolerance: tol,
    })
}

/// Rock outside a filled hole's profile that fills it all the same (a block mostly inside).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FillOutside {
    /// The hole (excavation, then inclusion, in the domain's order).
    pub hole: u32,
    /// Area of the blocks' zones outside the profile, m².
    pub area: f64,
    /// The centroid of the largest such zone, m.
    pub at: [f64; 2],
}

/// The hole each block fills (`NOT_FILL` for rock) among the `filled` ones of `holes`: the one
/// holding more than half of its area, measured over the triangles of its zoning (or outline) by
/// where their centroids lie. A block lies wholly inside a hole or outside it but for the
/// vertices the cutter merged within its tolerance, so the measure tells even a sliver of rock
/// along the wall (all its vertices within the tolerance of it) from the fill; with it, the rock
/// outside each profile that fills it all the same.
fn holes_filled(
    blocks: &[Block],
    meshes: &[TriMesh],
    holes: &[Polygon],
    filled: &[bool],
) -> (Vec<u32>, Vec<FillOutside>) {
    let bounds: Vec<_> = holes.iter().map(Polygon::bounds).collect();
    let mut outside: Vec<FillOutside> = Vec::new();
    let hole = (blocks.iter().zip(meshes))
        .map(|(b, mesh)| {
            let (lo, hi) = b.outer.bounds();
            let candidates = (0..holes.len()).filter(|&j| {
                let (hlo, hhi) = bounds[j];
                filled[j] && (0..2).all(|d| lo[d] <= hhi[d] && hlo[d] <= hi[d])
            });
            for j in candidates {
                let (mut inside, mut out, mut largest) = (0.0, 0.0, (0.0, [0.0; 2]));
                for t in &mesh.triangles {
                    let [a, b, c] = t.map(|v| mesh.points[v as usize]);
                    let area =
                        0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
                    let centroid = [(a[0] + b[0] + c[0]) / 3.0, (a[1] + b[1] + c[1]) / 3.0];
                    let (hlo, hhi) = bounds[j];
                    let in_box = (0..2).all(|d| hlo[d] <= centroid[d] && centroid[d] <= hhi[d]);
                    if in_box && holes[j].contains(centroid) {
                        inside += area;
                    } else {
                        out += area;
                        if area > largest.0 {
                            largest = (area, centroid);
                        }
                    }
                }
                if inside > out {
                    if out > 0.0 {
                        outside.push(FillOutside {
                            hole: j as u32,
                            area: out,
                            at: largest.1,
                        });
                    }
                    return j as u32;
                }
            }
            NOT_FILL
        })
        .collect();
    (hole, outside)
}

/// Whether a region selects block `b`: a polygon the blocks whose centroid lies inside it, a
/// point the block containing it.
pub fn selects(b: &Block, polygon: &Option<Vec<[f64; 2]>>, at: Option<[f64; 2]>) -> bool {
    match (polygon, at) {
        (Some(poly), _) => Polygon::new(poly.clone()).contains(b.outer.centroid()),
        (None, Some(p)) => b.outer.contains(p) && !b.holes.iter().any(|h| h.contains(p)),
        (None, None) => false,
    }
}

/// Mode of each block: the scene's `blocks.mode`, overridden by the regions in order.
pub fn block_modes(scene: &Scene, blocks: &[Block]) -> Vec<BlockMode> {
    blocks
        .iter()
        .map(|b| {
            scene
                .blocks
                .regions
                .iter()
                .rev()
                .find(|r| selects(b, &r.polygon, r.at))
                .map_or(scene.blocks.mode, |r| r.mode)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A block of the square `lo`..`hi` (m), meshed as its two triangles.
    fn square(lo: [f64; 2], hi: [f64; 2]) -> (Block, TriMesh) {
        let corners = vec![lo, [hi[0], lo[1]], hi, [lo[0], hi[1]]];
        let block = Block {
            outer: Polygon::new(corners.clone()),
            outer_kinds: vec![EdgeKind::Region(0); 4],
            holes: vec![],
            hole_kinds: vec![],
        };
        let mesh = TriMesh {
            points: corners,
            triangles: vec![[0, 1, 2], [0, 2, 3]],
            boundary: vec![],
            angle_limit_deg: 0.0,
        };
        (block, mesh)
    }

    /// The block (2, 1)–(4.5, 3) m, 4 m² of it left of x = 4 m and 1 m² right of it, zoned
    /// along that line.
    fn straddling() -> (Block, TriMesh) {
        let (block, _) = square([2.0, 1.0], [4.5, 3.0]);
        let mesh = TriMesh {
            points: vec![
                [2.0, 1.0],
                [4.0, 1.0],
                [4.5, 1.0],
                [4.5, 3.0],
                [4.0, 3.0],
                [2.0, 3.0],
            ],
            triangles: vec![[0, 1, 4], [0, 4, 5], [1, 2, 3], [1, 3, 4]],
            boundary: vec![],
            angle_limit_deg: 0.0,
        };
        (block, mesh)
    }

    /// A block fills the hole holding most of its area; a sliver outside the wall, however
    /// close, is rock; what of a fill block lies outside is reported.
    #[test]
    fn a_block_fills_the_hole_that_holds_most_of_it() {
        let hole = Polygon::new(vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]);
        let (blocks, meshes): (Vec<Block>, Vec<TriMesh>) = [
            square([1.0, 1.0], [3.0, 3.0]),  // inside
            square([4.0, 1.0], [4.05, 3.0]), // a sliver along the wall, outside
            straddling(),
            square([10.0, 10.0], [11.0, 11.0]), // far away
        ]
        .into_iter()
        .unzip();
        let (fill, outside) = holes_filled(&blocks, &meshes, std::slice::from_ref(&hole), &[true]);
        assert_eq!(fill, vec![0, NOT_FILL, 0, NOT_FILL]);
        assert_eq!(outside.len(), 1);
        assert!((outside[0].area - 1.0).abs() < 1e-12, "{outside:?}");
        // A hole not filled takes nothing.
        let (fill, _) = holes_filled(&blocks, &meshes, &[hole], &[false]);
        assert!(fill.iter().all(|&f| f == NOT_FILL));
    }
}
