//! The tangent stiffness of the zones in sparse form: constant-strain triangles in plane strain,
//! over the free degrees of freedom.

use faer::sparse::{SparseColMat, Triplet};
use rayon::prelude::*;

use super::bodies::BodyDofs;
use super::structural::{SupportDofs, support_stiffness};
use crate::cycle::contact_normal;
use crate::far_field::FarField;
use crate::joint::JointLaw;
use crate::law::{ZoneLaw, plane_strain_moduli};
use crate::model::blocks::Blocks;
use crate::model::bodies::{Bodies, NO_BODY};
use crate::model::{BODY, Contacts, FIX_X, FIX_Y, Model, Nodes, Zones};
use crate::support::Supports;

/// Marks a fixed component: no unknown.
pub const FIXED: u32 = u32::MAX;

/// The unknowns: for each node its x and y component's equation number, or `FIXED` (a fixed
/// component, or a node of a rigid or simple block, which follows its body's); then the bodies'
/// and the installed supports' own.
pub struct Dofs {
    pub of_node: Vec<[u32; 2]>,
    pub bodies: BodyDofs,
    pub supports: SupportDofs,
    pub count: usize,
}

impl Dofs {
    /// One unknown per component of a zoned block's node that is not fixed, numbered node by
    /// node, then those of the bodies and of the installed bolts and liners.
    pub fn of(nodes: &Nodes, bodies: &Bodies, supports: &Supports) -> Dofs {
        let mut count = 0usize;
        let of_node = (nodes.fixed.iter())
            .map(|&f| {
                [FIX_X, FIX_Y].map(|flag| {
                    if f & (flag | BODY) != 0 {
                        FIXED
                    } else {
                        count += 1;
                        (count - 1) as u32
                    }
                })
            })
            .collect();
        let (bodies, count) = BodyDofs::of(bodies, count);
        let (supports, count) = SupportDofs::of(supports, count);
        Dofs {
            of_node,
            bodies,
            supports,
            count,
        }
    }

    /// How component `d` of node `n` moves with the unknowns: its own equation, or through its
    /// body's (at the current positions `x`), or not at all.
    pub fn terms(&self, bodies: &Bodies, x: &[[f64; 2]], n: u32, d: usize) -> Terms {
        let n = n as usize;
        match bodies.of_node.get(n) {
            Some(&k) if k != NO_BODY => {
                let c = bodies.centroid[k as usize];
                let r = [x[n][0] - c[0], x[n][1] - c[1]];
                self.bodies.node_terms(k as usize, r, d)
            }
            _ => {
                let mut t = Terms::default();
                if self.of_node[n][d] != FIXED {
                    t.push(self.of_node[n][d], 1.0);
                }
                t
            }
        }
    }
}

/// A node component as a combination of unknowns: up to six (equation, coefficient) pairs.
#[derive(Debug, Clone, Copy, Default)]
pub struct Terms {
    eq: [u32; 6],
    coef: [f64; 6],
    len: usize,
}

impl Terms {
    pub fn push(&mut self, eq: u32, coef: f64) {
        self.eq[self.len] = eq;
        self.coef[self.len] = coef;
        self.len += 1;
    }

    fn pairs(&self) -> impl Iterator<Item = (u32, f64)> + '_ {
        self.eq[..self.len]
            .iter()
            .copied()
            .zip(self.coef[..self.len].iter().copied())
    }
}

/// The lower-triangle entries of a dense element matrix `k` (k(r, c) over the element's
/// components) whose components move with the unknowns as `terms` say: Σ c_a c_b k(r, c) at
/// (eq_a, eq_b), summed per pair of equations first (a contact between two bodies' nodes has 18
/// equations, not 36 × 36 products), skipping zeros. At most 8 components.
pub fn expanded_triplets(
    terms: &[Terms],
    k: impl Fn(usize, usize) -> f64,
    out: &mut Vec<Triplet<usize, usize, f64>>,
) {
    const MOST: usize = 48;
    let mut eqs = [0u32; MOST];
    let mut count = 0;
    // local[r][i]: the local index of component r's i-th term.
    let mut local = [[0usize; 6]; 8];
    for (r, t) in terms.iter().enumerate() {
        for (i, (eq, _)) in t.pairs().enumerate() {
            local[r][i] = match eqs[..count].iter().position(|&e| e == eq) {
                Some(j) => j,
                None => {
                    eqs[count] = eq;
                    count += 1;
                    count - 1
                }
            };
        }
    }
    // The count × count sums, row by row: on the stack for up to `ON_STACK` equations (a contact
    // of deformable blocks has 6), else on the heap. Zeroing a whole MOST × MOST array (18 KB)
    // for each contact took 13 % of the instructions of an implicit solve of the jointed tunnel.
    const ON_STACK: usize = 8;
    let mut stack = [0.0; ON_STACK * ON_STACK];
    let mut heap = Vec::new();
    let m: &mut [f64] = if count <= ON_STACK {
        &mut stack[..count * count]
    } else {
        heap.resize(count * count, 0.0);
        &mut heap
    };
    for (r, tr) in terms.iter().enumerate() {
        for (c, tc) in terms.iter().enumerate() {
            let v = k(r, c);
            if v == 0.0 {
                continue;
            }
            for (i, (_, cr)) in tr.pairs().enumerate() {
                for (j, (_, cc)) in tc.pairs().enumerate() {
                    m[local[r][i] * count + local[c][j]] += cr * cc * v;
                }
            }
        }
    }
    for a in 0..count {
        for b in 0..count {
            let v = m[a * count + b];
            if eqs[a] >= eqs[b] && v != 0.0 {
                out.push(Triplet::new(eqs[a] as usize, eqs[b] as usize, v));
            }
        }
    }
}

impl Dofs {
    /// The free components of the node vectors `v` into their rows of `x`.
    pub fn gather(&self, v: &[[f64; 2]], x: &mut [f64]) {
        for (eq, v) in self.of_node.iter().zip(v) {
            for d in 0..2 {
                if eq[d] != FIXED {
                    x[eq[d] as usize] = v[d];
                }
            }
        }
    }

    /// The node vectors of `x` into `v` (zero in a fixed component).
    pub fn scatter(&self, x: &[f64], v: &mut [[f64; 2]]) {
        for (eq, v) in self.of_node.iter().zip(v) {
            *v = std::array::from_fn(|d| {
                if eq[d] == FIXED {
                    0.0
                } else {
                    x[eq[d] as usize]
                }
            });
        }
    }
}

/// The lower-triangle entries (row ≥ column) of a dense element matrix `k` (k(r, c) over the
/// element's components) at the equation numbers `eq`, skipping fixed components and zeros.
pub fn lower_triplets(
    eq: &[u32],
    k: impl Fn(usize, usize) -> f64,
    out: &mut Vec<Triplet<usize, usize, f64>>,
) {
    for (r, &row) in eq.iter().enumerate() {
        for (c, &col) in eq.iter().enumerate() {
            if row != FIXED && col != FIXED && row >= col {
                let v = k(r, c);
                if v != 0.0 {
                    out.push(Triplet::new(row as usize, col as usize, v));
                }
            }
        }
    }
}

/// Plane-strain elasticity of bulk modulus K and shear modulus G (Pa), engineering shear strain:
/// σ = D ε with D = [[K + 4G/3, K − 2G/3, 0], [K − 2G/3, K + 4G/3, 0], [0, 0, G]].
pub fn plane_strain(bulk: f64, shear: f64) -> [[f64; 3]; 3] {
    let (a, b) = plane_strain_moduli(bulk, shear);
    [[a, b, 0.0], [b, a, 0.0], [0.0, 0.0, shear]]
}

/// Stiffness of a constant-strain triangle, N/m per m: K_e = A Bᵀ D B over its corner components
/// (u0, v0, u1, v1, u2, v2), with B the strain–displacement matrix of the gradients `g`
/// ([∂N0/∂x, ∂N1/∂x, ∂N2/∂x, ∂N0/∂y, ∂N1/∂y, ∂N2/∂y], 1/m; Zienkiewicz & Taylor vol. 1 §6.2).
/// Its product with a displacement increment is minus the change of the zone's corner forces
/// f_i = −A σ·∇N_i that the explicit zone stage computes.
pub fn cst_stiffness(g: &[f64; 6], area: f64, d: &[[f64; 3]; 3]) -> [[f64; 6]; 6] {
    let mut b = [[0.0; 6]; 3];
    for i in 0..3 {
        let (gx, gy) = (g[i], g[3 + i]);
        b[0][2 * i] = gx;
        b[1][2 * i + 1] = gy;
        b[2][2 * i] = gy;
        b[2][2 * i + 1] = gx;
    }
    let mut db = [[0.0; 6]; 3];
    for r in 0..3 {
        for c in 0..6 {
            db[r][c] = (0..3).map(|k| d[r][k] * b[k][c]).sum();
        }
    }
    let mut k = [[0.0; 6]; 6];
    for r in 0..6 {
        for c in 0..6 {
            k[r][c] = area * (0..3).map(|m| b[m][r] * db[m][c]).sum::<f64>();
        }
    }
    k
}

/// The zones' stiffness over the unknowns (lower triangle, for a Cholesky factorization), from
/// each zone law's elastic moduli: the initial stiffness, exact for elastic zones and the
/// modified-Newton matrix for yielding ones.
pub fn zone_stiffness(
    zones: &Zones,
    laws: &[Box<dyn ZoneLaw>],
    dofs: &Dofs,
) -> Vec<Triplet<usize, usize, f64>> {
    (0..zones.len())
        .into_par_iter()
        .with_min_len(1024)
        .flat_map_iter(|z| {
            let (bulk, shear) = laws[zones.material[z].0 as usize].moduli();
            let k = cst_stiffness(&zones.grad[z], zones.area[z], &plane_strain(bulk, shear));
            let eq: [u32; 6] =
                std::array::from_fn(|i| dofs.of_node[zones.nodes[z][i / 2] as usize][i % 2]);
            let mut out = Vec::with_capacity(21);
            lower_triplets(&eq, |r, c| k[r][c], &mut out);
            out
        })
        .collect()
}

/// The model's stiffness over the unknowns (lower triangle): zones, contacts, bolts and liners.
pub fn stiffness(
    model: &Model,
    dofs: &Dofs,
) -> Result<SparseColMat<usize, f64>, faer::sparse::CreationError> {
    let mut triplets = zone_stiffness(&model.zones, &model.materials.zone, dofs);
    let x = model.nodes.current();
    let terms = |n: u32, d: usize| dofs.terms(&model.bodies, &x, n, d);
    if !model.contacts.is_empty() {
        let (blocks, contacts, laws) = (&model.blocks, &model.contacts, &model.materials.joint);
        triplets.extend(contact_stiffness(blocks, contacts, laws, &x, &terms));
    }
    if !model.bodies.is_empty() {
        triplets.extend(dofs.bodies.stiffness(&model.bodies, &model.materials.zone));
    }
    if !model.supports.is_empty() {
        triplets.extend(support_stiffness(&model.supports, &terms, &dofs.supports));
    }
    if let Some(far) = &model.far_field {
        triplets.extend(far_field_stiffness(far, &terms));
    }
    compressed(dofs.count, &triplets)
}

/// The n × n matrix of `triplets` in compressed columns, duplicates summed in the triplets'
/// order (so the values do not depend on how a sort broke ties): a counting sort by column, then
/// each column's few entries sorted by row. faer's `try_new_from_triplets` sorts them all at
/// once: 45 % of an assembly of `models/jointed_tunnel_mixed.json` in a profile (perf), whose
/// assembly this took from 66 to 53 ms (5 assemblies; the tunnel's from 48 to 31 ms).
pub fn compressed(
    n: usize,
    triplets: &[Triplet<usize, usize, f64>],
) -> Result<SparseColMat<usize, f64>, faer::sparse::CreationError> {
    if let Some(t) = triplets.iter().find(|t| t.row >= n || t.col >= n) {
        return Err(faer::sparse::CreationError::OutOfBounds {
            row: t.row,
            col: t.col,
        });
    }
    let mut start = vec![0usize; n + 1];
    for t in triplets {
        start[t.col + 1] += 1;
    }
    for j in 0..n {
        start[j + 1] += start[j];
    }
    // Each column's entries, in the triplets' order.
    let mut next = start.clone();
    let mut by_column = vec![(0usize, 0.0f64); triplets.len()];
    for t in triplets {
        by_column[next[t.col]] = (t.row, t.val);
        next[t.col] += 1;
    }
    let mut col_ptr = Vec::with_capacity(n + 1);
    col_ptr.push(0);
    // At most one entry a triplet: no growing (and copying) as the columns fill.
    let (mut rows, mut values) = (
        Vec::with_capacity(triplets.len()),
        Vec::with_capacity(triplets.len()),
    );
    for j in 0..n {
        let column = &mut by_column[start[j]..start[j + 1]];
        // Stable: duplicates stay in the triplets' order.
        column.sort_by_key(|&(row, _)| row);
        for &(row, v) in column.iter() {
            if rows.len() > col_ptr[j] && rows.last() == Some(&row) {
                *values.last_mut().expect("a value beside each row") += v;
            } else {
                rows.push(row);
                values.push(v);
            }
        }
        col_ptr.push(rows.len());
    }
    let pattern = faer::sparse::SymbolicSparseColMat::new_checked(n, n, col_ptr, None, rows);
    Ok(SparseColMat::new(pattern, values))
}

/// The contacts' stiffness over the unknowns (lower triangle), at the current positions `x`:
/// a contact of node i against the point ξ of edge (j, k), of length L, normal n and tangent t,
/// with its joint law's stiffnesses kn, ks (Pa/m) in the contact's state (`JointLaw::tangent`), adds
/// K_c = L (w wᵀ) ⊗ (kn n nᵀ + ks t tᵀ), w = (1, −(1 − ξ), −ξ) over the components of (i, j, k):
/// the linearization of the contact stage's forces F = −L(σn n + τ t) on i, −(1 − ξ)F on j and
/// −ξF on k for a contact that neither slips nor opens (the initial stiffness of a joint).
pub fn contact_stiffness(
    blocks: &Blocks,
    contacts: &Contacts,
    laws: &[Box<dyn JointLaw>],
    x: &[[f64; 2]],
    terms: &(dyn Fn(u32, usize) -> Terms + Sync),
) -> Vec<Triplet<usize, usize, f64>> {
    let at = |n: u32| x[n as usize];
    (0..contacts.len())
        .into_par_iter()
        .with_min_len(256)
        .flat_map_iter(|c| {
            let (i, e) = (contacts.node[c], contacts.edge[c]);
            let n = contact_normal(blocks, &at, i, e, contacts.corner[c]);
            let t = [-n[1], n[0]];
            let (kn, ks) = laws[contacts.material[c] as usize].tangent(&contacts.state[c]);
            let (len, xi) = (contacts.length[c], contacts.xi[c]);
            let w = [1.0, -(1.0 - xi), -xi];
            let [j, k] = blocks.edges[e as usize];
            let nodes = [i, j, k];
            let frame = |a: usize, b: usize| kn * n[a] * n[b] + ks * t[a] * t[b];
            let comps: [Terms; 6] = std::array::from_fn(|r| terms(nodes[r / 2], r % 2));
            let mut out = Vec::with_capacity(21);
            expanded_triplets(
                &comps,
                |r, q| len * w[r / 2] * w[q / 2] * frame(r % 2, q % 2),
                &mut out,
            );
            out
        })
        .collect()
}

/// The far field's stiffness over the unknowns (lower triangle): the symmetric part of K,
/// (K + Kᵀ)/2, the collocation's K being not quite symmetric (`far_field`; its asymmetry is the
/// residual's, which the iterations converge on).
pub fn far_field_stiffness(
    far: &FarField,
    terms: &(dyn Fn(u32, usize) -> Terms + Sync),
) -> Vec<Triplet<usize, usize, f64>> {
    let n = far.nodes.len();
    let comps: Vec<Terms> = (0..2 * n).map(|r| terms(far.nodes[r / 2], r % 2)).collect();
    let k = &far.stiffness;
    (0..2 * n)
        .into_par_iter()
        .flat_map_iter(|r| {
            let mut out = Vec::new();
            for c in 0..=r {
                let v = 0.5 * (k.at(r / 2, r % 2, c / 2, c % 2) + k.at(c / 2, c % 2, r / 2, r % 2));
                for (a, ca) in comps[r].pairs() {
                    for (b, cb) in comps[c].pairs() {
                        // The component pair (r, r) adds each product of its terms once, at
                        // its place in the lower triangle; a pair (r, c), c < r, stands for
                        // (c, r) too, whose product lands on the same lower entry, and twice
                        // on a diagonal one (a = b).
                        if c == r && a < b {
                            continue;
                        }
                        let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
                        let weight = if c == r || a != b { 1.0 } else { 2.0 };
                        out.push(Triplet::new(hi as usize, lo as usize, weight * ca * cb * v));
                    }
                }
            }
            out
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::zones::cst_gradients;

    /// The compressed columns hold what faer's own construction holds: the same pattern, and the
    /// same values to round-off (duplicates summed in another order), on random triplets with
    /// many duplicates; an index out of bounds is an error.
    #[test]
    fn compressed_columns_equal_faers() {
        let n = 40;
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 33) as usize
        };
        let triplets: Vec<_> = (0..2000)
            .map(|_| {
                let (a, b) = (next() % n, next() % n);
                let v = (next() % 1000) as f64 / 7.0 - 70.0;
                Triplet::new(a.max(b), a.min(b), v)
            })
            .collect();
        let ours = compressed(n, &triplets).unwrap();
        let faers = SparseColMat::try_new_from_triplets(n, n, &triplets).unwrap();
        assert_eq!(ours.symbolic().col_ptr(), faers.symbolic().col_ptr());
        assert_eq!(ours.symbolic().row_idx(), faers.symbolic().row_idx());
        for (a, b) in ours.val().iter().zip(faers.val()) {
            assert!((a - b).abs() <= 1e-12 * b.abs().max(1.0), "{a} {b}");
        }
        let outside = [Triplet::new(n, 0, 1.0)];
        assert!(compressed(n, &outside).is_err());
    }

    /// A rigid-body motion strains nothing: the element stiffness has three zero-energy modes
    /// (two translations, one rotation), and it is symmetric.
    #[test]
    fn rigid_motions_cost_no_energy() {
        let p = [[0.0, 0.0], [1.3, 0.2], [0.4, 0.9]];
        let (g, area) = cst_gradients(p);
        let k = cst_stiffness(&g, area, &plane_strain(5e9, 3e9));
        let c = [0.45, 0.35];
        let modes = [
            [1.0, 0.0, 1.0, 0.0, 1.0, 0.0],
            [0.0, 1.0, 0.0, 1.0, 0.0, 1.0],
            std::array::from_fn(|i| {
                let q = p[i / 2];
                if i % 2 == 0 {
                    -(q[1] - c[1])
                } else {
                    q[0] - c[0]
                }
            }),
        ];
        for m in modes {
            for row in &k {
                let f: f64 = row.iter().zip(&m).map(|(a, b)| a * b).sum();
                assert!(f.abs() < 1e-6 * 5e9, "{f}");
            }
        }
        for (r, row) in k.iter().enumerate() {
            for (c, &v) in row.iter().enumerate() {
                assert!((v - k[c][r]).abs() <= 1e-9 * row[r].abs());
            }
        }
    }
}
