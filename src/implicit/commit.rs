//! The committed state of an implicit solve: what the zones' and bolts' trials start from (issue
//! 17: "laws evaluate a trial stress or force from their last committed state and a total
//! increment, and commit on convergence"), and what a load step that does not converge goes back
//! to before it is halved (`steps`).
//!
//! - **Zones.** Each iteration their stresses, yield flags and plastic strains go back to the
//!   commit, and their laws' `trial` takes the whole strain since (`Cycle::displace`), so a step's
//!   answer does not depend on the iterations that reach it. Integrated along the iterations'
//!   path instead, the plastic strain piled up with the steps: the shipped Salençon hole in 16
//!   load steps ended 3.65 % from the closed form at the wall, against 0.91 % from the commit and
//!   0.87 % explicitly released as slowly.
//! - **Bolts.** Their grout slip and plastic elongation go back to the commit, and their laws take
//!   the whole displacement since (`support::Cables::forces` works from total displacements).
//!   Without it an accelerated iteration that overshoots leaves slip behind (the pull-out at 60 %
//!   of its capacity ended 1.3 % off the shear-lag solution instead of 0.006 %).
//!
//! - **Joints.** Each contact's joint law takes its trial from its committed state and the
//!   whole relative displacement since (`Cycle::contact_forces`). Contacts detected anew within
//!   a step are another list: the joints then commit where they are (`follow_detection`), so
//!   their answer depends on the iterations only through where detection happened.

use crate::cycle::{Cycle, JointCommit, Trial};
use crate::joint::JointState;
use crate::law::Stress;
use crate::model::bodies::Bodies;
use crate::model::{Contacts, Model, Zones};
use crate::support::Supports;

/// The model's state at the commit: what the trials start from, and what a cut step
/// (`steps`) goes back to.
pub struct Committed {
    /// Node displacements, m.
    disp: Vec<[f64; 2]>,
    /// Zone stresses, Pa.
    stress: Vec<Stress>,
    /// Zone yield flags.
    state: Vec<u8>,
    /// Zone plastic shear strains (dimensionless).
    plastic: Vec<f64>,
    /// The supports (the bolts' grout slip and plastic elongation are their state), the contacts
    /// and the bodies, whole.
    supports: Supports,
    contacts: Contacts,
    bodies: Bodies,
    /// The joints' commit: each contact's state and the node displacements (m) then; the
    /// commit's own until contacts are detected anew within the step.
    joint_state: Vec<JointState>,
    joint_disp: Vec<[f64; 2]>,
    /// The detections counted (`Cycle::detections`) when the joints last committed.
    detections: u64,
}

impl Committed {
    /// Commit the model's present state, after the detections `cycle` has counted; the zones'
    /// trials start afresh from it (`Cycle::zones_committed`).
    pub fn of(model: &Model, cycle: &mut Cycle) -> Committed {
        cycle.zones_committed();
        let detections = cycle.detections();
        Committed {
            joint_state: model.contacts.state.clone(),
            joint_disp: model.nodes.disp.clone(),
            detections,
            disp: model.nodes.disp.clone(),
            stress: model.zones.stress.clone(),
            state: model.zones.state.clone(),
            plastic: model.zones.plastic.clone(),
            supports: model.supports.clone(),
            contacts: model.contacts.clone(),
            bodies: model.bodies.clone(),
        }
    }

    /// Put the whole model back to the commit (a step that failed, before it is cut), the
    /// joints' commit with it.
    pub fn restore(&mut self, model: &mut Model, cycle: &mut Cycle) {
        cycle.zones_committed();
        model.nodes.disp.copy_from_slice(&self.disp);
        self.trial_zones(&mut model.zones);
        model.supports.clone_from(&self.supports);
        model.contacts.clone_from(&self.contacts);
        model.bodies.clone_from(&self.bodies);
        self.joint_state.clone_from(&self.contacts.state);
        self.joint_disp.copy_from_slice(&self.disp);
    }

    /// After contacts were detected anew (`detections` counted, more than at the joints'
    /// commit), the joints commit where they are: their states, which the detection carried
    /// over to the contacts that persist (new ones start as `Cycle::detect` makes them), and
    /// the displacements now.
    pub fn follow_detection(&mut self, model: &Model, detections: u64) {
        if detections != self.detections {
            self.joint_state.clone_from(&model.contacts.state);
            self.joint_disp.copy_from_slice(&model.nodes.disp);
            self.detections = detections;
        }
    }

    /// What the joints take their trial from.
    pub fn joints(&self) -> JointCommit<'_> {
        JointCommit {
            state: &self.joint_state,
            disp: &self.joint_disp,
        }
    }

    /// What the zones' and the joints' trials start from (`Cycle::displace`).
    pub fn trial(&self) -> Trial<'_> {
        Trial {
            disp: &self.disp,
            joints: self.joints(),
        }
    }

    /// Put the zones' stresses, yield flags and plastic strains back to the commit, from which
    /// their laws' trial takes the whole strain since (`Cycle::displace`).
    pub fn trial_zones(&self, zones: &mut Zones) {
        zones.stress.copy_from_slice(&self.stress);
        zones.state.copy_from_slice(&self.state);
        zones.plastic.copy_from_slice(&self.plastic);
    }

    /// Put the bolts' grout slip and plastic elongation back to the commit, before the force
    /// stage evaluates them from the total displacements; their grout forces, rock displacements
    /// and energies too, so that a load step puts its energy into the bolts once, by the
    /// trapezoid from the commit (`Cables::absorbed`).
    pub fn trial_supports(&self, supports: &mut Supports) {
        let (to, from) = (&mut supports.cables, &self.supports.cables);
        to.slip.copy_from_slice(&from.slip);
        to.plastic.copy_from_slice(&from.plastic);
        to.grout_force.copy_from_slice(&from.grout_force);
        to.rock_last.copy_from_slice(&from.rock_last);
        to.absorbed.copy_from_slice(&from.absorbed);
    }
}
