//! Validation of adit against closed forms: each case runs the engine, measures its error against
//! the exact solution and its cost, and is run in full by the report binary and coarsely by tests.

pub mod direct_shear;
pub mod glued;
pub mod gravity;
pub mod incline;
pub mod kirsch;
pub mod kirsch_case;
pub mod patch;
pub mod plot;
pub mod report;
