//! Melan's kernels against what defines them: a free surface, the force they carry, Hooke's law
//! between the complementary displacement and traction, and Kelvin's kernels deep down.

use super::*;

fn half_plane() -> Melan {
    Melan {
        kelvin: Kelvin {
            shear: 4e9,
            poisson: 0.3,
        },
        surface: 2.5,
    }
}

/// The surface carries no traction: T on the normal (0, 1) at points of y = y_s vanishes for a
/// force at any depth, to round-off against Kelvin's traction there.
#[test]
fn the_surface_is_free() {
    let m = half_plane();
    for xi in [[0.0, 1.5], [3.0, -4.0], [-1.0, 2.4]] {
        for x0 in [-7.0, -1.0, 0.0, 0.4, 5.0] {
            let x = [x0, m.surface];
            let (t, k) = (
                m.traction_at(x, xi, [0.0, 1.0]),
                m.kelvin.traction_at(x, xi, [0.0, 1.0]),
            );
            let scale = k.iter().flatten().fold(0.0f64, |a, v| a.max(v.abs()));
            for v in t.iter().flatten() {
                assert!(
                    v.abs() < 1e-12 * scale.max(1e-3),
                    "{xi:?} {x:?}: {t:?} {k:?}"
                );
            }
        }
    }
}

/// ∮ T_ij dΓ = −δ_ij on a circle about the force inside the medium (the complementary part
/// is regular there and carries nothing).
#[test]
fn a_circle_about_the_force_carries_it() {
    let m = half_plane();
    for radius in [0.2, 1.0, 1.9] {
        let missed = crate::far_field::kernel::force_missed(&m, [0.3, 0.5], radius, 4000);
        assert!(missed < 1e-9, "{radius}: {missed}");
    }
}

/// The complementary displacement's strain through Hooke's law (plane strain) gives the
/// complementary stress, which is in equilibrium.
#[test]
fn the_complementary_part_is_an_elastic_field() {
    let m = half_plane();
    let (g, nu) = (m.kelvin.shear, m.kelvin.poisson);
    let lambda = 2.0 * g * nu / (1.0 - 2.0 * nu);
    let h = 1e-5;
    let xi = [0.5, 0.0];
    for x in [[0.0, -1.0], [2.0, 1.0], [-3.0, 2.0], [0.7, -6.0]] {
        let du = |e: [f64; 2], f: usize, c: usize| {
            let p = m
                .complementary_at([x[0] + h * e[0], x[1] + h * e[1]], xi, [0.0, 0.0])
                .1;
            let q = m
                .complementary_at([x[0] - h * e[0], x[1] - h * e[1]], xi, [0.0, 0.0])
                .1;
            (p[f][c] - q[f][c]) / (2.0 * h)
        };
        let dt = |e: [f64; 2], n: [f64; 2], f: usize, c: usize| {
            let p = m
                .complementary_at([x[0] + h * e[0], x[1] + h * e[1]], xi, n)
                .0;
            let q = m
                .complementary_at([x[0] - h * e[0], x[1] - h * e[1]], xi, n)
                .0;
            (p[f][c] - q[f][c]) / (2.0 * h)
        };
        for f in 0..2 {
            let (exx, eyy) = (du([1.0, 0.0], f, 0), du([0.0, 1.0], f, 1));
            let gxy = du([0.0, 1.0], f, 0) + du([1.0, 0.0], f, 1);
            let (tx, ty) = (
                m.complementary_at(x, xi, [1.0, 0.0]).0,
                m.complementary_at(x, xi, [0.0, 1.0]).0,
            );
            let sxx = (lambda + 2.0 * g) * exx + lambda * eyy;
            let syy = lambda * exx + (lambda + 2.0 * g) * eyy;
            let sxy = g * gxy;
            let scale = tx[f][0].abs().max(ty[f][1].abs()).max(tx[f][1].abs());
            for (got, want) in [(sxx, tx[f][0]), (sxy, tx[f][1]), (syy, ty[f][1])] {
                assert!((got - want).abs() < 1e-6 * scale, "{x:?} {f}: {got} {want}");
            }
            let div = [
                dt([1.0, 0.0], [1.0, 0.0], f, 0) + dt([0.0, 1.0], [1.0, 0.0], f, 1),
                dt([1.0, 0.0], [1.0, 0.0], f, 1) + dt([0.0, 1.0], [0.0, 1.0], f, 1),
            ];
            assert!(div[0].abs().max(div[1].abs()) < 1e-5 * scale, "{div:?}");
        }
    }
}

/// Deep below the surface, near the force, Melan's traction is Kelvin's: the complementary
/// part falls as the ratio of distance to depth.
#[test]
fn deep_down_it_is_kelvins() {
    for depth in [10.0, 100.0, 1000.0] {
        let m = Melan {
            surface: depth,
            ..half_plane()
        };
        let (x, xi, n) = ([0.6, 0.8], [0.0, 0.0], [0.6, 0.8]);
        let (t, k) = (m.traction_at(x, xi, n), m.kelvin.traction_at(x, xi, n));
        let off = (0..2)
            .flat_map(|i| (0..2).map(move |j| (i, j)))
            .map(|(i, j)| (t[i][j] - k[i][j]).abs())
            .fold(0.0, f64::max);
        assert!(off < 2.0 / depth * k[0][0].abs(), "{depth}: {off}");
    }
}
