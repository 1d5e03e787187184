// microsurface WGSL library: a material's distribution chosen at run time (microfacet.wgsl),
// the WGSL counterpart of the Rust `MicrofacetDistribution` door that the BSDFs use. A
// renderer that knows its NDF calls the per-NDF functions (ms_ggx_d, …) directly.

// Which NDF (`ndf`: an MS_NDF_* constant) at roughness (αx, αy), and for an NDF with a
// table of its own (a shape table: Student-T, Ei, Erfc, K0, Bessel-K; GTR's material table)
// the table's first row in `ms_tables` (`microsurface_gpu::Tables::add_shape` or `add_gtr`
// gives it; 0 and unused for the others). Every NDF but GGX reads the library's buffer
// (tables.wgsl), so a shader that takes this door binds it. GTR's α is its table's (αx = αy
// = α; at γ = 2, GGX's, any (αx, αy)).
struct MsMicrofacet {
    ndf: u32,
    alpha: vec2<f32>,
    table: u32,
}

const MS_NDF_GGX: u32 = 0u;
const MS_NDF_BECKMANN: u32 = 1u;
const MS_NDF_DOUBLE_GGX: u32 = 2u;
const MS_NDF_EXPONENTIAL: u32 = 3u;
const MS_NDF_GTR: u32 = 4u;
const MS_NDF_STUDENT_T: u32 = 5u;
const MS_NDF_EI: u32 = 6u;
const MS_NDF_ERFC: u32 = 7u;
const MS_NDF_K0: u32 = 8u;
const MS_NDF_BESSEL_K: u32 = 9u;

// The NDFs this pipeline's door may meet, one bit each (1 << MS_NDF_*): a pipeline-overridable
// constant, every NDF by default. A shader whose materials use a few NDFs sets it when it
// creates its pipeline (wgpu: `compilation_options.constants`, "MS_DOOR_NDFS"), and the
// compiler drops the other NDFs' code from the door: every NDF inlined into every kernel costs
// registers and code size even where its branch is never taken (BENCHMARKS.md). A material of
// an NDF outside the mask meets the door's default answers (D = 0, …).
override MS_DOOR_NDFS: u32 = 0xffffffffu;

fn ms_door_has(ndf: u32) -> bool {
    return (MS_DOOR_NDFS & (1u << ndf)) != 0u;
}

// D(wm); 0 below the horizon (and for an NDF this library does not have).
fn ms_d(mf: MsMicrofacet, wm: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_d(wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_d(wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_d(wm, mf.alpha, mf.table);
    }
    return 0.0;
}

// Smith Λ(w).
fn ms_lambda(mf: MsMicrofacet, w: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_lambda(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_lambda(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_lambda(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_lambda(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_lambda(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_lambda(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_lambda(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_lambda(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_lambda(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_lambda(w, mf.alpha, mf.table);
    }
    return 0.0;
}

// G1(w).
fn ms_g1(mf: MsMicrofacet, w: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_g1(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_g1(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_g1(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_g1(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_g1(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_g1(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_g1(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_g1(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_g1(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_g1(w, mf.alpha, mf.table);
    }
    return 0.0;
}

// Height-correlated G2(wo, wi).
fn ms_g2(mf: MsMicrofacet, wo: vec3<f32>, wi: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_g2(wo, wi, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_g2(wo, wi, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_g2(wo, wi, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_g2(wo, wi, mf.alpha);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_g2(wo, wi, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_g2(wo, wi, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_g2(wo, wi, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_g2(wo, wi, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_g2(wo, wi, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_g2(wo, wi, mf.alpha, mf.table);
    }
    return 0.0;
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_g2_separable(mf: MsMicrofacet, wo: vec3<f32>, wi: vec3<f32>) -> f32 {
    return ms_g1(mf, wo) * ms_g1(mf, wi);
}

// The visible-normal density D_w(wm).
fn ms_pdf(mf: MsMicrofacet, w: vec3<f32>, wm: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_pdf(w, wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_pdf(w, wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_pdf(w, wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_pdf(w, wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_pdf(w, wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_pdf(w, wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_pdf(w, wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_pdf(w, wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_pdf(w, wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_pdf(w, wm, mf.alpha, mf.table);
    }
    return 0.0;
}

// The D·cos density D(wm) cos θm (0 for wm.z ≤ 0): the density of ms_sample_dcos.
fn ms_pdf_dcos(mf: MsMicrofacet, wm: vec3<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_d(mf, wm) * wm.z;
}

// A visible normal for w from u ∈ [0, 1)², with its pdf.
fn ms_sample(mf: MsMicrofacet, w: vec3<f32>, u: vec2<f32>) -> MsSample {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_sample(w, mf.alpha, u);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_sample(w, mf.alpha, u);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_sample(w, mf.alpha, u);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_sample(w, mf.alpha, u);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_sample(w, mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_sample(w, mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_sample(w, mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_sample(w, mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_sample(w, mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_sample(w, mf.alpha, u, mf.table);
    }
    return MsSample(vec3<f32>(0.0, 0.0, 1.0), 0.0);
}

// A normal distributed as D(m) cos θm, with its pdf.
fn ms_sample_dcos(mf: MsMicrofacet, u: vec2<f32>) -> MsSample {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_sample_dcos(mf.alpha, u);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_sample_dcos(mf.alpha, u);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_sample_dcos(mf.alpha, u);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_sample_dcos(mf.alpha, u);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_sample_dcos(mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_sample_dcos(mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_sample_dcos(mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_sample_dcos(mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_sample_dcos(mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_sample_dcos(mf.alpha, u, mf.table);
    }
    return MsSample(vec3<f32>(0.0, 0.0, 1.0), 0.0);
}

// Whether the surface is effectively smooth (max(αx, αy) < 1e-3): the BSDFs are then a
// delta lobe, as pbrt-v4's and the Rust types'.
fn ms_effectively_smooth(mf: MsMicrofacet) -> bool {
    return max(mf.alpha.x, mf.alpha.y) < 1e-3;
}
