//! Fully grouted cables (rock bolts), as UDEC's and FLAC's cable elements: each bolt is a chain of
//! axial segments between cable nodes; each cable node is tied to the rock by a grout spring
//! acting along the bolt, at the point of the zone that hosts it (its displacement interpolated
//! with the zone's linear shape functions). So a bolt crossing a joint ties the blocks on both
//! sides.
//!
//! Per unit thickness of the model (plane strain), with s the bolts' spacing along the tunnel:
//!   segment   N = N0 + (EA/s)/L · (u_j − u_i − δp),  |N| ≤ Fy/s  (δp its plastic elongation),
//!   grout     F = (kg/s) ℓ (u_rock − u_cable − sp),  |F| ≤ (τb/s) ℓ  (sp the plastic slip),
//! u the displacements along the bolt, ℓ the node's tributary length, N0 the pretension
//! (Itasca, UDEC *Structural Elements*, "cable elements"; St John & Van Dillen 1983).

use crate::damping::local_damping;

/// Properties of one bolt group, per metre of model thickness.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CableProps {
    /// Axial stiffness EA/s, N.
    pub axial_stiffness: f64,
    /// Axial yield force Fy/s, N/m.
    pub(crate) yield_force: f64,
    /// Grout stiffness kg/s per length of bolt, N/m per m per m.
    pub grout_stiffness: f64,
    /// Bond strength τb/s per length of bolt, N/m per m.
    pub bond_strength: f64,
    /// Pretension N0/s, N/m.
    pub(crate) pretension: f64,
    /// Mass per length ρA/s, kg/m per m.
    pub(crate) line_density: f64,
    /// Spacing s of the bolts along the tunnel axis, m: a bolt's force is s times the force per
    /// metre.
    pub(crate) spacing: f64,
}

/// One bolt's largest load, as `summary.json`'s `bolts` gives it.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct BoltLoad {
    /// Its group's name.
    pub group: String,
    /// Its head, m.
    pub head: [f64; 2],
    /// The axial force of its most loaded segment, N per bolt (tension positive).
    pub force_n: f64,
    /// Its yield force, N per bolt.
    pub capacity_n: f64,
    /// |force| / capacity (1 at yield).
    pub utilization: f64,
    /// The energy the rock has put into it since its installation, J per bolt: the work of its
    /// grout's forces over the rock's displacement along the path the run took (what its steel
    /// stored and dissipated by yielding, its grout by slipping, and its own motion).
    pub energy_j: f64,
    /// Whether a segment has yielded.
    pub yielded: bool,
}

/// Bolt groups, cable nodes and segments as structure-of-arrays. A group is inactive until a
/// stage installs it.
#[derive(Debug, Clone, Default)]
pub struct Cables {
    pub names: Vec<String>,
    pub(crate) props: Vec<CableProps>,
    pub active: Vec<bool>,
    /// Group of each cable node.
    pub(crate) group: Vec<u32>,
    /// Position of each cable node, m.
    pub pos: Vec<[f64; 2]>,
    /// Unit vector along the bolt (head to toe).
    pub axis: Vec<[f64; 2]>,
    /// Tributary length of each cable node, m.
    pub length: Vec<f64>,
    /// Rock nodes of the hosting zone and the node's shape-function weights there.
    pub(crate) host: Vec<[u32; 3]>,
    pub weight: Vec<[f64; 3]>,
    /// Displacement along the bolt since installation, m.
    pub disp: Vec<f64>,
    /// Velocity along the bolt, m/s.
    pub vel: Vec<f64>,
    /// Unbalanced force along the bolt, N/m.
    pub force: Vec<f64>,
    /// Load applied along the bolt at the node (a pull-out test), N/m.
    pub applied: Vec<f64>,
    /// Inertial mass (scaled in static runs), kg/m.
    pub mass: Vec<f64>,
    /// Rock displacement along the bolt at installation, m.
    pub(crate) rock_origin: Vec<f64>,
    /// Force of the grout on the cable node along the bolt, N/m.
    pub(crate) grout_force: Vec<f64>,
    /// Rock displacement along the bolt at the node at the last force stage, m, and the energy
    /// the rock has put into the bolt there since installation, ∫ f d(u_rock), J/m (the grout
    /// force's work over the rock's displacement: the steel's stored and yielded energy, the
    /// grout's slip and the bolt's own motion).
    pub(crate) rock_last: Vec<f64>,
    pub(crate) absorbed: Vec<f64>,
    /// Plastic slip of the grout, m.
    pub slip: Vec<f64>,
    /// First segment of each bolt (its segments run to the next bolt's first, or to the end).
    pub bolt_start: Vec<u32>,
    /// Cable nodes of each segment (head side first) and its group.
    pub segment: Vec<[u32; 2]>,
    pub(crate) segment_group: Vec<u32>,
    /// Segment length, m.
    pub(crate) segment_length: Vec<f64>,
    /// Axial force, N/m (tension positive).
    pub axial: Vec<f64>,
    /// Plastic elongation, m.
    pub plastic: Vec<f64>,
}

impl Cables {
    pub fn nodes(&self) -> usize {
        self.pos.len()
    }

    /// Add one bolt of group `g` as a chain of cable nodes at `points` (head first), each with
    /// its host zone's nodes and weights.
    pub fn add_bolt(&mut self, g: u32, points: &[[f64; 2]], hosts: &[([u32; 3], [f64; 3])]) {
        let first = self.pos.len() as u32;
        let (a, b) = (points[0], points[points.len() - 1]);
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        let axis = [(b[0] - a[0]) / len, (b[1] - a[1]) / len];
        let k = points.len();
        for (i, (&p, &(host, w))) in points.iter().zip(hosts).enumerate() {
            let dist = |j: usize| {
                let q = points[j];
                (q[0] - p[0]).hypot(q[1] - p[1])
            };
            let trib = 0.5 * (if i > 0 { dist(i - 1) } else { 0.0 })
                + 0.5 * (if i + 1 < k { dist(i + 1) } else { 0.0 });
            self.group.push(g);
            self.pos.push(p);
            self.axis.push(axis);
            self.length.push(trib);
            self.host.push(host);
            self.weight.push(w);
        }
        let n = self.pos.len();
        for v in [
            &mut self.disp,
            &mut self.vel,
            &mut self.force,
            &mut self.applied,
            &mut self.mass,
            &mut self.rock_origin,
            &mut self.grout_force,
            &mut self.rock_last,
            &mut self.absorbed,
            &mut self.slip,
        ] {
            v.resize(n, 0.0);
        }
        self.bolt_start.push(self.segment.len() as u32);
        for i in 0..k as u32 - 1 {
            let (p, q) = (points[i as usize], points[i as usize + 1]);
            self.segment.push([first + i, first + i + 1]);
            self.segment_group.push(g);
            self.segment_length.push((q[0] - p[0]).hypot(q[1] - p[1]));
            self.axial.push(0.0);
            self.plastic.push(0.0);
        }
    }

    /// The force of one bolt in segment `s`, N (tension positive): its force per metre times the
    /// bolts' spacing.
    pub fn bolt_force(&self, s: usize) -> f64 {
        self.axial[s] * self.props[self.segment_group[s] as usize].spacing
    }

    /// The capacity of a bolt of group `g`: its yield force Fy, N per bolt.
    pub fn capacity(&self, g: usize) -> f64 {
        self.props[g].yield_force * self.props[g].spacing
    }

    /// The utilization of segment `s`: |N| / Fy, its force over its bolt's yield force (1 at
    /// yield).
    pub fn utilization(&self, s: usize) -> f64 {
        self.axial[s].abs() / self.props[self.segment_group[s] as usize].yield_force
    }

    /// Each installed bolt, in the order the bolts were added: its group and its segments (head
    /// first).
    pub fn installed_bolts(&self) -> impl Iterator<Item = (usize, std::ops::Range<usize>)> + '_ {
        let ends = (self.bolt_start.iter().skip(1).copied()).chain([self.segment.len() as u32]);
        (self.bolt_start.iter().zip(ends))
            .map(|(&first, end)| {
                (
                    self.segment_group[first as usize] as usize,
                    first as usize..end as usize,
                )
            })
            .filter(|(g, _)| self.active[*g])
    }

    /// The head of the bolt whose first segment is `first`, m.
    pub fn head(&self, first: usize) -> [f64; 2] {
        self.pos[self.segment[first][0] as usize]
    }

    /// Each installed bolt's largest load (`BoltLoad`), in the order the bolts were added.
    pub fn bolt_loads(&self) -> Vec<BoltLoad> {
        self.installed_bolts()
            .map(|(g, segments)| {
                let worst = (segments.clone())
                    .max_by(|&a, &b| self.utilization(a).total_cmp(&self.utilization(b)))
                    .expect("a bolt has a segment");
                let nodes = self.segment[segments.start][0] as usize
                    ..=self.segment[segments.end - 1][1] as usize;
                let absorbed: f64 = self.absorbed[nodes].iter().sum();
                BoltLoad {
                    group: self.names[g].clone(),
                    head: self.head(segments.start),
                    force_n: self.bolt_force(worst),
                    capacity_n: self.capacity(g),
                    utilization: self.utilization(worst),
                    yielded: segments.into_iter().any(|s| self.plastic[s] != 0.0),
                    energy_j: absorbed * self.props[g].spacing,
                }
            })
            .collect()
    }

    /// Rock displacement along the bolt at cable node `n`, m.
    fn rock_disp(&self, n: usize, rock: &[[f64; 2]]) -> f64 {
        let a = self.axis[n];
        self.host[n]
            .iter()
            .zip(self.weight[n])
            .map(|(&r, w)| {
                let u = rock[r as usize];
                w * (u[0] * a[0] + u[1] * a[1])
            })
            .sum()
    }

    /// Install group `g`: the grout sets around the rock as it is now; the segments carry the
    /// pretension.
    pub fn install(&mut self, g: usize, rock: &[[f64; 2]]) {
        self.active[g] = true;
        for n in (0..self.nodes()).filter(|&n| self.group[n] as usize == g) {
            self.rock_origin[n] = self.rock_disp(n, rock);
            self.rock_last[n] = self.rock_origin[n];
            self.grout_force[n] = 0.0;
            self.absorbed[n] = 0.0;
            self.disp[n] = 0.0;
            self.vel[n] = 0.0;
            self.slip[n] = 0.0;
        }
        let pre = self.props[g].pretension;
        for s in (0..self.segment.len()).filter(|&s| self.segment_group[s] as usize == g) {
            self.axial[s] = pre;
            self.plastic[s] = 0.0;
        }
    }

    /// Forces: grout springs (with slip) and segments (with yield); the rock's share goes to
    /// `slots` (3 per cable node: minus the grout force times each host weight).
    pub fn forces(&mut self, rock: &[[f64; 2]], slots: &mut [[f64; 2]]) {
        for n in 0..self.nodes() {
            let g = self.group[n] as usize;
            if !self.active[g] {
                continue;
            }
            let p = &self.props[g];
            let k = p.grout_stiffness * self.length[n];
            let cap = p.bond_strength * self.length[n];
            let along = self.rock_disp(n, rock);
            let rel = along - self.rock_origin[n] - self.disp[n];
            let mut f = k * (rel - self.slip[n]);
            if f.abs() > cap {
                self.slip[n] += (f.abs() - cap) / k * f.signum();
                f = cap * f.signum();
            }
            self.absorbed[n] += 0.5 * (self.grout_force[n] + f) * (along - self.rock_last[n]);
            self.rock_last[n] = along;
            self.grout_force[n] = f;
            self.force[n] = f + self.applied[n];
            let a = self.axis[n];
            for (slot, w) in slots[3 * n..3 * n + 3].iter_mut().zip(self.weight[n]) {
                *slot = [-f * w * a[0], -f * w * a[1]];
            }
        }
        for s in 0..self.segment.len() {
            let g = self.segment_group[s] as usize;
            if !self.active[g] {
                continue;
            }
            let p = &self.props[g];
            let [i, j] = self.segment[s].map(|n| n as usize);
            let k = p.axial_stiffness / self.segment_length[s];
            let stretch = self.disp[j] - self.disp[i] - self.plastic[s];
            let mut n = p.pretension + k * stretch;
            if n.abs() > p.yield_force {
                self.plastic[s] += (n.abs() - p.yield_force) / k * n.signum();
                n = p.yield_force * n.signum();
            }
            self.axial[s] = n;
            self.force[i] += n;
            self.force[j] -= n;
        }
    }

    /// Central-difference update of the active cable nodes with local damping α; returns the
    /// largest speed, m/s.
    pub fn motion(&mut self, alpha: f64, dt: f64) -> f64 {
        let mut fastest = 0.0f64;
        for n in 0..self.nodes() {
            if !self.active[self.group[n] as usize] {
                continue;
            }
            let (f, v) = (self.force[n], &mut self.vel[n]);
            let fd = local_damping(f, *v, alpha);
            *v += fd / self.mass[n] * dt;
            self.disp[n] += *v * dt;
            fastest = fastest.max(v.abs());
        }
        fastest
    }

    /// Gershgorin stiffness bound of each cable node (segments and grout), N/m per m, and the
    /// grout's share on the rock nodes added into `rock`.
    pub fn stiffness(&self, rock: &mut [f64]) -> Vec<f64> {
        let mut r = vec![0.0; self.nodes()];
        for s in 0..self.segment.len() {
            let k =
                self.props[self.segment_group[s] as usize].axial_stiffness / self.segment_length[s];
            for n in self.segment[s] {
                r[n as usize] += 2.0 * k;
            }
        }
        for (n, r) in r.iter_mut().enumerate() {
            let k = self.props[self.group[n] as usize].grout_stiffness * self.length[n];
            *r += 2.0 * k;
            if self.active[self.group[n] as usize] {
                for (&h, w) in self.host[n].iter().zip(self.weight[n]) {
                    rock[h as usize] += 2.0 * k * w.abs();
                }
            }
        }
        r
    }

    /// Real lumped masses, kg/m.
    pub fn real_masses(&self) -> Vec<f64> {
        (0..self.nodes())
            .map(|n| self.props[self.group[n] as usize].line_density * self.length[n])
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One bolt of 4 nodes in rock that does not move, pulled at its head.
    fn bolt() -> Cables {
        let mut c = Cables {
            names: vec!["b".into()],
            props: vec![CableProps {
                axial_stiffness: 1e8,
                yield_force: 1e5,
                grout_stiffness: 1e8,
                bond_strength: 1e4,
                pretension: 0.0,
                line_density: 1.0,
                spacing: 1.5,
            }],
            active: vec![false],
            ..Default::default()
        };
        let pts: Vec<[f64; 2]> = (0..4).map(|i| [0.0, i as f64]).collect();
        let hosts = vec![([0, 1, 2], [1.0, 0.0, 0.0]); 4];
        c.add_bolt(0, &pts, &hosts);
        c
    }

    /// A bolt's load is its most used segment's, per bolt (the force per metre times the
    /// spacing) and over its capacity Fy = yield force per metre times the spacing; a bolt not
    /// installed has none.
    #[test]
    fn a_bolt_reports_its_force_per_bolt_and_its_utilization() {
        let mut c = bolt();
        c.add_bolt(
            0,
            &[[5.0, 0.0], [5.0, 1.0]],
            &[([0, 1, 2], [1.0, 0.0, 0.0]); 2],
        );
        assert!(c.bolt_loads().is_empty());
        c.active[0] = true;
        c.axial = vec![2e4, 6e4, -1e4, 8e4];
        let loads = c.bolt_loads();
        assert_eq!(loads.len(), 2);
        let (first, second) = (&loads[0], &loads[1]);
        assert_eq!(first.head, [0.0, 0.0]);
        assert_eq!((first.force_n, first.capacity_n), (6e4 * 1.5, 1e5 * 1.5));
        assert_eq!(first.utilization, 0.6);
        assert_eq!(
            (second.head, second.force_n, second.utilization),
            ([5.0, 0.0], 1.2e5, 0.8)
        );
        assert!(!first.yielded);
    }

    /// The rock moving along a held bolt puts the grout's work into it: ½ k u² per node while
    /// the grout holds, then the bond strength times the further slip (k = ks L, cap = τb L per
    /// node; the bolt's energy per bolt is the sum times its spacing).
    #[test]
    fn the_rock_puts_the_grouts_work_into_the_bolt() {
        let mut c = bolt();
        let mut rock = vec![[0.0; 2]; 3];
        c.install(0, &rock);
        let mut slots = vec![[0.0; 2]; 12];
        // The rock moves 0.2 mm along the bolt (+y) in 200 steps; the cable nodes stay put.
        let (total, steps) = (2e-4, 200);
        for i in 1..=steps {
            rock[0] = [0.0, total * i as f64 / steps as f64];
            c.forces(&rock, &mut slots);
        }
        // Per node: k = 1e8 L, cap = 1e4 L, so the grout slips past u_y = 1e-4 m.
        let yielding = 1e-4;
        let per_length = 0.5 * 1e8 * yielding * yielding + 1e4 * (total - yielding);
        let exact = per_length * c.length.iter().sum::<f64>() * 1.5;
        let energy = c.bolt_loads()[0].energy_j;
        assert!(
            (energy - exact).abs() < 1e-3 * exact,
            "{energy} against {exact}"
        );
    }

    #[test]
    fn grout_slips_at_its_bond_strength_and_segments_yield() {
        let mut c = bolt();
        let rock = vec![[0.0; 2]; 3];
        c.install(0, &rock);
        assert_eq!(c.length, vec![0.5, 1.0, 1.0, 0.5]);
        let mut slots = vec![[0.0; 2]; 12];
        // Pull the head back (against the axis) by 1 mm: grout 1e8·0.5·1e-3 = 5e4 > cap 5e3.
        c.disp[0] = -1e-3;
        c.forces(&rock, &mut slots);
        assert!((c.grout_force[0] - 5e3).abs() < 1e-9);
        assert!(c.slip[0] > 0.0);
        assert_eq!(slots[0], [0.0, -5e3]);
        // Segment 0 stretched by 1 mm: 1e8 · 1e-3 = 1e5 = yield, so it just holds.
        assert!((c.axial[0] - 1e5).abs() < 1e-6);
        c.disp[0] = -2e-3;
        c.forces(&rock, &mut slots);
        assert!((c.axial[0] - 1e5).abs() < 1e-6);
        assert!((c.plastic[0] - 1e-3).abs() < 1e-12);
    }

    #[test]
    fn an_inactive_group_exerts_nothing() {
        let mut c = bolt();
        c.disp[0] = -1e-3;
        let mut slots = vec![[0.0; 2]; 12];
        c.forces(&[[0.0; 2]; 3], &mut slots);
        assert!(slots.iter().all(|s| *s == [0.0, 0.0]));
        assert_eq!(c.force, vec![0.0; 4]);
    }
}
