//! The bolts' committed state (issue 17: "laws evaluate a trial stress or force from their last
//! committed state and a total increment"). Each implicit iteration puts the bolts' grout slip
//! and plastic elongation back to where they were when the solve began, and their laws then take
//! the whole displacement since (`support::Cables::forces` works from total displacements): one
//! step of the grout and segment laws, so where they converge does not depend on the iterations'
//! path. Without it an accelerated iteration that overshoots leaves slip behind (the pull-out
//! at 60 % of its capacity ended 1.3 % off the shear-lag solution instead of 0.006 %).
//!
//! The zones and the joints still integrate along the iterations' path: one step of the
//! Mohr–Coulomb return over a whole stage crosses the corners of its yield surface, which the law
//! does not handle, and joints stepped from a fixed commit flip between stick and slip from one
//! iteration to the next where the jointed tunnel's wedges are about to move (its ratio then
//! alternated between 2.5e-5 and 2.9e-5 for 200 iterations).

use crate::support::Supports;

/// The bolts' grout slip and plastic elongation at the commit.
pub struct Committed {
    /// Each cable node's grout slip and each segment's plastic elongation, m.
    slip: Vec<f64>,
    plastic: Vec<f64>,
}

impl Committed {
    /// Commit the supports' present state.
    pub fn of(supports: &Supports) -> Committed {
        Committed {
            slip: supports.cables.slip.clone(),
            plastic: supports.cables.plastic.clone(),
        }
    }

    /// Put the bolts' grout slip and plastic elongation back to the commit, before the force
    /// stage evaluates them from the total displacements.
    pub fn trial(&self, supports: &mut Supports) {
        supports.cables.slip.copy_from_slice(&self.slip);
        supports.cables.plastic.copy_from_slice(&self.plastic);
    }
}
