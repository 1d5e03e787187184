//! The Exponential NDF (the Exponential NDF page): exponentially distributed slope magnitudes.
//!
//! D(u) = 2 exp(−2 tan θ/α)/(π α² u⁴),  P22(r) = 2 e^{−2r/α}/(π α²),  f(x) = 2 e^{−2x}/π
//! (derivations.md A.11),  P2(p) = (4|p|/(π α²)) K₁(2|p|/α) (derivations.md A.14),  σ(0) = α/π.
//! It is a Gamma(3/2) superposition of Beckmann NDFs with roughness α√m, and a Chi-3
//! superposition with roughness α m/√2 ([`crate::ndf::mixture`]).
//!
//! Λ and σ: the page says they are not known analytically; derivations.md A.14 derives
//! Λ = (2K₁(z) − Ki₁(z))/π, z = 2 cot θ/α (Ki₁ the Bickley function). We compute them exactly
//! by the Smith integral of `smith` (a fixed tanh-sinh rule with e^{−2a/α} factored out,
//! relative tolerance 1e-13; documented accuracy 1e-10, measured ≤ 1e-13 against mpmath).
//!
//! The page's approximations are kept, under their own names, in [`approx`].
//!
//! Valid for α ∈ [1e-6, 1e6].

use crate::error::{check_alpha, ParamError};
use crate::math::smith::smith_integral;
use crate::math::special::{dd::Dd, k1e};
use crate::ndf::{Ndf, ShapeInvariant};
use std::f64::consts::PI;

/// exp(−x) underflows to 0 beyond this.
const EXP_UNDERFLOW: f64 = crate::ndf::beckmann::EXP_UNDERFLOW;

/// The Exponential NDF with roughness α.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Exponential {
    alpha: f64,
}

impl Exponential {
    /// Exponential NDF with roughness α ∈ [1e-6, 1e6].
    pub fn new(alpha: f64) -> Result<Self, ParamError> {
        Ok(Exponential {
            alpha: check_alpha(alpha)?,
        })
    }

    /// 2 e^{−2r/α}/(π α²) for a double-double r.
    fn p22_r(&self, r: Dd) -> f64 {
        let x = r.div_dd(Dd::new(0.5 * self.alpha));
        if x.hi.is_nan() {
            return f64::NAN;
        }
        if x.hi > EXP_UNDERFLOW {
            return 0.0;
        }
        2.0 * x.exp_neg() / (PI * self.alpha * self.alpha)
    }

    /// I(a) of `smith`: e^{−2a/α} is factored out so the quadrature sees only the
    /// boundary layer e^{−2d/α}.
    fn smith(&self, a: Dd) -> f64 {
        let front = self.p22_r(a);
        if front == 0.0 {
            return 0.0;
        }
        let k = 2.0 / self.alpha;
        front * smith_integral(|d| (-k * d).exp(), a.hi, 0.5 * self.alpha)
    }

    /// cot θ in double-double.
    fn cot(u: f64) -> Dd {
        Dd::new(u).div_dd(Dd::one_minus_sq(u).sqrt())
    }
}

impl Ndf for Exponential {
    fn name(&self) -> &'static str {
        "exponential"
    }

    fn alpha(&self) -> f64 {
        self.alpha
    }

    fn d_pos(&self, u: f64) -> f64 {
        let tan = Dd::one_minus_sq(u).sqrt().div_dd(Dd::new(u));
        let p = self.p22_r(tan);
        if p == 0.0 {
            return 0.0;
        }
        let u2 = u * u;
        p / (u2 * u2)
    }

    fn p22(&self, p: f64, q: f64) -> f64 {
        let r2 = Dd::mul_f(p, p).add_dd(Dd::mul_f(q, q));
        if !r2.hi.is_finite() {
            return if r2.hi.is_nan() { f64::NAN } else { 0.0 };
        }
        self.p22_r(r2.sqrt())
    }

    fn p2(&self, p: f64) -> f64 {
        if p.is_nan() {
            return p;
        }
        // (2/(π α)) x K₁(x), x = 2|p|/α, with x K₁(x) = x K₁e(x) e^{−x} → 1 as x → 0.
        // Past the underflow of e^{−x} the value is 0; tested on |p| first, since the
        // double-double quotient of a |p| near f64::MAX is NaN (its splitting overflows).
        if p.abs() > 0.5 * self.alpha * EXP_UNDERFLOW {
            return 0.0;
        }
        let x = Dd::new(p.abs()).div_dd(Dd::new(0.5 * self.alpha));
        // x K₁(x) = 1 + (x²/2)(ln(x/2) + γ_E − ½) + O(x⁴ ln x): below x = 1e-20 the correction
        // is under 1e-38, and K₁e(x) ~ 1/x would overflow at subnormal x.
        let xk1 = if x.hi < 1e-20 {
            1.0
        } else {
            x.hi * k1e(x.hi) * x.exp_neg()
        };
        2.0 * xk1 / (PI * self.alpha)
    }

    fn lambda_pos(&self, u: f64) -> f64 {
        let a = Self::cot(u);
        2.0 * self.smith(a) / a.hi
    }

    fn sigma_neg(&self, u: f64) -> f64 {
        // σ(−u) = 2 sin θ I(cot θ).
        let sin = Dd::one_minus_sq(u).sqrt();
        2.0 * sin.hi * self.smith(Dd::new(u).div_dd(sin))
    }

    fn sigma_zero(&self) -> f64 {
        self.alpha / PI
    }
}

impl ShapeInvariant for Exponential {
    fn f(&self, x: f64) -> f64 {
        let e = 2.0 * x.abs();
        if e > EXP_UNDERFLOW {
            return 0.0;
        }
        2.0 * (-e).exp() / PI
    }
}

/// The page's approximations (the Exponential NDF page), kept as named approximations.
///
/// | approximation | max. abs. error vs the exact Exponential NDF (measured, tests/approximations.rs) |
/// |---|---|
/// | [`approx::ei_g1`]`(u, 1.7α)` | G1: 3.06e-3, at cot θ/α ≈ 1.20 (independent of α) |
/// | [`approx::g1_rational`]`(u, α)` | G1: 3.07e-3; it fits `ei_g1(u, 1.7α)` (to 3.4e-5), not the exact G1, and jumps from 0.99939 to 1 at its x = 1.5 switch |
/// | [`approx::ei_sigma`]`(u, 1.7α)` | σ over u ∈ [−1, 1]: 2.1e-4 (α = 0.05), 1.7e-3 (α = 0.5), 2.5e-3 (α = 1) |
///
/// `ei_lambda` and `ei_sigma` are the *exact* Λ and σ of a different NDF,
/// P22 = E₁(r²/α²)/(π α²) (a uniform mixture of Beckmann roughness² over [0, α²], derivations.md B.7);
/// with α scaled by 1.7 they approximate the Exponential NDF to 3e-3 in σ.
pub mod approx {
    use crate::math::special::{erfc, erfc_ratio_tail};

    /// √π
    use crate::math::special::SQRT_PI;

    /// The page's `Ei`Λ[u, α]` for 0 < u < 1 (pass 1.7 α to approximate the Exponential NDF):
    /// Λ = [2 e^{−a²}(1 + a²) − √π a (3 + 2a²) erfc a]/(6√π a), a = cot θ/α.
    pub fn ei_lambda(u: f64, alpha: f64) -> f64 {
        if u.is_nan() || alpha.is_nan() {
            return f64::NAN;
        }
        if u >= 1.0 {
            return 0.0;
        }
        if u <= 0.0 {
            return f64::INFINITY;
        }
        let a = crate::math::smith::cot_theta(u) / alpha;
        let e = (-a * a).exp();
        if a < 3.0 {
            (2.0 * e * (1.0 + a * a) - SQRT_PI * a * (3.0 + 2.0 * a * a) * erfc(a))
                / (6.0 * SQRT_PI * a)
        } else {
            // √π a e^{a²} erfc a = a/(a + k): numerator = e^{−a²}(2k(1+a²) − a)/(a + k).
            let k = erfc_ratio_tail(a);
            e * (2.0 * k * (1.0 + a * a) - a) / (a + k) / (6.0 * SQRT_PI * a)
        }
    }

    /// The page's `Ei`σ[u, α]` on [−1, 1]: u (1 + Λ) for u > 0, |u| Λ(|u|) for u < 0.
    pub fn ei_sigma(u: f64, alpha: f64) -> f64 {
        let u = u.clamp(-1.0, 1.0);
        if u == 0.0 {
            // lim u→0 of u·Ei`Λ: 2e^0/(6√π)·α = α/(3√π).
            return alpha / (3.0 * SQRT_PI);
        }
        let l = ei_lambda(u.abs(), alpha);
        if u > 0.0 {
            u * (1.0 + l)
        } else {
            -u * l
        }
    }

    /// The page's `Ei`G1[u, α] = 1/(1 + Ei`Λ[u, α])` (use α' = 1.7 α for the Exponential NDF).
    pub fn ei_g1(u: f64, alpha: f64) -> f64 {
        1.0 / (1.0 + ei_lambda(u.abs(), alpha))
    }

    /// The page's rational fit `Exponential`G1approx[u, α]` (coefficients as printed, the
    /// garbled powers read as x³ and x⁴, derivations.md A.13); x = cot θ/(1.7 α), G1 = 1 for x ≥ 1.5.
    pub fn g1_rational(u: f64, alpha: f64) -> f64 {
        let u = u.abs();
        if u >= 1.0 {
            return 1.0;
        }
        let x = crate::math::smith::cot_theta(u) / (1.7 * alpha);
        if x >= 1.5 {
            return 1.0;
        }
        let num = 4.15428848706139e-8 + 5.3171271839868055 * x + 1.5604787398328208 * x * x;
        let den = 1.0 + 2.9490717540313374 * x + 3.812617848664264 * x * x
            - 1.0148658798039354 * x * x * x
            + 0.18113230976734568 * x * x * x * x;
        num / den
    }
}
