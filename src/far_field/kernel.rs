//! The fundamental solution a far field's boundary elements integrate: the displacement and
//! traction at a field point x of a unit line force at the source point ξ in the infinite (or
//! semi-infinite) medium, and their integrals over the element that holds the collocation point
//! (singular, so each kernel gives them in closed form, `elements::OwnScalars`, plus what is
//! regular there).

use super::elements::{Element, Integrals};

pub trait Kernel {
    /// U_ij, m/N per m of line: the displacement at `x` along j of a unit force at `xi` along i
    /// (m, apart).
    fn displacement_at(&self, x: [f64; 2], xi: [f64; 2]) -> [[f64; 2]; 2];

    /// T_ij, 1/m: the traction at `x` (on the surface of unit normal `n`, pointing out of the
    /// medium) along j of a unit force at `xi` along i (the boundary integral equation's order,
    /// c_ij u_j + ∫ T_ij u_j = ∫ U_ij t_j for the force along i).
    fn traction_at(&self, x: [f64; 2], xi: [f64; 2], n: [f64; 2]) -> [[f64; 2]; 2];

    /// ∫ T_ij φ_k ds (principal value, without the free term) and ∫ U_ij φ_k ds over the
    /// element `el` for its own collocation point `c`.
    fn own(&self, el: &Element, c: usize) -> Integrals;

    /// How much closer than its distance a point may seem to the kernel (≥ 1): regular
    /// quadrature takes pieces this much shorter. 1 for an isotropic medium.
    fn stretch(&self) -> f64 {
        1.0
    }

    /// The distance (m) from the element `el` to the nearest point where the kernels of a force
    /// at `xi` are singular: `xi` itself, and a half-plane's image point too. Quadrature keeps
    /// its pieces a third of it long.
    fn nearest_singularity(&self, xi: [f64; 2], el: &Element) -> f64 {
        el.distance_to(xi)
    }
}
