//! Reference for a circular hole in plastic rock where no closed form holds: the plane-strain
//! axisymmetric problem solved in one dimension (u(r) only) with adit's own zone law, unloaded
//! quasi-statically. Salençon's closed form assumes that σzz stays the intermediate principal
//! stress; with ν small enough against the strength (ν < (p0 − σc)/(2p0 − σc) at the wall) the
//! elastic σzz = −p0 + ν(σr + σθ + 2p0) becomes the major one and the rock yields out of plane,
//! which the closed form does not see. The one-dimensional solve has no such assumption.
//!
//! Discretization: linear elements on a geometric grid a ≤ r ≤ R (`ELEMENTS`, R = `OUTER` a), one
//! integration point at each element's mid-radius r_m, strains ε_r = du/dr, ε_θ = u/r, ε_z = 0,
//! internal force f_i = Σ_e (σr N_i' + σθ N_i / r_m) r_m L_e (per radian). The rock outside R is
//! the elastic infinite medium: σr(R) = −p0 − 2G u(R)/R (the exterior Lamé solution), a spring
//! 2G on the last node. The wall pressure falls from p0 to pi in equal steps (`STEPS` unless
//! asked for more: a brittle rock's path needs many more, see `solve_law`); each is
//! solved by the initial-stiffness method (the elastic tridiagonal matrix, Thomas algorithm) with
//! every zone's stress returned by the law from its state at the start of the step, until the
//! residual is below 1e-10 p0 a (or the tolerance `solve_law` is given).

use adit::law::{Elastic, MohrCoulomb, ZoneLaw};

/// Elements along the radius.
pub const ELEMENTS: usize = 1200;
/// Outer radius of the grid over the hole radius.
pub const OUTER: f64 = 40.0;
/// Pressure steps from p0 to pi.
pub const STEPS: usize = 60;

/// The rock and load of one hole (SI units; angles in degrees).
#[derive(Debug, Clone, Copy)]
pub struct Hole {
    pub radius: f64,
    pub young: f64,
    pub poisson: f64,
    pub cohesion: f64,
    pub friction_deg: f64,
    pub dilation_deg: f64,
    /// In-situ pressure, Pa (compression positive).
    pub p0: f64,
    /// Final wall pressure, Pa (compression positive).
    pub pi: f64,
}

/// The hole's radius (m) and its pressures (Pa, compression positive).
struct Pressures {
    radius: f64,
    p0: f64,
    pi: f64,
}

/// What the reference gives: the wall's radial displacement (m, outward positive), the radius out
/// to which zones have yielded in shear (m), and whether any zone yielded with σzz as its major or
/// minor principal stress (outside Salençon's assumption).
#[derive(Debug, Clone, Copy)]
pub struct Reference {
    pub wall_displacement: f64,
    pub plastic_radius: f64,
    pub out_of_plane_yield: bool,
}

/// Solve the hole (see the module).
pub fn solve(h: &Hole) -> anyhow::Result<Reference> {
    let law = MohrCoulomb::new(
        Elastic::from_young(h.young, h.poisson, 1.0),
        h.cohesion,
        h.friction_deg,
        h.dilation_deg,
        f64::INFINITY,
    );
    solve_law(&law, h.radius, (h.p0, h.pi), 1e-10, STEPS)
}

/// Solve the hole of `radius` (m) in rock of any zone `law`, the wall unloaded from the in-situ
/// pressure p0 to pi (Pa, compression positive), each step to a residual of `tolerance` p0 a: at
/// least the relative accuracy of the law's return (Mohr–Coulomb's is closed-form, 1e-10 holds;
/// Hoek–Brown's is Newton's to 1e-9 of σci, so 1e-8), in `steps` equal unloading steps. Each
/// step returns the whole step's strain from its start, so a rock whose strength drops at once
/// (elastic–brittle–plastic) follows the quasi-static path only as the steps shrink: the fair
/// Hoek–Brown rock dropping to GSI 30 misses Carranza-Torres's wall displacement by −11.9 % in
/// 60 steps, −4.2 % in 240, −0.5 % in 960.
pub fn solve_law(
    law: &dyn ZoneLaw,
    radius: f64,
    (p0, pi): (f64, f64),
    tolerance: f64,
    steps: usize,
) -> anyhow::Result<Reference> {
    let h = Pressures { radius, p0, pi };
    let (k, g) = law.moduli();
    let (a1, a2) = (k + 4.0 / 3.0 * g, k - 2.0 / 3.0 * g);
    let n = ELEMENTS;
    let r: Vec<f64> = (0..=n)
        .map(|i| h.radius * OUTER.powf(i as f64 / n as f64))
        .collect();
    let mid: Vec<f64> = (0..n).map(|e| 0.5 * (r[e] + r[e + 1])).collect();
    let len: Vec<f64> = (0..n).map(|e| r[e + 1] - r[e]).collect();
    // Elastic tridiagonal stiffness: B = [N'; N/r_m], D = [[a1, a2], [a2, a1]].
    let (mut diag, mut off) = (vec![0.0; n + 1], vec![0.0; n]);
    for e in 0..n {
        let (rm, l) = (mid[e], len[e]);
        let b = [[-1.0 / l, 0.5 / rm], [1.0 / l, 0.5 / rm]];
        let kij = |i: usize, j: usize| {
            let (bi, bj) = (b[i], b[j]);
            (bi[0] * (a1 * bj[0] + a2 * bj[1]) + bi[1] * (a2 * bj[0] + a1 * bj[1])) * rm * l
        };
        diag[e] += kij(0, 0);
        diag[e + 1] += kij(1, 1);
        off[e] += kij(0, 1);
    }
    let outer = OUTER * h.radius;
    diag[n] += 2.0 * g;
    let mut u = vec![0.0; n + 1];
    let mut stress = vec![[-h.p0; 4]; n];
    for s in &mut stress {
        s[3] = 0.0;
    }
    let (mut state, mut plastic) = (vec![0u8; n], vec![0.0; n]);
    let mut out_of_plane = false;
    let tolerance = tolerance * h.p0 * h.radius;
    for step in 1..=steps {
        let pi = h.p0 + (h.pi - h.p0) * step as f64 / steps as f64;
        let (u0, s0, st0, pl0) = (u.clone(), stress.clone(), state.clone(), plastic.clone());
        let mut converged = false;
        for _ in 0..200_000 {
            // Stresses from the step's strain increment, returned from the step's start.
            let mut force = vec![0.0; n + 1];
            for e in 0..n {
                let (rm, l) = (mid[e], len[e]);
                let du = [u[e] - u0[e], u[e + 1] - u0[e + 1]];
                let de = [(du[1] - du[0]) / l, 0.5 * (du[0] + du[1]) / rm, 0.0];
                let (mut s, mut st, mut pl) = (s0[e], st0[e], pl0[e]);
                law.update(&mut s, &mut st, &mut pl, &de);
                (stress[e], state[e], plastic[e]) = (s, st, pl);
                force[e] += (-s[0] / l + 0.5 * s[1] / rm) * rm * l;
                force[e + 1] += (s[0] / l + 0.5 * s[1] / rm) * rm * l;
            }
            // Residual: external minus internal (wall pressure pushes outward at r = a).
            let mut res: Vec<f64> = force.iter().map(|f| -f).collect();
            res[0] += pi * h.radius;
            res[n] += (-h.p0 - 2.0 * g * u[n] / outer) * outer;
            let worst = res.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            if worst < tolerance {
                converged = true;
                break;
            }
            let du = thomas(&off, &diag, &res);
            for (ui, d) in u.iter_mut().zip(du) {
                *ui += d;
            }
        }
        anyhow::ensure!(
            converged,
            "axisymmetric reference: step {step} did not converge"
        );
    }
    let mut plastic_radius = h.radius;
    for e in 0..n {
        if state[e] & adit::law::SHEAR_PAST != 0 {
            plastic_radius = plastic_radius.max(r[e + 1]);
            let s = stress[e];
            let (lo, hi) = (s[0].min(s[1]), s[0].max(s[1]));
            if s[2] < lo - 1e-6 * h.p0 || s[2] > hi + 1e-6 * h.p0 {
                out_of_plane = true;
            }
        }
    }
    Ok(Reference {
        wall_displacement: u[0],
        plastic_radius,
        out_of_plane_yield: out_of_plane,
    })
}

/// Solve the symmetric tridiagonal system (diagonal `d`, off-diagonal `o`) for `b`.
fn thomas(o: &[f64], d: &[f64], b: &[f64]) -> Vec<f64> {
    let n = d.len();
    let (mut c, mut x) = (vec![0.0; n], vec![0.0; n]);
    let mut denom = d[0];
    c[0] = if n > 1 { o[0] / denom } else { 0.0 };
    x[0] = b[0] / denom;
    for i in 1..n {
        denom = d[i] - o[i - 1] * c[i - 1];
        if i < n - 1 {
            c[i] = o[i] / denom;
        }
        x[i] = (b[i] - o[i - 1] * x[i - 1]) / denom;
    }
    for i in (0..n - 1).rev() {
        let next = x[i + 1];
        x[i] -= c[i] * next;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::salencon::Salencon;

    /// Where σzz stays intermediate the reference is Salençon's closed form: wall displacement
    /// and plastic radius within 0.5 %.
    #[test]
    fn reference_meets_salencon_where_it_holds() {
        let h = Hole {
            radius: 1.0,
            young: 10e9,
            poisson: 0.3,
            cohesion: 3e6,
            friction_deg: 30.0,
            dilation_deg: 0.0,
            p0: 10e6,
            pi: 0.0,
        };
        let reference = solve(&h).unwrap();
        let closed = Salencon {
            radius: 1.0,
            p0: h.p0,
            pi: 0.0,
            cohesion: h.cohesion,
            friction: h.friction_deg.to_radians(),
            dilation: 0.0,
            shear: h.young / (2.0 * (1.0 + h.poisson)),
            poisson: h.poisson,
        };
        assert!(!reference.out_of_plane_yield);
        let (u, ue) = (reference.wall_displacement, closed.wall_displacement());
        assert!((u / ue - 1.0).abs() < 5e-3, "{u} vs {ue}");
        let (rp, rpe) = (reference.plastic_radius, closed.plastic_radius());
        assert!((rp / rpe - 1.0).abs() < 5e-3, "{rp} vs {rpe}");
    }
}
