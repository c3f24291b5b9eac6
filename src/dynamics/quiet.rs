//! Quiet (viscous) boundary (Lysmer & Kuhlemeyer 1969, "Finite dynamic model for infinite
//! media", J. Eng. Mech. Div. ASCE 95(EM4); UDEC's and FLAC's viscous boundary). Each edge of a
//! quiet part, of length L and outward normal n, carries dashpots of ρCp per unit length normal
//! to it and ρCs along it, Cp = √((K + 4G/3)/ρ) and Cs = √(G/ρ) of the zone beside it (plane
//! strain), half to each of its nodes, so that a node's dashpots sum to the matrix
//!
//!   C = Σ_edges (L/2) (ρCp n nᵀ + ρCs t tᵀ),   N·s/m per metre of tunnel.
//!
//! The force on the node is C (2 vᵢ(t) d − v): the dashpots' −C v, and an incident plane wave of
//! particle velocity vᵢ(t) along d (the inward normal −n for a P wave, the tangent
//! t = (−n_y, n_x) for an S wave) brought in as the stress 2ρC vᵢ, which the dashpot turns into
//! the wave vᵢ going in while it absorbs what comes out. A plane wave meeting the boundary
//! normally leaves it whole; at other angles a fraction is reflected (Lysmer & Kuhlemeyer's
//! plane-wave analysis).
//!
//! Integrated centred in time with the motion stage's central difference,
//! m (v⁺ − v⁻)/Δt = F + C (2vᵢ d − (v⁺ + v⁻)/2), that is
//!
//!   (m/Δt I + C/2) v⁺ = (m/Δt) v* − (C/2) v⁻ + 2C vᵢ d,   v* = v⁻ + F Δt/m,
//!
//! v* being the motion stage's update without the dashpots (`QuietBoundary::absorb` corrects it
//! and the displacement by (v⁺ − v*) Δt): stable for any C, where the dashpot taken at v⁻ alone
//! is stable only for C Δt/m < 2. A fixed component keeps its velocity.

use crate::scene::{IncidentSpec, WaveKind};

use super::History;
use super::free_field::{Column, ColumnElement};

/// The dashpots and incident waves of the quiet parts of one list of boundary conditions.
#[derive(Debug, Clone)]
pub struct QuietBoundary {
    /// Nodes of the quiet parts, each once, ascending.
    pub nodes: Vec<u32>,
    /// Each node's dashpot matrix C as [Cxx, Cxy, Cyy], N·s/m per m.
    dashpot: Vec<[f64; 3]>,
    /// The energy each node's dashpots have absorbed since the stage began, J/m:
    /// Σ Δt v̄ᵀ C v̄ with v̄ = (v⁺ + v⁻)/2, the velocity the centred dashpot force −C v̄ acts at.
    pub absorbed: Vec<f64>,
    /// The work the boundary's forces (dashpots and incident waves, G = C (2vᵢ d − v̄)) have done
    /// on the model since the stage began, J/m, by the trapezoid the energy balance takes for
    /// every force (`dynamics::Energy`): Σ ½(G_{n−1} + G_n)·v_{n−½} Δt, from the stage's second
    /// step on.
    exchanged: f64,
    /// Each node's boundary force at the last step, N/m, and the steps so far.
    last_force: Vec<[f64; 2]>,
    steps: u64,
    /// The incident waves.
    incident: Vec<Wave>,
    /// The free-field columns of its free-field parts (`free_field.rs`).
    columns: Vec<Column>,
    /// Each node's velocity before the motion stage, m/s (scratch).
    before: Vec<[f64; 2]>,
    /// Each node's incident-wave force this step, N/m (scratch).
    driving: Vec<[f64; 2]>,
}

/// An incident wave: its history, with the force per unit velocity it puts on each node it
/// reaches, 2 Σ (L/2) ρC d (index into `QuietBoundary::nodes`; N·s/m per m).
#[derive(Debug, Clone)]
struct Wave {
    history: History,
    gains: Vec<(u32, [f64; 2])>,
}

/// One edge of a quiet part, as the model's set-up finds it.
#[derive(Debug, Clone, Copy)]
pub struct QuietEdge {
    /// Its nodes.
    pub nodes: [u32; 2],
    /// Their positions, m.
    pub ends: [[f64; 2]; 2],
    /// Its length, m, and unit outward normal.
    pub length: f64,
    pub normal: [f64; 2],
    /// The impedances ρCp and ρCs of the zone beside it, Pa·s/m, and its density, kg/m³.
    pub impedance: [f64; 2],
    pub density: f64,
    /// The quiet condition it belongs to (its index in its list).
    pub condition: usize,
}

impl QuietEdge {
    /// Its share at each node: the matrix (L/2)(ρCp n nᵀ + ρCs t tᵀ) as [Cxx, Cxy, Cyy].
    fn matrix(&self) -> [f64; 3] {
        let ([nx, ny], half) = (self.normal, 0.5 * self.length);
        let (a, b) = (half * self.impedance[0], half * self.impedance[1]);
        [
            a * nx * nx + b * ny * ny,
            (a - b) * nx * ny,
            a * ny * ny + b * nx * nx,
        ]
    }

    /// The incident wave's force on each of its nodes per unit particle velocity, twice its
    /// dashpot there along d: 2 (L/2) ρC d, N·s/m per m.
    fn incident(&self, wave: WaveKind) -> [f64; 2] {
        let ([nx, ny], l) = (self.normal, self.length);
        let (p, s) = (l * self.impedance[0], l * self.impedance[1]);
        match wave {
            WaveKind::P => [-p * nx, -p * ny],
            WaveKind::S => [-s * ny, s * nx],
        }
    }
}

impl QuietBoundary {
    /// The dashpots of `edges`, the waves `incident` brings in through the edges of the quiet
    /// condition each names (its index in its list), and a free-field column beside each
    /// condition `free_field` names (vertical parts: `QuietBoundary::columns`).
    pub fn new(
        edges: &[QuietEdge],
        incident: &[(usize, &IncidentSpec)],
        free_field: &[usize],
    ) -> QuietBoundary {
        let mut nodes: Vec<u32> = edges.iter().flat_map(|e| e.nodes).collect();
        nodes.sort_unstable();
        nodes.dedup();
        let index = |n: u32| nodes.binary_search(&n).expect("a quiet node") as u32;
        let mut dashpot = vec![[0.0; 3]; nodes.len()];
        for e in edges {
            let m = e.matrix();
            for n in e.nodes {
                let c = &mut dashpot[index(n) as usize];
                (0..3).for_each(|i| c[i] += m[i]);
            }
        }
        let columns = (free_field.iter())
            .map(|&k| column(edges, incident, k, &index))
            .collect();
        let incident = (incident.iter())
            .map(|&(k, spec)| {
                let mut gain = vec![None::<[f64; 2]>; nodes.len()];
                for e in edges.iter().filter(|e| e.condition == k) {
                    let f = e.incident(spec.wave);
                    for n in e.nodes {
                        let g = gain[index(n) as usize].get_or_insert([0.0; 2]);
                        (0..2).for_each(|d| g[d] += f[d]);
                    }
                }
                let gains = (gain.into_iter().enumerate())
                    .filter_map(|(i, g)| g.map(|g| (i as u32, g)))
                    .collect();
                Wave {
                    history: History::of(&spec.history()),
                    gains,
                }
            })
            .collect();
        let before = vec![[0.0; 2]; nodes.len()];
        let driving = before.clone();
        QuietBoundary {
            columns,
            absorbed: vec![0.0; nodes.len()],
            exchanged: 0.0,
            last_force: vec![[0.0; 2]; nodes.len()],
            steps: 0,
            nodes,
            dashpot,
            incident,
            before,
            driving,
        }
    }

    /// The net energy that has left through the boundary since the stage began, J/m: what its
    /// dashpots absorbed less what its incident waves brought in (`exchanged`, negated).
    pub fn net_outflow(&self) -> f64 {
        -self.exchanged
    }

    /// Before the motion stage: keep each quiet node's velocity v⁻.
    pub(crate) fn remember(&mut self, vel: &[[f64; 2]]) {
        for (b, &n) in self.before.iter_mut().zip(&self.nodes) {
            *b = vel[n as usize];
        }
    }

    /// After the motion stage: each quiet node's velocity v⁺ from the centred update (module
    /// doc) at time `time` (s since the stage began, the time the step's forces act at), its
    /// displacement corrected alike, and the dashpot and incident forces added to its recorded
    /// force. Returns the largest speed of the quiet nodes after it, m/s. Nothing at a zero step.
    pub(crate) fn absorb<F: Fn(u32) -> [bool; 2]>(
        &mut self,
        nodes: Moving<F>,
        dt: f64,
        time: f64,
    ) -> f64 {
        let Moving {
            mass,
            vel,
            disp,
            force,
            free,
        } = nodes;
        if dt <= 0.0 {
            return 0.0;
        }
        let mut fastest = 0.0f64;
        let driving = &mut self.driving;
        driving.fill([0.0; 2]);
        for wave in &self.incident {
            let v = wave.history.at(time);
            for &(i, g) in &wave.gains {
                driving[i as usize][0] += v * g[0];
                driving[i as usize][1] += v * g[1];
            }
        }
        for column in &mut self.columns {
            column.step(dt, time, &self.dashpot, driving);
        }
        for (i, &n) in self.nodes.iter().enumerate() {
            let free = free(n);
            let n = n as usize;
            let (m, c, before) = (mass[n] / dt, self.dashpot[i], self.before[i]);
            let star = vel[n];
            // Right-hand side (m/Δt) v* − (C/2) v⁻ + 2C vᵢ d, and the matrix m/Δt I + C/2.
            let cv = [
                c[0] * before[0] + c[1] * before[1],
                c[1] * before[0] + c[2] * before[1],
            ];
            let rhs = [
                m * star[0] - 0.5 * cv[0] + driving[i][0],
                m * star[1] - 0.5 * cv[1] + driving[i][1],
            ];
            let (a, b, d) = (m + 0.5 * c[0], 0.5 * c[1], m + 0.5 * c[2]);
            let after = match free {
                [true, true] => {
                    let det = a * d - b * b;
                    [
                        (d * rhs[0] - b * rhs[1]) / det,
                        (a * rhs[1] - b * rhs[0]) / det,
                    ]
                }
                [true, false] => [(rhs[0] - b * star[1]) / a, star[1]],
                [false, true] => [star[0], (rhs[1] - b * star[0]) / d],
                [false, false] => star,
            };
            for k in 0..2 {
                disp[n][k] += (after[k] - star[k]) * dt;
                if free[k] {
                    force[n][k] += m * (after[k] - star[k]);
                }
            }
            vel[n] = after;
            fastest = fastest.max(after[0].hypot(after[1]));
            let mean = [0.5 * (before[0] + after[0]), 0.5 * (before[1] + after[1])];
            self.absorbed[i] += dt
                * (c[0] * mean[0] * mean[0]
                    + 2.0 * c[1] * mean[0] * mean[1]
                    + c[2] * mean[1] * mean[1]);
            let force = [
                driving[i][0] - (c[0] * mean[0] + c[1] * mean[1]),
                driving[i][1] - (c[1] * mean[0] + c[2] * mean[1]),
            ];
            if self.steps > 0 {
                let last = self.last_force[i];
                self.exchanged += 0.5
                    * dt
                    * ((last[0] + force[0]) * before[0] + (last[1] + force[1]) * before[1]);
            }
            self.last_force[i] = force;
        }
        self.steps += 1;
        fastest
    }
}

/// The free-field column beside the edges of quiet condition `k` (vertical: the set-up checked),
/// its base loaded by the incident waves of the conditions whose edges reach the side's lowest
/// node, each along its direction there (the P wave's −n, the S wave's t), its top quiet when
/// another quiet condition's edge reaches the side's highest node; `index` maps a node to its
/// index among the quiet nodes.
fn column(
    edges: &[QuietEdge],
    incident: &[(usize, &IncidentSpec)],
    k: usize,
    index: &dyn Fn(u32) -> u32,
) -> Column {
    let side: Vec<&QuietEdge> = edges.iter().filter(|e| e.condition == k).collect();
    let elements: Vec<ColumnElement> = (side.iter())
        .map(|e| {
            let ([zp, zs], rho) = (e.impedance, e.density);
            ColumnElement {
                y: [e.ends[0][1], e.ends[1][1]],
                quiet_index: e.nodes.map(index),
                density: rho,
                shear: zs * zs / rho,
                constrained: zp * zp / rho,
            }
        })
        .collect();
    let ends: Vec<(u32, f64)> = (side.iter())
        .flat_map(|e| (0..2).map(move |j| (e.nodes[j], e.ends[j][1])))
        .collect();
    let lowest = (ends.iter())
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|e| e.0);
    let highest = (ends.iter())
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|e| e.0);
    let mut waves = Vec::new();
    for &(c, spec) in incident {
        let reaching = edges
            .iter()
            .find(|e| e.condition == c && lowest.is_some_and(|n| e.nodes.contains(&n)));
        if let Some(e) = reaching {
            let [nx, ny] = e.normal;
            let d = match spec.wave {
                WaveKind::P => [-nx, -ny],
                WaveKind::S => [-ny, nx],
            };
            waves.push((History::of(&spec.history()), d));
        }
    }
    let quiet_top =
        (edges.iter()).any(|e| e.condition != k && highest.is_some_and(|n| e.nodes.contains(&n)));
    let normal_x = side.first().map_or(1.0, |e| e.normal[0].signum());
    Column::new(&elements, normal_x, waves, quiet_top)
}

/// The nodes' state the quiet boundary reads and corrects after the motion stage: masses (kg/m),
/// velocities (m/s), displacements (m), recorded forces (N/m), and which components of a node are
/// free (not fixed).
pub(crate) struct Moving<'a, F: Fn(u32) -> [bool; 2]> {
    pub mass: &'a [f64],
    pub vel: &'a mut [[f64; 2]],
    pub disp: &'a mut [[f64; 2]],
    pub force: &'a mut [[f64; 2]],
    pub free: F,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two free nodes moving off a quiet edge with nothing else acting: the centred update
    /// m (v⁺ − v⁻)/Δt = −C (v⁺ + v⁻)/2 gives ½m(v⁺² − v⁻²) = −Δt v̄ᵀ C v̄ exactly, so the energy
    /// absorbed and the kinetic energy left add up to the kinetic energy at the start, at any
    /// step, also far past the explicit dashpot's limit C Δt/m < 2 (where the nodes ring,
    /// v⁺ ≈ −v⁻, instead of coming to rest: nothing is created either way).
    #[test]
    fn the_dashpots_absorb_what_the_nodes_lose() {
        let edge = QuietEdge {
            nodes: [0, 1],
            ends: [[0.0, 0.0], [1.6, 1.2]],
            length: 2.0,
            normal: [0.6, -0.8],
            impedance: [5.0e6, 3.0e6],
            density: 2500.0,
            condition: 0,
        };
        for dt in [1e-5, 1e-3] {
            let mut quiet = QuietBoundary::new(&[edge], &[], &[]);
            let mass = [40.0, 60.0];
            let mut vel = [[1.0, -2.0], [-0.5, 0.3]];
            let (mut disp, mut force) = ([[0.0; 2]; 2], [[0.0; 2]; 2]);
            let kinetic = |v: &[[f64; 2]; 2]| {
                (0..2)
                    .map(|n| 0.5 * mass[n] * (v[n][0] * v[n][0] + v[n][1] * v[n][1]))
                    .sum::<f64>()
            };
            let start = kinetic(&vel);
            for step in 0..50 {
                quiet.remember(&vel);
                let nodes = Moving {
                    mass: &mass,
                    vel: &mut vel,
                    disp: &mut disp,
                    force: &mut force,
                    free: |_| [true, true],
                };
                quiet.absorb(nodes, dt, step as f64 * dt);
            }
            let absorbed: f64 = quiet.absorbed.iter().sum();
            if dt < 1e-4 {
                assert!(absorbed > 0.99 * start, "{dt}: {absorbed} of {start} J/m");
            }
            assert!(
                (absorbed + kinetic(&vel) - start).abs() < 1e-12 * start,
                "{dt}: {absorbed} + {} ≠ {start}",
                kinetic(&vel)
            );
        }
    }
}
