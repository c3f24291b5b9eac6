//! Checkpoints: the state at the end of every stage, so that `adit run SCENE --from-stage N`
//! goes on from there and gives the numbers of the run that was not stopped, bit for bit, and
//! `adit run SCENE --from CHECKPOINT` branches: another scene whose stages up to the checkpoint's
//! are the same (another bolt pattern, liner or strength later) goes on from it.
//!
//! A checkpoint (`<out>/checkpoints/stage_NN.ckpt`, NN the stage's number from 1) is versioned
//! binary: the magic `ADITCKPT`, the format's version, the text of the part of the scene that
//! sets the state so far (`prefix.rs`: the scene as parsed, without its name, output folder,
//! later stages and the supports only they install), the run's scene name, then the run so far
//! (stages done, cycles, history, each stage's summary, the paths taken, the implicit solves'
//! cost but for its seconds, the output steps) and the model's state (`state.rs`). No wall-clock
//! figure is kept, so a run's checkpoints are the same bytes on every run (a branch's too); a
//! resumed run's seconds count the stages it ran. A restart builds the model from
//! the scene, replays the stages before N (their excavations, materials, supports and loads,
//! which set what the state does not hold: the laws), and puts the saved state in. A checkpoint
//! whose part differs from the scene's is refused naming the first field that differs; one of
//! another version or a damaged one is refused, naming why.

pub mod codec;
pub mod prefix;
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
/// excavations' wall moves (`StageSummary::walls`). 8: with their liners' wall pressure. 9: the
/// scene's part so far as text (`prefix.rs`) for its hash, the run's name, the supports' state
/// per installed group. 10: no implicit seconds (`Cost`'s wall-clock figures are not state).
/// 11: each bolt node's rock displacement at the last force stage and the energy the bolt took
/// there (`Cables::rock_last`, `absorbed`). 12: each trial's farthest block departure
/// (`Trial::departure_m`). 13: each trial's inverted zones and a failed trial's reason
/// (`Trial::inverted`, `Trial::reason`).
pub const VERSION: u32 = 13;

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

/// The checkpoint of `run` and `model` for `scene`, as bytes.
pub fn encode(scene: &Scene, run: &RunSoFar, model: &Model) -> Vec<u8> {
    let mut out = MAGIC.to_vec();
    put(&mut out, &VERSION);
    put(&mut out, &prefix::prefix(scene, run.stages_done));
    put_run(&mut out, run);
    state::save(model, &mut out);
    out
}

fn put_run(out: &mut Vec<u8>, run: &RunSoFar) {
    put(out, &run.stages_done);
    put(out, &run.cycles);
    put(out, &run.history);
    put(out, &run.samples);
    put(out, &run.summaries);
    put(out, &run.methods);
    put(out, &run.implicit);
    put(out, &run.steps);
}

/// A checkpoint read up to the model's state: the run so far, its scene's part and name.
pub struct Read<'a> {
    pub run: RunSoFar,
    /// The part of the checkpoint's scene that set its state (`prefix::prefix`).
    pub prefix: String,
    /// Where the model's state starts in the checkpoint's bytes.
    state_at: usize,
    state: Reader<'a>,
}

/// Read the run so far from `bytes`: an error naming why when they are not a checkpoint of this
/// version.
pub fn read(bytes: &[u8]) -> anyhow::Result<Read<'_>> {
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
    let prefix = String::get(&mut r)?;
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
    Ok(Read {
        run,
        prefix,
        state_at: MAGIC.len() + r.position(),
        state: r,
    })
}

impl Read<'_> {
    /// An error naming the first field where `scene`'s stages so far differ from the
    /// checkpoint's.
    pub fn same_stages_as(&self, scene: &Scene) -> anyhow::Result<()> {
        let ours = prefix::prefix(scene, self.run.stages_done);
        match prefix::first_difference(&self.prefix, &ours) {
            None => Ok(()),
            Some((path, theirs, ours)) => anyhow::bail!(
                "the checkpoint's run differs from this scene in its first {} stage(s): first at \
                 {path} (the checkpoint's `{theirs}`, the scene's `{ours}`); a run goes on from a \
                 checkpoint whose stages so far are the scene's",
                self.run.stages_done
            ),
        }
    }

    /// Put the state into `model` (built from `scene`, the stages before replayed) and return
    /// the run so far, its output files named for `scene`.
    pub fn restore(mut self, scene: &Scene, model: &mut Model) -> anyhow::Result<RunSoFar> {
        self.same_stages_as(scene)?;
        state::restore(model, &mut self.state)?;
        anyhow::ensure!(
            self.state.at_end(),
            "the checkpoint has bytes after its state (damaged?)"
        );
        Ok(self.run.named(&scene.name))
    }
}

impl RunSoFar {
    /// The run so far with its output files named as the run of the scene named `name` writes
    /// them.
    fn named(mut self, name: &str) -> RunSoFar {
        for (_, _, files) in &mut self.steps {
            for f in files.iter_mut() {
                *f = renamed(f, name);
            }
        }
        self
    }
}

/// The checkpoint `bytes` as the run of the scene named `name` writes it: its output files
/// renamed, the rest (the stages' part of the scene, the state) the same for any scene going on
/// from it.
pub fn named(bytes: &[u8], name: &str) -> anyhow::Result<Vec<u8>> {
    let read = read(bytes)?;
    let mut out = MAGIC.to_vec();
    put(&mut out, &VERSION);
    put(&mut out, &read.prefix);
    let state_at = read.state_at;
    put_run(&mut out, &read.run.named(name));
    out.extend_from_slice(&bytes[state_at..]);
    Ok(out)
}

/// The output file `file` (`<name>_<kind>_NNNN.vtu`) as the run of the scene named `name`
/// writes it.
pub fn renamed(file: &str, name: &str) -> String {
    let mut parts = file.rsplitn(3, '_');
    match (parts.next(), parts.next(), parts.next()) {
        (Some(step), Some(kind), Some(_)) => format!("{name}_{kind}_{step}"),
        _ => file.to_string(),
    }
}

/// Read the run so far from `bytes` and put the state into `model` (built from `scene`, the
/// stages before replayed): an error naming why when the bytes are not a checkpoint of `scene`'s
/// stages so far at this version.
pub fn decode(bytes: &[u8], scene: &Scene, model: &mut Model) -> anyhow::Result<RunSoFar> {
    read(bytes)?.restore(scene, model)
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
        put(out, &self.departure_m);
        put(out, &self.inverted);
        put(out, &self.moving);
        put(out, &self.reason);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        Ok(Trial {
            factor: Codec::get(r)?,
            stable: Codec::get(r)?,
            status: Codec::get(r)?,
            cycles: Codec::get(r)?,
            displacement_m: Codec::get(r)?,
            departure_m: Codec::get(r)?,
            inverted: Codec::get(r)?,
            moving: Codec::get(r)?,
            reason: Codec::get(r)?,
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
        Ok(Cost {
            unknowns: unknowns as usize,
            matrix_nonzeros: matrix_nonzeros as usize,
            factor_nonzeros: factor_nonzeros as usize,
            factorizations,
            analyses,
            iterations,
            cuts,
            ..Cost::default()
        })
    }
}
