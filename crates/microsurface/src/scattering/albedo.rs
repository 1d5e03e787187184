//! The walk's albedo statistics (estimates with standard errors, by side and order) and the
//! single-scattering albedo by quadrature: see the [`crate::scattering`] docs.

// `!(x > 0)` is the NaN-aware test (false for NaN), on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::walk::{Facets, RandomWalk, WalkRng, Walked};
use crate::bsdf::frame::dot;
use crate::bsdf::Masking;
use crate::distribution::MicrofacetDistribution;

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
/// total), over `orders` order bins (1, 2, …, ≥ `orders`; [`Albedo`]'s 4 by default).
#[derive(Clone, Debug)]
pub(crate) struct AlbedoSums {
    /// [side][order 1, …, ≥ orders, any], side 0 reflection, 1 transmission.
    bins: [Vec<Bin>; 2],
    total: Bin,
    walks: u64,
}

impl Default for AlbedoSums {
    fn default() -> Self {
        AlbedoSums::with_orders(4)
    }
}

impl AlbedoSums {
    /// Sums over `orders` ≥ 1 order bins (the last one: that order and above).
    pub(crate) fn with_orders(orders: usize) -> Self {
        let k = orders.max(1) + 1;
        AlbedoSums {
            bins: [vec![Bin::default(); k], vec![Bin::default(); k]],
            total: Bin::default(),
            walks: 0,
        }
    }

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
        let any = bins.len() - 1;
        bins[(p.order.max(1) as usize).min(any) - 1].add(w);
        bins[any].add(w);
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

    /// The estimates by side and order.
    pub(crate) fn finish_orders(&self) -> AlbedoOrders {
        let side = |b: &[Bin]| {
            let e: Vec<Estimate> = b.iter().map(|x| x.estimate(self.walks)).collect();
            let (orders, total) = e.split_at(e.len() - 1);
            (orders.to_vec(), total[0])
        };
        let (reflect, reflect_total) = side(&self.bins[0]);
        let (transmit, transmit_total) = side(&self.bins[1]);
        AlbedoOrders {
            reflect,
            reflect_total,
            transmit,
            transmit_total,
            total: self.total.estimate(self.walks),
        }
    }

    /// [`Albedo`] (of sums with 4 order bins, the default).
    pub(crate) fn finish(&self) -> Albedo {
        self.finish_orders().four()
    }
}

/// The albedo by side and by any number of orders K ([`albedo_orders`]): `reflect[k]` and
/// `transmit[k]` the energy leaving on each side after k + 1 events, the last entry after
/// K or more; each side's total; and the total over sides.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct AlbedoOrders {
    pub reflect: Vec<Estimate>,
    pub reflect_total: Estimate,
    pub transmit: Vec<Estimate>,
    pub transmit_total: Estimate,
    pub total: Estimate,
}

impl AlbedoOrders {
    /// [`Albedo`] of estimates by 4 order bins (orders 1, 2, 3, ≥ 4), as [`albedo`] makes
    /// them.
    fn four(self) -> Albedo {
        debug_assert_eq!(self.reflect.len(), 4, "four order bins");
        let side = |o: &[Estimate], t: Estimate| ByOrder {
            orders: std::array::from_fn(|k| o[k].mean),
            stderr: std::array::from_fn(|k| o[k].stderr),
            total: t.mean,
            total_stderr: t.stderr,
        };
        Albedo {
            reflect: side(&self.reflect, self.reflect_total),
            transmit: side(&self.transmit, self.transmit_total),
            total: self.total,
        }
    }
}

/// [`Albedo`] from `walks` walks from wo (E_k(wo) = E[weight; the walk leaves on that side
/// after k events]); walks that fail (wo on the horizon, cut paths) count with weight 0.
/// One channel (a spectral albedo is one call per channel, each with its own seed or the
/// same one for correlated estimates). [`albedo_orders`] with 4 orders.
///
/// **Streams.** The walks run in two interleaved lanes (their dependency chains overlap in
/// the processor): ⌈walks/2⌉ walks one after another from the stream of `seed`
/// ([`WalkRng::new`]), ⌊walks/2⌋ from a second stream derived from it, each walk what
/// [`RandomWalk::walk`] gives from its stream, the two lanes' sums merged. A deterministic
/// function of the arguments, as before the lanes; not the figures of one stream.
pub fn albedo<D: MicrofacetDistribution<f64>>(
    surface: &RandomWalk<D>,
    facets: &impl Facets<1>,
    wo: [f64; 3],
    walks: u64,
    seed: u64,
) -> Albedo {
    albedo_orders(surface, facets, wo, walks, seed, 4).four()
}

/// The albedo by side and by `orders` order bins (1, 2, …, `orders` − 1 and ≥ `orders`;
/// at least 1) from wo (any finite nonzero length), as [`albedo`] (the same walks from the
/// same seed, in the same two lanes: its 4-order figures are these at `orders` = 4, and the
/// orders below the last are the same for any `orders`).
pub fn albedo_orders<D: MicrofacetDistribution<f64>>(
    surface: &RandomWalk<D>,
    facets: &impl Facets<1>,
    wo: [f64; 3],
    walks: u64,
    seed: u64,
    orders: usize,
) -> AlbedoOrders {
    // (A direction of any finite nonzero length, as the contract has them: the walk's
    // heights and cosines are for unit vectors.)
    let wo = crate::distribution::unit(wo);
    let mut rngs: [WalkRng; LANES] = std::array::from_fn(|j| match j {
        0 => WalkRng::new(seed),
        _ => WalkRng::new(lane_seed(seed, j as u64)),
    });
    let mut sums: [AlbedoSums; LANES] = std::array::from_fn(|_| AlbedoSums::with_orders(orders));
    surface.walk_lanes(facets, wo, walks, &mut rngs, |j, w| sums[j].add(wo, w));
    let (first, rest) = sums.split_at_mut(1);
    for b in rest.iter() {
        first[0].merge(b);
    }
    first[0].finish_orders()
}

/// The walks [`albedo_orders`] interleaves ([`RandomWalk`]'s lanes): two measured faster than
/// one and than four (BENCHMARKS.md, target 7).
const LANES: usize = 2;

/// The seed of lane `j` ≥ 1's stream from the call's `seed` (a SplitMix64 output: streams
/// far apart in the generator's sequence).
pub(crate) fn lane_seed(seed: u64, j: u64) -> u64 {
    crate::math::rng::SplitMix64(seed ^ j.wrapping_mul(0xD1B5_4A32_D192_ED03)).next_u64()
}

/// [`albedo_orders`] as it was before the walks were interleaved: one stream, one walk after
/// another (the benchmark's baseline).
#[doc(hidden)]
pub fn albedo_orders_serial<D: MicrofacetDistribution<f64>>(
    surface: &RandomWalk<D>,
    facets: &impl Facets<1>,
    wo: [f64; 3],
    walks: u64,
    seed: u64,
    orders: usize,
) -> AlbedoOrders {
    let wo = crate::distribution::unit(wo);
    let mut rng = WalkRng::new(seed);
    let mut sums = AlbedoSums::with_orders(orders);
    for _ in 0..walks {
        sums.add(wo, surface.walk(facets, wo, &mut rng));
    }
    sums.finish_orders()
}

/// The single-scattering albedo of a conductor with F = 1 and the height-correlated G2,
/// E₁(wo) = ∫ D(wh) G2(wo, wi)/(4 cos θo) dωi over the upper hemisphere (wh the half
/// vector; wo below the surface is −wo's mirror image, E(wo) = E(−wo): the BSDFs are
/// two-sided; 0 on the horizon), by nested adaptive tanh-sinh quadrature in (cos θi, φ), split where the lobe
/// peaks (the mirror direction's θ and azimuth): relative error ≤ 1e-9 requested, 1e-6
/// guaranteed by tests/walk.rs against an independent rule. The walk's order 1 estimates the
/// same quantity. For the NDFs whose D has a pole at the normal (Ei, Erfc, K0, Bessel-K
/// a ≤ 1) the integral is taken over the microfacet normal instead, as
/// [`single_scattering_albedo_dielectric`] does (level 4 of its rule), where the pole is an
/// end point of the outer integral: measured, it agrees with the integral over wi to 1e-12
/// (K0, Ei at α = 0.3, μ ∈ {0.2, 0.7, 1}; GGX, Beckmann too), levels 3 to 5 agree to 3e-11
/// for Bessel-K a = 0.3, and it takes seconds there where the integral over wi took minutes
/// (K0: tens of milliseconds).
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
    // wo below the surface: the BSDFs are two-sided (a pair below is the mirror image −wo,
    // −wi of a pair above, whose f is the same: every NDF is point-symmetric in its slopes),
    // so E(wo) = E(−wo), as AlbedoTable::e, e_dir and the walk's albedo have it.
    let wo = if wo[2] < 0.0 {
        [-wo[0], -wo[1], -wo[2]]
    } else {
        wo
    };
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
        return over_normals(dist, wo, None, Masking::Correlated, 4).0;
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
/// directional albedo of [`crate::bsdf::RoughDielectric`] (its default G2 =
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
/// **Masking.** [`single_scattering_albedo_dielectric_level`] takes the BSDF's other
/// [`Masking`] forms. The default transmits more than the exact height-correlated
/// [`Masking::CorrelatedBeta`] (B(1 + Λo, 1 + Λi) for G2(wo, wt), the random walk's order 1)
/// wherever Λo and Λi are both large: measured for GGX at η = 1.5 from outside, 0.7278
/// against 0.0506 at α = 1, μo = 0.05 (the walk: 0.0504 ± 0.0002), 0.7185 against 0.5890
/// at α = 1, μo = 0.5, equal at μo = 1 (the table in [`crate::bsdf::RoughDielectric`]'s
/// docs, both sides in docs/derivations.md G). The reflection is the same.
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
/// from both sides, μ ∈ [0.01, 1]): level 4 (the default; milliseconds) within 1.7e-5 (Double
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
    single_scattering_albedo_dielectric_level(dist, wo, eta, Masking::Correlated, 4)
}

/// [`single_scattering_albedo_dielectric`] of the BSDF with a given masking-shadowing term
/// (`RoughDielectric::with_masking`; [`Masking::CorrelatedBeta`] is the random walk's order
/// 1, [`RandomWalk::eval`]) and level of the tanh-sinh rule. The accuracy above was measured
/// for the default; level 4 against level 5 with [`Masking::CorrelatedBeta`] is held to the
/// same 3e-5 by tests/bsdf.rs.
pub fn single_scattering_albedo_dielectric_level<D: MicrofacetDistribution<f64>>(
    dist: &D,
    wo: [f64; 3],
    eta: f64,
    masking: Masking,
    level: u32,
) -> (f64, f64) {
    if !(eta > 0.0 && eta.is_finite()) {
        return (0.0, 0.0);
    }
    over_normals(dist, wo, Some(eta), masking, level)
}

/// The single-scattering albedo over the microfacet normal (the method of
/// [`single_scattering_albedo_dielectric`]): a dielectric of relative index η (reflection,
/// transmission), or with `None` the F = 1 mirror facets of [`single_scattering_albedo`]
/// (reflection only; 0 from below).
fn over_normals<D: MicrofacetDistribution<f64>>(
    dist: &D,
    wo: [f64; 3],
    eta: Option<f64>,
    masking: Masking,
    level: u32,
) -> (f64, f64) {
    let (r, t) = over_normals_weighted(dist, wo, eta, masking, level, |_| [1.0]);
    (r[0], t[0])
}

/// [`over_normals`] of K integrands at once: the facets' reflected and transmitted shares
/// each weighted by `weights(c)`, c = wo·m the cosine at the microfacet (a split sum's
/// Fresnel terms; smooth in c, so the rule's cuts at the level sets of c stay the only
/// places the integrand is not smooth).
pub(crate) fn over_normals_weighted<D: MicrofacetDistribution<f64>, const K: usize>(
    dist: &D,
    wo: [f64; 3],
    eta: Option<f64>,
    masking: Masking,
    level: u32,
    weights: impl Fn(f64) -> [f64; K],
) -> ([f64; K], [f64; K]) {
    use std::f64::consts::{FRAC_PI_2, PI};
    let zero = ([0.0; K], [0.0; K]);
    if wo.iter().any(|x| !x.is_finite()) || wo[2] == 0.0 || (eta.is_none() && wo[2] < 0.0) {
        return zero;
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
    let integrand = |theta: f64, phi: f64| -> ([f64; K], [f64; K]) {
        let (sm, cm) = theta.sin_cos();
        let (sp, cp) = phi.sin_cos();
        let m = [
            sm * (cp * e1[0] + sp * e2[0]),
            sm * (cp * e1[1] + sp * e2[1]),
            cm,
        ];
        let c = dot(wo, m);
        if !(c > 0.0) {
            return zero;
        }
        let w = dist.d(m) * c / mu * sm;
        if !(w > 0.0 && w.is_finite()) {
            return zero;
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
        let gr = if wr[2] > 0.0 {
            masking.g2(dist, wo, wr)
        } else {
            0.0
        };
        let cos2_t = 1.0 - (1.0 - c) * (1.0 + c) / (eta * eta);
        let gt = if !mirror && r < 1.0 && cos2_t > 0.0 {
            let k = c / eta - cos2_t.sqrt();
            let wt = [
                k * m[0] - wo[0] / eta,
                k * m[1] - wo[1] / eta,
                k * m[2] - wo[2] / eta,
            ];
            if wt[2] < 0.0 {
                masking.g2(dist, wo, wt)
            } else {
                0.0
            }
        } else {
            0.0
        };
        let (wr, wt) = (w * r * gr, w * (1.0 - r) * gt);
        let k = weights(c);
        (k.map(|x| wr * x), k.map(|x| wt * x))
    };
    let rule = crate::math::quad::rule01(level);
    let (ax, ay) = dist.alpha();
    let iso = ax == ay;
    let over_phi = |theta: f64| -> ([f64; K], [f64; K]) {
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
        let mut sum = zero;
        for p in cuts.windows(2) {
            let (r, t) = apply_rule(&rule, p[0], p[1], |phi| {
                let a = integrand(theta, phi);
                let b = if iso { a } else { integrand(theta, -phi) };
                (add(a.0, b.0), add(a.1, b.1))
            });
            sum = (add(sum.0, r), add(sum.1, t));
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
    let mut sum = zero;
    for p in cuts.windows(2) {
        let (r, t) = apply_rule(&rule, p[0], p[1], over_phi);
        sum = (add(sum.0, r), add(sum.1, t));
    }
    sum
}

fn add<const K: usize>(a: [f64; K], b: [f64; K]) -> [f64; K] {
    std::array::from_fn(|i| a[i] + b[i])
}

/// ∫_a^b of a pair-valued f by `rule` (a node whose value is not finite counts 0).
fn apply_rule<const K: usize>(
    rule: &[(f64, bool, f64)],
    a: f64,
    b: f64,
    mut f: impl FnMut(f64) -> ([f64; K], [f64; K]),
) -> ([f64; K], [f64; K]) {
    let len = b - a;
    let mut sum = ([0.0; K], [0.0; K]);
    for &(d, upper, w) in rule {
        let x = if upper { b - len * d } else { a + len * d };
        let (p, q) = f(x);
        if p.iter().chain(&q).all(|v| v.is_finite()) {
            for i in 0..K {
                sum.0[i] += w * p[i];
                sum.1[i] += w * q[i];
            }
        }
    }
    (sum.0.map(|v| v * len), sum.1.map(|v| v * len))
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scattering::{DielectricFacets, Heights};
    use crate::{Ggx, Microfacet};

    /// The interleaved walks are each lane's walks one after another: `albedo_orders` is,
    /// bit for bit, the merged sums of ⌈n/2⌉ walks from the seed's stream and ⌊n/2⌋ from the
    /// second lane's (an odd count, a rough dielectric whose walks end at different steps).
    #[test]
    fn lanes_are_their_streams_walks() {
        let s = RandomWalk::new(
            Microfacet::<f64, Ggx>::new(1.5, 1.5).unwrap(),
            Heights::Uniform,
        );
        let (f, wo, n, seed) = (
            DielectricFacets::new(1.5).unwrap(),
            [0.6, 0.0, 0.8],
            20_001,
            5,
        );
        let lane = |rng: &mut WalkRng, walks: u64| {
            let mut sums = AlbedoSums::with_orders(6);
            for _ in 0..walks {
                sums.add(wo, s.walk::<1>(&f, wo, rng));
            }
            sums
        };
        let mut a = lane(&mut WalkRng::new(seed), n - n / 2);
        a.merge(&lane(&mut WalkRng::new(lane_seed(seed, 1)), n / 2));
        assert_eq!(a.finish_orders(), albedo_orders(&s, &f, wo, n, seed, 6));
    }
}
