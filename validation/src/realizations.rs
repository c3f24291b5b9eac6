//! Joint realizations: `models/tunnel.json` with its joint sets scattered as a study of uncertain
//! joints would scatter them (issue 52: origins moved by up to ± the set's spacing in x and in y,
//! dips by ±15°, spacings and traces scaled by U(0.6, 1.4): each set's `scatter`, and the scene's
//! `realization` N picks the draw), each built whole and the first run through the stages (issue
//! 14 had asked it of a narrower scatter: ±2 m, ±10°, ±30 %).

use std::path::Path;
use std::time::Instant;

use adit::Scene;
use adit::scene::Scatter;
use adit_meshing::triangulate::smallest_angle;

/// The scatter of the study for a set `spacing` m apart: its origin by ± the spacing, its dip
/// by ±15°, its spacing and trace by ±40 %.
pub fn study(spacing: f64) -> Scatter {
    Scatter {
        origin: spacing,
        dip: 15.0,
        spacing: 0.4,
        trace: 0.4,
        gap: 0.0,
    }
}

/// `base` with every joint set scattered by `study`, at realization `n` (≥ 1).
pub fn realization(base: &Scene, n: u64) -> Scene {
    let mut sc = base.clone();
    for set in &mut sc.joint_sets {
        set.scatter = Some(study(set.spacing));
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
            adit::setup::setup(&realization(&base, n))
                .err()
                .map(|e| format!("realization {n}: {e}"))
        })
        .collect())
}

/// One realization of the study: how its build went.
#[derive(Debug, Clone)]
pub struct Built {
    /// Realization number N.
    pub n: u64,
    /// Wall seconds of the build (cutting, meshing, blocks, contacts), s.
    pub seconds: f64,
    /// The build's error, if it failed.
    pub error: Option<String>,
    pub zones: usize,
    pub blocks: usize,
    /// Smallest interior angle over the zones, degrees.
    pub min_angle: f64,
}

/// One realization run through its stages: the tunnel's closure at the end, m (inward positive).
#[derive(Debug, Clone)]
pub struct Ran {
    pub n: u64,
    pub closure: Result<f64, String>,
    /// Whether every stage reached equilibrium (the run's status `converged`).
    pub converged: bool,
    pub cycles: u64,
    pub seconds: f64,
}

/// Build realizations 1..=`count` of the tunnel model, timing each.
pub fn build_all(count: u64) -> anyhow::Result<Vec<Built>> {
    let base = Scene::load(&crate::repository_root().join("models/tunnel.json"))?;
    Ok((1..=count)
        .map(|n| {
            let start = Instant::now();
            let built = adit::setup::setup(&realization(&base, n));
            let seconds = start.elapsed().as_secs_f64();
            match built {
                Ok(b) => {
                    let m = &b.model;
                    let min_angle = m
                        .zones
                        .nodes
                        .iter()
                        .map(|t| smallest_angle(t.map(|k| m.nodes.pos[k as usize])))
                        .fold(180.0, f64::min);
                    Built {
                        n,
                        seconds,
                        error: None,
                        zones: m.zones.len(),
                        blocks: m.blocks.len(),
                        min_angle,
                    }
                }
                Err(e) => Built {
                    n,
                    seconds,
                    error: Some(format!("{e:#}")),
                    zones: 0,
                    blocks: 0,
                    min_angle: f64::NAN,
                },
            }
        })
        .collect())
}

/// Run realizations 1..=`count` of the tunnel model through its stages (output in `out`, each
/// replacing the last), recording the final closure of the tunnel.
pub fn run_all(count: u64, out: &Path) -> anyhow::Result<Vec<Ran>> {
    let base = Scene::load(&crate::repository_root().join("models/tunnel.json"))?;
    Ok((1..=count)
        .map(|n| {
            let start = Instant::now();
            let result = adit::run_scene(&realization(&base, n), out, &mut adit::solve::Quiet);
            let seconds = start.elapsed().as_secs_f64();
            match result {
                Ok(r) => Ran {
                    n,
                    closure: r
                        .summary
                        .stages
                        .last()
                        .and_then(|s| s.closure.values().next().copied())
                        .ok_or_else(|| {
                            // A run that failed before its excavation: say why.
                            r.summary
                                .reason
                                .clone()
                                .unwrap_or_else(|| "no closure in the summary".to_string())
                        }),
                    converged: r.summary.status == "converged",
                    cycles: r.summary.cycles,
                    seconds,
                },
                Err(e) => Ran {
                    n,
                    closure: Err(format!("{e:#}")),
                    converged: false,
                    cycles: 0,
                    seconds,
                },
            }
        })
        .collect())
}

/// The `q`-quantile (0 to 1) of `values` (sorted by the caller or not), nearest rank.
pub fn quantile(values: &[f64], q: f64) -> f64 {
    let mut v: Vec<f64> = values.iter().copied().filter(|x| !x.is_nan()).collect();
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[((q * (v.len() - 1) as f64).round() as usize).min(v.len() - 1)]
}

#[cfg(test)]
mod tests {
    /// The report's realizations in small: the first 4 run through the tunnel's stages, each
    /// to equilibrium.
    #[test]
    fn first_realizations_run_to_equilibrium() {
        let out = crate::run_folder("realizations_twin");
        let ran = super::run_all(4, &out).unwrap();
        let short: Vec<String> = (ran.iter())
            .filter(|r| !r.converged)
            .map(|r| format!("realization {}: {:?}", r.n, r.closure))
            .collect();
        assert!(short.is_empty(), "{}", short.join("\n"));
    }

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
