//! Double GGX: Λ, σ, G1, G2 from a generated octave table (relative error ≤ 1e-7 required,
//! ≤ 2e-9 measured; tests/fast.rs checks it over the whole domain against the exact
//! [`crate::DoubleGgx`], whose Λ is (√π U(−½, 0, 2x) − 1)/2 = (x eˣ(K₀(x) + K₁(x)) − 1)/2).
//!
//! The variable is x = α² tan²θ/2 = α²(1 − u)(1 + u)/(2u²) (one division, no square root).
//! * x < 2^−30 (near the normal): Λ = (x/2)(1 − γ_E − ln(x/2)) + O(x² ln x), relative error
//!   below 1e-9 there.
//! * 2^−30 ≤ x < 2^16: the table (degree and segments in `tables.rs`).
//! * x ≥ 2^16 (grazing): Λ = (√(2πx)(1 + 1/(8x) − 3/(128x²)) − 1)/2, the large-x expansion
//!   of K₀ + K₁, whose next term is below 1e-14 there.

use super::tables::{
    DGGX, DGGX32, DGGX32_K0, DGGX32_K1, DGGX32_M, DGGX_D, DGGX_D_K0, DGGX_D_K1, DGGX_D_M, DGGX_K0,
    DGGX_K1, DGGX_M,
};
use super::{fit, Real};

use std::f64::consts::FRAC_PI_2;

/// Euler's constant γ_E.
const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// Λ(x), x = α² tan²θ/2 ≥ 0 (+∞ at x = +∞, NaN for NaN).
#[inline]
pub fn lambda_x(x: f64) -> f64 {
    // 2^{DGGX_K0} and 2^{DGGX_K1}: the table's ends.
    let lo = super::fit::pow2(DGGX_K0);
    let hi = super::fit::pow2(DGGX_K1);
    if x >= lo && x < hi {
        return fit::eval(&DGGX, DGGX_K0, DGGX_M, x);
    }
    if x < lo {
        if x <= 0.0 {
            return 0.0;
        }
        return 0.5 * x * (1.0 - EULER_GAMMA - (0.5 * x).ln());
    }
    if x.is_nan() {
        return x;
    }
    let r = 1.0 / x;
    let s = (std::f64::consts::TAU * x).sqrt() * (1.0 + r * (0.125 - r * (3.0 / 128.0)));
    0.5 * (s - 1.0)
}

/// D(u) (every u; 0 below the horizon) = G(1/y)/(π α² u⁴), y = tan²θ/α² =
/// (1 − u)(1 + u)/(α²u²), with the slope kernel G(c) = c²((1 + c) e^c E₁(c) − 1) read from a
/// generated table on octaves of y ∈ [2^−30, 2^30) (fit error 6e-12; tests/fast.rs measures
/// the whole path against the exact [`crate::DoubleGgx`]). Outside the table (within 1e-9 α²
/// of the normal, grazing past tan θ = 2^15 α, u > 1, NaN) the exact closed form answers (its
/// E₁ series and continued fraction; ≤ 1e-13). Evaluated in f64.
#[inline]
pub fn d<F: Real>(u: F, alpha: F) -> F {
    let (u, a) = (u.to_f64(), alpha.to_f64());
    let den = a * a * (u * u);
    let y = (1.0 - u) * (1.0 + u) / den;
    // Above the horizon and 2^{DGGX_D_K0} ≤ y < 2^{DGGX_D_K1} (false for NaN).
    if u > 0.0 && y >= fit::pow2(DGGX_D_K0) && y < fit::pow2(DGGX_D_K1) {
        let g = fit::eval(&DGGX_D, DGGX_D_K0, DGGX_D_M, y);
        return F::from_f64(g / (std::f64::consts::PI * den * (u * u)));
    }
    F::from_f64(d_ends(u, a))
}

/// The slope kernel G(1/y) of [`d`] where its table covers y = tan²θ/α² (`None` elsewhere):
/// for anisotropic materials, which form y from the normal directly (y = ((x/αx)² +
/// (y/αy)²)/z²) and divide by π αx αy z⁴.
#[inline(always)]
pub(crate) fn d_kernel_in_table(y: f64) -> Option<f64> {
    (y >= fit::pow2(DGGX_D_K0) && y < fit::pow2(DGGX_D_K1))
        .then(|| fit::eval(&DGGX_D, DGGX_D_K0, DGGX_D_M, y))
}

/// Λ from its argument x = α² tan²θ/2 where the table of the precision covers it (`None`
/// elsewhere): for anisotropic materials, which form x = (αx²x² + αy²y²)/(2z²) from the
/// direction (no projected α). Same tables, so the same accuracy, as [`lambda`].
#[inline(always)]
pub(crate) fn lambda_in_table<F: Real>(x: F) -> Option<F> {
    if F::IS_F32 {
        let x = x.to_f32();
        let (lo, hi) = (fit::pow2(DGGX32_K0) as f32, fit::pow2(DGGX32_K1) as f32);
        return (x >= lo && x < hi)
            .then(|| F::from_f32(fit::eval32(&DGGX32, DGGX32_K0, DGGX32_M, x)));
    }
    let x = x.to_f64();
    (x >= fit::pow2(DGGX_K0) && x < fit::pow2(DGGX_K1))
        .then(|| F::from_f64(fit::eval(&DGGX, DGGX_K0, DGGX_M, x)))
}

/// D where the table does not reach (out of line): the exact path.
#[cold]
#[inline(never)]
fn d_ends(u: f64, a: f64) -> f64 {
    use crate::Ndf;
    crate::DoubleGgx::raw(a).d(u)
}

/// Λ(u) for 0 ≤ u ≤ 1 (−0 and 1 + 2ε included; +∞ at u = 0, 0 at u = 1). f64: x and the table in f64. f32: x and
/// the table (cubics, `DGGX32` in tables.rs) in f32, since Λ's condition number in x is at most about
/// 1 (Λ ~ x ln x near the normal, ~ √x at grazing): x's few roundings cost a few ulp of Λ
/// (measured: 1.6e-7 for the table, 2.9e-7 at random f32 (u, α), tests/fast.rs); outside the table
/// (x < 2^−30, x ≥ 2^16, u = 0 or 1, NaN) the f64 path answers.
#[inline]
pub fn lambda<F: Real>(u: F, alpha: F) -> F {
    if F::IS_F32 {
        return F::from_f32(lambda32(u.to_f32(), alpha.to_f32()));
    }
    let (u, a) = (u.to_f64(), alpha.to_f64());
    let x = 0.5 * a * a * ((1.0 - u) * (1.0 + u)) / (u * u);
    // The table's range (false for NaN), the one test on the hot path; the rest out of line.
    if x >= fit::pow2(DGGX_K0) && x < fit::pow2(DGGX_K1) {
        return F::from_f64(fit::eval(&DGGX, DGGX_K0, DGGX_M, x));
    }
    F::from_f64(lambda_ends(u, a, x))
}

/// Λ outside the table (out of line): near the normal and u > 1 (x < 2^−30: x < 0 at u > 1,
/// Λ = 0 as at u = 1) by [`lambda_x`]; at grazing (x ≥ 2^16) by the expansion, where x may
/// itself have overflowed (u² underflows, or α² tan²θ passes f64::MAX) while Λ is finite:
/// √x is formed without x. NaN stays NaN.
#[cold]
#[inline(never)]
fn lambda_ends(u: f64, a: f64, x: f64) -> f64 {
    if x < fit::pow2(DGGX_K0) {
        return lambda_x(x);
    }
    lambda_grazing(u, a)
}

/// Λ in the grazing expansion of [`lambda_x`] from √x = α √((1 − u)(1 + u)/2)/u, which does
/// not overflow while Λ is finite (NaN stays NaN, u = 0 gives +∞).
fn lambda_grazing(u: f64, a: f64) -> f64 {
    // (u < 0, −0 included: the side the direction comes from, |u|.)
    let u = super::cos_in(u);
    let sx = a * (0.5 * (1.0 - u) * (1.0 + u)).sqrt() / u;
    // 1/x, 0 once x overflows (the corrections are then far below an ulp).
    let r = 1.0 / (sx * sx);
    // √(2πx)/2 = √(π/2) √x, halved before it can overflow.
    let s = (FRAC_PI_2.sqrt() * sx) * (1.0 + r * (0.125 - r * (3.0 / 128.0)));
    s - 0.5
}

/// Λ in f32 arithmetic (see [`lambda`]).
#[inline(always)]
fn lambda32(u: f32, a: f32) -> f32 {
    let x = 0.5 * a * a * ((1.0 - u) * (1.0 + u)) / (u * u);
    // 2^{DGGX32_K0} ≤ x < 2^{DGGX32_K1}: the table's ends (false for NaN).
    let (lo, hi) = (fit::pow2(DGGX32_K0) as f32, fit::pow2(DGGX32_K1) as f32);
    if x >= lo && x < hi {
        return fit::eval32(&DGGX32, DGGX32_K0, DGGX32_M, x);
    }
    lambda32_ends(u, a)
}

/// Λ where the f32 table does not reach (out of line): the f64 path, rounded.
#[cold]
#[inline(never)]
fn lambda32_ends(u: f32, a: f32) -> f32 {
    lambda(f64::from(u), f64::from(a)) as f32
}

g1_g2_from_lambda!();

/// σ(u) for u ∈ [−1, 1]: u(1 + Λ(u)) above the horizon, |u| Λ(|u|) below, σ(0) = √π α/2.
/// In the precision of F (Λ's, see [`lambda`]).
#[inline(always)]
pub fn sigma<F: Real>(u: F, alpha: F) -> F {
    let s0 = F::from_f64(0.5 * super::SQRT_PI) * alpha;
    super::sigma_from_lambda(u, s0, |v| lambda(v, alpha))
}

/// The floor of a component's mixing variable t in both samplers. t = 0 (a uniform of
/// exactly 0: probability 2⁻⁵³, or 2⁻²⁴ from an f32 source) would put the normal on the
/// horizon; t ≥ 1e-200 keeps √t and c²t positive (a component roughness of at most 1e100 α),
/// and in f32 t ≥ 1e-60, so that the normal's z ≥ √(1e-60 · 2⁻²⁴)/1e6 is not rounded to 0.
/// Below the floor lies probability ~1e-100 (1e-30 in f32).
#[inline(always)]
fn t_floor<F: Real>() -> f64 {
    if F::IS_F32 {
        1e-60
    } else {
        1e-200
    }
}

/// A normal distributed exactly as D(m) cos θm, anisotropic roughness (αx, αy): D·cos of
/// the superposition D = ∫₀^∞ e^{−t} D_GGX(αx/√t, αy/√t) dt is the same superposition of the
/// components' D·cos (each integrates to 1), so t ~ Exp(1) from `uniform` (the ziggurat,
/// `ziggurat::exp1`: one uniform, a second in about 3 % of draws), then GGX's D·cos
/// at α/√t driven by u:
/// m ∝ (αx √ξ cos φ, αy √ξ sin φ, √(t(1 − ξ))), ξ = u₀, φ = 2πu₁. Evaluated in f64. Not a warp
/// of u alone (no inverse), unlike the exact [`crate::Exact`] D·cos sampler (a Newton
/// inversion on quadrature-backed CDFs, microseconds).
#[inline]
pub(crate) fn sample_dcos<F: Real>(
    ax: F,
    ay: F,
    u: [F; 2],
    uniform: &mut impl FnMut() -> F,
) -> [F; 3] {
    let mut next = || uniform().to_f64();
    let t = super::ziggurat::exp1(next(), &mut next).max(t_floor::<F>());
    super::ggx_dcos(ax.to_f64(), ay.to_f64(), [u[0].to_f64(), u[1].to_f64()], t)
}

/// A visible normal for the unit direction w (mirrored if w.z < 0), anisotropic roughness
/// (αx, αy), distributed exactly as max(0, w·m) D(m)/σ(w): the visible normals of the
/// Gamma-1 superposition D = ∫₀^∞ e^{−t} D_GGX(αx/√t, αy/√t) dt, evaluated in f64 (f32 rounds
/// once).
///
/// σ is linear in D, so the visible normals of a superposition are a superposition of the
/// components' visible normals with weights e^{−t} σ_t(w)/σ(w), where
/// σ_t(w) = (c + √(c² + h²/t))/2 (c = w.z, h² = αx²w.x² + αy²w.y²) is the GGX component's
/// projected area. t is drawn from that weight by rejection: since √(c² + h²/t) ≤ c + h/√t,
/// the envelope e^{−t}(2c + h t^{−1/2}) is a mixture of Exp(1) (mass 2c) and Gamma(½) (mass
/// h√π), and a candidate is kept with probability (c + √(c² + h²/t))/(2c + h/√t) ≥ 4/5
/// (the minimum, at h/√t = 4c/3; the mean number of candidates is in tests/fast.rs). One
/// uniform picks the part and, scaled, drives that part's ziggurat (`ziggurat`:
/// Exp(1), or Gamma(½) = Z²/2 from the half-normal Z), so neither needs a logarithm or an
/// erfinv. The normal is then the GGX component's spherical-cap sample
/// ([`super::ggx::sample_visible`]) driven by `u`, so stratification of `u` carries over to
/// the normal within each component.
///
/// `uniform` supplies the selection's uniforms in [0, 1): two per candidate (and the
/// ziggurats' occasional extra ones). Unlike the
/// exact [`crate::Exact`] sampler this is not a warp of u alone (no inverse).
#[inline]
pub(crate) fn sample_visible<F: Real>(
    w: [F; 3],
    ax: F,
    ay: F,
    u: [F; 2],
    uniform: &mut impl FnMut() -> F,
) -> [F; 3] {
    let (ax, ay) = (ax.to_f64(), ay.to_f64());
    let mut w = [w[0].to_f64(), w[1].to_f64(), w[2].to_f64()];
    let n2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    // Far from unit length (squares near the ends of the range, or NaN): rescaled.
    if !(1e-200..=1e200).contains(&n2) {
        w = super::rescaled(w);
    }
    let sign = if w[2] < 0.0 { -1.0 } else { 1.0 };
    let (wx, wy, wz) = (sign * w[0], sign * w[1], sign * w[2]);
    let (sx, sy) = (ax * wx, ay * wy);
    let (c, h) = (wz, (sx * sx + sy * sy).sqrt());
    if !(c + h).is_finite() {
        // NaN in w or α (the loop below would never accept).
        return [F::from_f64(f64::NAN); 3];
    }
    // The envelope's masses: 2c for Exp(1), h√π for Gamma(½); their reciprocal shares are
    // computed once, off the candidates' dependency chain.
    let (e, g) = (2.0 * c, super::SQRT_PI * h);
    let p_exp = e / (e + g);
    // (Capped at f64::MAX: at a grazing w (c → 0, e.g. 1e-310) or at normal incidence
    // (h = 0) a share is 0 or subnormal and its reciprocal infinite, and a uniform of 0
    // would make 0 · ∞ = NaN; the capped product stays below 1 where it is used.)
    let (inv_p, inv_q) = (((e + g) / e).min(f64::MAX), ((e + g) / g).min(f64::MAX));
    let mut next = || uniform().to_f64();
    let (mut s, mut len) = (1.0, 1.0);
    // At most 64 candidates: each is kept with probability ≥ 4/5, so a 65th would be needed
    // with probability below 1e-44; the cap only guarantees termination for a `uniform` that
    // returns NaN.
    for _ in 0..64 {
        let v = next();
        // The part and a uniform within it (1 − p_exp of the parts is Gamma(½)), then the
        // part's ziggurat: Exp(1) itself, or Gamma(½) = Z²/2 from the half-normal Z. Selects,
        // not branches: the part is a coin flip for a random direction.
        let exp = v < p_exp;
        let (layers, w) = if exp {
            (&super::ziggurat::EXP, v * inv_p)
        } else {
            (&super::ziggurat::HALF_NORMAL, (v - p_exp) * inv_q)
        };
        let x = super::ziggurat::sample(layers, w, &mut next);
        let t = if exp { x } else { 0.5 * x * x };
        let t = t.max(t_floor::<F>());
        s = t.sqrt();
        // √(c²t + h²) is also the length of the stretched direction (αx w.x, αy w.y, √t w.z)
        // that the GGX step normalises.
        len = (c * c * t + h * h).sqrt();
        // Kept with probability (c + √(c² + h²/t))/(2c + h/√t), multiplied through by √t
        // (no division on the chain).
        if next() * (e * s + h) <= c * s + len {
            break;
        }
    }
    // GGX's visible normal at (αx, αy)/√t, as the stretch (αx, αy, √t).
    let u = [u[0].to_f64(), u[1].to_f64()];
    let m = super::ggx_visible_stretched_len([wx, wy, wz], ax, ay, s, u, len);
    let m = super::facing(m, [wx, wy, wz]);
    [F::from_f64(m[0]), F::from_f64(m[1]), F::from_f64(m[2])]
}

/// A visible normal for v below the horizon (v.z < 0), not mirrored
/// ([`crate::MicrofacetDistribution::sample_wm_stream`]), anisotropic roughness (αx, αy), from the
/// uniforms of `uniform`: the superposition's visible normals from below are its GGX
/// components' with weights e^{−t} σ⁻_t(v), σ⁻_t(v) = (√(c² + h²/t) − c)/2 (c = |v.z|, h the
/// stretched horizontal length: the component's |v.z| Λ). Since σ⁻_t ≤ h/(2√t), t is drawn
/// from the Gamma(½) envelope (Z²/2, Z half-normal, by the ziggurat) and kept with
/// probability (√(c² + h²/t) − c)√t/h = h/(√(c²t + h²) + c√t); the normal is then GGX's
/// cap at the stretch (αx, αy, √t), which covers v.z < 0 as it is. The acceptance is high
/// at grazing v and falls for steep ones (h ≪ c), which rarely meet the microsurface
/// from below; `None` after 256 candidates (the caller's rejection takes over), at h = 0,
/// or for a rounded normal with v·m ≤ 0.
pub(crate) fn sample_visible_below<F: Real>(
    v: [F; 3],
    ax: F,
    ay: F,
    uniform: &mut dyn FnMut() -> F,
) -> Option<[F; 3]> {
    let (v, ax, ay, _, _, h) = super::stream_view(v, ax, ay);
    let c = -v[2];
    if !(c > 0.0 && h > 0.0 && (c + h).is_finite()) {
        return None;
    }
    let mut next = || uniform().to_f64();
    for _ in 0..256 {
        let z = super::ziggurat::sample(&super::ziggurat::HALF_NORMAL, next(), &mut next);
        let t = (0.5 * z * z).max(t_floor::<F>());
        let s = t.sqrt();
        let len = (c * c * t + h * h).sqrt();
        if next() * (len + c * s) <= h {
            let u = [next(), next()];
            let m = super::ggx_visible_stretched_len(v, ax, ay, s, u, len);
            let m = [F::from_f64(m[0]), F::from_f64(m[1]), F::from_f64(m[2])];
            return super::stream_normal(m, v);
        }
    }
    None
}
