//! Large-strain zone stage (`solve.large_strain`): each zone's gradients come from its shape at
//! the middle of the step, x = X + u − v Δt/2 (the velocity v moved it there from the last
//! position), and its stress first turns with the zone's spin, then takes the strain increment
//! through its law — an objective update (Hughes & Winget 1980): a zone turning as a rigid body
//! takes no strain at all on its mid-step shape and keeps its stress in its own frame. The
//! corner forces then act on the shape at the end of the step:
//!
//!   ω = ½(∂v_y/∂x − ∂v_x/∂y),   σ ← R(ωΔt) σ R(ωΔt)ᵀ,   Δε = sym(∇v) Δt
//!
//! (Itasca, FLAC *Theory and Background*, §1.3.3 "large-strain mode"; Belytschko, Liu & Moran,
//! *Nonlinear Finite Elements*, §5.4). Small-strain zones keep their original shape: a rigid
//! rotation θ then reads as a strain of order 1 − cos θ.

use rayon::prelude::*;

use super::bodies::rotate;
use super::{Cycle, CycleParams, corner_forces, strain_increment, velocity_gradient, with_viscous};
use crate::law::ZoneLaw;
use crate::model::zones::cst_gradients;
use crate::model::{Nodes, Zones};

impl Cycle {
    /// The zone stage on the zones' current shapes (see the module).
    pub(super) fn zone_forces_large(
        &mut self,
        nodes: &Nodes,
        zones: &mut Zones,
        laws: &[Box<dyn ZoneLaw>],
        p: &CycleParams,
    ) {
        let (vel, pos, disp) = (&nodes.vel, &nodes.pos, &nodes.disp);
        let (dt, viscous) = (p.dt, p.viscous_ratio());
        zones
            .stress
            .par_iter_mut()
            .zip(zones.state.par_iter_mut())
            .zip(zones.plastic.par_iter_mut())
            .zip(self.zone_force.par_chunks_mut(3))
            .zip(zones.nodes.par_iter())
            .zip(zones.material.par_iter())
            .with_min_len(1024)
            .for_each(|(((((s, state), plastic), f), t), mat)| {
                let v = t.map(|n| vel[n as usize]);
                let x: [[f64; 2]; 3] = std::array::from_fn(|k| {
                    let n = t[k] as usize;
                    [pos[n][0] + disp[n][0], pos[n][1] + disp[n][1]]
                });
                let mid = std::array::from_fn(|k| {
                    [x[k][0] - 0.5 * v[k][0] * dt, x[k][1] - 0.5 * v[k][1] * dt]
                });
                let (g, _) = cst_gradients(mid);
                let l = velocity_gradient(&g, v);
                rotate(s, 0.5 * (l[1][0] - l[0][1]) * dt);
                let turned = *s;
                let de = strain_increment(&l, dt);
                laws[mat.0 as usize].update(s, state, plastic, &de);
                // Forces act on the shape at the end of the step; the viscous stress is the rate
                // of the law's stress in the zone's frame (its spin is no strain rate).
                let (g, area) = cst_gradients(x);
                corner_forces(&with_viscous(s, &turned, viscous), &g, area, f);
            });
    }
}
