//! Joint traces: sets of parallel joints (dip, spacing, origin, optional trace length and gap,
//! optional random spread) and explicit joint lines, as segments to cut the region with.

use crate::geometry::Point;

/// What a cutting segment is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum EdgeKind {
    /// Edge `i` of the region polygon.
    Region(u32),
    /// Wall of excavation `j`.
    Excavation(u32),
    /// A joint of joint set or explicit line `k` (numbered in scene order).
    Joint(u32),
}

impl std::fmt::Display for EdgeKind {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self {
            EdgeKind::Region(i) => write!(f, "region edge {i}"),
            EdgeKind::Excavation(j) => write!(f, "wall of excavation {j}"),
            EdgeKind::Joint(k) => write!(f, "joint {k}"),
        }
    }
}

/// A straight cutting segment, metres, with its kind.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    pub a: Point,
    pub b: Point,
    pub kind: EdgeKind,
}

/// A set of parallel joints, UDEC-style.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointSet {
    /// Dip angle, degrees counter-clockwise from the +x axis.
    pub dip_deg: f64,
    /// Perpendicular spacing between joints, m.
    pub spacing: f64,
    /// A point one joint passes through, m.
    pub origin: Point,
    /// Length of each joint trace, m (`None`: persistent joints crossing the whole region).
    pub trace: Option<f64>,
    /// Rock bridge between successive traces on one joint line, m (with `trace`).
    pub gap: f64,
    /// Random spread: each line's dip varies uniformly within ±`spread_dip_deg` and its position
    /// within ±`spread_spacing` (m); traces start at a random offset. Zero spreads: regular set.
    pub spread_dip_deg: f64,
    pub spread_spacing: f64,
    /// Seed of the spread (same seed, same joints).
    pub seed: u64,
}

/// SplitMix64 (Steele, Lea & Flood 2014): a small deterministic generator for joint spreads.
pub struct SplitMix(pub u64);

impl SplitMix {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [−1, 1).
    pub fn symmetric(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
}

impl JointSet {
    /// The joint traces of the set over the box `lo`–`hi` (m), tagged `kind`.
    pub fn segments(&self, lo: Point, hi: Point, kind: EdgeKind) -> Vec<Segment> {
        let mut rng = SplitMix(self.seed);
        let corners = [lo, [hi[0], lo[1]], hi, [lo[0], hi[1]]];
        let theta = self.dip_deg.to_radians();
        let n = [-theta.sin(), theta.cos()];
        let offset = |p: Point| (p[0] - self.origin[0]) * n[0] + (p[1] - self.origin[1]) * n[1];
        let (omin, omax) = corners
            .iter()
            .map(|&c| offset(c))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), o| {
                (a.min(o), b.max(o))
            });
        let diag = ((hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2)).sqrt();
        let margin = self.spread_spacing + diag * self.spread_dip_deg.to_radians().sin().abs();
        let k0 = ((omin - margin) / self.spacing).floor() as i64;
        let k1 = ((omax + margin) / self.spacing).ceil() as i64;
        let mut out = Vec::new();
        for k in k0..=k1 {
            let t = (self.dip_deg + self.spread_dip_deg * rng.symmetric()).to_radians();
            let shift = k as f64 * self.spacing + self.spread_spacing * rng.symmetric();
            let start = rng.symmetric();
            let base = [self.origin[0] + n[0] * shift, self.origin[1] + n[1] * shift];
            let d = [t.cos(), t.sin()];
            let Some((s0, s1)) = clip_line_to_box(base, d, lo, hi) else {
                continue;
            };
            match self.trace {
                None => out.push(Segment {
                    a: at(base, d, s0),
                    b: at(base, d, s1),
                    kind,
                }),
                Some(trace) => {
                    let period = trace + self.gap;
                    let phase = if self.spread_dip_deg > 0.0 || self.spread_spacing > 0.0 {
                        0.5 * (start + 1.0) * period
                    } else {
                        0.0
                    };
                    let mut s = ((s0 - phase) / period).floor() * period + phase;
                    while s < s1 {
                        let (a, b) = (s.max(s0), (s + trace).min(s1));
                        if b > a {
                            out.push(Segment {
                                a: at(base, d, a),
                                b: at(base, d, b),
                                kind,
                            });
                        }
                        s += period;
                    }
                }
            }
        }
        out
    }
}

fn at(p: Point, d: Point, s: f64) -> Point {
    [p[0] + s * d[0], p[1] + s * d[1]]
}

/// Parameter range of the line p + s·d inside the box (Liang–Barsky), if it meets it.
fn clip_line_to_box(p: Point, d: Point, lo: Point, hi: Point) -> Option<(f64, f64)> {
    let (mut s0, mut s1) = (f64::NEG_INFINITY, f64::INFINITY);
    for k in 0..2 {
        if d[k].abs() < 1e-300 {
            if p[k] < lo[k] || p[k] > hi[k] {
                return None;
            }
        } else {
            let (a, b) = ((lo[k] - p[k]) / d[k], (hi[k] - p[k]) / d[k]);
            s0 = s0.max(a.min(b));
            s1 = s1.min(a.max(b));
        }
    }
    (s1 > s0).then_some((s0, s1))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn set(dip: f64, spacing: f64) -> JointSet {
        JointSet {
            dip_deg: dip,
            spacing,
            origin: [0.0, 0.0],
            trace: None,
            gap: 0.0,
            spread_dip_deg: 0.0,
            spread_spacing: 0.0,
            seed: 1,
        }
    }

    #[test]
    fn horizontal_set_spans_the_box_at_its_spacing() {
        let segs = set(0.0, 1.0).segments([0.0, 0.0], [10.0, 4.5], EdgeKind::Joint(0));
        let ys: Vec<f64> = segs.iter().map(|s| s.a[1]).collect();
        assert_eq!(ys, [0.0, 1.0, 2.0, 3.0, 4.0]);
        assert!(segs.iter().all(|s| s.a[0] == 0.0 && s.b[0] == 10.0));
    }

    #[test]
    fn traces_and_gaps_alternate() {
        let s = JointSet {
            trace: Some(2.0),
            gap: 1.0,
            ..set(0.0, 10.0)
        };
        let segs = s.segments([0.0, -1.0], [10.0, 1.0], EdgeKind::Joint(0));
        let xs: Vec<(f64, f64)> = segs.iter().map(|s| (s.a[0], s.b[0])).collect();
        assert_eq!(xs, [(0.0, 2.0), (3.0, 5.0), (6.0, 8.0), (9.0, 10.0)]);
    }

    #[test]
    fn spread_is_reproducible_from_its_seed() {
        let s = JointSet {
            spread_dip_deg: 5.0,
            spread_spacing: 0.2,
            seed: 42,
            ..set(30.0, 1.0)
        };
        let a = s.segments([0.0, 0.0], [5.0, 5.0], EdgeKind::Joint(0));
        let b = s.segments([0.0, 0.0], [5.0, 5.0], EdgeKind::Joint(0));
        assert_eq!(a, b);
        let c = JointSet { seed: 43, ..s }.segments([0.0, 0.0], [5.0, 5.0], EdgeKind::Joint(0));
        assert_ne!(a, c);
    }
}
