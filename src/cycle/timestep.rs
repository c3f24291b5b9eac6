//! Time step and nodal masses from the stiffness of the zones (Gershgorin bound).
//!
//! For central differences the step is stable when ω_max·Δt ≤ 2. By Gershgorin's theorem
//! ω_max² ≤ max_i R_i / m_i, where R_i is the absolute row sum of the assembled stiffness at
//! node i (the larger of its x and y rows) and m_i its lumped mass. Dynamic runs use real lumped
//! masses (ρA/3 per corner) and Δt = s · 2/√(max R_i/m_i) with safety factor s; static runs scale
//! masses instead (m_i = R_i/(4 s²), Δt = 1), as FLAC's mass scaling for static solutions
//! (Itasca, FLAC *Theory and Background*, §1.3.5; Cundall 1982).

use crate::model::{Model, NodeId, Zones};

/// What the step derivation found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepLimit {
    /// Critical step with real masses, s.
    pub dt_critical: f64,
    /// Node whose stiffness-to-mass ratio sets the critical step.
    pub limiting_node: NodeId,
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

/// Gershgorin stiffness bound R_i per node (zones and contacts), N/m.
pub fn nodal_stiffness(model: &Model) -> Vec<f64> {
    let Zones {
        nodes,
        grad,
        area,
        material,
        ..
    } = &model.zones;
    let mut r = vec![[0.0f64; 2]; model.nodes.len()];
    for z in 0..nodes.len() {
        let (k, g) = model.laws[material[z].0 as usize].moduli();
        let sums = zone_row_sums(&grad[z], area[z], k + 4.0 / 3.0 * g, k - 2.0 / 3.0 * g, g);
        for (c, &n) in nodes[z].iter().enumerate() {
            r[n as usize][0] += sums[c][0];
            r[n as usize][1] += sums[c][1];
        }
    }
    let mut r: Vec<f64> = r.into_iter().map(|[x, y]| x.max(y)).collect();
    add_contact_stiffness(model, &mut r);
    r
}

/// Contact springs stiffen the boundary nodes. A node's contact (length ≤ half its tributary
/// length L) couples it to two edge nodes with stiffness at most (kn + ks)·L/2 per direction, and
/// as an edge node it meets at most a few such contacts; 4 L (kn + ks) per boundary node bounds
/// both roles, for contacts present now and any that form later, so the step stays stable
/// however the blocks move.
fn add_contact_stiffness(model: &Model, r: &mut [f64]) {
    if model.blocks.len() < 2 {
        return;
    }
    let k = model
        .joint_laws
        .iter()
        .map(|l| l.stiffness())
        .map(|(kn, ks)| kn + ks)
        .fold(0.0, f64::max);
    let blocks = &model.blocks;
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
        r[n] += 4.0 * trib * k;
    }
}

/// Real lumped masses, kg/m: ρ A / 3 to each corner.
pub fn lumped_masses(model: &Model) -> Vec<f64> {
    let mut m = vec![0.0; model.nodes.len()];
    let z = &model.zones;
    for i in 0..z.len() {
        let w = model.laws[z.material[i].0 as usize].density() * z.area[i] / 3.0;
        for &n in &z.nodes[i] {
            m[n as usize] += w;
        }
    }
    m
}

/// The critical time step with real masses and the node that sets it.
pub fn critical_step(stiffness: &[f64], masses: &[f64]) -> StepLimit {
    let (node, ratio) = stiffness
        .iter()
        .zip(masses)
        .map(|(r, m)| r / m)
        .enumerate()
        .fold(
            (0, 0.0f64),
            |best, (i, w2)| if w2 > best.1 { (i, w2) } else { best },
        );
    StepLimit {
        dt_critical: 2.0 / ratio.sqrt(),
        limiting_node: NodeId(node as u32),
    }
}

/// Masses for a static (mass-scaled) run with Δt = 1: m_i = R_i / (4 s²).
pub fn scaled_masses(stiffness: &[f64], safety: f64) -> Vec<f64> {
    stiffness
        .iter()
        .map(|r| r / (4.0 * safety * safety))
        .collect()
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
