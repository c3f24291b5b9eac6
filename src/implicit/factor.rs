//! The stiffness's LLᵀ factorization through faer's sparse Cholesky, kept with its symbolic
//! analysis and the scratch its solves need, so that an iteration's solve allocates nothing and
//! the factor's size can be reported.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::SparseColMatRef;
use faer::sparse::linalg::cholesky::{LltRef, SymbolicCholesky, factorize_symbolic_cholesky};
use faer::{Conj, Par, Side};

use crate::vector_state::clear_upper_vector_state;

/// The factorizations and solves run on the calling thread. Measured on this project's 2-core
/// machines, faer's supernodal factorization on the two rayon threads took twice as long as on
/// one (Kirsch's hole: 8 676 unknowns 13.7–16.6 ms against 5.0–6.1 ms a numeric factorization;
/// 23 374 unknowns 30–57 against 17–19 ms; 51 716 unknowns 109–137 against 60–61 ms; the
/// solves alike or a little faster), and on one thread its rounding cannot depend on the number
/// of threads.
const PAR: Par = Par::Seq;

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
    /// The factorized matrix's pattern (its lower triangle's column pointers and row indices),
    /// which a later matrix must have to reuse `symbolic`.
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
}

impl Factor {
    /// Factorize `k` (its lower triangle): the symbolic analysis (a fill-reducing ordering and
    /// the supernodes), then the numeric LLᵀ; an error in words when `k` is not positive definite.
    /// The analysis of `last` (an earlier factorization) is reused when `k` has its pattern;
    /// the second value says whether it was.
    pub fn new(
        k: SparseColMatRef<'_, usize, f64>,
        last: Option<Factor>,
    ) -> Result<(Factor, bool), FactorError> {
        let par = PAR;
        let pattern = k.symbolic();
        let kept = last.filter(|f| {
            f.col_ptr == pattern.col_ptr()
                && pattern.col_nnz().is_none()
                && f.row_idx == pattern.row_idx()
        });
        let reused = kept.is_some();
        let symbolic = match kept {
            Some(f) => f.symbolic,
            None => factorize_symbolic_cholesky(
                pattern,
                Side::Lower,
                Default::default(),
                Default::default(),
            )
            .map_err(|e| FactorError::Numeric(format!("{e:?}")))?,
        };
        let scratch_req = symbolic.factorize_numeric_llt_scratch::<f64>(par, Default::default());
        let bytes = symbolic.len_val() * std::mem::size_of::<f64>() + scratch_req.size_bytes();
        fits(bytes, available_memory())?;
        let mut values = vec![0.0; symbolic.len_val()];
        let mut work = MemBuffer::try_new(scratch_req)
            .map_err(|e| FactorError::Memory(format!("implicit: factorization scratch: {e:?}")))?;
        let factorized = symbolic
            .factorize_numeric_llt::<f64>(
                &mut values,
                k,
                Side::Lower,
                Default::default(),
                par,
                MemStack::new(&mut work),
                Default::default(),
            )
            .map_err(|e| FactorError::Numeric(format!("{e:?}")));
        clear_upper_vector_state();
        factorized?;
        let scratch = MemBuffer::try_new(symbolic.solve_in_place_scratch::<f64>(1, par))
            .map_err(|e| FactorError::Memory(format!("implicit: solve scratch: {e:?}")))?;
        Ok((
            Factor {
                symbolic,
                values,
                scratch,
                col_ptr: pattern.col_ptr().to_vec(),
                row_idx: pattern.row_idx().to_vec(),
            },
            reused,
        ))
    }

    /// Non-zeros of L (what the factor holds, 8 bytes each with its row indices beside).
    pub fn nonzeros(&self) -> usize {
        self.values.len()
    }

    /// Solve K x = b in place (`rhs`: b in, x out).
    pub fn solve_in_place(&mut self, rhs: &mut [f64]) {
        let par = PAR;
        LltRef::new(&self.symbolic, &self.values).solve_in_place_with_conj(
            Conj::No,
            faer::ColMut::from_slice_mut(rhs).as_mat_mut(),
            par,
            MemStack::new(&mut self.scratch),
        );
        clear_upper_vector_state();
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

    /// The 5-point Laplacian of an n × n grid plus the identity (symmetric positive definite),
    /// its lower triangle: a matrix whose factor has dense supernodes, as a zoned model's has.
    fn grid(n: usize) -> faer::sparse::SparseColMat<usize, f64> {
        use faer::sparse::Triplet;
        let id = |i: usize, j: usize| i * n + j;
        let mut t = Vec::new();
        for i in 0..n {
            for j in 0..n {
                t.push(Triplet::new(id(i, j), id(i, j), 5.0));
                if i + 1 < n {
                    t.push(Triplet::new(id(i + 1, j), id(i, j), -1.0));
                }
                if j + 1 < n {
                    t.push(Triplet::new(id(i, j + 1), id(i, j), -1.0));
                }
            }
        }
        faer::sparse::SparseColMat::try_new_from_triplets(n * n, n * n, &t).unwrap()
    }

    /// After a factorization and after a solve, no upper half of a vector register is left in
    /// use on this thread nor on a rayon worker (XGETBV with ECX = 1, XINUSE: bit 2 the upper halves
    /// of YMM0–15, bit 6 of ZMM0–15), so the SSE code that follows pays no AVX–SSE transition.
    /// Skipped where the CPU cannot report it.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn a_factorization_and_a_solve_leave_the_vector_registers_clean() {
        use std::arch::x86_64::{__cpuid_count, _xgetbv};
        const UPPER: u64 = 1 << 2 | 1 << 6;
        let xinuse =
            std::arch::is_x86_feature_detected!("xsave") && __cpuid_count(0xD, 1).eax & 4 != 0;
        if !xinuse {
            eprintln!("skipped: this CPU does not report the registers in use (XINUSE)");
            return;
        }
        fn in_use() -> u64 {
            // SAFETY: XSAVE and XGETBV with ECX = 1 are supported (checked above).
            unsafe { _xgetbv(1) }
        }
        // A pool of its own: other tests' factorizations on the global pool's workers cannot
        // leave them dirty in between.
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap();
        pool.install(|| {
            let k = grid(150);
            let (mut f, _) = Factor::new(k.as_ref(), None).unwrap();
            assert_eq!(in_use() & UPPER, 0);
            let workers: Vec<u64> = rayon::broadcast(|_| in_use() & UPPER);
            assert!(workers.iter().all(|&u| u == 0), "{workers:?}");
            let mut x = vec![1.0; 150 * 150];
            f.solve_in_place(&mut x);
            assert_eq!(in_use() & UPPER, 0);
            assert!(x.iter().all(|v| v.is_finite() && *v > 0.0));
        });
    }

    /// The symbolic analysis of an earlier factorization is reused for a matrix of its pattern
    /// (other values: the solve is the new matrix's) and not for another pattern.
    #[test]
    fn an_analysis_is_reused_for_the_same_pattern_only() {
        let (n, b) = (30, vec![1.0; 900]);
        let solve = |f: &mut Factor| {
            let mut x = b.clone();
            f.solve_in_place(&mut x);
            x
        };
        let (mut first, reused) = Factor::new(grid(n).as_ref(), None).unwrap();
        assert!(!reused);
        let x1 = solve(&mut first);
        // The same pattern, every value doubled: reused, and the solution halves.
        let mut k2 = grid(n);
        k2.val_mut().iter_mut().for_each(|v| *v *= 2.0);
        let (mut second, reused) = Factor::new(k2.as_ref(), Some(first)).unwrap();
        assert!(reused);
        let x2 = solve(&mut second);
        assert!(
            x1.iter()
                .zip(&x2)
                .all(|(a, b)| (a - 2.0 * b).abs() < 1e-12 * a.abs())
        );
        // Another pattern (a larger grid): analysed anew.
        let (_, reused) = Factor::new(grid(n + 1).as_ref(), Some(second)).unwrap();
        assert!(!reused);
    }
}
