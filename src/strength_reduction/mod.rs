//! Factor of safety by shear strength reduction (Dawson, Roth & Drescher 1999, Géotechnique
//! 49(6):835; Griffiths & Lane 1999; UDEC's and FLAC's `solve fos`, RS2's critical SRF): every
//! zone and joint law's strength divided by a trial factor F (`ZoneLaw::reduced`,
//! `JointLaw::reduced`: c/F, tan φ/F), the stage solved again from its equilibrium at F = 1, and
//! F bracketed, then bisected, between the largest factor found stable and the smallest found
//! unstable, until they differ by at most `tolerance` × the stable one. The factor of safety is
//! the largest stable factor.
//!
//! A trial is stable when its solve reaches the stage's equilibrium criterion (`solve.ratio`)
//! within its limit with no block still sliding (`cycle::drift`: the ratio cannot see a block
//! sliding at its joints' strength, which carries no unbalanced force) and no block left the rock
//! around it: every node of it moved further from the stage's equilibrium than
//! `displacement_limit` beyond the farthest any node of the blocks it touched there moved (a
//! block that slid off its plane and came to rest on the ground below is at equilibrium, but not
//! where it stood: the unbounded displacement of Dawson et al., bounded by the model's edges).
//! Displacement alone does not judge a trial: below the factor of safety a perfectly plastic
//! rock mass comes to rest after a plastic displacement that depends on the path the solve takes
//! to it (a sudden strength drop cycled explicitly, a backward-Euler step implicitly), and the
//! small blocks at its wall ride that flow, so a bound on the displacement would put the factor
//! where a path-dependent displacement crosses an arbitrary bound (the Hoek–Brown tunnel,
//! `docs/theory.md`).
//! Explicitly the limit is `solve.max_cycles` cycles: past its factor of safety the
//! rock's out-of-balance force does not fall, a mechanism accelerates and its displacement grows
//! without bound (Dawson et al.'s non-convergence). Implicitly it is `solve.max_iterations` a
//! load step with their cuts: past its factor of safety no displacement balances the loads and the
//! iterations do not converge (Griffiths & Lane's criterion). A trial the monitor stops (a runaway,
//! interpenetration: a mechanism moving fast) is unstable too.
//!
//! Each trial starts from the stage's equilibrium (`checkpoint::state`, saved once and put back),
//! so trials do not accumulate each other's plastic strain; the stage's laws come back when the
//! search ends. The state of the last unstable trial (the smallest unstable factor's, since each
//! unstable trial lowers it) is kept: the mechanism, for output.

use crate::checkpoint::codec::Reader;
use crate::checkpoint::state;
use crate::joint::JointLaw;
use crate::law::ZoneLaw;
use crate::model::{Materials, Model};
pub use crate::output::factor_of_safety::{FactorOfSafety, MovingBlock, Trial};
use crate::scene::FactorOfSafetySpec;
use crate::solve::{Solution, Status};

/// How a search ended.
pub enum Searched {
    /// The factor, and the model's state at the smallest unstable factor (the mechanism), if one
    /// was found (`restore` puts it into the model).
    Found(FactorOfSafety, Option<Vec<u8>>),
    /// Ctrl-C or SIGTERM stopped a trial; the model is back at the stage's equilibrium.
    Interrupted,
}

/// Search the factor of safety of the stage `model` stands at (in equilibrium when `stable_at_one`,
/// its own solve having converged) as the module says, each trial solved by `solve`, which also
/// names the block still sliding when it converged, if one is (`cycle::drift`). The model
/// ends at the stage's equilibrium with its own laws. `Err` when the saved equilibrium cannot be
/// put back.
pub fn search(
    model: &mut Model,
    spec: &FactorOfSafetySpec,
    stable_at_one: bool,
    mut solve: impl FnMut(&mut Model) -> (Solution, Option<String>),
) -> anyhow::Result<Searched> {
    let mut equilibrium = Vec::new();
    state::save(model, &mut equilibrium);
    let at_rest = model.nodes.disp.clone();
    let touching = neighbours(model);
    let limit = (spec.displacement_limit).unwrap_or(DISPLACEMENT_LIMIT * model.size);
    let laws = Laws::of(&model.materials);
    let mut bracket = Bracket::new(stable_at_one, spec);
    let (mut trials, mut mechanism, mut moving_blocks) = (Vec::new(), None, Vec::new());
    while let Some(factor) = bracket.next() {
        restore(model, &equilibrium)?;
        laws.reduced(factor).put(&mut model.materials);
        let (solution, moving) = solve(model);
        if solution.status == Status::Interrupted {
            restore(model, &equilibrium)?;
            laws.put(&mut model.materials);
            return Ok(Searched::Interrupted);
        }
        let moved = distances(&at_rest, &model.nodes.disp);
        let displacement = moved.iter().fold(0.0, |m: f64, &d| m.max(d));
        let departed = farthest_departure(model, &moved, &touching);
        let inverted = inverted_zones(model);
        let stable = solution.status == Status::Converged && moving.is_none() && departed <= limit;
        if !stable {
            let mut at = Vec::new();
            state::save(model, &mut at);
            mechanism = Some(at);
            moving_blocks = moved_blocks(model, &moved);
        }
        bracket.record(factor, stable);
        let reason = match &solution.status {
            Status::Failed(reason) => Some(reason.clone()),
            _ => None,
        };
        trials.push(Trial {
            factor,
            stable,
            status: solution.status.label().to_string(),
            cycles: solution.cycles,
            displacement_m: displacement,
            departure_m: departed,
            inverted,
            moving,
            reason,
        });
    }
    restore(model, &equilibrium)?;
    laws.put(&mut model.materials);
    let found = FactorOfSafety {
        factor: bracket.stable,
        unstable: bracket.unstable.is_finite().then_some(bracket.unstable),
        tolerance: spec.tolerance,
        trials,
        mechanism: moving_blocks,
    };
    Ok(Searched::Found(found, mechanism))
}

/// The default `displacement_limit`: this fraction of the region's size.
pub const DISPLACEMENT_LIMIT: f64 = 0.01;

/// Each node's distance between its displacement in `from` and in `to`, m: how far it moved in
/// a trial, which the trial's largest displacement, its blocks' departures and its mechanism read.
fn distances(from: &[[f64; 2]], to: &[[f64; 2]]) -> Vec<f64> {
    (from.iter().zip(to))
        .map(|(a, b)| (b[0] - a[0]).hypot(b[1] - a[1]))
        .collect()
}

/// The blocks each block touched at the stage's equilibrium (either side of a contact).
fn neighbours(model: &Model) -> Vec<Vec<u32>> {
    let mut touching = vec![Vec::new(); model.blocks.len()];
    let contacts = &model.contacts;
    for (&node, &other) in contacts.node.iter().zip(&contacts.block) {
        let own = model.blocks.block_of_node(node);
        for (a, b) in [(own, other as usize), (other as usize, own)] {
            if a != b && !touching[a].contains(&(b as u32)) {
                touching[a].push(b as u32);
            }
        }
    }
    touching
}

/// How far the block that left the rock around it furthest moved beyond it, m: for each block,
/// the least distance one of its nodes moved (`moved`, per node, m) less the most one of the
/// nodes of the blocks it touched at the stage's equilibrium (`touching`) moved; the largest over
/// the blocks (0 when none moved further than the rock around it).
fn farthest_departure(model: &Model, moved: &[f64], touching: &[Vec<u32>]) -> f64 {
    let blocks = &model.blocks;
    let moves = |b: usize| {
        let nodes = blocks.node_start[b] as usize..blocks.node_start[b + 1] as usize;
        (moved[nodes].iter()).fold((f64::INFINITY, 0.0f64), |(least, most), &m| {
            (least.min(m), most.max(m))
        })
    };
    let span: Vec<(f64, f64)> = (0..blocks.len()).map(moves).collect();
    (0..blocks.len())
        .filter(|&b| !blocks.is_removed(b) && span[b].0.is_finite())
        .map(|b| {
            let around = (touching[b].iter())
                .map(|&n| span[n as usize].1)
                .fold(0.0, f64::max);
            span[b].0 - around
        })
        .fold(0.0, f64::max)
}

/// How many zones of the rock (blocks not excavated) the trial turned inside out: their area in
/// the current configuration x = X + u of the opposite sign to their reference area, or zero (a
/// triangle whose vertex has passed through its opposite edge: the rock gone through itself).
/// Small strain does not see it, so it does not judge a trial (the factor at which it first
/// happens depends on the path as the displacement does); a factor of safety whose trial has
/// any is warned of (`FactorOfSafety::inverted_warning`).
fn inverted_zones(model: &Model) -> usize {
    let (zones, nodes) = (&model.zones, &model.nodes);
    let at = |n: u32| {
        let (p, u) = (nodes.pos[n as usize], nodes.disp[n as usize]);
        [p[0] + u[0], p[1] + u[1]]
    };
    (0..zones.len())
        .filter(|&z| !model.blocks.is_removed(zones.block[z] as usize))
        .filter(|&z| {
            let [a, b, c] = zones.nodes[z].map(at);
            let twice = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
            twice * zones.area[z].signum() <= 0.0
        })
        .count()
}

/// The most blocks a mechanism names.
const MECHANISM_BLOCKS: usize = 10;

/// The blocks of `model` whose nodes moved (`moved`, per node, m) at least half as far as the
/// farthest block's, farthest first, at most [`MECHANISM_BLOCKS`]; a block's move is its
/// farthest node's.
fn moved_blocks(model: &Model, moved: &[f64]) -> Vec<MovingBlock> {
    let blocks = &model.blocks;
    let mut named: Vec<MovingBlock> = (0..blocks.len())
        .filter(|&b| !blocks.is_removed(b))
        .map(|b| {
            let nodes = blocks.node_start[b] as usize..blocks.node_start[b + 1] as usize;
            MovingBlock {
                block: b as u32,
                at: blocks.node_mean(b, &model.nodes.pos),
                displacement_m: moved[nodes].iter().fold(0.0, |m: f64, &d| m.max(d)),
            }
        })
        .collect();
    let farthest = named.iter().map(|m| m.displacement_m).fold(0.0, f64::max);
    named.retain(|m| m.displacement_m >= 0.5 * farthest && farthest > 0.0);
    named.sort_by(|a, b| b.displacement_m.total_cmp(&a.displacement_m));
    named.truncate(MECHANISM_BLOCKS);
    named
}

/// Put a state saved by `checkpoint::state::save` of this model back into it.
pub fn restore(model: &mut Model, saved: &[u8]) -> anyhow::Result<()> {
    state::restore(model, &mut Reader::new(saved))
}

/// The bracket [stable, unstable] of the factor of safety and the next factor to try: doubled
/// from a stable start until unstable (at most `max_factor`), halved from an unstable one until
/// stable (at least 1 / `max_factor`), then bisected until unstable − stable ≤ tolerance × stable.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Bracket {
    /// The largest factor found stable (0: none yet).
    stable: f64,
    /// The smallest factor found unstable (∞: none yet).
    unstable: f64,
    tolerance: f64,
    max_factor: f64,
}

impl Bracket {
    fn new(stable_at_one: bool, spec: &FactorOfSafetySpec) -> Bracket {
        let (stable, unstable) = if stable_at_one {
            (1.0, f64::INFINITY)
        } else {
            (0.0, 1.0)
        };
        Bracket {
            stable,
            unstable,
            tolerance: spec.tolerance,
            max_factor: spec.max_factor,
        }
    }

    /// The next factor to try, or `None` when the bracket is narrow enough or at its limits.
    fn next(&self) -> Option<f64> {
        if self.unstable.is_infinite() {
            (self.stable < self.max_factor).then(|| (2.0 * self.stable).min(self.max_factor))
        } else if self.stable == 0.0 {
            let floor = 1.0 / self.max_factor;
            (self.unstable > floor).then(|| (0.5 * self.unstable).max(floor))
        } else {
            let narrow = self.unstable - self.stable <= self.tolerance * self.stable;
            (!narrow).then_some(0.5 * (self.stable + self.unstable))
        }
    }

    fn record(&mut self, factor: f64, stable: bool) {
        if stable {
            self.stable = self.stable.max(factor);
        } else {
            self.unstable = self.unstable.min(factor);
        }
    }
}

/// Copies of a model's zone and joint laws.
struct Laws {
    zone: Vec<Box<dyn ZoneLaw>>,
    joint: Vec<Box<dyn JointLaw>>,
}

impl Laws {
    fn of(materials: &Materials) -> Laws {
        Laws {
            zone: materials.zone.iter().map(|l| l.boxed_copy()).collect(),
            joint: materials.joint.iter().map(|l| l.boxed_copy()).collect(),
        }
    }

    /// Every law with its strength divided by `factor`.
    fn reduced(&self, factor: f64) -> Laws {
        Laws {
            zone: self.zone.iter().map(|l| l.reduced(factor)).collect(),
            joint: self.joint.iter().map(|l| l.reduced(factor)).collect(),
        }
    }

    /// Give `materials` these laws.
    fn put(self, materials: &mut Materials) {
        materials.zone = self.zone;
        materials.joint = self.joint;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(tolerance: f64) -> FactorOfSafetySpec {
        FactorOfSafetySpec {
            tolerance,
            max_factor: 100.0,
            displacement_limit: None,
        }
    }

    /// The bracket of a stage whose true factor of safety is `fos` (stable at F ≤ fos): the
    /// factors it tries and where it ends.
    fn search_for(fos: f64, tolerance: f64) -> (Bracket, Vec<f64>) {
        let mut b = Bracket::new(fos >= 1.0, &spec(tolerance));
        let mut tried = Vec::new();
        while let Some(f) = b.next() {
            tried.push(f);
            b.record(f, f <= fos);
            assert!(tried.len() < 100, "{tried:?}");
        }
        (b, tried)
    }

    #[test]
    fn the_bracket_closes_on_the_factor_within_its_tolerance() {
        for fos in [0.013, 0.37, 0.999, 1.0, 1.2345, 3.0, 17.2, 99.0] {
            let (b, tried) = search_for(fos, 0.005);
            assert!(b.stable <= fos && fos < b.unstable, "{fos}: {b:?}");
            assert!(b.unstable - b.stable <= 0.005 * b.stable, "{fos}: {b:?}");
            assert!(tried.len() <= 20, "{fos}: {tried:?}");
        }
    }

    /// A 1 m × 0.25 m rigid block (ρ 2 500 kg/m³) on a Coulomb joint over a fixed base, gravity
    /// tilted by α = 30°, solved by `method`.
    fn block_on_a_plane(method: &str, friction: f64, cohesion: f64) -> String {
        let plane = format!(
            r#"{{ "normal_stiffness": 1e10, "shear_stiffness": 1e10, "friction": {friction},
                "cohesion": {cohesion}, "residual_cohesion": {cohesion} }}"#
        );
        let solve = format!(r#"{{ "ratio": 1e-6, "max_cycles": 20000, "method": "{method}" }}"#);
        block_on(&plane, &solve, method)
    }

    /// The block of [`block_on_a_plane`] on the joint material `plane`, solved by `solve` (JSON
    /// objects), named for `tag`.
    fn block_on(plane: &str, solve: &str, tag: &str) -> String {
        let a = 30f64.to_radians();
        format!(
            r#"{{ "name": "block_{tag}",
            "materials": {{ "rock": {{ "density": 2500, "young": 10e9, "poisson": 0.25 }} }},
            "region": {{ "polygon": [[0, 0], [10, 0], [10, 1], [3, 1], [3, 1.25], [2, 1.25], [2, 1], [0, 1]],
                         "edge_names": ["bottom", "a", "b", "c", "d", "e", "f", "g"], "material": "rock" }},
            "zoning": {{ "edge_at_excavation": 0.25, "edge_far": 0.25 }},
            "joint_materials": {{ "plane": {plane} }},
            "joints": [{{ "from": [2, 1], "to": [3, 1], "material": "plane" }}],
            "gravity": [{gx}, {gy}],
            "blocks": {{ "regions": [{{ "at": [2.5, 1.125], "mode": "rigid" }}] }},
            "boundary": [{{ "part": "bottom", "fix": "xy" }}],
            "solve": {solve},
            "stages": [{{ "name": "fos", "factor_of_safety": {{ "tolerance": 0.005 }} }}] }}"#,
            gx = 9.81 * a.sin(),
            gy = -9.81 * a.cos(),
        )
    }

    fn factor_of(text: &str, name: &str) -> FactorOfSafety {
        let scene = crate::Scene::from_json(text, name).unwrap();
        let out = std::env::temp_dir().join(format!("adit-test-fos-{name}"));
        let r = crate::run_scene(&scene, &out, &mut crate::solve::Quiet).unwrap();
        let _ = std::fs::remove_dir_all(&out);
        assert_eq!(r.summary.status, "converged", "{name}");
        r.summary.stages[0].factor_of_safety.clone().unwrap()
    }

    /// The block on a plane (Hoek & Bray's planar slide without water): FoS = (c A + W cos α
    /// tan φ)/(W sin α), here with friction alone (φ 40°: 1.4534) and with a cohesion the joint
    /// keeps when it slips (φ 30°, c = cr = 1.5 kPa: 1.4893); explicit and implicit bracket it
    /// within the tolerance and agree.
    #[test]
    fn a_block_on_a_plane_has_its_limit_equilibrium_factor() {
        let w = 2500.0 * 9.81 * 0.25;
        let (sin, cos) = 30f64.to_radians().sin_cos();
        for (friction, cohesion) in [(40.0f64, 0.0), (30.0, 1500.0)] {
            let exact = (cohesion + w * cos * friction.to_radians().tan()) / (w * sin);
            let mut found = Vec::new();
            for method in ["explicit", "implicit"] {
                let f = factor_of(&block_on_a_plane(method, friction, cohesion), method);
                let unstable = f.unstable.unwrap();
                assert!(
                    f.factor <= exact * 1.001 && exact <= unstable * 1.001,
                    "{f:?} {exact}"
                );
                assert!(unstable - f.factor <= 0.005 * f.factor, "{f:?}");
                // The mechanism is the block on the plane, the base's block standing still.
                let [moving] = f.mechanism.as_slice() else {
                    panic!("one block moves: {:?}", f.mechanism)
                };
                assert!(
                    (moving.at[0] - 2.5).abs() < 0.5 && moving.at[1] > 1.0,
                    "{moving:?}"
                );
                found.push(f.factor);
            }
            assert!((found[0] - found[1]).abs() <= 0.01 * found[0], "{found:?}");
        }
    }

    /// The block on the joint laws whose strength lives in each contact's state, reduced at
    /// every state: a continuously yielding joint with φm0 = φ = 40° at its bound, tan φ / tan α
    /// = 1.4534; a Barton–Bandis joint (JRC 5, JCS 20 MPa over the block's 1 m, φr 30°) at its
    /// peak strength integrated over the rigid block's linear σn (resultant (h/2) tan α
    /// downslope), 1.9113 (`validation/src/strength_reduction.rs`), each trial released over
    /// 20 000 cycles (at once, the block slides past the peak it is climbing to; over 10 000,
    /// 1.1 % low).
    #[test]
    fn a_block_on_a_yielding_or_barton_bandis_joint_has_its_limit_factor() {
        let stiff = r#""normal_stiffness": 1e10, "shear_stiffness": 1e10"#;
        for (plane, solve, exact) in [
            (
                format!(
                    r#"{{ "law": "continuously_yielding", "friction": 40, "roughness": 1e-3, {stiff} }}"#
                ),
                r#"{ "ratio": 1e-6, "max_cycles": 20000, "method": "explicit" }"#,
                40f64.to_radians().tan() / 30f64.to_radians().tan(),
            ),
            (
                format!(
                    r#"{{ "law": "barton_bandis", "friction": 30, "jrc": 5, "jcs": 20e6,
                    "max_closure": 1e-4, "max_normal_stiffness": 2e10, "sample_length": 1, {stiff} }}"#
                ),
                r#"{ "ratio": 1e-6, "max_cycles": 60000, "ramp": 20000, "method": "explicit" }"#,
                barton_bandis_block_factor(),
            ),
        ] {
            let f = factor_of(&block_on(&plane, solve, "state"), "state");
            let unstable = f.unstable.unwrap();
            assert!(
                (f.factor - exact).abs() < 0.01 * exact && unstable >= f.factor,
                "{f:?} against {exact}"
            );
        }
    }

    /// The Barton–Bandis block's factor, ∫ τp(σn(x)) dx / (W sin α), by the midpoint rule over
    /// the base's linear σn(x) = (W cos α / L)(1 + 12 e x / L²), e = (h/2) tan α.
    fn barton_bandis_block_factor() -> f64 {
        let (w, a, l, h) = (2500.0 * 9.81 * 0.25, 30f64.to_radians(), 1.0, 0.25);
        let e = 0.5 * h * a.tan();
        let n = 1000;
        let strength: f64 = (0..n)
            .map(|i| {
                let x = -0.5 * l + (i as f64 + 0.5) * l / n as f64;
                let sn = w * a.cos() / l * (1.0 + 12.0 * e * x / (l * l));
                sn * (30.0 + 5.0 * (20e6 / sn).log10()).to_radians().tan() * l / n as f64
            })
            .sum();
        strength / (w * a.sin())
    }

    #[test]
    fn the_bracket_stops_at_its_limits() {
        let (b, tried) = search_for(1e6, 0.005);
        assert_eq!((b.stable, b.unstable), (100.0, f64::INFINITY));
        assert_eq!(tried.last(), Some(&100.0));
        let (b, _) = search_for(1e-6, 0.005);
        assert_eq!(b.stable, 0.0);
        assert!(b.unstable >= 0.01 && b.unstable < 0.02, "{b:?}");
    }

    /// No rigid move inverts a zone; a vertex moved through the line of its opposite edge does.
    #[test]
    fn a_zone_is_inverted_when_a_vertex_passes_its_opposite_edge() {
        let scene = crate::Scene::from_json(&block_on_a_plane("explicit", 40.0, 0.0), "d").unwrap();
        let mut model = crate::setup::setup(&scene).unwrap().model;
        assert!(!model.zones.is_empty());
        assert_eq!(inverted_zones(&model), 0);
        // A rigid move of everything, a metre across and a quarter-turn: no zone inverted.
        let (s, c) = std::f64::consts::FRAC_PI_2.sin_cos();
        for (u, p) in model.nodes.disp.iter_mut().zip(&model.nodes.pos) {
            let turned = [c * p[0] - s * p[1] + 1.0, s * p[0] + c * p[1] - 0.5];
            *u = [turned[0] - p[0], turned[1] - p[1]];
        }
        assert_eq!(inverted_zones(&model), 0);
        // Zone 0's first vertex mirrored through the line of its opposite edge.
        model.nodes.disp.fill([0.0; 2]);
        let [a, b, c] = model.zones.nodes[0].map(|n| model.nodes.pos[n as usize]);
        let (e, f) = ([c[0] - b[0], c[1] - b[1]], [a[0] - b[0], a[1] - b[1]]);
        let along = (e[0] * f[0] + e[1] * f[1]) / (e[0] * e[0] + e[1] * e[1]);
        let foot = [b[0] + along * e[0], b[1] + along * e[1]];
        let n = model.zones.nodes[0][0] as usize;
        model.nodes.disp[n] = [2.0 * (foot[0] - a[0]), 2.0 * (foot[1] - a[1])];
        assert!(inverted_zones(&model) >= 1);
    }

    /// A block that moved further than the rock around it has departed by the difference; one
    /// the rock around it carried as far (plastic flow with blocks riding on it) has not.
    #[test]
    fn a_block_departs_only_beyond_the_rock_around_it() {
        let scene = crate::Scene::from_json(&block_on_a_plane("explicit", 40.0, 0.0), "d").unwrap();
        let mut model = crate::setup::setup(&scene).unwrap().model;
        let mut solver = crate::solve::Solver::new(&mut model, &scene.solve, 0);
        solver.cycle.run(&mut model, &solver.params);
        let at_rest = model.nodes.disp.clone();
        let touching = neighbours(&model);
        assert_eq!(touching[0], [1]);
        assert_eq!(touching[1], [0]);
        let block = model.blocks.block_of_node(model.contacts.node[0]);
        let nodes =
            |b: usize| model.blocks.node_start[b] as usize..model.blocks.node_start[b + 1] as usize;
        // The block slides 3 m down the plane (and beyond it), the base stays.
        for n in nodes(block) {
            model.nodes.disp[n] = [at_rest[n][0] + 3.0, at_rest[n][1] - 0.5];
        }
        let departed =
            farthest_departure(&model, &distances(&at_rest, &model.nodes.disp), &touching);
        assert!((departed - 3.0f64.hypot(0.5)).abs() < 1e-12, "{departed}");
        // The base flows under it as far at one node: the block rode the flow.
        let base = nodes(1 - block).start;
        model.nodes.disp[base] = [at_rest[base][0] + 3.5, at_rest[base][1]];
        let moved = distances(&at_rest, &model.nodes.disp);
        assert_eq!(farthest_departure(&model, &moved, &touching), 0.0);
    }
}
