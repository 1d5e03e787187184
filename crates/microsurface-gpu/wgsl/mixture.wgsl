// microsurface WGSL library: what the Beckmann mixtures share (mixture.wgsl): their fitted Λ
// from a material's shape table, and exact visible-normal sampling by the mixing variable's
// posterior over the uniform stream.
//
// A shape table (written by the Rust `microsurface_gpu::Tables::add_shape`, from the Rust
// fast path's own `fast::fitted::FittedShape` of the shape, rounded to f32) lies in the
// library's buffer `ms_tables` from the material's row `table`:
//   row 0: (shape (γ, a; 0 for none), k₁, 1 if the rows hold Λ₁ itself else 0, σ₁(0))
//   row 1: (1 for a power-law tail else 0, p, ln K, K₂): Λ₁ = e^{ln K − p ln z}(1 + K₂/z²)
//          past z = 2^k₁ (0 past it for the others)
//   row 2: (E[β] of the prior, the mixing's parameter k, the mixing (ms_mixing_ln_beta's
//          code), 0)
//   rows 3…: the Λ₁ rows, two vec4 each (five coefficients of the degree-4 polynomial in
//          s ∈ [−1, 1), s⁰ first), 32 rows an octave of z = cot θ/α̃ from 2^−24 to 2^k₁,
//          holding Λ₁ or 256 log₂ Λ₁ (the Rust `FittedShape` layout).
// Every member is shape invariant: Λ(w) = Λ₁(z) with z = |w.z|/|(αx w.x, αy w.y)|.

const MS_SHAPE_K0: i32 = -24;
const MS_SHAPE_M: u32 = 5u;
// Rows before the Λ₁ rows of a shape table.
const MS_SHAPE_HEADER: u32 = 3u;

// Λ₁(z) of the shape table at `table` (the Rust FittedShape::lambda_z in f32): the row's
// polynomial by Horner's rule, through exp2 where the rows hold 256 log₂ Λ₁; σ₁(0)/z − ½
// below 2^−24 (+∞ at 0), the tail past 2^k₁; NaN stays NaN.
fn ms_shape_lambda_z(table: u32, z: f32) -> f32 {
    let head = ms_tables[table];
    let k1 = i32(head.y);
    if z >= 5.9604645e-8 && z < exp2(head.y) {
        let g = ms_fam_segment(z, MS_SHAPE_K0, k1, MS_SHAPE_M);
        let i = table + MS_SHAPE_HEADER + 2u * u32(g.x);
        let lo = ms_tables[i];
        let hi = ms_tables[i + 1u];
        let s = g.y;
        let p = (((hi.x * s + lo.w) * s + lo.z) * s + lo.y) * s + lo.x;
        if head.z > 0.5 {
            return p;
        }
        return exp2(p * (1.0 / 256.0));
    }
    if z != z {
        return z;
    }
    if z < 5.9604645e-8 {
        return head.w / z - 0.5;
    }
    let tail = ms_tables[table + 1u];
    if tail.x < 0.5 {
        return 0.0;
    }
    return exp(tail.z - tail.y * log(z)) * (1.0 + tail.w / (z * z));
}

// Λ(w) of the shape at (αx, αy), Λ(−w) = Λ(w): +∞ on the horizon, 0 at the normal.
fn ms_shape_lambda(table: u32, w: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let sx = alpha.x * w.x;
    let sy = alpha.y * w.y;
    let h = sqrt(sx * sx + sy * sy);
    let z = abs(w.z);
    if !(h > 0.0) {
        // (Normal incidence: cot θ = ∞; NaN passes on.)
        return select(h, 0.0, h == 0.0 && z > 0.0);
    }
    if z == 0.0 {
        return ms_inf();
    }
    return ms_shape_lambda_z(table, z / h);
}

// A standard normal variate from w ∈ [0, 1) (the Rust fast::ziggurat::normal): the lower half
// picks the sign, the rest drives the half-normal ziggurat.
fn ms_zig_normal(w: f32, src: ptr<function, MsSource>) -> f32 {
    if w < 0.5 {
        return -ms_zig_half_normal(2.0 * w, src);
    }
    return ms_zig_half_normal(2.0 * w - 1.0, src);
}

// A uniform of the source in (0, 1): 0 reads as 2^−53, as in Rust (ln 0 would send a variate
// to ±∞).
fn ms_source_next_positive(src: ptr<function, MsSource>) -> f32 {
    return max(ms_source_next(src), 1.1102230246251565e-16);
}

// ln of a Gamma(k, 1) variate, k > 0 (Marsaglia & Tsang 2000, as the Rust ln_gamma_variate:
// acceptance ≥ 0.95 for k ≥ 1; below, Gamma(k + 1) U^{1/k} in logarithms). NaN after 64
// rejections (probability below 1e-80).
fn ms_ln_gamma_variate(k_in: f32, src: ptr<function, MsSource>) -> f32 {
    var k = k_in;
    var boost = 0.0;
    if k < 1.0 {
        boost = log(ms_source_next_positive(src)) / k;
        k = k + 1.0;
    }
    let d = k - 1.0 / 3.0;
    let c = 1.0 / sqrt(9.0 * d);
    for (var n = 0; n < 64; n++) {
        let x = ms_zig_normal(ms_source_next(src), src);
        var v = 1.0 + c * x;
        if v <= 0.0 {
            continue;
        }
        v = v * v * v;
        if log(ms_source_next_positive(src)) < 0.5 * x * x + d - d * v + d * log(v) {
            return log(d) + log(v) + boost;
        }
    }
    return bitcast<f32>(0x7fc00000u);
}

// A visible normal of Beckmann at (αx, αy) for v above the horizon (v.z > 0) from the
// stream (the Rust fast::beckmann::sample_visible_above): in v's slope frame (a = v.z/h) the
// visible slope X has density ∝ (X + a)e^{−X²} on X > −a, drawn from the envelope X e^{−X²}
// on X ≥ 0 (mass ½: X = √(−ln U)) plus a e^{−X²} on the line (mass a√π: X = ±Z/√2),
// kept with probability (X + a)/a where X < 0 (acceptance ≥ 0.75); Y is N(0, ½). Returns
// (m, 1), or (m, 0) where m as rounded lies on or below the horizon or faces away from v.
fn ms_beckmann_sample_stream_above(v: vec3<f32>, alpha: vec2<f32>,
    src: ptr<function, MsSource>) -> vec4<f32> {
    let sx = alpha.x * v.x;
    let sy = alpha.y * v.y;
    // |(sx, sy)| without squaring them (the posterior's β α reaches e^80).
    let big = max(abs(sx), abs(sy));
    var h = 0.0;
    if big > 0.0 {
        let qx = sx / big;
        let qy = sy / big;
        h = big * sqrt(qx * qx + qy * qy);
    }
    var cp = 1.0;
    var sp = 0.0;
    var x = 0.0;
    if h == 0.0 {
        x = ms_zig_normal(ms_source_next(src), src) * 0.70710678118654752;
    } else {
        cp = sx / h;
        sp = sy / h;
        let a = v.z / h;
        let p_ray = 0.5 / (0.5 + a * MS_SQRT_PI);
        x = bitcast<f32>(0x7fc00000u);
        for (var n = 0; n < 64; n++) {
            let w = ms_source_next(src);
            if w < p_ray {
                x = sqrt(-log(ms_source_next_positive(src)));
                break;
            }
            let c = ms_zig_normal((w - p_ray) / (1.0 - p_ray), src) * 0.70710678118654752;
            if c >= 0.0 || (c > -a && ms_source_next(src) * a < c + a) {
                x = c;
                break;
            }
        }
    }
    let y = ms_zig_normal(ms_source_next(src), src) * 0.70710678118654752;
    let p = alpha.x * (cp * x - sp * y);
    let q = alpha.y * (sp * x + cp * y);
    let m = ms_unit_normal(vec3<f32>(p, q, 1.0));
    // Kept (w = 1) only above the horizon and facing v as rounded (the Rust stream_normal);
    // NaN x (64 rejections) fails too.
    let ok = m.z > 0.0 && ms_dot(m, v) > 0.0;
    return vec4<f32>(m, select(0.0, 1.0, ok));
}

// ln β(t) of the mixing variable t drawn from its prior (`biased` false) or its size-biased
// prior w(t)β(t)/E[β] (true), at α = 1 (the Rust Posterior::draw_ln_beta): `mixing` 0
// inverse-Gamma(k) (Student-T, β = √(k/t)), 1 Gamma(k) (K0, Bessel-K, β = √t), 2 uniform in
// β² (Ei: t = U, or U^{2/3}), 3 uniform in β (Erfc: t = U, or √U).
fn ms_mixing_ln_beta(mixing: u32, k: f32, biased: bool, src: ptr<function, MsSource>) -> f32 {
    let bias = select(0.0, 1.0, biased);
    if mixing == 0u {
        return 0.5 * (log(k) - ms_ln_gamma_variate(k - 0.5 * bias, src));
    }
    if mixing == 1u {
        return 0.5 * ms_ln_gamma_variate(k + 0.5 * bias, src);
    }
    if mixing == 2u {
        return 0.5 * log(ms_source_next_positive(src)) / (1.0 + 0.5 * bias);
    }
    return log(ms_source_next_positive(src)) / (1.0 + bias);
}

// ln β of the mixing variable's posterior for a unit direction with z = v.z > 0 and stretched
// horizontal length h (the Rust mixture::Posterior::sample_ln_beta): a candidate from the
// prior (weight z) or the size-biased prior (weight h E[β]/(2√π)), kept with probability
// σ_B/(z + βh/(2√π)) ≥ ½, σ_B = z + (βh/(2√π)) e^{−a²} r(a), a = z/(βh), r(a) = 1 − √π a
// erfcx(a) (Beckmann's projected area, two positive terms). `mixing`: 0 inverse-Gamma(k)
// (Student-T), 1 Gamma(k) (K0, Bessel-K), 2 uniform in β² (Ei), 3 uniform in β (Erfc), as
// ms_mixing_ln_beta. NaN after 64 candidates (probability below 1e-19).
fn ms_posterior_ln_beta(mixing: u32, k: f32, mean_beta: f32, z: f32, h: f32,
    src: ptr<function, MsSource>) -> f32 {
    let c = 0.5 * MS_FRAC_1_SQRT_PI;
    let p_prior = z / (z + c * h * mean_beta);
    for (var n = 0; n < 64; n++) {
        let biased = ms_source_next(src) >= p_prior;
        let ln_beta = ms_mixing_ln_beta(mixing, k, biased, src);
        let hb = h * exp(ln_beta);
        var keep = 1.0;
        if hb > 0.0 && hb <= 3.4028235e38 {
            let a = z / hb;
            keep = (z + c * hb * exp(-a * a) * ms_bk_erfc_ratio(a)) / (z + c * hb);
        }
        if ms_source_next(src) < keep {
            return ln_beta;
        }
    }
    return bitcast<f32>(0x7fc00000u);
}

// A visible normal of the mixture whose shape table is at `table` for w (w.z < 0 mirrored)
// from u: β from the posterior over the stream of u (the table's mixing), then Beckmann's
// stream sampler at β(αx, αy) (the Rust Posterior::sample_visible; its uniforms are f64 draws
// of the stream, these f32 ones: the same distribution, not the same normal). Where the
// posterior gives up (probability ~1e-19), β = E[β].
fn ms_mixture_sample_wm(table: u32, w_in: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>) -> vec3<f32> {
    var w = ms_unit(w_in);
    if w.z < 0.0 {
        w = -w;
    }
    let params = ms_tables[table + 2u];
    let sx = alpha.x * w.x;
    let sy = alpha.y * w.y;
    let h = sqrt(sx * sx + sy * sy);
    if !(w.z > 0.0) {
        // (On the horizon: Beckmann's warp at (αx, αy), a visible normal, as the Rust type.)
        return ms_beckmann_sample_wm(w, alpha, u);
    }
    var src = ms_source_after_u(u);
    let ln_beta = ms_posterior_ln_beta(u32(params.z), params.y, params.x, w.z, h, &src);
    if ln_beta == ln_beta {
        let m = ms_beckmann_sample_stream_above(w, ms_mixture_beta(ln_beta, alpha) * alpha, &src);
        if m.w > 0.0 {
            return m.xyz;
        }
    }
    // The posterior gave up (probability below 1e-19) or the component's normal rounded
    // behind v: Beckmann's warp at (αx, αy), as the Rust type (a visible normal, not this
    // NDF's distribution, with that probability).
    return ms_beckmann_sample_wm(w, alpha, u);
}

// G1, G2 (height-correlated and separable) and the visible density D_w(wm) =
// G1(w)(w·wm)D(wm)/|w.z| of a mixture from its shape table (Λ) and, for the density, its
// D(wm) = d; w.z < 0 mirrored; 0 at grazing w and for wm facing away from w.
fn ms_mixture_g1(table: u32, w: vec3<f32>, alpha: vec2<f32>) -> f32 {
    return 1.0 / (1.0 + ms_shape_lambda(table, w, alpha));
}

fn ms_mixture_g2(table: u32, wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>) -> f32 {
    return 1.0 / (1.0 + (ms_shape_lambda(table, wo, alpha) + ms_shape_lambda(table, wi, alpha)));
}

fn ms_mixture_g2_separable(table: u32, wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>) -> f32 {
    return ms_mixture_g1(table, wo, alpha) * ms_mixture_g1(table, wi, alpha);
}

// (From ln D, not D: D may lie below f32's normals, and a device flush it to 0, where the
// density G1 (c/z) D, with c/z up to 1/|w.z|, is a normal f32.)
fn ms_mixture_pdf(table: u32, w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>, ln_d: f32) -> f32 {
    let z = abs(w.z);
    var c = ms_dot(w, wm);
    if w.z < 0.0 {
        c = -c;
    }
    if !(c > 0.0 && z > 0.0) {
        return 0.0;
    }
    return exp(log(ms_mixture_g1(table, w, alpha) * (c / z)) + ln_d);
}

// The clamp of ln β: β(αx, αy) within f32's range with margin (|ln| ≤ 80); β = 0 or ∞ has
// probability 0.
fn ms_mixture_beta(ln_beta: f32, alpha: vec2<f32>) -> f32 {
    let lo = log(min(alpha.x, alpha.y));
    let hi = log(max(alpha.x, alpha.y));
    return exp(clamp(ln_beta, -80.0 - lo, 80.0 - hi));
}

// A D·cos normal of the mixture whose shape table is at `table`, from u: D·cos of a
// superposition of (normalised) Beckmann components is the superposition of their D·cos
// with the prior's weights, so β from the prior over the stream of u, then Beckmann's D·cos
// warp of u at β(αx, αy). Exact in distribution; the Rust fast path inverts the radial CDF
// instead (a warp of u), so the normals are not the Rust ones.
fn ms_mixture_sample_dcos_wm(table: u32, alpha: vec2<f32>, u: vec2<f32>) -> vec3<f32> {
    let params = ms_tables[table + 2u];
    // (β from the stream alone: u drives the warp, and must not drive β too.)
    var src = ms_source_stream_wide(u);
    var ln_beta = ms_mixing_ln_beta(u32(params.z), params.y, false, &src);
    if ln_beta != ln_beta {
        ln_beta = log(params.x);
    }
    return ms_beckmann_sample_dcos(ms_mixture_beta(ln_beta, alpha) * alpha, u).wm;
}

// ln D of a mixture from the logarithm of its radial profile at unit roughness, ln f₁(r) (r
// the stretched slope's length, ms_mixture_r, wm above the horizon): D = f₁(r)/(αx αy z⁴) is one exponential of ln f₁ − ln(αx αy z⁴), so that neither f₁
// nor z⁴ underflows on the way where D is a normal f32.
fn ms_mixture_ln_d(ln_f: f32, wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    return ln_f - log(alpha.x * alpha.y) - 4.0 * log(wm.z);
}

// The stretched slope's length r = |(m.x/αx, m.y/αy)|/z of wm at (αx, αy), without squaring
// the components (r² leaves f32's normals below r ~ 1e-19, where a pole's D still varies).
fn ms_mixture_r(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let x = abs(wm.x / alpha.x);
    let y = abs(wm.y / alpha.y);
    let big = max(x, y);
    if !(big > 0.0) {
        return big;
    }
    let qx = x / big;
    let qy = y / big;
    return big * sqrt(qx * qx + qy * qy) / wm.z;
}

// e^z K₀(z) for z > 0: (1 + z)(−ln(z/2) − γ_E) below 2^−14 (the next terms, O(z² ln z), are
// below ε/4 there), the table (MS_SF_K0E) to 2^9, the asymptotic series √(π/(2z))(1 − 1/(8z) +
// 9/(128z²)) beyond (next term 3e-10).
fn ms_k0e(z: f32) -> f32 {
    if z < 6.1035156e-5 {
        return (1.0 + z) * (-log(0.5 * z) - MS_EULER_GAMMA);
    }
    if z >= 512.0 {
        let r = 1.0 / z;
        return sqrt(0.5 * MS_PI * r) * (1.0 - r * (0.125 - r * (9.0 / 128.0)));
    }
    let g = ms_bk_segment(z, MS_SF_K0E_K0, MS_SF_K0E_K1);
    let i = MS_SF_K0E_AT + 2u * u32(g.x);
    return ms_bk_poly(ms_tables[i], ms_tables[i + 1u], g.y);
}

// e^y E₁(y) for y > 0: −γ_E − ln y below 2^−24 (the next term, y, is below ε/16 of it), the
// table (MS_SF_E1X) to 2^9, the asymptotic series (1/y)(1 − 1/y + 2/y² − 6/y³) beyond (next
// term 24/y⁴ ≤ 3.5e-10).
fn ms_e1x(y: f32) -> f32 {
    if y < 5.9604645e-8 {
        return -MS_EULER_GAMMA - log(y);
    }
    if y >= 512.0 {
        let r = 1.0 / y;
        return r * (1.0 - r * (1.0 - r * (2.0 - r * 6.0)));
    }
    let g = ms_bk_segment(y, MS_SF_E1X_K0, MS_SF_E1X_K1);
    let i = MS_SF_E1X_AT + 2u * u32(g.x);
    return ms_bk_poly(ms_tables[i], ms_tables[i + 1u], g.y);
}
