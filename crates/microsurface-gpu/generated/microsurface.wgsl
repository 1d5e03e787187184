// microsurface WGSL library: constants and vector helpers (common.wgsl).
//
// Conventions (the Rust crate's): directions are unit vec3<f32> in the local shading frame,
// z = the shading normal; wo and wi both point away from the surface; roughness is
// vec2<f32>(αx, αy), αx along the frame's tangent. Every public name starts with `ms_` or
// `Ms`/`MS_` (WGSL has no namespaces). WGSL lets an implementation assume that no NaN or
// infinity occurs; the library produces +∞ only where the Rust type does (Λ at grazing), and
// its edge guards are written as the Rust code's (`!(x > 0.0)` is false for NaN there too).

const MS_PI: f32 = 3.14159265358979323846;
const MS_TAU: f32 = 6.28318530717958647692;

// +∞ (Λ on the horizon, as the Rust fast path answers). Formed at run time from its bits:
// a constant expression may not be infinite in WGSL.
fn ms_inf() -> f32 {
    var bits = 0x7f800000u;
    return bitcast<f32>(bits);
}

// (cos 2πv, sin 2πv) for v ∈ [0, 1] in f32, as the Rust fast path's cos_sin_turn in f64:
// v is reduced exactly to r = v − k/4, |r| ≤ 1/8 (v and k/4 share the exponent range, so
// the difference is exact), the polynomials (Taylor to x⁹ and x¹⁰, truncation below 2e-9 at
// |x| = π/4) run at x = 2πr, and the k quarter turns are a swap and sign flips. The shading
// language's sin and cos are not used: Vulkan allows them 2⁻¹¹ absolute error.
fn ms_cos_sin_turn(v: f32) -> vec2<f32> {
    let k = round(4.0 * v);
    let r = v - 0.25 * k;
    let x = MS_TAU * r;
    let x2 = x * x;
    let s = x * (1.0 + x2 * (-1.6666667e-1 + x2 * (8.3333333e-3 + x2 * (-1.9841270e-4
        + x2 * 2.7557319e-6))));
    let c = 1.0 + x2 * (-0.5 + x2 * (4.1666667e-2 + x2 * (-1.3888889e-3 + x2 * (2.4801587e-5
        + x2 * -2.7557319e-7))));
    let q = i32(k) & 3;
    if q == 0 {
        return vec2<f32>(c, s);
    } else if q == 1 {
        return vec2<f32>(-s, c);
    } else if q == 2 {
        return vec2<f32>(-c, -s);
    }
    return vec2<f32>(s, -c);
}

// a divided by its largest component's magnitude (the same direction, length in [1, √3]);
// a zero or non-finite a as it is.
fn ms_rescaled(a: vec3<f32>) -> vec3<f32> {
    let m = max(abs(a.x), max(abs(a.y), abs(a.z)));
    if !(m > 0.0 && m <= 3.4028235e38) {
        return a;
    }
    return a / m;
}

// a/|a| (the Rust `frame::normalize`): a·(1/√(a·a)) where the squared length keeps its
// digits (1e±30), else rescaled by the largest component first.
fn ms_normalize(a: vec3<f32>) -> vec3<f32> {
    let n2 = ms_dot(a, a);
    if n2 >= 1e-30 && n2 <= 1e30 {
        return a * (1.0 / sqrt(n2));
    }
    let w = ms_rescaled(a);
    return w * (1.0 / sqrt(ms_dot(w, w)));
}

// a·b in the Rust order, a.x b.x + a.y b.y + a.z b.z (WGSL's dot leaves the order to the
// implementation).
fn ms_dot(a: vec3<f32>, b: vec3<f32>) -> f32 {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// w as a unit vector (the Rust `distribution::unit`): w itself where |w|² is 1 within 1e-6,
// else rescaled and normalised.
fn ms_unit(w: vec3<f32>) -> vec3<f32> {
    let n2 = ms_dot(w, w);
    if abs(n2 - 1.0) <= 1e-6 {
        return w;
    }
    let m = max(abs(w.x), max(abs(w.y), abs(w.z)));
    if !(m > 0.0 && m <= 3.4028235e38) {
        return w;
    }
    return ms_normalize(w * (1.0 / m));
}

// The unit normal of (x, y, z) (z ≥ 0) built from scaled slopes (the Rust fast path's
// unit_normal): the zero vector gives (0, 0, 1).
fn ms_unit_normal(v: vec3<f32>) -> vec3<f32> {
    let n2 = ms_dot(v, v);
    if n2 >= 1e-30 && n2 <= 1e30 {
        return v * (1.0 / sqrt(n2));
    }
    let m = max(abs(v.x), max(abs(v.y), abs(v.z)));
    if m == 0.0 {
        return vec3<f32>(0.0, 0.0, 1.0);
    }
    let s = v / m;
    return s * (1.0 / sqrt(ms_dot(s, s)));
}

// The reflection of wo about the unit normal n: −wo + 2(wo·n)n.
fn ms_reflect(wo: vec3<f32>, n: vec3<f32>) -> vec3<f32> {
    let d = ms_dot(wo, n);
    return (d + d) * n - wo;
}

// Whether a and b lie on the same side of the surface (a.z b.z > 0).
fn ms_same_hemisphere(a: vec3<f32>, b: vec3<f32>) -> bool {
    return a.z * b.z > 0.0;
}

// The half vector of a reflection, (wo + wi)/|wo + wi| turned to z ≥ 0; (0, 0, 0) where
// there is none (wo + wi = 0), which the callers test as `.z != .z || all zero`: use
// ms_half_vector_ok.
fn ms_half_vector_reflection(wo: vec3<f32>, wi: vec3<f32>) -> vec3<f32> {
    let s = wo + wi;
    if !(max(abs(s.x), max(abs(s.y), abs(s.z))) > 0.0) {
        return vec3<f32>(0.0);
    }
    let m = ms_normalize(s);
    if m.z < 0.0 {
        return -m;
    }
    return m;
}

// Whether ms_half_vector_reflection found a half vector.
fn ms_half_vector_ok(m: vec3<f32>) -> bool {
    return ms_dot(m, m) > 0.5;
}

// m, or where it lies on or behind the plane perpendicular to w (w mirrored to w.z ≥ 0),
// m less its component along w plus a margin, renormalised (the Rust fast path's facing).
fn ms_facing(m: vec3<f32>, w: vec3<f32>) -> vec3<f32> {
    var d = ms_dot(m, w);
    if w.z < 0.0 {
        d = -d;
    }
    if d > 0.0 {
        return m;
    }
    let r = ms_rescaled(w);
    var s = 1.0;
    if r.z < 0.0 {
        s = -1.0;
    }
    let wu = s * r / sqrt(ms_dot(r, r));
    let e = ms_dot(m, wu) - 2.0 * 4e-7;
    return ms_unit_normal(m - e * wu);
}

// η' wi + wo, formed as (wo + wi) + (η' − 1) wi: accurate to a few ulp of its own length,
// also where it nearly vanishes (η' → 1, wi → −wo).
fn ms_refraction_sum(wo: vec3<f32>, wi: vec3<f32>, etap: f32) -> vec3<f32> {
    return (wo + wi) + wi * (etap - 1.0);
}

// The generalised half vector of a refraction with relative index η (η_inside/η_outside),
// wm ∝ η' wi + wo, η' = η for wo.z > 0 and 1/η below, turned to z ≥ 0: vec4(wm, η'), or
// (0, 0, 0, η') where it vanishes.
fn ms_half_vector_refraction(wo: vec3<f32>, wi: vec3<f32>, eta: f32) -> vec4<f32> {
    var etap = eta;
    if !(wo.z > 0.0) {
        etap = 1.0 / eta;
    }
    let s = ms_refraction_sum(wo, wi, etap);
    if !(max(abs(s.x), max(abs(s.y), abs(s.z))) > 0.0) {
        return vec4<f32>(0.0, 0.0, 0.0, etap);
    }
    var m = ms_normalize(s);
    if m.z < 0.0 {
        m = -m;
    }
    return vec4<f32>(m, etap);
}

// wi·wm + (wo·wm)/η' = (η' wi + wo)·wm/η', the refraction's Jacobian and BSDF denominator.
fn ms_refraction_denominator(wo: vec3<f32>, wi: vec3<f32>, wm: vec3<f32>, etap: f32) -> f32 {
    return ms_dot(ms_refraction_sum(wo, wi, etap), wm) / etap;
}

// |∂wm/∂wi| of the refraction half vector: |wi·wm|/(wi·wm + (wo·wm)/η')² (Walter et al.
// 2007, eq. 17).
fn ms_jacobian_refraction(wo: vec3<f32>, wi: vec3<f32>, wm: vec3<f32>, etap: f32) -> f32 {
    let s = ms_refraction_denominator(wo, wi, wm, etap);
    return abs(ms_dot(wi, wm)) / (s * s);
}

// The refraction of wi through the unit normal n with relative index η = η_t/η_i (the Rust
// `frame::refract`, pbrt-v4's Refract with wi's tangential part projected twice): wi on the
// other side of n flips n and takes 1/η. vec4(wt, η'), or η' = 0 at total internal reflection.
fn ms_refract(wi: vec3<f32>, n_in: vec3<f32>, eta_in: f32) -> vec4<f32> {
    var cos_i = ms_dot(n_in, wi);
    var eta = eta_in;
    var n = n_in;
    if cos_i < 0.0 {
        eta = 1.0 / eta;
        cos_i = -cos_i;
        n = -n;
    }
    let t0 = wi + n * -cos_i;
    let t = t0 + n * -ms_dot(t0, n);
    let sin2_t = ms_dot(t, t) / (eta * eta);
    if !(sin2_t < 1.0) {
        return vec4<f32>(0.0);
    }
    let cos_t = sqrt(1.0 - sin2_t);
    return vec4<f32>(t * (-1.0 / eta) + n * -cos_t, eta);
}

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

// microsurface WGSL library: GGX (Trowbridge–Reitz), anisotropic (ggx.wgsl).
//
// The Rust `Microfacet<f32, Ggx>` (crates/microsurface/src/distribution/microfacet.rs and
// src/fast/ggx.rs, fast/mod.rs) operation for operation, in f32 throughout (the Rust f32
// path forms the samplers' cos 2πu and the rescaled edge cases in f64; here they are f32):
//
//   D(m)   = 1/(π αx αy t²),  t = (m.x/αx)² + (m.y/αy)² + m.z²        (0 for m.z ≤ 0)
//   Λ(w)   = s/(2(z² + z√(z² + s))),  s = αx²w.x² + αy²w.y², z = |w.z|  (+∞ at z = 0)
//   G1(w)  = 2z/(z + √(z² + s))
//   G2     = 1/(1 + (Λ(wo) + Λ(wi)))  (height-correlated);  G1(wo) G1(wi) (separable)
//   D_w(m) = G1(w)(w·m)D(m)/|w.z| = 2(w·m)/(π αx αy t² (z + |(αx w.x, αy w.y, z)|))
//
// (Heitz 2014, JCGT 3(2); pbrt-v4's TrowbridgeReitzDistribution). w.z < 0 is mirrored (the
// microsurface seen from below through its mirror image, as pbrt-v4 and the Rust type).
// Visible normals: spherical caps (Dupuy & Benyoub 2023); bounded VNDF for reflection (Eto &
// Tokuyoshi 2023); D·cos: Walter et al. 2007's inversion, stretched.

// A sampled normal and its density per unit solid angle of the normal.
struct MsSample {
    wm: vec3<f32>,
    pdf: f32,
}

// D(wm) for a unit normal; 0 below the horizon.
fn ms_ggx_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let z = wm.z;
    if !(z > 0.0) {
        return 0.0;
    }
    let x = wm.x / alpha.x;
    let y = wm.y / alpha.y;
    let t = x * x + y * y + z * z;
    return 1.0 / (MS_PI * alpha.x * alpha.y * t * t);
}

// Smith Λ(w) of the side w comes from (Λ(−w) = Λ(w)); +∞ at grazing, 0 at the normal.
fn ms_ggx_lambda(w: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let x = alpha.x * w.x;
    let y = alpha.y * w.y;
    let z = abs(w.z);
    let t = x * x + y * y;
    let z2 = z * z;
    let den = 2.0 * (z2 + z * sqrt(z2 + t));
    if !(den > 0.0) {
        // Grazing: z = 0 is +∞; a z whose square underflows, two divisions.
        if z == 0.0 {
            return ms_inf();
        }
        return t / (z + sqrt(z * z + t)) / (z + z);
    }
    return t / den;
}

// G1(w) = 1/(1 + Λ(w)) = 2z/(z + √(z² + s)): one division, 0 at grazing.
fn ms_ggx_g1(w: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let x = alpha.x * w.x;
    let y = alpha.y * w.y;
    let z = abs(w.z);
    let den = z + sqrt(z * z + (x * x + y * y));
    if !(den > 0.0) {
        return 0.0;
    }
    return (z + z) / den;
}

// Height-correlated G2(wo, wi) = 1/(1 + (Λ(wo) + Λ(wi))), symmetric to the bit.
fn ms_ggx_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>) -> f32 {
    return 1.0 / (1.0 + (ms_ggx_lambda(wo, alpha) + ms_ggx_lambda(wi, alpha)));
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_ggx_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>) -> f32 {
    return ms_ggx_g1(wo, alpha) * ms_ggx_g1(wi, alpha);
}

// The visible-normal density D_w(wm) (the density of ms_ggx_sample); w.z < 0 mirrored; 0 at
// grazing w, for wm on or behind the plane perpendicular to w, and below the horizon.
fn ms_ggx_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let z = abs(w.z);
    var c = ms_dot(w, wm);
    if w.z < 0.0 {
        c = -c;
    }
    if !(c > 0.0 && z > 0.0 && wm.z > 0.0) {
        return 0.0;
    }
    let sx = alpha.x * w.x;
    let sy = alpha.y * w.y;
    let len = sqrt(sx * sx + sy * sy + z * z);
    let mx = wm.x / alpha.x;
    let my = wm.y / alpha.y;
    let t = mx * mx + my * my + wm.z * wm.z;
    return (c + c) / (MS_PI * alpha.x * alpha.y * t * t * (z + len));
}

// The spherical-cap visible normal for the unit w (w.z ≥ 0) given the length of the
// stretched (αx w.x, αy w.y, w.z): a point of the cap z ∈ [−w'.z, 1] about w', unstretched.
fn ms_ggx_cap_normal(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>, len: f32) -> vec3<f32> {
    let inv = 1.0 / len;
    let x = alpha.x * w.x * inv;
    let y = alpha.y * w.y * inv;
    let z = w.z * inv;
    let cs = ms_cos_sin_turn(u.x);
    // cz + z = (1 − u₁)(1 + z) formed without the cancellation (u₁ → 1); sin² = (1 − cz)
    // (1 + cz) = u₁(above (1 + z) + x² + y²), a sum of positive terms (1 − cz² cancels at
    // the poles, cz → ±1).
    let above = (1.0 - u.y) * (1.0 + z);
    let sin = sqrt(max(u.y * (above * (1.0 + z) + (x * x + y * y)), 0.0));
    let h = vec3<f32>(alpha.x * (sin * cs.x + x), alpha.y * (sin * cs.y + y), above);
    let n = 1.0 / sqrt(h.x * h.x + h.y * h.y + h.z * h.z);
    return h * n;
}

// A visible normal for w (any finite nonzero length; w.z < 0 mirrored) from u ∈ [0, 1)²:
// spherical caps (Dupuy & Benyoub 2023), a warp of u.
fn ms_ggx_sample_wm(w_in: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>) -> vec3<f32> {
    var w = w_in;
    if w.z < 0.0 {
        w = -w;
    }
    let s = vec3<f32>(alpha.x * w.x, alpha.y * w.y, w.z);
    let n2 = s.x * s.x + s.y * s.y + s.z * s.z;
    if n2 >= 1e-24 && n2 <= 1e24 {
        let m = ms_ggx_cap_normal(w, alpha, u, sqrt(n2));
        // Clearly facing w (above 4ε|w|₁, the dot product's rounding): the common case.
        let d = m.x * w.x + m.y * w.y + m.z * w.z;
        let l1 = abs(w.x) + abs(w.y) + abs(w.z);
        if d > 2.4e-7 * l1 {
            return m;
        }
        return ms_facing(m, w);
    }
    // A direction far from unit length or an extreme stretch: w rescaled first.
    let r = ms_rescaled(w);
    let sr = vec3<f32>(alpha.x * r.x, alpha.y * r.y, r.z);
    let m = ms_ggx_cap_normal(r, alpha, u, sqrt(sr.x * sr.x + sr.y * sr.y + sr.z * sr.z));
    return ms_facing(m, w);
}

// A visible normal with its pdf (ms_ggx_pdf at w normalised).
fn ms_ggx_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>) -> MsSample {
    let wm = ms_ggx_sample_wm(w, alpha, u);
    return MsSample(wm, ms_ggx_pdf(ms_unit(w), wm, alpha));
}

// The density of ms_ggx_sample_dcos: D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_ggx_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_ggx_d(wm, alpha) * wm.z;
}

// A normal distributed as D(m) cos θm with its pdf: tan²θ = ξ/(1 − ξ) at unit roughness
// (ξ = u₀), azimuth 2πu₁, stretched: m ∝ (αx √ξ cos φ, αy √ξ sin φ, √(1 − ξ)).
fn ms_ggx_sample_dcos(alpha: vec2<f32>, u: vec2<f32>) -> MsSample {
    let cs = ms_cos_sin_turn(u.y);
    let r = sqrt(u.x);
    let wm = ms_unit_normal(vec3<f32>(alpha.x * r * cs.x, alpha.y * r * cs.y,
        sqrt(max(1.0 - u.x, 0.0))));
    return MsSample(wm, ms_ggx_d(wm, alpha) * wm.z);
}

// The bounded VNDF's cap for the unit w (mirrored to w.z ≥ 0): the stretched unit direction
// w', the cap's lower bound −b, and w'.z − b = (1 − k) w'.z with 1 − k formed without the
// cancellation of k → 1 (a small α).
struct MsBoundedCap {
    ws: vec3<f32>,
    b: f32,
    top: f32,
}

fn ms_ggx_bounded_cap(w: vec3<f32>, alpha: vec2<f32>) -> MsBoundedCap {
    let down = w.z < 0.0;
    var v = w;
    if down {
        v = -w;
    }
    let ws = ms_normalize(vec3<f32>(alpha.x * v.x, alpha.y * v.y, v.z));
    if down {
        return MsBoundedCap(ws, ws.z, 0.0);
    }
    let a = min(min(alpha.x, alpha.y), 1.0);
    let s = 1.0 + sqrt(v.x * v.x + v.y * v.y);
    let a2 = a * a;
    let s2 = s * s;
    let den = s2 + a2 * v.z * v.z;
    let k = (1.0 - a2) * s2 / den;
    // 1 − k = a²(s² + w.z²)/(s² + a²w.z²).
    let one_minus_k = a2 * (s2 + v.z * v.z) / den;
    return MsBoundedCap(ws, k * ws.z, one_minus_k * ws.z);
}

// Bounded visible-normal sampling for reflection (Eto & Tokuyoshi 2023): the spherical cap
// shrunk to z ∈ [−k w'.z, 1], k = (1 − a²)s²/(s² + a²w.z²), a = min(1, αx, αy),
// s = 1 + |w.xy|: only normals whose reflection of w points below the horizon are removed
// (w.z > 0; a down-welling w is mirrored and the full cap used).
fn ms_ggx_sample_bounded(w_in: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>) -> MsSample {
    let w = ms_unit(w_in);
    let cap = ms_ggx_bounded_cap(w, alpha);
    let ws = cap.ws;
    let b = cap.b;
    let cs = ms_cos_sin_turn(u.x);
    // The cap point's height z ∈ [−b, 1]: z + b = above, 1 − z = u₁(1 + b), 1 + z = above +
    // (1 − b), 1 − b = (1 − w'.z) + (w'.z − b), 1 − w'.z = (w'.x² + w'.y²)/(1 + w'.z): sin²
    // without the cancellation of 1 − z² at the poles (z → ±1).
    let above = (1.0 - u.y) * (1.0 + b);
    let one_minus_b = (ws.x * ws.x + ws.y * ws.y) / (1.0 + ws.z) + cap.top;
    let sin = sqrt(max(u.y * (1.0 + b) * (above + one_minus_b), 0.0));
    let m = vec3<f32>(sin * cs.x + ws.x, sin * cs.y + ws.y, above + cap.top);
    let wm = ms_facing(ms_normalize(vec3<f32>(alpha.x * m.x, alpha.y * m.y, max(m.z, 0.0))), w);
    return MsSample(wm, ms_ggx_pdf_bounded(w, wm, alpha));
}

// The density of ms_ggx_sample_bounded per unit solid angle of the normal: the visible
// density scaled by (1 + w'.z)/(1 + k w'.z), 0 outside the bounded cap.
fn ms_ggx_pdf_bounded(w_in: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let w = ms_unit(w_in);
    let cap = ms_ggx_bounded_cap(w, alpha);
    let ws = cap.ws;
    let b = cap.b;
    let m = ms_normalize(vec3<f32>(wm.x / alpha.x, wm.y / alpha.y, wm.z));
    let d = ms_dot(m, ws);
    // The cap point: the reflection of w' about m'.
    let cz = (d + d) * m.z - ws.z;
    if cz < -b {
        return 0.0;
    }
    return ms_ggx_pdf(w, wm, alpha) * (1.0 + ws.z) / (1.0 + b);
}

// The density of wi = reflect(wo, wm) for wm from ms_ggx_sample_bounded(wo, ·):
// pdf(wm)/(4|wo·wm|) (Eto & Tokuyoshi's reflection pdf).
fn ms_ggx_pdf_bounded_reflection(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let wm = ms_half_vector_reflection(wo, wi);
    if !ms_half_vector_ok(wm) {
        return 0.0;
    }
    let c = abs(ms_dot(wo, wm));
    if !(c > 0.0) {
        return 0.0;
    }
    return ms_ggx_pdf_bounded(wo, wm, alpha) / (4.0 * c);
}

// microsurface WGSL library: Beckmann's special-function tables (beckmann_tables.wgsl).
// Generated by crates/microsurface-gpu/tools/beckmann_tables.rs (examples/translate.rs)
// from the Rust f64 functions of microsurface::fast::beckmann; do not edit.
// Each row: the degree-7 polynomial in s ∈ [−1, 1) of one segment (2 vec4, s⁰ first).

const MS_BK_SEGMENTS_LOG2: u32 = 2u;

// erfcx(x) = e^{x²} erfc x on [2^−14, 2^5) (fit error 4.3e-8 relative).
const MS_BK_ERFCX_K0: i32 = -14;
const MS_BK_ERFCX_K1: i32 = 5;
var<private> MS_BK_ERFCX: array<vec4<f32>, 152> = array<vec4<f32>, 152>(
    vec4<f32>(9.999225e-1, -8.607803e-6, 5.8177935e-11, 8.471002e-14),
    vec4<f32>(4.973799e-14, -1.7230661e-13, -3.1530334e-14, 1.0125234e-13),
    vec4<f32>(9.999053e-1, -8.60757e-6, 5.817566e-11, 8.326673e-14),
    vec4<f32>(5.1736393e-14, -1.7030821e-13, -3.330669e-14, 1.0036416e-13),
    vec4<f32>(9.998881e-1, -8.607337e-6, 5.8172744e-11, 9.30922e-14),
    vec4<f32>(5.2402527e-14, -1.8574031e-13, -3.28626e-14, 1.0791368e-13),
    vec4<f32>(9.998709e-1, -8.607104e-6, 5.8170968e-11, 8.915091e-14),
    vec4<f32>(5.4845017e-14, -1.8163249e-13, -3.5527137e-14, 1.0658141e-13),
    vec4<f32>(9.998451e-1, -1.721351e-5, 2.3273894e-10, 9.314771e-14),
    vec4<f32>(4.7517545e-14, -1.911804e-13, -3.0198066e-14, 1.110223e-13),
    vec4<f32>(9.9981064e-1, -1.7212578e-5, 2.3271904e-10, 9.2370556e-14),
    vec4<f32>(5.684342e-14, -1.9029223e-13, -3.5971226e-14, 1.110223e-13),
    vec4<f32>(9.997762e-1, -1.7211647e-5, 2.3270427e-10, 9.003909e-14),
    vec4<f32>(5.306866e-14, -1.8607338e-13, -3.330669e-14, 1.0835777e-13),
    vec4<f32>(9.997418e-1, -1.7210717e-5, 2.3268884e-10, 8.837375e-14),
    vec4<f32>(5.4400928e-14, -1.7963409e-13, -3.5083048e-14, 1.03916875e-13),
    vec4<f32>(9.996902e-1, -3.441864e-5, 9.307227e-10, 7.0665696e-14),
    vec4<f32>(5.6621374e-14, -1.8485213e-13, -3.6415315e-14, 1.0791368e-13),
    vec4<f32>(9.9962133e-1, -3.441492e-5, 9.305945e-10, 7.438494e-14),
    vec4<f32>(5.639933e-14, -1.9229063e-13, -3.5971226e-14, 1.1191048e-13),
    vec4<f32>(9.995525e-1, -3.4411194e-5, 9.304685e-10, 6.267209e-14),
    vec4<f32>(5.151435e-14, -1.7219559e-13, -3.330669e-14, 1.0169643e-13),
    vec4<f32>(9.994837e-1, -3.4407472e-5, 9.303388e-10, 7.3996365e-14),
    vec4<f32>(5.5289107e-14, -1.9084734e-13, -3.5527137e-14, 1.1057821e-13),
    vec4<f32>(9.9938047e-1, -6.880378e-5, 3.7206538e-9, -8.376633e-14),
    vec4<f32>(5.4845017e-14, -1.7730262e-13, -3.5527137e-14, 1.04360964e-13),
    vec4<f32>(9.9924284e-1, -6.8788904e-5, 3.7196282e-9, -8.493206e-14),
    vec4<f32>(5.4400928e-14, -1.7497115e-13, -3.419487e-14, 1.030287e-13),
    vec4<f32>(9.9910533e-1, -6.8774025e-5, 3.7186056e-9, -7.971401e-14),
    vec4<f32>(5.107026e-14, -1.8074431e-13, -3.2418512e-14, 1.04805054e-13),
    vec4<f32>(9.9896777e-1, -6.875915e-5, 3.7175791e-9, -7.582823e-14),
    vec4<f32>(5.6621374e-14, -1.9029223e-13, -3.5527137e-14, 1.110223e-13),
    vec4<f32>(9.9876153e-1, -1.374737e-4, 1.4864249e-8, -1.2666534e-12),
    vec4<f32>(5.2402527e-14, -1.9473312e-13, -3.375078e-14, 1.1279866e-13),
    vec4<f32>(9.9848664e-1, -1.3741427e-4, 1.4856064e-8, -1.2739254e-12),
    vec4<f32>(5.5289107e-14, -1.8085533e-13, -3.5083048e-14, 1.0613732e-13),
    vec4<f32>(9.9821186e-1, -1.3735486e-4, 1.4847887e-8, -1.2725376e-12),
    vec4<f32>(5.0404125e-14, -1.8096635e-13, -3.1974423e-14, 1.0569323e-13),
    vec4<f32>(9.979372e-1, -1.3729549e-4, 1.4839712e-8, -1.2732593e-12),
    vec4<f32>(5.77316e-14, -1.8152146e-13, -3.6859404e-14, 1.070255e-13),
    vec4<f32>(9.9752545e-1, -2.7441297e-4, 5.9309926e-8, -1.0789258e-11),
    vec4<f32>(5.1736393e-14, -1.8762769e-13, -3.1974423e-14, 1.09245946e-13),
    vec4<f32>(9.969769e-1, -2.7417587e-4, 5.9244666e-8, -1.0777879e-11),
    vec4<f32>(5.595524e-14, -1.8329782e-13, -3.5083048e-14, 1.070255e-13),
    vec4<f32>(9.964288e-1, -2.7393902e-4, 5.9179495e-8, -1.07598375e-11),
    vec4<f32>(5.795364e-14, -1.9095836e-13, -3.5971226e-14, 1.1191048e-13),
    vec4<f32>(9.9588114e-1, -2.7370243e-4, 5.911441e-8, -1.0746071e-11),
    vec4<f32>(5.8619776e-14, -1.8851587e-13, -3.6415315e-14, 1.09245946e-13),
    vec4<f32>(9.9506056e-1, -5.466961e-4, 2.3606782e-7, -8.645806e-11),
    vec4<f32>(8.104628e-14, -1.9739765e-13, -3.375078e-14, 1.1457502e-13),
    vec4<f32>(9.939681e-1, -5.457528e-4, 2.3554915e-7, -8.6238516e-11),
    vec4<f32>(7.9269924e-14, -1.881828e-13, -3.330669e-14, 1.08801856e-13),
    vec4<f32>(9.9287754e-1, -5.4481166e-4, 2.3503182e-7, -8.60223e-11),
    vec4<f32>(8.326673e-14, -1.7630342e-13, -3.5083048e-14, 1.030287e-13),
    vec4<f32>(9.9178886e-1, -5.4387253e-4, 2.3451582e-7, -8.5797314e-11),
    vec4<f32>(8.726353e-14, -1.8129942e-13, -3.863576e-14, 1.0613732e-13),
    vec4<f32>(9.9015933e-1, -1.0849356e-3, 9.3497744e-7, -6.843407e-10),
    vec4<f32>(4.958256e-13, -1.8651747e-13, -3.375078e-14, 1.0835777e-13),
    vec4<f32>(9.879932e-1, -1.0812038e-3, 9.3088147e-7, -6.8081535e-10),
    vec4<f32>(4.967138e-13, -1.757483e-13, -3.5971226e-14, 1.03472786e-13),
    vec4<f32>(9.8583454e-1, -1.0774885e-3, 9.268066e-7, -6.7730505e-10),
    vec4<f32>(4.9449334e-13, -1.6886492e-13, -3.6415315e-14, 9.9031894e-14),
    vec4<f32>(9.836832e-1, -1.0737894e-3, 9.2275275e-7, -6.738057e-10),
    vec4<f32>(4.898304e-13, -1.8474111e-13, -3.5083048e-14, 1.0835777e-13),
    vec4<f32>(9.804702e-1, -2.136542e-3, 3.6668446e-6, -5.349492e-9),
    vec4<f32>(6.9506623e-12, -1.8463009e-13, -3.0642155e-14, 1.03472786e-13),
    vec4<f32>(9.762117e-1, -2.1219386e-3, 3.634912e-6, -5.294606e-9),
    vec4<f32>(6.8760553e-12, -1.6997515e-13, -3.463896e-14, 9.636736e-14),
    vec4<f32>(9.719823e-1, -2.1074624e-3, 3.603307e-6, -5.2403415e-9),
    vec4<f32>(6.7961192e-12, -1.7919e-13, -3.419487e-14, 1.0036416e-13),
    vec4<f32>(9.677818e-1, -2.0931116e-3, 3.5720257e-6, -5.1867053e-9),
    vec4<f32>(6.72018e-12, -1.8951507e-13, -3.5527137e-14, 1.0524914e-13),
    vec4<f32>(9.6153444e-1, -4.1436376e-3, 1.41028095e-5, -4.0860034e-8),
    vec4<f32>(1.04839026e-10, -4.0389914e-13, -3.0198066e-14, 9.503509e-14),
    vec4<f32>(9.533033e-1, -4.0877135e-3, 1.38601445e-5, -4.003137e-8),
    vec4<f32>(1.0243628e-10, -4.0412118e-13, -3.28626e-14, 9.7699626e-14),
    vec4<f32>(9.451829e-1, -4.03275e-3, 1.3622393e-5, -3.922171e-8),
    vec4<f32>(1.0009482e-10, -3.9857007e-13, -3.463896e-14, 9.8587805e-14),
    vec4<f32>(9.3717164e-1, -3.978728e-3, 1.33894455e-5, -3.8430567e-8),
    vec4<f32>(9.780243e-11, -3.8902215e-13, -2.9309888e-14, 9.592327e-14),
    vec4<f32>(9.253549e-1, -7.798837e-3, 5.219515e-5, -2.9822098e-7),
    vec4<f32>(1.5110095e-9, -7.114087e-12, -1.7763568e-15, 9.681145e-14),
    vec4<f32>(9.0996367e-1, -7.593587e-3, 5.044154e-5, -2.864066e-7),
    vec4<f32>(1.4432613e-9, -6.7774675e-12, -5.3290705e-15, 1.0214052e-13),
    vec4<f32>(8.9497596e-1, -7.395212e-3, 4.8757214e-5, -2.751207e-7),
    vec4<f32>(1.3788544e-9, -6.4440675e-12, -5.7731597e-15, 9.636736e-14),
    vec4<f32>(8.803784e-1, -7.203441e-3, 4.7139085e-5, -2.6433727e-7),
    vec4<f32>(1.3176158e-9, -6.128653e-12, -6.661338e-15, 9.2370556e-14),
    vec4<f32>(8.591853e-1, -1.3855208e-2, 1.7931846e-4, -1.9924057e-6),
    vec4<f32>(1.9700584e-8, -1.7741708e-10, 1.4441781e-12, 8.2156504e-14),
    vec4<f32>(8.321765e-1, -1.3161226e-2, 1.67823e-4, -1.8416622e-6),
    vec4<f32>(1.8013315e-8, -1.6064183e-10, 1.2949641e-12, 7.41629e-14),
    vec4<f32>(8.065109e-1, -1.251147e-2, 1.5719283e-4, -1.7037701e-6),
    vec4<f32>(1.6484886e-8, -1.4560297e-10, 1.1577406e-12, 7.771561e-14),
    vec4<f32>(7.8210336e-1, -1.19026285e-2, 1.4735448e-4, -1.5775245e-6),
    vec4<f32>(1.509912e-8, -1.3207224e-10, 1.0387247e-12, 7.149836e-14),
    vec4<f32>(7.476803e-1, -2.2119032e-2, 5.35751e-4, -1.1261245e-5),
    vec4<f32>(2.1210928e-7, -3.6533685e-9, 5.8341776e-11, -7.904788e-13),
    vec4<f32>(7.054984e-1, -2.0104656e-2, 4.729953e-4, -9.701633e-6),
    vec4<f32>(1.7884639e-7, -3.0213583e-9, 4.739409e-11, -6.177281e-13),
    vec4<f32>(6.671063e-1, -1.8323604e-2, 4.1884705e-4, -8.384501e-6),
    vec4<f32>(1.5129326e-7, -2.5070404e-9, 3.863443e-11, -4.8361315e-13),
    vec4<f32>(6.320697e-1, -1.6744182e-2, 3.7197946e-4, -7.2685484e-6),
    vec4<f32>(1.2839418e-7, -2.0870798e-9, 3.1593617e-11, -3.8458126e-13),
    vec4<f32>(5.849986e-1, -2.9390983e-2, 1.2518741e-3, -4.7198217e-5),
    vec4<f32>(1.6154092e-6, -5.1030575e-8, 1.5075681e-9, -4.1826098e-11),
    vec4<f32>(5.3087085e-1, -2.4901982e-2, 1.0037073e-3, -3.609688e-5),
    vec4<f32>(1.184846e-6, -3.6036894e-8, 1.0280106e-9, -2.7595037e-11),
    vec4<f32>(4.8481083e-1, -2.1285098e-2, 8.129084e-4, -2.7909606e-5),
    vec4<f32>(8.7906886e-7, -2.5752737e-8, 7.096015e-10, -1.8429702e-11),
    vec4<f32>(4.4528228e-1, -1.8342182e-2, 6.646467e-4, -2.1803336e-5),
    vec4<f32>(6.593681e-7, -1.8613841e-8, 4.9558735e-10, -1.24527055e-11),
    vec4<f32>(3.9569807e-1, -2.9757312e-2, 1.9981607e-3, -1.2264443e-4),
    vec4<f32>(6.987141e-6, -3.7349582e-7, 1.8967754e-8, -9.1232955e-10),
    vec4<f32>(3.432959e-1, -2.3039434e-2, 1.4040956e-3, -7.910815e-5),
    vec4<f32>(4.1711164e-6, -2.0765906e-7, 9.8661594e-9, -4.460312e-10),
    vec4<f32>(3.022612e-1, -1.8253779e-2, 1.0150324e-3, -5.269123e-5),
    vec4<f32>(2.5784761e-6, -1.1981767e-7, 5.3355205e-9, -2.2702906e-10),
    vec4<f32>(2.6942998e-1, -1.475209e-2, 7.523223e-4, -3.6117242e-5),
    vec4<f32>(1.6450233e-6, -7.151112e-8, 2.99032e-9, -1.1994128e-10),
    vec4<f32>(2.3108725e-1, -2.2121625e-2, 1.9995393e-3, -1.719072e-4),
    vec4<f32>(1.4136136e-5, -1.1168833e-6, 8.599324e-8, -6.3321353e-9),
    vec4<f32>(1.9366209e-1, -1.580941e-2, 1.2349121e-3, -9.272403e-5),
    vec4<f32>(6.716945e-6, -4.708829e-7, 3.2301084e-8, -2.1350468e-9),
    vec4<f32>(1.6633534e-1, -1.17998505e-2, 8.085807e-4, -5.367924e-5),
    vec4<f32>(3.460897e-6, -2.1716717e-7, 1.3379374e-8, -7.990484e-10),
    vec4<f32>(1.4558972e-1, -9.114064e-3, 5.549222e-4, -3.2926295e-5),
    vec4<f32>(1.9070969e-6, -1.0798676e-7, 6.0202017e-9, -3.2691727e-10),
    vec4<f32>(1.224848e-1, -1.3007964e-2, 1.3532817e-3, -1.3807204e-4),
    vec4<f32>(1.3827661e-5, -1.3608255e-6, 1.3408695e-7, -1.2762786e-8),
    vec4<f32>(1.0096222e-1, -8.897383e-3, 7.727532e-4, -6.618298e-5),
    vec4<f32>(5.5922324e-6, -4.6646701e-7, 3.8935426e-8, -3.167861e-9),
    vec4<f32>(8.580567e-2, -6.452728e-3, 4.8005197e-4, -3.5342062e-5),
    vec4<f32>(2.5755642e-6, -1.8585855e-7, 1.34171385e-8, -9.498649e-10),
    vec4<f32>(7.4573696e-2, -4.8868856e-3, 3.1760236e-4, -2.0475041e-5),
    vec4<f32>(1.3095655e-6, -8.311601e-8, 5.2764815e-9, -3.2987502e-10),
    vec4<f32>(6.2307723e-2, -6.8401345e-3, 7.465146e-4, -8.1003855e-5),
    vec4<f32>(8.73851e-6, -9.3759945e-7, 1.0234092e-7, -1.0859012e-8),
    vec4<f32>(5.1080596e-2, -4.6060826e-3, 4.1368822e-4, -3.700841e-5),
    vec4<f32>(3.2976134e-6, -2.9272368e-7, 2.6292172e-8, -2.315999e-9),
    vec4<f32>(4.327192e-2, -3.3091987e-3, 2.5233987e-4, -1.918695e-5),
    vec4<f32>(1.4547079e-6, -1.0998697e-7, 8.387229e-9, -6.3057826e-10),
    vec4<f32>(3.7529606e-2, -2.4909754e-3, 1.6497479e-4, -1.09024595e-5),
    vec4<f32>(7.1892913e-7, -4.730736e-8, 3.133176e-9, -2.0528737e-10),
    vec4<f32>(3.1295717e-2, -3.4666515e-3, 3.834194e-4, -4.2342763e-5),
    vec4<f32>(4.668181e-6, -5.1397853e-7, 5.7898873e-8, -6.355341e-9),
    vec4<f32>(2.561857e-2, -2.3241737e-3, 2.106384e-4, -1.9070545e-5),
    vec4<f32>(1.7246861e-6, -1.5583068e-7, 1.4297796e-8, -1.2891967e-9),
    vec4<f32>(2.1683585e-2, -1.6655098e-3, 1.2783332e-4, -9.804431e-6),
    vec4<f32>(7.513878e-7, -5.7545e-8, 4.4559494e-9, -3.4075398e-10),
    vec4<f32>(1.8795889e-2, -1.2516708e-3, 8.3306186e-5, -5.5414653e-6),
    vec4<f32>(3.6840203e-7, -2.4478858e-8, 1.6400711e-9, -1.0885354e-10),
);

// r(a) = 1 − √π a erfcx(a) on [2^−14, 2^5) (fit error 5.8e-8 relative).
const MS_BK_ERFC_RATIO_K0: i32 = -14;
const MS_BK_ERFC_RATIO_K1: i32 = 5;
var<private> MS_BK_ERFC_RATIO: array<vec4<f32>, 152> = array<vec4<f32>, 152>(
    vec4<f32>(9.998783e-1, -1.3520655e-5, 1.16372106e-10, 8.9372953e-14),
    vec4<f32>(5.4622973e-14, -1.831868e-13, -3.5083048e-14, 1.0746959e-13),
    vec4<f32>(9.998513e-1, -1.3520189e-5, 1.1636769e-10, 8.6985974e-14),
    vec4<f32>(5.395684e-14, -1.777467e-13, -3.463896e-14, 1.04360964e-13),
    vec4<f32>(9.998242e-1, -1.3519723e-5, 1.16361754e-10, 9.531265e-14),
    vec4<f32>(5.6621374e-14, -1.926237e-13, -3.6415315e-14, 1.1235457e-13),
    vec4<f32>(9.9979717e-1, -1.3519258e-5, 1.1635656e-10, 9.2870156e-14),
    vec4<f32>(5.6621374e-14, -1.8840485e-13, -3.5971226e-14, 1.09690035e-13),
    vec4<f32>(9.9975663e-1, -2.7037118e-5, 4.654685e-10, 8.06577e-14),
    vec4<f32>(5.6177285e-14, -1.761924e-13, -3.5527137e-14, 1.03472786e-13),
    vec4<f32>(9.997026e-1, -2.7035258e-5, 4.654293e-10, 8.9595e-14),
    vec4<f32>(5.973e-14, -1.9295676e-13, -3.8191672e-14, 1.1279866e-13),
    vec4<f32>(9.996485e-1, -2.7033395e-5, 4.653939e-10, 8.01581e-14),
    vec4<f32>(5.4178884e-14, -1.7652546e-13, -3.463896e-14, 1.03916875e-13),
    vec4<f32>(9.9959445e-1, -2.7031534e-5, 4.6535684e-10, 8.01581e-14),
    vec4<f32>(5.306866e-14, -1.7652546e-13, -3.419487e-14, 1.03916875e-13),
    vec4<f32>(9.995133e-1, -5.4057484e-5, 1.8612636e-9, 3.8469228e-14),
    vec4<f32>(5.5067062e-14, -1.8152146e-13, -3.5527137e-14, 1.070255e-13),
    vec4<f32>(9.994052e-1, -5.405004e-5, 1.8609614e-9, 3.758105e-14),
    vec4<f32>(5.5067062e-14, -1.7952306e-13, -3.5527137e-14, 1.0613732e-13),
    vec4<f32>(9.9929714e-1, -5.4042597e-5, 1.8606601e-9, 4.4131365e-14),
    vec4<f32>(5.4622973e-14, -1.9173552e-13, -3.5527137e-14, 1.1235457e-13),
    vec4<f32>(9.991891e-1, -5.4035154e-5, 1.8603591e-9, 4.052314e-14),
    vec4<f32>(5.1958438e-14, -1.8540725e-13, -3.330669e-14, 1.09245946e-13),
    vec4<f32>(9.9902695e-1, -1.08047985e-4, 7.439686e-9, -3.1830094e-13),
    vec4<f32>(5.4622973e-14, -1.7141844e-13, -3.5083048e-14, 1.0125234e-13),
    vec4<f32>(9.988109e-1, -1.08018234e-4, 7.4372717e-9, -3.2190917e-13),
    vec4<f32>(5.6621374e-14, -1.6553425e-13, -3.6415315e-14, 9.8143715e-14),
    vec4<f32>(9.985949e-1, -1.0798849e-4, 7.43486e-9, -3.1646907e-13),
    vec4<f32>(5.4845017e-14, -1.7352786e-13, -3.5083048e-14, 1.0169643e-13),
    vec4<f32>(9.9837893e-1, -1.0795875e-4, 7.4324493e-9, -3.1152858e-13),
    vec4<f32>(5.0404125e-14, -1.8207658e-13, -3.1974423e-14, 1.0658141e-13),
    vec4<f32>(9.9805516e-1, -2.1582833e-4, 2.9715395e-8, -3.128331e-12),
    vec4<f32>(5.551115e-14, -1.7486013e-13, -3.5527137e-14, 1.03472786e-13),
    vec4<f32>(9.976236e-1, -2.1570952e-4, 2.969612e-8, -3.120837e-12),
    vec4<f32>(5.7065463e-14, -1.8207658e-13, -3.5971226e-14, 1.0658141e-13),
    vec4<f32>(9.971923e-1, -2.1559077e-4, 2.9676862e-8, -3.1179503e-12),
    vec4<f32>(5.1292304e-14, -1.8363089e-13, -3.2418512e-14, 1.0746959e-13),
    vec4<f32>(9.9676126e-1, -2.154721e-4, 2.9657613e-8, -3.1167846e-12),
    vec4<f32>(5.973e-14, -1.8129942e-13, -3.8191672e-14, 1.0613732e-13),
    vec4<f32>(9.961151e-1, -4.3058846e-4, 1.1851517e-7, -2.5533409e-11),
    vec4<f32>(5.4622973e-14, -1.8196555e-13, -3.1974423e-14, 1.070255e-13),
    vec4<f32>(9.952544e-1, -4.301147e-4, 1.1836154e-7, -2.549444e-11),
    vec4<f32>(5.750955e-14, -1.8396396e-13, -3.375078e-14, 1.0791368e-13),
    vec4<f32>(9.943946e-1, -4.2964157e-4, 1.1820814e-7, -2.54613e-11),
    vec4<f32>(5.750955e-14, -1.771916e-13, -3.330669e-14, 1.04805054e-13),
    vec4<f32>(9.935358e-1, -4.2916907e-4, 1.1805497e-7, -2.5424052e-11),
    vec4<f32>(5.77316e-14, -1.7463808e-13, -3.419487e-14, 1.0258461e-13),
    vec4<f32>(9.9224937e-1, -8.569228e-4, 4.713026e-7, -2.0354624e-10),
    vec4<f32>(1.2922996e-13, -1.7463808e-13, -3.463896e-14, 1.0258461e-13),
    vec4<f32>(9.905374e-1, -8.5504004e-4, 4.700826e-7, -2.0295265e-10),
    vec4<f32>(1.298961e-13, -1.6986412e-13, -3.5527137e-14, 1.0036416e-13),
    vec4<f32>(9.888292e-1, -8.5316214e-4, 4.6886615e-7, -2.0235569e-10),
    vec4<f32>(1.2811974e-13, -1.7386093e-13, -3.463896e-14, 1.0214052e-13),
    vec4<f32>(9.8712474e-1, -8.5128914e-4, 4.676533e-7, -2.0176294e-10),
    vec4<f32>(1.2834178e-13, -1.7452706e-13, -3.5083048e-14, 1.030287e-13),
    vec4<f32>(9.845751e-1, -1.6969773e-3, 1.8633626e-6, -1.6076107e-9),
    vec4<f32>(1.2352341e-12, -1.8551827e-13, -3.6859404e-14, 1.08801856e-13),
    vec4<f32>(9.811886e-1, -1.6895431e-3, 1.8537446e-6, -1.5982158e-9),
    vec4<f32>(1.2265744e-12, -1.8851587e-13, -3.5971226e-14, 1.09245946e-13),
    vec4<f32>(9.778169e-1, -1.6821473e-3, 1.8441829e-6, -1.5888955e-9),
    vec4<f32>(1.2161383e-12, -1.6819879e-13, -3.375078e-14, 9.8143715e-14),
    vec4<f32>(9.7445995e-1, -1.6747896e-3, 1.8346768e-6, -1.5796264e-9),
    vec4<f32>(1.209477e-12, -1.6719959e-13, -3.463896e-14, 9.8587805e-14),
    vec4<f32>(9.694521e-1, -3.3276482e-3, 7.2820867e-6, -1.2527211e-8),
    vec4<f32>(1.8354651e-11, -1.9839685e-13, -3.1974423e-14, 1.03472786e-13),
    vec4<f32>(9.628258e-1, -3.2986696e-3, 7.2073603e-6, -1.238172e-8),
    vec4<f32>(1.8118618e-11, -1.9206858e-13, -3.1530334e-14, 9.8587805e-14),
    vec4<f32>(9.5625716e-1, -3.269988e-3, 7.133501e-6, -1.2238096e-8),
    vec4<f32>(1.7883695e-11, -1.8784974e-13, -2.9309888e-14, 9.7699626e-14),
    vec4<f32>(9.4974566e-1, -3.2416002e-3, 7.0604983e-6, -1.2096301e-8),
    vec4<f32>(1.765632e-11, -1.9806379e-13, -2.9753977e-14, 1.030287e-13),
    vec4<f32>(9.4008404e-1, -6.399124e-3, 2.7810303e-5, -9.509669e-8),
    vec4<f32>(2.7642266e-10, -8.895107e-13, -3.1086245e-14, 1.04805054e-13),
    vec4<f32>(9.273963e-1, -6.289015e-3, 2.7246298e-5, -9.291387e-8),
    vec4<f32>(2.6941782e-10, -8.56093e-13, -3.1530334e-14, 9.636736e-14),
    vec4<f32>(9.149265e-1, -6.1811362e-3, 2.6695225e-5, -9.078632e-8),
    vec4<f32>(2.6260571e-10, -8.3555385e-13, -3.1974423e-14, 9.503509e-14),
    vec4<f32>(9.026703e-1, -6.0754367e-3, 2.6156755e-5, -8.871252e-8),
    vec4<f32>(2.5598057e-10, -8.2167606e-13, -3.1974423e-14, 9.9031894e-14),
    vec4<f32>(8.8467705e-1, -1.1841728e-2, 1.01487945e-4, -6.8559564e-7),
    vec4<f32>(3.9413006e-9, -2.022571e-11, 6.039613e-14, 9.8143715e-14),
    vec4<f32>(8.613941e-1, -1.14438785e-2, 9.746738e-5, -6.548533e-7),
    vec4<f32>(3.7461754e-9, -1.9134916e-11, 5.728751e-14, 9.148238e-14),
    vec4<f32>(8.38891e-1, -1.1061749e-2, 9.3626666e-5, -6.256297e-7),
    vec4<f32>(3.5615182e-9, -1.8111956e-11, 5.3290705e-14, 8.7041485e-14),
    vec4<f32>(8.171371e-1, -1.0694638e-2, 8.995695e-5, -5.9784344e-7),
    vec4<f32>(3.3867338e-9, -1.7152058e-11, 4.7073456e-14, 8.615331e-14),
    vec4<f32>(7.8584695e-1, -2.0341357e-2, 3.3901897e-4, -4.4695416e-6),
    vec4<f32>(5.0268525e-8, -5.015497e-10, 4.514167e-12, 3.996803e-14),
    vec4<f32>(7.464853e-1, -1.9037347e-2, 3.133691e-4, -4.086745e-6),
    vec4<f32>(4.5516558e-8, -4.5011284e-10, 4.0136783e-12, 4.7073456e-14),
    vec4<f32>(7.096321e-1, -1.783149e-2, 2.89906e-4, -3.7399832e-6),
    vec4<f32>(4.1250228e-8, -4.043006e-10, 3.574474e-12, 4.6185278e-14),
    vec4<f32>(6.750995e-1, -1.6715458e-2, 2.684246e-4, -3.4255886e-6),
    vec4<f32>(3.7416495e-8, -3.634768e-10, 3.1872283e-12, 4.6185278e-14),
    vec4<f32>(6.272794e-1, -3.0387005e-2, 9.580818e-4, -2.4061048e-5),
    vec4<f32>(5.1801413e-7, -9.927543e-9, 1.7332358e-10, -2.7222669e-12),
    vec4<f32>(5.7015324e-1, -2.6827596e-2, 8.253934e-4, -2.0287804e-5),
    vec4<f32>(4.283978e-7, -8.065489e-9, 1.3850876e-10, -2.1382895e-12),
    vec4<f32>(5.196439e-1, -2.3756387e-2, 7.133347e-4, -1.7162258e-5),
    vec4<f32>(3.5547052e-7, -6.5749886e-9, 1.1106582e-10, -1.677547e-12),
    vec4<f32>(4.7485265e-1, -2.1098126e-2, 6.18392e-4, -1.4564653e-5),
    vec4<f32>(2.9592425e-7, -5.377808e-9, 8.935852e-11, -1.3233858e-12),
    vec4<f32>(4.167533e-1, -3.5502225e-2, 2.0077599e-3, -9.16237e-5),
    vec4<f32>(3.617964e-6, -1.2807482e-7, 4.1592605e-9, -1.2519785e-10),
    vec4<f32>(3.5310093e-1, -2.8464397e-2, 1.5355214e-3, -6.720277e-5),
    vec4<f32>(2.5549414e-6, -8.734229e-8, 2.74549e-9, -8.015033e-11),
    vec4<f32>(3.0181482e-1, -2.3053482e-2, 1.1872437e-3, -4.985952e-5),
    vec4<f32>(1.8258146e-6, -6.0294994e-8, 1.8349833e-9, -5.1961768e-11),
    vec4<f32>(2.6008537e-1, -1.8848889e-2, 9.2748983e-4, -3.7398404e-5),
    vec4<f32>(1.3196806e-6, -4.211374e-8, 1.24123e-9, -3.4098946e-11),
    vec4<f32>(2.1097384e-1, -2.833318e-2, 2.6085791e-3, -1.9815165e-4),
    vec4<f32>(1.3240014e-5, -8.032937e-7, 4.5332847e-8, -2.383124e-9),
    vec4<f32>(1.6334534e-1, -1.9909557e-2, 1.6825865e-3, -1.1829047e-4),
    vec4<f32>(7.361291e-6, -4.1804822e-7, 2.216081e-8, -1.0987664e-9),
    vec4<f32>(1.2941593e-1, -1.4392785e-2, 1.1207133e-3, -7.312401e-5),
    vec4<f32>(4.2474107e-6, -2.2617557e-7, 1.1279408e-8, -5.2811067e-10),
    vec4<f32>(1.045896e-1, -1.0667653e-2, 7.6819374e-4, -4.665181e-5),
    vec4<f32>(2.534995e-6, -1.2680964e-7, 5.958998e-9, -2.638087e-10),
    vec4<f32>(7.841912e-2, -1.4176364e-2, 1.8281857e-3, -2.0045321e-4),
    vec4<f32>(1.9795682e-5, -1.8097585e-6, 1.5757479e-7, -1.2851965e-8),
    vec4<f32>(5.60429e-2, -8.755298e-3, 9.860945e-4, -9.524624e-5),
    vec4<f32>(8.346028e-6, -6.8116896e-7, 5.3103143e-8, -3.906189e-9),
    vec4<f32>(4.182938e-2, -5.7326877e-3, 5.708639e-4, -4.907507e-5),
    vec4<f32>(3.84914e-6, -2.8258418e-7, 1.986625e-8, -1.325575e-9),
    vec4<f32>(3.230852e-2, -3.9342963e-3, 3.5016204e-4, -2.7042239e-5),
    vec4<f32>(1.9139986e-6, -1.2730473e-7, 8.125588e-9, -4.946015e-10),
    vec4<f32>(2.3056017e-2, -4.7972575e-3, 7.341793e-4, -9.804619e-5),
    vec4<f32>(1.20590175e-5, -1.4004432e-6, 1.5913854e-7, -1.7034818e-8),
    vec4<f32>(1.5770199e-2, -2.7393384e-3, 3.519189e-4, -3.9650156e-5),
    vec4<f32>(4.1337757e-6, -4.0863492e-7, 3.944863e-8, -3.62363e-9),
    vec4<f32>(1.1437163e-2, -1.7017398e-3, 1.8792653e-4, -1.8260866e-5),
    vec4<f32>(1.6470873e-6, -1.412674e-7, 1.1818231e-8, -9.471726e-10),
    vec4<f32>(8.66178e-3, -1.1258711e-3, 1.088732e-4, -9.2847595e-6),
    vec4<f32>(7.365851e-7, -5.5677763e-8, 4.1018984e-9, -2.9088262e-10),
    vec4<f32>(6.061911e-3, -1.3231621e-3, 2.1536356e-4, -3.0982304e-5),
    vec4<f32>(4.154092e-6, -5.319391e-7, 6.779496e-8, -8.1705505e-9),
    vec4<f32>(4.0820343e-3, -7.332432e-4, 9.839357e-5, -1.1690638e-5),
    vec4<f32>(1.2970188e-6, -1.3763658e-7, 1.44309e-8, -1.4465321e-9),
    vec4<f32>(2.932701e-3, -4.4726077e-4, 5.101198e-5, -5.157015e-6),
    vec4<f32>(4.873513e-7, -4.4093955e-8, 3.9244634e-9, -3.361419e-10),
    vec4<f32>(2.2075695e-3, -2.924102e-4, 2.8986162e-5, -2.548597e-6),
    vec4<f32>(2.0962135e-7, -1.6517234e-8, 1.276658e-9, -9.536809e-11),
    vec4<f32>(1.53612e-3, -3.3979642e-4, 5.6287994e-5, -8.275684e-6),
    vec4<f32>(1.1385838e-6, -1.502121e-7, 1.9849313e-8, -2.4841724e-9),
    vec4<f32>(1.0298727e-3, -1.8667341e-4, 2.5351253e-5, -3.0571844e-6),
    vec4<f32>(3.4523006e-7, -3.7393693e-8, 4.0174672e-9, -4.1333592e-10),
    vec4<f32>(7.380098e-4, -1.1328932e-4, 1.3033428e-5, -1.331858e-6),
    vec4<f32>(1.274904e-7, -1.170815e-8, 1.0604964e-9, -9.25777e-11),
    vec4<f32>(5.5463216e-4, -7.382818e-5, 7.366494e-6, -6.529916e-7),
    vec4<f32>(5.4233485e-8, -4.32196e-9, 3.384992e-10, -2.5654366e-11),
);

// erfinv(1 − q)/(1 − q) on q ∈ [2^−25, 1) (fit error 5.3e-8 relative).
const MS_BK_ERFINV_Q_K0: i32 = -25;
const MS_BK_ERFINV_Q_K1: i32 = 0;
var<private> MS_BK_ERFINV_Q: array<vec4<f32>, 200> = array<vec4<f32>, 200>(
    vec4<f32>(3.9046016e0, -1.3801319e-2, 7.43736e-4, -5.4314907e-5),
    vec4<f32>(4.4844564e-6, -3.9593175e-7, 3.7148247e-8, -3.5245051e-9),
    vec4<f32>(3.8796005e0, -1.1360582e-2, 5.0071336e-4, -2.9913715e-5),
    vec4<f32>(2.0206483e-6, -1.4595663e-7, 1.1134741e-8, -8.638139e-10),
    vec4<f32>(3.8586712e0, -9.6619185e-3, 3.6021826e-4, -1.8206969e-5),
    vec4<f32>(1.0405903e-6, -6.3597454e-8, 4.09052e-9, -2.6818192e-10),
    vec4<f32>(3.8406575e0, -8.410642e-3, 2.7168475e-4, -1.1899763e-5),
    vec4<f32>(5.8939276e-7, -3.121761e-8, 1.7361579e-9, -9.8363984e-11),
    vec4<f32>(3.8175905e0, -1.4097435e-2, 7.5870205e-4, -5.5376688e-5),
    vec4<f32>(4.5705096e-6, -4.034267e-7, 3.784378e-8, -3.5899408e-9),
    vec4<f32>(3.7920496e0, -1.16073135e-2, 5.109042e-4, -3.0504969e-5),
    vec4<f32>(2.0598447e-6, -1.4874925e-7, 1.13454615e-8, -8.8002494e-10),
    vec4<f32>(3.7706635e0, -9.873917e-3, 3.6761994e-4, -1.8570187e-5),
    vec4<f32>(1.0609601e-6, -6.482521e-8, 4.1686317e-9, -2.732765e-10),
    vec4<f32>(3.7522526e0, -8.596826e-3, 2.7731352e-4, -1.2139064e-5),
    vec4<f32>(6.0102127e-7, -3.182494e-8, 1.7695712e-9, -1.0026646e-10),
    vec4<f32>(3.7286723e0, -1.4413081e-2, 7.745885e-4, -5.6501816e-5),
    vec4<f32>(4.6615996e-6, -4.1135434e-7, 3.8579007e-8, -3.659057e-9),
    vec4<f32>(3.702556e0, -1.187052e-2, 5.2172894e-4, -3.1131895e-5),
    vec4<f32>(2.101361e-6, -1.5170475e-7, 1.1568334e-8, -8.971881e-10),
    vec4<f32>(3.6806822e0, -1.010022e-2, 3.7548656e-4, -1.8955525e-5),
    vec4<f32>(1.0825465e-6, -6.612525e-8, 4.2512838e-9, -2.7866953e-10),
    vec4<f32>(3.6618476e0, -8.795687e-3, 2.832988e-4, -1.2393057e-5),
    vec4<f32>(6.133498e-7, -3.24683e-8, 1.8049384e-9, -1.022773e-10),
    vec4<f32>(3.6377184e0, -1.4750466e-2, 7.9149194e-4, -5.7696743e-5),
    vec4<f32>(4.75823e-6, -4.1975713e-7, 3.9357786e-8, -3.7322554e-9),
    vec4<f32>(3.6109867e0, -1.215209e-2, 5.3325505e-4, -3.1798165e-5),
    vec4<f32>(2.1454307e-6, -1.5483947e-7, 1.180455e-8, -9.15346e-10),
    vec4<f32>(3.588591e0, -1.0342483e-2, 3.83868e-4, -1.9365283e-5),
    vec4<f32>(1.1054735e-6, -6.750487e-8, 4.3389274e-9, -2.843752e-10),
    vec4<f32>(3.5693026e0, -9.008703e-3, 2.896792e-4, -1.2663283e-5),
    vec4<f32>(6.2645034e-7, -3.3151345e-8, 1.842464e-9, -1.0441781e-10),
    vec4<f32>(3.5445855e0, -1.5112158e-2, 8.0952386e-4, -5.896887e-5),
    vec4<f32>(4.860975e-6, -4.286838e-7, 4.018454e-8, -3.8099e-9),
    vec4<f32>(3.5171936e0, -1.2454218e-2, 5.455602e-4, -3.2508004e-5),
    vec4<f32>(2.1923224e-6, -1.581719e-7, 1.20555015e-8, -9.346071e-10),
    vec4<f32>(3.4942381e0, -1.0602634e-2, 3.9282197e-4, -1.9802106e-5),
    vec4<f32>(1.1298831e-6, -6.897236e-8, 4.4321133e-9, -2.9042546e-10),
    vec4<f32>(3.4744618e0, -9.237601e-3, 2.964994e-4, -1.2951515e-5),
    vec4<f32>(6.4040535e-7, -3.3878305e-8, 1.8823698e-9, -1.0666312e-10),
    vec4<f32>(3.4491127e0, -1.5501155e-2, 8.288132e-4, -6.032672e-5),
    vec4<f32>(4.970496e-6, -4.3818997e-7, 4.1064304e-8, -3.892488e-9),
    vec4<f32>(3.4210105e0, -1.2779471e-2, 5.5873464e-4, -3.3266275e-5),
    vec4<f32>(2.2423446e-6, -1.617233e-7, 1.2322719e-8, -9.551169e-10),
    vec4<f32>(3.3974519e0, -1.0882929e-2, 4.0241532e-4, -2.0269052e-5),
    vec4<f32>(1.1559393e-6, -7.0537226e-8, 4.5313797e-9, -2.9689673e-10),
    vec4<f32>(3.37715e0, -9.484401e-3, 3.0381125e-4, -1.32598025e-5),
    vec4<f32>(6.5531015e-7, -3.465392e-8, 1.9249136e-9, -1.09070086e-10),
    vec4<f32>(3.3511188e0, -1.5920965e-2, 8.4950996e-4, -6.178017e-5),
    vec4<f32>(5.087556e-6, -4.4834e-7, 4.200286e-8, -3.980542e-9),
    vec4<f32>(3.3222501e0, -1.3130857e-2, 5.728834e-4, -3.4078632e-5),
    vec4<f32>(2.2958548e-6, -1.655182e-7, 1.2608043e-8, -9.770353e-10),
    vec4<f32>(3.2980394e0, -1.1186014e-2, 4.1272625e-4, -2.0769668e-5),
    vec4<f32>(1.1838317e-6, -7.221059e-8, 4.6374424e-9, -3.037819e-10),
    vec4<f32>(3.277169e0, -9.751473e-3, 3.116754e-4, -1.3590532e-5),
    vec4<f32>(6.71275e-7, -3.5483797e-8, 1.9704043e-9, -1.1163692e-10),
    vec4<f32>(3.2503996e0, -1.6375713e-2, 8.717899e-4, -6.334072e-5),
    vec4<f32>(5.213043e-6, -4.5920837e-7, 4.3006956e-8, -4.074634e-9),
    vec4<f32>(3.2206998e0, -1.3511909e-2, 5.881297e-4, -3.4951667e-5),
    vec4<f32>(2.3532677e-6, -1.6958528e-7, 1.2913533e-8, -1.000446e-9),
    vec4<f32>(3.1957817e0, -1.1514996e-2, 4.2384653e-4, -2.1308108e-5),
    vec4<f32>(1.2137815e-6, -7.4005264e-8, 4.7510866e-9, -3.1115022e-10),
    vec4<f32>(3.174294e0, -1.0041602e-2, 3.2016315e-4, -1.3946497e-5),
    vec4<f32>(6.8842894e-7, -3.637438e-8, 2.0191653e-9, -1.1440093e-10),
    vec4<f32>(3.1467223e0, -1.6870238e-2, 8.958599e-4, -6.502186e-5),
    vec4<f32>(5.347992e-6, -4.708819e-7, 4.4084366e-8, -4.175549e-9),
    vec4<f32>(3.116118e0, -1.3926776e-2, 6.04619e-4, -3.589312e-5),
    vec4<f32>(2.4150706e-6, -1.7395772e-7, 1.3241644e-8, -1.0256045e-9),
    vec4<f32>(3.0904295e0, -1.1873523e-2, 4.358846e-4, -2.188925e-5),
    vec4<f32>(1.246048e-6, -7.593623e-8, 4.8732485e-9, -3.1908698e-10),
    vec4<f32>(3.0682685e0, -1.0358051e-2, 3.2935888e-4, -1.4330984e-5),
    vec4<f32>(7.069231e-7, -3.7333344e-8, 2.07163e-9, -1.1734258e-10),
    vec4<f32>(3.0398211e0, -1.7410206e-2, 9.219652e-4, -6.683949e-5),
    vec4<f32>(5.4936227e-6, -4.8346243e-7, 4.524427e-8, -4.2841144e-9),
    vec4<f32>(3.0082288e0, -1.43803e-2, 6.225238e-4, -3.6912148e-5),
    vec4<f32>(2.4818357e-6, -1.7867475e-7, 1.35952245e-8, -1.0526833e-9),
    vec4<f32>(2.9816978e0, -1.226584e-2, 4.4896934e-4, -2.2518867e-5),
    vec4<f32>(1.2809368e-6, -7.802119e-8, 5.005015e-9, -3.2763658e-10),
    vec4<f32>(2.9588e0, -1.0704613e-2, 3.3936297e-4, -1.4747889e-5),
    vec4<f32>(7.269362e-7, -3.836955e-8, 2.1282425e-9, -1.2052404e-10),
    vec4<f32>(2.929393e0, -1.8002173e-2, 9.5039775e-4, -6.881249e-5),
    vec4<f32>(5.6513745e-6, -4.970702e-7, 4.649744e-8, -4.40129e-9),
    vec4<f32>(2.8967168e0, -1.4878061e-2, 6.420499e-4, -3.8019614e-5),
    vec4<f32>(2.554242e-6, -1.837827e-7, 1.3977669e-8, -1.0819079e-9),
    vec4<f32>(2.8692605e0, -1.2696815e-2, 4.6325443e-4, -2.3203835e-5),
    vec4<f32>(1.3188106e-6, -8.0281076e-8, 5.147651e-9, -3.3688075e-10),
    vec4<f32>(2.8455532e0, -1.1085614e-2, 3.502952e-4, -1.5201849e-5),
    vec4<f32>(7.4868024e-7, -3.9493628e-8, 2.1895872e-9, -1.2397017e-10),
    vec4<f32>(2.815091e0, -1.8653564e-2, 9.815063e-4, -7.096336e-5),
    vec4<f32>(5.822963e-6, -5.118478e-7, 4.7856616e-8, -4.528255e-9),
    vec4<f32>(2.7812214e0, -1.5426309e-2, 6.634432e-4, -3.92285e-5),
    vec4<f32>(2.6330981e-6, -1.8933653e-7, 1.4392947e-8, -1.1136372e-9),
    vec4<f32>(2.7527456e0, -1.3171851e-2, 4.7892373e-4, -2.3952363e-5),
    vec4<f32>(1.3601024e-6, -8.2740854e-8, 5.3027023e-9, -3.4688163e-10),
    vec4<f32>(2.7281454e0, -1.1505804e-2, 3.6229877e-4, -1.5698415e-5),
    vec4<f32>(7.7240867e-7, -4.0718195e-8, 2.2563267e-9, -1.2772361e-10),
    vec4<f32>(2.696519e0, -1.9372422e-2, 1.0157079e-3, -7.3319046e-5),
    vec4<f32>(6.0104376e-6, -5.2796565e-7, 4.933704e-8, -4.666397e-9),
    vec4<f32>(2.6613321e0, -1.603169e-2, 6.869972e-4, -4.0554365e-5),
    vec4<f32>(2.7193719e-6, -1.9540201e-7, 1.48458685e-8, -1.1482246e-9),
    vec4<f32>(2.6317303e0, -1.36965765e-2, 4.9619644e-4, -2.4774296e-5),
    vec4<f32>(1.4053304e-6, -8.543022e-8, 5.471989e-9, -3.578311e-10),
    vec4<f32>(2.606144e0, -1.1970042e-2, 3.755443e-4, -1.6244237e-5),
    vec4<f32>(7.984251e-7, -4.205842e-8, 2.329264e-9, -1.31811e-10),
    vec4<f32>(2.573231e0, -2.0166716e-2, 1.0534975e-3, -7.5911834e-5),
    vec4<f32>(6.2162558e-6, -5.4562787e-7, 5.09569e-8, -4.8173803e-9),
    vec4<f32>(2.536589e0, -1.6700514e-2, 7.130596e-4, -4.2015832e-5),
    vec4<f32>(2.8142244e-6, -2.0205817e-7, 1.5342142e-8, -1.1860406e-9),
    vec4<f32>(2.5057435e0, -1.4276106e-2, 5.15331e-4, -2.5681413e-5),
    vec4<f32>(1.4551165e-6, -8.8384986e-8, 5.657702e-9, -3.6982772e-10),
    vec4<f32>(2.4790678e0, -1.248253e-2, 3.902321e-4, -1.6847269e-5),
    vec4<f32>(8.270938e-7, -4.353243e-8, 2.4093687e-9, -1.362972e-10),
    vec4<f32>(2.4447355e0, -2.104281e-2, 1.095453e-3, -7.878026e-5),
    vec4<f32>(6.443364e-6, -5.6507946e-7, 5.2738095e-8, -4.9831614e-9),
    vec4<f32>(2.4064891e0, -1.7437218e-2, 7.420323e-4, -4.3635056e-5),
    vec4<f32>(2.9190458e-6, -2.0939954e-7, 1.5888661e-8, -1.2276562e-9),
    vec4<f32>(2.3742747e0, -1.4913496e-2, 5.366236e-4, -2.668767e-5),
    vec4<f32>(1.5102039e-6, -9.1648126e-8, 5.86246e-9, -3.8298698e-10),
    vec4<f32>(2.3464022e0, -1.304529e-2, 4.0658945e-4, -1.7516893e-5),
    vec4<f32>(8.588491e-7, -4.5162007e-8, 2.49777e-9, -1.4122747e-10),
    vec4<f32>(2.3105128e0, -2.2002447e-2, 1.1422209e-3, -8.1969505e-5),
    vec4<f32>(6.695264e-6, -5.866131e-7, 5.4706796e-8, -5.1661893e-9),
    vec4<f32>(2.2705123e0, -1.8241411e-2, 7.7435584e-4, -4.5437824e-5),
    vec4<f32>(3.0354806e-6, -2.1753901e-7, 1.6493642e-8, -1.273647e-9),
    vec4<f32>(2.236806e0, -1.5606855e-2, 5.6039204e-4, -2.7809185e-5),
    vec4<f32>(1.5714677e-6, -9.527039e-8, 6.089433e-9, -3.9760462e-10),
    vec4<f32>(2.2076337e0, -1.3655325e-2, 4.2485518e-4, -1.8263856e-5),
    vec4<f32>(8.9419996e-7, -4.697286e-8, 2.5958737e-9, -1.4669865e-10),
    vec4<f32>(2.1700609e0, -2.3037259e-2, 1.1944568e-3, -8.553065e-5),
    vec4<f32>(6.9760285e-6, -6.1057364e-7, 5.6894102e-8, -5.3692695e-9),
    vec4<f32>(2.1281753e0, -1.9102605e-2, 8.1045576e-4, -4.7452715e-5),
    vec4<f32>(3.1654206e-6, -2.2660836e-7, 1.7166768e-8, -1.324767e-9),
    vec4<f32>(2.0928764e0, -1.6344287e-2, 5.8692734e-4, -2.9063465e-5),
    vec4<f32>(1.6399031e-6, -9.9310945e-8, 6.3422583e-9, -4.1385917e-10),
    vec4<f32>(2.0623264e0, -1.4299758e-2, 4.4523497e-4, -1.909959e-5),
    vec4<f32>(9.337183e-7, -4.8994558e-8, 2.7052582e-9, -1.5282353e-10),
    vec4<f32>(2.022984e0, -2.4119532e-2, 1.2526698e-3, -8.951629e-5),
    vec4<f32>(7.290149e-6, -6.373527e-7, 5.933588e-8, -5.595746e-9),
    vec4<f32>(1.979139e0, -1.9991564e-2, 8.5060863e-4, -4.970783e-5),
    vec4<f32>(3.3108984e-6, -2.3675476e-7, 1.7919117e-8, -1.3818449e-9),
    vec4<f32>(1.942207e0, -1.7095732e-2, 6.1637646e-4, -3.0466854e-5),
    vec4<f32>(1.7165502e-6, -1.0383447e-7, 6.6250836e-9, -4.3201887e-10),
    vec4<f32>(1.9102618e0, -1.4948109e-2, 4.6779844e-4, -2.0034176e-5),
    vec4<f32>(9.779849e-7, -5.125901e-8, 2.8277016e-9, -1.5964474e-10),
    vec4<f32>(1.8691553e0, -2.5187917e-2, 1.3168737e-3, -9.3968345e-5),
    vec4<f32>(7.641974e-6, -6.673582e-7, 6.207099e-8, -5.8492855e-9),
    vec4<f32>(1.8233994e0, -2.0847276e-2, 8.946555e-4, -5.222205e-5),
    vec4<f32>(3.4737473e-6, -2.4812485e-7, 1.8762261e-8, -1.4457795e-9),
    vec4<f32>(1.7849144e0, -1.7800989e-2, 6.485017e-4, -3.202801e-5),
    vec4<f32>(1.8022729e-6, -1.08902384e-7, 6.9421056e-9, -4.523848e-10),
    vec4<f32>(1.7516758e0, -1.5541209e-2, 4.922726e-4, -2.1071275e-5),
    vec4<f32>(1.027437e-6, -5.3794814e-8, 2.9649403e-9, -1.6729018e-10),
    vec4<f32>(1.7089858e0, -2.6127469e-2, 1.3859146e-3, -9.8889126e-5),
    vec4<f32>(8.034221e-6, -7.0092483e-7, 6.513523e-8, -6.1335106e-9),
    vec4<f32>(1.661593e0, -2.155937e-2, 9.4147393e-4, -5.4985212e-5),
    vec4<f32>(3.6547415e-6, -2.6082154e-7, 1.970593e-8, -1.5174422e-9),
    vec4<f32>(1.6218514e0, -1.835404e-2, 6.8225386e-4, -3.3733508e-5),
    vec4<f32>(1.8972198e-6, -1.145496e-7, 7.2964355e-9, -4.751515e-10),
    vec4<f32>(1.5876296e0, -1.5977072e-2, 5.176902e-4, -2.219729e-5),
    vec4<f32>(1.0820094e-6, -5.6613743e-8, 3.1180836e-9, -1.7583979e-10),
    vec4<f32>(1.5438341e0, -2.6745113e-2, 1.4563905e-3, -1.0418113e-4),
    vec4<f32>(8.464568e-6, -7.380944e-7, 6.854569e-8, -6.4507653e-9),
    vec4<f32>(1.4954515e0, -2.1947289e-2, 9.881904e-4, -5.7918332e-5),
    vec4<f32>(3.851704e-6, -2.7480246e-7, 2.0751955e-8, -1.597166e-9),
    vec4<f32>(1.4551003e0, -1.8584935e-2, 7.151847e-4, -3.5519966e-5),
    vec4<f32>(1.9996733e-6, -1.2073113e-7, 7.687485e-9, -5.0042903e-10),
    vec4<f32>(1.4205356e0, -1.6094834e-2, 5.4194545e-4, -2.3360897e-5),
    vec4<f32>(1.1403876e-6, -5.968042e-8, 3.286317e-9, -1.8528468e-10),
    vec4<f32>(1.3765777e0, -2.6741873e-2, 1.5214762e-3, -1.0953786e-4),
    vec4<f32>(8.9188425e-6, -7.7814497e-7, 7.2265436e-8, -6.799411e-9),
    vec4<f32>(1.3284252e0, -2.1736078e-2, 1.0295288e-3, -6.0804487e-5),
    vec4<f32>(4.0558825e-6, -2.8966952e-7, 2.1881299e-8, -1.6840769e-9),
    vec4<f32>(1.2886416e0, -1.8237479e-2, 7.431373e-4, -3.722715e-5),
    vec4<f32>(2.1039357e-6, -1.27216e-7, 8.105257e-9, -5.2774496e-10),
    vec4<f32>(1.2548714e0, -1.5653165e-2, 5.6172244e-4, -2.443957e-5),
    vec4<f32>(1.1986928e-6, -6.285337e-8, 3.4641143e-9, -1.954179e-10),
    vec4<f32>(1.2123915e0, -2.5669008e-2, 1.5716114e-3, -1.14269154e-4),
    vec4<f32>(9.359751e-6, -8.1871406e-7, 7.61339e-8, -7.1681012e-9),
    vec4<f32>(1.1665534e0, -2.0507988e-2, 1.0593316e-3, -6.3177686e-5),
    vec4<f32>(4.246493e-6, -3.0429752e-7, 2.302945e-8, -1.7743171e-9),
    vec4<f32>(1.1293287e0, -1.6913543e-2, 7.623282e-4, -3.851879e-5),
    vec4<f32>(2.1974927e-6, -1.334076e-7, 8.52023e-9, -5.555725e-10),
    vec4<f32>(1.0982742e0, -1.42653985e-2, 5.7499664e-4, -2.5177267e-5),
    vec4<f32>(1.2489646e-6, -6.5789614e-8, 3.6365875e-9, -2.0552937e-10),
    vec4<f32>(1.0600606e0, -2.2765124e-2, 1.6065057e-3, -1.16895484e-4),
    vec4<f32>(9.718163e-6, -8.5442923e-7, 7.975475e-8, -7.525863e-9),
    vec4<f32>(1.0201536e0, -1.7486874e-2, 1.0848793e-3, -6.394562e-5),
    vec4<f32>(4.3910923e-6, -3.162387e-7, 2.4051475e-8, -1.858278e-9),
    vec4<f32>(9.890693e-1, -1.3795619e-2, 7.8597997e-4, -3.848282e-5),
    vec4<f32>(2.2658453e-6, -1.3800106e-7, 8.871655e-9, -5.8034155e-10),
    vec4<f32>(9.643464e-1, -1.105056e-2, 6.002069e-4, -2.4733703e-5),
    vec4<f32>(1.2869389e-6, -6.768162e-8, 3.776423e-9, -2.1408253e-10),
    vec4<f32>(9.3601894e-1, -1.600197e-2, 1.7300105e-3, -1.1061144e-4),
    vec4<f32>(1.0079049e-5, -8.684125e-7, 8.26543e-8, -7.7986275e-9),
    vec4<f32>(9.10188e-1, -1.014341e-2, 1.2541759e-3, -5.498795e-5),
    vec4<f32>(4.7320996e-6, -3.095109e-7, 2.5183692e-8, -1.8972703e-9),
    vec4<f32>(8.945452e-1, -5.6558223e-3, 1.0179977e-3, -2.6360902e-5),
    vec4<f32>(2.7362382e-6, -1.1889169e-7, 9.967572e-9, -5.541012e-10),
    vec4<f32>(8.871352e-1, -1.8204233e-3, 9.180593e-4, -7.889442e-6),
    vec4<f32>(2.0247833e-6, -3.1811947e-8, 5.627185e-9, -1.276832e-10),
);

// erfinv(v)/v as a function of w = −ln(1 − v²) on [2^4, 2^7) (fit error 4.0e-8 relative).
const MS_BK_ERFINV_W_K0: i32 = 4;
const MS_BK_ERFINV_W_K1: i32 = 7;
var<private> MS_BK_ERFINV_W: array<vec4<f32>, 24> = array<vec4<f32>, 24>(
    vec4<f32>(4.0847907e0, 2.3805167e-1, -6.5722e-3, 3.5707987e-4),
    vec4<f32>(-2.402215e-5, 1.7950236e-6, -1.4368759e-7, 1.15537375e-8),
    vec4<f32>(4.537127e0, 2.1539979e-1, -4.890394e-3, 2.1908246e-4),
    vec4<f32>(-1.21752e-5, 7.5388596e-7, -5.0288303e-8, 3.464292e-9),
    vec4<f32>(4.9499445e0, 1.9812965e-1, -3.817813e-3, 1.4543012e-4),
    vec4<f32>(-6.8792533e-6, 3.6283808e-7, -2.0583688e-8, 1.2122374e-9),
    vec4<f32>(5.331996e0, 1.8440899e-1, -3.0855183e-3, 1.0220255e-4),
    vec4<f32>(-4.207019e-6, 1.9318979e-7, -9.5291295e-9, 4.892762e-10),
    vec4<f32>(5.8599133e0, 3.3653504e-1, -9.400734e-3, 5.206732e-4),
    vec4<f32>(-3.5867182e-5, 2.757981e-6, -2.3015748e-7, 1.9792743e-8),
    vec4<f32>(6.4990478e0, 3.0421674e-1, -6.9607254e-3, 3.162562e-4),
    vec4<f32>(-1.788632e-5, 1.1297641e-6, -7.708788e-8, 5.4481575e-9),
    vec4<f32>(7.081914e0, 2.7967435e-1, -5.4173684e-3, 2.0858926e-4),
    vec4<f32>(-1.00035295e-5, 5.3599996e-7, -3.094365e-8, 1.8562574e-9),
    vec4<f32>(7.621117e0, 2.6022553e-1, -4.3693497e-3, 1.4594554e-4),
    vec4<f32>(-6.0745874e-6, 2.825655e-7, -1.4139069e-8, 7.3704953e-10),
    vec4<f32>(8.365978e0, 4.7478202e-1, -1.32863475e-2, 7.4028183e-4),
    vec4<f32>(-5.14196e-5, 3.9930333e-6, -3.3704123e-7, 2.9332409e-8),
    vec4<f32>(9.267606e0, 4.2914096e-1, -9.823337e-3, 4.4806645e-4),
    vec4<f32>(-2.5490534e-5, 1.6217386e-6, -1.1159105e-7, 7.958128e-9),
    vec4<f32>(1.0089817e1, 3.9452025e-1, -7.639068e-3, 2.9490137e-4),
    vec4<f32>(-1.4204039e-5, 7.652497e-7, -4.4464695e-8, 2.686253e-9),
    vec4<f32>(1.0850455e1, 3.6710206e-1, -6.1583975e-3, 2.0605928e-4),
    vec4<f32>(-8.604421e-6, 4.0195354e-7, -2.0215943e-8, 1.0598242e-9),
);

// erfinv(2u − 1) at u = 2^−1074, where the Rust samplers clamp u = 0.
const MS_BK_QUANTILE_EDGE: f32 = -2.7200563e1;

// microsurface WGSL library: Beckmann, anisotropic (beckmann.wgsl).
//
// The Rust `Microfacet<f32, Beckmann>` (crates/microsurface/src/fast/beckmann.rs, the
// `Shape for Beckmann` of distribution/microfacet.rs), in f32 throughout. The Rust f32 path
// evaluates Λ and the samplers in f64 and rounds once; here the same formulas run in f32,
// arranged so that nothing cancels, with the special functions from the tables of
// beckmann_tables.wgsl (generated from the Rust f64 functions):
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

// One segment of an octave table (beckmann_tables.wgsl) at x ∈ [2^k0, 2^k1): its first row
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
    return ms_bk_poly(MS_BK_ERFCX[i], MS_BK_ERFCX[i + 1u], g.y);
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
    return ms_bk_poly(MS_BK_ERFC_RATIO[i], MS_BK_ERFC_RATIO[i + 1u], g.y);
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
        ratio = ms_bk_poly(MS_BK_ERFINV_Q[i], MS_BK_ERFINV_Q[i + 1u], g.y);
    } else {
        // (2 − q rounds to 2; w within the table up to q = 2^−126 and held inside below.)
        let w = min(-log(q) - log(2.0), 127.99);
        let g = ms_bk_segment(w, MS_BK_ERFINV_W_K0, MS_BK_ERFINV_W_K1);
        let i = 2u * u32(g.x);
        ratio = ms_bk_poly(MS_BK_ERFINV_W[i], MS_BK_ERFINV_W[i + 1u], g.y);
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

// microsurface WGSL library: the tables of Double GGX and the Exponential NDF
// (family_tables.wgsl). Generated by crates/microsurface-gpu/tools/family_tables.rs
// (examples/translate.rs) from the Rust tables of microsurface::fast::tables; do not
// edit. Octave tables as fast::fit's: x ∈ [2^K0, 2^K1), 2^M segments per octave, each
// row the polynomial in s ∈ [−1, 1) of one segment (s⁰ first, zero-padded to vec4).

// Double GGX Λ(x), x = α² tan²θ/2: the Rust DGGX32 (f32 cubics), bit for bit.
const MS_DG_LAMBDA_K0: i32 = -30;
const MS_DG_LAMBDA_K1: i32 = 16;
const MS_DG_LAMBDA_M: u32 = 3u;
var<private> MS_DG_LAMBDA: array<vec4<f32>, 368> = array<vec4<f32>, 368>(
    vec4<f32>(1.08104805e-8, 6.0680677e-10, -8.5648925e-13, 1.6801664e-14),
    vec4<f32>(1.2020797e-8, 6.035697e-10, -7.662442e-13, 1.3447851e-14),
    vec4<f32>(1.3224975e-8, 6.0065686e-10, -6.932104e-13, 1.100667e-14),
    vec4<f32>(1.4423601e-8, 5.9800925e-10, -6.328914e-13, 9.174653e-15),
    vec4<f32>(1.561716e-8, 5.955825e-10, -5.822319e-13, 7.764749e-15),
    vec4<f32>(1.6806055e-8, 5.9334265e-10, -5.390831e-13, 6.6565647e-15),
    vec4<f32>(1.7990637e-8, 5.912629e-10, -5.0188965e-13, 5.769762e-15),
    vec4<f32>(1.91712e-8, 5.89322e-10, -4.6949803e-13, 5.049067e-15),
    vec4<f32>(2.093507e-8, 1.173267e-9, -1.7129785e-12, 3.360333e-14),
    vec4<f32>(2.327501e-8, 1.1667929e-9, -1.5324883e-12, 2.6895702e-14),
    vec4<f32>(2.5602674e-8, 1.1609673e-9, -1.3864208e-12, 2.201334e-14),
    vec4<f32>(2.7919233e-8, 1.155672e-9, -1.2657828e-12, 1.8349305e-14),
    vec4<f32>(3.0225657e-8, 1.1508186e-9, -1.1644638e-12, 1.5529499e-14),
    vec4<f32>(3.2522756e-8, 1.1463389e-9, -1.0781661e-12, 1.3313129e-14),
    vec4<f32>(3.4811226e-8, 1.1421794e-9, -1.0037793e-12, 1.1539524e-14),
    vec4<f32>(3.709166e-8, 1.1382975e-9, -9.389961e-13, 1.0098134e-14),
    vec4<f32>(4.049836e-8, 2.2658413e-9, -3.4259568e-12, 6.720666e-14),
    vec4<f32>(4.5016854e-8, 2.2528928e-9, -3.0649767e-12, 5.3791403e-14),
    vec4<f32>(4.9510795e-8, 2.2412416e-9, -2.7728414e-12, 4.402668e-14),
    vec4<f32>(5.398253e-8, 2.2306512e-9, -2.5315655e-12, 3.669861e-14),
    vec4<f32>(5.843399e-8, 2.2209443e-9, -2.3289274e-12, 3.1058997e-14),
    vec4<f32>(6.28668e-8, 2.2119848e-9, -2.1563322e-12, 2.6626259e-14),
    vec4<f32>(6.728236e-8, 2.203666e-9, -2.0075584e-12, 2.3079046e-14),
    vec4<f32>(7.168184e-8, 2.195902e-9, -1.877992e-12, 2.0196267e-14),
    vec4<f32>(7.8253166e-8, 4.3702966e-9, -6.851913e-12, 1.3441331e-13),
    vec4<f32>(8.696738e-8, 4.3444e-9, -6.129953e-12, 1.07582807e-13),
    vec4<f32>(9.563249e-8, 4.3210973e-9, -5.5456824e-12, 8.805336e-14),
    vec4<f32>(1.0425318e-7, 4.2999164e-9, -5.0631305e-12, 7.339722e-14),
    vec4<f32>(1.1283333e-7, 4.2805026e-9, -4.6578544e-12, 6.2117995e-14),
    vec4<f32>(1.2137619e-7, 4.2625836e-9, -4.312664e-12, 5.3252518e-14),
    vec4<f32>(1.2988451e-7, 4.245946e-9, -4.0151164e-12, 4.615809e-14),
    vec4<f32>(1.383607e-7, 4.2304182e-9, -3.7559834e-12, 4.0392535e-14),
    vec4<f32>(1.5101921e-7, 8.417821e-9, -1.37038245e-11, 2.6882663e-13),
    vec4<f32>(1.678021e-7, 8.366028e-9, -1.2259904e-11, 2.151656e-13),
    vec4<f32>(1.8448677e-7, 8.319423e-9, -1.1091363e-11, 1.7610671e-13),
    vec4<f32>(2.0108261e-7, 8.277061e-9, -1.0126259e-11, 1.4679444e-13),
    vec4<f32>(2.1759736e-7, 8.238233e-9, -9.315707e-12, 1.2423599e-13),
    vec4<f32>(2.3403753e-7, 8.202395e-9, -8.625326e-12, 1.06505035e-13),
    vec4<f32>(2.5040865e-7, 8.16912e-9, -8.030231e-12, 9.231618e-14),
    vec4<f32>(2.667155e-7, 8.1380644e-9, -7.511965e-12, 8.078507e-14),
    vec4<f32>(2.9106417e-7, 1.61901e-8, -2.7407642e-11, 5.3765326e-13),
    vec4<f32>(3.2333887e-7, 1.6086512e-8, -2.4519801e-11, 4.303312e-13),
    vec4<f32>(3.5541711e-7, 1.5993303e-8, -2.218272e-11, 3.522134e-13),
    vec4<f32>(3.8731773e-7, 1.590858e-8, -2.0252511e-11, 2.9358888e-13),
    vec4<f32>(4.1905614e-7, 1.5830924e-8, -1.8631407e-11, 2.4847195e-13),
    vec4<f32>(4.506454e-7, 1.5759248e-8, -1.7250645e-11, 2.1301006e-13),
    vec4<f32>(4.8209654e-7, 1.5692697e-8, -1.6060455e-11, 1.8463237e-13),
    vec4<f32>(5.1341914e-7, 1.5630585e-8, -1.5023925e-11, 1.6157013e-13),
    vec4<f32>(5.601799e-7, 3.108911e-8, -5.481526e-11, 1.0753064e-12),
    vec4<f32>(6.2214707e-7, 3.088194e-8, -4.9039574e-11, 8.606624e-13),
    vec4<f32>(6.8372145e-7, 3.069552e-8, -4.4365414e-11, 7.044268e-13),
    vec4<f32>(7.4494045e-7, 3.052607e-8, -4.0505e-11, 5.871777e-13),
    vec4<f32>(8.058351e-7, 3.037076e-8, -3.726279e-11, 4.969439e-13),
    vec4<f32>(8.6643144e-7, 3.022741e-8, -3.4501266e-11, 4.260201e-13),
    vec4<f32>(9.2675157e-7, 3.009431e-8, -3.2120886e-11, 3.692647e-13),
    vec4<f32>(9.868146e-7, 2.9970085e-8, -3.0047822e-11, 3.2314025e-13),
    vec4<f32>(1.0764628e-6, 5.9596054e-8, -1.09630416e-10, 2.1506128e-12),
    vec4<f32>(1.1952329e-6, 5.918171e-8, -9.807905e-11, 1.7213246e-12),
    vec4<f32>(1.3132172e-6, 5.880887e-8, -8.873073e-11, 1.4088535e-12),
    vec4<f32>(1.4304909e-6, 5.8469972e-8, -8.10099e-11, 1.1743554e-12),
    vec4<f32>(1.547116e-6, 5.8159355e-8, -7.452548e-11, 9.938877e-13),
    vec4<f32>(1.6631443e-6, 5.787265e-8, -6.9002436e-11, 8.520401e-13),
    vec4<f32>(1.7786202e-6, 5.7606446e-8, -6.4241674e-11, 7.3852935e-13),
    vec4<f32>(1.893582e-6, 5.7358005e-8, -6.0095554e-11, 6.462804e-13),
    vec4<f32>(2.0651319e-6, 1.1402777e-7, -2.1926046e-10, 4.3012247e-12),
    vec4<f32>(2.2923432e-6, 1.1319908e-7, -1.9615773e-10, 3.4426487e-12),
    vec4<f32>(2.5179834e-6, 1.1245341e-7, -1.7746109e-10, 2.8177066e-12),
    vec4<f32>(2.742202e-6, 1.1177561e-7, -1.6201943e-10, 2.3487104e-12),
    vec4<f32>(2.9651235e-6, 1.1115438e-7, -1.4905059e-10, 1.987775e-12),
    vec4<f32>(3.1868515e-6, 1.1058098e-7, -1.3800451e-10, 1.7040799e-12),
    vec4<f32>(3.4074747e-6, 1.1004857e-7, -1.2848299e-10, 1.4770584e-12),
    vec4<f32>(3.6270694e-6, 1.09551685e-7, -1.2019075e-10, 1.2925606e-12),
    vec4<f32>(3.9546762e-6, 2.177269e-7, -4.3851947e-10, 8.602448e-12),
    vec4<f32>(4.388442e-6, 2.1606952e-7, -3.9231404e-10, 6.8852957e-12),
    vec4<f32>(4.8190645e-6, 2.1457818e-7, -3.5492076e-10, 5.6354114e-12),
    vec4<f32>(5.246845e-6, 2.132226e-7, -3.2403746e-10, 4.697419e-12),
    vec4<f32>(5.6720305e-6, 2.1198014e-7, -2.980998e-10, 3.9755486e-12),
    vec4<f32>(6.094829e-6, 2.1083333e-7, -2.7600763e-10, 3.4081583e-12),
    vec4<f32>(6.515418e-6, 2.0976853e-7, -2.5696462e-10, 2.9541155e-12),
    vec4<f32>(6.9339508e-6, 2.0877475e-7, -2.403801e-10, 2.5851198e-12),
    vec4<f32>(7.5581784e-6, 4.147966e-7, -8.7703356e-10, 1.7204887e-11),
    vec4<f32>(8.384395e-6, 4.1148186e-7, -7.846227e-10, 1.3770584e-11),
    vec4<f32>(9.2043265e-6, 4.084992e-7, -7.098362e-10, 1.1270816e-11),
    vec4<f32>(1.00185725e-5, 4.057881e-7, -6.480696e-10, 9.394832e-12),
    vec4<f32>(1.082763e-5, 4.0330315e-7, -5.9619437e-10, 7.951091e-12),
    vec4<f32>(1.1631913e-5, 4.0100957e-7, -5.5201005e-10, 6.8163114e-12),
    vec4<f32>(1.2431778e-5, 3.9888e-7, -5.13924e-10, 5.9082257e-12),
    vec4<f32>(1.3227527e-5, 3.9689246e-7, -4.8075505e-10, 5.170235e-12),
    vec4<f32>(1.4414012e-5, 7.882792e-7, -1.7540466e-9, 3.440974e-11),
    vec4<f32>(1.5983818e-5, 7.816498e-7, -1.5692251e-9, 2.7541136e-11),
    vec4<f32>(1.7541053e-5, 7.756845e-7, -1.4196523e-9, 2.2541602e-11),
    vec4<f32>(1.9086918e-5, 7.702624e-7, -1.2961193e-9, 1.8789638e-11),
    vec4<f32>(2.0622403e-5, 7.652926e-7, -1.1923689e-9, 1.590216e-11),
    vec4<f32>(2.2148342e-5, 7.607055e-7, -1.1040004e-9, 1.3632601e-11),
    vec4<f32>(2.3665443e-5, 7.564464e-7, -1.0278285e-9, 1.1816431e-11),
    vec4<f32>(2.5174319e-5, 7.5247146e-7, -9.614908e-10, 1.0340451e-11),
    vec4<f32>(2.7423346e-5, 1.4939317e-6, -3.508016e-9, 6.881934e-11),
    vec4<f32>(3.0397705e-5, 1.4806732e-6, -3.138374e-9, 5.5082147e-11),
    vec4<f32>(3.334692e-5, 1.4687429e-6, -2.839229e-9, 4.5083094e-11),
    vec4<f32>(3.62734e-5, 1.4578989e-6, -2.5921638e-9, 3.7579172e-11),
    vec4<f32>(3.917912e-5, 1.4479597e-6, -2.3846636e-9, 3.1804222e-11),
    vec4<f32>(4.206575e-5, 1.4387858e-6, -2.2079272e-9, 2.7265114e-11),
    vec4<f32>(4.49347e-5, 1.4302678e-6, -2.0555837e-9, 2.363278e-11),
    vec4<f32>(4.7787198e-5, 1.4223183e-6, -1.9229087e-9, 2.0680825e-11),
    vec4<f32>(5.2037383e-5, 2.8226148e-6, -7.015744e-9, 1.3763812e-10),
    vec4<f32>(5.7655605e-5, 2.7960991e-6, -6.276463e-9, 1.10163795e-10),
    vec4<f32>(6.3223546e-5, 2.7722397e-6, -5.6781757e-9, 9.0165736e-11),
    vec4<f32>(6.874601e-5, 2.7505528e-6, -5.184048e-9, 7.5157935e-11),
    vec4<f32>(7.422696e-5, 2.7306755e-6, -4.7690496e-9, 6.360807e-11),
    vec4<f32>(7.966973e-5, 2.712329e-6, -4.415579e-9, 5.4529877e-11),
    vec4<f32>(8.5077154e-5, 2.6952941e-6, -4.1108943e-9, 4.7265233e-11),
    vec4<f32>(9.0451664e-5, 2.679396e-6, -3.845546e-9, 4.1361345e-11),
    vec4<f32>(9.8456316e-5, 5.314752e-6, -1.4030413e-8, 2.75274e-10),
    vec4<f32>(1.0903181e-4, 5.2617247e-6, -1.25518635e-8, 2.2032559e-10),
    vec4<f32>(1.19506745e-4, 5.21401e-6, -1.1355301e-8, 1.8032967e-10),
    vec4<f32>(1.2989074e-4, 5.17064e-6, -1.0367055e-8, 1.5031422e-10),
    vec4<f32>(1.4019171e-4, 5.13089e-6, -9.537068e-9, 1.2721461e-10),
    vec4<f32>(1.5041634e-4, 5.094201e-6, -8.830136e-9, 1.0905835e-10),
    vec4<f32>(1.6057027e-4, 5.060135e-6, -8.220775e-9, 9.452916e-11),
    vec4<f32>(1.7065839e-4, 5.028343e-6, -7.690086e-9, 8.272147e-11),
    vec4<f32>(1.8567636e-4, 9.968618e-6, -2.8056842e-8, 5.505391e-10),
    vec4<f32>(2.0550558e-4, 9.862579e-6, -2.5099794e-8, 4.4064322e-10),
    vec4<f32>(2.2513374e-4, 9.7671655e-6, -2.2706715e-8, 3.6065212e-10),
    vec4<f32>(2.4458003e-4, 9.6804415e-6, -2.0730264e-8, 3.0062186e-10),
    vec4<f32>(2.6386033e-4, 9.600956e-6, -1.9070328e-8, 2.5442318e-10),
    vec4<f32>(2.8298792e-4, 9.527593e-6, -1.7656498e-8, 2.1811108e-10),
    vec4<f32>(3.0197419e-4, 9.459477e-6, -1.6437808e-8, 1.890531e-10),
    vec4<f32>(3.2082887e-4, 9.395908e-6, -1.5376461e-8, 1.6543805e-10),
    vec4<f32>(3.488825e-4, 1.8615723e-5, -5.6099008e-8, 1.1010426e-9),
    vec4<f32>(3.85898e-4, 1.8403704e-5, -5.0185115e-8, 8.8125457e-10),
    vec4<f32>(4.2251145e-4, 1.8212935e-5, -4.5399137e-8, 7.212754e-10),
    vec4<f32>(4.587613e-4, 1.8039544e-5, -4.1446402e-8, 6.0121735e-10),
    vec4<f32>(4.9467926e-4, 1.7880628e-5, -3.8126682e-8, 5.0882215e-10),
    vec4<f32>(5.3029193e-4, 1.7733959e-5, -3.5299163e-8, 4.3619977e-10),
    vec4<f32>(5.6562206e-4, 1.7597782e-5, -3.2861912e-8, 3.7808534e-10),
    vec4<f32>(6.0068915e-4, 1.7470697e-5, -3.0739336e-8, 3.308566e-10),
    vec4<f32>(6.5283314e-4, 3.458937e-5, -1.12144356e-7, 2.2019426e-9),
    vec4<f32>(7.215802e-4, 3.4165547e-5, -1.0031737e-7, 1.7623817e-9),
    vec4<f32>(7.895236e-4, 3.3784218e-5, -9.074614e-8, 1.4424356e-9),
    vec4<f32>(8.567402e-4, 3.3437642e-5, -8.284133e-8, 1.2023296e-9),
    vec4<f32>(9.232934e-4, 3.3120017e-5, -7.62025e-8, 1.0175476e-9),
    vec4<f32>(9.892365e-4, 3.282688e-5, -7.054801e-8, 8.7231e-10),
    vec4<f32>(1.0546149e-3, 3.2554726e-5, -6.567403e-8, 7.560873e-10),
    vec4<f32>(1.1194675e-3, 3.2300755e-5, -6.142937e-8, 6.616352e-10),
    vec4<f32>(1.2158342e-3, 6.389805e-5, -2.2409415e-7, 4.403317e-9),
    vec4<f32>(1.3427676e-3, 6.305117e-5, -2.0044341e-7, 3.524255e-9),
    vec4<f32>(1.4680953e-3, 6.228928e-5, -1.8130385e-7, 2.8844114e-9),
    vec4<f32>(1.5919709e-3, 6.1596875e-5, -1.6549687e-7, 2.4042395e-9),
    vec4<f32>(1.7145213e-3, 6.096236e-5, -1.5222162e-7, 2.0347093e-9),
    vec4<f32>(1.835853e-3, 6.0376813e-5, -1.4091488e-7, 1.7442628e-9),
    vec4<f32>(1.9560566e-3, 5.9833226e-5, -1.3116897e-7, 1.5118422e-9),
    vec4<f32>(2.0752102e-3, 5.9325997e-5, -1.2268158e-7, 1.3229596e-9),
    vec4<f32>(2.2521182e-3, 1.1724719e-4, -4.4749032e-7, 8.804367e-9),
    vec4<f32>(2.4848902e-3, 1.1555619e-4, -4.0020169e-7, 7.0464834e-9),
    vec4<f32>(2.714456e-3, 1.14035116e-4, -3.6193416e-7, 5.7669904e-9),
    vec4<f32>(2.9411232e-3, 1.1265299e-4, -3.3033066e-7, 4.8068074e-9),
    vec4<f32>(3.1651452e-3, 1.11386595e-4, -3.037898e-7, 4.0678816e-9),
    vec4<f32>(3.3867348e-3, 1.102181e-4, -2.8118515e-7, 3.4871037e-9),
    vec4<f32>(3.6060733e-3, 1.09133485e-4, -2.6170162e-7, 3.0223615e-9),
    vec4<f32>(3.8233171e-3, 1.0812155e-4, -2.4473448e-7, 2.6446825e-9),
    vec4<f32>(4.1455477e-3, 2.1344097e-4, -8.925083e-7, 1.759972e-8),
    vec4<f32>(4.5689945e-3, 2.1006877e-4, -7.979822e-7, 1.4084913e-8),
    vec4<f32>(4.9860487e-3, 2.0703621e-4, -7.21493e-7, 1.1526703e-8),
    vec4<f32>(5.397324e-3, 2.0428137e-4, -6.5832774e-7, 9.606978e-9),
    vec4<f32>(5.803328e-3, 2.0175784e-4, -6.0528413e-7, 8.129665e-9),
    vec4<f32>(6.204486e-3, 1.9942995e-4, -5.601101e-7, 6.9685675e-9),
    vec4<f32>(6.6011595e-3, 1.972697e-4, -5.211756e-7, 6.0394783e-9),
    vec4<f32>(6.993661e-3, 1.9525469e-4, -4.8727173e-7, 5.284464e-9),
    vec4<f32>(7.575177e-3, 3.8493125e-4, -1.7763956e-6, 3.5163744e-8),
    vec4<f32>(8.338204e-3, 3.782209e-4, -1.5875456e-6, 2.8137958e-8),
    vec4<f32>(9.088512e-3, 3.721891e-4, -1.4347489e-6, 2.3024638e-8),
    vec4<f32>(9.827329e-3, 3.6671202e-4, -1.3085831e-6, 1.9187745e-8),
    vec4<f32>(1.0555668e-2, 3.6169693e-4, -1.2026466e-6, 1.6235266e-8),
    vec4<f32>(1.1274377e-2, 3.5707257e-4, -1.1124372e-6, 1.3914898e-8),
    vec4<f32>(1.1984181e-2, 3.5278292e-4, -1.0346969e-6, 1.2058295e-8),
    vec4<f32>(1.2685701e-2, 3.4878327e-4, -9.67009e-7, 1.0549637e-8),
    vec4<f32>(1.3723622e-2, 6.864997e-4, -3.5233136e-6, 7.018714e-8),
    vec4<f32>(1.5083066e-2, 6.731953e-4, -3.1464085e-6, 5.6150814e-8),
    vec4<f32>(1.6417304e-2, 6.612449e-4, -2.8415275e-6, 4.59365e-8),
    vec4<f32>(1.7728783e-2, 6.5040134e-4, -2.5898412e-6, 3.8272887e-8),
    vec4<f32>(1.9019522e-2, 6.4047927e-4, -2.3785574e-6, 3.2376462e-8),
    vec4<f32>(2.0291219e-2, 6.3133636e-4, -2.198681e-6, 2.7742988e-8),
    vec4<f32>(2.1545311e-2, 6.2286085e-4, -2.043702e-6, 2.4036035e-8),
    vec4<f32>(2.2783047e-2, 6.149634e-4, -1.9087927e-6, 2.102416e-8),
    vec4<f32>(2.4611302e-2, 1.2080917e-3, -6.9482953e-6, 1.3982884e-7),
    vec4<f32>(2.7000764e-2, 1.18187e-3, -6.19757e-6, 1.1181662e-7),
    vec4<f32>(2.9340576e-2, 1.1583447e-3, -5.5905675e-6, 9.1436796e-8),
    vec4<f32>(3.163561e-2, 1.1370223e-3, -5.0896883e-6, 7.614981e-8),
    vec4<f32>(3.3889886e-2, 1.1175335e-3, -4.6693926e-6, 6.439069e-8),
    vec4<f32>(3.6106776e-2, 1.0995944e-3, -4.311725e-6, 5.515242e-8),
    vec4<f32>(3.828915e-2, 1.082982e-3, -4.0036925e-6, 4.776318e-8),
    vec4<f32>(4.0439468e-2, 1.0675183e-3, -3.7356622e-6, 4.1760877e-8),
    vec4<f32>(4.3609485e-2, 2.0923347e-3, -1.3578713e-5, 2.7757648e-7),
    vec4<f32>(4.774197e-2, 2.0411385e-3, -1.2089014e-5, 2.2178959e-7),
    vec4<f32>(5.1777598e-2, 1.9952909e-3, -1.0885477e-5, 1.812215e-7),
    vec4<f32>(5.5726036e-2, 1.9538095e-3, -9.893145e-6, 1.5080514e-7),
    vec4<f32>(5.959525e-2, 1.9159595e-3, -9.061116e-6, 1.2741879e-7),
    vec4<f32>(6.339192e-2, 1.8811759e-3, -8.3536115e-6, 1.0905419e-7),
    vec4<f32>(6.71217e-2, 1.8490158e-3, -7.744756e-6, 9.437186e-8),
    vec4<f32>(7.078949e-2, 1.8191254e-3, -7.2153666e-6, 8.245069e-8),
    vec4<f32>(7.6184064e-2, 3.5558625e-3, -2.6170086e-5, 5.4743236e-7),
    vec4<f32>(8.319531e-2, 3.4573302e-3, -2.3234155e-5, 4.3677838e-7),
    vec4<f32>(9.002039e-2, 3.3693316e-3, -2.0865602e-5, 3.5638158e-7),
    vec4<f32>(9.667835e-2, 3.28992e-3, -1.8915434e-5, 2.9615543e-7),
    vec4<f32>(1.0318482e-1, 3.2176396e-3, -1.7282546e-5, 2.4988884e-7),
    vec4<f32>(1.09552905e-1, 3.1513735e-3, -1.5895916e-5, 2.1358788e-7),
    vec4<f32>(1.15793735e-1, 3.0902456e-3, -1.4704203e-5, 1.8458998e-7),
    vec4<f32>(1.21916845e-1, 3.0335572e-3, -1.3669374e-5, 1.6106502e-7),
    vec4<f32>(1.3089867e-1, 5.911274e-3, -4.9425e-5, 1.0673878e-6),
    vec4<f32>(1.425317e-1, 5.7255533e-3, -4.3707227e-5, 8.495504e-7),
    vec4<f32>(1.5381451e-1, 5.5603227e-3, -3.9105566e-5, 6.915318e-7),
    vec4<f32>(1.6478407e-1, 5.4117553e-3, -3.5325626e-5, 5.733445e-7),
    vec4<f32>(1.7547072e-1, 5.276995e-3, -3.2167856e-5, 4.8269163e-7),
    vec4<f32>(1.8589978e-1, 5.153852e-3, -2.9492245e-5, 4.1167314e-7),
    vec4<f32>(1.9609272e-1, 5.040614e-3, -2.719769e-5, 3.5502705e-7),
    vec4<f32>(2.0606792e-1, 4.9359147e-3, -2.5209387e-5, 3.0913975e-7),
    vec4<f32>(2.2065678e-1, 9.585025e-3, -9.077162e-5, 2.0425605e-6),
    vec4<f32>(2.394794e-1, 9.244838e-3, -7.985033e-5, 1.6194352e-6),
    vec4<f32>(2.5766212e-1, 8.943713e-3, -7.109417e-5, 1.313349e-6),
    vec4<f32>(2.752753e-1, 8.67424e-3, -6.392768e-5, 1.0850314e-6),
    vec4<f32>(2.9237646e-1, 8.430898e-3, -5.7961613e-5, 9.103631e-7),
    vec4<f32>(3.090135e-1, 8.209469e-3, -5.292344e-5, 7.738741e-7),
    vec4<f32>(3.2522672e-1, 8.006659e-3, -4.8616737e-5, 6.652771e-7),
    vec4<f32>(3.4105077e-1, 7.819853e-3, -4.489647e-5, 5.7751885e-7),
    vec4<f32>(3.641212e-1, 1.51302535e-2, -1.6082333e-4, 3.7991404e-6),
    vec4<f32>(3.9376748e-1, 1.4529486e-2, -1.4056418e-4, 2.9954115e-6),
    vec4<f32>(4.222872e-1, 1.4000985e-2, -1.2440921e-4, 2.4165456e-6),
    vec4<f32>(4.4981015e-1, 1.3530731e-2, -1.11254616e-4, 1.9865672e-6),
    vec4<f32>(4.7644195e-1, 1.3108328e-2, -1.0035639e-4, 1.6589489e-6),
    vec4<f32>(5.0227004e-1, 1.2725862e-2, -9.119533e-5, 1.4039338e-6),
    vec4<f32>(5.273679e-1, 1.2377179e-2, -8.339851e-5, 1.201789e-6),
    vec4<f32>(5.5179805e-1, 1.2057406e-2, -7.66914e-5, 1.0390216e-6),
    vec4<f32>(5.8730686e-1, 2.3247147e-2, -2.731088e-4, 6.795988e-6),
    vec4<f32>(6.3276064e-1, 2.2230627e-2, -2.3699379e-4, 5.3199788e-6),
    vec4<f32>(6.763147e-1, 2.1342492e-2, -2.0839374e-4, 4.2635293e-6),
    vec4<f32>(7.1819896e-1, 2.0557145e-2, -1.8525429e-4, 3.4833931e-6),
    vec4<f32>(7.5859916e-1, 1.9855717e-2, -1.6619792e-4, 2.8922548e-6),
    vec4<f32>(7.9766816e-1, 1.9223928e-2, -1.5026816e-4, 2.43452e-6),
    vec4<f32>(8.3553386e-1, 1.8650731e-2, -1.3678128e-4, 2.0734806e-6),
    vec4<f32>(8.723043e-1, 1.8127419e-2, -1.2523626e-4, 1.7841386e-6),
    vec4<f32>(9.256055e-1, 3.4842193e-2, -4.433474e-4, 1.1592821e-5),
    vec4<f32>(9.936049e-1, 3.3198003e-2, -3.819814e-4, 9.001887e-6),
    vec4<f32>(1.0585419e0, 3.177112e-2, -3.3375886e-4, 7.161684e-6),
    vec4<f32>(1.1208042e0, 3.0516941e-2, -2.9501598e-4, 5.8123924e-6),
    vec4<f32>(1.1807029e0, 2.940282e-2, -2.6331292e-4, 4.796665e-6),
    vec4<f32>(1.2384924e0, 2.8404215e-2, -2.3696655e-4, 4.0149307e-6),
    vec4<f32>(1.2943841e0, 2.7502252e-2, -2.1478084e-4, 3.40182e-6),
    vec4<f32>(1.3485559e0, 2.6682144e-2, -1.9588433e-4, 2.9130604e-6),
    vec4<f32>(1.4269143e0, 5.116063e-2, -6.898112e-4, 1.8804556e-5),
    vec4<f32>(1.5266197e0, 4.861049e-2, -5.9064786e-4, 1.44875985e-5),
    vec4<f32>(1.6215888e0, 4.6410188e-2, -5.132998e-4, 1.1446311e-5),
    vec4<f32>(1.712444e0, 4.448599e-2, -4.515643e-4, 9.2325445e-6),
    vec4<f32>(1.7996808e0, 4.2784315e-2, -4.013426e-4, 7.576994e-6),
    vec4<f32>(1.8837026e0, 4.1265137e-2, -3.598268e-4, 6.3104353e-6),
    vec4<f32>(1.9648426e0, 3.9897885e-2, -3.2503434e-4, 5.3224962e-6),
    vec4<f32>(2.0433795e0, 3.8658716e-2, -2.9552908e-4, 4.538873e-6),
    vec4<f32>(2.1568127e0, 7.399966e-2, -1.0364982e-3, 2.9137233e-5),
    vec4<f32>(2.3008876e0, 7.017706e-2, -8.8333135e-4, 2.2302554e-5),
    vec4<f32>(2.4378788e0, 6.689317e-2, -7.645847e-4, 1.7522107e-5),
    vec4<f32>(2.5687413e0, 6.4032026e-2, -6.70305e-4, 1.4064265e-5),
    vec4<f32>(2.6942325e0, 6.150992e-2, -5.9396157e-4, 1.1492692e-5),
    vec4<f32>(2.8149652e0, 5.9264667e-2, -5.311088e-4, 9.535065e-6),
    vec4<f32>(2.931444e0, 5.7249e-2, -4.7862553e-4, 8.014847e-6),
    vec4<f32>(3.0440898e0, 5.542622e-2, -4.3426236e-4, 6.813847e-6),
    vec4<f32>(3.206635e0, 1.05983995e-1, -1.5189003e-3, 4.356501e-5),
    vec4<f32>(3.4128585e0, 1.00391276e-1, -1.2904061e-3, 3.3191744e-5),
    vec4<f32>(3.6087332e0, 9.560045e-2, -1.1140187e-3, 2.5975389e-5),
    vec4<f32>(3.7956772e0, 9.143642e-2, -9.7448385e-4, 2.0779657e-5),
    vec4<f32>(3.974812e0, 8.7773375e-2, -8.618482e-4, 1.693105e-5),
    vec4<f32>(4.1470423e0, 8.451823e-2, -7.693686e-4, 1.4011501e-5),
    vec4<f32>(4.3131094e0, 8.160048e-2, -6.923307e-4, 1.1751274e-5),
    vec4<f32>(4.4736323e0, 7.8965575e-2, -6.273496e-4, 9.970542e-6),
    vec4<f32>(4.705139e0, 1.50904e-1, -2.1906106e-3, 6.3583626e-5),
    vec4<f32>(4.9986672e0, 1.4284573e-1, -1.8575933e-3, 4.8302976e-5),
    vec4<f32>(5.2772975e0, 1.359546e-1, -1.6012046e-3, 3.7710044e-5),
    vec4<f32>(5.543091e0, 1.2997352e-1, -1.3988354e-3, 3.010568e-5),
    vec4<f32>(5.797674e0, 1.247183e-1, -1.2357878e-3, 2.44871e-5),
    vec4<f32>(6.0423565e0, 1.2005308e-1, -1.102135e-3, 2.0234087e-5),
    vec4<f32>(6.2782106e0, 1.1587511e-1, -9.909563e-4, 1.6947752e-5),
    vec4<f32>(6.506129e0, 1.1210507e-1, -8.972937e-4, 1.4362898e-5),
    vec4<f32>(6.834737e0, 2.1416405e-1, -3.1303046e-3, 9.145801e-5),
    vec4<f32>(7.2512383e0, 2.0265523e-1, -2.6516847e-3, 6.9363006e-5),
    vec4<f32>(7.6464715e0, 1.9282252e-1, -2.2837566e-3, 5.4077675e-5),
    vec4<f32>(8.0233965e0, 1.8429494e-1, -1.9937137e-3, 4.3123488e-5),
    vec4<f32>(8.384343e0, 1.7680715e-1, -1.7602745e-3, 3.5041478e-5),
    vec4<f32>(8.731187e0, 1.7016368e-1, -1.5690933e-3, 2.8931276e-5),
    vec4<f32>(9.065461e0, 1.6421692e-1, -1.4101833e-3, 2.421489e-5),
    vec4<f32>(9.388442e0, 1.5885301e-1, -1.2764002e-3, 2.0508678e-5),
    vec4<f32>(9.85404e0, 3.0341908e-1, -4.4506574e-3, 1.3048682e-4),
    vec4<f32>(1.0444066e1, 2.870605e-1, -3.76809e-3, 9.887438e-5),
    vec4<f32>(1.100387e1, 2.7309126e-1, -3.2438098e-3, 7.702943e-5),
    vec4<f32>(1.1537667e1, 2.6098114e-1, -2.8307892e-3, 6.138877e-5),
    vec4<f32>(1.2048779e1, 2.5035125e-1, -2.4985587e-3, 4.985801e-5),
    vec4<f32>(1.2539872e1, 2.4092269e-1, -2.2265993e-3, 4.11462e-5),
    vec4<f32>(1.3013129e1, 2.3248501e-1, -2.0006387e-3, 3.4425473e-5),
    vec4<f32>(1.3470364e1, 2.2487597e-1, -1.8104751e-3, 2.9146817e-5),
    vec4<f32>(1.4129445e1, 4.2948967e-1, -6.3113025e-3, 1.8536898e-4),
    vec4<f32>(1.4964586e1, 4.062956e-1, -5.3418707e-3, 1.4039507e-4),
    vec4<f32>(1.5756882e1, 3.864943e-1, -4.5975656e-3, 1.09335306e-4),
    vec4<f32>(1.6512318e1, 3.6933187e-1, -4.011416e-3, 8.71077e-5),
    vec4<f32>(1.7235607e1, 3.5426983e-1, -3.540058e-3, 7.072743e-5),
    vec4<f32>(1.793053e1, 3.40912e-1, -3.1543053e-3, 5.8355905e-5),
    vec4<f32>(1.860019e1, 3.289595e-1, -2.833866e-3, 4.8814687e-5),
    vec4<f32>(1.9247152e1, 3.1818202e-1, -2.56424e-3, 4.1322633e-5),
    vec4<f32>(2.017968e1, 6.076678e-1, -8.93776e-3, 2.6274854e-4),
    vec4<f32>(2.136126e1, 5.748239e-1, -7.563813e-3, 1.9895364e-4),
    vec4<f32>(2.248217e1, 5.46788e-1, -6.5091588e-3, 1.5490904e-4),
    vec4<f32>(2.3550898e1, 5.2249086e-1, -5.678752e-3, 1.2339673e-4),
    vec4<f32>(2.4574112e1, 5.011692e-1, -5.0110705e-3, 1.0017902e-4),
    vec4<f32>(2.555718e1, 4.8226142e-1, -4.4647176e-3, 8.264643e-5),
    vec4<f32>(2.6504482e1, 4.6534392e-1, -4.010918e-3, 6.912689e-5),
    vec4<f32>(2.7419662e1, 4.500904e-1, -3.6291145e-3, 5.8512298e-5),
    vec4<f32>(2.8738773e1, 8.5956895e-1, -1.2648595e-2, 3.7200787e-4),
    vec4<f32>(3.0410141e1, 8.130905e-1, -1.070343e-2, 2.8165118e-4),
    vec4<f32>(3.1995659e1, 7.734185e-1, -9.210467e-3, 2.1927757e-4),
    vec4<f32>(3.3507336e1, 7.390389e-1, -8.035052e-3, 1.7465708e-4),
    vec4<f32>(3.4954617e1, 7.088708e-1, -7.0900396e-3, 1.4178491e-4),
    vec4<f32>(3.634509e1, 6.8211913e-1, -6.3167997e-3, 1.1696403e-4),
    vec4<f32>(3.7684967e1, 6.5818423e-1, -5.674583e-3, 9.7825854e-5),
    vec4<f32>(3.8979393e1, 6.36604e-1, -5.13428e-3, 8.28009e-5),
    vec4<f32>(4.0845123e1, 1.2157536e0, -1.7893976e-2, 5.264004e-4),
    vec4<f32>(4.320905e1, 1.1500016e0, -1.5141601e-2, 3.985194e-4),
    vec4<f32>(4.545153e1, 1.0938805e0, -1.3029199e-2, 3.1024934e-4),
    vec4<f32>(4.758955e1, 1.0452474e0, -1.1366172e-2, 2.4710715e-4),
    vec4<f32>(4.9636482e1, 1.002573e0, -1.0029179e-2, 2.0059239e-4),
    vec4<f32>(5.1603058e1, 9.647319e-1, -8.935241e-3, 1.6547188e-4),
    vec4<f32>(5.3498062e1, 9.3087566e-1, -8.026692e-3, 1.383932e-4),
    vec4<f32>(5.532878e1, 9.0035075e-1, -7.26234e-3, 1.17135e-4),
    vec4<f32>(5.7967476e1, 1.7194339e0, -2.5310267e-2, 7.446564e-4),
    vec4<f32>(6.1310757e1, 1.6264316e0, -2.1416761e-2, 5.637363e-4),
    vec4<f32>(6.4482254e1, 1.5470526e0, -1.8428642e-2, 4.3886082e-4),
    vec4<f32>(6.750601e1, 1.4782659e0, -1.6076243e-2, 3.4953648e-4),
    vec4<f32>(7.0400925e1, 1.4179077e0, -1.4185063e-2, 2.8373586e-4),
    vec4<f32>(7.318219e1, 1.3643862e0, -1.263771e-2, 2.340549e-4),
    vec4<f32>(7.586222e1, 1.3165014e0, -1.1352604e-2, 1.9575047e-4),
    vec4<f32>(7.845133e1, 1.2733283e0, -1.027147e-2, 1.6567999e-4),
    vec4<f32>(8.218313e1, 2.4317167e0, -3.5797212e-2, 1.0532545e-3),
    vec4<f32>(8.691136e1, 2.3001807e0, -3.029021e-2, 7.9734606e-4),
    vec4<f32>(9.139665e1, 2.1879137e0, -2.6063854e-2, 6.207151e-4),
    vec4<f32>(9.567298e1, 2.0906281e0, -2.2736687e-2, 4.943717e-4),
    vec4<f32>(9.976709e1, 2.0052633e0, -2.0061884e-2, 4.013023e-4),
    vec4<f32>(1.0370046e2, 1.9295684e0, -1.7873392e-2, 3.3103355e-4),
    vec4<f32>(1.0749067e2, 1.8618454e0, -1.6055817e-2, 2.7685627e-4),
    vec4<f32>(1.1115228e2, 1.8007865e0, -1.4526739e-2, 2.3432534e-4),
    vec4<f32>(1.1642992e2, 3.4390159e0, -5.0627083e-2, 1.4896339e-3),
    vec4<f32>(1.23116745e2, 3.2529883e0, -4.2838477e-2, 1.1276901e-3),
    vec4<f32>(1.2945998e2, 3.094213e0, -3.6861144e-2, 8.778748e-4),
    vec4<f32>(1.3550769e2, 2.956626e0, -3.215556e-2, 6.991843e-4),
    vec4<f32>(1.412977e2, 2.8358984e0, -2.837262e-2, 5.6755485e-4),
    vec4<f32>(1.4686038e2, 2.7288465e0, -2.5277479e-2, 4.6817327e-4),
    vec4<f32>(1.5222058e2, 2.633069e0, -2.270693e-2, 3.915504e-4),
    vec4<f32>(1.5739893e2, 2.5467167e0, -2.0544397e-2, 3.3139915e-4),
    vec4<f32>(1.6486269e2, 4.863538e0, -7.159905e-2, 2.1067362e-3),
    vec4<f32>(1.7431937e2, 4.60045e0, -6.0583927e-2, 1.5948459e-3),
    vec4<f32>(1.832901e2, 4.3759036e0, -5.213044e-2, 1.2415386e-3),
    vec4<f32>(1.918429e2, 4.1813226e0, -4.547555e-2, 9.888222e-4),
    vec4<f32>(2.0003125e2, 4.010586e0, -4.012553e-2, 8.026634e-4),
    vec4<f32>(2.078981e2, 3.8591893e0, -3.5748236e-2, 6.6211197e-4),
    vec4<f32>(2.154786e2, 3.7237377e0, -3.211285e-2, 5.537475e-4),
    vec4<f32>(2.2280193e2, 3.6016157e0, -2.9054508e-2, 4.686784e-4),
    vec4<f32>(2.3335732e2, 6.878106e0, -1.0125744e-1, 2.9794285e-3),
    vec4<f32>(2.4673111e2, 6.5060396e0, -8.5679434e-2, 2.255489e-3),
    vec4<f32>(2.594177e2, 6.18848e0, -7.372422e-2, 1.7558262e-3),
    vec4<f32>(2.715132e2, 5.913299e0, -6.431265e-2, 1.3984243e-3),
    vec4<f32>(2.8309332e2, 5.6718383e0, -5.6746487e-2, 1.1351514e-3),
    vec4<f32>(2.9421875e2, 5.45773e0, -5.0555985e-2, 9.363783e-4),
    vec4<f32>(3.0493924e2, 5.2661715e0, -4.541472e-2, 7.831255e-4),
    vec4<f32>(3.15296e2, 5.093464e0, -4.1089524e-2, 6.6281785e-4),
);

// Double GGX slope kernel G(1/y), y = tan²θ/α²: the Rust DGGX_D (degree 9, f64)
// rounded to f32 (largest relative change 5.8e-8).
const MS_DG_D_K0: i32 = -30;
const MS_DG_D_K1: i32 = 30;
const MS_DG_D_M: u32 = 2u;
var<private> MS_DG_D: array<vec4<f32>, 720> = array<vec4<f32>, 720>(
    vec4<f32>(1e0, -4.656634e-10, -1.2034818e-14, -3.3795188e-14),
    vec4<f32>(4.0856207e-14, 2.0348168e-13, -4.689582e-14, -3.215206e-13),
    vec4<f32>(1.7053026e-14, 1.5489831e-13, 0e0, 0e0),
    vec4<f32>(1e0, -4.6566087e-10, -1.3100632e-14, -5.5733196e-14),
    vec4<f32>(3.8014036e-14, 2.7986503e-13, -3.4816595e-14, -4.266809e-13),
    vec4<f32>(8.526513e-15, 2.0321523e-13, 0e0, 0e0),
    vec4<f32>(1e0, -4.6566184e-10, -1.6342483e-14, -4.733991e-14),
    vec4<f32>(6.2705395e-14, 2.4655833e-13, -8.029133e-14, -3.7942983e-13),
    vec4<f32>(3.2684965e-14, 1.8189894e-13, 0e0, 0e0),
    vec4<f32>(1e0, -4.656623e-10, -1.7630342e-14, -3.9301895e-14),
    vec4<f32>(6.536993e-14, 2.2000179e-13, -8.31335e-14, -3.449685e-13),
    vec4<f32>(3.4106053e-14, 1.66267e-13, 0e0, 0e0),
    vec4<f32>(1e0, -9.313227e-10, -2.1627145e-14, -5.382361e-14),
    vec4<f32>(7.993606e-14, 2.7391422e-13, -1.0089707e-13, -4.1779912e-13),
    vec4<f32>(4.121148e-14, 1.9895197e-13, 0e0, 0e0),
    vec4<f32>(1e0, -9.3132185e-10, -1.4521718e-14, -5.804246e-14),
    vec4<f32>(5.471179e-14, 2.782663e-13, -7.1054274e-14, -4.1744386e-13),
    vec4<f32>(2.9842794e-14, 1.9753088e-13, 0e0, 0e0),
    vec4<f32>(1e0, -9.3132185e-10, -1.5898393e-14, -5.888623e-14),
    vec4<f32>(5.6665782e-14, 2.872369e-13, -6.750156e-14, -4.355627e-13),
    vec4<f32>(2.5579538e-14, 2.0747848e-13, 0e0, 0e0),
    vec4<f32>(1e0, -9.313226e-10, -1.8296476e-14, -5.7687186e-14),
    vec4<f32>(6.306067e-14, 2.8945734e-13, -7.460699e-14, -4.3947067e-13),
    vec4<f32>(2.842171e-14, 2.0889956e-13, 0e0, 0e0),
    vec4<f32>(1e0, -1.8626456e-9, -1.5498714e-14, -4.7251093e-14),
    vec4<f32>(5.4001247e-14, 2.5277558e-13, -6.252776e-14, -3.9150904e-13),
    vec4<f32>(2.2737368e-14, 1.8758328e-13, 0e0, 0e0),
    vec4<f32>(1e0, -1.8626447e-9, -1.8296476e-14, -5.959677e-14),
    vec4<f32>(6.6080476e-14, 2.9487524e-13, -8.029133e-14, -4.4764192e-13),
    vec4<f32>(3.126388e-14, 2.1316282e-13, 0e0, 0e0),
    vec4<f32>(1e0, -1.862646e-9, -1.4965807e-14, -4.369838e-14),
    vec4<f32>(5.0803806e-14, 2.438938e-13, -5.82645e-14, -3.8298255e-13),
    vec4<f32>(2.1316282e-14, 1.8474111e-13, 0e0, 0e0),
    vec4<f32>(1e0, -1.8626454e-9, -1.9673152e-14, -4.6673775e-14),
    vec4<f32>(7.3008263e-14, 2.4238389e-13, -9.30811e-14, -3.719691e-13),
    vec4<f32>(3.836931e-14, 1.7763568e-13, 0e0, 0e0),
    vec4<f32>(9.9999994e-1, -3.725292e-9, -1.5942803e-14, -3.5971226e-14),
    vec4<f32>(5.222489e-14, 2.1298519e-13, -5.7553964e-14, -3.389289e-13),
    vec4<f32>(1.9895196e-14, 1.6484592e-13, 0e0, 0e0),
    vec4<f32>(9.9999994e-1, -3.725292e-9, -2.0783375e-14, -4.1611158e-14),
    vec4<f32>(8.06466e-14, 2.4682478e-13, -1.08002494e-13, -3.9399595e-13),
    vec4<f32>(4.689582e-14, 1.9184654e-13, 0e0, 0e0),
    vec4<f32>(9.9999994e-1, -3.7252916e-9, -1.9628743e-14, -2.5623948e-14),
    vec4<f32>(8.029133e-14, 1.7257307e-13, -1.1155521e-13, -2.8741454e-13),
    vec4<f32>(4.973799e-14, 1.4352964e-13, 0e0, 0e0),
    vec4<f32>(9.9999994e-1, -3.7252907e-9, -1.5321078e-14, -4.209966e-14),
    vec4<f32>(5.2402527e-14, 2.359002e-13, -6.110668e-14, -3.709033e-13),
    vec4<f32>(2.2737368e-14, 1.7905677e-13, 0e0, 0e0),
    vec4<f32>(9.9999994e-1, -7.4505815e-9, -1.7497116e-14, -3.126388e-14),
    vec4<f32>(6.128431e-14, 1.9895197e-13, -7.531753e-14, -3.2400748e-13),
    vec4<f32>(2.9842794e-14, 1.5916157e-13, 0e0, 0e0),
    vec4<f32>(9.9999994e-1, -7.450581e-9, -1.8429702e-14, -4.2765792e-14),
    vec4<f32>(6.377121e-14, 2.4522607e-13, -7.531753e-14, -3.8902215e-13),
    vec4<f32>(2.842171e-14, 1.8900437e-13, 0e0, 0e0),
    vec4<f32>(9.999999e-1, -7.4505797e-9, -1.7230661e-14, -5.0404125e-14),
    vec4<f32>(6.430412e-14, 2.6565417e-13, -8.242296e-14, -4.082068e-13),
    vec4<f32>(3.4106053e-14, 1.9468871e-13, 0e0, 0e0),
    vec4<f32>(9.999999e-1, -7.4505793e-9, -1.5143441e-14, -5.4400928e-14),
    vec4<f32>(5.222489e-14, 2.866152e-13, -6.110668e-14, -4.4231285e-13),
    vec4<f32>(2.2737368e-14, 2.1174173e-13, 0e0, 0e0),
    vec4<f32>(9.999999e-1, -1.4901156e-8, -1.6298074e-14, -5.884182e-14),
    vec4<f32>(6.3948846e-14, 2.8643754e-13, -8.242296e-14, -4.330758e-13),
    vec4<f32>(3.4106053e-14, 2.060574e-13, 0e0, 0e0),
    vec4<f32>(9.999998e-1, -1.4901153e-8, -1.8607339e-14, -7.158718e-14),
    vec4<f32>(7.389644e-14, 3.2276403e-13, -9.4502185e-14, -4.7108986e-13),
    vec4<f32>(3.836931e-14, 2.1884716e-13, 0e0, 0e0),
    vec4<f32>(9.999998e-1, -1.4901155e-8, -1.9584333e-14, -5.4312112e-14),
    vec4<f32>(7.194245e-14, 2.8252956e-13, -8.881784e-14, -4.3876014e-13),
    vec4<f32>(3.5527137e-14, 2.1174173e-13, 0e0, 0e0),
    vec4<f32>(9.9999976e-1, -1.4901154e-8, -1.5898393e-14, -5.2580163e-14),
    vec4<f32>(5.897505e-14, 2.7657875e-13, -7.247536e-14, -4.2703617e-13),
    vec4<f32>(2.842171e-14, 2.046363e-13, 0e0, 0e0),
    vec4<f32>(9.9999976e-1, -2.9802305e-8, -1.5942803e-14, -5.551115e-14),
    vec4<f32>(6.3948846e-14, 2.6556535e-13, -7.9580785e-14, -3.971934e-13),
    vec4<f32>(3.126388e-14, 1.8758328e-13, 0e0, 0e0),
    vec4<f32>(9.999997e-1, -2.98023e-8, -1.7497116e-14, -5.7420736e-14),
    vec4<f32>(6.32383e-14, 2.8448354e-13, -7.31859e-14, -4.3520743e-13),
    vec4<f32>(2.7000624e-14, 2.0889956e-13, 0e0, 0e0),
    vec4<f32>(9.9999964e-1, -2.9802298e-8, -1.5498714e-14, -4.1877614e-14),
    vec4<f32>(5.702105e-14, 2.310152e-13, -6.6080476e-14, -3.6486368e-13),
    vec4<f32>(2.4158454e-14, 1.7763568e-13, 0e0, 0e0),
    vec4<f32>(9.999996e-1, -2.980229e-8, -1.3944401e-14, -7.331913e-14),
    vec4<f32>(5.435652e-14, 3.2995828e-13, -6.750156e-14, -4.8352435e-13),
    vec4<f32>(2.7000624e-14, 2.2595258e-13, 0e0, 0e0),
    vec4<f32>(9.9999946e-1, -5.9604574e-8, -7.1942455e-15, -4.5385916e-14),
    vec4<f32>(4.1389113e-14, 2.284395e-13, -4.973799e-14, -3.4958703e-13),
    vec4<f32>(1.847411e-14, 1.6768809e-13, 0e0, 0e0),
    vec4<f32>(9.9999934e-1, -5.9604556e-8, -1.89182e-14, -5.5466743e-14),
    vec4<f32>(8.757439e-14, 2.6956215e-13, -1.1155521e-13, -4.0536463e-13),
    vec4<f32>(4.5474736e-14, 1.9184654e-13, 0e0, 0e0),
    vec4<f32>(9.999992e-1, -5.960454e-8, -1.0214052e-14, -3.259615e-14),
    vec4<f32>(4.902745e-14, 2.0037306e-13, -5.471179e-14, -3.2116532e-13),
    vec4<f32>(1.847411e-14, 1.563194e-13, 0e0, 0e0),
    vec4<f32>(9.999991e-1, -5.9604524e-8, -1.7497116e-14, -4.5030647e-14),
    vec4<f32>(8.206769e-14, 2.444267e-13, -1.07291956e-13, -3.8227199e-13),
    vec4<f32>(4.5474736e-14, 1.8474111e-13, 0e0, 0e0),
    vec4<f32>(9.999989e-1, -1.19209005e-7, -7.549517e-16, -4.2543748e-14),
    vec4<f32>(6.181722e-14, 2.4211744e-13, -7.7449155e-14, -3.7587712e-13),
    vec4<f32>(3.126388e-14, 1.7905677e-13, 0e0, 0e0),
    vec4<f32>(9.999987e-1, -1.19208934e-7, 3.907985e-15, -5.3246297e-14),
    vec4<f32>(4.52971e-14, 2.583711e-13, -5.5422335e-14, -3.8760106e-13),
    vec4<f32>(2.1316282e-14, 1.8332002e-13, 0e0, 0e0),
    vec4<f32>(9.9999845e-1, -1.1920888e-7, -1.7763569e-16, -5.3246297e-14),
    vec4<f32>(6.128431e-14, 2.6671997e-13, -7.8870246e-14, -4.0394353e-13),
    vec4<f32>(3.2684965e-14, 1.9184654e-13, 0e0, 0e0),
    vec4<f32>(9.999982e-1, -1.1920881e-7, 1.5543122e-15, -2.882139e-14),
    vec4<f32>(5.2580163e-14, 1.9690915e-13, -6.6080476e-14, -3.2791548e-13),
    vec4<f32>(2.7000624e-14, 1.6342483e-13, 0e0, 0e0),
    vec4<f32>(9.9999785e-1, -2.3841743e-7, 4.6673775e-14, -4.485301e-14),
    vec4<f32>(6.5902836e-14, 2.469136e-13, -8.526513e-14, -3.8795632e-13),
    vec4<f32>(3.5527137e-14, 1.8758328e-13, 0e0, 0e0),
    vec4<f32>(9.999974e-1, -2.3841717e-7, 4.5385916e-14, -5.9063865e-14),
    vec4<f32>(7.602807e-14, 2.9647395e-13, -1.05160326e-13, -4.4977355e-13),
    vec4<f32>(4.689582e-14, 2.1316282e-13, 0e0, 0e0),
    vec4<f32>(9.999969e-1, -2.3841692e-7, 4.8672177e-14, -4.236611e-14),
    vec4<f32>(5.0803806e-14, 2.5259794e-13, -5.82645e-14, -4.0643045e-13),
    vec4<f32>(2.1316282e-14, 1.9895197e-13, 0e0, 0e0),
    vec4<f32>(9.999964e-1, -2.3841666e-7, 4.2676972e-14, -4.0989435e-14),
    vec4<f32>(8.100187e-14, 2.2568614e-13, -1.05160326e-13, -3.549161e-13),
    vec4<f32>(4.4053648e-14, 1.7195135e-13, 0e0, 0e0),
    vec4<f32>(9.999957e-1, -4.7683255e-7, 2.4069635e-13, -3.1841195e-14),
    vec4<f32>(5.4001247e-14, 2.235545e-13, -6.536993e-14, -3.733902e-13),
    vec4<f32>(2.5579538e-14, 1.861622e-13, 0e0, 0e0),
    vec4<f32>(9.9999475e-1, -4.7683153e-7, 2.3665515e-13, -5.915268e-14),
    vec4<f32>(6.732393e-14, 2.781775e-13, -8.3844044e-14, -4.121148e-13),
    vec4<f32>(3.4106053e-14, 1.9326763e-13, 0e0, 0e0),
    vec4<f32>(9.999938e-1, -4.768305e-7, 2.3927526e-13, -5.058176e-14),
    vec4<f32>(6.092904e-14, 2.5268676e-13, -7.81597e-14, -3.8760106e-13),
    vec4<f32>(3.2684965e-14, 1.861622e-13, 0e0, 0e0),
    vec4<f32>(9.9999285e-1, -4.7682948e-7, 2.3767655e-13, -4.0634163e-14),
    vec4<f32>(6.217249e-14, 2.4025226e-13, -7.1054274e-14, -3.8902215e-13),
    vec4<f32>(2.5579538e-14, 1.9184654e-13, 0e0, 0e0),
    vec4<f32>(9.999914e-1, -9.536559e-7, 1.0079493e-12, -4.7206684e-14),
    vec4<f32>(5.77316e-14, 2.4966696e-13, -7.31859e-14, -3.8689053e-13),
    vec4<f32>(2.9842794e-14, 1.861622e-13, 0e0, 0e0),
    vec4<f32>(9.999895e-1, -9.536518e-7, 1.0051515e-12, -5.0137672e-14),
    vec4<f32>(6.785683e-14, 2.663647e-13, -8.668621e-14, -4.1247005e-13),
    vec4<f32>(3.5527137e-14, 1.9753088e-13, 0e0, 0e0),
    vec4<f32>(9.999876e-1, -9.536477e-7, 1.00564e-12, -5.018208e-14),
    vec4<f32>(6.661338e-14, 2.5242032e-13, -8.31335e-14, -3.8298255e-13),
    vec4<f32>(3.2684965e-14, 1.8189894e-13, 0e0, 0e0),
    vec4<f32>(9.999857e-1, -9.536436e-7, 1.0045298e-12, -4.3431926e-14),
    vec4<f32>(6.767919e-14, 2.284395e-13, -8.5975674e-14, -3.5100812e-13),
    vec4<f32>(3.5527137e-14, 1.6768809e-13, 0e0, 0e0),
    vec4<f32>(9.9998283e-1, -1.907275e-6, 4.076517e-12, -4.3876015e-14),
    vec4<f32>(5.2402527e-14, 2.3501202e-13, -5.6132877e-14, -3.687717e-13),
    vec4<f32>(1.847411e-14, 1.7905677e-13, 0e0, 0e0),
    vec4<f32>(9.99979e-1, -1.9072586e-6, 4.0750957e-12, -4.1255888e-14),
    vec4<f32>(6.3593573e-14, 2.324363e-13, -8.029133e-14, -3.6628477e-13),
    vec4<f32>(3.2684965e-14, 1.7763568e-13, 0e0, 0e0),
    vec4<f32>(9.999752e-1, -1.9072422e-6, 4.0778934e-12, -4.8094863e-14),
    vec4<f32>(4.9915628e-14, 2.5410785e-13, -5.968559e-14, -3.932854e-13),
    vec4<f32>(2.2737368e-14, 1.8900437e-13, 0e0, 0e0),
    vec4<f32>(9.999714e-1, -1.9072259e-6, 4.071543e-12, -4.9293902e-14),
    vec4<f32>(7.7449155e-14, 2.5313085e-13, -9.947598e-14, -3.9008797e-13),
    vec4<f32>(4.121148e-14, 1.8758328e-13, 0e0, 0e0),
    vec4<f32>(9.9996567e-1, -3.8144026e-6, 1.6357759e-11, -4.569678e-14),
    vec4<f32>(2.8776982e-14, 2.5055514e-13, -1.7763568e-14, -3.9470648e-13),
    vec4<f32>(-1.4210855e-15, 1.9184654e-13, 0e0, 0e0),
    vec4<f32>(9.9995804e-1, -3.814337e-6, 1.6345324e-11, -6.004086e-14),
    vec4<f32>(8.970602e-14, 2.9842795e-13, -1.1937117e-13, -4.504841e-13),
    vec4<f32>(5.1159076e-14, 2.1316282e-13, 0e0, 0e0),
    vec4<f32>(9.999504e-1, -3.8142716e-6, 1.6348967e-11, -5.7376325e-14),
    vec4<f32>(6.714629e-14, 2.8652636e-13, -8.526513e-14, -4.3272054e-13),
    vec4<f32>(3.5527137e-14, 2.046363e-13, 0e0, 0e0),
    vec4<f32>(9.999428e-1, -3.8142061e-6, 1.634568e-11, -4.938272e-14),
    vec4<f32>(8.402168e-14, 2.6059154e-13, -1.0942358e-13, -4.057199e-13),
    vec4<f32>(4.5474736e-14, 1.961098e-13, 0e0, 0e0),
    vec4<f32>(9.9993134e-1, -7.628216e-6, 6.5451866e-11, -6.386003e-14),
    vec4<f32>(5.595524e-14, 3.1032953e-13, -7.531753e-14, -4.7108986e-13),
    vec4<f32>(3.2684965e-14, 2.2453151e-13, 0e0, 0e0),
    vec4<f32>(9.999161e-1, -7.6279543e-6, 6.544383e-11, -2.9531932e-14),
    vec4<f32>(6.5902836e-14, 1.8287593e-13, -8.31335e-14, -2.9451997e-13),
    vec4<f32>(3.4106053e-14, 1.4352964e-13, 0e0, 0e0),
    vec4<f32>(9.999008e-1, -7.6276924e-6, 6.544054e-11, -3.250733e-14),
    vec4<f32>(6.945555e-14, 2.0108359e-13, -9.4502185e-14, -3.2827075e-13),
    vec4<f32>(4.121148e-14, 1.6200374e-13, 0e0, 0e0),
    vec4<f32>(9.9988556e-1, -7.6274305e-6, 6.543468e-11, -3.9301895e-14),
    vec4<f32>(7.247536e-14, 2.2444268e-13, -9.4502185e-14, -3.5846882e-13),
    vec4<f32>(3.9790393e-14, 1.7479352e-13, 0e0, 0e0),
    vec4<f32>(9.998627e-1, -1.5254075e-5, 2.61776e-10, -4.893863e-14),
    vec4<f32>(5.0270897e-14, 2.4797943e-13, -5.82645e-14, -3.922196e-13),
    vec4<f32>(2.1316282e-14, 1.9042545e-13, 0e0, 0e0),
    vec4<f32>(9.998322e-1, -1.5253028e-5, 2.6174515e-10, -4.7473137e-14),
    vec4<f32>(5.2402527e-14, 2.2444268e-13, -6.8212105e-14, -3.4710012e-13),
    vec4<f32>(2.842171e-14, 1.66267e-13, 0e0, 0e0),
    vec4<f32>(9.998017e-1, -1.52519815e-5, 2.617087e-10, -6.17284e-14),
    vec4<f32>(6.8034466e-14, 2.897238e-13, -8.668621e-14, -4.455103e-13),
    vec4<f32>(3.5527137e-14, 2.1316282e-13, 0e0, 0e0),
    vec4<f32>(9.997712e-1, -1.5250935e-5, 2.6167588e-10, -5.8131275e-14),
    vec4<f32>(7.0699e-14, 2.7169377e-13, -9.0238926e-14, -4.181544e-13),
    vec4<f32>(3.694822e-14, 2.0037306e-13, 0e0, 0e0),
    vec4<f32>(9.997254e-1, -3.049873e-5, 1.0465673e-9, -7.580603e-14),
    vec4<f32>(7.531753e-14, 2.2195578e-13, -9.30811e-14, -3.7125858e-13),
    vec4<f32>(3.694822e-14, 1.861622e-13, 0e0, 0e0),
    vec4<f32>(9.996644e-1, -3.0494544e-5, 1.0463136e-9, -1.1719514e-13),
    vec4<f32>(6.536993e-14, 3.3759662e-13, -7.602807e-14, -4.9560356e-13),
    vec4<f32>(2.842171e-14, 2.3163692e-13, 0e0, 0e0),
    vec4<f32>(9.9960345e-1, -3.0490359e-5, 1.0460617e-9, -1.04805054e-13),
    vec4<f32>(4.9560355e-14, 2.8492763e-13, -5.1159076e-14, -4.220624e-13),
    vec4<f32>(1.563194e-14, 1.9895197e-13, 0e0, 0e0),
    vec4<f32>(9.995425e-1, -3.0486175e-5, 1.045803e-9, -7.704948e-14),
    vec4<f32>(7.176482e-14, 2.1058711e-13, -8.952839e-14, -3.399947e-13),
    vec4<f32>(3.5527137e-14, 1.66267e-13, 0e0, 0e0),
    vec4<f32>(9.9945104e-1, -6.0959803e-5, 4.1817403e-9, -3.7889692e-13),
    vec4<f32>(6.412648e-14, 2.2382096e-13, -7.460699e-14, -3.5242919e-13),
    vec4<f32>(2.7000624e-14, 1.7053026e-13, 0e0, 0e0),
    vec4<f32>(9.9932915e-1, -6.094308e-5, 4.1797037e-9, -3.9359626e-13),
    vec4<f32>(5.435652e-14, 2.7045033e-13, -6.536993e-14, -4.1033843e-13),
    vec4<f32>(2.5579538e-14, 1.9468871e-13, 0e0, 0e0),
    vec4<f32>(9.9920726e-1, -6.0926362e-5, 4.1776627e-9, -3.7507774e-13),
    vec4<f32>(7.531753e-14, 2.3039348e-13, -9.166001e-14, -3.8156145e-13),
    vec4<f32>(3.5527137e-14, 1.9042545e-13, 0e0, 0e0),
    vec4<f32>(9.990854e-1, -6.0909657e-5, 4.1756314e-9, -3.6806113e-13),
    vec4<f32>(5.82645e-14, 1.8687273e-13, -6.8922644e-14, -3.0553338e-13),
    vec4<f32>(2.5579538e-14, 1.5063507e-13, 0e0, 0e0),
    vec4<f32>(9.9890274e-1, -1.21769226e-4, 1.6690375e-8, -2.7688962e-12),
    vec4<f32>(5.2935432e-14, 2.6947333e-13, -6.32383e-14, -3.9861446e-13),
    vec4<f32>(2.4158454e-14, 1.8758328e-13, 0e0, 0e0),
    vec4<f32>(9.9865925e-1, -1.217025e-4, 1.6674127e-8, -2.7378544e-12),
    vec4<f32>(5.915268e-14, 1.7932322e-13, -7.1054274e-14, -2.7746693e-13),
    vec4<f32>(2.7000624e-14, 1.3216095e-13, 0e0, 0e0),
    vec4<f32>(9.984159e-1, -1.2163583e-4, 1.6657905e-8, -2.7359005e-12),
    vec4<f32>(5.2047254e-14, 2.0206059e-13, -5.7553964e-14, -3.200995e-13),
    vec4<f32>(1.9895196e-14, 1.5489831e-13, 0e0, 0e0),
    vec4<f32>(9.981727e-1, -1.2156923e-4, 1.6641705e-8, -2.7438496e-12),
    vec4<f32>(6.004086e-14, 2.5011105e-13, -6.8922644e-14, -3.8937741e-13),
    vec4<f32>(2.5579538e-14, 1.8758328e-13, 0e0, 0e0),
    vec4<f32>(9.9780816e-1, -2.4293891e-4, 6.646987e-8, -2.1565772e-11),
    vec4<f32>(6.732393e-14, 2.110312e-13, -6.252776e-14, -3.410605e-13),
    vec4<f32>(2.1316282e-14, 1.6768809e-13, 0e0, 0e0),
    vec4<f32>(9.9732256e-1, -2.4267328e-4, 6.634088e-8, -2.1545566e-11),
    vec4<f32>(8.8107297e-14, 3.4505732e-13, -1.0658141e-13, -4.9844574e-13),
    vec4<f32>(4.5474736e-14, 2.3163692e-13, 0e0, 0e0),
    vec4<f32>(9.9683744e-1, -2.4240819e-4, 6.6212294e-8, -2.1441782e-11),
    vec4<f32>(3.3040238e-14, 2.2577495e-13, -2.1316282e-14, -3.5313975e-13),
    vec4<f32>(4.2632566e-15, 1.7053026e-13, 0e0, 0e0),
    vec4<f32>(9.963529e-1, -2.421436e-4, 6.608407e-8, -2.1392044e-11),
    vec4<f32>(8.5087495e-14, 2.8830272e-13, -1.0018653e-13, -4.3840487e-13),
    vec4<f32>(4.2632564e-14, 2.0747848e-13, 0e0, 0e0),
    vec4<f32>(9.9562705e-1, -4.8349533e-4, 2.6356997e-7, -1.6997426e-10),
    vec4<f32>(1.991296e-13, 2.692957e-13, -9.0238926e-14, -4.1353588e-13),
    vec4<f32>(3.694822e-14, 1.9895197e-13, 0e0, 0e0),
    vec4<f32>(9.9466115e-1, -4.8244308e-4, 2.6255353e-7, -1.6896151e-10),
    vec4<f32>(1.8935964e-13, 2.9638515e-13, -8.1712415e-14, -4.4018123e-13),
    vec4<f32>(3.4106053e-14, 2.060574e-13, 0e0, 0e0),
    vec4<f32>(9.936973e-1, -4.8139488e-4, 2.6154316e-7, -1.6790733e-10),
    vec4<f32>(2.1564972e-13, 1.4805934e-13, -1.2008172e-13, -2.4904522e-13),
    vec4<f32>(5.1159076e-14, 1.2363443e-13, 0e0, 0e0),
    vec4<f32>(9.9273556e-1, -4.8035072e-4, 2.6053883e-7, -1.6695241e-10),
    vec4<f32>(2.0747848e-13, 3.2791548e-13, -1.1297629e-13, -4.9595885e-13),
    vec4<f32>(4.973799e-14, 2.359002e-13, 0e0, 0e0),
    vec4<f32>(9.912968e-1, -9.5758395e-4, 1.0361744e-6, -1.3232332e-9),
    vec4<f32>(2.0300207e-12, 2.7213786e-13, -7.247536e-14, -4.1353588e-13),
    vec4<f32>(2.842171e-14, 1.961098e-13, 0e0, 0e0),
    vec4<f32>(9.893858e-1, -9.534551e-4, 1.0282824e-6, -1.307596e-9),
    vec4<f32>(1.960565e-12, 2.9638515e-13, -1.7053026e-14, -4.5865536e-13),
    vec4<f32>(2.842171e-15, 2.2026825e-13, 0e0, 0e0),
    vec4<f32>(9.87483e-1, -9.493576e-4, 1.0204834e-6, -1.2922011e-9),
    vec4<f32>(1.9461765e-12, 2.3314684e-13, -4.4053648e-14, -3.733902e-13),
    vec4<f32>(1.4210855e-14, 1.8047785e-13, 0e0, 0e0),
    vec4<f32>(9.855884e-1, -9.452911e-4, 1.012776e-6, -1.2770583e-9),
    vec4<f32>(1.9408474e-12, 1.389111e-13, -7.9580785e-14, -2.4300562e-13),
    vec4<f32>(2.9842794e-14, 1.2221336e-13, 0e0, 0e0),
    vec4<f32>(9.8276156e-1, -1.8784974e-3, 4.005532e-6, -1.0038706e-8),
    vec4<f32>(2.9339375e-11, 1.3855583e-13, -1.3002932e-13, -3.6948222e-13),
    vec4<f32>(5.5422335e-14, 1.7905677e-13, 0e0, 0e0),
    vec4<f32>(9.7902054e-1, -1.8625949e-3, 3.945994e-6, -9.808617e-9),
    vec4<f32>(2.8365577e-11, 1.5525359e-13, -9.947598e-14, -3.6806113e-13),
    vec4<f32>(4.2632564e-14, 1.7053026e-13, 0e0, 0e0),
    vec4<f32>(9.7531104e-1, -1.8469277e-3, 3.8878143e-6, -9.585989e-9),
    vec4<f32>(2.7424108e-11, 2.364331e-13, -5.4001247e-14, -4.8956396e-13),
    vec4<f32>(1.9895196e-14, 2.33058e-13, 0e0, 0e0),
    vec4<f32>(9.7163266e-1, -1.8314905e-3, 3.8309486e-6, -9.370443e-9),
    vec4<f32>(2.6557067e-11, 1.6164847e-13, -5.4001247e-14, -3.9790393e-13),
    vec4<f32>(1.847411e-14, 1.961098e-13, 0e0, 0e0),
    vec4<f32>(9.661724e-1, -3.6175102e-3, 1.4992095e-5, -7.247863e-8),
    vec4<f32>(4.0433168e-10, -2.3299585e-12, -9.947598e-15, -3.6273206e-13),
    vec4<f32>(4.2632566e-15, 1.7763568e-13, 0e0, 0e0),
    vec4<f32>(9.589968e-1, -3.5583987e-3, 1.4566726e-5, -6.934376e-8),
    vec4<f32>(3.7980766e-10, -2.1611157e-12, -3.9790393e-14, -3.1548099e-13),
    vec4<f32>(1.9895196e-14, 1.563194e-13, 0e0, 0e0),
    vec4<f32>(9.519377e-1, -3.500952e-3, 1.4159594e-5, -6.6397334e-8),
    vec4<f32>(3.5723174e-10, -1.861622e-12, -5.5422335e-14, -4.391154e-13),
    vec4<f32>(2.4158454e-14, 2.0179413e-13, 0e0, 0e0),
    vec4<f32>(9.449919e-1, -3.445099e-3, 1.3769612e-5, -6.362442e-8),
    vec4<f32>(3.3642938e-10, -1.7327473e-12, -1.0018653e-13, -4.1104896e-13),
    vec4<f32>(4.4053648e-14, 1.9753088e-13, 0e0, 0e0),
    vec4<f32>(9.3477887e-1, -6.7283274e-3, 5.2858522e-5, -4.7809255e-7),
    vec4<f32>(4.9283138e-9, -5.6851412e-11, 6.288303e-13, -2.394529e-13),
    vec4<f32>(4.121148e-14, 1.1937117e-13, 0e0, 0e0),
    vec4<f32>(9.215299e-1, -6.522477e-3, 5.0103856e-5, -4.408346e-7),
    vec4<f32>(4.399544e-9, -4.8796432e-11, 5.31486e-13, -3.733902e-13),
    vec4<f32>(2.9842794e-14, 1.7763568e-13, 0e0, 0e0),
    vec4<f32>(9.0868187e-1, -6.327215e-3, 4.7560654e-5, -4.0750783e-7),
    vec4<f32>(3.9432613e-9, -4.2243188e-11, 3.907985e-13, -3.0127013e-13),
    vec4<f32>(4.689582e-14, 1.3926638e-13, 0e0, 0e0),
    vec4<f32>(8.962145e-1, -6.1417394e-3, 4.520696e-5, -3.7758312e-7),
    vec4<f32>(3.5472716e-9, -3.677867e-11, 2.9132252e-13, -2.4265036e-13),
    vec4<f32>(5.5422335e-14, 1.179501e-13, 0e0, 0e0),
    vec4<f32>(8.781862e-1, -1.1760647e-2, 1.6796311e-4, -2.705018e-6),
    vec4<f32>(4.8727752e-8, -9.677165e-10, 2.0886404e-11, -6.9171334e-13),
    vec4<f32>(2.2737368e-14, 9.5212724e-14, 0e0, 0e0),
    vec4<f32>(8.5531586e-1, -1.111977e-2, 1.5282976e-4, -2.3508153e-6),
    vec4<f32>(4.018063e-8, -7.524938e-10, 1.5185719e-11, -8.4803274e-13),
    vec4<f32>(3.9790393e-14, 2.4016344e-13, 0e0, 0e0),
    vec4<f32>(8.336695e-1, -1.0535432e-2, 1.3963242e-4, -2.0572145e-6),
    vec4<f32>(3.348336e-8, -5.941628e-10, 1.1322854e-11, -5.4782844e-13),
    vec4<f32>(1.7053026e-14, 1.4495072e-13, 0e0, 0e0),
    vec4<f32>(8.131412e-1, -1.0000563e-2, 1.2804777e-4, -1.8114252e-6),
    vec4<f32>(2.816208e-8, -4.750305e-10, 8.5321975e-12, -6.4943607e-13),
    vec4<f32>(3.9790393e-14, 2.1600499e-13, 0e0, 0e0),
    vec4<f32>(7.842452e-1, -1.8556649e-2, 4.5258808e-4, -1.2096336e-5),
    vec4<f32>(3.528734e-7, -1.1111291e-8, 3.7369077e-10, -1.3644197e-11),
    vec4<f32>(5.1159077e-13, 1.4352964e-13, 0e0, 0e0),
    vec4<f32>(7.488508e-1, -1.6880982e-2, 3.876717e-4, -9.664666e-6),
    vec4<f32>(2.6094423e-7, -7.555131e-9, 2.3236808e-10, -7.794832e-12),
    vec4<f32>(2.4158453e-13, 1.2292389e-13, 0e0, 0e0),
    vec4<f32>(7.1656615e-1, -1.5438484e-2, 3.3539304e-4, -7.845951e-6),
    vec4<f32>(1.9747785e-7, -5.3009495e-9, 1.5046667e-10, -4.5304203e-12),
    vec4<f32>(1.16529e-13, 3.126388e-14, 0e0, 0e0),
    vec4<f32>(6.86971e-1, -1.4185142e-2, 2.9266605e-4, -6.456378e-6),
    vec4<f32>(1.5237971e-7, -3.8175787e-9, 1.0068106e-10, -2.9762859e-12),
    vec4<f32>(9.0238926e-14, 1.0444978e-13, 0e0, 0e0),
    vec4<f32>(6.468867e-1, -2.5176845e-2, 9.674642e-4, -3.9391554e-5),
    vec4<f32>(1.7036004e-6, -7.775216e-8, 3.7184875e-9, -1.8531505e-10),
    vec4<f32>(9.639933e-12, -4.6398443e-13, 0e0, 0e0),
    vec4<f32>(6.0011274e-1, -2.1730753e-2, 7.6656416e-4, -2.8366827e-5),
    vec4<f32>(1.1063033e-6, -4.52452e-8, 1.9288653e-9, -8.550334e-11),
    vec4<f32>(3.923617e-12, -6.465939e-14, 0e0, 0e0),
    vec4<f32>(5.5950695e-1, -1.897278e-2, 6.197067e-4, -2.1059226e-5),
    vec4<f32>(7.494345e-7, -2.7825521e-8, 1.0723312e-9, -4.3035797e-11),
    vec4<f32>(1.811884e-12, 8.100187e-14, 0e0, 0e0),
    vec4<f32>(5.2388287e-1, -1.6724719e-2, 5.093432e-4, -1.602632e-5),
    vec4<f32>(5.2526724e-7, -1.7885863e-8, 6.3001837e-10, -2.3013235e-11),
    vec4<f32>(8.56204e-13, 4.1922022e-14, 0e0, 0e0),
    vec4<f32>(4.7789872e-1, -2.810214e-2, 1.5572221e-3, -8.838051e-5),
    vec4<f32>(5.1907828e-6, -3.150968e-7, 1.970239e-8, -1.2650648e-9),
    vec4<f32>(8.4108366e-11, -5.501022e-12, 0e0, 0e0),
    vec4<f32>(4.2729038e-1, -2.2789631e-2, 1.1303158e-3, -5.6890047e-5),
    vec4<f32>(2.942655e-6, -1.5646835e-7, 8.532486e-9, -4.761359e-10),
    vec4<f32>(2.7402792e-11, -1.4971135e-12, 0e0, 0e0),
    vec4<f32>(3.8581982e-1, -1.886795e-2, 8.488521e-4, -3.8467508e-5),
    vec4<f32>(1.7817267e-6, -8.44738e-8, 4.0935824e-9, -2.0220306e-10),
    vec4<f32>(1.0156498e-11, -5.755396e-13, 0e0, 0e0),
    vec4<f32>(3.5119763e-1, -1.588319e-2, 6.549132e-4, -2.7035181e-5),
    vec4<f32>(1.135561e-6, -4.8653796e-8, 2.1246034e-9, -9.453984e-11),
    vec4<f32>(4.342482e-12, -1.4495072e-13, 0e0, 0e0),
    vec4<f32>(3.0879384e-1, -2.515609e-2, 1.8478157e-3, -1.348767e-4),
    vec4<f32>(9.9630315e-6, -7.4757827e-7, 5.697885e-8, -4.4075037e-9),
    vec4<f32>(3.5114595e-10, -2.7911895e-11, 0e0, 0e0),
    vec4<f32>(2.6493257e-1, -1.9115072e-2, 1.2290902e-3, -7.792716e-5),
    vec4<f32>(4.972059e-6, -3.208716e-7, 2.0962961e-8, -1.3859125e-9),
    vec4<f32>(9.370922e-11, -6.3693053e-12, 0e0, 0e0),
    vec4<f32>(2.3106582e-1, -1.4996914e-2, 8.5942814e-4, -4.826962e-5),
    vec4<f32>(2.7163353e-6, -1.5409705e-7, 8.826524e-9, -5.1087223e-10),
    vec4<f32>(3.0091485e-11, -1.6100899e-12, 0e0, 0e0),
    vec4<f32>(2.041626e-1, -1.2062349e-2, 6.244964e-4, -3.15311e-5),
    vec4<f32>(1.5894985e-6, -8.055956e-8, 4.113857e-9, -2.1222872e-10),
    vec4<f32>(1.103082e-11, -3.684164e-13, 0e0, 0e0),
    vec4<f32>(1.7285645e-1, -1.8045181e-2, 1.6356099e-3, -1.4372423e-4),
    vec4<f32>(1.2556188e-5, -1.0993467e-6, 9.672248e-8, -8.561739e-9),
    vec4<f32>(7.782461e-10, -6.9794656e-11, 0e0, 0e0),
    vec4<f32>(1.4232971e-1, -1.2898196e-2, 1.0052373e-3, -7.549118e-5),
    vec4<f32>(5.6121708e-6, -4.16777e-7, 3.102492e-8, -2.3186955e-9),
    vec4<f32>(1.7656561e-10, -1.3273471e-11, 0e0, 0e0),
    vec4<f32>(1.20028526e-1, -9.631822e-3, 6.597896e-4, -4.334511e-5),
    vec4<f32>(2.8095578e-6, -1.8146298e-7, 1.1725502e-8, -7.595021e-10),
    vec4<f32>(4.9872995e-11, -3.2137847e-12, 0e0, 0e0),
    vec4<f32>(1.0309709e-1, -7.4354606e-3, 4.5501083e-4, -2.6602445e-5),
    vec4<f32>(1.5304726e-6, -8.756127e-8, 5.0039772e-9, -2.8630986e-10),
    vec4<f32>(1.6549605e-11, -9.274359e-13, 0e0, 0e0),
    vec4<f32>(8.4273346e-2, -1.0575515e-2, 1.1179436e-3, -1.1239671e-4),
    vec4<f32>(1.1084435e-5, -1.0844861e-6, 1.0577039e-7, -1.0312659e-8),
    vec4<f32>(1.0308846e-9, -1.0071277e-10, 0e0, 0e0),
    vec4<f32>(6.684323e-2, -7.168023e-3, 6.4272905e-4, -5.4559096e-5),
    vec4<f32>(4.5283036e-6, -3.7197273e-7, 3.040501e-8, -2.4805125e-9),
    vec4<f32>(2.0567867e-10, -1.6761526e-11, 0e0, 0e0),
    vec4<f32>(5.470385e-2, -5.131766e-3, 4.0022618e-4, -2.9444855e-5),
    vec4<f32>(2.112852e-6, -1.497738e-7, 1.0550057e-8, -7.408271e-10),
    vec4<f32>(5.2588333e-11, -3.6752823e-12, 0e0, 0e0),
    vec4<f32>(4.5835268e-2, -3.8268303e-3, 2.6439672e-4, -1.718297e-5),
    vec4<f32>(1.0870192e-6, -6.783347e-8, 4.2015844e-9, -2.5919678e-10),
    vec4<f32>(1.6105162e-11, -9.814816e-13, 0e0, 0e0),
    vec4<f32>(3.6344558e-2, -5.2188607e-3, 6.167174e-4, -6.831998e-5),
    vec4<f32>(7.3500064e-6, -7.7864263e-7, 8.1744744e-8, -8.539351e-9),
    vec4<f32>(9.138718e-10, -9.4969456e-11, 0e0, 0e0),
    vec4<f32>(2.7924158e-2, -3.386312e-3, 3.3604607e-4, -3.115492e-5),
    vec4<f32>(2.7983506e-6, -2.470724e-7, 2.1591491e-8, -1.875188e-9),
    vec4<f32>(1.6526011e-10, -1.4249313e-11, 0e0, 0e0),
    vec4<f32>(2.2284523e-2, -2.3427603e-3, 2.0067116e-4, -1.601577e-5),
    vec4<f32>(1.23614e-6, -9.3658834e-8, 7.0167454e-9, -5.219619e-10),
    vec4<f32>(3.9173574e-11, -2.8859137e-12, 0e0, 0e0),
    vec4<f32>(1.8290734e-2, -1.6990538e-3, 1.281427e-4, -8.985964e-6),
    vec4<f32>(6.084994e-7, -4.0406324e-8, 2.6508968e-9, -1.7256581e-10),
    vec4<f32>(1.1290325e-11, -7.252865e-13, 0e0, 0e0),
    vec4<f32>(1.4145321e-2, -2.2406406e-3, 2.8696412e-4, -3.408568e-5),
    vec4<f32>(3.9029387e-6, -4.376743e-7, 4.842992e-8, -5.314429e-9),
    vec4<f32>(5.972312e-10, -6.485042e-11, 0e0, 0e0),
    vec4<f32>(1.0590195e-2, -1.4045356e-3, 1.4997198e-4, -1.4813785e-5),
    vec4<f32>(1.4081163e-6, -1.3091567e-7, 1.2000194e-8, -1.0897881e-9),
    vec4<f32>(1.00322875e-10, -9.002898e-12, 0e0, 0e0),
    vec4<f32>(8.281491e-3, -9.459269e-4, 8.670181e-5, -7.3370716e-6),
    vec4<f32>(5.9669355e-7, -4.7416766e-8, 3.7123915e-9, -2.877658e-10),
    vec4<f32>(2.2474323e-11, -1.7184587e-12, 0e0, 0e0),
    vec4<f32>(6.6859834e-3, -6.712604e-4, 5.3937463e-5, -3.99511e-6),
    vec4<f32>(2.8407612e-7, -1.972195e-8, 1.3482018e-9, -9.120162e-11),
    vec4<f32>(6.191525e-12, -4.1198157e-13, 0e0, 0e0),
    vec4<f32>(5.068806e-3, -8.624461e-4, 1.1707453e-4, -1.4622326e-5),
    vec4<f32>(1.7509971e-6, -2.0452964e-7, 2.3499844e-8, -2.6711127e-9),
    vec4<f32>(3.1088374e-10, -3.483116e-11, 0e0, 0e0),
    vec4<f32>(3.7179298e-3, -5.263837e-4, 5.9266848e-5, -6.1279725e-6),
    vec4<f32>(6.067016e-7, -5.8536184e-8, 5.5523754e-9, -5.206078e-10),
    vec4<f32>(4.94469e-11, -4.5655758e-12, 0e0, 0e0),
    vec4<f32>(2.8613391e-3, -3.4724647e-4, 3.3429842e-5, -2.951127e-6),
    vec4<f32>(2.4920854e-7, -2.0493347e-8, 1.6559919e-9, -1.3220658e-10),
    vec4<f32>(1.0624052e-11, -8.342271e-13, 0e0, 0e0),
    vec4<f32>(2.2803796e-3, -2.4233757e-4, 2.038882e-5, -1.5711131e-6),
    vec4<f32>(1.1571718e-7, -8.294876e-9, 5.840337e-10, -4.061159e-11),
    vec4<f32>(2.8308994e-12, -1.9312607e-13, 0e0, 0e0),
    vec4<f32>(1.7021558e-3, -3.0520523e-4, 4.322169e-5, -5.5981413e-6),
    vec4<f32>(6.9238814e-7, -8.328658e-8, 9.831807e-9, -1.1461302e-9),
    vec4<f32>(1.3680011e-10, -1.5674503e-11, 0e0, 0e0),
    vec4<f32>(1.2287702e-3, -1.8252023e-4, 2.1360174e-5, -2.2830093e-6),
    vec4<f32>(2.3278474e-7, -2.3068317e-8, 2.2426903e-9, -2.151695e-10),
    vec4<f32>(2.090133e-11, -1.9697536e-12, 0e0, 0e0),
    vec4<f32>(9.3401317e-4, -1.1852049e-4, 1.1826654e-5, -1.0766075e-6),
    vec4<f32>(9.3427154e-8, -7.875315e-9, 6.510453e-10, -5.309224e-11),
    vec4<f32>(4.3550163e-12, -3.4856146e-13, 0e0, 0e0),
    vec4<f32>(7.369446e-4, -8.166858e-5, 7.1061822e-6, -5.6358084e-7),
    vec4<f32>(4.2582972e-8, -3.1239604e-9, 2.246961e-10, -1.5937906e-11),
    vec4<f32>(1.1323887e-12, -7.873285e-14, 0e0, 0e0),
    vec4<f32>(5.43503e-4, -1.0130456e-4, 1.4798497e-5, -1.9682495e-6),
    vec4<f32>(2.4922562e-7, -3.0624445e-8, 3.686629e-9, -4.3768214e-10),
    vec4<f32>(5.3201877e-11, -6.19516e-12, 0e0, 0e0),
    vec4<f32>(3.8754012e-4, -5.9650654e-5, 7.182156e-6, -7.864899e-7),
    vec4<f32>(8.1933905e-8, -8.278807e-9, 8.1937507e-10, -7.993216e-11),
    vec4<f32>(7.89196e-12, -7.547844e-13, 0e0, 0e0),
    vec4<f32>(2.917654e-4, -3.82723e-5, 3.9213664e-6, -3.6510684e-7),
    vec4<f32>(3.2321285e-8, -2.7740423e-9, 2.3315905e-10, -1.9309316e-11),
    vec4<f32>(1.6076817e-12, -1.3045363e-13, 0e0, 0e0),
    vec4<f32>(2.284266e-4, -2.611827e-5, 2.3298414e-6, -1.8872943e-7),
    vec4<f32>(1.4529161e-8, -1.084061e-9, 7.919366e-11, -5.6990367e-12),
    vec4<f32>(4.105643e-13, -2.8903617e-14, 0e0, 0e0),
    vec4<f32>(1.6690556e-4, -3.2025397e-5, 4.7871736e-6, -6.492874e-7),
    vec4<f32>(8.36461e-8, -1.0439839e-8, 1.274866e-9, -1.5338152e-10),
    vec4<f32>(1.8893371e-11, -2.2260173e-12, 0e0, 0e0),
    vec4<f32>(1.178792e-4, -1.8635772e-5, 2.2917989e-6, -2.5551182e-7),
    vec4<f32>(2.7042812e-8, -2.771769e-9, 2.7794428e-10, -2.7446035e-11),
    vec4<f32>(2.742249e-12, -2.6510304e-13, 0e0, 0e0),
    vec4<f32>(8.80896e-5, -1.1847759e-5, 1.2381256e-6, -1.17222676e-7),
    vec4<f32>(1.05311315e-8, -9.159385e-10, 7.792758e-11, -6.52699e-12),
    vec4<f32>(5.493923e-13, -4.502492e-14, 0e0, 0e0),
    vec4<f32>(6.855226e-5, -8.025702e-6, 7.2937826e-7, -6.00217e-8),
    vec4<f32>(4.6851816e-9, -3.5396633e-10, 2.6155694e-11, -1.9023296e-12),
    vec4<f32>(1.3844716e-13, -9.838744e-15, 0e0, 0e0),
    vec4<f32>(4.9728107e-5, -9.754038e-6, 1.4834819e-6, -2.041669e-7),
    vec4<f32>(2.6642027e-8, -3.3638188e-9, 4.1513548e-10, -5.043788e-11),
    vec4<f32>(6.2739276e-12, -7.455859e-13, 0e0, 0e0),
    vec4<f32>(3.4860626e-5, -5.6246495e-6, 7.0284705e-7, -7.9422215e-8),
    vec4<f32>(8.505716e-9, -8.8110447e-10, 8.921613e-11, -8.889397e-12),
    vec4<f32>(8.960091e-13, -8.7307765e-14, 0e0, 0e0),
    vec4<f32>(2.5899995e-5, -3.5507492e-6, 3.7665586e-7, -3.611259e-8),
    vec4<f32>(3.2802823e-9, -2.8814096e-10, 2.4737804e-11, -2.0894055e-12),
    vec4<f32>(1.7729594e-13, -1.4637986e-14, 0e0, 0e0),
    vec4<f32>(2.0060837e-5, -2.3915948e-6, 2.2044664e-7, -1.8357941e-8),
    vec4<f32>(1.4479783e-9, -1.104218e-10, 8.229325e-12, -6.032673e-13),
    vec4<f32>(4.423701e-14, -3.166998e-15, 0e0, 0e0),
    vec4<f32>(1.4469778e-5, -2.8867664e-6, 4.448795e-7, -6.19091e-8),
    vec4<f32>(8.157163e-9, -1.0388977e-9, 1.2923003e-10, -1.5816471e-11),
    vec4<f32>(1.9817882e-12, -2.3702492e-13, 0e0, 0e0),
    vec4<f32>(1.00844045e-5, -1.6529644e-6, 2.0909607e-7, -2.387142e-8),
    vec4<f32>(2.5794742e-9, -2.6935565e-10, 2.7473307e-11, -2.755933e-12),
    vec4<f32>(2.7961552e-13, -2.7407211e-14, 0e0, 0e0),
    vec4<f32>(7.4580053e-6, -1.0377724e-6, 1.1135919e-7, -1.07799805e-8),
    vec4<f32>(9.874419e-10, -8.739019e-11, 7.554136e-12, -6.420734e-13),
    vec4<f32>(5.481437e-14, -4.5507e-15, 0e0, 0e0),
    vec4<f32>(5.755073e-6, -6.9587924e-7, 6.484783e-8, -5.449747e-9),
    vec4<f32>(4.3327325e-10, -3.3276385e-11, 2.4960303e-12, -1.8406938e-13),
    vec4<f32>(1.357445e-14, -9.770288e-16, 0e0, 0e0),
    vec4<f32>(4.1324206e-6, -8.3546064e-7, 1.3007761e-7, -1.8256513e-8),
    vec4<f32>(2.4233802e-9, -3.106914e-10, 3.8880246e-11, -4.785022e-12),
    vec4<f32>(6.02871e-13, -7.245272e-14, 0e0, 0e0),
    vec4<f32>(2.8665863e-6, -4.757435e-7, 6.075729e-8, -6.99157e-9),
    vec4<f32>(7.607056e-10, -7.9923915e-11, 8.197489e-12, -8.2654754e-13),
    vec4<f32>(8.428025e-14, -8.297784e-15, 0e0, 0e0),
    vec4<f32>(2.1122462e-6, -2.9739175e-7, 3.2200596e-8, -3.1405187e-9),
    vec4<f32>(2.895396e-10, -2.577299e-11, 2.2395467e-12, -1.912721e-13),
    vec4<f32>(1.6404689e-14, -1.3677346e-15, 0e0, 0e0),
    vec4<f32>(1.6250713e-6, -1.9871392e-7, 1.8677358e-8, -1.5808235e-9),
    vec4<f32>(1.2645662e-10, -9.765496e-12, 7.361468e-13, -5.4535498e-14),
    vec4<f32>(4.0393036e-15, -2.9189163e-16, 0e0, 0e0),
    vec4<f32>(1.1626524e-6, -2.3755727e-7, 3.728639e-8, -5.268233e-9),
    vec4<f32>(7.0335604e-10, -9.063811e-11, 1.13953005e-11, -1.4084296e-12),
    vec4<f32>(1.7820226e-13, -2.1495511e-14, 0e0, 0e0),
    vec4<f32>(8.0347553e-7, -1.3467825e-7, 1.7330278e-8, -2.0067412e-9),
    vec4<f32>(2.195189e-10, -2.3174383e-11, 2.387205e-12, -2.4165793e-13),
    vec4<f32>(2.4736042e-14, -2.4437714e-15, 0e0, 0e0),
    vec4<f32>(5.90284e-7, -8.389701e-8, 9.1493995e-9, -8.976225e-10),
    vec4<f32>(8.317834e-11, -7.437497e-12, 6.4892324e-13, -5.5630102e-14),
    vec4<f32>(4.7882984e-15, -4.0051376e-16, 0e0, 0e0),
    vec4<f32>(4.530349e-7, -5.5900433e-8, 5.2902474e-9, -4.5028845e-10),
    vec4<f32>(3.6195612e-11, -2.8072124e-12, 2.1243767e-13, -1.5793998e-14),
    vec4<f32>(1.1737728e-15, -8.507463e-17, 0e0, 0e0),
    vec4<f32>(3.231643e-7, -6.6598226e-8, 1.0520944e-8, -1.4944364e-9),
    vec4<f32>(2.0043442e-10, -2.5933682e-11, 3.2723644e-12, -4.0580996e-13),
    vec4<f32>(5.151519e-14, -6.231861e-15, 0e0, 0e0),
    vec4<f32>(2.2264099e-7, -3.7621838e-8, 4.8707047e-9, -5.668196e-10),
    vec4<f32>(6.2271036e-11, -6.5988287e-12, 6.8207164e-13, -6.926242e-14),
    vec4<f32>(7.111115e-15, -7.0442987e-16, 0e0, 0e0),
    vec4<f32>(1.6316703e-7, -2.3370331e-8, 2.5634588e-9, -2.5268887e-10),
    vec4<f32>(2.3510823e-11, -2.109808e-12, 1.8467703e-13, -1.5878617e-14),
    vec4<f32>(1.3705918e-15, -1.149339e-16, 0e0, 0e0),
    vec4<f32>(1.2497743e-7, -1.5535694e-8, 1.4784393e-9, -1.2641242e-10),
    vec4<f32>(1.0201018e-11, -7.938756e-13, 6.0262796e-14, -4.4929783e-15),
    vec4<f32>(3.3479808e-16, -2.4327125e-17, 0e0, 0e0),
    vec4<f32>(8.893243e-8, -1.8456852e-8, 2.9311524e-9, -4.181466e-10),
    vec4<f32>(5.6288658e-11, -7.306685e-12, 9.246588e-13, -1.1497358e-13),
    vec4<f32>(1.463354e-14, -1.7742684e-15, 0e0, 0e0),
    vec4<f32>(6.111235e-8, -1.0395877e-8, 1.3526198e-9, -1.5804848e-10),
    vec4<f32>(1.742353e-11, -1.8520003e-12, 1.9195213e-13, -1.9540937e-14),
    vec4<f32>(2.0110864e-15, -1.9964626e-16, 0e0, 0e0),
    vec4<f32>(4.4696407e-8, -6.442839e-9, 7.1007455e-10, -7.026569e-11),
    vec4<f32>(6.5593065e-12, -5.903272e-13, 5.1807564e-14, -4.4650186e-15),
    vec4<f32>(3.8627582e-16, -3.245839e-17, 0e0, 0e0),
    vec4<f32>(3.4177788e-8, -4.274783e-9, 4.0867057e-10, -3.5073017e-11),
    vec4<f32>(2.8392393e-12, -2.215741e-13, 1.6861616e-14, -1.260001e-15),
    vec4<f32>(9.409147e-17, -6.850294e-18, 0e0, 0e0),
    vec4<f32>(2.4270674e-8, -5.066745e-9, 8.081684e-10, -1.15698166e-10),
    vec4<f32>(1.5621579e-11, -2.0331558e-12, 2.579035e-13, -3.2137243e-14),
    vec4<f32>(4.099008e-15, -4.979024e-16, 0e0, 0e0),
    vec4<f32>(1.664237e-8, -2.8469e-9, 3.71948e-10, -4.3606414e-11),
    vec4<f32>(4.8209414e-12, -5.1371223e-13, 5.3363062e-14, -5.443459e-15),
    vec4<f32>(5.613163e-16, -5.581949e-17, 0e0, 0e0),
    vec4<f32>(1.2151041e-8, -1.7609452e-9, 1.9484654e-10, -1.9342954e-11),
    vec4<f32>(1.8105826e-12, -1.6333809e-13, 1.4365233e-14, -1.2404618e-15),
    vec4<f32>(1.07511755e-16, -9.04898e-18, 0e0, 0e0),
    vec4<f32>(9.27832e-9, -1.1665093e-9, 1.11945536e-10, -9.637102e-12),
    vec4<f32>(7.821897e-13, -6.118203e-14, 4.6654456e-15, -3.4927864e-16),
    vec4<f32>(2.6128478e-17, -1.9054006e-18, 0e0, 0e0),
    vec4<f32>(6.577366e-9, -1.3799166e-9, 2.2090814e-10, -3.1718694e-11),
    vec4<f32>(4.293362e-12, -5.6000343e-13, 7.117414e-14, -8.884677e-15),
    vec4<f32>(1.1351801e-15, -1.3809573e-16, 0e0, 0e0),
    vec4<f32>(4.5018345e-9, -7.737527e-10, 1.0144317e-10, -1.1926342e-11),
    vec4<f32>(1.321655e-12, -1.4112542e-13, 1.4686821e-14, -1.5006847e-15),
    vec4<f32>(1.5499571e-16, -1.5435354e-17, 0e0, 0e0),
    vec4<f32>(3.2821017e-9, -4.7781873e-10, 5.304712e-11, -5.2803087e-12),
    vec4<f32>(4.9538395e-13, -4.4778797e-14, 3.945168e-15, -3.4121862e-16),
    vec4<f32>(2.9618492e-17, -2.4961108e-18, 0e0, 0e0),
    vec4<f32>(2.5031188e-9, -3.1609426e-10, 3.0432604e-11, -2.6266764e-12),
    vec4<f32>(2.1366085e-13, -1.6744322e-14, 1.2790194e-15, -9.590159e-17),
    vec4<f32>(7.184515e-18, -5.246787e-19, 0e0, 0e0),
    vec4<f32>(1.7718077e-9, -3.733001e-10, 5.9946416e-11, -8.628729e-12),
    vec4<f32>(1.1704168e-12, -1.5294238e-13, 1.9469977e-14, -2.4340248e-15),
    vec4<f32>(3.1143985e-16, -3.793398e-17, 0e0, 0e0),
    vec4<f32>(1.2107926e-9, -2.089512e-10, 2.7475916e-11, -3.2379295e-12),
    vec4<f32>(3.5954e-13, -3.8458355e-14, 4.008537e-15, -4.1016266e-16),
    vec4<f32>(4.2419804e-17, -4.2294154e-18, 0e0, 0e0),
    vec4<f32>(8.816253e-10, -1.2885348e-10, 1.43461285e-11, -1.4312796e-12),
    vec4<f32>(1.3453732e-13, -1.2181482e-14, 1.074829e-15, -9.308721e-17),
    vec4<f32>(8.09046e-18, -6.8268074e-19, 0e0, 0e0),
    vec4<f32>(6.71674e-10, -8.5142136e-11, 8.219944e-12, -7.1104516e-13),
    vec4<f32>(5.79461e-14, -4.548516e-15, 3.4793964e-16, -2.6122716e-17),
    vec4<f32>(1.9593713e-18, -1.4321342e-19, 0e0, 0e0),
    vec4<f32>(4.748241e-10, -1.00407085e-10, 1.6166842e-11, -2.3320172e-12),
    vec4<f32>(3.1688484e-13, -4.1472746e-14, 5.2868624e-15, -6.617563e-16),
    vec4<f32>(8.4776365e-17, -1.03367194e-17, 0e0, 0e0),
    vec4<f32>(3.240348e-10, -5.6116892e-11, 7.397906e-12, -8.7359015e-13),
    vec4<f32>(9.716947e-14, -1.0409202e-14, 1.0863853e-15, -1.1129359e-16),
    vec4<f32>(1.1523243e-17, -1.1500411e-18, 0e0, 0e0),
    vec4<f32>(2.3568322e-10, -3.456351e-11, 3.857684e-12, -3.8562865e-13),
    vec4<f32>(3.6308088e-14, -3.292164e-15, 2.9085137e-16, -2.5218464e-17),
    vec4<f32>(2.1941588e-18, -1.8531294e-19, 0e0, 0e0),
    vec4<f32>(1.7939335e-10, -2.2815425e-11, 2.2079664e-12, -1.9135881e-13),
    vec4<f32>(1.561959e-14, -1.2277695e-15, 9.403388e-17, -7.067714e-18),
    vec4<f32>(5.306708e-19, -3.882852e-20, 0e0, 0e0),
    vec4<f32>(1.2667484e-10, -2.6872529e-11, 4.3368226e-12, -6.267226e-13),
    vec4<f32>(8.529293e-14, -1.1177713e-14, 1.4265926e-15, -1.7875654e-16),
    vec4<f32>(2.2923901e-17, -2.7975774e-18, 0e0, 0e0),
    vec4<f32>(8.634329e-11, -1.4999108e-11, 1.9817284e-12, -2.3442744e-13),
    vec4<f32>(2.6113877e-14, -2.8010033e-15, 2.9266502e-16, -3.0012286e-17),
    vec4<f32>(3.1104646e-18, -3.1069912e-19, 0e0, 0e0),
    vec4<f32>(6.274029e-11, -9.2284696e-12, 1.0322179e-12, -1.0336044e-13),
    vec4<f32>(9.745585e-15, -8.8475254e-16, 7.82502e-17, -6.791401e-18),
    vec4<f32>(5.914394e-19, -4.9995126e-20, 0e0, 0e0),
    vec4<f32>(4.7717223e-11, -6.0863628e-12, 5.9024107e-13, -5.1239554e-14),
    vec4<f32>(4.1882107e-15, -3.2960675e-16, 2.5271084e-17, -1.9012217e-18),
    vec4<f32>(1.4287783e-19, -1.0462263e-20, 0e0, 0e0),
    vec4<f32>(3.366101e-11, -7.1608544e-12, 1.1579908e-12, -1.676115e-13),
    vec4<f32>(2.2841377e-14, -2.9968424e-15, 3.8287213e-16, -4.8019168e-17),
    vec4<f32>(6.1635233e-18, -7.527568e-19, 0e0, 0e0),
    vec4<f32>(2.2919524e-11, -3.992263e-12, 5.284977e-13, -6.261472e-14),
    vec4<f32>(6.9838997e-15, -7.4993317e-16, 7.843422e-17, -8.050389e-18),
    vec4<f32>(8.3503955e-19, -8.347183e-20, 0e0, 0e0),
    vec4<f32>(1.663998e-11, -2.4540233e-12, 2.7500485e-13, -2.757858e-14),
    vec4<f32>(2.6035538e-15, -2.366178e-16, 2.0947069e-17, -1.8195653e-18),
    vec4<f32>(1.5858689e-19, -1.3414987e-20, 0e0, 0e0),
    vec4<f32>(1.26465505e-11, -1.6172217e-12, 1.5712322e-13, -1.3659915e-14),
    vec4<f32>(1.1178871e-15, -8.806836e-17, 6.758475e-18, -5.0888213e-19),
    vec4<f32>(3.827249e-20, -2.804742e-21, 0e0, 0e0),
    vec4<f32>(8.913342e-12, -1.9008985e-12, 3.0794494e-13, -4.4635763e-14),
    vec4<f32>(6.089908e-15, -7.998185e-16, 1.0227466e-16, -1.2837391e-17),
    vec4<f32>(1.6490309e-18, -2.0153152e-19, 0e0, 0e0),
    vec4<f32>(6.0633148e-12, -1.0586894e-12, 1.4039117e-13, -1.66557e-14),
    vec4<f32>(1.8598398e-15, -1.9990477e-16, 2.0925653e-17, -2.1494387e-18),
    vec4<f32>(2.2311726e-19, -2.2317436e-20, 0e0, 0e0),
    vec4<f32>(4.398726e-12, -6.502334e-13, 7.2988965e-14, -7.329282e-15),
    vec4<f32>(6.926801e-16, -6.3012104e-17, 5.5829215e-18, -4.8532227e-19),
    vec4<f32>(4.2328574e-20, -3.582933e-21, 0e0, 0e0),
    vec4<f32>(3.3409519e-12, -4.2821378e-13, 4.167162e-14, -3.627494e-15),
    vec4<f32>(2.9718122e-16, -2.3433835e-17, 1.7998015e-18, -1.356154e-19),
    vec4<f32>(1.020639e-20, -7.4844336e-22, 0e0, 0e0),
    vec4<f32>(2.3528597e-12, -5.028965e-13, 8.1598174e-14, -1.18421855e-14),
    vec4<f32>(1.6173719e-15, -2.1260718e-16, 2.7207908e-17, -3.4175093e-18),
    vec4<f32>(4.3929696e-19, -5.3718686e-20, 0e0, 0e0),
    vec4<f32>(1.599188e-12, -2.798285e-13, 3.716453e-14, -4.414437e-15),
    vec4<f32>(4.934271e-16, -5.308168e-17, 5.560702e-18, -5.7157177e-19),
    vec4<f32>(5.936888e-20, -5.9417365e-21, 0e0, 0e0),
    vec4<f32>(1.159365e-12, -1.7174036e-13, 1.9306698e-14, -1.9409824e-15),
    vec4<f32>(1.8361823e-16, -1.671747e-17, 1.4822721e-18, -1.2893876e-19),
    vec4<f32>(1.1252661e-20, -9.529651e-22, 0e0, 0e0),
    vec4<f32>(8.8006696e-13, -1.1303061e-13, 1.1015619e-14, -9.600034e-16),
    vec4<f32>(7.872278e-17, -6.212655e-18, 4.7749694e-19, -3.6002703e-20),
    vec4<f32>(2.7111814e-21, -1.9889688e-22, 0e0, 0e0),
    vec4<f32>(6.193462e-13, -1.3264215e-13, 2.1552545e-14, -3.1313607e-15),
    vec4<f32>(4.2806718e-16, -5.6315005e-17, 7.211799e-18, -9.064193e-19),
    vec4<f32>(1.1658428e-19, -1.4263673e-20, 0e0, 0e0),
    vec4<f32>(4.20637e-13, -7.37462e-14, 9.8078224e-15, -1.1662383e-15),
    vec4<f32>(1.3047367e-16, -1.4046807e-17, 1.4724996e-18, -1.5144617e-19),
    vec4<f32>(1.5739623e-20, -1.576037e-21, 0e0, 0e0),
    vec4<f32>(3.0476218e-13, -4.5230614e-14, 5.091542e-15, -5.1241136e-16),
    vec4<f32>(4.8516648e-17, -4.420483e-18, 3.922039e-19, -3.4136745e-20),
    vec4<f32>(2.9807928e-21, -2.5256506e-22, 0e0, 0e0),
    vec4<f32>(2.3122403e-13, -2.9751954e-14, 2.9033346e-15, -2.5328347e-16),
    vec4<f32>(2.0787578e-17, -1.6417142e-18, 1.26261e-19, -9.5253725e-21),
    vec4<f32>(7.1769035e-22, -5.268236e-23, 0e0, 0e0),
    vec4<f32>(1.626194e-13, -3.4890056e-14, 5.6763888e-15, -8.255442e-16),
    vec4<f32>(1.1294791e-16, -1.4869566e-17, 1.9054066e-18, -2.3961556e-19),
    vec4<f32>(3.0836114e-20, -3.7744167e-21, 0e0, 0e0),
    vec4<f32>(1.10369254e-13, -1.9383822e-14, 2.581129e-15, -3.0721692e-16),
    vec4<f32>(3.439766e-17, -3.7058006e-18, 3.8870615e-19, -3.9999873e-20),
    vec4<f32>(4.159263e-21, -4.166617e-22, 0e0, 0e0),
    vec4<f32>(7.99208e-14, -1.1881537e-14, 1.3391028e-15, -1.3489435e-16),
    vec4<f32>(1.27821896e-17, -1.1654002e-18, 1.0345999e-19, -9.009708e-21),
    vec4<f32>(7.8710774e-22, -6.672181e-23, 0e0, 0e0),
    vec4<f32>(6.0607837e-14, -7.811566e-15, 7.631913e-16, -6.664154e-17),
    vec4<f32>(5.473617e-18, -4.3256632e-19, 3.3286956e-20, -2.512525e-21),
    vec4<f32>(1.8939657e-22, -1.3907458e-23, 0e0, 0e0),
    vec4<f32>(4.2600567e-14, -9.1548956e-15, 1.4911606e-15, -2.170621e-16),
    vec4<f32>(2.9719766e-17, -3.9150963e-18, 5.0196613e-19, -6.315659e-20),
    vec4<f32>(8.1315425e-21, -9.957309e-22, 0e0, 0e0),
    vec4<f32>(2.8894818e-14, -5.0827745e-15, 6.775757e-16, -8.071858e-17),
    vec4<f32>(9.044229e-18, -9.749752e-19, 1.02321886e-19, -1.0534557e-20),
    vec4<f32>(1.0959051e-21, -1.0982789e-22, 0e0, 0e0),
    vec4<f32>(2.0912762e-14, -3.1138553e-15, 3.5133002e-16, -3.542147e-17),
    vec4<f32>(3.3588051e-18, -3.0641998e-19, 2.721726e-20, -2.3713083e-21),
    vec4<f32>(2.072539e-22, -1.7575326e-23, 0e0, 0e0),
    vec4<f32>(1.5852418e-14, -2.046286e-15, 2.0013726e-16, -1.7490557e-17),
    vec4<f32>(1.4375852e-18, -1.1367605e-19, 8.752169e-21, -6.60926e-22),
    vec4<f32>(4.9842277e-23, -3.6614655e-24, 0e0, 0e0),
    vec4<f32>(1.11365715e-14, -2.3968193e-15, 3.9080605e-16, -5.6934544e-17),
    vec4<f32>(7.80064e-18, -1.0282005e-18, 1.3189516e-19, -1.6602329e-20),
    vec4<f32>(2.1385145e-21, -2.6196422e-22, 0e0, 0e0),
    vec4<f32>(7.549331e-15, -1.3298985e-15, 1.7746731e-16, -2.1158236e-17),
    vec4<f32>(2.3722607e-18, -2.558751e-19, 2.6866813e-20, -2.7672865e-21),
    vec4<f32>(2.879986e-22, -2.8872782e-23, 0e0, 0e0),
    vec4<f32>(5.4613313e-15, -8.1433165e-16, 9.19711e-17, -9.279837e-18),
    vec4<f32>(8.805158e-19, -8.037249e-20, 7.1423815e-21, -6.225476e-22),
    vec4<f32>(5.4432835e-23, -4.6175397e-24, 0e0, 0e0),
    vec4<f32>(4.1382193e-15, -5.349201e-16, 5.236918e-17, -4.5801826e-18),
    vec4<f32>(3.7669156e-19, -2.9802632e-20, 2.2956496e-21, -1.7343017e-22),
    vec4<f32>(1.3083999e-23, -9.615318e-25, 0e0, 0e0),
    vec4<f32>(2.9057503e-15, -6.262287e-16, 1.0220549e-16, -1.4900893e-17),
    vec4<f32>(2.0428346e-18, -2.6940675e-19, 3.4574705e-20, -4.3538777e-21),
    vec4<f32>(5.61036e-22, -6.8749e-23, 0e0, 0e0),
    vec4<f32>(1.9687396e-15, -3.4727583e-16, 4.6385175e-17, -5.5342072e-18),
    vec4<f32>(6.208661e-19, -6.7001604e-20, 7.038289e-21, -7.2523353e-22),
    vec4<f32>(7.5505254e-23, -7.572116e-24, 0e0, 0e0),
    vec4<f32>(1.4236181e-15, -2.1254988e-16, 2.4027425e-17, -2.4260773e-18),
    vec4<f32>(2.303326e-19, -2.1034996e-20, 1.8701122e-21, -1.6306699e-22),
    vec4<f32>(1.4263022e-23, -1.2103322e-24, 0e0, 0e0),
    vec4<f32>(1.0783335e-15, -1.3956718e-16, 1.367601e-17, -1.1969315e-18),
    vec4<f32>(9.849671e-20, -7.796564e-21, 6.0081434e-22, -4.5407263e-23),
    vec4<f32>(3.426818e-24, -2.519079e-25, 0e0, 0e0),
    vec4<f32>(7.568395e-16, -1.6331314e-16, 2.6677369e-17, -3.892037e-18),
    vec4<f32>(5.3387736e-19, -7.0440846e-20, 9.043905e-21, -1.1392934e-21),
    vec4<f32>(1.4686085e-22, -1.8001729e-23, 0e0, 0e0),
    vec4<f32>(5.1253657e-16, -9.051926e-17, 1.2100881e-17, -1.4447138e-18),
    vec4<f32>(1.6216677e-19, -1.7508607e-20, 1.839969e-21, -1.896614e-22),
    vec4<f32>(1.9752722e-23, -1.9815013e-24, 0e0, 0e0),
    vec4<f32>(3.7047585e-16, -5.537921e-17, 6.2655184e-18, -6.330488e-19),
    vec4<f32>(6.013406e-20, -5.4942176e-21, 4.886573e-22, -4.262428e-23),
    vec4<f32>(3.729463e-24, -3.1656547e-25, 0e0, 0e0),
    vec4<f32>(2.8052807e-16, -3.6351087e-17, 3.5649317e-18, -3.1220433e-19),
    vec4<f32>(2.5705134e-20, -2.0356174e-21, 1.5692906e-22, -1.18642424e-23),
    vec4<f32>(8.956717e-25, -6.585758e-26, 0e0, 0e0),
    vec4<f32>(1.9681034e-16, -4.251728e-17, 6.950841e-18, -1.0147128e-18),
    vec4<f32>(1.3926152e-19, -1.8382501e-20, 2.3610336e-21, -2.9752935e-22),
    vec4<f32>(3.8365676e-23, -4.7040462e-24, 0e0, 0e0),
    vec4<f32>(1.3322206e-16, -2.3554891e-17, 3.1513668e-18, -3.7646897e-19),
    vec4<f32>(4.2279253e-20, -4.566704e-21, 4.800914e-22, -4.9503597e-23),
    vec4<f32>(5.1572823e-24, -5.174967e-25, 0e0, 0e0),
    vec4<f32>(9.6261794e-17, -1.4405238e-17, 1.6310453e-18, -1.6489456e-19),
    vec4<f32>(1.5671244e-20, -1.4324217e-21, 1.2744663e-22, -1.11204625e-23),
    vec4<f32>(9.732928e-25, -8.2633654e-26, 0e0, 0e0),
    vec4<f32>(7.2868186e-17, -9.452594e-18, 9.277152e-19, -8.1293954e-20),
    vec4<f32>(6.6965226e-21, -5.3052347e-22, 4.0913637e-23, -3.0941665e-24),
    vec4<f32>(2.336577e-25, -1.7185256e-26, 0e0, 0e0),
    vec4<f32>(5.1102705e-17, -1.1051569e-17, 1.8080849e-18, -2.641041e-19),
    vec4<f32>(3.6263424e-20, -4.788698e-21, 6.152727e-22, -7.7558835e-23),
    vec4<f32>(1.0004033e-23, -1.2269174e-24, 0e0, 0e0),
    vec4<f32>(3.4577496e-17, -6.1199917e-18, 8.193784e-19, -9.793987e-20),
    vec4<f32>(1.1004203e-20, -1.189064e-21, 1.2504764e-22, -1.2897963e-23),
    vec4<f32>(1.344095e-24, -1.3490323e-25, 0e0, 0e0),
    vec4<f32>(2.4976156e-17, -3.741418e-18, 4.239277e-19, -4.2881734e-20),
    vec4<f32>(4.0772427e-21, -3.728222e-22, 3.3182235e-23, -2.8962101e-24),
    vec4<f32>(2.5355437e-25, -2.1532904e-26, 0e0, 0e0),
    vec4<f32>(1.8901089e-17, -2.4543543e-18, 2.4104935e-19, -2.1134205e-20),
    vec4<f32>(1.7416904e-21, -1.3803565e-22, 1.0648751e-23, -8.055672e-25),
    vec4<f32>(6.0849735e-26, -4.4769632e-27, 0e0, 0e0),
);

// Exponential Λ(√q), q = z² < 64: the Rust EXPONENTIAL32_QA (f32 cubics), bit for bit.
const MS_EXP_QA_K0: i32 = -24;
const MS_EXP_QA_K1: i32 = 6;
const MS_EXP_QA_M: u32 = 5u;
var<private> MS_EXP_QA: array<vec4<f32>, 960> = array<vec4<f32>, 960>(
    vec4<f32>(2.5869585e3, -1.9903526e1, 2.2969571e-1, -2.9448576e-3),
    vec4<f32>(2.548047e3, -1.9019007e1, 2.1293393e-1, -2.6484663e-3),
    vec4<f32>(2.51084e3, -1.8198116e1, 1.978359e-1, -2.3893518e-3),
    vec4<f32>(2.4752163e3, -1.7434622e1, 1.8419519e-1, -2.1619403e-3),
    vec4<f32>(2.441067e3, -1.672306e1, 1.7183578e-1, -1.9616173e-3),
    vec4<f32>(2.4082927e3, -1.6058619e1, 1.60607e-1, -1.7845407e-3),
    vec4<f32>(2.376804e3, -1.5437037e1, 1.5037926e-1, -1.6274971e-3),
    vec4<f32>(2.3465186e3, -1.48545475e1, 1.4104067e-1, -1.4877847e-3),
    vec4<f32>(2.3173618e3, -1.4307789e1, 1.3249426e-1, -1.3631218e-3),
    vec4<f32>(2.2892656e3, -1.3793768e1, 1.2465568e-1, -1.2515737e-3),
    vec4<f32>(2.2621667e3, -1.3309804e1, 1.174513e-1, -1.1514927e-3),
    vec4<f32>(2.2360078e3, -1.2853494e1, 1.1081665e-1, -1.0614704e-3),
    vec4<f32>(2.2107358e3, -1.2422672e1, 1.0469508e-1, -9.802983e-4),
    vec4<f32>(2.1863015e3, -1.2015392e1, 9.9036686e-2, -9.069357e-4),
    vec4<f32>(2.1626597e3, -1.162989e1, 9.379735e-2, -8.404837e-4),
    vec4<f32>(2.1397686e3, -1.126457e1, 8.8938005e-2, -7.80163e-4),
    vec4<f32>(2.1175889e3, -1.0917984e1, 8.4423944e-2, -7.2529615e-4),
    vec4<f32>(2.096085e3, -1.0588813e1, 8.0224246e-2, -6.752923e-4),
    vec4<f32>(2.075223e3, -1.0275856e1, 7.631131e-2, -6.296349e-4),
    vec4<f32>(2.0549714e3, -9.978017e0, 7.266045e-2, -5.87871e-4),
    vec4<f32>(2.0353014e3, -9.694292e0, 6.9249526e-2, -5.496023e-4),
    vec4<f32>(2.0161855e3, -9.423763e0, 6.605863e-2, -5.144779e-4),
    vec4<f32>(1.9975981e3, -9.165587e0, 6.306984e-2, -4.821877e-4),
    vec4<f32>(1.9795155e3, -8.918988e0, 6.0267e-2, -4.524571e-4),
    vec4<f32>(1.9619149e3, -8.683251e0, 5.7635494e-2, -4.2504247e-4),
    vec4<f32>(1.9447756e3, -8.45772e0, 5.5162083e-2, -3.9972703e-4),
    vec4<f32>(1.9280776e3, -8.241784e0, 5.2834768e-2, -3.7631762e-4),
    vec4<f32>(1.9118025e3, -8.0348835e0, 5.0642632e-2, -3.5464176e-4),
    vec4<f32>(1.8959325e3, -7.8364973e0, 4.857575e-2, -3.3454507e-4),
    vec4<f32>(1.8804512e3, -7.6461425e0, 4.6625067e-2, -3.1588922e-4),
    vec4<f32>(1.8653429e3, -7.463371e0, 4.478232e-2, -2.985499e-4),
    vec4<f32>(1.8505929e3, -7.287767e0, 4.303994e-2, -2.8241533e-4),
    vec4<f32>(1.8291095e3, -1.4073918e1, 1.624194e-1, -2.0823288e-3),
    vec4<f32>(1.801595e3, -1.3448469e1, 1.5056702e-1, -1.8727485e-3),
    vec4<f32>(1.7752856e3, -1.28680105e1, 1.398911e-1, -1.6895268e-3),
    vec4<f32>(1.7500958e3, -1.2328139e1, 1.3024567e-1, -1.5287227e-3),
    vec4<f32>(1.7259486e3, -1.1824989e1, 1.21506244e-1, -1.3870728e-3),
    vec4<f32>(1.7027737e3, -1.1355157e1, 1.13566294e-1, -1.2618608e-3),
    vec4<f32>(1.6805077e3, -1.0915634e1, 1.0633419e-1, -1.1508142e-3),
    vec4<f32>(1.6590928e3, -1.0503751e1, 9.9730805e-2, -1.0520226e-3),
    vec4<f32>(1.638476e3, -1.0117134e1, 9.368759e-2, -9.6387265e-4),
    vec4<f32>(1.6186088e3, -9.753667e0, 8.8144876e-2, -8.849962e-4),
    vec4<f32>(1.599447e3, -9.411452e0, 8.3050616e-2, -8.1422826e-4),
    vec4<f32>(1.58095e3, -9.088792e0, 7.835921e-2, -7.505729e-4),
    vec4<f32>(1.5630798e3, -8.784156e0, 7.40306e-2, -6.9317553e-4),
    vec4<f32>(1.5458022e3, -8.496165e0, 7.002951e-2, -6.413004e-4),
    vec4<f32>(1.529085e3, -8.223575e0, 6.632474e-2, -5.9431174e-4),
    vec4<f32>(1.5128984e3, -7.9652543e0, 6.288867e-2, -5.5165857e-4),
    vec4<f32>(1.4972151e3, -7.7201805e0, 5.9696745e-2, -5.128618e-4),
    vec4<f32>(1.4820095e3, -7.487421e0, 5.6727108e-2, -4.7750375e-4),
    vec4<f32>(1.4672578e3, -7.266127e0, 5.396025e-2, -4.452191e-4),
    vec4<f32>(1.4529379e3, -7.055523e0, 5.13787e-2, -4.1568757e-4),
    vec4<f32>(1.439029e3, -6.8548994e0, 4.896681e-2, -3.8862752e-4),
    vec4<f32>(1.4255121e3, -6.663607e0, 4.6710502e-2, -3.637908e-4),
    vec4<f32>(1.4123688e3, -6.481049e0, 4.459711e-2, -3.4095818e-4),
    vec4<f32>(1.3995824e3, -6.306677e0, 4.2615205e-2, -3.199355e-4),
    vec4<f32>(1.387137e3, -6.139986e0, 4.075445e-2, -3.005504e-4),
    vec4<f32>(1.3750176e3, -5.9805107e0, 3.9005484e-2, -2.8264968e-4),
    vec4<f32>(1.3632104e3, -5.8278217e0, 3.7359823e-2, -2.6609673e-4),
    vec4<f32>(1.3517021e3, -5.681521e0, 3.5809748e-2, -2.5076958e-4),
    vec4<f32>(1.3404803e3, -5.54124e0, 3.4348242e-2, -2.3655909e-4),
    vec4<f32>(1.3295333e3, -5.406639e0, 3.29689e-2, -2.233674e-4),
    vec4<f32>(1.3188502e3, -5.2774e0, 3.166588e-2, -2.1110666e-4),
    vec4<f32>(1.3084204e3, -5.153229e0, 3.0433834e-2, -1.996978e-4),
    vec4<f32>(1.2932292e3, -9.951762e0, 1.14847854e-1, -1.4724288e-3),
    vec4<f32>(1.2737736e3, -9.509503e0, 1.06466964e-1, -1.3242331e-3),
    vec4<f32>(1.25517e3, -9.099057e0, 9.891795e-2, -1.1946759e-3),
    vec4<f32>(1.2373583e3, -8.717311e0, 9.209759e-2, -1.0809702e-3),
    vec4<f32>(1.2202836e3, -8.36153e0, 8.591789e-2, -9.808085e-4),
    vec4<f32>(1.2038965e3, -8.029308e0, 8.03035e-2, -8.9227036e-4),
    vec4<f32>(1.188152e3, -7.7185183e0, 7.518963e-2, -8.137486e-4),
    vec4<f32>(1.1730093e3, -7.4272733e0, 7.052033e-2, -7.438923e-4),
    vec4<f32>(1.158431e3, -7.153894e0, 6.624713e-2, -6.8156084e-4),
    vec4<f32>(1.1443828e3, -6.8968835e0, 6.2327836e-2, -6.257868e-4),
    vec4<f32>(1.1308335e3, -6.6549015e0, 5.872565e-2, -5.7574635e-4),
    vec4<f32>(1.117754e3, -6.4267464e0, 5.5408325e-2, -5.307352e-4),
    vec4<f32>(1.105118e3, -6.211336e0, 5.234754e-2, -4.9014913e-4),
    vec4<f32>(1.0929009e3, -6.0076957e0, 4.951834e-2, -4.5346786e-4),
    vec4<f32>(1.08108e3, -5.8149447e0, 4.6898674e-2, -4.2024185e-4),
    vec4<f32>(1.0696343e3, -5.632285e0, 4.4469003e-2, -3.900815e-4),
    vec4<f32>(1.0585446e3, -5.4589915e0, 4.2211972e-2, -3.6264808e-4),
    vec4<f32>(1.0477926e3, -5.294406e0, 4.0112123e-2, -3.3764614e-4),
    vec4<f32>(1.0373616e3, -5.1379275e0, 3.8155656e-2, -3.1481744e-4),
    vec4<f32>(1.0272358e3, -4.989008e0, 3.6330227e-2, -2.939355e-4),
    vec4<f32>(1.0174008e3, -4.8471456e0, 3.4624763e-2, -2.7480116e-4),
    vec4<f32>(1.00784283e3, -4.7118816e0, 3.3029314e-2, -2.5723895e-4),
    vec4<f32>(9.9854913e2, -4.582793e0, 3.1534918e-2, -2.4109385e-4),
    vec4<f32>(9.895078e2, -4.4594936e0, 3.0133499e-2, -2.2622856e-4),
    vec4<f32>(9.807076e2, -4.3416257e0, 2.8817745e-2, -2.1252122e-4),
    vec4<f32>(9.721379e2, -4.2288594e0, 2.7581042e-2, -1.998635e-4),
    vec4<f32>(9.6378894e2, -4.120892e0, 2.6417384e-2, -1.8815881e-4),
    vec4<f32>(9.556513e2, -4.0174417e0, 2.5321316e-2, -1.7732088e-4),
    vec4<f32>(9.477163e2, -3.9182484e0, 2.4287876e-2, -1.6727253e-4),
    vec4<f32>(9.3997565e2, -3.8230708e0, 2.3312533e-2, -1.579446e-4),
    vec4<f32>(9.324215e2, -3.7316852e0, 2.2391157e-2, -1.4927494e-4),
    vec4<f32>(9.250465e2, -3.643883e0, 2.1519968e-2, -1.4120767e-4),
    vec4<f32>(9.143048e2, -7.036958e0, 8.12097e-2, -1.0411644e-3),
    vec4<f32>(9.0054755e2, -6.7242336e0, 7.528351e-2, -9.3637424e-4),
    vec4<f32>(8.873929e2, -6.434005e0, 6.994555e-2, -8.447634e-4),
    vec4<f32>(8.7479803e2, -6.164069e0, 6.512283e-2, -7.6436135e-4),
    vec4<f32>(8.6272437e2, -5.912494e0, 6.0753122e-2, -6.9353636e-4),
    vec4<f32>(8.5113696e2, -5.677578e0, 5.6783147e-2, -6.309304e-4),
    vec4<f32>(8.4000397e2, -5.457816e0, 5.3167094e-2, -5.754071e-4),
    vec4<f32>(8.2929645e2, -5.251875e0, 4.9865402e-2, -5.260113e-4),
    vec4<f32>(8.1898804e2, -5.0585666e0, 4.684379e-2, -4.819363e-4),
    vec4<f32>(8.090545e2, -4.876833e0, 4.4072434e-2, -4.424981e-4),
    vec4<f32>(7.9947363e2, -4.7057257e0, 4.1525304e-2, -4.0711413e-4),
    vec4<f32>(7.902251e2, -4.5443954e0, 3.91796e-2, -3.7528644e-4),
    vec4<f32>(7.8129004e2, -4.3920774e0, 3.70153e-2, -3.4658777e-4),
    vec4<f32>(7.726512e2, -4.248082e0, 3.5014752e-2, -3.206502e-4),
    vec4<f32>(7.642926e2, -4.111787e0, 3.316237e-2, -2.9715587e-4),
    vec4<f32>(7.5619934e2, -3.9826264e0, 3.1444333e-2, -2.7582928e-4),
    vec4<f32>(7.4835767e2, -3.8600895e0, 2.984837e-2, -2.564309e-4),
    vec4<f32>(7.407548e2, -3.74371e0, 2.8363552e-2, -2.3875188e-4),
    vec4<f32>(7.3337897e2, -3.633063e0, 2.6980123e-2, -2.2260955e-4),
    vec4<f32>(7.2621906e2, -3.527761e0, 2.5689349e-2, -2.0784378e-4),
    vec4<f32>(7.1926465e2, -3.4274492e0, 2.4483403e-2, -1.9431376e-4),
    vec4<f32>(7.125061e2, -3.331803e0, 2.335525e-2, -1.818954e-4),
    vec4<f32>(7.059345e2, -3.240524e0, 2.2298554e-2, -1.7047909e-4),
    vec4<f32>(6.995413e2, -3.153338e0, 2.13076e-2, -1.5996773e-4),
    vec4<f32>(6.933186e2, -3.0699925e0, 2.0377222e-2, -1.502752e-4),
    vec4<f32>(6.872589e2, -2.9902549e0, 1.950274e-2, -1.4132484e-4),
    vec4<f32>(6.813553e2, -2.9139104e0, 1.867991e-2, -1.3304836e-4),
    vec4<f32>(6.7560114e2, -2.84076e0, 1.7904874e-2, -1.2538479e-4),
    vec4<f32>(6.699903e2, -2.7706196e0, 1.7174121e-2, -1.1827954e-4),
    vec4<f32>(6.645168e2, -2.703319e0, 1.648445e-2, -1.116837e-4),
    vec4<f32>(6.5917523e2, -2.6386995e0, 1.5832938e-2, -1.0555332e-4),
    vec4<f32>(6.539603e2, -2.5766141e0, 1.5216916e-2, -9.984889e-5),
    vec4<f32>(6.4636475e2, -4.97588e0, 5.7423923e-2, -7.3621434e-4),
    vec4<f32>(6.366369e2, -4.7547507e0, 5.323348e-2, -6.6211657e-4),
    vec4<f32>(6.2733514e2, -4.5495276e0, 4.9458973e-2, -5.973379e-4),
    vec4<f32>(6.1842926e2, -4.3586545e0, 4.6048794e-2, -5.404851e-4),
    vec4<f32>(6.098919e2, -4.180764e0, 4.295894e-2, -4.9040426e-4),
    vec4<f32>(6.0169836e2, -4.014653e0, 4.0151745e-2, -4.4613515e-4),
    vec4<f32>(5.938261e2, -3.8592584e0, 3.759481e-2, -4.0687426e-4),
    vec4<f32>(5.862548e2, -3.7136357e0, 3.5260163e-2, -3.7194614e-4),
    vec4<f32>(5.7896564e2, -3.5769463e0, 3.312356e-2, -3.4078042e-4),
    vec4<f32>(5.719415e2, -3.448441e0, 3.1163916e-2, -3.128934e-4),
    vec4<f32>(5.651669e2, -3.32745e0, 2.9362824e-2, -2.8787315e-4),
    vec4<f32>(5.5862714e2, -3.2133722e0, 2.770416e-2, -2.653676e-4),
    vec4<f32>(5.5230914e2, -3.105667e0, 2.6173769e-2, -2.4507454e-4),
    vec4<f32>(5.4620056e2, -3.0038471e0, 2.4759168e-2, -2.2673392e-4),
    vec4<f32>(5.402901e2, -2.9074717e0, 2.3449335e-2, -2.1012091e-4),
    vec4<f32>(5.345673e2, -2.8161418e0, 2.22345e-2, -1.9504075e-4),
    vec4<f32>(5.290224e2, -2.729495e0, 2.1105984e-2, -1.8132402e-4),
    vec4<f32>(5.236464e2, -2.6472023e0, 2.005606e-2, -1.6882305e-4),
    vec4<f32>(5.184309e2, -2.568963e0, 1.9077826e-2, -1.5740872e-4),
    vec4<f32>(5.1336804e2, -2.4945033e0, 1.8165112e-2, -1.4696774e-4),
    vec4<f32>(5.0845056e2, -2.423572e0, 1.731238e-2, -1.3740057e-4),
    vec4<f32>(5.0367157e2, -2.35594e0, 1.6514655e-2, -1.2861946e-4),
    vec4<f32>(4.9902472e2, -2.291396e0, 1.5767459e-2, -1.20546916e-4),
    vec4<f32>(4.9450406e2, -2.229746e0, 1.50667485e-2, -1.1311427e-4),
    vec4<f32>(4.9010394e2, -2.1708121e0, 1.44088715e-2, -1.062606e-4),
    vec4<f32>(4.858191e2, -2.114429e0, 1.3790519e-2, -9.993175e-5),
    vec4<f32>(4.8164462e2, -2.0604453e0, 1.320869e-2, -9.40794e-5),
    vec4<f32>(4.775758e2, -2.0087202e0, 1.2660657e-2, -8.866043e-5),
    vec4<f32>(4.736083e2, -1.9591235e0, 1.2143936e-2, -8.363626e-5),
    vec4<f32>(4.6973798e2, -1.9115348e0, 1.1656266e-2, -7.89723e-5),
    vec4<f32>(4.659609e2, -1.865842e0, 1.1195578e-2, -7.4637464e-5),
    vec4<f32>(4.6227344e2, -1.8219409e0, 1.0759983e-2, -7.0603826e-5),
    vec4<f32>(4.5690256e2, -3.518478e0, 4.060484e-2, -5.2058214e-4),
    vec4<f32>(4.5002396e2, -3.3621156e0, 3.764175e-2, -4.681871e-4),
    vec4<f32>(4.4344662e2, -3.2170012e0, 3.4972772e-2, -4.2238168e-4),
    vec4<f32>(4.3714917e2, -3.0820332e0, 3.256141e-2, -3.8218065e-4),
    vec4<f32>(4.3111237e2, -2.956246e0, 3.0376555e-2, -3.4676815e-4),
    vec4<f32>(4.2531866e2, -2.8387878e0, 2.839157e-2, -3.1546518e-4),
    vec4<f32>(4.1975217e2, -2.728907e0, 2.6583543e-2, -2.8770353e-4),
    vec4<f32>(4.143984e2, -2.6259363e0, 2.4932697e-2, -2.630056e-4),
    vec4<f32>(4.092442e2, -2.529282e0, 2.3421891e-2, -2.4096813e-4),
    vec4<f32>(4.0427744e2, -2.4384153e0, 2.2036213e-2, -2.2124902e-4),
    vec4<f32>(3.99487e2, -2.3528616e0, 2.0762648e-2, -2.0355705e-4),
    vec4<f32>(3.9486273e2, -2.2721965e0, 1.9589799e-2, -1.876432e-4),
    vec4<f32>(3.903952e2, -2.1960375e0, 1.8507646e-2, -1.7329387e-4),
    vec4<f32>(3.860758e2, -2.12404e0, 1.7507374e-2, -1.6032509e-4),
    vec4<f32>(3.8189648e2, -2.0558922e0, 1.6581181e-2, -1.485779e-4),
    vec4<f32>(3.7784985e2, -1.9913123e0, 1.5722163e-2, -1.3791463e-4),
    vec4<f32>(3.7392905e2, -1.9300438e0, 1.4924183e-2, -1.2821544e-4),
    vec4<f32>(3.7012762e2, -1.871854e0, 1.4181774e-2, -1.1937592e-4),
    vec4<f32>(3.664397e2, -1.8165305e0, 1.34900585e-2, -1.1130476e-4),
    vec4<f32>(3.6285974e2, -1.7638794e0, 1.28446715e-2, -1.0392188e-4),
    vec4<f32>(3.5938254e2, -1.7137237e0, 1.2241699e-2, -9.7156866e-5),
    vec4<f32>(3.5600327e2, -1.6659005e0, 1.1677623e-2, -9.094769e-5),
    vec4<f32>(3.5271747e2, -1.620261e0, 1.1149275e-2, -8.523953e-5),
    vec4<f32>(3.4952087e2, -1.576668e0, 1.06537985e-2, -7.998386e-5),
    vec4<f32>(3.4640952e2, -1.5349953e0, 1.0188609e-2, -7.513759e-5),
    vec4<f32>(3.433797e2, -1.4951265e0, 9.751368e-3, -7.066241e-5),
    vec4<f32>(3.404279e2, -1.4569542e0, 9.339953e-3, -6.6524175e-5),
    vec4<f32>(3.375508e2, -1.420379e0, 8.952435e-3, -6.269239e-5),
    vec4<f32>(3.3474536e2, -1.3853089e0, 8.587059e-3, -5.9139762e-5),
    vec4<f32>(3.3200864e2, -1.3516586e0, 8.2422225e-3, -5.584184e-5),
    vec4<f32>(3.2933783e2, -1.3193488e0, 7.916467e-3, -5.2776653e-5),
    vec4<f32>(3.2673038e2, -1.2883061e0, 7.608456e-3, -4.9924438e-5),
    vec4<f32>(3.2293262e2, -2.4879384e0, 2.8711954e-2, -3.681071e-4),
    vec4<f32>(3.180687e2, -2.3773737e0, 2.6616732e-2, -3.3105823e-4),
    vec4<f32>(3.1341782e2, -2.2747622e0, 2.472948e-2, -2.9866892e-4),
    vec4<f32>(3.0896487e2, -2.1793253e0, 2.302439e-2, -2.7024248e-4),
    vec4<f32>(3.046962e2, -2.0903804e0, 2.1479465e-2, -2.452021e-4),
    vec4<f32>(3.0059943e2, -2.007325e0, 2.0075867e-2, -2.2306755e-4),
    vec4<f32>(2.9666333e2, -1.9296275e0, 1.87974e-2, -2.034371e-4),
    vec4<f32>(2.9287766e2, -1.8568163e0, 1.7630076e-2, -1.8597304e-4),
    vec4<f32>(2.892331e2, -1.7884715e0, 1.6561775e-2, -1.7039018e-4),
    vec4<f32>(2.8572104e2, -1.7242188e0, 1.5581953e-2, -1.5644667e-4),
    vec4<f32>(2.823337e2, -1.6637235e0, 1.4681407e-2, -1.4393654e-4),
    vec4<f32>(2.7906384e2, -1.6066846e0, 1.3852076e-2, -1.3268377e-4),
    vec4<f32>(2.7590485e2, -1.552832e0, 1.308688e-2, -1.2253725e-4),
    vec4<f32>(2.7285056e2, -1.501922e0, 1.237958e-2, -1.13366936e-4),
    vec4<f32>(2.6989532e2, -1.4537344e0, 1.1724663e-2, -1.0506043e-4),
    vec4<f32>(2.6703394e2, -1.4080694e0, 1.1117246e-2, -9.752035e-5),
    vec4<f32>(2.642615e2, -1.3647461e0, 1.0552988e-2, -9.066199e-5),
    vec4<f32>(2.6157352e2, -1.3235997e0, 1.0028026e-2, -8.441151e-5),
    vec4<f32>(2.5896576e2, -1.2844801e0, 9.538909e-3, -7.870434e-5),
    vec4<f32>(2.5643433e2, -1.2472502e0, 9.082552e-3, -7.3483854e-5),
    vec4<f32>(2.5397557e2, -1.2117846e0, 8.656186e-3, -6.870027e-5),
    vec4<f32>(2.5158609e2, -1.1779686e0, 8.257324e-3, -6.4309716e-5),
    vec4<f32>(2.4926266e2, -1.1456966e0, 7.883726e-3, -6.0273444e-5),
    vec4<f32>(2.4700233e2, -1.1148717e0, 7.533371e-3, -5.655712e-5),
    vec4<f32>(2.4480228e2, -1.0854046e0, 7.2044325e-3, -5.313029e-5),
    vec4<f32>(2.4265987e2, -1.0572132e0, 6.8952567e-3, -4.996586e-5),
    vec4<f32>(2.4057263e2, -1.0302213e0, 6.6043423e-3, -4.7039684e-5),
    vec4<f32>(2.3853822e2, -1.0043588e0, 6.3303253e-3, -4.4330205e-5),
    vec4<f32>(2.3655447e2, -9.7956043e-1, 6.071965e-3, -4.181812e-5),
    vec4<f32>(2.3461932e2, -9.557661e-1, 5.82813e-3, -3.9486138e-5),
    vec4<f32>(2.3273079e2, -9.329197e-1, 5.597786e-3, -3.7318725e-5),
    vec4<f32>(2.3088704e2, -9.1096914e-1, 5.3799893e-3, -3.5301902e-5),
    vec4<f32>(2.2820161e2, -1.7592363e0, 2.0302411e-2, -2.6029098e-4),
    vec4<f32>(2.2476231e2, -1.6810553e0, 1.8820865e-2, -2.3409347e-4),
    vec4<f32>(2.2147365e2, -1.6084981e0, 1.7486377e-2, -2.1119077e-4),
    vec4<f32>(2.1832494e2, -1.5410142e0, 1.6280698e-2, -1.9109025e-4),
    vec4<f32>(2.1530653e2, -1.4781204e0, 1.518827e-2, -1.7338402e-4),
    vec4<f32>(2.1240968e2, -1.4193915e0, 1.4195777e-2, -1.5773253e-4),
    vec4<f32>(2.0962643e2, -1.3644512e0, 1.3291764e-2, -1.4385172e-4),
    vec4<f32>(2.0694957e2, -1.3129659e0, 1.2466341e-2, -1.3150276e-4),
    vec4<f32>(2.0437247e2, -1.2646388e0, 1.1710939e-2, -1.2048402e-4),
    vec4<f32>(2.0188908e2, -1.2192054e0, 1.10181e-2, -1.10624474e-4),
    vec4<f32>(1.9949388e2, -1.1764287e0, 1.0381318e-2, -1.0177848e-4),
    vec4<f32>(1.9718175e2, -1.1360961e0, 9.794893e-3, -9.382157e-5),
    vec4<f32>(1.94948e2, -1.0980166e0, 9.253818e-3, -8.66469e-5),
    vec4<f32>(1.927883e2, -1.0620178e0, 8.753681e-3, -8.016251e-5),
    vec4<f32>(1.9069864e2, -1.027944e0, 8.290585e-3, -7.4288924e-5),
    vec4<f32>(1.8867532e2, -9.95654e-1, 7.861076e-3, -6.8957284e-5),
    vec4<f32>(1.8671492e2, -9.6501976e-1, 7.4620857e-3, -6.410769e-5),
    vec4<f32>(1.8481422e2, -9.359249e-1, 7.0908815e-3, -5.9687936e-5),
    vec4<f32>(1.8297026e2, -9.082632e-1, 6.745024e-3, -5.5652356e-5),
    vec4<f32>(1.8118028e2, -8.819377e-1, 6.422331e-3, -5.1960913e-5),
    vec4<f32>(1.7944168e2, -8.568598e-1, 6.1208447e-3, -4.857841e-5),
    vec4<f32>(1.7775206e2, -8.3294827e-1, 5.8388067e-3, -4.5473822e-5),
    vec4<f32>(1.7610916e2, -8.101285e-1, 5.574633e-3, -4.2619748e-5),
    vec4<f32>(1.7451086e2, -7.8833205e-1, 5.3268946e-3, -3.9991908e-5),
    vec4<f32>(1.729552e2, -7.674957e-1, 5.0943005e-3, -3.7568774e-5),
    vec4<f32>(1.7144028e2, -7.4756134e-1, 4.87568e-3, -3.5331188e-5),
    vec4<f32>(1.6996439e2, -7.284752e-1, 4.669972e-3, -3.326207e-5),
    vec4<f32>(1.6852585e2, -7.101876e-1, 4.4762134e-3, -3.1346175e-5),
    vec4<f32>(1.6712314e2, -6.926526e-1, 4.293525e-3, -2.9569866e-5),
    vec4<f32>(1.6575476e2, -6.7582744e-1, 4.1211075e-3, -2.7920905e-5),
    vec4<f32>(1.6441937e2, -6.596726e-1, 3.95823e-3, -2.6388312e-5),
    vec4<f32>(1.6311566e2, -6.441513e-1, 3.8042243e-3, -2.4962204e-5),
    vec4<f32>(1.6121678e2, -1.2439656e0, 1.4355964e-2, -1.8405345e-4),
    vec4<f32>(1.5878482e2, -1.1886833e0, 1.3308353e-2, -1.6552901e-4),
    vec4<f32>(1.564594e2, -1.1373776e0, 1.2364727e-2, -1.4933437e-4),
    vec4<f32>(1.5423293e2, -1.0896592e0, 1.1512183e-2, -1.3512115e-4),
    vec4<f32>(1.520986e2, -1.0451868e0, 1.073972e-2, -1.2260096e-4),
    vec4<f32>(1.5005022e2, -1.0036591e0, 1.0037922e-2, -1.1153369e-4),
    vec4<f32>(1.4808217e2, -9.6481043e-1, 9.398689e-3, -1.0171848e-4),
    vec4<f32>(1.4618935e2, -9.2840487e-1, 8.815028e-3, -9.298645e-5),
    vec4<f32>(1.4436707e2, -8.942325e-1, 8.280878e-3, -8.5195024e-5),
    vec4<f32>(1.4261105e2, -8.6210626e-1, 7.790967e-3, -7.8223275e-5),
    vec4<f32>(1.4091739e2, -8.318586e-1, 7.3406943e-3, -7.196822e-5),
    vec4<f32>(1.3928247e2, -8.033392e-1, 6.926029e-3, -6.634183e-5),
    vec4<f32>(1.3770297e2, -7.7641296e-1, 6.543431e-3, -6.1268576e-5),
    vec4<f32>(1.3617583e2, -7.5095797e-1, 6.1897817e-3, -5.668342e-5),
    vec4<f32>(1.3469823e2, -7.2686416e-1, 5.8623236e-3, -5.2530173e-5),
    vec4<f32>(1.3326753e2, -7.040317e-1, 5.558615e-3, -4.8760136e-5),
    vec4<f32>(1.3188132e2, -6.8237007e-1, 5.2764863e-3, -4.5330955e-5),
    vec4<f32>(1.3053734e2, -6.6179687e-1, 5.0140056e-3, -4.220572e-5),
    vec4<f32>(1.2923346e2, -6.422371e-1, 4.7694477e-3, -3.9352133e-5),
    vec4<f32>(1.2796775e2, -6.2362224e-1, 4.541269e-3, -3.674189e-5),
    vec4<f32>(1.2673838e2, -6.058895e-1, 4.3280865e-3, -3.43501e-5),
    vec4<f32>(1.2554365e2, -5.889815e-1, 4.1286554e-3, -3.215483e-5),
    vec4<f32>(1.2438194e2, -5.728455e-1, 3.9418563e-3, -3.0136693e-5),
    vec4<f32>(1.2325178e2, -5.5743307e-1, 3.7666792e-3, -2.8278531e-5),
    vec4<f32>(1.2215176e2, -5.426996e-1, 3.6022102e-3, -2.6565118e-5),
    vec4<f32>(1.2108056e2, -5.2860385e-1, 3.4476225e-3, -2.4982905e-5),
    vec4<f32>(1.2003694e2, -5.151079e-1, 3.3021653e-3, -2.3519819e-5),
    vec4<f32>(1.1901975e2, -5.021767e-1, 3.165157e-3, -2.2165079e-5),
    vec4<f32>(1.1802788e2, -4.8977757e-1, 3.0359772e-3, -2.0909038e-5),
    vec4<f32>(1.170603e2, -4.7788042e-1, 2.9140597e-3, -1.9743047e-5),
    vec4<f32>(1.1611604e2, -4.6645722e-1, 2.798888e-3, -1.865934e-5),
    vec4<f32>(1.15194176e2, -4.55482e-1, 2.6899895e-3, -1.7650931e-5),
    vec4<f32>(1.1385147e2, -8.796131e-1, 1.0151186e-2, -1.3014534e-4),
    vec4<f32>(1.1213183e2, -8.4052265e-1, 9.410414e-3, -1.170466e-4),
    vec4<f32>(1.1048751e2, -8.042441e-1, 8.743171e-3, -1.0559526e-4),
    vec4<f32>(1.0891316e2, -7.705022e-1, 8.140331e-3, -9.554501e-5),
    vec4<f32>(1.0740397e2, -7.3905545e-1, 7.5941184e-3, -8.66919e-5),
    vec4<f32>(1.0595555e2, -7.09691e-1, 7.0978724e-3, -7.8866164e-5),
    vec4<f32>(1.0456394e2, -6.822209e-1, 6.6458667e-3, -7.192576e-5),
    vec4<f32>(1.0322552e2, -6.564783e-1, 6.233156e-3, -6.575129e-5),
    vec4<f32>(1.0193698e2, -6.323148e-1, 5.855455e-3, -6.0241924e-5),
    vec4<f32>(1.006953e2, -6.0959816e-1, 5.5090366e-3, -5.5312154e-5),
    vec4<f32>(9.94977e1, -5.8820987e-1, 5.190646e-3, -5.0889164e-5),
    vec4<f32>(9.8341644e1, -5.6804365e-1, 4.8974333e-3, -4.691071e-5),
    vec4<f32>(9.722478e1, -5.4900396e-1, 4.626896e-3, -4.332338e-5),
    vec4<f32>(9.6144936e1, -5.310046e-1, 4.3768287e-3, -4.0081188e-5),
    vec4<f32>(9.510011e1, -5.139677e-1, 4.145281e-3, -3.71444e-5),
    vec4<f32>(9.408847e1, -4.9782276e-1, 3.930527e-3, -3.447858e-5),
    vec4<f32>(9.310828e1, -4.825057e-1, 3.7310321e-3, -3.2053787e-5),
    vec4<f32>(9.2157936e1, -4.679583e-1, 3.5454305e-3, -2.9843915e-5),
    vec4<f32>(9.123596e1, -4.541275e-1, 3.372502e-3, -2.7826129e-5),
    vec4<f32>(9.034098e1, -4.409648e-1, 3.2111555e-3, -2.598041e-5),
    vec4<f32>(8.947169e1, -4.2842588e-1, 3.0604128e-3, -2.428916e-5),
    vec4<f32>(8.8626884e1, -4.1647014e-1, 2.919394e-3, -2.2736867e-5),
    vec4<f32>(8.780544e1, -4.0506032e-1, 2.7873074e-3, -2.1309832e-5),
    vec4<f32>(8.70063e1, -3.9416212e-1, 2.6634387e-3, -1.9995916e-5),
    vec4<f32>(8.622848e1, -3.8374397e-1, 2.5471416e-3, -1.8784349e-5),
    vec4<f32>(8.547102e1, -3.7377682e-1, 2.4378316e-3, -1.7665558e-5),
    vec4<f32>(8.4733086e1, -3.642338e-1, 2.334978e-3, -1.6631e-5),
    vec4<f32>(8.4013824e1, -3.5509002e-1, 2.2380988e-3, -1.5673055e-5),
    vec4<f32>(8.331247e1, -3.4632254e-1, 2.1467549e-3, -1.47849005e-5),
    vec4<f32>(8.2628296e1, -3.3791e-1, 2.0605463e-3, -1.3960422e-5),
    vec4<f32>(8.196061e1, -3.298326e-1, 1.9791077e-3, -1.3194127e-5),
    vec4<f32>(8.1308754e1, -3.2207197e-1, 1.9021049e-3, -1.2481075e-5),
    vec4<f32>(8.035933e1, -6.2197554e-1, 7.177954e-3, -9.2026516e-5),
    vec4<f32>(7.9143364e1, -5.943345e-1, 6.65415e-3, -8.276431e-5),
    vec4<f32>(7.798067e1, -5.686818e-1, 6.182338e-3, -7.4667e-5),
    vec4<f32>(7.686745e1, -5.448227e-1, 5.756067e-3, -6.756041e-5),
    vec4<f32>(7.580029e1, -5.225866e-1, 5.369837e-3, -6.130032e-5),
    vec4<f32>(7.4776115e1, -5.018228e-1, 5.018939e-3, -5.5766697e-5),
    vec4<f32>(7.379211e1, -4.8239857e-1, 4.699323e-3, -5.08591e-5),
    vec4<f32>(7.284571e1, -4.6419588e-1, 4.407493e-3, -4.6493093e-5),
    vec4<f32>(7.193458e1, -4.471098e-1, 4.140419e-3, -4.259739e-5),
    vec4<f32>(7.105659e1, -4.3104672e-1, 3.8954644e-3, -3.911152e-5),
    vec4<f32>(7.020977e1, -4.1592297e-1, 3.6703285e-3, -3.5984e-5),
    vec4<f32>(6.939232e1, -4.0166333e-1, 3.4629966e-3, -3.317081e-5),
    vec4<f32>(6.8602585e1, -3.8820028e-1, 3.2716983e-3, -3.063419e-5),
    vec4<f32>(6.783903e1, -3.7547287e-1, 3.0948739e-3, -2.8341618e-5),
    vec4<f32>(6.710024e1, -3.6342603e-1, 2.9311455e-3, -2.6265e-5),
    vec4<f32>(6.63849e1, -3.5200986e-1, 2.7792917e-3, -2.4379984e-5),
    vec4<f32>(6.569181e1, -3.411791e-1, 2.638228e-3, -2.26654e-5),
    vec4<f32>(6.501983e1, -3.308926e-1, 2.506988e-3, -2.1102785e-5),
    vec4<f32>(6.4367905e1, -3.2111275e-1, 2.3847094e-3, -1.9675996e-5),
    vec4<f32>(6.3735058e1, -3.1180537e-1, 2.2706205e-3, -1.8370878e-5),
    vec4<f32>(6.3120388e1, -3.0293906e-1, 2.1640295e-3, -1.7174987e-5),
    vec4<f32>(6.252303e1, -2.9448512e-1, 2.0643144e-3, -1.6077352e-5),
    vec4<f32>(6.194219e1, -2.864172e-1, 1.9709154e-3, -1.5068287e-5),
    vec4<f32>(6.1377117e1, -2.7871102e-1, 1.8833271e-3, -1.4139209e-5),
    vec4<f32>(6.0827118e1, -2.713443e-1, 1.801093e-3, -1.3282505e-5),
    vec4<f32>(6.029153e1, -2.642965e-1, 1.7237994e-3, -1.24914e-5),
    vec4<f32>(5.9769733e1, -2.575486e-1, 1.6510711e-3, -1.175986e-5),
    vec4<f32>(5.9261147e1, -2.5108302e-1, 1.5825673e-3, -1.1082492e-5),
    vec4<f32>(5.8765224e1, -2.448835e-1, 1.5179777e-3, -1.0454473e-5),
    vec4<f32>(5.8281445e1, -2.3893495e-1, 1.4570191e-3, -9.87148e-6),
    vec4<f32>(5.7809326e1, -2.332234e-1, 1.3994335e-3, -9.3296285e-6),
    vec4<f32>(5.7348404e1, -2.2773582e-1, 1.3449845e-3, -8.8254255e-6),
    vec4<f32>(5.6677067e1, -4.3979633e-1, 5.075554e-3, -6.507237e-5),
    vec4<f32>(5.5817265e1, -4.2025125e-1, 4.7051692e-3, -5.852302e-5),
    vec4<f32>(5.4995125e1, -4.0211213e-1, 4.3715495e-3, -5.2797368e-5),
    vec4<f32>(5.420797e1, -3.8524133e-1, 4.070131e-3, -4.777226e-5),
    vec4<f32>(5.3453392e1, -3.6951807e-1, 3.7970261e-3, -4.3345724e-5),
    vec4<f32>(5.2729206e1, -3.54836e-1, 3.5489046e-3, -3.943287e-5),
    vec4<f32>(5.2033417e1, -3.4110105e-1, 3.3229028e-3, -3.5962683e-5),
    vec4<f32>(5.1364223e1, -3.2822987e-1, 3.1165488e-3, -3.2875458e-5),
    vec4<f32>(5.0719975e1, -3.1614825e-1, 2.9276994e-3, -3.0120787e-5),
    vec4<f32>(5.009915e1, -3.0479002e-1, 2.754491e-3, -2.7655913e-5),
    vec4<f32>(4.950037e1, -2.94096e-1, 2.5952966e-3, -2.5444428e-5),
    vec4<f32>(4.892236e1, -2.8401297e-1, 2.4486913e-3, -2.3455208e-5),
    vec4<f32>(4.836394e1, -2.7449325e-1, 2.3134237e-3, -2.1661552e-5),
    vec4<f32>(4.782404e1, -2.6549366e-1, 2.1883906e-3, -2.0040463e-5),
    vec4<f32>(4.7301647e1, -2.5697532e-1, 2.0726176e-3, -1.8572076e-5),
    vec4<f32>(4.679584e1, -2.4890293e-1, 1.9652413e-3, -1.7239174e-5),
    vec4<f32>(4.630576e1, -2.412445e-1, 1.8654945e-3, -1.6026783e-5),
    vec4<f32>(4.5830605e1, -2.3397088e-1, 1.7726943e-3, -1.4921851e-5),
    vec4<f32>(4.5369637e1, -2.2705555e-1, 1.6862307e-3, -1.3912963e-5),
    vec4<f32>(4.492216e1, -2.2047427e-1, 1.6055581e-3, -1.2990109e-5),
    vec4<f32>(4.4487534e1, -2.1420489e-1, 1.5301872e-3, -1.2144488e-5),
    vec4<f32>(4.4065147e1, -2.0822711e-1, 1.4596784e-3, -1.1368347e-5),
    vec4<f32>(4.365444e1, -2.0252226e-1, 1.3936356e-3, -1.0654832e-5),
    vec4<f32>(4.3254887e1, -1.9707324e-1, 1.3317016e-3, -9.997878e-6),
    vec4<f32>(4.286599e1, -1.9186424e-1, 1.2735536e-3, -9.392099e-6),
    vec4<f32>(4.248728e1, -1.8688072e-1, 1.218899e-3, -8.832706e-6),
    vec4<f32>(4.2118324e1, -1.8210928e-1, 1.1674728e-3, -8.31543e-6),
    vec4<f32>(4.175871e1, -1.7753746e-1, 1.1190335e-3, -7.836461e-6),
    vec4<f32>(4.140805e1, -1.7315379e-1, 1.073362e-3, -7.3923866e-6),
    vec4<f32>(4.106598e1, -1.6894758e-1, 1.030258e-3, -6.9801495e-6),
    vec4<f32>(4.0732147e1, -1.6490893e-1, 9.895391e-4, -6.5970044e-6),
    vec4<f32>(4.0406235e1, -1.6102867e-1, 9.510381e-4, -6.2404806e-6),
    vec4<f32>(3.9931545e1, -3.1097332e-1, 3.5889214e-3, -4.601283e-5),
    vec4<f32>(3.9323593e1, -2.9715303e-1, 3.3270218e-3, -4.1381758e-5),
    vec4<f32>(3.8742268e1, -2.8432685e-1, 3.0911183e-3, -3.733313e-5),
    vec4<f32>(3.8185688e1, -2.7239752e-1, 2.877985e-3, -3.377986e-5),
    vec4<f32>(3.7652138e1, -2.6127964e-1, 2.6848717e-3, -3.064984e-5),
    vec4<f32>(3.7140076e1, -2.5089797e-1, 2.5094245e-3, -2.788305e-5),
    vec4<f32>(3.66481e1, -2.4118601e-1, 2.3496184e-3, -2.5429268e-5),
    vec4<f32>(3.6174927e1, -2.3208483e-1, 2.203705e-3, -2.3246284e-5),
    vec4<f32>(3.5719387e1, -2.2354195e-1, 2.0701694e-3, -2.1298449e-5),
    vec4<f32>(3.528042e1, -2.1551058e-1, 1.9476935e-3, -1.9555528e-5),
    vec4<f32>(3.4857033e1, -2.0794885e-1, 1.835127e-3, -1.799178e-5),
    vec4<f32>(3.4448334e1, -2.0081918e-1, 1.7314623e-3, -1.65852e-5),
    vec4<f32>(3.405349e1, -1.940878e-1, 1.6358144e-3, -1.53169e-5),
    vec4<f32>(3.3671738e1, -1.8772423e-1, 1.5474034e-3, -1.4170625e-5),
    vec4<f32>(3.330237e1, -1.8170093e-1, 1.4655403e-3, -1.3132325e-5),
    vec4<f32>(3.2944725e1, -1.7599298e-1, 1.3896144e-3, -1.21898265e-5),
    vec4<f32>(3.25982e1, -1.7057773e-1, 1.3190835e-3, -1.1332542e-5),
    vec4<f32>(3.2262234e1, -1.6543458e-1, 1.2534644e-3, -1.0551243e-5),
    vec4<f32>(3.1936293e1, -1.6054478e-1, 1.192326e-3, -9.837856e-6),
    vec4<f32>(3.1619896e1, -1.5589121e-1, 1.1352825e-3, -9.1853035e-6),
    vec4<f32>(3.1312582e1, -1.5145816e-1, 1.0819877e-3, -8.587364e-6),
    vec4<f32>(3.1013926e1, -1.472313e-1, 1.0321309e-3, -8.0385535e-6),
    vec4<f32>(3.0723528e1, -1.4319743e-1, 9.854321e-4, -7.5340263e-6),
    vec4<f32>(3.0441015e1, -1.3934445e-1, 9.4163866e-4, -7.0694928e-6),
    vec4<f32>(3.0166037e1, -1.356612e-1, 9.005222e-4, -6.6411453e-6),
    vec4<f32>(2.9898264e1, -1.3213739e-1, 8.6187606e-4, -6.2455974e-6),
    vec4<f32>(2.9637388e1, -1.2876353e-1, 8.255125e-4, -5.8798314e-6),
    vec4<f32>(2.9383116e1, -1.2553082e-1, 7.912612e-4, -5.5411515e-6),
    vec4<f32>(2.9135176e1, -1.2243115e-1, 7.589669e-4, -5.227146e-6),
    vec4<f32>(2.8893307e1, -1.1945697e-1, 7.284882e-4, -4.935653e-6),
    vec4<f32>(2.8657269e1, -1.1660128e-1, 6.996959e-4, -4.664731e-6),
    vec4<f32>(2.8426828e1, -1.13857575e-1, 6.724719e-4, -4.4126327e-6),
    vec4<f32>(2.809119e1, -2.1987772e-1, 2.5376983e-3, -3.253558e-5),
    vec4<f32>(2.7661331e1, -2.101055e-1, 2.3525094e-3, -2.9260947e-5),
    vec4<f32>(2.72503e1, -2.0103623e-1, 2.1857028e-3, -2.6398162e-5),
    vec4<f32>(2.6856764e1, -1.9260111e-1, 2.0349966e-3, -2.3885645e-5),
    vec4<f32>(2.6479513e1, -1.8473975e-1, 1.8984469e-3, -2.167241e-5),
    vec4<f32>(2.6117456e1, -1.7739898e-1, 1.7743887e-3, -1.9716012e-5),
    vec4<f32>(2.5769602e1, -1.7053175e-1, 1.6613903e-3, -1.7980945e-5),
    vec4<f32>(2.5435041e1, -1.640964e-1, 1.5582156e-3, -1.6437358e-5),
    vec4<f32>(2.5112953e1, -1.5805583e-1, 1.4637931e-3, -1.50600445e-5),
    vec4<f32>(2.4802578e1, -1.5237693e-1, 1.3771909e-3, -1.3827628e-5),
    vec4<f32>(2.4503223e1, -1.4703013e-1, 1.2975957e-3, -1.2721905e-5),
    vec4<f32>(2.4214254e1, -1.4198883e-1, 1.2242949e-3, -1.1727312e-5),
    vec4<f32>(2.3935081e1, -1.3722916e-1, 1.1566627e-3, -1.08305e-5),
    vec4<f32>(2.3665163e1, -1.3272956e-1, 1.0941478e-3, -1.001997e-5),
    vec4<f32>(2.3404001e1, -1.2847058e-1, 1.0362628e-3, -9.285792e-6),
    vec4<f32>(2.3151133e1, -1.2443457e-1, 9.82576e-4, -8.619352e-6),
    vec4<f32>(2.2906126e1, -1.2060552e-1, 9.327041e-4, -8.0131695e-6),
    vec4<f32>(2.2668583e1, -1.16968885e-1, 8.8630524e-4, -7.4607146e-6),
    vec4<f32>(2.2438131e1, -1.1351138e-1, 8.430747e-4, -6.9562807e-6),
    vec4<f32>(2.2214426e1, -1.1022091e-1, 8.027396e-4, -6.494863e-6),
    vec4<f32>(2.1997143e1, -1.07086375e-1, 7.650553e-4, -6.0720618e-6),
    vec4<f32>(2.1785982e1, -1.04097635e-1, 7.2980195e-4, -5.6839995e-6),
    vec4<f32>(2.1580662e1, -1.0124536e-1, 6.9678156e-4, -5.32725e-6),
    vec4<f32>(2.1380917e1, -9.852099e-2, 6.6581555e-4, -4.9987802e-6),
    vec4<f32>(2.1186499e1, -9.591663e-2, 6.3674245e-4, -4.6958976e-6),
    vec4<f32>(2.0997175e1, -9.342501e-2, 6.094161e-4, -4.4162075e-6),
    vec4<f32>(2.0812727e1, -9.103942e-2, 5.837038e-4, -4.157576e-6),
    vec4<f32>(2.063295e1, -8.875364e-2, 5.59485e-4, -3.918097e-6),
    vec4<f32>(2.045765e1, -8.6561926e-2, 5.3665e-4, -3.6960653e-6),
    vec4<f32>(2.0286644e1, -8.445894e-2, 5.150988e-4, -3.489952e-6),
    vec4<f32>(2.0119759e1, -8.243974e-2, 4.9474003e-4, -3.2983842e-6),
    vec4<f32>(1.9956831e1, -8.049972e-2, 4.7549023e-4, -3.1201268e-6),
    vec4<f32>(1.971953e1, -1.5545778e-1, 1.7943493e-3, -2.3005558e-5),
    vec4<f32>(1.9415611e1, -1.4854807e-1, 1.6634045e-3, -2.0690086e-5),
    vec4<f32>(1.9125006e1, -1.421354e-1, 1.5454573e-3, -1.8665829e-5),
    vec4<f32>(1.884677e1, -1.3617113e-1, 1.4388949e-3, -1.6889244e-5),
    vec4<f32>(1.8580051e1, -1.3061257e-1, 1.3423424e-3, -1.532428e-5),
    vec4<f32>(1.8324074e1, -1.254221e-1, 1.2546225e-3, -1.3940927e-5),
    vec4<f32>(1.807814e1, -1.2056648e-1, 1.1747228e-3, -1.2714074e-5),
    vec4<f32>(1.7841606e1, -1.16016224e-1, 1.1017694e-3, -1.16226165e-5),
    vec4<f32>(1.7613888e1, -1.1174511e-1, 1.0350046e-3, -1.06487305e-5),
    vec4<f32>(1.7394455e1, -1.0772974e-1, 9.737696e-4, -9.7773e-6),
    vec4<f32>(1.7182814e1, -1.03949174e-1, 9.1748906e-4, -8.995453e-6),
    vec4<f32>(1.6978514e1, -1.0038464e-1, 8.6565927e-4, -8.292187e-6),
    vec4<f32>(1.6781141e1, -9.701923e-2, 8.1783766e-4, -7.65806e-6),
    vec4<f32>(1.6590315e1, -9.3837716e-2, 7.7363447e-4, -7.0849433e-6),
    vec4<f32>(1.6405678e1, -9.082633e-2, 7.3270506e-4, -6.565813e-6),
    vec4<f32>(1.6226904e1, -8.797262e-2, 6.947442e-4, -6.0945817e-6),
    vec4<f32>(1.605369e1, -8.5265234e-2, 6.5948063e-4, -5.6659565e-6),
    vec4<f32>(1.5885752e1, -8.2693905e-2, 6.2667293e-4, -5.2753226e-6),
    vec4<f32>(1.572283e1, -8.024924e-2, 5.9610547e-4, -4.9186433e-6),
    vec4<f32>(1.5564676e1, -7.792267e-2, 5.6758535e-4, -4.592381e-6),
    vec4<f32>(1.5411065e1, -7.570637e-2, 5.409396e-4, -4.293424e-6),
    vec4<f32>(1.5261783e1, -7.3593155e-2, 5.160127e-4, -4.0190303e-6),
    vec4<f32>(1.5116629e1, -7.157643e-2, 4.9266475e-4, -3.766778e-6),
    vec4<f32>(1.4975416e1, -6.965014e-2, 4.7076942e-4, -3.5345217e-6),
    vec4<f32>(1.4837971e1, -6.780871e-2, 4.502125e-4, -3.3203578e-6),
    vec4<f32>(1.4704128e1, -6.6047005e-2, 4.3089068e-4, -3.1225932e-6),
    vec4<f32>(1.4573733e1, -6.436026e-2, 4.1271013e-4, -2.9397188e-6),
    vec4<f32>(1.444664e1, -6.274409e-2, 3.9558564e-4, -2.770387e-6),
    vec4<f32>(1.4322713e1, -6.119443e-2, 3.794396e-4, -2.613392e-6),
    vec4<f32>(1.420182e1, -5.9707515e-2, 3.642013e-4, -2.4676528e-6),
    vec4<f32>(1.4083843e1, -5.827984e-2, 3.4980616e-4, -2.3321986e-6),
    vec4<f32>(1.3968664e1, -5.690815e-2, 3.3619517e-4, -2.2061558e-6),
    vec4<f32>(1.3800907e1, -1.0989807e-1, 1.2686915e-3, -1.6266578e-5),
    vec4<f32>(1.3586058e1, -1.05012566e-1, 1.1761042e-3, -1.4629351e-5),
    vec4<f32>(1.3380622e1, -1.0047852e-1, 1.0927073e-3, -1.3198038e-5),
    vec4<f32>(1.3183932e1, -9.626153e-2, 1.0173602e-3, -1.1941851e-5),
    vec4<f32>(1.2995385e1, -9.2331395e-2, 9.4909105e-4, -1.0835299e-5),
    vec4<f32>(1.2814433e1, -8.866152e-2, 8.8706723e-4, -9.857159e-6),
    vec4<f32>(1.2640581e1, -8.5228406e-2, 8.305729e-4, -8.989679e-6),
    vec4<f32>(1.2473376e1, -8.2011215e-2, 7.7899016e-4, -8.217935e-6),
    vec4<f32>(1.2312405e1, -7.899138e-2, 7.317832e-4, -7.5293233e-6),
    vec4<f32>(1.21572895e1, -7.615239e-2, 6.884862e-4, -6.9131565e-6),
    vec4<f32>(1.2007685e1, -7.3479414e-2, 6.486924e-4, -6.360333e-6),
    vec4<f32>(1.1863271e1, -7.095918e-2, 6.1204564e-4, -5.8630717e-6),
    vec4<f32>(1.1723754e1, -6.857974e-2, 5.782329e-4, -5.414698e-6),
    vec4<f32>(1.1588864e1, -6.6330336e-2, 5.4697867e-4, -5.009463e-6),
    vec4<f32>(1.1458352e1, -6.420121e-2, 5.180393e-4, -4.642401e-6),
    vec4<f32>(1.1331985e1, -6.218357e-2, 4.911988e-4, -4.3092073e-6),
    vec4<f32>(1.1209549e1, -6.02694e-2, 4.6626554e-4, -4.0061395e-6),
    vec4<f32>(1.1090844e1, -5.845142e-2, 4.4306874e-4, -3.7299342e-6),
    vec4<f32>(1.0975684e1, -5.6723002e-2, 4.2145594e-4, -3.477738e-6),
    vec4<f32>(1.0863896e1, -5.5078086e-2, 4.0129074e-4, -3.2470482e-6),
    vec4<f32>(1.075532e1, -5.351113e-2, 3.8245082e-4, -3.0356657e-6),
    vec4<f32>(1.0649803e1, -5.2017063e-2, 3.648263e-4, -2.8416514e-6),
    vec4<f32>(1.0547206e1, -5.059122e-2, 3.4831814e-4, -2.6632924e-6),
    vec4<f32>(1.0447395e1, -4.922932e-2, 3.328371e-4, -2.4990723e-6),
    vec4<f32>(1.0350248e1, -4.792742e-2, 3.1830242e-4, -2.3476448e-6),
    vec4<f32>(1.0255649e1, -4.668188e-2, 3.0464103e-4, -2.2078127e-6),
    vec4<f32>(1.0163486e1, -4.5489352e-2, 2.9178656e-4, -2.0785092e-6),
    vec4<f32>(1.0073658e1, -4.434672e-2, 2.796788e-4, -1.9587812e-6),
    vec4<f32>(9.986068e0, -4.3251112e-2, 2.6826287e-4, -1.8477763e-6),
    vec4<f32>(9.900623e0, -4.219987e-2, 2.5748878e-4, -1.74473e-6),
    vec4<f32>(9.81724e0, -4.119051e-2, 2.4731085e-4, -1.6489558e-6),
    vec4<f32>(9.735835e0, -4.0220734e-2, 2.3768733e-4, -1.5598363e-6),
    vec4<f32>(9.61727e0, -7.767131e-2, 8.969515e-4, -1.1501065e-5),
    vec4<f32>(9.4654255e0, -7.421733e-2, 8.31489e-4, -1.0343454e-5),
    vec4<f32>(9.320236e0, -7.101183e-2, 7.7252457e-4, -9.3314375e-6),
    vec4<f32>(9.18123e0, -6.80305e-2, 7.192519e-4, -8.443248e-6),
    vec4<f32>(9.047978e0, -6.525198e-2, 6.709836e-4, -7.660858e-6),
    vec4<f32>(8.920098e0, -6.265748e-2, 6.271311e-4, -6.9692646e-6),
    vec4<f32>(8.797237e0, -6.0230374e-2, 5.8718823e-4, -6.3559146e-6),
    vec4<f32>(8.679075e0, -5.795593e-2, 5.5071805e-4, -5.8102555e-6),
    vec4<f32>(8.565321e0, -5.5821024e-2, 5.1734183e-4, -5.323376e-6),
    vec4<f32>(8.455706e0, -5.381397e-2, 4.8673004e-4, -4.8877196e-6),
    vec4<f32>(8.349987e0, -5.1924296e-2, 4.5859517e-4, -4.4968497e-6),
    vec4<f32>(8.247937e0, -5.0142616e-2, 4.326854e-4, -4.1452663e-6),
    vec4<f32>(8.14935e0, -4.8460476e-2, 4.0877942e-4, -3.8282483e-6),
    vec4<f32>(8.054033e0, -4.687027e-2, 3.8668237e-4, -3.5417322e-6),
    vec4<f32>(7.961812e0, -4.536511e-2, 3.66222e-4, -3.2822063e-6),
    vec4<f32>(7.872521e0, -4.3938763e-2, 3.4724563e-4, -3.0466267e-6),
    vec4<f32>(7.7860084e0, -4.2585574e-2, 3.2961776e-4, -2.832348e-6),
    vec4<f32>(7.702133e0, -4.130039e-2, 3.132176e-4, -2.6370622e-6),
    vec4<f32>(7.6207643e0, -4.0078525e-2, 2.9793737e-4, -2.458752e-6),
    vec4<f32>(7.5417795e0, -3.8915697e-2, 2.8368065e-4, -2.295648e-6),
    vec4<f32>(7.465065e0, -3.7807986e-2, 2.7036094e-4, -2.146195e-6),
    vec4<f32>(7.3905134e0, -3.6751807e-2, 2.5790054e-4, -2.009022e-6),
    vec4<f32>(7.3180256e0, -3.5743862e-2, 2.4622944e-4, -1.882918e-6),
    vec4<f32>(7.247508e0, -3.4781124e-2, 2.3528453e-4, -1.7668108e-6),
    vec4<f32>(7.1788726e0, -3.3860806e-2, 2.2500873e-4, -1.6597485e-6),
    vec4<f32>(7.112038e0, -3.2980334e-2, 2.1535034e-4, -1.5608846e-6),
    vec4<f32>(7.0469265e0, -3.2137338e-2, 2.0626248e-4, -1.4694648e-6),
    vec4<f32>(6.983465e0, -3.132962e-2, 1.9770255e-4, -1.3848153e-6),
    vec4<f32>(6.9215856e0, -3.0555148e-2, 1.8963176e-4, -1.3063332e-6),
    vec4<f32>(6.8612237e0, -2.9812036e-2, 1.8201474e-4, -1.2334781e-6),
    vec4<f32>(6.802318e0, -2.9098539e-2, 1.7481922e-4, -1.1657647e-6),
    vec4<f32>(6.744811e0, -2.8413026e-2, 1.6801569e-4, -1.1027564e-6),
    vec4<f32>(6.6610546e0, -5.48679e-2, 6.340294e-4, -8.130863e-6),
    vec4<f32>(6.553791e0, -5.242639e-2, 5.8774976e-4, -7.312426e-6),
    vec4<f32>(6.451232e0, -5.016055e-2, 5.460643e-4, -6.596929e-6),
    vec4<f32>(6.3530436e0, -4.8053183e-2, 5.0840294e-4, -5.968979e-6),
    vec4<f32>(6.258924e0, -4.6089202e-2, 4.742796e-4, -5.4158336e-6),
    vec4<f32>(6.1686e0, -4.425531e-2, 4.432782e-4, -4.926882e-6),
    vec4<f32>(6.081824e0, -4.2539753e-2, 4.150409e-4, -4.4932503e-6),
    vec4<f32>(5.998369e0, -4.093212e-2, 3.8925876e-4, -4.107477e-6),
    vec4<f32>(5.9180293e0, -3.9423134e-2, 3.65664e-4, -3.7632612e-6),
    vec4<f32>(5.840616e0, -3.800453e-2, 3.4402363e-4, -3.4552606e-6),
    vec4<f32>(5.765956e0, -3.6668904e-2, 3.241344e-4, -3.1789248e-6),
    vec4<f32>(5.6938896e0, -3.540962e-2, 3.0581822e-4, -2.9303644e-6),
    vec4<f32>(5.6242704e0, -3.4220707e-2, 2.8891873e-4, -2.706242e-6),
    vec4<f32>(5.5569634e0, -3.309678e-2, 2.7329806e-4, -2.5036843e-6),
    vec4<f32>(5.4918437e0, -3.2032974e-2, 2.5883445e-4, -2.3202088e-6),
    vec4<f32>(5.4287944e0, -3.102488e-2, 2.4542003e-4, -2.153663e-6),
    vec4<f32>(5.3677096e0, -3.00685e-2, 2.3295889e-4, -2.0021769e-6),
    vec4<f32>(5.3084884e0, -2.9160196e-2, 2.2136571e-4, -1.8641185e-6),
    vec4<f32>(5.251039e0, -2.8296651e-2, 2.1056428e-4, -1.7380618e-6),
    vec4<f32>(5.195274e0, -2.747484e-2, 2.004864e-4, -1.6227556e-6),
    vec4<f32>(5.1411138e0, -2.6691988e-2, 1.9107095e-4, -1.5171003e-6),
    vec4<f32>(5.088482e0, -2.5945563e-2, 1.8226299e-4, -1.4201268e-6),
    vec4<f32>(5.0373087e0, -2.5233233e-2, 1.7401301e-4, -1.330979e-6),
    vec4<f32>(4.987528e0, -2.455286e-2, 1.662764e-4, -1.2488985e-6),
    vec4<f32>(4.9390774e0, -2.390247e-2, 1.590128e-4, -1.1732125e-6),
    vec4<f32>(4.891899e0, -2.3280248e-2, 1.5218568e-4, -1.1033227e-6),
    vec4<f32>(4.8459387e0, -2.2684515e-2, 1.4576188e-4, -1.0386955e-6),
    vec4<f32>(4.801144e0, -2.2113718e-2, 1.3971128e-4, -9.788547e-7),
    vec4<f32>(4.7574677e0, -2.156642e-2, 1.3400646e-4, -9.2337405e-7),
    vec4<f32>(4.714864e0, -2.1041293e-2, 1.2862244e-4, -8.718715e-7),
    vec4<f32>(4.673289e0, -2.0537095e-2, 1.2353637e-4, -8.240039e-7),
    vec4<f32>(4.6327024e0, -2.0052679e-2, 1.1872741e-4, -7.7946254e-7),
    vec4<f32>(4.573592e0, -3.872165e-2, 4.4802664e-4, -5.747094e-6),
    vec4<f32>(4.4978957e0, -3.6996413e-2, 4.1531524e-4, -5.168539e-6),
    vec4<f32>(4.4255238e0, -3.5395343e-2, 3.8585148e-4, -4.6627565e-6),
    vec4<f32>(4.35624e0, -3.3906285e-2, 3.592323e-4, -4.218865e-6),
    vec4<f32>(4.289831e0, -3.251857e-2, 3.3511413e-4, -3.827855e-6),
    vec4<f32>(4.2261043e0, -3.12228e-2, 3.1320282e-4, -3.4822265e-6),
    vec4<f32>(4.164884e0, -3.001067e-2, 2.9324536e-4, -3.1757045e-6),
    vec4<f32>(4.106011e0, -2.8874815e-2, 2.7502337e-4, -2.9030145e-6),
    vec4<f32>(4.0493383e0, -2.7808681e-2, 2.5834754e-4, -2.6597027e-6),
    vec4<f32>(3.9947336e0, -2.6806423e-2, 2.430532e-4, -2.4419915e-6),
    vec4<f32>(3.9420736e0, -2.5862811e-2, 2.2899665e-4, -2.2466645e-6),
    vec4<f32>(3.8912463e0, -2.4973154e-2, 2.1605202e-4, -2.070972e-6),
    vec4<f32>(3.8421478e0, -2.4133228e-2, 2.0410873e-4, -1.9125546e-6),
    vec4<f32>(3.7946827e0, -2.333923e-2, 1.9306937e-4, -1.7693811e-6),
    vec4<f32>(3.7487626e0, -2.258772e-2, 1.8284784e-4, -1.6396966e-6),
    vec4<f32>(3.7043056e0, -2.1875583e-2, 1.733679e-4, -1.5219796e-6),
    vec4<f32>(3.6612358e0, -2.1199992e-2, 1.6456174e-4, -1.4149077e-6),
    vec4<f32>(3.619483e0, -2.0558374e-2, 1.5636907e-4, -1.3173277e-6),
    vec4<f32>(3.5789814e0, -1.9948386e-2, 1.48736e-4, -1.2282311e-6),
    vec4<f32>(3.5396698e0, -1.9367889e-2, 1.4161435e-4, -1.1467338e-6),
    vec4<f32>(3.5014915e0, -1.8814925e-2, 1.3496088e-4, -1.0720584e-6),
    vec4<f32>(3.464393e0, -1.8287702e-2, 1.2873676e-4, -1.0035196e-6),
    vec4<f32>(3.4283245e0, -1.7784571e-2, 1.2290703e-4, -9.405124e-7),
    vec4<f32>(3.3932395e0, -1.7304022e-2, 1.17440126e-4, -8.8250073e-7),
    vec4<f32>(3.3590944e0, -1.684466e-2, 1.12307534e-4, -8.2900897e-7),
    vec4<f32>(3.3258476e0, -1.6405202e-2, 1.0748342e-4, -7.796141e-7),
    vec4<f32>(3.293461e0, -1.598446e-2, 1.0294436e-4, -7.339391e-7),
    vec4<f32>(3.261898e0, -1.558134e-2, 9.866905e-5, -6.9164713e-7),
    vec4<f32>(3.2311246e0, -1.5194823e-2, 9.463812e-5, -6.5243705e-7),
    vec4<f32>(3.2011085e0, -1.482397e-2, 9.08339e-5, -6.1603873e-7),
    vec4<f32>(3.171819e0, -1.4467906e-2, 8.724026e-5, -5.822097e-7),
    vec4<f32>(3.1432273e0, -1.4125819e-2, 8.384245e-5, -5.507316e-7),
    vec4<f32>(3.10159e0, -2.7274514e-2, 3.1637572e-4, -4.060551e-6),
    vec4<f32>(3.0482745e0, -2.6056256e-2, 2.9326408e-4, -3.6516876e-6),
    vec4<f32>(2.9973066e0, -2.4925727e-2, 2.7244753e-4, -3.294259e-6),
    vec4<f32>(2.948519e0, -2.3874333e-2, 2.536412e-4, -2.9805735e-6),
    vec4<f32>(2.9017615e0, -2.2894537e-2, 2.3660224e-4, -2.7042624e-6),
    vec4<f32>(2.8568976e0, -2.1979697e-2, 2.2112274e-4, -2.460025e-6),
    vec4<f32>(2.8138032e0, -2.1123946e-2, 2.0702393e-4, -2.243426e-6),
    vec4<f32>(2.7723658e0, -2.0322077e-2, 1.9415145e-4, -2.0507373e-6),
    vec4<f32>(2.7324822e0, -1.956946e-2, 1.8237151e-4, -1.8788108e-6),
    vec4<f32>(2.694058e0, -1.8861966e-2, 1.7156775e-4, -1.7249769e-6),
    vec4<f32>(2.6570067e0, -1.81959e-2, 1.6163859e-4, -1.5869617e-6),
    vec4<f32>(2.621249e0, -1.7567942e-2, 1.5249508e-4, -1.4628224e-6),
    vec4<f32>(2.5867114e0, -1.6975114e-2, 1.440591e-4, -1.3508912e-6),
    vec4<f32>(2.5533268e0, -1.6414724e-2, 1.3626178e-4, -1.2497325e-6),
    vec4<f32>(2.5210326e0, -1.5884345e-2, 1.290423e-4, -1.1581059e-6),
    vec4<f32>(2.489771e0, -1.5381775e-2, 1.2234676e-4, -1.0749362e-6),
    vec4<f32>(2.4594884e0, -1.4905016e-2, 1.16127274e-4, -9.99289e-7),
    vec4<f32>(2.4301348e0, -1.4452252e-2, 1.10341214e-4, -9.303491e-7),
    vec4<f32>(2.4016645e0, -1.4021826e-2, 1.049505e-4, -8.6740374e-7),
    vec4<f32>(2.3740337e0, -1.3612227e-2, 9.99211e-5, -8.0982824e-7),
    vec4<f32>(2.3472025e0, -1.3222071e-2, 9.522244e-5, -7.5707305e-7),
    vec4<f32>(2.3211334e0, -1.2850093e-2, 9.082712e-5, -7.086541e-7),
    vec4<f32>(2.295791e0, -1.2495129e-2, 8.671039e-5, -6.641437e-7),
    vec4<f32>(2.2711422e0, -1.2156111e-2, 8.284998e-5, -6.231631e-7),
    vec4<f32>(2.2471564e0, -1.1832054e-2, 7.922573e-5, -5.8537603e-7),
    vec4<f32>(2.2238045e0, -1.1522051e-2, 7.581939e-5, -5.504837e-7),
    vec4<f32>(2.2010593e0, -1.12252645e-2, 7.2614406e-5, -5.182196e-7),
    vec4<f32>(2.1788952e0, -1.0940919e-2, 6.9595735e-5, -4.8834585e-7),
    vec4<f32>(2.1572878e0, -1.0668297e-2, 6.6749686e-5, -4.6064946e-7),
    vec4<f32>(2.1362147e0, -1.0406734e-2, 6.406377e-5, -4.349397e-7),
    vec4<f32>(2.115654e0, -1.01556135e-2, 6.1526596e-5, -4.110451e-7),
    vec4<f32>(2.0955856e0, -9.91436e-3, 5.9127746e-5, -3.888115e-7),
    vec4<f32>(2.0663643e0, -1.913965e-2, 2.2310158e-4, -2.8666036e-6),
    vec4<f32>(2.028955e0, -1.8280597e-2, 2.0678602e-4, -2.5778306e-6),
    vec4<f32>(1.9932007e0, -1.7483473e-2, 1.9209138e-4, -2.325394e-6),
    vec4<f32>(1.9589839e0, -1.674221e-2, 1.7881645e-4, -2.103859e-6),
    vec4<f32>(1.9261982e0, -1.6051486e-2, 1.6678967e-4, -1.9087265e-6),
    vec4<f32>(1.8947474e0, -1.54066095e-2, 1.5586418e-4, -1.7362504e-6),
    vec4<f32>(1.8645439e0, -1.4803437e-2, 1.459137e-4, -1.5832976e-6),
    vec4<f32>(1.8355083e0, -1.42382905e-2, 1.3682917e-4, -1.4472341e-6),
    vec4<f32>(1.8075676e0, -1.3707904e-2, 1.2851611e-4, -1.3258359e-6),
    vec4<f32>(1.7806555e0, -1.3209359e-2, 1.2089232e-4, -1.2172168e-6),
    vec4<f32>(1.7547107e0, -1.2740046e-2, 1.1388606e-4, -1.1197706e-6),
    vec4<f32>(1.7296773e0, -1.2297623e-2, 1.07434505e-4, -1.0321244e-6),
    vec4<f32>(1.7055037e0, -1.1879987e-2, 1.0148247e-4, -9.5310054e-7),
    vec4<f32>(1.6821421e0, -1.1485238e-2, 9.598133e-5, -8.816846e-7),
    vec4<f32>(1.6595486e0, -1.1111661e-2, 9.088813e-5, -8.170005e-7),
    vec4<f32>(1.6376824e0, -1.07577015e-2, 8.6164786e-5, -7.5828876e-7),
    vec4<f32>(1.6165057e0, -1.042195e-2, 8.177751e-5, -7.0488915e-7),
    vec4<f32>(1.5959834e0, -1.0103125e-2, 7.7696175e-5, -6.5622606e-7),
    vec4<f32>(1.5760827e0, -9.800056e-3, 7.389391e-5, -6.11796e-7),
    vec4<f32>(1.5567733e0, -9.511676e-3, 7.0346665e-5, -5.7115767e-7),
    vec4<f32>(1.5380268e0, -9.23701e-3, 6.703287e-5, -5.3392307e-7),
    vec4<f32>(1.5198168e0, -8.975163e-3, 6.393316e-5, -4.997502e-7),
    vec4<f32>(1.5021182e0, -8.725315e-3, 6.1030078e-5, -4.6833696e-7),
    vec4<f32>(1.484908e0, -8.486711e-3, 5.8307884e-5, -4.3941594e-7),
    vec4<f32>(1.4681643e0, -8.258658e-3, 5.5752353e-5, -4.1274967e-7),
    vec4<f32>(1.4518667e0, -8.040514e-3, 5.33506e-5, -3.881271e-7),
    vec4<f32>(1.435996e0, -7.831687e-3, 5.1090934e-5, -3.6536002e-7),
    vec4<f32>(1.4205341e0, -7.631633e-3, 4.8962735e-5, -3.4428044e-7),
    vec4<f32>(1.405464e0, -7.4398434e-3, 4.695634e-5, -3.2473798e-7),
    vec4<f32>(1.3907696e0, -7.2558504e-3, 4.5062934e-5, -3.065979e-7),
    vec4<f32>(1.3764358e0, -7.0792176e-3, 4.3274475e-5, -2.8973918e-7),
    vec4<f32>(1.3624481e0, -6.909541e-3, 4.1583604e-5, -2.7405295e-7),
    vec4<f32>(1.3420864e0, -1.3334502e-2, 1.5688321e-4, -2.0203636e-6),
    vec4<f32>(1.3160291e0, -1.2730475e-2, 1.4538468e-4, -1.8166505e-6),
    vec4<f32>(1.2911354e0, -1.2170091e-2, 1.350296e-4, -1.6385837e-6),
    vec4<f32>(1.2673225e0, -1.164907e-2, 1.2567591e-4, -1.4823263e-6),
    vec4<f32>(1.2445154e0, -1.11636575e-2, 1.1720258e-4, -1.3447013e-6),
    vec4<f32>(1.2226464e0, -1.0710545e-2, 1.0950595e-4, -1.2230647e-6),
    vec4<f32>(1.2016537e0, -1.0286809e-2, 1.02496895e-4, -1.1152046e-6),
    vec4<f32>(1.1814812e0, -9.889858e-3, 9.609848e-5, -1.0192615e-6),
    vec4<f32>(1.1620779e0, -9.517387e-3, 9.0244044e-5, -9.3366566e-7),
    vec4<f32>(1.1433969e0, -9.167339e-3, 8.487557e-5, -8.5708575e-7),
    vec4<f32>(1.1253948e0, -8.837874e-3, 7.9942474e-5, -7.8838815e-7),
    vec4<f32>(1.1080327e0, -8.527343e-3, 7.540041e-5, -7.2660396e-7),
    vec4<f32>(1.0912739e0, -8.234261e-3, 7.121046e-5, -6.709019e-7),
    vec4<f32>(1.0750849e0, -7.957289e-3, 6.7338326e-5, -6.205662e-7),
    vec4<f32>(1.0594348e0, -7.6952185e-3, 6.3753694e-5, -5.749786e-7),
    vec4<f32>(1.0442948e0, -7.4469554e-3, 6.042974e-5, -5.3360327e-7),
    vec4<f32>(1.0296384e0, -7.2115045e-3, 5.7342593e-5, -4.9597423e-7),
    vec4<f32>(1.0154408e0, -6.9879633e-3, 5.4471035e-5, -4.6168537e-7),
    vec4<f32>(1.0016792e0, -6.7755072e-3, 5.1796105e-5, -4.3038153e-7),
    vec4<f32>(9.88332e-1, -6.5733846e-3, 4.9300845e-5, -4.0175132e-7),
    vec4<f32>(9.753792e-1, -6.3809087e-3, 4.697005e-5, -3.7552098e-7),
    vec4<f32>(9.628023e-1, -6.1974484e-3, 4.479006e-5, -3.5144933e-7),
    vec4<f32>(9.505838e-1, -6.0224268e-3, 4.2748576e-5, -3.2932323e-7),
    vec4<f32>(9.3870735e-1, -5.855311e-3, 4.0834493e-5, -3.0895401e-7),
    vec4<f32>(9.271576e-1, -5.6956136e-3, 3.903779e-5, -2.9017426e-7),
    vec4<f32>(9.1592026e-1, -5.5428827e-3, 3.734938e-5, -2.7283502e-7),
    vec4<f32>(9.0498173e-1, -5.396702e-3, 3.5761022e-5, -2.5680365e-7),
    vec4<f32>(8.943293e-1, -5.256687e-3, 3.426524e-5, -2.419616e-7),
    vec4<f32>(8.8395107e-1, -5.12248e-3, 3.285521e-5, -2.282029e-7),
    vec4<f32>(8.7383574e-1, -4.993752e-3, 3.1524727e-5, -2.1543245e-7),
    vec4<f32>(8.6397266e-1, -4.8701963e-3, 3.0268126e-5, -2.0356497e-7),
    vec4<f32>(8.543517e-1, -4.751527e-3, 2.9080215e-5, -1.9252364e-7),
    vec4<f32>(8.403537e-1, -9.164223e-3, 1.0968189e-4, -1.4190899e-6),
    vec4<f32>(8.224529e-1, -8.742006e-3, 1.0160624e-4, -1.2757313e-6),
    vec4<f32>(8.053653e-1, -8.350436e-3, 9.4335206e-5, -1.1504392e-6),
    vec4<f32>(7.8903276e-1, -7.986503e-3, 8.7768734e-5, -1.0405092e-6),
    vec4<f32>(7.7340263e-1, -7.6475637e-3, 8.182156e-5, -9.43702e-7),
    vec4<f32>(7.584274e-1, -7.331293e-3, 7.6420685e-5, -8.581541e-7),
    vec4<f32>(7.4406374e-1, -7.0356345e-3, 7.150335e-5, -7.823067e-7),
    vec4<f32>(7.302723e-1, -6.758766e-3, 6.70154e-5, -7.148496e-7),
    vec4<f32>(7.1701723e-1, -6.4990656e-3, 6.290987e-5, -6.5467657e-7),
    vec4<f32>(7.042656e-1, -6.2550884e-3, 5.914596e-5, -6.0084983e-7),
    vec4<f32>(6.919873e-1, -6.025541e-3, 5.5688033e-5, -5.525707e-7),
    vec4<f32>(6.8015456e-1, -5.809264e-3, 5.25049e-5, -5.091568e-7),
    vec4<f32>(6.6874206e-1, -5.6052133e-3, 4.9569167e-5, -4.7002254e-7),
    vec4<f32>(6.5772617e-1, -5.41245e-3, 4.6856705e-5, -4.3466386e-7),
    vec4<f32>(6.470853e-1, -5.2301246e-3, 4.434619e-5, -4.0264538e-7),
    vec4<f32>(6.367992e-1, -5.057467e-3, 4.201874e-5, -3.7358978e-7),
    vec4<f32>(6.268494e-1, -4.8937807e-3, 3.9857583e-5, -3.4716905e-7),
    vec4<f32>(6.1721855e-1, -4.73843e-3, 3.784778e-5, -3.2309725e-7),
    vec4<f32>(6.0789055e-1, -4.5908373e-3, 3.597601e-5, -3.0112437e-7),
    vec4<f32>(5.9885037e-1, -4.450475e-3, 3.4230343e-5, -2.8103125e-7),
    vec4<f32>(5.9008414e-1, -4.31686e-3, 3.260009e-5, -2.6262524e-7),
    vec4<f32>(5.8157873e-1, -4.189551e-3, 3.1075655e-5, -2.4573654e-7),
    vec4<f32>(5.73322e-1, -4.0681413e-3, 2.9648383e-5, -2.3021525e-7),
    vec4<f32>(5.653025e-1, -3.9522597e-3, 2.831048e-5, -2.1592858e-7),
    vec4<f32>(5.5750954e-1, -3.8415617e-3, 2.7054895e-5, -2.0275877e-7),
    vec4<f32>(5.49933e-1, -3.7357318e-3, 2.587525e-5, -1.9060104e-7),
    vec4<f32>(5.4256356e-1, -3.634478e-3, 2.4765755e-5, -1.7936206e-7),
    vec4<f32>(5.353922e-1, -3.53753e-3, 2.3721152e-5, -1.689585e-7),
    vec4<f32>(5.2841073e-1, -3.4446386e-3, 2.2736655e-5, -1.5931576e-7),
    vec4<f32>(5.2161115e-1, -3.3555718e-3, 2.1807906e-5, -1.5036706e-7),
    vec4<f32>(5.1498604e-1, -3.270115e-3, 2.093092e-5, -1.4205236e-7),
    vec4<f32>(5.085284e-1, -3.1880683e-3, 2.010206e-5, -1.343177e-7),
    vec4<f32>(4.9914154e-1, -6.1419797e-3, 7.5777236e-5, -9.897259e-7),
    vec4<f32>(4.8715293e-1, -5.850384e-3, 7.0146205e-5, -8.893467e-7),
    vec4<f32>(4.7572577e-1, -5.580154e-3, 6.507847e-5, -8.0164517e-7),
    vec4<f32>(4.648195e-1, -5.3291814e-3, 6.0503848e-5, -7.2472056e-7),
    vec4<f32>(4.5439744e-1, -5.095618e-3, 5.6362514e-5, -6.5700004e-7),
    vec4<f32>(4.444265e-1, -4.877836e-3, 5.260328e-5, -5.9717456e-7),
    vec4<f32>(4.3487653e-1, -4.6743974e-3, 4.918215e-5, -5.4414943e-7),
    vec4<f32>(4.2572019e-1, -4.4840286e-3, 4.6061148e-5, -4.9700486e-7),
    vec4<f32>(4.1693246e-1, -4.305597e-3, 4.320738e-5, -4.5496424e-7),
    vec4<f32>(4.0849054e-1, -4.1380916e-3, 4.0592247e-5, -4.1736936e-7),
    vec4<f32>(4.0037343e-1, -3.9806096e-3, 3.8190792e-5, -3.8365988e-7),
    vec4<f32>(3.9256194e-1, -3.8323414e-3, 3.598118e-5, -3.5335694e-7),
    vec4<f32>(3.850384e-1, -3.692559e-3, 3.3944223e-5, -3.2604987e-7),
    vec4<f32>(3.777865e-1, -3.5606062e-3, 3.206303e-5, -3.0138517e-7),
    vec4<f32>(3.7079117e-1, -3.4358904e-3, 3.0322693e-5, -2.7905753e-7),
    vec4<f32>(3.6403847e-1, -3.3178758e-3, 2.8709992e-5, -2.588025e-7),
    vec4<f32>(3.575155e-1, -3.2060754e-3, 2.7213197e-5, -2.403901e-7),
    vec4<f32>(3.5121033e-1, -3.1000471e-3, 2.5821864e-5, -2.2362006e-7),
    vec4<f32>(3.4511176e-1, -2.9993884e-3, 2.4526676e-5, -2.0831716e-7),
    vec4<f32>(3.3920944e-1, -2.9037313e-3, 2.33193e-5, -1.9432788e-7),
    vec4<f32>(3.334937e-1, -2.8127402e-3, 2.2192267e-5, -1.8151732e-7),
    vec4<f32>(3.2795557e-1, -2.7261074e-3, 2.1138867e-5, -1.697666e-7),
    vec4<f32>(3.2258657e-1, -2.6435505e-3, 2.0153064e-5, -1.5897075e-7),
    vec4<f32>(3.1737882e-1, -2.5648104e-3, 1.9229408e-5, -1.4903686e-7),
    vec4<f32>(3.1232494e-1, -2.4896485e-3, 1.8362984e-5, -1.398825e-7),
    vec4<f32>(3.07418e-1, -2.417845e-3, 1.7549337e-5, -1.3143438e-7),
    vec4<f32>(3.0265146e-1, -2.349197e-3, 1.6784426e-5, -1.2362719e-7),
    vec4<f32>(2.9801923e-1, -2.283517e-3, 1.6064587e-5, -1.16402674e-7),
    vec4<f32>(2.9351553e-1, -2.2206316e-3, 1.538648e-5, -1.0970868e-7),
    vec4<f32>(2.8913495e-1, -2.1603801e-3, 1.4747067e-5, -1.034985e-7),
    vec4<f32>(2.8487235e-1, -2.1026132e-3, 1.4143571e-5, -9.773018e-8),
    vec4<f32>(2.8072292e-1, -2.0471925e-3, 1.3573456e-5, -9.2366015e-8),
    vec4<f32>(2.7470106e-1, -3.936363e-3, 5.111038e-5, -6.8013077e-7),
    vec4<f32>(2.6702744e-1, -3.7398308e-3, 4.7242545e-5, -6.105832e-7),
    vec4<f32>(2.5973195e-1, -3.5579677e-3, 4.376487e-5, -5.4985907e-7),
    vec4<f32>(2.5278676e-1, -3.389314e-3, 4.0628507e-5, -4.966319e-7),
    vec4<f32>(2.4616675e-1, -3.2325904e-3, 3.779186e-5, -4.4980428e-7),
    vec4<f32>(2.3984921e-1, -3.0866712e-3, 3.5219342e-5, -4.0846325e-7),
    vec4<f32>(2.3381352e-1, -2.9505633e-3, 3.2880387e-5, -3.7184572e-7),
    vec4<f32>(2.2804101e-1, -2.8233868e-3, 3.0748626e-5, -3.3931067e-7),
    vec4<f32>(2.2251455e-1, -2.7043596e-3, 2.8801225e-5, -3.1031723e-7),
    vec4<f32>(2.172186e-1, -2.592785e-3, 2.7018346e-5, -2.8440707e-7),
    vec4<f32>(2.1213886e-1, -2.488041e-3, 2.5382687e-5, -2.611902e-7),
    vec4<f32>(2.0726225e-1, -2.3895695e-3, 2.387911e-5, -2.4033346e-7),
    vec4<f32>(2.0257674e-1, -2.2968696e-3, 2.2494332e-5, -2.215513e-7),
    vec4<f32>(1.9807123e-1, -2.2094902e-3, 2.1216658e-5, -2.0459797e-7),
    vec4<f32>(1.937355e-1, -2.1270236e-3, 2.0035763e-5, -1.8926136e-7),
    vec4<f32>(1.895601e-1, -2.0491017e-3, 1.8942514e-5, -1.7535774e-7),
    vec4<f32>(1.8553628e-1, -1.9753908e-3, 1.7928798e-5, -1.6272753e-7),
    vec4<f32>(1.8165594e-1, -1.905587e-3, 1.6987402e-5, -1.5123165e-7),
    vec4<f32>(1.7791152e-1, -1.8394147e-3, 1.6111891e-5, -1.407486e-7),
    vec4<f32>(1.7429602e-1, -1.7766218e-3, 1.5296517e-5, -1.3117193e-7),
    vec4<f32>(1.7080294e-1, -1.7169784e-3, 1.4536122e-5, -1.2240812e-7),
    vec4<f32>(1.6742615e-1, -1.6602741e-3, 1.3826085e-5, -1.1437484e-7),
    vec4<f32>(1.6416e-1, -1.6063158e-3, 1.3162243e-5, -1.0699937e-7),
    vec4<f32>(1.6099918e-1, -1.5549266e-3, 1.2540847e-5, -1.002174e-7),
    vec4<f32>(1.5793869e-1, -1.5059436e-3, 1.1958508e-5, -9.397189e-8),
    vec4<f32>(1.549739e-1, -1.4592166e-3, 1.1412164e-5, -8.821215e-8),
    vec4<f32>(1.5210041e-1, -1.4146075e-3, 1.0899037e-5, -8.289303e-8),
    vec4<f32>(1.4931414e-1, -1.3719886e-3, 1.0416607e-5, -7.797427e-8),
    vec4<f32>(1.4661121e-1, -1.3312416e-3, 9.962581e-6, -7.341984e-8),
    vec4<f32>(1.43988e-1, -1.2922572e-3, 9.534871e-6, -6.919748e-8),
    vec4<f32>(1.4144108e-1, -1.2549341e-3, 9.131575e-6, -6.5278265e-8),
    vec4<f32>(1.3896722e-1, -1.2191781e-3, 8.750951e-6, -6.163615e-8),
    vec4<f32>(1.3538681e-1, -2.336586e-3, 3.2881064e-5, -4.5320238e-7),
    vec4<f32>(1.3084161e-1, -2.2103293e-3, 3.0306168e-5, -4.060787e-7),
    vec4<f32>(1.2653899e-1, -2.0938287e-3, 2.7995457e-5, -3.6499063e-7),
    vec4<f32>(1.22460455e-1, -1.9860966e-3, 2.5915531e-5, -3.2902528e-7),
    vec4<f32>(1.1858934e-1, -1.8862686e-3, 2.4037987e-5, -2.974281e-7),
    vec4<f32>(1.1491062e-1, -1.7935853e-3, 2.2338545e-5, -2.6957196e-7),
    vec4<f32>(1.11410685e-1, -1.7073769e-3, 2.0796371e-5, -2.4493306e-7),
    vec4<f32>(1.0807719e-1, -1.6270519e-3, 1.939352e-5, -2.2307182e-7),
    vec4<f32>(1.0489891e-1, -1.5520845e-3, 1.8114459e-5, -2.0361762e-7),
    vec4<f32>(1.0186559e-1, -1.4820076e-3, 1.6945714e-5, -1.8625667e-7),
    vec4<f32>(9.8967895e-2, -1.4164039e-3, 1.5875545e-5, -1.7072225e-7),
    vec4<f32>(9.619725e-2, -1.3549002e-3, 1.48936915e-5, -1.5678667e-7),
    vec4<f32>(9.354579e-2, -1.2971619e-3, 1.3991159e-5, -1.4425495e-7),
    vec4<f32>(9.100629e-2, -1.2428877e-3, 1.3160037e-5, -1.3295946e-7),
    vec4<f32>(8.857211e-2, -1.1918064e-3, 1.2393354e-5, -1.2275561e-7),
    vec4<f32>(8.6237095e-2, -1.143673e-3, 1.16849415e-5, -1.13518276e-7),
    vec4<f32>(8.3995596e-2, -1.0982653e-3, 1.1029334e-5, -1.0513888e-7),
    vec4<f32>(8.1842355e-2, -1.0553823e-3, 1.0421672e-5, -9.75229e-8),
    vec4<f32>(7.977251e-2, -1.0148411e-3, 9.857629e-6, -9.0587804e-8),
    vec4<f32>(7.778154e-2, -9.7647496e-4, 9.333341e-6, -8.426135e-8),
    vec4<f32>(7.586526e-2, -9.40132e-4, 8.845349e-6, -7.848015e-8),
    vec4<f32>(7.401975e-2, -9.056735e-4, 8.390552e-6, -7.318841e-8),
    vec4<f32>(7.2241396e-2, -8.7297213e-4, 7.966164e-6, -6.833694e-8),
    vec4<f32>(7.052677e-2, -8.419116e-4, 7.5696757e-6, -6.388224e-8),
    vec4<f32>(6.887273e-2, -8.123849e-4, 7.1988247e-6, -5.97858e-8),
    vec4<f32>(6.727628e-2, -7.842935e-4, 6.851566e-6, -5.601338e-8),
    vec4<f32>(6.5734655e-2, -7.57547e-4, 6.526048e-6, -5.2534563e-8),
    vec4<f32>(6.424525e-2, -7.3206174e-4, 6.220592e-6, -4.93222e-8),
    vec4<f32>(6.2805615e-2, -7.077606e-4, 5.933673e-6, -4.635205e-8),
    vec4<f32>(6.1413463e-2, -6.845723e-4, 5.663904e-6, -4.3602427e-8),
    vec4<f32>(6.006663e-2, -6.6243083e-4, 5.410022e-6, -4.1053873e-8),
    vec4<f32>(5.8763083e-2, -6.4127496e-4, 5.170872e-6, -3.868893e-8),
    vec4<f32>(5.6884773e-2, -1.2225321e-3, 1.9353032e-5, -2.836588e-7),
    vec4<f32>(5.45149e-2, -1.1484134e-3, 1.7744429e-5, -2.5319105e-7),
    vec4<f32>(5.2287064e-2, -1.080378e-3, 1.6306392e-5, -2.2670228e-7),
    vec4<f32>(5.0189756e-2, -1.0177891e-3, 1.5016932e-5, -2.0358308e-7),
    vec4<f32>(4.821265e-2, -9.6009107e-4, 1.38573805e-5, -1.8333057e-7),
    vec4<f32>(4.634646e-2, -9.067972e-4, 1.28118245e-5, -1.6552761e-7),
    vec4<f32>(4.458281e-2, -8.574795e-4, 1.18666385e-5, -1.498264e-7),
    vec4<f32>(4.291414e-2, -8.117607e-4, 1.1010108e-5, -1.3593566e-7),
    vec4<f32>(4.1333593e-2, -7.693071e-4, 1.02321255e-5, -1.2361022e-7),
    vec4<f32>(3.9834935e-2, -7.298224e-4, 9.523936e-6, -1.1264291e-7),
    vec4<f32>(3.84125e-2, -6.930431e-4, 8.87793e-6, -1.0285794e-7),
    vec4<f32>(3.7061118e-2, -6.587342e-4, 8.287473e-6, -9.410557e-8),
    vec4<f32>(3.5776056e-2, -6.2668533e-4, 7.746764e-6, -8.625777e-8),
    vec4<f32>(3.4552995e-2, -5.96708e-4, 7.250712e-6, -7.920469e-8),
    vec4<f32>(3.338796e-2, -5.6863273e-4, 6.794838e-6, -7.2851755e-8),
    vec4<f32>(3.2277297e-2, -5.4230704e-4, 6.3751927e-6, -6.71173e-8),
    vec4<f32>(3.1217655e-2, -5.1759306e-4, 5.988281e-6, -6.1930564e-8),
    vec4<f32>(3.0205933e-2, -4.943662e-4, 5.631005e-6, -5.723007e-8),
    vec4<f32>(2.9239275e-2, -4.7251367e-4, 5.300612e-6, -5.296225e-8),
    vec4<f32>(2.8315032e-2, -4.5193286e-4, 4.9946484e-6, -4.9080302e-8),
    vec4<f32>(2.7430758e-2, -4.3253053e-4, 4.7109243e-6, -4.5543224e-8),
    vec4<f32>(2.658418e-2, -4.142218e-4, 4.447481e-6, -4.2315023e-8),
    vec4<f32>(2.5773194e-2, -3.969291e-4, 4.202562e-6, -3.9363997e-8),
    vec4<f32>(2.4995834e-2, -3.8058154e-4, 3.97459e-6, -3.666219e-8),
    vec4<f32>(2.425028e-2, -3.6511428e-4, 3.7621446e-6, -3.4184872e-8),
    vec4<f32>(2.353483e-2, -3.5046777e-4, 3.5639462e-6, -3.1910133e-8),
    vec4<f32>(2.2847898e-2, -3.3658743e-4, 3.3788388e-6, -2.9818512e-8),
    vec4<f32>(2.2188004e-2, -3.23423e-4, 3.205776e-6, -2.7892698e-8),
    vec4<f32>(2.155376e-2, -3.109283e-4, 3.0438107e-6, -2.611725e-8),
    vec4<f32>(2.0943873e-2, -2.990606e-4, 2.8920822e-6, -2.4478386e-8),
    vec4<f32>(2.0357126e-2, -2.877806e-4, 2.7498093e-6, -2.2963766e-8),
    vec4<f32>(1.9792382e-2, -2.7705193e-4, 2.6162795e-6, -2.156233e-8),
    vec4<f32>(1.8984202e-2, -5.2383944e-4, 9.725706e-6, -1.5723472e-7),
    vec4<f32>(1.7974196e-2, -4.867584e-4, 8.837187e-6, -1.393348e-7),
    vec4<f32>(1.7034939e-2, -4.5302548e-4, 8.048596e-6, -1.2386228e-7),
    vec4<f32>(1.6160112e-2, -4.2226876e-4, 7.346547e-6, -1.1043572e-7),
    vec4<f32>(1.5344095e-2, -3.9416543e-4, 6.7197325e-6, -9.874162e-8),
    vec4<f32>(1.4581869e-2, -3.684344e-4, 6.158556e-6, -8.852094e-8),
    vec4<f32>(1.3868941e-2, -3.4483e-4, 5.6548406e-6, -7.955855e-8),
    vec4<f32>(1.3201276e-2, -3.2313686e-4, 5.20159e-6, -7.167496e-8),
    vec4<f32>(1.2575245e-2, -3.031655e-4, 4.7927933e-6, -6.47197e-8),
    vec4<f32>(1.1987578e-2, -2.8474873e-4, 4.423271e-6, -5.856613e-8),
    vec4<f32>(1.1435313e-2, -2.6773877e-4, 4.088542e-6, -5.3107204e-8),
    vec4<f32>(1.0915773e-2, -2.5200436e-4, 3.7847171e-6, -4.82521e-8),
    vec4<f32>(1.0426523e-2, -2.3742893e-4, 3.5084117e-6, -4.3923464e-8),
    vec4<f32>(9.965354e-3, -2.2390844e-4, 3.2566695e-6, -4.00552e-8),
    vec4<f32>(9.530249e-3, -2.1134996e-4, 3.026902e-6, -3.6590613e-8),
    vec4<f32>(9.119368e-3, -1.9967026e-4, 2.8168372e-6, -3.3480948e-8),
    vec4<f32>(8.731032e-3, -1.8879463e-4, 2.624474e-6, -3.0684127e-8),
    vec4<f32>(8.363699e-3, -1.7865589e-4, 2.4480473e-6, -2.8163734e-8),
    vec4<f32>(8.015958e-3, -1.6919349e-4, 2.2859954e-6, -2.5888165e-8),
    vec4<f32>(7.6865107e-3, -1.6035278e-4, 2.1369333e-6, -2.3829914e-8),
    vec4<f32>(7.374165e-3, -1.520843e-4, 1.9996305e-6, -2.1964986e-8),
    vec4<f32>(7.0778215e-3, -1.443433e-4, 1.8729917e-6, -2.027239e-8),
    vec4<f32>(6.796467e-3, -1.3708908e-4, 1.7560387e-6, -1.873372e-8),
    vec4<f32>(6.5291654e-3, -1.3028471e-4, 1.6478979e-6, -1.7332807e-8),
    vec4<f32>(6.2750513e-3, -1.2389653e-4, 1.5477858e-6, -1.60554e-8),
    vec4<f32>(6.0333223e-3, -1.17893884e-4, 1.4550002e-6, -1.4888927e-8),
    vec4<f32>(5.803237e-3, -1.1224873e-4, 1.3689091e-6, -1.3822266e-8),
    vec4<f32>(5.5841063e-3, -1.0693546e-4, 1.2889441e-6, -1.2845559e-8),
    vec4<f32>(5.37529e-3, -1.0193063e-4, 1.214592e-6, -1.19500525e-8),
    vec4<f32>(5.1761926e-3, -9.721272e-5, 1.1453893e-6, -1.112796e-8),
    vec4<f32>(4.986261e-3, -9.2762e-5, 1.080917e-6, -1.0372339e-8),
    vec4<f32>(4.8049786e-3, -8.8560315e-5, 1.0207948e-6, -9.676995e-9),
    vec4<f32>(4.5482293e-3, -1.6537713e-4, 3.7529771e-6, -6.98945e-8),
    vec4<f32>(4.2319414e-3, -1.5117212e-4, 3.36045e-6, -6.11557e-8),
    vec4<f32>(3.9425613e-3, -1.38437e-4, 3.0164524e-6, -5.3683262e-8),
    vec4<f32>(3.677334e-3, -1.2699206e-4, 2.714032e-6, -4.7268394e-8),
    vec4<f32>(3.4338364e-3, -1.1668308e-4, 2.44737e-6, -4.1740837e-8),
    vec4<f32>(3.2099334e-3, -1.0737714e-4, 2.2115732e-6, -3.6961026e-8),
    vec4<f32>(3.0037363e-3, -9.895934e-5, 2.00251e-6, -3.281397e-8),
    vec4<f32>(2.8135707e-3, -9.132999e-5, 1.8166777e-6, -2.9204465e-8),
    vec4<f32>(2.6379486e-3, -8.4402316e-5, 1.6510946e-6, -2.6053357e-8),
    vec4<f32>(2.4755443e-3, -7.8100595e-5, 1.5032142e-6, -2.3294525e-8),
    vec4<f32>(2.3251735e-3, -7.235851e-5, 1.3708535e-6, -2.0872529e-8),
    vec4<f32>(2.1857761e-3, -6.7117864e-5, 1.252135e-6, -1.8740693e-8),
    vec4<f32>(2.056402e-3, -6.232742e-5, 1.145439e-6, -1.6859579e-8),
    vec4<f32>(1.9361966e-3, -5.7941972e-5, 1.0493641e-6, -1.5195745e-8),
    vec4<f32>(1.8243908e-3, -5.3921543e-5, 9.626938e-7, -1.3720742e-8),
    vec4<f32>(1.7202907e-3, -5.0230694e-5, 8.843698e-7, -1.2410282e-8),
    vec4<f32>(1.6232694e-3, -4.6837933e-5, 8.1346866e-7, -1.1243571e-8),
    vec4<f32>(1.532759e-3, -4.371523e-5, 7.4918273e-7, -1.0202755e-8),
    vec4<f32>(1.4482451e-3, -4.0837585e-5, 6.908037e-7, -9.272457e-9),
    vec4<f32>(1.3692604e-3, -3.8182643e-5, 6.3770915e-7, -8.439398e-9),
    vec4<f32>(1.2953795e-3, -3.573039e-5, 5.893509e-7, -7.6920825e-9),
    vec4<f32>(1.2262156e-3, -3.3462875e-5, 5.452451e-7, -7.020533e-9),
    vec4<f32>(1.1614156e-3, -3.136397e-5, 5.049637e-7, -6.416069e-9),
    vec4<f32>(1.100657e-3, -2.941915e-5, 4.6812735e-7, -5.871119e-9),
    vec4<f32>(1.0436451e-3, -2.7615326e-5, 4.3439923e-7, -5.379067e-9),
    vec4<f32>(9.901096e-4, -2.594068e-5, 4.0347967e-7, -4.934116e-9),
    vec4<f32>(9.398034e-4, -2.4384526e-5, 3.7510165e-7, -4.531179e-9),
    vec4<f32>(8.9249905e-4, -2.2937182e-5, 3.4902672e-7, -4.165782e-9),
    vec4<f32>(8.47988e-4, -2.1589874e-5, 3.2504175e-7, -3.8339816e-9),
    vec4<f32>(8.060782e-4, -2.0334634e-5, 3.0295573e-7, -3.532296e-9),
    vec4<f32>(7.665929e-4, -1.9164214e-5, 2.8259743e-7, -3.2576466e-9),
    vec4<f32>(7.2936923e-4, -1.807202e-5, 2.6381295e-7, -3.0073048e-9),
    vec4<f32>(6.774483e-4, -3.313478e-5, 9.534653e-7, -2.1382784e-8),
    vec4<f32>(6.148264e-4, -2.9566318e-5, 8.3458946e-7, -1.8323824e-8),
    vec4<f32>(5.588896e-4, -2.643846e-5, 7.325478e-7, -1.5756715e-8),
    vec4<f32>(5.0882023e-4, -2.3689447e-5, 6.4466167e-7, -1.359353e-8),
    vec4<f32>(4.639141e-4, -2.1267246e-5, 5.687263e-7, -1.1763643e-8),
    vec4<f32>(4.2356286e-4, -1.912784e-5, 5.0291845e-7, -1.0210012e-8),
    vec4<f32>(3.8723927e-4, -1.7233862e-5, 4.4572374e-7, -8.886333e-9),
    vec4<f32>(3.5448512e-4, -1.5553485e-5, 3.9587925e-7, -7.754835e-9),
    vec4<f32>(3.2490114e-4, -1.4059497e-5, 3.5232745e-7, -6.7845694e-9),
    vec4<f32>(2.981385e-4, -1.2728568e-5, 3.1417957e-7, -5.950064e-9),
    vec4<f32>(2.738916e-4, -1.15406365e-5, 2.80686e-7, -5.230268e-9),
    vec4<f32>(2.518922e-4, -1.0478397e-5, 2.5121233e-7, -4.6077178e-9),
    vec4<f32>(2.3190425e-4, -9.5268815e-6, 2.2521986e-7, -4.0678665e-9),
    vec4<f32>(2.1371956e-4, -8.673115e-6, 2.022499e-7, -3.5985581e-9),
    vec4<f32>(1.9715418e-4, -7.905816e-6, 1.8191054e-7, -3.189597e-9),
    vec4<f32>(1.8204523e-4, -7.2151556e-6, 1.638661e-7, -2.832404e-9),
    vec4<f32>(1.6824821e-4, -6.5925487e-6, 1.4782825e-7, -2.5197378e-9),
    vec4<f32>(1.556347e-4, -6.0304806e-6, 1.3354867e-7, -2.2454676e-9),
    vec4<f32>(1.4409034e-4, -5.52236e-6, 1.2081298e-7, -2.0043878e-9),
    vec4<f32>(1.3351317e-4, -5.062393e-6, 1.0943566e-7, -1.792066e-9),
    vec4<f32>(1.2381207e-4, -4.645479e-6, 9.925578e-8, -1.6047187e-9),
    vec4<f32>(1.1490557e-4, -4.267114e-6, 9.013342e-8, -1.439107e-9),
    vec4<f32>(1.0672059e-4, -3.9233205e-6, 8.194671e-8, -1.2924517e-9),
    vec4<f32>(9.9191595e-5, -3.610574e-6, 7.458923e-8, -1.162363e-9),
    vec4<f32>(9.225969e-5, -3.3257486e-6, 6.79679e-8, -1.0467801e-9),
    vec4<f32>(8.587185e-5, -3.0660676e-6, 6.2001156e-8, -9.439232e-10),
    vec4<f32>(7.998031e-5, -2.8290597e-6, 5.6617353e-8, -8.5225055e-10),
    vec4<f32>(7.454197e-5, -2.6125226e-6, 5.175348e-8, -7.70425e-10),
    vec4<f32>(6.951788e-5, -2.4144904e-6, 4.7354025e-8, -6.97284e-10),
    vec4<f32>(6.4872846e-5, -2.233206e-6, 4.336997e-8, -6.3181477e-10),
    vec4<f32>(6.0574945e-5, -2.0670968e-6, 3.9757996e-8, -5.731336e-10),
    vec4<f32>(5.659528e-5, -1.914753e-6, 3.647974e-8, -5.204679e-10),
);

// Exponential Λ(√q), 64 ≤ q < 4096: the Rust EXPONENTIAL32_QB (f32 cubics), bit for bit.
const MS_EXP_QB_K0: i32 = 6;
const MS_EXP_QB_K1: i32 = 12;
const MS_EXP_QB_M: u32 = 7u;
var<private> MS_EXP_QB: array<vec4<f32>, 768> = array<vec4<f32>, 768>(
    vec4<f32>(5.380349e-5, -9.0438135e-7, 8.553779e-9, -6.055752e-11),
    vec4<f32>(5.2028467e-5, -8.7088296e-7, 8.198912e-9, -5.7753618e-11),
    vec4<f32>(5.0319035e-5, -8.387709e-7, 7.860433e-9, -5.5093576e-11),
    vec4<f32>(4.86725e-5, -8.0798134e-7, 7.537504e-9, -5.256925e-11),
    vec4<f32>(4.708627e-5, -7.784537e-7, 7.2293336e-9, -5.0173015e-11),
    vec4<f32>(4.555788e-5, -7.5013037e-7, 6.935174e-9, -4.789771e-11),
    vec4<f32>(4.4084984e-5, -7.2295677e-7, 6.654321e-9, -4.5736605e-11),
    vec4<f32>(4.2665324e-5, -6.9688105e-7, 6.3861085e-9, -4.36834e-11),
    vec4<f32>(4.129676e-5, -6.7185385e-7, 6.1299064e-9, -4.1732152e-11),
    vec4<f32>(3.997724e-5, -6.478285e-7, 5.88512e-9, -3.9877296e-11),
    vec4<f32>(3.8704806e-5, -6.247603e-7, 5.6511875e-9, -3.811359e-11),
    vec4<f32>(3.747759e-5, -6.026069e-7, 5.427576e-9, -3.6436104e-11),
    vec4<f32>(3.6293797e-5, -5.813282e-7, 5.2137827e-9, -3.48402e-11),
    vec4<f32>(3.515172e-5, -5.608858e-7, 5.0093316e-9, -3.3321523e-11),
    vec4<f32>(3.404972e-5, -5.412432e-7, 4.813771e-9, -3.1875953e-11),
    vec4<f32>(3.2986238e-5, -5.223657e-7, 4.6266746e-9, -3.049963e-11),
    vec4<f32>(3.195977e-5, -5.042204e-7, 4.447638e-9, -2.9188905e-11),
    vec4<f32>(3.0968888e-5, -4.8677566e-7, 4.276277e-9, -2.7940344e-11),
    vec4<f32>(3.001222e-5, -4.7000162e-7, 4.1122297e-9, -2.6750708e-11),
    vec4<f32>(2.9088453e-5, -4.538697e-7, 3.9551513e-9, -2.561694e-11),
    vec4<f32>(2.8196331e-5, -4.3835266e-7, 3.804715e-9, -2.4536165e-11),
    vec4<f32>(2.733465e-5, -4.2342458e-7, 3.6606118e-9, -2.350566e-11),
    vec4<f32>(2.6502257e-5, -4.0906073e-7, 3.5225471e-9, -2.2522857e-11),
    vec4<f32>(2.5698046e-5, -3.952375e-7, 3.3902425e-9, -2.1585338e-11),
    vec4<f32>(2.492096e-5, -3.8193238e-7, 3.2634329e-9, -2.0690808e-11),
    vec4<f32>(2.4169985e-5, -3.691239e-7, 3.141867e-9, -1.9837111e-11),
    vec4<f32>(2.3444149e-5, -3.5679162e-7, 3.025306e-9, -1.9022197e-11),
    vec4<f32>(2.2742515e-5, -3.449159e-7, 2.9135232e-9, -1.8244139e-11),
    vec4<f32>(2.2064192e-5, -3.334781e-7, 2.806303e-9, -1.7501108e-11),
    vec4<f32>(2.1408323e-5, -3.2246038e-7, 2.70344e-9, -1.6791376e-11),
    vec4<f32>(2.0774081e-5, -3.1184572e-7, 2.60474e-9, -1.6113305e-11),
    vec4<f32>(2.0160682e-5, -3.0161783e-7, 2.510017e-9, -1.5465353e-11),
    vec4<f32>(1.9567364e-5, -2.9176115e-7, 2.4190956e-9, -1.484605e-11),
    vec4<f32>(1.89934e-5, -2.8226083e-7, 2.3318072e-9, -1.4254011e-11),
    vec4<f32>(1.8438092e-5, -2.7310264e-7, 2.247993e-9, -1.3687922e-11),
    vec4<f32>(1.790077e-5, -2.64273e-7, 2.1675004e-9, -1.3146538e-11),
    vec4<f32>(1.738079e-5, -2.5575892e-7, 2.090185e-9, -1.2628678e-11),
    vec4<f32>(1.6877531e-5, -2.4754797e-7, 2.0159092e-9, -1.2133224e-11),
    vec4<f32>(1.6390404e-5, -2.3962826e-7, 1.9445414e-9, -1.1659115e-11),
    vec4<f32>(1.5918833e-5, -2.3198841e-7, 1.875957e-9, -1.1205346e-11),
    vec4<f32>(1.546227e-5, -2.2461751e-7, 1.8100367e-9, -1.0770962e-11),
    vec4<f32>(1.502019e-5, -2.1750513e-7, 1.7466667e-9, -1.0355058e-11),
    vec4<f32>(1.4592085e-5, -2.1064132e-7, 1.685739e-9, -9.956774e-12),
    vec4<f32>(1.4177465e-5, -2.040165e-7, 1.6271501e-9, -9.575295e-12),
    vec4<f32>(1.3775865e-5, -1.976215e-7, 1.5708017e-9, -9.2098456e-12),
    vec4<f32>(1.33868325e-5, -1.9144758e-7, 1.5165998e-9, -8.859689e-12),
    vec4<f32>(1.3009933e-5, -1.854863e-7, 1.4644548e-9, -8.524128e-12),
    vec4<f32>(1.264475e-5, -1.7972964e-7, 1.414281e-9, -8.202496e-12),
    vec4<f32>(1.2290883e-5, -1.7416986e-7, 1.365997e-9, -7.894164e-12),
    vec4<f32>(1.1947945e-5, -1.6879955e-7, 1.3195245e-9, -7.598529e-12),
    vec4<f32>(1.1615563e-5, -1.6361163e-7, 1.2747892e-9, -7.315022e-12),
    vec4<f32>(1.1293381e-5, -1.5859929e-7, 1.2317198e-9, -7.043099e-12),
    vec4<f32>(1.09810535e-5, -1.53756e-7, 1.1902487e-9, -6.7822445e-12),
    vec4<f32>(1.0678249e-5, -1.4907552e-7, 1.1503107e-9, -6.5319664e-12),
    vec4<f32>(1.0384647e-5, -1.445518e-7, 1.1118438e-9, -6.2917965e-12),
    vec4<f32>(1.00999405e-5, -1.4017911e-7, 1.0747889e-9, -6.0612904e-12),
    vec4<f32>(9.823833e-6, -1.3595192e-7, 1.039089e-9, -5.8400233e-12),
    vec4<f32>(9.55604e-6, -1.318649e-7, 1.00469e-9, -5.627592e-12),
    vec4<f32>(9.296284e-6, -1.2791294e-7, 9.715402e-10, -5.4236116e-12),
    vec4<f32>(9.044301e-6, -1.2409117e-7, 9.395897e-10, -5.227716e-12),
    vec4<f32>(8.799836e-6, -1.2039487e-7, 9.087913e-10, -5.0395556e-12),
    vec4<f32>(8.562642e-6, -1.1681954e-7, 8.790995e-10, -4.8587974e-12),
    vec4<f32>(8.332479e-6, -1.1336084e-7, 8.5047086e-10, -4.685125e-12),
    vec4<f32>(8.109123e-6, -1.1001459e-7, 8.228638e-10, -4.518235e-12),
    vec4<f32>(7.8923495e-6, -1.0677678e-7, 7.962384e-10, -4.35784e-12),
    vec4<f32>(7.681946e-6, -1.0364358e-7, 7.705566e-10, -4.203664e-12),
    vec4<f32>(7.4777076e-6, -1.00611274e-7, 7.4578194e-10, -4.0554443e-12),
    vec4<f32>(7.279436e-6, -9.7676306e-8, 7.2187933e-10, -3.9129307e-12),
    vec4<f32>(7.0869396e-6, -9.483526e-8, 6.988153e-10, -3.7758846e-12),
    vec4<f32>(6.9000344e-6, -9.2084846e-8, 6.765577e-10, -3.644077e-12),
    vec4<f32>(6.718542e-6, -8.9421896e-8, 6.550758e-10, -3.5172904e-12),
    vec4<f32>(6.5422905e-6, -8.6843364e-8, 6.3434014e-10, -3.3953168e-12),
    vec4<f32>(6.3711145e-6, -8.434633e-8, 6.143223e-10, -3.2779575e-12),
    vec4<f32>(6.204853e-6, -8.192798e-8, 5.9499533e-10, -3.1650225e-12),
    vec4<f32>(6.0433517e-6, -7.95856e-8, 5.7633315e-10, -3.0563306e-12),
    vec4<f32>(5.8864616e-6, -7.731657e-8, 5.5831084e-10, -2.9517085e-12),
    vec4<f32>(5.734038e-6, -7.511839e-8, 5.4090443e-10, -2.8509905e-12),
    vec4<f32>(5.5859423e-6, -7.298864e-8, 5.2409105e-10, -2.7540182e-12),
    vec4<f32>(5.4420398e-6, -7.0925e-8, 5.0784865e-10, -2.6606402e-12),
    vec4<f32>(5.3022e-6, -6.892521e-8, 4.9215615e-10, -2.570712e-12),
    vec4<f32>(5.166298e-6, -6.698713e-8, 4.7699317e-10, -2.484095e-12),
    vec4<f32>(5.0342114e-6, -6.510867e-8, 4.6234033e-10, -2.400657e-12),
    vec4<f32>(4.9058244e-6, -6.3287835e-8, 4.4817888e-10, -2.3202707e-12),
    vec4<f32>(4.781023e-6, -6.152269e-8, 4.3449092e-10, -2.2428155e-12),
    vec4<f32>(4.659698e-6, -5.981138e-8, 4.212592e-10, -2.1681751e-12),
    vec4<f32>(4.541743e-6, -5.8152104e-8, 4.0846715e-10, -2.0962388e-12),
    vec4<f32>(4.427056e-6, -5.6543144e-8, 3.9609888e-10, -2.0268997e-12),
    vec4<f32>(4.315538e-6, -5.4982834e-8, 3.841391e-10, -1.9600565e-12),
    vec4<f32>(4.2070933e-6, -5.346957e-8, 3.7257317e-10, -1.8956115e-12),
    vec4<f32>(4.101629e-6, -5.2001806e-8, 3.6138692e-10, -1.8334715e-12),
    vec4<f32>(3.999057e-6, -5.057805e-8, 3.5056685e-10, -1.773547e-12),
    vec4<f32>(3.899289e-6, -4.919686e-8, 3.400999e-10, -1.7157523e-12),
    vec4<f32>(3.8022417e-6, -4.785685e-8, 3.2997352e-10, -1.6600054e-12),
    vec4<f32>(3.7078348e-6, -4.655669e-8, 3.201757e-10, -1.6062276e-12),
    vec4<f32>(3.6159893e-6, -4.5295078e-8, 3.106948e-10, -1.5543434e-12),
    vec4<f32>(3.5266296e-6, -4.4070774e-8, 3.0151975e-10, -1.5042806e-12),
    vec4<f32>(3.4396821e-6, -4.2882576e-8, 2.9263977e-10, -1.45597e-12),
    vec4<f32>(3.355076e-6, -4.1729322e-8, 2.8404457e-10, -1.409345e-12),
    vec4<f32>(3.2727423e-6, -4.0609898e-8, 2.7572422e-10, -1.3643419e-12),
    vec4<f32>(3.1926145e-6, -3.952322e-8, 2.676692e-10, -1.3208997e-12),
    vec4<f32>(3.1146283e-6, -3.8468244e-8, 2.5987026e-10, -1.2789596e-12),
    vec4<f32>(3.0387212e-6, -3.7443968e-8, 2.5231864e-10, -1.2384654e-12),
    vec4<f32>(2.9648327e-6, -3.6449418e-8, 2.4500577e-10, -1.1993631e-12),
    vec4<f32>(2.8929041e-6, -3.5483655e-8, 2.3792346e-10, -1.1616009e-12),
    vec4<f32>(2.8228794e-6, -3.454577e-8, 2.3106385e-10, -1.1251292e-12),
    vec4<f32>(2.7547032e-6, -3.363489e-8, 2.244193e-10, -1.0899001e-12),
    vec4<f32>(2.6883224e-6, -3.2750172e-8, 2.1798253e-10, -1.0558678e-12),
    vec4<f32>(2.6236855e-6, -3.1890796e-8, 2.1174647e-10, -1.0229884e-12),
    vec4<f32>(2.5607428e-6, -3.1055976e-8, 2.0570433e-10, -9.912196e-13),
    vec4<f32>(2.4994458e-6, -3.0244944e-8, 1.9984958e-10, -9.605207e-13),
    vec4<f32>(2.4397477e-6, -2.9456967e-8, 1.9417593e-10, -9.308529e-13),
    vec4<f32>(2.381603e-6, -2.8691332e-8, 1.8867727e-10, -9.0217867e-13),
    vec4<f32>(2.324968e-6, -2.7947351e-8, 1.8334777e-10, -8.7446196e-13),
    vec4<f32>(2.2697996e-6, -2.722436e-8, 1.7818179e-10, -8.4766824e-13),
    vec4<f32>(2.2160568e-6, -2.6521713e-8, 1.7317388e-10, -8.2176426e-13),
    vec4<f32>(2.1636997e-6, -2.583879e-8, 1.6831882e-10, -7.967181e-13),
    vec4<f32>(2.1126891e-6, -2.5174991e-8, 1.6361153e-10, -7.724991e-13),
    vec4<f32>(2.0629873e-6, -2.4529731e-8, 1.5904715e-10, -7.490776e-13),
    vec4<f32>(2.014558e-6, -2.3902452e-8, 1.5462098e-10, -7.264254e-13),
    vec4<f32>(1.967366e-6, -2.3292607e-8, 1.5032849e-10, -7.04515e-13),
    vec4<f32>(1.9213765e-6, -2.2699673e-8, 1.4616529e-10, -6.833203e-13),
    vec4<f32>(1.8765563e-6, -2.2123139e-8, 1.4212719e-10, -6.62816e-13),
    vec4<f32>(1.8328732e-6, -2.1562515e-8, 1.3821011e-10, -6.4297775e-13),
    vec4<f32>(1.790296e-6, -2.1017321e-8, 1.3441011e-10, -6.237823e-13),
    vec4<f32>(1.7487939e-6, -2.0487102e-8, 1.3072342e-10, -6.052071e-13),
    vec4<f32>(1.7083379e-6, -1.9971408e-8, 1.2714636e-10, -5.8723046e-13),
    vec4<f32>(1.6688989e-6, -1.9469807e-8, 1.2367543e-10, -5.698316e-13),
    vec4<f32>(1.6304494e-6, -1.8981883e-8, 1.2030722e-10, -5.529905e-13),
    vec4<f32>(1.5745718e-6, -3.6549526e-8, 4.6178492e-10, -4.2300135e-12),
    vec4<f32>(1.5032864e-6, -3.4752276e-8, 4.3714554e-10, -3.985475e-12),
    vec4<f32>(1.4354989e-6, -3.3050704e-8, 4.139272e-10, -3.756186e-12),
    vec4<f32>(1.3710236e-6, -3.1439303e-8, 3.9204145e-10, -3.541123e-12),
    vec4<f32>(1.3096851e-6, -2.991291e-8, 3.7140582e-10, -3.3393366e-12),
    vec4<f32>(1.2513184e-6, -2.8466689e-8, 3.519434e-10, -3.1499451e-12),
    vec4<f32>(1.1957679e-6, -2.7096082e-8, 3.335822e-10, -2.97213e-12),
    vec4<f32>(1.1428866e-6, -2.5796824e-8, 3.162551e-10, -2.80513e-12),
    vec4<f32>(1.0925357e-6, -2.4564907e-8, 2.998994e-10, -2.6482384e-12),
    vec4<f32>(1.0445846e-6, -2.3396565e-8, 2.844564e-10, -2.5007975e-12),
    vec4<f32>(9.989095e-7, -2.2288255e-8, 2.6987126e-10, -2.3621955e-12),
    vec4<f32>(9.553937e-7, -2.1236653e-8, 2.560927e-10, -2.2318631e-12),
    vec4<f32>(9.139271e-7, -2.0238629e-8, 2.4307267e-10, -2.1092707e-12),
    vec4<f32>(8.744055e-7, -1.9291239e-8, 2.3076624e-10, -1.9939241e-12),
    vec4<f32>(8.3673024e-7, -1.8391717e-8, 2.1913132e-10, -1.8853638e-12),
    vec4<f32>(8.0080844e-7, -1.7537452e-8, 2.0812851e-10, -1.7831613e-12),
    vec4<f32>(7.665519e-7, -1.6725993e-8, 1.9772088e-10, -1.6869168e-12),
    vec4<f32>(7.3387747e-7, -1.5955031e-8, 1.8787379e-10, -1.5962574e-12),
    vec4<f32>(7.0270625e-7, -1.5222387e-8, 1.785548e-10, -1.5108357e-12),
    vec4<f32>(6.729637e-7, -1.4526012e-8, 1.6973345e-10, -1.430327e-12),
    vec4<f32>(6.445793e-7, -1.3863972e-8, 1.6138119e-10, -1.3544281e-12),
    vec4<f32>(6.174862e-7, -1.3234446e-8, 1.5347122e-10, -1.2828561e-12),
    vec4<f32>(5.91621e-7, -1.26357165e-8, 1.4597838e-10, -1.2153465e-12),
    vec4<f32>(5.6692386e-7, -1.20661605e-8, 1.3887906e-10, -1.1516521e-12),
    vec4<f32>(5.4333793e-7, -1.1524251e-8, 1.3215104e-10, -1.0915419e-12),
    vec4<f32>(5.208094e-7, -1.1008543e-8, 1.2577347e-10, -1.0347996e-12),
    vec4<f32>(4.992872e-7, -1.05176765e-8, 1.197268e-10, -9.812233e-13),
    vec4<f32>(4.78723e-7, -1.0050365e-8, 1.1399255e-10, -9.306236e-13),
    vec4<f32>(4.5907086e-7, -9.605392e-9, 1.0855343e-10, -8.8282344e-13),
    vec4<f32>(4.402873e-7, -9.181612e-9, 1.0339314e-10, -8.3765693e-13),
    vec4<f32>(4.22331e-7, -8.777939e-9, 9.849634e-11, -7.9496875e-13),
    vec4<f32>(4.051628e-7, -8.393351e-9, 9.3848616e-11, -7.546133e-13),
    vec4<f32>(3.8874552e-7, -8.026876e-9, 8.9436375e-11, -7.1645413e-13),
    vec4<f32>(3.7304383e-7, -7.6776e-9, 8.5246823e-11, -6.8036337e-13),
    vec4<f32>(3.5802424e-7, -7.3446556e-9, 8.126792e-11, -6.4622103e-13),
    vec4<f32>(3.4365488e-7, -7.027224e-9, 7.7488314e-11, -6.139146e-13),
    vec4<f32>(3.299055e-7, -6.7245294e-9, 7.389731e-11, -5.833385e-13),
    vec4<f32>(3.1674742e-7, -6.435837e-9, 7.0484826e-11, -5.5439366e-13),
    vec4<f32>(3.041533e-7, -6.1604535e-9, 6.724136e-11, -5.2698693e-13),
    vec4<f32>(2.9209718e-7, -5.8977196e-9, 6.4157936e-11, -5.01031e-13),
    vec4<f32>(2.805544e-7, -5.647013e-9, 6.1226114e-11, -4.7644375e-13),
    vec4<f32>(2.695015e-7, -5.407743e-9, 5.84379e-11, -4.531481e-13),
    vec4<f32>(2.5891617e-7, -5.179351e-9, 5.5785775e-11, -4.3107147e-13),
    vec4<f32>(2.487772e-7, -4.9613065e-9, 5.3262627e-11, -4.1014574e-13),
    vec4<f32>(2.3906438e-7, -4.7531077e-9, 5.0861745e-11, -3.9030685e-13),
    vec4<f32>(2.2975853e-7, -4.5542774e-9, 4.857679e-11, -3.7149445e-13),
    vec4<f32>(2.2084133e-7, -4.364365e-9, 4.6401775e-11, -3.5365187e-13),
    vec4<f32>(2.122954e-7, -4.1829415e-9, 4.4331042e-11, -3.367257e-13),
    vec4<f32>(2.0410418e-7, -4.009601e-9, 4.2359248e-11, -3.2066572e-13),
    vec4<f32>(1.9625188e-7, -3.843958e-9, 4.0481337e-11, -3.0542458e-13),
    vec4<f32>(1.8872346e-7, -3.6856465e-9, 3.869253e-11, -2.9095771e-13),
    vec4<f32>(1.8150463e-7, -3.5343193e-9, 3.6988305e-11, -2.772232e-13),
    vec4<f32>(1.7458174e-7, -3.3896463e-9, 3.5364395e-11, -2.6418142e-13),
    vec4<f32>(1.6794182e-7, -3.2513152e-9, 3.381675e-11, -2.5179514e-13),
    vec4<f32>(1.6157246e-7, -3.119028e-9, 3.234155e-11, -2.4002922e-13),
    vec4<f32>(1.5546186e-7, -2.9925025e-9, 3.0935168e-11, -2.288505e-13),
    vec4<f32>(1.4959879e-7, -2.8714704e-9, 2.9594178e-11, -2.1822774e-13),
    vec4<f32>(1.4397249e-7, -2.7556766e-9, 2.831533e-11, -2.0813145e-13),
    vec4<f32>(1.3857274e-7, -2.6448788e-9, 2.7095551e-11, -1.9853383e-13),
    vec4<f32>(1.333898e-7, -2.5388467e-9, 2.5931932e-11, -1.8940862e-13),
    vec4<f32>(1.2841433e-7, -2.437361e-9, 2.4821709e-11, -1.8073103e-13),
    vec4<f32>(1.2363746e-7, -2.3402138e-9, 2.3762268e-11, -1.7247767e-13),
    vec4<f32>(1.1905072e-7, -2.2472064e-9, 2.2751133e-11, -1.6462644e-13),
    vec4<f32>(1.14646e-7, -2.158151e-9, 2.178595e-11, -1.5715647e-13),
    vec4<f32>(1.104156e-7, -2.0728679e-9, 2.0864496e-11, -1.5004804e-13),
    vec4<f32>(1.06352125e-7, -1.9911865e-9, 1.9984655e-11, -1.432825e-13),
    vec4<f32>(1.0244856e-7, -1.9129445e-9, 1.9144422e-11, -1.3684225e-13),
    vec4<f32>(9.869816e-8, -1.8379872e-9, 1.83419e-11, -1.3071063e-13),
    vec4<f32>(9.509452e-8, -1.7661674e-9, 1.757528e-11, -1.248719e-13),
    vec4<f32>(9.163149e-8, -1.697345e-9, 1.6842854e-11, -1.1931116e-13),
    vec4<f32>(8.830323e-8, -1.6313866e-9, 1.6142991e-11, -1.1401433e-13),
    vec4<f32>(8.510412e-8, -1.5681649e-9, 1.5474155e-11, -1.0896807e-13),
    vec4<f32>(8.2028826e-8, -1.5075589e-9, 1.4834875e-11, -1.04159784e-13),
    vec4<f32>(7.907222e-8, -1.449453e-9, 1.4223763e-11, -9.957751e-14),
    vec4<f32>(7.622942e-8, -1.3937375e-9, 1.3639494e-11, -9.5209966e-14),
    vec4<f32>(7.349575e-8, -1.3403072e-9, 1.3080814e-11, -9.104644e-14),
    vec4<f32>(7.086673e-8, -1.2890625e-9, 1.254653e-11, -8.707679e-14),
    vec4<f32>(6.83381e-8, -1.2399078e-9, 1.2035506e-11, -8.3291426e-14),
    vec4<f32>(6.5905766e-8, -1.1927526e-9, 1.1546665e-11, -7.968125e-14),
    vec4<f32>(6.356582e-8, -1.1475099e-9, 1.10789815e-11, -7.623764e-14),
    vec4<f32>(6.131451e-8, -1.1040971e-9, 1.0631481e-11, -7.295242e-14),
    vec4<f32>(5.9148263e-8, -1.0624356e-9, 1.0203236e-11, -6.9817856e-14),
    vec4<f32>(5.706365e-8, -1.0224498e-9, 9.793366e-12, -6.68266e-14),
    vec4<f32>(5.5057395e-8, -9.840682e-10, 9.40103e-12, -6.3971696e-14),
    vec4<f32>(5.3126353e-8, -9.472221e-10, 9.025432e-12, -6.124653e-14),
    vec4<f32>(5.1267527e-8, -9.118461e-10, 8.665813e-12, -5.864485e-14),
    vec4<f32>(4.9478032e-8, -8.7787777e-10, 8.321448e-12, -5.6160704e-14),
    vec4<f32>(4.7755115e-8, -8.4525753e-10, 7.991649e-12, -5.3788452e-14),
    vec4<f32>(4.609614e-8, -8.1392837e-10, 7.675763e-12, -5.1522744e-14),
    vec4<f32>(4.4498577e-8, -7.838359e-10, 7.373164e-12, -4.9358497e-14),
    vec4<f32>(4.2960007e-8, -7.5492823e-10, 7.0832576e-12, -4.729089e-14),
    vec4<f32>(4.147811e-8, -7.2715567e-10, 6.8054794e-12, -4.5315334e-14),
    vec4<f32>(4.0050658e-8, -7.004709e-10, 6.5392895e-12, -4.3427488e-14),
    vec4<f32>(3.867553e-8, -6.7482847e-10, 6.284174e-12, -4.1623216e-14),
    vec4<f32>(3.735068e-8, -6.5018513e-10, 6.0396436e-12, -3.9898586e-14),
    vec4<f32>(3.607415e-8, -6.264995e-10, 5.8052317e-12, -3.8249873e-14),
    vec4<f32>(3.484407e-8, -6.03732e-10, 5.580493e-12, -3.6673528e-14),
    vec4<f32>(3.3658637e-8, -5.818448e-10, 5.3650044e-12, -3.5166186e-14),
    vec4<f32>(3.2516127e-8, -5.608016e-10, 5.1583607e-12, -3.3724634e-14),
    vec4<f32>(3.1414892e-8, -5.4056803e-10, 4.960177e-12, -3.2345834e-14),
    vec4<f32>(3.0353338e-8, -5.2111077e-10, 4.770085e-12, -3.1026885e-14),
    vec4<f32>(2.932995e-8, -5.023983e-10, 4.5877343e-12, -2.9765033e-14),
    vec4<f32>(2.8343269e-8, -4.844003e-10, 4.4127904e-12, -2.8557655e-14),
    vec4<f32>(2.7391893e-8, -4.670877e-10, 4.2449334e-12, -2.740226e-14),
    vec4<f32>(2.647448e-8, -4.5043289e-10, 4.083859e-12, -2.6296475e-14),
    vec4<f32>(2.558974e-8, -4.3440926e-10, 3.929276e-12, -2.523804e-14),
    vec4<f32>(2.4736439e-8, -4.1899142e-10, 3.7809074e-12, -2.4224809e-14),
    vec4<f32>(2.3913387e-8, -4.0415507e-10, 3.638488e-12, -2.3254734e-14),
    vec4<f32>(2.3119446e-8, -3.8987688e-10, 3.5017644e-12, -2.2325866e-14),
    vec4<f32>(2.2353522e-8, -3.761346e-10, 3.370495e-12, -2.1436352e-14),
    vec4<f32>(2.1614564e-8, -3.6290684e-10, 3.2444492e-12, -2.0584425e-14),
    vec4<f32>(2.0901565e-8, -3.5017317e-10, 3.1234065e-12, -1.9768404e-14),
    vec4<f32>(2.0213555e-8, -3.37914e-10, 3.0071564e-12, -1.8986682e-14),
    vec4<f32>(1.9549606e-8, -3.2611056e-10, 2.8954974e-12, -1.8237736e-14),
    vec4<f32>(1.8908821e-8, -3.1474487e-10, 2.7882377e-12, -1.7520109e-14),
    vec4<f32>(1.8290345e-8, -3.0379974e-10, 2.6851932e-12, -1.6832413e-14),
    vec4<f32>(1.7693354e-8, -2.932586e-10, 2.5861886e-12, -1.6173328e-14),
    vec4<f32>(1.7117053e-8, -2.831057e-10, 2.491056e-12, -1.5541593e-14),
    vec4<f32>(1.6560682e-8, -2.7332583e-10, 2.3996345e-12, -1.4936006e-14),
    vec4<f32>(1.602351e-8, -2.6390448e-10, 2.3117714e-12, -1.4355423e-14),
    vec4<f32>(1.5504835e-8, -2.548277e-10, 2.2273195e-12, -1.3798749e-14),
    vec4<f32>(1.5003979e-8, -2.4608213e-10, 2.1461383e-12, -1.32649425e-14),
    vec4<f32>(1.4520293e-8, -2.3765492e-10, 2.0680942e-12, -1.275301e-14),
    vec4<f32>(1.4053155e-8, -2.2953385e-10, 1.9930583e-12, -1.2262003e-14),
    vec4<f32>(1.3601962e-8, -2.217071e-10, 1.920908e-12, -1.1791017e-14),
    vec4<f32>(1.31661375e-8, -2.1416335e-10, 1.8515259e-12, -1.1339188e-14),
    vec4<f32>(1.2745127e-8, -2.068918e-10, 1.7847993e-12, -1.0905691e-14),
    vec4<f32>(1.2338396e-8, -1.9988199e-10, 1.7206207e-12, -1.0489739e-14),
    vec4<f32>(1.1753956e-8, -3.7967274e-10, 6.5161995e-12, -7.918133e-14),
    vec4<f32>(1.1020051e-8, -3.545371e-10, 6.0589827e-12, -7.3296654e-14),
    vec4<f32>(1.03346345e-8, -3.3116135e-10, 5.6356703e-12, -6.787376e-14),
    vec4<f32>(9.694319e-9, -3.0941527e-10, 5.243608e-12, -6.287445e-14),
    vec4<f32>(9.0959675e-9, -2.8917888e-10, 4.880361e-12, -5.826381e-14),
    vec4<f32>(8.536672e-9, -2.703414e-10, 4.543693e-12, -5.4010002e-14),
    vec4<f32>(8.013737e-9, -2.5280072e-10, 4.2315526e-12, -5.00839e-14),
    vec4<f32>(7.524667e-9, -2.3646257e-10, 3.942054e-12, -4.645889e-14),
    vec4<f32>(7.0671438e-9, -2.212399e-10, 3.673465e-12, -4.3110643e-14),
    vec4<f32>(6.639018e-9, -2.0705232e-10, 3.4241921e-12, -4.0016896e-14),
    vec4<f32>(6.238294e-9, -1.9382554e-10, 3.1927707e-12, -3.715726e-14),
    vec4<f32>(5.8631207e-9, -1.814909e-10, 2.9778528e-12, -3.451308e-14),
    vec4<f32>(5.511778e-9, -1.6998492e-10, 2.7781974e-12, -3.206725e-14),
    vec4<f32>(5.182668e-9, -1.5924886e-10, 2.592662e-12, -2.980411e-14),
    vec4<f32>(4.8743054e-9, -1.4922838e-10, 2.4201945e-12, -2.770929e-14),
    vec4<f32>(4.585311e-9, -1.398732e-10, 2.259825e-12, -2.5769607e-14),
    vec4<f32>(4.3144004e-9, -1.3113671e-10, 2.1106589e-12, -2.3972969e-14),
    vec4<f32>(4.0603805e-9, -1.2297582e-10, 1.971872e-12, -2.2308273e-14),
    vec4<f32>(3.82214e-9, -1.1535052e-10, 1.842704e-12, -2.0765323e-14),
    vec4<f32>(3.598646e-9, -1.08223784e-10, 1.7224524e-12, -1.933475e-14),
    vec4<f32>(3.3889356e-9, -1.0156126e-10, 1.6104691e-12, -1.8007942e-14),
    vec4<f32>(3.1921128e-9, -9.533109e-11, 1.5061558e-12, -1.6776985e-14),
    vec4<f32>(3.0073428e-9, -8.950371e-11, 1.4089593e-12, -1.5634595e-14),
    vec4<f32>(2.8338478e-9, -8.405171e-11, 1.3183688e-12, -1.457407e-14),
    vec4<f32>(2.6709026e-9, -7.894961e-11, 1.2339116e-12, -1.3589243e-14),
    vec4<f32>(2.5178317e-9, -7.417377e-11, 1.1551508e-12, -1.2674431e-14),
    vec4<f32>(2.3740048e-9, -6.970223e-11, 1.0816824e-12, -1.1824405e-14),
    vec4<f32>(2.2388338e-9, -6.551457e-11, 1.0131321e-12, -1.10343406e-14),
    vec4<f32>(2.1117699e-9, -6.159184e-11, 9.491537e-13, -1.0299794e-14),
    vec4<f32>(1.9923014e-9, -5.7916387e-11, 8.8942666e-13, -9.616664e-15),
    vec4<f32>(1.8799504e-9, -5.4471816e-11, 8.336538e-13, -8.981172e-15),
    vec4<f32>(1.7742705e-9, -5.1242868e-11, 7.815599e-13, -8.389826e-15),
    vec4<f32>(1.6748447e-9, -4.821534e-11, 7.3288993e-13, -7.839406e-15),
    vec4<f32>(1.5812837e-9, -4.537603e-11, 6.874073e-13, -7.326937e-15),
    vec4<f32>(1.4932233e-9, -4.271262e-11, 6.448928e-13, -6.8496717e-15),
    vec4<f32>(1.4103236e-9, -4.0213662e-11, 6.0514267e-13, -6.4050704e-15),
    vec4<f32>(1.3322662e-9, -3.7868476e-11, 5.6796825e-13, -5.9907866e-15),
    vec4<f32>(1.2587538e-9, -3.5667115e-11, 5.3319415e-13, -5.6046497e-15),
    vec4<f32>(1.189508e-9, -3.3600314e-11, 5.0065757e-13, -5.2446535e-15),
    vec4<f32>(1.1242687e-9, -3.165942e-11, 4.702073e-13, -4.9089396e-15),
    vec4<f32>(1.0627919e-9, -2.9836383e-11, 4.417029e-13, -4.5957903e-15),
    vec4<f32>(1.0048495e-9, -2.8123682e-11, 4.150138e-13, -4.303614e-15),
    vec4<f32>(9.502282e-10, -2.65143e-11, 3.900186e-13, -4.030937e-15),
    vec4<f32>(8.9872787e-10, -2.5001688e-11, 3.6660448e-13, -3.7763943e-15),
    vec4<f32>(8.5016105e-10, -2.357974e-11, 3.4466646e-13, -3.5387211e-15),
    vec4<f32>(8.0435225e-10, -2.224275e-11, 3.2410687e-13, -3.316745e-15),
    vec4<f32>(7.61137e-10, -2.0985384e-11, 3.0483485e-13, -3.1093785e-15),
    vec4<f32>(7.2036094e-10, -1.9802668e-11, 2.8676578e-13, -2.915614e-15),
    vec4<f32>(6.8187966e-10, -1.8689947e-11, 2.698209e-13, -2.7345159e-15),
    vec4<f32>(6.455574e-10, -1.7642875e-11, 2.5392682e-13, -2.5652162e-15),
    vec4<f32>(6.112671e-10, -1.6657387e-11, 2.3901521e-13, -2.4069093e-15),
    vec4<f32>(5.788893e-10, -1.5729681e-11, 2.250224e-13, -2.2588471e-15),
    vec4<f32>(5.4831223e-10, -1.4856205e-11, 2.1188899e-13, -2.1203352e-15),
    vec4<f32>(5.194306e-10, -1.4033632e-11, 1.9955967e-13, -1.9907277e-15),
    vec4<f32>(4.921458e-10, -1.325885e-11, 1.8798282e-13, -1.8694252e-15),
    vec4<f32>(4.663653e-10, -1.25289475e-11, 1.7711029e-13, -1.7558702e-15),
    vec4<f32>(4.4200194e-10, -1.1841198e-11, 1.6689719e-13, -1.6495443e-15),
    vec4<f32>(4.1897408e-10, -1.119305e-11, 1.573016e-13, -1.5499656e-15),
    vec4<f32>(3.9720494e-10, -1.0582111e-11, 1.4828438e-13, -1.4566855e-15),
    vec4<f32>(3.7662234e-10, -1.0006143e-11, 1.3980902e-13, -1.3692872e-15),
    vec4<f32>(3.5715847e-10, -9.463047e-12, 1.3184141e-13, -1.2873821e-15),
    vec4<f32>(3.3874956e-10, -8.9508565e-12, 1.2434967e-13, -1.2106089e-15),
    vec4<f32>(3.2133565e-10, -8.467729e-12, 1.1730403e-13, -1.1386309e-15),
    vec4<f32>(3.0486041e-10, -8.011937e-12, 1.1067668e-13, -1.0711347e-15),
    vec4<f32>(2.8927077e-10, -7.581858e-12, 1.04441615e-13, -1.0078283e-15),
    vec4<f32>(2.7451685e-10, -7.1759742e-12, 9.8574516e-14, -9.484393e-16),
    vec4<f32>(2.605517e-10, -6.7928592e-12, 9.305265e-14, -8.927143e-16),
    vec4<f32>(2.4733113e-10, -6.431175e-12, 8.7854745e-14, -8.4041667e-16),
    vec4<f32>(2.3481356e-10, -6.0896665e-12, 8.2960914e-14, -7.9132587e-16),
    vec4<f32>(2.229598e-10, -5.767155e-12, 7.835253e-14, -7.4523626e-16),
    vec4<f32>(2.11733e-10, -5.4625336e-12, 7.401218e-14, -7.0195595e-16),
    vec4<f32>(2.0109843e-10, -5.174764e-12, 6.992354e-14, -6.613058e-16),
    vec4<f32>(1.9102336e-10, -4.9028693e-12, 6.607134e-14, -6.231187e-16),
    vec4<f32>(1.8147699e-10, -4.645934e-12, 6.244128e-14, -5.872385e-16),
    vec4<f32>(1.7243024e-10, -4.403096e-12, 5.901994e-14, -5.535196e-16),
    vec4<f32>(1.6385575e-10, -4.1735456e-12, 5.5794785e-14, -5.218259e-16),
    vec4<f32>(1.5572771e-10, -3.956522e-12, 5.2754045e-14, -4.920302e-16),
    vec4<f32>(1.4802179e-10, -3.751311e-12, 4.9886686e-14, -4.640137e-16),
    vec4<f32>(1.4071504e-10, -3.5572387e-12, 4.7182378e-14, -4.3766534e-16),
    vec4<f32>(1.3378583e-10, -3.373673e-12, 4.463142e-14, -4.1288137e-16),
    vec4<f32>(1.2721374e-10, -3.200019e-12, 4.222472e-14, -3.8956467e-16),
    vec4<f32>(1.2097952e-10, -3.0357169e-12, 3.995375e-14, -3.6762453e-16),
    vec4<f32>(1.15064985e-10, -2.88024e-12, 3.7810514e-14, -3.46976e-16),
    vec4<f32>(1.09453e-10, -2.7330926e-12, 3.5787494e-14, -3.2753967e-16),
    vec4<f32>(1.0412737e-10, -2.593808e-12, 3.387765e-14, -3.0924122e-16),
    vec4<f32>(9.907282e-11, -2.461947e-12, 3.2074356e-14, -2.92011e-16),
    vec4<f32>(9.4274914e-11, -2.3370962e-12, 3.037141e-14, -2.7578397e-16),
    vec4<f32>(8.972002e-11, -2.2188657e-12, 2.8762972e-14, -2.6049908e-16),
    vec4<f32>(8.539528e-11, -2.1068887e-12, 2.7243563e-14, -2.460992e-16),
    vec4<f32>(8.128853e-11, -2.0008192e-12, 2.5808035e-14, -2.3253087e-16),
    vec4<f32>(7.738828e-11, -1.900332e-12, 2.445155e-14, -2.197439e-16),
    vec4<f32>(7.3683684e-11, -1.80512e-12, 2.3169566e-14, -2.0769137e-16),
    vec4<f32>(7.016448e-11, -1.7148936e-12, 2.1957804e-14, -1.963292e-16),
    vec4<f32>(6.682097e-11, -1.6293803e-12, 2.0812252e-14, -1.8561614e-16),
    vec4<f32>(6.3643986e-11, -1.5483228e-12, 1.972913e-14, -1.7551349e-16),
    vec4<f32>(6.062487e-11, -1.4714785e-12, 1.8704885e-14, -1.6598493e-16),
    vec4<f32>(5.775542e-11, -1.398619e-12, 1.7736177e-14, -1.5699645e-16),
    vec4<f32>(5.502788e-11, -1.3295281e-12, 1.681986e-14, -1.4851607e-16),
    vec4<f32>(5.243493e-11, -1.2640024e-12, 1.595298e-14, -1.4051385e-16),
    vec4<f32>(4.9969626e-11, -1.2018498e-12, 1.513275e-14, -1.3296165e-16),
    vec4<f32>(4.7625404e-11, -1.1428891e-12, 1.4356551e-14, -1.2583308e-16),
    vec4<f32>(4.5396055e-11, -1.0869489e-12, 1.3621915e-14, -1.1910334e-16),
    vec4<f32>(4.3275702e-11, -1.033868e-12, 1.29265215e-14, -1.1274916e-16),
    vec4<f32>(4.1258778e-11, -9.834936e-13, 1.2268183e-14, -1.06748704e-16),
    vec4<f32>(3.934002e-11, -9.356817e-13, 1.1644838e-14, -1.01081405e-16),
    vec4<f32>(3.7514436e-11, -8.9029625e-13, 1.10545465e-14, -9.5727984e-17),
    vec4<f32>(3.57773e-11, -8.4720886e-13, 1.0495481e-14, -9.0670324e-17),
    vec4<f32>(3.4124148e-11, -8.06298e-13, 9.965918e-15, -8.589138e-17),
    vec4<f32>(3.2550736e-11, -7.67449e-13, 9.464233e-15, -8.1375143e-17),
    vec4<f32>(3.105305e-11, -7.305534e-13, 8.988896e-15, -7.7106554e-17),
    vec4<f32>(2.962729e-11, -6.9550875e-13, 8.538464e-15, -7.307146e-17),
    vec4<f32>(2.8269847e-11, -6.622182e-13, 8.111576e-15, -6.925656e-17),
    vec4<f32>(2.6977308e-11, -6.305902e-13, 7.7069495e-15, -6.564931e-17),
    vec4<f32>(2.5746434e-11, -6.0053807e-13, 7.323373e-15, -6.223794e-17),
    vec4<f32>(2.4574159e-11, -5.7197996e-13, 6.959706e-15, -5.9011376e-17),
    vec4<f32>(2.3457571e-11, -5.448385e-13, 6.6148703e-15, -5.595917e-17),
    vec4<f32>(2.239391e-11, -5.190402e-13, 6.2878504e-15, -5.3071514e-17),
    vec4<f32>(2.138056e-11, -4.94516e-13, 5.977686e-15, -5.0339165e-17),
    vec4<f32>(2.0415041e-11, -4.712001e-13, 5.6834725e-15, -4.775342e-17),
    vec4<f32>(1.9494996e-11, -4.490306e-13, 5.4043544e-15, -4.530609e-17),
    vec4<f32>(1.8618194e-11, -4.2794864e-13, 5.139525e-15, -4.2989447e-17),
    vec4<f32>(1.7782513e-11, -4.0789862e-13, 4.888222e-15, -4.079623e-17),
    vec4<f32>(1.6985946e-11, -3.8882794e-13, 4.6497255e-15, -3.871959e-17),
    vec4<f32>(1.6226583e-11, -3.706867e-13, 4.4233556e-15, -3.6753074e-17),
    vec4<f32>(1.5502611e-11, -3.5342768e-13, 4.20847e-15, -3.4890597e-17),
    vec4<f32>(1.4812313e-11, -3.3700622e-13, 4.0044618e-15, -3.3126433e-17),
    vec4<f32>(1.41540555e-11, -3.2137997e-13, 3.8107576e-15, -3.1455177e-17),
    vec4<f32>(1.35262895e-11, -3.0650878e-13, 3.6268155e-15, -2.9871732e-17),
    vec4<f32>(1.26386115e-11, -5.710703e-13, 1.3474503e-14, -2.2122919e-16),
    vec4<f32>(1.1548633e-11, -5.1974945e-13, 1.221289e-14, -1.996548e-16),
    vec4<f32>(1.0556418e-11, -4.7322405e-13, 1.1074056e-14, -1.8026637e-16),
    vec4<f32>(9.652851e-12, -4.3102834e-13, 1.0045587e-14, -1.6283392e-16),
    vec4<f32>(8.829698e-12, -3.9274362e-13, 9.116373e-15, -1.4715255e-16),
    vec4<f32>(8.079521e-12, -3.5799323e-13, 8.276464e-15, -1.3303963e-16),
    vec4<f32>(7.395596e-12, -3.2643818e-13, 7.5169465e-15, -1.2033233e-16),
    vec4<f32>(6.7718426e-12, -2.9777323e-13, 6.8298304e-15, -1.0888534e-16),
    vec4<f32>(6.20276e-12, -2.7172345e-13, 6.2079494e-15, -9.856891e-17),
    vec4<f32>(5.683371e-12, -2.4804106e-13, 5.6448736e-15, -8.926719e-17),
    vec4<f32>(5.2091673e-12, -2.2650263e-13, 5.13483e-15, -8.0876605e-17),
    vec4<f32>(4.776066e-12, -2.0690662e-13, 4.6726357e-15, -7.330456e-17),
    vec4<f32>(4.380367e-12, -1.8907118e-13, 4.2536313e-15, -6.646823e-17),
    vec4<f32>(4.018717e-12, -1.728321e-13, 3.873628e-15, -6.029345e-17),
    vec4<f32>(3.6880737e-12, -1.5804107e-13, 3.5288602e-15, -5.4713835e-17),
    vec4<f32>(3.3856774e-12, -1.4456409e-13, 3.2159376e-15, -4.966989e-17),
    vec4<f32>(3.1090226e-12, -1.3228e-13, 2.931809e-15, -4.5108283e-17),
    vec4<f32>(2.8558354e-12, -1.2107924e-13, 2.673726e-15, -4.098119e-17),
    vec4<f32>(2.6240496e-12, -1.108627e-13, 2.4392126e-15, -3.7245706e-17),
    vec4<f32>(2.4117884e-12, -1.01540656e-13, 2.2260363e-15, -3.3863312e-17),
    vec4<f32>(2.217345e-12, -9.303188e-14, 2.0321843e-15, -3.0799405e-17),
    vec4<f32>(2.0391679e-12, -8.526277e-14, 1.85584e-15, -2.8022914e-17),
    vec4<f32>(1.8758456e-12, -7.816665e-14, 1.6953645e-15, -2.5505891e-17),
    vec4<f32>(1.7260931e-12, -7.168307e-14, 1.5492774e-15, -2.3223213e-17),
    vec4<f32>(1.5887415e-12, -6.5757214e-14, 1.4162415e-15, -2.1152272e-17),
    vec4<f32>(1.4627258e-12, -6.0339334e-14, 1.2950484e-15, -1.9272723e-17),
    vec4<f32>(1.3470758e-12, -5.538429e-14, 1.1846055e-15, -1.7566239e-17),
    vec4<f32>(1.2409074e-12, -5.08511e-14, 1.0839248e-15, -1.6016316e-17),
    vec4<f32>(1.143415e-12, -4.670255e-14, 9.921122e-16, -1.4608077e-17),
    vec4<f32>(1.0538635e-12, -4.2904807e-14, 9.083586e-16, -1.3328108e-17),
    vec4<f32>(9.715824e-13, -3.9427137e-14, 8.3193104e-16, -1.2164311e-17),
    vec4<f32>(8.959602e-13, -3.624159e-14, 7.6216586e-16, -1.1105769e-17),
    vec4<f32>(8.2643836e-13, -3.3322744e-14, 6.9846157e-16, -1.0142625e-17),
    vec4<f32>(7.625069e-13, -3.0647465e-14, 6.402728e-16, -9.265979e-18),
    vec4<f32>(7.037002e-13, -2.8194705e-14, 5.871051e-16, -8.46779e-18),
    vec4<f32>(6.495926e-13, -2.5945292e-14, 5.385098e-16, -7.74079e-18),
    vec4<f32>(5.997951e-13, -2.3881769e-14, 4.9407993e-16, -7.078408e-18),
    vec4<f32>(5.5395223e-13, -2.1988227e-14, 4.534458e-16, -6.474699e-18),
    vec4<f32>(5.117386e-13, -2.0250167e-14, 4.1627167e-16, -5.9242866e-18),
    vec4<f32>(4.728567e-13, -1.8654373e-14, 3.8225268e-16, -5.4223017e-18),
    vec4<f32>(4.370343e-13, -1.718879e-14, 3.5111162e-16, -4.964336e-18),
    vec4<f32>(4.040221e-13, -1.5842418e-14, 3.225966e-16, -4.5463964e-18),
    vec4<f32>(3.7359186e-13, -1.4605221e-14, 2.9647845e-16, -4.164864e-18),
    vec4<f32>(3.4553455e-13, -1.3468038e-14, 2.7254868e-16, -3.8164583e-18),
    vec4<f32>(3.1965863e-13, -1.2422501e-14, 2.5061765e-16, -3.498205e-18),
    vec4<f32>(2.9578857e-13, -1.1460968e-14, 2.3051258e-16, -3.207405e-18),
    vec4<f32>(2.7376343e-13, -1.0576455e-14, 2.1207628e-16, -2.9416094e-18),
    vec4<f32>(2.5343567e-13, -9.762578e-15, 1.9516544e-16, -2.698595e-18),
    vec4<f32>(2.3466992e-13, -9.013505e-15, 1.7964955e-16, -2.4763434e-18),
    vec4<f32>(2.1734203e-13, -8.323894e-15, 1.6540959e-16, -2.2730204e-18),
    vec4<f32>(2.0133798e-13, -7.688866e-15, 1.5233706e-16, -2.0869593e-18),
    vec4<f32>(1.8655317e-13, -7.103952e-15, 1.4033302e-16, -1.9166453e-18),
    vec4<f32>(1.728915e-13, -6.565061e-15, 1.2930715e-16, -1.760701e-18),
    vec4<f32>(1.6026475e-13, -6.06845e-15, 1.1917706e-16, -1.6178737e-18),
    vec4<f32>(1.485918e-13, -5.610688e-15, 1.09867525e-16, -1.4870226e-18),
    vec4<f32>(1.3779819e-13, -5.188633e-15, 1.01309826e-16, -1.3671102e-18),
    vec4<f32>(1.278154e-13, -4.7994056e-15, 9.344122e-17, -1.2571917e-18),
    vec4<f32>(1.1858045e-13, -4.440366e-15, 8.620435e-17, -1.1564066e-18),
    vec4<f32>(1.1003542e-13, -4.109095e-15, 7.954681e-17, -1.0639706e-18),
    vec4<f32>(1.0212704e-13, -3.803372e-15, 7.342068e-17, -9.791694e-19),
    vec4<f32>(9.480626e-14, -3.521161e-15, 6.778212e-17, -9.013515e-19),
    vec4<f32>(8.8027974e-14, -3.2605932e-15, 6.259104e-17, -8.299231e-19),
    vec4<f32>(8.175061e-14, -3.0199537e-15, 5.781076e-17, -7.6434213e-19),
    vec4<f32>(7.593592e-14, -2.7976672e-15, 5.3407697e-17, -7.0411434e-19),
    vec4<f32>(7.054867e-14, -2.592288e-15, 4.9351098e-17, -6.4878846e-19),
    vec4<f32>(6.5556386e-14, -2.4024872e-15, 4.5612807e-17, -5.9795253e-19),
    vec4<f32>(6.0929153e-14, -2.2270444e-15, 4.216703e-17, -5.512303e-19),
    vec4<f32>(5.663939e-14, -2.0648374e-15, 3.8990128e-17, -5.082782e-19),
    vec4<f32>(5.2661668e-14, -1.914835e-15, 3.6060436e-17, -4.6878197e-19),
    vec4<f32>(4.8972548e-14, -1.7760888e-15, 3.3358093e-17, -4.3245473e-19),
    vec4<f32>(4.5550393e-14, -1.6477264e-15, 3.0864878e-17, -3.9903394e-19),
    vec4<f32>(4.2375256e-14, -1.5289453e-15, 2.8564085e-17, -3.682796e-19),
    vec4<f32>(3.942872e-14, -1.4190072e-15, 2.6440385e-17, -3.3997216e-19),
    vec4<f32>(3.6693786e-14, -1.3172322e-15, 2.4479704e-17, -3.139107e-19),
    vec4<f32>(3.4154767e-14, -1.2229945e-15, 2.2669126e-17, -2.8991132e-19),
    vec4<f32>(3.179717e-14, -1.1357179e-15, 2.0996792e-17, -2.6780567e-19),
    vec4<f32>(2.960761e-14, -1.0548716e-15, 1.9451807e-17, -2.4743953e-19),
    vec4<f32>(2.7573723e-14, -9.799666e-16, 1.8024163e-17, -2.286717e-19),
    vec4<f32>(2.5684084e-14, -9.105522e-16, 1.6704663e-17, -2.113728e-19),
    vec4<f32>(2.392813e-14, -8.46213e-16, 1.5484854e-17, -1.9542417e-19),
    vec4<f32>(2.2296103e-14, -7.865661e-16, 1.4356965e-17, -1.8071712e-19),
    vec4<f32>(2.0778973e-14, -7.312584e-16, 1.3313851e-17, -1.6715195e-19),
    vec4<f32>(1.9368394e-14, -6.799641e-16, 1.2348936e-17, -1.5463723e-19),
    vec4<f32>(1.8056643e-14, -6.323828e-16, 1.1456174e-17, -1.4308904e-19),
    vec4<f32>(1.6836574e-14, -5.8823707e-16, 1.06300004e-17, -1.3243041e-19),
    vec4<f32>(1.5701575e-14, -5.4727106e-16, 9.86529e-18, -1.225907e-19),
    vec4<f32>(1.4645528e-14, -5.0924854e-16, 9.157329e-18, -1.13505e-19),
    vec4<f32>(1.3662764e-14, -4.7395136e-16, 8.501772e-18, -1.05113744e-19),
    vec4<f32>(1.274804e-14, -4.4117793e-16, 7.894621e-18, -9.736221e-20),
    vec4<f32>(1.1896495e-14, -4.107422e-16, 7.3321885e-18, -9.0200117e-20),
    vec4<f32>(1.1103628e-14, -3.8247222e-16, 6.8110788e-18, -8.358126e-20),
    vec4<f32>(1.0365268e-14, -3.5620904e-16, 6.3281616e-18, -7.7463164e-20),
    vec4<f32>(9.677552e-15, -3.3180575e-16, 5.8805515e-18, -7.180678e-20),
    vec4<f32>(9.036896e-15, -3.0912655e-16, 5.4655864e-18, -6.657619e-20),
    vec4<f32>(8.43998e-15, -2.8804584e-16, 5.0808126e-18, -6.173836e-20),
    vec4<f32>(7.8837244e-15, -2.6844748e-16, 4.723965e-18, -5.726289e-20),
    vec4<f32>(7.365274e-15, -2.50224e-16, 4.3929556e-18, -5.312182e-20),
    vec4<f32>(6.881979e-15, -2.3327594e-16, 4.0858553e-18, -4.9289402e-20),
    vec4<f32>(6.4313814e-15, -2.1751134e-16, 3.8008846e-18, -4.5741925e-20),
    vec4<f32>(6.0112014e-15, -2.0284498e-16, 3.5363998e-18, -4.2457565e-20),
    vec4<f32>(5.619322e-15, -1.8919802e-16, 3.2908837e-18, -3.9416216e-20),
    vec4<f32>(5.253778e-15, -1.7649742e-16, 3.062934e-18, -3.6599356e-20),
    vec4<f32>(4.9127466e-15, -1.6467557e-16, 2.8512558e-18, -3.3989908e-20),
    vec4<f32>(4.594532e-15, -1.5366979e-16, 2.6546525e-18, -3.1572143e-20),
    vec4<f32>(4.2975623e-15, -1.4342205e-16, 2.472018e-18, -2.933156e-20),
    vec4<f32>(4.0203745e-15, -1.3387855e-16, 2.3023298e-18, -2.7254784e-20),
    vec4<f32>(3.761612e-15, -1.2498941e-16, 2.1446428e-18, -2.5329479e-20),
    vec4<f32>(3.5200116e-15, -1.1670843e-16, 1.998082e-18, -2.3544268e-20),
    vec4<f32>(3.2944012e-15, -1.08992725e-16, 1.8618394e-18, -2.1888653e-20),
    vec4<f32>(3.0836904e-15, -1.01802554e-16, 1.7351664e-18, -2.0352945e-20),
    vec4<f32>(2.8868653e-15, -9.510104e-17, 1.6173711e-18, -1.8928204e-20),
    vec4<f32>(2.7029834e-15, -8.8853975e-17, 1.5078123e-18, -1.7606173e-20),
    vec4<f32>(2.5311676e-15, -8.3029624e-17, 1.4058973e-18, -1.6379228e-20),
    vec4<f32>(2.3706028e-15, -7.759852e-17, 1.3110767e-18, -1.5240326e-20),
    vec4<f32>(2.2205297e-15, -7.253333e-17, 1.2228422e-18, -1.4182968e-20),
    vec4<f32>(2.0802424e-15, -6.7808653e-17, 1.1407226e-18, -1.32011386e-20),
    vec4<f32>(1.9490838e-15, -6.3400926e-17, 1.0642816e-18, -1.2289287e-20),
    vec4<f32>(1.8264421e-15, -5.928825e-17, 9.93115e-19, -1.1442278e-20),
    vec4<f32>(1.7117477e-15, -5.545029e-17, 9.268481e-19, -1.0655367e-20),
    vec4<f32>(1.6044703e-15, -5.1868155e-17, 8.651336e-19, -9.924163e-21),
    vec4<f32>(1.5041162e-15, -4.8524287e-17, 8.076497e-19, -9.244609e-21),
    vec4<f32>(1.4102253e-15, -4.5402372e-17, 7.5409776e-19, -8.61295e-21),
    vec4<f32>(1.3223689e-15, -4.2487242e-17, 7.04201e-19, -8.0257134e-21),
    vec4<f32>(1.2401478e-15, -3.9764802e-17, 6.577027e-19, -7.479682e-21),
    vec4<f32>(1.16319e-15, -3.7221936e-17, 6.143645e-19, -6.971883e-21),
    vec4<f32>(1.0911486e-15, -3.4846456e-17, 5.739656e-19, -6.4995604e-21),
    vec4<f32>(1.0237002e-15, -3.262702e-17, 5.363007e-19, -6.0601647e-21),
    vec4<f32>(9.605435e-16, -3.0553084e-17, 5.0117943e-19, -5.6513347e-21),
    vec4<f32>(8.7324565e-16, -5.5387395e-17, 1.8120661e-18, -4.0732894e-20),
    vec4<f32>(7.6940153e-16, -4.860877e-17, 1.583844e-18, -3.5454354e-20),
    vec4<f32>(6.782429e-16, -4.268224e-17, 1.3851398e-18, -3.087814e-20),
    vec4<f32>(5.9817816e-16, -3.7497814e-17, 1.2120336e-18, -2.6908334e-20),
    vec4<f32>(5.278208e-16, -3.296008e-17, 1.0611402e-18, -2.3462458e-20),
    vec4<f32>(4.659622e-16, -2.8986215e-17, 9.295336e-19, -2.0469544e-20),
    vec4<f32>(4.1154822e-16, -2.5504283e-17, 8.1468326e-19, -1.786849e-20),
    vec4<f32>(3.6365896e-16, -2.2451771e-17, 7.143997e-19, -1.560665e-20),
    vec4<f32>(3.2149125e-16, -1.9774317e-17, 6.267868e-19, -1.363863e-20),
    vec4<f32>(2.8434332e-16, -1.7424622e-17, 5.5020167e-19, -1.1925272e-20),
    vec4<f32>(2.5160182e-16, -1.536151e-17, 4.8322004e-19, -1.0432769e-20),
    vec4<f32>(2.2273025e-16, -1.3549109e-17, 4.2460623e-19, -9.131915e-21),
    vec4<f32>(1.9725918e-16, -1.1956157e-17, 3.732878e-19, -7.997468e-21),
    vec4<f32>(1.7477759e-16, -1.05553896e-17, 3.283332e-19, -7.0075955e-21),
    vec4<f32>(1.5492544e-16, -9.323017e-18, 2.8893287e-19, -6.143399e-21),
    vec4<f32>(1.3738716e-16, -8.238273e-18, 2.5438296e-19, -5.3885162e-21),
    vec4<f32>(1.2188607e-16, -7.2830134e-18, 2.24071e-19, -4.7287674e-21),
    vec4<f32>(1.08179395e-16, -6.441386e-18, 1.9746388e-19, -4.1518594e-21),
    vec4<f32>(9.605405e-17, -5.6995255e-18, 1.7409721e-19, -3.647126e-21),
    vec4<f32>(8.5322906e-17, -5.045303e-18, 1.5356631e-19, -3.2053111e-21),
    vec4<f32>(7.5821526e-17, -4.468101e-18, 1.3551829e-19, -2.8183734e-21),
    vec4<f32>(6.740538e-17, -3.9586213e-18, 1.1964532e-19, -2.4793255e-21),
    vec4<f32>(5.994735e-17, -3.5087165e-18, 1.0567863e-19, -2.1820918e-21),
    vec4<f32>(5.3335577e-17, -3.1112436e-18, 9.338354e-20, -1.9213869e-21),
    vec4<f32>(4.747161e-17, -2.7599386e-18, 8.255497e-20, -1.6926097e-21),
    vec4<f32>(4.2268724e-17, -2.4493035e-18, 7.3013624e-20, -1.4917531e-21),
    vec4<f32>(3.7650515e-17, -2.1745118e-18, 6.4602664e-20, -1.315325e-21),
    vec4<f32>(3.3549622e-17, -1.9313245e-18, 5.718484e-20, -1.1602813e-21),
    vec4<f32>(2.9906642e-17, -1.7160155e-18, 5.0639978e-20, -1.023966e-21),
    vec4<f32>(2.6669165e-17, -1.5253098e-18, 4.48628e-20, -9.040613e-22),
    vec4<f32>(2.3790929e-17, -1.3563259e-18, 3.9761044e-20, -7.985431e-22),
    vec4<f32>(2.1231078e-17, -1.2065283e-18, 3.5253798e-20, -7.0564327e-22),
    vec4<f32>(1.8953519e-17, -1.0736852e-18, 3.1270083e-20, -6.238159e-22),
    vec4<f32>(1.692635e-17, -9.5583e-19, 2.7747602e-20, -5.5170927e-22),
    vec4<f32>(1.5121366e-17, -8.512304e-19, 2.4631652e-20, -4.881406e-22),
    vec4<f32>(1.3513615e-17, -7.5835893e-19, 2.1874168e-20, -4.320745e-22),
    vec4<f32>(1.2081014e-17, -6.7586844e-19, 1.9432914e-20, -3.826041e-22),
    vec4<f32>(1.0804016e-17, -6.0257026e-19, 1.7270743e-20, -3.3893486e-22),
    vec4<f32>(9.665307e-18, -5.374152e-19, 1.5354981e-20, -3.003701e-22),
    vec4<f32>(8.6495464e-18, -4.794767e-19, 1.3656868e-20, -2.6629897e-22),
    vec4<f32>(7.743138e-18, -4.2793607e-19, 1.2151086e-20, -2.3618528e-22),
    vec4<f32>(6.9340214e-18, -3.820698e-19, 1.0815327e-20, -2.0955846e-22),
    vec4<f32>(6.2115035e-18, -3.4123816e-19, 9.629933e-21, -1.8600516e-22),
    vec4<f32>(5.5660913e-18, -3.0487525e-19, 8.577575e-21, -1.651622e-22),
    vec4<f32>(4.9893582e-18, -2.7248027e-19, 7.642968e-21, -1.4671032e-22),
    vec4<f32>(4.4738216e-18, -2.4360994e-19, 6.8126216e-21, -1.3036874e-22),
    vec4<f32>(4.012832e-18, -2.1787164e-19, 6.0746315e-21, -1.1589043e-22),
    vec4<f32>(3.60048e-18, -1.9491749e-19, 5.4184817e-21, -1.03057975e-22),
    vec4<f32>(3.231512e-18, -1.744392e-19, 4.834883e-21, -9.167988e-23),
    vec4<f32>(2.9012553e-18, -1.5616341e-19, 4.3156246e-21, -8.158747e-23),
    vec4<f32>(2.6055523e-18, -1.3984765e-19, 3.8534467e-21, -7.2632083e-23),
    vec4<f32>(2.3407021e-18, -1.2527678e-19, 3.441928e-21, -6.468264e-23),
    vec4<f32>(2.1034097e-18, -1.122598e-19, 3.075386e-21, -5.7623525e-23),
    vec4<f32>(1.8907405e-18, -1.00627116e-19, 2.7487908e-21, -5.1352718e-23),
    vec4<f32>(1.7000792e-18, -9.0228086e-20, 2.4576879e-21, -4.578015e-23),
    vec4<f32>(1.5290953e-18, -8.092884e-20, 2.1981305e-21, -4.0826288e-23),
    vec4<f32>(1.3757103e-18, -7.261035e-20, 1.966621e-21, -3.6420856e-23),
    vec4<f32>(1.2380709e-18, -6.516678e-20, 1.7600592e-21, -3.250175e-23),
    vec4<f32>(1.114523e-18, -5.850399e-20, 1.5756946e-21, -2.9014055e-23),
    vec4<f32>(1.0035904e-18, -5.253819e-20, 1.4110869e-21, -2.5909198e-23),
    vec4<f32>(9.039555e-19, -4.7194787e-20, 1.2640707e-21, -2.3144198e-23),
    vec4<f32>(8.1444084e-19, -4.2407356e-20, 1.132723e-21, -2.0681011e-23),
    vec4<f32>(7.33995e-19, -3.8116725e-20, 1.0153358e-21, -1.8485942e-23),
    vec4<f32>(6.6167806e-19, -3.427016e-20, 9.103915e-22, -1.6529152e-23),
    vec4<f32>(5.9664977e-19, -3.082066e-20, 8.165413e-22, -1.4784187e-23),
    vec4<f32>(5.3815874e-19, -2.7726296e-20, 7.325858e-22, -1.3227603e-23),
    vec4<f32>(4.8553284e-19, -2.4949679e-20, 6.574583e-22, -1.1838606e-23),
    vec4<f32>(4.3817055e-19, -2.2457443e-20, 5.9020947e-22, -1.0598747e-23),
    vec4<f32>(3.9553342e-19, -2.0219802e-20, 5.299946e-22, -9.4916565e-24),
    vec4<f32>(3.571394e-19, -1.8210161e-20, 4.7606143e-22, -8.502799e-24),
    vec4<f32>(3.2255665e-19, -1.6404767e-20, 4.277399e-22, -7.619267e-24),
    vec4<f32>(2.9139836e-19, -1.4782396e-20, 3.844332e-22, -6.829592e-24),
    vec4<f32>(2.6331775e-19, -1.3324076e-20, 3.456092e-22, -6.123583e-24),
    vec4<f32>(2.3800403e-19, -1.2012848e-20, 3.107936e-22, -5.4921794e-24),
    vec4<f32>(2.1517845e-19, -1.08335465e-20, 2.7956334e-22, -4.927324e-24),
    vec4<f32>(1.9459097e-19, -9.772602e-21, 2.5154106e-22, -4.4218474e-24),
    vec4<f32>(1.7601726e-19, -8.8178705e-21, 2.2638993e-22, -3.9693706e-24),
    vec4<f32>(1.5925595e-19, -7.958485e-21, 2.0380927e-22, -3.564215e-24),
    vec4<f32>(1.4412627e-19, -7.184712e-21, 1.8353061e-22, -3.2013232e-24),
    vec4<f32>(1.3046586e-19, -6.4878356e-21, 1.6531412e-22, -2.8761898e-24),
    vec4<f32>(1.1812889e-19, -5.8600447e-21, 1.489455e-22, -2.5848006e-24),
    vec4<f32>(1.069843e-19, -5.2943404e-21, 1.3423319e-22, -2.3235772e-24),
    vec4<f32>(9.691433e-20, -4.784448e-21, 1.2100595e-22, -2.0893289e-24),
    vec4<f32>(8.7813074e-20, -4.3247398e-21, 1.091106e-22, -1.87921e-24),
    vec4<f32>(7.958529e-20, -3.9101696e-21, 9.841011e-23, -1.690681e-24),
    vec4<f32>(7.214533e-20, -3.536209e-21, 8.878186e-23, -1.5214756e-24),
    vec4<f32>(6.5416105e-20, -3.1987927e-21, 8.0116076e-23, -1.3695708e-24),
    vec4<f32>(5.932824e-20, -2.8942724e-21, 7.231448e-23, -1.2331595e-24),
    vec4<f32>(5.3819275e-20, -2.6193718e-21, 6.5289025e-23, -1.1106275e-24),
    vec4<f32>(4.8832973e-20, -2.3711472e-21, 5.896084e-23, -1.0005325e-24),
    vec4<f32>(4.431867e-20, -2.1469543e-21, 5.325924e-23, -9.015852e-25),
    vec4<f32>(4.0230724e-20, -1.9444167e-21, 4.8120837e-23, -8.1263274e-25),
    vec4<f32>(3.6528e-20, -1.7613973e-21, 4.3488826e-23, -7.3264397e-25),
    vec4<f32>(3.317341e-20, -1.595975e-21, 3.931223e-23, -6.606965e-25),
    vec4<f32>(3.013352e-20, -1.4464217e-21, 3.5545318e-23, -5.9596484e-25),
    vec4<f32>(2.7378182e-20, -1.3111826e-21, 3.2147054e-23, -5.377099e-25),
    vec4<f32>(2.4880184e-20, -1.1888585e-21, 2.9080594e-23, -4.8527005e-25),
    vec4<f32>(2.261498e-20, -1.0781895e-21, 2.6312852e-23, -4.3805254e-25),
    vec4<f32>(2.0560414e-20, -9.780419e-22, 2.3814114e-23, -3.9552633e-25),
    vec4<f32>(1.8696482e-20, -8.873942e-22, 2.1557685e-23, -3.572156e-25),
    vec4<f32>(1.7005121e-20, -8.053259e-22, 1.9519573e-23, -3.2269369e-25),
    vec4<f32>(1.5470014e-20, -7.3100814e-22, 1.767821e-23, -2.9157808e-25),
    vec4<f32>(1.4076422e-20, -6.636934e-22, 1.6014206e-23, -2.6352562e-25),
    vec4<f32>(1.2811022e-20, -6.02708e-22, 1.4510118e-23, -2.382285e-25),
    vec4<f32>(1.16617765e-20, -5.474443e-22, 1.3150259e-23, -2.1541048e-25),
    vec4<f32>(1.0617797e-20, -4.973542e-22, 1.1920509e-23, -1.9482352e-25),
    vec4<f32>(9.669241e-21, -4.5194334e-22, 1.080816e-23, -1.76245e-25),
    vec4<f32>(8.807203e-21, -4.1076538e-22, 9.801773e-24, -1.594749e-25),
    vec4<f32>(8.023627e-21, -3.734176e-22, 8.891042e-24, -1.4433358e-25),
    vec4<f32>(7.3112224e-21, -3.395363e-22, 8.066689e-24, -1.3065956e-25),
    vec4<f32>(6.66339e-21, -3.0879313e-22, 7.3203515e-24, -1.1830775e-25),
    vec4<f32>(6.0741565e-21, -2.8089133e-22, 6.644494e-24, -1.0714766e-25),
    vec4<f32>(5.53811e-21, -2.555629e-22, 6.0323243e-24, -9.706196e-26),
    vec4<f32>(5.0503512e-21, -2.325656e-22, 5.477717e-24, -8.79451e-26),
    vec4<f32>(4.60644e-21, -2.1168049e-22, 4.9751485e-24, -7.970211e-26),
    vec4<f32>(4.2023534e-21, -1.9270954e-22, 4.519636e-24, -7.2247536e-26),
    vec4<f32>(3.8344454e-21, -1.7547377e-22, 4.1066844e-24, -6.5504415e-26),
    vec4<f32>(3.49941e-21, -1.5981118e-22, 3.732235e-24, -5.940348e-26),
    vec4<f32>(3.19425e-21, -1.4557526e-22, 3.3926257e-24, -5.388233e-26),
    vec4<f32>(2.9162467e-21, -1.326334e-22, 3.0845481e-24, -4.8884752e-26),
    vec4<f32>(2.662934e-21, -1.2086558e-22, 2.8050156e-24, -4.4360092e-26),
    vec4<f32>(2.4320744e-21, -1.1016314e-22, 2.55133e-24, -4.02627e-26),
    vec4<f32>(2.2216369e-21, -1.0042765e-22, 2.3210526e-24, -3.6551408e-26),
    vec4<f32>(2.0297786e-21, -9.156999e-23, 2.1119804e-24, -3.318911e-26),
    vec4<f32>(1.854826e-21, -8.35094e-23, 1.922121e-24, -3.014233e-26),
    vec4<f32>(1.6952586e-21, -7.617272e-23, 1.7496734e-24, -2.7380863e-26),
    vec4<f32>(1.5496967e-21, -6.949361e-23, 1.59300885e-24, -2.4877457e-26),
    vec4<f32>(1.416886e-21, -6.341196e-23, 1.4506538e-24, -2.260752e-26),
    vec4<f32>(1.239114e-21, -1.1058371e-22, 5.0470816e-24, -1.5679356e-25),
    vec4<f32>(1.0369238e-21, -9.217711e-23, 4.190151e-24, -1.29641e-25),
    vec4<f32>(8.683286e-22, -7.689001e-23, 3.481349e-24, -1.0727512e-25),
    vec4<f32>(7.2764515e-22, -6.418417e-23, 2.8946103e-24, -8.8837053e-26),
    vec4<f32>(6.1016874e-22, -5.36159e-23, 2.4085377e-24, -7.362472e-26),
    vec4<f32>(5.1200203e-22, -4.481911e-23, 2.0055518e-24, -6.106377e-26),
    vec4<f32>(4.29914e-22, -3.7491555e-23, 1.671197e-24, -5.0683906e-26),
    vec4<f32>(3.6122385e-22, -3.1383462e-23, 1.393578e-24, -4.2099732e-26),
    vec4<f32>(3.0370572e-22, -2.6288267e-23, 1.1628965e-24, -3.4995124e-26),
    vec4<f32>(2.5551015e-22, -2.2035028e-23, 9.71077e-25, -2.9110598e-26),
    vec4<f32>(2.1509927e-22, -1.8482151e-23, 8.1145714e-25, -2.4232958e-26),
    vec4<f32>(1.8119335e-22, -1.5512276e-23, 6.78537e-25, -2.0186915e-26),
    vec4<f32>(1.5272678e-22, -1.3028051e-23, 5.6777223e-25, -1.6828221e-26),
    vec4<f32>(1.2881156e-22, -1.094867e-23, 4.7540555e-25, -1.4038083e-26),
    vec4<f32>(1.0870722e-22, -9.207e-24, 3.9832787e-25, -1.1718592e-26),
    vec4<f32>(9.1795843e-23, -7.747238e-24, 3.339645e-25, -9.788987e-27),
    vec4<f32>(7.756146e-23, -6.5229603e-24, 2.8018192e-25, -8.182606e-27),
    vec4<f32>(6.5572927e-23, -5.49552e-24, 2.3521069e-25, -6.844376e-27),
    vec4<f32>(5.546974e-23, -4.632722e-24, 1.9758237e-25, -5.7287688e-27),
    vec4<f32>(4.6950272e-23, -3.9077286e-24, 1.6607743e-25, -4.798118e-27),
    vec4<f32>(3.976197e-23, -3.2981507e-24, 1.3968234e-25, -4.021238e-27),
    vec4<f32>(3.3693256e-23, -2.7852996e-24, 1.1755417e-25, -3.37229e-27),
    vec4<f32>(2.8566752e-23, -2.3535643e-24, 9.8991406e-26, -2.8298496e-27),
    vec4<f32>(2.423367e-23, -1.989896e-24, 8.3409813e-26, -2.3761417e-27),
    vec4<f32>(2.056911e-23, -1.6833803e-24, 7.032251e-26, -1.9964067e-27),
    vec4<f32>(1.746817e-23, -1.4248833e-24, 5.932346e-26, -1.6783815e-27),
    vec4<f32>(1.4842692e-23, -1.2067547e-24, 5.0073855e-26, -1.4118698e-27),
    vec4<f32>(1.2618537e-23, -1.0225841e-24, 4.2290747e-26, -1.18838785e-27),
    vec4<f32>(1.0733321e-23, -8.669959e-25, 3.5737738e-26, -1.0008725e-27),
    vec4<f32>(9.134522e-24, -7.3547958e-25, 3.0217163e-26, -8.434392e-28),
    vec4<f32>(7.777893e-24, -6.242485e-25, 2.5563646e-26, -7.1118184e-28),
    vec4<f32>(6.6261366e-24, -5.3012163e-25, 2.1638744e-26, -6.000079e-28),
    vec4<f32>(5.6477964e-24, -4.504249e-25, 1.8326484e-26, -5.06501e-28),
    vec4<f32>(4.8163248e-24, -3.8290929e-25, 1.5529651e-26, -4.278073e-28),
    vec4<f32>(4.109307e-24, -3.2568219e-25, 1.316672e-26, -3.6154159e-28),
    vec4<f32>(3.5078053e-24, -2.7714976e-25, 1.1169263e-26, -3.0570897e-28),
    vec4<f32>(2.9958117e-24, -2.3596925e-25, 9.479824e-27, -2.5864002e-28),
    vec4<f32>(2.559786e-24, -2.0100857e-25, 8.0501276e-27, -2.189367e-28),
    vec4<f32>(2.1882708e-24, -1.713129e-25, 6.8395866e-27, -1.8542766e-28),
    vec4<f32>(1.8715646e-24, -1.4607634e-25, 5.8140593e-27, -1.5713081e-28),
    vec4<f32>(1.6014488e-24, -1.2461837e-25, 4.9448093e-27, -1.3322232e-28),
    vec4<f32>(1.3709574e-24, -1.0636399e-25, 4.207635e-27, -1.1301061e-28),
    vec4<f32>(1.1741829e-24, -9.0827164e-26, 3.5821438e-27, -9.5914886e-29),
    vec4<f32>(1.0061126e-24, -7.759676e-26, 3.0511422e-27, -8.144704e-29),
    vec4<f32>(8.624914e-25, -6.632484e-26, 2.6001264e-27, -6.9196647e-29),
    vec4<f32>(7.39705e-25, -5.671682e-26, 2.2168542e-27, -5.8818406e-29),
    vec4<f32>(6.3468213e-25, -4.8523124e-26, 1.890987e-27, -5.0021646e-29),
    vec4<f32>(5.448114e-25, -4.1532217e-26, 1.6137897e-27, -4.2561535e-29),
    vec4<f32>(4.6787163e-25, -3.5564706e-26, 1.3778768e-27, -3.623174e-29),
    vec4<f32>(4.0197233e-25, -3.046838e-26, 1.1770019e-27, -3.0858294e-29),
    vec4<f32>(3.455039e-25, -2.6114026e-26, 1.0058785e-27, -2.6294418e-29),
    vec4<f32>(2.9709512e-25, -2.2391903e-26, 8.600302e-28, -2.2416215e-29),
    vec4<f32>(2.555773e-25, -1.9208754e-26, 7.3566475e-28, -1.911905e-29),
    vec4<f32>(2.1995392e-25, -1.64853e-26, 6.2956787e-28, -1.6314503e-29),
    vec4<f32>(1.8937482e-25, -1.4154101e-26, 5.3901387e-28, -1.392782e-29),
    vec4<f32>(1.6311446e-25, -1.2157773e-26, 4.616899e-28, -1.1895769e-29),
    vec4<f32>(1.4055323e-25, -1.0447454e-26, 3.9563276e-28, -1.01648326e-29),
    vec4<f32>(1.2116185e-25, -8.981526e-27, 3.3917511e-28, -8.689696e-30),
    vec4<f32>(1.0448797e-25, -7.724519e-27, 2.9090019e-28, -7.43197e-30),
    vec4<f32>(9.014476e-26, -6.646193e-27, 2.4960353e-28, -6.359116e-30),
    vec4<f32>(7.780136e-26, -5.720753e-27, 2.1426074e-28, -5.4435383e-30),
    vec4<f32>(6.7174575e-26, -4.9261852e-27, 1.8400016e-28, -4.6618255e-30),
    vec4<f32>(5.8021965e-26, -4.2436946e-27, 1.5807964e-28, -3.994104e-30),
    vec4<f32>(5.0135836e-26, -3.6572273e-27, 1.3586712e-28, -3.423496e-30),
    vec4<f32>(4.333823e-26, -3.1530643e-27, 1.1682399e-28, -2.9356604e-30),
    vec4<f32>(3.747657e-26, -2.7194772e-27, 1.0049108e-28, -2.5184066e-30),
    vec4<f32>(3.2419992e-26, -2.346434e-27, 8.647675e-29, -2.1613668e-30),
    vec4<f32>(2.805622e-26, -2.0253509e-27, 7.4446834e-29, -1.8557189e-30),
    vec4<f32>(2.4288873e-26, -1.7488794e-27, 6.411604e-29, -1.5939534e-30),
    vec4<f32>(2.103518e-26, -1.5107264e-27, 5.5240726e-29, -1.3696741e-30),
    vec4<f32>(1.8224034e-26, -1.3055001e-27, 4.761272e-29, -1.1774317e-30),
    vec4<f32>(1.5794325e-26, -1.1285786e-27, 4.1054065e-29, -1.0125807e-30),
    vec4<f32>(1.3693505e-26, -9.759988e-28, 3.5412582e-29, -8.711594e-31),
    vec4<f32>(1.1876379e-26, -8.443608e-28, 3.0558074e-29, -7.497878e-31),
    vec4<f32>(1.0304055e-26, -7.3074693e-28, 2.6379107e-29, -6.455806e-31),
    vec4<f32>(8.9430534e-27, -6.3265195e-28, 2.2780257e-29, -5.560741e-31),
    vec4<f32>(7.764543e-27, -5.479241e-28, 1.9679784e-29, -4.7916342e-31),
    vec4<f32>(6.7436845e-27, -4.7471453e-28, 1.7007639e-29, -4.130495e-31),
    vec4<f32>(5.8590706e-27, -4.114338e-28, 1.470376e-29, -3.5619414e-31),
    vec4<f32>(5.0922454e-27, -3.567153e-28, 1.271664e-29, -3.0728149e-31),
    vec4<f32>(4.4272892e-27, -3.0938307e-28, 1.1002078e-29, -2.6518548e-31),
    vec4<f32>(3.8504667e-27, -2.6842526e-28, 9.5221324e-30, -2.2894208e-31),
    vec4<f32>(3.349922e-27, -2.3297057e-28, 8.244223e-30, -1.9772553e-31),
    vec4<f32>(2.9154182e-27, -2.0226863e-28, 7.140361e-30, -1.7082839e-31),
    vec4<f32>(2.5381122e-27, -1.7567288e-28, 6.1864906e-30, -1.4764414e-31),
    vec4<f32>(2.2103626e-27, -1.5262601e-28, 5.3619304e-30, -1.2765275e-31),
    vec4<f32>(1.9255642e-27, -1.3264747e-28, 4.6488932e-30, -1.1040805e-31),
    vec4<f32>(1.6780048e-27, -1.1532274e-28, 4.032073e-30, -9.552714e-32),
    vec4<f32>(1.4627436e-27, -1.002941e-28, 3.4982968e-30, -8.268128e-32),
    vec4<f32>(1.2755045e-27, -8.72528e-29, 3.0362195e-30, -7.15881e-32),
    vec4<f32>(1.1125861e-27, -7.593218e-29, 2.6360703e-30, -6.200499e-32),
    vec4<f32>(9.70783e-28, -6.610188e-29, 2.2894282e-30, -5.37234e-32),
    vec4<f32>(8.473184e-28, -5.756285e-29, 1.9890342e-30, -4.6564005e-32),
    vec4<f32>(7.3978604e-28, -5.0143e-29, 1.7286288e-30, -4.0372547e-32),
    vec4<f32>(6.4609995e-28, -4.369351e-29, 1.5028109e-30, -3.5016266e-32),
    vec4<f32>(5.644513e-28, -3.8085635e-29, 1.3069205e-30, -3.0380884e-32),
    vec4<f32>(4.9327096e-28, -3.3207955e-29, 1.136934e-30, -2.6367975e-32),
    vec4<f32>(4.3119727e-28, -2.896402e-29, 9.8937645e-31, -2.2892751e-32),
    vec4<f32>(3.7704833e-28, -2.52703e-29, 8.612459e-31, -1.9882135e-32),
    vec4<f32>(3.2979774e-28, -2.2054436e-29, 7.4994795e-31, -1.7273125e-32),
    vec4<f32>(2.8855402e-28, -1.9253714e-29, 6.5323956e-31, -1.5011382e-32),
    vec4<f32>(2.5254252e-28, -1.6813776e-29, 5.691809e-31, -1.3050025e-32),
    vec4<f32>(2.2108997e-28, -1.468748e-29, 4.9609374e-31, -1.1348591e-32),
    vec4<f32>(1.9361091e-28, -1.2833932e-29, 4.3252564e-31, -9.8721454e-33),
    vec4<f32>(1.6959618e-28, -1.1217646e-29, 3.7721912e-31, -8.590516e-33),
    vec4<f32>(1.4860278e-28, -9.8078186e-30, 3.2908526e-31, -7.477632e-33),
    vec4<f32>(1.3024518e-28, -8.577703e-30, 2.8718068e-31, -6.510962e-33),
    vec4<f32>(1.1418771e-28, -7.5040655e-30, 2.5068776e-31, -5.6710245e-33),
    vec4<f32>(1.0013811e-28, -6.56672e-30, 2.1889776e-31, -4.940972e-33),
    vec4<f32>(8.7841725e-29, -5.748119e-30, 1.9119606e-31, -4.3062256e-33),
    vec4<f32>(7.7076685e-29, -5.0330075e-30, 1.6704949e-31, -3.7541693e-33),
    vec4<f32>(6.764959e-29, -4.4081185e-30, 1.459954e-31, -3.27388e-33),
    vec4<f32>(5.93918e-29, -3.8619082e-30, 1.2763217e-31, -2.8558975e-33),
    vec4<f32>(5.215623e-29, -3.3843314e-30, 1.1161106e-31, -2.4920264e-33),
    vec4<f32>(4.5814572e-29, -2.9666427e-30, 9.7629185e-32, -2.1751634e-33),
    vec4<f32>(4.0254834e-29, -2.6012276e-30, 8.542336e-32, -1.8991514e-33),
    vec4<f32>(3.5379255e-29, -2.2814523e-30, 7.476484e-32, -1.6586508e-33),
    vec4<f32>(3.110247e-29, -2.0015372e-30, 6.545474e-32, -1.4490293e-33),
    vec4<f32>(2.7349905e-29, -1.7564443e-30, 5.732011e-32, -1.2662673e-33),
    vec4<f32>(2.4056416e-29, -1.5417816e-30, 5.0210483e-32, -1.1068756e-33),
    vec4<f32>(2.1165057e-29, -1.3537184e-30, 4.399491e-32, -9.678247e-34),
    vec4<f32>(1.8626048e-29, -1.188913e-30, 3.8559415e-32, -8.46483e-34),
    vec4<f32>(1.6395852e-29, -1.0444495e-30, 3.3804743e-32, -7.4056424e-34),
    vec4<f32>(1.4436393e-29, -9.177823e-31, 2.9644445e-32, -6.4808103e-34),
    vec4<f32>(1.2714347e-29, -8.066889e-31, 2.6003196e-32, -5.673059e-34),
    vec4<f32>(1.1200554e-29, -7.092282e-31, 2.2815354e-32, -4.967363e-34),
    vec4<f32>(9.8694814e-30, -6.2370433e-31, 2.0023684e-32, -4.350653e-34),
    vec4<f32>(8.698771e-30, -5.4863514e-31, 1.757828e-32, -3.8115542e-34),
);

// Exponential Λ(z) e^z on octaves of z: the Rust EXPONENTIAL_FAR (degree 6, f64)
// rounded to f32 (largest relative change 4.4e-8).
const MS_EXP_FAR_K0: i32 = 5;
const MS_EXP_FAR_K1: i32 = 9;
const MS_EXP_FAR_M: u32 = 3u;
var<private> MS_EXP_FAR: array<vec4<f32>, 64> = array<vec4<f32>, 64>(
    vec4<f32>(7.111587e-2, -2.246514e-3, 1.0573132e-4, -5.497686e-6),
    vec4<f32>(2.9870606e-7, -1.6718072e-8, 9.44299e-10, 0e0),
    vec4<f32>(6.700608e-2, -1.8811737e-3, 7.877816e-5, -3.648073e-6),
    vec4<f32>(1.7665366e-7, -8.806663e-9, 4.4379203e-10, 0e0),
    vec4<f32>(6.353223e-2, -1.6048107e-3, 6.0520677e-5, -2.5256554e-6),
    vec4<f32>(1.1027937e-7, -4.9554725e-9, 2.2536348e-10, 0e0),
    vec4<f32>(6.0546108e-2, -1.3898631e-3, 4.7666133e-5, -1.8100195e-6),
    vec4<f32>(7.1946e-8, -2.9423612e-9, 1.2190093e-10, 0e0),
    vec4<f32>(5.794363e-2, -1.21883e-3, 3.8324113e-5, -1.3348546e-6),
    vec4<f32>(4.868659e-8, -1.8267587e-9, 6.9485924e-11, 0e0),
    vec4<f32>(5.5649314e-2, -1.0801274e-3, 3.1352698e-5, -1.0084839e-6),
    vec4<f32>(3.3979106e-8, -1.1776131e-9, 4.1399533e-11, 0e0),
    vec4<f32>(5.360691e-2, -9.6581783e-4, 2.6032296e-5, -7.7778105e-7),
    vec4<f32>(2.4348072e-8, -7.8394863e-10, 2.5611497e-11, 0e0),
    vec4<f32>(5.1773548e-2, -8.703009e-4, 2.1892976e-5, -6.10632e-7),
    vec4<f32>(1.7848933e-8, -5.365844e-10, 1.6378612e-11, 0e0),
    vec4<f32>(4.934452e-2, -1.5073958e-3, 6.893625e-5, -3.4965565e-6),
    vec4<f32>(1.8591417e-7, -1.0208081e-8, 5.6703947e-10, 0e0),
    vec4<f32>(4.6580184e-2, -1.268377e-3, 5.1723375e-5, -2.3401205e-6),
    vec4<f32>(1.11017e-7, -5.4340528e-9, 2.6944086e-10, 0e0),
    vec4<f32>(4.423322e-2, -1.0863993e-3, 3.9970582e-5, -1.6319623e-6),
    vec4<f32>(6.988309e-8, -3.0856753e-9, 1.3815178e-10, 0e0),
    vec4<f32>(4.2208277e-2, -9.4408635e-4, 3.1639298e-5, -1.1769074e-6),
    vec4<f32>(4.592217e-8, -1.8468107e-9, 7.536792e-11, 0e0),
    vec4<f32>(4.0437926e-2, -8.3031674e-4, 2.5548821e-5, -8.7269524e-7),
    vec4<f32>(3.127352e-8, -1.1546849e-9, 4.328723e-11, 0e0),
    vec4<f32>(3.8872972e-2, -7.3767756e-4, 2.0980424e-5, -6.6248845e-7),
    vec4<f32>(2.1948832e-8, -7.4903106e-10, 2.5966087e-11, 0e0),
    vec4<f32>(3.747657e-2, -6.610586e-4, 1.7478125e-5, -5.1310735e-7),
    vec4<f32>(1.5806263e-8, -5.0143756e-10, 1.615801e-11, 0e0),
    vec4<f32>(3.6220495e-2, -5.9683475e-4, 1.4742335e-5, -4.0436328e-7),
    vec4<f32>(1.1639013e-8, -3.4494801e-10, 1.0394257e-11, 0e0),
    vec4<f32>(3.4552623e-2, -1.0363347e-3, 4.6599005e-5, -2.32694e-6),
    vec4<f32>(1.2194789e-7, -6.6056907e-9, 3.623846e-10, 0e0),
    vec4<f32>(3.2649495e-2, -8.744242e-4, 3.5113193e-5, -1.566006e-6),
    vec4<f32>(7.330524e-8, -3.5432177e-9, 1.7364311e-10, 0e0),
    vec4<f32>(3.102964e-2, -7.5067027e-4, 2.7230604e-5, -1.0971651e-6),
    vec4<f32>(4.640167e-8, -2.0249022e-9, 8.966895e-11, 0e0),
    vec4<f32>(2.9629128e-2, -6.5357494e-4, 2.161885e-5, -7.9432914e-7),
    vec4<f32>(3.0636365e-8, -1.218566e-9, 4.922062e-11, 0e0),
    vec4<f32>(2.8402554e-2, -5.757397e-4, 1.7501497e-5, -5.909812e-7),
    vec4<f32>(2.0948754e-8, -7.654922e-10, 2.8419609e-11, 0e0),
    vec4<f32>(2.7316663e-2, -5.122113e-4, 1.4403438e-5, -4.4993268e-7),
    vec4<f32>(1.47546455e-8, -4.986109e-10, 1.7126847e-11, 0e0),
    vec4<f32>(2.6346477e-2, -4.5956133e-4, 1.2021881e-5, -3.493636e-7),
    vec4<f32>(1.0658463e-8, -3.3500694e-10, 1.0694746e-11, 0e0),
    vec4<f32>(2.5472807e-2, -4.1534996e-4, 1.0157099e-5, -2.7593788e-7),
    vec4<f32>(7.869969e-9, -2.3119767e-10, 6.9104245e-12, 0e0),
    vec4<f32>(2.4311308e-2, -7.2218425e-4, 3.2174954e-5, -1.5925119e-6),
    vec4<f32>(8.275261e-8, -4.445751e-9, 2.4198663e-10, 0e0),
    vec4<f32>(2.2984095e-2, -6.102595e-4, 2.43021e-5, -1.0751786e-6),
    vec4<f32>(4.9941516e-8, -2.3958373e-9, 1.1656924e-10, 0e0),
    vec4<f32>(2.1852912e-2, -5.24526e-4, 1.8883204e-5, -7.552677e-7),
    vec4<f32>(3.1715967e-8, -1.3745001e-9, 6.0465286e-11, 0e0),
    vec4<f32>(2.0873819e-2, -4.5714062e-4, 1.5016035e-5, -5.480046e-7),
    vec4<f32>(2.0997641e-8, -8.2985496e-10, 3.3318015e-11, 0e0),
    vec4<f32>(2.0015528e-2, -4.0304102e-4, 1.21729e-5, -4.0847695e-7),
    vec4<f32>(1.4391403e-8, -5.227571e-10, 1.9298911e-11, 0e0),
    vec4<f32>(1.9255085e-2, -3.5882893e-4, 1.0029889e-5, -3.1148537e-7),
    vec4<f32>(1.01565165e-8, -3.413132e-10, 1.1662861e-11, 0e0),
    vec4<f32>(1.8575206e-2, -3.221474e-4, 8.380028e-6, -2.42199e-7),
    vec4<f32>(7.3496906e-9, -2.2980214e-10, 7.292793e-12, 0e0),
    vec4<f32>(1.7962605e-2, -2.9131552e-4, 7.086478e-6, -1.9152965e-7),
    vec4<f32>(5.4351585e-9, -1.5888171e-10, 4.729225e-12, 0e0),
);

// The Exp(1) ziggurat's layer edges x_i (the Rust ZIG_EXP_X, rounded to f32).
var<private> MS_ZIG_EXP_X: array<f32, 257> = array<f32, 257>(
    8.697118e0, 7.6971173e0, 6.941034e0, 6.4783783e0,
    6.1441646e0, 5.8821445e0, 5.66641e0, 5.4828906e0,
    5.3230906e0, 5.181487e0, 5.0542884e0, 4.938777e0,
    4.8329396e0, 4.735243e0, 4.6444917e0, 4.559737e0,
    4.4802117e0, 4.4052877e0, 4.3344436e0, 4.2672424e0,
    4.203314e0, 4.1423407e0, 4.084051e0, 4.0282087e0,
    3.974606e0, 3.9230626e0, 3.8734176e0, 3.8255293e0,
    3.779271e0, 3.7345288e0, 3.691201e0, 3.6491954e0,
    3.6084287e0, 3.5688252e0, 3.5303159e0, 3.4928377e0,
    3.456333e0, 3.4207485e0, 3.3860354e0, 3.352149e0,
    3.3190475e0, 3.2866921e0, 3.2550473e0, 3.2240796e0,
    3.193758e0, 3.1640534e0, 3.134939e0, 3.106389e0,
    3.07838e0, 3.05089e0, 3.0238974e0, 2.9973829e0,
    2.9713278e0, 2.9457145e0, 2.9205263e0, 2.8957477e0,
    2.871364e0, 2.8473608e0, 2.8237252e0, 2.8004444e0,
    2.777506e0, 2.7548993e0, 2.7326126e0, 2.7106361e0,
    2.6889596e0, 2.667574e0, 2.64647e0, 2.625639e0,
    2.605073e0, 2.5847638e0, 2.5647042e0, 2.5448866e0,
    2.5253043e0, 2.5059507e0, 2.4868193e0, 2.467904e0,
    2.449199e0, 2.4306984e0, 2.412397e0, 2.394289e0,
    2.3763702e0, 2.358635e0, 2.3410792e0, 2.3236978e0,
    2.3064868e0, 2.2894418e0, 2.272559e0, 2.2558339e0,
    2.2392628e0, 2.2228425e0, 2.206569e0, 2.190439e0,
    2.174449e0, 2.1585958e0, 2.1428764e0, 2.1272876e0,
    2.1118267e0, 2.0964901e0, 2.081276e0, 2.0661807e0,
    2.0512023e0, 2.036338e0, 2.0215852e0, 2.0069418e0,
    1.9924049e0, 1.9779727e0, 1.9636427e0, 1.9494127e0,
    1.9352808e0, 1.9212447e0, 1.9073025e0, 1.8934522e0,
    1.8796918e0, 1.8660195e0, 1.8524336e0, 1.8389319e0,
    1.8255131e0, 1.8121753e0, 1.7989168e0, 1.785736e0,
    1.7726312e0, 1.7596009e0, 1.7466437e0, 1.7337579e0,
    1.720942e0, 1.7081947e0, 1.6955146e0, 1.6829001e0,
    1.67035e0, 1.6578629e0, 1.6454375e0, 1.6330724e0,
    1.6207665e0, 1.6085185e0, 1.5963271e0, 1.5841911e0,
    1.5721092e0, 1.5600805e0, 1.5481036e0, 1.5361774e0,
    1.5243009e0, 1.5124729e0, 1.5006921e0, 1.4889578e0,
    1.4772687e0, 1.4656237e0, 1.4540218e0, 1.4424621e0,
    1.4309433e0, 1.4194646e0, 1.4080249e0, 1.3966233e0,
    1.3852586e0, 1.37393e0, 1.3626364e0, 1.3513769e0,
    1.3401506e0, 1.3289564e0, 1.3177934e0, 1.3066607e0,
    1.2955571e0, 1.284482e0, 1.2734343e0, 1.2624129e0,
    1.2514172e0, 1.2404459e0, 1.2294981e0, 1.2185732e0,
    1.2076699e0, 1.1967874e0, 1.1859246e0, 1.1750807e0,
    1.1642547e0, 1.1534455e0, 1.1426523e0, 1.131874e0,
    1.1211096e0, 1.1103581e0, 1.0996186e0, 1.08889e0,
    1.0781711e0, 1.0674613e0, 1.056759e0, 1.0460634e0,
    1.0353734e0, 1.0246879e0, 1.0140057e0, 1.0033256e0,
    9.926464e-1, 9.8196703e-1, 9.7128624e-1, 9.606027e-1,
    9.499152e-1, 9.3922234e-1, 9.2852277e-1, 9.178152e-1,
    9.0709805e-1, 8.9637e-1, 8.856295e-1, 8.748749e-1,
    8.641046e-1, 8.53317e-1, 8.4251034e-1, 8.3168286e-1,
    8.208326e-1, 8.0995774e-1, 7.990562e-1, 7.881259e-1,
    7.7716464e-1, 7.661701e-1, 7.5514e-1, 7.440717e-1,
    7.3296267e-1, 7.218101e-1, 7.1061105e-1, 6.9936246e-1,
    6.880611e-1, 6.767036e-1, 6.652861e-1, 6.5380496e-1,
    6.4225596e-1, 6.3063467e-1, 6.189365e-1, 6.071562e-1,
    5.952886e-1, 5.833277e-1, 5.712673e-1, 5.5910057e-1,
    5.468201e-1, 5.3441787e-1, 5.2188504e-1, 5.0921196e-1,
    4.9638805e-1, 4.8340148e-1, 4.7023928e-1, 4.5688683e-1,
    4.4332787e-1, 4.2954394e-1, 4.1551417e-1, 4.012147e-1,
    3.86618e-1, 3.7169215e-1, 3.5639977e-1, 3.4069648e-1,
    3.245291e-1, 3.0783296e-1, 2.9052797e-1, 2.7251318e-1,
    2.5365835e-1, 2.3379049e-1, 2.126715e-1, 1.8995869e-1,
    1.6512762e-1, 1.3730498e-1, 1.04838505e-1, 6.385216e-2,
    0e0,
);

// e^{−x_i} at those edges (the Rust ZIG_EXP_F, rounded to f32).
var<private> MS_ZIG_EXP_F: array<f32, 257> = array<f32, 257>(
    1.670667e-4, 4.5413437e-4, 9.672693e-4, 1.5362998e-3,
    2.1459677e-3, 2.7887989e-3, 3.4602648e-3, 4.157295e-3,
    4.8776558e-3, 5.6196423e-3, 6.381906e-3, 7.1633533e-3,
    7.963077e-3, 8.780315e-3, 9.614414e-3, 1.046481e-2,
    1.1331013e-2, 1.2212592e-2, 1.3109165e-2, 1.4020392e-2,
    1.4945968e-2, 1.5885621e-2, 1.6839107e-2, 1.78062e-2,
    1.87867e-2, 1.9780423e-2, 2.0787204e-2, 2.1806888e-2,
    2.2839336e-2, 2.3884421e-2, 2.4942026e-2, 2.6012046e-2,
    2.7094385e-2, 2.818895e-2, 2.929566e-2, 3.0414443e-2,
    3.1545233e-2, 3.2687962e-2, 3.3842582e-2, 3.5009038e-2,
    3.6187284e-2, 3.7377283e-2, 3.8578995e-2, 3.9792392e-2,
    4.1017443e-2, 4.2254124e-2, 4.3502413e-2, 4.47623e-2,
    4.6033762e-2, 4.7316793e-2, 4.8611384e-2, 4.9917534e-2,
    5.1235236e-2, 5.2564494e-2, 5.3905312e-2, 5.525769e-2,
    5.662164e-2, 5.7997175e-2, 5.9384305e-2, 6.0783047e-2,
    6.2193416e-2, 6.3615434e-2, 6.504912e-2, 6.6494495e-2,
    6.795159e-2, 6.9420435e-2, 7.090106e-2, 7.2393484e-2,
    7.389775e-2, 7.541389e-2, 7.6941945e-2, 7.848195e-2,
    8.003395e-2, 8.1597984e-2, 8.3174095e-2, 8.476233e-2,
    8.636274e-2, 8.7975375e-2, 8.960028e-2, 9.1237515e-2,
    9.288713e-2, 9.454919e-2, 9.622374e-2, 9.791085e-2,
    9.961058e-2, 1.01323e-1, 1.0304816e-1, 1.0478614e-1,
    1.0653701e-1, 1.0830083e-1, 1.1007768e-1, 1.1186763e-1,
    1.1367077e-1, 1.15487166e-1, 1.173169e-1, 1.19160056e-1,
    1.2101672e-1, 1.2288698e-1, 1.2477092e-1, 1.2666863e-1,
    1.285802e-1, 1.3050574e-1, 1.3244532e-1, 1.3439907e-1,
    1.3636707e-1, 1.3834943e-1, 1.4034624e-1, 1.4235765e-1,
    1.4438373e-1, 1.4642459e-1, 1.4848037e-1, 1.5055119e-1,
    1.5263714e-1, 1.5473837e-1, 1.5685499e-1, 1.5898713e-1,
    1.6113494e-1, 1.6329853e-1, 1.6547804e-1, 1.6767362e-1,
    1.698854e-1, 1.7211354e-1, 1.7435817e-1, 1.7661946e-1,
    1.7889754e-1, 1.811926e-1, 1.8350479e-1, 1.8583426e-1,
    1.881812e-1, 1.9054577e-1, 1.9292815e-1, 1.9532852e-1,
    1.9774707e-1, 2.0018397e-1, 2.0263945e-1, 2.0511365e-1,
    2.0760682e-1, 2.1011916e-1, 2.1265087e-1, 2.1520215e-1,
    2.1777324e-1, 2.2036438e-1, 2.2297576e-1, 2.2560766e-1,
    2.282603e-1, 2.3093392e-1, 2.3362878e-1, 2.3634516e-1,
    2.3908329e-1, 2.4184346e-1, 2.4462597e-1, 2.4743107e-1,
    2.5025907e-1, 2.531103e-1, 2.5598502e-1, 2.5888354e-1,
    2.6180625e-1, 2.6475343e-1, 2.677254e-1, 2.707226e-1,
    2.737453e-1, 2.7679393e-1, 2.7986884e-1, 2.8297043e-1,
    2.8609908e-1, 2.8925523e-1, 2.9243928e-1, 2.956517e-1,
    2.9889292e-1, 3.021634e-1, 3.054636e-1, 3.0879408e-1,
    3.1215525e-1, 3.1554767e-1, 3.189719e-1, 3.224285e-1,
    3.2591796e-1, 3.2944095e-1, 3.3299807e-1, 3.365899e-1,
    3.4021714e-1, 3.4388044e-1, 3.475805e-1, 3.51318e-1,
    3.5509375e-1, 3.5890847e-1, 3.62763e-1, 3.666581e-1,
    3.7059465e-1, 3.7457356e-1, 3.7859577e-1, 3.8266218e-1,
    3.8677382e-1, 3.9093173e-1, 3.9513698e-1, 3.993907e-1,
    4.03694e-1, 4.0804818e-1, 4.1245446e-1, 4.169142e-1,
    4.2142874e-1, 4.2599955e-1, 4.3062815e-1, 4.3531612e-1,
    4.4006512e-1, 4.4487688e-1, 4.4975325e-1, 4.5469615e-1,
    4.5970762e-1, 4.6478975e-1, 4.6994483e-1, 4.751752e-1,
    4.8048335e-1, 4.85872e-1, 4.9134386e-1, 4.96902e-1,
    5.025495e-1, 5.0828975e-1, 5.141264e-1, 5.2006316e-1,
    5.261042e-1, 5.3225386e-1, 5.385169e-1, 5.448982e-1,
    5.514034e-1, 5.580383e-1, 5.648092e-1, 5.7172304e-1,
    5.787874e-1, 5.8601034e-1, 5.934009e-1, 6.0096896e-1,
    6.0872537e-1, 6.166822e-1, 6.248527e-1, 6.3325197e-1,
    6.418967e-1, 6.5080583e-1, 6.6000086e-1, 6.695063e-1,
    6.7935055e-1, 6.895665e-1, 7.0019263e-1, 7.1127474e-1,
    7.2286767e-1, 7.350381e-1, 7.478686e-1, 7.614634e-1,
    7.7595687e-1, 7.915276e-1, 8.084217e-1, 8.269933e-1,
    8.477855e-1, 8.7170434e-1, 9.0046996e-1, 9.381437e-1,
    1e0,
);

// microsurface WGSL library: the rejection samplers' uniform stream and the Exp(1) ziggurat
// (stream.wgsl).
//
// The Rust samplers of Double GGX and the Exponential NDF draw uniforms beyond u from
// `UniformStream` (crates/microsurface/src/distribution/mod.rs): SplitMix64 (Steele, Lea &
// Flood 2014; math/rng.rs) seeded by the bits of u as f64, a ^ rotl(b, 29) ^ 0x243F6A8885A308D3,
// each f32 uniform the top 24 bits of an output over 2^24. WGSL has only 32-bit integers: a
// 64-bit word is vec2<u32>(low, high), and the add, the multiplications and the shifts are
// written out on the halves (the multiplications through 16-bit limbs), so the stream is the
// Rust one bit for bit (tests/family.rs). The state lives in the caller's function variable.

// a + b (mod 2^64).
fn ms_u64_add(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    let lo = a.x + b.x;
    return vec2<u32>(lo, a.y + b.y + select(0u, 1u, lo < a.x));
}

// The full 64-bit product of two u32, by 16-bit limbs (every partial sum fits in u32).
fn ms_u32_mul_wide(x: u32, y: u32) -> vec2<u32> {
    let x0 = x & 0xffffu;
    let x1 = x >> 16u;
    let y0 = y & 0xffffu;
    let y1 = y >> 16u;
    let p00 = x0 * y0;
    let p01 = x0 * y1;
    let p10 = x1 * y0;
    let p11 = x1 * y1;
    let mid = (p00 >> 16u) + (p01 & 0xffffu) + (p10 & 0xffffu);
    return vec2<u32>((mid << 16u) | (p00 & 0xffffu), p11 + (p01 >> 16u) + (p10 >> 16u) + (mid >> 16u));
}

// a · b (mod 2^64): the low halves' full product, the cross terms into the high half.
fn ms_u64_mul(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    let p = ms_u32_mul_wide(a.x, b.x);
    return vec2<u32>(p.x, p.y + a.x * b.y + a.y * b.x);
}

// a ^ (a >> k) for 0 < k < 32.
fn ms_u64_xorshift(a: vec2<u32>, k: u32) -> vec2<u32> {
    return a ^ vec2<u32>((a.x >> k) | (a.y << (32u - k)), a.y >> k);
}

// The bits of the f64 of an f32 (exact: subnormal f32 become normal f64; infinities and
// NaN keep their class).
fn ms_f64_bits(v: f32) -> vec2<u32> {
    let b = bitcast<u32>(v);
    let sign = b & 0x80000000u;
    let e = (b >> 23u) & 0xffu;
    var man = b & 0x7fffffu;
    var e64: u32;
    if e == 0u {
        if man == 0u {
            return vec2<u32>(0u, sign);
        }
        // man · 2^−149 with its leading bit at p: 2^{p−149}(1 + the bits below p).
        let p = firstLeadingBit(man);
        e64 = p + 874u;
        man = (man << (23u - p)) & 0x7fffffu;
    } else if e == 255u {
        e64 = 2047u;
    } else {
        e64 = e + 896u;
    }
    return vec2<u32>(man << 29u, sign | (e64 << 20u) | (man >> 3u));
}

// The stream of u: SplitMix64's state a ^ rotl(b, 29) ^ 0x243F6A8885A308D3, a and b the f64
// bits of u₀ and u₁ (the Rust UniformStream::new).
fn ms_stream_new(u: vec2<f32>) -> vec2<u32> {
    let a = ms_f64_bits(u.x);
    let b = ms_f64_bits(u.y);
    let rot = vec2<u32>((b.x << 29u) | (b.y >> 3u), (b.y << 29u) | (b.x >> 3u));
    return a ^ rot ^ vec2<u32>(0x85a308d3u, 0x243f6a88u);
}

// SplitMix64's next 64 bits (the Rust SplitMix64::next_u64).
fn ms_stream_next_u64(state: ptr<function, vec2<u32>>) -> vec2<u32> {
    *state = ms_u64_add(*state, vec2<u32>(0x7f4a7c15u, 0x9e3779b9u));
    var z = ms_u64_mul(ms_u64_xorshift(*state, 30u), vec2<u32>(0x1ce4e5b9u, 0xbf58476du));
    z = ms_u64_mul(ms_u64_xorshift(z, 27u), vec2<u32>(0x133111ebu, 0x94d049bbu));
    return ms_u64_xorshift(z, 31u);
}

// The next uniform in [0, 1): the top 24 bits over 2^24 (the Rust next_uniform::<f32>).
fn ms_stream_next(state: ptr<function, vec2<u32>>) -> f32 {
    let z = ms_stream_next_u64(state);
    return f32(z.y >> 8u) * (1.0 / 16777216.0);
}

// An Exp(1) variate from w ∈ [0, 1) by the ziggurat of Marsaglia & Tsang 2000 (the Rust
// fast::ziggurat::exp1 over its generated layers, family_tables.wgsl, in f32): layer
// i = ⌊256w⌋, x = (256w − i)x_i, kept when below x_{i+1}; else the tail r + Exp(1) (layer
// 0, from −ln(1 − v)) or the wedge's height test, with further uniforms from the stream.
fn ms_zig_exp1(w: f32, state: ptr<function, vec2<u32>>) -> f32 {
    var y = w * 256.0;
    var k = u32(max(y, 0.0));
    var i = k & 255u;
    var x = (y - f32(k)) * MS_ZIG_EXP_X[i];
    if x < MS_ZIG_EXP_X[i + 1u] {
        return x;
    }
    // Each pass keeps its candidate with probability ≥ 0.98; the cap (the Rust one) only
    // guarantees termination.
    for (var n = 0; n < 64; n++) {
        if x != x {
            return x;
        }
        if i == 0u {
            return MS_ZIG_EXP_X[1] - log(1.0 - ms_stream_next(state));
        }
        let h = MS_ZIG_EXP_F[i] + ms_stream_next(state) * (MS_ZIG_EXP_F[i + 1u] - MS_ZIG_EXP_F[i]);
        if h < exp(-x) {
            return x;
        }
        y = ms_stream_next(state) * 256.0;
        k = u32(y);
        i = k & 255u;
        x = (y - f32(k)) * MS_ZIG_EXP_X[i];
        if x < MS_ZIG_EXP_X[i + 1u] {
            return x;
        }
    }
    return x;
}

// microsurface WGSL library: Double GGX, anisotropic (double_ggx.wgsl).
//
// The Rust `Microfacet<f32, DoubleGgx>` (crates/microsurface/src/fast/double_ggx.rs, the
// `Shape for DoubleGgx` of distribution/microfacet.rs), with the Rust tables as generated
// WGSL data (family_tables.wgsl). Double GGX is the Gamma-1 superposition of GGX,
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
// Visible normals (the Rust rejection over t, then GGX's caps) are not in this file yet.

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
    return ms_fam_cubic(MS_DG_LAMBDA[u32(g.x)], g.y);
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

// Smith Λ(w), Λ(−w) = Λ(w): isotropic from u = |w.z| (the Rust lambda32), anisotropic from
// x = (αx²w.x² + αy²w.y²)/(2w.z²) (lambda_aniso); the ends at the projected roughness
// α̃² = (αx²x² + αy²y²)/(x² + y²) (the Rust lambda_projected).
fn ms_double_ggx_lambda(w: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let u = abs(w.z);
    var x: f32;
    if alpha.x == alpha.y {
        let a = alpha.x;
        x = 0.5 * a * a * ((1.0 - u) * (1.0 + u)) / (u * u);
    } else {
        let sx = alpha.x * w.x;
        let sy = alpha.y * w.y;
        x = 0.5 * ((sx * sx + sy * sy) / (w.z * w.z));
    }
    // 2^−30 ≤ x < 2^16 (false for NaN).
    if x >= 9.313225746154785e-10 && x < 65536.0 {
        return ms_dg_lambda_table(x);
    }
    var a = alpha.x;
    let s2 = w.x * w.x + w.y * w.y;
    if alpha.x != alpha.y && s2 > 0.0 {
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
    let c0 = MS_DG_D[3u * i];
    let c1 = MS_DG_D[3u * i + 1u];
    let c2 = MS_DG_D[3u * i + 2u];
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
    var state = ms_stream_new(u);
    let t = max(ms_zig_exp1(ms_stream_next(&state), &state), 1e-36);
    let cs = ms_cos_sin_turn(u.y);
    let r = sqrt(u.x);
    let wm = ms_unit_normal(vec3<f32>(alpha.x * r * cs.x, alpha.y * r * cs.y,
        sqrt(t * max(1.0 - u.x, 0.0))));
    return MsSample(wm, ms_double_ggx_d(wm, alpha) * wm.z);
}

// microsurface WGSL library: the Exponential NDF, anisotropic (exponential.wgsl).
//
// The Rust `Microfacet<f32, Exponential>` (crates/microsurface/src/fast/exponential.rs, the
// `Shape for Exponential` of distribution/microfacet.rs), with the Rust tables as generated
// WGSL data (family_tables.wgsl). The slope density is P22(r) = 2e^{−2r}/π at unit roughness
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
// Rust sample_dcos). Visible normals (the Rust rejection in slope space) are not in this
// file yet.

// Λ from the q tables at 2^−24 ≤ q < 4096 (the Rust eval_narrow of EXPONENTIAL32_QA/_QB).
fn ms_exp_lambda_q(q: f32) -> f32 {
    if q < 64.0 {
        let g = ms_fam_segment(q, MS_EXP_QA_K0, MS_EXP_QA_K1, MS_EXP_QA_M);
        return ms_fam_cubic(MS_EXP_QA[u32(g.x)], g.y);
    }
    let g = ms_fam_segment(q, MS_EXP_QB_K0, MS_EXP_QB_K1, MS_EXP_QB_M);
    return ms_fam_cubic(MS_EXP_QB[u32(g.x)], g.y);
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
        let lo = MS_EXP_FAR[i];
        let hi = MS_EXP_FAR[i + 1u];
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

// Smith Λ(w), Λ(−w) = Λ(w): q = 4u²/(α²(1 − u)(1 + u)) at u = |w.z| where isotropic (the Rust
// q_of), q = 4w.z²/(αx²w.x² + αy²w.y²) where anisotropic; the ends at z = 2u/(α̃√((1 − u)(1 +
// u))), α̃ the projected roughness (the Rust lambda_projected).
fn ms_exponential_lambda(w: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let u = abs(w.z);
    var q: f32;
    if alpha.x == alpha.y {
        let a = alpha.x;
        q = 4.0 * u * u / (a * a * ((1.0 - u) * (1.0 + u)));
    } else {
        let sx = alpha.x * w.x;
        let sy = alpha.y * w.y;
        q = 4.0 * (w.z * w.z) / (sx * sx + sy * sy);
    }
    // 2^−24 ≤ q < 4096 (false for NaN).
    if q >= 5.960464477539063e-8 && q < 4096.0 {
        return ms_exp_lambda_q(q);
    }
    var a = alpha.x;
    let s2 = w.x * w.x + w.y * w.y;
    if alpha.x != alpha.y && s2 > 0.0 {
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
    var state = ms_stream_new(u);
    let e = ms_zig_exp1(ms_stream_next(&state), &state);
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

// microsurface WGSL library: a material's distribution chosen at run time (microfacet.wgsl),
// the WGSL counterpart of the Rust `MicrofacetDistribution` door that the BSDFs use. A
// renderer that knows its NDF calls the per-NDF functions (ms_ggx_d, …) directly.

// Which NDF (`ndf`: an MS_NDF_* constant) at roughness (αx, αy).
struct MsMicrofacet {
    ndf: u32,
    alpha: vec2<f32>,
}

const MS_NDF_GGX: u32 = 0u;
const MS_NDF_BECKMANN: u32 = 1u;
const MS_NDF_DOUBLE_GGX: u32 = 2u;
const MS_NDF_EXPONENTIAL: u32 = 3u;

// D(wm); 0 below the horizon (and for an NDF this library does not have).
fn ms_d(mf: MsMicrofacet, wm: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN {
        return ms_beckmann_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX {
        return ms_double_ggx_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL {
        return ms_exponential_d(wm, mf.alpha);
    }
    return 0.0;
}

// Smith Λ(w).
fn ms_lambda(mf: MsMicrofacet, w: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_lambda(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN {
        return ms_beckmann_lambda(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX {
        return ms_double_ggx_lambda(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL {
        return ms_exponential_lambda(w, mf.alpha);
    }
    return 0.0;
}

// G1(w).
fn ms_g1(mf: MsMicrofacet, w: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_g1(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN {
        return ms_beckmann_g1(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX {
        return ms_double_ggx_g1(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL {
        return ms_exponential_g1(w, mf.alpha);
    }
    return 0.0;
}

// Height-correlated G2(wo, wi).
fn ms_g2(mf: MsMicrofacet, wo: vec3<f32>, wi: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_g2(wo, wi, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN {
        return ms_beckmann_g2(wo, wi, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX {
        return ms_double_ggx_g2(wo, wi, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL {
        return ms_exponential_g2(wo, wi, mf.alpha);
    }
    return 0.0;
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_g2_separable(mf: MsMicrofacet, wo: vec3<f32>, wi: vec3<f32>) -> f32 {
    return ms_g1(mf, wo) * ms_g1(mf, wi);
}

// The visible-normal density D_w(wm).
fn ms_pdf(mf: MsMicrofacet, w: vec3<f32>, wm: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_pdf(w, wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN {
        return ms_beckmann_pdf(w, wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX {
        return ms_double_ggx_pdf(w, wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL {
        return ms_exponential_pdf(w, wm, mf.alpha);
    }
    return 0.0;
}

// A visible normal for w from u ∈ [0, 1)², with its pdf. Double GGX and the Exponential
// NDF have no visible-normal sampler here yet (the Rust ones are rejection samplers over
// the stream of u): the normal (0, 0, 1) with pdf 0, which a BSDF reads as no sample.
fn ms_sample(mf: MsMicrofacet, w: vec3<f32>, u: vec2<f32>) -> MsSample {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_sample(w, mf.alpha, u);
    }
    if mf.ndf == MS_NDF_BECKMANN {
        return ms_beckmann_sample(w, mf.alpha, u);
    }
    return MsSample(vec3<f32>(0.0, 0.0, 1.0), 0.0);
}

// A normal distributed as D(m) cos θm, with its pdf.
fn ms_sample_dcos(mf: MsMicrofacet, u: vec2<f32>) -> MsSample {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_sample_dcos(mf.alpha, u);
    }
    if mf.ndf == MS_NDF_BECKMANN {
        return ms_beckmann_sample_dcos(mf.alpha, u);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX {
        return ms_double_ggx_sample_dcos(mf.alpha, u);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL {
        return ms_exponential_sample_dcos(mf.alpha, u);
    }
    return MsSample(vec3<f32>(0.0, 0.0, 1.0), 0.0);
}

// Whether the surface is effectively smooth (max(αx, αy) < 1e-3): the BSDFs are then a
// delta lobe, as pbrt-v4's and the Rust types'.
fn ms_effectively_smooth(mf: MsMicrofacet) -> bool {
    return max(mf.alpha.x, mf.alpha.y) < 1e-3;
}

// microsurface WGSL library: the single-scattering rough conductor (conductor.wgsl), as the
// Rust `bsdf::RoughConductor` (crates/microsurface/src/bsdf/mod.rs) in f32:
//
//   f = D(wm) F(|wo·wm|) G2(wo, wi)/(4|cos θo||cos θi|),  wm the half vector of wo and wi
//
// (Cook & Torrance 1982; Walter et al. 2007, eq. 20), two-sided; eval is f without the
// cosine; pdf per unit solid angle of wi, D_wo(wm)/(4|wo·wm|); sample draws a visible normal
// and reflects (a reflection below the horizon is rejected: flags without MS_SAMPLE_VALID).
// Effectively smooth (max α < 1e-3): a delta lobe, eval and pdf 0, sample the mirror
// direction with MS_SAMPLE_SPECULAR, f = F/|cos θi|, pdf 1.

// The masking-shadowing term G2: MS_MASKING_CORRELATED 1/(1 + Λo + Λi) (the default),
// MS_MASKING_SEPARABLE G1(wo) G1(wi); MS_MASKING_CORRELATED_BETA is the correlated one for a
// reflection (its transmission form is the dielectric's).
const MS_MASKING_CORRELATED: u32 = 0u;
const MS_MASKING_SEPARABLE: u32 = 1u;
const MS_MASKING_CORRELATED_BETA: u32 = 2u;

// A rough conductor: the distribution, the Fresnel term, the masking.
struct MsConductor {
    mf: MsMicrofacet,
    fresnel: MsFresnel,
    masking: u32,
}

// A sampled direction: wi, f(wo, wi) without the cosine, its pdf, flags (MS_SAMPLE_VALID: a
// sample; MS_SAMPLE_SPECULAR: a delta lobe, f and pdf its weights; MS_SAMPLE_TRANSMISSION:
// the dielectric's refracted lobe), and the relative index η' along the path (1 for a
// reflection).
struct MsBsdfSample {
    wi: vec3<f32>,
    pdf: f32,
    f: vec3<f32>,
    flags: u32,
    eta: f32,
}

const MS_SAMPLE_VALID: u32 = 1u;
const MS_SAMPLE_SPECULAR: u32 = 2u;

// Whether a cosine counts as on the horizon (|cos θ| below 1e-18, where f's 1/(|cos θo||cos θi|)
// underflows f32).
fn ms_on_horizon(z: f32) -> bool {
    return !(abs(z) >= 1e-18);
}

// A sampled pdf or D a renderer can divide by: at least f32's smallest normal over the horizon
// floor (1.2e-20), and finite.
fn ms_usable(v: f32) -> bool {
    return v >= 1.1754944e-20 && v <= 3.4028235e38;
}

// G2 of the masking form for a reflection.
fn ms_masking_g2(mf: MsMicrofacet, masking: u32, wo: vec3<f32>, wi: vec3<f32>) -> f32 {
    if masking == MS_MASKING_SEPARABLE {
        return ms_g2_separable(mf, wo, wi);
    }
    return ms_g2(mf, wo, wi);
}

// D(wm) G2(wo, wi)/(4|cos θo||cos θi|), D(wm) given.
fn ms_reflected(mf: MsMicrofacet, masking: u32, wo: vec3<f32>, wi: vec3<f32>, d_wm: f32) -> f32 {
    return d_wm * ms_masking_g2(mf, masking, wo, wi) / (4.0 * abs(wo.z * wi.z));
}

// F times the lobe, 0 where a channel reflects nothing (also where the lobe is +∞).
fn ms_weighted(fr: vec3<f32>, k: f32) -> vec3<f32> {
    return select(fr * k, vec3<f32>(0.0), fr == vec3<f32>(0.0));
}

// The half vector of a pair the rough lobe reaches (same side, neither on the horizon, a
// rough surface), else (0, 0, 0).
fn ms_conductor_lobe_normal(c: MsConductor, wo: vec3<f32>, wi: vec3<f32>) -> vec3<f32> {
    if !ms_same_hemisphere(wo, wi) || ms_on_horizon(wo.z) || ms_on_horizon(wi.z)
        || ms_effectively_smooth(c.mf) {
        return vec3<f32>(0.0);
    }
    return ms_half_vector_reflection(wo, wi);
}

// f(wo, wi) without the cosine (F at the mean of |wo·wm| and |wi·wm|: reciprocal).
fn ms_conductor_eval(c: MsConductor, wo: vec3<f32>, wi: vec3<f32>) -> vec3<f32> {
    let wm = ms_conductor_lobe_normal(c, wo, wi);
    if !ms_half_vector_ok(wm) {
        return vec3<f32>(0.0);
    }
    let fr = ms_fresnel_eval(c.fresnel, 0.5 * (abs(ms_dot(wo, wm)) + abs(ms_dot(wi, wm))));
    let k = ms_reflected(c.mf, c.masking, wo, wi, ms_d(c.mf, wm));
    return ms_weighted(fr, k);
}

// The density of ms_conductor_sample's wi per unit solid angle (0 for the delta lobe).
fn ms_conductor_pdf(c: MsConductor, wo: vec3<f32>, wi: vec3<f32>) -> f32 {
    let wm = ms_conductor_lobe_normal(c, wo, wi);
    if !ms_half_vector_ok(wm) {
        return 0.0;
    }
    return ms_pdf(c.mf, wo, wm) / (4.0 * abs(ms_dot(wo, wm)));
}

// (f, pdf) of the pair in one call, the two above bit for bit: vec4(f, pdf).
fn ms_conductor_eval_pdf(c: MsConductor, wo: vec3<f32>, wi: vec3<f32>) -> vec4<f32> {
    let wm = ms_conductor_lobe_normal(c, wo, wi);
    if !ms_half_vector_ok(wm) {
        return vec4<f32>(0.0);
    }
    let co = abs(ms_dot(wo, wm));
    let fr = ms_fresnel_eval(c.fresnel, 0.5 * (co + abs(ms_dot(wi, wm))));
    let k = ms_reflected(c.mf, c.masking, wo, wi, ms_d(c.mf, wm));
    return vec4<f32>(ms_weighted(fr, k), ms_pdf(c.mf, wo, wm) / (4.0 * co));
}

// A direction wi from the uniforms u (the visible normal); uc, the lobe choice, is unused by
// a conductor and kept for the dielectric's signature.
fn ms_conductor_sample(c: MsConductor, wo: vec3<f32>, uc: f32, u: vec2<f32>) -> MsBsdfSample {
    let none = MsBsdfSample(vec3<f32>(0.0), 0.0, vec3<f32>(0.0), 0u, 1.0);
    if ms_on_horizon(wo.z) {
        return none;
    }
    if ms_effectively_smooth(c.mf) {
        let wi = vec3<f32>(-wo.x, -wo.y, wo.z);
        let k = 1.0 / abs(wi.z);
        return MsBsdfSample(wi, 1.0, ms_fresnel_eval(c.fresnel, abs(wo.z)) * k,
            MS_SAMPLE_VALID | MS_SAMPLE_SPECULAR, 1.0);
    }
    let s = ms_sample(c.mf, wo, u);
    let wi = ms_reflect(wo, s.wm);
    if !ms_same_hemisphere(wo, wi) || ms_on_horizon(wi.z) {
        return none;
    }
    let co = abs(ms_dot(wo, s.wm));
    let pdf = s.pdf / (4.0 * co);
    if !ms_usable(pdf) {
        return none;
    }
    let fr = ms_fresnel_eval(c.fresnel, co);
    let d = ms_d(c.mf, s.wm);
    if !ms_usable(d) {
        return none;
    }
    let f = ms_weighted(fr, ms_reflected(c.mf, c.masking, wo, wi, d));
    if !all(f <= vec3<f32>(3.4028235e38)) {
        return none;
    }
    return MsBsdfSample(wi, pdf, f, MS_SAMPLE_VALID, 1.0);
}

// microsurface WGSL library: the single-scattering rough dielectric (dielectric.wgsl), as the
// Rust `bsdf::RoughDielectric` (crates/microsurface/src/bsdf/mod.rs) in f32 (Walter et al.
// 2007, eqs. 16–21, with visible-normal sampling):
//
//   reflection    f = R D(wm) G2/(4|cos θo||cos θi|), wm the half vector
//   transmission  f = (1 − R) D(wm) G2 |wi·wm||wo·wm| / (|cos θi||cos θo| (wi·wm + wo·wm/η')²)
//                   (÷ η'² for radiance transport), wm ∝ η' wi + wo
//
// η = η_inside/η_outside (inside: z < 0), η' = η for wo above the surface, 1/η below; R the
// dielectric Fresnel reflectance at wo·wm. f is grey (one value). Sampling: a visible normal
// from wo, then reflection with probability R (the uniform uc), refraction otherwise.
// Microfacets facing away from either direction contribute nothing. η = 1 or an effectively
// smooth surface: delta lobes (eval and pdf 0; sample the mirror or refracted direction with
// MS_SAMPLE_SPECULAR, f = R/|cos θi| or (1 − R)/|cos θi| (÷ η'²), pdf R or 1 − R). Masking:
// MS_MASKING_CORRELATED (1/(1 + Λo + Λi), pbrt-v4's, also for the transmission) or
// MS_MASKING_SEPARABLE; the Rust type's CorrelatedBeta transmission form (Euler's beta
// function of Λo, Λi, which f32 log-gamma differences cannot give to the f32 bound at large Λ)
// is not in the WGSL library: MS_MASKING_CORRELATED_BETA evaluates as MS_MASKING_CORRELATED.

const MS_TRANSPORT_RADIANCE: u32 = 0u;
const MS_TRANSPORT_IMPORTANCE: u32 = 1u;

// A sample's lobe: set in MsBsdfSample.flags for a transmission.
const MS_SAMPLE_TRANSMISSION: u32 = 4u;

// A rough dielectric interface of relative index η.
struct MsDielectric {
    mf: MsMicrofacet,
    eta: f32,
    masking: u32,
    transport: u32,
}

fn ms_dielectric_smooth(d: MsDielectric) -> bool {
    return d.eta == 1.0 || ms_effectively_smooth(d.mf);
}

// G2 of the masking form (reflection or transmission alike; see the file's header).
fn ms_dielectric_g2(d: MsDielectric, wo: vec3<f32>, wi: vec3<f32>) -> f32 {
    return ms_masking_g2(d.mf, d.masking, wo, wi);
}

// The half vector of (wo, wi) and η' (1 for reflection) as vec4(wm, η'), if the pair is a
// reflection or a refraction through a microfacet facing both; η' = 0 otherwise.
fn ms_dielectric_half(d: MsDielectric, wo: vec3<f32>, wi: vec3<f32>) -> vec4<f32> {
    let none = vec4<f32>(0.0);
    let co = wo.z;
    let ci = wi.z;
    if ms_on_horizon(co) || ms_on_horizon(ci) {
        return none;
    }
    var wm: vec3<f32>;
    var etap = 1.0;
    if co * ci > 0.0 {
        wm = ms_half_vector_reflection(wo, wi);
    } else {
        let h = ms_half_vector_refraction(wo, wi, d.eta);
        wm = h.xyz;
        etap = h.w;
    }
    if !ms_half_vector_ok(wm) {
        return none;
    }
    // Microfacets facing away from either direction: no contribution.
    if ms_dot(wm, wi) * ci < 0.0 || ms_dot(wm, wo) * co < 0.0 {
        return none;
    }
    return vec4<f32>(wm, etap);
}

// f of a transmission through wm (η' one-sided), D(wm) and the transmittance t given.
fn ms_dielectric_f_transmission(d: MsDielectric, wo: vec3<f32>, wi: vec3<f32>, wm: vec3<f32>,
    d_wm: f32, etap: f32, t: f32) -> f32 {
    let di = ms_dot(wi, wm);
    let d_o = ms_dot(wo, wm);
    let s = ms_refraction_denominator(wo, wi, wm, etap);
    // G2/|cos θo cos θi| before the 1/s²: the cosines' product times s² could underflow.
    let geometric = ms_dielectric_g2(d, wo, wi) / abs(wi.z * wo.z) * (abs(di * d_o) / (s * s));
    var f = d_wm * t * geometric;
    if d.transport == MS_TRANSPORT_RADIANCE {
        f = f / (etap * etap);
    }
    return f;
}

// f(wo, wi) without the cosine (grey).
fn ms_dielectric_eval(d: MsDielectric, wo: vec3<f32>, wi: vec3<f32>) -> f32 {
    if ms_dielectric_smooth(d) {
        return 0.0;
    }
    let h = ms_dielectric_half(d, wo, wi);
    if h.w == 0.0 {
        return 0.0;
    }
    let wm = h.xyz;
    let r = ms_fresnel_dielectric(ms_dot(wo, wm), d.eta);
    let d_wm = ms_d(d.mf, wm);
    if wo.z * wi.z > 0.0 {
        return r * ms_reflected(d.mf, d.masking, wo, wi, d_wm);
    }
    return ms_dielectric_f_transmission(d, wo, wi, wm, d_wm, h.w, 1.0 - r);
}

// The density of ms_dielectric_sample's wi per unit solid angle (0 for the delta lobes).
fn ms_dielectric_pdf(d: MsDielectric, wo: vec3<f32>, wi: vec3<f32>) -> f32 {
    if ms_dielectric_smooth(d) {
        return 0.0;
    }
    let h = ms_dielectric_half(d, wo, wi);
    if h.w == 0.0 {
        return 0.0;
    }
    let wm = h.xyz;
    let r = ms_fresnel_dielectric(ms_dot(wo, wm), d.eta);
    let pdf_wm = ms_pdf(d.mf, wo, wm);
    if wo.z * wi.z > 0.0 {
        return pdf_wm * r / (4.0 * abs(ms_dot(wo, wm)));
    }
    return pdf_wm * (1.0 - r) * ms_jacobian_refraction(wo, wi, wm, h.w);
}

// The smooth interface's delta lobes.
fn ms_dielectric_sample_smooth(d: MsDielectric, wo: vec3<f32>, uc: f32) -> MsBsdfSample {
    let r = ms_fresnel_dielectric(wo.z, d.eta);
    if uc < r {
        let wi = vec3<f32>(-wo.x, -wo.y, wo.z);
        return MsBsdfSample(wi, r, vec3<f32>(r / abs(wi.z)), MS_SAMPLE_VALID | MS_SAMPLE_SPECULAR,
            1.0);
    }
    let none = MsBsdfSample(vec3<f32>(0.0), 0.0, vec3<f32>(0.0), 0u, 1.0);
    let rt = ms_refract(wo, vec3<f32>(0.0, 0.0, 1.0), d.eta);
    if rt.w == 0.0 {
        return none;
    }
    let wi = rt.xyz;
    if ms_on_horizon(wi.z) {
        return none;
    }
    let t = 1.0 - r;
    var f = t / abs(wi.z);
    if d.transport == MS_TRANSPORT_RADIANCE {
        f = f / (rt.w * rt.w);
    }
    return MsBsdfSample(wi, t, vec3<f32>(f),
        MS_SAMPLE_VALID | MS_SAMPLE_SPECULAR | MS_SAMPLE_TRANSMISSION, rt.w);
}

// A direction wi from the uniforms uc (reflection where uc < R) and u (the visible normal).
fn ms_dielectric_sample(d: MsDielectric, wo: vec3<f32>, uc: f32, u: vec2<f32>) -> MsBsdfSample {
    let none = MsBsdfSample(vec3<f32>(0.0), 0.0, vec3<f32>(0.0), 0u, 1.0);
    if ms_on_horizon(wo.z) {
        return none;
    }
    if ms_dielectric_smooth(d) {
        return ms_dielectric_sample_smooth(d, wo, uc);
    }
    let s = ms_sample(d.mf, wo, u);
    let wm = s.wm;
    let c = ms_dot(wo, wm);
    let r = ms_fresnel_dielectric(c, d.eta);
    if uc < r {
        let wi = ms_reflect(wo, wm);
        if !ms_same_hemisphere(wo, wi) || ms_on_horizon(wi.z) {
            return none;
        }
        let d_wm = ms_d(d.mf, wm);
        if !ms_usable(d_wm) {
            return none;
        }
        let f = r * ms_reflected(d.mf, d.masking, wo, wi, d_wm);
        let pdf = s.pdf * r / (4.0 * abs(c));
        if !ms_usable(pdf) || !(f <= 3.4028235e38) {
            return none;
        }
        return MsBsdfSample(wi, pdf, vec3<f32>(f), MS_SAMPLE_VALID, 1.0);
    }
    let rt = ms_refract(wo, wm, d.eta);
    if rt.w == 0.0 {
        return none;
    }
    let wi = rt.xyz;
    let etap = rt.w;
    if ms_same_hemisphere(wo, wi) || ms_on_horizon(wi.z) {
        return none;
    }
    let t = 1.0 - r;
    let pdf = s.pdf * t * ms_jacobian_refraction(wo, wi, wm, etap);
    let d_wm = ms_d(d.mf, wm);
    if !ms_usable(d_wm) {
        return none;
    }
    let f = ms_dielectric_f_transmission(d, wo, wi, wm, d_wm, etap, t);
    if !ms_usable(pdf) || !(f <= 3.4028235e38) {
        return none;
    }
    return MsBsdfSample(wi, pdf, vec3<f32>(f), MS_SAMPLE_VALID | MS_SAMPLE_TRANSMISSION, etap);
}

// microsurface WGSL library: energy compensation of the rough conductor (compensation.wgsl),
// as the Rust `scattering::CompensatedConductor` in f32, with its albedo read from the tables
// of `scattering::lut` (the CLI's `microsurface lut --kind albedo` and `--kind albedo-avg`).
//
// The tables. E(μ, α) = the F = 1 single-scattering albedo, row-major [roughness][μ] (μ the
// inner, fastest index), and E_avg(α) = 2∫E(μ)μ dμ, one value per roughness node. An axis of n
// nodes puts them at the texel centres x_i = (i + ½)/n of its coordinate: the roughness
// coordinate is √(α/α_max) for isotropic α, (αx αy)^¼/√α_max for anisotropic roughness
// (ms_lut_roughness_coord), the μ coordinate is μ = |cos θ| itself (the `Lut` defaults:
// `sqrt_alpha`, `mu`, α_max = 1). A lookup is the linear filter with clamp-to-edge addressing,
// as `Lut::lookup` (and a GPU's sampler) computes it:
//
//   t = clamp(x n − ½, 0, n − 1),  i = min(⌊t⌋, n − 2),  f = t − i,
//   value = (1 − f) v_i + f v_{i+1}      (bilinear: the product weights, summed in Rust's order)
//
// The library declares no binding: where the tables live (a storage buffer, a texture whose
// sampler does the filtering, constants) is the including shader's choice. It takes a tap per
// axis (ms_lut_tap: the node index and the weight) and the fetched node values, and the
// compensation functions take the looked-up albedos. A shader with the tables in a storage
// buffer `lut` (E at offset 0, E_avg after it) writes, say:
//
//   let r = ms_lut_tap(ms_lut_roughness_coord(alpha, 1.0), n_alpha);
//   let m = ms_lut_tap(abs(wo.z), n_mu);
//   let e_o = ms_lut_bilerp(r, m, lut[ms_lut_index(r.i, m.i, n_mu)],
//       lut[ms_lut_index(r.i + 1u, m.i, n_mu)], lut[ms_lut_index(r.i, m.i + 1u, n_mu)],
//       lut[ms_lut_index(r.i + 1u, m.i + 1u, n_mu)]);
//
// (the crate's tests/furnace.rs has the whole shader).
//
// Kulla & Conty 2017 ("Revisiting Physically Based Shading at Imageworks", SIGGRAPH course):
// the single-scattering lobe plus
//
//   f_ms(μo, μi) = F_ms (1 − E(μo))(1 − E(μi)) / (π (1 − E_avg)),
//   F_ms = F_avg² E_avg / (1 − F_avg (1 − E_avg)),
//
// F_avg = 2∫F(μ)μ dμ of the Fresnel term (the Rust type's: 8-point Gauss–Legendre on 16
// intervals; the caller passes it). With F = 1 the white furnace ∫(f_ss + f_ms) cos θi dωi is
// 1 + E(μo) − E_l(μo), E_l the table's lookup, exactly when E_avg is the average of the
// looked-up E (a linear filter's E_l ≤ 1 wherever the nodes are, so no clamp changes the lobe's
// normalisation; the Rust type's `lost_avg` is then 1 − E_avg). Turquin 2019 ("Practical
// multiple scattering compensation for microfacet models"): the single-scattering lobe scaled
// by 1 + F0 (1 − E(μo))/E(μo), F0 = F(μ = 1); with F = 1 the furnace is E(μo)/E_l(μo).

// One axis' tap: the lower node `i` and the weight `f` of node i + 1.
struct MsLutTap {
    i: u32,
    f: f32,
}

// The tap of coordinate x on an axis of n ≥ 2 texel-centred nodes (`Lut::lookup`'s):
// clamped to the edge nodes outside [½/n, 1 − ½/n], so x = 0 and x = 1 are the edge values.
fn ms_lut_tap(x: f32, n: u32) -> MsLutTap {
    let t = clamp(x * f32(n) - 0.5, 0.0, f32(n - 1u));
    let i = min(u32(floor(t)), n - 2u);
    return MsLutTap(i, t - f32(i));
}

// The flat index of node (roughness ir, μ im) of a row-major [roughness][μ] table of n_mu
// nodes along μ.
fn ms_lut_index(ir: u32, im: u32, n_mu: u32) -> u32 {
    return ir * n_mu + im;
}

// The 1-D linear filter between v0 (node t.i) and v1 (node t.i + 1).
fn ms_lut_lerp(t: MsLutTap, v0: f32, v1: f32) -> f32 {
    return (1.0 - t.f) * v0 + t.f * v1;
}

// The bilinear filter of a [roughness][μ] table: v_ab the node (r.i + a, m.i + b). The weights
// and the order of the sum are `Lut::lookup`'s (roughness the outer axis).
fn ms_lut_bilerp(r: MsLutTap, m: MsLutTap, v00: f32, v10: f32, v01: f32, v11: f32) -> f32 {
    let gr = 1.0 - r.f;
    let gm = 1.0 - m.f;
    return gr * gm * v00 + r.f * gm * v10 + gr * m.f * v01 + r.f * m.f * v11;
}

// The roughness coordinate of a `sqrt_alpha` axis: √(√(αx αy)/α_max) (perceptual roughness;
// for isotropic α, √(α/α_max)).
fn ms_lut_roughness_coord(alpha: vec2<f32>, alpha_max: f32) -> f32 {
    return sqrt(sqrt(alpha.x * alpha.y) / alpha_max);
}

// Kulla–Conty's Fresnel factor F_ms = F_avg² E_avg / (1 − F_avg (1 − E_avg)), per channel.
fn ms_kulla_conty_f_ms(f_avg: vec3<f32>, e_avg: f32) -> vec3<f32> {
    return f_avg * f_avg * e_avg / (1.0 - f_avg * (1.0 - e_avg));
}

// Kulla–Conty's lobe without F_ms, (1 − E(μo))(1 − E(μi))/(π (1 − E_avg)), from the looked-up
// e_o = E(μo), e_i = E(μi): each factor clamped at 0 (as the Rust type: f ≥ 0 wherever a
// table's value passes 1), and 0 where nothing is lost (E_avg ≥ 1: a smooth surface).
fn ms_kulla_conty_lobe(e_o: f32, e_i: f32, e_avg: f32) -> f32 {
    let den = MS_PI * (1.0 - e_avg);
    if !(den > 0.0) {
        return 0.0;
    }
    return max(1.0 - e_o, 0.0) * max(1.0 - e_i, 0.0) / den;
}

// The Kulla–Conty compensated conductor's f(wo, wi) without the cosine: ms_conductor_eval plus
// f_ms ms_kulla_conty_lobe where wo and wi lie on one side (the single-scattering lobe's
// sides). e_o, e_i: E at |cos θo|, |cos θi| and the material's roughness; f_ms:
// ms_kulla_conty_f_ms of the Fresnel term's average.
fn ms_conductor_eval_kulla_conty(c: MsConductor, wo: vec3<f32>, wi: vec3<f32>, e_o: f32,
    e_i: f32, e_avg: f32, f_ms: vec3<f32>) -> vec3<f32> {
    let f = ms_conductor_eval(c, wo, wi);
    if !(wo.z * wi.z > 0.0) {
        return f;
    }
    return f + ms_kulla_conty_lobe(e_o, e_i, e_avg) * f_ms;
}

// Turquin's scale of the single-scattering lobe, 1 + F0 (1 − E(μo))/E(μo), per channel.
fn ms_turquin_scale(e_o: f32, f0: vec3<f32>) -> vec3<f32> {
    return 1.0 + f0 * (1.0 - e_o) / e_o;
}

// The Turquin compensated conductor's f(wo, wi) without the cosine: ms_conductor_eval scaled
// by ms_turquin_scale(e_o, f0), e_o = E(|cos θo|), f0 = the Fresnel term at normal incidence.
fn ms_conductor_eval_turquin(c: MsConductor, wo: vec3<f32>, wi: vec3<f32>, e_o: f32,
    f0: vec3<f32>) -> vec3<f32> {
    return ms_conductor_eval(c, wo, wi) * ms_turquin_scale(e_o, f0);
}
