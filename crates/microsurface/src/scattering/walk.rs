//! The microsurface random walk: see the [`crate::scattering`] docs.

// `!(x > 0)` is the NaN-aware test (false for NaN), on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::albedo::{ByOrder, OrderSums};
use crate::bsdf::frame::{dot, reflect};
use crate::bsdf::fresnel::Fresnel;
use crate::bsdf::{Bsdf, BsdfSample, Lobe, Transport};
use crate::distribution::{unit, MicrofacetDistribution};
use crate::math::real::Real;
use crate::math::rng::SplitMix64;

/// The distribution of microsurface heights (the BSDF does not depend on it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Heights {
    /// Uniform on [−1, 1]: C1(h) = (h + 1)/2.
    #[default]
    Uniform,
    /// Standard normal: C1(h) = Φ(h) = erfc(−h/√2)/2.
    Gaussian,
}

impl Heights {
    /// The height of ℓ = ln C1(h), as the walk keeps it (module docs): ℓ itself for uniform
    /// heights; for Gaussian heights ℓ rounded through the physical height h = Φ⁻¹(e^ℓ).
    #[inline]
    fn settle(self, l: f64) -> f64 {
        match self {
            Heights::Uniform => l,
            Heights::Gaussian => Self::gaussian_l(Self::gaussian_h(l)),
        }
    }

    /// The height ℓ of −h, the same point seen from the other medium: C1(−h) = 1 − C1(h).
    #[inline]
    fn cross(self, l: f64) -> f64 {
        let l = match self {
            // ln(1 − e^ℓ) without cancellation (Mächler 2012, "Accurately computing
            // log(1 − exp(−|a|))": expm1 above −ln 2, ln_1p below).
            Heights::Uniform if l > -std::f64::consts::LN_2 => (-l.exp_m1()).ln(),
            Heights::Uniform => (-l.exp()).ln_1p(),
            Heights::Gaussian => Self::gaussian_l(-Self::gaussian_h(l)),
        };
        // (A crossing at the very top, ℓ = −0 after a free path that rounded away, lands at
        // C1 = 0, from where no path moves: the lowest normal f64 instead, ln 2^−1022.)
        if l < LN_MIN_POSITIVE {
            LN_MIN_POSITIVE
        } else {
            l
        }
    }

    /// The standard normal height of ℓ (+∞ at the top, ℓ = 0).
    fn gaussian_h(l: f64) -> f64 {
        // (e^ℓ underflows below ℓ ≈ −745: the lowest height erfinv resolves.)
        let c = l.exp().clamp(f64::MIN_POSITIVE, 1.0);
        std::f64::consts::SQRT_2 * crate::fast::beckmann::erfinv_2u_minus_1(c)
    }

    /// ℓ = ln Φ(h) for a standard normal height.
    fn gaussian_l(h: f64) -> f64 {
        (0.5 * crate::math::special::erfc(-h * std::f64::consts::FRAC_1_SQRT_2)).ln()
    }
}

/// ln of the smallest normal f64, 2^−1022.
const LN_MIN_POSITIVE: f64 = -708.396_418_532_264_1;

/// A 53-bit uniform strictly inside (0, 1): (k + ½)/2⁵³ for the top 53 bits k of a
/// SplitMix64 output (Steele, Lea & Flood 2014).
#[derive(Clone, Debug)]
pub struct WalkRng(SplitMix64);

impl WalkRng {
    /// The stream of `seed`.
    pub fn new(seed: u64) -> Self {
        WalkRng(SplitMix64(seed ^ 0x5851_F42D_4C95_7F2D))
    }

    /// The next uniform in (0, 1).
    #[inline]
    pub fn next_open(&mut self) -> f64 {
        ((self.0.next_u64() >> 11) as f64 + 0.5) * (1.0 / 9_007_199_254_740_992.0)
    }
}

/// What a scattering event did: the direction the ray leaves in, the weight that multiplies
/// the path's, and whether it crossed into the other medium (a dielectric's refraction).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scattered<const N: usize> {
    /// The new travel direction, in the frame of the side the ray arrived on (see
    /// [`Facets`]).
    pub w: [f64; 3],
    /// The facet's weight per channel.
    pub weight: [f64; N],
    /// Whether the ray crossed the interface.
    pub crossed: bool,
}

/// What the microfacets do with a ray: the phase function of the microflake volume given
/// the facet (sampled by [`Facets::scatter`]) and its density (evaluated by
/// [`Facets::phase`], the stochastic evaluation's next-event estimate).
///
/// **Frames.** Both work in the frame of the side the ray is on: outside (above the
/// macrosurface) the local frame itself; inside (below, a dielectric's lower medium, or the
/// mirrored microsurface of a conductor seen from below) every vector negated, so that the
/// ray's own medium is always z > 0 and the facets' normals point up. `inside` says which
/// side it is, for a relative index that differs between the two.
pub trait Facets<const N: usize> {
    /// The relative index η = η_inside/η_outside of facets that transmit (the walk then
    /// crosses between media); `None` for opaque facets.
    fn interface_eta(&self) -> Option<f64> {
        None
    }

    /// Scatter a ray that arrived from v (v = −w, the reverse of its travel) off the facet
    /// wm (v·wm > 0). `None`: absorbed (the path ends with weight 0).
    fn scatter(
        &self,
        v: [f64; 3],
        wm: [f64; 3],
        inside: bool,
        rng: &mut WalkRng,
    ) -> Option<Scattered<N>>;

    /// The phase function's density per unit solid angle for leaving in w having arrived
    /// from v, over the facets visible from v: a reflection (w on v's side) or, with
    /// `crossed`, a transmission (w into the other medium, w·wm < 0 for the facet). Its
    /// integral over the sphere of w, both kinds together, is the facets' albedo
    /// (E\[weight\]). Stochastic where the facet's own lobe is not a delta (diffuse facets
    /// draw one visible normal): unbiased.
    fn phase<D: MicrofacetDistribution<f64>>(
        &self,
        surface: &RandomWalk<D>,
        v: [f64; 3],
        w: [f64; 3],
        crossed: bool,
        inside: bool,
        rng: &mut WalkRng,
    ) -> [f64; N];

    /// The density per unit solid angle of single scattering's sampling from wo (wo.z > 0
    /// in the side's frame): a visible normal, then the facet's lobe. Closed for mirror and
    /// dielectric facets; diffuse facets answer the cosine lobe about the macronormal (the
    /// closed form is an integral over the normals). [`MultipleScattering::pdf`] adds a
    /// floor to it.
    fn single_pdf<D: MicrofacetDistribution<f64>>(
        &self,
        surface: &RandomWalk<D>,
        wo: [f64; 3],
        wi: [f64; 3],
        inside: bool,
    ) -> f64;

    /// Whether each facet scatters into a delta lobe (a mirror, a smooth interface): then
    /// [`Facets::phase`] toward a direction that mirrors or refracts the path's into it is as
    /// high as D's peak allows, and the stochastic evaluation's orders ≥ 2 are spiky, which
    /// [`MultipleScattering::pdf`] answers with a larger floor. True unless a type says
    /// otherwise ([`DiffuseFacets`]: false).
    fn specular(&self) -> bool {
        true
    }
}

/// The half vector of a refraction from v (on the facets' side) into w (the other medium)
/// at relative index η, turned up, if the facet faces v and turns its back on w (Walter et
/// al. 2007, eqs. 16–17: wm ∝ v + η w).
fn refraction_half(v: [f64; 3], w: [f64; 3], eta: f64) -> Option<[f64; 3]> {
    let h = [v[0] + eta * w[0], v[1] + eta * w[1], v[2] + eta * w[2]];
    let l = dot(h, h).sqrt();
    let s = if h[2] < 0.0 { -1.0 / l } else { 1.0 / l };
    let wm = [h[0] * s, h[1] * s, h[2] * s];
    (dot(v, wm) > 0.0 && dot(w, wm) < 0.0).then_some(wm)
}

/// The mirror reflection's half vector of v and w, if it points up.
fn reflection_half(v: [f64; 3], w: [f64; 3]) -> Option<[f64; 3]> {
    let h = [v[0] + w[0], v[1] + w[1], v[2] + w[2]];
    let l = dot(h, h).sqrt();
    (l > 0.0 && h[2] > 0.0).then(|| [h[0] / l, h[1] / l, h[2] / l])
}

/// Mirror facets with a Fresnel term (a conductor; `fresnel::One::<1>` for the white
/// furnace).
#[derive(Clone, Copy, Debug)]
pub struct MirrorFacets<Fr>(pub Fr);

impl<Fr: Fresnel<f64, N>, const N: usize> Facets<N> for MirrorFacets<Fr> {
    #[inline]
    fn scatter(&self, v: [f64; 3], wm: [f64; 3], _: bool, _: &mut WalkRng) -> Option<Scattered<N>> {
        Some(Scattered {
            w: reflect(v, wm),
            weight: self.0.eval(dot(v, wm).abs()),
            crossed: false,
        })
    }

    fn phase<D: MicrofacetDistribution<f64>>(
        &self,
        surface: &RandomWalk<D>,
        v: [f64; 3],
        w: [f64; 3],
        crossed: bool,
        _: bool,
        _: &mut WalkRng,
    ) -> [f64; N] {
        match surface.mirror_phase(v, w) {
            Some((p, c)) if !crossed => self.0.eval(c).map(|f| f * p),
            _ => [0.0; N],
        }
    }

    fn single_pdf<D: MicrofacetDistribution<f64>>(
        &self,
        surface: &RandomWalk<D>,
        wo: [f64; 3],
        wi: [f64; 3],
        _: bool,
    ) -> f64 {
        match reflection_half(wo, wi) {
            Some(wm) if wi[2] > 0.0 => surface.dist.pdf(wo, wm) / (4.0 * dot(wo, wm)),
            _ => 0.0,
        }
    }
}

/// Lambertian facets of albedo ρ (Heitz et al.'s diffuse microsurface): the ray leaves in a
/// cosine-weighted direction about the facet's normal, weight ρ.
#[derive(Clone, Copy, Debug)]
pub struct DiffuseFacets(pub f64);

/// (Grey: the same weight in each of N channels, so that the facets serve any spectrum.)
impl<const N: usize> Facets<N> for DiffuseFacets {
    fn scatter(
        &self,
        _v: [f64; 3],
        wm: [f64; 3],
        _: bool,
        rng: &mut WalkRng,
    ) -> Option<Scattered<N>> {
        // A cosine-weighted direction in wm's frame.
        let local = crate::bsdf::frame::cosine_hemisphere([rng.next_open(), rng.next_open()]);
        let frame = crate::bsdf::frame::Frame::from_normal(wm);
        Some(Scattered {
            w: frame.from_local(local),
            weight: [self.0; N],
            crossed: false,
        })
    }

    /// ρ max(0, wm·w)/π for one visible normal wm drawn from v (the paper's stochastic
    /// evaluation of the diffuse microflakes' phase function).
    fn phase<D: MicrofacetDistribution<f64>>(
        &self,
        surface: &RandomWalk<D>,
        v: [f64; 3],
        w: [f64; 3],
        crossed: bool,
        _: bool,
        rng: &mut WalkRng,
    ) -> [f64; N] {
        if crossed {
            return [0.0; N];
        }
        let wm = surface.visible_normal(v, rng);
        [self.0 * dot(wm, w).max(0.0) * std::f64::consts::FRAC_1_PI; N]
    }

    fn single_pdf<D: MicrofacetDistribution<f64>>(
        &self,
        _: &RandomWalk<D>,
        _: [f64; 3],
        wi: [f64; 3],
        _: bool,
    ) -> f64 {
        wi[2].max(0.0) * std::f64::consts::FRAC_1_PI
    }

    fn specular(&self) -> bool {
        false
    }
}

/// Smooth dielectric facets of relative index η = η_inside/η_outside (the macrosurface's
/// lower medium is inside): each facet reflects with the Fresnel probability R(v·wm) and
/// refracts otherwise (weight 1: the walk transports importance, Veach 1997 §5.2, and
/// [`MultipleScattering`] applies radiance's 1/η'² once at the end).
#[derive(Clone, Copy, Debug)]
pub struct DielectricFacets(pub(crate) f64);

impl DielectricFacets {
    /// The facets of relative index η: [`crate::ParamError::Eta`] for η NaN, infinite or
    /// ≤ 0 (a negative η gave plausible-looking transmission). η = 1 is no interface: the
    /// walk's BSDF is then a delta lobe straight through.
    pub fn new(eta: f64) -> Result<Self, crate::ParamError> {
        Ok(DielectricFacets(crate::error::check_eta(eta)?))
    }

    /// The relative index η.
    pub fn index(&self) -> f64 {
        self.0
    }

    /// The relative index across the interface from the side the ray is on.
    #[inline]
    fn eta(&self, inside: bool) -> f64 {
        if inside {
            1.0 / self.0
        } else {
            self.0
        }
    }
}

/// (Grey: the same weight in each of N channels.)
impl<const N: usize> Facets<N> for DielectricFacets {
    fn interface_eta(&self) -> Option<f64> {
        Some(self.0)
    }

    fn scatter(
        &self,
        v: [f64; 3],
        wm: [f64; 3],
        inside: bool,
        rng: &mut WalkRng,
    ) -> Option<Scattered<N>> {
        let eta = self.eta(inside);
        let r = crate::bsdf::fresnel::dielectric(dot(v, wm), eta);
        if rng.next_open() >= r {
            if let Some((t, _)) = crate::bsdf::frame::refract(v, wm, eta) {
                return Some(Scattered {
                    w: t,
                    weight: [1.0; N],
                    crossed: true,
                });
            }
        }
        Some(Scattered {
            w: reflect(v, wm),
            weight: [1.0; N],
            crossed: false,
        })
    }

    fn phase<D: MicrofacetDistribution<f64>>(
        &self,
        surface: &RandomWalk<D>,
        v: [f64; 3],
        w: [f64; 3],
        crossed: bool,
        inside: bool,
        _: &mut WalkRng,
    ) -> [f64; N] {
        let eta = self.eta(inside);
        if !crossed {
            return match surface.mirror_phase(v, w) {
                Some((p, c)) => [crate::bsdf::fresnel::dielectric(c, eta) * p; N],
                None => [0.0; N],
            };
        }
        let Some(wm) = refraction_half(v, w, eta) else {
            return [0.0; N];
        };
        let cv = dot(v, wm);
        let sigma = surface.sigma(v);
        let t = 1.0 - crate::bsdf::fresnel::dielectric(cv, eta);
        let p = t * surface.dist.d(wm) * cv / sigma
            * crate::bsdf::frame::jacobian_refraction(v, w, wm, eta);
        [if p.is_finite() { p } else { 0.0 }; N]
    }

    fn single_pdf<D: MicrofacetDistribution<f64>>(
        &self,
        surface: &RandomWalk<D>,
        wo: [f64; 3],
        wi: [f64; 3],
        inside: bool,
    ) -> f64 {
        let eta = self.eta(inside);
        let p = if wi[2] > 0.0 {
            let Some(wm) = reflection_half(wo, wi) else {
                return 0.0;
            };
            let c = dot(wo, wm);
            surface.dist.pdf(wo, wm) * crate::bsdf::fresnel::dielectric(c, eta) / (4.0 * c)
        } else {
            let Some(wm) = refraction_half(wo, wi, eta) else {
                return 0.0;
            };
            let c = dot(wo, wm);
            surface.dist.pdf(wo, wm)
                * (1.0 - crate::bsdf::fresnel::dielectric(c, eta))
                * crate::bsdf::frame::jacobian_refraction(wo, wi, wm, eta)
        };
        if p.is_finite() {
            p
        } else {
            0.0
        }
    }
}

/// One walk's result.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Walked<const N: usize> {
    /// The direction the path leaves the microsurface in, in the macrosurface's frame
    /// (z > 0: reflected to wo's side or, for a dielectric, either side).
    pub w: [f64; 3],
    /// The product of the facets' weights.
    pub weight: [f64; N],
    /// The number of scattering events (≥ 1).
    pub order: u32,
}

/// Walks longer than this are cut ([`RandomWalk::walk`] answers `None`, which [`albedo`](crate::scattering::albedo())
/// counts as weight 0). The mean order of an F = 1 conductor at normal incidence grows with
/// the roughness, about 3α (measured for GGX: 26 at α = 10, 305 at α = 100, 3130 at
/// α = 1000), so walks are cut, and energy lost, only on surfaces far rougher than any
/// material (α ≳ 300); at α ≤ 2 the mean order is below 4. (And through dielectric facets
/// of η = 1, a transparent interface, a ray keeps its direction: from |wo.z| ≲ 1e-3 it
/// crosses the microsurface about α/|wo.z| times and is cut.)
pub const MAX_ORDER: u32 = 10_000;

/// The stochastic evaluation's estimate of f(wo, wi)|cos θi| by order: orders 1, 2, 3 and
/// ≥ 4 (index 3), per channel. (The walk transports importance: a dielectric's transmitted
/// value is [`crate::bsdf::Transport::Importance`]'s.)
pub type OrderValues<const N: usize> = [[f64; N]; 4];

/// A walk's state between steps: the travel direction and height ℓ = ln C1 in the frame of
/// the side it is on, the weight so far, the side, and the number of events so far.
#[derive(Clone, Copy, Debug)]
struct Path<const N: usize> {
    w: [f64; 3],
    h: f64,
    weight: [f64; N],
    inside: bool,
    order: u32,
}

impl<const N: usize> Path<N> {
    /// A path arriving along −wo (wo a finite unit vector off the horizon) at the top.
    #[inline]
    fn start(wo: [f64; 3]) -> Self {
        let inside = wo[2] < 0.0;
        Path {
            w: if inside { wo } else { [-wo[0], -wo[1], -wo[2]] },
            h: 0.0,
            weight: [1.0; N],
            inside,
            order: 0,
        }
    }
}

/// The microsurface of a distribution with a height distribution: the walk's state-free part.
#[derive(Clone, Debug)]
pub struct RandomWalk<D> {
    dist: D,
    heights: Heights,
}

impl<D: MicrofacetDistribution<f64>> RandomWalk<D> {
    /// The microsurface of `dist` with heights distributed as `heights`.
    pub fn new(dist: D, heights: Heights) -> Self {
        RandomWalk { dist, heights }
    }

    /// The distribution.
    pub fn distribution(&self) -> &D {
        &self.dist
    }

    /// Smith's Λ for a travel direction w of either hemisphere: Λ(w) above, −1 − Λ(−w) below
    /// (the paper's eq. 8; [`MicrofacetDistribution::lambda`] is Λ of the side w comes from).
    pub fn lambda_signed(&self, w: [f64; 3]) -> f64 {
        let l = self.dist.lambda(w);
        if w[2] >= 0.0 {
            l
        } else {
            -1.0 - l
        }
    }

    /// The projected area of the facets visible from v, σ(v) = ∫ max(0, v·m) D(m) dm:
    /// v.z (1 + Λ(v)) above, |v.z| Λ(v) below (σ(v) − σ(−v) = v.z; no cancellation in
    /// either form).
    pub fn sigma(&self, v: [f64; 3]) -> f64 {
        let l = self.dist.lambda(v);
        if v[2] >= 0.0 {
            v[2] * (1.0 + l)
        } else {
            -v[2] * l
        }
    }

    /// The mirror phase function's geometry for v → w: D_v(wm)/(4 v·wm) = D(wm)/(4σ(v))
    /// with wm the half vector, and v·wm; `None` where no upward facet reflects v into w.
    fn mirror_phase(&self, v: [f64; 3], w: [f64; 3]) -> Option<(f64, f64)> {
        let wm = reflection_half(v, w)?;
        let p = self.dist.d(wm) / (4.0 * self.sigma(v));
        // (σ(v) is 0·∞ for v exactly on the horizon: no density there.)
        p.is_finite().then_some((p, dot(v, wm)))
    }

    /// The probability that a ray leaving the height ℓ = ln C1(h) in the upward direction w
    /// escapes, G1(w, h) = C1(h)^Λ(w) = exp(Λ ℓ); 0 for w on or below the horizon.
    fn escape(&self, w: [f64; 3], l: f64) -> f64 {
        if !(w[2] > 0.0) {
            return 0.0;
        }
        let lambda = self.dist.lambda(w);
        if lambda == 0.0 {
            return 1.0;
        }
        (lambda * l).exp()
    }

    /// The next height ℓ' = ln C1(h') for a ray travelling in w from ℓ, or `None` if it
    /// escapes (upward rays only), from the uniform u ∈ (0, 1).
    #[inline]
    fn next_height(&self, w: [f64; 3], l: f64, u: f64) -> Option<f64> {
        let lambda = self.lambda_signed(w);
        // ln(1 − U) as ln U': 1 − U is uniform as U is, and strictly inside (0, 1) (ln is
        // cheaper than ln_1p, and exact enough at every 53-bit uniform).
        let lu = u.ln();
        // Going up, it escapes with probability G1 = C1(h)^Λ: u > 1 − C1^Λ, that is
        // ln(1 − u) < Λ ℓ.
        if w[2] > 0.0 && (lu < lambda * l || !(lambda > 0.0)) {
            return None;
        }
        // C1(h') = C1(h)/(1 − u)^{1/Λ}. (ℓ' ≤ 0 in exact arithmetic; the min keeps a
        // rounding from lifting it above the top.)
        Some(self.heights.settle((l - lu / lambda).min(0.0)))
    }

    /// A visible normal for the direction v (either hemisphere; the microflakes' D_v(m) ∝
    /// max(0, v·m) D(m)): the distribution's own sampler above, the rejection of the module
    /// docs below.
    fn visible_normal(&self, v: [f64; 3], rng: &mut WalkRng) -> [f64; 3] {
        if let Some(m) = self.dist.sample_wm_stream(v, &mut || rng.next_open()) {
            return m;
        }
        if v[2] >= 0.0 {
            return self.dist.sample_wm(v, [rng.next_open(), rng.next_open()]);
        }
        let up = [v[0], v[1], -v[2]];
        let mut m = up;
        // (The expected number of candidates is (1 + Λ)/Λ, large only for steep rays, which
        // rarely get here; the cap keeps a direction straight down, which no facet faces,
        // from looping: it is never reached in tests/walk.rs or the fuzz suite.)
        for _ in 0..1_000_000 {
            // (The stream sampler of the mirror image where there is one: the family's
            // Beckmann mixtures have one above the horizon only.)
            m = match self.dist.sample_wm_stream(up, &mut || rng.next_open()) {
                Some(m) => m,
                None => self.dist.sample_wm(up, [rng.next_open(), rng.next_open()]),
            };
            let (a, b) = (dot(v, m), dot(up, m));
            if rng.next_open() * b < a || !(b > 0.0) {
                return m;
            }
        }
        m
    }

    /// The walk itself from wo (toward the viewer, either side; the path arrives along
    /// −wo), calling `event(order, v, ℓ, inside, weight, rng)` at each scattering event
    /// before the facet scatters (v the reverse of the travel direction, in the side's
    /// frame, ℓ = ln C1 the height in that side's frame, and `weight` the path's so far).
    fn run<const N: usize, Fa: Facets<N>>(
        &self,
        facets: &Fa,
        wo: [f64; 3],
        rng: &mut WalkRng,
        mut event: impl FnMut(u32, [f64; 3], f64, bool, &[f64; N], &mut WalkRng),
    ) -> Option<Walked<N>> {
        // (A guard: unit vectors are the documented input, and any other length would scale
        // every height step; from |wo| = 1e300 a walk never ended.)
        let wo = unit(wo);
        if wo[2] == 0.0 || !(wo[0].is_finite() && wo[1].is_finite() && wo[2].is_finite()) {
            return None;
        }
        let mut x = Path::start(wo);
        loop {
            if let Some(r) = self.step(facets, &mut x, rng, &mut event) {
                return r;
            }
        }
    }

    /// One height step of a path and, if it meets the surface, its scattering event (the
    /// body of [`RandomWalk::run`]'s loop): `Some(result)` when the walk ended (escaped,
    /// absorbed, failed or cut at [`MAX_ORDER`]).
    #[inline(always)]
    fn step<const N: usize, Fa: Facets<N>>(
        &self,
        facets: &Fa,
        x: &mut Path<N>,
        rng: &mut WalkRng,
        event: &mut impl FnMut(u32, [f64; 3], f64, bool, &[f64; N], &mut WalkRng),
    ) -> Option<Option<Walked<N>>> {
        match self.next_height(x.w, x.h, rng.next_open()) {
            None => {
                let w = if x.inside {
                    [-x.w[0], -x.w[1], -x.w[2]]
                } else {
                    x.w
                };
                return Some(Some(Walked {
                    w,
                    weight: x.weight,
                    order: x.order,
                }));
            }
            Some(next) => x.h = next,
        }
        let v = [-x.w[0], -x.w[1], -x.w[2]];
        event(x.order + 1, v, x.h, x.inside, &x.weight, rng);
        let m = self.visible_normal(v, rng);
        let Some(s) = facets.scatter(v, m, x.inside, rng) else {
            return Some(None);
        };
        for (a, b) in x.weight.iter_mut().zip(s.weight) {
            *a *= b;
        }
        if s.crossed {
            // The other medium's frame: every vector and height negated.
            x.w = [-s.w[0], -s.w[1], -s.w[2]];
            x.h = self.heights.cross(x.h);
            x.inside = !x.inside;
        } else {
            x.w = s.w;
        }
        // (ℓ = 0 is the top: a grazing ray can meet the surface where C1 rounds to 1.
        // Only NaN is a failure.)
        if !(x.w[0].is_finite() && x.w[1].is_finite() && x.w[2].is_finite()) || x.h.is_nan() {
            return Some(None);
        }
        x.order += 1;
        (x.order > MAX_ORDER).then_some(None)
    }

    /// `walks` walks from wo (a unit vector) in `L` interleaved lanes: lane j runs a fixed
    /// share, ⌈(walks − j)/L⌉ walks, one after the other from its own stream `rngs[j]`, each
    /// walk what [`RandomWalk::walk`] from that stream gives, and `record(j, walked)` is
    /// called with each in the lane's order. While every lane is busy they advance in
    /// lockstep, one height step and event each a round, so that their dependency chains
    /// (each event's direction depends on the last) overlap in the processor; a lane that
    /// ends a walk starts its next one in the same round. What each lane computes does not
    /// depend on the interleaving.
    #[inline]
    pub(crate) fn walk_lanes<const N: usize, const L: usize, Fa: Facets<N>>(
        &self,
        facets: &Fa,
        wo: [f64; 3],
        walks: u64,
        rngs: &mut [WalkRng; L],
        mut record: impl FnMut(usize, Option<Walked<N>>),
    ) {
        let wo = unit(wo);
        let quota: [u64; L] = std::array::from_fn(|j| (walks + (L - 1 - j) as u64) / L as u64);
        if wo[2] == 0.0 || !(wo[0].is_finite() && wo[1].is_finite() && wo[2].is_finite()) {
            for (j, &q) in quota.iter().enumerate() {
                for _ in 0..q {
                    record(j, None);
                }
            }
            return;
        }
        let start = Path::start(wo);
        let mut none = |_: u32, _: [f64; 3], _: f64, _: bool, _: &[f64; N], _: &mut WalkRng| {};
        let mut lanes = [start; L];
        // The walks each lane has still to start after its current one.
        let mut left: [u64; L] = std::array::from_fn(|j| quota[j].saturating_sub(1));
        let mut busy: [bool; L] = std::array::from_fn(|j| quota[j] > 0);
        'lockstep: while busy.iter().all(|&b| b) {
            for j in 0..L {
                if let Some(r) = self.step(facets, &mut lanes[j], &mut rngs[j], &mut none) {
                    record(j, r);
                    if left[j] == 0 {
                        busy[j] = false;
                        break 'lockstep;
                    }
                    left[j] -= 1;
                    lanes[j] = start;
                }
            }
        }
        // The lanes still busy, one after the other.
        for j in 0..L {
            while busy[j] {
                if let Some(r) = self.step(facets, &mut lanes[j], &mut rngs[j], &mut none) {
                    record(j, r);
                    if left[j] == 0 {
                        busy[j] = false;
                    } else {
                        left[j] -= 1;
                        lanes[j] = start;
                    }
                }
            }
        }
    }

    /// One walk from the direction wo (toward the viewer; below the surface for a path that
    /// starts in a dielectric's lower medium, or a conductor seen from below, which is its
    /// mirror image). `None` for wo on the horizon or not finite, or a path cut at
    /// [`MAX_ORDER`].
    pub fn walk<const N: usize>(
        &self,
        facets: &impl Facets<N>,
        wo: [f64; 3],
        rng: &mut WalkRng,
    ) -> Option<Walked<N>> {
        self.run(facets, wo, rng, |_, _, _, _, _, _| {})
    }

    /// One sample of the paper's stochastic evaluation (its section 5.2) of
    /// f(wo, wi)|cos θi| by order: a walk from wo that, at each scattering event at height
    /// h, adds the path's weight × the phase function's density toward wi × the
    /// probability that wi escapes from h (next-event estimation). Unbiased for every
    /// order; order 1's expectation is the single-scattering BSDF with the height-correlated
    /// G2 (for a reflection 1/(1 + Λo + Λi); for a dielectric's transmission the exact
    /// height-correlated form B(1 + Λo, 1 + Λi), Heitz 2014, "Understanding the
    /// masking-shadowing function", section 6: [`crate::bsdf::RoughDielectric`] with
    /// [`crate::bsdf::Masking::CorrelatedBeta`]; by default it uses the approximation
    /// 1/(1 + Λo + Λi) as pbrt-v4 does). wi on the other side of the
    /// macrosurface is a transmission (0 for opaque facets). Units: unit vectors.
    pub fn eval<const N: usize>(
        &self,
        facets: &impl Facets<N>,
        wo: [f64; 3],
        wi: [f64; 3],
        rng: &mut WalkRng,
    ) -> OrderValues<N> {
        let mut out = [[0.0; N]; 4];
        let wi_inside = wi[2] < 0.0;
        if wi[2] == 0.0
            || wi[2].is_nan()
            || (facets.interface_eta().is_none() && wi_inside != (wo[2] < 0.0))
        {
            return out;
        }
        self.run(facets, wo, rng, |order, v, h, inside, weight, rng| {
            let crossed = wi_inside != inside;
            let w = if inside { [-wi[0], -wi[1], -wi[2]] } else { wi };
            let g = if crossed {
                self.escape([-w[0], -w[1], -w[2]], self.heights.cross(h))
            } else {
                self.escape(w, h)
            };
            if g == 0.0 {
                return;
            }
            let p = facets.phase(self, v, w, crossed, inside, rng);
            let k = (order.min(4) - 1) as usize;
            for c in 0..N {
                let x = weight[c] * p[c] * g;
                if x.is_finite() {
                    out[k][c] += x;
                }
            }
        });
        out
    }
}

/// A hash of the bits of `xs` (the seed of a stream that is a deterministic function of a
/// BSDF call's arguments, as [`crate::distribution::UniformStream`] is for the samplers).
fn seed_of(xs: &[f64]) -> u64 {
    xs.iter().fold(0x243F_6A88_85A3_08D3, |h: u64, x| {
        (h ^ x.to_bits())
            .wrapping_mul(0x9E37_79B9_7F4A_7C15)
            .rotate_left(31)
    })
}

/// [`MultipleScattering::pdf`]'s cosine floor a (type docs): the excess of the evaluation's
/// E\[X²\]/E\[X\] over p₁ near the normal, measured (examples/walk_mis.rs, `peff`), is
/// 0.8 |cos θi|/π at α = 0.5 and 2.5 |cos θi|/π at α = 1, and grows about as α beyond
/// (5.5 at α = 2, 12 at α = 4); of a ∈ {2.5, 3, 4}, 3 is the smallest that holds MIS's
/// variance under a sky within 0.5 % of BSDF sampling alone up to α = 4 (2.5 left α = 2
/// 1.3 % above).
const MIS_COSINE: f64 = 3.0;

/// [`MultipleScattering::pdf`]'s spike floor b (type docs): at α ≤ 0.2 the excess grows
/// toward grazing wi (θi = 85°: about 0.5 sr⁻¹ at α = 0.2, 5 at 0.1, 20 to 70 at 0.05) as
/// D's peak 1/(π α²) grows; of b ∈ {0.015, 0.025, 0.05} the smallest that holds MIS's
/// variance under a sky within 0.5 % of BSDF sampling alone at every α measured (0.015 and
/// 0.025 left it 3.2 % and 1.6 % above at α = 0.1 and 0.2, normal incidence).
const MIS_SPIKES: f64 = 0.05;

/// Below |cos θi| = 0.01 (89.4°) the spike floor is held, so that p̃ stays finite on the
/// horizon (the measured excess ends at 85°; the hold is 100 times the floor at the normal).
const MIS_COS_MIN: f64 = 0.01;

/// The multiple-scattering BSDF of a microsurface, [`Bsdf`] over the random walk, for every
/// NDF and facet material ([`MirrorFacets`]: a conductor, [`DielectricFacets`]: a rough
/// interface, [`DiffuseFacets`]).
///
/// * `sample` is the walk (exact: its weight f|cos θi|/pdf is the path's, ≤ 1 for F ≤ 1), its
///   stream seeded by the bits of (uc, u), so a sample is a deterministic function of its
///   arguments.
/// * `eval` is one sample of the stochastic evaluation ([`RandomWalk::eval`], summed over
///   orders, divided by |cos θi|), seeded by the bits of (wo, wi): unbiased, noisy.
///   [`MultipleScattering::eval_orders`] averages many, by order, with standard errors.
/// * `pdf` is **not** the density of `sample`'s directions (which has no closed form): it is
///   the stand-in that multiple importance sampling (MIS) weighs light samples against,
///   single scattering's sampling density p₁(wo, wi) plus a floor,
///   p̃ = p₁ + a max(1, √(αx αy)) |cos θi|/π + b/(π αx αy max(|cos θi|, 0.01)),
///   with a = 3, b = 0.05 (1/(π αx αy) is the peak of GGX's and Beckmann's D, used as the
///   scale of every NDF's, some of which have a pole there); the second term only for
///   facets with a delta lobe ([`Facets::specular`]: not [`DiffuseFacets`]), both halved on
///   each side for a dielectric. `sample` reports p̃ as its pdf and f = weight · p̃/|cos θi|.
/// * **Why a floor.** `eval` is one noisy sample, and MIS's balance-optimal stand-in for a
///   strategy whose light samples carry a noisy estimate X of f|cos θi| is E\[X²\]/E\[X\],
///   not f|cos θi|: the walk's next-event estimate at orders ≥ 2 is spiky (a bounce that
///   mirrors the path into wi weighs up to D's peak/(4σ)), most at small α and toward
///   grazing wi. The floor covers that excess as measured over α ∈ [0.05, 4] (the cosine
///   term the rough end, the second term the smooth end's grazing spikes). It integrates to
///   more than 1: p̃ is a weight, not a density. In effect light sampling takes over where
///   the light's density exceeds the floor (a sun, a small lamp), and BSDF sampling, whose
///   weight is ≤ 1 (the walk's own), carries broad light (a sky).
/// * **Measured** (BENCHMARKS.md, "The walk under MIS": one BSDF and one light sample,
///   power heuristic, against BSDF sampling alone, per-pixel variance; GGX conductor,
///   α from 0.05 to 4). Under a white furnace plus a sky, MIS with p̃ is within 0.5 % of
///   BSDF sampling alone (0.94 to 1.005 of its variance), with no fireflies; the previous
///   stand-in, single scattering plus a cosine term, was 2.7 to 400 times noisier, with
///   fireflies. Under a 5° sun light sampling keeps its gain (0.004 to 0.87 of BSDF
///   sampling's variance). The trade-off is at small α, where the floor is high: a 15°
///   lamp off the specular direction at α ≤ 0.1 is left mostly to BSDF sampling (0.44 to
///   0.92 of its variance), and the 5° sun off it at α = 0.05 partly (0.045 to 0.06, where
///   a floor a third as high measured 0.003 to 0.03 but left the sky 3 % noisier). Under
///   the sky the dielectric's MIS stays at 0.73 to 1.0 of BSDF sampling's variance and the
///   diffuse facets' at 1.02 to 1.035.
/// * **Use**: MIS with the power or balance heuristic, p̃ on both strategies' sides (the
///   image is unbiased with any weights that sum to one; the floor keeps every direction
///   the walk leaves in at a positive p̃), or BSDF sampling alone; not light sampling
///   alone, whose noise is `eval`'s.
/// * The transport is radiance by default: a transmitted f is divided by η'², η' the
///   relative index along the path (as [`crate::bsdf::RoughDielectric`]); the walk itself
///   transports importance.
/// * There is no smooth limit: at α < 1e-3 the lobes are as sharp as D; a renderer uses
///   [`crate::bsdf::RoughDielectric`] or [`crate::bsdf::RoughConductor`] there, whose delta lobes
///   have no multiple scattering.
#[derive(Clone, Debug)]
pub struct MultipleScattering<D, Fa, const N: usize> {
    surface: RandomWalk<D>,
    facets: Fa,
    transport: Transport,
}

impl<D: MicrofacetDistribution<f64>, Fa: Facets<N>, const N: usize> MultipleScattering<D, Fa, N> {
    /// The BSDF of `dist` with `facets`, uniform heights, radiance transport.
    pub fn new(dist: D, facets: Fa) -> Self {
        MultipleScattering {
            surface: RandomWalk::new(dist, Heights::Uniform),
            facets,
            transport: Transport::Radiance,
        }
    }

    /// The same for the other transport direction.
    pub fn with_transport(mut self, transport: Transport) -> Self {
        self.transport = transport;
        self
    }

    /// The same with another height distribution (which changes the random numbers, not
    /// the BSDF).
    pub fn with_heights(mut self, heights: Heights) -> Self {
        self.surface.heights = heights;
        self
    }

    /// The microsurface.
    pub fn surface(&self) -> &RandomWalk<D> {
        &self.surface
    }

    /// The facets.
    pub fn facets(&self) -> &Fa {
        &self.facets
    }

    /// Whether the facets are an interface of index 1 (no interface: a delta lobe straight
    /// through, [`Bsdf::sample`] below).
    fn invisible(&self) -> bool {
        self.facets.interface_eta() == Some(1.0)
    }

    /// η'⁻² for a transmission under radiance transport, else 1.
    fn transport_factor(&self, wo: [f64; 3], wi: [f64; 3]) -> f64 {
        match self.facets.interface_eta() {
            Some(eta)
                if self.transport == Transport::Radiance && (wo[2] < 0.0) != (wi[2] < 0.0) =>
            {
                let etap = if wo[2] > 0.0 { eta } else { 1.0 / eta };
                1.0 / (etap * etap)
            }
            _ => 1.0,
        }
    }

    /// f(wo, wi) by order (1, 2, 3, ≥ 4) per channel, the mean of `samples` stochastic
    /// evaluations from the stream `seed`, with standard errors.
    pub fn eval_orders(&self, wo: [f64; 3], wi: [f64; 3], samples: u64, seed: u64) -> [ByOrder; N] {
        let mut rng = WalkRng::new(seed);
        let mut sums = [OrderSums::default(); N];
        let (wo, wi) = (unit(wo), unit(wi));
        // On the horizon (either direction) f·|cos θi| → 0 and f is answered 0, as the
        // single-scattering BSDFs do there (1/|cos θi| would make 0 · ∞ = NaN).
        if crate::bsdf::on_horizon(wo[2]) || crate::bsdf::on_horizon(wi[2]) {
            return sums.map(|s| s.finish(samples));
        }
        let scale = self.transport_factor(wo, wi) / wi[2].abs();
        for _ in 0..samples {
            let e = self.surface.eval(&self.facets, wo, wi, &mut rng);
            for (c, s) in sums.iter_mut().enumerate() {
                s.add(std::array::from_fn(|k| e[k][c] * scale));
            }
        }
        sums.map(|s| s.finish(samples))
    }
}

impl<F: Real, D: MicrofacetDistribution<f64>, Fa: Facets<N>, const N: usize> Bsdf<F>
    for MultipleScattering<D, Fa, N>
{
    type Value = [F; N];

    fn eval(&self, wo: [F; 3], wi: [F; 3]) -> [F; N] {
        if self.invisible() {
            return [F::ZERO; N];
        }
        // On the horizon of F (|cos θ| below 1e-18 in f32) as the single-scattering BSDFs:
        // f carries 1/|cos θi|, which overflows f32 there (an f32 wi.z of 1e-40 gave f = ∞).
        // The test reads the unit directions' cosines (any length is in contract).
        let (wo, wi) = (unit(wo), unit(wi));
        if crate::bsdf::on_horizon(wo[2]) || crate::bsdf::on_horizon(wi[2]) {
            return [F::ZERO; N];
        }
        self.eval_f64(wo.map(F::to_f64), wi.map(F::to_f64))
            .map(F::from_f64)
    }

    fn pdf(&self, wo: [F; 3], wi: [F; 3]) -> F {
        if self.invisible() {
            return F::ZERO;
        }
        F::from_f64(self.pdf_f64(wo.map(F::to_f64), wi.map(F::to_f64)))
    }

    fn sample(&self, wo: [F; 3], uc: F, u: [F; 2]) -> Option<BsdfSample<F, [F; N]>> {
        if self.invisible() {
            // An interface of index 1 is no interface: the ray goes straight on, a delta
            // lobe of weight 1 (as RoughDielectric's at η = 1; the walk there returned
            // f = 2.8e32 with pdf 2.5e32).
            let w = unit(wo);
            let wi = [-w[0], -w[1], -w[2]];
            if !(wi[2].abs() > F::ZERO) {
                return None;
            }
            return Some(BsdfSample {
                wi,
                f: [F::ONE / wi[2].abs(); N],
                pdf: F::ONE,
                lobe: crate::bsdf::Lobe::Transmission,
                specular: true,
                eta: F::ONE,
            });
        }
        let s = self.sample_f64(wo.map(F::to_f64), uc.to_f64(), u.map(F::to_f64))?;
        let (pdf, f) = (F::from_f64(s.pdf), s.f.map(F::from_f64));
        // (A pdf or f that leaves F's range in the rounding: rejected, as any unusable sample.)
        if !(pdf > F::ZERO && pdf.to_f64().is_finite() && f.iter().all(|x| x.to_f64().is_finite()))
        {
            return None;
        }
        Some(BsdfSample {
            wi: s.wi.map(F::from_f64),
            f,
            pdf,
            lobe: s.lobe,
            specular: s.specular,
            eta: F::from_f64(s.eta),
        })
    }
}

/// The walk's BSDF in f64 (the walk computes in f64 for every F).
impl<D: MicrofacetDistribution<f64>, Fa: Facets<N>, const N: usize> MultipleScattering<D, Fa, N> {
    fn eval_f64(&self, wo: [f64; 3], wi: [f64; 3]) -> [f64; N] {
        // (Directions of any finite nonzero length, as the contract has them: the walk's
        // heights and cosines are for unit vectors, and from |wo| = 1e300 a walk never ended.)
        let (wo, wi) = (unit(wo), unit(wi));
        let mut rng = WalkRng::new(seed_of(&[wo[0], wo[1], wo[2], wi[0], wi[1], wi[2]]));
        let e = self.surface.eval(&self.facets, wo, wi, &mut rng);
        let scale = self.transport_factor(wo, wi) / wi[2].abs();
        std::array::from_fn(|c| {
            let f = (e[0][c] + e[1][c] + e[2][c] + e[3][c]) * scale;
            if f.is_finite() {
                f
            } else {
                0.0
            }
        })
    }

    fn pdf_f64(&self, wo: [f64; 3], wi: [f64; 3]) -> f64 {
        let (wo, wi) = (unit(wo), unit(wi));
        if wo[2] == 0.0 || wi[2] == 0.0 || wo[2].is_nan() || wi[2].is_nan() {
            return 0.0;
        }
        let inside = wo[2] < 0.0;
        let (wo_s, wi_s) = if inside {
            ([-wo[0], -wo[1], -wo[2]], [-wi[0], -wi[1], -wi[2]])
        } else {
            (wo, wi)
        };
        let transmits = self.facets.interface_eta().is_some();
        if !transmits && !(wi_s[2] > 0.0) {
            return 0.0;
        }
        // The floor of the type's docs: a cosine term scaled with the roughness beyond α = 1
        // and, for delta facets, the spike term ∝ 1/(π αx αy), held below |cos θi| = 0.01.
        let (ax, ay) = self.surface.dist.alpha();
        let (cos, inv_pi) = (wi_s[2].abs(), std::f64::consts::FRAC_1_PI);
        let mut floor = MIS_COSINE * (ax * ay).sqrt().max(1.0) * cos * inv_pi;
        if self.facets.specular() {
            floor += MIS_SPIKES * inv_pi / (ax * ay * cos.max(MIS_COS_MIN));
        }
        let floor = if transmits { 0.5 * floor } else { floor };
        let p = self.facets.single_pdf(&self.surface, wo_s, wi_s, inside) + floor;
        if p.is_finite() {
            p
        } else {
            0.0
        }
    }

    fn sample_f64(&self, wo: [f64; 3], uc: f64, u: [f64; 2]) -> Option<BsdfSample<f64, [f64; N]>> {
        let wo = unit(wo);
        let mut rng = WalkRng::new(seed_of(&[uc, u[0], u[1]]));
        let p = self.surface.walk(&self.facets, wo, &mut rng)?;
        let wi = p.w;
        let pdf = self.pdf_f64(wo, wi);
        if !(pdf > 0.0 && pdf.is_finite()) {
            return None;
        }
        let transmitted = (wo[2] < 0.0) != (wi[2] < 0.0);
        let scale = self.transport_factor(wo, wi) * pdf / wi[2].abs();
        let f = p.weight.map(|x| x * scale);
        if !f.iter().all(|x| x.is_finite()) {
            return None;
        }
        let eta = match self.facets.interface_eta() {
            Some(eta) if transmitted => {
                if wo[2] > 0.0 {
                    eta
                } else {
                    1.0 / eta
                }
            }
            _ => 1.0,
        };
        Some(BsdfSample {
            wi,
            f,
            pdf,
            lobe: if transmitted {
                Lobe::Transmission
            } else {
                Lobe::Reflection
            },
            specular: false,
            eta,
        })
    }
}
