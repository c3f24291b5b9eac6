//! One explicit cycle as a pipeline of named stages: detect (when something has moved far enough),
//! contact forces, zone forces, structural forces (supports), motion; the monitor runs every few
//! cycles. The `Cycle` owns only scratch space, the detection trigger and stage timers.

mod bodies;
mod contacts;
pub mod drift;
mod dynamic;
mod far_field;
pub use contacts::JointCommit;
pub(crate) use contacts::contact_normal;
mod large_strain;
mod mixed;
pub mod monitor;
pub mod timestep;

use std::time::Instant;

use rayon::prelude::*;

use crate::contact::detect::Detection;
use crate::damping::local_damping;
use crate::law::StrainIncrement;
use crate::law::ZoneLaw;
use crate::model::blocks::Blocks;
use crate::model::{BODY, Contacts, FIX_X, FIX_Y, Gather, Materials, Model, Nodes, Stress, Zones};
use crate::support::Supports;

pub use monitor::Monitor;

/// Numerical parameters of the cycle (filled from the scene's `solve`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CycleParams {
    /// Time step, s (1 in static mass-scaled runs).
    pub dt: f64,
    /// Local non-viscous damping coefficient α (0.8 is UDEC's default for static runs).
    pub damping: f64,
    /// How the zones turn node velocities into stress.
    pub(crate) scheme: ZoneScheme,
    /// Mass-proportional Rayleigh coefficient α_R, 1/s (0 for none; `scene::Rayleigh`).
    pub(crate) mass_damping: f64,
    /// Stiffness-proportional Rayleigh coefficient β_R, s (0 for none).
    pub(crate) stiffness_damping: f64,
    /// Whether the zones take their law's `trial` (the implicit path: the state is the last
    /// commit's and the increment the whole one since) instead of `update`.
    pub(crate) trial: bool,
}

/// What the implicit path's trial starts from (`implicit::commit`, `Cycle::displace`): the
/// node displacements at the zones' commit (m; the zones hold their committed state), and the
/// joints' commit.
#[derive(Debug, Clone, Copy)]
pub struct Trial<'a> {
    pub disp: &'a [[f64; 2]],
    pub joints: JointCommit<'a>,
}

/// The gathers of the motion stage's force sources, each node's slots in the zone, contact,
/// support and far-field force buffers.
#[derive(Clone, Copy)]
pub struct Gathers<'a> {
    pub zones: &'a Gather,
    pub contacts: &'a Gather,
    pub supports: &'a Gather,
    pub far_field: &'a Gather,
}

/// How the zone stage turns node velocities into stress and corner forces: one of three, fixed
/// for a solve (`solve.large_strain` for the solve, `zoning.mixed` for the model; the two together
/// are refused by the scene's validation).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ZoneScheme {
    /// Constant-strain triangles on their initial shape (`Cycle::zone_forces_small`).
    SmallStrain,
    /// `zoning.mixed`: each zone's volumetric strain increment replaced by its nodes' patch average
    /// (`mixed.rs`).
    Mixed,
    /// `solve.large_strain`: zones on their current shape, stress turned by their spin
    /// (`large_strain.rs`).
    LargeStrain,
}

impl ZoneScheme {
    /// The scheme of a solve with `large_strain` on `model` (mixed when the model was set up
    /// with `zoning.mixed`).
    pub fn of(model: &Model, large_strain: bool) -> ZoneScheme {
        if large_strain {
            ZoneScheme::LargeStrain
        } else if model.mixed.is_some() {
            ZoneScheme::Mixed
        } else {
            ZoneScheme::SmallStrain
        }
    }
}

impl CycleParams {
    /// β_R / Δt: the share of a stress increment over this step added as viscous stress,
    /// β_R σ̇ = (β_R / Δt) Δσ (0 without stiffness damping or at a zero step).
    pub fn viscous_ratio(&self) -> f64 {
        if self.dt > 0.0 {
            self.stiffness_damping / self.dt
        } else {
            0.0
        }
    }
}

/// The stress that acts on the nodes with stiffness-proportional damping: σ + (β_R / Δt)(σ − σ_old),
/// the elastic stress plus β_R σ̇ over the step, Pa; σ itself (`old` unread) when `ratio` is 0.
#[inline]
pub(crate) fn with_viscous(s: &Stress, old: &Stress, ratio: f64) -> Stress {
    if ratio == 0.0 {
        return *s;
    }
    std::array::from_fn(|k| s[k] + ratio * (s[k] - old[k]))
}

/// Advance a zone's `s` (Pa), `state` and `plastic` by `de` through its `law`: `trial` from a
/// commit (the implicit path) or `update` (a cycle).
#[inline]
pub(crate) fn advance(
    law: &dyn ZoneLaw,
    trial: bool,
    s: &mut Stress,
    state: &mut u8,
    plastic: &mut f64,
    de: &StrainIncrement,
) {
    if trial {
        law.trial(s, state, plastic, de);
    } else {
        law.update(s, state, plastic, de);
    }
}

/// Seconds spent in each stage since the start of the run.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct StageSeconds {
    pub detect: f64,
    pub contacts: f64,
    pub zones: f64,
    /// The structural stage's, and the far field's (`region.far_field`) with it.
    pub supports: f64,
    pub motion: f64,
    /// The dynamic stage's (`dynamic.rs`: quiet and free-field boundaries, prescribed motions
    /// and load histories, peak velocities, the energy balance; absent when nothing ran).
    #[serde(skip_serializing_if = "is_zero")]
    pub dynamics: f64,
    pub output: f64,
    /// Implicit solves: assembling, factorizing and iterating (absent when none ran).
    #[serde(skip_serializing_if = "is_zero")]
    pub implicit: f64,
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

/// Scratch space and timers of the cycle.
#[derive(Debug, Default)]
pub struct Cycle {
    /// Force of each zone on each of its corners, N/m, indexed zone·3 + corner.
    zone_force: Vec<[f64; 2]>,
    /// Force of each contact on its node and on the two nodes of its edge, N/m, contact·3 + role.
    contact_force: Vec<[f64; 2]>,
    /// Energy each contact's joint took in the last contact stage, J/m (`contact_forces`).
    contact_work: Vec<f64>,
    /// Force of the supports on the rock nodes, N/m, one per support slot
    /// (`Supports::slot_nodes`).
    support_force: Vec<[f64; 2]>,
    /// Force of the far field on each interface node, N/m (`FarField::nodes`), and the
    /// interface's displacement scratch.
    far_force: Vec<[f64; 2]>,
    far_moved: Vec<[f64; 2]>,
    /// Upper bound on how far any node has moved since the last detection, m.
    moved: f64,
    /// 1 / (shortest zone edge at each node), 1/m (0 for nodes without zones).
    inv_size: Vec<f64>,
    /// The largest step of the last cycle relative to the node's shortest zone edge, |v| Δt / h,
    /// and that of the cycle before.
    jump: f64,
    last_jump: f64,
    /// Mixed discretization scratch: each zone's strain increment, each node's area-averaged
    /// volumetric strain increment (then its averaged plastic change of mean stress, Pa), and each
    /// zone's plastic change of mean stress, Pa.
    zone_strain: Vec<StrainIncrement>,
    node_volumetric: Vec<f64>,
    zone_plastic_mean: Vec<f64>,
    /// Mixed discretization, implicit path: each zone's plastic mean-stress shift from its last
    /// trial, Pa, which its next trial adds to its predictor (`mixed`; zero at a commit).
    zone_pressure_lag: Vec<f64>,
    /// Mixed discretization scratch: each zone's stress at the start of the step, Pa (written only
    /// with stiffness-proportional damping, whose viscous stress is the step's change).
    zone_stress_start: Vec<Stress>,
    /// Viscous stress β_R σ̇ of each body over its last step, Pa (zero for rigid blocks and
    /// without stiffness-proportional damping).
    body_viscous: Vec<Stress>,
    seconds: StageSeconds,
    /// Contact detections so far (the solver re-derives static masses after each).
    detections: u64,
    /// Time since the cycle was made (the solve began), s: the time the next step's forces
    /// act at.
    time: f64,
}

impl Cycle {
    /// Seconds spent in each stage so far.
    pub fn seconds(&self) -> StageSeconds {
        self.seconds
    }

    /// Contact detections so far.
    pub fn detections(&self) -> u64 {
        self.detections
    }

    pub fn new(model: &Model) -> Cycle {
        Cycle {
            zone_force: vec![[0.0; 2]; 3 * model.zones.len()],
            contact_force: vec![[0.0; 2]; 3 * model.contacts.len()],
            contact_work: vec![0.0; model.contacts.len()],
            support_force: vec![[0.0; 2]; model.supports.slot_count()],
            far_force: vec![[0.0; 2]; model.far_field.as_ref().map_or(0, |f| f.nodes.len())],
            far_moved: vec![[0.0; 2]; model.far_field.as_ref().map_or(0, |f| f.nodes.len())],
            inv_size: inverse_zone_size(model),
            zone_strain: vec![[0.0; 3]; model.mixed.as_ref().map_or(0, |_| model.zones.len())],
            node_volumetric: vec![0.0; model.mixed.as_ref().map_or(0, |_| model.nodes.len())],
            zone_plastic_mean: vec![0.0; model.mixed.as_ref().map_or(0, |_| model.zones.len())],
            zone_pressure_lag: vec![0.0; model.mixed.as_ref().map_or(0, |_| model.zones.len())],
            zone_stress_start: vec![
                [0.0; 4];
                model.mixed.as_ref().map_or(0, |_| model.zones.len())
            ],
            body_viscous: vec![[0.0; 4]; model.bodies.len()],
            ..Default::default()
        }
    }

    /// Advance the model by one step: the stages in order, each handed the parts of the model it
    /// reads (shared) and writes (exclusive).
    pub fn run(&mut self, model: &mut Model, p: &CycleParams) {
        let Model {
            nodes,
            zones,
            gather,
            blocks,
            bodies,
            contacts,
            contact_tolerance,
            supports,
            mixed,
            support_gather,
            far_field,
            far_gather,
            materials,
            quiet,
            inputs,
            peaks,
            ejection,
            energy,
            ..
        } = model;
        let (laws, joint_laws) = (&materials.zone, &materials.joint);
        let t0 = Instant::now();
        self.detect_when_moved(nodes, blocks, contacts, materials, *contact_tolerance);
        let t1 = Instant::now();
        self.contact_forces(nodes, blocks, contacts, joint_laws, p, None);
        let t2 = Instant::now();
        self.zone_forces(nodes, zones, laws, gather, mixed.as_deref(), p);
        let t3 = Instant::now();
        self.structural_forces(supports, &nodes.disp, p);
        self.far_field_forces(far_field.as_ref(), &nodes.disp);
        let t4 = Instant::now();
        let gathers = Gathers {
            zones: gather,
            contacts: &contacts.gather,
            supports: support_gather,
            far_field: far_gather,
        };
        let mut dynamic = dynamic::Dynamic {
            quiet,
            inputs,
            peaks,
            ejection,
            energy,
        };
        dynamic.before_motion(nodes, bodies, self.time, p.dt);
        let t5 = Instant::now();
        let speed = self
            .motion(nodes, &gathers, p)
            .max(self.body_motion(nodes, bodies, laws, p));
        let t6 = Instant::now();
        let exchanged = dynamic::Exchanged {
            joints: &self.contact_work,
            supports: &self.support_force,
        };
        let damped = dynamic::Damped {
            nodes: p.damping > 0.0 || p.mass_damping > 0.0,
            viscous: p.viscous_ratio(),
            zones,
            laws,
            internal: &|n| self.internal_force(&gathers, n),
        };
        let time = self.time;
        let speed = speed.max(dynamic.after_motion(nodes, bodies, exchanged, damped, time, p.dt));
        self.time += p.dt;
        self.moved += speed * p.dt;
        let t7 = Instant::now();
        self.seconds.detect += (t1 - t0).as_secs_f64();
        self.seconds.contacts += (t2 - t1).as_secs_f64();
        self.seconds.zones += (t3 - t2).as_secs_f64();
        self.seconds.supports += (t4 - t3).as_secs_f64();
        self.seconds.motion += (t6 - t5).as_secs_f64();
        self.seconds.dynamics += ((t5 - t4) + (t7 - t6)).as_secs_f64();
    }

    /// Fill the zone, contact and support forces of the state as it is, without moving it: the
    /// force stages with a zero step (zero strain and displacement increments), so `node_force`
    /// gives the out-of-balance force of a state before its first cycle.
    pub fn prime(&mut self, model: &mut Model, p: &CycleParams) {
        self.prime_but_zones(model, p, None);
        self.model_zone_forces(model, &CycleParams { dt: 0.0, ..*p });
    }

    /// The zone stage (`zone_forces`) on `model`'s own zones, nodes and laws.
    fn model_zone_forces(&mut self, model: &mut Model, p: &CycleParams) {
        let Model {
            nodes,
            zones,
            gather,
            mixed,
            materials,
            ..
        } = model;
        self.zone_forces(nodes, zones, &materials.zone, gather, mixed.as_deref(), p);
    }

    /// `prime` of the contact and support forces only; the zone forces stay as they are. The
    /// joints take their trial from `joints` where given (`contact_forces`).
    fn prime_but_zones(&mut self, model: &mut Model, p: &CycleParams, joints: Option<JointCommit>) {
        let still = CycleParams { dt: 0.0, ..*p };
        let Model {
            nodes,
            blocks,
            contacts,
            supports,
            far_field,
            materials,
            ..
        } = model;
        self.contact_forces(nodes, blocks, contacts, &materials.joint, &still, joints);
        self.structural_forces(supports, &nodes.disp, &still);
        self.far_field_forces(far_field.as_ref(), &nodes.disp);
    }

    /// The out-of-balance force of the state as it is, N/m, into `nodes.force` (zero in a fixed
    /// component, as the motion stage leaves it): the force stages with a zero step (`prime`),
    /// gathered per node; the zone stage skipped when `zones_current` (the zone forces are those
    /// of the state as it is: `displace` left them); the joints' trial from `joints` where given.
    /// The implicit path's residual, measured as the explicit path measures it.
    pub fn balance(
        &mut self,
        model: &mut Model,
        p: &CycleParams,
        zones_current: bool,
        joints: Option<JointCommit>,
    ) {
        self.prime_but_zones(model, p, joints);
        if !zones_current {
            self.model_zone_forces(model, &CycleParams { dt: 0.0, ..*p });
        }
        for n in 0..model.nodes.len() {
            let mut f = self.node_force(model, n);
            let fixed = model.nodes.fixed[n];
            // A body node's force goes whole to its body, whose constraint takes the fixities.
            for (d, flag) in [(0, FIX_X), (1, FIX_Y)] {
                if fixed & flag != 0 && fixed & BODY == 0 {
                    f[d] = 0.0;
                }
            }
            model.nodes.force[n] = f;
        }
        if !model.bodies.is_empty() {
            self.body_balance(&mut model.nodes, &mut model.bodies);
        }
    }

    /// Move the nodes by `du` (m) in one step of the contact and zone stages, both from the
    /// commit `from` (`implicit::commit`): each contact's joint law takes the relative
    /// displacement since its commit, and each zone's law its strain since the zones' commit
    /// (the zones hold the committed state), sym(∇(u + du − u_c)), through `trial`; then `du` is
    /// added to the displacements, and contacts are detected again once any node may have moved
    /// half the contact tolerance. No damping acts. The implicit path's update.
    pub fn displace(&mut self, model: &mut Model, du: &[[f64; 2]], from: Trial, p: &CycleParams) {
        let unit = CycleParams {
            dt: 1.0,
            mass_damping: 0.0,
            stiffness_damping: 0.0,
            trial: true,
            ..*p
        };
        model.nodes.vel.copy_from_slice(du);
        let largest = du.iter().fold(0.0f64, |m, d| m.max(d[0].hypot(d[1])));
        let Model {
            nodes,
            blocks,
            contacts,
            materials,
            contact_tolerance,
            ..
        } = model;
        // The joints' states at the new place matter here only to a detection, which carries
        // them to the contacts that persist; the residual (`balance`) evaluates them anew.
        if self.detects_after(blocks, largest, *contact_tolerance) {
            self.contact_forces(
                nodes,
                blocks,
                contacts,
                &materials.joint,
                &unit,
                Some(from.joints),
            );
        }
        for (((v, u), d), c) in nodes.vel.iter_mut().zip(&nodes.disp).zip(du).zip(from.disp) {
            *v = [u[0] + d[0] - c[0], u[1] + d[1] - c[1]];
        }
        self.model_zone_forces(model, &unit);
        let Model {
            nodes,
            blocks,
            contacts,
            contact_tolerance,
            materials,
            ..
        } = model;
        for (u, d) in nodes.disp.iter_mut().zip(du) {
            u[0] += d[0];
            u[1] += d[1];
        }
        nodes.vel.iter_mut().for_each(|v| *v = [0.0; 2]);
        self.moved += largest;
        self.detect_when_moved(nodes, blocks, contacts, materials, *contact_tolerance);
    }

    /// Whether the detect stage runs once the nodes have moved `more` (m) further: when any node
    /// may have moved half the contact `tolerance` (m) since the last detection (and there are
    /// blocks to touch).
    fn detects_after(&self, blocks: &Blocks, more: f64, tolerance: f64) -> bool {
        blocks.len() > 1 && self.moved + more > 0.5 * tolerance
    }

    /// The detect stage, when any node may have moved half the contact `tolerance` (m) since the
    /// last detection (and there are blocks to touch).
    fn detect_when_moved(
        &mut self,
        nodes: &Nodes,
        blocks: &Blocks,
        contacts: &mut Contacts,
        materials: &Materials,
        tolerance: f64,
    ) {
        if self.detects_after(blocks, 0.0, tolerance) {
            let x = nodes.current();
            let d = Detection {
                blocks,
                x: &x,
                tolerance,
                joint_material: &materials.feature,
                hole_material: &materials.hole,
            };
            self.detect(&d, contacts);
        }
    }

    /// Structural stage: bolts and liners take the rock's displacements `rock` (m), push back on
    /// the rock through the support slots, and move their own nodes (`support::Supports::cycle`).
    pub fn structural_forces(
        &mut self,
        supports: &mut Supports,
        rock: &[[f64; 2]],
        p: &CycleParams,
    ) {
        if supports.is_empty() {
            return;
        }
        supports.cycle(rock, &mut self.support_force, p.damping, p.dt);
    }

    /// Zone stage, by the solve's `ZoneScheme`: the zones' stresses and corner forces from the
    /// nodes' motion and the zone laws; the mixed scheme also reads the zone gather and each
    /// node's 1 / patch area (`Model::mixed`), 1/m².
    pub fn zone_forces(
        &mut self,
        nodes: &Nodes,
        zones: &mut Zones,
        laws: &[Box<dyn ZoneLaw>],
        gather: &Gather,
        inv_patch: Option<&[f64]>,
        p: &CycleParams,
    ) {
        match p.scheme {
            ZoneScheme::SmallStrain => self.zone_forces_small(nodes, zones, laws, p),
            ZoneScheme::Mixed => {
                let inv_patch = inv_patch.expect("the mixed scheme is chosen only with patches");
                self.zone_forces_mixed(nodes, zones, laws, gather, inv_patch, p)
            }
            ZoneScheme::LargeStrain => self.zone_forces_large(nodes, zones, laws, p),
        }
    }

    /// Small-strain zone stage: strain increment from node velocities, Δε = sym(∇v)Δt with the CST
    /// gradients, stress update by the zone law, then corner forces f_i = −A σ·∇N_i
    /// (the virtual-work nodal force of a constant-stress triangle).
    fn zone_forces_small(
        &mut self,
        nodes: &Nodes,
        zones: &mut Zones,
        laws: &[Box<dyn ZoneLaw>],
        p: &CycleParams,
    ) {
        let vel = &nodes.vel;
        let (dt, viscous, trial) = (p.dt, p.viscous_ratio(), p.trial);
        zones
            .stress
            .par_iter_mut()
            .zip(zones.state.par_iter_mut())
            .zip(zones.plastic.par_iter_mut())
            .zip(self.zone_force.par_chunks_mut(3))
            .zip(zones.nodes.par_iter())
            .zip(zones.grad.par_iter())
            .zip(zones.area.par_iter())
            .zip(zones.material.par_iter())
            .with_min_len(1024)
            .for_each(|(((((((s, state), plastic), f), t), g), &area), mat)| {
                let l = velocity_gradient(g, t.map(|n| vel[n as usize]));
                let de = strain_increment(&l, dt);
                let old = *s;
                advance(laws[mat.0 as usize].as_ref(), trial, s, state, plastic, &de);
                corner_forces(&with_viscous(s, &old, viscous), g, area, f);
            });
    }

    /// Total force on node `n`, N/m, from the last cycle: its applied load plus the zone, contact
    /// and support forces gathered as the motion stage does, before fixities and damping. At a
    /// fixed node its negative is the reaction of the support (a platen's load, for instance).
    pub fn node_force(&self, model: &Model, n: usize) -> [f64; 2] {
        let gathers = Gathers {
            zones: &model.gather,
            contacts: &model.contacts.gather,
            supports: &model.support_gather,
            far_field: &model.far_gather,
        };
        let [a, f] = [model.nodes.applied[n], self.internal_force(&gathers, n)];
        [a[0] + f[0], a[1] + f[1]]
    }

    /// The force the rock, its joints, supports and far field put on node `n` in the last
    /// cycle (its zone, contact, support and far-field forces gathered by `gathers`), N/m.
    fn internal_force(&self, gathers: &Gathers, n: usize) -> [f64; 2] {
        let mut f = [0.0; 2];
        let sources = [
            (gathers.zones, &self.zone_force),
            (gathers.contacts, &self.contact_force),
            (gathers.supports, &self.support_force),
            (gathers.far_field, &self.far_force),
        ];
        for (gather, forces) in sources {
            for &s in gather.of(n) {
                let c = forces[s as usize];
                f[0] += c[0];
                f[1] += c[1];
            }
        }
        f
    }

    /// Motion stage: gather forces per node in a fixed order (deterministic on any thread count),
    /// add applied loads, apply local non-viscous damping F_d = F − α|F|sign(v) per component
    /// (Cundall 1987; UDEC's default), then the central-difference update
    /// v ← v + F_d Δt / m, u ← u + v Δt; with mass-proportional Rayleigh damping α_R the viscous
    /// force −α_R m v is taken at the mean of the old and new velocities (`mass_damping_factors`). A fixed component keeps its velocity (zero unless
    /// the scene or a test prescribes one), as FLAC's FIX. Returns the largest node speed, m/s,
    /// and records in `jump` the largest step relative to the node's zone size (an explicit
    /// scheme past its stability limit grows such steps by a large factor every cycle).
    pub fn motion(&mut self, nodes: &mut Nodes, gathers: &Gathers, p: &CycleParams) -> f64 {
        let (zf, cf, sf) = (&self.zone_force, &self.contact_force, &self.support_force);
        let ff = &self.far_force;
        let Gathers {
            zones: gather,
            contacts: contact_gather,
            supports: support_gather,
            far_field: far_gather,
        } = *gathers;
        let inv_size = &self.inv_size;
        let (alpha, dt) = (p.damping, p.dt);
        let (keep, gain) = mass_damping_factors(p);
        let (speed2, jump2) = nodes
            .vel
            .par_iter_mut()
            .zip(nodes.disp.par_iter_mut())
            .zip(nodes.force.par_iter_mut())
            .zip(nodes.applied.par_iter())
            .zip(nodes.mass.par_iter())
            .zip(nodes.fixed.par_iter())
            .enumerate()
            .with_min_len(1024)
            .map(|(n, (((((v, u), force), applied), &m), &fixed))| {
                let mut f = *applied;
                for &s in gather.of(n) {
                    let c = zf[s as usize];
                    f[0] += c[0];
                    f[1] += c[1];
                }
                for &s in contact_gather.of(n) {
                    let c = cf[s as usize];
                    f[0] += c[0];
                    f[1] += c[1];
                }
                for &s in support_gather.of(n) {
                    let c = sf[s as usize];
                    f[0] += c[0];
                    f[1] += c[1];
                }
                for &s in far_gather.of(n) {
                    let c = ff[s as usize];
                    f[0] += c[0];
                    f[1] += c[1];
                }
                if fixed & BODY != 0 {
                    *force = f;
                    return (0.0, 0.0);
                }
                for (d, flag) in [(0, FIX_X), (1, FIX_Y)] {
                    if fixed & flag != 0 {
                        f[d] = 0.0;
                    } else {
                        let fd = local_damping(f[d], v[d], alpha);
                        v[d] = keep * v[d] + gain * fd / m * dt;
                    }
                    u[d] += v[d] * dt;
                }
                *force = f;
                let v2 = v[0] * v[0] + v[1] * v[1];
                (v2, v2 * inv_size[n] * inv_size[n])
            })
            .reduce(|| (0.0, 0.0), |a, b| (a.0.max(b.0), a.1.max(b.1)));
        self.last_jump = self.jump;
        self.jump = jump2.sqrt() * dt;
        speed2.sqrt()
    }
}

/// (keep, gain) of the velocity update v ← keep·v + gain·F Δt / m with mass-proportional damping
/// α_R: m (v⁺ − v)/Δt = F − α_R m (v⁺ + v)/2 gives keep = (1 − a)/(1 + a), gain = 1/(1 + a),
/// a = α_R Δt / 2; stable at any α_R (a mode's amplification only shrinks), (1, 1) without.
#[inline]
pub(crate) fn mass_damping_factors(p: &CycleParams) -> (f64, f64) {
    let a = 0.5 * p.mass_damping * p.dt;
    ((1.0 - a) / (1.0 + a), 1.0 / (1.0 + a))
}

/// Velocity gradient of a constant-strain triangle, L[i][j] = ∂v_i/∂x_j (1/s), from its gradients
/// and its corners' velocities.
#[inline]
fn velocity_gradient(g: &[f64; 6], v: [[f64; 2]; 3]) -> [[f64; 2]; 2] {
    let dx = |c: usize| g[0] * v[0][c] + g[1] * v[1][c] + g[2] * v[2][c];
    let dy = |c: usize| g[3] * v[0][c] + g[4] * v[1][c] + g[5] * v[2][c];
    [[dx(0), dy(0)], [dx(1), dy(1)]]
}

/// Strain increment Δε = sym(L)Δt = [Δεxx, Δεyy, Δγxy] of a velocity gradient L.
#[inline]
fn strain_increment(l: &[[f64; 2]; 2], dt: f64) -> StrainIncrement {
    [l[0][0] * dt, l[1][1] * dt, (l[0][1] + l[1][0]) * dt]
}

/// Corner forces of a constant-stress triangle, f_i = −A σ·∇N_i, N/m.
#[inline]
fn corner_forces(s: &crate::model::Stress, g: &[f64; 6], area: f64, f: &mut [[f64; 2]]) {
    for i in 0..3 {
        let (bx, by) = (g[i], g[3 + i]);
        f[i] = [
            -area * (s[0] * bx + s[3] * by),
            -area * (s[3] * bx + s[1] * by),
        ];
    }
}

/// 1 / (shortest zone edge at each node), 1/m; 0 for nodes no zone touches.
fn inverse_zone_size(model: &Model) -> Vec<f64> {
    let pos = &model.nodes.pos;
    let mut h = vec![f64::INFINITY; pos.len()];
    for t in &model.zones.nodes {
        for k in 0..3 {
            let (a, b) = (t[k] as usize, t[(k + 1) % 3] as usize);
            let len = (pos[b][0] - pos[a][0]).hypot(pos[b][1] - pos[a][1]);
            h[a] = h[a].min(len);
            h[b] = h[b].min(len);
        }
    }
    h.into_iter().map(|h| 1.0 / h).collect()
}
