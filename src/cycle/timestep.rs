//! Time step and nodal masses from the stiffness of the zones (Gershgorin bound).
//!
//! For central differences the step is stable when ω_max·Δt ≤ 2. By Gershgorin's theorem
//! ω_max² ≤ max_i R_i / m_i, where R_i is the absolute row sum of the assembled stiffness at
//! node i (the larger of its x and y rows) and m_i its lumped mass. Dynamic runs use real lumped
//! masses (ρA/3 per corner) and Δt = s · 2/√(max R_i/m_i) with safety factor s; static runs scale
//! masses instead (m_i = R_i/(4 s²), Δt = 1), as FLAC's mass scaling for static solutions
//! (Itasca, FLAC *Theory and Background*, §1.3.5; Cundall 1982).

use crate::law::plane_strain_moduli;
use crate::model::bodies::{BodyMode, DOFS, Dof, Moments, polygon_moments, velocity_map};
use crate::model::{Model, NodeId, Zones};

/// What the step derivation found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepLimit {
    /// Critical step with real masses, s.
    pub dt_critical: f64,
    /// Node whose stiffness-to-mass ratio sets the critical step (the first node of the limiting
    /// block when a rigid or simple block sets it).
    pub(crate) limiting_node: NodeId,
    /// The rigid or simple block that sets the critical step, if one does.
    pub(crate) limiting_block: Option<u32>,
    /// What stiffness dominates at the limit.
    pub(crate) by: Limiter,
}

/// The stiffness that sets the critical step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Limiter {
    /// The zones at the limiting node (their size and modulus).
    #[default]
    Zones,
    /// The contact springs at the limiting node (joint stiffness over its edge length).
    Contacts,
    /// A bolt or liner (its own nodes, or its springs at the limiting node).
    Supports,
    /// A rigid or simple block.
    Block,
}

impl StepLimit {
    /// What set the step, for reports: `zones at node 12`, `contacts at node 40`, `block 3`, ….
    pub fn describe(&self) -> String {
        match self.by {
            Limiter::Zones => format!("zones at node {}", self.limiting_node.0),
            Limiter::Contacts => format!("contacts at node {}", self.limiting_node.0),
            Limiter::Supports => "supports".to_string(),
            Limiter::Block => format!("block {}", self.limiting_block.unwrap_or(0)),
        }
    }
}

/// Element stiffness K = A Bᵀ D B of a plane-strain CST with moduli α1 = K + 4G/3, α2 = K − 2G/3, G;
/// returns the absolute row sums for the x and y rows of each corner, N/m.
fn zone_row_sums(grad: &[f64; 6], area: f64, a1: f64, a2: f64, g: f64) -> [[f64; 2]; 3] {
    // B columns for corner i: x dof → (bx, 0, by), y dof → (0, by, bx).
    let col = |i: usize, d: usize| -> [f64; 3] {
        let (bx, by) = (grad[i], grad[3 + i]);
        if d == 0 { [bx, 0.0, by] } else { [0.0, by, bx] }
    };
    let db = |c: [f64; 3]| [a1 * c[0] + a2 * c[1], a2 * c[0] + a1 * c[1], g * c[2]];
    std::array::from_fn(|i| {
        std::array::from_fn(|d| {
            let di = db(col(i, d));
            (0..3)
                .flat_map(|j| [col(j, 0), col(j, 1)])
                .map(|cj| (area * (di[0] * cj[0] + di[1] * cj[1] + di[2] * cj[2])).abs())
                .sum()
        })
    })
}

/// Gershgorin stiffness bound R_i per node from the zones alone, N/m.
pub fn zone_stiffness(model: &Model) -> Vec<f64> {
    let Zones {
        nodes,
        grad,
        area,
        material,
        ..
    } = &model.zones;
    let mut r = vec![[0.0f64; 2]; model.nodes.len()];
    for z in 0..nodes.len() {
        let (k, g) = model.materials.zone[material[z].0 as usize].moduli();
        let (a1, a2) = plane_strain_moduli(k, g);
        let sums = zone_row_sums(&grad[z], area[z], a1, a2, g);
        for (c, &n) in nodes[z].iter().enumerate() {
            r[n as usize][0] += sums[c][0];
            r[n as usize][1] += sums[c][1];
        }
    }
    r.into_iter().map(|[x, y]| x.max(y)).collect()
}

/// Contact springs stiffen the boundary nodes. A node's contact (length ≤ half its tributary
/// length L) couples it to two edge nodes with stiffness at most (kn + ks)·L/2 per direction, and
/// as an edge node it usually meets a few such contacts: 4 L (kn + ks) per boundary node bounds
/// both roles for contacts that form later. Where more contacts crowd a node than that allows (the
/// tip of a sliver wedge touches the blocks on both of its sides, and edges of several blocks),
/// the exact row sums of the contacts present are taken instead: a contact of length Lc with
/// weights w = (1, −(1 − ξ), −ξ) on its node and edge nodes adds to node a's row at most
/// |w_a| Σ|w| Lc (kn + ks) (1 + √2)/2 = (1 + √2) |w_a| Lc (kn + ks) (the largest row of
/// n nᵀ + t tᵀ-weighted springs over all normals n).
pub(crate) fn add_contact_stiffness(model: &Model, r: &mut [f64]) {
    if model.blocks.len() < 2 {
        return;
    }
    let k = model
        .materials
        .joint
        .iter()
        .map(|l| l.stiffness())
        .map(|(kn, ks)| kn + ks)
        .fold(0.0, f64::max);
    let blocks = &model.blocks;
    let mut present = vec![0.0f64; r.len()];
    let c = &model.contacts;
    for i in 0..c.len() {
        let (kn, ks) = model.materials.joint[c.material[i] as usize].stiffness();
        let spring = (1.0 + std::f64::consts::SQRT_2) * c.length[i] * (kn + ks);
        let [a, b] = blocks.edges[c.edge[i] as usize];
        present[c.node[i] as usize] += spring;
        present[a as usize] += (1.0 - c.xi[i]).abs() * spring;
        present[b as usize] += c.xi[i].abs() * spring;
    }
    for (n, edges) in blocks.node_edges.iter().enumerate() {
        let trib: f64 = edges
            .iter()
            .filter(|&&e| e != crate::model::blocks::NO_EDGE)
            .map(|&e| {
                let [a, b] = blocks.edges[e as usize];
                let (p, q) = (model.nodes.pos[a as usize], model.nodes.pos[b as usize]);
                0.5 * (q[0] - p[0]).hypot(q[1] - p[1])
            })
            .sum();
        r[n] += (4.0 * trib * k).max(present[n]);
    }
}

/// Real lumped masses, kg/m: ρ A / 3 to each corner.
pub fn lumped_masses(model: &Model) -> Vec<f64> {
    let mut m = vec![0.0; model.nodes.len()];
    let z = &model.zones;
    for i in 0..z.len() {
        let w = model.materials.zone[z.material[i].0 as usize].density() * z.area[i] / 3.0;
        for &n in &z.nodes[i] {
            m[n as usize] += w;
        }
    }
    m
}

/// The critical time step with real masses and the node that sets it (nodes without mass, those of
/// rigid and simple blocks, are left to `body_step`).
pub fn critical_step(stiffness: &[f64], masses: &[f64]) -> StepLimit {
    let (node, ratio) = stiffness
        .iter()
        .zip(masses)
        .map(|(r, m)| if *m > 0.0 { r / m } else { 0.0 })
        .enumerate()
        .fold(
            (0, 0.0f64),
            |best, (i, w2)| if w2 > best.1 { (i, w2) } else { best },
        );
    StepLimit {
        dt_critical: 2.0 / ratio.sqrt(),
        limiting_node: NodeId(node as u32),
        limiting_block: None,
        by: Limiter::Zones,
    }
}

/// Current area, centroid and second moments of body k's block.
pub fn body_moments(model: &Model, k: usize) -> Moments {
    let (blocks, nodes) = (&model.blocks, &model.nodes);
    let x = |n: u32| {
        let (p, u) = (nodes.pos[n as usize], nodes.disp[n as usize]);
        [p[0] + u[0], p[1] + u[1]]
    };
    let b = model.bodies.block[k] as usize;
    polygon_moments(blocks.edge_range(b).map(|e| {
        let [a, c] = blocks.edges[e];
        (x(a), x(c))
    }))
}

/// Stiffness bounds D (one per DOF) of each body: the body's DOFs drive its nodes through
/// v_i = T_i q̇, so the reduced stiffness is at most S = Σ_i R_i T_iᵀT_i (R_i the node's Gershgorin
/// bound), plus A·[[K+4G/3, K−2G/3, 0], [K−2G/3, K+4G/3, 0], [0, 0, 4G]] on a simple block's strain
/// rates. With |T| bounded entrywise by |r_i| and weights w = (1, 1, 1/ℓ, …) (ℓ the block's radius),
/// D_k = Σ_l |S_kl| w_l / w_k ≥ S in the PSD sense (weighted Gershgorin), so ω² ≤ max_k D_k/M_k
/// for a diagonal mass M.
pub fn body_stiffness(model: &Model, nodal: &[f64]) -> Vec<Dof> {
    let bodies = &model.bodies;
    (0..bodies.len())
        .map(|k| {
            let ell = bodies.radius[k];
            let c = bodies.centroid[k];
            let mut s = [[0.0f64; DOFS]; DOFS];
            let range = bodies.nodes[k][0] as usize..bodies.nodes[k][1] as usize;
            for (n, &r_n) in range.clone().zip(&nodal[range]) {
                let (p, u) = (model.nodes.pos[n], model.nodes.disp[n]);
                let rho = (p[0] + u[0] - c[0]).hypot(p[1] + u[1] - c[1]);
                let t = velocity_map([rho, rho]).map(|row| row.map(f64::abs));
                for a in 0..DOFS {
                    for b in 0..DOFS {
                        s[a][b] += r_n * (t[0][a] * t[0][b] + t[1][a] * t[1][b]);
                    }
                }
            }
            let dofs = bodies.mode[k].dofs();
            if bodies.mode[k] == BodyMode::Simple {
                let (kb, g) = model.materials.zone[bodies.material[k].0 as usize].moduli();
                let (a1, a2, area) = (kb + 4.0 / 3.0 * g, kb - 2.0 / 3.0 * g, bodies.area[k]);
                s[3][3] += area * a1;
                s[4][4] += area * a1;
                s[3][4] += area * a2;
                s[4][3] += area * a2;
                s[5][5] += area * 4.0 * g;
            }
            let w = |d: usize| if d < 2 { 1.0 } else { 1.0 / ell };
            std::array::from_fn(|a| {
                if a >= dofs {
                    return 0.0;
                }
                (0..dofs).map(|b| s[a][b].abs() * w(b) / w(a)).sum()
            })
        })
        .collect()
}

/// Real diagonal generalised masses of each body (its density over its current polygon).
pub fn body_masses(model: &Model) -> Vec<Dof> {
    (0..model.bodies.len())
        .map(|k| {
            let rho = model.materials.zone[model.bodies.material[k].0 as usize].density();
            body_moments(model, k).masses(rho)
        })
        .collect()
}

/// Tighten `limit` by the bodies: Δt_crit = 2/√(max_k D_k/M_k) over each body's DOFs.
pub fn body_step(model: &Model, stiffness: &[Dof], masses: &[Dof], limit: &mut StepLimit) {
    for k in 0..model.bodies.len() {
        let dofs = model.bodies.mode[k].dofs();
        let w2 = (0..dofs)
            .map(|d| stiffness[k][d] / masses[k][d])
            .fold(0.0, f64::max);
        let dt = 2.0 / w2.sqrt();
        if dt < limit.dt_critical {
            *limit = StepLimit {
                dt_critical: dt,
                limiting_node: NodeId(model.bodies.nodes[k][0]),
                limiting_block: Some(model.bodies.block[k]),
                by: Limiter::Block,
            };
        }
    }
}

/// Masses for a static (mass-scaled) run with Δt = 1 and local damping α:
/// m_i = μ R_i / (4 s²), μ = `damped_margin(s, α)`.
pub fn scaled_masses(stiffness: &[f64], safety: f64, alpha: f64) -> Vec<f64> {
    let scale = damped_margin(safety, alpha) / (4.0 * safety * safety);
    stiffness.iter().map(|r| r * scale).collect()
}

/// Mass margin μ = max(1, (1 + α) s²) that keeps a mass-scaled, locally damped solve stable.
///
/// Local damping pushes a node with F − α|F| sign(v): up to (1 + α)|F| while the node moves against
/// its force, so the scheme steps an effective stiffness (1 + α)K. Central differences stay stable
/// when (1 + α) λmax(M⁻¹K) Δt² ≤ 4; Gershgorin gives λmax ≤ max R_i/m_i = 4s²/μ, hence
/// μ ≥ (1 + α) s². Meshes of well-shaped zones never reach their Gershgorin bound and did without
/// it; a node whose stiffness sits in one spring (a joint contact between two blocks, a sliver
/// zone) does reach it, and with α = 0.8, s = 0.8 the run diverged there (the sliver case of
/// `validation/src/slivers.rs`). The price is √μ = 1.07× more cycles at the defaults.
pub fn damped_margin(safety: f64, alpha: f64) -> f64 {
    ((1.0 + alpha) * safety * safety).max(1.0)
}

/// Factor √(1 + ξ²) − ξ on the critical step with stiffness-proportional damping β_R (s), where
/// ξ = β_R ω_max / 2 is the damping of the fastest mode, ω_max = 2 / Δt_crit; 1 without.
///
/// The viscous stress β_R σ̇ is taken over the step the stress stage has just made, so a mode
/// steps v ← v − Δt (ω² x + 2ξω v), x ← x + Δt v: the spectral radius of that map stays ≤ 1
/// exactly while ω Δt ≤ 2 (√(1 + ξ²) − ξ) (the bound of Belytschko, Liu & Moran, *Nonlinear
/// Finite Elements for Continua and Structures*, ch. 6, for damping lagged by half a step).
pub fn viscous_margin(beta: f64, dt_critical: f64) -> f64 {
    let xi = beta / dt_critical;
    (1.0 + xi * xi).sqrt() - xi
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::zones::cst_gradients;

    #[test]
    fn row_sums_bound_the_rigid_free_stiffness() {
        // Rigid-body translation is in the null space: each row of K sums (with signs) to zero,
        // so the absolute row sum is at least twice the diagonal.
        let (g, a) = cst_gradients([[0.0, 0.0], [1.0, 0.1], [0.2, 0.9]]);
        let s = zone_row_sums(&g, a, 3.0, 1.0, 1.0);
        let diag_x0 = a * (3.0 * g[0] * g[0] + 1.0 * g[3] * g[3]);
        assert!(s[0][0] >= 2.0 * diag_x0 - 1e-12);
    }
}
