//! Draw realizations of `models/tunnel.json`'s two joint sets (origins moved by up to ±2 m, dips
//! by ±10°, spacings and traces by ±30 %) and build each; print how many fail and why.
//! `cargo run --release -p adit-validation --example realizations -- 800 [seed]`.

use adit::Scene;

/// A 64-bit LCG, uniform in [lo, hi).
struct Draws(u64);

impl Draws {
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }
}

fn main() -> anyhow::Result<()> {
    let mut args = std::env::args().skip(1);
    let count: usize = args.next().map_or(Ok(100), |a| a.parse())?;
    let seed: u64 = args.next().map_or(Ok(1), |a| a.parse())?;
    let base = Scene::load(&adit_validation::repository_root().join("models/tunnel.json"))?;
    let mut draws = Draws(seed);
    let start = std::time::Instant::now();
    let mut failed = 0;
    for k in 0..count {
        let mut sc = base.clone();
        for set in &mut sc.joint_sets {
            set.origin[0] += draws.uniform(-2.0, 2.0);
            set.origin[1] += draws.uniform(-2.0, 2.0);
            set.dip += draws.uniform(-10.0, 10.0);
            set.spacing *= draws.uniform(0.7, 1.3);
            set.trace = set.trace.map(|t| t * draws.uniform(0.7, 1.3));
        }
        if let Err(e) = adit::build::build(&sc) {
            failed += 1;
            println!("realization {k}: {e}");
        }
    }
    println!(
        "{failed} of {count} realizations failed to build ({:.1} s)",
        start.elapsed().as_secs_f64()
    );
    Ok(())
}
