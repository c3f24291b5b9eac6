//! Joint realizations: `models/tunnel.json` with its joint sets scattered as a study of uncertain
//! joints would scatter them (origins moved by up to ±2 m, dips by ±10°, spacings and traces by
//! ±30 %: each set's `scatter`, and the scene's `realization` N picks the draw), each built whole
//! (issue 14: 17 of 30 such realizations stopped in `adit check` with "block boundary crosses
//! itself").

use adit::Scene;
use adit::scene::Scatter;

/// The scatter of the study: ±2 m, ±10°, ±30 % of spacing and trace.
pub const STUDY: Scatter = Scatter {
    origin: 2.0,
    dip: 10.0,
    spacing: 0.3,
    trace: 0.3,
    gap: 0.0,
};

/// `base` with every joint set scattered as `STUDY`, at realization `n` (≥ 1).
pub fn realization(base: &Scene, n: u64) -> Scene {
    let mut sc = base.clone();
    for set in &mut sc.joint_sets {
        set.scatter = Some(STUDY);
    }
    sc.realization = n;
    sc
}

/// Build realizations `first`, `first + 1`, … (`count` of them) of the tunnel model; the errors of
/// those that fail, each with its number.
pub fn failures(count: u64, first: u64) -> anyhow::Result<Vec<String>> {
    let base = Scene::load(&crate::repository_root().join("models/tunnel.json"))?;
    Ok((first..first + count)
        .filter_map(|n| {
            adit::build::build(&realization(&base, n))
                .err()
                .map(|e| format!("realization {n}: {e}"))
        })
        .collect())
}

#[cfg(test)]
mod tests {
    /// 40 realizations of the tunnel model's two non-persistent sets each build (mesh, blocks,
    /// contacts, supports).
    #[test]
    fn tunnel_model_builds_for_drawn_joint_realizations() {
        let failed = super::failures(40, 1).unwrap();
        assert!(
            failed.is_empty(),
            "{} of 40 failed:\n{}",
            failed.len(),
            failed.join("\n")
        );
    }
}
