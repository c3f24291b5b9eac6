//! Random scenes (issue 5, case 10): runs over random block arrangements, joint angles,
//! stiffnesses, block modes and loads. A box 2–4 m wide, cut by one or two joint sets (the second
//! at least 3° from the first: nearer sets cut the sliver wedges of case 3, `slivers.rs`), joints
//! of kn = 1e10–1e12 Pa/m, φ = 10–45°, blocks deformable, simple or rigid, base fixed, sides on
//! rollers, up to 2 MPa on top, with or without gravity. Whatever the draw, a run must end
//! converged, at its cycle limit, or stopped as a mechanism (a wedge sliding out under a constant
//! load runs away: the runaway check names it) — never with NaN, an unstable step or
//! interpenetration — with every stress finite and every contact overlap within its joint length.
//!
//! The draws come from proptest strategies: `cargo test` runs 64 of them as a property (shrinking
//! any failure to a small reproducer), the report a longer seeded sweep.

use std::time::Instant;

use adit::Scene;
use adit::scene::SolveMethod;
use adit::solve::Quiet;
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, TestRng, TestRunner};

use crate::report::{CaseReport, StepInfo};

/// One random scene's parameters.
#[derive(Debug, Clone)]
pub struct Draw {
    /// Box width and height, m.
    pub width: f64,
    /// Joint set dips, degrees.
    pub dips: [f64; 2],
    /// Joint set spacings, m.
    pub spacings: [f64; 2],
    pub sets: usize,
    /// Joint normal stiffness, Pa/m (shear stiffness half of it).
    pub kn: f64,
    /// Joint friction angle, degrees.
    pub friction: f64,
    pub mode: &'static str,
    /// Pressure on top, Pa.
    pub pressure: f64,
    pub gravity: bool,
}

/// The strategy the draws come from.
pub fn draw() -> impl Strategy<Value = Draw> {
    use proptest::prelude::*;
    (
        2.0..4.0f64,
        (0.0..180.0f64, 3.0..177.0f64),
        (0.5..1.5f64, 0.5..1.5f64),
        1usize..=2,
        10.0..12.0f64,
        10.0..45.0f64,
        prop_oneof![Just("deformable"), Just("simple"), Just("rigid")],
        0.0..2e6f64,
        any::<bool>(),
    )
        .prop_map(
            |(width, dips, spacings, sets, log_kn, friction, mode, pressure, gravity)| Draw {
                width,
                dips: [dips.0, (dips.0 + dips.1) % 180.0],
                spacings: [spacings.0, spacings.1],
                sets,
                kn: 10f64.powf(log_kn),
                friction,
                mode,
                pressure,
                gravity,
            },
        )
}

/// The scene of a draw.
pub fn scene(d: &Draw) -> anyhow::Result<Scene> {
    let sets: Vec<serde_json::Value> = (0..d.sets)
        .map(|i| {
            serde_json::json!({ "dip": d.dips[i], "spacing": d.spacings[i], "origin": [0.13, 0.07],
                                "material": "joint" })
        })
        .collect();
    let w = d.width;
    let text = serde_json::json!({
        "name": "random",
        "materials": { "rock": { "density": 2600, "young": 10e9, "poisson": 0.25 } },
        "region": { "polygon": [[0, 0], [w, 0], [w, w], [0, w]],
                    "edge_names": ["base", "right", "top", "left"], "material": "rock" },
        "zoning": { "edge_at_excavation": 0.25, "edge_far": 0.25 },
        "joint_materials": { "joint": { "normal_stiffness": d.kn, "shear_stiffness": 0.5 * d.kn,
                                        "friction": d.friction } },
        "joint_sets": sets,
        "blocks": { "mode": d.mode },
        "gravity": [0, if d.gravity { -9.81 } else { 0.0 }],
        "boundary": [{ "part": "base", "fix": "xy" }, { "part": "left", "fix": "x" },
                     { "part": "right", "fix": "x" }, { "part": "top", "normal_stress": -d.pressure }],
        "solve": { "ratio": 1e-5, "max_cycles": 3000 }
    });
    Ok(Scene::from_json(&text.to_string(), "random")?)
}

/// How one random scene ended.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// `converged`, `cycle limit` or `failed`.
    pub status: String,
    pub reason: String,
    pub zones: usize,
    pub blocks: usize,
    pub cycles: u64,
    /// Every zone stress and node displacement finite.
    pub finite: bool,
    /// Largest contact overlap over its contact length (checked on runs that did not stop).
    pub overlap: f64,
    /// A zone grid was written (a finished-looking result; a stopped run must write none).
    pub grid_written: bool,
    pub step: StepInfo,
}

impl Outcome {
    /// A mechanism the runaway check stopped (a block sliding out under constant load).
    pub fn is_mechanism(&self) -> bool {
        self.status == "failed" && self.reason.contains("runaway displacement")
    }

    /// The property: no failure but a runaway mechanism, everything finite, overlaps within the
    /// contact length, and no zone grid from a stopped run.
    pub fn check(&self) -> Result<(), String> {
        if self.status == "failed" && !self.is_mechanism() {
            return Err(format!("failed: {}", self.reason));
        }
        if self.status == "failed" && self.grid_written {
            return Err("a stopped run wrote a zone grid".into());
        }
        if !self.finite {
            return Err("non-finite stress or displacement".into());
        }
        if self.overlap > 1.0 {
            return Err(format!("overlap {:.3} of the contact length", self.overlap));
        }
        Ok(())
    }
}

/// Run one draw (output written under the system's temporary directory).
pub fn run(d: &Draw) -> anyhow::Result<Outcome> {
    run_by(d, SolveMethod::Explicit)
}

/// [`run`] solved by `method` (`solve.method`).
pub fn run_by(d: &Draw, method: SolveMethod) -> anyhow::Result<Outcome> {
    let mut sc = scene(d)?;
    sc.solve.method = method;
    // A directory of its own per run: tests run draws on several threads of one process.
    static RUNS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let run = RUNS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("adit_random_scene_{}_{run}", std::process::id()));
    if dir.exists() {
        std::fs::remove_dir_all(&dir)?;
    }
    let r = adit::run_scene(&sc, &dir, &mut Quiet);
    let grid_written = dir.join("random_zones_0000.vtu").exists();
    // The output was only looked at for the grid: the directory goes either way.
    let _ = std::fs::remove_dir_all(&dir);
    let r = r?;
    let m = &r.built.model;
    let stopped = r.summary.status == "failed";
    let c = &m.contacts;
    let overlap = (0..c.len())
        .filter(|_| !stopped)
        .map(|k| -c.state[k].normal_displacement / c.length[k])
        .fold(0.0, f64::max);
    Ok(Outcome {
        status: r.summary.status.clone(),
        reason: r.summary.reason.clone().unwrap_or_default(),
        zones: m.zones.len(),
        blocks: m.blocks.len(),
        cycles: r.summary.cycles,
        finite: m.zones.stress.iter().flatten().all(|s| s.is_finite())
            && m.nodes.disp.iter().flatten().all(|u| u.is_finite()),
        overlap,
        grid_written,
        step: StepInfo::from_summary(&r.summary),
    })
}

/// A seeded sweep's tally.
#[derive(Debug, Clone)]
pub struct Sweep {
    pub scenes: usize,
    pub converged: usize,
    pub at_limit: usize,
    pub mechanisms: usize,
    pub blocks: usize,
    pub cycles: u64,
    pub zone_cycles: f64,
    pub worst_overlap: f64,
    /// The smallest critical step met.
    pub tightest: StepInfo,
    pub wall_s: f64,
}

impl Sweep {
    pub fn report(&self) -> CaseReport {
        let mut row = CaseReport::new(
            format!(
                "{} random jointed boxes ({} blocks in all): {} converged, {} at the cycle limit, \
                 {} mechanisms stopped by the runaway check, no NaN, no unstable step; the tightest \
                 critical step is listed",
                self.scenes,
                self.blocks,
                self.converged,
                self.at_limit,
                self.mechanisms
            ),
            (self.zone_cycles / self.cycles.max(1) as f64).round() as usize,
            self.cycles,
            self.wall_s,
            None,
            &[("worst_overlap_over_length", self.worst_overlap)],
        )
        .with_step(self.tightest.clone());
        row.zone_cycles_per_s = self.zone_cycles / self.wall_s;
        row
    }
}

/// Run `scenes` draws from the strategy seeded by `seed`, failing on the first that breaks the
/// property (its draw in the message).
pub fn sweep(scenes: usize, seed: u8) -> anyhow::Result<Sweep> {
    let start = Instant::now();
    let rng = TestRng::from_seed(proptest::test_runner::RngAlgorithm::ChaCha, &[seed; 32]);
    let mut runner = TestRunner::new_with_rng(Config::default(), rng);
    let strategy = draw();
    let mut s = Sweep {
        scenes,
        converged: 0,
        at_limit: 0,
        mechanisms: 0,
        blocks: 0,
        cycles: 0,
        zone_cycles: 0.0,
        worst_overlap: 0.0,
        tightest: StepInfo {
            critical_s: f64::INFINITY,
            used_s: 1.0,
            limited_by: String::new(),
        },
        wall_s: 0.0,
    };
    for _ in 0..scenes {
        let d = strategy
            .new_tree(&mut runner)
            .map_err(|e| anyhow::anyhow!("drawing a scene: {e}"))?
            .current();
        let o = run(&d)?;
        o.check()
            .map_err(|e| anyhow::anyhow!("random scene {d:?}: {e}"))?;
        match o.status.as_str() {
            "converged" => s.converged += 1,
            _ if o.is_mechanism() => s.mechanisms += 1,
            _ => s.at_limit += 1,
        }
        s.blocks += o.blocks;
        s.cycles += o.cycles;
        s.zone_cycles += (o.zones * o.cycles as usize) as f64;
        s.worst_overlap = s.worst_overlap.max(o.overlap);
        if o.step.critical_s < s.tightest.critical_s {
            s.tightest = o.step.clone();
        }
    }
    s.wall_s = start.elapsed().as_secs_f64();
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Two draws whose meshes varied from run to run while spade's bulk load re-inserted the
    /// vertices its sweep skipped in a per-process hash order: each is set up eight times in one
    /// process (every set up draws new hash seeds) and must give the same zones and nodes, and
    /// run twice to the same number of cycles.
    #[test]
    fn the_same_scene_meshes_and_runs_the_same_every_time() {
        let draws = [
            (
                3.827061826659075,
                [33.703344807453625, 54.75539245717681],
                [1.3702724625578186, 0.784121823476921],
                11460162256.680052,
                41.07045616884105,
                802313.5580568212,
            ),
            (
                2.6760296991312424,
                [47.81634695416339, 156.7316982465687],
                [1.278556636317355, 0.628108613575933],
                35816706715.80541,
                15.0451053324865,
                1364192.5031490405,
            ),
        ];
        for (width, dips, spacings, kn, friction, pressure) in draws {
            let d = Draw {
                width,
                dips,
                spacings,
                sets: 1,
                kn,
                friction,
                mode: "deformable",
                pressure,
                gravity: false,
            };
            let sc = scene(&d).unwrap();
            let first = adit::setup::setup(&sc).unwrap().model;
            for _ in 0..7 {
                let again = adit::setup::setup(&sc).unwrap().model;
                assert_eq!(again.zones.nodes, first.zones.nodes, "{d:?}");
                assert_eq!(again.nodes.pos, first.nodes.pos, "{d:?}");
            }
            let (a, b) = (run(&d).unwrap(), run(&d).unwrap());
            assert_eq!((a.zones, a.cycles), (b.zones, b.cycles), "{d:?}");
        }
    }

    proptest! {
        // A fixed seed: the same 64 scenes on every machine (change it to explore others).
        #![proptest_config(ProptestConfig {
            cases: 64,
            rng_seed: proptest::test_runner::RngSeed::Fixed(20261123),
            failure_persistence: None,
            ..ProptestConfig::default()
        })]
        #[test]
        fn random_jointed_boxes_stay_sane(d in draw()) {
            let o = run(&d).unwrap();
            prop_assert!(o.check().is_ok(), "{:?}: {:?}", d, o.check());
        }
    }

    proptest! {
        // Other scenes, solved by `auto`: the implicit path, handing over to explicit cycling
        // what it cannot settle (a sliding or loose block); the same property.
        #![proptest_config(ProptestConfig {
            cases: 32,
            rng_seed: proptest::test_runner::RngSeed::Fixed(20261124),
            failure_persistence: None,
            ..ProptestConfig::default()
        })]
        #[test]
        fn random_jointed_boxes_stay_sane_solved_by_auto(d in draw()) {
            let o = run_by(&d, SolveMethod::Auto).unwrap();
            prop_assert!(o.check().is_ok(), "{:?}: {:?}", d, o.check());
        }
    }
}
