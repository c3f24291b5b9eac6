//! Validation of adit against closed forms: each case runs the engine, measures its error against
//! the exact solution and its cost, and is run in full by the report binary and coarsely by tests.

pub mod axisymmetric;
pub mod bundled;
pub mod carranza_torres;
pub mod case;
pub mod cases;
pub mod column_slide;
pub mod corners;
pub mod direct_shear;
pub mod drop;
pub mod energy;
pub mod equivalent;
pub mod far_field;
pub mod flow_network;
pub mod flutter;
pub mod free_field;
pub mod glued;
pub mod grains;
pub mod gravity;
pub mod impact;
pub mod incline;
pub mod inclusion;
pub mod incompressible;
pub mod joint_waves;
pub mod kirsch;
pub mod kirsch_case;
pub mod lamb;
pub mod lined;
pub mod miller;
pub mod modes;
pub mod newmark;
pub mod oblique;
pub mod pao_mow;
pub mod patch;
pub mod peer;
pub mod plot;
pub mod pullout;
pub mod quiet;
pub mod random_scenes;
pub mod rayleigh;
pub mod readme;
pub mod realizations;
pub mod recovery;
pub mod render;
pub mod report;
pub mod rotation;
pub mod salencon;
pub mod scale;
pub mod scaling;
pub mod slivers;
pub mod slope;
pub mod softening;
pub mod stiff_joints;
pub mod strength_reduction;
pub mod triaxial;
pub mod unstable;

use std::path::PathBuf;

use adit::model::Model;
use adit::scene::SolveSpec;
use adit::solve::{Quiet, Solver, Status};

/// The repository root (models, docs and target live there).
pub fn repository_root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// A folder of its own under `target/validation/` for one run named `name`: the same case run by
/// two tests at once (the Lamé cylinder's explicit run, in two tests) wrote into one folder, and
/// one of them lost a file the other replaced.
pub fn run_folder(name: &str) -> PathBuf {
    static RUNS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let run = RUNS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    repository_root().join(format!(
        "target/validation/{name}_{}_{run}",
        std::process::id()
    ))
}

/// The Kirsch scene as shipped in `models/kirsch.json`.
pub fn shipped_kirsch() -> anyhow::Result<adit::Scene> {
    Ok(adit::Scene::load(
        &repository_root().join("models/kirsch.json"),
    )?)
}

/// Constrained (P-wave) modulus M = K + 4G/3 = E(1 − ν)/((1 + ν)(1 − 2ν)), Pa, of Young's modulus
/// `young` (Pa) and Poisson's ratio `poisson`: the stiffness of uniaxial strain.
pub fn constrained_modulus(young: f64, poisson: f64) -> f64 {
    young * (1.0 - poisson) / ((1.0 + poisson) * (1.0 - 2.0 * poisson))
}

/// Solve `model` statically to the ratio of `spec`; an error naming `what` unless it converges.
/// Returns the solver (masses and step set up) and the cycles taken.
pub fn settle(model: &mut Model, spec: &SolveSpec, what: &str) -> anyhow::Result<(Solver, u64)> {
    let mut solver = Solver::new(model, spec, 0);
    let sol = solver.solve(model, &mut Quiet);
    anyhow::ensure!(
        sol.status == Status::Converged,
        "{what} did not converge: {:?}",
        sol.status
    );
    Ok((solver, sol.cycles))
}

/// Solve `model` statically by the method `spec` names (`solve.method`: `implicit`, else explicit
/// cycling, `auto` included: the report's cases were written to measure explicit cycling where
/// they name no path, and name `implicit` where they measure it; the README's models table
/// measures the path `adit run` takes, [`as_adit_runs`]), to its ratio, from a fresh solver;
/// returns the solver (masses, step and timings), the solution and, when the implicit solve
/// ran, its cost.
pub fn solve_by_method(
    model: &mut Model,
    spec: &SolveSpec,
) -> (Solver, adit::solve::Solution, Option<adit::implicit::Cost>) {
    let mut solver = Solver::new(model, spec, 0);
    let (solution, cost) = if spec.method == adit::scene::SolveMethod::Implicit {
        let adit::implicit::Solved { solution, cost, .. } =
            adit::implicit::solve(model, &mut solver.cycle, &solver.params, spec, &mut Quiet);
        (solution, Some(cost))
    } else {
        (solver.solve(model, &mut Quiet), None)
    };
    (solver, solution, cost)
}

/// The scene as `adit run` solves it: `auto` (the default method) set to the path the engine
/// takes on its model (`adit::implicit::method`: implicit for a static solve the implicit path
/// can take, else explicit). The engine would hand an implicit stage that does not converge
/// over to explicit cycling; a bundled model's implicit solve converges, and a case that
/// solves it fails if it does not.
pub fn as_adit_runs(scene: &adit::Scene) -> anyhow::Result<adit::Scene> {
    use adit::implicit::Method;
    use adit::scene::SolveMethod;
    let mut s = scene.clone();
    if s.solve.method == SolveMethod::Auto {
        let built = adit::setup::setup(scene)?;
        let scheme = adit::cycle::ZoneScheme::of(&built.model, s.solve.large_strain);
        let joints = &built.model.materials.joint;
        s.solve.method = match adit::implicit::method(s.solve.method, s.solve.mode, scheme, joints)
        {
            Ok(Method::Implicit) => SolveMethod::Implicit,
            _ => SolveMethod::Explicit,
        };
    }
    Ok(s)
}

/// Fix `nodes` along `axis` (0: x, 1: y) and drive them at `velocity` (m a cycle, signed; Δt = 1
/// in the mass-scaled static mode) in a displacement-controlled test solved by `method`, sampled
/// every `chunk` cycles: explicitly as their velocity, implicitly as the returned drive of
/// `velocity` × `chunk` a sample (`drive_sample`).
pub fn drive_nodes(
    model: &mut Model,
    nodes: &[u32],
    axis: usize,
    velocity: f64,
    chunk: u64,
    method: adit::scene::SolveMethod,
) -> Vec<adit::implicit::Drive> {
    let explicit = method == adit::scene::SolveMethod::Explicit;
    let flag = [adit::model::FIX_X, adit::model::FIX_Y][axis];
    let mut step = [0.0; 2];
    step[axis] = velocity * chunk as f64;
    for &n in nodes {
        model.nodes.fixed[n as usize] |= flag;
        model.nodes.vel[n as usize][axis] = if explicit { velocity } else { 0.0 };
    }
    nodes.iter().map(|&n| (n, step)).collect()
}

/// One sample of a displacement-controlled test solved by `spec.method`: explicitly `solver`
/// cycles on (the driven nodes' velocities move them), implicitly one static solve with the nodes
/// moved by `drive` (`implicit::solve_driven`, reusing the symbolic analysis in `analysis`), its
/// cost added to `cost`. Err: the status, when the explicit cycles failed or the implicit solve
/// did not converge.
pub fn drive_sample(
    model: &mut Model,
    solver: &mut Solver,
    spec: &SolveSpec,
    drive: &[adit::implicit::Drive],
    analysis: &mut adit::implicit::Analysis,
    cost: &mut Option<adit::implicit::Cost>,
) -> Result<adit::solve::Solution, Status> {
    if spec.method == adit::scene::SolveMethod::Explicit {
        let sol = solver.solve(model, &mut Quiet);
        return match sol.status {
            Status::Failed(_) => Err(sol.status),
            _ => Ok(sol),
        };
    }
    let adit::implicit::Solved {
        solution, cost: c, ..
    } = adit::implicit::solve_driven(
        model,
        &mut solver.cycle,
        &solver.params,
        spec,
        drive,
        analysis,
        &mut Quiet,
    );
    *cost = Some(cost.map_or(c, |a| a.plus(c)));
    match solution.status {
        Status::Converged => Ok(solution),
        _ => Err(solution.status),
    }
}

/// [`solve_by_method`], failing with `what` named unless it converged; returns the cycles (or
/// iterations) and, when the implicit solve ran, its cost.
pub fn settle_by_method(
    model: &mut Model,
    spec: &SolveSpec,
    what: &str,
) -> anyhow::Result<(u64, Option<adit::implicit::Cost>)> {
    let (_, cycles, cost) = settle_keeping_solver(model, spec, what)?;
    Ok((cycles, cost))
}

/// [`settle_by_method`], also returning the solver, for a test that drives the settled model on
/// (`drive_nodes`, `drive_sample`).
pub fn settle_keeping_solver(
    model: &mut Model,
    spec: &SolveSpec,
    what: &str,
) -> anyhow::Result<(Solver, u64, Option<adit::implicit::Cost>)> {
    let (solver, sol, cost) = solve_by_method(model, spec);
    anyhow::ensure!(
        sol.status == Status::Converged,
        "{what} did not converge: {:?}",
        sol.status
    );
    Ok((solver, sol.cycles, cost))
}

/// Release the out-of-balance force of the solve `spec` gradually, as its method can: over
/// `release` cycles explicitly (`solve.ramp`, the cycle limit raised by as many; 0: at once), in `release` load
/// steps implicitly (`solve.load_steps`; 0 or 1: at once).
pub fn release_gradually(spec: &mut SolveSpec, release: u64) {
    if spec.method == adit::scene::SolveMethod::Explicit {
        spec.ramp = release;
        spec.max_cycles += release;
    } else {
        spec.load_steps = release.max(1);
    }
}

/// What a row's case name adds for the method that solved it: nothing for explicit (the names the
/// report always had), `, implicit` otherwise.
pub fn method_suffix(method: adit::scene::SolveMethod) -> String {
    match method {
        adit::scene::SolveMethod::Explicit => String::new(),
        _ => format!(", {}", method.name()),
    }
}

/// What a row's case name adds for its release (`release_gradually`): nothing at once,
/// `, over N cycles` explicitly, `, in N load steps` implicitly.
pub fn release_suffix(release: u64, method: adit::scene::SolveMethod) -> String {
    match (release, method) {
        (0, _) => String::new(),
        (n, adit::scene::SolveMethod::Explicit) => format!(", over {n} cycles"),
        (n, _) => format!(", in {n} load steps"),
    }
}

/// Radial displacement of each of `nodes` about the origin, m (outward positive).
pub fn radial_displacements<'a>(
    model: &'a Model,
    nodes: &'a [u32],
) -> impl Iterator<Item = f64> + 'a {
    nodes.iter().map(|&n| {
        let (p, u) = (model.nodes.pos[n as usize], model.nodes.disp[n as usize]);
        (u[0] * p[0] + u[1] * p[1]) / p[0].hypot(p[1])
    })
}

/// Mean radial displacement of `nodes` about the origin, m (outward positive).
pub fn mean_radial_displacement(model: &Model, nodes: &[u32]) -> f64 {
    radial_displacements(model, nodes).sum::<f64>() / nodes.len() as f64
}

/// Largest deviation of a zone's in-plane stress (`stresses`, Pa) from the uniform `target`
/// [σxx, σyy, σxy] (Pa), component by component, over `scale` (Pa).
pub fn uniform_stress_error(stresses: &[adit::model::Stress], target: [f64; 3], scale: f64) -> f64 {
    stresses
        .iter()
        .map(|s| {
            let d = [s[0] - target[0], s[1] - target[1], s[3] - target[2]];
            d.iter().fold(0.0f64, |m, x| m.max(x.abs())) / scale
        })
        .fold(0.0, f64::max)
}
