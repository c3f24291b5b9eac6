//! The edges of a large block in a uniform grid, so the narrow phase asks only the edges a node
//! can touch: `node_to_edge` walked every edge of the other block for every nearby node, which
//! made detection quadratic in a block's edge count (a block beside thousands of small ones).

use crate::model::blocks::Blocks;

/// Blocks with fewer edges than this are searched edge by edge.
pub const MIN_EDGES: usize = 48;

/// One block's edges, each entered in every cell its box grown by its reach covers.
pub struct EdgeGrid {
    lo: [f64; 2],
    cell: f64,
    nx: usize,
    ny: usize,
    /// Edge ids per cell (row-major), ascending.
    cells: Vec<Vec<u32>>,
}

impl EdgeGrid {
    /// The grid of block `b`'s edges at positions `x` (m). An edge of length L reaches
    /// max(`near`, L/2) (m) beyond its box: a node centre farther from it cannot touch it (the
    /// narrow phase needs a gap below the tolerance, `near` = tolerance + the largest rounding
    /// radius, and a depth behind it under L/2).
    pub fn new(blocks: &Blocks, x: &[[f64; 2]], b: usize, near: f64) -> EdgeGrid {
        let range = blocks.edge_range(b);
        let boxes: Vec<([f64; 2], [f64; 2])> = range
            .clone()
            .map(|e| {
                let [j, k] = blocks.edges[e];
                let (p, q) = (x[j as usize], x[k as usize]);
                let reach = near.max(0.5 * (q[0] - p[0]).hypot(q[1] - p[1]));
                (
                    [p[0].min(q[0]) - reach, p[1].min(q[1]) - reach],
                    [p[0].max(q[0]) + reach, p[1].max(q[1]) + reach],
                )
            })
            .collect();
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        let mut size = 0.0;
        for (blo, bhi) in &boxes {
            for d in 0..2 {
                lo[d] = lo[d].min(blo[d]);
                hi[d] = hi[d].max(bhi[d]);
            }
            size += (bhi[0] - blo[0]).max(bhi[1] - blo[1]);
        }
        let count = boxes.len().max(1);
        // Cells of the mean grown box, at most about 4 per edge over the block's extent.
        let span = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(f64::MIN_POSITIVE);
        let cell = (size / count as f64).max(span / (2.0 * (count as f64).sqrt()).max(1.0));
        let n = |d: usize| (((hi[d] - lo[d]) / cell).floor() as usize + 1).max(1);
        let (nx, ny) = (n(0), n(1));
        let mut grid = EdgeGrid {
            lo,
            cell,
            nx,
            ny,
            cells: vec![Vec::new(); nx * ny],
        };
        for (e, (blo, bhi)) in range.zip(&boxes) {
            let (x0, y0) = grid.index(*blo);
            let (x1, y1) = grid.index(*bhi);
            for cy in y0..=y1 {
                for cx in x0..=x1 {
                    grid.cells[cy * nx + cx].push(e as u32);
                }
            }
        }
        grid
    }

    fn index(&self, p: [f64; 2]) -> (usize, usize) {
        let i = |d: usize, n: usize| {
            (((p[d] - self.lo[d]) / self.cell).floor().max(0.0) as usize).min(n - 1)
        };
        (i(0, self.nx), i(1, self.ny))
    }

    /// The edges, ascending, that a node centred at `c` (m) may touch; empty outside the grid.
    pub fn near(&self, c: [f64; 2]) -> &[u32] {
        let inside = (0..2).all(|d| {
            c[d] >= self.lo[d] && c[d] <= self.lo[d] + self.cell * [self.nx, self.ny][d] as f64
        });
        if !inside {
            return &[];
        }
        let (cx, cy) = self.index(c);
        &self.cells[cy * self.nx + cx]
    }
}
