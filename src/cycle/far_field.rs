//! The far-field stage of the cycle: the elastic medium outside the region pushes on the
//! interface's nodes (`far_field::FarField::forces`).

use super::Cycle;
use crate::far_field::FarField;

impl Cycle {
    /// Far-field stage: the force of the far field (when the model has one) on each interface
    /// node for the displacements `disp` (m), into its buffer.
    pub(crate) fn far_field_forces(&mut self, far: Option<&FarField>, disp: &[[f64; 2]]) {
        if let Some(f) = far {
            f.forces(disp, &mut self.far_moved, &mut self.far_force);
        }
    }
}
