//! Melan's fundamental solution (1932): a unit line force in an isotropic elastic half-plane
//! below a traction-free horizontal surface y = y_s, for a far field under a ground surface (a
//! shallow tunnel). It is Kelvin's solution plus a complementary part, regular in the medium and
//! singular at the image point ξ̄ (ξ mirrored in the surface), which frees the surface of
//! Kelvin's traction.
//!
//! Derived here with Kolosov–Muskhelishvili potentials (Muskhelishvili, *Some Basic Problems of
//! the Mathematical Theory of Elasticity*, 1953, §§ 32–33, 57, 93; plane strain, κ = 3 − 4ν): with
//! z = x + i(y − y_s) and the medium in Im z < 0,
//!
//! σ_xx + σ_yy = 4 Re φ′, σ_yy − σ_xx + 2i σ_xy = 2 (z̄ φ″ + ψ′), 2G (u + iv) = κ φ − z conj(φ′) − conj(ψ),
//!
//! and the force resultant φ + z conj(φ′) + conj(ψ), constant along a free boundary. A force
//! F = X + iY at z₀ is, in the whole plane, φ₀ = A ln(z − z₀), ψ₀ = −κ Ā ln(z − z₀) − A z̄₀/(z − z₀),
//! A = −F/(2π(1 + κ)) (Kelvin's solution). On the real axis its force resultant is
//! A ln(t − z₀) − κ A ln(t − z̄₀) + Ā (t − z₀)/(t − z̄₀); potentials analytic in the medium (singular
//! at z̄₀ alone) that cancel it there are, with δ = z̄₀ − z₀,
//!
//! φ₁ = κ A ln(z − z̄₀) − Ā δ/(z − z̄₀),
//! ψ₁ = −Ā ln(z − z̄₀) − (κ A z̄₀ + Ā δ)/(z − z̄₀) − Ā δ z̄₀/(z − z̄₀)²,
//!
//! the complementary part. The kernels are Kelvin's (`kelvin`, Brebbia's real form) plus the
//! displacement and traction of φ₁, ψ₁ for F = 1 (along x) and F = i (along y). On the element
//! holding the collocation point the complementary part is regular: Kelvin's analytical
//! integrals plus quadrature of it, kept a third of the image point's distance from each piece.

use nalgebra::Complex;

use super::elements::{Element, Integrals};
use super::kelvin::Kelvin;
use super::kernel::Kernel;

type C = Complex<f64>;

/// An isotropic half-plane below the surface y = `surface` (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Melan {
    pub kelvin: Kelvin,
    /// The ground surface's height, m: the medium is y < surface.
    pub surface: f64,
}

impl Melan {
    /// ξ mirrored in the surface, m.
    pub fn image_of(&self, xi: [f64; 2]) -> [f64; 2] {
        [xi[0], 2.0 * self.surface - xi[1]]
    }

    /// The complementary part's potentials φ₁′, φ₁″, ψ₁′ at z for the force at z₀ along
    /// `force` (0: x, 1: y), and its displacement 2G(u + iv).
    fn complementary(&self, z: C, z0: C, force: usize) -> (C, C, C, C) {
        let kappa = 3.0 - 4.0 * self.kelvin.poisson;
        let f = if force == 0 {
            C::new(1.0, 0.0)
        } else {
            C::new(0.0, 1.0)
        };
        let a = -f / (2.0 * std::f64::consts::PI * (1.0 + kappa));
        let (ab, z0b) = (a.conj(), z0.conj());
        let delta = z0b - z0;
        let w = z - z0b;
        let (w2, w3) = (w * w, w * w * w);
        let phi = a * kappa * w.ln() - ab * delta / w;
        let dphi = a * kappa / w + ab * delta / w2;
        let ddphi = -a * kappa / w2 - ab * delta * 2.0 / w3;
        let psi = -ab * w.ln() - (a * kappa * z0b + ab * delta) / w - ab * delta * z0b / w2;
        let dpsi = -ab / w + (a * kappa * z0b + ab * delta) / w2 + ab * delta * z0b * 2.0 / w3;
        let two_g_u = phi * kappa - z * dphi.conj() - psi.conj();
        (dphi, ddphi, dpsi, two_g_u)
    }

    /// Local complex coordinates of `x` and `xi`: origin on the surface.
    fn local(&self, x: [f64; 2], xi: [f64; 2]) -> (C, C) {
        (
            C::new(x[0], x[1] - self.surface),
            C::new(xi[0], xi[1] - self.surface),
        )
    }

    /// The complementary parts of T_ij on the normal `n` (1/m) and of U_ij (m/N per m).
    pub fn complementary_at(
        &self,
        x: [f64; 2],
        xi: [f64; 2],
        n: [f64; 2],
    ) -> ([[f64; 2]; 2], [[f64; 2]; 2]) {
        let (z, z0) = self.local(x, xi);
        let two_g = 2.0 * self.kelvin.shear;
        let (mut t, mut u) = ([[0.0; 2]; 2], [[0.0; 2]; 2]);
        for i in 0..2 {
            let (dphi, ddphi, dpsi, two_g_u) = self.complementary(z, z0, i);
            let p = 4.0 * dphi.re;
            let q = (z.conj() * ddphi + dpsi) * 2.0;
            let (sxx, syy, sxy) = (0.5 * (p - q.re), 0.5 * (p + q.re), 0.5 * q.im);
            t[i] = [sxx * n[0] + sxy * n[1], sxy * n[0] + syy * n[1]];
            let ui = two_g_u / two_g;
            u[i] = [ui.re, ui.im];
        }
        (t, u)
    }
}

/// The sum of two kernels' values.
fn sum(a: [[f64; 2]; 2], b: [[f64; 2]; 2]) -> [[f64; 2]; 2] {
    std::array::from_fn(|i| std::array::from_fn(|j| a[i][j] + b[i][j]))
}

/// The complementary part alone, as a kernel regular at the source, for quadrature over the
/// element that holds the collocation point.
struct Complementary<'a>(&'a Melan);

impl Kernel for Complementary<'_> {
    fn displacement_at(&self, x: [f64; 2], xi: [f64; 2]) -> [[f64; 2]; 2] {
        self.0.complementary_at(x, xi, [0.0, 0.0]).1
    }

    fn traction_at(&self, x: [f64; 2], xi: [f64; 2], n: [f64; 2]) -> [[f64; 2]; 2] {
        self.0.complementary_at(x, xi, n).0
    }

    fn kernels_at(&self, x: [f64; 2], xi: [f64; 2], n: [f64; 2]) -> ([[f64; 2]; 2], [[f64; 2]; 2]) {
        self.0.complementary_at(x, xi, n)
    }

    fn own(&self, el: &Element, c: usize) -> Integrals {
        el.regular(self, el.at(super::elements::COLLOCATION[c]))
    }

    fn nearest_singularity(&self, xi: [f64; 2], el: &Element) -> f64 {
        el.distance_to(self.0.image_of(xi))
    }
}

impl Kernel for Melan {
    fn displacement_at(&self, x: [f64; 2], xi: [f64; 2]) -> [[f64; 2]; 2] {
        let c = self.complementary_at(x, xi, [0.0, 0.0]).1;
        sum(self.kelvin.displacement_at(x, xi), c)
    }

    fn traction_at(&self, x: [f64; 2], xi: [f64; 2], n: [f64; 2]) -> [[f64; 2]; 2] {
        sum(
            self.kelvin.traction_at(x, xi, n),
            self.complementary_at(x, xi, n).0,
        )
    }

    fn kernels_at(&self, x: [f64; 2], xi: [f64; 2], n: [f64; 2]) -> ([[f64; 2]; 2], [[f64; 2]; 2]) {
        let ((kt, ku), (ct, cu)) = (
            self.kelvin.kernels_at(x, xi, n),
            self.complementary_at(x, xi, n),
        );
        (sum(kt, ct), sum(ku, cu))
    }

    fn own(&self, el: &Element, c: usize) -> Integrals {
        let ((h, g), (hc, gc)) = (self.kelvin.own(el, c), Complementary(self).own(el, c));
        (
            std::array::from_fn(|k| sum(h[k], hc[k])),
            std::array::from_fn(|k| sum(g[k], gc[k])),
        )
    }

    fn nearest_singularity(&self, xi: [f64; 2], el: &Element) -> f64 {
        el.distance_to(xi).min(el.distance_to(self.image_of(xi)))
    }
}

#[cfg(test)]
mod tests;
