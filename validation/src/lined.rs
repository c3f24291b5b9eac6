//! A lined circular tunnel in elastic ground (Einstein & Schwartz 1979, "Simplified analysis for
//! tunnel supports", J. Geotech. Eng. Div. ASCE 105(GT4), no-slip interface). The liner is put
//! in place as the hole is made (no relaxation before it) under a vertical in-situ stress P and a
//! horizontal one K·P. With the compressibility and flexibility ratios
//!
//!   C = E R (1 − νs²) / (Es As (1 − ν²)),   F = E R³ (1 − νs²) / (Es Is (1 − ν²)),
//!   β = [(6 + F) C (1 − ν) + 2 F ν] / [3F + 3C + 2 C F (1 − ν)],
//!   a0* = C F (1 − ν) / [C + F + C F (1 − ν)],
//!   b2* = C (1 − ν) / (2 [C (1 − ν) + 4ν − 6β − 3β C (1 − ν)]),   a2* = β b2*,
//!
//! thrust (compression positive) and moment at angle θ from the springline are
//!
//!   T / (P R)  = ½ (1 + K)(1 − a0*) + ½ (1 − K)(1 + 2 a2*) cos 2θ,
//!   M / (P R²) = ¼ (1 − K)(1 − 2 a2* + 2 b2*) cos 2θ
//!
//! (E-S's M is positive with the outer face in tension: adit's liner moment is −M). For K = 1
//! the thrust reduces to the thin ring on the elastic hole, P R / (1 + C (1 − ν)), checked below.
//!
//! E-S's no-slip moment is an approximation; the liner is also checked against the exact solution
//! of the same thin ring (hoop strain (v′ + w)/R, curvature change (v′ − w″)/R², w outward, v
//! along θ) bonded to the elastic ground, derived here mode by mode. Mode 0: the ring's hoop force
//! N0 = −P0 EA/(2G + EA/R), P0 = P(1 + K)/2. Mode 2 (w = W cos 2θ, v = V sin 2θ): with S = P(1 − K)/2
//! the in-situ stresses at the wall are σrr = S cos 2θ, σrθ = −S sin 2θ (deviatoric part); the ring
//! loaded by the interface stresses Ar cos 2θ, Aθ sin 2θ is in equilibrium (stationary energy)
//! when R·[Ar, Aθ] = Kring·[W, V], Kring = [[EA/R + 16EI/R³, 2EA/R + 8EI/R³],
//! [2EA/R + 8EI/R³, 4EA/R + 4EI/R³]]; the ground's exterior Michell solution for the stress change
//! a = Ar − S, b = Aθ + S on the hole (Barber, *Elasticity*, table 9.1, κ = 3 − 4ν) moves the wall
//! by 2G W/R = a(1/3 − (κ + 1)/2) + b((κ + 1)/2 − 2/3), 2G V/R = a(1/3 + (κ − 1)/2) − b(2/3 + (κ − 1)/2)
//! (without a ring it gives Kirsch's u_r = κ S R/(2G) cos 2θ). Solving the 2 × 2 system gives
//! N2 = EA(2V + W)/R and M2 = EI(2V + 4W)/R² (outer face in tension positive). For the shipped case
//! (t = 0.15 m) its thrust is within 0.5 % of E-S's and E-S's moment is 18 % above it.

use std::time::Instant;

use adit::Scene;
use adit::scene::{LinerCapacitySpec, LinerSpec, SolveMethod};
use adit::setup::setup;
use adit::support::Liners;

use crate::kirsch_case::scaled;
use crate::report::CaseReport;

/// The closed form of one case.
#[derive(Debug, Clone, Copy)]
pub struct EinsteinSchwartz {
    /// Liner radius R, m.
    pub radius: f64,
    /// Vertical in-situ stress P (compression positive), Pa, and the ratio K of the horizontal.
    pub p: f64,
    pub k: f64,
    /// Ground modulus and Poisson's ratio.
    pub young: f64,
    pub poisson: f64,
    /// Liner modulus, Poisson's ratio, area and second moment per metre (m², m⁴).
    pub liner_young: f64,
    pub liner_poisson: f64,
    pub area: f64,
    pub inertia: f64,
}

impl EinsteinSchwartz {
    /// (C, F).
    pub fn ratios(&self) -> (f64, f64) {
        let g = self.young * (1.0 - self.liner_poisson.powi(2))
            / (self.liner_young * (1.0 - self.poisson.powi(2)));
        (
            g * self.radius / self.area,
            g * self.radius.powi(3) / self.inertia,
        )
    }

    /// (a0*, a2*, b2*) for no slip.
    fn coefficients(&self) -> (f64, f64, f64) {
        let (c, f) = self.ratios();
        let nu = self.poisson;
        let cn = c * (1.0 - nu);
        let beta = ((6.0 + f) * cn + 2.0 * f * nu) / (3.0 * f + 3.0 * c + 2.0 * f * cn);
        let a0 = f * cn / (c + f + f * cn);
        let b2 = cn / (2.0 * (cn + 4.0 * nu - 6.0 * beta - 3.0 * beta * cn));
        (a0, beta * b2, b2)
    }

    /// Thrust T(θ), N/m (compression positive).
    pub fn thrust(&self, theta: f64) -> f64 {
        let (a0, a2, _) = self.coefficients();
        let k = self.k;
        self.p
            * self.radius
            * (0.5 * (1.0 + k) * (1.0 - a0)
                + 0.5 * (1.0 - k) * (1.0 + 2.0 * a2) * (2.0 * theta).cos())
    }

    /// The exact thin ring bonded to the ground, [N0, N2, M2]: hoop force N0 + N2 cos 2θ (N/m,
    /// tension positive), moment M2 cos 2θ (N·m/m, outer face in tension positive).
    pub fn thin_ring(&self) -> [f64; 3] {
        let r = self.radius;
        let e = self.liner_young / (1.0 - self.liner_poisson.powi(2));
        let (ea, ei) = (e * self.area, e * self.inertia);
        let g = self.young / (2.0 * (1.0 + self.poisson));
        let kappa = 3.0 - 4.0 * self.poisson;
        let n0 = -0.5 * self.p * (1.0 + self.k) * ea / (2.0 * g + ea / r);
        let s = 0.5 * self.p * (1.0 - self.k);
        // Ring stiffness (per R) and ground compliance (times R/2G), mode 2.
        let kr = [
            [
                ea / r + 16.0 * ei / r.powi(3),
                2.0 * ea / r + 8.0 * ei / r.powi(3),
            ],
            [
                2.0 * ea / r + 8.0 * ei / r.powi(3),
                4.0 * ea / r + 4.0 * ei / r.powi(3),
            ],
        ]
        .map(|row| row.map(|k| k / r));
        let c = r / (2.0 * g);
        let gm = [
            [
                1.0 / 3.0 - 0.5 * (kappa + 1.0),
                0.5 * (kappa + 1.0) - 2.0 / 3.0,
            ],
            [
                1.0 / 3.0 + 0.5 * (kappa - 1.0),
                -2.0 / 3.0 - 0.5 * (kappa - 1.0),
            ],
        ];
        // x = c·Gm·(Kr x + [−S, S])  ⇒  (I − c Gm Kr) x = c Gm [−S, S].
        let gk = |i: usize, j: usize| c * (gm[i][0] * kr[0][j] + gm[i][1] * kr[1][j]);
        let m = [[1.0 - gk(0, 0), -gk(0, 1)], [-gk(1, 0), 1.0 - gk(1, 1)]];
        let rhs = [c * (gm[0][1] - gm[0][0]) * s, c * (gm[1][1] - gm[1][0]) * s];
        let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        let w = (rhs[0] * m[1][1] - m[0][1] * rhs[1]) / det;
        let v = (m[0][0] * rhs[1] - m[1][0] * rhs[0]) / det;
        [
            n0,
            ea * (2.0 * v + w) / r,
            ei * (2.0 * v + 4.0 * w) / (r * r),
        ]
    }

    /// Moment M(θ), N·m/m, E-S's sign (outer face in tension positive).
    pub fn moment(&self, theta: f64) -> f64 {
        let (_, a2, b2) = self.coefficients();
        self.p
            * self.radius.powi(2)
            * 0.25
            * (1.0 - self.k)
            * (1.0 - 2.0 * a2 + 2.0 * b2)
            * (2.0 * theta).cos()
    }
}

/// The liner's strengths: shotcrete of σc = 40 MPa, σt = 4 MPa.
const SHOTCRETE: LinerCapacitySpec = LinerCapacitySpec {
    compressive_strength: 40e6,
    tensile_strength: 4e6,
};

/// The factor of safety of a rectangular section of depth `t` (per metre) under thrust `thrust`
/// (N/m, compression positive), moment `moment` and shear `shear`, by hand from its capacity
/// diagram (Carranza-Torres & Diederichs 2009): the factor λ by which the point (M, T) can be
/// scaled along its ray from the origin to reach the FS = 1 diamond through (0, σc t),
/// (±(σc + σt) t²/12, (σc − σt) t/2), (0, −σt t), and the point (V, T) to reach the curve
/// (1.5 V/t)² = σc² − σc T/t (compression side) or σt² + σt T/t (tension side): with σ0 = T/t,
/// τ = 1.5 V/t, the roots λ of τ²λ² + σc σ0 λ − σc² = 0 and τ²λ² − σt σ0 λ − σt² = 0.
pub fn hand_factor_of_safety(t: f64, thrust: f64, moment: f64, shear: f64) -> f64 {
    let (c, ts) = (SHOTCRETE.compressive_strength, SHOTCRETE.tensile_strength);
    let diamond = [
        (0.0, c * t),
        ((c + ts) * t * t / 12.0, 0.5 * (c - ts) * t),
        (0.0, -ts * t),
        (-(c + ts) * t * t / 12.0, 0.5 * (c - ts) * t),
    ];
    // Ray λ(M, T) meets edge a + μ(b − a): solve the 2×2 system for (λ, μ).
    let mut bending = f64::INFINITY;
    for k in 0..4 {
        let (a, b) = (diamond[k], diamond[(k + 1) % 4]);
        let d = (b.0 - a.0, b.1 - a.1);
        let det = moment * -d.1 + d.0 * thrust;
        if det.abs() < 1e-300 {
            continue;
        }
        let lambda = (a.0 * -d.1 + d.0 * a.1) / det;
        let mu = (moment * a.1 - thrust * a.0) / det;
        if lambda > 0.0 && (-1e-12..=1.0 + 1e-12).contains(&mu) {
            bending = bending.min(lambda);
        }
    }
    let (s0, tau) = (thrust / t, 1.5 * shear / t);
    let root = |b: f64, cc: f64| {
        if tau == 0.0 {
            if b > 0.0 { cc / b } else { f64::INFINITY }
        } else {
            (-b + (b * b + 4.0 * tau * tau * cc).sqrt()) / (2.0 * tau * tau)
        }
    };
    let shear_fs = root(c * s0, c * c).min(root(-ts * s0, ts * ts));
    bending.min(shear_fs)
}

/// The largest relative difference between the engine's factor of safety of each liner element
/// (`Liners::safety`) and [`hand_factor_of_safety`] at both its ends.
pub fn safety_deviation(l: &Liners, thickness: f64) -> f64 {
    (0..l.element.len())
        .map(|e| {
            let engine = l.safety(e).expect("the liner has strengths").factor();
            let hand = (l.section_forces(e).iter())
                .map(|f| hand_factor_of_safety(thickness, f.thrust, f.moment, f.shear))
                .fold(f64::INFINITY, f64::min);
            (engine - hand).abs() / hand
        })
        .fold(0.0, f64::max)
}

/// The shipped Kirsch geometry (R = 1 m, zoning scaled by `factor`) in elastic ground
/// (E = 10 GPa, ν = 0.25) under P = 20 MPa, K = 0.5, lined from the start by a shotcrete shell
/// (Es = 30 GPa, νs = 0.2) of thickness `thickness` (m).
fn scene(kirsch: &Scene, factor: f64, thickness: f64) -> (Scene, EinsteinSchwartz) {
    let mut s = scaled(kirsch, factor);
    s.name = "lined".into();
    let m = &s.materials[&s.region.material];
    let (young, poisson) = (m.young, m.poisson);
    s.in_situ.sxx = -10e6;
    s.in_situ.syy = -20e6;
    s.solve.ratio = 1e-6;
    s.solve.max_cycles = 400_000;
    let (area, inertia) = (thickness, thickness.powi(3) / 12.0);
    s.liners = vec![LinerSpec {
        name: "shotcrete".into(),
        excavation: s.excavations[0].name.clone(),
        young: 30e9,
        poisson: 0.2,
        area,
        inertia,
        out_of_plane_spacing: 1.0,
        density: 2500.0,
        capacity: Some(SHOTCRETE),
    }];
    let radius = s.excavations[0]
        .circle
        .as_ref()
        .expect("circular hole")
        .radius;
    let exact = EinsteinSchwartz {
        radius,
        p: 20e6,
        k: 0.5,
        young,
        poisson,
        liner_young: 30e9,
        liner_poisson: 0.2,
        area,
        inertia,
    };
    (s, exact)
}

/// Solve and compare the liner's thrust with E-S (`thrust`: largest |T_h − T| over the elements
/// relative to the largest |T|) and with the exact thin ring (`thrust_ring`), and its moment at
/// each element's middle with the exact thin ring (`moment_ring`, likewise) and with E-S
/// (`moment_es`).
pub fn run(kirsch: &Scene, factor: f64, thickness: f64) -> anyhow::Result<CaseReport> {
    run_by(kirsch, factor, thickness, SolveMethod::Explicit)
}

/// [`run`] solved by `method` (`solve.method`); the row's case names it.
pub fn run_by(
    kirsch: &Scene,
    factor: f64,
    thickness: f64,
    method: SolveMethod,
) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let (mut sc, exact) = scene(kirsch, factor, thickness);
    sc.solve.method = method;
    let mut b = setup(&sc)?;
    let (cycles, implicit) = crate::settle_by_method(&mut b.model, &sc.solve, "lined tunnel")?;
    let l = &b.model.supports.liners;
    let [n0, n2, m2] = exact.thin_ring();
    // Largest deviation over the elements relative to the largest reference value.
    let deviation = |computed: &dyn Fn(usize) -> f64, reference: &dyn Fn(f64) -> f64| {
        let (mut err, mut max) = (0.0f64, 0.0f64);
        for e in 0..l.element.len() {
            let [p, q] = l.element[e].map(|n| l.pos[n as usize]);
            let theta = (0.5 * (p[1] + q[1])).atan2(0.5 * (p[0] + q[0]));
            let r = reference(theta);
            err = err.max((computed(e) - r).abs());
            max = max.max(r.abs());
        }
        err / max
    };
    let thrust = |e: usize| -l.axial[e];
    let moment = |e: usize| 0.5 * (l.moment[e][0] + l.moment[e][1]);
    let errors = [
        ("thrust", deviation(&thrust, &|t| exact.thrust(t))),
        (
            "thrust_ring",
            deviation(&thrust, &|t| -(n0 + n2 * (2.0 * t).cos())),
        ),
        (
            "moment_ring",
            deviation(&moment, &|t| -m2 * (2.0 * t).cos()),
        ),
        ("moment_es", deviation(&moment, &|t| -exact.moment(t))),
        ("safety", safety_deviation(l, thickness)),
    ];
    let (c, f) = exact.ratios();
    Ok(CaseReport::new(
        format!(
            "Einstein–Schwartz: lined hole, P = 20 MPa, K = 0.5, C = {c:.2}, F = {f:.0} (×{factor}){}",
            crate::method_suffix(method)
        ),
        b.model.zones.len(),
        cycles,
        start.elapsed().as_secs_f64(),
        None,
        &errors,
    )
    .with_implicit(implicit))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hydrostatic_thrust_is_the_thin_ring_on_an_elastic_hole() {
        let mut es = EinsteinSchwartz {
            radius: 3.0,
            p: 10e6,
            k: 1.0,
            young: 5e9,
            poisson: 0.3,
            liner_young: 30e9,
            liner_poisson: 0.0,
            area: 0.2,
            inertia: 0.2f64.powi(3) / 12.0,
        };
        let (c, _) = es.ratios();
        let ring = es.p * es.radius / (1.0 + c * (1.0 - es.poisson));
        // F large (thin shell): a0* → C(1−ν)/(1 + C(1−ν)).
        es.inertia = 1e-12;
        assert!((es.thrust(0.3) - ring).abs() < 1e-6 * ring);
        assert_eq!(es.moment(0.3), 0.0);
    }

    #[test]
    fn the_exact_thin_ring_agrees_with_einstein_schwartz_where_it_should() {
        let mut es = EinsteinSchwartz {
            radius: 1.0,
            p: 20e6,
            k: 0.5,
            young: 10e9,
            poisson: 0.25,
            liner_young: 30e9,
            liner_poisson: 0.2,
            area: 0.15,
            inertia: 0.15f64.powi(3) / 12.0,
        };
        let [n0, n2, m2] = es.thin_ring();
        // Thrust: E-S's to 1 %; moment: below E-S's simplified no-slip value.
        assert!((-(n0 + n2) - es.thrust(0.0)).abs() < 0.01 * es.thrust(0.0));
        assert!(m2 > 0.0 && m2 < es.moment(0.0));
        // A ring with no bending stiffness carries no moment; hydrostatic stress bends nothing.
        es.inertia = 0.0;
        assert!(es.thin_ring()[2].abs() < 1e-9);
        es.inertia = 1e-3;
        es.k = 1.0;
        let [n0, n2, m2] = es.thin_ring();
        assert!(n2.abs() < 1e-6 && m2.abs() < 1e-9);
        let (c, _) = es.ratios();
        let ring = es.p * es.radius / (1.0 + c * (1.0 - es.poisson));
        assert!((-n0 - ring).abs() < 1e-9 * ring);
    }

    #[test]
    fn liner_thrust_matches_einstein_schwartz() {
        let kirsch = crate::shipped_kirsch().unwrap();
        let r = run(&kirsch, 2.0, 0.15).unwrap();
        assert!(r.errors["thrust"] < 0.05, "{r:?}");
        assert!(r.errors["moment_ring"] < 0.1, "{r:?}");
        assert!(r.errors["safety"] < 1e-6, "{r:?}");
    }

    /// The hand calculation of the capacity diagram: pure thrust and pure tension meet the
    /// strengths, a point on an edge of the diamond scaled down by 3 has FS 3, and a shear alone
    /// meets the tensile strength at the neutral axis.
    #[test]
    fn the_hand_capacity_diagram_meets_the_strengths() {
        let t = 0.2;
        assert!((hand_factor_of_safety(t, 4e6, 0.0, 0.0) - 2.0).abs() < 1e-12);
        assert!((hand_factor_of_safety(t, -0.4e6, 0.0, 0.0) - 2.0).abs() < 1e-12);
        // Halfway along the upper right edge of the FS = 1 diamond, scaled by 1/3: FS 3.
        let (c, ts) = (40e6, 4e6);
        let (m, th) = (
            0.5 * (c + ts) * t * t / 12.0,
            0.5 * (c * t + 0.5 * (c - ts) * t),
        );
        let fs = hand_factor_of_safety(t, th / 3.0, m / 3.0, 0.0);
        assert!((fs - 3.0).abs() < 1e-12, "{fs}");
        // Shear alone: τ = 1.5 V/t reaches σt (the tension side) at V = σt t/1.5.
        let fs = hand_factor_of_safety(t, 0.0, 0.0, ts * t / 1.5 / 4.0);
        assert!((fs - 4.0).abs() < 1e-12, "{fs}");
    }

    /// The implicit solve assembles the liner (beam elements and links): rock and liner are
    /// elastic, so one iteration reaches equilibrium, at the explicit path's thrust and moment.
    #[test]
    fn the_implicit_solve_carries_the_liner() {
        let kirsch = crate::shipped_kirsch().unwrap();
        let e = run(&kirsch, 2.0, 0.15).unwrap();
        let i = run_by(&kirsch, 2.0, 0.15, SolveMethod::Implicit).unwrap();
        assert!(i.cycles <= 2, "{i:?}");
        for (k, v) in &e.errors {
            assert!(
                (i.errors[k] - v).abs() < 2e-3,
                "{k}: {} vs {v}",
                i.errors[k]
            );
        }
    }
}
