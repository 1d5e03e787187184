//! Continuous superpositions (mixtures) of NDFs: D = ∫ w(t) D_{α(t)} dt.
//!
//! σ, and hence Λ(u) = σ(−u)/u at a fixed u, are linear in D, so they mix with the same weights;
//! G1 does not (mix σ, never G1). The pages' representations (seeds 000, 002, 004):
//!
//! | mixing | weight w(t) | component roughness α(t) | gives |
//! |---|---|---|---|
//! | [`Mixing::Frechet2`] | 2α² e^{−α²/t²}/t³ (t = α_B) | t | GGX from Beckmann |
//! | [`Mixing::Gamma1`] | e^{−t} | α/√t | GGX from Beckmann; Double GGX from GGX |
//! | [`Mixing::Gamma32`] | √t e^{−t}/Γ(3/2) | α√t | Exponential from Beckmann |
//! | [`Mixing::Chi3`] | √(2/π) t² e^{−t²/2} | α t/√2 | Exponential from Beckmann |
//! | [`Mixing::InverseGamma`]`(k)` | t^{k−1} e^{−t}/Γ(k) | α√(k/t) | Student-T (k = γ − 1) from Beckmann |
//! | [`Mixing::Gamma`]`(k)` | t^{k−1} e^{−t}/Γ(k) | α√t | K0 (k = 1), Bessel-K (k = a) from Beckmann |
//! | [`Mixing::UniformSquare`] | 1 on (0, 1) | α√t | Ei from Beckmann |
//! | [`Mixing::Uniform`] | 1 on (0, 1) | α t | Erfc from Beckmann |
//!
//! [`superpose`] integrates any component quantity against a mixing density by tanh-sinh
//! quadrature on (0, ∞) (relative tolerance 1e-13); it is what `microsurface verify` uses to check
//! the representations, and what visible-normal sampling of the mixtures will build on.

use crate::math::quad;
use crate::{Beckmann, Ggx};
use std::f64::consts::PI;

/// A mixing density over the component roughness.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mixing {
    /// Fréchet(shape 2, scale α) over the component roughness itself.
    Frechet2,
    /// Gamma(1, 1) = Exp(1) over t, component roughness α/√t.
    Gamma1,
    /// Gamma(3/2, 1) over t, component roughness α√t.
    Gamma32,
    /// Chi with 3 degrees of freedom over t, component roughness α t/√2.
    Chi3,
    /// Gamma(k, 1) over t, component roughness α√(k/t) (Student-T with k = γ − 1).
    InverseGamma(f64),
    /// Gamma(k, 1) over t, component roughness α√t (Bessel-K with k = a; K0 at k = 1).
    Gamma(f64),
    /// Uniform on (0, 1), component roughness α√t (the Ei NDF).
    UniformSquare,
    /// Uniform on (0, 1), component roughness α t (the Erfc NDF).
    Uniform,
}

impl Mixing {
    /// The weight density w(t) for mixture roughness α.
    pub fn pdf(self, alpha: f64, t: f64) -> f64 {
        if t <= 0.0 || !t.is_finite() {
            return 0.0;
        }
        match self {
            Mixing::Frechet2 => {
                let r = alpha / t;
                2.0 * r * r * (-r * r).exp() / t
            }
            Mixing::Gamma1 => (-t).exp(),
            // Γ(3/2) = √π/2
            Mixing::Gamma32 => t.sqrt() * (-t).exp() / (0.5 * PI.sqrt()),
            Mixing::Chi3 => (2.0 / PI).sqrt() * t * t * (-0.5 * t * t).exp(),
            Mixing::InverseGamma(k) | Mixing::Gamma(k) => crate::math::special::gamma_pdf(k, t),
            Mixing::UniformSquare | Mixing::Uniform => {
                if t < 1.0 {
                    1.0
                } else {
                    0.0
                }
            }
        }
    }

    /// The component roughness α(t).
    pub fn roughness(self, alpha: f64, t: f64) -> f64 {
        match self {
            Mixing::Frechet2 => t,
            Mixing::Gamma1 => alpha / t.sqrt(),
            Mixing::Gamma32 => alpha * t.sqrt(),
            Mixing::Chi3 => alpha * t / std::f64::consts::SQRT_2,
            Mixing::InverseGamma(k) => alpha * (k / t).sqrt(),
            Mixing::Gamma(_) | Mixing::UniformSquare => alpha * t.sqrt(),
            Mixing::Uniform => alpha * t,
        }
    }

    /// The natural scale of t (where the weight lives).
    fn scale(self, alpha: f64) -> f64 {
        match self {
            Mixing::Frechet2 => alpha,
            Mixing::InverseGamma(k) | Mixing::Gamma(k) => k,
            _ => 1.0,
        }
    }

    /// Name for reports.
    pub fn name(self) -> &'static str {
        match self {
            Mixing::Frechet2 => "Frechet-2",
            Mixing::Gamma1 => "Gamma-1",
            Mixing::Gamma32 => "Gamma(3/2)",
            Mixing::Chi3 => "Chi-3",
            Mixing::InverseGamma(_) => "inverse-Gamma",
            Mixing::Gamma(_) => "Gamma",
            Mixing::UniformSquare => "uniform in β²",
            Mixing::Uniform => "uniform in β",
        }
    }
}

/// ∫₀^∞ w(t) q(α(t)) dt: the mixture of a component quantity `q(roughness)`.
///
/// The integrand can be a narrow peak far from the weight's own scale (at grazing angles and
/// small α the components that matter are the rough ones, deep in the weight's tail), so the
/// quadrature's scale is put at the integrand's maximum, found on a logarithmic grid of t.
pub fn superpose(mixing: Mixing, alpha: f64, q: impl Fn(f64) -> f64) -> quad::Quad {
    let f = |t: f64| {
        let w = mixing.pdf(alpha, t);
        if w == 0.0 {
            return 0.0;
        }
        w * q(mixing.roughness(alpha, t))
    };
    if matches!(mixing, Mixing::Uniform | Mixing::UniformSquare) {
        // Finite support: tanh-sinh on (0, 1) (the integrand's peak, if any, is at an end).
        return quad::integrate(f, 0.0, 1.0, 1e-13);
    }
    // 1e-12 … 1e12 around the weight's scale, 8 points per decade.
    let base = mixing.scale(alpha);
    let mut peak = (base, f(base).abs());
    for k in -96..=96 {
        let t = base * 10f64.powf(k as f64 / 8.0);
        let v = f(t).abs();
        if v > peak.1 {
            peak = (t, v);
        }
    }
    quad::integrate_to_inf(f, 0.0, peak.0, 1e-13)
}

/// A fixed quadrature rule over the mixing variable at roughness α: (component roughness,
/// weight) pairs such that Σ wᵢ q(αᵢ) = ∫ w(t) q(α(t)) dt to ~1e-14 for q smooth and bounded in
/// t (tanh-sinh, step 1/32; checked against [`superpose`] in the tests).
pub fn fixed_rule(mixing: Mixing, alpha: f64) -> Vec<(f64, f64)> {
    quad::half_line_rule(|t| mixing.pdf(alpha, t), mixing.scale(alpha), 5)
        .into_iter()
        .map(|(t, w)| (mixing.roughness(alpha, t), w))
        .collect()
}

/// Mixture of Beckmann components; `q` sees each component (any roughness > 0, unchecked).
pub fn superpose_beckmann(mixing: Mixing, alpha: f64, q: impl Fn(&Beckmann) -> f64) -> f64 {
    superpose(mixing, alpha, |a| q(&Beckmann::raw(a))).value
}

/// Mixture of GGX components; `q` sees each component (any roughness > 0, unchecked).
pub fn superpose_ggx(mixing: Mixing, alpha: f64, q: impl Fn(&Ggx) -> f64) -> f64 {
    superpose(mixing, alpha, |a| q(&Ggx::raw(a))).value
}

/// Exact visible-normal sampling of a Beckmann mixture (Student-T, Ei, Erfc, K0, Bessel-K):
/// the posterior of the mixing variable, then that Beckmann component's visible normal.
///
/// For a direction v the visible-normal distribution max(0, v·m) D(m)/σ(v) of
/// D = ∫ w(t) D_B(β(t)) dt is the mixture of the components' visible-normal distributions
/// with the posterior weights w(t) σ_B(v; β(t))/σ(v). With z = v.z > 0 and h the stretched
/// horizontal length of the unit v (h = |(αx vx, αy vy)|), Beckmann's projected area is
/// σ_B = z (1 + erf a)/2 + βh e^{−a²}/(2√π), a = z/(βh) (its Λ = (e^{−a²}/(a√π) − erfc a)/2,
/// written as two positive terms), and
/// max(z, βh/(2√π)) ≤ σ_B ≤ z + βh/(2√π).
/// The upper bound's two terms are two standard laws: the prior w (weight z) and the
/// size-biased prior w(t)β(t)/E[β] (weight h E[β]/(2√π)); a candidate from their mixture is
/// kept with probability σ_B/(z + βh/(2√π)) ≥ ½, so at most two candidates on average
/// (d'Eon, *A Hitchhiker's Guide to Multiple Scattering*, the NDF pages' mixture
/// representations; the sampler and its bounds are derived in `docs/derivations.md` F.7). The size-biased
/// priors, in t of [`Mixing`] (β for α = 1):
///
/// | mixing | β(t) | prior | size-biased | E[β] |
/// |---|---|---|---|---|
/// | `InverseGamma(k)` (Student-T, k = γ − 1) | √(k/t) | Gamma(k) | Gamma(k − ½) | √k Γ(k − ½)/Γ(k) |
/// | `Gamma(k)` (K0 k = 1, Bessel-K k = a) | √t | Gamma(k) | Gamma(k + ½) | Γ(k + ½)/Γ(k) |
/// | `UniformSquare` (Ei) | √t | U | U^{2/3} | 2/3 |
/// | `Uniform` (Erfc) | t | U | √U | ½ |
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Posterior {
    mixing: Mixing,
    /// E[β] under the prior, for α = 1.
    mean_beta: f64,
}

impl Posterior {
    /// The sampler of `mixing`'s posterior; `None` for the mixings it does not cover (the
    /// classic NDFs' own, which have their own samplers) and for Student-T with k ≤ ½
    /// (γ ≤ 3/2: E[β] = ∞, Λ infinite).
    pub(crate) fn new(mixing: Mixing) -> Option<Posterior> {
        let mean_beta = match mixing {
            Mixing::InverseGamma(k) if k > 0.5 => {
                k.sqrt() / crate::math::special::gamma_ratio_half(k - 0.5)
            }
            Mixing::Gamma(k) => crate::math::special::gamma_ratio_half(k),
            Mixing::UniformSquare => 2.0 / 3.0,
            Mixing::Uniform => 0.5,
            _ => return None,
        };
        Some(Posterior { mixing, mean_beta })
    }

    /// The mixing density.
    pub(crate) fn mixing(&self) -> Mixing {
        self.mixing
    }

    /// The mixing's parameter k (0 for the uniform mixings) and E[β] (the GPU tables).
    pub(crate) fn parameters(&self) -> (f64, f64) {
        let k = match self.mixing {
            Mixing::InverseGamma(k) | Mixing::Gamma(k) => k,
            _ => 0.0,
        };
        (k, self.mean_beta)
    }

    /// ln β(t) for t drawn from the prior (D·cos sampling of the mixture).
    pub(crate) fn draw_prior_ln_beta(&self, next: &mut dyn FnMut() -> f64) -> f64 {
        self.draw_ln_beta(false, next)
    }

    /// ln β(t) for t drawn from the prior, or from the size-biased prior.
    fn draw_ln_beta(&self, size_biased: bool, next: &mut dyn FnMut() -> f64) -> f64 {
        let bias = if size_biased { 1.0 } else { 0.0 };
        // (A uniform of exactly 0, which [0, 1) sources give, reads as 2^−53: ln 0 would send
        // β to 0 or ∞, a spike normal whose D overflows.)
        let next = &mut || next().max(f64::EPSILON / 2.0);
        match self.mixing {
            Mixing::InverseGamma(k) => 0.5 * (k.ln() - ln_gamma_variate(k - 0.5 * bias, next)),
            Mixing::Gamma(k) => 0.5 * ln_gamma_variate(k + 0.5 * bias, next),
            // t = U^{1/(1 + bias/2)}: U, or U^{2/3} (density (3/2)√t).
            Mixing::UniformSquare => 0.5 * next().ln() / (1.0 + 0.5 * bias),
            // t = U or √U (density 2t).
            Mixing::Uniform => next().ln() / (1.0 + bias),
            _ => f64::NAN,
        }
    }

    /// ln β of the posterior for a unit direction with z = v.z > 0 and stretched horizontal
    /// length h (see the type's docs); `None` after 64 candidates (acceptance ≥ ½:
    /// probability below 1e-19).
    pub(crate) fn sample_ln_beta(
        &self,
        z: f64,
        h: f64,
        next: &mut dyn FnMut() -> f64,
    ) -> Option<f64> {
        const C: f64 = 0.5 / crate::math::special::SQRT_PI;
        let p_prior = z / (z + C * h * self.mean_beta);
        for _ in 0..64 {
            let size_biased = next() >= p_prior;
            let ln_beta = self.draw_ln_beta(size_biased, next);
            let hb = h * ln_beta.exp();
            // (hb = 0 or ∞: σ_B equals its bound, z or βh/(2√π).)
            let keep = if hb > 0.0 && hb.is_finite() {
                let a = z / hb;
                let sigma =
                    0.5 * z * (1.0 + crate::math::special::erf(a)) + C * hb * (-a * a).exp();
                sigma / (z + C * hb)
            } else {
                1.0
            };
            if next() < keep {
                return Some(ln_beta);
            }
        }
        None
    }
}

impl Posterior {
    /// A visible normal for the unit direction v (v.z > 0) at roughness (αx, αy): β from
    /// [`Posterior::sample_ln_beta`], then Beckmann's stream sampler at (β αx, β αy).
    /// `None` where either gives up (see theirs) or v is not above the horizon.
    pub(crate) fn sample_visible<F: crate::math::real::Real>(
        &self,
        v: [f64; 3],
        ax: f64,
        ay: f64,
        next: &mut dyn FnMut() -> f64,
    ) -> Option<[F; 3]> {
        if v[2].is_nan() || v[2] <= 0.0 {
            return None;
        }
        let h = crate::math::vec3::hypot(ax * v[0], ay * v[1]);
        let ln_beta = self.sample_ln_beta(v[2], h, next)?;
        // β (αx, αy) within [1e-290, 1e290], where the component sampler's slopes stay
        // finite: β = 0 or ∞ (a Gamma variate of small shape in logarithms, e^{ln β}) has
        // probability 0 and would give a pole or horizon normal anyway.
        let (lo, hi) = (ax.min(ay).ln(), ax.max(ay).ln());
        let beta = ln_beta.clamp(-667.0 - lo, 667.0 - hi).exp();
        let (bx, by) = (F::from_f64(beta * ax), F::from_f64(beta * ay));
        let v = v.map(F::from_f64);
        crate::fast::beckmann::sample_visible_above(v, bx, by, &mut || F::from_f64(next()))
    }
}

/// ln of a Gamma(k, 1) variate, k > 0 (Marsaglia & Tsang 2000, "A simple method for
/// generating gamma variables": acceptance ≥ 0.95 for k ≥ 1; below, Gamma(k + 1) U^{1/k},
/// their §6, kept in logarithms, where U^{1/k} underflows for small k). NaN after 64
/// rejections (probability below 1e-80).
fn ln_gamma_variate(k: f64, next: &mut dyn FnMut() -> f64) -> f64 {
    if k < 1.0 {
        let boost = next().ln() / k;
        return ln_gamma_variate(k + 1.0, next) + boost;
    }
    let d = k - 1.0 / 3.0;
    let c = 1.0 / (9.0 * d).sqrt();
    for _ in 0..64 {
        let x = crate::fast::ziggurat::normal(next(), &mut || next());
        let v = 1.0 + c * x;
        if v <= 0.0 {
            continue;
        }
        let v = v * v * v;
        if next().ln() < 0.5 * x * x + d - d * v + d * v.ln() {
            return d.ln() + v.ln();
        }
    }
    f64::NAN
}
