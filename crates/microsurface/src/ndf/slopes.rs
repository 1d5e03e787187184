//! The radial slope distribution under D·cos ([`RadialSlopes`]): what every NDF provides so
//! that [`crate::sampling`] can sample and invert it. The trait sits with the NDFs (each
//! implements it beside its closed forms); the warps built on it are `sampling`'s, which
//! re-exports it.

use crate::math::solve::newton_bracketed;
use crate::ndf::Ndf;
use std::f64::consts::PI;

/// The radial slope distribution of an NDF under D·cos.
pub trait RadialSlopes: Ndf {
    /// F(r) = P(tan θm ≤ r).
    fn slope_cdf(&self, r: f64) -> f64;

    /// 1 − F(r), accurate where F is close to 1.
    fn slope_ccdf(&self, r: f64) -> f64;

    /// The density of r = tan θm: 2π r P22(r).
    fn slope_pdf(&self, r: f64) -> f64 {
        radial_pdf(self, r)
    }

    /// r with F(r) = ξ, for ξ ∈ [0, 1] (ξ = 1 gives +∞).
    fn slope_quantile(&self, xi: f64) -> f64 {
        quantile_by_newton(self, xi)
    }

    /// The tail index β of an algebraic (Pareto) tail, 1 − F(r) ∝ r^{−β} (P22 ∝ r^{−β−2})
    /// as r → ∞ up to corrections of relative order 1/r² or smaller; `None` (the default)
    /// for tails lighter than every power, or not of that form. GGX and GTR β = 2, Student-T
    /// β = 2γ − 2. The visible sampler ([`crate::sampling::radial`]) continues a tail with
    /// β < 3/2 (visible mass ∝ r^{1−β} per ln r, spread over many decades) analytically
    /// beyond the slopes its quadrature covers.
    fn slope_tail_index(&self) -> Option<f64> {
        None
    }
}

/// 2π r P22(r, 0), with its limits at r = 0 and ∞ (not 0·∞): P22 grows slower than 1/r at the
/// pole (a logarithm at most; Bessel-K with a ≤ ½ overrides `slope_pdf`) and falls faster
/// than 1/r² at infinity.
pub(crate) fn radial_pdf<N: Ndf + ?Sized>(n: &N, r: f64) -> f64 {
    if r == 0.0 || r == f64::INFINITY {
        return 0.0;
    }
    2.0 * PI * r * n.p22(r, 0.0)
}

/// The quantile at the edges: NaN → NaN, ξ ≤ 0 → 0, ξ ≥ 1 → ∞; `None` inside (0, 1).
pub(crate) fn quantile_edge(xi: f64) -> Option<f64> {
    if xi.is_nan() {
        Some(xi)
    } else if xi <= 0.0 {
        Some(0.0)
    } else if xi >= 1.0 {
        Some(f64::INFINITY)
    } else {
        None
    }
}

/// Generic quantile: Newton on F (or on 1 − F above the median) in ln r.
pub(crate) fn quantile_by_newton<N: RadialSlopes + ?Sized>(n: &N, xi: f64) -> f64 {
    if let Some(r) = quantile_edge(xi) {
        return r;
    }
    let a = n.alpha();
    // ln r ∈ [ln α − 745, ln α + 745] brackets every representable quantile.
    let (lo, hi) = (a.ln() - 745.0, a.ln() + 745.0);
    let dfds = |s: f64| {
        let r = s.exp();
        n.slope_pdf(r) * r
    };
    let s = if xi <= 0.5 {
        newton_bracketed(|s| n.slope_cdf(s.exp()) - xi, dfds, lo, hi, a.ln())
    } else {
        let q = 1.0 - xi; // exact for ξ ≥ 0.5
        newton_bracketed(|s| q - n.slope_ccdf(s.exp()), dfds, lo, hi, a.ln())
    };
    s.exp()
}
