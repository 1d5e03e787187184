//! The microsurface random walk: see the [`crate::scattering`] docs.

// `!(x > 0)` is the NaN-aware test (false for NaN), on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::bsdf::frame::{dot, reflect};
use crate::bsdf::fresnel::Fresnel;
use crate::bsdf::{Bsdf, BsdfSample, Lobe, Transport};
use crate::distribution::MicrofacetDistribution;
use crate::fast::Real;
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
    /// closed form is an integral over the normals). [`MultipleScattering::pdf`] mixes it
    /// with a diffuse-like term.
    fn single_pdf<D: MicrofacetDistribution<f64>>(
        &self,
        surface: &RandomWalk<D>,
        wo: [f64; 3],
        wi: [f64; 3],
        inside: bool,
    ) -> f64;
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
}

/// Smooth dielectric facets of relative index η = η_inside/η_outside (the macrosurface's
/// lower medium is inside): each facet reflects with the Fresnel probability R(v·wm) and
/// refracts otherwise (weight 1: the walk transports importance, Veach 1997 §5.2, and
/// [`MultipleScattering`] applies radiance's 1/η'² once at the end).
#[derive(Clone, Copy, Debug)]
pub struct DielectricFacets(pub f64);

impl DielectricFacets {
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

/// Walks longer than this are cut ([`RandomWalk::walk`] answers `None`, which [`albedo`]
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
        if wo[2] == 0.0 || !(wo[0].is_finite() && wo[1].is_finite() && wo[2].is_finite()) {
            return None;
        }
        let mut inside = wo[2] < 0.0;
        let mut w = if inside { wo } else { [-wo[0], -wo[1], -wo[2]] };
        let mut h = 0.0;
        let mut weight = [1.0; N];
        for order in 0..=MAX_ORDER {
            match self.next_height(w, h, rng.next_open()) {
                None => {
                    let w = if inside { [-w[0], -w[1], -w[2]] } else { w };
                    return Some(Walked { w, weight, order });
                }
                Some(next) => h = next,
            }
            let v = [-w[0], -w[1], -w[2]];
            event(order + 1, v, h, inside, &weight, rng);
            let m = self.visible_normal(v, rng);
            let s = facets.scatter(v, m, inside, rng)?;
            for (a, b) in weight.iter_mut().zip(s.weight) {
                *a *= b;
            }
            if s.crossed {
                // The other medium's frame: every vector and height negated.
                w = [-s.w[0], -s.w[1], -s.w[2]];
                h = self.heights.cross(h);
                inside = !inside;
            } else {
                w = s.w;
            }
            // (ℓ = 0 is the top: a grazing ray can meet the surface where C1 rounds to 1.
            // Only NaN is a failure.)
            if !(w[0].is_finite() && w[1].is_finite() && w[2].is_finite()) || h.is_nan() {
                return None;
            }
        }
        None
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
    /// masking-shadowing function", section 6, whose approximation 1/(1 + Λo + Λi)
    /// [`crate::bsdf::RoughDielectric`] uses as pbrt-v4 does). wi on the other side of the
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
///   the paper's MIS proxy (section 6), single scattering's sampling density plus a
///   diffuse-like term for the higher orders,
///   p̃(wo, wi) = (1 − q) p₁(wo, wi) + q |cos θi|/π (halved on each side for a dielectric),
///   with q = 1 − G1(wo) clamped to [0.05, 0.95], which tracks the share of energy beyond
///   order 1 (0 on a smooth surface, growing with α and toward grazing). `sample` reports
///   p̃ as its pdf and f = weight · p̃/|cos θi|. Multiple importance sampling stays unbiased
///   with any weights that sum to one, so a renderer that uses p̃ on both strategies'
///   sides gets a correct image; the 5 % floor keeps every direction the walk can produce
///   at a positive p̃.
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
        self.eval_f64(wo.map(F::to_f64), wi.map(F::to_f64))
            .map(F::from_f64)
    }

    fn pdf(&self, wo: [F; 3], wi: [F; 3]) -> F {
        F::from_f64(self.pdf_f64(wo.map(F::to_f64), wi.map(F::to_f64)))
    }

    fn sample(&self, wo: [F; 3], uc: F, u: [F; 2]) -> Option<BsdfSample<F, [F; N]>> {
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
        // (G1 ∈ [0, 1]; the clamp also maps a NaN G1 to the floor.)
        let q = (1.0 - self.surface.dist.g1(wo_s)).clamp(0.05, 0.95);
        let diffuse = wi_s[2].abs() * std::f64::consts::FRAC_1_PI;
        let diffuse = if transmits { 0.5 * diffuse } else { diffuse };
        let p1 = self.facets.single_pdf(&self.surface, wo_s, wi_s, inside);
        let p = (1.0 - q) * p1 + q * diffuse;
        if p.is_finite() {
            p
        } else {
            0.0
        }
    }

    fn sample_f64(&self, wo: [f64; 3], uc: f64, u: [f64; 2]) -> Option<BsdfSample<f64, [f64; N]>> {
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

/// An estimate with its standard error.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Estimate {
    pub mean: f64,
    pub stderr: f64,
}

/// Running sums of a Monte Carlo estimator by order (1, 2, 3, ≥ 4 and the total), shifted
/// by the first sample (the variance as E[(x − K)²] − E[x − K]² with K the first value: the
/// textbook E[x²] − E[x]² cancels catastrophically where the spread is far below the mean,
/// as for order 1 near normal incidence, where every sample agrees to 1e-7).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct OrderSums {
    shift: Option<[f64; 5]>,
    s: [f64; 5],
    s2: [f64; 5],
}

impl OrderSums {
    /// One sample's values by order (the total is their sum).
    pub(crate) fn add(&mut self, x: [f64; 4]) {
        let t: f64 = x.iter().sum();
        let x = [x[0], x[1], x[2], x[3], t];
        let k = *self.shift.get_or_insert(x);
        for i in 0..5 {
            let d = x[i] - k[i];
            self.s[i] += d;
            self.s2[i] += d * d;
        }
    }

    /// The means and standard errors over n samples.
    pub(crate) fn finish(&self, n: u64) -> ByOrder {
        let n = n.max(1) as f64;
        let k = self.shift.unwrap_or_default();
        let e: [Estimate; 5] = std::array::from_fn(|i| {
            let d = self.s[i] / n;
            let var = (self.s2[i] / n - d * d).max(0.0);
            Estimate {
                mean: k[i] + d,
                stderr: (var / n).sqrt(),
            }
        });
        ByOrder {
            orders: [e[0].mean, e[1].mean, e[2].mean, e[3].mean],
            stderr: [e[0].stderr, e[1].stderr, e[2].stderr, e[3].stderr],
            total: e[4].mean,
            total_stderr: e[4].stderr,
        }
    }
}

/// A quantity by scattering order: orders 1, 2, 3 and ≥ 4, their total, and standard errors.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct ByOrder {
    /// Orders 1, 2, 3, ≥ 4.
    pub orders: [f64; 4],
    /// Their standard errors.
    pub stderr: [f64; 4],
    /// The sum over orders.
    pub total: f64,
    /// Its standard error.
    pub total_stderr: f64,
}

/// The albedo of a microsurface from wo by order, per side: `reflect` the energy that leaves
/// on wo's side, `transmit` on the other (0 for opaque facets), channel 0 of the weight.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Albedo {
    pub reflect: ByOrder,
    pub transmit: ByOrder,
    /// Reflected plus transmitted (its standard error from the walks' totals: the two sides
    /// are estimated from the same walks).
    pub total: Estimate,
}

/// Running sums of one bin of [`Albedo`]'s estimators: a walk puts its weight w in one
/// bin (its side and order) and 0 in the others, so a bin keeps the count of its walks and
/// the sums of w − K and (w − K)² over them, K its first weight (shifted, as [`OrderSums`],
/// so that a bin whose weights all agree, order 1 near normal incidence, keeps its tiny
/// spread).
#[derive(Clone, Copy, Debug, Default)]
struct Bin {
    n: u64,
    shift: f64,
    s: f64,
    s2: f64,
}

impl Bin {
    #[inline(always)]
    fn add(&mut self, w: f64) {
        if self.n == 0 {
            self.shift = w;
        }
        let d = w - self.shift;
        self.n += 1;
        self.s += d;
        self.s2 += d * d;
    }

    fn merge(&mut self, o: &Bin) {
        if o.n == 0 {
            return;
        }
        if self.n == 0 {
            *self = *o;
            return;
        }
        let d = o.shift - self.shift;
        let n = o.n as f64;
        self.s2 += o.s2 + 2.0 * d * o.s + n * d * d;
        self.s += o.s + n * d;
        self.n += o.n;
    }

    /// The mean and standard error over `walks` walks of X = w in this bin, 0 elsewhere:
    /// with p = n/walks and the bin's own mean m and variance v of w,
    /// Var X = p v + p(1 − p) m² (a sum of non-negative terms: no cancellation).
    fn estimate(&self, walks: u64) -> Estimate {
        if self.n == 0 || walks == 0 {
            return Estimate::default();
        }
        let (n, total) = (self.n as f64, walks as f64);
        let d = self.s / n;
        let m = self.shift + d;
        let v = (self.s2 / n - d * d).max(0.0);
        let p = n / total;
        // (p(1 − p) from the counts, exactly.)
        let pq = n * (walks - self.n) as f64 / (total * total);
        Estimate {
            mean: p * m,
            stderr: ((p * v + pq * m * m) / total).sqrt(),
        }
    }
}

/// Running sums of [`Albedo`]'s estimators (bins per side and order, per side, and the
/// total).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct AlbedoSums {
    /// [side][order 1, 2, 3, ≥ 4, any], side 0 reflection, 1 transmission.
    bins: [[Bin; 5]; 2],
    total: Bin,
    walks: u64,
}

impl AlbedoSums {
    /// One walk from wo (`None`: failed, weight 0).
    #[inline]
    pub(crate) fn add<const N: usize>(&mut self, wo: [f64; 3], walked: Option<Walked<N>>) {
        self.walks += 1;
        let Some(p) = walked else {
            return;
        };
        let w = p.weight[0];
        let side = usize::from((p.w[2] < 0.0) != (wo[2] < 0.0));
        let bins = &mut self.bins[side];
        bins[(p.order.clamp(1, 4) - 1) as usize].add(w);
        bins[4].add(w);
        self.total.add(w);
    }

    pub(crate) fn merge(&mut self, o: &AlbedoSums) {
        for (a, b) in self.bins.iter_mut().zip(&o.bins) {
            for (x, y) in a.iter_mut().zip(b) {
                x.merge(y);
            }
        }
        self.total.merge(&o.total);
        self.walks += o.walks;
    }

    pub(crate) fn finish(&self) -> Albedo {
        let side = |b: &[Bin; 5]| {
            let e = b.map(|x| x.estimate(self.walks));
            ByOrder {
                orders: [e[0].mean, e[1].mean, e[2].mean, e[3].mean],
                stderr: [e[0].stderr, e[1].stderr, e[2].stderr, e[3].stderr],
                total: e[4].mean,
                total_stderr: e[4].stderr,
            }
        };
        Albedo {
            reflect: side(&self.bins[0]),
            transmit: side(&self.bins[1]),
            total: self.total.estimate(self.walks),
        }
    }
}

/// [`Albedo`] from `walks` walks from wo (E_k(wo) = E[weight; the walk leaves on that side
/// after k events]); walks that fail (wo on the horizon, cut paths) count with weight 0.
/// One channel (a spectral albedo is one call per channel, each with its own seed or the
/// same one for correlated estimates).
pub fn albedo<D: MicrofacetDistribution<f64>>(
    surface: &RandomWalk<D>,
    facets: &impl Facets<1>,
    wo: [f64; 3],
    walks: u64,
    seed: u64,
) -> Albedo {
    let mut rng = WalkRng::new(seed);
    let mut sums = AlbedoSums::default();
    for _ in 0..walks {
        sums.add(wo, surface.walk(facets, wo, &mut rng));
    }
    sums.finish()
}

/// The single-scattering albedo of a conductor with F = 1 and the height-correlated G2,
/// E₁(wo) = ∫ D(wh) G2(wo, wi)/(4 cos θo) dωi over the upper hemisphere (wh the half
/// vector), by nested adaptive tanh-sinh quadrature in (cos θi, φ), split where the lobe
/// peaks (the mirror direction's θ and azimuth): relative error ≤ 1e-9 requested, 1e-6
/// guaranteed by tests/walk.rs against an independent rule. The walk's order 1 estimates the
/// same quantity. For the NDFs whose D has a pole at the normal (Ei, Erfc, K0, Bessel-K
/// a ≤ 1) the integral is taken over the microfacet normal instead, as
/// [`single_scattering_albedo_dielectric`] does (level 4 of its rule), where the pole is an
/// end point of the outer integral: measured, it agrees with the integral over wi to 1e-12
/// (K0, Ei at α = 0.3, μ ∈ {0.2, 0.7, 1}; GGX, Beckmann too), levels 3 to 5 agree to 3e-11
/// for Bessel-K a = 0.3, and it takes 15 s there against 210 s over wi (K0: 20–50 ms).
pub fn single_scattering_albedo<D: MicrofacetDistribution<f64>>(dist: &D, wo: [f64; 3]) -> f64 {
    single_scattering_albedo_tol(dist, wo, 1e-9)
}

/// [`single_scattering_albedo`] at relative tolerance `tol` (the inner integrals at
/// `tol`/10).
pub(crate) fn single_scattering_albedo_tol<D: MicrofacetDistribution<f64>>(
    dist: &D,
    wo: [f64; 3],
    tol: f64,
) -> f64 {
    let mu_o = wo[2];
    if !(mu_o > 0.0) {
        return 0.0;
    }
    // D with a pole at the normal (Ei, Erfc, K0, Bessel-K a ≤ 1): over the microfacet normal,
    // where the pole is the end θm = 0 of the outer integral, which the tanh-sinh rule
    // takes as it is (over wi it sits inside the lobe: Bessel-K a = 0.3 took 210 s there).
    let pole = dist
        .ndf()
        .and_then(|(kind, shape)| crate::AnyNdf::new(kind, 1.0, shape).ok())
        .is_some_and(|n| n.singular_at_pole());
    if pole {
        return over_normals(dist, wo, None, G2Form::Approximate, 4).0;
    }
    lobe_integral(
        |wi| {
            let h = [wo[0] + wi[0], wo[1] + wi[1], wo[2] + wi[2]];
            let l = dot(h, h).sqrt();
            if !(l > 0.0) {
                return 0.0;
            }
            let wh = [h[0] / l, h[1] / l, h[2] / l];
            dist.d(wh) * dist.g2(wo, wi) / (4.0 * mu_o)
        },
        wo,
        mu_o,
        1.0,
        tol,
    )
}

/// The single-scattering albedo of a rough dielectric interface of relative index η
/// (η_inside/η_outside) seen from wo, split into reflection and transmission: the
/// directional albedo of [`crate::bsdf::RoughDielectric`] (height-correlated G2 =
/// 1/(1 + Λo + Λi), importance transport, so that reflection + transmission is the share
/// of the energy that single scattering keeps: 1 − their sum is what multiple scattering
/// adds), as an integral over the microfacet normal,
///
/// E(wo) = (1/μo) ∫ D(m) (wo·m)⁺ [R(wo·m) G2(wo, wr) + (1 − R(wo·m)) G2(wo, wt)] dm,
///
/// wr and wt the reflection and refraction of wo about m (each counted where it leaves on
/// its side: wr.z > 0, wt.z < 0; R = 1 past the critical angle). wo below the surface is
/// the mirror image of wo above with 1/η.
///
/// **Quadrature.** Over the directions wi the transmission lobe has an integrable
/// singularity (where wi·m + wo·m/η' → 0) that no product rule resolves; over m the
/// integrand is bounded, and in polar coordinates about the normal (θm, φ from wo's
/// azimuth) every place where it is not smooth is a level set of c = wo·m, which for a
/// fixed θm is monotone in φ on [0, π]: the visibility edge c = 0, the critical angle
/// c = √(1 − η²) (η < 1), the reflection's horizon c = μo/(2 cos θm) and the refraction's
/// c = (k² + 1 − η²)/(2k), k = μo/cos θm (η < 1; for η > 1 the refracted ray always goes
/// down). So the inner integral over φ is split where c crosses those levels, and the outer
/// one over θm where a level enters or leaves the range [cos(θo + θm), cos(θo − θm)] of c
/// (closed forms for the constant levels and the reflection's, bisection for the
/// refraction's) and at θm = atan(α·{¼, 1, 4}) (the peak of D); each piece by the tanh-sinh
/// rule of step 2^−`level` (end-point singularities of the pieces cost nothing).
///
/// **Accuracy** (measured against level 7, every NDF at α ∈ {0.05, 0.4, 2}, η ∈ {1.5, 2.4}
/// from both sides, μ ∈ [0.01, 1]): level 4 (the default; 5–30 ms) within 1.7e-5 (Double
/// GGX at α = 0.4; GGX 7e-6), level 3 within 1.2e-4. Beckmann and the Exponential NDF
/// converge double-exponentially (level 4 within 1e-7, mostly 1e-14); the heavy-tailed
/// GGX family only about 8× per level, the sign of a non-smooth place the cuts miss (not
/// found). tests/compensate.rs holds level 4 to level 5 and both, reflection and
/// transmission, to a Monte Carlo estimate from the BSDF's own samples within 4σ.
pub fn single_scattering_albedo_dielectric<D: MicrofacetDistribution<f64>>(
    dist: &D,
    wo: [f64; 3],
    eta: f64,
) -> (f64, f64) {
    single_scattering_albedo_dielectric_level(dist, wo, eta, G2Form::Approximate, 4)
}

/// Which height-correlated G2 a dielectric's single scattering uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum G2Form {
    /// 1/(1 + Λo + Λi) for both lobes: [`crate::bsdf::RoughDielectric`], as pbrt-v4.
    #[default]
    Approximate,
    /// The exact height-correlated form (Heitz 2014, "Understanding the masking-shadowing
    /// function", section 6): 1/(1 + Λo + Λi) for a reflection, B(1 + Λo, 1 + Λi) (Euler's
    /// beta function) for a transmission; the walk's order 1 ([`RandomWalk::eval`]).
    Exact,
}

/// [`single_scattering_albedo_dielectric`] with a given G2 and level of the tanh-sinh rule.
pub fn single_scattering_albedo_dielectric_level<D: MicrofacetDistribution<f64>>(
    dist: &D,
    wo: [f64; 3],
    eta: f64,
    g2: G2Form,
    level: u32,
) -> (f64, f64) {
    if !(eta > 0.0 && eta.is_finite()) {
        return (0.0, 0.0);
    }
    over_normals(dist, wo, Some(eta), g2, level)
}

/// The single-scattering albedo over the microfacet normal (the method of
/// [`single_scattering_albedo_dielectric`]): a dielectric of relative index η (reflection,
/// transmission), or with `None` the F = 1 mirror facets of [`single_scattering_albedo`]
/// (reflection only; 0 from below).
fn over_normals<D: MicrofacetDistribution<f64>>(
    dist: &D,
    wo: [f64; 3],
    eta: Option<f64>,
    g2: G2Form,
    level: u32,
) -> (f64, f64) {
    use std::f64::consts::{FRAC_PI_2, PI};
    if wo.iter().any(|x| !x.is_finite()) || wo[2] == 0.0 || (eta.is_none() && wo[2] < 0.0) {
        return (0.0, 0.0);
    }
    // (A mirror is η = ∞: no transmission, R = 1; its levels below are the dielectric's
    // with η > 1.)
    let mirror = eta.is_none();
    let eta = eta.unwrap_or(f64::INFINITY);
    let (wo, eta) = if wo[2] < 0.0 {
        ([wo[0], wo[1], -wo[2]], 1.0 / eta)
    } else {
        (wo, eta)
    };
    let len = dot(wo, wo).sqrt();
    let wo = [wo[0] / len, wo[1] / len, wo[2] / len];
    let mu = wo[2];
    let st = ((1.0 - mu) * (1.0 + mu)).max(0.0).sqrt();
    let theta_o = st.atan2(mu);
    let e1 = if st > 0.0 {
        [wo[0] / st, wo[1] / st]
    } else {
        [1.0, 0.0]
    };
    let e2 = [-e1[1], e1[0]];
    let c_tir = if eta < 1.0 {
        Some(((1.0 - eta) * (1.0 + eta)).sqrt())
    } else {
        None
    };
    // The refraction's horizon level at cos θm = cm (η < 1), where it exists.
    let c_t = |cm: f64| -> Option<f64> {
        if eta >= 1.0 {
            return None;
        }
        let k = mu / cm;
        let c = (k * k + (1.0 - eta) * (1.0 + eta)) / (2.0 * k);
        (c >= k && c <= 1.0).then_some(c)
    };
    let integrand = |theta: f64, phi: f64| -> (f64, f64) {
        let (sm, cm) = theta.sin_cos();
        let (sp, cp) = phi.sin_cos();
        let m = [
            sm * (cp * e1[0] + sp * e2[0]),
            sm * (cp * e1[1] + sp * e2[1]),
            cm,
        ];
        let c = dot(wo, m);
        if !(c > 0.0) {
            return (0.0, 0.0);
        }
        let w = dist.d(m) * c / mu * sm;
        if !(w > 0.0 && w.is_finite()) {
            return (0.0, 0.0);
        }
        let r = if mirror {
            1.0
        } else {
            crate::bsdf::fresnel::dielectric(c, eta)
        };
        let wr = [
            2.0 * c * m[0] - wo[0],
            2.0 * c * m[1] - wo[1],
            2.0 * c * m[2] - wo[2],
        ];
        let gr = if wr[2] > 0.0 { dist.g2(wo, wr) } else { 0.0 };
        let cos2_t = 1.0 - (1.0 - c) * (1.0 + c) / (eta * eta);
        let gt = if !mirror && r < 1.0 && cos2_t > 0.0 {
            let k = c / eta - cos2_t.sqrt();
            let wt = [
                k * m[0] - wo[0] / eta,
                k * m[1] - wo[1] / eta,
                k * m[2] - wo[2] / eta,
            ];
            if !(wt[2] < 0.0) {
                0.0
            } else if g2 == G2Form::Exact {
                let (lo, li) = (dist.lambda(wo), dist.lambda(wt));
                let b =
                    libm::lgamma(1.0 + lo) + libm::lgamma(1.0 + li) - libm::lgamma(2.0 + lo + li);
                b.exp()
            } else {
                dist.g2(wo, wt)
            }
        } else {
            0.0
        };
        (w * r * gr, w * (1.0 - r) * gt)
    };
    let rule = crate::math::quad::rule01(level);
    let (ax, ay) = dist.alpha();
    let iso = ax == ay;
    let over_phi = |theta: f64| -> (f64, f64) {
        let (sm, cm) = theta.sin_cos();
        let mut cuts = vec![0.0, PI];
        let mut levels = vec![0.0, mu / (2.0 * cm)];
        levels.extend(c_tir);
        levels.extend(c_t(cm));
        let den = st * sm;
        if den > 0.0 {
            for c in levels {
                let x = (c - mu * cm) / den;
                if x > -1.0 && x < 1.0 {
                    cuts.push(x.acos());
                }
            }
        }
        cuts.sort_by(f64::total_cmp);
        let mut sum = (0.0, 0.0);
        for p in cuts.windows(2) {
            let (r, t) = apply_rule(&rule, p[0], p[1], |phi| {
                let a = integrand(theta, phi);
                if iso {
                    (2.0 * a.0, 2.0 * a.1)
                } else {
                    let b = integrand(theta, -phi);
                    (a.0 + b.0, a.1 + b.1)
                }
            });
            sum.0 += r;
            sum.1 += t;
        }
        sum
    };
    // Outer cuts: the constant levels' entries, the reflection's (closed forms), the
    // refraction's (bisection on a scan), and the peak of D.
    let mut cuts = vec![0.0, FRAC_PI_2];
    let mut push = |x: f64| {
        if x > 0.0 && x < FRAC_PI_2 {
            cuts.push(x);
        }
    };
    for c in std::iter::once(0.0).chain(c_tir) {
        let a = c.acos();
        push(a - theta_o);
        push(theta_o - a);
        push(a + theta_o);
    }
    push(0.5 * (theta_o + FRAC_PI_2));
    push(0.5 * (FRAC_PI_2 - theta_o));
    let a_min = ax.min(ay);
    for k in [0.25, 1.0, 4.0] {
        push((k * a_min).atan());
    }
    if eta < 1.0 {
        let sides = |th: f64| -> [f64; 3] {
            let cm = th.cos();
            let c = c_t(cm).unwrap_or(f64::NAN);
            let k = mu / cm;
            [
                c - (theta_o - th).cos(),
                c - (theta_o + th).cos(),
                (1.0 - eta) * (1.0 + eta) - k * k,
            ]
        };
        const SCAN: usize = 256;
        let mut prev = (1e-9, sides(1e-9));
        for i in 1..=SCAN {
            let th = FRAC_PI_2 * i as f64 / SCAN as f64 * (1.0 - 1e-12);
            let cur = sides(th);
            for (j, &b) in cur.iter().enumerate() {
                let a = prev.1[j];
                if a.is_finite() && b.is_finite() && (a < 0.0) != (b < 0.0) {
                    let (mut lo, mut hi) = (prev.0, th);
                    for _ in 0..60 {
                        let mid = 0.5 * (lo + hi);
                        let v = sides(mid)[j];
                        if v.is_finite() && (v < 0.0) == (a < 0.0) {
                            lo = mid;
                        } else {
                            hi = mid;
                        }
                    }
                    push(0.5 * (lo + hi));
                }
            }
            prev = (th, cur);
        }
    }
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let mut sum = (0.0, 0.0);
    for p in cuts.windows(2) {
        let (r, t) = apply_rule(&rule, p[0], p[1], over_phi);
        sum.0 += r;
        sum.1 += t;
    }
    sum
}

/// ∫_a^b of a pair-valued f by `rule`.
fn apply_rule(
    rule: &[(f64, bool, f64)],
    a: f64,
    b: f64,
    mut f: impl FnMut(f64) -> (f64, f64),
) -> (f64, f64) {
    let len = b - a;
    let mut sum = (0.0, 0.0);
    for &(d, upper, w) in rule {
        let x = if upper { b - len * d } else { a + len * d };
        let (p, q) = f(x);
        if p.is_finite() && q.is_finite() {
            sum.0 += w * p;
            sum.1 += w * q;
        }
    }
    (sum.0 * len, sum.1 * len)
}

/// ∫ g(wi) dωi over the hemisphere of sign `side` (±1: wi.z of that sign) of a lobe that
/// peaks at |cos θi| = `mu_peak` and at the azimuth opposite wo's (a reflection's or a
/// refraction's), by nested adaptive tanh-sinh in (|cos θi|, φ), split at the peak in both:
/// relative tolerance `tol` (the inner integrals at `tol`/10).
pub(crate) fn lobe_integral(
    g: impl Fn([f64; 3]) -> f64,
    wo: [f64; 3],
    mu_peak: f64,
    side: f64,
    tol: f64,
) -> f64 {
    use crate::math::quad::integrate;
    let phi_o = wo[1].atan2(wo[0]);
    let f = |mu: f64, phi: f64| -> f64 {
        let s = ((1.0 - mu) * (1.0 + mu)).max(0.0).sqrt();
        let (sp, cp) = (phi_o + std::f64::consts::PI + phi).sin_cos();
        g([s * cp, s * sp, side * mu])
    };
    // φ measured from the peak's azimuth: both ends of [−π, π] are the lobe's far side.
    let over_phi = |mu: f64| {
        integrate(|p| f(mu, p), -std::f64::consts::PI, 0.0, 0.1 * tol).value
            + integrate(|p| f(mu, p), 0.0, std::f64::consts::PI, 0.1 * tol).value
    };
    let m = mu_peak.clamp(0.0, 1.0);
    integrate(over_phi, 0.0, m, tol).value + integrate(over_phi, m, 1.0, tol).value
}
