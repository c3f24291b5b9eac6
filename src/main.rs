//! The `adit` command: run, check or mesh a scene file.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use std::io::Write;

use adit::Scene;
use adit::output::OutputWriter;
use adit::run::{SmallestStep, default_out_dir};
use adit::setup::{mesh, setup, setup_meshed};
use adit::solve::{HistoryRow, Observer, Status};
use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};

/// `println!` that returns the write's error instead of panicking (a reader that closed its pipe).
macro_rules! say {
    ($($t:tt)*) => {
        writeln!(std::io::stdout(), $($t)*)
    };
}

#[derive(Parser)]
#[command(
    name = "adit",
    version,
    about = "2D distinct element engine for jointed rock"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Solve a scene and write results (.pvd/.vtu, history.csv, summary.json).
    Run {
        scene: PathBuf,
        /// Output folder (default: the scene's output.folder, else out/<name>).
        #[arg(long)]
        out: Option<PathBuf>,
        /// No progress bar.
        #[arg(long)]
        quiet: bool,
        /// Go on from stage N (numbered from 1) with the checkpoint stage N − 1 left in the output
        /// folder: the numbers of the run that was not stopped.
        #[arg(long, value_name = "N", default_value_t = 1)]
        from_stage: usize,
        /// Go on from a stage's checkpoint (`<out>/checkpoints/stage_NN.ckpt`) of this scene or
        /// of another whose stages up to it are the same, and run only the later stages (another
        /// bolt pattern, liner or strength): the files of a whole run of this scene.
        #[arg(long, value_name = "CHECKPOINT", conflicts_with = "from_stage")]
        from: Option<PathBuf>,
    },
    /// Validate a scene and print mesh statistics, without solving.
    Check { scene: PathBuf },
    /// Mesh a scene and write the zones with their initial stress, without solving.
    Mesh {
        scene: PathBuf,
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Run a sweep: a base scene over a grid or random draws of parameters and joint
    /// realizations, each run independent, gathered into sweep.csv and sweep.png. Runs already
    /// done are skipped, so a sweep interrupted and started again runs only what is missing.
    Sweep {
        spec: PathBuf,
        /// Output folder (default: the spec's out, else out/<name>).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Runs at once (default: the machine's cores).
        #[arg(long)]
        workers: Option<usize>,
        /// A Dask scheduler's address: the runs go to its cluster, through the Python package
        /// (`python3 -m adit.sweep`, or the Python that ADIT_PYTHON names), which must be
        /// installed.
        #[arg(long)]
        scheduler: Option<String>,
    },
    /// One run of a sweep, in a process of its own (what `adit sweep` starts for each run); it
    /// stops, leaving no row, when its standard input closes (the sweep has ended).
    #[command(hide = true)]
    SweepRun {
        /// The base scene, a JSON file.
        base: PathBuf,
        id: String,
        /// The run's parameters, a JSON object of dotted paths.
        params: String,
        out: PathBuf,
    },
}

/// Progress bar over the current stage's cycles (or implicit iterations) against its own limit,
/// showing the stage's name, the unbalanced-force ratio and the last factorization's size and
/// time when the solve is implicit.
struct Progress {
    bar: ProgressBar,
    /// The factorization's note, the stage's name and the cycle it started at.
    factor: String,
    stage: String,
    from: u64,
}

/// The bar's message: the stage (staged runs), the ratio and the factorization's note.
fn progress_message(stage: &str, ratio: f64, factor: &str) -> String {
    let stage = if stage.is_empty() {
        String::new()
    } else {
        format!("stage '{stage}', ")
    };
    format!("{stage}ratio {ratio:.2e}{factor}")
}

impl Observer for Progress {
    fn monitored(&mut self, row: &HistoryRow) {
        self.bar.set_position(row.cycle.saturating_sub(self.from));
        self.bar
            .set_message(progress_message(&self.stage, row.ratio, &self.factor));
    }
    fn factorized(&mut self, bytes: usize, seconds: f64) {
        self.factor = format!(", factor {:.1} MB in {seconds:.3} s", bytes as f64 / 1e6);
    }
    fn stage_started(&mut self, name: &str, from: u64, max_cycles: u64) {
        (self.stage, self.from) = (name.to_string(), from);
        self.bar.set_length(max_cycles);
        self.bar.set_position(0);
    }
}

fn load(path: &Path) -> anyhow::Result<Scene> {
    Ok(Scene::load(path)?)
}

/// Where a run starts: at a stage (1: the beginning), or from a checkpoint (`--from`).
enum Start {
    Stage(usize),
    Checkpoint(PathBuf),
}

fn run(
    scene_path: &Path,
    out: Option<PathBuf>,
    quiet: bool,
    start: Start,
) -> anyhow::Result<ExitCode> {
    let scene = load(scene_path)?;
    let given = out.is_some();
    let out = out.unwrap_or_else(|| default_out_dir(&scene));
    if !given && matches!(start, Start::Stage(1)) && out.join("summary.json").exists() {
        eprintln!(
            "note: {} holds an earlier run; this run replaces it (--out DIR keeps both)",
            out.display()
        );
    }
    let bar = if quiet {
        ProgressBar::hidden()
    } else {
        ProgressBar::new(scene.solve.max_cycles)
    };
    bar.set_style(
        ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {pos}/{len} cycles, {msg}")?
            .progress_chars("=> "),
    );
    let mut progress = Progress {
        bar,
        factor: String::new(),
        stage: String::new(),
        from: 0,
    };
    let result = match start {
        Start::Stage(from_stage) => {
            anyhow::ensure!(from_stage >= 1, "--from-stage: stages are numbered from 1");
            adit::run_scene_from(&scene, &out, from_stage, &mut progress)?
        }
        Start::Checkpoint(path) => adit::run_scene_branch(&scene, &out, &path, &mut progress)?,
    };
    progress.bar.finish_and_clear();
    let s = &result.summary;
    for w in &s.warnings {
        eprintln!("warning: {w}");
    }
    say!(
        "scene {}: {} blocks ({} rigid, {} simple), {} zones, {} nodes, min angle {:.1}°{}",
        s.scene,
        s.blocks,
        s.rigid_blocks,
        s.simple_blocks,
        s.zones,
        s.nodes,
        s.min_zone_angle,
        if adit::setup::sharper_than(s.min_zone_angle, scene.zoning.min_angle) {
            format!(
                " (zoning.min_angle = {}° holds but where joints or walls meet at a sharper \
                 corner: `adit check` says where)",
                scene.zoning.min_angle
            )
        } else {
            String::new()
        }
    )?;
    say!(
        "time step: critical {:.3e} s ({}{}), used {:.3e} s{}",
        s.critical_timestep,
        s.critical_limiter,
        s.critical_stage
            .as_ref()
            .map_or(String::new(), |st| format!(", stage '{st}'")),
        s.timestep,
        if scene.solve.mode == adit::scene::SolveMode::Static {
            " on scaled masses (static: each node's mass is set from its stiffness so that 1 s is \
             stable, FLAC's mass scaling; the critical step prices a dynamic run)"
        } else {
            ""
        }
    )?;
    say!(
        "{} after {} cycles, ratio {}, {:.2} s wall, {:.3e} zone-cycles/s, {:.3e} block-cycles/s",
        s.status,
        s.cycles,
        s.final_ratio
            .map_or("not measured".to_string(), |r| format!("{r:.2e}")),
        s.wall_seconds,
        s.zone_cycles_per_second,
        s.block_cycles_per_second
    )?;
    if let Some(c) = &s.implicit {
        say!(
            "implicit: {} unknowns, factor of {} non-zeros ({:.1} MB), {} factorization(s), {} \
             iteration(s){}; {:.3} s assembling, {:.3} s factorizing, {:.3} s iterating (cycles \
             above count explicit cycles and implicit iterations together)",
            c.unknowns,
            c.factor_nonzeros,
            c.factor_nonzeros as f64 * 8e-6,
            c.factorizations,
            c.iterations,
            match c.cuts {
                0 => String::new(),
                n => format!(", {n} load step(s) halved"),
            },
            c.assemble_s,
            c.factorize_s,
            c.iterate_s
        )?;
    }
    let sup = &result.built.model.supports;
    if !sup.is_empty() {
        let loads = sup.loads();
        say!(
            "supports: {} bolt segments (largest force {:.1} kN/m, {} at yield), {} liner elements \
             (largest thrust {:.2} MN/m)",
            sup.cables.segment.len(),
            loads.bolt_force / 1e3,
            loads.bolts_yielded,
            sup.liners.element.len(),
            loads.liner_thrust / 1e6
        )?;
        for l in &s.liners {
            let capacity = match (l.factor_of_safety, l.at, l.over_capacity) {
                (Some(fs), Some(at), Some(over)) => format!(
                    "; least factor of safety {fs:.2} at ({:.2}, {:.2}) m, {over} of {} elements \
                     over capacity",
                    at[0], at[1], l.elements
                ),
                _ => String::new(),
            };
            say!(
                "liner '{}': largest thrust {:.2} MN, moment {:.1} kN·m, shear {:.1} kN per set{capacity}",
                l.liner,
                l.thrust_n / 1e6,
                l.moment_n_m / 1e3,
                l.shear_n / 1e3
            )?;
        }
        let most_used = (s.bolts.iter()).max_by(|a, b| a.utilization.total_cmp(&b.utilization));
        if let Some(b) = most_used {
            say!(
                "bolts: the most used, of '{}' at ({:.2}, {:.2}) m, carries {:.1} kN of its {:.1} kN \
                 capacity ({:.0} %); {} of {} bolts at yield",
                b.group,
                b.head[0],
                b.head[1],
                b.force_n / 1e3,
                b.capacity_n / 1e3,
                100.0 * b.utilization,
                s.bolts.iter().filter(|b| b.yielded).count(),
                s.bolts.len()
            )?;
        }
    }
    for st in &s.stages {
        let closure: Vec<String> = st
            .closure
            .iter()
            .map(|(name, c)| format!("{name} closure {:.2} mm", 1e3 * c))
            .collect();
        say!(
            "stage '{}': {} after {} cycles{}{}",
            st.name,
            st.status,
            st.cycles,
            if closure.is_empty() { "" } else { ", " },
            closure.join(", ")
        )?;
        if let Some(f) = &st.factor_of_safety {
            say!("stage '{}': {}", st.name, f.describe())?;
        }
    }
    // Where each wall moved by the end (inward positive).
    for (name, w) in s.stages.last().iter().flat_map(|st| &st.walls) {
        say!(
            "{name}: crown {:.2} mm down, invert {:.2} mm up, walls {:.2} and {:.2} mm in; \
             span converges {:.2} mm, height {:.2} mm",
            1e3 * w.crown_m,
            1e3 * w.invert_m,
            1e3 * w.left_m,
            1e3 * w.right_m,
            1e3 * w.span_convergence_m,
            1e3 * w.height_convergence_m
        )?;
    }
    say!("results in {}", result.out_dir.display())?;
    if s.status == Status::Interrupted.label() {
        eprintln!("error: interrupted at cycle {}", s.cycles);
        return Ok(ExitCode::from(130));
    }
    if let Some(reason) = &s.reason {
        eprintln!("error: run failed: {reason}");
        return Ok(ExitCode::from(2));
    }
    if s.status == Status::CycleLimit.label() {
        eprintln!(
            "warning: the run stopped at its cycle limit (ratio {}), not at equilibrium: its \
             results are not converged (raise solve.max_cycles, or see summary.json's stages)",
            s.final_ratio
                .map_or("not measured".into(), |r| format!("{r:.2e}"))
        );
        return Ok(ExitCode::from(3));
    }
    Ok(ExitCode::SUCCESS)
}

/// Validate and build `scene_path` as `run` does before solving (supports and stages included),
/// and print what was built with the build's warnings (the repairs made).
fn check(scene_path: &Path) -> anyhow::Result<()> {
    let scene = load(scene_path)?;
    let meshed = mesh(&scene)?;
    let s = meshed.stats();
    let depth = adit::setup::zoning(&scene)?.plastic_depth;
    let refined = if depth > 0.0 {
        format!(", zones halved out to {depth:.3} m from the walls (zoning.plastic_depth)")
    } else {
        String::new()
    };
    let lines = [
        format!("scene {}: valid", scene.name),
        format!(
            "domain area {:.6} m², {} excavation(s)",
            meshed.domain.area(),
            meshed.domain.holes.len()
        ),
        format!(
            "blocks: {} ({} sliver(s)); {:.3} m of joint traces end inside a block and are part of \
             its rock (a joint acts only where it separates two blocks, as in UDEC)",
            meshed.blocking.blocks.len(),
            meshed.blocking.slivers.len(),
            meshed.blocking.absorbed_joint_length
        ),
        format!(
            "mesh: {} zones, {} nodes, min angle {:.1}°{}, edges {:.4}–{:.4} m, zoned area \
             {:.6} m²{refined}",
            s.zones,
            s.nodes,
            s.min_angle_deg,
            meshed.min_angle_note(scene.zoning.min_angle),
            s.min_edge,
            s.max_edge,
            s.area
        ),
    ];
    let mut built = setup_meshed(&scene, meshed)?;
    adit::run::refuse_before_solving(&scene, &built.plan, &built.model)?;
    let speed = measured_speed(&scene, &mut built.model)?;
    let step = SmallestStep::replayed(&mut built);
    let cost = format!(
        "cost: critical time step {}, the smallest over the stages as `adit run` reports it; \
         {speed}",
        step.describe(&built.plan)
    );
    let mut out = std::io::stdout().lock();
    for line in lines.into_iter().chain([cost]) {
        writeln!(out, "{line}")?;
    }
    for w in &built.warnings {
        writeln!(out, "warning: {w}")?;
    }
    Ok(())
}

/// What a cycle of `model` costs, measured over 20 cycles here; an error when they blow up.
fn measured_speed(scene: &Scene, model: &mut adit::model::Model) -> anyhow::Result<String> {
    const CYCLES: u32 = 20;
    let mut solver = adit::solve::Solver::new(model, &scene.solve, 0);
    adit::run::ensure_time_step(&solver)?;
    let start = std::time::Instant::now();
    // The guards of `run`'s cycling: a scene whose first cycles blow up fails here as it would
    // there, before a detection sizes its grids on exploded positions.
    for cycle in 1..=CYCLES {
        solver.cycle.run(model, &solver.params);
        if let Some(reason) = solver.cycle.unstable_step(model, solver.params.dt) {
            anyhow::bail!("the scene's first cycles fail: cycle {cycle}: {reason}");
        }
    }
    if let Err(reason) = solver.cycle.monitor(model) {
        anyhow::bail!("the scene's first cycles fail: cycle {CYCLES}: {reason}");
    }
    let per_cycle = start.elapsed().as_secs_f64() / f64::from(CYCLES);
    Ok(format!(
        "{:.0} cycles/s ({:.3e} zone-cycles/s) measured over {CYCLES} cycles here",
        1.0 / per_cycle,
        model.zones.len() as f64 / per_cycle
    ))
}

fn write_mesh(scene_path: &Path, out: Option<PathBuf>) -> anyhow::Result<()> {
    let scene = load(scene_path)?;
    let out = out.unwrap_or_else(|| default_out_dir(&scene));
    let built = setup(&scene)?;
    let mut writer = OutputWriter::new(&out, &format!("{}_mesh", scene.name))?;
    writer.write_step(&built.model, 0.0)?;
    say!(
        "{} zones, {} nodes written to {}",
        built.mesh.zones,
        built.mesh.nodes,
        out.display()
    )?;
    Ok(())
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Run {
            scene,
            out,
            quiet,
            from_stage,
            from,
        } => {
            // Ctrl-C and SIGTERM stop the solve at the end of a cycle; the run then writes what
            // it has, with status `interrupted`.
            adit::interrupt::install();
            let start = match from {
                Some(checkpoint) => Start::Checkpoint(checkpoint),
                None => Start::Stage(from_stage),
            };
            run(&scene, out, quiet, start)
        }
        Command::Check { scene } => check(&scene).map(|_| ExitCode::SUCCESS),
        Command::Mesh { scene, out } => write_mesh(&scene, out).map(|_| ExitCode::SUCCESS),
        Command::Sweep {
            spec,
            out,
            workers,
            scheduler: Some(address),
        } => on_dask(&spec, out, workers, &address),
        Command::SweepRun {
            base,
            id,
            params,
            out,
        } => {
            adit::interrupt::install();
            stop_when_the_sweep_ends();
            sweep_run(&base, id, &params, &out)
        }
        Command::Sweep {
            spec,
            out,
            workers,
            scheduler: None,
        } => {
            adit::interrupt::install();
            sweep(&spec, out, workers)
        }
    };
    match result {
        Ok(code) => code,
        // The reader went away (`adit check s.json | head -1`): nothing left to tell it.
        Err(e) if is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

/// `adit sweep` on this machine's threads.
fn sweep(path: &Path, out: Option<PathBuf>, workers: Option<usize>) -> anyhow::Result<ExitCode> {
    let spec = adit::sweep::SweepSpec::load(path)?;
    let dir = path.parent().unwrap_or(Path::new("."));
    let base = spec.base_scene(dir)?;
    let out = out.unwrap_or_else(|| spec.out_dir());
    let runs = adit::sweep::plan(&spec);
    let workers = workers.unwrap_or_else(|| {
        std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get)
    });
    say!(
        "sweep {}: {} runs, {} at once, into {}",
        spec.name,
        runs.len(),
        workers,
        out.display()
    )?;
    std::fs::create_dir_all(&out).map_err(|e| anyhow::anyhow!("{}: {e}", out.display()))?;
    adit::sweep::remove_table(&out).map_err(|e| anyhow::anyhow!("{}: {e}", out.display()))?;
    let count = std::sync::atomic::AtomicUsize::new(0);
    let told = |row: &adit::sweep::Row, before: bool| {
        let k = count.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
        let how = if before {
            "done before".to_string()
        } else {
            format!("{:.2} s", row.wall_seconds)
        };
        let error = row
            .error
            .as_deref()
            .map_or(String::new(), |e| format!(": {e}"));
        let _ = say!(
            "[{k}/{}] {} {} ({how}){error}",
            runs.len(),
            row.id,
            row.status
        );
    };
    // Each run in a process of its own, which reads the base scene from one file.
    let base_file = out.join("base.json");
    adit::output::atomic::write_atomic(&base_file, |w| w.write_all(base.to_string().as_bytes()))?;
    let exe = std::env::current_exe()?;
    let run = |input: &adit::sweep::RunInput| adit::sweep::in_child(&exe, &base_file, input, &out);
    let rows = adit::sweep::run_local(&runs, &out, workers, &run, &told);
    let finished: Vec<adit::sweep::Row> = rows.iter().flatten().cloned().collect();
    if finished.len() < runs.len() {
        eprintln!(
            "interrupted with {} of {} runs done: run the same command again to make the others",
            finished.len(),
            runs.len()
        );
        return Ok(ExitCode::from(130));
    }
    for w in adit::sweep::write_table(&out, &finished)? {
        eprintln!("warning: {w}");
    }
    let failed = finished.iter().filter(|r| r.status == "failed").count();
    say!(
        "{} runs in {} ({failed} failed); table {}",
        finished.len(),
        out.display(),
        out.join("sweep.csv").display()
    )?;
    Ok(ExitCode::SUCCESS)
}

/// A sweep's run stops (at the end of a cycle, leaving no row) once the sweep that started it
/// ends, however it ends: the sweep holds the write end of the run's standard input
/// (`sweep::in_child`), which the system closes when the sweep's process goes, SIGKILL
/// included, so a read of it ends.
fn stop_when_the_sweep_ends() {
    std::thread::spawn(|| {
        let mut byte = [0u8; 1];
        let mut stdin = std::io::stdin();
        while let Ok(1) = std::io::Read::read(&mut stdin, &mut byte) {}
        adit::interrupt::request();
    });
}

/// `adit sweep-run`: one run of a sweep, its row left in `out`.
fn sweep_run(base: &Path, id: String, params: &str, out: &Path) -> anyhow::Result<ExitCode> {
    let text =
        std::fs::read_to_string(base).map_err(|e| anyhow::anyhow!("{}: {e}", base.display()))?;
    let base: serde_json::Value = serde_json::from_str(&text)?;
    let params = serde_json::from_str(params)?;
    let row = adit::sweep::run_one(&base, &adit::sweep::RunInput { id, params }, out);
    Ok(if row.status == "interrupted" {
        ExitCode::from(130)
    } else {
        ExitCode::SUCCESS
    })
}

/// `adit sweep --scheduler ADDR`: hand the sweep to the Python package's Dask path.
fn on_dask(
    spec: &Path,
    out: Option<PathBuf>,
    workers: Option<usize>,
    address: &str,
) -> anyhow::Result<ExitCode> {
    let interpreter = std::env::var("ADIT_PYTHON").unwrap_or_else(|_| "python3".into());
    let mut python = std::process::Command::new(&interpreter);
    python
        .args(["-m", "adit.sweep"])
        .arg(spec)
        .args(["--scheduler", address]);
    if let Some(out) = out {
        python.arg("--out").arg(out);
    }
    if let Some(w) = workers {
        python.args(["--workers", &w.to_string()]);
    }
    let status = python.status().map_err(|e| {
        anyhow::anyhow!(
            "--scheduler: {interpreter} could not be started ({e}); install the package \
             (pip install ./python) or name the Python that has it in ADIT_PYTHON"
        )
    })?;
    Ok(ExitCode::from(
        status.code().unwrap_or(1).clamp(0, 255) as u8
    ))
}

/// Whether `e` is a write to a pipe whose reader has closed.
fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bar names the stage it counts (issue 49, friction item 8), and no stage in an
    /// unstaged run.
    #[test]
    fn the_progress_bar_names_its_stage() {
        let staged = progress_message("bolts and shotcrete", 2.5e-4, "");
        assert_eq!(staged, "stage 'bolts and shotcrete', ratio 2.50e-4");
        assert_eq!(
            progress_message("", 1e-3, ", factor 1.0 MB in 0.010 s"),
            "ratio 1.00e-3, factor 1.0 MB in 0.010 s"
        );
    }
}
