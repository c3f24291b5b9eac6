//! The implicit path (issue 17): a sparse direct solve reaches the explicit path's equilibrium.

use crate::common;

use adit::Scene;
use adit::solve::Quiet;

fn model_scene(file: &str) -> Scene {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(file);
    Scene::load(&path).unwrap()
}

fn run(sc: &Scene, folder: &str) -> adit::RunResult {
    try_run(sc, folder).unwrap()
}

/// `run`, its error returned.
fn try_run(sc: &Scene, folder: &str) -> anyhow::Result<adit::RunResult> {
    let out = std::env::temp_dir().join(folder);
    let _ = std::fs::remove_dir_all(&out);
    adit::run_scene(sc, &out, &mut Quiet)
}

/// Relative L2 difference of two runs' zone stresses (in-plane components).
fn stress_difference(a: &adit::RunResult, b: &adit::RunResult) -> f64 {
    let (sa, sb) = (&a.built.model.zones.stress, &b.built.model.zones.stress);
    let (mut num, mut den) = (0.0, 0.0);
    for (x, y) in sa.iter().zip(sb) {
        for c in [0, 1, 3] {
            num += (x[c] - y[c]).powi(2);
            den += y[c].powi(2);
        }
    }
    (num / den).sqrt()
}

/// The shipped Kirsch model solved implicitly: one iteration to round-off, and the explicit
/// solution to within its own unbalanced-force tolerance.
#[test]
fn implicit_kirsch_equals_the_explicit_solution() {
    let explicit = model_scene("models/kirsch.json");
    let mut implicit = explicit.clone();
    implicit.solve.method = adit::scene::SolveMethod::Implicit;
    let e = run(&explicit, "adit-test-kirsch-explicit");
    let i = run(&implicit, "adit-test-kirsch-implicit");
    assert_eq!(i.summary.status, "converged");
    let cost = i.summary.implicit.expect("an implicit solve ran");
    assert_eq!((cost.factorizations, cost.iterations), (1, 1));
    assert!(
        i.summary.final_ratio.unwrap() < 1e-12,
        "{:?}",
        i.summary.final_ratio
    );
    let d = stress_difference(&i, &e);
    println!("stress difference implicit vs explicit: {d:.3e}");
    assert!(d < 2e-4, "{d}");
}

/// Salençon's problem: a hole of 1 m in Mohr–Coulomb rock (c = 5 MPa, φ = 30°) under 30 MPa.
const MC_HOLE: &str = r#"{
    "name": "mc_hole",
    "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.25,
                              "law": "mohr_coulomb", "cohesion": 5e6, "friction": 30 } },
    "region": { "polygon": [[-15, -15], [15, -15], [15, 15], [-15, 15]], "material": "rock" },
    "excavations": [{ "name": "hole", "circle": { "center": [0, 0], "radius": 1, "segments": 64 } }],
    "zoning": { "edge_at_excavation": 0.1, "edge_far": 2.0, "grading": 0.25 },
    "in_situ": { "sxx": -30e6, "syy": -30e6 },
    "boundary": [ { "part": "outer", "in_situ_traction": true },
                  { "at": [15, 0], "fix": "y" }, { "at": [-15, 0], "fix": "y" },
                  { "at": [0, 15], "fix": "x" }, { "at": [0, -15], "fix": "x" } ],
    "solve": { "ratio": 1e-6, "max_cycles": 200000 }
}"#;

/// Zones that have yielded.
fn yielded(r: &adit::RunResult) -> usize {
    r.built
        .model
        .zones
        .state
        .iter()
        .filter(|&&s| s != 0)
        .count()
}

/// Mean inward radial displacement of the `wall` nodes around the origin, m.
fn closure(r: &adit::RunResult, wall: &[u32]) -> f64 {
    let m = &r.built.model;
    wall.iter()
        .map(|&n| {
            let (p, u) = (m.nodes.pos[n as usize], m.nodes.disp[n as usize]);
            -(p[0] * u[0] + p[1] * u[1]) / p[0].hypot(p[1])
        })
        .sum::<f64>()
        / wall.len() as f64
}

/// A hole in Mohr–Coulomb rock (Salençon's problem, c = 5 MPa, φ = 30°, p0 = 30 MPa): the
/// implicit path iterates with the initial stiffness and reaches the explicit answer: the same
/// yielded zones within 1 %, the same wall closure within 0.5 %.
#[test]
fn implicit_plastic_hole_matches_explicit() {
    let explicit = Scene::from_json(MC_HOLE, "mc_hole").unwrap();
    let mut implicit = explicit.clone();
    implicit.solve.method = adit::scene::SolveMethod::Implicit;
    let e = run(&explicit, "adit-test-mc-explicit");
    let i = run(&implicit, "adit-test-mc-implicit");
    assert_eq!(i.summary.status, "converged", "{:?}", i.summary.reason);
    let wall = &i.built.plan.boundary.part_nodes["hole"];
    let closure = |r: &adit::RunResult| closure(r, wall);
    let cost = i.summary.implicit.unwrap();
    println!(
        "yielded {} / {}, closure {:.4e} / {:.4e} m, explicit {} cycles {:.2} s, implicit {} iterations {:.2} s",
        yielded(&i),
        yielded(&e),
        closure(&i),
        closure(&e),
        e.summary.cycles,
        e.summary.wall_seconds,
        cost.iterations,
        i.summary.wall_seconds
    );
    let (yi, ye) = (yielded(&i) as f64, yielded(&e) as f64);
    assert!((yi - ye).abs() <= 0.01 * ye, "{yi} {ye}");
    assert!((closure(&i) / closure(&e) - 1.0).abs() < 0.005);
}

/// A load step that does not converge within `max_iterations` is halved from the last commit
/// until its steps do: the hole in Mohr–Coulomb rock, solved with at most 24 iterations a step
/// (released at once it takes 35), converges after halving, reports its cuts, and keeps the
/// explicit answer: the zones' trial is from the commit, so the cuts leave the answer alone
/// (measured after 4 cuts: closure −0.01 %, 336 zones yielded against 338; asserted at 1 %;
/// integrated along the iterations' path it was +2.0 % and +2.4 % after 3 cuts).
#[test]
fn a_step_that_does_not_converge_is_cut() {
    let mut explicit = Scene::from_json(MC_HOLE, "mc_hole").unwrap();
    // On the zoning as written, whose step and cuts were measured (refined through its plastic
    // zone, the default, the step takes more iterations than its cuts leave it).
    explicit.zoning.plastic_depth = adit::scene::PlasticDepth::OFF;
    let mut implicit = explicit.clone();
    implicit.solve.method = adit::scene::SolveMethod::Implicit;
    implicit.solve.max_iterations = 24;
    let e = run(&explicit, "adit-test-cut-explicit");
    let i = run(&implicit, "adit-test-cut-implicit");
    assert_eq!(i.summary.status, "converged", "{:?}", i.summary.reason);
    let cost = i.summary.implicit.unwrap();
    println!("{cost:?}");
    assert!(cost.cuts >= 1, "{cost:?}");
    let wall = &i.built.plan.boundary.part_nodes["hole"];
    let (ci, ce) = (closure(&i, wall), closure(&e, wall));
    assert!((ci / ce - 1.0).abs() < 0.01, "{ci} {ce}");
    let (yi, ye) = (yielded(&i) as f64, yielded(&e) as f64);
    assert!((yi - ye).abs() <= 0.01 * ye, "{yi} {ye}");
}

/// Two blocks across a horizontal glued joint under 1 MPa: `implicit` carries the load through
/// the contacts as the explicit path does, in deformable, rigid and simple blocks; `auto` takes
/// the implicit path; the large-strain update and the continuously yielding joint are refused by
/// `implicit`, naming the field and the reason, and `auto` cycles the latter explicitly, saying
/// why.
#[test]
fn implicit_contacts_and_what_it_refuses() {
    let text = |method: &str, mode: &str, law: &str| {
        format!(
            r#"{{
        "name": "two_blocks",
        "materials": {{ "rock": {{ "density": 2500, "young": 10e9, "poisson": 0.25 }} }},
        "joint_materials": {{ "j": {{ "normal_stiffness": 1e11, "shear_stiffness": 1e11, "law": "{law}" }} }},
        "region": {{ "polygon": [[0, 0], [2, 0], [2, 2], [0, 2]], "material": "rock",
                     "edge_names": ["bottom", "right", "top", "left"] }},
        "joints": [{{ "from": [-1, 1], "to": [3, 1], "material": "j" }}],
        "blocks": {{ "mode": "{mode}" }},
        "zoning": {{ "edge_at_excavation": 0.25, "edge_far": 0.25 }},
        "boundary": [ {{ "part": "bottom", "fix": "xy" }}, {{ "part": "top", "normal_stress": -1e6 }} ],
        "solve": {{ "method": "{method}", "ratio": 1e-7, "max_cycles": 100000 }}
    }}"#
        )
    };
    let scene =
        |method, mode, law| Scene::from_json(&text(method, mode, law), "two_blocks").unwrap();
    let i = run(
        &scene("implicit", "deformable", "glued"),
        "adit-test-implicit-contacts",
    );
    let e = run(
        &scene("explicit", "deformable", "glued"),
        "adit-test-explicit-contacts",
    );
    assert_eq!(i.summary.status, "converged", "{:?}", i.summary.reason);
    let d = stress_difference(&i, &e);
    let cost = i.summary.implicit.unwrap();
    println!(
        "two blocks: {} iterations, stress difference {d:.2e}",
        cost.iterations
    );
    assert!(d < 1e-4, "{d}");
    // A Coulomb joint (φ = 30°) converges too; its answer may differ where the explicit path's
    // relaxation slipped the joint's ends on its way (friction remembers the path).
    let c = run(
        &scene("implicit", "deformable", "coulomb"),
        "adit-test-implicit-coulomb",
    );
    assert_eq!(c.summary.status, "converged", "{:?}", c.summary.reason);
    let a = run(
        &scene("auto", "deformable", "coulomb"),
        "adit-test-implicit-auto",
    );
    assert_eq!(a.summary.methods, ["implicit"]);
    assert_eq!(a.summary.status, "converged");
    // Rigid and simple blocks: their generalised displacements are the unknowns; the glued
    // (linear) joint gives the explicit settlement to the solve's tolerance.
    let settlement = |r: &adit::RunResult| {
        let m = &r.built.model;
        m.nodes.disp.iter().map(|u| u[1]).fold(0.0f64, f64::min)
    };
    for mode in ["rigid", "simple"] {
        let i = run(
            &scene("implicit", mode, "glued"),
            "adit-test-implicit-bodies",
        );
        let e = run(
            &scene("explicit", mode, "glued"),
            "adit-test-explicit-bodies",
        );
        assert_eq!(i.summary.status, "converged", "{:?}", i.summary.reason);
        let (si, se) = (settlement(&i), settlement(&e));
        assert!(
            se < 0.0 && (si / se - 1.0).abs() < 1e-3,
            "{mode}: {si} {se}"
        );
    }
    let out = std::env::temp_dir().join("adit-test-implicit-refused");
    let large = text("implicit", "deformable", "glued").replace(
        r#""method": "implicit","#,
        r#""method": "implicit", "large_strain": true,"#,
    );
    let msg = adit::run_scene(
        &Scene::from_json(&large, "two_blocks").unwrap(),
        &out,
        &mut Quiet,
    )
    .err()
    .unwrap()
    .to_string();
    assert!(
        msg.starts_with("solve.method: implicit cannot solve this model: the large-strain"),
        "{msg}"
    );
    // The continuously yielding joint is refused by `implicit`, and `auto` cycles it explicitly.
    let yielding = |method: &str| {
        let t = text(method, "deformable", "continuously_yielding").replace(
            r#""law": "continuously_yielding""#,
            r#""law": "continuously_yielding", "friction": 30, "roughness": 1e-3"#,
        );
        Scene::from_json(&t, "two_blocks").unwrap()
    };
    // A folder of its own: a child process that another test forks while the run above holds
    // its folder's lock shares that lock until it execs, so a second run in the same folder at
    // once can find it held.
    let out = std::env::temp_dir().join(format!(
        "adit-test-implicit-refused-cy-{}",
        std::process::id()
    ));
    let msg = adit::run_scene(&yielding("implicit"), &out, &mut Quiet)
        .err()
        .unwrap()
        .to_string();
    assert!(
        msg.starts_with(
            "solve.method: implicit cannot solve this model: the continuously yielding joint law"
        ),
        "{msg}"
    );
    let a = run(&yielding("auto"), "adit-test-implicit-auto-yielding");
    assert!(
        a.summary.methods[0].starts_with("explicit (the continuously yielding joint law"),
        "{:?}",
        a.summary.methods
    );
    assert_eq!(a.summary.status, "converged", "{:?}", a.summary.reason);
}

/// `implicit` asks for static equilibrium: a dynamic solve with it is refused naming the field.
#[test]
fn implicit_dynamic_is_refused() {
    let mut text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/kirsch.json"),
    )
    .unwrap();
    text = text.replacen(
        "\"solve\": {",
        "\"solve\": { \"method\": \"implicit\", \"mode\": \"dynamic\",",
        1,
    );
    let msg = Scene::from_json(&text, "kirsch").unwrap_err().to_string();
    assert!(
        msg.starts_with("solve.method: an implicit solve finds static equilibrium"),
        "{msg}"
    );
}

/// A staged excavation (a tunnel filled with rock glued to its walls, excavated with half the
/// in-situ traction left, then released): the implicit path gives the explicit path's closures,
/// one iteration per stage (none in the in-situ stage, which starts at rest).
#[test]
fn implicit_stages_give_the_explicit_closures() {
    let explicit = Scene::from_json(common::STAGED_TUNNEL, "staged").unwrap();
    let mut implicit = explicit.clone();
    implicit.solve.method = adit::scene::SolveMethod::Implicit;
    let e = run(&explicit, "adit-test-staged-explicit");
    let i = run(&implicit, "adit-test-staged-implicit");
    for (a, b) in i.summary.stages.iter().zip(&e.summary.stages) {
        assert_eq!(a.status, "converged", "{}", a.name);
        // In its in-situ stress the filled tunnel starts at rest: no iteration.
        let iterations = if a.name == "in-situ" { 0 } else { 1 };
        assert_eq!(a.cycles, iterations, "{}", a.name);
        for (name, c) in &a.closure {
            assert!(
                (c / b.closure[name] - 1.0).abs() < 1e-3,
                "{}: {c} {}",
                a.name,
                b.closure[name]
            );
        }
    }
}

/// A block nothing holds (no fixed node, no contact) is a mechanism: the implicit stage stops
/// naming it before factorizing, instead of reporting a singular matrix or a convergence.
#[test]
fn implicit_names_a_block_nothing_holds() {
    let text = r#"{
        "name": "loose",
        "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.25 } },
        "region": { "polygon": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "rock" },
        "zoning": { "edge_at_excavation": 0.5, "edge_far": 0.5 },
        "boundary": [ { "part": "outer", "normal_stress": -1e6 } ],
        "solve": { "method": "implicit" }
    }"#;
    let r = run(
        &Scene::from_json(text, "loose").unwrap(),
        "adit-test-implicit-loose",
    );
    assert_eq!(r.summary.status, "failed");
    let reason = r.summary.reason.unwrap();
    assert!(
        reason.contains("1 block(s) held by nothing") && reason.contains("(block 0)"),
        "{reason}"
    );
}

/// A later stage asking the implicit path of what it cannot solve (the large-strain update) is refused
/// before the first stage solves: no output step is written.
#[test]
fn a_later_implicit_stage_is_refused_before_any_solve() {
    let text = r#"{
        "name": "staged_rigid",
        "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.25 } },
        "joint_materials": { "j": { "normal_stiffness": 1e11, "shear_stiffness": 1e11 } },
        "region": { "polygon": [[0, 0], [2, 0], [2, 2], [0, 2]], "material": "rock",
                     "edge_names": ["bottom", "right", "top", "left"] },
        "joints": [{ "from": [-1, 1], "to": [3, 1], "material": "j" }],
        "zoning": { "edge_at_excavation": 0.5, "edge_far": 0.5 },
        "boundary": [ { "part": "bottom", "fix": "xy" }, { "part": "top", "normal_stress": -1e6 } ],
        "solve": { "max_cycles": 2000 },
        "stages": [ { "name": "settle" },
                    { "name": "again", "solve": { "method": "implicit", "large_strain": true } } ]
    }"#;
    let out = std::env::temp_dir().join("adit-test-implicit-later-stage");
    let _ = std::fs::remove_dir_all(&out);
    let sc = Scene::from_json(text, "staged_rigid").unwrap();
    let msg = adit::run_scene(&sc, &out, &mut Quiet)
        .err()
        .unwrap()
        .to_string();
    assert!(
        msg.starts_with("stages[1].solve.method (or the scene's solve.method): implicit cannot"),
        "{msg}"
    );
    assert!(!out.join("staged_rigid_zones_0000.vtu").exists());
}

/// A block sliding on a joint flatter than its friction holds (18.4° against φ = 10°): the
/// implicit path never converges on it and, when its iterations run out (at 50, 60, 80 or 100),
/// names the block that keeps moving instead of ending at the iteration limit. Its correction
/// swings by up to 5× from one iteration to the next; compared one iteration against one other,
/// the base it pushes was named at 60 and the slider at 80 (`implicit::moving::SPAN`). At
/// φ = 30° the same block holds and the solve converges.
#[test]
fn implicit_names_a_sliding_block() {
    let text = r#"{
        "name": "slide",
        "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.25 } },
        "joint_materials": { "j": { "normal_stiffness": 1e10, "shear_stiffness": 5e9,
                                    "friction": 10 } },
        "region": { "polygon": [[0, 0], [4, 0], [4, 3], [0, 3]], "material": "rock",
                     "edge_names": ["bottom", "right", "top", "left"] },
        "joints": [{ "from": [-1, 0.5], "to": [5, 2.5], "material": "j" }],
        "zoning": { "edge_at_excavation": 0.5, "edge_far": 0.5 },
        "gravity": [0, -9.81],
        "boundary": [ { "part": "bottom", "fix": "xy" } ],
        "solve": { "method": "implicit", "max_iterations": 60 }
    }"#;
    for limit in [50, 60, 80, 100] {
        let text = text.replace(
            r#""max_iterations": 60"#,
            &format!(r#""max_iterations": {limit}"#),
        );
        let r = run(
            &Scene::from_json(&text, "slide").unwrap(),
            "adit-test-implicit-slide",
        );
        assert_eq!(r.summary.status, "failed", "{limit}");
        let reason = r.summary.reason.unwrap();
        let m = &r.built.model;
        let top = (0..m.nodes.len())
            .max_by(|&a, &b| m.nodes.pos[a][1].total_cmp(&m.nodes.pos[b][1]))
            .unwrap();
        let sliding = m.blocks.block_of_node(top as u32);
        assert!(
            reason.contains("1 block(s) still move")
                && reason.contains(&format!("(block {sliding} ")),
            "{limit}: {reason}"
        );
    }
    let held = run(
        &Scene::from_json(
            &text.replace(r#""friction": 10"#, r#""friction": 30"#),
            "hold",
        )
        .unwrap(),
        "adit-test-implicit-hold",
    );
    assert_eq!(held.summary.status, "converged");
    // `auto` hands the sliding block over to explicit cycling, saying why.
    let auto = run(
        &Scene::from_json(
            &text.replace(
                r#""method": "implicit""#,
                r#""method": "auto", "max_cycles": 3000"#,
            ),
            "slide_auto",
        )
        .unwrap(),
        "adit-test-implicit-slide-auto",
    );
    let said = &auto.summary.methods[0];
    assert!(
        said.starts_with("implicit, then explicit (implicit: after 60 iterations 1 block(s)"),
        "{said}"
    );
    assert_eq!(auto.summary.cycles, 60 + 3000, "{:?}", auto.summary.status);
    assert!(auto.summary.implicit.is_some());
}

/// The patch test solved implicitly: a graded, irregular mesh of a square loaded from zero stress
/// by the traction of a uniform stress on its whole boundary (two points fixed against rigid
/// motion) takes that stress in every zone, to round-off, in one iteration.
#[test]
fn implicit_passes_the_patch_test() {
    let text = r#"{
        "name": "patch",
        "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.3 } },
        "region": { "polygon": [[0, 0], [2, 0], [2.3, 1.7], [-0.2, 2]], "material": "rock" },
        "excavations": [ { "name": "pocket", "circle": { "center": [1, 1], "radius": 0.2 } } ],
        "zoning": { "edge_at_excavation": 0.05, "edge_far": 0.4, "grading": 0.3 },
        "boundary": [ { "part": "outer", "stress": { "sxx": -1e6, "syy": -2e6, "sxy": 5e5 } },
                      { "part": "pocket", "stress": { "sxx": -1e6, "syy": -2e6, "sxy": 5e5 } },
                      { "at": [0, 0], "fix": "xy" }, { "at": [2, 0], "fix": "y" } ],
        "solve": { "method": "implicit", "ratio": 1e-12 }
    }"#;
    let r = run(
        &Scene::from_json(text, "patch").unwrap(),
        "adit-test-implicit-patch",
    );
    assert_eq!(r.summary.status, "converged");
    assert_eq!(r.summary.implicit.unwrap().iterations, 1);
    let worst = r
        .built
        .model
        .zones
        .stress
        .iter()
        .map(|s| {
            [(s[0], -1e6), (s[1], -2e6), (s[3], 5e5)]
                .iter()
                .map(|(got, want)| (got - want).abs())
                .fold(0.0, f64::max)
        })
        .fold(0.0, f64::max);
    println!("largest stress error {worst:.3e} Pa");
    assert!(worst < 1e-8 * 2e6, "largest stress error {worst} Pa");
}

/// The observer (the CLI's progress bar) hears of each factorization, with the factor's size
/// and the time it took, as many times as `summary.json` counts.
#[test]
fn each_factorization_is_reported_to_the_observer() {
    struct Heard(Vec<(usize, f64)>);
    impl adit::solve::Observer for Heard {
        fn factorized(&mut self, bytes: usize, seconds: f64) {
            self.0.push((bytes, seconds));
        }
    }
    let mut sc = model_scene("models/kirsch.json");
    sc.solve.method = adit::scene::SolveMethod::Implicit;
    let out = std::env::temp_dir().join("adit-test-implicit-heard");
    let _ = std::fs::remove_dir_all(&out);
    let mut heard = Heard(Vec::new());
    let r = adit::run_scene(&sc, &out, &mut heard).unwrap();
    let cost = r.summary.implicit.unwrap();
    assert_eq!(heard.0.len() as u64, cost.factorizations);
    assert!(
        heard
            .0
            .iter()
            .all(|&(b, s)| b == 8 * cost.factor_nonzeros && s > 0.0)
    );
}

/// `auto` hands over to explicit cycling only from a state it can go on from: when the monitor
/// stops the implicit iterations (here a runaway: a soft square squashed by five times its
/// modulus), the stage fails as it is, naming the cause.
#[test]
fn auto_does_not_hand_over_a_runaway() {
    let text = r#"{
        "name": "squash",
        "materials": { "rock": { "density": 2500, "young": 1e6, "poisson": 0.25 } },
        "region": { "polygon": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "rock",
                     "edge_names": ["bottom", "right", "top", "left"] },
        "zoning": { "edge_at_excavation": 0.25, "edge_far": 0.25 },
        "boundary": [ { "part": "bottom", "fix": "xy" }, { "part": "top", "normal_stress": -5e6 } ],
        "solve": { "method": "auto", "max_cycles": 2000 }
    }"#;
    let r = run(
        &Scene::from_json(text, "squash").unwrap(),
        "adit-test-implicit-squash",
    );
    assert_eq!(r.summary.status, "failed");
    assert_eq!(r.summary.methods, ["implicit"]);
    let reason = r.summary.reason.unwrap();
    assert!(reason.contains("runaway displacement"), "{reason}");
}

/// A model that converges slowly is not a mechanism: `models/jointed_tunnel_mixed.json` stopped
/// at 200 iterations (ratio 2.7e-5, converging at 216) was reported with 365 blocks "still
/// moving" by 1e-8 m an iteration, about 1e-5 of what they had moved. It must end at its limit or
/// converge, never fail naming blocks.
#[test]
fn a_slowly_converging_model_is_not_called_a_mechanism() {
    let mut sc = model_scene("models/jointed_tunnel_mixed.json");
    sc.solve.method = adit::scene::SolveMethod::Implicit;
    sc.solve.max_iterations = 200;
    let r = run(&sc, "adit-test-implicit-slow");
    assert!(
        r.summary.status == "converged" || r.summary.status == "cycle_limit",
        "{}: {:?}",
        r.summary.status,
        r.summary.reason
    );
}

/// Displacement control: a platen driven down on an elastic column gives the column's stiffness
/// (σyy = M ε over the column, M = E(1 − ν)/((1 + ν)(1 − 2ν)) with the sides on rollers); a drive
/// along a free component is refused naming the node, before any factorization.
#[test]
fn a_driven_platen_strains_the_column_it_drives() {
    let text = r#"{
        "name": "column",
        "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.25 } },
        "region": { "polygon": [[0, 0], [1, 0], [1, 2], [0, 2]], "material": "rock",
                    "edge_names": ["bottom", "right", "top", "left"] },
        "zoning": { "edge_at_excavation": 0.25, "edge_far": 0.25 },
        "boundary": [ { "part": "bottom", "fix": "y" }, { "part": "left", "fix": "x" },
                      { "part": "right", "fix": "x" }, { "part": "top", "fix": "y" } ],
        "solve": { "method": "implicit", "ratio": 1e-9 }
    }"#;
    let sc = Scene::from_json(text, "column").unwrap();
    let mut b = adit::setup::setup(&sc).unwrap();
    let mut solver = adit::solve::Solver::new(&mut b.model, &sc.solve, 0);
    let top = b.plan.boundary.part_nodes["top"].clone();
    let strain = 1e-4;
    let drive: Vec<adit::implicit::Drive> =
        top.iter().map(|&n| (n, [0.0, -2.0 * strain])).collect();
    let solved = adit::implicit::solve_driven(
        &mut b.model,
        &mut solver.cycle,
        &solver.params,
        &sc.solve,
        &drive,
        &mut adit::implicit::Analysis::default(),
        &mut Quiet,
    );
    assert_eq!(
        solved.solution.status,
        adit::solve::Status::Converged,
        "{:?}",
        solved.solution.status
    );
    let (e, nu) = (10e9, 0.25);
    let m = e * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
    for s in &b.model.zones.stress {
        assert!((s[1] / (-m * strain) - 1.0).abs() < 1e-6, "{s:?}");
    }
    // Along x the top corner nodes are fixed (the sides' rollers), the others are not.
    let free = top
        .iter()
        .copied()
        .find(|&n| b.model.nodes.fixed[n as usize] & adit::model::FIX_X == 0)
        .unwrap();
    let refused = adit::implicit::solve_driven(
        &mut b.model,
        &mut solver.cycle,
        &solver.params,
        &sc.solve,
        &[(free, [1e-4, 0.0])],
        &mut adit::implicit::Analysis::default(),
        &mut Quiet,
    );
    let adit::solve::Status::Failed(reason) = refused.solution.status else {
        panic!("{:?}", refused.solution.status);
    };
    assert!(
        reason.contains(&format!("node {free} is driven along x but free along it")),
        "{reason}"
    );
    assert_eq!(refused.cost.factorizations, 0);
}

/// Joints the first stage opened (the rock's in-situ tension released between two fixed edges:
/// eight blocks, every contact open) and the second stage closes (the top edge loaded in
/// compression): the implicit solve ends within 2 % of the explicit one on the top edge's mean
/// settlement (1.3 %: friction on the vertical joints remembers the path). The matrix holds every joint
/// stuck; one that held the open joints at a tenth of their stiffness (tried to save iterations)
/// overshot as they closed, detected contacts elsewhere, committed the joints there, and ended
/// 10.5 % off in 113 iterations against 59.
#[test]
fn a_joint_that_closes_converges_on_the_stiff_answer() {
    let text = |method: &str| {
        format!(
            r#"{{
        "name": "reopen",
        "materials": {{ "rock": {{ "density": 2500, "young": 10e9, "poisson": 0.25 }} }},
        "joint_materials": {{ "j": {{ "normal_stiffness": 1e11, "shear_stiffness": 5e10,
                                      "friction": 30 }} }},
        "region": {{ "polygon": [[0, 0], [2, 0], [2, 2], [0, 2]], "material": "rock",
                     "edge_names": ["bottom", "right", "top", "left"] }},
        "joints": [{{ "from": [-1, 0.5], "to": [3, 0.5], "material": "j" }},
                   {{ "from": [-1, 1], "to": [3, 1], "material": "j" }},
                   {{ "from": [-1, 1.5], "to": [3, 1.5], "material": "j" }},
                   {{ "from": [0.7, -1], "to": [0.7, 3], "material": "j" }},
                   {{ "from": [1.3, -1], "to": [1.3, 3], "material": "j" }}],
        "zoning": {{ "edge_at_excavation": 0.25, "edge_far": 0.25 }},
        "in_situ": {{ "syy": 1e6, "sxx": 1e6 }},
        "boundary": [ {{ "part": "bottom", "fix": "xy" }}, {{ "part": "top", "fix": "xy" }} ],
        "solve": {{ "method": "{method}", "max_cycles": 20000 }},
        "stages": [ {{ "name": "open" }},
                    {{ "name": "close", "boundary": [ {{ "part": "bottom", "fix": "xy" }},
                                                    {{ "part": "top", "normal_stress": -2e6 }},
                                                    {{ "part": "left", "fix": "x" }},
                                                    {{ "part": "right", "fix": "x" }} ] }} ]
    }}"#
        )
    };
    let implicit = run(
        &Scene::from_json(&text("implicit"), "reopen").unwrap(),
        "adit-test-implicit-reopen",
    );
    let explicit = run(
        &Scene::from_json(&text("explicit"), "reopen").unwrap(),
        "adit-test-implicit-reopen-explicit",
    );
    assert_eq!(
        implicit.summary.status, "converged",
        "{:?}",
        implicit.summary.reason
    );
    assert_eq!(explicit.summary.status, "converged");
    let top = |r: &adit::RunResult| {
        let m = &r.built.model;
        (0..m.nodes.len())
            .filter(|&n| m.nodes.pos[n][1] > 1.999)
            .map(|n| m.nodes.disp[n][1])
            .sum::<f64>()
    };
    let (i, e) = (top(&implicit), top(&explicit));
    assert!(e < 0.0 && (i / e - 1.0).abs() < 0.02, "{i} {e}");
}

/// A dilatant hole in mixed zones (`zoning.mixed`, ν = 0.4, c = 1 MPa, φ = 25°, ψ = 10°,
/// p0 = 15 MPa): a zone's plastic change of mean stress is averaged over its patches, which
/// moves its stress off its yield surface. Explicitly the next cycle returns it; the implicit
/// trial, taken once per iteration from the commit, adds the shift of the iteration before to
/// its predictor (`cycle::mixed`). Shifted after the return instead, the implicit answer held
/// zones beyond their strength: closure 7.63 mm against 10.48 mm explicitly released over
/// 16 000 cycles (−27 %), and an explicit stage after it took 1 410 cycles to move the wall to
/// 10.69 mm. Now 10.54 mm (+0.55 %), and the explicit stage after it is at rest in 10 cycles.
#[test]
fn a_mixed_dilatant_hole_solved_implicitly_is_at_explicit_rest() {
    let json = MC_HOLE
        .replace(r#""poisson": 0.25,"#, r#""poisson": 0.4, "dilation": 10,"#)
        .replace(
            r#""cohesion": 5e6, "friction": 30"#,
            r#""cohesion": 1e6, "friction": 25"#,
        )
        .replace("-30e6", "-15e6")
        .replace(
            r#""edge_at_excavation": 0.1, "edge_far": 2.0"#,
            r#""edge_at_excavation": 0.15, "edge_far": 2.0, "mixed": true"#,
        );
    let handed = Scene::from_json(&handed_over(&json), "mc_hole").unwrap();
    assert!(handed.zoning.mixed && handed.materials["rock"].dilation == 10.0);
    let h = run(&handed, "adit-test-mixed-dilatant-handed");
    assert_at_explicit_rest(&h, "hole");

    let (c_implicit, c_explicit) =
        against_explicit_slowly(&h, &json, "hole", "adit-test-mixed-dilatant-slowly");
    assert!(
        (c_implicit / c_explicit - 1.0).abs() < 0.02,
        "{c_implicit} {c_explicit}"
    );
}

/// `json`, a scene without stages, solved in one stage implicitly and then in one explicitly from
/// where it left the model.
fn handed_over(json: &str) -> String {
    format!(
        r#"{}, "stages": [
            {{ "name": "implicit", "solve": {{ "method": "implicit", "ratio": 1e-5 }} }},
            {{ "name": "explicit after it", "solve": {{ "ratio": 1e-5, "max_cycles": 200000 }} }}
        ] }}"#,
        json.trim_end().strip_suffix('}').unwrap()
    )
}

/// The explicit stage of a `handed_over` run found the implicit one's state at rest: converged
/// within 100 cycles, the mean closure of `wall` unchanged to 1e-3.
fn assert_at_explicit_rest(r: &adit::RunResult, wall: &str) {
    let [solved, _] = &r.summary.stages[..] else {
        panic!("two stages")
    };
    assert_eq!(solved.status, "converged");
    if let Err(e) = at_explicit_rest(r, wall) {
        panic!("{e}");
    }
}

/// Whether the explicit stage of a `handed_over` run, its implicit stage converged, found that
/// stage's state at rest (`assert_at_explicit_rest`), or how it did not.
fn at_explicit_rest(r: &adit::RunResult, wall: &str) -> Result<(), String> {
    let [solved, after] = &r.summary.stages[..] else {
        return Err("two stages".into());
    };
    let (c_solved, c_after) = (solved.closure[wall], after.closure[wall]);
    println!(
        "implicit {} iterations, closure {c_solved:.5e} m; explicit after it {} cycles, {c_after:.5e} m",
        solved.cycles, after.cycles
    );
    if after.status != "converged" || after.cycles > 100 {
        return Err(format!(
            "explicit after it: {} after {} cycles",
            after.status, after.cycles
        ));
    }
    if (c_after / c_solved - 1.0).abs() >= 1e-3 {
        return Err(format!("closure {c_solved} moved to {c_after}"));
    }
    Ok(())
}

/// The mean closures of `wall` (m) of the handed-over run `h` and of its scene `json` solved
/// explicitly into `folder`, the out-of-balance force released over 16 000 cycles (to a ratio of
/// 1e-5).
fn against_explicit_slowly(
    h: &adit::RunResult,
    json: &str,
    wall: &str,
    folder: &str,
) -> (f64, f64) {
    let mut slowly = Scene::from_json(json, "slowly").unwrap();
    slowly.solve.ratio = 1e-5;
    slowly.solve.ramp = 16_000;
    slowly.solve.max_cycles += slowly.solve.ramp;
    let e = run(&slowly, folder);
    let nodes = &e.built.plan.boundary.part_nodes[wall];
    let (c_implicit, c_explicit) = (closure(h, nodes), closure(&e, nodes));
    println!(
        "mean wall closure: implicit {c_implicit:.5e} m, explicit released over 16 000 cycles \
         {c_explicit:.5e} m"
    );
    (c_implicit, c_explicit)
}

/// A hole through rock cut by two sets of joints with cohesion (0.2 MPa, φ = 25°), excavated at
/// once: joints near the wall fail. A cycle's joint loses its cohesion from the cycle after it
/// failed; the implicit trial from the commit returned a joint that failed within the step to
/// its intact strength, c − σn tan φ, before this test, which held those joints at it: the
/// implicit closure was 1.004 mm, and explicit cycles after it took 2 410 cycles to close the
/// hole to 1.137 mm (+13 %; the scene is a random draw's, found comparing the two paths). Now
/// the implicit state is the explicit one's rest (1.134 mm).
#[test]
fn joints_failing_within_an_implicit_step_lose_their_cohesion() {
    let json = r#"{
        "name": "jointed_hole",
        "materials": { "rock": { "density": 2600, "young": 20e9, "poisson": 0.25 } },
        "region": { "polygon": [[-12, -12], [12, -12], [12, 12], [-12, 12]], "material": "rock" },
        "excavations": [{ "name": "tunnel", "circle": { "center": [0, -0.8], "radius": 2, "segments": 48 } }],
        "zoning": { "edge_at_excavation": 0.25, "edge_far": 3, "grading": 0.25 },
        "joint_materials": { "j": { "normal_stiffness": 2e10, "shear_stiffness": 1e10,
                                    "friction": 25, "cohesion": 2e5 } },
        "joint_sets": [
            { "dip": 176.96, "spacing": 1.94, "origin": [0.397, -0.782], "trace": 6.12, "gap": 1.19, "material": "j" },
            { "dip": 56.53, "spacing": 1.54, "origin": [0.708, -0.418], "trace": 10.46, "gap": 2.10, "material": "j" } ],
        "in_situ": { "sxx": -4.32e6, "syy": -5e6 },
        "boundary": [ { "part": "outer", "in_situ_traction": true },
                      { "at": [12, 0], "fix": "y" }, { "at": [-12, 0], "fix": "y" },
                      { "at": [0, 12], "fix": "x" }, { "at": [0, -12], "fix": "x" } ],
        "solve": { "ratio": 1e-5, "max_cycles": 200000 }
    }"#;
    let handed = Scene::from_json(&handed_over(json), "jointed_hole").unwrap();
    let h = run(&handed, "adit-test-jointed-handed");
    assert_at_explicit_rest(&h, "tunnel");
}

/// A hole through rock cut by two sets of dilatant joints (kn = 1e11 Pa/m, ks = 1e10 Pa/m,
/// φ = 25°, ψ = 5°, no cohesion; a random draw's scene): a slipping joint's dilation adds
/// kn tan ψ tan φ = 4.1e9 Pa/m to its shear resistance, which the implicit trial's return takes
/// into account (`CoulombSlip::plastic_slip`). Returned by excess / ks instead (40 % too much
/// slip), this solve stopped unconverged; in the draw's own scene (Mohr–Coulomb rock, staged,
/// bolted) the excavation took 8 414 iterations and its slow release in 16 load steps did not
/// converge. Now 48 iterations, within 0.01 % of the explicit slow release.
#[test]
fn dilatant_joints_converge_implicitly_on_the_explicit_answer() {
    let json = r#"{
        "name": "dilatant_joints",
        "materials": { "rock": { "density": 2600, "young": 5e9, "poisson": 0.3 } },
        "region": { "polygon": [[-8, -8], [8, -8], [8, 8], [-8, 8]], "material": "rock" },
        "excavations": [{ "name": "tunnel", "circle": { "center": [0, -0.59], "radius": 1.086, "segments": 48 } }],
        "zoning": { "edge_at_excavation": 0.2, "edge_far": 3, "grading": 0.25 },
        "joint_materials": { "j": { "normal_stiffness": 1e11, "shear_stiffness": 1e10,
                                    "friction": 25, "dilation": 5 } },
        "joint_sets": [
            { "dip": 32.24, "spacing": 3.388, "origin": [0.322, -0.346], "trace": 6.72, "gap": 2.28, "material": "j" },
            { "dip": 59.33, "spacing": 3.255, "origin": [-0.648, 0.167], "trace": 11.13, "gap": 1.79, "material": "j" } ],
        "in_situ": { "sxx": -6.237e6, "syy": -5e6 },
        "boundary": [ { "part": "outer", "in_situ_traction": true },
                      { "at": [8, 0], "fix": "y" }, { "at": [-8, 0], "fix": "y" },
                      { "at": [0, 8], "fix": "x" }, { "at": [0, -8], "fix": "x" } ],
        "solve": { "ratio": 1e-5, "max_cycles": 200000 }
    }"#;
    let handed = Scene::from_json(&handed_over(json), "dilatant_joints").unwrap();
    let h = run(&handed, "adit-test-dilatant-joints-handed");
    assert_at_explicit_rest(&h, "tunnel");
    let iterations = h.summary.stages[0].cycles;
    assert!(iterations <= 300, "{iterations}");

    let (c_implicit, c_explicit) =
        against_explicit_slowly(&h, json, "tunnel", "adit-test-dilatant-joints-slowly");
    assert!(
        (c_implicit / c_explicit - 1.0).abs() < 0.015,
        "{c_implicit} {c_explicit}"
    );
}

/// Drawn scenes solved implicitly are at explicit rest: a hole in a box of rock (elastic or
/// Mohr–Coulomb, dilatant or not, plain or mixed zones) cut by up to two non-persistent sets of
/// Coulomb joints (with or without cohesion and dilation), solved in one implicit stage and then
/// cycled explicitly from where it left the model: where the implicit stage converged, the
/// explicit one converges within 100 cycles without moving the wall. This oracle, run by hand on
/// 42 random scenes, found the three defects of the tests above (mixed zones' plastic pressure,
/// joints that fail within a step, dilatant joints' return); with those three undone this
/// property fails too (on its 32 draws, in 1.4 s).
mod drawn {
    use super::*;
    use proptest::prelude::*;

    #[allow(clippy::too_many_arguments)]
    fn scene(
        half: f64,
        radius: f64,
        plastic: Option<(f64, f64, f64)>,
        poisson: f64,
        mixed: bool,
        sets: &[(f64, f64, f64, f64)],
        joint: (f64, f64, f64, f64),
        stress: (f64, f64),
    ) -> String {
        let law = plastic.map_or(String::new(), |(c, phi, psi)| {
            format!(
                r#", "law": "mohr_coulomb", "cohesion": {c}, "friction": {phi}, "dilation": {psi}"#
            )
        });
        let (kn, phi, c, psi) = joint;
        let sets: Vec<String> = sets
            .iter()
            .map(|&(dip, spacing, trace, gap)| {
                format!(
                    r#"{{ "dip": {dip}, "spacing": {spacing}, "origin": [0.3, -0.2], "trace": {trace}, "gap": {gap}, "material": "j" }}"#
                )
            })
            .collect();
        format!(
            r#"{{
            "name": "drawn",
            "materials": {{ "rock": {{ "density": 2600, "young": 10e9, "poisson": {poisson}{law} }} }},
            "region": {{ "polygon": [[-{half}, -{half}], [{half}, -{half}], [{half}, {half}], [-{half}, {half}]], "material": "rock" }},
            "excavations": [{{ "name": "tunnel", "circle": {{ "center": [0, 0], "radius": {radius}, "segments": 48 }} }}],
            "zoning": {{ "edge_at_excavation": 0.25, "edge_far": 3, "grading": 0.25, "mixed": {mixed} }},
            "joint_materials": {{ "j": {{ "normal_stiffness": {kn}, "shear_stiffness": 1e10,
                                        "friction": {phi}, "cohesion": {c}, "dilation": {psi} }} }},
            "joint_sets": [{}],
            "in_situ": {{ "sxx": {}, "syy": {} }},
            "boundary": [ {{ "part": "outer", "in_situ_traction": true }},
                          {{ "at": [{half}, 0], "fix": "y" }}, {{ "at": [-{half}, 0], "fix": "y" }},
                          {{ "at": [0, {half}], "fix": "x" }}, {{ "at": [0, -{half}], "fix": "x" }} ],
            "solve": {{ "ratio": 1e-5, "max_cycles": 200000 }}
        }}"#,
            sets.join(", "),
            stress.0,
            stress.1
        )
    }

    proptest! {
        #![proptest_config(ProptestConfig {
            cases: 32,
            rng_seed: proptest::test_runner::RngSeed::Fixed(33),
            failure_persistence: None,
            ..ProptestConfig::default()
        })]

        #[test]
        fn drawn_scenes_solved_implicitly_are_at_explicit_rest(
            half in 8.0f64..14.0,
            radius in 1.0f64..2.0,
            plastic in proptest::option::of((1e6f64..4e6, 25.0f64..40.0, prop_oneof![Just(0.0), Just(5.0), Just(10.0)])),
            poisson in prop_oneof![Just(0.25), Just(0.3), Just(0.4)],
            mixed in any::<bool>(),
            sets in proptest::collection::vec((0.0f64..180.0, 1.5f64..4.0, 4.0f64..12.0, 1.0f64..3.0), 0..=2),
            joint in (prop_oneof![Just(2e10), Just(1e11)], 25.0f64..35.0, prop_oneof![Just(0.0), Just(2e5)], prop_oneof![Just(0.0), Just(5.0)]),
            p in 4e6f64..10e6,
            k in 0.5f64..1.5,
        ) {
            let json = scene(half, radius, plastic, poisson, mixed, &sets, joint, (-p * k, -p));
            let handed = Scene::from_json(&handed_over(&json), "drawn").unwrap();
            // An implicit stage that fails (a mechanism named) ends the run: nothing to hand
            // over. Any other error is the test's.
            let r = match try_run(&handed, "adit-test-drawn-handed") {
                Ok(r) => r,
                Err(e) => {
                    let e = format!("{e:#}");
                    prop_assert!(e.contains("implicit: "), "{e}");
                    return Ok(());
                }
            };
            let [solved, _] = &r.summary.stages[..] else { return Ok(()) };
            prop_assume!(solved.status == "converged");
            at_explicit_rest(&r, "tunnel").map_err(TestCaseError::fail)?;
        }
    }
}
