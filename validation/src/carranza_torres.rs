//! Circular hole in generalized Hoek–Brown rock under hydrostatic stress p0 with an internal
//! pressure pi (Carranza-Torres, "Elasto-plastic solution of tunnel problems using the generalized
//! form of the Hoek–Brown failure criterion", IJRMMS 41 suppl. 1, 2004). Pressures positive in
//! compression, q(σ) = σci (mb σ/σci + s)^a the strength σθ − σr at a radial stress σ:
//!
//!   critical pressure  pcr:  2 (p0 − pcr) = q(pcr)  (the elastic zone's wall meets the yield
//!                      surface there: σθ = 2p0 − σr);
//!   plastic zone       dσr/d(ln r) = q(σr), σr(a) = pi, so ln(Rp/a) = ∫_pi^pcr dσ / q(σ);
//!                      (elastic–brittle–plastic rock: q of the residual constants here, the
//!                      peak's in pcr, the strength dropping at once at Rp);
//!   elastic zone       σr = p0 − (p0 − pcr)(Rp/r)²,  σθ = p0 + (p0 − pcr)(Rp/r)².
//!
//! Carranza-Torres writes these in scaled stresses and, for a ≠ 1/2, integrates them numerically;
//! here the integral is Simpson's rule on 20 000 panels and the plastic zone's radial stress a
//! table of the same ODE by RK4 in ln r (interpolated linearly: to about 1e-9 of p0). The wall's
//! radial displacement follows from the flow rule's compatibility with the elastic strains
//! (`salencon::wall_of`, as for Mohr–Coulomb), from u(Rp) = −(p0 − pcr) Rp / (2G).

use adit::Scene;
use adit::scene::{SolveMethod, ZoneLawKind};

use crate::kirsch_case::{scaled, support_wall};
use crate::report::CaseReport;
use crate::salencon::{
    ClosedHole, ElasticStrain, Leg, elastic_zone_stress, measure_hole, measure_hole_along, wall_of,
};

/// Steps of the quadrature and of the radial-stress table.
const STEPS: usize = 20_000;

/// The closed form of one case.
#[derive(Debug, Clone)]
pub struct CarranzaTorres {
    /// Hole radius a, m.
    pub radius: f64,
    /// In-situ and internal pressures (compression positive), Pa.
    pub p0: f64,
    pub pi: f64,
    /// σci, Pa, and mb, s, a.
    pub sigma_ci: f64,
    pub mb: f64,
    pub s: f64,
    pub a: f64,
    /// Dilation angle ψ, rad.
    pub dilation: f64,
    /// Shear modulus, Pa, and Poisson's ratio.
    pub shear: f64,
    pub poisson: f64,
    /// The residual rock's mb, s and a: the plastic zone's strength (the peak's unless
    /// `with_residual` gives others: the elastic–brittle–plastic rock).
    pub residual: (f64, f64, f64),
    /// pcr (Pa) and Rp (m), computed once by `new`.
    pcr: f64,
    rp: f64,
    /// σr (compression positive, Pa) at ln(r/a) = k ln(Rp/a)/STEPS, k = 0..=STEPS.
    table: Vec<f64>,
}

impl CarranzaTorres {
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        radius: f64,
        (p0, pi): (f64, f64),
        sigma_ci: f64,
        (mb, s, a): (f64, f64, f64),
        dilation: f64,
        shear: f64,
        poisson: f64,
    ) -> CarranzaTorres {
        let mut c = CarranzaTorres {
            radius,
            p0,
            pi,
            sigma_ci,
            mb,
            s,
            a,
            dilation,
            shear,
            poisson,
            residual: (mb, s, a),
            pcr: 0.0,
            rp: radius,
            table: Vec::new(),
        };
        c.pcr = c.solve_critical_pressure();
        c.rp = c.solve_plastic_radius();
        c.table = c.radial_table();
        c
    }

    /// The elastic–brittle–plastic rock (Carranza-Torres 2004, his second case): the peak
    /// constants bound the elastic zone (pcr), the residual ones `(mb, s, a)` the plastic zone,
    /// where the strength drops at once at Rp.
    pub fn with_residual(mut self, residual: (f64, f64, f64)) -> CarranzaTorres {
        self.residual = residual;
        self.rp = self.solve_plastic_radius();
        self.table = self.radial_table();
        self
    }

    /// q(σ) = σci (mb σ/σci + s)^a of the peak constants, Pa (0 beyond the apex).
    pub fn strength(&self, sigma: f64) -> f64 {
        self.strength_of((self.mb, self.s, self.a), sigma)
    }

    /// q(σ) of the residual constants, Pa: the plastic zone's strength.
    fn residual_strength(&self, sigma: f64) -> f64 {
        self.strength_of(self.residual, sigma)
    }

    fn strength_of(&self, (mb, s, a): (f64, f64, f64), sigma: f64) -> f64 {
        self.sigma_ci * (mb * sigma / self.sigma_ci + s).max(0.0).powf(a)
    }

    /// pcr, Pa.
    pub fn critical_pressure(&self) -> f64 {
        self.pcr
    }

    /// Plastic radius Rp, m (a when elastic).
    pub fn plastic_radius(&self) -> f64 {
        self.rp
    }

    /// pcr, Pa: the root of 2 (p0 − p) − q(p) between the apex −s σci/mb and p0 (bisection).
    fn solve_critical_pressure(&self) -> f64 {
        let f = |p: f64| 2.0 * (self.p0 - p) - self.strength(p);
        let (mut lo, mut hi) = (-self.s * self.sigma_ci / self.mb, self.p0);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if f(mid) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// Whether the rock yields: the support pressure is below pcr.
    fn yields(&self) -> bool {
        self.pi < self.critical_pressure()
    }

    /// Plastic radius Rp = a exp(∫_pi^pcr dσ / q_res(σ)), m (Simpson's rule); a when elastic.
    fn solve_plastic_radius(&self) -> f64 {
        if !self.yields() {
            return self.radius;
        }
        let (lo, hi) = (self.pi, self.critical_pressure());
        let h = (hi - lo) / STEPS as f64;
        let g = |k: usize| 1.0 / self.residual_strength(lo + k as f64 * h);
        let inner: f64 = (1..STEPS)
            .map(|k| if k % 2 == 1 { 4.0 * g(k) } else { 2.0 * g(k) })
            .sum();
        self.radius * (h / 3.0 * (g(0) + inner + g(STEPS))).exp()
    }

    /// σr through the plastic zone by RK4 in ln r from σr(a) = pi (see `table`).
    fn radial_table(&self) -> Vec<f64> {
        if !self.yields() {
            return Vec::new();
        }
        let h = (self.plastic_radius() / self.radius).ln() / STEPS as f64;
        let mut sigma = self.pi;
        let mut table = Vec::with_capacity(STEPS + 1);
        table.push(sigma);
        for _ in 0..STEPS {
            let k1 = self.residual_strength(sigma);
            let k2 = self.residual_strength(sigma + 0.5 * h * k1);
            let k3 = self.residual_strength(sigma + 0.5 * h * k2);
            let k4 = self.residual_strength(sigma + h * k3);
            sigma += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
            table.push(sigma);
        }
        table
    }

    /// Radial and hoop stress at radius r ≥ a, Pa (tension positive).
    pub fn stress(&self, r: f64) -> (f64, f64) {
        let rp = self.plastic_radius();
        if r < rp && !self.table.is_empty() {
            let x = (r / self.radius).ln() / (rp / self.radius).ln() * STEPS as f64;
            let k = (x.floor() as usize).min(STEPS - 1);
            let w = x - k as f64;
            let sr = (1.0 - w) * self.table[k] + w * self.table[k + 1];
            (-sr, -(sr + self.residual_strength(sr)))
        } else {
            let pe = if self.yields() {
                self.critical_pressure()
            } else {
                self.pi
            };
            elastic_zone_stress(self.p0, (pe, rp), r)
        }
    }

    /// Radial displacement of the wall, m (negative: inward).
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

impl ClosedHole for CarranzaTorres {
    fn plastic_radius(&self) -> f64 {
        CarranzaTorres::plastic_radius(self)
    }
    fn stress(&self, r: f64) -> (f64, f64) {
        CarranzaTorres::stress(self, r)
    }
    fn wall_displacement(&self) -> f64 {
        CarranzaTorres::wall_displacement(self)
    }
}

/// Rock and load of one Hoek–Brown hole.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rock {
    pub gsi: f64,
    pub mi: f64,
    /// σci, Pa.
    pub sigma_ci: f64,
    /// Dilation angle ψ, degrees.
    pub dilation_deg: f64,
    /// Young's modulus, Pa, and Poisson's ratio.
    pub young: f64,
    pub poisson: f64,
    /// In-situ pressure p0 (compression positive), Pa.
    pub p0: f64,
    /// Support pressure pi on the wall (compression positive), Pa; 0 unsupported.
    pub pi: f64,
}

/// Three rock masses of the report (issue 48): good, fair and poor, with their plastic zones
/// from about 1.2 to 2.8 hole radii, one of them dilatant.
pub const ROCKS: [Rock; 3] = [
    Rock {
        gsi: 75.0,
        mi: 25.0,
        sigma_ci: 150e6,
        dilation_deg: 0.0,
        young: 40e9,
        poisson: 0.2,
        p0: 100e6,
        pi: 0.0,
    },
    Rock {
        gsi: 50.0,
        mi: 12.0,
        sigma_ci: 80e6,
        dilation_deg: 5.0,
        young: 10e9,
        poisson: 0.25,
        p0: 30e6,
        pi: 0.0,
    },
    Rock {
        gsi: 25.0,
        mi: 8.0,
        sigma_ci: 40e6,
        dilation_deg: 0.0,
        young: 2e9,
        poisson: 0.3,
        p0: 10e6,
        pi: POOR_SUPPORT,
    },
];

/// The poor rock's support pressure, Pa: 3 % of its p0. Unsupported (`POOR_UNSUPPORTED`), its
/// wall lies where the criterion's slope dσ1/dσ3 is 15.5 and its apex 17.5 kPa away in tension:
/// the constant stress of a triangle near the wall strays past the apex, those zones fail in
/// tension, and the wall closes too much, the more so the finer the zones (explicitly 11 % on the
/// shipped zoning, 20 % on zones half the size; implicitly its load steps do not converge; the
/// report's "Hoek–Brown rock"). Supported, the wall's minor stress stays clear of the apex.
/// Itasca's own verification of this hole supports it too (p_i = p0/6).
pub const POOR_SUPPORT: f64 = 0.3e6;

/// The poor rock unsupported: the closed form's wall at σ3 = 0 (reported, not a bar; see
/// `POOR_SUPPORT`).
pub const POOR_UNSUPPORTED: Rock = Rock {
    pi: 0.0,
    ..ROCKS[2]
};

/// The shipped Kirsch geometry (a = 1 m in a 40 m square, its graded zoning scaled by `factor`)
/// in Hoek–Brown `rock` (D = 0) under its p0, with the closed form.
pub fn scene(kirsch: &Scene, factor: f64, rock: &Rock) -> (Scene, CarranzaTorres) {
    let mut s = scaled(kirsch, factor);
    s.name = "hoek_brown_hole".into();
    let m = s
        .materials
        .get_mut(&s.region.material)
        .expect("region material");
    m.law = ZoneLawKind::HoekBrown;
    m.sigma_ci = Some(rock.sigma_ci);
    m.gsi = Some(rock.gsi);
    m.mi = Some(rock.mi);
    m.dilation = rock.dilation_deg;
    m.young = rock.young;
    m.poisson = rock.poisson;
    s.in_situ.sxx = -rock.p0;
    s.in_situ.syy = -rock.p0;
    s.in_situ.szz = Some(-rock.p0);
    support_wall(&mut s, rock.pi);
    // The bundled models' ratio: on the zoning refined through the plastic zone (the default)
    // the implicit iterations of the fair rock's first load step stall between 2e-6 and 1e-5
    // and do not reach 1e-6 in four cuts of 2 000 iterations (measured); at 1e-5 they converge
    // in 879 iterations.
    s.solve.ratio = 1e-5;
    s.solve.max_cycles = 400_000;
    s.solve.max_iterations = 2_000;
    let radius = s.excavations[0]
        .circle
        .as_ref()
        .expect("circular hole")
        .radius;
    let closed = CarranzaTorres::new(
        radius,
        (rock.p0, rock.pi),
        rock.sigma_ci,
        adit::law::hoek_brown_constants(rock.gsi, rock.mi, 0.0),
        rock.dilation_deg.to_radians(),
        rock.young / (2.0 * (1.0 + rock.poisson)),
        rock.poisson,
    );
    (s, closed)
}

/// The hole in `rock` on the zoning ×`factor`, solved by `method` with its out-of-balance force
/// released as `release` says (`crate::release_gradually`), against Carranza-Torres's solution
/// (`salencon::measure_hole`'s measures).
pub fn run(
    kirsch: &Scene,
    factor: f64,
    rock: &Rock,
    method: SolveMethod,
    release: u64,
) -> anyhow::Result<CaseReport> {
    run_along(kirsch, factor, rock, &[Leg::new(method, release)])
}

/// [`run`] along `path`: one solve after the other from where the last left the model
/// (`salencon::measure_hole_along`), e.g. the implicit path's load steps, then explicit cycling.
pub fn run_along(
    kirsch: &Scene,
    factor: f64,
    rock: &Rock,
    path: &[Leg],
) -> anyhow::Result<CaseReport> {
    let (sc, exact) = scene(kirsch, factor, rock);
    let case = format!(
        "Hoek–Brown hole GSI {}, mi {}, σci {} MPa, ψ = {}°, p0 = {} MPa, pi = {} MPa, Rp = {:.3} m (×{factor}){}",
        rock.gsi,
        rock.mi,
        rock.sigma_ci / 1e6,
        rock.dilation_deg,
        rock.p0 / 1e6,
        rock.pi / 1e6,
        exact.plastic_radius(),
        path_suffix(path)
    );
    Ok(measure_hole_along(sc, &exact, path, case)?.0)
}

/// What a row's case name adds for its path of solves: the first one's release and method
/// (`crate::release_suffix`, `crate::method_suffix`), then `, then METHOD`, its release and its
/// own ratio for each after it.
fn path_suffix(path: &[Leg]) -> String {
    let mut out = String::new();
    for (k, leg) in path.iter().enumerate() {
        if k > 0 {
            out += &format!(", then {}", leg.method.name());
        }
        out += &crate::release_suffix(leg.release, leg.method);
        if k == 0 {
            out += &crate::method_suffix(leg.method);
        }
        if let Some(ratio) = leg.ratio {
            out += &format!(" to a ratio of {ratio:e}");
        }
    }
    out
}

/// The hole in `rock` softening to the constants of `residual_gsi` (the rock's mi, D = 0) over
/// the plastic shear strain `strain` (small: the elastic–brittle–plastic rock) against Carranza-
/// Torres's elastic–brittle–plastic solution, otherwise as [`run`].
pub fn run_brittle(
    kirsch: &Scene,
    factor: f64,
    rock: &Rock,
    (residual_gsi, strain): (f64, f64),
    (method, release): (SolveMethod, u64),
) -> anyhow::Result<CaseReport> {
    let (mut sc, exact) = scene(kirsch, factor, rock);
    // The zoning as written, its plastic zone not refined: on the default zoning (refined) the
    // implicit path's 256 load steps do not converge within their cuts.
    sc.zoning.plastic_depth = adit::scene::PlasticDepth::OFF;
    let residual = adit::law::hoek_brown_constants(residual_gsi, rock.mi, 0.0);
    let exact = exact.with_residual(residual);
    sc.materials
        .get_mut(&sc.region.material)
        .expect("region material")
        .residual = Some(adit::scene::HoekBrownResidual {
        gsi: Some(residual_gsi),
        mb: None,
        s: None,
        a: None,
        plastic_strain: strain,
    });
    let case = format!(
        "Hoek–Brown hole GSI {} → {residual_gsi} at e^ps = {strain}, mi {}, σci {} MPa, p0 = {} MPa, Rp = {:.3} m (×{factor}, plastic_depth 0){}{}",
        rock.gsi,
        rock.mi,
        rock.sigma_ci / 1e6,
        rock.p0 / 1e6,
        exact.plastic_radius(),
        crate::release_suffix(release, method),
        crate::method_suffix(method)
    );
    Ok(measure_hole(sc, &exact, release, method, case)?.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::salencon::Salencon;

    /// With a = 1 the criterion is Mohr–Coulomb's (Nφ = 1 + mb, σc = s σci): the solution is
    /// Salençon's, radius, stresses and wall displacement.
    #[test]
    fn with_a_of_1_it_is_salencon() {
        let (phi, c): (f64, f64) = (30f64.to_radians(), 3e6);
        let n_phi = (1.0 + phi.sin()) / (1.0 - phi.sin());
        let sigma_c = 2.0 * c * n_phi.sqrt();
        let (shear, nu) = (4e9, 0.25);
        for (pi, psi) in [(0.0, 0.0), (2e6, 10f64.to_radians())] {
            let ct = CarranzaTorres::new(
                1.0,
                (30e6, pi),
                sigma_c,
                (n_phi - 1.0, 1.0, 1.0),
                psi,
                shear,
                nu,
            );
            let sal = Salencon {
                radius: 1.0,
                p0: 30e6,
                pi,
                cohesion: c,
                friction: phi,
                dilation: psi,
                shear,
                poisson: nu,
            };
            let rel = |x: f64, y: f64| (x - y).abs() / y.abs();
            assert!(rel(ct.plastic_radius(), sal.plastic_radius()) < 1e-10);
            assert!(rel(ct.wall_displacement(), sal.wall_displacement()) < 1e-8);
            for r in [1.0, 1.2, 1.5, 2.5] {
                let (a, b) = (ct.stress(r), sal.stress(r));
                assert!(
                    rel(a.0, b.0) < 1e-8 || (a.0 - b.0).abs() < 1.0,
                    "{r}: {a:?} {b:?}"
                );
                assert!(rel(a.1, b.1) < 1e-8, "{r}: {a:?} {b:?}");
            }
        }
    }

    /// The elastic–brittle–plastic rock: with the peak's own constants as residual it is the
    /// perfectly plastic rock; with weaker ones the plastic zone grows, σr stays continuous at
    /// Rp and σθ drops there from the peak's surface to the residual's.
    #[test]
    fn a_brittle_drop_widens_the_plastic_zone() {
        let peak = adit::law::hoek_brown_constants(50.0, 12.0, 0.0);
        let plastic = CarranzaTorres::new(3.0, (30e6, 0.0), 80e6, peak, 0.0, 4e9, 0.25);
        let same = plastic.clone().with_residual(peak);
        assert!((same.plastic_radius() - plastic.plastic_radius()).abs() < 1e-12);
        assert!((same.wall_displacement() - plastic.wall_displacement()).abs() < 1e-12);
        let residual = adit::law::hoek_brown_constants(30.0, 12.0, 0.0);
        let brittle = plastic.clone().with_residual(residual);
        let rp = brittle.plastic_radius();
        assert!(rp > 1.2 * plastic.plastic_radius(), "{rp}");
        let (inside, outside) = (
            brittle.stress(rp * (1.0 - 1e-9)),
            brittle.stress(rp * (1.0 + 1e-9)),
        );
        assert!(
            (inside.0 - outside.0).abs() < 1e-4 * 30e6,
            "{inside:?} {outside:?}"
        );
        let pcr = brittle.critical_pressure();
        let drop = brittle.strength(pcr) - brittle.residual_strength(pcr);
        assert!(
            ((inside.1 - outside.1) - drop).abs() < 1e-4 * 30e6,
            "{inside:?} {outside:?}"
        );
        assert!(brittle.wall_displacement() < plastic.wall_displacement());
    }

    /// The stresses are continuous across Rp and satisfy the criterion in the plastic zone.
    #[test]
    fn stresses_meet_at_the_plastic_radius() {
        let (mb, s, a) = adit::law::hoek_brown_constants(50.0, 12.0, 0.0);
        let ct = CarranzaTorres::new(3.0, (30e6, 0.0), 80e6, (mb, s, a), 0.0, 4e9, 0.25);
        let rp = ct.plastic_radius();
        assert!(rp > 3.3 && rp < 9.0, "{rp}");
        let (inside, outside) = (ct.stress(rp * (1.0 - 1e-9)), ct.stress(rp * (1.0 + 1e-9)));
        assert!(
            (inside.0 - outside.0).abs() < 1e-4 * 30e6,
            "{inside:?} {outside:?}"
        );
        assert!(
            (inside.1 - outside.1).abs() < 1e-4 * 30e6,
            "{inside:?} {outside:?}"
        );
        assert!(ct.wall_displacement() < -30e6 * 3.0 / (2.0 * 4e9));
    }
}

#[cfg(test)]
mod coarse {
    use adit::scene::SolveMethod;

    /// A Hoek–Brown hole in small: the fair rock on the shipped zoning ×2, excavated at once
    /// and cycled explicitly: its plastic radius within 3 % of Carranza-Torres's (the wall
    /// displacement within 15 %: released at once the explicit solve overshoots dynamically, 6 %
    /// beyond the quasi-static answer on the shipped zoning); on the shipped zoning (×1) released
    /// in 16 implicit load steps, both within 3 % (the bar of issue 48).
    #[test]
    fn a_hoek_brown_hole_follows_carranza_torres() {
        let kirsch = crate::shipped_kirsch().unwrap();
        let r = super::run(&kirsch, 2.0, &super::ROCKS[1], SolveMethod::Explicit, 0).unwrap();
        eprintln!("{}: {:?}", r.case, r.errors);
        assert!(r.errors["plastic_radius"] < 0.03, "{:?}", r.errors);
        assert!(r.errors["wall_displacement"] < 0.15, "{:?}", r.errors);
        let r = super::run(&kirsch, 1.0, &super::ROCKS[1], SolveMethod::Implicit, 16).unwrap();
        eprintln!("{}: {:?}", r.case, r.errors);
        assert!(r.errors["plastic_radius"] < 0.03, "{:?}", r.errors);
        assert!(r.errors["wall_displacement"] < 0.03, "{:?}", r.errors);
    }

    /// The fair rock's explicit bar (its explicit release localizes, `cases::hoek_brown`): on
    /// the default zoning (×1) along the quasi-static path, then cycled explicitly to a ratio a
    /// hundred times tighter, it stays on the axisymmetric answer: within 3 %, the wall's radial
    /// displacement uniform to 3 % of its mean.
    #[test]
    fn explicit_cycling_holds_the_fair_rock_on_the_quasi_static_path() {
        let kirsch = crate::shipped_kirsch().unwrap();
        let path = [
            super::Leg::new(SolveMethod::Implicit, 16),
            super::Leg {
                method: SolveMethod::Explicit,
                release: 0,
                ratio: Some(1e-7),
            },
        ];
        let r = super::run_along(&kirsch, 1.0, &super::ROCKS[1], &path).unwrap();
        eprintln!("{}: {:?}", r.case, r.errors);
        assert!(
            r.case.ends_with("then explicit to a ratio of 1e-7"),
            "{}",
            r.case
        );
        assert!(r.hole_within(0.03), "{:?}", r.errors);
        assert!(r.errors["wall_spread"] < 0.03, "{:?}", r.errors);
    }

    /// The poor rock's hole under its support pressure (0.3 MPa, Rp 2.26 a) on the shipped
    /// zoning as written, released slowly: within 3 % (measured +0.02 % in closure). Unsupported
    /// it closes 11 % too much there (`POOR_SUPPORT`).
    #[test]
    fn the_poor_rock_supported_follows_carranza_torres() {
        let mut kirsch = crate::shipped_kirsch().unwrap();
        kirsch.zoning.plastic_depth = adit::scene::PlasticDepth::OFF;
        let ramp = crate::bundled::QUASI_STATIC_RAMP;
        let r = super::run(&kirsch, 1.0, &super::ROCKS[2], SolveMethod::Explicit, ramp).unwrap();
        eprintln!("{}: {:?}", r.case, r.errors);
        assert!(r.case.contains("pi = 0.3 MPa"), "{}", r.case);
        assert!(r.errors["plastic_radius"] < 0.03, "{:?}", r.errors);
        assert!(r.errors["wall_displacement"] < 0.03, "{:?}", r.errors);
    }
}
