//! Friction-induced flutter of a block sliding on a Coulomb joint: the linearized stability of
//! steady sliding, the reference against which the incline's deformable and simple blocks are read.
//!
//! A block sliding with every contact slipping feels at each contact a normal force −kn L δn and a
//! friction force μ kn L δn along the slide, so the friction couples the normal displacement δn
//! into tangential forces and the stiffness of small perturbations is not symmetric:
//! K = K_elastic + Σ kn L Tᵀ (−μ t + n) nᵀ T. Two modes whose frequencies it brings together merge
//! into a pair that grows as e^(σt) (mode-coupling instability: Martins, Oden & Simões, *Int. J.
//! Eng. Sci.* 28, 1990; Hoffmann et al., *Mech. Res. Commun.* 29, 2002; for elastic half-spaces,
//! Adams, *J. Appl. Mech.* 62, 1995). A rigid block whose whole base stays closed has no such
//! pair: its tangential motion feels no stiffness, so the coupling is one-way and σ = 0. Beyond
//! the kern its heel lifts (`heel`), and then its bounce and rocking couple through the friction's
//! moment and it can flutter too; the linearization is about the closed contacts only. A
//! deformable or simple block has such a pair, above a friction coefficient that falls as the
//! joint gets stiffer against the block; its vibration then
//! grows until contacts open and, where the slide is slower than the vibration, reverse their slip,
//! so the friction averages out and the block slides faster than the rigid closed form. This is the
//! modelled system's own dynamics, not an error of the integration: it does not go away with a
//! smaller step or smaller zones.
//!
//! Here the simple block of the engine (`adit::model::bodies`: rigid motion plus uniform strain,
//! the lumped generalized masses of `Moments::masses`) is linearized about steady sliding on a
//! rigid base with point contacts at its base nodes, and σ is the largest real part of the
//! eigenvalues of the first-order system ẋ = [0 I; −M⁻¹K 0] x.

use adit::cycle::timestep::lumped_masses;
use adit::model::Model;
use adit::model::bodies::{DOFS, Moments, velocity_map};
use nalgebra::DMatrix;

/// A rectangular block resting on a rigid base through equally spaced point contacts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlidingBlock {
    /// Width along the slide, m.
    pub width: f64,
    /// Height, m.
    pub height: f64,
    /// Density ρ, kg/m³.
    pub density: f64,
    /// Young's modulus E, Pa.
    pub young: f64,
    /// Poisson's ratio ν.
    pub poisson: f64,
    /// Joint normal stiffness kn, Pa/m.
    pub normal_stiffness: f64,
    /// Contacts along the base, including the two corners (at least 2).
    pub contacts: usize,
}

impl SlidingBlock {
    /// The incline's block: 1 m × `incline::BLOCK_HEIGHT`, ρ = 2 500 kg/m³, E = 10 GPa, ν = 0.25,
    /// contacts at its base nodes 0.125 m apart.
    pub fn incline(normal_stiffness: f64) -> SlidingBlock {
        SlidingBlock {
            width: 1.0,
            height: crate::incline::BLOCK_HEIGHT,
            density: 2500.0,
            young: 10e9,
            poisson: 0.25,
            normal_stiffness,
            contacts: 9,
        }
    }

    /// The base contacts: their places x along the slide from the block's middle, m, and the
    /// lengths of joint they stand for, m (the trapezoidal rule over the contacts' spacing).
    fn base(&self) -> impl Iterator<Item = (f64, f64)> {
        let n = self.contacts.max(2);
        let spacing = self.width / (n - 1) as f64;
        (0..n).map(move |c| {
            let x = -0.5 * self.width + c as f64 * spacing;
            let ends = c == 0 || c == n - 1;
            (x, if ends { 0.5 * spacing } else { spacing })
        })
    }

    /// Growth rate σ, 1/s, of the fastest-growing small perturbation of steady sliding with friction
    /// coefficient `mu` (all contacts slipping), for the block's first `dofs` generalized degrees of
    /// freedom (3: rigid, 6: simple); 0 when steady sliding is stable.
    pub fn growth_rate(&self, mu: f64, dofs: usize) -> f64 {
        self.damped_growth_rate(mu, dofs, 0.0)
    }

    /// The same with stiffness-proportional Rayleigh damping β_R (s): the engine's viscous
    /// stresses are β_R times the rate of the zones' and contacts' stresses, friction included,
    /// so the damping matrix is C = β_R K.
    pub fn damped_growth_rate(&self, mu: f64, dofs: usize, beta: f64) -> f64 {
        let (w, h) = (self.width, self.height);
        let moments = Moments {
            area: w * h,
            centroid: [0.0; 2],
            xx: h * w.powi(3) / 12.0,
            yy: w * h.powi(3) / 12.0,
            xy: 0.0,
        };
        let mass = moments.masses(self.density);
        let mut k = DMatrix::<f64>::zeros(DOFS, DOFS);
        // Uniform plane strain εxx = q3, εyy = q4, γxy = 2 q5 of the whole block.
        let (nu, e) = (self.poisson, self.young);
        let lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
        let g = e / (2.0 * (1.0 + nu));
        let a = w * h;
        k[(3, 3)] = a * (lambda + 2.0 * g);
        k[(4, 4)] = a * (lambda + 2.0 * g);
        k[(3, 4)] = a * lambda;
        k[(4, 3)] = a * lambda;
        k[(5, 5)] = 4.0 * g * a;
        let base: Vec<(f64, f64)> = self.base().collect();
        let heel = heel(&base, 0.5 * mu * h);
        for &(x, length) in base.iter().filter(|&&(x, _)| x > heel) {
            let t = velocity_map([x, -0.5 * h]);
            // Force on the block per unit normal displacement δn = t[1]·q: (−μ, 1) kn L (−δn)…
            // acting through Tᵀ: K += kn L Tᵀ (−μ, 1)ᵀ t[1].
            for i in 0..DOFS {
                let force_dir = -mu * t[0][i] + t[1][i];
                for j in 0..DOFS {
                    k[(i, j)] += self.normal_stiffness * length * force_dir * t[1][j];
                }
            }
        }
        let d = dofs.min(DOFS);
        growth_rate(&k.view((0, 0), (d, d)).into_owned(), &mass[..d], beta)
    }
}

/// Growth rate σ, 1/s, of the same linearization for a deformable block of the engine's own
/// mesh: block `block` of `model` (its zones' plane-strain CST stiffness, its real lumped masses)
/// on a rigid base through point contacts at its lowest nodes, each of the node's tributary length
/// along the base, slipping along +x with friction coefficient `mu` on a joint of normal
/// stiffness `kn`, Pa/m, with stiffness-proportional damping `beta`, s (C = β_R K).
pub fn deformable_growth_rate(model: &Model, block: usize, mu: f64, kn: f64, beta: f64) -> f64 {
    partly_slipping_growth_rate(model, block, mu, kn, beta, &|_| false)
}

/// [`deformable_growth_rate`] with the base nodes for which `stuck` (of the node) is true held by
/// their joint instead of slipping: normal and shear springs kn L (the incline's joint has
/// ks = kn) and no friction coupling. A block holding with part of its base at the friction
/// limit, linearized with those contacts slipping: a perturbation that slips them grows at σ.
pub fn partly_slipping_growth_rate(
    model: &Model,
    block: usize,
    mu: f64,
    kn: f64,
    beta: f64,
    stuck: &dyn Fn(usize) -> bool,
) -> f64 {
    let start = model.blocks.node_start[block] as usize;
    let end = model.blocks.node_start[block + 1] as usize;
    let n = end - start;
    let dof = |node: u32, d: usize| 2 * (node as usize - start) + d;
    let mut k = DMatrix::<f64>::zeros(2 * n, 2 * n);
    let zones = &model.zones;
    for z in (0..zones.len()).filter(|&z| zones.block[z] as usize == block) {
        let (bulk, shear) = model.materials.zone[zones.material[z].0 as usize].moduli();
        let (a1, a2) = (bulk + 4.0 / 3.0 * shear, bulk - 2.0 / 3.0 * shear);
        let (g, area) = (zones.grad[z], zones.area[z]);
        // Strain (εxx, εyy, γxy) per unit displacement of corner i in direction d.
        let b = |i: usize, d: usize| -> [f64; 3] {
            if d == 0 {
                [g[i], 0.0, g[3 + i]]
            } else {
                [0.0, g[3 + i], g[i]]
            }
        };
        for (i, &ni) in zones.nodes[z].iter().enumerate() {
            for di in 0..2 {
                let e = b(i, di);
                let s = [a1 * e[0] + a2 * e[1], a2 * e[0] + a1 * e[1], shear * e[2]];
                for (j, &nj) in zones.nodes[z].iter().enumerate() {
                    for dj in 0..2 {
                        let f = b(j, dj);
                        k[(dof(ni, di), dof(nj, dj))] +=
                            area * (s[0] * f[0] + s[1] * f[1] + s[2] * f[2]);
                    }
                }
            }
        }
    }
    let x = |node: usize| {
        let (p, u) = (model.nodes.pos[node], model.nodes.disp[node]);
        [p[0] + u[0], p[1] + u[1]]
    };
    let bottom = (start..end).map(|i| x(i)[1]).fold(f64::INFINITY, f64::min);
    let mut base: Vec<usize> = (start..end).filter(|&i| x(i)[1] - bottom < 1e-6).collect();
    base.sort_by(|&a, &b| x(a)[0].total_cmp(&x(b)[0]));
    // The block's centroid, m, and its base nodes' places from below it and tributary lengths, m.
    let block_zones = || (0..zones.len()).filter(|&z| zones.block[z] as usize == block);
    let area: f64 = block_zones().map(|z| zones.area[z]).sum();
    let centroid = [0, 1].map(|d| {
        block_zones()
            .map(|z| {
                zones.area[z]
                    * zones.nodes[z]
                        .iter()
                        .map(|&n| x(n as usize)[d])
                        .sum::<f64>()
                    / 3.0
            })
            .sum::<f64>()
            / area
    });
    let contacts: Vec<(f64, f64)> = (0..base.len())
        .map(|c| {
            let at = |c: usize| x(base[c])[0];
            let left = if c > 0 { at(c) - at(c - 1) } else { 0.0 };
            let right = if c + 1 < base.len() {
                at(c + 1) - at(c)
            } else {
                0.0
            };
            (at(c) - centroid[0], 0.5 * (left + right))
        })
        .collect();
    let heel = heel(&contacts, mu * (centroid[1] - bottom));
    for (&node, &(place, length)) in base.iter().zip(&contacts) {
        if place <= heel {
            continue;
        }
        let spring = kn * length;
        let stuck_here = stuck(node);
        let node = node as u32;
        if stuck_here {
            k[(dof(node, 1), dof(node, 1))] += spring;
            k[(dof(node, 0), dof(node, 0))] += spring;
            continue;
        }
        // Normal force on the node −kn L uy (up when it sinks), friction −μ times it along x.
        k[(dof(node, 1), dof(node, 1))] += spring;
        k[(dof(node, 0), dof(node, 1))] -= mu * spring;
    }
    let masses = lumped_masses(model);
    let mass: Vec<f64> = (0..2 * n).map(|i| masses[start + i / 2]).collect();
    growth_rate(&k, &mass, beta)
}

/// Where the closed contacts of steady sliding begin along the slide, m, of a block on `base`
/// contacts (their places x along the slide from below the block's centroid, m, and the lengths
/// of joint they stand for, m), whose normal forces' resultant lies `e` m ahead of the centroid;
/// −∞ when all stay closed. Sliding with friction coefficient μ, the friction μN at the base, a
/// height c below the centroid, turns the block towards its toe, so e = μ c (moments about the
/// centroid; μ h / 2 for a rectangle of height h). The block is taken stiff against the joint:
/// the forces are kn L δ(x) with δ linear in x. Beyond the kern (e greater than their centroid
/// with δ = 0 at the heel) the heel lifts, δ(x) = x − x0 where positive, and x0 is where that
/// distribution's centroid is e.
pub fn heel(base: &[(f64, f64)], e: f64) -> f64 {
    let centroid = |x0: f64| {
        let (mut f, mut m) = (0.0, 0.0);
        for &(x, l) in base.iter().filter(|&&(x, _)| x > x0) {
            f += l * (x - x0);
            m += l * (x - x0) * x;
        }
        m / f
    };
    let mut lo = base.iter().map(|b| b.0).fold(f64::INFINITY, f64::min);
    let mut hi = base.iter().map(|b| b.0).fold(f64::NEG_INFINITY, f64::max);
    if centroid(lo) >= e {
        return f64::NEG_INFINITY;
    }
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if centroid(mid) < e {
            lo = mid
        } else {
            hi = mid
        }
    }
    lo
}

/// Largest real part, 1/s, of the eigenvalues of ẋ = [0 I; −M⁻¹K −β M⁻¹K] x for a diagonal
/// mass M and damping C = β K (0 when none is positive).
fn growth_rate(k: &DMatrix<f64>, mass: &[f64], beta: f64) -> f64 {
    let d = mass.len();
    let mut system = DMatrix::<f64>::zeros(2 * d, 2 * d);
    for i in 0..d {
        system[(i, d + i)] = 1.0;
        for j in 0..d {
            system[(d + i, j)] = -k[(i, j)] / mass[i];
            system[(d + i, d + j)] = -beta * k[(i, j)] / mass[i];
        }
    }
    system
        .complex_eigenvalues()
        .iter()
        .map(|l| l.re)
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    const TAN_44: f64 = 0.965_688_774_807_074;

    #[test]
    fn frictionless_and_rigid_sliding_are_stable() {
        for kn in [1e9, 1e11, 1e12] {
            let b = SlidingBlock::incline(kn);
            assert!(b.growth_rate(0.0, 6) < 1e-6 * kn.sqrt());
            assert!(b.growth_rate(TAN_44, 3) < 1e-6 * kn.sqrt());
        }
    }

    /// The simple block flutters above a friction coefficient that falls as the joint stiffens:
    /// stable on a soft joint (1e8 Pa/m) at any friction up to φ = 44°, unstable on the incline's
    /// joint (1e11 Pa/m) at 40° and 44°, growing faster with friction and stiffness.
    #[test]
    fn simple_block_flutters_on_stiff_frictional_joints() {
        let soft = SlidingBlock::incline(1e8);
        assert!(soft.growth_rate(TAN_44, 6) < 1e-3);
        let stiff = SlidingBlock::incline(1e11);
        let at_40 = stiff.growth_rate(40f64.to_radians().tan(), 6);
        let at_44 = stiff.growth_rate(TAN_44, 6);
        assert!(at_40 > 100.0 && at_44 > at_40, "{at_40} {at_44}");
        let at_1e10 = SlidingBlock::incline(1e10).growth_rate(TAN_44, 6);
        assert!(at_1e10 > 10.0 && at_1e10 < at_44, "{at_1e10} {at_44}");
    }

    /// On a uniform base (many contacts) the heel lifts once the resultant leaves the kern
    /// (e > L/6), and the closed part is then the triangle whose centroid is e.
    #[test]
    fn the_heel_lifts_beyond_the_kern() {
        let base: Vec<(f64, f64)> = (0..=1000)
            .map(|c| {
                (
                    -0.5 + c as f64 * 1e-3,
                    if c == 0 || c == 1000 { 5e-4 } else { 1e-3 },
                )
            })
            .collect();
        assert_eq!(heel(&base, 1.0 / 6.0 - 1e-3), f64::NEG_INFINITY);
        // Triangle over [x0, 1/2]: centroid x0 + (1/2 − x0)·2/3 = e, so x0 = 3e − 1.
        let x0 = heel(&base, 0.3);
        assert!((x0 - (3.0 * 0.3 - 1.0)).abs() < 2e-3, "{x0}");
    }

    /// A block 0.5 m high on the incline lifts its heel sliding on φ = 44°, and then even a rigid
    /// block flutters (its bounce and rocking couple through the friction moment); the shipped
    /// block (`incline::BLOCK_HEIGHT`) keeps its base closed and its rigid slide stable.
    #[test]
    fn a_rigid_block_that_lifts_its_heel_flutters() {
        for kn in [1e9, 1e11] {
            let shipped = SlidingBlock::incline(kn);
            let tall = SlidingBlock {
                height: 0.5,
                ..shipped
            };
            let base: Vec<(f64, f64)> = shipped.base().collect();
            assert_eq!(
                heel(&base, 0.5 * TAN_44 * shipped.height),
                f64::NEG_INFINITY
            );
            assert!(heel(&base, 0.5 * TAN_44 * tall.height) > -0.5);
            assert!(shipped.growth_rate(TAN_44, 3) < 1e-6 * kn.sqrt());
            let sigma = tall.growth_rate(TAN_44, 3);
            assert!(sigma > 1e-3 * kn.sqrt(), "{kn:e}: {sigma}");
        }
    }
}
