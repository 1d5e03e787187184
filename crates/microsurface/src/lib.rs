//! # microsurface
//!
//! Microfacet theory for physically based rendering: every NDF of d'Eon's *Hitchhiker's Guide
//! to Multiple Scattering* (Beckmann, GGX, GTR, Double GGX, the Exponential NDF, Student-T,
//! Ei, Erfc, K0, Bessel-K, the generalised exponential) with every quantity (D, the slope
//! densities, σ, Smith's Λ, G1, G2, D·cos and visible-normal sampling), exact and fast, in
//! f32 and f64; rough conductor and dielectric BSDFs; multiple scattering by the
//! microsurface random walk and by energy compensation.
//!
//! ## For renderers
//!
//! Materials chosen by name at run time ([`AnyMicrofacet`], a spec string as a scene file
//! writes it), every BSDF behind one trait ([`bsdf::Bsdf`], `Value = [F; 3]` for RGB),
//! evaluated and sampled in the local shading frame (z = the shading normal):
//!
//! ```
//! use microsurface::prelude::*;
//! let metal = AnyMicrofacet::<f32>::parse("trowbridge_reitz", 0.3, 0.1)?; // anisotropic GGX
//! let gold = fresnel::Conductor { eta: [0.14, 0.42, 1.37], k: [3.98, 2.38, 1.60] };
//! let glass = AnyMicrofacet::<f32>::parse("student_t:2.5", 0.2, 0.2)?;
//! let bsdfs: Vec<Box<dyn Bsdf<f32, Value = [f32; 3]>>> = vec![
//!     Box::new(RoughConductor::new(metal, gold)),
//!     Box::new(RoughDielectric::new(glass, 1.5)?),
//! ];
//! let frame = Frame::from_normal_tangent([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]);
//! let wo = frame.to_local([0.48, 0.0, 0.8775]); // toward the viewer, world → local
//! for bsdf in &bsdfs {
//!     let s = bsdf.sample(wo, 0.5, [0.3, 0.7]).expect("a direction");
//!     let (f, pdf) = (bsdf.eval(wo, s.wi), bsdf.pdf(wo, s.wi));
//!     assert!(f[1] > 0.0 && (pdf - s.pdf).abs() <= 1e-3 * pdf);
//!     let _wi = frame.from_local(s.wi); // local → world
//! }
//! # Ok::<(), microsurface::SpecError>(())
//! ```
//!
//! The static [`Microfacet<F, N>`](Microfacet) is the same material with the NDF fixed at
//! compile time (bit-identical values); [`scattering`] adds multiple scattering
//! ([`scattering::CompensatedConductor`], [`scattering::CompensatedDielectric`], the random
//! walk's [`scattering::MultipleScattering`]), all of them `Box<dyn Bsdf<f32, Value =
//! [f32; 3]>>` too. [`fast::batch`] has slice forms of the hottest paths.
//!
//! ## For researchers
//!
//! Exact values by cosine ([`Ndf`]: closed forms to 1e-13, quadratures to 1e-10, checked
//! against mpmath), the identities that tie them together as residuals ([`check::verify`]),
//! the exact invertible samplers ([`Exact`], one explicit call away:
//! [`AnyMicrofacet::exact`]) and the random walk's albedos by order:
//!
//! ```
//! use microsurface::scattering::{albedo, MirrorFacets, RandomWalk, Heights};
//! use microsurface::{bsdf::fresnel::One, Ggx, Ndf, StudentT};
//! let t = StudentT::new(0.3, 4.0)?; // between GGX (γ = 2) and Beckmann (γ → ∞)
//! assert!((t.lambda(0.5) / 0.005324521393580268 - 1.0).abs() < 1e-13); // mpmath
//! let g = Ggx::new(0.3)?;
//! assert!((g.sigma(0.5) - 0.5 * (1.0 + g.lambda(0.5))).abs() < 1e-15); // σ = u (1 + Λ)
//! let walk = RandomWalk::new(microsurface::Microfacet::<f64, Ggx>::new(1.0, 1.0)?, Heights::Uniform);
//! let a = albedo(&walk, &MirrorFacets(One::<1>), [0.6, 0.0, 0.8], 20_000, 1);
//! assert!((a.reflect.total - 1.0).abs() < 1e-12); // a white furnace keeps all energy
//! # Ok::<(), microsurface::ParamError>(())
//! ```
//!
//! ## Layout
//!
//! | module | what |
//! |---|---|
//! | [`ndf`] | the research layer, by cos θ: the [`Ndf`] trait, one module per NDF, [`AnyNdf`], [`NdfKind`] and [`NdfSpec`] (names), the Beckmann superpositions ([`ndf::mixture`]) |
//! | [`distribution`] | the renderer layer, by direction: [`MicrofacetDistribution`], [`Microfacet<F, N>`](Microfacet), [`AnyMicrofacet`], [`Exact`] |
//! | [`sampling`] | D·cos and visible-slope sampling of the 1-D NDFs, the pages' stochastic samplers |
//! | [`bsdf`] | the [`bsdf::Bsdf`] trait, [`bsdf::RoughConductor`], [`bsdf::RoughDielectric`], [`bsdf::fresnel`], [`bsdf::frame`] |
//! | [`scattering`] | multiple scattering: the random walk, albedos, energy compensation, albedo tables |
//! | [`check`] | identities ([`check::verify`]), the χ² harness ([`check::chi2`]), quadrature |
//! | [`fast`] | the fast scalar kernels behind the materials, and their slice forms |
//! | [`prelude`] | what a renderer imports in one line |
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
//! * BSDFs: pbrt-v4's conventions (both directions away from the surface, `wo` toward the
//!   viewer, f without the cosine, pdf per solid angle; [`bsdf`]).
//!
//! ## The contract
//! Every public function and method holds it; `tests/fuzz.rs` (a seeded fuzz suite) checks
//! it: 7.8·10⁶ hostile evaluations in CI (about 35 s on two cores, release), 1.09·10⁸ with
//! `MICROSURFACE_FUZZ_SCALE=14` (about 9 minutes). The first five points are the NDFs' and
//! their materials'; the rest say the same of the types built on them.
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
//! * **The run-time door** ([`AnyMicrofacet`]): `new`, `from_spec` and `parse` answer `Ok`
//!   or a typed error (a one-line message) for any parameters and any string; an accepted
//!   material has both α in [1e-6, 1e6], is the NDF asked for, names itself by a spec that
//!   parses back to it, and is the static type bit for bit.
//! * **Fresnel** ([`bsdf::fresnel`]): `dielectric` for cos θ ∈ [−1, 1] and any finite η > 0,
//!   `conductor` for cos θ ∈ [0, 1] (clamped) and any finite η, k ≥ 0, `schlick` for
//!   F0 ∈ [0, 1], `f82_tint` for F0 ∈ [0, 1] and any finite tint: finite and in [0, 1];
//!   η = 1 (n = 1) is 0 at every angle, the complex index η + 0i is the dielectric (1e-12;
//!   √ε at the critical angle's square-root edge); the [`bsdf::fresnel::Fresnel`] terms are
//!   the functions, channel by channel.
//! * **Frames** ([`bsdf::frame`]): [`bsdf::frame::Frame::from_normal`] of any finite nonzero
//!   normal and [`bsdf::frame::Frame::from_normal_tangent`] with any tangent (zero, NaN or
//!   parallel to n: `from_normal`'s) are orthonormal and right-handed to 1e-14 (f32 5e-6),
//!   with s along the tangent's part orthogonal to n; `to_local` and `from_local` are inverse;
//!   `normalize` of a finite nonzero vector is unit; `refract` of unit vectors at any η > 0
//!   is unit and on the other side; the half vectors are unit in z ≥ 0, or `None`.
//! * **BSDFs** ([`bsdf::Bsdf`]: [`bsdf::RoughConductor`] with any Fresnel term above,
//!   [`bsdf::RoughDielectric`] at any finite η > 0, 1 ± ε and 1e±6 included, every
//!   [`bsdf::Masking`], both transports, over every NDF, f32 and f64), for unit wo, wi (on
//!   and below the horizon, subnormal z) and uniforms in [0, 1): `eval` finite and ≥ 0
//!   (+∞ only at a singular NDF's pole, wo and wi on the axis), `pdf` finite and ≥ 0,
//!   `eval_pdf` the two bit for bit (every BSDF, the walk's included). A
//!   sample is `None` or has a unit wi (1e-12, f32 1e-5) on the side its lobe names, a
//!   finite pdf ≥ 2.2e-158 (f32 1.2e-20; a delta lobe's: its probability, ≤ 1), a finite
//!   f ≥ 0, and a weight f|cos θi|/pdf ≤ 1 for F ≤ 1 (1/η'² for a radiance transmission)
//!   within 1e-12 + 8ε/|wo·wm| (f32: 2e-6 + 8ε/|wo·wm|): so the white furnace, the albedo
//!   ∫ f |cos θi| dωi of a conductor with F = 1 or of a dielectric (importance transport),
//!   is at most 1. A non-specular sample's weight is eval |cos θi|/pdf at its wi, to the
//!   same tolerance, and that pdf is > 0, wherever the half vector is resolvable from the
//!   rounded directions (recomputed from them it moves by δ = 4ε(1 + η')/|η' wi + wo|; below
//!   1e-2 of |wo·wm|, |wi·wm|, wm.z and α wm.z); a conductor's on its F = 1 lobe, which
//!   bounds its f. A conductor is reciprocal to the bit, f(wo, wi) = f(wi, wo). Out of
//!   contract (η ≤ 0, ∞ or NaN; zero, NaN or non-unit directions; uniforms ≥ 1 or NaN): no
//!   panic.
//! * **Compensation** ([`scattering::CompensatedConductor`],
//!   [`scattering::CompensatedDielectric`] over [`scattering::AlbedoTable`] and
//!   [`scattering::DielectricTables`]): the BSDFs' bounds; Kulla–Conty's samples carry
//!   `eval` and `pdf` at their wi exactly and its conductor is reciprocal to the bit;
//!   Turquin's weights are eval |cos θi|/pdf where the half vector is resolvable; the white
//!   furnace (F = 1) of an isotropic material is at most 1 + 1e-3 (the tables'
//!   interpolation); a shipped table (any α, η, shape asked for) is `None` or finite values
//!   in [0, 1] (1e-3).
//! * **The walk** ([`scattering::RandomWalk`], [`scattering::MultipleScattering`]): a walk
//!   from wo.z = 0 or NaN is `None`, else its exit direction is unit (on wo's side for opaque
//!   facets), its order ≥ 1, its weight in [0, 1]; `RandomWalk::eval` is finite and ≥ 0 by
//!   order, Λ of a travel direction ≥ 0 going up and ≤ −1 going down, σ(v) − σ(−v) = v.z.
//!   The walk's BSDF: `eval` (a stochastic estimate) and `pdf` finite and ≥ 0; a sample's
//!   pdf is `pdf` at its wi (the MIS proxy, the same function) and its weight ≤ 1 for F ≤ 1
//!   (1/η'² for a radiance transmission) within 1e-9 (f32 1e-5).
//! * **Tables** ([`scattering::table`]): `Grid::from_bytes` of any bytes is an error or a
//!   grid whose values fill it; `Spec::validate` answers for any parameters; `Grid::value`
//!   outside the grid is NaN. [`scattering::lut`]: a spec is a typed error or a table of
//!   finite values (albedos ≤ 1 within the rule's error at its level); `Lut::lookup` and
//!   `Lut::exact` answer any coordinates (NaN where they are NaN or out of range for
//!   `exact`).
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
//! Closed forms: ≤ 1e-13 relative (absolute 1e-300 where the value underflows), or, far in a
//! tail where the value's condition number κ = |d ln v/d ln x| in its input x is large,
//! ≤ 4ε·κ (what the rounding of the binary input alone costs any implementation: D of a
//! Beckmann lobe at 1e-300 has κ ≈ 1400; `tests/data/extra-tails.json` records κ with each
//! value). Quantities computed by quadrature (GTR Λ/σ/P2 for general γ, the Exponential NDF's
//! Λ/σ): ≤ 1e-10 relative documented, ≤ 1e-13 measured. Each module's docs say how.
//!
pub mod bsdf;
pub mod check;
pub mod distribution;
mod error;
pub mod fast;
mod math;
pub mod ndf;
pub mod prelude;
pub mod sampling;
pub mod scattering;

pub use distribution::{AnyMicrofacet, Exact, Microfacet, MicrofacetDistribution, Sample};
pub use error::{ParamError, ALPHA_MAX, ALPHA_MIN, GAMMA_MAX};
pub use fast::Real;
pub use math::vec3::Vec3;
pub use ndf::{
    AnyNdf, Beckmann, BesselK, DoubleGgx, Ei, Erfc, Exponential, GenExponential, Ggx, Gtr, Ndf,
    NdfKind, NdfSpec, ShapeInvariant, SpecError, StudentT, K0,
};
pub use sampling::{RadialSlopes, UnitSlopes};

// Every Rust snippet of the README compiles and runs as a doctest.
#[doc = include_str!("../../../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
