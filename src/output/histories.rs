//! Monitoring points (`histories`, UDEC's and FLAC's `history`): each a quantity at a point,
//! sampled at every monitor step of every stage into `histories.csv` (cycle, time, one column
//! per point, `<name>:<quantity>_<unit>`) and drawn in `histories.png`.
//!
//! A point is found once, when the run starts: the node nearest it (displacement, velocity;
//! displacements since the last `reset_displacements`, as the output shows them), the zone that
//! holds it or else the zone whose centroid is nearest (stress; an excavated zone holds none), the
//! bolt segment or liner element whose middle is nearest (support forces, per bolt and per set);
//! the energy balance's terms are the whole model's (`dynamics::Energy`).

use std::io::Write;

use crate::model::Model;
use crate::scene::{HistoryQuantity, HistorySpec};
use crate::setup::NOT_FILL;

/// What a monitoring point reads: the quantity and the node, zone, segment or element.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Probe {
    quantity: HistoryQuantity,
    /// Node, zone, bolt segment or liner element.
    at: usize,
}

/// The monitoring points of a run, found in its model, and their column names.
#[derive(Debug, Clone, Default)]
pub struct Probes {
    probes: Vec<Probe>,
    columns: Vec<String>,
    /// The header of `histories.csv`, made once.
    header: String,
}

/// Index of the item of `points` nearest `p` (the first of equals); none when there are none.
fn nearest(points: impl Iterator<Item = [f64; 2]>, p: [f64; 2]) -> Option<usize> {
    points
        .map(|q| (q[0] - p[0]).hypot(q[1] - p[1]))
        .enumerate()
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(i, _)| i)
}

/// Whether `p` lies in the triangle `t` (its edges included).
fn in_triangle(t: [[f64; 2]; 3], p: [f64; 2]) -> bool {
    let side =
        |a: [f64; 2], b: [f64; 2]| (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    let s = [side(t[0], t[1]), side(t[1], t[2]), side(t[2], t[0])];
    s.iter().all(|&v| v >= 0.0) || s.iter().all(|&v| v <= 0.0)
}

impl Probes {
    /// The points of `specs` in `model`, whose blocks `fill` (`Plan::fill`: the staged
    /// excavation whose rock each block is, or `NOT_FILL`) are left out: a wall point reads the
    /// wall, not the rock a stage removes (`histories[i]` errors name the field).
    pub fn of(specs: &[HistorySpec], model: &Model, fill: &[u32]) -> anyhow::Result<Probes> {
        let mut probes = Probes::default();
        for (i, h) in specs.iter().enumerate() {
            let at = Self::find(h, model, fill).ok_or_else(|| {
                anyhow::anyhow!(
                    "histories[{i}]: nothing in the model to read {} from",
                    h.quantity.column()
                )
            })?;
            probes.probes.push(Probe {
                quantity: h.quantity,
                at,
            });
            probes
                .columns
                .push(format!("{}:{}", h.name, h.quantity.column()));
        }
        probes.header = String::from("cycle,time_s");
        for c in &probes.columns {
            probes.header.push(',');
            probes.header.push_str(&super::csv_field(c));
        }
        Ok(probes)
    }

    /// The node, zone, segment or element `h` reads.
    fn find(h: &HistorySpec, model: &Model, fill: &[u32]) -> Option<usize> {
        use HistoryQuantity as Q;
        let at = h.at.unwrap_or_default();
        let nodes = &model.nodes.pos;
        let blocks = &model.blocks;
        let rock = |b: usize| fill.get(b).is_none_or(|&f| f == NOT_FILL);
        // The nearest of `items` (by `place`) that lie in rock, as an index among all.
        let nearest_in_rock = |items: Vec<usize>, place: &dyn Fn(usize) -> [f64; 2]| {
            let k = nearest(items.iter().map(|&i| place(i)), at)?;
            Some(items[k])
        };
        match h.quantity {
            Q::DisplacementX
            | Q::DisplacementY
            | Q::Displacement
            | Q::VelocityX
            | Q::VelocityY
            | Q::AccelerationX
            | Q::AccelerationY => {
                let candidates = (0..nodes.len())
                    .filter(|&n| rock(blocks.block_of_node(n as u32)))
                    .collect();
                nearest_in_rock(candidates, &|n| nodes[n])
            }
            Q::StressXx | Q::StressYy | Q::StressXy => {
                let zones = &model.zones;
                let corners = |z: usize| zones.nodes[z].map(|n| nodes[n as usize]);
                let candidates: Vec<usize> = (0..zones.len())
                    .filter(|&z| rock(blocks.block_of_node(zones.nodes[z][0])))
                    .collect();
                (candidates.iter().copied())
                    .find(|&z| in_triangle(corners(z), at))
                    .or_else(|| nearest_in_rock(candidates, &|z| zones.centroid(z, nodes)))
            }
            Q::BoltForce => {
                let c = &model.supports.cables;
                let middle = |s: &[u32; 2]| {
                    let [a, b] = s.map(|n| c.pos[n as usize]);
                    [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
                };
                nearest(c.segment.iter().map(middle), at)
            }
            Q::LinerThrust | Q::LinerMoment => {
                let l = &model.supports.liners;
                nearest((0..l.element.len()).map(|e| l.middle(e)), at)
            }
            Q::KineticEnergy
            | Q::StrainEnergy
            | Q::BoundaryWork
            | Q::QuietEnergy
            | Q::JointEnergy
            | Q::SupportEnergy
            | Q::DampingEnergy
            | Q::EnergyError => Some(0),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.probes.is_empty()
    }

    /// The header of `histories.csv`.
    pub fn header(&self) -> &str {
        &self.header
    }

    /// The columns' names.
    pub fn columns(&self) -> &[String] {
        &self.columns
    }

    /// Every point's value in `model` now.
    pub fn sample(&self, model: &Model) -> Vec<f64> {
        use HistoryQuantity as Q;
        let (nodes, zones) = (&model.nodes, &model.zones);
        let (cables, liners) = (&model.supports.cables, &model.supports.liners);
        let moved = |n: usize| {
            let (u, o) = (nodes.disp[n], nodes.origin[n]);
            [u[0] - o[0], u[1] - o[1]]
        };
        let accelerated = |n: usize| model.peaks.as_ref().map_or([0.0; 2], |p| p.acceleration[n]);
        let balance = model.energy.as_ref().map(|e| {
            let laws = &model.materials.zone;
            let quiet = model.quiet.as_ref().map_or(0.0, |q| q.net_outflow());
            let moduli = |z: usize| laws[zones.material[z].0 as usize].moduli();
            e.balance(&zones.stress, &zones.area, moduli, quiet)
        });
        let term = |f: fn(&crate::dynamics::Balance) -> f64| balance.as_ref().map_or(0.0, f);
        (self.probes.iter())
            .map(|p| match p.quantity {
                Q::DisplacementX => moved(p.at)[0],
                Q::DisplacementY => moved(p.at)[1],
                Q::Displacement => {
                    let u = moved(p.at);
                    u[0].hypot(u[1])
                }
                Q::VelocityX => nodes.vel[p.at][0],
                Q::VelocityY => nodes.vel[p.at][1],
                Q::AccelerationX => accelerated(p.at)[0],
                Q::AccelerationY => accelerated(p.at)[1],
                Q::StressXx => zones.stress[p.at][0],
                Q::StressYy => zones.stress[p.at][1],
                Q::StressXy => zones.stress[p.at][3],
                Q::BoltForce => cables.bolt_force(p.at),
                Q::LinerThrust => liners.section_forces(p.at)[0].thrust,
                Q::LinerMoment => {
                    let [a, b] = liners.section_forces(p.at);
                    0.5 * (a.moment + b.moment)
                }
                Q::KineticEnergy => term(|b| b.kinetic),
                Q::StrainEnergy => term(|b| b.strain),
                Q::BoundaryWork => term(|b| b.boundary_work),
                Q::QuietEnergy => term(|b| b.quiet),
                Q::JointEnergy => term(|b| b.joints),
                Q::SupportEnergy => term(|b| b.supports),
                Q::DampingEnergy => term(|b| b.damping),
                Q::EnergyError => term(|b| b.error),
            })
            .collect()
    }
}

/// One row of `histories.csv`.
pub fn row(w: &mut dyn Write, cycle: u64, time: f64, values: &[f64]) -> std::io::Result<()> {
    write!(w, "{cycle},{time:e}")?;
    for v in values {
        write!(w, ",{v:e}")?;
    }
    writeln!(w)
}

/// The samples of a run: one row of values per monitor step, with its cycle (from the start of
/// the run) and time, s.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Samples {
    pub cycle: Vec<u64>,
    pub time: Vec<f64>,
    pub values: Vec<Vec<f64>>,
}

impl Samples {
    pub fn push(&mut self, cycle: u64, time: f64, values: Vec<f64>) {
        self.cycle.push(cycle);
        self.time.push(time);
        self.values.push(values);
    }

    pub fn len(&self) -> usize {
        self.cycle.len()
    }

    pub fn is_empty(&self) -> bool {
        self.cycle.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_is_in_the_triangle_around_it_and_on_its_edges() {
        let t = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        assert!(in_triangle(t, [0.2, 0.2]));
        assert!(in_triangle(t, [0.5, 0.0]));
        assert!(!in_triangle(t, [0.6, 0.6]));
        let clockwise = [t[0], t[2], t[1]];
        assert!(in_triangle(clockwise, [0.2, 0.2]));
        assert_eq!(
            nearest([[0.0, 0.0], [2.0, 0.0]].into_iter(), [1.5, 0.1]),
            Some(1)
        );
    }

    /// A dynamic run's acceleration history is the central difference's own, (v_{n+½} −
    /// v_{n−½})/Δt: sampled every step, each sample is the change of the velocity history over
    /// the step, damped or not.
    #[test]
    fn the_acceleration_is_the_velocitys_change_over_the_step() {
        for damping in [r#""damping": 0"#, r#""damping": 0.1"#] {
            let text = format!(
                r#"{{ "name": "a", "materials": {{ "rock": {{ "density": 2500, "young": 1e10, "poisson": 0.25 }} }},
                  "region": {{ "polygon": [[0, 0], [2, 0], [2, 10], [0, 10]], "edge_names": ["base", "right", "top", "left"], "material": "rock" }},
                  "zoning": {{ "edge_at_excavation": 1.0, "edge_far": 1.0 }},
                  "boundary": [{{ "part": "base", "fix": "xy" }}, {{ "part": "left", "fix": "x" }},
                               {{ "part": "right", "fix": "x" }}, {{ "part": "top", "normal_stress": -1e6 }}],
                  "solve": {{ "mode": "dynamic", "duration": 0.005, {damping}, "monitor_every": 1 }},
                  "histories": [{{ "name": "v", "at": [1, 10], "quantity": "velocity_y" }},
                                {{ "name": "a", "at": [1, 10], "quantity": "acceleration_y" }}],
                  "output": {{ "checkpoints": false }} }}"#
            );
            let scene = crate::Scene::from_json(&text, "a").unwrap();
            let out =
                std::env::temp_dir().join(format!("adit-test-acceleration-{}", damping.len()));
            crate::run_scene(&scene, &out, &mut crate::solve::Quiet).unwrap();
            let csv = std::fs::read_to_string(out.join("histories.csv")).unwrap();
            let _ = std::fs::remove_dir_all(&out);
            let rows: Vec<Vec<f64>> = (csv.lines().skip(1))
                .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
                .collect();
            let largest = rows.iter().map(|r| r[3].abs()).fold(0.0, f64::max);
            assert!(largest > 1.0, "{damping}: {largest} m/s²");
            for w in rows.windows(2).skip(1) {
                let change = (w[1][2] - w[0][2]) / (w[1][1] - w[0][1]);
                assert!(
                    (w[1][3] - change).abs() < 1e-6 * largest,
                    "{damping}: {w:?}"
                );
            }
        }
    }
}
