//! The Student-T NDF (Ribardière, Bringier, Meneveaux & Simonot 2017, "STD: Student's
//! t-MicrofacetDistribution of Slopes for Microfacet Based BSDFs", Computer Graphics Forum 36(2); the
//! StudentT_NDF page of d'Eon's *A Hitchhiker's Guide to Multiple Scattering*).
//!
//! With c = α²(γ − 1):
//!
//! D(u) = (1 + tan²θ/c)^{−γ}/(π α² u⁴),  P22(r) = (1 + r²/c)^{−γ}/(π α²),
//! f(x) = ((γ−1)/(x² + γ − 1))^γ/π,  P2(p) = (1 + p²/c)^{½−γ}/(B(γ−1, ½) √c),
//! Q(T) = P(tan θm > T) = (1 + T²/c)^{1−γ},  σ(0) = √c/(B(γ−1, ½)(2γ − 3)).
//!
//! γ = 2 is GGX(α) exactly; γ → ∞ is Beckmann(α) (relative difference O((r/α)⁴/γ)). It is a
//! superposition of Beckmann NDFs: m ~ Gamma(γ − 1, 1), component roughness α√((γ−1)/m).
//!
//! **Λ** (derived; docs/derivations.md F.1). With ζ = cot θ/√c, z₀ = 1/(1 + ζ²),
//! s = √(1 + ζ²), b = γ − 1:
//!
//!   Λ = z₀^b/B(b, ½) · s/((2b − 1) ζ) − I_{z₀}(b, ½)/2            (incomplete beta)
//!     = z₀^b/B(b, ½) · [ (s/ζ)/(2b(2b − 1)) + Σ_{n≥0} cₙ z₀ⁿ/(b + n + 1) / (4b s ζ) ],
//!
//! cₙ = (b + ½)ₙ/(b + 1)ₙ. The second form has only positive terms: the first cancels by a
//! factor ≈ 2γ s²/(1 + s²) (Λ is the small difference of the two terms), which the series
//! removes analytically (it follows from I_z(b, ½) = z^b √(1−z) ₂F₁(b + ½, 1; b + 1; z)/(b B)).
//!
//! **Parameters.** α ∈ [1e-6, 1e6], γ ∈ (1, 1e6]: D is normalised for every γ > 1. For
//! γ ≤ 3/2 the mean slope E|p| diverges: Λ(u) = +∞ for every u < 1, σ(0) = σ(u ≠ 1) = +∞ and
//! G1 = 0 (what this type returns); the direction API ([`crate::Exact`]) needs Λ finite and
//! rejects γ ≤ 3/2. Λ has a pole at γ = 3/2 (∝ 1/(2γ − 3)).
//!
//! # Numerics
//! * (1 + t)^{−γ} as exp(−γ ln1p t) (no overflow at large γ), t = r²/c from 1 − u² in
//!   double-double; past the overflow of t, ln(1 + t) = ln t.
//! * Λ: the series for z₀ ≤ 0.84 (ζ ≥ 0.44; ≤ 200 terms to 1e-17); below it the incomplete
//!   beta form for γ ≤ 21 (its cancellation, a factor ≤ 1.1 b there, costs ≤ 1.5 digits), and the
//!   Smith integral over P2 (tanh-sinh, positive integrand) for larger γ.
//! * B(b, ½) = √π Γ(b)/Γ(b + ½) through `special::gamma_ratio_half` (exact also where
//!   both Gammas overflow).
//! * Accuracy (tests/reference.rs against mpmath): closed forms ≤ 1e-13 relative; Λ by the Smith
//!   integral (γ > 21, ζ < 0.44) ≤ 1e-12.

use crate::error::{check_alpha, check_shape, ParamError};
use crate::math::special::{dd::Dd, exp_over, gamma_ratio_half, inc_beta};
use crate::ndf::slopes::RadialSlopes;
use crate::ndf::{Ndf, ShapeInvariant};
use std::f64::consts::PI;

use crate::math::special::SQRT_PI;
/// Largest supported γ: beyond it Student-T is Beckmann to ~1e-6 in the body of the lobe
/// and nothing new is tested.
pub const STUDENT_T_GAMMA_MAX: f64 = 1e6;
/// Above this γ the incomplete-beta form of Λ (used for ζ < 0.44) would lose more than
/// 1.5 digits to its cancellation; the Smith integral is used instead.
const INC_BETA_GAMMA_MAX: f64 = 21.0;
/// z₀ at or below which the positive series of Λ is summed (0.84²⁰⁰ < 1e-15 bounds the terms).
const SERIES_Z0_MAX: f64 = 0.84;

/// The Student-T NDF with roughness α and shape γ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StudentT {
    alpha: f64,
    gamma: f64,
    /// c = α²(γ − 1).
    c: f64,
    /// 1/B(γ − 1, ½) = Γ(γ − ½)/(√π Γ(γ − 1)).
    inv_beta: f64,
}

impl StudentT {
    /// Student-T with roughness α ∈ [1e-6, 1e6] and shape γ ∈ (1, 1e6].
    pub fn new(alpha: f64, gamma: f64) -> Result<Self, ParamError> {
        let alpha = check_alpha(alpha)?;
        let gamma = check_shape(
            gamma,
            1.0,
            true,
            STUDENT_T_GAMMA_MAX,
            "student_t gamma",
            "(1, 1e6]",
        )?;
        Ok(StudentT {
            alpha,
            gamma,
            c: alpha * alpha * (gamma - 1.0),
            inv_beta: gamma_ratio_half(gamma - 1.0) / SQRT_PI,
        })
    }

    /// The shape γ.
    pub fn gamma(&self) -> f64 {
        self.gamma
    }

    /// Whether Λ and σ are finite (γ > 3/2).
    pub fn has_finite_lambda(&self) -> bool {
        self.gamma > 1.5
    }

    /// ln(1 + t) for t = r²/c ≥ 0, with r² given as r2 (possibly +∞ from an overflow) and as
    /// ln r² (`ln_r2`, used when r²/c overflows).
    fn ln1p_t(&self, r2: f64, ln_r2: impl Fn() -> f64) -> f64 {
        let t = r2 / self.c;
        if t.is_finite() {
            t.ln_1p()
        } else {
            ln_r2() - self.c.ln()
        }
    }

    /// (1 + t)^{−e} for t = r²/c > 1 by `powf` of the rounded base (≈ e ulps, the condition
    /// number's share: exp(−e ln1p t) would carry e ln t ulps), where that is a normal double;
    /// `None` for t ≤ 1 (ln1p is exact there) and outside the normal range.
    fn pow_tail(&self, r2: f64, e: f64) -> Option<f64> {
        let t = r2 / self.c;
        let v = (1.0 + t).powf(-e);
        (t > 1.0 && v.is_normal()).then_some(v)
    }

    /// D(u) u^k for 0 < u ≤ 1 (k = 0: D; k = 1: D cos θ, finite where D overflows toward the
    /// horizon at γ < 2, D ~ u^{2γ−4}).
    fn d_times_pow(&self, u: f64, k: f64) -> f64 {
        // tan²θ = (1 − u²)/u², 1 − u² in double-double.
        let s2 = Dd::one_minus_sq(u).hi;
        let r2 = s2 / (u * u);
        let norm = PI * self.alpha * self.alpha;
        if r2 > self.c {
            // The tail (t > 1): D u^k = b^{−γ} u^{2γ−4+k}/(π α²) with b = u²(1 + t) =
            // u² + (1 − u²)/c, two powers of rounded bases (≈ 2γ ulps, the condition number's
            // own share) where the exponential of the summed logarithms below would carry
            // |γ ln t| + |4 ln u| ulps.
            let head = (u * u + s2 / self.c).powf(-self.gamma);
            let tail = u.powf(2.0 * self.gamma - 4.0 + k);
            let v = head * tail / norm;
            if head.is_normal() && tail.is_normal() && v.is_normal() {
                return v;
            }
        }
        let l = self.ln1p_t(r2, || s2.ln() - 2.0 * u.ln());
        // Toward the horizon (1 + t)^{−γ} turns subnormal and u⁴ underflows (below u ~ 1e-77)
        // while D ~ u^{2γ−4} stays representable: in logarithms there.
        let d = norm * (u * u) * (u * u);
        exp_over(-self.gamma * l, d / u.powf(k), || {
            norm.ln() + (4.0 - k) * u.ln()
        })
    }

    /// Λ at x = cot θ/α (+∞ for γ ≤ 3/2).
    pub(crate) fn lambda_x(&self, x: f64) -> f64 {
        if !self.has_finite_lambda() {
            return f64::INFINITY;
        }
        // ζ = cot θ/√c = x α/√c.
        let zeta = x * self.alpha / self.c.sqrt();
        self.lambda_zeta(zeta, 1.0 / (1.0 + zeta * zeta))
    }

    /// Λ at ζ = cot θ/√c (ζ > 0), with z₀ = 1/(1 + ζ²) given.
    fn lambda_zeta(&self, zeta: f64, z0: f64) -> f64 {
        let b = self.gamma - 1.0;
        // s/ζ = √(1 + 1/ζ²), formed so that neither overflows.
        let s_over_zeta = (1.0 + 1.0 / (zeta * zeta)).sqrt();
        if z0 <= SERIES_Z0_MAX {
            // z₀^b = exp(−b ln1p(ζ²)).
            let zb = (-b * (zeta * zeta).ln_1p()).exp();
            if zb == 0.0 {
                return 0.0;
            }
            let (mut sum, mut cn, mut pow) = (0.0, 1.0, 1.0);
            for n in 0..400 {
                let nf = n as f64;
                let t = cn * pow / (b + nf + 1.0);
                sum += t;
                if t <= 1e-17 * sum {
                    break;
                }
                cn *= (b + 0.5 + nf) / (b + 1.0 + nf);
                pow *= z0;
            }
            // sum/(4b s ζ) = sum (s/ζ)/(4b s²) with s² = 1 + ζ².
            let s2 = 1.0 + zeta * zeta;
            let bracket =
                s_over_zeta / (2.0 * b * (2.0 * b - 1.0)) + sum * s_over_zeta / (4.0 * b * s2);
            return zb * self.inv_beta * bracket;
        }
        if self.gamma <= INC_BETA_GAMMA_MAX {
            let zb = z0.powf(b);
            return zb * self.inv_beta * s_over_zeta / (2.0 * b - 1.0) - 0.5 * inc_beta(b, 0.5, z0);
        }
        // Smith: Λ = (1/μ) ∫_0^∞ d P2(μ + d) dd, μ = ζ √c.
        let sc = self.c.sqrt();
        let mu = zeta * sc;
        // A fixed rule scaled to P2's decay length at μ (α near the peak, ~ c/((2γ + 1) μ)
        // in the tail), from the slope of ln P2 there.
        let step = 1e-3 * self.alpha;
        let slope = (self.p2(mu).ln() - self.p2(mu + step).ln()) / step;
        let scale = if slope > 0.0 {
            self.alpha.min(1.0 / slope)
        } else {
            self.alpha
        };
        crate::math::quad::to_inf_fixed(
            |d| d * self.p2(mu + d),
            0.0,
            scale,
            crate::math::smith::SMITH_LEVEL,
        ) / mu
    }
}

impl Ndf for StudentT {
    fn name(&self) -> &'static str {
        "student_t"
    }

    fn alpha(&self) -> f64 {
        self.alpha
    }

    fn d_pos(&self, u: f64) -> f64 {
        self.d_times_pow(u, 0.0)
    }

    fn d_cos_pos(&self, u: f64) -> f64 {
        self.d_times_pow(u, 1.0)
    }

    fn p22(&self, p: f64, q: f64) -> f64 {
        let r2 = p * p + q * q;
        if r2.is_nan() {
            return f64::NAN;
        }
        let norm = PI * self.alpha * self.alpha;
        if let Some(v) = self.pow_tail(r2, self.gamma) {
            return v / norm;
        }
        let l = self.ln1p_t(r2, || 2.0 * p.abs().hypot(q.abs()).ln());
        exp_over(-self.gamma * l, norm, || norm.ln())
    }

    fn p2(&self, p: f64) -> f64 {
        if p.is_nan() {
            return p;
        }
        let norm = self.c.sqrt() / self.inv_beta;
        if let Some(v) = self.pow_tail(p * p, self.gamma - 0.5) {
            return v / norm;
        }
        let l = self.ln1p_t(p * p, || 2.0 * p.abs().ln());
        exp_over((0.5 - self.gamma) * l, norm, || norm.ln())
    }

    fn lambda_pos(&self, u: f64) -> f64 {
        if !self.has_finite_lambda() {
            return f64::INFINITY;
        }
        // ζ = cot θ/√c, z₀ = 1/(1 + ζ²) = c(1 − u²)/(c(1 − u²) + u²).
        let s2 = Dd::one_minus_sq(u).hi;
        let zeta = u / (s2.sqrt() * self.c.sqrt());
        let cs = self.c * s2;
        let z0 = cs / (cs + u * u);
        self.lambda_zeta(zeta, z0)
    }

    fn sigma_zero(&self) -> f64 {
        if !self.has_finite_lambda() {
            return f64::INFINITY;
        }
        self.c.sqrt() * self.inv_beta / (2.0 * self.gamma - 3.0)
    }
}

impl ShapeInvariant for StudentT {
    fn f(&self, x: f64) -> f64 {
        let g1 = self.gamma - 1.0;
        let t = x * x / g1;
        let l = if t.is_finite() {
            t.ln_1p()
        } else {
            2.0 * x.abs().ln() - g1.ln()
        };
        (-self.gamma * l).exp() / PI
    }
}

impl RadialSlopes for StudentT {
    fn slope_cdf(&self, r: f64) -> f64 {
        let l = self.ln1p_t(r * r, || 2.0 * r.ln());
        -((1.0 - self.gamma) * l).exp_m1()
    }
    fn slope_ccdf(&self, r: f64) -> f64 {
        let l = self.ln1p_t(r * r, || 2.0 * r.ln());
        ((1.0 - self.gamma) * l).exp()
    }
    fn slope_quantile(&self, xi: f64) -> f64 {
        if xi.is_nan() {
            return xi;
        }
        if xi <= 0.0 {
            return 0.0;
        }
        if xi >= 1.0 {
            return f64::INFINITY;
        }
        // tan²θ = c (e^{−ln(1−ξ)/(γ−1)} − 1) (Ribardière et al. 2017, eq. 18, written with
        // expm1 and ln(1 − ξ) exact on both halves so small ξ and γ large keep their digits).
        let l = if xi < 0.5 {
            -(-xi).ln_1p()
        } else {
            -(1.0 - xi).ln()
        };
        let x = l / (self.gamma - 1.0);
        if x > 1.0 {
            // r² = c eˣ(1 − e^{−x}) in logarithms: eˣ overflows from x = 710 (γ near 1),
            // while r stays finite up to x ≈ 1418 (a normal at m.z ~ 1e-300).
            return (0.5 * (self.c.ln() + x + (-(-x).exp()).ln_1p())).exp();
        }
        (self.c * x.exp_m1()).sqrt()
    }
    fn slope_tail_index(&self) -> Option<f64> {
        // Q = (1 + r²/c)^{1−γ} = (c/r²)^{γ−1} (1 + O(γ c/r²)).
        Some(2.0 * (self.gamma - 1.0))
    }
}

#[cfg(test)]
mod fixed_rule {
    use super::*;

    /// Λ for γ > 21 by the fixed rule against the adaptive rule (the route it replaced).
    #[test]
    fn smith_by_the_fixed_rule_against_the_adaptive_rule() {
        for g in [21.5, 25.0, 40.0, 70.0, 100.0] {
            for alpha in [1e-3, 0.5, 30.0] {
                let n = StudentT::new(alpha, g).unwrap();
                for k in 0..200 {
                    let u = (k as f64 + 0.5) / 200.0;
                    let mu = crate::math::smith::cot_theta(u);
                    let zeta = mu / n.c.sqrt();
                    if 1.0 / (1.0 + zeta * zeta) <= SERIES_Z0_MAX {
                        continue; // (the series' side)
                    }
                    let want = crate::math::quad::integrate_to_inf(
                        |d| d * n.p2(mu + d),
                        0.0,
                        n.alpha,
                        1e-14,
                    )
                    .value
                        / mu;
                    let got = n.lambda_pos(u);
                    if want > 1e-290 {
                        assert!(
                            (got / want - 1.0).abs() < 1e-13,
                            "γ={g} α={alpha} u={u}: {got} vs {want}"
                        );
                    }
                }
            }
        }
    }
}
