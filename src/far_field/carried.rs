//! The net load a far field carries. K (`interface_stiffness_chains`) is the response to tractions
//! of no net force (∫ t dΓ = 0, a translation costing the infinite medium nothing), so a near field
//! whose own loads do not balance, an excavation under gravity (its weight removed) above all,
//! would leave the difference to its fixities, pinning the model there. The far field carries it
//! instead, exactly for a linear medium: with the net external load N (N/m) on the near field,
//! the medium's field of a line force N at a point P inside the near field (Kelvin's, Melan's or
//! Lekhnitskii's) exerts σ_N·ν on the interface (ν out of the near field; ∫ σ_N·ν dΓ = −N) and
//! moves it by u_N; what is left of the interface's traction has no net force, and K answers for
//! it from the displacement less u_N (uniqueness of the exterior problem: u_N's translation, the
//! logarithm's arbitrary reference, costs K nothing). So the far field pushes interface node a by
//! F⁰_a + F^N_a − Σ_b K_ab (u_b − u⁰_b − u^N_b), F^N_a = ∫ N_a σ_N·ν dΓ, the hats N_a integrated
//! by Gauss–Legendre on pieces a third of P's distance long.

use super::elements::{GAUSS, distance_to_segment};
use super::{FarField, Kernel};

/// Most pieces an interface edge is split into for the net load's nodal forces.
const MOST_PIECES: usize = 64;

impl FarField {
    /// Carry the net external load `net` (N/m) on the near field as the medium's field of a line
    /// force `net` at `at` (m, inside the near field): sets the nodal loads F^N and
    /// displacements u^N (module doc); a zero `net` clears them.
    pub fn carry(&mut self, net: [f64; 2], at: [f64; 2]) {
        let n = self.nodes.len();
        self.carried = vec![[0.0; 2]; n];
        self.carried_disp = vec![[0.0; 2]; n];
        if net == [0.0; 2] {
            return;
        }
        let m = &self.medium;
        for (u, &x) in self.carried_disp.iter_mut().zip(&self.positions) {
            let g = m.displacement_at(x, at);
            *u = std::array::from_fn(|j| net[0] * g[0][j] + net[1] * g[1][j]);
        }
        for &[a, b] in &self.edges {
            let (pa, pb) = (self.positions[a], self.positions[b]);
            let d = [pb[0] - pa[0], pb[1] - pa[1]];
            let len = d[0].hypot(d[1]);
            // The material is on the edge's left: the medium's normal (out of the far field)
            // points left, ν = −n to the right.
            let n_medium = [-d[1] / len, d[0] / len];
            let distance = distance_to_segment(at, pa, pb).max(1e-12 * len);
            let pieces = ((3.0 * len / distance).ceil() as usize).clamp(1, MOST_PIECES);
            for p in 0..pieces {
                for &(g, w) in &GAUSS {
                    let t = (p as f64 + 0.5 * (1.0 + g)) / pieces as f64;
                    let x = [pa[0] + t * d[0], pa[1] + t * d[1]];
                    let tr = m.traction_at(x, at, n_medium);
                    // σ_N·ν = −σ_N·n_medium on the near field.
                    let on = std::array::from_fn::<f64, 2, _>(|j| {
                        -(net[0] * tr[0][j] + net[1] * tr[1][j])
                    });
                    let weight = 0.5 * w * len / pieces as f64;
                    for (node, hat) in [(a, 1.0 - t), (b, t)] {
                        for (c, o) in self.carried[node].iter_mut().zip(on) {
                            *c += weight * hat * o;
                        }
                    }
                }
            }
        }
    }
}
