//! From a validated scene to a model: mesh the region, create nodes and zones, initialise the
//! in-situ stress, and apply fixities, boundary tractions and gravity.

use std::collections::BTreeMap;

use adit_meshing::{
    BoundaryEdge, Domain, EdgeKind, Hole, MeshError, MeshStats, Polygon, TriMesh, Zoning,
    triangulate,
};

use crate::law::{Elastic, ZoneLaw};
use crate::model::{FIX_X, FIX_Y, Gather, MaterialId, Model, Nodes, Zones};
use crate::scene::{BoundaryCondition, Fix, InSitu, Scene};

/// A model ready to cycle, with what was learnt while building it.
pub struct Built {
    pub model: Model,
    pub mesh: MeshStats,
    /// Boundary nodes of each named part (`outer`, region edge names, excavation names), sorted.
    pub part_nodes: BTreeMap<String, Vec<u32>>,
    /// Boundary edges of the mesh, material on the left, labelled by domain part.
    pub boundary: Vec<BoundaryEdge>,
    /// The validated domain the mesh covers.
    pub domain: Domain,
}

/// The domain (region with excavation holes) a scene describes.
pub fn domain(scene: &Scene) -> Result<Domain, MeshError> {
    let outer = Polygon::new(scene.region.polygon.clone());
    let holes = scene
        .excavations
        .iter()
        .map(|e| {
            let polygon = match (&e.circle, &e.polygon) {
                (Some(c), _) => Polygon::circle(c.center, c.radius, c.segments),
                (None, Some(p)) => Polygon::new(p.clone()),
                (None, None) => unreachable!("validated: one shape per excavation"),
            };
            Hole {
                name: e.name.clone(),
                polygon,
            }
        })
        .collect();
    Domain::new(outer, scene.edge_names(), holes)
}

/// The scene field a meshing error is about: `region.polygon` or `excavations[i]`.
fn field_of(scene: &Scene, err: &MeshError) -> String {
    let shape = match err {
        MeshError::Degenerate { shape, .. }
        | MeshError::SelfIntersecting { shape, .. }
        | MeshError::HoleOutside { shape, .. } => shape.as_str(),
        MeshError::HolesOverlap { a, .. } => a.as_str(),
        MeshError::Zoning(_) | MeshError::Triangulation(_) => return "zoning".into(),
    };
    match scene.excavations.iter().position(|e| e.name == shape) {
        Some(i) => format!("excavations[{i}]"),
        None => "region.polygon".into(),
    }
}

/// Mesh a scene's domain with its zoning controls; errors name the scene field.
pub fn mesh(scene: &Scene) -> anyhow::Result<(Domain, TriMesh)> {
    mesh_domain(scene).map_err(|e| anyhow::anyhow!("{}: {e}", field_of(scene, &e)))
}

fn mesh_domain(scene: &Scene) -> Result<(Domain, TriMesh), MeshError> {
    let domain = domain(scene)?;
    let z = &scene.zoning;
    let zoning = Zoning {
        h_excavation: z.edge_at_excavation,
        h_far: z.edge_far,
        grading: z.grading,
        min_angle_deg: z.min_angle,
        max_zones: z.max_zones,
    };
    let mesh = triangulate(&domain, &zoning)?;
    Ok((domain, mesh))
}

/// In-situ stress at elevation y, Pa: [σxx, σyy, σzz, σxy], σzz defaulting to ν(σxx + σyy).
pub fn in_situ_stress(s: &InSitu, y: f64, poisson: f64) -> [f64; 4] {
    let dy = y - s.y_ref;
    let sxx = s.sxx + s.gradient.sxx * dy;
    let syy = s.syy + s.gradient.syy * dy;
    let szz = match s.szz {
        Some(v) => v + s.gradient.szz * dy,
        None => poisson * (sxx + syy),
    };
    [sxx, syy, szz, s.sxy]
}

/// Build the model of a validated scene.
pub fn build(scene: &Scene) -> anyhow::Result<Built> {
    let (domain, mesh) = mesh(scene)?;
    let stats = mesh.stats();
    let mut nodes = Nodes::at(mesh.points.clone());
    let mut zones = Zones::from_triangles(&mesh.triangles, &nodes.pos);

    let material_names: Vec<String> = scene.materials.keys().cloned().collect();
    let laws: Vec<Box<dyn ZoneLaw>> = scene
        .materials
        .values()
        .map(|m| Box::new(Elastic::from_young(m.young, m.poisson, m.density)) as Box<dyn ZoneLaw>)
        .collect();
    let region_mat = material_names
        .iter()
        .position(|n| *n == scene.region.material)
        .expect("validated");
    let poisson = scene.materials[&scene.region.material].poisson;
    for z in 0..zones.len() {
        zones.material[z] = MaterialId(region_mat as u32);
        let c = zones.centroid(z, &nodes.pos);
        zones.stress[z] = in_situ_stress(&scene.in_situ, c[1], poisson);
    }

    // Gravity: body force ρ g A / 3 on each corner (lumped).
    if scene.gravity != [0.0, 0.0] {
        for z in 0..zones.len() {
            let w = laws[zones.material[z].0 as usize].density() * zones.area[z] / 3.0;
            for &n in &zones.nodes[z] {
                nodes.applied[n as usize][0] += w * scene.gravity[0];
                nodes.applied[n as usize][1] += w * scene.gravity[1];
            }
        }
    }

    let names = &domain.outer_edge_names;
    let edge_in_part = |kind: EdgeKind, name: &str| match kind {
        EdgeKind::Region(i) => name == "outer" || names[i as usize] == name,
        EdgeKind::Excavation(j) => domain.holes[j as usize].name == name,
        EdgeKind::Joint(_) => false,
    };
    let mut part_nodes = BTreeMap::new();
    for name in scene.part_names() {
        let mut list: Vec<u32> = mesh
            .boundary
            .iter()
            .filter(|e| edge_in_part(e.kind, &name))
            .flat_map(|e| e.nodes)
            .collect();
        list.sort_unstable();
        list.dedup();
        part_nodes.insert(name, list);
    }
    for bc in &scene.boundary {
        apply_condition(bc, scene, &mesh, &mut nodes, &part_nodes, &|p| {
            edge_in_part(p, bc.part.as_deref().unwrap_or(""))
        });
    }

    let size = domain.outer.size();
    let gather = Gather::new(nodes.len(), &zones.nodes);
    let model = Model {
        nodes,
        zones,
        gather,
        laws,
        material_names,
        size,
    };
    Ok(Built {
        model,
        mesh: stats,
        part_nodes,
        boundary: mesh.boundary,
        domain,
    })
}

fn fix_flags(f: Fix) -> u8 {
    match f {
        Fix::X => FIX_X,
        Fix::Y => FIX_Y,
        Fix::XY => FIX_X | FIX_Y,
    }
}

/// Apply one boundary condition: fixities on nodes, tractions as consistent nodal loads.
fn apply_condition(
    bc: &BoundaryCondition,
    scene: &Scene,
    mesh: &TriMesh,
    nodes: &mut Nodes,
    part_nodes: &BTreeMap<String, Vec<u32>>,
    in_part: &dyn Fn(EdgeKind) -> bool,
) {
    if let Some(at) = bc.at {
        let all: Vec<u32> = part_nodes.values().flatten().copied().collect();
        let d2 = |n: u32| {
            let p = nodes.pos[n as usize];
            (p[0] - at[0]).powi(2) + (p[1] - at[1]).powi(2)
        };
        if let Some(&n) = all.iter().min_by(|&&a, &&b| d2(a).total_cmp(&d2(b))) {
            nodes.fixed[n as usize] |= fix_flags(bc.fix.expect("validated: point conditions fix"));
        }
        return;
    }
    let name = bc.part.as_deref().expect("validated: part or at");
    if let Some(f) = bc.fix {
        for &n in &part_nodes[name] {
            nodes.fixed[n as usize] |= fix_flags(f);
        }
    }
    let poisson = scene.materials[&scene.region.material].poisson;
    let traction = |p: [f64; 2], n: [f64; 2]| -> Option<[f64; 2]> {
        let s = if let Some(s) = bc.stress {
            [s.sxx, s.syy, 0.0, s.sxy]
        } else if bc.in_situ_traction {
            in_situ_stress(&scene.in_situ, p[1], poisson)
        } else if bc.normal_stress.is_some() || bc.shear_stress.is_some() {
            let (sn, tau) = (
                bc.normal_stress.unwrap_or(0.0),
                bc.shear_stress.unwrap_or(0.0),
            );
            return Some([sn * n[0] - tau * n[1], sn * n[1] + tau * n[0]]);
        } else {
            return None;
        };
        Some([s[0] * n[0] + s[3] * n[1], s[3] * n[0] + s[1] * n[1]])
    };
    if bc.stress.is_some()
        || bc.in_situ_traction
        || bc.normal_stress.is_some()
        || bc.shear_stress.is_some()
    {
        let edges = mesh.boundary.iter().filter(|e| in_part(e.kind));
        add_tractions(nodes, edges, |p, n| {
            traction(p, n).expect("a load is given")
        });
    }
}

/// Add the consistent nodal loads of a traction t(p, n) (Pa, at point p with outward unit normal
/// n) over boundary edges (material on the left of each edge): for t varying linearly along an
/// edge of length L, (2tₐ + t_b)L/6 to its first node and (tₐ + 2t_b)L/6 to its second.
pub fn add_tractions<'a>(
    nodes: &mut Nodes,
    edges: impl Iterator<Item = &'a BoundaryEdge>,
    traction: impl Fn([f64; 2], [f64; 2]) -> [f64; 2],
) {
    for e in edges {
        let [a, b] = e.nodes.map(|n| n as usize);
        let (pa, pb) = (nodes.pos[a], nodes.pos[b]);
        let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
        let len = (dx * dx + dy * dy).sqrt();
        let n = [dy / len, -dx / len];
        let (ta, tb) = (traction(pa, n), traction(pb, n));
        for d in 0..2 {
            nodes.applied[a][d] += (2.0 * ta[d] + tb[d]) * len / 6.0;
            nodes.applied[b][d] += (ta[d] + 2.0 * tb[d]) * len / 6.0;
        }
    }
}

#[cfg(test)]
mod tests {
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
        let msg = build(&s).err().unwrap().to_string();
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
        let msg = build(&s).err().unwrap().to_string();
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
        let b = build(&s).unwrap();
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
        // The traction on the top edge (n = +y) is (σxy, σyy) over 10 m.
        let top: f64 = b.part_nodes["edge2"]
            .iter()
            .map(|&n| b.model.nodes.applied[n as usize][1])
            .sum();
        assert!(
            (top - (-2e6 * 10.0 - 1e6 * 0.0)).abs() < 1e-3 * 2e7,
            "{top}"
        );
    }
}
