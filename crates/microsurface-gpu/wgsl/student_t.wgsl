// microsurface WGSL library: the Student-T NDF, anisotropic (student_t.wgsl).
//
// The Rust `Microfacet<f32, StudentT>` (crates/microsurface/src/fast/fitted.rs, the family's
// fast path; ndf/student_t.rs for the formulas: Ribardière, Bringier, Meneveaux & Simonot
// 2017, "STD: Student's t-Distribution of Slopes for Microfacet Based BSDFs", and the
// StudentT_NDF page of d'Eon's "A Hitchhiker's Guide to Multiple Scattering"), in f32.
// The shape γ (> 3/2) and the fitted Λ₁ live in the material's shape table (mixture.wgsl;
// `microsurface_gpu::Tables::add_shape` in Rust): a material is (α, the table's row).
//
//   D(m) = (1 + q/(γ − 1))^{−γ}/(π αx αy z⁴),  q = ((m.x/αx)² + (m.y/αy)²)/z²  (0 for z ≤ 0)
//   Λ(w) = Λ₁(cot θ/α̃) from the table,  G1 = 1/(1 + Λ),  G2 = 1/(1 + Λo + Λi) or G1 G1
//   D_w(m) = G1(w)(w·m)D(m)/|w.z|
//
// D·cos: the radial quantile of Ribardière et al. (their eq. 18), tan²θ/α² = (γ − 1)
// expm1(−ln(1 − u₀)/(γ − 1)), azimuth 2πu₁, stretched: the Rust warp (the same normal for the
// same u, to f32's rounding). Visible normals: the mixing variable's posterior (Student-T is
// the inverse-Gamma(γ − 1) superposition of Beckmann), then Beckmann's stream sampler
// (mixture.wgsl): the Rust sampler's distribution, not its normals.

// The shape γ of the table at `table`.
fn ms_student_t_gamma(table: u32) -> f32 {
    return ms_tables[table].x;
}

// ln(1 + t) for t ≥ 0 without losing small t (the classic correction of log(1 + t)).
fn ms_ln_1p(t: f32) -> f32 {
    let v = 1.0 + t;
    if v == 1.0 {
        return t;
    }
    return log(v) * (t / (v - 1.0));
}

// e^x − 1 without losing small x: its Taylor series to x⁹ below |x| = ½ (the next term,
// 2^−10/10!, is below ε/20 relative), e^x − 1 above (where the subtraction magnifies exp's
// error at most e^½/(e^½ − 1) ≈ 2.6 times).
fn ms_expm1(x: f32) -> f32 {
    if abs(x) < 0.5 {
        return x * (1.0 + x * (0.5 + x * (1.0 / 6.0 + x * (1.0 / 24.0 + x * (1.0 / 120.0
            + x * (1.0 / 720.0 + x * (1.0 / 5040.0 + x * (1.0 / 40320.0 + x * (1.0 / 362880.0)))))))));
    }
    return exp(x) - 1.0;
}

// D(wm); 0 on and below the horizon. In logarithms (D = e^{−γ ln(1 + t) − …}), so that a
// large t or a small z⁴ does not overflow or underflow on the way.
fn ms_student_t_d(wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    let z = wm.z;
    if !(z > 0.0) {
        return select(0.0, z, z != z);
    }
    let g = ms_student_t_gamma(table);
    let x = wm.x / alpha.x;
    let y = wm.y / alpha.y;
    let q = x * x + y * y;
    let z2 = z * z;
    if z > 1e-9 {
        let t = q / (z2 * (g - 1.0));
        let e = g * ms_ln_1p(t);
        let norm = MS_PI * alpha.x * alpha.y * z2 * z2;
        // (Past e = 80, e^{−e} nears f32's least normal: the normalisation joins the exponent,
        // so that D stays a normal f32 where it is one, as the Rust f64 D rounds.)
        if e < 80.0 {
            return exp(-e) / norm;
        }
        return exp(-e - log(norm));
    }
    // Grazing: ln(1 + t) = ln q − 2 ln z − ln(γ − 1) (+ (γ − 1)z²/q, below ε there for
    // γ ≤ 1e6 at z ≤ 1e-9 and q ≥ 1e-3; q smaller here makes D vanish anyway), with z's two
    // powers joined, (2γ − 4) ln z: apart they cancel (2γ ln z against 4 ln z, hundreds each).
    let ln_d = -g * (log(q) - log(g - 1.0)) + (2.0 * g - 4.0) * log(z)
        - log(MS_PI * alpha.x * alpha.y);
    return exp(ln_d);
}

// Smith Λ(w), Λ(−w) = Λ(w).
fn ms_student_t_lambda(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_shape_lambda(table, w, alpha);
}

// G1(w) (mixture.wgsl's, over the shape table).
fn ms_student_t_g1(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g1(table, w, alpha);
}

// Height-correlated G2(wo, wi).
fn ms_student_t_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2(table, wo, wi, alpha);
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_student_t_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2_separable(table, wo, wi, alpha);
}

// The visible-normal density D_w(wm) = G1(w)(w·wm)D(wm)/|w.z|; w.z < 0 mirrored; 0 at grazing
// w and for wm facing away from w.
fn ms_student_t_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    let z = abs(w.z);
    var c = ms_dot(w, wm);
    if w.z < 0.0 {
        c = -c;
    }
    if !(c > 0.0 && z > 0.0) {
        return 0.0;
    }
    // ((c/z) first: G1 c D can pass below f32's normals where the density is one.)
    return ms_student_t_g1(w, alpha, table) * (c / z) * ms_student_t_d(wm, alpha, table);
}

// The density of ms_student_t_sample_dcos: D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_student_t_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_student_t_d(wm, alpha, table) * wm.z;
}

// A normal distributed as D(m) cos θm with its pdf: the radial quantile r² = (γ − 1)
// expm1(−ln(1 − u₀)/(γ − 1)) at unit roughness (the Rust slope_quantile), azimuth 2πu₁, m ∝
// (αx r cos φ, αy r sin φ, 1), or divided by r past r = 1 (the Rust normal_from_polar).
fn ms_student_t_sample_dcos(alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let g1 = ms_student_t_gamma(table) - 1.0;
    let r = sqrt(g1 * ms_expm1(-ms_bk_ln_1m(u.x) / g1));
    let cs = ms_cos_sin_turn(u.y);
    var v: vec3<f32>;
    if r > 1.0 {
        v = vec3<f32>(alpha.x * cs.x, alpha.y * cs.y, 1.0 / r);
    } else {
        v = vec3<f32>(alpha.x * r * cs.x, alpha.y * r * cs.y, 1.0);
    }
    let wm = ms_unit_normal(v);
    return MsSample(wm, ms_student_t_pdf_dcos(wm, alpha, table));
}

// A visible normal for w (w.z < 0 mirrored) from u, with its pdf: the posterior of the
// inverse-Gamma(γ − 1) mixing, then Beckmann's stream sampler (mixture.wgsl).
fn ms_student_t_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_wm(table, w, alpha, u);
    return MsSample(wm, ms_student_t_pdf(ms_unit(w), wm, alpha, table));
}
