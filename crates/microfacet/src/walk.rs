//! Multiple scattering on the microsurface: the random walk of Heitz, Hanika, d'Eon and
//! Dachsbacher (2016), "Multiple-Scattering Microfacet BSDFs with the Smith Model", for every
//! NDF of the library (through [`Distribution`]).
//!
//! **The model.** The Smith microsurface is a volume of microflakes with normals distributed
//! as D, stacked over heights h with a height distribution P1 (CDF C1). A ray travelling in
//! direction w (unit) at height h meets the microsurface above h' < h … the walk's free path
//! is the height at which it next intersects: for a ray going up (w.z > 0) it escapes with
//! probability G1(w, h) = C1(h)^Λ(w), else it meets the surface at the height h' with
//! C1(h') = C1(h)/(1 − U)^{1/Λ(w)} (U uniform); going down (w.z < 0) it always meets it, the
//! same formula with Λ(w) = −1 − Λ(−w) ≤ −1 (Smith's Λ extended to the lower hemisphere, the
//! paper's eq. 8). At each intersection the ray picks a microfacet among those it sees, the
//! visible normals D_{−w}(m) ∝ max(0, −w·m) D(m), and scatters off it (a conductor: mirror
//! reflection with Fresnel weight; a diffuse facet: a cosine lobe about m). The walk's output
//! is the direction it leaves in, the product of the weights, and the number of scattering
//! events (the order).
//!
//! **Heights.** The BSDF does not depend on the height distribution (the paper, section 4.1:
//! the walk's heights are a monotone reparametrisation of C1 ∈ [0, 1]). [`Heights::Uniform`]
//! (h ∈ [−1, 1]) and [`Heights::Gaussian`] (standard normal) are both provided, and
//! tests/walk.rs checks that they give the same albedos within the Monte Carlo error. The walk
//! starts above the surface (C1 = 1).
//!
//! **Visible normals from below.** A ray going up can still meet the microsurface; its
//! visible normals are those of the direction v = −w with v.z < 0, D_v(m) ∝ max(0, v·m) D(m)
//! over the upper hemisphere of m (normalisation σ(v) = |v.z| Λ(|v|)). [`Distribution`]'s
//! sampler mirrors a down-welling direction (pbrt's convention), which is another
//! distribution; the walk samples D_v by rejection from D_{v′}, v′ = (v.x, v.y, |v.z|): for m
//! in the upper hemisphere v·m = v′·m − 2|v.z| m.z ≤ v′·m, so accepting m with probability
//! max(0, v·m)/(v′·m) leaves exactly D_v (acceptance σ(v)/σ(v′) = Λ/(1 + Λ), which is small
//! only for steep upward rays, and those rarely meet the surface: the expected number of
//! candidates per step stays bounded).
//!
//! **Order 1** is the single-scattering BSDF with the height-correlated G2 (the paper's
//! section 5.3): for a conductor with F = 1, E₁(μ) = ∫ D G2/(4μ) dωi, which
//! [`single_scattering_albedo`] integrates deterministically and tests/walk.rs holds the
//! walk's order 1 to, within 4 standard errors.
//!
//! **Uniforms** are drawn strictly inside (0, 1) (53-bit uniforms shifted by half a step): a
//! uniform of exactly 0 in the height step would leave the ray at its height forever, and
//! one that rounds to 1 would make a walk leave with no bounce (a bug of a public f32 port
//! of the paper's code).

// `!(x > 0)` is the NaN-aware test (false for NaN), on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::distribution::Distribution;
use crate::frame::{dot, reflect};
use crate::fresnel::Fresnel;

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
    /// C1(h) (1 above the microsurface's top, +∞).
    fn c1(self, h: f64) -> f64 {
        match self {
            Heights::Uniform => (0.5 * (h + 1.0)).clamp(0.0, 1.0),
            Heights::Gaussian => 0.5 * crate::special::erfc(-h * std::f64::consts::FRAC_1_SQRT_2),
        }
    }

    /// C1⁻¹(c) for c ∈ (0, 1].
    fn inv_c1(self, c: f64) -> f64 {
        match self {
            Heights::Uniform => 2.0 * c - 1.0,
            Heights::Gaussian => {
                std::f64::consts::SQRT_2 * crate::fast::beckmann::erfinv_2u_minus_1(c)
            }
        }
    }
}

/// A 53-bit uniform strictly inside (0, 1): (k + ½)/2⁵³ for the top 53 bits k of a
/// SplitMix64 output (Steele, Lea & Flood 2014).
#[derive(Clone, Debug)]
pub struct WalkRng(u64);

impl WalkRng {
    /// The stream of `seed`.
    pub fn new(seed: u64) -> Self {
        WalkRng(seed ^ 0x5851_F42D_4C95_7F2D)
    }

    /// The next uniform in (0, 1).
    #[inline]
    pub fn next_open(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        ((z >> 11) as f64 + 0.5) * (1.0 / 9_007_199_254_740_992.0)
    }
}

/// What the microfacets do with a ray: the phase function's second half, given the facet.
pub trait Facets<const N: usize> {
    /// The direction the ray leaves the facet wm in, having arrived from v (v = −w, the
    /// reverse of its travel; v·wm > 0), and the weight that multiplies the path's, per
    /// channel. `None`: absorbed (the path ends with weight 0).
    fn scatter(&self, v: [f64; 3], wm: [f64; 3], rng: &mut WalkRng)
        -> Option<([f64; 3], [f64; N])>;
}

/// Mirror facets with a Fresnel term (a conductor; `fresnel::One::<1>` for the white
/// furnace).
#[derive(Clone, Copy, Debug)]
pub struct MirrorFacets<Fr>(pub Fr);

impl<Fr: Fresnel<f64, N>, const N: usize> Facets<N> for MirrorFacets<Fr> {
    #[inline]
    fn scatter(&self, v: [f64; 3], wm: [f64; 3], _: &mut WalkRng) -> Option<([f64; 3], [f64; N])> {
        Some((reflect(v, wm), self.0.eval(dot(v, wm).abs())))
    }
}

/// Lambertian facets of albedo ρ (Heitz et al.'s diffuse microsurface): the ray leaves in a
/// cosine-weighted direction about the facet's normal, weight ρ.
#[derive(Clone, Copy, Debug)]
pub struct DiffuseFacets(pub f64);

impl Facets<1> for DiffuseFacets {
    fn scatter(
        &self,
        _v: [f64; 3],
        wm: [f64; 3],
        rng: &mut WalkRng,
    ) -> Option<([f64; 3], [f64; 1])> {
        // A cosine-weighted direction in wm's frame.
        let local = crate::frame::cosine_hemisphere([rng.next_open(), rng.next_open()]);
        let frame = crate::frame::Frame::from_normal(wm);
        Some((frame.from_local(local), [self.0]))
    }
}

/// One walk's result.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Walked<const N: usize> {
    /// The direction the path leaves the microsurface in (w.z > 0).
    pub w: [f64; 3],
    /// The product of the facets' weights.
    pub weight: [f64; N],
    /// The number of scattering events (≥ 1).
    pub order: u32,
}

/// Walks longer than this are cut ([`Microsurface::walk`] answers `None`, which [`albedo`]
/// counts as weight 0). The mean order of an F = 1 conductor at normal incidence grows with
/// the roughness, about 3α (measured for GGX: 26 at α = 10, 305 at α = 100, 3130 at
/// α = 1000), so walks are cut, and energy lost, only on surfaces far rougher than any
/// material (α ≳ 300); at α ≤ 2 the mean order is below 4.
pub const MAX_ORDER: u32 = 10_000;

/// The microsurface of a distribution with a height distribution: the walk's state-free part.
#[derive(Clone, Debug)]
pub struct Microsurface<D> {
    dist: D,
    heights: Heights,
}

impl<D: Distribution<f64>> Microsurface<D> {
    /// The microsurface of `dist` with heights distributed as `heights`.
    pub fn new(dist: D, heights: Heights) -> Self {
        Microsurface { dist, heights }
    }

    /// The distribution.
    pub fn distribution(&self) -> &D {
        &self.dist
    }

    /// Smith's Λ for a travel direction w of either hemisphere: Λ(w) above, −1 − Λ(−w) below
    /// (the paper's eq. 8; [`Distribution::lambda`] is Λ of the side w comes from).
    pub fn lambda_signed(&self, w: [f64; 3]) -> f64 {
        let l = self.dist.lambda(w);
        if w[2] >= 0.0 {
            l
        } else {
            -1.0 - l
        }
    }

    /// The next height for a ray travelling in w from height h, or `None` if it escapes
    /// (upward rays only), from the uniform u ∈ (0, 1).
    fn next_height(&self, w: [f64; 3], h: f64, u: f64) -> Option<f64> {
        let lc = self.heights.c1(h).ln();
        let l = self.lambda_signed(w);
        let lu = (-u).ln_1p();
        // Going up, it escapes with probability G1 = C1(h)^Λ: u > 1 − C1^Λ, that is
        // ln(1 − u) < Λ ln C1 (no powf; ln(1 − u) serves the next line too).
        if w[2] > 0.0 && (lu < l * lc || !(l > 0.0)) {
            return None;
        }
        // C1(h') = C1(h)/(1 − u)^{1/Λ}: ln-space, so that (1 − u)^{1/Λ} does not underflow.
        let c_next = (lc - lu / l).exp();
        if !(c_next > 0.0) {
            // (Going down from the top with a tiny C1: below every height the distribution
            // resolves; the path meets the surface at its bottom.)
            return Some(self.heights.inv_c1(f64::MIN_POSITIVE));
        }
        Some(self.heights.inv_c1(c_next.min(1.0)))
    }

    /// A visible normal for the direction v (either hemisphere; the microflakes' D_v(m) ∝
    /// max(0, v·m) D(m)): the distribution's own sampler above, the rejection of the module
    /// docs below.
    fn visible_normal(&self, v: [f64; 3], rng: &mut WalkRng) -> [f64; 3] {
        if v[2] >= 0.0 {
            return self.dist.sample_wm(v, [rng.next_open(), rng.next_open()]);
        }
        let up = [v[0], v[1], -v[2]];
        let mut m = up;
        // (The expected number of candidates is (1 + Λ)/Λ, large only for steep rays, which
        // rarely get here; the cap keeps a direction straight down, which no facet faces,
        // from looping: it is never reached in tests/walk.rs or the fuzz suite.)
        for _ in 0..1_000_000 {
            m = self.dist.sample_wm(up, [rng.next_open(), rng.next_open()]);
            let (a, b) = (dot(v, m), dot(up, m));
            if rng.next_open() * b < a || !(b > 0.0) {
                return m;
            }
        }
        m
    }

    /// One walk from the direction wo (toward the viewer, wo.z > 0: the path arrives along
    /// −wo). `None` for wo on or below the horizon, or a path cut at [`MAX_ORDER`].
    pub fn walk<const N: usize>(
        &self,
        facets: &impl Facets<N>,
        wo: [f64; 3],
        rng: &mut WalkRng,
    ) -> Option<Walked<N>> {
        if !(wo[2] > 0.0) {
            return None;
        }
        let mut w = [-wo[0], -wo[1], -wo[2]];
        let mut h = f64::INFINITY;
        let mut weight = [1.0; N];
        for order in 0..=MAX_ORDER {
            match self.next_height(w, h, rng.next_open()) {
                None => {
                    return Some(Walked { w, weight, order });
                }
                Some(next) => h = next,
            }
            let v = [-w[0], -w[1], -w[2]];
            let m = self.visible_normal(v, rng);
            let (out, f) = facets.scatter(v, m, rng)?;
            for (a, b) in weight.iter_mut().zip(f) {
                *a *= b;
            }
            w = out;
            // (h = +∞ is the top of a Gaussian microsurface: a grazing ray meets it where C1
            // rounds to 1. Only NaN is a failure.)
            if !(w[0].is_finite() && w[1].is_finite() && w[2].is_finite()) || h.is_nan() {
                return None;
            }
        }
        None
    }
}

/// The albedo of a microsurface by order: E_k(wo) = E[weight; the walk's order is k] for
/// k = 1, 2, 3 and ≥ 4, their total, and standard errors (per channel 0 of the weight).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Albedo {
    /// E₁, E₂, E₃, E₄₊.
    pub orders: [f64; 4],
    /// Their standard errors.
    pub stderr: [f64; 4],
    /// E = ΣE_k.
    pub total: f64,
    /// Its standard error.
    pub total_stderr: f64,
}

/// [`Albedo`] from `walks` walks from wo, channel 0 of the facets' weight; walks that fail
/// (wo on the horizon, cut paths) count with weight 0.
pub fn albedo<D: Distribution<f64>, const N: usize>(
    surface: &Microsurface<D>,
    facets: &impl Facets<N>,
    wo: [f64; 3],
    walks: u64,
    seed: u64,
) -> Albedo {
    let mut rng = WalkRng::new(seed);
    let (mut s, mut s2) = ([0.0; 5], [0.0; 5]);
    for _ in 0..walks {
        if let Some(r) = surface.walk(facets, wo, &mut rng) {
            let x = r.weight[0];
            let k = (r.order.max(1) as usize).min(4) - 1;
            s[k] += x;
            s2[k] += x * x;
            s[4] += x;
            s2[4] += x * x;
        }
    }
    let n = walks.max(1) as f64;
    let stat = |k: usize| {
        let mean = s[k] / n;
        let var = (s2[k] / n - mean * mean).max(0.0);
        (mean, (var / n).sqrt())
    };
    let e: [(f64, f64); 5] = std::array::from_fn(stat);
    Albedo {
        orders: [e[0].0, e[1].0, e[2].0, e[3].0],
        stderr: [e[0].1, e[1].1, e[2].1, e[3].1],
        total: e[4].0,
        total_stderr: e[4].1,
    }
}

/// The single-scattering albedo of a conductor with F = 1 and the height-correlated G2,
/// E₁(wo) = ∫ D(wh) G2(wo, wi)/(4 cos θo) dωi over the upper hemisphere (wh the half
/// vector), by nested adaptive tanh-sinh quadrature in (cos θi, φ), split where the lobe
/// peaks (the mirror direction's θ and azimuth): relative error ≤ 1e-9 requested, 1e-6
/// guaranteed by tests/walk.rs against an independent rule. The walk's order 1 estimates the
/// same quantity.
pub fn single_scattering_albedo<D: Distribution<f64>>(dist: &D, wo: [f64; 3]) -> f64 {
    single_scattering_albedo_tol(dist, wo, 1e-9)
}

/// [`single_scattering_albedo`] at relative tolerance `tol` (the inner integrals at
/// `tol`/10).
pub(crate) fn single_scattering_albedo_tol<D: Distribution<f64>>(
    dist: &D,
    wo: [f64; 3],
    tol: f64,
) -> f64 {
    use crate::quad::integrate;
    let mu_o = wo[2];
    if !(mu_o > 0.0) {
        return 0.0;
    }
    let phi_o = wo[1].atan2(wo[0]);
    let f_cos = |mu: f64, phi: f64| -> f64 {
        let s = ((1.0 - mu) * (1.0 + mu)).max(0.0).sqrt();
        let (sp, cp) = (phi_o + std::f64::consts::PI + phi).sin_cos();
        let wi = [s * cp, s * sp, mu];
        let h = [wo[0] + wi[0], wo[1] + wi[1], wo[2] + wi[2]];
        let l = dot(h, h).sqrt();
        if !(l > 0.0) {
            return 0.0;
        }
        let wh = [h[0] / l, h[1] / l, h[2] / l];
        dist.d(wh) * dist.g2(wo, wi) / (4.0 * mu_o)
    };
    // φ measured from the mirror azimuth: the lobe peaks at φ = 0 (both ends of [−π, π] are
    // its far side), and at μ = μo.
    let over_phi = |mu: f64| {
        integrate(|p| f_cos(mu, p), -std::f64::consts::PI, 0.0, 0.1 * tol).value
            + integrate(|p| f_cos(mu, p), 0.0, std::f64::consts::PI, 0.1 * tol).value
    };
    integrate(over_phi, 0.0, mu_o, tol).value + integrate(over_phi, mu_o, 1.0, tol).value
}
