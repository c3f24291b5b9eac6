//! A harmonic S wave across a Coulomb joint that slips (issue 50) against Miller's analysis
//! (Miller 1978, "An approximate method of analysing the effects of a single joint on the
//! transmission of a shear wave", the verification problem UDEC's and 3DEC's manuals give for
//! their dynamic option).
//!
//! A plane S wave of stress τᵢ(t) = τ₀ sin ωt meets a joint normal to its path that is rigid
//! until its shear stress reaches its strength τs = σn tan φ, then slips at that stress. With
//! the same rock of impedance Z = ρCs on both sides, the traction is continuous, τᵢ + τr = τt,
//! and the two sides move alike while the joint sticks (τr = 0, τt = τᵢ); while it slips,
//! τt = ±τs and τr = ±τs − τᵢ, and the slip rate 2(|τᵢ| − τs)/Z keeps it slipping exactly while
//! |τᵢ| > τs. The joint clips the transmitted stress at ±τs. Over a half period, with
//! R = τs/τ₀ and θ₀ = asin R, the energy fluxes Z⁻¹∫τ² dt against the incident one:
//!
//!   transmitted  E_T = [θ₀ − ½ sin 2θ₀ + R²(π − 2θ₀)] / (π/2),
//!   reflected    E_R = [½(π − 2θ₀) + ½ sin 2θ₀ − 4R cos θ₀ + R²(π − 2θ₀)] / (π/2),
//!
//! and the joint's friction takes the rest, 1 − E_T − E_R (R → 0 reflects all, R → 1 passes
//! all). Every half period clips alike whatever the slip before it, so a train of whole
//! cycles has the same ratios.
//!
//! The run: a column of elastic rock under a uniform vertical stress σn, held by its fixed base
//! and top in a static stage, then a dynamic one whose base and top are quiet (holding the
//! fixities' reactions), its sides on rollers, cut across by one Coulomb joint
//! whose friction gives τs = R τ₀; a train of `CYCLES` sine cycles enters through the base. A
//! gauge far enough below the joint sees the incident train pass before the reflected one
//! arrives; a gauge above it sees the transmitted one. The energy fluxes are ∫ v² dt of their
//! velocities (the flux of a plane wave is Z v²). The energy balance's `joint_energy` at the end
//! is what the joint's friction took, against Miller's 1 − E_T − E_R of the incident energy.

use std::f64::consts::PI;
use std::time::Instant;

use adit::scene::WaveKind;

use crate::quiet::{ROCK, history_after, run_to_completion, values_after, wave_speed};
use crate::report::CaseReport;

/// The wave's frequency, Hz, its peak particle velocity, m/s, and the cycles of its train.
const FREQUENCY: f64 = 25.0;
const PEAK: f64 = 0.1;
const CYCLES: f64 = 2.0;
/// The static normal stress on the joint, Pa (compression negative): it keeps the joint closed
/// and sets its strength σn tan φ.
const NORMAL_STRESS: f64 = -1e6;
/// ωZ/2κ of the joint's elastic springs at the wave's frequency: stiff enough that a joint that
/// sticks passes the wave whole (|T| = 1 − 2e-4), as Miller's rigid joint.
const COMPLIANCE: f64 = 0.02;
/// The column's width, m; the rock below the lower gauge, between the gauges and the joint, and
/// above the upper gauge, m.
const WIDTH: f64 = 2.0;
const BELOW: f64 = 10.0;
const ABOVE: f64 = 10.0;

/// Miller's energy ratios at a strength ratio R = τs/τ₀ in [0, 1].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Energies {
    pub transmitted: f64,
    pub reflected: f64,
}

impl Energies {
    /// The closed form (module docs).
    pub fn miller(ratio: f64) -> Energies {
        let r = ratio.clamp(0.0, 1.0);
        let t0 = r.asin();
        let slipping = PI - 2.0 * t0;
        let half = 0.5 * PI;
        Energies {
            transmitted: (t0 - 0.5 * (2.0 * t0).sin() + r * r * slipping) / half,
            reflected: (0.5 * slipping + 0.5 * (2.0 * t0).sin() - 4.0 * r * t0.cos()
                + r * r * slipping)
                / half,
        }
    }

    /// What the joint's friction takes: 1 − E_T − E_R.
    pub fn dissipated(&self) -> f64 {
        1.0 - self.transmitted - self.reflected
    }
}

/// A harmonic S wave of stress amplitude τ₀ across a joint of strength `ratio` τ₀, in a column
/// zoned at `zone` m.
#[derive(Debug, Clone, Copy)]
pub struct Slip {
    pub ratio: f64,
    pub zone: f64,
}

/// A measured run against Miller's ratios.
pub struct Measured {
    pub report: CaseReport,
    pub measured: Energies,
    pub exact: Energies,
}

impl Slip {
    /// The distance from the lower gauge to the joint, m: the incident train has passed the
    /// gauge, with half a period to spare, when the reflected one comes back to it.
    fn gap() -> f64 {
        0.5 * wave_speed(WaveKind::S) * (CYCLES + 0.5) / FREQUENCY
    }

    /// The heights of the lower gauge, the joint, the upper gauge and the top, m.
    fn levels() -> [f64; 4] {
        let joint = BELOW + Self::gap();
        [BELOW, joint, joint + ABOVE, joint + 2.0 * ABOVE]
    }

    /// The record's length in the dynamic stage: until the reflected train and half a period
    /// after it have passed the lower gauge, s.
    fn duration() -> f64 {
        (BELOW + 2.0 * Self::gap()) / wave_speed(WaveKind::S) + (CYCLES + 0.5) / FREQUENCY
    }

    /// The time that parts the incident train at the lower gauge from the reflected one, a
    /// quarter period after the first has passed, s.
    fn parting() -> f64 {
        BELOW / wave_speed(WaveKind::S) + (CYCLES + 0.25) / FREQUENCY
    }

    /// The joint's friction angle, degrees: σn tan φ = R τ₀, τ₀ = Z v₀.
    fn friction(&self) -> f64 {
        let tau0 = ROCK.2 * wave_speed(WaveKind::S) * PEAK;
        (self.ratio * tau0 / -NORMAL_STRESS).atan().to_degrees()
    }

    fn scene(&self) -> adit::Scene {
        let (e, nu, rho) = ROCK;
        let [low, joint, high, top] = Self::levels();
        let w = WIDTH;
        let stiffness = PI * FREQUENCY * rho * wave_speed(WaveKind::S) / COMPLIANCE;
        let sides = [("left", "y"), ("right", "y")]
            .map(|(part, fix)| serde_json::json!({ "part": part, "fix": fix }));
        let text = serde_json::json!({
            "name": "miller",
            "materials": { "rock": { "density": rho, "young": e, "poisson": nu } },
            "region": { "polygon": [[0, 0], [w, 0], [w, top], [0, top]],
                        "edge_names": ["base", "right", "top", "left"], "material": "rock" },
            "zoning": { "edge_at_excavation": self.zone, "edge_far": self.zone },
            "in_situ": { "sxx": 0, "syy": NORMAL_STRESS, "sxy": 0 },
            "joint_materials": { "joint": { "law": "coulomb", "normal_stiffness": stiffness,
                                            "shear_stiffness": stiffness,
                                            "friction": self.friction() } },
            "joints": [{ "from": [0, joint], "to": [w, joint], "material": "joint" }],
            "boundary": [sides[0], sides[1], { "part": "base", "fix": "xy" },
                         { "part": "top", "fix": "y" }],
            "solve": { "ratio": 1e-8, "method": "implicit" },
            "stages": [
                { "name": "in situ" },
                { "name": "wave",
                  "boundary": [sides[0], sides[1],
                      { "part": "base", "quiet": true,
                        "incident": { "wave": "s", "velocity": PEAK, "pulse": "sine",
                                      "frequency": FREQUENCY, "cycles": CYCLES } },
                      { "part": "top", "quiet": true }],
                  "solve": { "mode": "dynamic", "duration": Self::duration(), "damping": 0,
                             "monitor_every": 1, "max_cycles": 10_000_000 } }
            ],
            "histories": [{ "name": "below", "at": [0, low], "quantity": "velocity_x" },
                          { "name": "above", "at": [0, high], "quantity": "velocity_x" },
                          { "name": "joint", "quantity": "joint_energy" },
                          { "name": "error", "quantity": "energy_error" }],
            "output": { "checkpoints": false, "every": 0 }
        });
        adit::Scene::from_json(&text.to_string(), "miller").expect("a valid column")
    }

    /// Run the column and measure the transmitted and reflected energy against the incident.
    pub fn run(&self) -> anyhow::Result<Measured> {
        let start = Instant::now();
        let (r, csv) = run_to_completion(&self.scene())?;
        let settled = r.summary.stages[0].cycles;
        let below = history_after(&csv, "below", settled)?;
        let above = history_after(&csv, "above", settled)?;
        let split = Self::parting();
        let incident = flux(&below, |t| t < split);
        let measured = Energies {
            transmitted: flux(&above, |_| true) / incident,
            reflected: flux(&below, |t| t >= split) / incident,
        };
        // The energy the train brought in, J/m (flux Z v² over the column's width), against what
        // the joint took (its friction: its springs hold nothing once the wave has passed) and
        // what the balance leaves unaccounted.
        let brought = ROCK.2 * wave_speed(WaveKind::S) * incident * WIDTH;
        let values = |name: &str| values_after(&csv, name, settled);
        let joint = values("joint")?.last().copied().unwrap_or(f64::NAN) / brought;
        let unaccounted = values("error")?.iter().fold(0.0f64, |m, e| m.max(e.abs())) / brought;
        let exact = Energies::miller(self.ratio);
        let report = CaseReport::new(
            format!(
                "S wave {PEAK} m/s at {FREQUENCY} Hz ({CYCLES} cycles) across a Coulomb joint, \
                 τs/τ₀ = {} (φ {:.2}° under {} MPa): transmitted {:.4} (Miller {:.4}), \
                 reflected {:.4} ({:.4}), dissipated {:.4} ({:.4}; the joint's energy {:.4})",
                self.ratio,
                self.friction(),
                -NORMAL_STRESS / 1e6,
                measured.transmitted,
                exact.transmitted,
                measured.reflected,
                exact.reflected,
                measured.dissipated(),
                exact.dissipated(),
                joint,
            ),
            r.summary.zones,
            r.summary.cycles,
            start.elapsed().as_secs_f64(),
            Some(self.zone),
            &[
                (
                    "transmitted",
                    (measured.transmitted - exact.transmitted).abs(),
                ),
                ("reflected", (measured.reflected - exact.reflected).abs()),
                ("dissipated", (joint - exact.dissipated()).abs()),
                ("energy", unaccounted),
            ],
        );
        Ok(Measured {
            report,
            measured,
            exact,
        })
    }
}

/// ∫ v² dt over the samples whose time `keep` takes, by the trapezoidal rule, m²/s.
fn flux(samples: &[(f64, f64)], keep: impl Fn(f64) -> bool) -> f64 {
    (samples.windows(2))
        .filter(|w| keep(w[0].0) && keep(w[1].0))
        .map(|w| 0.5 * (w[1].0 - w[0].0) * (w[0].1 * w[0].1 + w[1].1 * w[1].1))
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed form against a direct quadrature of the clipped sine over a half period, and
    /// its ends: a joint without strength reflects everything, one as strong as the wave passes
    /// everything.
    #[test]
    fn millers_ratios_are_the_clipped_sines() {
        for ratio in [0.1, 0.25, 0.5, 0.75, 0.9] {
            let n = 200_000;
            let (mut inc, mut tr, mut re) = (0.0, 0.0, 0.0);
            for k in 0..n {
                let s = (PI * (k as f64 + 0.5) / n as f64).sin();
                let t = s.min(ratio);
                inc += s * s;
                tr += t * t;
                re += (s - t) * (s - t);
            }
            let e = Energies::miller(ratio);
            assert!((e.transmitted - tr / inc).abs() < 1e-8, "{ratio}: {e:?}");
            assert!((e.reflected - re / inc).abs() < 1e-8, "{ratio}: {e:?}");
            assert!(e.dissipated() > 0.0);
        }
        let (none, all) = (Energies::miller(0.0), Energies::miller(1.0));
        assert!(none.transmitted.abs() < 1e-15 && (none.reflected - 1.0).abs() < 1e-15);
        assert!((all.transmitted - 1.0).abs() < 1e-15 && all.reflected.abs() < 1e-15);
    }

    /// The coarse twin of the report's rows, on 1 m zones: the transmitted and reflected energy,
    /// and the energy balance's joint energy, within ±0.03 of Miller's at two strength ratios;
    /// the balance closing within 1 % of the energy the wave brought.
    #[test]
    fn a_slipping_joint_clips_the_wave_as_miller_says() {
        for ratio in [0.25, 0.75] {
            let m = Slip { ratio, zone: 1.0 }.run().unwrap();
            let e = &m.report.errors;
            assert!(
                e["transmitted"] < 0.03 && e["reflected"] < 0.03 && e["dissipated"] < 0.03,
                "{:?}",
                m.report
            );
            assert!(e["energy"] < 0.01, "{:?}", m.report);
        }
    }
}
