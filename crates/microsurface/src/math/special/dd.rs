//! Minimal double-double helpers (error-free transformations with `mul_add`).
//!
//! Used where an f64 result is `exp(−x)` of a large argument: an argument of 700 with a
//! relative error of 2 ulp gives a result off by 3e-13, so the argument is formed with its
//! rounding error (`lo`) and the exponential is corrected by `exp(−hi)·(1 − lo)`.

/// A value `hi + lo` with |lo| ≤ ulp(hi)/2.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dd {
    pub hi: f64,
    pub lo: f64,
}

impl Dd {
    #[inline]
    pub fn new(x: f64) -> Self {
        Dd { hi: x, lo: 0.0 }
    }

    /// Exact product of two doubles.
    #[inline]
    pub fn mul_f(a: f64, b: f64) -> Self {
        let hi = a * b;
        // An overflowed product has no meaningful low part (fma would give inf − inf = NaN).
        let lo = if hi.is_finite() {
            a.mul_add(b, -hi)
        } else {
            0.0
        };
        Dd { hi, lo }
    }

    /// (self) × b, to about 2⁻¹⁰⁴ relative.
    #[inline]
    pub fn mul_dd(self, b: Dd) -> Self {
        let p = Dd::mul_f(self.hi, b.hi);
        let lo = p.lo + (self.hi * b.lo + self.lo * b.hi);
        Dd::fast_two_sum(p.hi, lo)
    }

    /// (self) / b.
    #[inline]
    pub fn div_dd(self, b: Dd) -> Self {
        let q = self.hi / b.hi;
        if !q.is_finite() || q == 0.0 {
            return Dd::new(q);
        }
        // r = self − q·b, computed exactly for the leading part.
        let p = Dd::mul_f(q, b.hi);
        let r = (self.hi - p.hi) - p.lo + self.lo - q * b.lo;
        Dd::fast_two_sum(q, r / b.hi)
    }

    /// √self for self > 0.
    #[inline]
    pub fn sqrt(self) -> Self {
        let s = self.hi.sqrt();
        if s == 0.0 || !s.is_finite() {
            return Dd::new(s);
        }
        let r = (-s).mul_add(s, self.hi) + self.lo;
        Dd::fast_two_sum(s, r / (2.0 * s))
    }

    /// self + b.
    #[inline]
    pub fn add_dd(self, b: Dd) -> Self {
        let s = self.hi + b.hi;
        if !s.is_finite() {
            return Dd::new(s);
        }
        let bb = s - self.hi;
        let err = (self.hi - (s - bb)) + (b.hi - bb);
        Dd::fast_two_sum(s, err + self.lo + b.lo)
    }

    /// 1 − u² exactly enough for |u| ≤ 1.
    #[inline]
    pub fn one_minus_sq(u: f64) -> Self {
        let sq = Dd::mul_f(u, u);
        let hi = 1.0 - sq.hi;
        // 1 − sq.hi is exact when sq.hi ∈ [0.5, 1] (Sterbenz); otherwise recover the error.
        let err = (1.0 - hi) - sq.hi;
        Dd::fast_two_sum(hi, -sq.lo - err)
    }

    #[inline]
    fn fast_two_sum(a: f64, b: f64) -> Self {
        let s = a + b;
        Dd {
            hi: s,
            lo: b - (s - a),
        }
    }

    /// exp(−self), with the low part applied as a first-order correction.
    #[inline]
    pub fn exp_neg(self) -> f64 {
        let e = (-self.hi).exp();
        e - e * self.lo
    }

    /// exp(−self)/d for d > 0 without a subnormal intermediate (see [`super::exp_over`]; `ln_d`
    /// gives ln d where d or e^{−self} leaves the normal range).
    #[inline]
    pub fn exp_neg_over(self, d: f64, ln_d: impl FnOnce() -> f64) -> f64 {
        let e = super::exp_over(-self.hi, d, ln_d);
        e - e * self.lo
    }
}
