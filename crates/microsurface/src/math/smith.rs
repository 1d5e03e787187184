//! Numerical Smith integrals for isotropic NDFs whose Λ has no closed form (GTR for general γ,
//! the Exponential NDF; the generalised exponential through [`kernel`]), and the
//! projected-area ("delta") kernel used by the checks.
//!
//! With a = cot θ and the slope density written radially, P22(p, q) = P(r), r² = p² + q²,
//!
//!   σ(−u) = u Λ(u) = 2 sin θ · I(a),   I(a) = ∫_a^∞ r² P(r) h(y) dr,   cos y = a/r,
//!   h(y) = sin y − y cos y,
//!
//! which follows from Λ = (1/a)∫∫_{p>a} (p − a) P22 dp dq in polar coordinates
//! (∫ (r cos φ − a)₊ dφ = 2 r h(y)). I(0) = ∫₀^∞ r² P dr gives σ(0) = 2 I(0). Every term is
//! positive, so the integral has no cancellation and keeps its relative accuracy even where
//! Λ is exponentially small. h(y) ~ y³/3 near the lower end is summed as a series.

use crate::math::quad;

/// Relative tolerance requested from the quadrature (the documented accuracy is 1e-10; the
/// measured error against mpmath is below 1e-13, tests/reference.rs).
pub const SMITH_TOL: f64 = 1e-13;

/// h(y) = sin y − y cos y, without cancellation for small y.
pub fn h(y: f64) -> f64 {
    if y < 1.0 {
        // y³ Σ_{k=1}^{10} (−1)^{k+1} 2k y^{2(k−1)}/(2k+1)!; at y = 1 the k = 10 term is 4e-19.
        const C: [f64; 10] = {
            let mut c = [0.0; 10];
            let mut fact = 6.0; // (2k+1)!
            let mut k = 1;
            while k <= 10 {
                let sign = if k % 2 == 1 { 1.0 } else { -1.0 };
                c[k - 1] = sign * 2.0 * k as f64 / fact;
                fact *= ((2 * k + 2) * (2 * k + 3)) as f64;
                k += 1;
            }
            c
        };
        let y2 = y * y;
        let mut p = C[9];
        for &c in C[..9].iter().rev() {
            p = p * y2 + c;
        }
        y * y2 * p
    } else {
        y.sin() - y * y.cos()
    }
}

/// I(a) = ∫_a^∞ r² P(r) h(y) dr for a radial slope density given as `p_of_offset(d)` =
/// P(a + d) (the offset d = r − a is passed exactly, which keeps y accurate near the lower
/// end). `scale` is the width over which P changes near r = a.
///
/// A fixed rule, not an adaptive one: tanh-sinh of step 2^−[`SMITH_LEVEL`] under the
/// half-line map scaled to the caller's `scale` ([`quad::to_inf_fixed`]), about 60–190
/// integrand evaluations, for a density with one scale (the Exponential NDF's e^{−2r/α}):
/// within 3e-14 of the adaptive rule at 1e-13 for a from 1e-12 α to 1e3 α (tests below),
/// 2.4e-12 one level coarser. A density with two scales and a power law between them
/// (GTR: α and 1) takes [`smith_integral_adaptive`]: at this level GTR was within 5e-14
/// for α ∈ [1e-3, 100], but 5e-10 off at α = 1e-6, γ = 1, a = 1e-8.
pub fn smith_integral(p_of_offset: impl Fn(f64) -> f64, a: f64, scale: f64) -> f64 {
    quad::to_inf_fixed(
        |d| kernel_times(a, d, || p_of_offset(d)),
        0.0,
        scale,
        SMITH_LEVEL,
    )
}

/// The step 2^−5 of [`smith_integral`]'s fixed rule (see there).
pub const SMITH_LEVEL: u32 = 5;

/// [`smith_integral`] by the adaptive rule at relative tolerance [`SMITH_TOL`] (GTR's, and
/// the reference the fixed rule is tested against).
pub fn smith_integral_adaptive(p_of_offset: impl Fn(f64) -> f64, a: f64, scale: f64) -> f64 {
    quad::integrate_to_inf(|d| kernel(a, d) * p_of_offset(d), 0.0, scale, SMITH_TOL).value
}

/// The integrand r² h(y) P(r) at r = a + d: [`kernel`] times the density `p`, which is not
/// evaluated where the kernel vanishes (past r = ∞, where P's own form may be NaN).
#[inline]
pub fn kernel_times(a: f64, d: f64, p: impl FnOnce() -> f64) -> f64 {
    let k = kernel(a, d);
    if k == 0.0 {
        0.0
    } else {
        k * p()
    }
}

/// The Smith kernel r² h(y) at r = a + d (cos y = a/r), from the exact offset d.
#[inline]
pub fn kernel(a: f64, d: f64) -> f64 {
    let r = a + d;
    if !r.is_finite() {
        return 0.0;
    }
    // y = atan2(√(r² − a²), a) with r² − a² = d (2a + d), exact in d.
    let s = (d * (2.0 * a + d)).sqrt();
    let y = s.atan2(a);
    // From y = 1 on, h = sin y − y cos y = (s − y a)/r (no cancellation there: h(1) =
    // 0.30), which saves a sine and a cosine; below, the series.
    let hy = if y >= 1.0 && s.is_finite() {
        (s - y * a) / r
    } else {
        h(y)
    };
    r * r * hy
}

/// The projected-area kernel Δσ(u, u_i) = ∫₀^{2π} max(0, ω·m) dφ_m for cos θ = u (direction)
/// and cos θm = u_i (normal): 2(√(B² − A²) + A·acos(−A/B)) with A = u u_i,
/// B = √(1−u²)√(1−u_i²); 2π A when A ≥ B (every azimuth lit) and 0 when A ≤ −B (none lit).
/// σ(u) = ∫₀¹ D(u_i) Δσ(u, u_i) du_i (the GGX page; derivations.md B.1).
pub fn delta_sigma(u: f64, ui: f64) -> f64 {
    delta_sigma_at(u, ui, (1.0 - ui * ui).max(0.0).sqrt())
}

/// [`delta_sigma`] with the normal's sin θm given (formed without 1 − u_i² cancellation by a
/// caller that has the slope).
pub fn delta_sigma_at(u: f64, ui: f64, sin_m: f64) -> f64 {
    let a = u * ui;
    let b = (1.0 - u * u).max(0.0).sqrt() * sin_m;
    if a >= b {
        2.0 * std::f64::consts::PI * a
    } else if a <= -b {
        0.0
    } else {
        2.0 * ((b * b - a * a).sqrt() + a * (-a / b).acos())
    }
}

/// cot θ = u/√(1−u²) for 0 < u < 1.
#[inline]
pub fn cot_theta(u: f64) -> f64 {
    u / ((1.0 - u) * (1.0 + u)).sqrt()
}

#[cfg(test)]
mod fixed_rule {
    use super::*;

    /// The fixed rule at SMITH_LEVEL against the adaptive rule at 1e-13, for the Exponential
    /// NDF's e^{−2r/α} (its only user; one scale, so α only rescales a) over a from 1e-12 α
    /// to 1e3 α (measured: within 3e-14).
    #[test]
    fn against_the_adaptive_rule() {
        let mut worst = 0.0f64;
        for alpha in [1e-6, 1e-3, 0.3, 1.0, 100.0, 1e6] {
            let p = |d: f64| (-2.0 * d / alpha).exp();
            for k in 0..=150 {
                let a = alpha * 10f64.powf(-12.0 + k as f64 / 10.0);
                let want = smith_integral_adaptive(p, a, 0.5 * alpha);
                let got = smith_integral(p, a, 0.5 * alpha);
                worst = worst.max((got / want - 1.0).abs());
            }
        }
        assert!(worst < 1e-13, "{worst:e}");
    }
}
