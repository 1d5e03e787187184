// microsurface WGSL library: the Exponential NDF, anisotropic (exponential.wgsl).
//
// The Rust `Microfacet<f32, Exponential>` (crates/microsurface/src/fast/exponential.rs, the
// `Shape for Exponential` of distribution/microfacet.rs), with the Rust tables in the
// library's tables buffer (tables.wgsl). The slope density is P22(r) = 2e^{−2r}/π at unit roughness
// (d'Eon, "A Hitchhiker's Guide to Multiple Scattering"; derivations.md A.14):
//
//   D(m) = 2 e^{−2√q/z}/(π αx αy z⁴),  q = (m.x/αx)² + (m.y/αy)²        (0 for m.z ≤ 0)
//   Λ(w) = (2K₁(z) − Ki₁(z))/π,  z = 2|w.z|/√(αx²w.x² + αy²w.y²)
//   G1 = 1/(1 + Λ),  G2 = 1/(1 + (Λ(wo) + Λ(wi))) (height-correlated), G1 G1 (separable)
//   D_w(m) = G1(w)(w·m)D(m)/|w.z|
//
// Λ: the Rust f32 path reads its f32 cubic tables (EXPONENTIAL32_QA on q = z² ∈ [2^−24, 64),
// _QB on [64, 4096), Horner) at a q formed in f64; here q is formed in f32 (WGSL has no
// portable f64), which costs Λ its condition number in z (about z, up to 64 in the tables)
// times q's few roundings: the bound of tests/family.rs. Outside the tables (the Rust f64
// ends, in f32): z < 2^−12, Λ = 2/(πz) − ½ + z/(2π); 64 ≤ z < 2^9, Λ e^z from the far table
// (EXPONENTIAL_FAR rounded to f32) times e^{−z}; beyond, 0 (e^{−z} is below f32's range).
// D: e^{−e}, e = 2√q/z, times the normalisation; past e = 80 the normalisation joins the
// exponent (as beckmann.wgsl's D), so that D stays a normal f32 where the Rust path (in f64)
// has one. D·cos: the slope radius at unit roughness is Gamma(2, ½): r = ½(E − ln(1 − u₀)),
// E ~ Exp(1) from the uniform stream (stream.wgsl's ziggurat), azimuth 2πu₁, stretched (the
// Rust sample_dcos). Visible normals: the Rust rejection in slope space over the stream
// of u (ms_exponential_sample_wm).

// Λ from the q tables at 2^−24 ≤ q < 4096 (the Rust eval_narrow of EXPONENTIAL32_QA/_QB).
fn ms_exp_lambda_q(q: f32) -> f32 {
    if q < 64.0 {
        let g = ms_fam_segment(q, MS_EXP_QA_K0, MS_EXP_QA_K1, MS_EXP_QA_M);
        return ms_fam_cubic(ms_tables[MS_EXP_QA_AT + u32(g.x)], g.y);
    }
    let g = ms_fam_segment(q, MS_EXP_QB_K0, MS_EXP_QB_K1, MS_EXP_QB_M);
    return ms_fam_cubic(ms_tables[MS_EXP_QB_AT + u32(g.x)], g.y);
}

// Λ(z) past the q tables (the Rust lambda_z_ends): +∞ at z = 0, NaN for NaN.
fn ms_exp_lambda_z(z: f32) -> f32 {
    if z < 2.44140625e-4 {
        return 0.6366197723675814 / z - 0.5 + 0.15915494309189535 * z;
    }
    let q = z * z;
    if q < 4096.0 {
        return ms_exp_lambda_q(q);
    }
    if z < 512.0 {
        let g = ms_fam_segment(z, MS_EXP_FAR_K0, MS_EXP_FAR_K1, MS_EXP_FAR_M);
        let i = 2u * u32(g.x);
        let lo = ms_tables[MS_EXP_FAR_AT + i];
        let hi = ms_tables[MS_EXP_FAR_AT + i + 1u];
        let s = g.y;
        let s2 = s * s;
        let p = ((lo.x + lo.y * s) + (lo.z + lo.w * s) * s2) + ((hi.x + hi.y * s) + hi.z * s2) * (s2 * s2);
        return p * exp(-z);
    }
    if z != z {
        return z;
    }
    return 0.0;
}

// Smith Λ(w), Λ(−w) = Λ(w), from q = 4w.z²/(αx²w.x² + αy²w.y²) for isotropic materials too
// (the Rust lambda_aniso, which the door takes for both: 1 − u² of a rounded unit vector has
// lost its digits near the normal); the ends at z = 2u/(α̃√((1 − u)(1 + u))), α̃ the projected
// roughness (the Rust lambda_projected).
fn ms_exponential_lambda(w: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let u = abs(w.z);
    let sx = alpha.x * w.x;
    let sy = alpha.y * w.y;
    let q = 4.0 * (w.z * w.z) / (sx * sx + sy * sy);
    // 2^−24 ≤ q < 4096 (false for NaN).
    if q >= 5.960464477539063e-8 && q < 4096.0 {
        return ms_exp_lambda_q(q);
    }
    var a = alpha.x;
    let s2 = w.x * w.x + w.y * w.y;
    if s2 > 0.0 {
        a = sqrt((alpha.x * alpha.x * w.x * w.x + alpha.y * alpha.y * w.y * w.y) / s2);
    }
    return ms_exp_lambda_z((u + u) / (a * sqrt((1.0 - u) * (1.0 + u))));
}

// G1(w) = 1/(1 + Λ(w)); 0 on the horizon.
fn ms_exponential_g1(w: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if w.z == 0.0 {
        return 0.0;
    }
    return 1.0 / (1.0 + ms_exponential_lambda(w, alpha));
}

// Height-correlated G2(wo, wi) = 1/(1 + (Λ(wo) + Λ(wi))).
fn ms_exponential_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if wo.z == 0.0 || wi.z == 0.0 {
        return 0.0;
    }
    return 1.0 / (1.0 + (ms_exponential_lambda(wo, alpha) + ms_exponential_lambda(wi, alpha)));
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_exponential_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>) -> f32 {
    return ms_exponential_g1(wo, alpha) * ms_exponential_g1(wi, alpha);
}

// D(wm) (the Rust d_aniso, isotropic included); 0 below the horizon.
fn ms_exponential_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let z = wm.z;
    let r = 1.0 / (alpha.x * alpha.y);
    let x = wm.x * alpha.y * r;
    let y = wm.y * alpha.x * r;
    let z2 = z * z;
    if !(z > 0.0 && z2 > 0.0) {
        return select(0.0, z, z != z);
    }
    let e = 2.0 * sqrt(x * x + y * y) / z;
    if e <= 80.0 {
        return 2.0 * exp(-e) * r / (MS_PI * z2 * z2);
    }
    return exp((log(2.0 * r) - log(MS_PI) - 4.0 * log(z)) - e);
}

// The visible-normal density D_w(wm) = G1(w)(w·wm)D(wm)/|w.z| (the Rust d_visible_with);
// w.z < 0 mirrored; 0 at grazing w and for wm facing away from w.
fn ms_exponential_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let z = abs(w.z);
    var c = ms_dot(w, wm);
    if w.z < 0.0 {
        c = -c;
    }
    if !(c > 0.0 && z > 0.0) {
        return 0.0;
    }
    return ms_exponential_g1(w, alpha) * c * ms_exponential_d(wm, alpha) / z;
}

// The density of ms_exponential_sample_dcos: D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_exponential_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_exponential_d(wm, alpha) * wm.z;
}

// A normal distributed as D(m) cos θm with its pdf (the Rust sample_dcos): r = ½(E − ln(1 −
// u₀)) at unit roughness, E ~ Exp(1) from the stream of u, azimuth 2πu₁; m ∝ (αx r cos φ,
// αy r sin φ, 1), or divided by r past r = 1 (the Rust normal_from_polar).
fn ms_exponential_sample_dcos(alpha: vec2<f32>, u: vec2<f32>) -> MsSample {
    var src = ms_source_stream(u);
    let e = ms_zig_exp1(ms_source_next(&src), &src);
    let r = 0.5 * (e - ms_bk_ln_1m(u.x));
    let cs = ms_cos_sin_turn(u.y);
    var v: vec3<f32>;
    if r > 1.0 {
        v = vec3<f32>(alpha.x * cs.x, alpha.y * cs.y, 1.0 / r);
    } else {
        v = vec3<f32>(alpha.x * r * cs.x, alpha.y * r * cs.y, 1.0);
    }
    let wm = ms_unit_normal(v);
    return MsSample(wm, ms_exponential_d(wm, alpha) * wm.z);
}

// A visible normal for w (w.z < 0 mirrored) from u ∈ [0, 1)² (the Rust sample_visible, in
// f32), by rejection in slope space. In the stretched frame of w (h cos φ, h sin φ, c) the
// visible slopes (x̃ along φ, ỹ across) have the density (c + h x̃)⁺ P22, P22(r) =
// 2e^{−2r}/π; the envelope c + h x̃⁺ has two exactly sampled parts: c P22 (mass c; r ~
// Gamma(2, ½) = −½ ln(v₁v₂), azimuth uniform; kept where x̃ ≥ 0, else with probability
// (c + h x̃)⁺/c) and h x̃⁺ P22 (mass h/π; r ~ Gamma(3, ½), sin ψ uniform on (−1, 1)). u
// drives the first candidate (u₀ the part and the azimuth, u₁ a factor of the radius), the
// stream of u the rest.
fn ms_exponential_sample_wm(w_in: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>) -> vec3<f32> {
    var w = ms_unit(w_in);
    if w.z < 0.0 {
        w = -w;
    }
    let sx = alpha.x * w.x;
    let sy = alpha.y * w.y;
    let c = w.z;
    let h = sqrt(sx * sx + sy * sy);
    var cp = 1.0;
    var sp = 0.0;
    if h > 0.0 {
        cp = sx / h;
        sp = sy / h;
    }
    if !(abs(c + h) <= 3.4028235e38) {
        return vec3<f32>(c + h);
    }
    let e = c;
    let g = h * MS_FRAC_1_PI;
    let total = e + g;
    // (Capped: at grazing w or normal incidence a mass is 0 and its reciprocal infinite.)
    let inv_p = min(total / e, 3.4028235e38);
    let inv_g = min(1.0 / g, 3.4028235e38);
    var state = ms_stream_new(u);
    var v0 = u.x;
    var v1 = u.y;
    var x = 0.0;
    var y = 0.0;
    // Each candidate is kept with probability above ½; the cap only guarantees termination.
    for (var n = 0; n < 64; n++) {
        if n > 0 {
            v0 = ms_stream_next(&state);
            v1 = ms_stream_next(&state);
        }
        let prod = (1.0 - v1) * (1.0 - ms_stream_next(&state));
        let d = v0 * total - e;
        if d < 0.0 {
            let r = -0.5 * log(prod);
            let turn = v0 * inv_p;
            let cs = ms_cos_sin_turn(turn);
            x = r * cs.x;
            y = r * cs.y;
            if abs(turn - 0.5) >= 0.25 || ms_stream_next(&state) * c <= c + h * x {
                break;
            }
        } else {
            let r = -0.5 * log(prod * (1.0 - ms_stream_next(&state)));
            // sin ψ = s = 2d/g − 1, with 1 + s = 2d/g and 1 − s = 2(1 − v₀)(total/g) each
            // formed without cancellation (1 − s from s itself would lose its digits as
            // v₀ → 1 in f32; the Rust path is f64).
            let one_plus = 2.0 * (d * inv_g);
            let one_minus = 2.0 * (1.0 - v0) * (total * inv_g);
            x = r * sqrt(max(one_minus * one_plus, 0.0));
            y = r * (one_plus - 1.0);
            break;
        }
    }
    let p = alpha.x * (cp * x - sp * y);
    let q = alpha.y * (sp * x + cp * y);
    let m = ms_unit_normal(vec3<f32>(p, q, 1.0));
    return ms_facing(m, w);
}

// A visible normal with its pdf (ms_exponential_pdf).
fn ms_exponential_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>) -> MsSample {
    let wm = ms_exponential_sample_wm(w, alpha, u);
    return MsSample(wm, ms_exponential_pdf(ms_unit(w), wm, alpha));
}
