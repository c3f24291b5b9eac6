//! Many blocks (issue 5, case 8): a specimen of Voronoi grains bonded by Coulomb grain boundaries
//! (cohesion and tensile strength lost once they fail), compressed biaxially to failure.
//!
//! Specimen W × 2W of grains of mean size g (one jittered seed per g × g cell, Voronoi edges
//! shorter than 0.1 g collapsed), E = 30 GPa, grain boundaries kn = 1e11 Pa / g (`GRAIN_KN_TIMES_SIZE`),
//! ks = kn / 2, φ = 30°, c = 4 MPa, T = 2 MPa, contact tolerance 0.1 g (rigid grains in a force chain
//! press their corners 2–3 % of g into their neighbours); σ3 = 1 MPa on the sides (starting from a
//! hydrostatic 1 MPa), the base on rollers, the top a smooth platen driven down at a constant rate
//! (or servo-controlled to keep the unbalanced-force ratio near a target: slower, quasi-static). In
//! mass-scaled relaxation the platen's rate per cycle is not free: the grains' inertial number
//! (scaled masses) is at most a few 1e-5, yet the peak falls as the platen slows, most likely
//! because failure spreads from bond to bond over cycles and a fast platen outruns it (the report
//! runs the coarse specimen at three rates and servo-controlled). The grains are rigid (3 DOF each),
//! except those within 2g of the platens, which are deformable so that the platens can drive their
//! nodes. The axial stress is the platen's reaction over W (`Cycle::node_force` at its nodes). No
//! closed form: the run must stay stable through the peak and the softening that follows, and it
//! reports the peak strength.

use std::time::Instant;

use adit::Scene;
use adit::joint::FAILED;
use adit::model::FIX_Y;
use adit::setup::setup;
use adit::solve::{Quiet, Status};
use serde::Serialize;

use crate::report::{CaseReport, StepInfo};

/// Confining stress σ3, Pa (compression).
pub const CONFINING: f64 = 1e6;

/// Grain-boundary normal stiffness times the grain size, Pa: kn = 1e11 Pa / g (1e12 Pa/m for
/// 0.1 m grains, about 3.3 E / g), so that a contact's overlap stays the same fraction of its grain
/// at every grain size (UDEC's guidance ties kn to E over the zone or block size).
pub const GRAIN_KN_TIMES_SIZE: f64 = 1e11;

/// The specimen: `across` grains of size `size` m across, twice as many up.
pub fn scene(across: usize, size: f64) -> anyhow::Result<Scene> {
    let (w, h) = (across as f64 * size, 2.0 * across as f64 * size);
    let band = 2.0 * size;
    let (wo, ho) = (w + 1.0, h + 1.0);
    let kn = GRAIN_KN_TIMES_SIZE / size;
    let text = serde_json::json!({
        "name": "grains",
        "materials": { "rock": { "density": 2600, "young": 30e9, "poisson": 0.2 } },
        "region": { "polygon": [[0, 0], [w, 0], [w, h], [0, h]],
                    "edge_names": ["base", "right", "top", "left"], "material": "rock" },
        "zoning": { "edge_at_excavation": size, "edge_far": size, "min_angle": 20 },
        "joint_materials": { "grain": { "normal_stiffness": kn, "shear_stiffness": 0.5 * kn,
                                        "friction": 30, "cohesion": 4e6, "tensile_strength": 2e6 } },
        "voronoi": { "size": size, "seed": 11, "material": "grain" },
        "contacts": { "tolerance": 0.1 * size },
        "blocks": { "mode": "rigid", "regions": [
            { "mode": "deformable", "polygon": [[-1, -1], [wo, -1], [wo, band], [-1, band]] },
            { "mode": "deformable", "polygon": [[-1, h - band], [wo, h - band], [wo, ho], [-1, ho]] }
        ] },
        "in_situ": { "sxx": -CONFINING, "syy": -CONFINING },
        "boundary": [
            { "part": "base", "fix": "y" }, { "at": [w / 2.0, 0], "fix": "x" },
            { "part": "top", "fix": "y" },
            { "part": "left", "normal_stress": -CONFINING },
            { "part": "right", "normal_stress": -CONFINING }
        ],
        "solve": { "ratio": 1e-5, "max_cycles": 4000000 }
    });
    Ok(Scene::from_json(&text.to_string(), "grains")?)
}

/// What one biaxial test measured.
#[derive(Debug, Clone, Serialize)]
pub struct GrainsResult {
    #[serde(skip)]
    pub loading: Loading,
    pub grains: usize,
    pub rigid: usize,
    pub zones: usize,
    pub contacts: usize,
    pub cycles: u64,
    pub wall_s: f64,
    /// Peak axial stress (Pa, compression positive) and the axial strain there.
    pub peak: f64,
    pub peak_strain: f64,
    /// Axial stress and strain at the end of the test.
    pub end: f64,
    pub end_strain: f64,
    /// Fraction of the bonded grain boundaries (face contacts) that failed.
    pub broken: f64,
    /// (axial strain, axial stress Pa) along the test.
    pub curve: Vec<(f64, f64)>,
    /// Why the run stopped early (a NaN, runaway, overlap or unstable-step check), if it did.
    pub stopped: Option<String>,
    pub step: StepInfo,
}

impl GrainsResult {
    pub fn report(&self) -> CaseReport {
        CaseReport::new(
            format!(
                "{} Voronoi grains ({} rigid), σ3 = {} MPa, {}: largest σ1 {:.1} MPa at ε = {:.2e}, \
                 {:.1} MPa at the end (ε = {:.2e}), {:.0} % of the bonds broken, {} contacts",
                self.grains,
                self.rigid,
                CONFINING / 1e6,
                match self.loading.servo {
                    Some(target) => format!("servo-controlled (ratio {target:.0e})"),
                    None => format!("{:.1e} strain per cycle", self.loading.strain_per_cycle),
                },
                self.peak / 1e6,
                self.peak_strain,
                self.end / 1e6,
                self.end_strain,
                100.0 * self.broken,
                self.contacts
            ) + &self
                .stopped
                .as_ref()
                .map_or(String::new(), |r| format!("; STOPPED {r}")),
            self.zones,
            self.cycles,
            self.wall_s,
            None,
            &[],
        )
        .with_step(self.step.clone())
    }
}

/// How the platen loads the specimen.
#[derive(Debug, Clone, Copy)]
pub struct Loading {
    /// Platen speed as axial strain per cycle (static relaxation takes Δt = 1).
    pub strain_per_cycle: f64,
    /// Servo target for the unbalanced-force ratio: after every 200 cycles the speed grows by
    /// 10 % while the ratio is below it and falls by 30 % while above, within 1–100 % of
    /// `strain_per_cycle` (slower, quasi-static). `None`: constant speed.
    pub servo: Option<f64>,
    /// Stop once the axial stress has fallen to this fraction of its peak…
    pub residual: f64,
    /// …or at this axial strain.
    pub max_strain: f64,
}

/// Compress the specimen of `across` grains of `size` m as `loading` says. Every free node and
/// grain starts on the platens' affine velocity field (`Model::impose_velocity_gradient`, FLAC's
/// initial velocity gradient), so the specimen deforms uniformly from the first cycle instead of
/// waiting for a wave from the platen.
pub fn run(across: usize, size: f64, loading: &Loading) -> anyhow::Result<GrainsResult> {
    let start = Instant::now();
    let sc = scene(across, size)?;
    let (w, h) = (across as f64 * size, 2.0 * across as f64 * size);
    let mut b = setup(&sc)?;
    let mut solver = adit::solve::Solver::new(&mut b.model, &sc.solve, 0);
    let top = b.plan.boundary.part_nodes["top"].clone();
    for &n in &top {
        b.model.nodes.fixed[n as usize] |= FIX_Y;
    }
    let rate = loading.strain_per_cycle * h;
    let mut speed = if loading.servo.is_some() {
        0.1 * rate
    } else {
        rate
    };
    b.model
        .impose_velocity_gradient([[0.0, 0.0], [0.0, -speed / h]], [0.0, 0.0]);
    solver.spec.max_cycles = 200;
    solver.spec.ratio = 0.0;
    let (mut cycles, mut curve, mut stopped) = (0u64, Vec::new(), None);
    let (mut peak, mut peak_strain) = (0.0f64, 0.0);
    loop {
        for &n in &top {
            b.model.nodes.vel[n as usize][1] = -speed;
        }
        let sol = solver.solve(&mut b.model, &mut Quiet);
        if let Some(target) = loading.servo {
            let factor = if sol.final_ratio > target { 0.7 } else { 1.1 };
            speed = (factor * speed).clamp(0.01 * rate, rate);
        }
        cycles += sol.cycles;
        if let Status::Failed(reason) = &sol.status {
            stopped = Some(format!("after {cycles} cycles: {reason}"));
            break;
        }
        let m = &b.model;
        let load: f64 = top
            .iter()
            .map(|&n| solver.cycle.node_force(m, n as usize)[1])
            .sum();
        let stress = load / w;
        let strain = -m.nodes.disp[top[0] as usize][1] / h;
        curve.push((strain, stress));
        if stress > peak {
            (peak, peak_strain) = (stress, strain);
        }
        if (peak > 2.0 * CONFINING && stress < loading.residual * peak)
            || strain > loading.max_strain
        {
            break;
        }
    }
    let m = &b.model;
    // Contact indices change with re-detection: count failed bonds among the face contacts now.
    let faces = m.contacts.state.iter().filter(|s| s.initial_normal != 0.0);
    let (all, failed) = faces.fold((0usize, 0usize), |(a, f), s| {
        (a + 1, f + (s.flags & FAILED != 0) as usize)
    });
    let &(end_strain, end) = curve.last().unwrap_or(&(0.0, 0.0));
    Ok(GrainsResult {
        loading: *loading,
        grains: m.blocks.len(),
        rigid: m.bodies.len(),
        zones: m.zones.len(),
        contacts: m.contacts.len(),
        cycles,
        wall_s: start.elapsed().as_secs_f64(),
        peak,
        peak_strain,
        end,
        end_strain,
        broken: failed as f64 / all.max(1) as f64,
        curve,
        stopped,
        step: StepInfo::of(&solver),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Static masses follow the contacts: once the grains have moved and their contacts have been
    /// re-detected, every node's mass is what a fresh derivation from the current contacts gives,
    /// and some differ from the first derivation's.
    #[test]
    fn static_masses_follow_the_contacts() {
        let sc = scene(10, 0.1).unwrap();
        let mut b = setup(&sc).unwrap();
        let mut solver = adit::solve::Solver::new(&mut b.model, &sc.solve, 0);
        let first = b.model.nodes.mass.clone();
        let top = b.plan.boundary.part_nodes["top"].clone();
        for &n in &top {
            b.model.nodes.fixed[n as usize] |= FIX_Y;
            b.model.nodes.vel[n as usize][1] = -5e-6;
        }
        solver.spec.max_cycles = 3000;
        solver.spec.ratio = 0.0;
        solver.solve(&mut b.model, &mut Quiet);
        assert!(
            solver.cycle.detections() >= 2,
            "{} detections",
            solver.cycle.detections()
        );
        let kept = b.model.nodes.mass.clone();
        adit::solve::derive_masses(&mut b.model, &sc.solve);
        assert_eq!(kept, b.model.nodes.mass);
        assert!(kept.iter().zip(&first).any(|(k, f)| k != f));
    }

    /// Coarse twin of the report's 10 000 grains: 10 × 20 grains compressed through their peak.
    #[test]
    fn grains_fail_in_compression_without_blowing_up() {
        let loading = Loading {
            strain_per_cycle: 5e-7,
            servo: None,
            residual: 0.8,
            max_strain: 0.02,
        };
        let r = run(10, 0.1, &loading).unwrap();
        eprintln!("{:?}", r.report());
        assert!(r.stopped.is_none(), "{:?}", r.stopped);
        assert!(r.grains > 150, "{} grains", r.grains);
        assert!(r.peak > 3.0 * CONFINING, "peak {}", r.peak);
        assert!(
            r.end < 0.8 * r.peak + 1.0,
            "no softening: end {} peak {}",
            r.end,
            r.peak
        );
        assert!(r.broken > 0.0);
    }
}
