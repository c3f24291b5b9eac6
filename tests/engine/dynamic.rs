//! Dynamic mode: real masses with the derived time step stay stable without damping, and a
//! suddenly applied load overshoots to about twice its static displacement, as an undamped elastic
//! body must (dynamic amplification factor 2 for a step load).

use adit::Scene;
use adit::setup::setup;
use adit::solve::{Observer, Solver, Status};

const TEXT: &str = r#"{
    "name": "step",
    "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.25 } },
    "region": { "polygon": [[0, 0], [1, 0], [1, 4], [0, 4]], "edge_names": ["bottom", "right", "top", "left"],
                "material": "rock" },
    "zoning": { "edge_at_excavation": 0.25, "edge_far": 0.25 },
    "boundary": [ { "part": "bottom", "fix": "y" }, { "part": "left", "fix": "x" }, { "part": "right", "fix": "x" },
                  { "part": "top", "normal_stress": -1e6 } ],
    "solve": { "mode": "dynamic", "damping": 0, "max_cycles": 4000, "monitor_every": 1 }
}"#;

struct MaxEnergy(f64);
impl Observer for MaxEnergy {
    fn monitored(&mut self, row: &adit::solve::HistoryRow) {
        self.0 = self.0.max(row.kinetic);
    }
}

#[test]
fn undamped_step_load_overshoots_twice_static_and_stays_bounded() {
    let scene = Scene::from_json(TEXT, "step").unwrap();
    let mut b = setup(&scene).unwrap();
    let mut solver = Solver::new(&mut b.model, &scene.solve, 0);
    assert!(solver.params.dt > 0.0 && solver.params.dt == 0.8 * solver.step.dt_critical);
    let top: Vec<usize> = b.plan.boundary.part_nodes["top"]
        .iter()
        .map(|&n| n as usize)
        .collect();
    // Confined column (sides on rollers): static top displacement −p H / M, M = K + 4G/3 = E(1−ν)/((1+ν)(1−2ν)).
    let m = 10e9 * 0.75 / (1.25 * 0.5);
    let u_static = -1e6 * 4.0 / m;
    let (mut peak, mut energy) = (0.0f64, MaxEnergy(0.0));
    solver.spec.max_cycles = 1;
    for _ in 0..4000 {
        let sol = solver.solve(&mut b.model, &mut energy);
        assert!(!matches!(sol.status, Status::Failed(_)), "{:?}", sol.status);
        let u = top.iter().map(|&n| b.model.nodes.disp[n][1]).sum::<f64>() / top.len() as f64;
        peak = peak.min(u);
    }
    let amplification = peak / u_static;
    eprintln!(
        "dynamic amplification {amplification:.4}, peak kinetic energy {:.3e} J/m",
        energy.0
    );
    assert!(
        (1.9..=2.1).contains(&amplification),
        "dynamic amplification {amplification}"
    );
    // Work of the load at the peak bounds the kinetic energy: ½·(p·width)·(2u_static)… ≤ p·width·|2u_static|.
    assert!(
        energy.0 <= 1e6 * 1.0 * 2.0 * u_static.abs(),
        "kinetic energy {}",
        energy.0
    );
}

#[test]
fn a_step_three_times_past_the_limit_stops_with_the_node_named() {
    let scene = Scene::from_json(TEXT, "step").unwrap();
    let mut b = setup(&scene).unwrap();
    let mut solver = Solver::new(&mut b.model, &scene.solve, 0);
    solver.params.dt = 3.0 * solver.step.dt_critical;
    let sol = solver.solve(&mut b.model, &mut adit::solve::Quiet);
    let Status::Failed(reason) = &sol.status else {
        panic!("expected a failure, got {:?}", sol.status)
    };
    assert!(sol.cycles <= 10, "stopped only after {} cycles", sol.cycles);
    assert!(
        reason.contains("unstable: node ") && reason.contains("time step"),
        "{reason}"
    );
}

/// Kuhlemeyer & Lysmer's rule: a scene whose incident wave is too short for its zones is warned,
/// naming the frequency; the same wave through zones ten times finer than its shortest shear
/// wavelength is not.
#[test]
fn zones_too_coarse_for_the_incident_wave_are_warned() {
    let scene = |frequency: f64| {
        let text = serde_json::json!({
            "name": "waves",
            "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.25 } },
            "region": { "polygon": [[0, 0], [4, 0], [4, 40], [0, 40]],
                        "edge_names": ["base", "right", "top", "left"], "material": "rock" },
            "zoning": { "edge_at_excavation": 1.0, "edge_far": 1.0 },
            "boundary": [
                { "part": "base", "quiet": true,
                  "incident": { "wave": "s", "velocity": 0.1, "pulse": "ricker", "frequency": frequency } },
                { "part": "left", "fix": "y" }, { "part": "right", "fix": "y" }
            ],
            "solve": { "mode": "dynamic", "duration": 0.01 }
        });
        Scene::from_json(&text.to_string(), "waves").unwrap()
    };
    let warned = |frequency: f64| {
        (setup(&scene(frequency)).unwrap().warnings.iter())
            .any(|w| w.contains("load histories carry frequencies up to"))
    };
    // Cs = 1 265 m/s: at 40 Hz the Ricker's highest frequency is 96 Hz, its shear wavelength
    // 13 m (13 zone edges of about 1 m); at 100 Hz, 5.3 m.
    assert!(!warned(40.0));
    assert!(warned(100.0));
}

/// `output.interval` writes a dynamic stage's steps every interval of simulated time: a stage of
/// 0.01 s at 0.002 s writes four or five intermediate steps (the interval rounded to whole time
/// steps) and the final one; a scene without a dynamic solve refuses it.
#[test]
fn a_dynamic_stage_writes_its_steps_at_the_interval() {
    let mut text = serde_json::json!({
        "name": "interval",
        "materials": { "rock": { "density": 2500, "young": 1e10, "poisson": 0.25 } },
        "region": { "polygon": [[0, 0], [2, 0], [2, 10], [0, 10]],
                    "edge_names": ["base", "right", "top", "left"], "material": "rock" },
        "zoning": { "edge_at_excavation": 1, "edge_far": 1 },
        "boundary": [{ "part": "base", "quiet": true },
                     { "part": "top", "normal_stress": -1e6,
                       "history": { "pulse": "ricker", "amplitude": 1, "frequency": 100 } }],
        "solve": { "mode": "dynamic", "duration": 0.01 },
        "output": { "interval": 0.002, "checkpoints": false }
    });
    let dir = std::env::temp_dir().join(format!("adit-interval-{}", std::process::id()));
    let scene = Scene::from_json(&text.to_string(), "interval").unwrap();
    let result = adit::run_scene(&scene, &dir, &mut adit::solve::Quiet).unwrap();
    let steps = std::fs::read_dir(&dir)
        .unwrap()
        .filter(|e| {
            let name = e.as_ref().unwrap().file_name();
            let name = name.to_string_lossy();
            name.starts_with("interval_zones_") && name.ends_with(".vtu")
        })
        .count();
    std::fs::remove_dir_all(&dir).unwrap();
    let dt = result.summary.timestep;
    let every = (0.002 / dt).round() as u64;
    // Intermediate steps at the multiples of `every` before the last cycle, then the final one.
    let expected = ((result.summary.cycles - 1) / every) as usize + 1;
    assert!(
        steps == expected && (5..=6).contains(&steps),
        "{steps} steps, {expected} expected"
    );
    text["solve"] = serde_json::json!({});
    text["boundary"] = serde_json::json!([{ "part": "base", "fix": "xy" }]);
    let e = Scene::from_json(&text.to_string(), "interval")
        .err()
        .unwrap();
    assert!(e.to_string().starts_with("output.interval"), "{e}");
}

/// `models/tunnel_rockburst.json` runs as shipped but for a shorter event (0.02 s): its static
/// stages settle, the dynamic stage with its quiet base, free-field sides and quiet top
/// completes, and the run reports a peak particle velocity, the energy the wave brought in and
/// what the joints and supports took of it, the wall blocks' ejection and each bolt's energy.
#[test]
fn the_rockburst_model_runs() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/tunnel_rockburst.json");
    let mut scene = Scene::load(&path).unwrap();
    let event = scene.stages.last_mut().unwrap();
    let solve = event.solve.as_mut().unwrap();
    assert_eq!(solve.mode, adit::scene::SolveMode::Dynamic);
    solve.duration = Some(0.02);
    scene.output.checkpoints = false;
    let dir = std::env::temp_dir().join(format!("adit-rockburst-{}", std::process::id()));
    let r = adit::run_scene(&scene, &dir, &mut adit::solve::Quiet).unwrap();
    let csv = std::fs::read_to_string(dir.join("histories.csv")).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(r.summary.status, "completed");
    let ppv = r.summary.peak_particle_velocity.unwrap().largest_m_per_s;
    assert!(ppv > 0.0 && ppv.is_finite(), "{ppv}");
    // The quiet boundaries' net outflow goes negative as the wave comes in.
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let net = header
        .iter()
        .position(|h| h.starts_with("net out:"))
        .unwrap();
    let least = (csv.lines().skip(1))
        .map(|l| l.split(',').nth(net).unwrap().parse::<f64>().unwrap())
        .fold(0.0, f64::min);
    assert!(least < 0.0, "{least}");
    let last: Vec<f64> = (csv.lines().last().unwrap().split(','))
        .map(|v| v.parse().unwrap())
        .collect();
    for name in ["joints:", "supports:"] {
        let k = header.iter().position(|h| h.starts_with(name)).unwrap();
        assert!(last[k] > 0.0 && last[k].is_finite(), "{name} {}", last[k]);
    }
    let ejection = &r.summary.ejection;
    assert!(!ejection.is_empty());
    assert!(
        ejection
            .windows(2)
            .all(|w| w[0].peak_velocity_m_per_s >= w[1].peak_velocity_m_per_s)
    );
    assert!(
        ejection
            .iter()
            .all(|e| e.mass_kg_per_m > 0.0 && e.excavation == "tunnel")
    );
    assert!(
        r.summary.bolts.iter().all(|b| b.energy_j > 0.0),
        "{:?}",
        r.summary.bolts
    );
}
