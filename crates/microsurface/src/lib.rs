//! # microsurface
//!
//! Microfacet normal distribution functions (NDFs) for physically based rendering, with every
//! quantity of d'Eon's *Hitchhiker's Guide to Multiple Scattering* NDF pages and Burley's GTR
//! appendix: D, the slope densities P22 and P2, the shape-invariant profile f, the projected
//! area σ, Smith's Λ, G1 and G2 — exact, and checked against mpmath references and against the
//! identities that tie them together ([`verify`]).
//!
//! ## Conventions (stated once)
//! * Local frame: z is the macro-surface normal. u = cos θ of a microfacet normal (for D) or of
//!   a direction (for Λ, σ, G1); θ is measured from z. tan θ = √(1−u²)/u.
//! * Slopes: a normal m = (−p, −q, 1)/√(1+p²+q²); P22(p, q) = D(u) u⁴ with u = 1/√(1+p²+q²),
//!   ∫∫ P22 dp dq = 1, and P2(p) = ∫ P22(p, q) dq.
//! * Normalisation: ∫ D(m) cos θm dm = 2π ∫₀¹ D(u) u du = 1; D = 0 for u ≤ 0.
//! * Projected area for a signed direction: σ(u) = ∫ max(0, ω·m) D(m) dm, u ∈ [−1, 1];
//!   σ(u) = u (1 + Λ(u)) and σ(−u) = u Λ(u) for u > 0.
//! * Smith Λ(u) = (1/a) ∫_a^∞ (q − a) P2(q) dq with a = cot θ; G1 = 1/(1+Λ);
//!   height-correlated G2 = 1/(1 + Λo + Λi).
//! * Shape-invariant NDFs ([`ShapeInvariant`]): P22(p, q) = f(r/α)/α² with r = √(p²+q²).
//!
//! ## The family
//! [`Beckmann`], [`Ggx`], [`Gtr`], [`DoubleGgx`], [`Exponential`]; [`AnyNdf`] holds any of them
//! (for command lines and sweeps). Constructors return `Result<_, ParamError>`.
//!
//! ## Directions, sampling and BSDFs: one door
//! [`Microfacet`]`<F, N>` is the direction API for renderers, one type for every NDF, f32 or
//! f64, anisotropic: D, Λ, G1, G2 (height-correlated and separable), the visible-normal
//! density, and samplers taking explicit uniforms that return each normal with its pdf
//! ([`Distribution`]). It runs the fast paths; [`Microfacet::exact`] gives the same material's
//! validated f64 path ([`Exact`], with the samplers' inverses; [`Exact::new`] picks the NDF at
//! run time). [`frame`], [`fresnel`] and [`bsdf`] build rough conductors and dielectrics on
//! it. [`sample`] has D·cos sampling of the 1-D NDF types (mixtures included).
//!
//! ## Fast paths
//! [`fast`] has the scalar functions of u behind [`Microfacet`]: GGX and Beckmann D, Λ, G1, G2
//! in f64 and f32 at the cost of the textbook formulas (benchmarked against C in
//! `crates/microsurface-bench`), fitted Λ, σ, G1, G2 for Double GGX, the Exponential NDF and GTR
//! at any γ (relative error ≤ 1e-7), and slice forms (`fast::batch`, parallel with the `rayon`
//! feature). Their samplers are [`Microfacet`]'s.
//!
//! ## The contract
//! Every public function and method holds it; `tests/fuzz.rs` (a seeded fuzz suite, about
//! 5·10⁶ hostile evaluations in CI, 10⁸ with `MICROSURFACE_FUZZ_SCALE=20`) checks it.
//! * **No panic**, for any input, in or out of contract (a zero or NaN normal given to an
//!   inverse or a pdf, u = 1, NaN parameters to the fast paths). Constructors return
//!   `Err(ParamError)` for parameters outside α ∈ [1e-6, 1e6], γ ∈ (0, 100]. The one
//!   exception is a programming error, not an input: `fast::batch`'s slice functions panic
//!   when given slices of different lengths, as slice indexing does.
//! * **In contract**: cosines u ∈ [−1, 1], including ±0, subnormals and 1 + 2ε (the z of a
//!   rounded unit vector, treated as 1); uniforms in [0, 1)², exactly 0 and 1 − ε included;
//!   directions w any finite nonzero vector (any length: they are normalised; below the
//!   horizon, w.z < 0, they are mirrored, in the fast paths as in the exact API; on it,
//!   z = ±0 or 1e-300). The fast scalar Λ, G1, G2 take u ∈ [0, 1] (−0 and 1 + 2ε included).
//!   Finite in-contract input gives finite output, except where the true value is +∞ or
//!   overflows: Λ = +∞ at u = 0 and where Λ ~ σ(0)/u overflows; the poles of the singular
//!   family members, D(1) = P22(0, 0) = +∞ for Ei, Erfc, K0 and Bessel-K a ≤ 1 (and so
//!   the pdfs at m = (0, 0, 1) exactly), P2(0) = +∞ for Erfc and Bessel-K a ≤ ½; densities
//!   that grow past f64::MAX (Bessel-K a < 1: P22 ~ r^{2a−2} at r ≲ 10^{−308/(2−2a)} α;
//!   Student-T γ < 2: D ~ u^{2γ−4} at grazing u); Student-T γ ≤ 3/2: σ = Λ = +∞ (E|p| = ∞),
//!   G1 = 0. Near the pole the sampler pdfs are computed through the slopes, finite for
//!   every normal off the exact pole.
//! * **Bounds**: D ≥ 0, Λ ≥ 0 for u > 0, G1 and G2 in [0, 1], G2 ≤ min(G1(u_o), G1(u_i)),
//!   σ ≥ 0; every fast path within its documented relative error ([`fast`]'s table) wherever
//!   the exact value is a normal float (fast GTR Λ: where Λ > 1e-280, absolute below).
//! * **Samplers** return a finite unit normal in the closed upper hemisphere, visible from w
//!   (w·m ≥ 0, to rounding), for every in-contract u; its pdf is finite, and > 0 at interior
//!   u with w off the horizon.
//! * **Out of contract** (a normal that is zero, NaN or below the horizon given to an inverse,
//!   a zero or NaN direction, u outside [0, 1) to a sampler): NaN, or the value the method's
//!   docs name; never a panic. Pdfs of such normals are NaN, 0 or a non-negative number.
//!
//! ## Sources
//! d'Eon, *A Hitchhiker's Guide to Multiple Scattering* (2020) and its NDF pages (GGX,
//! Double GGX, GTR, Exponential NDF); Burley 2012, *Physically-Based Shading at Disney*,
//! appendix B; Heitz 2014 (masking-shadowing), Heitz & d'Eon 2014 and Heitz 2018 (visible
//! normals), Dupuy & Benyoub 2023 (spherical caps), Eto & Tokuyoshi 2023 (bounded VNDF),
//! Walter et al. 2007. What the implementation established beyond them (corrections to the
//! pages, closed forms they lack, cancellations, limits) is in `docs/derivations.md`, which
//! the module docs cite by section ("derivations.md A.14").
//!
//! ## Accuracy
//! Closed forms: ≤ 1e-13 relative (absolute 1e-300 where the value underflows). Quantities
//! computed by quadrature (GTR Λ/σ/P2 for general γ, the Exponential NDF's Λ/σ): ≤ 1e-10
//! relative documented, ≤ 1e-13 measured. Each module's docs say how.
//!
//! ```
//! use microsurface::{Ggx, Ndf};
//! let ggx = Ggx::new(0.3).unwrap();
//! let u = 0.5;
//! assert!((ggx.sigma(u) - u * (1.0 + ggx.lambda(u))).abs() < 1e-15);
//! assert!(Ggx::new(-1.0).is_err());
//! ```

pub mod any_microfacet;
pub mod beckmann;
pub mod bessel_k;
pub mod bsdf;
pub mod chi2;
pub mod compensate;
pub mod distribution;
pub mod double_ggx;
pub mod ei;
pub mod erfc;
pub mod error;
pub mod exponential;
pub mod family;
pub mod fast;
pub mod frame;
pub mod fresnel;
pub mod gen_exponential;
pub mod ggx;
pub mod gtr;
pub mod k0;
pub(crate) mod microsurface;
pub mod mixture;
pub mod ndf;
pub mod quad;
pub mod sample;
pub mod smith;
pub mod solve;
pub mod special;
pub mod stochastic;
pub mod student_t;
pub mod table;
pub mod vec3;
pub mod verify;
pub mod visible;
pub mod walk;

pub use any_microfacet::AnyMicrofacet;
pub use beckmann::Beckmann;
pub use bessel_k::BesselK;
pub use distribution::{Distribution, Exact, Microfacet, Sample};
pub use double_ggx::DoubleGgx;
pub use ei::Ei;
pub use erfc::Erfc;
pub use error::ParamError;
pub use exponential::Exponential;
pub use family::{AnyNdf, NdfKind, NdfSpec, SpecError};
pub use fast::Real;
pub use gen_exponential::GenExponential;
pub use ggx::Ggx;
pub use gtr::Gtr;
pub use k0::K0;
pub use ndf::{Ndf, ShapeInvariant};
pub use sample::RadialSlopes;
pub use student_t::StudentT;
pub use vec3::Vec3;
pub use visible::UnitSlopes;

// Every Rust snippet of the README compiles and runs as a doctest.
#[doc = include_str!("../../../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
