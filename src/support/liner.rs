//! Liners: elastic Euler–Bernoulli beam elements along an excavation's wall. Each liner node has
//! its own two displacements and rotation and is bonded (no slip) to the rock wall node(s) at its
//! place by stiff links, so a liner stays continuous across the joints that cut the wall.
//!
//! Element (length L, axis e, normal n = e rotated +90°, per unit thickness of the model, with
//! s the sets' spacing along the tunnel), in total form from installation (small rotations):
//!   N   = (EA/s)/L · (u_b − u_a)·e                                   axial force (tension +),
//!   m_a = (EI/s)/L · (4θ_a + 2θ_b − 6φ),  m_b = (EI/s)/L · (2θ_a + 4θ_b − 6φ),
//!   φ = (u_b − u_a)·n / L,
//! end moments on the element; its shear is V = (m_a + m_b)/L. The internal bending moment is
//! −m_a at a and m_b at b (positive when the face toward −n, the excavation, is in tension),
//! E = E/(1 − ν²) for a shell in plane strain (Przemieniecki, *Theory of Matrix Structural
//! Analysis*, §4; Itasca, UDEC *Structural Elements*, "beam elements").

use super::liner_capacity::{Safety, Section, SectionForces};
use crate::damping::local_damping;

/// Properties of one liner, per metre of model thickness.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinerProps {
    /// Axial stiffness EA/s, N.
    pub axial_stiffness: f64,
    /// Bending stiffness EI/s, N·m².
    pub(crate) bending_stiffness: f64,
    /// Mass per length ρA/s, kg/m per m; rotational inertia per length ρI/s, kg·m.
    pub(crate) line_density: f64,
    pub(crate) line_inertia: f64,
    /// Spacing s of the sets along the tunnel axis, m: a set's force is s times the force per
    /// metre.
    pub(crate) spacing: f64,
    /// One set's section and strengths, when the scene gives them (`liner_capacity`).
    pub(crate) section: Option<Section>,
}

/// One installed liner's largest forces and its least factor of safety, as `summary.json`'s
/// `liners` gives them (per set: per metre times the sets' spacing).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct LinerLoad {
    /// Its name.
    pub liner: String,
    /// Largest thrust, N per set (compression positive; negative: the liner is in tension
    /// everywhere).
    pub thrust_n: f64,
    /// Largest bending moment magnitude, N·m per set.
    pub moment_n_m: f64,
    /// Largest shear force magnitude, N per set.
    pub shear_n: f64,
    /// Its elements' least factor of safety (`liner_capacity`), where it is (the element's
    /// middle, m) and how many elements are below 1; absent without strengths.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub factor_of_safety: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub at: Option<[f64; 2]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub over_capacity: Option<usize>,
    /// Its elements.
    pub elements: usize,
}

/// Liners, their nodes, links to the rock and elements as structure-of-arrays.
#[derive(Debug, Clone, Default)]
pub struct Liners {
    pub names: Vec<String>,
    pub(crate) props: Vec<LinerProps>,
    pub active: Vec<bool>,
    /// Liner of each liner node.
    pub(crate) group: Vec<u32>,
    /// Position, m.
    pub pos: Vec<[f64; 2]>,
    /// Displacement since installation, m, and rotation, rad.
    pub disp: Vec<[f64; 3]>,
    /// Velocity, m/s, and angular velocity, rad/s.
    pub vel: Vec<[f64; 3]>,
    /// Unbalanced force, N/m, and moment, N·m/m.
    pub force: Vec<[f64; 3]>,
    /// Inertial mass, kg/m, and rotational inertia, kg·m (scaled in static runs).
    pub mass: Vec<[f64; 2]>,
    /// Links: liner node, rock node, stiffness (N/m per m) and the rock displacement at
    /// installation (m).
    pub(crate) link_node: Vec<u32>,
    pub(crate) link_rock: Vec<u32>,
    pub(crate) link_stiffness: Vec<f64>,
    pub(crate) link_origin: Vec<[f64; 2]>,
    /// Elements: liner nodes, liner, length (m), unit axis.
    pub element: Vec<[u32; 2]>,
    pub(crate) element_group: Vec<u32>,
    pub(crate) element_length: Vec<f64>,
    pub(crate) element_axis: Vec<[f64; 2]>,
    /// Axial force N, N/m (tension positive), and internal bending moments at both ends, N·m/m.
    pub axial: Vec<f64>,
    pub moment: Vec<[f64; 2]>,
    /// Shortest element at each liner node, m (the scale between its moment and its forces).
    pub(crate) node_length: Vec<f64>,
}

impl Liners {
    pub fn nodes(&self) -> usize {
        self.pos.len()
    }

    /// Add liner `g` over the wall edges `edges` (pairs of rock nodes, rock on the left) at the
    /// rock node positions `rock_pos`: one liner node per distinct position (closer than `tol`),
    /// linked to every rock node there, one element per edge.
    pub fn add(&mut self, g: u32, edges: &[[u32; 2]], rock_pos: &[[f64; 2]], tol: f64) {
        let first = self.pos.len();
        let node_of = |rock: u32, this: &mut Liners| -> u32 {
            let p = rock_pos[rock as usize];
            let found = (first..this.pos.len()).find(|&i| {
                let q = this.pos[i];
                (q[0] - p[0]).hypot(q[1] - p[1]) <= tol
            });
            let i = found.unwrap_or_else(|| {
                this.pos.push(p);
                this.group.push(g);
                this.pos.len() - 1
            }) as u32;
            if !(0..this.link_node.len())
                .any(|l| this.link_node[l] == i && this.link_rock[l] == rock)
            {
                this.link_node.push(i);
                this.link_rock.push(rock);
                this.link_stiffness.push(0.0);
                this.link_origin.push([0.0; 2]);
            }
            i
        };
        let p = self.props[g as usize];
        for &[a, b] in edges {
            let (na, nb) = (node_of(a, self), node_of(b, self));
            let (pa, pb) = (rock_pos[a as usize], rock_pos[b as usize]);
            let len = (pb[0] - pa[0]).hypot(pb[1] - pa[1]);
            self.element.push([na, nb]);
            self.element_group.push(g);
            self.element_length.push(len);
            self.element_axis
                .push([(pb[0] - pa[0]) / len, (pb[1] - pa[1]) / len]);
            self.axial.push(0.0);
            self.moment.push([0.0; 2]);
        }
        let n = self.pos.len();
        self.node_length.resize(n, f64::INFINITY);
        for (e, nodes) in self.element.iter().enumerate() {
            for &m in nodes {
                let l = &mut self.node_length[m as usize];
                *l = l.min(self.element_length[e]);
            }
        }
        self.disp.resize(n, [0.0; 3]);
        self.vel.resize(n, [0.0; 3]);
        self.force.resize(n, [0.0; 3]);
        self.mass.resize(n, [0.0; 2]);
        // Links twice as axially stiff as the stiffest element touching the node: their
        // compliance is (L/R)²/2 of the ring's hoop compliance (no slip in effect). Bending
        // stiffness is left out: a ring's radial stiffness in bending, (n² − 1)² EI/R⁴ per length,
        // is far below EA/L, and 12 EI/L³ would make short elements' wall nodes needlessly heavy.
        for l in 0..self.link_node.len() {
            let i = self.link_node[l];
            if self.group[i as usize] != g {
                continue;
            }
            // The stiffest element at the node is its shortest (∞ where none: no stiffness).
            self.link_stiffness[l] = 2.0 * p.axial_stiffness / self.node_length[i as usize];
        }
    }

    /// Install liner `g`: it starts unstressed on the wall as the wall is now.
    pub fn install(&mut self, g: usize, rock: &[[f64; 2]]) {
        self.active[g] = true;
        for l in 0..self.link_node.len() {
            if self.group[self.link_node[l] as usize] as usize == g {
                self.link_origin[l] = rock[self.link_rock[l] as usize];
            }
        }
        for n in (0..self.nodes()).filter(|&n| self.group[n] as usize == g) {
            self.disp[n] = [0.0; 3];
            self.vel[n] = [0.0; 3];
        }
    }

    /// Element and link forces; the rock's share of each link goes to `slots` (one per link).
    pub fn forces(&mut self, rock: &[[f64; 2]], slots: &mut [[f64; 2]]) {
        for f in &mut self.force {
            *f = [0.0; 3];
        }
        for e in 0..self.element.len() {
            let g = self.element_group[e] as usize;
            if !self.active[g] {
                continue;
            }
            let p = &self.props[g];
            let [a, b] = self.element[e].map(|n| n as usize);
            let (len, ax) = (self.element_length[e], self.element_axis[e]);
            let nrm = [-ax[1], ax[0]];
            let (da, db) = (self.disp[a], self.disp[b]);
            let along = |d: [f64; 3], v: [f64; 2]| d[0] * v[0] + d[1] * v[1];
            let axial = p.axial_stiffness / len * (along(db, ax) - along(da, ax));
            let chord = (along(db, nrm) - along(da, nrm)) / len;
            let k = p.bending_stiffness / len;
            let ma = k * (4.0 * da[2] + 2.0 * db[2] - 6.0 * chord);
            let mb = k * (2.0 * da[2] + 4.0 * db[2] - 6.0 * chord);
            let shear = (ma + mb) / len;
            self.axial[e] = axial;
            self.moment[e] = [-ma, mb];
            // Node a is pulled along +e by tension and pushed along −n by the shear.
            let fa = [
                axial * ax[0] - shear * nrm[0],
                axial * ax[1] - shear * nrm[1],
            ];
            self.force[a][0] += fa[0];
            self.force[a][1] += fa[1];
            self.force[a][2] -= ma;
            self.force[b][0] -= fa[0];
            self.force[b][1] -= fa[1];
            self.force[b][2] -= mb;
        }
        for (l, slot) in slots.iter_mut().enumerate().take(self.link_node.len()) {
            let n = self.link_node[l] as usize;
            if !self.active[self.group[n] as usize] {
                continue;
            }
            let f = self.link_force(l, rock);
            self.force[n][0] += f[0];
            self.force[n][1] += f[1];
            *slot = [-f[0], -f[1]];
        }
    }

    /// The force of link `l` on its liner node, N/m: k (u_rock − u_rock,installed − u_liner);
    /// the rock node gets its opposite.
    fn link_force(&self, l: usize, rock: &[[f64; 2]]) -> [f64; 2] {
        let n = self.link_node[l] as usize;
        let (r, o, k) = (
            rock[self.link_rock[l] as usize],
            self.link_origin[l],
            self.link_stiffness[l],
        );
        [
            k * (r[0] - o[0] - self.disp[n][0]),
            k * (r[1] - o[1] - self.disp[n][1]),
        ]
    }

    /// The force each installed liner's links exert on their rock nodes, N/m: (rock node, force).
    pub fn rock_forces<'a>(
        &'a self,
        rock: &'a [[f64; 2]],
    ) -> impl Iterator<Item = (usize, [f64; 2])> + 'a {
        (0..self.link_node.len())
            .filter(|&l| self.active[self.group[self.link_node[l] as usize] as usize])
            .map(move |l| {
                let f = self.link_force(l, rock);
                (self.link_rock[l] as usize, [-f[0], -f[1]])
            })
    }

    /// Central-difference update of the active liner nodes with local damping α; returns the
    /// largest speed, m/s.
    pub fn motion(&mut self, alpha: f64, dt: f64) -> f64 {
        let mut fastest = 0.0f64;
        for n in 0..self.nodes() {
            if !self.active[self.group[n] as usize] {
                continue;
            }
            for d in 0..3 {
                let (f, v) = (self.force[n][d], &mut self.vel[n][d]);
                let fd = local_damping(f, *v, alpha);
                *v += fd / self.mass[n][d / 2] * dt;
                self.disp[n][d] += *v * dt;
            }
            fastest = fastest.max(self.vel[n][0].hypot(self.vel[n][1]));
        }
        fastest
    }

    /// Gershgorin bounds of each liner node, [translation N/m per m, rotation N·m per m]
    /// (rotations weighted by 1/L: 36 EI/L³ + 2 EA/L and 18 EI/L per element, 2k per link),
    /// and the links' share on the rock nodes added into `rock`.
    pub fn stiffness(&self, rock: &mut [f64]) -> Vec<[f64; 2]> {
        let mut r = vec![[0.0; 2]; self.nodes()];
        for e in 0..self.element.len() {
            let p = &self.props[self.element_group[e] as usize];
            let len = self.element_length[e];
            let ei = p.bending_stiffness;
            for n in self.element[e] {
                r[n as usize][0] += 36.0 * ei / len.powi(3) + 2.0 * p.axial_stiffness / len;
                r[n as usize][1] += 18.0 * ei / len;
            }
        }
        for l in 0..self.link_node.len() {
            let n = self.link_node[l] as usize;
            r[n][0] += 2.0 * self.link_stiffness[l];
            if self.active[self.group[n] as usize] {
                rock[self.link_rock[l] as usize] += 2.0 * self.link_stiffness[l];
            }
        }
        r
    }

    /// The sets' spacing of element `e`'s liner, m.
    pub fn spacing(&self, e: usize) -> f64 {
        self.props[self.element_group[e] as usize].spacing
    }

    /// Element `e`'s shear force V = (M_b − M_a)/L from its internal moments at its ends a and b
    /// (`moment`), N/m.
    pub fn shear(&self, e: usize) -> f64 {
        let [at_a, at_b] = self.moment[e];
        (at_b - at_a) / self.element_length[e]
    }

    /// Element `e`'s forces per set at its two ends: its thrust −N s, its internal moment s m at
    /// each end and its shear s V.
    pub fn section_forces(&self, e: usize) -> [SectionForces; 2] {
        let s = self.spacing(e);
        let shear = s * self.shear(e);
        self.moment[e].map(|m| SectionForces {
            thrust: -s * self.axial[e],
            moment: s * m,
            shear,
        })
    }

    /// Element `e`'s factors of safety, the least of its two ends' (`liner_capacity`); none
    /// without strengths.
    pub fn safety(&self, e: usize) -> Option<Safety> {
        let section = self.props[self.element_group[e] as usize].section?;
        let [a, b] = self.section_forces(e).map(|f| section.safety(&f));
        Some(Safety {
            bending: a.bending.min(b.bending),
            shear: a.shear.min(b.shear),
        })
    }

    /// Element `e`'s utilization, 1/FS (0 without strengths; 1 on the capacity envelope).
    pub fn utilization(&self, e: usize) -> f64 {
        self.safety(e).map_or(0.0, |s| 1.0 / s.factor())
    }

    /// The middle of element `e`, m.
    pub fn middle(&self, e: usize) -> [f64; 2] {
        let [a, b] = self.element[e].map(|n| self.pos[n as usize]);
        [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
    }

    /// Each installed liner's largest forces and least factor of safety (`LinerLoad`).
    pub fn liner_loads(&self) -> Vec<LinerLoad> {
        let elements = |g: usize| {
            (0..self.element.len()).filter(move |&e| self.element_group[e] as usize == g)
        };
        (0..self.names.len())
            .filter(|&g| self.active[g])
            .map(|g| {
                let forces: Vec<SectionForces> =
                    elements(g).flat_map(|e| self.section_forces(e)).collect();
                let largest = |f: fn(&SectionForces) -> f64| {
                    forces.iter().map(f).fold(f64::NEG_INFINITY, f64::max)
                };
                let safety: Vec<(usize, f64)> = elements(g)
                    .filter_map(|e| Some((e, self.safety(e)?.factor())))
                    .collect();
                let least = safety.iter().copied().min_by(|a, b| a.1.total_cmp(&b.1));
                LinerLoad {
                    liner: self.names[g].clone(),
                    thrust_n: largest(|f| f.thrust),
                    moment_n_m: largest(|f| f.moment.abs()),
                    shear_n: largest(|f| f.shear.abs()),
                    factor_of_safety: least.map(|(_, fs)| fs),
                    at: least.map(|(e, _)| self.middle(e)),
                    over_capacity: least.map(|_| safety.iter().filter(|s| s.1 < 1.0).count()),
                    elements: elements(g).count(),
                }
            })
            .collect()
    }

    /// Real lumped masses [ρA ℓ, ρI ℓ], ℓ the tributary length.
    pub fn real_masses(&self) -> Vec<[f64; 2]> {
        let mut m = vec![[0.0; 2]; self.nodes()];
        for e in 0..self.element.len() {
            let p = &self.props[self.element_group[e] as usize];
            let half = 0.5 * self.element_length[e];
            for n in self.element[e] {
                m[n as usize][0] += p.line_density * half;
                m[n as usize][1] += p.line_inertia * half;
            }
        }
        m
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    const ROCK: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [2.0, 0.0]];

    /// A liner (EA = 1e9 N, EI = 1e6 N·m²) on the wall `edges` of rock nodes at `rock`.
    pub(crate) fn liner_on(edges: &[[u32; 2]], rock: &[[f64; 2]]) -> Liners {
        let mut l = Liners {
            names: vec!["l".into()],
            props: vec![LinerProps {
                axial_stiffness: 1e9,
                bending_stiffness: 1e6,
                line_density: 1.0,
                line_inertia: 1.0,
                spacing: 1.0,
                section: None,
            }],
            active: vec![false],
            ..Default::default()
        };
        l.add(0, edges, rock, 1e-9);
        l
    }

    /// A straight two-element liner along x on four rock nodes; rock nodes 1 and 2 coincide (a
    /// joint meets the wall there): one liner node.
    fn liner() -> Liners {
        liner_on(&[[0, 1], [2, 3]], &ROCK)
    }

    #[test]
    fn coincident_wall_nodes_share_one_liner_node() {
        let l = liner();
        assert_eq!(l.nodes(), 3);
        assert_eq!(l.link_node.len(), 4);
        assert_eq!(l.element.len(), 2);
        assert_eq!(l.element, vec![[0, 1], [1, 2]]);
    }

    #[test]
    fn rigid_motion_is_free_and_bending_is_not() {
        let mut l = liner();
        l.install(0, &[[0.0; 2]; 4]);
        let mut slots = vec![[0.0; 2]; 4];
        // A small rigid rotation θ about node 0: u = θ(−y, x), all nodes rotate by θ.
        let t = 1e-6;
        let rock: Vec<[f64; 2]> = ROCK.iter().map(|p| [-t * p[1], t * p[0]]).collect();
        for (n, r) in [0, 1, 3].into_iter().enumerate() {
            l.disp[n] = [rock[r][0], rock[r][1], t];
        }
        l.forces(&rock, &mut slots);
        for f in &l.force {
            assert!(f.iter().all(|v| v.abs() < 1e-6), "{f:?}");
        }
        // Bend: lift the middle node by w; moments m = EI/L·(−6φ) at the ends of each element.
        l.disp[1] = [0.0, 1e-3, 0.0];
        l.disp[0] = [0.0; 3];
        l.disp[2] = [0.0; 3];
        l.forces(&[[0.0; 2]; 4], &mut slots);
        let f1 = l.force[1][1];
        // Two clamped-clamped elements: 12 EI/L³ each against the lift, plus two links.
        let link = l.link_stiffness[1] + l.link_stiffness[2];
        assert!(
            (f1 + (24.0 * 1e6 + link) * 1e-3).abs() < 1e-6 * link,
            "{f1}"
        );
        assert!(
            (l.moment[0][1] - l.moment[1][0]).abs() < 1e-9,
            "moment continuous at node 1"
        );
    }

    #[test]
    fn a_ring_pinched_by_two_loads_bends_as_the_closed_form() {
        // Free thin ring (R = 1 m) squeezed by P at the crown and the invert: M = PR/π under
        // the loads and −PR(1/2 − 1/π) at the springlines; thrust P/2 at the springlines
        // (Roark's Formulas for Stress and Strain, table 9.2 case 1).
        let n = 96;
        let rock: Vec<[f64; 2]> = (0..n)
            .map(|k| {
                let t = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
                [t.cos(), t.sin()]
            })
            .collect();
        let edges: Vec<[u32; 2]> = (0..n as u32).map(|k| [k, (k + 1) % n as u32]).collect();
        let mut l = liner_on(&edges, &rock);
        l.link_stiffness.iter_mut().for_each(|k| *k = 0.0);
        l.install(0, &vec![[0.0; 2]; n]);
        let r = l.stiffness(&mut vec![0.0; n]);
        l.mass = r
            .iter()
            .map(|r| [r[0] * 1.8 / 2.56, r[1] * 1.8 / 2.56])
            .collect();
        let (p, top, bottom) = (1e3, n / 4, 3 * n / 4);
        let mut slots = vec![[0.0; 2]; n];
        for _ in 0..200_000 {
            l.forces(&rock, &mut slots);
            l.force[top][1] -= p;
            l.force[bottom][1] += p;
            l.motion(0.8, 1.0);
        }
        // Elements around the crown node and the right springline node (node 0).
        let at = |node: usize| {
            let e = (0..n).find(|&e| l.element[e][1] as usize == node).unwrap();
            (l.moment[e][1], l.axial[e], l.axial[(e + 1) % n])
        };
        let (m_top, _, _) = at(top);
        let (m_side, n1, n2) = at(0);
        let pr = p * 1.0;
        let pi = std::f64::consts::PI;
        assert!((m_top.abs() - pr / pi).abs() < 0.01 * pr, "{m_top}");
        assert!(
            (m_side.abs() - pr * (0.5 - 1.0 / pi)).abs() < 0.01 * pr,
            "{m_side}"
        );
        assert!(m_top * m_side < 0.0);
        assert!((0.5 * (n1 + n2) + 0.5 * p).abs() < 0.01 * p, "{n1} {n2}");
    }
}
