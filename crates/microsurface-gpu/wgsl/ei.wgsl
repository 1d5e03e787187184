// microsurface WGSL library: the Ei NDF, anisotropic (ei.wgsl).
//
// The Rust `Microfacet<f32, Ei>` (crates/microsurface/src/fast/fitted.rs, the family's fast
// path; ndf/ei.rs for the formulas: the Ei_NDF page of d'Eon's "A Hitchhiker's Guide to
// Multiple Scattering"), in f32. A uniform superposition of Beckmann NDFs over roughness² ∈ (0, α²].
// Its Λ₁ lives in a shape table (mixture.wgsl; `microsurface_gpu::Tables::add_shape(NdfKind::
// Ei, None)` in Rust, one table for every roughness: the NDF is shape invariant).
//
//   D(m) = f₁(r)/(αx αy z⁴),  f₁(r) = E₁(r²)/π  (e^y E₁(y) from the MS_SF_E1X table)
//   Λ(w) = Λ₁(cot θ/α̃) from the table,  G1 = 1/(1 + Λ),  G2 = 1/(1 + Λo + Λi) or G1 G1
//
// D·cos and visible normals: exact samplers over the mixture (ms_mixture_sample_dcos_wm: β
// from the prior, then Beckmann's D·cos warp; ms_mixture_sample_wm: the posterior, then
// Beckmann's stream sampler), the Rust samplers' distributions, not their normals.

// ln f₁ at r: ln(e^y E₁(y)) − y − ln π, y = r²; below y = 2^−24, e^y E₁(y) = −γ_E − 2 ln r
// (from r: y itself may leave f32's normals).
fn ms_ei_ln_profile(r: f32) -> f32 {
    let y = r * r;
    if y < 5.9604645e-8 {
        return log(-MS_EULER_GAMMA - 2.0 * log(r)) - y - log(MS_PI);
    }
    return log(ms_e1x(y)) - y - log(MS_PI);
}

// ln D(wm) for wm above the horizon (−1e30, D = 0, on and below it; NaN for NaN), +1e30 (D = +∞) at the pole (r = 0).
fn ms_ei_ln_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return select(-1e30, wm.z, wm.z != wm.z);
    }
    let r = ms_mixture_r(wm, alpha);
    if r == 0.0 {
        return 1e30;
    }
    return ms_mixture_ln_d(ms_ei_ln_profile(r), wm, alpha);
}

// D(wm); 0 on and below the horizon, +∞ at the pole, NaN for NaN.
fn ms_ei_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let ln_d = ms_ei_ln_d(wm, alpha);
    if ln_d >= 1e30 {
        return ms_inf();
    }
    return exp(ln_d);
}

// Smith Λ(w), Λ(−w) = Λ(w), from the shape table at `table`.
fn ms_ei_lambda(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_shape_lambda(table, w, alpha);
}

// G1(w).
fn ms_ei_g1(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g1(table, w, alpha);
}

// Height-correlated G2(wo, wi).
fn ms_ei_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2(table, wo, wi, alpha);
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_ei_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2_separable(table, wo, wi, alpha);
}

// The visible-normal density D_w(wm) (w.z < 0 mirrored).
fn ms_ei_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_pdf(table, w, wm, alpha, ms_ei_ln_d(wm, alpha));
}

// The D·cos density D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_ei_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_ei_d(wm, alpha) * wm.z;
}

// A D·cos normal from u, with its pdf.
fn ms_ei_sample_dcos(alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_dcos_wm(table, alpha, u);
    return MsSample(wm, ms_ei_pdf_dcos(wm, alpha));
}

// A visible normal for w (w.z < 0 mirrored) from u, with its pdf.
fn ms_ei_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_wm(table, w, alpha, u);
    return MsSample(wm, ms_ei_pdf(ms_unit(w), wm, alpha, table));
}
