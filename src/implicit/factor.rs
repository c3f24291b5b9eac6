//! The stiffness's LLᵀ factorization through faer's sparse Cholesky, kept with its symbolic
//! analysis and the scratch its solves need, so that an iteration's solve allocates nothing and
//! the factor's size can be reported.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::SparseColMatRef;
use faer::sparse::linalg::cholesky::{LltRef, SymbolicCholesky, factorize_symbolic_cholesky};
use faer::{Conj, Side};

pub struct Factor {
    symbolic: SymbolicCholesky<usize>,
    /// The values of L.
    values: Vec<f64>,
    /// Scratch of one solve with one right-hand side.
    scratch: MemBuffer,
}

impl Factor {
    /// Factorize `k` (its lower triangle): the symbolic analysis (a fill-reducing ordering and
    /// the supernodes), then the numeric LLᵀ; an error in words when `k` is not positive definite.
    pub fn new(k: SparseColMatRef<'_, usize, f64>) -> Result<Factor, String> {
        let par = faer::get_global_parallelism();
        let symbolic = factorize_symbolic_cholesky(
            k.symbolic(),
            Side::Lower,
            Default::default(),
            Default::default(),
        )
        .map_err(|e| format!("{e:?}"))?;
        let mut values = vec![0.0; symbolic.len_val()];
        let mut work = MemBuffer::try_new(
            symbolic.factorize_numeric_llt_scratch::<f64>(par, Default::default()),
        )
        .map_err(|e| format!("{e:?}"))?;
        symbolic
            .factorize_numeric_llt::<f64>(
                &mut values,
                k,
                Side::Lower,
                Default::default(),
                par,
                MemStack::new(&mut work),
                Default::default(),
            )
            .map_err(|e| format!("{e:?}"))?;
        let scratch = MemBuffer::try_new(symbolic.solve_in_place_scratch::<f64>(1, par))
            .map_err(|e| format!("{e:?}"))?;
        Ok(Factor {
            symbolic,
            values,
            scratch,
        })
    }

    /// Non-zeros of L (what the factor holds, 8 bytes each with its row indices beside).
    pub fn nonzeros(&self) -> usize {
        self.values.len()
    }

    /// Solve K x = b in place (`rhs`: b in, x out).
    pub fn solve_in_place(&mut self, rhs: &mut [f64]) {
        let par = faer::get_global_parallelism();
        LltRef::new(&self.symbolic, &self.values).solve_in_place_with_conj(
            Conj::No,
            faer::ColMut::from_slice_mut(rhs).as_mat_mut(),
            par,
            MemStack::new(&mut self.scratch),
        );
    }
}
