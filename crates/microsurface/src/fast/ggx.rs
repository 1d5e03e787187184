//! GGX (Trowbridge–Reitz): the fast scalar D, Λ, G1, G2, σ and samplers, f32 and f64.

use super::Real;

/// D(u) = α²/(π ((1 − u²) + u²α²)²); 0 for u ≤ 0, D(1) for u > 1. 1 − u² is
/// (1 − u)(1 + u), exact enough that the near-normal peak keeps full relative accuracy in
/// f32.
#[inline]
pub fn d<F: Real>(u: F, alpha: F) -> F {
    // (False for NaN; one test for both edges, as the hot path had for u ≤ 0.)
    if !(u > F::ZERO && u <= F::ONE) {
        return d_edges(u, alpha);
    }
    let a2 = alpha * alpha;
    let t = (F::ONE - u) * (F::ONE + u) + u * u * a2;
    a2 / (F::PI * t * t)
}

/// D outside (0, 1] (out of line): 0 for u ≤ 0, D(1) for u > 1, NaN for NaN.
#[cold]
#[inline(never)]
fn d_edges<F: Real>(u: F, alpha: F) -> F {
    super::d_at_edge(u, |v| d(v, alpha))
}

/// Below this u (1e-290 in f64, 1e-30 in f32) u√(u² + t) of [`lambda`] could be
/// subnormal (√t ≥ 1e-6 for α ≥ 1e-6), and lose digits: [`lambda_tiny`] answers there.
#[inline(always)]
pub(crate) fn lambda_tiny_below<F: Real>() -> F {
    F::from_f64(if F::IS_F32 { 1e-30 } else { 1e-290 })
}

/// Λ(u) = s/(2(1 + √(1+s))), s = α² tan²θ, for 0 ≤ u ≤ 1 (−0 and 1 + 2ε included; +∞
/// at u = 0), written with u² multiplied through as α²(1−u²)/(2(u² + u√(u² + α²(1−u²)))):
/// one square root and one division, and no cancellation. Negative u gives Λ(|u|) (the
/// exact [`crate::Ndf::lambda`] has Heitz's extension there instead).
#[inline]
pub fn lambda<F: Real>(u: F, alpha: F) -> F {
    // One test sends every edge out of line: u below lambda_tiny_below (±0 included),
    // u > 1, negative u and NaN (false for it).
    if !(u >= lambda_tiny_below() && u <= F::ONE) {
        return lambda_tiny(u, alpha);
    }
    lambda_kernel(u, alpha)
}

/// [`lambda`]'s formula for lambda_tiny_below ≤ u ≤ 1 (the slice kernels' lanes).
#[inline(always)]
pub(crate) fn lambda_kernel<F: Real>(u: F, alpha: F) -> F {
    let t = alpha * alpha * ((F::ONE - u) * (F::ONE + u));
    let u2 = u * u;
    t / ((F::ONE + F::ONE) * (u2 + u * (u2 + t).sqrt()))
}

/// Λ at the edges (out of line): u below `lambda_tiny_below` (and ±0) as
/// (t/(u + √(u² + t)))/(2u), two divisions, so that no intermediate is subnormal; u > 1
/// as u = 1 and negative u as |u| (`cos_in`); NaN stays NaN.
#[cold]
#[inline(never)]
fn lambda_tiny<F: Real>(u: F, alpha: F) -> F {
    let u = super::cos_in(u);
    let t = alpha * alpha * ((F::ONE - u) * (F::ONE + u));
    t / (u + (u * u + t).sqrt()) / (u + u)
}

/// G1(u) = 2/(1 + √(1 + s)) = 2u/(u + √(u² + α²(1−u²))) for 0 ≤ u ≤ 1 (one square root,
/// one division); u > 1 is 1, negative u is |u|, and u below `lambda_tiny_below` takes
/// the edge path (G1 → 2u/(α√(1 − u²)) there: the closed form keeps full precision).
#[inline]
pub fn g1<F: Real>(u: F, alpha: F) -> F {
    if !(u >= F::ZERO && u <= F::ONE) {
        return g1_edges(u, alpha);
    }
    g1_kernel(u, alpha)
}

/// [`g1`]'s formula for 0 ≤ u ≤ 1 (the slice kernels' lanes).
#[inline(always)]
pub(crate) fn g1_kernel<F: Real>(u: F, alpha: F) -> F {
    let t = alpha * alpha * ((F::ONE - u) * (F::ONE + u));
    (u + u) / (u + (u * u + t).sqrt())
}

/// G1 at u ∉ [0, 1] (out of line): `cos_in`'s u, NaN for NaN.
#[cold]
#[inline(never)]
fn g1_edges<F: Real>(u: F, alpha: F) -> F {
    let u = super::cos_in(u);
    if u.to_f64().is_nan() {
        return u;
    }
    g1(u, alpha)
}

/// Height-correlated G2 = 1/(1 + Λ(u_o) + Λ(u_i)) = g_o g_i/(g_o + g_i − g_o g_i) from the
/// two G1 = g (one division besides theirs, as from two Λ), then capped by both, so that
/// G2 ≤ min(G1(u_o), G1(u_i)) holds in floating point (the two closed forms round
/// differently: uncapped, G2 exceeded G1 by an ulp at u_i = 1). The denominator in that
/// form has no cancellation at either end (written 1 − (1 − g_o)(1 − g_i), it lost g's
/// digits where both G1 are small: 2.7e-9 relative at u = 1e-8). Where g_o g_i is subnormal
/// or 0 the form divided through by the larger G1 (`g2_tiny`) keeps its digits.
#[inline]
pub fn g2<F: Real>(u_o: F, u_i: F, alpha: F) -> F {
    let (go, gi) = (g1(u_o, alpha), g1(u_i, alpha));
    let p = go * gi;
    let tiny = F::from_f64(if F::IS_F32 {
        f32::MIN_POSITIVE as f64
    } else {
        f64::MIN_POSITIVE
    });
    let g = if p >= tiny {
        p / (go + gi - p)
    } else {
        g2_tiny(go, gi)
    };
    g.min(go).min(gi)
}

/// G2 from two G1 whose product is subnormal or 0 (out of line): go gi/(go + gi − go gi)
/// divided through by the larger, b, as a/(a/b + 1 − a) (a/b ≤ 1 cannot overflow). The
/// product underflowed where both are tiny (1.5e-232 × 1.8e-107 at α = 18.14 gave G2 = 0
/// for 1.49e-232). 0 where b = 0 (grazing on both sides); NaN passes through.
#[cold]
#[inline(never)]
fn g2_tiny<F: Real>(go: F, gi: F) -> F {
    let (a, b) = if go < gi { (go, gi) } else { (gi, go) };
    if b > F::ZERO {
        a / (a / b + (F::ONE - a))
    } else {
        a * b
    }
}

/// σ(u) for u ∈ [−1, 1] (σ(0) = α/2), evaluated in f64.
#[inline]
pub fn sigma<F: Real>(u: F, alpha: F) -> F {
    let a = alpha.to_f64();
    F::from_f64(super::sigma_from_lambda(u.to_f64(), 0.5 * a, |v| {
        lambda(v, a)
    }))
}

/// A normal distributed as D(m) cos θm (Walter et al. 2007), anisotropic roughness
/// (αx, αy), u ∈ [0, 1]²: tan²θ = ξ/(1 − ξ) at unit roughness (ξ = u₀), azimuth 2πu₁, then
/// stretched; m ∝ (αx √ξ cos φ, αy √ξ sin φ, √(1 − ξ)), so u₀ = 1 gives the horizon
/// without a division. A warp of u (the exact [`crate::Exact`] D·cos sampler's, to
/// rounding); evaluated in f64.
#[inline]
pub(crate) fn sample_dcos<F: Real>(ax: F, ay: F, u: [F; 2]) -> [F; 3] {
    super::ggx_dcos(
        ax.to_f64(),
        ay.to_f64(),
        [u[0].to_f64(), u[1].to_f64()],
        1.0,
    )
}

/// A visible normal for the direction w (any length; mirrored if w.z < 0, as the exact
/// API does) by spherical caps (Dupuy & Benyoub 2023), anisotropic roughness (αx, αy);
/// `u` uniform in [0, 1)².
#[inline]
pub(crate) fn sample_visible<F: Real>(w: [F; 3], ax: F, ay: F, u: [F; 2]) -> [F; 3] {
    let w = if w[2] < F::ZERO {
        [-w[0], -w[1], -w[2]]
    } else {
        w
    };
    // The common case in one test, the edges out of line (one branch where the range test of
    // the stretched length and `facing` each had theirs: BENCHMARKS.md measures what each
    // cost).
    let (x, y, z) = (ax * w[0], ay * w[1], w[2]);
    let n2 = x * x + y * y + z * z;
    let m = super::ggx_visible_stretched_len(w, ax, ay, F::ONE, u, n2.sqrt());
    if super::plain_and_facing(n2, m, w) {
        return m;
    }
    sample_visible_edges(w, ax, ay, u)
}

/// [`sample_visible`] where the stretched length left its safe range (a direction far from
/// unit length, an extreme stretch, NaN) or m came out on or behind the plane perpendicular
/// to w (for w mirrored to w.z ≥ 0).
#[cold]
#[inline(never)]
fn sample_visible_edges<F: Real>(w: [F; 3], ax: F, ay: F, u: [F; 2]) -> [F; 3] {
    super::facing(super::ggx_visible_stretched(w, ax, ay, F::ONE, u), w)
}

/// A visible normal for v below the horizon, not mirrored
/// ([`crate::MicrofacetDistribution::sample_wm_stream`]): the same spherical cap, whose height
/// range [−z, 1] (z the stretched v's) is the cap above |z| when v points down: every
/// point of it gives m.z > 0 and v·m > 0. `None` for v.z ≥ 0, NaN, or a rounded normal
/// that fails those tests (the caller's rejection takes over).
#[inline]
// `!(x < 0)` is the NaN-aware test, on purpose.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
pub(crate) fn sample_visible_below<F: Real>(v: [F; 3], ax: F, ay: F, u: [F; 2]) -> Option<[F; 3]> {
    if !(v[2] < F::ZERO) {
        return None;
    }
    let m = super::ggx_visible_stretched(v, ax, ay, F::ONE, u);
    super::stream_normal(m, [v[0].to_f64(), v[1].to_f64(), v[2].to_f64()])
}
