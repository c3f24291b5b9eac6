//! Joint constitutive laws behind one small trait; each law is one file.

mod barton_bandis;
mod coulomb;
mod glued;
mod yielding;

pub use barton_bandis::{BartonBandis, Roughness};
pub use coulomb::{CoulombSlip, tan_deg};
pub use glued::Glued;
pub use yielding::{ContinuouslyYielding, SHEAR_NEGATIVE};

/// Bit flag of `JointState::flags`: the joint is slipping now.
pub const SLIPPING: u8 = 1;
/// Bit flag: the joint is open (no normal contact).
pub const OPEN: u8 = 2;
/// Bit flag: the joint has failed (in shear or tension) and lost its cohesion and tensile strength.
pub const FAILED: u8 = 4;

/// Stress state of one contact, Pa, tension positive.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct JointState {
    /// Normal stress, Pa (negative in compression).
    pub normal: f64,
    /// Shear stress, Pa, along the contact tangent.
    pub shear: f64,
    /// Accumulated shear displacement, m.
    pub shear_displacement: f64,
    /// Accumulated normal displacement (opening positive), m.
    pub normal_displacement: f64,
    /// Normal stress when the contact was made (the in-situ stress for joints present from the start), Pa.
    pub initial_normal: f64,
    /// Accumulated dilation (opening the joint would need to keep its stress), m.
    pub dilation: f64,
    /// Bounding friction angle φm of the continuously yielding law, rad (0 until first used).
    pub(crate) bounding_friction: f64,
    /// Reversal factor r of the continuously yielding law (τ/τm at the last shear reversal).
    pub(crate) reversal: f64,
    /// The shear path Σ|Δus| since the contact was made, m: the Barton–Bandis law's mobilization
    /// coordinate (counted by that law only).
    pub shear_path: f64,
    /// The mobilized joint roughness coefficient JRCmob of the Barton–Bandis law (0 for the other
    /// laws).
    pub jrc_mobilized: f64,
    /// `SLIPPING`, `OPEN`, `FAILED` bit flags (and a law's own, such as `SHEAR_NEGATIVE`).
    pub flags: u8,
}

/// A joint law: updates a contact's stresses from its normal and shear displacement increments.
pub trait JointLaw: Send + Sync + CopyJointLaw {
    /// Advance `state` by the increments of opening `dn` (m, positive opening) and shear `ds` (m).
    fn update(&self, state: &mut JointState, dn: f64, ds: f64);
    /// The implicit path's update: `state` is the contact's last committed state and `dn`, `ds`
    /// (m) the whole relative displacement since (issue 17: "laws evaluate a trial stress or
    /// force from their last committed state and a total increment"), however large. The
    /// default is `update`, exact for a law whose return does not depend on the increment's size.
    fn trial(&self, state: &mut JointState, dn: f64, ds: f64) {
        self.update(state, dn, ds)
    }
    /// Normal and shear stiffness (Pa/m), for the time step: the stiffest the law gets.
    fn stiffness(&self) -> (f64, f64);
    /// The normal and shear stiffness (Pa/m) of a contact in `state`, for the implicit path's
    /// matrix; the default is `stiffness`, for the laws whose elastic stiffness is constant.
    fn tangent(&self, _state: &JointState) -> (f64, f64) {
        self.stiffness()
    }
    /// Why the implicit path cannot integrate this law, or `None` (the default). The implicit
    /// path steps the joints through its iterations' corrections, which go back and forth on
    /// their way to equilibrium: a law whose response depends on the history of its increments
    /// beyond where they end (reversals, not only slip) would take them for the joint's history.
    fn implicit_refusal(&self) -> Option<&'static str> {
        None
    }
    /// The law with its shear strength divided by the factor F > 0 (the factor of safety's
    /// strength reduction, `strength_reduction`): a Coulomb joint's c/F, tan φ/F, its
    /// dilation capped at the reduced friction and its tensile strength over F; the continuously
    /// yielding and Barton–Bandis joints' strength over F at every state; a joint that never
    /// slips is itself.
    fn reduced(&self, factor: f64) -> Box<dyn JointLaw>;
}

/// A boxed copy of a joint law: a stage plan keeps the law it gives a joint material and the
/// catalogue takes a copy.
pub trait CopyJointLaw {
    fn boxed_copy(&self) -> Box<dyn JointLaw>;
}

impl<L: JointLaw + Clone + 'static> CopyJointLaw for L {
    fn boxed_copy(&self) -> Box<dyn JointLaw> {
        Box::new(self.clone())
    }
}
