//! Kelvin's fundamental solution of plane strain: the displacement and the traction at a field
//! point x of a unit line force at the source point ξ in an infinite isotropic elastic medium
//! (Brebbia & Dominguez, *Boundary Elements: An Introductory Course*, 1992, §5.2):
//!
//! U_ij = 1/(8πG(1 − ν)) [(3 − 4ν) ln(1/r) δ_ij + r_,i r_,j]
//! T_ij = −1/(4π(1 − ν) r) [∂r/∂n ((1 − 2ν) δ_ij + 2 r_,i r_,j) + (1 − 2ν)(r_,j n_i − r_,i n_j)]
//!
//! with r = |x − ξ|, r_,i = (x − ξ)_i / r and n the unit normal at x, pointing out of the domain:
//! the displacement and traction along j of a unit force along i (`kernel::Kernel`).
//!
//! On the element that holds the collocation point, r = |s − s₀| and ∂r/∂n = 0: U integrates
//! through ∫ φ ln|s − s₀| ds, and T keeps its antisymmetric part alone, a principal value.

use super::elements::{Integrals, OwnScalars};
use super::kernel::Translational;

/// An isotropic medium: shear modulus G (Pa) and Poisson's ratio ν.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kelvin {
    pub shear: f64,
    pub poisson: f64,
}

impl Translational for Kelvin {
    fn displacement(&self, d: [f64; 2]) -> [[f64; 2]; 2] {
        let nu = self.poisson;
        let r = d[0].hypot(d[1]);
        let g = [d[0] / r, d[1] / r];
        let c = 1.0 / (8.0 * std::f64::consts::PI * self.shear * (1.0 - nu));
        let log = -(3.0 - 4.0 * nu) * r.ln();
        std::array::from_fn(|i| {
            std::array::from_fn(|j| c * (if i == j { log } else { 0.0 } + g[i] * g[j]))
        })
    }

    fn traction(&self, d: [f64; 2], n: [f64; 2]) -> [[f64; 2]; 2] {
        let nu = self.poisson;
        let r = d[0].hypot(d[1]);
        let g = [d[0] / r, d[1] / r];
        let dr_dn = g[0] * n[0] + g[1] * n[1];
        let c = -1.0 / (4.0 * std::f64::consts::PI * (1.0 - nu) * r);
        std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let delta = if i == j { 1.0 } else { 0.0 };
                c * (dr_dn * ((1.0 - 2.0 * nu) * delta + 2.0 * g[i] * g[j])
                    + (1.0 - 2.0 * nu) * (g[j] * n[i] - g[i] * n[j]))
            })
        })
    }

    fn own_on(&self, t: [f64; 2], n: [f64; 2], s: &[OwnScalars; 2]) -> Integrals {
        let nu = self.poisson;
        let gc = 1.0 / (8.0 * std::f64::consts::PI * self.shear * (1.0 - nu));
        let tc = -(1.0 - 2.0 * nu) / (4.0 * std::f64::consts::PI * (1.0 - nu));
        let (mut h, mut g) = ([[[0.0; 2]; 2]; 2], [[[0.0; 2]; 2]; 2]);
        for (k, s) in s.iter().enumerate() {
            for i in 0..2 {
                for j in 0..2 {
                    let delta = if i == j { 1.0 } else { 0.0 };
                    g[k][i][j] = gc * (-(3.0 - 4.0 * nu) * s.log * delta + t[i] * t[j] * s.whole);
                    h[k][i][j] = tc * (t[j] * n[i] - t[i] * n[j]) * s.pv;
                }
            }
        }
        (h, g)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tractions of a unit force on any circle about it balance the force: ∮ T_ij dΓ = −δ_ij
    /// with n pointing away from the source (the circle's outside: the force acts on the disc).
    #[test]
    fn a_circle_about_the_force_carries_it() {
        let m = Kelvin {
            shear: 3e9,
            poisson: 0.3,
        };
        for radius in [0.1, 1.0, 7.0] {
            let missed = crate::far_field::kernel::force_missed(&m, [0.0, 0.0], radius, 720);
            assert!(missed < 1e-9, "{radius}: {missed}");
        }
    }

    /// U is symmetric, and its log term makes a unit force's displacement fall as ln(1/r).
    #[test]
    fn the_displacement_kernel_is_symmetric_and_logarithmic() {
        let m = Kelvin {
            shear: 1.0,
            poisson: 0.25,
        };
        let u = m.displacement([0.3, -0.7]);
        assert_eq!(u[0][1], u[1][0]);
        let (near, far) = (
            m.displacement([1.0, 0.0]),
            m.displacement([std::f64::consts::E, 0.0]),
        );
        let per_log = (3.0 - 4.0 * 0.25) / (8.0 * std::f64::consts::PI * 0.75);
        assert!((near[1][1] - far[1][1] - per_log).abs() < 1e-12);
    }
}
