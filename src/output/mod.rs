//! Results on disk, as the output contract of `design.md`: a ParaView collection (`.pvd`) over
//! zone grids (`_zones_NNNN.vtu`), contacts and supports (`_contacts_`, `_supports_NNNN.vtu`),
//! `history.csv` and `summary.json`, each written atomically.

pub mod atomic;
pub mod supports_vtu;
pub mod vtu;

use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::cycle::StageSeconds;
use crate::model::Model;
use crate::solve::HistoryRow;
use atomic::write_atomic;

/// Writes the output steps of one run into a folder.
pub struct OutputWriter {
    pub dir: PathBuf,
    pub name: String,
    /// (timestep value, file names: zones, then contacts when there are blocks, then supports when
    /// there are any) of each step so far.
    steps: Vec<(f64, Vec<String>)>,
}

impl OutputWriter {
    pub fn new(dir: &Path, name: &str) -> std::io::Result<OutputWriter> {
        std::fs::create_dir_all(dir)?;
        Ok(OutputWriter {
            dir: dir.to_path_buf(),
            name: name.to_string(),
            steps: Vec::new(),
        })
    }

    /// Write the zone grid of this step and refresh the collection; `timestep` is the cumulative
    /// cycle count.
    pub fn write_step(&mut self, model: &Model, timestep: f64) -> anyhow::Result<()> {
        let step = self.steps.len();
        let zones = format!("{}_zones_{step:04}.vtu", self.name);
        let xml = vtu::zones_vtu(model)?;
        write_atomic(&self.dir.join(&zones), |w| w.write_all(&xml))?;
        let mut files = vec![zones];
        if model.blocks.len() > 1 {
            let contacts = format!("{}_contacts_{step:04}.vtu", self.name);
            let xml = vtu::contacts_vtu(model)?;
            write_atomic(&self.dir.join(&contacts), |w| w.write_all(&xml))?;
            files.push(contacts);
        }
        if !model.supports.is_empty() {
            let supports = format!("{}_supports_{step:04}.vtu", self.name);
            let xml = supports_vtu::supports_vtu(model)?;
            write_atomic(&self.dir.join(&supports), |w| w.write_all(&xml))?;
            files.push(supports);
        }
        self.steps.push((timestep, files));
        self.write_pvd()?;
        Ok(())
    }

    fn write_pvd(&self) -> std::io::Result<()> {
        let path = self.dir.join(format!("{}.pvd", self.name));
        write_atomic(&path, |w| {
            writeln!(w, "<?xml version=\"1.0\"?>")?;
            writeln!(
                w,
                "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">"
            )?;
            writeln!(w, "  <Collection>")?;
            for (t, files) in &self.steps {
                for (part, file) in files.iter().enumerate() {
                    writeln!(
                        w,
                        "    <DataSet timestep=\"{t}\" group=\"\" part=\"{part}\" file=\"{file}\"/>"
                    )?;
                }
            }
            writeln!(w, "  </Collection>")?;
            writeln!(w, "</VTKFile>")
        })
    }

    /// Write `history.csv`: cycle, time, unbalanced-force ratio, kinetic energy.
    pub fn write_history(&self, rows: &[HistoryRow]) -> std::io::Result<()> {
        write_atomic(&self.dir.join("history.csv"), |w| {
            writeln!(w, "cycle,time_s,unbalanced_ratio,kinetic_energy_J_per_m")?;
            for r in rows {
                writeln!(w, "{},{:e},{:e},{:e}", r.cycle, r.time, r.ratio, r.kinetic)?;
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
                write!(w, ",closure_{n}_m")?;
            }
            writeln!(w)?;
            for s in stages {
                write!(w, "{},{}", s.name.replace(',', ";"), s.support_fraction)?;
                for n in names {
                    match s.closure.get(n) {
                        Some(c) => write!(w, ",{c:e}")?,
                        None => write!(w, ",")?,
                    }
                }
                writeln!(w)?;
            }
            Ok(())
        })
    }

    /// Write `summary.json`.
    pub fn write_summary(&self, summary: &Summary) -> std::io::Result<()> {
        let text = serde_json::to_string_pretty(summary).map_err(std::io::Error::other)?;
        write_atomic(&self.dir.join("summary.json"), |w| {
            w.write_all(text.as_bytes())
        })
    }
}

/// One stage in `summary.json`.
#[derive(Debug, Clone, Serialize)]
pub struct StageSummary {
    pub name: String,
    pub cycles: u64,
    /// `converged`, `cycle_limit` or `failed`.
    pub status: String,
    pub final_ratio: f64,
    /// Support fraction on the walls of the excavations made so far.
    pub support_fraction: f64,
    /// Mean wall closure of each excavation made so far at the end of the stage, m (inward
    /// positive, displacement since the start of the run): with `support_fraction`, the ground
    /// reaction curve.
    pub closure: std::collections::BTreeMap<String, f64>,
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
    pub final_ratio: f64,
    /// `converged`, `cycle_limit` or `failed`.
    pub status: String,
    /// Why the run failed (only with status `failed`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    /// Time step used, s (1 in static mass-scaled runs).
    pub timestep: f64,
    /// Critical time step with real masses, s, and the node that sets it.
    pub critical_timestep: f64,
    pub critical_node: u32,
    /// The rigid or simple block that sets the critical time step, if one does.
    pub critical_block: Option<u32>,
    /// What sets the critical step: `zones at node N`, `contacts at node N`, `supports`, `block B`.
    pub critical_limiter: String,
    /// Smallest zone angle, degrees.
    pub min_zone_angle: f64,
    /// What building the model found worth a warning (sliver blocks, absorbed joints).
    pub warnings: Vec<String>,
    /// Each stage of a staged scene, in order (empty without stages).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub stages: Vec<StageSummary>,
}
