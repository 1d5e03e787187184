// microsurface WGSL library: the Erfc NDF, anisotropic (erfc.wgsl).
//
// The Rust `Microfacet<f32, Erfc>` (crates/microsurface/src/fast/fitted.rs, the family's fast
// path; ndf/erfc.rs for the formulas: the Erfc_NDF page of d'Eon's "A Hitchhiker's Guide to
// Multiple Scattering"), in f32. A uniform superposition of Beckmann NDFs over roughness ∈ (0, α].
// Its Λ₁ lives in a shape table (mixture.wgsl; `microsurface_gpu::Tables::add_shape(NdfKind::
// Erfc, None)` in Rust, one table for every roughness: the NDF is shape invariant).
//
//   D(m) = f₁(r)/(αx αy z⁴),  f₁(r) = erfc(r)/(2√π r)  (erfc = erfcx e^{−r²}, erfcx from Beckmann's table)
//   Λ(w) = Λ₁(cot θ/α̃) from the table,  G1 = 1/(1 + Λ),  G2 = 1/(1 + Λo + Λi) or G1 G1
//
// D·cos and visible normals: exact samplers over the mixture (ms_mixture_sample_dcos_wm: β
// from the prior, then Beckmann's D·cos warp; ms_mixture_sample_wm: the posterior, then
// Beckmann's stream sampler), the Rust samplers' distributions, not their normals.

// ln f₁ at r: ln(erfcx(r)/(2√π r)) − r².
fn ms_erfc_ln_profile(r: f32) -> f32 {
    return log(ms_bk_erfcx(r) / (2.0 * MS_SQRT_PI * r)) - r * r;
}

// ln D(wm) for wm above the horizon (−1e30, D = 0, on and below it; NaN for NaN), +1e30 (D = +∞) at the pole (r = 0).
fn ms_erfc_ln_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return select(-1e30, wm.z, wm.z != wm.z);
    }
    let r = ms_mixture_r(wm, alpha);
    if r == 0.0 {
        return 1e30;
    }
    return ms_mixture_ln_d(ms_erfc_ln_profile(r), wm, alpha);
}

// D(wm); 0 on and below the horizon, +∞ at the pole, NaN for NaN.
fn ms_erfc_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let ln_d = ms_erfc_ln_d(wm, alpha);
    if ln_d >= 1e30 {
        return ms_inf();
    }
    return exp(ln_d);
}

// Smith Λ(w), Λ(−w) = Λ(w), from the shape table at `table`.
fn ms_erfc_lambda(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_shape_lambda(table, w, alpha);
}

// G1(w).
fn ms_erfc_g1(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g1(table, w, alpha);
}

// Height-correlated G2(wo, wi).
fn ms_erfc_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2(table, wo, wi, alpha);
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_erfc_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2_separable(table, wo, wi, alpha);
}

// The visible-normal density D_w(wm) (w.z < 0 mirrored).
fn ms_erfc_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_pdf(table, w, wm, alpha, ms_erfc_ln_d(wm, alpha));
}

// The D·cos density D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_erfc_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_erfc_d(wm, alpha) * wm.z;
}

// A D·cos normal from u, with its pdf.
fn ms_erfc_sample_dcos(alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_dcos_wm(table, alpha, u);
    return MsSample(wm, ms_erfc_pdf_dcos(wm, alpha));
}

// A visible normal for w (w.z < 0 mirrored) from u, with its pdf.
fn ms_erfc_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_wm(table, w, alpha, u);
    return MsSample(wm, ms_erfc_pdf(ms_unit(w), wm, alpha, table));
}
