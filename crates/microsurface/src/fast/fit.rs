//! Piecewise polynomials on octaves: the tables behind the fast Λ of the NDFs without a cheap
//! closed form.
//!
//! A table covers x ∈ [2^k0, 2^k1); every octave [2^e, 2^{e+1}) is cut into 2^m equal segments,
//! and on each segment the function is the polynomial Σ c_j s^j of degree N − 1 in
//! s = 2(x − x₀)/h − 1 ∈ [−1, 1) (x₀ the segment's start, h its width). The segment and s come
//! from the bits of x (no logarithm, no search): the exponent and the top m mantissa bits
//! index the segment, and the remaining mantissa bits are the position (x − x₀)/h, exactly,
//! so s is formed from them by integer operations and one exact subtraction (faster than
//! x − x₀ and a multiplication: BENCHMARKS.md).
//!
//! Tables are built by Chebyshev interpolation ([`fit_octaves`]): at N Chebyshev points of each
//! segment, converted to the monomial basis in s (|s| ≤ 1 keeps that conversion well
//! conditioned for N ≤ 12). The fits of Double GGX and the Exponential NDF are generated once
//! by `gen_tables.rs` (an ignored unit test) into `tables.rs`; GTR's are built per (α, γ) at run time.

/// 2^k for a normal exponent k (the ends of a table's range), exactly, from its bits.
#[inline(always)]
pub fn pow2(k: i32) -> f64 {
    f64::from_bits(((1023 + k) as u64) << 52)
}

/// Evaluates the table `coef` (first octave 2^k0, 2^m segments per octave) at x.
///
/// Meaningful for 2^k0 ≤ x < 2^{k0 + coef.len()/2^m}; outside, the index is clamped (the load
/// stays in bounds, so the slice kernels can evaluate every lane) and the value is
/// meaningless, so callers range-check or redo such x.
#[inline(always)]
pub fn eval<const N: usize>(coef: &[[f64; N]], k0: i32, m: u32, x: f64) -> f64 {
    let (idx, s) = octave_segment(k0, m, x);
    poly(&coef[idx.min(coef.len() - 1)], s)
}

/// [`eval`] by Estrin's scheme whatever the row's length, for the slice kernels (see [`poly`]).
#[inline(always)]
pub fn eval_estrin<const N: usize>(coef: &[[f64; N]], k0: i32, m: u32, x: f64) -> f64 {
    let (idx, s) = octave_segment(k0, m, x);
    estrin(&coef[idx.min(coef.len() - 1)], s)
}

/// The bits of 2.0 (f64 and f32): with a position's bits as the mantissa, 2(1 + position).
const TWO: u64 = 0x4000_0000_0000_0000;
const TWO32: u32 = 0x4000_0000;

/// The row (unclamped: out of range for x outside the table) and s of x in an octave table
/// (see [`eval`]).
#[inline(always)]
pub fn octave_segment(k0: i32, m: u32, x: f64) -> (usize, f64) {
    let bits = x.to_bits();
    let idx = (bits >> (52 - m)).wrapping_sub(((1023 + k0) as u64) << m) as usize;
    // The 52 − m mantissa bits below the index are x's position in its segment: as the
    // mantissa of a number in [2, 4) (the exponent of 2.0) they give 2(1 + (x − x₀)/h)
    // exactly, and s = 2(1 + ·) − 3 is one exact subtraction (the same s as (x − x₀)·2/h − 1,
    // with integer operations in place of a subtraction and a multiplication on the chain;
    // the mantissa of a number in [1, 2), doubled and then shifted, took two additions).
    // Sign, exponent and the index's m bits are shifted out.
    let position = (bits << (12 + m)) >> 12;
    (idx, f64::from_bits(TWO | position) - 3.0)
}

/// [`eval`] in single precision: a table of f32 coefficients, indexed by the bits of an f32
/// x and evaluated in f32 arithmetic (the native f32 paths; same meaning of k0 and m).
#[inline(always)]
pub fn eval32<const N: usize>(coef: &[[f32; N]], k0: i32, m: u32, x: f32) -> f32 {
    let (idx, s) = octave_segment32(k0, m, x);
    poly(&coef[idx.min(coef.len() - 1)], s)
}

/// [`eval`] of an f32 table at an f64 x (for the f32 paths whose variable must stay in f64),
/// with no f64 arithmetic: the bits below the segment's index are x's position in its
/// segment, and their top 23 make the f32 2(1 + position) ∈ [2, 4), so s = 2(1 + position) − 3
/// is one exact subtraction (the truncation moves x by less than 2^−23 of a segment's
/// width). Then the polynomial in f32.
#[inline(always)]
pub fn eval_narrow<const N: usize>(coef: &[[f32; N]], k0: i32, m: u32, x: f64) -> f32 {
    let bits = x.to_bits();
    let idx = (bits >> (52 - m)).wrapping_sub(((1023 + k0) as u64) << m) as usize;
    // Sign, exponent and the index's m mantissa bits shifted out; the position's top 23
    // bits kept.
    let position = ((bits << (12 + m)) >> 41) as u32;
    let s = f32::from_bits(TWO32 | position) - 3.0;
    poly(&coef[idx.min(coef.len() - 1)], s)
}

/// [`octave_segment`] of an f32 x (8 exponent bits, 23 mantissa bits).
#[inline(always)]
pub fn octave_segment32(k0: i32, m: u32, x: f32) -> (usize, f32) {
    let bits = x.to_bits();
    let idx = (bits >> (23 - m)).wrapping_sub(((127 + k0) as u32) << m) as usize;
    // The position's 23 − m bits as the mantissa of 2(1 + position) (see `octave_segment`).
    let position = (bits << (9 + m)) >> 9;
    (idx, f32::from_bits(TWO32 | position) - 3.0)
}

/// Σ c_j s^j for a table row: [`horner`] up to 6 coefficients, [`estrin`] beyond.
///
/// The scalar fast paths are called in loops of independent calls (a renderer's, the
/// benchmark's), which overlap; what bounds them is the operations in flight more than one
/// call's chain. For the short rows (the Λ tables: 4 to 6 coefficients) Horner's rule, the
/// fewest operations, measured faster than Estrin's scheme (Double GGX and Exponential Λ in
/// f64 and f32, GTR in f32; BENCHMARKS.md; GTR's f64 rows were no faster and call
/// [`estrin`]). For the long ones (7 to 11: erfcx, erfinv, Double GGX D, the sine and cosine
/// of the samplers) the chain of Horner's rule cost more (GGX D·cos with Horner's rule
/// throughout was slower), so they keep Estrin's. The slice kernels call [`estrin`]
/// directly: vector code is bound by its gathers' latency there (GTR's kernel was slower
/// with Horner's rule).
#[inline(always)]
pub fn poly<F: super::Real, const N: usize>(c: &[F; N], s: F) -> F {
    // (6: see above; the longest rows of the Λ tables.)
    if N <= 6 {
        horner(c, s)
    } else {
        estrin(c, s)
    }
}

/// Σ c_j s^j by Horner's rule, (…(c_{N−1} s + c_{N−2}) s + …) s + c₀: N − 1 multiplications
/// and additions, on one chain of that length.
#[inline(always)]
pub fn horner<F: super::Real, const N: usize>(c: &[F; N], s: F) -> F {
    const { assert!(N >= 1, "a row holds a coefficient") };
    let mut acc = c[N - 1];
    for j in (0..N - 1).rev() {
        acc = acc * s + c[j];
    }
    acc
}

/// Σ c_j s^j, by Estrin's scheme: pairs c_{2i} + c_{2i+1} s, then pairs of those with s²,
/// s⁴, …: a dependency chain of depth ~2 log₂ N instead of Horner's 2N (the default x86-64
/// target has no fused multiply-add, so the chain's latency is the cost), for a few more
/// operations. For |s| ≤ 1 and decaying coefficients the rounding error is that of Horner's
/// within a few ulp.
#[inline(always)]
pub fn estrin<F: super::Real, const N: usize>(c: &[F; N], s: F) -> F {
    const { assert!(N >= 1 && N <= 16, "tables hold 1 to 16 coefficients") };
    // Fixed trip counts and conditions on the constant N: LLVM unrolls every level and drops
    // the dead branches, so this is straight-line code for each table's N.
    let s2 = s * s;
    let s4 = s2 * s2;
    let s8 = s4 * s4;
    let mut b = [F::ZERO; 8];
    for (i, bi) in b.iter_mut().enumerate() {
        let k = 2 * i;
        if k + 1 < N {
            *bi = c[k] + c[k + 1] * s;
        } else if k < N {
            *bi = c[k];
        }
    }
    let nb = N.div_ceil(2);
    let mut d = [F::ZERO; 4];
    for (j, dj) in d.iter_mut().enumerate() {
        let k = 2 * j;
        if k + 1 < nb {
            *dj = b[k] + b[k + 1] * s2;
        } else if k < nb {
            *dj = b[k];
        }
    }
    let nd = nb.div_ceil(2);
    let e0 = if nd > 1 { d[0] + d[1] * s4 } else { d[0] };
    let e1 = if nd > 3 { d[2] + d[3] * s4 } else { d[2] };
    if nd > 2 {
        e0 + e1 * s8
    } else {
        e0
    }
}

/// Chebyshev interpolation of `f` on every segment of [2^k0, 2^k1) (2^m segments per octave),
/// in the monomial basis of [`eval`].
pub fn fit_octaves<const N: usize>(
    k0: i32,
    k1: i32,
    m: u32,
    f: impl FnMut(f64) -> f64,
) -> Vec<[f64; N]> {
    octave_node_values::<N>(k0, k1, m, f)
        .iter()
        .map(chebyshev_coefficients)
        .collect()
}

/// `f` at the N Chebyshev points of every segment of [2^k0, 2^k1), segment by segment (the
/// input of [`chebyshev_coefficients`]; a caller can transform the values first and so fit
/// two functions of one set of evaluations).
pub fn octave_node_values<const N: usize>(
    k0: i32,
    k1: i32,
    m: u32,
    mut f: impl FnMut(f64) -> f64,
) -> Vec<[f64; N]> {
    let per = 1usize << m;
    let nodes = chebyshev_nodes::<N>();
    let mut out = Vec::with_capacity((k1 - k0) as usize * per);
    for e in k0..k1 {
        let lo = 2f64.powi(e);
        let h = lo / per as f64;
        for j in 0..per {
            let x0 = lo + j as f64 * h;
            out.push(nodes.map(|s| f(x0 + 0.5 * (s + 1.0) * h)));
        }
    }
    out
}

/// The Chebyshev points of the first kind on [−1, 1], cos(π(k + ½)/N).
pub fn chebyshev_nodes<const N: usize>() -> [f64; N] {
    std::array::from_fn(|k| (std::f64::consts::PI * (k as f64 + 0.5) / N as f64).cos())
}

/// The degree N − 1 interpolant of `g` on [−1, 1] at the Chebyshev points of the first kind,
/// as monomial coefficients.
pub fn chebyshev_fit<const N: usize>(g: impl FnMut(f64) -> f64) -> [f64; N] {
    chebyshev_coefficients(&chebyshev_nodes::<N>().map(g))
}

/// The monomial coefficients in s of the polynomial through `values` at
/// [`chebyshev_nodes`].
pub fn chebyshev_coefficients<const N: usize>(values: &[f64; N]) -> [f64; N] {
    use std::f64::consts::PI;
    // Chebyshev coefficients a_j = (2/N) Σ_k f(s_k) T_j(s_k) (halved for j = 0).
    let mut a = [0.0; N];
    for (j, aj) in a.iter_mut().enumerate() {
        let sum: f64 = (0..N)
            .map(|k| values[k] * (PI * j as f64 * (k as f64 + 0.5) / N as f64).cos())
            .sum();
        *aj = if j == 0 { 1.0 } else { 2.0 } * sum / N as f64;
    }
    // Σ a_j T_j(s) in monomials: T_{j+1} = 2 s T_j − T_{j−1}.
    let mut out = [0.0; N];
    let mut t_prev = [0.0; N];
    let mut t_cur = [0.0; N];
    t_prev[0] = 1.0; // T_0
    if N > 1 {
        t_cur[1] = 1.0; // T_1
    }
    for (i, c) in out.iter_mut().enumerate() {
        *c += a[0] * t_prev[i];
    }
    for &aj in a.iter().skip(1) {
        for (i, c) in out.iter_mut().enumerate() {
            *c += aj * t_cur[i];
        }
        let mut next = [0.0; N];
        for i in 0..N {
            next[i] = -t_prev[i] + if i > 0 { 2.0 * t_cur[i - 1] } else { 0.0 };
        }
        t_prev = t_cur;
        t_cur = next;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_a_smooth_function_and_indexes_segments_from_bits() {
        let f = |x: f64| x.ln() * x.sqrt();
        let (k0, k1, m) = (-5, 7, 2);
        let t = fit_octaves::<9>(k0, k1, m, f);
        assert_eq!(t.len(), 12 * 4);
        let mut worst = 0.0f64;
        let mut x = 2f64.powi(k0);
        while x < 2f64.powi(k1) {
            let e = (eval(&t, k0, m, x) - f(x)).abs() / f(x).abs().max(1e-3);
            worst = worst.max(e);
            x *= 1.001_234;
        }
        assert!(worst < 1e-9, "{worst}");
        // Segment ends: both sides of a boundary agree with f.
        let b = 2.0f64 * 1.25;
        for x in [b, f64::from_bits(b.to_bits() - 1)] {
            assert!((eval(&t, k0, m, x) - f(x)).abs() < 1e-9);
        }
    }
}
