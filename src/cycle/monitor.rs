//! Monitor stage: unbalanced-force ratio, kinetic energy, and the checks that stop a run that has
//! gone wrong (NaN, runaway displacement) with the node or zone named.

use rayon::prelude::*;

use super::Cycle;
use crate::model::Model;

/// A node stepping this fraction of its shortest zone edge in one cycle, `UNSTABLE_GROWTH` times
/// its step of the cycle before, stops the run: a static solve moves nodes by a tiny fraction of
/// that per cycle, a dynamic one by |v|Δt ≪ h (the step is below the time a wave takes across a
/// zone), and a scheme past its stability limit multiplies the step by about (ωΔt)² every cycle,
/// so it passes both within a few cycles. A block falling freely (a mechanism, not an
/// instability) speeds up by less than that per cycle and is left to the cycle limit.
pub const UNSTABLE_JUMP: f64 = 0.1;
/// See `UNSTABLE_JUMP`.
pub const UNSTABLE_GROWTH: f64 = 4.0;

/// Chunk length of the deterministic reductions (independent of the thread count).
const CHUNK: usize = 4096;

/// Figures of one monitor step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Monitor {
    /// max_i |F_i| / mean_i Σ|f_i|: largest unbalanced nodal force over the mean gross nodal force
    /// (sum of magnitudes of the zone and applied forces meeting at a node), as FLAC's ratio; 1
    /// (nothing balanced) where an unbalanced force meets no gross force at all (an unstressed
    /// model loaded only through its supports), 0 where there is neither.
    pub ratio: f64,
    /// Kinetic energy ½ Σ m v², J/m (with the scaled masses in static runs).
    pub kinetic: f64,
    /// Largest unbalanced force, N/m.
    pub(crate) max_force: f64,
}

impl Cycle {
    /// Measure the state after a cycle; an error names the first node or zone that is not finite
    /// or has run away.
    pub fn monitor(&self, model: &Model) -> Result<Monitor, String> {
        let nodes = &model.nodes;
        let n = nodes.len();
        let partial: Vec<(f64, f64, f64)> = (0..n.div_ceil(CHUNK))
            .into_par_iter()
            .map(|c| {
                let (mut max_f, mut gross, mut ke) = (0.0f64, 0.0, 0.0);
                for i in c * CHUNK..((c + 1) * CHUNK).min(n) {
                    let f = nodes.force[i];
                    max_f = max_f.max((f[0] * f[0] + f[1] * f[1]).sqrt());
                    let a = nodes.applied[i];
                    gross += (a[0] * a[0] + a[1] * a[1]).sqrt();
                    for &s in model.gather.of(i) {
                        let z = self.zone_force[s as usize];
                        gross += (z[0] * z[0] + z[1] * z[1]).sqrt();
                    }
                    for &s in model.contacts.gather.of(i) {
                        let c = self.contact_force[s as usize];
                        gross += (c[0] * c[0] + c[1] * c[1]).sqrt();
                    }
                    for &s in model.support_gather.of(i) {
                        let c = self.support_force[s as usize];
                        gross += (c[0] * c[0] + c[1] * c[1]).sqrt();
                    }
                    for &s in model.far_gather.of(i) {
                        let c = self.far_force[s as usize];
                        gross += (c[0] * c[0] + c[1] * c[1]).sqrt();
                    }
                    let v = nodes.vel[i];
                    ke += 0.5 * nodes.mass[i] * (v[0] * v[0] + v[1] * v[1]);
                }
                (max_f, gross, ke)
            })
            .collect();
        let (mut max_force, mut gross, mut kinetic) = (0.0f64, 0.0, 0.0);
        for (m, g, k) in partial {
            max_force = max_force.max(m);
            gross += g;
            kinetic += k;
        }
        // Rigid and simple blocks: their unbalanced force, moments and strain forces over their
        // radius, their weight as gross force, ½ Σ M q̇² as kinetic energy.
        let b = &model.bodies;
        for k in 0..b.len() {
            let (q, l) = (b.force[k], b.radius[k]);
            let turning = q[2..].iter().fold(0.0f64, |m, x| m.max(x.abs() / l));
            max_force = max_force.max(q[0].hypot(q[1]).max(turning));
            gross += b.weight[k][0].hypot(b.weight[k][1]);
            let (v, m) = (b.velocity[k], b.mass[k]);
            kinetic += (0..b.mode[k].dofs())
                .map(|d| 0.5 * m[d] * v[d] * v[d])
                .sum::<f64>();
        }
        let (support_force, support_kinetic) = model.supports.monitor();
        max_force = max_force.max(support_force);
        kinetic += support_kinetic;
        if !(max_force.is_finite() && kinetic.is_finite()) {
            return Err(self.first_bad(model));
        }
        let limit = 0.5 * model.size;
        if let Some(i) = nodes
            .disp
            .iter()
            .position(|u| u[0].abs() > limit || u[1].abs() > limit)
        {
            let p = nodes.pos[i];
            return Err(format!(
                "runaway displacement: node {i} at ({:.4}, {:.4}) moved more than half the model size ({limit:.3} m)",
                p[0], p[1]
            ));
        }
        if let Some(reason) = interpenetration(model) {
            return Err(reason);
        }
        let mean = gross / n as f64;
        let ratio = if mean > 0.0 {
            max_force / mean
        } else if max_force > 0.0 {
            1.0
        } else {
            0.0
        };
        Ok(Monitor {
            ratio,
            kinetic,
            max_force,
        })
    }

    /// Whether the last cycle's step was unstable (`jump` past `UNSTABLE_JUMP` and `UNSTABLE_GROWTH`
    /// times the cycle before's), and then why, naming the node.
    pub fn unstable_step(&self, model: &Model, dt: f64) -> Option<String> {
        let unstable = self.jump > UNSTABLE_JUMP && self.jump > UNSTABLE_GROWTH * self.last_jump;
        unstable.then(|| self.unstable(model, dt))
    }

    /// The reason for an unstable step (`jump` past `UNSTABLE_JUMP`), naming the node
    /// that made it (the first of the largest).
    fn unstable(&self, model: &Model, dt: f64) -> String {
        let step = |n: usize| {
            let v = model.nodes.vel[n];
            v[0].hypot(v[1]) * dt * self.inv_size[n]
        };
        let n =
            (0..model.nodes.len()).fold(0, |best, n| if step(n) > step(best) { n } else { best });
        let ratio = step(n);
        let (p, h) = (model.nodes.pos[n], 1.0 / self.inv_size[n]);
        format!(
            "unstable: node {n} at ({:.4}, {:.4}) moved {:.3e} m in one cycle, {:.2} of its \
             shortest zone edge ({h:.3e} m): the time step is past the stability limit, or a \
             stiffness is missing from its derivation",
            p[0],
            p[1],
            ratio * h,
            ratio
        )
    }

    fn first_bad(&self, model: &Model) -> String {
        let bodies = &model.bodies;
        if let Some(k) = (0..bodies.len()).find(|&k| {
            bodies.velocity[k]
                .iter()
                .chain(&bodies.force[k])
                .any(|v| !v.is_finite())
        }) {
            let c = bodies.centroid[k];
            return format!(
                "non-finite velocity or force of {} block {} at ({:.4}, {:.4})",
                bodies.mode[k].label(),
                bodies.block[k],
                c[0],
                c[1]
            );
        }
        let contacts = &model.contacts;
        if let Some(c) = contacts
            .state
            .iter()
            .position(|s| !(s.normal.is_finite() && s.shear.is_finite()))
        {
            return format!(
                "non-finite joint stress at contact {c} (node {})",
                contacts.node[c]
            );
        }
        if let Some(z) = model
            .zones
            .stress
            .iter()
            .position(|s| s.iter().any(|v| !v.is_finite()))
        {
            let c = model.zones.centroid(z, &model.nodes.pos);
            return format!(
                "non-finite stress in zone {z} at ({:.4}, {:.4})",
                c[0], c[1]
            );
        }
        let (cables, liners) = (&model.supports.cables, &model.supports.liners);
        if let Some(n) = (0..cables.nodes())
            .find(|&n| !(cables.vel[n].is_finite() && cables.force[n].is_finite()))
        {
            let p = cables.pos[n];
            return format!(
                "non-finite velocity or force of cable node {n} of bolt group '{}' at ({:.4}, {:.4})",
                cables.names[cables.group[n] as usize], p[0], p[1]
            );
        }
        if let Some(n) = (0..liners.nodes()).find(|&n| {
            liners.vel[n]
                .iter()
                .chain(&liners.force[n])
                .any(|v| !v.is_finite())
        }) {
            let p = liners.pos[n];
            return format!(
                "non-finite velocity or force of liner node {n} of '{}' at ({:.4}, {:.4})",
                liners.names[liners.group[n] as usize], p[0], p[1]
            );
        }
        let n = model
            .nodes
            .vel
            .iter()
            .position(|v| !(v[0].is_finite() && v[1].is_finite()))
            .unwrap_or(0);
        let p = model.nodes.pos[n];
        format!(
            "non-finite velocity or force at node {n} at ({:.4}, {:.4})",
            p[0], p[1]
        )
    }
}

/// The first contact whose overlap exceeds the joint length it stands for or the contact tolerance,
/// whichever is larger (the node has gone through the opposite block; a vertex between two very
/// short edges stands for a tiny length but may press in as deep as a contact can start),
/// named with its node and block.
fn interpenetration(model: &Model) -> Option<String> {
    let c = &model.contacts;
    let tolerance = model.contact_tolerance;
    (0..c.len()).find(|&k| -c.state[k].normal_displacement > c.length[k].max(tolerance)).map(|k| {
        let p = model.nodes.pos[c.node[k] as usize];
        format!(
            "interpenetration at contact {k}: node {} (block {}, at ({:.4}, {:.4})) is {:.3e} m inside block {}, \
             beyond the {:.3e} m limit; stiffer joints or smaller loads are needed",
            c.node[k],
            model.blocks.block_of_node(c.node[k]),
            p[0],
            p[1],
            -c.state[k].normal_displacement,
            c.block[k],
            c.length[k].max(tolerance)
        )
    })
}
