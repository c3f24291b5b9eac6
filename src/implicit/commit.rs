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
//! The joints still integrate along the iterations' path: stepped from a fixed commit they flip
//! between stick and slip from one iteration to the next where the jointed tunnel's wedges are
//! about to move (its ratio then alternated between 2.5e-5 and 2.9e-5 for 200 iterations).

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
}

impl Committed {
    /// Commit the model's present state.
    pub fn of(model: &Model) -> Committed {
        Committed {
            disp: model.nodes.disp.clone(),
            stress: model.zones.stress.clone(),
            state: model.zones.state.clone(),
            plastic: model.zones.plastic.clone(),
            supports: model.supports.clone(),
            contacts: model.contacts.clone(),
            bodies: model.bodies.clone(),
        }
    }

    /// Put the whole model back to the commit (a step that failed, before it is cut).
    pub fn restore(&self, model: &mut Model) {
        model.nodes.disp.copy_from_slice(&self.disp);
        self.trial_zones(&mut model.zones);
        model.supports.clone_from(&self.supports);
        model.contacts.clone_from(&self.contacts);
        model.bodies.clone_from(&self.bodies);
    }

    /// Node displacements at the commit, m.
    pub fn displacements(&self) -> &[[f64; 2]] {
        &self.disp
    }

    /// Put the zones' stresses, yield flags and plastic strains back to the commit, from which
    /// their laws' trial takes the whole strain since (`Cycle::displace`).
    pub fn trial_zones(&self, zones: &mut Zones) {
        zones.stress.copy_from_slice(&self.stress);
        zones.state.copy_from_slice(&self.state);
        zones.plastic.copy_from_slice(&self.plastic);
    }

    /// Put the bolts' grout slip and plastic elongation back to the commit, before the force
    /// stage evaluates them from the total displacements.
    pub fn trial_supports(&self, supports: &mut Supports) {
        let cables = &self.supports.cables;
        supports.cables.slip.copy_from_slice(&cables.slip);
        supports.cables.plastic.copy_from_slice(&cables.plastic);
    }
}
