//! The typed error returned by every NDF constructor.

use std::fmt;

/// Smallest and largest supported roughness. Outside [1e-6, 1e6] the closed forms still hold
/// mathematically, but D at the normal (∝ 1/α²) and the slope densities leave the comfortable
/// f64 range and the numerical quantities would need other scalings; we reject rather than
/// return garbage.
pub const ALPHA_MIN: f64 = 1e-6;
/// See [`ALPHA_MIN`].
pub const ALPHA_MAX: f64 = 1e6;
/// Largest supported GTR exponent γ. Above it the GTR lobe is a narrow spike of relative width
/// ~1/√γ that the quadrature of the numerical quantities is not tuned for.
pub const GAMMA_MAX: f64 = 100.0;

/// Why a parameter was rejected.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum ParamError {
    /// α is NaN, infinite, ≤ 0, or outside [`ALPHA_MIN`, `ALPHA_MAX`].
    Alpha(f64),
    /// γ (GTR) is NaN, ≤ 0 or above [`GAMMA_MAX`].
    Gamma(f64),
    /// αx ≠ αy for GTR at this γ ≠ 2 (GTR is shape invariant, and so stretchable, only at
    /// γ = 2, where it is GGX: [`crate::Microfacet::gtr`]).
    Anisotropic(f64),
    /// A shape parameter of the NDF family outside its supported range: `name` says which
    /// (e.g. `student_t gamma`), `range` the range accepted.
    Shape {
        name: &'static str,
        range: &'static str,
        value: f64,
    },
    /// A relative index of refraction η (a dielectric's, or the walk's dielectric facets')
    /// that is NaN, infinite or ≤ 0.
    Eta(f64),
}

/// A rejected value as an error message shows it: in full where that is short, in
/// scientific notation where it would be long (1e300 written out is 301 digits).
struct Shown(f64);

impl fmt::Display for Shown {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if x != 0.0 && x.is_finite() && !(1e-4..1e7).contains(&x.abs()) {
            write!(f, "{x:e}")
        } else {
            write!(f, "{x}")
        }
    }
}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            ParamError::Alpha(a) => write!(
                f,
                "alpha must be a finite number in [{ALPHA_MIN:e}, {ALPHA_MAX:e}], got {}",
                Shown(a)
            ),
            ParamError::Gamma(g) => write!(
                f,
                "gamma must be a finite number in (0, {GAMMA_MAX}], got {}",
                Shown(g)
            ),
            ParamError::Shape { name, range, value } => {
                write!(f, "{name} must be a finite number in {range}, got {}", Shown(value))
            }
            ParamError::Eta(e) => write!(
                f,
                "eta (a relative index of refraction) must be a finite number > 0, got {}",
                Shown(e)
            ),
            ParamError::Anisotropic(g) => write!(
                f,
                "GTR is anisotropic only at gamma = 2 (where it is GGX); got alpha_x != alpha_y at gamma = {}",
                Shown(g)
            ),
        }
    }
}

impl std::error::Error for ParamError {}

/// Checks α; written so that NaN fails (`!(x >= lo)` is true for NaN).
pub(crate) fn check_alpha(alpha: f64) -> Result<f64, ParamError> {
    if !(ALPHA_MIN..=ALPHA_MAX).contains(&alpha) {
        return Err(ParamError::Alpha(alpha));
    }
    Ok(alpha)
}

/// Checks a relative index η: finite and > 0 (NaN fails).
pub(crate) fn check_eta(eta: f64) -> Result<f64, ParamError> {
    if !(eta > 0.0 && eta.is_finite()) {
        return Err(ParamError::Eta(eta));
    }
    Ok(eta)
}

/// Checks γ (NaN fails the range test).
pub(crate) fn check_gamma(gamma: f64) -> Result<f64, ParamError> {
    if !(gamma > 0.0 && gamma <= GAMMA_MAX) {
        return Err(ParamError::Gamma(gamma));
    }
    Ok(gamma)
}

/// Checks a shape parameter against (lo, hi] (`open_lo`) or [lo, hi]; NaN fails.
pub(crate) fn check_shape(
    value: f64,
    lo: f64,
    open_lo: bool,
    hi: f64,
    name: &'static str,
    range: &'static str,
) -> Result<f64, ParamError> {
    let above = if open_lo { value > lo } else { value >= lo };
    if !(above && value <= hi) {
        return Err(ParamError::Shape { name, range, value });
    }
    Ok(value)
}
