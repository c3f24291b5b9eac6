//! Bounds on the work a scene asks for, checked before anything is built: the counts of wall
//! vertices, joint traces, grains, bolt segments and zones are estimated from the scene in floating
//! point (so no count overflows) and refused past a documented limit, naming the field. A scene
//! that passes builds in time and memory proportional to these counts.

use adit_meshing::Polygon;

use super::validate::{Num, SceneError, invalid};
use super::{BlockMode, DEFAULT_MERGE, Excavation, JointSetSpec, Scene};

/// Most vertices of the region polygon (a ground surface traced from a terrain model): its
/// checks, the cutter and the mesher reach its edges through grids and indexes, and 100 000
/// vertices build in about 2 s (`validation/src/scale.rs`).
pub const MAX_REGION_VERTICES: usize = 200_000;

/// Most vertices of an excavation or an inclusion, given or from `segments`: the mesher grades the
/// zones by each point's distance to every excavation edge, and a liner or a fill walks them too.
pub const MAX_POLYGON_VERTICES: usize = 20_000;

/// Most joint traces, over all sets and explicit lines, as estimated over the region's diagonal
/// (about twice what a set draws inside a square region). The cutter pairs them through a grid:
/// the tunnel model with sets 0.12 m apart (about 45 000 traces, 132 000 blocks, 465 000 zones)
/// sets up in about 40 s and 0.9 GB.
pub const MAX_JOINTS: f64 = 100_000.0;

/// Most blocks the joint sets may cut the region into (estimated from their crossings: the
/// sets' traces and their crossings each add about one block). The tunnel with both sets 0.12 m
/// apart (estimated at 264 000, cut into 242 471 blocks and 562 544 zones) is checked in 24 s and
/// 1.2 GB, about 5 kB a block.
pub const MAX_BLOCKS: f64 = 500_000.0;

/// Most Voronoi grains.
pub const MAX_GRAINS: f64 = 1_000_000.0;

/// Most bolts, and most bolt segments over all bolts.
pub const MAX_BOLTS: usize = 10_000;
pub const MAX_BOLT_SEGMENTS: f64 = 1_000_000.0;

/// Area of an equilateral triangle of unit edge, √3/4: the most area a zone of edge h covers.
const ZONE_AREA_PER_EDGE2: f64 = 0.433_012_701_892_219_3;

impl Scene {
    /// Refuse a scene whose size exceeds the limits above or `zoning.max_zones`, before any of it
    /// is allocated.
    pub(super) fn validate_limits(&self) -> Result<(), SceneError> {
        let limit = |p: String, n: usize, most: usize| {
            if n > most {
                Err(invalid(
                    p,
                    format!("{n} vertices exceed the limit of {most} per polygon"),
                ))
            } else {
                Ok(())
            }
        };
        limit(
            "region.polygon".into(),
            self.region.polygon.len(),
            MAX_REGION_VERTICES,
        )?;
        let polygon = |p: String, n: usize| limit(p, n, MAX_POLYGON_VERTICES);
        for (i, e) in self.excavations.iter().enumerate() {
            let p = format!("excavations[{i}]");
            if let Some(c) = &e.circle {
                polygon(format!("{p}.circle.segments"), c.segments)?;
            }
            if let Some(h) = &e.horseshoe {
                polygon(format!("{p}.horseshoe.segments"), h.segments)?;
            }
            if let Some(v) = &e.polygon {
                polygon(format!("{p}.polygon"), v.len())?;
            }
        }
        for (i, inc) in self.inclusions.iter().enumerate() {
            let p = format!("inclusions[{i}]");
            if let Some(c) = &inc.circle {
                polygon(format!("{p}.circle.segments"), c.segments)?;
            }
            if let Some(v) = &inc.polygon {
                polygon(format!("{p}.polygon"), v.len())?;
            }
        }
        let region = Polygon::new(self.region.polygon.clone());
        let (lo, hi) = region.bounds();
        let diagonal = (hi[0] - lo[0]).hypot(hi[1] - lo[1]);
        let mut joints = self.joints.len() as f64;
        if joints > MAX_JOINTS {
            return Err(invalid(
                "joints",
                format!("{joints} joint traces exceed the limit of {MAX_JOINTS}"),
            ));
        }
        for i in 0..self.joint_sets.len() {
            joints += traces_of_set(&self.realized_set(i), diagonal);
            if beyond(joints, MAX_JOINTS) {
                return Err(invalid(
                    format!("joint_sets[{i}]"),
                    format!(
                        "about {:.4e} joint traces in all exceed the limit of {MAX_JOINTS}: \
                         widen `spacing`, lengthen `trace` + `gap` or narrow `spread_spacing`",
                        joints
                    ),
                ));
            }
        }
        self.validate_block_count(&region, joints)?;
        if let Some(v) = &self.voronoi {
            let margin = 4.0 * v.size;
            let grains = (hi[0] - lo[0] + margin) / v.size * ((hi[1] - lo[1] + margin) / v.size);
            if beyond(grains, MAX_GRAINS) {
                return Err(invalid(
                    "voronoi.size",
                    format!(
                        "about {grains:.4e} grains exceed the limit of {MAX_GRAINS}: \
                         make the grains larger"
                    ),
                ));
            }
        }
        self.validate_bolt_counts(diagonal)?;
        let zones = self.zone_estimate(&region);
        let max = self.zoning.max_zones;
        if beyond(zones, max as f64) {
            return Err(invalid(
                "zoning.max_zones",
                format!(
                    "the zoning asks for at least {zones:.4e} zones, more than the limit of {max}: \
                     coarsen `zoning.edge_at_excavation` or `zoning.edge_far`, or raise \
                     `zoning.max_zones`"
                ),
            ));
        }
        if let Some((i, strips)) = self.strip_zone_estimate(&region)
            && beyond(strips, max as f64)
        {
            return Err(invalid(
                format!("joint_sets[{i}].spacing"),
                format!(
                    "the blocks between this set's joints need at least {strips:.4e} zones \
                     (strips {} m wide, zoned across at that width or zoning.edge_at_excavation / \
                     4), more than zoning.max_zones ({max}): widen `spacing`, or take thin blocks \
                     out of the zoning with `blocks.thin`: `rigid`",
                    Num(self.realized_set(i).spacing)
                ),
            ));
        }
        Ok(())
    }

    /// Refuse joints that would cut the region into more than [`MAX_BLOCKS`] blocks (estimated
    /// from the traces and their [`crossings`]), naming the set that passes the limit,
    /// before the cutter allocates them.
    fn validate_block_count(&self, region: &Polygon, traces: f64) -> Result<(), SceneError> {
        let area = region.signed_area().abs();
        let sets: Vec<JointSetSpec> = (0..self.joint_sets.len())
            .map(|i| self.realized_set(i))
            .collect();
        let mut blocks = 1.0 + traces;
        for j in 0..sets.len() {
            blocks += (0..j)
                .map(|i| crossings(&sets[i], &sets[j], area))
                .sum::<f64>();
            if beyond(blocks, MAX_BLOCKS) {
                return Err(invalid(
                    format!("joint_sets[{j}]"),
                    format!(
                        "the joint sets cut the region into about {blocks:.4e} blocks, more than \
                         the limit of {MAX_BLOCKS}: widen the sets' `spacing` or shorten their \
                         `trace`"
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The zones the strips between one set's joints force, where they are narrower than the
    /// coarsest zone asked for and are zoned (deformable; `blocks.thin` for those under half
    /// `zoning.edge_at_excavation`): each strip of width s is zoned across with edges
    /// e = max(s, h0/4) along it (`adit_meshing::spacing`), two zones per e of its length, so the
    /// region's area A takes about p² A / (s e / 2) zones, p = trace / (trace + gap) the set's
    /// persistence (p² the share of the area between two overlapping traces); half of that, a
    /// lower bound on the bundled tunnel's sets (0.2 m apart: 102 400 of its 213 528 zones;
    /// 0.12 m: 284 444 of 562 544). The largest over the sets, with the set.
    fn strip_zone_estimate(&self, region: &Polygon) -> Option<(usize, f64)> {
        if self.blocks.mode != BlockMode::Deformable {
            return None;
        }
        let h0 = self.zoning.edge_at_excavation;
        let area = region.signed_area().abs();
        (0..self.joint_sets.len())
            .filter_map(|i| {
                let set = self.realized_set(i);
                let s = set.spacing;
                let zoned = s >= 0.5 * h0 || self.blocks.thin == BlockMode::Deformable;
                // A set closer than the merge tolerance is the cutter's to refuse, at once.
                let cut = s >= self.zoning.merge_tolerance.unwrap_or(DEFAULT_MERGE * h0);
                (zoned && cut && s < self.zoning.edge_far.min(region.size())).then(|| {
                    let p = persistence(&set);
                    (i, 0.5 * p * p * area / (0.5 * s * s.max(0.25 * h0)))
                })
            })
            .max_by(|a, b| a.1.total_cmp(&b.1))
    }

    fn validate_bolt_counts(&self, diagonal: f64) -> Result<(), SceneError> {
        let mut segments = 0.0;
        let mut bolts = 0usize;
        for (i, b) in self.bolts.iter().enumerate() {
            let p = format!("bolts[{i}]");
            let segment = b.segment.unwrap_or(self.zoning.edge_at_excavation);
            let (count, length, field) = match (&b.line, &b.pattern) {
                (Some(l), _) => (1, (l.to[0] - l.from[0]).hypot(l.to[1] - l.from[1]), "line"),
                (None, Some(pat)) => (pat.count, pat.length, "pattern.length"),
                (None, None) => (0, 0.0, "line"),
            };
            bolts = bolts.saturating_add(count);
            if bolts > MAX_BOLTS {
                return Err(invalid(
                    format!("{p}.pattern.count"),
                    format!("{bolts} bolts in all exceed the limit of {MAX_BOLTS}"),
                ));
            }
            if beyond(length, diagonal) {
                return Err(invalid(
                    format!("{p}.{field}"),
                    format!(
                        "a bolt of {length:.4e} m is longer than the region's diagonal \
                         ({diagonal:.4e} m)"
                    ),
                ));
            }
            segments += count as f64 * (length / segment).ceil().max(1.0);
            if beyond(segments, MAX_BOLT_SEGMENTS) {
                return Err(invalid(
                    format!("{p}.segment"),
                    format!(
                        "about {segments:.4e} bolt segments in all exceed the limit of \
                         {MAX_BOLT_SEGMENTS}: lengthen `segment`"
                    ),
                ));
            }
        }
        Ok(())
    }

    /// A lower bound on the zone count of the graded zoning (joints and the plastic zone's
    /// refinement, `zoning.plastic_depth`, only add zones): equilateral
    /// zones of the target edge h over the region at `edge_far`, plus the band graded from each
    /// excavation wall: the band of `fine_depth` D at h0, min(P0 D + π D², A) / h0², then the graded
    /// one, h = h0 + g (d − D) up to h_far, of perimeter P = P0 + 2π d at distance d:
    ///
    ///   N ≈ [A / h_far² + Σ_walls (min(P0 D + π D², A)/h0² + P_D/g (1/h0 − 1/h_far)
    ///        + 2π/g² (ln(h_far/h0) + h0/h_far − 1))] / (√3/4),   P_D = P0 + 2π D.
    /// (No zone edge is longer than the region's box, whatever `edge_far` says.)
    fn zone_estimate(&self, region: &Polygon) -> f64 {
        let z = &self.zoning;
        let (h0, g) = (z.edge_at_excavation, z.grading);
        let h_far = z.edge_far.min(region.size());
        let area = region.signed_area().abs();
        let mut per_area = area / (h_far * h_far);
        let depth = z.fine_depth.min(region.size());
        for e in &self.excavations {
            let p0 = wall_length(e);
            let band = (p0 * depth + std::f64::consts::PI * depth * depth).min(area);
            per_area += band / (h0 * h0);
            let p0 = p0 + std::f64::consts::TAU * depth;
            if h_far > h0 {
                per_area += p0 / g * (1.0 / h0 - 1.0 / h_far)
                    + std::f64::consts::TAU / (g * g) * ((h_far / h0).ln() + h0 / h_far - 1.0);
            } else {
                per_area += p0 / h0;
            }
        }
        per_area / ZONE_AREA_PER_EDGE2
    }
}

/// Perimeter of an excavation, m.
fn wall_length(e: &Excavation) -> f64 {
    match (&e.circle, &e.polygon, &e.horseshoe) {
        (Some(c), _, _) => std::f64::consts::TAU * c.radius,
        (_, Some(v), _) => Polygon::new(v.clone()).perimeter(),
        (_, _, Some(h)) => (std::f64::consts::PI + 2.0) * h.radius + 2.0 * h.wall_height,
        _ => 0.0,
    }
}

/// About how many traces `set` cuts over a region of `diagonal` m (`JointSet::segments` walks
/// the lines across the region's box widened by the spread, and the traces along each).
fn traces_of_set(set: &JointSetSpec, diagonal: f64) -> f64 {
    let margin = set.spread_spacing + diagonal * set.spread_dip.to_radians().sin().abs();
    let lines = (diagonal + 2.0 * margin) / set.spacing + 2.0;
    let per_line = match set.trace {
        Some(t) => diagonal / (t + set.gap) + 2.0,
        None => 1.0,
    };
    lines * per_line
}

/// A set's persistence: the share of each of its lines its traces cover, trace / (trace + gap)
/// (1 for a persistent set).
fn persistence(set: &JointSetSpec) -> f64 {
    set.trace.map_or(1.0, |t| t / (t + set.gap))
}

/// About how many times sets `a` and `b` cross in a region of `area` m²: lines s_a and s_b apart
/// at an angle θ cross once per s_a s_b / |sin θ| of area, each crossing a joint's where both
/// traces are (p_a p_b); a random spread of dip can bring two sets to any angle within it.
fn crossings(a: &JointSetSpec, b: &JointSetSpec, area: f64) -> f64 {
    let spread = (a.spread_dip + b.spread_dip).min(90.0).to_radians().sin();
    let angle = (a.dip - b.dip).to_radians().sin().abs().max(spread);
    area * angle * persistence(a) * persistence(b) / (a.spacing * b.spacing)
}

/// Whether an estimated `count` passes `limit` (a NaN count does: it came from nonsense).
pub(super) fn beyond(count: f64, limit: f64) -> bool {
    count.is_nan() || count > limit
}
