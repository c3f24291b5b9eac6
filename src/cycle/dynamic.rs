//! The dynamic stage around the motion update (`dynamics`): before it, the quiet boundary keeps
//! the velocities v⁻, the prescribed motions and load histories set the held velocities and the
//! loads, and the energy balance keeps v⁻; after it, the quiet and free-field boundaries correct
//! their nodes by their dashpots and driving forces, and the peak velocities, the wall blocks'
//! ejection and the energy balance take the step. A scene without them pays one branch each.

use crate::dynamics::{Ejection, Energy, Inputs, Moving, Peaks, QuietBoundary, Stepped};
use crate::law::ZoneLaw;
use crate::model::bodies::{Bodies, NO_BODY};
use crate::model::zones::Zones;
use crate::model::{FIX_X, FIX_Y, Nodes};

/// What the step's force stages passed between the rock and its joints and supports, for the
/// energy balance: each contact's energy into its joint (J/m) and each support slot's force on
/// its rock node (N/m, `Supports::slot_nodes`).
pub(super) struct Exchanged<'a> {
    pub joints: &'a [f64],
    pub supports: &'a [[f64; 2]],
}

/// What the step's damping and prescribed motions acted on, for the energy balance: whether the
/// motion stage damped the nodes (local or mass-proportional damping), β_R/Δt
/// (`CycleParams::viscous_ratio`), the zones' stress after the step (Pa), areas (m²), materials
/// and laws (their moduli), and the force the rock put on a node this step (`internal`, N/m: on a
/// held component, what the prescribed motion works against).
pub(super) struct Damped<'a> {
    pub nodes: bool,
    pub viscous: f64,
    pub zones: &'a Zones,
    pub laws: &'a [Box<dyn ZoneLaw>],
    pub internal: &'a dyn Fn(usize) -> [f64; 2],
}

/// The dynamic state of the model the stage reads and writes.
pub(super) struct Dynamic<'a> {
    pub quiet: &'a mut Option<QuietBoundary>,
    pub inputs: &'a mut Option<Inputs>,
    pub peaks: &'a mut Option<Peaks>,
    pub ejection: &'a mut Option<Ejection>,
    pub energy: &'a mut Option<Energy>,
}

impl Dynamic<'_> {
    /// Before the motion stage of the step from `time` (s since the solve began) by `dt` (s).
    pub fn before_motion(&mut self, nodes: &mut Nodes, bodies: &Bodies, time: f64, dt: f64) {
        if let Some(q) = self.quiet.as_mut() {
            q.remember(&nodes.vel);
        }
        if let Some(i) = self.inputs.as_mut() {
            i.impose(&mut nodes.vel, &mut nodes.applied, time, dt);
        }
        if let Some(e) = self.energy.as_mut() {
            e.remember(&nodes.vel, &bodies.velocity);
        }
    }

    /// After the motion stage: the quiet nodes' velocities and displacements corrected, then
    /// the peaks, the wall blocks' ejection and the energy balance (with what the step
    /// `exchanged` with the joints and supports). Returns the quiet nodes' largest speed, m/s (0
    /// without).
    pub fn after_motion(
        &mut self,
        nodes: &mut Nodes,
        bodies: &Bodies,
        exchanged: Exchanged,
        damped: Damped,
        time: f64,
        dt: f64,
    ) -> f64 {
        if let Some(e) = self.energy.as_mut() {
            e.damp_nodes(
                &stepped(nodes, bodies, &exchanged),
                &nodes.force,
                damped.nodes,
                dt,
            );
        }
        let mut speed = 0.0;
        if let Some(q) = self.quiet.as_mut() {
            let fixed = &nodes.fixed;
            let moving = Moving {
                mass: &nodes.mass,
                vel: &mut nodes.vel,
                disp: &mut nodes.disp,
                force: &mut nodes.force,
                free: |n: u32| {
                    let f = fixed[n as usize];
                    [f & FIX_X == 0, f & FIX_Y == 0]
                },
            };
            speed = q.absorb(moving, dt, time);
        }
        if let Some(peaks) = self.peaks.as_mut() {
            peaks.record(&nodes.vel, dt);
        }
        if let Some(ejection) = self.ejection.as_mut() {
            ejection.record(&nodes.mass, &nodes.vel);
        }
        if let Some(e) = self.energy.as_mut() {
            let zones = damped.zones;
            let moduli = |z: usize| damped.laws[zones.material[z].0 as usize].moduli();
            e.damp_zones(&zones.stress, &zones.area, moduli, damped.viscous);
            if let Some(inputs) = self.inputs.as_ref() {
                e.drive(inputs.held(), damped.internal, &nodes.vel, dt);
            }
            e.account(stepped(nodes, bodies, &exchanged), dt);
        }
        speed
    }
}

/// The nodes' and blocks' state as the energy balance reads it after a step (`Stepped`): a node's
/// free components, none for a rigid or simple block's node (its block carries it).
fn stepped<'a>(
    nodes: &'a Nodes,
    bodies: &'a Bodies,
    exchanged: &Exchanged<'a>,
) -> Stepped<'a, impl Fn(usize) -> Option<[bool; 2]> + 'a> {
    let (fixed, of_node) = (&nodes.fixed, &bodies.of_node);
    Stepped {
        mass: &nodes.mass,
        vel: &nodes.vel,
        applied: &nodes.applied,
        free: move |n: usize| {
            let f = fixed[n];
            (of_node.get(n).is_none_or(|&b| b == NO_BODY))
                .then_some([f & FIX_X == 0, f & FIX_Y == 0])
        },
        body_mass: &bodies.mass,
        body_vel: &bodies.velocity,
        joint_work: exchanged.joints,
        support_force: exchanged.supports,
    }
}
