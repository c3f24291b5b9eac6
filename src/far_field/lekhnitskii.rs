//! Lekhnitskii's fundamental solution of a plane anisotropic medium: a unit line force in the
//! infinite plane of any in-plane compliance (a jointed rock mass taken as an equivalent
//! continuum, `rock_mass`). Lekhnitskii, *Theory of Elasticity of an Anisotropic Body*, 1963,
//! §§ 16–19; as a boundary element kernel, Rizzo & Shippy, *J. Compos. Mater.* 4, 1970.
//!
//! With the plane-strain compliance b (ε_xx, ε_yy, γ_xy = b (σ_xx, σ_yy, σ_xy)), the roots μ_k of
//! b₁₁ μ⁴ − 2 b₁₆ μ³ + (2 b₁₂ + b₆₆) μ² − 2 b₂₆ μ + b₂₂ = 0 with Im μ_k > 0 (k = 1, 2) and
//! z_k = x + μ_k y, any pair of analytic φ_k(z_k) gives
//!
//! σ_xx = 2 Re Σ μ_k² φ_k′, σ_yy = 2 Re Σ φ_k′, σ_xy = −2 Re Σ μ_k φ_k′,
//! u = 2 Re Σ p_k φ_k, v = 2 Re Σ q_k φ_k,
//! p_k = b₁₁ μ_k² + b₁₂ − b₁₆ μ_k, q_k = b₁₂ μ_k + b₂₂/μ_k − b₂₆.
//!
//! A force P at the origin is φ_k = A_k ln z_k, with A_k from four real conditions: the tractions
//! on a loop about the origin balance P (Σ A_k − c.c. = −i P_y/2π, Σ μ_k A_k − c.c. = i P_x/2π) and
//! the displacement comes back to itself (Σ p_k A_k − c.c. = 0, Σ q_k A_k − c.c. = 0). Then
//!
//! U_ij = 2 Re Σ_k P_jk A_ki ln(z_k − z_k⁰), P_1k = p_k, P_2k = q_k,
//! T_i1 = 2 Re Σ_k μ_k (μ_k n_x − n_y) A_ki / (z_k − z_k⁰), T_i2 = −2 Re Σ_k (μ_k n_x − n_y) A_ki / (z_k − z_k⁰),
//!
//! the displacement and traction along j of a unit force along i (`kernel::Kernel`).
//!
//! Both principal logarithms cut along the same ray (d_y = 0, d_x < 0), where their jumps cancel
//! by the third and fourth conditions, so U is continuous off the source. An isotropic
//! compliance has the double root μ = i, where this form fails: a compliance whose roots lie
//! closer than `SPLIT` is given a shear compliance b₆₆ larger by a millionth (or by ten, a
//! hundred … millionths, until they split), which moves the answers by as much.

use nalgebra::{Complex, Matrix4, Vector4};

use super::elements::{Integrals, OwnScalars};
use super::kernel::Translational;

type C = Complex<f64>;

/// The least distance between the two roots, relative to their size, that the kernel takes as
/// distinct.
const SPLIT: f64 = 1e-3;

/// A plane anisotropic medium: its plane-strain compliance and Lekhnitskii's constants.
#[derive(Debug, Clone, PartialEq)]
pub struct Lekhnitskii {
    /// The plane-strain compliance b, Pa⁻¹: (ε_xx, ε_yy, γ_xy) = b (σ_xx, σ_yy, σ_xy).
    pub compliance: [[f64; 3]; 3],
    /// The roots μ_k with positive imaginary part.
    mu: [C; 2],
    /// p_k (row 0) and q_k (row 1), Pa⁻¹.
    pq: [[C; 2]; 2],
    /// A_kj: root k, unit force along j, N/m per N/m.
    a: [[C; 2]; 2],
}

impl Lekhnitskii {
    /// The medium of compliance `b` (Pa⁻¹, symmetric positive definite); an error naming the
    /// reason otherwise.
    pub fn new(b: [[f64; 3]; 3]) -> Result<Self, String> {
        if b.iter().flatten().any(|v| !v.is_finite()) {
            return Err("far field: the compliance is not finite".into());
        }
        let scale = b.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
        let asymmetric = (0..3).any(|i| (0..i).any(|j| (b[i][j] - b[j][i]).abs() > 1e-12 * scale));
        if asymmetric {
            return Err("far field: the compliance is not symmetric".into());
        }
        let det2 = b[0][0] * b[1][1] - b[0][1] * b[1][0];
        let det3 = nalgebra::Matrix3::from_fn(|i, j| b[i][j]).determinant();
        if !(b[0][0] > 0.0 && det2 > 0.0 && det3 > 0.0) {
            return Err("far field: the compliance is not positive definite".into());
        }
        let mut b = b;
        let mut nudge = 1e-6;
        loop {
            let mu = roots(&b);
            if (mu[0] - mu[1]).norm() >= SPLIT * (mu[0].norm() + mu[1].norm()) {
                return Self::with_roots(b, mu);
            }
            if nudge > 1e-2 {
                return Err("far field: the compliance's characteristic roots do not split".into());
            }
            b[2][2] *= 1.0 + nudge;
            nudge *= 10.0;
        }
    }

    /// The constants for the roots `mu`; an error where round-off leaves their conditions
    /// singular or the constants not finite (a compliance of extreme anisotropy).
    fn with_roots(b: [[f64; 3]; 3], mu: [C; 2]) -> Result<Self, String> {
        let p = mu.map(|m| m * m * b[0][0] + b[0][1] - m * b[0][2]);
        let q = mu.map(|m| m * b[0][1] + b[1][1] / m - b[1][2]);
        let row = |v: [C; 2]| [v[0], v[1], -v[0].conj(), -v[1].conj()];
        let one = C::new(1.0, 0.0);
        let m = Matrix4::from_rows(&[
            row([one, one]).into(),
            row(mu).into(),
            row(p).into(),
            row(q).into(),
        ]);
        let lu = m.lu();
        let tau = 2.0 * std::f64::consts::PI;
        let singular = || {
            "far field: the compliance is too anisotropic for its kernels (their force conditions \
             are singular to round-off)"
                .to_string()
        };
        let solve = |rhs: Vector4<C>| lu.solve(&rhs).ok_or_else(singular);
        // Unit forces along x and along y.
        let ax = solve(Vector4::new(
            C::new(0.0, 0.0),
            C::new(0.0, 1.0 / tau),
            C::new(0.0, 0.0),
            C::new(0.0, 0.0),
        ))?;
        let ay = solve(Vector4::new(
            C::new(0.0, -1.0 / tau),
            C::new(0.0, 0.0),
            C::new(0.0, 0.0),
            C::new(0.0, 0.0),
        ))?;
        let finite = |z: &C| z.re.is_finite() && z.im.is_finite();
        let all = [
            ax[0], ax[1], ay[0], ay[1], mu[0], mu[1], p[0], p[1], q[0], q[1],
        ];
        if !all.iter().all(finite) {
            return Err(singular());
        }
        Ok(Self {
            compliance: b,
            mu,
            pq: [p, q],
            a: [[ax[0], ay[0]], [ax[1], ay[1]]],
        })
    }

    /// The roots μ₁, μ₂.
    pub fn roots(&self) -> [C; 2] {
        self.mu
    }

    /// μ_k n_x − n_y times (μ_k, −1): the traction factors of root k on the normal `n`.
    fn traction_factors(&self, n: [f64; 2]) -> [[C; 2]; 2] {
        let f = self.mu.map(|m| m * n[0] - n[1]);
        [[self.mu[0] * f[0], self.mu[1] * f[1]], [-f[0], -f[1]]]
    }

    /// 2 Re Σ_k c_jk A_ki w_k at [i][j] (a unit force along i, the component j): the sum every
    /// kernel here is.
    fn sum(&self, c: &[[C; 2]; 2], w: [C; 2]) -> [[f64; 2]; 2] {
        std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                2.0 * (0..2)
                    .map(|k| (c[j][k] * self.a[k][i] * w[k]).re)
                    .sum::<f64>()
            })
        })
    }
}

impl Translational for Lekhnitskii {
    fn displacement(&self, d: [f64; 2]) -> [[f64; 2]; 2] {
        let w = self.mu.map(|m| (m * d[1] + d[0]).ln());
        self.sum(&self.pq, w)
    }

    fn traction(&self, d: [f64; 2], n: [f64; 2]) -> [[f64; 2]; 2] {
        let w = self.mu.map(|m| (m * d[1] + d[0]).inv());
        self.sum(&self.traction_factors(n), w)
    }

    /// Along the element z_k − z_k⁰ = (s − s₀) ω_k, ω_k = t_x + μ_k t_y: ln(z_k − z_k⁰) is
    /// ln|s − s₀| + ln ω_k after the point and ln|s − s₀| + ln(−ω_k) before it (principal
    /// logarithms), and 1/(z_k − z_k⁰) = 1/((s − s₀) ω_k).
    fn own_on(&self, t: [f64; 2], n: [f64; 2], s: &[OwnScalars; 2]) -> Integrals {
        let omega = self.mu.map(|m| m * t[1] + t[0]);
        let tf = self.traction_factors(n);
        let (mut h, mut g) = ([[[0.0; 2]; 2]; 2], [[[0.0; 2]; 2]; 2]);
        for (k, s) in s.iter().enumerate() {
            let w = omega.map(|o| o.ln() * s.after + (-o).ln() * s.before + s.log);
            g[k] = self.sum(&self.pq, w);
            h[k] = self.sum(&tf, omega.map(|o| o.inv() * s.pv));
        }
        (h, g)
    }

    /// The largest condition number of the maps (x, y) ↦ z_k = x + μ_k y: the kernels vary with
    /// |z_k − z_k⁰|, which may be this many times smaller than the distance.
    fn stretch(&self) -> f64 {
        let condition = |m: C| {
            // Singular values of [1, Re μ; 0, Im μ]: the roots of s⁴ − (1 + |μ|²) s² + (Im μ)².
            let (sum, det) = (1.0 + m.norm_sqr(), m.im.abs());
            let root = (sum * sum - 4.0 * det * det).max(0.0).sqrt();
            ((sum + root) / (sum - root)).sqrt()
        };
        condition(self.mu[0]).max(condition(self.mu[1]))
    }
}

/// The two roots with positive imaginary part of b₁₁ μ⁴ − 2 b₁₆ μ³ + (2 b₁₂ + b₆₆) μ² − 2 b₂₆ μ +
/// b₂₂ (none is real for a positive definite b, and they come in conjugate pairs): the
/// companion matrix's eigenvalues, each polished by Newton's steps on the polynomial, the one of
/// smaller imaginary part first.
fn roots(b: &[[f64; 3]; 3]) -> [C; 2] {
    let c = [
        b[1][1] / b[0][0],
        -2.0 * b[1][2] / b[0][0],
        (2.0 * b[0][1] + b[2][2]) / b[0][0],
        -2.0 * b[0][2] / b[0][0],
    ];
    #[rustfmt::skip]
    let companion = Matrix4::new(
        -c[3], -c[2], -c[1], -c[0],
        1.0, 0.0, 0.0, 0.0,
        0.0, 1.0, 0.0, 0.0,
        0.0, 0.0, 1.0, 0.0,
    );
    // The two of largest imaginary part: a double root may come out as two roots or one pair
    // with a round-off's imaginary parts apart.
    let mut all: Vec<C> = companion.complex_eigenvalues().iter().copied().collect();
    all.sort_by(|x, y| y.im.total_cmp(&x.im));
    let upper = [all[0], all[1]];
    let polish = |mut z: C| {
        for _ in 0..8 {
            let f = (((z + c[3]) * z + c[2]) * z + c[1]) * z + c[0];
            let df = ((z * 4.0 + 3.0 * c[3]) * z + 2.0 * c[2]) * z + c[1];
            if df.norm() == 0.0 {
                break;
            }
            z -= f / df;
        }
        z
    };
    let mut mu = [polish(upper[0]), polish(upper[1])];
    if mu[1].im < mu[0].im {
        mu.swap(0, 1);
    }
    mu
}

#[cfg(test)]
pub(super) mod tests;
