//! The cubic law: laminar flow between parallel plates.

/// The conductance of a pipe of hydraulic aperture `aperture` (m) and length `length` (m) along
/// the flow, for a fluid of viscosity `viscosity` (Pa·s): C = a³ / (12 μ l), m²/(Pa·s) per metre
/// out of the plane, so that the flow q = C Δh (m²/s per metre) for a head difference Δh (Pa).
/// (Snow 1965; Witherspoon et al. 1980, "Validity of cubic law for fluid flow in a deformable
/// rock fracture", Water Resources Research 16(6).)
pub fn cubic_law_conductance(aperture: f64, length: f64, viscosity: f64) -> f64 {
    aperture.powi(3) / (12.0 * viscosity * length)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Parallel plates 1e-4 m apart over 10 m under 1 MPa: Q = a³Δp/(12μL) = 8.333e-6 m²/s.
    #[test]
    fn parallel_plates_pass_the_cubic_laws_flow() {
        let q = cubic_law_conductance(1e-4, 10.0, 1e-3) * 1e6;
        assert_relative_eq!(q, 8.333_333e-6, max_relative = 1e-6);
    }
}
