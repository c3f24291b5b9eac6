//! What each block mode buys: the jointed tunnel (`models/jointed_tunnel.json`, 372 blocks) run
//! to equilibrium with every block deformable, simple or rigid, and deformable with a 10× stiffer
//! rock (which must move towards the rigid result: a stiff deformable block moves like a rigid
//! one). Reported: cycles, wall seconds, zone- and block-cycles per second, the tunnel's median
//! radial closure against the deformable reference, and the largest closure at a wall node.
//!
//! The median, not the mean: the sidewall wedges (blocks 4 and 10, apex ≈ 96°, half-angle 48° >
//! φ = 35°) are removable key blocks that the in-situ stress squeezes out once the tunnel is
//! open. They lose their clamping within about a millimetre; a deformable wedge then stops (its
//! zones' vibration is damped), while a rigid or simple one keeps the speed it had, since local
//! damping acts on unbalanced force and a loose block has none: the run converges with the wedge
//! still drifting into the tunnel, as in UDEC. The largest closure shows it.

use std::time::Instant;

use adit::Scene;
use adit::model::Model;
use adit::scene::BlockMode;
use adit::setup::setup;
use adit::solve::Status;

use crate::incline::mode_name;
use crate::report::CaseReport;

/// One run of the scene in one mode.
#[derive(Debug, Clone)]
pub struct ModeRun {
    pub label: String,
    pub blocks: usize,
    pub zones: usize,
    pub cycles: u64,
    pub wall_s: f64,
    /// Blocks × cycles per second of cycling.
    pub block_cycles_per_s: f64,
    /// Zones × cycles per second of cycling (0 without zones).
    pub zone_cycles_per_s: f64,
    /// Median radial closure of the tunnel wall, m (inward positive).
    pub closure: f64,
    /// Mean radial closure of the tunnel wall, m (inward positive).
    pub mean_closure: f64,
    /// Largest radial closure at a wall node, m (a loose key block drifting in).
    pub largest: f64,
    /// What the implicit solve cost, when `solve.method` asked for it.
    pub implicit: Option<adit::implicit::Cost>,
}

/// Inward radial displacements of the nodes of `wall`, about the origin, m, in increasing order.
pub fn closures(model: &Model, wall: &[u32]) -> Vec<f64> {
    let mut c: Vec<f64> = crate::radial_displacements(model, wall)
        .map(|u| -u)
        .collect();
    c.sort_by(f64::total_cmp);
    c
}

/// Run `scene` with every block in `mode` and the rock's Young's modulus times `stiffen`.
pub fn run(scene: &Scene, mode: BlockMode, stiffen: f64) -> anyhow::Result<ModeRun> {
    let mut sc = scene.clone();
    sc.blocks.mode = mode;
    sc.blocks.regions.clear();
    for m in sc.materials.values_mut() {
        m.young *= stiffen;
    }
    let label = if stiffen == 1.0 {
        mode_name(mode).to_string()
    } else {
        format!("{} (E ×{stiffen})", mode_name(mode))
    };
    run_as(&sc, label)
}

/// Run `scene` with its own block modes, reporting it as `label`.
pub fn run_as(sc: &Scene, label: String) -> anyhow::Result<ModeRun> {
    let start = Instant::now();
    let mut b = setup(sc)?;
    let (solver, sol, implicit) = crate::solve_by_method(&mut b.model, &sc.solve);
    anyhow::ensure!(
        sol.status == Status::Converged,
        "{label} did not converge: {:?}",
        sol.status
    );
    let closures = closures(&b.model, &b.plan.boundary.part_nodes["tunnel"]);
    let s = solver.cycle.seconds();
    let cycling = s.detect + s.contacts + s.zones + s.motion;
    // Cycling rates (0 for an implicit solve, which does not cycle).
    let per_s = |items: usize| {
        if cycling > 0.0 {
            items as f64 * sol.cycles as f64 / cycling
        } else {
            0.0
        }
    };
    Ok(ModeRun {
        label,
        blocks: b.model.blocks.len(),
        zones: b.model.zones.len(),
        cycles: sol.cycles,
        wall_s: start.elapsed().as_secs_f64(),
        block_cycles_per_s: per_s(b.model.blocks.len()),
        zone_cycles_per_s: per_s(b.model.zones.len()),
        closure: closures[closures.len() / 2],
        mean_closure: closures.iter().sum::<f64>() / closures.len() as f64,
        largest: closures[closures.len() - 1],
        implicit,
    })
}

/// All modes on `scene`: deformable (the reference), simple, rigid, deformable ×10 stiffer, and
/// `mixed` (the same rock mass with modes by region) when given.
pub fn table(scene: &Scene, mixed: Option<&Scene>) -> anyhow::Result<Vec<ModeRun>> {
    let mut runs = vec![
        run(scene, BlockMode::Deformable, 1.0)?,
        run(scene, BlockMode::Simple, 1.0)?,
        run(scene, BlockMode::Rigid, 1.0)?,
        run(scene, BlockMode::Deformable, 10.0)?,
    ];
    if let Some(m) = mixed {
        runs.push(run_as(m, format!("mixed (`{}.json`)", m.name))?);
    }
    Ok(runs)
}

impl ModeRun {
    /// The run as a report row along `path` (in words, or empty), its case name ending in
    /// `suffix`, with `errors`.
    fn row(&self, path: &str, suffix: &str, errors: &[(&str, f64)]) -> CaseReport {
        let path = if path.is_empty() {
            String::new()
        } else {
            format!(" {path}")
        };
        CaseReport::new(
            format!(
                "jointed tunnel, {} blocks{path}: median closure {:.2} mm, largest {:.1} mm{suffix}",
                self.label,
                1e3 * self.closure,
                1e3 * self.largest
            ),
            self.zones,
            self.cycles,
            self.wall_s,
            None,
            errors,
        )
        .with_implicit(self.implicit)
    }
}

/// Case reports of the table: the closure error of each mode against the deformable reference.
pub fn reports(runs: &[ModeRun]) -> Vec<CaseReport> {
    let reference = runs[0].closure;
    runs.iter()
        .map(|r| {
            let change = (r.closure - reference).abs() / reference;
            r.row("", "", &[("closure_vs_deformable", change)])
        })
        .collect()
}

/// The same mode solved explicitly (`e`) and implicitly (`i`) along `path` (in words) as report
/// rows; the implicit row's error is its relative change from the explicit run's median closure.
/// (The largest closures, in the case names, differ by design: released at once, the explicit
/// run's loose rigid or simple wedges keep drifting at the speed they had, the module's note
/// says why, while the static solve leaves them where they lost their clamping.)
pub fn method_reports(e: &ModeRun, i: &ModeRun, path: &str) -> (CaseReport, CaseReport) {
    let change = (i.closure - e.closure).abs() / e.closure;
    (
        e.row(path, "", &[("closure", 0.0)]),
        i.row(path, ", implicit", &[("closure", change)]),
    )
}

/// Cycles over which an explicit run of the jointed tunnel in rigid or simple blocks releases its
/// load along the quasi-static path (`solve.ramp`). Rigid and simple blocks slip along their
/// path more than deformable ones (`bundled::QUASI_STATIC_RAMP`): measured, the median closure
/// in rigid blocks moved 0.85 % from 16 000 cycles to 64 000 (1.537 to 1.524 mm), in simple
/// blocks 0.9 % (3.760 to 3.726 mm).
pub const QUASI_STATIC_RAMP: u64 = 64_000;

/// Load steps of an implicit run of the jointed tunnel in rigid or simple blocks along the
/// quasi-static path (`solve.load_steps`): measured, its median closure in rigid blocks at 16,
/// 32 and 64 steps 1.457, 1.521 and 1.521 mm, in simple blocks 3.658, 3.727 and 3.719 mm.
pub const QUASI_STATIC_STEPS: u64 = 32;

/// The release of the blocks' quasi-static path for `method` (`crate::release_gradually`).
pub fn quasi_static(method: adit::scene::SolveMethod) -> u64 {
    match method {
        adit::scene::SolveMethod::Explicit => QUASI_STATIC_RAMP,
        _ => QUASI_STATIC_STEPS,
    }
}

/// The jointed tunnel `scene` in block `mode`, solved by `method`, at once or `slowly` (along
/// the quasi-static path, `quasi_static`).
pub fn run_by(
    scene: &Scene,
    mode: BlockMode,
    method: adit::scene::SolveMethod,
    slowly: bool,
) -> anyhow::Result<ModeRun> {
    let mut s = scene.clone();
    s.solve.method = method;
    if slowly {
        crate::release_gradually(&mut s.solve, quasi_static(method));
    }
    run(&s, mode, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every mode converges on the jointed tunnel and the closures order as the stiffness of the
    /// kinematics: rigid < simple < deformable (simple blocks, one uniform strain each, miss the
    /// stress gradient at the wall); a 10× stiffer deformable rock closes towards the rigid result
    /// (between the two, nearer to the rigid).
    /// The implicit solve takes rigid and simple blocks (their generalised displacements as
    /// unknowns): along the quasi-static path the jointed tunnel's median closure as explicit,
    /// within 1 % (measured: rigid −0.2 %, simple +0.03 %). Released at once, the two paths
    /// differ (rigid: 1.39 mm implicitly, 1.56 mm explicitly), as they do for a plastic rock.
    #[test]
    fn the_implicit_solve_takes_rigid_and_simple_blocks() {
        use adit::scene::SolveMethod::{Explicit, Implicit};
        let scene = Scene::load(&crate::repository_root().join("models/jointed_tunnel.json"))
            .expect("shipped model");
        for mode in [BlockMode::Rigid, BlockMode::Simple] {
            let by = |method| run_by(&scene, mode, method, true).unwrap();
            let (e, i) = (by(Explicit), by(Implicit));
            let (_, r) = method_reports(&e, &i, "slowly");
            assert!(r.errors["closure"] < 0.01, "{r:?} {e:?}");
            assert!(i.implicit.is_some_and(|c| c.iterations > 1), "{i:?}");
        }
    }

    #[test]
    fn modes_agree_where_they_should() {
        let scene = Scene::load(&crate::repository_root().join("models/jointed_tunnel.json"))
            .expect("shipped model");
        let mixed = Scene::load(&crate::repository_root().join("models/jointed_tunnel_mixed.json"))
            .expect("shipped model");
        let runs = table(&scene, Some(&mixed)).unwrap();
        for r in &runs {
            eprintln!("{r:?}");
        }
        let (deformable, simple, rigid, stiff) = (
            runs[0].closure,
            runs[1].closure,
            runs[2].closure,
            runs[3].closure,
        );
        assert!(deformable > 0.0 && rigid > 0.0, "{deformable} {rigid}");
        assert!(
            rigid < simple && simple < deformable,
            "{rigid} {simple} {deformable}"
        );
        assert!(
            rigid < stiff && stiff < deformable,
            "{rigid} < {stiff} < {deformable}"
        );
        assert!(
            stiff - rigid < 0.5 * (deformable - rigid),
            "{rigid} {stiff} {deformable}"
        );
        assert_eq!(runs[2].zones, 0);
        // Deformable blocks where the stress varies most (within 12 m of the tunnel), simple ones
        // beyond: within 15 % of the closure with under half the zones.
        let m = &runs[4];
        assert!(m.zones * 2 < runs[0].zones, "{m:?}");
        assert!((m.closure - deformable).abs() < 0.15 * deformable, "{m:?}");
    }
}
