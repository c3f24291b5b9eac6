//! Mohr–Coulomb elastic–perfectly plastic zone law with tension cut-off and non-associated shear
//! flow, in principal stresses (Itasca, FLAC/FLAC3D *Theory and Background*, "Mohr-Coulomb
//! Model"). With σ1 ≤ σ2 ≤ σ3 (compression negative; σzz is one of the three in plane strain):
//!
//!   shear yield   fs = σ1 − σ3 Nφ + 2c√Nφ  (failure when fs < 0),  potential gs = σ1 − σ3 Nψ,
//!   tension yield ft = σt − σ3              (failure when ft < 0),  potential gt = −σ3,
//!
//! Nφ = (1 + sin φ)/(1 − sin φ), Nψ likewise for the dilation angle ψ. An elastic trial stress that
//! violates a criterion returns to it along the flow rule (α1 = K + 4G/3, α2 = K − 2G/3):
//!
//!   shear:   λs = fs / ((α1 − α2Nψ) − (α2 − α1Nψ)Nφ),
//!            σ1 −= λs(α1 − α2Nψ),  σ2 −= λs α2(1 − Nψ),  σ3 −= λs(α2 − α1Nψ);
//!   tension: λt = (σ3 − σt)/α1,  σ1 −= λt α2,  σ2 −= λt α2,  σ3 −= λt α1,
//!
//! the choice between them made by the diagonal h = σ3 − σt + αP(σ1 − σP) (αP = √(1 + Nφ²) + Nφ,
//! σP = σt Nφ − 2c√Nφ): shear when h ≤ 0, tension when h > 0. The principal directions are kept.
//! That single return is FLAC's and the explicit path's (`update`): its increments are small. The
//! implicit path's trial (`trial`) takes the whole increment since the last commit, whose single
//! return can end outside the criterion (σ2 passing σ1 or σ3, a shear return past the cut-off);
//! there the stress returns from the same trial to an edge or corner of the criterion instead
//! (`corner_return.rs`).
//!
//! Strain softening (FLAC's strain-softening model): cohesion and friction follow a piecewise-linear
//! table of the plastic shear strain e^ps, accumulated from each shear correction as
//! Δe^ps = √(½[(Δε1 − Δεm)² + Δεm² + (Δε3 − Δεm)²]), Δε1 = λs, Δε3 = −λs Nψ, Δεm = (Δε1 + Δε3)/3.

use super::corner_return::Surface;
use super::principal::{Principal, state_after};
use super::{Elastic, StrainIncrement, Stress, ZoneLaw, plane_strain_moduli, reduced_friction};

/// Zone state bit: yielding in shear now.
pub const SHEAR_NOW: u8 = 1;
/// Zone state bit: yielding in tension now.
pub const TENSION_NOW: u8 = 2;
/// Zone state bit: has yielded in shear at some time.
pub const SHEAR_PAST: u8 = 4;
/// Zone state bit: has yielded in tension at some time.
pub const TENSION_PAST: u8 = 8;

/// Mohr–Coulomb material.
#[derive(Debug, Clone, PartialEq)]
pub struct MohrCoulomb {
    pub elastic: Elastic,
    /// Cohesion c, Pa.
    pub cohesion: f64,
    /// Friction angle φ, rad.
    pub friction: f64,
    /// Dilation angle ψ ≤ φ, rad.
    pub dilation: f64,
    /// Tensile strength σt, Pa (at most c / tan φ, the apex of the shear criterion).
    pub tension: f64,
    /// Softening table: (e^ps, c in Pa, φ in rad), e^ps ascending and above 0; the strength at
    /// e^ps = 0 is (`cohesion`, `friction`), linear in between, constant beyond the last point.
    pub softening: Vec<(f64, f64, f64)>,
    /// The criterion at (`cohesion`, `friction`), made once by `new` (so a law is made by `new`,
    /// not by changing its strength afterwards): without softening every zone's return takes it
    /// as it is, where making it anew (two sines and a tangent) cost each zone and cycle about as
    /// much as the rest of its update.
    intact: Surface,
}

impl MohrCoulomb {
    /// From c (Pa), φ and ψ (degrees) and σt (Pa, capped at c / tan φ).
    pub fn new(
        elastic: Elastic,
        cohesion: f64,
        friction_deg: f64,
        dilation_deg: f64,
        tension: f64,
    ) -> Self {
        let friction = friction_deg.to_radians();
        let apex = if friction > 0.0 {
            cohesion / friction.tan()
        } else {
            f64::INFINITY
        };
        let mut law = MohrCoulomb {
            elastic,
            cohesion,
            friction,
            dilation: dilation_deg.to_radians(),
            tension: tension.min(apex),
            softening: Vec::new(),
            intact: Surface::default(),
        };
        law.intact = law.surface(cohesion, friction);
        law
    }

    /// The intact rock's deviator at failure q = σ1 − σ3 = 2c√Nφ + (Nφ − 1) σ3 under a
    /// confinement σ3 (Pa, compression positive), Pa: the peak envelope, before any softening.
    pub fn peak_deviator(&self, confinement: f64) -> f64 {
        self.intact.k + (self.intact.n_phi - 1.0) * confinement
    }

    /// The law with its strength divided by `factor` F (`ZoneLaw::reduced`): c/F, tan φ/F (the
    /// softening table's too), ψ at most the reduced φ, σt/F.
    pub fn reduced_by(&self, factor: f64) -> MohrCoulomb {
        let friction = reduced_friction(self.friction, factor);
        let mut law = MohrCoulomb::new(
            self.elastic,
            self.cohesion / factor,
            friction.to_degrees(),
            self.dilation.min(friction).to_degrees(),
            self.tension / factor,
        );
        law.softening = (self.softening.iter())
            .map(|&(e, c, phi)| (e, c / factor, reduced_friction(phi, factor)))
            .collect();
        law
    }

    /// Cohesion (Pa) and friction (rad) at plastic shear strain `eps`.
    pub fn strength(&self, eps: f64) -> (f64, f64) {
        let mut prev = (0.0, self.cohesion, self.friction);
        for &next in &self.softening {
            if eps <= next.0 {
                let w = (eps - prev.0) / (next.0 - prev.0);
                return (
                    prev.1 + w * (next.1 - prev.1),
                    prev.2 + w * (next.2 - prev.2),
                );
            }
            prev = next;
        }
        (prev.1, prev.2)
    }

    /// The criterion of cohesion `c` (Pa) and friction `phi` (rad) with this law's dilation,
    /// tensile strength (capped at the apex c / tan φ) and elastic moduli.
    fn surface(&self, c: f64, phi: f64) -> Surface {
        let n = |a: f64| (1.0 + a.sin()) / (1.0 - a.sin());
        let (n_phi, n_psi) = (n(phi), n(self.dilation.min(phi)));
        let (a1, a2) = plane_strain_moduli(self.elastic.bulk, self.elastic.shear);
        let apex = if phi > 0.0 {
            c / phi.tan()
        } else {
            f64::INFINITY
        };
        Surface {
            n_phi,
            n_psi,
            k: 2.0 * c * n_phi.sqrt(),
            st: self.tension.min(apex),
            a1,
            a2,
        }
    }

    /// Return principal stresses `p` (ascending, Pa) to the yield `surface`; the state bits set
    /// now and the plastic shear strain increment. The single-plane return above; with
    /// `corners`, where it leaves the stress outside the criterion (a corner), the multi-surface
    /// return of [`Surface::corner_return`] from the same trial.
    fn correct(surface: &Surface, p: &mut [f64; 3], corners: bool) -> (u8, f64) {
        let trial = *p;
        let single = single_plane_return(surface, p);
        if !corners || surface.admits(p, surface.tolerance(&trial)) {
            return single;
        }
        let mut q = trial;
        match surface.corner_return(&mut q) {
            Some((shear, tension, eps)) => {
                *p = q;
                let bits =
                    if shear { SHEAR_NOW } else { 0 } | if tension { TENSION_NOW } else { 0 };
                (bits, eps)
            }
            None => single,
        }
    }

    /// Elastic trial (plane strain), then the return in principal stresses (with the corner return
    /// when `corners`); the in-plane principal directions are kept (`Principal`).
    fn advance(
        &self,
        s: &mut Stress,
        state: &mut u8,
        plastic: &mut f64,
        de: &StrainIncrement,
        corners: bool,
    ) {
        self.elastic.update(s, state, plastic, de);
        let principal = Principal::of(s);
        let mut p = principal.values();
        let softened;
        let surface = if self.softening.is_empty() {
            &self.intact
        } else {
            let (c, phi) = self.strength(*plastic);
            softened = self.surface(c, phi);
            &softened
        };
        let (now, eps) = Self::correct(surface, &mut p, corners);
        *plastic += eps;
        *state = state_after(*state, now);
        if now != 0 {
            principal.put(&p, s);
        }
    }
}

/// FLAC's single-plane return of the ascending principal stresses `p` (Pa): shear or tension by
/// the diagonal h (module doc); the state bits set and the plastic shear strain increment.
fn single_plane_return(surface: &Surface, p: &mut [f64; 3]) -> (u8, f64) {
    let Surface {
        n_phi,
        n_psi,
        k,
        st,
        a1,
        a2,
    } = *surface;
    let fs = p[0] - p[2] * n_phi + k;
    let ft = st - p[2];
    if fs >= 0.0 && ft >= 0.0 {
        return (0, 0.0);
    }
    let alpha_p = (1.0 + n_phi * n_phi).sqrt() + n_phi;
    let sigma_p = st * n_phi - k;
    let h = p[2] - st + alpha_p * (p[0] - sigma_p);
    if fs < 0.0 && h <= 0.0 {
        let ls = fs / ((a1 - a2 * n_psi) - (a2 - a1 * n_psi) * n_phi);
        p[0] -= ls * (a1 - a2 * n_psi);
        p[1] -= ls * a2 * (1.0 - n_psi);
        p[2] -= ls * (a2 - a1 * n_psi);
        let (e1, e3) = (ls, -ls * n_psi);
        let em = (e1 + e3) / 3.0;
        let eps = (0.5 * ((e1 - em).powi(2) + em * em + (e3 - em).powi(2))).sqrt();
        (SHEAR_NOW, eps)
    } else if ft < 0.0 {
        let lt = (p[2] - st) / a1;
        p[0] -= lt * a2;
        p[1] -= lt * a2;
        p[2] -= lt * a1;
        (TENSION_NOW, 0.0)
    } else {
        (0, 0.0)
    }
}

impl ZoneLaw for MohrCoulomb {
    /// c/F, φ_F with tan φ_F = tan φ / F, ψ capped at φ_F, σt/F (capped at the reduced apex by
    /// `new`), every point of the softening table reduced alike (`MohrCoulomb::reduced_by`).
    fn reduced(&self, factor: f64) -> Box<dyn ZoneLaw> {
        Box::new(self.reduced_by(factor))
    }

    /// FLAC's update: the single-plane return (`advance`).
    fn update(&self, s: &mut Stress, state: &mut u8, plastic: &mut f64, de: &StrainIncrement) {
        self.advance(s, state, plastic, de, false);
    }

    /// The update with the corner return where the single-plane one ends outside (module doc):
    /// the whole increment since the commit may cross the criterion's edges.
    fn trial(&self, s: &mut Stress, state: &mut u8, plastic: &mut f64, de: &StrainIncrement) {
        self.advance(s, state, plastic, de, true);
    }

    fn moduli(&self) -> (f64, f64) {
        (self.elastic.bulk, self.elastic.shear)
    }

    fn density(&self) -> f64 {
        self.elastic.density
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rock() -> MohrCoulomb {
        MohrCoulomb::new(
            Elastic::from_young(10e9, 0.25, 2500.0),
            1e6,
            30.0,
            0.0,
            0.5e6,
        )
    }

    /// Reduced by F, the peak's Mohr circle at every confinement touches the envelope
    /// τ = (c + σn tan φ)/F (compression positive); the dilation is capped at the reduced
    /// friction, the tension and the softening table follow.
    #[test]
    fn a_reduced_law_has_the_envelope_over_the_factor() {
        let mut law = MohrCoulomb::new(
            Elastic::from_young(10e9, 0.25, 2500.0),
            1e6,
            40.0,
            35.0,
            0.5e6,
        );
        law.softening = vec![(0.01, 0.2e6, 36f64.to_radians())];
        for factor in [0.7, 1.0, 1.3, 2.0, 5.0] {
            let r = law.reduced_by(factor);
            let tan = 40f64.to_radians().tan() / factor;
            assert!((r.friction.tan() - tan).abs() < 1e-14, "{factor}");
            for sigma3 in [0.0, 1e6, 5e6, 20e6] {
                let q = r.peak_deviator(sigma3);
                let centre = sigma3 + 0.5 * q;
                let distance = (1e6 / factor + centre * tan) * (tan.atan()).cos();
                assert!((distance - 0.5 * q).abs() < 1e-9 * q, "{factor} {sigma3}");
            }
            assert!(r.dilation <= r.friction && r.dilation <= law.dilation);
            assert!((r.tension - (0.5e6 / factor).min(1e6 / factor / tan)).abs() < 1e-6);
            let (c, phi) = r.strength(0.02);
            assert!((c - 0.2e6 / factor).abs() < 1e-6);
            assert!((phi.tan() - 36f64.to_radians().tan() / factor).abs() < 1e-14);
        }
    }

    /// Principal stresses, ascending.
    fn principal(s: &Stress) -> [f64; 3] {
        let (c, r) = (
            0.5 * (s[0] + s[1]),
            (0.25 * (s[0] - s[1]).powi(2) + s[3] * s[3]).sqrt(),
        );
        let mut p = [c - r, c + r, s[2]];
        p.sort_by(f64::total_cmp);
        p
    }

    /// Biaxial compression at (nearly) constant lateral stress: the axial stress stops at the
    /// Mohr–Coulomb strength σ1 = σ3 Nφ − 2c√Nφ of the current σ3 and stays there.
    #[test]
    fn compression_is_capped_by_the_strength() {
        let law = rock();
        let mut s = [-2e6, -2e6, -1e6, 0.0];
        let mut state = 0;
        for _ in 0..4000 {
            // Shorten in y while the lateral stress is held by expanding in x as needed.
            let mut de = [0.0, -1e-6, 0.0];
            let a1 = law.elastic.bulk + 4.0 / 3.0 * law.elastic.shear;
            let a2 = law.elastic.bulk - 2.0 / 3.0 * law.elastic.shear;
            de[0] = -(s[0] + 2e6 + a2 * de[1]) / a1;
            law.update(&mut s, &mut state, &mut 0.0, &de);
        }
        let n_phi: f64 = 3.0; // φ = 30°
        let p = principal(&s);
        assert!((p[2] + 2e6).abs() < 0.01 * 2e6, "{p:?}");
        let strength = p[2] * n_phi - 2.0 * 1e6 * n_phi.sqrt();
        assert!(
            (p[0] - strength).abs() < 1e-6 * strength.abs(),
            "{p:?} vs {strength}"
        );
        assert_eq!(state, SHEAR_NOW | SHEAR_PAST);
        // Unloading leaves the past flag only.
        law.update(&mut s, &mut state, &mut 0.0, &[0.0, 1e-5, 0.0]);
        assert_eq!(state, SHEAR_PAST);
    }

    /// Tension beyond σt returns the largest principal stress to σt (tension flags), and the
    /// in-plane principal directions are kept.
    #[test]
    fn tension_is_cut_off_keeping_directions() {
        let law = rock();
        let mut s = [0.0, 0.0, 0.0, 0.0];
        let mut state = 0;
        // Pure extension along 45°: Δεxx = Δεyy = e/2, Δγxy = e.
        law.update(&mut s, &mut state, &mut 0.0, &[0.5e-4, 0.5e-4, 1e-4]);
        let p = principal(&s);
        assert!((p[2] - 0.5e6).abs() < 1e-6, "{p:?}");
        assert_eq!(state & TENSION_NOW, TENSION_NOW);
        // The major axis is still at 45°: σxx = σyy.
        assert!((s[0] - s[1]).abs() < 1e-6 * s[3].abs().max(1.0));
    }

    #[test]
    fn elastic_states_are_untouched() {
        let law = rock();
        let mut s = [-5e6, -4e6, -3e6, 0.2e6];
        let before = s;
        let mut state = 0;
        law.update(&mut s, &mut state, &mut 0.0, &[0.0; 3]);
        assert_eq!((s, state), (before, 0));
    }

    /// With cohesion softening from 1 MPa to 0.2 MPa over e^ps = 0.01 (friction kept), biaxial
    /// compression at a lateral 2 MPa peaks at the intact strength and falls to the residual one.
    #[test]
    fn softening_drops_the_strength_to_its_residual() {
        let mut law = rock();
        law.softening = vec![(0.01, 0.2e6, 30f64.to_radians())];
        let (a1, a2) = (
            law.elastic.bulk + 4.0 / 3.0 * law.elastic.shear,
            law.elastic.bulk - 2.0 / 3.0 * law.elastic.shear,
        );
        let mut s = [-2e6, -2e6, -1e6, 0.0];
        let (mut state, mut plastic, mut peak) = (0, 0.0, 0.0f64);
        for _ in 0..40_000 {
            let mut de = [0.0, -1e-6, 0.0];
            de[0] = -(s[0] + 2e6 + a2 * de[1]) / a1;
            law.update(&mut s, &mut state, &mut plastic, &de);
            peak = peak.min(principal(&s)[0]);
        }
        let n_phi: f64 = 3.0;
        let p = principal(&s);
        let strength = |c: f64| p[2] * n_phi - 2.0 * c * n_phi.sqrt();
        assert!(plastic > 0.01, "e^ps = {plastic}");
        assert!((p[0] - strength(0.2e6)).abs() < 1e-3 * p[0].abs(), "{p:?}");
        assert!(
            (peak - strength(1e6)).abs() < 0.02 * peak.abs(),
            "peak {peak}"
        );
        assert_eq!(law.strength(0.005), (0.6e6, 30f64.to_radians()));
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(4000))]
        /// Whatever the stress and the strain increment, the trial ends inside the criterion
        /// (FLAC's single-plane return alone, `update`, left stresses up to 2.5 MPa outside in
        /// `models/tunnel.json`, where σ2 passed σ3 or a shear return passed the cut-off).
        #[test]
        fn every_trial_ends_inside_the_criterion(
            sxx in -40e6..5e6f64, syy in -40e6..5e6f64, szz in -40e6..5e6f64, sxy in -15e6..15e6f64,
            exx in -2e-3..2e-3f64, eyy in -2e-3..2e-3f64, gxy in -2e-3..2e-3f64,
            dilation in 0.0..30.0f64,
        ) {
            let law = MohrCoulomb::new(Elastic::from_young(10e9, 0.3, 2500.0), 1e6, 30.0, dilation, 0.5e6);
            let mut s = [sxx, syy, szz, sxy];
            law.trial(&mut s, &mut 0, &mut 0.0, &[exx, eyy, gxy]);
            let p = principal(&s);
            let n_phi = 3.0;
            let tol = 1e-9 * 40e6;
            proptest::prop_assert!(p[0] - n_phi * p[2] + 2e6 * n_phi.sqrt() >= -tol, "{p:?}");
            proptest::prop_assert!(p[2] <= 0.5e6 + tol, "{p:?}");
        }
    }
}
