//! The direction API for renderers, and anisotropy by stretching (written once for every
//! shape-invariant NDF).
//!
//! [`Microsurface`] works with unit vectors in the local shading frame (z = macro normal):
//! `d(wm)`, `lambda(w)`, `g1(w, wm)`, `g2(wo, wi, wm)`, the visible-normal density
//! `d_visible(w, wm) = G1(w) max(0, w·wm) D(wm)/w.z`, and samplers with their exact pdfs and
//! inverses. [`Stretched`] implements it for Beckmann, GGX, Double GGX and the Exponential NDF
//! with roughness (αx, αy): the α = 1 slopes are sampled and stretched by (αx, αy)
//! (pbrt's recipe: stretch, sample the α = 1 slopes, unstretch, build the normal).
//!
//! Conventions: a direction w is any finite nonzero vector (it is normalised, without
//! overflow for lengths up to f64::MAX; a zero or NaN vector is not a direction and gives
//! NaN). It may lie below the horizon (w.z < 0, the side of the surface opposite the macro
//! normal) or on it. Λ(w) depends on w only through tan²θ (the masking of the side w comes
//! from). G1(w, wm) is 0 when w·wm and w.z disagree in sign. For w.z < 0 the visible
//! normals are those seen from −w (the microsurface seen from below is sampled through its
//! mirror image, as in pbrt-v4); so `sample_visible(w, u) == sample_visible(−w, u)` and the
//! pdf matches. Normals given to D, the pdfs and the inverses are normalised the same way;
//! an inverse answers NaN for a normal no sampler returns (zero, NaN, below the horizon).

use crate::math::vec3::Vec3;
use crate::ndf::Ndf;
use crate::sampling::dcos::RadialSlopes;
use crate::sampling::visible::UnitSlopes;
use crate::{Beckmann, DoubleGgx, Exponential, Ggx, ParamError};
use std::f64::consts::PI;

/// NDFs with directions, samplers and pdfs.
pub trait Microsurface {
    /// D(wm); 0 for wm.z ≤ 0.
    fn d(&self, wm: Vec3) -> f64;

    /// Smith Λ(w) (a function of tan²θ; +∞ at grazing).
    fn lambda(&self, w: Vec3) -> f64;

    /// Projected area σ(w) = ∫ max(0, w·m) D(m) dm for a direction with w.z ≥ 0
    /// (= w.z (1 + Λ(w)), finite at grazing).
    fn sigma(&self, w: Vec3) -> f64;

    /// Density of [`Microsurface::sample_dcos`] w.r.t. solid angle: D(wm) cos θm.
    fn pdf_dcos(&self, wm: Vec3) -> f64 {
        let wm = wm.to_unit();
        if wm.z <= 0.0 {
            return 0.0;
        }
        self.d(wm) * wm.z
    }

    /// A normal distributed as D(m) cos θm.
    fn sample_dcos(&self, u: [f64; 2]) -> Vec3;

    /// The u that [`Microsurface::sample_dcos`] maps to `wm`.
    fn invert_dcos(&self, wm: Vec3) -> [f64; 2];

    /// A normal distributed as [`Microsurface::d_visible`]`(w, ·)`.
    fn sample_visible(&self, w: Vec3, u: [f64; 2]) -> Vec3;

    /// The u that [`Microsurface::sample_visible`] maps to `wm`.
    fn invert_visible(&self, w: Vec3, wm: Vec3) -> [f64; 2];
}

/// The direction of w (any finite nonzero length; NaN for a zero or non-finite w), mirrored
/// into the upper hemisphere.
fn upper(w: Vec3) -> Vec3 {
    let w = w.to_unit();
    if w.z < 0.0 {
        -w
    } else {
        w
    }
}

/// m, or where it lies on or behind the plane perpendicular to the unit w (w·m ≤ 0), m less
/// its component along w plus a margin of 1e-15, renormalised (m.z only grows, as w.z ≥ 0).
///
/// Every visible-normal sampler draws m with w·m > 0 almost surely, but the unstretch
/// magnifies the rounding of the α = 1 slopes (by up to αmax/αmin), and near the cap's
/// antipode of w the spherical-cap construction is a difference of near-opposite vectors:
/// the computed w·m can come out zero or slightly negative for a normal nearly perpendicular
/// to w, where the visible density (and the pdf) vanishes. This moves it just inside.
pub(crate) fn facing(m: Vec3, w: Vec3) -> Vec3 {
    let d = m.dot(w);
    if d > 0.0 {
        m
    } else {
        (m - w * (d - 2e-15)).normalize()
    }
}

/// The direction of a normal given to an inverse, if it is one a sampler can return: finite,
/// nonzero, in the closed upper hemisphere (None otherwise: the inverses answer NaN).
fn above(wm: Vec3) -> Option<Vec3> {
    let wm = wm.to_unit();
    (wm.z >= 0.0).then_some(wm)
}

/// A shape-invariant NDF with roughness (αx, αy), isotropic when αx = αy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stretched {
    kind: UnitSlopes,
    alpha_x: f64,
    alpha_y: f64,
}

impl Stretched {
    /// Beckmann, GGX, Double GGX or Exponential with roughness (αx, αy), each in [1e-6, 1e6].
    pub fn new(kind: UnitSlopes, alpha_x: f64, alpha_y: f64) -> Result<Self, ParamError> {
        let alpha_x = crate::error::check_alpha(alpha_x)?;
        let alpha_y = crate::error::check_alpha(alpha_y)?;
        Ok(Stretched {
            kind,
            alpha_x,
            alpha_y,
        })
    }

    /// Without the range check (superposition components reach any roughness > 0).
    pub(crate) fn raw(kind: UnitSlopes, alpha_x: f64, alpha_y: f64) -> Self {
        Stretched {
            kind,
            alpha_x,
            alpha_y,
        }
    }

    /// (αx, αy).
    pub fn alpha(&self) -> (f64, f64) {
        (self.alpha_x, self.alpha_y)
    }

    /// Which α = 1 slope distribution this is.
    pub fn kind(&self) -> UnitSlopes {
        self.kind
    }

    /// The α = 1 member of the family, for D, Λ and the radial CDF.
    fn unit(&self) -> UnitNdf {
        match self.kind {
            UnitSlopes::Beckmann => UnitNdf::Beckmann(Beckmann::new(1.0).expect("α = 1 is valid")),
            UnitSlopes::Ggx => UnitNdf::Ggx(Ggx::new(1.0).expect("α = 1 is valid")),
            UnitSlopes::DoubleGgx => {
                UnitNdf::DoubleGgx(DoubleGgx::new(1.0).expect("α = 1 is valid"))
            }
            UnitSlopes::Exponential => {
                UnitNdf::Exponential(Exponential::new(1.0).expect("α = 1 is valid"))
            }
        }
    }

    /// D at `wm` from the α = 1 member's D (`d1`): D_α(m) = D₁(u₁)/(αx αy ℓ⁴), with
    /// ℓ² = z² + (x/αx)² + (y/αy)² and u₁ = z/ℓ (P22 stretches as f(r₁)/(αx αy), u⁴ D = P22).
    fn d_with(&self, wm: Vec3, d1: impl Fn(f64) -> f64) -> f64 {
        let wm = wm.to_unit();
        if wm.z.is_nan() {
            return f64::NAN;
        }
        if wm.z <= 0.0 {
            return 0.0;
        }
        let (x, y) = (wm.x / self.alpha_x, wm.y / self.alpha_y);
        let l2 = wm.z * wm.z + x * x + y * y;
        let u1 = wm.z / l2.sqrt();
        d1(u1) / (self.alpha_x * self.alpha_y * l2 * l2)
    }

    /// Λ at `w` from the α = 1 member's Λ: Λ₁ at the stretched direction.
    fn lambda_with(&self, w: Vec3, lambda1: impl Fn(f64) -> f64) -> f64 {
        let s = self.stretch(upper(w));
        let l = s.length();
        if l == 0.0 {
            return f64::NAN;
        }
        lambda1(s.z / l)
    }

    /// σ at `w` from the α = 1 member's σ: σ_α(w) = |stretch(w)| σ₁(stretch(w)/|stretch(w)|).
    fn sigma_with(&self, w: Vec3, sigma1: impl Fn(f64) -> f64) -> f64 {
        let s = self.stretch(upper(w));
        let l = s.length();
        l * sigma1(s.z / l)
    }

    /// (αx x, αy y, z): the direction in the α = 1 configuration (not normalised).
    pub(crate) fn stretch(&self, w: Vec3) -> Vec3 {
        Vec3::new(self.alpha_x * w.x, self.alpha_y * w.y, w.z)
    }

    /// The normal ∝ (αx x̃, αy ỹ, 1) for α = 1 slopes (x̃, ỹ) of a normal ∝ (x̃, ỹ, 1).
    fn normal_from_unit_slopes(&self, x: f64, y: f64) -> Vec3 {
        let (p, q) = (self.alpha_x * x, self.alpha_y * y);
        Vec3::from_slopes(-p, -q)
    }

    /// α = 1 slopes of `wm` (inverse of `normal_from_unit_slopes`).
    fn unit_slopes(&self, wm: Vec3) -> (f64, f64) {
        (wm.x / (self.alpha_x * wm.z), wm.y / (self.alpha_y * wm.z))
    }

    /// For the visible sampler: cot θ' and the azimuth (cos φ', sin φ') of the stretched w.
    fn stretched_frame(&self, w: Vec3) -> (f64, f64, f64) {
        let s = self.stretch(upper(w));
        let h = crate::math::vec3::hypot(s.x, s.y);
        if h == 0.0 {
            return (f64::INFINITY, 1.0, 0.0);
        }
        (s.z / h, s.x / h, s.y / h)
    }
}

/// The α = 1 NDFs, for evaluation.
#[derive(Clone, Copy, Debug)]
enum UnitNdf {
    Beckmann(Beckmann),
    Ggx(Ggx),
    DoubleGgx(DoubleGgx),
    Exponential(Exponential),
}

impl UnitNdf {
    fn ndf(&self) -> &dyn Ndf {
        match self {
            UnitNdf::Beckmann(n) => n,
            UnitNdf::Ggx(n) => n,
            UnitNdf::DoubleGgx(n) => n,
            UnitNdf::Exponential(n) => n,
        }
    }
    fn quantile(&self, xi: f64) -> f64 {
        match self {
            UnitNdf::Beckmann(n) => n.slope_quantile(xi),
            UnitNdf::Ggx(n) => n.slope_quantile(xi),
            UnitNdf::DoubleGgx(n) => n.slope_quantile(xi),
            UnitNdf::Exponential(n) => n.slope_quantile(xi),
        }
    }
    fn cdf(&self, r: f64) -> f64 {
        match self {
            UnitNdf::Beckmann(n) => n.slope_cdf(r),
            UnitNdf::Ggx(n) => n.slope_cdf(r),
            UnitNdf::DoubleGgx(n) => n.slope_cdf(r),
            UnitNdf::Exponential(n) => n.slope_cdf(r),
        }
    }
}

impl Microsurface for Stretched {
    fn d(&self, wm: Vec3) -> f64 {
        self.d_with(wm, |u| self.unit().ndf().d(u))
    }

    fn lambda(&self, w: Vec3) -> f64 {
        self.lambda_with(w, |u| self.unit().ndf().lambda(u))
    }

    fn sigma(&self, w: Vec3) -> f64 {
        self.sigma_with(w, |u| self.unit().ndf().sigma(u))
    }

    fn sample_dcos(&self, u: [f64; 2]) -> Vec3 {
        let r = self.unit().quantile(u[0]);
        let (sin, cos) = (2.0 * PI * u[1]).sin_cos();
        if r == f64::INFINITY {
            return Vec3::new(self.alpha_x * cos, self.alpha_y * sin, 0.0).normalize();
        }
        self.normal_from_unit_slopes(r * cos, r * sin)
    }

    fn invert_dcos(&self, wm: Vec3) -> [f64; 2] {
        let Some(wm) = above(wm) else {
            return [f64::NAN; 2];
        };
        let (x, y) = self.unit_slopes(wm);
        let mut phi = y.atan2(x);
        if phi < 0.0 {
            phi += 2.0 * PI;
        }
        [
            self.unit().cdf(crate::math::vec3::hypot(x, y)),
            (phi / (2.0 * PI)).min(1.0),
        ]
    }

    fn sample_visible(&self, w: Vec3, u: [f64; 2]) -> Vec3 {
        let (a, c, s) = self.stretched_frame(w);
        let (x, y) = if self.kind == UnitSlopes::Ggx {
            ggx_spherical_cap(a, u)
        } else {
            self.kind.sample(a, u)
        };
        // Rotate from the frame of the stretched w back, then unstretch.
        facing(
            self.normal_from_unit_slopes(c * x - s * y, s * x + c * y),
            upper(w),
        )
    }

    fn invert_visible(&self, w: Vec3, wm: Vec3) -> [f64; 2] {
        let Some(wm) = above(wm) else {
            return [f64::NAN; 2];
        };
        let (a, c, s) = self.stretched_frame(w);
        let (gx, gy) = self.unit_slopes(wm);
        let (x, y) = (c * gx + s * gy, -s * gx + c * gy);
        if self.kind == UnitSlopes::Ggx {
            ggx_spherical_cap_inverse(a, x, y)
        } else {
            self.kind.invert(a, x, y)
        }
    }
}

/// GGX (α = 1) visible slopes by the spherical-cap method (Dupuy & Benyoub 2023), for a
/// direction in the xz-plane with cot θ = a: a point c uniform on the cap z ≥ −w.z of the unit
/// sphere, and the normal h = c + w.
fn ggx_spherical_cap(a: f64, u: [f64; 2]) -> (f64, f64) {
    let (wx, wz) = dir_from_cot(a);
    let phi = 2.0 * PI * u[0];
    // z + w.z = (1 − u₁)(1 + w.z), formed without the cancellation (at u₁ → 1 the sum
    // would round to either sign).
    let above = (1.0 - u[1]) * (1.0 + wz);
    // sin² = (1 − z)(1 + z) with 1 − z = u₁(1 + w.z), 1 + z = above + (1 − w.z) and
    // (1 − w.z)(1 + w.z) = w.x²: no cancellation at the poles (z → ±1), as 1 − z² has.
    let sin = (u[1] * (above * (1.0 + wz) + wx * wx)).max(0.0).sqrt();
    let (hx, hy, hz) = (sin * phi.cos() + wx, sin * phi.sin(), above);
    // Slopes of h ∝ (x̃, ỹ, 1).
    (hx / hz, hy / hz)
}

/// Inverse of [`ggx_spherical_cap`]: c = 2(ĥ·w)ĥ − w is the cap point (the reflection of w).
fn ggx_spherical_cap_inverse(a: f64, x: f64, y: f64) -> [f64; 2] {
    let (wx, wz) = dir_from_cot(a);
    let n = Vec3::new(x, y, 1.0).normalize();
    let d = n.x * wx + n.z * wz;
    let c = Vec3::new(2.0 * d * n.x - wx, 2.0 * d * n.y, 2.0 * d * n.z - wz);
    let mut phi = c.y.atan2(c.x);
    if phi < 0.0 {
        phi += 2.0 * PI;
    }
    let u1 = 1.0 - (c.z + wz) / (1.0 + wz);
    [(phi / (2.0 * PI)).min(1.0), u1.clamp(0.0, 1.0)]
}

/// (sin θ, cos θ) for cot θ = a ≥ 0 (a = ∞ at normal incidence).
fn dir_from_cot(a: f64) -> (f64, f64) {
    if a == f64::INFINITY {
        return (0.0, 1.0);
    }
    let l = (1.0 + a * a).sqrt();
    (1.0 / l, a / l)
}

/// Any isotropic NDF with the direction API; visible normals by the polar slope-space inversion
/// of [`crate::sampling::radial`] (the method used for GTR; exact to the quadrature's 1e-13).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Isotropic<N>(pub N);

impl<N: Ndf + RadialSlopes> Isotropic<N> {
    /// (cot θ, cos φ, sin φ) of w mirrored to the upper hemisphere.
    fn frame(w: Vec3) -> (f64, f64, f64) {
        let w = upper(w);
        let h = crate::math::vec3::hypot(w.x, w.y);
        if h == 0.0 {
            return (f64::INFINITY, 1.0, 0.0);
        }
        (w.z / h, w.x / h, w.y / h)
    }
}

impl<N: Ndf + RadialSlopes> Microsurface for Isotropic<N> {
    fn d(&self, wm: Vec3) -> f64 {
        self.0.d(wm.to_unit().z)
    }

    fn lambda(&self, w: Vec3) -> f64 {
        self.0.lambda(upper(w).z)
    }

    fn sigma(&self, w: Vec3) -> f64 {
        self.0.sigma(upper(w).z)
    }

    fn sample_dcos(&self, u: [f64; 2]) -> Vec3 {
        crate::sampling::dcos::sample_dcos(&self.0, u)
    }

    fn invert_dcos(&self, wm: Vec3) -> [f64; 2] {
        match above(wm) {
            Some(wm) => crate::sampling::dcos::invert_dcos(&self.0, wm),
            None => [f64::NAN; 2],
        }
    }

    fn sample_visible(&self, w: Vec3, u: [f64; 2]) -> Vec3 {
        let (a, c, s) = Self::frame(w);
        let (r, psi) = crate::sampling::visible::radial::sample(&self.0, a, u);
        facing(
            crate::sampling::dcos::normal_from_polar_slope(r, psi + s.atan2(c)),
            upper(w),
        )
    }

    fn invert_visible(&self, w: Vec3, wm: Vec3) -> [f64; 2] {
        let Some(wm) = above(wm) else {
            return [f64::NAN; 2];
        };
        let (a, c, s) = Self::frame(w);
        let r = crate::math::vec3::hypot(wm.x, wm.y) / wm.z;
        let mut psi = wm.y.atan2(wm.x) - s.atan2(c);
        if psi > PI {
            psi -= 2.0 * PI;
        } else if psi < -PI {
            psi += 2.0 * PI;
        }
        crate::sampling::visible::radial::invert(&self.0, a, r, psi)
    }
}

/// Any shape-invariant NDF of the family at roughness (αx, αy) (the Student-T, Ei, Erfc, K0,
/// Bessel-K and generalised exponential NDFs): D, Λ and σ of the α = 1 member at the
/// stretched direction (as [`Stretched`]), D·cos normals by the α = 1 radial quantile, and
/// visible normals by the exact polar slope-space inversion of [`crate::sampling::radial`] applied
/// to the α = 1 member in the stretched frame (so anisotropy comes for free, and the warp is
/// invertible).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shaped {
    /// The α = 1 member.
    unit: crate::AnyNdf,
    alpha_x: f64,
    alpha_y: f64,
    /// The posterior sampler of the Beckmann mixtures (not the generalised exponential).
    posterior: Option<crate::ndf::mixture::Posterior>,
}

impl Shaped {
    /// The α = 1 member of `ndf` and its posterior sampler (None for the generalised
    /// exponential): what [`Shaped`] keeps of the shape.
    pub fn unit_of(ndf: &crate::AnyNdf) -> (crate::AnyNdf, Option<crate::ndf::mixture::Posterior>) {
        (
            ndf.with_alpha(1.0),
            ndf.beckmann_mixing()
                .and_then(crate::ndf::mixture::Posterior::new),
        )
    }

    /// The member `unit` (α = 1, as [`Shaped::unit_of`] gives it, with its posterior) at
    /// roughness (αx, αy), each in [1e-6, 1e6].
    pub fn from_unit(
        unit: crate::AnyNdf,
        posterior: Option<crate::ndf::mixture::Posterior>,
        alpha_x: f64,
        alpha_y: f64,
    ) -> Result<Self, ParamError> {
        Ok(Shaped {
            unit,
            alpha_x: crate::error::check_alpha(alpha_x)?,
            alpha_y: crate::error::check_alpha(alpha_y)?,
            posterior,
        })
    }

    /// A visible normal for v above the horizon from a uniform stream
    /// ([`crate::MicrofacetDistribution::sample_wm_stream`]), for the Beckmann mixtures: the mixing
    /// variable by [`crate::ndf::mixture::Posterior`], then the Beckmann component's stream
    /// sampler at roughness (β αx, β αy). `None` for the generalised exponential (no such
    /// sampler), v on or below the horizon, or where a sampler gives up.
    pub fn sample_visible_stream(&self, v: Vec3, next: &mut dyn FnMut() -> f64) -> Option<Vec3> {
        let v = v.to_unit();
        self.posterior?
            .sample_visible::<f64>(v.into(), self.alpha_x, self.alpha_y, next)
            .map(Vec3::from)
    }

    /// The α = 1 member (its kind and shape parameter).
    pub fn unit(&self) -> &crate::AnyNdf {
        &self.unit
    }

    /// [`Stretched`]'s stretch helpers at (αx, αy) (its slope kind is not used by them).
    fn stretched(&self) -> Stretched {
        Stretched::raw(UnitSlopes::Ggx, self.alpha_x, self.alpha_y)
    }
}

impl Microsurface for Shaped {
    fn d(&self, wm: Vec3) -> f64 {
        // Near the pole D = P22₁(α = 1 slopes)/(αx αy cos⁴θ): the unit member's cos θ would
        // round to 1 below slopes ~1e-8, and D(1) is the pole (+∞) of the log- and
        // power-singular members (Ei, Erfc, K0, Bessel-K a ≤ 1) while P22 at the slopes is
        // still finite.
        // Near the horizon too, D₁ at the stretched cosine u₁ = z/ℓ underflows where D does
        // not (Student-T γ < 2 grows like z^{2γ−4}): both ends through the slopes
        // (AnyNdf::d_stretched, in logarithms there).
        let m = wm.to_unit();
        if m.z > 0.0 {
            let (ax, ay) = (self.alpha_x, self.alpha_y);
            let (sx, sy) = (m.x / ax, m.y / ay);
            let s2 = sx * sx + sy * sy;
            if s2 < 1e-4 * m.z * m.z || m.z < 1e-150 * s2.sqrt() {
                return self.unit.d_stretched(m.into(), ax, ay);
            }
        }
        self.stretched().d_with(wm, |u| self.unit.d(u))
    }

    fn pdf_dcos(&self, wm: Vec3) -> f64 {
        // D cos θm where D itself overflows toward the horizon (Student-T at γ < 2, D ~
        // z^{2γ−4}): the slopes' form with one power of z fewer, in logarithms there.
        let m = wm.to_unit();
        if m.z > 0.0 {
            let s = crate::math::vec3::hypot(m.x / self.alpha_x, m.y / self.alpha_y);
            if m.z < 1e-150 * s {
                return self
                    .unit
                    .d_cos_k_stretched(m.into(), self.alpha_x, self.alpha_y, 1);
            }
        } else {
            return if m.z.is_nan() { m.z } else { 0.0 };
        }
        self.d(m) * m.z
    }

    fn lambda(&self, w: Vec3) -> f64 {
        // From the stretched vector's cot θ = z/|(αx x, αy y)| where the member has Λ of cot θ
        // (the Beckmann mixtures): through the cosine, 1 − u² near the normal carries u's
        // rounding, 2ε/sin²θ relative (4e-5 of Λ at cot θ = 3e5 for Student-T near γ = 3/2).
        let s = self.stretched().stretch(upper(w));
        let h = crate::math::vec3::hypot(s.x, s.y);
        let cot = s.z / h;
        if h > 0.0 && s.z > 0.0 && cot.is_finite() {
            if let Some(l) = self.unit.lambda_x(cot) {
                return l;
            }
        }
        self.stretched().lambda_with(w, |u| self.unit.lambda(u))
    }

    fn sigma(&self, w: Vec3) -> f64 {
        self.stretched().sigma_with(w, |u| self.unit.sigma(u))
    }

    fn sample_dcos(&self, u: [f64; 2]) -> Vec3 {
        let r = self.unit.slope_quantile(u[0]);
        let (sin, cos) = (2.0 * PI * u[1]).sin_cos();
        if r == f64::INFINITY {
            return Vec3::new(self.alpha_x * cos, self.alpha_y * sin, 0.0).normalize();
        }
        self.stretched().normal_from_unit_slopes(r * cos, r * sin)
    }

    fn invert_dcos(&self, wm: Vec3) -> [f64; 2] {
        let Some(wm) = above(wm) else {
            return [f64::NAN; 2];
        };
        let (x, y) = self.stretched().unit_slopes(wm);
        let mut phi = y.atan2(x);
        if phi < 0.0 {
            phi += 2.0 * PI;
        }
        [
            self.unit
                .slope_cdf(crate::math::vec3::hypot(x, y))
                .clamp(0.0, 1.0),
            (phi / (2.0 * PI)).min(1.0),
        ]
    }

    fn sample_visible(&self, w: Vec3, u: [f64; 2]) -> Vec3 {
        let st = self.stretched();
        let (a, c, s) = st.stretched_frame(w);
        let (r, psi) = crate::sampling::visible::radial::sample(&self.unit, a, u);
        let phi = psi + s.atan2(c);
        let (sp, cp) = phi.sin_cos();
        if r == f64::INFINITY {
            return facing(
                Vec3::new(self.alpha_x * cp, self.alpha_y * sp, 0.0).normalize(),
                upper(w),
            );
        }
        facing(st.normal_from_unit_slopes(r * cp, r * sp), upper(w))
    }

    fn invert_visible(&self, w: Vec3, wm: Vec3) -> [f64; 2] {
        let Some(wm) = above(wm) else {
            return [f64::NAN; 2];
        };
        let st = self.stretched();
        let (a, c, s) = st.stretched_frame(w);
        let (gx, gy) = st.unit_slopes(wm);
        let r = crate::math::vec3::hypot(gx, gy);
        let mut psi = gy.atan2(gx) - s.atan2(c);
        if psi > PI {
            psi -= 2.0 * PI;
        } else if psi < -PI {
            psi += 2.0 * PI;
        }
        crate::sampling::visible::radial::invert(&self.unit, a, r, psi)
    }
}
