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
//! G1: none, both bound by the divider; GGX D: 1.6×, bound by memory traffic). The slice
//! functions pay off where the scalar path has branches, table lookups or libm calls, which
//! keep the compiler from vectorising a loop (Beckmann D, Double GGX, Exponential, GTR: 1.9×
//! to 2.2× the iterator loop at 10⁶ elements).

// `!(x > 0)` is the NaN-aware test (false for NaN) on a generic `Real`, on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::arith;
use super::tables::{DGGX, DGGX_K0, DGGX_K1, DGGX_M};
use super::{beckmann, double_ggx, exponential, fit, ggx};
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

/// Runs `kernel` over blocks of [`BLOCK`] elements (the last one shorter); in each, `kernel`'s
/// flag reports the lanes that need the scalar path, which `scalar` then supplies.
///
/// The block's loop is a plain loop over contiguous elements, so the compiler vectorises it
/// with contiguous loads and stores in every build. (Chunks of 8 with the lane loop unrolled
/// had made the AVX-512 builds vectorise across chunks instead: 16 `vgatherqpd` and 8
/// `vscatterqpd` per iteration for GGX D, 5–13× slower than the AVX2 build on AMD Zen 5.
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
/// sets the thread's affinity) scales there as on a dedicated machine (BENCHMARKS.md, on 2
/// cores: 1.85–1.95× pinned, with no round of 21 below 1.5×; unpinned, 3 to 18 rounds of 21
/// below 1.5× per row).
#[cfg(feature = "rayon")]
pub mod par {
    use rayon::prelude::*;

    /// Elements per rayon task: large enough to hide the scheduling (~1 µs), small enough to
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

/// Vectors in structure-of-arrays form, a wavefront renderer's layout: element i is
/// `(x[i], y[i], z[i])`. The slices must have equal lengths.
#[derive(Clone, Copy, Debug)]
pub struct Vectors<'a, F> {
    pub x: &'a [F],
    pub y: &'a [F],
    pub z: &'a [F],
}

/// Output vectors in structure-of-arrays form (each slice at least as long as the inputs).
#[derive(Debug)]
pub struct VectorsMut<'a, F> {
    pub x: &'a mut [F],
    pub y: &'a mut [F],
    pub z: &'a mut [F],
}

/// The GGX conductor the BSDF slices take: an f32 or f64 [`crate::Microfacet`] GGX with the
/// exact complex-IOR Fresnel term, RGB.
pub type GgxConductor<F> = crate::bsdf::RoughConductor<
    F,
    crate::Microfacet<F, crate::Ggx>,
    crate::bsdf::fresnel::Conductor<F, 3>,
    3,
>;

use super::Real;
use crate::bsdf::{Bsdf, Masking};
use crate::distribution::MicrofacetDistribution;

/// (cos 2πv, sin 2πv) for a uniform v in the precision of F, branch-free (the slice kernels'
/// azimuth): f64 is [`super::cos_sin_turn`]; f32 the same reduction to the nearest quarter
/// turn, then Taylor polynomials to x⁹ (sin) and x⁸ (cos) on |x| ≤ π/4 in f32 (the next
/// terms are below 2.5e-8; the f32 roundings give about 1e-7).
#[inline(always)]
fn cos_sin_turn_f<F: Real>(v: F) -> (F, F) {
    if !F::IS_F32 {
        let (c, s) = super::cos_sin_turn(v.to_f64());
        return (F::from_f64(c), F::from_f64(s));
    }
    let v = v.to_f32();
    // 1.5·2^23: adding it rounds to an integer held in the low mantissa bits.
    const MAGIC: f32 = 12_582_912.0;
    let t = 4.0 * v + MAGIC;
    let k = t.to_bits();
    let r = v - (t - MAGIC) * 0.25;
    let x = std::f32::consts::TAU * r;
    let x2 = x * x;
    let s = x
        * (1.0
            + x2 * (-1.0 / 6.0
                + x2 * (1.0 / 120.0 + x2 * (-1.0 / 5040.0 + x2 * (1.0 / 362_880.0)))));
    let c = 1.0 + x2 * (-0.5 + x2 * (1.0 / 24.0 + x2 * (-1.0 / 720.0 + x2 * (1.0 / 40_320.0))));
    // k odd: (c, s) → (−s, c); k & 2: both negated.
    let odd = (k & 1).wrapping_neg();
    let flip = (k & 2) << 30;
    let c1 = (c.to_bits() & !odd) | ((-s).to_bits() & odd);
    let s1 = (s.to_bits() & !odd) | (c.to_bits() & odd);
    (
        F::from_f32(f32::from_bits(c1 ^ flip)),
        F::from_f32(f32::from_bits(s1 ^ flip)),
    )
}

/// Panics unless every input slice has length n and every output at least n (the slice
/// functions' one panic, as slice indexing's).
fn check_lengths(n: usize, inputs: &[usize], outputs: &[usize]) {
    assert!(
        inputs.iter().all(|&l| l == n) && outputs.iter().all(|&l| l >= n),
        "slice lengths differ"
    );
}

/// One lane of the GGX visible-normal slice: spherical caps (Dupuy & Benyoub 2023) as
/// [`super::ggx_visible_stretched_len`], branch-free, with the flag of the lanes the scalar
/// sampler redoes: a stretched direction whose squared length leaves [1e-24, 1e24] (f32) or
/// [1e-200, 1e200] (f64) (a non-unit or extreme direction), a normal that does not face w
/// strictly (the scalar path's `facing` fix), and NaN.
#[inline(always)]
fn ggx_vndf_lane<F: Real>(w: [F; 3], ax: F, ay: F, u: [F; 2]) -> ([F; 3], bool) {
    let s = if w[2] < F::ZERO { -F::ONE } else { F::ONE };
    let (wx, wy, wz) = (s * w[0], s * w[1], s * w[2]);
    let (x, y) = (ax * wx, ay * wy);
    let n2 = x * x + y * y + wz * wz;
    let inv = F::ONE / n2.sqrt();
    let (x, y, z) = (x * inv, y * inv, wz * inv);
    let (c, sn) = cos_sin_turn_f(u[0]);
    let above = (F::ONE - u[1]) * (F::ONE + z);
    let cz = above - z;
    let sin = (F::ONE - cz * cz).max(F::ZERO).sqrt();
    let (hx, hy, hz) = (ax * (sin * c + x), ay * (sin * sn + y), above);
    let inv = F::ONE / (hx * hx + hy * hy + hz * hz).sqrt();
    let m = [hx * inv, hy * inv, hz * inv];
    let (lo, hi) = if F::IS_F32 {
        (1e-24, 1e24)
    } else {
        (1e-200, 1e200)
    };
    let facing = m[0] * wx + m[1] * wy + m[2] * wz;
    let ok = n2 >= F::from_f64(lo) && n2 <= F::from_f64(hi) && facing > F::ZERO;
    (m, !ok)
}

/// The GGX visible-normal slice in the precision of F (see [`ggx_sample_visible_f32`]).
#[inline(always)]
fn ggx_vndf_slice<F: Real>(
    m: &crate::Microfacet<F, crate::Ggx>,
    w: Vectors<'_, F>,
    u0: &[F],
    u1: &[F],
    out: VectorsMut<'_, F>,
) {
    let n = w.x.len();
    check_lengths(
        n,
        &[w.y.len(), w.z.len(), u0.len(), u1.len()],
        &[out.x.len(), out.y.len(), out.z.len()],
    );
    let (ax, ay) = m.alpha();
    let mut start = 0;
    while start < n {
        let end = (start + BLOCK).min(n);
        // The lanes the scalar sampler redoes, recorded in the vectorised pass.
        let mut flags = [false; BLOCK];
        for i in start..end {
            let (v, bad) = ggx_vndf_lane([w.x[i], w.y[i], w.z[i]], ax, ay, [u0[i], u1[i]]);
            out.x[i] = v[0];
            out.y[i] = v[1];
            out.z[i] = v[2];
            flags[i - start] = bad;
        }
        for i in start..end {
            if flags[i - start] {
                let v = m.sample_wm([w.x[i], w.y[i], w.z[i]], [u0[i], u1[i]]);
                (out.x[i], out.y[i], out.z[i]) = (v[0], v[1], v[2]);
            }
        }
        start = end;
    }
}

dispatched! {
/// GGX visible normals for a slice of directions (one material; w of any finite nonzero
/// length, mirrored if w.z < 0, as [`MicrofacetDistribution::sample_wm`]): element i is the normal for
/// `(w[i], [u0[i], u1[i]])`. The same spherical caps as the scalar sampler; f64 returns its
/// bits, f32 takes the azimuth's cosine and sine from a polynomial in f32 (the normal within
/// a few f32 ulps of the scalar's, magnified by the anisotropy: 2e-6 at αx/αy = 2000,
/// tests/wavefront.rs); lanes the vectorised formula does not cover (extreme lengths, a normal
/// that must be tipped to face w) get the scalar sampler's answer. Panics if the lengths
/// differ (as slice indexing does).
pub fn ggx_sample_visible_f32(
    m: &crate::Microfacet<f32, crate::Ggx>,
    w: Vectors<'_, f32>,
    u0: &[f32],
    u1: &[f32],
    out: VectorsMut<'_, f32>,
) {
    ggx_vndf_slice(m, w, u0, u1, out);
}
}

dispatched! {
/// [`ggx_sample_visible_f32`] in f64.
pub fn ggx_sample_visible_f64(
    m: &crate::Microfacet<f64, crate::Ggx>,
    w: Vectors<'_, f64>,
    u0: &[f64],
    u1: &[f64],
    out: VectorsMut<'_, f64>,
) {
    ggx_vndf_slice(m, w, u0, u1, out);
}
}

/// The Beckmann visible-normal slice (the scalar sampler per element: its exact warp is a
/// table guess refined by Halley's method on erf, whose branches and libm calls keep the
/// compiler from vectorising it; the slice form is the same API, compiled per instruction
/// set as the others).
#[inline(always)]
fn beckmann_vndf_slice<F: Real>(
    m: &crate::Microfacet<F, crate::Beckmann>,
    w: Vectors<'_, F>,
    u0: &[F],
    u1: &[F],
    out: VectorsMut<'_, F>,
) {
    let n = w.x.len();
    check_lengths(
        n,
        &[w.y.len(), w.z.len(), u0.len(), u1.len()],
        &[out.x.len(), out.y.len(), out.z.len()],
    );
    for i in 0..n {
        let v = m.sample_wm([w.x[i], w.y[i], w.z[i]], [u0[i], u1[i]]);
        (out.x[i], out.y[i], out.z[i]) = (v[0], v[1], v[2]);
    }
}

dispatched! {
/// Beckmann visible normals for a slice of directions (as [`ggx_sample_visible_f32`]; the
/// scalar sampler's values exactly).
pub fn beckmann_sample_visible_f32(
    m: &crate::Microfacet<f32, crate::Beckmann>,
    w: Vectors<'_, f32>,
    u0: &[f32],
    u1: &[f32],
    out: VectorsMut<'_, f32>,
) {
    beckmann_vndf_slice(m, w, u0, u1, out);
}
}

dispatched! {
/// [`beckmann_sample_visible_f32`] in f64.
pub fn beckmann_sample_visible_f64(
    m: &crate::Microfacet<f64, crate::Beckmann>,
    w: Vectors<'_, f64>,
    u0: &[f64],
    u1: &[f64],
    out: VectorsMut<'_, f64>,
) {
    beckmann_vndf_slice(m, w, u0, u1, out);
}
}

/// GGX Λ of a unit direction at (αx, αy), branch-free (+∞ or NaN at z = 0: flagged by the
/// callers).
#[inline(always)]
fn ggx_lambda_lane<F: Real>(w: [F; 3], ax: F, ay: F) -> F {
    let (x, y, z) = (ax * w[0], ay * w[1], w[2].abs());
    let t = x * x + y * y;
    let z2 = z * z;
    t / ((F::ONE + F::ONE) * (z2 + z * (z2 + t).sqrt()))
}

/// One lane of the GGX conductor's eval and pdf (wo, wi unit), branch-free: f = F(wo·wm)
/// D G2/(4|cos θo cos θi|), pdf = G1(wo) D/(4|cos θo|) with wm the half vector, 0 where wo
/// and wi lie on opposite sides; the flag marks the lanes the scalar BSDF redoes (within
/// 1e-6 of the horizon, a half vector of length below 1e-6, NaN, a value not finite).
#[inline(always)]
fn conductor_lane<F: Real>(
    ax: F,
    ay: F,
    fr: &crate::bsdf::fresnel::Conductor<F, 3>,
    masking: Masking,
    wo: [F; 3],
    wi: [F; 3],
) -> ([F; 3], F, bool) {
    let (co, ci) = (wo[2], wi[2]);
    let same = co * ci > F::ZERO;
    let h = [wo[0] + wi[0], wo[1] + wi[1], co + ci];
    let hl2 = h[0] * h[0] + h[1] * h[1] + h[2] * h[2];
    let sign = if h[2] < F::ZERO { -F::ONE } else { F::ONE };
    let inv = sign / hl2.sqrt();
    let wm = [h[0] * inv, h[1] * inv, h[2] * inv];
    // D at wm (wm.z ≥ 0 here), GGX's vector form.
    let (x, y, z) = (wm[0] / ax, wm[1] / ay, wm[2]);
    let t = x * x + y * y + z * z;
    let d = F::ONE / (F::PI * ax * ay * t * t);
    let (lo, li) = (ggx_lambda_lane(wo, ax, ay), ggx_lambda_lane(wi, ax, ay));
    let g2 = match masking {
        Masking::Correlated => F::ONE / (F::ONE + lo + li),
        Masking::Separable => F::ONE / ((F::ONE + lo) * (F::ONE + li)),
    };
    let c = (wo[0] * wm[0] + wo[1] * wm[1] + co * wm[2]).abs();
    let k = d * g2 / (F::from_f64(4.0) * (co * ci).abs());
    let f = std::array::from_fn(|j| crate::bsdf::fresnel::conductor(c, fr.eta[j], fr.k[j]) * k);
    let pdf = d / ((F::ONE + lo) * F::from_f64(4.0) * co.abs());
    let floor = F::from_f64(1e-6);
    let ok = co.abs() >= floor && ci.abs() >= floor && hl2 >= floor * floor;
    let f = f.map(|v| if same { v } else { F::ZERO });
    let pdf = if same { pdf } else { F::ZERO };
    let finite = f[0].to_f64().is_finite()
        && f[1].to_f64().is_finite()
        && f[2].to_f64().is_finite()
        && pdf.to_f64().is_finite();
    (f, pdf, !(ok && finite))
}

/// The GGX conductor's eval and pdf slices (see [`ggx_conductor_eval_f32`]).
#[inline(always)]
fn conductor_eval_slice<F: Real>(
    b: &GgxConductor<F>,
    wo: Vectors<'_, F>,
    wi: Vectors<'_, F>,
    f: [&mut [F]; 3],
    pdf: &mut [F],
) {
    let n = wo.x.len();
    check_lengths(
        n,
        &[wo.y.len(), wo.z.len(), wi.x.len(), wi.y.len(), wi.z.len()],
        &[f[0].len(), f[1].len(), f[2].len(), pdf.len()],
    );
    let [f0, f1, f2] = f;
    let m = b.distribution();
    let (fr, masking) = b.fresnel_masking();
    let (ax, ay) = m.alpha();
    if m.effectively_smooth() {
        // A delta lobe: f and pdf are 0 for every pair of directions (the scalar's answer).
        for v in [&mut *f0, &mut *f1, &mut *f2, &mut *pdf] {
            v[..n].fill(F::ZERO);
        }
        return;
    }
    let mut start = 0;
    while start < n {
        let end = (start + BLOCK).min(n);
        let mut flags = [false; BLOCK];
        for i in start..end {
            let o = [wo.x[i], wo.y[i], wo.z[i]];
            let v = [wi.x[i], wi.y[i], wi.z[i]];
            let (fv, p, bad) = conductor_lane(ax, ay, fr, masking, o, v);
            (f0[i], f1[i], f2[i], pdf[i]) = (fv[0], fv[1], fv[2], p);
            flags[i - start] = bad;
        }
        for i in start..end {
            if flags[i - start] {
                let o = [wo.x[i], wo.y[i], wo.z[i]];
                let v = [wi.x[i], wi.y[i], wi.z[i]];
                let fv = b.eval(o, v);
                (f0[i], f1[i], f2[i], pdf[i]) = (fv[0], fv[1], fv[2], b.pdf(o, v));
            }
        }
        start = end;
    }
}

dispatched! {
/// The GGX conductor's f (RGB, one slice per channel) and pdf for a slice of direction pairs
/// `(wo[i], wi[i])`, unit vectors: [`Bsdf::eval`] and [`Bsdf::pdf`] element by element (the
/// same formulas, to a few ulp: the half vector is normalised by one division), with the
/// lanes near the horizon or degenerate redone by the scalar BSDF. Panics if the lengths
/// differ.
pub fn ggx_conductor_eval_f32(
    b: &GgxConductor<f32>,
    wo: Vectors<'_, f32>,
    wi: Vectors<'_, f32>,
    f: [&mut [f32]; 3],
    pdf: &mut [f32],
) {
    conductor_eval_slice(b, wo, wi, f, pdf);
}
}

dispatched! {
/// [`ggx_conductor_eval_f32`] in f64.
pub fn ggx_conductor_eval_f64(
    b: &GgxConductor<f64>,
    wo: Vectors<'_, f64>,
    wi: Vectors<'_, f64>,
    f: [&mut [f64]; 3],
    pdf: &mut [f64],
) {
    conductor_eval_slice(b, wo, wi, f, pdf);
}
}

/// The GGX conductor's sample slices (see [`ggx_conductor_sample_f32`]).
#[inline(always)]
fn conductor_sample_slice<F: Real>(
    b: &GgxConductor<F>,
    wo: Vectors<'_, F>,
    u0: &[F],
    u1: &[F],
    wi: VectorsMut<'_, F>,
    f: [&mut [F]; 3],
    pdf: &mut [F],
) {
    let n = wo.x.len();
    check_lengths(
        n,
        &[wo.y.len(), wo.z.len(), u0.len(), u1.len()],
        &[
            f[0].len(),
            f[1].len(),
            f[2].len(),
            pdf.len(),
            wi.x.len(),
            wi.y.len(),
            wi.z.len(),
        ],
    );
    let [f0, f1, f2] = f;
    let m = b.distribution();
    let (fr, masking) = b.fresnel_masking();
    let (ax, ay) = m.alpha();
    let smooth = m.effectively_smooth();
    let mut start = 0;
    while start < n {
        let end = (start + BLOCK).min(n);
        // The lanes the scalar sampler redoes (all of them for a delta lobe).
        let mut flags = [smooth; BLOCK];
        if !smooth {
            for i in start..end {
                let o = [wo.x[i], wo.y[i], wo.z[i]];
                let (wm, bad_m) = ggx_vndf_lane(o, ax, ay, [u0[i], u1[i]]);
                let c = o[0] * wm[0] + o[1] * wm[1] + o[2] * wm[2];
                let v = [
                    (c + c) * wm[0] - o[0],
                    (c + c) * wm[1] - o[1],
                    (c + c) * wm[2] - o[2],
                ];
                let (fv, p, bad_f) = conductor_lane(ax, ay, fr, masking, o, v);
                (wi.x[i], wi.y[i], wi.z[i]) = (v[0], v[1], v[2]);
                (f0[i], f1[i], f2[i], pdf[i]) = (fv[0], fv[1], fv[2], p);
                // Rejected (wi on the other side: pdf 0) or flagged: the scalar decides.
                flags[i - start] = bad_m | bad_f | !(p > F::ZERO);
            }
        }
        for i in start..end {
            if flags[i - start] {
                let o = [wo.x[i], wo.y[i], wo.z[i]];
                let (v, fv, p) = match b.sample(o, F::ZERO, [u0[i], u1[i]]) {
                    Some(s) => (s.wi, s.f, s.pdf),
                    None => ([F::ZERO; 3], [F::ZERO; 3], F::ZERO),
                };
                (wi.x[i], wi.y[i], wi.z[i]) = (v[0], v[1], v[2]);
                (f0[i], f1[i], f2[i], pdf[i]) = (fv[0], fv[1], fv[2], p);
            }
        }
        start = end;
    }
}

dispatched! {
/// The GGX conductor's samples for a slice of outgoing directions `wo[i]` (unit) and uniforms
/// `(u0[i], u1[i])`: wi, f (RGB) and pdf as [`Bsdf::sample`] element by element (its visible
/// normal by [`ggx_sample_visible_f32`]'s lanes, then the reflection and the eval lane). A
/// rejected sample (the scalar's `None`: wi below the horizon, wo on it) is written as
/// wi = 0, f = 0, pdf = 0; a delta lobe (α < 1e-3) as the scalar's mirror sample. Panics if
/// the lengths differ.
pub fn ggx_conductor_sample_f32(
    b: &GgxConductor<f32>,
    wo: Vectors<'_, f32>,
    u0: &[f32],
    u1: &[f32],
    wi: VectorsMut<'_, f32>,
    f: [&mut [f32]; 3],
    pdf: &mut [f32],
) {
    conductor_sample_slice(b, wo, u0, u1, wi, f, pdf);
}
}

dispatched! {
/// [`ggx_conductor_sample_f32`] in f64.
pub fn ggx_conductor_sample_f64(
    b: &GgxConductor<f64>,
    wo: Vectors<'_, f64>,
    u0: &[f64],
    u1: &[f64],
    wi: VectorsMut<'_, f64>,
    f: [&mut [f64]; 3],
    pdf: &mut [f64],
) {
    conductor_sample_slice(b, wo, u0, u1, wi, f, pdf);
}
}
