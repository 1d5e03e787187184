//! D·cos (Walter 2007) sampling for every NDF of the family, by exact inversion of the radial
//! slope CDF, with its pdf and its inverse.
//!
//! Under D(m) cos θm the slope magnitude r = tan θm has the CDF
//! F(R) = 2π ∫₀^R r P22(r) dr and the azimuth is uniform. [`RadialSlopes`] gives F, its
//! complement and its quantile for each NDF:
//!
//! | NDF | F(R) (x = R/α) | quantile |
//! |---|---|---|
//! | Beckmann | 1 − e^{−x²} | closed form |
//! | GGX | x²/(1 + x²) | closed form |
//! | GTR | Burley's CDF, expm1((γ−1)X)/expm1((γ−1)L), X = ln(α²/w) (Burley 2012, appendix B, eq. 3; derivations.md B.3) | closed form (eqs 3, 5, 7, 9 in one stable formula) |
//! | Double GGX | 1 − c e^c E₁(c), c = 1/x² | Newton on F (1e-15) |
//! | Exponential | 1 − (1 + 2x) e^{−2x} | Newton on F (1e-15) |
//!
//! The Newton inversions are safeguarded by bisection (`solve`) and converge to a
//! few ulp; the closed forms are arranged with expm1/log1p so they stay accurate at α = 1,
//! γ = 1 and in both tails. [`sample_dcos`] maps u ∈ [0,1)² to a normal; [`invert_dcos`] maps
//! the normal back to u (round trip to 1e-12, tests/sampling.rs); [`pdf_dcos`] is D(m) cos θm.

use crate::math::special::{e1, e1_cf_tail, expm1_over_x, ln1p_over_x};
use crate::math::vec3::Vec3;
use crate::{AnyNdf, Beckmann, DoubleGgx, Exponential, Ggx, Gtr, Ndf};
use std::f64::consts::PI;

pub use crate::ndf::slopes::RadialSlopes;
use crate::ndf::slopes::{quantile_edge, radial_pdf};

impl RadialSlopes for Beckmann {
    fn slope_cdf(&self, r: f64) -> f64 {
        let x = r / self.alpha();
        -(-x * x).exp_m1()
    }
    fn slope_ccdf(&self, r: f64) -> f64 {
        let x = r / self.alpha();
        (-x * x).exp()
    }
    fn slope_quantile(&self, xi: f64) -> f64 {
        // x² = −ln(1 − ξ); for ξ ≥ 1/2, 1 − ξ is exact, below it ln1p(−ξ) keeps small ξ.
        let l = if xi < 0.5 {
            -(-xi).ln_1p()
        } else {
            -(1.0 - xi).ln()
        };
        self.alpha() * l.max(0.0).sqrt()
    }
}

impl RadialSlopes for Ggx {
    fn slope_cdf(&self, r: f64) -> f64 {
        let x = r / self.alpha();
        if x > 1e150 {
            return 1.0;
        }
        x * x / (1.0 + x * x)
    }
    fn slope_ccdf(&self, r: f64) -> f64 {
        let x = r / self.alpha();
        if x > 1e150 {
            return 0.0;
        }
        1.0 / (1.0 + x * x)
    }
    fn slope_quantile(&self, xi: f64) -> f64 {
        if xi >= 1.0 {
            return f64::INFINITY;
        }
        self.alpha() * (xi / (1.0 - xi)).max(0.0).sqrt()
    }
    fn slope_tail_index(&self) -> Option<f64> {
        // 1 − F = 1/(1 + x²).
        Some(2.0)
    }
}

impl RadialSlopes for Exponential {
    fn slope_cdf(&self, r: f64) -> f64 {
        let y = 2.0 * r / self.alpha();
        if y < 0.5 {
            // 1 − (1+y)e^{−y} = Σ_{n≥2} (−1)ⁿ (n−1) yⁿ/n!, which does not cancel.
            let (mut term, mut sum) = (y, 0.0);
            for n in 2..30 {
                term *= -y / n as f64; // term = (−1)^{n+1} yⁿ/n!
                let t = -(n as f64 - 1.0) * term;
                sum += t;
                if t.abs() < 1e-18 * sum.abs() {
                    break;
                }
            }
            sum
        } else {
            1.0 - self.slope_ccdf(r)
        }
    }
    fn slope_ccdf(&self, r: f64) -> f64 {
        let y = 2.0 * r / self.alpha();
        if y > 746.0 {
            return 0.0;
        }
        (1.0 + y) * (-y).exp()
    }
}

impl RadialSlopes for DoubleGgx {
    fn slope_cdf(&self, r: f64) -> f64 {
        let a = self.alpha();
        let c = (a / r) * (a / r);
        if c == f64::INFINITY {
            return 0.0;
        }
        if c >= 1.0 {
            // 1 − c e^c E₁(c) = (1 − T)/(c + 1 − T).
            let t = e1_cf_tail(c);
            (1.0 - t) / (c + 1.0 - t)
        } else {
            1.0 - self.slope_ccdf(r)
        }
    }
    fn slope_ccdf(&self, r: f64) -> f64 {
        let a = self.alpha();
        let c = (a / r) * (a / r);
        if c == 0.0 {
            return 0.0;
        }
        // r = 0 (or a slope whose c = α²/r² overflows): all the mass lies beyond.
        if c == f64::INFINITY {
            return 1.0;
        }
        if c >= 1.0 {
            c / (c + 1.0 - e1_cf_tail(c))
        } else {
            c * c.exp() * e1(c)
        }
    }
}

impl RadialSlopes for Gtr {
    fn slope_cdf(&self, r: f64) -> f64 {
        if r == f64::INFINITY {
            return 1.0;
        }
        // F = (w^{1−γ} − α^{2−2γ})/(1 − α^{2−2γ}) = expm1(−kX)/expm1(−kL), k = 1 − γ,
        // L = ln α², w = (r²+α²)/(1+r²), X = L − ln w = ln(α²/w).
        let (l, k) = (self.burley().l, self.burley().k);
        let (ln_w, _, x_over_l) = self.log_ratios(r);
        let f = if -k * l > 1.0 {
            // Large exponents: = e^{k ln w} expm1(kX)/expm1(kL), whose exponentials are all
            // of arguments known to full relative accuracy.
            (k * ln_w).exp() * (k * x_over_l * l).exp_m1() / (k * l).exp_m1()
        } else {
            x_over_l * expm1_over_x(-k * x_over_l * l) / expm1_over_x(-k * l)
        };
        // (The ratio rounds to 1 + ulp as r → ∞.)
        f.min(1.0)
    }
    fn slope_ccdf(&self, r: f64) -> f64 {
        if r == f64::INFINITY {
            return 0.0;
        }
        // 1 − F = expm1((1−γ) ln w)/expm1((1−γ)L).
        let (l, k) = (self.burley().l, self.burley().k);
        let (ln_w, w_over_l, x_over_l) = self.log_ratios(r);
        if k * l > 1.0 {
            // = e^{−kX} expm1(−k ln w)/expm1(−kL) (see slope_cdf).
            (-k * x_over_l * l).exp() * (-k * ln_w).exp_m1() / (-k * l).exp_m1()
        } else {
            w_over_l * expm1_over_x(k * ln_w) / expm1_over_x(k * l)
        }
    }
    fn slope_quantile(&self, xi: f64) -> f64 {
        if let Some(r) = quantile_edge(xi) {
            return r;
        }
        self.burley().tan2(xi).sqrt()
    }
    fn slope_tail_index(&self) -> Option<f64> {
        // P22 = c (1 + r²)^{γ−2} (r² + α²)^{−γ} = c r⁻⁴ (1 + O(max(1, α²)/r²)) for every γ.
        Some(2.0)
    }
}

impl Gtr {
    /// (ln w, ln w / L, X / L) at slope r, with w = (r²+α²)/(1+r²) = 1 + δ/(1+r²),
    /// α²/w = 1 + δ r²/(r²+α²) and X = ln(α²/w), L = ln α², δ = α² − 1. Near α = 1 the ratios
    /// are formed as z lr(δz)/lr(δ) (lr(x) = ln1p(x)/x), which has the limit z; elsewhere each
    /// logarithm is ln1p of its small part, or the log of a ratio of positive sums.
    fn log_ratios(&self, r: f64) -> (f64, f64, f64) {
        let a2 = self.alpha() * self.alpha();
        let r2 = r * r;
        let (l, delta) = (self.burley().l, self.burley().delta);
        // (c₀ + c₁r²)/(d₀ + d₁r²), in 1/r² above r² = 1 (r² = ∞ gives c₁/d₁, not NaN).
        let ratio = |c0: f64, c1: f64, d0: f64, d1: f64| {
            if r2 > 1.0 {
                let s = 1.0 / r2;
                (c0 * s + c1) / (d0 * s + d1)
            } else {
                (c0 + c1 * r2) / (d0 + d1 * r2)
            }
        };
        let zw = 1.0 / (1.0 + r2); // w − 1 = δ zw
        let zx = ratio(0.0, 1.0, a2, 1.0); // α²/w − 1 = δ zx = δ r²/(r² + α²)
        if delta.abs() < 0.5 {
            let lr = self.burley().lr_delta;
            let w_over_l = zw * ln1p_over_x(delta * zw) / lr;
            let x_over_l = zx * ln1p_over_x(delta * zx) / lr;
            ((delta * zw).ln_1p(), w_over_l, x_over_l)
        } else {
            let ln = |small: f64, big: f64| {
                if small.abs() < 0.5 {
                    small.ln_1p()
                } else {
                    big.ln()
                }
            };
            let ln_w = ln(delta * zw, ratio(a2, 1.0, 1.0, 1.0));
            let x = ln(delta * zx, a2 * ratio(1.0, 1.0, a2, 1.0));
            (ln_w, ln_w / l, x / l)
        }
    }
}

impl RadialSlopes for AnyNdf {
    fn slope_cdf(&self, r: f64) -> f64 {
        match self {
            AnyNdf::Beckmann(n) => n.slope_cdf(r),
            AnyNdf::Ggx(n) => n.slope_cdf(r),
            AnyNdf::Gtr(n) => n.slope_cdf(r),
            AnyNdf::DoubleGgx(n) => n.slope_cdf(r),
            AnyNdf::Exponential(n) => n.slope_cdf(r),
            AnyNdf::StudentT(n) => n.slope_cdf(r),
            AnyNdf::Ei(n) => n.slope_cdf(r),
            AnyNdf::Erfc(n) => n.slope_cdf(r),
            AnyNdf::K0(n) => n.slope_cdf(r),
            AnyNdf::BesselK(n) => n.slope_cdf(r),
            AnyNdf::GenExponential(n) => n.slope_cdf(r),
        }
    }
    fn slope_ccdf(&self, r: f64) -> f64 {
        match self {
            AnyNdf::Beckmann(n) => n.slope_ccdf(r),
            AnyNdf::Ggx(n) => n.slope_ccdf(r),
            AnyNdf::Gtr(n) => n.slope_ccdf(r),
            AnyNdf::DoubleGgx(n) => n.slope_ccdf(r),
            AnyNdf::Exponential(n) => n.slope_ccdf(r),
            AnyNdf::StudentT(n) => n.slope_ccdf(r),
            AnyNdf::Ei(n) => n.slope_ccdf(r),
            AnyNdf::Erfc(n) => n.slope_ccdf(r),
            AnyNdf::K0(n) => n.slope_ccdf(r),
            AnyNdf::BesselK(n) => n.slope_ccdf(r),
            AnyNdf::GenExponential(n) => n.slope_ccdf(r),
        }
    }
    fn slope_pdf(&self, r: f64) -> f64 {
        match self {
            AnyNdf::BesselK(n) => n.slope_pdf(r),
            n => radial_pdf(n, r),
        }
    }
    fn slope_quantile(&self, xi: f64) -> f64 {
        match self {
            AnyNdf::Beckmann(n) => n.slope_quantile(xi),
            AnyNdf::Ggx(n) => n.slope_quantile(xi),
            AnyNdf::Gtr(n) => n.slope_quantile(xi),
            AnyNdf::DoubleGgx(n) => n.slope_quantile(xi),
            AnyNdf::Exponential(n) => n.slope_quantile(xi),
            AnyNdf::StudentT(n) => n.slope_quantile(xi),
            AnyNdf::Ei(n) => n.slope_quantile(xi),
            AnyNdf::Erfc(n) => n.slope_quantile(xi),
            AnyNdf::K0(n) => n.slope_quantile(xi),
            AnyNdf::BesselK(n) => n.slope_quantile(xi),
            AnyNdf::GenExponential(n) => n.slope_quantile(xi),
        }
    }
    fn slope_tail_index(&self) -> Option<f64> {
        match self {
            AnyNdf::Ggx(n) => n.slope_tail_index(),
            AnyNdf::Gtr(n) => n.slope_tail_index(),
            AnyNdf::StudentT(n) => n.slope_tail_index(),
            AnyNdf::Beckmann(_)
            | AnyNdf::DoubleGgx(_)
            | AnyNdf::Exponential(_)
            | AnyNdf::Ei(_)
            | AnyNdf::Erfc(_)
            | AnyNdf::K0(_)
            | AnyNdf::BesselK(_)
            | AnyNdf::GenExponential(_) => None,
        }
    }
}

/// A microfacet normal distributed as D(m) cos θm: r = F⁻¹(u₀), φ = 2π u₁.
pub fn sample_dcos<N: RadialSlopes + ?Sized>(ndf: &N, u: [f64; 2]) -> Vec3 {
    let r = ndf.slope_quantile(u[0]);
    let phi = 2.0 * PI * u[1];
    normal_from_polar_slope(r, phi)
}

/// The normal (r cos φ, r sin φ, 1)/√(1 + r²) (slope r towards azimuth φ), exact for r = ∞.
pub(crate) fn normal_from_polar_slope(r: f64, phi: f64) -> Vec3 {
    let (s, c) = phi.sin_cos();
    if r == f64::INFINITY {
        return Vec3::new(c, s, 0.0);
    }
    if r > 1e150 {
        // r² would overflow: z = 1/r, sin θ = 1 (both within r^{−2} ≤ 1e-300 relative).
        return Vec3::new(c, s, 1.0 / r);
    }
    let z = 1.0 / (1.0 + r * r).sqrt();
    let sin = r * z; // sin θ = r cos θ, without 1 − z² cancellation
    Vec3::new(sin * c, sin * s, z)
}

/// The u that [`sample_dcos`] maps to `wm` (for wm.z > 0).
pub fn invert_dcos<N: RadialSlopes + ?Sized>(ndf: &N, wm: Vec3) -> [f64; 2] {
    let sin = crate::math::vec3::hypot(wm.x, wm.y);
    let r = sin / wm.z;
    let mut phi = wm.y.atan2(wm.x);
    if phi < 0.0 {
        phi += 2.0 * PI;
    }
    // (The clamp: a CDF may round a few ulp past 1.)
    [
        ndf.slope_cdf(r).clamp(0.0, 1.0),
        (phi / (2.0 * PI)).min(1.0),
    ]
}

/// The solid-angle density of [`sample_dcos`]: D(m) cos θm (0 below the horizon).
pub fn pdf_dcos<N: Ndf + ?Sized>(ndf: &N, wm: Vec3) -> f64 {
    if wm.z <= 0.0 {
        return 0.0;
    }
    // Within 45° of the normal through the slopes, D = P22(x/z, y/z)/z⁴ (exact): there the
    // cosine carries the direction poorly. It rounds to 1 below slopes ~1e-8, where D(1) is
    // the pole (+∞) of Ei, Erfc, K0 and Bessel-K a ≤ 1 while P22 at the slopes is finite; and
    // 1 − u² carries u's rounding, ε/(1 − u), which D's exponent multiplies by tan²θ/α² (a
    // relative ε/α² inside a narrow lobe). Past 45° the cosine is well conditioned and z³ of
    // a near-horizon normal would underflow.
    let (p, q) = (wm.x / wm.z, wm.y / wm.z);
    if p * p + q * q < 1.0 {
        let z2 = wm.z * wm.z;
        return ndf.p22(p, q) / (z2 * wm.z);
    }
    ndf.d_cos_pos(wm.z.min(1.0))
}
