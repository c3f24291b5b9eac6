//! Mixed discretization (`zoning.mixed`): constant-strain triangles lock as ν → 0.5, because each
//! zone must keep its own volume. Here most of each zone's volumetric strain increment is replaced
//! by the average over its corners of the nodes' patch averages (the average nodal pressure
//! triangle of Bonet & Burton 1998; FLAC's nodal mixed discretization, Detournay & Dzik 2006, in
//! spirit):
//!
//!   Δε̄_v(n) = Σ_z∋n A_z Δε_v(z) / Σ_z∋n A_z,
//!   Δε_v*(z) = (1 − β) ⅓ Σ_corners Δε̄_v(n) + β Δε_v(z),   β = min(1, c G / K),
//!   Δε*(z) = Δε(z) + ½ (Δε_v*(z) − Δε_v(z)) [1, 1, 0],
//!
//! leaving the deviatoric part of each zone's strain increment untouched.
//!
//! The share β of the zone's own volumetric strain is a stabilization in the manner of Puso &
//! Solberg (2006, IJNME 67:841): it resists a zone's volume change away from its patches' average
//! with a modulus K β = c G (`VOLUMETRIC_STABILIZATION` = c), tied to the shear modulus and not to
//! K, so nothing locks as K/G → ∞ (ν = 0.499: β = 0.004). Without it, volume changes that
//! alternate from zone to zone and cancel in every patch cost no volumetric energy at all; once a
//! zone yields they cost no shear energy either, and plastic zones flowed in them: Salençon's hole
//! (c = 1 MPa, φ = 25°, ν = 0.3, p0 = 15 MPa) closed 18 % too much at local damping 0.8, and more
//! as the mesh was refined. With c = 2 it closes −5.2 % on the shipped mesh and within 0.5 % on
//! one twice as fine, at 0.8 as at 0.95 (docs/validation.md, Salençon sweep).
//!
//! The law then returns the zone to its yield surface. A plastic correction that changes the mean
//! stress (dilation, the tension cut-off) is averaged the same way, so that it does not undo the
//! averaging: with Δp_z the change of the zone's mean stress beyond the elastic K Δε_v*(z),
//!
//!   Δp̄(n) = Σ_z∋n A_z Δp_z / Σ_z∋n A_z,   σ(z) += (1 − β)(⅓ Σ_corners Δp̄(n) − Δp_z) I,
//!
//! so the pressure stays the patch average of K (ε_v − ε_v^p) in the share 1 − β. Left local, a
//! dilating zone's pressure rose in itself alone while the volume it needed came from its
//! neighbours, and runs ran away (Salençon's hole with ψ = 5° within 17 000 cycles, ψ = φ = 30°
//! within 500).
//!
//! That shift moves the zone's stress off its yield surface; a cycle's next return brings it back.
//! The implicit path's trial is taken once per iteration from the commit with the step's whole
//! strain (`CycleParams::trial`), so a shift added after the return would stay, and the answer
//! would hold zones beyond their strength. There each trial adds the shift of the iteration
//! before to its predictor instead, and keeps the return's stress: at convergence the shift is
//! the one that return produces, and every zone lies on or within its surface. Added after the
//! return, a dilatant hole (ν = 0.4, ψ = 10°: `tests/engine/implicit.rs`) closed 27 % less than
//! explicitly released slowly, and an explicit stage after it closed it 40 % further; lagged,
//! +0.55 %, and the explicit stage after it is at rest.

use rayon::prelude::*;

use super::{
    Cycle, CycleParams, advance, corner_forces, strain_increment, velocity_gradient, with_viscous,
};
use crate::law::ZoneLaw;
use crate::model::{Gather, Nodes, Zones};

/// c of the mixed discretization's stabilization: a zone's own volumetric strain is resisted with
/// a modulus min(K, c G) (see the module). Of 0.5, 1, 2 and 4 tried, 2 is the smallest that kept
/// the mixed closure of the Salençon sweep's rocks within a point of plain zones' on every mesh;
/// ν = 0.499 stays unlocked.
pub const VOLUMETRIC_STABILIZATION: f64 = 2.0;

/// β = min(1, c G / K) of `law`: the share of a zone's own volumetric strain it keeps (1 for a law
/// without stiffness, an excavated zone).
fn own_share(law: &dyn ZoneLaw) -> f64 {
    let (bulk, shear) = law.moduli();
    if bulk > 0.0 {
        (VOLUMETRIC_STABILIZATION * shear / bulk).min(1.0)
    } else {
        1.0
    }
}

impl Cycle {
    /// The zone stage with the volumetric strain averaged over node patches (see the module).
    pub(super) fn zone_forces_mixed(
        &mut self,
        nodes: &Nodes,
        zones: &mut Zones,
        laws: &[Box<dyn ZoneLaw>],
        gather: &Gather,
        inv_patch: &[f64],
        p: &CycleParams,
    ) {
        let (vel, dt, viscous, trial) = (&nodes.vel, p.dt, p.viscous_ratio(), p.trial);
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
            .zip(self.zone_stress_start.par_iter_mut())
            .zip(self.zone_pressure_lag.par_iter())
            .with_min_len(1024)
            .for_each(
                |((((((((s, state), plastic), t), mat), de), dp), start), &lag)| {
                    if viscous > 0.0 {
                        *start = *s;
                    }
                    if trial {
                        shift_mean(s, lag);
                    }
                    let law = &laws[mat.0 as usize];
                    let own = de[0] + de[1];
                    let beta = own_share(law.as_ref());
                    let patches = t.iter().map(|&n| node_vol[n as usize]).sum::<f64>() / 3.0;
                    let averaged = (1.0 - beta) * patches + beta * own;
                    let shift = 0.5 * (averaged - own);
                    let de = [de[0] + shift, de[1] + shift, de[2]];
                    let before = mean_stress(s);
                    advance(law.as_ref(), trial, s, state, plastic, &de);
                    *dp = mean_stress(s) - before - law.moduli().0 * averaged;
                },
            );
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
            .zip(zones.material.par_iter())
            .zip(self.zone_stress_start.par_iter())
            .zip(self.zone_pressure_lag.par_iter_mut())
            .with_min_len(1024)
            .for_each(|((((((((s, f), t), g), &area), &dp), mat), start), lag)| {
                let smoothed = t.iter().map(|&n| node_plastic[n as usize]).sum::<f64>() / 3.0;
                let shift = (1.0 - own_share(laws[mat.0 as usize].as_ref())) * (smoothed - dp);
                if trial {
                    *lag = shift;
                } else {
                    shift_mean(s, shift);
                }
                corner_forces(&with_viscous(s, start, viscous), g, area, f);
            });
    }

    /// The implicit path's zones have committed (or gone back to their commit): the plastic
    /// mean-stress shifts of the step's last trial, which the next trial would start from, are
    /// forgotten (the step's plastic strain starts from zero).
    pub(crate) fn zones_committed(&mut self) {
        self.zone_pressure_lag.iter_mut().for_each(|l| *l = 0.0);
    }
}

/// Add `shift` (Pa) to the normal stresses of `s`, moving its mean stress by as much.
#[inline]
fn shift_mean(s: &mut crate::model::Stress, shift: f64) {
    if shift != 0.0 {
        s[0] += shift;
        s[1] += shift;
        s[2] += shift;
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
