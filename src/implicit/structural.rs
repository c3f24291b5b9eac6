//! Bolts and liners in the implicit solve: their own unknowns (a cable node's displacement along
//! its bolt; a liner node's two displacements and its rotation) and their stiffness, coupled to
//! the rock's unknowns through the grout springs and the liner links. The stiffness is the
//! elastic one (the initial stiffness, as for the zones): a yielding segment or a slipping grout
//! spring converges by the iterations, the residual carrying their laws' own forces
//! (`support::Cables::forces`, `support::Liners::forces`).

use faer::sparse::Triplet;

use super::assemble::{FIXED, Terms, expanded_triplets, lower_triplets};
use crate::support::Supports;

/// The supports' unknowns: each cable node's equation number and each liner node's three (x, y,
/// rotation), `FIXED` where its bolt group or liner is not installed.
#[derive(Debug, Clone, Default)]
pub struct SupportDofs {
    pub cable: Vec<u32>,
    pub liner: Vec<[u32; 3]>,
}

impl SupportDofs {
    /// Number the installed supports' unknowns from `first`; returns them and the next number.
    pub fn of(supports: &Supports, first: usize) -> (SupportDofs, usize) {
        let mut next = first;
        let mut number = |active: bool| {
            if active {
                next += 1;
                (next - 1) as u32
            } else {
                FIXED
            }
        };
        let (c, l) = (&supports.cables, &supports.liners);
        let cable = (0..c.nodes())
            .map(|n| number(c.active[c.group[n] as usize]))
            .collect();
        let liner = (0..l.nodes())
            .map(|n| {
                let active = l.active[l.group[n] as usize];
                [(); 3].map(|_| number(active))
            })
            .collect();
        (SupportDofs { cable, liner }, next)
    }

    /// The supports' out-of-balance forces (N/m, and N·m/m for a liner's moment) of the last
    /// force stage into their rows of `rhs`.
    pub fn residual(&self, supports: &Supports, rhs: &mut [f64]) {
        for (n, &eq) in self.cable.iter().enumerate() {
            if eq != FIXED {
                rhs[eq as usize] = supports.cables.force[n];
            }
        }
        for (n, eq) in self.liner.iter().enumerate() {
            for d in 0..3 {
                if eq[d] != FIXED {
                    rhs[eq[d] as usize] = supports.liners.force[n][d];
                }
            }
        }
    }

    /// Move the supports' nodes by their part of the solution `x` (m, and rad).
    pub fn displace(&self, supports: &mut Supports, x: &[f64]) {
        for (n, &eq) in self.cable.iter().enumerate() {
            if eq != FIXED {
                supports.cables.disp[n] += x[eq as usize];
            }
        }
        for (n, eq) in self.liner.iter().enumerate() {
            for d in 0..3 {
                if eq[d] != FIXED {
                    supports.liners.disp[n][d] += x[eq[d] as usize];
                }
            }
        }
    }
}

/// The installed supports' stiffness over the unknowns (lower triangle), with `rock(n, d)` how
/// component d of rock node n moves with the unknowns (`assemble::Dofs::terms`):
/// - a cable segment of axial stiffness k = (EA/s)/L between its nodes' displacements;
/// - a grout spring of stiffness kg ℓ: K = kg ℓ c cᵀ over c = (w_h a for each host node h, −1 for
///   the cable node), a the bolt's axis and w_h the host zone's shape-function weights, the
///   linearization of F = kg ℓ (Σ w_h a·u_h − u_cable);
/// - a liner element: the Euler–Bernoulli beam's stiffness in its frame (EA/L on the axial
///   displacements; EI/L³ [[12, 6L, −12, 6L], [6L, 4L², −6L, 2L²], …] on the transverse ones and
///   the rotations; Przemieniecki §5.3), turned to x, y;
/// - a link of stiffness k between a liner node and its rock node, in x and in y.
pub fn support_stiffness(
    supports: &Supports,
    rock: &dyn Fn(u32, usize) -> Terms,
    dofs: &SupportDofs,
) -> Vec<Triplet<usize, usize, f64>> {
    let mut out = Vec::new();
    let c = &supports.cables;
    for (s, seg) in c.segment.iter().enumerate() {
        let k = c.props[c.segment_group[s] as usize].axial_stiffness / c.segment_length[s];
        let eq = seg.map(|n| dofs.cable[n as usize]);
        lower_triplets(&eq, |r, q| if r == q { k } else { -k }, &mut out);
    }
    for (n, &cable) in dofs.cable.iter().enumerate() {
        if cable == FIXED {
            continue;
        }
        let k = c.props[c.group[n] as usize].grout_stiffness * c.length[n];
        let (a, w, host) = (c.axis[n], c.weight[n], c.host[n]);
        let mut comps = [Terms::default(); 7];
        let mut v = [0.0; 7];
        for h in 0..3 {
            for d in 0..2 {
                comps[2 * h + d] = rock(host[h], d);
                v[2 * h + d] = w[h] * a[d];
            }
        }
        comps[6].push(cable, 1.0);
        v[6] = -1.0;
        expanded_triplets(&comps, |r, q| k * v[r] * v[q], &mut out);
    }
    let l = &supports.liners;
    for (e, &[a, b]) in l.element.iter().enumerate() {
        let eq_a = dofs.liner[a as usize];
        if eq_a[0] == FIXED {
            continue;
        }
        let p = &l.props[l.element_group[e] as usize];
        let k = beam_stiffness(
            p.axial_stiffness,
            p.bending_stiffness,
            l.element_length[e],
            l.element_axis[e],
        );
        let eq_b = dofs.liner[b as usize];
        let eq = [eq_a[0], eq_a[1], eq_a[2], eq_b[0], eq_b[1], eq_b[2]];
        lower_triplets(&eq, |r, q| k[r][q], &mut out);
    }
    for (link, &node) in l.link_node.iter().enumerate() {
        let liner = dofs.liner[node as usize];
        if liner[0] == FIXED {
            continue;
        }
        let k = l.link_stiffness[link];
        for (d, &eq) in liner.iter().enumerate().take(2) {
            let mut own = Terms::default();
            own.push(eq, 1.0);
            let comps = [rock(l.link_rock[link], d), own];
            expanded_triplets(&comps, |i, j| if i == j { k } else { -k }, &mut out);
        }
    }
    out
}

/// Stiffness of a plane Euler–Bernoulli beam element over (u_a, v_a, θ_a, u_b, v_b, θ_b) in x, y
/// (N/m per m; N per m against rotations; N·m per m between rotations): axial stiffness `ea`
/// (EA/s, N), bending stiffness `ei` (EI/s, N·m²), length `len` (m), unit axis `axis`;
/// K = Tᵀ K_local T with T taking (u, v) to (along the axis, along the normal n = axis rotated
/// +90°).
pub fn beam_stiffness(ea: f64, ei: f64, len: f64, axis: [f64; 2]) -> [[f64; 6]; 6] {
    let (l, l2, l3) = (len, len * len, len * len * len);
    let (x, b) = (ea / l, ei / l3);
    #[rustfmt::skip]
    let local = [
        [x, 0.0, 0.0, -x, 0.0, 0.0],
        [0.0, 12.0 * b, 6.0 * l * b, 0.0, -12.0 * b, 6.0 * l * b],
        [0.0, 6.0 * l * b, 4.0 * l2 * b, 0.0, -6.0 * l * b, 2.0 * l2 * b],
        [-x, 0.0, 0.0, x, 0.0, 0.0],
        [0.0, -12.0 * b, -6.0 * l * b, 0.0, 12.0 * b, -6.0 * l * b],
        [0.0, 6.0 * l * b, 2.0 * l2 * b, 0.0, -6.0 * l * b, 4.0 * l2 * b],
    ];
    let nrm = [-axis[1], axis[0]];
    // t[i][j]: local component i from global component j.
    let mut t = [[0.0; 6]; 6];
    for o in [0, 3] {
        t[o][o] = axis[0];
        t[o][o + 1] = axis[1];
        t[o + 1][o] = nrm[0];
        t[o + 1][o + 1] = nrm[1];
        t[o + 2][o + 2] = 1.0;
    }
    let mut k = [[0.0; 6]; 6];
    for r in 0..6 {
        for c in 0..6 {
            k[r][c] = (0..6)
                .flat_map(|i| (0..6).map(move |j| (i, j)))
                .map(|(i, j)| t[i][r] * local[i][j] * t[j][c])
                .sum();
        }
    }
    k
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::support::liner::tests::liner_on;

    /// The beam matrix is the linearization of the liner's own element forces: for any
    /// displacement d of a slanted element's two nodes, K d = −F(d) (the element is linear in
    /// total form and starts unstressed).
    #[test]
    fn the_beam_matrix_is_the_liner_forces_linearized() {
        let rock = [[0.3, -0.2], [1.1, 0.4]];
        let mut l = liner_on(&[[0, 1]], &rock);
        l.install(0, &[[0.0; 2]; 2]);
        let d = [[1e-3, -2e-3, 3e-3], [-0.5e-3, 1.5e-3, -1e-3]];
        l.disp = d.to_vec();
        let mut slots = vec![[0.0; 2]; l.link_node.len()];
        // Rock displaced as the liner is: the links carry nothing.
        let rock_disp = [[d[0][0], d[0][1]], [d[1][0], d[1][1]]];
        l.forces(&rock_disp, &mut slots);
        let p = l.props[0];
        let k = beam_stiffness(
            p.axial_stiffness,
            p.bending_stiffness,
            l.element_length[0],
            l.element_axis[0],
        );
        let flat = [d[0][0], d[0][1], d[0][2], d[1][0], d[1][1], d[1][2]];
        for (r, row) in k.iter().enumerate() {
            let kd: f64 = row.iter().zip(&flat).map(|(a, b)| a * b).sum();
            let f = l.force[r / 3][r % 3];
            assert!((kd + f).abs() <= 1e-9 * kd.abs().max(1.0), "{r}: {kd} {f}");
        }
    }
}
