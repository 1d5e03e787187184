// microsurface WGSL library: Fresnel reflectances (fresnel.wgsl), as the Rust
// `bsdf::fresnel` functions in f32 (the same guards: η = 1 reflects nothing, a complex index
// near 0 reflects everything, |n| past 1e18 takes the reciprocal form; results in [0, 1]).

// Unpolarised dielectric reflectance for cos θi ∈ [−1, 1] and relative index η > 0 (cos θi
// < 0: seen from inside, η → 1/η); 1 under total internal reflection.
fn ms_fresnel_dielectric(cos_in: f32, eta_in: f32) -> f32 {
    var cos_i = cos_in;
    var eta = eta_in;
    if cos_i < 0.0 {
        cos_i = -cos_i;
        eta = 1.0 / eta;
    }
    let c = min(cos_i, 1.0);
    if eta == 1.0 {
        return 0.0;
    }
    if c == 0.0 {
        return 1.0;
    }
    var r_parl: f32;
    var r_perp: f32;
    if eta > 1e18 {
        let e = 1.0 / eta;
        let cos_t = sqrt((1.0 - e) * (1.0 + e) + (c * e) * (c * e));
        r_parl = (c - e * cos_t) / (c + e * cos_t);
        r_perp = (e * c - cos_t) / (e * c + cos_t);
    } else {
        // η² cos²θt = η² − sin²θi, without the cancellation of either form.
        var ect2: f32;
        if eta > 1.0 {
            ect2 = (eta - 1.0) * (eta + 1.0) + c * c;
        } else {
            ect2 = eta * eta - (1.0 - c) * (1.0 + c);
        }
        if ect2 <= 0.0 {
            return 1.0;
        }
        let ect = sqrt(ect2);
        let e2c = eta * eta * c;
        r_parl = (e2c - ect) / (e2c + ect);
        r_perp = (c - ect) / (c + ect);
    }
    return 0.5 * (r_parl * r_parl + r_perp * r_perp);
}

// Complex arithmetic on vec2 (re, im).
fn ms_cmul(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

fn ms_cnorm(a: vec2<f32>) -> f32 {
    return a.x * a.x + a.y * a.y;
}

// |a|²/|b|², both scaled by their largest part first (no overflow or underflow).
fn ms_cnorm_ratio(a: vec2<f32>, b: vec2<f32>) -> f32 {
    let s = max(max(abs(a.x), abs(a.y)), max(abs(b.x), abs(b.y)));
    if s == 0.0 {
        return 0.0;
    }
    if !(s <= 3.4028235e38) {
        return ms_cnorm(a) / ms_cnorm(b);
    }
    return ms_cnorm(a / s) / ms_cnorm(b / s);
}

// 1/a by Smith's algorithm.
fn ms_crecip(a: vec2<f32>) -> vec2<f32> {
    if abs(a.x) >= abs(a.y) {
        let r = a.y / a.x;
        let d = a.x + a.y * r;
        return vec2<f32>(1.0 / d, -r / d);
    }
    let r = a.x / a.y;
    let d = a.x * r + a.y;
    return vec2<f32>(r / d, -1.0 / d);
}

// The principal square root.
fn ms_csqrt(a: vec2<f32>) -> vec2<f32> {
    let r = sqrt(ms_cnorm(a));
    if r == 0.0 {
        return vec2<f32>(0.0);
    }
    let t = sqrt((r + abs(a.x)) * 0.5);
    if a.x >= 0.0 {
        return vec2<f32>(t, a.y / (t + t));
    }
    var s = t;
    if a.y < 0.0 {
        s = -t;
    }
    return vec2<f32>(abs(a.y) / (t + t), s);
}

// Unpolarised reflectance of a conductor of complex index η + ik for cos θi (clamped to
// [0, 1]), η, k ≥ 0 (pbrt-v4's FrComplex, with the Rust function's cancellation-free forms).
fn ms_fresnel_conductor(cos_in: f32, eta: f32, k: f32) -> f32 {
    let cos_i = min(max(cos_in, 0.0), 1.0);
    if eta == 1.0 && k == 0.0 {
        return 0.0;
    }
    if abs(eta) < 1e-9 && abs(k) < 1e-9 {
        return 1.0;
    }
    let n = vec2<f32>(eta, k);
    let sin2_i = (1.0 - cos_i) * (1.0 + cos_i);
    let ci = vec2<f32>(cos_i, 0.0);
    if max(abs(eta), abs(k)) > 1e18 {
        let m = ms_crecip(n);
        let sin2_t = ms_cmul(m, m) * sin2_i;
        let cos_t = ms_csqrt(vec2<f32>(1.0 - sin2_t.x, -sin2_t.y));
        let ct_m = ms_cmul(cos_t, m);
        let ci_m = m * cos_i;
        let r_parl = ms_cnorm_ratio(ci - ct_m, ci + ct_m);
        let r_perp = ms_cnorm_ratio(ci_m - cos_t, ci_m + cos_t);
        return min(0.5 * (r_parl + r_perp), 1.0);
    }
    let n2 = ms_cmul(n, n);
    var w: vec2<f32>;
    if ms_cnorm(n) >= 1.0 {
        w = ms_cmul(vec2<f32>(eta - 1.0, k), vec2<f32>(eta + 1.0, k)) + vec2<f32>(cos_i * cos_i, 0.0);
    } else {
        w = n2 - vec2<f32>(sin2_i, 0.0);
    }
    let cos_t = ms_csqrt(ms_cmul(w, ms_crecip(n2)));
    let n_ci = n * cos_i;
    let n_ct = ms_cmul(n, cos_t);
    let r_parl = ms_cnorm_ratio(n_ci - cos_t, n_ci + cos_t);
    let r_perp = ms_cnorm_ratio(ci - n_ct, ci + n_ct);
    return min(0.5 * (r_parl + r_perp), 1.0);
}

// Schlick's approximation F0 + (1 − F0)(1 − cos θi)⁵.
fn ms_fresnel_schlick(cos_i: f32, f0: f32) -> f32 {
    let m = 1.0 - min(max(cos_i, 0.0), 1.0);
    let m2 = m * m;
    return f0 + (1.0 - f0) * (m2 * m2 * m);
}

// Hoffman's F82-tint (Kutz et al. 2021's Adobe standard material form): Schlick less a
// cos θ (1 − cos θ)⁶ term pinned so that F(cos θ̄ = 1/7) = h · Schlick(1/7); clamped to [0, 1].
fn ms_fresnel_f82_tint(cos_i: f32, f0: f32, h: f32) -> f32 {
    let mu = min(max(cos_i, 0.0), 1.0);
    let m = 1.0 - mu;
    let m5 = m * m * m * m * m;
    // (1 − 1/7)⁵ and (1/7)(1 − 1/7)⁶, rounded from f64 as the Rust function does.
    let mb5 = 0.4626643660379606;
    let a = (f0 + (1.0 - f0) * mb5) * (1.0 - h) / 0.056652779514852314;
    let r = f0 + (1.0 - f0) * m5 - a * mu * m5 * m;
    return min(max(r, 0.0), 1.0);
}

// A Fresnel term of three channels: which (`kind`) and its parameters.
//   MS_FRESNEL_ONE         F = 1
//   MS_FRESNEL_DIELECTRIC  a.x = η
//   MS_FRESNEL_CONDUCTOR   a = η, b = k per channel
//   MS_FRESNEL_SCHLICK     a = F0 per channel
//   MS_FRESNEL_F82_TINT    a = F0, b = the tint h per channel
struct MsFresnel {
    kind: u32,
    a: vec3<f32>,
    b: vec3<f32>,
}

const MS_FRESNEL_ONE: u32 = 0u;
const MS_FRESNEL_DIELECTRIC: u32 = 1u;
const MS_FRESNEL_CONDUCTOR: u32 = 2u;
const MS_FRESNEL_SCHLICK: u32 = 3u;
const MS_FRESNEL_F82_TINT: u32 = 4u;

// The Fresnel term at cos θi, channel by channel (an unknown kind is 0).
fn ms_fresnel_eval(fr: MsFresnel, cos_i: f32) -> vec3<f32> {
    switch fr.kind {
        case MS_FRESNEL_ONE: {
            return vec3<f32>(1.0);
        }
        case MS_FRESNEL_DIELECTRIC: {
            return vec3<f32>(ms_fresnel_dielectric(cos_i, fr.a.x));
        }
        case MS_FRESNEL_CONDUCTOR: {
            return vec3<f32>(ms_fresnel_conductor(cos_i, fr.a.x, fr.b.x),
                ms_fresnel_conductor(cos_i, fr.a.y, fr.b.y),
                ms_fresnel_conductor(cos_i, fr.a.z, fr.b.z));
        }
        case MS_FRESNEL_SCHLICK: {
            return vec3<f32>(ms_fresnel_schlick(cos_i, fr.a.x), ms_fresnel_schlick(cos_i, fr.a.y),
                ms_fresnel_schlick(cos_i, fr.a.z));
        }
        case MS_FRESNEL_F82_TINT: {
            return vec3<f32>(ms_fresnel_f82_tint(cos_i, fr.a.x, fr.b.x),
                ms_fresnel_f82_tint(cos_i, fr.a.y, fr.b.y),
                ms_fresnel_f82_tint(cos_i, fr.a.z, fr.b.z));
        }
        default: {
            return vec3<f32>(0.0);
        }
    }
}
