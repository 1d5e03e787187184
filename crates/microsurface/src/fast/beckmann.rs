//! Beckmann: D, Λ, G1, G2, σ in closed form, and visible-normal sampling.
//!
//! `sample_visible` (behind `Microfacet<_, Beckmann>`) is the exact warp of [`crate::Exact`]'s Beckmann sampler (Heitz &
//! d'Eon 2014's slope-space inversion), made fast. For a direction with cot θ = a in the
//! α = 1 configuration the visible slope x̃ has the CDF N(X)/Z with
//!
//!   N(X) = (a/2)(erfc(−X) − erfc a) − (e^{−X²} − e^{−a²})/(2√π),
//!   Z − N(X) = (a/2) erfc X + e^{−X²}/(2√π),  Z = a(1 + Λ(a)),
//!
//! (the second form has no cancellation for X > 0), and ỹ is Gaussian: ỹ = erfinv(2u₂ − 1).
//! x̃ starts from a bilinear table of the inverse over (1/(1 + a), u₁) (`BECKMANN_GUESS` in
//! tables.rs, generated from the exact sampler by `gen_tables.rs` (an ignored unit test); guess error
//! about 1e-4) and is finished by safeguarded Halley steps
//! on N (two, typically; every step is bracketed, so the tails, where the table is coarse,
//! only take more steps). [`erfinv`] is a Chebyshev table of erfinv(v)/v in w = −ln(1 − v²)
//! (fit error below 1e-15). Accuracy against the exact sampler: tests/fast.rs.

use super::tables::{
    BECKMANN_GUESS, ERFCX, ERFCX_K0, ERFCX_K1, ERFCX_M, ERFC_RATIO, ERFC_RATIO_K0, ERFC_RATIO_K1,
    ERFC_RATIO_M, ERFINV, ERFINV_K0, ERFINV_K1, ERFINV_M,
};
use super::Real;

/// D(u) = exp(−x)/(π α² u⁴), x = tan²θ/α²; 0 for u ≤ 0, D(1) for u > 1.
///
/// In f32 the exponent x carries a few f32 roundings (relative 2e-7), which e^{−x} turns
/// into an error of about 2e-7·x: below 2e-5 while x < 80. Beyond, and where e^{−x} would be
/// subnormal in f32 while D is not (x > 87, small α), the f32 entry point evaluates in f64
/// and rounds once, so its bound is 2e-5 everywhere D is a normal f32 (tests/fuzz.rs).
#[inline]
pub fn d<F: Real>(u: F, alpha: F) -> F {
    // (False for NaN; one test for both edges, as the hot path had for u ≤ 0.)
    if !(u > F::ZERO && u <= F::ONE) {
        return d_edges(u, alpha);
    }
    let u2 = u * u;
    let a2 = alpha * alpha;
    let x = (F::ONE - u) * (F::ONE + u) / (u2 * a2);
    // f32 past x = 80: see above (a test on the precision, removed by the compiler in f64).
    if F::IS_F32 && x > F::from_f64(80.0) {
        return F::from_f64(d(u.to_f64(), alpha.to_f64()));
    }
    // e^{−x} underflows (in f64) past 745; so does D, and u⁴ may too (0/0), so answer 0.
    if x > F::EXP_ZERO {
        return F::ZERO;
    }
    (-x).exp() / (F::PI * a2 * u2 * u2)
}

/// D outside (0, 1] (out of line): 0 for u ≤ 0, D(1) for u > 1, NaN for NaN.
#[cold]
#[inline(never)]
fn d_edges<F: Real>(u: F, alpha: F) -> F {
    super::d_at_edge(u, |v| d(v, alpha))
}

/// Λ(u) = e^{−a²} r(a)/(2a√π), a = cot θ/α, r(a) = 1 − √π a erfcx(a), for 0 ≤ u ≤ 1
/// (−0 and 1 + 2ε included; +∞ at u = 0, 0 at u = 1), evaluated in f64 ([`lambda_cot`];
/// f32 rounds once).
#[inline]
pub fn lambda<F: Real>(u: F, alpha: F) -> F {
    let (u, alpha) = (u.to_f64(), alpha.to_f64());
    // (False for NaN.)
    if !(u > 0.0 && u <= 1.0) {
        return F::from_f64(lambda_edges(u, alpha));
    }
    F::from_f64(lambda_cot(u / (alpha * ((1.0 - u) * (1.0 + u)).sqrt())))
}

/// Λ at u ∉ (0, 1] (out of line): +∞ at ±0, 0 past 1, Λ(|u|) below 0, NaN for NaN.
#[cold]
#[inline(never)]
fn lambda_edges(u: f64, alpha: f64) -> f64 {
    super::lambda_at_edge(u, |v| lambda(v, alpha))
}

/// Λ at a = cot θ/α ≥ 0, as e^{−a²} r(a)/(2a√π): r is a table with no cancellation anywhere
/// (the textbook (erf a − 1)/2 + e^{−a²}/(2a√π) loses ~2a² ulps and is 0 past a ≈ 6), so
/// the relative error is that of the exponential and the table, ~1e-15 (tests/fast.rs).
#[inline]
pub fn lambda_cot(a: f64) -> f64 {
    0.5 * (-a * a).exp() * erfc_ratio(a) / (SQRT_PI * a)
}

/// r(a) = 1 − √π a erfcx(a) for a ≥ 0: 1 − √π a + O(a²) below 2^−30, a table to 2^5, and
/// the asymptotic series 1/(2a²) − 3/(4a⁴) + 15/(8a⁶) − 105/(16a⁸) + 945/(32a¹⁰) beyond
/// (next term below 3e-13 of the sum at a = 32).
#[inline(always)]
pub fn erfc_ratio(a: f64) -> f64 {
    if a < super::fit::pow2(ERFC_RATIO_K0) {
        return 1.0 - SQRT_PI * a;
    }
    if a >= super::fit::pow2(ERFC_RATIO_K1) {
        let r = 1.0 / (a * a);
        return r * (0.5 - r * (0.75 - r * (15.0 / 8.0 - r * (105.0 / 16.0 - r * (945.0 / 32.0)))));
    }
    super::fit::eval(&ERFC_RATIO, ERFC_RATIO_K0, ERFC_RATIO_M, a)
}

/// erfcx(x) = e^{x²} erfc x for x ≥ 0: 1 − 2x/√π below 2^−30, a table (fit error 1e-16) to
/// 2^5, and (1 − 1/(2x²) + 3/(4x⁴) − 15/(8x⁶) + 105/(16x⁸))/(√π x) beyond (3e-14 at x = 32).
#[inline(always)]
pub fn erfcx(x: f64) -> f64 {
    if x < super::fit::pow2(ERFCX_K0) {
        return 1.0 - 2.0 * x / SQRT_PI;
    }
    if x >= super::fit::pow2(ERFCX_K1) {
        let r = 1.0 / (x * x);
        return (1.0 - r * (0.5 - r * (0.75 - r * (15.0 / 8.0 - r * (105.0 / 16.0)))))
            / (SQRT_PI * x);
    }
    super::fit::eval(&ERFCX, ERFCX_K0, ERFCX_M, x)
}

/// G1 = 1/(1 + Λ).
#[inline]
pub fn g1<F: Real>(u: F, alpha: F) -> F {
    F::ONE / (F::ONE + lambda(u, alpha))
}

/// Height-correlated G2 = 1/(1 + Λ(u_o) + Λ(u_i)).
#[inline]
pub fn g2<F: Real>(u_o: F, u_i: F, alpha: F) -> F {
    F::ONE / (F::ONE + lambda(u_o, alpha) + lambda(u_i, alpha))
}

/// σ(u) for u ∈ [−1, 1] (σ(0) = α/(2√π)), evaluated in f64.
#[inline]
pub fn sigma<F: Real>(u: F, alpha: F) -> F {
    let a = alpha.to_f64();
    F::from_f64(super::sigma_from_lambda(
        u.to_f64(),
        0.5 * a / super::SQRT_PI,
        |v| lambda(v, a),
    ))
}

/// √π
const SQRT_PI: f64 = super::SQRT_PI;
/// 1/√π
const FRAC_1_SQRT_PI: f64 = 0.564_189_583_547_756_3;

/// erfinv(v) for v ∈ [−1, 1] (±∞ at ±1, NaN for NaN or |v| > 1); relative error about 2e-16
/// (tests/fast.rs checks erf(erfinv v) = v).
#[inline]
pub fn erfinv(v: f64) -> f64 {
    let q = 1.0 - v.abs();
    if q.is_nan() || q <= 0.0 {
        return if q == 0.0 {
            v * f64::INFINITY
        } else {
            f64::NAN
        };
    }
    v * erfinv_ratio(q)
}

/// erfinv(2u − 1) for u ∈ [0, 1]: the quantile of N(0, 1/2). Takes q = 2 min(u, 1 − u)
/// exactly, so the lower tail keeps full relative accuracy down to u = 2^−1074 (where 2u − 1
/// would round to −1 below u ≈ 1e-17).
#[inline]
pub fn erfinv_2u_minus_1(u: f64) -> f64 {
    // Branch-free in the common case: u is as likely below 1/2 as above.
    let q = 2.0 * u.min(1.0 - u);
    if q.is_nan() || q <= 0.0 {
        // u = 0 or 1 (the ends of the distribution), or u outside [0, 1] or NaN.
        return if q == 0.0 {
            (u - 0.5).signum() * f64::INFINITY
        } else {
            f64::NAN
        };
    }
    ((1.0 - q) * erfinv_ratio(q)).copysign(u - 0.5)
}

/// erfinv(v)/v for |v| = 1 − q, from w = −ln(q(2 − q)) = −ln(1 − v²). Near v = 0 the
/// product rounds to 1 − v² within an ulp, an absolute error of ~1e-16 in w, and the ratio
/// changes by only (π/12)·(√π/2) per unit of w there, so no ln1p is needed.
#[inline(always)]
fn erfinv_ratio(q: f64) -> f64 {
    let w = -(q * (2.0 - q)).ln();
    // q ≥ 2^−1074 keeps w below 745, inside the table.
    debug_assert!(w < super::fit::pow2(ERFINV_K1));
    if w < super::fit::pow2(ERFINV_K0) {
        return 0.5 * SQRT_PI * (1.0 + std::f64::consts::PI / 12.0 * w);
    }
    super::fit::eval(&ERFINV, ERFINV_K0, ERFINV_M, w)
}

/// Visible slopes (x̃, ỹ) of the α = 1 Beckmann NDF for a direction in the xz-plane with
/// cot θ = a ≥ 0 (a = ∞ at normal incidence), from u ∈ [0, 1]²: the same warp as
/// [`crate::UnitSlopes::sample`]. u₁ is clamped to [0, 1 − 2^−53] and u₂ to
/// [2^−1075, 1 − 2^−53], so the slopes stay finite (|ỹ| ≤ 27.3, x̃ ≤ 8).
pub fn sample_visible11(a: f64, u: [f64; 2]) -> (f64, f64) {
    // Largest u below 1, and the smallest positive u: the ends of a finite slope.
    const ONE_BELOW: f64 = 1.0 - f64::EPSILON / 2.0;
    let u1 = u[0].clamp(0.0, ONE_BELOW);
    let u2 = u[1].clamp(f64::from_bits(1), ONE_BELOW);
    let y = erfinv_2u_minus_1(u2);
    if a.is_nan() || u1.is_nan() {
        return (f64::NAN, y);
    }
    let x = if a == f64::INFINITY {
        // Normal incidence: x̃ is Gaussian as well (u₁ = 0 is the lower end, −∞ → clamp).
        erfinv_2u_minus_1(u1.max(f64::from_bits(1)))
    } else {
        visible_x(a.max(0.0), u1)
    };
    (x, y)
}

/// Solves N(X) = u Z for X ∈ [−a, 8], a finite.
#[inline]
fn visible_x(a: f64, u: f64) -> f64 {
    let ea = (-a * a).exp();
    let erfc_a = erfcx(a) * ea;
    // Z = (a/2) erfc(−a) + e^{−a²}/(2√π).
    let half_ea = 0.5 * FRAC_1_SQRT_PI * ea;
    let z = 0.5 * a * (2.0 - erfc_a) + half_ea;
    let (target_lo, target_hi) = (u * z, (1.0 - u) * z);
    // X = 8 is past every quantile: (Z − N(8))/Z < 1e-28 < 1 − u.
    let (mut lo, mut hi) = (-a, 8.0f64);
    let mut x = guess(a, u).clamp(lo, hi);
    for _ in 0..64 {
        let e = (-x * x).exp();
        // erfc(|X|), from the e^{−X²} needed anyway.
        let ec = erfcx(x.abs()) * e;
        let half_e = 0.5 * FRAC_1_SQRT_PI * e;
        // F(X) = N(X) − uZ, from the side without cancellation.
        let f = if x <= 0.0 {
            0.5 * a * (ec - erfc_a) - (half_e - half_ea) - target_lo
        } else {
            target_hi - 0.5 * a * ec - half_e
        };
        if f < 0.0 {
            lo = x;
        } else if f > 0.0 {
            hi = x;
        } else {
            return x;
        }
        // F' = g₁E and F'' = g₂E with E = e^{−X²}/√π. Halley's step is the Newton step f/F'
        // over 1 − fF''/(2F'²); with E cancelled it takes one division. Far from the root,
        // where that correction exceeds 1/2, plain Newton (an underflowed E gives ±∞ or NaN,
        // which the bracket test below sends to bisection).
        let (g1, g2, big_e) = (x + a, 1.0 - 2.0 * x * (x + a), e * FRAC_1_SQRT_PI);
        let (fg2, g1e) = (f * g2, g1 * g1 * big_e);
        let step = if fg2.abs() < g1e {
            2.0 * f * g1 / (2.0 * g1e - fg2)
        } else {
            f / (g1 * big_e)
        };
        let next = x - step;
        // Converged: Halley is cubic, so once the step is 1e-7 of the density's length scale
        // (1/(1 + |X|), or the distance to the lower end −a) the error left is ~1e-21 of it.
        let size = step.abs();
        if size * (1.0 + x.abs()) <= 1e-7 && size <= 1e-7 * (x + a) {
            return next.clamp(-a, 8.0);
        }
        x = if next > lo && next < hi {
            next
        } else {
            0.5 * (lo + hi)
        };
        if hi - lo <= 4e-16 * hi.abs().max(lo.abs()) {
            break;
        }
    }
    x
}

/// Grid of the initial guess (`tables::BECKMANN_GUESS`): `GUESS_T` intervals in
/// t = 1/(1 + a), `GUESS_U` in u.
pub const GUESS_T: usize = 32;
/// See [`GUESS_T`].
pub const GUESS_U: usize = 128;

/// Bilinear interpolation of the inverse CDF over (t, u); the first and last u-intervals take
/// their inner node (the quantile is infinite at u = 1 and −a at u = 0).
#[inline(always)]
fn guess(a: f64, u: f64) -> f64 {
    let g = &BECKMANN_GUESS;
    let t = 1.0 / (1.0 + a);
    let ft = t * GUESS_T as f64;
    let it = (ft as usize).min(GUESS_T - 1);
    let wt = ft - it as f64;
    let fu = (u * GUESS_U as f64).clamp(1.0, (GUESS_U - 1) as f64);
    let iu = (fu as usize).min(GUESS_U - 2);
    let wu = fu - iu as f64;
    let row = GUESS_U + 1;
    let at = |i: usize, j: usize| g[i * row + j] as f64;
    let lo = at(it, iu) + wu * (at(it, iu + 1) - at(it, iu));
    let hi = at(it + 1, iu) + wu * (at(it + 1, iu + 1) - at(it + 1, iu));
    lo + wt * (hi - lo)
}

/// A normal distributed as D(m) cos θm, anisotropic roughness (αx, αy), u ∈ [0, 1]²:
/// tan²θ = −ln(1 − ξ) at unit roughness (ξ = u₀, by ln1p: exact for small ξ), azimuth 2πu₁,
/// then stretched; u₀ = 1 gives the horizon. A warp of u (the exact [`crate::Exact`] D·cos
/// sampler's, to rounding); evaluated in f64.
#[inline]
pub(crate) fn sample_dcos<F: Real>(ax: F, ay: F, u: [F; 2]) -> [F; 3] {
    let r = (-super::arith::ln_1p(-u[0].to_f64())).sqrt();
    let cs = super::cos_sin_turn(u[1].to_f64());
    super::normal_from_polar(r, cs, ax.to_f64(), ay.to_f64())
}

/// A visible normal for the unit direction w (mirrored if w.z < 0), anisotropic roughness
/// (αx, αy), u ∈ [0, 1]²: the warp of [`crate::Exact`]'s Beckmann `sample_visible`,
/// evaluated in f64 (f32 rounds once).
#[inline]
pub(crate) fn sample_visible<F: Real>(w: [F; 3], ax: F, ay: F, u: [F; 2]) -> [F; 3] {
    let (ax, ay) = (ax.to_f64(), ay.to_f64());
    let (c, h, cp, sp) = super::slope_frame(w, ax, ay);
    let a = if h == 0.0 { f64::INFINITY } else { c / h };
    let (x, y) = sample_visible11(a, [u[0].to_f64(), u[1].to_f64()]);
    super::facing(super::normal_from_slopes(x, y, (cp, sp), ax, ay), w)
}

/// A visible normal for v below the horizon (v.z < 0), not mirrored
/// ([`crate::MicrofacetDistribution::sample_wm_stream`]), anisotropic roughness (αx, αy), from the
/// uniforms of `uniform`. In the slope frame of v (stretched azimuth φ, a = |v.z|/h, h the
/// stretched horizontal length) the visible slopes of the α = 1 distribution have density
/// ∝ max(0, X − a) e^{−X²} e^{−Y²}: Y is N(0, ½) and X lies in the tail X > a, drawn by
/// rejection from one of two envelopes, whichever accepts more:
///
/// * a < 1/√2: the Rayleigh tail X = √(a² + E) (E ~ Exp(1), density ∝ X e^{−X²} on X > a),
///   kept with probability (X − a)/X; acceptance 1 − a√π erfcx(a) (1 at a = 0, 0.35 at
///   1/√2);
/// * a ≥ 1/√2: X = a + x with x ~ Gamma(2, 2a) (density ∝ x e^{−2ax}, the tail's
///   exponential factor), kept with probability e^{−x²}; acceptance 2a² times the other's
///   (0.35 at 1/√2, 0.87 at a = 3).
///
/// `None` at h = 0 (v straight down: no facet of the upper hemisphere faces it), after 64
/// candidates (acceptance ≥ 0.35: probability below 1e-12), or for a rounded normal with
/// v·m ≤ 0.
pub(crate) fn sample_visible_below<F: Real>(
    v: [F; 3],
    ax: F,
    ay: F,
    uniform: &mut dyn FnMut() -> F,
) -> Option<[F; 3]> {
    let (v, ax, ay, sx, sy, h) = super::stream_view(v, ax, ay);
    if !(v[2] < 0.0 && h > 0.0 && h.is_finite()) {
        return None;
    }
    let a = -v[2] / h;
    let mut next = || uniform().to_f64();
    let mut x = f64::NAN;
    for _ in 0..64 {
        if a < std::f64::consts::FRAC_1_SQRT_2 {
            let c = (a * a - next().ln()).sqrt();
            if next() * c <= c - a {
                x = c;
                break;
            }
        } else {
            let t = -(next() * next()).ln() / (2.0 * a);
            if next() <= (-t * t).exp() {
                x = a + t;
                break;
            }
        }
    }
    if x.is_nan() {
        return None;
    }
    let y = erfinv_2u_minus_1(next());
    super::stream_normal(super::normal_from_slopes(x, y, (sx / h, sy / h), ax, ay), v)
}

/// A visible normal for v above the horizon (v.z > 0) from a uniform stream
/// ([`crate::MicrofacetDistribution::sample_wm_stream`]; not a warp of two uniforms, as
/// [`sample_visible`] is, and about four times cheaper than its Halley inversion). In the
/// slope frame of v (a = v.z/h as [`sample_visible_below`]) the visible slope X has density
/// ∝ (X + a) e^{−X²} on X > −a and Y is N(0, ½). X by rejection from the envelope
/// X e^{−X²} on X ≥ 0 (mass ½: X = √(−ln U)) plus a e^{−X²} on the whole line (mass a√π:
/// X = ±Z/√2, Z half-normal by the ziggurat), which equals the density for X ≥ 0 and
/// exceeds it for X < 0, where the candidate is kept with probability (X + a)/a (0 below
/// −a); acceptance (½ + a√π/2 + ∫₋ₐ⁰(X + a)e^{−X²}dX)/(½ + a√π), 0.8 at a = 1 and above 0.75
/// everywhere. At normal incidence (h = 0) both slopes are N(0, ½). `None` after 64
/// candidates (probability below 1e-38) or for a rounded normal with v·m ≤ 0.
pub(crate) fn sample_visible_above<F: Real>(
    v: [F; 3],
    ax: F,
    ay: F,
    uniform: &mut dyn FnMut() -> F,
) -> Option<[F; 3]> {
    let (v, ax, ay, sx, sy, h) = super::stream_view(v, ax, ay);
    if !(v[2] > 0.0 && h.is_finite()) {
        return None;
    }
    let mut next = || uniform().to_f64();
    // ±Z/√2 from one uniform.
    let normal = |w: f64, next: &mut dyn FnMut() -> f64| {
        super::ziggurat::normal(w, &mut || next()) * std::f64::consts::FRAC_1_SQRT_2
    };
    let (frame, x) = if h == 0.0 {
        ((1.0, 0.0), normal(next(), &mut next))
    } else {
        let a = v[2] / h;
        // (a√π overflows only past 1e307: then the Rayleigh part is never drawn.)
        let p_ray = 0.5 / (0.5 + a * super::SQRT_PI);
        let mut x = f64::NAN;
        for _ in 0..64 {
            let w = next();
            if w < p_ray {
                x = (-next().ln()).sqrt();
                break;
            }
            let c = normal((w - p_ray) / (1.0 - p_ray), &mut next);
            if c >= 0.0 || (c > -a && next() * a < c + a) {
                x = c;
                break;
            }
        }
        ((sx / h, sy / h), x)
    };
    if x.is_nan() {
        return None;
    }
    let y = normal(next(), &mut next);
    super::stream_normal(super::normal_from_slopes(x, y, frame, ax, ay), v)
}
