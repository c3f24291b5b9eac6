//! The energy balance of a dynamic stage (the `kinetic_energy`, `strain_energy`,
//! `boundary_work`, `quiet_energy` and `energy_error` histories), J per metre of tunnel. The
//! central difference conserves, for a linear undamped model under loads F,
//!
//!   E_n = ½ v_{n−½}ᵀ M v_{n+½} + ½ u_nᵀ K u_n,   E_n − E_0 = Σ_{k=1..n} ½(F_{k−1} + F_k)·(u_k − u_{k−1})
//!
//! exactly (the momentum equation at steps n and n − 1 dotted with v_{n−½}), so the balance
//! takes the kinetic energy as ½ Σ m v⁻·v⁺ over the nodes' free components (a held one moves
//! as its boundary says, whose work on the rock is W's; and ½ Σ M q̇⁻·q̇⁺ over the rigid and
//! simple blocks) after each step, the work of the applied loads (tractions, gravity, load
//! histories, a quiet boundary's held reactions) by that trapezoid over the free components, the
//! zones' strain energy from their stress change since the stage began,
//!
//!   U = Σ A (σ₀ + ½Δσ) : D⁻¹ : Δσ,   a : D⁻¹ : b = p_a p_b / K + s_a : s_b / (2G)
//!
//! (σ₀ the stress when the balance began, p the mean stress, s the deviator, σzz included: the work
//! σ : dε of an elastic zone from σ₀; an inelastic zone's recoverable part), and the net energy
//! out through the quiet boundaries, the work of their dashpots' and incident waves' forces by the
//! same trapezoid, negated (`QuietBoundary::net_outflow`). The joints' energy J (what their
//! springs store and their friction and viscosity dissipate) sums each contact's
//! L ½[(σn⁰ + σn) Δun + (τ⁰ + τ) Δus] over the steps (`Cycle::contact_forces`: the work the
//! rock does on the joint, the same trapezoid); the supports' S (what bolts and liners store,
//! dissipate by yielding and carry as their own motion) is the work the rock does on them,
//! −Σ ½(f_{n−1} + f_n)·v_{n−½} Δt over their force slots f. The error is the work less the rest:
//! W − ΔK − U − Q − J − S − D, zero to round-off for a linear model (a joint that slips or a
//! support that yields within a step: of the order of that step's share), with D what damping
//! took: at the nodes, the force the motion stage's local and mass-proportional damping took from
//! each free component, f_d = m (v⁺ − v⁻)/Δt − F (read before the quiet boundary corrects its
//! nodes), by the same trapezoid, negated; in the zones, the stiffness-proportional viscous stress
//! σ_v = (β_R/Δt) Δσ by ½ A (σ_v,n−1 + σ_v,n) : D⁻¹ : Δσ_n over each step's stress change Δσ_n
//! (exact for an elastic zone, whose strain increment is D⁻¹ Δσ; a yielding zone's viscous stress
//! works on its elastic part only). The prescribed motions' work on the rock is in W: −½(G_{n−1} +
//! G_n)·Δu over each held component, G the force the rock puts on it (`drive`). Not yet counted:
//! the damping of rigid and simple blocks.

use crate::law::Stress;

/// A rigid or simple block's generalised vector (`model::bodies::Dof`: velocity, mass).
type Generalised = [f64; 6];

/// The energy balance's state since its stage began.
#[derive(Debug, Clone, PartialEq)]
pub struct Energy {
    /// Each node's velocity before this step's motion stage v⁻ (m/s), each body's q̇⁻.
    before: Vec<[f64; 2]>,
    body_before: Vec<Generalised>,
    /// Each node's applied load at the last step, N/m.
    last_applied: Vec<[f64; 2]>,
    /// Each zone's stress when the balance began, Pa.
    start_stress: Vec<Stress>,
    /// The work of the applied loads so far, J/m.
    work: f64,
    /// The kinetic energy at the first step, J/m (`None` before it).
    start_kinetic: Option<f64>,
    /// The kinetic energy after the last step, J/m.
    kinetic: f64,
    /// The rock node each support force slot acts on (`Supports::slot_nodes`), and each slot's
    /// force at the last step, N/m.
    slot_nodes: Vec<u32>,
    last_support: Vec<[f64; 2]>,
    /// The energy into the joints and into the supports so far, J/m.
    joints: f64,
    supports: f64,
    /// Each node's damping force at the last step (local and mass-proportional, free components),
    /// N/m.
    last_damping: Vec<[f64; 2]>,
    /// Each zone's stress after the last step and its viscous stress then (stiffness-proportional
    /// damping), Pa.
    last_stress: Vec<Stress>,
    last_viscous: Vec<Stress>,
    /// The energy damping took so far, J/m.
    damping: f64,
    /// Each held component's force from the rock at the last step (N/m) and its velocity then,
    /// v_{n+½} (m/s), in the order `Inputs::held` gives them.
    held_last: Vec<(f64, f64)>,
}

/// The balance's terms, J/m.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Balance {
    pub kinetic: f64,
    pub strain: f64,
    pub boundary_work: f64,
    pub quiet: f64,
    pub joints: f64,
    pub supports: f64,
    pub damping: f64,
    /// W − ΔK − U − Q − J − S − D.
    pub error: f64,
}

/// The state a step's account reads: the nodes' masses (kg/m), velocities v⁺ (m/s) and applied
/// loads (N/m), each node's free components (`None` for a rigid or simple block's node, which its
/// block carries), the blocks' generalised masses and velocities, each contact's energy into its
/// joint this step (J/m) and each support slot's force on the rock (N/m).
pub(crate) struct Stepped<'a, F: Fn(usize) -> Option<[bool; 2]>> {
    pub mass: &'a [f64],
    pub vel: &'a [[f64; 2]],
    pub applied: &'a [[f64; 2]],
    pub free: F,
    pub body_mass: &'a [Generalised],
    pub body_vel: &'a [Generalised],
    pub joint_work: &'a [f64],
    pub support_force: &'a [[f64; 2]],
}

impl Energy {
    /// A balance beginning from the nodes' velocities `vel` (m/s) and applied loads `applied`
    /// (N/m), the blocks' `body_vel`, the zones' `stress` (Pa) and the rock node of each support
    /// force slot.
    pub fn start(
        vel: &[[f64; 2]],
        body_vel: &[Generalised],
        applied: &[[f64; 2]],
        stress: &[Stress],
        slot_nodes: Vec<u32>,
    ) -> Energy {
        Energy {
            before: vel.to_vec(),
            body_before: body_vel.to_vec(),
            last_applied: applied.to_vec(),
            start_stress: stress.to_vec(),
            work: 0.0,
            start_kinetic: None,
            kinetic: 0.0,
            last_support: vec![[0.0; 2]; slot_nodes.len()],
            slot_nodes,
            joints: 0.0,
            supports: 0.0,
            last_damping: vec![[0.0; 2]; vel.len()],
            last_stress: stress.to_vec(),
            last_viscous: vec![[0.0; 4]; stress.len()],
            damping: 0.0,
            held_last: Vec::new(),
        }
    }

    /// After the step: the work of the prescribed motions on the rock, −½(G_{n−1} + G_n)·Δu over
    /// each held component (`held`: node, axis), with G the force the rock put on it
    /// (`internal`, N/m) and Δu = u_n − u_{n−1} = v_{n−½} Δt its move over the step before (the
    /// motion held it at v_{n+½}, `vel`, m/s, for the next); counted as the loads' work W (not at
    /// the balance's first step).
    pub(crate) fn drive(
        &mut self,
        held: impl Iterator<Item = (u32, usize)>,
        internal: &dyn Fn(usize) -> [f64; 2],
        vel: &[[f64; 2]],
        dt: f64,
    ) {
        let (mut work, mut k) = (0.0, 0);
        for (n, axis) in held {
            let (g, v) = (internal(n as usize)[axis], vel[n as usize][axis]);
            match self.held_last.get_mut(k) {
                Some(last) => {
                    work -= 0.5 * (last.0 + g) * last.1 * dt;
                    *last = (g, v);
                }
                None => self.held_last.push((g, v)),
            }
            k += 1;
        }
        if self.start_kinetic.is_some() {
            self.work += work;
        }
    }

    /// After the motion stage, before the quiet boundary corrects its nodes: each free node
    /// component's damping force f_d = m (v⁺ − v⁻)/Δt − F, what local and mass-proportional damping
    /// took from the force F the motion stage gathered (`force`, N/m), and the energy it took,
    /// −½(f_d,n−1 + f_d,n)·v⁻ Δt (not at the balance's first step). An undamped step's f_d is 0
    /// and is not computed (`damped` false).
    pub(crate) fn damp_nodes<F: Fn(usize) -> Option<[bool; 2]>>(
        &mut self,
        s: &Stepped<F>,
        force: &[[f64; 2]],
        damped: bool,
        dt: f64,
    ) {
        if !damped {
            return;
        }
        let mut took = 0.0;
        for (n, gathered) in force.iter().enumerate() {
            let Some(free) = (s.free)(n) else {
                continue;
            };
            let (before, after, last) = (self.before[n], s.vel[n], &mut self.last_damping[n]);
            for d in (0..2).filter(|&d| free[d]) {
                let f = s.mass[n] * (after[d] - before[d]) / dt - gathered[d];
                took -= 0.5 * (last[d] + f) * before[d] * dt;
                last[d] = f;
            }
        }
        if self.start_kinetic.is_some() {
            self.damping += took;
        }
    }

    /// After the step: each zone's viscous stress σ_v = `viscous` Δσ (β_R/Δt,
    /// `CycleParams::viscous_ratio`; nothing without stiffness-proportional damping) over its
    /// stress change Δσ since the last step (`stress`, Pa), and the energy it took,
    /// ½ A (σ_v,n−1 + σ_v,n) : D⁻¹ : Δσ, with the zones' `area` (m²) and `moduli` (bulk, shear, Pa).
    pub(crate) fn damp_zones(
        &mut self,
        stress: &[Stress],
        area: &[f64],
        moduli: impl Fn(usize) -> (f64, f64),
        viscous: f64,
    ) {
        if viscous == 0.0 {
            return;
        }
        let mut took = 0.0;
        for z in 0..stress.len() {
            let change: Stress = std::array::from_fn(|k| stress[z][k] - self.last_stress[z][k]);
            let rate: Stress = change.map(|c| viscous * c);
            let mean: Stress = std::array::from_fn(|k| 0.5 * (self.last_viscous[z][k] + rate[k]));
            let (bulk, shear) = moduli(z);
            took += area[z] * compliance(&mean, &change, bulk, shear);
            self.last_stress[z] = stress[z];
            self.last_viscous[z] = rate;
        }
        if self.start_kinetic.is_some() {
            self.damping += took;
        }
    }

    /// Before the motion stage (the loads of the step applied): keep v⁻.
    pub(crate) fn remember(&mut self, vel: &[[f64; 2]], body_vel: &[Generalised]) {
        self.before.copy_from_slice(vel);
        self.body_before.copy_from_slice(body_vel);
    }

    /// After the motion stage of a step of `dt` s: the kinetic energy ½ v⁻·M v⁺ over the free
    /// components, the loads'
    /// work ½(F_{n−1} + F_n)·v⁻ Δt over the free components, the joints' energy and the supports'
    /// −½(f_{n−1} + f_n)·v⁻ Δt (none at the balance's first step, whose v⁻ moved the model before
    /// it began).
    pub(crate) fn account<F: Fn(usize) -> Option<[bool; 2]>>(&mut self, s: Stepped<F>, dt: f64) {
        let (mut kinetic, mut work) = (0.0, 0.0);
        for n in 0..s.vel.len() {
            let Some(free) = (s.free)(n) else {
                continue;
            };
            let (before, after) = (self.before[n], s.vel[n]);
            for d in (0..2).filter(|&d| free[d]) {
                kinetic += 0.5 * s.mass[n] * before[d] * after[d];
                let f = 0.5 * (self.last_applied[n][d] + s.applied[n][d]);
                work += f * before[d] * dt;
            }
        }
        for ((m, before), after) in s.body_mass.iter().zip(&self.body_before).zip(s.body_vel) {
            kinetic += 0.5 * (0..6).map(|d| m[d] * before[d] * after[d]).sum::<f64>();
        }
        let joints: f64 = s.joint_work.iter().sum();
        let mut supports = 0.0;
        for ((&n, last), f) in (self.slot_nodes.iter())
            .zip(&mut self.last_support)
            .zip(s.support_force)
        {
            let v = self.before[n as usize];
            supports -= 0.5 * ((last[0] + f[0]) * v[0] + (last[1] + f[1]) * v[1]) * dt;
            *last = *f;
        }
        self.last_applied.copy_from_slice(s.applied);
        self.kinetic = kinetic;
        if self.start_kinetic.is_none() {
            self.start_kinetic = Some(kinetic);
        } else {
            self.work += work;
            self.joints += joints;
            self.supports += supports;
        }
    }

    /// The balance now: the zones' strain energy from their `stress` (Pa), `area` (m²) and
    /// `moduli` (each zone's bulk and shear moduli, Pa), with the energy the quiet boundaries
    /// absorbed, `quiet` (J/m).
    pub fn balance(
        &self,
        stress: &[Stress],
        area: &[f64],
        moduli: impl Fn(usize) -> (f64, f64),
        quiet: f64,
    ) -> Balance {
        let strain = (0..stress.len())
            .map(|z| {
                let (s0, s) = (&self.start_stress[z], &stress[z]);
                let change: Stress = std::array::from_fn(|k| s[k] - s0[k]);
                let mid: Stress = std::array::from_fn(|k| s0[k] + 0.5 * change[k]);
                let (bulk, shear) = moduli(z);
                area[z] * compliance(&mid, &change, bulk, shear)
            })
            .sum::<f64>();
        let kinetic = self.kinetic - self.start_kinetic.unwrap_or(self.kinetic);
        Balance {
            kinetic: self.kinetic,
            strain,
            boundary_work: self.work,
            quiet,
            joints: self.joints,
            supports: self.supports,
            damping: self.damping,
            error: self.work
                - kinetic
                - strain
                - quiet
                - self.joints
                - self.supports
                - self.damping,
        }
    }
}

/// a : D⁻¹ : b for isotropic elasticity of bulk modulus K and shear modulus G (Pa): p_a p_b / K
/// + s_a : s_b / (2G), stresses [xx, yy, zz, xy] (Pa), s : s counting xy twice; 1/Pa · Pa² = Pa.
fn compliance(a: &Stress, b: &Stress, bulk: f64, shear: f64) -> f64 {
    let (pa, pb) = ((a[0] + a[1] + a[2]) / 3.0, (b[0] + b[1] + b[2]) / 3.0);
    let deviatoric = (0..3).map(|k| (a[k] - pa) * (b[k] - pb)).sum::<f64>() + 2.0 * a[3] * b[3];
    let volumetric = if bulk > 0.0 { pa * pb / bulk } else { 0.0 };
    let distortion = if shear > 0.0 {
        deviatoric / (2.0 * shear)
    } else {
        0.0
    };
    volumetric + distortion
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ½ σ : D⁻¹ : σ of a uniaxial stress σ in xx alone is σ²/(2E).
    #[test]
    fn the_compliance_gives_the_strain_energy_density() {
        let (e, nu): (f64, f64) = (10e9, 0.25);
        let (bulk, shear) = (e / (3.0 * (1.0 - 2.0 * nu)), e / (2.0 * (1.0 + nu)));
        let s = [-3e6, 0.0, 0.0, 0.0];
        let u = 0.5 * compliance(&s, &s, bulk, shear);
        assert!((u - 9e12 / (2.0 * e)).abs() < 1e-9 * u, "{u}");
        let t = [0.0, 0.0, 0.0, 2e6];
        let u = 0.5 * compliance(&t, &t, bulk, shear);
        assert!((u - 4e12 / (2.0 * shear)).abs() < 1e-9 * u, "{u}");
    }
}
