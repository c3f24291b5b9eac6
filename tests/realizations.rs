//! Joint realizations: the main model builds for joint sets shifted, turned and spaced as a study
//! of uncertain joints would draw them (issue 14: 17 of 30 such realizations of `tunnel.json`
//! stopped in `adit check` with "block boundary crosses itself").

use adit::Scene;

/// A small deterministic generator (64-bit LCG), uniform in [lo, hi).
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

/// 40 realizations of the tunnel model's two non-persistent sets: origins moved by up to ±2 m,
/// dips by ±10°, spacings and traces by ±30 %; each builds (mesh, blocks, contacts).
#[test]
fn tunnel_model_builds_for_drawn_joint_realizations() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let base = Scene::load(&root.join("models/tunnel.json")).unwrap();
    let mut draws = Draws(2026);
    let mut failed = Vec::new();
    for k in 0..40 {
        let mut sc = base.clone();
        for set in &mut sc.joint_sets {
            set.origin[0] += draws.uniform(-2.0, 2.0);
            set.origin[1] += draws.uniform(-2.0, 2.0);
            set.dip += draws.uniform(-10.0, 10.0);
            set.spacing *= draws.uniform(0.7, 1.3);
            set.trace = set.trace.map(|t| t * draws.uniform(0.7, 1.3));
        }
        if let Err(e) = adit::build::build(&sc) {
            failed.push(format!("realization {k}: {e}"));
        }
    }
    assert!(
        failed.is_empty(),
        "{} of 40 failed:\n{}",
        failed.len(),
        failed.join("\n")
    );
}

/// Moving set 0's origin across ±1 m in 5 cm steps (20 of 40 positions failed before).
#[test]
fn tunnel_model_builds_as_a_set_moves_in_small_steps() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let base = Scene::load(&root.join("models/tunnel.json")).unwrap();
    let failed: Vec<String> = (0..=40)
        .filter_map(|k| {
            let mut sc = base.clone();
            sc.joint_sets[0].origin[0] += -1.0 + 0.05 * k as f64;
            adit::build::build(&sc)
                .err()
                .map(|e| format!("step {k}: {e}"))
        })
        .collect();
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}
