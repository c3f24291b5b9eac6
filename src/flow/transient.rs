//! Transient flow, stepped explicitly: each free domain's pressure follows the water it gains,
//! Δpᵢ = (Kw / Vᵢ) (Σⱼ qⱼᵢ + sᵢ) Δt (Kw the fluid's bulk modulus, Vᵢ the domain's volume, qⱼᵢ the
//! cubic law's flows into it), UDEC's fluid step. Forward in time it is stable while
//! Δt ≤ min over free domains of Vᵢ / (Kw Σⱼ Cᵢⱼ) (`stable_step`: by Gershgorin's theorem the
//! step's amplification stays within [−1, 1]; the bound is reached along a uniform row of
//! domains, whose highest mode alternates in sign).

use super::{Fluid, Network};

/// The largest stable fluid step of `net`, s: min over free domains of Vᵢ / (Kw Σⱼ Cᵢⱼ), from
/// the pipes' `conductance` (m²/(Pa·s)); infinite where no free domain has a pipe.
pub fn stable_step(net: &Network, fluid: &Fluid, conductance: &[f64]) -> f64 {
    let mut sum = vec![0.0; net.domains.len()];
    for (&[a, b], &c) in net.pipes.ends.iter().zip(conductance) {
        sum[a.0 as usize] += c;
        sum[b.0 as usize] += c;
    }
    let d = &net.domains;
    (0..d.len())
        .filter(|&i| !d.fixed[i] && sum[i] > 0.0)
        .map(|i| d.volume[i] / (fluid.bulk_modulus * sum[i]))
        .fold(f64::INFINITY, f64::min)
}

/// The explicit stepper of a network whose pipes keep their apertures: their conductances, the
/// stable step, and the scratch a step needs, so that stepping allocates nothing.
#[derive(Debug, Clone)]
pub struct Transient {
    fluid: Fluid,
    /// g, m/s², acting down y.
    gravity: f64,
    conductance: Vec<f64>,
    /// The stable step, s.
    pub limit: f64,
    head: Vec<f64>,
    flow: Vec<f64>,
    inflow: Vec<f64>,
    /// The largest flow through a pipe the ratio has seen, m²/s: its scale.
    largest_flow: f64,
}

impl Transient {
    /// The stepper of `net` (checked) for `fluid` under gravity `gravity` m/s².
    pub fn new(net: &Network, fluid: &Fluid, gravity: f64) -> Result<Transient, String> {
        net.check()?;
        let fluid = fluid.checked()?;
        let mut conductance = vec![0.0; net.pipes.len()];
        net.conductances(&fluid, &mut conductance);
        let limit = stable_step(net, &fluid, &conductance);
        Ok(Transient {
            fluid,
            gravity,
            conductance,
            limit,
            head: vec![0.0; net.domains.len()],
            flow: vec![0.0; net.pipes.len()],
            inflow: vec![0.0; net.domains.len()],
            largest_flow: 0.0,
        })
    }

    /// Advance `net`'s pressures by `dt` s; refused, naming both, when `dt` exceeds the stable
    /// step.
    pub fn step(&mut self, net: &mut Network, dt: f64) -> Result<(), String> {
        self.stable(dt)?;
        self.advance(net, dt);
        Ok(())
    }

    /// `dt` (s), or an error naming it and the stable step when it is not within it.
    fn stable(&self, dt: f64) -> Result<(), String> {
        if dt > 0.0 && dt <= self.limit {
            return Ok(());
        }
        Err(format!(
            "flow: the step {dt:.4e} s is not within the fluid's stable step {:.4e} s \
             (min V / (Kw Σ C) over the domains)",
            self.limit
        ))
    }

    /// One forward step of `dt` s, unchecked.
    fn advance(&mut self, net: &mut Network, dt: f64) {
        self.balance(net);
        self.gain(net, dt);
    }

    /// Each free domain's pressure by the water it gained over `dt` s at the inflows `balance`
    /// left in the scratch.
    fn gain(&self, net: &mut Network, dt: f64) {
        let d = &mut net.domains;
        let k = self.fluid.bulk_modulus * dt;
        for i in 0..d.len() {
            if !d.fixed[i] {
                d.pressure[i] += k / d.volume[i] * self.inflow[i];
            }
        }
    }

    /// The flows and every domain's net inflow at the network's pressures, into the scratch.
    fn balance(&mut self, net: &Network) {
        net.heads(&self.fluid, self.gravity, &mut self.head);
        net.flows(&self.conductance, &self.head, &mut self.flow);
        net.inflows(&self.flow, &mut self.inflow);
    }

    /// The flow ratio: the largest net inflow of a free domain over the largest flow through a
    /// pipe seen by the ratio since the stepper was made (as the mechanical ratio measures the
    /// unbalanced force against the forces that were applied: water that comes to rest in a
    /// sealed group of domains has no flow left to measure against); 0 when nothing has flowed.
    pub fn ratio(&mut self, net: &Network) -> f64 {
        self.balance(net);
        let d = &net.domains;
        let unbalanced = (0..d.len())
            .filter(|&i| !d.fixed[i])
            .map(|i| self.inflow[i].abs())
            .fold(0.0, f64::max);
        let flowing = self.flow.iter().fold(0.0f64, |m, q| m.max(q.abs()));
        self.largest_flow = self.largest_flow.max(flowing);
        if self.largest_flow > 0.0 {
            unbalanced / self.largest_flow
        } else {
            0.0
        }
    }

    /// The largest flow through a pipe the ratio has seen, m²/s per metre: its denominator.
    pub fn largest_flow(&self) -> f64 {
        self.largest_flow
    }

    /// Step by `dt` s until the flow ratio falls below `ratio`, at most `max_steps` steps; the
    /// steps taken, or an error when they do not reach it.
    pub fn run_to_ratio(
        &mut self,
        net: &mut Network,
        dt: f64,
        ratio: f64,
        max_steps: usize,
    ) -> Result<usize, String> {
        self.stable(dt)?;
        for n in 0..max_steps {
            // The ratio's balance is the step's: its inflows move the pressures.
            if self.ratio(net) < ratio {
                return Ok(n);
            }
            self.gain(net, dt);
        }
        Err(format!(
            "flow: the flow ratio is still {:.3e} after {max_steps} steps (asked {ratio:.1e})",
            self.ratio(net)
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flow::solve_steady;

    /// A row of `n` equal domains between a held pressure and a sealed end.
    fn row(n: usize) -> Network {
        let mut net = Network::default();
        let ids: Vec<_> = (0..=n).map(|_| net.add_domain(1e-4, 0.0, 0.0)).collect();
        for w in ids.windows(2) {
            net.add_pipe(w[0], w[1], 1e-4, 1.0);
        }
        net.fix(ids[0], 1e6);
        net
    }

    /// The explicit run reaches the steady solve's pressures at 0.99 of its stable step; at 1.05
    /// of it the row's highest mode grows (the bound is the step's true limit there), and a step
    /// above the limit is refused with both named.
    #[test]
    fn the_explicit_step_is_stable_just_below_its_limit_and_refused_above() {
        let fluid = Fluid::WATER;
        let mut net = row(12);
        let mut t = Transient::new(&net, &fluid, 9.81).unwrap();
        let c = 1e-12 / 12e-3;
        assert!((t.limit - 1e-4 / (fluid.bulk_modulus * 2.0 * c)).abs() < 1e-12 * t.limit);
        let steps = t
            .run_to_ratio(&mut net, 0.99 * t.limit, 1e-10, 100_000)
            .unwrap();
        assert!(steps > 10);
        let mut steady = row(12);
        solve_steady(&mut steady, &fluid, 9.81).unwrap();
        for (p, s) in net.domains.pressure.iter().zip(&steady.domains.pressure) {
            assert!((p - s).abs() < 1e-6 * 1e6, "{p} {s}");
        }
        let e = t.step(&mut net, 1.01 * t.limit).unwrap_err();
        assert!(e.contains("stable step"), "{e}");
        // Past the limit the highest mode grows: a small alternating disturbance blows up.
        let mut net = row(12);
        for (i, p) in net.domains.pressure.iter_mut().enumerate().skip(1) {
            *p = if i % 2 == 0 { 1.0 } else { -1.0 };
        }
        net.domains.pressure[0] = 0.0;
        let dt = 1.05 * t.limit;
        for _ in 0..2000 {
            t.advance(&mut net, dt);
        }
        let largest = net
            .domains
            .pressure
            .iter()
            .fold(0.0f64, |m, p| m.max(p.abs()));
        assert!(largest > 1e6, "{largest}");
    }

    /// Random networks (apertures over one decade, heads and a source): the explicit run at its
    /// stable step, to a flow ratio of 1e-10, ends within 1e-6 of the pressures' range of the
    /// steady solve's.
    #[test]
    fn an_explicit_run_on_a_random_network_reaches_the_steady_state() {
        let (fluid, g) = (Fluid::WATER, 9.81);
        for seed in 0..8 {
            let mut net = crate::flow::steady::tests::random_network(seed, 25, 20, 1.0, 2);
            let mut steady = net.clone();
            solve_steady(&mut steady, &fluid, g).unwrap();
            let mut t = Transient::new(&net, &fluid, g).unwrap();
            t.run_to_ratio(&mut net, t.limit, 1e-10, 2_000_000).unwrap();
            let range = steady
                .domains
                .pressure
                .iter()
                .fold(0.0f64, |m, p| m.max(p.abs()));
            let worst = (net.domains.pressure.iter().zip(&steady.domains.pressure))
                .map(|(p, s)| (p - s).abs())
                .fold(0.0, f64::max);
            assert!(
                worst < 1e-6 * range,
                "seed {seed}: {worst:.3e} of {range:.3e}"
            );
        }
    }
}
