//! Fast paths for renderers: GGX and Beckmann D, Λ, G1, G2 and GGX visible-normal sampling, in
//! f64 and f32 ([`Real`]), at the cost of the textbook formulas but without their
//! cancellations. No parameter validation (the caller owns α > 0); the exact, validated paths
//! of [`crate::Ggx`] and [`crate::Beckmann`] stay the reference.
//!
//! Accuracy (tests/fast.rs, against the exact f64 paths over u ∈ [1e-3, 1], α ∈ [1e-3, 2]):
//! GGX D, Λ, G1 ≤ 1e-14 relative in f64 and ≤ 1e-6 in f32; Beckmann D ≤ 1e-12 (its exponent
//! is not formed in double-double) and Λ ≤ 1e-12 in f64 where Λ > 1e-300; f32 ≤ 2e-5 while the
//! exponent of D is below 80 (beyond it single precision cannot hold e^{−x} to that accuracy).

use std::ops::{Add, Div, Mul, Neg, Sub};

pub mod batch;
pub mod double_ggx;
pub mod exponential;
pub mod fit;
pub mod gtr;
#[rustfmt::skip]
mod tables;

/// √π
const SQRT_PI: f64 = 1.772_453_850_905_516;

/// σ(u) on [−1, 1] from Λ on (0, 1]: u(1 + Λ(u)) for u > 0, |u| Λ(|u|) for u < 0 (Λ(u)u = σ(−u)),
/// σ(0) + u/2 near u = 0 (where uΛ(u) → σ(0) = `s0` but 0 · ∞ would be NaN). NaN stays NaN.
#[inline(always)]
fn sigma_from_lambda(u: f64, s0: f64, lambda: impl Fn(f64) -> f64) -> f64 {
    // Below 1e-150, σ(u) = σ(0) + u/2 + O(u²) (σ(u) − σ(−u) = u) is exact to double precision,
    // and uΛ(u) would overflow in Λ first.
    if u.abs() < 1e-150 {
        s0 + 0.5 * u
    } else if u > 0.0 {
        let u = u.min(1.0);
        u + u * lambda(u)
    } else if u < 0.0 {
        let v = (-u).min(1.0);
        v * lambda(v)
    } else {
        u
    }
}

/// The floating-point operations the fast paths need; implemented for f32 and f64.
pub trait Real:
    Copy
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    const ZERO: Self;
    const ONE: Self;
    const HALF: Self;
    const PI: Self;
    /// 1/√π
    const FRAC_1_SQRT_PI: Self;
    /// Beckmann Λ: from this a on, the erfc continued fraction (cheaper and exact) replaces
    /// the difference e^{−a²}/(a√π) − erfc a (which loses ~2a² ulps).
    const CF_FROM: Self;
    /// e^{−x} is 0 in this precision beyond this x.
    const EXP_ZERO: Self;
    /// Depth of that continued fraction (error below the precision from CF_FROM on).
    const CF_DEPTH: usize;
    fn from_usize(n: usize) -> Self;
    /// Widening to f64 (exact).
    fn to_f64(self) -> f64;
    /// Rounding from f64.
    fn from_f64(x: f64) -> Self;
    fn sqrt(self) -> Self;
    fn exp(self) -> Self;
    fn erfc(self) -> Self;
    fn sin_cos(self) -> (Self, Self);
    fn max(self, o: Self) -> Self;
}

macro_rules! real {
    ($t:ty, $erfc:path, $from:expr, $depth:expr, $zero:expr) => {
        impl Real for $t {
            const CF_FROM: Self = $from;
            const CF_DEPTH: usize = $depth;
            const EXP_ZERO: Self = $zero;
            #[inline(always)]
            fn from_usize(n: usize) -> Self {
                n as $t
            }
            #[inline(always)]
            fn to_f64(self) -> f64 {
                self as f64
            }
            #[inline(always)]
            fn from_f64(x: f64) -> Self {
                x as $t
            }
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const HALF: Self = 0.5;
            const PI: Self = std::f64::consts::PI as $t;
            const FRAC_1_SQRT_PI: Self = 0.564_189_583_547_756_3;
            #[inline(always)]
            fn sqrt(self) -> Self {
                <$t>::sqrt(self)
            }
            #[inline(always)]
            fn exp(self) -> Self {
                <$t>::exp(self)
            }
            #[inline(always)]
            fn erfc(self) -> Self {
                $erfc(self)
            }
            #[inline(always)]
            fn sin_cos(self) -> (Self, Self) {
                <$t>::sin_cos(self)
            }
            #[inline(always)]
            fn max(self, o: Self) -> Self {
                <$t>::max(self, o)
            }
        }
    };
}
// f64: depth 20 from a = 4 gives < 1e-15 (checked against mpmath when it was chosen: 4e-13 at
// depth 16, 5e-17 at depth 24); f32: depth 12 from a = 2.5 gives < 1e-7.
real!(f64, libm::erfc, 4.0, 20, 745.2);
real!(f32, libm::erfcf, 2.5, 12, 103.98);

/// GGX (Trowbridge–Reitz).
pub mod ggx {
    use super::Real;

    /// D(u) = α²/(π ((1 − u²) + u²α²)²); 0 for u ≤ 0. 1 − u² is (1 − u)(1 + u), exact enough
    /// that the near-normal peak keeps full relative accuracy in f32.
    #[inline]
    pub fn d<F: Real>(u: F, alpha: F) -> F {
        if u <= F::ZERO {
            return F::ZERO;
        }
        let a2 = alpha * alpha;
        let t = (F::ONE - u) * (F::ONE + u) + u * u * a2;
        a2 / (F::PI * t * t)
    }

    /// Λ(u) = s/(2(1 + √(1+s))), s = α² tan²θ, for 0 < u ≤ 1, written with u² multiplied
    /// through as α²(1−u²)/(2(u² + u√(u² + α²(1−u²)))): one square root and one division, and
    /// no cancellation.
    #[inline]
    pub fn lambda<F: Real>(u: F, alpha: F) -> F {
        let t = alpha * alpha * ((F::ONE - u) * (F::ONE + u));
        let u2 = u * u;
        t / ((F::ONE + F::ONE) * (u2 + u * (u2 + t).sqrt()))
    }

    /// G1(u) = 2/(1 + √(1 + s)) = 2u/(u + √(u² + α²(1−u²))).
    #[inline]
    pub fn g1<F: Real>(u: F, alpha: F) -> F {
        let t = alpha * alpha * ((F::ONE - u) * (F::ONE + u));
        (u + u) / (u + (u * u + t).sqrt())
    }

    /// Height-correlated G2 = 1/(1 + Λ(u_o) + Λ(u_i)).
    #[inline]
    pub fn g2<F: Real>(u_o: F, u_i: F, alpha: F) -> F {
        F::ONE / (F::ONE + lambda(u_o, alpha) + lambda(u_i, alpha))
    }

    /// A visible normal for the unit direction w (w.z > 0) by spherical caps (Dupuy &
    /// Benyoub 2023), anisotropic roughness (αx, αy); `u` uniform in [0, 1)².
    #[inline]
    pub fn sample_visible<F: Real>(w: [F; 3], ax: F, ay: F, u: [F; 2]) -> [F; 3] {
        let (x, y, z) = (ax * w[0], ay * w[1], w[2]);
        let inv = F::ONE / (x * x + y * y + z * z).sqrt();
        let (x, y, z) = (x * inv, y * inv, z * inv);
        let (s, c) = ((F::PI + F::PI) * u[0]).sin_cos();
        let cz = (F::ONE - u[1]) * (F::ONE + z) - z;
        let sin = (F::ONE - cz * cz).max(F::ZERO).sqrt();
        let (hx, hy, hz) = (ax * (sin * c + x), ay * (sin * s + y), cz + z);
        let inv = F::ONE / (hx * hx + hy * hy + hz * hz).sqrt();
        [hx * inv, hy * inv, hz * inv]
    }
}

/// Beckmann.
pub mod beckmann {
    use super::Real;

    /// D(u) = exp(−tan²θ/α²)/(π α² u⁴); 0 for u ≤ 0.
    #[inline]
    pub fn d<F: Real>(u: F, alpha: F) -> F {
        if u <= F::ZERO {
            return F::ZERO;
        }
        let u2 = u * u;
        let a2 = alpha * alpha;
        let x = (F::ONE - u) * (F::ONE + u) / (u2 * a2);
        // e^{−x} underflows (in f64) past 745; so does D, and u⁴ may too (0/0), so answer 0.
        if x > F::EXP_ZERO {
            return F::ZERO;
        }
        (-x).exp() / (F::PI * a2 * u2 * u2)
    }

    /// Λ(u) = (e^{−a²}/(a√π) − erfc a)/2, a = cot θ/α, for 0 < u < 1; for large a through the
    /// erfc continued fraction, without the cancellation of the textbook
    /// (erf(a) − 1)/2 + e^{−a²}/(2a√π) (complete past a ≈ 11).
    #[inline]
    pub fn lambda<F: Real>(u: F, alpha: F) -> F {
        let a = u / (alpha * ((F::ONE - u) * (F::ONE + u)).sqrt());
        let e = (-a * a).exp() * F::FRAC_1_SQRT_PI / a;
        if a < F::CF_FROM {
            return F::HALF * (e - a.erfc());
        }
        // 1 − √π a e^{a²} erfc a = k/(a + k), k = ½/(a + 1/(a + (3/2)/(a + …))) evaluated by
        // the forward recurrence of its convergents (multiply-adds and one division).
        let (mut p0, mut p1) = (F::ONE, F::ZERO); // A_{n−2}, A_{n−1}
        let (mut q0, mut q1) = (F::ZERO, F::ONE); // B_{n−2}, B_{n−1}
        for n in 1..=F::CF_DEPTH {
            let an = F::HALF * F::from_usize(n);
            let p2 = a * p1 + an * p0;
            let q2 = a * q1 + an * q0;
            (p0, p1, q0, q1) = (p1, p2, q1, q2);
        }
        let k = p1 / q1;
        F::HALF * e * (k / (a + k))
    }

    /// G1 = 1/(1 + Λ).
    #[inline]
    pub fn g1<F: Real>(u: F, alpha: F) -> F {
        F::ONE / (F::ONE + lambda(u, alpha))
    }
}
