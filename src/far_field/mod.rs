//! An elastic far field by boundary elements (issue 18; the seed book's chapter 7 and Lorig &
//! Brady's HYDEBE, 1984): the infinite plane-strain medium outside a closed polygon (the
//! interface, whose inside is the near field of zones and blocks) condensed into a stiffness on
//! the polygon's nodes; or the half-plane below a free surface outside an open curve from the
//! surface to the surface.
//!
//! Direct boundary element method (Brebbia & Dominguez 1992, ch. 5) with a fundamental solution
//! (`kernel::Kernel`: Kelvin's for intact rock, `kelvin`; Lekhnitskii's for a jointed rock mass,
//! `lekhnitskii` and `rock_mass`; Melan's for a half-plane, `melan`) on straight discontinuous
//! linear elements, one per polygon edge or one
//! per straight run of several (`elements`): at each collocation point ξ,
//! c_ij u_j(ξ) + ∫_Γ T_ij u_j dΓ = ∫_Γ U_ij t_j dΓ + C_i, over the interface alone, with C the
//! displacement at infinity and the tractions carrying no net force, ∫_Γ t dΓ = 0 (the exterior
//! problem's two conditions at infinity). Collocated at every element's two points,
//! H u_c = G t_c + C and ∫ t = 0, solved for t_c = X u_c (faer's dense LU). The free C makes a
//! translation of the interface cost no force, as it costs the infinite medium none, and frees
//! the solution from the length unit of Kelvin's ln r (without it G is singular for an
//! interface of one size, the degenerate scale, a circle of about a metre here). The polygon's
//! nodes move the collocation points linearly (u_c = Q u, exact for the near field's straight
//! edges), and the tractions, linear along each element, load the nodes through the edges'
//! linear shape functions (f = P t_c, ∫ N_a φ_k ds). So K = P X Q (N/m per m of node
//! displacement): the far field pushes node a by −(K u)_a, u the displacements of the
//! interface's nodes since the far field was attached.
//!
//! K is not symmetric (collocation); its symmetric part is what the implicit path can factorize.

mod attached;
mod carried;
mod elements;
mod kelvin;
mod kernel;
mod lekhnitskii;
mod melan;
mod rock_mass;

use faer::{Conj, Mat, Par};

pub use attached::FarField;
use elements::{COLLOCATION, Element, Integrals};
pub use kelvin::Kelvin;
pub use kernel::Kernel;
pub use lekhnitskii::Lekhnitskii;
pub use melan::Melan;
pub use rock_mass::{JointSet, jointed_compliance, plane_strain_compliance};

/// The far field's rock: isotropic (Kelvin's kernels), anisotropic (Lekhnitskii's, a jointed
/// rock mass as an equivalent continuum), or an isotropic half-plane under a free surface
/// (Melan's).
#[derive(Debug, Clone, PartialEq)]
pub enum Medium {
    Isotropic(Kelvin),
    Anisotropic(Box<Lekhnitskii>),
    HalfPlane(Melan),
}

impl Medium {
    /// The isotropic medium of shear modulus G (Pa) and Poisson's ratio ν.
    pub fn isotropic(shear: f64, poisson: f64) -> Self {
        Self::Isotropic(Kelvin { shear, poisson })
    }

    /// The anisotropic medium of plane-strain compliance `b` (Pa⁻¹; `Lekhnitskii::new`).
    pub fn anisotropic(b: [[f64; 3]; 3]) -> Result<Self, String> {
        Lekhnitskii::new(b).map(|m| Self::Anisotropic(Box::new(m)))
    }
}

impl Kernel for Medium {
    fn displacement_at(&self, x: [f64; 2], xi: [f64; 2]) -> [[f64; 2]; 2] {
        match self {
            Self::Isotropic(m) => m.displacement_at(x, xi),
            Self::Anisotropic(m) => m.displacement_at(x, xi),
            Self::HalfPlane(m) => m.displacement_at(x, xi),
        }
    }

    fn traction_at(&self, x: [f64; 2], xi: [f64; 2], n: [f64; 2]) -> [[f64; 2]; 2] {
        match self {
            Self::Isotropic(m) => m.traction_at(x, xi, n),
            Self::Anisotropic(m) => m.traction_at(x, xi, n),
            Self::HalfPlane(m) => m.traction_at(x, xi, n),
        }
    }

    fn kernels_at(&self, x: [f64; 2], xi: [f64; 2], n: [f64; 2]) -> ([[f64; 2]; 2], [[f64; 2]; 2]) {
        match self {
            Self::Isotropic(m) => m.kernels_at(x, xi, n),
            Self::Anisotropic(m) => m.kernels_at(x, xi, n),
            Self::HalfPlane(m) => m.kernels_at(x, xi, n),
        }
    }

    fn own(&self, el: &Element, c: usize) -> Integrals {
        match self {
            Self::Isotropic(m) => m.own(el, c),
            Self::Anisotropic(m) => m.own(el, c),
            Self::HalfPlane(m) => m.own(el, c),
        }
    }

    fn nearest_singularity(&self, xi: [f64; 2], el: &Element) -> f64 {
        match self {
            Self::Isotropic(m) => m.nearest_singularity(xi, el),
            Self::Anisotropic(m) => m.nearest_singularity(xi, el),
            Self::HalfPlane(m) => m.nearest_singularity(xi, el),
        }
    }

    fn stretch(&self) -> f64 {
        match self {
            Self::Isotropic(m) => m.stretch(),
            Self::Anisotropic(m) => m.stretch(),
            Self::HalfPlane(m) => m.stretch(),
        }
    }
}

/// The far field condensed on the interface's nodes: K, row-major 2n × 2n over the components
/// (x, y) of the n nodes in the polygon's order (N/m per m).
#[derive(Debug, Clone)]
pub struct InterfaceStiffness {
    pub nodes: usize,
    pub k: Vec<f64>,
}

impl InterfaceStiffness {
    /// K's entry for component `d` of node `a` against component `e` of node `b`.
    pub fn at(&self, a: usize, d: usize, b: usize, e: usize) -> f64 {
        self.k[(2 * a + d) * 2 * self.nodes + 2 * b + e]
    }

    /// (K u) for component `d` of node `a`, the node displacements `u` (m), N/m.
    pub fn row_times(&self, a: usize, d: usize, u: &[[f64; 2]]) -> f64 {
        let n2 = 2 * self.nodes;
        let row = &self.k[(2 * a + d) * n2..(2 * a + d + 1) * n2];
        row.iter().zip(u.iter().flatten()).map(|(k, v)| k * v).sum()
    }

    /// The force (N/m) the far field exerts on each node for the displacements `u` (m): −K u.
    pub fn forces(&self, u: &[[f64; 2]], out: &mut [[f64; 2]]) {
        for (a, f) in out.iter_mut().enumerate() {
            *f = [-self.row_times(a, 0, u), -self.row_times(a, 1, u)];
        }
    }
}

/// The far field's stiffness on the closed polygon `points` (m; either orientation, the far
/// field outside), one element per edge: `interface_stiffness_on` with the edges from each point
/// to the next.
pub fn interface_stiffness(
    points: &[[f64; 2]],
    medium: Medium,
) -> Result<InterfaceStiffness, String> {
    let n = points.len();
    let edges: Vec<[usize; 2]> = (0..n).map(|i| [i, (i + 1) % n]).collect();
    interface_stiffness_on(points, &edges, medium)
}

/// The far field's stiffness on the nodes `points` (m) for the elements `edges` (point indices,
/// from start to end along a closed curve, either orientation, the far field outside): two
/// nodes at one place (the two sides of a joint that reaches the interface) stay two nodes,
/// each loaded by its own elements. An error naming the reason for fewer than 3 elements, an
/// element of zero length or of a point that is not given, or constants out of range.
pub fn interface_stiffness_on(
    points: &[[f64; 2]],
    edges: &[[usize; 2]],
    medium: Medium,
) -> Result<InterfaceStiffness, String> {
    let chains: Vec<Vec<usize>> = edges.iter().map(|e| e.to_vec()).collect();
    interface_stiffness_chains(points, &chains, medium)
}

/// `interface_stiffness_on` with elements longer than the edges between nodes: each element is
/// the straight chain of nodes `chains[e]` (point indices from its start to its end, in order
/// along it), whose nodes all move it (its linear displacement the L2 projection of the chain's
/// piecewise-linear field) and all carry its traction (through their hat functions along the
/// chain). An error besides for a chain of fewer than 2 points, not straight, or out of order.
pub fn interface_stiffness_chains(
    points: &[[f64; 2]],
    chains: &[Vec<usize>],
    medium: Medium,
) -> Result<InterfaceStiffness, String> {
    check(points, chains, &medium)?;
    let n = points.len();
    let ends = |c: &Vec<usize>| (points[c[0]], points[c[c.len() - 1]]);
    // Twice the signed area the elements enclose; a half-plane's interface is open, closed by
    // the surface, which adds nothing to it about a point of the surface.
    let lift = match &medium {
        Medium::HalfPlane(m) => m.surface,
        _ => 0.0,
    };
    let area2: f64 = (chains.iter())
        .map(|c| {
            let (p, q) = ends(c);
            p[0] * (q[1] - lift) - q[0] * (p[1] - lift)
        })
        .sum();
    // The far field's outward normal points into the curve: left of a counter-clockwise edge.
    let side = area2.signum();
    let elements: Vec<Element> = (chains.iter())
        .map(|c| {
            let (a, b) = ends(c);
            let len = (b[0] - a[0]).hypot(b[1] - a[1]);
            let t = [(b[0] - a[0]) / len, (b[1] - a[1]) / len];
            Element {
                a,
                b,
                n: [-side * t[1], side * t[0]],
            }
        })
        .collect();
    let places: Vec<Vec<f64>> = (chains.iter().zip(&elements))
        .map(|(c, el)| fractions(points, c, el))
        .collect();
    // Unknowns: component i of collocation point (element e, point k) at 2 (2e + k) + i.
    let size = 4 * elements.len();
    let (mut h, mut g) = (Mat::<f64>::zeros(size, size), Mat::<f64>::zeros(size, size));
    for (e, el) in elements.iter().enumerate() {
        for (c, &eta) in COLLOCATION.iter().enumerate() {
            let xi = el.at(eta);
            let row = 2 * (2 * e + c);
            for (f, other) in elements.iter().enumerate() {
                let (hi, gi) = if f == e {
                    medium.own(other, c)
                } else {
                    other.regular(&medium, xi)
                };
                for k in 0..2 {
                    let col = 2 * (2 * f + k);
                    for i in 0..2 {
                        for j in 0..2 {
                            h[(row + i, col + j)] += hi[k][i][j];
                            g[(row + i, col + j)] += gi[k][i][j];
                        }
                    }
                }
            }
            // The free term of a smooth point: δ_ij / 2.
            for i in 0..2 {
                h[(row + i, row + i)] += 0.5;
            }
        }
    }
    // [G 1; L 0] [t_c; C] = [H u_c; 0], L_(i, (f,k,i)) = ∫ φ_k ds = L_f / 2, by faer's dense LU
    // on this thread (`solve_dense`).
    let mut a = Mat::<f64>::zeros(size + 2, size + 2);
    let mut rhs = Mat::<f64>::zeros(size + 2, size);
    for r in 0..size {
        for c in 0..size {
            a[(r, c)] = g[(r, c)];
            rhs[(r, c)] = h[(r, c)];
        }
        a[(r, size + r % 2)] = 1.0;
    }
    for (f, el) in elements.iter().enumerate() {
        for k in 0..2 {
            for i in 0..2 {
                a[(size + i, 2 * (2 * f + k) + i)] = 0.5 * el.length();
            }
        }
    }
    drop((g, h));
    solve_dense(a, rhs.as_mut())?;
    let h = rhs;
    // K = P X Q.
    // ∫ N_a φ_k ds over element e for each chain node a: its hat function against φ₁ = 3/2 − 2w,
    // φ₂ = 2w − 1/2 (L·[5, 1; 1, 5]/12 for a chain of its two ends), by Simpson's rule on each
    // piece of the hat (exact: the product is quadratic).
    let p = |e: usize, k: usize| -> Vec<(usize, f64)> {
        let (f, chain, len) = (&places[e], &chains[e], elements[e].length());
        let phi = |w: f64| if k == 0 { 1.5 - 2.0 * w } else { 2.0 * w - 0.5 };
        let simpson = |lo: f64, hi: f64, g: &dyn Fn(f64) -> f64| {
            (hi - lo) / 6.0 * (g(lo) + 4.0 * g(0.5 * (lo + hi)) + g(hi))
        };
        (0..chain.len())
            .map(|i| {
                let mut sum = 0.0;
                if i > 0 {
                    let (lo, hi) = (f[i - 1], f[i]);
                    sum += simpson(lo, hi, &|w| (w - lo) / (hi - lo) * phi(w));
                }
                if i + 1 < chain.len() {
                    let (lo, hi) = (f[i], f[i + 1]);
                    sum += simpson(lo, hi, &|w| (hi - w) / (hi - lo) * phi(w));
                }
                (chain[i], len * sum)
            })
            .collect()
    };
    // The element's linear displacement at its collocation point c, from the chain's nodes: the
    // L2 projection of the chain's piecewise-linear field onto the element's linear functions,
    // ũ = M⁻¹ Pᵀ u with M = ∫ φ_k φ_l ds = L·[7, −1; −1, 7]/12, M⁻¹ = [7, 1; 1, 7]/(4L). So
    // K = P X M⁻¹ Pᵀ does work only through what the element can carry, and its symmetric part
    // is positive semi-definite as the one-edge elements' is. For a chain of its two ends the
    // projection is the field itself, ũ(η) = (1 − w) u₀ + w u₁ at w = (1 + η)/2 ([3, 1; 1, 3]/4),
    // taken so. Sampling the chain's field at the collocation points instead gave a chain of 3 or
    // more edges a symmetric part with eigenvalues down to −23 % of the largest (a square of 80
    // edges in elements of 3 to 10 edges), which no zoning's stiffness covers: the implicit
    // factorization broke down (NonPositivePivot).
    let q = |e: usize, c: usize| -> Vec<(usize, f64)> {
        let chain = &chains[e];
        if chain.len() == 2 {
            let w = 0.5 * (1.0 + COLLOCATION[c]);
            return vec![(chain[0], 1.0 - w), (chain[1], w)];
        }
        let len = elements[e].length();
        let m_inv = |k: usize, l: usize| (if k == l { 7.0 } else { 1.0 }) / (4.0 * len);
        let (p0, p1) = (p(e, 0), p(e, 1));
        (p0.iter().zip(&p1))
            .map(|(&(node, a), &(_, b))| (node, m_inv(c, 0) * a + m_inv(c, 1) * b))
            .collect()
    };
    let q: Vec<[Vec<(usize, f64)>; 2]> = (0..elements.len()).map(|e| [q(e, 0), q(e, 1)]).collect();
    // X Q first (size × 2n; X the first `size` rows of the solution), then P (X Q) (2n × 2n).
    let mut xq = vec![0.0; size * 2 * n];
    for row in 0..size {
        for (f, q) in q.iter().enumerate() {
            for (c, q) in q.iter().enumerate() {
                for &(node, w) in q {
                    for j in 0..2 {
                        xq[row * 2 * n + 2 * node + j] += h[(row, 2 * (2 * f + c) + j)] * w;
                    }
                }
            }
        }
    }
    let mut k = vec![0.0; 4 * n * n];
    for e in 0..elements.len() {
        for c in 0..2 {
            for (node, w) in p(e, c) {
                for i in 0..2 {
                    let from = (2 * (2 * e + c) + i) * 2 * n;
                    let to = (2 * node + i) * 2 * n;
                    for col in 0..2 * n {
                        k[to + col] += w * xq[from + col];
                    }
                }
            }
        }
    }
    Ok(InterfaceStiffness { nodes: n, k })
}

/// Solve `a` x = `rhs` in place by faer's LU with partial pivoting, on the calling thread: the
/// same rounding on any number of threads (a parallel LU's blocking follows the thread count),
/// as the implicit path's factorizations (`implicit::factor`); an error if its scratch cannot be
/// had.
fn solve_dense(mut a: Mat<f64>, rhs: faer::MatMut<'_, f64>) -> Result<(), String> {
    use faer::dyn_stack::{MemBuffer, MemStack};
    use faer::linalg::lu::partial_pivoting::{factor, solve};
    let (m, par) = (a.nrows(), Par::Seq);
    let scratch = |req| {
        MemBuffer::try_new(req).map_err(|e| format!("far field: the dense solve's scratch: {e:?}"))
    };
    let (mut fwd, mut bwd) = (vec![0usize; m], vec![0usize; m]);
    let mut work = scratch(factor::lu_in_place_scratch::<usize, f64>(
        m,
        m,
        par,
        Default::default(),
    ))?;
    let (_, perm) = factor::lu_in_place(
        a.as_mut(),
        &mut fwd,
        &mut bwd,
        par,
        MemStack::new(&mut work),
        Default::default(),
    );
    let mut work = scratch(solve::solve_in_place_scratch::<usize, f64>(
        m,
        rhs.ncols(),
        par,
    ))?;
    solve::solve_in_place_with_conj(
        a.as_ref(),
        a.as_ref(),
        perm,
        Conj::No,
        rhs,
        par,
        MemStack::new(&mut work),
    );
    crate::vector_state::clear_upper_vector_state();
    Ok(())
}

/// Where each node of `chain` sits along `element` (fractions of its length, 0 at its start and
/// 1 at its end).
fn fractions(points: &[[f64; 2]], chain: &[usize], element: &Element) -> Vec<f64> {
    let (a, b) = (element.a, element.b);
    let d = [b[0] - a[0], b[1] - a[1]];
    let l2 = d[0] * d[0] + d[1] * d[1];
    (chain.iter())
        .map(|&i| {
            let p = points[i];
            ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / l2
        })
        .collect()
}

/// The reasons `interface_stiffness_chains` refuses its input.
fn check(points: &[[f64; 2]], chains: &[Vec<usize>], m: &Medium) -> Result<(), String> {
    if let Medium::Isotropic(m) | Medium::HalfPlane(Melan { kelvin: m, .. }) = m {
        if !(m.shear > 0.0 && m.shear.is_finite()) {
            return Err(format!(
                "far field: shear modulus {} Pa is not positive",
                m.shear
            ));
        }
        if !(m.poisson > -1.0 && m.poisson < 0.5) {
            return Err(format!(
                "far field: Poisson's ratio {} is outside (−1, 0.5)",
                m.poisson
            ));
        }
    }
    if chains.len() < 3 {
        return Err(format!(
            "far field: the interface has {} elements, fewer than 3",
            chains.len()
        ));
    }
    if let Some(i) = points
        .iter()
        .position(|p| !(p[0].is_finite() && p[1].is_finite()))
    {
        return Err(format!("far field: interface point {i} is not finite"));
    }
    let span = (points.iter().flatten()).fold(0.0f64, |m, v| m.max(v.abs()));
    for (e, chain) in chains.iter().enumerate() {
        if chain.len() < 2 {
            return Err(format!("far field: element {e} has {} points", chain.len()));
        }
        if let Some(&i) = chain.iter().find(|&&i| i >= points.len()) {
            return Err(format!(
                "far field: element {e} joins point {i}, of {} given",
                points.len()
            ));
        }
        let (a, b) = (chain[0], chain[chain.len() - 1]);
        let (p, q) = (points[a], points[b]);
        let len = (q[0] - p[0]).hypot(q[1] - p[1]);
        if len <= 1e-12 * span {
            return Err(format!(
                "far field: element {e}'s ends, points {a} and {b}, coincide"
            ));
        }
        let t = [(q[0] - p[0]) / len, (q[1] - p[1]) / len];
        let mut last = f64::NEG_INFINITY;
        for &i in chain {
            let r = [points[i][0] - p[0], points[i][1] - p[1]];
            let (along, off) = (r[0] * t[0] + r[1] * t[1], r[0] * t[1] - r[1] * t[0]);
            if off.abs() > 1e-6 * len {
                return Err(format!(
                    "far field: element {e} is not straight (point {i} lies {off:.3e} m off it)"
                ));
            }
            if along <= last {
                return Err(format!(
                    "far field: element {e}'s points are not in order along it (point {i})"
                ));
            }
            last = along;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests;
