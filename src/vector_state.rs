//! The vector registers' state after faer's kernels (`implicit::factor`, `far_field`).

/// Clear the upper halves of this thread's vector registers. faer's kernels (chosen at run
/// time, AVX-512 on this project's machines) leave those halves in use after a numeric
/// factorization with dense supernodes (`implicit::factor`'s test); the SSE code compiled for the baseline
/// x86-64 (the zone and joint laws, libm's `sin` and `tan`) then pays the AVX–SSE transition on
/// every instruction: measured, explicit cycling of `models/tunnel.json` after an implicit
/// Mohr–Coulomb solve in the same process took 6.5 s instead of 1.35 s, and the implicit
/// iterations' own force stages paid it too (the weak rock's Salençon hole: 0.61 s, 0.21 s
/// cleared). `vzeroupper` is the remedy of Intel's optimization manual ("Mixing AVX code with
/// SSE code"). faer runs on the calling thread only (`implicit::factor`, `far_field`); a solve
/// leaves it clean (`implicit::factor`'s test), and is cleared all the same, at one instruction a
/// solve.
pub(crate) fn clear_upper_vector_state() {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx") {
        // SAFETY: `vzeroupper` only zeroes the upper halves of the vector registers, which no
        // live value on this thread holds across this call; the CPU has AVX (checked).
        unsafe { std::arch::x86_64::_mm256_zeroupper() }
    }
}
