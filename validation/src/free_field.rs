//! Free-field boundaries (issue 50): a vertically travelling plane wave through a box whose base
//! is quiet and whose sides are free-field (`boundary[i].free_field`) behaves as in the
//! one-dimensional column: the free top moves at twice the incident velocity everywhere across
//! it, the sides included. The same box with plain quiet sides (no free field) shows why the
//! free field is needed: their dashpots take the wave's motion.

use std::time::Instant;

use adit::scene::WaveKind;

use crate::quiet::{ROCK, history, run_to_completion, wave_speed};
use crate::report::CaseReport;

/// The incident wavelet's peak particle velocity (m/s) and frequency (Hz).
const PEAK: f64 = 1.0;
const FREQUENCY: f64 = 10.0;

/// A box `width` × `height` m zoned at `zone` m, its base quiet with a Ricker `wave` coming in,
/// its sides free-field (or, without `free_field`, plain quiet), horizontal glued joints every
/// `joint_spacing` m if given.
#[derive(Debug, Clone, Copy)]
pub struct FreeFieldBox {
    pub wave: WaveKind,
    pub width: f64,
    pub height: f64,
    pub zone: f64,
    pub free_field: bool,
    pub joint_spacing: Option<f64>,
}

impl FreeFieldBox {
    /// Run it: the report, with the largest |peak velocity / 2v₀ − 1| at the top's points at 0,
    /// ¼, ½ and 1 of the width (`surface`), and the dynamic stage's share of the cycling seconds
    /// (the quiet and free-field boundaries; `stage_seconds.dynamics`).
    pub fn run(&self) -> anyhow::Result<(CaseReport, f64, f64)> {
        let start = Instant::now();
        let (e, nu, rho) = ROCK;
        let (w, h) = (self.width, self.height);
        let (wave, component) = match self.wave {
            WaveKind::P => ("p", "velocity_y"),
            WaveKind::S => ("s", "velocity_x"),
        };
        let side = |part: &str| serde_json::json!({ "part": part, "quiet": true, "free_field": self.free_field });
        let points = [0.0, 0.25, 0.5, 1.0];
        let histories: Vec<_> = (points.iter().enumerate())
            .map(|(k, f)| {
                serde_json::json!({ "name": format!("top{k}"), "at": [f * w, h], "quantity": component })
            })
            .collect();
        let duration = 2.4 / FREQUENCY + h / wave_speed(self.wave) + 1.2 / FREQUENCY;
        let mut text = serde_json::json!({
            "name": "free_field_box",
            "materials": { "rock": { "density": rho, "young": e, "poisson": nu } },
            "region": { "polygon": [[0, 0], [w, 0], [w, h], [0, h]],
                        "edge_names": ["base", "right", "top", "left"], "material": "rock" },
            "zoning": { "edge_at_excavation": self.zone, "edge_far": self.zone },
            "boundary": [
                { "part": "base", "quiet": true,
                  "incident": { "wave": wave, "velocity": PEAK, "pulse": "ricker", "frequency": FREQUENCY } },
                side("left"), side("right")
            ],
            "solve": { "mode": "dynamic", "duration": duration, "damping": 0, "monitor_every": 1,
                       "max_cycles": 1_000_000 },
            "histories": histories,
            "output": { "checkpoints": false, "every": 0 }
        });
        if let Some(s) = self.joint_spacing {
            // Glued joints of kn = ks = 2e10 Pa/m pass most of a 10 Hz wave (ωZ/2κ ≈ 0.05).
            text["joint_materials"] = serde_json::json!({ "j": {
                "law": "glued", "normal_stiffness": 2e10, "shear_stiffness": 2e10 } });
            text["joint_sets"] = serde_json::json!([{ "material": "j", "dip": 0, "spacing": s, "origin": [0, 0.5 * s] }]);
        }
        let scene = adit::Scene::from_json(&text.to_string(), "free field").expect("a valid box");
        let (r, csv) = run_to_completion(&scene)?;
        let mut worst = 0.0f64;
        for k in 0..points.len() {
            let peak = (history(&csv, &format!("top{k}"))?.iter())
                .map(|(_, v)| v.abs())
                .fold(0.0, f64::max);
            worst = worst.max((peak / (2.0 * PEAK) - 1.0).abs());
        }
        let report = CaseReport::new(
            format!(
                "{} wave up a {w} m × {h} m box, zones {} m, {} sides{}",
                wave.to_uppercase(),
                self.zone,
                if self.free_field {
                    "free-field"
                } else {
                    "plain quiet"
                },
                self.joint_spacing
                    .map_or(String::new(), |s| format!(", glued joints every {s} m"))
            ),
            r.summary.zones,
            r.summary.cycles,
            start.elapsed().as_secs_f64(),
            Some(self.zone),
            &[("surface", worst)],
        );
        let s = r.summary.stage_seconds;
        let cycling = s.detect + s.contacts + s.zones + s.supports + s.motion + s.dynamics;
        let share = if cycling > 0.0 {
            s.dynamics / cycling
        } else {
            0.0
        };
        Ok((report, worst, share))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The coarse twin of the report's section: an S and a P wave up a box with free-field sides
    /// double at the top within 2 % across it; with plain quiet sides the S wave does not.
    #[test]
    fn free_field_sides_pass_a_vertical_wave() {
        for wave in [WaveKind::S, WaveKind::P] {
            let run = FreeFieldBox {
                wave,
                width: 40.0,
                height: 40.0,
                zone: 2.0,
                free_field: true,
                joint_spacing: None,
            };
            let (report, worst, _) = run.run().unwrap();
            assert!(worst < 0.02, "{wave:?}: {:?}", report.errors);
        }
        let plain = FreeFieldBox {
            wave: WaveKind::S,
            width: 40.0,
            height: 40.0,
            zone: 2.0,
            free_field: false,
            joint_spacing: None,
        };
        let (_, worst, _) = plain.run().unwrap();
        assert!(worst > 0.2, "plain quiet sides: {worst}");
    }
}
