//! The factor of safety by strength reduction (issue 49) against limit equilibrium: a block on a
//! plane, FoS = (c A + W cos α tan φ)/(W sin α) (Hoek & Bray, *Rock Slope Engineering*, the plane
//! failure without water or tension crack), the block rigid or deformable, on a joint that keeps
//! its cohesion when it slips (`residual_cohesion` = `cohesion`: limit equilibrium's uniform
//! mobilization), searched explicitly and implicitly.

use std::time::Instant;

use adit::scene::{BlockMode, SolveMethod};
use adit::strength_reduction::FactorOfSafety;

use crate::incline::mode_name;
use crate::report::CaseReport;

const G: f64 = 9.81;
/// Rock density, kg/m³.
const DENSITY: f64 = 2600.0;

/// A block of `length` × `height` m on a plane dipping at `dip` degrees (gravity tilted by it),
/// its joint of friction `friction` degrees and cohesion `cohesion` Pa (kept when it slips).
#[derive(Debug, Clone, Copy)]
pub struct Block {
    pub length: f64,
    pub height: f64,
    pub dip: f64,
    pub friction: f64,
    pub cohesion: f64,
    pub mode: BlockMode,
}

/// The blocks of the report: friction alone and with cohesion, rigid and deformable, at dips and
/// sizes the engine's tests do not use.
pub const BLOCKS: [Block; 3] = [
    Block {
        length: 2.0,
        height: 0.5,
        dip: 35.0,
        friction: 45.0,
        cohesion: 0.0,
        mode: BlockMode::Rigid,
    },
    Block {
        length: 2.0,
        height: 0.5,
        dip: 35.0,
        friction: 28.0,
        cohesion: 8e3,
        mode: BlockMode::Rigid,
    },
    Block {
        length: 2.0,
        height: 0.5,
        dip: 40.0,
        friction: 32.0,
        cohesion: 12e3,
        mode: BlockMode::Deformable,
    },
];

impl Block {
    /// Limit equilibrium's factor of safety per metre of the slope's strike.
    pub fn exact(&self) -> f64 {
        let weight = DENSITY * G * self.length * self.height;
        let (sin, cos) = self.dip.to_radians().sin_cos();
        (self.cohesion * self.length + weight * cos * self.friction.to_radians().tan())
            / (weight * sin)
    }

    /// The scene: the block on a 10 m × 1 m base fixed at its bottom, one stage that searches
    /// its factor of safety by `method`.
    pub fn scene(&self, method: SolveMethod) -> adit::Scene {
        let (sin, cos) = self.dip.to_radians().sin_cos();
        let (x0, x1, top) = (3.0, 3.0 + self.length, 1.0 + self.height);
        let text = serde_json::json!({
            "name": "block_on_a_plane",
            "materials": { "rock": { "density": DENSITY, "young": 20e9, "poisson": 0.25 } },
            "region": {
                "polygon": [[0, 0], [10, 0], [10, 1], [x1, 1], [x1, top], [x0, top], [x0, 1], [0, 1]],
                "edge_names": ["bottom", "side", "base", "front", "top", "back", "base", "side"],
                "material": "rock"
            },
            "zoning": { "edge_at_excavation": 0.125, "edge_far": 0.25 },
            "joint_materials": { "plane": {
                "normal_stiffness": 2e10, "shear_stiffness": 2e10, "friction": self.friction,
                "cohesion": self.cohesion, "residual_cohesion": self.cohesion
            } },
            "joints": [{ "from": [x0, 1.0], "to": [x1, 1.0], "material": "plane" }],
            "gravity": [G * sin, -G * cos],
            "blocks": { "regions": [{ "at": [x0 + 0.5 * self.length, 1.0 + 0.5 * self.height],
                                      "mode": mode_name(self.mode) }] },
            "boundary": [{ "part": "bottom", "fix": "xy" }],
            "solve": { "ratio": 1e-6, "max_cycles": 30000, "method": method.name() },
            "output": { "checkpoints": false },
            "stages": [{ "name": "search", "factor_of_safety": { "tolerance": 0.002 } }]
        });
        adit::Scene::from_json(&text.to_string(), "block on a plane").expect("valid block scene")
    }

    /// The case's name.
    pub fn name(&self) -> String {
        format!(
            "{} block {} m × {} m on a {}° plane, φ {}°, c {} kPa",
            mode_name(self.mode),
            self.length,
            self.height,
            self.dip,
            self.friction,
            self.cohesion / 1e3
        )
    }
}

/// Search the block's factor of safety by `method`: the row (`factor`: |F − FoS| / FoS, F the
/// largest stable factor; `bracket`: (F_unstable − F) / FoS) and the search.
pub fn run(block: &Block, method: SolveMethod) -> anyhow::Result<(CaseReport, FactorOfSafety)> {
    let start = Instant::now();
    let scene = block.scene(method);
    let out = std::env::temp_dir().join(format!(
        "adit-validation-fos-{}-{}",
        std::process::id(),
        method.name()
    ));
    let r = adit::run_scene(&scene, &out, &mut adit::solve::Quiet);
    let _ = std::fs::remove_dir_all(&out);
    let r = r?;
    let stage = &r.summary.stages[0];
    let found = (stage.factor_of_safety.clone())
        .ok_or_else(|| anyhow::anyhow!("{}: no factor of safety found", block.name()))?;
    let unstable = found
        .unstable
        .ok_or_else(|| anyhow::anyhow!("{}: stable up to the largest factor", block.name()))?;
    let exact = block.exact();
    let cycles = stage.cycles + found.trials.iter().map(|t| t.cycles).sum::<u64>();
    let report = CaseReport::new(
        format!(
            "{}: FoS {exact:.4}, found {:.4} in {} trials{}",
            block.name(),
            found.factor,
            found.trials.len(),
            crate::method_suffix(method)
        ),
        r.summary.zones,
        cycles,
        start.elapsed().as_secs_f64(),
        None,
        &[
            ("factor", (found.factor - exact).abs() / exact),
            ("bracket", (unstable - found.factor) / exact),
        ],
    );
    Ok((report, found))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The limit-equilibrium factor of the blocks, by hand: the first, friction alone, is
    /// tan 45° / tan 35°.
    #[test]
    fn the_closed_form_is_tan_phi_over_tan_alpha_without_cohesion() {
        let f = BLOCKS[0].exact();
        assert!((f - 1.0 / 35f64.to_radians().tan()).abs() < 1e-12, "{f}");
        assert!(BLOCKS[1].exact() > 28f64.to_radians().tan() / 35f64.to_radians().tan());
    }
}
