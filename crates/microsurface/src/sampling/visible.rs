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
/// where F is the NDF's radial D·cos CDF, T(X) = a (1 − F(X)) + J(X),
/// J(X) = 2 ∫_X^∞ r² P22 h dr, and Z = a + J(a) = a (1 + Λ). Given r, ψ has density
/// ∝ (r cos ψ + a) on |ψ| ≤ acos(−a/r), whose CDF is closed-form. Both are inverted by
/// safeguarded Newton (bracketed: at most 200 steps, each one CDF evaluation).
///
/// **The tail.** J is a tanh-sinh quadrature (relative tolerance 1e-13) on [X, ∞) under the
/// half-line map at the lobe's scale max(X, α). For an NDF with an algebraic tail of index β
/// ([`crate::RadialSlopes::slope_tail_index`]: GGX, GTR, Student-T) the integrand per ln r
/// falls like r^{−κ}, κ = β − 1; below κ = 1/2 (Student-T under γ = 7/4, κ = 2γ − 3) the mass
/// beyond the map's last node (1e-37 from its end), ~(1e-37)^κ, exceeds 1e-18, and as κ → 0
/// the rule's levels stop agreeing (each CDF evaluation then bisected to the depth limit).
/// Near γ = 3/2 most of the visible mass lies at slopes beyond f64 (99.86 % beyond r = 1e300
/// at γ = 1.500001, θ = 82°: Λ's pole is this mass). There the quadrature covers the lobe,
/// [X, M] with M = 1e3 max(X, α, 1) (the same map bent to end at M), and the decades
/// [M, R] in ln r, R = 1e16 max(a, α, 1); beyond R the tail is the power law's in closed
/// form, J(X) = J(R) (R/X)^κ with J(R) = 2 R³ P22(R) h(y(R))/κ (exact to the relative
/// corrections of the asymptotic form at R, ≤ 2e-16).
///
/// **Accuracy.** The normaliser Z against a(1 + Λ) from the NDF's own Λ: ≤ 1e-14 relative
/// (Student-T γ = 1.500001 … 2.5, a = 1e-300 … 1e5; tests/hardening.rs), and the CDFs agree
/// with mpmath to the same order. u ↦ (r, ψ) ↦ u round trips to 1e-12 (measured ≤ 4e-16;
/// tests/sampling.rs, tests/hardening.rs) wherever the sampled slope is at most
/// [`radial::R_MAX`]. A u₀ whose quantile lies beyond R_MAX (mass 1e-16 or more lies there
/// only for κ ≲ 0.05, Student-T below γ ≈ 1.53) gives r = R_MAX, the representable normal
/// nearest the horizon in the sampled azimuth, whose inverse is C(R_MAX) < u₀.
pub mod radial {
    use crate::math::quad::{integrate, integrate_scaled, integrate_to_inf};
    use crate::math::smith::h;
    use crate::math::solve::newton_bracketed;
    use crate::ndf::Ndf;
    use crate::sampling::dcos::RadialSlopes;
    use std::f64::consts::PI;

    /// The largest slope the sampler returns: stretched by α ≤ 1e6 it stays below 1e306, so
    /// the normal (θm within 1e-300 of the horizon) keeps a normal-range z and a finite D.
    pub const R_MAX: f64 = 1e300;

    /// Where a heavy algebraic tail (κ < 1/2, so Student-T γ < 7/4) is taken over by its power
    /// law, relative to max(a, α, 1): at 1e16 the relative corrections to the asymptotic
    /// form, (π/2) a/R from h and γ(γ − 1)α²/R² from P22, are ≤ 2e-16; P22(R) ∝ R^{−3−κ}
    /// stays normal up to R ~ 1e88, and where it underflows (a ≳ 1e72) the mass beyond R,
    /// ≲ 1/κ against Z ≥ a, is below 1e-50 of Z and is dropped with it.
    const TAIL_START: f64 = 1e16;

    /// Where the quadrature of an algebraic tail passes from r to ln r, relative to
    /// max(X, α, 1): past 1e3 the lobe's structure (its scale α, the cut at a ≤ X) is three
    /// decades behind, and what is left varies on the scale of ln r.
    const TAIL_BODY: f64 = 1e3;

    /// y = acos(a/r) ∈ [0, π/2] for r ≥ a, as atan2(√(r² − a²), a) without overflow.
    fn y_of(a: f64, r: f64) -> f64 {
        if r > 1e150 {
            let q = a / r;
            ((1.0 - q) * (1.0 + q)).sqrt().atan2(q)
        } else {
            ((r - a) * (r + a)).sqrt().atan2(a)
        }
    }

    /// An algebraic tail too heavy for the half-line map: (R, J(R), κ), the power law's
    /// start and its mass beyond it; `None` where the NDF declares no algebraic tail, where
    /// κ ≥ 1/2 (the map's last node, 1e-37 from its end, then leaves a mass ~(1e-37)^κ
    /// ≤ 1e-18 beyond it), or where R overflows (a > 1e292).
    fn heavy_tail<N: Ndf + RadialSlopes + ?Sized>(n: &N, a: f64) -> Option<(f64, f64, f64)> {
        // κ > 0: Λ finite (κ ≤ 0 is Student-T γ ≤ 3/2, which the direction API rejects).
        let kappa = n.slope_tail_index()? - 1.0;
        let r = TAIL_START * a.max(n.alpha()).max(1.0);
        if !(kappa > 0.0 && kappa < 0.5 && r.is_finite()) {
            return None;
        }
        // g(R) = 2 R³ P22(R) h(y), the integrand per unit ln r (R P22 first: R³ may
        // overflow), and J(R) = ∫_R^∞ g d ln r = g(R)/κ for g ∝ r^{−κ}.
        let g = 2.0 * (r * n.p22(r, 0.0)) * r * r * h(y_of(a, r));
        Some((r, g / kappa, kappa))
    }

    /// J(X) = 2 ∫_X^∞ r² P22(r) h(y) dr, cos y = a/r, for X ≥ a.
    fn tail_integral<N: Ndf + RadialSlopes + ?Sized>(n: &N, a: f64, x: f64) -> f64 {
        // r² P22(r) h(y) at r = x + d, d = r − x given exactly (r − a = (x − a) + d then
        // keeps y accurate near r = a).
        let integrand = |d: f64| {
            let r = x + d;
            if !r.is_finite() {
                return 0.0;
            }
            let y = if r > 1e150 {
                y_of(a, r)
            } else {
                let rma = (x - a) + d;
                (rma * (r + a)).sqrt().atan2(a)
            };
            // (r P22 first: r² overflows where P22 underflows.)
            r * (r * n.p22(r, 0.0)) * h(y)
        };
        let scale = x.max(n.alpha());
        let Some((r_top, j_top, kappa)) = heavy_tail(n, a) else {
            // On [x, ∞) by the half-line map at the lobe's scale.
            return 2.0 * integrate_to_inf(integrand, 0.0, scale, 1e-13).value;
        };
        if x >= r_top {
            // The power law: J(R) (R/X)^κ.
            return j_top * (-kappa * (x / r_top).ln()).exp();
        }
        // The lobe on [x, M] by the same map bent to end at M, then the algebraic tail on
        // [M, R] in t = ln(r/M), where it is smooth (it spreads its mass evenly over the
        // decades as κ → 0, which the half-line map's end-point clustering cannot resolve).
        let m = (TAIL_BODY * scale.max(1.0)).min(r_top);
        let lobe = integrate_scaled(integrand, 0.0, m - x, scale, 1e-13).value;
        let decades = if m < r_top {
            integrate(
                |t| {
                    let r = m * t.exp();
                    r * integrand(r - x)
                },
                0.0,
                (r_top / m).ln(),
                1e-13,
            )
            .value
        } else {
            0.0
        };
        2.0 * (lobe + decades) + j_top
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
            2.0 * PI * a + 2.0 * r * h(y_of(a, r))
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
        let Psi { p0, s0, wr, wa } = Psi::new(a, r);
        let psi = psi.clamp(-p0, p0);
        let total = wr * s0 + wa * p0;
        ((wr * psi.sin() + wa * psi + total) / (2.0 * total)).clamp(0.0, 1.0)
    }

    /// The ψ-density's support |ψ| ≤ ψ₀ (and sin ψ₀) and its weights: (r cos ψ + a) divided by
    /// the larger of r and a, wr cos ψ + wa (finite for r = ∞ and for a = ∞).
    struct Psi {
        p0: f64,
        s0: f64,
        wr: f64,
        wa: f64,
    }

    impl Psi {
        fn new(a: f64, r: f64) -> Psi {
            if r <= a || !a.is_finite() {
                // (a = r = 0: uniform.)
                let wr = if a > 0.0 && a.is_finite() { r / a } else { 0.0 };
                Psi {
                    p0: PI,
                    s0: 0.0,
                    wr,
                    wa: 1.0,
                }
            } else {
                let q = a / r;
                Psi {
                    p0: (-q).acos(),
                    s0: ((1.0 - q) * (1.0 + q)).sqrt(),
                    wr: 1.0,
                    wa: q,
                }
            }
        }
    }

    /// Visible slopes (r, ψ) relative to the direction's azimuth.
    pub fn sample<N: Ndf + RadialSlopes + ?Sized>(n: &N, a: f64, u: [f64; 2]) -> (f64, f64) {
        let z = if a.is_finite() { normaliser(n, a) } else { 1.0 };
        // Below α e^{−745} the slope is 0 in f64; R_MAX is the largest slope returned.
        let lo = n.alpha().ln() - 745.0;
        let hi = R_MAX.ln();
        let s = newton_bracketed(
            |s| r_cdf(n, a, z, s.exp()) - u[0],
            |s| r_pdf(n, a, z, s.exp()) * s.exp(),
            lo,
            hi,
            n.alpha().ln(),
        );
        let r = s.exp().min(R_MAX);
        let Psi { p0, s0, wr, wa } = Psi::new(a, r);
        let total = wr * s0 + wa * p0;
        let psi = newton_bracketed(
            |t| psi_cdf(a, r, t) - u[1],
            |t| (wr * t.cos() + wa) / (2.0 * total),
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
