//! Joint realizations: `models/tunnel.json` with its joint sets drawn as a study of uncertain
//! joints would draw them (origins moved by up to ±2 m, dips by ±10°, spacings and traces by
//! ±30 %), each built whole (issue 14: 17 of 30 such realizations stopped in `adit check` with
//! "block boundary crosses itself").

use adit::Scene;

/// A small deterministic generator (64-bit LCG), uniform in [lo, hi).
pub struct Draws(pub u64);

impl Draws {
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }
}

/// `base` with each joint set's origin moved by up to ±2 m, its dip by ±10°, its spacing and
/// trace by ±30 %.
pub fn draw(base: &Scene, draws: &mut Draws) -> Scene {
    let mut sc = base.clone();
    for set in &mut sc.joint_sets {
        set.origin[0] += draws.uniform(-2.0, 2.0);
        set.origin[1] += draws.uniform(-2.0, 2.0);
        set.dip += draws.uniform(-10.0, 10.0);
        set.spacing *= draws.uniform(0.7, 1.3);
        set.trace = set.trace.map(|t| t * draws.uniform(0.7, 1.3));
    }
    sc
}

/// Build `count` realizations of the tunnel model drawn from `seed`; the errors of those that
/// fail, each with its index.
pub fn failures(count: usize, seed: u64) -> anyhow::Result<Vec<String>> {
    let base = Scene::load(&crate::repository_root().join("models/tunnel.json"))?;
    let mut draws = Draws(seed);
    Ok((0..count)
        .filter_map(|k| {
            let sc = draw(&base, &mut draws);
            adit::build::build(&sc)
                .err()
                .map(|e| format!("realization {k}: {e}"))
        })
        .collect())
}

#[cfg(test)]
mod tests {
    /// 40 realizations of the tunnel model's two non-persistent sets each build (mesh, blocks,
    /// contacts, supports).
    #[test]
    fn tunnel_model_builds_for_drawn_joint_realizations() {
        let failed = super::failures(40, 2026).unwrap();
        assert!(
            failed.is_empty(),
            "{} of 40 failed:\n{}",
            failed.len(),
            failed.join("\n")
        );
    }
}
