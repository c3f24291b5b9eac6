//! Circular hole in Mohr–Coulomb rock under hydrostatic stress p0 with an internal pressure pi
//! (Salençon 1969; the classical elastic–perfectly plastic solution, e.g. Brady & Brown, *Rock
//! Mechanics for Underground Mining*, §7.6; Itasca's FLAC verification "Cylindrical hole in an
//! infinite Mohr–Coulomb medium"). With Kp = (1 + sin φ)/(1 − sin φ), σc = 2c cos φ/(1 − sin φ)
//! and q = σc/(Kp − 1), pressures positive in compression:
//!
//!   plastic radius  Rp = a [ 2/(Kp + 1) · (p0 + q)/(pi + q) ]^{1/(Kp − 1)},
//!   plastic zone    σr = −[(pi + q)(r/a)^{Kp−1} − q],  σθ = −[Kp (pi + q)(r/a)^{Kp−1} − q],
//!   elastic zone    σr = −p0 + (p0 − pe)(Rp/r)²,  σθ = −p0 − (p0 − pe)(Rp/r)²,  pe = (2p0 − σc)/(Kp + 1).
//!
//! (tension positive in the formulas as in adit). The radial displacement follows from
//! compatibility with the flow rule ε_r^p = −Nψ ε_θ^p (shear potential σ1 − σ3 Nψ, σ1 = σθ, σ3 = σr)
//! and the elastic strains of the stress change (plane strain):
//!
//!   du/dr + Nψ u/r = ε_r^e(r) + Nψ ε_θ^e(r)  on a ≤ r ≤ Rp,   u(Rp) = −(p0 − pe) Rp / (2G),
//!
//! a linear ODE in u integrated here to round-off (RK4 on a fine grid; Salençon's solution in
//! closed form integrates the same equation). The hole is excavated at once: the zones start at
//! −p0 and the free wall unloads them.

use std::time::Instant;

use adit::Scene;
use adit::implicit::Cost;
use adit::law::{SHEAR_NOW, SHEAR_PAST};
use adit::scene::{SolveMethod, SolveSpec};
use adit::scene::{Stage, ZoneLawKind};
use adit::setup::setup;
use adit::stage::Staging;

use crate::kirsch_case::{scaled, support_wall};
use crate::report::CaseReport;

/// The closed form of one case.
#[derive(Debug, Clone, Copy)]
pub struct Salencon {
    /// Hole radius a, m.
    pub radius: f64,
    /// In-situ pressure p0 (compression positive), Pa.
    pub p0: f64,
    /// Internal support pressure pi (compression positive), Pa.
    pub pi: f64,
    /// Cohesion, Pa.
    pub cohesion: f64,
    /// Friction angle, rad.
    pub friction: f64,
    /// Dilation angle, rad.
    pub dilation: f64,
    /// Shear modulus, Pa.
    pub shear: f64,
    /// Poisson's ratio.
    pub poisson: f64,
}

impl Salencon {
    fn kp(&self) -> f64 {
        (1.0 + self.friction.sin()) / (1.0 - self.friction.sin())
    }

    fn sigma_c(&self) -> f64 {
        2.0 * self.cohesion * self.friction.cos() / (1.0 - self.friction.sin())
    }

    /// Plastic radius Rp, m (the hole radius when the rock stays elastic).
    pub fn plastic_radius(&self) -> f64 {
        let (kp, q) = (self.kp(), self.sigma_c() / (self.kp() - 1.0));
        let rp =
            self.radius * (2.0 / (kp + 1.0) * (self.p0 + q) / (self.pi + q)).powf(1.0 / (kp - 1.0));
        rp.max(self.radius)
    }

    /// Radial and hoop stress at radius r, Pa (tension positive).
    pub fn stress(&self, r: f64) -> (f64, f64) {
        let (kp, sc) = (self.kp(), self.sigma_c());
        let q = sc / (kp - 1.0);
        let rp = self.plastic_radius();
        if r < rp {
            let f = (self.pi + q) * (r / self.radius).powf(kp - 1.0);
            (-(f - q), -(kp * f - q))
        } else {
            let pe = if rp > self.radius {
                (2.0 * self.p0 - sc) / (kp + 1.0)
            } else {
                self.pi
            };
            elastic_zone_stress(self.p0, (pe, rp), r)
        }
    }

    /// Radial displacement of the wall, m (negative: inward), from the compatibility ODE above.
    pub fn wall_displacement(&self) -> f64 {
        let elastic = ElasticStrain {
            p0: self.p0,
            shear: self.shear,
            poisson: self.poisson,
        };
        wall_of(
            (self.radius, self.plastic_radius()),
            &elastic,
            self.dilation,
            |r| self.stress(r),
        )
    }
}

/// (σr, σθ) at r ≥ Rp (Pa, tension positive) in the elastic zone around a hole's plastic zone of
/// radius `rp` whose boundary carries the radial pressure `pe` (compression positive) under the
/// in-situ pressure `p0`: Lamé's σr, σθ = −p0 ± (p0 − pe)(Rp/r)².
pub fn elastic_zone_stress(p0: f64, (pe, rp): (f64, f64), r: f64) -> (f64, f64) {
    let k = (p0 - pe) * (rp / r).powi(2);
    (-p0 + k, -p0 - k)
}

/// The wall's radial displacement u(a), m (negative: inward), of a hole of radius a plastic out
/// to Rp (`(a, rp)`) whose closed-form stresses (Pa, tension positive) are `stress(r)`: the
/// elastic zone's u(Rp) = −(p0 − pe) Rp/(2G), pe = −σr(Rp), then in to the wall by the flow
/// rule's compatibility with the elastic strains (`wall_by_flow`, Nψ of `dilation`, rad).
pub fn wall_of(
    (radius, rp): (f64, f64),
    elastic: &ElasticStrain,
    dilation: f64,
    stress: impl Fn(f64) -> (f64, f64),
) -> f64 {
    let (sr_e, _) = stress(rp);
    let u_rp = -(elastic.p0 + sr_e) * rp / (2.0 * elastic.shear);
    if rp <= radius {
        return u_rp;
    }
    let n_psi = (1.0 + dilation.sin()) / (1.0 - dilation.sin());
    wall_by_flow(radius, rp, u_rp, n_psi, |r| elastic.of(stress(r)))
}

/// The plane-strain elastic strains of a stress change from the hydrostatic −p0.
pub struct ElasticStrain {
    /// In-situ pressure (compression positive), Pa.
    pub p0: f64,
    /// Shear modulus, Pa.
    pub shear: f64,
    pub poisson: f64,
}

impl ElasticStrain {
    /// (ε_r, ε_θ) of the stresses (σr, σθ) (Pa, tension positive).
    pub fn of(&self, (sr, st): (f64, f64)) -> (f64, f64) {
        let nu = self.poisson;
        let (dr, dt) = (sr + self.p0, st + self.p0);
        let k = 1.0 / (2.0 * self.shear);
        (
            k * ((1.0 - nu) * dr - nu * dt),
            k * ((1.0 - nu) * dt - nu * dr),
        )
    }
}

/// The wall's radial displacement u(a), m (negative: inward), of a hole of `radius` a whose
/// plastic zone reaches `rp` with u(Rp) = `u_rp`: the flow rule ε_r^p = −Nψ ε_θ^p (`n_psi`) and the
/// elastic strains `elastic(r)` (ε_r^e, ε_θ^e) make du/dr + Nψ u/r = ε_r^e + Nψ ε_θ^e on
/// a ≤ r ≤ Rp, a linear ODE integrated by RK4 on 20 000 steps (to round-off).
pub fn wall_by_flow(
    radius: f64,
    rp: f64,
    u_rp: f64,
    n_psi: f64,
    elastic: impl Fn(f64) -> (f64, f64),
) -> f64 {
    let du = |r: f64, u: f64| {
        let (er, et) = elastic(r);
        er + n_psi * et - n_psi * u / r
    };
    let steps = 20_000;
    let h = (radius - rp) / steps as f64;
    let (mut r, mut u) = (rp, u_rp);
    for _ in 0..steps {
        let k1 = du(r, u);
        let k2 = du(r + 0.5 * h, u + 0.5 * h * k1);
        let k3 = du(r + 0.5 * h, u + 0.5 * h * k2);
        let k4 = du(r + h, u + h * k3);
        u += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        r += h;
    }
    u
}

/// Rock and load of one Salençon case (the validation's own: c = 5 MPa, φ = 30°, ψ = 0, ν = 0.25,
/// p0 = 30 MPa, E = 10 GPa; the sweep varies them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rock {
    /// Cohesion c, Pa.
    pub cohesion: f64,
    /// Friction angle φ, degrees.
    pub friction_deg: f64,
    /// Dilation angle ψ, degrees.
    pub dilation_deg: f64,
    /// Young's modulus, Pa.
    pub young: f64,
    /// Poisson's ratio.
    pub poisson: f64,
    /// In-situ pressure p0 (compression positive), Pa.
    pub p0: f64,
    /// `zoning.mixed`.
    pub mixed: bool,
}

/// The rock of issue 13's report (c = 1 MPa, φ = 25°, ψ = 0, E = 10 GPa, ν = 0.3, p0 = 15 MPa,
/// plain zones): a plastic zone almost three hole radii deep.
pub const WEAK_ROCK: Rock = Rock {
    cohesion: 1e6,
    friction_deg: 25.0,
    dilation_deg: 0.0,
    young: 10e9,
    poisson: 0.3,
    p0: 15e6,
    mixed: false,
};

impl Rock {
    /// The shipped case's rock and load.
    pub const SHIPPED: Rock = Rock {
        cohesion: 5e6,
        friction_deg: 30.0,
        dilation_deg: 0.0,
        young: 10e9,
        poisson: 0.25,
        p0: 30e6,
        mixed: false,
    };
}

/// The shipped Kirsch geometry (a = 1 m in a 40 m square, graded zoning scaled by `factor`) in
/// Mohr–Coulomb `rock` under its p0, with a support pressure `pi` (Pa) on the wall.
pub fn scene(kirsch: &Scene, factor: f64, pi: f64, rock: &Rock) -> (Scene, Salencon) {
    let mut s = scaled(kirsch, factor);
    s.name = "salencon".into();
    s.zoning.mixed = rock.mixed;
    let m = s
        .materials
        .get_mut(&s.region.material)
        .expect("region material");
    m.law = ZoneLawKind::MohrCoulomb;
    m.cohesion = Some(rock.cohesion);
    m.friction = Some(rock.friction_deg);
    m.dilation = rock.dilation_deg;
    m.young = rock.young;
    m.poisson = rock.poisson;
    let (young, poisson) = (m.young, m.poisson);
    let p0 = rock.p0;
    s.in_situ.sxx = -p0;
    s.in_situ.syy = -p0;
    s.in_situ.szz = Some(-p0);
    s.solve.ratio = 1e-6;
    s.solve.max_cycles = 400_000;
    // The implicit solve's initial-stiffness iterations, where a method asks for it.
    s.solve.max_iterations = 2_000;
    support_wall(&mut s, pi);
    let radius = s.excavations[0]
        .circle
        .as_ref()
        .expect("circular hole")
        .radius;
    let closed = Salencon {
        radius,
        p0,
        pi,
        cohesion: rock.cohesion,
        friction: rock.friction_deg.to_radians(),
        dilation: rock.dilation_deg.to_radians(),
        shear: young / (2.0 * (1.0 + poisson)),
        poisson,
    };
    (s, closed)
}

/// Solve and compare: `plastic_radius` (radius of a circle with the hole's area plus the yielded
/// zones' area, against Rp), `stress_l2` (area-weighted L2 of (σr, σθ) over zones with centroid
/// r ≤ 3Rp, relative to the exact norm there) and `wall_displacement` (mean radial displacement of
/// the wall nodes against u(a)).
pub fn run(kirsch: &Scene, factor: f64, pi: f64) -> anyhow::Result<CaseReport> {
    run_rock(kirsch, factor, pi, &Rock::SHIPPED)
}

/// [`run`] for another rock and load.
pub fn run_rock(kirsch: &Scene, factor: f64, pi: f64, rock: &Rock) -> anyhow::Result<CaseReport> {
    run_rock_by(kirsch, factor, pi, rock, SolveMethod::Explicit)
}

/// [`run_rock`] solved by `method` (`solve.method`); the row's case names it.
pub fn run_rock_by(
    kirsch: &Scene,
    factor: f64,
    pi: f64,
    rock: &Rock,
    method: SolveMethod,
) -> anyhow::Result<CaseReport> {
    Ok(measure(kirsch, factor, pi, rock, 0, method)?.0)
}

/// [`run_rock_by`] along the quasi-static path (the hole's out-of-balance force released slowly:
/// `bundled::quasi_static`); the row's case says so.
pub fn run_rock_slowly_by(
    kirsch: &Scene,
    factor: f64,
    rock: &Rock,
    method: SolveMethod,
) -> anyhow::Result<CaseReport> {
    run_rock_released_by(
        kirsch,
        factor,
        rock,
        method,
        crate::bundled::quasi_static(method),
    )
}

/// [`run_rock_slowly_by`] with the hole's out-of-balance force released as `release` says
/// (`crate::release_gradually`: cycles explicitly, load steps implicitly).
pub fn run_rock_released_by(
    kirsch: &Scene,
    factor: f64,
    rock: &Rock,
    method: SolveMethod,
    release: u64,
) -> anyhow::Result<CaseReport> {
    let mut r = measure(kirsch, factor, 0.0, rock, release, method)?.0;
    r.case = r.case.replacen("Salençon", "Salençon slowly", 1);
    Ok(r)
}

/// [`run_rock`] with the hole's out-of-balance forces released over `ramp` cycles
/// (`solve.ramp`: the quasi-static path of a slow excavation).
pub fn run_rock_ramped(
    kirsch: &Scene,
    factor: f64,
    rock: &Rock,
    ramp: u64,
) -> anyhow::Result<CaseReport> {
    Ok(measure(kirsch, factor, 0.0, rock, ramp, SolveMethod::Explicit)?.0)
}

/// [`run_rock`] by `method`, the hole's out-of-balance force released as `release` says
/// (`crate::release_gradually`), with the wall displacement over the closed form's, u_h / u.
fn measure(
    kirsch: &Scene,
    factor: f64,
    pi: f64,
    rock: &Rock,
    release: u64,
    method: SolveMethod,
) -> anyhow::Result<(CaseReport, f64)> {
    let (sc, exact) = scene(kirsch, factor, pi, rock);
    let rp = exact.plastic_radius();
    let case = if *rock == Rock::SHIPPED {
        format!(
            "Salençon: hole in Mohr–Coulomb rock, p0 = 30 MPa, pi = {} MPa, Rp = {rp:.3} m (×{factor}){}",
            pi / 1e6,
            crate::method_suffix(method)
        )
    } else {
        format!(
            "Salençon c = {} MPa, φ = {}°, ψ = {}°, ν = {}, p0 = {} MPa{}, Rp = {rp:.3} m (×{factor}){}",
            rock.cohesion / 1e6,
            rock.friction_deg,
            rock.dilation_deg,
            rock.poisson,
            rock.p0 / 1e6,
            if rock.mixed { ", mixed" } else { "" },
            crate::method_suffix(method)
        )
    };
    measure_hole(sc, &exact, release, method, case)
}

/// An axisymmetric hole's closed form, what [`measure_hole`] compares a run with.
pub trait ClosedHole {
    /// Plastic radius, m.
    fn plastic_radius(&self) -> f64;
    /// Radial and hoop stress at radius r, Pa (tension positive).
    fn stress(&self, r: f64) -> (f64, f64);
    /// Radial displacement of the wall, m (negative: inward).
    fn wall_displacement(&self) -> f64;
}

impl ClosedHole for Salencon {
    fn plastic_radius(&self) -> f64 {
        Salencon::plastic_radius(self)
    }
    fn stress(&self, r: f64) -> (f64, f64) {
        Salencon::stress(self, r)
    }
    fn wall_displacement(&self) -> f64 {
        Salencon::wall_displacement(self)
    }
}

/// Solve the hole scene `sc` by `method` (its out-of-balance force released as `release` says,
/// `crate::release_gradually`) and measure it against `exact` ([`measure_hole_along`]).
pub fn measure_hole(
    sc: Scene,
    exact: &dyn ClosedHole,
    release: u64,
    method: SolveMethod,
    case: String,
) -> anyhow::Result<(CaseReport, f64)> {
    measure_hole_along(sc, exact, &[Leg::new(method, release)], case)
}

/// One solve of a path (`measure_hole_along`): its method, its release
/// (`crate::release_gradually`) and, if given, its own ratio instead of the scene's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Leg {
    pub method: SolveMethod,
    pub release: u64,
    pub ratio: Option<f64>,
}

impl Leg {
    /// A solve to the scene's ratio.
    pub fn new(method: SolveMethod, release: u64) -> Leg {
        Leg {
            method,
            release,
            ratio: None,
        }
    }
}

/// Solve the hole scene `sc` along `path`, one solve after the other from where the last left
/// the model (each by its method to its ratio, its out-of-balance force released as its release
/// says, `crate::release_gradually`), and compare it with `exact`: `plastic_radius` (radius of a circle
/// with the hole's area plus the yielded zones' area, against Rp), `stress_l2` (area-weighted L2
/// of (σr, σθ) over zones with centroid r ≤ 3Rp, relative to the exact norm there),
/// `wall_displacement` (mean radial displacement of the wall nodes against u(a)) and
/// `wall_spread` (the wall nodes' largest minus smallest radial displacement over the mean: 0 for
/// the axisymmetric answer, large where the plastic zone localizes on one side); the row named
/// `case`, with the wall displacement over the closed form's, u_h / u.
pub fn measure_hole_along(
    mut sc: Scene,
    exact: &dyn ClosedHole,
    path: &[Leg],
    case: String,
) -> anyhow::Result<(CaseReport, f64)> {
    let start = Instant::now();
    let leg = |l: &Leg| {
        let mut spec = sc.solve.clone();
        spec.method = l.method;
        spec.ratio = l.ratio.unwrap_or(spec.ratio);
        crate::release_gradually(&mut spec, l.release);
        spec
    };
    let specs: Vec<_> = path.iter().map(leg).collect();
    // The model is set up for the first solve, as a scene with that solve would be.
    sc.solve = specs.first().cloned().unwrap_or(sc.solve);
    let mut b = setup(&sc)?;
    let (mut cycles, mut implicit) = (0, None);
    for spec in &specs {
        let (n, cost) = crate::settle_by_method(&mut b.model, spec, "hole case")?;
        cycles += n;
        implicit = implicit.or(cost);
    }
    let (m, rp) = (&b.model, exact.plastic_radius());
    let z = &m.zones;
    let hole_area = b.plan.boundary.domain.holes[0].polygon.signed_area().abs();
    let mut yielded = 0.0;
    let (mut num, mut den, mut h2, mut count) = (0.0, 0.0, 0.0, 0.0);
    for i in 0..z.len() {
        if z.state[i] & (SHEAR_NOW | SHEAR_PAST) != 0 {
            yielded += z.area[i];
        }
        let c = z.centroid(i, &m.nodes.pos);
        let r = c[0].hypot(c[1]);
        if r > 3.0 * rp {
            continue;
        }
        let (cs, sn) = (c[0] / r, c[1] / r);
        let s = z.stress[i];
        let sr = s[0] * cs * cs + s[1] * sn * sn + 2.0 * s[3] * cs * sn;
        let st = s[0] * sn * sn + s[1] * cs * cs - 2.0 * s[3] * cs * sn;
        let (er, et) = exact.stress(r);
        num += z.area[i] * ((sr - er).powi(2) + (st - et).powi(2));
        den += z.area[i] * (er * er + et * et);
        h2 += z.area[i];
        count += 1.0;
    }
    let rp_h = ((hole_area + yielded) / std::f64::consts::PI).sqrt();
    let wall = b
        .plan
        .boundary
        .part_nodes
        .get(&sc.excavations[0].name)
        .ok_or_else(|| anyhow::anyhow!("no wall nodes"))?;
    let u_wall = crate::mean_radial_displacement(m, wall);
    let (low, high) = crate::radial_displacements(m, wall)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), u| {
            (l.min(u), h.max(u))
        });
    let u_exact = exact.wall_displacement();
    let h = (h2 / count).sqrt();
    let report = CaseReport::new(
        case,
        z.len(),
        cycles,
        start.elapsed().as_secs_f64(),
        Some(h),
        &[
            ("plastic_radius", (rp_h - rp).abs() / rp),
            ("stress_l2", (num / den).sqrt()),
            (
                "wall_displacement",
                (u_wall - u_exact).abs() / u_exact.abs(),
            ),
            ("wall_spread", (high - low) / u_wall.abs()),
        ],
    )
    .with_implicit(implicit);
    Ok((report, u_wall / u_exact))
}

/// One row of the Salençon sweep: a rock and mesh, plain and mixed, against the closed form and the
/// one-dimensional axisymmetric reference (`crate::axisymmetric`).
#[derive(Debug, Clone, serde::Serialize)]
pub struct SweepRow {
    pub rock: String,
    /// Zone size factor of the shipped Kirsch mesh (< 1 finer).
    pub factor: f64,
    pub zones: usize,
    /// Closure u_h / u − 1 at the wall, plain and mixed (signed: positive is too much closure).
    pub closure_plain: f64,
    pub closure_mixed: f64,
    /// The same along the closed form's quasi-static path: solved implicitly in
    /// `bundled::QUASI_STATIC_STEPS` load steps (released at once, the explicit solve overshoots
    /// dynamically).
    pub slowly_plain: f64,
    pub slowly_mixed: f64,
    /// Plastic radius error |Rp_h − Rp| / Rp, plain and mixed.
    pub radius_plain: f64,
    pub radius_mixed: f64,
    pub cycles_plain: u64,
    pub cycles_mixed: u64,
    pub seconds_plain: f64,
    pub seconds_mixed: f64,
    /// The axisymmetric reference's wall displacement over the closed form's, minus 1.
    pub reference_vs_closed: f64,
    /// Whether the reference yields out of plane (σzz the major or minor stress: outside the closed
    /// form's assumption).
    pub out_of_plane: bool,
}

/// Signed closure error u_h / u − 1 and plastic radius error of one run (see `run`), with its cost.
fn closure_and_radius(
    kirsch: &Scene,
    factor: f64,
    rock: &Rock,
) -> anyhow::Result<(f64, f64, CaseReport)> {
    let (report, ratio) = measure(kirsch, factor, 0.0, rock, 0, SolveMethod::Explicit)?;
    let radius = report.errors["plastic_radius"];
    Ok((ratio - 1.0, radius, report))
}

/// Signed closure error u_h / u − 1 of `rock` along the quasi-static path: the implicit solve in
/// `bundled::QUASI_STATIC_STEPS` load steps.
fn quasi_static_closure(kirsch: &Scene, factor: f64, rock: &Rock) -> anyhow::Result<f64> {
    let steps = crate::bundled::QUASI_STATIC_STEPS;
    Ok(measure(kirsch, factor, 0.0, rock, steps, SolveMethod::Implicit)?.1 - 1.0)
}

/// The sweep: each rock at each mesh factor, plain and mixed, on the graded zoning as written
/// (`zoning.plastic_depth` 0 at every factor): a refinement study of issue 13, whose ×1 must be
/// coarser than its ×0.5 (refined through its plastic zone, the default, ×1 is as fine as ×0.5 at
/// the wall). The default zoning's rows are the plastic-zoning section's.
pub fn sweep(kirsch: &Scene, rocks: &[Rock], factors: &[f64]) -> anyhow::Result<Vec<SweepRow>> {
    let mut written = kirsch.clone();
    written.zoning.plastic_depth = adit::scene::PlasticDepth::OFF;
    let kirsch = &written;
    let mut rows = Vec::new();
    for rock in rocks {
        let reference = crate::axisymmetric::solve(&crate::axisymmetric::Hole {
            radius: 1.0,
            young: rock.young,
            poisson: rock.poisson,
            cohesion: rock.cohesion,
            friction_deg: rock.friction_deg,
            dilation_deg: rock.dilation_deg,
            p0: rock.p0,
            pi: 0.0,
        })?;
        let closed = scene(kirsch, 1.0, 0.0, rock).1;
        let (plain_rock, mixed_rock) = (
            Rock {
                mixed: false,
                ..*rock
            },
            Rock {
                mixed: true,
                ..*rock
            },
        );
        for &factor in factors {
            let (cp, rp, plain) = closure_and_radius(kirsch, factor, &plain_rock)?;
            let (cm, rm, mixed) = closure_and_radius(kirsch, factor, &mixed_rock)?;
            let slowly_plain = quasi_static_closure(kirsch, factor, &plain_rock)?;
            let slowly_mixed = quasi_static_closure(kirsch, factor, &mixed_rock)?;
            rows.push(SweepRow {
                rock: format!(
                    "c = {} MPa, φ = {}°, ψ = {}°, ν = {}, p0 = {} MPa (Rp = {:.2} a)",
                    rock.cohesion / 1e6,
                    rock.friction_deg,
                    rock.dilation_deg,
                    rock.poisson,
                    rock.p0 / 1e6,
                    closed.plastic_radius() / closed.radius
                ),
                factor,
                zones: plain.zones,
                closure_plain: cp,
                closure_mixed: cm,
                slowly_plain,
                slowly_mixed,
                radius_plain: rp,
                radius_mixed: rm,
                cycles_plain: plain.cycles,
                cycles_mixed: mixed.cycles,
                seconds_plain: plain.wall_s,
                seconds_mixed: mixed.wall_s,
                reference_vs_closed: reference.wall_displacement / closed.wall_displacement() - 1.0,
                out_of_plane: reference.out_of_plane_yield,
            });
        }
    }
    Ok(rows)
}

/// The rocks of a sweep that miss issue 13's bars for mixed zones, each with the bar it misses: on
/// its finest mesh closure and plastic radius within 3 %; closure error no larger on the finest mesh
/// than on the coarsest; closure error never more than 1 point above plain zones' on any mesh;
/// the closure along the quasi-static path within 3 % on the finest mesh and within a point of
/// plain zones' there too.
pub fn sweep_bars_missed(rows: &[SweepRow]) -> Vec<String> {
    let mut missed = Vec::new();
    let mut rocks: Vec<&str> = rows.iter().map(|r| r.rock.as_str()).collect();
    rocks.dedup();
    for rock in rocks {
        let of: Vec<&SweepRow> = rows.iter().filter(|r| r.rock == rock).collect();
        let by_size = |a: &&&SweepRow, b: &&&SweepRow| a.factor.total_cmp(&b.factor);
        let (Some(finest), Some(coarsest)) = (of.iter().min_by(by_size), of.iter().max_by(by_size))
        else {
            continue;
        };
        let mut bars = Vec::new();
        if finest.closure_mixed.abs() > 0.03 || finest.radius_mixed > 0.03 {
            bars.push("within 3 % on the finest mesh");
        }
        if finest.closure_mixed.abs() > coarsest.closure_mixed.abs() {
            bars.push("falling with refinement");
        }
        if of
            .iter()
            .any(|r| r.closure_mixed.abs() > r.closure_plain.abs() + 0.01)
        {
            bars.push("within a point of plain zones");
        }
        if finest.slowly_mixed.abs() > 0.03 {
            bars.push("quasi-static within 3 % on the finest mesh");
        }
        if of
            .iter()
            .any(|r| r.slowly_mixed.abs() > r.slowly_plain.abs() + 0.01)
        {
            bars.push("quasi-static within a point of plain zones");
        }
        if !bars.is_empty() {
            missed.push(format!("{rock} ({})", bars.join(", ")));
        }
    }
    missed
}

/// One point of a ground reaction curve: support pressure (Pa), wall displacement computed and
/// closed-form (m, negative inward).
#[derive(Debug, Clone, Copy, serde::Serialize)]
pub struct GrcPoint {
    pub pressure: f64,
    pub computed: f64,
    pub exact: f64,
}

/// The ground reaction curve (convergence–confinement) through scene stages: the hole starts
/// filled with rock; the first stage excavates it leaving the full in-situ traction on the wall
/// (`support_fraction` 1: nothing moves), the next ones lower the support to `fractions` of it
/// (descending to 0), each solved to equilibrium; the mean radial wall displacement against
/// Salençon's u(pi). Returns the curve and a report whose `grc` error is the largest |u_h − u|
/// over the curve relative to |u(0)|.
pub fn ground_reaction(
    kirsch: &Scene,
    factor: f64,
    fractions: &[f64],
) -> anyhow::Result<(Vec<GrcPoint>, CaseReport)> {
    ground_reaction_by(kirsch, factor, fractions, SolveMethod::Explicit, 0)
}

/// [`ground_reaction`] with every stage solved by `method` (`solve.method`), its out-of-balance
/// force released as `release` says (`crate::release_gradually`; 0: at once); the row's case
/// names the method, and says `slowly` when `release` > 0.
pub fn ground_reaction_by(
    kirsch: &Scene,
    factor: f64,
    fractions: &[f64],
    method: SolveMethod,
    release: u64,
) -> anyhow::Result<(Vec<GrcPoint>, CaseReport)> {
    let start = Instant::now();
    let (mut sc, exact) = scene(kirsch, factor, 0.0, &Rock::SHIPPED);
    let hole = sc.excavations[0].name.clone();
    let stage = |name: String, excavate: Vec<String>, support_fraction: f64| Stage {
        name,
        excavate,
        support_fraction,
        ..Default::default()
    };
    sc.stages = std::iter::once(stage("excavate, supported".into(), vec![hole.clone()], 1.0))
        .chain(
            fractions
                .iter()
                .map(|&f| stage(format!("support {f}"), vec![], f)),
        )
        .collect();
    let mut b = setup(&sc)?;
    let p0 = exact.p0;
    // The wall nodes of the rock that stays (the fill's own wall nodes go with it).
    let fill = |n: u32| b.plan.fill[b.model.blocks.block_of_node(n)] != adit::setup::NOT_FILL;
    let wall: Vec<u32> = b.plan.boundary.part_nodes[&hole]
        .iter()
        .copied()
        .filter(|&n| !fill(n))
        .collect();
    let mean_u = |m: &adit::model::Model| crate::mean_radial_displacement(m, &wall);
    let adit::setup::Setup { model, plan, .. } = &mut b;
    let mut staging = Staging::new(plan);
    let (mut curve, mut cycles, mut implicit) = (Vec::new(), 0, None::<Cost>);
    for st in &plan.stages {
        staging.apply(st, model, plan);
        let mut spec = SolveSpec {
            method,
            ..st.solve.clone()
        };
        crate::release_gradually(&mut spec, release);
        let what = format!("ground reaction, stage {}", st.name);
        let (stage_cycles, cost) = crate::settle_by_method(model, &spec, &what)?;
        implicit = match (implicit, cost) {
            (Some(a), Some(b)) => Some(a.plus(b)),
            (a, b) => a.or(b),
        };
        cycles += stage_cycles;
        let pi = st.support_fraction * p0;
        curve.push(GrcPoint {
            pressure: pi,
            computed: mean_u(model),
            exact: Salencon { pi, ..exact }.wall_displacement(),
        });
    }
    let scale = curve.iter().map(|p| p.exact.abs()).fold(0.0, f64::max);
    let worst = curve
        .iter()
        .map(|p| (p.computed - p.exact).abs() / scale)
        .fold(0.0, f64::max);
    let report = CaseReport::new(
        format!(
            "Salençon ground reaction curve{}, {} support pressures (×{factor}){}",
            if release > 0 { " slowly" } else { "" },
            fractions.len(),
            crate::method_suffix(method)
        ),
        b.model.zones.len(),
        cycles,
        start.elapsed().as_secs_f64(),
        None,
        &[("grc", worst)],
    )
    .with_implicit(implicit);
    Ok((curve, report))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed form is continuous at Rp and meets the wall condition σr(a) = −pi.
    #[test]
    fn closed_form_is_consistent() {
        let (_, s) = scene(&crate::shipped_kirsch().unwrap(), 1.0, 0.0, &Rock::SHIPPED);
        let rp = s.plastic_radius();
        assert!(rp > 1.4 && rp < 1.6, "{rp}");
        let (a, b) = (s.stress(rp * (1.0 - 1e-9)), s.stress(rp * (1.0 + 1e-9)));
        assert!(
            (a.0 - b.0).abs() < 1.0 && (a.1 - b.1).abs() < 1.0,
            "{a:?} {b:?}"
        );
        assert!(s.stress(s.radius).0.abs() < 1e-6);
        // Without yield (p0 below the strength) the wall moves as in elasticity: −p0 a / (2G).
        let elastic = Salencon { p0: 5e6, ..s };
        let u = elastic.wall_displacement();
        assert!((u + 5e6 * s.radius / (2.0 * s.shear)).abs() < 1e-12, "{u}");
        // Yield makes the wall move more than the elastic −p0 a/(2G).
        assert!(s.wall_displacement() < -s.p0 * s.radius / (2.0 * s.shear));
    }

    /// Coarse twin of the ground reaction curve: elastic down to the critical pressure, plastic
    /// below. Then the same stages solved implicitly, against the explicit solve along the same
    /// path: each stage's support lowered slowly (over 4 000 cycles). Released at once, each
    /// explicit stage overshoots dynamically and closes the wall further (1.9 % from Salençon on
    /// this coarse mesh against 5.05 % slowly); the implicit stages, whose zones return from the
    /// stage's start, follow the slow path (measured 5.03 %).
    #[test]
    fn ground_reaction_curve_follows_salencon() {
        let kirsch = crate::shipped_kirsch().unwrap();
        let fractions = [0.6, 0.3, 0.1, 0.0];
        let (curve, r) = ground_reaction(&kirsch, 2.0, &fractions).unwrap();
        for p in &curve {
            eprintln!("{p:?}");
        }
        assert!(r.errors["grc"] < 0.05, "{r:?}");
        let by = |method, release| {
            ground_reaction_by(&kirsch, 2.0, &fractions, method, release)
                .unwrap()
                .1
        };
        let slow = by(SolveMethod::Explicit, 4000);
        let i = by(SolveMethod::Implicit, 0);
        assert!(i.errors["grc"] < 0.06, "{i:?}");
        assert!(
            (i.errors["grc"] - slow.errors["grc"]).abs() < 0.005,
            "{i:?} {slow:?}"
        );
    }

    /// Issue 17's nonlinear bar on rocks no case was tuned to, on the coarse mesh: released
    /// slowly (explicit over `bundled::QUASI_STATIC_RAMP` cycles, implicit in
    /// `bundled::QUASI_STATIC_STEPS` load steps), each error of the implicit solve within 0.5
    /// percentage points of the explicit one's or below it. Measured: a dilatant stiff rock
    /// (ψ = 20°, ν = 0.35) +0.05 pp at the wall, a non-dilatant one +0.003 pp (on the shipped
    /// mesh +0.05 and +0.12; a weak mixed rock, c = 0.5 MPa, φ = 20°, 1.2 pp nearer the closed
    /// form's plastic radius on this mesh).
    #[test]
    fn the_implicit_solve_follows_the_slow_explicit_path_on_other_rocks() {
        let kirsch = crate::shipped_kirsch().unwrap();
        let rocks = [
            Rock {
                cohesion: 3e6,
                friction_deg: 40.0,
                dilation_deg: 20.0,
                young: 20e9,
                poisson: 0.35,
                p0: 40e6,
                mixed: false,
            },
            Rock {
                cohesion: 4e6,
                friction_deg: 28.0,
                dilation_deg: 0.0,
                young: 30e9,
                poisson: 0.3,
                p0: 35e6,
                mixed: false,
            },
        ];
        for rock in rocks {
            let e = run_rock_slowly_by(&kirsch, 2.0, &rock, SolveMethod::Explicit).unwrap();
            let i = run_rock_slowly_by(&kirsch, 2.0, &rock, SolveMethod::Implicit).unwrap();
            for k in ["plastic_radius", "stress_l2", "wall_displacement"] {
                assert!(i.errors[k] - e.errors[k] < 0.005, "{k}: {i:?} {e:?}");
            }
        }
    }

    /// Coarse twins of the sweep. On the shipped mesh at ν = 0.45, its plastic zone refined (the
    /// default), plain triangles lock (−5.9 %; −15 % as written) and mixed ones must not
    /// (+1.0 %; −4.7 % as written); on zones twice the shipped size at ν = 0.3 mixed ones must
    /// stay within a point of plain ones (−16 % both: the mesh is coarse). Before the stabilization
    /// (`cycle::mixed`) mixed zones closed 18 % too much on the shipped mesh at ν = 0.3.
    #[test]
    fn mixed_zones_meet_salencon_where_plain_ones_lock() {
        let kirsch = crate::shipped_kirsch().unwrap();
        for (poisson, factor) in [(0.45, 1.0), (0.3, 2.0)] {
            let rock = Rock {
                poisson,
                ..WEAK_ROCK
            };
            let (plain, _, _) = closure_and_radius(&kirsch, factor, &rock).unwrap();
            let mixed_rock = Rock {
                mixed: true,
                ..rock
            };
            let (mixed, radius, r) = closure_and_radius(&kirsch, factor, &mixed_rock).unwrap();
            eprintln!("ν = {poisson}: plain {plain:+.4}, mixed {mixed:+.4}, {r:?}");
            assert!(
                mixed.abs() <= plain.abs() + 0.01,
                "ν = {poisson}: mixed {mixed} vs plain {plain}"
            );
            if poisson == 0.45 {
                assert!(plain < -0.04, "plain triangles lock at ν = 0.45: {plain}");
                assert!(mixed.abs() < 0.03, "mixed closure error {mixed}");
                assert!(radius < 0.08, "{r:?}");
            }
        }
    }

    /// Dilatant mixed zones converge and close within a point of plain ones (ψ = 10°, zones twice
    /// the shipped size); with associated flow (ψ = φ = 30°) too. Left local, the plastic change of
    /// mean stress ran them away within 500 cycles.
    #[test]
    fn dilatant_mixed_zones_converge() {
        let kirsch = crate::shipped_kirsch().unwrap();
        let rock = Rock {
            dilation_deg: 10.0,
            ..WEAK_ROCK
        };
        let (plain, _, _) = closure_and_radius(&kirsch, 2.0, &rock).unwrap();
        let mixed_rock = Rock {
            mixed: true,
            ..rock
        };
        let (mixed, _, r) = closure_and_radius(&kirsch, 2.0, &mixed_rock).unwrap();
        eprintln!("ψ = 10°: plain {plain:+.4}, mixed {mixed:+.4}, {r:?}");
        assert!(
            mixed.abs() <= plain.abs() + 0.01,
            "mixed {mixed} vs plain {plain}"
        );
        let associated = Rock {
            cohesion: 3e6,
            friction_deg: 30.0,
            dilation_deg: 30.0,
            young: 10e9,
            poisson: 0.3,
            p0: 10e6,
            mixed: true,
        };
        let r = run_rock(&kirsch, 2.0, 0.0, &associated).unwrap();
        eprintln!("{r:?}");
        assert!(r.errors["plastic_radius"] < 0.1, "{r:?}");
    }

    /// Coarse twin (zones twice the shipped size), without and with a support pressure.
    #[test]
    fn plastic_zone_matches_salencon() {
        for pi in [0.0, 2e6] {
            let r = run(&crate::shipped_kirsch().unwrap(), 2.0, pi).unwrap();
            eprintln!("{r:?}");
            assert!(r.errors["plastic_radius"] < 0.05, "{r:?}");
            assert!(r.errors["stress_l2"] < 0.05, "{r:?}");
            assert!(r.errors["wall_displacement"] < 0.05, "{r:?}");
        }
    }
}
