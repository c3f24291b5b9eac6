//! Mixed discretization (`zoning.mixed`): constant-strain triangles lock as ν → 0.5, because each
//! zone must keep its own volume. Here each zone's volumetric strain increment is replaced by the
//! average over its corners of the nodes' patch averages (the average nodal pressure triangle of
//! Bonet & Burton 1998; FLAC's nodal mixed discretization, Detournay & Dzik 2006, in spirit):
//!
//!   Δε̄_v(n) = Σ_z∋n A_z Δε_v(z) / Σ_z∋n A_z,   Δε_v*(z) = ⅓ Σ_corners Δε̄_v(n),
//!   Δε*(z) = Δε(z) + ½ (Δε_v*(z) − Δε_v(z)) [1, 1, 0],
//!
//! leaving the deviatoric part of each zone's strain increment untouched.
//!
//! The law then returns the zone to its yield surface. A plastic correction that changes the mean
//! stress (the tension cut-off; dilation, which `zoning.mixed` refuses for now) is averaged the
//! same way, so that it does not undo the averaging: with Δp_z the change of the zone's mean
//! stress beyond the elastic K Δε_v*(z),
//!
//!   Δp̄(n) = Σ_z∋n A_z Δp_z / Σ_z∋n A_z,   σ(z) += (⅓ Σ_corners Δp̄(n) − Δp_z) I,
//!
//! so the pressure stays the patch average of K (ε_v − ε_v^p). Left local, a dilating zone's
//! pressure rose in itself alone while the volume it needed came from its neighbours, and runs ran
//! away (Salençon's hole with ψ = 5° within 17 000 cycles, ψ = φ = 30° within 500).

use rayon::prelude::*;

use super::{Cycle, CycleParams, corner_forces, strain_increment, velocity_gradient};
use crate::model::{Gather, Model};

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
        patch_average(&mut self.node_volumetric, gather, area, inv_patch, |z| {
            strain[z][0] + strain[z][1]
        });
        let node_vol = &self.node_volumetric;
        zones
            .stress
            .par_iter_mut()
            .zip(zones.state.par_iter_mut())
            .zip(zones.plastic.par_iter_mut())
            .zip(zones.nodes.par_iter())
            .zip(zones.material.par_iter())
            .zip(self.zone_strain.par_iter())
            .zip(self.zone_plastic_mean.par_iter_mut())
            .with_min_len(1024)
            .for_each(|((((((s, state), plastic), t), mat), de), dp)| {
                let law = &laws[mat.0 as usize];
                let averaged = t.iter().map(|&n| node_vol[n as usize]).sum::<f64>() / 3.0;
                let shift = 0.5 * (averaged - (de[0] + de[1]));
                let de = [de[0] + shift, de[1] + shift, de[2]];
                let before = mean_stress(s);
                law.update(s, state, plastic, &de);
                *dp = mean_stress(s) - before - law.moduli().0 * averaged;
            });
        let zone_plastic = &self.zone_plastic_mean;
        patch_average(&mut self.node_volumetric, gather, area, inv_patch, |z| {
            zone_plastic[z]
        });
        let node_plastic = &self.node_volumetric;
        zones
            .stress
            .par_iter_mut()
            .zip(self.zone_force.par_chunks_mut(3))
            .zip(zones.nodes.par_iter())
            .zip(zones.grad.par_iter())
            .zip(zones.area.par_iter())
            .zip(zone_plastic.par_iter())
            .with_min_len(1024)
            .for_each(|(((((s, f), t), g), &area), &dp)| {
                let smoothed = t.iter().map(|&n| node_plastic[n as usize]).sum::<f64>() / 3.0;
                let shift = smoothed - dp;
                if shift != 0.0 {
                    s[0] += shift;
                    s[1] += shift;
                    s[2] += shift;
                }
                corner_forces(s, g, area, f);
            });
    }
}

/// The area-weighted average over each node's patch of a zone quantity, Σ_z∋n A_z q_z / Σ_z∋n A_z,
/// into `out` (one per node; `inv_patch` is 1 / Σ_z∋n A_z).
fn patch_average(
    out: &mut [f64],
    gather: &Gather,
    area: &[f64],
    inv_patch: &[f64],
    q: impl Fn(usize) -> f64 + Sync,
) {
    out.par_iter_mut()
        .enumerate()
        .with_min_len(1024)
        .for_each(|(n, v)| {
            let sum: f64 = gather
                .of(n)
                .iter()
                .map(|&s| {
                    let z = s as usize / 3;
                    area[z] * q(z)
                })
                .sum();
            *v = sum * inv_patch[n];
        });
}

/// Mean stress (σxx + σyy + σzz)/3 of a zone, Pa.
#[inline]
fn mean_stress(s: &crate::model::Stress) -> f64 {
    (s[0] + s[1] + s[2]) / 3.0
}
