//! GGX / Trowbridge–Reitz NDF.
//!
//! D(u) = α²/(π (1 + u²(α² − 1))²),  P22 = α²/(π (r² + α²)²),  P2(p) = α²/(2 (p² + α²)^{3/2}),
//! f(x) = 1/(π (1 + x²)²),  Λ(u) = (−1 + √(1 + α² tan²θ))/2,
//! σ(u) = (u + √(α² + u²(1 − α²)))/2 on [−1, 1],  σ(0) = α/2.
//!
//! Source: d'Eon, *A Hitchhiker's Guide to Multiple Scattering*, the GGX page (Λ; one
//! derivation line is garbled, derivations.md A.3); Walter et al. 2007. Any α in [1e-6, 1e6].
//!
//! # Numerics
//! * 1 + u²(α² − 1) is evaluated as (1 − u²) + u²α² (a sum of positive terms).
//! * Λ = s/(2(1 + √(1+s))), s = α² tan²θ, which does not cancel as s → 0 (derivations.md D).
//! * Accuracy: closed forms within 1e-14 relative (tests/reference.rs).

use crate::error::{check_alpha, ParamError};
use crate::math::special::dd::Dd;
use crate::ndf::{Ndf, ShapeInvariant};
use std::f64::consts::PI;

/// The GGX (Trowbridge–Reitz) NDF with roughness α.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ggx {
    alpha: f64,
}

impl Ggx {
    /// GGX with roughness α ∈ [1e-6, 1e6].
    pub fn new(alpha: f64) -> Result<Self, ParamError> {
        Ok(Ggx {
            alpha: check_alpha(alpha)?,
        })
    }

    /// Without the range check (superposition components).
    pub(crate) fn raw(alpha: f64) -> Self {
        Ggx { alpha }
    }
}

/// GGX Λ at t = α tan θ = α/cot θ: (√(1 + t²) − 1)/2, as t²/(2(1 + √(1 + t²))) (no
/// cancellation near the normal). Shared with GTR's γ = 2 case ([`crate::Gtr::lambda_cot`]).
pub(crate) fn lambda_of_t(t: f64) -> f64 {
    // For t > 1e150, t² overflows; there Λ = (√(1+t²) − 1)/2 = t/2 to f64 precision.
    if t > 1e150 {
        return 0.5 * t;
    }
    let s = t * t;
    s / (2.0 * (1.0 + (1.0 + s).sqrt()))
}

impl Ndf for Ggx {
    fn name(&self) -> &'static str {
        "ggx"
    }

    fn alpha(&self) -> f64 {
        self.alpha
    }

    fn d_pos(&self, u: f64) -> f64 {
        let a = self.alpha;
        let ua = u * a;
        let w = Dd::one_minus_sq(u).hi + ua * ua;
        // α²/(π w²) written as 1/(π α² (w/α²)²) would overflow less, but w ≥ min(1, α²)·u²
        // keeps w² normal for α ≥ 1e-6.
        a * a / (PI * w * w)
    }

    fn p22(&self, p: f64, q: f64) -> f64 {
        let a2 = self.alpha * self.alpha;
        let w = p * p + q * q + a2;
        a2 / (PI * w * w)
    }

    fn p2(&self, p: f64) -> f64 {
        let a2 = self.alpha * self.alpha;
        let w = p * p + a2;
        a2 / (2.0 * w * w.sqrt())
    }

    fn lambda_pos(&self, u: f64) -> f64 {
        lambda_of_t(self.alpha / crate::math::smith::cot_theta(u))
    }

    fn sigma_zero(&self) -> f64 {
        self.alpha / 2.0
    }
}

impl ShapeInvariant for Ggx {
    fn f(&self, x: f64) -> f64 {
        let w = 1.0 + x * x;
        1.0 / (PI * w * w)
    }
}
