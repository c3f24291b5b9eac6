use adit_validation::kirsch_case::{OuterLoad, run, scaled};
fn main() {
    let mut s = adit::Scene::load(std::path::Path::new("models/kirsch.json")).unwrap();
    for r in [1e-6, 1e-7, 1e-8] {
        s.solve.ratio = r;
        s.solve.max_cycles = 1_000_000;
        for f in [4.0, 2.0, 1.0, 0.5] {
            let res = run(&scaled(&s, f), "x", OuterLoad::Exact).unwrap();
            println!(
                "ratio {r:e} f {f}: zones {} cycles {} stress {:.5} wall {:.5} zcps {:.3e} t {:.2}",
                res.zones,
                res.cycles,
                res.stress_l2,
                res.wall_displacement,
                res.zone_cycles_per_s,
                res.wall_s
            );
        }
    }
}
