//! The Erfc NDF (the Erfc_NDF page of d'Eon's *A Hitchhiker's Guide to Multiple Scattering*):
//! a uniform superposition of Beckmann NDFs over roughness β ∈ (0, α] (β = α m, m ~ U(0, 1)).
//!
//! D(u) = erfc(tan θ/α)/(2√π α tan θ u⁴),  P22(r) = erfc(r/α)/(2√π α r),  f(x) = erfc(x)/(2√π x),
//! P2(p) = E₁(p²/α²)/(2√π α),
//! Λ(u) = ¼ (−2 erfc x + (e^{−x²} + x² E₁(x²))/(√π x)),  x = cot θ/α,
//! σ(0) = α/(4√π),  Q(T) = e^{−y²} − √π y erfc y,  y = T/α.
//!
//! D(1) = P22(0) = P2(0) = +∞ (D like 1/tan θ, P2 logarithmic). Λ is the page's (In\[2692\]);
//! P2 and Q are derived (docs/derivations.md F.3). Valid for α ∈ [1e-6, 1e6].
//!
//! # Numerics
//! * Q = e^{−y²} k/(y + k) for y ≥ 2 by the erfc continued fraction (the difference cancels
//!   like 1/(2y²)); its complement 1 − Q = (1 − e^{−y²}) + √π y erfc y for y < 2.
//! * Λ's closed form cancels to relative O(x⁻⁴); used for x ≤ 2, above by the superposition
//!   Λ = ∫₀¹ Λ_Beckmann(x/m) dm (tanh-sinh, positive integrand).
//! * Accuracy (tests/reference.rs against mpmath): closed forms ≤ 1e-13, Λ for x > 2 ≤ 1e-12.

use crate::error::{check_alpha, ParamError};
use crate::math::special::{dd::Dd, e1_with, erfc, erfc_ratio_tail};
use crate::ndf::slopes::RadialSlopes;
use crate::ndf::{Ndf, ShapeInvariant};

use crate::math::special::SQRT_PI;
/// e^{−y} underflows beyond this.
const EXP_UNDERFLOW: f64 = crate::ndf::beckmann::EXP_UNDERFLOW;

/// The Erfc NDF with roughness α.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Erfc {
    alpha: f64,
}

impl Erfc {
    /// Erfc NDF with roughness α ∈ [1e-6, 1e6].
    pub fn new(alpha: f64) -> Result<Self, ParamError> {
        Ok(Erfc {
            alpha: check_alpha(alpha)?,
        })
    }

    /// erfc(r/α)/(2√π α r) for the slope magnitude r.
    fn p22_r(&self, r: f64) -> f64 {
        if r.is_nan() {
            return r;
        }
        if r == 0.0 {
            return f64::INFINITY;
        }
        let x = r / self.alpha;
        // erfc(x) = 0 in f64 past x ≈ 27.3.
        if x > 27.5 {
            return 0.0;
        }
        erfc(x) / (2.0 * SQRT_PI * self.alpha) / r
    }
}

/// Λ of the Erfc NDF at x = cot θ/α.
pub(crate) fn lambda_x(x: f64) -> f64 {
    if x <= crate::ndf::ei::CLOSED_FORM_X_MAX {
        let y = x * x;
        let e = (-y).exp();
        return 0.25 * (-2.0 * erfc(x) + (e + y * e1_with(y, e)) / (SQRT_PI * x));
    }
    // Λ ~ e^{−x²}/(8√π x⁵): zero in f64 past x² ≈ 745.
    if x * x > EXP_UNDERFLOW {
        return 0.0;
    }
    // m = 1/(1 + v): Λ_B(z) = e^{−z²} r(z)/(2√π z) at z = x(1 + v) is e^{−x²} (once, in
    // double-double) times e^{−x²(2v + v²)}, a decay of scale 1/(2x²) in v that a fixed rule
    // resolves at its level (math::smith::SMITH_LEVEL); r from the fast path's table (within
    // 3.6e-15).
    let x2 = Dd::mul_f(x, x);
    let sum = crate::math::quad::to_inf_fixed(
        |v| {
            let w = 1.0 + v;
            let z = x * w;
            let e = (-(x2.hi * (v * (2.0 + v)))).exp();
            e * crate::fast::beckmann::erfc_ratio(z) / (z * w * w)
        },
        0.0,
        0.5 / x2.hi,
        crate::math::smith::SMITH_LEVEL,
    );
    x2.exp_neg() * sum / (2.0 * SQRT_PI)
}

impl Ndf for Erfc {
    fn name(&self) -> &'static str {
        "erfc"
    }

    fn alpha(&self) -> f64 {
        self.alpha
    }

    fn d_pos(&self, u: f64) -> f64 {
        let tan = Dd::one_minus_sq(u).sqrt().hi / u;
        let p = self.p22_r(tan);
        if p == 0.0 || p == f64::INFINITY {
            return p;
        }
        let u2 = u * u;
        p / (u2 * u2)
    }

    fn p22(&self, p: f64, q: f64) -> f64 {
        self.p22_r(p.hypot(q))
    }

    fn p2(&self, p: f64) -> f64 {
        if p.is_nan() {
            return p;
        }
        let t = p.abs() / self.alpha;
        let y = t * t;
        if y < crate::ndf::ei::SMALL_Y && p != 0.0 {
            return crate::ndf::ei::e1_small(p.abs(), self.alpha) / (2.0 * SQRT_PI * self.alpha);
        }
        let e = if y > EXP_UNDERFLOW {
            0.0
        } else {
            Dd::mul_f(t, t).exp_neg()
        };
        e1_with(y, e) / (2.0 * SQRT_PI * self.alpha)
    }

    fn lambda_pos(&self, u: f64) -> f64 {
        lambda_x(crate::math::smith::cot_theta(u) / self.alpha)
    }

    fn sigma_zero(&self) -> f64 {
        self.alpha / (4.0 * SQRT_PI)
    }
}

impl ShapeInvariant for Erfc {
    fn f(&self, x: f64) -> f64 {
        let x = x.abs();
        if x == 0.0 {
            return f64::INFINITY;
        }
        if x > 27.5 {
            return 0.0;
        }
        erfc(x) / (2.0 * SQRT_PI * x)
    }
}

impl RadialSlopes for Erfc {
    fn slope_cdf(&self, r: f64) -> f64 {
        let y = r / self.alpha;
        if y < 2.0 {
            -(-y * y).exp_m1() + SQRT_PI * y * erfc(y)
        } else {
            1.0 - self.slope_ccdf(r)
        }
    }
    fn slope_ccdf(&self, r: f64) -> f64 {
        let y = r / self.alpha;
        if y * y > EXP_UNDERFLOW {
            return 0.0;
        }
        let e = Dd::mul_f(y, y).exp_neg();
        if y < 2.0 {
            e - SQRT_PI * y * erfc(y)
        } else {
            let k = erfc_ratio_tail(y);
            e * k / (y + k)
        }
    }
}

#[cfg(test)]
mod fixed_rule {
    /// The fast path's table of r(a) = 1 − √π a erfcx(a) that the mixtures' Beckmann Λ and
    /// these tails use, against the continued fraction k/(a + k) on [2, 32).
    #[test]
    fn erfc_ratio_table_within_5e_15() {
        let mut worst = 0.0f64;
        for k in 0..30_000 {
            let a = 2.0 + 30.0 * k as f64 / 30_000.0;
            let kf = crate::math::special::erfc_ratio_tail(a);
            let want = kf / (a + kf);
            let got = crate::fast::beckmann::erfc_ratio(a);
            worst = worst.max((got / want - 1.0).abs());
        }
        assert!(worst <= 5e-15, "{worst:e}");
    }

    /// Λ's tails (x = cot θ/α > 2) of Erfc and Ei by the fixed rule against the adaptive rule
    /// over the mixing variable (the route it replaced): within 5e-14 measured, allowed 1e-13
    /// or 4ε times the condition number 2x² of e^{−x²}.
    #[test]
    fn against_the_adaptive_rule() {
        let b = crate::ndf::beckmann::lambda_at;
        let (mut we, mut wf) = ((0.0f64, 0.0), (0.0f64, 0.0));
        for k in 0..2000 {
            let x = 2.0 + 25.3 * k as f64 / 2000.0;
            let ei = crate::math::quad::integrate(|m| b(x / m.sqrt()), 0.0, 1.0, 1e-14).value;
            let er = crate::math::quad::integrate(|m| b(x / m), 0.0, 1.0, 1e-14).value;
            if ei > 1e-300 {
                let e = (crate::ndf::ei::lambda_x(x) / ei - 1.0).abs();
                if e > we.0 {
                    we = (e, x);
                }
            }
            if er > 1e-300 {
                let e = (super::lambda_x(x) / er - 1.0).abs();
                if e > wf.0 {
                    wf = (e, x);
                }
            }
        }
        for (e, x) in [we, wf] {
            assert!(
                e < (1e-13f64).max(8.0 * f64::EPSILON * x * x),
                "{e:e} at x = {x}"
            );
        }
    }
}
