//! The dynamic stress concentration at a circular hole under a plane harmonic P wave (Pao & Mow
//! 1973, *Diffraction of Elastic Waves and Dynamic Stress Concentrations*, ch. IV; Mow & Mente
//! 1963): the closed form a dynamic run of a hole is checked against (issue 50).
//!
//! A P wave φᵢ = φ₀ e^{i(αx − ωt)} (α = ω/Cp, β = ω/Cs) meets a hole of radius a. With
//! e^{iαr cos θ} = Σ εₙ iⁿ Jₙ(αr) cos nθ (ε₀ = 1, εₙ = 2), the scattered potentials are
//! φₛ = Σ Aₙ Hₙ(αr) cos nθ and ψₛ = Σ Bₙ Hₙ(βr) sin nθ (Hₙ = Hₙ⁽¹⁾: outgoing), u = ∇φ + ∇×(ψ e_z).
//! For a term φ = f(r) cos nθ, ψ = g(r) sin nθ, in plane strain,
//!
//!   σrr / cos nθ = −λα² f + 2μ [f″ + n (g′/r − g/r²)],
//!   σrθ / sin nθ = μ [−2n f′/r + 2n f/r² − g″ + g′/r − n² g/r²],
//!   σθθ / cos nθ = −λα² f + 2μ [f′/r + n g/r² − n² f/r² − n g′/r],
//!
//! f″ and g″ from Bessel's equation. The free wall, σrr = σrθ = 0 at r = a, gives Aₙ and Bₙ
//! (a 2 × 2 system each n), and the hoop stress σθθ(a, θ) follows. Against the incident wave's
//! stress amplitude σ₀ = (λ + 2μ) α² φ₀ (its σxx), |σθθ|/σ₀ tends at αa → 0 to Kirsch's value
//! for σxx = σ₀, σyy = ν/(1 − ν) σ₀ (uniaxial strain): 3 − ν/(1 − ν) at θ = 90°, 2.667 at
//! ν = 1/4; it peaks near αa ≈ 0.25 (2.91 at ν = 1/4).
//!
//! Bessel functions of the first and second kind of real argument (moderate: the series
//! converge to rounding for x ≲ 10): Jₙ by its power series, Y₀ and Y₁ by theirs (Abramowitz &
//! Stegun 9.1.13 and 9.1.11), Yₙ by the upward recurrence Yₙ₊₁ = (2n/x) Yₙ − Yₙ₋₁ (stable for
//! Y); Zₙ′ = Zₙ₋₁ − (n/x) Zₙ, Z₀′ = −Z₁.
//!
//! The run (`Hole`): a square of elastic rock with the hole at its centre, its base quiet with a
//! broadband Ricker P pulse coming in (`incident`), its sides free-field, its top quiet, so that
//! the plane wave passes and what the hole scatters leaves. The wall's hoop stress at the two
//! points where the wave's front first runs along it (θ = 90° from its direction: σθθ = σyy at
//! (±a, 0) for a wave travelling up) is extrapolated every step from the zones beside each
//! point (a least-squares quadratic in the polar offsets, the zones' constant stresses standing
//! at their centroids; its own error is measured on the static limit, `Hole::quasi_static`),
//! and its Fourier transform over the incident wave's stress ρCp V(ω) (the Ricker's own, the
//! particle velocity V brought in) is the measured |σθθ|/σ₀ at αa = ωa/Cp, compared with the
//! series over the band where the pulse carries its energy.

use std::f64::consts::PI;
use std::time::Instant;

use adit::model::Model;
use adit::solve::{HistoryRow, Observer};
use nalgebra::Complex;

use crate::joint_waves::{Spectrum, Taper};
use crate::quiet::ROCK;
use crate::report::CaseReport;

/// Euler's constant γ.
const EULER: f64 = 0.577_215_664_901_532_9;

/// Jₙ(x) by its power series Σ (−1)^k (x/2)^{2k+n} / (k! (n+k)!).
pub fn bessel_j(n: u32, x: f64) -> f64 {
    let mut term = (x / 2.0).powi(n as i32) / (1..=n).map(f64::from).product::<f64>();
    let mut sum = 0.0;
    for k in 1..200u32 {
        sum += term;
        term *= -(x * x / 4.0) / (f64::from(k) * f64::from(n + k));
        if term.abs() <= 1e-17 * sum.abs() && k > 4 {
            break;
        }
    }
    sum
}

/// Y₀(x) = (2/π) [(ln(x/2) + γ) J₀(x) + Σₖ₌₁ (−1)^{k+1} Hₖ (x²/4)^k/(k!)²], Hₖ = 1 + … + 1/k.
fn bessel_y0(x: f64) -> f64 {
    let (mut sum, mut term, mut harmonic) = (0.0, 1.0, 0.0);
    for k in 1..200 {
        let k = f64::from(k);
        term *= -(x * x / 4.0) / (k * k);
        harmonic += 1.0 / k;
        sum -= term * harmonic;
        if term.abs() * harmonic <= 1e-17 * sum.abs() {
            break;
        }
    }
    2.0 / PI * (((x / 2.0).ln() + EULER) * bessel_j(0, x) + sum)
}

/// Y₁(x) = (2/π) ln(x/2) J₁(x) − 2/(πx) − (1/π) Σₖ (−1)^k [ψ(k+1) + ψ(k+2)] (x/2)^{2k+1}/(k!(k+1)!),
/// ψ(m + 1) = −γ + Hₘ.
fn bessel_y1(x: f64) -> f64 {
    let (mut sum, mut term, mut harmonic) = (0.0, x / 2.0, 0.0);
    for k in 0..200 {
        let k = f64::from(k);
        let psi = 2.0 * (harmonic - EULER) + 1.0 / (k + 1.0);
        sum += psi * term;
        harmonic += 1.0 / (k + 1.0);
        term *= -(x * x / 4.0) / ((k + 1.0) * (k + 2.0));
        if term.abs() <= 1e-18 * sum.abs() && k > 4.0 {
            break;
        }
    }
    2.0 / PI * (x / 2.0).ln() * bessel_j(1, x) - 2.0 / (PI * x) - sum / PI
}

/// Yₙ(x) by upward recurrence from Y₀ and Y₁.
pub fn bessel_y(n: u32, x: f64) -> f64 {
    let (mut below, mut at) = (bessel_y0(x), bessel_y1(x));
    if n == 0 {
        return below;
    }
    for m in 1..n {
        (below, at) = (at, 2.0 * f64::from(m) / x * at - below);
    }
    at
}

/// A radial function Zₙ(s r) at r = a and its first two derivatives in r: (Z, dZ/dr, d²Z/dr²),
/// the second from Bessel's equation Z″ = −Z′/r − (s² − n²/r²) Z.
type Radial = [Complex<f64>; 3];

/// Jₙ(s r) (`hankel` false) or Hₙ⁽¹⁾(s r) = Jₙ + iYₙ at r = `a`, with its derivatives.
fn radial(n: u32, s: f64, a: f64, hankel: bool) -> Radial {
    let z = |m: u32| {
        let x = s * a;
        let j = bessel_j(m, x);
        Complex::new(j, if hankel { bessel_y(m, x) } else { 0.0 })
    };
    let value = z(n);
    let slope = if n == 0 {
        -z(1)
    } else {
        z(n - 1) - value * (f64::from(n) / (s * a))
    } * s;
    let curvature = -slope / a - value * (s * s - f64::from(n * n) / (a * a));
    [value, slope, curvature]
}

/// |σθθ(a, θ)| / σ₀ at the wall of a hole under a plane P wave of wavenumber times radius
/// `alpha_a`, in rock of Poisson's ratio `poisson`, at the angle `theta` (radians) from the
/// wave's direction: the module's series, its terms up to n = `terms` − 1.
pub fn hoop_concentration(alpha_a: f64, poisson: f64, theta: f64, terms: u32) -> f64 {
    let (mu, a) = (1.0, 1.0);
    let lambda = 2.0 * mu * poisson / (1.0 - 2.0 * poisson);
    let alpha = alpha_a / a;
    let beta = alpha * ((lambda + 2.0 * mu) / mu).sqrt();
    let zero: Radial = [Complex::new(0.0, 0.0); 3];
    let mut hoop = Complex::new(0.0, 0.0);
    for n in 0..terms {
        let nf = f64::from(n);
        let srr = |f: &Radial, g: &Radial| {
            -f[0] * (lambda * alpha * alpha)
                + (f[2] + (g[1] / a - g[0] / (a * a)) * nf) * (2.0 * mu)
        };
        let srt = |f: &Radial, g: &Radial| {
            (-f[1] * (2.0 * nf / a) + f[0] * (2.0 * nf / (a * a)) - g[2] + g[1] / a
                - g[0] * (nf * nf / (a * a)))
                * mu
        };
        let stt = |f: &Radial, g: &Radial| {
            -f[0] * (lambda * alpha * alpha)
                + (f[1] / a + g[0] * (nf / (a * a)) - f[0] * (nf * nf / (a * a)) - g[1] * (nf / a))
                    * (2.0 * mu)
        };
        let weight = Complex::new(0.0, 1.0).powu(n) * if n == 0 { 1.0 } else { 2.0 };
        let incident = radial(n, alpha, a, false).map(|v| v * weight);
        let (p, s) = (radial(n, alpha, a, true), radial(n, beta, a, true));
        // [srr(p, 0) srr(0, s); srt(p, 0) srt(0, s)] [A; B] = −[srr(inc, 0); srt(inc, 0)].
        let (m11, m12, m21, m22) = (
            srr(&p, &zero),
            srr(&zero, &s),
            srt(&p, &zero),
            srt(&zero, &s),
        );
        let (r1, r2) = (-srr(&incident, &zero), -srt(&incident, &zero));
        let det = m11 * m22 - m12 * m21;
        let amp_p = (r1 * m22 - m12 * r2) / det;
        let amp_s = (m11 * r2 - r1 * m21) / det;
        let f: Radial = std::array::from_fn(|i| incident[i] + p[i] * amp_p);
        let g: Radial = s.map(|v| v * amp_s);
        hoop += stt(&f, &g) * (nf * theta).cos();
    }
    hoop.norm() / ((lambda + 2.0 * mu) * alpha * alpha)
}

/// The incident pulse's peak particle velocity, m/s (the rock stays elastic: only ratios count).
const PEAK: f64 = 0.1;
/// The band compared: where the incident spectrum is above this fraction of its peak.
const BAND: f64 = 0.1;
/// Below this αa the concentration is quasi-static (the series within 1.5 % of Kirsch's).
pub const QUASI_STATIC: f64 = 0.06;
/// The wall's stress is fitted over the zones whose centroids lie within this many radii of the
/// wall point (a reach fixed in zones would keep the wall zones' own bias as they shrink).
const REACH: f64 = 0.3;

/// A hole of radius `radius` m in a square `size` m wide, zoned at `wall_zone` m on its wall
/// and `far_zone` m away from it, under a Ricker P pulse of peak frequency `frequency` Hz.
#[derive(Debug, Clone, Copy)]
pub struct Hole {
    pub radius: f64,
    pub size: f64,
    pub wall_zone: f64,
    pub far_zone: f64,
    pub frequency: f64,
}

/// A run against the series: the row, the measured and the series' concentration over the band
/// (αa, measured, series), and the errors.
pub struct Measured {
    pub report: CaseReport,
    pub curve: Vec<(f64, f64, f64)>,
    /// The largest |measured / series − 1| below `QUASI_STATIC`.
    pub quasi_static: f64,
    /// |largest measured / largest series − 1| over the band.
    pub peak: f64,
    /// The largest |measured / series − 1| over the band.
    pub band: f64,
}

impl Hole {
    fn speed() -> f64 {
        (crate::constrained_modulus(ROCK.0, ROCK.1) / ROCK.2).sqrt()
    }

    fn delay(&self) -> f64 {
        1.2 / self.frequency
    }

    /// The window: until the pulse has passed the hole (its half length after its peak's
    /// arrival at the centre) and 10 wall transits of the S wave more (the hole rings down),
    /// then a fall over a period.
    fn taper(&self) -> Taper {
        let cs = (ROCK.0 / (2.0 * (1.0 + ROCK.1)) / ROCK.2).sqrt();
        let arrival = self.delay() + 0.5 * self.size / Self::speed();
        Taper {
            arrival,
            end: arrival + 1.2 / self.frequency + 10.0 * self.radius / cs,
            fall: 1.0 / self.frequency,
        }
    }

    /// The square with its hole, zoned, as JSON: the scenes' common part, named `name`.
    fn square(&self, name: &str) -> serde_json::Value {
        let (e, nu, rho) = ROCK;
        let h = 0.5 * self.size;
        let segments = (2.0 * PI * self.radius / self.wall_zone).round() as u32;
        serde_json::json!({
            "name": name,
            "materials": { "rock": { "density": rho, "young": e, "poisson": nu } },
            "region": { "polygon": [[-h, -h], [h, -h], [h, h], [-h, h]],
                        "edge_names": ["base", "right", "top", "left"], "material": "rock" },
            "excavations": [{ "name": "hole",
                              "circle": { "center": [0, 0], "radius": self.radius, "segments": segments } }],
            "zoning": { "edge_at_excavation": self.wall_zone, "edge_far": self.far_zone },
            "output": { "checkpoints": false, "every": 0 }
        })
    }

    pub fn scene(&self) -> adit::Scene {
        let taper = self.taper();
        let mut text = self.square("pao_mow");
        text["boundary"] = serde_json::json!([
            { "part": "base", "quiet": true,
              "incident": { "wave": "p", "velocity": PEAK, "pulse": "ricker", "frequency": self.frequency } },
            { "part": "top", "quiet": true },
            { "part": "left", "quiet": true, "free_field": true },
            { "part": "right", "quiet": true, "free_field": true }
        ]);
        text["solve"] = serde_json::json!({ "mode": "dynamic", "duration": taper.end + taper.fall,
                                             "damping": 0, "monitor_every": 1, "max_cycles": 10_000_000 });
        adit::Scene::from_json(&text.to_string(), "pao_mow").expect("a valid hole")
    }

    /// Run `scene` in a scratch folder with the wall's gauge: the result and the gauge's
    /// samples; an error unless it ended `status`.
    fn gauged(
        &self,
        scene: &adit::Scene,
        status: &str,
    ) -> anyhow::Result<(adit::RunResult, Vec<(f64, f64)>)> {
        let out = std::env::temp_dir().join(format!(
            "adit-validation-{}-{}",
            scene.name,
            std::process::id()
        ));
        let mut gauge = WallGauge::new(self.radius, REACH * self.radius);
        let r = adit::run_scene(scene, &out, &mut gauge);
        let _ = std::fs::remove_dir_all(&out);
        let r = r?;
        anyhow::ensure!(
            r.summary.status == status,
            "{}: {}",
            scene.name,
            r.summary.status
        );
        Ok((r, gauge.samples))
    }

    /// The incident particle velocity at the base, m/s: the Ricker wavelet.
    fn incident(&self, t: f64) -> f64 {
        let x = (PI * self.frequency * (t - self.delay())).powi(2);
        PEAK * (1.0 - 2.0 * x) * (-x).exp()
    }

    /// Run the hole and compare |σθθ|/σ₀ with the series over the band.
    pub fn run(&self) -> anyhow::Result<Measured> {
        let start = Instant::now();
        let (r, wall) = self.gauged(&self.scene(), "completed")?;
        let incident: Vec<(f64, f64)> = (wall.iter())
            .map(|&(t, _)| (t, ROCK.2 * Self::speed() * self.incident(t)))
            .collect();
        let (taper, open) = (
            self.taper(),
            Taper {
                arrival: 0.0,
                end: f64::INFINITY,
                fall: 1.0,
            },
        );
        let step = 0.02 * self.frequency;
        let spectra: Vec<(f64, f64, f64)> = (1..=150)
            .map(|j| {
                let omega = 2.0 * PI * step * f64::from(j);
                let w = Spectrum::of(&wall, omega, &taper).value.norm();
                let i = Spectrum::of(&incident, omega, &open).value.norm();
                (omega * self.radius / Self::speed(), w, i)
            })
            .collect();
        let top = spectra.iter().map(|s| s.2).fold(0.0, f64::max);
        let curve: Vec<(f64, f64, f64)> = (spectra.iter())
            .filter(|s| s.2 >= BAND * top)
            .map(|&(aa, w, i)| (aa, w / i, hoop_concentration(aa, ROCK.1, PI / 2.0, TERMS)))
            .collect();
        anyhow::ensure!(curve.len() > 10, "pao_mow: too few frequencies in the band");
        let error = |c: &(f64, f64, f64)| (c.1 / c.2 - 1.0).abs();
        let quasi_static = (curve.iter())
            .filter(|c| c.0 <= QUASI_STATIC)
            .map(error)
            .fold(0.0, f64::max);
        let band = curve.iter().map(error).fold(0.0, f64::max);
        let largest = |k: usize| curve.iter().map(|c| [c.1, c.2][k]).fold(0.0, f64::max);
        let peak = (largest(0) / largest(1) - 1.0).abs();
        let (low, high) = (curve[0].0, curve[curve.len() - 1].0);
        let report = CaseReport::new(
            format!(
                "hole a = {} m in a {} m square, Ricker {} Hz, zones {} m at the wall, {} m away: αa {low:.3}–{high:.3}",
                self.radius, self.size, self.frequency, self.wall_zone, self.far_zone
            ),
            r.summary.zones,
            r.summary.cycles,
            start.elapsed().as_secs_f64(),
            Some(self.wall_zone),
            &[
                ("quasi_static", quasi_static),
                ("peak", peak),
                ("band", band),
            ],
        );
        Ok(Measured {
            report,
            curve,
            quasi_static,
            peak,
            band,
        })
    }
}

impl Hole {
    /// The gauge on the quasi-static limit itself: the same hole and zoning solved statically
    /// under the incident wave's stress state at αa → 0, uniaxial strain (σyy = −σ₀,
    /// σxx = −ν/(1 − ν) σ₀, held by the in-situ tractions on the square's sides); the wall's
    /// hoop stress over σ₀ against Kirsch's 3 − ν/(1 − ν), and the row.
    pub fn quasi_static(&self) -> anyhow::Result<(CaseReport, f64)> {
        let start = Instant::now();
        let nu = ROCK.1;
        let (h, s0) = (0.5 * self.size, 1e6);
        let mut text = self.square("pao_mow_static");
        text["in_situ"] = serde_json::json!({ "sxx": -s0 * nu / (1.0 - nu), "syy": -s0, "sxy": 0 });
        text["boundary"] = serde_json::json!([
            { "part": "outer", "in_situ_traction": true },
            { "at": [h, 0], "fix": "y" }, { "at": [-h, 0], "fix": "y" },
            { "at": [0, h], "fix": "x" }, { "at": [0, -h], "fix": "x" }
        ]);
        text["solve"] = serde_json::json!({ "ratio": 1e-8, "max_cycles": 100_000 });
        let scene = adit::Scene::from_json(&text.to_string(), "pao_mow_static")?;
        let (r, samples) = self.gauged(&scene, "converged")?;
        let hoop = samples.last().map_or(f64::NAN, |s| -s.1 / s0);
        let kirsch = 3.0 - nu / (1.0 - nu);
        let error = (hoop / kirsch - 1.0).abs();
        let report = CaseReport::new(
            format!(
                "the gauge on the static limit: hole a = {} m, uniaxial strain, zones {} m at the wall: σθθ/σ₀ = {hoop:.4} (Kirsch {kirsch:.4})",
                self.radius, self.wall_zone
            ),
            r.summary.zones,
            r.summary.cycles,
            start.elapsed().as_secs_f64(),
            Some(self.wall_zone),
            &[("static", error)],
        );
        Ok((report, error))
    }
}

/// The series' terms the run's comparison sums (αa ≤ 1: converged to rounding by n ≈ 10).
const TERMS: u32 = 20;

/// The hoop stress σθθ at the wall points (±a, 0), each extrapolated from the zones whose
/// centroids lie within `reach` m of it by a least-squares fit σθθ = c₀ + c₁δ + c₂δ² + c₃t + c₄t²
/// of their hoop stresses (their constant stress turned to the polar axes at their centroid;
/// δ = (r − a)/reach and t = a(θ − θ₀)/reach the offsets from the point across and along the
/// wall): c₀, a fixed weighting of the zones' stress components, found at the first sample.
/// Their mean, every step.
struct WallGauge {
    radius: f64,
    reach: f64,
    /// Each zone with the weights of its σxx, σyy and σxy in the mean of c₀.
    weights: Vec<(usize, [f64; 3])>,
    time: f64,
    samples: Vec<(f64, f64)>,
}

impl WallGauge {
    fn new(radius: f64, reach: f64) -> WallGauge {
        WallGauge {
            radius,
            reach,
            weights: Vec::new(),
            time: 0.0,
            samples: Vec::new(),
        }
    }

    /// The weights of both points' fits, each halved (the mean of the two).
    fn fit(&self, model: &Model) -> Vec<(usize, [f64; 3])> {
        let mut weights = Vec::new();
        for theta0 in [0.0, PI] {
            let point = [self.radius * theta0.cos(), 0.0];
            let near: Vec<(usize, Basis, f64)> = (0..model.zones.len())
                .map(|z| (z, model.zones.centroid(z, &model.nodes.pos)))
                .filter(|(_, c)| c[0].hypot(c[1]) >= self.radius)
                .filter(|(_, c)| (c[0] - point[0]).hypot(c[1] - point[1]) <= self.reach)
                .map(|(z, c)| {
                    let (r, theta) = (c[0].hypot(c[1]), c[1].atan2(c[0]));
                    let turn = (theta - theta0 + PI).rem_euclid(2.0 * PI) - PI;
                    let (d, t) = (
                        (r - self.radius) / self.reach,
                        self.radius * turn / self.reach,
                    );
                    (z, Basis::from([1.0, d, d * d, t, t * t]), theta)
                })
                .collect();
            let normal: Normal = near.iter().map(|(_, b, _)| b * b.transpose()).sum();
            let inverse = normal
                .try_inverse()
                .expect("zones all round the wall point");
            weights.extend(near.iter().map(|(z, b, theta)| {
                let w = 0.5 * (inverse * b)[0];
                let (sin, cos) = theta.sin_cos();
                (*z, [w * sin * sin, w * cos * cos, -2.0 * w * sin * cos])
            }));
        }
        weights
    }
}

type Basis = nalgebra::SVector<f64, 5>;
type Normal = nalgebra::SMatrix<f64, 5, 5>;

impl Observer for WallGauge {
    fn monitored(&mut self, row: &HistoryRow) {
        self.time = row.time;
    }

    fn sampled(&mut self, model: &Model) {
        if self.weights.is_empty() {
            self.weights = self.fit(model);
        }
        let stress = &model.zones.stress;
        let hoop: f64 = (self.weights.iter())
            .map(|&(z, w)| w[0] * stress[z][0] + w[1] * stress[z][1] + w[2] * stress[z][3])
            .sum();
        self.samples.push((self.time, hoop));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tabulated values (Abramowitz & Stegun, table 9.1) and the Wronskian
    /// Jₙ₊₁Yₙ − JₙYₙ₊₁ = 2/(πx).
    #[test]
    fn bessel_functions_match_their_tables_and_wronskian() {
        let close = |a: f64, b: f64| (a - b).abs() < 1e-9;
        assert!(close(bessel_j(0, 1.0), 0.765_197_686_6));
        assert!(close(bessel_j(1, 1.0), 0.440_050_585_7));
        assert!(close(bessel_y(0, 1.0), 0.088_256_964_2));
        assert!(close(bessel_y(1, 1.0), -0.781_212_821_3));
        assert!(close(bessel_j(2, 2.0), 0.352_834_028_6));
        assert!(close(bessel_y(2, 2.0), -0.617_408_104_7));
        for x in [0.05, 0.3, 1.0, 2.5, 5.0] {
            for n in 0..8 {
                let w = bessel_j(n + 1, x) * bessel_y(n, x) - bessel_j(n, x) * bessel_y(n + 1, x);
                let exact = 2.0 / (PI * x);
                assert!(
                    (w - exact).abs() < 1e-10 * exact,
                    "n {n} x {x}: {w} {exact}"
                );
            }
        }
    }

    /// The quasi-static limit is Kirsch's under uniaxial strain, 3 − ν/(1 − ν), and at ν = 1/4
    /// the concentration peaks near αa = 0.25 at 2.91 (Pao & Mow 1973).
    #[test]
    fn the_concentration_has_kirschs_limit_and_pao_and_mows_peak() {
        let side = PI / 2.0;
        for nu in [0.1, 0.25, 0.4] {
            let kirsch = 3.0 - nu / (1.0 - nu);
            let low = hoop_concentration(1e-3, nu, side, 20);
            assert!(
                (low - kirsch).abs() < 1e-3 * kirsch,
                "ν {nu}: {low} {kirsch}"
            );
        }
        let curve: Vec<(f64, f64)> = (1..=60)
            .map(|i| {
                let aa = 0.01 * f64::from(i);
                (aa, hoop_concentration(aa, 0.25, side, 20))
            })
            .collect();
        let (at, peak) = curve
            .iter()
            .copied()
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap();
        assert!((at - 0.25).abs() <= 0.03, "peak at {at}");
        assert!((peak - 2.91).abs() < 0.01, "peak {peak}");
        // More terms change nothing at these wavenumbers.
        let more = hoop_concentration(0.5, 0.25, side, 30);
        assert!((hoop_concentration(0.5, 0.25, side, 20) - more).abs() < 1e-12 * more);
    }

    /// The coarse twin of the report's section: a hole of 1 m zoned at 0.05 m on its wall, 1 m
    /// away, in a 110 m square: the quasi-static concentration within 2 % of the series, the
    /// peak within 5 %; and the gauge reads the static limit within 2 %.
    #[test]
    fn a_coarse_hole_has_pao_and_mows_concentration() {
        let hole = Hole {
            radius: 1.0,
            size: 110.0,
            wall_zone: 0.05,
            far_zone: 1.0,
            frequency: 60.0,
        };
        let (_, error) = hole.quasi_static().unwrap();
        assert!(error < 0.02, "{error}");
        let m = hole.run().unwrap();
        assert!(
            m.quasi_static < 0.02 && m.peak < 0.05,
            "{:?}",
            m.report.errors
        );
    }
}
