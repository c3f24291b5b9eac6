//! Zone constitutive laws behind one small trait; each law is one file.

mod corner_return;
mod elastic;
mod hoek_brown;
mod hoek_brown_reduction;
mod mohr_coulomb;
mod null;
mod principal;
mod ubiquitous_joint;

pub use elastic::{Elastic, plane_strain_moduli};
pub use hoek_brown::{HoekBrown, Residual, hoek_brown_constants};
pub use hoek_brown_reduction::{fit_misfit, reduced_constants};
pub use mohr_coulomb::{MohrCoulomb, SHEAR_NOW, SHEAR_PAST, TENSION_NOW, TENSION_PAST};
pub use null::Null;
pub use ubiquitous_joint::{
    Matrix, PLANE_SHEAR_NOW, PLANE_SHEAR_PAST, PLANE_TENSION_NOW, PLANE_TENSION_PAST,
    UbiquitousJoint, WeakPlane,
};

/// Zone stress, Pa, tension positive: [σxx, σyy, σzz, σxy] (σzz from plane strain).
pub type Stress = [f64; 4];

/// Strain increment of a zone over one step: [Δεxx, Δεyy, Δγxy] (engineering shear), dimensionless.
pub type StrainIncrement = [f64; 3];

/// A zone constitutive law: updates stress (Pa), yield state and plastic shear strain from a
/// plane-strain strain increment.
pub trait ZoneLaw: Send + Sync + CopyZoneLaw {
    /// Advance `stress` (Pa), `state` (yield bit flags) and `plastic` (the accumulated plastic
    /// shear strain e^ps, dimensionless, for softening laws) by the strain increment `de`.
    fn update(&self, stress: &mut Stress, state: &mut u8, plastic: &mut f64, de: &StrainIncrement);
    /// The implicit path's update: `stress`, `state` and `plastic` are the last committed state
    /// and `de` the whole strain increment since (issue 17: "laws evaluate a trial stress from
    /// their last committed state and a total increment"), however large it is. The default is
    /// `update`, exact for a law whose return does not depend on the increment's size.
    fn trial(&self, stress: &mut Stress, state: &mut u8, plastic: &mut f64, de: &StrainIncrement) {
        self.update(stress, state, plastic, de);
    }
    /// Bulk and shear moduli (Pa) that bound the law's tangent stiffness, for the time step.
    fn moduli(&self) -> (f64, f64);
    /// Mass density, kg/m³.
    fn density(&self) -> f64;
    /// The law with its strength divided by the factor F > 0 (the factor of safety's strength
    /// reduction, `strength_reduction`): a Coulomb criterion's c/F and tan φ/F
    /// ([`reduced_friction`]), the dilation capped at the reduced friction, a tensile strength
    /// over F; a law without strength is itself.
    fn reduced(&self, factor: f64) -> Box<dyn ZoneLaw>;
}

/// The friction angle φ_F (rad) of the strength reduction by F (Dawson, Roth & Drescher 1999,
/// Géotechnique 49(6)): tan φ_F = tan φ / F, φ in rad.
pub fn reduced_friction(friction: f64, factor: f64) -> f64 {
    (friction.tan() / factor).atan()
}

/// A boxed copy of a zone law: a stage plan keeps the law it gives a material and the catalogue
/// takes a copy.
pub trait CopyZoneLaw {
    fn boxed_copy(&self) -> Box<dyn ZoneLaw>;
}

impl<L: ZoneLaw + Clone + 'static> CopyZoneLaw for L {
    fn boxed_copy(&self) -> Box<dyn ZoneLaw> {
        Box::new(self.clone())
    }
}
