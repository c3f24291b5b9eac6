//! Glued joint: linear normal and shear springs that never slip or open (a construction joint,
//! UDEC's glued contacts): σn = σn0 + kn un, τ ← τ + ks Δus, with no strength limit.

use super::{JointLaw, JointState};

/// Glued joint material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Glued {
    /// Normal stiffness kn, Pa/m.
    pub normal_stiffness: f64,
    /// Shear stiffness ks, Pa/m.
    pub shear_stiffness: f64,
}

impl JointLaw for Glued {
    fn update(&self, s: &mut JointState, dn: f64, ds: f64) {
        s.normal_displacement += dn;
        s.shear_displacement += ds;
        s.normal = s.initial_normal + self.normal_stiffness * s.normal_displacement;
        s.shear += self.shear_stiffness * ds;
        s.flags = 0;
    }

    fn stiffness(&self) -> (f64, f64) {
        (self.normal_stiffness, self.shear_stiffness)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn glued_joint_carries_tension_and_any_shear() {
        let law = Glued {
            normal_stiffness: 1e10,
            shear_stiffness: 5e9,
        };
        let mut s = JointState::default();
        for _ in 0..100 {
            law.update(&mut s, 1e-5, 1e-4);
        }
        assert!((s.normal - 1e10 * 1e-3).abs() < 1e-3);
        assert!((s.shear - 5e9 * 1e-2).abs() < 1e-2);
        assert_eq!(s.flags, 0);
    }
}
