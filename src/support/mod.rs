//! Structural supports: fully grouted cables (rock bolts) and liners (beams bonded to an
//! excavation's wall). They carry their own degrees of freedom, stay inactive until a stage
//! installs them, and pass their forces on the rock through force slots that the motion stage
//! gathers per node (`Model::support_gather`, in a fixed order).

pub mod cable;
pub mod liner;
pub mod liner_capacity;

pub use cable::{BoltLoad, CableProps, Cables};
pub use liner::{LinerLoad, LinerProps, Liners};

/// What the supports carry: the figures a user looks at first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SupportLoads {
    /// Largest bolt axial force, N/m (tension positive; 0 without bolts).
    pub bolt_force: f64,
    /// Bolt segments that have yielded.
    pub bolts_yielded: usize,
    /// Largest liner thrust (compression), N/m, positive; 0 without liners.
    pub liner_thrust: f64,
    /// Largest liner bending moment magnitude, N·m/m.
    pub liner_moment: f64,
}

/// All supports of a model.
#[derive(Debug, Clone, Default)]
pub struct Supports {
    pub cables: Cables,
    pub liners: Liners,
}

/// A bolt group or a liner: its index among the scene's bolt groups or liners.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SupportId {
    Bolts(u32),
    Liner(u32),
}

impl Supports {
    pub fn is_empty(&self) -> bool {
        self.cables.nodes() == 0 && self.liners.nodes() == 0
    }

    /// Whether a bolt group or a liner holding any element is installed.
    pub fn any_installed(&self) -> bool {
        let c = &self.cables;
        let l = &self.liners;
        c.segment_group.iter().any(|&g| c.active[g as usize])
            || l.element_group.iter().any(|&g| l.active[g as usize])
    }

    /// The largest forces the bolts and liners carry now.
    pub fn loads(&self) -> SupportLoads {
        let (c, l) = (&self.cables, &self.liners);
        SupportLoads {
            bolt_force: c.axial.iter().fold(0.0f64, |a, &n| a.max(n)),
            bolts_yielded: c.plastic.iter().filter(|&&p| p != 0.0).count(),
            liner_thrust: -l.axial.iter().fold(0.0f64, |a, &n| a.min(n)),
            liner_moment: l
                .moment
                .iter()
                .flatten()
                .fold(0.0f64, |a, &n| a.max(n.abs())),
        }
    }

    /// Force slots: three per cable node (its host zone's corners), then one per liner link.
    pub fn slot_count(&self) -> usize {
        3 * self.cables.nodes() + self.liners.link_node.len()
    }

    /// The rock node each force slot acts on.
    pub fn slot_nodes(&self) -> Vec<u32> {
        let c = &self.cables;
        c.host
            .iter()
            .flatten()
            .chain(&self.liners.link_rock)
            .copied()
            .collect()
    }

    /// The bolt group or liner called `name`.
    pub fn id(&self, name: &str) -> Option<SupportId> {
        let index = |names: &[String]| names.iter().position(|n| n == name).map(|g| g as u32);
        index(&self.cables.names)
            .map(SupportId::Bolts)
            .or_else(|| index(&self.liners.names).map(SupportId::Liner))
    }

    /// Install the bolt group or liner `id` on the rock as it is now (`rock`: node displacements).
    pub fn install(&mut self, id: SupportId, rock: &[[f64; 2]]) {
        match id {
            SupportId::Bolts(g) => self.cables.install(g as usize, rock),
            SupportId::Liner(g) => self.liners.install(g as usize, rock),
        }
    }

    /// The supports stage: forces from the rock's displacements `rock` (into `slots`), then the
    /// central-difference update of the supports' own nodes. Returns their largest speed, m/s.
    pub fn cycle(&mut self, rock: &[[f64; 2]], slots: &mut [[f64; 2]], alpha: f64, dt: f64) -> f64 {
        let (cable_slots, liner_slots) = slots.split_at_mut(3 * self.cables.nodes());
        self.cables.forces(rock, cable_slots);
        self.liners.forces(rock, liner_slots);
        self.cables
            .motion(alpha, dt)
            .max(self.liners.motion(alpha, dt))
    }

    /// Set the supports' masses and add their stiffness to the rock nodes' bounds `rock`
    /// (before the rock's masses are derived from them). Static runs (`safety` given) scale
    /// masses to the Gershgorin bounds for Δt = 1, m = (1 + α) R/(4 s²): a chain of segments
    /// reaches its bound R (the zigzag mode), and local damping α can raise the force against
    /// the motion to (1 + α) F, so the bound needs that margin. Dynamic runs take real masses.
    /// Returns the supports' critical step with real masses, s (∞ without supports).
    pub fn set_masses(&mut self, rock: &mut [f64], safety: Option<f64>, alpha: f64) -> f64 {
        let rc = self.cables.stiffness(rock);
        let rl = self.liners.stiffness(rock);
        let (mc, ml) = (self.cables.real_masses(), self.liners.real_masses());
        let mut w2 = 0.0f64;
        for (r, m) in rc.iter().zip(&mc) {
            w2 = w2.max(r / m);
        }
        for (r, m) in rl.iter().zip(&ml) {
            w2 = w2.max(r[0] / m[0]).max(r[1] / m[1]);
        }
        match safety {
            Some(s) => {
                let scale = 4.0 * s * s / (1.0 + alpha);
                self.cables.mass = rc.iter().map(|r| r / scale).collect();
                self.liners.mass = rl.iter().map(|r| [r[0] / scale, r[1] / scale]).collect();
            }
            None => {
                self.cables.mass = mc;
                self.liners.mass = ml;
            }
        }
        if w2 > 0.0 {
            2.0 / w2.sqrt()
        } else {
            f64::INFINITY
        }
    }

    /// Largest unbalanced force (N/m; liner moments over the element length) and kinetic energy
    /// (J/m) of the active supports' nodes.
    pub fn monitor(&self) -> (f64, f64) {
        let (c, l) = (&self.cables, &self.liners);
        let (mut max_f, mut ke) = (0.0f64, 0.0);
        for n in (0..c.nodes()).filter(|&n| c.active[c.group[n] as usize]) {
            max_f = max_f.max(c.force[n].abs());
            ke += 0.5 * c.mass[n] * c.vel[n] * c.vel[n];
        }
        for n in (0..l.nodes()).filter(|&n| l.active[l.group[n] as usize]) {
            let (f, v, m) = (l.force[n], l.vel[n], l.mass[n]);
            max_f = max_f
                .max(f[0].hypot(f[1]))
                .max(f[2].abs() / l.node_length[n]);
            ke += 0.5 * (m[0] * (v[0] * v[0] + v[1] * v[1]) + m[1] * v[2] * v[2]);
        }
        (max_f, ke)
    }
}
