// microsurface WGSL library: the Bessel-K NDF, anisotropic (bessel_k.wgsl).
//
// The Rust `Microfacet<f32, BesselK>` (crates/microsurface/src/fast/fitted.rs, the family's fast
// path; ndf/bessel_k.rs for the formulas: the BesselK_NDF page of d'Eon's "A Hitchhiker's Guide to
// Multiple Scattering"), in f32. The Gamma(a) superposition of Beckmann NDFs over roughness α√t
// (K0 at a = 1).
// Its Λ₁ and profile live in a shape table (mixture.wgsl; `microsurface_gpu::Tables::add_shape(
// NdfKind::BesselK, Some(a))` in Rust, one table per a for every roughness: shape invariant),
// the profile as a block after the Λ₁ rows (row 2's w its offset): a row (ν, k0, k1, 0),
// then the octave table of h(x) = ln f₁(x) + 2x on [2^k0, 2^k1) (degree 7, two rows a segment,
// fitted to the Rust f64 profile).
//
//   D(m) = f₁(r)/(αx αy z⁴),  f₁(r) = 2 r^ν K_ν(2r)/(π Γ(a)),  ν = a − 1
//   Λ(w) = Λ₁(cot θ/α̃) from the table,  G1 = 1/(1 + Λ),  G2 = 1/(1 + Λo + Λi) or G1 G1
//
// D·cos and visible normals: exact samplers over the mixture (ms_mixture_sample_dcos_wm: β
// from the prior, then Beckmann's D·cos warp; ms_mixture_sample_wm: the posterior, then
// Beckmann's stream sampler), the Rust samplers' distributions, not their normals.

// h(x) = ln f₁(x) + 2x from the profile block at `at` (head = its first row), x in the table.
fn ms_bessel_k_h(at: u32, head: vec4<f32>, x: f32) -> f32 {
    let g = ms_bk_segment(x, i32(head.y), i32(head.z));
    let i = at + 1u + 2u * u32(g.x);
    return ms_bk_poly(ms_tables[i], ms_tables[i + 1u], g.y);
}

// ln f₁ at r = x: h(x) − 2x in the table; past it f₁ < e^{−500} (−1e30: D = 0); below 2^k0
// (within 1e-12 α of the pole) the profile's leading power from the table's first node x₀:
// 2ν ln(x/x₀) for ν < 0, ln(ln x/ln x₀) for ν = 0 (f₁ ∝ −ln x), constant for ν > 0.
fn ms_bessel_k_ln_profile(table: u32, x: f32) -> f32 {
    let at = table + u32(ms_tables[table + 2u].w);
    let head = ms_tables[at];
    if !(x < exp2(head.z)) {
        return select(-1e30, x, x != x);
    }
    let x0 = exp2(head.y);
    if x < x0 {
        let h0 = ms_bessel_k_h(at, head, x0) - 2.0 * x0;
        if head.x < 0.0 {
            return h0 + 2.0 * head.x * log(x / x0);
        }
        if head.x == 0.0 {
            return h0 + log(log(x) / log(x0));
        }
        return h0;
    }
    return ms_bessel_k_h(at, head, x) - 2.0 * x;
}

// ln D(wm) for wm above the horizon (−1e30, D = 0, on and below it; NaN for NaN), at the pole (r = 0) ln(1/(πν αx αy)) or +1e30 (+∞).
fn ms_bessel_k_ln_d(wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    if !(wm.z > 0.0) {
        return select(-1e30, wm.z, wm.z != wm.z);
    }
    let r = ms_mixture_r(wm, alpha);
    if r == 0.0 {
        let nu = ms_tables[table].x - 1.0;
        if nu > 0.0 {
            return -log(MS_PI * nu * alpha.x * alpha.y) - 4.0 * log(wm.z);
        }
        return 1e30;
    }
    return ms_mixture_ln_d(ms_bessel_k_ln_profile(table, r), wm, alpha);
}

// D(wm); 0 on and below the horizon, 1/(πν αx αy) or +∞ at the pole, NaN for NaN.
fn ms_bessel_k_d(wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    let ln_d = ms_bessel_k_ln_d(wm, alpha, table);
    if ln_d >= 1e30 {
        return ms_inf();
    }
    return exp(ln_d);
}

// Smith Λ(w), Λ(−w) = Λ(w), from the shape table at `table`.
fn ms_bessel_k_lambda(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_shape_lambda(table, w, alpha);
}

// G1(w).
fn ms_bessel_k_g1(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g1(table, w, alpha);
}

// Height-correlated G2(wo, wi).
fn ms_bessel_k_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2(table, wo, wi, alpha);
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_bessel_k_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2_separable(table, wo, wi, alpha);
}

// The visible-normal density D_w(wm) (w.z < 0 mirrored).
fn ms_bessel_k_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_pdf(table, w, wm, alpha, ms_bessel_k_ln_d(wm, alpha, table));
}

// The D·cos density D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_bessel_k_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_bessel_k_d(wm, alpha, table) * wm.z;
}

// A D·cos normal from u, with its pdf.
fn ms_bessel_k_sample_dcos(alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_dcos_wm(table, alpha, u);
    return MsSample(wm, ms_bessel_k_pdf_dcos(wm, alpha, table));
}

// A visible normal for w (w.z < 0 mirrored) from u, with its pdf.
fn ms_bessel_k_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_wm(table, w, alpha, u);
    return MsSample(wm, ms_bessel_k_pdf(ms_unit(w), wm, alpha, table));
}
