//! The fundamental solution a far field's boundary elements integrate: the displacement and
//! traction at a field point x of a unit line force at the source point ξ in the infinite (or
//! semi-infinite) medium, and their integrals over the element that holds the collocation point
//! (singular, so each kernel gives them in closed form, `elements::OwnScalars`, plus what is
//! regular there).

use super::elements::{Element, Integrals, OwnScalars};

pub trait Kernel {
    /// U_ij, m/N per m of line: the displacement at `x` along j of a unit force at `xi` along i
    /// (m, apart).
    fn displacement_at(&self, x: [f64; 2], xi: [f64; 2]) -> [[f64; 2]; 2];

    /// T_ij, 1/m: the traction at `x` (on the surface of unit normal `n`, pointing out of the
    /// medium) along j of a unit force at `xi` along i (the boundary integral equation's order,
    /// c_ij u_j + ∫ T_ij u_j = ∫ U_ij t_j for the force along i).
    fn traction_at(&self, x: [f64; 2], xi: [f64; 2], n: [f64; 2]) -> [[f64; 2]; 2];

    /// T_ij on the normal `n` and U_ij together (quadrature wants both at each point): a kernel
    /// whose two share their work computes it once.
    fn kernels_at(&self, x: [f64; 2], xi: [f64; 2], n: [f64; 2]) -> ([[f64; 2]; 2], [[f64; 2]; 2]) {
        (self.traction_at(x, xi, n), self.displacement_at(x, xi))
    }

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

/// A kernel of the whole plane, which depends on d = x − ξ alone (Kelvin's, Lekhnitskii's): its
/// own-element integrals follow from the element's scalar integrals.
pub trait Translational {
    /// U_ij for `d` = x − ξ (m, non-zero), m/N per m of line.
    fn displacement(&self, d: [f64; 2]) -> [[f64; 2]; 2];

    /// T_ij for `d` = x − ξ (m, non-zero) on the unit normal `n`, 1/m.
    fn traction(&self, d: [f64; 2], n: [f64; 2]) -> [[f64; 2]; 2];

    /// The own-element integrals on an element of unit tangent `t` and normal `n` from its
    /// scalar integrals `s`.
    fn own_on(&self, t: [f64; 2], n: [f64; 2], s: &[OwnScalars; 2]) -> Integrals;

    /// `Kernel::stretch`.
    fn stretch(&self) -> f64 {
        1.0
    }
}

impl<T: Translational> Kernel for T {
    fn displacement_at(&self, x: [f64; 2], xi: [f64; 2]) -> [[f64; 2]; 2] {
        self.displacement([x[0] - xi[0], x[1] - xi[1]])
    }

    fn traction_at(&self, x: [f64; 2], xi: [f64; 2], n: [f64; 2]) -> [[f64; 2]; 2] {
        self.traction([x[0] - xi[0], x[1] - xi[1]], n)
    }

    fn own(&self, el: &Element, c: usize) -> Integrals {
        self.own_on(el.tangent(), el.n, &el.own_scalars(c))
    }

    fn stretch(&self) -> f64 {
        Translational::stretch(self)
    }
}

/// ∮ T_ij dΓ over the circle of `radius` (m) about `xi`, n pointing away from it, by `count`
/// midpoints: −δ_ij for any kernel, whose tractions balance the unit force inside.
#[cfg(test)]
pub(super) fn force_carried(
    m: &impl Kernel,
    xi: [f64; 2],
    radius: f64,
    count: usize,
) -> [[f64; 2]; 2] {
    let mut sum = [[0.0; 2]; 2];
    let ds = std::f64::consts::TAU * radius / count as f64;
    for k in 0..count {
        let a = std::f64::consts::TAU * (k as f64 + 0.5) / count as f64;
        let n = [a.cos(), a.sin()];
        let t = m.traction_at([xi[0] + radius * n[0], xi[1] + radius * n[1]], xi, n);
        for (row, t) in sum.iter_mut().zip(t) {
            for (v, t) in row.iter_mut().zip(t) {
                *v += t * ds;
            }
        }
    }
    sum
}

/// The largest difference of `force_carried` from −δ_ij.
#[cfg(test)]
pub(super) fn force_missed(m: &impl Kernel, xi: [f64; 2], radius: f64, count: usize) -> f64 {
    let sum = force_carried(m, xi, radius, count);
    (0..2)
        .flat_map(|i| (0..2).map(move |j| (i, j)))
        .map(|(i, j)| (sum[i][j] + if i == j { 1.0 } else { 0.0 }).abs())
        .fold(0.0, f64::max)
}
