//! The fundamental solution a far field's boundary elements integrate: the displacement and
//! traction at a field point of a unit line force in the infinite medium, and their integrals
//! over the element that holds the collocation point (singular, so each kernel gives them in
//! closed form from the element's scalar integrals, `elements::OwnScalars`).

use super::elements::{Integrals, OwnScalars};

pub trait Kernel {
    /// U_ij, m/N per m of line: the displacement at x along j of a unit force at ξ along i
    /// (symmetric); `d` = x − ξ (m, non-zero).
    fn displacement(&self, d: [f64; 2]) -> [[f64; 2]; 2];

    /// T_ij, 1/m: the traction at x (on the surface of unit normal `n`, pointing out of the
    /// medium) along j of a unit force at ξ along i (the boundary integral equation's order,
    /// c_ij u_j + ∫ T_ij u_j = ∫ U_ij t_j for the force along i); `d` = x − ξ (m, non-zero).
    fn traction(&self, d: [f64; 2], n: [f64; 2]) -> [[f64; 2]; 2];

    /// ∫ T_ij φ_k ds (principal value, without the free term) and ∫ U_ij φ_k ds over a straight
    /// element of unit tangent `t` and normal `n` for a collocation point on it, from the
    /// element's scalar integrals `s` (one per shape function k).
    fn own(&self, t: [f64; 2], n: [f64; 2], s: &[OwnScalars; 2]) -> Integrals;

    /// How much closer than its distance a point may seem to the kernel (≥ 1): regular
    /// quadrature takes pieces this much shorter. 1 for an isotropic medium.
    fn stretch(&self) -> f64 {
        1.0
    }
}
