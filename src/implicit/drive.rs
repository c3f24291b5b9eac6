//! Displacement control: nodes moved by a given displacement over an implicit solve, as the
//! platens of a compression test or the box of a direct shear test move the specimen. The move is
//! part of the solve's first increment from the commit: one displace of the contact and zone
//! stages by the drive (zero elsewhere), whose zones take it through their laws' trial with the
//! rest of the increment, so a plastic zone at a platen does not yield twice. The driven
//! components must be fixed (the iterations would otherwise move the node back).

use crate::cycle::{Cycle, CycleParams};
use crate::model::{BODY, FIX_X, FIX_Y, Model};

use super::commit::Committed;

/// A node (its index) and the displacement (m) its fixed components are driven by over a solve;
/// a free component's must be 0.
pub type Drive = (u32, [f64; 2]);

/// Why `drive` cannot act on `model`, or `None`: a node out of range, a rigid or simple block's
/// node (its body's unknowns move it), or a driven component that is free.
pub fn refused(model: &Model, drive: &[Drive]) -> Option<String> {
    for &(n, d) in drive {
        let Some(&fixed) = model.nodes.fixed.get(n as usize) else {
            return Some(format!(
                "implicit: driven node {n} is not a node of the model"
            ));
        };
        if fixed & BODY != 0 {
            return Some(format!(
                "implicit: driven node {n} belongs to a rigid or simple block"
            ));
        }
        for (k, (flag, axis)) in [(FIX_X, "x"), (FIX_Y, "y")].into_iter().enumerate() {
            if d[k] != 0.0 && fixed & flag == 0 {
                return Some(format!(
                    "implicit: node {n} is driven along {axis} but free along it; fix it there"
                ));
            }
        }
    }
    None
}

/// Move `drive`'s nodes from the commit: the zones back to the commit, then one displace by the
/// drive (`du` is scratch, one per node).
pub fn apply(
    model: &mut Model,
    cycle: &mut Cycle,
    params: &CycleParams,
    committed: &Committed,
    drive: &[Drive],
    du: &mut [[f64; 2]],
) {
    du.fill([0.0; 2]);
    for &(n, d) in drive {
        du[n as usize] = d;
    }
    committed.trial_zones(&mut model.zones);
    cycle.displace(model, du, committed.trial(), params);
}
