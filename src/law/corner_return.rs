//! Multi-surface return of the Mohr–Coulomb law, for the trial stresses whose single-plane return
//! (FLAC's) leaves the stress outside the criterion: near an edge of the pyramid (σ2 → σ1 or
//! σ2 → σ3) or where shear meets the tension cut-off (Koiter's rule; Clausen, Damkilde &
//! Andersen, "Efficient return algorithms for associated plasticity with multiple yield planes",
//! IJNME 66, 2006; de Souza Neto, Perić & Owen, *Computational Methods for Plasticity*, §8.2).
//!
//! In principal stresses (tension positive) six planes bound the admissible set, each a yield
//! function f ≥ 0 and a plastic potential g:
//!
//!   shear (i, j), i ≠ j:  f = σi − Nφ σj + 2c√Nφ,   g = σi − Nψ σj,  for (1,3), (2,3), (1,2);
//!   tension k:            f = σt − σk,              g = −σk,         for k = 1, 2, 3.
//!
//! With the set A of active planes, the corrected stress is σ = σᵗ + Σ_{b∈A} λb D ∇gb and the
//! multipliers solve Σ_b (∇fa · D ∇gb) λb = −fa(σᵗ) for a ∈ A (D the elastic matrix: α1 on the
//! diagonal, α2 off it). A set is admissible when every λ ≥ 0 and the corrected stress satisfies
//! the whole criterion; of the admissible sets the one with fewest planes is taken, and among
//! those the one nearest in the energy norm Σ λa λb ∇ga · D ∇gb. On one plane this is exactly the
//! single-plane return of [`super::MohrCoulomb`].

use nalgebra::{Matrix3, Vector3};

/// One bounding plane of a criterion in principal stresses (Mohr–Coulomb's here, Hoek–Brown's
/// curved surfaces by the same indices).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Plane {
    /// Shear between principal values `minor` and `major` (indices 0..3).
    Shear { minor: usize, major: usize },
    /// Tension cut-off on principal value `k`.
    Tension { k: usize },
}

pub(super) const PLANES: [Plane; 6] = [
    Plane::Shear { minor: 0, major: 2 },
    Plane::Shear { minor: 1, major: 2 },
    Plane::Shear { minor: 0, major: 1 },
    Plane::Tension { k: 2 },
    Plane::Tension { k: 1 },
    Plane::Tension { k: 0 },
];

/// An admissible return: its planes (`set[..size]`, indices into [`PLANES`]), multipliers,
/// corrected principal stresses (Pa) and complementary energy (Pa).
pub(super) struct Candidate {
    pub size: usize,
    pub energy: f64,
    pub stress: [f64; 3],
    pub lambda: Vector3<f64>,
    pub set: [usize; 3],
}

/// The Mohr–Coulomb criterion in principal stresses with the elastic matrix it returns through.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct Surface {
    /// Nφ = (1 + sin φ)/(1 − sin φ).
    pub n_phi: f64,
    /// Nψ = (1 + sin ψ)/(1 − sin ψ).
    pub n_psi: f64,
    /// 2c√Nφ, Pa.
    pub k: f64,
    /// Tensile strength σt, Pa (at most the apex c / tan φ).
    pub st: f64,
    /// α1 = K + 4G/3, Pa.
    pub a1: f64,
    /// α2 = K − 2G/3, Pa.
    pub a2: f64,
}

impl Surface {
    fn f(&self, plane: Plane, p: &[f64; 3]) -> f64 {
        match plane {
            Plane::Shear { minor, major } => p[minor] - self.n_phi * p[major] + self.k,
            Plane::Tension { k } => self.st - p[k],
        }
    }

    fn grad_f(&self, plane: Plane) -> Vector3<f64> {
        self.gradient(plane, self.n_phi)
    }

    fn grad_g(&self, plane: Plane) -> Vector3<f64> {
        self.gradient(plane, self.n_psi)
    }

    /// ∇(σi − N σj) for shear, ∇(−σk) for tension.
    fn gradient(&self, plane: Plane, n: f64) -> Vector3<f64> {
        let mut v = Vector3::zeros();
        match plane {
            Plane::Shear { minor, major } => {
                v[minor] = 1.0;
                v[major] = -n;
            }
            Plane::Tension { k } => v[k] = -1.0,
        }
        v
    }

    fn elastic(&self, v: &Vector3<f64>) -> Vector3<f64> {
        elastic_times(self.a1, self.a2, v)
    }

    /// Whether principal stresses `p` (any order, Pa) satisfy the criterion within `tol` (Pa).
    pub fn admits(&self, p: &[f64; 3], tol: f64) -> bool {
        let lo = p[0].min(p[1]).min(p[2]);
        let hi = p[0].max(p[1]).max(p[2]);
        lo - self.n_phi * hi + self.k >= -tol && self.st - hi >= -tol
    }

    /// Tolerance (Pa) of the admissibility test for stresses of magnitude `p`: rounding only.
    pub fn tolerance(&self, p: &[f64; 3]) -> f64 {
        1e-10 * (p.iter().fold(0.0f64, |m, v| m.max(v.abs())) + self.k + self.st.abs())
    }

    /// Return the trial principal stresses `p` (Pa, in place) by the multi-surface rule; the
    /// state bits (shear and/or tension now) and the plastic shear strain increment
    /// √(½ Σ (Δεk − Δεm)²) of the shear planes' plastic strain Σ λb ∇gb. Leaves `p` and returns
    /// `None` if no set of planes is admissible (never seen; the caller keeps its own return).
    pub fn corner_return(&self, p: &mut [f64; 3]) -> Option<(bool, bool, f64)> {
        let tol = self.tolerance(p);
        if self.admits(p, 0.0) {
            return Some((false, false, 0.0));
        }
        // Where FLAC's return fails: its own two planes alone, then the edges its shear return
        // crosses (σ2 past σ3, σ2 past σ1, past the cut-off); every set by size if none admits.
        let planes = [(1, [0, 0, 0]), (1, [3, 0, 0])];
        let edges = [(2, [0, 1, 0]), (2, [0, 2, 0]), (2, [0, 3, 0])];
        let best = self
            .best(planes.into_iter(), p, tol)
            .or_else(|| self.best(edges.into_iter(), p, tol))
            .or_else(|| {
                (1..=3).find_map(|size| self.best(subsets(size).map(|set| (size, set)), p, tol))
            });
        let Candidate {
            size,
            stress,
            lambda,
            set,
            ..
        } = best?;
        *p = stress;
        let mut strain = Vector3::zeros();
        let (mut shear, mut tension) = (false, false);
        for (b, &i) in set[..size].iter().enumerate() {
            match PLANES[i] {
                Plane::Shear { .. } => {
                    shear = true;
                    strain += lambda[b] * self.grad_g(PLANES[i]);
                }
                Plane::Tension { .. } => tension = true,
            }
        }
        let mean = strain.sum() / 3.0;
        let eps = (0.5 * strain.iter().map(|e| (e - mean).powi(2)).sum::<f64>()).sqrt();
        Some((shear, tension, eps))
    }

    /// Of the sets of planes `sets` (size, indices into [`PLANES`]), the admissible return of
    /// least complementary energy (every λ ≥ 0, the whole criterion met within `tol`, Pa) from
    /// the trial `p` (Pa).
    fn best(
        &self,
        sets: impl Iterator<Item = (usize, [usize; 3])>,
        p: &[f64; 3],
        tol: f64,
    ) -> Option<Candidate> {
        let mut best: Option<Candidate> = None;
        for (size, set) in sets {
            let Some((lambda, q)) = self.solve(&set[..size], p) else {
                continue;
            };
            if lambda.iter().take(size).any(|&l| l < 0.0) || !self.admits(&q, tol) {
                continue;
            }
            let energy = self.energy(&set[..size], &lambda);
            if best.as_ref().is_none_or(|b| energy < b.energy) {
                best = Some(Candidate {
                    size,
                    energy,
                    stress: q,
                    lambda,
                    set,
                });
            }
        }
        best
    }

    /// Multipliers of the planes `set` (indices into [`PLANES`]) and the corrected stresses, or
    /// `None` where the planes do not meet (a singular system).
    fn solve(&self, set: &[usize], p: &[f64; 3]) -> Option<(Vector3<f64>, [f64; 3])> {
        let n = set.len();
        let mut a = Matrix3::identity();
        let mut rhs = Vector3::zeros();
        for (r, &ia) in set.iter().enumerate() {
            let fa = self.grad_f(PLANES[ia]);
            for (c, &ib) in set.iter().enumerate() {
                a[(r, c)] = fa.dot(&self.elastic(&self.grad_g(PLANES[ib])));
            }
            rhs[r] = -self.f(PLANES[ia], p);
        }
        let scale = (0..n).map(|r| a[(r, r)].abs()).fold(0.0, f64::max);
        // Cramer's rule on the leading n × n block (the rest is the identity).
        let det = a.determinant();
        if det.abs() <= 1e-12 * scale.powi(n as i32) {
            return None;
        }
        let lambda = Vector3::from_fn(|c, _| {
            let mut ac = a;
            ac.set_column(c, &rhs);
            ac.determinant() / det
        });
        let mut q = *p;
        for (b, &i) in set.iter().enumerate() {
            let d = self.elastic(&self.grad_g(PLANES[i]));
            for (k, qk) in q.iter_mut().enumerate() {
                *qk += lambda[b] * d[k];
            }
        }
        Some((lambda, q))
    }

    /// Complementary energy of the correction, Σ λa λb ∇ga · D ∇gb (Pa).
    fn energy(&self, set: &[usize], lambda: &Vector3<f64>) -> f64 {
        let mut e = 0.0;
        for (a, &ia) in set.iter().enumerate() {
            let ga = self.grad_g(PLANES[ia]);
            for (b, &ib) in set.iter().enumerate() {
                e += lambda[a] * lambda[b] * ga.dot(&self.elastic(&self.grad_g(PLANES[ib])));
            }
        }
        e
    }
}

/// D v in principal stresses: D the plane-strain elastic matrix, α1 = K + 4G/3 (Pa) on the
/// diagonal, α2 = K − 2G/3 off it.
pub(super) fn elastic_times(a1: f64, a2: f64, v: &Vector3<f64>) -> Vector3<f64> {
    let sum = v.sum();
    Vector3::from_fn(|i, _| a2 * sum + (a1 - a2) * v[i])
}

/// The sets of `size` planes out of six (indices ascending, padded with 0 to three).
pub(super) fn subsets(size: usize) -> impl Iterator<Item = [usize; 3]> {
    (0u32..64)
        .filter(move |m| m.count_ones() as usize == size)
        .map(|m| {
            let mut set = [0; 3];
            for (slot, i) in (0..6).filter(|i| m & (1 << i) != 0).enumerate() {
                set[slot] = i;
            }
            set
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// φ = 30°, ψ as given, c = 1 MPa, σt = 0.5 MPa, K = 6.67 GPa, G = 4 GPa.
    fn surface(psi_deg: f64) -> Surface {
        surface_of(30.0, psi_deg, 1e6, 0.5e6, 0.25)
    }

    /// φ, ψ in degrees, c and σt (capped at the apex) in Pa, Poisson's ratio ν; G = 4 GPa.
    fn surface_of(phi_deg: f64, psi_deg: f64, c: f64, st: f64, nu: f64) -> Surface {
        let n = |a: f64| (1.0 + a.to_radians().sin()) / (1.0 - a.to_radians().sin());
        let shear = 4e9;
        let bulk = 2.0 * shear * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu));
        Surface {
            n_phi: n(phi_deg),
            n_psi: n(psi_deg.min(phi_deg)),
            k: 2.0 * c * n(phi_deg).sqrt(),
            st: st.min(c / phi_deg.to_radians().tan()),
            a1: bulk + 4.0 / 3.0 * shear,
            a2: bulk - 2.0 / 3.0 * shear,
        }
    }

    #[test]
    fn the_sets_are_every_choice_of_planes() {
        assert_eq!(subsets(1).count(), 6);
        assert_eq!(subsets(2).count(), 15);
        assert_eq!(subsets(3).count(), 20);
        assert!(subsets(2).all(|s| s[0] < s[1]));
    }

    /// On one shear plane the return is FLAC's: σ1 −= λ(α1 − α2Nψ), σ3 −= λ(α2 − α1Nψ).
    #[test]
    fn one_plane_is_the_single_plane_return() {
        let s = surface(10.0);
        let mut p = [-30e6, -12e6, -5e6];
        let (shear, tension, _) = s.corner_return(&mut p).unwrap();
        assert!(shear && !tension);
        let fs = -30e6 + 5e6 * s.n_phi + s.k;
        let l = fs / ((s.a1 - s.a2 * s.n_psi) - (s.a2 - s.a1 * s.n_psi) * s.n_phi);
        let expect = [
            -30e6 - l * (s.a1 - s.a2 * s.n_psi),
            -12e6 - l * s.a2 * (1.0 - s.n_psi),
            -5e6 - l * (s.a2 - s.a1 * s.n_psi),
        ];
        for k in 0..3 {
            assert!((p[k] - expect[k]).abs() < 1e-6, "{p:?} vs {expect:?}");
        }
    }

    /// σ2 = σ3 (the edge where two shear planes meet): the stress lands on both, σ2 = σ3 kept.
    #[test]
    fn an_edge_trial_lands_on_both_planes() {
        let s = surface(0.0);
        let mut p = [-40e6, -5e6, -5e6];
        s.corner_return(&mut p).unwrap();
        assert!((p[1] - p[2]).abs() < 1e-6, "{p:?}");
        assert!((p[0] - s.n_phi * p[2] + s.k).abs() < 1e-6, "{p:?}");
    }

    /// Hydrostatic tension beyond σt returns to σt in every direction.
    #[test]
    fn hydrostatic_tension_returns_to_the_cut_off() {
        let s = surface(0.0);
        let mut p = [3e6, 3e6, 3e6];
        let (_, tension, _) = s.corner_return(&mut p).unwrap();
        assert!(tension);
        for v in p {
            assert!((v - s.st).abs() < 1e-6, "{p:?}");
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4000))]
        /// Any trial stress returns to an admissible stress, with multipliers ≥ 0 (checked in
        /// `corner_return`) and no larger correction than needed: an admissible trial stays.
        #[test]
        fn every_trial_returns_inside(
            a in -60e6..10e6f64, b in -60e6..10e6f64, c in -60e6..10e6f64,
            phi in 5.0..55.0f64, psi in 0.0..55.0f64, coh in 0.0..5e6f64, st in 0.0..5e6f64,
            nu in 0.0..0.49f64,
        ) {
            let s = surface_of(phi, psi, coh, st, nu);
            let mut p = [a, b, c];
            p.sort_by(f64::total_cmp);
            let trial = p;
            let admissible = s.admits(&p, 0.0);
            let done = s.corner_return(&mut p);
            prop_assert!(done.is_some(), "{trial:?}");
            prop_assert!(s.admits(&p, s.tolerance(&trial)), "{trial:?} -> {p:?}");
            if admissible {
                prop_assert_eq!(p, trial);
            }
        }
    }
}
