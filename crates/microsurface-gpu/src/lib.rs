//! The `microsurface` fast paths as a WGSL shader library, and a small wgpu compute runner
//! that checks it against the Rust f32 path.
//!
//! # The library
//!
//! [`WGSL`] is the library's one source: the files under `wgsl/` of this crate (common,
//! Fresnel, GGX, the tables' binding, the uniform stream, Beckmann, Double GGX, the
//! Exponential NDF, the Beckmann mixtures and Student-T, GTR, the run-time distribution, the
//! rough conductor and dielectric, energy compensation) in one string, and [`TABLES`] the
//! contents of its one storage buffer (the fitted tables, generated from the Rust library).
//! WGSL has no `#include`: a shader includes the library by being compiled with it in front,
//! which WGSL allows as module-scope declarations may come in any order. From Rust:
//!
//! ```
//! let shader = format!("{}\n{}", microsurface_gpu::WGSL, "
//!     @group(0) @binding(0) var<storage, read_write> out: array<f32>;
//!     const MS_TABLES_GROUP: u32 = 1u;   // where this shader would bind TABLES
//!     const MS_TABLES_BINDING: u32 = 0u;
//!     @compute @workgroup_size(64)
//!     fn main(@builtin(global_invocation_id) id: vec3<u32>) {
//!         let wo = vec3<f32>(0.48, 0.0, 0.8775);
//!         let s = ms_ggx_sample(wo, vec2<f32>(0.3, 0.1), vec2<f32>(0.25, 0.5));
//!         out[id.x] = s.pdf;
//!     }");
//! // (naga, the compiler wgpu uses, validates it.)
//! let module = naga::front::wgsl::parse_str(&shader).expect("parses");
//! naga::valid::Validator::new(Default::default(), Default::default())
//!     .validate(&module)
//!     .expect("validates");
//! ```
//!
//! and from any other build, by prepending the generated one-file form
//! `generated/microsurface.wgsl` (the same string, written by `examples/translate.rs`, which
//! also writes GLSL 450, HLSL, MSL and SPIR-V translations of the library with its test
//! kernels through naga). Every public name starts with `ms_` (`Ms`, `MS_` for types and
//! constants).
//!
//! | WGSL | Rust (f32) |
//! |---|---|
//! | `ms_ggx_d(wm, α)`, `ms_ggx_lambda(w, α)`, `ms_ggx_g1(w, α)` | `Microfacet::<f32, Ggx>` `d`, `lambda`, `g1` |
//! | `ms_ggx_g2(wo, wi, α)`, `ms_ggx_g2_separable(wo, wi, α)` | `g2`, `g2_separable` |
//! | `ms_ggx_pdf(w, wm, α)`, `ms_ggx_sample(w, α, u)` → `MsSample` | `pdf` (= `d_visible`), `sample` (spherical caps) |
//! | `ms_ggx_sample_dcos(α, u)`, `ms_ggx_pdf_dcos(wm, α)` | `sample_dcos`, `pdf_dcos` |
//! | `ms_ggx_sample_bounded(w, α, u)`, `ms_ggx_pdf_bounded(w, wm, α)`, `ms_ggx_pdf_bounded_reflection(wo, wi, α)` | `sample_bounded`, `pdf_bounded`, `pdf_bounded_reflection` |
//! | `ms_beckmann_d`, `ms_beckmann_lambda`, `ms_beckmann_g1`, `ms_beckmann_g2`, `ms_beckmann_g2_separable` | `Microfacet::<f32, Beckmann>` `d`, `lambda`, `g1`, `g2`, `g2_separable` |
//! | `ms_beckmann_pdf(w, wm, α)`, `ms_beckmann_sample(w, α, u)`; `ms_beckmann_sample_dcos`, `ms_beckmann_pdf_dcos` | `pdf`, `sample` (the same warp of u: slope-space inversion); `sample_dcos`, `pdf_dcos` |
//! | `ms_double_ggx_d`, `_lambda`, `_g1`, `_g2`, `_g2_separable`, `_pdf`, `_sample`, `_pdf_dcos`, `_sample_dcos`; `ms_exponential_` the same | `Microfacet::<f32, DoubleGgx>`, `Microfacet::<f32, Exponential>`: `d`, `lambda`, `g1`, `g2`, `g2_separable`, `pdf`, `sample`, `pdf_dcos`, `sample_dcos` (rejection samplers over the stream of u, as the Rust ones: the same candidates, so mostly the same normal; χ²-consistent) |
//! | `ms_gtr_d(wm, α, table)`, `_lambda`, `_g1`, `_g2`, `_g2_separable`, `_pdf`, `_pdf_dcos`, `_sample_dcos`, `_sample` (the material's `table` from [`Tables::add_gtr`]) | `Microfacet::<f32, Gtr>::gtr(α, α, γ)`: `d`, `lambda`, `g1`, `g2`, `g2_separable`, `pdf`, `pdf_dcos`, `sample_dcos` (Burley's inversion, the same warp of u), `sample` (the Rust rejection sampler over the stream of u: the same candidates, so the same normal to f32's rounding; χ²-consistent); γ = 2 is GGX's functions, anisotropic allowed |
//! | `ms_student_t_d(wm, α, table)`, `_lambda(w, α, table)`, `_g1`, `_g2`, `_g2_separable`, `_pdf`, `_pdf_dcos`, `_sample_dcos` (the Rust radial-quantile warp), `_sample` (the posterior); `ms_ei_`, `ms_erfc_`, `ms_k0_`, `ms_bessel_k_` the same (their D·cos by the prior, then Beckmann's D·cos; Bessel-K's `d` takes the table too) | `Microfacet::<f32, StudentT>` (γ), `Ei`, `Erfc`, `K0`, `BesselK` (a) (the family's fast path: Λ from the shape's fitted table, here rounded to f32 in the material's table; visible normals by the mixing variable's posterior, then Beckmann's stream sampler, and the mixtures' D·cos by the prior, over the same uniforms as Rust: the same normal where the f32 arithmetic allows) |
//! | [`Tables`] + `Tables::add_shape(kind, shape)`, `Tables::add_gtr(α, γ)` → the `table` row of `MsMicrofacet` | `fast::fitted::FittedShape` (built once per shape), `fast::gtr::FittedGtr` (per material) |
//! | `ms_stream_new(u)`, `ms_stream_next(&state)`, `ms_stream_next_u64`; `ms_zig_exp1(w, &state)`, `ms_zig_half_normal`, `ms_zig_normal`; `ms_ln_gamma_variate(k, &state)` | `distribution::UniformStream` (SplitMix64 seeded by u's bits, bit for bit); `fast::ziggurat::{exp1, half_normal, normal}`; Marsaglia & Tsang's Gamma variates |
//! | `ms_fresnel_dielectric`, `ms_fresnel_conductor`, `ms_fresnel_schlick`, `ms_fresnel_f82_tint`; `MsFresnel` + `ms_fresnel_eval` | `bsdf::fresnel::{dielectric, conductor, schlick, f82_tint}`; the `Fresnel` terms |
//! | `MsMicrofacet(ndf, α, table)` (`MS_NDF_GGX`, `_BECKMANN`, `_DOUBLE_GGX`, `_EXPONENTIAL`, `_GTR`, `_STUDENT_T`, `_EI`, `_ERFC`, `_K0`, `_BESSEL_K`; `table` the material's table row (GTR's, or a shape's), 0 for the first four) + `ms_d`, `ms_lambda`, `ms_g1`, `ms_g2`, `ms_g2_separable`, `ms_pdf`, `ms_pdf_dcos`, `ms_sample`, `ms_sample_dcos`; `override MS_DOOR_NDFS` (the NDFs a pipeline's door may meet, one bit each: set it per pipeline, [`Gpu::pipeline_with`], and the compiler drops the others) | `MicrofacetDistribution` over `AnyMicrofacet` (the generalised exponential not yet on the GPU) |
//! | `MsConductor` + `ms_conductor_eval`, `ms_conductor_pdf`, `ms_conductor_eval_pdf`, `ms_conductor_sample` → `MsBsdfSample` | `bsdf::RoughConductor` (`Masking::Correlated` or `Separable`) |
//! | `MsDielectric` + `ms_dielectric_eval`, `ms_dielectric_pdf`, `ms_dielectric_sample` → `MsBsdfSample` | `bsdf::RoughDielectric` (`Masking::Correlated` or `Separable`; both transports) |
//! | `MsLutTap` + `ms_lut_tap(x, n)` (texel centres), `ms_lut_tap_edges(x, n)` (edge-aligned nodes), `ms_lut_index`, `ms_lut_lerp`, `ms_lut_bilerp`, `ms_lut_roughness_coord(α, α_max)` | `scattering::lut::Lut::lookup` (`Nodes::Centres`, clamp-to-edge; `Nodes::Edges`) |
//! | `ms_kulla_conty_f_ms(F_avg, E_avg)`, `ms_kulla_conty_lobe(E(μo), E(μi), E_avg)`, `ms_conductor_eval_kulla_conty`, `ms_conductor_pdf_kulla_conty`, `ms_conductor_sample_kulla_conty` + `ms_kulla_conty_sample_f` (E(μi) at the sampled wi); `ms_turquin_scale(E(μo), F0)`, `ms_conductor_eval_turquin`, `ms_conductor_sample_turquin` (pdf: `ms_conductor_pdf`) | `scattering::CompensatedConductor` (`Scheme::KullaConty`, `Scheme::Turquin`) `eval`, `pdf`, `sample` |
//! | `ms_lut_index3`, `ms_lut_eta_coord(η)` (√((η − 1)/2)), `ms_lut_trilerp`, `ms_lut_bilerp_eta`; `ms_dielectric_kulla_conty_k`, `ms_dielectric_kulla_conty_lobe`, `ms_dielectric_eval_kulla_conty`, `ms_dielectric_kulla_conty_lobe_pdf`, `ms_dielectric_pdf_kulla_conty`, `ms_dielectric_sample_kulla_conty` + `ms_dielectric_kulla_conty_sample_f` (E_t(μi) of the sampled side); `ms_dielectric_eval_turquin`, `ms_dielectric_sample_turquin` (pdf: `ms_dielectric_pdf`) (over `LutKind::Dielectric` and `DielectricAvg`, E = R + T) | `Lut::lookup`; `scattering::CompensatedDielectric` (`Scheme::KullaConty`, `Scheme::Turquin`) `eval`, `pdf`, `sample` |
//! | `ms_reflect`, `ms_refract`, `ms_half_vector_reflection`, `ms_half_vector_refraction`, `ms_jacobian_refraction` | `bsdf::frame` |
//!
//! Conventions are the Rust crate's: unit directions in the local shading frame (z = the
//! normal), wo and wi pointing away from the surface, w.z < 0 mirrored by the visible-normal
//! functions, roughness `vec2(αx, αy)`; uniforms in [0, 1)². The formulas, their sources and
//! their guards are those of the Rust f32 fast path, operation for operation (each WGSL
//! function's comment names its Rust counterpart); where the Rust f32 path computes in f64
//! (the samplers' cos 2πu, and out-of-line edge paths), the WGSL computes in f32: WGSL has no
//! portable f64.
//!
//! # Energy compensation over the engines' tables
//!
//! `compensation.wgsl` reads the tables of `microsurface::scattering::lut` as the CLI's
//! `microsurface lut --kind albedo` and `--kind albedo-avg` write them (the defaults: μ and √α
//! coordinates, α_max = 1): E(μ, α) row-major `[roughness][μ]`, E_avg(α) one value per
//! roughness node, every axis' nodes at the texel centres (i + ½)/n. The library declares no
//! binding (WGSL has no externs, and the tables may live in a storage buffer, a filtered
//! texture or constants): `ms_lut_tap` gives a coordinate's node and weight (t = clamp(x·n −
//! ½, 0, n − 1), i = min(⌊t⌋, n − 2), f = t − i, as `Lut::lookup`), the shader fetches the two
//! or four nodes (`ms_lut_index`), and `ms_lut_lerp`/`ms_lut_bilerp` blend them with
//! `Lut::lookup`'s weights; the roughness coordinate is √α, or (αx αy)^¼ for anisotropic
//! roughness. A table written with `--nodes edges` (nodes at i/(n − 1), both ends included)
//! takes `ms_lut_tap_edges` instead (t = clamp(x(n − 1), 0, n − 1)): its furnace error is
//! within 1e-3 over α, μo ∈ [0.05, 1] from 64 nodes, where texel centres leave the clamped
//! half texel at α = 1 and μo = 1 (BENCHMARKS.md). The compensated conductor then takes the looked-up albedos: Kulla & Conty
//! 2017's f_ss + F_ms (1 − E(μo))(1 − E(μi))/(π(1 − E_avg)), F_ms = F_avg² E_avg/(1 −
//! F_avg(1 − E_avg)) for the caller's F_avg, or Turquin 2019's f_ss (1 + F0 (1 −
//! E(μo))/E(μo)). `tests/furnace.rs` has a whole shader (tables in a third storage binding).
//!
//! Sampling (Kulla–Conty) mixes as the Rust type: the added lobe, cosine-weighted on wo's side,
//! with probability q = 1 − E(μo), the single-scattering sample otherwise; pdf (1 − q) pdf_ss +
//! q |cos θi|/π. The sampler's f is the single-scattering one: E(μi) at the sampled direction
//! is a lookup only the caller can make, and `ms_kulla_conty_sample_f` adds the lobe with it.
//! `tests/furnace.rs` checks eval, pdf and samples against `CompensatedConductor<f32, …>` element
//! by element, fed the Rust table's E(μo), E(μi) and E_avg as numbers (the Rust type reads its
//! own cubic √μ table, not `lut`'s): the GPU's values differ from the Rust type's by the
//! single-scattering part's own difference plus f32 roundings of the compensation, no more
//! (at most 0.58 of that bound); the pdf integrates to q + (1 − q)∫pdf_ss within 4e-8.
//!
//! The compensated dielectric samples as its Rust type too: from wo's side s, the added lobes
//! with probability q = 1 − E_s(μo), across the surface with probability k_s within them
//! (each a cosine-weighted direction on its side), the single-scattering sample otherwise; pdf
//! (1 − q) pdf_ss + q ((1 − k_s) on wo's side, k_s across)|cos θi|/π. E_s(μo) and k_s depend on
//! wo only; the sampler's f is the single-scattering one, and
//! `ms_dielectric_kulla_conty_sample_f` adds the lobe with E_t(|cos θi|) and E_avg,t of the
//! sampled side t. Turquin samples as the single-scattering lobes, f over E_s(μo).
//! `tests/furnace.rs` checks eval, pdf and samples against `CompensatedDielectric<f32, …>`
//! element by element (GGX; η 1.5 and 1/1.5; α from 0.05 to 1 and an effectively smooth one;
//! both transports; wo on both sides, normal to grazing; uniforms 0 and 1 − 2⁻²⁴ included), fed
//! the Rust tables' E, 1 − lost_avg and F_avg as numbers, k formed on the GPU
//! (`ms_dielectric_kulla_conty_k`): within the single-scattering part's own difference plus f32
//! roundings of the compensation, derived per element (at most 0.62 of that bound; Turquin's
//! samples against the Rust type's own samples reach 0.997 of theirs, as any exact scaling
//! would: there the two single-scattering samples differ by far more than the scale's
//! roundings, of whose allowance 0.31 is used); the pdf integrates to q + (1 − q)∫pdf_ss
//! within 3e-8.
//!
//! Measured on lavapipe (`tests/furnace.rs`): the filter is within its f32 rounding bound of
//! `Lut::lookup` (at most a quarter of it, 32 and 64 nodes, 0, 1 and past them included). The
//! white furnace (F = 1, GGX, α ∈ [0.05, 1], μo ∈ [0.05, 1]), summed from the GPU's f on a
//! quadrature rule, equals 1 + E(μo) − E_l(μo) for Kulla–Conty (E_l the lookup, E_avg the
//! average of the looked-up E) and E/E_l for Turquin within 2e-6: the deviation is the
//! table's own filter error. Max |furnace − 1| for Kulla–Conty: 1.9e-2 (32 nodes) and 9.4e-3
//! (64), at α = 1, which lies half a texel past the last roughness centre (clamp-to-edge's
//! error, falling as 1/n: 1.2e-3 at 512); with √α and μ inside the last centres 2.6e-3 (32),
//! 1.6e-3 (64), 1.8e-4 (128), largest at grazing μo = 0.05 and α = 0.05, where E bends most
//! along a linear μ axis: 1e-3 holds there from 128 nodes. Turquin's deviation is Kulla–Conty's
//! over E_l (5.8e-2 and 3.0e-2 at α = 1). Taking E_avg from the `albedo-avg` table (the exact
//! average) instead of the average of the looked-up E moves the furnace by at most 1.4e-4
//! (32 nodes) and 3.6e-5 (64): small beside the filter's error, but only the lookup's average
//! makes the identity exact.
//!
//! # Accuracy against the Rust f32 path
//!
//! `tests/lavapipe.rs` runs every function above in compute shaders and compares element by
//! element with `Microfacet<f32, Ggx>`, the `fresnel` functions, `RoughConductor` and
//! `RoughDielectric`, on grids of directions (normal incidence, grazing cos θ = 1e-4, below
//! and on the horizon), roughness (2e-3 to 2, isotropic and anisotropic), η (1/2.4 to 2.4)
//! and uniforms (0 and 1 − 2⁻²⁴ included). D, Λ, G1, G2 and the pdfs agree within 2e-6
//! relative (twice the Rust f32 fast path's documented 1e-6); sampled normals within 16ε
//! per component times the cancellation of the caps' unnormalised normal where the cap
//! point nears the antipode of the stretched w (both sides form the caps' sine without
//! cancellation at the poles); BSDF values within bounds derived per element
//! from the half vector's rounding and the Fresnel formulas' conditioning (the test file has
//! each derivation). CI checks them on Mesa's lavapipe; the same test binary passes on an
//! NVIDIA H200, whose compiler fuses multiply-adds and divides to Vulkan's 2.5 ulp.
//! BENCHMARKS.md has the measured maxima on both.
//!
//! `tests/lavapipe.rs` also runs the conductor's and dielectric's eval and pdf over every other
//! NDF of the door (Beckmann, Double GGX, Exponential, GTR, Student-T, Ei, Erfc, K0,
//! Bessel-K, with their tables) against the Rust types over `AnyMicrofacet<f32>`: within 0.13
//! of bounds made of D's and Λ's bounds (from the Rust f64 functions' condition numbers) and
//! D's move under the half vector's rounding.
//!
//! `tests/family.rs` also checks Student-T (γ = 1.8, 2.5, 10, 40), Ei, Erfc, K0 and Bessel-K
//! (a = 0.4, 2.5) through `MsMicrofacet` over their shape tables: D, Λ, G1, G2 and the pdfs
//! within 0.61 of bounds
//! derived per element from the Rust f64 functions' condition numbers (the f32 rounding of
//! the tables and Vulkan's exp/log allowances included); Student-T's D·cos warp within 0.07
//! of its bound; the mixtures' D·cos and visible samplers draw the Rust samplers' uniforms
//! (u's, then the stream's f64 draws rounded to f32), so ≥ 99.6 % of the grids' normals are
//! the Rust draw (within 1e-3; the rest, accept decisions on either side of f32 rounding),
//! and their distributions pass the two-sample χ².
//!
//! `tests/family.rs` does the same for Double GGX and the Exponential NDF (D within 0.13 of
//! its bound, Λ, G1, G2 and the pdfs within 0.13, D·cos normals within 0.125 of 16ε on
//! lavapipe; each bound's derivation is in the file). Their visible-normal samplers reject
//! over the stream of u as the Rust ones do, so the same u mostly gives the same normal (on
//! the grids: every Exponential normal within 5e-6 of the Rust one; Double GGX's within
//! 8e-4, its ziggurat reading t from an f32 product's low bits); their distribution is
//! checked by a two-sample χ² against the Rust samplers (2^18 normals each, 512 bins, p =
//! 1e-6), themselves χ²-tested against the Rust pdf.
//!
//! `tests/gtr.rs` does the same for GTR through `MsMicrofacet` (γ = ½, 1, 1.5, 3, 10 at the
//! grids' isotropic roughness, γ = 100 at α = 2, and γ = 2 at every roughness, where it is
//! GGX): D within 0.16 of its bound (e^{ln c − γ ln x} in f32, with Vulkan's allowances for
//! exp and log), Λ within 0.15 (bit for bit where the Rust type has its f32 table; its f64
//! rows rounded to f32 elsewhere, γ = 10 at α ≤ 0.3 here, whose rounding moves ln Λ by at
//! most 3.8e-6), G1, G2 and the pdfs within 0.16, D·cos normals (Burley's inversion in f32,
//! the Rust warp) within 0.13 of their bounds. The visible sampler is the Rust one, alias
//! table and all, over the same stream (the column's fraction formed exactly from u's
//! significand, as the Rust f64 product is): every one of the grids' 30 240 normals is the
//! Rust draw within 6.6e-7, and a two-sample χ² against the Rust sampler holds (five
//! configurations, 2^18 each).
//!
//! # The runner
//!
//! [`Gpu`] opens the first Vulkan adapter (wgpu, Vulkan back end only; a discrete GPU
//! before others), compiles a WGSL source ([`Gpu::program`]) and runs one of its compute
//! entry points over an input buffer of `vec4<f32>` records ([`Gpu::run`]): the tests'
//! harness, and the bench's device (`examples/gpu_bench.rs`). On an NVIDIA machine without a
//! display, point the Vulkan loader at the driver's EGL library (`VK_ICD_FILENAMES`: an ICD
//! file whose `library_path` is `libEGL_nvidia.so.0`): the GLX one that the driver's own ICD
//! file names creates no instance without an X server (BENCHMARKS.md).

#[doc(hidden)]
pub mod fit;

use std::collections::HashMap;
use std::fmt;
use std::sync::{mpsc, Mutex};

/// The WGSL library, one source: `wgsl/common.wgsl`, `fresnel.wgsl`, `ggx.wgsl`,
/// `tables.wgsl` (generated: the tables buffer's binding and layout), `stream.wgsl`,
/// `beckmann.wgsl`, `double_ggx.wgsl`, `exponential.wgsl`, `mixture.wgsl`, `student_t.wgsl`,
/// `gtr.wgsl`, `ei.wgsl`, `erfc.wgsl`, `k0.wgsl`, `bessel_k.wgsl`, `microfacet.wgsl`,
/// `conductor.wgsl`, `dielectric.wgsl`, `compensation.wgsl`, in that order. A shader that
/// includes it defines `MS_TABLES_GROUP` and `MS_TABLES_BINDING` (see [`TABLES`]).
pub const WGSL: &str = concat!(
    include_str!("../wgsl/common.wgsl"),
    "\n",
    include_str!("../wgsl/fresnel.wgsl"),
    "\n",
    include_str!("../wgsl/ggx.wgsl"),
    "\n",
    include_str!("../wgsl/tables.wgsl"),
    "\n",
    include_str!("../wgsl/stream.wgsl"),
    "\n",
    include_str!("../wgsl/beckmann.wgsl"),
    "\n",
    include_str!("../wgsl/double_ggx.wgsl"),
    "\n",
    include_str!("../wgsl/exponential.wgsl"),
    "\n",
    include_str!("../wgsl/mixture.wgsl"),
    "\n",
    include_str!("../wgsl/student_t.wgsl"),
    "\n",
    include_str!("../wgsl/gtr.wgsl"),
    "\n",
    include_str!("../wgsl/ei.wgsl"),
    "\n",
    include_str!("../wgsl/erfc.wgsl"),
    "\n",
    include_str!("../wgsl/k0.wgsl"),
    "\n",
    include_str!("../wgsl/bessel_k.wgsl"),
    "\n",
    include_str!("../wgsl/microfacet.wgsl"),
    "\n",
    include_str!("../wgsl/conductor.wgsl"),
    "\n",
    include_str!("../wgsl/dielectric.wgsl"),
    "\n",
    include_str!("../wgsl/compensation.wgsl"),
);

/// The library's fitted tables, the contents of its one storage buffer `ms_tables`
/// (`array<vec4<f32>>`, little-endian f32; `generated/microsurface_tables.bin` is the same
/// bytes for other builds): Beckmann's special functions, Double GGX's and the Exponential
/// NDF's Λ and D, the Exp(1) ziggurat. Generated from the Rust library by
/// `tools/tables.rs`, never typed by hand; `wgsl/tables.wgsl` has each table's first row.
/// A shader that includes [`WGSL`] says where it binds the buffer with two constants of its
/// own, e.g.
///
/// ```wgsl
/// const MS_TABLES_GROUP: u32 = 1u;
/// const MS_TABLES_BINDING: u32 = 0u;
/// ```
///
/// and binds these bytes there when its entry point reads a table (through Beckmann, Double
/// GGX, the Exponential NDF or `MsMicrofacet`); an entry point that calls only GGX and
/// Fresnel functions needs no buffer bound. [`Gpu`] binds it at group 1, binding 0.
pub static TABLES: &[u8] = include_bytes!("../generated/microsurface_tables.bin");

/// Bessel-K's profile table spans x ∈ [2^−40, 2^8): below, the profile is its leading
/// power of x (within 1e-12 α of the pole); above, f₁ < e^{−500} and D is 0 in f32 for every
/// accepted roughness.
const BESSEL_PROFILE_K0: i32 = -40;
const BESSEL_PROFILE_K1: i32 = 8;

/// The contents of the library's buffer `ms_tables` for a shader whose materials have tables
/// of their own: the library's [`TABLES`] followed by each shape's (the fitted Λ₁ and the
/// posterior's parameters of a Student-T γ, a Bessel-K a (with its profile's table), or of
/// Ei, Erfc, K0; the layout is in `wgsl/mixture.wgsl` and `wgsl/bessel_k.wgsl`) and each GTR
/// material's ([`Tables::add_gtr`]: Λ fitted to its (α, γ), Burley's constants, the visible
/// sampler's envelopes; the layout is in `wgsl/gtr.wgsl`). A shape's table is built once
/// (the Rust fast path's `FittedShape`: milliseconds) and serves every roughness; a GTR
/// table serves one (α, γ), as the Rust `FittedGtr` it is written from. Its row goes into
/// `MsMicrofacet`'s `table`.
///
/// ```
/// use microsurface::NdfKind;
/// let mut tables = microsurface_gpu::Tables::new();
/// let row = tables.add_shape(NdfKind::StudentT, Some(2.5))?;
/// // MsMicrofacet(MS_NDF_STUDENT_T, alpha, row) in the shader; bind tables.bytes().
/// assert!(row as usize * 16 >= microsurface_gpu::TABLES.len());
/// // GTR at α = 0.3, γ = 1.5: MsMicrofacet(MS_NDF_GTR, vec2(0.3, 0.3), gtr).
/// let gtr = tables.add_gtr(f64::from(0.3f32), 1.5)?;
/// assert!(gtr > row);
/// # Ok::<(), microsurface::ParamError>(())
/// ```
#[derive(Clone, Debug)]
pub struct Tables {
    rows: Vec<[f32; 4]>,
}

impl Default for Tables {
    fn default() -> Self {
        Tables::new()
    }
}

impl Tables {
    /// The library's tables alone ([`TABLES`]).
    pub fn new() -> Tables {
        let rows = TABLES
            .chunks_exact(16)
            .map(|r| {
                let f = |k: usize| f32::from_le_bytes([r[k], r[k + 1], r[k + 2], r[k + 3]]);
                [f(0), f(4), f(8), f(12)]
            })
            .collect();
        Tables { rows }
    }

    /// Appends the shape table of `kind` at `shape` and returns its first row (the `table`
    /// of an `MsMicrofacet` of that NDF): Student-T (γ in (3/2, 1e6]), Bessel-K (its a), Ei,
    /// Erfc and K0 (shape `None`; one table serves every material of the NDF). `ParamError`
    /// for other kinds and shapes out of range.
    /// (GTR's table depends on α too: [`Tables::add_gtr`].)
    pub fn add_shape(
        &mut self,
        kind: microsurface::NdfKind,
        shape: Option<f64>,
    ) -> Result<u32, microsurface::ParamError> {
        use microsurface::fast::fitted::FittedShape;
        use microsurface::ndf::mixture::Mixing;
        let ndf = microsurface::AnyNdf::new(kind, 1.0, shape)?;
        // (FittedShape takes the Beckmann mixtures and refuses the others, typed.)
        let fitted = FittedShape::new(&ndf)?;
        let l = fitted.layout();
        // The posterior's mixing as mixture.wgsl's code (ms_mixing_ln_beta).
        let mixing = match l.mixing {
            Mixing::InverseGamma(_) => 0.0,
            Mixing::Gamma(_) => 1.0,
            Mixing::UniformSquare => 2.0,
            // (Uniform, Erfc's: FittedShape admits no other mixing.)
            _ => 3.0,
        };
        let at = self.rows.len() as u32;
        let (tail_on, tail) = match l.tail {
            Some(t) => (1.0, t),
            None => (0.0, [0.0; 3]),
        };
        self.rows.push([
            ndf.shape().unwrap_or(0.0) as f32,
            l.k1 as f32,
            if l.direct { 1.0 } else { 0.0 },
            l.sigma0 as f32,
        ]);
        self.rows
            .push([tail_on, tail[0] as f32, tail[1] as f32, tail[2] as f32]);
        // (Bessel-K's profile block follows the Λ₁ rows: its offset from the table's first
        // row, exact in f32.)
        let profile_at = if l.bessel_nu.is_some() {
            (3 + 2 * l.rows.len()) as f32
        } else {
            0.0
        };
        self.rows
            .push([l.mean_beta as f32, l.mixing_k as f32, mixing, profile_at]);
        for c in l.rows {
            self.rows
                .push([c[0] as f32, c[1] as f32, c[2] as f32, c[3] as f32]);
            self.rows.push([c[4] as f32, 0.0, 0.0, 0.0]);
        }
        if let Some(nu) = l.bessel_nu {
            self.push_bessel_profile(&ndf, nu);
        }
        Ok(at)
    }

    /// Bessel-K's profile block (bessel_k.wgsl): a row (ν, k0, k1, 0), then the octave table
    /// ([`fit`], degree 7, two rows a segment) of h(x) = ln f₁(x) + 2x on x ∈ [2^k0, 2^k1),
    /// f₁ the unit member's radial profile 2x^ν K_ν(2x)/(π Γ(a)) from the Rust f64 NDF (its
    /// K_ν by quadrature: Λ₁'s table aside, this is where the construction's time goes).
    /// h is smooth on octaves: the exponential decay is taken out, what is left grows like
    /// (ν − ½) ln x at large x and like 2ν ln x (ν < 0), a constant (ν > 0) or ln(−ln x)
    /// (ν = 0) near 0.
    fn push_bessel_profile(&mut self, unit: &microsurface::AnyNdf, nu: f64) {
        let h = |x: f64| unit.f(x).unwrap_or(f64::NAN).ln() + 2.0 * x;
        self.rows.push([
            nu as f32,
            BESSEL_PROFILE_K0 as f32,
            BESSEL_PROFILE_K1 as f32,
            0.0,
        ]);
        for j in 0..fit::segments(BESSEL_PROFILE_K0, BESSEL_PROFILE_K1) {
            let c = fit::fit(&h, BESSEL_PROFILE_K0, j).map(|x| x as f32);
            self.rows.push([c[0], c[1], c[2], c[3]]);
            self.rows.push([c[4], c[5], c[6], c[7]]);
        }
    }

    /// Appends the table of the GTR material (α, γ) (`Microfacet::<f32, Gtr>::gtr(α, α, γ)`;
    /// pass the shader's f32 α widened, `f64::from(alpha)`, for the same fit) and returns its
    /// first row (the `table` of an `MsMicrofacet` of `MS_NDF_GTR`): the Rust fast path's
    /// `FittedGtr` of (α, γ) (its f32 Λ table where it has one, else its f64 rows rounded to
    /// f32, the ends' constants, D's normalisation, Burley's quantile constants and the
    /// visible sampler's envelopes; the layout is in `wgsl/gtr.wgsl`): milliseconds, tens at
    /// γ ∉ {1, 2}, and a table per material (50 KiB at α = 0.3, γ = 1.5, 107 KiB at α =
    /// 0.05, γ = 10, 450 KiB at α = 1e-3, γ = 100: the envelopes' pieces grow with γ). γ = 2 is
    /// GGX, one row, any α (the material's `alpha` then carries the roughness, anisotropic
    /// allowed). `ParamError` for α outside [1e-6, 1e6] and γ outside (0, 100], as
    /// [`microsurface::Gtr::new`].
    pub fn add_gtr(&mut self, alpha: f64, gamma: f64) -> Result<u32, microsurface::ParamError> {
        use microsurface::fast::gtr::FittedGtr;
        microsurface::Gtr::new(alpha, gamma)?;
        let at = self.rows.len();
        if gamma == 2.0 {
            self.rows.push([2.0, alpha as f32, 0.0, 0.0]);
            return Ok(at as u32);
        }
        let fitted = FittedGtr::new(alpha, gamma)?;
        let l = fitted.layout();
        // Saturated at f32's largest (an exponential past f32's range: a flag says so).
        let sat = |x: f64| x.clamp(-(f32::MAX as f64), f32::MAX as f64) as f32;
        let kind = if !l.rows32.is_empty() {
            1.0
        } else if l.direct {
            2.0
        } else {
            3.0
        };
        let n_rows = l.rows.len();
        let per_row = if l.rows32.is_empty() { 2 } else { 1 };
        let header = 8;
        let dcos_at = header + per_row * n_rows;
        let moment_at = dcos_at + 2 * l.dcos.pieces.len();
        let b = l.burley;
        let over = |e: f64| if e > f32::MAX as f64 { 1.0 } else { 0.0 };
        let rows = &mut self.rows;
        rows.push([gamma as f32, alpha as f32, kind, l.sigma0 as f32]);
        rows.push([l.ln_c as f32, sat(l.c), l.m[0] as f32, l.m[1] as f32]);
        rows.push([
            l.k[0] as f32,
            l.k[1] as f32,
            l.off32[0] as i32 as f32,
            l.off32[1] as i32 as f32,
        ]);
        rows.push([l.lo32[0], l.lo32[1], n_rows as f32, 0.0]);
        rows.push([b[0] as f32, b[1] as f32, b[2] as f32, over(b[3])]);
        rows.push([sat(b[3]), sat(b[4]), sat(b[5]), sat(b[6])]);
        rows.push([sat(b[7]), sat(b[8]), sat(b[9]), over(b[5])]);
        rows.push([
            dcos_at as f32,
            l.dcos.pieces.len() as f32,
            moment_at as f32,
            l.moment.pieces.len() as f32,
        ]);
        if l.rows32.is_empty() {
            for c in l.rows {
                rows.push([c[0] as f32, c[1] as f32, c[2] as f32, c[3] as f32]);
                rows.push([c[4] as f32, 0.0, 0.0, 0.0]);
            }
        } else {
            rows.extend(l.rows32.iter().copied());
        }
        for radial in [&l.dcos, &l.moment] {
            push_radial(rows, radial);
        }
        debug_assert_eq!(self.rows.len(), at + moment_at + 2 * l.moment.pieces.len());
        Ok(at as u32)
    }

    /// The buffer's bytes (little-endian `vec4<f32>` rows).
    pub fn bytes(&self) -> &[u8] {
        bytemuck::cast_slice(&self.rows)
    }
}

/// A radial envelope's pieces, two rows each (the layout is in `wgsl/gtr.wgsl`).
fn push_radial(rows: &mut Vec<[f32; 4]>, r: &microsurface::fast::gtr::RadialLayout) {
    for p in &r.pieces {
        // (A column's own share below f32's least normal is kept at that: the column is
        // then its own piece at fraction 0, as in f64, not its alias.)
        let prob = if p.prob > 0.0 {
            (p.prob as f32).max(f32::MIN_POSITIVE)
        } else {
            0.0
        };
        let column = [prob, p.alias as f32];
        if p.tail {
            rows.push([
                p.a as f32,
                p.beta as f32,
                (r.top + p.e0) as f32,
                p.squeeze as f32,
            ]);
            let em1 = p.em1.clamp(-1.0, f32::MAX as f64) as f32;
            rows.push([em1, column[0], column[1], 1.0]);
        } else {
            rows.push([p.r0 as f32, p.dr as f32, p.s0 as f32, p.s1 as f32]);
            rows.push([(r.top + p.h) as f32, column[0], column[1], 0.0]);
        }
    }
}

/// The test kernels (`wgsl/kernels.wgsl`): compute entry points over records of five
/// `vec4<f32>` in and two out (the layout is in the file), compiled after [`WGSL`]; the
/// tables at group 1, binding 0.
pub const KERNELS_WGSL: &str = include_str!("../wgsl/kernels.wgsl");

/// Records in and out per element of the test kernels.
pub const KERNEL_IN: usize = 5;
/// See [`KERNEL_IN`].
pub const KERNEL_OUT: usize = 2;

/// The compute entry points of [`KERNELS_WGSL`].
pub const KERNEL_ENTRY_POINTS: [&str; 13] = [
    "ms_k_ggx_eval",
    "ms_k_ggx_sample",
    "ms_k_ggx_bounded",
    "ms_k_beckmann_eval",
    "ms_k_beckmann_sample",
    "ms_k_fresnel",
    "ms_k_conductor_eval",
    "ms_k_conductor_sample",
    "ms_k_dielectric_eval",
    "ms_k_dielectric_sample",
    "ms_k_family_eval",
    "ms_k_family_sample",
    "ms_k_stream",
];

/// The library followed by its test kernels: one WGSL module.
pub fn kernels_source() -> String {
    format!("{WGSL}\n{KERNELS_WGSL}")
}

/// The workgroup size of the kernels (x).
pub const WORKGROUP: u32 = 64;

/// What went wrong opening the device or running a kernel.
#[derive(Debug)]
pub enum Error {
    /// No Vulkan adapter (no GPU driver, no lavapipe).
    NoAdapter(String),
    /// The adapter would not give a device.
    Device(String),
    /// The shader or the pipeline did not validate (naga's message).
    Shader(String),
    /// Mapping the results back failed.
    Readback(String),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::NoAdapter(m) => write!(f, "no Vulkan adapter: {m}"),
            Error::Device(m) => write!(f, "no device: {m}"),
            Error::Shader(m) => write!(f, "shader: {m}"),
            Error::Readback(m) => write!(f, "readback: {m}"),
        }
    }
}

impl std::error::Error for Error {}

/// A Vulkan device and queue (wgpu), with the adapter's description.
pub struct Gpu {
    device: wgpu::Device,
    queue: wgpu::Queue,
    info: wgpu::AdapterInfo,
    timestamps: bool,
    tables_layout: wgpu::BindGroupLayout,
    tables: wgpu::BindGroup,
}

/// A compiled WGSL module whose entry points take the two storage buffers of the kernels'
/// layout (group 0: binding 0 read, binding 1 read-write) and the library's [`TABLES`]
/// (group 1, binding 0); pipelines are made per entry point on first use.
pub struct Program {
    module: wgpu::ShaderModule,
    layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    pipelines: Mutex<HashMap<String, wgpu::ComputePipeline>>,
}

impl Gpu {
    /// The first Vulkan adapter (high-performance preferred), its device with the adapter's
    /// own limits (large storage buffers) and timestamp queries where it has them.
    pub fn new() -> Result<Gpu, Error> {
        Gpu::with_tables(&Tables::new())
    }

    /// [`Gpu::new`] with `tables` bound as the library's buffer (materials with shape tables).
    pub fn with_tables(tables: &Tables) -> Result<Gpu, Error> {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends: wgpu::Backends::VULKAN,
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        });
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            ..Default::default()
        }))
        .map_err(|e| Error::NoAdapter(e.to_string()))?;
        let timestamps = adapter.features().contains(wgpu::Features::TIMESTAMP_QUERY);
        let features = if timestamps {
            wgpu::Features::TIMESTAMP_QUERY
        } else {
            wgpu::Features::empty()
        };
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("microsurface-gpu"),
            required_features: features,
            required_limits: adapter.limits(),
            ..Default::default()
        }))
        .map_err(|e| Error::Device(e.to_string()))?;
        let tables_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("microsurface tables"),
            entries: &[storage_entry(0, true)],
        });
        let bytes = tables.bytes();
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("microsurface tables"),
            size: bytes.len() as u64,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        queue.write_buffer(&buffer, 0, bytes);
        let tables = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("microsurface tables"),
            layout: &tables_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: buffer.as_entire_binding(),
            }],
        });
        Ok(Gpu {
            device,
            queue,
            info: adapter.get_info(),
            timestamps,
            tables_layout,
            tables,
        })
    }

    /// The layout of the tables' bind group (one read-only storage buffer at binding 0), for
    /// pipelines of one's own that bind [`Gpu::tables`] at group 1 as [`Gpu::program`]'s do.
    pub fn tables_layout(&self) -> &wgpu::BindGroupLayout {
        &self.tables_layout
    }

    /// The bind group of the library's tables ([`TABLES`], or the [`Tables`] of
    /// [`Gpu::with_tables`]), uploaded once.
    pub fn tables(&self) -> &wgpu::BindGroup {
        &self.tables
    }

    /// The adapter's name, driver and device type.
    pub fn adapter_info(&self) -> &wgpu::AdapterInfo {
        &self.info
    }

    /// Whether the device has timestamp queries (the bench times with them where it has).
    pub fn has_timestamps(&self) -> bool {
        self.timestamps
    }

    /// The wgpu device.
    pub fn device(&self) -> &wgpu::Device {
        &self.device
    }

    /// The wgpu queue.
    pub fn queue(&self) -> &wgpu::Queue {
        &self.queue
    }

    /// Compiles a WGSL source whose compute entry points use the kernels' two bindings;
    /// `Err` with naga's message where it does not validate.
    pub fn program(&self, source: &str) -> Result<Program, Error> {
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = self
            .device
            .create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("microsurface"),
                source: wgpu::ShaderSource::Wgsl(source.into()),
            });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(Error::Shader(e.to_string()));
        }
        let layout = self
            .device
            .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("microsurface"),
                entries: &[storage_entry(0, true), storage_entry(1, false)],
            });
        let pipeline_layout = self
            .device
            .create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("microsurface"),
                bind_group_layouts: &[Some(&layout), Some(&self.tables_layout)],
                immediate_size: 0,
            });
        Ok(Program {
            module,
            layout,
            pipeline_layout,
            pipelines: Mutex::new(HashMap::new()),
        })
    }

    /// The compute pipeline of `entry` in `program` (made once, then cached).
    pub fn pipeline(&self, program: &Program, entry: &str) -> Result<wgpu::ComputePipeline, Error> {
        self.pipeline_with(program, entry, &[])
    }

    /// The compute pipeline of `entry` with pipeline-overridable constants set (the door's
    /// `MS_DOOR_NDFS`, say; made once per entry and constants, then cached).
    pub fn pipeline_with(
        &self,
        program: &Program,
        entry: &str,
        constants: &[(&str, f64)],
    ) -> Result<wgpu::ComputePipeline, Error> {
        let key = format!("{entry}{constants:?}");
        let mut map = program.pipelines.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(p) = map.get(&key) {
            return Ok(p.clone());
        }
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let p = self
            .device
            .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some(entry),
                layout: Some(&program.pipeline_layout),
                module: &program.module,
                entry_point: Some(entry),
                compilation_options: wgpu::PipelineCompilationOptions {
                    constants,
                    ..Default::default()
                },
                cache: None,
            });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(Error::Shader(format!("{entry}: {e}")));
        }
        map.insert(key, p.clone());
        Ok(p)
    }

    /// The bind group of `program`'s layout over an input and an output buffer.
    pub fn bind(
        &self,
        program: &Program,
        input: &wgpu::Buffer,
        output: &wgpu::Buffer,
    ) -> wgpu::BindGroup {
        self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("microsurface"),
            layout: &program.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: input.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: output.as_entire_binding(),
                },
            ],
        })
    }

    /// A storage buffer of `bytes` (copy source and destination too).
    pub fn storage(&self, bytes: u64) -> wgpu::Buffer {
        self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("microsurface"),
            size: bytes.max(16),
            usage: wgpu::BufferUsages::STORAGE
                | wgpu::BufferUsages::COPY_DST
                | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        })
    }

    /// Runs `entry` over `input` (`per_in` records of `vec4<f32>` per element) and returns
    /// `per_out` records per element: workgroups of [`WORKGROUP`] in x, then y where x
    /// would pass the device's 65535 (the kernels take the index x + y·64·(groups in x)).
    pub fn run(
        &self,
        program: &Program,
        entry: &str,
        input: &[[f32; 4]],
        per_in: usize,
        per_out: usize,
    ) -> Result<Vec<[f32; 4]>, Error> {
        let n = input.len() / per_in;
        let pipeline = self.pipeline(program, entry)?;
        let in_buf = self.storage((input.len() * 16) as u64);
        self.queue
            .write_buffer(&in_buf, 0, bytemuck::cast_slice(&input[..n * per_in]));
        let out_bytes = (n * per_out * 16) as u64;
        let out_buf = self.storage(out_bytes);
        let read = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: out_bytes.max(16),
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind = self.bind(program, &in_buf, &out_buf);
        let mut enc = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        {
            let mut pass = enc.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &bind, &[]);
            pass.set_bind_group(1, &self.tables, &[]);
            let (x, y) = groups(n as u64);
            pass.dispatch_workgroups(x, y, 1);
        }
        enc.copy_buffer_to_buffer(&out_buf, 0, &read, 0, out_bytes.max(16));
        self.queue.submit([enc.finish()]);
        let (tx, rx) = mpsc::channel();
        read.slice(..).map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| Error::Readback(e.to_string()))?;
        rx.recv()
            .map_err(|e| Error::Readback(e.to_string()))?
            .map_err(|e| Error::Readback(e.to_string()))?;
        let view = read
            .get_mapped_range(..)
            .map_err(|e| Error::Readback(e.to_string()))?;
        let out: Vec<[f32; 4]> = bytemuck::cast_slice(&view[..(n * per_out * 16)]).to_vec();
        drop(view);
        read.unmap();
        Ok(out)
    }
}

/// A compute-visible storage buffer's layout entry.
pub fn storage_entry(binding: u32, read_only: bool) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

/// Workgroups (x, y) covering n elements in groups of [`WORKGROUP`]: x at most 65535.
pub fn groups(n: u64) -> (u32, u32) {
    let g = n.div_ceil(WORKGROUP as u64).max(1);
    let x = g.min(65_535);
    (x as u32, g.div_ceil(x) as u32)
}
