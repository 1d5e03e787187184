//! Directions as `[F; 3]`: the shading frame, reflection, refraction, the generalised half
//! vectors and their Jacobians (pbrt-v4's conventions: every direction points away from the
//! surface, z is the shading normal, η = η_inside/η_outside, "inside" being z < 0).
//!
//! * Reflection: wi = −wo + 2(wo·wm)wm; the half vector is wm = (wo + wi)/|wo + wi| and
//!   |∂wm/∂wi| = 1/(4|wi·wm|) (Walter et al. 2007, eq. 14).
//! * Refraction (Walter et al. 2007, eqs. 16–17): with η' = η for wo above the surface and 1/η
//!   below, the generalised half vector is wm ∝ η' wi + wo, and
//!   |∂wm/∂wi| = |wi·wm| / (wi·wm + (wo·wm)/η')² (pbrt-v4's form, η' taken relative to wo).
//!
//! ```
//! use microsurface::bsdf::frame::{refract, reflect, Frame};
//! let frame = Frame::from_normal_tangent([0.0f32, 0.0, 1.0], [1.0, 0.0, 0.0]);
//! let wo = frame.to_local([0.6, 0.0, 0.8]);
//! let wi = reflect(wo, [0.0, 0.0, 1.0]);
//! assert_eq!(wi, [-0.6, 0.0, 0.8]);
//! let (wt, eta) = refract(wo, [0.0, 0.0, 1.0], 1.5).unwrap();
//! assert!(wt[2] < 0.0 && eta == 1.5);
//! ```

// `!(x > 0)` is the NaN-aware test (false for NaN) on a generic `Real`, on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::fast::Real;

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

/// A shading frame: orthonormal (s, t, n), z = n in local coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame<F> {
    /// The tangent (local x).
    pub s: [F; 3],
    /// The bitangent n × s (local y).
    pub t: [F; 3],
    /// The shading normal (local z).
    pub n: [F; 3],
}

impl<F: Real> Frame<F> {
    /// The frame of the normal n (normalised here) with a tangent chosen from n alone,
    /// branch-free but for the sign of n.z (Duff et al. 2017, "Building an orthonormal basis,
    /// revisited", JCGT 6(1)); the tangent jumps where n.z changes sign. A normal with no
    /// direction (zero, or NaN or infinite components) gives the all-NaN frame, which every
    /// BSDF evaluation through it then answers with NaN, never with a plausible value; a
    /// renderer that can meet one tests `frame.n[2].is_nan()` (a hit's normal is the caller's
    /// data, so this is documented rather than an `Err` on the hot path).
    pub fn from_normal(n: [F; 3]) -> Self {
        let n = normalize(n);
        let sign = if n[2] < F::ZERO { -F::ONE } else { F::ONE };
        let a = -F::ONE / (sign + n[2]);
        let b = n[0] * n[1] * a;
        Frame {
            s: [F::ONE + sign * n[0] * n[0] * a, sign * b, -sign * n[0]],
            t: [b, sign + n[1] * n[1] * a, -n[1]],
            n,
        }
    }

    /// The frame of the normal n and a tangent (both normalised here; the tangent is made
    /// orthogonal to n by Gram–Schmidt, twice, so that s·n is at rounding level). A tangent
    /// parallel to n (its part orthogonal to n within 64ε of the unit tangent's length: the
    /// rounding residue, not a direction) falls back to [`Frame::from_normal`]; anisotropic
    /// roughness αx runs along the tangent.
    pub fn from_normal_tangent(n: [F; 3], tangent: [F; 3]) -> Self {
        let n = normalize(n);
        let t = normalize(tangent);
        let r = add(t, scale(n, -dot(t, n)));
        let len = dot(r, r).sqrt();
        let eps = F::from_f64(if F::IS_F32 {
            f32::EPSILON as f64
        } else {
            f64::EPSILON
        });
        // (False for NaN: a NaN tangent falls back too.)
        if !(len > F::from_f64(64.0) * eps) {
            return Self::from_normal(n);
        }
        let s = scale(r, F::ONE / len);
        let s = normalize(add(s, scale(n, -dot(s, n))));
        Frame {
            s,
            t: cross(n, s),
            n,
        }
    }

    /// World (or object) coordinates to the local frame (z = n).
    #[inline(always)]
    pub fn to_local(&self, v: [F; 3]) -> [F; 3] {
        [dot(v, self.s), dot(v, self.t), dot(v, self.n)]
    }

    /// The local frame back to world coordinates.
    #[inline(always)]
    pub fn from_local(&self, v: [F; 3]) -> [F; 3] {
        add(
            add(scale(self.s, v[0]), scale(self.t, v[1])),
            scale(self.n, v[2]),
        )
    }
}

#[cfg(feature = "glam")]
mod glam_interop {
    use super::Frame;

    impl From<glam::Mat3> for Frame<f32> {
        /// Columns (s, t, n).
        fn from(m: glam::Mat3) -> Self {
            Frame {
                s: m.x_axis.to_array(),
                t: m.y_axis.to_array(),
                n: m.z_axis.to_array(),
            }
        }
    }

    impl From<Frame<f32>> for glam::Mat3 {
        /// Columns (s, t, n): `m * local` is the world vector.
        fn from(f: Frame<f32>) -> Self {
            glam::Mat3::from_cols(f.s.into(), f.t.into(), f.n.into())
        }
    }

    impl From<glam::DMat3> for Frame<f64> {
        fn from(m: glam::DMat3) -> Self {
            Frame {
                s: m.x_axis.to_array(),
                t: m.y_axis.to_array(),
                n: m.z_axis.to_array(),
            }
        }
    }

    impl From<Frame<f64>> for glam::DMat3 {
        fn from(f: Frame<f64>) -> Self {
            glam::DMat3::from_cols(f.s.into(), f.t.into(), f.n.into())
        }
    }
}

#[cfg(feature = "mint")]
mod mint_interop {
    use super::Frame;

    impl<F: Copy> From<mint::ColumnMatrix3<F>> for Frame<F> {
        /// Columns (s, t, n).
        fn from(m: mint::ColumnMatrix3<F>) -> Self {
            Frame {
                s: m.x.into(),
                t: m.y.into(),
                n: m.z.into(),
            }
        }
    }

    impl<F: Copy> From<Frame<F>> for mint::ColumnMatrix3<F> {
        fn from(f: Frame<F>) -> Self {
            mint::ColumnMatrix3 {
                x: f.s.into(),
                y: f.t.into(),
                z: f.n.into(),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_are_orthonormal_and_round_trip() {
        for n in [
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -1.0],
            [0.3, -0.4, 0.2],
            [1.0, 0.0, 0.0],
            [0.0, 1e-300, -1.0],
        ] {
            let f = Frame::from_normal(n);
            let g = Frame::from_normal_tangent(n, [0.2, 0.9, -0.1]);
            for fr in [f, g] {
                for (a, b, e) in [
                    (fr.s, fr.s, 1.0),
                    (fr.t, fr.t, 1.0),
                    (fr.n, fr.n, 1.0),
                    (fr.s, fr.t, 0.0),
                    (fr.s, fr.n, 0.0),
                    (fr.t, fr.n, 0.0),
                ] {
                    assert!((dot(a, b) - e).abs() < 1e-15, "{n:?} {fr:?}");
                }
                assert!((dot(cross(fr.s, fr.t), fr.n) - 1.0).abs() < 1e-15);
                let v = [0.1, -0.7, 0.3];
                let back = fr.from_local(fr.to_local(v));
                for k in 0..3 {
                    assert!((back[k] - v[k]).abs() < 1e-15);
                }
            }
        }
    }

    #[test]
    fn refraction_obeys_snell_and_reverses() {
        let n = [0.0, 0.0, 1.0];
        for (wo, eta) in [
            ([0.6, 0.0, 0.8], 1.5),
            ([0.3, 0.4, 0.866], 1.0 / 1.5),
            ([0.1, -0.2, -0.97], 1.33),
        ] {
            let wo = normalize(wo);
            let Some((wt, etap)) = refract(wo, n, eta) else {
                panic!("{wo:?}")
            };
            let sin_o = (wo[0] * wo[0] + wo[1] * wo[1]).sqrt();
            let sin_t = (wt[0] * wt[0] + wt[1] * wt[1]).sqrt();
            assert!((sin_o - etap * sin_t).abs() < 1e-15);
            assert!(wt[2] * wo[2] < 0.0 && (dot(wt, wt) - 1.0).abs() < 1e-15);
            // Back through the same interface.
            let (back, _) = refract(wt, n, eta).unwrap();
            for k in 0..3 {
                assert!((back[k] - wo[k]).abs() < 1e-15);
            }
            // The generalised half vector of the pair is the normal.
            let (wm, _) = half_vector_refraction(wo, wt, eta).unwrap();
            assert!((wm[2] - 1.0).abs() < 1e-15, "{wm:?}");
        }
        // Total internal reflection from inside glass past the critical angle.
        assert!(refract([0.8, 0.0, -0.6], n, 1.5).is_none());
        assert!(refract([f64::NAN, 0.0, 1.0], n, 1.5).is_none());
    }

    #[test]
    fn jacobians_match_finite_differences() {
        // Solid-angle ratio of a small cone of wi mapped to wm, by a finite-difference
        // parallelogram, against the closed forms.
        let wo = normalize([0.4, 0.1, 0.9]);
        for (wi, eta) in [
            (normalize([-0.5, 0.2, 0.84]), None),
            (normalize([-0.3, 0.1, -0.95]), Some(1.5)),
            (normalize([-0.3, 0.1, -0.95]), Some(1.0 / 1.3)),
        ] {
            let h = |wi: [f64; 3]| match eta {
                None => half_vector_reflection(wo, wi).unwrap(),
                Some(e) => half_vector_refraction(wo, wi, e).unwrap().0,
            };
            let fr = Frame::from_normal(wi);
            let e = 1e-6;
            let a = normalize(fr.from_local([e, 0.0, 1.0]));
            let b = normalize(fr.from_local([0.0, e, 1.0]));
            let (h0, ha, hb) = (h(wi), h(a), h(b));
            let da = [ha[0] - h0[0], ha[1] - h0[1], ha[2] - h0[2]];
            let db = [hb[0] - h0[0], hb[1] - h0[1], hb[2] - h0[2]];
            let c = cross(da, db);
            let ratio = dot(c, c).sqrt() / (e * e);
            let jac = match eta {
                None => jacobian_reflection(wi, h0),
                Some(e) => {
                    let (_, etap) = half_vector_refraction(wo, wi, e).unwrap();
                    jacobian_refraction(wo, wi, h0, etap)
                }
            };
            assert!((ratio / jac - 1.0).abs() < 1e-4, "{ratio} {jac}");
        }
    }
}
