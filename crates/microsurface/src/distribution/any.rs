//! The run-time door: [`AnyMicrofacet`].

use crate::distribution::{Exact, Microfacet, MicrofacetDistribution, Sample};
use crate::math::real::Real;
use crate::ndf::family::{NdfKind, NdfSpec, SpecError};
use crate::{Beckmann, BesselK, DoubleGgx, Ei, Erfc, Exponential, Ggx, Gtr, ParamError};
use crate::{StudentT, K0};

/// How many fits each process-wide cache keeps ([`crate::AnyMicrofacet`]): past it, a new
/// shape is fitted for its material alone. A fit holds a few kilobytes; 256 shapes cover
/// every material of a scene, and a textured shape parameter cannot grow memory without
/// bound.
pub const FIT_CACHE_CAPACITY: usize = 256;

/// Any NDF at roughness (αx, αy) in precision `F`, chosen at run time.
///
/// The run-time door: [`AnyMicrofacet<F>`](AnyMicrofacet), any NDF of the library chosen by
/// name at run time (a scene file's `"ndf": "student_t:2.5"`, a command line, a Python
/// call), running the same fast kernels as the static [`Microfacet<F, N>`](Microfacet).
///
/// It is an enum over the static materials, matched once per call (static dispatch, no trait
/// object), so its values and samples are bit-identical to the static type's (tests/any.rs
/// checks every NDF, f32 and f64, isotropic and anisotropic). Build it from
/// `(NdfKind, αx, αy, shape)` ([`AnyMicrofacet::new`]) or from a spec string
/// ([`AnyMicrofacet::parse`], [`NdfSpec`]); [`AnyMicrofacet::exact`] is the validated f64 path
/// of the same material.
///
/// **What runs.** GGX, Beckmann, Double GGX, the Exponential NDF: closed forms and fixed
/// tables. GTR: Λ fitted per (α, γ) at construction; the family's Beckmann mixtures
/// (Student-T, Ei, Erfc, K0, Bessel-K): Λ₁ fitted per shape at construction. Both fits are
/// cached process-wide (by (kind, shape) for the family, by (α, γ) for GTR, up to
/// [`FIT_CACHE_CAPACITY`] entries each), so a renderer that builds one material per shading
/// point with a textured α pays a family shape's fit once (GTR's fit depends on α: a
/// textured GTR α pays one fit per distinct α until the cache is full, then one per
/// material). **The generalised exponential** has no fast path (see
/// [`crate::distribution`]): it runs its exact path, in f64, converted from and to `F`; its
/// Λ is a quadrature per call and its visible normals an exact warp of tens to hundreds of
/// microseconds.
///
/// ```
/// use microsurface::{AnyMicrofacet, MicrofacetDistribution, Ggx, Microfacet};
/// let m = AnyMicrofacet::<f32>::parse("Trowbridge-Reitz", 0.3, 0.2)?;
/// let s = Microfacet::<f32, Ggx>::new(0.3, 0.2)?;
/// let (wo, u) = ([0.48f32, 0.0, 0.8775], [0.3, 0.7]);
/// assert_eq!(m.sample(wo, u), s.sample(wo, u)); // bit for bit
/// let t = AnyMicrofacet::<f32>::parse("student_t:2.5", 0.3, 0.3)?;
/// assert!(t.sample(wo, u).pdf > 0.0);
/// # Ok::<(), microsurface::SpecError>(())
/// ```
#[derive(Clone, Debug)]
pub struct AnyMicrofacet<F: Real> {
    inner: Inner<F>,
}

#[derive(Clone, Debug)]
enum Inner<F: Real> {
    Ggx(Microfacet<F, Ggx>),
    Beckmann(Microfacet<F, Beckmann>),
    DoubleGgx(Microfacet<F, DoubleGgx>),
    Exponential(Microfacet<F, Exponential>),
    Gtr(Microfacet<F, Gtr>),
    StudentT(Microfacet<F, StudentT>),
    Ei(Microfacet<F, Ei>),
    Erfc(Microfacet<F, Erfc>),
    K0(Microfacet<F, K0>),
    BesselK(Microfacet<F, BesselK>),
    /// The generalised exponential: the exact path, in f64.
    Exact(Exact),
}

/// `$body` with `$m` bound to the static material (every kind but the exact one), or
/// `$exact` with `$e` bound to the [`Exact`].
macro_rules! dispatch {
    ($self:expr, |$m:ident| $body:expr, |$e:ident| $exact:expr) => {
        match &$self.inner {
            Inner::Ggx($m) => $body,
            Inner::Beckmann($m) => $body,
            Inner::DoubleGgx($m) => $body,
            Inner::Exponential($m) => $body,
            Inner::Gtr($m) => $body,
            Inner::StudentT($m) => $body,
            Inner::Ei($m) => $body,
            Inner::Erfc($m) => $body,
            Inner::K0($m) => $body,
            Inner::BesselK($m) => $body,
            Inner::Exact($e) => $exact,
        }
    };
}

impl<F: Real> AnyMicrofacet<F> {
    /// NDF `kind` at roughness (αx, αy), each in [1e-6, 1e6], with its shape parameter where
    /// it has one ([`NdfKind::shape_name`]: γ of GTR, Student-T and the generalised
    /// exponential, a of Bessel-K; ignored by the others). Typed errors as the static
    /// constructors' ([`Microfacet::new`], [`Microfacet::gtr`], [`Microfacet::with_shape`],
    /// [`Exact::new`]): GTR is anisotropic only at γ = 2, Student-T needs γ > 3/2.
    pub fn new(
        kind: NdfKind,
        alpha_x: F,
        alpha_y: F,
        shape: Option<f64>,
    ) -> Result<Self, ParamError> {
        let (ax, ay) = (alpha_x, alpha_y);
        let inner = match kind {
            NdfKind::Ggx => Inner::Ggx(Microfacet::new(ax, ay)?),
            NdfKind::Beckmann => Inner::Beckmann(Microfacet::new(ax, ay)?),
            NdfKind::DoubleGgx => Inner::DoubleGgx(Microfacet::new(ax, ay)?),
            NdfKind::Exponential => Inner::Exponential(Microfacet::new(ax, ay)?),
            NdfKind::Gtr => Inner::Gtr(Microfacet::gtr(ax, ay, shape.unwrap_or(f64::NAN))?),
            NdfKind::StudentT => Inner::StudentT(Microfacet::with_shape(ax, ay, shape)?),
            NdfKind::Ei => Inner::Ei(Microfacet::with_shape(ax, ay, None)?),
            NdfKind::Erfc => Inner::Erfc(Microfacet::with_shape(ax, ay, None)?),
            NdfKind::K0 => Inner::K0(Microfacet::with_shape(ax, ay, None)?),
            NdfKind::BesselK => Inner::BesselK(Microfacet::with_shape(ax, ay, shape)?),
            NdfKind::GenExponential => {
                let (ax, ay) = (super::microfacet::check(ax)?, super::microfacet::check(ay)?);
                Inner::Exact(Exact::new(kind, ax, ay, shape)?)
            }
        };
        Ok(AnyMicrofacet { inner })
    }

    /// The material of a parsed [`NdfSpec`] at roughness (αx, αy).
    pub fn from_spec(spec: NdfSpec, alpha_x: F, alpha_y: F) -> Result<Self, ParamError> {
        AnyMicrofacet::new(spec.kind, alpha_x, alpha_y, spec.shape)
    }

    /// The material named by `spec` (`"ggx"`, `"GGX"`, `"trowbridge_reitz"`,
    /// `"student_t:2.5"`, `"gtr:1.5"`, `"bessel_k:0.7"`: [`NdfSpec`]) at roughness (αx, αy).
    pub fn parse(spec: &str, alpha_x: F, alpha_y: F) -> Result<Self, SpecError> {
        let spec: NdfSpec = spec.parse()?;
        Ok(AnyMicrofacet::from_spec(spec, alpha_x, alpha_y)?)
    }

    /// Which NDF this is.
    pub fn kind(&self) -> NdfKind {
        match &self.inner {
            Inner::Ggx(_) => NdfKind::Ggx,
            Inner::Beckmann(_) => NdfKind::Beckmann,
            Inner::DoubleGgx(_) => NdfKind::DoubleGgx,
            Inner::Exponential(_) => NdfKind::Exponential,
            Inner::Gtr(_) => NdfKind::Gtr,
            Inner::StudentT(_) => NdfKind::StudentT,
            Inner::Ei(_) => NdfKind::Ei,
            Inner::Erfc(_) => NdfKind::Erfc,
            Inner::K0(_) => NdfKind::K0,
            Inner::BesselK(_) => NdfKind::BesselK,
            Inner::Exact(_) => NdfKind::GenExponential,
        }
    }

    /// The NDF and its shape parameter, as a spec (`"gtr:1.5"` when printed).
    pub fn spec(&self) -> NdfSpec {
        let (kind, shape) = self.ndf().unwrap_or((self.kind(), None));
        NdfSpec { kind, shape }
    }

    /// Whether the material runs a fast path (every NDF but the generalised exponential).
    pub fn is_fast(&self) -> bool {
        !matches!(self.inner, Inner::Exact(_))
    }

    /// The validated exact path of the same material, in f64 ([`Microfacet::exact`]).
    pub fn exact(&self) -> Exact {
        dispatch!(self, |m| m.exact(), |e| *e)
    }
}

fn f64s<F: Real>(w: [F; 3]) -> [f64; 3] {
    w.map(F::to_f64)
}

fn from_f64s<F: Real>(w: [f64; 3]) -> [F; 3] {
    w.map(F::from_f64)
}

// The per-call methods are inlined whole (`inline(always)`: the match and every arm's body),
// so that a caller's loop over one material sees a loop-invariant discriminant it can hoist;
// with `inline` alone LLVM kept the large match out of line (BENCHMARKS.md).
impl<F: Real> MicrofacetDistribution<F> for AnyMicrofacet<F> {
    #[inline]
    fn alpha(&self) -> (F, F) {
        dispatch!(self, |m| m.alpha(), |e| {
            let (ax, ay) = e.alpha();
            (F::from_f64(ax), F::from_f64(ay))
        })
    }
    #[inline(always)]
    fn d(&self, wm: [F; 3]) -> F {
        dispatch!(self, |m| m.d(wm), |e| F::from_f64(e.d(f64s(wm))))
    }
    #[inline(always)]
    fn lambda(&self, w: [F; 3]) -> F {
        dispatch!(self, |m| m.lambda(w), |e| F::from_f64(e.lambda(f64s(w))))
    }
    #[inline(always)]
    fn g1(&self, w: [F; 3]) -> F {
        dispatch!(self, |m| m.g1(w), |e| F::from_f64(e.g1(f64s(w))))
    }
    #[inline(always)]
    fn g2(&self, wo: [F; 3], wi: [F; 3]) -> F {
        dispatch!(self, |m| m.g2(wo, wi), |e| F::from_f64(
            e.g2(f64s(wo), f64s(wi))
        ))
    }
    #[inline]
    fn g2_separable(&self, wo: [F; 3], wi: [F; 3]) -> F {
        dispatch!(self, |m| m.g2_separable(wo, wi), |e| F::from_f64(
            e.g2_separable(f64s(wo), f64s(wi))
        ))
    }
    #[inline(always)]
    fn d_visible(&self, w: [F; 3], wm: [F; 3]) -> F {
        dispatch!(self, |m| m.d_visible(w, wm), |e| F::from_f64(
            e.d_visible(f64s(w), f64s(wm))
        ))
    }
    #[inline(always)]
    fn pdf(&self, w: [F; 3], wm: [F; 3]) -> F {
        dispatch!(self, |m| m.pdf(w, wm), |e| F::from_f64(
            e.pdf(f64s(w), f64s(wm))
        ))
    }
    #[inline(always)]
    fn sample_wm(&self, w: [F; 3], u: [F; 2]) -> [F; 3] {
        dispatch!(self, |m| m.sample_wm(w, u), |e| from_f64s(
            e.sample_wm(f64s(w), u.map(F::to_f64))
        ))
    }
    #[inline]
    fn sample_wm_stream(&self, v: [F; 3], uniform: &mut dyn FnMut() -> F) -> Option<[F; 3]> {
        dispatch!(self, |m| m.sample_wm_stream(v, uniform), |e| e
            .sample_wm_stream(f64s(v), &mut || uniform().to_f64())
            .map(from_f64s))
    }
    #[inline(always)]
    fn sample(&self, w: [F; 3], u: [F; 2]) -> Sample<F> {
        // (The exact path: the normal rounded to F first, then its pdf in F, so that a
        // sample's pdf is `pdf(w, wm)` of the normal returned, as the static types'.)
        dispatch!(self, |m| m.sample(w, u), |_e| {
            let wm = self.sample_wm(w, u);
            Sample {
                wm,
                pdf: self.pdf(super::unit(w), wm),
            }
        })
    }
    #[inline]
    fn sample_dcos(&self, u: [F; 2]) -> Sample<F> {
        dispatch!(self, |m| m.sample_dcos(u), |e| {
            let wm = from_f64s(e.sample_dcos(u.map(F::to_f64)).wm);
            Sample {
                wm,
                pdf: self.pdf_dcos(wm),
            }
        })
    }
    #[inline]
    fn pdf_dcos(&self, wm: [F; 3]) -> F {
        dispatch!(self, |m| m.pdf_dcos(wm), |e| F::from_f64(
            e.pdf_dcos(f64s(wm))
        ))
    }
    fn ndf(&self) -> Option<(NdfKind, Option<f64>)> {
        dispatch!(self, |m| m.ndf(), |e| e.ndf())
    }
    #[inline]
    fn effectively_smooth(&self) -> bool {
        dispatch!(self, |m| m.effectively_smooth(), |e| e.effectively_smooth())
    }
}
