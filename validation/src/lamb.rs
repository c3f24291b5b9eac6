//! Lamb's problem in plane strain (Lamb 1904): a vertical line load on the surface of an elastic
//! half-space, and the motion of the surface at a distance x from it — the closed form a dynamic
//! run with quiet boundaries is checked against (issue 50).
//!
//! The surface's vertical displacement under an impulsive line load P δ(t) (N·s/m) pushing into
//! the half-space, by the Cagniard–de Hoop method (Miklowitz 1978, *The Theory of Elastic Waves
//! and Waveguides*, §7.4), with k = Cp/Cs, τ = Cp t/x (the P wave arrives at τ = 1, the S wave at
//! τ = k), S = k² − 2τ², T = √(τ² − 1), U = √(k² − τ²), V = √(τ² − k²) and
//! G₀ = Cs/(π μ x):
//!
//!   1 ≤ τ < k:  G_z = −G₀ k³ S² T / (S⁴ + 16 τ⁴ T² U²),
//!   τ ≥ k:      G_z = −G₀ k³ T / (S² − 4 τ² T V),
//!
//! (m per N·s/m, positive into the half-space), nil before the P wave. The second form has a
//! simple pole at the Rayleigh wave's arrival τ_R = k Cs/C_R, where S² − 4τ²TV vanishes; C_R
//! solves Rayleigh's equation ξ³ − 8ξ² + (24 − 16/k²) ξ − 16 (1 − 1/k²) = 0, ξ = (C_R/Cs)².
//! At late times G_z → k²/(2π μ (k² − 1) t) = (1 − ν)/(π μ t): the step load's displacement grows
//! as (1 − ν)/(π μ) ln t, Flamant's static logarithm.
//!
//! Under a load history F(t) (N/m, nil before 0) the surface's vertical velocity is the
//! convolution v_z(t) = ∫ F′(t − s) G_z(s) ds, a principal value across the Rayleigh pole: the
//! pole's part A/(s − t_R) is taken out with F′ at the pole and integrated in closed form,
//! A F′(t − t_R) ln|(b − t_R)/(a − t_R)| over the window [a, b]; the rest is bounded and is
//! integrated by Gauss–Legendre panels between the arrivals. A load spread uniformly over a
//! strip of width w is the line load's response averaged over the strip (Gauss points across
//! it).

//! The run (`Surface`): the half-space's right half, x ∈ [0, L], y ∈ [−D, 0] (a vertical load on
//! the axis keeps the other half its mirror: the axis on rollers), its base and far side quiet
//! (Lysmer–Kuhlemeyer dashpots), its surface free but for the strip [0, Δl] beside the axis (the
//! load's half-width one zone) loaded by the normal stress −F(t)/(2Δl), F a Ricker wavelet of
//! peak 1 MN/m; the surface's vertical velocity at three distances, sampled every step, against
//! [`HalfSpace::strip_velocity`] (the closed form is F's rate convolved with G_z, so the run's
//! velocity sampled at its step is compared as it is). Measured over each receiver's record up to
//! the end of its Rayleigh pulse, t_R + the wavelet's length (the waves the quiet boundaries
//! return come later or weakened): the waveform's largest error over the closed form's peak, the
//! P wave's arrival (the first time |v| reaches 2 % of the peak) and the Rayleigh wave's (the time
//! of the peak) against the closed form's, in zone transits Δl/Cp and Δl/C_R.

use std::time::Instant;

use crate::quiet::{ROCK, history, run_to_completion};
use crate::report::CaseReport;

/// An isotropic elastic half-space.
#[derive(Debug, Clone, Copy)]
pub struct HalfSpace {
    /// P and S wave speeds, m/s.
    pub cp: f64,
    pub cs: f64,
    /// Shear modulus μ, Pa.
    pub shear_modulus: f64,
}

impl HalfSpace {
    /// Of Young's modulus E (Pa), Poisson's ratio ν and density ρ (kg/m³), in plane strain.
    pub fn of(young: f64, poisson: f64, density: f64) -> HalfSpace {
        let mu = young / (2.0 * (1.0 + poisson));
        let lambda = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
        HalfSpace {
            cp: ((lambda + 2.0 * mu) / density).sqrt(),
            cs: (mu / density).sqrt(),
            shear_modulus: mu,
        }
    }

    /// k = Cp/Cs.
    fn k(&self) -> f64 {
        self.cp / self.cs
    }

    /// The Rayleigh wave's speed C_R, m/s: the root ξ = (C_R/Cs)² in (0, 1) of Rayleigh's cubic,
    /// by bisection (the cubic is −16(1 − 1/k²) < 0 at 0 and 1 > 0 at 1).
    pub fn rayleigh_speed(&self) -> f64 {
        let k2 = self.k().powi(2);
        let cubic =
            |x: f64| x.powi(3) - 8.0 * x * x + (24.0 - 16.0 / k2) * x - 16.0 * (1.0 - 1.0 / k2);
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if cubic(mid) < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        self.cs * (0.5 * (lo + hi)).sqrt()
    }

    /// The arrival times (s) of the P, S and Rayleigh waves at distance `x` (m).
    pub fn arrivals(&self, x: f64) -> [f64; 3] {
        [x / self.cp, x / self.cs, x / self.rayleigh_speed()]
    }

    /// G_z at distance `x` (m) a time `t` (s) after the impulse: m per N·s/m, positive into the
    /// half-space (the module's formula; unbounded at the Rayleigh arrival).
    pub fn impulse_displacement(&self, x: f64, t: f64) -> f64 {
        let k = self.k();
        let tau = self.cp * t / x;
        if tau < 1.0 {
            return 0.0;
        }
        let g0 = self.cs / (std::f64::consts::PI * self.shear_modulus * x);
        let (k2, tau2) = (k * k, tau * tau);
        let s = k2 - 2.0 * tau2;
        let t_ = (tau2 - 1.0).sqrt();
        if tau < k {
            let u = (k2 - tau2).sqrt();
            -g0 * k.powi(3) * s * s * t_ / (s.powi(4) + 16.0 * tau2 * tau2 * t_ * t_ * u * u)
        } else {
            let v = (tau2 - k2).sqrt();
            -g0 * k.powi(3) * t_ / (s * s - 4.0 * tau2 * t_ * v)
        }
    }

    /// The residue A (m·s per N·s/m) of G_z's pole at the Rayleigh arrival t_R at distance `x`:
    /// G_z ≈ A/(t − t_R) near it, A = −G₀ k³ T / (dD/dτ · Cp/x) with D = S² − 4τ²TV.
    pub fn rayleigh_residue(&self, x: f64) -> f64 {
        let k = self.k();
        let tau = k * self.cs / self.rayleigh_speed();
        let g0 = self.cs / (std::f64::consts::PI * self.shear_modulus * x);
        let (k2, tau2) = (k * k, tau * tau);
        let s = k2 - 2.0 * tau2;
        let (t_, v) = ((tau2 - 1.0).sqrt(), (tau2 - k2).sqrt());
        let d_dtau = 2.0 * s * (-4.0 * tau)
            - 8.0 * tau * t_ * v
            - 4.0 * tau2 * (tau * v / t_ + tau * t_ / v);
        -g0 * k.powi(3) * t_ / (d_dtau * self.cp / x)
    }

    /// The surface's vertical velocity v_z (m/s, positive into the half-space) at distance `x`
    /// (m) and time `t` (s) under a line load F(t) (N/m, pushing in) nil outside `support` (s),
    /// given its rate `rate` = F′(t) (N/m/s): the module's principal-value convolution, each
    /// stretch between the arrivals in `panels` Gauss–Legendre panels.
    pub fn line_velocity(
        &self,
        x: f64,
        t: f64,
        rate: &dyn Fn(f64) -> f64,
        support: (f64, f64),
        panels: usize,
    ) -> f64 {
        // The lags s with F′(t − s) possibly nonzero and G_z nonzero.
        let [tp, ts, tr] = self.arrivals(x);
        let (a, b) = ((t - support.1).max(tp), t - support.0);
        if b <= a {
            return 0.0;
        }
        let residue = self.rayleigh_residue(x);
        let at_pole = rate(t - tr);
        let bounded =
            |s: f64| rate(t - s) * self.impulse_displacement(x, s) - at_pole * residue / (s - tr);
        let mut cuts = vec![a, b];
        cuts.extend([ts, tr].into_iter().filter(|&c| c > a && c < b));
        cuts.sort_by(f64::total_cmp);
        let regular: f64 = (cuts.windows(2))
            .map(|w| gauss_legendre(&bounded, w[0], w[1], panels))
            .sum();
        regular + at_pole * residue * ((b - tr) / (a - tr)).abs().ln()
    }

    /// v_z (m/s) at distance `x` (m) from the middle of a strip of width `width` (m) carrying the
    /// load F(t) (N/m, spread uniformly over it), `x` beyond the strip: [`Self::line_velocity`]
    /// averaged over the strip by 4 Gauss points.
    pub fn strip_velocity(
        &self,
        x: f64,
        width: f64,
        t: f64,
        rate: &dyn Fn(f64) -> f64,
        support: (f64, f64),
        panels: usize,
    ) -> f64 {
        (GAUSS_4.iter())
            .map(|&(xi, w)| {
                let at = x - 0.5 * width * xi;
                0.5 * w * self.line_velocity(at, t, rate, support, panels)
            })
            .sum()
    }
}

/// The Ricker wavelet's peak line load, N/m.
const LOAD: f64 = 1e6;
/// Its delay, in periods (the engine's default).
const DELAY_PERIODS: f64 = 1.2;
/// The P arrival's threshold: this share of the closed form's peak.
const ONSET: f64 = 0.02;
/// Gauss–Legendre panels a stretch of the closed form's convolution.
const PANELS: usize = 24;

/// Lamb's problem run at `zone` m with a Ricker wavelet of peak frequency `frequency` Hz, the
/// surface's velocity read at `distances` m.
#[derive(Debug, Clone, Copy)]
pub struct Surface {
    pub zone: f64,
    pub frequency: f64,
    pub distances: [f64; 3],
}

/// A run against the closed form: the row, and each receiver's waveform error (over the peak)
/// and arrival errors (in zone transits).
pub struct Measured {
    pub report: CaseReport,
    pub waveform: [f64; 3],
    pub p_arrival: [f64; 3],
    pub rayleigh_arrival: [f64; 3],
}

impl Surface {
    fn rock() -> HalfSpace {
        HalfSpace::of(ROCK.0, ROCK.1, ROCK.2)
    }

    fn delay(&self) -> f64 {
        DELAY_PERIODS / self.frequency
    }

    /// The farthest receiver's record: to the end of its Rayleigh pulse and a period more, s.
    fn duration(&self) -> f64 {
        self.distances[2] / Self::rock().rayleigh_speed()
            + 2.0 * self.delay()
            + 1.0 / self.frequency
    }

    /// The half-space's width L and depth D, m: half as far again as the farthest receiver (in
    /// whole zones, so that the surface's nodes stand at whole zones from the axis), and as deep
    /// as it is far.
    fn extent(&self) -> (f64, f64) {
        let far = self.distances[2];
        ((1.5 * far / self.zone).ceil() * self.zone, far)
    }

    pub fn scene(&self) -> adit::Scene {
        let (e, nu, rho) = ROCK;
        let (l, d) = self.extent();
        let z = self.zone;
        let text = serde_json::json!({
            "name": "lamb",
            "materials": { "rock": { "density": rho, "young": e, "poisson": nu } },
            "region": { "polygon": [[0, -d], [l, -d], [l, 0], [z, 0], [0, 0]],
                        "edge_names": ["base", "side", "surface", "source", "axis"],
                        "material": "rock" },
            "zoning": { "edge_at_excavation": z, "edge_far": z },
            "boundary": [
                { "part": "base", "quiet": true }, { "part": "side", "quiet": true },
                { "part": "axis", "fix": "x" },
                { "part": "source", "normal_stress": -LOAD / (2.0 * z),
                  "history": { "pulse": "ricker", "amplitude": 1, "frequency": self.frequency,
                               "delay": self.delay() } }
            ],
            "solve": { "mode": "dynamic", "duration": self.duration(), "damping": 0,
                       "monitor_every": 1, "max_cycles": 10_000_000 },
            "histories": (self.distances.iter().enumerate())
                .map(|(i, x)| serde_json::json!({ "name": format!("r{i}"), "at": [x, 0],
                                                  "quantity": "velocity_y" }))
                .collect::<Vec<_>>(),
            "output": { "checkpoints": false, "every": 0 }
        });
        adit::Scene::from_json(&text.to_string(), "lamb").expect("a valid half-space")
    }

    /// The closed form's upward velocity at `x` m and `t` s: the strip's load pushes down.
    fn exact(&self, x: f64, t: f64) -> f64 {
        let (f, delay) = (self.frequency, self.delay());
        let rate = move |t: f64| ricker_rate(LOAD, f, delay, t);
        -Self::rock().strip_velocity(x, 2.0 * self.zone, t, &rate, (0.0, 2.0 * delay), PANELS)
    }

    /// Run the half-space and measure each receiver against the closed form.
    pub fn run(&self) -> anyhow::Result<Measured> {
        let start = Instant::now();
        let (r, csv) = run_to_completion(&self.scene())?;
        let rock = Self::rock();
        let (mut waveform, mut p_arrival, mut rayleigh_arrival) = ([0.0; 3], [0.0; 3], [0.0; 3]);
        for (i, &x) in self.distances.iter().enumerate() {
            let end = rock.arrivals(x)[2] + 2.0 * self.delay();
            let run: Vec<(f64, f64)> = (history(&csv, &format!("r{i}"))?.into_iter())
                .filter(|(t, _)| *t <= end)
                .collect();
            let exact: Vec<f64> = run.iter().map(|&(t, _)| self.exact(x, t)).collect();
            let peak = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            waveform[i] = (run.iter().zip(&exact))
                .map(|((_, v), e)| (v - e).abs())
                .fold(0.0, f64::max)
                / peak;
            let times: Vec<f64> = run.iter().map(|(t, _)| *t).collect();
            let values: Vec<f64> = run.iter().map(|(_, v)| *v).collect();
            let onset = |v: &[f64]| first_reaching(&times, v, ONSET * peak);
            p_arrival[i] = (onset(&values) - onset(&exact)).abs() / (self.zone / rock.cp);
            rayleigh_arrival[i] = (peak_time(&times, &values) - peak_time(&times, &exact)).abs()
                / (self.zone / rock.rayleigh_speed());
        }
        let worst = |v: &[f64; 3]| v.iter().copied().fold(0.0, f64::max);
        let report = CaseReport::new(
            format!(
                "line load, Ricker {} Hz, on a half-space zoned at {} m: surface velocity at {:?} m",
                self.frequency, self.zone, self.distances
            ),
            r.summary.zones,
            r.summary.cycles,
            start.elapsed().as_secs_f64(),
            Some(self.zone),
            &[
                ("waveform", worst(&waveform)),
                ("p_arrival", worst(&p_arrival)),
                ("rayleigh_arrival", worst(&rayleigh_arrival)),
            ],
        );
        Ok(Measured {
            report,
            waveform,
            p_arrival,
            rayleigh_arrival,
        })
    }
}

/// The first of `times` (s) where |`values`| reaches `level`, ∞ if none does.
fn first_reaching(times: &[f64], values: &[f64], level: f64) -> f64 {
    (times.iter().zip(values))
        .find(|(_, v)| v.abs() >= level)
        .map_or(f64::INFINITY, |(t, _)| *t)
}

/// The time (s) of the largest |`values`|.
fn peak_time(times: &[f64], values: &[f64]) -> f64 {
    (times.iter().zip(values))
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        .map_or(f64::NAN, |(t, _)| *t)
}

/// The 4-point Gauss–Legendre rule on [−1, 1]: (node, weight).
const GAUSS_4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
];

/// ∫ f over [a, b] by `panels` equal panels of the 4-point Gauss–Legendre rule.
fn gauss_legendre(f: &dyn Fn(f64) -> f64, a: f64, b: f64, panels: usize) -> f64 {
    let h = (b - a) / panels as f64;
    (0..panels)
        .map(|p| {
            let mid = a + (p as f64 + 0.5) * h;
            (GAUSS_4.iter())
                .map(|&(xi, w)| 0.5 * h * w * f(mid + 0.5 * h * xi))
                .sum::<f64>()
        })
        .sum()
}

/// A Ricker wavelet's rate: the derivative of h = A (1 − 2u) e^(−u), u = π² f² (t − t₀)²,
/// dh/dt = A e^(−u) 2π² f² (t − t₀) (2u − 3).
pub fn ricker_rate(amplitude: f64, frequency: f64, delay: f64, t: f64) -> f64 {
    let a = std::f64::consts::PI * frequency;
    let tau = t - delay;
    let u = (a * tau).powi(2);
    amplitude * (-u).exp() * 2.0 * a * a * tau * (2.0 * u - 3.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    const ROCK: (f64, f64, f64) = (20e9, 0.25, 2500.0);

    fn rock() -> HalfSpace {
        HalfSpace::of(ROCK.0, ROCK.1, ROCK.2)
    }

    /// The coarse twin of the report's section: 4 m zones (11 a shortest wavelength), the
    /// issue's bars (the waveform within 10 % of the closed form's peak, the P and Rayleigh
    /// arrivals within one zone transit) at every receiver.
    #[test]
    fn a_line_load_moves_the_surface_as_lambs_closed_form() {
        let m = Surface {
            zone: 4.0,
            frequency: 12.0,
            distances: [100.0, 200.0, 300.0],
        }
        .run()
        .unwrap();
        for i in 0..3 {
            assert!(m.waveform[i] <= 0.10, "{:?}", m.report.errors);
            assert!(m.p_arrival[i] <= 1.0, "{:?}", m.report.errors);
            assert!(m.rayleigh_arrival[i] <= 1.0, "{:?}", m.report.errors);
        }
    }

    /// At ν = 1/4 Rayleigh's equation has the root ξ = 2 − 2/√3 (Rayleigh 1885).
    #[test]
    fn the_rayleigh_speed_is_rayleighs() {
        let h = rock();
        let exact = h.cs * (2.0 - 2.0 / 3f64.sqrt()).sqrt();
        assert!((h.rayleigh_speed() - exact).abs() < 1e-12 * exact);
        assert!((exact / h.cs - 0.919_402).abs() < 1e-6);
    }

    /// The two forms meet at the S arrival (each differing from the value there by O(√ε) at
    /// t_S (1 ± ε)), G_z is nil before the P wave, and at late times it is (1 − ν)/(π μ t):
    /// Flamant's static logarithm.
    #[test]
    fn the_green_function_is_continuous_and_ends_in_flamants_logarithm() {
        let h = rock();
        let x = 50.0;
        let [tp, ts, _] = h.arrivals(x);
        assert_eq!(h.impulse_displacement(x, 0.999 * tp), 0.0);
        let (below, above) = (
            h.impulse_displacement(x, ts * (1.0 - 1e-12)),
            h.impulse_displacement(x, ts * (1.0 + 1e-12)),
        );
        assert!((below - above).abs() < 1e-5 * below.abs());
        let t = 1e5 * tp;
        let late = (1.0 - ROCK.1) / (std::f64::consts::PI * h.shear_modulus * t);
        assert!((h.impulse_displacement(x, t) - late).abs() < 1e-4 * late);
    }

    /// G_z (t − t_R) tends to the residue on both sides of the Rayleigh pole.
    #[test]
    fn the_residue_is_the_poles() {
        let h = rock();
        let x = 80.0;
        let (tr, a) = (h.arrivals(x)[2], h.rayleigh_residue(x));
        for side in [-1.0, 1.0] {
            let dt = side * 1e-7 * tr;
            let near = h.impulse_displacement(x, tr + dt) * dt;
            assert!((near - a).abs() < 1e-5 * a.abs(), "{near} {a}");
        }
    }

    /// The principal-value convolution converges with its panels (40 against 160 a stretch:
    /// 5e-6 of the peak, measured), is nil before the P wave reaches, and six Rayleigh
    /// wavelengths out its Rayleigh pulse dominates (its peak within 2e-4 s of t_R + the
    /// wavelet's delay, measured).
    #[test]
    fn the_convolution_converges() {
        let h = rock();
        let (f, delay) = (40.0, 1.5 / 40.0);
        let rate = |t: f64| ricker_rate(1e6, f, delay, t);
        let support = (0.0, 2.0 * delay);
        let x = 400.0;
        let [tp, _, tr] = h.arrivals(x);
        assert_eq!(h.line_velocity(x, 0.99 * tp, &rate, support, 20), 0.0);
        let span = tr + 4.0 * delay - tp;
        let times: Vec<f64> = (0..300).map(|i| tp + i as f64 * span / 300.0).collect();
        let coarse: Vec<f64> = times
            .iter()
            .map(|&t| h.line_velocity(x, t, &rate, support, 40))
            .collect();
        let fine: Vec<f64> = times
            .iter()
            .map(|&t| h.line_velocity(x, t, &rate, support, 160))
            .collect();
        let peak = fine.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let worst = (coarse.iter().zip(&fine))
            .map(|(c, f)| (c - f).abs())
            .fold(0.0, f64::max);
        assert!(worst < 1e-4 * peak, "{worst} {peak}");
        let at_peak = times[(fine.iter().enumerate())
            .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
            .unwrap()
            .0];
        assert!(
            (at_peak - (tr + delay)).abs() < 0.05 / f,
            "{at_peak} {}",
            tr + delay
        );
        assert!(fine.iter().all(|v| v.is_finite()));
    }
}
