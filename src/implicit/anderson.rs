//! Anderson acceleration of the initial-stiffness iteration (Anderson 1965; Walker & Ni, "Anderson
//! acceleration for fixed-point iterations", SIAM J. Numer. Anal. 49, 2011, Alg. AA with the
//! least-squares problem in its unconstrained form). The iteration is the fixed-point map
//! G(x) = x + K₀⁻¹ R(x) over the free unknowns moved since the stage began; with f_k = G(x_k) − x_k
//! and the differences ΔF, ΔG of the last m iterates, the next iterate is
//! x_{k+1} = G(x_k) − ΔG γ with γ = argmin ‖f_k − ΔF γ‖₂ (normal equations, m ≤ `DEPTH`).
//! Where zones yield or joints slip, the initial stiffness K₀ is too stiff and plain iterations
//! shrink the error by a constant factor each; the history supplies the missing softness (a
//! multisecant update of K₀⁻¹). A simple block's law integrates along the iterations' path and
//! contacts detected anew commit their joints where they are, so R can depend on the path as
//! well as on x: the solve restarts the history when the out-of-balance force grows past
//! `RESTART_RISE` times the least since the last restart, and at each new factorization.

use nalgebra::{DMatrix, DVector};

/// a · b.
fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(p, q)| p * q).sum::<f64>()
}

/// Iterates kept (m). Measured over the implicit report's cases (31 solves: Salençon's four rocks
/// at once and slowly, the ground reaction curve, Lamé at ν = 0.499, the pull-out, the softening
/// specimen, the direct shear, the bundled tunnels, four realizations of the jointed tunnel's
/// sets it was not tuned to, the block modes): 12 491 iterations in all at m = 5, 10 843 at 8,
/// 10 551 at 10 and 10 463 at 12; the seconds 7.3, 6.8, 6.8 and 7.0, as each history column
/// costs a dot product and a combination per iteration. From m = 5 to 8 the median closures,
/// plastic radii and errors moved by at most 5e-4 of themselves (most by under 5e-5), the
/// largest closure of the jointed tunnel in rigid blocks by 9e-3 (a loose wedge stops where the
/// iterations leave it, `validation/src/modes.rs`).
pub const DEPTH: usize = 8;

/// The history of the last iterates, preallocated per solve.
pub struct Anderson {
    prev_x: Vec<f64>,
    prev_f: Vec<f64>,
    /// ΔF and ΔG columns, a ring of `DEPTH`.
    df: Vec<Vec<f64>>,
    dg: Vec<Vec<f64>>,
    /// The Gram matrix of the ΔF columns, by ring slot: gram[i][j] = ΔF_i · ΔF_j, updated for
    /// the one new column each step (m dot products, not m²).
    gram: [[f64; DEPTH]; DEPTH],
    /// Columns held and the next to overwrite.
    held: usize,
    next: usize,
    started: bool,
}

impl Anderson {
    pub fn new(unknowns: usize) -> Anderson {
        Anderson {
            prev_x: vec![0.0; unknowns],
            prev_f: vec![0.0; unknowns],
            df: vec![vec![0.0; unknowns]; DEPTH],
            dg: vec![vec![0.0; unknowns]; DEPTH],
            gram: [[0.0; DEPTH]; DEPTH],
            held: 0,
            next: 0,
            started: false,
        }
    }

    /// Forget the history (the map changed: a new factorization or new contacts).
    pub fn reset(&mut self) {
        self.held = 0;
        self.next = 0;
        self.started = false;
    }

    /// Given the iterate `x` and `f` = G(x) − x, leave in `f` the step x_{k+1} − x_k.
    pub fn step(&mut self, x: &[f64], f: &mut [f64]) {
        if self.started {
            let (df, dg) = (&mut self.df[self.next], &mut self.dg[self.next]);
            for i in 0..x.len() {
                df[i] = f[i] - self.prev_f[i];
                dg[i] = (x[i] - self.prev_x[i]) + df[i];
            }
            let new = self.next;
            self.next = (self.next + 1) % DEPTH;
            self.held = (self.held + 1).min(DEPTH);
            for j in 0..self.held {
                let g = dot(&self.df[new], &self.df[j]);
                self.gram[new][j] = g;
                self.gram[j][new] = g;
            }
        }
        self.prev_x.copy_from_slice(x);
        self.prev_f.copy_from_slice(f);
        self.started = true;
        let m = self.held;
        if m == 0 {
            return;
        }
        let gram = DMatrix::from_fn(m, m, |i, j| self.gram[i][j]);
        let rhs = DVector::from_fn(m, |i, _| dot(&self.df[i], f));
        // A tiny Tikhonov term keeps nearly dependent differences solvable.
        let scale = (0..m).map(|i| gram[(i, i)]).fold(0.0, f64::max);
        let regular = gram + DMatrix::identity(m, m) * (1e-12 * scale).max(f64::MIN_POSITIVE);
        let Some(gamma) = regular.cholesky().map(|c| c.solve(&rhs)) else {
            self.reset();
            return;
        };
        for (j, g) in gamma.iter().enumerate() {
            for (fi, dgi) in f.iter_mut().zip(&self.dg[j]) {
                *fi -= g * dgi;
            }
        }
    }
}
