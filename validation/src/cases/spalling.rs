//! Brittle spalling (issue 48): `models/spalling.json`, the cohesion-weakening friction-
//! strengthening rock around a circular opening, its failed depth against Martin et al. (1999)'s
//! empirical line.

use std::fmt::Write as _;
use std::time::Instant;

use adit::law::{SHEAR_PAST, TENSION_PAST};
use adit::solve::Quiet;

use crate::case::{Case, Context, Section, print_row, table};
use crate::report::CaseReport;

/// Half-width of the wedge about σ3's axis in which the notch's depth is read, degrees.
const WEDGE_DEG: f64 = 15.0;
/// Martin et al.'s (1999) scatter about their line, in Rf/a: the band the report gives.
const BAND: f64 = 0.1;

/// Martin, Kaiser & McCreath (1999), "Hoek–Brown parameters for predicting the depth of
/// brittle failure around tunnels", CGJ 36: Rf/a = 0.49 (±0.1) + 1.25 σmax/σci.
pub fn martin(sigma_max_over_ci: f64) -> f64 {
    0.49 + 1.25 * sigma_max_over_ci
}

/// What the model gave.
#[derive(Debug, Clone)]
pub struct Spalled {
    /// Opening radius a, m; the failed region's farthest radius along σ3's axis, m.
    pub radius: f64,
    pub failed_radius: f64,
    /// σmax = 3σ1 − σ3 at the wall (Kirsch), Pa.
    pub sigma_max: f64,
    pub zones: usize,
    pub cycles: u64,
    pub seconds: f64,
}

/// The shipped model.
pub fn shipped(root: &std::path::Path) -> anyhow::Result<adit::Scene> {
    Ok(adit::Scene::load(&root.join("models/spalling.json"))?)
}

/// The shipped model's rock as the brittle Hoek–Brown criterion of Martin et al. (1999):
/// mb = 0, s = 0.11, a = 0.5 with σci = [`SIGMA_CI`], the same tension cut-off.
pub fn brittle_hoek_brown(mut scene: adit::Scene) -> adit::Scene {
    for m in scene.materials.values_mut() {
        m.law = adit::scene::ZoneLawKind::HoekBrown;
        (m.cohesion, m.friction, m.cwfs) = (None, None, None);
        m.sigma_ci = Some(SIGMA_CI);
        (m.mb, m.s, m.a) = (Some(0.0), Some(0.11), Some(0.5));
    }
    scene
}

/// Run `scene` and read the failed depth: the farthest radius the zones that yielded reach (their
/// vertices: the failed region's outer edge, as a notch's tip is observed), of those whose
/// centroid lies within ±`WEDGE_DEG` of the vertical (σ3's axis, where σθ peaks).
pub fn run(scene: &adit::Scene) -> anyhow::Result<Spalled> {
    let start = Instant::now();
    let out = std::env::temp_dir().join(format!("adit-spalling-{}", std::process::id()));
    let r = adit::run_scene(scene, &out, &mut Quiet)?;
    let _ = std::fs::remove_dir_all(&out);
    anyhow::ensure!(
        r.summary.status == "converged",
        "spalling: {}",
        r.summary.status
    );
    let m = &r.built.model;
    let radius = opening_radius(scene)?;
    let mut failed_radius = radius;
    for i in 0..m.zones.len() {
        if m.zones.state[i] & (SHEAR_PAST | TENSION_PAST) == 0 {
            continue;
        }
        let c = m.zones.centroid(i, &m.nodes.pos);
        let off_vertical = c[0].atan2(c[1].abs()).abs().to_degrees();
        if off_vertical <= WEDGE_DEG {
            for &n in &m.zones.nodes[i] {
                let p = m.nodes.pos[n as usize];
                failed_radius = failed_radius.max(p[0].hypot(p[1]));
            }
        }
    }
    let (s1, s3) = (-scene.in_situ.sxx, -scene.in_situ.syy);
    Ok(Spalled {
        radius,
        failed_radius,
        sigma_max: 3.0 * s1 - s3,
        zones: m.zones.len(),
        cycles: r.summary.cycles,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// The opening's radius, m.
fn opening_radius(scene: &adit::Scene) -> anyhow::Result<f64> {
    Ok(scene.excavations[0]
        .circle
        .as_ref()
        .ok_or_else(|| anyhow::anyhow!("spalling: the opening is a circle"))?
        .radius)
}

/// Martin et al.'s (1999) own use of the brittle criterion: the elastic (Kirsch) stresses on σ3's
/// axis, σθ − σr = √s σci at the failed depth, with compression positive far-field P1 along x and
/// P3 along y,
///   σr = (P1 + P3)/2 (1 − a²/r²) − (P1 − P3)/2 (1 − 4a²/r² + 3a⁴/r⁴),
///   σθ = (P1 + P3)/2 (1 + a²/r²) + (P1 − P3)/2 (1 + 3a⁴/r⁴)  (θ = 90°);
/// the radius (m) where σθ − σr falls to √0.11 σci, by bisection between a and 10a.
pub fn elastic_depth(scene: &adit::Scene) -> anyhow::Result<f64> {
    let a = opening_radius(scene)?;
    let (p1, p3) = (-scene.in_situ.sxx, -scene.in_situ.syy);
    let deviator = |r: f64| {
        let (q2, q4) = ((a / r).powi(2), (a / r).powi(4));
        let sr = 0.5 * (p1 + p3) * (1.0 - q2) - 0.5 * (p1 - p3) * (1.0 - 4.0 * q2 + 3.0 * q4);
        let st = 0.5 * (p1 + p3) * (1.0 + q2) + 0.5 * (p1 - p3) * (1.0 + 3.0 * q4);
        st - sr
    };
    let strength = 0.11f64.sqrt() * SIGMA_CI;
    if deviator(a) < strength {
        return Ok(a);
    }
    let (mut lo, mut hi) = (a, 10.0 * a);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if deviator(mid) > strength {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// σci of the model's granite (Lac du Bonnet, Martin et al. 1999), Pa.
pub const SIGMA_CI: f64 = 213e6;

pub struct Spalling;

impl Case for Spalling {
    fn name(&self) -> &'static str {
        "spalling"
    }

    fn run(&self, cx: &Context) -> anyhow::Result<Section> {
        let scene = shipped(&cx.root)?;
        let cwfs = run(&scene)?;
        let brittle = run(&brittle_hoek_brown(scene.clone()))?;
        let elastic = elastic_depth(&scene)? / cwfs.radius;
        let ratio = cwfs.sigma_max / SIGMA_CI;
        let line = martin(ratio);
        let row = |s: &Spalled, what: &str| {
            let depth = s.failed_radius / s.radius;
            CaseReport::new(
                format!(
                    "spalling: {what}, σmax/σci = {ratio:.3}, Rf/a = {depth:.3} against Martin's {line:.3}"
                ),
                s.zones,
                s.cycles,
                s.seconds,
                None,
                &[("martin_line", (depth - line).abs() / line)],
            )
        };
        let rows = vec![
            row(&cwfs, "models/spalling.json (CWFS)"),
            row(
                &brittle,
                "the same, brittle Hoek–Brown (mb 0, s 0.11, a 0.5)",
            ),
        ];
        for r in &rows {
            print_row(r);
        }
        let mut md = String::new();
        let _ = writeln!(
            md,
            "\n## Brittle spalling: CWFS against Martin's line (issue 48)\n"
        );
        let _ = writeln!(
            md,
            "`models/spalling.json`: a circular opening (a = {} m) in massive granite under σ1 = \
             60 MPa horizontal, σ3 = 11 MPa vertical and 45 MPa along the tunnel (the stresses and \
             size of AECL's Mine-by tunnel, σci = {} MPa), E = 60 GPa, ν = 0.2, the \
             cohesion-weakening friction-strengthening model of Hajiabdolmajid, Kaiser & Martin \
             (2002): cohesion 50 → 15 MPa over a plastic shear strain of 0.2 %, friction 0 → 48° \
             over 0.5 %, tension cut-off 10 MPa; excavated in a stage released over 16 000 \
             cycles. The failed depth is the farthest radius reached by the zones that yielded \
             (their vertices: the failed region's outer edge, as a notch's tip is observed; read \
             at their centroids, half a zone inside, CWFS gave 1.38) with centroids within \
             ±{WEDGE_DEG}° of the vertical (σ3's axis, where σθ = 3σ1 − σ3 peaks), against \
             Martin, Kaiser & McCreath (1999)'s empirical line Rf/a = 0.49 + 1.25 σmax/σci from \
             observed failure depths, whose data scatter about ±{BAND} in Rf/a: an empirical band, \
             not a closed form. `martin_line` is the relative distance from the line. The second \
             row runs the same model with the rock as Martin et al.'s brittle Hoek–Brown \
             criterion (mb = 0, s = 0.11, a = 0.5: σ1′ − σ3′ = √0.11 σci = {:.1} MPa, perfectly \
             plastic); their own use of it, the depth where the elastic (Kirsch) stresses reach \
             it, gives Rf/a = {elastic:.3}.\n",
            cwfs.radius,
            SIGMA_CI / 1e6,
            0.11f64.sqrt() * SIGMA_CI / 1e6
        );
        table(&mut md, &rows);
        let depth = cwfs.failed_radius / cwfs.radius;
        let _ = writeln!(
            md,
            "\nσmax/σci = {ratio:.3}: CWFS Rf/a = {depth:.3} ({:.2} m of failed rock beyond the \
             wall), brittle Hoek–Brown {:.3}, elastic with the brittle criterion {elastic:.3}; the \
             line gives {line:.3} (band {:.2}–{:.2}): CWFS {}.\n",
            cwfs.failed_radius - cwfs.radius,
            brittle.failed_radius / brittle.radius,
            line - BAND,
            line + BAND,
            if (depth - line).abs() <= BAND {
                "within the band"
            } else {
                "outside the band"
            }
        );
        Ok(Section {
            markdown: md,
            rows,
            ..Default::default()
        })
    }
}

#[cfg(test)]
mod coarse {
    /// The shipped model spalls, and to a depth within Martin's band; the elastic prediction
    /// with the brittle criterion is Martin et al.'s 1.43.
    #[test]
    fn the_spalling_model_fails_to_martins_depth() {
        let scene = super::shipped(&crate::repository_root()).unwrap();
        let s = super::run(&scene).unwrap();
        let elastic = super::elastic_depth(&scene).unwrap() / s.radius;
        assert!((elastic - 1.434).abs() < 1e-3, "{elastic}");
        let depth = s.failed_radius / s.radius;
        let line = super::martin(s.sigma_max / super::SIGMA_CI);
        eprintln!("Rf/a {depth}, Martin's line {line}");
        assert!(depth > 1.1, "{depth}");
        assert!(
            (depth - line).abs() <= super::BAND,
            "{depth} against {line}"
        );
    }
}
