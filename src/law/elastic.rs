//! Isotropic linear elasticity in plane strain.

use super::{StrainIncrement, Stress, ZoneLaw};

/// Isotropic elastic material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Elastic {
    /// Bulk modulus K = E / (3(1 − 2ν)), Pa.
    pub(crate) bulk: f64,
    /// Shear modulus G = E / (2(1 + ν)), Pa.
    pub shear: f64,
    /// Density, kg/m³.
    pub density: f64,
}

impl Elastic {
    /// From Young's modulus E (Pa), Poisson's ratio ν and density ρ (kg/m³).
    pub fn from_young(young: f64, poisson: f64, density: f64) -> Elastic {
        Elastic {
            bulk: young / (3.0 * (1.0 - 2.0 * poisson)),
            shear: young / (2.0 * (1.0 + poisson)),
            density,
        }
    }
}

/// The plane-strain moduli α1 = K + 4G/3 and α2 = K − 2G/3 (Pa) of bulk modulus K and shear
/// modulus G (Pa): Δσxx = α1 Δεxx + α2 Δεyy in plane strain (Itasca, FLAC *Theory and
/// Background*, §1.3.3).
#[inline]
pub fn plane_strain_moduli(bulk: f64, shear: f64) -> (f64, f64) {
    (bulk + 4.0 / 3.0 * shear, bulk - 2.0 / 3.0 * shear)
}

impl ZoneLaw for Elastic {
    /// Elastic rock has no strength to reduce.
    fn reduced(&self, _factor: f64) -> Box<dyn ZoneLaw> {
        Box::new(*self)
    }

    /// Hooke's law in plane strain (Δεzz = 0), with α1 = K + 4G/3 and α2 = K − 2G/3:
    /// Δσxx = α1 Δεxx + α2 Δεyy, Δσyy = α2 Δεxx + α1 Δεyy, Δσzz = α2 (Δεxx + Δεyy), Δσxy = G Δγxy
    /// (Itasca, FLAC *Theory and Background*, §1.3.3).
    #[inline]
    fn update(&self, s: &mut Stress, _state: &mut u8, _plastic: &mut f64, de: &StrainIncrement) {
        let (a1, a2) = plane_strain_moduli(self.bulk, self.shear);
        s[0] += a1 * de[0] + a2 * de[1];
        s[1] += a2 * de[0] + a1 * de[1];
        s[2] += a2 * (de[0] + de[1]);
        s[3] += self.shear * de[2];
    }

    fn moduli(&self) -> (f64, f64) {
        (self.bulk, self.shear)
    }

    fn density(&self) -> f64 {
        self.density
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn uniaxial_strain_gives_plane_strain_stresses() {
        let (e, nu) = (10e9, 0.25);
        let law = Elastic::from_young(e, nu, 2500.0);
        let mut s = [0.0; 4];
        law.update(&mut s, &mut 0, &mut 0.0, &[1e-4, 0.0, 0.0]);
        let lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
        let mu = e / (2.0 * (1.0 + nu));
        assert_relative_eq!(s[0], (lambda + 2.0 * mu) * 1e-4, max_relative = 1e-12);
        assert_relative_eq!(s[1], lambda * 1e-4, max_relative = 1e-12);
        assert_relative_eq!(s[2], lambda * 1e-4, max_relative = 1e-12);
    }
}
