//! Jointed models: blocks cut by joints interact through contacts.

use adit::Scene;
use adit::build::build;
use adit::solve::{Quiet, Solver, Status};

fn column(friction: f64) -> Scene {
    let text = format!(
        r#"{{
        "name": "column",
        "materials": {{ "rock": {{ "density": 2500, "young": 10e9, "poisson": 0.25 }} }},
        "region": {{ "polygon": [[0, 0], [1, 0], [1, 3], [0, 3]], "edge_names": ["base", "right", "top", "left"],
                    "material": "rock" }},
        "zoning": {{ "edge_at_excavation": 0.25, "edge_far": 0.25 }},
        "joint_materials": {{ "bedding": {{ "normal_stiffness": 1e11, "shear_stiffness": 1e11, "friction": {friction} }} }},
        "joint_sets": [{{ "dip": 0, "spacing": 1, "material": "bedding" }}],
        "gravity": [0, -9.81],
        "boundary": [{{ "part": "base", "fix": "xy" }}, {{ "part": "left", "fix": "x" }}, {{ "part": "right", "fix": "x" }}],
        "solve": {{ "ratio": 1e-7 }}
    }}"#
    );
    Scene::from_json(&text, "column").unwrap()
}

#[test]
fn column_of_blocks_carries_the_weight_above_each_joint() {
    let scene = column(30.0);
    let mut b = build(&scene).unwrap();
    assert_eq!(b.model.blocks.len(), 3);
    assert!(!b.model.contacts.is_empty());
    let mut solver = Solver::new(&mut b.model, &scene.solve, 0);
    let sol = solver.solve(&mut b.model, &mut Quiet);
    assert_eq!(sol.status, Status::Converged, "{:?}", sol.status);
    let c = &b.model.contacts;
    for (joint_y, depth) in [(1.0, 2.0), (2.0, 1.0)] {
        let weight = 2500.0 * 9.81 * depth;
        let (mut force, mut length) = (0.0, 0.0);
        for k in 0..c.len() {
            let y = b.model.nodes.pos[c.node[k] as usize][1];
            if (y - joint_y).abs() < 1e-9 {
                force += c.state[k].normal * c.length[k];
                length += c.length[k];
            }
        }
        assert!(
            (length - 1.0).abs() < 1e-9,
            "contacts at y = {joint_y} cover {length} m"
        );
        let err = (-force - weight).abs() / weight;
        eprintln!(
            "joint at y = {joint_y}: normal force {force:.1} N/m, weight above {weight:.1} N/m, error {err:.2e}"
        );
        assert!(err < 0.02, "error {err}");
    }
}
