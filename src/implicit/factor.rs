//! The stiffness's LLᵀ factorization through faer's sparse Cholesky, kept with its symbolic
//! analysis and the scratch its solves need, so that an iteration's solve allocates nothing and
//! the factor's size can be reported.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::SparseColMatRef;
use faer::sparse::linalg::cholesky::{LltRef, SymbolicCholesky, factorize_symbolic_cholesky};
use faer::{Conj, Side};

/// Why a factorization failed: not enough memory for it (the message says how much), or the
/// numeric factorization broke down (a zero or negative pivot).
#[derive(Debug)]
pub enum FactorError {
    Memory(String),
    Numeric(String),
}

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
    pub fn new(k: SparseColMatRef<'_, usize, f64>) -> Result<Factor, FactorError> {
        let par = faer::get_global_parallelism();
        let symbolic = factorize_symbolic_cholesky(
            k.symbolic(),
            Side::Lower,
            Default::default(),
            Default::default(),
        )
        .map_err(|e| FactorError::Numeric(format!("{e:?}")))?;
        let scratch_req = symbolic.factorize_numeric_llt_scratch::<f64>(par, Default::default());
        let bytes = symbolic.len_val() * std::mem::size_of::<f64>() + scratch_req.size_bytes();
        fits(bytes, available_memory())?;
        let mut values = vec![0.0; symbolic.len_val()];
        let mut work = MemBuffer::try_new(scratch_req)
            .map_err(|e| FactorError::Memory(format!("implicit: factorization scratch: {e:?}")))?;
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
            .map_err(|e| FactorError::Numeric(format!("{e:?}")))?;
        let scratch = MemBuffer::try_new(symbolic.solve_in_place_scratch::<f64>(1, par))
            .map_err(|e| FactorError::Memory(format!("implicit: solve scratch: {e:?}")))?;
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

/// An error naming both sizes when a factorization needing `bytes` would not fit in the `free`
/// memory (bytes; `None`: unknown, taken to fit), before anything is allocated.
fn fits(bytes: usize, free: Option<usize>) -> Result<(), FactorError> {
    match free {
        Some(free) if bytes > free => Err(FactorError::Memory(format!(
            "implicit: the factor needs {:.2} GB, more than the {:.2} GB of memory available; \
             coarsen the zoning or solve explicitly",
            bytes as f64 / 1e9,
            free as f64 / 1e9
        ))),
        _ => Ok(()),
    }
}

/// Memory the system can still give, bytes (Linux's `MemAvailable`); `None` where it cannot be
/// read, and the factorization then goes ahead unchecked.
fn available_memory() -> Option<usize> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: usize = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A factor larger than the memory left is refused with both sizes named; an unknown amount
    /// of memory is taken to fit; this machine reports what it has.
    #[test]
    fn a_factor_that_does_not_fit_is_refused_before_it_is_allocated() {
        let Err(FactorError::Memory(m)) = fits(3_000_000_000, Some(1_000_000_000)) else {
            panic!("a 3 GB factor fitted in 1 GB");
        };
        assert!(m.contains("3.00 GB") && m.contains("1.00 GB"), "{m}");
        assert!(fits(3_000_000_000, None).is_ok());
        assert!(fits(1_000, Some(1_000_000)).is_ok());
        if cfg!(target_os = "linux") {
            assert!(available_memory().is_some_and(|b| b > 0));
        }
    }
}
