//! Salençon's hole in the rock of issue 13 (c = 1 MPa, φ = 25°, ψ = 0, ν = 0.3, p0 = 15 MPa) on
//! zones half the shipped size, plain and mixed, released at once and over 20 000 cycles
//! (`solve.ramp`): whether the answer depends on the relaxation path. Before the mixed zones'
//! stabilization (`cycle/mixed.rs`) mixed zones closed 5.1 % and 4.7 % too much; now (|closure
//! error|): plain 0.10 % and 0.23 %, mixed 0.40 % and 0.04 %.
//! `cargo run --release -p adit-validation --example salencon_ramp` (about 3 min on 2 cores).

use adit_validation::salencon::{Rock, WEAK_ROCK, run_rock_ramped};

fn main() -> anyhow::Result<()> {
    let kirsch = adit_validation::shipped_kirsch()?;
    for mixed in [false, true] {
        for ramp in [0, 20_000] {
            let rock = Rock { mixed, ..WEAK_ROCK };
            let r = run_rock_ramped(&kirsch, 0.5, &rock, ramp)?;
            println!(
                "mixed {mixed:5} ramp {ramp:6}: |wall closure error| {:.2} %, plastic radius {:.2} %, {} cycles",
                100.0 * r.errors["wall_displacement"],
                100.0 * r.errors["plastic_radius"],
                r.cycles
            );
        }
    }
    Ok(())
}
