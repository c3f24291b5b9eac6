//! Sweeps: one base scene run many times, each run with its own parameters (a grid, random draws
//! or joint realizations), each independent, gathered into one table.
//!
//! The engine's part is the same for the command line (`adit sweep SPEC`, a pool of processes) and
//! the Python package (`adit.sweep`, a process pool or a Dask cluster): the spec (`spec.rs`), its
//! runs and their scenes (`plan.rs`), one run to one row (`row.rs`), and the table with its plot
//! (`table.rs`). A run that fails is a row with its error. Each finished run leaves its row in
//! `<out>/runs/<id>/row.json`, so a sweep started again runs only what is missing. The table is
//! written only when every run has its row (a sweep starting removes the last one's), so a table
//! that exists is of a sweep that finished.

pub mod local;
pub mod plan;
pub mod row;
pub mod spec;
pub mod table;

pub use local::{in_child, run_local};
pub use plan::{RunInput, plan, scene_of};
pub use row::{Row, done, run_one, save};
pub use spec::SweepSpec;
pub use table::{remove_table, write_table};
