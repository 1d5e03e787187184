//! Beckmann NDF: the Gaussian slope distribution, base of the superpositions.
//!
//! D(u) = exp(−tan²θ/α²)/(π α² u⁴),  P22(p, q) = exp(−(p²+q²)/α²)/(π α²),
//! P2(p) = exp(−p²/α²)/(√π α),  f(x) = e^{−x²}/π,
//! Λ(u) = (e^{−a²}/(a√π) − erfc a)/2 with a = cot θ/α,  σ(0) = α/(2√π).
//!
//! Source: d'Eon, *A Hitchhiker's Guide to Multiple Scattering*, the GGX page (Beckmann D
//! with the exponent corrected, derivations.md A.2; its Δ read as Λ, A.1). Valid for every α in [1e-6, 1e6].
//!
//! # Numerics
//! * The exponents tan²θ/α² and a² are formed in double-double: an exponent of 700 with a
//!   2-ulp error would cost 3e-13 in the result.
//! * Λ's printed form cancels completely for large a (derivations.md D); for a ≥ 2 we use
//!   Λ = e^{−a²}/(2a√π) · k/(a + k) with k the tail of the erfc continued fraction
//!   (`special::erfc_ratio_tail`).
//! * Accuracy (tests/reference.rs): D, P22, P2, Λ, σ, G1 within 1e-13 relative of mpmath over the
//!   reference grid; values below ~1e-308 underflow to (sub)normal or 0.

use crate::error::{check_alpha, ParamError};
use crate::math::special::{dd::Dd, erfc, erfc_ratio_tail};
use crate::ndf::{Ndf, ShapeInvariant};
use std::f64::consts::PI;

use crate::math::special::SQRT_PI;
/// exp(−x) is 0 in f64 for x above this (the smallest subnormal is e^{−744.4}).
pub(crate) const EXP_UNDERFLOW: f64 = 746.0;

/// The Beckmann NDF with roughness α.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Beckmann {
    alpha: f64,
}

impl Beckmann {
    /// Beckmann with roughness α ∈ [1e-6, 1e6]; NaN and out-of-range values are rejected.
    pub fn new(alpha: f64) -> Result<Self, ParamError> {
        Ok(Beckmann {
            alpha: check_alpha(alpha)?,
        })
    }

    /// Without the range check, for superposition integrals whose components reach any α > 0.
    pub(crate) fn raw(alpha: f64) -> Self {
        Beckmann { alpha }
    }

    /// exp(−x/α²)/(π α²) for a double-double x ≥ 0.
    fn gauss(&self, x: Dd) -> f64 {
        let a2 = Dd::mul_f(self.alpha, self.alpha);
        let e = x.div_dd(a2);
        if e.hi > EXP_UNDERFLOW {
            return 0.0;
        }
        e.exp_neg() / (PI * a2.hi)
    }
}

impl Ndf for Beckmann {
    fn name(&self) -> &'static str {
        "beckmann"
    }

    fn alpha(&self) -> f64 {
        self.alpha
    }

    fn d_pos(&self, u: f64) -> f64 {
        // tan²θ = (1 − u²)/u²
        let t2 = Dd::one_minus_sq(u).div_dd(Dd::mul_f(u, u));
        let g = self.gauss(t2);
        if g == 0.0 {
            return 0.0;
        }
        let u2 = u * u;
        g / (u2 * u2)
    }

    fn p22(&self, p: f64, q: f64) -> f64 {
        let r2 = Dd::mul_f(p, p).add_dd(Dd::mul_f(q, q));
        if !r2.hi.is_finite() {
            return if r2.hi.is_nan() { f64::NAN } else { 0.0 };
        }
        self.gauss(r2)
    }

    fn p2(&self, p: f64) -> f64 {
        let x = Dd::mul_f(p, p).div_dd(Dd::mul_f(self.alpha, self.alpha));
        if x.hi.is_nan() {
            return f64::NAN;
        }
        if x.hi > EXP_UNDERFLOW {
            return 0.0;
        }
        x.exp_neg() / (SQRT_PI * self.alpha)
    }

    fn lambda_pos(&self, u: f64) -> f64 {
        // a² = u²/(α²(1 − u²)), in double-double for e^{−a²}.
        let a2 =
            Dd::mul_f(u, u).div_dd(Dd::mul_f(self.alpha, self.alpha).mul_dd(Dd::one_minus_sq(u)));
        // a itself from u directly: a² underflows for u below ~1e-154 α.
        let a = crate::math::smith::cot_theta(u) / self.alpha;
        lambda_of(a, a2)
    }

    fn sigma_zero(&self) -> f64 {
        self.alpha / (2.0 * SQRT_PI)
    }
}

/// Λ of a Beckmann NDF as a function of a = cot θ/α alone (a ≥ 0; +∞ at 0, 0 at +∞), for the
/// mixtures of Beckmann components ([`crate::ndf::bessel_k`], the tails of [`crate::ndf::ei`] and
/// [`crate::ndf::erfc`]), whose component argument a is a computed value anyway.
pub(crate) fn lambda_at(a: f64) -> f64 {
    if a.is_nan() {
        return a;
    }
    if a == 0.0 {
        return f64::INFINITY;
    }
    if a == f64::INFINITY {
        return 0.0;
    }
    if a >= 2.0 {
        // As `lambda_of`, with r(a) = k/(a + k) from the fast path's table (within 3.6e-15 of
        // the continued fraction on [2, 32), tests in ndf::erfc; the fraction costs ~50
        // divisions at a = 2, the mixtures evaluate this at every node).
        let a2 = Dd::mul_f(a, a);
        if a2.hi > EXP_UNDERFLOW {
            return 0.0;
        }
        return a2.exp_neg() * crate::fast::beckmann::erfc_ratio(a) / (2.0 * a * SQRT_PI);
    }
    lambda_of(a, Dd::mul_f(a, a))
}

/// Λ as a function of a = cot θ/α (and a² in double-double).
fn lambda_of(a: f64, a2: Dd) -> f64 {
    if a < 2.0 {
        // Cancellation here is at most a factor 10 (at a = 2).
        (a2.exp_neg() / (a * SQRT_PI) - erfc(a)) / 2.0
    } else if a2.hi > EXP_UNDERFLOW {
        0.0
    } else {
        let k = erfc_ratio_tail(a);
        a2.exp_neg() / (2.0 * a * SQRT_PI) * (k / (a + k))
    }
}

impl ShapeInvariant for Beckmann {
    fn f(&self, x: f64) -> f64 {
        let x2 = Dd::mul_f(x, x);
        if x2.hi > EXP_UNDERFLOW {
            return 0.0;
        }
        x2.exp_neg() / PI
    }
}
