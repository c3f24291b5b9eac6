//! Dynamics beyond real masses and Rayleigh damping (the seed's §9.6): boundaries that let a
//! wave leave the model and bring a wave or a motion into it. A quiet (viscous) boundary part
//! carries dashpots on its nodes (`quiet.rs`, Lysmer & Kuhlemeyer 1969), and an incident plane
//! wave given as a particle-velocity history (`history.rs`) enters through it as the force of the
//! stress 2ρC v; a part with a prescribed motion has one velocity component follow a velocity or
//! an integrated acceleration history (`motion.rs`); a free-field part's dashpots act on the
//! velocity relative to a one-dimensional column beside it, whose stress loads it
//! (`free_field.rs`), a part with a load history its traction
//! scaled by it (`load.rs`), both the list's `Inputs`; every node's peak particle velocity is
//! kept over the dynamic stages (`peaks.rs`), and the energy balance of a stage when a history
//! asks for it (`energy.rs`); the blocks on an excavation's wall are watched for the velocity
//! they leave it with (`ejection.rs`). The mechanical cycle knows this physics only
//! through its stages around the motion update (`Cycle::run`); a scene without them pays nothing
//! for it.

mod ejection;
mod energy;
mod free_field;
mod history;
mod inputs;
mod load;
mod motion;
mod peaks;
mod quiet;

pub use ejection::{Ejected, Ejection, WallBlock};
pub(crate) use energy::Stepped;
pub use energy::{Balance, Energy};
pub use free_field::{Column, ColumnElement};
pub use history::History;
pub use inputs::Inputs;
pub(crate) use load::TimedLoad;
pub use motion::Integrated;
pub(crate) use motion::Motion;
pub use peaks::Peaks;
pub(crate) use quiet::Moving;
pub use quiet::{QuietBoundary, QuietEdge};
