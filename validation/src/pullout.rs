//! A fully grouted bolt pulled out of a block (the shear-lag solution of a grouted bar; Farmer
//! 1975, "Stress distribution along a resin grouted rock anchor", Int. J. Rock Mech. Min. Sci.
//! 12; the grout of the cable element as in Itasca's UDEC/FLAC cable verification). A bolt of
//! axial stiffness EA in rock that does not move, grout stiffness k per length, pulled at its
//! head (x = 0) by P, free at its toe (x = L): EA u'' = k u gives, with λ = √(k/EA),
//!
//!   N(x) = P sinh(λ(L − x)) / sinh(λL),   grout force per length k u(0) = P λ coth(λL),
//!
//! elastic until that reaches the bond strength s at the head (P1 = s / (λ coth λL)). Beyond it
//! the grout slips over a length a from the head, where N falls by s per metre, and the rest is
//! the elastic solution over L − a loaded by P − s a, its head just at the bond strength:
//!
//!   (P − s a) λ coth(λ(L − a)) = s,   N(x) = P − s x (x ≤ a),
//!   N(x) = (P − s a) sinh(λ(L − x)) / sinh(λ(L − a)) (x ≥ a);
//!
//! the bolt pulls out at P = s L.

use std::time::Instant;

use adit::scene::SolveMethod;
use adit::setup::setup;

use crate::report::CaseReport;

/// The closed form.
#[derive(Debug, Clone, Copy)]
pub struct ShearLag {
    /// Bolt length L, m.
    pub length: f64,
    /// Axial stiffness EA, N.
    pub axial_stiffness: f64,
    /// Grout stiffness per length k, N/m per m.
    pub grout_stiffness: f64,
    /// Bond strength per length s, N/m.
    pub bond_strength: f64,
}

impl ShearLag {
    fn lambda(&self) -> f64 {
        (self.grout_stiffness / self.axial_stiffness).sqrt()
    }

    /// Pull at which the grout first slips, N.
    pub fn first_slip(&self) -> f64 {
        let l = self.lambda();
        self.bond_strength / (l / (l * self.length).tanh())
    }

    /// Length of grout slipping under a pull `p`, m (0 while elastic).
    pub fn slip_length(&self, p: f64) -> f64 {
        if p <= self.first_slip() {
            return 0.0;
        }
        let (s, l, len) = (self.bond_strength, self.lambda(), self.length);
        let excess = |a: f64| (p - s * a) * l / (l * (len - a)).tanh() - s;
        // excess decreases from > 0 at a = 0 to < 0 as a → p/s (bisection to round-off).
        let (mut lo, mut hi) = (0.0, (p / s).min(len));
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if excess(mid) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// Axial force at x from the head under a pull p, N.
    pub fn axial(&self, p: f64, x: f64) -> f64 {
        let (s, l, len) = (self.bond_strength, self.lambda(), self.length);
        let a = self.slip_length(p);
        if x <= a {
            p - s * x
        } else {
            (p - s * a) * (l * (len - x)).sinh() / (l * (len - a)).sinh()
        }
    }
}

/// The bolt of the case (as in `scene`).
pub const CASE: ShearLag = ShearLag {
    length: 3.0,
    axial_stiffness: 200e9 * 4.9e-4,
    grout_stiffness: 1e8,
    bond_strength: 5e4,
};

/// Axial force at one segment's middle: position x from the head (m), computed and closed-form
/// force (N/m).
#[derive(Debug, Clone, Copy, serde::Serialize)]
pub struct ProfilePoint {
    pub x: f64,
    pub computed: f64,
    pub exact: f64,
}

/// The pull-out block and bolt, segments `segment` m long.
fn scene(segment: f64) -> anyhow::Result<adit::Scene> {
    let scene: adit::Scene = serde_json::from_value(serde_json::json!({
        "name": "pullout",
        "materials": { "rock": { "density": 2700, "young": 1e12, "poisson": 0.25 } },
        "region": { "polygon": [[0, -1], [4, -1], [4, 1], [0, 1]], "material": "rock" },
        "zoning": { "edge_at_excavation": 0.1, "edge_far": 0.25, "grading": 0.2, "min_angle": 28 },
        "boundary": [{ "part": "outer", "fix": "xy" }],
        "bolts": [{
            "name": "bolt", "young": 200e9, "area": 4.9e-4, "yield_force": 1e6,
            "grout_stiffness": 1e8, "bond_strength": 5e4, "segment": segment,
            "line": { "from": [0, 0], "to": [3, 0] }
        }],
        "solve": { "ratio": 1e-7, "max_cycles": 400000 }
    }))?;
    scene.validate()?;
    Ok(scene)
}

/// A 4 m × 2 m block fixed on its outline (E = 1000 GPa: it hardly moves), one bolt along its
/// axis from the face x = 0 to x = 3 m (EA = 98 MN, k = 100 MN/m/m, s = 50 kN/m, segments
/// `segment` m), pulled at its head by `fraction` × the pull-out load s L. Error `axial`: the
/// largest |N_h − N| over the segments (at their middles) relative to the pull.
pub fn run(fraction: f64, segment: f64) -> anyhow::Result<(CaseReport, Vec<ProfilePoint>)> {
    run_by(fraction, segment, SolveMethod::Explicit)
}

/// [`run`] solved by `method` (`solve.method`); the row's case names it.
pub fn run_by(
    fraction: f64,
    segment: f64,
    method: SolveMethod,
) -> anyhow::Result<(CaseReport, Vec<ProfilePoint>)> {
    let start = Instant::now();
    let exact = CASE;
    let mut scene = scene(segment)?;
    scene.solve.method = method;
    let mut b = setup(&scene)?;
    let pull = fraction * exact.bond_strength * exact.length;
    // Pull the head out of the rock: against the bolt's axis (head to toe, +x).
    b.model.supports.cables.applied[0] = -pull;
    let (cycles, implicit) = crate::settle_by_method(&mut b.model, &scene.solve, "pull-out")?;
    let c = &b.model.supports.cables;
    let mut profile = Vec::new();
    let mut err = 0.0f64;
    for (s, nodes) in c.segment.iter().enumerate() {
        let x = 0.5 * (c.pos[nodes[0] as usize][0] + c.pos[nodes[1] as usize][0]);
        let n = exact.axial(pull, x);
        err = err.max((c.axial[s] - n).abs() / pull);
        profile.push(ProfilePoint {
            x,
            computed: c.axial[s],
            exact: n,
        });
    }
    let report = CaseReport::new(
        format!(
            "Grouted bolt pull-out at {:.0} % of s·L ({}), segments {segment} m{}",
            100.0 * fraction,
            if pull > exact.first_slip() {
                format!("grout slipping over {:.2} m", exact.slip_length(pull))
            } else {
                "elastic".to_string()
            },
            crate::method_suffix(method)
        ),
        b.model.zones.len(),
        cycles,
        start.elapsed().as_secs_f64(),
        Some(segment),
        &[("axial", err)],
    )
    .with_implicit(implicit);
    Ok((report, profile))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closed_form_is_continuous_and_balanced() {
        let e = ShearLag {
            length: 3.0,
            axial_stiffness: 1e8,
            grout_stiffness: 1e8,
            bond_strength: 5e4,
        };
        let p1 = e.first_slip();
        assert!(e.slip_length(0.99 * p1) == 0.0 && e.slip_length(1.2 * p1) > 0.0);
        let p = 0.5 * (p1 + 1.5e5);
        let a = e.slip_length(p);
        assert!((e.axial(p, a - 1e-9) - e.axial(p, a + 1e-9)).abs() < 1e-3);
        assert!((e.axial(p, 0.0) - p).abs() < 1e-9 && e.axial(p, 3.0).abs() < 1e-9);
    }

    #[test]
    fn axial_force_follows_the_shear_lag_solution() {
        for fraction in [0.25, 0.6] {
            let (r, _) = run(fraction, 0.1).unwrap();
            assert!(r.errors["axial"] < 0.02, "{r:?}");
        }
    }

    /// The implicit solve assembles the bolt (segments and grout springs): with the grout
    /// slipping over part of the bolt it converges to the same profile.
    #[test]
    fn the_implicit_solve_carries_the_bolt() {
        for fraction in [0.25, 0.6] {
            let (e, _) = run(fraction, 0.1).unwrap();
            let (i, _) = run_by(fraction, 0.1, SolveMethod::Implicit).unwrap();
            assert!(i.errors["axial"] < 0.02, "{i:?}");
            assert!(
                (i.errors["axial"] - e.errors["axial"]).abs() < 5e-3,
                "{i:?} {e:?}"
            );
        }
    }

    #[test]
    fn the_bolt_pulls_out_beyond_its_bond_capacity() {
        let mut sc = scene(0.1).unwrap();
        sc.solve.max_cycles = 20_000;
        let mut b = setup(&sc).unwrap();
        // 5 % over s·L = 150 kN: the grout slips along the whole bolt and it keeps moving.
        b.model.supports.cables.applied[0] = -1.05 * 1.5e5;
        let mut solver = adit::solve::Solver::new(&mut b.model, &sc.solve, 0);
        let sol = solver.solve(&mut b.model, &mut adit::solve::Quiet);
        assert_eq!(sol.status, adit::solve::Status::CycleLimit);
        let c = &b.model.supports.cables;
        assert!(
            c.slip.iter().all(|&s| s > 0.0),
            "the grout slips everywhere"
        );
        assert!(c.disp[0] < -0.01, "the head has moved {} m", c.disp[0]);
    }
}
