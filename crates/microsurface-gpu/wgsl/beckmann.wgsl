// microsurface WGSL library: Beckmann, anisotropic (beckmann.wgsl).
//
// The Rust `Microfacet<f32, Beckmann>` (crates/microsurface/src/fast/beckmann.rs, the
// `Shape for Beckmann` of distribution/microfacet.rs), in f32 throughout. The Rust f32 path
// evaluates Λ and the samplers in f64 and rounds once; here the same formulas run in f32,
// arranged so that nothing cancels, with the special functions from the tables of
// the library's tables buffer (tables.wgsl, generated from the Rust f64 functions):
//
//   D(m)   = e^{−e}/(π αx αy z⁴),  e = ((m.x/αx)² + (m.y/αy)²)/z²        (0 for m.z ≤ 0)
//   Λ(w)   = e^{−a²} r(a)/(2a√π),  a = |w.z|/√(αx²w.x² + αy²w.y²),  r(a) = 1 − √π a erfcx(a)
//   G1     = 1/(1 + Λ),  G2 = 1/(1 + (Λ(wo) + Λ(wi))) (height-correlated), G1 G1 (separable)
//   D_w(m) = G1(w)(w·m)D(m)/|w.z|
//
// (r has no cancellation: the textbook (erf a − 1)/2 + e^{−a²}/(2a√π) loses ~2a² ulps.)
// Visible normals: the slope-space inversion of Heitz & d'Eon 2014 (the Rust warp: the same
// normal for the same u): in the stretched frame of w, with cot θ = a, x̃ solves
// N(x̃) = u₀Z, N(X) = (a/2)(erfc(−X) − erfc a) − (e^{−X²} − e^{−a²})/(2√π), Z = N(∞), by the
// Rust cold path's safeguarded Halley iteration on [−a, 8] (F = N − u₀Z from the side
// without cancellation, erfc from erfcx), and ỹ = erfinv(2u₁ − 1). The Rust hot path takes
// one high-order step from a table guess instead; both reach the root to the rounding of F,
// so they agree to the conditioning ε Z/N′(x̃) (tests/lavapipe.rs). D·cos: tan²θ = −ln(1 − u₀)
// at unit roughness, azimuth 2πu₁, stretched.

const MS_FRAC_1_SQRT_PI: f32 = 0.564189583547756287;
const MS_SQRT_PI: f32 = 1.77245385090551603;

// One segment of an octave table (tables.wgsl) at x ∈ [2^k0, 2^k1): its first row
// (two per segment) and s ∈ [−1, 1), exactly from x's bits (the Rust fast::fit::octave_segment32).
fn ms_bk_segment(x: f32, k0: i32, k1: i32) -> vec2<f32> {
    let m = MS_BK_SEGMENTS_LOG2;
    let bits = bitcast<u32>(x);
    let rows = u32(k1 - k0) << m;
    let idx = min((bits >> (23u - m)) - (u32(127 + k0) << m), rows - 1u);
    let pos = (bits << (9u + m)) >> 9u;
    return vec2<f32>(f32(idx), bitcast<f32>(0x40000000u | pos) - 3.0);
}

// The degree-7 polynomial of a table row pair (s⁰ first), Horner.
fn ms_bk_poly(lo: vec4<f32>, hi: vec4<f32>, s: f32) -> f32 {
    return ((((((hi.w * s + hi.z) * s + hi.y) * s + hi.x) * s + lo.w) * s + lo.z) * s + lo.y)
        * s + lo.x;
}

// erfcx(x) = e^{x²} erfc x for x ≥ 0: 1 − 2x/√π below 2^−14 (the next term, x², is below
// ε/4 there), the table to 2^5, the asymptotic series beyond (next term 3e-14 at 32).
fn ms_bk_erfcx(x: f32) -> f32 {
    if x < 6.1035156e-5 {
        return 1.0 - 2.0 * MS_FRAC_1_SQRT_PI * x;
    }
    if x >= 32.0 {
        let r = 1.0 / (x * x);
        return (1.0 - r * (0.5 - r * (0.75 - r * (1.875 - r * 6.5625)))) * MS_FRAC_1_SQRT_PI / x;
    }
    let g = ms_bk_segment(x, MS_BK_ERFCX_K0, MS_BK_ERFCX_K1);
    let i = 2u * u32(g.x);
    return ms_bk_poly(ms_tables[MS_BK_ERFCX_AT + i], ms_tables[MS_BK_ERFCX_AT + i + 1u], g.y);
}

// r(a) = 1 − √π a erfcx(a) for a ≥ 0: 1 − √π a below 2^−14 (the next term, 2a², is below
// ε/4 there), the table to 2^5, the asymptotic series beyond (as the Rust erfc_ratio).
fn ms_bk_erfc_ratio(a: f32) -> f32 {
    if a < 6.1035156e-5 {
        return 1.0 - MS_SQRT_PI * a;
    }
    if a >= 32.0 {
        let r = 1.0 / (a * a);
        return r * (0.5 - r * (0.75 - r * (1.875 - r * (6.5625 - r * 29.53125))));
    }
    let g = ms_bk_segment(a, MS_BK_ERFC_RATIO_K0, MS_BK_ERFC_RATIO_K1);
    let i = 2u * u32(g.x);
    return ms_bk_poly(ms_tables[MS_BK_ERFC_RATIO_AT + i], ms_tables[MS_BK_ERFC_RATIO_AT + i + 1u], g.y);
}

// erfinv(2u − 1), the quantile of N(0, ½), for u ∈ [0, 1): q = 2 min(u, 1 − u) exactly, the
// ratio erfinv(v)/v from the q table (q ≥ 2^−25; q = 1 at the float below, as the Rust
// erfinv_ratio_q) or from w = −ln(q(2 − q)) below; u = 0 is the Rust samplers' clamp to
// 2^−1074 (MS_BK_QUANTILE_EDGE).
fn ms_bk_quantile(u: f32) -> f32 {
    let q = 2.0 * min(u, 1.0 - u);
    var sign = 1.0;
    if u < 0.5 {
        sign = -1.0;
    }
    if !(q > 0.0) {
        return -sign * MS_BK_QUANTILE_EDGE;
    }
    var ratio: f32;
    if q >= 2.9802322e-8 {
        let g = ms_bk_segment(min(q, 0.99999994), MS_BK_ERFINV_Q_K0, MS_BK_ERFINV_Q_K1);
        let i = 2u * u32(g.x);
        ratio = ms_bk_poly(ms_tables[MS_BK_ERFINV_Q_AT + i], ms_tables[MS_BK_ERFINV_Q_AT + i + 1u], g.y);
    } else {
        // (2 − q rounds to 2; w within the table up to q = 2^−126 and held inside below.)
        let w = min(-log(q) - log(2.0), 127.99);
        let g = ms_bk_segment(w, MS_BK_ERFINV_W_K0, MS_BK_ERFINV_W_K1);
        let i = 2u * u32(g.x);
        ratio = ms_bk_poly(ms_tables[MS_BK_ERFINV_W_AT + i], ms_tables[MS_BK_ERFINV_W_AT + i + 1u], g.y);
    }
    return sign * ((1.0 - q) * ratio);
}

// ln(1 − ξ) for ξ ∈ [0, 1): 2 atanh(t), t = −ξ/(2 − ξ), by its series to t¹⁵ where ξ ≤ ½
// (|t| ≤ ⅓: truncation below 2e-9 relative; the shading language's log has an absolute
// error of 2^−21 near 1, which would be all of a small ξ's digits), log(1 − ξ) (exact
// argument) above.
fn ms_bk_ln_1m(xi: f32) -> f32 {
    if xi > 0.5 {
        return log(1.0 - xi);
    }
    let t = -xi / (2.0 - xi);
    let t2 = t * t;
    let p = 1.0 + t2 * (1.0 / 3.0 + t2 * (0.2 + t2 * (1.0 / 7.0 + t2 * (1.0 / 9.0
        + t2 * (1.0 / 11.0 + t2 * (1.0 / 13.0 + t2 * (1.0 / 15.0)))))));
    return 2.0 * t * p;
}

// D(wm) (the Rust d_aniso, isotropic included); 0 below the horizon. Past e = 80 the
// normalisation joins the exponent (e^{−e + ln(1/(π αx αy z⁴))}), so that D stays a normal
// f32 where the Rust f32 path (in f64 there) has one and e^{−e} alone would underflow.
fn ms_beckmann_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let z = wm.z;
    let r = 1.0 / (alpha.x * alpha.y);
    let x = wm.x * alpha.y * r;
    let y = wm.y * alpha.x * r;
    let z2 = z * z;
    if !(z > 0.0 && z2 > 0.0) {
        return 0.0;
    }
    let e = (x * x + y * y) / z2;
    if e <= 80.0 {
        return exp(-e) * r / (MS_PI * z2 * z2);
    }
    return exp((log(r) - log(MS_PI) - 4.0 * log(z)) - e);
}

// Λ at a = cot θ̃ ≥ 0: e^{−a²} r(a)/(2a√π); +∞ at a = 0.
fn ms_beckmann_lambda_cot(a: f32) -> f32 {
    if !(a > 0.0) {
        return ms_inf();
    }
    // e^{−a²} is 0 in f32 past a = 10.3 (Λ below 1e-47).
    if a > 10.5 {
        return 0.0;
    }
    return 0.5 * exp(-a * a) * ms_bk_erfc_ratio(a) / (MS_SQRT_PI * a);
}

// Smith Λ(w), Λ(−w) = Λ(w): at cot θ̃ = |w.z|/√(αx²w.x² + αy²w.y²); 0 at the normal.
fn ms_beckmann_lambda(w: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let x = alpha.x * w.x;
    let y = alpha.y * w.y;
    let s = sqrt(x * x + y * y);
    if !(s > 0.0) {
        return 0.0;
    }
    return ms_beckmann_lambda_cot(abs(w.z) / s);
}

// G1(w) = 1/(1 + Λ(w)); 0 on the horizon.
fn ms_beckmann_g1(w: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if w.z == 0.0 {
        return 0.0;
    }
    return 1.0 / (1.0 + ms_beckmann_lambda(w, alpha));
}

// Height-correlated G2(wo, wi) = 1/(1 + (Λ(wo) + Λ(wi))).
fn ms_beckmann_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if wo.z == 0.0 || wi.z == 0.0 {
        return 0.0;
    }
    return 1.0 / (1.0 + (ms_beckmann_lambda(wo, alpha) + ms_beckmann_lambda(wi, alpha)));
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_beckmann_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>) -> f32 {
    return ms_beckmann_g1(wo, alpha) * ms_beckmann_g1(wi, alpha);
}

// The visible-normal density D_w(wm) = G1(w)(w·wm)D(wm)/|w.z| (the Rust d_visible_with);
// w.z < 0 mirrored; 0 at grazing w and for wm facing away from w.
fn ms_beckmann_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let z = abs(w.z);
    var c = ms_dot(w, wm);
    if w.z < 0.0 {
        c = -c;
    }
    if !(c > 0.0 && z > 0.0) {
        return 0.0;
    }
    return ms_beckmann_g1(w, alpha) * c * ms_beckmann_d(wm, alpha) / z;
}

// The density of ms_beckmann_sample_dcos: D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_beckmann_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_beckmann_d(wm, alpha) * wm.z;
}

// A normal distributed as D(m) cos θm with its pdf: r = tan θ = √(−ln(1 − u₀)) at unit
// roughness, azimuth 2πu₁, stretched: m ∝ (αx r cos φ, αy r sin φ, 1), or divided by r
// past r = 1 (the Rust normal_from_polar); u₀ = 1 is the horizon.
fn ms_beckmann_sample_dcos(alpha: vec2<f32>, u: vec2<f32>) -> MsSample {
    let cs = ms_cos_sin_turn(u.y);
    var v: vec3<f32>;
    if u.x >= 1.0 {
        v = vec3<f32>(alpha.x * cs.x, alpha.y * cs.y, 0.0);
    } else {
        let r = sqrt(-ms_bk_ln_1m(u.x));
        if r > 1.0 {
            v = vec3<f32>(alpha.x * cs.x, alpha.y * cs.y, 1.0 / r);
        } else {
            v = vec3<f32>(alpha.x * r * cs.x, alpha.y * r * cs.y, 1.0);
        }
    }
    let wm = ms_unit_normal(v);
    return MsSample(wm, ms_beckmann_d(wm, alpha) * wm.z);
}

// The α = 1 visible slope x̃ for cot θ = a ≥ 0 (finite): N(x̃) = uZ by safeguarded Halley
// steps on the bracket [−a, 8] (the Rust visible_x_loop in f32; X = 8 is past every
// quantile an f32 u reaches), from the Gaussian quantile (the limit a → ∞) where a ≥ 1 and
// the Rayleigh one (a = 0) below.
fn ms_bk_visible_x(a: f32, u: f32) -> f32 {
    let ea = exp(-a * a);
    let erfc_a = ms_bk_erfcx(a) * ea;
    let half_ea = 0.5 * MS_FRAC_1_SQRT_PI * ea;
    let z = 0.5 * a * (2.0 - erfc_a) + half_ea;
    let target_lo = u * z;
    let target_hi = (1.0 - u) * z;
    var lo = -a;
    var hi = 8.0;
    var x: f32;
    if a >= 1.0 {
        x = ms_bk_quantile(u);
    } else {
        x = sqrt(-ms_bk_ln_1m(u)) - a;
    }
    x = clamp(x, lo, hi);
    for (var k = 0; k < 64; k++) {
        let e = exp(-x * x);
        let ec = ms_bk_erfcx(abs(x)) * e;
        let half_e = 0.5 * MS_FRAC_1_SQRT_PI * e;
        // F(X) = N(X) − uZ, from the side without cancellation.
        var f: f32;
        if x <= 0.0 {
            f = 0.5 * a * (ec - erfc_a) - (half_e - half_ea) - target_lo;
        } else {
            f = target_hi - 0.5 * a * ec - half_e;
        }
        if f < 0.0 {
            lo = x;
        } else if f > 0.0 {
            hi = x;
        } else {
            return x;
        }
        // F′ = g₁E, F″ = g₂E, E = e^{−X²}/√π: Halley's step with E cancelled, or Newton's
        // where the correction exceeds ½ (far from the root).
        let g1 = x + a;
        let g2 = 1.0 - 2.0 * x * (x + a);
        let big_e = e * MS_FRAC_1_SQRT_PI;
        let fg2 = f * g2;
        let g1e = g1 * g1 * big_e;
        var step: f32;
        if abs(fg2) < g1e {
            step = 2.0 * f * g1 / (2.0 * g1e - fg2);
        } else {
            step = f / (g1 * big_e);
        }
        let next = x - step;
        // Converged: Halley is cubic, so a step of 1e-4 of the scale (1 + |X|, or the
        // distance to −a) leaves ~1e-12 of it, below f32's rounding.
        let size = abs(step);
        if size * (1.0 + abs(x)) <= 1e-4 && size <= 1e-4 * (x + a) {
            return clamp(next, -a, 8.0);
        }
        // (A non-finite step, as where E underflows, fails both tests: bisection.)
        if next > lo && next < hi {
            x = next;
        } else {
            x = 0.5 * (lo + hi);
        }
        if hi - lo <= 2.4e-7 * max(abs(hi), abs(lo)) {
            break;
        }
    }
    return x;
}

// A visible normal for w (w.z < 0 mirrored) from u ∈ [0, 1)²: the visible slopes (x̃, ỹ) in
// the stretched frame of w, rotated back and unstretched (the Rust normal_from_slopes); at
// normal incidence both slopes Gaussian.
fn ms_beckmann_sample_wm(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>) -> vec3<f32> {
    var sign = 1.0;
    if w.z < 0.0 {
        sign = -1.0;
    }
    let sx = sign * alpha.x * w.x;
    let sy = sign * alpha.y * w.y;
    let c = sign * w.z;
    let h = sqrt(sx * sx + sy * sy);
    let y = ms_bk_quantile(u.y);
    var x: f32;
    var cp = 1.0;
    var sp = 0.0;
    if h > 0.0 {
        let inv = 1.0 / h;
        cp = sx * inv;
        sp = sy * inv;
        x = ms_bk_visible_x(c * inv, u.x);
    } else {
        x = ms_bk_quantile(u.x);
    }
    let p = alpha.x * (cp * x - sp * y);
    let q = alpha.y * (sp * x + cp * y);
    let n = 1.0 / sqrt(p * p + q * q + 1.0);
    return ms_facing(vec3<f32>(p * n, q * n, n), w);
}

// A visible normal with its pdf (ms_beckmann_pdf at w normalised).
fn ms_beckmann_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>) -> MsSample {
    let wm = ms_beckmann_sample_wm(w, alpha, u);
    return MsSample(wm, ms_beckmann_pdf(ms_unit(w), wm, alpha));
}
