//! Results on disk, as the output contract of `design.md`: a ParaView collection (`.pvd`) over
//! zone grids (`_zones_NNNN.vtu`), contacts, joints and supports (`_contacts_`, `_joints_`,
//! `_supports_NNNN.vtu`),
//! `history.csv` and `summary.json`, each written atomically (`history.csv` is also written row by
//! row while a run goes, so that a killed run keeps it; the run's `summary.json` says `running`).
//! A run holds its folder while it goes (`lock`): a second run into it is refused.

pub mod arrays;
pub mod atomic;
pub mod capacity_plot;
pub mod factor_of_safety;
pub mod histories;
pub mod histories_plot;
pub mod joints_vtu;
pub mod lock;
pub mod plots;
pub mod reactions;
pub mod recovery;
pub mod supports_vtu;
pub mod vtu;

use std::io::Write;
use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::cycle::StageSeconds;
use crate::model::Model;
use crate::solve::HistoryRow;
use atomic::write_atomic;

/// Writes the output steps of one run into a folder.
pub struct OutputWriter {
    pub(crate) dir: PathBuf,
    pub name: String,
    /// Each step so far: its timestep value, its stage and its file names (zones, then contacts
    /// and joints when there are blocks, then supports when there are any).
    steps: Vec<Step>,
    /// The stage the next steps belong to and its number (`set_stage`; `None` before the first).
    stage: Option<(usize, String)>,
    /// The index of the first stage the run solves (`for_run`).
    first_stage: usize,
    /// Whether rows go to `history.csv` as the run goes (`for_run`, until `write_history`).
    live_history: bool,
    /// That file, from the first row on, flushed at each row, so that a killed run keeps its
    /// history; rewritten whole and atomically at the end.
    history: Option<std::io::BufWriter<std::fs::File>>,
    /// `histories.csv` (monitoring points) as `history` is.
    histories: Option<std::io::BufWriter<std::fs::File>>,
    /// The folder held for the run (`for_run`), given back when the writer is dropped.
    _lock: Option<lock::FolderLock>,
}

impl OutputWriter {
    /// Write grids of `name` into `dir`, created if need be.
    pub fn new(dir: &Path, name: &str) -> anyhow::Result<OutputWriter> {
        std::fs::create_dir_all(dir)
            .map_err(|e| anyhow::anyhow!("output folder {}: {e}", dir.display()))?;
        Ok(OutputWriter {
            dir: dir.to_path_buf(),
            name: name.to_string(),
            steps: Vec::new(),
            stage: None,
            first_stage: 0,
            live_history: false,
            history: None,
            histories: None,
            _lock: None,
        })
    }

    /// Open `dir` for a run of the scene `name` from stage `from` (numbered from 1), holding it
    /// until the writer is dropped (a run already writing there fails this one, `lock`): from the
    /// first, remove what an earlier run of that name left there (`is_run_output`, and its
    /// checkpoints); from a later one, keep it until `resume` says which steps to keep. Then
    /// write a `summary.json` with status `running`. A folder then never shows an earlier run's
    /// results as this one's, and one that cannot be written fails here, before anything is
    /// solved.
    pub fn for_run(dir: &Path, name: &str, from: usize) -> anyhow::Result<OutputWriter> {
        let writer = OutputWriter::new(dir, name)?;
        let held = lock::FolderLock::take(dir)?;
        if from <= 1 {
            writer.remove_outputs(0, 0)?;
        }
        writer
            .write_status("running", None)
            .map_err(|e| anyhow::anyhow!("output folder {}: {e}", dir.display()))?;
        Ok(OutputWriter {
            live_history: true,
            first_stage: from.saturating_sub(1),
            _lock: Some(held),
            ..writer
        })
    }

    /// Remove the outputs of an earlier run of this scene but its first `steps` output steps
    /// and its checkpoints of stages up to `stages`.
    fn remove_outputs(&self, steps: usize, stages: usize) -> anyhow::Result<()> {
        let dir = &self.dir;
        let in_folder = |e: std::io::Error| anyhow::anyhow!("output folder {}: {e}", dir.display());
        for entry in std::fs::read_dir(dir).map_err(in_folder)? {
            let entry = entry.map_err(in_folder)?;
            let file = entry.file_name().to_string_lossy().into_owned();
            let kept = step_of(&file, &self.name).is_some_and(|s| s < steps);
            if is_run_output(&file, &self.name) && !kept {
                std::fs::remove_file(entry.path()).map_err(in_folder)?;
            }
        }
        let checkpoints = dir.join("checkpoints");
        if let Ok(entries) = std::fs::read_dir(&checkpoints) {
            for entry in entries.flatten() {
                let file = entry.file_name().to_string_lossy().into_owned();
                let number = file
                    .strip_prefix("stage_")
                    .and_then(|f| f.strip_suffix(".ckpt"))
                    .and_then(|n| n.parse::<usize>().ok());
                if number.is_some_and(|n| n > stages) {
                    std::fs::remove_file(entry.path()).map_err(in_folder)?;
                }
            }
        }
        Ok(())
    }

    /// The index of the first stage this writer's run solves (0 unless it goes on from a
    /// checkpoint).
    pub fn first_stage(&self) -> usize {
        self.first_stage
    }

    /// The output steps written so far: timestep, stage and files of each.
    pub fn steps(&self) -> Vec<(f64, String, Vec<String>)> {
        self.steps
            .iter()
            .map(|s| (s.timestep, s.stage.clone(), s.files.clone()))
            .collect()
    }

    /// Go on from a checkpoint: keep its output `steps` (removing any later step and
    /// checkpoint an earlier run left) and start `history.csv` with its `history`.
    pub fn resume(
        &mut self,
        steps: &[(f64, String, Vec<String>)],
        history: &[HistoryRow],
    ) -> anyhow::Result<()> {
        self.remove_outputs(steps.len(), self.first_stage)?;
        self.steps = steps
            .iter()
            .map(|(timestep, stage, files)| Step {
                timestep: *timestep,
                stage: stage.clone(),
                files: files.clone(),
            })
            .collect();
        self.history = None;
        for r in history {
            self.append_history(r)?;
        }
        Ok(())
    }

    /// Add a row to the `history.csv` a run writes as it goes (nothing for other writers).
    pub fn append_history(&mut self, r: &HistoryRow) -> std::io::Result<()> {
        if !self.live_history {
            return Ok(());
        }
        let h = live_csv(
            &mut self.history,
            &self.dir.join("history.csv"),
            HISTORY_HEADER,
        )?;
        history_row(h, r)?;
        h.flush()
    }

    /// Add a row of the monitoring points' `values` at `cycle` and `time` (s) to the
    /// `histories.csv` a run writes as it goes, started with `header` (nothing for other writers).
    pub fn append_samples(
        &mut self,
        header: &str,
        cycle: u64,
        time: f64,
        values: &[f64],
    ) -> std::io::Result<()> {
        if !self.live_history {
            return Ok(());
        }
        let h = live_csv(&mut self.histories, &self.dir.join("histories.csv"), header)?;
        histories::row(h, cycle, time, values)?;
        h.flush()
    }

    /// Write `histories.csv` whole: `header`, then a row per sample.
    pub fn write_histories(
        &mut self,
        header: &str,
        samples: &histories::Samples,
    ) -> std::io::Result<()> {
        self.histories = None;
        write_atomic(&self.dir.join("histories.csv"), |w| {
            writeln!(w, "{header}")?;
            for k in 0..samples.len() {
                histories::row(w, samples.cycle[k], samples.time[k], &samples.values[k])?;
            }
            Ok(())
        })
    }

    /// Write a `summary.json` that holds only the scene name, a status and, if given, the reason:
    /// while the run goes on (`running`), or when it failed before it had figures to report.
    pub fn write_status(&self, status: &str, reason: Option<&str>) -> std::io::Result<()> {
        let mut doc = serde_json::json!({ "scene": self.name, "status": status });
        if let Some(r) = reason {
            doc["reason"] = r.into();
        }
        let text = serde_json::to_string_pretty(&doc).map_err(std::io::Error::other)?;
        write_atomic(&self.dir.join("summary.json"), |w| {
            w.write_all(text.as_bytes())
        })
    }

    /// Label the steps written from now on with stage `index` of the run, named `name` (their
    /// files' field data and the collection's `stage` of each data set).
    pub fn set_stage(&mut self, index: usize, name: &str) {
        self.stage = Some((index, name.to_string()));
    }

    /// Write the grids of this step and refresh the collection; `timestep` is the cumulative
    /// cycle count.
    pub fn write_step(&mut self, model: &Model, timestep: f64) -> anyhow::Result<()> {
        let step = self.steps.len();
        let stage = self.stage.as_ref().map(|(i, n)| (*i, n.as_str()));
        let labels = vtu::Labels::of(model, stage);
        let mut files = Vec::new();
        let mut write = |kind: &str, xml: Vec<u8>| -> std::io::Result<()> {
            let file = format!("{}_{kind}_{step:04}.vtu", self.name);
            write_atomic(&self.dir.join(&file), |w| w.write_all(&xml))?;
            files.push(file);
            Ok(())
        };
        write("zones", grid(vtu::zones_vtu(model, &labels))?)?;
        // A step with no contact (the joints all left the model, as a staged hole's fill does)
        // writes neither file: an empty grid is valid VTK but meshio cannot read it.
        if model.blocks.len() > 1 && !model.contacts.is_empty() {
            write("contacts", grid(vtu::contacts_vtu(model, &labels))?)?;
            write("joints", grid(joints_vtu::joints_vtu(model, &labels))?)?;
        }
        if model.supports.any_installed() {
            write(
                "supports",
                grid(supports_vtu::supports_vtu(model, &labels))?,
            )?;
        }
        self.steps.push(Step {
            timestep,
            stage: self
                .stage
                .as_ref()
                .map_or(String::new(), |(_, n)| n.clone()),
            files,
        });
        self.write_pvd()?;
        Ok(())
    }

    /// The collection: one data set per file of each step, its `part` and `name` the file's kind
    /// (`PARTS`: 0 `zones`, 1 `contacts`, 2 `joints`, 3 `supports`, the same at every step whatever
    /// a step leaves out; ParaView names its blocks so)
    /// and its `stage` the step's stage (an attribute readers pass over; the files' field data
    /// `stage` carries it into ParaView).
    fn write_pvd(&self) -> std::io::Result<()> {
        let path = self.dir.join(format!("{}.pvd", self.name));
        write_atomic(&path, |w| {
            writeln!(w, "<?xml version=\"1.0\"?>")?;
            writeln!(
                w,
                "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">"
            )?;
            writeln!(w, "  <Collection>")?;
            for s in &self.steps {
                let stage = xml_attribute(&s.stage);
                for file in &s.files {
                    let kind = file_kind(file);
                    let part = PARTS.iter().position(|&k| k == kind).unwrap_or(PARTS.len());
                    writeln!(
                        w,
                        "    <DataSet timestep=\"{}\" group=\"\" part=\"{part}\" name=\"{kind}\" stage=\"{stage}\" file=\"{file}\"/>",
                        s.timestep
                    )?;
                }
            }
            writeln!(w, "  </Collection>")?;
            writeln!(w, "</VTKFile>")
        })
    }

    /// Write `history.csv`: cycle, time, unbalanced-force ratio, kinetic energy.
    pub fn write_history(&mut self, rows: &[HistoryRow]) -> std::io::Result<()> {
        self.live_history = false;
        self.history = None;
        write_atomic(&self.dir.join("history.csv"), |w| {
            writeln!(w, "{HISTORY_HEADER}")?;
            for r in rows {
                history_row(w, r)?;
            }
            Ok(())
        })
    }

    /// Write `ground_reaction.csv`: one row per stage, support fraction and the wall closure (m) of
    /// each excavation (empty where not yet excavated).
    pub fn write_ground_reaction(
        &self,
        stages: &[StageSummary],
        names: &[String],
    ) -> std::io::Result<()> {
        write_atomic(&self.dir.join("ground_reaction.csv"), |w| {
            write!(w, "stage,support_fraction")?;
            for n in names {
                write!(w, ",{}", csv_field(&format!("closure_{n}_m")))?;
                for (column, _) in WALL_COLUMNS {
                    write!(w, ",{}", csv_field(&format!("{n}_{column}")))?;
                }
            }
            writeln!(w)?;
            for s in stages {
                write!(w, "{},{}", csv_field(&s.name), s.support_fraction)?;
                for n in names {
                    match s.closure.get(n) {
                        Some(c) => write!(w, ",{c:e}")?,
                        None => write!(w, ",")?,
                    }
                    for (_, figure) in WALL_COLUMNS {
                        match s.walls.get(n) {
                            Some(moves) => write!(w, ",{:e}", figure(moves))?,
                            None => write!(w, ",")?,
                        }
                    }
                }
                writeln!(w)?;
            }
            Ok(())
        })
    }

    /// Write `summary.json`, leaving out every field without a value (a figure not measured, or
    /// not finite: JSON's `null`), as README promises.
    pub fn write_summary(&self, summary: &Summary) -> std::io::Result<()> {
        let mut doc = serde_json::to_value(summary).map_err(std::io::Error::other)?;
        drop_nulls(&mut doc);
        let text = serde_json::to_string_pretty(&doc).map_err(std::io::Error::other)?;
        write_atomic(&self.dir.join("summary.json"), |w| {
            w.write_all(text.as_bytes())
        })
    }
}

/// A grid file's text, or why it could not be made (vtkio's I/O error unwrapped, whose message
/// would otherwise say its cause twice).
fn grid(xml: Result<Vec<u8>, vtkio::Error>) -> anyhow::Result<Vec<u8>> {
    xml.map_err(|e| match e {
        vtkio::Error::IO(io) => anyhow::Error::new(io),
        e => anyhow::Error::new(e),
    })
}

/// Remove the members of every object in `v` whose value is `null` (serde writes a non-finite
/// number and an absent option so).
fn drop_nulls(v: &mut serde_json::Value) {
    match v {
        serde_json::Value::Object(fields) => {
            fields.retain(|_, x| !x.is_null());
            fields.values_mut().for_each(drop_nulls);
        }
        serde_json::Value::Array(items) => items.iter_mut().for_each(drop_nulls),
        _ => {}
    }
}

/// One output step of the collection.
struct Step {
    timestep: f64,
    stage: String,
    files: Vec<String>,
}

/// The kinds of a step's files, in the order of their `part` in the collection.
const PARTS: [&str; 4] = ["zones", "contacts", "joints", "supports"];

/// The kind of a grid file `<name>_<kind>_NNNN.vtu`: `zones`, `contacts`, `joints` or `supports`.
fn file_kind(file: &str) -> &str {
    let stem = file.strip_suffix(".vtu").unwrap_or(file);
    let stem = stem.rsplit_once('_').map_or(stem, |(s, _)| s);
    stem.rsplit_once('_').map_or(stem, |(_, k)| k)
}

/// `text` as an XML attribute value (its `&`, `<`, `>` and `"` escaped).
pub(crate) fn xml_attribute(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A figure for `summary.json`: `Some` when finite. A run that stops before measuring something
/// (its ratio is still ∞) or whose state is no longer finite leaves the field out instead of
/// writing `null` (JSON has no ∞ or NaN) where a reader expects a number.
pub fn measured(x: f64) -> Option<f64> {
    x.is_finite().then_some(x)
}

/// One stage in `summary.json`.
#[derive(Debug, Clone, Serialize)]
pub struct StageSummary {
    pub name: String,
    pub cycles: u64,
    /// `converged`, `cycle_limit` or `failed`.
    pub status: String,
    /// The last unbalanced-force ratio measured (`measured`); absent when the stage stopped before
    /// its first monitor step.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub final_ratio: Option<f64>,
    /// Support fraction on the walls of the excavations made so far.
    pub support_fraction: f64,
    /// Mean wall closure of each excavation made so far at the end of the stage, m (inward
    /// positive, displacement since the start of the run): with `support_fraction`, the ground
    /// reaction curve.
    pub closure: std::collections::BTreeMap<String, f64>,
    /// How the crown, invert and sidewalls of each excavation made so far moved by the end of
    /// the stage, and its span's and height's convergence (`WallMoves`); absent when none is.
    #[serde(skip_serializing_if = "std::collections::BTreeMap::is_empty")]
    pub walls: std::collections::BTreeMap<String, WallMoves>,
    /// The block still sliding when the stage's explicit solve converged, or the fastest when it
    /// stopped at its cycle limit, named with its speed (`cycle::drift`); absent when none is.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub moving: Option<String>,
    /// The stage's factor of safety by strength reduction (`stages[i].factor_of_safety`), with
    /// its trials; absent when not asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub factor_of_safety: Option<factor_of_safety::FactorOfSafety>,
}

/// An excavation's wall at its four extreme points (its rock wall nodes highest, lowest,
/// leftmost and rightmost at the start), each displacement inward positive, m, since the start
/// of the run (as `closure`): the crown's settlement, the invert's heave, each sidewall's move
/// toward the opening, and their sums, the convergence of the span (left + right) and of the
/// height (crown + invert).
/// With them, the pressure the installed liners put on the wall (the links' forces on the rock
/// along its outward normals, over the wall's length), Pa, and over the in-situ mean normal
/// stress at the opening's centre (the support's reaction curve against the ground's).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct WallMoves {
    pub crown_m: f64,
    pub invert_m: f64,
    pub left_m: f64,
    pub right_m: f64,
    pub span_convergence_m: f64,
    pub height_convergence_m: f64,
    pub support_pressure_pa: f64,
    pub support_pressure_ratio: f64,
}

/// One figure of an excavation's wall moves.
type WallFigure = fn(&WallMoves) -> f64;

/// The wall moves `ground_reaction.csv` gives per excavation, each column after the
/// excavation's name: inward displacements of the crown, invert and side walls, the span's and
/// height's convergence (m), and the liners' pressure on the wall (Pa).
const WALL_COLUMNS: [(&str, WallFigure); 7] = [
    ("crown_m", |w| w.crown_m),
    ("invert_m", |w| w.invert_m),
    ("left_wall_m", |w| w.left_m),
    ("right_wall_m", |w| w.right_m),
    ("span_convergence_m", |w| w.span_convergence_m),
    ("height_convergence_m", |w| w.height_convergence_m),
    ("support_pressure_pa", |w| w.support_pressure_pa),
];

impl WallMoves {
    /// From the displacements (m) of the crown, invert, left and right wall points.
    pub fn of(crown: [f64; 2], invert: [f64; 2], left: [f64; 2], right: [f64; 2]) -> WallMoves {
        let (crown_m, invert_m, left_m, right_m) = (-crown[1], invert[1], left[0], -right[0]);
        WallMoves {
            crown_m,
            invert_m,
            left_m,
            right_m,
            span_convergence_m: left_m + right_m,
            height_convergence_m: crown_m + invert_m,
            ..WallMoves::default()
        }
    }

    /// Every figure finite (a failed stage's state may not be).
    pub fn is_finite(&self) -> bool {
        self.to_array().iter().all(|v| v.is_finite())
    }

    /// Its figures in codec order (`from_array` reads them back).
    pub fn to_array(&self) -> [f64; 6] {
        [
            self.crown_m,
            self.invert_m,
            self.left_m,
            self.right_m,
            self.support_pressure_pa,
            self.support_pressure_ratio,
        ]
    }

    pub fn from_array([c, i, l, r, p, q]: [f64; 6]) -> WallMoves {
        WallMoves {
            support_pressure_pa: p,
            support_pressure_ratio: q,
            ..WallMoves::of([0.0, -c], [0.0, i], [l, 0.0], [-r, 0.0])
        }
    }
}

/// Contents of `summary.json`.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    pub scene: String,
    pub zones: usize,
    pub nodes: usize,
    pub blocks: usize,
    /// Blocks in rigid and in simple mode (the rest are deformable).
    pub rigid_blocks: usize,
    pub simple_blocks: usize,
    pub contacts: usize,
    pub cycles: u64,
    pub wall_seconds: f64,
    pub stage_seconds: StageSeconds,
    pub zone_cycles_per_second: f64,
    /// Blocks × cycles per second of cycling, the figure of merit of rigid and simple blocks.
    pub block_cycles_per_second: f64,
    /// The last unbalanced-force ratio measured; absent when the run stopped before its first
    /// monitor step (a failure or interruption at once): no field holds `null`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub final_ratio: Option<f64>,
    /// `converged`, `cycle_limit` or `failed`.
    pub status: String,
    /// Why the run failed (only with status `failed`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    /// Time step used, s (1 in static mass-scaled runs).
    pub timestep: f64,
    /// Critical time step with real masses, s, and the node that sets it.
    pub critical_timestep: f64,
    pub(crate) critical_node: u32,
    /// The rigid or simple block that sets the critical time step, if one does (else absent).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) critical_block: Option<u32>,
    /// What sets the critical step: `zones at node N`, `contacts at node N`, `supports`, `block B`.
    /// The step is the smallest over the stages (the supports a stage installs stiffen it).
    pub critical_limiter: String,
    /// The stage whose critical step is the smallest (staged scenes only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub critical_stage: Option<String>,
    /// Smallest zone angle, degrees.
    pub min_zone_angle: f64,
    /// What building the model found worth a warning (sliver blocks, joints merged into walls).
    pub warnings: Vec<String>,
    /// Each stage of a staged scene, in order (empty without stages).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub stages: Vec<StageSummary>,
    /// The path each stage took, when `solve.method` is not `explicit`: `implicit`, or `explicit`
    /// with the reason `auto` did not solve implicitly.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub methods: Vec<String>,
    /// What the implicit solves cost, summed over the stages (absent when none ran).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub implicit: Option<crate::implicit::Cost>,
    /// What each fixing boundary condition in force at the end holds (`reactions`); absent when
    /// none fixes anything or the last stage failed.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub reactions: Vec<reactions::Reaction>,
    /// Each installed bolt's largest load, per bolt (N) and over its capacity (absent without
    /// bolts).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub bolts: Vec<crate::support::BoltLoad>,
    /// Each installed liner's largest forces per set and, with strengths, its least factor of
    /// safety (absent without liners).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub liners: Vec<crate::support::LinerLoad>,
    /// The largest peak particle velocity over the dynamic stages and where (absent without a
    /// dynamic stage).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub peak_particle_velocity: Option<PeakVelocity>,
    /// The blocks on the excavations' walls at the first dynamic stage, each bounded by joints
    /// and its wall, with the peak of its velocity into the opening, fastest first (absent
    /// without a dynamic stage or such blocks).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub ejection: Vec<crate::dynamics::Ejected>,
    /// The far field's interface and what condensing it cost (absent without one).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub far_field: Option<FarFieldSummary>,
}

/// `summary.json`'s `peak_particle_velocity`: the largest of the nodes' peak speeds (the `ppv`
/// point field).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PeakVelocity {
    /// m/s.
    pub largest_m_per_s: f64,
    /// Where: the node's current position, m.
    pub at_m: [f64; 2],
}

impl PeakVelocity {
    /// The largest peak of `model`'s, if it keeps them.
    pub fn of(model: &crate::model::Model) -> Option<PeakVelocity> {
        let (n, largest) = model.peaks.as_ref()?.largest()?;
        let (p, u) = (model.nodes.pos[n as usize], model.nodes.disp[n as usize]);
        Some(PeakVelocity {
            largest_m_per_s: largest,
            at_m: [p[0] + u[0], p[1] + u[1]],
        })
    }
}

/// `summary.json`'s `far_field`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FarFieldSummary {
    /// Nodes on the interface (the region's outer boundary).
    pub interface_nodes: usize,
    /// Seconds condensing the far field's stiffness took (once, at setup).
    pub condense_seconds: f64,
    /// Bytes of its stiffness K, (2n)² values (the condensing took (4e + 2)² twice for e elements).
    pub stiffness_bytes: usize,
    /// How many times faster the far-field rock's field varies along the interface than an
    /// intact rock's (1 for intact rock; a jointed rock mass's, `Kernel::stretch`): K's error
    /// grows about as its square, and over 3 the run warns.
    pub stretch: f64,
}

impl FarFieldSummary {
    pub fn of(f: &crate::far_field::FarField) -> FarFieldSummary {
        FarFieldSummary {
            interface_nodes: f.nodes.len(),
            condense_seconds: f.assemble_s,
            stiffness_bytes: f.stiffness.k.len() * std::mem::size_of::<f64>(),
            stretch: f.stretch,
        }
    }
}

/// A CSV file a run writes as it goes: `slot`'s, or `path` created with its `header` line.
fn live_csv<'a>(
    slot: &'a mut Option<std::io::BufWriter<std::fs::File>>,
    path: &Path,
    header: &str,
) -> std::io::Result<&'a mut std::io::BufWriter<std::fs::File>> {
    if slot.is_none() {
        let mut h = std::io::BufWriter::new(std::fs::File::create(path)?);
        writeln!(h, "{header}")?;
        *slot = Some(h);
    }
    Ok(slot.as_mut().expect("opened above"))
}

/// The header of `history.csv`.
const HISTORY_HEADER: &str = "cycle,time_s,unbalanced_ratio,kinetic_energy_j_per_m";

/// One row of `history.csv`.
fn history_row(w: &mut dyn Write, r: &HistoryRow) -> std::io::Result<()> {
    writeln!(w, "{},{:e},{:e},{:e}", r.cycle, r.time, r.ratio, r.kinetic)
}

/// Whether `file` is an output of a run of the scene `name` (or such a file's temporary):
/// `<name>.pvd`, `<name>_zones_NNNN.vtu` and its contacts, joints and supports siblings, `history.csv`,
/// `ground_reaction.csv`, `summary.json` and the plots (`plots.rs`).
fn is_run_output(file: &str, name: &str) -> bool {
    let file = match file.strip_prefix('.').and_then(|f| f.strip_suffix(".tmp")) {
        Some(inner) => inner,
        None => file,
    };
    const FILES: [&str; 9] = [
        "history.csv",
        "histories.csv",
        "histories.png",
        "ground_reaction.csv",
        "summary.json",
        "history.png",
        "ground_reaction.png",
        "bolts.png",
        "liner_capacity.png",
    ];
    if FILES.contains(&file) {
        return true;
    }
    let Some(rest) = file.strip_prefix(name) else {
        return false;
    };
    if rest == ".pvd" {
        return true;
    }
    ["_zones_", "_contacts_", "_joints_", "_supports_"]
        .iter()
        .any(|kind| {
            rest.strip_prefix(kind)
                .and_then(|r| r.strip_suffix(".vtu"))
                .is_some_and(|n| n.len() == 4 && n.bytes().all(|b| b.is_ascii_digit()))
        })
}

/// The step number of an output grid file of the scene `name` (`<name>_<kind>_NNNN.vtu`).
fn step_of(file: &str, name: &str) -> Option<usize> {
    let rest = file.strip_prefix(name)?.strip_suffix(".vtu")?;
    let (_, number) = rest.rsplit_once('_')?;
    (number.len() == 4).then(|| number.parse().ok())?
}

/// A CSV field (RFC 4180): quoted, with quotes doubled, when it holds a comma, a quote or a line
/// break; as it is otherwise.
pub(crate) fn csv_field(text: &str) -> std::borrow::Cow<'_, str> {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\"")).into()
    } else {
        text.into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stage that failed before its first monitor step (ratio still ∞) with a state gone NaN
    /// writes no `null`: the unmeasured ratio is left out.
    #[test]
    fn an_unmeasured_figure_is_left_out_not_null() {
        let stage = StageSummary {
            name: "excavate".into(),
            cycles: 3,
            status: "failed".into(),
            final_ratio: measured(f64::INFINITY),
            support_fraction: 0.0,
            closure: Default::default(),
            walls: Default::default(),
            moving: None,
            factor_of_safety: None,
        };
        let json = serde_json::to_string(&stage).unwrap();
        assert!(
            !json.contains("null") && !json.contains("final_ratio"),
            "{json}"
        );
        assert_eq!(measured(f64::NAN), None);
        assert_eq!(measured(2e-6), Some(2e-6));
    }

    #[test]
    fn a_run_clears_only_its_own_earlier_outputs() {
        for mine in [
            "tunnel.pvd",
            "tunnel_zones_0002.vtu",
            "tunnel_contacts_0000.vtu",
            "tunnel_joints_0001.vtu",
            "tunnel_supports_0013.vtu",
            "history.csv",
            "summary.json",
            "ground_reaction.csv",
            ".tunnel_zones_0001.vtu.tmp",
            ".summary.json.tmp",
        ] {
            assert!(is_run_output(mine, "tunnel"), "{mine}");
        }
        for other in [
            "tunnel.json",
            "tunnel_mesh.pvd",
            "tunnel_mesh_zones_0000.vtu",
            "kirsch.pvd",
            "tunnel_zones_1.vtu",
            "notes.txt",
        ] {
            assert!(!is_run_output(other, "tunnel"), "{other}");
        }
    }

    #[test]
    fn csv_fields_with_commas_or_quotes_are_quoted() {
        assert_eq!(csv_field("in-situ"), "in-situ");
        assert_eq!(csv_field("excavate, 25 %"), "\"excavate, 25 %\"");
        assert_eq!(csv_field("a \"b\""), "\"a \"\"b\"\"\"");
    }
}
