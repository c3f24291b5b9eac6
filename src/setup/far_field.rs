//! The far field of `region.far_field` attached to a model: the interface is the region's outer
//! boundary as meshed (one boundary element per boundary edge of the zones), its stiffness
//! condensed once (`far_field::interface_stiffness_on`) and reused at every stage.

use std::collections::BTreeMap;
use std::time::Instant;

use adit_meshing::EdgeKind;

use super::boundary::traction_loads;
use super::plan::{Boundary, InSituField};
use crate::far_field::{FarField, Medium, interface_stiffness_on};
use crate::model::{Model, traction};
use crate::scene::Scene;

/// Most interface elements a far field takes: its dense matrices hold (4n + 2)² values twice
/// while it is condensed, 1.0 GB at this many (measured: 1 600 elements took 15 s and 0.74 GB).
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
    let medium = Medium {
        shear: young / (2.0 * (1.0 + poisson)),
        poisson,
    };
    let outer: Vec<[u32; 2]> = (boundary.edges.iter())
        .filter(|e| matches!(e.kind, EdgeKind::Region(_)))
        .map(|e| e.nodes)
        .collect();
    anyhow::ensure!(
        outer.len() <= MOST_ELEMENTS,
        "region.far_field: the outer boundary is meshed into {} edges, more than the {} boundary \
         elements a far field takes (its dense matrices grow as the square); coarsen \
         zoning.edge_far or shrink the region",
        outer.len(),
        MOST_ELEMENTS
    );
    let mut local: BTreeMap<u32, usize> = BTreeMap::new();
    let mut nodes = Vec::new();
    let edges: Vec<[usize; 2]> = (outer.iter())
        .map(|e| {
            e.map(|n| {
                *local.entry(n).or_insert_with(|| {
                    nodes.push(n);
                    nodes.len() - 1
                })
            })
        })
        .collect();
    let points: Vec<[f64; 2]> = nodes.iter().map(|&n| model.nodes.pos[n as usize]).collect();
    let stiffness = interface_stiffness_on(&points, &edges, medium)
        .map_err(|e| anyhow::anyhow!("region.{e}"))?;
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
    }))
}
