//! Pieces the integration tests share.

use std::io::Read;
use std::process::Child;
use std::time::{Duration, Instant};

/// Elastic rock (E = 10 GPa, ν = 0.25) under hydrostatic 10 MPa with a 1 m tunnel excavated in
/// the second stage with half the in-situ traction left on the wall, and released in the third.
pub const STAGED_TUNNEL: &str = r#"{
        "name": "staged",
        "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.25 } },
        "region": { "polygon": [[-12, -12], [12, -12], [12, 12], [-12, 12]], "material": "rock" },
        "excavations": [{ "name": "tunnel", "circle": { "center": [0, 0], "radius": 1, "segments": 96 } }],
        "zoning": { "edge_at_excavation": 0.1, "edge_far": 2.0, "grading": 0.25 },
        "in_situ": { "sxx": -10e6, "syy": -10e6 },
        "boundary": [ { "part": "outer", "in_situ_traction": true },
                      { "at": [12, 0], "fix": "y" }, { "at": [-12, 0], "fix": "y" },
                      { "at": [0, 12], "fix": "x" }, { "at": [0, -12], "fix": "x" } ],
        "solve": { "ratio": 1e-6 },
        "stages": [
            { "name": "in-situ" },
            { "name": "excavate", "excavate": ["tunnel"], "support_fraction": 0.5 },
            { "name": "release", "support_fraction": 0.0 }
        ]
    }"#;

/// `STAGED_TUNNEL` zoned to a box of ±4 m with the elastic far field outside, solved by `method`.
pub fn staged_with_far_field(method: &str) -> adit::Scene {
    let text = STAGED_TUNNEL
        .replace(
            "[[-12, -12], [12, -12], [12, 12], [-12, 12]]",
            "[[-4, -4], [4, -4], [4, 4], [-4, 4]]",
        )
        .replace(
            r#""material": "rock" },"#,
            r#""material": "rock", "far_field": { "kind": "boundary_elements" } },"#,
        )
        .replace(r#"{ "part": "outer", "in_situ_traction": true },"#, "")
        .replace("[12, 0]", "[4, 0]")
        .replace("[-12, 0]", "[-4, 0]")
        .replace("[0, 12]", "[0, 4]")
        .replace("[0, -12]", "[0, -4]")
        .replace(
            r#""ratio": 1e-6 }"#,
            &format!(r#""ratio": 1e-7, "method": "{method}" }}"#),
        );
    adit::Scene::from_json(&text, "far").unwrap()
}

/// A lone rigid block in a dynamic run: nothing to derive a time step from.
pub const LONE_RIGID_BLOCK: &str = r#"{
    "name": "lone",
    "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.25 } },
    "region": { "polygon": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "rock" },
    "zoning": { "edge_at_excavation": 0.5, "edge_far": 0.5 },
    "blocks": { "mode": "rigid" },
    "gravity": [0, -9.81],
    "solve": { "mode": "dynamic", "damping": 0, "max_cycles": 10 }
}"#;

/// Wait for `child` (spawned with stderr piped) at most `limit`, killing it after: its exit code
/// (None if killed or ended by a signal) and its stderr.
pub fn wait_at_most(mut child: Child, limit: Duration) -> (Option<i32>, String) {
    let start = Instant::now();
    let code = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status.code();
        }
        if start.elapsed() > limit {
            child.kill().unwrap();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    let mut err = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    (code, err)
}
