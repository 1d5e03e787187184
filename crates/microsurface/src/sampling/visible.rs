//! Visible-normal (VNDF) sampling in the slope space of the α = 1 member of a shape-invariant
//! NDF, by exact inversion of the visible slope distribution (Heitz & d'Eon 2014's
//! formulation; Jakob 2014 for Beckmann).
//!
//! For a direction with cot θ = a in the xz-plane, the visible slopes (x̃, ỹ) of normals
//! m ∝ (x̃, ỹ, 1) have density (x̃ + a)₊ P22(x̃, ỹ)/(a(1 + Λ)). Its x̃-marginal has the CDF
//!
//!   C(X) = [a (M₀(X) − M₀(−a)) + M₁(X) − M₁(−a)] / [a M₀(a) − M₁(−a)],
//!
//! M₀(X) = ∫_{−∞}^X P2, M₁(X) = ∫_{−∞}^X x P2 (the denominator is a(1 + Λ(a))), and ỹ
//! given x̃ has the CDF
//! ½ + ∫₀^ỹ P22(x̃, y) dy / P2(x̃). Beckmann and GGX have all of these in closed form
//! ([`Component`]); Double GGX and the Exponential NDF are superpositions of them (Gamma-1 of GGX,
//! Gamma(3/2) of Beckmann), and since every quantity above is linear in P22, theirs are the
//! weighted integrals of the components' (a fixed tanh-sinh rule over the mixing variable,
//! [`crate::ndf::mixture::fixed_rule`], ~1e-14). Each CDF is
//! inverted by safeguarded Newton to a few ulp, so the warp is exact and invertible.

use crate::math::solve::newton_bracketed;
use crate::math::special::{erf, erfc};
use crate::ndf::mixture::{fixed_rule, Mixing};
use std::f64::consts::PI;
use std::sync::OnceLock;

use crate::math::special::SQRT_PI;

/// A closed-form component: Beckmann or GGX slopes with roughness α.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Component {
    Beckmann(f64),
    Ggx(f64),
}

/// The visible-slope integrals of a component: [M₀, M₁/a-part, …] evaluated at X.
impl Component {
    /// P2(x).
    fn p2(self, x: f64) -> f64 {
        match self {
            Component::Beckmann(a) => {
                let t = x / a;
                (-t * t).exp() / (SQRT_PI * a)
            }
            Component::Ggx(a) => {
                let w = x * x + a * a;
                a * a / (2.0 * w * w.sqrt())
            }
        }
    }

    /// M₀(X) = ∫_{−∞}^X P2 (0 at −∞, 1 at +∞).
    fn m0(self, x: f64) -> f64 {
        match self {
            Component::Beckmann(a) => 0.5 * erfc(-x / a),
            Component::Ggx(a) => {
                if x == f64::NEG_INFINITY {
                    return 0.0;
                }
                if x == f64::INFINITY {
                    return 1.0;
                }
                let s = (x * x + a * a).sqrt();
                // For X < 0 write 1 + X/s = α²/(s(s − X)) to avoid cancellation.
                if x < 0.0 {
                    0.5 * a * a / (s * (s - x))
                } else {
                    0.5 * (1.0 + x / s)
                }
            }
        }
    }

    /// M₁(X) = ∫_{−∞}^X x P2 (0 at ±∞).
    fn m1(self, x: f64) -> f64 {
        if x.is_infinite() {
            return 0.0;
        }
        match self {
            Component::Beckmann(a) => {
                let t = x / a;
                -a * (-t * t).exp() / (2.0 * SQRT_PI)
            }
            Component::Ggx(a) => -a * a / (2.0 * (x * x + a * a).sqrt()),
        }
    }

    /// ∫₀^Y P22(x, y) dy.
    fn p22_partial(self, x: f64, y: f64) -> f64 {
        match self {
            Component::Beckmann(a) => 0.5 * self.p2(x) * erf(y / a),
            Component::Ggx(a) => {
                let b2 = x * x + a * a;
                let b = b2.sqrt();
                let part = y / (2.0 * b2 * (b2 + y * y)) + (y / b).atan() / (2.0 * b2 * b);
                a * a / PI * part
            }
        }
    }
}

/// The α = 1 slope distribution of a shape-invariant NDF, as a component or a superposition.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum UnitSlopes {
    Beckmann,
    Ggx,
    /// Gamma-1 superposition of GGX.
    DoubleGgx,
    /// Gamma(3/2) superposition of Beckmann.
    Exponential,
}

impl UnitSlopes {
    /// The NDF it is the α = 1 slope distribution of.
    pub fn kind(self) -> crate::NdfKind {
        match self {
            UnitSlopes::Beckmann => crate::NdfKind::Beckmann,
            UnitSlopes::Ggx => crate::NdfKind::Ggx,
            UnitSlopes::DoubleGgx => crate::NdfKind::DoubleGgx,
            UnitSlopes::Exponential => crate::NdfKind::Exponential,
        }
    }

    /// E[q(component)] over the mixing distribution (or q itself for a plain component).
    fn mix(self, q: impl Fn(Component) -> f64) -> f64 {
        match self {
            UnitSlopes::Beckmann => q(Component::Beckmann(1.0)),
            UnitSlopes::Ggx => q(Component::Ggx(1.0)),
            UnitSlopes::DoubleGgx => {
                static RULE: OnceLock<Vec<(f64, f64)>> = OnceLock::new();
                let rule = RULE.get_or_init(|| fixed_rule(Mixing::Gamma1, 1.0));
                rule.iter().map(|&(a, w)| w * q(Component::Ggx(a))).sum()
            }
            UnitSlopes::Exponential => {
                static RULE: OnceLock<Vec<(f64, f64)>> = OnceLock::new();
                let rule = RULE.get_or_init(|| fixed_rule(Mixing::Gamma32, 1.0));
                rule.iter()
                    .map(|&(a, w)| w * q(Component::Beckmann(a)))
                    .sum()
            }
        }
    }

    /// The marginal slope density P2(x) of the α = 1 NDF (from the components).
    pub fn p2(self, x: f64) -> f64 {
        self.mix(|c| c.p2(x))
    }

    /// The normaliser of the visible x̃-marginal: ∫_{−a}^∞ (x + a) P2 dx = a(1 + Λ(a)) for
    /// a ≤ 1, and that divided by a for a > 1 (so that a = 0 and a = ∞ both stay finite);
    /// with M₀(a) = 1 − M₀(−a) it is a M₀(a) − M₁(−a).
    fn normaliser(self, a: f64) -> f64 {
        if a <= 1.0 {
            self.mix(|c| a * c.m0(a) - c.m1(-a))
        } else {
            self.mix(|c| c.m0(a) - c.m1(-a) / a)
        }
    }

    /// C(X): the CDF of the visible x̃-slope for cot θ = a (a = ∞ at normal incidence).
    pub fn marginal_cdf(self, a: f64, x: f64) -> f64 {
        self.marginal_cdf_with(a, x, self.normaliser(a))
    }

    fn marginal_cdf_with(self, a: f64, x: f64, den: f64) -> f64 {
        if x <= -a {
            return 0.0;
        }
        // ∫_{−a}^X (x + a) P2 = a ΔM₀ + ΔM₁, scaled like the normaliser.
        let num = if a <= 1.0 {
            self.mix(|c| a * (c.m0(x) - c.m0(-a)) + (c.m1(x) - c.m1(-a)))
        } else {
            let inv = if a.is_finite() { 1.0 / a } else { 0.0 };
            self.mix(|c| c.m0(x) - c.m0(-a) + (c.m1(x) - c.m1(-a)) * inv)
        };
        (num / den).clamp(0.0, 1.0)
    }

    /// The density of C: (X + a) P2(X) over the normaliser.
    fn marginal_pdf_with(self, a: f64, x: f64, den: f64) -> f64 {
        if x <= -a {
            return 0.0;
        }
        let w = if a <= 1.0 {
            x + a
        } else if a.is_finite() {
            (x + a) / a
        } else {
            1.0
        };
        w * self.p2(x) / den
    }

    /// The CDF of ỹ given x̃ = x.
    pub fn conditional_cdf(self, x: f64, y: f64) -> f64 {
        self.conditional_cdf_with(x, y, self.p2(x))
    }

    /// `conditional_cdf` given P2(x) (fixed while ỹ is solved for).
    fn conditional_cdf_with(self, x: f64, y: f64, p2x: f64) -> f64 {
        let part = self.mix(|c| c.p22_partial(x, y));
        (0.5 + part / p2x).clamp(0.0, 1.0)
    }

    fn conditional_pdf_with(self, x: f64, y: f64, p2x: f64) -> f64 {
        let r = crate::math::vec3::hypot(x, y);
        let p22 = self.mix(|c| match c {
            Component::Beckmann(a) => (-(r / a) * (r / a)).exp() / (PI * a * a),
            Component::Ggx(a) => {
                let w = r * r + a * a;
                a * a / (PI * w * w)
            }
        });
        p22 / p2x
    }

    /// Visible slopes (x̃, ỹ) for cot θ = a in the xz-plane, from u ∈ [0, 1)².
    pub fn sample(self, a: f64, u: [f64; 2]) -> (f64, f64) {
        let den = self.normaliser(a);
        let x = invert_increasing(
            |x| self.marginal_cdf_with(a, x, den) - u[0],
            |x| self.marginal_pdf_with(a, x, den),
            -a,
        );
        let p2x = self.p2(x);
        let y = invert_increasing(
            |y| self.conditional_cdf_with(x, y, p2x) - u[1],
            |y| self.conditional_pdf_with(x, y, p2x),
            f64::NEG_INFINITY,
        );
        (x, y)
    }

    /// The u that [`UnitSlopes::sample`] maps to (x̃, ỹ).
    pub fn invert(self, a: f64, x: f64, y: f64) -> [f64; 2] {
        [self.marginal_cdf(a, x), self.conditional_cdf(x, y)]
    }
}

/// Solves f(x) = 0 for an increasing f on (lower, ∞) by growing a bracket from [−1, 1].
fn invert_increasing(f: impl Fn(f64) -> f64, df: impl Fn(f64) -> f64, lower: f64) -> f64 {
    let mut lo = if lower.is_finite() { lower } else { -1.0 };
    let mut hi = if lower.is_finite() { lower + 1.0 } else { 1.0 };
    // Grow the bracket geometrically; 1e300 is beyond any quantile of a non-degenerate u.
    while f(hi) < 0.0 && hi < 1e300 {
        lo = hi;
        hi = if hi > 0.0 { hi * 4.0 } else { 1.0 };
    }
    if !lower.is_finite() {
        while f(lo) > 0.0 && lo > -1e300 {
            hi = lo;
            lo = if lo < 0.0 { lo * 4.0 } else { -1.0 };
        }
    }
    newton_bracketed(f, df, lo, hi, 0.5 * (lo + hi))
}

/// Visible-normal sampling for any isotropic NDF (GTR for general γ included) in polar slope
/// coordinates (r, ψ) relative to the direction's azimuth.
///
/// For cot θ = a the visible slopes have density (r cos ψ + a)₊ P22(r) r / (a(1 + Λ)). Its
/// r-marginal is r P22(r) g(r) with g = 2πa for r ≤ a and g = 2πa + 2r h(y), cos y = a/r,
/// otherwise (`smith::h`); so the r-CDF is a F(X)/Z below a and 1 − T(X)/Z above,
/// where F is the NDF's radial D·cos CDF, T(X) = a (1 − F(X)) + 2 ∫_X^∞ r² P22 h dr (tanh-sinh,
/// 1e-13) and Z = a + 2 I(a) = a (1 + Λ). Given r, ψ has density ∝ (r cos ψ + a) on
/// |ψ| ≤ acos(−a/r), whose CDF is closed-form. Both are inverted by safeguarded Newton.
pub mod radial {
    use crate::math::quad::integrate_to_inf;
    use crate::math::smith::h;
    use crate::math::solve::newton_bracketed;
    use crate::ndf::Ndf;
    use crate::sampling::dcos::RadialSlopes;
    use std::f64::consts::PI;

    /// 2 ∫_X^∞ r² P22(r) h(y) dr, cos y = a/r, for X ≥ a.
    fn tail_integral<N: Ndf + ?Sized>(n: &N, a: f64, x: f64) -> f64 {
        let scale = x.max(n.alpha());
        2.0 * integrate_to_inf(
            |d| {
                let r = x + d;
                if !r.is_finite() {
                    return 0.0;
                }
                // y = atan2(√(r² − a²), a), with r − a = (x − a) + d formed exactly enough.
                let rma = (x - a) + d;
                let y = (rma * (r + a)).sqrt().atan2(a);
                r * r * n.p22(r, 0.0) * h(y)
            },
            0.0,
            scale,
            1e-13,
        )
        .value
    }

    /// T(X) = ∫_X^∞ r P22 g dr for X ≥ a.
    fn tail<N: Ndf + RadialSlopes + ?Sized>(n: &N, a: f64, x: f64) -> f64 {
        a * n.slope_ccdf(x) + tail_integral(n, a, x)
    }

    /// The normaliser Z = a(1 + Λ) = a + 2 I(a), from the same pieces as the CDF.
    pub fn normaliser<N: Ndf + RadialSlopes + ?Sized>(n: &N, a: f64) -> f64 {
        a * n.slope_cdf(a) + tail(n, a, a)
    }

    /// P(r ≤ X) for visible normals, cot θ = a (a = ∞: the D·cos CDF).
    pub fn r_cdf<N: Ndf + RadialSlopes + ?Sized>(n: &N, a: f64, z: f64, x: f64) -> f64 {
        if a == f64::INFINITY {
            // (The clamp: a CDF may round a few ulp past 1.)
            return n.slope_cdf(x).clamp(0.0, 1.0);
        }
        if x <= a {
            (a * n.slope_cdf(x) / z).clamp(0.0, 1.0)
        } else {
            (1.0 - tail(n, a, x) / z).clamp(0.0, 1.0)
        }
    }

    /// The density of `r_cdf`: r P22(r) g(r)/Z.
    fn r_pdf<N: Ndf + RadialSlopes + ?Sized>(n: &N, a: f64, z: f64, r: f64) -> f64 {
        if a == f64::INFINITY {
            return n.slope_pdf(r);
        }
        let g = if r <= a {
            2.0 * PI * a
        } else {
            let y = ((r - a) * (r + a)).sqrt().atan2(a);
            2.0 * PI * a + 2.0 * r * h(y)
        };
        r * n.p22(r, 0.0) * g / z
    }

    /// ψ-CDF given r: ∫_{−ψ₀}^{ψ} (r cos t + a) dt / (2 (r sin ψ₀ + a ψ₀)), ψ₀ = acos(−a/r).
    pub fn psi_cdf(a: f64, r: f64, psi: f64) -> f64 {
        // NaN in (the inverse of a zero or NaN normal): NaN out (the clamp below needs
        // ordered bounds).
        if a.is_nan() || r.is_nan() || psi.is_nan() {
            return f64::NAN;
        }
        let (p0, s0) = psi_range(a, r);
        let psi = psi.clamp(-p0, p0);
        let weight = |t: f64| {
            if a.is_finite() {
                r * t.sin() + a * t
            } else {
                t
            }
        };
        let total = if a.is_finite() { r * s0 + a * p0 } else { p0 };
        ((weight(psi) + total) / (2.0 * total)).clamp(0.0, 1.0)
    }

    /// (ψ₀, sin ψ₀).
    fn psi_range(a: f64, r: f64) -> (f64, f64) {
        if r <= a || !a.is_finite() {
            (PI, 0.0)
        } else {
            let p0 = (-a / r).acos();
            (p0, ((r - a) * (r + a)).sqrt() / r)
        }
    }

    /// Visible slopes (r, ψ) relative to the direction's azimuth.
    pub fn sample<N: Ndf + RadialSlopes + ?Sized>(n: &N, a: f64, u: [f64; 2]) -> (f64, f64) {
        let z = if a.is_finite() { normaliser(n, a) } else { 1.0 };
        let lo = n.alpha().ln() - 745.0;
        let hi = n.alpha().ln() + 745.0;
        let s = newton_bracketed(
            |s| r_cdf(n, a, z, s.exp()) - u[0],
            |s| r_pdf(n, a, z, s.exp()) * s.exp(),
            lo,
            hi,
            n.alpha().ln(),
        );
        let r = s.exp();
        let (p0, s0) = psi_range(a, r);
        let psi = newton_bracketed(
            |t| psi_cdf(a, r, t) - u[1],
            |t| {
                if a.is_finite() {
                    (r * t.cos() + a) / (2.0 * (r * s0 + a * p0))
                } else {
                    1.0 / (2.0 * p0)
                }
            },
            -p0,
            p0,
            0.0,
        );
        (r, psi)
    }

    /// The u that [`sample`] maps to (r, ψ).
    pub fn invert<N: Ndf + RadialSlopes + ?Sized>(n: &N, a: f64, r: f64, psi: f64) -> [f64; 2] {
        let z = if a.is_finite() { normaliser(n, a) } else { 1.0 };
        [r_cdf(n, a, z, r), psi_cdf(a, r, psi)]
    }
}
