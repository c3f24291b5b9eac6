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
//! (tension positive in the formulas as in adit). The hole is excavated at once: the zones start at
//! −p0 and the free wall unloads them.

use std::time::Instant;

use adit::Scene;
use adit::build::build;
use adit::law::{SHEAR_NOW, SHEAR_PAST};
use adit::scene::ZoneLawKind;
use adit::solve::{Quiet, Solver, Status};

use crate::kirsch_case::scaled;
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
            let k = (self.p0 - pe) * (rp / r).powi(2);
            (-self.p0 + k, -self.p0 - k)
        }
    }
}

/// The shipped Kirsch geometry (a = 1 m in a 40 m square, graded zoning scaled by `factor`) in
/// Mohr–Coulomb rock (E = 10 GPa, ν = 0.25, c = 5 MPa, φ = 30°, ψ = 0) under p0 = 30 MPa.
fn scene(kirsch: &Scene, factor: f64) -> (Scene, Salencon) {
    let mut s = scaled(kirsch, factor);
    s.name = "salencon".into();
    let m = s
        .materials
        .get_mut(&s.region.material)
        .expect("region material");
    m.law = ZoneLawKind::MohrCoulomb;
    m.cohesion = Some(5e6);
    m.friction = Some(30.0);
    let p0 = 30e6;
    s.in_situ.sxx = -p0;
    s.in_situ.syy = -p0;
    s.in_situ.szz = Some(-p0);
    s.solve.ratio = 1e-6;
    s.solve.max_cycles = 400_000;
    let radius = s.excavations[0]
        .circle
        .as_ref()
        .expect("circular hole")
        .radius;
    let closed = Salencon {
        radius,
        p0,
        pi: 0.0,
        cohesion: 5e6,
        friction: 30f64.to_radians(),
    };
    (s, closed)
}

/// Solve and compare: `plastic_radius` (radius of a circle with the hole's area plus the yielded
/// zones' area, against Rp) and `stress_l2` (area-weighted L2 of (σr, σθ) over zones with centroid
/// r ≤ 3Rp, relative to the exact norm there).
pub fn run(kirsch: &Scene, factor: f64) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let (sc, exact) = scene(kirsch, factor);
    let mut b = build(&sc)?;
    let mut solver = Solver::new(&mut b.model, &sc.solve, 0);
    let sol = solver.solve(&mut b.model, &mut Quiet);
    anyhow::ensure!(
        sol.status == Status::Converged,
        "Salençon case did not converge: {:?}",
        sol.status
    );
    let (m, rp) = (&b.model, exact.plastic_radius());
    let z = &m.zones;
    let hole_area = b.domain.holes[0].polygon.signed_area().abs();
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
    let h = (h2 / count).sqrt();
    Ok(CaseReport::new(
        format!("Salençon: hole in Mohr–Coulomb rock, p0 = 30 MPa, Rp = {rp:.3} m (×{factor})"),
        z.len(),
        sol.cycles,
        start.elapsed().as_secs_f64(),
        Some(h),
        &[
            ("plastic_radius", (rp_h - rp).abs() / rp),
            ("stress_l2", (num / den).sqrt()),
        ],
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed form is continuous at Rp and meets the wall condition σr(a) = −pi.
    #[test]
    fn closed_form_is_consistent() {
        let (_, s) = scene(&crate::shipped_kirsch().unwrap(), 1.0);
        let rp = s.plastic_radius();
        assert!(rp > 1.4 && rp < 1.6, "{rp}");
        let (a, b) = (s.stress(rp * (1.0 - 1e-9)), s.stress(rp * (1.0 + 1e-9)));
        assert!(
            (a.0 - b.0).abs() < 1.0 && (a.1 - b.1).abs() < 1.0,
            "{a:?} {b:?}"
        );
        assert!(s.stress(s.radius).0.abs() < 1e-6);
    }

    /// Coarse twin (zones twice the shipped size).
    #[test]
    fn plastic_zone_matches_salencon() {
        let r = run(&crate::shipped_kirsch().unwrap(), 2.0).unwrap();
        eprintln!("{r:?}");
        assert!(r.errors["plastic_radius"] < 0.05, "{r:?}");
        assert!(r.errors["stress_l2"] < 0.05, "{r:?}");
    }
}
