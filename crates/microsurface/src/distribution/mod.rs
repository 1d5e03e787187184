//! The renderer's door: one anisotropic microfacet distribution type for every NDF, in f32
//! or f64, with the visible-normal pdf beside every sample.
//!
//! [`Microfacet<F, N>`](Microfacet) is an NDF `N` ([`Ggx`], [`Beckmann`], [`DoubleGgx`],
//! [`Exponential`], [`Gtr`], and the family's Beckmann mixtures [`crate::StudentT`],
//! [`crate::Ei`], [`crate::Erfc`], [`crate::K0`], [`crate::BesselK`]) at roughness (αx, αy) in
//! precision `F` (f32 or f64). It is built once per material ([`Microfacet::new`], validated:
//! α ∈ [1e-6, 1e6]; GTR through [`Microfacet::gtr`], the family through
//! [`Microfacet::with_shape`], which fits Λ for the shape: [`fast::fitted`]) and is then
//! cheap per call, through the [`MicrofacetDistribution`] trait that the BSDFs ([`crate::bsdf`]) are
//! generic over:
//!
//! | method | value |
//! |---|---|
//! | `d(wm)` | D(wm), 0 below the horizon |
//! | `lambda(w)` | Smith Λ(w) of the side w comes from (Λ(−w) = Λ(w)) |
//! | `g1(w)` | 1/(1 + Λ(w)) |
//! | `g2(wo, wi)` | height-correlated 1/(1 + Λ(wo) + Λ(wi)) (Heitz 2014, eq. 99, as pbrt-v4 uses it for both reflection and transmission) |
//! | `g2_separable(wo, wi)` | G1(wo) G1(wi) |
//! | `d_visible(w, wm)` = `pdf(w, wm)` | G1(w) max(0, w·wm) D(wm)/|w.z| (w.z < 0: w mirrored to −w) |
//! | `sample(w, u)` | a visible normal with its pdf ([`Sample`]) |
//! | `sample_dcos(u)` | a normal distributed as D(m) cos θm, with its pdf |
//!
//! Directions are unit vectors `[F; 3]` in the local shading frame (z = the shading normal;
//! [`crate::bsdf::frame::Frame`] converts). The projected roughness of an anisotropic Λ, the
//! stretch of the samplers and the normalisation of D are inside; no caller computes them.
//!
//! **Anisotropy.** Beckmann, GGX, Double GGX, the Exponential NDF and the family are shape invariant
//! (P22(p, q) = P22₁(p/αx, q/αy)/(αx αy)): D(m) = P22₁(x̃, ỹ)/(αx αy z⁴) with x̃ = x/(αx z), and
//! Λ(w) is the α = 1 Λ at cot θ̃ = z/√(αx²x² + αy²y²) (Heitz 2014, §5.3). GTR at γ ≠ 2 is not
//! shape invariant: Burley's anisotropic form c/((x/αx)² + (y/αy)² + z²)^γ has no projected
//! roughness for Λ and no stretch for its visible normals, and its Λ would be a 2D
//! quadrature per direction. GTR is therefore isotropic here except at γ = 2, where it *is*
//! GGX (same D, same normalisation) and runs GGX's anisotropic kernels; [`Microfacet::gtr`]
//! rejects αx ≠ αy at other γ with [`ParamError::Anisotropic`].
//!
//! **The generalised exponential** ([`crate::GenExponential`]) has no `Microfacet` type; it
//! runs through [`Exact`] (D closed form, Λ by quadrature, exact warps of 10–200 µs a
//! sample). The two halves of a fast path are missing for it: its Λ₁ falls like e^{−z^γ},
//! by 300 orders of magnitude between z = 1 and 1.4 at γ = 20 (z²⁰ goes from 190 to 2000
//! across the eighth octave above z = 1.3), which the family's eighth-octave polynomial
//! tables of ln Λ₁ ([`fast::fitted`]) cannot follow in relative terms; and above γ = 2 it is not a Beckmann mixture, below it one
//! over a positive stable law, so there is no posterior sampler for visible normals (the
//! family's other members draw theirs in ~0.2 µs). No renderer ships it; Student-T covers the
//! range between GGX's and Beckmann's tails that a renderer wants.
//!
//! **Evaluation.** The fast paths ([`crate::fast`]) by default: closed forms for GGX and
//! Beckmann, fitted tables (≤ 1e-7 relative) for Double GGX, the Exponential NDF and GTR.
//! GGX's D and Λ and Beckmann's Λ are evaluated from the vector ((x/αx)² + (y/αy)² and
//! αx²x² + αy²y²: better conditioned near the normal than 1 − z² of a rounded unit vector,
//! and as cheap). The other quantities call the fast scalar functions of u = |w.z| as they
//! are (bit for bit) for isotropic materials, and at the projected roughness
//! α̃ for anisotropic ones. Accuracy against the exact path (tests/bsdf.rs, D, G1 and the visible pdf at random
//! directions): the fast paths' own bounds ([`crate::fast`]) — measured f64: GGX 2e-15,
//! Beckmann 7e-13, Double GGX 3e-11, Exponential 6e-12, GTR 8e-11; f32: GGX 6e-7, Beckmann
//! 2e-5, fitted 4e-6 isotropic and 1e-5 anisotropic (there α̃ is itself rounded to f32, and Λ's
//! condition number in α reaches ~100 where Λ is small). The validated exact path
//! ([`Microfacet::exact`], f64) implements the same trait from the exact NDF types
//! (closed forms ≤ 1e-13, quadratures ≤ 1e-10).
//!
//! **Sampling.** `sample(w, u)` takes two uniforms u ∈ [0, 1)². GGX (spherical caps, Dupuy &
//! Benyoub 2023) and Beckmann (the exact inversion of Heitz & d'Eon 2014) are warps of u.
//! Double GGX, the Exponential NDF and GTR use exact rejection samplers: u drives the first
//! candidate, and the uniforms of any further ones come from a SplitMix64 stream seeded by
//! the bits of u ([`UniformStream`]) — the same shape for every NDF, deterministic in u, and
//! the exact distribution (χ²-tested). GGX also has Eto & Tokuyoshi's bounded VNDF
//! ([`Microfacet::sample_bounded`]) with its reflection pdf.
//!
//! ```
//! use microsurface::{MicrofacetDistribution, Exponential, Ggx, Microfacet};
//! let ggx = Microfacet::<f32, Ggx>::new(0.3, 0.1)?;
//! let wo = [0.48f32, 0.0, 0.8775];
//! let s = ggx.sample(wo, [0.3, 0.7]);
//! assert!(s.pdf > 0.0 && (s.pdf - ggx.pdf(wo, s.wm)).abs() <= 1e-5 * s.pdf);
//! let exp = Microfacet::<f32, Exponential>::new(0.3, 0.1)?; // same API, another NDF
//! assert!(exp.sample(wo, [0.3, 0.7]).pdf > 0.0);
//! # Ok::<(), microsurface::ParamError>(())
//! ```

// `!(x > 0)` is the NaN-aware test (false for NaN) on a generic `Real`, on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod any;
pub(crate) mod kernels;

pub use any::{AnyMicrofacet, FIT_CACHE_CAPACITY};

use crate::bsdf::frame::{dot, normalize};
use crate::distribution::kernels::{Isotropic, Microsurface, Shaped, Stretched};
use crate::fast::{self, Real};
use crate::math::rng::SplitMix64;
use crate::math::vec3::Vec3;
use crate::sampling::visible::UnitSlopes;
use crate::{Beckmann, DoubleGgx, Exponential, Ggx, Gtr, ParamError};
use std::collections::HashMap;
use std::hash::Hash;
use std::marker::PhantomData;
use std::sync::{Arc, Mutex, OnceLock};

/// A visible normal and its density w.r.t. the solid angle of the normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample<F> {
    /// The microfacet normal (unit, upper hemisphere, facing the sampled direction).
    pub wm: [F; 3],
    /// Its density: [`MicrofacetDistribution::pdf`]`(w, wm)`.
    pub pdf: F,
}

/// The direction API every distribution has (f32 or f64): what the BSDFs use.
///
/// Directions w and normals wm are unit vectors in the local frame (z = the macro normal),
/// as a renderer holds them (pbrt-v4's convention); the samplers also accept w of any finite
/// nonzero length, and [`Exact`] accepts any length everywhere (it normalises).
pub trait MicrofacetDistribution<F: Real> {
    /// (αx, αy).
    fn alpha(&self) -> (F, F);

    /// D(wm) for a unit normal; 0 for wm.z ≤ 0.
    fn d(&self, wm: [F; 3]) -> F;

    /// Smith Λ(w) of the side w comes from (a function of |w.z| and the azimuth); +∞ at
    /// grazing (w.z = 0), 0 at normal incidence.
    fn lambda(&self, w: [F; 3]) -> F;

    /// G1(w) = 1/(1 + Λ(w)).
    #[inline]
    fn g1(&self, w: [F; 3]) -> F {
        F::ONE / (F::ONE + self.lambda(w))
    }

    /// Height-correlated G2(wo, wi) = 1/(1 + Λ(wo) + Λ(wi)).
    #[inline]
    fn g2(&self, wo: [F; 3], wi: [F; 3]) -> F {
        F::ONE / (F::ONE + self.lambda(wo) + self.lambda(wi))
    }

    /// Separable G2(wo, wi) = G1(wo) G1(wi) (Mitsuba 3's `G`).
    #[inline]
    fn g2_separable(&self, wo: [F; 3], wi: [F; 3]) -> F {
        self.g1(wo) * self.g1(wi)
    }

    /// The visible-normal density D_w(wm) = G1(w) max(0, w·wm) D(wm)/|w.z|, for w.z < 0 that
    /// of −w (the microsurface seen from below is sampled through its mirror image, as in
    /// pbrt-v4); 0 at grazing w and for wm below the horizon.
    #[inline]
    fn d_visible(&self, w: [F; 3], wm: [F; 3]) -> F {
        let z = w[2].abs();
        let c = if w[2] < F::ZERO {
            -dot(w, wm)
        } else {
            dot(w, wm)
        };
        // (False for NaN.)
        if !(c > F::ZERO && z > F::ZERO) {
            return if c.to_f64().is_nan() { c } else { F::ZERO };
        }
        let d = self.d(wm);
        if d.to_f64() == f64::INFINITY {
            // D's pole (the family's singular members at m = (0, 0, 1)), where g1·c can
            // underflow to 0: the density is +∞ there, not NaN.
            return d;
        }
        // (In this order: g1 ~ z/σ(0) cancels the 1/z of a direction near the horizon.)
        self.g1(w) * c * d / z
    }

    /// The density of [`MicrofacetDistribution::sample`]: [`MicrofacetDistribution::d_visible`].
    #[inline]
    fn pdf(&self, w: [F; 3], wm: [F; 3]) -> F {
        self.d_visible(w, wm)
    }

    /// A visible normal for w (w.z < 0 is mirrored) from u ∈ [0, 1)².
    fn sample_wm(&self, w: [F; 3], u: [F; 2]) -> [F; 3];

    /// A visible normal for a direction v of **either** hemisphere, not mirrored: distributed
    /// as max(0, v·m) D(m)/σ(v) over the upper hemisphere of m (σ(v) = v.z(1 + Λ(v)) above,
    /// |v.z| Λ(v) below: the microsurface seen from beneath its mean plane, as a ray inside
    /// the microsurface's height field sees it, [`crate::scattering`]), from the uniforms in
    /// (0, 1) that `uniform` supplies (two, or more for a sampler that rejects): for a
    /// caller that needs the distribution of m, not a warp of two uniforms. `None` where the
    /// distribution has no such sampler for v, or for a rounded normal that fails the test
    /// v·m > 0, m.z > 0, or a rejection sampler past its cap; the caller then uses
    /// [`MicrofacetDistribution::sample_wm`] (above) or a rejection from the mirror image (below):
    /// all exact, so the mixture is too. Provided: GGX (its spherical cap covers v.z < 0 as
    /// it is: Dupuy & Benyoub 2023, the cap z ∈ [−v.z, 1] of the stretched v), Beckmann (the
    /// visible slope by rejection on both sides, four times cheaper than its warp above)
    /// and Double GGX (the mixing variable by rejection, then GGX's cap).
    #[inline]
    fn sample_wm_stream(&self, v: [F; 3], uniform: &mut dyn FnMut() -> F) -> Option<[F; 3]> {
        let _ = (v, uniform);
        None
    }

    /// A visible normal and its pdf.
    #[inline]
    fn sample(&self, w: [F; 3], u: [F; 2]) -> Sample<F> {
        let wm = self.sample_wm(w, u);
        Sample {
            wm,
            pdf: self.pdf(w, wm),
        }
    }

    /// A normal distributed as D(m) cos θm, and that density.
    fn sample_dcos(&self, u: [F; 2]) -> Sample<F>;

    /// The density of [`MicrofacetDistribution::sample_dcos`]: D(wm) cos θm (0 for wm.z ≤ 0).
    #[inline]
    fn pdf_dcos(&self, wm: [F; 3]) -> F {
        if !(wm[2] > F::ZERO) {
            return if wm[2].to_f64().is_nan() {
                wm[2]
            } else {
                F::ZERO
            };
        }
        self.d(wm) * wm[2]
    }

    /// Which NDF this is (with GTR's γ), where the type knows: the library's materials
    /// ([`Microfacet`], [`Exact`]) answer, so that [`crate::scattering`] can use the tables
    /// it ships; `None` by default.
    fn ndf(&self) -> Option<(crate::NdfKind, Option<f64>)> {
        None
    }

    /// Whether the surface is effectively smooth (max(αx, αy) < 1e-3): the BSDFs then
    /// behave as a perfect mirror or interface (a delta lobe), as pbrt-v4 does. At α = 1e-3
    /// the GGX lobe's half-width is 0.06°, below a pixel's footprint in any practical
    /// camera, and D's peak 3e5 strains f32 pdf arithmetic.
    #[inline]
    fn effectively_smooth(&self) -> bool {
        let (ax, ay) = self.alpha();
        ax.max(ay) < F::from_f64(1e-3)
    }
}

/// The uniforms of a rejection sampler's second and later candidates: SplitMix64 (Steele,
/// Lea & Flood 2014) seeded by the bits of the sample's u, so that
/// [`MicrofacetDistribution::sample`] is a deterministic function of (w, u) for every NDF. f64: 53
/// random bits per uniform; f32: 24; both in [0, 1).
#[derive(Clone, Copy, Debug)]
pub struct UniformStream(SplitMix64);

impl UniformStream {
    /// The stream of u.
    #[inline(always)]
    pub fn new<F: Real>(u: [F; 2]) -> Self {
        let a = u[0].to_f64().to_bits();
        let b = u[1].to_f64().to_bits();
        UniformStream(SplitMix64(a ^ b.rotate_left(29) ^ 0x243F_6A88_85A3_08D3))
    }

    /// The next uniform.
    #[inline(always)]
    pub fn next_uniform<F: Real>(&mut self) -> F {
        let z = self.0.next_u64();
        if F::IS_F32 {
            F::from_f32((z >> 40) as f32 * (1.0 / 16_777_216.0))
        } else {
            F::from_f64((z >> 11) as f64 * (1.0 / 9_007_199_254_740_992.0))
        }
    }
}

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
    Fitted(Arc<fast::gtr::FittedGtr>),
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
            type Data = Arc<fast::fitted::FittedShape>;
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

/// An NDF `N` at roughness (αx, αy) in precision `F`: see the [module docs](self).
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

/// A process-wide cache of fits or tables ([`crate::AnyMicrofacet::FIT_CACHE_CAPACITY`]
/// entries).
pub(crate) type FitCache<K, V> = OnceLock<Mutex<HashMap<K, Arc<V>>>>;

/// The value of `key` from `cache`, or `make`'s, kept while the cache has room. `make` runs
/// outside the lock (a fit or a table takes milliseconds); it is a deterministic function of
/// its key, so whichever thread stores it first, every material gets the same bits. A
/// poisoned lock (a panic elsewhere while it was held) is used as it is: the map is never
/// left half-written.
pub(crate) fn cached<K: Eq + Hash, V, E>(
    cache: &'static FitCache<K, V>,
    key: K,
    make: impl FnOnce() -> Result<V, E>,
) -> Result<Arc<V>, E> {
    let map = cache.get_or_init(Default::default);
    if let Some(v) = map.lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
        return Ok(v.clone());
    }
    let v = Arc::new(make()?);
    let mut m = map.lock().unwrap_or_else(|e| e.into_inner());
    if m.len() < crate::distribution::any::FIT_CACHE_CAPACITY || m.contains_key(&key) {
        return Ok(m.entry(key).or_insert(v).clone());
    }
    Ok(v)
}

fn check<F: Real>(a: F) -> Result<f64, ParamError> {
    crate::error::check_alpha(a.to_f64())
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
    /// its Λ fitted once here (1–90 ms, see the README); anisotropic only at γ = 2, where it
    /// is GGX ([`ParamError::Anisotropic`] otherwise).
    pub fn gtr(alpha_x: F, alpha_y: F, gamma: f64) -> Result<Self, ParamError> {
        let (ax, ay) = (check(alpha_x)?, check(alpha_y)?);
        let gamma = crate::error::check_gamma(gamma)?;
        let iso = alpha_x == alpha_y;
        let data = if gamma == 2.0 {
            GtrData::Ggx
        } else if iso {
            static FITS: FitCache<(u64, u64), fast::gtr::FittedGtr> = OnceLock::new();
            GtrData::Fitted(cached(&FITS, (ax.to_bits(), gamma.to_bits()), || {
                fast::gtr::FittedGtr::new(ax, gamma)
            })?)
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

impl<F: Real, N: Shape<Data = Arc<fast::fitted::FittedShape>>> Microfacet<F, N> {
    /// A member of the family's Beckmann mixtures ([`crate::StudentT`] with `shape` = γ > 3/2,
    /// [`crate::BesselK`] with a ∈ [0.1, 100], [`crate::Ei`], [`crate::Erfc`], [`crate::K0`]
    /// with `None`) at roughness (αx, αy), each in [1e-6, 1e6]: Λ₁ of the shape fitted once
    /// here ([`fast::fitted`]: 1–3 ms; Bessel-K ~0.1 s, its exact Λ integrates K_ν),
    /// relative error ≤ 1e-7 (tests/fast.rs); D exact; visible normals by the mixing
    /// variable's posterior (exact, ~0.2 µs). Typed errors as [`crate::AnyNdf::new`]'s.
    pub fn with_shape(alpha_x: F, alpha_y: F, shape: Option<f64>) -> Result<Self, ParamError> {
        let (ax, ay) = (check(alpha_x)?, check(alpha_y)?);
        let kind = N::FAMILY.expect("the family's Shape impls name their kind");
        let ndf = crate::AnyNdf::new(kind, 1.0, shape)?;
        static FITS: FitCache<(crate::NdfKind, u64), fast::fitted::FittedShape> = OnceLock::new();
        let key = (kind, ndf.shape().unwrap_or(0.0).to_bits());
        let data = cached(&FITS, key, || fast::fitted::FittedShape::new(&ndf))?;
        Ok(Microfacet {
            ax: alpha_x,
            ay: alpha_y,
            iso: alpha_x == alpha_y,
            data,
            exact: ExactParams {
                ax,
                ay,
                gamma: ndf.shape().unwrap_or(f64::NAN),
            },
            _n: PhantomData,
        })
    }
}

impl<F: Real, N: Shape> Microfacet<F, N> {
    /// The validated exact path for the same material, in f64 (closed forms ≤ 1e-13,
    /// quadratures ≤ 1e-10; samplers: exact invertible warps of u, 10–80 µs for the
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
    /// with the stretched unit direction w'.
    #[inline(always)]
    fn bounded_cap(&self, w: [F; 3]) -> ([F; 3], F) {
        let down = w[2] < F::ZERO;
        let w = if down { crate::bsdf::frame::neg(w) } else { w };
        let ws = normalize([self.ax * w[0], self.ay * w[1], w[2]]);
        if down {
            return (ws, ws[2]);
        }
        let a = self.ax.min(self.ay).min(F::ONE);
        let s = F::ONE + (w[0] * w[0] + w[1] * w[1]).sqrt();
        let (a2, s2) = (a * a, s * s);
        let k = (F::ONE - a2) * s2 / (s2 + a2 * w[2] * w[2]);
        (ws, k * ws[2])
    }

    /// Bounded visible-normal sampling for reflection (Eto & Tokuyoshi 2023): the spherical
    /// cap shrunk to z ∈ [−k w'.z, 1] (w' the stretched direction), k = (1 − a²)s²/(s² +
    /// a²w.z²), a = min(1, αx, αy), s = 1 + |w.xy|, which removes only normals whose
    /// reflection of w would point below the horizon (for w.z > 0; a down-welling w is
    /// mirrored and the full cap used). The pdf is the visible density scaled by
    /// (1 + w'.z)/(1 + k w'.z).
    pub fn sample_bounded(&self, w: [F; 3], u: [F; 2]) -> Sample<F> {
        let (ws, b) = self.bounded_cap(w);
        let (c, s) = fast::cos_sin_turn(u[0].to_f64());
        let (c, s) = (F::from_f64(c), F::from_f64(s));
        let above = (F::ONE - u[1]) * (F::ONE + b);
        let z = above - b;
        let sin = ((F::ONE - z) * (F::ONE + z)).max(F::ZERO).sqrt();
        let m = [sin * c + ws[0], sin * s + ws[1], above + (ws[2] - b)];
        let wm = normalize([self.ax * m[0], self.ay * m[1], m[2].max(F::ZERO)]);
        let wm = fast::facing(wm, w);
        Sample {
            wm,
            pdf: self.pdf_bounded(w, wm),
        }
    }

    /// Density of [`Microfacet::sample_bounded`] w.r.t. the solid angle of the normal.
    pub fn pdf_bounded(&self, w: [F; 3], wm: [F; 3]) -> F {
        let (ws, b) = self.bounded_cap(w);
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
        let Some(wm) = crate::bsdf::frame::half_vector_reflection(wo, wi) else {
            return F::ZERO;
        };
        let c = dot(wo, wm).abs();
        if !(c > F::ZERO) {
            return F::ZERO;
        }
        self.pdf_bounded(wo, wm) / (F::from_f64(4.0) * c)
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
    fn sample_wm(&self, w: [F; 3], u: [F; 2]) -> [F; 3] {
        N::sample_wm(&self.data, w, self.ax, self.ay, u)
    }

    #[inline(always)]
    fn sample_wm_stream(&self, v: [F; 3], uniform: &mut dyn FnMut() -> F) -> Option<[F; 3]> {
        N::sample_wm_stream(&self.data, v, self.ax, self.ay, uniform)
    }

    #[inline(always)]
    fn sample_dcos(&self, u: [F; 2]) -> Sample<F> {
        let wm = N::sample_dcos(&self.data, self.ax, self.ay, u);
        Sample {
            wm,
            pdf: self.d(wm) * wm[2],
        }
    }
}

/// The exact path of a [`Microfacet`] material (f64): see [`Microfacet::exact`].
#[derive(Clone, Copy, Debug)]
pub struct Exact {
    alpha: (f64, f64),
    inner: ExactInner,
}

#[derive(Clone, Copy, Debug)]
enum ExactInner {
    Stretched(Stretched),
    Gtr(Isotropic<Gtr>),
    Shaped(Shaped),
}

impl Exact {
    /// The exact path of NDF `kind` at roughness (αx, αy) with its shape parameter `gamma`
    /// where it has one ([`crate::NdfKind::shape_name`]: γ of GTR, Student-T and the
    /// generalised exponential, a of Bessel-K), for an NDF chosen at run time (command lines,
    /// sweeps); [`Microfacet::exact`] is the same for a material built at compile time. GTR:
    /// isotropic at γ ≠ 2, as [`Microfacet::gtr`]. The family's other NDFs (Student-T, Ei,
    /// Erfc, K0, Bessel-K, generalised exponential) are anisotropic by stretching, with visible
    /// normals by the exact slope-space inversion (quadratures: tens of microseconds a sample);
    /// Student-T needs γ > 3/2 here (Λ is infinite below). Typed errors as the constructors'.
    pub fn new(
        kind: crate::NdfKind,
        alpha_x: f64,
        alpha_y: f64,
        gamma: Option<f64>,
    ) -> Result<Exact, ParamError> {
        use crate::NdfKind as K;
        let (ax, ay) = (
            crate::error::check_alpha(alpha_x)?,
            crate::error::check_alpha(alpha_y)?,
        );
        let unit = match kind {
            K::Beckmann => UnitSlopes::Beckmann,
            K::Ggx => UnitSlopes::Ggx,
            K::DoubleGgx => UnitSlopes::DoubleGgx,
            K::Exponential => UnitSlopes::Exponential,
            K::StudentT | K::Ei | K::Erfc | K::K0 | K::BesselK | K::GenExponential => {
                let ndf = crate::AnyNdf::new(kind, ax, gamma)?;
                if let crate::AnyNdf::StudentT(t) = ndf {
                    if !t.has_finite_lambda() {
                        return Err(ParamError::Shape {
                            name: "student_t gamma (visible normals and G need a finite Lambda)",
                            range: "(1.5, 1e6]",
                            value: t.gamma(),
                        });
                    }
                }
                return Ok(Exact {
                    alpha: (ax, ay),
                    inner: ExactInner::Shaped(Shaped::new(&ndf, ax, ay)?),
                });
            }
            K::Gtr => {
                let gamma = crate::error::check_gamma(gamma.unwrap_or(f64::NAN))?;
                if gamma == 2.0 {
                    UnitSlopes::Ggx
                } else if ax != ay {
                    return Err(ParamError::Anisotropic(gamma));
                } else {
                    return Ok(Exact {
                        alpha: (ax, ay),
                        inner: ExactInner::Gtr(Isotropic(Gtr::new(ax, gamma)?)),
                    });
                }
            }
        };
        Ok(Exact::stretched(unit, ax, ay))
    }

    fn stretched(kind: UnitSlopes, ax: f64, ay: f64) -> Exact {
        Exact {
            alpha: (ax, ay),
            inner: ExactInner::Stretched(Stretched::raw(kind, ax, ay)),
        }
    }

    /// The projected area σ(w) = ∫ max(0, w·m) D(m) dm = |w.z| (1 + Λ(w)) (finite at grazing,
    /// where it is σ(0) of the azimuth), for w mirrored to the upper hemisphere.
    pub fn sigma(&self, w: [f64; 3]) -> f64 {
        let w = Vec3::from(w);
        self.surface().sigma(if w.z < 0.0 { -w } else { w })
    }

    fn surface(&self) -> &dyn Microsurface {
        match &self.inner {
            ExactInner::Stretched(s) => s,
            ExactInner::Gtr(g) => g,
            ExactInner::Shaped(g) => g,
        }
    }

    /// The u that [`MicrofacetDistribution::sample`] maps to wm (the exact samplers are invertible
    /// warps); NaN for a normal no sampler returns.
    pub fn invert(&self, w: [f64; 3], wm: [f64; 3]) -> [f64; 2] {
        self.surface().invert_visible(Vec3::from(w), Vec3::from(wm))
    }

    /// The u that [`MicrofacetDistribution::sample_dcos`] maps to wm.
    pub fn invert_dcos(&self, wm: [f64; 3]) -> [f64; 2] {
        self.surface().invert_dcos(Vec3::from(wm))
    }
}

impl MicrofacetDistribution<f64> for Exact {
    fn alpha(&self) -> (f64, f64) {
        self.alpha
    }
    fn ndf(&self) -> Option<(crate::NdfKind, Option<f64>)> {
        Some(match &self.inner {
            ExactInner::Stretched(s) => (s.kind().kind(), None),
            ExactInner::Gtr(g) => (crate::NdfKind::Gtr, Some(g.0.gamma())),
            ExactInner::Shaped(g) => (g.unit().kind(), g.unit().shape()),
        })
    }
    fn d(&self, wm: [f64; 3]) -> f64 {
        self.surface().d(Vec3::from(wm))
    }
    fn lambda(&self, w: [f64; 3]) -> f64 {
        self.surface().lambda(Vec3::from(w))
    }
    fn sample_wm(&self, w: [f64; 3], u: [f64; 2]) -> [f64; 3] {
        self.surface().sample_visible(Vec3::from(w), u).into()
    }
    /// As the trait's: for the Beckmann mixtures of the family (Student-T, Ei, Erfc, K0,
    /// Bessel-K) above the horizon, the posterior of the mixing variable
    /// (`Shaped::sample_visible_stream`: ≤ 2 candidates on average, then Beckmann's stream
    /// sampler; Bessel-K's exact warp inverts a CDF that integrates K_ν); `None` otherwise.
    fn sample_wm_stream(&self, v: [f64; 3], uniform: &mut dyn FnMut() -> f64) -> Option<[f64; 3]> {
        match &self.inner {
            ExactInner::Shaped(s) => s
                .sample_visible_stream(Vec3::from(v), uniform)
                .map(Into::into),
            _ => None,
        }
    }
    fn sample_dcos(&self, u: [f64; 2]) -> Sample<f64> {
        let s = self.surface();
        let wm = s.sample_dcos(u);
        Sample {
            wm: wm.into(),
            pdf: s.pdf_dcos(wm),
        }
    }
    /// As the trait's, for w and wm of any finite nonzero length (normalised here), in the
    /// form max(0, w·wm) D(wm)/σ(w) (finite at grazing w).
    fn d_visible(&self, w: [f64; 3], wm: [f64; 3]) -> f64 {
        let (w, wm) = (Vec3::from(w).to_unit(), Vec3::from(wm).to_unit());
        let w = if w.z < 0.0 { -w } else { w };
        let c = w.dot(wm);
        if !(c > 0.0 && wm.z > 0.0) {
            return if c.is_nan() || wm.z.is_nan() {
                f64::NAN
            } else {
                0.0
            };
        }
        let s = self.surface();
        c * s.d(wm) / s.sigma(w)
    }
    /// As the trait's, for wm of any finite nonzero length (normalised here).
    fn pdf_dcos(&self, wm: [f64; 3]) -> f64 {
        self.surface().pdf_dcos(Vec3::from(wm))
    }
}
