//! Rigid and simple blocks ("bodies"): blocks without zones whose boundary nodes follow a few
//! degrees of freedom about the block centroid c,
//!
//!   v_i = v_c + L r_i,   L = [[ε̇xx, ε̇xy − ω], [ε̇xy + ω, ε̇yy]],   r_i = x_i − c,
//!
//! with generalised velocity q̇ = (vx, vy, ω, ε̇xx, ε̇yy, ε̇xy). A `rigid` block keeps the strain
//! rates at zero (3 DOF, UDEC's rigid blocks); a `simple` block has all six (the simply deformable
//! block of Wang & Xing 1991, ch. 5: rigid motion plus one uniform strain, its stress from the
//! zone law of its material). The generalised force is Q = Σ_i T_iᵀ f_i over the block's nodes,
//! T_i = [[1, 0, −r_y, r_x, 0, r_y], [0, 1, r_x, 0, r_y, r_x]], minus A(σxx, σyy, 2σxy) on the
//! strain DOFs, plus the weight ρ A g on the translation.

use super::{MaterialId, Stress};

/// Number of generalised DOFs of a simple block (a rigid block uses the first 3).
pub const DOFS: usize = 6;

/// Generalised vector (velocity m/s, rad/s, 1/s; force N/m, N·m/m, N·m/m; mass kg/m, kg·m).
pub type Dof = [f64; DOFS];

/// Constraint Gram matrix of a body: G = Σ tᵀ t over the rows t of the velocity map at its fixed
/// node components (zero: free; identity: held still).
pub type Gram = [[f64; DOFS]; DOFS];

/// How a body moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BodyMode {
    Rigid,
    Simple,
}

impl BodyMode {
    /// Name as in scenes: `rigid` or `simple`.
    pub fn label(self) -> &'static str {
        match self {
            BodyMode::Rigid => "rigid",
            BodyMode::Simple => "simple",
        }
    }

    /// DOFs in use: 3 for rigid, 6 for simple.
    pub fn dofs(self) -> usize {
        match self {
            BodyMode::Rigid => 3,
            BodyMode::Simple => DOFS,
        }
    }
}

/// Structure-of-arrays body state; body k is block `block[k]`, owning nodes
/// `nodes[k][0]..nodes[k][1]` (all boundary nodes).
#[derive(Debug, Clone, Default)]
pub struct Bodies {
    pub block: Vec<u32>,
    pub mode: Vec<BodyMode>,
    pub nodes: Vec<[u32; 2]>,
    /// Current centroid, m.
    pub centroid: Vec<[f64; 2]>,
    /// Generalised velocity q̇.
    pub velocity: Vec<Dof>,
    /// Diagonal generalised mass used by the integrator (scaled in static runs).
    pub mass: Vec<Dof>,
    /// Last unbalanced generalised force (the constraint's reaction removed).
    pub force: Vec<Dof>,
    /// Weight ρ A g, N/m.
    pub weight: Vec<[f64; 2]>,
    /// Current area, m².
    pub area: Vec<f64>,
    /// Radius of gyration scale ℓ = max |r_i| at the start, m (turns moments into forces).
    pub radius: Vec<f64>,
    pub material: Vec<MaterialId>,
    /// Uniform stress of a simple block, Pa (zero for rigid blocks).
    pub stress: Vec<Stress>,
    /// Zone-law state of a simple block.
    pub state: Vec<u8>,
    /// Accumulated plastic shear strain of a simple block (dimensionless).
    pub plastic: Vec<f64>,
    /// What the boundary conditions on the block's nodes hold: the Gram matrix of their rows of
    /// the velocity map (a roller on a simple block holds one velocity component along its wall,
    /// not the block's strain).
    pub(crate) constraint: Vec<Gram>,
    /// The mass-orthogonal projector onto the velocities the constraint allows (set with the
    /// masses by the solver), `None` for a free body.
    pub(crate) projector: Vec<Option<Gram>>,
    /// This cycle's motion: old centroid, new centroid and the map r_new = A r_old
    /// (row-major 2×2), read by the node update.
    pub step: Vec<([f64; 2], [f64; 2], [f64; 4])>,
    /// For each node, its body, or `NO_BODY`.
    pub(crate) of_node: Vec<u32>,
    /// Display triangles (node ids) of the bodies' outlines, and the body of each.
    pub(crate) outline: Vec<[u32; 3]>,
    pub(crate) outline_body: Vec<u32>,
}

/// Marks "not a body node" in `Bodies::of_node`.
pub const NO_BODY: u32 = u32::MAX;

impl Bodies {
    pub fn len(&self) -> usize {
        self.block.len()
    }

    pub fn is_empty(&self) -> bool {
        self.block.is_empty()
    }
}

/// An orthonormal basis of the generalised motions over the first `dofs` DOFs that the
/// constraint Gram `g` allows: its null space, the eigenvectors whose eigenvalues are below 1e-9
/// of the largest (empty for a body held still); `None` for a free body (G = 0).
pub fn allowed_motions(g: &Gram, dofs: usize) -> Option<Vec<Dof>> {
    use nalgebra::{DMatrix, SymmetricEigen};
    let gd = DMatrix::from_fn(dofs, dofs, |i, j| g[i][j]);
    let eig = SymmetricEigen::new(gd);
    let largest = eig.eigenvalues.iter().fold(0.0f64, |m, &v| m.max(v.abs()));
    if largest == 0.0 {
        return None;
    }
    Some(
        (0..dofs)
            .filter(|&j| eig.eigenvalues[j].abs() <= 1e-9 * largest)
            .map(|j| {
                std::array::from_fn(|i| {
                    if i < dofs {
                        eig.eigenvectors[(i, j)]
                    } else {
                        0.0
                    }
                })
            })
            .collect(),
    )
}

/// The mass-orthogonal projector onto the velocities a constraint allows, over the first `dofs`
/// DOFs: with N the basis of `allowed_motions`, P = N (Nᵀ M N)⁻¹ Nᵀ M. It keeps what the
/// constraint allows (P N = N) and removes the reaction: P M⁻¹ Cᵀλ = 0, so the body is in
/// equilibrium when its force is a reaction. `None` for a free body (G = 0).
pub fn projector(g: &Gram, mass: &Dof, dofs: usize) -> Option<Gram> {
    use nalgebra::DMatrix;
    let free = allowed_motions(g, dofs)?;
    let mut out = [[0.0; DOFS]; DOFS];
    if free.is_empty() {
        return Some(out);
    }
    let n = DMatrix::from_fn(dofs, free.len(), |i, j| free[j][i]);
    let m = DMatrix::from_fn(dofs, dofs, |i, j| if i == j { mass[i] } else { 0.0 });
    let reduced = (n.transpose() * &m * &n).try_inverse()?;
    let p = &n * reduced * n.transpose() * m;
    for (i, row) in out.iter_mut().enumerate().take(dofs) {
        for (j, v) in row.iter_mut().enumerate().take(dofs) {
            *v = p[(i, j)];
        }
    }
    Some(out)
}

/// y = P x over all DOFs.
pub fn apply(p: &Gram, x: &Dof) -> Dof {
    std::array::from_fn(|i| (0..DOFS).map(|j| p[i][j] * x[j]).sum())
}

/// The velocity map T (2 × 6) at offset r from the centroid.
pub fn velocity_map(r: [f64; 2]) -> [[f64; DOFS]; 2] {
    [
        [1.0, 0.0, -r[1], r[0], 0.0, r[1]],
        [0.0, 1.0, r[0], 0.0, r[1], r[0]],
    ]
}

/// Area, centroid and second moments (∫x², ∫y², ∫xy about the centroid, m⁴) of the region on the
/// left of closed rings of edges, by Green's theorem (Σ over edges (a, b) of the cross product
/// a × b times the edge's moment polynomial), taken about the first vertex for precision.
pub fn polygon_moments(edges: impl Iterator<Item = ([f64; 2], [f64; 2])> + Clone) -> Moments {
    let origin = edges.clone().next().map_or([0.0; 2], |e| e.0);
    let (mut a, mut sx, mut sy, mut ixx, mut iyy, mut ixy) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    for (p, q) in edges {
        let (x0, y0) = (p[0] - origin[0], p[1] - origin[1]);
        let (x1, y1) = (q[0] - origin[0], q[1] - origin[1]);
        let cross = x0 * y1 - x1 * y0;
        a += cross;
        sx += cross * (x0 + x1);
        sy += cross * (y0 + y1);
        ixx += cross * (x0 * x0 + x0 * x1 + x1 * x1);
        iyy += cross * (y0 * y0 + y0 * y1 + y1 * y1);
        ixy += cross * (x0 * y1 + 2.0 * x0 * y0 + 2.0 * x1 * y1 + x1 * y0);
    }
    let area = 0.5 * a;
    let (cx, cy) = (sx / (6.0 * area), sy / (6.0 * area));
    Moments {
        area,
        centroid: [origin[0] + cx, origin[1] + cy],
        xx: ixx / 12.0 - area * cx * cx,
        yy: iyy / 12.0 - area * cy * cy,
        xy: ixy / 24.0 - area * cx * cy,
    }
}

/// Area (m²), centroid (m) and central second moments (m⁴) of a polygon.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Moments {
    pub area: f64,
    pub centroid: [f64; 2],
    pub xx: f64,
    pub yy: f64,
    pub xy: f64,
}

impl Moments {
    /// Real diagonal generalised masses for density ρ: (m, m, I, ρ∫x², ρ∫y², I) with m = ρA and
    /// I = ρ∫(x² + y²). Exact for a rigid block; for a simple block the couplings between spin and
    /// strain rates (ρ(∫x² − ∫y²), ρ∫xy) are lumped away, as nodal masses are lumped.
    pub fn masses(&self, density: f64) -> Dof {
        let m = density * self.area;
        let i = density * (self.xx + self.yy);
        [m, m, i, density * self.xx, density * self.yy, i]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn moments_of_a_rectangle_and_a_frame() {
        // 4 × 2 rectangle centred at (3, 1): A = 8, ∫x² = b h³/12 rotated: 2·4³/12, ∫y² = 4·2³/12.
        let ring = |v: &[[f64; 2]]| -> Vec<_> {
            (0..v.len()).map(|i| (v[i], v[(i + 1) % v.len()])).collect()
        };
        let sq = ring(&[[1.0, 0.0], [5.0, 0.0], [5.0, 2.0], [1.0, 2.0]]);
        let m = polygon_moments(sq.iter().copied());
        assert_relative_eq!(m.area, 8.0, max_relative = 1e-14);
        assert_relative_eq!(m.centroid[0], 3.0, max_relative = 1e-14);
        assert_relative_eq!(m.centroid[1], 1.0, max_relative = 1e-14);
        assert_relative_eq!(m.xx, 2.0 * 64.0 / 12.0, max_relative = 1e-13);
        assert_relative_eq!(m.yy, 4.0 * 8.0 / 12.0, max_relative = 1e-13);
        assert!(m.xy.abs() < 1e-12);
        // The same rectangle with a clockwise 2 × 1 hole at its centre.
        let hole = ring(&[[2.0, 0.5], [2.0, 1.5], [4.0, 1.5], [4.0, 0.5]]);
        let f = polygon_moments(sq.iter().chain(&hole).copied());
        assert_relative_eq!(f.area, 6.0, max_relative = 1e-14);
        assert_relative_eq!(f.xx, 2.0 * 64.0 / 12.0 - 8.0 / 12.0, max_relative = 1e-13);
    }

    #[test]
    fn velocity_map_is_rigid_for_spin() {
        let r = [0.3, -0.7];
        let t = velocity_map(r);
        // ω = 1: v = (−r_y, r_x), perpendicular to r.
        let v = [t[0][2], t[1][2]];
        assert_eq!(v, [0.7, 0.3]);
        assert!((v[0] * r[0] + v[1] * r[1]).abs() < 1e-15);
    }
}
