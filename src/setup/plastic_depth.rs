//! `zoning.plastic_depth`: the depth from the excavation walls where the rock is expected to
//! yield, zoned at half the graded size (issue 48). Plain triangles converge to a plastic zone's
//! closure from the stiff side: Salençon's hole with its plastic zone 2.8 and 4.2 radii deep
//! closes 6 % and 13 % too little on a graded zoning whose wall zones are a 28th of the radius,
//! within 3 % on zones half the size (`docs/validation.md`, "Plastic zones against zoning").
//! `"auto"` estimates the depth before meshing from the closed form of a circular hole in the
//! region's rock, so the zoning a user writes resolves the plastic zone it will have; it is the
//! default.

use crate::scene::{PlasticDepth, Scene, SceneError};

use super::catalogue::matrix_law;
use super::geometry::outline;
use super::in_situ_stress;

/// The estimated plastic depth Rp − a is zoned finely out to this multiple of it.
pub const DEPTH_MARGIN: f64 = 1.2;

/// Midpoints of the plastic radius's integral (over √σ, which keeps an envelope with s = 0
/// integrable at σ = 0).
const POINTS: usize = 2000;

/// Plastic radius (m) of a circular hole of radius `radius` (m) unloaded from a hydrostatic
/// stress `p0` (Pa, compression positive) to a free wall, in perfectly plastic rock whose
/// deviator at failure under a confinement σ is q(σ) (Pa, compression positive): the wall yields
/// once the support pressure falls below pcr, 2 (p0 − pcr) = q(pcr) (the elastic wall's
/// σθ − σr), and radial equilibrium dσr/dr = q(σr)/r through the plastic zone gives
/// ln(Rp/a) = ∫₀^pcr dσ / q(σ). For Mohr–Coulomb this is Salençon's (1969) Rp, for Hoek–Brown
/// Carranza-Torres's (2004); the radius itself where the wall does not yield.
pub fn plastic_radius(q: impl Fn(f64) -> f64, p0: f64, radius: f64) -> f64 {
    if p0.is_nan() || p0 <= 0.0 || q(0.0) >= 2.0 * p0 {
        return radius;
    }
    // 2 (p0 − p) − q(p) falls from positive at p = 0 to −q(p0) < 0 at p = p0.
    let (mut lo, mut hi) = (0.0, p0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if 2.0 * (p0 - mid) > q(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let pcr = 0.5 * (lo + hi);
    // σ = pcr t²: ∫₀¹ 2 pcr t / q(pcr t²) dt.
    let dt = 1.0 / POINTS as f64;
    let log_ratio: f64 = (0..POINTS)
        .map(|k| {
            let t = (k as f64 + 0.5) * dt;
            2.0 * pcr * t / q(pcr * t * t) * dt
        })
        .sum();
    radius * log_ratio.exp()
}

/// The plastic depth the scene's zoning refines, m: the depth given, or for `"auto"` the largest
/// over its excavations of `DEPTH_MARGIN` (Rp − a), Rp estimated by [`plastic_radius`] for a
/// circular hole of the excavation's area (a = √(A/π)) in the region's rock (its peak envelope;
/// a weak plane, supports and staging aside) under the in-situ stress at the excavation's
/// centroid, p0 its major principal compression; 0 in elastic rock.
pub fn plastic_depth(scene: &Scene) -> Result<f64, SceneError> {
    if let PlasticDepth::Depth(d) = scene.zoning.plastic_depth {
        return Ok(d);
    }
    let name = &scene.region.material;
    let material = (scene.materials.get(name)).ok_or_else(|| SceneError::Invalid {
        path: "region.material".into(),
        reason: format!("no material named {name}"),
    })?;
    let path = format!("materials.{name}");
    let law = matrix_law(material, &path)?;
    if law.peak_deviator(0.0).is_none() {
        return Ok(0.0);
    }
    let q = |s: f64| law.peak_deviator(s).expect("a plastic matrix");
    let mut depth: f64 = 0.0;
    for (i, e) in scene.excavations.iter().enumerate() {
        let outline = outline(e.shape(&format!("excavations[{i}]"))?);
        let radius = (outline.signed_area().abs() / std::f64::consts::PI).sqrt();
        let y = outline.centroid()[1];
        let [sxx, syy, _, sxy] = in_situ_stress(&scene.in_situ, y, material.poisson);
        let major = -(0.5 * (sxx + syy) - (0.25 * (sxx - syy).powi(2) + sxy * sxy).sqrt());
        let rp = plastic_radius(q, major, radius);
        depth = depth.max(DEPTH_MARGIN * (rp - radius));
    }
    Ok(depth)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Mohr–Coulomb: Salençon's closed form Rp = a [2 ((Nφ − 1) p0 + σc) / ((Nφ + 1) σc)]^(1/(Nφ − 1)),
    /// σc = 2c√Nφ, at rocks it was not written for.
    #[test]
    fn mohr_coulomb_radius_is_salencons() {
        for (c, phi_deg, p0, a) in [
            (1e6, 25.0, 15e6, 1.0),
            (0.5e6, 20.0, 8e6, 3.0),
            (3e6, 40.0, 30e6, 0.5),
        ] {
            let phi: f64 = f64::to_radians(phi_deg);
            let n = (1.0 + phi.sin()) / (1.0 - phi.sin());
            let sc = 2.0 * c * n.sqrt();
            let exact = a * (2.0 * ((n - 1.0) * p0 + sc) / ((n + 1.0) * sc)).powf(1.0 / (n - 1.0));
            let rp = plastic_radius(|s| sc + (n - 1.0) * s, p0, a);
            assert_relative_eq!(rp, exact, max_relative = 1e-6);
        }
    }

    /// Hoek–Brown with a = 1/2: Carranza-Torres's scaled closed form. With S = s/(mb²), the
    /// scaled pressure P = p/(mb σci) + S, Rp = a exp(2 (√Pcr − √S)), Pcr = (1 − √(1 + 16 P0))²/16.
    #[test]
    fn hoek_brown_radius_is_carranza_torres() {
        for (mb, s, sci, p0) in [
            (2.0, 0.004, 80e6, 30e6),
            (0.55, 2.4e-4, 40e6, 10e6),
            (5.0, 0.06, 150e6, 100e6),
        ] {
            let q = |x: f64| sci * (mb * x / sci + s).sqrt();
            let big_s = s / (mb * mb);
            let p0s = p0 / (mb * sci) + big_s;
            let pcr = (1.0 - (1.0 + 16.0 * p0s).sqrt()).powi(2) / 16.0;
            let exact = 2.0 * (2.0 * (pcr.sqrt() - big_s.sqrt())).exp();
            assert_relative_eq!(plastic_radius(q, p0, 2.0), exact, max_relative = 1e-5);
        }
    }

    /// The mean area (m²) of the zones of `scene` whose centroids lie within `depth` (m) of its
    /// first excavation's wall, and their count.
    fn zones_near_wall(scene: &Scene, depth: f64) -> (f64, usize) {
        let meshed = crate::setup::mesh(scene).unwrap();
        let wall = &meshed.domain.holes[0].polygon;
        let (mut area, mut count) = (0.0, 0);
        for m in &meshed.meshes {
            for t in &m.triangles {
                let [a, b, c] = t.map(|i| m.points[i as usize]);
                let centre = [(a[0] + b[0] + c[0]) / 3.0, (a[1] + b[1] + c[1]) / 3.0];
                if wall.boundary_distance(centre) < depth {
                    let cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
                    area += 0.5 * cross.abs();
                    count += 1;
                }
            }
        }
        (area / count as f64, count)
    }

    /// `models/kirsch.json` in Mohr–Coulomb rock with `plastic_depth: "auto"`: Salençon's depth
    /// for its major in-situ compression, and zones within it of about a quarter of the area
    /// (half the edge) of those the scene as written makes there.
    #[test]
    fn auto_halves_the_zones_of_the_plastic_zone() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/kirsch.json");
        let mut auto = Scene::load(std::path::Path::new(path)).unwrap();
        let rock = auto.materials.get_mut("rock").unwrap();
        rock.law = crate::scene::ZoneLawKind::MohrCoulomb;
        (rock.cohesion, rock.friction) = (Some(2e6), Some(30.0));
        assert_eq!(auto.zoning.plastic_depth, PlasticDepth::Auto);
        let mut written = auto.clone();
        written.zoning.plastic_depth = PlasticDepth::OFF;
        assert_eq!(plastic_depth(&written).unwrap(), 0.0);
        let depth = plastic_depth(&auto).unwrap();
        let n = 3.0;
        let sc = 4e6 * 3f64.sqrt();
        let rp = (2.0 * ((n - 1.0) * 20e6 + sc) / ((n + 1.0) * sc)).powf(1.0 / (n - 1.0));
        assert_relative_eq!(depth, DEPTH_MARGIN * (rp - 1.0), max_relative = 2e-3);
        let (fine, n_fine) = zones_near_wall(&auto, depth);
        let (coarse, n_coarse) = zones_near_wall(&written, depth);
        let ratio = fine / coarse;
        assert!(
            ratio > 0.2 && ratio < 0.32,
            "{ratio}: {n_fine} against {n_coarse} zones"
        );
    }

    /// `models/tunnel.json` (Mohr–Coulomb rock, joints, a horseshoe under anisotropic stress):
    /// `"auto"` estimates a depth and zones it more finely.
    #[test]
    fn auto_refines_the_bundled_tunnel() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/tunnel.json");
        let auto = Scene::load(std::path::Path::new(path)).unwrap();
        let mut written = auto.clone();
        written.zoning.plastic_depth = PlasticDepth::OFF;
        let depth = plastic_depth(&auto).unwrap();
        assert!(depth > 0.5 && depth < 10.0, "{depth}");
        let (fine, n_fine) = zones_near_wall(&auto, depth);
        let (coarse, n_coarse) = zones_near_wall(&written, depth);
        assert!(
            n_fine as f64 > 1.5 * n_coarse as f64,
            "{n_fine} against {n_coarse}"
        );
        assert!(fine < 0.7 * coarse, "{fine} against {coarse} m²");
    }

    /// A hole whose wall does not yield has no plastic zone.
    #[test]
    fn strong_rock_does_not_yield() {
        assert_eq!(plastic_radius(|s| 50e6 + 3.0 * s, 20e6, 1.5), 1.5);
    }
}
