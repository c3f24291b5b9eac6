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

use std::f64::consts::PI;

use nalgebra::Complex;

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
}
