//! A whole run of a scene: build, solve, and write every output of the contract.

use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::build::{Built, build};
use crate::cycle::Cycle;
use crate::model::Model;
use crate::model::bodies::BodyMode;
use crate::output::{OutputWriter, Summary};
use crate::scene::Scene;
use crate::solve::{HistoryRow, Observer, Solution, Solver, Status};

/// The result of a run, with the model in its final state.
pub struct RunResult {
    pub built: Built,
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

/// Forwards monitor rows to the caller and writes intermediate output steps.
struct Writing<'a> {
    writer: &'a mut OutputWriter,
    inner: &'a mut dyn Observer,
    output_seconds: f64,
    error: Option<anyhow::Error>,
}

impl Observer for Writing<'_> {
    fn monitored(&mut self, row: &HistoryRow) {
        self.inner.monitored(row);
    }
    fn output_step(&mut self, cycle: u64, _time: f64, model: &Model, _c: &mut Cycle) {
        let t = Instant::now();
        if let Err(e) = self.writer.write_step(model, cycle as f64) {
            self.error.get_or_insert(e);
        }
        self.output_seconds += t.elapsed().as_secs_f64();
    }
}

/// Build and solve `scene`, writing results into `out_dir`. A failed solve still writes
/// `history.csv` and a `summary.json` with status `failed`, but no final zone grid.
pub fn run_scene(
    scene: &Scene,
    out_dir: &Path,
    observer: &mut dyn Observer,
) -> anyhow::Result<RunResult> {
    let start = Instant::now();
    let mut built = build(scene)?;
    let mut solver = Solver::new(&mut built.model, &scene.solve, scene.output.every);
    anyhow::ensure!(
        solver.params.dt.is_finite(),
        "solve: no zone or contact stiffness to derive the time step from (a lone rigid or simple \
         block without joints); make the block deformable or add joints"
    );
    let mut writer = OutputWriter::new(out_dir, &scene.name)?;
    let mut writing = Writing {
        writer: &mut writer,
        inner: observer,
        output_seconds: 0.0,
        error: None,
    };
    let solution = solver.solve(&mut built.model, &mut writing);
    let mut output_seconds = writing.output_seconds;
    if let Some(e) = writing.error {
        return Err(e);
    }
    let t = Instant::now();
    if !matches!(solution.status, Status::Failed(_)) {
        writer.write_step(&built.model, solution.cycles as f64)?;
    }
    writer.write_history(&solution.history)?;
    output_seconds += t.elapsed().as_secs_f64();
    let mut seconds = solver.cycle.seconds;
    seconds.output = output_seconds;
    let wall = start.elapsed().as_secs_f64();
    let cycling = seconds.detect + seconds.contacts + seconds.zones + seconds.motion;
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
        final_ratio: solution.final_ratio,
        status: solution.status.label().to_string(),
        reason: match &solution.status {
            Status::Failed(r) => Some(r.clone()),
            _ => None,
        },
        timestep: solver.params.dt,
        critical_timestep: solver.step.dt_critical,
        critical_node: solver.step.limiting_node.0,
        critical_block: solver.step.limiting_block,
        min_zone_angle: built.mesh.min_angle_deg,
        warnings: built.warnings.clone(),
    };
    writer.write_summary(&summary)?;
    Ok(RunResult {
        built,
        solution,
        summary,
        out_dir: out_dir.to_path_buf(),
    })
}
