//! Double GGX: the NDF that is to GGX what GGX is to Beckmann (the Double GGX page),
//! D(u, α) = ∫₀^∞ e^{−t} D_GGX(u, α/√t) dt.
//!
//! P22(r) = G(α²/r²)/(π α²) with G(c) = c²[(1+c) e^c E₁(c) − 1] (the Double GGX page, with the
//! minus sign restored, derivations.md A.4; Ei(−c) = −E₁(c)), D(u) = G(α²u²/(1−u²))/(π α² u⁴),
//! f(x) = G(1/x²)/π,
//! P2(p) = (α²/(2|p|³)) e^{c/2}[(1+c)K₀(c/2) − c K₁(c/2)], c = α²/p² (derivations.md A.16),
//! Λ(u) = (√π U(−½, 0, z) − 1)/2,  z = α² tan²θ,  √π U(−½, 0, z) = x e^x (K₀(x) + K₁(x)), x = z/2
//! (derivations.md A.5), σ(0) = √π α/2.
//!
//! Valid for α ∈ [1e-6, 1e6].
//!
//! # Numerics
//! * G(c) cancels like 1/c² near the normal in the printed form; `special::dggx_g`
//!   evaluates it from a continued fraction without cancellation.
//! * D diverges logarithmically at grazing (D ~ α² ln(1/c)/π, c = α²/tan²θ → 0): it is
//!   finite for every u > 0 and evaluated without forming c² or u⁴ there.
//! * Λ cancels as u → 1; `special::bessel_k_sum_m1` sums series there.
//! * P2 cancels for small |p| (c large): for c > 1/4 we use the integral
//!   P2 = (1/(2α)) ∫₀^∞ e^{−t} √t (1 + t/c)^{−3/2} dt (tanh-sinh, 1e-14), which is
//!   Γ(3/2) c^{3/2} U(3/2, 1, c) α²/(2|p|³) written without the cancelling prefactor.
//! * Accuracy: ≤ 1e-13 relative over the reference grid (tests/reference.rs).

use crate::error::{check_alpha, ParamError};
use crate::math::quad;
use crate::math::special::{bessel_k_sum_m1, dd::Dd, dggx_bracket, dggx_g, k0e, k1e};
use crate::ndf::{Ndf, ShapeInvariant};
use std::f64::consts::PI;

use crate::math::special::SQRT_PI;

/// The Double GGX NDF with roughness α.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DoubleGgx {
    alpha: f64,
}

impl DoubleGgx {
    /// Double GGX with roughness α ∈ [1e-6, 1e6].
    pub fn new(alpha: f64) -> Result<Self, ParamError> {
        Ok(DoubleGgx {
            alpha: check_alpha(alpha)?,
        })
    }

    /// Without the range check (the fast paths' callers own α > 0).
    pub(crate) fn raw(alpha: f64) -> Self {
        DoubleGgx { alpha }
    }
}

impl Ndf for DoubleGgx {
    fn name(&self) -> &'static str {
        "double_ggx"
    }

    fn alpha(&self) -> f64 {
        self.alpha
    }

    fn d_pos(&self, u: f64) -> f64 {
        let a2 = self.alpha * self.alpha;
        let ua = u * self.alpha;
        let one_u2 = Dd::one_minus_sq(u).hi;
        let c = ua * ua / one_u2; // = α²/tan²θ, +∞ at u = 1
        if c < 1e-300 {
            // c (nearly) underflows: g(c) = −γ_E − 1 − ln c + O(c ln c), ln c from logs.
            const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;
            let ln_c = 2.0 * (u.ln() + self.alpha.ln()) - one_u2.ln();
            return a2 * (-EULER_GAMMA - 1.0 - ln_c) / (PI * one_u2 * one_u2);
        }
        if c < 1.0 {
            // G(c)/(α² u⁴) = α² g(c)/(1 − u²)²: D grows like α² ln(1/c)/π at grazing, while
            // c² and u⁴ would both underflow.
            return a2 * dggx_bracket(c) / (PI * one_u2 * one_u2);
        }
        let u2 = u * u;
        dggx_g(c) / (PI * a2 * u2 * u2)
    }

    fn p22(&self, p: f64, q: f64) -> f64 {
        let r2 = p * p + q * q;
        let a2 = self.alpha * self.alpha;
        dggx_g(a2 / r2) / (PI * a2)
    }

    fn p2(&self, p: f64) -> f64 {
        if p.is_nan() {
            return p;
        }
        let a = self.alpha;
        let ap = p.abs();
        let c = (a / ap) * (a / ap);
        if c == f64::INFINITY {
            return SQRT_PI / (4.0 * a);
        }
        // c < 1e-280 means |p| > 1e134 α, where P2 ~ α² ln(1/c)/(2|p|³) has underflowed.
        if c < 1e-280 {
            return 0.0;
        }
        if c <= 0.25 {
            // The Bessel form; its bracket is at least a third of its largest term here.
            let h = 0.5 * c;
            let bracket = (1.0 + c) * k0e(h) - c * k1e(h);
            return a / ap * (a / ap) / (2.0 * ap) * bracket;
        }
        let q = quad::integrate_to_inf(
            |t| (-t).exp() * t.sqrt() * (1.0 + t / c).powf(-1.5),
            0.0,
            1.0,
            1e-14,
        );
        q.value / (2.0 * a)
    }

    fn lambda_pos(&self, u: f64) -> f64 {
        let t = self.alpha / crate::math::smith::cot_theta(u);
        // For t > 1e150, t² overflows; there S = x e^x (K₀ + K₁) = √(2πx)(1 + O(1/x)) = √π t.
        if t > 1e150 {
            return 0.5 * SQRT_PI * t;
        }
        0.5 * bessel_k_sum_m1(0.5 * t * t)
    }

    fn sigma_zero(&self) -> f64 {
        SQRT_PI * self.alpha / 2.0
    }
}

/// Λ as a function of x = α² tan²θ/2 (shape invariance: every α and θ at once), exact:
/// (x eˣ(K₀(x) + K₁(x)) − 1)/2 by the Bessel form, with its cancellation at small x summed
/// as a series ([`DoubleGgx`]'s `lambda`; within 4e-15 of mpmath). What the fast tables fit.
pub fn lambda_x(x: f64) -> f64 {
    0.5 * bessel_k_sum_m1(x)
}

impl ShapeInvariant for DoubleGgx {
    fn f(&self, x: f64) -> f64 {
        dggx_g(1.0 / (x * x)) / PI
    }
}
