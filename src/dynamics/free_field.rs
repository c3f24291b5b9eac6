//! Free-field boundaries (`boundary[i].free_field` on a vertical quiet part; UDEC's and FLAC's
//! free field, Cundall et al. 1980): beside each lateral side of the model runs a
//! one-dimensional column, the rock as it would be with no model beside it, solved alongside the
//! model with the same step and loaded at its base by the same incident waves as the model's
//! quiet base. The side's nodes are quiet, with their dashpots acting on the velocity relative to
//! the column's and the column's stress acting as a traction: the force on a side node is
//!
//!   C (v̄_ff − v̄) + Σ_edges (L/2) σ_ff·n,
//!
//! so that a vertically travelling plane wave passes the side as if the rock went on, and what
//! the model sends out (a wave scattered by an opening) leaves through the dashpots.
//!
//! The column's nodes are at the side's nodes' heights (its elements the side's edges, with the
//! moduli of the zone beside each; a joint cutting the side puts two model nodes at one height,
//! both coupled to the column's node there, the column itself continuous): per unit width, node masses ½ρ h over its elements, the element stresses of a
//! vertical plane wave, σxy = G ∂u_x/∂y, σyy = M ∂u_y/∂y and σxx = λ ∂u_y/∂y (M = λ + 2G,
//! plane strain), its base quiet (dashpots ρCs, ρCp with the incident waves' 2ρC vᵢ, centred as
//! the model's quiet base), its top free, or quiet where the model's top is. Integrated by the same central difference; the
//! column is driven by nothing the model does (one-way coupling).

use super::History;

/// One side's column.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    /// Node heights, m, ascending: the side's nodes' distinct heights (a joint that cuts the side
    /// puts two model nodes at one height; the column itself is continuous rock).
    y: Vec<f64>,
    /// Each side node as (column node, index among the quiet boundary's nodes).
    nodes: Vec<(u32, u32)>,
    /// Each side edge as (its quiet nodes, the column element beside it, half its length m).
    edges: Vec<([u32; 2], u32, f64)>,
    /// Lumped mass per unit width, kg/m².
    mass: Vec<f64>,
    /// Displacement (m) and velocity (m/s) [x, y] of each node, and the velocity before the
    /// last step.
    disp: Vec<[f64; 2]>,
    vel: Vec<[f64; 2]>,
    before: Vec<[f64; 2]>,
    /// Each element's (between nodes k and k + 1) shear modulus G, constrained modulus M and
    /// λ = M − 2G, Pa.
    moduli: Vec<[f64; 3]>,
    /// The base's dashpots ρCs (x) and ρCp (y), Pa·s/m, and the top's when the model's top is
    /// quiet too (else the top is free).
    base_impedance: [f64; 2],
    top_impedance: Option<[f64; 2]>,
    /// The incident waves at the base: each history with its direction [x, y] (the model base's
    /// particle velocity direction).
    incident: Vec<(History, [f64; 2])>,
    /// The outward normal's x of the side (±1): the traction σ·n = (σxx nₓ, σxy nₓ).
    normal_x: f64,
    /// Scratch: each element's stress [σxx, σyy, σxy] (Pa) and each node's force (N/m²).
    stress: Vec<[f64; 3]>,
    force: Vec<[f64; 2]>,
}

/// A side's edge as the set-up finds it: its two nodes' heights (m) and quiet indices, and the
/// rock beside it: density (kg/m³), shear and constrained moduli (Pa).
#[derive(Debug, Clone, Copy)]
pub struct ColumnElement {
    pub y: [f64; 2],
    pub quiet_index: [u32; 2],
    pub density: f64,
    pub shear: f64,
    pub constrained: f64,
}

impl Column {
    /// The column of a side's `edges` (in any order; together a vertical line from bottom to top)
    /// whose outward normal's x is `normal_x`, with the base's `incident` waves, its top quiet
    /// when `quiet_top` (the model's top is), else free.
    pub fn new(
        edges: &[ColumnElement],
        normal_x: f64,
        incident: Vec<(History, [f64; 2])>,
        quiet_top: bool,
    ) -> Column {
        let mut heights: Vec<f64> = edges.iter().flat_map(|e| e.y).collect();
        heights.sort_by(f64::total_cmp);
        let span = heights.last().unwrap_or(&0.0) - heights.first().unwrap_or(&0.0);
        heights.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * span);
        let node_at = |y: f64| {
            let k = heights.partition_point(|&h| h < y - 1e-9 * span);
            k.min(heights.len().saturating_sub(1)) as u32
        };
        let elements = heights.len().saturating_sub(1);
        let (mut mass, mut moduli) = (vec![0.0; heights.len()], vec![[0.0; 3]; elements]);
        let (mut base, mut top) = ([0.0; 2], [0.0; 2]);
        let (mut nodes, mut sides) = (Vec::new(), Vec::new());
        for e in edges {
            let ends = e.y.map(node_at);
            nodes.extend(ends.into_iter().zip(e.quiet_index));
            let (lo, hi) = (ends[0].min(ends[1]), ends[0].max(ends[1]));
            // An edge spans one element of the column (the column's nodes are the side's).
            for k in lo..hi {
                let k = k as usize;
                moduli[k] = [e.shear, e.constrained, e.constrained - 2.0 * e.shear];
                let half = 0.5 * e.density * (heights[k + 1] - heights[k]);
                mass[k] += half;
                mass[k + 1] += half;
                let impedance = [
                    (e.shear * e.density).sqrt(),
                    (e.constrained * e.density).sqrt(),
                ];
                if k == 0 {
                    base = impedance;
                }
                if k + 1 == elements {
                    top = impedance;
                }
            }
            sides.push((e.quiet_index, lo, 0.5 * (e.y[1] - e.y[0]).abs()));
        }
        nodes.sort_unstable();
        nodes.dedup();
        let n = heights.len();
        Column {
            y: heights,
            nodes,
            edges: sides,
            mass,
            disp: vec![[0.0; 2]; n],
            vel: vec![[0.0; 2]; n],
            before: vec![[0.0; 2]; n],
            moduli,
            base_impedance: base,
            top_impedance: quiet_top.then_some(top),
            incident,
            normal_x,
            stress: vec![[0.0; 3]; elements],
            force: vec![[0.0; 2]; n],
        }
    }

    /// Element k's stress [σxx, σyy, σxy], Pa, from the column's displacement.
    fn element_stress(&self, k: usize) -> [f64; 3] {
        let h = self.y[k + 1] - self.y[k];
        let (a, b) = (self.disp[k], self.disp[k + 1]);
        let (gxy, eyy) = ((b[0] - a[0]) / h, (b[1] - a[1]) / h);
        let [g, m, lambda] = self.moduli[k];
        [lambda * eyy, m * eyy, g * gxy]
    }

    /// One step of `dt` s whose forces act at `time` (s since the stage began): the column's
    /// velocities to v⁺ and displacements to u + v⁺Δt, its base's dashpots centred (as the
    /// model's quiet nodes). Then, into `driving` (N/m per quiet node), each side node's force
    /// from the column but its own dashpot: C v̄_ff + Σ (L/2) σ_ff·n, with `dashpot` the quiet
    /// nodes' matrices [Cxx, Cxy, Cyy].
    pub(crate) fn step(
        &mut self,
        dt: f64,
        time: f64,
        dashpot: &[[f64; 3]],
        driving: &mut [[f64; 2]],
    ) {
        let n = self.y.len();
        if n < 2 {
            return;
        }
        for k in 0..n - 1 {
            self.stress[k] = self.element_stress(k);
        }
        self.before.copy_from_slice(&self.vel);
        // Internal forces per unit width: each element pulls its nodes by its stress (σxy, σyy).
        let force = &mut self.force;
        force.fill([0.0; 2]);
        for (k, s) in self.stress.iter().enumerate() {
            force[k][0] += s[2];
            force[k][1] += s[1];
            force[k + 1][0] -= s[2];
            force[k + 1][1] -= s[1];
        }
        let (base, top) = (self.base_impedance, self.top_impedance.unwrap_or([0.0; 2]));
        let mut base_drive = [0.0; 2];
        for (h, d) in &self.incident {
            let v = h.at(time);
            base_drive[0] += 2.0 * base[0] * v * d[0];
            base_drive[1] += 2.0 * base[1] * v * d[1];
        }
        for (i, f) in force.iter().enumerate() {
            // The ends' dashpots centred: (m/Δt + Z/2) v⁺ = (m/Δt) v⁻ + F − (Z/2) v⁻ + 2Z vᵢ.
            let (z, drive) = match i {
                0 => (base, base_drive),
                _ if i + 1 == n => (top, [0.0; 2]),
                _ => ([0.0; 2], [0.0; 2]),
            };
            let a = self.mass[i] / dt;
            for d in 0..2 {
                let v = self.vel[i][d];
                self.vel[i][d] = (a * v + f[d] - 0.5 * z[d] * v + drive[d]) / (a + 0.5 * z[d]);
                self.disp[i][d] += self.vel[i][d] * dt;
            }
        }
        for &(k, q) in &self.nodes {
            let (c, k) = (dashpot[q as usize], k as usize);
            let mean = [
                0.5 * (self.before[k][0] + self.vel[k][0]),
                0.5 * (self.before[k][1] + self.vel[k][1]),
            ];
            let drive = &mut driving[q as usize];
            drive[0] += c[0] * mean[0] + c[1] * mean[1];
            drive[1] += c[1] * mean[0] + c[2] * mean[1];
        }
        for &(ends, k, half) in &self.edges {
            let s = self.stress[k as usize];
            let t = [s[0] * self.normal_x, s[2] * self.normal_x];
            for q in ends {
                driving[q as usize][0] += half * t[0];
                driving[q as usize][1] += half * t[1];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The column's velocity at its node nearest height `y` (m), m/s.
    fn velocity_at(column: &Column, y: f64) -> [f64; 2] {
        let k = (column.y.iter().enumerate())
            .min_by(|a, b| (a.1 - y).abs().total_cmp(&(b.1 - y).abs()))
            .map_or(0, |(k, _)| k);
        column.vel[k]
    }

    /// A column with a quiet base and a free top under a Ricker S wave: its top moves at twice
    /// the incident velocity when the wavelet arrives, H/Cs later (the one-dimensional answer).
    #[test]
    fn a_column_doubles_the_wave_at_its_top() {
        let (rho, g, m) = (2500.0, 4e9, 12e9);
        let (h, height) = (1.0, 100.0);
        let elements: Vec<ColumnElement> = (0..100)
            .map(|k| ColumnElement {
                y: [k as f64 * h, (k + 1) as f64 * h],
                quiet_index: [k, k + 1],
                density: rho,
                shear: g,
                constrained: m,
            })
            .collect();
        let (f, v0) = (10.0, 0.5);
        let ricker = History::Ricker {
            peak: v0,
            frequency: f,
            delay: 1.2 / f,
        };
        let mut column = Column::new(&elements, -1.0, vec![(ricker, [1.0, 0.0])], false);
        let cs = (g / rho).sqrt();
        let dt = 0.5 * h / (m / rho).sqrt();
        let (dashpot, mut driving) = (vec![[0.0; 3]; 101], vec![[0.0; 2]; 101]);
        let mut peak = 0.0f64;
        let steps = ((1.2 / f + height / cs + 1.2 / f) / dt) as usize;
        for s in 0..steps {
            column.step(dt, s as f64 * dt, &dashpot, &mut driving);
            peak = peak.max(velocity_at(&column, height)[0].abs());
        }
        assert!((peak / (2.0 * v0) - 1.0).abs() < 0.01, "{peak}");
    }
}
