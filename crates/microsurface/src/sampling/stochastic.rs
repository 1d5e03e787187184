//! The pages' own stochastic samplers, behind `rand`'s [`Distribution`] trait. Each draws a
//! microfacet normal distributed as D(m) cos θm by sampling the mixing variable of a
//! superposition and then the component (they consume a variable number of uniforms, so they
//! are not warps of `[f64; 2]`; the deterministic samplers are in [`crate::sampling`]).
//!
//! * [`DoubleGgxMixture`]: t ~ Gamma(1) = Exp(1), then GGX with roughness α/√t (the Double GGX page).
//! * [`GgxBeckmannMixture`]: t ~ Exp(1), then Beckmann with roughness α/√t (the GGX page).
//! * [`ExponentialChi3`]: three Gaussians and one uniform (the Exponential NDF page):
//!   cos θm = 1/√(1 − (α²/2)(g₁² + g₂² + g₃²) ln u₁), azimuth uniform.

use crate::math::vec3::Vec3;
use crate::sampling::dcos::{normal_from_polar_slope, RadialSlopes};
use crate::{Beckmann, Ggx, ParamError};
use rand::distr::Distribution;
use rand::{Rng, RngExt};
use std::f64::consts::PI;

/// Uniform in (0, 1] (never 0, so logarithms are finite).
fn uniform_open0<R: Rng + ?Sized>(rng: &mut R) -> f64 {
    1.0 - rng.random::<f64>()
}

/// Exp(1) by inversion.
fn exp1<R: Rng + ?Sized>(rng: &mut R) -> f64 {
    -uniform_open0(rng).ln()
}

/// A standard normal pair by Box–Muller.
fn normal_pair<R: Rng + ?Sized>(rng: &mut R) -> (f64, f64) {
    let r = (-2.0 * uniform_open0(rng).ln()).sqrt();
    let (s, c) = (2.0 * PI * rng.random::<f64>()).sin_cos();
    (r * c, r * s)
}

/// A D·cos normal of a component NDF, from two fresh uniforms.
fn component_dcos<N: RadialSlopes, R: Rng + ?Sized>(n: &N, rng: &mut R) -> Vec3 {
    let r = n.slope_quantile(rng.random::<f64>());
    normal_from_polar_slope(r, 2.0 * PI * rng.random::<f64>())
}

/// Double GGX (D·cos) as a Gamma-1 superposition of GGX.
#[derive(Clone, Copy, Debug)]
pub struct DoubleGgxMixture {
    alpha: f64,
}

impl DoubleGgxMixture {
    pub fn new(alpha: f64) -> Result<Self, ParamError> {
        Ok(DoubleGgxMixture {
            alpha: crate::error::check_alpha(alpha)?,
        })
    }
}

impl Distribution<Vec3> for DoubleGgxMixture {
    fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> Vec3 {
        let t = exp1(rng);
        component_dcos(&Ggx::raw(self.alpha / t.sqrt()), rng)
    }
}

/// GGX (D·cos) as a Gamma-1 superposition of Beckmann.
#[derive(Clone, Copy, Debug)]
pub struct GgxBeckmannMixture {
    alpha: f64,
}

impl GgxBeckmannMixture {
    pub fn new(alpha: f64) -> Result<Self, ParamError> {
        Ok(GgxBeckmannMixture {
            alpha: crate::error::check_alpha(alpha)?,
        })
    }
}

impl Distribution<Vec3> for GgxBeckmannMixture {
    fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> Vec3 {
        let t = exp1(rng);
        component_dcos(&Beckmann::raw(self.alpha / t.sqrt()), rng)
    }
}

/// The Exponential NDF (D·cos) from three Gaussians and one uniform (its Chi-3 superposition
/// of Beckmann).
#[derive(Clone, Copy, Debug)]
pub struct ExponentialChi3 {
    alpha: f64,
}

impl ExponentialChi3 {
    pub fn new(alpha: f64) -> Result<Self, ParamError> {
        Ok(ExponentialChi3 {
            alpha: crate::error::check_alpha(alpha)?,
        })
    }
}

impl Distribution<Vec3> for ExponentialChi3 {
    fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> Vec3 {
        let (g1, g2) = normal_pair(rng);
        let (g3, _) = normal_pair(rng);
        let chi2 = g1 * g1 + g2 * g2 + g3 * g3;
        // tan²θ = −(α²/2) χ² ln u₁, i.e. cos θ = 1/√(1 + tan²θ) as on the page.
        let tan2 = -0.5 * self.alpha * self.alpha * chi2 * uniform_open0(rng).ln();
        normal_from_polar_slope(tan2.sqrt(), 2.0 * PI * rng.random::<f64>())
    }
}

/// Visible normals of a superposition by the posterior of its mixing variable: t is drawn
/// with density ∝ w(t) σ_t(w) (σ is linear in D, so this is exact), then a visible normal of
/// the component with roughness α(t) (spherical caps for GGX, exact slope inversion for
/// Beckmann). Works in the α = 1 configuration of (αx, αy), so anisotropy comes for free.
///
/// Kinds: Double GGX (Gamma-1 of GGX), Exponential (Gamma(3/2) of Beckmann), and GGX as a
/// Gamma-1 superposition of Beckmann (a check of the method). The posterior CDF is inverted
/// by safeguarded Newton on tanh-sinh quadratures (1e-12).
#[derive(Clone, Copy, Debug)]
pub struct VisibleMixture {
    target: crate::distribution::kernels::Stretched,
    wi: Vec3,
    /// The posterior's normalisation ∫ w(t) σ_t dt (a function of the target and wi alone,
    /// integrated once here rather than per sample).
    total: f64,
}

impl VisibleMixture {
    /// Visible normals of `kind` (Double GGX, Exponential or GGX) at roughness (αx, αy)
    /// seen from `wi` (a down-welling `wi` is mirrored, as in [`crate::MicrofacetDistribution`]).
    pub fn new(
        kind: crate::UnitSlopes,
        alpha_x: f64,
        alpha_y: f64,
        wi: Vec3,
    ) -> Result<Self, &'static str> {
        let target = crate::distribution::kernels::Stretched::new(kind, alpha_x, alpha_y)
            .map_err(|_| "alpha outside [1e-6, 1e6]")?;
        match kind {
            crate::UnitSlopes::Beckmann => Err("Beckmann is not a superposition in this family"),
            _ => {
                let mut m = VisibleMixture {
                    target,
                    wi: if wi.z < 0.0 { -wi } else { wi }.normalize(),
                    total: 0.0,
                };
                m.total =
                    crate::math::quad::integrate_to_inf(|t| m.density(t), 0.0, 1.0, 1e-13).value;
                Ok(m)
            }
        }
    }

    /// The direction in the α = 1 configuration of the target.
    fn w1(&self) -> Vec3 {
        self.target.stretch(self.wi).normalize()
    }

    /// The posterior density of the mixing variable t, unnormalised: w(t) σ_t(w1).
    fn density(&self, t: f64) -> f64 {
        use crate::distribution::kernels::Microsurface;
        let (mixing, component) = self.parts();
        let a = mixing.roughness(1.0, t);
        mixing.pdf(1.0, t)
            * crate::distribution::kernels::Stretched::raw(component, a, a).sigma(self.w1())
    }

    /// (mixing, component kind).
    fn parts(&self) -> (crate::ndf::mixture::Mixing, crate::UnitSlopes) {
        use crate::ndf::mixture::Mixing;
        use crate::UnitSlopes as U;
        match self.target.kind() {
            U::DoubleGgx => (Mixing::Gamma1, U::Ggx),
            U::Exponential => (Mixing::Gamma32, U::Beckmann),
            _ => (Mixing::Gamma1, U::Beckmann),
        }
    }
}

impl Distribution<Vec3> for VisibleMixture {
    fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> Vec3 {
        use crate::distribution::kernels::Microsurface;
        let (mixing, component) = self.parts();
        let w1 = self.w1();
        let density = |t: f64| self.density(t);
        let total = self.total;
        // Posterior CDF of t by quadrature, inverted in ln t; each of Newton's steps
        // integrates only from the previous iterate (the steps shrink as it converges).
        let memo = std::cell::Cell::new((0.0f64, 0.0f64));
        let cdf = |t: f64| {
            let (t0, c0) = memo.get();
            let c = if t >= t0 {
                c0 + crate::math::quad::integrate(density, t0, t, 1e-13).value
            } else {
                c0 - crate::math::quad::integrate(density, t, t0, 1e-13).value
            };
            memo.set((t, c));
            c / total
        };
        let xi = rng.random::<f64>();
        let s = crate::math::solve::newton_bracketed(
            |s| cdf(s.exp()) - xi,
            |s| density(s.exp()) * s.exp() / total,
            -60.0,
            60.0,
            0.0,
        );
        let a = mixing.roughness(1.0, s.exp());
        let m1 = crate::distribution::kernels::Stretched::raw(component, a, a)
            .sample_visible(w1, [rng.random::<f64>(), rng.random::<f64>()]);
        let (ax, ay) = self.target.alpha();
        // m1 ∝ (x̃, ỹ, 1) in the α = 1 configuration → (αx x̃, αy ỹ, 1); visible from wi
        // where the unstretch's rounding had tipped it (as every visible sampler).
        crate::distribution::kernels::facing(
            Vec3::new(ax * m1.x, ay * m1.y, m1.z).normalize(),
            self.wi,
        )
    }
}
