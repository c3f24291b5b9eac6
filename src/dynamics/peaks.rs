//! Peak particle velocity (PPV): each node's largest speed |v| over the run's dynamic stages,
//! m/s, the measure of ground shaking that blast and rockburst damage criteria use (the `ppv`
//! point field and `summary.json`'s `peak_particle_velocity`). Kept only once a dynamic stage has
//! begun: a static run pays nothing for it.

use rayon::prelude::*;

/// Each node's peak speed so far, m/s.
#[derive(Debug, Clone, PartialEq)]
pub struct Peaks {
    pub speed: Vec<f64>,
}

impl Peaks {
    /// `n` nodes that have not moved.
    pub fn new(n: usize) -> Peaks {
        Peaks {
            speed: vec![0.0; n],
        }
    }

    /// After a step: each node's peak to the larger of it and its speed now, |v| (m/s).
    pub(crate) fn record(&mut self, vel: &[[f64; 2]]) {
        (self.speed.par_iter_mut())
            .zip(vel.par_iter())
            .with_min_len(4096)
            .for_each(|(p, v)| *p = p.max(v[0].hypot(v[1])));
    }

    /// The largest peak and its node (`None` without nodes).
    pub fn largest(&self) -> Option<(u32, f64)> {
        (self.speed.iter().enumerate())
            .max_by(|a, b| a.1.total_cmp(b.1))
            .map(|(n, &s)| (n as u32, s))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn peaks_keep_the_largest_speed() {
        let mut p = Peaks::new(2);
        p.record(&[[3.0, 4.0], [0.0, -1.0]]);
        p.record(&[[1.0, 0.0], [0.0, 2.0]]);
        assert_eq!(p.speed, vec![5.0, 2.0]);
        assert_eq!(p.largest(), Some((0, 5.0)));
    }
}
