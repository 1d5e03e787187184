//! Elementary functions in arithmetic only: e^x, e^x − 1, ln x and ln(1 + x) from a few bit
//! operations and a polynomial, with no call into libm. They inline and vectorise: the
//! slice kernels ([`super::batch`]) take their exponential from here. In scalar code they
//! are slower than glibc's table-driven exp and ln (per call in a loop of independent
//! arguments, and more so on a dependency chain), but faster than its ln_1p and exp_m1
//! (BENCHMARKS.md): the D·cos samplers' exponential variates use [`ln_1p`].
//! `exp2_256` (crate-private) trades accuracy for speed where 1e-7 is asked (5e-10; a table
//! and a quadratic): the fitted Λ tables' exponential.
//!
//! * [`exp`] and [`exp_m1`]: x = n ln 2 + r, n = round(x log₂e), |r| ≤ ln 2/2, and the
//!   Taylor series of e^r to r¹³ (remainder below 4e-18). [`exp`] takes it by one Horner
//!   chain and multiplies by 2ⁿ. [`exp_m1`] takes p = e^r − 1 in even and odd powers (two
//!   short chains side by side) and returns 2ⁿp + (2ⁿ − 1), without cancellation (2ⁿ − 1 is
//!   exact, and at n = 0 it is p itself). The one chain is what the slice kernels want: the
//!   split form, tried there, made the Beckmann D slice slower (it no longer vectorised as
//!   well; BENCHMARKS.md).
//! * [`ln`] and [`ln_1p`]: x = 2ᵏ m with m ∈ [√½, √2) from the bits, f = m − 1 (exact),
//!   s = f/(2 + f), ln m = 2 atanh s = 2s + sR, R = 2s²/3 + … + 2s¹⁸/19 (|s| ≤ 0.172: the
//!   first omitted term is below 1e-17), arranged as f − (f²/2 − s(f²/2 + R)) so that the
//!   leading term is the exact f; ln x = k ln 2 + ln m with ln 2 split in two, so k ln 2
//!   carries no rounding. ln(1 + x) rounds 1 + x to v and adds the rounding back as
//!   (x − (v − 1))/v.
//!
//! Accuracy (tests/fast.rs, against libm over the whole ranges): [`exp`], [`exp_m1`] and
//! [`ln_1p`] within 3e-16 relative (2.2e-16 to 2.7e-16 measured); [`ln`] within
//! 2.3e-16 (1 + |ln x|) absolute, so within a few ulps relative away from x = 1 and within
//! 3e-16 relative near it.

/// 1.5·2^52: adding it rounds to an integer held in the low mantissa bits.
const MAGIC: f64 = 6_755_399_441_055_744.0;
/// ln 2 in two parts; the high part has 32 significant bits, so n · LN2_HI is exact for
/// |n| < 2^21.
const LN2_HI: f64 = 6.931_471_803_691_238e-1;
const LN2_LO: f64 = 1.908_214_929_270_587_7e-10;

/// 1/k! for k = 0..=13.
const INV_FACT: [f64; 14] = {
    let mut c = [1.0; 14];
    let mut k = 1;
    while k < 14 {
        c[k] = c[k - 1] / k as f64;
        k += 1;
    }
    c
};

/// 2/(2k + 1) for k = 0..=9: ln m = s Σ 2 s^{2k}/(2k + 1).
const ATANH: [f64; 10] = {
    let mut c = [0.0; 10];
    let mut k = 0;
    while k < 10 {
        c[k] = 2.0 / (2 * k + 1) as f64;
        k += 1;
    }
    c
};

/// (2ⁿ, e^r − 1) with x = n ln 2 + r, for x clamped to [−708, 709] (2ⁿ stays normal).
#[inline(always)]
fn exp_parts(x: f64) -> (f64, f64) {
    let (t, r) = reduce(x);
    let r2 = r * r;
    // Σ_{k=1}^{13} r^k/k! = r Σ_j r^{2j}/(2j+1)! + r² Σ_j r^{2j}/(2j+2)!.
    let c = &INV_FACT;
    let odd = ((((c[13] * r2 + c[11]) * r2 + c[9]) * r2 + c[7]) * r2 + c[5]) * r2 + c[3];
    let even = (((c[12] * r2 + c[10]) * r2 + c[8]) * r2 + c[6]) * r2 + c[4];
    let p = r + (r2 * (c[2] + r * odd) + r2 * r2 * even);
    (scale(t), p)
}

/// e^x for x ∈ [−708, 709], within 3e-16 relative. Outside that range the result is e^{−708}
/// or e^{709} (the argument is clamped), and callers select; NaN gives NaN.
#[inline(always)]
pub fn exp(x: f64) -> f64 {
    let (t, r) = reduce(x);
    // Σ_{k≤13} r^k/k! by Horner on the reciprocal factorials.
    let mut p = INV_FACT[13];
    let mut k = 13;
    while k > 0 {
        k -= 1;
        p = p * r + INV_FACT[k];
    }
    p * scale(t)
}

/// x clamped to [−708, 709] (so that 2ⁿ stays normal) as n ln 2 + r: (t, r), where t holds
/// n in its low mantissa bits ([`scale`] makes 2ⁿ of it).
#[inline(always)]
fn reduce(x: f64) -> (f64, f64) {
    let x = x.clamp(-708.0, 709.0);
    let t = x * std::f64::consts::LOG2_E + MAGIC;
    let n = t - MAGIC;
    (t, (x - n * LN2_HI) - n * LN2_LO)
}

/// 2ⁿ from [`reduce`]'s t: its low bits hold n + 2^51, and (n + 1023) lands in the exponent
/// field.
#[inline(always)]
fn scale(t: f64) -> f64 {
    f64::from_bits(t.to_bits().wrapping_add(1023) << 52)
}

/// 2^(j/256) for j = 0..256, each by the Taylor series of e^(j ln 2/256) in const arithmetic
/// (the unit test below holds every entry within 2 ulps of libm's `exp2`).
const EXP2_256THS: [f64; 256] = {
    let mut t = [1.0; 256];
    let mut j = 1;
    while j < 256 {
        let x = j as f64 * (std::f64::consts::LN_2 / 256.0);
        // 1 + x(1 + x/2(1 + x/3(…))) from the inside (x < 0.7: the 25th term is below
        // 1e-26); the outermost steps, near 1, carry the rounding.
        let (mut p, mut k) = (1.0, 25);
        while k > 0 {
            p = 1.0 + p * x / k as f64;
            k -= 1;
        }
        t[j] = p;
        j += 1;
    }
    t
};

/// 2^(y/256) for y ∈ [−1022·256, 1023·256] within 5e-10 relative; crate-private, as it does
/// not check its range (outside it the exponent bits wrap: garbage, not 0 or ∞; a clamp
/// cost a measurable share of a fitted Λ, BENCHMARKS.md): the fitted Λ tables'
/// exponential ([`super::fitted`], which holds 256 log₂ Λ, asks for 1e-7 and keeps its
/// underflowed rows at 2^−1000). With k = round(y) (the magic-number addition, not libm's
/// `round`, which baseline x86-64 calls) and r = y − k ∈ [−½, ½]: 2^(y/256) =
/// 2^⌊k/256⌋ · 2^((k mod 256)/256) · e^(r ln 2/256), the middle factor from a table of 256
/// (2 KiB), the power of two added to its exponent bits, the last 1 + x + x²/2 (|x| ≤ 0.00136:
/// the remainder is below x³/6 = 4.2e-10). Its chain is two multiply-adds and a table load,
/// against [`exp`]'s thirteen and libm's call, which makes a fitted Λ faster
/// (BENCHMARKS.md).
#[inline(always)]
pub(crate) fn exp2_256(y: f64) -> f64 {
    const C1: f64 = std::f64::consts::LN_2 / 256.0;
    const C2: f64 = C1 * C1 / 2.0;
    let t = y + MAGIC;
    let bits = t.to_bits();
    // (Exact: y and k are multiples of y's ulp, and |r| ≤ ½.)
    let r = y - (t - MAGIC);
    // The low bits of t hold 2^51 + k, so (bits >> 8) holds 2^43 + ⌊k/256⌋: shifted into the
    // exponent field it adds ⌊k/256⌋ to the exponent of the table's entry (the bits above
    // shift out).
    let scaled = f64::from_bits(
        EXP2_256THS[(bits & 255) as usize]
            .to_bits()
            .wrapping_add((bits >> 8) << 52),
    );
    scaled * (1.0 + r * (C1 + r * C2))
}

/// e^x − 1 for x ≤ 709, within 3e-16 relative (also for tiny x); −1 below −708 (where it
/// is −1 to double precision); NaN gives NaN.
#[inline(always)]
pub fn exp_m1(x: f64) -> f64 {
    let (scale, p) = exp_parts(x);
    scale * p + (scale - 1.0)
}

/// ln x for normal x > 0 (x ≥ 2^−1022, finite), within 2.3e-16 (1 + |ln x|) absolute.
/// Any other x (0, subnormal, negative, ∞, NaN) takes libm's `ln` out of line.
#[inline(always)]
pub fn ln(x: f64) -> f64 {
    if !(f64::MIN_POSITIVE..f64::INFINITY).contains(&x) {
        return ln_special(x);
    }
    ln_normal(x)
}

/// [`ln`] without the check: x must be positive, normal and finite.
#[inline(always)]
pub(crate) fn ln_normal(x: f64) -> f64 {
    // The bits of √½: x = 2ᵏ m with m ∈ [√½, √2) (k from the exponent of x/√½).
    const SQRT_HALF_BITS: i64 = 0x3FE6_A09E_667F_3BCD;
    let ix = x.to_bits() as i64;
    let k = (ix - SQRT_HALF_BITS) >> 52;
    let m = f64::from_bits((ix - (k << 52)) as u64);
    let f = m - 1.0;
    let s = f / (2.0 + f);
    let s2 = s * s;
    let c = &ATANH;
    // Σ_{k≥1} 2 s^{2k}/(2k+1), in s⁴ for two chains side by side.
    let s4 = s2 * s2;
    let a = (((c[9] * s4 + c[7]) * s4 + c[5]) * s4 + c[3]) * s4 + c[1];
    let b = ((c[8] * s4 + c[6]) * s4 + c[4]) * s4 + c[2];
    let r = s2 * (a + s2 * b);
    // ln m = 2s + sR = f − (f²/2 − s(f²/2 + R)) (as 2s = f − sf): f is exact, and the
    // rounding of s only reaches the terms that are a fraction f/2 of f.
    let hfsq = 0.5 * f * f;
    let k = k as f64;
    k * LN2_HI - ((hfsq - (s * (hfsq + r) + k * LN2_LO)) - f)
}

#[cold]
#[inline(never)]
fn ln_special(x: f64) -> f64 {
    x.ln()
}

/// ln(1 + x) for x > −1, within 3e-16 relative; −∞ at −1, NaN below, and libm's `ln_1p`
/// out of line where 1 + x is not normal and finite.
#[inline(always)]
pub fn ln_1p(x: f64) -> f64 {
    let v = 1.0 + x;
    if !(f64::MIN_POSITIVE..f64::INFINITY).contains(&v) {
        return ln_1p_special(x);
    }
    // v = 1 + x − δ with δ = (v − 1) − x (v − 1 is exact); ln(1 + x) = ln v + δ'/v,
    // δ' = x − (v − 1), to first order (δ'/v is below an ulp of v).
    ln_normal(v) + (x - (v - 1.0)) / v
}

#[cold]
#[inline(never)]
fn ln_1p_special(x: f64) -> f64 {
    x.ln_1p()
}

#[cfg(test)]
mod tests {
    use super::exp2_256;

    /// [`exp2_256`] against libm's `exp2` over its whole range, relative (the bound its docs
    /// state); at integer y (r = 0) it is its table's entry times a power of two, so there
    /// every entry is checked to 2 ulps.
    #[test]
    fn exp2_256_matches_libm() {
        let rel = |got: f64, want: f64| ((got - want) / want).abs();
        let (mut worst, mut entries) = (0.0f64, 0.0f64);
        let mut y = -1022.0 * 256.0;
        while y < 1023.0 * 256.0 {
            worst = worst.max(rel(exp2_256(y), (y / 256.0).exp2()));
            y += 0.123_456_7;
        }
        for j in -512..512 {
            let y = j as f64;
            entries = entries.max(rel(exp2_256(y), (y / 256.0).exp2()));
        }
        // Half-way points of k's rounding, and both ends.
        for y in [-1022.0 * 256.0, 1023.0 * 256.0, 0.5, -0.5, 255.5, -255.5] {
            worst = worst.max(rel(exp2_256(y), (y / 256.0).exp2()));
        }
        assert!(worst <= 5e-10, "{worst}");
        assert!(entries <= 2.0 * f64::EPSILON, "{entries}");
    }
}
