//! Dynamics beyond real masses and Rayleigh damping (the seed's §9.6): boundaries that let a
//! wave leave the model and bring a wave into it. A quiet (viscous) boundary part carries
//! dashpots on its nodes (`quiet.rs`, Lysmer & Kuhlemeyer 1969), and an incident plane wave given
//! as a particle-velocity history (`incident.rs`) enters through it as the force of the stress
//! 2ρC v. The mechanical cycle knows this physics only through its stage around the motion
//! update (`Cycle::run`); a scene without quiet parts pays nothing for it.

mod incident;
mod quiet;

pub use incident::History;
pub(crate) use quiet::Moving;
pub use quiet::{QuietBoundary, QuietEdge};
