// microsurface WGSL library: Double GGX, anisotropic (double_ggx.wgsl).
//
// The Rust `Microfacet<f32, DoubleGgx>` (crates/microsurface/src/fast/double_ggx.rs, the
// `Shape for DoubleGgx` of distribution/microfacet.rs), with the Rust tables in the
// library's tables buffer (tables.wgsl). Double GGX is the Gamma-1 superposition of GGX,
// D = ∫₀^∞ e^{−t} D_GGX(α/√t) dt (d'Eon, "A Hitchhiker's Guide to Multiple Scattering"):
//
//   D(m) = G(1/y)/(π αx αy z⁴),  y = ((m.x/αx)² + (m.y/αy)²)/z²,
//          G(c) = c²((1 + c) e^c E₁(c) − 1)                    (0 for m.z ≤ 0)
//   Λ(w) = (x eˣ(K₀(x) + K₁(x)) − 1)/2,  x = (αx²w.x² + αy²w.y²)/(2w.z²)
//   G1 = 1/(1 + Λ),  G2 = 1/(1 + (Λ(wo) + Λ(wi))) (height-correlated), G1 G1 (separable)
//   D_w(m) = G1(w)(w·m)D(m)/|w.z|
//
// Λ is the Rust f32 path operation for operation (x in f32, the f32 cubic table DGGX32 on
// [2^−30, 2^16), Horner): isotropic materials form x from u = |w.z| as the Rust lambda32,
// anisotropic ones from the direction as lambda_aniso. Outside the table the Rust f32 path
// rounds its f64 ends; here the same expansions run in f32: x < 2^−30, Λ = (x/2)(1 − γ_E −
// ln(x/2)); x ≥ 2^16, Λ = √(π/2)√x(1 + 1/(8x) − 3/(128x²)) − ½ with √x formed without x.
// D: the Rust f64 path (the kernel table DGGX_D on y ∈ [2^−30, 2^30), degree 9) in f32, the
// table rounded to f32; outside it G(1/y) = 1 − 4y + O(y²) near the normal (4y < ε/16 there:
// 1) and G(1/y) = (ln y − γ_E − 1)/y² (1 + O(ln y/y)) at grazing, where D = (ln y − γ_E −
// 1)/(π αx αy q²), q = (m.x/αx)² + (m.y/αy)², without z⁴.
// D·cos: t ~ Exp(1) from the uniform stream (stream.wgsl's ziggurat), then GGX's D·cos
// at α/√t: m ∝ (αx √u₀ cos 2πu₁, αy √u₀ sin 2πu₁, √(t(1 − u₀))) (the Rust sample_dcos).
// Visible normals: the Rust rejection over t, then GGX's caps (ms_double_ggx_sample_wm).

const MS_EULER_GAMMA: f32 = 0.5772156649015329;

// One segment of an octave table at x ∈ [2^k0, 2^k1), 2^m segments per octave: its row and
// s ∈ [−1, 1), exactly from x's bits (the Rust fast::fit::octave_segment32); rows past the
// end clamped (the callers range-check x).
fn ms_fam_segment(x: f32, k0: i32, k1: i32, m: u32) -> vec2<f32> {
    let bits = bitcast<u32>(x);
    let rows = u32(k1 - k0) << m;
    let idx = min((bits >> (23u - m)) - (u32(127 + k0) << m), rows - 1u);
    let pos = (bits << (9u + m)) >> 9u;
    return vec2<f32>(f32(idx), bitcast<f32>(0x40000000u | pos) - 3.0);
}

// A cubic row (s⁰ first) by Horner's rule, as the Rust fit::poly for four coefficients.
fn ms_fam_cubic(c: vec4<f32>, s: f32) -> f32 {
    return ((c.w * s + c.z) * s + c.y) * s + c.x;
}

// Double GGX Λ from the table at x ∈ [2^−30, 2^16) (the Rust eval32 of DGGX32).
fn ms_dg_lambda_table(x: f32) -> f32 {
    let g = ms_fam_segment(x, MS_DG_LAMBDA_K0, MS_DG_LAMBDA_K1, MS_DG_LAMBDA_M);
    return ms_fam_cubic(ms_tables[MS_DG_LAMBDA_AT + u32(g.x)], g.y);
}

// Λ outside the table at u = |w.z| and the (projected) roughness a: the near-normal
// expansion (0 at x ≤ 0), or the grazing one from √x = a√((1 − u)(1 + u)/2)/u, which does
// not overflow while Λ is finite (+∞ at u = 0); NaN stays NaN.
fn ms_dg_lambda_ends(u: f32, a: f32) -> f32 {
    let x = 0.5 * a * a * ((1.0 - u) * (1.0 + u)) / (u * u);
    if x < 9.313225746154785e-10 {
        if x <= 0.0 {
            return 0.0;
        }
        return 0.5 * x * (1.0 - MS_EULER_GAMMA - log(0.5 * x));
    }
    let sx = a * sqrt(0.5 * (1.0 - u) * (1.0 + u)) / u;
    let r = 1.0 / (sx * sx);
    return (1.2533141373155003 * sx) * (1.0 + r * (0.125 - r * (3.0 / 128.0))) - 0.5;
}

// Smith Λ(w), Λ(−w) = Λ(w), from x = (αx²w.x² + αy²w.y²)/(2w.z²) for isotropic materials too
// (the Rust lambda_aniso, which the door takes for both: 1 − u² of a rounded unit vector has
// lost its digits near the normal); the ends at the projected roughness
// α̃² = (αx²x² + αy²y²)/(x² + y²) (the Rust lambda_projected).
fn ms_double_ggx_lambda(w: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let u = abs(w.z);
    let sx = alpha.x * w.x;
    let sy = alpha.y * w.y;
    let x = 0.5 * ((sx * sx + sy * sy) / (w.z * w.z));
    // 2^−30 ≤ x < 2^16 (false for NaN).
    if x >= 9.313225746154785e-10 && x < 65536.0 {
        return ms_dg_lambda_table(x);
    }
    var a = alpha.x;
    let s2 = w.x * w.x + w.y * w.y;
    if s2 > 0.0 {
        a = sqrt((alpha.x * alpha.x * w.x * w.x + alpha.y * alpha.y * w.y * w.y) / s2);
    }
    return ms_dg_lambda_ends(u, a);
}

// G1(w) = 1/(1 + Λ(w)); 0 on the horizon.
fn ms_double_ggx_g1(w: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if w.z == 0.0 {
        return 0.0;
    }
    return 1.0 / (1.0 + ms_double_ggx_lambda(w, alpha));
}

// Height-correlated G2(wo, wi) = 1/(1 + (Λ(wo) + Λ(wi))).
fn ms_double_ggx_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if wo.z == 0.0 || wi.z == 0.0 {
        return 0.0;
    }
    return 1.0 / (1.0 + (ms_double_ggx_lambda(wo, alpha) + ms_double_ggx_lambda(wi, alpha)));
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_double_ggx_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>) -> f32 {
    return ms_double_ggx_g1(wo, alpha) * ms_double_ggx_g1(wi, alpha);
}

// The degree-9 kernel row (three vec4, s⁰ first) by Estrin's scheme, as the Rust estrin.
fn ms_dg_kernel_row(i: u32, s: f32) -> f32 {
    let c0 = ms_tables[MS_DG_D_AT + 3u * i];
    let c1 = ms_tables[MS_DG_D_AT + 3u * i + 1u];
    let c2 = ms_tables[MS_DG_D_AT + 3u * i + 2u];
    let s2 = s * s;
    let s4 = s2 * s2;
    let s8 = s4 * s4;
    let b0 = c0.x + c0.y * s;
    let b1 = c0.z + c0.w * s;
    let b2 = c1.x + c1.y * s;
    let b3 = c1.z + c1.w * s;
    let b4 = c2.x + c2.y * s;
    return ((b0 + b1 * s2) + (b2 + b3 * s2) * s4) + b4 * s8;
}

// D(wm) (the Rust d_aniso, isotropic included): G(1/y) r/(π z⁴), r = 1/(αx αy), from the
// stretched normal; 0 below the horizon.
fn ms_double_ggx_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let z = wm.z;
    let r = 1.0 / (alpha.x * alpha.y);
    let x = wm.x * alpha.y * r;
    let y = wm.y * alpha.x * r;
    let q = x * x + y * y;
    if !(z > 0.0) {
        return select(0.0, z, z != z);
    }
    let z2 = z * z;
    let t = q / z2;
    // y ∈ [2^−30, 2^30): the kernel's table (false for NaN).
    if t >= 9.313225746154785e-10 && t < 1073741824.0 {
        let g = ms_fam_segment(t, MS_DG_D_K0, MS_DG_D_K1, MS_DG_D_M);
        return ms_dg_kernel_row(u32(g.x), g.y) * r / (MS_PI * z2 * z2);
    }
    if t < 9.313225746154785e-10 {
        return r / (MS_PI * z2 * z2);
    }
    // Grazing (t may have overflowed): ln y = ln q − 2 ln z.
    return (log(q) - 2.0 * log(z) - MS_EULER_GAMMA - 1.0) * r / (MS_PI * q * q);
}

// The visible-normal density D_w(wm) = G1(w)(w·wm)D(wm)/|w.z| (the Rust d_visible_with);
// w.z < 0 mirrored; 0 at grazing w and for wm facing away from w.
fn ms_double_ggx_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let z = abs(w.z);
    var c = ms_dot(w, wm);
    if w.z < 0.0 {
        c = -c;
    }
    if !(c > 0.0 && z > 0.0) {
        return 0.0;
    }
    return ms_double_ggx_g1(w, alpha) * c * ms_double_ggx_d(wm, alpha) / z;
}

// The density of ms_double_ggx_sample_dcos: D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_double_ggx_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_double_ggx_d(wm, alpha) * wm.z;
}

// A normal distributed as D(m) cos θm with its pdf (the Rust sample_dcos): t ~ Exp(1) from
// the stream of u (the ziggurat), floored at 1e-36 (the Rust f32 floor, 1e-60, is below
// f32's range; t = 0 has probability 2^−24 and would put the normal on the horizon), then
// GGX's D·cos normal at α/√t driven by u.
fn ms_double_ggx_sample_dcos(alpha: vec2<f32>, u: vec2<f32>) -> MsSample {
    var src = ms_source_stream(u);
    let t = max(ms_zig_exp1(ms_source_next(&src), &src), 1e-36);
    let cs = ms_cos_sin_turn(u.y);
    let r = sqrt(u.x);
    let wm = ms_unit_normal(vec3<f32>(alpha.x * r * cs.x, alpha.y * r * cs.y,
        sqrt(t * max(1.0 - u.x, 0.0))));
    return MsSample(wm, ms_double_ggx_d(wm, alpha) * wm.z);
}

// A visible normal for w (w.z < 0 mirrored) from u ∈ [0, 1)² (the Rust sample_visible, in
// f32): σ is linear in D, so the visible normals of the superposition are its GGX
// components' with weights e^{−t} σ_t(w), σ_t = (c + √(c² + h²/t))/2 (c = w.z, h the
// stretched horizontal length). t is drawn by rejection from the envelope e^{−t}(2c +
// h t^{−1/2}), a mixture of Exp(1) (mass 2c) and Gamma(½) = Z²/2 (mass h√π, Z half-normal),
// both by ziggurat over the stream of u, and kept with probability (c s + √(c²t + h²))/(2c s
// + h), s = √t (≥ 4/5); the normal is then GGX's cap at the stretch (αx, αy, s), driven by u.
// t is floored at 1e-36 as in ms_double_ggx_sample_dcos.
fn ms_double_ggx_sample_wm(w_in: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>) -> vec3<f32> {
    var w = ms_unit(w_in);
    if w.z < 0.0 {
        w = -w;
    }
    let sx = alpha.x * w.x;
    let sy = alpha.y * w.y;
    let c = w.z;
    let h = sqrt(sx * sx + sy * sy);
    if !(abs(c + h) <= 3.4028235e38) {
        return vec3<f32>(c + h);
    }
    let e = 2.0 * c;
    let g = MS_SQRT_PI * h;
    let p_exp = e / (e + g);
    // (Capped: at grazing w or normal incidence a share is 0 and its reciprocal infinite.)
    let inv_p = min((e + g) / e, 3.4028235e38);
    let inv_q = min((e + g) / g, 3.4028235e38);
    var src = ms_source_stream(u);
    var s = 1.0;
    var len = 1.0;
    for (var n = 0; n < 64; n++) {
        let v = ms_source_next(&src);
        var t: f32;
        if v < p_exp {
            t = ms_zig_exp1(v * inv_p, &src);
        } else {
            let z = ms_zig_half_normal((v - p_exp) * inv_q, &src);
            t = 0.5 * z * z;
        }
        t = max(t, 1e-36);
        s = sqrt(t);
        len = sqrt(c * c * t + h * h);
        if ms_source_next(&src) * (e * s + h) <= c * s + len {
            break;
        }
    }
    let m = ms_ggx_cap_normal_stretched(w, vec3<f32>(alpha, s), u, len);
    return ms_facing(m, w);
}

// A visible normal with its pdf (ms_double_ggx_pdf).
fn ms_double_ggx_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>) -> MsSample {
    let wm = ms_double_ggx_sample_wm(w, alpha, u);
    return MsSample(wm, ms_double_ggx_pdf(ms_unit(w), wm, alpha));
}
