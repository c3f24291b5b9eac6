//! Ejection of the blocks on an excavation's wall (`summary.json`'s `ejection`): the blocks a
//! dynamic stage finds on the wall of an open excavation, each bounded by joints and that wall
//! alone (a block that reaches the region's edge is the rock mass, not a piece of it), are
//! watched at every step for their velocity into the opening, the mass-weighted mean of their
//! nodes' velocities along the wall's outward normal,
//!
//!   v_out = (Σ mᵢ vᵢ / Σ mᵢ) · n,   n = Σ_wall edges (Δy, −Δx) / |Σ …|,
//!
//! and keep its peak. A rockburst's demand on the support is the kinetic energy ½ M v_out² of
//! the blocks it throws (Kaiser et al. 1996, the Canadian Rockburst Support Handbook: ejection
//! velocities of 1–3 m/s against the energy a yielding support absorbs).

/// A block on a wall, as the stage finds it: its id, its excavation's, its nodes
/// (`start..end`), its unit outward normal (out of the rock into the opening) and its centroid, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WallBlock {
    pub block: u32,
    pub excavation: u32,
    pub nodes: [u32; 2],
    pub normal: [f64; 2],
    pub centroid: [f64; 2],
}

/// The watched blocks and their peaks so far.
#[derive(Debug, Clone, PartialEq)]
pub struct Ejection {
    blocks: Vec<WallBlock>,
    /// Each block's mass, kg/m (taken at the first step, from the dynamic solve's real masses;
    /// empty before), and its peak velocity into the opening so far, m/s.
    mass: Vec<f64>,
    peak: Vec<f64>,
}

/// One watched block's ejection, as `summary.json` gives it.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Ejected {
    /// The excavation's name and the block's number.
    pub excavation: String,
    pub block: u32,
    /// Its centroid when the stage began, m.
    pub at_m: [f64; 2],
    /// Its mass per metre of tunnel, kg/m.
    pub mass_kg_per_m: f64,
    /// The peak of its mean velocity into the opening, m/s (0 if it never moved inward).
    pub peak_velocity_m_per_s: f64,
    /// ½ M v², J/m.
    pub kinetic_energy_j_per_m: f64,
}

impl Ejection {
    /// Watch `blocks`.
    pub fn new(blocks: Vec<WallBlock>) -> Ejection {
        Ejection {
            peak: vec![0.0; blocks.len()],
            mass: Vec::new(),
            blocks,
        }
    }

    /// After a step: each block's velocity into the opening from its nodes' `mass` (kg/m) and
    /// `vel` (m/s), its peak kept.
    pub fn record(&mut self, mass: &[f64], vel: &[[f64; 2]]) {
        if self.mass.is_empty() {
            self.mass = (self.blocks.iter())
                .map(|b| mass[b.nodes[0] as usize..b.nodes[1] as usize].iter().sum())
                .collect();
        }
        for ((b, &total), peak) in self.blocks.iter().zip(&self.mass).zip(&mut self.peak) {
            if total <= 0.0 {
                continue;
            }
            let range = b.nodes[0] as usize..b.nodes[1] as usize;
            let momentum = (mass[range.clone()].iter().zip(&vel[range]))
                .fold([0.0; 2], |p, (m, v)| [p[0] + m * v[0], p[1] + m * v[1]]);
            let out = (momentum[0] * b.normal[0] + momentum[1] * b.normal[1]) / total;
            *peak = peak.max(out);
        }
    }

    /// Every watched block's ejection, the fastest first (ties in block order), each named by
    /// its excavation's name from `names`.
    pub fn report(&self, names: &[String]) -> Vec<Ejected> {
        let mut order: Vec<usize> = (0..self.blocks.len()).collect();
        order.sort_by(|&a, &b| self.peak[b].total_cmp(&self.peak[a]).then(a.cmp(&b)));
        (order.into_iter())
            .map(|k| {
                let (b, m, v) = (&self.blocks[k], self.mass[k], self.peak[k]);
                Ejected {
                    excavation: names
                        .get(b.excavation as usize)
                        .cloned()
                        .unwrap_or_default(),
                    block: b.block,
                    at_m: b.centroid,
                    mass_kg_per_m: m,
                    peak_velocity_m_per_s: v,
                    kinetic_energy_j_per_m: 0.5 * m * v * v,
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A block of two nodes moving into the opening at their mass-weighted mean velocity along
    /// the normal, a block moving out of it not at all; the fastest reported first.
    #[test]
    fn the_peak_is_the_mean_velocity_into_the_opening() {
        let blocks = vec![
            WallBlock {
                block: 0,
                excavation: 0,
                nodes: [0, 2],
                normal: [1.0, 0.0],
                centroid: [1.0, 0.0],
            },
            WallBlock {
                block: 1,
                excavation: 0,
                nodes: [2, 3],
                normal: [0.0, -1.0],
                centroid: [0.0, 2.0],
            },
        ];
        let mass = [1.0, 3.0, 2.0];
        let mut e = Ejection::new(blocks);
        e.record(&mass, &[[2.0, 5.0], [1.0, -1.0], [0.0, 1.0]]);
        e.record(&mass, &[[0.5, 0.0], [0.5, 0.0], [0.0, 2.0]]);
        let r = e.report(&["tunnel".to_string()]);
        assert_eq!((r[0].block, r[1].block), (0, 1));
        assert_eq!(r[0].peak_velocity_m_per_s, (2.0 + 3.0) / 4.0);
        assert_eq!(r[0].kinetic_energy_j_per_m, 0.5 * 4.0 * 1.25 * 1.25);
        assert_eq!((r[1].peak_velocity_m_per_s, r[1].mass_kg_per_m), (0.0, 2.0));
        assert_eq!(r[0].excavation, "tunnel");
    }
}
