//! The run driver: derive the time step and masses, cycle to the stop criterion, record the
//! history, and report intermediate output steps to an observer.

use crate::cycle::timestep::{
    Limiter, StepLimit, add_contact_stiffness, body_masses, body_step, body_stiffness,
    critical_step, damped_margin, lumped_masses, scaled_masses, viscous_margin, zone_stiffness,
};
use crate::cycle::{Cycle, CycleParams, Monitor, ZoneScheme};
use crate::model::Model;
use crate::model::bodies::{NO_BODY, projector};
use crate::scene::{SolveMode, SolveSpec};

pub use crate::cycle::monitor::{UNSTABLE_GROWTH, UNSTABLE_JUMP};

/// How a solve ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Status {
    /// The unbalanced-force ratio fell below the target.
    Converged,
    /// A dynamic solve ran its `duration`.
    Completed,
    /// The cycle limit was reached first.
    CycleLimit,
    /// The run was stopped; the reason names the node or zone.
    Failed(String),
    /// Ctrl-C or SIGTERM stopped the run at the end of a cycle (`interrupt`).
    Interrupted,
}

impl Status {
    pub fn label(&self) -> &'static str {
        match self {
            Status::Converged => "converged",
            Status::Completed => "completed",
            Status::CycleLimit => "cycle_limit",
            Status::Failed(_) => "failed",
            Status::Interrupted => "interrupted",
        }
    }
}

/// One history row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HistoryRow {
    pub cycle: u64,
    /// Time, s (fictitious in static runs: cycles × 1 s).
    pub time: f64,
    pub ratio: f64,
    /// Kinetic energy, J/m.
    pub kinetic: f64,
}

/// What a solve produced.
#[derive(Debug, Clone)]
pub struct Solution {
    pub status: Status,
    pub cycles: u64,
    pub(crate) history: Vec<HistoryRow>,
    pub final_ratio: f64,
}

impl Solution {
    /// The monitor rows of the solve, in order.
    pub fn history(&self) -> &[HistoryRow] {
        &self.history
    }

    /// This solve followed by `rest`, which went on from where it stopped: the cycles and the
    /// history of both (`rest`'s counted on from this one's), `rest`'s status and final ratio.
    pub fn then(mut self, rest: Solution) -> Solution {
        let offset = self.cycles;
        self.history.extend(rest.history.iter().map(|r| HistoryRow {
            cycle: r.cycle + offset,
            ..*r
        }));
        Solution {
            status: rest.status,
            cycles: offset + rest.cycles,
            history: self.history,
            final_ratio: rest.final_ratio,
        }
    }
}

/// Receives progress during a solve.
pub trait Observer: Send {
    /// After each monitor step.
    fn monitored(&mut self, _row: &HistoryRow) {}
    /// After each monitor step, right after `monitored`: the model as it is then (the
    /// monitoring points read it).
    fn sampled(&mut self, _model: &Model) {}
    /// When stage `name` starts (empty in an unstaged run), at cycle `from` of the run (monitor
    /// rows count from the run's start), with its own cycle limit `max_cycles`.
    fn stage_started(&mut self, _name: &str, _from: u64, _max_cycles: u64) {}
    /// When an intermediate output step is due (every `output_every` cycles).
    fn output_step(&mut self, _cycle: u64, _time: f64, _model: &Model, _cycle_state: &mut Cycle) {}
    /// After an implicit solve factorized its stiffness: the factor's size (bytes of its
    /// values) and the seconds assembling and factorizing took.
    fn factorized(&mut self, _bytes: usize, _seconds: f64) {}
}

/// An observer that ignores everything.
pub struct Quiet;
impl Observer for Quiet {}

/// Time step, masses and cycle scratch for a model.
pub struct Solver {
    pub cycle: Cycle,
    pub params: CycleParams,
    /// Step limit with real masses (reported in every mode).
    pub step: StepLimit,
    pub spec: SolveSpec,
    /// Cycles between intermediate output steps (0: none).
    pub(crate) output_every: u64,
}

impl Solver {
    /// Set nodal masses and the time step for the solve mode: static runs scale masses so that
    /// Δt = 1 s is stable; dynamic runs keep real masses and take Δt = s·Δt_crit.
    pub fn new(model: &mut Model, spec: &SolveSpec, output_every: u64) -> Solver {
        let (dt, step) = derive_masses(model, spec);
        Solver {
            cycle: Cycle::new(model),
            params: CycleParams {
                dt,
                damping: spec.damping_coefficient(),
                scheme: ZoneScheme::of(model, spec.large_strain),
                mass_damping: spec.rayleigh.map_or(0.0, |r| r.coefficients().0),
                stiffness_damping: spec.rayleigh.map_or(0.0, |r| r.coefficients().1),
                trial: false,
            },
            step,
            spec: spec.clone(),
            output_every,
        }
    }

    /// Cycle until converged, the cycle limit, or failure.
    pub fn solve(&mut self, model: &mut Model, observer: &mut dyn Observer) -> Solution {
        // Cycle on a worker thread of the pool: each stage's parallel loop then starts from inside
        // the pool instead of injecting a job and blocking the caller, several times per cycle.
        rayon::scope(|_| self.cycle_to_stop(model, observer))
    }

    fn cycle_to_stop(&mut self, model: &mut Model, observer: &mut dyn Observer) -> Solution {
        let mut history = Vec::new();
        let mut last = Monitor {
            ratio: f64::INFINITY,
            kinetic: 0.0,
            max_force: 0.0,
        };
        let every = self.spec.monitor_every;
        let ramp = Ramp::start(self.spec.ramp, model, &mut self.cycle, &self.params);
        // A dynamic solve with a duration runs its cycles, the ratio notwithstanding.
        let end = (self.spec.mode == SolveMode::Dynamic)
            .then_some(self.spec.duration)
            .flatten()
            .map(|d| (d / self.params.dt).ceil().max(1.0) as u64);
        let mut cycle = 0u64;
        let status = loop {
            if let Some(ramp) = &ramp {
                ramp.apply(cycle, model);
            }
            let detections = self.cycle.detections();
            self.cycle.run(model, &self.params);
            cycle += 1;
            // New contacts add stiffness at their nodes: static masses follow (FLAC rescales its
            // masses as the stiffness changes), or a node that gains a contact can go unstable.
            if self.cycle.detections() != detections && self.spec.mode == SolveMode::Static {
                self.step = derive_masses(model, &self.spec).1;
            }
            if let Some(reason) = self.cycle.unstable_step(model, self.params.dt) {
                break Status::Failed(format!("cycle {cycle}: {reason}"));
            }
            let time = cycle as f64 * self.params.dt;
            // An interrupted solve records its last cycle, so the history ends at the cycle reached.
            let interrupted = crate::interrupt::requested();
            let due = cycle.is_multiple_of(every) || cycle == self.spec.max_cycles || interrupted;
            if due {
                match self.cycle.monitor(model) {
                    Ok(m) => last = m,
                    Err(reason) => break Status::Failed(format!("cycle {cycle}: {reason}")),
                }
                let row = HistoryRow {
                    cycle,
                    time,
                    ratio: last.ratio,
                    kinetic: last.kinetic,
                };
                history.push(row);
                observer.monitored(&row);
                observer.sampled(model);
                if end.is_none() && last.ratio <= self.spec.ratio && cycle > self.spec.ramp {
                    break Status::Converged;
                }
            }
            if end.is_some_and(|e| cycle >= e) {
                break Status::Completed;
            }
            if cycle >= self.spec.max_cycles {
                break Status::CycleLimit;
            }
            if interrupted {
                break Status::Interrupted;
            }
            if self.output_every > 0 && cycle.is_multiple_of(self.output_every) {
                observer.output_step(cycle, time, model, &mut self.cycle);
            }
        };
        Solution {
            status,
            cycles: cycle,
            history,
            final_ratio: last.ratio,
        }
    }
}

/// The out-of-balance force F0 a static solve starts with, released gradually: the nodes carry
/// their applied loads minus a held share h of F0, so the net force grows from zero (h = 1) to
/// the true one (h = 0), as when a load is applied slowly (FLAC's gradual relaxation of an
/// excavation's forces works the same way). F0 is the nodal force of the zones, contacts and
/// supports in the state the solve starts from, with the loads; a rigid or simple block's own
/// weight and stress terms are released at once. Explicit cycling holds it over `solve.ramp`
/// cycles ([`Ramp`]), the implicit path in `solve.load_steps` steps (`implicit::steps`).
pub struct Release {
    /// The nodes' applied loads, N/m.
    applied: Vec<[f64; 2]>,
    /// F0, N/m.
    unbalanced: Vec<[f64; 2]>,
}

impl Release {
    /// F0 of `model` as it is now.
    pub fn of(model: &mut Model, cycle: &mut Cycle, params: &CycleParams) -> Release {
        cycle.prime(model, params);
        let unbalanced = (0..model.nodes.len())
            .map(|n| cycle.node_force(model, n))
            .collect();
        Release {
            applied: model.nodes.applied.clone(),
            unbalanced,
        }
    }

    /// Set the nodes' loads to the applied ones minus `held` × F0 (the applied loads themselves
    /// at 0).
    pub fn hold(&self, held: f64, model: &mut Model) {
        if held == 0.0 {
            model.nodes.applied.copy_from_slice(&self.applied);
            return;
        }
        for ((a, full), f0) in (model.nodes.applied.iter_mut())
            .zip(&self.applied)
            .zip(&self.unbalanced)
        {
            *a = [full[0] - held * f0[0], full[1] - held * f0[1]];
        }
    }
}

/// `solve.ramp`: at cycle c < N the held share of F0 is 1 − c/N ([`Release`]).
struct Ramp {
    cycles: u64,
    release: Release,
}

impl Ramp {
    fn start(
        cycles: u64,
        model: &mut Model,
        cycle: &mut Cycle,
        params: &CycleParams,
    ) -> Option<Ramp> {
        (cycles > 0).then(|| Ramp {
            cycles,
            release: Release::of(model, cycle, params),
        })
    }

    /// Set the loads for cycle `c` (the applied loads themselves from cycle N on).
    fn apply(&self, c: u64, model: &mut Model) {
        if c > self.cycles {
            return;
        }
        let held = 1.0 - c as f64 / self.cycles as f64;
        self.release.hold(held, model);
    }
}

/// Nodal and body masses and the time step for the solve mode, from the stiffness of the zones,
/// the current contacts and the supports (`cycle::timestep`); returns Δt, s, and the step limit
/// with real masses.
pub fn derive_masses(model: &mut Model, spec: &SolveSpec) -> (f64, StepLimit) {
    let alpha = spec.damping_coefficient();
    let mut zones_only = zone_stiffness(model);
    // The far field's row sums stiffen its interface's nodes (counted with the zones').
    if let Some(f) = &model.far_field {
        for (&n, k) in f.nodes.iter().zip(f.row_sums()) {
            zones_only[n as usize] += k;
        }
    }
    let mut stiffness = zones_only.clone();
    add_contact_stiffness(model, &mut stiffness);
    let with_contacts = stiffness.clone();
    let s = spec.safety_factor;
    let scaled = (spec.mode == SolveMode::Static).then_some(s);
    let support_dt = model.supports.set_masses(&mut stiffness, scaled, alpha);
    let real = lumped_masses(model);
    let mut step = critical_step(&stiffness, &real);
    // Name the largest share of the limiting node's stiffness.
    let n = step.limiting_node.0 as usize;
    let (zones, contacts) = (zones_only[n], with_contacts[n] - zones_only[n]);
    let supports = stiffness[n] - with_contacts[n];
    step.by = if support_dt < step.dt_critical || supports > zones.max(contacts) {
        Limiter::Supports
    } else if contacts > zones {
        Limiter::Contacts
    } else {
        Limiter::Zones
    };
    step.dt_critical = step.dt_critical.min(support_dt);
    let body_k = body_stiffness(model, &stiffness);
    let body_real = body_masses(model);
    body_step(model, &body_k, &body_real, &mut step);
    let dt = match spec.mode {
        SolveMode::Static => {
            model.nodes.mass = scaled_masses(&stiffness, s, alpha);
            model.bodies.mass = body_k
                .iter()
                .map(|d| {
                    d.map(|k| {
                        if k > 0.0 {
                            k * damped_margin(s, alpha) / (4.0 * s * s)
                        } else {
                            1.0
                        }
                    })
                })
                .collect();
            1.0
        }
        SolveMode::Dynamic => {
            model.nodes.mass = real;
            model.bodies.mass = body_real;
            let beta = spec.rayleigh.map_or(0.0, |r| r.coefficients().1);
            s * step.dt_critical * viscous_margin(beta, step.dt_critical)
        }
    };
    let bodies = &mut model.bodies;
    bodies.projector = (0..bodies.len())
        .map(|k| {
            projector(
                &bodies.constraint[k],
                &bodies.mass[k],
                bodies.mode[k].dofs(),
            )
        })
        .collect();
    // Body nodes move with their body and carry no mass of their own.
    for (m, &b) in model.nodes.mass.iter_mut().zip(&model.bodies.of_node) {
        if b != NO_BODY {
            *m = 0.0;
        }
    }
    (dt, step)
}
