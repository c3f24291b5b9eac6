//! The scikit-fem peer of the implicit solve (issue 17): the same Kirsch problem on adit's own
//! mesh (nodes, triangles, fixities, the out-of-balance force of the in-situ stress and the exact
//! outer traction) solved by `validation/peer/kirsch_skfem.py` with scikit-fem's linear
//! triangles and SciPy's sparse direct solver. Both solve the same discrete problem, so their
//! stresses agree to round-off (`difference`) and the comparison is one of speed alone.

use std::path::Path;
use std::process::Command;

use adit::Scene;
use adit::scene::SolveMethod;
use adit::setup::setup;
use adit::solve::{Quiet, Solver, Status};

use crate::kirsch_case::{closed_form, load_outer_exactly, scaled};

/// What the peer printed.
#[derive(Debug, Clone, serde::Deserialize)]
pub struct PeerResult {
    /// Seconds of assembly, solve and stresses (the mesh is adit's, read from a file).
    pub seconds: f64,
    pub unknowns: usize,
    /// Relative L2 stress error over the zones within 5a, as `kirsch_case` measures it.
    pub stress_l2: f64,
    /// Largest difference of a zone stress component from adit's implicit one, over the
    /// largest exact stress.
    pub difference: f64,
}

/// `Ok` when python3 can import scikit-fem; otherwise the note saying what is missing.
pub fn available() -> Result<(), String> {
    let ok = Command::new("python3")
        .args(["-c", "import skfem, scipy"])
        .output()
        .is_ok_and(|o| o.status.success());
    if ok {
        Ok(())
    } else {
        Err("python3 with scikit-fem is not available (`pip install scikit-fem`)".into())
    }
}

/// Kirsch at zone size × `factor` (exact outer traction) solved by adit's implicit path and by
/// the peer on the same mesh; the problem file is written under `dir`.
pub fn solve(kirsch: &Scene, factor: f64, dir: &Path) -> anyhow::Result<PeerResult> {
    let mut s = scaled(kirsch, factor);
    s.solve.method = SolveMethod::Implicit;
    let exact = closed_form(&s)?;
    let mut built = setup(&s)?;
    load_outer_exactly(&mut built, |x, y| exact.stress(x, y));
    let model = &mut built.model;
    let mut solver = Solver::new(model, &s.solve, 0);
    solver.cycle.balance(model, &solver.params, false, None);
    let a = exact.radius;
    let z = &model.zones;
    let measured: Vec<usize> = (0..z.len())
        .filter(|&i| {
            let c = z.centroid(i, &model.nodes.pos);
            c[0].hypot(c[1]) <= 5.0 * a
        })
        .collect();
    let plane = |st: &adit::model::Stress| [st[0], st[1], st[3]];
    let mut problem = serde_json::json!({
        "nodes": model.nodes.pos,
        "triangles": z.nodes,
        "fixed": model.nodes.fixed,
        "force": model.nodes.force,
        "initial_stress": z.stress.iter().map(plane).collect::<Vec<_>>(),
        "young": s.materials[&s.region.material].young,
        "poisson": s.materials[&s.region.material].poisson,
        "measured": measured,
        "exact": measured.iter().map(|&i| {
            let c = z.centroid(i, &model.nodes.pos);
            exact.stress(c[0], c[1])
        }).collect::<Vec<_>>(),
    });
    let adit::implicit::Solved { solution, .. } = adit::implicit::solve(
        model,
        &mut solver.cycle,
        &solver.params,
        &s.solve,
        &mut Quiet,
    );
    anyhow::ensure!(
        solution.status == Status::Converged,
        "Kirsch ×{factor} implicit did not converge: {:?}",
        solution.status
    );
    problem["adit_stress"] =
        serde_json::json!(model.zones.stress.iter().map(plane).collect::<Vec<_>>());
    std::fs::create_dir_all(dir)?;
    let path = dir.join(format!("peer_kirsch_{factor}.json"));
    std::fs::write(&path, problem.to_string())?;
    let script = crate::repository_root().join("validation/peer/kirsch_skfem.py");
    let out = Command::new("python3").arg(&script).arg(&path).output()?;
    anyhow::ensure!(
        out.status.success(),
        "the scikit-fem peer failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let _ = std::fs::remove_file(&path);
    Ok(serde_json::from_slice(&out.stdout)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On a coarse Kirsch mesh the peer and adit's implicit path solve the same discrete
    /// problem: the same stresses to round-off. Required when `ADIT_REQUIRE_PEER=1` (as in
    /// `.ci/run`, which installs scikit-fem); otherwise skipped with a note without it.
    #[test]
    fn the_peer_and_the_implicit_path_give_the_same_stresses() {
        if let Err(note) = available() {
            let required = std::env::var("ADIT_REQUIRE_PEER").is_ok_and(|v| v == "1");
            assert!(!required, "ADIT_REQUIRE_PEER=1 but {note}");
            eprintln!("skipping the scikit-fem peer: {note}");
            return;
        }
        let kirsch = crate::shipped_kirsch().unwrap();
        let dir = std::env::temp_dir().join(format!("adit_peer_{}", std::process::id()));
        let peer = solve(&kirsch, 3.0, &dir).unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        eprintln!("{peer:?}");
        assert!(peer.difference < 1e-9, "{peer:?}");
        let adit = crate::kirsch_case::run(
            &{
                let mut s = scaled(&kirsch, 3.0);
                s.solve.method = SolveMethod::Implicit;
                s
            },
            "kirsch ×3 implicit",
            crate::kirsch_case::OuterLoad::Exact,
        )
        .unwrap();
        assert!(
            (peer.stress_l2 - adit.stress_l2).abs() < 1e-9,
            "{peer:?} {adit:?}"
        );
    }
}
