//! A whole run of a scene: build, solve, and write every output of the contract.

use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::checkpoint::{self, RunSoFar};
use crate::cycle::timestep::StepLimit;
use crate::cycle::{Cycle, ZoneScheme};
use crate::implicit::{self, Method};
use crate::model::Model;
use crate::model::bodies::BodyMode;
use crate::output::atomic::write_atomic;
use crate::output::histories::{Probes, Samples};
use crate::output::{FarFieldSummary, OutputWriter, StageSummary, Summary, measured};
use crate::scene::{OutputSpec, Scene};
use crate::scene::{SolveMethod, SolveMode};
use crate::setup::StagePlan;
use crate::setup::{Plan, Setup, setup};
use crate::solve::{HistoryRow, Observer, Quiet, Solution, Solver, Status, derive_masses};
use crate::stage::Staging;
use crate::strength_reduction::{self, FactorOfSafety, Searched};

/// The result of a run, with the model in its final state.
pub struct RunResult {
    pub built: Setup,
    pub solution: Solution,
    pub summary: Summary,
    pub out_dir: PathBuf,
}

/// Default output folder of a scene: `output.folder`, else `out/<name>`.
pub fn default_out_dir(scene: &Scene) -> PathBuf {
    scene
        .output
        .folder
        .as_ref()
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new("out").join(&scene.name))
}

/// A folder no earlier run wrote, for a run given no folder (Python's `adit.run`): the scene's
/// `output.folder` as given, else the first of `out/<name>`, `out/<name>-2`, `out/<name>-3`, …
/// that holds no `summary.json`; absolute.
pub fn fresh_out_dir(scene: &Scene) -> PathBuf {
    let dir = match &scene.output.folder {
        Some(folder) => PathBuf::from(folder),
        None => {
            let base = Path::new("out");
            let taken = |d: &Path| d.join("summary.json").exists();
            let mut dir = base.join(&scene.name);
            let mut k = 2;
            while taken(&dir) {
                dir = base.join(format!("{}-{k}", scene.name));
                k += 1;
            }
            dir
        }
    };
    std::path::absolute(&dir).unwrap_or(dir)
}

/// Forwards monitor rows to the caller and writes intermediate output steps; cycles count from
/// the start of the run (`offset`: cycles of the stages before this one).
struct Writing<'a> {
    writer: &'a mut OutputWriter,
    inner: &'a mut dyn Observer,
    output_seconds: f64,
    error: Option<anyhow::Error>,
    offset: u64,
    /// The monitoring points, their samples so far, and the cycle (from the start of the run)
    /// and time of the last monitor step.
    probes: &'a Probes,
    samples: &'a mut Samples,
    at: (u64, f64),
}

impl Observer for Writing<'_> {
    fn monitored(&mut self, row: &HistoryRow) {
        let row = HistoryRow {
            cycle: row.cycle + self.offset,
            ..*row
        };
        if let Err(e) = self.writer.append_history(&row) {
            self.error.get_or_insert(e.into());
        }
        self.at = (row.cycle, row.time);
        self.inner.monitored(&row);
    }
    fn sampled(&mut self, model: &Model) {
        self.inner.sampled(model);
        if self.probes.is_empty() {
            return;
        }
        let values = self.probes.sample(model);
        let (cycle, time) = self.at;
        let header = self.probes.header();
        if let Err(e) = self.writer.append_samples(header, cycle, time, &values) {
            self.error.get_or_insert(e.into());
        }
        self.samples.push(cycle, time, values);
    }
    fn factorized(&mut self, bytes: usize, seconds: f64) {
        self.inner.factorized(bytes, seconds);
    }
    fn stage_started(&mut self, name: &str, from: u64, max_cycles: u64) {
        self.inner.stage_started(name, from, max_cycles);
    }
    fn output_step(&mut self, cycle: u64, _time: f64, model: &Model, _c: &mut Cycle) {
        let t = Instant::now();
        if let Err(e) = self.writer.write_step(model, (cycle + self.offset) as f64) {
            self.error.get_or_insert(e);
        }
        self.output_seconds += t.elapsed().as_secs_f64();
    }
}

/// Why an `auto` stage's implicit solve hands over to explicit cycling: it ended at its
/// iteration limit or failed (a block nothing holds, or one still moving, or a factor that would
/// not fit) with the model in a `sound` state; `None` when it converged, was interrupted, the
/// monitor stopped it (a non-finite value, a runaway: the stage fails as it is), or the method
/// was asked for by name.
fn hand_over(asked: SolveMethod, solution: &Solution, sound: bool) -> Option<String> {
    if asked != SolveMethod::Auto || !sound {
        return None;
    }
    match &solution.status {
        Status::CycleLimit => Some(format!(
            "the implicit solve did not converge in {} iterations, ratio {:.2e}",
            solution.cycles, solution.final_ratio
        )),
        Status::Failed(reason) => Some(reason.clone()),
        Status::Converged | Status::Completed | Status::Interrupted => None,
    }
}

/// The solver of `stage`: its masses and time step, with intermediate output steps as `output`
/// times them for its mode (`OutputSpec::cycles_between`).
fn stage_solver(model: &mut Model, stage: &StagePlan, output: &OutputSpec) -> Solver {
    let mut solver = Solver::new(model, &stage.solve, 0);
    solver.output_every = output.cycles_between(&stage.solve, solver.params.dt);
    solver
}

/// A solve needs a finite time step: something with stiffness to derive it from.
pub fn ensure_time_step(solver: &Solver) -> anyhow::Result<()> {
    anyhow::ensure!(
        solver.params.dt.is_finite(),
        "solve: no zone or contact stiffness to derive the time step from (a lone rigid or simple \
         block without joints); make the block deformable or add joints"
    );
    Ok(())
}

/// Build and solve `scene`, writing results into `out_dir`. A failed solve still writes
/// `history.csv` and a `summary.json` with status `failed`, but no final zone grid. An
/// interruption asked for before the run (`interrupt::requested`) stops it at once: a caller that
/// runs again after a Ctrl-C clears it first (`interrupt::clear`), as the Python package does,
/// while a sweep's concurrent runs all stop on one. Each stage that ends leaves its checkpoint
/// (`checkpoint::path`) unless `output.checkpoints` is false.
pub fn run_scene(
    scene: &Scene,
    out_dir: &Path,
    observer: &mut dyn Observer,
) -> anyhow::Result<RunResult> {
    run_scene_from(scene, out_dir, 1, observer)
}

/// [`run_scene`] from stage `from` (numbered from 1): with `from` > 1, the run goes on from the
/// checkpoint stage `from − 1` left in `out_dir` (`adit run --from-stage`), keeping the earlier
/// stages' output steps and history, and gives the numbers of the run that was not stopped.
pub fn run_scene_from(
    scene: &Scene,
    out_dir: &Path,
    from: usize,
    observer: &mut dyn Observer,
) -> anyhow::Result<RunResult> {
    let start = Instant::now();
    let resumed = if from > 1 {
        Some(std::fs::read(checkpoint::path(out_dir, from - 1)).map_err(|e| {
            anyhow::anyhow!(
                "--from-stage {from}: no checkpoint of stage {} in {} ({e}); run the scene from \
                 the start first{}",
                from - 1,
                out_dir.display(),
                if scene.output.checkpoints {
                    ""
                } else {
                    " (its output.checkpoints is false: the run leaves none)"
                }
            )
        })?)
    } else {
        None
    };
    let mut writer = OutputWriter::for_run(out_dir, &scene.name, from)?;
    let result = build_solve_write(scene, &mut writer, observer, start, resumed.as_deref());
    if let Err(e) = &result {
        // The summary must not stay `running`; the error itself is the caller's to report.
        let _ = writer.write_status("failed", Some(&format!("{e:#}")));
    }
    result
}

/// Go on from `checkpoint`, a stage's checkpoint of this scene or of another whose stages up to
/// it are the same (UDEC's save and restore, branched: the same excavation bolted otherwise),
/// and run only the later stages, writing into `out_dir` what a whole run of `scene` writes: the
/// earlier output steps and checkpoints are copied from the checkpoint's run folder (renamed for
/// this scene) unless that is `out_dir`. Refused, naming the first field that differs, when an
/// earlier stage differs.
pub fn run_scene_branch(
    scene: &Scene,
    out_dir: &Path,
    checkpoint: &Path,
    observer: &mut dyn Observer,
) -> anyhow::Result<RunResult> {
    let field = |e: &dyn std::fmt::Display| anyhow::anyhow!("--from {}: {e}", checkpoint.display());
    let bytes = std::fs::read(checkpoint).map_err(|e| field(&e))?;
    let read = checkpoint::read(&bytes).map_err(|e| field(&e))?;
    read.same_stages_as(scene).map_err(|e| field(&e))?;
    let done = read.run.stages_done;
    let stages = scene.stages.len().max(1);
    if done >= stages {
        return Err(field(&format!(
            "the checkpoint is of stage {done}, the scene's last: there is nothing to go on with"
        )));
    }
    let source = checkpoint
        .parent()
        .and_then(Path::parent)
        .unwrap_or(Path::new("."));
    if !same_folder(source, out_dir) {
        copy_run_so_far(source, out_dir, &read, scene).map_err(|e| field(&e))?;
    }
    run_scene_from(scene, out_dir, done + 1, observer)
}

/// Whether `a` and `b` name the same folder (a folder that does not exist yet is no other's).
fn same_folder(a: &Path, b: &Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    }
}

/// Copy the output steps and the checkpoints up to `read`'s stage from the run folder `source`
/// into `out`, each file named for `scene`.
fn copy_run_so_far(
    source: &Path,
    out: &Path,
    read: &checkpoint::Read,
    scene: &Scene,
) -> anyhow::Result<()> {
    std::fs::create_dir_all(out.join("checkpoints"))?;
    for (_, _, files) in &read.run.steps {
        for f in files {
            let to = out.join(checkpoint::renamed(f, &scene.name));
            std::fs::copy(source.join(f), &to)
                .map_err(|e| anyhow::anyhow!("copying {}: {e}", source.join(f).display()))?;
        }
    }
    for stage in 1..=read.run.stages_done {
        let from = checkpoint::path(source, stage);
        if let Ok(bytes) = std::fs::read(&from) {
            let renamed = checkpoint::named(&bytes, &scene.name)
                .map_err(|e| anyhow::anyhow!("{}: {e}", from.display()))?;
            write_atomic(&checkpoint::path(out, stage), |w| w.write_all(&renamed))?;
        }
    }
    Ok(())
}

/// The path stage `i` of `plan` takes on `model`; an error naming the field when it asks the
/// implicit path of a model that path cannot solve. The model's feature it depends on (its zone
/// scheme) is set up once, so the answer holds from the start of the run.
fn stage_method(plan: &Plan, i: usize, model: &Model) -> anyhow::Result<Method> {
    let spec = &plan.stages[i].solve;
    let scheme = ZoneScheme::of(model, spec.large_strain);
    implicit::method(spec.method, spec.mode, scheme, &model.materials.joint).map_err(|reason| {
        let field = if plan.staged {
            format!("stages[{i}].solve.method (or the scene's solve.method)")
        } else {
            "solve.method".to_string()
        };
        anyhow::anyhow!(
            "{field}: implicit cannot solve this model: {reason}; use \"explicit\" or \"auto\""
        )
    })
}

/// What a run refuses once the model is built, before any solve (`adit check` and Python's
/// `adit.check` refuse it too): a stage asking the implicit path of a model it cannot solve, a
/// monitoring point with nothing to read. Returns the monitoring points found.
pub fn refuse_before_solving(scene: &Scene, plan: &Plan, model: &Model) -> anyhow::Result<Probes> {
    for i in 0..plan.stages.len() {
        stage_method(plan, i, model)?;
    }
    Probes::of(&scene.histories, model, &plan.fill)
}

/// The smallest critical step (real masses) over the stages solved or replayed, and its stage:
/// what `summary.json` and `adit check` report (supports a later stage installs, or rock it
/// removes, change the step).
#[derive(Default)]
pub struct SmallestStep(Option<(StepLimit, usize)>);

impl SmallestStep {
    /// Keep `step` of stage `i` if it is the smallest so far.
    pub fn tighten(&mut self, step: StepLimit, i: usize) {
        if self.0.is_none_or(|(s, _)| step.dt_critical < s.dt_critical) {
            self.0 = Some((step, i));
        }
    }

    /// The smallest step, else `solver`'s.
    fn step(&self, solver: &Solver) -> StepLimit {
        self.0.map_or(solver.step, |(s, _)| s)
    }

    /// The name of the stage that has the smallest step, in a staged plan.
    pub fn stage(&self, plan: &Plan) -> Option<String> {
        let (_, i) = self.0?;
        plan.staged.then(|| plan.stages[i].name.clone())
    }

    /// The step limit and stage of `scene`'s stages replayed on `built` without solving (the
    /// model is left at the last stage's start): `adit check`'s answer, the run's own up to the
    /// contacts its solves form.
    pub fn replayed(built: &mut Setup) -> SmallestStep {
        let Setup { model, plan, .. } = built;
        let mut smallest = SmallestStep::default();
        smallest.replay(&mut Staging::new(plan), plan.stages.len(), model, plan);
        smallest
    }

    /// Apply the first `stages` stages of `plan` to `model` without solving, each one's step
    /// limit tightening this.
    fn replay(&mut self, staging: &mut Staging, stages: usize, model: &mut Model, plan: &Plan) {
        for (i, stage) in plan.stages[..stages].iter().enumerate() {
            staging.apply(stage, model, plan);
            self.tighten(derive_masses(model, &stage.solve).1, i);
        }
    }

    /// `4.870e-6 s (supports, stage 'bolts')`.
    pub fn describe(&self, plan: &Plan) -> String {
        match self.0 {
            Some((s, _)) => match self.stage(plan) {
                Some(name) => format!("{:.3e} s ({}, stage '{name}')", s.dt_critical, s.describe()),
                None => format!("{:.3e} s ({})", s.dt_critical, s.describe()),
            },
            None => "none (no stage)".to_string(),
        }
    }
}

/// Validate and build `scene` as a run does and refuse what the run would refuse, without
/// solving: `adit check`'s and Python's `adit.check`'s verdict.
pub fn check_scene(scene: &Scene) -> anyhow::Result<Setup> {
    let built = setup(scene)?;
    refuse_before_solving(scene, &built.plan, &built.model)?;
    Ok(built)
}

/// What a stage's factor-of-safety search left: the factor, the mechanism's state, whether a
/// signal stopped it.
#[derive(Default)]
struct StageFos {
    found: Option<FactorOfSafety>,
    mechanism: Option<Vec<u8>>,
    interrupted: bool,
}

/// Search the factor of safety `stage` asks for (none when it asks none or its solve failed),
/// each trial solved without output along the stage's path: implicitly (`implicit`: its
/// non-convergence the criterion; `auto`: a trial whose iterations do not converge is handed over
/// to explicit cycling from where they left it, as an `auto` stage is) or by explicit cycling.
fn stage_factor_of_safety(
    model: &mut Model,
    stage: &StagePlan,
    method: &Method,
    solution: &Solution,
    analysis: &mut implicit::Analysis,
) -> anyhow::Result<StageFos> {
    let Some(spec) = &stage.factor_of_safety else {
        return Ok(StageFos::default());
    };
    if !matches!(solution.status, Status::Converged | Status::CycleLimit) {
        return Ok(StageFos::default());
    }
    let solve_spec = &stage.solve;
    let cycle_explicitly = |model: &mut Model| {
        let mut solver = Solver::new(model, solve_spec, 0);
        let solution = solver.solve(model, &mut Quiet);
        let moving = (solution.status == Status::Converged)
            .then(|| {
                let dt = solver.params.dt;
                crate::cycle::drift::still_moving(model, solution.cycles, dt)
            })
            .flatten();
        (solution, moving)
    };
    let solve = |model: &mut Model| match method {
        Method::Implicit => {
            let mut solver = Solver::new(model, solve_spec, 0);
            let (cycle, params) = (&mut solver.cycle, &solver.params);
            let solved =
                implicit::solve_driven(model, cycle, params, solve_spec, &[], analysis, &mut Quiet);
            match hand_over(solve_spec.method, &solved.solution, solved.sound) {
                Some(_) => {
                    let (rest, moving) = cycle_explicitly(model);
                    (solved.solution.then(rest), moving)
                }
                None => (solved.solution, solved.moving),
            }
        }
        _ => cycle_explicitly(model),
    };
    let stable_at_one = solution.status == Status::Converged;
    Ok(
        match strength_reduction::search(model, spec, stable_at_one, solve)? {
            Searched::Found(found, mechanism) => StageFos {
                found: Some(found),
                mechanism,
                interrupted: false,
            },
            Searched::Interrupted => StageFos {
                interrupted: true,
                ..StageFos::default()
            },
        },
    )
}

/// Write the mechanism at the smallest unstable factor (`mechanism`, a saved state) as an output
/// step, its displacements measured from the stage's equilibrium, and put the equilibrium back.
fn write_mechanism(
    model: &mut Model,
    writer: &mut OutputWriter,
    mechanism: &[u8],
    time: f64,
) -> anyhow::Result<()> {
    let mut equilibrium = Vec::new();
    checkpoint::state::save(model, &mut equilibrium);
    let at_rest = model.nodes.disp.clone();
    strength_reduction::restore(model, mechanism)?;
    model.nodes.origin = at_rest;
    writer.write_step(model, time)?;
    strength_reduction::restore(model, &equilibrium)
}

/// [`run_scene`] once its folder is open.
fn build_solve_write(
    scene: &Scene,
    writer: &mut OutputWriter,
    observer: &mut dyn Observer,
    start: Instant,
    resumed: Option<&[u8]>,
) -> anyhow::Result<RunResult> {
    let mut built = setup(scene)?;
    let Setup { model, plan, .. } = &mut built;
    let mut staging = Staging::new(plan);
    let mut seconds = crate::cycle::StageSeconds::default();
    let mut output_seconds = 0.0;
    let mut last: Option<(Solver, Solution, usize)> = None;
    let mut smallest = SmallestStep::default();
    let probes = refuse_before_solving(scene, plan, model)?;
    // Going on from a checkpoint: the stages before replayed (what the state does not hold),
    // then the state put in.
    let so_far = match resumed {
        Some(bytes) => {
            let first = writer.first_stage();
            anyhow::ensure!(
                first < plan.stages.len(),
                "--from-stage {}: the scene has {} stage(s)",
                first + 1,
                plan.stages.len()
            );
            smallest.replay(&mut staging, first, model, plan);
            let run = checkpoint::decode(bytes, scene, model)
                .map_err(|e| anyhow::anyhow!("--from-stage {}: {e}", first + 1))?;
            anyhow::ensure!(
                run.stages_done == first,
                "--from-stage {}: the checkpoint is of stage {}",
                first + 1,
                run.stages_done
            );
            writer.resume(&run.steps, &run.history)?;
            for k in 0..run.samples.len() {
                let s = &run.samples;
                writer.append_samples(probes.header(), s.cycle[k], s.time[k], &s.values[k])?;
            }
            run
        }
        None => RunSoFar::default(),
    };
    let RunSoFar {
        mut history,
        mut samples,
        mut cycles,
        summaries: mut stage_summaries,
        mut methods,
        implicit: mut implicit_cost,
        ..
    } = so_far;
    // The last factorization, whose symbolic analysis a later stage reuses while the stiffness
    // keeps its pattern.
    let mut analysis = implicit::Analysis::default();
    let first = writer.first_stage();
    for (i, stage) in plan.stages.iter().enumerate().skip(first) {
        staging.apply(stage, model, plan);
        writer.set_stage(i, &stage.name);
        let mut solver = stage_solver(model, stage, &scene.output);
        ensure_time_step(&solver)?;
        smallest.tighten(solver.step, i);
        let spec = &stage.solve;
        let method = stage_method(plan, i, model)?;
        let mut writing = Writing {
            writer,
            inner: observer,
            output_seconds: 0.0,
            error: None,
            offset: cycles,
            probes: &probes,
            samples: &mut samples,
            at: (cycles, 0.0),
        };
        let shown = if plan.staged { stage.name.as_str() } else { "" };
        writing.stage_started(shown, cycles, spec.max_cycles);
        let (mut handed_over, mut implicit_moving) = (None, None);
        let solution = match method {
            Method::Implicit => {
                let implicit::Solved {
                    solution,
                    cost,
                    sound,
                    moving,
                } = implicit::solve_driven(
                    model,
                    &mut solver.cycle,
                    &solver.params,
                    spec,
                    &[],
                    &mut analysis,
                    &mut writing,
                );
                seconds.implicit += cost.seconds();
                implicit_cost = Some(implicit_cost.map_or(cost, |c| c.plus(cost)));
                implicit_moving = moving;
                match hand_over(spec.method, &solution, sound) {
                    // `auto`: what the iterations could not settle, explicit cycling relaxes from
                    // where they left the model.
                    Some(reason) => {
                        solver = stage_solver(model, stage, &scene.output);
                        ensure_time_step(&solver)?;
                        writing.offset += solution.cycles;
                        let rest = solver.solve(model, &mut writing);
                        handed_over = Some(reason);
                        solution.then(rest)
                    }
                    None => solution,
                }
            }
            _ => solver.solve(model, &mut writing),
        };
        if spec.method != SolveMethod::Explicit {
            methods.push(match &method {
                Method::Implicit => match &handed_over {
                    Some(reason) => format!("implicit, then explicit ({reason})"),
                    None => "implicit".to_string(),
                },
                Method::Fallback(reason) => format!("explicit ({reason})"),
                Method::Explicit => "explicit".to_string(),
            });
        }
        output_seconds += writing.output_seconds;
        if let Some(e) = writing.error {
            return Err(e);
        }
        let fos = stage_factor_of_safety(model, stage, &method, &solution, &mut analysis)?;
        history.extend(solution.history.iter().map(|r| HistoryRow {
            cycle: r.cycle + cycles,
            ..*r
        }));
        cycles += solution.cycles;
        let s = solver.cycle.seconds();
        seconds.detect += s.detect;
        seconds.contacts += s.contacts;
        seconds.zones += s.zones;
        seconds.supports += s.supports;
        seconds.motion += s.motion;
        seconds.dynamics += s.dynamics;
        stage_summaries.push(StageSummary {
            name: stage.name.clone(),
            cycles: solution.cycles,
            status: solution.status.label().to_string(),
            final_ratio: measured(solution.final_ratio),
            support_fraction: staging.support_fraction(),
            closure: staging.closures(model, plan),
            walls: staging.wall_moves(model, plan),
            factor_of_safety: fos.found,
            moving: match (&solution.status, spec.mode) {
                (Status::Converged, SolveMode::Static) => {
                    crate::cycle::drift::still_moving(model, solution.cycles, solver.params.dt)
                }
                // Explicit cycling ran last: its velocities say what moves.
                (Status::CycleLimit, _) if method != Method::Implicit || handed_over.is_some() => {
                    let (cycles, dt) = (solution.cycles, solver.params.dt);
                    crate::cycle::drift::fastest_at_limit(model, cycles, dt)
                }
                (Status::CycleLimit, _) => implicit_moving,
                _ => None,
            },
        });
        let t = Instant::now();
        let failed = matches!(solution.status, Status::Failed(_));
        let interrupted = solution.status == Status::Interrupted || fos.interrupted;
        if !failed {
            writer.write_step(model, cycles as f64)?;
        }
        if let Some(mechanism) = &fos.mechanism {
            write_mechanism(model, writer, mechanism, cycles as f64)?;
        }
        if !failed && !interrupted && scene.output.checkpoints {
            let run = RunSoFar {
                stages_done: i + 1,
                cycles,
                history: history.clone(),
                samples: samples.clone(),
                summaries: stage_summaries.clone(),
                methods: methods.clone(),
                implicit: implicit_cost,
                steps: writer.steps(),
            };
            let bytes = checkpoint::encode(scene, &run, model);
            let path = checkpoint::path(&writer.dir, i + 1);
            std::fs::create_dir_all(path.parent().expect("a checkpoint has a folder"))?;
            write_atomic(&path, |w| w.write_all(&bytes))?;
        }
        output_seconds += t.elapsed().as_secs_f64();
        last = Some((solver, solution, i));
        if failed || interrupted {
            break;
        }
    }
    let Some((solver, last_solution, last_stage)) = last else {
        anyhow::bail!("stages: the plan has no stage to solve");
    };
    let critical = smallest.step(&solver);
    let critical_stage = smallest.stage(plan);
    // A failed stage's state may not be finite: its reactions are not reported.
    let reactions = match last_solution.status {
        Status::Failed(_) => Vec::new(),
        _ => crate::output::reactions::reactions(scene, plan, model, &solver.cycle, last_stage)?,
    };
    let solution = Solution {
        status: last_solution.status,
        cycles,
        history,
        final_ratio: last_solution.final_ratio,
    };
    let t = Instant::now();
    writer.write_history(&solution.history)?;
    if !probes.is_empty() {
        writer.write_histories(probes.header(), &samples)?;
    }
    if plan.staged {
        writer.write_ground_reaction(&stage_summaries, &plan.excavations)?;
    }
    let excavations: &[String] = if plan.staged { &plan.excavations } else { &[] };
    let mut plot_warnings = crate::output::plots::write_plots(
        &writer.dir,
        &solution.history,
        &stage_summaries,
        excavations,
        model,
    );
    if !crate::interrupt::requested() {
        let ends = crate::output::plots::stage_ends(&stage_summaries);
        let columns = probes.columns();
        let drawn = crate::output::histories_plot::write(&writer.dir, columns, &samples, &ends);
        plot_warnings.extend(drawn);
    }
    output_seconds += t.elapsed().as_secs_f64();
    seconds.output = output_seconds;
    let wall = start.elapsed().as_secs_f64();
    let cycling =
        seconds.detect + seconds.contacts + seconds.zones + seconds.motion + seconds.dynamics;
    let zones = built.model.zones.len();
    let per_second = |items: usize| {
        if cycling > 0.0 {
            items as f64 * solution.cycles as f64 / cycling
        } else {
            0.0
        }
    };
    let count = |mode| {
        built
            .model
            .bodies
            .mode
            .iter()
            .filter(|&&m| m == mode)
            .count()
    };
    let liners = built.model.supports.liners.liner_loads();
    let summary = Summary {
        scene: scene.name.clone(),
        zones,
        nodes: built.model.nodes.len(),
        blocks: built.model.blocks.len(),
        rigid_blocks: count(BodyMode::Rigid),
        simple_blocks: count(BodyMode::Simple),
        contacts: built.model.contacts.len(),
        cycles: solution.cycles,
        wall_seconds: wall,
        stage_seconds: seconds,
        zone_cycles_per_second: per_second(zones),
        block_cycles_per_second: per_second(built.model.blocks.len()),
        final_ratio: measured(solution.final_ratio),
        status: solution.status.label().to_string(),
        reason: match &solution.status {
            Status::Failed(r) => Some(r.clone()),
            _ => None,
        },
        timestep: solver.params.dt,
        critical_timestep: critical.dt_critical,
        critical_node: critical.limiting_node.0,
        critical_block: critical.limiting_block,
        critical_limiter: critical.describe(),
        critical_stage,
        min_zone_angle: built.mesh.min_angle_deg,
        warnings: [
            built.warnings.clone(),
            moving_warnings(&stage_summaries, built.plan.staged),
            inverted_warnings(&stage_summaries, built.plan.staged),
            over_capacity_warnings(&liners),
            plot_warnings,
        ]
        .concat(),
        stages: if built.plan.staged {
            stage_summaries
        } else {
            vec![]
        },
        methods,
        implicit: implicit_cost,
        reactions,
        bolts: built.model.supports.cables.bolt_loads(),
        liners,
        peak_particle_velocity: crate::output::PeakVelocity::of(&built.model),
        ejection: (built.model.ejection.as_ref())
            .map_or_else(Vec::new, |e| e.report(&built.plan.excavations)),
        far_field: built.model.far_field.as_ref().map(FarFieldSummary::of),
    };
    writer.write_summary(&summary)?;
    Ok(RunResult {
        built,
        solution,
        summary,
        out_dir: writer.dir.clone(),
    })
}

/// A warning for each liner with an element over its capacity (factor of safety below 1).
fn over_capacity_warnings(liners: &[crate::support::LinerLoad]) -> Vec<String> {
    (liners.iter())
        .filter_map(|l| {
            let (fs, at, over) = (l.factor_of_safety?, l.at?, l.over_capacity?);
            (over > 0).then(|| {
                format!(
                    "liner '{}': {over} of {} elements over capacity (least factor of safety \
                     {fs:.2}, at ({:.2}, {:.2}) m): see liner_capacity.png",
                    l.liner, l.elements, at[0], at[1]
                )
            })
        })
        .collect()
}

/// The stages' factors of safety whose trial turned zones inside out
/// (`FactorOfSafety::inverted_warning`), each named by its stage in a `staged` run.
fn inverted_warnings(stages: &[StageSummary], staged: bool) -> Vec<String> {
    (stages.iter())
        .filter_map(|s| {
            let warning = s.factor_of_safety.as_ref()?.inverted_warning()?;
            Some(of_stage(s, staged, warning))
        })
        .collect()
}

/// The stages' blocks still moving at convergence or at a cycle limit (`cycle::drift`) as
/// warnings, each named by its stage in a `staged` run.
fn moving_warnings(stages: &[StageSummary], staged: bool) -> Vec<String> {
    (stages.iter())
        .filter_map(|s| Some(of_stage(s, staged, s.moving.clone()?)))
        .collect()
}

/// A stage's `warning`, named by its stage in a `staged` run.
fn of_stage(stage: &StageSummary, staged: bool, warning: String) -> String {
    if staged {
        format!("stage '{}': {warning}", stage.name)
    } else {
        warning
    }
}
