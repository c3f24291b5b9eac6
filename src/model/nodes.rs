//! Node state: reference position, displacement, velocity, unbalanced force, mass, fixity and
//! applied loads, one entry per node.

/// Bit flag: x velocity fixed.
pub const FIX_X: u8 = 1;
/// Bit flag: y velocity fixed.
pub const FIX_Y: u8 = 2;
/// Bit flag: the node belongs to a rigid or simple block and moves with it (`cycle::bodies`).
pub const BODY: u8 = 4;

/// Structure-of-arrays node state.
#[derive(Debug, Clone, Default)]
pub struct Nodes {
    /// Reference (initial) position, m.
    pub pos: Vec<[f64; 2]>,
    /// Displacement since the start of the run, m.
    pub disp: Vec<[f64; 2]>,
    /// Displacement at the last reset (a stage's `reset_displacements`), m: output shows
    /// `disp − origin`.
    pub origin: Vec<[f64; 2]>,
    /// Velocity, m/s.
    pub vel: Vec<[f64; 2]>,
    /// Unbalanced force of the last cycle (fixed components zeroed), N per metre of thickness.
    pub force: Vec<[f64; 2]>,
    /// Inertial mass used by the integrator (scaled in static mode), kg per metre of thickness.
    pub mass: Vec<f64>,
    /// Applied force: boundary tractions and gravity, N/m.
    pub applied: Vec<[f64; 2]>,
    /// Fixity bit flags (`FIX_X`, `FIX_Y`, `BODY`).
    pub fixed: Vec<u8>,
}

impl Nodes {
    /// Current positions x = X + u, m.
    pub fn current(&self) -> Vec<[f64; 2]> {
        self.pos
            .iter()
            .zip(&self.disp)
            .map(|(p, u)| [p[0] + u[0], p[1] + u[1]])
            .collect()
    }

    /// `n` nodes at the given positions, at rest, free and unloaded (masses zero until set).
    pub fn at(pos: Vec<[f64; 2]>) -> Nodes {
        let n = pos.len();
        Nodes {
            pos,
            disp: vec![[0.0; 2]; n],
            origin: vec![[0.0; 2]; n],
            vel: vec![[0.0; 2]; n],
            force: vec![[0.0; 2]; n],
            mass: vec![0.0; n],
            applied: vec![[0.0; 2]; n],
            fixed: vec![0; n],
        }
    }

    pub fn len(&self) -> usize {
        self.pos.len()
    }

    pub fn is_empty(&self) -> bool {
        self.pos.is_empty()
    }
}
