//! Tests of building: geometry errors name their field, tractions balance.

use super::*;

fn scene_with(region: &str, excavation: &str) -> Scene {
    let text = format!(
        r#"{{ "name": "t", "materials": {{ "rock": {{ "density": 2500, "young": 1e9, "poisson": 0.2 }} }},
                "region": {{ "polygon": {region}, "material": "rock" }},
                "excavations": [{excavation}],
                "zoning": {{ "edge_at_excavation": 0.5, "edge_far": 2 }} }}"#
    );
    Scene::from_json(&text, "test").unwrap()
}

#[test]
fn self_intersecting_region_names_the_field() {
    let s = scene_with("[[0, 0], [10, 10], [10, 0], [0, 10]]", "");
    let msg = setup(&s).err().unwrap().to_string();
    assert!(
        msg.starts_with("region.polygon:") && msg.contains("self-intersecting"),
        "{msg}"
    );
}

#[test]
fn hole_outside_region_names_the_excavation() {
    let s = scene_with(
        "[[0, 0], [10, 0], [10, 10], [0, 10]]",
        r#"{ "name": "adit", "circle": { "center": [20, 5], "radius": 1 } }"#,
    );
    let msg = setup(&s).err().unwrap().to_string();
    assert!(
        msg.starts_with("excavations[0]:") && msg.contains("not inside the region"),
        "{msg}"
    );
}

#[test]
fn tractions_of_a_uniform_stress_balance_on_a_closed_boundary() {
    let mut s = scene_with(
        "[[0, 0], [10, 0], [10, 10], [0, 10]]",
        r#"{ "name": "adit", "circle": { "center": [4, 5], "radius": 1 } }"#,
    );
    s.boundary = serde_json::from_str(
        r#"[{ "part": "outer", "stress": { "sxx": -1e6, "syy": -2e6, "sxy": 5e5 } }]"#,
    )
    .unwrap();
    let b = setup(&s).unwrap();
    let (mut fx, mut fy, mut m) = (0.0, 0.0, 0.0);
    for (p, f) in b.model.nodes.pos.iter().zip(&b.model.nodes.applied) {
        fx += f[0];
        fy += f[1];
        m += p[0] * f[1] - p[1] * f[0];
    }
    assert!(
        fx.abs() < 1e-6 && fy.abs() < 1e-6 && m.abs() < 1e-5,
        "{fx} {fy} {m}"
    );
    // The traction on the top edge (n = +y) is (σxy, σyy) over 10 m; its corner nodes also carry
    // half of the first segment of each side edge, whose traction's y part is σxy·nx
    // (nx = +1 on the right edge, −1 on the left).
    let pos = &b.model.nodes.pos;
    let nodes = |part: &str| b.plan.boundary.part_nodes[part].clone();
    let first_segment = |part: &str, corner: [f64; 2]| {
        nodes(part)
            .iter()
            .map(|&n| pos[n as usize])
            .map(|p| (p[0] - corner[0]).hypot(p[1] - corner[1]))
            .filter(|&d| d > 1e-9)
            .fold(f64::INFINITY, f64::min)
    };
    let (right, left) = (
        first_segment("edge1", [10.0, 10.0]),
        first_segment("edge3", [0.0, 10.0]),
    );
    let top: f64 = nodes("edge2")
        .iter()
        .map(|&n| b.model.nodes.applied[n as usize][1])
        .sum();
    let expected = -2e6 * 10.0 + 5e5 * (right - left) / 2.0;
    assert!((top - expected).abs() < 1e-9 * 2e7, "{top} {expected}");
}

#[test]
fn horseshoe_excavation_has_its_area() {
    let s = scene_with(
        "[[-10, -10], [10, -10], [10, 10], [-10, 10]]",
        r#"{ "name": "drive", "horseshoe": { "center": [0, 0], "radius": 3, "wall_height": 2, "segments": 256 } }"#,
    );
    let b = setup(&s).unwrap();
    let hole = b.plan.boundary.domain.holes[0].polygon.signed_area().abs();
    let exact = 0.5 * std::f64::consts::PI * 9.0 + 6.0 * 2.0;
    assert!((hole - exact).abs() < 1e-3 * exact, "{hole} vs {exact}");
    assert!((b.mesh.area - (400.0 - hole)).abs() < 1e-6 * 400.0);
}

/// Non-persistent joints leave clusters of blocks floating inside a large block, as holes some
/// of which touch each other or its outer ring at a vertex; the zones must still cover the region.
#[test]
fn non_persistent_joints_leave_no_area_unzoned() {
    let text = r#"{ "name": "t", "materials": { "rock": { "density": 2500, "young": 1e9, "poisson": 0.2 } },
        "region": { "polygon": [[-40, -40], [40, -40], [40, 40], [-40, 40]], "material": "rock" },
        "zoning": { "edge_at_excavation": 0.25, "edge_far": 4.0, "grading": 0.25, "min_angle": 28 },
        "joint_materials": { "j": { "normal_stiffness": 1e10, "shear_stiffness": 1e10 } },
        "joint_sets": [
            { "dip": 30, "spacing": 2.5, "origin": [0.4, 0.3], "trace": 12, "gap": 3, "material": "j" },
            { "dip": 105, "spacing": 3.0, "origin": [-0.2, 0.5], "trace": 10, "gap": 4, "material": "j" } ] }"#;
    let s = Scene::from_json(text, "test").unwrap();
    let m = mesh(&s).unwrap();
    assert!(m.blocking.blocks.iter().any(|b| b.holes.len() > 5));
    let zoned = m.stats().area;
    assert!((zoned - 6400.0).abs() < 1e-6 * 6400.0, "{zoned}");
}

/// A joint 0.2 m from the region's edge cuts a strip thinner than half the finest zone (0.5 m):
/// it is named in a warning and zoned by default, and `blocks.thin` makes it rigid or simple.
#[test]
fn a_strip_too_thin_to_zone_is_named_and_takes_blocks_thin() {
    let strip = |thin: &str| {
        let text = format!(
            r#"{{ "name": "t", "materials": {{ "rock": {{ "density": 2500, "young": 1e9, "poisson": 0.2 }} }},
                "region": {{ "polygon": [[0, 0], [10, 0], [10, 10], [0, 10]], "material": "rock" }},
                "joint_materials": {{ "j": {{ "normal_stiffness": 1e10, "shear_stiffness": 5e9, "friction": 30 }} }},
                "joints": [{{ "from": [9.8, -1], "to": [9.8, 11], "material": "j" }}],
                "zoning": {{ "edge_at_excavation": 0.5, "edge_far": 2 }},
                "blocks": {{ "thin": "{thin}" }} }}"#
        );
        setup(&Scene::from_json(&text, "test").unwrap()).unwrap()
    };
    for (thin, bodies, said) in [
        ("deformable", 0, "zoned as finely as it needs"),
        ("rigid", 1, "made rigid (blocks.thin)"),
        ("simple", 1, "made simple (blocks.thin)"),
    ] {
        let b = strip(thin);
        let warned: Vec<&String> = b.warnings.iter().filter(|w| w.contains("thick")).collect();
        assert_eq!(warned.len(), 1, "{:?}", b.warnings);
        assert!(
            warned[0].contains("1.961e-1 m thick") && warned[0].contains(said),
            "{}",
            warned[0]
        );
        assert_eq!(b.model.bodies.len(), bodies, "{thin}");
    }
}

/// The builder takes the typed forms of the scene's choices: a scene that skipped validation gets
/// an error naming the field where a validated one could not go wrong, never a panic.
#[test]
fn an_unvalidated_scene_is_refused_by_field_not_by_panic() {
    let base = |excavation: &str, material: &str| {
        format!(
            r#"{{ "name": "t", "materials": {{ "rock": {{ "density": 2500, "young": 1e9, "poisson": 0.2 {material} }} }},
                "region": {{ "polygon": [[0, 0], [10, 0], [10, 10], [0, 10]], "material": "rock" }},
                "excavations": [{excavation}],
                "zoning": {{ "edge_at_excavation": 0.5, "edge_far": 2 }} }}"#
        )
    };
    let unchecked = |text: &str| serde_json::from_str::<Scene>(text).unwrap();
    let no_shape = unchecked(&base(r#"{ "name": "adit" }"#, ""));
    let msg = setup(&no_shape).err().unwrap().to_string();
    assert!(msg.starts_with("excavations[0]: give exactly one"), "{msg}");
    let half_law = unchecked(&base("", r#", "law": "mohr_coulomb""#));
    let msg = setup(&half_law).err().unwrap().to_string();
    assert!(msg.starts_with("materials.rock: "), "{msg}");
}

/// Gravity against the in-situ stress: its gradient balanced (ρ g, and within 1 %), no warning;
/// of the wrong sign, or a uniform stress under gravity, a warning naming
/// `in_situ.gradient.syy`; an unstressed start (gravity building the stress), none.
#[test]
fn an_in_situ_stress_that_does_not_balance_gravity_is_named() {
    let warned = |syy: f64, gradient: f64| {
        let mut s = scene_with("[[0, 0], [10, 0], [10, 10], [0, 10]]", "");
        s.gravity = [0.0, -9.81];
        s.in_situ.syy = syy;
        s.in_situ.gradient.syy = gradient;
        let built = setup(&s).unwrap();
        (built.warnings.iter()).any(|w| w.starts_with("in_situ.gradient.syy"))
    };
    let rho_g = 2500.0 * 9.81;
    assert!(!warned(0.0, rho_g) && !warned(-1e6, 1.005 * rho_g) && !warned(0.0, 0.0));
    assert!(warned(0.0, -rho_g) && warned(-1e6, 0.0) && warned(-1e6, 1.02 * rho_g));
}
