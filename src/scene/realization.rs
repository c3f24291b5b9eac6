//! Realizations of uncertain joint sets (UDEC users draw them by hand): the scene's `realization`
//! N ≥ 1 moves each joint set with a `scatter` as a whole — origin, dip, spacing, trace and gap,
//! each uniformly within its ± bound — from a draw fixed by N and the set's index, so that
//! realization N of a joint model is the same on every machine. Realization 0 is the model as
//! written. (A set's `spread_dip` and `spread_spacing` scatter its joints one by one within a
//! realization; `scatter` moves the whole set between realizations.)

use adit_meshing::SplitMix;
use serde::Deserialize;

use super::validate::{Num, SceneError, invalid};
use super::{JointSetSpec, Scene};

/// How far a joint set moves between realizations, each bound ± (default 0: fixed).
#[derive(Debug, Clone, Copy, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Scatter {
    /// Origin moved within ± this in x and in y, m.
    pub origin: f64,
    /// Dip turned within ± this, degrees.
    pub dip: f64,
    /// Spacing scaled by 1 + u, u within ± this (a fraction, below 1).
    pub spacing: f64,
    /// Trace length scaled likewise (a fraction, below 1).
    pub trace: f64,
    /// Rock bridge scaled likewise (a fraction, below 1).
    pub gap: f64,
}

impl Scene {
    /// Joint set `i` of realization `self.realization`: as written for realization 0 or without a
    /// `scatter`, else moved within the scatter by the draw of (N, i).
    pub fn realized_set(&self, i: usize) -> JointSetSpec {
        let set = &self.joint_sets[i];
        let Some(s) = set.scatter.filter(|_| self.realization > 0) else {
            return set.clone();
        };
        let mut rng = SplitMix(
            self.realization.wrapping_mul(0xD1B5_4A32_D192_ED03)
                ^ (i as u64 + 1).wrapping_mul(0x9E37_79B9_7F4A_7C15),
        );
        // Always six draws in this order, so a bound set to 0 leaves the others' draws alone.
        let u: [f64; 6] = std::array::from_fn(|_| rng.symmetric());
        JointSetSpec {
            origin: [
                set.origin[0] + s.origin * u[0],
                set.origin[1] + s.origin * u[1],
            ],
            dip: set.dip + s.dip * u[2],
            spacing: set.spacing * (1.0 + s.spacing * u[3]),
            trace: set.trace.map(|t| t * (1.0 + s.trace * u[4])),
            gap: set.gap * (1.0 + s.gap * u[5]),
            ..set.clone()
        }
    }

    /// The `scatter` bounds, and a `realization` that has something to draw.
    pub(super) fn validate_realization(&self) -> Result<(), SceneError> {
        for (i, set) in self.joint_sets.iter().enumerate() {
            let Some(s) = &set.scatter else { continue };
            let p = format!("joint_sets[{i}].scatter");
            for (field, v, below) in [
                ("origin", s.origin, f64::INFINITY),
                ("dip", s.dip, 90.0),
                ("spacing", s.spacing, 1.0),
                ("trace", s.trace, 1.0),
                ("gap", s.gap, 1.0),
            ] {
                if !(v >= 0.0 && v < below) {
                    return Err(invalid(
                        format!("{p}.{field}"),
                        format!(
                            "must be at least 0 and below {}, got {}",
                            Num(below),
                            Num(v)
                        ),
                    ));
                }
            }
            if s.trace > 0.0 && set.trace.is_none() {
                return Err(invalid(
                    format!("{p}.trace"),
                    "the set's joints are persistent (no `trace` to scatter)",
                ));
            }
        }
        if self.realization > 0 && self.joint_sets.iter().all(|s| s.scatter.is_none()) {
            return Err(invalid(
                "realization",
                "no joint set has a `scatter` to draw the realization from",
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::Scene;

    fn tunnel() -> Scene {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        Scene::load(&root.join("models/tunnel.json")).unwrap()
    }

    #[test]
    fn a_realization_moves_each_set_within_its_scatter_reproducibly() {
        let mut s = tunnel();
        let scatter = super::Scatter {
            origin: 2.0,
            dip: 10.0,
            spacing: 0.3,
            trace: 0.3,
            gap: 0.3,
        };
        for set in &mut s.joint_sets {
            set.scatter = Some(scatter);
        }
        assert_eq!(s.realized_set(0).origin, s.joint_sets[0].origin);
        let mut seen = Vec::new();
        for n in 1..=200 {
            s.realization = n;
            for i in 0..2 {
                let (r, g) = (s.realized_set(i), &s.joint_sets[i]);
                assert!((r.origin[0] - g.origin[0]).abs() <= 2.0);
                assert!((r.dip - g.dip).abs() <= 10.0);
                assert!((r.spacing / g.spacing - 1.0).abs() <= 0.3);
                assert!((r.trace.unwrap() / g.trace.unwrap() - 1.0).abs() <= 0.3);
                assert_eq!(r.spread_dip, g.spread_dip);
                assert_eq!(r.origin, s.realized_set(i).origin, "reproducible");
                seen.push(r.dip);
            }
        }
        seen.sort_by(f64::total_cmp);
        seen.dedup();
        assert_eq!(seen.len(), 400, "every realization and set draws its own");
    }

    #[test]
    fn a_realization_needs_a_scatter_and_a_scatter_its_bounds() {
        let text = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/tunnel.json"),
        )
        .unwrap();
        let err = Scene::from_json(&text.replacen("{", "{ \"realization\": 3,", 1), "t")
            .unwrap_err()
            .to_string();
        assert!(
            err.starts_with("realization: no joint set has a `scatter`"),
            "{err}"
        );
        let scattered = text.replacen(
            "\"dip\": 30,",
            "\"dip\": 30, \"scatter\": { \"spacing\": 1.5 },",
            1,
        );
        let err = Scene::from_json(&scattered, "t").unwrap_err().to_string();
        assert!(
            err.starts_with("joint_sets[0].scatter.spacing: must be at least 0 and below 1"),
            "{err}"
        );
    }
}
