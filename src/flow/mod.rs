//! Water in the joints (the seed's §9.11, issue 51): a network of domains (the voids between
//! blocks along the joints and at their intersections), each with a volume and a pressure, joined
//! by pipes (the contacts along the joints) that carry flow by the cubic law.
//!
//! What is here: the network's state (`network.rs`, structure of arrays with typed ids), the fluid
//! (`fluid.rs`), the laws (the cubic law's conductance, `cubic.rs`; the hydraulic aperture that
//! follows a joint's opening, `aperture.rs`), the steady state solved directly (`steady.rs`: the
//! conductances make a graph Laplacian, factorized by faer's sparse Cholesky) and transient flow
//! stepped explicitly at its derived stable step (`transient.rs`). Heads are pressures plus
//! ρw g y (y up, m), so that water at rest in a column carries the hydrostatic gradient.
//!
//! The network of a model's joints (`build.rs`): domains where the joint faces' nodes meet, pipes
//! along the joint edges between blocks.
//!
//! Not yet here (issue 51 continues): the apertures following the contacts, the pressure acting
//! on the blocks and the joint laws' effective stress, and the scene's fields for water; no scene
//! reaches this module yet.

mod aperture;
mod build;
mod cubic;
mod fluid;
mod network;
mod steady;
mod transient;

pub use aperture::HydraulicAperture;
pub use build::{JointNetwork, NO_DOMAIN, joint_network};
pub use cubic::cubic_law_conductance;
pub use fluid::Fluid;
pub use network::{DomainId, Domains, Network, Pipes};
pub use steady::{SteadyError, solve_steady};
pub use transient::{Transient, stable_step};
