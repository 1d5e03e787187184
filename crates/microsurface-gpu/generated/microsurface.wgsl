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

// D(wm); 0 below the horizon (and for an NDF this library does not have).
fn ms_d(mf: MsMicrofacet, wm: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN {
        return ms_beckmann_d(wm, mf.alpha);
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
    return 0.0;
}

// A visible normal for w from u ∈ [0, 1)², with its pdf.
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
//
// Sampling, as the Rust type: Kulla–Conty mixes the added lobe (a cosine-weighted direction on
// wo's side) with probability q = 1 − E(μo) and the single-scattering sample, pdf = (1 − q)
// pdf_ss + q |cos θi|/π; Turquin samples and weighs as the single-scattering lobe. The
// Kulla–Conty sampler returns the single-scattering f at its wi: the added lobe needs E at
// the sampled |cos θi|, which the including shader looks up and adds (ms_kulla_conty_sample_f).

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

// The tap of coordinate x on an axis of n ≥ 2 edge-aligned nodes x_i = i/(n − 1) (the
// `lut` tables written with `--nodes edges`, Cycles' layout: `Lut::lookup`'s t = x(n − 1)),
// clamped to [0, 1]. (A texture sampler reaches node i at (i + ½)/n instead: sample at
// (x(n − 1) + ½)/n there.)
fn ms_lut_tap_edges(x: f32, n: u32) -> MsLutTap {
    let t = clamp(x * f32(n - 1u), 0.0, f32(n - 1u));
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

// Kulla–Conty's probability of sampling the added lobe, 1 − E(μo) clamped to [0, 1]: its share
// of the energy with F = 1 (the Rust type's `p_ms`).
fn ms_kulla_conty_p_ms(e_o: f32) -> f32 {
    return clamp(1.0 - e_o, 0.0, 1.0);
}

// The density of a cosine-weighted direction wi on wo's side, |cos θi|/π (0 across the
// surface): the added lobe's sampling density.
fn ms_cosine_pdf_same_side(wo: vec3<f32>, wi: vec3<f32>) -> f32 {
    if !(wo.z * wi.z > 0.0) {
        return 0.0;
    }
    return abs(wi.z) / MS_PI;
}

// The Kulla–Conty compensated conductor's pdf: the mixture (1 − q) pdf_ss + q |cos θi|/π,
// q = ms_kulla_conty_p_ms(e_o), e_o = E(|cos θo|) (`CompensatedConductor::pdf`). Turquin's
// pdf is the single-scattering one, ms_conductor_pdf.
fn ms_conductor_pdf_kulla_conty(c: MsConductor, wo: vec3<f32>, wi: vec3<f32>, e_o: f32) -> f32 {
    let q = ms_kulla_conty_p_ms(e_o);
    return (1.0 - q) * ms_conductor_pdf(c, wo, wi) + q * ms_cosine_pdf_same_side(wo, wi);
}

// A cosine-weighted direction on the upper hemisphere from u (Malley's method, the Rust
// `frame::cosine_hemisphere`): (√u₀ cos 2πu₁, √u₀ sin 2πu₁, √(1 − u₀)).
fn ms_cosine_hemisphere(u: vec2<f32>) -> vec3<f32> {
    let r = sqrt(u.x);
    let cs = ms_cos_sin_turn(u.y);
    return vec3<f32>(r * cs.x, r * cs.y, sqrt(max(1.0 - u.x, 0.0)));
}

// The Kulla–Conty compensated conductor's sample (`CompensatedConductor::sample`): with
// probability q = 1 − E(μo) (uc < q) a cosine-weighted direction on wo's side, else the
// single-scattering sample from the same u (a delta lobe returned as it is); pdf the mixture's,
// ms_conductor_pdf_kulla_conty at wi (rejected where it is not ms_usable). f is the
// single-scattering f at wi, ms_conductor_eval: the added lobe needs E(|cos θi|) at the
// sampled direction, which the caller looks up and adds with ms_kulla_conty_sample_f.
fn ms_conductor_sample_kulla_conty(c: MsConductor, wo: vec3<f32>, uc: f32, u: vec2<f32>,
    e_o: f32) -> MsBsdfSample {
    let none = MsBsdfSample(vec3<f32>(0.0), 0.0, vec3<f32>(0.0), 0u, 1.0);
    if ms_on_horizon(wo.z) {
        return none;
    }
    let q = ms_kulla_conty_p_ms(e_o);
    var wi: vec3<f32>;
    if uc < q {
        wi = ms_cosine_hemisphere(u);
        if wo.z < 0.0 {
            wi.z = -wi.z;
        }
    } else {
        let s = ms_conductor_sample(c, wo, (uc - q) / (1.0 - q), u);
        if (s.flags & MS_SAMPLE_VALID) == 0u || (s.flags & MS_SAMPLE_SPECULAR) != 0u {
            return s;
        }
        wi = s.wi;
    }
    let pdf = ms_conductor_pdf_kulla_conty(c, wo, wi, e_o);
    if !ms_usable(pdf) {
        return none;
    }
    return MsBsdfSample(wi, pdf, ms_conductor_eval(c, wo, wi), MS_SAMPLE_VALID, 1.0);
}

// A ms_conductor_sample_kulla_conty sample's f completed with the added lobe: + f_ms
// ms_kulla_conty_lobe(e_o, e_i, e_avg) on wo's side, e_i = E(|cos θi|) at s.wi (a delta or
// rejected sample as it is). Equal to ms_conductor_eval_kulla_conty at s.wi.
fn ms_kulla_conty_sample_f(s: MsBsdfSample, wo: vec3<f32>, e_o: f32, e_i: f32, e_avg: f32,
    f_ms: vec3<f32>) -> MsBsdfSample {
    if (s.flags & MS_SAMPLE_VALID) == 0u || (s.flags & MS_SAMPLE_SPECULAR) != 0u
        || !(wo.z * s.wi.z > 0.0) {
        return s;
    }
    return MsBsdfSample(s.wi, s.pdf, s.f + ms_kulla_conty_lobe(e_o, e_i, e_avg) * f_ms, s.flags,
        s.eta);
}

// The Turquin compensated conductor's sample (`CompensatedConductor::sample`, Scheme::Turquin):
// the single-scattering sample with its own f scaled by ms_turquin_scale(e_o, f0) (a delta
// lobe as it is; a scaled f that overflows is rejected); the pdf is ms_conductor_pdf.
fn ms_conductor_sample_turquin(c: MsConductor, wo: vec3<f32>, uc: f32, u: vec2<f32>, e_o: f32,
    f0: vec3<f32>) -> MsBsdfSample {
    let s = ms_conductor_sample(c, wo, uc, u);
    if (s.flags & MS_SAMPLE_VALID) == 0u || (s.flags & MS_SAMPLE_SPECULAR) != 0u {
        return s;
    }
    let f = s.f * ms_turquin_scale(e_o, f0);
    if !all(f <= vec3<f32>(3.4028235e38)) {
        return MsBsdfSample(vec3<f32>(0.0), 0.0, vec3<f32>(0.0), 0u, 1.0);
    }
    return MsBsdfSample(s.wi, s.pdf, f, s.flags, s.eta);
}

// ---- The compensated rough dielectric (two-sided Kulla–Conty, Turquin's 1/E), as the Rust
// `scattering::CompensatedDielectric` in f32, over the `lut` tables `LutKind::Dielectric`
// (R, T over [side][η][roughness][μ]; the shader keeps E = R + T) and `DielectricAvg`.
//
// Axes: side 0 is wo outside (relative index η > 1), 1 wo inside (1/η); the η coordinate is
// √((η − 1)/2) (Cycles' map, η = 1 + 2x²), texel centres as the other axes. Within a side the
// lookup is trilinear over (η, roughness, μ), `Lut::lookup`'s weights and order of the sum.
//
// From side s the lost energy 1 − E_s(μo) is split: reflected share 1 − k_s, lobe
// (1 − k_s)(1 − E_s(μo))(1 − E_s(μi))/(π(1 − E_avg,s)); transmitted share k_s, lobe
// k_s(1 − E_s(μo))(1 − E_s̄(μi))/(π(1 − E_avg,s̄)) (s̄ the other side; ÷ η'² for radiance
// transport). k_out = 1 − F_avg(η), k_in = k_out (1 − E_avg,out)/(η²(1 − E_avg,in))
// (reciprocity of importance transport, f(out → in) = η² f(in → out)), both scaled down
// together where k_in passes 1 (ms_dielectric_kulla_conty_k). Each lobe integrates to its share
// exactly when E_avg is the average of the looked-up E, so the white furnace (importance
// transport, reflection + transmission) is 1 + E(μo) − E_l(μo), the table's own filter error.
// Turquin: the single-scattering lobes scaled by 1/E_s(μo).

// The flat index of node (η ie, roughness ir, μ im) within one side's block of a row-major
// [η][roughness][μ] table (the side's block starts at side · n_eta n_r n_mu).
fn ms_lut_index3(ie: u32, ir: u32, im: u32, n_r: u32, n_mu: u32) -> u32 {
    return (ie * n_r + ir) * n_mu + im;
}

// The η coordinate of an interface of relative index η ≥ 1: √((η − 1)/2).
fn ms_lut_eta_coord(eta: f32) -> f32 {
    return sqrt(max(eta - 1.0, 0.0) * 0.5);
}

// The trilinear filter over (η, roughness, μ): node (e.i + b₀, r.i + b₁, m.i + b₂) is lo[b₀ +
// 2b₁] for b₂ = 0 and hi[b₀ + 2b₁] for b₂ = 1 (the η tap the fastest, as `Lut::lookup`'s
// corners), summed in its order with its weights ((w_η) w_r) w_μ. (Two vec4 rather than an
// array: naga's HLSL writes a by-value array's zero initialiser in a form glslang rejects.)
fn ms_lut_trilerp(e: MsLutTap, r: MsLutTap, m: MsLutTap, lo: vec4<f32>, hi: vec4<f32>) -> f32 {
    let we = vec2<f32>(1.0 - e.f, e.f);
    let wr = vec2<f32>(1.0 - r.f, r.f);
    let wm = vec2<f32>(1.0 - m.f, m.f);
    var s = 0.0;
    for (var b = 0u; b < 8u; b++) {
        let v = select(lo[b & 3u], hi[b & 3u], b >= 4u);
        s += we[b & 1u] * wr[(b >> 1u) & 1u] * wm[b >> 2u] * v;
    }
    return s;
}

// The bilinear filter over (η, roughness) of an average table: v[b₀ + 2b₁] the node
// (e.i + b₀, r.i + b₁).
fn ms_lut_bilerp_eta(e: MsLutTap, r: MsLutTap, v: vec4<f32>) -> f32 {
    let we = vec2<f32>(1.0 - e.f, e.f);
    let wr = vec2<f32>(1.0 - r.f, r.f);
    var s = 0.0;
    for (var b = 0u; b < 4u; b++) {
        s += we[b & 1u] * wr[b >> 1u] * v[b];
    }
    return s;
}

// Kulla–Conty's transmitted shares (k_out, k_in) of an interface of relative index η with the
// smooth interface's Fresnel average f_avg = 2∫F(μ)μ dμ from outside (the caller's; the Rust
// type integrates it by Gauss–Legendre) and the sides' averages e_avg = (E_avg,out, E_avg,in).
fn ms_dielectric_kulla_conty_k(eta: f32, f_avg: f32, e_avg: vec2<f32>) -> vec2<f32> {
    let k_out = 1.0 - f_avg;
    var k = vec2<f32>(k_out, k_out * (1.0 - e_avg.x) / (eta * eta * (1.0 - e_avg.y)));
    if !(k.y <= 1.0) {
        // (Also a lossless inside, whose lobes are 0 anyway.)
        k = k * select(0.0, 1.0 / k.y, k.y > 1.0);
    }
    return k;
}

// Kulla–Conty's added f(wo, wi) of the dielectric (the Rust type's `f_ms`): e_o = E_s(|cos θo|)
// of wo's side s, e_i = E_t(|cos θi|) and e_avg_i = E_avg,t of wi's side t, k_o = k_s. 0 on
// the horizon and where nothing is lost.
fn ms_dielectric_kulla_conty_lobe(d: MsDielectric, wo: vec3<f32>, wi: vec3<f32>, e_o: f32,
    e_i: f32, e_avg_i: f32, k_o: f32) -> f32 {
    if !(abs(wo.z) > 0.0 && abs(wi.z) > 0.0) {
        return 0.0;
    }
    let lost = 1.0 - e_o;
    let crossed = (wi.z < 0.0) != (wo.z < 0.0);
    let share = select(1.0 - k_o, k_o, crossed);
    let den = MS_PI * (1.0 - e_avg_i);
    if !(den > 0.0 && lost > 0.0) {
        return 0.0;
    }
    var f = share * lost * max(1.0 - e_i, 0.0) / den;
    if crossed && d.transport == MS_TRANSPORT_RADIANCE {
        let etap = select(1.0 / d.eta, d.eta, wo.z > 0.0);
        f = f / (etap * etap);
    }
    return f;
}

// The Kulla–Conty compensated dielectric's f(wo, wi) without the cosine (grey): the
// single-scattering f plus ms_dielectric_kulla_conty_lobe (a smooth interface as it is).
fn ms_dielectric_eval_kulla_conty(d: MsDielectric, wo: vec3<f32>, wi: vec3<f32>, e_o: f32,
    e_i: f32, e_avg_i: f32, k_o: f32) -> f32 {
    let f = ms_dielectric_eval(d, wo, wi);
    if ms_dielectric_smooth(d) {
        return f;
    }
    return f + ms_dielectric_kulla_conty_lobe(d, wo, wi, e_o, e_i, e_avg_i, k_o);
}

// The Turquin compensated dielectric's f(wo, wi): the single-scattering f over e_o = E_s(μo)
// of wo's side (1 where e_o is not positive).
fn ms_dielectric_eval_turquin(d: MsDielectric, wo: vec3<f32>, wi: vec3<f32>, e_o: f32) -> f32 {
    let f = ms_dielectric_eval(d, wo, wi);
    if ms_dielectric_smooth(d) || !(e_o > 0.0) {
        return f;
    }
    return f / e_o;
}
