//! The capacity of a liner's section against its thrust, moment and shear (Carranza-Torres &
//! Diederichs 2009, "Mechanical analysis of circular liners with particular reference to
//! composite supports", *Tunnelling and Underground Space Technology* 24, §6: the support
//! capacity diagrams RS2 draws).
//!
//! A rectangular section of one set (area A, second moment I, so depth t = √(12 I / A)) of a
//! material with uniaxial compressive strength σc and tensile strength σt, carrying the thrust T
//! (compression positive), the moment M (positive when its excavation face is in tension) and the
//! shear V, all per set:
//!
//!   fibre stresses (compression positive)   σ_exc = T/A − M t/(2I),   σ_rock = T/A + M t/(2I),
//!   at the neutral axis                     σ0 = T/A,   τ = 3V/(2A)  (a rectangle's largest shear),
//!                                           σ1,3 = σ0/2 ± √((σ0/2)² + τ²).
//!
//! The section holds while every stress lies within [−σt, σc]; its factor of safety is the
//! number FS by which both strengths can be divided before one does not:
//!
//!   FS_stress(σ) = σc/σ for σ > 0, σt/(−σ) for σ < 0 (∞ at 0),
//!   FS_bending = min(FS_stress(σ_exc), FS_stress(σ_rock)),
//!   FS_shear   = min(FS_stress(σ1), FS_stress(σ3)),   FS = min(FS_bending, FS_shear).
//!
//! Every stress is linear (the principal stresses homogeneous) in the forces, so FS is also the
//! factor by which the forces can grow before they meet the envelope of FS = 1, and the envelope
//! of FS = f is that of strengths σc/f, σt/f: in the (M, T) plane the diamond through
//! (0, σc A/f), (±(σc + σt) I/(t f), (σc − σt) A/(2f)) and (0, −σt A/f); in the (V, T) plane
//! V = (2A/3) √(min((σc/f)² − (σc/f) σ0, (σt/f)² + (σt/f) σ0)) for σ0 = T/A in [−σt/f, σc/f].

/// The section of one set of a liner and its material's strengths.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Section {
    /// Area A, m², and second moment I, m⁴, of one set.
    pub area: f64,
    pub inertia: f64,
    /// Uniaxial compressive strength σc, Pa (positive).
    pub compressive: f64,
    /// Tensile strength σt, Pa (positive).
    pub tensile: f64,
}

/// The forces a liner element carries at one end, per set.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SectionForces {
    /// Thrust T, N (compression positive).
    pub thrust: f64,
    /// Moment M, N·m (positive when the excavation face is in tension).
    pub moment: f64,
    /// Shear V, N.
    pub shear: f64,
}

/// A section's factors of safety under its forces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Safety {
    /// Against thrust with moment (the extreme fibres).
    pub bending: f64,
    /// Against thrust with shear (the neutral axis).
    pub shear: f64,
}

impl Safety {
    /// The smaller of the two.
    pub fn factor(&self) -> f64 {
        self.bending.min(self.shear)
    }
}

impl Section {
    /// Depth of the rectangle, t = √(12 I / A), m.
    pub fn depth(&self) -> f64 {
        (12.0 * self.inertia / self.area).sqrt()
    }

    /// FS_stress(σ): the strength on σ's side over σ (compression positive; ∞ at 0).
    fn stress_factor(&self, sigma: f64) -> f64 {
        if sigma > 0.0 {
            self.compressive / sigma
        } else if sigma < 0.0 {
            self.tensile / -sigma
        } else {
            f64::INFINITY
        }
    }

    /// The fibre stresses [σ_exc, σ_rock], Pa (compression positive).
    pub fn fibre_stresses(&self, f: &SectionForces) -> [f64; 2] {
        let axial = f.thrust / self.area;
        let bending = f.moment * 0.5 * self.depth() / self.inertia;
        [axial - bending, axial + bending]
    }

    /// The principal stresses [σ1, σ3] at the neutral axis, Pa (compression positive).
    pub fn neutral_axis_stresses(&self, f: &SectionForces) -> [f64; 2] {
        let half = 0.5 * f.thrust / self.area;
        let tau = 1.5 * f.shear / self.area;
        let radius = half.hypot(tau);
        [half + radius, half - radius]
    }

    /// The section's factors of safety under `f`.
    pub fn safety(&self, f: &SectionForces) -> Safety {
        let least = |s: [f64; 2]| self.stress_factor(s[0]).min(self.stress_factor(s[1]));
        Safety {
            bending: least(self.fibre_stresses(f)),
            shear: least(self.neutral_axis_stresses(f)),
        }
    }

    /// The thrust–moment envelope of factor of safety `fs`, closed: points (M, T), N·m and N.
    pub fn moment_envelope(&self, fs: f64) -> [(f64, f64); 5] {
        let (c, t) = (self.compressive / fs, self.tensile / fs);
        let moment = (c + t) * self.inertia / self.depth();
        let thrust = 0.5 * (c - t) * self.area;
        [
            (0.0, c * self.area),
            (moment, thrust),
            (0.0, -t * self.area),
            (-moment, thrust),
            (0.0, c * self.area),
        ]
    }

    /// The thrust–shear envelope of factor of safety `fs` at `n` + 1 thrusts from the tensile to
    /// the compressive limit, both signs of shear, closed: points (V, T), N.
    pub fn shear_envelope(&self, fs: f64, n: usize) -> Vec<(f64, f64)> {
        let (c, t) = (self.compressive / fs, self.tensile / fs);
        let half: Vec<(f64, f64)> = (0..=n)
            .map(|k| {
                let s0 = -t + (c + t) * k as f64 / n as f64;
                let tau2 = (c * c - c * s0).min(t * t + t * s0).max(0.0);
                (2.0 * self.area / 3.0 * tau2.sqrt(), s0 * self.area)
            })
            .collect();
        let back = half.iter().rev().map(|&(v, thrust)| (-v, thrust));
        half.iter().copied().chain(back).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 0.3 m of shotcrete per metre: σc 40 MPa, σt 4 MPa.
    fn shotcrete() -> Section {
        let t: f64 = 0.3;
        Section {
            area: t,
            inertia: t.powi(3) / 12.0,
            compressive: 40e6,
            tensile: 4e6,
        }
    }

    fn forces(thrust: f64, moment: f64, shear: f64) -> SectionForces {
        SectionForces {
            thrust,
            moment,
            shear,
        }
    }

    #[test]
    fn pure_thrust_and_pure_tension_meet_the_strengths() {
        let s = shotcrete();
        assert!((s.depth() - 0.3).abs() < 1e-15);
        let squeeze = s.safety(&forces(6e6, 0.0, 0.0));
        assert!((squeeze.bending - 2.0).abs() < 1e-12, "{squeeze:?}");
        assert!((squeeze.shear - 2.0).abs() < 1e-12, "{squeeze:?}");
        let pull = s.safety(&forces(-0.6e6, 0.0, 0.0));
        assert!((pull.factor() - 2.0).abs() < 1e-12, "{pull:?}");
    }

    #[test]
    fn every_point_of_an_envelope_has_its_factor_of_safety() {
        let s = shotcrete();
        for fs in [0.7, 1.0, 1.5, 3.0] {
            for w in s.moment_envelope(fs).windows(2) {
                for k in 0..=8 {
                    let a = k as f64 / 8.0;
                    let (m, t) = (
                        w[0].0 + a * (w[1].0 - w[0].0),
                        w[0].1 + a * (w[1].1 - w[0].1),
                    );
                    let got = s.safety(&forces(t, m, 0.0)).bending;
                    assert!((got - fs).abs() < 1e-9 * fs, "{fs} at ({m}, {t}): {got}");
                }
            }
            for (v, t) in s.shear_envelope(fs, 40) {
                if v.abs() < 1e-6 * s.area * s.tensile {
                    continue;
                }
                let got = s.safety(&forces(t, 0.0, v)).shear;
                assert!((got - fs).abs() < 1e-9 * fs, "{fs} at ({v}, {t}): {got}");
            }
        }
    }

    #[test]
    fn a_moment_tensions_the_face_it_bends_outward() {
        let s = shotcrete();
        // M > 0: the excavation face in tension.
        let [exc, rock] = s.fibre_stresses(&forces(0.0, 1e5, 0.0));
        assert!(exc < 0.0 && rock > 0.0);
        assert!((rock - 1e5 * 6.0 / 0.09).abs() < 1e-6);
    }
}
