//! Fresnel reflectance, unpolarised, as functions of cos θ = wo·wm, with spectral values as
//! `[F; N]` (RGB is N = 3; nothing allocates).
//!
//! * [`dielectric`]: exact, for a real relative index η = η_t/η_i; cos θ < 0 is the interface
//!   seen from inside (η → 1/η); 1 at total internal reflection.
//! * [`conductor`]: exact, for a complex index η + ik (pbrt-v4's `FrComplex`, Born & Wolf
//!   §13.4).
//! * [`schlick`]: F0 + (1 − F0)(1 − cos θ)⁵ (Schlick 1994).
//! * [`f82_tint`]: Hoffman's F82-tint model (Hoffman 2023, "Generalization of Adobe's Fresnel
//!   model", in *Physically Based Shading in Theory and Practice*, SIGGRAPH 2023 course; after
//!   Kutz et al. 2021): Schlick less a μ(1 − μ)⁶ with a chosen so that F at μ̄ = 1/7
//!   (θ ≈ 82°) is the tint h times Schlick's value there:
//!   a = (F0 + (1 − F0)(1 − μ̄)⁵)(1 − h)/(μ̄(1 − μ̄)⁶).
//!
//! The [`Fresnel`] trait wraps each as a value a BSDF carries.

// `!(x > 0)` is the NaN-aware test (false for NaN) on a generic `Real`, on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::fast::Real;

/// Exact unpolarised Fresnel reflectance of a dielectric interface with relative index η
/// (η_t/η_i; the side cos θ > 0 is outside), for cos θ ∈ [−1, 1]: cos θ < 0 swaps the sides.
/// 1 at and beyond the critical angle and at grazing; 0 at η = 1 (at every cos θ); in
/// [0, 1] for every finite η > 0 (1 where η or 1/η overflows).
///
/// With (η cos θt)² = η² − sin²θ formed without cancellation, as (η − 1)(η + 1) + cos²θ
/// above η = 1 and η² − (1 − cos θ)(1 + cos θ) below (the plain 1 − sin²θ/η² lost cos θt
/// near grazing at η ≈ 1: at η = 1, cos θ = 1e-8 it gave R = 1e-3, not 0); past η = 1e150
/// (1e18 in f32), where η² overflows, the ratios divided through by η. Near the critical
/// angle R has a square-root edge, which turns the rounding ε of η² − sin²θ into √ε.
#[inline]
pub fn dielectric<F: Real>(cos_i: F, eta: F) -> F {
    let (cos_i, eta) = if cos_i < F::ZERO {
        (-cos_i, F::ONE / eta)
    } else {
        (cos_i, eta)
    };
    let c = cos_i.min(F::ONE);
    if eta == F::ONE {
        return F::ZERO;
    }
    if c == F::ZERO {
        return F::ONE;
    }
    let big = F::from_f64(if F::IS_F32 { 1e18 } else { 1e150 });
    // (NaN fails every test and flows through the formulas.)
    let (r_parl, r_perp) = if eta > big {
        let e = F::ONE / eta;
        let cos_t = ((F::ONE - e) * (F::ONE + e) + (c * e) * (c * e)).sqrt();
        (
            (c - e * cos_t) / (c + e * cos_t),
            (e * c - cos_t) / (e * c + cos_t),
        )
    } else {
        let ect2 = if eta > F::ONE {
            (eta - F::ONE) * (eta + F::ONE) + c * c
        } else {
            eta * eta - (F::ONE - c) * (F::ONE + c)
        };
        // Total internal reflection (false for NaN).
        if ect2 <= F::ZERO {
            return F::ONE;
        }
        let ect = ect2.sqrt();
        let e2c = eta * eta * c;
        ((e2c - ect) / (e2c + ect), (c - ect) / (c + ect))
    };
    F::HALF * (r_parl * r_parl + r_perp * r_perp)
}

/// A complex number, for [`conductor`].
#[derive(Clone, Copy, Debug)]
struct Complex<F> {
    re: F,
    im: F,
}

impl<F: Real> Complex<F> {
    fn new(re: F, im: F) -> Self {
        Complex { re, im }
    }
    fn add(self, o: Self) -> Self {
        Complex::new(self.re + o.re, self.im + o.im)
    }
    fn sub(self, o: Self) -> Self {
        Complex::new(self.re - o.re, self.im - o.im)
    }
    fn mul(self, o: Self) -> Self {
        Complex::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }
    fn norm(self) -> F {
        self.re * self.re + self.im * self.im
    }
    /// |a/b|² = |a|²/|b|², the four parts divided by the largest first (no overflow or
    /// underflow of the squares; divided, not multiplied by 1/s, which overflows for a
    /// subnormal s); 0 where both are 0 (the limit of every ratio the reflectance takes
    /// there: an interface of index 1 seen at grazing).
    fn norm_ratio(a: Self, b: Self) -> F {
        let s = a.re.abs().max(a.im.abs()).max(b.re.abs()).max(b.im.abs());
        if s == F::ZERO {
            return F::ZERO;
        }
        if !(s < F::from_f64(f64::INFINITY)) {
            // (∞ or NaN parts: the unscaled ratio says which.)
            return a.norm() / b.norm();
        }
        let d = |z: Self| Complex::new(z.re / s, z.im / s);
        d(a).norm() / d(b).norm()
    }
    /// 1/z by Smith's algorithm (no overflow of |z|² for large z).
    fn recip_smith(self) -> Self {
        if self.re.abs() >= self.im.abs() {
            let r = self.im / self.re;
            let d = self.re + self.im * r;
            Complex::new(F::ONE / d, -r / d)
        } else {
            let r = self.re / self.im;
            let d = self.re * r + self.im;
            Complex::new(r / d, -F::ONE / d)
        }
    }
    fn scale(self, s: F) -> Self {
        Complex::new(self.re * s, self.im * s)
    }
    /// The principal square root (re ≥ 0), without cancellation.
    fn sqrt(self) -> Self {
        let r = self.norm().sqrt();
        if r == F::ZERO {
            return Complex::new(F::ZERO, F::ZERO);
        }
        let t = ((r + self.re.abs()) * F::HALF).sqrt();
        if self.re >= F::ZERO {
            Complex::new(t, self.im / (t + t))
        } else {
            let s = if self.im < F::ZERO { -t } else { t };
            Complex::new(self.im.abs() / (t + t), s)
        }
    }
}

/// Exact unpolarised Fresnel reflectance of a conductor with complex relative index η + ik,
/// for cos θ ∈ [0, 1] (clamped there; light arrives from outside): in [0, 1] and finite for
/// every finite η + ik, → 1 as |η + ik| → ∞ (the ratios are divided through by n past
/// |n| ~ 1e150, 1e18 in f32, where n² would overflow) and as |η + ik| → 0 (1 below
/// |η|, |k| < 1e-75, 1e-9 in f32, where 1 − F ≤ 4|n| is below the rounding), 0 for n = 1
/// (no interface) at every cos θ. cos²θt = 1 − sin²θ/n² is
/// formed as ((n − 1)(n + 1) + cos²θ)/n², without the cancellation that lost it near
/// grazing for n ≈ 1 (n = 1 gave F = 1 at cos θ = 1e-9).
#[inline]
pub fn conductor<F: Real>(cos_i: F, eta: F, k: F) -> F {
    let cos_i = cos_i.max(F::ZERO).min(F::ONE);
    if eta == F::ONE && k == F::ZERO {
        return F::ZERO;
    }
    // n² loses digits below |n| ~ 1e-154 (1e-19 in f32); F = 1 − O(|n|) rounds to 1 well
    // before. (Both tested apart: a NaN part is false here and flows on.)
    let tiny = F::from_f64(if F::IS_F32 { 1e-9 } else { 1e-75 });
    if eta.abs() < tiny && k.abs() < tiny {
        return F::ONE;
    }
    let n = Complex::new(eta, k);
    let sin2_i = (F::ONE - cos_i) * (F::ONE + cos_i);
    // Past |n| ~ 1e150 (1e18 in f32) n² overflows: the same ratios divided through by n,
    // with m = 1/n (F → 1 as |n| → ∞).
    let big = F::from_f64(if F::IS_F32 { 1e18 } else { 1e150 });
    if eta.abs().max(k.abs()) > big {
        let m = n.recip_smith();
        let sin2_t = m.mul(m).scale(sin2_i);
        let cos_t = Complex::new(F::ONE - sin2_t.re, -sin2_t.im).sqrt();
        let ci = Complex::new(cos_i, F::ZERO);
        let ct_m = cos_t.mul(m);
        let ci_m = m.scale(cos_i);
        let r_parl = Complex::norm_ratio(ci.sub(ct_m), ci.add(ct_m));
        let r_perp = Complex::norm_ratio(ci_m.sub(cos_t), ci_m.add(cos_t));
        return at_most_one(F::HALF * (r_parl + r_perp));
    }
    // cos θt = √(1 − sin²θi/n²) = √((n² − sin²θi)/n²), n² − sin²θi formed as the
    // dielectric's: (n − 1)(n + 1) + cos²θi for |n| ≥ 1, n² − (1 − cos θi)(1 + cos θi)
    // below.
    let n2 = n.mul(n);
    let w = if n.norm() >= F::ONE {
        Complex::new(eta - F::ONE, k)
            .mul(Complex::new(eta + F::ONE, k))
            .add(Complex::new(cos_i * cos_i, F::ZERO))
    } else {
        n2.sub(Complex::new(sin2_i, F::ZERO))
    };
    // (Smith's 1/n², no overflow of |n²|² for |n| up to the switch at 1e150.)
    let cos_t = w.mul(n2.recip_smith()).sqrt();
    let ci = Complex::new(cos_i, F::ZERO);
    let n_ci = n.scale(cos_i);
    let n_ct = n.mul(cos_t);
    let r_parl = Complex::norm_ratio(n_ci.sub(cos_t), n_ci.add(cos_t));
    let r_perp = Complex::norm_ratio(ci.sub(n_ct), ci.add(n_ct));
    at_most_one(F::HALF * (r_parl + r_perp))
}

/// A reflectance rounded past 1 brought back to 1 (each ratio |a − b|²/|a + b|² is at most 1
/// but for rounding: 1 + 4e-16 came out at n = 1e-9 (1 + i)); NaN passes through.
#[inline(always)]
fn at_most_one<F: Real>(r: F) -> F {
    if r > F::ONE {
        F::ONE
    } else {
        r
    }
}

/// Schlick's approximation F0 + (1 − F0)(1 − cos θ)⁵, cos θ clamped to [0, 1].
#[inline]
pub fn schlick<F: Real>(cos_i: F, f0: F) -> F {
    let m = F::ONE - cos_i.max(F::ZERO).min(F::ONE);
    let m2 = m * m;
    f0 + (F::ONE - f0) * (m2 * m2 * m)
}

/// μ̄ = 1/7 (cos 81.79°), where Hoffman's model pins the tint.
const MU_BAR: f64 = 1.0 / 7.0;

/// Hoffman's F82-tint model for reflectance f0 at normal incidence and tint h ∈ [0, 1] at
/// μ̄ = 1/7 (cos θ clamped to [0, 1]); h = 1 is Schlick. The result is clamped to [0, 1].
#[inline]
pub fn f82_tint<F: Real>(cos_i: F, f0: F, h: F) -> F {
    let mu = cos_i.max(F::ZERO).min(F::ONE);
    let m = F::ONE - mu;
    let m5 = m * m * m * m * m;
    let mb = 1.0 - MU_BAR;
    let mb5 = mb.powi(5);
    let a = (f0 + (F::ONE - f0) * F::from_f64(mb5)) * (F::ONE - h) / F::from_f64(MU_BAR * mb5 * mb);
    let r = f0 + (F::ONE - f0) * m5 - a * mu * m5 * m;
    // A reflectance is in [0, 1]: the model dips below 0 near μ̄ for a dark f0 and h < 1, and
    // passes 1 for h > 1; clamped as OpenPBR does (NaN passes through).
    if r < F::ZERO {
        F::ZERO
    } else if r > F::ONE {
        F::ONE
    } else {
        r
    }
}

/// A Fresnel term a BSDF carries: N channels (RGB: N = 3).
pub trait Fresnel<F: Real, const N: usize>: Clone {
    /// The reflectance per channel at cos θ = wo·wm (for a [`Dielectric`], cos θ < 0 is the
    /// inside; the other models clamp it to [0, 1]).
    fn eval(&self, cos_i: F) -> [F; N];
}

/// F = 1 in each of N channels (a perfect mirror: white-furnace tests), e.g. `One::<1>`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct One<const N: usize>;

impl<F: Real, const N: usize> Fresnel<F, N> for One<N> {
    #[inline(always)]
    fn eval(&self, _cos_i: F) -> [F; N] {
        [F::ONE; N]
    }
}

/// A dielectric's reflectance, the same in every channel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dielectric<F> {
    /// Relative index η_t/η_i.
    pub eta: F,
}

impl<F: Real, const N: usize> Fresnel<F, N> for Dielectric<F> {
    #[inline]
    fn eval(&self, cos_i: F) -> [F; N] {
        [dielectric(cos_i, self.eta); N]
    }
}

/// A conductor's exact reflectance, complex index η + ik per channel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conductor<F, const N: usize> {
    pub eta: [F; N],
    pub k: [F; N],
}

impl<F: Real, const N: usize> Fresnel<F, N> for Conductor<F, N> {
    #[inline]
    fn eval(&self, cos_i: F) -> [F; N] {
        std::array::from_fn(|c| conductor(cos_i, self.eta[c], self.k[c]))
    }
}

/// Schlick's approximation with F0 per channel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Schlick<F, const N: usize> {
    pub f0: [F; N],
}

impl<F: Real, const N: usize> Fresnel<F, N> for Schlick<F, N> {
    #[inline]
    fn eval(&self, cos_i: F) -> [F; N] {
        std::array::from_fn(|c| schlick(cos_i, self.f0[c]))
    }
}

/// Hoffman's F82-tint model, F0 and the tint h per channel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct F82Tint<F, const N: usize> {
    pub f0: [F; N],
    pub h: [F; N],
}

impl<F: Real, const N: usize> Fresnel<F, N> for F82Tint<F, N> {
    #[inline]
    fn eval(&self, cos_i: F) -> [F; N] {
        std::array::from_fn(|c| f82_tint(cos_i, self.f0[c], self.h[c]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dielectric_limits_and_symmetry() {
        // Normal incidence: ((η − 1)/(η + 1))².
        let r0: f64 = (0.5 / 2.5) * (0.5 / 2.5);
        assert!((dielectric(1.0, 1.5) - r0).abs() < 1e-16);
        assert!((dielectric(-1.0, 1.5) - r0).abs() < 1e-16);
        assert_eq!(dielectric(0.0, 1.5), 1.0);
        assert_eq!(dielectric(0.5, 1.0), 0.0);
        // Total internal reflection inside glass past the critical angle (sin θc = 1/1.5).
        assert_eq!(dielectric(-0.7, 1.5), 1.0);
        // Stokes: reflectance from outside at θi equals from inside at θt.
        let ci: f64 = 0.6;
        let st = (1.0 - ci * ci).sqrt() / 1.5;
        let ct = (1.0 - st * st).sqrt();
        assert!((dielectric(ci, 1.5) - dielectric(-ct, 1.5)).abs() < 1e-15);
    }

    #[test]
    fn conductor_reduces_to_dielectric_and_known_values() {
        for c in [0.0, 0.1, 0.5, 0.9, 1.0] {
            assert!((conductor(c, 1.5, 0.0) - dielectric(c, 1.5)).abs() < 1e-15);
        }
        // Normal incidence: ((η − 1)² + k²)/((η + 1)² + k²).
        let (n, k) = (0.2, 3.9f64);
        let r0 = ((n - 1.0) * (n - 1.0) + k * k) / ((n + 1.0) * (n + 1.0) + k * k);
        assert!((conductor(1.0, n, k) - r0).abs() < 1e-15);
        assert!((conductor(0.0, n, k) - 1.0).abs() < 1e-15);
        let f: [f32; 3] = Conductor {
            eta: [0.2f32, 0.9, 1.1],
            k: [3.9, 2.4, 2.2],
        }
        .eval(0.5);
        assert!(f.iter().all(|&x| x > 0.5 && x < 1.0));
    }

    #[test]
    fn f82_tint_pins_its_value() {
        let (f0, h) = (0.9f64, 0.7);
        let at = f82_tint(MU_BAR, f0, h);
        assert!((at - h * schlick(MU_BAR, f0)).abs() < 1e-15);
        assert_eq!(f82_tint(1.0, f0, h), f0);
        assert!((f82_tint(0.0, f0, h) - 1.0).abs() < 1e-15);
        assert!((f82_tint(0.3, f0, 1.0) - schlick(0.3, f0)).abs() < 1e-15);
    }
}
