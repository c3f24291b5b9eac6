//! adit: a 2D distinct element engine for jointed rock.
//!
//! A scene (`scene`) is set up (`setup`) as a model of structure-of-arrays state (`model`) whose
//! zones follow constitutive laws (`law`); a solver (`solve`) repeats the cycle's named stages
//! (`cycle`) to equilibrium or through time, stage after stage (`stage`), and `output` writes the
//! results. Units are SI
//! (m, Pa, kg, s), tension positive.

pub mod checkpoint;
pub mod contact;
pub mod cycle;
mod damping;
pub mod dynamics;
pub mod far_field;
pub mod flow;
pub mod implicit;
pub mod interrupt;
pub mod joint;
pub mod law;
pub mod model;
pub mod output;
pub mod run;
pub mod scene;
pub mod setup;
pub mod solve;
pub mod stage;
pub mod strength_reduction;
pub mod support;
pub mod sweep;
mod vector_state;

pub use run::{RunResult, run_scene, run_scene_branch, run_scene_from};
pub use scene::Scene;
