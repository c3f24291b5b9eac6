//! Body stage: rigid and simple blocks gather their nodes' forces (contacts and boundary loads,
//! summed by the motion stage) into generalised forces, integrate their few DOFs by central
//! differences with the same local damping as nodes, and move their nodes.

use rayon::prelude::*;

use super::{Cycle, CycleParams, mass_damping_factors};
use crate::damping::local_damping;
use crate::law::{StrainIncrement, ZoneLaw};
use crate::model::bodies::{Bodies, BodyMode, DOFS, NO_BODY, apply, velocity_map};
use crate::model::{Nodes, Stress};

/// σ' = R σ Rᵀ for an in-plane rotation by `angle` (rad): the stress of a simple block turns with it.
pub(super) fn rotate(s: &mut Stress, angle: f64) {
    if angle == 0.0 {
        return;
    }
    let (sn, cs) = angle.sin_cos();
    let (xx, yy, xy) = (s[0], s[1], s[3]);
    s[0] = cs * cs * xx - 2.0 * cs * sn * xy + sn * sn * yy;
    s[1] = sn * sn * xx + 2.0 * cs * sn * xy + cs * cs * yy;
    s[3] = cs * sn * (xx - yy) + (cs * cs - sn * sn) * xy;
}

/// What one body is and carries, read by its force and its step.
struct BodyView<'a> {
    mode: BodyMode,
    range: [u32; 2],
    weight: [f64; 2],
    mass: &'a [f64; DOFS],
    projector: &'a Option<crate::model::bodies::Gram>,
}

/// A body's generalised out-of-balance force: Q = Σ T_iᵀ f_i over its nodes' gathered forces
/// (`nodes.force`, N/m; offsets from its centroid `c`, m), plus its weight, minus
/// A(σxx, σyy, 2σxy) on a simple block's strain DOFs (`area` A in m², σ in Pa with the viscous
/// stress `sv`), zero beyond its mode's DOFs; for a constrained body the part its constraint does
/// not react to, q ← M P M⁻¹ q.
fn generalised_force(
    b: &BodyView,
    nodes: &Nodes,
    c: [f64; 2],
    s: &Stress,
    sv: &Stress,
    area: f64,
) -> [f64; DOFS] {
    let (pos, disp) = (&nodes.pos, &nodes.disp);
    let mut q = [0.0; DOFS];
    for n in b.range[0] as usize..b.range[1] as usize {
        let f = nodes.force[n];
        let r = [pos[n][0] + disp[n][0] - c[0], pos[n][1] + disp[n][1] - c[1]];
        let t = velocity_map(r);
        for d in 0..DOFS {
            q[d] += t[0][d] * f[0] + t[1][d] * f[1];
        }
    }
    q[0] += b.weight[0];
    q[1] += b.weight[1];
    if b.mode == BodyMode::Simple {
        q[3] -= area * (s[0] + sv[0]);
        q[4] -= area * (s[1] + sv[1]);
        q[5] -= 2.0 * area * (s[3] + sv[3]);
    }
    let dofs = b.mode.dofs();
    q[dofs..].fill(0.0);
    // A constrained body keeps the force its constraint does not react to.
    if let Some(p) = b.projector {
        let m = b.mass;
        let a = apply(
            p,
            &std::array::from_fn(|d| if d < dofs { q[d] / m[d] } else { 0.0 }),
        );
        q = std::array::from_fn(|d| if d < dofs { a[d] * m[d] } else { 0.0 });
    }
    q
}

/// A body's state that its step changes.
struct BodyState<'a> {
    centroid: &'a mut [f64; 2],
    stress: &'a mut Stress,
    state: &'a mut u8,
    plastic: &'a mut f64,
    area: &'a mut f64,
    viscous: &'a mut Stress,
}

/// Move a body by its generalised velocity `v` over `dt` (s): the centroid by v_c Δt, the offsets
/// by the exact rotation by ωΔt (rigid) or I + LΔt (simple, whose stress takes the strain
/// increment through its zone `law`, β_R σ̇ into its viscous stress when `viscous` > 0, and
/// turns by ωΔt). Returns (old centroid, new centroid, map r_new = A r_old).
fn body_step(
    simple: bool,
    v: &[f64; DOFS],
    dt: f64,
    b: BodyState,
    law: &dyn ZoneLaw,
    viscous: f64,
) -> ([f64; 2], [f64; 2], [f64; 4]) {
    let c = b.centroid;
    let old = *c;
    *c = [c[0] + v[0] * dt, c[1] + v[1] * dt];
    let spin = v[2] * dt;
    let map = if simple {
        let (exx, eyy, exy) = (v[3] * dt, v[4] * dt, v[5] * dt);
        let de: StrainIncrement = [exx, eyy, 2.0 * exy];
        let s = b.stress;
        let before = *s;
        law.update(s, b.state, b.plastic, &de);
        if viscous > 0.0 {
            // β_R σ̇ over this step, acting with the stress in the next one.
            *b.viscous = std::array::from_fn(|i| viscous * (s[i] - before[i]));
        }
        rotate(s, spin);
        let a = [1.0 + exx, exy - spin, exy + spin, 1.0 + eyy];
        *b.area *= a[0] * a[3] - a[1] * a[2];
        a
    } else {
        let (sn, cs) = spin.sin_cos();
        [cs, -sn, sn, cs]
    };
    (old, *c, map)
}

/// Where a point at `x` (m) goes in a body's step (old centroid, new centroid, map), m.
fn follow(step: &([f64; 2], [f64; 2], [f64; 4]), x: [f64; 2]) -> [f64; 2] {
    let (c0, c1, a) = step;
    let r = [x[0] - c0[0], x[1] - c0[1]];
    [
        c1[0] + a[0] * r[0] + a[1] * r[1],
        c1[1] + a[2] * r[0] + a[3] * r[1],
    ]
}

impl Cycle {
    /// Body stage: the generalised force Q of each body (`generalised_force`); local damping
    /// Q_d = Q − α|Q| sign(q̇) per DOF; q̇ ← q̇ + Q_d Δt / M (mass-proportional damping as nodes),
    /// kept in what a constraint allows; then the body's step (`body_step`). Nodes then take the
    /// chord velocity (x_new − x)/Δt. Returns the largest body-node speed, m/s.
    pub fn body_motion(
        &mut self,
        nodes: &mut Nodes,
        bodies: &mut Bodies,
        laws: &[Box<dyn ZoneLaw>],
        p: &CycleParams,
    ) -> f64 {
        if bodies.is_empty() {
            return 0.0;
        }
        let (alpha, dt, viscous) = (p.damping, p.dt, p.viscous_ratio());
        let (keep, gain) = mass_damping_factors(p);
        let read: &Nodes = nodes;
        let (mode, range, mass, weight, material, projector) = (
            &bodies.mode,
            &bodies.nodes,
            &bodies.mass,
            &bodies.weight,
            &bodies.material,
            &bodies.projector,
        );
        bodies
            .velocity
            .par_iter_mut()
            .zip(bodies.force.par_iter_mut())
            .zip(bodies.centroid.par_iter_mut())
            .zip(bodies.stress.par_iter_mut())
            .zip(bodies.state.par_iter_mut())
            .zip(bodies.plastic.par_iter_mut())
            .zip(bodies.area.par_iter_mut())
            .zip(bodies.step.par_iter_mut())
            .zip(self.body_viscous.par_iter_mut())
            .enumerate()
            .with_min_len(64)
            .for_each(
                |(k, ((((((((v, q_out), c), s), state), plastic), area), step), sv))| {
                    let b = BodyView {
                        mode: mode[k],
                        range: range[k],
                        weight: weight[k],
                        mass: &mass[k],
                        projector: &projector[k],
                    };
                    let q = generalised_force(&b, read, *c, s, sv, *area);
                    let m = &mass[k];
                    for d in 0..mode[k].dofs() {
                        let damped = local_damping(q[d], v[d], alpha);
                        v[d] = keep * v[d] + gain * damped / m[d] * dt;
                    }
                    if let Some(p) = &projector[k] {
                        *v = apply(p, v);
                    }
                    *q_out = q;
                    let moved = BodyState {
                        centroid: c,
                        stress: s,
                        state,
                        plastic,
                        area,
                        viscous: sv,
                    };
                    let law = laws[material[k].0 as usize].as_ref();
                    *step = body_step(mode[k] == BodyMode::Simple, v, dt, moved, law, viscous);
                },
            );
        let step = &bodies.step;
        nodes
            .vel
            .par_iter_mut()
            .zip(nodes.disp.par_iter_mut())
            .zip(nodes.force.par_iter_mut())
            .zip(nodes.pos.par_iter())
            .zip(bodies.of_node.par_iter())
            .with_min_len(1024)
            .map(|((((vel, u), f), p), &b)| {
                if b == NO_BODY {
                    return 0.0;
                }
                let x = [p[0] + u[0], p[1] + u[1]];
                let new = follow(&step[b as usize], x);
                *vel = [(new[0] - x[0]) / dt, (new[1] - x[1]) / dt];
                *u = [new[0] - p[0], new[1] - p[1]];
                // A body node's force is part of its body's; the unbalanced force is the body's.
                *f = [0.0; 2];
                vel[0] * vel[0] + vel[1] * vel[1]
            })
            .reduce(|| 0.0, f64::max)
            .sqrt()
    }

    /// The bodies' out-of-balance forces for the implicit path: each body's generalised force Q
    /// from its nodes' gathered forces `nodes.force` into `bodies.force`, its nodes' forces then
    /// zeroed (the unbalanced force is the body's), as the body stage leaves them.
    pub fn body_balance(&self, nodes: &mut Nodes, bodies: &mut Bodies) {
        for k in 0..bodies.len() {
            let b = BodyView {
                mode: bodies.mode[k],
                range: bodies.nodes[k],
                weight: bodies.weight[k],
                mass: &bodies.mass[k],
                projector: &bodies.projector[k],
            };
            bodies.force[k] = generalised_force(
                &b,
                nodes,
                bodies.centroid[k],
                &bodies.stress[k],
                &self.body_viscous[k],
                bodies.area[k],
            );
        }
        for (f, &b) in nodes.force.iter_mut().zip(&bodies.of_node) {
            if b != NO_BODY {
                *f = [0.0; 2];
            }
        }
    }

    /// Move each body by its generalised displacement `dq` (m, rad, strain) in one step of its
    /// law (`body_step` with a unit step), writing into `du` the displacement of each of its
    /// nodes (m): the implicit path's update, before the node stages move the nodes by `du`.
    pub fn body_displace(
        &mut self,
        nodes: &Nodes,
        bodies: &mut Bodies,
        laws: &[Box<dyn ZoneLaw>],
        dq: &[[f64; DOFS]],
        du: &mut [[f64; 2]],
    ) {
        for k in 0..bodies.len() {
            let moved = BodyState {
                centroid: &mut bodies.centroid[k],
                stress: &mut bodies.stress[k],
                state: &mut bodies.state[k],
                plastic: &mut bodies.plastic[k],
                area: &mut bodies.area[k],
                viscous: &mut self.body_viscous[k],
            };
            let law = laws[bodies.material[k].0 as usize].as_ref();
            let simple = bodies.mode[k] == BodyMode::Simple;
            bodies.step[k] = body_step(simple, &dq[k], 1.0, moved, law, 0.0);
        }
        for (n, &b) in bodies.of_node.iter().enumerate() {
            if b != NO_BODY {
                let (p, u) = (nodes.pos[n], nodes.disp[n]);
                let x = [p[0] + u[0], p[1] + u[1]];
                let new = follow(&bodies.step[b as usize], x);
                du[n] = [new[0] - x[0], new[1] - x[1]];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_keeps_the_invariants_and_turns_the_axes() {
        let mut s = [-3.0, -1.0, -0.5, 0.4];
        let (tr, det) = (s[0] + s[1], s[0] * s[1] - s[3] * s[3]);
        rotate(&mut s, 0.7);
        assert!((s[0] + s[1] - tr).abs() < 1e-14);
        assert!((s[0] * s[1] - s[3] * s[3] - det).abs() < 1e-13);
        // A uniaxial σxx turned by 90° becomes σyy.
        let mut u = [-2.0, 0.0, 0.0, 0.0];
        rotate(&mut u, std::f64::consts::FRAC_PI_2);
        assert!(u[0].abs() < 1e-15 && (u[1] + 2.0).abs() < 1e-15 && u[3].abs() < 1e-15);
    }
}
