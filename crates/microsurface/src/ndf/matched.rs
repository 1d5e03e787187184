//! Matched roughness: the α at which one NDF has the same value of a chosen quantity as
//! another. α is not comparable across NDFs (at α = 0.3 the mean slopes of the book's NDFs
//! differ by several times), so comparisons of shapes hold one quantity fixed instead:
//! d'Eon's *A Hitchhiker's Guide to Multiple Scattering* compares its NDFs at equal
//! G1 at 45° and at equal projected area at grazing; the median of the D·cos distribution is
//! the roughness a sampler's histogram shows.
//!
//! [`AnyNdf::matched`] finds α by bisection in ln α over the whole accepted range
//! [1e-6, 1e6] (64 halvings: the bracket is then below 1e-17 in relative α, so the match is
//! as accurate as the quantity itself: the exact path's ≤ 1e-13 for closed forms, ≤ 1e-10
//! for quadratures; tests/matched.rs checks the quantities agree to that). Each quantity is
//! monotone in α for a fixed shape (a shape-invariant NDF scales its slopes by α; GTR's
//! features move monotonically with it), which the bisection needs.

use super::{AnyNdf, Ndf, NdfKind};
use crate::error::{ParamError, ALPHA_MAX, ALPHA_MIN};
use crate::ndf::slopes::RadialSlopes;
use std::fmt;
use std::str::FromStr;

/// The quantity two NDFs are matched by ([`AnyNdf::matched`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MatchBy {
    /// Smith's G1 at θ = 45° (cos θ = 1/√2): the masking of a typical direction (the
    /// book's matched-masking comparison). Decreasing in α. Matched through Λ(45°), which
    /// falls like e^{−1/α²} for light tails and like α² for GGX's: a smooth Beckmann
    /// (α ≲ 0.3) has no GGX match by it ([`MatchError::Unreachable`]).
    G1At45,
    /// The projected area at grazing σ(0) = lim u Λ(u) as u → 0, = E(max(0, −p)) = E|p|/2
    /// over the slope marginal: how much the microsurface sticks out sideways. Increasing
    /// in α; infinite for Student-T at γ ≤ 3/2 (no match then).
    SigmaZero,
    /// The mean slope E(tan θm) under D cos θm (the slope density P22). For an isotropic
    /// NDF E(tan θm) = π σ(0) (E|p| = (2/π) E(r) for a radially symmetric density), so this
    /// is the same match as [`MatchBy::SigmaZero`], offered under the name researchers use.
    MeanSlope,
    /// The median of tan θm under D cos θm ([`RadialSlopes::slope_quantile`] at ½): the
    /// roughness a histogram of D·cos samples shows; finite for every NDF.
    DcosMedian,
}

impl MatchBy {
    /// Every quantity, in the order of the names below.
    pub const ALL: [MatchBy; 4] = [
        MatchBy::G1At45,
        MatchBy::SigmaZero,
        MatchBy::MeanSlope,
        MatchBy::DcosMedian,
    ];

    /// The name [`FromStr`] reads and the Python package takes (`by="g1_45"`).
    pub fn name(self) -> &'static str {
        match self {
            MatchBy::G1At45 => "g1_45",
            MatchBy::SigmaZero => "sigma0",
            MatchBy::MeanSlope => "mean_slope",
            MatchBy::DcosMedian => "dcos_median",
        }
    }

    /// The quantity of `ndf` (its exact path).
    pub fn of(self, ndf: &AnyNdf) -> f64 {
        match self {
            MatchBy::G1At45 => ndf.g1(std::f64::consts::FRAC_1_SQRT_2),
            MatchBy::SigmaZero => ndf.sigma_zero(),
            MatchBy::MeanSlope => std::f64::consts::PI * ndf.sigma_zero(),
            MatchBy::DcosMedian => ndf.slope_quantile(0.5),
        }
    }
}

impl MatchBy {
    /// What the bisection compares: the quantity, or for G1 at 45° its Λ (the same match:
    /// G1 = 1/(1 + Λ), but Λ keeps its relative precision where G1 rounds to 1, e.g.
    /// Beckmann at α = 0.05, where Λ(45°) ≈ 2e-175).
    fn key(self, ndf: &AnyNdf) -> f64 {
        match self {
            MatchBy::G1At45 => ndf.lambda(std::f64::consts::FRAC_1_SQRT_2),
            _ => self.of(ndf),
        }
    }
}

impl fmt::Display for MatchBy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Why [`AnyNdf::matched`] found no α.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MatchError {
    /// The NDF's shape parameter is invalid (or α at the range's ends, which cannot be).
    Param(ParamError),
    /// The quantity is not a finite number for the reference, or no α in [1e-6, 1e6] gives
    /// it: `target` is the reference's value, `range` the NDF's values at the range's ends.
    Unreachable {
        by: MatchBy,
        target: f64,
        range: (f64, f64),
    },
    /// An unknown name for [`MatchBy`].
    UnknownQuantity,
}

impl fmt::Display for MatchError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MatchError::Param(e) => e.fmt(f),
            MatchError::Unreachable { by, target, range } => write!(
                f,
                "no alpha in [1e-6, 1e6] matches {by} = {target:e} (the NDF's {by} there runs from {:e} to {:e})",
                range.0, range.1
            ),
            MatchError::UnknownQuantity => f.write_str(
                "the quantity to match must be 'g1_45', 'sigma0', 'mean_slope' or 'dcos_median'",
            ),
        }
    }
}

impl std::error::Error for MatchError {}

impl From<ParamError> for MatchError {
    fn from(e: ParamError) -> Self {
        MatchError::Param(e)
    }
}

impl FromStr for MatchBy {
    type Err = MatchError;
    fn from_str(s: &str) -> Result<Self, MatchError> {
        MatchBy::ALL
            .into_iter()
            .find(|m| m.name().eq_ignore_ascii_case(s))
            .ok_or(MatchError::UnknownQuantity)
    }
}

impl AnyNdf {
    /// The NDF `kind` (with `shape`, as [`AnyNdf::new`]) at the α whose quantity `by` equals
    /// `reference`'s: matched roughness (the module's page). Bisection in ln α over [1e-6,
    /// 1e6]; [`MatchError::Unreachable`] where the reference's value is not finite or lies
    /// outside the NDF's range of it (Student-T at γ ≤ 3/2 has σ(0) = ∞; a reference
    /// rougher than any α of the NDF).
    pub fn matched(
        kind: NdfKind,
        shape: Option<f64>,
        reference: &AnyNdf,
        by: MatchBy,
    ) -> Result<AnyNdf, MatchError> {
        let target = by.key(reference);
        let at = |ln_alpha: f64| -> Result<f64, ParamError> {
            // (The ends exactly: exp(ln 1e6) rounds above 1e6.)
            let a = ln_alpha.exp().clamp(ALPHA_MIN, ALPHA_MAX);
            Ok(by.key(&AnyNdf::new(kind, a, shape)?))
        };
        let (mut lo, mut hi) = (ALPHA_MIN.ln(), ALPHA_MAX.ln());
        let (q_lo, q_hi) = (at(lo)?, at(hi)?);
        let inside = (q_lo.min(q_hi)..=q_lo.max(q_hi)).contains(&target);
        if !target.is_finite() || !inside {
            let of = |q: f64| match by {
                MatchBy::G1At45 => 1.0 / (1.0 + q),
                _ => q,
            };
            return Err(MatchError::Unreachable {
                by,
                target: by.of(reference),
                range: (of(q_lo), of(q_hi)),
            });
        }
        let rising = q_hi > q_lo;
        // 64 halvings of a bracket 27.6 wide in ln α: below 1e-17 relative in α. (Where the
        // quantity is flat, Λ(45°) = 0 below α ≈ 0.04 for Beckmann, every α there matches:
        // the bisection returns one of them.)
        for _ in 0..64 {
            let mid = 0.5 * (lo + hi);
            if (at(mid)? < target) == rising {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let alpha = (0.5 * (lo + hi)).exp().clamp(ALPHA_MIN, ALPHA_MAX);
        Ok(AnyNdf::new(kind, alpha, shape)?)
    }
}
