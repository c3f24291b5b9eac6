//! Load steps of an implicit stage (`solve.load_steps`): the out-of-balance force F0 the stage
//! starts with (from an excavation, a load, a change of material or gravity) is released in equal
//! steps, each solved to the stage's ratio and committed before the next, as the explicit path's
//! `solve.ramp` releases it over cycles (`solve::Release`): at a fraction s of the stage the
//! nodes carry their applied loads minus (1 − s) F0. Plasticity and friction remember the path:
//! `models/tunnel.json`'s median wall closure is 7.33 mm (666 zones yielded) in one step, 7.32 mm
//! (657) in 4 and 7.29 mm (651) in 8, against 7.27 mm (644) explicitly with each stage released
//! over 16 000 cycles and 7.41 mm (679) released at once.
//!
//! A step that does not converge within `solve.max_iterations` is cut: the model goes back to the
//! last commit and the step is halved (a stage solved in one step too), at most `MAX_CUTS` times
//! in a stage (RS2's and ABAQUS's automatic increment cutting, in its simplest form).

use crate::cycle::{Cycle, CycleParams};
use crate::model::Model;
use crate::solve::Release;

/// Halvings of a step a stage may make in all.
pub const MAX_CUTS: u32 = 4;

/// The stage's load fraction done and the step being solved.
pub struct LoadSteps {
    /// F0 and the loads it is released towards.
    release: Release,
    /// Fraction of F0 released and committed.
    done: f64,
    /// Fraction the step being solved releases.
    size: f64,
    cuts: u32,
}

impl LoadSteps {
    /// `count` equal steps over the out-of-balance force `model` has now.
    pub fn new(count: u64, model: &mut Model, cycle: &mut Cycle, params: &CycleParams) -> Self {
        LoadSteps {
            release: Release::of(model, cycle, params),
            done: 0.0,
            size: 1.0 / count.max(1) as f64,
            cuts: 0,
        }
    }

    /// The fraction of F0 released at the end of the step being solved.
    fn target(&self) -> f64 {
        if self.is_last() {
            1.0
        } else {
            self.done + self.size
        }
    }

    /// Whether no step has been committed yet (the step being solved starts the stage).
    pub fn is_first(&self) -> bool {
        self.done == 0.0
    }

    /// Whether the step being solved ends the stage.
    pub fn is_last(&self) -> bool {
        self.done + self.size >= 1.0 - 1e-9
    }

    /// Set the nodes' loads for the step being solved.
    pub fn apply(&self, model: &mut Model) {
        self.release.hold(1.0 - self.target(), model);
    }

    /// The step converged: the next one starts from its end.
    pub fn advance(&mut self) {
        self.done = self.target();
    }

    /// Halve the step being solved; false when the stage has cut `MAX_CUTS` times already.
    pub fn cut(&mut self) -> bool {
        if self.cuts == MAX_CUTS {
            return false;
        }
        self.cuts += 1;
        self.size *= 0.5;
        true
    }

    /// Halvings made so far.
    pub fn cuts(&self) -> u32 {
        self.cuts
    }
}
