//! The engine's integration tests, one binary (one link on a fresh build, issue 49 friction
//! item 15): each module a subject, in its own file beside this one.

mod architecture;
mod bad_input;
mod barton_bandis;
mod blocks;
mod cli;
mod common;
mod determinism;
mod dynamic;
mod far_field;
mod fuzz;
mod hoek_brown;
mod implicit;
mod interrupt;
mod output;
mod realizations;
mod render;
mod restart;
mod stages;
mod supports;
mod sweep;
