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

use crate::math::real::Real;

pub(crate) use crate::math::dirs::{add, cosine_hemisphere, refraction_denominator, scale};
pub use crate::math::dirs::{
    cross, dot, half_vector_reflection, half_vector_refraction, jacobian_reflection,
    jacobian_refraction, normalize, reflect, refract, same_hemisphere,
};

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
