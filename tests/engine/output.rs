//! The output contract: a run writes a readable `.pvd`, zone, contact and support `.vtu` with the
//! contract's fields, `history.csv` and `summary.json`; meshio (Python) reads the `.vtu` too.

use std::path::{Path, PathBuf};
use std::process::Command;

use adit::solve::Quiet;
use adit::{Scene, run_scene};
use vtkio::model::{Attribute, DataSet, Piece, Vtk};

fn small_scene() -> Scene {
    let mut s =
        Scene::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("models/kirsch.json")).unwrap();
    s.zoning.edge_at_excavation = 0.3;
    s.zoning.edge_far = 8.0;
    s.zoning.grading = 0.5;
    s.excavations[0].circle.as_mut().unwrap().segments = 24;
    s.solve.method = adit::scene::SolveMethod::Explicit;
    s.solve.max_cycles = 300;
    s.output.every = 100;
    s
}

fn out_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("adit-test-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

#[test]
fn run_writes_every_contract_file() {
    let dir = out_dir("contract");
    let r = run_scene(&small_scene(), &dir, &mut Quiet).unwrap();
    let (zones, nodes) = (r.summary.zones, r.summary.nodes);
    let pvd = std::fs::read_to_string(dir.join("kirsch.pvd")).unwrap();
    // Intermediate steps at cycles 100 and 200, and the final one.
    assert_eq!(pvd.matches("<DataSet ").count(), 3, "{pvd}");
    assert!(pvd.contains("file=\"kirsch_zones_0002.vtu\""));

    let vtk = Vtk::import(dir.join("kirsch_zones_0002.vtu")).unwrap();
    let DataSet::UnstructuredGrid { pieces, .. } = vtk.data else {
        panic!("not an unstructured grid")
    };
    let Piece::Inline(piece) = &pieces[0] else {
        panic!("piece not inline")
    };
    assert_eq!(piece.num_points(), nodes);
    assert_eq!(piece.cells.types.len(), zones);
    let sizes = |attrs: &[Attribute]| -> Vec<(String, usize)> {
        attrs
            .iter()
            .map(|a| match a {
                Attribute::DataArray(d) => (d.name.clone(), d.data.len()),
                Attribute::Field { name, .. } => (name.clone(), 0),
            })
            .collect()
    };
    let cell = sizes(&piece.data.cell);
    for (name, per) in [
        ("stress", 9),
        ("sigma1", 1),
        ("sigma3", 1),
        ("block", 1),
        ("material", 1),
        ("state", 1),
        ("recovery_error", 1),
    ] {
        assert!(
            cell.contains(&(name.to_string(), per * zones)),
            "cell data {name}: {cell:?}"
        );
    }
    let point = sizes(&piece.data.point);
    for (name, per) in [
        ("displacement", 3),
        ("velocity", 3),
        ("stress_nodal", 9),
        ("sigma1_nodal", 1),
        ("sigma3_nodal", 1),
    ] {
        assert!(
            point.contains(&(name.to_string(), per * nodes)),
            "point data {name}: {point:?}"
        );
    }

    let history = std::fs::read_to_string(dir.join("history.csv")).unwrap();
    // One spelling of each unit in every column (issue 49, friction item 9): lower case, as the
    // Python tables and the progress rows spell it.
    assert!(history.starts_with("cycle,time_s,unbalanced_ratio,kinetic_energy_j_per_m\n"));
    assert_eq!(history.lines().count(), 1 + 30);
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    for key in [
        "scene",
        "zones",
        "nodes",
        "blocks",
        "contacts",
        "cycles",
        "wall_seconds",
        "stage_seconds",
        "zone_cycles_per_second",
        "final_ratio",
        "status",
    ] {
        assert!(summary.get(key).is_some(), "summary.json lacks {key}");
    }
    assert_eq!(summary["status"], "cycle_limit");
    // No field is ever null (it had been `critical_block` in every run without blocks).
    let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    assert!(!text.contains("null"), "{text}");
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().ends_with(".tmp"))
        .collect();
    assert!(leftovers.is_empty(), "temporary files left: {leftovers:?}");
    check_with_meshio(&dir.join("kirsch_zones_0002.vtu"), zones, nodes);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The bundled jointed model runs to equilibrium and writes contacts beside zones.
#[test]
fn jointed_tunnel_converges_and_writes_contacts() {
    let dir = out_dir("jointed");
    let scene =
        Scene::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("models/jointed_tunnel.json"))
            .unwrap();
    let r = run_scene(&scene, &dir, &mut Quiet).unwrap();
    assert_eq!(r.summary.status, "converged", "{:?}", r.summary.reason);
    assert!(
        r.summary.blocks > 100 && r.summary.contacts > 1000,
        "{:?}",
        (r.summary.blocks, r.summary.contacts)
    );
    let pvd = std::fs::read_to_string(dir.join("jointed_tunnel.pvd")).unwrap();
    assert!(
        pvd.contains(
            "part=\"1\" name=\"contacts\" stage=\"solve\" file=\"jointed_tunnel_contacts_0000.vtu\""
        ),
        "{pvd}"
    );
    check_with_meshio(
        &dir.join("jointed_tunnel_zones_0000.vtu"),
        r.summary.zones,
        r.summary.nodes,
    );
    check_contacts_with_meshio(
        &dir.join("jointed_tunnel_contacts_0000.vtu"),
        r.summary.contacts,
    );
    check_joints_with_meshio(&dir.join("jointed_tunnel_joints_0000.vtu"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn supports_are_written_as_line_cells() {
    let text = r#"{
        "name": "lined",
        "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.25 } },
        "region": { "polygon": [[-10, -10], [10, -10], [10, 10], [-10, 10]], "material": "rock" },
        "excavations": [{ "name": "tunnel", "circle": { "center": [0, 0], "radius": 1, "segments": 48 } }],
        "zoning": { "edge_at_excavation": 0.15, "edge_far": 2.0, "grading": 0.3 },
        "in_situ": { "sxx": -10e6, "syy": -5e6 },
        "boundary": [ { "part": "outer", "in_situ_traction": true },
                      { "at": [10, 0], "fix": "y" }, { "at": [-10, 0], "fix": "y" },
                      { "at": [0, 10], "fix": "x" }, { "at": [0, -10], "fix": "x" } ],
        "bolts": [{ "name": "bolts", "young": 200e9, "area": 4.9e-4, "yield_force": 2e5,
                    "grout_stiffness": 1e9, "bond_strength": 2e5, "segment": 0.5,
                    "pattern": { "excavation": "tunnel", "count": 3, "length": 2, "spacing": 1 } }],
        "liners": [{ "name": "liner", "excavation": "tunnel", "young": 30e9, "area": 0.1, "inertia": 8.3e-5 }],
        "solve": { "ratio": 1e-5 },
        "stages": [
            { "name": "excavate", "excavate": ["tunnel"], "support_fraction": 0.5 },
            { "name": "support", "install": ["bolts", "liner"] }
        ]
    }"#;
    let sc = Scene::from_json(text, "lined").unwrap();
    let dir = out_dir("supports");
    let r = run_scene(&sc, &dir, &mut Quiet).unwrap();
    assert!(r.summary.stages.iter().all(|s| s.status == "converged"));
    let s = &r.built.model.supports;
    let (segments, elements) = (s.cables.segment.len(), s.liners.element.len());
    assert_eq!(segments, 3 * 4, "three bolts of four 0.5 m segments");
    assert_eq!(elements, 48, "one liner element per wall edge");
    let pvd = std::fs::read_to_string(dir.join("lined.pvd")).unwrap();
    // The supports file holds the installed supports: none before the stage installing them.
    assert_eq!(pvd.matches("_supports_").count(), 1, "{pvd}");
    assert!(!dir.join("lined_supports_0000.vtu").exists());
    let points = s.cables.nodes() + s.liners.nodes();
    let script = format!(
        r#"
import sys, meshio
m = meshio.read(sys.argv[1])
assert m.points.shape == ({points}, 3), m.points.shape
lines = [c for c in m.cells if c.type == "line"]
assert len(lines) == 1 and lines[0].data.shape == ({cells}, 2)
for name in ["axial_force", "moment", "kind", "installed", "yielded"]:
    assert m.cell_data[name][0].shape[0] == {cells}, name
assert m.point_data["displacement"].shape == ({points}, 3)
kind, axial = m.cell_data["kind"][0], m.cell_data["axial_force"][0]
assert (axial[kind == 1] < 0).all(), "the liner is in compression"
print("meshio ok")
"#,
        cells = segments + elements
    );
    run_python(&script, &dir.join("lined_supports_0001.vtu"));
    for plot in ["history.png", "ground_reaction.png", "bolts.png"] {
        let png = std::fs::read(dir.join(plot)).unwrap();
        assert_eq!(&png[1..4], b"PNG", "{plot}");
    }
    assert!(
        r.summary.warnings.iter().all(|w| !w.contains(".png")),
        "{:?}",
        r.summary.warnings
    );
}

/// Read a zones file with Python's meshio and check the contract's fields and sizes.
fn check_with_meshio(path: &Path, zones: usize, nodes: usize) {
    let script = format!(
        r#"
import sys, meshio
m = meshio.read(sys.argv[1])
assert m.points.shape == ({nodes}, 3), m.points.shape
tri = [c for c in m.cells if c.type == "triangle"]
assert len(tri) == 1 and tri[0].data.shape == ({zones}, 3)
for name, comps in [("stress", 9), ("sigma1", 1), ("sigma3", 1), ("block", 1), ("material", 1), ("state", 1), ("recovery_error", 1)]:
    a = m.cell_data[name][0]
    assert a.shape[0] == {zones} and (a.size // {zones}) == comps, (name, a.shape)
for name in ["displacement", "velocity"]:
    assert m.point_data[name].shape == ({nodes}, 3), name
assert m.point_data["stress_nodal"].shape == ({nodes}, 9)
assert "material: rock" in m.field_data, list(m.field_data)
print("meshio ok")
"#
    );
    run_python(&script, path);
}

/// A staged excavation without joints drops every contact (the fill's glue goes with it): that
/// step writes no contacts or joints file (issue 49, friction item 14: meshio 5.3 reads no `.vtu`
/// without cells, not even one it wrote itself), its collection lists the zones alone, the
/// contacts keep part 1 in the steps that have them, and meshio reads every file listed.
#[test]
fn a_step_without_contacts_lists_only_files_meshio_reads() {
    let mut s = small_scene();
    s.output.every = 0;
    s.stages = serde_json::from_value(serde_json::json!([
        { "name": "in-situ" },
        { "name": "excavate", "excavate": ["tunnel"] }
    ]))
    .unwrap();
    let dir = out_dir("empty-contacts");
    let r = run_scene(&s, &dir, &mut Quiet).unwrap();
    assert_eq!(r.summary.contacts, 0);
    assert!(dir.join("kirsch_contacts_0000.vtu").exists());
    assert!(!dir.join("kirsch_contacts_0001.vtu").exists());
    assert!(!dir.join("kirsch_joints_0001.vtu").exists());
    let pvd = std::fs::read_to_string(dir.join("kirsch.pvd")).unwrap();
    assert!(
        pvd.contains("part=\"1\" name=\"contacts\" stage=\"in-situ\"")
            && pvd.contains("part=\"2\" name=\"joints\" stage=\"in-situ\"")
            && !pvd.contains("_contacts_0001"),
        "{pvd}"
    );
    let script = r#"
import sys, os, re, meshio
pvd = sys.argv[1]
files = re.findall(r'file="([^"]+)"', open(pvd).read())
assert len(files) == 4, files
for f in files:
    meshio.read(os.path.join(os.path.dirname(pvd), f))
print("meshio ok")
"#;
    run_python(script, &dir.join("kirsch.pvd"));
}

/// Read a contacts file with meshio: vertex cells with the contract's point data.
fn check_contacts_with_meshio(path: &Path, contacts: usize) {
    let script = format!(
        r#"
import sys, meshio
m = meshio.read(sys.argv[1])
assert m.points.shape == ({contacts}, 3), m.points.shape
for name in ["normal_stress", "shear_stress", "normal_displacement", "shear_displacement", "state"]:
    assert m.point_data[name].shape[0] == {contacts}, name
print("meshio ok")
"#
    );
    run_python(&script, path);
}

/// Read a joints file with meshio: line cells with the joints' cell data, some of them closed
/// and compressed (the jointed tunnel's joints carry the in-situ stress).
fn check_joints_with_meshio(path: &Path) {
    let script = r#"
import sys, meshio
m = meshio.read(sys.argv[1])
lines = [c for c in m.cells if c.type == "line"]
assert len(lines) == 1 and lines[0].data.shape[0] > 100, [c.type for c in m.cells]
n = lines[0].data.shape[0]
for name in ["normal_stress", "shear_stress", "shear_displacement", "aperture", "jrc_mobilized", "state", "material", "block"]:
    assert m.cell_data[name][0].shape[0] == n, name
assert (m.cell_data["normal_stress"][0] < 0).mean() > 0.9
print("meshio ok")
"#;
    run_python(script, path);
}

/// Run a Python check on `path`. Required when `ADIT_REQUIRE_MESHIO=1` (as in `.ci/run`, which
/// installs meshio); otherwise skipped with a note when meshio is not installed.
fn run_python(script: &str, path: &Path) {
    let required = std::env::var("ADIT_REQUIRE_MESHIO").is_ok_and(|v| v == "1");
    let has = Command::new("python3")
        .args(["-c", "import meshio"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !has {
        assert!(
            !required,
            "ADIT_REQUIRE_MESHIO=1 but python3 cannot import meshio"
        );
        eprintln!(
            "meshio not installed: skipping the meshio read (set ADIT_REQUIRE_MESHIO=1 to require it)"
        );
        return;
    }
    let out = Command::new("python3")
        .args(["-c", script])
        .arg(path)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "meshio failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// A rerun clears what an earlier run of the scene left in its folder (so a failed or killed
/// rerun cannot pass for the earlier one) and leaves other files alone.
#[test]
fn a_rerun_replaces_the_earlier_outputs() {
    let dir = out_dir("rerun");
    std::fs::create_dir_all(&dir).unwrap();
    for earlier in [
        "kirsch_zones_0007.vtu",
        ".kirsch.pvd.tmp",
        "summary.json",
        "notes.txt",
    ] {
        std::fs::write(dir.join(earlier), "earlier run").unwrap();
    }
    run_scene(&small_scene(), &dir, &mut Quiet).unwrap();
    assert!(!dir.join("kirsch_zones_0007.vtu").exists());
    assert!(!dir.join(".kirsch.pvd.tmp").exists());
    assert!(dir.join("notes.txt").exists());
    let summary = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    assert!(summary.contains("\"status\": \"cycle_limit\""), "{summary}");

    // A rerun whose build fails leaves a summary saying so, not the earlier one.
    let mut outside = small_scene();
    outside.excavations[0].circle.as_mut().unwrap().center = [19.5, 0.0];
    let err = run_scene(&outside, &dir, &mut Quiet).err().unwrap();
    let summary = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    assert!(summary.contains("\"status\": \"failed\""), "{summary}");
    assert!(
        summary.contains("not inside the region"),
        "{summary} / {err}"
    );
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert!(
        !dir.join("kirsch.pvd").exists() && !dir.join("history.csv").exists(),
        "{left:?}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `adit run models/kirsch.json --quiet --out <dir>`, its exit and output.
fn run_kirsch_into(dir: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_adit"))
        .args([
            "run",
            concat!(env!("CARGO_MANIFEST_DIR"), "/models/kirsch.json"),
            "--quiet",
            "--out",
        ])
        .arg(dir)
        .output()
        .unwrap()
}

/// A run into a folder another run holds is refused before it writes anything, leaving that
/// run's files alone (two runs into one folder would each leave files that look complete); once
/// the folder is let go a run goes ahead. The `adit` command says why it stopped.
#[test]
fn a_second_run_into_a_held_folder_is_refused() {
    let dir = out_dir("held");
    run_scene(&small_scene(), &dir, &mut Quiet).unwrap();
    let before = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    let held = adit::output::lock::FolderLock::take(&dir).unwrap();
    let err = run_scene(&small_scene(), &dir, &mut Quiet).err().unwrap();
    assert!(
        format!("{err:#}").contains("another run is writing there"),
        "{err:#}"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("summary.json")).unwrap(),
        before
    );
    let out = run_kirsch_into(&dir);
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(
        !out.status.success() && said.contains("another run"),
        "{said}"
    );
    drop(held);
    run_scene(&small_scene(), &dir, &mut Quiet).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
}

/// An output folder that cannot be made is an error naming it, before the scene is built.
#[test]
fn an_unwritable_output_folder_fails_first_naming_it() {
    let file = out_dir("not-a-folder");
    std::fs::write(&file, "a file").unwrap();
    let out = run_kirsch_into(&file.join("sub"));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.starts_with("error: output folder ") && err.contains("not-a-folder"),
        "{err}"
    );
    std::fs::remove_file(&file).unwrap();
}

/// After its stage, an excavation's rock is gone from the zone files (it was drawn as stress-free
/// triangles inside the hole), and each file names its stage and the materials.
#[test]
fn excavated_zones_leave_the_zone_files() {
    let mut s = small_scene();
    s.output.every = 0;
    s.stages = ["in-situ", "excavate"]
        .iter()
        .map(|name| {
            let excavate: Vec<&str> = if *name == "excavate" {
                vec!["tunnel"]
            } else {
                vec![]
            };
            serde_json::from_value(serde_json::json!({ "name": name, "excavate": excavate }))
                .unwrap()
        })
        .collect();
    let dir = out_dir("excavated");
    let r = run_scene(&s, &dir, &mut Quiet).unwrap();
    let grid = |step: usize| {
        let path = dir.join(format!("kirsch_zones_{step:04}.vtu"));
        let text = std::fs::read_to_string(&path).unwrap();
        let vtk = Vtk::import(&path).unwrap();
        let DataSet::UnstructuredGrid { pieces, .. } = vtk.data else {
            panic!("not an unstructured grid")
        };
        let Piece::Inline(piece) = pieces[0].clone() else {
            panic!("piece not inline")
        };
        (text, *piece)
    };
    let materials = |piece: &vtkio::model::UnstructuredGridPiece| -> Vec<i64> {
        piece
            .data
            .cell
            .iter()
            .find_map(|a| match a {
                Attribute::DataArray(d) if d.name == "material" => {
                    d.data.clone().cast_into::<i64>()
                }
                _ => None,
            })
            .unwrap()
    };
    let (before_text, before) = grid(0);
    let (after_text, after) = grid(1);
    assert_eq!(before.cells.types.len(), r.summary.zones);
    let null = 1; // `rock`, then the staged scene's null law `excavated`
    assert!(before_text.contains("Name=\"material: excavated\""));
    assert!(!materials(&before).contains(&null));
    let removed = r.summary.zones - after.cells.types.len();
    assert!(removed > 50, "{removed} zones left out");
    assert!(!materials(&after).contains(&null));
    assert!(
        before_text.contains("Name=\"stage: in-situ\""),
        "{before_text:.2000}"
    );
    assert!(after_text.contains("Name=\"stage: excavate\""));
    let pvd = std::fs::read_to_string(dir.join("kirsch.pvd")).unwrap();
    assert!(
        pvd.contains("stage=\"excavate\" file=\"kirsch_zones_0001.vtu\""),
        "{pvd}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A state that is not finite is never written as a result: an in-situ σzz of 1e308 Pa (a scene
/// file now refuses it) converged, and its recovered nodal stress overflowed to infinity in 4 339
/// values of a run that said `converged`. The run fails naming the field, and its summary says so.
#[test]
fn a_state_that_is_not_finite_fails_the_run() {
    let dir = out_dir("not-finite");
    let mut scene = small_scene();
    scene.in_situ.szz = Some(1e308);
    let err = run_scene(&scene, &dir, &mut Quiet)
        .err()
        .expect("the run fails");
    assert!(format!("{err:#}").contains("not finite"), "{err:#}");
    let summary = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    assert!(summary.contains("\"failed\""), "{summary}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Monitoring points (`histories`): `histories.csv` has a row per monitor step, as
/// `history.csv`, a column per point named with its quantity and unit, and its last row holds
/// the model's own values at the end (the node nearest the crown, the zone holding the point);
/// `histories.png` is drawn.
#[test]
fn monitoring_points_record_the_models_values() {
    let mut s = small_scene();
    s.solve.max_cycles = 2000;
    let text = r#"[
        { "name": "crown", "at": [0, 1], "quantity": "displacement_y" },
        { "name": "side, 0.5 m in", "at": [1.5, 0], "quantity": "stress_yy" }
    ]"#;
    s.histories = serde_json::from_str(text).unwrap();
    let out = out_dir("histories");
    let r = run_scene(&s, &out, &mut Quiet).unwrap();
    let csv = std::fs::read_to_string(out.join("histories.csv")).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(
        lines[0],
        "cycle,time_s,crown:displacement_y_m,\"side, 0.5 m in:stress_yy_pa\""
    );
    let history = std::fs::read_to_string(out.join("history.csv")).unwrap();
    assert_eq!(lines.len(), history.lines().count());
    let last: Vec<f64> = lines
        .last()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    let m = &r.built.model;
    let crown = (0..m.nodes.len())
        .min_by(|&a, &b| {
            let d = |n: usize| m.nodes.pos[n][0].hypot(m.nodes.pos[n][1] - 1.0);
            d(a).total_cmp(&d(b))
        })
        .unwrap();
    assert_eq!(last[0], r.summary.cycles as f64);
    assert_eq!(last[2], m.nodes.disp[crown][1] - m.nodes.origin[crown][1]);
    // The crown moves down under the vertical stress; the side carries about 3 × 20 MPa less
    // the decay 0.5 m in.
    assert!(last[2] < -1e-3, "{last:?}");
    assert!(last[3] < -20e6 && last[3] > -60e6, "{last:?}");
    assert!(out.join("histories.png").exists());
}

#[test]
fn monitoring_points_are_checked() {
    let bad = |text: &str, field: &str| {
        let mut v: serde_json::Value =
            serde_json::from_str(include_str!("../../models/kirsch.json")).unwrap();
        v["histories"] = serde_json::from_str(text).unwrap();
        let err = Scene::from_json(&v.to_string(), "kirsch")
            .unwrap_err()
            .to_string();
        assert!(err.contains(field), "{err}");
    };
    bad(
        r#"[{ "name": "far", "at": [500, 0], "quantity": "displacement_x" }]"#,
        "histories[0].at",
    );
    bad(
        r#"[{ "name": "a", "at": [0, 1], "quantity": "displacement_x" },
            { "name": "a", "at": [0, 2], "quantity": "displacement_y" }]"#,
        "histories[1].name",
    );
    bad(
        r#"[{ "name": "bolt", "at": [0, 1], "quantity": "bolt_force" }]"#,
        "histories[0].quantity",
    );
    bad(
        r#"[{ "name": "x", "at": [0, 1], "quantity": "temperature" }]"#,
        "unknown variant `temperature`",
    );
}

/// Each stage reports how its excavations' walls moved: the bundled tunnel's invert (the floor's
/// middle, not a corner) is the node its `invert` monitoring point reads, the crown settles, the
/// invert heaves, both sidewalls move in, and the convergences are the sums.
#[test]
fn a_stage_reports_its_crown_invert_and_sidewalls() {
    let s = Scene::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("models/tunnel.json")).unwrap();
    let out = out_dir("walls");
    let r = run_scene(&s, &out, &mut Quiet).unwrap();
    let last = r.summary.stages.last().unwrap();
    let w = last.walls["tunnel"];
    let csv = std::fs::read_to_string(out.join("histories.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let row: Vec<f64> = (csv.lines().last().unwrap().split(','))
        .map(|v| v.parse().unwrap())
        .collect();
    let column = |name: &str| row[header.iter().position(|h| *h == name).unwrap()];
    assert_eq!(w.invert_m, column("invert:displacement_y_m"));
    assert_eq!(w.crown_m, -column("crown:displacement_y_m"));
    assert!(
        w.crown_m > 0.0 && w.invert_m > 0.0 && w.left_m > 0.0 && w.right_m > 0.0,
        "{w:?}"
    );
    assert_eq!(w.span_convergence_m, w.left_m + w.right_m);
    assert_eq!(w.height_convergence_m, w.crown_m + w.invert_m);
    assert!(
        r.summary.stages[0].walls.is_empty(),
        "nothing excavated in-situ"
    );
}
