//! Initial velocity fields (FLAC's `initialize xvel … gradient`): a loading test that starts from
//! rest waits for a wave from the moving platen before the specimen deforms. Starting every free
//! node and body on the affine field the platens impose makes the whole specimen deform uniformly
//! from the first cycle; under local damping a motion with no unbalanced force keeps its velocity,
//! so only the departures from the affine field (where grains slip and bonds break) have to be
//! driven by forces. (On the 242-grain biaxial test it moved the peak by 1.5 %: the rate effect
//! there is not the wave.)

use super::bodies::{BodyMode, apply};
use super::{FIX_X, FIX_Y, Model};

impl Model {
    /// Set v(x) = G (x − x0) on every free node component and every rigid or simple block:
    /// G is the velocity gradient (1/s, row-major ∂v_i/∂x_j), x0 the point at rest (m), x the
    /// current position. A block takes v_c = G (c − x0), spin ω = (G₁₀ − G₀₁)/2 and, when simple,
    /// strain rates ε̇xx = G₀₀, ε̇yy = G₁₁, ε̇xy = (G₀₁ + G₁₀)/2; a block held by fixed nodes keeps
    /// only the part its constraint allows (its mass-orthogonal projector, set by the solver).
    /// Fixed node components keep their velocity.
    pub fn impose_velocity_gradient(&mut self, g: [[f64; 2]; 2], x0: [f64; 2]) {
        let field = |x: [f64; 2]| {
            let r = [x[0] - x0[0], x[1] - x0[1]];
            [
                g[0][0] * r[0] + g[0][1] * r[1],
                g[1][0] * r[0] + g[1][1] * r[1],
            ]
        };
        let nodes = &mut self.nodes;
        for n in 0..nodes.len() {
            if self
                .bodies
                .of_node
                .get(n)
                .is_some_and(|&b| b != super::bodies::NO_BODY)
            {
                continue;
            }
            let v = field([
                nodes.pos[n][0] + nodes.disp[n][0],
                nodes.pos[n][1] + nodes.disp[n][1],
            ]);
            for (axis, bit) in [FIX_X, FIX_Y].into_iter().enumerate() {
                if nodes.fixed[n] & bit == 0 {
                    nodes.vel[n][axis] = v[axis];
                }
            }
        }
        let bodies = &mut self.bodies;
        let spin = 0.5 * (g[1][0] - g[0][1]);
        for k in 0..bodies.len() {
            let vc = field(bodies.centroid[k]);
            let mut q = [vc[0], vc[1], spin, 0.0, 0.0, 0.0];
            if bodies.mode[k] == BodyMode::Simple {
                q[3] = g[0][0];
                q[4] = g[1][1];
                q[5] = 0.5 * (g[0][1] + g[1][0]);
            }
            if let Some(p) = bodies.projector.get(k).and_then(|p| p.as_ref()) {
                q = apply(p, &q);
            }
            bodies.velocity[k] = q;
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::scene::Scene;
    use crate::setup::setup;

    /// A rigid and a deformable block side by side take the affine field: nodes exactly, the rigid
    /// block its centroid's velocity and the field's spin.
    #[test]
    fn affine_field_reaches_nodes_and_bodies() {
        let text = r#"{
            "name": "affine",
            "materials": { "rock": { "density": 2600, "young": 1e9, "poisson": 0.25 } },
            "region": { "polygon": [[0,0],[2,0],[2,1],[0,1]], "material": "rock" },
            "zoning": { "edge_at_excavation": 0.5, "edge_far": 0.5 },
            "joint_materials": { "j": { "normal_stiffness": 1e10, "shear_stiffness": 1e10 } },
            "joint_sets": [ { "material": "j", "dip": 90, "spacing": 10, "origin": [1, 0] } ],
            "blocks": { "mode": "deformable", "regions": [
                { "mode": "rigid", "polygon": [[1,-1],[3,-1],[3,2],[1,2]] } ] }
        }"#;
        let scene = Scene::from_json(text, "affine").unwrap();
        let mut b = setup(&scene).unwrap();
        let g = [[0.0, 0.5], [0.0, -1.0]];
        b.model.impose_velocity_gradient(g, [0.0, 0.0]);
        let m = &b.model;
        assert_eq!(m.bodies.len(), 1);
        let c = m.bodies.centroid[0];
        let v = m.bodies.velocity[0];
        assert!((v[0] - 0.5 * c[1]).abs() < 1e-12 && (v[1] + c[1]).abs() < 1e-12);
        assert!((v[2] + 0.25).abs() < 1e-12, "spin {}", v[2]);
        let mut free = 0;
        for n in 0..m.nodes.len() {
            if m.bodies.of_node[n] == crate::model::bodies::NO_BODY {
                let y = m.nodes.pos[n][1];
                assert!((m.nodes.vel[n][0] - 0.5 * y).abs() < 1e-12);
                assert!((m.nodes.vel[n][1] + y).abs() < 1e-12);
                free += 1;
            }
        }
        assert!(free > 0);
    }
}
