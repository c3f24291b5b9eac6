//! Static equilibrium by a sparse direct solve (issue 17): the zones' stiffness is assembled once
//! per stage over the free components and factorized by faer's sparse Cholesky; each iteration
//! solves K Δu = R for the out-of-balance force R that the explicit force stages compute, and
//! moves the model by Δu through the same zone stage, so the zone laws are the explicit path's
//! and both stop on the same unbalanced-force ratio. For elastic zones one iteration reaches
//! equilibrium to round-off; yielding zones converge as the initial-stiffness method
//! (modified Newton: Zienkiewicz, Valliappan & King 1969), the factorization reused, accelerated
//! by Anderson mixing of the last iterates (`anderson`).
//!
//! Contacts enter the matrix with their joints' elastic stiffness (the initial stiffness of a
//! joint, at its state where it depends on it, as the Barton–Bandis hyperbola's: in the matrix it
//! neither slips nor opens, while the residual carries the joint law's own forces), and the matrix is factorized again when a detection finds a node touching a block it
//! did not touch at the last factorization (a contact that slid onto the next edge, or opened,
//! leaves the matrix close enough or too stiff, and the iterations converge on it). Slip alone
//! converges linearly and slowly (`models/jointed_tunnel.json`: ratio 2.2e-3 after 200 plain
//! iterations; 111 iterations to 1e-5 accelerated, the joints' trial from the commit). The
//! tangent of slipping and open contacts diverged there (a wedge left without stiffness runs
//! off); at a tenth of their stiffness it saved iterations (52 instead of 118) but moved answers
//! that depend on where contacts are detected (`tests/engine/implicit.rs`,
//! `a_joint_that_closes_converges_on_the_stiff_answer`) and let a sliding block run off before
//! it was named.
//!
//! Bolts and liners bring their own unknowns and their elastic stiffness (`structural`). The
//! zones' and the joints' laws (through `ZoneLaw::trial` and `JointLaw::trial`) and the bolts'
//! grout slip and yield are evaluated from the state of the last commit and the whole
//! displacement since (`commit`). The
//! stage's out-of-balance force is released in `solve.load_steps` steps, a step that does not
//! converge halved from the last commit (`steps`).
//! Mixed zones (`zoning.mixed`) keep the plain triangles' matrix, too stiff volumetrically near
//! ν = 0.5, while the residual is the mixed zone stage's: the iterations converge to the mixed
//! answer (Lamé's cylinder at ν = 0.499: 123 iterations, no locking).
//!
//! Mechanisms: a block nothing holds is named before any factorization (`support`); a block that
//! slides or falls on its joints is named when the iterations run out and its corrections have
//! not shrunk (`moving`). Neither ends as converged or at a bare iteration limit; a stage that
//! ends at its iteration limit all the same names the block whose last correction was the
//! largest (`moving::fastest`).
//!
//! Rigid and simple blocks bring their generalised displacements as unknowns (`bodies`).
//!
//! Displacement control: `solve_driven` moves given fixed nodes by given displacements with the
//! first load step (`drive`), as a platen or a shear box moves a specimen.
//!
//! What it does not yet do (`implicit` is refused, `auto` cycles explicitly): the large-strain
//! zone update, and the continuously yielding joint (`JointLaw::implicit_refusal`).

mod anderson;
pub mod assemble;
mod bodies;
mod commit;
mod drive;
pub(crate) mod factor;
mod moving;
mod steps;
mod structural;
mod support;

use std::time::Instant;

use crate::cycle::{Cycle, CycleParams, ZoneScheme};
use crate::joint::JointLaw;
use crate::model::Model;
use crate::scene::{SolveMethod, SolveMode, SolveSpec};
use crate::solve::{HistoryRow, Observer, Solution, Status};
use anderson::Anderson;
pub use anderson::DEPTH as ANDERSON_DEPTH;
use assemble::{Dofs, stiffness};
use commit::Committed;
pub use drive::Drive;
use factor::{Factor, FactorError};
use moving::Movement;
use steps::LoadSteps;

/// How far the unbalanced-force ratio may grow over the least it reached since Anderson mixing
/// last restarted before the mixing restarts from a plain step. With the zones' trial from the
/// commit, restarting on any rise over the last iteration (as the zones integrated along the
/// path needed) took 888 iterations for the weak Salençon rock released at once and never
/// converged the shipped rock in 16 load steps; this rule took 177 and 174, the jointed tunnel
/// 200 at once and 226 in 16 steps (182 and 294 restarting on any rise). Restarting on a rise of
/// half over the last iteration was as fast on both but took the jointed tunnel in simple blocks
/// 556 iterations and a cut to +1.7 % of the explicit closure (66 iterations here).
const RESTART_RISE: f64 = 2.0;

/// Why the implicit path cannot solve a model of zone `scheme` and joint laws `joints`, or
/// `None` if it can.
pub fn unsupported(scheme: ZoneScheme, joints: &[Box<dyn JointLaw>]) -> Option<&'static str> {
    if scheme == ZoneScheme::LargeStrain {
        Some("the large-strain zone update (`solve.large_strain`) is not assembled")
    } else {
        joints.iter().find_map(|law| law.implicit_refusal())
    }
}

/// What an implicit solve cost (summed over the stages in `summary.json`).
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct Cost {
    /// Unknowns (free displacement components).
    pub unknowns: usize,
    /// Non-zeros stored of the stiffness matrix (its lower triangle).
    pub matrix_nonzeros: usize,
    /// Non-zeros of the Cholesky factor L (8 bytes of value each, with their row indices).
    pub factor_nonzeros: usize,
    pub factorizations: u64,
    /// Symbolic analyses (fill-reducing ordering and supernodes): a factorization whose matrix
    /// has the last one's pattern reuses its analysis, within a solve and across the stages of a
    /// run (`Analysis`).
    pub analyses: u64,
    pub iterations: u64,
    /// Load steps halved because they did not converge (`steps`).
    pub cuts: u64,
    /// Seconds assembling, factorizing, and iterating (residuals, solves, zone updates).
    pub assemble_s: f64,
    pub factorize_s: f64,
    pub iterate_s: f64,
}

impl Cost {
    /// Seconds the solve took in all: assembling, factorizing and iterating.
    pub fn seconds(&self) -> f64 {
        self.assemble_s + self.factorize_s + self.iterate_s
    }

    /// The costs of two solves together (the largest system's size).
    pub fn plus(self, o: Cost) -> Cost {
        Cost {
            unknowns: self.unknowns.max(o.unknowns),
            matrix_nonzeros: self.matrix_nonzeros.max(o.matrix_nonzeros),
            factor_nonzeros: self.factor_nonzeros.max(o.factor_nonzeros),
            factorizations: self.factorizations + o.factorizations,
            analyses: self.analyses + o.analyses,
            iterations: self.iterations + o.iterations,
            cuts: self.cuts + o.cuts,
            assemble_s: self.assemble_s + o.assemble_s,
            factorize_s: self.factorize_s + o.factorize_s,
            iterate_s: self.iterate_s + o.iterate_s,
        }
    }
}

/// The path a stage takes.
#[derive(Debug, Clone, PartialEq)]
pub enum Method {
    Explicit,
    Implicit,
    /// `auto` fell back to explicit cycling, for this reason.
    Fallback(&'static str),
}

/// The path `asked` takes on a model of zone `scheme`; an error (the reason) when `implicit` is
/// asked of what the implicit path cannot solve. `auto` takes the implicit path for every static
/// solve it can; a stage whose iterations do not converge is then handed over to explicit
/// cycling (`run`).
pub fn method(
    asked: SolveMethod,
    mode: SolveMode,
    scheme: ZoneScheme,
    joints: &[Box<dyn JointLaw>],
) -> Result<Method, &'static str> {
    match (asked, mode) {
        (SolveMethod::Explicit, _) => Ok(Method::Explicit),
        (SolveMethod::Auto, SolveMode::Dynamic) => Ok(Method::Explicit),
        (SolveMethod::Auto, SolveMode::Static) => Ok(match unsupported(scheme, joints) {
            Some(reason) => Method::Fallback(reason),
            None => Method::Implicit,
        }),
        (SolveMethod::Implicit, _) => match unsupported(scheme, joints) {
            Some(reason) => Err(reason),
            None => Ok(Method::Implicit),
        },
    }
}

/// The model's stiffness over `dofs`, factorized; an
/// error in words when it is not positive definite or its factor would not fit in memory. Its
/// size and time go to `observer`.
fn factorize(
    model: &Model,
    dofs: &Dofs,
    cost: &mut Cost,
    observer: &mut dyn Observer,
    last: Option<Factor>,
) -> Result<Factor, String> {
    let start = Instant::now();
    let k = stiffness(model, dofs)
        .map_err(|e| format!("implicit: the stiffness could not be assembled ({e:?})"))?;
    cost.assemble_s += start.elapsed().as_secs_f64();
    cost.matrix_nonzeros = cost.matrix_nonzeros.max(k.compute_nnz());
    let t = Instant::now();
    let factor = Factor::new(k.as_ref(), last).map(|(factor, reused)| {
        cost.analyses += u64::from(!reused);
        factor
    });
    cost.factorize_s += t.elapsed().as_secs_f64();
    cost.factorizations += 1;
    if let Ok(f) = &factor {
        cost.factor_nonzeros = cost.factor_nonzeros.max(f.nonzeros());
        let bytes = f.nonzeros() * std::mem::size_of::<f64>();
        observer.factorized(bytes, start.elapsed().as_secs_f64());
    }
    factor.map_err(|e| match e {
        FactorError::Memory(reason) => reason,
        FactorError::Numeric(e) => format!(
            "implicit: the stiffness is not positive definite ({e}): a part of the model is free \
             to move (a mechanism) or has no stiffness"
        ),
    })
}

/// The (node, block) pairs of `contacts`, sorted.
fn touching(contacts: &crate::model::Contacts) -> Vec<u64> {
    let mut pairs: Vec<u64> = (contacts.node.iter().zip(&contacts.block))
        .map(|(&n, &b)| u64::from(n) << 32 | u64::from(b))
        .collect();
    pairs.sort_unstable();
    pairs
}

/// What an implicit solve leaves for the next one on the same model: its last factorization,
/// whose symbolic analysis the next reuses while the stiffness keeps its pattern (the stages of
/// `adit run`, the samples of a displacement-controlled test).
#[derive(Default)]
pub struct Analysis {
    factor: Option<Factor>,
}

/// How an implicit solve ended.
pub struct Solved {
    pub solution: Solution,
    pub cost: Cost,
    /// Whether the model is left in a state explicit cycling can go on from: false when the
    /// monitor stopped the iterations (a non-finite value, a runaway displacement,
    /// interpenetration), true otherwise (converged, at the iteration limit, or stopped on a
    /// mechanism or a factorization before the state went wrong).
    pub sound: bool,
    /// At the iteration limit, the block that moved most in the last iteration, in words
    /// (`moving::fastest`).
    pub moving: Option<String>,
}

/// Solve `model` to static equilibrium as `spec` asks: the ratio below `spec.ratio`, the stage's
/// out-of-balance force released in `spec.load_steps` steps of at most `spec.max_iterations`
/// iterations each (a step that needs more is halved: `steps`), reporting each iteration to
/// `observer` as a history row. The stiffness is factorized again when a node touches a block anew
/// and after a cut.
pub fn solve(
    model: &mut Model,
    cycle: &mut Cycle,
    params: &CycleParams,
    spec: &SolveSpec,
    observer: &mut dyn Observer,
) -> Solved {
    solve_driven(
        model,
        cycle,
        params,
        spec,
        &[],
        &mut Analysis::default(),
        observer,
    )
}

/// [`solve`] under displacement control: each of `drive`'s nodes moved by its displacement (m)
/// along its fixed components at the start, with the first load step (`drive`; a step halved goes
/// back to before the move and makes it again). A drive that cannot act (a free component driven,
/// a body's node) fails the solve naming the node, before any factorization. The symbolic
/// analysis of `analysis`'s factorization, an earlier solve's, is reused while the stiffness has
/// its pattern, and the solve leaves its own last factorization there.
pub fn solve_driven(
    model: &mut Model,
    cycle: &mut Cycle,
    params: &CycleParams,
    spec: &SolveSpec,
    drive: &[Drive],
    analysis: &mut Analysis,
    observer: &mut dyn Observer,
) -> Solved {
    let (ratio, max_iterations) = (spec.ratio, spec.max_iterations);
    if let Some(reason) = drive::refused(model, drive) {
        let solution = Solution {
            status: Status::Failed(reason),
            cycles: 0,
            history: Vec::new(),
            final_ratio: f64::NAN,
        };
        return Solved {
            solution,
            cost: Cost::default(),
            sound: true,
            moving: None,
        };
    }
    // The zones take their laws' trial from the commit (`Cycle::displace`).
    let params = &CycleParams {
        trial: true,
        ..*params
    };
    let mut sound = true;
    let mut cost = Cost::default();
    let dofs = Dofs::of(&model.nodes, &model.bodies, &model.supports);
    cost.unknowns = dofs.count;
    let loose = support::unsupported_blocks(model);
    // A block nothing holds is named before any factorization: the stage fails as a mechanism.
    let mut factor = if loose.is_empty() {
        factorize(model, &dofs, &mut cost, observer, analysis.factor.take())
    } else {
        let names: Vec<String> = loose.iter().take(10).map(|b| b.to_string()).collect();
        Err(format!(
            "implicit: {} block(s) held by nothing, neither a fixed node nor a chain of contacts \
             to one (block {}{}): a mechanism the matrix cannot solve; fix them in `boundary`, or \
             solve explicitly{}",
            loose.len(),
            names.join(", "),
            if loose.len() > 10 { ", …" } else { "" },
            if model.far_field.is_some() {
                " (the far field, region.far_field, holds no translation, which costs the \
                 infinite medium nothing: fix a point or two, as `{ \"at\": …, \"fix\": … }`)"
            } else {
                ""
            }
        ))
    };
    let (t, before) = (Instant::now(), cost.assemble_s + cost.factorize_s);
    let mut history = Vec::new();
    let mut rhs = vec![0.0; dofs.count];
    let mut du = vec![[0.0; 2]; model.nodes.len()];
    let mut dq = vec![[0.0; crate::model::bodies::DOFS]; model.bodies.len()];
    // Iterations in all, and in the step being solved.
    let (mut iteration, mut in_step) = (0u64, 0u64);
    let mut movement = Movement::new(model);
    let window_start = max_iterations.checked_sub(moving::WINDOW);
    let mut detections = cycle.detections();
    // The (node, block) pairs in contact when the matrix was last factorized.
    let mut factored = touching(&model.contacts);
    let mut anderson = Anderson::new(dofs.count);
    let mut x = vec![0.0; dofs.count];
    // The least unbalanced-force ratio since Anderson mixing last restarted.
    let mut least_ratio = f64::INFINITY;
    let mut moving = None;
    let mut steps = LoadSteps::new(spec.load_steps, model, cycle, params);
    steps.apply(model);
    let mut committed = Committed::of(model, cycle);
    // Whether the zone forces are those of the state as it is (`displace` left them). A solve
    // that cannot start (no factor) leaves the driven nodes where they are.
    let mut zones_current = !drive.is_empty() && factor.is_ok();
    if zones_current {
        drive::apply(model, cycle, params, &committed, drive, &mut du);
    }
    let status = loop {
        let llt = match &mut factor {
            Ok(llt) => llt,
            Err(reason) => break Status::Failed(reason.clone()),
        };
        committed.trial_supports(&mut model.supports);
        committed.follow_detection(model, cycle.detections());
        cycle.balance(model, params, zones_current, Some(committed.joints()));
        let m = match cycle.monitor(model) {
            Ok(m) => m,
            Err(reason) => {
                sound = false;
                break Status::Failed(format!("iteration {iteration}: {reason}"));
            }
        };
        let row = HistoryRow {
            cycle: iteration,
            time: iteration as f64,
            ratio: m.ratio,
            kinetic: 0.0,
        };
        history.push(row);
        observer.monitored(&row);
        observer.sampled(model);
        if m.ratio <= ratio {
            if steps.is_last() {
                break Status::Converged;
            }
            steps.advance();
            steps.apply(model);
            committed = Committed::of(model, cycle);
            (in_step, least_ratio, movement) = (0, f64::INFINITY, Movement::new(model));
            anderson.reset();
            continue;
        }
        // An accelerated iterate whose out-of-balance force has grown past `RESTART_RISE` times
        // the least since the acceleration began restarts it from a plain step.
        least_ratio = least_ratio.min(m.ratio);
        if m.ratio > RESTART_RISE * least_ratio {
            anderson.reset();
            least_ratio = m.ratio;
        }
        if crate::interrupt::requested() {
            break Status::Interrupted;
        }
        if in_step == max_iterations {
            let steady = movement.steady(model);
            if window_start.is_some() && !steady.is_empty() {
                break Status::Failed(moving::describe(model, &steady, iteration));
            }
            // A step that does not converge is cut: back to the commit, half the step.
            if !steps.cut() {
                moving = moving::fastest(model, &movement, iteration);
                break Status::CycleLimit;
            }
            committed.restore(model, cycle);
            steps.apply(model);
            // Back before the drive while no step has committed it: it is made again.
            zones_current = steps.is_first() && !drive.is_empty();
            if zones_current {
                drive::apply(model, cycle, params, &committed, drive, &mut du);
            }
            factor = factorize(model, &dofs, &mut cost, observer, factor.ok());
            factored = touching(&model.contacts);
            (in_step, least_ratio, movement) = (0, f64::INFINITY, Movement::new(model));
            anderson.reset();
            continue;
        }
        dofs.gather(&model.nodes.force, &mut rhs);
        dofs.bodies.residual(&model.bodies, &mut rhs);
        dofs.supports.residual(&model.supports, &mut rhs);
        llt.solve_in_place(&mut rhs);
        // Blocks still moving are judged on the plain correction K⁻¹R, which the residual of a
        // block the joints cannot hold keeps up; the accelerated one mixes in earlier iterates.
        // The step's last is recorded in any case: at the iteration limit it names the block
        // that moves most (`moving::fastest`).
        if window_start.is_some() || in_step + 1 == max_iterations {
            dofs.scatter(&rhs, &mut du);
            dofs.bodies.expand(&rhs, &mut dq);
            bodies::node_motion(&model.bodies, &model.nodes, &dq, &mut du);
            movement.record(model, &du, Some(in_step) == window_start);
        }
        anderson.step(&x, &mut rhs);
        for (xi, d) in x.iter_mut().zip(&rhs) {
            *xi += d;
        }
        dofs.scatter(&rhs, &mut du);
        if !model.bodies.is_empty() {
            dofs.bodies.expand(&rhs, &mut dq);
            let Model {
                nodes,
                bodies,
                materials,
                ..
            } = model;
            cycle.body_displace(nodes, bodies, &materials.zone, &dq, &mut du);
        }
        committed.trial_zones(&mut model.zones);
        cycle.displace(model, &du, committed.trial(), params);
        zones_current = true;
        dofs.supports.displace(&mut model.supports, &rhs);
        iteration += 1;
        in_step += 1;
        if cycle.detections() != detections {
            detections = cycle.detections();
            // A node that touches a block it did not touch at the last factorization brings a
            // stiffness the matrix lacks (too soft, its corrections overshoot): factorized anew.
            // A contact that slid onto the next edge of the same block, or that is gone, leaves
            // the matrix near enough or too stiff, which the iterations converge on: the jointed
            // tunnel at once re-detects 182 contacts on other edges of the same blocks after its
            // 4th iteration, and solves in 88 iterations and one factorization (0.08 s) against
            // 82 and three (0.11 s) factorizing at every detection.
            let now = touching(&model.contacts);
            if now.iter().any(|k| factored.binary_search(k).is_err()) {
                factor = factorize(model, &dofs, &mut cost, observer, factor.ok());
                factored = now;
            }
            anderson.reset();
            least_ratio = f64::INFINITY;
        }
    };
    analysis.factor = factor.ok();
    cost.iterations = iteration;
    cost.cuts = u64::from(steps.cuts());
    let refactoring = cost.assemble_s + cost.factorize_s - before;
    cost.iterate_s = t.elapsed().as_secs_f64() - refactoring;
    let final_ratio = history.last().map_or(f64::NAN, |r| r.ratio);
    let solution = Solution {
        status,
        cycles: iteration,
        history,
        final_ratio,
    };
    Solved {
        solution,
        cost,
        sound,
        moving,
    }
}
