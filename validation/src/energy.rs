//! The energy balance of undamped elastic dynamic stages (issue 50): the work of the loads and
//! what the quiet boundaries let in and out against the kinetic and strain energy
//! (`dynamics::Energy`, read as the `kinetic_energy`, `strain_energy`, `boundary_work`,
//! `quiet_energy` and `energy_error` histories). Three columns of the quiet section's rock: a step
//! load on the top of a column on a fixed base (nothing leaves: the energy rings between kinetic
//! and strain), a pressure pulse on the top of a column with a quiet base (the load's work leaves
//! through the base), and a Ricker wave brought in through a quiet base to a free top and out
//! again (the incident wave's work in, the dashpots' out); and the step load on a column cut by
//! two glued joints (their springs store what the rock passes them: `joint_energy`); and the step
//! load damped locally and by Rayleigh damping (`damping_energy`); and a Ricker velocity prescribed
//! on the base (the motion's work on the rock is in the loads' W). The error is the largest
//! |W − ΔK − U − Q − J − D| over the record relative to the largest energy that entered.

use std::time::Instant;

use crate::quiet::{FREQUENCY, ROCK, run_to_completion, values_after, wave_speed};
use crate::report::CaseReport;
use adit::scene::WaveKind;

/// What loads a column.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Loading {
    /// A step normal stress on the top, the base fixed.
    Step,
    /// A Ricker pressure pulse on the top, the base quiet.
    Pulse,
    /// A Ricker P wave through the quiet base, the top free.
    Incident,
    /// The step load on a column cut across by two glued joints at a third and two thirds of
    /// its height.
    JointedStep,
    /// A Ricker velocity prescribed on the base (its y component held), the top free.
    Shaken,
}

/// The glued joints' stiffness, kn = ks, Pa/m: about the rock's over 2 m, so that they hold a
/// good share of the energy.
const JOINT_STIFFNESS: f64 = 5e9;

impl Loading {
    fn label(self) -> &'static str {
        match self {
            Loading::Step => "step load on the top, base fixed",
            Loading::Pulse => "pressure pulse on the top, base quiet",
            Loading::Incident => "P wave in through the quiet base, top free",
            Loading::JointedStep => "step load on the top, base fixed, two glued joints",
            Loading::Shaken => "Ricker velocity prescribed on the base, top free",
        }
    }
}

/// How a column is damped.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Damping {
    None,
    /// Local non-viscous damping of this coefficient.
    Local(f64),
    /// Rayleigh damping of this fraction of critical at the column's first mode (a quarter
    /// wavelength over its height, fixed base and free top), with these components (`both`,
    /// `mass`, `stiffness`).
    Rayleigh(f64, &'static str),
}

impl Damping {
    fn label(self) -> String {
        match self {
            Damping::None => "undamped".into(),
            Damping::Local(a) => format!("local damping {a}"),
            Damping::Rayleigh(xi, c) => format!("Rayleigh ξ = {} % ({c})", 100.0 * xi),
        }
    }

    /// The `solve` fields that damp a column `height` m tall.
    fn fields(self, height: f64) -> serde_json::Value {
        let first = wave_speed(WaveKind::P) / (4.0 * height);
        match self {
            Damping::None => serde_json::json!({ "damping": 0 }),
            Damping::Local(a) => serde_json::json!({ "damping": a }),
            Damping::Rayleigh(xi, c) => serde_json::json!({ "rayleigh":
                { "fraction": xi, "frequency": first, "components": c } }),
        }
    }
}

/// Run a column 2 m × `height` m zoned at `zone` m under `loading`, damped by `damping`: the
/// report, with the balance's largest error relative to the largest energy that entered
/// (`energy`), and what damping took of it at the end (`damped`, none undamped).
pub fn balance(
    loading: Loading,
    damping: Damping,
    height: f64,
    zone: f64,
) -> anyhow::Result<(CaseReport, f64)> {
    let start = Instant::now();
    let (e, nu, rho) = ROCK;
    let w = 2.0;
    let ricker = serde_json::json!({ "pulse": "ricker", "amplitude": 1, "frequency": FREQUENCY });
    let sides = [
        serde_json::json!({ "part": "left", "fix": "x" }),
        serde_json::json!({ "part": "right", "fix": "x" }),
    ];
    let (base, top) = match loading {
        Loading::Step | Loading::JointedStep => (
            serde_json::json!({ "part": "base", "fix": "xy" }),
            Some(serde_json::json!({ "part": "top", "normal_stress": -1e6 })),
        ),
        Loading::Pulse => (
            serde_json::json!({ "part": "base", "quiet": true }),
            Some(serde_json::json!({ "part": "top", "normal_stress": -1e6, "history": ricker })),
        ),
        Loading::Shaken => (
            serde_json::json!({ "part": "base", "motion": { "direction": "y",
                "velocity": { "pulse": "ricker", "amplitude": 1, "frequency": FREQUENCY } } }),
            None,
        ),
        Loading::Incident => (
            serde_json::json!({ "part": "base", "quiet": true,
                "incident": { "wave": "p", "velocity": 1, "pulse": "ricker", "frequency": FREQUENCY } }),
            None,
        ),
    };
    let mut boundary = vec![base, sides[0].clone(), sides[1].clone()];
    boundary.extend(top);
    // Long enough for the wave to cross the column three times (the step rings; the pulses leave).
    let duration = 2.4 / FREQUENCY + 3.0 * height / wave_speed(WaveKind::P);
    let terms = [
        ("kinetic", "kinetic_energy"),
        ("strain", "strain_energy"),
        ("work", "boundary_work"),
        ("quiet", "quiet_energy"),
        ("joints", "joint_energy"),
        ("damping", "damping_energy"),
        ("error", "energy_error"),
    ];
    let joints: Vec<_> = match loading {
        Loading::JointedStep => [1.0, 2.0]
            .map(|k| {
                let y = k * height / 3.0;
                serde_json::json!({ "from": [0, y], "to": [w, y], "material": "joint" })
            })
            .to_vec(),
        _ => Vec::new(),
    };
    let histories: Vec<_> = (terms.iter())
        .map(|(n, q)| serde_json::json!({ "name": n, "quantity": q }))
        .collect();
    // Its own name, so that runs side by side (the tests') write their own folders.
    let name: String = format!("energy_{loading:?}_{damping:?}_{zone}")
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    let mut text = serde_json::json!({
        "name": name,
        "materials": { "rock": { "density": rho, "young": e, "poisson": nu } },
        "region": { "polygon": [[0, 0], [w, 0], [w, height], [0, height]],
                    "edge_names": ["base", "right", "top", "left"], "material": "rock" },
        "zoning": { "edge_at_excavation": zone, "edge_far": zone },
        "boundary": boundary,
        "solve": { "mode": "dynamic", "duration": duration, "monitor_every": 1,
                   "max_cycles": 1_000_000 },
        "histories": histories,
        "output": { "checkpoints": false, "every": 0 }
    });
    for (key, value) in damping.fields(height).as_object().expect("fields") {
        text["solve"][key] = value.clone();
    }
    if !joints.is_empty() {
        text["joint_materials"] = serde_json::json!({ "joint": { "law": "glued",
            "normal_stiffness": JOINT_STIFFNESS, "shear_stiffness": JOINT_STIFFNESS } });
        text["joints"] = serde_json::Value::Array(joints);
    }
    let scene = adit::Scene::from_json(&text.to_string(), "energy").expect("a valid column");
    let (r, csv) = run_to_completion(&scene)?;
    let column = |name: &str| values_after(&csv, name, 0);
    let (work, quiet, error) = (column("work")?, column("quiet")?, column("error")?);
    // What entered: the loads' work, or the incident wave's (the quiet term's most negative).
    let entered = (work.iter().zip(&quiet))
        .map(|(w, q)| w.abs().max(-q))
        .fold(0.0, f64::max);
    anyhow::ensure!(entered > 0.0, "energy balance: nothing entered the column");
    let worst = error.iter().fold(0.0f64, |m, e| m.max(e.abs()));
    let relative = worst / entered;
    let took = column("damping")?.last().copied().unwrap_or(0.0) / entered;
    let mut errors = vec![("energy", relative)];
    if damping != Damping::None {
        errors.push(("damped", took));
    }
    let report = CaseReport::new(
        format!(
            "{} m column, {}, zones {zone} m, {}",
            height,
            loading.label(),
            damping.label()
        ),
        r.summary.zones,
        r.summary.cycles,
        start.elapsed().as_secs_f64(),
        Some(zone),
        &errors,
    );
    Ok((report, relative))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The coarse twin of the report's section: each loading's balance closes within 1 % of the
    /// energy that entered, on zones of 1 m.
    #[test]
    fn the_energy_balance_closes() {
        for loading in [
            Loading::Step,
            Loading::Pulse,
            Loading::Incident,
            Loading::JointedStep,
            Loading::Shaken,
        ] {
            let (report, relative) = balance(loading, Damping::None, 40.0, 1.0).unwrap();
            assert!(relative < 0.01, "{loading:?}: {:?}", report.errors);
        }
    }

    /// With damping, the balance counts what it took: it closes within 1 % of what entered,
    /// and damping took a real share of it.
    #[test]
    fn the_energy_balance_counts_damping() {
        for damping in [
            Damping::Local(0.1),
            Damping::Rayleigh(0.05, "mass"),
            Damping::Rayleigh(0.05, "stiffness"),
        ] {
            let (report, relative) = balance(Loading::Step, damping, 40.0, 1.0).unwrap();
            assert!(relative < 0.01, "{damping:?}: {:?}", report.errors);
            assert!(
                report.errors["damped"] > 0.02,
                "{damping:?}: {:?}",
                report.errors
            );
        }
    }
}
