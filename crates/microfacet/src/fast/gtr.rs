//! GTR at any γ: Λ, σ, G1, G2 from an octave table built for one (α, γ) at construction.
//!
//! GTR is not shape invariant: Λ depends on cot θ, α and γ, a three-parameter function no
//! static table covers at 1e-7. A renderer fixes (α, γ) per material, so [`Gtr::new`] fits
//! ln Λ(a), a = cot θ, for that material by Chebyshev interpolation of the exact Smith
//! integral ([`crate::Gtr::lambda_cot`]) on quarter octaves (degree 8). The logarithm is what
//! makes a fixed degree enough: for large γ and small α, Λ falls like a^{−2γ} near the normal
//! (by 10^15 across one quarter octave at γ = 100), which no short polynomial follows in
//! relative terms, while ln Λ stays smooth. Evaluation costs a square root, a division, a
//! degree-8 polynomial and an exponential. Construction evaluates the exact Λ about 1 500
//! times (tens of milliseconds; BENCHMARKS.md has the measured figure).
//!
//! Where Λ underflows (γ ≳ 30 with small α: Λ ~ α^{2γ} near the normal), a segment with any
//! node below 1e-300 returns 0; so Λ is relatively accurate where it exceeds 1e-280 (a
//! quarter octave spans at most a factor 10^15 there) and absolutely below.
//!
//! Range: the features of P22 = c(1 + r²)^{γ−2}(r² + α²)^{−γ} lie at slopes r ~ α, 1 and √γ
//! (where ((1 + r²)/(α² + r²))^γ settles). With s₋ = min(α, 1)/max(1, √γ) and
//! s₊ = max(α, 1, √γ), the table spans a ∈ [2^−18 s₋, 2^18 s₊]; beyond it
//! * a > 2^18 s₊ (near the normal, P22 ~ c r⁻⁴ past every feature): Λ = K/a², K matched at
//!   the end (the next term is O((s₊/a)²) relative, below 1e-10);
//! * a < 2^−18 s₋ (grazing): Λ = m/a − 1/2, m matched at the end (next term O((a/s₋)²)).
//!
//! Accuracy: relative error ≤ 1e-7 required; tests/fast.rs measures it over u ∈ (0, 1] for
//! α ∈ [1e-3, 1e3], γ ∈ [0.1, 100].

use super::{fit, Real};
use crate::error::ParamError;
use crate::ndf::Ndf;

/// Polynomial coefficients per segment (degree 8).
const N: usize = 9;
/// 2^M segments per octave.
pub(crate) const M: u32 = 2;
/// The table reaches 2^SPAN beyond the outermost feature scale on each side.
const SPAN: i32 = 18;
/// Below this Λ is treated as underflowed (see the module docs).
const TINY: f64 = 1e-300;

/// A GTR NDF prepared for fast Λ, σ, G1 and G2.
#[derive(Clone, Debug)]
pub struct Gtr {
    alpha: f64,
    gamma: f64,
    k0: i32,
    lo: f64,
    hi: f64,
    coef: Vec<[f64; N]>,
    /// Λ ≈ m/a − 1/2 below `lo`.
    m: f64,
    /// Λ ≈ K/a² above `hi`.
    k: f64,
    sigma0: f64,
    exact: crate::Gtr,
}

impl Gtr {
    /// Fits Λ for α ∈ [1e-6, 1e6], γ ∈ (0, 100] (validated as in [`crate::Gtr::new`]).
    pub fn new(alpha: f64, gamma: f64) -> Result<Self, ParamError> {
        let exact = crate::Gtr::new(alpha, gamma)?;
        let s_lo = alpha.min(1.0) / gamma.sqrt().max(1.0);
        let s_hi = alpha.max(1.0).max(gamma.sqrt());
        let k0 = s_lo.log2().floor() as i32 - SPAN;
        let k1 = s_hi.log2().ceil() as i32 + SPAN;
        let mut coef = fit::fit_octaves::<N>(k0, k1, M, |a| exact.lambda_cot(a).max(TINY).ln());
        for c in coef.iter_mut() {
            // A node at the floor: the segment reaches the underflow (see the module docs).
            if (0..N).any(|k| {
                let s = (std::f64::consts::PI * (k as f64 + 0.5) / N as f64).cos();
                fit::horner(c, s) <= TINY.ln() + 1e-6
            }) {
                *c = [0.0; N];
                c[0] = -800.0; // e^{−800} = 0
            }
        }
        let (lo, hi) = (2f64.powi(k0), 2f64.powi(k1));
        Ok(Gtr {
            alpha,
            gamma,
            k0,
            lo,
            hi,
            coef,
            m: (exact.lambda_cot(lo) + 0.5) * lo,
            k: exact.lambda_cot(hi) * hi * hi,
            sigma0: exact.sigma(0.0),
            exact,
        })
    }

    /// α.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// γ.
    pub fn gamma(&self) -> f64 {
        self.gamma
    }

    /// (first octave, table start, table end, ln Λ coefficients) for the slice functions.
    pub(crate) fn table(&self) -> (i32, f64, f64, &[[f64; N]]) {
        (self.k0, self.lo, self.hi, &self.coef)
    }

    /// Λ at a = cot θ ≥ 0 (+∞ at a = 0, 0 at a = +∞).
    #[inline]
    pub fn lambda_cot(&self, a: f64) -> f64 {
        if a >= self.lo && a < self.hi {
            return fit::eval(&self.coef, self.k0, M, a).exp();
        }
        if a < self.lo {
            return self.m / a - 0.5;
        }
        if a.is_nan() {
            return a;
        }
        let r = 1.0 / a;
        self.k * r * r
    }

    /// D(u) for every u: the exact closed form (≤ 1e-13), rounded to F.
    #[inline]
    pub fn d<F: Real>(&self, u: F) -> F {
        F::from_f64(self.exact.d(u.to_f64()))
    }

    /// Λ(u) for 0 ≤ u ≤ 1.
    #[inline]
    pub fn lambda<F: Real>(&self, u: F) -> F {
        let u = u.to_f64();
        F::from_f64(self.lambda_cot(u / ((1.0 - u) * (1.0 + u)).sqrt()))
    }

    /// G1(u) = 1/(1 + Λ(u)) for 0 ≤ u ≤ 1.
    #[inline]
    pub fn g1<F: Real>(&self, u: F) -> F {
        F::from_f64(1.0 / (1.0 + self.lambda(u.to_f64())))
    }

    /// Height-correlated G2 = 1/(1 + Λ(u_o) + Λ(u_i)).
    #[inline]
    pub fn g2<F: Real>(&self, u_o: F, u_i: F) -> F {
        F::from_f64(1.0 / (1.0 + self.lambda(u_o.to_f64()) + self.lambda(u_i.to_f64())))
    }

    /// σ(u) for u ∈ [−1, 1].
    #[inline]
    pub fn sigma<F: Real>(&self, u: F) -> F {
        F::from_f64(super::sigma_from_lambda(u.to_f64(), self.sigma0, |v| {
            self.lambda(v)
        }))
    }
}
