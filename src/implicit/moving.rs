//! Blocks still moving when the implicit iterations run out. A block sliding or falling on its
//! joints keeps the matrix positive definite (its contacts carry the joints' initial stiffness),
//! but the joint law's forces in the residual never hold it: each iteration's plain correction
//! K⁻¹R moves it by about the same amount again. Over the last `WINDOW` iterations a converging
//! model's corrections shrink (by 4× at the slowest rate seen, 0.973 per iteration on a deep
//! plastic zone), while such a block's stay, and each is still a notable share of all the plain
//! corrections have moved it (accelerated iterations that stall near convergence keep their
//! corrections too, but tiny against the movement made: `STILL_MOVING`): it is named instead of
//! the stage ending at its iteration limit. The share is of the plain corrections' sum, not of the
//! block's displacement: Anderson mixing carries a sliding block far further than the plain
//! corrections do, and the monitor's runaway stop (half the model's size) can come first. Each
//! end of the window is a mean over `SPAN` iterations. A block that moves as a body (every node's
//! correction at least `AS_A_BODY` of its largest) is named before the blocks it pushes, which
//! deform as it moves and whose corrections stay as steady; failing that, a block no fixed node
//! holds is named before those held (the sliding-block test's slider, its joints' trial from the
//! commit, turns as well as slides in its last correction: its least node correction 0.36 of its
//! largest, while the base it pushes is held at its fixed nodes). (Slip that converges but very
//! slowly can still look the same: the message says so.)

use crate::model::{BODY, FIX_X, FIX_Y, Model};

/// Iterations over which a moving block's correction must not have shrunk.
pub const WINDOW: u64 = 50;

/// A block whose correction is still this fraction of what it was `WINDOW` iterations earlier
/// moves steadily.
pub const STEADY: f64 = 0.8;

/// Blocks whose correction is under this fraction of the largest block's are left out (their
/// movement is the model's elastic response to the moving ones).
const NOTABLE: f64 = 1e-2;

/// A block moves steadily only while its correction is still this share of the sum of all its
/// plain corrections since the solve began. A sliding block's correction stays a constant step,
/// about 1/k of the sum after k iterations; a block of a model that converges slowly has made
/// nearly all its movement and creeps on by far less
/// (`models/jointed_tunnel_mixed.json` at its 200th iteration: 7.7e-8 m an iteration against
/// about a millimetre, 1e-4).
const STILL_MOVING: f64 = 1e-3;

/// A block's correction is a body's motion when its smallest node correction is at least this
/// share of its largest (a translation, or a rotation about a point well outside it); a block
/// held at a fixed node, or pushed by a sliding neighbour, deforms instead (the sliding-block
/// test's base block: 0 at its fixed nodes).
const AS_A_BODY: f64 = 0.5;

/// Iterations over which a block's corrections are averaged at each end of the window: a
/// sliding block's correction swings by up to 5× from one iteration to the next (the sliding-block
/// test's slider, 1e-6 to 5e-6 m), so one iteration against one other named the base it pushes
/// or the slider by chance of the iteration limit.
pub const SPAN: usize = 10;

/// Each block's mean largest node correction, m, over the first `SPAN` iterations of the window
/// and its last `SPAN` largest corrections (a ring), its largest and smallest node correction of
/// the last iteration, and the sum of its largest corrections since the solve began.
pub struct Movement {
    then: Vec<f64>,
    /// Iterations recorded since the window's start (`None` before it).
    in_window: Option<usize>,
    recent: Vec<[f64; SPAN]>,
    recorded: usize,
    now: Vec<f64>,
    least: Vec<f64>,
    sum: Vec<f64>,
}

impl Movement {
    pub fn new(model: &Model) -> Movement {
        let blocks = model.blocks.len();
        Movement {
            then: vec![0.0; blocks],
            in_window: None,
            recent: vec![[0.0; SPAN]; blocks],
            recorded: 0,
            now: vec![0.0; blocks],
            least: vec![0.0; blocks],
            sum: vec![0.0; blocks],
        }
    }

    /// Record an iteration's plain corrections `du` (m per node); `first` marks the window's start.
    pub fn record(&mut self, model: &Model, du: &[[f64; 2]], first: bool) {
        if first {
            self.then.fill(0.0);
            self.in_window = Some(0);
        }
        let opening = self.in_window.filter(|&k| k < SPAN);
        let starts = &model.blocks.node_start;
        for b in 0..self.now.len() {
            let nodes = starts[b] as usize..starts[b + 1] as usize;
            let (least, most) = du[nodes]
                .iter()
                .map(|d| d[0].hypot(d[1]))
                .fold((f64::INFINITY, 0.0f64), |(l, m), v| (l.min(v), m.max(v)));
            self.now[b] = most;
            self.least[b] = if least.is_finite() { least } else { 0.0 };
            self.sum[b] += most;
            self.recent[b][self.recorded % SPAN] = most;
            if opening.is_some() {
                self.then[b] += most;
            }
        }
        self.recorded += 1;
        if let Some(k) = self.in_window.as_mut() {
            *k += 1;
        }
    }

    /// Block b's mean correction over the window's first `SPAN` iterations (or as many as it has
    /// had) and over the last `SPAN` recorded, m.
    fn means(&self, b: usize) -> (f64, f64) {
        let opened = self.in_window.unwrap_or(0).clamp(1, SPAN) as f64;
        let last = self.recorded.clamp(1, SPAN);
        let recent = self.recent[b][..last].iter().sum::<f64>() / last as f64;
        (self.then[b] / opened, recent)
    }

    /// The blocks moving steadily (their mean correction over the last `SPAN` iterations at least
    /// `STEADY` of that over the window's first), (block, that mean correction in m), largest first:
    /// those moving as bodies if any is, else those no fixed node holds if any, else all.
    pub fn steady(&self, model: &Model) -> Vec<(usize, f64)> {
        let means: Vec<(f64, f64)> = (0..self.now.len()).map(|b| self.means(b)).collect();
        let largest = means.iter().map(|m| m.1).fold(0.0, f64::max);
        let mut out: Vec<(usize, f64)> = (0..self.now.len())
            .filter(|&b| !model.blocks.is_removed(b))
            .filter(|&b| {
                let (then, now) = means[b];
                now > NOTABLE * largest && now >= STEADY * then && now >= STILL_MOVING * self.sum[b]
            })
            .map(|b| (b, means[b].1))
            .collect();
        if out.iter().any(|&(b, _)| self.is_body(b)) {
            out.retain(|&(b, _)| self.is_body(b));
        } else if out.iter().any(|&(b, _)| !held(model, b)) {
            out.retain(|&(b, _)| !held(model, b));
        }
        out.sort_by(|a, b| b.1.total_cmp(&a.1).then(a.0.cmp(&b.0)));
        out
    }

    /// Whether block `b`'s last correction moves it as a body (`AS_A_BODY`).
    fn is_body(&self, b: usize) -> bool {
        self.least[b] >= AS_A_BODY * self.now[b]
    }
}

/// The block whose last recorded plain correction was the largest, with that correction (m), at
/// the iteration limit of a solve that found no steady mover: named as where to look; `None`
/// before any correction was recorded.
pub fn fastest(model: &Model, movement: &Movement, iterations: u64) -> Option<String> {
    let (b, moved) = (0..movement.now.len())
        .filter(|&b| !model.blocks.is_removed(b))
        .map(|b| (b, movement.now[b]))
        .filter(|&(_, d)| d > 0.0)
        .max_by(|x, y| x.1.total_cmp(&y.1).then(y.0.cmp(&x.0)))?;
    let [x, y] = model.blocks.node_mean(b, &model.nodes.pos);
    Some(format!(
        "at the iteration limit ({iterations} iterations) block {b} near ({x:.3}, {y:.3}) m moves \
         most, {moved:.3e} m in the last iteration (its plain correction K⁻¹R): slip or flow \
         converging too slowly, or a block the joints do not hold; solve this stage explicitly \
         to see it move"
    ))
}

/// Whether block `b` has a fixed node (in either component; not a body's node, which its body
/// holds).
fn held(model: &Model, b: usize) -> bool {
    let starts = &model.blocks.node_start;
    (model.nodes.fixed[starts[b] as usize..starts[b + 1] as usize].iter())
        .any(|&f| f & (FIX_X | FIX_Y) != 0 && f & BODY == 0)
}

/// The reason a stage stops on `steady` blocks after `iterations`.
pub fn describe(model: &Model, steady: &[(usize, f64)], iterations: u64) -> String {
    let named: Vec<String> = steady
        .iter()
        .take(5)
        .map(|&(b, moved)| {
            let [x, y] = model.blocks.node_mean(b, &model.nodes.pos);
            format!("block {b} near ({x:.3}, {y:.3}) m moves {moved:.2e} m per iteration")
        })
        .collect();
    format!(
        "implicit: after {iterations} iterations {} block(s) still move by about as much per \
         iteration as {WINDOW} iterations before ({}{}): sliding or falling on their joints, or \
         flowing plastically (a mechanism, or slip or flow too slow for the implicit solve to \
         follow); solve this stage explicitly",
        steady.len(),
        named.join("; "),
        if steady.len() > 5 { "; …" } else { "" }
    )
}
