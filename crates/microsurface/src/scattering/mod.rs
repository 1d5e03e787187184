//! Multiple scattering: the microsurface random walk of Heitz et al. 2016 ([`RandomWalk`],
//! its facets, the walk's BSDF [`MultipleScattering`], albedos by order and the
//! single-scattering albedo by quadrature), energy compensation of the single-scattering
//! BSDFs ([`CompensatedConductor`], [`CompensatedDielectric`] over [`AlbedoTable`] and
//! [`DielectricTables`]), albedo tables over (α, μ) ([`table`]), and the tables real-time
//! engines load ([`lut`]: the split sum, E and E_avg, a dielectric's R and T).
//!
//! # The random walk
//!
//! Multiple scattering on the microsurface: the random walk of Heitz, Hanika, d'Eon and
//! Dachsbacher (2016), "Multiple-Scattering Microfacet BSDFs with the Smith Model", for every
//! NDF of the library (through [`MicrofacetDistribution`](crate::MicrofacetDistribution)).
//!
//! **The model.** The Smith microsurface is a volume of microflakes with normals distributed
//! as D, stacked over heights h with a height distribution P1 (CDF C1). A ray travelling in
//! direction w (unit) at height h meets the microsurface above h' < h … the walk's free path
//! is the height at which it next intersects: for a ray going up (w.z > 0) it escapes with
//! probability G1(w, h) = C1(h)^Λ(w), else it meets the surface at the height h' with
//! C1(h') = C1(h)/(1 − U)^{1/Λ(w)} (U uniform); going down (w.z < 0) it always meets it, the
//! same formula with Λ(w) = −1 − Λ(−w) ≤ −1 (Smith's Λ extended to the lower hemisphere, the
//! paper's eq. 8). At each intersection the ray picks a microfacet among those it sees, the
//! visible normals D_{−w}(m) ∝ max(0, −w·m) D(m), and scatters off it (a conductor: mirror
//! reflection with Fresnel weight; a diffuse facet: a cosine lobe about m). The walk's output
//! is the direction it leaves in, the product of the weights, and the number of scattering
//! events (the order).
//!
//! **Heights.** The BSDF does not depend on the height distribution (the paper, section 4.1:
//! the walk's heights are a monotone reparametrisation of C1 ∈ [0, 1]). [`Heights::Uniform`]
//! (h ∈ [−1, 1]) and [`Heights::Gaussian`] (standard normal) are both provided, and
//! tests/walk.rs checks that they give the same albedos within the Monte Carlo error. The walk
//! starts above the surface (C1 = 1). Every formula above is in ln C1(h), which is what the
//! walk carries as its height: ℓ = ln C1 ≤ 0, the free path ℓ' = ℓ − ln(1 − U)/Λ(w), the
//! escape test ln(1 − U) < Λ ℓ, G1(w, h) = exp(Λ ℓ), and a crossing into the other medium
//! (h → −h, C1 → 1 − C1 for both symmetric distributions) ℓ → ln(1 − e^ℓ). For uniform heights
//! ℓ is an exact change of variable (C1 affine in h), so a step costs one logarithm and no
//! conversion; for Gaussian heights each step goes through the physical height,
//! h = Φ⁻¹(e^ℓ) and back (as the paper's code does), which changes the random numbers' roundoff
//! and nothing else. In ℓ nothing underflows: a path far below the surface's top (C1 below
//! the smallest f64) keeps its height.
//!
//! **Visible normals from below.** A ray going up can still meet the microsurface; its
//! visible normals are those of the direction v = −w with v.z < 0, D_v(m) ∝ max(0, v·m) D(m)
//! over the upper hemisphere of m (normalisation σ(v) = |v.z| Λ(|v|)). [`MicrofacetDistribution`](crate::MicrofacetDistribution)'s
//! sampler mirrors a down-welling direction (pbrt's convention), which is another
//! distribution; the walk samples D_v by rejection from D_{v′}, v′ = (v.x, v.y, |v.z|): for m
//! in the upper hemisphere v·m = v′·m − 2|v.z| m.z ≤ v′·m, so accepting m with probability
//! max(0, v·m)/(v′·m) leaves exactly D_v (acceptance σ(v)/σ(v′) = Λ/(1 + Λ), which is small
//! only for steep upward rays, and those rarely meet the surface: the expected number of
//! candidates per step stays bounded). Where the distribution samples D_v from a uniform
//! stream ([`MicrofacetDistribution::sample_wm_stream`](crate::MicrofacetDistribution::sample_wm_stream): GGX, Beckmann, Double GGX) that is used
//! instead, for rays going down too (Beckmann's rejection there is cheaper than its exact
//! warp): one call without the full sampler per candidate (BENCHMARKS.md).
//!
//! **Order 1** is the single-scattering BSDF with the height-correlated G2 (the paper's
//! section 5.3): for a conductor with F = 1, E₁(μ) = ∫ D G2/(4μ) dωi, which
//! [`single_scattering_albedo`] integrates deterministically and tests/walk.rs holds the
//! walk's order 1 to, within 4 standard errors; for a dielectric, the reflection with the
//! same G2 and the transmission with B(1 + Λo, 1 + Λi)
//! ([`crate::bsdf::Masking::CorrelatedBeta`], not the BSDF's default), which
//! [`single_scattering_albedo_dielectric_level`] integrates.
//!
//! **Uniforms** are drawn strictly inside (0, 1) (53-bit uniforms shifted by half a step): a
//! uniform of exactly 0 in the height step would leave the ray at its height forever, and
//! one that rounds to 1 would make a walk leave with no bounce (a bug of a public f32 port
//! of the paper's code).
//!
//! # Energy compensation
//!
//! Energy compensation for the single-scattering rough conductor and dielectric, for every
//! NDF: the energy a single-scattering microfacet BSDF loses (1 − E(μ), E its directional
//! albedo with F = 1, or a dielectric's reflection plus transmission; the report's albedo
//! plot, and [`crate::scattering`]'s higher orders) put back by
//!
//! * **Kulla & Conty 2017** ("Revisiting Physically Based Shading at Imageworks", section
//!   "Multiple scattering"): an added lobe f_ms(μo, μi) = (1 − E(μo))(1 − E(μi))/(π(1 −
//!   E_avg)), E_avg = 2∫E(μ)μ dμ, times F_ms = F_avg² E_avg/(1 − F_avg(1 − E_avg)) with
//!   F_avg = 2∫F(μ)μ dμ (their eq. for the Fresnel-weighted multiple-scattering term). With
//!   F = 1, ∫ f_ms cos θi dωi = 1 − E(μo), so the white furnace is 1.
//! * **Turquin 2019** ("Practical multiple scattering compensation for microfacet models"):
//!   the single-scattering lobe scaled by 1 + F0 (1 − E(μo))/E(μo) (F0 the Fresnel term at
//!   normal incidence), so that with F = 1 the furnace is E(μo)/E(μo) = 1; sampling is the
//!   single-scattering lobe's.
//!
//! **The table.** [`AlbedoTable`] holds E(μ) of one material (F = 1, height-correlated G2)
//! at 33 nodes uniform in √μ (E changes fastest at grazing μ) from
//! [`crate::scattering::single_scattering_albedo`]'s quadrature, and interpolates by cubic
//! Lagrange on the four nearest nodes in √μ; E_avg integrates the interpolant (Gauss–
//! Legendre on each interval), so that the compensation's own integral identities hold for
//! the interpolant exactly and the white furnace's error is the interpolation error alone:
//! ≤ 1e-3 required, measured in tests/compensate.rs for every NDF and α ∈ [0.05, 2].
//!
//! **Anisotropy.** An anisotropic material's albedo depends on wo's azimuth φ too (a GGX
//! α = (0.9, 0.2) conductor keeps 92 % of the energy at μ = 0.2 along one axis and 80 % along
//! the other), so its table holds E(μ, φ): a cosine series in 2φ from [`AZIMUTHS`] azimuths
//! (E is even in φ and symmetric about π/2), each coefficient cubic in √μ
//! ([`AlbedoTable::e_dir`]). Both schemes then read E at the direction itself (f_ms =
//! (1 − E(wo))(1 − E(wi))/(π(1 − E_avg)), E_avg the hemispherical average), so the furnace holds
//! along every azimuth: within 4.4e-4 at GGX aspects of 4 and 4.5 and 6.3e-5 for Beckmann at
//! 3, where the azimuth's mean alone (the table before) missed it by 2.4–15.5 %
//! (tests/compensate.rs; BENCHMARKS.md, "Materials per call").
//!
//! **Dielectrics.** [`CompensatedDielectric`] (see there for the two-sided Kulla–Conty
//! split and its reciprocity) over [`DielectricTables`]: E(μ) from outside and from inside
//! at the material's η, 65 nodes each, from
//! [`crate::scattering::single_scattering_albedo_dielectric`]: shipped for the isotropic materials
//! at five common indices (`data/compensation/*-dielectric.mfd`, interpolated in ln α),
//! computed at construction otherwise (under a second). White furnace (importance transport, both
//! sides) within 1e-3, measured ≤ 1.9e-4 over every NDF (tests/compensate.rs).

pub(crate) mod albedo;
pub(crate) mod compensation;
pub mod lut;
pub(crate) mod progress;
pub mod table;
pub(crate) mod walk;

pub use albedo::*;
pub use compensation::*;
pub use progress::{Cancel, Cancellable, Cancelled, Progress};
pub use walk::*;
