//! Glued joint: linear normal and shear springs that never slip or open (a construction joint,
//! UDEC's glued contacts): σn = σn0 + kn un, τ ← τ + ks Δus, with no strength limit. A contact that
//! is no joint (it starts failed: the corners of diagonal blocks where joints cross, which start
//! apart, and contacts that form later) is glued only while shut: open (un > 0) it carries nothing,
//! or it would pull its corners shut across their gap with kn un.

use super::{FAILED, JointLaw, JointState, OPEN};

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
        let normal = s.initial_normal + self.normal_stiffness * s.normal_displacement;
        if s.flags & FAILED != 0 && normal > 0.0 {
            (s.normal, s.shear) = (0.0, 0.0);
            s.flags |= OPEN;
            return;
        }
        s.normal = normal;
        s.shear += self.shear_stiffness * ds;
        s.flags &= FAILED;
    }

    fn stiffness(&self) -> (f64, f64) {
        (self.normal_stiffness, self.shear_stiffness)
    }

    /// A glued joint has no strength to reduce.
    fn reduced(&self, _factor: f64) -> Box<dyn JointLaw> {
        Box::new(*self)
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

    /// A contact that is no joint, 1 mm apart: nothing until it shuts, then the springs, and
    /// nothing again once it opens.
    #[test]
    fn a_contact_that_is_no_joint_pushes_only_once_shut() {
        let law = Glued {
            normal_stiffness: 1e10,
            shear_stiffness: 5e9,
        };
        let mut s = JointState {
            normal_displacement: 1e-3,
            flags: FAILED,
            ..Default::default()
        };
        law.update(&mut s, -0.5e-3, 1e-4);
        assert_eq!((s.normal, s.shear), (0.0, 0.0));
        law.update(&mut s, -1e-3, 1e-4);
        assert!((s.normal + 1e10 * 0.5e-3).abs() < 1e-3, "{}", s.normal);
        assert!((s.shear - 5e9 * 1e-4).abs() < 1e-3, "{}", s.shear);
        law.update(&mut s, 1e-3, 0.0);
        assert_eq!((s.normal, s.shear), (0.0, 0.0));
        assert_eq!(s.flags, FAILED | OPEN);
    }
}
