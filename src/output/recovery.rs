//! Recovered nodal stress and the zones' error indicator (Zienkiewicz & Zhu, "The superconvergent
//! patch recovery and a posteriori error estimates", Int. J. Numer. Meth. Eng. 33, 1992).
//!
//! A constant-strain zone's stress is constant, so a zone grid shows a checkerboard that no
//! contour filter can follow. The recovered stress σ* is a field at the nodes:
//! - at a node inside its block, the least-squares plane σ*(x, y) = a₀ + a₁ (x − xₙ)/h +
//!   a₂ (y − yₙ)/h through the stresses at the centroids of the zones around it (its patch; h the
//!   patch's mean zone size), each stress component on its own: σ*ₙ = a₀;
//! - at a node on its block's boundary (a joint, a wall, the region's edge), the mean of the
//!   planes of the inner nodes whose patches hold it, evaluated there (patches extrapolate to the
//!   boundary, as the method prescribes);
//! - where neither exists (a block too small to have an inner node with three zones around it),
//!   the area-weighted mean of the stresses of the zones around the node.
//!
//! Patches are built from one block's zones, and every node belongs to one block: σ* never
//! averages across a joint. A rigid or simple block's nodes take its uniform stress; an excavated
//! block's nodes are zero.
//!
//! The indicator of zone e is the root mean square over the zone of the in-plane σ* − σₑ, with σ*
//! linear between the zone's corners: ηₑ = √(Σ_c w_c (Σᵢ dᵢ² + (Σᵢ dᵢ)²)/12) (Pa), with dᵢ the
//! difference of component c ∈ {xx, yy, xy} at corner i (∫ f² dA = A (Σ fᵢ² + (Σ fᵢ)²)/12 for f
//! linear on a triangle) and w_xy = 2 (the tensor's two off-diagonal entries); σzz, which plane
//! strain derives from the others, is left out. Where the zoning is too coarse for the stress
//! gradient, ηₑ is large; the report measures how it tracks the true error on Kirsch.

use rayon::prelude::*;

use crate::model::blocks::NO_EDGE;
use crate::model::{Model, Stress};

/// Fewest zones in a patch that fit a plane (three unknowns per component).
const PATCH_ZONES: usize = 3;

/// A patch's plane is used only when its normal matrix is this well conditioned (determinant of
/// the scaled 3×3 normal matrix over the zone count cubed): below, the centroids lie near a line.
const LEAST_SPREAD: f64 = 1e-6;

/// The nodal stress σ* of every node (Pa; [σxx, σyy, σzz, σxy], tension positive), as the module
/// says.
pub fn nodal_stress(model: &Model) -> Vec<Stress> {
    let star = Star::of(model);
    let planes: Vec<Option<Plane>> = (0..model.nodes.len())
        .into_par_iter()
        .map(|n| patch_plane(model, &star, n))
        .collect();
    let mut nodal: Vec<Stress> = (0..model.nodes.len())
        .into_par_iter()
        .map(|n| match &planes[n] {
            Some(p) => p.a0,
            None => from_neighbours(model, &star, &planes, n),
        })
        .collect();
    for k in 0..model.bodies.len() {
        let [n0, n1] = model.bodies.nodes[k];
        let removed = model.blocks.is_removed(model.bodies.block[k] as usize);
        for s in &mut nodal[n0 as usize..n1 as usize] {
            *s = if removed {
                [0.0; 4]
            } else {
                model.bodies.stress[k]
            };
        }
    }
    nodal
}

/// The indicator ηₑ (Pa) of every zone against the nodal stress `nodal`, as the module says.
pub fn indicator(model: &Model, nodal: &[Stress]) -> Vec<f64> {
    let z = &model.zones;
    (0..z.len())
        .into_par_iter()
        .map(|e| {
            let s = z.stress[e];
            let d = z.nodes[e].map(|n| {
                let r = nodal[n as usize];
                std::array::from_fn::<f64, 4, _>(|c| r[c] - s[c])
            });
            let square = |c: usize| {
                let (sum, sq) = d
                    .iter()
                    .fold((0.0, 0.0), |(a, b), di| (a + di[c], b + di[c] * di[c]));
                (sq + sum * sum) / 12.0
            };
            (square(0) + square(1) + 2.0 * square(3)).sqrt()
        })
        .collect()
}

/// The zones around each node, in zone order (compressed rows), of blocks not excavated.
struct Star {
    start: Vec<u32>,
    zones: Vec<u32>,
}

impl Star {
    fn of(model: &Model) -> Star {
        let (z, blocks) = (&model.zones, &model.blocks);
        let live = |e: usize| !blocks.is_removed(z.block[e] as usize);
        let mut start = vec![0u32; model.nodes.len() + 1];
        for e in (0..z.len()).filter(|&e| live(e)) {
            for n in z.nodes[e] {
                start[n as usize + 1] += 1;
            }
        }
        for n in 0..model.nodes.len() {
            start[n + 1] += start[n];
        }
        let mut next = start.clone();
        let mut zones = vec![0u32; start[model.nodes.len()] as usize];
        for e in (0..z.len()).filter(|&e| live(e)) {
            for n in z.nodes[e] {
                zones[next[n as usize] as usize] = e as u32;
                next[n as usize] += 1;
            }
        }
        Star { start, zones }
    }

    fn around(&self, n: usize) -> &[u32] {
        &self.zones[self.start[n] as usize..self.start[n + 1] as usize]
    }
}

/// A patch's least-squares plane about its node: value a0 there and gradients (per h) of each
/// stress component.
struct Plane {
    at: [f64; 2],
    h: f64,
    a0: Stress,
    ax: Stress,
    ay: Stress,
}

impl Plane {
    fn value(&self, p: [f64; 2]) -> Stress {
        let (x, y) = ((p[0] - self.at[0]) / self.h, (p[1] - self.at[1]) / self.h);
        std::array::from_fn(|c| self.a0[c] + self.ax[c] * x + self.ay[c] * y)
    }
}

/// Whether node `n` lies on its block's boundary (or belongs to no zone's block boundary list).
fn on_boundary(model: &Model, n: usize) -> bool {
    model
        .blocks
        .node_edges
        .get(n)
        .is_none_or(|e| *e != [NO_EDGE, NO_EDGE])
}

/// The plane of node `n`'s patch: `None` on its block's boundary, with fewer than
/// `PATCH_ZONES` zones, or with centroids too near a line.
fn patch_plane(model: &Model, star: &Star, n: usize) -> Option<Plane> {
    let around = star.around(n);
    if around.len() < PATCH_ZONES || on_boundary(model, n) {
        return None;
    }
    let (z, pos) = (&model.zones, &model.nodes.pos);
    let at = pos[n];
    let h = (around.iter().map(|&e| z.area[e as usize]).sum::<f64>() / around.len() as f64).sqrt();
    let mut m = [[0.0; 3]; 3];
    let mut b = [[0.0; 4]; 3];
    for &e in around {
        let c = z.centroid(e as usize, pos);
        let p = [1.0, (c[0] - at[0]) / h, (c[1] - at[1]) / h];
        let s = z.stress[e as usize];
        for i in 0..3 {
            for j in 0..3 {
                m[i][j] += p[i] * p[j];
            }
            for k in 0..4 {
                b[i][k] += p[i] * s[k];
            }
        }
    }
    let det = det3(&m);
    if det.abs() <= LEAST_SPREAD * (around.len() as f64).powi(3) {
        return None;
    }
    // Cramer's rule for each component.
    let solve = |k: usize| {
        std::array::from_fn::<f64, 3, _>(|col| {
            let mut mc = m;
            for (row, rhs) in mc.iter_mut().zip(&b) {
                row[col] = rhs[k];
            }
            det3(&mc) / det
        })
    };
    let a: [[f64; 3]; 4] = std::array::from_fn(solve);
    Some(Plane {
        at,
        h,
        a0: a.map(|c| c[0]),
        ax: a.map(|c| c[1]),
        ay: a.map(|c| c[2]),
    })
}

fn det3(m: &[[f64; 3]; 3]) -> f64 {
    m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
}

/// σ* at node `n` without a plane of its own: the mean of its neighbours' planes evaluated at it,
/// else the area-weighted mean of its zones' stresses (zero for a node no live zone has).
fn from_neighbours(model: &Model, star: &Star, planes: &[Option<Plane>], n: usize) -> Stress {
    let z = &model.zones;
    let p = model.nodes.pos[n];
    let around = star.around(n);
    let (mut sum, mut count) = ([0.0; 4], 0usize);
    for (i, &e) in around.iter().enumerate() {
        for m in z.nodes[e as usize] {
            // Each neighbour once: skip it where an earlier zone of the star has it.
            let earlier = around[..i]
                .iter()
                .any(|&f| z.nodes[f as usize].contains(&m));
            if m as usize == n || earlier {
                continue;
            }
            if let Some(plane) = &planes[m as usize] {
                let v = plane.value(p);
                for c in 0..4 {
                    sum[c] += v[c];
                }
                count += 1;
            }
        }
    }
    if count > 0 {
        return sum.map(|s| s / count as f64);
    }
    let (mut sum, mut area) = ([0.0; 4], 0.0);
    for &e in around {
        let (s, a) = (z.stress[e as usize], z.area[e as usize]);
        for c in 0..4 {
            sum[c] += a * s[c];
        }
        area += a;
    }
    if area > 0.0 {
        sum.map(|s| s / area)
    } else {
        [0.0; 4]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Scene;
    use crate::setup::setup;

    fn model(joint: bool) -> Model {
        let joints = if joint {
            r#", "joint_materials": { "j": { "normal_stiffness": 1e10, "shear_stiffness": 1e10 } },
            "joint_sets": [ { "material": "j", "dip": 90, "spacing": 10, "origin": [1.03, 0] } ]"#
        } else {
            ""
        };
        let text = format!(
            r#"{{
            "name": "recovery",
            "materials": {{ "rock": {{ "density": 2600, "young": 1e9, "poisson": 0.25 }} }},
            "region": {{ "polygon": [[0,0],[2,0],[2,1.2],[0,1.2]], "material": "rock" }},
            "zoning": {{ "edge_at_excavation": 0.13, "edge_far": 0.13 }}{joints}
        }}"#
        );
        setup(&Scene::from_json(&text, "recovery").unwrap())
            .unwrap()
            .model
    }

    /// A stress field linear in x and y is recovered exactly at every node that has a plane of
    /// its own or a neighbour's (all but a few block corners), though each zone holds only its
    /// centroid's value.
    #[test]
    fn a_linear_field_is_recovered_exactly() {
        let mut m = model(false);
        let field = |p: [f64; 2]| -> Stress {
            [
                1e6 + 3e6 * p[0] - 2e6 * p[1],
                -5e6 + 1e6 * p[1],
                -2e6 + 0.5e6 * p[0],
                0.7e6 * p[0] + 0.2e6 * p[1],
            ]
        };
        for e in 0..m.zones.len() {
            m.zones.stress[e] = field(m.zones.centroid(e, &m.nodes.pos));
        }
        let nodal = nodal_stress(&m);
        let star = Star::of(&m);
        let planes: Vec<Option<Plane>> = (0..m.nodes.len())
            .map(|n| patch_plane(&m, &star, n))
            .collect();
        let mut fallback = 0;
        for n in 0..m.nodes.len() {
            let from_plane = planes[n].is_some()
                || star.around(n).iter().any(|&e| {
                    m.zones.nodes[e as usize]
                        .iter()
                        .any(|&k| planes[k as usize].is_some())
                });
            if !from_plane {
                fallback += 1;
                continue;
            }
            let want = field(m.nodes.pos[n]);
            for c in 0..4 {
                assert!(
                    (nodal[n][c] - want[c]).abs() < 1e-6 * 1e6,
                    "node {n} component {c}: {} against {}",
                    nodal[n][c],
                    want[c]
                );
            }
        }
        assert!(fallback <= 4, "{fallback} nodes without a plane");
        assert!(planes.iter().filter(|p| p.is_some()).count() > 50);
    }

    /// Two blocks with their own uniform stresses: each block's nodes take its stress, those on
    /// the joint too, and no zone of either shows an error.
    #[test]
    fn the_recovery_never_averages_across_a_joint() {
        let mut m = model(true);
        assert_eq!(m.blocks.len(), 2);
        let stress = [[-1e6, -2e6, -0.75e6, 0.3e6], [-9e6, -4e6, -3.25e6, -1e6]];
        for e in 0..m.zones.len() {
            m.zones.stress[e] = stress[m.zones.block[e] as usize];
        }
        let nodal = nodal_stress(&m);
        for (n, s) in nodal.iter().enumerate() {
            let want = stress[m.blocks.block_of_node(n as u32)];
            for c in 0..4 {
                assert!(
                    (s[c] - want[c]).abs() < 1e-6,
                    "node {n}: {s:?} against {want:?}"
                );
            }
        }
        assert!(indicator(&m, &nodal).iter().all(|&eta| eta < 1e-6));
    }
}
