//! Boundary conditions: fixities on boundary nodes and tractions as consistent nodal loads.

use std::collections::BTreeMap;

use adit_meshing::geometry::segment_distance;
use adit_meshing::{BoundaryEdge, Domain, EdgeKind};

use super::plan::{Boundary, InSituField};
use crate::model::{FIX_X, FIX_Y, Nodes, traction};
use crate::scene::{BoundaryCondition, Condition, Fix, Load, Scene};

/// Whether a boundary edge of `kind` belongs to the part `name`: `outer` takes every region edge,
/// a region edge name its own, an excavation name its walls.
pub fn edge_in_part(domain: &Domain, kind: EdgeKind, name: &str) -> bool {
    match kind {
        EdgeKind::Region(i) => name == "outer" || domain.outer_edge_names[i as usize] == name,
        EdgeKind::Excavation(j) => domain.holes[j as usize].name == name,
        EdgeKind::Joint(_) => false,
    }
}

/// The boundary nodes of each part a condition may name (`Scene::part_names`), ascending, in one
/// pass over the boundary edges: the parts of an edge are `outer` and its region edge's name, or
/// its excavation's name.
pub fn part_nodes(
    scene: &Scene,
    domain: &Domain,
    boundary: &[BoundaryEdge],
) -> BTreeMap<String, Vec<u32>> {
    let mut parts: BTreeMap<String, Vec<u32>> = scene
        .part_names()
        .into_iter()
        .map(|name| (name, Vec::new()))
        .collect();
    let mut add = |name: &str, nodes: [u32; 2]| {
        if let Some(list) = parts.get_mut(name) {
            list.extend(nodes);
        }
    };
    for e in boundary {
        match e.kind {
            EdgeKind::Region(i) => {
                add("outer", e.nodes);
                add(&domain.outer_edge_names[i as usize], e.nodes);
            }
            EdgeKind::Excavation(j) => add(&domain.holes[j as usize].name, e.nodes),
            EdgeKind::Joint(_) => {}
        }
    }
    for list in parts.values_mut() {
        list.sort_unstable();
        list.dedup();
    }
    parts
}

/// Fixity flags of each node (`FIX_X`, `FIX_Y`) and its consistent nodal load, N/m, from a list of
/// boundary conditions.
pub type BoundaryEffect = (Vec<u8>, Vec<[f64; 2]>);

/// Fixity flags and consistent nodal loads (N/m) of the boundary conditions `conditions` alone, on
/// nodes at `pos`, as `setup` applies them; `path` names the list in errors.
pub fn boundary_effect(
    conditions: &[BoundaryCondition],
    path: &str,
    boundary: &Boundary,
    in_situ: &InSituField,
    pos: &[[f64; 2]],
) -> anyhow::Result<BoundaryEffect> {
    let mut scratch = Nodes::at(pos.to_vec());
    for (k, bc) in conditions.iter().enumerate() {
        let path = format!("{path}[{k}]");
        let mut condition = bc.condition(&path)?;
        // A load with a history is the dynamic inputs' (`history_loads`), not a constant one.
        if let (Condition::Part { load, .. }, Some(_)) = (&mut condition, &bc.history) {
            *load = None;
        }
        apply_condition(condition, &path, boundary, in_situ, &mut scratch)?;
    }
    Ok((scratch.fixed, scratch.applied))
}

/// Nodes and the load on each, N/m.
pub type NodalLoads = Vec<(u32, [f64; 2])>;

/// The consistent nodal loads (N/m at h = 1) of each condition of `conditions` with a load
/// history, as `(k, loads)`: the nodes its traction loads, ascending.
pub fn history_loads(
    conditions: &[BoundaryCondition],
    boundary: &Boundary,
    in_situ: &InSituField,
    pos: &[[f64; 2]],
) -> Vec<(usize, NodalLoads)> {
    let mut out = Vec::new();
    let mut loads = vec![[0.0; 2]; pos.len()];
    for (k, bc) in conditions.iter().enumerate() {
        let (
            Some(_),
            Some(name),
            Ok(Condition::Part {
                load: Some(load), ..
            }),
        ) = (&bc.history, &bc.part, bc.condition(""))
        else {
            continue;
        };
        let edges =
            (boundary.edges.iter()).filter(|e| edge_in_part(&boundary.domain, e.kind, name));
        traction_loads(pos, &mut loads, edges, traction_of(load, in_situ));
        let nodes = (loads.iter_mut().enumerate())
            .filter(|(_, f)| **f != [0.0; 2])
            .map(|(n, f)| (n as u32, std::mem::take(f)))
            .collect();
        out.push((k, nodes));
    }
    out
}

/// The traction t(p, n) (Pa at point p, m, with outward unit normal n) of a load.
fn traction_of(load: Load, in_situ: &InSituField) -> impl Fn([f64; 2], [f64; 2]) -> [f64; 2] + '_ {
    move |p, n| match load {
        Load::Stress(s) => traction(&[s.sxx, s.syy, 0.0, s.sxy], n),
        Load::InSitu => traction(&in_situ.at(p[1]), n),
        Load::NormalShear { normal, shear } => {
            [normal * n[0] - shear * n[1], normal * n[1] + shear * n[0]]
        }
    }
}

fn fix_flags(f: Fix) -> u8 {
    match f {
        Fix::X => FIX_X,
        Fix::Y => FIX_Y,
        Fix::XY => FIX_X | FIX_Y,
    }
}

/// Apply one boundary condition, the scene's `path`: fixities on nodes, tractions as consistent
/// nodal loads.
fn apply_condition(
    condition: Condition,
    path: &str,
    boundary: &Boundary,
    in_situ: &InSituField,
    nodes: &mut Nodes,
) -> anyhow::Result<()> {
    let part_nodes = &boundary.part_nodes;
    let (name, fix, load) = match condition {
        Condition::Point { at, fix } => {
            let all: Vec<u32> = part_nodes.values().flatten().copied().collect();
            let d2 = |n: u32| {
                let p = nodes.pos[n as usize];
                (p[0] - at[0]).powi(2) + (p[1] - at[1]).powi(2)
            };
            refuse_far_point(path, at, &nodes.pos, boundary)?;
            if let Some(&n) = all.iter().min_by(|&&a, &&b| d2(a).total_cmp(&d2(b))) {
                nodes.fixed[n as usize] |= fix_flags(fix);
            }
            return Ok(());
        }
        Condition::Part { name, fix, load } => (name, fix, load),
    };
    if let Some(f) = fix {
        let Some(part) = part_nodes.get(name) else {
            anyhow::bail!("boundary: no part '{name}'");
        };
        for &n in part {
            nodes.fixed[n as usize] |= fix_flags(f);
        }
    }
    let Some(load) = load else {
        return Ok(());
    };
    let domain = &boundary.domain;
    let edges = (boundary.edges.iter()).filter(|e| edge_in_part(domain, e.kind, name));
    add_tractions(nodes, edges, traction_of(load, in_situ));
    Ok(())
}

/// A point fixity at `at` (m) holds the boundary node nearest it: an error naming `path` when the
/// point is farther from the nearest wall or region edge than that edge is long (the point is off
/// the boundary, and the node taken may be on another wall than the one meant: inside a box, a
/// point took the tunnel's wall).
fn refuse_far_point(
    path: &str,
    at: [f64; 2],
    pos: &[[f64; 2]],
    boundary: &Boundary,
) -> anyhow::Result<()> {
    let nearest = (boundary.edges.iter())
        .filter(|e| !matches!(e.kind, EdgeKind::Joint(_)))
        .map(|e| {
            let [a, b] = e.nodes.map(|n| pos[n as usize]);
            let length = (a[0] - b[0]).hypot(a[1] - b[1]);
            (segment_distance(at, a, b), length)
        })
        .min_by(|x, y| x.0.total_cmp(&y.0));
    if let Some((d, length)) = nearest.filter(|&(d, length)| d > length) {
        anyhow::bail!(
            "{path}.at: ({}, {}) m is {d:.3} m from the boundary, farther than its edge there is \
             long ({length:.3} m): a point fixity holds the node of the region's or an \
             excavation's boundary nearest it; give a point on that boundary",
            at[0],
            at[1]
        );
    }
    Ok(())
}

/// Add the consistent nodal loads of a traction t(p, n) (Pa, at point p with outward unit normal
/// n) over boundary edges (material on the left of each edge): for t varying linearly along an
/// edge of length L, (2tₐ + t_b)L/6 to its first node and (tₐ + 2t_b)L/6 to its second.
pub fn add_tractions<'a>(
    nodes: &mut Nodes,
    edges: impl Iterator<Item = &'a BoundaryEdge>,
    traction: impl Fn([f64; 2], [f64; 2]) -> [f64; 2],
) {
    traction_loads(&nodes.pos, &mut nodes.applied, edges, traction);
}

/// `add_tractions` into `loads` (N/m per node) for nodes at `pos` (m).
pub fn traction_loads<'a>(
    pos: &[[f64; 2]],
    loads: &mut [[f64; 2]],
    edges: impl Iterator<Item = &'a BoundaryEdge>,
    traction: impl Fn([f64; 2], [f64; 2]) -> [f64; 2],
) {
    for e in edges {
        let [a, b] = e.nodes.map(|n| n as usize);
        let (pa, pb) = (pos[a], pos[b]);
        let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
        let len = (dx * dx + dy * dy).sqrt();
        let n = [dy / len, -dx / len];
        let (ta, tb) = (traction(pa, n), traction(pb, n));
        for d in 0..2 {
            loads[a][d] += (2.0 * ta[d] + tb[d]) * len / 6.0;
            loads[b][d] += (ta[d] + 2.0 * tb[d]) * len / 6.0;
        }
    }
}

#[cfg(test)]
mod tests {
    fn scene(at: [f64; 2]) -> crate::Scene {
        let text = format!(
            r#"{{ "name": "p", "materials": {{ "rock": {{ "density": 2600, "young": 2e10, "poisson": 0.25 }} }},
              "region": {{ "polygon": [[-10, -10], [10, -10], [10, 10], [-10, 10]], "material": "rock" }},
              "excavations": [{{ "name": "t", "circle": {{ "center": [0, 0], "radius": 1, "segments": 32 }} }}],
              "zoning": {{ "edge_at_excavation": 0.5, "edge_far": 2 }},
              "boundary": [{{ "part": "outer", "stress": {{ "sxx": -1e6, "syy": -1e6, "sxy": 0 }} }},
                           {{ "at": [{}, {}], "fix": "xy" }}] }}"#,
            at[0], at[1]
        );
        crate::Scene::from_json(&text, "p").unwrap()
    }

    /// A point fixity inside the rock, 4 m from the tunnel's wall and 5 m from the box's side, is
    /// refused, naming the condition; points on the side, or off it by less than an edge, hold
    /// the node nearest them.
    #[test]
    fn a_point_fixity_off_the_boundary_is_refused() {
        let e = crate::setup::setup(&scene([5.0, 0.0])).err().unwrap();
        let e = format!("{e:#}");
        assert!(e.contains("boundary[1].at: (5, 0) m is 4.0"), "{e}");
        for at in [[10.0, 0.3], [10.2, -10.1], [-1.0, 0.05]] {
            let built = crate::setup::setup(&scene(at)).unwrap();
            let fixed = built.model.nodes.fixed.iter().filter(|&&f| f != 0).count();
            assert_eq!(fixed, 1, "at {at:?}");
        }
    }
}
