//! The far field's stiffness against the closed forms of a circular hole in an infinite plane.

use super::*;

const SHEAR: f64 = 4e9;

fn medium(poisson: f64) -> Medium {
    Medium::isotropic(SHEAR, poisson)
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
        let e = interface_stiffness(points, Medium::isotropic(shear, poisson)).unwrap_err();
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

/// Elements of any length store no negative work, for any displacement of their nodes, not
/// only one linear along each element: the symmetric part of K is positive semi-definite (its
/// least eigenvalue above −1e-9 of its largest) on boxes whose sides carry unevenly spaced nodes,
/// cut into elements of 1 to 6 edges at random, in intact, jointed and half-plane rock (an open
/// interface of three sides under the surface). Sampling a chain's displacement at the
/// collocation points (before the projection, `interface_stiffness_chains`) gave least
/// eigenvalues down to −23 % of the largest with elements of 3 edges or more.
#[test]
fn elements_of_any_length_store_no_negative_work() {
    use nalgebra::DMatrix;
    let mut seed = 2024u64;
    let mut random = move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let surface = 4.0;
    let jointed = {
        let set = |dip: f64, spacing: f64| JointSet {
            dip,
            spacing,
            normal_stiffness: 5e9,
            shear_stiffness: 1e9,
        };
        let b = jointed_compliance(
            plane_strain_compliance(2.0 * SHEAR * 1.25, 0.25),
            &[set(35.0, 1.0), set(110.0, 1.5)],
        );
        Medium::anisotropic(b).unwrap()
    };
    let media = [
        medium(0.25),
        jointed,
        Medium::HalfPlane(Melan {
            kelvin: Kelvin {
                shear: SHEAR,
                poisson: 0.3,
            },
            surface,
        }),
    ];
    for case in 0..12 {
        let m = &media[case % 3];
        let half_plane = matches!(m, Medium::HalfPlane(_));
        // The box's corners, counter-clockwise; under a half-plane the top side is the surface
        // and stays free: the interface runs from its left end down, across and up.
        let corners: Vec<[f64; 2]> = if half_plane {
            vec![
                [-5.0, surface],
                [-5.0, surface - 8.0],
                [5.0, surface - 8.0],
                [5.0, surface],
            ]
        } else {
            vec![[-5.0, -4.0], [5.0, -4.0], [5.0, 4.0], [-5.0, 4.0]]
        };
        let sides = if half_plane { 3 } else { 4 };
        let (mut points, mut chains) = (Vec::new(), Vec::new());
        for s in 0..sides {
            let (a, b) = (corners[s], corners[(s + 1) % 4]);
            // Unevenly spaced nodes along the side (its start included, its end the next's).
            let count = 6 + (random() * 14.0) as usize;
            let mut t: Vec<f64> = (1..count).map(|_| random()).collect();
            t.push(0.0);
            t.sort_by(f64::total_cmp);
            let first = points.len();
            points.extend(
                t.iter()
                    .map(|&t| [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]),
            );
            let end = if !half_plane || s + 1 < sides {
                first + count
            } else {
                points.push(b);
                first + count
            };
            let mut i = first;
            while i < end {
                let j = (i + 1 + (random() * 6.0) as usize).min(end);
                chains.push((i..=j).collect::<Vec<usize>>());
                i = j;
            }
        }
        let n = points.len();
        if !half_plane {
            // The last chain closes the loop on the first point.
            for c in &mut chains {
                for p in c.iter_mut() {
                    *p %= n;
                }
            }
        }
        let k = interface_stiffness_chains(&points, &chains, m.clone()).unwrap();
        let kk = DMatrix::from_fn(2 * n, 2 * n, |r, c| k.k[r * 2 * n + c]);
        let eigen = ((&kk + kk.transpose()) * 0.5).symmetric_eigenvalues();
        let (least, most) = (eigen.min(), eigen.max());
        let longest = chains.iter().map(Vec::len).max().unwrap_or(0) - 1;
        assert!(
            least > -1e-9 * most,
            "case {case}: {} elements of up to {longest} edges: least eigenvalue {least:.3e}, \
             largest {most:.3e}",
            chains.len()
        );
    }
}

/// The net load a far field carries (`FarField::carry`): the field of a line force N at a point
/// inside the interface loads the interface's nodes by −N in all (to 1e-6, the hats' quadrature),
/// with no moment about the point (to 1e-4 of N times the radius), and moves them by the
/// medium's displacement there; in intact rock and in a half-plane (a circle below the surface),
/// the point off the centre. No load, no change.
#[test]
fn a_far_field_carries_a_net_load_as_a_line_force() {
    let surface = 10.0;
    let media = [
        medium(0.25),
        Medium::HalfPlane(Melan {
            kelvin: Kelvin {
                shear: SHEAR,
                poisson: 0.3,
            },
            surface,
        }),
    ];
    for m in media {
        let (radius, centre) = (3.0, [1.0, 2.0]);
        let points = circle(96, radius, centre);
        let n = points.len();
        let mut far = FarField {
            nodes: (0..n as u32).collect(),
            stiffness: interface_stiffness(&points, m.clone()).unwrap(),
            in_situ: vec![[0.0; 2]; n],
            attached: vec![[0.0; 2]; n],
            assemble_s: 0.0,
            stretch: 1.0,
            medium: m.clone(),
            positions: points.clone(),
            edges: (0..n).map(|i| [i, (i + 1) % n]).collect(),
            carried: vec![[0.0; 2]; n],
            carried_disp: vec![[0.0; 2]; n],
        };
        let (net, at) = ([3e5, -2e5], [1.8, 1.1]);
        far.carry(net, at);
        let total = far
            .carried
            .iter()
            .fold([0.0; 2], |s, f| [s[0] + f[0], s[1] + f[1]]);
        let size = net[0].hypot(net[1]);
        assert!(
            (total[0] + net[0]).hypot(total[1] + net[1]) < 1e-6 * size,
            "{total:?} against {net:?}"
        );
        let moment: f64 = (points.iter().zip(&far.carried))
            .map(|(p, f)| (p[0] - at[0]) * f[1] - (p[1] - at[1]) * f[0])
            .sum();
        assert!(moment.abs() < 1e-4 * size * radius, "{moment}");
        let g = m.displacement_at(points[7], at);
        let u = [
            net[0] * g[0][0] + net[1] * g[1][0],
            net[0] * g[0][1] + net[1] * g[1][1],
        ];
        assert_eq!(far.carried_disp[7], u);
        far.carry([0.0; 2], at);
        assert!(
            far.carried
                .iter()
                .chain(&far.carried_disp)
                .all(|v| *v == [0.0; 2])
        );
    }
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

/// The nodal forces ∫ N_a t ds on the closed polygon `points` (counter-clockwise, the medium
/// outside) of the exact field of unit forces `forces` (at ξ, along e) inside it: t the
/// traction on the medium, whose outward normal points into the polygon.
fn nodal_forces_of(
    m: &Medium,
    points: &[[f64; 2]],
    forces: &[([f64; 2], [f64; 2])],
) -> Vec<[f64; 2]> {
    let n = points.len();
    let edges: Vec<[usize; 2]> = (0..n).map(|a| [a, (a + 1) % n]).collect();
    nodal_forces_on(m, points, &edges, forces)
}

/// `nodal_forces_of` on the edges `edges` (each from its first point to its second, the medium
/// to their right).
fn nodal_forces_on(
    m: &Medium,
    points: &[[f64; 2]],
    edges: &[[usize; 2]],
    forces: &[([f64; 2], [f64; 2])],
) -> Vec<[f64; 2]> {
    let mut out = vec![[0.0; 2]; points.len()];
    let steps = 400;
    for &[a, b] in edges {
        let (p, q) = (points[a], points[b]);
        let len = (q[0] - p[0]).hypot(q[1] - p[1]);
        let normal = [-(q[1] - p[1]) / len, (q[0] - p[0]) / len];
        for s in 0..steps {
            let w = (s as f64 + 0.5) / steps as f64;
            let x = [p[0] + w * (q[0] - p[0]), p[1] + w * (q[1] - p[1])];
            let mut t = [0.0; 2];
            for (xi, e) in forces {
                let k = m.traction_at(x, *xi, normal);
                for (i, ei) in e.iter().enumerate() {
                    for (j, tj) in t.iter_mut().enumerate() {
                        *tj += ei * k[i][j];
                    }
                }
            }
            for d in 0..2 {
                out[a][d] += (1.0 - w) * t[d] * len / steps as f64;
                out[b][d] += w * t[d] * len / steps as f64;
            }
        }
    }
    out
}

/// The displacement at `x` of the unit forces `forces`, m per N/m.
fn displacement_of(m: &Medium, x: [f64; 2], forces: &[([f64; 2], [f64; 2])]) -> [f64; 2] {
    let mut u = [0.0; 2];
    for (xi, e) in forces {
        let k = m.displacement_at(x, *xi);
        for (i, ei) in e.iter().enumerate() {
            for (j, uj) in u.iter_mut().enumerate() {
                *uj += ei * k[i][j];
            }
        }
    }
    u
}

/// Outside a circle, the far field of an anisotropic rock mass (the jointed tunnel's, and a
/// strongly skewed one) takes the tractions of an exact field of that medium: two pairs of
/// opposite unit forces inside the hole, which carry no net force, so the field dies away and the
/// exterior problem holds it. K u on the nodes' exact displacements gives the hat-weighted
/// integrals of the exact traction (the largest difference, relative to the largest force).
/// Measured at 64, 128 and 256 nodes: isotropic 7.7e-3, 2.0e-3, 4.9e-4; jointed 9.5e-3, 2.5e-3,
/// 6.2e-4 (both as h²); skewed (a soft set at 20°, whose z_k stretch distances elevenfold, so
/// the sources 0.7 m inside the wall seem 0.06 m away) 1.5e-1, 8.6e-2, 3.6e-2, and 1.2e-2 at 512.
#[test]
fn an_anisotropic_far_field_takes_the_tractions_of_an_exact_field() {
    use crate::far_field::lekhnitskii::tests::jointed;
    let forces = [
        ([0.25, 0.1], [1.0, 0.0]),
        ([-0.25, -0.1], [-1.0, 0.0]),
        ([0.1, -0.3], [0.0, 1.0]),
        ([-0.1, 0.3], [0.0, -1.0]),
    ];
    let skewed = Lekhnitskii::new(jointed_compliance(
        plane_strain_compliance(30e9, 0.2),
        &[JointSet {
            dip: 20.0,
            spacing: 0.5,
            normal_stiffness: 5e9,
            shear_stiffness: 5e8,
        }],
    ))
    .unwrap();
    for (name, m, bound) in [
        ("isotropic", medium(0.25), 2.5e-3),
        ("jointed", Medium::Anisotropic(Box::new(jointed())), 2.5e-3),
        ("skewed", Medium::Anisotropic(Box::new(skewed)), 4e-2),
    ] {
        let mut errors = Vec::new();
        for count in [64, 128, 256] {
            let points = circle(count, 1.0, [0.0, 0.0]);
            let k = interface_stiffness(&points, m.clone()).unwrap();
            let u: Vec<[f64; 2]> = points
                .iter()
                .map(|&p| displacement_of(&m, p, &forces))
                .collect();
            let expected = nodal_forces_of(&m, &points, &forces);
            errors.push(worst(&k, &u, &expected));
        }
        eprintln!("{name}: 64, 128, 256 nodes: {errors:?}");
        assert!(
            errors[2] < bound && errors[2] < errors[1] && errors[1] < errors[0],
            "{name}"
        );
    }
}

/// For random rock masses (one to three sets of random dip, spacing 0.2–10 m, kₙ 1e8–1e11 Pa/m,
/// kₛ up to a hundred times softer), K on a circle of 64 and then 128 nodes, given the exact
/// displacement of two pairs of opposite forces near its centre, returns their tractions ever
/// closer. The error grows with the medium's stretch (`Kernel::stretch`: the field varies that
/// much faster along the wall): measured about 0.14 % × stretch² at 128 nodes (0.27 % at 1.41,
/// 1.1 % at 2.8, 2.2 % at 4.2; slower than h² beyond, 16 % at 44), asserted below 0.2 % × stretch².
#[test]
fn random_rock_masses_take_the_tractions_of_an_exact_field() {
    let forces = [
        ([0.05, 0.02], [1.0, 0.0]),
        ([-0.05, -0.02], [-1.0, 0.0]),
        ([0.02, -0.06], [0.0, 1.0]),
        ([-0.02, 0.06], [0.0, -1.0]),
    ];
    let mut seed = 2024u64;
    let mut random = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for case in 0..24 {
        let sets: Vec<JointSet> = (0..1 + (3.0 * random()) as usize)
            .map(|_| {
                let kn = 10f64.powf(8.0 + 3.0 * random());
                JointSet {
                    dip: 180.0 * random(),
                    spacing: 0.2 + 9.8 * random(),
                    normal_stiffness: kn,
                    shear_stiffness: kn / 10f64.powf(2.0 * random()),
                }
            })
            .collect();
        let b = jointed_compliance(
            plane_strain_compliance(1e9 + 99e9 * random(), 0.45 * random()),
            &sets,
        );
        let m = Medium::anisotropic(b).unwrap();
        let stretch = m.stretch();
        let errors: Vec<f64> = [64, 128]
            .iter()
            .map(|&count| {
                let points = circle(count, 1.0, [0.0, 0.0]);
                let k = interface_stiffness(&points, m.clone()).unwrap();
                let u: Vec<[f64; 2]> = (points.iter())
                    .map(|&p| displacement_of(&m, p, &forces))
                    .collect();
                worst(&k, &u, &nodal_forces_of(&m, &points, &forces))
            })
            .collect();
        eprintln!(
            "case {case}: {} sets, stretch {stretch:.2}: {errors:?}",
            sets.len()
        );
        assert!(errors[1] < errors[0], "case {case}: {errors:?}");
        assert!(
            errors[1] < 2e-3 * stretch * stretch,
            "case {case}: stretch {stretch}, {errors:?}"
        );
    }
}

/// A half-plane's far field on an open interface, a half-circle below the surface from one
/// surface point to the other (the near field the half-disc inside, the rest of the surface
/// free): given the exact displacement of two pairs of opposite forces in the half-disc (Melan's
/// field, which leaves the surface free), K returns their tractions, within 1 % of the largest at
/// 64 elements and ever closer (measured 6.8e-3, 1.8e-3 and 4.4e-4 at 64, 128 and 256: h²).
#[test]
fn a_half_plane_far_field_takes_the_tractions_of_an_exact_field() {
    let surface = 3.0;
    let m = Medium::HalfPlane(Melan {
        kelvin: Kelvin {
            shear: SHEAR,
            poisson: 0.3,
        },
        surface,
    });
    let forces = [
        ([0.25, surface - 0.5], [1.0, 0.0]),
        ([-0.25, surface - 0.4], [-1.0, 0.0]),
        ([0.1, surface - 0.3], [0.0, 1.0]),
        ([-0.1, surface - 0.6], [0.0, -1.0]),
    ];
    let mut errors = Vec::new();
    for count in [64, 128, 256] {
        // From (−1, surface) under the centre to (1, surface): count elements, count + 1 nodes.
        let points: Vec<[f64; 2]> = (0..=count)
            .map(|k| {
                let a = std::f64::consts::PI * (1.0 + k as f64 / count as f64);
                [a.cos(), surface + a.sin()]
            })
            .collect();
        let edges: Vec<[usize; 2]> = (0..count).map(|i| [i, i + 1]).collect();
        let k = interface_stiffness_on(&points, &edges, m.clone()).unwrap();
        let u: Vec<[f64; 2]> = points
            .iter()
            .map(|&p| displacement_of(&m, p, &forces))
            .collect();
        let expected = nodal_forces_on(&m, &points, &edges, &forces);
        errors.push(worst(&k, &u, &expected));
    }
    eprintln!("half-plane: 64, 128, 256 elements: {errors:?}");
    assert!(
        errors[0] < 1e-2 && errors[1] < errors[0] && errors[2] < errors[1],
        "{errors:?}"
    );
}
