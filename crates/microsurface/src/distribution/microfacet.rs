//! [`Microfacet<F, N>`](Microfacet), the static renderer type, and the per-NDF kernels
//! behind it ([`Shape`]): see the [`crate::distribution`] docs.

// `!(x > 0)` is the NaN-aware test (false for NaN) on a generic `Real`, on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::exact::{Exact, ExactInner};
use super::kernels::Isotropic;
use super::{shared_fit, Fit, MicrofacetDistribution, Sample, SharedFits, UniformStream};
use crate::fast::{self, Real};
use crate::math::dirs::{dot, normalize};
use crate::sampling::visible::UnitSlopes;
use crate::{Beckmann, DoubleGgx, Exponential, Ggx, Gtr, ParamError};
use std::cell::Cell;
use std::marker::PhantomData;
use std::sync::OnceLock;

mod sealed {
    pub trait Sealed {}
    impl Sealed for crate::Ggx {}
    impl Sealed for crate::Beckmann {}
    impl Sealed for crate::DoubleGgx {}
    impl Sealed for crate::Exponential {}
    impl Sealed for crate::Gtr {}
    impl Sealed for crate::StudentT {}
    impl Sealed for crate::Ei {}
    impl Sealed for crate::Erfc {}
    impl Sealed for crate::K0 {}
    impl Sealed for crate::BesselK {}
}

/// An NDF that [`Microfacet`] can run: the exact NDF types name it. Implemented for
/// [`Ggx`], [`Beckmann`], [`DoubleGgx`], [`Exponential`] and [`Gtr`], and for the family's
/// Beckmann mixtures [`crate::StudentT`], [`crate::Ei`], [`crate::Erfc`], [`crate::K0`] and
/// [`crate::BesselK`] (built by [`Microfacet::with_shape`]); sealed.
pub trait Shape: sealed::Sealed + Sized {
    /// What a material of this NDF holds beyond (αx, αy): nothing, or GTR's fitted tables.
    #[doc(hidden)]
    type Data: Clone + std::fmt::Debug + Send + Sync;
    /// Which exact α = 1 slope distribution it is (None: GTR and the family).
    #[doc(hidden)]
    const UNIT: Option<UnitSlopes>;
    /// The family member it is (its exact path is [`Exact::new`]'s).
    #[doc(hidden)]
    const FAMILY: Option<crate::NdfKind> = None;
    /// D(u) at isotropic roughness α (the fast scalar path).
    #[doc(hidden)]
    fn d_iso<F: Real>(data: &Self::Data, u: F, alpha: F) -> F;
    /// Λ(u) at isotropic roughness α (the fast scalar path).
    #[doc(hidden)]
    fn lambda_iso<F: Real>(data: &Self::Data, u: F, alpha: F) -> F;
    /// D for the unit normal wm at (αx, αy), αx ≠ αy: the isotropic D at the projected
    /// roughness α̃² = (x² + y²)/(x²/αx² + y²/αy²), times α̃²/(αx αy).
    #[doc(hidden)]
    #[inline]
    fn d_aniso<F: Real>(data: &Self::Data, wm: [F; 3], ax: F, ay: F) -> F {
        d_projected::<Self, F>(data, wm, ax, ay)
    }
    /// Λ for the unit direction w at (αx, αy), αx ≠ αy: the isotropic Λ at the projected
    /// roughness α̃² = (αx²x² + αy²y²)/(x² + y²).
    #[doc(hidden)]
    #[inline]
    fn lambda_aniso<F: Real>(data: &Self::Data, w: [F; 3], ax: F, ay: F) -> F {
        lambda_projected::<Self, F>(data, w, ax, ay)
    }
    /// D(wm) of a material: the fast scalar D of u = wm.z where isotropic, else
    /// [`Shape::d_aniso`] (overridden where a direct vector form is as cheap and better
    /// conditioned).
    #[doc(hidden)]
    #[inline(always)]
    fn d<F: Real>(data: &Self::Data, wm: [F; 3], ax: F, ay: F, iso: bool) -> F {
        if iso {
            Self::d_iso(data, wm[2], ax)
        } else {
            Self::d_aniso(data, wm, ax, ay)
        }
    }
    /// Λ(w) of a material (as [`Shape::d`]).
    #[doc(hidden)]
    #[inline(always)]
    fn lambda<F: Real>(data: &Self::Data, w: [F; 3], ax: F, ay: F, iso: bool) -> F {
        if iso {
            Self::lambda_iso(data, w[2].abs(), ax)
        } else {
            Self::lambda_aniso(data, w, ax, ay)
        }
    }
    /// G1(w) = 1/(1 + Λ(w)) of a material (overridden where a closed form is cheaper).
    #[doc(hidden)]
    #[inline(always)]
    fn g1<F: Real>(data: &Self::Data, w: [F; 3], ax: F, ay: F, iso: bool) -> F {
        F::ONE / (F::ONE + Self::lambda(data, w, ax, ay, iso))
    }
    /// The visible density D_w(wm) of a material: from [`Shape::d`] and [`Shape::g1`]
    /// (overridden where a closed form is cheaper).
    #[doc(hidden)]
    #[inline(always)]
    fn d_visible<F: Real>(data: &Self::Data, w: [F; 3], wm: [F; 3], ax: F, ay: F, iso: bool) -> F {
        super::d_visible_with(
            w,
            wm,
            || Self::d(data, wm, ax, ay, iso),
            || Self::g1(data, w, ax, ay, iso),
        )
    }
    /// The visible-normal sampler at (αx, αy).
    #[doc(hidden)]
    fn sample_wm<F: Real>(data: &Self::Data, w: [F; 3], ax: F, ay: F, u: [F; 2]) -> [F; 3];
    /// [`MicrofacetDistribution::sample_wm_stream`] at (αx, αy).
    #[doc(hidden)]
    #[inline(always)]
    fn sample_wm_stream<F: Real>(
        data: &Self::Data,
        v: [F; 3],
        ax: F,
        ay: F,
        uniform: &mut dyn FnMut() -> F,
    ) -> Option<[F; 3]> {
        let _ = (data, v, ax, ay, uniform);
        None
    }
    /// The D·cos sampler at (αx, αy).
    #[doc(hidden)]
    fn sample_dcos<F: Real>(data: &Self::Data, ax: F, ay: F, u: [F; 2]) -> [F; 3];
}

/// D for the unit normal wm at (αx, αy), αx ≠ αy, by the projected roughness: the
/// isotropic D at α̃² = (x² + y²)/(x²/αx² + y²/αy²), times α̃²/(αx αy). (Every
/// shape-invariant D is P22₁(slope/α)/(α² cos⁴θ), and the anisotropic one reads P22₁ at the
/// stretched slope, whose length is the isotropic one's at α̃.)
#[inline]
fn d_projected<S: Shape, F: Real>(data: &S::Data, wm: [F; 3], ax: F, ay: F) -> F {
    let (x, y, z) = (wm[0], wm[1], wm[2]);
    let s2 = x * x + y * y;
    let r2 = x * x / (ax * ax) + y * y / (ay * ay);
    if !(r2 > F::ZERO) {
        // At the normal (or NaN): the density there is P22₁(0)/(αx αy).
        return S::d_iso(data, z, ax) * (ax / ay);
    }
    let a2 = s2 / r2;
    S::d_iso(data, z, a2.sqrt()) * (a2 / (ax * ay))
}

/// Λ for the unit direction w at (αx, αy), αx ≠ αy, by the projected roughness: the
/// isotropic Λ at α̃² = (αx²x² + αy²y²)/(x² + y²).
#[inline]
fn lambda_projected<S: Shape, F: Real>(data: &S::Data, w: [F; 3], ax: F, ay: F) -> F {
    let (x, y) = (w[0], w[1]);
    let s2 = x * x + y * y;
    if !(s2 > F::ZERO) {
        return S::lambda_iso(data, w[2], ax);
    }
    let a2 = (ax * ax * x * x + ay * ay * y * y) / s2;
    S::lambda_iso(data, w[2], a2.sqrt())
}

/// A normal's (z, 1/(αx αy), (x/αx)² + (y/αy)²) in f64 (x/αx = x αy/(αx αy): one
/// division), for the fitted NDFs' anisotropic D.
#[inline(always)]
fn stretched_normal<F: Real>(wm: [F; 3], ax: F, ay: F) -> (f64, f64, f64) {
    let (a, b) = (ax.to_f64(), ay.to_f64());
    let r = 1.0 / (a * b);
    let (x, y) = (wm[0].to_f64() * b * r, wm[1].to_f64() * a * r);
    (wm[2].to_f64(), r, x * x + y * y)
}

/// The projected route out of line: the anisotropic fitted paths' ends (outside their
/// tables: near the normal, grazing, below the horizon, NaN).
#[cold]
#[inline(never)]
fn d_projected_cold<S: Shape, F: Real>(data: &S::Data, wm: [F; 3], ax: F, ay: F) -> F {
    d_projected::<S, F>(data, wm, ax, ay)
}

/// See [`d_projected_cold`].
#[cold]
#[inline(never)]
fn lambda_projected_cold<S: Shape, F: Real>(data: &S::Data, w: [F; 3], ax: F, ay: F) -> F {
    lambda_projected::<S, F>(data, w, ax, ay)
}

impl Shape for Ggx {
    type Data = ();
    const UNIT: Option<UnitSlopes> = Some(UnitSlopes::Ggx);
    #[inline(always)]
    fn d_iso<F: Real>(_: &(), u: F, alpha: F) -> F {
        fast::ggx::d(u, alpha)
    }
    #[inline(always)]
    fn lambda_iso<F: Real>(_: &(), u: F, alpha: F) -> F {
        fast::ggx::lambda(u, alpha)
    }
    #[inline(always)]
    fn d_aniso<F: Real>(_: &(), wm: [F; 3], ax: F, ay: F) -> F {
        ggx_d_aniso(wm, ax, ay)
    }
    #[inline(always)]
    fn lambda_aniso<F: Real>(_: &(), w: [F; 3], ax: F, ay: F) -> F {
        ggx_lambda_aniso(w, ax, ay)
    }
    /// The vector form for isotropic materials too: x² + y² where the scalar path has
    /// 1 − z², which near normal incidence has lost the digits of the rounded unit vector.
    #[inline(always)]
    fn d<F: Real>(_: &(), wm: [F; 3], ax: F, ay: F, _iso: bool) -> F {
        ggx_d_aniso(wm, ax, ay)
    }
    #[inline(always)]
    fn lambda<F: Real>(_: &(), w: [F; 3], ax: F, ay: F, _iso: bool) -> F {
        ggx_lambda_aniso(w, ax, ay)
    }
    #[inline(always)]
    fn g1<F: Real>(_: &(), w: [F; 3], ax: F, ay: F, _iso: bool) -> F {
        ggx_g1(w, ax, ay)
    }
    #[inline(always)]
    fn d_visible<F: Real>(_: &(), w: [F; 3], wm: [F; 3], ax: F, ay: F, _iso: bool) -> F {
        ggx_d_visible(w, wm, ax, ay)
    }
    #[inline(always)]
    fn sample_wm<F: Real>(_: &(), w: [F; 3], ax: F, ay: F, u: [F; 2]) -> [F; 3] {
        fast::ggx::sample_visible(w, ax, ay, u)
    }
    #[inline(always)]
    fn sample_wm_stream<F: Real>(
        _: &(),
        v: [F; 3],
        ax: F,
        ay: F,
        uniform: &mut dyn FnMut() -> F,
    ) -> Option<[F; 3]> {
        let u = [uniform(), uniform()];
        if v[2] > F::ZERO {
            Some(fast::ggx::sample_visible(v, ax, ay, u))
        } else {
            fast::ggx::sample_visible_below(v, ax, ay, u)
        }
    }
    #[inline(always)]
    fn sample_dcos<F: Real>(_: &(), ax: F, ay: F, u: [F; 2]) -> [F; 3] {
        fast::ggx::sample_dcos(ax, ay, u)
    }
}

/// GGX's anisotropic D = 1/(π αx αy (x²/αx² + y²/αy² + z²)²) for a unit wm (pbrt-v4's form,
/// without its tan²θ: no division by cos⁴θ); 0 below the horizon.
#[inline(always)]
fn ggx_d_aniso<F: Real>(wm: [F; 3], ax: F, ay: F) -> F {
    let z = wm[2];
    if !(z > F::ZERO) {
        return if z.to_f64().is_nan() { z } else { F::ZERO };
    }
    let (x, y) = (wm[0] / ax, wm[1] / ay);
    let t = x * x + y * y + z * z;
    F::ONE / (F::PI * ax * ay * t * t)
}

/// GGX's visible density with one division besides the slopes' two: with G1(w) = 2|w.z|/(|w.z| + ℓ), ℓ the length of
/// (αx w.x, αy w.y, w.z), and D(m) = 1/(π αx αy t²), t = (m.x/αx)² + (m.y/αy)² + m.z²,
///
///   D_w(m) = G1 (w·m) D/|w.z| = 2 (w·m)/(π αx αy t² (|w.z| + ℓ))
///
/// (the 1/|w.z| cancels: nothing grows toward the horizon; any length of w), where D, G1 and
/// their product apart cost three. The mirror image for w.z < 0; 0 at grazing w, for m on or
/// behind the plane perpendicular to w, and for m below the horizon.
#[inline(always)]
fn ggx_d_visible<F: Real>(w: [F; 3], wm: [F; 3], ax: F, ay: F) -> F {
    let z = w[2].abs();
    let c = if w[2] < F::ZERO {
        -dot(w, wm)
    } else {
        dot(w, wm)
    };
    // (False for NaN.)
    if !(c > F::ZERO && z > F::ZERO && wm[2] > F::ZERO) {
        return if c.to_f64().is_nan() { c } else { F::ZERO };
    }
    let (sx, sy) = (ax * w[0], ay * w[1]);
    let len = (sx * sx + sy * sy + z * z).sqrt();
    let (mx, my) = (wm[0] / ax, wm[1] / ay);
    let t = mx * mx + my * my + wm[2] * wm[2];
    (c + c) / (F::PI * ax * ay * t * t * (z + len))
}

/// GGX's G1 = 1/(1 + Λ) = 2|z|/(|z| + √(z² + t)), t = αx²x² + αy²y²: one division (0 at
/// z = 0; no overflow, as |z| + √(z² + t) ≥ |z|).
#[inline(always)]
fn ggx_g1<F: Real>(w: [F; 3], ax: F, ay: F) -> F {
    let (x, y, z) = (ax * w[0], ay * w[1], w[2].abs());
    let den = z + (z * z + (x * x + y * y)).sqrt();
    if !(den > F::ZERO) {
        // w = 0 (or its components underflow once scaled): as Λ, G1 = 0; NaN stays NaN.
        return if den.to_f64().is_nan() { den } else { F::ZERO };
    }
    (z + z) / den
}

/// GGX's anisotropic Λ = s/(2(1 + √(1 + s))), s = (αx²x² + αy²y²)/z², multiplied through by
/// z² as t/(2(z² + |z|√(z² + t))), t = αx²x² + αy²y² (no cancellation, one square root and
/// one division; +∞ at z = 0).
#[inline(always)]
fn ggx_lambda_aniso<F: Real>(w: [F; 3], ax: F, ay: F) -> F {
    let (x, y, z) = (ax * w[0], ay * w[1], w[2].abs());
    let t = x * x + y * y;
    let z2 = z * z;
    let den = (F::ONE + F::ONE) * (z2 + z * (z2 + t).sqrt());
    if !(den > F::ZERO) {
        // Grazing (z = 0, or z² subnormal-small), or NaN.
        return ggx_lambda_aniso_edge(w, ax, ay);
    }
    t / den
}

/// [`ggx_lambda_aniso`] where z² may underflow (out of line): in f64, two divisions.
#[cold]
#[inline(never)]
fn ggx_lambda_aniso_edge<F: Real>(w: [F; 3], ax: F, ay: F) -> F {
    let (x, y, z) = (
        ax.to_f64() * w[0].to_f64(),
        ay.to_f64() * w[1].to_f64(),
        w[2].to_f64().abs(),
    );
    if z == 0.0 {
        return F::from_f64(f64::INFINITY);
    }
    let t = x * x + y * y;
    F::from_f64(t / (z + (z * z + t).sqrt()) / (z + z))
}

impl Shape for Beckmann {
    type Data = ();
    const UNIT: Option<UnitSlopes> = Some(UnitSlopes::Beckmann);
    #[inline(always)]
    fn d_iso<F: Real>(_: &(), u: F, alpha: F) -> F {
        fast::beckmann::d(u, alpha)
    }
    #[inline(always)]
    fn lambda_iso<F: Real>(_: &(), u: F, alpha: F) -> F {
        fast::beckmann::lambda(u, alpha)
    }
    /// The vector form for isotropic materials too (as [`Ggx`]'s): x² + y² where the scalar
    /// path has 1 − z², which near the normal has lost the digits of a rounded unit vector.
    #[inline(always)]
    fn d<F: Real>(data: &(), wm: [F; 3], ax: F, ay: F, _iso: bool) -> F {
        Self::d_aniso(data, wm, ax, ay)
    }
    /// D = e^{−y}/(π αx αy z⁴), y = ((x/αx)² + (y/αy)²)/z², from the normal directly; the
    /// ends (below the horizon, f32 past y = 80 where the scalar path widens, underflow) by
    /// the projected route, out of line.
    #[inline(always)]
    fn d_aniso<F: Real>(data: &(), wm: [F; 3], ax: F, ay: F) -> F {
        let z = wm[2];
        let r = F::ONE / (ax * ay);
        let (x, y) = (wm[0] * ay * r, wm[1] * ax * r);
        let z2 = z * z;
        let e = (x * x + y * y) / z2;
        // (False for NaN, z ≤ 0 and z² = 0; see fast::beckmann::d for the f32 bound.)
        let limit = if F::IS_F32 {
            F::from_f64(80.0)
        } else {
            F::EXP_ZERO
        };
        if !(z > F::ZERO && e <= limit && z2 > F::ZERO) {
            return d_projected_cold::<Self, F>(data, wm, ax, ay);
        }
        (-e).exp() * r / (F::PI * z2 * z2)
    }
    /// Isotropic or not, Λ at cot θ̃ = |z|/√(αx²x² + αy²y²) (as [`Ggx`]'s vector forms).
    #[inline(always)]
    fn lambda<F: Real>(data: &(), w: [F; 3], ax: F, ay: F, _iso: bool) -> F {
        Self::lambda_aniso(data, w, ax, ay)
    }
    /// Λ at cot θ̃ = |z|/√(αx²x² + αy²y²) directly (Beckmann's Λ is a function of it).
    #[inline(always)]
    fn lambda_aniso<F: Real>(_: &(), w: [F; 3], ax: F, ay: F) -> F {
        let (x, y, z) = (
            ax.to_f64() * w[0].to_f64(),
            ay.to_f64() * w[1].to_f64(),
            w[2].to_f64().abs(),
        );
        let a = z / (x * x + y * y).sqrt();
        // (a = ∞ at normal incidence gives Λ = 0; z = 0 gives a = 0, Λ = ∞.)
        F::from_f64(fast::beckmann::lambda_cot(a))
    }
    #[inline(always)]
    fn sample_wm<F: Real>(_: &(), w: [F; 3], ax: F, ay: F, u: [F; 2]) -> [F; 3] {
        fast::beckmann::sample_visible(w, ax, ay, u)
    }
    #[inline(always)]
    fn sample_wm_stream<F: Real>(
        _: &(),
        v: [F; 3],
        ax: F,
        ay: F,
        uniform: &mut dyn FnMut() -> F,
    ) -> Option<[F; 3]> {
        if v[2] > F::ZERO {
            fast::beckmann::sample_visible_above(v, ax, ay, uniform)
        } else {
            fast::beckmann::sample_visible_below(v, ax, ay, uniform)
        }
    }
    #[inline(always)]
    fn sample_dcos<F: Real>(_: &(), ax: F, ay: F, u: [F; 2]) -> [F; 3] {
        fast::beckmann::sample_dcos(ax, ay, u)
    }
}

impl Shape for DoubleGgx {
    type Data = ();
    const UNIT: Option<UnitSlopes> = Some(UnitSlopes::DoubleGgx);
    #[inline(always)]
    fn d_iso<F: Real>(_: &(), u: F, alpha: F) -> F {
        fast::double_ggx::d(u, alpha)
    }
    #[inline(always)]
    fn lambda_iso<F: Real>(_: &(), u: F, alpha: F) -> F {
        fast::double_ggx::lambda(u, alpha)
    }
    /// Λ by the vector form for isotropic materials too, as D: the scalar path's cot θ from
    /// 1 − z² lost the digits of a rounded f32 unit vector near the normal (G1 2 % off at
    /// α = 1e4, 1 − z = 5e-7; 6e-6 at α = 254, past the documented 4e-6).
    #[inline(always)]
    fn lambda<F: Real>(data: &(), w: [F; 3], ax: F, ay: F, _iso: bool) -> F {
        Self::lambda_aniso(data, w, ax, ay)
    }
    /// The vector form for isotropic materials too (as [`Ggx`]'s): x² + y² where the scalar
    /// path has 1 − z², which near the normal has lost the digits of a rounded unit vector.
    #[inline(always)]
    fn d<F: Real>(data: &(), wm: [F; 3], ax: F, ay: F, _iso: bool) -> F {
        Self::d_aniso(data, wm, ax, ay)
    }
    /// D = G(1/y)/(π αx αy z⁴), y = ((x/αx)² + (y/αy)²)/z², from the normal and the kernel's
    /// table; the ends by the projected route, out of line. Evaluated in f64 (as the scalar D).
    #[inline(always)]
    fn d_aniso<F: Real>(data: &(), wm: [F; 3], ax: F, ay: F) -> F {
        let (z, r, q) = stretched_normal(wm, ax, ay);
        let z2 = z * z;
        let g = if z > 0.0 {
            fast::double_ggx::d_kernel_in_table(q / z2)
        } else {
            None
        };
        match g {
            Some(g) => F::from_f64(g * r / (std::f64::consts::PI * z2 * z2)),
            None => d_projected_cold::<Self, F>(data, wm, ax, ay),
        }
    }
    /// Λ at x = (αx²x² + αy²y²)/(2z²) from the direction and the table; the ends by the
    /// projected route, out of line.
    #[inline(always)]
    fn lambda_aniso<F: Real>(data: &(), w: [F; 3], ax: F, ay: F) -> F {
        let (x, y, z) = (ax * w[0], ay * w[1], w[2]);
        let q = (x * x + y * y) / (z * z);
        match fast::double_ggx::lambda_in_table(F::from_f64(0.5) * q) {
            Some(v) => v,
            None => lambda_projected_cold::<Self, F>(data, w, ax, ay),
        }
    }
    #[inline(always)]
    fn sample_wm<F: Real>(_: &(), w: [F; 3], ax: F, ay: F, u: [F; 2]) -> [F; 3] {
        let mut s = UniformStream::new(u);
        fast::double_ggx::sample_visible(w, ax, ay, u, &mut || s.next_uniform())
    }
    #[inline(always)]
    fn sample_wm_stream<F: Real>(
        _: &(),
        v: [F; 3],
        ax: F,
        ay: F,
        uniform: &mut dyn FnMut() -> F,
    ) -> Option<[F; 3]> {
        if v[2] > F::ZERO {
            let u = [uniform(), uniform()];
            Some(fast::double_ggx::sample_visible(v, ax, ay, u, &mut || {
                uniform()
            }))
        } else {
            fast::double_ggx::sample_visible_below(v, ax, ay, uniform)
        }
    }
    #[inline(always)]
    fn sample_dcos<F: Real>(_: &(), ax: F, ay: F, u: [F; 2]) -> [F; 3] {
        let mut s = UniformStream::new(u);
        fast::double_ggx::sample_dcos(ax, ay, u, &mut || s.next_uniform())
    }
}

impl Shape for Exponential {
    type Data = ();
    const UNIT: Option<UnitSlopes> = Some(UnitSlopes::Exponential);
    #[inline(always)]
    fn d_iso<F: Real>(_: &(), u: F, alpha: F) -> F {
        fast::exponential::d(u, alpha)
    }
    #[inline(always)]
    fn lambda_iso<F: Real>(_: &(), u: F, alpha: F) -> F {
        fast::exponential::lambda(u, alpha)
    }
    /// Λ by the vector form for isotropic materials too, as D: the scalar path's cot θ from
    /// 1 − z² lost the digits of a rounded f32 unit vector near the normal (G1 2 % off at
    /// α = 1e4, 1 − z = 5e-7; 6e-6 at α = 254, past the documented 4e-6).
    #[inline(always)]
    fn lambda<F: Real>(data: &(), w: [F; 3], ax: F, ay: F, _iso: bool) -> F {
        Self::lambda_aniso(data, w, ax, ay)
    }
    /// The vector form for isotropic materials too (as [`Ggx`]'s): x² + y² where the scalar
    /// path has 1 − z², which near the normal has lost the digits of a rounded unit vector.
    #[inline(always)]
    fn d<F: Real>(data: &(), wm: [F; 3], ax: F, ay: F, _iso: bool) -> F {
        Self::d_aniso(data, wm, ax, ay)
    }
    /// D = 2 e^{−2√y}/(π αx αy z⁴), y = ((x/αx)² + (y/αy)²)/z², from the normal; the ends by
    /// the projected route, out of line. Evaluated in f64 (as the scalar D).
    #[inline(always)]
    fn d_aniso<F: Real>(data: &(), wm: [F; 3], ax: F, ay: F) -> F {
        let (z, r, q) = stretched_normal(wm, ax, ay);
        let z2 = z * z;
        let e = 2.0 * q.sqrt() / z;
        // (The scalar D's bound: e^{−e} is 0 past 745; false for NaN and z ≤ 0.)
        if !(z > 0.0 && e <= 745.2 && z2 > 0.0) {
            return d_projected_cold::<Self, F>(data, wm, ax, ay);
        }
        F::from_f64(2.0 * (-e).exp() * r / (std::f64::consts::PI * z2 * z2))
    }
    /// Λ at q = 4z²/(αx²x² + αy²y²) from the direction and the tables; the ends by the
    /// projected route, out of line. q in f64 (as the scalar path: see fast::exponential).
    #[inline(always)]
    fn lambda_aniso<F: Real>(data: &(), w: [F; 3], ax: F, ay: F) -> F {
        let (x, y, z) = (
            ax.to_f64() * w[0].to_f64(),
            ay.to_f64() * w[1].to_f64(),
            w[2].to_f64(),
        );
        let q = 4.0 * (z * z) / (x * x + y * y);
        match fast::exponential::lambda_in_table::<F>(q) {
            Some(v) => v,
            None => lambda_projected_cold::<Self, F>(data, w, ax, ay),
        }
    }
    #[inline(always)]
    fn sample_wm<F: Real>(_: &(), w: [F; 3], ax: F, ay: F, u: [F; 2]) -> [F; 3] {
        let mut s = UniformStream::new(u);
        fast::exponential::sample_visible(w, ax, ay, u, &mut || s.next_uniform())
    }
    #[inline(always)]
    fn sample_dcos<F: Real>(_: &(), ax: F, ay: F, u: [F; 2]) -> [F; 3] {
        let mut s = UniformStream::new(u);
        fast::exponential::sample_dcos(ax, ay, u, &mut || s.next_uniform())
    }
}

/// GTR's material: the fitted tables (isotropic, any γ), or GGX's kernels (γ = 2, where
/// GTR is GGX, anisotropic allowed).
#[doc(hidden)]
#[derive(Clone, Debug)]
pub enum GtrData {
    Fitted(Fit<fast::gtr::FittedGtr>),
    Ggx,
}

impl Shape for Gtr {
    type Data = GtrData;
    const UNIT: Option<UnitSlopes> = None;
    #[inline(always)]
    fn d_iso<F: Real>(data: &GtrData, u: F, alpha: F) -> F {
        match data {
            GtrData::Fitted(g) => g.d(u),
            GtrData::Ggx => fast::ggx::d(u, alpha),
        }
    }
    #[inline(always)]
    fn lambda_iso<F: Real>(data: &GtrData, u: F, alpha: F) -> F {
        match data {
            GtrData::Fitted(g) => g.lambda(u),
            GtrData::Ggx => fast::ggx::lambda(u, alpha),
        }
    }
    /// Λ from the vector too ([`fast::gtr::FittedGtr::lambda_vec`]: the scalar path's u
    /// lost the digits of a rounded f32 unit vector near the normal, G1 2 % off at α = 1e4,
    /// 1 − z = 5e-7).
    #[inline(always)]
    fn lambda<F: Real>(data: &GtrData, w: [F; 3], ax: F, ay: F, _iso: bool) -> F {
        match data {
            GtrData::Fitted(g) => g.lambda_vec(w),
            GtrData::Ggx => ggx_lambda_aniso(w, ax, ay),
        }
    }
    /// From the vector (x² + y² rather than 1 − z², as [`Ggx`]'s).
    #[inline(always)]
    fn d<F: Real>(data: &GtrData, wm: [F; 3], ax: F, ay: F, _iso: bool) -> F {
        match data {
            GtrData::Fitted(g) => g.d_vec(wm),
            GtrData::Ggx => ggx_d_aniso(wm, ax, ay),
        }
    }
    #[inline(always)]
    fn d_aniso<F: Real>(_: &GtrData, wm: [F; 3], ax: F, ay: F) -> F {
        // Only γ = 2 is anisotropic (the constructor's rule).
        ggx_d_aniso(wm, ax, ay)
    }
    #[inline(always)]
    fn lambda_aniso<F: Real>(_: &GtrData, w: [F; 3], ax: F, ay: F) -> F {
        ggx_lambda_aniso(w, ax, ay)
    }
    #[inline(always)]
    fn sample_wm<F: Real>(data: &GtrData, w: [F; 3], ax: F, ay: F, u: [F; 2]) -> [F; 3] {
        match data {
            GtrData::Fitted(g) => {
                let mut s = UniformStream::new(u);
                g.sample_visible(w, u, &mut || s.next_uniform())
            }
            GtrData::Ggx => fast::ggx::sample_visible(w, ax, ay, u),
        }
    }
    #[inline(always)]
    fn sample_dcos<F: Real>(data: &GtrData, ax: F, ay: F, u: [F; 2]) -> [F; 3] {
        match data {
            GtrData::Fitted(g) => g.sample_dcos(u),
            GtrData::Ggx => fast::ggx::sample_dcos(ax, ay, u),
        }
    }
}

/// The family's Beckmann mixtures: Λ from the shape's fitted table, D exact, samplers of the
/// exact path ([`fast::fitted`]).
macro_rules! family_shape {
    ($($t:ident),*) => {$(
        impl Shape for crate::$t {
            type Data = Fit<fast::fitted::FittedShape>;
            const UNIT: Option<UnitSlopes> = None;
            const FAMILY: Option<crate::NdfKind> = Some(crate::NdfKind::$t);
            #[inline(always)]
            fn d_iso<F: Real>(data: &Self::Data, u: F, alpha: F) -> F {
                data.d(u, alpha)
            }
            #[inline(always)]
            fn lambda_iso<F: Real>(data: &Self::Data, u: F, alpha: F) -> F {
                data.lambda(u, alpha)
            }
            /// From the vector's cot θ/α̃ (FittedShape::lambda_vec).
            #[inline(always)]
            fn lambda<F: Real>(data: &Self::Data, w: [F; 3], ax: F, ay: F, _iso: bool) -> F {
                data.lambda_vec(w, ax, ay)
            }
            /// From the normal's slopes (FittedShape::d_vec), else (the horizon, z ≤ 1e-60,
            /// NaN) as the trait's.
            #[inline(always)]
            fn d<F: Real>(data: &Self::Data, wm: [F; 3], ax: F, ay: F, iso: bool) -> F {
                let w = wm.map(|x| x.to_f64());
                if let Some(d) = data.d_vec(w, ax.to_f64(), ay.to_f64()) {
                    return F::from_f64(d);
                }
                if iso {
                    Self::d_iso(data, wm[2], ax)
                } else {
                    Self::d_aniso(data, wm, ax, ay)
                }
            }
            #[inline(always)]
            fn sample_wm<F: Real>(data: &Self::Data, w: [F; 3], ax: F, ay: F, u: [F; 2]) -> [F; 3] {
                data.sample_visible(w, ax.to_f64(), ay.to_f64(), u)
            }
            #[inline(always)]
            fn sample_wm_stream<F: Real>(
                data: &Self::Data,
                v: [F; 3],
                ax: F,
                ay: F,
                uniform: &mut dyn FnMut() -> F,
            ) -> Option<[F; 3]> {
                data.sample_visible_stream(v, ax.to_f64(), ay.to_f64(), uniform)
            }
            #[inline(always)]
            fn sample_dcos<F: Real>(data: &Self::Data, ax: F, ay: F, u: [F; 2]) -> [F; 3] {
                data.sample_dcos(ax.to_f64(), ay.to_f64(), u)
            }
        }
    )*};
}
family_shape!(StudentT, Ei, Erfc, K0, BesselK);

/// An NDF `N` at roughness (αx, αy) in precision `F`: see the [module docs](crate::distribution).
pub struct Microfacet<F, N: Shape> {
    ax: F,
    ay: F,
    /// αx == αy: the fast scalar functions of u answer as they are.
    iso: bool,
    data: N::Data,
    /// (The exact parameters, for [`Microfacet::exact`].)
    exact: ExactParams,
    _n: PhantomData<fn() -> N>,
}

// (By hand: derives would ask N itself for Clone and Debug.)
impl<F: Copy, N: Shape> Clone for Microfacet<F, N> {
    fn clone(&self) -> Self {
        Microfacet {
            ax: self.ax,
            ay: self.ay,
            iso: self.iso,
            data: self.data.clone(),
            exact: self.exact,
            _n: PhantomData,
        }
    }
}

impl<F: std::fmt::Debug, N: Shape> std::fmt::Debug for Microfacet<F, N> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Microfacet")
            .field("ndf", &std::any::type_name::<N>())
            .field("alpha_x", &self.ax)
            .field("alpha_y", &self.ay)
            .field("data", &self.data)
            .finish()
    }
}

#[derive(Clone, Copy, Debug)]
struct ExactParams {
    ax: f64,
    ay: f64,
    /// GTR's γ or the family member's shape; NaN where there is none.
    gamma: f64,
}

/// α in f64 for the exact twin, after the range check. An f32 α is accepted where it is the
/// f32 nearest a value in [`crate::ALPHA_MIN`], [`crate::ALPHA_MAX`] (1e-6 has no f32: 1e-6f32
/// is 1e-6 − 3e-15, below it) and taken at the bound there.
#[inline(always)]
pub(crate) fn check<F: Real>(a: F) -> Result<f64, ParamError> {
    let a = a.to_f64();
    match crate::error::check_alpha(a) {
        Ok(a) => Ok(a),
        // (Out of line: the test in the path cost the family's f32 construction ~15 ns,
        // 27–38 ns against 40–53, BENCHMARKS.md.)
        Err(e) => f32_bound::<F>(a, e),
    }
}

/// [`check`]'s refusal, unless α is the f32 nearest a bound.
#[cold]
#[inline(never)]
fn f32_bound<F: Real>(a: f64, e: ParamError) -> Result<f64, ParamError> {
    let (lo, hi) = (crate::ALPHA_MIN, crate::ALPHA_MAX);
    if F::IS_F32 && (a == lo as f32 as f64 || a == hi as f32 as f64) {
        return Ok(a.clamp(lo, hi));
    }
    Err(e)
}

impl<F: Real, N: Shape<Data = ()>> Microfacet<F, N> {
    /// The NDF at roughness (αx, αy) (αx along the frame's tangent), each in [1e-6, 1e6];
    /// `Err` otherwise (NaN included). Isotropic when αx = αy.
    pub fn new(alpha_x: F, alpha_y: F) -> Result<Self, ParamError> {
        let (ax, ay) = (check(alpha_x)?, check(alpha_y)?);
        Ok(Microfacet {
            ax: alpha_x,
            ay: alpha_y,
            iso: alpha_x == alpha_y,
            data: (),
            exact: ExactParams {
                ax,
                ay,
                gamma: f64::NAN,
            },
            _n: PhantomData,
        })
    }
}

impl<F: Real> Microfacet<F, Gtr> {
    /// GTR at roughness (αx, αy) and exponent γ ∈ (0, 100]: isotropic (αx = αy) at any γ,
    /// its Λ fitted once here (milliseconds to tens of milliseconds, cached per (α, γ):
    /// [`crate::distribution::FIT_CACHE_CAPACITY`]); anisotropic only at γ = 2, where it
    /// is GGX ([`ParamError::Anisotropic`] otherwise).
    pub fn gtr(alpha_x: F, alpha_y: F, gamma: f64) -> Result<Self, ParamError> {
        let (ax, ay) = (check(alpha_x)?, check(alpha_y)?);
        let gamma = crate::error::check_gamma(gamma)?;
        let iso = alpha_x == alpha_y;
        let data = if gamma == 2.0 {
            GtrData::Ggx
        } else if iso {
            type Key = (u64, u64);
            static FITS: SharedFits<Key, fast::gtr::FittedGtr> = OnceLock::new();
            thread_local! {
                static LAST: Cell<Option<(Key, &'static fast::gtr::FittedGtr)>> =
                    const { Cell::new(None) };
            }
            GtrData::Fitted(shared_fit(
                &FITS,
                &LAST,
                (ax.to_bits(), gamma.to_bits()),
                || fast::gtr::FittedGtr::new(ax, gamma),
            )?)
        } else {
            return Err(ParamError::Anisotropic(gamma));
        };
        Ok(Microfacet {
            ax: alpha_x,
            ay: alpha_y,
            iso,
            data,
            exact: ExactParams { ax, ay, gamma },
            _n: PhantomData,
        })
    }
}

impl<F: Real, N: Shape<Data = Fit<fast::fitted::FittedShape>>> Microfacet<F, N> {
    /// A member of the family's Beckmann mixtures ([`crate::StudentT`] with `shape` = γ > 3/2,
    /// [`crate::BesselK`] with a ∈ [0.1, 100], [`crate::Ei`], [`crate::Erfc`], [`crate::K0`]
    /// with `None`) at roughness (αx, αy), each in [1e-6, 1e6]: Λ₁ of the shape fitted on the
    /// shape's first use in the process ([`fast::fitted`]: milliseconds; Bessel-K tens of
    /// milliseconds, its exact Λ integrates K_ν) and shared by every later material of the
    /// shape, whose construction is then a thread-local lookup (tens of nanoseconds:
    /// BENCHMARKS.md, "Materials per call");
    /// relative error ≤ 1e-7 (tests/fast.rs); D exact; visible normals by the mixing
    /// variable's posterior (exact, a fraction of a microsecond). Typed errors as
    /// [`crate::AnyNdf::new`]'s.
    pub fn with_shape(alpha_x: F, alpha_y: F, shape: Option<f64>) -> Result<Self, ParamError> {
        let (ax, ay) = (check(alpha_x)?, check(alpha_y)?);
        let kind = N::FAMILY.expect("the family's Shape impls name their kind");
        type Key = (crate::NdfKind, u64);
        static FITS: SharedFits<Key, fast::fitted::FittedShape> = OnceLock::new();
        thread_local! {
            static LAST: Cell<Option<(Key, &'static fast::fitted::FittedShape)>> =
                const { Cell::new(None) };
        }
        let key = super::shape_key(kind, shape);
        // The shape as the NDF takes it (NaN for the members without one).
        let gamma = kind
            .shape_name()
            .map_or(f64::NAN, |_| f64::from_bits(key.1));
        let data = shared_fit(&FITS, &LAST, key, || {
            fast::fitted::FittedShape::new(&crate::AnyNdf::new(kind, 1.0, shape)?)
        })?;
        Ok(Microfacet {
            ax: alpha_x,
            ay: alpha_y,
            iso: alpha_x == alpha_y,
            data,
            exact: ExactParams { ax, ay, gamma },
            _n: PhantomData,
        })
    }
}

impl<F: Real, N: Shape> Microfacet<F, N> {
    /// The validated exact path for the same material, in f64 (closed forms ≤ 1e-13,
    /// quadratures ≤ 1e-10; samplers: exact invertible warps of u, tens of microseconds for the
    /// superpositions): for references and checks, not a renderer's inner loop.
    pub fn exact(&self) -> Exact {
        let p = self.exact;
        if let Some(kind) = N::FAMILY {
            let shape = Some(p.gamma).filter(|g| !g.is_nan());
            return Exact::new(kind, p.ax, p.ay, shape).expect("validated at construction");
        }
        match N::UNIT {
            Some(kind) => Exact::stretched(kind, p.ax, p.ay),
            None if p.gamma == 2.0 => Exact::stretched(UnitSlopes::Ggx, p.ax, p.ay),
            None => Exact {
                alpha: (p.ax, p.ay),
                inner: ExactInner::Gtr(Isotropic(
                    Gtr::new(p.ax, p.gamma).expect("validated at construction"),
                )),
            },
        }
    }
}

impl<F: Real> Microfacet<F, Ggx> {
    /// The cap's lower bound −b of Eto & Tokuyoshi's bounded VNDF for w (mirrored to w.z ≥ 0),
    /// with the stretched unit direction w' and w'.z − b = (1 − k) w'.z, formed without the
    /// cancellation of k → 1 (a small α): the sampler's 1 − b and the cap's top need it.
    #[inline(always)]
    fn bounded_cap(&self, w: [F; 3]) -> ([F; 3], F, F) {
        let down = w[2] < F::ZERO;
        let w = if down { crate::math::dirs::neg(w) } else { w };
        let ws = normalize([self.ax * w[0], self.ay * w[1], w[2]]);
        if down {
            return (ws, ws[2], F::ZERO);
        }
        let a = self.ax.min(self.ay).min(F::ONE);
        let s = F::ONE + (w[0] * w[0] + w[1] * w[1]).sqrt();
        let (a2, s2) = (a * a, s * s);
        let den = s2 + a2 * w[2] * w[2];
        let k = (F::ONE - a2) * s2 / den;
        // 1 − k = a²(s² + w.z²)/(s² + a²w.z²).
        let one_minus_k = a2 * (s2 + w[2] * w[2]) / den;
        (ws, k * ws[2], one_minus_k * ws[2])
    }

    /// Bounded visible-normal sampling for reflection (Eto & Tokuyoshi 2023): the spherical
    /// cap shrunk to z ∈ [−k w'.z, 1] (w' the stretched direction), k = (1 − a²)s²/(s² +
    /// a²w.z²), a = min(1, αx, αy), s = 1 + |w.xy|, which removes only normals whose
    /// reflection of w would point below the horizon (for w.z > 0; a down-welling w is
    /// mirrored and the full cap used). The pdf is the visible density scaled by
    /// (1 + w'.z)/(1 + k w'.z).
    pub fn sample_bounded(&self, w: [F; 3], u: [F; 2]) -> Sample<F> {
        let w = super::unit(w);
        let (ws, b, top) = self.bounded_cap(w);
        let (c, s) = fast::cos_sin_turn(u[0].to_f64());
        let (c, s) = (F::from_f64(c), F::from_f64(s));
        // The cap point's height z ∈ [−b, 1]: z + b = above, 1 − z = u₁(1 + b), and
        // 1 + z = above + (1 − b), 1 − b = (1 − w'.z) + (w'.z − b), 1 − w'.z = (w'.x² +
        // w'.y²)/(1 + w'.z): sin² = (1 − z)(1 + z) without the cancellation at the poles
        // (z → ±1: u₁ → 0, or u₁ → 1 at a small α), where 1 − z² would lose it to z's
        // rounding.
        let above = (F::ONE - u[1]) * (F::ONE + b);
        let one_minus_b = (ws[0] * ws[0] + ws[1] * ws[1]) / (F::ONE + ws[2]) + top;
        let sin = (u[1] * (F::ONE + b) * (above + one_minus_b))
            .max(F::ZERO)
            .sqrt();
        let m = [sin * c + ws[0], sin * s + ws[1], above + top];
        let wm = normalize([self.ax * m[0], self.ay * m[1], m[2].max(F::ZERO)]);
        let wm = fast::facing(wm, w);
        Sample {
            wm,
            pdf: self.pdf_bounded(w, wm),
        }
    }

    /// Density of [`Microfacet::sample_bounded`] w.r.t. the solid angle of the normal.
    pub fn pdf_bounded(&self, w: [F; 3], wm: [F; 3]) -> F {
        let w = super::unit(w);
        let (ws, b, _) = self.bounded_cap(w);
        let m = normalize([wm[0] / self.ax, wm[1] / self.ay, wm[2]]);
        let d = dot(m, ws);
        // The cap point: the reflection of w' about m'.
        let cz = (d + d) * m[2] - ws[2];
        if cz < -b {
            return F::ZERO;
        }
        self.d_visible(w, wm) * (F::ONE + ws[2]) / (F::ONE + b)
    }

    /// Density of the reflected direction wi = reflect(wo, wm) for wm from
    /// [`Microfacet::sample_bounded`]`(wo, ·)`: pdf(wm)/(4|wo·wm|) (Eto & Tokuyoshi's).
    pub fn pdf_bounded_reflection(&self, wo: [F; 3], wi: [F; 3]) -> F {
        let Some(wm) = crate::math::dirs::half_vector_reflection(wo, wi) else {
            return F::ZERO;
        };
        let c = dot(wo, wm).abs();
        if !(c > F::ZERO) {
            return F::ZERO;
        }
        self.pdf_bounded(wo, wm) / (F::from_f64(4.0) * c)
    }
}

impl<F: Real, N: Shape> Microfacet<F, N> {
    /// [`MicrofacetDistribution::pdf_dcos`] where D·cos was not finite: the exact path's
    /// (built here: cold).
    #[cold]
    #[inline(never)]
    fn pdf_dcos_cold(&self, wm: [F; 3]) -> F {
        F::from_f64(self.exact().pdf_dcos(wm.map(F::to_f64)))
    }
}

impl<F: Real, N: Shape> MicrofacetDistribution<F> for Microfacet<F, N> {
    #[inline(always)]
    fn alpha(&self) -> (F, F) {
        (self.ax, self.ay)
    }
    fn ndf(&self) -> Option<(crate::NdfKind, Option<f64>)> {
        if let Some(kind) = N::FAMILY {
            return Some((kind, kind.shape_name().map(|_| self.exact.gamma)));
        }
        Some(match N::UNIT {
            Some(unit) => (unit.kind(), None),
            None => (crate::NdfKind::Gtr, Some(self.exact.gamma)),
        })
    }

    #[inline(always)]
    fn d(&self, wm: [F; 3]) -> F {
        N::d(&self.data, wm, self.ax, self.ay, self.iso)
    }

    #[inline(always)]
    fn lambda(&self, w: [F; 3]) -> F {
        N::lambda(&self.data, w, self.ax, self.ay, self.iso)
    }

    #[inline(always)]
    fn g1(&self, w: [F; 3]) -> F {
        N::g1(&self.data, w, self.ax, self.ay, self.iso)
    }

    #[inline(always)]
    fn d_visible(&self, w: [F; 3], wm: [F; 3]) -> F {
        N::d_visible(&self.data, w, wm, self.ax, self.ay, self.iso)
    }

    #[inline(always)]
    fn sample_wm(&self, w: [F; 3], u: [F; 2]) -> [F; 3] {
        N::sample_wm(&self.data, w, self.ax, self.ay, super::below_one(u))
    }

    #[inline(always)]
    fn sample_wm_stream(&self, v: [F; 3], uniform: &mut dyn FnMut() -> F) -> Option<[F; 3]> {
        N::sample_wm_stream(&self.data, v, self.ax, self.ay, uniform)
    }

    #[inline(always)]
    fn sample_dcos(&self, u: [F; 2]) -> Sample<F> {
        let wm = N::sample_dcos(&self.data, self.ax, self.ay, super::below_one(u));
        Sample {
            wm,
            pdf: self.pdf_dcos(wm),
        }
    }

    /// D(wm) cos θm (0 for wm.z ≤ 0); where D overflows but the product need not (a
    /// subnormal wm.z: Student-T γ = 1.5016, α = 1.5e-3 at wm.z = 9.7e-319 gave +∞ for
    /// 1.6e-5), the exact path's D·cos form, out of line.
    #[inline(always)]
    fn pdf_dcos(&self, wm: [F; 3]) -> F {
        let z = wm[2];
        if !(z > F::ZERO) {
            return if z.to_f64().is_nan() { z } else { F::ZERO };
        }
        let p = self.d(wm) * z;
        if p.to_f64().is_finite() {
            p
        } else {
            self.pdf_dcos_cold(wm)
        }
    }
}
