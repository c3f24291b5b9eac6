//! The far field's stiffness against the closed forms of a circular hole in an infinite plane.

use super::*;

const SHEAR: f64 = 4e9;

fn medium(poisson: f64) -> Medium {
    Medium {
        shear: SHEAR,
        poisson,
    }
}

/// `count` points on a circle of `radius` (m) about `centre`, counter-clockwise.
fn circle(count: usize, radius: f64, centre: [f64; 2]) -> Vec<[f64; 2]> {
    (0..count)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / count as f64;
            [centre[0] + radius * a.cos(), centre[1] + radius * a.sin()]
        })
        .collect()
}

/// The largest relative difference of the forces K u on a circle's nodes from `expected`.
fn worst(k: &InterfaceStiffness, u: &[[f64; 2]], expected: &[[f64; 2]]) -> f64 {
    let mut f = vec![[0.0; 2]; u.len()];
    k.forces(u, &mut f);
    let scale = expected
        .iter()
        .map(|e| e[0].hypot(e[1]))
        .fold(0.0, f64::max);
    (f.iter().zip(expected))
        .map(|(f, e)| (-f[0] - e[0]).hypot(-f[1] - e[1]) / scale)
        .fold(0.0, f64::max)
}

/// A hole of radius a whose wall moves by u₀ radially (Lamé's cavity) or turns by u₀ (the
/// rotation mode, u_θ = u₀ a/r): both take the traction 2G u₀/a from the medium outside, whatever
/// ν, so each node of a polygon of edges L carries 2G u₀ L/a. Within 0.3 % at 64 nodes, and
/// closer with more; the polygon's orientation and the circle's place and size do not matter.
#[test]
fn a_circular_hole_takes_the_traction_of_its_closed_form() {
    let u0 = 1e-3;
    let mut errors = Vec::new();
    for (count, radius, centre, poisson, reversed) in [
        (32, 1.0, [0.0, 0.0], 0.25, false),
        (64, 1.0, [0.0, 0.0], 0.25, false),
        (64, 3.5, [10.0, -4.0], 0.1, true),
        (128, 1.0, [0.0, 0.0], 0.45, false),
    ] {
        let mut points = circle(count, radius, centre);
        if reversed {
            points.reverse();
        }
        let k = interface_stiffness(&points, medium(poisson)).unwrap();
        let edge = (points[1][0] - points[0][0]).hypot(points[1][1] - points[0][1]);
        let per_node = 2.0 * SHEAR * u0 * edge / radius;
        let radial: Vec<[f64; 2]> = (points.iter())
            .map(|p| {
                let (x, y) = (p[0] - centre[0], p[1] - centre[1]);
                let r = x.hypot(y);
                [x / r, y / r]
            })
            .collect();
        let u: Vec<[f64; 2]> = radial.iter().map(|e| [u0 * e[0], u0 * e[1]]).collect();
        let expected: Vec<[f64; 2]> = radial
            .iter()
            .map(|e| [per_node * e[0], per_node * e[1]])
            .collect();
        let radial_error = worst(&k, &u, &expected);
        let turn = |v: &[f64; 2]| [-v[1], v[0]];
        let u: Vec<[f64; 2]> = u.iter().map(turn).collect();
        let expected: Vec<[f64; 2]> = expected.iter().map(turn).collect();
        let rotation_error = worst(&k, &u, &expected);
        eprintln!(
            "{count} nodes, ν = {poisson}: radial {radial_error:.2e}, rotation {rotation_error:.2e}"
        );
        errors.push((count, radial_error.max(rotation_error)));
    }
    assert!(errors[1].1 < 3e-3, "{errors:?}");
    assert!(errors[0].1 > errors[1].1, "{errors:?}");
    assert!(errors.iter().all(|e| e.1 < 1e-2), "{errors:?}");
}

/// Work is stored, not made: uᵀ K u > 0 for any displacement of a box's boundary, and K is
/// nearly symmetric (collocation is not exactly).
#[test]
fn the_stiffness_stores_work_and_is_nearly_symmetric() {
    let mut points = Vec::new();
    for k in 0..10 {
        points.push([-5.0 + k as f64, -5.0]);
    }
    for k in 0..10 {
        points.push([5.0, -5.0 + k as f64]);
    }
    for k in 0..10 {
        points.push([5.0 - k as f64, 5.0]);
    }
    for k in 0..10 {
        points.push([-5.0, 5.0 - k as f64]);
    }
    let k = interface_stiffness(&points, medium(0.3)).unwrap();
    let n2 = 2 * k.nodes;
    let (mut asym, mut size) = (0.0f64, 0.0f64);
    for r in 0..n2 {
        for c in 0..n2 {
            asym = asym.max((k.k[r * n2 + c] - k.k[c * n2 + r]).abs());
            size = size.max(k.k[r * n2 + c].abs());
        }
    }
    eprintln!("largest asymmetry {:.2e} of the largest entry", asym / size);
    assert!(asym < 0.1 * size, "{asym} {size}");
    let mut seed = 12345u64;
    let mut random = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    for _ in 0..50 {
        let u: Vec<[f64; 2]> = (0..k.nodes).map(|_| [random(), random()]).collect();
        let mut f = vec![[0.0; 2]; k.nodes];
        k.forces(&u, &mut f);
        let work: f64 = -(f.iter().zip(&u))
            .map(|(f, u)| f[0] * u[0] + f[1] * u[1])
            .sum::<f64>();
        assert!(work > 0.0, "{work}");
    }
}

/// An interface that cannot bound a far field is refused, naming why.
#[test]
fn a_bad_interface_is_refused() {
    let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let cases: [(&[[f64; 2]], f64, f64, &str); 4] = [
        (&square[..2], SHEAR, 0.25, "fewer than 3"),
        (
            &[[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
            SHEAR,
            0.25,
            "coincide",
        ),
        (&square, SHEAR, 0.5, "Poisson"),
        (&square, -1.0, 0.25, "shear modulus"),
    ];
    for (points, shear, poisson, reason) in cases {
        let e = interface_stiffness(points, Medium { shear, poisson }).unwrap_err();
        assert!(e.contains(reason), "{e}");
    }
}

/// A translation of the interface costs no force (the infinite medium moves with it), and K
/// does not depend on the length unit: a circle scaled by 10⁻² or 10³ (through the degenerate
/// scale of Kelvin's ln r, about a metre) has the same K.
#[test]
fn translation_is_free_and_the_size_does_not_matter() {
    let reference = interface_stiffness(&circle(48, 1.0, [0.0, 0.0]), medium(0.3)).unwrap();
    let size = reference.k.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for scale in [0.01, 0.6, 1.0, 1.2, 1000.0] {
        let k = interface_stiffness(&circle(48, scale, [0.0, 0.0]), medium(0.3)).unwrap();
        let worst = (k.k.iter().zip(&reference.k))
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(worst < 1e-8 * size, "scale {scale}: {worst} of {size}");
        let mut f = vec![[0.0; 2]; k.nodes];
        k.forces(&vec![[1e-3, -2e-3]; k.nodes], &mut f);
        let most = f.iter().map(|f| f[0].hypot(f[1])).fold(0.0, f64::max);
        assert!(most < 1e-9 * size * 1e-3, "scale {scale}: {most}");
    }
}

/// Two nodes at one place (the sides of a joint reaching the interface) each take the force of
/// their own elements: moved together they carry what the one node of the undivided interface
/// carries, and the others are as if it were one.
#[test]
fn two_nodes_at_one_place_share_their_node_s_force() {
    let points = circle(40, 2.0, [0.0, 0.0]);
    let whole = interface_stiffness(&points, medium(0.25)).unwrap();
    let mut split_points = points.clone();
    split_points.push(points[0]);
    let mut edges: Vec<[usize; 2]> = (0..39).map(|i| [i, i + 1]).collect();
    edges.push([39, 40]);
    let split = interface_stiffness_on(&split_points, &edges, medium(0.25)).unwrap();
    let u: Vec<[f64; 2]> = (0..40)
        .map(|i| [1e-3 * (i as f64).sin(), 2e-4 * i as f64])
        .collect();
    let mut u_split = u.clone();
    u_split.push(u[0]);
    let (mut f, mut fs) = (vec![[0.0; 2]; 40], vec![[0.0; 2]; 41]);
    whole.forces(&u, &mut f);
    split.forces(&u_split, &mut fs);
    let scale = f.iter().map(|f| f[0].hypot(f[1])).fold(0.0, f64::max);
    let joined = [fs[0][0] + fs[40][0], fs[0][1] + fs[40][1]];
    assert!((joined[0] - f[0][0]).hypot(joined[1] - f[0][1]) < 1e-9 * scale);
    for i in 1..40 {
        assert!(
            (fs[i][0] - f[i][0]).hypot(fs[i][1] - f[i][1]) < 1e-9 * scale,
            "{i}"
        );
    }
}

/// Elements longer than the edges between nodes: on a box whose sides carry nodes every 0.25 m,
/// elements of 1 m (chains of five nodes) store the work the same elements do on the box with
/// nodes at their ends only, for any displacement linear along each element; a bent chain is
/// refused.
#[test]
fn elements_over_several_nodes_store_the_work_of_their_ends() {
    let (side, per) = (4usize, 4usize);
    // The box's corner-to-corner path, counter-clockwise, at `step` points per metre.
    let path = |step: usize| -> Vec<[f64; 2]> {
        let mut p = Vec::new();
        for s in 0..4 {
            for k in 0..side * step {
                let t = k as f64 / step as f64;
                p.push(match s {
                    0 => [t, 0.0],
                    1 => [side as f64, t],
                    2 => [side as f64 - t, side as f64],
                    _ => [0.0, side as f64 - t],
                });
            }
        }
        p
    };
    let (coarse, fine) = (path(1), path(per));
    let n = coarse.len();
    let chains: Vec<Vec<usize>> = (0..n)
        .map(|e| (0..=per).map(|k| (e * per + k) % fine.len()).collect())
        .collect();
    let k_fine = interface_stiffness_chains(&fine, &chains, medium(0.3)).unwrap();
    let k_coarse = interface_stiffness(&coarse, medium(0.3)).unwrap();
    let u: Vec<[f64; 2]> = (0..n)
        .map(|i| [1e-3 * (i as f64 * 0.7).sin(), 1e-3 * (i as f64 * 1.3).cos()])
        .collect();
    let u_fine: Vec<[f64; 2]> = (0..fine.len())
        .map(|j| {
            let (e, t) = (j / per, (j % per) as f64 / per as f64);
            let (a, b) = (u[e], u[(e + 1) % n]);
            [(1.0 - t) * a[0] + t * b[0], (1.0 - t) * a[1] + t * b[1]]
        })
        .collect();
    let work = |k: &InterfaceStiffness, u: &[[f64; 2]]| {
        let mut f = vec![[0.0; 2]; u.len()];
        k.forces(u, &mut f);
        -(f.iter().zip(u))
            .map(|(f, u)| f[0] * u[0] + f[1] * u[1])
            .sum::<f64>()
    };
    let (wf, wc) = (work(&k_fine, &u_fine), work(&k_coarse, &u));
    assert!((wf - wc).abs() < 1e-9 * wc.abs(), "{wf} {wc}");
    let mut bent = fine.clone();
    bent[2][1] += 0.01;
    let e = interface_stiffness_chains(&bent, &chains, medium(0.3)).unwrap_err();
    assert!(e.contains("element 0 is not straight"), "{e}");
}

/// The same interface gives the same K, bit for bit, on one thread and on two (the dense solve
/// runs on the calling thread; the forces' rows each sum in order).
#[test]
fn the_stiffness_does_not_depend_on_the_thread_count() {
    let points = circle(96, 3.0, [1.0, 2.0]);
    let on = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| interface_stiffness(&points, medium(0.3)).unwrap().k)
    };
    assert!(on(1) == on(2));
}
