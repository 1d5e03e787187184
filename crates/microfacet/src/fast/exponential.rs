//! The Exponential NDF: Λ, σ, G1, G2 from a generated octave table (relative error ≤ 1e-7
//! required; the measured figure is in tests/fast.rs and BENCHMARKS.md), against the exact
//! [`crate::Exponential`], Λ = (2K₁(z) − Ki₁(z))/π, z = 2 cot θ/α (ERRATA A.14).
//!
//! The variable is z = 2u/(α√((1 − u)(1 + u))). Λ falls like e^{−z}/√z, so the table holds
//! Λ(z) e^z and one exponential restores the factor.
//! * z < 2^−12 (grazing): Λ = 2/(πz) − 1/2 + z/(2π) + O(z³ ln z), relative error below 1e-14.
//! * 2^−12 ≤ z < 2^9: the table.
//! * z ≥ 2^9 (near the normal): Λ = e^{−z}(1 + 11/(8z) − 159/(128z²) + 8595/(3072z³))/√(2πz),
//!   from the large-z expansions of K₁ and Ki₁ (the z⁻³ coefficient fitted to mpmath values of
//!   the Struve form at z = 100…800 and recognised as 315/1536 + 2655/1024); the next term is
//!   about 9/z⁴, below 2e-10 relative. From z ≈ 708 on Λ is subnormal and only absolutely
//!   accurate; it underflows to 0 near z = 745.

use super::tables::{EXPONENTIAL, EXPONENTIAL_K0, EXPONENTIAL_K1, EXPONENTIAL_M};
use super::{fit, Real};
use std::f64::consts::{FRAC_1_PI, FRAC_2_PI};

/// Λ(z), z = 2 cot θ/α ≥ 0 (+∞ at z = 0, NaN for NaN).
#[inline]
pub fn lambda_z(z: f64) -> f64 {
    let lo = super::fit::pow2(EXPONENTIAL_K0);
    let hi = super::fit::pow2(EXPONENTIAL_K1);
    if z >= lo && z < hi {
        return fit::eval(&EXPONENTIAL, EXPONENTIAL_K0, EXPONENTIAL_M, z) * (-z).exp();
    }
    if z < lo {
        return FRAC_2_PI / z - 0.5 + 0.5 * FRAC_1_PI * z;
    }
    if z.is_nan() {
        return z;
    }
    let r = 1.0 / z;
    let series = 1.0 + r * (11.0 / 8.0 - r * (159.0 / 128.0 - r * (8595.0 / 3072.0)));
    (-z).exp() * series / (std::f64::consts::TAU * z).sqrt()
}

/// D(u) = 2 exp(−2 tan θ/α)/(π α² u⁴); 0 for u ≤ 0 and where e^{−2tan θ/α} underflows
/// (relative error ≤ 1e-13 in f64 while the exponent is below 30, growing like ε·exponent).
#[inline]
pub fn d<F: Real>(u: F, alpha: F) -> F {
    let (u, a) = (u.to_f64(), alpha.to_f64());
    if u <= 0.0 {
        return F::ZERO;
    }
    let u2 = u * u;
    let x = 2.0 * ((1.0 - u) * (1.0 + u)).sqrt() / (u * a);
    // e^{−x} is 0 past 745 (and u⁴ could underflow too: 0/0).
    if x > 745.2 {
        return F::ZERO;
    }
    F::from_f64(2.0 * (-x).exp() / (std::f64::consts::PI * a * a * u2 * u2))
}

/// Λ(u) for 0 ≤ u ≤ 1 (+∞ at u = 0, 0 at u = 1).
#[inline]
pub fn lambda<F: Real>(u: F, alpha: F) -> F {
    let (u, a) = (u.to_f64(), alpha.to_f64());
    let z = (u + u) / (a * ((1.0 - u) * (1.0 + u)).sqrt());
    F::from_f64(lambda_z(z))
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

/// σ(u) for u ∈ [−1, 1]: u(1 + Λ(u)) above the horizon, |u| Λ(|u|) below, σ(0) = α/π.
#[inline]
pub fn sigma<F: Real>(u: F, alpha: F) -> F {
    let (u, a) = (u.to_f64(), alpha.to_f64());
    F::from_f64(super::sigma_from_lambda(u, a * FRAC_1_PI, |v| lambda(v, a)))
}
