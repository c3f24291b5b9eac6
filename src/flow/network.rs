//! The flow network's state as structure-of-arrays: domains (voids with a volume and a pressure)
//! and pipes (the contacts between them, each with a hydraulic aperture and a length).

use super::{Fluid, cubic_law_conductance};

/// Index of a domain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct DomainId(pub u32);

/// The domains: the voids along the joints and at their intersections.
#[derive(Debug, Clone, Default)]
pub struct Domains {
    /// Volume per metre out of the plane, m².
    pub volume: Vec<f64>,
    /// Water pressure, Pa (positive in compression of the water, as engineers quote it).
    pub pressure: Vec<f64>,
    /// Elevation of the domain's centre y, m (up).
    pub elevation: Vec<f64>,
    /// Whether the pressure is held (a boundary at a given pressure or head, a drained wall).
    pub fixed: Vec<bool>,
    /// Water brought into the domain from outside the network (a well), m²/s per metre.
    pub source: Vec<f64>,
}

/// The pipes: each joins two domains along a joint.
#[derive(Debug, Clone, Default)]
pub struct Pipes {
    /// The two domains a pipe joins; its flow is positive from the first to the second.
    pub ends: Vec<[DomainId; 2]>,
    /// Hydraulic aperture, m.
    pub aperture: Vec<f64>,
    /// Length along the flow between the domains' centres, m.
    pub length: Vec<f64>,
}

/// A flow network: domains joined by pipes.
#[derive(Debug, Clone, Default)]
pub struct Network {
    pub domains: Domains,
    pub pipes: Pipes,
}

impl Domains {
    pub fn len(&self) -> usize {
        self.volume.len()
    }

    pub fn is_empty(&self) -> bool {
        self.volume.is_empty()
    }
}

impl Pipes {
    pub fn len(&self) -> usize {
        self.ends.len()
    }

    pub fn is_empty(&self) -> bool {
        self.ends.is_empty()
    }
}

impl Network {
    /// A free domain of `volume` m² per metre at elevation `elevation` m holding `pressure` Pa.
    pub fn add_domain(&mut self, volume: f64, elevation: f64, pressure: f64) -> DomainId {
        let d = &mut self.domains;
        d.volume.push(volume);
        d.elevation.push(elevation);
        d.pressure.push(pressure);
        d.fixed.push(false);
        d.source.push(0.0);
        DomainId(d.volume.len() as u32 - 1)
    }

    /// Hold domain `d` at `pressure` Pa.
    pub fn fix(&mut self, d: DomainId, pressure: f64) {
        self.domains.fixed[d.0 as usize] = true;
        self.domains.pressure[d.0 as usize] = pressure;
    }

    /// A pipe of hydraulic aperture `aperture` m and length `length` m from `a` to `b`.
    pub fn add_pipe(&mut self, a: DomainId, b: DomainId, aperture: f64, length: f64) {
        self.pipes.ends.push([a, b]);
        self.pipes.aperture.push(aperture);
        self.pipes.length.push(length);
    }

    /// The network, or an error naming the first domain or pipe whose data cannot be: a volume,
    /// aperture or length that is not a positive number, a pressure or elevation that is not
    /// finite, a pipe joining a domain to itself or to one that does not exist.
    pub fn check(&self) -> Result<(), String> {
        let d = &self.domains;
        for i in 0..d.len() {
            if !(d.volume[i].is_finite() && d.volume[i] > 0.0) {
                return Err(format!(
                    "flow domain {i}: volume {} m² is not positive",
                    d.volume[i]
                ));
            }
            if !(d.pressure[i].is_finite() && d.elevation[i].is_finite() && d.source[i].is_finite())
            {
                return Err(format!(
                    "flow domain {i}: pressure, elevation or source not finite"
                ));
            }
        }
        let p = &self.pipes;
        for k in 0..p.len() {
            let [a, b] = p.ends[k];
            if a.0 as usize >= d.len() || b.0 as usize >= d.len() || a == b {
                return Err(format!(
                    "flow pipe {k}: joins domains {} and {} of {}",
                    a.0,
                    b.0,
                    d.len()
                ));
            }
            for (what, v) in [("aperture", p.aperture[k]), ("length", p.length[k])] {
                if !(v.is_finite() && v > 0.0) {
                    return Err(format!("flow pipe {k}: {what} {v} m is not positive"));
                }
            }
        }
        Ok(())
    }

    /// Each pipe's conductance by the cubic law, m²/(Pa·s), into `out`.
    pub fn conductances(&self, fluid: &Fluid, out: &mut [f64]) {
        let p = &self.pipes;
        for ((c, &a), &l) in out.iter_mut().zip(&p.aperture).zip(&p.length) {
            *c = cubic_law_conductance(a, l, fluid.viscosity);
        }
    }

    /// Each domain's head h = p + ρw g y, Pa (`gravity` g m/s², acting down y), into `out`: water
    /// flows from a higher head to a lower.
    pub fn heads(&self, fluid: &Fluid, gravity: f64, out: &mut [f64]) {
        let d = &self.domains;
        let rho_g = fluid.density * gravity;
        for ((h, &p), &y) in out.iter_mut().zip(&d.pressure).zip(&d.elevation) {
            *h = p + rho_g * y;
        }
    }

    /// Each pipe's flow q = C (h_a − h_b), m²/s per metre, positive from its first domain to
    /// its second, from `conductance` and `head`, into `out`.
    pub fn flows(&self, conductance: &[f64], head: &[f64], out: &mut [f64]) {
        for ((q, &[a, b]), &c) in out.iter_mut().zip(&self.pipes.ends).zip(conductance) {
            *q = c * (head[a.0 as usize] - head[b.0 as usize]);
        }
    }

    /// Each domain's net inflow (the pipes' flows into it and its source), m²/s per metre, from
    /// the pipes' `flow`, into `out`.
    pub fn inflows(&self, flow: &[f64], out: &mut [f64]) {
        out.copy_from_slice(&self.domains.source);
        for (&[a, b], &q) in self.pipes.ends.iter().zip(flow) {
            out[a.0 as usize] -= q;
            out[b.0 as usize] += q;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bad_domain_or_pipe_is_named() {
        let mut n = Network::default();
        let a = n.add_domain(1e-3, 0.0, 0.0);
        let b = n.add_domain(1e-3, 0.0, 0.0);
        n.add_pipe(a, b, 1e-4, 1.0);
        assert!(n.check().is_ok());
        n.add_pipe(a, a, 1e-4, 1.0);
        assert!(n.check().unwrap_err().contains("flow pipe 1"));
        n.pipes.ends[1] = [a, DomainId(7)];
        assert!(n.check().unwrap_err().contains("flow pipe 1"));
        n.pipes.ends[1] = [a, b];
        n.pipes.length[1] = 0.0;
        assert!(n.check().unwrap_err().contains("length"));
        n.pipes.length[1] = 1.0;
        n.domains.volume[0] = -1.0;
        assert!(n.check().unwrap_err().contains("flow domain 0"));
    }

    /// Water at rest in a column under gravity: the heads are equal, nothing flows.
    #[test]
    fn hydrostatic_water_does_not_flow() {
        let (fluid, g) = (Fluid::WATER, 9.81);
        let mut n = Network::default();
        let ids: Vec<_> = (0..5)
            .map(|i| {
                let y = -(i as f64) * 2.0;
                n.add_domain(1e-3, y, -fluid.density * g * y)
            })
            .collect();
        for w in ids.windows(2) {
            n.add_pipe(w[0], w[1], 1e-4, 2.0);
        }
        let (mut c, mut h, mut q) = (vec![0.0; 4], vec![0.0; 5], vec![0.0; 4]);
        n.conductances(&fluid, &mut c);
        n.heads(&fluid, g, &mut h);
        n.flows(&c, &h, &mut q);
        assert!(q.iter().all(|q| q.abs() < 1e-20), "{q:?}");
    }
}
