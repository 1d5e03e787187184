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

use crate::math::quad::GL8;
use crate::math::real::Real;

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

/// The hemispherical average F_avg = 2∫₀¹ F(μ) μ dμ of `f` over [a, b] ⊂ [0, 1] (its share
/// 2∫_a^b f μ dμ), adaptively: 8-point Gauss–Legendre on an interval against the same on its
/// halves, bisected until the two agree within `tol` (relative to the interval's share of
/// [0, 1]) or 40 levels deep.
fn average_adaptive(f: &impl Fn(f64) -> f64, a: f64, b: f64, tol: f64) -> f64 {
    fn gl8(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
        GL8.iter()
            .map(|&(x, w)| {
                let mu = a + (b - a) * x;
                2.0 * w * (b - a) * f(mu) * mu
            })
            .sum()
    }
    fn go(f: &impl Fn(f64) -> f64, a: f64, b: f64, whole: f64, tol: f64, depth: u32) -> f64 {
        let m = 0.5 * (a + b);
        let (l, r) = (gl8(f, a, m), gl8(f, m, b));
        // (A NaN difference stops the recursion as a match does: NaN parameters are the
        // caller's to refuse.)
        if depth >= 40 || !((l + r - whole).abs() > tol * (b - a)) {
            l + r
        } else {
            go(f, a, m, l, tol, depth + 1) + go(f, m, b, r, tol, depth + 1)
        }
    }
    go(f, a, b, gl8(f, a, b), tol, 0)
}

/// The tolerance of the adaptive Fresnel averages, per unit of μ: the average errs by about
/// this (the bisection's estimate; tests below measure 1e-12 against a dense rule), far
/// below anything compensation can show (its tables interpolate to 1e-4).
const AVERAGE_TOL: f64 = 1e-12;

/// F_avg = 2∫₀¹ F(μ) μ dμ of the exact [`dielectric`] reflectance at relative index η
/// (light from the side that meets η; η > 0): the smooth interface's average reflectance,
/// which Kulla–Conty's dielectric compensation transmits the rest of. Below the critical
/// angle (η < 1: μ < μc = √(1 − η²)) F = 1 and contributes μc²; above it
/// μ = μc + (1 − μc)t² removes F's square-root edge at μc, and 8-point Gauss–Legendre on 8
/// intervals of t (32 within 5% of η = 1 and outside [0.2, 5], 128 below η = 0.05) is within
/// 1e-12 of the same on 256 intervals over η ∈ [1.0001, 100] and its reciprocals, and of
/// mpmath (30 digits) to 1e-15 at η = 1.5, 1/1.5, 2.42, 1/2.42 (tests below). NaN for NaN η.
pub fn dielectric_average(eta: f64) -> f64 {
    let mc = if eta < 1.0 {
        ((1.0 - eta) * (1.0 + eta)).sqrt()
    } else {
        0.0
    };
    // (Near η = 1 F rises only at grazing; below η = 0.2 the p ratio has a pole near t = 0,
    // at a distance of about η²/√(2(1 − μc)) ≈ η^(3/2)/√2 measured to the end of t's interval;
    // above η = 5 F's rise at grazing steepens. The counts meet 1e-12: tests below.)
    let intervals = if eta < 0.05 {
        128
    } else if (eta - 1.0).abs() < 0.05 || !(0.2..=5.0).contains(&eta) {
        32
    } else {
        8
    };
    dielectric_average_on(eta, mc, intervals)
}

/// [`dielectric_average`] on `intervals` intervals of t.
fn dielectric_average_on(eta: f64, mc: f64, intervals: usize) -> f64 {
    let h = 1.0 / intervals as f64;
    let mut f_avg = mc * mc;
    for k in 0..intervals {
        for (x, w) in GL8 {
            let t = (k as f64 + x) * h;
            let mu = mc + (1.0 - mc) * t * t;
            f_avg += 2.0 * w * h * dielectric(mu, eta) * mu * (1.0 - mc) * 2.0 * t;
        }
    }
    f_avg
}

/// F_avg = 2∫₀¹ F(μ) μ dμ of the exact [`conductor`] reflectance at η + ik, computed in
/// f64. F(μ) is analytic in μ but for the branch points ±μb, μb = √(1 − (η + ik)²), of
/// cos θt and the poles of the p ratio at μp = −1/√(1 + (η + ik)²) (near μ = 0 for a metal,
/// |μp| ≈ 1/|η + ik|), and their conjugates. So Gauss–Legendre with n points converges like
/// ρ^(−2n), ρ the smaller Bernstein ellipse of [0, 1] through μb or μp: n = ⌈15/ln ρ⌉
/// rounded up to a multiple of 8 (ρ^(−2n) ≤ 1e-13; 24 to 32 points for gold, copper and
/// aluminium in RGB, ρ = 1.76 to 3.3), while that is at most 64; else (an index near the real axis, where F has the
/// critical angle's edge or its smoothed trace at Re μb) the adaptive rule, split at Re μb.
/// Within 1e-11 of a dense reference over η ∈ [0.02, 20], k ∈ {0} ∪ [1e-4, 20] (tests below).
/// The last four indices a thread averaged are remembered (a lookup, then).
pub fn conductor_average(eta: f64, k: f64) -> f64 {
    // A texture varies α at every shading point while the metal stays: the last few indices
    // a thread averaged are kept (four: RGB's three channels and one more), so that a
    // compensated conductor built per call pays the rule once per metal, not per material.
    thread_local! {
        static RECENT: std::cell::Cell<[(u64, u64, f64); 4]> =
            const { std::cell::Cell::new([(u64::MAX, u64::MAX, f64::NAN); 4]) };
    }
    let key = (eta.to_bits(), k.to_bits());
    let recent = RECENT.with(|r| r.get());
    if let Some(&(_, _, v)) = recent.iter().find(|e| (e.0, e.1) == key) {
        return v;
    }
    let v = conductor_average_rule(eta, k);
    RECENT.with(|r| {
        let mut e = r.get();
        e.rotate_right(1);
        e[0] = (key.0, key.1, v);
        r.set(e);
    });
    v
}

/// [`conductor_average`]'s rule, uncached.
fn conductor_average_rule(eta: f64, k: f64) -> f64 {
    let f = |mu: f64| conductor(mu, eta, k);
    // The square of the Bernstein parameter of a point p for [0, 1]: |z ± √(z² − 1)|²,
    // z = 2p − 1, the larger (their product is 1; `norm` is the squared modulus).
    let rho2 = |p: Complex<f64>| {
        let z = Complex::new(2.0 * p.re - 1.0, 2.0 * p.im);
        let root = z.mul(z).sub(Complex::new(1.0, 0.0)).sqrt();
        z.add(root).norm().max(z.sub(root).norm())
    };
    // 1 − (η + ik)² = (1 − η² + k²) − 2iηk; 1 + (η + ik)² = (1 + η² − k²) + 2iηk.
    let mub = Complex::new(1.0 - eta * eta + k * k, -2.0 * eta * k).sqrt();
    let mup = Complex::new(1.0 + eta * eta - k * k, 2.0 * eta * k)
        .sqrt()
        .recip_smith()
        .scale(-1.0);
    let r2 = rho2(mub).min(rho2(mup));
    // n = 15/ln ρ = 30/ln ρ²; ρ at 1 (a singular point on [0, 1]) or below it by rounding,
    // and NaN, fall to the adaptive rule.
    let n = (30.0 / r2.ln()).ceil();
    if r2 > 1.0 && n <= 64.0 {
        let n = (n.max(8.0) as usize).div_ceil(8) * 8;
        if let Some(rule) = crate::math::quad::gauss_legendre(n) {
            return rule.iter().map(|&(x, w)| 2.0 * w * f(x) * x).sum();
        }
    }
    // (Past |η + ik| ~ 1e154 the squares overflow and μb is NaN; F is 1 but for a layer
    // of width ~1/|η + ik| at grazing, which the adaptive rule on [0, 1] finds.)
    let s = if mub.re.is_finite() {
        mub.re.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let left = if s > 0.0 {
        average_adaptive(&f, 0.0, s, AVERAGE_TOL)
    } else {
        0.0
    };
    left + average_adaptive(&f, s, 1.0, AVERAGE_TOL)
}

/// [`Fresnel::average`]'s default: 8-point Gauss–Legendre on 16 intervals of `eval`.
fn quadrature_average<F: Real, const N: usize>(eval: impl Fn(F) -> [F; N]) -> [f64; N] {
    let mut f_avg = [0.0; N];
    for k in 0..16 {
        for (x, w) in GL8 {
            let mu = (k as f64 + x) / 16.0;
            let f = eval(F::from_f64(mu));
            for c in 0..N {
                f_avg[c] += 2.0 * w / 16.0 * f[c].to_f64() * mu;
            }
        }
    }
    f_avg
}

/// The F82-tint model's average in closed form, F0 + (1 − F0)/21 − a/126, where its clamp to
/// [0, 1] is inactive (checked at μ = 0, 1 and its critical points: r′(μ) =
/// −(1 − μ)⁴(5(1 − F0) + a(1 − μ)(1 − 7μ))); `None` where it is active.
fn f82_tint_average(f0: f64, h: f64) -> Option<f64> {
    let mb = 1.0 - MU_BAR;
    let mb5 = mb.powi(5);
    let a = (f0 + (1.0 - f0) * mb5) * (1.0 - h) / (MU_BAR * mb5 * mb);
    let r = |mu: f64| {
        let m = 1.0 - mu;
        f0 + (1.0 - f0) * m.powi(5) - a * mu * m.powi(6)
    };
    let inside = |v: f64| (0.0..=1.0).contains(&v);
    let mut ok = inside(r(0.0)) && inside(r(1.0));
    if a != 0.0 {
        // 7aμ² − 8aμ + a + 5(1 − F0) = 0.
        let disc = 64.0 * a * a - 28.0 * a * (a + 5.0 * (1.0 - f0));
        if disc >= 0.0 {
            for sign in [-1.0, 1.0] {
                let mu = (8.0 * a + sign * disc.sqrt()) / (14.0 * a);
                if (0.0..=1.0).contains(&mu) {
                    ok &= inside(r(mu));
                }
            }
        }
    }
    (ok && a.is_finite()).then(|| f0 + (1.0 - f0) * SCHLICK_AVG - a / 126.0)
}

/// The closed forms of the Schlick average: 2∫₀¹ (1 − μ)⁵ μ dμ = 2B(2, 6) = 1/21.
const SCHLICK_AVG: f64 = 1.0 / 21.0;

/// A Fresnel term a BSDF carries: N channels (RGB: N = 3).
pub trait Fresnel<F: Real, const N: usize>: Clone {
    /// The reflectance per channel at cos θ = wo·wm (for a [`Dielectric`], cos θ < 0 is the
    /// inside; the other models clamp it to [0, 1]).
    fn eval(&self, cos_i: F) -> [F; N];

    /// F_avg = 2∫₀¹ F(μ) μ dμ per channel, in f64: the hemispherical average reflectance
    /// (Kulla–Conty's F_avg). The library's models give it in closed form ([`One`],
    /// [`Schlick`], [`F82Tint`] where unclamped) or by rules fitted to their singularities
    /// ([`dielectric_average`], [`conductor_average`]), within 1e-11; this default, for a
    /// model written elsewhere, is 8-point Gauss–Legendre on 16 intervals of `eval` (exact
    /// for smooth models to the rounding of `F`; an edge such as a critical angle costs
    /// digits, 1e-4 for a dielectric η < 1, so override it there).
    fn average(&self) -> [f64; N] {
        quadrature_average(|mu| self.eval(mu))
    }
}

/// F = 1 in each of N channels (a perfect mirror: white-furnace tests), e.g. `One::<1>`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct One<const N: usize>;

impl<F: Real, const N: usize> Fresnel<F, N> for One<N> {
    #[inline(always)]
    fn eval(&self, _cos_i: F) -> [F; N] {
        [F::ONE; N]
    }

    fn average(&self) -> [f64; N] {
        [1.0; N]
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

    fn average(&self) -> [f64; N] {
        [dielectric_average(self.eta.to_f64()); N]
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

    fn average(&self) -> [f64; N] {
        std::array::from_fn(|c| conductor_average(self.eta[c].to_f64(), self.k[c].to_f64()))
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

    /// F0 + (1 − F0)/21, exactly.
    fn average(&self) -> [f64; N] {
        std::array::from_fn(|c| {
            let f0 = self.f0[c].to_f64();
            f0 + (1.0 - f0) * SCHLICK_AVG
        })
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

    /// Where the model stays in [0, 1] (its clamp inactive): F0 + (1 − F0)/21 − a/126
    /// (2∫₀¹ μ²(1 − μ)⁶ dμ = 2B(3, 7) = 1/126), exactly; else the default quadrature of the
    /// clamped model.
    fn average(&self) -> [f64; N] {
        let closed: [Option<f64>; N] =
            std::array::from_fn(|c| f82_tint_average(self.f0[c].to_f64(), self.h[c].to_f64()));
        if closed.iter().all(Option::is_some) {
            return closed.map(|v| v.unwrap_or(0.0));
        }
        let q = quadrature_average(|mu| self.eval(mu));
        std::array::from_fn(|c| closed[c].unwrap_or(q[c]))
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
    /// The hemispherical Fresnel average against the reciprocity of the averaged
    /// transmittance, 1 − F_avg(1/η) = (1 − F_avg(η))/η² (the kink at the critical angle
    /// is on the 1/η side), and against values integrated with mpmath (30 digits).
    #[test]
    fn fresnel_average() {
        for eta in [1.05, 1.33, 1.5, 2.42, 3.0] {
            let (out, inside) = (dielectric_average(eta), dielectric_average(1.0 / eta));
            assert!(
                ((1.0 - inside) - (1.0 - out) / (eta * eta)).abs() < 1e-14,
                "η={eta}: {out} {inside}"
            );
        }
        for (eta, want) in [
            (1.5, 0.091_777_959_342_351_21),
            (1.0 / 1.5, 0.596_345_759_707_711_8),
            (2.42, 0.212_540_794_738_842_13),
            (1.0 / 2.42, 0.865_538_691_813_886),
        ] {
            assert!((dielectric_average(eta) - want).abs() < 1e-15, "η={eta}");
        }
    }

    /// The dielectric rule against the same on 256 intervals (1e-16 of mpmath where tested
    /// above) over η ∈ [1.0001, 100] and reciprocals.
    #[test]
    fn dielectric_average_against_a_dense_rule() {
        let mut worst = 0.0f64;
        for i in 0..=400 {
            let e = 1e-4f64 * (1e6f64).powf(i as f64 / 400.0);
            for eta in [1.0 + e, 1.0 / (1.0 + e)] {
                let mc = if eta < 1.0 {
                    ((1.0 - eta) * (1.0 + eta)).sqrt()
                } else {
                    0.0
                };
                let err = (dielectric_average(eta) - dielectric_average_on(eta, mc, 256)).abs();
                worst = worst.max(err);
            }
        }
        assert!(worst < 1e-12, "{worst:e}");
        assert_eq!(dielectric_average(1.0), 0.0);
    }

    /// The conductor rule against a dense one (split at Re μb, each side substituted as the
    /// dielectric's, 8-point Gauss–Legendre on 512 intervals) over η ∈ [0.02, 20],
    /// k ∈ {0} ∪ [1e-4, 20], and for k = 0 against the dielectric average.
    #[test]
    fn conductor_average_against_a_dense_rule() {
        let dense = |eta: f64, k: f64| {
            let mub = Complex::new(1.0 - eta * eta + k * k, -2.0 * eta * k).sqrt();
            let s = mub.re.clamp(0.0, 1.0);
            let n = 512;
            let mut sum = 0.0;
            for j in 0..n {
                for (x, w) in GL8 {
                    let t = (j as f64 + x) / n as f64;
                    let (ml, mr) = (s * (1.0 - t * t), s + (1.0 - s) * t * t);
                    sum += 2.0 * w / n as f64
                        * (conductor(ml, eta, k) * ml * s + conductor(mr, eta, k) * mr * (1.0 - s))
                        * 2.0
                        * t;
                }
            }
            sum
        };
        let mut worst = (0.0f64, 0.0, 0.0);
        for i in 0..=40 {
            let eta = 0.02 * 1000f64.powf(i as f64 / 40.0);
            for j in 0..=40 {
                let k = if j == 0 {
                    0.0
                } else {
                    1e-4 * 2e5f64.powf((j - 1) as f64 / 39.0)
                };
                let err = (conductor_average(eta, k) - dense(eta, k)).abs();
                if err > worst.0 {
                    worst = (err, eta, k);
                }
            }
        }
        assert!(worst.0 < 1e-11, "{worst:?}");
        for (eta, k) in [(1e300, 1e300), (1e300, 1.0), (1.0, 1e300), (1e-300, 1e-300)] {
            let a = conductor_average(eta, k);
            assert!((0.0..=1.0).contains(&a), "{eta} {k}: {a}");
            assert!(a > 0.999, "{eta} {k}: {a}");
        }
        for eta in [0.3, 1.0 / 1.5, 1.5, 2.42] {
            let d = (conductor_average(eta, 0.0) - dielectric_average(eta)).abs();
            assert!(d < 1e-11, "η {eta}: {d:e}");
        }
    }

    /// The closed forms (One, Schlick, unclamped F82-tint) against the default quadrature,
    /// and F82-tint where its clamp is active (a dark F0 with a low tint) by the quadrature.
    #[test]
    fn closed_form_averages_match_the_quadrature() {
        let q = |f: &dyn Fn(f64) -> f64| quadrature_average::<f64, 1>(|mu| [f(mu)])[0];
        assert_eq!(Fresnel::<f64, 2>::average(&One::<2>), [1.0; 2]);
        for f0 in [0.0, 0.04, 0.5, 0.95, 1.0] {
            let got = Fresnel::<f64, 1>::average(&Schlick { f0: [f0] })[0];
            assert!((got - q(&|mu| schlick(mu, f0))).abs() < 1e-15, "F0 {f0}");
            for h in [0.0, 0.3, 0.7, 1.0, 1.3] {
                let got = Fresnel::<f64, 1>::average(&F82Tint { f0: [f0], h: [h] })[0];
                let want = q(&|mu| f82_tint(mu, f0, h));
                // (Where the clamp acts the model has a kink, and the quadrature is the
                // answer either way.)
                assert!((got - want).abs() < 1e-14, "F0 {f0} h {h}: {got} {want}");
            }
        }
        assert!(f82_tint_average(0.9, 0.7).is_some());
        assert!(f82_tint_average(0.02, 0.0).is_none());
    }

    /// The thread's last indices are remembered: the same value again, for five metals
    /// cycled through the four places (each evicted and recomputed in turn).
    #[test]
    fn conductor_average_remembers_exactly() {
        let metals = [
            (0.18, 3.4),
            (0.42, 2.35),
            (1.37, 1.77),
            (1.35, 7.5),
            (2.9, 3.0),
        ];
        let first: Vec<f64> = metals
            .iter()
            .map(|&(n, k)| conductor_average_rule(n, k))
            .collect();
        for _ in 0..3 {
            for (j, &(n, k)) in metals.iter().enumerate() {
                assert_eq!(conductor_average(n, k).to_bits(), first[j].to_bits());
            }
        }
        assert!(conductor_average(f64::NAN, 1.0).is_nan());
        assert!(conductor_average(f64::NAN, 1.0).is_nan());
    }
}
