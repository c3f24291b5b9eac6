//! Rigid and simple blocks in the implicit solve. A body's nodes follow its generalised
//! displacement q (translation, rotation, and for a simple block a uniform strain: u_i = T_i q,
//! `model::bodies::velocity_map`), so its unknowns are q's components in what its boundary
//! conditions allow: the columns N of an orthonormal basis of the null space of its constraint
//! Gram matrix G (all of q for a free body), q = N a. A node's row of the contact, liner-link or
//! grout stiffness then acts on a through T_i N; a simple block adds its own stiffness
//! A Sᵀ D S over its strain components (S = diag(1, 1, 2): the shear component is ε̇xy, the
//! stress work 2σxy), the linearization of its generalised force −A(σxx, σyy, 2σxy). Its residual
//! is Nᵀ Q, the generalised out-of-balance force the explicit body stage computes, in which a
//! constraint's reaction has no part.

use faer::sparse::Triplet;

use super::assemble::{Terms, plane_strain};
use crate::law::ZoneLaw;
use crate::model::Nodes;
use crate::model::bodies::{Bodies, BodyMode, DOFS, Dof, NO_BODY, allowed_motions, velocity_map};

/// The bodies' unknowns.
#[derive(Debug, Clone, Default)]
pub struct BodyDofs {
    /// Each body's first equation number and how many it has (0: held still).
    pub first: Vec<u32>,
    pub count: Vec<u8>,
    /// Each body's allowed motions N, column j as `basis[k][j]`.
    pub basis: Vec<[Dof; DOFS]>,
}

impl BodyDofs {
    /// Number the bodies' unknowns from `first`; returns them and the next number.
    pub fn of(bodies: &Bodies, first: usize) -> (BodyDofs, usize) {
        let mut out = BodyDofs::default();
        let mut next = first;
        for k in 0..bodies.len() {
            let dofs = bodies.mode[k].dofs();
            let unit = |j: usize| std::array::from_fn(|i| if i == j { 1.0 } else { 0.0 });
            let cols = allowed_motions(&bodies.constraint[k], dofs)
                .unwrap_or_else(|| (0..dofs).map(unit).collect());
            let mut basis = [[0.0; DOFS]; DOFS];
            basis[..cols.len()].copy_from_slice(&cols);
            out.first.push(next as u32);
            out.count.push(cols.len() as u8);
            out.basis.push(basis);
            next += cols.len();
        }
        (out, next)
    }

    /// The bodies' out-of-balance forces `bodies.force` (N/m, N·m/m) into their rows of `rhs`:
    /// Nᵀ Q.
    pub fn residual(&self, bodies: &Bodies, rhs: &mut [f64]) {
        for k in 0..self.first.len() {
            for j in 0..self.count[k] as usize {
                let col = &self.basis[k][j];
                rhs[self.first[k] as usize + j] =
                    (0..DOFS).map(|d| col[d] * bodies.force[k][d]).sum();
            }
        }
    }

    /// Each body's generalised displacement q = N a from its part of the solution `x`.
    pub fn expand(&self, x: &[f64], dq: &mut [Dof]) {
        for (k, q) in dq.iter_mut().enumerate() {
            *q = [0.0; DOFS];
            for j in 0..self.count[k] as usize {
                let a = x[self.first[k] as usize + j];
                for (qd, nd) in q.iter_mut().zip(&self.basis[k][j]) {
                    *qd += a * nd;
                }
            }
        }
    }

    /// How component `d` of a node of body `k` at offset `r` (m) from its centroid moves with
    /// the body's unknowns: (T(r) N)[d].
    pub fn node_terms(&self, k: usize, r: [f64; 2], d: usize) -> Terms {
        let t = velocity_map(r);
        let mut out = Terms::default();
        for j in 0..self.count[k] as usize {
            let c: f64 = (0..DOFS).map(|m| t[d][m] * self.basis[k][j][m]).sum();
            out.push(self.first[k] + j as u32, c);
        }
        out
    }

    /// The simple blocks' own stiffness over their unknowns (lower triangle): Nᵀ (A Sᵀ D S) N
    /// over the strain components, D the plane-strain elasticity of their law's moduli.
    pub fn stiffness(
        &self,
        bodies: &Bodies,
        laws: &[Box<dyn ZoneLaw>],
    ) -> Vec<Triplet<usize, usize, f64>> {
        let mut out = Vec::new();
        for k in 0..bodies.len() {
            if bodies.mode[k] != BodyMode::Simple || self.count[k] == 0 {
                continue;
            }
            let (bulk, shear) = laws[bodies.material[k].0 as usize].moduli();
            let d = plane_strain(bulk, shear);
            let scale = [1.0, 1.0, 2.0];
            let own = |a: usize, b: usize| -> f64 {
                if a < 3 || b < 3 {
                    0.0
                } else {
                    bodies.area[k] * scale[a - 3] * d[a - 3][b - 3] * scale[b - 3]
                }
            };
            let n = self.count[k] as usize;
            for i in 0..n {
                for j in 0..=i {
                    let (ci, cj) = (&self.basis[k][i], &self.basis[k][j]);
                    let v: f64 = (0..DOFS)
                        .flat_map(|a| (0..DOFS).map(move |b| (a, b)))
                        .map(|(a, b)| ci[a] * own(a, b) * cj[b])
                        .sum();
                    if v != 0.0 {
                        let (row, col) = (self.first[k] as usize + i, self.first[k] as usize + j);
                        out.push(Triplet::new(row, col, v));
                    }
                }
            }
        }
        out
    }
}

/// The displacement of each body node (m) to first order in the bodies' generalised
/// displacements `dq`: T_i q, at the current positions (into `du`; other nodes untouched).
pub fn node_motion(bodies: &Bodies, nodes: &Nodes, dq: &[Dof], du: &mut [[f64; 2]]) {
    for (n, &k) in bodies.of_node.iter().enumerate() {
        if k == NO_BODY {
            continue;
        }
        let (p, u, c) = (nodes.pos[n], nodes.disp[n], bodies.centroid[k as usize]);
        let t = velocity_map([p[0] + u[0] - c[0], p[1] + u[1] - c[1]]);
        let q = &dq[k as usize];
        du[n] = std::array::from_fn(|d| (0..DOFS).map(|m| t[d][m] * q[m]).sum());
    }
}
