//! A block still sliding when an explicit static solve has converged. The unbalanced-force ratio
//! cannot see it: a block that has lost its clamping and slides on joints at their strength, or
//! falls freely, carries no unbalanced force, and local damping (which acts on force, not
//! velocity) leaves it the speed the release gave it, as in UDEC. Its displacement then depends
//! on when the run stopped, not on the problem. Such a run stays `converged` (its other answers
//! are equilibrium), and says which block moves (`StageSummary::moving`). A solve that stops at
//! its cycle limit names its fastest block as well (`fastest_at_limit`): a wedge falling into a
//! tunnel is the usual reason, and nothing else in the summary says where it is.

use crate::model::Model;

/// A node moving at its last speed for as many cycles as the solve took would add this fraction
/// of the model's largest displacement. Measured at convergence (ratio 1e-6) over 120 random
/// jointed, plastic and supported scenes and the bundled models: 1.9 for a simple block sliding
/// into a tunnel (0.8 m; fuzzed scene), 0.77 for a deformable block whose displacement went on
/// from 1.1e-2 to 2.0e-2 m with the ratio taken to 1e-8 (the implicit solve: 2.7e-3 m), 0.14 for
/// one still settling (1.69e-3, 1.72e-3 and 1.74e-3 m at 1e-6, 1e-7 and 1e-8), at most 1.5e-2
/// for the bundled models.
pub const DRIFT: f64 = 0.25;

/// Nor does a node warn that would move less than this fraction of the contact tolerance in as
/// many cycles again, which changes no contact: an in-situ stage, where nothing moves but
/// rounding (displacements of 1e-6 m), has speeds of the same order relative to them.
pub const NEGLIGIBLE: f64 = 0.01;

/// The fastest node of a model after a solve: the node, its speed (m/s), what it would move in
/// as many cycles again (m) and its displacement (m), and the largest displacement of any node
/// (m).
struct Fastest {
    node: usize,
    speed: f64,
    more: f64,
    moved: f64,
    largest: f64,
}

impl Fastest {
    /// Of `model` after `cycles` cycles of `dt` s; `None` without nodes.
    fn of(model: &Model, cycles: u64, dt: f64) -> Option<Fastest> {
        let nodes = &model.nodes;
        let length = |v: &[f64; 2]| v[0].hypot(v[1]);
        let largest = nodes.disp.iter().map(length).fold(0.0, f64::max);
        let (node, speed) =
            (nodes.vel.iter().map(length).enumerate()).max_by(|a, b| a.1.total_cmp(&b.1))?;
        Some(Fastest {
            node,
            speed,
            more: speed * cycles as f64 * dt,
            moved: length(&nodes.disp[node]),
            largest,
        })
    }

    /// "block B (node N at (x, y) m)".
    fn named(&self, model: &Model) -> String {
        let p = model.nodes.pos[self.node];
        format!(
            "block {} (node {} at ({:.3}, {:.3}) m)",
            model.blocks.block_of_node(self.node as u32),
            self.node,
            p[0],
            p[1]
        )
    }
}

/// "cycle" in a static solve (Δt = 1), else "time step".
fn per(dt: f64) -> &'static str {
    if dt == 1.0 { "cycle" } else { "time step" }
}

/// The fastest node of `model` when a solve of `cycles` cycles of `dt` s stopped at its cycle
/// limit, named with its block, speed and displacement, and whether it is still moving by
/// `DRIFT` (the run's own length again would add that share of the largest displacement: a
/// block finding no equilibrium) or settling; `None` when nothing moves.
pub fn fastest_at_limit(model: &Model, cycles: u64, dt: f64) -> Option<String> {
    let f = Fastest::of(model, cycles, dt)?;
    if !(f.speed > 0.0 && f.speed.is_finite()) {
        return None;
    }
    Some(format!(
        "at the cycle limit {} moves fastest, {:.3e} m per {}, having moved {:.3e} m{}",
        f.named(model),
        f.speed * dt,
        per(dt),
        f.moved,
        if f.more >= DRIFT * f.largest {
            ": it finds no equilibrium (a block sliding or falling: a mechanism), or is still \
             being released; more cycles (solve.max_cycles) tell which"
        } else {
            ", settling"
        }
    ))
}

/// The node of `model` still moving the most after a solve of `cycles` cycles of `dt` s, named
/// with its block, speed and displacement, when its speed times the solve's duration reaches
/// `DRIFT` of the largest displacement and `NEGLIGIBLE` of the contact tolerance; `None`
/// otherwise.
pub fn still_moving(model: &Model, cycles: u64, dt: f64) -> Option<String> {
    let f = Fastest::of(model, cycles, dt)?;
    if !(f.more >= DRIFT * f.largest && f.more >= NEGLIGIBLE * model.contact_tolerance) {
        return None;
    }
    Some(format!(
        "{} still moves {:.3e} m per {} at convergence, having moved {:.3e} m: a block sliding at \
         its joints' strength or falling freely carries no unbalanced force for the ratio to \
         see, and local damping leaves it its speed, so its displacement depends on when the \
         run stopped; release the load slowly (solve.ramp) or solve implicitly (solve.method; a \
         static solve leaves the block where it finds equilibrium, or names it)",
        f.named(model),
        f.speed * dt,
        per(dt),
        f.moved,
    ))
}
