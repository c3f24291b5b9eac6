//! Lekhnitskii's kernels checked against what defines them: the force they carry, Hooke's law
//! with their compliance between U and T, equilibrium, and Kelvin's kernels in the isotropic limit.

use super::*;
use crate::far_field::{JointSet, Kelvin, jointed_compliance, plane_strain_compliance};

/// The jointed tunnel's rock mass: 20 GPa, ν = 0.25, sets at 35° and 110°.
pub(in crate::far_field) fn jointed() -> Lekhnitskii {
    let sets = [
        JointSet {
            dip: 35.0,
            spacing: 2.5,
            normal_stiffness: 2e10,
            shear_stiffness: 1e10,
        },
        JointSet {
            dip: 110.0,
            spacing: 3.0,
            normal_stiffness: 2e10,
            shear_stiffness: 1e10,
        },
    ];
    Lekhnitskii::new(jointed_compliance(
        plane_strain_compliance(20e9, 0.25),
        &sets,
    ))
    .unwrap()
}

/// A strongly anisotropic compliance with every coupling term: one soft set at 20°.
fn skewed() -> Lekhnitskii {
    let set = JointSet {
        dip: 20.0,
        spacing: 0.5,
        normal_stiffness: 5e9,
        shear_stiffness: 5e8,
    };
    Lekhnitskii::new(jointed_compliance(
        plane_strain_compliance(30e9, 0.2),
        &[set],
    ))
    .unwrap()
}

/// Each root solves the characteristic equation, with Im μ > 0.
#[test]
fn the_roots_solve_the_characteristic_equation() {
    for m in [jointed(), skewed()] {
        let b = m.compliance;
        for mu in m.roots() {
            let f = mu.powi(4) * b[0][0] - mu.powi(3) * (2.0 * b[0][2])
                + mu * mu * (2.0 * b[0][1] + b[2][2])
                - mu * (2.0 * b[1][2])
                + b[1][1];
            assert!(f.norm() < 1e-12 * b[0][0], "{mu} {f}");
            assert!(mu.im > 0.0);
        }
    }
}

/// ∮ T_ij dΓ = −δ_ij on a circle about the force (n pointing away from it), as Kelvin's.
#[test]
fn a_circle_about_the_force_carries_it() {
    for m in [jointed(), skewed()] {
        for radius in [0.1, 1.0, 7.0] {
            let missed = crate::far_field::kernel::force_missed(&m, [0.0, 0.0], radius, 4000);
            assert!(missed < 1e-9, "{radius}: {missed}");
        }
    }
}

/// The stress of Hooke's law on U's strain (central differences) is T's: σ n on any normal,
/// and it is in equilibrium (its divergence, by differences of T, vanishes).
#[test]
fn the_displacement_and_traction_agree_through_the_compliance() {
    for m in [jointed(), skewed()] {
        let stiffness = nalgebra::Matrix3::from_fn(|i, j| m.compliance[i][j])
            .try_inverse()
            .unwrap();
        let h = 1e-5;
        for d in [
            [0.7, 0.2],
            [-0.3, 0.9],
            [-1.1, -0.4],
            [0.05, -0.6],
            [-2.0, 1e-3],
        ] {
            let du = |e: [f64; 2]| {
                let (p, q) = (
                    m.displacement([d[0] + h * e[0], d[1] + h * e[1]]),
                    m.displacement([d[0] - h * e[0], d[1] - h * e[1]]),
                );
                // [component][force].
                std::array::from_fn::<_, 2, _>(|c| {
                    std::array::from_fn::<_, 2, _>(|f| (p[f][c] - q[f][c]) / (2.0 * h))
                })
            };
            let (dx, dy) = (du([1.0, 0.0]), du([0.0, 1.0]));
            for j in 0..2 {
                // Strain of a unit force along j: u_x,x, u_y,y, u_x,y + u_y,x.
                let eps = nalgebra::Vector3::new(dx[0][j], dy[1][j], dy[0][j] + dx[1][j]);
                let s = stiffness * eps;
                let tx = m.traction(d, [1.0, 0.0]);
                let ty = m.traction(d, [0.0, 1.0]);
                let scale = tx[j][0].abs().max(ty[j][1].abs()).max(tx[j][1].abs());
                for (got, want) in [(s[0], tx[j][0]), (s[2], tx[j][1]), (s[1], ty[j][1])] {
                    assert!((got - want).abs() < 1e-6 * scale, "{d:?} {j}: {got} {want}");
                }
                // ∂σ_xx/∂x + ∂σ_xy/∂y and ∂σ_xy/∂x + ∂σ_yy/∂y.
                let at = |e: [f64; 2], n: [f64; 2], i: usize| {
                    let (p, q) = (
                        m.traction([d[0] + h * e[0], d[1] + h * e[1]], n),
                        m.traction([d[0] - h * e[0], d[1] - h * e[1]], n),
                    );
                    (p[j][i] - q[j][i]) / (2.0 * h)
                };
                let div = [
                    at([1.0, 0.0], [1.0, 0.0], 0) + at([0.0, 1.0], [1.0, 0.0], 1),
                    at([1.0, 0.0], [1.0, 0.0], 1) + at([0.0, 1.0], [0.0, 1.0], 1),
                ];
                let r = d[0].hypot(d[1]);
                assert!(div[0].abs().max(div[1].abs()) < 1e-5 * scale / r, "{div:?}");
            }
        }
    }
}

/// An isotropic compliance (whose double root μ = i is split by a nudge of b₆₆) gives Kelvin's
/// kernels: U to within the nudge plus its constant (U is defined to a rigid translation, so
/// the difference U(d) − U(d′) is compared), T to within the nudge.
#[test]
fn the_isotropic_limit_is_kelvins() {
    let (young, poisson) = (20e9, 0.3);
    let m = Lekhnitskii::new(plane_strain_compliance(young, poisson)).unwrap();
    let k = Kelvin {
        shear: young / (2.0 * (1.0 + poisson)),
        poisson,
    };
    let base = [1.0, 0.0];
    let (ub, kb) = (m.displacement(base), k.displacement(base));
    for d in [[0.3, 0.4], [-2.0, 0.5], [0.1, -3.0]] {
        let (u, ku) = (m.displacement(d), k.displacement(d));
        let (t, kt) = (m.traction(d, [0.6, 0.8]), k.traction(d, [0.6, 0.8]));
        let (us, ts) = (
            ku[0][0].abs() + ku[1][1].abs(),
            kt[0][0].abs() + kt[1][1].abs(),
        );
        for i in 0..2 {
            for j in 0..2 {
                let du = (u[i][j] - ub[i][j]) - (ku[i][j] - kb[i][j]);
                assert!(du.abs() < 1e-4 * us, "U {d:?} {i}{j}: {du:e}");
                assert!(
                    (t[i][j] - kt[i][j]).abs() < 1e-4 * ts,
                    "T {d:?} {i}{j}: {t:?} {kt:?} {:?}",
                    m.roots()
                );
            }
        }
    }
}

/// A compliance that is not positive definite is refused, naming it.
#[test]
fn a_compliance_that_is_not_positive_definite_is_refused() {
    let mut b = plane_strain_compliance(20e9, 0.25);
    b[0][1] = 2.0 * b[0][0];
    b[1][0] = b[0][1];
    let e = Lekhnitskii::new(b).unwrap_err();
    assert!(e.contains("positive definite"), "{e}");
}

mod random {
    use super::*;
    use proptest::prelude::*;

    /// A rock mass of random intact constants cut by one to three random sets.
    fn rock_mass() -> impl Strategy<Value = [[f64; 3]; 3]> {
        let set = (0.0..180.0f64, 0.2..10.0f64, 8.0..11.0f64, 0.0..2.0f64).prop_map(
            |(dip, spacing, kn, ratio)| JointSet {
                dip,
                spacing,
                normal_stiffness: 10f64.powf(kn),
                shear_stiffness: 10f64.powf(kn - ratio),
            },
        );
        (
            1e9..1e11f64,
            0.0..0.45f64,
            prop::collection::vec(set, 1..=3),
        )
            .prop_map(|(young, poisson, sets)| {
                jointed_compliance(plane_strain_compliance(young, poisson), &sets)
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        /// For any rock mass the roots solve their equation, the kernels carry a unit force round
        /// a circle, and U's strain through Hooke's law gives T's stress.
        #[test]
        fn any_rock_mass_has_consistent_kernels(b in rock_mass(), angle in 0.0..std::f64::consts::TAU) {
            let m = Lekhnitskii::new(b).unwrap();
            for mu in m.roots() {
                let terms = [
                    mu.powi(4) * b[0][0],
                    -mu.powi(3) * (2.0 * b[0][2]),
                    mu * mu * (2.0 * b[0][1] + b[2][2]),
                    -mu * (2.0 * b[1][2]),
                    b[1][1].into(),
                ];
                let f: nalgebra::Complex<f64> = terms.iter().sum();
                // Relative to its largest term: a root of a strongly anisotropic mass is large
                // (|μ| ≈ 330 where the shear compliance b66 is 1e5 times b11), and its terms with it.
                let scale = terms.iter().map(|t| t.norm()).fold(0.0, f64::max);
                prop_assert!(f.norm() < 1e-10 * scale, "{mu} {f}");
            }
            let missed = crate::far_field::kernel::force_missed(&m, [0.0, 0.0], 1.0, 8000);
            prop_assert!(missed < 1e-6, "{missed} stretch {}", m.stretch());
            let stiffness = nalgebra::Matrix3::from_fn(|i, j| b[i][j]).try_inverse().unwrap();
            let d = [angle.cos(), angle.sin()];
            let h = 1e-6;
            let du = |e: [f64; 2], c: usize, f: usize| {
                let p = m.displacement([d[0] + h * e[0], d[1] + h * e[1]]);
                let q = m.displacement([d[0] - h * e[0], d[1] - h * e[1]]);
                (p[f][c] - q[f][c]) / (2.0 * h)
            };
            for f in 0..2 {
                let eps = nalgebra::Vector3::new(
                    du([1.0, 0.0], 0, f),
                    du([0.0, 1.0], 1, f),
                    du([0.0, 1.0], 0, f) + du([1.0, 0.0], 1, f),
                );
                let s = stiffness * eps;
                let (tx, ty) = (m.traction(d, [1.0, 0.0]), m.traction(d, [0.0, 1.0]));
                let scale = tx[f][0].abs().max(ty[f][1].abs()).max(tx[f][1].abs());
                for (got, want) in [(s[0], tx[f][0]), (s[2], tx[f][1]), (s[1], ty[f][1])] {
                    prop_assert!((got - want).abs() < 1e-4 * scale, "{got} {want}");
                }
            }
        }
    }
}

/// Extreme rock masses (joints from 1e-6 to 1e20 Pa/m against 20 GPa rock, one set or two) give
/// a medium or an error naming the compliance, never a panic or kernels that are not finite.
#[test]
fn extreme_rock_masses_give_kernels_or_an_error() {
    for kn in [1e-6, 1e2, 1e6, 1e14, 1e20] {
        for ratio in [1.0, 1e-6, 1e6] {
            for count in [1, 2] {
                let sets: Vec<JointSet> = (0..count)
                    .map(|k| JointSet {
                        dip: 20.0 + 70.0 * k as f64,
                        spacing: 1.0,
                        normal_stiffness: kn,
                        shear_stiffness: kn * ratio,
                    })
                    .collect();
                let b = jointed_compliance(plane_strain_compliance(20e9, 0.25), &sets);
                match Lekhnitskii::new(b) {
                    Ok(m) => {
                        let (u, t) = (
                            m.displacement([0.3, 0.7]),
                            m.traction([0.3, 0.7], [0.6, 0.8]),
                        );
                        assert!(
                            u.iter().chain(&t).flatten().all(|v| v.is_finite()),
                            "{kn} {ratio}"
                        );
                    }
                    Err(e) => assert!(e.contains("compliance"), "{e}"),
                }
            }
        }
    }
}
