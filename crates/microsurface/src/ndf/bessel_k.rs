//! The Bessel-K NDF (the BesselK_NDF page of d'Eon's *A Hitchhiker's Guide to Multiple
//! Scattering*): a Gamma(a) superposition of Beckmann NDFs, β = α√m, m ~ Gamma(a, 1)
//! (equivalently β = αχ/√2, χ ~ Chi(2a)); the marginal slopes are symmetric variance-gamma.
//!
//! With x = r/α:
//!
//! P22(r) = (2/(π α² Γ(a))) x^{a−1} K_{a−1}(2x),  D(u) = P22(tan θ)/u⁴,
//! f(x) = 2 x^{a−1} K_{a−1}(2x)/(π Γ(a)),
//! P2(p) = 2 (|p|/α)^{a−½} K_{a−½}(2|p|/α)/(√π α Γ(a)),  Q(T) = 2 (T/α)^a K_a(2T/α)/Γ(a),
//! Λ(u) = 2^{½−a}/(√π Γ(a)) [z^{a−½} K_{a+½}(z) − Ki_{a−½}(z)],  z = 2 cot θ/α,
//! σ(0) = α Γ(a + ½)/(2√π Γ(a)),  D(1) = 1/(π α² (a − 1)) for a > 1, +∞ for a ≤ 1.
//!
//! a = 1 is the K0 NDF ([`crate::K0`]), a = 3/2 the Exponential NDF ([`crate::Exponential`],
//! same α); a → ∞ with α√a fixed is Beckmann. The page gives D, P22, the normalisation and the
//! superpositions; P2, Q, Λ and σ(0) are derived (docs/derivations.md F.5).
//!
//! **Computation.** No Rust crate has K_ν of real order or the integrated Bessel function Ki_ν.
//! P22, P2 and Q are the closed forms above with K_ν from `special::ln_bessel_k`
//! (the trapezoidal rule on ∫ e^{−z cosh t} cosh νt dt, exponentially convergent). Λ, and 1 − Q
//! where Q > ½ (where 1 − Q would cancel), come from the superposition, as the Gamma(a)
//! average of a Beckmann closed form (σ, and so Λ(u) = σ(−u)/u at fixed u, are linear in D):
//! Λ = E[Λ_Beckmann(cot θ/(α√m))], 1 − Q = E[1 − e^{−x²/m}]: one tanh-sinh quadrature over m
//! of a positive integrand, with the quadrature's scale at the integrand's peak m* (the root
//! of (a − 1 − k)/m − 1 + x²/m² = 0 for an integrand ~ m^{a−1−k} e^{−m − x²/m}; in t = m^a
//! for a < 1, with a − 1 dropped). Λ for a ≥ 0.35 by fixed rules of step 2⁻⁵ split at the
//! peak (no adaptive refinement; within 3.5e-14 of the adaptive rule), else and for 1 − Q the
//! adaptive rule (relative tolerance 1e-14); the identity checks compare P22, P2 and Q with
//! the same averages (`microsurface verify`).
//!
//! **Parameters.** α ∈ [1e-6, 1e6], a ∈ [0.1, 100]. Below a = 0.1 the Gamma weight puts
//! 1 − 10^{−30a} of its mass below m = 1e-30 (a spike that no longer tests anything a
//! quadrature of fixed tolerance resolves); above 100 the NDF is Beckmann(α√a) to 1e-2.
//! Accuracy (tests/reference.rs against mpmath): ≤ 1e-12 relative for every quantity.

use crate::error::{check_alpha, check_shape, ParamError};
use crate::math::special::{
    exp_over, gamma_ratio_half, ln_bessel_k, ln_gamma, ln_xnu_bessel_k_small,
};
use crate::ndf::slopes::RadialSlopes;
use crate::ndf::{Ndf, ShapeInvariant};
use std::f64::consts::LN_2;
use std::f64::consts::PI;

use crate::math::special::SQRT_PI;
/// Supported range of the shape a (see the module docs).
pub const BESSEL_K_A_MIN: f64 = 0.1;
/// See [`BESSEL_K_A_MIN`].
pub const BESSEL_K_A_MAX: f64 = 100.0;
/// From this a on, Λ's Gamma(a) average is a fixed rule split at the integrand's peak
/// (`quad::to_inf_fixed_peaked`; within 1.1e-14 of the adaptive rule at a = 0.35 … 100, x
/// from 1e-5 to 100); below, in t = m^a the peak narrows to a width the fixed step does not
/// resolve (0.5 off at a = 0.1, x = 3.6) and the adaptive rule stays.
const FIXED_RULE_A_MIN: f64 = 0.35;
/// Below x = r/α = 1e-150 P22 takes the small-argument series of K_ν (its omitted terms are
/// O(x) relative there), where x² underflows and the trapezoidal K_ν would need its window
/// to reach t ~ ln(1/x).
const SMALL_X: f64 = 1e-150;
/// Relative tolerance of the superposition quadratures.
const TOL: f64 = 1e-14;

/// The Bessel-K NDF with roughness α and shape a.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BesselK {
    alpha: f64,
    a: f64,
    /// ln Γ(a).
    ln_gamma_a: f64,
}

impl BesselK {
    /// Bessel-K NDF with roughness α ∈ [1e-6, 1e6] and shape a ∈ [0.1, 100].
    pub fn new(alpha: f64, a: f64) -> Result<Self, ParamError> {
        let alpha = check_alpha(alpha)?;
        let a = check_shape(
            a,
            BESSEL_K_A_MIN,
            false,
            BESSEL_K_A_MAX,
            "bessel_k a",
            "[0.1, 100]",
        )?;
        Ok(Self::raw(alpha, a))
    }

    /// Without the range checks (the α = 1 member of a validated material).
    pub(crate) fn raw(alpha: f64, a: f64) -> Self {
        BesselK {
            alpha,
            a,
            ln_gamma_a: ln_gamma(a),
        }
    }

    /// The shape a.
    pub fn a(&self) -> f64 {
        self.a
    }

    /// E[g(m)] over m ~ Gamma(a, 1), for an integrand that behaves like m^{−k} e^{−x2/m}
    /// (which places the quadrature's scale); `g` gets m and ln m.
    fn mix(&self, k: f64, x2: f64, g: impl Fn(f64, f64) -> f64) -> f64 {
        self.mix_by(k, x2, g, |f, scale| {
            crate::math::quad::integrate_to_inf(f, 0.0, scale, TOL).value
        })
    }

    /// [`BesselK::mix`] by `rule(integrand, scale)` over the half line.
    fn mix_by(
        &self,
        k: f64,
        x2: f64,
        g: impl Fn(f64, f64) -> f64,
        rule: impl Fn(&dyn Fn(f64) -> f64, f64) -> f64,
    ) -> f64 {
        let a = self.a;
        // The integrand's peak in the variable integrated: m for a ≥ 1 (weight m^{a−1}), and
        // for a < 1 in t = m^a, whose weight dt/Γ(a + 1) has no power of m left.
        let base = if a < 1.0 { -k } else { a - 1.0 - k };
        // m* = (base + √(base² + 4x²))/2, written without cancellation for base < 0.
        let root = (base * base + 4.0 * x2).sqrt();
        let peak = if base >= 0.0 {
            0.5 * (base + root)
        } else {
            2.0 * x2 / (root - base)
        };
        let scale = if peak > 1e-300 && peak.is_finite() {
            peak
        } else {
            1.0
        };
        let ln_g = self.ln_gamma_a;
        if a < 1.0 {
            // m = t^{1/a}: m^{a−1} dm/Γ(a) = dt/Γ(a + 1) removes the weight's pole at m = 0
            // (at a = 0.1 and x = 0.01 the quadrature in m missed 7e-5 of F).
            let ln_g1 = ln_g + a.ln();
            return rule(
                &|t| {
                    if t.is_nan() || t <= 0.0 || !t.is_finite() {
                        return 0.0;
                    }
                    let lm = t.ln() / a;
                    let m = lm.exp();
                    let w = (-m - ln_g1).exp();
                    if w == 0.0 || m == 0.0 {
                        return 0.0;
                    }
                    w * g(m, lm)
                },
                scale.powf(a),
            );
        }
        rule(
            &|m| {
                if m.is_nan() || m <= 0.0 || !m.is_finite() {
                    return 0.0;
                }
                let lm = m.ln();
                let w = ((a - 1.0) * lm - m - ln_g).exp();
                if w == 0.0 {
                    return 0.0;
                }
                w * g(m, lm)
            },
            scale,
        )
    }

    /// P22 at x = r/α ≤ [`SMALL_X`] from ln x, by the small-argument series of K_{a−1}
    /// ([`ln_xnu_bessel_k_small`]): finite wherever the true value is (x^{2a−2} overflows
    /// only for a < 1 and x below ~10^{−308/(2−2a)}).
    fn p22_small(&self, ln_x: f64) -> f64 {
        self.ln_p22_small(ln_x).exp()
    }

    /// ln P22 at x = r/α ≤ [`SMALL_X`], from ln x.
    fn ln_p22_small(&self, ln_x: f64) -> f64 {
        let ln = ln_xnu_bessel_k_small(self.a - 1.0, ln_x) + LN_2 - self.ln_gamma_a;
        ln - (PI * self.alpha * self.alpha).ln()
    }

    /// P22 at x² = r²/α² (for x² > 0): (2/(π α² Γ(a))) x^{a−1} K_{a−1}(2x).
    fn p22_x2(&self, x2: f64) -> f64 {
        self.p22_x2_over(x2, 1.0, || 0.0)
    }

    /// P22/d at x² = r²/α², with ln d from `ln_d` (d = u⁴ for D: P22 turns subnormal before D
    /// does, and u⁴ may underflow).
    fn p22_x2_over(&self, x2: f64, d: f64, ln_d: impl FnOnce() -> f64) -> f64 {
        if x2.is_nan() {
            return x2;
        }
        if x2 == 0.0 {
            return self.p22_zero() / d;
        }
        if x2 == f64::INFINITY {
            return 0.0;
        }
        let x = x2.sqrt();
        let ln =
            (self.a - 1.0) * x.ln() + ln_bessel_k(self.a - 1.0, 2.0 * x) + LN_2 - self.ln_gamma_a;
        exp_over(ln - (PI * self.alpha * self.alpha).ln(), d, ln_d)
    }

    /// P22(0) = D(1) = E[1/m]/(π α²) = 1/(π α² (a − 1)) for a > 1, +∞ otherwise.
    fn p22_zero(&self) -> f64 {
        if self.a > 1.0 {
            1.0 / (PI * self.alpha * self.alpha * (self.a - 1.0))
        } else {
            f64::INFINITY
        }
    }
}

impl Ndf for BesselK {
    fn name(&self) -> &'static str {
        "bessel_k"
    }

    fn alpha(&self) -> f64 {
        self.alpha
    }

    fn d_pos(&self, u: f64) -> f64 {
        let s2 = crate::math::special::dd::Dd::one_minus_sq(u).hi;
        let x2 = s2 / (u * u * self.alpha * self.alpha);
        self.p22_x2_over(x2, (u * u) * (u * u), || 4.0 * u.ln())
    }

    fn p22(&self, p: f64, q: f64) -> f64 {
        let r = p.hypot(q);
        if r > 0.0 && r < SMALL_X * self.alpha {
            // (x² would underflow, and x itself may: ln x from r and α.)
            return self.p22_small(r.ln() - self.alpha.ln());
        }
        let x = r / self.alpha;
        self.p22_x2(x * x)
    }

    fn p2(&self, p: f64) -> f64 {
        if p.is_nan() {
            return p;
        }
        let x = p.abs() / self.alpha;
        let x2 = x * x;
        if x2 == f64::INFINITY {
            return 0.0;
        }
        if p != 0.0 && x < SMALL_X {
            // (As P22: 2 x^{a−½} K_{a−½}(2x) by its small-argument series.)
            let ln = ln_xnu_bessel_k_small(self.a - 0.5, p.abs().ln() - self.alpha.ln()) + LN_2
                - self.ln_gamma_a;
            return (ln - (SQRT_PI * self.alpha).ln()).exp();
        }
        if x2 == 0.0 {
            // E[m^{−½}]/(√π α) = Γ(a − ½)/(Γ(a) √π α) for a > ½.
            if self.a <= 0.5 {
                return f64::INFINITY;
            }
            return 1.0 / (gamma_ratio_half(self.a - 0.5) * SQRT_PI * self.alpha);
        }
        // 2 x^{a−½} K_{a−½}(2x)/(√π α Γ(a)).
        let ln =
            (self.a - 0.5) * x.ln() + ln_bessel_k(self.a - 0.5, 2.0 * x) + LN_2 - self.ln_gamma_a;
        (ln - (SQRT_PI * self.alpha).ln()).exp()
    }

    fn lambda_pos(&self, u: f64) -> f64 {
        self.lambda_x(crate::math::smith::cot_theta(u) / self.alpha)
    }

    fn sigma_zero(&self) -> f64 {
        self.alpha * gamma_ratio_half(self.a) / (2.0 * SQRT_PI)
    }
}

impl BesselK {
    /// Λ at x = cot θ/α: the Gamma(a) average of Beckmann's Λ.
    pub(crate) fn lambda_x(&self, x: f64) -> f64 {
        if x == 0.0 {
            return f64::INFINITY;
        }
        // Λ_B(y) ~ 1/(2√π y) ∝ √m for small y, ~ e^{−y²}/(4√π y³) ∝ m^{3/2} e^{−x²/m} for large.
        let k = if x < 1.0 { -0.5 } else { -1.5 };
        let g = |m: f64, _| crate::ndf::beckmann::lambda_at(x / m.sqrt());
        if self.a < FIXED_RULE_A_MIN {
            return self.mix(k, x * x, g);
        }
        self.mix_by(k, x * x, g, |f, peak| {
            crate::math::quad::to_inf_fixed_peaked(f, peak, crate::math::smith::SMITH_LEVEL)
        })
    }
}

impl ShapeInvariant for BesselK {
    fn f(&self, x: f64) -> f64 {
        // (P22, not p22_x2: its small-argument branch where x² underflows.)
        BesselK::raw(1.0, self.a).p22(x, 0.0)
    }
}

impl RadialSlopes for BesselK {
    fn slope_cdf(&self, r: f64) -> f64 {
        let x = r / self.alpha;
        let x2 = x * x;
        if x2.is_nan() {
            return x2;
        }
        if x2 == 0.0 {
            return 0.0;
        }
        if x2 == f64::INFINITY {
            return 1.0;
        }
        // 1 − Q where Q ≤ ½ (no cancellation); below, E[1 − e^{−x²/m}] over the mixture
        // (positive terms: 1 − Q would cancel as x → 0).
        let q = self.q_closed(x);
        if q <= 0.5 {
            return 1.0 - q;
        }
        self.cdf_mix(x2)
    }
    fn slope_ccdf(&self, r: f64) -> f64 {
        let x = r / self.alpha;
        let x2 = x * x;
        if x2.is_nan() {
            return x2;
        }
        if x2 == 0.0 {
            return 1.0;
        }
        if x2 == f64::INFINITY {
            return 0.0;
        }
        // Above ½, 1 − F by the mixture: Q's closed form is a sum of logarithms of size
        // ~a |ln x| that cancel to ~0 as x → 0 (2e-13 absolute at a = 20, x = 1e-100).
        let q = self.q_closed(x);
        if q <= 0.5 {
            return q;
        }
        1.0 - self.cdf_mix(x2)
    }

    fn slope_pdf(&self, r: f64) -> f64 {
        if r == 0.0 && self.a <= 0.5 {
            // 2π r P22 ~ 2π r (2/(π α² Γ(a))) Γ(1 − a)/2 x^{2a−2}: +∞ below a = ½, and
            // 2/α at a = ½ (P22 = e^{−2x}/(π α r)).
            return if self.a < 0.5 {
                f64::INFINITY
            } else {
                2.0 / self.alpha
            };
        }
        if r == 0.0 || r == f64::INFINITY {
            return 0.0;
        }
        if r < SMALL_X * self.alpha {
            // In logarithms: P22 ~ r^{2a−2} overflows (a < 1) where r P22 does not.
            let ln_r = r.ln();
            return ((2.0 * PI).ln() + ln_r + self.ln_p22_small(ln_r - self.alpha.ln())).exp();
        }
        2.0 * PI * r * self.p22(r, 0.0)
    }
}

impl BesselK {
    /// Q = 2 x^a K_a(2x)/Γ(a) in closed form (x = r/α > 0 finite), relative error ~a|ln x|ε.
    fn q_closed(&self, x: f64) -> f64 {
        let ln = self.a * x.ln() + ln_bessel_k(self.a, 2.0 * x) + LN_2 - self.ln_gamma_a;
        ln.exp().min(1.0)
    }

    /// F = E[1 − e^{−x²/m}] over the Gamma(a) mixture: positive terms, full relative accuracy
    /// as x → 0.
    fn cdf_mix(&self, x2: f64) -> f64 {
        self.mix(0.0, x2, |m, _| -(-x2 / m).exp_m1()).min(1.0)
    }
}

#[cfg(test)]
mod fixed_rule {
    use super::*;

    /// Λ by the peak-split fixed rule against the adaptive rule (the route it replaced), a
    /// from 0.35 to 100 (below, Λ keeps the adaptive rule), x from 1e-10 to 100: within
    /// 3.5e-14 measured.
    #[test]
    fn against_the_adaptive_rule() {
        for a in [0.35, 0.5, 0.8, 1.0, 1.5, 2.0, 3.0, 6.0, 12.0, 30.0, 100.0] {
            let n = BesselK::raw(1.0, a);
            let mut worst = (0.0f64, 0.0);
            for k in 0..300 {
                let x = 10f64.powf(-10.0 + 12.0 * k as f64 / 300.0);
                let kk = if x < 1.0 { -0.5 } else { -1.5 };
                let want = n.mix(kk, x * x, |m, _| {
                    crate::ndf::beckmann::lambda_at(x / m.sqrt())
                });
                let got = n.lambda_x(x);
                if want > 1e-290 {
                    let e = (got / want - 1.0).abs();
                    if e > worst.0 {
                        worst = (e, x);
                    }
                }
            }
            assert!(worst.0 < 1e-13, "a = {a}: {:e} at x = {}", worst.0, worst.1);
        }
    }
}
