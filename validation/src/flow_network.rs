//! Flow networks of fixed apertures (issue 51) against answers written here: a joint between two
//! pressures by the cubic law (Q = a³Δp/(12μL)), and a grid of two orthogonal joint sets (domains
//! at the intersections, pipes along the joints) against a dense solve of its own Laplacian and,
//! with equal apertures, against Snow's equivalent medium.

use std::time::Instant;

use adit::flow::{DomainId, Fluid, Network, Transient, solve_steady};

/// The grid's joints are this far apart, m.
pub const SPACING: f64 = 2.0;
/// The pressure held on the grid's left side, Pa (its right side at 0).
pub const PRESSURE: f64 = 1e6;

/// A grid of `n` × `n` intersections of two orthogonal joint sets `SPACING` apart, its left
/// column held at `PRESSURE`, its right at 0, top and bottom sealed; apertures from `aperture`
/// (pipe index → m). Gravity is off in it (a horizontal section through the rock).
pub fn grid(n: usize, aperture: impl Fn(usize) -> f64) -> Network {
    let mut net = Network::default();
    let id = |i: usize, j: usize| DomainId((i * n + j) as u32);
    for _ in 0..n * n {
        net.add_domain(1e-4 * SPACING, 0.0, 0.0);
    }
    for i in 0..n {
        for j in 0..n {
            if j + 1 < n {
                let k = net.pipes.len();
                net.add_pipe(id(i, j), id(i, j + 1), aperture(k), SPACING);
            }
            if i + 1 < n {
                let k = net.pipes.len();
                net.add_pipe(id(i, j), id(i + 1, j), aperture(k), SPACING);
            }
        }
    }
    for i in 0..n {
        net.fix(id(i, 0), PRESSURE);
        net.fix(id(i, n - 1), 0.0);
    }
    net
}

/// Apertures spread log-uniformly over `decades` decades above 1e-5 m, from a fixed seed.
pub fn random_apertures(seed: u64, decades: f64) -> impl Fn(usize) -> f64 {
    move |k| {
        let mut s = seed ^ (k as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        s ^= s >> 33;
        s = s.wrapping_mul(0xff51_afd7_ed55_8ccd);
        s ^= s >> 33;
        s = s.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
        s ^= s >> 33;
        let u = (s >> 11) as f64 / (1u64 << 53) as f64;
        1e-5 * 10f64.powf(decades * u)
    }
}

/// The flow into the right side (m²/s per metre): the sum of the flows of the pipes into its
/// held domains.
pub fn outflow(net: &Network, fluid: &Fluid) -> f64 {
    let mut c = vec![0.0; net.pipes.len()];
    let mut h = vec![0.0; net.domains.len()];
    let mut q = vec![0.0; net.pipes.len()];
    net.conductances(fluid, &mut c);
    net.heads(fluid, 0.0, &mut h);
    net.flows(&c, &h, &mut q);
    let d = &net.domains;
    let into_right = |i: usize| d.fixed[i] && d.pressure[i] == 0.0;
    (net.pipes.ends.iter().zip(&q))
        .map(|(&[a, b], &q)| {
            let (a, b) = (a.0 as usize, b.0 as usize);
            if into_right(b) && !into_right(a) {
                q
            } else if into_right(a) && !into_right(b) {
                -q
            } else {
                0.0
            }
        })
        .sum()
}

/// The steady pressures by a dense LU solve of the network's Laplacian over its free domains,
/// built here entry by entry (no gravity).
pub fn dense_pressures(net: &Network, fluid: &Fluid) -> Vec<f64> {
    dense(net, fluid).0
}

/// The largest pressure error (Pa) a flow ratio `ratio` admits when the ratio's denominator was
/// `largest_flow` m²/s: the unbalanced inflows r are at most `ratio` × `largest_flow`, and the
/// pressures' error e = L⁻¹ r is at most ‖L⁻¹‖∞ times them (L the dense Laplacian).
pub fn admitted_error(net: &Network, fluid: &Fluid, ratio: f64, largest_flow: f64) -> f64 {
    ratio * largest_flow * dense(net, fluid).1
}

/// The dense solve's pressures and ‖L⁻¹‖∞, m²/(Pa·s) inverted.
fn dense(net: &Network, fluid: &Fluid) -> (Vec<f64>, f64) {
    let n = net.domains.len();
    let mut free = 0;
    let index: Vec<usize> = (net.domains.fixed.iter())
        .map(|&held| {
            if held {
                usize::MAX
            } else {
                free += 1;
                free - 1
            }
        })
        .collect();
    let mut k = nalgebra::DMatrix::<f64>::zeros(free, free);
    let mut b = nalgebra::DVector::<f64>::zeros(free);
    for p in 0..net.pipes.len() {
        let [x, y] = net.pipes.ends[p].map(|d| d.0 as usize);
        let a = net.pipes.aperture[p];
        let c = a * a * a / (12.0 * fluid.viscosity * net.pipes.length[p]);
        for (u, v) in [(x, y), (y, x)] {
            if index[u] == usize::MAX {
                continue;
            }
            k[(index[u], index[u])] += c;
            if index[v] == usize::MAX {
                b[index[u]] += c * net.domains.pressure[v];
            } else {
                k[(index[u], index[v])] -= c;
            }
        }
    }
    let lu = k.lu();
    let x = lu.solve(&b).expect("a grid joined to its held sides");
    let inverse = lu.try_inverse().expect("a grid joined to its held sides");
    let norm = (inverse.row_iter())
        .map(|r| r.iter().map(|v| v.abs()).sum::<f64>())
        .fold(0.0, f64::max);
    let p = (0..n)
        .map(|i| {
            if index[i] == usize::MAX {
                net.domains.pressure[i]
            } else {
                x[index[i]]
            }
        })
        .collect();
    (p, norm)
}

/// The largest difference of two pressure fields over `PRESSURE`.
pub fn worst(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs() / PRESSURE)
        .fold(0.0, f64::max)
}

/// An explicit run of `net` at its stable step to the flow ratio `ratio`: the steps, the
/// seconds it took and the ratio's denominator (the largest flow it saw, m²/s).
pub fn run_explicit(
    net: &mut Network,
    fluid: &Fluid,
    ratio: f64,
) -> anyhow::Result<(usize, f64, f64)> {
    let start = Instant::now();
    let mut t = Transient::new(net, fluid, 0.0).map_err(anyhow::Error::msg)?;
    let steps = (t.run_to_ratio(net, t.limit, ratio, 50_000_000)).map_err(anyhow::Error::msg)?;
    Ok((steps, start.elapsed().as_secs_f64(), t.largest_flow()))
}

/// A joint of aperture `aperture` m and length `length` m between a held `PRESSURE` and 0, as
/// `domains` domains in a row (each over an equal part of it) between the two held ends.
pub fn joint(domains: usize, aperture: f64, length: f64) -> Network {
    let mut net = Network::default();
    let part = length / domains as f64;
    let ids: Vec<DomainId> = (0..domains + 2)
        .map(|_| net.add_domain(aperture * part, 0.0, 0.0))
        .collect();
    for k in 0..=domains {
        let l = if k == 0 || k == domains {
            part / 2.0
        } else {
            part
        };
        net.add_pipe(ids[k], ids[k + 1], aperture, l);
    }
    net.fix(ids[0], PRESSURE);
    net.fix(ids[domains + 1], 0.0);
    net
}

/// A joint of aperture `aperture` m as a row of domains `part` m apart (domain k at x = k `part`,
/// `domains` of them after the first), at rest at zero pressure, its first domain (x = 0) held
/// at `PRESSURE` from t = 0 and its far end sealed.
pub fn diffusion(domains: usize, part: f64, aperture: f64) -> Network {
    let mut net = Network::default();
    let ids: Vec<DomainId> = (0..=domains)
        .map(|_| net.add_domain(aperture * part, 0.0, 0.0))
        .collect();
    for w in ids.windows(2) {
        net.add_pipe(w[0], w[1], aperture, part);
    }
    net.fix(ids[0], PRESSURE);
    net
}

/// The diffusivity of a rigid joint of aperture `a` m: its transmissivity a³/(12μ) over its
/// storage a/Kw, D = a² Kw / (12 μ), m²/s.
pub fn diffusivity(a: f64, fluid: &Fluid) -> f64 {
    a * a * fluid.bulk_modulus / (12.0 * fluid.viscosity)
}

/// The complementary error function, erfc x = 1 − erf x, to a fractional error below 1.2e-7
/// (the Chebyshev fit of Press et al., Numerical Recipes, 2nd ed., §6.2, `erfcc`).
pub fn erfc(x: f64) -> f64 {
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let poly = [
        -1.265_512_23,
        1.000_023_68,
        0.374_091_96,
        0.096_784_18,
        -0.186_288_06,
        0.278_868_07,
        -1.135_203_98,
        1.488_515_87,
        -0.822_152_23,
        0.170_872_77,
    ]
    .iter()
    .rev()
    .fold(0.0, |acc, c| acc * t + c);
    let r = t * (-z * z + poly).exp();
    if x >= 0.0 { r } else { 2.0 - r }
}

/// The diffusion joint (`diffusion`, `part` m domains, 1e-4 m aperture, 60 m long) run
/// explicitly to each of `times` (s, rising) by equal steps within the stable step: at each, the
/// largest difference from p₀ erfc(x / 2√(Dt)) over p₀; with the steps taken and the seconds.
pub fn diffusion_errors(
    part: f64,
    times: &[f64],
    fluid: &Fluid,
) -> anyhow::Result<(Vec<f64>, usize, f64)> {
    let start = Instant::now();
    let aperture = 1e-4;
    let mut net = diffusion((60.0 / part) as usize, part, aperture);
    let mut t = Transient::new(&net, fluid, 0.0).map_err(anyhow::Error::msg)?;
    let d = diffusivity(aperture, fluid);
    let (mut now, mut steps, mut errors) = (0.0, 0, Vec::new());
    for &until in times {
        let n = ((until - now) / t.limit).ceil();
        let dt = (until - now) / n;
        for _ in 0..n as usize {
            t.step(&mut net, dt).map_err(anyhow::Error::msg)?;
        }
        (now, steps) = (until, steps + n as usize);
        let exact = |x: f64| PRESSURE * erfc(x / (2.0 * (d * now).sqrt()));
        let worst = (net.domains.pressure.iter().enumerate())
            .map(|(k, p)| (p - exact(k as f64 * part)).abs() / PRESSURE)
            .fold(0.0, f64::max);
        errors.push(worst);
    }
    Ok((errors, steps, start.elapsed().as_secs_f64()))
}

/// The steady solve of `net` in place and the seconds it took.
pub fn run_steady(net: &mut Network, fluid: &Fluid) -> anyhow::Result<f64> {
    let start = Instant::now();
    solve_steady(net, fluid, 0.0)?;
    Ok(start.elapsed().as_secs_f64())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The coarse twin of the diffusion rows: 0.5 m domains within 2 % of p₀ at both times.
    #[test]
    fn pressure_diffuses_along_a_joint_as_erfc_says() {
        let (errors, _, _) = diffusion_errors(0.5, &[0.005, 0.02], &Fluid::WATER).unwrap();
        assert!(errors.iter().all(|&e| e < 0.02), "{errors:?}");
    }

    #[test]
    fn erfc_has_its_tabulated_values() {
        for (x, v) in [
            (0.0, 1.0),
            (0.5, 0.479_500_122),
            (1.0, 0.157_299_207),
            (2.0, 4.677_734_98e-3),
            (-1.0, 1.842_700_79),
        ] {
            assert!((erfc(x) - v).abs() < 2e-7 * v, "{x}: {} {v}", erfc(x));
        }
    }

    /// The coarse twin: a 12 × 12 grid of random apertures over one decade, its steady solve
    /// against the dense one within 1e-8 and its explicit run to a ratio of 1e-9 within what
    /// that ratio admits;
    /// with equal apertures each of its 12 rows of joints carries the cubic law's flow across
    /// its width (the vertical joints none), within 1e-10.
    #[test]
    fn a_grid_of_joints_flows_as_its_closed_forms_say() {
        let fluid = Fluid::WATER;
        let mut net = grid(12, random_apertures(7, 1.0));
        let dense = dense_pressures(&net, &fluid);
        let mut explicit = net.clone();
        run_steady(&mut net, &fluid).unwrap();
        assert!(worst(&net.domains.pressure, &dense) < 1e-8);
        let (_, _, largest) = run_explicit(&mut explicit, &fluid, 1e-9).unwrap();
        let admits = |q| admitted_error(&explicit, &fluid, 1e-9, q) / PRESSURE;
        let error = worst(&explicit.domains.pressure, &dense);
        assert!(
            error < admits(largest),
            "{error:.3e} {:.3e}",
            admits(largest)
        );
        let mut uniform = grid(12, |_| 1e-4);
        run_steady(&mut uniform, &fluid).unwrap();
        let snow = 12.0 * 1e-12 / (12.0 * fluid.viscosity) * PRESSURE / (11.0 * SPACING);
        let q = outflow(&uniform, &fluid);
        assert!((q - snow).abs() < 1e-10 * snow, "{q} {snow}");
    }
}
