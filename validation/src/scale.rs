//! Builds at scale (issue 14): a region traced from a terrain model with 100 000 vertices, with a
//! tunnel and two non-persistent joint sets, and the tunnel model with about 10 000 joint traces,
//! each cut, meshed and given its blocks and contacts. Every step that paired segments or walked a
//! polygon per query (the cutter, the polygon checks, the labelling of boundary edges, the parts'
//! node lists) goes through a grid or an index, so these take seconds: the 20 000-vertex region
//! took 17 s and the 100 000-vertex one 8.4 min before.

use std::time::Instant;

use adit::Scene;
use adit_meshing::Polygon;

/// One scene built: what it is, its size and its build time.
#[derive(Debug, Clone)]
pub struct Row {
    pub what: String,
    /// Vertices of the region polygon.
    pub region_vertices: usize,
    /// Joint traces the sets drew (before cutting).
    pub traces: usize,
    pub blocks: usize,
    pub zones: usize,
    /// Zoned area over the region's area less the open excavations' (1 when the blocks tile it).
    pub tiling: f64,
    /// Wall seconds of `adit::setup::setup`, s.
    pub seconds: f64,
}

/// A 5 km slope section: a flat base 800 m down, sides, and a ground surface of `vertices` points
/// (two waves, 20 m and 3 m high); a 6 m horseshoe tunnel 300 m under the surface; with `joints`,
/// two sets 25 m apart in traces of 100 m (gaps 50 m), under gravity.
pub fn terrain(vertices: usize, joints: bool) -> Scene {
    let width = 5000.0;
    let n = vertices.max(4) - 2;
    let surface: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let s = i as f64 / (n - 1) as f64;
            let tau = std::f64::consts::TAU;
            [
                0.5 * width - width * s,
                300.0 + 20.0 * (tau * 7.0 * s).sin() + 3.0 * (tau * 331.0 * s).sin(),
            ]
        })
        .collect();
    let mut polygon = vec![[-0.5 * width, -500.0], [0.5 * width, -500.0]];
    polygon.extend(surface);
    let mut names = vec!["base".to_string(), "right".to_string()];
    names.extend(std::iter::repeat_n("surface".to_string(), n - 1));
    names.push("left".to_string());
    let sets = if joints {
        serde_json::json!([
            { "dip": 30, "spacing": 25, "origin": [0.4, 0.3], "trace": 100, "gap": 50, "material": "joint" },
            { "dip": 105, "spacing": 25, "origin": [-0.2, 0.5], "trace": 100, "gap": 50, "material": "joint" }
        ])
    } else {
        serde_json::json!([])
    };
    let scene = serde_json::json!({
        "name": "terrain",
        "materials": { "rock": { "density": 2700, "young": 20e9, "poisson": 0.25 } },
        "region": { "polygon": polygon, "edge_names": names, "material": "rock" },
        "excavations": [
            { "name": "tunnel", "horseshoe": { "center": [0, 0], "radius": 3, "wall_height": 2.5, "segments": 64 } }
        ],
        "zoning": { "edge_at_excavation": 0.5, "edge_far": 50, "grading": 0.25, "min_angle": 25 },
        "joint_materials": {
            "joint": { "normal_stiffness": 2e10, "shear_stiffness": 1e10, "friction": 30 }
        },
        "joint_sets": sets,
        "gravity": [0, -9.81],
        "boundary": [{ "part": "base", "fix": "xy" }, { "part": "left", "fix": "x" }, { "part": "right", "fix": "x" }],
        "solve": { "ratio": 1e-5, "max_cycles": 10 },
        "stages": [{ "name": "gravity" }]
    });
    Scene::from_json(&scene.to_string(), "terrain").expect("a valid terrain scene")
}

/// `models/tunnel.json` with both joint sets 0.25 m apart in traces of 3 m (gaps 2 m): about
/// 10 000 traces.
pub fn dense_joints() -> anyhow::Result<Scene> {
    let mut scene = Scene::load(&crate::repository_root().join("models/tunnel.json"))?;
    for set in &mut scene.joint_sets {
        set.spacing = 0.25;
        set.trace = Some(3.0);
        set.gap = 2.0;
    }
    scene.validate()?;
    Ok(scene)
}

/// Build `scene` and measure it.
pub fn measure(what: &str, scene: &Scene) -> anyhow::Result<Row> {
    scene.validate()?;
    let domain = adit::setup::domain(scene)?;
    let traces = adit::setup::joint_segments(scene, &domain)?.len();
    let start = Instant::now();
    let built = adit::setup::setup(scene)?;
    let seconds = start.elapsed().as_secs_f64();
    let m = &built.model;
    let zoned: f64 = (0..m.zones.len())
        .map(|z| {
            let [a, b, c] = m.zones.nodes[z].map(|k| m.nodes.pos[k as usize]);
            Polygon::new(vec![a, b, c]).signed_area()
        })
        .sum();
    // The rock: the region less the excavations open from the start (a staged one keeps its fill,
    // and inclusions are rock, until a stage removes them).
    let open: f64 = scene
        .excavations
        .iter()
        .zip(&domain.holes)
        .filter(|(e, _)| !scene.is_staged(&e.name))
        .map(|(_, h)| h.polygon.signed_area())
        .sum();
    let rock = domain.outer.signed_area() + open;
    Ok(Row {
        what: what.to_string(),
        region_vertices: scene.region.polygon.len(),
        traces,
        blocks: m.blocks.len(),
        zones: m.zones.len(),
        tiling: zoned / rock,
        seconds,
    })
}

/// The report's rows: the terrain region at 20 000 and 100 000 vertices, bare and jointed, and
/// the tunnel model with about 10 000 traces.
pub fn rows() -> anyhow::Result<Vec<Row>> {
    let mut rows = Vec::new();
    for vertices in [20_000, 100_000] {
        for joints in [false, true] {
            let what = if joints {
                "terrain, jointed"
            } else {
                "terrain"
            };
            rows.push(measure(what, &terrain(vertices, joints))?);
        }
    }
    rows.push(measure("tunnel, sets 0.25 m apart", &dense_joints()?)?);
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Coarse twin of the report's rows: a 100 000-vertex jointed terrain and the tunnel with
    /// about 10 000 traces build, and their zones tile the rock exactly.
    #[test]
    fn a_terrain_region_and_ten_thousand_joints_build_and_tile() {
        let terrain = measure("terrain", &terrain(100_000, true)).unwrap();
        assert_eq!(terrain.region_vertices, 100_000);
        assert!(terrain.blocks > 1000, "{terrain:?}");
        let dense = measure("dense", &dense_joints().unwrap()).unwrap();
        assert!(dense.traces >= 10_000, "{dense:?}");
        for row in [terrain, dense] {
            assert!((row.tiling - 1.0).abs() < 1e-9, "{row:?}");
        }
    }
}
