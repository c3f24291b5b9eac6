//! A prescribed motion of a boundary part (`boundary[i].motion`; UDEC's and FLAC's velocity
//! boundary with a history): each node of the part has one component held (x or y) whose velocity
//! follows a history, m/s, given as a velocity or integrated from an acceleration (`Integrated`).
//! The motion stage keeps a held component's velocity and moves the node by it, so the stage
//! sets it first to the velocity at the middle of the step, v(t + Δt/2): the central difference's
//! velocities live at half steps, and the node's displacement over the step, v(t + Δt/2) Δt, is
//! the midpoint rule's ∫v dt.

use crate::scene::MotionSpec;

use super::History;

/// One part's motion: its nodes, the component held (0 x, 1 y) and its velocity.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Motion {
    pub nodes: Vec<u32>,
    pub axis: usize,
    velocity: Velocity,
}

/// A velocity history, m/s: given, or integrated from an acceleration.
#[derive(Debug, Clone, PartialEq)]
enum Velocity {
    Given(History),
    Integrated(Integrated),
}

impl Motion {
    /// The motion `spec` gives the nodes `nodes` (validated: one of a velocity and an
    /// acceleration, an acceleration's record ending).
    pub fn new(spec: &MotionSpec, nodes: Vec<u32>) -> Motion {
        let velocity = match (&spec.velocity, &spec.acceleration) {
            (Some(v), _) => Velocity::Given(History::of(v)),
            (None, Some(a)) => {
                Velocity::Integrated(Integrated::new(&History::of(a), spec.baseline))
            }
            (None, None) => Velocity::Given(History::Table(Vec::new())),
        };
        Motion {
            nodes,
            axis: spec.direction.index(),
            velocity,
        }
    }

    /// Before the motion stage of the step from `time` to `time + dt` (s since the stage
    /// began): each held component's velocity to the history's at `time + dt/2`, m/s.
    pub fn impose(&self, vel: &mut [[f64; 2]], time: f64, dt: f64) {
        let v = match &self.velocity {
            Velocity::Given(h) => h.at(time + 0.5 * dt),
            Velocity::Integrated(i) => i.velocity(time + 0.5 * dt),
        };
        for &n in &self.nodes {
            vel[n as usize][self.axis] = v;
        }
    }
}

/// Samples per period 1/f of a pulse integrated as an acceleration: the piecewise-linear
/// acceleration through them departs from the pulse by at most (2π/200)²/8 ≈ 1.2e-4 of its peak.
const SAMPLES_PER_PERIOD: f64 = 200.0;

/// A velocity integrated from an acceleration a(t), m/s² (piecewise linear through samples
/// tₖ, aₖ: a table's points, or a pulse sampled `SAMPLES_PER_PERIOD` times a period over its
/// `History::support`), exactly:
///
///   v(t) = vₖ + aₖ τ + (aₖ₊₁ − aₖ) τ²/(2Δₖ),  τ = t − tₖ,  Δₖ = tₖ₊₁ − tₖ,
///
/// vₖ₊₁ = vₖ + (aₖ + aₖ₊₁) Δₖ/2 from v₀ = 0; before the record v = 0, after it v keeps its final
/// value (the acceleration is then 0). With the baseline corrected, the straight line
/// δa(s) = c₁ + 2c₂ s, s = t − t₀, is taken off the acceleration over the record [t₀, t₀ + T]:
/// the velocity less δv = c₁ s + c₂ s² with δv(T) = V and ∫₀ᵀ δv ds = U, V and U the record's final
/// velocity and displacement, so that it ends at rest where it began:
///
///   c₂ = (3VT − 6U)/T³,  c₁ = V/T − c₂ T
///
/// (a low-order baseline correction as for strong-motion records; Boore & Bommer 2005 review
/// them).
#[derive(Debug, Clone, PartialEq)]
pub struct Integrated {
    times: Vec<f64>,
    accel: Vec<f64>,
    vel: Vec<f64>,
    /// The baseline's c₁ (m/s²) and c₂ (m/s³), zero when not corrected.
    baseline: [f64; 2],
}

impl Integrated {
    /// The velocity of the acceleration `a` (whose record ends: `History::support`; an unending
    /// one is taken as nil), its baseline corrected if `baseline`.
    pub fn new(a: &History, baseline: bool) -> Integrated {
        let (times, accel) = samples(a);
        let mut vel = vec![0.0; times.len()];
        let mut disp = 0.0;
        for k in 1..times.len() {
            let d = times[k] - times[k - 1];
            vel[k] = vel[k - 1] + 0.5 * (accel[k - 1] + accel[k]) * d;
            disp += vel[k - 1] * d + (2.0 * accel[k - 1] + accel[k]) * d * d / 6.0;
        }
        let span = match (times.first(), times.last()) {
            (Some(a), Some(b)) => b - a,
            _ => 0.0,
        };
        let baseline = if baseline && span > 0.0 {
            let v = *vel.last().expect("a sample");
            let c2 = (3.0 * v * span - 6.0 * disp) / span.powi(3);
            [v / span - c2 * span, c2]
        } else {
            [0.0; 2]
        };
        Integrated {
            times,
            accel,
            vel,
            baseline,
        }
    }

    /// v(t), m/s (the baseline taken off).
    pub fn velocity(&self, t: f64) -> f64 {
        let Some(&start) = self.times.first() else {
            return 0.0;
        };
        if t <= start {
            return 0.0;
        }
        let end = *self.times.last().expect("a sample");
        let s = t.min(end) - start;
        let correction = self.baseline[0] * s + self.baseline[1] * s * s;
        let k = self.times.partition_point(|&x| x <= t);
        if k == self.times.len() {
            return self.vel[k - 1] - correction;
        }
        let (k, d) = (k - 1, self.times[k] - self.times[k - 1]);
        let tau = t - self.times[k];
        let slope = (self.accel[k + 1] - self.accel[k]) / d;
        self.vel[k] + self.accel[k] * tau + 0.5 * slope * tau * tau - correction
    }
}

/// The samples (t s, a) of a history over its support: a table's own points, a pulse's at
/// `SAMPLES_PER_PERIOD` per period (both ends included); none for an unending one.
fn samples(a: &History) -> (Vec<f64>, Vec<f64>) {
    if let History::Table(points) = a {
        return points.iter().map(|p| (p[0], p[1])).unzip();
    }
    let Some((t0, t1)) = a.support() else {
        return (Vec::new(), Vec::new());
    };
    let period = 1.0 / a.highest_frequency().max(f64::MIN_POSITIVE);
    let n = (((t1 - t0) / period * SAMPLES_PER_PERIOD).ceil() as usize).max(2);
    (0..=n)
        .map(|k| {
            let t = t0 + (t1 - t0) * k as f64 / n as f64;
            (t, a.at(t))
        })
        .unzip()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A rectangular acceleration pulse (ramps of 1e-6 s) of A for t_p: the velocity rises as A t
    /// and keeps A t_p after it; corrected, the record ends at rest where it began.
    #[test]
    fn a_rectangular_pulse_integrates_to_a_ramp_and_a_plateau() {
        let (a, tp, r) = (3.0, 0.2, 1e-6);
        let table = History::Table(vec![[0.0, 0.0], [r, a], [tp, a], [tp + r, 0.0]]);
        let v = Integrated::new(&table, false);
        assert_eq!(v.velocity(-1.0), 0.0);
        for t in [0.05, 0.1, 0.15] {
            assert!((v.velocity(t) - a * (t - 0.5 * r)).abs() < 1e-12, "{t}");
        }
        for t in [tp + r, 0.3, 10.0] {
            assert!(
                (v.velocity(t) - a * tp).abs() < 1e-12,
                "{t}: {}",
                v.velocity(t)
            );
        }
        let c = Integrated::new(&table, true);
        let end = tp + r;
        assert!(c.velocity(end).abs() < 1e-12 && c.velocity(5.0).abs() < 1e-12);
        // Its displacement, by Simpson's rule on fine steps, returns to 0.
        let n = 20_000;
        let h = end / n as f64;
        let u: f64 = (0..=n)
            .map(|k| {
                let w = if k == 0 || k == n {
                    1.0
                } else if k % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                w * c.velocity(k as f64 * h)
            })
            .sum::<f64>()
            * h
            / 3.0;
        assert!(u.abs() < 1e-9, "{u} m");
    }

    /// A half-sine acceleration A sin(2πf τ) over half a period integrates to
    /// (A/2πf)(1 − cos 2πf τ), ending at A/(πf).
    #[test]
    fn a_half_sine_acceleration_integrates_to_its_closed_form() {
        use std::f64::consts::TAU;
        let (a, f, t0) = (2.0, 5.0, 0.03);
        let h = History::HalfSine {
            peak: a,
            frequency: f,
            delay: t0,
        };
        let v = Integrated::new(&h, false);
        for t in [0.0, 0.04, 0.07, 0.1, 0.13, 0.5] {
            let tau = (t - t0).clamp(0.0, 0.5 / f);
            let exact = a / (TAU * f) * (1.0 - (TAU * f * tau).cos());
            assert!((v.velocity(t) - exact).abs() < 1e-5 * a / f, "{t}");
        }
    }

    /// The held components follow the velocity at the middle of the step; the other stays.
    #[test]
    fn held_components_take_the_midstep_velocity() {
        let spec: MotionSpec = serde_json::from_str(
            r#"{ "direction": "y", "velocity": { "table": [[0, 0], [1, 2]] } }"#,
        )
        .unwrap();
        let motion = Motion::new(&spec, vec![1, 2]);
        let mut vel = [[5.0, 5.0]; 3];
        motion.impose(&mut vel, 0.25, 0.5);
        assert_eq!(vel, [[5.0, 5.0], [5.0, 1.0], [5.0, 1.0]]);
    }
}
