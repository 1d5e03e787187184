//! The K0 NDF (the K0_NDF page of d'Eon's *A Hitchhiker's Guide to Multiple Scattering*): the
//! Bessel-K NDF at a = 1, an Exp(1) superposition of Beckmann NDFs (β = α√m, m ~ Exp(1)),
//! whose marginal slopes are Laplace distributed.
//!
//! With z = 2 tan θ/α and x = cot θ/α:
//!
//! D(u) = 2 K₀(z)/(π α² u⁴),  P22(r) = 2 K₀(2r/α)/(π α²),  f(x) = 2 K₀(2x)/π,
//! P2(p) = e^{−2|p|/α}/α,  Λ(u) = e^{−2x}/(4x),  σ(−u) = (α/4) sin θ e^{−2x},  σ(0) = α/4,
//! Q(T) = z K₁(z) (z = 2T/α).
//!
//! D(1) = +∞ (logarithmic: "always remains shiny", as the page says). Λ is the page's
//! (In\[2650\]); P2 and Q are derived (docs/derivations.md F.4). Valid for α ∈ [1e-6, 1e6].
//!
//! # Numerics
//! * K₀ and K₁ exponentially scaled (Cephes k0e, k1e) times e^{−z} with z in double-double.
//! * 1 − Q = −(z K₁(z) − 1) by its ascending series below z = 2 (`special::xk1_m1`).
//! * Accuracy (tests/reference.rs against mpmath): every quantity closed form, ≤ 1e-13.

use crate::error::{check_alpha, ParamError};
use crate::math::special::{dd::Dd, k0e, k1e, xk1_m1};
use crate::ndf::slopes::RadialSlopes;
use crate::ndf::{Ndf, ShapeInvariant};
use std::f64::consts::PI;

/// e^{−z} underflows beyond this.
const EXP_UNDERFLOW: f64 = crate::ndf::beckmann::EXP_UNDERFLOW;

/// The K0 NDF with roughness α.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct K0 {
    alpha: f64,
}

impl K0 {
    /// K0 NDF with roughness α ∈ [1e-6, 1e6].
    pub fn new(alpha: f64) -> Result<Self, ParamError> {
        Ok(K0 {
            alpha: check_alpha(alpha)?,
        })
    }

    /// 2 K₀(z)/(π α²) for z = 2r/α in double-double.
    fn p22_z(&self, z: Dd) -> f64 {
        self.p22_z_over(z, 1.0, || 0.0)
    }

    /// P22/d at z = 2r/α, with ln d from `ln_d` (d = u⁴ for D: e^{−z} turns subnormal before D
    /// does, and u⁴ may underflow).
    fn p22_z_over(&self, z: Dd, d: f64, ln_d: impl FnOnce() -> f64) -> f64 {
        if z.hi.is_nan() {
            return f64::NAN;
        }
        if z.hi == 0.0 {
            return f64::INFINITY;
        }
        if z.hi == f64::INFINITY {
            return 0.0;
        }
        // P22 = 2 e^{−z} K₀e(z)/(π α²) = e^{−z}/n, n = π α²/(2 K₀e(z)).
        let n = PI * self.alpha * self.alpha / (2.0 * k0e(z.hi));
        z.exp_neg_over(n * d, || n.ln() + ln_d())
    }

    /// z = 2r/α in double-double.
    fn z(&self, r: Dd) -> Dd {
        r.div_dd(Dd::new(0.5 * self.alpha))
    }
}

impl K0 {
    /// Λ at x = cot θ/α: e^{−2x}/(4x) (0 where e^{−2x} underflows, +∞ at 0).
    pub(crate) fn lambda_x(x: f64) -> f64 {
        if 2.0 * x > EXP_UNDERFLOW {
            return 0.0;
        }
        (-2.0 * x).exp() / (4.0 * x)
    }
}

impl Ndf for K0 {
    fn name(&self) -> &'static str {
        "k0"
    }

    fn alpha(&self) -> f64 {
        self.alpha
    }

    fn d_pos(&self, u: f64) -> f64 {
        let tan = Dd::one_minus_sq(u).sqrt().div_dd(Dd::new(u));
        self.p22_z_over(self.z(tan), (u * u) * (u * u), || 4.0 * u.ln())
    }

    fn p22(&self, p: f64, q: f64) -> f64 {
        let r2 = Dd::mul_f(p, p).add_dd(Dd::mul_f(q, q));
        if !r2.hi.is_finite() {
            return if r2.hi.is_nan() { f64::NAN } else { 0.0 };
        }
        if r2.hi < 1e-300 * self.alpha * self.alpha && (p != 0.0 || q != 0.0) {
            // K₀(z) = −ln(z/2) − γ_E + O(z² ln z) for z = 2r/α < 2e-150 (z/2 may underflow:
            // ln(z/2) = ln r − ln α).
            let k0 = -(p.hypot(q).ln() - self.alpha.ln()) - crate::math::special::EULER_GAMMA;
            return 2.0 * k0 / (PI * self.alpha * self.alpha);
        }
        self.p22_z(self.z(r2.sqrt()))
    }

    fn p2(&self, p: f64) -> f64 {
        if p.is_nan() {
            return p;
        }
        if p.abs() > 0.5 * self.alpha * EXP_UNDERFLOW {
            return 0.0;
        }
        self.z(Dd::new(p.abs())).exp_neg() / self.alpha
    }

    fn lambda_pos(&self, u: f64) -> f64 {
        // (K0::lambda_x is the same at a cot θ given exactly.)
        // 2x = 2 cot θ/α in double-double.
        let sin = Dd::one_minus_sq(u).sqrt();
        let two_x = Dd::new(u).div_dd(sin).div_dd(Dd::new(0.5 * self.alpha));
        if two_x.hi > EXP_UNDERFLOW {
            return 0.0;
        }
        two_x.exp_neg() / (2.0 * two_x.hi)
    }

    fn sigma_neg(&self, u: f64) -> f64 {
        let sin = Dd::one_minus_sq(u).sqrt();
        let two_x = Dd::new(u).div_dd(sin).div_dd(Dd::new(0.5 * self.alpha));
        if two_x.hi > EXP_UNDERFLOW {
            return 0.0;
        }
        0.25 * self.alpha * sin.hi * two_x.exp_neg()
    }

    fn sigma_zero(&self) -> f64 {
        0.25 * self.alpha
    }
}

impl ShapeInvariant for K0 {
    fn f(&self, x: f64) -> f64 {
        let z = 2.0 * x.abs();
        if z == 0.0 {
            return f64::INFINITY;
        }
        if z > EXP_UNDERFLOW {
            return 0.0;
        }
        2.0 * k0e(z) * (-z).exp() / PI
    }
}

impl RadialSlopes for K0 {
    fn slope_cdf(&self, r: f64) -> f64 {
        -xk1_m1(2.0 * r / self.alpha)
    }
    fn slope_ccdf(&self, r: f64) -> f64 {
        let z = self.z(Dd::new(r));
        if z.hi > EXP_UNDERFLOW {
            return 0.0;
        }
        if z.hi < 2.0 {
            return 1.0 + xk1_m1(z.hi);
        }
        z.hi * k1e(z.hi) * z.exp_neg()
    }
}
