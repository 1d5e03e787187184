//! The [`Ndf`] trait: what every NDF provides, and the identities written once.

pub mod beckmann;
pub mod bessel_k;
pub mod double_ggx;
pub mod ei;
pub mod erfc;
pub mod exponential;
pub(crate) mod family;
pub mod gen_exponential;
pub mod ggx;
pub mod gtr;
pub mod k0;
mod matched;
pub mod mixture;
pub(crate) mod slopes;
pub mod student_t;

pub use beckmann::Beckmann;
pub use bessel_k::BesselK;
pub use double_ggx::DoubleGgx;
pub use ei::Ei;
pub use erfc::Erfc;
pub use exponential::Exponential;
pub use family::{AnyNdf, NdfKind, NdfSpec, SpecError, UnknownNdf};
pub use gen_exponential::GenExponential;
pub use ggx::Ggx;
pub use gtr::Gtr;
pub use k0::K0;
pub use matched::{MatchBy, MatchError};
pub use student_t::StudentT;

/// Below u = GRAZING · min(σ(0), 1) Λ and σ take their grazing asymptotes σ(0)/u − ½ and
/// σ(0) ± u/2: the next terms are O(u) against σ(0)/u, and σ(0)(1 − sin θ) ≈ σ(0) u²/2, both
/// below 1e-40 relative, so every NDF gets the same exact-to-rounding values there without its
/// own route having to reach u ~ 1e-300. (The min: a superposition's components reach any
/// roughness, and at σ(0) = 1e30 the bound without it took u = 0.999 as grazing.)
const GRAZING: f64 = 1e-20;

/// A microfacet normal distribution function, isotropic, in the conventions of the crate docs.
///
/// Required: `d_pos` (D on (0, 1]), `p22`, `p2`, `lambda_pos` (Λ on (0, 1)) and `sigma_zero`
/// (σ(0)). Provided from them: the total `d` and `lambda` (every u), `sigma_neg` (σ(−u)),
/// `sigma` (signed direction), `g1`, `g2`, `g2_separable`. An NDF overrides a provided method
/// only where it has a better formula.
///
/// Every method is total: finite for every finite input (u is clamped to [−1, 1]), except
/// Λ(0) = +∞ (grazing: the true value). A NaN input gives NaN.
pub trait Ndf {
    /// Short lower-case name (`beckmann`, `ggx`, `gtr`, `double_ggx`, `exponential`).
    fn name(&self) -> &'static str;

    /// Roughness α.
    fn alpha(&self) -> f64;

    /// D(u) for 0 < u ≤ 1 (callers use [`Ndf::d`]).
    fn d_pos(&self, u: f64) -> f64;

    /// Slope density P22(p, q) = D(u) u⁴ with u = 1/√(1+p²+q²); ∫∫ P22 dp dq = 1.
    fn p22(&self, p: f64, q: f64) -> f64;

    /// Marginal slope density P2(p) = ∫ P22(p, q) dq.
    fn p2(&self, p: f64) -> f64;

    /// Smith Λ(u) for 0 < u < 1 (callers use [`Ndf::lambda`]).
    fn lambda_pos(&self, u: f64) -> f64;

    /// Projected area at grazing incidence, σ(0) = ∫∫ max(0, p) P22 dp dq.
    fn sigma_zero(&self) -> f64;

    /// D(u), u = cos θm; D = 0 for u ≤ 0; normalised so that ∫ D(m) cos θm dm = 1.
    fn d(&self, u: f64) -> f64 {
        if u.is_nan() {
            return u;
        }
        if u > 0.0 {
            self.d_pos(u.min(1.0))
        } else {
            0.0
        }
    }

    /// D(u) u for 0 < u ≤ 1, the density of D·cos sampling (callers use
    /// [`crate::sampling::pdf_dcos`]). Overridden where D overflows toward the horizon while
    /// D u does not (Student-T at γ < 2).
    fn d_cos_pos(&self, u: f64) -> f64 {
        self.d_pos(u) * u
    }

    /// σ(−u) = u Λ(u) for 0 < u < 1, the projected area seen from below (callers use
    /// [`Ndf::sigma`]). Overridden where σ(−u) has a more direct route than u · Λ(u).
    fn sigma_neg(&self, u: f64) -> f64 {
        u * self.lambda_pos(u)
    }

    /// Smith Λ(u) for every u: Λ(1) = 0, Λ(0) = +∞, and for u < 0 Heitz's extension
    /// Λ(u) = −1 − Λ(−u), so that u (1 + Λ(u)) = σ(u) holds for every u ≠ 0.
    fn lambda(&self, u: f64) -> f64 {
        if u.is_nan() {
            return u;
        }
        let u = u.clamp(-1.0, 1.0);
        if u == 0.0 {
            f64::INFINITY
        } else if u > 0.0 {
            if u >= 1.0 {
                0.0
            } else if u < GRAZING * self.sigma_zero().min(1.0) {
                // Λ = σ(0)/u − ½ + O(u): the rest is below 1e-20 of the sum here, and the
                // per-NDF routes (cot θ/α overflowing, quadratures of overflowing
                // integrands) need not reach this far.
                self.sigma_zero() / u - 0.5
            } else {
                self.lambda_pos(u)
            }
        } else {
            -1.0 - self.lambda(-u)
        }
    }

    /// Projected area σ(u) = ∫ max(0, ω·m) D(m) dm of the direction with cos θ = u, u ∈ [−1, 1]:
    /// σ(u) = u (1 + Λ(u)) for u > 0 and σ(−u) = u Λ(u); σ(1) = 1, σ(−1) = 0.
    fn sigma(&self, u: f64) -> f64 {
        if u.is_nan() {
            return u;
        }
        let u = u.clamp(-1.0, 1.0);
        let a = u.abs();
        if a == 0.0 {
            return self.sigma_zero();
        }
        let lit = u.max(0.0);
        if a >= 1.0 {
            return lit;
        }
        if a < GRAZING * self.sigma_zero().min(1.0) {
            // σ(±u) = σ(0) ± u/2 + O(u²) (see `lambda`).
            return self.sigma_zero() + 0.5 * u;
        }
        let shadow = self.sigma_neg(a);
        // Λ overflows only for u below ~1e-300 · α, where σ(±u) has reached σ(0).
        if !shadow.is_finite() {
            return self.sigma_zero() + lit;
        }
        lit + shadow
    }

    /// Smith masking G1(u) = 1/(1 + Λ(|u|)) (the direction is flipped to the upper hemisphere:
    /// for u < 0 this is the masking of the back side). G1(0) = 0, G1(±1) = 1.
    fn g1(&self, u: f64) -> f64 {
        if u.is_nan() {
            return u;
        }
        1.0 / (1.0 + self.lambda(u.abs()))
    }

    /// Height-correlated masking-shadowing G2 = 1/(1 + Λ(|u_o|) + Λ(|u_i|)).
    fn g2(&self, u_o: f64, u_i: f64) -> f64 {
        if u_o.is_nan() || u_i.is_nan() {
            return f64::NAN;
        }
        1.0 / (1.0 + self.lambda(u_o.abs()) + self.lambda(u_i.abs()))
    }

    /// Separable masking-shadowing G1(u_o) G1(u_i).
    fn g2_separable(&self, u_o: f64, u_i: f64) -> f64 {
        self.g1(u_o) * self.g1(u_i)
    }
}

/// Shape-invariant NDFs: D(u) = f(tan θ/α)/(α² u⁴), i.e. P22(p, q) = f(r/α)/α².
pub trait ShapeInvariant: Ndf {
    /// The α = 1 radial profile f(x), x = tan θm / α; even (f(−x) = f(x)).
    fn f(&self, x: f64) -> f64;
}
