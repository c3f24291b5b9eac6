//! Checkpoints: the state at the end of every stage, so that `adit run SCENE --from-stage N`
//! goes on from there and gives the numbers of the run that was not stopped, bit for bit.
//!
//! A checkpoint (`<out>/checkpoints/stage_NN.ckpt`, NN the stage's number from 1) is versioned
//! binary: the magic `ADITCKPT`, the format's version, a hash of the scene as parsed, then the
//! run so far (stages done, cycles, history, each stage's summary, the paths taken, the implicit
//! solves' cost, the output steps) and the model's state (`state.rs`). A restart builds the model
//! from the scene, replays the stages before N (their excavations, materials, supports and loads,
//! which set what the state does not hold: the laws), and puts the saved state in. A checkpoint of
//! another scene, of another version or a damaged one is refused, naming why.

pub mod codec;
pub mod state;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use codec::{Codec, Reader, put};

use crate::Scene;
use crate::implicit::Cost;
use crate::model::Model;
use crate::output::factor_of_safety::{FactorOfSafety, MovingBlock, Trial};
use crate::output::histories::Samples;
use crate::output::{StageSummary, WallMoves};
use crate::solve::HistoryRow;

/// The format's version: a checkpoint of another version is refused. 2: each stage's summary
/// holds the block still moving at its convergence (`StageSummary::moving`). 3: a joint's state
/// holds its shear path and mobilized JRC (the Barton–Bandis law). 4: each stage's summary holds
/// its factor of safety (`StageSummary::factor_of_safety`). 5: each trial of it, its largest
/// displacement (`Trial::displacement_m`), and the mechanism's blocks (`FactorOfSafety::mechanism`).
/// 6: the monitoring points' samples (`RunSoFar::samples`). 7: each stage's summary, its
/// excavations' wall moves (`StageSummary::walls`). 8: with their liners' wall pressure.
pub const VERSION: u32 = 8;

const MAGIC: &[u8; 8] = b"ADITCKPT";

/// The run up to the end of a stage.
#[derive(Debug, Clone, Default)]
pub struct RunSoFar {
    /// Stages done (the checkpoint's stage number, from 1).
    pub stages_done: usize,
    pub cycles: u64,
    pub history: Vec<HistoryRow>,
    /// The monitoring points' samples (`histories.csv`).
    pub samples: Samples,
    pub summaries: Vec<StageSummary>,
    pub methods: Vec<String>,
    pub implicit: Option<Cost>,
    /// The output steps written: timestep, stage and files of each.
    pub steps: Vec<(f64, String, Vec<String>)>,
}

/// The file of the checkpoint after stage `number` (from 1) in the output folder `out`.
pub fn path(out: &Path, number: usize) -> PathBuf {
    out.join("checkpoints")
        .join(format!("stage_{number:02}.ckpt"))
}

/// FNV-1a (64 bits) of the scene as parsed (its `Debug` text: the same scene, whatever its
/// layout in the file, hashes the same).
pub fn scene_hash(scene: &Scene) -> u64 {
    format!("{scene:?}")
        .bytes()
        .fold(0xcbf2_9ce4_8422_2325, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
        })
}

/// The checkpoint of `run` and `model` for `scene`, as bytes.
pub fn encode(scene: &Scene, run: &RunSoFar, model: &Model) -> Vec<u8> {
    let mut out = MAGIC.to_vec();
    put(&mut out, &VERSION);
    put(&mut out, &scene_hash(scene));
    put(&mut out, &run.stages_done);
    put(&mut out, &run.cycles);
    put(&mut out, &run.history);
    put(&mut out, &run.samples);
    put(&mut out, &run.summaries);
    put(&mut out, &run.methods);
    put(&mut out, &run.implicit);
    put(&mut out, &run.steps);
    state::save(model, &mut out);
    out
}

/// Read the run so far from `bytes` and put the state into `model` (built from `scene`, the
/// stages before replayed): an error naming why when the bytes are not a checkpoint of `scene`
/// at this version.
pub fn decode(bytes: &[u8], scene: &Scene, model: &mut Model) -> anyhow::Result<RunSoFar> {
    anyhow::ensure!(
        bytes.len() >= MAGIC.len() && &bytes[..MAGIC.len()] == MAGIC,
        "not an adit checkpoint"
    );
    let mut r = Reader::new(&bytes[MAGIC.len()..]);
    let version = u32::get(&mut r)?;
    anyhow::ensure!(
        version == VERSION,
        "a checkpoint of format version {version}; this adit reads version {VERSION}"
    );
    anyhow::ensure!(
        u64::get(&mut r)? == scene_hash(scene),
        "the checkpoint is of another scene (or of this scene before it was changed)"
    );
    let run = RunSoFar {
        stages_done: Codec::get(&mut r)?,
        cycles: Codec::get(&mut r)?,
        history: Codec::get(&mut r)?,
        samples: Codec::get(&mut r)?,
        summaries: Codec::get(&mut r)?,
        methods: Codec::get(&mut r)?,
        implicit: Codec::get(&mut r)?,
        steps: Codec::get(&mut r)?,
    };
    state::restore(model, &mut r)?;
    anyhow::ensure!(
        r.at_end(),
        "the checkpoint has bytes after its state (damaged?)"
    );
    Ok(run)
}

impl Codec for HistoryRow {
    fn put(&self, out: &mut Vec<u8>) {
        put(out, &self.cycle);
        put(out, &[self.time, self.ratio, self.kinetic]);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        let cycle = u64::get(r)?;
        let [time, ratio, kinetic] = <[f64; 3]>::get(r)?;
        Ok(HistoryRow {
            cycle,
            time,
            ratio,
            kinetic,
        })
    }
}

impl Codec for StageSummary {
    fn put(&self, out: &mut Vec<u8>) {
        put(out, &self.name);
        put(out, &self.cycles);
        put(out, &self.status);
        put(out, &self.final_ratio);
        put(out, &self.support_fraction);
        let closure: Vec<(String, f64)> = self.closure.clone().into_iter().collect();
        put(out, &closure);
        let walls: Vec<(String, [f64; 6])> = (self.walls.iter())
            .map(|(k, w)| (k.clone(), w.to_array()))
            .collect();
        put(out, &walls);
        put(out, &self.moving);
        put(out, &self.factor_of_safety);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        let name = String::get(r)?;
        let cycles = u64::get(r)?;
        let status = String::get(r)?;
        let final_ratio = Option::<f64>::get(r)?;
        let support_fraction = f64::get(r)?;
        let closure: Vec<(String, f64)> = Codec::get(r)?;
        let walls: Vec<(String, [f64; 6])> = Codec::get(r)?;
        let moving = Option::<String>::get(r)?;
        let factor_of_safety = Codec::get(r)?;
        Ok(StageSummary {
            name,
            cycles,
            status,
            final_ratio,
            support_fraction,
            closure: closure.into_iter().collect::<BTreeMap<_, _>>(),
            walls: (walls.into_iter())
                .map(|(k, w)| (k, WallMoves::from_array(w)))
                .collect(),
            moving,
            factor_of_safety,
        })
    }
}

impl Codec for FactorOfSafety {
    fn put(&self, out: &mut Vec<u8>) {
        put(out, &self.factor);
        put(out, &self.unstable);
        put(out, &self.tolerance);
        put(out, &self.trials);
        put(out, &self.mechanism);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        Ok(FactorOfSafety {
            factor: Codec::get(r)?,
            unstable: Codec::get(r)?,
            tolerance: Codec::get(r)?,
            trials: Codec::get(r)?,
            mechanism: Codec::get(r)?,
        })
    }
}

impl Codec for Samples {
    fn put(&self, out: &mut Vec<u8>) {
        put(out, &self.cycle);
        put(out, &self.time);
        put(out, &self.values);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        Ok(Samples {
            cycle: Codec::get(r)?,
            time: Codec::get(r)?,
            values: Codec::get(r)?,
        })
    }
}

impl Codec for MovingBlock {
    fn put(&self, out: &mut Vec<u8>) {
        put(out, &self.block);
        put(out, &self.at);
        put(out, &self.displacement_m);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        Ok(MovingBlock {
            block: Codec::get(r)?,
            at: Codec::get(r)?,
            displacement_m: Codec::get(r)?,
        })
    }
}

impl Codec for Trial {
    fn put(&self, out: &mut Vec<u8>) {
        put(out, &self.factor);
        put(out, &self.stable);
        put(out, &self.status);
        put(out, &self.cycles);
        put(out, &self.displacement_m);
        put(out, &self.moving);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        Ok(Trial {
            factor: Codec::get(r)?,
            stable: Codec::get(r)?,
            status: Codec::get(r)?,
            cycles: Codec::get(r)?,
            displacement_m: Codec::get(r)?,
            moving: Codec::get(r)?,
        })
    }
}

impl Codec for Cost {
    fn put(&self, out: &mut Vec<u8>) {
        put(
            out,
            &[
                self.unknowns as u64,
                self.matrix_nonzeros as u64,
                self.factor_nonzeros as u64,
                self.factorizations,
                self.analyses,
                self.iterations,
                self.cuts,
            ],
        );
        put(out, &[self.assemble_s, self.factorize_s, self.iterate_s]);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        let [
            unknowns,
            matrix_nonzeros,
            factor_nonzeros,
            factorizations,
            analyses,
            iterations,
            cuts,
        ] = <[u64; 7]>::get(r)?;
        let [assemble_s, factorize_s, iterate_s] = <[f64; 3]>::get(r)?;
        Ok(Cost {
            unknowns: unknowns as usize,
            matrix_nonzeros: matrix_nonzeros as usize,
            factor_nonzeros: factor_nonzeros as usize,
            factorizations,
            analyses,
            iterations,
            cuts,
            assemble_s,
            factorize_s,
            iterate_s,
        })
    }
}
