//! The hydraulic aperture of a joint, which follows its opening.

/// A joint's hydraulic aperture a = a₀ + uₙ (uₙ the joint's normal displacement since the
/// aperture was a₀, opening positive, m), held between a residual aperture (a closed joint still
/// passes water) and a largest one (UDEC's `azero`, `ares`, `amax`). Apertures in m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HydraulicAperture {
    /// The aperture at zero normal displacement a₀, m.
    pub zero: f64,
    /// The smallest aperture, reached on closing, m.
    pub residual: f64,
    /// The largest aperture, reached on opening, m.
    pub maximum: f64,
}

impl HydraulicAperture {
    /// The aperture at normal displacement `opening` (m, positive opening), m.
    pub fn at(&self, opening: f64) -> f64 {
        (self.zero + opening).clamp(self.residual, self.maximum)
    }

    /// The law, or an error (naming the field under `field`) when the apertures are not
    /// 0 < residual ≤ zero ≤ maximum.
    pub fn checked(self, field: &str) -> Result<HydraulicAperture, String> {
        let finite = [self.zero, self.residual, self.maximum]
            .iter()
            .all(|v| v.is_finite());
        if !finite || self.residual <= 0.0 {
            return Err(format!(
                "{field}: the residual aperture must be a positive number of metres (got {})",
                self.residual
            ));
        }
        if !(self.residual <= self.zero && self.zero <= self.maximum) {
            return Err(format!(
                "{field}: apertures must be residual ≤ zero ≤ maximum (got {} ≤ {} ≤ {} m)",
                self.residual, self.zero, self.maximum
            ));
        }
        Ok(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_aperture_follows_the_opening_between_its_bounds() {
        let a = HydraulicAperture {
            zero: 1e-4,
            residual: 2e-5,
            maximum: 5e-4,
        }
        .checked("joint_materials.j.hydraulic")
        .unwrap();
        assert_eq!(a.at(0.0), 1e-4);
        assert!((a.at(5e-5) - 1.5e-4).abs() < 1e-18);
        assert_eq!(a.at(-1e-3), 2e-5);
        assert_eq!(a.at(1e-2), 5e-4);
        let bad = HydraulicAperture {
            residual: 2e-4,
            ..a
        };
        let e = bad.checked("joint_materials.j.hydraulic").unwrap_err();
        assert!(e.contains("joint_materials.j.hydraulic"), "{e}");
    }
}
