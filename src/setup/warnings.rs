//! What setting up a scene found worth saying: sliver and thin blocks, repairs, refinement that
//! did not reach its angle, merged vertices, joints merged into walls, an in-situ
//! stress that does not balance gravity; and the one mesh fault that is an error, a zone sharper
//! than the scene accepts.

use super::geometry::Meshed;
use crate::dynamics::History;
use crate::law::ZoneLaw;
use crate::model::Zones;
use crate::scene::{BlockMode, DEFAULT_DAMPING, Scene, SolveMode};

/// Most thin blocks named one by one in the warnings; the rest are counted.
const THIN_NAMED: usize = 10;

/// A warning for each block too thin to zone at the finest size asked for (the first
/// `THIN_NAMED`, then a count), saying what became of it.
fn thin_warnings(scene: &Scene, meshed: &Meshed) -> Vec<String> {
    let made = match scene.blocks.thin {
        BlockMode::Deformable => {
            "zoned as finely as it needs (its zones may set the time step; blocks.thin: \
             \"simple\" or \"rigid\" takes it out of the zoning)"
        }
        BlockMode::Simple => "made simple (blocks.thin)",
        BlockMode::Rigid => "made rigid (blocks.thin)",
    };
    let mut out: Vec<String> = meshed
        .thin
        .iter()
        .take(THIN_NAMED)
        .map(|t| {
            let c = meshed.blocking.blocks[t.block].outer.centroid();
            format!(
                "block {} (centroid ({:.3}, {:.3}) m) is {:.3e} m thick (2 × area / perimeter), \
                 under half zoning.edge_at_excavation = {} m: {made}",
                t.block, c[0], c[1], t.thickness, scene.zoning.edge_at_excavation
            )
        })
        .collect();
    if meshed.thin.len() > THIN_NAMED {
        out.push(format!(
            "{} more blocks are as thin, and were treated alike",
            meshed.thin.len() - THIN_NAMED
        ));
    }
    out
}

/// The mesh's sharpest zone against `zoning.accept_angle`: an error naming the block and where.
fn refuse_sharp_zones(scene: &Scene, meshed: &Meshed) -> anyhow::Result<()> {
    let sharpest = meshed.sharpest_zone();
    let accept = scene.zoning.accept_angle;
    match sharpest {
        Some((angle, at, b)) if angle < accept => anyhow::bail!(
            "zoning.accept_angle: a zone of block {b} near ({:.3}, {:.3}) m has an angle of \
             {angle:.2}°, below the {accept}° accepted (joints or walls meet at such an angle, or \
             lie closer than the zoning there; it would set a tiny time step): move or coarsen \
             the joints, or lower `zoning.accept_angle` (0 accepts any)",
            at[0],
            at[1]
        ),
        _ => Ok(()),
    }
}

/// Below this a friction angle given in degrees (the scene's unit) is more likely radians: 1.6 rad
/// is 92°, beyond any friction angle.
const RADIANS_LIKELY: f64 = 1.6;

/// What the scene's numbers say of a slip of units or sign, each naming the field: an in-situ
/// stress component tensile over the whole region (adit takes tension positive, as UDEC; RS2 and
/// most reports give compression positive), a friction angle that looks like radians, supports
/// in a scene without stages (in the rock before its excavations are made).
fn input_warnings(scene: &Scene) -> Vec<String> {
    let mut out = Vec::new();
    let supports = scene.bolts.len() + scene.liners.len();
    if scene.stages.is_empty() && supports > 0 && !scene.excavations.is_empty() {
        out.push(format!(
            "stages: none, so the {supports} bolt group(s) and liner(s) act from the start, as \
             if installed before the excavations were made, and take their whole release; to \
             install them after an excavation, give stages that excavate it and then install \
             them (`stages[i].install`)"
        ));
    }
    out.extend(undamped_default_warnings(scene));
    let ys = scene.region.polygon.iter().map(|p| p[1]);
    let (low, high) = ys.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), y| {
        (l.min(y), h.max(y))
    });
    let s = &scene.in_situ;
    for (field, at_ref, gradient) in [
        ("sxx", s.sxx, s.gradient.sxx),
        ("syy", s.syy, s.gradient.syy),
    ] {
        let at = |y: f64| at_ref + gradient * (y - s.y_ref);
        if at(low) > 0.0 && at(high) > 0.0 {
            out.push(format!(
                "in_situ.{field}: tensile over the whole region ({:.4} MPa at the reference \
                 elevation); adit takes tension positive, as UDEC does, so rock compressed in \
                 situ has negative in-situ stresses (RS2 and most reports give compression \
                 positive)",
                at_ref / 1e6
            ));
        }
    }
    let frictions = (scene.materials.iter())
        .filter_map(|(name, m)| {
            m.friction
                .map(|f| (format!("materials.{name}.friction"), f))
        })
        .chain(
            (scene.joint_materials.iter())
                .map(|(name, j)| (format!("joint_materials.{name}.friction"), j.friction)),
        );
    for (field, degrees) in frictions {
        if degrees > 0.0 && degrees < RADIANS_LIKELY {
            out.push(format!(
                "{field}: {degrees}° is a very small friction angle; angles are in degrees (if \
                 {degrees} is in radians, give {:.1})",
                degrees.to_degrees()
            ));
        }
    }
    out
}

/// A warning for each dynamic solve that gives neither `damping` nor `rayleigh` and so takes the
/// static default local damping (`DEFAULT_DAMPING`, 0.8: about a quarter of critical, α = πξ), which
/// takes most of a wave's energy within a few periods; a dynamic analysis names its damping.
fn undamped_default_warnings(scene: &Scene) -> Vec<String> {
    let solves = std::iter::once(("solve".to_string(), &scene.solve)).chain(
        (scene.stages.iter().enumerate())
            .filter_map(|(i, st)| Some((format!("stages[{i}].solve"), st.solve.as_ref()?))),
    );
    let used_by_stages = scene.stages.is_empty() || scene.stages.iter().any(|s| s.solve.is_none());
    (solves)
        .filter(|(field, s)| {
            (field != "solve" || used_by_stages)
                && s.mode == SolveMode::Dynamic
                && s.damping.is_none()
                && s.rayleigh.is_none()
        })
        .map(|(field, _)| {
            format!(
                "{field}: a dynamic solve with neither `damping` nor `rayleigh` takes the static \
                 default local damping {DEFAULT_DAMPING} (about {:.0} % of critical), which takes \
                 most of a wave's energy within a few periods; give `damping` (0 for none, \
                 π ξ for a fraction ξ of critical) or `rayleigh`",
                100.0 * DEFAULT_DAMPING / std::f64::consts::PI
            )
        })
        .collect()
}

/// The warnings of `meshed`, in the order `adit check` prints them; an error when a zone is sharper
/// than `zoning.accept_angle`.
pub(super) fn warnings(scene: &Scene, meshed: &Meshed) -> anyhow::Result<Vec<String>> {
    let mut warnings = input_warnings(scene);
    let mut is_thin = vec![false; meshed.blocking.blocks.len()];
    for t in &meshed.thin {
        is_thin[t.block] = true;
    }
    for &b in meshed.blocking.slivers.iter().filter(|&&b| !is_thin[b]) {
        let blk = &meshed.blocking.blocks[b];
        warnings.push(format!(
            "block {b} is a sliver (area {:.3e} m²); consider coarser joints or zoning",
            blk.area()
        ));
    }
    warnings.extend(thin_warnings(scene, meshed));
    refuse_sharp_zones(scene, meshed)?;
    warnings.extend(meshed.repairs.iter().cloned());
    for (b, mesh) in meshed.meshes.iter().enumerate() {
        if meshed.modes[b] == BlockMode::Deformable && mesh.angle_limit_deg < scene.zoning.min_angle
        {
            let c = meshed.blocking.blocks[b].outer.centroid();
            warnings.push(format!(
                "block {b} (centroid ({:.3}, {:.3}) m): refinement to zoning.min_angle = {}° did not \
                 end (its constraints meet at small angles); zoned aiming at {}°",
                c[0], c[1], scene.zoning.min_angle, mesh.angle_limit_deg
            ));
        }
    }
    let merges = meshed.blocking.merges;
    if merges.count > 0 {
        warnings.push(format!(
            "cutting moved {} vertices onto others within zoning.merge_tolerance = {:.4} m (joint \
             ends onto joints or walls, crossings onto corners); the largest move, {:.4} m, onto \
             ({:.3}, {:.3}) m",
            merges.count, meshed.merge_tolerance, merges.largest, merges.at[0], merges.at[1]
        ));
    }
    for o in &meshed.blocking.onto_walls {
        warnings.push(format!(
            "{}: {:.3} m of its traces lay along a wall within zoning.merge_tolerance = {:.4} m \
             (up to {:.4} m off it, near ({:.3}, {:.3}) m) and were merged into the wall, which \
             stands for the joint there (to keep it a joint, move it off the wall or lower \
             zoning.merge_tolerance)",
            super::geometry::edge_source(scene, o.kind),
            o.length,
            meshed.merge_tolerance,
            o.offset,
            o.at[0],
            o.at[1]
        ));
    }
    for &k in &meshed.sets_outside {
        warnings.push(format!(
            "joint_sets[{k}]: none of its traces reaches region.polygon, so it cuts nothing \
             (move its `origin`, or lengthen its `trace`)"
        ));
    }
    for f in &meshed.fill_outside {
        let j = f.hole as usize;
        let hole = match scene.excavations.get(j) {
            Some(e) => format!("excavation '{}'", e.name),
            None => format!("inclusions[{}]", j - scene.excavations.len()),
        };
        warnings.push(format!(
            "{hole}: {:.3e} m² of rock outside its profile (near ({:.3}, {:.3}) m) lies in blocks \
             mostly inside it and goes with them (the cutter merged their vertices onto the wall \
             within zoning.merge_tolerance = {:.4} m)",
            f.area, f.at[0], f.at[1], meshed.merge_tolerance
        ));
    }
    Ok(warnings)
}

/// Largest relative difference between the in-situ stress's vertical gradient dσyy/dy and the
/// −ρ g_y that balances gravity before `unbalanced_in_situ` warns (the bundled tunnel's 26 490
/// Pa/m against 2 700 × 9.81 = 26 487 is 1.1e-4).
const IN_SITU_BALANCE: f64 = 1e-2;

/// A warning when the in-situ stress does not balance the region rock's weight (density `rho`,
/// kg/m³) under the scene's gravity: dσyy/dy + ρ g_y = 0 (equilibrium in y, the in-situ stress
/// varying with y only), within `IN_SITU_BALANCE`. A gradient of the wrong sign, or a uniform
/// stress under gravity, leaves the first solve to move the whole model under the difference. A
/// model that starts unstressed is left alone: gravity switched on to build the stress (UDEC's
/// and FLAC's usual start) is meant to move it.
pub(super) fn unbalanced_in_situ(scene: &Scene, rho: f64) -> Option<String> {
    let s = &scene.in_situ;
    let stressed = [s.sxx, s.syy, s.sxy, s.szz.unwrap_or(0.0)]
        .into_iter()
        .chain([s.gradient.sxx, s.gradient.syy, s.gradient.szz])
        .any(|v| v != 0.0);
    if !stressed {
        return None;
    }
    let (gradient, g) = (s.gradient.syy, scene.gravity[1]);
    let balancing = -rho * g;
    let scale = gradient.abs().max(balancing.abs());
    ((gradient - balancing).abs() > IN_SITU_BALANCE * scale).then(|| {
        format!(
            "in_situ.gradient.syy = {gradient} Pa/m does not balance the region rock's weight \
             under gravity: equilibrium needs −ρ g_y = {balancing:.1} Pa/m (ρ = {rho} kg/m³, \
             g_y = {g} m/s²); the first solve moves the model under the difference"
        )
    })
}

/// Zones per shortest wavelength below which a wave is distorted (Kuhlemeyer & Lysmer 1973,
/// "Finite element method accuracy for wave propagation problems", J. Soil Mech. Found. Div. ASCE
/// 99(SM5): Δl ≤ λ/10 to λ/8, λ the wavelength of the highest frequency the wave carries).
const ZONES_PER_WAVELENGTH: f64 = 8.0;

/// A warning when the scene's incident waves, prescribed motions and load histories carry frequencies whose shear wavelength, in the
/// rock each zone is of, spans fewer than `ZONES_PER_WAVELENGTH` of that zone's longest edge
/// (shear: the slowest wave, which a wave turns partly into wherever it meets a boundary or a
/// joint), saying how many zones and by how much.
pub(super) fn coarse_for_waves(
    scene: &Scene,
    zones: &Zones,
    laws: &[Box<dyn ZoneLaw>],
    pos: &[[f64; 2]],
) -> Option<String> {
    let lists = std::iter::once(&scene.boundary)
        .chain(scene.stages.iter().filter_map(|s| s.boundary.as_ref()));
    let histories = (lists.flatten()).flat_map(|c| {
        let motion = c.motion.as_ref();
        [
            c.incident.as_ref().map(|w| w.history()),
            motion.and_then(|m| m.velocity.clone()),
            motion.and_then(|m| m.acceleration.clone()),
            c.history.clone(),
        ]
        .into_iter()
        .flatten()
    });
    let highest = histories
        .map(|h| History::of(&h).highest_frequency())
        .fold(0.0, f64::max);
    if highest <= 0.0 {
        return None;
    }
    let (mut coarse, mut worst) = (0usize, (0.0f64, 0.0f64));
    for (z, tri) in zones.nodes.iter().enumerate() {
        let law = &laws[zones.material[z].0 as usize];
        let (shear, rho) = (law.moduli().1, law.density());
        if shear <= 0.0 || rho <= 0.0 {
            continue;
        }
        let wavelength = (shear / rho).sqrt() / highest;
        let edge = (0..3)
            .map(|k| {
                let (a, b) = (pos[tri[k] as usize], pos[tri[(k + 1) % 3] as usize]);
                (b[0] - a[0]).hypot(b[1] - a[1])
            })
            .fold(0.0, f64::max);
        if edge * ZONES_PER_WAVELENGTH > wavelength {
            coarse += 1;
            if edge / wavelength > worst.0 / worst.1.max(f64::MIN_POSITIVE) {
                worst = (edge, wavelength);
            }
        }
    }
    (coarse > 0).then(|| {
        format!(
            "the incident waves, prescribed motions and load histories carry frequencies up to {highest:.1} Hz, whose shear wavelength \
             spans fewer than {ZONES_PER_WAVELENGTH} zone edges in {coarse} of {} zones (at \
             worst an edge of {:.3} m against a wavelength of {:.3} m): waves through them are \
             distorted (Kuhlemeyer & Lysmer 1973: an edge at most a tenth to an eighth of the \
             shortest wavelength); zone finer (zoning) or lower the frequency",
            zones.len(),
            worst.0,
            worst.1
        )
    })
}

#[cfg(test)]
mod tests {
    /// A set's joint 0.1 m inside a side (tolerance 0.3 m) is merged into it: the warning names
    /// the set and the whole 20 m.
    #[test]
    fn a_joint_merged_into_a_side_is_named() {
        let text = r#"{ "name": "w", "materials": { "rock": { "density": 2600, "young": 2e10, "poisson": 0.25 } },
          "region": { "polygon": [[-10, -10], [10, -10], [10, 10], [-10, 10]], "material": "rock" },
          "zoning": { "edge_at_excavation": 1.0, "edge_far": 1.0 },
          "joint_materials": { "j": { "normal_stiffness": 2e10, "shear_stiffness": 1e10, "friction": 35 } },
          "joint_sets": [
            { "dip": 0, "spacing": 4, "origin": [0, -9.9], "material": "j" },
            { "dip": 70, "spacing": 5, "origin": [0.3, 0], "material": "j" }],
          "boundary": [{ "at": [-10, -10], "fix": "xy" }] }"#;
        let scene = crate::Scene::from_json(text, "w").unwrap();
        let built = crate::setup::setup(&scene).unwrap();
        let merged: Vec<&String> = (built.warnings.iter())
            .filter(|w| w.contains("merged into the wall"))
            .collect();
        assert_eq!(merged.len(), 1, "{:?}", built.warnings);
        assert!(
            merged[0].starts_with("joint_sets[0]: 20.000 m") && merged[0].contains("0.1000 m off"),
            "{}",
            merged[0]
        );
    }

    /// A dynamic solve that names no damping is warned of, naming its field; one that names
    /// either is not, nor is the scene's `solve` when every stage gives its own.
    #[test]
    fn a_dynamic_solve_on_the_default_damping_is_warned_of() {
        let scene = |solve: &str, stage: &str| {
            let text = format!(
                r#"{{ "name": "d", "materials": {{ "rock": {{ "density": 2600, "young": 2e10, "poisson": 0.25 }} }},
                  "region": {{ "polygon": [[0, 0], [4, 0], [4, 4], [0, 4]], "material": "rock" }},
                  "zoning": {{ "edge_at_excavation": 1.0, "edge_far": 1.0 }},
                  "boundary": [{{ "part": "outer", "fix": "xy" }}],
                  "solve": {solve}, "stages": [{{ "name": "a" }}, {{ "name": "b"{stage} }}] }}"#
            );
            let scene = crate::Scene::from_json(&text, "d").unwrap();
            super::undamped_default_warnings(&scene)
        };
        let dynamic = r#"{ "mode": "dynamic", "duration": 0.01 }"#;
        let warned = scene(dynamic, "");
        assert_eq!(warned.len(), 1, "{warned:?}");
        assert!(
            warned[0].starts_with("solve: a dynamic solve"),
            "{}",
            warned[0]
        );
        let own = format!(r#", "solve": {dynamic}"#);
        let warned = scene("{}", &own);
        assert_eq!(warned.len(), 1, "{warned:?}");
        assert!(warned[0].starts_with("stages[1].solve:"), "{}", warned[0]);
        let damped = r#", "solve": { "mode": "dynamic", "duration": 0.01, "damping": 0 }"#;
        assert!(scene("{}", damped).is_empty());
        let rayleigh = r#", "solve": { "mode": "dynamic", "duration": 0.01,
            "rayleigh": { "fraction": 0.02, "frequency": 10 } }"#;
        assert!(scene("{}", rayleigh).is_empty());
    }
}
