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

// microsurface WGSL library: a material's distribution chosen at run time (microfacet.wgsl),
// the WGSL counterpart of the Rust `MicrofacetDistribution` door that the BSDFs use. A
// renderer that knows its NDF calls the per-NDF functions (ms_ggx_d, …) directly.

// Which NDF (`ndf`: an MS_NDF_* constant) at roughness (αx, αy).
struct MsMicrofacet {
    ndf: u32,
    alpha: vec2<f32>,
}

const MS_NDF_GGX: u32 = 0u;

// D(wm); 0 below the horizon (and for an NDF this library does not have).
fn ms_d(mf: MsMicrofacet, wm: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_d(wm, mf.alpha);
    }
    return 0.0;
}

// Smith Λ(w).
fn ms_lambda(mf: MsMicrofacet, w: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_lambda(w, mf.alpha);
    }
    return 0.0;
}

// G1(w).
fn ms_g1(mf: MsMicrofacet, w: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_g1(w, mf.alpha);
    }
    return 0.0;
}

// Height-correlated G2(wo, wi).
fn ms_g2(mf: MsMicrofacet, wo: vec3<f32>, wi: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_g2(wo, wi, mf.alpha);
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
    return 0.0;
}

// A visible normal for w from u ∈ [0, 1)², with its pdf.
fn ms_sample(mf: MsMicrofacet, w: vec3<f32>, u: vec2<f32>) -> MsSample {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_sample(w, mf.alpha, u);
    }
    return MsSample(vec3<f32>(0.0, 0.0, 1.0), 0.0);
}

// A normal distributed as D(m) cos θm, with its pdf.
fn ms_sample_dcos(mf: MsMicrofacet, u: vec2<f32>) -> MsSample {
    if mf.ndf == MS_NDF_GGX {
        return ms_ggx_sample_dcos(mf.alpha, u);
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
