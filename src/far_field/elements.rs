//! Straight discontinuous linear boundary elements and their integrals of a fundamental
//! solution (`kernel::Kernel`: Kelvin's isotropic one or Lekhnitskii's anisotropic one).
//!
//! An element from a to b (length L, unit tangent t) carries displacement and traction linear
//! along it, given at its two collocation points η = ∓1/2 (η ∈ [−1, 1] from a to b, s = L(η + 1)/2
//! the arc length): φ₁ = 1/2 − η, φ₂ = η + 1/2. Being inside the element, the collocation points
//! are smooth points of the boundary (free term c_ij = δ_ij/2) wherever the polygon has its
//! corners, and neighbouring elements need not share a traction (a corner's two tractions differ).
//!
//! The integrals over an element that holds the collocation point are analytical: along a
//! straight element both kernels are a constant times ln|s − s₀| (plus a constant on each side
//! of the point) for U and times 1/(s − s₀) for T, so each kernel combines the scalar integrals
//! ∫ φ ln|s − s₀| ds, the principal value of ∫ φ/(s − s₀) ds and ∫ φ ds before and after the
//! point (`OwnScalars`). The others are by
//! 8-point Gauss–Legendre over sub-segments no longer than a third of the collocation point's
//! distance from the element, so a neighbour's end, a quarter of an element from the point,
//! is integrated as accurately as a far element.

use super::kernel::Kernel;

/// Where an element's two collocation points sit, η.
pub const COLLOCATION: [f64; 2] = [-0.5, 0.5];

/// The shape functions of the element's two collocation points at η.
pub fn shape(eta: f64) -> [f64; 2] {
    [0.5 - eta, eta + 0.5]
}

/// 8-point Gauss–Legendre abscissae and weights on [−1, 1].
pub(super) const GAUSS: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

/// Most sub-segments a regular integral splits an element into.
const MOST_PIECES: usize = 256;

/// A straight element from `a` to `b` (m) and the unit normal `n` pointing out of the medium.
#[derive(Debug, Clone, Copy)]
pub struct Element {
    pub a: [f64; 2],
    pub b: [f64; 2],
    pub n: [f64; 2],
}

/// ∫ T_ij φ_k ds and ∫ U_ij φ_k ds over an element for one collocation point: [k][i][j].
pub type Integrals = ([[[f64; 2]; 2]; 2], [[[f64; 2]; 2]; 2]);

/// One shape function φ's scalar integrals over the element that holds the collocation point
/// s₀ (s the arc length, m).
#[derive(Debug, Clone, Copy)]
pub struct OwnScalars {
    /// ∫ φ ln|s − s₀| ds, m.
    pub log: f64,
    /// The principal value of ∫ φ / (s − s₀) ds.
    pub pv: f64,
    /// ∫ φ ds over s < s₀, m.
    pub before: f64,
    /// ∫ φ ds over s > s₀, m.
    pub after: f64,
    /// ∫ φ ds over the element, L/2, m.
    pub whole: f64,
}

impl Element {
    pub fn length(&self) -> f64 {
        (self.b[0] - self.a[0]).hypot(self.b[1] - self.a[1])
    }

    /// The point at η.
    pub fn at(&self, eta: f64) -> [f64; 2] {
        let w = 0.5 * (eta + 1.0);
        [
            self.a[0] + w * (self.b[0] - self.a[0]),
            self.a[1] + w * (self.b[1] - self.a[1]),
        ]
    }

    /// The integrals of T and U times each shape function for the collocation point `xi` (m)
    /// outside the element (regular, by quadrature).
    pub fn regular(&self, m: &impl Kernel, xi: [f64; 2]) -> Integrals {
        let len = self.length();
        let distance = m.nearest_singularity(xi, self);
        let pieces = ((3.0 * m.stretch() * len / distance).ceil() as usize).clamp(1, MOST_PIECES);
        let (mut h, mut g) = ([[[0.0; 2]; 2]; 2], [[[0.0; 2]; 2]; 2]);
        let width = 2.0 / pieces as f64;
        for p in 0..pieces {
            let start = -1.0 + p as f64 * width;
            for &(x, w) in &GAUSS {
                let eta = start + 0.5 * width * (x + 1.0);
                let weight = w * 0.5 * width * 0.5 * len;
                let x = self.at(eta);
                let (t, u) = m.kernels_at(x, xi, self.n);
                let phi = shape(eta);
                for k in 0..2 {
                    for i in 0..2 {
                        for j in 0..2 {
                            h[k][i][j] += t[i][j] * phi[k] * weight;
                            g[k][i][j] += u[i][j] * phi[k] * weight;
                        }
                    }
                }
            }
        }
        (h, g)
    }

    /// The distance from `p` to the element, m.
    pub fn distance_to(&self, p: [f64; 2]) -> f64 {
        distance_to_segment(p, self.a, self.b)
    }

    /// The unit tangent, from a to b.
    pub fn tangent(&self) -> [f64; 2] {
        let len = self.length();
        [(self.b[0] - self.a[0]) / len, (self.b[1] - self.a[1]) / len]
    }

    /// The scalar integrals of each shape function about the collocation point `c`.
    pub fn own_scalars(&self, c: usize) -> [OwnScalars; 2] {
        let len = self.length();
        let s0 = 0.5 * len * (COLLOCATION[c] + 1.0);
        // φ_k(s) = α + β s.
        let lines = [(1.5, -2.0 / len), (-0.5, 2.0 / len)];
        let (before, after) = (s0, len - s0);
        let f0 = |d: f64| d * d.ln() - d;
        let f1 = |d: f64| 0.5 * d * d * d.ln() - 0.25 * d * d;
        lines.map(|(alpha, beta)| {
            let at_s0 = alpha + beta * s0;
            OwnScalars {
                log: at_s0 * (f0(before) + f0(after)) + beta * (f1(after) - f1(before)),
                pv: at_s0 * (after / before).ln() + beta * len,
                before: alpha * s0 + 0.5 * beta * s0 * s0,
                after: alpha * after + 0.5 * beta * (len * len - s0 * s0),
                whole: 0.5 * len,
            }
        })
    }
}

/// The distance from `p` to the segment from `a` to `b`, m.
pub(super) fn distance_to_segment(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (ab, ap) = ([b[0] - a[0], b[1] - a[1]], [p[0] - a[0], p[1] - a[1]]);
    let w = ((ap[0] * ab[0] + ap[1] * ab[1]) / (ab[0] * ab[0] + ab[1] * ab[1])).clamp(0.0, 1.0);
    (ap[0] - w * ab[0]).hypot(ap[1] - w * ab[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The analytical integrals over the element's own point match quadrature that steps around
    /// the point, for Kelvin's kernels and for Lekhnitskii's (the jointed tunnel's rock mass): U
    /// by fine midpoint sums (its log is integrable), T's principal value by pairing the points
    /// at ±x about the point (∫ f(x)/x over [−w, w] is ∫ (f(x) − f(−x))/x over [0, w], regular)
    /// and a plain sum over the rest.
    #[test]
    fn the_own_element_integrals_match_careful_quadrature() {
        let kelvin = crate::far_field::Kelvin {
            shear: 2e9,
            poisson: 0.3,
        };
        own_integrals_match_quadrature(&kelvin);
        own_integrals_match_quadrature(&crate::far_field::lekhnitskii::tests::jointed());
    }

    fn own_integrals_match_quadrature(m: &impl Kernel) {
        let (dx, dy) = (0.9f64, 0.6f64);
        let l = dx.hypot(dy);
        let e = Element {
            a: [0.2, -0.1],
            b: [1.1, 0.5],
            n: [-dy / l, dx / l],
        };
        let len = e.length();
        let count = 200_000;
        for (c, &eta) in COLLOCATION.iter().enumerate() {
            let (h, g) = m.own(&e, c);
            let xi = e.at(eta);
            let s0 = 0.5 * len * (eta + 1.0);
            // T φ_k and U φ_k at arc length s.
            let at = |s: f64| {
                let eta = 2.0 * s / len - 1.0;
                let x = e.at(eta);
                (
                    m.traction_at(x, xi, e.n),
                    m.displacement_at(x, xi),
                    shape(eta),
                )
            };
            let (mut hq, mut gq) = ([[[0.0; 2]; 2]; 2], [[[0.0; 2]; 2]; 2]);
            let add = |into: &mut [[[f64; 2]; 2]; 2], k: [[f64; 2]; 2], phi: [f64; 2], w: f64| {
                for kk in 0..2 {
                    for i in 0..2 {
                        for j in 0..2 {
                            into[kk][i][j] += k[i][j] * phi[kk] * w;
                        }
                    }
                }
            };
            let ds = len / count as f64;
            for q in 0..count {
                let (_, u, phi) = at((q as f64 + 0.5) * ds);
                add(&mut gq, u, phi, ds);
            }
            let w = s0.min(len - s0);
            let dx = w / count as f64;
            for q in 0..count {
                let x = (q as f64 + 0.5) * dx;
                let ((tp, _, pp), (tm, _, pm)) = (at(s0 + x), at(s0 - x));
                add(&mut hq, tp, pp, dx);
                add(&mut hq, tm, pm, dx);
            }
            let (lo, hi) = if s0 < len - s0 {
                (2.0 * s0, len)
            } else {
                (0.0, len - 2.0 * (len - s0))
            };
            let dr = (hi - lo) / count as f64;
            for q in 0..count {
                let (t, _, phi) = at(lo + (q as f64 + 0.5) * dr);
                add(&mut hq, t, phi, dr);
            }
            for k in 0..2 {
                for i in 0..2 {
                    for j in 0..2 {
                        let scale_g = 1e-4 * g[k][0][0].abs();
                        assert!((g[k][i][j] - gq[k][i][j]).abs() < scale_g, "{g:?} {gq:?}");
                        assert!((h[k][i][j] - hq[k][i][j]).abs() < 1e-6, "{h:?} {hq:?}");
                    }
                }
            }
        }
    }
}
