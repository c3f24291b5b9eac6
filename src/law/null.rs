//! The null law of excavated zones: no stress, no stiffness (FLAC's null model).

use super::{StrainIncrement, Stress, ZoneLaw};

/// Excavated material.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Null;

impl ZoneLaw for Null {
    /// Excavated rock has no strength to reduce.
    fn reduced(&self, _factor: f64) -> Box<dyn ZoneLaw> {
        Box::new(Null)
    }

    fn update(&self, s: &mut Stress, state: &mut u8, _plastic: &mut f64, _de: &StrainIncrement) {
        *s = [0.0; 4];
        *state = 0;
    }

    fn moduli(&self) -> (f64, f64) {
        (0.0, 0.0)
    }

    fn density(&self) -> f64 {
        0.0
    }
}
