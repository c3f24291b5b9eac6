//! From the scene's `bolts` and `liners` to the model's supports: bolts become chains of cable
//! nodes hosted by the rock zones they lie in; liners become beams on the rock side of an
//! excavation's wall. All start inactive: a stage (or the start of the run) installs them.

use adit_meshing::Domain;

use super::plan::Boundary;
use super::{NOT_FILL, rock_walls};
use crate::model::Model;
use crate::scene::{BoltLayout, BoltSpec, LinerSpec, Scene};
use crate::support::liner_capacity::Section;
use crate::support::{CableProps, Cables, LinerProps, Liners, Supports};

/// Build the supports of `scene` on `model` (zones, blocks and fills in place).
pub fn supports(
    scene: &Scene,
    model: &Model,
    fill: &[u32],
    boundary: &Boundary,
) -> anyhow::Result<Supports> {
    let domain = &boundary.domain;
    let mut cables = Cables::default();
    let hosts = Hosts::new(model, fill);
    for (i, b) in scene.bolts.iter().enumerate() {
        let g = cables.names.len() as u32;
        cables.names.push(b.name.clone());
        cables.props.push(cable_props(b));
        cables.active.push(false);
        let segment = b.segment.unwrap_or(scene.zoning.edge_at_excavation);
        let lines = bolt_lines(
            b.layout(&format!("bolts[{i}]"))?,
            domain,
            &format!("bolts[{i}]"),
        )?;
        for (k, (head, toe)) in lines.into_iter().enumerate() {
            let len = (toe[0] - head[0]).hypot(toe[1] - head[1]);
            let n = (len / segment).ceil().max(1.0) as usize;
            let points: Vec<[f64; 2]> = (0..=n)
                .map(|j| {
                    let t = j as f64 / n as f64;
                    [
                        head[0] + t * (toe[0] - head[0]),
                        head[1] + t * (toe[1] - head[1]),
                    ]
                })
                .collect();
            let found: Option<Vec<_>> = points.iter().map(|&p| hosts.find(model, p)).collect();
            let Some(found) = found else {
                anyhow::bail!(
                    "bolts[{i}]: bolt {k} from ({:.3}, {:.3}) to ({:.3}, {:.3}) leaves the rock \
                     (it must lie in deformable blocks, outside every excavation)",
                    head[0],
                    head[1],
                    toe[0],
                    toe[1]
                );
            };
            cables.add_bolt(g, &points, &found);
        }
    }
    let mut liners = Liners::default();
    let tol = 1e-9 * model.size;
    for (i, l) in scene.liners.iter().enumerate() {
        let g = liners.names.len() as u32;
        let j = hole_of(domain, &l.excavation, &format!("liners[{i}].excavation"))?;
        liners.names.push(l.name.clone());
        liners.props.push(liner_props(l));
        liners.active.push(false);
        let walls: Vec<[u32; 2]> = rock_walls(&boundary.edges, &model.blocks, fill, j)
            .map(|e| e.nodes)
            .collect();
        liners.add(g, &walls, &model.nodes.pos, tol);
    }
    Ok(Supports { cables, liners })
}

fn cable_props(b: &BoltSpec) -> CableProps {
    let s = b.out_of_plane_spacing;
    CableProps {
        axial_stiffness: b.young * b.area / s,
        yield_force: b.yield_force / s,
        grout_stiffness: b.grout_stiffness / s,
        bond_strength: b.bond_strength / s,
        pretension: b.pretension / s,
        line_density: b.density * b.area / s,
        spacing: s,
    }
}

fn liner_props(l: &LinerSpec) -> LinerProps {
    let s = l.out_of_plane_spacing;
    let e = l.young / (1.0 - l.poisson * l.poisson);
    LinerProps {
        axial_stiffness: e * l.area / s,
        bending_stiffness: e * l.inertia / s,
        line_density: l.density * l.area / s,
        line_inertia: l.density * l.inertia / s,
        spacing: s,
        section: l.capacity.map(|c| Section {
            area: l.area,
            inertia: l.inertia,
            compressive: c.compressive_strength,
            tensile: c.tensile_strength,
        }),
    }
}

/// The hole (excavation id) of excavation `name`; an error naming the field `path` if there is none.
fn hole_of(domain: &Domain, name: &str, path: &str) -> anyhow::Result<u32> {
    let j = domain.holes.iter().position(|h| h.name == name);
    j.map(|j| j as u32)
        .ok_or_else(|| anyhow::anyhow!("{path}: no excavation named '{name}'"))
}

/// Head and toe of each bolt of a group (scene field `path`): its line, or its pattern laid out
/// along the wall.
fn bolt_lines(
    layout: BoltLayout,
    domain: &Domain,
    path: &str,
) -> anyhow::Result<Vec<([f64; 2], [f64; 2])>> {
    let pat = match layout {
        BoltLayout::Line(l) => return Ok(vec![(l.from, l.to)]),
        BoltLayout::Pattern(pat) => pat,
    };
    let j = hole_of(
        domain,
        &pat.excavation,
        &format!("{path}.pattern.excavation"),
    )?;
    let wall = &domain.holes[j as usize].polygon;
    let v = &wall.vertices;
    let n = v.len();
    let ccw = wall.signed_area() > 0.0;
    let c = wall.centroid();
    let edge_len = |i: usize| {
        let (a, b) = (v[i], v[(i + 1) % n]);
        (b[0] - a[0]).hypot(b[1] - a[1])
    };
    let perimeter: f64 = (0..n).map(edge_len).sum();
    // Arc length of the wall point seen from the centroid toward `toward`.
    let dir = [pat.toward.to_radians().cos(), pat.toward.to_radians().sin()];
    let mut s0 = 0.0;
    let (mut best, mut walked) = (f64::INFINITY, 0.0);
    for i in 0..n {
        let (a, b) = (v[i], v[(i + 1) % n]);
        let e = [b[0] - a[0], b[1] - a[1]];
        let den = dir[0] * (-e[1]) + dir[1] * e[0];
        if den.abs() > 1e-12 {
            let w = [a[0] - c[0], a[1] - c[1]];
            let t = (w[0] * (-e[1]) + w[1] * e[0]) / den;
            let u = (dir[0] * w[1] - dir[1] * w[0]) / den;
            if t > 0.0 && (0.0..=1.0).contains(&u) && t < best {
                best = t;
                s0 = walked + u * edge_len(i);
            }
        }
        walked += edge_len(i);
    }
    let lines = (0..pat.count)
        .map(|k| {
            let s = (s0 + (k as f64 - 0.5 * (pat.count as f64 - 1.0)) * pat.spacing)
                .rem_euclid(perimeter);
            let (mut i, mut left) = (0, s);
            while left > edge_len(i) && i + 1 < n {
                left -= edge_len(i);
                i += 1;
            }
            let (a, b) = (v[i], v[(i + 1) % n]);
            let len = edge_len(i);
            let t = left / len;
            let head = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
            // Away from the excavation: right of the edge for a counter-clockwise outline.
            let sign = if ccw { 1.0 } else { -1.0 };
            let out = [sign * (b[1] - a[1]) / len, -sign * (b[0] - a[0]) / len];
            let toe = [head[0] + pat.length * out[0], head[1] + pat.length * out[1]];
            (head, toe)
        })
        .collect();
    Ok(lines)
}

/// Zones that can host a cable node: those of the rock (not the fill of a staged excavation).
struct Hosts {
    zones: Vec<u32>,
}

impl Hosts {
    fn new(model: &Model, fill: &[u32]) -> Hosts {
        let z = &model.zones;
        let zones = (0..z.len() as u32)
            .filter(|&i| {
                fill.get(z.block[i as usize] as usize)
                    .copied()
                    .unwrap_or(NOT_FILL)
                    == NOT_FILL
            })
            .collect();
        Hosts { zones }
    }

    /// The zone containing `p` (or, on a wall, the nearest one within 5 % of its size) and the
    /// barycentric weights of `p` there.
    fn find(&self, model: &Model, p: [f64; 2]) -> Option<([u32; 3], [f64; 3])> {
        let pos = &model.nodes.pos;
        let mut best: Option<([u32; 3], [f64; 3], f64)> = None;
        for &z in &self.zones {
            let t = model.zones.nodes[z as usize];
            let [a, b, c] = t.map(|n| pos[n as usize]);
            let det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
            let l1 = ((p[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (p[1] - a[1])) / det;
            let l2 = ((b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1])) / det;
            let w = [1.0 - l1 - l2, l1, l2];
            let worst = w[0].min(w[1]).min(w[2]);
            if best.is_none_or(|(_, _, m)| worst > m) {
                best = Some((t, w, worst));
            }
            if worst >= 0.0 {
                break;
            }
        }
        best.filter(|&(_, _, m)| m >= -0.05).map(|(t, w, _)| {
            // Snap onto the zone: clamp and renormalise the weights.
            let w = w.map(|x| x.max(0.0));
            let s = w[0] + w[1] + w[2];
            (t, w.map(|x| x / s))
        })
    }
}
