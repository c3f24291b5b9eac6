//! Circular hole in an infinite elastic plate under far-field stress (Kirsch 1898), plane strain,
//! tension positive, after Jaeger, Cook & Zimmerman, *Fundamentals of Rock Mechanics*, 4th ed.,
//! §8.4. With P = (Sxx + Syy)/2, Q = (Sxx − Syy)/2 and θ measured from the x axis:
//!
//! σrr = P(1 − a²/r²) + Q(1 − 4a²/r² + 3a⁴/r⁴) cos 2θ
//! σθθ = P(1 + a²/r²) − Q(1 + 3a⁴/r⁴) cos 2θ
//! σrθ = −Q(1 + 2a²/r² − 3a⁴/r⁴) sin 2θ
//!
//! and the displacement induced by excavating the hole (relative to the in-situ state):
//! ur = (a²/2Gr) [P + Q(4(1 − ν) − a²/r²) cos 2θ],  uθ = −(a²/2Gr) Q (2(1 − 2ν) + a²/r²) sin 2θ.

/// The Kirsch problem: hole radius a (m), far field Sxx, Syy (Pa), shear modulus G (Pa), ν.
#[derive(Debug, Clone, Copy)]
pub struct Kirsch {
    pub radius: f64,
    pub sxx: f64,
    pub syy: f64,
    pub shear: f64,
    pub poisson: f64,
}

impl Kirsch {
    fn pq(&self) -> (f64, f64) {
        (0.5 * (self.sxx + self.syy), 0.5 * (self.sxx - self.syy))
    }

    /// Total stress [σxx, σyy, σxy] (Pa) at (x, y), r ≥ a.
    pub fn stress(&self, x: f64, y: f64) -> [f64; 3] {
        let (p, q) = self.pq();
        let r = x.hypot(y);
        let t = y.atan2(x);
        let (a2, a4) = ((self.radius / r).powi(2), (self.radius / r).powi(4));
        let (c2, s2) = ((2.0 * t).cos(), (2.0 * t).sin());
        let srr = p * (1.0 - a2) + q * (1.0 - 4.0 * a2 + 3.0 * a4) * c2;
        let stt = p * (1.0 + a2) - q * (1.0 + 3.0 * a4) * c2;
        let srt = -q * (1.0 + 2.0 * a2 - 3.0 * a4) * s2;
        let (c, s) = (t.cos(), t.sin());
        [
            srr * c * c + stt * s * s - 2.0 * srt * s * c,
            srr * s * s + stt * c * c + 2.0 * srt * s * c,
            (srr - stt) * s * c + srt * (c * c - s * s),
        ]
    }

    /// Excavation-induced displacement [ux, uy] (m) at (x, y), r ≥ a.
    pub fn displacement(&self, x: f64, y: f64) -> [f64; 2] {
        let (p, q) = self.pq();
        let r = x.hypot(y);
        let t = y.atan2(x);
        let a2 = (self.radius / r).powi(2);
        let k = self.radius * self.radius / (2.0 * self.shear * r);
        let ur = k * (p + q * (4.0 * (1.0 - self.poisson) - a2) * (2.0 * t).cos());
        let ut = -k * q * (2.0 * (1.0 - 2.0 * self.poisson) + a2) * (2.0 * t).sin();
        let (c, s) = (t.cos(), t.sin());
        [ur * c - ut * s, ur * s + ut * c]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn case() -> Kirsch {
        Kirsch {
            radius: 1.0,
            sxx: -10e6,
            syy: -20e6,
            shear: 4e9,
            poisson: 0.25,
        }
    }

    #[test]
    fn wall_is_traction_free_and_far_field_is_recovered() {
        let k = case();
        for t in [0.0, 0.4, 1.3, 2.9] {
            let (c, s) = (f64::cos(t), f64::sin(t));
            let st = k.stress(c, s);
            assert!((st[0] * c + st[2] * s).abs() < 1e-6 && (st[2] * c + st[1] * s).abs() < 1e-6);
        }
        let far = k.stress(1e4, 3e3);
        assert_relative_eq!(far[0], -10e6, max_relative = 1e-6);
        assert_relative_eq!(far[1], -20e6, max_relative = 1e-6);
        // Classic concentration: σθθ at the wall on the x axis is 3 Syy − Sxx.
        assert_relative_eq!(
            k.stress(1.0, 0.0)[1],
            3.0 * -20e6 - -10e6,
            max_relative = 1e-12
        );
    }

    /// The displacement field's strain, through plane-strain Hooke's law, gives the stress change
    /// of the Kirsch field: the two halves of the closed form agree.
    #[test]
    fn displacement_and_stress_are_consistent() {
        let k = case();
        let (g, nu) = (k.shear, k.poisson);
        let lambda = 2.0 * g * nu / (1.0 - 2.0 * nu);
        let h = 1e-6;
        for &(x, y) in &[(1.3, 0.4), (-0.7, 1.9), (2.5, -3.0)] {
            let d = |dx: f64, dy: f64| k.displacement(x + dx, y + dy);
            let dudx = [
                (d(h, 0.0)[0] - d(-h, 0.0)[0]) / (2.0 * h),
                (d(h, 0.0)[1] - d(-h, 0.0)[1]) / (2.0 * h),
            ];
            let dudy = [
                (d(0.0, h)[0] - d(0.0, -h)[0]) / (2.0 * h),
                (d(0.0, h)[1] - d(0.0, -h)[1]) / (2.0 * h),
            ];
            let (exx, eyy, gxy) = (dudx[0], dudy[1], dudy[0] + dudx[1]);
            let s = k.stress(x, y);
            let ds = [s[0] - k.sxx, s[1] - k.syy, s[2]];
            let scale = 1e7;
            assert!((lambda * (exx + eyy) + 2.0 * g * exx - ds[0]).abs() < 1e-6 * scale);
            assert!((lambda * (exx + eyy) + 2.0 * g * eyy - ds[1]).abs() < 1e-6 * scale);
            assert!((g * gxy - ds[2]).abs() < 1e-6 * scale);
        }
    }
}
