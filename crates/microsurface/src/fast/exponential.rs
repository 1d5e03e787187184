//! The Exponential NDF: Λ, σ, G1, G2 from a generated octave table (relative error ≤ 1e-7
//! required; the measured figure is in tests/fast.rs and BENCHMARKS.md), against the exact
//! [`crate::Exponential`], Λ = (2K₁(z) − Ki₁(z))/π, z = 2 cot θ/α (derivations.md A.14).
//!
//! The variable is z = 2u/(α√((1 − u)(1 + u))). Λ falls like e^{−z}/√z; it is read from
//! generated tables (`gen_tables.rs` (an ignored unit test)) in four ranges:
//! * z < 2^−12 (grazing): Λ = 2/(πz) − 1/2 + z/(2π) + O(z³ ln z), relative error below 1e-14.
//! * 2^−12 ≤ z < 64: Λ itself as a function of q = z² = 4u²/(α²(1 − u)(1 + u)) (one
//!   division, no square root), on octaves of q: 16 segments per octave up to q = 64 and 64
//!   from there. Every segment spans at most 0.35 in z, narrow enough for e^{−z} to be a
//!   polynomial (degree 5, fit error 2.0e-9): no exponential at run time. (Degree 7 on
//!   segments twice as wide erred by 1.2e-10; degree 5 takes two coefficients fewer, so
//!   two gathers fewer per lane in the slice kernels and a shorter scalar Λ, both faster
//!   (BENCHMARKS.md); 41 KiB instead of 28.) This range holds 99 % of the
//!   benchmark's random (u, α) (BENCHMARKS.md).
//! * 64 ≤ z < 2^9: Λ e^z on octave segments of z, and one exponential restores the factor.
//! * z ≥ 2^9 (near the normal): Λ = e^{−z}(1 + 11/(8z) − 159/(128z²) + 8595/(3072z³))/√(2πz),
//!   from the large-z expansions of K₁ and Ki₁ (the z⁻³ coefficient fitted to mpmath values of
//!   the Struve form at z = 100…800 and recognised as 315/1536 + 2655/1024); the next term is
//!   about 9/z⁴, below 2e-10 relative. From z ≈ 708 on Λ is subnormal and only absolutely
//!   accurate; it underflows to 0 near z = 745.

use super::tables::{EXPONENTIAL32_QA, EXPONENTIAL32_QA_K0, EXPONENTIAL32_QA_M};
use super::tables::{EXPONENTIAL32_QB, EXPONENTIAL32_QB_K0, EXPONENTIAL32_QB_M};
use super::tables::{EXPONENTIAL_FAR, EXPONENTIAL_FAR_K0, EXPONENTIAL_FAR_K1, EXPONENTIAL_FAR_M};
use super::tables::{EXPONENTIAL_Q, EXPONENTIAL_QA_K0, EXPONENTIAL_QA_M, EXPONENTIAL_QB_ROW0};
use super::tables::{EXPONENTIAL_QB_K0, EXPONENTIAL_QB_K1, EXPONENTIAL_QB_M};
use super::{fit, Real};
use std::f64::consts::{FRAC_1_PI, FRAC_2_PI};

/// Where the q tables change resolution (q = 64, z = 8) and end (q = 4096, z = 64).
pub(super) const Q_B: f64 = 64.0;
pub(super) const Q_END: f64 = 4096.0;
const _: () = {
    use super::tables::EXPONENTIAL_QA_K1;
    // 2^6 = Q_B, where QA ends and QB starts; 2^12 = Q_END.
    use super::tables::{EXPONENTIAL32_QA_K1, EXPONENTIAL32_QB_K1};
    assert!(EXPONENTIAL_QA_K1 == 6 && EXPONENTIAL_QB_K0 == 6 && EXPONENTIAL_QB_K1 == 12);
    assert!(EXPONENTIAL32_QA_K1 == 6 && EXPONENTIAL32_QB_K0 == 6 && EXPONENTIAL32_QB_K1 == 12);
};
// The far table starts an octave below z = 64, so that a z whose square rounds up to 4096
// still finds its row.
const _: () = assert!(EXPONENTIAL_FAR_K0 == 5);

/// Λ from the q tables for 2^−24 ≤ q < 4096 (None outside, and for NaN).
#[inline(always)]
fn lambda_q(q: f64) -> Option<f64> {
    let (qa, qb) = EXPONENTIAL_Q.split_at(EXPONENTIAL_QB_ROW0);
    if q < Q_B && q >= fit::pow2(EXPONENTIAL_QA_K0) {
        return Some(fit::eval(qa, EXPONENTIAL_QA_K0, EXPONENTIAL_QA_M, q));
    }
    if (Q_B..Q_END).contains(&q) {
        return Some(fit::eval(qb, EXPONENTIAL_QB_K0, EXPONENTIAL_QB_M, q));
    }
    None
}

/// Λ from q = z² = 4 cot²θ/α² where the tables of the precision cover it (`None`
/// elsewhere): for anisotropic materials, which form q = 4z²/(αx²x² + αy²y²) from the
/// direction (no projected α). Same tables, so the same accuracy, as [`lambda`].
#[inline(always)]
pub(crate) fn lambda_in_table<F: Real>(q: f64) -> Option<F> {
    if F::IS_F32 {
        if q < Q_B && q >= fit::pow2(EXPONENTIAL32_QA_K0) {
            return Some(F::from_f32(fit::eval_narrow(
                &EXPONENTIAL32_QA,
                EXPONENTIAL32_QA_K0,
                EXPONENTIAL32_QA_M,
                q,
            )));
        }
        if (Q_B..Q_END).contains(&q) {
            return Some(F::from_f32(fit::eval_narrow(
                &EXPONENTIAL32_QB,
                EXPONENTIAL32_QB_K0,
                EXPONENTIAL32_QB_M,
                q,
            )));
        }
        return None;
    }
    lambda_q(q).map(F::from_f64)
}

/// [`lambda_q`] without a branch (the range picks the row and s by selects), for the slice
/// kernels: (Λ, whether q is inside the tables).
#[inline(always)]
pub(super) fn lambda_q_select(q: f64) -> (f64, bool) {
    let b = q >= Q_B;
    let (k0, m, row0) = if b {
        (EXPONENTIAL_QB_K0, EXPONENTIAL_QB_M, EXPONENTIAL_QB_ROW0)
    } else {
        (EXPONENTIAL_QA_K0, EXPONENTIAL_QA_M, 0)
    };
    let (i, s) = fit::octave_segment(k0, m, q);
    let row = row0.wrapping_add(i).min(EXPONENTIAL_Q.len() - 1);
    let inside = q >= fit::pow2(EXPONENTIAL_QA_K0) && q < Q_END;
    (fit::estrin(&EXPONENTIAL_Q[row], s), inside)
}

/// q = z² = 4u²/(α²(1 − u)(1 + u)).
#[inline(always)]
pub(super) fn q_of(u: f64, a: f64) -> f64 {
    4.0 * u * u / (a * a * ((1.0 - u) * (1.0 + u)))
}

/// Λ(z), z = 2 cot θ/α ≥ 0 (+∞ at z = 0, NaN for NaN).
#[inline(always)]
pub fn lambda_z(z: f64) -> f64 {
    // The common cases (99 % of random directions and roughnesses) inline, one table lookup
    // and no exponential; the rest out of line, to keep the inlined body small.
    match lambda_q(z * z) {
        Some(v) => v,
        None => lambda_z_ends(z),
    }
}

/// Λ(z) past the q tables: z < 2^−12, z ≥ 64 (or a z whose square rounded out of the tables'
/// range), NaN, and any z whose q, computed from (u, α), under- or overflowed (u and α both
/// below ~1e-154, say).
#[cold]
#[inline(never)]
fn lambda_z_ends(z: f64) -> f64 {
    if z < fit::pow2(EXPONENTIAL_QA_K0 / 2) {
        // z < 2^−12.
        return FRAC_2_PI / z - 0.5 + 0.5 * FRAC_1_PI * z;
    }
    if z < fit::pow2(EXPONENTIAL_FAR_K0) {
        // 2^−12 ≤ z < 32: z² lies inside the q tables.
        if let Some(v) = lambda_q(z * z) {
            return v;
        }
    }
    if z < fit::pow2(EXPONENTIAL_FAR_K1) {
        return fit::eval(&EXPONENTIAL_FAR, EXPONENTIAL_FAR_K0, EXPONENTIAL_FAR_M, z) * (-z).exp();
    }
    if z.is_nan() {
        return z;
    }
    let r = 1.0 / z;
    let series = 1.0 + r * (11.0 / 8.0 - r * (159.0 / 128.0 - r * (8595.0 / 3072.0)));
    (-z).exp() * series / (std::f64::consts::TAU * z).sqrt()
}

/// z = 2u/(α√((1 − u)(1 + u))), for the ends (where q may under- or overflow).
#[inline(always)]
pub(super) fn z_of(u: f64, a: f64) -> f64 {
    (u + u) / (a * ((1.0 - u) * (1.0 + u)).sqrt())
}

/// D(u) = 2 exp(−2 tan θ/α)/(π α² u⁴); D(1) for u > 1; 0 for u ≤ 0 and where e^{−2tan θ/α} underflows
/// (relative error ≤ 1e-13 in f64 while the exponent is below 30, growing like ε·exponent).
#[inline]
pub fn d<F: Real>(u: F, alpha: F) -> F {
    let (u, a) = (u.to_f64(), alpha.to_f64());
    // (False for NaN; one test for both edges, as the hot path had for u ≤ 0.)
    if !(u > 0.0 && u <= 1.0) {
        return F::from_f64(d_edges(u, a));
    }
    let u2 = u * u;
    let x = 2.0 * ((1.0 - u) * (1.0 + u)).sqrt() / (u * a);
    // e^{−x} is 0 past 745 (and u⁴ could underflow too: 0/0).
    if x > 745.2 {
        return F::ZERO;
    }
    F::from_f64(2.0 * (-x).exp() / (std::f64::consts::PI * a * a * u2 * u2))
}

/// Λ(u) for 0 ≤ u ≤ 1 (−0 and 1 + 2ε included; +∞ at u = 0, 0 at u = 1). f32: q in f64 still (Λ's condition number
/// in z is about z, up to 64 in the tables, so q rounded to f32 would cost up to ~2e-6),
/// then cubics in f32 on 4× finer segments (32 rows per octave of q to q = 64, 128 beyond:
/// `EXPONENTIAL32_QA`, `_QB` in tables.rs, error 4.2e-7 with s rounded to f32 as
/// evaluated), by Horner's rule (`fit::poly`). Outside them the f64
/// path answers, rounded. (Evaluating the cubics in f64 with f32 coefficients was slower,
/// BENCHMARKS.md: four widenings of the coefficients and one more rounding at the end.)
#[inline]
pub fn lambda<F: Real>(u: F, alpha: F) -> F {
    if F::IS_F32 {
        return F::from_f32(lambda32(u.to_f64(), alpha.to_f64()));
    }
    let (u, a) = (u.to_f64(), alpha.to_f64());
    F::from_f64(match lambda_q(q_of(u, a)) {
        Some(v) => v,
        None => lambda_outside(u, a),
    })
}

/// Λ past the q tables (out of line): u ∉ (0, 1] first (+∞ at ±0, 0 past 1, Λ(|u|) below 0,
/// NaN for NaN), then the ends of z.
#[cold]
#[inline(never)]
fn lambda_outside(u: f64, a: f64) -> f64 {
    if !(u > 0.0 && u <= 1.0) {
        return super::lambda_at_edge(u, |v| lambda(v, a));
    }
    lambda_z_ends(z_of(u, a))
}

/// D outside (0, 1] (out of line): 0 for u ≤ 0, D(1) for u > 1, NaN for NaN.
#[cold]
#[inline(never)]
fn d_edges(u: f64, a: f64) -> f64 {
    super::d_at_edge(u, |v| d(v, a))
}

/// Λ for the f32 entry points (see [`lambda`]), from f32 inputs widened to f64.
#[inline(always)]
fn lambda32(u: f64, a: f64) -> f32 {
    let q = q_of(u, a);
    if q < Q_B && q >= fit::pow2(EXPONENTIAL32_QA_K0) {
        return fit::eval_narrow(
            &EXPONENTIAL32_QA,
            EXPONENTIAL32_QA_K0,
            EXPONENTIAL32_QA_M,
            q,
        );
    }
    if (Q_B..Q_END).contains(&q) {
        return fit::eval_narrow(
            &EXPONENTIAL32_QB,
            EXPONENTIAL32_QB_K0,
            EXPONENTIAL32_QB_M,
            q,
        );
    }
    lambda32_ends(u, a)
}

/// Λ past the f32 tables (out of line): the f64 path, rounded.
#[cold]
#[inline(never)]
fn lambda32_ends(u: f64, a: f64) -> f32 {
    lambda(u, a) as f32
}

g1_g2_from_lambda!();

/// σ(u) for u ∈ [−1, 1]: u(1 + Λ(u)) above the horizon, |u| Λ(|u|) below, σ(0) = α/π.
#[inline(always)]
pub fn sigma<F: Real>(u: F, alpha: F) -> F {
    let s0 = alpha * F::from_f64(FRAC_1_PI);
    super::sigma_from_lambda(u, s0, |v| lambda(v, alpha))
}

/// A normal distributed exactly as D(m) cos θm, anisotropic roughness (αx, αy): at unit
/// roughness the slope radius under D·cos, 2πr P22(r) = 4r e^{−2r}, is Gamma(2, ½), i.e.
/// r = ½(−ln(1 − ξ) + E) with ξ = u₀ and E ~ Exp(1) from `uniform` (the ziggurat,
/// [`super::ziggurat::exp1`]: one uniform, a second in about 3 % of draws); azimuth 2πu₁; then
/// stretched. Evaluated in f64. Not a warp of u alone (no inverse), unlike the exact
/// [`crate::Exact`] D·cos sampler (a Newton inversion, about a microsecond).
#[inline]
pub(crate) fn sample_dcos<F: Real>(
    ax: F,
    ay: F,
    u: [F; 2],
    uniform: &mut impl FnMut() -> F,
) -> [F; 3] {
    // Gamma(2) = −ln(1 − ξ) (ln1p: exact where ξ is small) + Exp(1) from the ziggurat.
    let mut next = || uniform().to_f64();
    let e = super::ziggurat::exp1(next(), &mut next);
    let r = 0.5 * (e - super::arith::ln_1p(-u[0].to_f64()));
    let cs = super::cos_sin_turn(u[1].to_f64());
    super::normal_from_polar(r, cs, ax.to_f64(), ay.to_f64())
}

/// A visible normal for the unit direction w (mirrored if w.z < 0), anisotropic roughness
/// (αx, αy), distributed exactly as max(0, w·m) D(m)/σ(w), by rejection in slope space;
/// evaluated in f64 (f32 rounds once).
///
/// In the α = 1 configuration (w stretched to w̃ ∝ (αx w.x, αy w.y, w.z) = (h cos φ,
/// h sin φ, c)), the visible slopes (x̃ along φ, ỹ across) have the density
/// (c + h x̃)⁺ P22(x̃, ỹ) with P22(r) = 2e^{−2r}/π. The envelope c + h x̃⁺ has two parts that
/// are sampled exactly:
/// * c · P22 (mass c): D·cos slopes, r ~ Gamma(2, ½) = −½ ln(v₁v₂), azimuth uniform;
/// * h x̃⁺ P22 (mass h σ(0) = h/π): r ~ Gamma(3, ½) = −½ ln(v₁v₂v₃), and an azimuth ψ with
///   density ∝ cos⁺ψ, i.e. sin ψ uniform on (−1, 1).
///
/// The second part is exact (x̃ ≥ 0 there), and so is the first where x̃ ≥ 0; where x̃ < 0 a
/// candidate is kept with probability (c + h x̃)⁺/c. The expected number of candidates is
/// (c + h/π)/σ(w̃), largest near 60° at α = 1 (about 1.2).
///
/// `u` drives the first candidate (u₀ picks the part and then the azimuth, u₁ is one factor
/// of the radius); `uniform` supplies the rest in [0, 1): one or two per candidate, plus
/// three per rejected one. Not a warp of u alone (no inverse), unlike [`crate::Exact`].
#[inline]
pub(crate) fn sample_visible<F: Real>(
    w: [F; 3],
    ax: F,
    ay: F,
    u: [F; 2],
    uniform: &mut impl FnMut() -> F,
) -> [F; 3] {
    let (ax, ay) = (ax.to_f64(), ay.to_f64());
    let (c, h, cp, sp) = super::slope_frame(w, ax, ay);
    if !(c + h).is_finite() {
        // NaN in w or α (the loop below would never accept).
        return [F::from_f64(f64::NAN); 3];
    }
    // The envelope's masses: c for the D·cos part, h/π for the first-moment part. The part is
    // decided by a multiplication (v0 < p_dcos ⇔ d < 0), and the reciprocals of p_dcos and of
    // g are computed once, off the candidates' chain.
    let (e, g) = (c, h * FRAC_1_PI);
    let total = e + g;
    // (Capped at f64::MAX: at a grazing w (c → 0) or at normal incidence (h = 0) a mass is 0
    // or subnormal and its reciprocal infinite; the capped products stay in [0, 1) where
    // they are used, never 0 · ∞.)
    let (inv_p, inv_g) = ((total / e).min(f64::MAX), (1.0 / g).min(f64::MAX));
    let (mut v0, mut v1) = (u[0].to_f64(), u[1].to_f64());
    let (mut x, mut y) = (0.0, 0.0);
    // At most 64 candidates: each is kept with probability above 1/2, so the cap (which only
    // guarantees termination for a `uniform` that returns NaN) is reached with probability
    // below 1e-19.
    for i in 0..64 {
        if i > 0 {
            v0 = uniform().to_f64();
            v1 = uniform().to_f64();
        }
        // A product of uniforms in (0, 1]: −½ ln of k of them is Gamma(k, ½).
        let prod = (1.0 - v1) * (1.0 - uniform().to_f64());
        let d = v0 * total - e;
        if d < 0.0 {
            let r = -0.5 * prod.ln();
            let turn = v0 * inv_p;
            let (co, s) = super::cos_sin_turn(turn);
            (x, y) = (r * co, r * s);
            // x ≥ 0 (cos 2πv ≥ 0) read from the turn itself, early on the chain.
            if (turn - 0.5).abs() >= 0.25 || uniform().to_f64() * c <= c + h * x {
                break;
            }
        } else {
            let r = -0.5 * (prod * (1.0 - uniform().to_f64())).ln();
            let s = 2.0 * (d * inv_g) - 1.0;
            // (The max: s may round past 1.)
            (x, y) = (r * ((1.0 - s) * (1.0 + s)).max(0.0).sqrt(), r * s);
            break;
        }
    }
    super::facing(super::normal_from_slopes(x, y, (cp, sp), ax, ay), w)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ranges_meet_where_the_tables_end() {
        // Continuity across each switch, to the tables' accuracy: each side within its fit
        // error (2.0e-9 for the q tables, 1.2e-11 for the far table), so 5e-9 apart at most.
        // (z = 2^−12, 8, 64 and 512: q = 2^−24, 64, 4096.)
        for z in [
            fit::pow2(EXPONENTIAL_QA_K0 / 2),
            Q_B.sqrt(),
            Q_END.sqrt(),
            512.0,
        ] {
            let below = lambda_z(f64::from_bits(z.to_bits() - 1));
            assert!((lambda_z(z) / below - 1.0).abs() < 5e-9, "{z}");
        }
        // Every z in the q tables' range lands in them or in the ends, both accurate: a z
        // below 64 whose q (computed from u and α, not as z²) rounds to 4096 goes to the far
        // table, which starts at 32.
        let mut z = 32.0;
        while z < 64.0 {
            assert!((lambda_z_ends(z) / lambda_z(z) - 1.0).abs() < 5e-9, "{z}");
            z *= 1.001;
        }
        // q under- or overflowing from (u, α) while z is moderate: the ends still answer.
        for (u, a) in [(1e-200, 1e-200), (3e-170, 1e-170)] {
            let z = z_of(u, a);
            // (q is 0/0 = NaN or 0 there.)
            let q = q_of(u, a);
            assert!(q.is_nan() || q < 1e-300, "{u} {a}");
            assert!((lambda(u, a) / lambda_z(z) - 1.0).abs() < 1e-12, "{u} {a}");
        }
        // The slice kernels' branch-free form agrees with the branches: the same row, by
        // Estrin's scheme there and Horner's rule here (fit::poly), so within rounding.
        let mut z = 2f64.powi(-12);
        while z < 64.0 {
            let (v, inside) = lambda_q_select(z * z);
            assert!(inside && (v / lambda_z(z) - 1.0).abs() <= 1e-15, "{z}");
            z *= 1.001;
        }
    }
}
