//! A history of time, t in s from the start of the dynamic stage: an incident wave's particle
//! velocity (`boundary[i].incident`, m/s), a prescribed velocity or acceleration
//! (`boundary[i].motion`, m/s or m/s²):
//!
//! - Ricker wavelet: h = A (1 − 2π²f²τ²) exp(−π²f²τ²), τ = t − t₀ (its peak A at t₀; default
//!   t₀ = 1.2/f, where the wavelet has risen from 2e-5 A);
//! - half sine: h = A sin(2πf τ) for 0 ≤ τ ≤ 1/(2f), τ = t − t₀ (a pulse of duration 1/(2f));
//! - sine: h = A sin(2πf τ) for 0 ≤ τ ≤ n/f (n cycles; unending without `cycles`);
//! - a table of (t, h), linear between its points and 0 outside them.

use crate::scene::{PulseKind, SignalSpec};

/// Default delay of a Ricker wavelet's peak, in periods 1/f.
pub const RICKER_DELAY_PERIODS: f64 = 1.2;

/// A history (its unit the quantity's).
#[derive(Debug, Clone, PartialEq)]
pub enum History {
    Ricker {
        peak: f64,
        frequency: f64,
        delay: f64,
    },
    HalfSine {
        peak: f64,
        frequency: f64,
        delay: f64,
    },
    Sine {
        peak: f64,
        frequency: f64,
        delay: f64,
        cycles: f64,
    },
    Table(Vec<[f64; 2]>),
}

impl History {
    /// The history a scene gives (validated: a pulse with its amplitude and frequency, or a
    /// table).
    pub fn of(spec: &SignalSpec) -> History {
        if let Some(table) = &spec.table {
            return History::Table(table.clone());
        }
        let (peak, frequency) = (spec.amplitude.unwrap_or(0.0), spec.frequency.unwrap_or(1.0));
        match spec.pulse.unwrap_or(PulseKind::Ricker) {
            PulseKind::Ricker => History::Ricker {
                peak,
                frequency,
                delay: spec.delay.unwrap_or(RICKER_DELAY_PERIODS / frequency),
            },
            PulseKind::HalfSine => History::HalfSine {
                peak,
                frequency,
                delay: spec.delay.unwrap_or(0.0),
            },
            PulseKind::Sine => History::Sine {
                peak,
                frequency,
                delay: spec.delay.unwrap_or(0.0),
                cycles: spec.cycles.unwrap_or(f64::INFINITY),
            },
        }
    }

    /// h(t).
    pub fn at(&self, t: f64) -> f64 {
        use std::f64::consts::{PI, TAU};
        match *self {
            History::Ricker {
                peak,
                frequency,
                delay,
            } => {
                let a = (PI * frequency * (t - delay)).powi(2);
                peak * (1.0 - 2.0 * a) * (-a).exp()
            }
            History::HalfSine {
                peak,
                frequency,
                delay,
            } => {
                let tau = t - delay;
                if (0.0..=0.5 / frequency).contains(&tau) {
                    peak * (TAU * frequency * tau).sin()
                } else {
                    0.0
                }
            }
            History::Sine {
                peak,
                frequency,
                delay,
                cycles,
            } => {
                let tau = t - delay;
                if tau >= 0.0 && tau * frequency <= cycles {
                    peak * (TAU * frequency * tau).sin()
                } else {
                    0.0
                }
            }
            History::Table(ref points) => table_at(points, t),
        }
    }

    /// The interval (s) outside which the history is nil or negligible: a Ricker wavelet's
    /// t₀ ± 1.5/f (where it is below 1e-8 of its peak; from 0 when it starts earlier), a half
    /// sine's or a sine's cycles, a table's first to last time; `None` for an unending sine.
    pub fn support(&self) -> Option<(f64, f64)> {
        match *self {
            History::Ricker {
                frequency, delay, ..
            } => Some(((delay - 1.5 / frequency).max(0.0), delay + 1.5 / frequency)),
            History::HalfSine {
                frequency, delay, ..
            } => Some((delay, delay + 0.5 / frequency)),
            History::Sine {
                frequency,
                delay,
                cycles,
                ..
            } => cycles
                .is_finite()
                .then(|| (delay, delay + cycles / frequency)),
            History::Table(ref points) => Some((points.first()?[0], points.last()?[0])),
        }
    }

    /// The highest frequency the history carries appreciably, Hz: a Ricker wavelet's amplitude
    /// spectrum, ∝ (f/f₀)² exp(1 − (f/f₀)²), stays below 5 % of its peak above 2.4 f₀; a half
    /// sine's main lobe ends at 3f (its first zero, the pulse lasting 1/(2f)); a sine is f; a
    /// table resolves up to the Nyquist frequency of its closest points, 1/(2 Δt).
    pub fn highest_frequency(&self) -> f64 {
        match *self {
            History::Ricker { frequency, .. } => RICKER_HIGHEST * frequency,
            History::HalfSine { frequency, .. } => 3.0 * frequency,
            History::Sine { frequency, .. } => frequency,
            History::Table(ref points) => {
                let closest = (points.windows(2))
                    .map(|w| w[1][0] - w[0][0])
                    .filter(|&d| d > 0.0)
                    .fold(f64::INFINITY, f64::min);
                if closest.is_finite() {
                    0.5 / closest
                } else {
                    0.0
                }
            }
        }
    }
}

/// A Ricker wavelet's highest appreciable frequency over its peak frequency: its amplitude
/// spectrum x e^(1 − x), x = (f/f₀)², is 5 % of its peak at x = 5.75.
const RICKER_HIGHEST: f64 = 2.4;

/// A table's value at `t`: linear between its points (times increasing), 0 outside them.
fn table_at(points: &[[f64; 2]], t: f64) -> f64 {
    let k = points.partition_point(|p| p[0] <= t);
    if k == 0 || k == points.len() {
        return if k == points.len() && points.last().is_some_and(|p| p[0] == t) {
            points[k - 1][1]
        } else {
            0.0
        };
    }
    let ([t0, v0], [t1, v1]) = (points[k - 1], points[k]);
    v0 + (v1 - v0) * (t - t0) / (t1 - t0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Ricker wavelet peaks at its delay with its amplitude, crosses zero at τ = ±1/(π f √2)
    /// and has risen from 2e-5 of it at t = 0 by default.
    #[test]
    fn a_ricker_wavelet_peaks_at_its_delay() {
        let r = History::Ricker {
            peak: 0.5,
            frequency: 20.0,
            delay: 1.2 / 20.0,
        };
        assert_eq!(r.at(0.06), 0.5);
        let zero = 1.0 / (std::f64::consts::PI * 20.0 * 2f64.sqrt());
        assert!(r.at(0.06 + zero).abs() < 1e-15 && r.at(0.06 - zero).abs() < 1e-15);
        assert!(r.at(0.0).abs() < 2e-5 * 0.5, "{}", r.at(0.0));
    }

    /// The half sine lasts half a period; the sine its cycles; a table interpolates and is 0
    /// beyond its ends.
    #[test]
    fn pulses_and_tables_start_and_stop() {
        let h = History::HalfSine {
            peak: 2.0,
            frequency: 10.0,
            delay: 0.01,
        };
        assert_eq!(h.at(0.005), 0.0);
        assert!((h.at(0.035) - 2.0).abs() < 1e-12);
        assert_eq!(h.at(0.0601), 0.0);
        let s = History::Sine {
            peak: 1.0,
            frequency: 5.0,
            delay: 0.0,
            cycles: 2.0,
        };
        assert!((s.at(0.05) - 1.0).abs() < 1e-12 && s.at(0.41) == 0.0);
        let t = History::Table(vec![[0.1, 0.0], [0.2, 1.0], [0.4, -1.0]]);
        for (at, v) in [
            (0.05, 0.0),
            (0.15, 0.5),
            (0.3, 0.0),
            (0.4, -1.0),
            (0.5, 0.0),
        ] {
            assert!((t.at(at) - v).abs() < 1e-15, "{at}: {}", t.at(at));
        }
    }
}
