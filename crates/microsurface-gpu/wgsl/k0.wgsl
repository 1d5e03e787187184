// microsurface WGSL library: the K0 NDF, anisotropic (k0.wgsl).
//
// The Rust `Microfacet<f32, K0>` (crates/microsurface/src/fast/fitted.rs, the family's fast
// path; ndf/k0.rs for the formulas: the K0_NDF page of d'Eon's "A Hitchhiker's Guide to
// Multiple Scattering"), in f32. The Gamma(1) superposition of Beckmann NDFs over roughness α√t.
// Its Λ₁ lives in a shape table (mixture.wgsl; `microsurface_gpu::Tables::add_shape(NdfKind::
// K0, None)` in Rust, one table for every roughness: the NDF is shape invariant).
//
//   D(m) = f₁(r)/(αx αy z⁴),  f₁(r) = 2K₀(2r)/π  (e^z K₀(z) from the MS_SF_K0E table)
//   Λ(w) = Λ₁(cot θ/α̃) from the table,  G1 = 1/(1 + Λ),  G2 = 1/(1 + Λo + Λi) or G1 G1
//
// D·cos and visible normals: exact samplers over the mixture (ms_mixture_sample_dcos_wm: β
// from the prior, then Beckmann's D·cos warp; ms_mixture_sample_wm: the posterior, then
// Beckmann's stream sampler), the Rust samplers' distributions, not their normals.

// ln f₁ at r: ln(2 e^z K₀(z)/π) − z, z = 2r.
fn ms_k0_ln_profile(r: f32) -> f32 {
    let z = 2.0 * r;
    return log(2.0 * ms_k0e(z) / MS_PI) - z;
}

// ln D(wm) for wm above the horizon (−1e30, D = 0, on and below it; NaN for NaN), +1e30 (D = +∞) at the pole (r = 0).
fn ms_k0_ln_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return select(-1e30, wm.z, wm.z != wm.z);
    }
    let r = ms_mixture_r(wm, alpha);
    if r == 0.0 {
        return 1e30;
    }
    return ms_mixture_ln_d(ms_k0_ln_profile(r), wm, alpha);
}

// D(wm); 0 on and below the horizon, +∞ at the pole, NaN for NaN.
fn ms_k0_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let ln_d = ms_k0_ln_d(wm, alpha);
    if ln_d >= 1e30 {
        return ms_inf();
    }
    return exp(ln_d);
}

// Smith Λ(w), Λ(−w) = Λ(w), from the shape table at `table`.
fn ms_k0_lambda(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_shape_lambda(table, w, alpha);
}

// G1(w).
fn ms_k0_g1(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g1(table, w, alpha);
}

// Height-correlated G2(wo, wi).
fn ms_k0_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2(table, wo, wi, alpha);
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_k0_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2_separable(table, wo, wi, alpha);
}

// The visible-normal density D_w(wm) (w.z < 0 mirrored).
fn ms_k0_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_pdf(table, w, wm, alpha, ms_k0_ln_d(wm, alpha));
}

// The D·cos density D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_k0_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_k0_d(wm, alpha) * wm.z;
}

// A D·cos normal from u, with its pdf.
fn ms_k0_sample_dcos(alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_dcos_wm(table, alpha, u);
    return MsSample(wm, ms_k0_pdf_dcos(wm, alpha));
}

// A visible normal for w (w.z < 0 mirrored) from u, with its pdf.
fn ms_k0_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_wm(table, w, alpha, u);
    return MsSample(wm, ms_k0_pdf(ms_unit(w), wm, alpha, table));
}
