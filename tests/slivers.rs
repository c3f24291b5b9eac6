//! Slivers and tiny blocks (issue 5, case 3): joint sets a few degrees apart cut wedge blocks a few
//! millimetres thick with zones of 1° angles; tiny blocks 1000× smaller than their neighbours sit
//! between loaded blocks. Mass scaling gives every node the mass its stiffness needs, so the static
//! runs converge and no block escapes.

use adit::Scene;
use adit::solve::Quiet;

/// A w × w box on a fixed base between rollers, cut by `sets` (dip°, spacing m), under gravity and
/// `pressure` Pa on top; joints kn = 1e10 Pa/m, ks = kn/2, friction `friction`°.
fn wedges(w: f64, sets: &[(f64, f64)], friction: f64, pressure: f64, mode: &str) -> Scene {
    let sets: Vec<serde_json::Value> = sets
        .iter()
        .map(|&(dip, spacing)| {
            serde_json::json!({ "dip": dip, "spacing": spacing, "origin": [0.13, 0.07],
                                "material": "joint" })
        })
        .collect();
    let text = serde_json::json!({
        "name": "slivers",
        "materials": { "rock": { "density": 2600, "young": 10e9, "poisson": 0.25 } },
        "region": { "polygon": [[0, 0], [w, 0], [w, w], [0, w]],
                    "edge_names": ["base", "right", "top", "left"], "material": "rock" },
        "zoning": { "edge_at_excavation": 0.25, "edge_far": 0.25 },
        "joint_materials": { "joint": { "normal_stiffness": 1e10, "shear_stiffness": 5e9,
                                        "friction": friction } },
        "joint_sets": sets,
        "blocks": { "mode": mode },
        "gravity": [0, -9.81],
        "boundary": [{ "part": "base", "fix": "xy" }, { "part": "left", "fix": "x" },
                     { "part": "right", "fix": "x" }, { "part": "top", "normal_stress": -pressure }],
        "solve": { "ratio": 1e-5, "max_cycles": 200000 }
    });
    Scene::from_json(&text.to_string(), "slivers").unwrap()
}

/// Run to equilibrium; the largest displacement (m) and the thinnest zone angle (degrees).
fn settle(sc: &Scene, what: &str) -> (f64, f64, u64) {
    let dir = std::env::temp_dir().join(format!("adit_slivers_{what}"));
    let r = adit::run_scene(sc, &dir, &mut Quiet).unwrap();
    assert_eq!(
        r.summary.status, "converged",
        "{what}: {:?} after {} cycles",
        r.summary.reason, r.summary.cycles
    );
    let m = &r.built.model;
    let umax = m
        .nodes
        .disp
        .iter()
        .map(|u| u[0].hypot(u[1]))
        .fold(0.0, f64::max);
    (umax, r.summary.min_zone_angle, r.summary.cycles)
}

/// The reproducer the random scenes found: sets 3.2° apart cut wedges down to 7 mm thick with 1.1°
/// zones. Under gravity alone (10° friction holds a 3° wedge) it must settle where it stands;
/// before the damped mass margin (`damped_margin` in `src/cycle/timestep.rs`) it diverged at the
/// wedge tip within 300 cycles.
#[test]
fn sliver_wedges_settle_under_gravity() {
    for mode in ["deformable", "simple", "rigid"] {
        let sc = wedges(3.806, &[(3.246, 1.182), (0.0, 0.5)], 10.0, 0.0, mode);
        let (umax, angle, cycles) = settle(&sc, mode);
        eprintln!(
            "{mode}: max displacement {umax:.3e} m, min zone angle {angle:.2}°, {cycles} cycles"
        );
        assert!(umax < 1e-3, "{mode}: a block moved {umax} m");
    }
}

/// Sets 3–5° apart under gravity and 1 MPa: every block in equilibrium, none escaping.
#[test]
fn near_parallel_sets_under_load_settle() {
    for (a, b) in [(0.0, 3.0), (20.0, 24.0), (40.0, 45.0)] {
        let sc = wedges(3.0, &[(a, 0.6), (b, 0.9)], 30.0, 1e6, "deformable");
        let (umax, angle, cycles) = settle(&sc, &format!("{a}_{b}"));
        eprintln!(
            "{a}°/{b}°: max displacement {umax:.3e} m, min angle {angle:.2}°, {cycles} cycles"
        );
        assert!(umax < 2e-3, "{a}°/{b}°: a block moved {umax} m");
    }
}

/// Tiny blocks: triangles of 3 cm legs (4.5e-4 m²) cut where the horizontal joints meet the side
/// walls, between 1 m × 2 m blocks (2000× their area), squeezed by 1 MPa on top: they settle
/// with their neighbours, rigid or deformable.
#[test]
fn tiny_blocks_between_large_ones_settle() {
    for mode in ["deformable", "rigid"] {
        let mut joints = Vec::new();
        for y in [1.0, 2.0] {
            joints.push(serde_json::json!({ "from": [0, y], "to": [2, y], "material": "joint" }));
            joints.push(
                serde_json::json!({ "from": [0, y + 0.03], "to": [0.03, y], "material": "joint" }),
            );
            joints.push(
                serde_json::json!({ "from": [2, y - 0.03], "to": [1.97, y], "material": "joint" }),
            );
        }
        let text = serde_json::json!({
            "name": "tiny",
            "materials": { "rock": { "density": 2600, "young": 10e9, "poisson": 0.25 } },
            "region": { "polygon": [[0, 0], [2, 0], [2, 3], [0, 3]],
                        "edge_names": ["base", "right", "top", "left"], "material": "rock" },
            "zoning": { "edge_at_excavation": 0.05, "edge_far": 0.25 },
            "joint_materials": { "joint": { "normal_stiffness": 1e11, "shear_stiffness": 5e10,
                                            "friction": 30 } },
            "joints": joints,
            "blocks": { "mode": mode },
            "gravity": [0, -9.81],
            "boundary": [{ "part": "base", "fix": "xy" }, { "part": "left", "fix": "x" },
                         { "part": "right", "fix": "x" }, { "part": "top", "normal_stress": -1e6 }],
            "solve": { "ratio": 1e-5, "max_cycles": 200000 }
        });
        let sc = Scene::from_json(&text.to_string(), "tiny").unwrap();
        let built = adit::build::build(&sc).unwrap();
        let areas: Vec<f64> = (0..built.model.blocks.len())
            .map(|b| block_area(&built.model, b))
            .collect();
        let (small, large) = areas
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(s, l), &a| (s.min(a), l.max(a)));
        assert!(
            areas.len() == 7 && large / small > 1000.0,
            "{mode}: blocks {areas:?}"
        );
        let (umax, _, cycles) = settle(&sc, &format!("tiny_{mode}"));
        eprintln!(
            "{mode}: {} blocks, area ratio {:.0}, max displacement {umax:.3e} m, {cycles} cycles",
            areas.len(),
            large / small
        );
        // 1 MPa over 3 m of rock and the joints: a fraction of a millimetre.
        assert!(umax < 1e-3, "{mode}: a block moved {umax} m");
    }
}

/// Area of block `b` from its boundary edges (shoelace), m².
fn block_area(m: &adit::model::Model, b: usize) -> f64 {
    m.blocks
        .edge_range(b)
        .map(|e| {
            let [p, q] = m.blocks.edges[e].map(|n| m.nodes.pos[n as usize]);
            0.5 * (p[0] * q[1] - q[0] * p[1])
        })
        .sum::<f64>()
        .abs()
}
