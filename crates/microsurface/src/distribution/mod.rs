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
//! **The generalised exponential** ([`crate::GenExponential`]) has no `Microfacet` type; it runs
//! through [`Exact`] (D closed form, Λ by quadrature, exact warps of tens to hundreds of
//! microseconds a sample). The two halves of a fast path are missing for it: its Λ₁ falls like
//! e^{−z^γ}, by 300 orders of magnitude between z = 1 and 1.4 at γ = 20 (z²⁰ goes from 190 to 2000
//! across the eighth octave above z = 1.3), which the family's eighth-octave polynomial tables of
//! ln Λ₁ ([`fast::fitted`]) cannot follow in relative terms; and above γ = 2 it is not a Beckmann
//! mixture, below it one over a positive stable law, so there is no posterior sampler for visible
//! normals (the family's other members draw theirs in a fraction of a microsecond). No renderer
//! ships it; Student-T covers the range between GGX's and Beckmann's tails that a renderer wants.
//!
//! **Evaluation.** The fast paths ([`crate::fast`]) by default: closed forms for GGX and
//! Beckmann, fitted tables (≤ 1e-7 relative) for Double GGX, the Exponential NDF and GTR.
//! Every NDF's D, and Λ of GGX, Beckmann and the family, are evaluated from the vector
//! ((x/αx)² + (y/αy)² and αx²x² + αy²y²: near the normal 1 − z² of a rounded unit vector has
//! lost its digits — an f32 normal 1e-3 from the pole of a Beckmann α = 2e-3 lobe moved D by
//! 1.3 % through its cosine — and the vector form is as cheap); so is Λ (and G1) of GGX,
//! Beckmann, Double GGX, Exponential and GTR (through 1 − z² an f32 direction 5e-7 from the
//! normal put G1 2 % off at α = 1e4). The other quantities call the fast scalar functions of
//! u = |w.z| as they are (bit for bit) for isotropic materials, and at the projected
//! roughness α̃ for anisotropic ones. Accuracy against the exact path (tests/bsdf.rs, D, G1 and the visible pdf at random
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
//!
//! [`Ggx`]: crate::Ggx
//! [`Beckmann`]: crate::Beckmann
//! [`DoubleGgx`]: crate::DoubleGgx
//! [`Exponential`]: crate::Exponential
//! [`Gtr`]: crate::Gtr
//! [`fast::fitted`]: crate::fast::fitted
//! [`ParamError::Anisotropic`]: crate::ParamError::Anisotropic

// `!(x > 0)` is the NaN-aware test (false for NaN) on a generic `Real`, on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod any;
mod exact;
pub(crate) mod kernels;
mod microfacet;

pub use any::{AnyMicrofacet, FIT_CACHE_CAPACITY};
pub use exact::Exact;
pub use microfacet::{GtrData, Microfacet, Shape};

use crate::math::dirs::{dot, normalize};
use crate::math::real::Real;
use crate::math::rng::SplitMix64;
use std::collections::HashMap;
use std::hash::Hash;
use std::sync::{Arc, Mutex, OnceLock};

/// A visible normal and its density w.r.t. the solid angle of the normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample<F> {
    /// The microfacet normal (unit, upper hemisphere, facing the sampled direction).
    pub wm: [F; 3],
    /// Its density: [`MicrofacetDistribution::pdf`]`(w, wm)`.
    pub pdf: F,
}

/// u with each component at most the largest value below 1 (1 − 2⁻²⁴ in f32, 1 − 2⁻⁵³ in
/// f64): u = 1 maps to the end of the warps' domain [0, 1) rather than to the horizon (a
/// normal with m.z = 0, which a BSDF's sample then rejects). NaN passes through.
#[inline(always)]
pub(crate) fn below_one<F: Real>(u: [F; 2]) -> [F; 2] {
    let top = F::from_f64(if F::IS_F32 {
        1.0 - 1.0 / 16_777_216.0
    } else {
        1.0 - f64::EPSILON / 2.0
    });
    u.map(|x| if x > top { top } else { x })
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

    /// Height-correlated G2(wo, wi) = 1/(1 + Λ(wo) + Λ(wi)), symmetric to the bit (Λo + Λi
    /// first: the BSDFs' reciprocity).
    #[inline]
    fn g2(&self, wo: [F; 3], wi: [F; 3]) -> F {
        F::ONE / (F::ONE + (self.lambda(wo) + self.lambda(wi)))
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
        d_visible_with(w, wm, || self.d(wm), || self.g1(w))
    }

    /// The density of [`MicrofacetDistribution::sample`]: [`MicrofacetDistribution::d_visible`].
    #[inline]
    fn pdf(&self, w: [F; 3], wm: [F; 3]) -> F {
        self.d_visible(w, wm)
    }

    /// A visible normal for w (w.z < 0 is mirrored) from u ∈ [0, 1)²; u = 1 (which a
    /// generator that rounds may return) is read as the largest value below 1, as pbrt's
    /// `OneMinusEpsilon`, by the library's samplers.
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
    /// visible slope by rejection on both sides, cheaper than its warp above)
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
            // (At w normalised: the samplers take any length, the pdf's formulas a unit w.)
            pdf: self.pdf(unit(w), wm),
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

/// D_w(wm) = G1(w) max(0, w·m) D(m)/|w.z| from D(wm) and G1(w) (the mirror image for
/// w.z < 0; 0 at grazing w and for wm behind the plane perpendicular to w): the formula of
/// [`MicrofacetDistribution::d_visible`], shared with the materials' own.
#[inline(always)]
pub(crate) fn d_visible_with<F: Real>(
    w: [F; 3],
    wm: [F; 3],
    d: impl FnOnce() -> F,
    g1: impl FnOnce() -> F,
) -> F {
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
    let d = d();
    if d.to_f64() == f64::INFINITY {
        // D's pole (the family's singular members at m = (0, 0, 1)), where g1·c can
        // underflow to 0: the density is +∞ there, not NaN.
        return d;
    }
    // (In this order: g1 ~ z/σ(0) cancels the 1/z of a direction near the horizon.)
    g1() * c * d / z
}

/// w as a unit vector: w itself where it is one to rounding (one dot product: the common
/// case), else rescaled by its largest part and normalised (any finite nonzero length; at
/// 1e300 or 1e-300 its squares would overflow or underflow). Zero and NaN come back as
/// they are.
#[inline(always)]
pub(crate) fn unit<F: Real>(w: [F; 3]) -> [F; 3] {
    let n2 = dot(w, w);
    // (A rounded unit vector is within a few ε of length 1.)
    let tol = F::from_f64(if F::IS_F32 { 1e-6 } else { 1e-14 });
    if (n2 - F::ONE).abs() <= tol {
        w
    } else {
        unit_cold(w)
    }
}

#[cold]
#[inline(never)]
fn unit_cold<F: Real>(w: [F; 3]) -> [F; 3] {
    let m = w[0].abs().max(w[1].abs()).max(w[2].abs());
    if !(m > F::ZERO && m < F::from_f64(f64::INFINITY)) {
        return w;
    }
    // (`normalize` scales in f64 by a division: 1/m overflowed f32 for a subnormal m, and a
    // w of components ~1e-41 became NaN, its pdf with it.)
    normalize(w)
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

/// A process-wide cache of fits or tables ([`crate::AnyMicrofacet::FIT_CACHE_CAPACITY`]
/// entries), the computed tables' (by `Arc`).
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

/// The key of a family member's shape in the per-shape caches: the shape's bits for the
/// kinds that have one (NaN, a missing shape, which no fit or member is made for, so an
/// error on every call), 0 for those that ignore it (their one entry is found).
pub(crate) fn shape_key(kind: crate::NdfKind, shape: Option<f64>) -> (crate::NdfKind, u64) {
    match kind.shape_name() {
        Some(_) => (kind, shape.unwrap_or(f64::NAN).to_bits()),
        None => (kind, 0),
    }
}

/// A fit shared by every material of its shape: the process-wide one (`Static`, kept for the
/// process: the cache never evicts, so holding it by reference costs no reference count, and
/// a material is built without an atomic operation), or one fitted for its material alone
/// once the cache is full (`Own`).
#[doc(hidden)]
#[derive(Debug)]
pub enum Fit<V: 'static> {
    /// The process-wide fit of its shape.
    Static(&'static V),
    /// A fit of this material alone (the cache was full).
    Own(Arc<V>),
}

impl<V> Clone for Fit<V> {
    #[inline]
    fn clone(&self) -> Self {
        match self {
            Fit::Static(v) => Fit::Static(v),
            Fit::Own(v) => Fit::Own(v.clone()),
        }
    }
}

impl<V> std::ops::Deref for Fit<V> {
    type Target = V;
    #[inline(always)]
    fn deref(&self) -> &V {
        match self {
            Fit::Static(v) => v,
            Fit::Own(v) => v,
        }
    }
}

/// The process-wide fits of one kind (a shape's, GTR's): a map from key to fit behind a
/// lock, in front of it each thread's last hit (`last`, a `thread_local!` of the call site),
/// so that a renderer building a material per shading point, with the shape fixed and α
/// textured, pays one thread-local read and a key comparison (no lock, no hash, no
/// reference count: BENCHMARKS.md, "Materials per call").
pub(crate) type SharedFits<K, V> = OnceLock<Mutex<HashMap<K, &'static V>>>;

/// The fit of `key` (validated by `make`, which returns its typed error on a miss: a hit
/// was validated when it was made): from this thread's last hit, the process-wide map, or
/// `make`, run outside the lock and then kept for the process (leaked, while the map has
/// room: at most [`crate::distribution::FIT_CACHE_CAPACITY`] fits, each a few kilobytes),
/// or, once the map is full, kept by this material alone.
pub(crate) fn shared_fit<K: Copy + Eq + Hash + 'static, V: Send + Sync + 'static, E>(
    cache: &'static SharedFits<K, V>,
    last: &'static std::thread::LocalKey<std::cell::Cell<Option<(K, &'static V)>>>,
    key: K,
    make: impl FnOnce() -> Result<V, E>,
) -> Result<Fit<V>, E> {
    if let Some((k, v)) = last.with(|c| c.get()) {
        if k == key {
            return Ok(Fit::Static(v));
        }
    }
    let map = cache.get_or_init(Default::default);
    let hit = map
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .get(&key)
        .copied();
    let v: &'static V = match hit {
        Some(v) => v,
        None => {
            let fresh = make()?;
            let mut m = map.lock().unwrap_or_else(|e| e.into_inner());
            match m.get(&key) {
                Some(v) => v,
                None if m.len() < crate::distribution::any::FIT_CACHE_CAPACITY => {
                    let v: &'static V = Box::leak(Box::new(fresh));
                    m.insert(key, v);
                    v
                }
                None => return Ok(Fit::Own(Arc::new(fresh))),
            }
        }
    };
    last.with(|c| c.set(Some((key, v))));
    Ok(Fit::Static(v))
}
