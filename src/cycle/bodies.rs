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

impl Cycle {
    /// Body stage: Q = Σ T_iᵀ f_i + weight − A(σxx, σyy, 2σxy) (with the viscous stress of
    /// stiffness-proportional damping, `Cycle::body_viscous`, added to σ); local damping
    /// Q_d = Q − α|Q| sign(q̇) per DOF; q̇ ← q̇ + Q_d Δt / M (mass-proportional damping as nodes); the centroid moves by v_c Δt and the
    /// offsets map as r ← A r, with A the exact rotation by ωΔt for a rigid block and I + LΔt for a
    /// simple one, whose stress takes the strain increment through its zone law and turns by ωΔt.
    /// Nodes then take the chord velocity (x_new − x)/Δt. Returns the largest body-node speed, m/s.
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
        let (pos, disp, force) = (&nodes.pos, &nodes.disp, &nodes.force);
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
                    let mut q = [0.0; DOFS];
                    for n in range[k][0] as usize..range[k][1] as usize {
                        let f = force[n];
                        let r = [pos[n][0] + disp[n][0] - c[0], pos[n][1] + disp[n][1] - c[1]];
                        let t = velocity_map(r);
                        for d in 0..DOFS {
                            q[d] += t[0][d] * f[0] + t[1][d] * f[1];
                        }
                    }
                    q[0] += weight[k][0];
                    q[1] += weight[k][1];
                    let simple = mode[k] == BodyMode::Simple;
                    if simple {
                        q[3] -= *area * (s[0] + sv[0]);
                        q[4] -= *area * (s[1] + sv[1]);
                        q[5] -= 2.0 * *area * (s[3] + sv[3]);
                    }
                    let dofs = mode[k].dofs();
                    q[dofs..].fill(0.0);
                    // A constrained body keeps the force its constraint does not react to:
                    // q ← M P M⁻¹ q, and its velocity stays in what the constraint allows.
                    let m = &mass[k];
                    if let Some(p) = &projector[k] {
                        let a = apply(
                            p,
                            &std::array::from_fn(|d| if d < dofs { q[d] / m[d] } else { 0.0 }),
                        );
                        q = std::array::from_fn(|d| if d < dofs { a[d] * m[d] } else { 0.0 });
                    }
                    for d in 0..dofs {
                        let damped = local_damping(q[d], v[d], alpha);
                        v[d] = keep * v[d] + gain * damped / m[d] * dt;
                    }
                    if let Some(p) = &projector[k] {
                        *v = apply(p, v);
                    }
                    *q_out = q;
                    let old = *c;
                    *c = [c[0] + v[0] * dt, c[1] + v[1] * dt];
                    let spin = v[2] * dt;
                    let map = if simple {
                        let (exx, eyy, exy) = (v[3] * dt, v[4] * dt, v[5] * dt);
                        let de: StrainIncrement = [exx, eyy, 2.0 * exy];
                        let old = *s;
                        laws[material[k].0 as usize].update(s, state, plastic, &de);
                        if viscous > 0.0 {
                            // β_R σ̇ over this step, acting with the stress in the next one.
                            *sv = std::array::from_fn(|i| viscous * (s[i] - old[i]));
                        }
                        rotate(s, spin);
                        let a = [1.0 + exx, exy - spin, exy + spin, 1.0 + eyy];
                        *area *= a[0] * a[3] - a[1] * a[2];
                        a
                    } else {
                        let (sn, cs) = spin.sin_cos();
                        [cs, -sn, sn, cs]
                    };
                    *step = (old, *c, map);
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
                let (c0, c1, a) = step[b as usize];
                let x = [p[0] + u[0], p[1] + u[1]];
                let r = [x[0] - c0[0], x[1] - c0[1]];
                let new = [
                    c1[0] + a[0] * r[0] + a[1] * r[1],
                    c1[1] + a[2] * r[0] + a[3] * r[1],
                ];
                *vel = [(new[0] - x[0]) / dt, (new[1] - x[1]) / dt];
                *u = [new[0] - p[0], new[1] - p[1]];
                // A body node's force is part of its body's; the unbalanced force is the body's.
                *f = [0.0; 2];
                vel[0] * vel[0] + vel[1] * vel[1]
            })
            .reduce(|| 0.0, f64::max)
            .sqrt()
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
