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
        ("jointed_tunnel_bem.json", BlockMode::Deformable),
        ("shallow_tunnel_bem.json", BlockMode::Deformable),
    ] {
        let (a, b) = (run_on(model, mode, 1), run_on(model, mode, 3));
        assert!(
            a.0 == b.0 && a.1 == b.1 && a.2.to_bits() == b.2.to_bits(),
            "{model} {mode:?}"
        );
    }
}

/// The implicit path too: the sparse Cholesky's parallel factorization must not change a bit with
/// the thread count (shipped Kirsch model, and the jointed tunnel for 20 iterations).
#[test]
fn implicit_one_and_three_threads_agree_bit_for_bit() {
    let run = |model: &str, threads: usize| {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("models")
            .join(model);
        let mut s = Scene::load(&path).unwrap();
        s.solve.method = adit::scene::SolveMethod::Implicit;
        s.solve.max_iterations = 20;
        let out = std::env::temp_dir().join(format!("adit-test-implicit-threads-{threads}"));
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let r = adit::run_scene(&s, &out, &mut Quiet).unwrap();
            (r.built.model.nodes.disp, r.built.model.zones.stress)
        })
    };
    for model in ["kirsch.json", "jointed_tunnel.json"] {
        assert!(run(model, 1) == run(model, 3), "{model}");
    }
}
