//! Directions as `[F; 3]`: dot and cross products, normalisation at any length, reflection,
//! refraction, the generalised half vectors and their Jacobians (the formulas and sources:
//! [`crate::bsdf::frame`], which re-exports the public ones). Here, below every folder that
//! uses them, so that the NDFs' directional forms need not import the BSDFs.

// `!(x > 0)` is the NaN-aware test (false for NaN) on a generic `Real`, on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::math::real::Real;

/// a·b.
#[inline(always)]
pub fn dot<F: Real>(a: [F; 3], b: [F; 3]) -> F {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// a + b.
#[inline(always)]
pub(crate) fn add<F: Real>(a: [F; 3], b: [F; 3]) -> [F; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// s a.
#[inline(always)]
pub(crate) fn scale<F: Real>(a: [F; 3], s: F) -> [F; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// −a.
#[inline(always)]
pub(crate) fn neg<F: Real>(a: [F; 3]) -> [F; 3] {
    [-a[0], -a[1], -a[2]]
}

/// a × b.
#[inline(always)]
pub fn cross<F: Real>(a: [F; 3], b: [F; 3]) -> [F; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// a/|a|; NaN for a zero or non-finite vector (not a direction), and without overflow or
/// underflow for any finite length (the vector is rescaled by its largest component first
/// where |a|² would leave the normal range).
#[inline]
pub fn normalize<F: Real>(a: [F; 3]) -> [F; 3] {
    let n2 = dot(a, a);
    // 1e±30 in f32 (1e±280 in f64): squares of the components keep full precision.
    let (lo, hi) = if F::IS_F32 {
        (1e-30, 1e30)
    } else {
        (1e-280, 1e280)
    };
    if !(n2 >= F::from_f64(lo) && n2 <= F::from_f64(hi)) {
        return normalize_scaled(a);
    }
    scale(a, F::ONE / n2.sqrt())
}

/// [`normalize`] far from unit length (out of line).
#[cold]
#[inline(never)]
fn normalize_scaled<F: Real>(a: [F; 3]) -> [F; 3] {
    let w = [a[0].to_f64(), a[1].to_f64(), a[2].to_f64()];
    let m = w[0].abs().max(w[1].abs()).max(w[2].abs());
    if !(m > 0.0 && m.is_finite()) {
        return [F::from_f64(f64::NAN); 3];
    }
    let w = [w[0] / m, w[1] / m, w[2] / m];
    let inv = 1.0 / (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
    [
        F::from_f64(w[0] * inv),
        F::from_f64(w[1] * inv),
        F::from_f64(w[2] * inv),
    ]
}

/// Whether a and b lie on the same side of the surface (a.z b.z > 0).
#[inline(always)]
pub fn same_hemisphere<F: Real>(a: [F; 3], b: [F; 3]) -> bool {
    a[2] * b[2] > F::ZERO
}

/// A cosine-weighted direction about +z from u ∈ [0, 1)² (Malley's method: a uniform point
/// of the unit disk, r = √u₀, φ = 2πu₁, lifted to the hemisphere); density cos θ/π.
#[inline]
pub(crate) fn cosine_hemisphere(u: [f64; 2]) -> [f64; 3] {
    let r = u[0].sqrt();
    let (s, c) = (std::f64::consts::TAU * u[1]).sin_cos();
    [r * c, r * s, (1.0 - u[0]).max(0.0).sqrt()]
}

/// The reflection of wo about the unit normal n: −wo + 2(wo·n)n.
#[inline(always)]
pub fn reflect<F: Real>(wo: [F; 3], n: [F; 3]) -> [F; 3] {
    let d = dot(wo, n);
    [
        (d + d) * n[0] - wo[0],
        (d + d) * n[1] - wo[1],
        (d + d) * n[2] - wo[2],
    ]
}

/// The refraction of wi through the unit normal n with relative index η = η_t/η_i for wi on
/// n's side (Snell's law, pbrt-v4's `Refract`): where wi lies on the other side (wi·n < 0),
/// the interface is seen from inside, η becomes 1/η and n is flipped. Returns the transmitted
/// direction (unit for unit input) and the η' used, or `None` at total internal reflection
/// (sin²θt ≥ 1) and for NaN input.
///
/// wt = −t/η' − cos θt n with t = wi − (wi·n) n, wi's part along the interface (projected
/// twice, so that t·n is at the rounding of t, not of 1): sin²θi = |t|² and
/// |wt|² = sin²θt + cos²θt = 1 to rounding for every η'. (pbrt's 1 − cos²θi and
/// −wi/η' + (cos θi/η' − cos θt) n lose the digits of sin θi near normal incidence, which a
/// small η' magnifies: η' = 1e-6 gave |wt| = 0.99989, and one projection 1 + 2e-10.)
#[inline]
pub fn refract<F: Real>(wi: [F; 3], n: [F; 3], eta: F) -> Option<([F; 3], F)> {
    let mut cos_i = dot(n, wi);
    // (max below would turn a NaN into 0.)
    if cos_i.to_f64().is_nan() {
        return None;
    }
    let (mut eta, mut n) = (eta, n);
    if cos_i < F::ZERO {
        eta = F::ONE / eta;
        cos_i = -cos_i;
        n = neg(n);
    }
    let t = add(wi, scale(n, -cos_i));
    let t = add(t, scale(n, -dot(t, n)));
    let sin2_t = dot(t, t) / (eta * eta);
    // (False for NaN: no direction.)
    if !(sin2_t < F::ONE) {
        return None;
    }
    let cos_t = (F::ONE - sin2_t).sqrt();
    let wt = add(scale(t, -F::ONE / eta), scale(n, -cos_t));
    Some((wt, eta))
}

/// The half vector of a reflection, wm = (wo + wi)/|wo + wi|, turned to the upper hemisphere
/// (wm.z ≥ 0); `None` where wo + wi = 0 (no half vector) or is not finite.
#[inline]
pub fn half_vector_reflection<F: Real>(wo: [F; 3], wi: [F; 3]) -> Option<[F; 3]> {
    up(add(wo, wi))
}

/// The generalised half vector of a refraction with relative index η (η_inside/η_outside),
/// wm ∝ η' wi + wo with η' = η for wo above the surface (wo.z > 0) and 1/η below, turned to
/// the upper hemisphere; `None` where it vanishes (wi = −wo at η' = 1) or is not finite.
/// Returns (wm, η').
#[inline]
pub fn half_vector_refraction<F: Real>(wo: [F; 3], wi: [F; 3], eta: F) -> Option<([F; 3], F)> {
    let etap = if wo[2] > F::ZERO { eta } else { F::ONE / eta };
    up(refraction_sum(wo, wi, etap)).map(|wm| (wm, etap))
}

/// η' wi + wo, formed as (wo + wi) + (η' − 1) wi. For unit wo, wi its length is at least
/// |η' − 1|, so neither term exceeds twice the result and the sum is accurate to a few ulp of
/// its own length, also where it nearly vanishes (η' → 1 with wi → −wo). The plain form
/// keeps only the rounding of η' wi there, an ulp of 1: at η' = 1 + 2⁻⁵² that is the size
/// of the result, whose direction (the half vector) then came out arbitrary and whose
/// projection on it (the Jacobian's denominator) came out 0.
#[inline(always)]
fn refraction_sum<F: Real>(wo: [F; 3], wi: [F; 3], etap: F) -> [F; 3] {
    add(add(wo, wi), scale(wi, etap - F::ONE))
}

/// wi·wm + (wo·wm)/η' = (η' wi + wo)·wm/η', the denominator of the refraction's Jacobian and
/// BSDF (Walter et al. 2007, eqs. 17 and 21), from [`refraction_sum`]: the two dot products
/// cancel (to 0 at η' = 1 + 2⁻⁵², wi ≈ −wo), the projection of the accurate sum does not.
#[inline(always)]
pub(crate) fn refraction_denominator<F: Real>(wo: [F; 3], wi: [F; 3], wm: [F; 3], etap: F) -> F {
    dot(refraction_sum(wo, wi, etap), wm) / etap
}

/// v normalised and turned to z ≥ 0; `None` for a zero or non-finite v.
#[inline(always)]
fn up<F: Real>(v: [F; 3]) -> Option<[F; 3]> {
    let m = normalize(v);
    // (False for NaN.)
    if m[2].to_f64().is_nan() {
        return None;
    }
    Some(if m[2] < F::ZERO { neg(m) } else { m })
}

/// |∂wm/∂wi| of the reflection half vector: 1/(4|wi·wm|) (∞ where wi·wm = 0).
#[inline(always)]
pub fn jacobian_reflection<F: Real>(wi: [F; 3], wm: [F; 3]) -> F {
    F::ONE / (F::from_f64(4.0) * dot(wi, wm).abs())
}

/// |∂wm/∂wi| of the refraction half vector wm ∝ η' wi + wo: |wi·wm|/(wi·wm + (wo·wm)/η')²
/// (Walter et al. 2007, eq. 17, with η' relative to wo as in
/// [`half_vector_refraction`]).
#[inline(always)]
pub fn jacobian_refraction<F: Real>(wo: [F; 3], wi: [F; 3], wm: [F; 3], etap: F) -> F {
    let s = refraction_denominator(wo, wi, wm, etap);
    dot(wi, wm).abs() / (s * s)
}
