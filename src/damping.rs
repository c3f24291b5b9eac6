//! Local non-viscous damping (Cundall 1987; UDEC's and FLAC's `damp local`), one formula for every
//! integrator: nodes, rigid and simple bodies, cable and liner nodes.

/// The damped out-of-balance force (N/m, or N·m/m for a rotation) on a degree of freedom moving at
/// `v`: F_d = F − α |F| sign(v), with sign(0) = 0 so that a DOF at rest is not damped. α is the
/// local damping coefficient (0.8 for static relaxation); the damping force does no work against
/// a steady motion and removes the fraction α of the kinetic energy a mode gains per cycle.
#[inline]
pub fn local_damping(f: f64, v: f64, alpha: f64) -> f64 {
    f - alpha * f.abs() * v.signum() * (v != 0.0) as u8 as f64
}

#[cfg(test)]
mod tests {
    use super::local_damping;

    /// Against the motion the force grows by α|F|, with it it shrinks by α|F|; at rest it is whole.
    #[test]
    fn damping_opposes_the_velocity_and_spares_a_dof_at_rest() {
        assert_eq!(local_damping(10.0, 1.0, 0.8), 2.0);
        assert_eq!(local_damping(10.0, -1.0, 0.8), 18.0);
        assert_eq!(local_damping(-10.0, 1.0, 0.8), -18.0);
        assert_eq!(local_damping(-10.0, 0.0, 0.8), -10.0);
    }
}
