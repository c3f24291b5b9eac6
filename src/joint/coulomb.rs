//! Linear Coulomb slip joint with tensile strength, cohesion and dilation (UDEC's joint area
//! contact Coulomb slip model; Itasca, UDEC *Theory and Background*, §1.2.4).

use super::{FAILED, JointLaw, JointState, OPEN, SLIPPING};

/// Coulomb slip joint material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoulombSlip {
    /// Normal stiffness kn, Pa/m.
    pub normal_stiffness: f64,
    /// Shear stiffness ks, Pa/m.
    pub shear_stiffness: f64,
    /// tan φ of the friction angle φ (dimensionless; `tan_deg` converts from degrees).
    pub tan_friction: f64,
    /// Cohesion c, Pa (falls to `residual_cohesion` once the joint fails).
    pub cohesion: f64,
    /// Cohesion after failure cr ≤ c, Pa (UDEC's residual cohesion; 0: the cohesion is lost; c:
    /// a perfectly plastic joint, the limit-equilibrium joint).
    pub residual_cohesion: f64,
    /// Tensile strength T, Pa (lost once the joint fails).
    pub tensile_strength: f64,
    /// tan ψ of the dilation angle ψ (dimensionless).
    pub tan_dilation: f64,
}

/// tan of an angle in degrees, exactly 0 for 0°.
pub fn tan_deg(deg: f64) -> f64 {
    if deg == 0.0 {
        0.0
    } else {
        deg.to_radians().tan()
    }
}

impl JointLaw for CoulombSlip {
    /// Normal stress from the total normal displacement, σn = σn0 + kn (un − d) with σn0 the stress
    /// when the contact was made and d the accumulated dilation (so an opened joint recloses at the
    /// right place); shear incremental, τ ← τ + ks Δus. Then tension: if σn > T the joint opens and
    /// fails (σn = τ = 0); shear: if |τ| > c − σn tan φ (σn ≤ 0), τ returns to the limit with its sign,
    /// the joint slips and fails, and dilation grows by |Δus| tan ψ. Failed joints have c = T = 0.
    fn update(&self, s: &mut JointState, dn: f64, ds: f64) {
        self.advance(s, dn, ds, Dilation::WholeIncrement);
    }

    /// `update`, but returned from the commit in one step: the joint dilates by the plastic slip
    /// alone (`plastic_slip`: from the commit, the whole increment of a step that begins to slip
    /// is partly elastic, and counting it all, as `update` does, exact in the limit of small
    /// increments, lifted the direct shear box further the longer the step), and its shear ends
    /// on the limit at the normal stress it dilated to. A joint that fails within the step ends
    /// it without its cohesion and tensile strength, as a cycle's joint has them no more from
    /// the cycle after it failed, and dilates by the slip beyond its intact limit, as the cycles
    /// after failing count it: returned to c − σn tan φ instead, the implicit answer held the
    /// joints that failed at their intact strength, and explicit cycles after it closed a
    /// jointed hole 13 % further (`tests/engine/implicit.rs`).
    fn trial(&self, s: &mut JointState, dn: f64, ds: f64) {
        let committed = *s;
        self.advance(s, dn, ds, Dilation::PlasticSlip(0.0));
        if committed.flags & FAILED == 0 && s.flags & FAILED != 0 {
            *s = committed;
            s.flags |= FAILED;
            let lost = self.cohesion - self.residual_cohesion;
            self.advance(s, dn, ds, Dilation::PlasticSlip(lost));
        }
    }

    fn stiffness(&self) -> (f64, f64) {
        (self.normal_stiffness, self.shear_stiffness)
    }

    /// c/F, tan φ/F, tan ψ at most the reduced tan φ, T/F.
    fn reduced(&self, factor: f64) -> Box<dyn JointLaw> {
        let tan_friction = self.tan_friction / factor;
        Box::new(CoulombSlip {
            tan_friction,
            cohesion: self.cohesion / factor,
            residual_cohesion: self.residual_cohesion / factor,
            tensile_strength: self.tensile_strength / factor,
            tan_dilation: self.tan_dilation.min(tan_friction),
            ..*self
        })
    }
}

/// What slip the dilation grows by: the whole shear increment, or the plastic slip beyond the
/// limit raised by a cohesion lost within the step (Pa).
#[derive(Clone, Copy, PartialEq)]
enum Dilation {
    WholeIncrement,
    PlasticSlip(f64),
}

impl CoulombSlip {
    fn advance(&self, s: &mut JointState, dn: f64, ds: f64, dilation: Dilation) {
        let failed = s.flags & FAILED != 0;
        let (c, t) = if failed {
            (self.residual_cohesion, 0.0)
        } else {
            (self.cohesion, self.tensile_strength)
        };
        s.normal_displacement += dn;
        s.shear_displacement += ds;
        s.flags &= !(SLIPPING | OPEN);
        let normal =
            s.initial_normal + self.normal_stiffness * (s.normal_displacement - s.dilation);
        if normal > t {
            s.normal = 0.0;
            s.shear = 0.0;
            s.flags |= OPEN | FAILED;
            return;
        }
        s.normal = normal;
        s.shear += self.shear_stiffness * ds;
        let limit = c - s.normal * self.tan_friction;
        if s.shear.abs() > limit {
            let (sign, excess) = (s.shear.signum(), s.shear.abs() - limit);
            s.flags |= SLIPPING | FAILED;
            match dilation {
                Dilation::WholeIncrement => {
                    s.shear = limit * sign;
                    self.dilate(s, ds.abs());
                }
                Dilation::PlasticSlip(lost) => {
                    self.dilate(s, self.plastic_slip(excess - lost));
                    s.shear = (c - s.normal * self.tan_friction) * sign;
                }
            }
        }
    }

    /// The plastic slip λ (m) of a return from a trial whose shear stress exceeds the limit by
    /// `excess` (Pa): the slip takes ks λ off the shear stress and, dilating by tan ψ λ, adds
    /// kn tan ψ λ to the compression and so tan φ kn tan ψ λ to the limit, so that
    /// λ = excess / (ks + kn tan ψ tan φ) ends on the limit at the final normal stress (the
    /// return of a non-associated Coulomb joint, e.g. Simo & Hughes, *Computational Inelasticity*,
    /// §2.2, with the coupling of the normal stress). Without the coupling, excess / ks slipped
    /// the jointed tunnel of a random draw (kn = 1e11 Pa/m, ks = 1e10 Pa/m, ψ = 5°: 40 % more
    /// slip than consistent) into 8 414 iterations and a closure 2 % off the explicit one.
    fn plastic_slip(&self, excess: f64) -> f64 {
        let coupling = self.normal_stiffness * self.tan_dilation * self.tan_friction;
        excess.max(0.0) / (self.shear_stiffness + coupling)
    }

    /// Dilate by `slip` (m): the dilation grows by slip tan ψ and the normal stress follows it.
    fn dilate(&self, s: &mut JointState, slip: f64) {
        if self.tan_dilation != 0.0 {
            s.dilation += slip * self.tan_dilation;
            s.normal =
                s.initial_normal + self.normal_stiffness * (s.normal_displacement - s.dilation);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn joint() -> CoulombSlip {
        CoulombSlip {
            normal_stiffness: 10e9,
            shear_stiffness: 5e9,
            tan_friction: tan_deg(30.0),
            cohesion: 1e5,
            residual_cohesion: 0.0,
            tensile_strength: 5e4,
            tan_dilation: 0.0,
        }
    }

    /// Reduced by F, a joint slips at (c − σn tan φ)/F and, failed, keeps cr/F of its residual
    /// cohesion.
    #[test]
    fn a_reduced_joint_slips_at_its_strength_over_the_factor() {
        let law = CoulombSlip {
            residual_cohesion: 0.4e5,
            ..joint()
        };
        for factor in [0.8, 1.0, 1.5, 3.0] {
            let reduced = law.reduced(factor);
            let mut s = JointState {
                normal: -1e6,
                initial_normal: -1e6,
                ..Default::default()
            };
            reduced.update(&mut s, 0.0, 1e-3);
            let peak = (1e5 + 1e6 * tan_deg(30.0)) / factor;
            assert!(
                (s.shear - peak).abs() < 1e-9 * peak,
                "{factor}: {}",
                s.shear
            );
            reduced.update(&mut s, 0.0, 1e-3);
            let residual = (0.4e5 + 1e6 * tan_deg(30.0)) / factor;
            assert!(
                (s.shear - residual).abs() < 1e-9 * residual,
                "{factor}: {}",
                s.shear
            );
        }
    }

    #[test]
    fn shear_stress_is_capped_at_cohesion_plus_friction_then_cohesion_is_lost() {
        let law = joint();
        let mut s = JointState {
            normal: -1e6,
            initial_normal: -1e6,
            ..Default::default()
        };
        for _ in 0..100 {
            law.update(&mut s, 0.0, 1e-5);
        }
        // After failure the cohesion is gone: τ = σn tan φ.
        assert!((s.shear - 1e6 * 30f64.to_radians().tan()).abs() < 1e-6 * 1e6);
        assert!(s.flags & SLIPPING != 0 && s.flags & FAILED != 0);
    }

    #[test]
    fn peak_includes_cohesion_before_failure() {
        let law = joint();
        let mut s = JointState {
            normal: -1e6,
            initial_normal: -1e6,
            ..Default::default()
        };
        let peak = 1e5 + 1e6 * 30f64.to_radians().tan();
        let mut max = 0.0f64;
        for _ in 0..200 {
            law.update(&mut s, 0.0, 1e-6);
            max = max.max(s.shear);
        }
        assert!((max - peak).abs() < 1e-9 * peak, "{max} vs {peak}");
    }

    #[test]
    fn tension_beyond_strength_opens_and_fails() {
        let law = joint();
        let mut s = JointState::default();
        law.update(&mut s, 1e-6, 0.0); // σn = 1e4 < T
        assert_eq!(s.flags, 0);
        law.update(&mut s, 1e-5, 0.0); // σn = 1.1e5 > T
        assert_eq!((s.normal, s.flags & (OPEN | FAILED)), (0.0, OPEN | FAILED));
        // Closing by less than the opening leaves it open; closing past it compresses.
        law.update(&mut s, -5e-6, 0.0);
        assert_eq!(s.normal, 0.0);
        law.update(&mut s, -7e-6, 0.0);
        assert!((s.normal - -1e4).abs() < 1e-6, "{}", s.normal);
    }

    /// A trial from the commit that fails the joint ends at its residual strength, where a cycle's
    /// joint is from the cycle after it failed, and dilates by the slip beyond its intact limit,
    /// as the cycles after failing count it, the slip taking the dilation's compression into
    /// account (`plastic_slip`).
    #[test]
    fn a_joint_that_fails_within_a_trial_ends_at_its_residual_strength() {
        let start = JointState {
            normal: -1e6,
            initial_normal: -1e6,
            ..Default::default()
        };
        let ds = 1e-4; // ks ds = 5e5 Pa, under c − σn tan φ = 6.77e5 Pa; 3 ds past it.
        let residual = 1e6 * tan_deg(30.0);
        let law = joint();
        let (mut trial, mut cycled) = (start, start);
        law.trial(&mut trial, 0.0, 3.0 * ds);
        law.update(&mut cycled, 0.0, 3.0 * ds);
        law.update(&mut cycled, 0.0, 0.0);
        assert!(trial.flags & FAILED != 0);
        assert!(
            (trial.shear - residual).abs() < 1e-9 * residual,
            "{}",
            trial.shear
        );
        assert_eq!((trial.shear, trial.flags), (cycled.shear, cycled.flags));
        // Dilating: by the slip beyond the intact limit, (ks 3 ds − (c − σn tan φ)) over
        // ks + kn tan ψ tan φ, and ending on the residual limit at the normal stress it dilated to.
        let law = CoulombSlip {
            tan_dilation: tan_deg(10.0),
            ..joint()
        };
        let mut dilated = start;
        law.trial(&mut dilated, 0.0, 3.0 * ds);
        let coupled = 5e9 + 10e9 * tan_deg(10.0) * tan_deg(30.0);
        let slip = (5e9 * 3.0 * ds - (1e5 + residual)) / coupled;
        let expected = slip * tan_deg(10.0);
        assert!(
            (dilated.dilation - expected).abs() < 1e-12 * expected,
            "{}",
            dilated.dilation
        );
        let normal = -1e6 - 10e9 * expected;
        assert!(
            (dilated.normal - normal).abs() < 1e-9 * 1e6,
            "{}",
            dilated.normal
        );
        assert!(
            (dilated.shear + normal * tan_deg(30.0)).abs() < 1e-9 * 1e6,
            "{}",
            dilated.shear
        );
        // Within the intact limit nothing fails.
        let mut held = start;
        law.trial(&mut held, 0.0, ds);
        assert_eq!((held.shear, held.flags), (5e5, 0));
    }

    #[test]
    fn dilation_raises_confinement_while_slipping() {
        let law = CoulombSlip {
            tan_dilation: tan_deg(10.0),
            cohesion: 0.0,
            residual_cohesion: 0.0,
            ..joint()
        };
        let mut s = JointState {
            normal: -1e6,
            initial_normal: -1e6,
            ..Default::default()
        };
        for _ in 0..100 {
            law.update(&mut s, 0.0, 1e-5);
        }
        assert!(s.normal < -1e6);
    }

    /// The trial from a commit at rest takes one whole increment: the joint slips past its limit
    /// and dilates by the plastic slip alone, (ks Δus − limit)/(ks + kn tan ψ tan φ) · tan ψ,
    /// ending on the limit at the normal stress it dilated to, where `update` counts the whole
    /// Δus and stays at the limit of the normal stress it started from; its flags are `update`'s.
    #[test]
    fn the_trial_dilates_by_the_plastic_slip() {
        let law = CoulombSlip {
            tan_dilation: tan_deg(10.0),
            cohesion: 0.0,
            residual_cohesion: 0.0,
            ..joint()
        };
        let start = JointState {
            normal: -1e6,
            initial_normal: -1e6,
            flags: FAILED,
            ..Default::default()
        };
        let ds = 1e-3;
        let (mut t, mut u) = (start, start);
        law.trial(&mut t, 0.0, ds);
        law.update(&mut u, 0.0, ds);
        let limit = 1e6 * law.tan_friction;
        let coupled =
            law.shear_stiffness + law.normal_stiffness * law.tan_dilation * law.tan_friction;
        let plastic = (law.shear_stiffness * ds - limit) / coupled;
        assert!(
            (t.dilation - plastic * law.tan_dilation).abs() < 1e-15,
            "{t:?}"
        );
        assert!(
            (t.shear + t.normal * law.tan_friction).abs() < 1e-9 * 1e6,
            "{t:?}"
        );
        assert!((u.dilation - ds * law.tan_dilation).abs() < 1e-15, "{u:?}");
        assert_eq!((u.shear, t.flags), (limit, u.flags));
    }
}
