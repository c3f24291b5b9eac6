//! The far field of `region.far_field` attached to a model: the interface is the region's outer
//! boundary as meshed (one boundary element per boundary edge of the zones, or per straight run
//! of them about `element_size` long), its stiffness condensed once
//! (`far_field::interface_stiffness_chains`) and reused at every stage.

use std::collections::BTreeMap;
use std::time::Instant;

use adit_meshing::{BoundaryEdge, EdgeKind};

use super::boundary::traction_loads;
use super::plan::{Boundary, InSituField};
use crate::far_field::{
    FarField, JointSet, Kelvin, Kernel, Medium, Melan, interface_stiffness_chains,
    jointed_compliance, plane_strain_compliance,
};
use crate::model::{Model, traction};
use crate::scene::{RockMass, Scene};

/// Most interface elements a far field takes: its dense matrices hold (4n + 2)² values twice
/// while it is condensed, 1.0 GB at this many (measured: 1 600 elements took 17 s on one thread
/// and 0.74 GB).
pub const MOST_ELEMENTS: usize = 2_000;

/// The far field of `scene` on `model` (None without `region.far_field`); an error naming the
/// element count when the interface has more than `MOST_ELEMENTS`, before anything is allocated.
pub fn far_field(
    scene: &Scene,
    model: &Model,
    boundary: &Boundary,
    in_situ: &InSituField,
) -> anyhow::Result<Option<FarField>> {
    let Some(spec) = &scene.region.far_field else {
        return Ok(None);
    };
    let start = Instant::now();
    let rock = &scene.materials[&scene.region.material];
    let (young, poisson) = (
        spec.young.unwrap_or(rock.young),
        spec.poisson.unwrap_or(rock.poisson),
    );
    let shear = young / (2.0 * (1.0 + poisson));
    let medium = match spec.rock_mass {
        RockMass::Intact => match spec.surface {
            None => Medium::isotropic(shear, poisson),
            Some(surface) => Medium::HalfPlane(Melan {
                kelvin: Kelvin { shear, poisson },
                surface,
            }),
        },
        RockMass::Jointed => {
            let sets: Vec<JointSet> = (0..scene.joint_sets.len())
                .map(|i| {
                    let set = scene.realized_set(i);
                    let joint = &scene.joint_materials[&set.material];
                    // A non-persistent set's joints cover trace/(trace + gap) of each line.
                    let persistence = set.trace.map_or(1.0, |t| t / (t + set.gap));
                    JointSet {
                        dip: set.dip,
                        spacing: set.spacing / persistence,
                        normal_stiffness: joint.normal_stiffness,
                        shear_stiffness: joint.shear_stiffness,
                    }
                })
                .collect();
            let b = jointed_compliance(plane_strain_compliance(young, poisson), &sets);
            Medium::anisotropic(b)
                .map_err(|e| anyhow::anyhow!("region.far_field.rock_mass: {e}"))?
        }
    };
    // The region's outer edges, but those on a half-plane's surface, which stay free.
    let span = crate::scene::coordinate_span(&model.nodes.pos);
    let on_surface =
        |e: &BoundaryEdge| spec.on_surface(&e.nodes.map(|n| model.nodes.pos[n as usize]), span);
    let outer: Vec<&BoundaryEdge> = (boundary.edges.iter())
        .filter(|e| matches!(e.kind, EdgeKind::Region(_)) && !on_surface(e))
        .collect();
    anyhow::ensure!(
        outer.len() <= 2 * MOST_ELEMENTS,
        "region.far_field: the outer boundary is meshed into {} edges, more than the {} nodes a \
         far field takes (its stiffness grows as the square); coarsen zoning.edge_far or shrink \
         the region",
        outer.len(),
        2 * MOST_ELEMENTS
    );
    let chains = match spec.element_size {
        None => outer.iter().map(|e| e.nodes.to_vec()).collect(),
        Some(size) => element_chains(&outer, &model.nodes.pos, size),
    };
    anyhow::ensure!(
        chains.len() <= MOST_ELEMENTS,
        "region.far_field: {} boundary elements, more than the {} a far field takes (its dense \
         matrices grow as the square); make element_size longer",
        chains.len(),
        MOST_ELEMENTS
    );
    let mut local: BTreeMap<u32, usize> = BTreeMap::new();
    let mut nodes = Vec::new();
    let chains: Vec<Vec<usize>> = (chains.iter())
        .map(|c| {
            (c.iter())
                .map(|&n| {
                    *local.entry(n).or_insert_with(|| {
                        nodes.push(n);
                        nodes.len() - 1
                    })
                })
                .collect()
        })
        .collect();
    let points: Vec<[f64; 2]> = nodes.iter().map(|&n| model.nodes.pos[n as usize]).collect();
    let stretch = medium.stretch();
    let stiffness = interface_stiffness_chains(&points, &chains, medium.clone())
        .map_err(|e| anyhow::anyhow!("region.{e}"))?;
    let edges = (outer.iter()).map(|e| e.nodes.map(|n| local[&n])).collect();
    let mut loads = vec![[0.0; 2]; model.nodes.len()];
    let region_edges = (boundary.edges.iter()).filter(|e| matches!(e.kind, EdgeKind::Region(_)));
    traction_loads(&model.nodes.pos, &mut loads, region_edges, |p, n| {
        traction(&in_situ.at(p[1]), n)
    });
    let in_situ = nodes.iter().map(|&n| loads[n as usize]).collect();
    let attached = nodes
        .iter()
        .map(|&n| model.nodes.disp[n as usize])
        .collect();
    Ok(Some(FarField {
        nodes,
        stiffness,
        in_situ,
        attached,
        assemble_s: start.elapsed().as_secs_f64(),
        stretch,
        medium,
        carried: vec![[0.0; 2]; points.len()],
        carried_disp: vec![[0.0; 2]; points.len()],
        positions: points,
        edges,
    }))
}

/// The outer boundary's edges `outer` (material on their left, so in a loop, or in an open curve
/// from surface to surface under a half-plane) grouped into elements of about `size` (m): the
/// loop is cut into runs at the region's corners, where a joint reaches it (an edge's end node
/// starts no edge: the next starts at its twin, the other block's node at the same place) and
/// where the curve ends, and each run of length L into max(1, round(L / size))
/// elements (at most one per edge), each ending at the edge end nearest its share of L. Each
/// element is its chain of nodes from start to end.
fn element_chains(outer: &[&BoundaryEdge], pos: &[[f64; 2]], size: f64) -> Vec<Vec<u32>> {
    let by_start: BTreeMap<u32, usize> = (outer.iter().enumerate())
        .map(|(i, e)| (e.nodes[0], i))
        .collect();
    let at = |n: u32| pos[n as usize];
    let gap = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).hypot(a[1] - b[1]);
    // The edge after each: the one starting at its end node, or else at the same place (a
    // joint's twin node); none where the interface ends (a half-plane's surface).
    let span = crate::scene::coordinate_span(
        (outer.iter()).flat_map(|e| e.nodes.iter().map(|&n| &pos[n as usize])),
    );
    let next: Vec<Option<usize>> = (outer.iter())
        .map(|e| match by_start.get(&e.nodes[1]) {
            Some(&j) => Some(j),
            None => (0..outer.len())
                .find(|&j| gap(at(outer[j].nodes[0]), at(e.nodes[1])) <= 1e-9 * span),
        })
        .collect();
    let breaks_after = |i: usize| match next[i] {
        None => true,
        Some(j) => outer[i].kind != outer[j].kind || outer[i].nodes[1] != outer[j].nodes[0],
    };
    // The runs, walked from the interface's open ends first, then from each break.
    let mut has_previous = vec![false; outer.len()];
    for j in next.iter().flatten() {
        has_previous[*j] = true;
    }
    let starts: Vec<usize> = (0..outer.len())
        .filter(|&i| !has_previous[i])
        .chain(
            (0..outer.len())
                .filter(|&i| breaks_after(i))
                .filter_map(|i| next[i]),
        )
        .collect();
    let mut visited = vec![false; outer.len()];
    let mut runs: Vec<Vec<usize>> = Vec::new();
    for start in starts {
        let (mut run, mut i) = (Vec::new(), start);
        while !visited[i] {
            visited[i] = true;
            run.push(i);
            if breaks_after(i) {
                runs.push(std::mem::take(&mut run));
            }
            match next[i] {
                Some(j) => i = j,
                None => break,
            }
        }
        if !run.is_empty() {
            runs.push(run);
        }
    }
    // A loop without a break, or edges the walks missed, keep one element per edge.
    if runs.is_empty() || visited.contains(&false) {
        return outer.iter().map(|e| e.nodes.to_vec()).collect();
    }
    let mut chains = Vec::new();
    for run in runs {
        let lengths: Vec<f64> = (run.iter())
            .map(|&e| gap(at(outer[e].nodes[0]), at(outer[e].nodes[1])))
            .collect();
        let total: f64 = lengths.iter().sum();
        let count = ((total / size).round() as usize).clamp(1, run.len());
        let mut chain = vec![outer[run[0]].nodes[0]];
        let (mut walked, mut made) = (0.0, 0);
        for (k, (&e, len)) in run.iter().zip(&lengths).enumerate() {
            walked += len;
            chain.push(outer[e].nodes[1]);
            // End the element at this edge's end when it is the run's last, or when it is the
            // end nearest the element's share of the run (the next lies farther past it), or when
            // the edges left are just enough for the elements left.
            let last = k + 1 == run.len();
            let share = total * (made + 1) as f64 / count as f64;
            let nearest = walked + 0.5 * lengths.get(k + 1).copied().unwrap_or(0.0) >= share;
            let (edges_left, elements_left) = (run.len() - 1 - k, count - made - 1);
            if last || (elements_left > 0 && (nearest || edges_left == elements_left)) {
                chains.push(std::mem::take(&mut chain));
                chain.push(outer[e].nodes[1]);
                made += 1;
            }
        }
    }
    chains
}

/// The stretch above which a far field's accuracy along the interface is worth a warning.
const STRETCH_WARNED: f64 = 3.0;

/// A warning for a jointed far field whose field varies along the interface `stretch` times
/// faster than intact rock's (its boundary elements resolve it as elements that many times longer
/// would resolve intact rock: the error on a circle grows about as stretch², `far_field::tests`).
pub fn stretch_warning(stretch: f64) -> Option<String> {
    (stretch > STRETCH_WARNED).then(|| {
        format!(
            "region.far_field: the jointed rock mass is strongly anisotropic (its field varies \
             {stretch:.1} times faster along the interface than intact rock's), so its boundary \
             elements answer about as elements {stretch:.1} times longer would for intact rock; \
             zone the outer boundary finer (zoning.edge_far) or move it farther out"
        )
    })
}
