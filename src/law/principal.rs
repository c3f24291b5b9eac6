//! The plane-strain stress of a zone in principal stresses and back, for the laws that return to
//! their criterion in principal stresses (Mohr–Coulomb, Hoek–Brown): σxx, σyy, σxy give the
//! in-plane pair c ∓ r (c, r the centre and radius of the in-plane Mohr circle) and σzz is the
//! third. Corrected values go back keeping the in-plane principal directions:
//! σ = c' I + (r'/r)(σ − c I) in the plane, c', r' the corrected circle's.

use super::{SHEAR_NOW, SHEAR_PAST, Stress, TENSION_NOW, TENSION_PAST};

/// A zone stress in principal values, ascending, with where each came from.
pub(super) struct Principal {
    /// (value, origin): origin 0 the in-plane minor, 1 the in-plane major, 2 out of plane.
    sorted: [(f64, u8); 3],
    /// In-plane half difference (σxx − σyy)/2 and shear σxy, Pa.
    d: f64,
    t: f64,
    /// In-plane Mohr circle's radius, Pa.
    r: f64,
}

impl Principal {
    pub fn of(s: &Stress) -> Principal {
        let (c, d, t) = (0.5 * (s[0] + s[1]), 0.5 * (s[0] - s[1]), s[3]);
        let r = (d * d + t * t).sqrt();
        let mut sorted = [(c - r, 0u8), (c + r, 1), (s[2], 2)];
        sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
        Principal { sorted, d, t, r }
    }

    /// The principal values, ascending (compression first), Pa.
    pub fn values(&self) -> [f64; 3] {
        self.sorted.map(|(v, _)| v)
    }

    /// Write corrected principal values `p` (Pa, in the order of `values`) back into `s`.
    pub fn put(&self, p: &[f64; 3], s: &mut Stress) {
        let mut by_origin = [0.0; 3];
        for (k, &(_, origin)) in self.sorted.iter().enumerate() {
            by_origin[origin as usize] = p[k];
        }
        let (minor, major) = (by_origin[0], by_origin[1]);
        let c_new = 0.5 * (minor + major);
        let scale = if self.r > 0.0 {
            0.5 * (major - minor) / self.r
        } else {
            0.0
        };
        s[0] = c_new + self.d * scale;
        s[1] = c_new - self.d * scale;
        s[3] = self.t * scale;
        s[2] = by_origin[2];
    }
}

/// A zone's state bits after a return that set the bits `now` (shear and/or tension now): the
/// past bits kept, and set for what yields now.
pub(super) fn state_after(state: u8, now: u8) -> u8 {
    (state & (SHEAR_PAST | TENSION_PAST))
        | now
        | if now & SHEAR_NOW != 0 { SHEAR_PAST } else { 0 }
        | if now & TENSION_NOW != 0 {
            TENSION_PAST
        } else {
            0
        }
}
