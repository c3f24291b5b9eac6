//! Shear strength reduction of a generalized Hoek–Brown rock: the generalized method of Hammah,
//! Yacoub, Corkum & Curran (2005, "The shear strength reduction method for the generalized
//! Hoek–Brown criterion", ARMA/USRMS 05-810), as RS2 reduces a Hoek–Brown material.
//!
//! The Hoek–Brown envelope has no single c and φ: at every normal stress σn its tangent is the
//! Mohr–Coulomb line of instantaneous cohesion cᵢ and friction φᵢ, and reducing those by F
//! (cᵢ/F, tan φᵢ/F) divides the envelope's shear strength by F at every σn: τ_F(σn) = τ(σn)/F.
//! The reduced envelope is not a Hoek–Brown curve; it is fitted with one (σci kept, mb, s, a
//! fitted), which the law then uses as its own. Compression positive here, as in Hoek's papers:
//!
//! 1. points of the envelope for σ3 from the apex −s σci/mb to `SIGMA3_SPAN` σci, by Balmer's
//!    parametric form (Hoek, Carranza-Torres & Corkum 2002, eqs. 12–13): with
//!    k = dσ1/dσ3 = 1 + a mb (mb σ3/σci + s)^(a−1),
//!    σn = (σ1 + σ3)/2 − (σ1 − σ3)/2 · (k − 1)/(k + 1),  τ = (σ1 − σ3) √k/(k + 1),
//!    tan φᵢ = (k − 1)/(2√k);
//! 2. each reduced: τ' = τ/F on the tangent of slope tan φ' = tan φᵢ/F, whose Mohr circle
//!    touching it there has its centre at σn + τ' tan φ' and its radius τ'/cos φ', hence
//!    σ1' and σ3' = centre ± radius;
//! 3. mb', s', a' fitted to the points (σ3', σ1'): for a given a', ((σ1' − σ3')/σci)^(1/a') =
//!    mb' σ3'/σci + s' is linear in mb' and s' (least squares); a' is searched over
//!    [0.5, 0.7] for the least squared misfit of σ1' (golden section on a bracketing grid).
//!
//! At F = 1 the fit returns the envelope's own constants (to the fit's tolerance); the misfit of
//! a reduced envelope is reported by `fit_misfit` and tested below (under 1 % of σci over the
//! range).

use super::HoekBrown;

/// The top of the σ3 range fitted, as a fraction of σci (Hoek's σ3max for deep tunnels and for
/// slopes lies below it: 0.47 σcm (σcm/γH)^−0.94 rarely exceeds σci/2).
const SIGMA3_SPAN: f64 = 0.5;

/// Points on the envelope sampled.
const POINTS: usize = 64;

/// The fitted exponent's range: a of the generalized criterion lies in [0.5, 0.67] for GSI from
/// 100 down to 0; a reduced envelope curves a little more.
const A_RANGE: (f64, f64) = (0.5, 0.7);

/// mb, s, a of the generalized Hoek–Brown envelope that fits `law`'s divided by `factor` in
/// shear strength at every normal stress, σci kept.
pub fn reduced_constants(law: &HoekBrown, factor: f64) -> (f64, f64, f64) {
    let points = reduced_points(law, factor);
    fit(law.sigma_ci, &points)
}

/// The reduced envelope's points (σ3', σ1'), Pa, compression positive.
pub fn reduced_points(law: &HoekBrown, factor: f64) -> Vec<(f64, f64)> {
    let (ci, mb, s, a) = (law.sigma_ci, law.mb, law.s, law.a);
    let apex = -s * ci / mb;
    let top = SIGMA3_SPAN * ci;
    (0..POINTS)
        .map(|i| {
            // Denser towards the apex, where the envelope curves most.
            let t = ((i as f64 + 0.5) / POINTS as f64).powi(2);
            let sigma3 = apex + t * (top - apex);
            let base = mb * sigma3 / ci + s;
            let sigma1 = sigma3 + ci * base.powf(a);
            let k = 1.0 + a * mb * base.powf(a - 1.0);
            let sn = 0.5 * (sigma1 + sigma3) - 0.5 * (sigma1 - sigma3) * (k - 1.0) / (k + 1.0);
            let tau = (sigma1 - sigma3) * k.sqrt() / (k + 1.0);
            let tan_phi = (k - 1.0) / (2.0 * k.sqrt()) / factor;
            let tau = tau / factor;
            let centre = sn + tau * tan_phi;
            let radius = tau * (1.0 + tan_phi * tan_phi).sqrt();
            (centre - radius, centre + radius)
        })
        .collect()
}

/// mb, s (for the exponent `a`) by linear least squares on ((σ1 − σ3)/σci)^(1/a) = mb σ3/σci + s,
/// and the misfit Σ (σ1 − σ1_fit)² / n of σ1 in units of σci².
fn fit_linear(ci: f64, points: &[(f64, f64)], a: f64) -> (f64, f64, f64) {
    let xy: Vec<(f64, f64)> = points
        .iter()
        .map(|&(s3, s1)| (s3 / ci, ((s1 - s3) / ci).max(0.0).powf(1.0 / a)))
        .collect();
    let n = xy.len() as f64;
    let (sx, sy) = xy.iter().fold((0.0, 0.0), |(p, q), &(x, y)| (p + x, q + y));
    let (mx, my) = (sx / n, sy / n);
    let (sxx, sxy) = xy.iter().fold((0.0, 0.0), |(p, q), &(x, y)| {
        (p + (x - mx) * (x - mx), q + (x - mx) * (y - my))
    });
    let mb = sxy / sxx;
    let s = (my - mb * mx).max(0.0);
    (mb, s, misfit(ci, points, (mb, s, a)))
}

/// Σ (σ1 − σ1_fit)² / n over `points`, in units of σci².
fn misfit(ci: f64, points: &[(f64, f64)], (mb, s, a): (f64, f64, f64)) -> f64 {
    let sum: f64 = points
        .iter()
        .map(|&(s3, s1)| {
            let fitted = s3 / ci + (mb * s3 / ci + s).max(0.0).powf(a);
            (s1 / ci - fitted).powi(2)
        })
        .sum();
    sum / points.len() as f64
}

/// The envelope (σci fixed) of least misfit to `points`: a over [`A_RANGE`] by a grid, then a
/// golden-section search around its best.
fn fit(ci: f64, points: &[(f64, f64)]) -> (f64, f64, f64) {
    let cost = |a: f64| fit_linear(ci, points, a).2;
    const GRID: usize = 40;
    let step = (A_RANGE.1 - A_RANGE.0) / GRID as f64;
    let best = (0..=GRID)
        .map(|i| A_RANGE.0 + i as f64 * step)
        .min_by(|x, y| cost(*x).total_cmp(&cost(*y)))
        .expect("a grid of exponents");
    let (mut lo, mut hi) = ((best - step).max(A_RANGE.0), (best + step).min(A_RANGE.1));
    let golden = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..60 {
        let (x1, x2) = (hi - golden * (hi - lo), lo + golden * (hi - lo));
        if cost(x1) < cost(x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    let a = 0.5 * (lo + hi);
    let (mb, s, _) = fit_linear(ci, points, a);
    (mb, s, a)
}

/// The root mean square misfit of `constants` to `law`'s envelope reduced by `factor`, as a
/// fraction of σci.
pub fn fit_misfit(law: &HoekBrown, factor: f64, constants: (f64, f64, f64)) -> f64 {
    misfit(law.sigma_ci, &reduced_points(law, factor), constants).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::law::Elastic;
    use crate::law::hoek_brown_constants;

    fn rock(gsi: f64, mi: f64) -> HoekBrown {
        let elastic = Elastic::from_young(10e9, 0.25, 2600.0);
        HoekBrown::new(elastic, 80e6, hoek_brown_constants(gsi, mi, 0.0), 0.0, 1e9)
    }

    /// Unreduced, the fit gives the envelope back.
    #[test]
    fn factor_one_returns_the_envelope() {
        for (gsi, mi) in [(50.0, 12.0), (30.0, 7.0), (75.0, 25.0)] {
            let law = rock(gsi, mi);
            let (mb, s, a) = reduced_constants(&law, 1.0);
            assert!(
                (mb / law.mb - 1.0).abs() < 1e-3,
                "{gsi}: mb {mb} {}",
                law.mb
            );
            assert!((a - law.a).abs() < 1e-4, "{gsi}: a {a} {}", law.a);
            assert!(
                (s - law.s).abs() < 1e-3 * law.s + 1e-9,
                "{gsi}: s {s} {}",
                law.s
            );
        }
    }

    /// The fitted envelope's shear strength at a normal stress is the original's over F (the
    /// generalized method's definition), within 2 % over the range, and the fit's misfit is
    /// below 1 % of σci.
    #[test]
    fn the_reduced_envelope_is_the_shear_strength_over_f() {
        for (gsi, mi, factor) in [(50.0, 12.0, 1.5), (30.0, 7.0, 1.3), (65.0, 20.0, 2.0)] {
            let law = rock(gsi, mi);
            let fitted = reduced_constants(&law, factor);
            assert!(fit_misfit(&law, factor, fitted) < 0.01, "{gsi}: misfit");
            let reduced = HoekBrown::new(law.elastic, law.sigma_ci, fitted, 0.0, 1e9);
            for sn in [1e6, 5e6, 10e6, 20e6, 35e6] {
                let (tau, tau_f) = (shear_strength(&law, sn), shear_strength(&reduced, sn));
                assert!(
                    (tau_f * factor / tau - 1.0).abs() < 0.02,
                    "GSI {gsi}, F {factor}, σn {sn}: {tau_f} against {}",
                    tau / factor
                );
            }
        }
    }

    /// The envelope's shear strength τ at normal stress σn (Pa, compression positive), from
    /// Balmer's parametric form by bisection on σ3.
    fn shear_strength(law: &HoekBrown, sn: f64) -> f64 {
        let (ci, mb, s, a) = (law.sigma_ci, law.mb, law.s, law.a);
        let at = |s3: f64| {
            let base = (mb * s3 / ci + s).max(1e-300);
            let s1 = s3 + ci * base.powf(a);
            let k = 1.0 + a * mb * base.powf(a - 1.0);
            let n = 0.5 * (s1 + s3) - 0.5 * (s1 - s3) * (k - 1.0) / (k + 1.0);
            (n, (s1 - s3) * k.sqrt() / (k + 1.0))
        };
        let (mut lo, mut hi) = (-s * ci / mb, ci);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if at(mid).0 < sn { lo = mid } else { hi = mid }
        }
        at(0.5 * (lo + hi)).1
    }
}
