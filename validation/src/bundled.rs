//! The bundled tunnel models solved by one method (issue 17's bar: the implicit solve within 1 %
//! of the explicit one on wall closure and yielded zones, at least 10× faster): each run through
//! its stages as `adit run` does, measured on its final state.

use std::path::Path;
use std::time::Instant;

use adit::Scene;
use adit::law::{SHEAR_NOW, SHEAR_PAST, TENSION_NOW, TENSION_PAST};
use adit::scene::SolveMethod;
use adit::solve::{Quiet, Status};

use crate::report::CaseReport;

/// What one run of a bundled model measured.
#[derive(Debug, Clone)]
pub struct ModelRun {
    /// Median inward radial displacement of the tunnel wall's nodes, m.
    pub closure: f64,
    /// Zones that have yielded (in shear or tension, now or before).
    pub yielded: usize,
    pub zones: usize,
    /// Explicit cycles or implicit iterations, over all stages.
    pub cycles: u64,
    /// Wall seconds, meshing and output included.
    pub wall_s: f64,
    pub implicit: Option<adit::implicit::Cost>,
}

/// Run the model `file` (under `root`) with every stage's `solve.method` set to `method`, and
/// each stage's out-of-balance forces released gradually: explicitly over `release` cycles
/// (`solve.ramp`; 0: at once), implicitly in `release` load steps (`solve.load_steps`; 0 or 1:
/// at once); writing into `out` (removed afterwards).
pub fn run(
    root: &Path,
    file: &str,
    method: SolveMethod,
    release: u64,
    out: &Path,
) -> anyhow::Result<ModelRun> {
    let mut sc = Scene::load(&root.join(file))?;
    let solves = std::iter::once(&mut sc.solve)
        .chain(sc.stages.iter_mut().filter_map(|st| st.solve.as_mut()));
    for s in solves {
        s.method = method;
        crate::release_gradually(s, release);
    }
    sc.validate()?;
    let start = Instant::now();
    let r = adit::run_scene(&sc, out, &mut Quiet)?;
    let wall_s = start.elapsed().as_secs_f64();
    let _ = std::fs::remove_dir_all(out);
    anyhow::ensure!(
        r.solution.status == Status::Converged,
        "{file} ({}) did not converge: {:?}",
        method.name(),
        r.solution.status
    );
    let m = &r.built.model;
    let wall = &r.built.plan.boundary.part_nodes["tunnel"];
    let closures = crate::modes::closures(m, wall);
    let yielded = (m.zones.state.iter())
        .filter(|&&s| s & (SHEAR_NOW | SHEAR_PAST | TENSION_NOW | TENSION_PAST) != 0)
        .count();
    Ok(ModelRun {
        closure: closures[closures.len() / 2],
        yielded,
        zones: m.zones.len(),
        cycles: r.summary.cycles,
        wall_s,
        implicit: r.summary.implicit,
    })
}

/// Cycles over which an explicit run releases each stage's load in the quasi-static path (a slow
/// excavation, `solve.ramp`): the tunnel's median closure moves by 0.07 % from 16 000 to 32 000.
pub const QUASI_STATIC_RAMP: u64 = 16_000;

/// Load steps of an implicit run on the quasi-static path (`solve.load_steps`): the tunnel's
/// median closure is 0.01 % from the explicit one's at 16 steps (645 zones yielded against 644).
pub const QUASI_STATIC_STEPS: u64 = 16;

/// The release of the quasi-static path for `method`: [`QUASI_STATIC_RAMP`] cycles explicitly,
/// [`QUASI_STATIC_STEPS`] load steps implicitly (`crate::release_gradually`).
pub fn quasi_static(method: SolveMethod) -> u64 {
    match method {
        SolveMethod::Explicit => QUASI_STATIC_RAMP,
        _ => QUASI_STATIC_STEPS,
    }
}

/// Issue 17's bar on the bundled tunnel models: the implicit median wall closure and yielded-zone
/// count within this fraction of the explicit run's along the same path.
pub const BAR: f64 = 0.01;

/// The implicit run's relative differences from the explicit one: median wall closure and count
/// of yielded zones (a count that is zero both ways differs by zero).
pub fn differences(e: &ModelRun, i: &ModelRun) -> (f64, f64) {
    let relative = |a: f64, b: f64| if b == 0.0 { a.abs() } else { (a - b).abs() / b };
    (
        relative(i.closure, e.closure),
        relative(i.yielded as f64, e.yielded as f64),
    )
}

/// The two runs of a model along one `path` (said in the rows' names) as report rows; the
/// implicit row's errors are its relative differences from the explicit run (closure, yielded
/// zones), the explicit row's zero.
pub fn reports(file: &str, path: &str, e: &ModelRun, i: &ModelRun) -> (CaseReport, CaseReport) {
    let row = |r: &ModelRun, method: SolveMethod, errors: &[(&str, f64)]| {
        CaseReport::new(
            format!(
                "`{file}` {path}: median closure {:.2} mm, {} zones yielded{}",
                1e3 * r.closure,
                r.yielded,
                crate::method_suffix(method)
            ),
            r.zones,
            r.cycles,
            r.wall_s,
            None,
            errors,
        )
        .with_implicit(r.implicit)
    };
    let (closure, yielded) = differences(e, i);
    (
        row(
            e,
            SolveMethod::Explicit,
            &[("closure", 0.0), ("yielded", 0.0)],
        ),
        row(
            i,
            SolveMethod::Implicit,
            &[("closure", closure), ("yielded", yielded)],
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 17's bar on the bundled tunnel models is 1 % of the explicit wall closure and
    /// yielded-zone count, on the quasi-static path (the plastic answer depends on the path:
    /// released at once, the explicit tunnel overshoots dynamically to 7.41 mm and 679 zones,
    /// +1.9 % and +5.4 %). Measured: the tunnel −0.24 % and −0.16 % (643 of 644 zones), the
    /// jointed tunnel +0.04 % and 0 of 0.
    #[test]
    fn the_implicit_solve_gives_the_tunnel_models_explicit_answer() {
        let root = crate::repository_root();
        for file in ["models/tunnel.json", "models/jointed_tunnel.json"] {
            let dir = std::env::temp_dir().join(format!(
                "adit_bundled_{}_{}",
                std::process::id(),
                file.replace(['/', '.'], "_")
            ));
            let (e, i) = (
                run(
                    &root,
                    file,
                    SolveMethod::Explicit,
                    QUASI_STATIC_RAMP,
                    &dir.join("e"),
                ),
                run(
                    &root,
                    file,
                    SolveMethod::Implicit,
                    QUASI_STATIC_STEPS,
                    &dir.join("i"),
                ),
            );
            let (_, r) = reports(file, "slowly", &e.unwrap(), &i.unwrap());
            assert!(r.errors["closure"] < BAR, "{r:?}");
            assert!(r.errors["yielded"] < BAR, "{r:?}");
        }
    }
}
