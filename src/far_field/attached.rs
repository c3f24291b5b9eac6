//! A far field attached to a model: its stiffness on the interface's nodes, the in-situ stress
//! it carries there, and where the interface was when it was attached.

use rayon::prelude::*;

use super::InterfaceStiffness;

/// The far field of a model (`region.far_field`): the force it exerts on interface node i is
/// f_i = F⁰_i + F^N_i − Σ_j K_ij (u_j − u⁰_j − u^N_j), F⁰ the in-situ stress's traction on the
/// interface as nodal loads and u⁰ the displacements when it was attached, so a model at rest
/// in its in-situ stress stays at rest and only what is excavated moves the far field; F^N and
/// u^N carry the near field's net load, if any (`carried`).
#[derive(Debug, Clone)]
pub struct FarField {
    /// The interface's nodes (model node ids), in K's order.
    pub nodes: Vec<u32>,
    pub stiffness: InterfaceStiffness,
    /// F⁰, N/m per node.
    pub in_situ: Vec<[f64; 2]>,
    /// u⁰, m per node.
    pub attached: Vec<[f64; 2]>,
    /// Seconds the stiffness took to assemble and condense.
    pub assemble_s: f64,
    /// How many times faster the far-field rock's field varies along the interface than an
    /// isotropic rock's (`Kernel::stretch`; 1 for intact rock).
    pub stretch: f64,
    /// The far-field rock, whose line-force field carries the near field's net load (`carry`).
    pub medium: super::Medium,
    /// The interface nodes' places, m, and its edges (indices into `nodes`, the near field on
    /// their left), along which the net load's traction becomes nodal loads.
    pub positions: Vec<[f64; 2]>,
    pub edges: Vec<[usize; 2]>,
    /// F^N, N/m per node, and u^N, m per node: the net load carried (`carry`; zero without one).
    pub carried: Vec<[f64; 2]>,
    pub carried_disp: Vec<[f64; 2]>,
}

impl FarField {
    /// The forces (N/m) on the interface's nodes for the model's displacements `disp` (m), into
    /// `out` (one per interface node); `moved` is scratch of the same length.
    pub fn forces(&self, disp: &[[f64; 2]], moved: &mut [[f64; 2]], out: &mut [[f64; 2]]) {
        let moving = (self.nodes.iter()).zip(self.attached.iter().zip(&self.carried_disp));
        for (m, (&n, (a, c))) in moved.iter_mut().zip(moving) {
            let u = disp[n as usize];
            *m = [u[0] - a[0] - c[0], u[1] - a[1] - c[1]];
        }
        let (k, moved) = (&self.stiffness, &*moved);
        out.par_iter_mut()
            .zip(self.in_situ.par_iter().zip(self.carried.par_iter()))
            .enumerate()
            .with_min_len(16)
            .for_each(|(i, (f, (f0, c)))| {
                *f = [
                    f0[0] + c[0] - k.row_times(i, 0, moved),
                    f0[1] + c[1] - k.row_times(i, 1, moved),
                ];
            });
    }

    /// The largest absolute row sum of K over each interface node's two rows, N/m per m: the
    /// node's share of the far field's stiffness for the time step (Gershgorin).
    pub fn row_sums(&self) -> Vec<f64> {
        let n2 = 2 * self.nodes.len();
        (0..self.nodes.len())
            .map(|i| {
                (0..2)
                    .map(|d| {
                        let row = &self.stiffness.k[(2 * i + d) * n2..(2 * i + d + 1) * n2];
                        row.iter().map(|v| v.abs()).sum::<f64>()
                    })
                    .fold(0.0, f64::max)
            })
            .collect()
    }
}
