//! The generalised exponential NDF (the GenExponential_NDF page of d'Eon's *A Hitchhiker's
//! Guide to Multiple Scattering*): slope magnitudes with a stretched-exponential profile.
//!
//! With x = r/α and N = π α² Γ(1 + 2/γ):
//!
//! D(u) = exp(−(tan θ/α)^γ)/(N u⁴),  P22(r) = e^{−x^γ}/N,  f(x) = e^{−x^γ}/(π Γ(1 + 2/γ)),
//! Q(T) = Γ(2/γ, (T/α)^γ)/Γ(2/γ) (regularised upper incomplete gamma),
//! P2(0) = 2Γ(1 + 1/γ)/(π α Γ(1 + 2/γ)),  σ(0) = α Γ(3/γ)/(π Γ(2/γ)).
//!
//! γ = 2 is Beckmann(α); γ = 1 is the Exponential NDF with roughness 2α (the page's In\[2420\]:
//! the roughness differs by a factor 2). For γ > 2 it is not a Beckmann superposition. Q,
//! P2(0) and σ(0) are derived (docs/derivations.md F.6); the page gives D, P22, the
//! normalisation, and P2 for γ = 1, 2 and 4.
//!
//! **Numerical quantities.** P2(p) = 2 ∫₀^∞ P22(√(p² + q²)) dq by tanh-sinh (relative
//! tolerance 1e-14) with a breakpoint where the slope crosses α (for large γ, P22 is nearly a
//! flat disk of radius α with an edge of width α/γ). Λ = 2I(a)/a, a = cot θ/α, by the Smith
//! integral I(a) = ∫_a^∞ r² f(r) h(y) dr of the α = 1 profile (`math::smith`) with two fixed
//! tanh-sinh rules of step 2⁻⁵, no adaptive refinement: in r over the flat top [a, 1], and
//! in v = r^γ beyond, where r² f dr = r³ e^{−v} dv/(γ v) is a smooth Gamma-like density for
//! every γ (e^{−v₀} at its start factored out, restored in logarithms). Tested against the
//! CCDF route Λ(u) = (1/π) ∫₀^∞ Q(cot θ · cosh s) sinh s tanh s ds (docs/derivations.md F.6)
//! by the adaptive rule: within 1.3e-13, or 4ε times Λ's condition number γ a^γ in the
//! tail. σ(−u) = u Λ(u).
//!
//! **Parameters.** α ∈ [1e-6, 1e6], γ ∈ [0.1, 20]. Outside, the disk edge (γ > 20) or the
//! stretched tails out to α (ln 1/ε)^{1/γ} (γ < 0.1: beyond 1e28 α) are not what the
//! quadratures are tuned for. The exponent (r/α)^γ has condition number γ (r/α)^γ: inputs near
//! grazing lose digits in any precision. Accuracy (tests/reference.rs against mpmath): closed
//! forms ≤ 1e-13, P2 and Λ ≤ 1e-12.

use crate::error::{check_alpha, check_shape, ParamError};
use crate::math::special::{exp_over, gamma, inc_gamma};
use crate::ndf::slopes::RadialSlopes;
use crate::ndf::{Ndf, ShapeInvariant};
use std::f64::consts::PI;

/// Supported range of γ (see the module docs).
pub const GEN_EXPONENTIAL_GAMMA_MIN: f64 = 0.1;
/// See [`GEN_EXPONENTIAL_GAMMA_MIN`].
pub const GEN_EXPONENTIAL_GAMMA_MAX: f64 = 20.0;
/// e^{−t} underflows beyond this (and Q with it).
const EXP_UNDERFLOW: f64 = crate::ndf::beckmann::EXP_UNDERFLOW;
/// Relative tolerance of the quadratures.
const TOL: f64 = 1e-14;
/// The step 2^−5 of Λ's fixed rules (`smith_unit`; the accuracy in the module docs).
const LAMBDA_LEVEL: u32 = 5;

/// The generalised exponential NDF with roughness α and exponent γ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GenExponential {
    alpha: f64,
    gamma: f64,
    /// Γ(1 + 2/γ).
    g2: f64,
}

impl GenExponential {
    /// Generalised exponential NDF with roughness α ∈ [1e-6, 1e6] and γ ∈ [0.1, 20].
    pub fn new(alpha: f64, gamma: f64) -> Result<Self, ParamError> {
        let alpha = check_alpha(alpha)?;
        let gamma = check_shape(
            gamma,
            GEN_EXPONENTIAL_GAMMA_MIN,
            false,
            GEN_EXPONENTIAL_GAMMA_MAX,
            "gen_exponential gamma",
            "[0.1, 20]",
        )?;
        Ok(GenExponential {
            alpha,
            gamma,
            g2: crate::math::special::gamma(1.0 + 2.0 / gamma),
        })
    }

    /// The exponent γ.
    pub fn gamma(&self) -> f64 {
        self.gamma
    }

    /// e^{−x^γ}/N at x = r/α.
    fn p22_x(&self, x: f64) -> f64 {
        self.p22_x_over(x, 1.0, || 0.0)
    }

    /// e^{−x^γ}/(N d) at x = r/α, with ln d from `ln_d` (d = u⁴ for D, 1 for P22).
    fn p22_x_over(&self, x: f64, d: f64, ln_d: impl FnOnce() -> f64) -> f64 {
        if x.is_nan() {
            return x;
        }
        let e = x.powf(self.gamma);
        let norm = PI * self.alpha * self.alpha * self.g2;
        exp_over(-e, norm * d, || norm.ln() + ln_d())
    }

    /// The scale of the tail of the slope distribution: α (2/γ)^{1/γ}, where the radial
    /// distribution's x^γ ~ Gamma(2/γ) has its mean (α for γ ≥ 2).
    /// The Smith integral I(a) = ∫_a^∞ r² f(r) h(y) dr at α = 1 (`math::smith`; Λ = 2I(a)/a
    /// at a = cot θ/α) by two fixed tanh-sinh rules: r ∈ [a, 1] (the flat top of the profile,
    /// when a < 1) in r, and r ≥ max(a, 1) in v = r^γ, where r² f(r) dr becomes
    /// r³ e^{−v} dv/(γ v), a Gamma-like density of v with mean ≈ 3/γ, smooth for every γ
    /// (in r it is a cliff of width 1/γ at γ = 20 and spreads over 1e13 at γ = 0.1). e^{−v₀}
    /// at the start v₀ = max(a, 1)^γ is factored out and restored in logarithms, so the tail
    /// keeps its relative accuracy until Λ itself underflows.
    fn smith_unit(&self, a: f64) -> f64 {
        use crate::math::quad;
        use crate::math::smith::{kernel, kernel_times};
        let g = self.gamma;
        let norm = PI * self.g2;
        let inner = if a < 1.0 {
            quad::integrate_fixed_positive(
                |d| kernel_times(a, d, || (-(a + d).powf(g)).exp()),
                0.0,
                1.0 - a,
                LAMBDA_LEVEL,
            )
        } else {
            0.0
        };
        let r0 = a.max(1.0);
        let v0 = r0.powf(g);
        // r(v₀ + t) − a = r₀ (1 + t/v₀)^{1/γ} − a, exact in t near the start when r₀ = a.
        let outer = quad::to_inf_fixed(
            |t| {
                let grow = (t / v0).ln_1p() / g;
                let d = if r0 == a {
                    a * grow.exp_m1()
                } else {
                    (r0 - a) + r0 * grow.exp_m1()
                };
                let r = r0 * grow.exp();
                let k = kernel(a, d);
                if k == 0.0 || !r.is_finite() {
                    return 0.0;
                }
                k * r / (g * (v0 + t)) * (-t).exp()
            },
            0.0,
            (3.0 / g).max(1.0),
            LAMBDA_LEVEL,
        );
        if v0 < 700.0 {
            (inner + outer * (-v0).exp()) / norm
        } else {
            // (a ≥ 1 here, so inner = 0.)
            (outer.ln() - v0 - norm.ln()).exp()
        }
    }

    fn tail_scale(&self) -> f64 {
        self.alpha * (2.0 / self.gamma).powf(1.0 / self.gamma).max(1.0)
    }
}

impl Ndf for GenExponential {
    fn name(&self) -> &'static str {
        "gen_exponential"
    }

    fn alpha(&self) -> f64 {
        self.alpha
    }

    fn d_pos(&self, u: f64) -> f64 {
        let tan = crate::math::special::dd::Dd::one_minus_sq(u).sqrt().hi / u;
        // (u⁴ underflows below u ~ 1e-77, e^{−x^γ} turns subnormal before D does: in
        // logarithms there.)
        self.p22_x_over(tan / self.alpha, (u * u) * (u * u), || 4.0 * u.ln())
    }

    fn p22(&self, p: f64, q: f64) -> f64 {
        self.p22_x(p.hypot(q) / self.alpha)
    }

    fn p2(&self, p: f64) -> f64 {
        if p.is_nan() {
            return p;
        }
        let p = p.abs();
        if p == 0.0 {
            return 2.0 * gamma(1.0 + 1.0 / self.gamma) / (PI * self.alpha * self.g2);
        }
        if self.p22_x(p / self.alpha) == 0.0 {
            return 0.0;
        }
        let f = |q: f64| self.p22_x(p.hypot(q) / self.alpha);
        // Breakpoint where √(p² + q²) = α (the disk edge at large γ).
        let edge = if p < self.alpha {
            ((self.alpha - p) * (self.alpha + p)).sqrt()
        } else {
            0.0
        };
        let inner = if edge > 0.0 {
            crate::math::quad::integrate(f, 0.0, edge, TOL).value
        } else {
            0.0
        };
        let scale = self.tail_scale().max(p) / self.gamma.max(1.0);
        let outer = crate::math::quad::integrate_to_inf(|d| f(edge + d), 0.0, scale, TOL).value;
        2.0 * (inner + outer)
    }

    fn lambda_pos(&self, u: f64) -> f64 {
        let a = crate::math::smith::cot_theta(u) / self.alpha;
        if a == 0.0 {
            return f64::INFINITY;
        }
        2.0 * self.smith_unit(a) / a
    }

    fn sigma_zero(&self) -> f64 {
        self.alpha * gamma(3.0 / self.gamma) / (PI * gamma(2.0 / self.gamma))
    }
}

impl ShapeInvariant for GenExponential {
    fn f(&self, x: f64) -> f64 {
        let e = x.abs().powf(self.gamma);
        if e > EXP_UNDERFLOW {
            return 0.0;
        }
        (-e).exp() / (PI * self.g2)
    }
}

impl RadialSlopes for GenExponential {
    fn slope_cdf(&self, r: f64) -> f64 {
        if r == f64::INFINITY {
            return 1.0;
        }
        inc_gamma(2.0 / self.gamma, (r / self.alpha).powf(self.gamma)).0
    }
    fn slope_ccdf(&self, r: f64) -> f64 {
        if r == f64::INFINITY {
            return 0.0;
        }
        inc_gamma(2.0 / self.gamma, (r / self.alpha).powf(self.gamma)).1
    }
}

#[cfg(test)]
mod fixed_rule {
    use super::*;
    use crate::ndf::Ndf;

    fn old_lambda(n: &GenExponential, u: f64) -> f64 {
        let mu = crate::math::smith::cot_theta(u);
        let (ag, g) = (2.0 / n.gamma, n.gamma);
        let alpha = n.alpha;
        let c_max = (alpha / mu) * EXP_UNDERFLOW.powf(1.0 / g);
        if c_max <= 1.0 {
            return 0.0;
        }
        let s_max = c_max.acosh();
        let integrand = |s: f64| {
            let t = mu * s.cosh() / alpha;
            let q = inc_gamma(ag, t.powf(g)).1;
            if q == 0.0 {
                return 0.0;
            }
            q * s.sinh() * s.tanh()
        };
        let edge = if mu < alpha {
            (alpha / mu).acosh().min(s_max)
        } else {
            0.0
        };
        let mut sum = 0.0;
        if edge > 0.0 {
            sum += crate::math::quad::integrate(integrand, 0.0, edge, TOL).value;
        }
        if s_max > edge {
            sum += crate::math::quad::integrate(integrand, edge, s_max, TOL).value;
        }
        sum / PI
    }

    /// Λ by the Smith integral's fixed rules against the CCDF route by the adaptive rule (the
    /// route it replaced), γ from 0.1 to 20, cot θ/α from 1e-12 to 1e3: within 1.3e-13, or 4ε
    /// times Λ's condition number γ (cot θ/α)^γ in the tail.
    #[test]
    fn against_the_ccdf_route() {
        for g in [
            0.1, 0.2, 0.35, 0.5, 0.8, 1.0, 1.5, 2.0, 3.0, 5.0, 8.0, 12.0, 20.0,
        ] {
            let n = GenExponential::new(1.0, g).unwrap();
            let mut worst = (0.0f64, 0.0);
            for k in 1..400 {
                let a = 10f64.powf(-12.0 + 15.0 * k as f64 / 400.0);
                let u = a / (1.0 + a * a).sqrt();
                let want = old_lambda(&n, u);
                let got = n.lambda_pos(u);
                if want > 1e-290 {
                    let e = ((got - want) / want).abs();
                    if e > worst.0 {
                        worst = (e, a);
                    }
                    let tol = (2e-13f64).max(4.0 * f64::EPSILON * g * a.powf(g));
                    assert!(e < tol, "γ = {g}, a = {a}: {got} vs {want}");
                }
            }
        }
    }
}
