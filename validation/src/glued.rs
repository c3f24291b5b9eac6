//! Glued-joint consistency: the Kirsch problem with the domain cut by two joint sets whose joints
//! are glued (`law: glued`: springs that never slip or open) must reproduce the intact solution as the joint
//! stiffness grows. Reported against the joint normal stiffness.

use adit::Scene;
use adit::scene::{JointLawKind, JointMaterial, JointSetSpec, SolveMethod};

use crate::kirsch_case::{KirschResult, OuterLoad, run};

/// The shipped Kirsch scene cut by two glued joint sets of normal (and shear) stiffness `k`, Pa/m.
pub fn glued_scene(kirsch: &Scene, k: f64) -> Scene {
    let mut s = kirsch.clone();
    s.name = "kirsch_glued".into();
    s.joint_materials.insert(
        "glued".into(),
        JointMaterial {
            normal_stiffness: k,
            shear_stiffness: k,
            friction: 45.0,
            cohesion: 0.0,
            residual_cohesion: 0.0,
            tensile_strength: 0.0,
            dilation: 0.0,
            law: JointLawKind::Glued,
            initial_friction: None,
            roughness: None,
            jrc: None,
            jcs: None,
            max_closure: None,
            max_normal_stiffness: None,
            sample_length: None,
            block_size: None,
            dilation_divisor: None,
        },
    );
    let set = |dip: f64, spacing: f64, origin: [f64; 2]| JointSetSpec {
        dip,
        spacing,
        origin,
        trace: None,
        gap: 0.0,
        spread_dip: 0.0,
        spread_spacing: 0.0,
        seed: 1,
        scatter: None,
        material: "glued".into(),
    };
    s.joint_sets = vec![set(30.0, 4.0, [0.3, 0.2]), set(120.0, 5.0, [0.1, -0.4])];
    s
}

/// Run the glued Kirsch case at normal stiffness `k` (Pa/m).
pub fn run_glued(kirsch: &Scene, k: f64) -> anyhow::Result<KirschResult> {
    run_glued_by(kirsch, k, SolveMethod::Explicit)
}

/// [`run_glued`] solved by `method` (`solve.method`); the row's case names it.
pub fn run_glued_by(kirsch: &Scene, k: f64, method: SolveMethod) -> anyhow::Result<KirschResult> {
    let mut s = glued_scene(kirsch, k);
    s.solve.method = method;
    run(
        &s,
        &format!(
            "kirsch, glued joints, kn = {k:.0e} Pa/m{}",
            crate::method_suffix(method)
        ),
        OuterLoad::Scene,
    )
}

/// The glued Kirsch scene with Coulomb joints instead (friction `friction` degrees, no cohesion):
/// joints near the hole slip, so the answer departs from Kirsch's; solved by `method`.
pub fn run_coulomb_by(
    kirsch: &Scene,
    k: f64,
    friction: f64,
    method: SolveMethod,
) -> anyhow::Result<KirschResult> {
    let mut s = glued_scene(kirsch, k);
    let m = s
        .joint_materials
        .get_mut("glued")
        .expect("the glued material");
    m.law = JointLawKind::Coulomb;
    m.friction = friction;
    s.solve.method = method;
    run(
        &s,
        &format!(
            "kirsch, Coulomb joints φ = {friction}°, kn = {k:.0e} Pa/m{}",
            crate::method_suffix(method)
        ),
        OuterLoad::Scene,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kirsch_case::scaled;

    /// Coarse twin: twice the shipped zone size, kn = 1e11 Pa/m.
    #[test]
    fn glued_joints_reproduce_the_intact_kirsch_solution() {
        let kirsch = crate::shipped_kirsch().unwrap();
        let r = run_glued(&scaled(&kirsch, 2.0), 1e11).unwrap();
        eprintln!("{r:?}");
        assert_eq!(r.status, "converged");
        assert!(r.stress_l2 < 0.05, "stress L2 {}", r.stress_l2);
        assert!(
            r.wall_displacement < 0.10,
            "wall displacement {}",
            r.wall_displacement
        );
        // Implicitly, glued and Coulomb (φ = 30°: slipping near the hole) joints meet the same
        // bounds as the explicit answer.
        let i = run_glued_by(&scaled(&kirsch, 2.0), 1e11, SolveMethod::Implicit).unwrap();
        let c = run_coulomb_by(&scaled(&kirsch, 2.0), 1e11, 30.0, SolveMethod::Implicit).unwrap();
        for r in [i, c] {
            assert_eq!(r.status, "converged", "{r:?}");
            assert!(r.stress_l2 < 0.05 && r.wall_displacement < 0.10, "{r:?}");
        }
    }
}
