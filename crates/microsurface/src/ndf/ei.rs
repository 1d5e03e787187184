//! The Ei NDF (the Ei_NDF page of d'Eon's *A Hitchhiker's Guide to Multiple Scattering*): a
//! uniform superposition of Beckmann NDFs over roughness² ∈ (0, α²] (β = α√m, m ~ U(0, 1)).
//!
//! With y = r²/α²:
//!
//! D(u) = E₁(tan²θ/α²)/(π α² u⁴),  P22(r) = E₁(y)/(π α²),  f(x) = E₁(x²)/π,
//! P2(p) = E_{3/2}(p²/α²)/(√π α) = (2/(√π α))(e^{−y} − √(π y) erfc √y)  (y = p²/α²; P2(0) = 2/(√π α)),
//! Λ(u) = e^{−x²}(1 + x²)/(3√π x) − (3 + 2x²) erfc(x)/6,  x = cot θ/α,
//! σ(0) = α/(3√π),  Q(T) = E₂(T²/α²) = e^{−y} − y E₁(y).
//!
//! D(1) = P22(0) = +∞ (logarithmic). These are the page's `Ei`Λ` and `Ei`σ` (which the
//! Exponential NDF page uses, with α scaled by 1.7, as an approximation: [`crate::ndf::exponential::approx`]);
//! P2 and Q are derived (docs/derivations.md F.2). Valid for α ∈ [1e-6, 1e6].
//!
//! # Numerics
//! * E₁ through `special::e1_with` (the continued fraction above 1, with e^{−y} in
//!   double-double); e^{−y} − √(πy) erfc √y = e^{−y} k/(t + k), t = √y ≥ 2, by the erfc
//!   continued fraction (`special::erfc_ratio_tail`).
//! * Λ's closed form cancels to relative O(x⁻⁴); it is used for x ≤ 2 (≤ 1.5 digits lost), and
//!   above the superposition Λ = ∫₀¹ Λ_Beckmann(x/√m) dm (tanh-sinh, positive integrand).
//! * Accuracy (tests/reference.rs against mpmath): closed forms ≤ 1e-13, Λ for x > 2 ≤ 1e-12.

use crate::error::{check_alpha, ParamError};
use crate::math::special::{dd::Dd, e1, e1_cf_tail, e1_with, erfc, erfc_ratio_tail};
use crate::ndf::slopes::RadialSlopes;
use crate::ndf::{Ndf, ShapeInvariant};
use std::f64::consts::PI;

use crate::math::special::SQRT_PI;
/// e^{−y} underflows beyond this.
const EXP_UNDERFLOW: f64 = crate::ndf::beckmann::EXP_UNDERFLOW;
/// Largest x = cot θ/α where the closed form of Λ is used (its cancellation, ~x⁴/5, costs
/// at most 1.5 digits there).
pub(crate) const CLOSED_FORM_X_MAX: f64 = 2.0;

/// The Ei NDF with roughness α.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ei {
    alpha: f64,
}

impl Ei {
    /// Ei NDF with roughness α ∈ [1e-6, 1e6].
    pub fn new(alpha: f64) -> Result<Self, ParamError> {
        Ok(Ei {
            alpha: check_alpha(alpha)?,
        })
    }

    /// E₁(y)/(π α²) for y = r²/α² given in double-double.
    fn p22_y(&self, y: Dd) -> f64 {
        if y.hi.is_nan() {
            return f64::NAN;
        }
        let e = if y.hi > EXP_UNDERFLOW {
            0.0
        } else {
            y.exp_neg()
        };
        e1_with(y.hi, e) / (PI * self.alpha * self.alpha)
    }
}

/// Below y = (r/α)² = 1e-200 E₁(y) = −γ_E − ln y + O(y) (the O(y) is 1e-200 of it): taken
/// with ln y = 2(ln r − ln α), finite wherever r > 0 (y itself underflows below r ~ 1e-154 α).
pub(crate) const SMALL_Y: f64 = 1e-200;

/// E₁((r/α)²) for (r/α)² < [`SMALL_Y`], r > 0.
pub(crate) fn e1_small(r: f64, alpha: f64) -> f64 {
    -crate::math::special::EULER_GAMMA - 2.0 * (r.ln() - alpha.ln())
}

/// Λ of the Ei NDF at x = cot θ/α.
pub(crate) fn lambda_x(x: f64) -> f64 {
    if x <= CLOSED_FORM_X_MAX {
        let e = (-x * x).exp();
        return e * (1.0 + x * x) / (3.0 * SQRT_PI * x) - (3.0 + 2.0 * x * x) * erfc(x) / 6.0;
    }
    // Λ ~ e^{−x²}/(4√π x⁵): zero in f64 past x² ≈ 745.
    if x * x > EXP_UNDERFLOW {
        return 0.0;
    }
    // m = 1/(1 + v): Λ_B(z) = e^{−z²} r(z)/(2√π z) at z² = x²(1 + v) is e^{−x²} (once, in
    // double-double) times e^{−x² v}, a decay of scale 1/x² in v that a fixed rule resolves
    // at its level (math::smith::SMITH_LEVEL); r from the fast path's table (within 3.6e-15).
    let x2 = Dd::mul_f(x, x);
    let sum = crate::math::quad::to_inf_fixed(
        |v| {
            let z = x * (1.0 + v).sqrt();
            let e = (-(x2.hi * v)).exp();
            e * crate::fast::beckmann::erfc_ratio(z) / (z * (1.0 + v) * (1.0 + v))
        },
        0.0,
        1.0 / x2.hi,
        crate::math::smith::SMITH_LEVEL,
    );
    x2.exp_neg() * sum / (2.0 * SQRT_PI)
}

impl Ndf for Ei {
    fn name(&self) -> &'static str {
        "ei"
    }

    fn alpha(&self) -> f64 {
        self.alpha
    }

    fn d_pos(&self, u: f64) -> f64 {
        // y = (1 − u²)/(u² α²) in double-double.
        let y =
            Dd::one_minus_sq(u).div_dd(Dd::mul_f(u, u).mul_dd(Dd::mul_f(self.alpha, self.alpha)));
        let p = self.p22_y(y);
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
        let y = r2.div_dd(Dd::mul_f(self.alpha, self.alpha));
        if y.hi < SMALL_Y && (p != 0.0 || q != 0.0) {
            return e1_small(p.hypot(q), self.alpha) / (PI * self.alpha * self.alpha);
        }
        self.p22_y(y)
    }

    fn p2(&self, p: f64) -> f64 {
        if p.is_nan() {
            return p;
        }
        let t = p.abs() / self.alpha;
        let y = t * t;
        if y > EXP_UNDERFLOW {
            return 0.0;
        }
        let e = Dd::mul_f(t, t).exp_neg();
        // e^{−y} − √(πy) erfc √y.
        let bracket = if t < 2.0 {
            e - SQRT_PI * t * erfc(t)
        } else {
            let k = erfc_ratio_tail(t);
            e * k / (t + k)
        };
        2.0 * bracket / (SQRT_PI * self.alpha)
    }

    fn lambda_pos(&self, u: f64) -> f64 {
        lambda_x(crate::math::smith::cot_theta(u) / self.alpha)
    }

    fn sigma_zero(&self) -> f64 {
        self.alpha / (3.0 * SQRT_PI)
    }
}

impl ShapeInvariant for Ei {
    fn f(&self, x: f64) -> f64 {
        // P22 at α = 1 (its small-argument branch where x² underflows).
        Ei { alpha: 1.0 }.p22(x, 0.0)
    }
}

impl RadialSlopes for Ei {
    fn slope_cdf(&self, r: f64) -> f64 {
        let t = r / self.alpha;
        let y = t * t;
        if y == 0.0 {
            // (y ln y underflows with y: 0·E₁(0) would be NaN.)
            return 0.0;
        }
        if y < 1.0 {
            // 1 − E₂(y) = (1 − e^{−y}) + y E₁(y): two positive terms.
            -(-y).exp_m1() + y * e1(y)
        } else {
            1.0 - self.slope_ccdf(r)
        }
    }
    fn slope_ccdf(&self, r: f64) -> f64 {
        let t = r / self.alpha;
        let y = t * t;
        if y > EXP_UNDERFLOW {
            return 0.0;
        }
        if y == 0.0 {
            return 1.0;
        }
        if y < 1.0 {
            return (-y).exp() - y * e1(y);
        }
        // E₂(y) = e^{−y}(1 − y e^y E₁(y)) = e^{−y} (1 − T)/(y + 1 − T).
        let tail = e1_cf_tail(y);
        Dd::mul_f(t, t).exp_neg() * (1.0 - tail) / (y + 1.0 - tail)
    }
}
