//! Single-scattering rough conductor and rough dielectric BSDFs for every NDF, generic over
//! the [`MicrofacetDistribution`] (so an Exponential conductor or a GTR clearcoat lobe is one line).
//!
//! Conventions (pbrt-v4's): directions in the local shading frame (z = normal, unit
//! vectors), both pointing away from the surface, `wo` toward the viewer; `eval` is f without
//! the cosine; `pdf` is per unit solid angle of wi; the dielectric's η = η_inside/η_outside
//! (inside: z < 0); [`Transport::Radiance`] divides transmitted f by η'² (η' the relative
//! index along the path), [`Transport::Importance`] does not.
//!
//! * [`RoughConductor`]: f = D(wm) F(|wo·wm|) G2(wo, wi)/(4|cos θo||cos θi|) with wm the half
//!   vector of wo and wi (Cook & Torrance 1982; Walter et al. 2007, eq. 20), two-sided (wo
//!   below the surface sees the mirrored microsurface). Sampling: a visible normal from wo
//!   (pdf D_wo(wm)), then reflection, pdf D_wo(wm)/(4|wo·wm|); a reflected direction below the
//!   horizon is a rejected sample (`None`), so ∫ pdf = 1 − (the rejected fraction), which is
//!   the energy a single-scattering conductor loses to the horizon (tests/bsdf.rs measures
//!   both and finds them equal).
//! * [`RoughDielectric`]: Walter et al. 2007 (eqs. 16–21) with visible-normal sampling: reflection
//!   as the conductor's with the dielectric Fresnel R, transmission
//!   f = D(wm)(1 − R) G2 |wi·wm||wo·wm| / (|cos θi||cos θo| (wi·wm + wo·wm/η')²), the
//!   generalised half vector wm ∝ η' wi + wo; a visible normal is drawn, then reflection with
//!   probability R and refraction otherwise. Microfacets facing away from either direction
//!   contribute nothing (pbrt-v4's rule).
//! * **Smooth limit.** Where the distribution is [effectively
//!   smooth](MicrofacetDistribution::effectively_smooth) (max α < 1e-3), or η = 1 for the dielectric,
//!   the BSDF is a delta lobe: `sample` returns the mirror (and refracted) direction with
//!   `specular = true`, f = F/|cos θi| (pdf the discrete probability), and `eval` and `pdf`
//!   are 0, as in pbrt-v4.
//! * G2 ([`Masking`]): height-correlated by default ([`Masking::Correlated`],
//!   1/(1 + Λo + Λi), used for transmission too as in pbrt-v4), separable G1(wo)G1(wi)
//!   ([`Masking::Separable`], Mitsuba 3's), or height-correlated with the exact form of a
//!   transmission, B(1 + Λo, 1 + Λi) ([`Masking::CorrelatedBeta`]: the random walk's order 1;
//!   a conductor's reflection is the same as with the default).
//!
//! ```
//! use microsurface::bsdf::{Bsdf, RoughConductor};
//! use microsurface::bsdf::fresnel::Conductor;
//! use microsurface::{Exponential, Ggx, Microfacet};
//! let gold = Conductor { eta: [0.14f32, 0.42, 1.37], k: [3.98, 2.38, 1.60] };
//! let ggx = RoughConductor::new(Microfacet::<f32, Ggx>::new(0.2, 0.05)?, gold);
//! let exp = RoughConductor::new(Microfacet::<f32, Exponential>::new(0.2, 0.05)?, gold);
//! let wo = [0.3f32, 0.1, 0.9487];
//! for s in [ggx.sample(wo, 0.5, [0.3, 0.6]), exp.sample(wo, 0.5, [0.3, 0.6])] {
//!     let s = s.expect("reflected above the horizon");
//!     assert!(s.f[0] > 0.0 && s.pdf > 0.0 && s.wi[2] > 0.0);
//! }
//! # Ok::<(), microsurface::ParamError>(())
//! ```

// `!(x > 0)` is the NaN-aware test (false for NaN) on a generic `Real`, on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod frame;
pub mod fresnel;

use crate::bsdf::frame::{
    dot, half_vector_reflection, half_vector_refraction, jacobian_refraction, reflect, refract,
    refraction_denominator, same_hemisphere,
};
use crate::distribution::MicrofacetDistribution;
use crate::error::ParamError;
use crate::math::real::Real;
use fresnel::Fresnel;
use std::marker::PhantomData;

/// Which way light flows: radiance (from the light, the camera path's weights) divides the
/// transmitted f by η'²; importance does not (Veach 1997, §5.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Transport {
    #[default]
    Radiance,
    Importance,
}

/// The masking-shadowing term G2(wo, wi) of the single-scattering BSDFs (Heitz 2014,
/// "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT 3(2),
/// section 6). The two height-correlated forms agree for a reflection (wo, wi on one side)
/// and differ for a dielectric's transmission (on opposite sides), where
/// [`Masking::CorrelatedBeta`] is the exact one and [`Masking::Correlated`] overestimates it
/// ([`RoughDielectric`] has the measured gap).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Masking {
    /// Height-correlated 1/(1 + Λ(wo) + Λ(wi)) for both lobes, as pbrt-v4 (the default):
    /// exact for a reflection, an approximation for a transmission.
    #[default]
    Correlated,
    /// Separable G1(wo) G1(wi), Mitsuba 3's.
    Separable,
    /// Height-correlated, exact for both lobes: 1/(1 + Λ(wo) + Λ(wi)) for a reflection,
    /// B(1 + Λ(wo), 1 + Λ(wi)) = Γ(1 + Λo) Γ(1 + Λi)/Γ(2 + Λo + Λi) (Euler's beta function)
    /// for a transmission. With C1 the height CDF, a microfacet at height h is seen from wo
    /// with probability C1(h)^Λo, and the refracted ray leaves through the lower medium,
    /// whose heights run the other way, with probability (1 − C1(h))^Λi; over the heights
    /// (C1 uniform on [0, 1]) that is ∫₀¹ c^Λo (1 − c)^Λi dc = B(1 + Λo, 1 + Λi), where a
    /// reflection's ∫₀¹ c^{Λo + Λi} dc gives 1/(1 + Λo + Λi). B ≤ 1/(1 + Λo + Λi), equal
    /// where Λo or Λi is 0. It is the order 1 of the microsurface random walk
    /// ([`crate::scattering::RandomWalk::eval`], tests/walk.rs). B within 4ε(1 + |ln B|) in
    /// f64 (finite for every Λ, 0 where one is ∞); in f32 it is computed in f64 and rounded
    /// once.
    CorrelatedBeta,
}

impl Masking {
    /// G2(wo, wi) of this form from the distribution's Λ; a pair on opposite sides of the
    /// surface (wo.z wi.z < 0) is a transmission. (The microfacet visibility terms, wm
    /// facing wo and wi, are the BSDF's.)
    #[inline(always)]
    pub fn g2<F: Real, D: MicrofacetDistribution<F>>(self, d: &D, wo: [F; 3], wi: [F; 3]) -> F {
        match self {
            Masking::Correlated => d.g2(wo, wi),
            Masking::Separable => d.g2_separable(wo, wi),
            Masking::CorrelatedBeta if wo[2] * wi[2] < F::ZERO => F::from_f64(
                crate::math::special::beta_1p(d.lambda(wo).to_f64(), d.lambda(wi).to_f64()),
            ),
            Masking::CorrelatedBeta => d.g2(wo, wi),
        }
    }
}

/// Which lobe a sample came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lobe {
    Reflection,
    Transmission,
}

/// A sampled direction: wi, f(wo, wi) (without the cosine), its pdf, and how it was made.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BsdfSample<F, V> {
    pub wi: [F; 3],
    pub f: V,
    /// Per unit solid angle; for a `specular` sample the discrete probability of the lobe.
    pub pdf: F,
    pub lobe: Lobe,
    /// A delta lobe (smooth limit): f and pdf are its weights, not densities.
    pub specular: bool,
    /// The relative index η' along the path for a transmission (1 for reflection).
    pub eta: F,
}

/// What every BSDF of the library answers: the single-scattering [`RoughConductor`] and
/// [`RoughDielectric`], the compensated ones ([`crate::scattering`]) and the random walk's
/// ([`crate::scattering::MultipleScattering`]), in f32 and f64. Their f is `[F; N]` (RGB: N = 3,
/// the default), so a renderer holds any mix of them as
/// `Box<dyn Bsdf<f32, Value = [f32; 3]>>`.
pub trait Bsdf<F: Real> {
    /// f's value: `[F; N]`, one value per channel.
    type Value: Copy;
    /// f(wo, wi), without the cosine.
    fn eval(&self, wo: [F; 3], wi: [F; 3]) -> Self::Value;
    /// The density of [`Bsdf::sample`]'s wi per unit solid angle (0 for delta lobes).
    fn pdf(&self, wo: [F; 3], wi: [F; 3]) -> F;
    /// (f, pdf) of the pair in one call, as multiple importance sampling needs both: equal
    /// to ([`Bsdf::eval`], [`Bsdf::pdf`]) bit for bit. [`RoughConductor`] shares the half
    /// vector and the tests between the two; the others answer the two calls.
    #[inline]
    fn eval_pdf(&self, wo: [F; 3], wi: [F; 3]) -> (Self::Value, F) {
        (self.eval(wo, wi), self.pdf(wo, wi))
    }
    /// A direction wi from the uniforms uc (the lobe choice) and u (the normal); `None` where
    /// the sample is rejected (a reflection below the horizon, a refraction back to wo's
    /// side, a pdf that is not a positive finite number; for the single-scattering BSDFs
    /// also a pdf below 2.2e-158 (f32: 1.2e-20), a subnormal D at the sampled normal, and
    /// an f that overflows, each of probability ~0) or wo is on the horizon. A sample's pdf
    /// is > 0 and finite, and f is finite.
    fn sample(&self, wo: [F; 3], uc: F, u: [F; 2]) -> Option<BsdfSample<F, Self::Value>>;
}

/// Whether a direction counts as on the horizon: |cos θ| below 1e-18 in f32, 1e-150 in f64
/// (NaN included). f carries 1/(|cos θo||cos θi|), and at such cosines the product
/// underflows F (and G2/cos θ is 0/0 where Λ overflows); the solid angle they span is
/// below 1e-18, and f|cos θi| → 0 there, so the BSDF answers 0 (eval, pdf) and rejects
/// (sample), as pbrt-v4 does on the horizon itself.
#[inline(always)]
pub(crate) fn on_horizon<F: Real>(z: F) -> bool {
    let floor = F::from_f64(if F::IS_F32 { 1e-18 } else { 1e-150 });
    !(z.abs() >= floor)
}

/// A sampled pdf a renderer can divide by: finite and at least the smallest normal float
/// over the horizon floor ([`on_horizon`]), 2.2e-158 in f64 and 1.2e-20 in f32 (false for
/// NaN). The visible density is G1 (wo·wm) D/|cos θo|: a smaller pdf may have passed through
/// a subnormal product before the division by |cos θo| and lost the digits the weight
/// f|cos θi|/pdf needs (f32's pdf of 1.5e-44 put it at 1.0018, f64's of 2.3e-293 at
/// 1 + 4e-12, where it is G2/G1 ≤ 1). Such a sample carries no energy (f|cos θi| ≤ pdf for
/// F ≤ 1: below 3e-157 over the sphere in f64, 2e-19 in f32) and is rejected, as one
/// whose pdf underflowed or overflowed.
#[inline(always)]
pub(crate) fn usable<F: Real>(pdf: F) -> bool {
    let min = F::from_f64(if F::IS_F32 {
        f32::MIN_POSITIVE as f64 / 1e-18
    } else {
        f64::MIN_POSITIVE / 1e-150
    });
    pdf >= min && pdf < F::from_f64(f64::INFINITY)
}

/// The reflection lobe without its Fresnel factor: D(wm) G2(wo, wi)/(4|cos θo||cos θi|),
/// with D(wm) given.
#[inline(always)]
fn reflected<F: Real, D: MicrofacetDistribution<F>>(
    d: &D,
    m: Masking,
    wo: [F; 3],
    wi: [F; 3],
    d_wm: F,
) -> F {
    d_wm * m.g2(d, wo, wi) / (F::from_f64(4.0) * (wo[2] * wi[2]).abs())
}

/// D at a sampled normal where a sample can carry it: a normal number. A subnormal D has
/// lost digits that 1/|cos θo| or a transmission's Jacobian (up to 1e32 at η' = 1 + ε)
/// bring back to the normal range of f and the pdf, each rounded its own way, so that their
/// ratio, the weight, left its bound (1.0017 for a pdf of 4e-301 from D = 1e-321); such a
/// normal has probability below 1e-150 (the pdf ∝ D/|cos θo|), and its sample is rejected
/// like one with an unusable pdf.
#[inline(always)]
fn sampled_d<F: Real, D: MicrofacetDistribution<F>>(d: &D, wm: [F; 3]) -> Option<F> {
    let v = d.d(wm);
    usable(v).then_some(v)
}

/// Every channel of f finite (a sample's f: the parts of f, D first, can overflow F where f
/// itself does not, as the generalised exponential's f64 D does rounded to f32).
#[inline(always)]
fn all_finite<F: Real>(f: &[F]) -> bool {
    f.iter().all(|x| x.to_f64().is_finite())
}

/// A channel's Fresnel factor times the lobe: 0 where the channel reflects nothing (F = 0),
/// also where the lobe is +∞ (a singular NDF's pole, D(1) = ∞: 0 · ∞ would be NaN).
#[inline(always)]
fn weighted<F: Real>(f: F, k: F) -> F {
    if f == F::ZERO {
        F::ZERO
    } else {
        f * k
    }
}

/// A rough conductor: a [`MicrofacetDistribution`] and a [`Fresnel`] term of N channels (RGB: N = 3).
#[derive(Clone, Debug)]
pub struct RoughConductor<F, D, Fr, const N: usize> {
    dist: D,
    fresnel: Fr,
    masking: Masking,
    _f: PhantomData<fn() -> [F; N]>,
}

impl<F: Real, D: MicrofacetDistribution<F>, Fr: Fresnel<F, N>, const N: usize>
    RoughConductor<F, D, Fr, N>
{
    /// The conductor with the height-correlated G2; f has the Fresnel term's N channels.
    pub fn new(dist: D, fresnel: Fr) -> Self {
        RoughConductor {
            dist,
            fresnel,
            masking: Masking::Correlated,
            _f: PhantomData,
        }
    }

    /// The same with another masking-shadowing term (a conductor only reflects:
    /// [`Masking::CorrelatedBeta`] is [`Masking::Correlated`] here).
    pub fn with_masking(mut self, masking: Masking) -> Self {
        self.masking = masking;
        self
    }

    /// The distribution.
    pub fn distribution(&self) -> &D {
        &self.dist
    }

    /// The half vector of a pair the rough lobe reaches (same side, neither on the horizon, a
    /// rough surface), else `None`: what `eval`, `pdf` and `eval_pdf` share.
    #[inline(always)]
    fn lobe_normal(&self, wo: [F; 3], wi: [F; 3]) -> Option<[F; 3]> {
        if !same_hemisphere(wo, wi)
            || on_horizon(wo[2])
            || on_horizon(wi[2])
            || self.dist.effectively_smooth()
        {
            return None;
        }
        half_vector_reflection(wo, wi)
    }

    /// (The slice kernels' view: the Fresnel term and the masking.)
    pub(crate) fn fresnel_masking(&self) -> (&Fr, Masking) {
        (&self.fresnel, self.masking)
    }
}

impl<F: Real, D: MicrofacetDistribution<F>, Fr: Fresnel<F, N>, const N: usize> Bsdf<F>
    for RoughConductor<F, D, Fr, N>
{
    type Value = [F; N];

    #[inline]
    fn eval(&self, wo: [F; 3], wi: [F; 3]) -> [F; N] {
        let Some(wm) = self.lobe_normal(wo, wi) else {
            return [F::ZERO; N];
        };
        // F at the mean of |wo·wm| and |wi·wm| (equal but for rounding, which the half
        // vector's 1/|wo + wi| magnifies toward backscatter): f(wo, wi) = f(wi, wo) up to
        // G2's rounding, as reciprocity has it.
        let fr = self
            .fresnel
            .eval(F::HALF * (dot(wo, wm).abs() + dot(wi, wm).abs()));
        let k = reflected(&self.dist, self.masking, wo, wi, self.dist.d(wm));
        fr.map(|f| weighted(f, k))
    }

    #[inline]
    fn pdf(&self, wo: [F; 3], wi: [F; 3]) -> F {
        let Some(wm) = self.lobe_normal(wo, wi) else {
            return F::ZERO;
        };
        self.dist.pdf(wo, wm) / (F::from_f64(4.0) * dot(wo, wm).abs())
    }

    #[inline]
    fn eval_pdf(&self, wo: [F; 3], wi: [F; 3]) -> ([F; N], F) {
        // `eval` and `pdf` with their shared part once: the same operations on the same
        // numbers, so bit for bit theirs.
        let Some(wm) = self.lobe_normal(wo, wi) else {
            return ([F::ZERO; N], F::ZERO);
        };
        let co = dot(wo, wm).abs();
        let fr = self.fresnel.eval(F::HALF * (co + dot(wi, wm).abs()));
        let k = reflected(&self.dist, self.masking, wo, wi, self.dist.d(wm));
        let pdf = self.dist.pdf(wo, wm) / (F::from_f64(4.0) * co);
        (fr.map(|f| weighted(f, k)), pdf)
    }

    #[inline]
    fn sample(&self, wo: [F; 3], _uc: F, u: [F; 2]) -> Option<BsdfSample<F, [F; N]>> {
        if on_horizon(wo[2]) {
            return None;
        }
        if self.dist.effectively_smooth() {
            let wi = [-wo[0], -wo[1], wo[2]];
            let k = F::ONE / wi[2].abs();
            return Some(BsdfSample {
                wi,
                f: self.fresnel.eval(wo[2].abs()).map(|f| f * k),
                pdf: F::ONE,
                lobe: Lobe::Reflection,
                specular: true,
                eta: F::ONE,
            });
        }
        let s = self.dist.sample(wo, u);
        let wi = reflect(wo, s.wm);
        if !same_hemisphere(wo, wi) || on_horizon(wi[2]) {
            return None;
        }
        let c = dot(wo, s.wm).abs();
        let pdf = s.pdf / (F::from_f64(4.0) * c);
        if !usable(pdf) {
            return None;
        }
        let fr = self.fresnel.eval(c);
        let k = reflected(
            &self.dist,
            self.masking,
            wo,
            wi,
            sampled_d(&self.dist, s.wm)?,
        );
        let f = fr.map(|f| weighted(f, k));
        if !all_finite(&f) {
            return None;
        }
        Some(BsdfSample {
            wi,
            f,
            pdf,
            lobe: Lobe::Reflection,
            specular: false,
            eta: F::ONE,
        })
    }
}

/// A rough dielectric interface of relative index η = η_inside/η_outside; f is grey, the
/// same value in each of its N channels (RGB by default: [`RoughDielectric::new`]; any N by
/// [`RoughDielectric::with_channels`]), so that it composes with the conductors
/// ([`Bsdf`]'s `Value = [F; N]`).
///
/// **The transmission's masking.** The default G2, pbrt-v4's 1/(1 + Λo + Λi), is exact for
/// the reflection only; for a transmission the exact height-correlated form is
/// B(1 + Λo, 1 + Λi) ([`Masking::CorrelatedBeta`], by [`RoughDielectric::with_masking`]),
/// the random walk's order 1. They agree where Λo or Λi is 0 (normal incidence) and part
/// where both are large. Measured: the transmitted directional albedo (importance transport)
/// of GGX at η = 1.5 seen from outside, by the quadrature over the normal
/// ([`crate::scattering::single_scattering_albedo_dielectric_level`]), against the walk's
/// order 1 ([`crate::scattering::albedo`], 10⁶ walks; ± one standard error):
///
/// | α | μo | default, 1/(1 + Λo + Λi) | `CorrelatedBeta`, B(1 + Λo, 1 + Λi) | walk, order 1 |
/// |---|---|---|---|---|
/// | 0.1 | 0.05 | 0.5778 | 0.5716 | 0.5725 ± 0.0005 |
/// | 0.1 | 0.5 | 0.9064 | 0.9063 | 0.9056 ± 0.0003 |
/// | 0.1 | 1 | 0.9592 | 0.9592 | 0.9591 ± 0.0002 |
/// | 0.5 | 0.05 | 0.7697 | 0.3607 | 0.3607 ± 0.0005 |
/// | 0.5 | 0.5 | 0.8487 | 0.8330 | 0.8327 ± 0.0004 |
/// | 0.5 | 1 | 0.9399 | 0.9399 | 0.9397 ± 0.0002 |
/// | 1 | 0.05 | 0.7278 | 0.0506 | 0.0504 ± 0.0002 |
/// | 1 | 0.5 | 0.7185 | 0.5890 | 0.5893 ± 0.0005 |
/// | 1 | 1 | 0.8806 | 0.8806 | 0.8810 ± 0.0003 |
///
/// From inside the gap is wider (α = 1, μo = 0.05: 0.0403 against 1.1e-6); the reflection
/// is the same in both. docs/derivations.md G has both sides and the separable form.
/// Energy compensation ([`crate::scattering::CompensatedDielectric`]) is built on the
/// default.
#[derive(Clone, Debug)]
pub struct RoughDielectric<F, D, const N: usize = 3> {
    dist: D,
    eta: F,
    masking: Masking,
    transport: Transport,
}

impl<F: Real, D: MicrofacetDistribution<F>> RoughDielectric<F, D, 3> {
    /// The interface with relative index η > 0 (η = 1: no interface, a pass-through delta
    /// lobe), height-correlated G2, radiance transport; f in three (RGB) channels.
    /// [`ParamError::Eta`] for η NaN, infinite or ≤ 0 (at η = 0 every value was NaN; a
    /// negative η gave plausible-looking transmission).
    pub fn new(dist: D, eta: F) -> Result<Self, ParamError> {
        crate::error::check_eta(eta.to_f64())?;
        Ok(RoughDielectric {
            dist,
            eta,
            masking: Masking::Correlated,
            transport: Transport::Radiance,
        })
    }
}

impl<F: Real, D: MicrofacetDistribution<F>, const N: usize> RoughDielectric<F, D, N> {
    /// The same interface with f in M channels (a spectral renderer's, or one).
    pub fn with_channels<const M: usize>(self) -> RoughDielectric<F, D, M> {
        RoughDielectric {
            dist: self.dist,
            eta: self.eta,
            masking: self.masking,
            transport: self.transport,
        }
    }

    /// The same with another masking-shadowing term (see the type's docs for what
    /// [`Masking::CorrelatedBeta`] changes); sampling is the same for every form (visible
    /// normals and the Fresnel choice do not depend on G2), so only f changes.
    pub fn with_masking(mut self, masking: Masking) -> Self {
        self.masking = masking;
        self
    }

    /// The same for the other transport direction.
    pub fn with_transport(mut self, transport: Transport) -> Self {
        self.transport = transport;
        self
    }

    /// The distribution.
    pub fn distribution(&self) -> &D {
        &self.dist
    }

    /// η.
    pub fn eta(&self) -> F {
        self.eta
    }

    fn smooth(&self) -> bool {
        self.eta == F::ONE || self.dist.effectively_smooth()
    }

    /// The half vector of (wo, wi) and η' (1 for reflection), if the pair is a reflection or
    /// a refraction through a microfacet facing both; None otherwise.
    #[inline(always)]
    fn half(&self, wo: [F; 3], wi: [F; 3]) -> Option<([F; 3], F, bool)> {
        let (co, ci) = (wo[2], wi[2]);
        if on_horizon(co) || on_horizon(ci) {
            return None;
        }
        let reflection = co * ci > F::ZERO;
        let (wm, etap) = if reflection {
            (half_vector_reflection(wo, wi)?, F::ONE)
        } else {
            half_vector_refraction(wo, wi, self.eta)?
        };
        // Microfacets facing away from either direction: no contribution.
        if dot(wm, wi) * ci < F::ZERO || dot(wm, wo) * co < F::ZERO {
            return None;
        }
        Some((wm, etap, reflection))
    }

    /// f for a transmission through wm (one-sided η').
    #[inline(always)]
    fn f_transmission(&self, wo: [F; 3], wi: [F; 3], wm: [F; 3], d_wm: F, etap: F, t: F) -> F {
        let (di, d_o) = (dot(wi, wm), dot(wo, wm));
        let s = refraction_denominator(wo, wi, wm, etap);
        // G2/|cos θo cos θi| before the 1/s² (≥ (η' − 1)²/η'², 5e-32 at η' = 1 + 2⁻⁵²): the
        // cosines' product stays normal above the horizon floor, times s² it could underflow.
        let geometric = self.masking.g2(&self.dist, wo, wi) / (wi[2] * wo[2]).abs()
            * ((di * d_o).abs() / (s * s));
        let mut f = d_wm * t * geometric;
        if self.transport == Transport::Radiance {
            f = f / (etap * etap);
        }
        f
    }
}

impl<F: Real, D: MicrofacetDistribution<F>, const N: usize> Bsdf<F> for RoughDielectric<F, D, N> {
    type Value = [F; N];

    #[inline]
    fn eval(&self, wo: [F; 3], wi: [F; 3]) -> [F; N] {
        [self.eval_grey(wo, wi); N]
    }

    #[inline]
    fn pdf(&self, wo: [F; 3], wi: [F; 3]) -> F {
        self.pdf_grey(wo, wi)
    }

    #[inline]
    fn sample(&self, wo: [F; 3], uc: F, u: [F; 2]) -> Option<BsdfSample<F, [F; N]>> {
        self.sample_grey(wo, uc, u).map(|s| s.map_f(|f| [f; N]))
    }
}

impl<F, V> BsdfSample<F, V> {
    /// The same sample with f mapped.
    #[inline(always)]
    pub(crate) fn map_f<W>(self, g: impl FnOnce(V) -> W) -> BsdfSample<F, W> {
        BsdfSample {
            wi: self.wi,
            f: g(self.f),
            pdf: self.pdf,
            lobe: self.lobe,
            specular: self.specular,
            eta: self.eta,
        }
    }
}

impl<F: Real, D: MicrofacetDistribution<F>, const N: usize> RoughDielectric<F, D, N> {
    /// f(wo, wi), one channel.
    #[inline]
    pub(crate) fn eval_grey(&self, wo: [F; 3], wi: [F; 3]) -> F {
        if self.smooth() {
            return F::ZERO;
        }
        let Some((wm, etap, reflection)) = self.half(wo, wi) else {
            return F::ZERO;
        };
        let r = fresnel::dielectric(dot(wo, wm), self.eta);
        if reflection {
            r * reflected(&self.dist, self.masking, wo, wi, self.dist.d(wm))
        } else {
            let d_wm = self.dist.d(wm);
            self.f_transmission(wo, wi, wm, d_wm, etap, F::ONE - r)
        }
    }

    /// The pdf of [`RoughDielectric::sample_grey`].
    #[inline]
    pub(crate) fn pdf_grey(&self, wo: [F; 3], wi: [F; 3]) -> F {
        if self.smooth() {
            return F::ZERO;
        }
        let Some((wm, etap, reflection)) = self.half(wo, wi) else {
            return F::ZERO;
        };
        let r = fresnel::dielectric(dot(wo, wm), self.eta);
        let pdf_wm = self.dist.pdf(wo, wm);
        if reflection {
            pdf_wm * r / (F::from_f64(4.0) * dot(wo, wm).abs())
        } else {
            pdf_wm * (F::ONE - r) * jacobian_refraction(wo, wi, wm, etap)
        }
    }

    /// A sample with f in one channel.
    #[inline]
    pub(crate) fn sample_grey(&self, wo: [F; 3], uc: F, u: [F; 2]) -> Option<BsdfSample<F, F>> {
        if on_horizon(wo[2]) {
            return None;
        }
        if self.smooth() {
            return self.sample_smooth(wo, uc);
        }
        let s = self.dist.sample(wo, u);
        let wm = s.wm;
        let c = dot(wo, wm);
        let r = fresnel::dielectric(c, self.eta);
        if uc < r {
            let wi = reflect(wo, wm);
            if !same_hemisphere(wo, wi) || on_horizon(wi[2]) {
                return None;
            }
            let f = r * reflected(&self.dist, self.masking, wo, wi, sampled_d(&self.dist, wm)?);
            let pdf = s.pdf * r / (F::from_f64(4.0) * c.abs());
            if !usable(pdf) || !all_finite(&[f]) {
                return None;
            }
            return Some(BsdfSample {
                wi,
                f,
                pdf,
                lobe: Lobe::Reflection,
                specular: false,
                eta: F::ONE,
            });
        }
        let (wi, etap) = refract(wo, wm, self.eta)?;
        if same_hemisphere(wo, wi) || on_horizon(wi[2]) {
            return None;
        }
        let t = F::ONE - r;
        let pdf = s.pdf * t * jacobian_refraction(wo, wi, wm, etap);
        let f = self.f_transmission(wo, wi, wm, sampled_d(&self.dist, wm)?, etap, t);
        if !usable(pdf) || !all_finite(&[f]) {
            return None;
        }
        Some(BsdfSample {
            wi,
            f,
            pdf,
            lobe: Lobe::Transmission,
            specular: false,
            eta: etap,
        })
    }
}

impl<F: Real, D: MicrofacetDistribution<F>, const N: usize> RoughDielectric<F, D, N> {
    /// The smooth interface's delta lobes.
    fn sample_smooth(&self, wo: [F; 3], uc: F) -> Option<BsdfSample<F, F>> {
        let r = fresnel::dielectric(wo[2], self.eta);
        if uc < r {
            let wi = [-wo[0], -wo[1], wo[2]];
            return Some(BsdfSample {
                wi,
                f: r / wi[2].abs(),
                pdf: r,
                lobe: Lobe::Reflection,
                specular: true,
                eta: F::ONE,
            });
        }
        let (wi, etap) = refract(wo, [F::ZERO, F::ZERO, F::ONE], self.eta)?;
        if on_horizon(wi[2]) {
            return None;
        }
        let t = F::ONE - r;
        let mut f = t / wi[2].abs();
        if self.transport == Transport::Radiance {
            f = f / (etap * etap);
        }
        Some(BsdfSample {
            wi,
            f,
            pdf: t,
            lobe: Lobe::Transmission,
            specular: true,
            eta: etap,
        })
    }
}
