//! Barton–Bandis joint (Bandis, Lumsden & Barton 1983, "Fundamentals of rock joint deformation",
//! IJRMMS 20(6); Barton, Bandis & Bakhtar 1985, "Strength, deformation and conductivity coupling of
//! rock joints", IJRMMS 22(3); UDEC's BB model), state carried per contact.
//!
//! **Normal**: hyperbolic closure. A joint closed by Δv (m) under the effective compression σ′ = −σn
//! (Pa) carries
//!
//!   σ′ = Kni Δv / (1 − Δv/Vm),   so   Δv = σ′ Vm / (Kni Vm + σ′),   Kn = Kni (1 + σ′/(Kni Vm))²,
//!
//! Kni (Pa/m) the initial stiffness and Vm (m) the maximum closure. The hyperbola holds until its
//! tangent reaches Kmax, by default at the joint wall's strength σ′ = JCS, where the asperities crush
//! and the criterion below stops holding (Kmax = Kni (1 + JCS/(Kni Vm))²); beyond, the joint stiffens
//! no more (linear with Kmax, the stiffness the time step is derived from). A lower Kmax, given,
//! ends the hyperbola at σ′* = Kni Vm (√(Kmax/Kni) − 1): cheaper cycles, the closure linear above σ′*. A joint present at the start sits at the
//! closure of its in-situ stress; opening past zero closure it carries nothing (no tension).
//!
//! **Shear**: elastic with ks, capped by the mobilized strength
//!
//!   τ ≤ σ′ tan(φr + JRCmob log10(JCS/σ′)),   the angle at most 70° (Barton 1976),
//!
//! where JRCmob follows Barton's dimensionless mobilization model (Barton 1982; Barton et al. 1985,
//! Table) along the shear path δ (the accumulated |Δus|, m) against the peak displacement
//! δp = (L/500) (JRC/L)^0.33 (Barton & Bandis 1982, L the joint's length in m):
//!
//! | δ/δp | 0 | 0.3 | 0.6 | 1 | 2 | 4 | 10 | 100 |
//! |---|---|---|---|---|---|---|---|---|
//! | JRCmob/JRC | −φr/i | 0 | 0.75 | 1 | 0.85 | 0.70 | 0.50 | 0 |
//!
//! (i = JRC log10(JCS/σ′): the mobilized angle rises from 0 to φr over the first 0.3 δp), linear
//! between the points; the peak, at δp, is τp = σ′ tan(φr + JRC log10(JCS/σ′)). Slipping, the joint
//! dilates by tan dmob per unit of plastic slip, dmob = JRCmob log10(JCS/σ′)/M (Barton & Choubey
//! 1977; M = 2 by default), and only once the roughness is mobilized (JRCmob > 0). The return
//! ends exactly on the limit at the normal stress the dilation brings (as `CoulombSlip::trial`),
//! so one step serves both the cycle's small increments and the implicit path's whole ones.
//!
//! **Scale** (Barton & Bandis 1982), as an option: a laboratory JRC0, JCS0 measured on a sample
//! of length L0 become at the block size Ln
//!
//!   JRCn = JRC0 (Ln/L0)^(−0.02 JRC0),   JCSn = JCS0 (Ln/L0)^(−0.03 JRC0),
//!
//! and δp takes Ln.
//!
//! **Strength reduction** by F (the factor of safety's search): the mobilized strength at every
//! shear path and compression divided by F, τ/F = σ′ tan φmob / F, i.e. tan φmob,F = tan φmob / F
//! (`law::reduced_friction`, Dawson, Roth & Drescher 1999's tan φ/F), the mobilization along the
//! path and the hyperbola unchanged, the dilation angle at most φmob,F (as a reduced Coulomb
//! joint's).

use super::{JointLaw, JointState, OPEN, SLIPPING};
use crate::law::reduced_friction;

/// Barton's mobilization model: (δ/δp, JRCmob/JRC) from 0.3 δp on (below it the mobilized angle
/// rises linearly from 0 to φr).
const MOBILIZATION: [(f64, f64); 7] = [
    (0.3, 0.0),
    (0.6, 0.75),
    (1.0, 1.0),
    (2.0, 0.85),
    (4.0, 0.70),
    (10.0, 0.50),
    (100.0, 0.0),
];

/// The largest mobilized friction angle φr + JRCmob log10(JCS/σ′), degrees (Barton 1976).
const MAX_ANGLE_DEG: f64 = 70.0;

/// Barton–Bandis joint material, its roughness and wall strength at the joint's scale.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BartonBandis {
    /// Initial normal stiffness Kni, Pa/m.
    pub initial_normal_stiffness: f64,
    /// Maximum closure Vm, m.
    pub max_closure: f64,
    /// The largest normal stiffness Kmax, Pa/m: the hyperbola's tangent where it ends.
    pub max_normal_stiffness: f64,
    /// Shear stiffness ks, Pa/m.
    pub shear_stiffness: f64,
    /// Residual friction angle φr, degrees.
    pub residual_friction_deg: f64,
    /// Joint roughness coefficient JRC at the joint's scale.
    pub jrc: f64,
    /// Joint wall compressive strength JCS at the joint's scale, Pa.
    pub jcs: f64,
    /// Shear displacement of the peak δp, m.
    pub peak_displacement: f64,
    /// The divisor M of the mobilized dilation angle dmob = JRCmob log10(JCS/σ′)/M.
    pub dilation_divisor: f64,
    /// The factor F its strength is divided by (1 but in the factor of safety's trials).
    pub strength_factor: f64,
}

/// Roughness as measured: JRC0 and JCS0 (Pa) on a sample of length L0 (m), and the block size Ln
/// (m) to scale them to, if any.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Roughness {
    pub jrc: f64,
    pub jcs: f64,
    pub sample_length: f64,
    pub block_size: Option<f64>,
}

impl Roughness {
    /// JRCn, JCSn (Pa) and the length (m) the peak displacement takes: scaled to the block size
    /// if one is given (Barton & Bandis 1982), else the sample's own.
    pub fn at_scale(&self) -> (f64, f64, f64) {
        match self.block_size {
            None => (self.jrc, self.jcs, self.sample_length),
            Some(ln) => {
                let ratio = ln / self.sample_length;
                (
                    self.jrc * ratio.powf(-0.02 * self.jrc),
                    self.jcs * ratio.powf(-0.03 * self.jrc),
                    ln,
                )
            }
        }
    }
}

/// The peak shear displacement δp = (L/500) (JRC/L)^0.33, m (Barton & Bandis 1982; L in m).
pub fn peak_displacement(jrc: f64, length: f64) -> f64 {
    length / 500.0 * (jrc / length).powf(0.33)
}

/// JRCmob/JRC at δ/δp ≥ 0.3 (`MOBILIZATION`, linear between its points, 0 beyond the last).
fn mobilized_fraction(r: f64) -> f64 {
    let k = MOBILIZATION.partition_point(|&(x, _)| x <= r);
    match k {
        0 => 0.0,
        k if k == MOBILIZATION.len() => 0.0,
        k => {
            let ((x0, y0), (x1, y1)) = (MOBILIZATION[k - 1], MOBILIZATION[k]);
            y0 + (y1 - y0) * (r - x0) / (x1 - x0)
        }
    }
}

/// What the roughness mobilizes at a shear path and an effective compression.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mobilized {
    /// JRCmob (0 below 0.3 δp, where the table's −φr/i (1 − δ/0.3δp) mobilizes friction, not
    /// roughness).
    pub jrc: f64,
    /// The friction angle φr + JRCmob log10(JCS/σ′) (at most 70°), rad.
    pub friction: f64,
    /// The dilation angle dmob (0 until JRCmob > 0), rad.
    pub dilation: f64,
}

impl BartonBandis {
    /// The law from its normal hyperbola (Kni Pa/m, Vm m), shear stiffness (Pa/m), roughness,
    /// residual friction (degrees) and dilation divisor M; Kmax the tangent at JCS
    /// (`with_max_normal_stiffness` lowers it).
    pub fn new(
        (initial_normal_stiffness, max_closure): (f64, f64),
        shear_stiffness: f64,
        roughness: Roughness,
        residual_friction_deg: f64,
        dilation_divisor: f64,
    ) -> Self {
        let (jrc, jcs, length) = roughness.at_scale();
        BartonBandis {
            initial_normal_stiffness,
            max_closure,
            max_normal_stiffness: initial_normal_stiffness
                * (1.0 + jcs / (initial_normal_stiffness * max_closure)).powi(2),
            shear_stiffness,
            residual_friction_deg,
            jrc,
            jcs,
            peak_displacement: peak_displacement(jrc, length),
            dilation_divisor,
            strength_factor: 1.0,
        }
    }

    /// Kni Vm, Pa: the compression at which the hyperbola has closed half its maximum closure.
    fn half_closure_stress(&self) -> f64 {
        self.initial_normal_stiffness * self.max_closure
    }

    /// The law with Kmax (Pa/m, at least Kni) lowered or raised from the tangent at JCS.
    pub fn with_max_normal_stiffness(self, max_normal_stiffness: f64) -> Self {
        BartonBandis {
            max_normal_stiffness,
            ..self
        }
    }

    /// Where the hyperbola ends: its closure Vm (1 − √(Kni/Kmax)) (m) and compression
    /// Kni Vm (√(Kmax/Kni) − 1) (Pa), where its tangent reaches Kmax.
    fn hyperbola_end(&self) -> (f64, f64) {
        let root = (self.max_normal_stiffness / self.initial_normal_stiffness).sqrt();
        (
            self.max_closure * (1.0 - 1.0 / root),
            self.half_closure_stress() * (root - 1.0),
        )
    }

    /// The effective compression σ′ (Pa) at closure Δv ≥ 0 (m): the hyperbola to its end, linear
    /// with Kmax beyond.
    pub fn compression(&self, closure: f64) -> f64 {
        let (end, at_end) = self.hyperbola_end();
        if closure <= end {
            self.initial_normal_stiffness * closure / (1.0 - closure / self.max_closure)
        } else {
            at_end + self.max_normal_stiffness * (closure - end)
        }
    }

    /// The closure Δv (m) at the effective compression σ′ ≥ 0 (Pa): the inverse of `compression`.
    pub fn closure(&self, compression: f64) -> f64 {
        let (end, at_end) = self.hyperbola_end();
        if compression <= at_end {
            compression * self.max_closure / (self.half_closure_stress() + compression)
        } else {
            end + (compression - at_end) / self.max_normal_stiffness
        }
    }

    /// The mobilized JRC, friction and dilation at the shear path δ (m) under σ′ (Pa).
    pub fn mobilized(&self, path: f64, compression: f64) -> Mobilized {
        let phi_r = self.residual_friction_deg;
        // log10(JCS/σ′), not below 0 (the criterion holds for σ′ ≤ JCS); at σ′ → 0 the angle is
        // bounded by the 70° cap instead.
        let log = if compression > 0.0 {
            (self.jcs / compression).log10().max(0.0)
        } else {
            f64::INFINITY
        };
        let r = path / self.peak_displacement;
        let (jrc, roughness_deg) = if r < 0.3 {
            // The angle rises from 0 to φr: JRCmob log = −φr (1 − r/0.3). JRCmob itself, −φr/i at
            // δ = 0, grows without bound as σ′ nears JCS; the friction, not the roughness, is
            // being mobilized, and JRCmob is reported 0.
            (0.0, -phi_r * (1.0 - r / 0.3))
        } else {
            let jrc = self.jrc * mobilized_fraction(r);
            let angle = if jrc == 0.0 { 0.0 } else { jrc * log };
            (jrc, angle)
        };
        let roughness_deg = roughness_deg.min(MAX_ANGLE_DEG - phi_r);
        let friction = (phi_r + roughness_deg).to_radians();
        let dilation = (roughness_deg.max(0.0) / self.dilation_divisor).to_radians();
        if self.strength_factor == 1.0 {
            return Mobilized {
                jrc,
                friction,
                dilation,
            };
        }
        let friction = reduced_friction(friction, self.strength_factor);
        Mobilized {
            jrc,
            friction,
            dilation: dilation.min(friction),
        }
    }

    /// The peak shear strength τp = σ′ tan(φr + JRC log10(JCS/σ′)) (angle at most 70°), Pa.
    pub fn peak_strength(&self, compression: f64) -> f64 {
        compression
            * self
                .mobilized(self.peak_displacement, compression)
                .friction
                .tan()
    }

    /// The shear strength at the shear path δ (m) under σ′ (Pa), Pa.
    fn strength(&self, path: f64, compression: f64) -> f64 {
        compression * self.mobilized(path, compression).friction.tan()
    }

    /// The shear path (m) at which the rising branch of the curve (δ ≤ δp) reaches the shear
    /// stress `shear` (Pa) under σ′ (Pa): δp if it is beyond the peak (bisection; the branch
    /// rises monotonically).
    fn path_reaching(&self, shear: f64, compression: f64) -> f64 {
        let (mut lo, mut hi) = (0.0, self.peak_displacement);
        if self.strength(hi, compression) <= shear {
            return hi;
        }
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if self.strength(mid, compression) < shear {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        hi
    }

    /// The effective compression (Pa) of a state whose contact started at `initial_normal` (Pa)
    /// and has opened by `opening` (m, the normal displacement less the dilation), or `None` if
    /// it is open.
    fn compression_of(&self, initial_normal: f64, opening: f64) -> Option<f64> {
        let closure = self.closure((-initial_normal).max(0.0)) - opening;
        (closure >= 0.0).then(|| self.compression(closure))
    }
}

impl JointLaw for BartonBandis {
    /// Normal stress from the hyperbola at the closure since the contact was made; shear trial
    /// τ + ks Δus; if beyond the mobilized strength, the plastic slip λ returns it: the joint
    /// dilates by tan dmob λ, and λ is such that τ ends on the strength at the compression the
    /// dilation brings, λ = excess/(ks + Kn tan dmob dτ/dσ′) linearized at the trial, the shear then
    /// set on the final limit (`CoulombSlip::plastic_slip`'s return with the tangents).
    fn update(&self, s: &mut JointState, dn: f64, ds: f64) {
        s.normal_displacement += dn;
        s.shear_displacement += ds;
        s.shear_path += ds.abs();
        s.flags &= !(SLIPPING | OPEN);
        let Some(compression) =
            self.compression_of(s.initial_normal, s.normal_displacement - s.dilation)
        else {
            (s.normal, s.shear) = (0.0, 0.0);
            s.flags |= OPEN;
            return;
        };
        s.normal = -compression;
        if s.shear_path == ds.abs() && s.shear != 0.0 {
            // A joint present from the start carries its in-situ shear: it has mobilized the
            // path at which the curve reaches it, and carries at most the peak (an in-situ shear
            // beyond it is capped there, as the Coulomb law caps one beyond its limit, without
            // the plastic slip a return would count).
            let path = self.path_reaching(s.shear.abs(), compression);
            s.shear_path += path;
            s.shear = s.shear.signum() * s.shear.abs().min(self.strength(path, compression));
        }
        let trial = s.shear + self.shear_stiffness * ds;
        let m = self.mobilized(s.shear_path, compression);
        s.jrc_mobilized = m.jrc;
        let limit = compression * m.friction.tan();
        if trial.abs() <= limit {
            s.shear = trial;
            return;
        }
        s.flags |= SLIPPING;
        let sign = trial.signum();
        let tan_dilation = m.dilation.tan();
        if tan_dilation > 0.0 {
            let h = 1e-6 * compression.max(1.0);
            // The strength rises with the compression wherever the criterion holds; a
            // negative difference (rounding, or the 70° cap's kink) is taken as none.
            let slope = ((self.strength(s.shear_path, compression + h) - limit) / h).max(0.0);
            let kn = self.tangent_normal_stiffness(compression);
            let slip = (trial.abs() - limit) / (self.shear_stiffness + kn * tan_dilation * slope);
            s.dilation += tan_dilation * slip.max(0.0);
            let opening = s.normal_displacement - s.dilation;
            // Dilating only closes the joint further: it stays in compression.
            let compression = self
                .compression_of(s.initial_normal, opening)
                .unwrap_or(compression);
            s.normal = -compression;
            s.shear = sign * self.strength(s.shear_path, compression);
        } else {
            s.shear = sign * limit;
        }
    }

    /// Kmax (the hyperbola's tangent where it ends, as stiff as the joint gets) and ks.
    fn stiffness(&self) -> (f64, f64) {
        (self.max_normal_stiffness, self.shear_stiffness)
    }

    /// The hyperbola's tangent at the contact's compression (Kni if open) and ks: Kmax in the
    /// implicit matrix held the bundled tunnel's stage with Barton–Bandis joints (Kmax four times
    /// the in-situ tangent) creeping at 1e-5 m an iteration after 500 iterations; the tangent
    /// converges it.
    fn tangent(&self, state: &JointState) -> (f64, f64) {
        let compression = (-state.normal).max(0.0);
        (
            self.tangent_normal_stiffness(compression),
            self.shear_stiffness,
        )
    }

    /// tan φmob / F at every shear path and compression, the dilation at most the reduced angle
    /// (the module's doc).
    fn reduced(&self, factor: f64) -> Box<dyn JointLaw> {
        Box::new(BartonBandis {
            strength_factor: self.strength_factor * factor,
            ..*self
        })
    }
}

impl BartonBandis {
    /// The tangent normal stiffness dσ′/dΔv at σ′ (Pa), Pa/m.
    pub fn tangent_normal_stiffness(&self, compression: f64) -> f64 {
        if compression >= self.hyperbola_end().1 {
            self.max_normal_stiffness
        } else {
            self.initial_normal_stiffness * (1.0 + compression / self.half_closure_stress()).powi(2)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// JRC 10, JCS 100 MPa on a 0.1 m sample, φr 30°, Kni 20 GPa/m, Vm 0.5 mm, ks 20 GPa/m.
    fn law() -> BartonBandis {
        BartonBandis::new(
            (20e9, 0.5e-3),
            20e9,
            Roughness {
                jrc: 10.0,
                jcs: 100e6,
                sample_length: 0.1,
                block_size: None,
            },
            30.0,
            2.0,
        )
    }

    fn loaded(law: &BartonBandis, sn: f64) -> JointState {
        let mut s = JointState::default();
        // Close it from zero stress to σn in small steps.
        let target = law.closure(sn);
        for _ in 0..1000 {
            law.update(&mut s, -target / 1000.0, 0.0);
        }
        s
    }

    /// The closure follows the hyperbola at any compression, and its inverse.
    #[test]
    fn closure_follows_the_hyperbola() {
        let l = law();
        for sn in [0.1e6, 1e6, 5e6, 30e6] {
            let s = loaded(&l, sn);
            assert!((s.normal + sn).abs() < 1e-9 * sn, "{sn}: {}", s.normal);
            let closure = -s.normal_displacement;
            let exact = sn * 0.5e-3 / (20e9 * 0.5e-3 + sn);
            assert!((closure - exact).abs() < 1e-12, "{closure} vs {exact}");
        }
        // Beyond JCS linear with the hyperbola's tangent there.
        let k = l.max_normal_stiffness;
        assert!((k - 20e9 * (1.0 + 100e6 / 10e6_f64).powi(2)).abs() < 1.0);
        assert!((l.hyperbola_end().1 - 100e6).abs() < 1e-6 * 100e6);
        let c = l.closure(120e6);
        assert!((l.compression(c) - 120e6).abs() < 1e-6 * 120e6);
        let slope = (l.compression(c + 1e-9) - l.compression(c)) / 1e-9;
        assert!((slope - k).abs() < 1e-4 * k);
        // A lower Kmax = 4 Kni ends the hyperbola at Kni Vm (2 − 1) = 10 MPa, continuously.
        let soft = l.with_max_normal_stiffness(4.0 * 20e9);
        let (end, at) = soft.hyperbola_end();
        assert!((at - 10e6).abs() < 1e-6 * 10e6 && (end - 0.25e-3).abs() < 1e-15);
        assert!((soft.compression(end) - l.compression(end)).abs() < 1e-6 * at);
        assert!((soft.closure(at + 8e10 * 1e-5) - (end + 1e-5)).abs() < 1e-12);
        // Opened past its zero closure, it carries nothing.
        let mut s = JointState::default();
        l.update(&mut s, 1e-6, 0.0);
        assert_eq!((s.normal, s.shear, s.flags & OPEN), (0.0, 0.0, OPEN));
    }

    /// The scale correction and the peak displacement, by the formulas.
    #[test]
    fn scale_correction_lowers_jrc_and_jcs() {
        let r = Roughness {
            jrc: 15.0,
            jcs: 80e6,
            sample_length: 0.1,
            block_size: Some(2.0),
        };
        let (jrc, jcs, l) = r.at_scale();
        assert!((jrc - 15.0 * 20f64.powf(-0.3)).abs() < 1e-12);
        assert!((jcs - 80e6 * 20f64.powf(-0.45)).abs() < 1e-3);
        assert_eq!(l, 2.0);
        assert!(jrc < 15.0 && jcs < 80e6);
        let dp = peak_displacement(jrc, 2.0);
        assert!((dp - 2.0 / 500.0 * (jrc / 2.0).powf(0.33)).abs() < 1e-15);
    }

    /// Under constant σn, monotonic shear peaks at σ′ tan(φr + JRC log10(JCS/σ′)) at δp and falls
    /// towards σ′ tan φr; it dilates by tan dmob once JRCmob > 0, fastest at the peak.
    #[test]
    fn shear_under_constant_stress_peaks_at_the_criterion() {
        let l = law();
        for sn in [0.5e6, 2e6, 8e6] {
            let mut s = loaded(&l, sn);
            let du = l.peak_displacement / 2000.0;
            let (mut peak, mut at, mut peak_normal) = (0.0f64, 0.0, 0.0);
            let mut opening = 0.0;
            for k in 1..=40_000 {
                let d = s.dilation;
                l.update(&mut s, opening, du);
                // Constant σn: the joint opens as it dilates (a step late, so σ′ departs from σn
                // by the compression of one step's dilation).
                opening = s.dilation - d;
                if s.shear > peak {
                    (peak, at, peak_normal) = (s.shear, k as f64 * du, -s.normal);
                }
            }
            assert!((peak_normal - sn).abs() < 0.01 * sn, "{peak_normal}");
            let exact = peak_normal
                * (30.0 + 10.0 * (100e6 / peak_normal).log10())
                    .to_radians()
                    .tan();
            // The largest sample may be the one before δp, under a σ′ one step's dilation higher.
            assert!(
                (peak - exact).abs() < 3e-4 * exact,
                "{sn}: {peak} vs {exact}"
            );
            assert!(
                (at / l.peak_displacement - 1.0).abs() < 0.02,
                "peak at {at}"
            );
            // At 20 δp JRCmob/JRC = 0.5 − 0.5·10/90.
            let f = 0.5 - 0.5 * 10.0 / 90.0;
            assert!(
                (s.jrc_mobilized - 10.0 * f).abs() < 1e-3,
                "{}",
                s.jrc_mobilized
            );
            assert!(s.dilation > 0.0);
        }
    }

    /// Reduced by F, every state's strength is the unreduced one over F: sheared under constant
    /// σn it peaks at τp/F at δp, its JRC mobilized as the unreduced joint's, its dilation angle
    /// at most the reduced friction; F = 1 changes nothing.
    #[test]
    fn the_reduced_law_mobilizes_its_strength_over_the_factor() {
        let l = law();
        for (factor, sn) in [(1.25, 2e6), (2.0, 0.5e6), (3.0, 8e6)] {
            let reduced = BartonBandis {
                strength_factor: factor,
                ..l
            };
            for r in [0.1, 0.3, 0.8, 1.0, 3.0, 50.0] {
                let (a, b) = (
                    l.mobilized(r * l.peak_displacement, sn),
                    reduced.mobilized(r * l.peak_displacement, sn),
                );
                assert!((b.friction.tan() - a.friction.tan() / factor).abs() < 1e-14);
                assert_eq!(a.jrc, b.jrc);
                assert!(b.dilation <= b.friction && b.dilation <= a.dilation);
            }
            let boxed = l.reduced(factor);
            let mut s = loaded(&l, sn);
            let du = l.peak_displacement / 2000.0;
            let (mut peak, mut peak_normal, mut opening) = (0.0f64, 0.0, 0.0);
            for _ in 0..6000 {
                let d = s.dilation;
                boxed.update(&mut s, opening, du);
                opening = s.dilation - d;
                if s.shear > peak {
                    (peak, peak_normal) = (s.shear, -s.normal);
                }
            }
            let exact = l.peak_strength(peak_normal) / factor;
            assert!(
                (peak - exact).abs() < 3e-4 * exact,
                "F {factor}: {peak} vs {exact}"
            );
        }
        let (same, mut a, mut b) = (l.reduced(1.0), loaded(&l, 2e6), loaded(&l, 2e6));
        for _ in 0..3000 {
            l.update(&mut a, 1e-9, 1e-6);
            same.update(&mut b, 1e-9, 1e-6);
        }
        assert_eq!(a, b);
    }

    /// A joint present from the start with an in-situ shear keeps it: it begins at the shear
    /// path where the rising branch reaches it (the peak if the shear is beyond it, capped there).
    #[test]
    fn an_in_situ_shear_starts_on_the_rising_branch() {
        let l = law();
        let sn = 5e6;
        let peak = l.peak_strength(sn);
        for shear in [0.3 * peak, 0.9 * peak] {
            let mut s = JointState {
                normal: -sn,
                initial_normal: -sn,
                shear,
                ..Default::default()
            };
            l.update(&mut s, 0.0, 1e-9);
            // It goes on from its shear: elastically, or along the curve where that is softer.
            assert!(s.shear >= shear && s.shear <= shear + 20e9 * 1e-9, "{s:?}");
            assert!(
                s.shear_path > 1e-9 && s.shear_path < l.peak_displacement,
                "{s:?}"
            );
            assert!((s.normal + sn).abs() < 1e-6 * sn);
        }
        let mut beyond = JointState {
            normal: -sn,
            initial_normal: -sn,
            shear: 1.5 * peak,
            ..Default::default()
        };
        l.update(&mut beyond, 0.0, 1e-9);
        assert!((beyond.shear - peak).abs() < 1e-6 * peak, "{beyond:?}");
        assert!(beyond.dilation < 1e-9, "{beyond:?}");
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(300))]
        /// Any material and any path of normal and shear increments keeps the joint on or
        /// inside its mobilized strength at the compression it carries, in compression or open,
        /// and its closure on the hyperbola.
        #[test]
        fn every_path_stays_within_the_mobilized_strength(
            jrc in 0.0..20.0f64, jcs in 10e6..200e6f64, phi in 20.0..40.0f64,
            kni in 1e9..1e11f64, vm in 1e-4..2e-3f64, ks in 1e9..1e11f64,
            sn in 0.0..30e6f64, steps in proptest::collection::vec((-1.0..1.0f64, -1.0..1.0f64), 1..200),
        ) {
            let l = BartonBandis::new(
                (kni, vm), ks,
                Roughness { jrc, jcs, sample_length: 0.1, block_size: None },
                phi, 2.0,
            );
            let mut s = JointState { normal: -sn, initial_normal: -sn, ..Default::default() };
            let scale = l.peak_displacement;
            for (dn, ds) in steps {
                l.update(&mut s, 0.05 * vm * dn, 0.2 * scale * ds);
                proptest::prop_assert!(s.normal.is_finite() && s.shear.is_finite());
                proptest::prop_assert!(s.normal <= 0.0);
                let compression = -s.normal;
                let limit = l.strength(s.shear_path, compression);
                proptest::prop_assert!(s.shear.abs() <= limit * (1.0 + 1e-9) + 1e-6, "{s:?} {limit}");
                if s.flags & OPEN == 0 {
                    let closure = l.closure(sn) - (s.normal_displacement - s.dilation);
                    proptest::prop_assert!((l.compression(closure) - compression).abs() <= 1e-6 * compression.max(1.0));
                }
            }
        }
    }

    #[test]
    fn the_mobilization_table_is_continuous_and_ends_at_zero() {
        assert_eq!(mobilized_fraction(0.3), 0.0);
        assert_eq!(mobilized_fraction(1.0), 1.0);
        assert!((mobilized_fraction(0.8) - 0.875).abs() < 1e-12);
        assert_eq!(mobilized_fraction(150.0), 0.0);
        let l = law();
        // Below 0.3 δp the angle rises from 0 to φr.
        let m0 = l.mobilized(0.0, 1e6);
        assert!(m0.friction.abs() < 1e-12);
        let m = l.mobilized(0.3 * l.peak_displacement, 1e6);
        assert!((m.friction - 30f64.to_radians()).abs() < 1e-12);
        assert_eq!(m.dilation, 0.0);
        // The 70° cap at a low stress.
        let low = l.mobilized(l.peak_displacement, 1.0);
        assert!((low.friction - 70f64.to_radians()).abs() < 1e-12);
    }
}
