//! The network's steady state, solved directly: at every free domain the flows in balance its
//! source, Σⱼ Cᵢⱼ (hᵢ − hⱼ) = sᵢ, a graph Laplacian in the heads over the free domains (the held
//! ones move to the right-hand side), symmetric and positive definite where each group of
//! connected domains holds at least one pressure; factorized by faer's sparse Cholesky.

use faer::sparse::{SparseColMat, Triplet};

use super::{Fluid, Network};
use crate::implicit::factor::{Factor, FactorError};

/// Why a steady state could not be found.
#[derive(Debug, thiserror::Error)]
pub enum SteadyError {
    #[error("{0}")]
    Input(String),
    /// A group of connected domains holds no pressure and is fed by a source: in steady state
    /// it can only fill without end.
    #[error(
        "flow domain {domain}: a source of {inflow:.3e} m²/s feeds a group of connected domains \
         that holds no pressure (no boundary, no drained wall): it has no steady state"
    )]
    Unbounded { domain: usize, inflow: f64 },
    #[error("flow: the steady solve failed: {0}")]
    Factor(String),
}

/// What the steady solve found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Steady {
    /// The domains whose pressure was solved for (the free ones joined to a held pressure).
    pub unknowns: usize,
    /// The free domains in groups that hold no pressure: their pressures are kept.
    pub isolated: usize,
}

/// Solve the network's steady state in place: every free domain joined through the pipes to a
/// held pressure gets the pressure that balances its flows (`gravity` g m/s² acting down y);
/// free domains in groups joined to none keep theirs (water trapped between closed joints).
pub fn solve_steady(net: &mut Network, fluid: &Fluid, gravity: f64) -> Result<Steady, SteadyError> {
    net.check().map_err(SteadyError::Input)?;
    let fluid = fluid.checked().map_err(SteadyError::Input)?;
    let n = net.domains.len();
    let anchored = anchored(net);
    let mut unknown = vec![u32::MAX; n];
    let mut unknowns = 0usize;
    let mut isolated = 0;
    for i in 0..n {
        if net.domains.fixed[i] {
            continue;
        }
        if anchored[i] {
            unknown[i] = unknowns as u32;
            unknowns += 1;
        } else if net.domains.source[i] != 0.0 {
            return Err(SteadyError::Unbounded {
                domain: i,
                inflow: net.domains.source[i],
            });
        } else {
            isolated += 1;
        }
    }
    if unknowns == 0 {
        return Ok(Steady { unknowns, isolated });
    }
    let mut conductance = vec![0.0; net.pipes.len()];
    net.conductances(&fluid, &mut conductance);
    let mut head = vec![0.0; n];
    net.heads(&fluid, gravity, &mut head);
    let mut rhs: Vec<f64> = (0..n)
        .filter(|&i| unknown[i] != u32::MAX)
        .map(|i| net.domains.source[i])
        .collect();
    let mut triplets = Vec::with_capacity(unknowns + 3 * net.pipes.len());
    for (&[a, b], &c) in net.pipes.ends.iter().zip(&conductance) {
        let (a, b) = (a.0 as usize, b.0 as usize);
        let (ua, ub) = (unknown[a], unknown[b]);
        for (u, other, uo) in [(ua, b, ub), (ub, a, ua)] {
            if u == u32::MAX {
                continue;
            }
            triplets.push(Triplet::new(u as usize, u as usize, c));
            if uo == u32::MAX {
                rhs[u as usize] += c * head[other];
            } else if uo < u {
                triplets.push(Triplet::new(u as usize, uo as usize, -c));
            }
        }
    }
    let k = SparseColMat::try_new_from_triplets(unknowns, unknowns, &triplets)
        .map_err(|e| SteadyError::Factor(format!("{e:?}")))?;
    let (mut factor, _) = Factor::new(k.as_ref(), None).map_err(|e| {
        SteadyError::Factor(match e {
            FactorError::Memory(m) | FactorError::Numeric(m) => m,
        })
    })?;
    factor.solve_in_place(&mut rhs);
    let rho_g = fluid.density * gravity;
    for i in 0..n {
        if unknown[i] != u32::MAX {
            net.domains.pressure[i] = rhs[unknown[i] as usize] - rho_g * net.domains.elevation[i];
        }
    }
    Ok(Steady { unknowns, isolated })
}

/// For each domain, whether it is joined through the pipes to a domain whose pressure is held
/// (union–find over the pipes, path halving).
fn anchored(net: &Network) -> Vec<bool> {
    let n = net.domains.len();
    let mut parent: Vec<u32> = (0..n as u32).collect();
    fn root(parent: &mut [u32], mut i: u32) -> u32 {
        while parent[i as usize] != i {
            parent[i as usize] = parent[parent[i as usize] as usize];
            i = parent[i as usize];
        }
        i
    }
    for &[a, b] in &net.pipes.ends {
        let (ra, rb) = (root(&mut parent, a.0), root(&mut parent, b.0));
        if ra != rb {
            parent[ra.max(rb) as usize] = ra.min(rb);
        }
    }
    let mut held = vec![false; n];
    for i in 0..n {
        if net.domains.fixed[i] {
            let r = root(&mut parent, i as u32);
            held[r as usize] = true;
        }
    }
    (0..n)
        .map(|i| held[root(&mut parent, i as u32) as usize])
        .collect()
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::flow::DomainId;
    use approx::assert_relative_eq;

    /// Parallel plates a = 1e-4 m apart over L = 10 m under Δp = 1 MPa, as 20 domains in a row:
    /// Q = a³Δp/(12μL) = 8.333e-6 m²/s through every pipe, the pressure linear along it.
    #[test]
    fn a_joint_between_two_pressures_passes_the_cubic_laws_flow() {
        let (fluid, domains, length) = (Fluid::WATER, 20, 10.0);
        let mut net = Network::default();
        let step = length / domains as f64;
        let ids: Vec<DomainId> = (0..=domains + 1)
            .map(|_| net.add_domain(1e-4 * step, 0.0, 0.0))
            .collect();
        // The end domains are the reservoirs at x = 0 and x = L; the others at the middles of
        // `domains` equal segments, half a segment from their neighbours at the ends.
        for k in 0..=domains {
            let l = if k == 0 || k == domains {
                step / 2.0
            } else {
                step
            };
            net.add_pipe(ids[k], ids[k + 1], 1e-4, l);
        }
        net.fix(ids[0], 1e6);
        net.fix(ids[domains + 1], 0.0);
        let s = solve_steady(&mut net, &fluid, 9.81).unwrap();
        assert_eq!(s.unknowns, domains);
        let (mut c, mut h, mut q) = (
            vec![0.0; domains + 1],
            vec![0.0; domains + 2],
            vec![0.0; domains + 1],
        );
        net.conductances(&fluid, &mut c);
        net.heads(&fluid, 9.81, &mut h);
        net.flows(&c, &h, &mut q);
        for q in q {
            assert_relative_eq!(q, 8.333_333_333e-6, max_relative = 1e-10);
        }
        for k in 1..=domains {
            let x = (k as f64 - 0.5) * step;
            assert_relative_eq!(
                net.domains.pressure[k],
                1e6 * (1.0 - x / length),
                max_relative = 1e-10
            );
        }
    }

    /// A group of domains joined to no held pressure keeps its pressures; fed by a source it has
    /// no steady state, and the error names the domain.
    #[test]
    fn water_joined_to_no_boundary_keeps_its_pressure_or_is_refused_when_fed() {
        let fluid = Fluid::WATER;
        let mut net = Network::default();
        let a = net.add_domain(1e-4, 0.0, 0.0);
        let b = net.add_domain(1e-4, 0.0, 0.0);
        let c = net.add_domain(1e-4, 0.0, 3e5);
        let d = net.add_domain(1e-4, 0.0, 4e5);
        net.add_pipe(a, b, 1e-4, 1.0);
        net.add_pipe(c, d, 1e-4, 1.0);
        net.fix(a, 1e5);
        let s = solve_steady(&mut net, &fluid, 0.0).unwrap();
        assert_eq!((s.unknowns, s.isolated), (1, 2));
        assert_relative_eq!(net.domains.pressure[1], 1e5, max_relative = 1e-12);
        assert_eq!(net.domains.pressure[2..], [3e5, 4e5]);
        net.domains.source[3] = 1e-6;
        let e = solve_steady(&mut net, &fluid, 0.0).unwrap_err().to_string();
        assert!(e.contains("flow domain 3"), "{e}");
    }

    /// A random network of `n` domains (a chain through them all, then `extra` random pipes),
    /// apertures spread over `spread` decades from 1e-5 m, random elevations and volumes, its
    /// first `held` domains at random pressures and a source in one free domain.
    pub(crate) fn random_network(
        seed: u64,
        n: usize,
        extra: usize,
        spread: f64,
        held: usize,
    ) -> Network {
        let mut state = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let mut next = move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut net = Network::default();
        let ids: Vec<DomainId> = (0..n)
            .map(|_| net.add_domain(1e-4 * (0.5 + next()), 100.0 * next(), 0.0))
            .collect();
        let pipe = |net: &mut Network, a: DomainId, b: DomainId, r: f64, l: f64| {
            net.add_pipe(a, b, 1e-5 * 10f64.powf(spread * r), 0.5 + 5.0 * l)
        };
        for w in ids.windows(2) {
            let (r, l) = (next(), next());
            pipe(&mut net, w[0], w[1], r, l);
        }
        for _ in 0..extra {
            let (a, b) = ((next() * n as f64) as usize, (next() * n as f64) as usize);
            if a != b {
                let (r, l) = (next(), next());
                pipe(&mut net, ids[a], ids[b], r, l);
            }
        }
        for &d in &ids[..held] {
            let p = 2e6 * next();
            net.fix(d, p);
        }
        net.domains.source[n - 1] = 1e-7;
        net
    }

    /// The same steady state by a dense solve written here: the Laplacian over the free domains
    /// in heads, built entry by entry, solved by LU.
    fn dense_steady(net: &Network, fluid: &Fluid, g: f64) -> Vec<f64> {
        let n = net.domains.len();
        let free: Vec<usize> = (0..n).filter(|&i| !net.domains.fixed[i]).collect();
        let at = |i: usize| free.iter().position(|&f| f == i);
        let h = |i: usize| net.domains.pressure[i] + fluid.density * g * net.domains.elevation[i];
        let mut k = nalgebra::DMatrix::<f64>::zeros(free.len(), free.len());
        let mut b = nalgebra::DVector::<f64>::zeros(free.len());
        for (r, &i) in free.iter().enumerate() {
            b[r] = net.domains.source[i];
        }
        for p in 0..net.pipes.len() {
            let [a, c] = net.pipes.ends[p].map(|d| d.0 as usize);
            let ap = net.pipes.aperture[p];
            let cond = ap * ap * ap / (12.0 * fluid.viscosity * net.pipes.length[p]);
            for (x, y) in [(a, c), (c, a)] {
                if let Some(r) = at(x) {
                    k[(r, r)] += cond;
                    match at(y) {
                        Some(q) => k[(r, q)] -= cond,
                        None => b[r] += cond * h(y),
                    }
                }
            }
        }
        let heads = k.lu().solve(&b).expect("a connected network");
        let mut p = net.domains.pressure.clone();
        for (r, &i) in free.iter().enumerate() {
            p[i] = heads[r] - fluid.density * g * net.domains.elevation[i];
        }
        p
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// Random joint networks with apertures over two decades (conductances over six): the
        /// sparse steady solve agrees with the dense one to 1e-8 of the pressures' range. (Over
        /// three decades a row of 28 domains' two solves part by 4.5e-8: the rounding of a
        /// Laplacian whose conductances span 1e9.)
        #[test]
        fn a_random_network_steady_state_matches_a_dense_solve(
            seed in 0u64..u64::MAX, n in 3usize..80, extra in 0usize..120, held in 1usize..3,
        ) {
            let (fluid, g) = (Fluid::WATER, 9.81);
            let mut net = random_network(seed, n, extra, 2.0, held.min(n - 1));
            let dense = dense_steady(&net, &fluid, g);
            solve_steady(&mut net, &fluid, g).unwrap();
            let range = dense.iter().fold(0.0f64, |m, p| m.max(p.abs()));
            for (p, d) in net.domains.pressure.iter().zip(&dense) {
                proptest::prop_assert!((p - d).abs() <= 1e-8 * range, "{} {}", p, d);
            }
        }
    }
}
