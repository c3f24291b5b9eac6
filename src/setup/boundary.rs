//! Boundary conditions: fixities on boundary nodes and tractions as consistent nodal loads.

use std::collections::BTreeMap;

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
        apply_condition(
            bc.condition(&format!("{path}[{k}]"))?,
            boundary,
            in_situ,
            &mut scratch,
        )?;
    }
    Ok((scratch.fixed, scratch.applied))
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
    condition: Condition,
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
    let traction = |p: [f64; 2], n: [f64; 2]| match load {
        Load::Stress(s) => traction(&[s.sxx, s.syy, 0.0, s.sxy], n),
        Load::InSitu => traction(&in_situ.at(p[1]), n),
        Load::NormalShear { normal, shear } => {
            [normal * n[0] - shear * n[1], normal * n[1] + shear * n[0]]
        }
    };
    let domain = &boundary.domain;
    let edges = (boundary.edges.iter()).filter(|e| edge_in_part(domain, e.kind, name));
    add_tractions(nodes, edges, traction);
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
