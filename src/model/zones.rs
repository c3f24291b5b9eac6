//! Zone state: constant-strain triangles with precomputed shape-function gradients, area, stress,
//! material, yield state and block.

use super::MaterialId;

pub use crate::law::Stress;

/// Structure-of-arrays zone state.
#[derive(Debug, Clone, Default)]
pub struct Zones {
    /// Corner nodes, counter-clockwise.
    pub nodes: Vec<[u32; 3]>,
    /// Area, m².
    pub area: Vec<f64>,
    /// Shape-function gradients [∂N0/∂x, ∂N1/∂x, ∂N2/∂x, ∂N0/∂y, ∂N1/∂y, ∂N2/∂y], 1/m.
    pub grad: Vec<[f64; 6]>,
    /// Stress, Pa.
    pub stress: Vec<Stress>,
    /// Material of each zone.
    pub material: Vec<MaterialId>,
    /// Yield-state bit flags (0: elastic).
    pub state: Vec<u8>,
    /// Accumulated plastic shear strain e^ps (dimensionless; softening laws read it).
    pub plastic: Vec<f64>,
    /// Block each zone belongs to.
    pub block: Vec<u32>,
}

/// CST gradients of a counter-clockwise triangle: with 2A = (x1−x0)(y2−y0) − (x2−x0)(y1−y0),
/// ∂Ni/∂x = (yj − yk)/2A and ∂Ni/∂y = (xk − xj)/2A for (i, j, k) cyclic
/// (Zienkiewicz & Taylor, *The Finite Element Method*, vol. 1, §6.2). Returns (gradients, area m²).
pub fn cst_gradients(p: [[f64; 2]; 3]) -> ([f64; 6], f64) {
    let two_a =
        (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
    let mut g = [0.0; 6];
    for i in 0..3 {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        g[i] = (p[j][1] - p[k][1]) / two_a;
        g[3 + i] = (p[k][0] - p[j][0]) / two_a;
    }
    (g, 0.5 * two_a)
}

/// Traction t = σ·n (Pa) of an in-plane stress on a plane of unit normal n (Cauchy's formula).
pub fn traction(s: &Stress, n: [f64; 2]) -> [f64; 2] {
    [s[0] * n[0] + s[3] * n[1], s[3] * n[0] + s[1] * n[1]]
}

impl Zones {
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// Zones over the given triangles with node positions `pos`, stress-free, material 0, block 0.
    pub fn from_triangles(triangles: &[[u32; 3]], pos: &[[f64; 2]]) -> Zones {
        let (grad, area): (Vec<_>, Vec<_>) = triangles
            .iter()
            .map(|t| cst_gradients(t.map(|n| pos[n as usize])))
            .unzip();
        let n = triangles.len();
        Zones {
            nodes: triangles.to_vec(),
            area,
            grad,
            stress: vec![[0.0; 4]; n],
            material: vec![MaterialId(0); n],
            state: vec![0; n],
            plastic: vec![0.0; n],
            block: vec![0; n],
        }
    }

    /// Centroid of zone `z`, m.
    pub fn centroid(&self, z: usize, pos: &[[f64; 2]]) -> [f64; 2] {
        let t = self.nodes[z];
        let mut c = [0.0; 2];
        for &n in &t {
            c[0] += pos[n as usize][0] / 3.0;
            c[1] += pos[n as usize][1] / 3.0;
        }
        c
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn gradients_reproduce_a_linear_field() {
        let p = [[0.3, -0.2], [2.1, 0.4], [0.7, 1.9]];
        let (g, a) = cst_gradients(p);
        assert!(a > 0.0);
        // f = 2 + 3x − 5y: Σ f_i ∂N_i/∂x = 3, Σ f_i ∂N_i/∂y = −5.
        let f: Vec<f64> = p.iter().map(|q| 2.0 + 3.0 * q[0] - 5.0 * q[1]).collect();
        assert_relative_eq!(
            (0..3).map(|i| f[i] * g[i]).sum::<f64>(),
            3.0,
            epsilon = 1e-12
        );
        assert_relative_eq!(
            (0..3).map(|i| f[i] * g[3 + i]).sum::<f64>(),
            -5.0,
            epsilon = 1e-12
        );
    }
}
