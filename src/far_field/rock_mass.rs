//! A jointed rock mass as an equivalent elastic continuum: intact rock plus sets of parallel
//! joints smeared over their spacing (Goodman, *Introduction to Rock Mechanics*, 1989, §6.5;
//! Amadei & Goodman 1981). A joint of unit normal n and tangent t, spacing s, normal and shear
//! stiffness kₙ, kₛ opens by σₙ/kₙ and slides by τ/kₛ, so the set adds the strain
//!
//! ε = (1/s) [ (σₙ/kₙ) n⊗n + (τ/kₛ) (n⊗t + t⊗n)/2 ],  σₙ = n·σn, τ = t·σn,
//!
//! and its compliance, in (ε_xx, ε_yy, γ_xy) against (σ_xx, σ_yy, σ_xy), is
//! (1/s) (a aᵀ/kₙ + c cᵀ/kₛ) with a = (n_x², n_y², 2 n_x n_y), c = (t_x n_x, t_y n_y, t_x n_y + t_y n_x).
//! The joints are stuck (elastic): what slips or opens belongs in the near field.

/// One set of parallel joints.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointSet {
    /// Dip: the joints' direction, degrees counter-clockwise from +x.
    pub dip: f64,
    /// Perpendicular spacing, m, divided by the share of each joint line that is joint (the
    /// persistence) for non-persistent joints.
    pub spacing: f64,
    /// Normal stiffness kₙ, Pa/m.
    pub normal_stiffness: f64,
    /// Shear stiffness kₛ, Pa/m.
    pub shear_stiffness: f64,
}

/// The plane-strain compliance of intact isotropic rock (Young's modulus E, Pa; Poisson's ratio
/// ν), Pa⁻¹: b₁₁ = b₂₂ = (1 − ν²)/E, b₁₂ = −ν(1 + ν)/E, b₆₆ = 2(1 + ν)/E.
pub fn plane_strain_compliance(young: f64, poisson: f64) -> [[f64; 3]; 3] {
    let (d, o, g) = (
        (1.0 - poisson * poisson) / young,
        -poisson * (1.0 + poisson) / young,
        2.0 * (1.0 + poisson) / young,
    );
    [[d, o, 0.0], [o, d, 0.0], [0.0, 0.0, g]]
}

/// The compliance `intact` (Pa⁻¹) with each of `sets` smeared in, Pa⁻¹.
pub fn jointed_compliance(intact: [[f64; 3]; 3], sets: &[JointSet]) -> [[f64; 3]; 3] {
    let mut b = intact;
    for set in sets {
        let (sin, cos) = set.dip.to_radians().sin_cos();
        let (t, n) = ([cos, sin], [-sin, cos]);
        let a = [n[0] * n[0], n[1] * n[1], 2.0 * n[0] * n[1]];
        let c = [t[0] * n[0], t[1] * n[1], t[0] * n[1] + t[1] * n[0]];
        for i in 0..3 {
            for j in 0..3 {
                b[i][j] += (a[i] * a[j] / set.normal_stiffness + c[i] * c[j] / set.shear_stiffness)
                    / set.spacing;
            }
        }
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Loaded across a horizontal set, the mass strains as intact rock plus σ/(kₙ s); sheared
    /// along it, plus τ/(kₛ s); and the compliance turns with the set as a tensor does.
    #[test]
    fn a_set_adds_its_opening_and_sliding_per_spacing() {
        let intact = plane_strain_compliance(20e9, 0.25);
        let set = JointSet {
            dip: 0.0,
            spacing: 2.0,
            normal_stiffness: 1e10,
            shear_stiffness: 4e9,
        };
        let b = jointed_compliance(intact, &[set]);
        assert!((b[1][1] - intact[1][1] - 1.0 / 2e10).abs() < 1e-24);
        assert!((b[2][2] - intact[2][2] - 1.0 / 8e9).abs() < 1e-24);
        assert_eq!(b[0][0], intact[0][0]);
        // Turned by 90°, the set stiffens y and softens x instead.
        let turned = jointed_compliance(intact, &[JointSet { dip: 90.0, ..set }]);
        assert!((turned[0][0] - b[1][1]).abs() < 1e-24);
        assert!((turned[1][1] - b[0][0]).abs() < 1e-24);
        assert!((turned[2][2] - b[2][2]).abs() < 1e-24);
        // At 30°: σ along the set's normal strains it by σ (b_intact + 1/(kₙ s)) along it.
        let (sin, cos) = 120f64.to_radians().sin_cos();
        let oblique = jointed_compliance(intact, &[JointSet { dip: 30.0, ..set }]);
        let sigma = [cos * cos, sin * sin, sin * cos];
        let eps: Vec<f64> = (0..3)
            .map(|i| (0..3).map(|j| oblique[i][j] * sigma[j]).sum())
            .collect();
        let along = eps[0] * cos * cos + eps[1] * sin * sin + eps[2] * sin * cos;
        assert!((along - intact[0][0] - 1.0 / 2e10).abs() < 1e-22, "{along}");
    }
}
