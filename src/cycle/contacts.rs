//! The detect and contact-force stages of the cycle.

use rayon::prelude::*;

use super::{Cycle, CycleParams};
use crate::contact::detect::{Detection, Touch, detect};
use crate::contact::rounding;
use crate::joint::{FAILED, JointLaw, JointState};
use crate::model::blocks::Blocks;
use crate::model::{Contacts, Nodes};

impl Cycle {
    /// Detect stage: re-detect contacts at the current positions. Persisting contacts keep their
    /// joint state; new ones start failed (no cohesion or tensile strength) at their current gap,
    /// or at zero overlap if they turn up deeper than a tenth of the contact tolerance, their force
    /// then growing from zero as in UDEC's incremental contacts: a node found behind an edge by a
    /// changed facing (below the toe of a neighbour's corner, say) must not get the whole overlap's
    /// force in one cycle.
    pub fn detect(&mut self, d: &Detection, contacts: &mut Contacts) {
        let shallow = -0.1 * d.tolerance;
        let fresh = |t: &Touch| JointState {
            normal_displacement: if t.gap >= shallow { t.gap } else { 0.0 },
            flags: FAILED,
            ..Default::default()
        };
        *contacts = detect(d, contacts, &fresh);
        self.contact_force.resize(3 * contacts.len(), [0.0; 2]);
        self.contact_work.resize(contacts.len(), 0.0);
        self.moved = 0.0;
        self.detections += 1;
    }

    /// Contact stage: relative velocity of the node against the point ξ of the edge, projected on the
    /// edge's normal n (outward of the edge's block; for corner against corner, the unit vector
    /// between their arcs' centres) and tangent t, gives the increments
    /// Δun = v_rel·n Δt, Δus = v_rel·t Δt; the joint law returns the stresses, and the force
    /// F = −L(σn n + τ t) acts on the node while −(1 − ξ)F and −ξF act on the edge's nodes, so
    /// momentum is conserved exactly. With stiffness-proportional Rayleigh damping σn and τ take
    /// β_R times their rate over the step on top (`CycleParams::viscous_ratio`). The energy the
    /// step puts into each contact's joint (its springs, friction and viscosity), by the trapezoid
    /// of its stresses before and after over its increments, L ½[(σn⁰ + σn) Δun + (τ⁰ + τ) Δus]
    /// (J/m; the energy balance's `joint_energy`), goes to `contact_work`.
    ///
    /// With a `commit` (the implicit path's trial) each contact starts from its committed state
    /// and its increments add the relative displacement since that commit, u − u_c, to the
    /// step's: the joint law takes the whole increment from the commit, so the state does not
    /// depend on the iterations that reached it.
    pub fn contact_forces(
        &mut self,
        nodes: &Nodes,
        blocks: &Blocks,
        contacts: &mut Contacts,
        joint_laws: &[Box<dyn JointLaw>],
        p: &CycleParams,
        commit: Option<JointCommit<'_>>,
    ) {
        if let Some(c) = &commit {
            assert_eq!(
                c.state.len(),
                contacts.len(),
                "a joint commit of other contacts than the model's (not renewed at a detection)"
            );
        }
        // The contacts may have been put back to a commit's (`implicit::commit`) since the last
        // detection.
        self.contact_force.resize(3 * contacts.len(), [0.0; 2]);
        self.contact_work.resize(contacts.len(), 0.0);
        let (pos, disp, vel) = (&nodes.pos, &nodes.disp, &nodes.vel);
        let x = |n: u32| {
            let (p, u) = (pos[n as usize], disp[n as usize]);
            [p[0] + u[0], p[1] + u[1]]
        };
        let (dt, viscous) = (p.dt, p.viscous_ratio());
        contacts
            .state
            .par_iter_mut()
            .zip(self.contact_force.par_chunks_mut(3))
            .zip(self.contact_work.par_iter_mut())
            .zip(contacts.node.par_iter())
            .zip(contacts.edge.par_iter())
            .zip(contacts.xi.par_iter())
            .zip(contacts.length.par_iter())
            .zip(contacts.material.par_iter())
            .zip(contacts.corner.par_iter())
            .enumerate()
            .with_min_len(256)
            .for_each(
                |(c, ((((((((state, f), work), &i), &e), &xi), &len), &mat), &corner))| {
                    let [j, k] = blocks.edges[e as usize];
                    let n = contact_normal(blocks, &x, i, e, corner);
                    let t = [-n[1], n[0]];
                    let vr = relative(xi, [i, j, k].map(|n| vel[n as usize]));
                    let mut dn = (vr[0] * n[0] + vr[1] * n[1]) * dt;
                    let mut ds = (vr[0] * t[0] + vr[1] * t[1]) * dt;
                    if let Some(from) = &commit {
                        *state = from.state[c];
                        let since = relative(
                            xi,
                            [i, j, k].map(|n| {
                                let (u, u0) = (disp[n as usize], from.disp[n as usize]);
                                [u[0] - u0[0], u[1] - u0[1]]
                            }),
                        );
                        dn += since[0] * n[0] + since[1] * n[1];
                        ds += since[0] * t[0] + since[1] * t[1];
                    }
                    let old = (state.normal, state.shear);
                    let law = &joint_laws[mat as usize];
                    if commit.is_some() {
                        law.trial(state, dn, ds);
                    } else {
                        law.update(state, dn, ds);
                    }
                    let (mut sn, mut ss) = (state.normal, state.shear);
                    // Stiffness-proportional damping: β_R times the rate of the law's stresses, on a
                    // contact that carries load after the step (an opened one pulls nothing back).
                    if viscous > 0.0 && (sn != 0.0 || ss != 0.0) {
                        sn += viscous * (sn - old.0);
                        ss += viscous * (ss - old.1);
                    }
                    let force = [
                        -len * (sn * n[0] + ss * t[0]),
                        -len * (sn * n[1] + ss * t[1]),
                    ];
                    *work = 0.5 * len * ((old.0 + sn) * dn + (old.1 + ss) * ds);
                    f[0] = force;
                    f[1] = [-(1.0 - xi) * force[0], -(1.0 - xi) * force[1]];
                    f[2] = [-xi * force[0], -xi * force[1]];
                },
            );
    }
}

/// A contact's relative value (velocity or displacement) of its node i against the point ξ of
/// its edge (j, k): v_i − (1 − ξ) v_j − ξ v_k, from `v` = [v_i, v_j, v_k].
#[inline]
fn relative(xi: f64, [vi, vj, vk]: [[f64; 2]; 3]) -> [f64; 2] {
    [
        vi[0] - (1.0 - xi) * vj[0] - xi * vk[0],
        vi[1] - (1.0 - xi) * vj[1] - xi * vk[1],
    ]
}

/// What the contacts' joint laws take their trial from (the implicit path, `contact_forces`):
/// each contact's state at the commit and the node displacements then, m.
#[derive(Debug, Clone, Copy)]
pub struct JointCommit<'a> {
    pub state: &'a [JointState],
    pub disp: &'a [[f64; 2]],
}

/// The unit normal of contact (node `i`, edge `e`) at positions `x`: the edge's outward normal
/// (material on its left), or for corner against corner (`corner`) the unit vector from the
/// arc centre of the edge's first node to the node's (`rounding::contact_arc`).
pub(crate) fn contact_normal(
    blocks: &Blocks,
    x: &impl Fn(u32) -> [f64; 2],
    i: u32,
    e: u32,
    corner: bool,
) -> [f64; 2] {
    let [j, k] = blocks.edges[e as usize];
    if corner {
        // Corner against corner: along the line of the centres (unless they coincide, a node
        // deep in the other block, where the edge's normal stands).
        let (ci, _) = rounding::contact_arc(blocks, x, i);
        let (cj, _) = rounding::contact_arc(blocks, x, j);
        let (dx, dy) = (ci[0] - cj[0], ci[1] - cj[1]);
        let l = (dx * dx + dy * dy).sqrt();
        if l > 0.0 {
            return [dx / l, dy / l];
        }
    }
    let (pj, pk) = (x(j), x(k));
    let l = ((pk[0] - pj[0]).powi(2) + (pk[1] - pj[1]).powi(2)).sqrt();
    [(pk[1] - pj[1]) / l, -(pk[0] - pj[0]) / l]
}
