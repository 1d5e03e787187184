//! The pages' own stochastic samplers, behind `rand`'s [`Distribution`] trait. Each draws a
//! microfacet normal distributed as D(m) cos θm by sampling the mixing variable of a
//! superposition and then the component (they consume a variable number of uniforms, so they
//! are not warps of `[f64; 2]`; the deterministic samplers are in [`crate::sample`]).
//!
//! * [`DoubleGgxMixture`]: t ~ Gamma(1) = Exp(1), then GGX with roughness α/√t (seed 002).
//! * [`GgxBeckmannMixture`]: t ~ Exp(1), then Beckmann with roughness α/√t (seed 000).
//! * [`ExponentialChi3`]: three Gaussians and one uniform (seed 004):
//!   cos θm = 1/√(1 − (α²/2)(g₁² + g₂² + g₃²) ln u₁), azimuth uniform.

use crate::sample::{normal_from_polar_slope, RadialSlopes};
use crate::vec3::Vec3;
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
