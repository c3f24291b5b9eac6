//! Newmark's sliding block (Newmark 1965, "Effects of earthquakes on dams and embankments",
//! Géotechnique 15(2)): a block on a horizontal Coulomb joint whose base takes a rectangular
//! acceleration pulse A for t_p. The joint passes at most the acceleration a_y = g tan φ to the
//! block (A > a_y), which slides back on its base until their velocities meet, the base at
//! V = A t_p: the slip is
//!
//!   d = V²/(2 a_y) (1 − a_y/A).
//!
//! The run is the scene path end to end: the block settles under gravity on a fixed base (static),
//! then a dynamic stage without damping drives the base's bottom by the acceleration
//! (`boundary[i].motion`, integrated to velocity by the engine), and the slip is read from
//! `histories.csv`: the block's top corner against the base's top away from it, over the last
//! tenth of the record (the joint's elastic rocking averaged out).

use std::time::Instant;

use adit::scene::BlockMode;

use crate::incline::mode_name;
use crate::quiet::{history_after, run_to_completion};
use crate::report::CaseReport;

const G: f64 = 9.81;

/// The base's thickness (m) and the rock's Young's modulus (Pa): the closed form's base is rigid,
/// and the block feels the base's motion only once the shear wave has crossed it, τ = thickness/Cs
/// later, which lets it slip about V τ farther (a 1 m base of 10 GPa rock, τ = 0.79 ms: +1.7 % at
/// A = 2 a_y). Half a metre of 50 GPa rock makes τ 0.18 ms (+0.35 %).
const BASE: f64 = 0.5;
const YOUNG: f64 = 50e9;

/// One Newmark run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Newmark {
    /// Friction angle of the joint, degrees.
    pub phi_deg: f64,
    /// The pulse's acceleration over the yield acceleration, A/a_y (> 1).
    pub ratio: f64,
    /// The pulse's duration t_p, s.
    pub duration: f64,
    /// Zone size, m.
    pub h: f64,
    pub mode: BlockMode,
}

/// A measured slip with its closed form, m.
#[derive(Debug, Clone)]
pub struct Slip {
    pub report: CaseReport,
    pub measured: f64,
    pub exact: f64,
}

impl Newmark {
    /// The yield acceleration a_y = g tan φ, m/s².
    pub fn yield_acceleration(&self) -> f64 {
        G * self.phi_deg.to_radians().tan()
    }

    /// Newmark's slip d = V²/(2 a_y)(1 − a_y/A), V = A t_p, m.
    pub fn exact(&self) -> f64 {
        let ay = self.yield_acceleration();
        let a = self.ratio * ay;
        let v = a * self.duration;
        v * v / (2.0 * ay) * (1.0 - ay / a)
    }

    /// The time the block stops slipping, V/a_y, s.
    fn slip_ends(&self) -> f64 {
        self.ratio * self.duration
    }

    fn scene(&self) -> adit::Scene {
        let a = self.ratio * self.yield_acceleration();
        // A rectangular pulse with ramps of a microsecond (shorter than the step): its area is
        // A t_p.
        let ramp = 1e-6;
        let pulse = [
            [0.0, 0.0],
            [ramp, a],
            [self.duration, a],
            [self.duration + ramp, 0.0],
        ];
        let record = 1.25 * self.slip_ends();
        let text = serde_json::json!({
            "name": "newmark",
            "materials": { "rock": { "density": 2500, "young": YOUNG, "poisson": 0.25 } },
            "region": {
                "polygon": [[0, 1.0 - BASE], [10, 1.0 - BASE], [10, 1], [3, 1], [3, 1.25], [2, 1.25],
                            [2, 1], [0, 1]],
                "edge_names": ["bottom", "e1", "e2", "e3", "e4", "e5", "e6", "e7"],
                "material": "rock"
            },
            "zoning": { "edge_at_excavation": self.h, "edge_far": self.h },
            "joint_materials": { "plane": {
                "normal_stiffness": 1e11, "shear_stiffness": 1e11, "friction": self.phi_deg } },
            "joints": [{ "from": [2, 1], "to": [3, 1], "material": "plane" }],
            "gravity": [0, -G],
            "blocks": { "regions": [{ "at": [2.5, 1.125], "mode": mode_name(self.mode) }] },
            "boundary": [{ "part": "bottom", "fix": "xy" }],
            "solve": { "ratio": 1e-7, "max_cycles": 400000 },
            "stages": [
                { "name": "settle" },
                { "name": "pulse", "reset_displacements": true,
                  "boundary": [{ "part": "bottom", "fix": "y",
                                 "motion": { "direction": "x", "acceleration": { "table": pulse } } }],
                  "solve": { "mode": "dynamic", "duration": record, "damping": 0,
                             "monitor_every": 20 } }
            ],
            "histories": [{ "name": "block", "at": [2, 1.25], "quantity": "displacement_x" },
                          { "name": "base", "at": [6, 1], "quantity": "displacement_x" }],
            "output": { "checkpoints": false, "every": 0 }
        });
        adit::Scene::from_json(&text.to_string(), "newmark").expect("a valid Newmark scene")
    }

    /// Run it: the slip, base less block, over the last tenth of the record against `exact`.
    pub fn run(&self) -> anyhow::Result<Slip> {
        let start = Instant::now();
        let (r, csv) = run_to_completion(&self.scene())?;
        let settled = r.summary.stages[0].cycles;
        let block = history_after(&csv, "block", settled)?;
        let base = history_after(&csv, "base", settled)?;
        let end = base.last().map_or(0.0, |p| p.0);
        let tail: Vec<f64> = (base.iter().zip(&block))
            .filter(|(b, _)| b.0 >= end - 0.1 * 1.25 * self.slip_ends())
            .map(|(b, k)| b.1 - k.1)
            .collect();
        anyhow::ensure!(!tail.is_empty(), "newmark: no samples at the record's end");
        let measured = tail.iter().sum::<f64>() / tail.len() as f64;
        let exact = self.exact();
        let report = CaseReport::new(
            format!(
                "{} block, φ = {}°, A = {} a_y for {} s ({:.3} m exact)",
                mode_name(self.mode),
                self.phi_deg,
                self.ratio,
                self.duration,
                exact
            ),
            r.summary.zones,
            r.summary.cycles,
            start.elapsed().as_secs_f64(),
            Some(self.h),
            &[("slip", (measured - exact).abs() / exact)],
        );
        Ok(Slip {
            report,
            measured,
            exact,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The coarse twin of the report's section: a rigid block, A = 2 a_y on φ = 30°, slips
    /// Newmark's d within 2 %.
    #[test]
    fn a_block_slips_newmarks_distance() {
        let run = Newmark {
            phi_deg: 30.0,
            ratio: 2.0,
            duration: 0.1,
            h: 0.25,
            mode: BlockMode::Rigid,
        };
        let slip = run.run().unwrap();
        assert!(
            (slip.measured - slip.exact).abs() < 0.02 * slip.exact,
            "{} m against {} m",
            slip.measured,
            slip.exact
        );
    }
}
