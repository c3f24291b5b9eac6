//! Rigid and simple blocks from the block modes: their bodies, and the rounding of their corners.

use crate::contact::rounding;
use crate::law::ZoneLaw;
use crate::model::blocks::Blocks;
use crate::model::bodies::{Bodies, BodyMode, DOFS, Gram, NO_BODY, polygon_moments, velocity_map};
use crate::model::{BODY, FIX_X, FIX_Y, MaterialId, Nodes};
use crate::scene::{BlockMode, Scene};

/// The rigid and simple blocks of `modes` as bodies of their block's `material`: centroid, area
/// and radius from the polygon, weight ρ A g, the in-situ stress at the centroid for a simple block, fixity from the boundary
/// conditions on their nodes (any fixed node holds the block's rotation and strain, and the
/// translation components it names); their nodes are marked `BODY`.
pub fn bodies(
    modes: &[BlockMode],
    blocks: &Blocks,
    nodes: &mut Nodes,
    material: &[MaterialId],
    laws: &[Box<dyn ZoneLaw>],
    stress_at: impl Fn([f64; 2], MaterialId) -> [f64; 4],
    gravity: [f64; 2],
) -> Bodies {
    let mut out = Bodies {
        of_node: vec![NO_BODY; nodes.len()],
        ..Default::default()
    };
    for (b, &mode) in modes.iter().enumerate() {
        let mode = match mode {
            BlockMode::Deformable => continue,
            BlockMode::Rigid => BodyMode::Rigid,
            BlockMode::Simple => BodyMode::Simple,
        };
        let k = out.len() as u32;
        let range = [blocks.node_start[b], blocks.node_start[b + 1]];
        let m = polygon_moments(blocks.edge_range(b).map(|e| {
            let [p, q] = blocks.edges[e];
            (nodes.pos[p as usize], nodes.pos[q as usize])
        }));
        let c = m.centroid;
        let (mut radius, mut gram): (f64, Gram) = (0.0, [[0.0; DOFS]; DOFS]);
        for n in range[0] as usize..range[1] as usize {
            let p = nodes.pos[n];
            radius = radius.max((p[0] - c[0]).hypot(p[1] - c[1]));
            let t = velocity_map([p[0] - c[0], p[1] - c[1]]);
            for (d, flag) in [FIX_X, FIX_Y].into_iter().enumerate() {
                if nodes.fixed[n] & flag != 0 {
                    for i in 0..DOFS {
                        for j in 0..DOFS {
                            gram[i][j] += t[d][i] * t[d][j];
                        }
                    }
                }
            }
            nodes.fixed[n] |= BODY;
            out.of_node[n] = k;
        }
        let law = laws[material[b].0 as usize].as_ref();
        out.block.push(b as u32);
        out.mode.push(mode);
        out.nodes.push(range);
        out.centroid.push(c);
        out.velocity.push([0.0; DOFS]);
        out.mass.push(m.masses(law.density()));
        out.force.push([0.0; DOFS]);
        out.weight.push([0.0; 2]);
        out.area.push(m.area);
        out.radius.push(radius);
        out.material.push(material[b]);
        out.stress.push(match mode {
            BodyMode::Simple => stress_at(c, material[b]),
            BodyMode::Rigid => [0.0; 4],
        });
        out.state.push(0);
        out.plastic.push(0.0);
        out.constraint.push(gram);
        out.projector.push(None);
        out.step.push((c, c, [1.0, 0.0, 0.0, 1.0]));
    }
    add_body_weight(&mut out, laws, gravity);
    out
}

/// Add the weight ρ A g of each rigid or simple block under gravity `g` (m/s²) to its load, N/m.
pub fn add_body_weight(bodies: &mut Bodies, laws: &[Box<dyn ZoneLaw>], g: [f64; 2]) {
    for k in 0..bodies.len() {
        let mass = laws[bodies.material[k].0 as usize].density() * bodies.area[k];
        bodies.weight[k][0] += mass * g[0];
        bodies.weight[k][1] += mass * g[1];
    }
}

/// Rounding radius of every node: `blocks.round` (default 1 % of the bodies' mean radius) at the
/// convex corners of rigid and simple blocks, 0 elsewhere.
pub fn round(
    scene: &Scene,
    bodies: &Bodies,
    blocks: &Blocks,
    pos: &[[f64; 2]],
    modes: &[BlockMode],
) -> Vec<f64> {
    let mean_radius = bodies.radius.iter().sum::<f64>() / bodies.len() as f64;
    let d = scene.blocks.round.unwrap_or(0.01 * mean_radius);
    rounding::radii(blocks, pos, d, |b| modes[b] != BlockMode::Deformable)
}
