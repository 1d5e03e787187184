//! Double GGX: Λ, σ, G1, G2 from a generated octave table (relative error ≤ 1e-7 required,
//! ≤ 2e-9 measured; tests/fast.rs checks it over the whole domain against the exact
//! [`crate::DoubleGgx`], whose Λ is (√π U(−½, 0, 2x) − 1)/2 = (x eˣ(K₀(x) + K₁(x)) − 1)/2).
//!
//! The variable is x = α² tan²θ/2 = α²(1 − u)(1 + u)/(2u²) (one division, no square root).
//! * x < 2^−30 (near the normal): Λ = (x/2)(1 − γ_E − ln(x/2)) + O(x² ln x), relative error
//!   below 1e-9 there.
//! * 2^−30 ≤ x < 2^16: the table (degree and segments in `tables.rs`).
//! * x ≥ 2^16 (grazing): Λ = (√(2πx)(1 + 1/(8x) − 3/(128x²)) − 1)/2, the large-x expansion
//!   of K₀ + K₁, whose next term is below 1e-14 there.

use super::tables::{DGGX, DGGX_K0, DGGX_K1, DGGX_M};
use super::{fit, Real};

/// Euler's constant γ_E.
const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// Λ(x), x = α² tan²θ/2 ≥ 0 (+∞ at x = +∞, NaN for NaN).
#[inline]
pub fn lambda_x(x: f64) -> f64 {
    // 2^{DGGX_K0} and 2^{DGGX_K1}: the table's ends.
    let lo = super::fit::pow2(DGGX_K0);
    let hi = super::fit::pow2(DGGX_K1);
    if x >= lo && x < hi {
        return fit::eval(&DGGX, DGGX_K0, DGGX_M, x);
    }
    if x < lo {
        if x <= 0.0 {
            return 0.0;
        }
        return 0.5 * x * (1.0 - EULER_GAMMA - (0.5 * x).ln());
    }
    if x.is_nan() {
        return x;
    }
    let r = 1.0 / x;
    let s = (std::f64::consts::TAU * x).sqrt() * (1.0 + r * (0.125 - r * (3.0 / 128.0)));
    0.5 * (s - 1.0)
}

/// D(u) (every u; 0 below the horizon): the exact closed form of [`crate::DoubleGgx`] (its
/// E₁ continued fraction; ≤ 1e-13), rounded to F.
#[inline]
pub fn d<F: Real>(u: F, alpha: F) -> F {
    use crate::Ndf;
    F::from_f64(crate::DoubleGgx::raw(alpha.to_f64()).d(u.to_f64()))
}

/// Λ(u) for 0 ≤ u ≤ 1 (+∞ at u = 0, 0 at u = 1).
#[inline]
pub fn lambda<F: Real>(u: F, alpha: F) -> F {
    let (u, a) = (u.to_f64(), alpha.to_f64());
    let x = 0.5 * a * a * ((1.0 - u) * (1.0 + u)) / (u * u);
    F::from_f64(lambda_x(x))
}

/// G1(u) = 1/(1 + Λ(u)) for 0 ≤ u ≤ 1.
#[inline]
pub fn g1<F: Real>(u: F, alpha: F) -> F {
    F::from_f64(1.0 / (1.0 + lambda(u.to_f64(), alpha.to_f64())))
}

/// Height-correlated G2 = 1/(1 + Λ(u_o) + Λ(u_i)).
#[inline]
pub fn g2<F: Real>(u_o: F, u_i: F, alpha: F) -> F {
    let a = alpha.to_f64();
    F::from_f64(1.0 / (1.0 + lambda(u_o.to_f64(), a) + lambda(u_i.to_f64(), a)))
}

/// σ(u) for u ∈ [−1, 1]: u(1 + Λ(u)) above the horizon, |u| Λ(|u|) below, σ(0) = √π α/2.
#[inline]
pub fn sigma<F: Real>(u: F, alpha: F) -> F {
    let (u, a) = (u.to_f64(), alpha.to_f64());
    F::from_f64(super::sigma_from_lambda(u, 0.5 * super::SQRT_PI * a, |v| {
        lambda(v, a)
    }))
}
