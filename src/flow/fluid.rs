//! The fluid in the joints.

/// A fluid's properties, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fluid {
    /// Density ρw, kg/m³.
    pub density: f64,
    /// Dynamic viscosity μ, Pa·s.
    pub viscosity: f64,
    /// Bulk modulus Kw, Pa.
    pub bulk_modulus: f64,
}

impl Fluid {
    /// Water at 20 °C: ρw 1 000 kg/m³, μ 1.0e-3 Pa·s, Kw 2.0 GPa.
    pub const WATER: Fluid = Fluid {
        density: 1000.0,
        viscosity: 1.0e-3,
        bulk_modulus: 2.0e9,
    };

    /// The fluid, or an error naming the first property that is not a positive finite number.
    pub fn checked(self) -> Result<Fluid, String> {
        for (name, v) in [
            ("density", self.density),
            ("viscosity", self.viscosity),
            ("bulk_modulus", self.bulk_modulus),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(format!("fluid.{name}: {v} is not a positive number"));
            }
        }
        Ok(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_property_that_is_not_positive_is_named() {
        assert!(Fluid::WATER.checked().is_ok());
        let e = Fluid {
            viscosity: 0.0,
            ..Fluid::WATER
        }
        .checked()
        .unwrap_err();
        assert!(e.contains("fluid.viscosity"), "{e}");
        let e = Fluid {
            bulk_modulus: f64::NAN,
            ..Fluid::WATER
        }
        .checked()
        .unwrap_err();
        assert!(e.contains("fluid.bulk_modulus"), "{e}");
    }
}
