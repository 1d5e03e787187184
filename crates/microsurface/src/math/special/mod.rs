//! Special functions: the one place where every transcendental the NDFs need is routed.
//!
//! | function | source | measured max. relative error vs mpmath (tests/special.rs) |
//! |---|---|---|
//! | `erf`; `erfc` on [0, 3] (where it is used) | `libm` (musl port) | ≤ 3e-16 (erfc: 5e-14 near x = 15, unused) |
//! | `e1` (= E₁) on (0, 1) (where it is used), `k0e`, `k1e`, `elliprd` | `spec_math` (Cephes / Carlson port) | ≤ 5e-15 (E₁: 3e-14 near x = 200, unused) |
//! | [`erfc_ratio_tail`], [`dggx_g`], [`bessel_k_sum_m1`] | this module (continued fractions and series) | ≤ 2e-15, 1e-14, 4e-15 |
//! | [`beta_1p`] (B(1 + x, 1 + y) for x, y up to 1e300 and ∞) | this module (Cephes' Γ below 10, Stirling's series above) | ≤ 4ε(1 + \|ln B\|) (measured 2.5) |
//!
//! The last two rows exist because the closed forms (the pages', and differences of ln Γ)
//! cancel catastrophically in some regions (see docs/derivations.md D); each function here
//! computes a cancellation-free combination instead of the difference of two large numbers.

pub mod dd;
#[cfg(test)]
mod tests;

/// √π.
pub const SQRT_PI: f64 = 1.772_453_850_905_516;

/// eˣ/d for d > 0, without a subnormal or overflowing intermediate: the plain quotient where
/// eˣ and d are normal doubles, else exp(x − ln d) with ln d from `ln_d` (which the caller forms
/// without underflow, e.g. ln π α² + 4 ln u for d = π α² u⁴). A value formed either way carries
/// about |x − ln d| ulps from the rounding of its exponent, the floor of any exponential.
#[inline]
pub fn exp_over(x: f64, d: f64, ln_d: impl FnOnce() -> f64) -> f64 {
    // e^x is normal for x ∈ [−708, 709] (2.2e-308 = e^{−708.4}, 1.8e308 = e^{709.8}).
    if (-708.0..=709.0).contains(&x) && d.is_normal() {
        x.exp() / d
    } else {
        (x - ln_d()).exp()
    }
}

/// Error function erf(x) (libm).
#[inline]
pub fn erf(x: f64) -> f64 {
    libm::erf(x)
}

/// Complementary error function erfc(x) = 1 − erf(x) (libm), accurate in the far tail.
#[inline]
pub fn erfc(x: f64) -> f64 {
    libm::erfc(x)
}

/// Exponential integral E₁(x) = ∫₁^∞ e^{−xt}/t dt for x > 0 (Cephes `expn(1, x)`).
#[inline]
pub fn e1(x: f64) -> f64 {
    spec_math::cephes64::expn(1, x)
}

/// Exponentially scaled modified Bessel function e^x K₀(x), x > 0 (Cephes).
#[inline]
pub fn k0e(x: f64) -> f64 {
    spec_math::cephes64::k0e(x)
}

/// Exponentially scaled modified Bessel function e^x K₁(x), x > 0 (Cephes).
#[inline]
pub fn k1e(x: f64) -> f64 {
    spec_math::cephes64::k1e(x)
}

/// Carlson's symmetric elliptic integral R_D(x, y, z) (spec_math's port of Carlson 1995).
///
/// Used for the complete integrals without cancellation:
/// K(m) − E(m) = (m/3) R_D(0, 1−m, 1), valid for every m < 1 (also m < 0).
#[inline]
pub fn elliprd(x: f64, y: f64, z: f64) -> f64 {
    spec_math::misc::elliprd(x, y, z)
}

/// expm1(x)/x, with its limit 1 at x = 0 (no 0/0).
#[inline]
pub fn expm1_over_x(x: f64) -> f64 {
    if x == 0.0 {
        1.0
    } else {
        x.exp_m1() / x
    }
}

/// ln(1+x)/x, with its limit 1 at x = 0 (no 0/0).
#[inline]
pub fn ln1p_over_x(x: f64) -> f64 {
    if x == 0.0 {
        1.0
    } else {
        x.ln_1p() / x
    }
}

/// The tail of the erfc continued fraction: returns `k` such that
/// √π · x · e^{x²} erfc(x) = x / (x + k), for x > 0.
///
/// `k = ½/(x + 1/(x + (3/2)/(x + 2/(x + …))))` (Abramowitz & Stegun 7.1.14), evaluated with the
/// modified Lentz method. It gives 1 − √π x e^{x²} erfc(x) = k/(x+k) without cancellation,
/// which is what Beckmann's Λ needs for large x. Converges quickly for x ≥ 2 (the only range
/// it is used in).
pub fn erfc_ratio_tail(x: f64) -> f64 {
    // k = a1/(x + a2/(x + a3/(x + …))), a_n = n/2.
    lentz(|n| 0.5 * n as f64, |_| x)
}

/// Modified Lentz evaluation of a1/(b1 + a2/(b2 + a3/(b3 + …))) with b_n = b(n), a_n = a(n).
fn lentz(a: impl Fn(usize) -> f64, b: impl Fn(usize) -> f64) -> f64 {
    // Tiny stands in for a zero denominator (Numerical Recipes §5.2).
    const TINY: f64 = 1e-300;
    let mut f = TINY;
    let mut c = f;
    let mut d = 0.0;
    for n in 1..10_000 {
        let an = a(n);
        let bn = b(n);
        d = bn + an * d;
        if d == 0.0 {
            d = TINY;
        }
        c = bn + an / c;
        if c == 0.0 {
            c = TINY;
        }
        d = 1.0 / d;
        let delta = c * d;
        f *= delta;
        // Converged to the last bit: |Δ − 1| below one ulp of 1.
        if (delta - 1.0).abs() <= 1e-16 {
            break;
        }
    }
    // b0 = 0 was represented by TINY, which only scales f by (1 + O(1e-300)).
    f
}

/// The Double-GGX slope kernel G(c) = c²·[(1+c) e^c E₁(c) − 1], c > 0, with G(∞) = 1.
///
/// Double GGX has P22(r) = G(α²/r²)/(π α²). The bracket equals ∫₀^∞ e^{−ct} t/(1+t)² dt,
/// which is positive and ~1/c² for large c, where the printed form cancels (it loses 2·log₁₀ c
/// digits, derivations.md D). For c ≥ 1 we use the even continued fraction of e^c E₁(c),
/// e^c E₁(c) = 1/(c+1 − T), T = 1/(c+3 − 4/(c+5 − 9/(c+7 − …))), for which the bracket is
/// exactly T/(c+1−T): no subtraction of nearly equal numbers. For c < 1 the bracket is at most
/// 6.5× smaller than its terms, so E₁ from Cephes (≤ 5e-15 there) keeps the result ≤ 1e-14.
pub fn dggx_g(c: f64) -> f64 {
    if c.is_nan() {
        return f64::NAN;
    }
    if c == f64::INFINITY {
        return 1.0;
    }
    if c <= 0.0 {
        return 0.0;
    }
    if c < 1.0 {
        return c * c * dggx_bracket(c);
    }
    let t = e1_cf_tail(c);
    let f1 = 1.0 / (c + 1.0 - t);
    // c²·T·f1 as (c·T)(c·f1): both factors are O(1), so nothing overflows for huge c.
    (c * t) * (c * f1)
}

/// The tail T of the even continued fraction e^c E₁(c) = 1/(c + 1 − T),
/// T = 1/(c+3 − 4/(c+5 − 9/(c+7 − …))), for c ≥ 1 (where it converges quickly).
pub fn e1_cf_tail(c: f64) -> f64 {
    // a_1 = 1, a_n = −n² (n ≥ 2), b_n = c + 2n + 1.
    lentz(
        |n| if n == 1 { 1.0 } else { -((n * n) as f64) },
        |n| c + (2 * n + 1) as f64,
    )
}

/// The bracket g(c) = (1+c) e^c E₁(c) − 1 of [`dggx_g`] for 0 < c < 1 (G = c² g), for callers
/// that must divide the c² out analytically (Double GGX D at grazing, where g ~ −ln c grows
/// while c² underflows).
pub fn dggx_bracket(c: f64) -> f64 {
    (1.0 + c) * c.exp() * e1(c) - 1.0
}

/// S(x) − 1 where S(x) = x e^x (K₀(x) + K₁(x)), for x > 0 (and 0 at x = 0).
///
/// Double GGX has √π U(−½, 0, 2x) = S(x), so Λ = (S − 1)/2. S → 1 as x → 0 and the direct
/// form cancels (derivations.md D); for x < 2 we sum the ascending series of K₀ and x K₁ − 1 (A&S
/// 9.6.13, 9.6.11), whose terms are all small, and combine as e^x (x K₀ + (x K₁ − 1)) + expm1(x).
pub fn bessel_k_sum_m1(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    if x <= 0.0 {
        return 0.0;
    }
    if x == f64::INFINITY {
        return x;
    }
    if x >= 2.0 {
        return x * (k0e(x) + k1e(x)) - 1.0;
    }
    const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;
    let q = 0.25 * x * x;
    let l = (0.5 * x).ln() + EULER_GAMMA;
    // K0 = −l I0 + Σ_{k≥1} H_k q^k/(k!)²
    // x K1 − 1 = x I1 ln(x/2) − (x²/4) Σ_{k≥0} [ψ(k+1)+ψ(k+2)] q^k/(k!(k+1)!)
    //          with ψ(k+1) = −γ + H_k, and x I1 = 2q Σ q^k/(k!(k+1)!).
    let mut i0 = 0.0;
    let mut s0 = 0.0;
    let mut xi1_sum = 0.0;
    let mut s1 = 0.0;
    let mut t0 = 1.0; // q^k/(k!)²
    let mut t1 = 1.0; // q^k/(k!(k+1)!)
    let mut h = 0.0; // H_k
    for k in 0..60 {
        let kf = k as f64;
        if k > 0 {
            h += 1.0 / kf;
            t0 *= q / (kf * kf);
            t1 *= q / (kf * (kf + 1.0));
        }
        i0 += t0;
        s0 += h * t0;
        xi1_sum += t1;
        // ψ(k+1) + ψ(k+2) = −2γ + 2H_k + 1/(k+1)
        s1 += (-2.0 * EULER_GAMMA + 2.0 * h + 1.0 / (kf + 1.0)) * t1;
        // Terms decrease geometrically (q < 1); stop when they no longer change the sums.
        if t1 < 1e-18 * xi1_sum && t0 < 1e-18 * i0 {
            break;
        }
    }
    let k0 = -l * i0 + s0;
    let xk1_m1 = 2.0 * q * xi1_sum * (0.5 * x).ln() - q * s1;
    x.exp() * (x * k0 + xk1_m1) + x.exp_m1()
}

/// x K₁(x) − 1 for x ≥ 0 (−1 at +∞), without the cancellation of the direct form near 0
/// (x K₁(x) = 1 + (x²/2)(ln(x/2) + γ_E − ½) + O(x⁴ ln x)): the ascending series of
/// [`bessel_k_sum_m1`] below x = 2, x K₁e(x) e^{−x} − 1 above (at most 0.28 of 1 there, so
/// no cancellation). The K0 NDF's D·cos CDF is −(x K₁(x) − 1).
pub fn xk1_m1(x: f64) -> f64 {
    if x.is_nan() {
        return x;
    }
    if x <= 0.0 {
        return 0.0;
    }
    if x >= 2.0 {
        return if x > 746.0 {
            -1.0
        } else {
            x * k1e(x) * (-x).exp() - 1.0
        };
    }
    let q = 0.25 * x * x;
    // x K₁ − 1 = 2q ln(x/2) Σ q^k/(k!(k+1)!) − q Σ [ψ(k+1)+ψ(k+2)] q^k/(k!(k+1)!).
    const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;
    let (mut sum, mut s1, mut t1, mut h) = (0.0, 0.0, 1.0, 0.0);
    for k in 0..60 {
        let kf = k as f64;
        if k > 0 {
            h += 1.0 / kf;
            t1 *= q / (kf * (kf + 1.0));
        }
        sum += t1;
        s1 += (-2.0 * EULER_GAMMA + 2.0 * h + 1.0 / (kf + 1.0)) * t1;
        // q < 1: geometric decrease; stop when a term no longer changes the sums.
        if t1 < 1e-18 * sum {
            break;
        }
    }
    2.0 * q * sum * (0.5 * x).ln() - q * s1
}

/// E₁(x) for x > 0 to ≤ 4e-16 relative: Cephes below 1, e^{−x}/(x + 1 − T) above with T the
/// tail of the even continued fraction ([`e1_cf_tail`], which converges fast there);
/// `exp_neg_x` lets a caller pass e^{−x} computed more accurately (in double-double) than from the
/// rounded x. +∞ at 0, 0 past the underflow of e^{−x}.
pub fn e1_with(x: f64, exp_neg_x: f64) -> f64 {
    if x.is_nan() {
        return x;
    }
    if x <= 0.0 {
        return f64::INFINITY;
    }
    if x < 1.0 {
        return e1(x);
    }
    if exp_neg_x == 0.0 {
        return 0.0;
    }
    exp_neg_x / (x + 1.0 - e1_cf_tail(x))
}

/// Γ(x + ½)/Γ(x) for x > 0, to a few ulp also where both Gammas overflow: directly below
/// x = 40, and above by the asymptotic series √x (1 − 1/(8x) + 1/(128x²) + 5/(1024x³)
/// − 21/(32768x⁴) − 399/(262144x⁵) + 869/(4194304x⁶) + 39325/(33554432x⁷) + …) (DLMF 5.11.13;
/// coefficients checked with mpmath: 3e-17 relative at x = 40).
pub fn gamma_ratio_half(x: f64) -> f64 {
    if x < 40.0 {
        return spec_math::cephes64::gamma(x + 0.5) / spec_math::cephes64::gamma(x);
    }
    const C: [f64; 8] = [
        1.0,
        -1.0 / 8.0,
        1.0 / 128.0,
        5.0 / 1024.0,
        -21.0 / 32768.0,
        -399.0 / 262144.0,
        869.0 / 4194304.0,
        39325.0 / 33554432.0,
    ];
    let y = 1.0 / x;
    let series = C.iter().rev().fold(0.0, |acc, &c| acc * y + c);
    x.sqrt() * series
}

/// Euler's constant γ_E.
pub const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// ln(x^ν K_ν(2x)) for 0 < x ≤ 1e-150 from ln x = `ln_x` (x itself may underflow): the
/// leading terms of the series, x^ν K_ν(2x) = ½[Γ(ν) + Γ(−ν) x^{2ν}] (relative error
/// O(x^{2−2|ν|}) + O(x²), below 1e-150 here), written as
/// [Γ(1+ν)(−expm1(2ν ln x)) + (Γ(1+ν) − Γ(1−ν)) x^{2ν}]/(2ν) so that ν → 0 (K0: −ln x − γ_E)
/// does not cancel; for |ν| ≥ ½ only the leading term (the other is below x). The difference
/// Γ(1+ν) − Γ(1−ν) is its odd series −2γ_E ν − 2(ζ(3)/3 + γ_E³/6 + γ_E ζ(2)/2) ν³ below
/// |ν| = 1e-4 (next term ~ν⁵: 1e-16 of it), direct above (its rounding, ε/ν ≤ 1e-12 of
/// itself, is ≤ 0.2 % of the sum, whose expm1 term is ≥ ln(1e150)).
pub fn ln_xnu_bessel_k_small(nu: f64, ln_x: f64) -> f64 {
    if nu >= 0.5 {
        return (0.5 * gamma(nu)).ln();
    }
    if nu <= -0.5 {
        return (0.5 * gamma(-nu)).ln() + 2.0 * nu * ln_x;
    }
    if nu == 0.0 {
        return (-ln_x - EULER_GAMMA).ln();
    }
    const ZETA2: f64 = 1.644_934_066_848_226_4;
    const ZETA3: f64 = 1.202_056_903_159_594_3;
    let diff = if nu.abs() < 1e-4 {
        let g = EULER_GAMMA;
        let c3 = ZETA3 / 3.0 + g * g * g / 6.0 + g * ZETA2 / 2.0;
        -2.0 * nu * (g + c3 * nu * nu)
    } else {
        gamma(1.0 + nu) - gamma(1.0 - nu)
    };
    let t = 2.0 * nu * ln_x;
    if t > 1.0 {
        // (ν < 0: x^{2ν} dominates and may overflow; factored out in logarithms.)
        return t + ((gamma(1.0 + nu) * (-t).exp() - gamma(1.0 - nu)) / (2.0 * nu)).ln();
    }
    ((gamma(1.0 + nu) * -t.exp_m1() + diff * t.exp()) / (2.0 * nu)).ln()
}

/// Γ(x) (Cephes).
#[inline]
pub fn gamma(x: f64) -> f64 {
    spec_math::cephes64::gamma(x)
}

/// ln Γ(x) (Cephes).
#[inline]
pub fn ln_gamma(x: f64) -> f64 {
    spec_math::cephes64::lgam(x)
}

/// Regularised incomplete beta I_x(a, b) (Cephes `incbet`).
#[inline]
pub fn inc_beta(a: f64, b: f64, x: f64) -> f64 {
    spec_math::cephes64::incbet(a, b, x)
}

/// ln(2π)/2.
const LN_SQRT_2PI: f64 = 0.918_938_533_204_672_8;

/// The remainder of Stirling's series, ln Γ(x) − [(x − ½) ln x − x + ln √(2π)], for x ≥ 10:
/// Σ B₂ₖ/(2k(2k − 1) x^{2k−1}), k = 1…7 (DLMF 5.11.1; the first omitted term,
/// 3617/(122400 x¹⁵), is below 3e-17 at x = 10, and the series alternates). 0 at x = ∞.
fn stirling_remainder(x: f64) -> f64 {
    const C: [f64; 7] = [
        1.0 / 12.0,
        -1.0 / 360.0,
        1.0 / 1260.0,
        -1.0 / 1680.0,
        1.0 / 1188.0,
        -691.0 / 360_360.0,
        1.0 / 156.0,
    ];
    let y = 1.0 / x;
    let y2 = y * y;
    y * C.iter().rev().fold(0.0, |acc, &c| acc * y2 + c)
}

/// The Gamma(k) density t^{k−1} e^{−t}/Γ(k) at t (0 for t ≤ 0, t = ∞ and NaN; k > 0).
///
/// **Method**: below k = 10, the exponent (k − 1) ln t − t − ln Γ(k) directly (its terms are
/// at most ~|ln t| k, small). From k = 10 the saddle-point form of Loader (2000, *Fast and
/// accurate computation of binomial probabilities*), with x = t/k:
/// ln p = −½ ln(2πk) − R(k) − ln x − k·b(x), b(x) = x − 1 − ln x ≥ 0 (R the
/// [`stirling_remainder`]); b = (1 − x)v + 2v Σ_{j≥1} v^{2j}/(2j + 1), v = (1 − x)/(1 + x),
/// where |v| < 0.5 (Loader's `bd0`: no cancellation near the peak), else directly (there
/// x − 1 and ln x differ by at least a factor 2). The direct exponent at large k is a
/// difference of terms of size
/// k ln k that cancel to O(1): at k = 10⁶ it lost 9 digits (the inverse-Gamma superposition
/// identity of Student-T γ = 10⁶ at 3.7e-10); here each term is small or relatively exact.
///
/// **Accuracy** against mpmath across the peak and its tails (k from 0.3 to 10⁹, tests.rs):
/// relative error within 2ε(1 + |ln p|) from k = 10 (the rounding of the exponent, the
/// density's own conditioning in t), 2ε(1 + |k − 1||ln t| + t + |ln Γ(k)|) below (the
/// direct exponent's terms; ≤ 5e-15 at the peak).
pub fn gamma_pdf(k: f64, t: f64) -> f64 {
    if !(t > 0.0 && t < f64::INFINITY) {
        return 0.0;
    }
    if k < 10.0 {
        return ((k - 1.0) * t.ln() - t - ln_gamma(k)).exp();
    }
    let x = t / k;
    // 1 − x from k − t (exact where t is within a factor 2 of k): x's own rounding, times
    // k(1 − 1/x), would otherwise cost ε|t − k| in ln p near the peak.
    let d = (k - t) / k;
    let v = d / (2.0 - d);
    // (|v| < 0.5: the series' terms fall by v² ≤ 1/4 each, 17 digits in at most 28 terms;
    // beyond it the direct b cancels by at most a factor 2.2, at x = 3.)
    let b = if v.abs() < 0.5 {
        let v2 = v * v;
        let mut e = 2.0 * v;
        let mut s = d * v;
        for j in 1..40 {
            e *= v2;
            let next = s + e / f64::from(2 * j + 1);
            if next == s {
                break;
            }
            s = next;
        }
        s
    } else {
        x - 1.0 - x.ln()
    };
    (-0.5 * (2.0 * std::f64::consts::PI * k).ln() - stirling_remainder(k) - x.ln() - k * b).exp()
}

/// B(1 + x, 1 + y) = Γ(1 + x) Γ(1 + y)/Γ(2 + x + y) = ∫₀¹ c^x (1 − c)^y dc, Euler's beta
/// function shifted by one: the height-correlated masking-shadowing of a transmitted path,
/// x = Λ(wo), y = Λ(wi) ([`crate::bsdf::Masking::CorrelatedBeta`]).
///
/// Domain x, y ∈ [0, ∞] (NaN outside it, and for NaN): the value lies in [0, 1], is 1 at
/// x = y = 0, 1/(1 + x) at y = 0, and 0 where x or y is ∞ or where it underflows.
///
/// **Method** (the split of TOMS 708's and R's `lbeta`), with p = 1 + min(x, y) ≤
/// q = 1 + max(x, y): below q = 10 the product Γ(p)Γ(q)/Γ(p + q) (Cephes' Γ; Γ(p + q) <
/// Γ(20), no overflow). Above, ln Γ(q) − ln Γ(p + q) by Stirling's series, written so that
/// nothing large cancels (ln Γ differences of huge arguments, as `ln_gamma(p) + ln_gamma(q)
/// − ln_gamma(p + q)`, lose everything: B(1 + 1e300, 1) = 1e-300 would come out as 1):
/// with s = p/(p + q) and R the [`stirling_remainder`],
///
/// * p < 10: ln B = ln Γ(p) + p − p ln(p + q) + (q − ½) ln(1 − s) + R(q) − R(p + q);
/// * p ≥ 10: ln B = ln √(2π) − ½ ln q + (p − ½) ln s + q ln(1 − s) + R(p) + R(q) − R(p + q);
///
/// p + q and its logarithm formed from q and p/q (no overflow up to x, y = f64::MAX).
///
/// **Accuracy**: relative error within 4ε(1 + |ln B|) against mpmath (tests.rs: x, y over
/// [0, 1e300], both branches and both sides of q = 10), the rounding of ln B itself (the
/// conditioning of B in x, y is of the same size).
pub fn beta_1p(x: f64, y: f64) -> f64 {
    // (NaN fails both tests.)
    if !(x >= 0.0 && y >= 0.0) {
        return f64::NAN;
    }
    let (p, q) = (1.0 + x.min(y), 1.0 + x.max(y));
    if q == f64::INFINITY {
        return 0.0;
    }
    // (Below 10 Γ(p + q) < Γ(20) ≈ 1.2e17 and Cephes' Γ is good to a few ulp; above, the
    // seven terms of Stirling's remainder are good to 3e-17.)
    if q < 10.0 {
        // (B ≤ B(1, 1) = 1 for p, q ≥ 1, kept through rounding: none was seen above 1 on a
        // dense grid near 0, but the bound is the contract.)
        return (gamma(p) * gamma(q) / gamma(p + q)).min(1.0);
    }
    let r = p / q;
    let s = r / (1.0 + r);
    let ln_pq = q.ln() + r.ln_1p();
    // (R(∞) = 0 where p + q overflows.)
    let rem_pq = stirling_remainder(q * (1.0 + r));
    let ln_b = if p < 10.0 {
        ln_gamma(p) + p - p * ln_pq + (q - 0.5) * (-s).ln_1p() + stirling_remainder(q) - rem_pq
    } else {
        LN_SQRT_2PI - 0.5 * q.ln()
            + (p - 0.5) * s.ln()
            + q * (-s).ln_1p()
            + stirling_remainder(p)
            + stirling_remainder(q)
            - rem_pq
    };
    // (ln B < ln B(1, 10) = −ln 10 here: no clamp needed.)
    ln_b.exp()
}

/// Regularised lower and upper incomplete gamma P(a, x), Q(a, x) (Cephes `igam`, `igamc`).
#[inline]
pub fn inc_gamma(a: f64, x: f64) -> (f64, f64) {
    (
        spec_math::cephes64::igam(a, x),
        spec_math::cephes64::igamc(a, x),
    )
}

/// ln K_ν(z) for real ν and z > 0: the modified Bessel function of the second kind of any real
/// order (no Rust crate has it), from K_ν(z) = ∫₀^∞ e^{−z cosh t} cosh(νt) dt by the
/// trapezoidal rule on the whole line (the integrand is even and entire in t, so the rule
/// converges exponentially: with step h ≤ min(¼, w/2), w = (ν² + z²)^{−¼} the width of the
/// peak at sinh t* = |ν|/z, the error terms e^{−π²/h} and e^{−2π²w²/h²} are below 1e-17).
/// Summed in logarithms from the peak (no overflow for large ν or small z), one exponential a
/// node (cosh t − 1 of the nodes by a recurrence on e^t − 1: faster than libm's cosh, exp
/// and ln_1p at each node, BENCHMARKS.md, and the same values to the last digits). cosh t − 1 is
/// formed without cancellation: as cosh t − cosh t*, above z ~ 1e16 it rounded to 0 at
/// every node of the narrow peak, the terms never fell and the sum ran to its cap of 10⁵
/// nodes (the Bessel-K visible-normal warp's quadrature nodes in the far tail of P22 met
/// that). Relative accuracy
/// 3(1e-15 + ε(|ln K| + z)): the rounding of ln K itself and the conditioning of e^{−z}
/// (tests/special.rs, against mpmath over ν ∈ [0, 100], z ∈ [5e-324, 1e4]). Below
/// z = 2e-150 the series' leading terms instead ([`ln_xnu_bessel_k_small`]; subnormal z
/// included, where e^{t*} would overflow).
pub fn ln_bessel_k(nu: f64, z: f64) -> f64 {
    if z.is_nan() || nu.is_nan() {
        return f64::NAN;
    }
    if z <= 0.0 {
        return f64::INFINITY;
    }
    if z == f64::INFINITY {
        return f64::NEG_INFINITY;
    }
    let nu = nu.abs();
    if z <= 2e-150 {
        // The series' leading terms (ln_xnu_bessel_k_small, relative error below 1e-150
        // here): the peak sits at t* = asinh(ν/z) > 345, where e^t overflows past z ~ 1e-306
        // (subnormal z), and the sum would walk ~4t* nodes to it.
        let ln_x = z.ln() - std::f64::consts::LN_2;
        let ln_xnu_k = if nu >= 0.5 {
            ln_gamma(nu) - std::f64::consts::LN_2
        } else {
            ln_xnu_bessel_k_small(nu, ln_x)
        };
        return ln_xnu_k - nu * ln_x;
    }
    let t_star = (nu / z).asinh();
    let w = (nu * nu + z * z).powf(-0.25);
    let h = (0.5 * w).min(0.25);
    // The peak, φ(t*) with φ(t) = −z cosh t + νt + ln((1 + e^{−2νt})/2) (a scale only: it
    // cancels, so its own rounding does not matter).
    let peak = -z * t_star.cosh() + nu * t_star + (-2.0 * nu * t_star).exp().ln_1p()
        - std::f64::consts::LN_2;
    // Terms e^{φ(t_k) − peak} = e^{(−z − peak) − z c_k + ν t_k} (1 + g_k)/2 with
    // c_k = cosh t_k − 1 = e_k²/(2(1 + e_k)), e_k = e^{t_k} − 1, and g_k = e^{−2ν t_k}: one
    // exponential a term. e_k by e_{k+1} = e_k + e_1 + e_k e_1 (positive terms: ~ε a step),
    // anchored by libm's expm1 every 8 steps; g_k by products (it is only added to 1).
    let base = -z - peak;
    let e1 = h.exp_m1();
    let q = (-2.0 * nu * h).exp();
    let (mut e, mut g) = (0.0f64, 1.0f64);
    let mut sum = 0.5 * base.exp();
    let mut k = 1u32;
    loop {
        let t = k as f64 * h;
        e = if k.is_multiple_of(8) {
            t.exp_m1()
        } else {
            e + e1 + e * e1
        };
        g *= q;
        // (e·(e/…): e² would overflow past t ≈ 354.)
        let c = e * (e / (2.0 * (1.0 + e)));
        let d = base - z * c + nu * t;
        sum += d.exp() * (0.5 + 0.5 * g);
        if t > t_star && d < -41.5 {
            break;
        }
        k += 1;
        if k > 100_000 {
            break;
        }
    }
    peak + (h * sum).ln()
}
