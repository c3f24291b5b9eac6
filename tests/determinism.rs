//! The same scene gives bit-identical results on one thread and on several.

use std::path::Path;

use adit::Scene;
use adit::scene::BlockMode;
use adit::setup::setup;
use adit::solve::{Quiet, Solver};

fn run_on(model: &str, mode: BlockMode, threads: usize) -> (Vec<[f64; 2]>, Vec<[f64; 4]>, f64) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("models")
        .join(model);
    let mut s = Scene::load(&path).unwrap();
    s.solve.max_cycles = 300;
    s.blocks.mode = mode;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    pool.install(|| {
        let mut b = setup(&s).unwrap();
        let mut solver = Solver::new(&mut b.model, &s.solve, 0);
        let sol = solver.solve(&mut b.model, &mut Quiet);
        let mut stress = b.model.zones.stress;
        stress.extend(b.model.bodies.stress);
        (b.model.nodes.disp, stress, sol.final_ratio)
    })
}

#[test]
fn one_and_three_threads_agree_bit_for_bit() {
    for (model, mode) in [
        ("kirsch.json", BlockMode::Deformable),
        ("jointed_tunnel.json", BlockMode::Deformable),
        ("jointed_tunnel.json", BlockMode::Simple),
        ("jointed_tunnel.json", BlockMode::Rigid),
    ] {
        let (a, b) = (run_on(model, mode, 1), run_on(model, mode, 3));
        assert!(
            a.0 == b.0 && a.1 == b.1 && a.2.to_bits() == b.2.to_bits(),
            "{model} {mode:?}"
        );
    }
}
