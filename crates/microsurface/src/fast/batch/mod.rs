//! Slices: the fast paths over `&[f64]` inputs into `&mut [f64]` outputs, written so that the
//! compiler vectorises them (no branches in the main loop, an exponential that is plain
//! arithmetic on the bits, table lookups as gathers), and with the `rayon` feature, the same
//! over all cores (`par_*`).
//!
//! Every function takes `u` and `alpha` of equal length and `out` at least as long (it panics
//! otherwise, as slice indexing does); element i of `out` is the scalar fast path at
//! `(u[i], alpha[i])` to within the scalar path's stated accuracy (tests/fast.rs compares them).
//! Lanes outside the vectorised formula's range (below-horizon u, Λ's asymptotic ends) are
//! redone by the scalar path after each block of 256, so every u ∈ [0, 1] (and ±0, 1 + 2ε, NaN)
//! gets the scalar path's answer to within its accuracy (tests/fuzz.rs: 1e-12 relative).
//!
//! Each slice function is compiled for the build's target, for AVX2 + FMA and for AVX-512
//! (F, DQ, VL), and runs the widest the CPU has ([`simd`], [`detected_simd`]; [`cap_simd`]
//! caps it on one thread, to compare or test the paths). All of them return the same bits.
//! Choosing is the library's only `unsafe`: calling a `#[target_feature]` function after
//! `is_x86_feature_detected!` has confirmed the features.
//!
//! Throughput and the scalar-loop comparison: BENCHMARKS.md. Where the scalar path is a
//! closed form (GGX D, Λ, G1), a caller's loop over zipped iterators is vectorised by the
//! compiler as well (SSE2), and the slice function gains little or nothing over it (GGX Λ and
//! G1 are bound by the divider, GGX D by memory traffic). The slice functions pay off where
//! the scalar path has branches, table lookups or libm calls, which keep the compiler from
//! vectorising a loop (Beckmann D, Double GGX, Exponential, GTR).

// `!(x > 0)` is the NaN-aware test (false for NaN) on a generic `Real`, on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::arith;
use super::tables::{DGGX, DGGX_K0, DGGX_K1, DGGX_M};
use super::{beckmann, double_ggx, exponential, fit, ggx, Real};
use std::f64::consts::PI;

/// Elements per block of [`chunks`]: a multiple of every SIMD width (2 to 8 doubles), and
/// 2 KiB per slice, so that a block's fix-up pass re-reads it from L1.
const BLOCK: usize = 256;

/// The instruction sets the slice functions are compiled for, narrowest first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Simd {
    /// The build's target (x86-64: SSE2, two doubles per vector).
    Generic,
    /// AVX2 and FMA (four doubles per vector, hardware gathers).
    Avx2,
    /// AVX-512 F, DQ and VL (eight doubles per vector).
    Avx512,
}

/// The widest [`Simd`] this CPU runs; the slice functions use it unless capped by
/// [`cap_simd`].
pub fn detected_simd() -> Simd {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::is_x86_feature_detected as has;
        if has!("avx512f") && has!("avx512dq") && has!("avx512vl") && has!("avx2") && has!("fma") {
            return Simd::Avx512;
        }
        if has!("avx2") && has!("fma") {
            return Simd::Avx2;
        }
    }
    Simd::Generic
}

thread_local! {
    static CAP: std::cell::Cell<Option<Simd>> = const { std::cell::Cell::new(None) };
}

/// Caps the instruction set the slice functions use on the calling thread (`None`: no cap),
/// to test or compare the paths. The `par` forms run on rayon's threads, which the cap does
/// not reach.
pub fn cap_simd(cap: Option<Simd>) {
    CAP.with(|c| c.set(cap));
}

/// The instruction set a slice function called on this thread uses.
pub fn simd() -> Simd {
    let d = detected_simd();
    CAP.with(|c| c.get()).map_or(d, |cap| cap.min(d))
}

/// Defines a public slice function whose body is compiled three times: for the default
/// target, with AVX2 + FMA, and with AVX-512 (F, DQ, VL), and runs the widest the CPU has
/// ([`simd`]; `is_x86_feature_detected!` caches its answer, so choosing costs a few loads per
/// call, not per element). The body is the same source in each; only the vector width the
/// compiler may use changes, and Rust never contracts a·b + c into an FMA by itself, so every
/// path returns the same bits (tests/fast.rs compares them).
macro_rules! dispatched {
    ($(#[$attr:meta])* pub fn $name:ident($($arg:ident: $ty:ty),* $(,)?) $body:block) => {
        $(#[$attr])*
        pub fn $name($($arg: $ty),*) {
            #[inline(always)]
            fn generic($($arg: $ty),*) $body
            #[cfg(target_arch = "x86_64")]
            {
                #[target_feature(enable = "avx512f,avx512dq,avx512vl,avx2,fma")]
                fn avx512($($arg: $ty),*) {
                    generic($($arg),*)
                }
                #[target_feature(enable = "avx2,fma")]
                fn avx2($($arg: $ty),*) {
                    generic($($arg),*)
                }
                match simd() {
                    // SAFETY: `simd` returns Avx512 only when the CPU has every feature
                    // `avx512` is compiled for (`detected_simd` checks each).
                    #[allow(unsafe_code)]
                    Simd::Avx512 => return unsafe { avx512($($arg),*) },
                    // SAFETY: `simd` returns Avx2 only when the CPU has AVX2 and FMA.
                    #[allow(unsafe_code)]
                    Simd::Avx2 => return unsafe { avx2($($arg),*) },
                    Simd::Generic => {}
                }
            }
            generic($($arg),*)
        }
    };
}

// (Declared after `dispatched!`, which its slice functions use.)
mod wavefront;

pub use wavefront::{
    beckmann_sample_visible_f32, beckmann_sample_visible_f64, ggx_conductor_eval_f32,
    ggx_conductor_eval_f64, ggx_conductor_sample_f32, ggx_conductor_sample_f64,
    ggx_sample_visible_f32, ggx_sample_visible_f64, GgxConductor, Vectors, VectorsMut,
};

/// Runs `kernel` over blocks of [`BLOCK`] elements (the last one shorter); in each, `kernel`'s
/// flag reports the lanes that need the scalar path, which `scalar` then supplies.
///
/// The block's loop is a plain loop over contiguous elements, so the compiler vectorises it
/// with contiguous loads and stores in every build. (Chunks of 8 with the lane loop unrolled
/// had made the AVX-512 builds vectorise across chunks instead: 16 `vgatherqpd` and 8
/// `vscatterqpd` per iteration for GGX D, several times slower than the AVX2 build on AMD
/// Zen 5: BENCHMARKS.md.
/// `scripts/check-simd-codegen.sh`, run by CI, reads this crate's assembly for gathers and
/// scatters on contiguous data; the bench's per-instruction-set table checks that the
/// dispatched build is never slower than a narrower one.)
#[inline(always)]
fn chunks<F: Copy>(
    u: &[F],
    alpha: &[F],
    out: &mut [F],
    kernel: impl Fn(F, F) -> (F, bool),
    scalar: impl Fn(F, F) -> F,
) {
    let n = u.len();
    assert!(alpha.len() == n && out.len() >= n, "slice lengths differ");
    for ((uc, ac), oc) in u
        .chunks(BLOCK)
        .zip(alpha.chunks(BLOCK))
        .zip(out[..n].chunks_mut(BLOCK))
    {
        let mut any = false;
        for ((o, &uu), &aa) in oc.iter_mut().zip(uc).zip(ac) {
            let (v, bad) = kernel(uu, aa);
            *o = v;
            any |= bad;
        }
        if any {
            for ((o, &uu), &aa) in oc.iter_mut().zip(uc).zip(ac) {
                if kernel(uu, aa).1 {
                    *o = scalar(uu, aa);
                }
            }
        }
    }
}

/// GGX D over slices of F (the f64 and f32 entry points below share it).
#[inline(always)]
fn ggx_d_of<F: Real>(u: &[F], alpha: &[F], out: &mut [F]) {
    chunks(
        u,
        alpha,
        out,
        |u, a| {
            let a2 = a * a;
            let t = (F::ONE - u) * (F::ONE + u) + u * u * a2;
            let d = a2 / (F::PI * t * t);
            // u > 1 (1 + 2ε): the scalar path, which evaluates at 1.
            (if u <= F::ZERO { F::ZERO } else { d }, u > F::ONE)
        },
        ggx::d,
    );
}

/// GGX Λ over slices of F.
#[inline(always)]
fn ggx_lambda_of<F: Real>(u: &[F], alpha: &[F], out: &mut [F]) {
    chunks(
        u,
        alpha,
        out,
        // Lanes with u below ggx::lambda_tiny_below or above 1 (and NaN): the scalar path.
        |u, a| {
            (
                ggx::lambda_kernel(u, a),
                !(u >= ggx::lambda_tiny_below() && u <= F::ONE),
            )
        },
        ggx::lambda,
    );
}

/// GGX G1 over slices of F.
#[inline(always)]
fn ggx_g1_of<F: Real>(u: &[F], alpha: &[F], out: &mut [F]) {
    // Lanes with u outside [0, 1] (and NaN): the scalar path.
    chunks(
        u,
        alpha,
        out,
        |u, a| (ggx::g1_kernel(u, a), !(u >= F::ZERO && u <= F::ONE)),
        ggx::g1,
    );
}

dispatched! {
/// GGX D.
pub fn ggx_d(u: &[f64], alpha: &[f64], out: &mut [f64]) {
    ggx_d_of(u, alpha, out);
}
}

dispatched! {
/// GGX Λ.
pub fn ggx_lambda(u: &[f64], alpha: &[f64], out: &mut [f64]) {
    ggx_lambda_of(u, alpha, out);
}
}

dispatched! {
/// GGX G1.
pub fn ggx_g1(u: &[f64], alpha: &[f64], out: &mut [f64]) {
    ggx_g1_of(u, alpha, out);
}
}

dispatched! {
/// GGX D in f32: the f32 scalar path's formula in f32 arithmetic (its accuracy,
/// [`crate::fast`]), twice the lanes of [`ggx_d`].
pub fn ggx_d_f32(u: &[f32], alpha: &[f32], out: &mut [f32]) {
    ggx_d_of(u, alpha, out);
}
}

dispatched! {
/// GGX Λ in f32 (as [`ggx_d_f32`]).
pub fn ggx_lambda_f32(u: &[f32], alpha: &[f32], out: &mut [f32]) {
    ggx_lambda_of(u, alpha, out);
}
}

dispatched! {
/// GGX G1 in f32 (as [`ggx_d_f32`]).
pub fn ggx_g1_f32(u: &[f32], alpha: &[f32], out: &mut [f32]) {
    ggx_g1_of(u, alpha, out);
}
}

dispatched! {
/// Beckmann D (0 where the exact D is below about 1e-300, as the scalar path).
pub fn beckmann_d(u: &[f64], alpha: &[f64], out: &mut [f64]) {
    chunks(
        u,
        alpha,
        out,
        |u, a| {
            let a2 = a * a;
            let u2 = u * u;
            let x = (1.0 - u) * (1.0 + u) / (u2 * a2);
            let d = arith::exp(-x) / (PI * a2 * u2 * u2);
            // x > 708: e^{−x} leaves arith::exp's range; u ≤ 0, u > 1 (or NaN): the scalar's
            // answer.
            (d, !(u > 0.0 && u <= 1.0 && x <= 708.0))
        },
        beckmann::d,
    );
}
}

dispatched! {
/// Double GGX Λ.
pub fn double_ggx_lambda(u: &[f64], alpha: &[f64], out: &mut [f64]) {
    let lo = 2f64.powi(DGGX_K0);
    let hi = 2f64.powi(DGGX_K1);
    chunks(
        u,
        alpha,
        out,
        |u, a| {
            let x = 0.5 * a * a * ((1.0 - u) * (1.0 + u)) / (u * u);
            (fit::eval_estrin(&DGGX, DGGX_K0, DGGX_M, x), !(x >= lo && x < hi))
        },
        double_ggx::lambda,
    );
}
}

dispatched! {
/// Exponential Λ (the q tables, one row picked per lane; the rest of z (z < 2^−12 or
/// z ≥ 64) by the scalar path).
pub fn exponential_lambda(u: &[f64], alpha: &[f64], out: &mut [f64]) {
    chunks(
        u,
        alpha,
        out,
        |u, a| {
            let (v, inside) = exponential::lambda_q_select(exponential::q_of(u, a));
            (v, !inside)
        },
        exponential::lambda,
    );
}
}

dispatched! {
/// Λ of a prepared GTR material for every u (one α, γ).
pub fn gtr_lambda(g: &super::gtr::FittedGtr, u: &[f64], out: &mut [f64]) {
    // One loop per kind of table, so that neither tests the kind per element.
    if g.is_direct() {
        gtr_chunks::<true>(g, u, out);
    } else {
        gtr_chunks::<false>(g, u, out);
    }
}
}

/// [`gtr_lambda`] for a table of Λ (`DIRECT`) or of ln Λ, in blocks as [`chunks`].
#[inline(always)]
fn gtr_chunks<const DIRECT: bool>(g: &super::gtr::FittedGtr, u: &[f64], out: &mut [f64]) {
    // Never fails; it tells the compiler that the clamped row is in bounds, so the loop
    // below has no panic branch and vectorises.
    assert!(g.rows() > 0);
    let n = u.len();
    assert!(out.len() >= n, "slice lengths differ");
    let kernel = |u: f64| {
        let normal_side = u >= 0.5;
        let (p, inside) = g.table_at_lanes(normal_side, if normal_side { 1.0 - u } else { u });
        if DIRECT {
            (p, !inside)
        } else {
            // Past arith::exp's range (Λ < e^{−708}) the scalar path answers.
            (arith::exp(p), !inside || p.is_nan() || p <= -708.0)
        }
    };
    for (uc, oc) in u.chunks(BLOCK).zip(out[..n].chunks_mut(BLOCK)) {
        let mut any = false;
        for (o, &uu) in oc.iter_mut().zip(uc) {
            let (v, bad) = kernel(uu);
            *o = v;
            any |= bad;
        }
        if any {
            for (o, &uu) in oc.iter_mut().zip(uc) {
                if kernel(uu).1 {
                    *o = g.lambda(uu);
                }
            }
        }
    }
}

/// The `par_*` forms: the same functions on every core (rayon), in pieces of 16 384.
///
/// They run on the pool they are called from (the global pool, or the one a caller
/// `install`s). Where the kernel packs runnable threads onto fewer vCPUs (the benchmark
/// machine's does: `sched_vcpu_pack` on its command line), rayon's workers can share one
/// vCPU for whole passes; a pool whose workers are pinned one per CPU (a `start_handler` that
/// sets the thread's affinity) scales there as on a dedicated machine (BENCHMARKS.md).
#[cfg(feature = "rayon")]
pub mod par {
    use rayon::prelude::*;

    /// Elements per rayon task: large enough to hide the scheduling (microseconds), small enough to
    /// balance two to many cores on 10⁶ elements.
    const PIECE: usize = 1 << 14;

    /// Applies a slice function to matching pieces of (u, alpha, out) in parallel.
    pub fn map(
        u: &[f64],
        alpha: &[f64],
        out: &mut [f64],
        f: impl Fn(&[f64], &[f64], &mut [f64]) + Sync,
    ) {
        assert!(
            alpha.len() == u.len() && out.len() >= u.len(),
            "slice lengths differ"
        );
        out[..u.len()]
            .par_chunks_mut(PIECE)
            .zip(u.par_chunks(PIECE).zip(alpha.par_chunks(PIECE)))
            .for_each(|(o, (u, a))| f(u, a, o));
    }

    /// GTR Λ of one material over u, in parallel.
    pub fn gtr_lambda(g: &crate::fast::gtr::FittedGtr, u: &[f64], out: &mut [f64]) {
        assert!(out.len() >= u.len(), "slice lengths differ");
        out[..u.len()]
            .par_chunks_mut(PIECE)
            .zip(u.par_chunks(PIECE))
            .for_each(|(o, u)| super::gtr_lambda(g, u, o));
    }
}
