//! The flow network of a model's joints: a domain wherever joint faces' boundary nodes meet (the
//! two faces of a joint are zoned with their nodes at the same places, so each place is one
//! domain, and where joints cross, the corners of every block around it are one), a pipe along
//! each joint edge between two blocks, its two faces one pipe.

use std::collections::HashMap;

use adit_meshing::EdgeKind;

use super::{DomainId, Network};
use crate::model::blocks::Blocks;

/// Marks a node on no joint in `JointNetwork::domain_of`.
pub const NO_DOMAIN: u32 = u32::MAX;

/// A model's joint network and where it sits on the model.
#[derive(Debug, Clone, Default)]
pub struct JointNetwork {
    pub network: Network,
    /// For each node, the domain it bounds, or `NO_DOMAIN`.
    pub domain_of: Vec<u32>,
    /// For each pipe, the boundary edges of its two faces.
    pub faces: Vec<[u32; 2]>,
}

/// The network of the joints between the blocks still in place, at node positions `pos` (m),
/// each pipe's aperture from `aperture` (the kind of joint its edge lies on → m); a domain's
/// volume is half its pipes' a·l, m² per metre, its elevation its place's y. Domains sit where
/// the nodes are bit for bit at the same place (the model as set up, before it moves).
pub fn joint_network(
    blocks: &Blocks,
    pos: &[[f64; 2]],
    aperture: impl Fn(EdgeKind) -> f64,
) -> JointNetwork {
    let mut out = JointNetwork {
        domain_of: vec![NO_DOMAIN; pos.len()],
        ..Default::default()
    };
    let mut at_place: HashMap<[u64; 2], DomainId> = HashMap::new();
    let mut pipe_of: HashMap<[u32; 2], usize> = HashMap::new();
    for b in 0..blocks.len() {
        if blocks.is_removed(b) {
            continue;
        }
        for e in blocks.edge_range(b) {
            if !matches!(blocks.edge_kind[e], EdgeKind::Joint(_))
                || blocks.across(e as u32).is_none()
            {
                continue;
            }
            let ends = blocks.edges[e].map(|n| {
                let p = pos[n as usize];
                let d = *at_place
                    .entry(p.map(f64::to_bits))
                    .or_insert_with(|| out.network.add_domain(0.0, p[1], 0.0));
                out.domain_of[n as usize] = d.0;
                d
            });
            let key = if ends[0].0 < ends[1].0 {
                [ends[0].0, ends[1].0]
            } else {
                [ends[1].0, ends[0].0]
            };
            match pipe_of.get(&key) {
                Some(&k) => out.faces[k][1] = e as u32,
                None => {
                    let [p, q] = blocks.edges[e].map(|n| pos[n as usize]);
                    let length = (q[0] - p[0]).hypot(q[1] - p[1]);
                    let a = aperture(blocks.edge_kind[e]);
                    pipe_of.insert(key, out.network.pipes.len());
                    out.network.add_pipe(ends[0], ends[1], a, length);
                    out.faces.push([e as u32, e as u32]);
                }
            }
        }
    }
    let (domains, pipes) = (&mut out.network.domains, &out.network.pipes);
    for ((&[a, b], &ap), &l) in pipes.ends.iter().zip(&pipes.aperture).zip(&pipes.length) {
        domains.volume[a.0 as usize] += 0.5 * ap * l;
        domains.volume[b.0 as usize] += 0.5 * ap * l;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flow::{Fluid, solve_steady};

    /// A 10 m square cut into four blocks by two joints crossing at its centre: one domain where
    /// the four corners meet, a tree of pipes (one fewer than the domains), both faces of each
    /// joint edge one pipe; held at 1 MPa at the left end of the horizontal joint and 0 at its
    /// right, the centre carries half the pressure and the vertical joint none of the flow.
    #[test]
    fn two_crossing_joints_make_one_tree_of_pipes() {
        let text = r#"{ "name": "cross",
            "materials": { "rock": { "density": 2500, "young": 1e10, "poisson": 0.25 } },
            "region": { "polygon": [[0, 0], [10, 0], [10, 10], [0, 10]], "material": "rock" },
            "zoning": { "edge_at_excavation": 1, "edge_far": 1 },
            "joint_materials": { "j": { "law": "glued", "normal_stiffness": 1e10, "shear_stiffness": 1e10 } },
            "joints": [ { "from": [0, 5], "to": [10, 5], "material": "j" },
                        { "from": [5, 0], "to": [5, 10], "material": "j" } ] }"#;
        let scene = crate::Scene::from_json(text, "cross").unwrap();
        let model = crate::setup::setup(&scene).unwrap().model;
        let pos = &model.nodes.pos;
        let j = joint_network(&model.blocks, pos, |_| 1e-4);
        let net = &j.network;
        assert_eq!(model.blocks.len(), 4);
        assert_eq!(net.domains.len(), net.pipes.len() + 1);
        assert!(j.faces.iter().all(|f| f[0] != f[1]), "a pipe with one face");
        let total: f64 = net.pipes.length.iter().sum();
        assert!((total - 20.0).abs() < 1e-9, "{total}");
        let place = |x: f64, y: f64| {
            (0..pos.len())
                .find(|&n| j.domain_of[n] != NO_DOMAIN && pos[n] == [x, y])
                .map(|n| j.domain_of[n])
                .expect("a domain there")
        };
        let centre = place(5.0, 5.0);
        let corners = (0..pos.len()).filter(|&n| j.domain_of[n] == centre).count();
        assert_eq!(corners, 4);
        let mut net = net.clone();
        net.fix(DomainId(place(0.0, 5.0)), 1e6);
        net.fix(DomainId(place(10.0, 5.0)), 0.0);
        solve_steady(&mut net, &Fluid::WATER, 0.0).unwrap();
        assert!((net.domains.pressure[centre as usize] - 5e5).abs() < 1e-6);
        let top = place(5.0, 10.0) as usize;
        assert!((net.domains.pressure[top] - 5e5).abs() < 1e-6);
    }

    /// The bundled tunnel's joint sets (written for the mechanics, not for this): every joint
    /// edge between two blocks is one pipe of two faces whose nodes sit at its domains, and the
    /// network is a valid one.
    #[test]
    fn the_tunnel_models_joints_make_a_valid_network() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/tunnel.json");
        let scene = crate::Scene::from_json(&std::fs::read_to_string(path).unwrap(), path).unwrap();
        let model = crate::setup::setup(&scene).unwrap().model;
        let (blocks, pos) = (&model.blocks, &model.nodes.pos);
        let j = joint_network(blocks, pos, |_| 1e-4);
        assert!(j.network.pipes.len() > 100, "{}", j.network.pipes.len());
        j.network.check().unwrap();
        for (k, &[e, f]) in j.faces.iter().enumerate() {
            assert_ne!(e, f, "pipe {k} has one face");
            let ends = j.network.pipes.ends[k].map(|d| d.0);
            for edge in [e, f] {
                let mut at: Vec<u32> = blocks.edges[edge as usize]
                    .map(|n| j.domain_of[n as usize])
                    .to_vec();
                at.sort();
                let mut want = ends.to_vec();
                want.sort();
                assert_eq!(at, want, "pipe {k}");
            }
        }
    }
}
