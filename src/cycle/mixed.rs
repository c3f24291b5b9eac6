//! Mixed discretization (`zoning.mixed`): constant-strain triangles lock as ν → 0.5, because each
//! zone must keep its own volume. Here each zone's volumetric strain increment is replaced by the
//! average over its corners of the nodes' patch averages (the average nodal pressure triangle of
//! Bonet & Burton 1998; FLAC's nodal mixed discretization, Detournay & Dzik 2006, in spirit):
//!
//!   Δε̄_v(n) = Σ_z∋n A_z Δε_v(z) / Σ_z∋n A_z,   Δε_v*(z) = ⅓ Σ_corners Δε̄_v(n),
//!   Δε*(z) = Δε(z) + ½ (Δε_v*(z) − Δε_v(z)) [1, 1, 0],
//!
//! leaving the deviatoric part of each zone's strain increment untouched.

use rayon::prelude::*;

use super::{Cycle, CycleParams, corner_forces, strain_increment, velocity_gradient};
use crate::model::Model;

impl Cycle {
    /// The zone stage with the volumetric strain averaged over node patches (see the module).
    pub fn zone_forces_mixed(&mut self, model: &mut Model, p: &CycleParams) {
        let Model {
            nodes,
            zones,
            laws,
            gather,
            mixed,
            ..
        } = model;
        let inv_patch = mixed.as_ref().expect("mixed discretization set up");
        let (vel, dt) = (&nodes.vel, p.dt);
        self.zone_strain
            .par_iter_mut()
            .zip(zones.nodes.par_iter())
            .zip(zones.grad.par_iter())
            .with_min_len(1024)
            .for_each(|((de, t), g)| {
                *de = strain_increment(&velocity_gradient(g, t.map(|n| vel[n as usize])), dt)
            });
        let (strain, area) = (&self.zone_strain, &zones.area);
        self.node_volumetric
            .par_iter_mut()
            .enumerate()
            .with_min_len(1024)
            .for_each(|(n, v)| {
                let sum: f64 = gather
                    .of(n)
                    .iter()
                    .map(|&s| {
                        let z = s as usize / 3;
                        area[z] * (strain[z][0] + strain[z][1])
                    })
                    .sum();
                *v = sum * inv_patch[n];
            });
        let node_vol = &self.node_volumetric;
        zones
            .stress
            .par_iter_mut()
            .zip(zones.state.par_iter_mut())
            .zip(zones.plastic.par_iter_mut())
            .zip(self.zone_force.par_chunks_mut(3))
            .zip(zones.nodes.par_iter())
            .zip(zones.grad.par_iter())
            .zip(zones.area.par_iter())
            .zip(zones.material.par_iter())
            .zip(self.zone_strain.par_iter())
            .with_min_len(1024)
            .for_each(
                |((((((((s, state), plastic), f), t), g), &area), mat), de)| {
                    let averaged = t.iter().map(|&n| node_vol[n as usize]).sum::<f64>() / 3.0;
                    let shift = 0.5 * (averaged - (de[0] + de[1]));
                    let de = [de[0] + shift, de[1] + shift, de[2]];
                    laws[mat.0 as usize].update(s, state, plastic, &de);
                    corner_forces(s, g, area, f);
                },
            );
    }
}
