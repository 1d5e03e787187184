// microsurface WGSL library: constants and vector helpers (common.wgsl).
//
// Conventions (the Rust crate's): directions are unit vec3<f32> in the local shading frame,
// z = the shading normal; wo and wi both point away from the surface; roughness is
// vec2<f32>(αx, αy), αx along the frame's tangent. Every public name starts with `ms_` or
// `Ms`/`MS_` (WGSL has no namespaces). WGSL lets an implementation assume that no NaN or
// infinity occurs; the library produces +∞ only where the Rust type does (Λ at grazing), and
// its edge guards are written as the Rust code's (`!(x > 0.0)` is false for NaN there too).

const MS_PI: f32 = 3.14159265358979323846;
const MS_FRAC_1_PI: f32 = 0.318309886183790671538;
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

// The spherical-cap visible normal for the unit w (w.z ≥ 0) with the stretch (αx, αy, sz)
// (roughness (αx, αy)/sz, the same directions up to a common factor), given the length of
// the stretched (αx w.x, αy w.y, sz w.z): a point of the cap z ∈ [−w'.z, 1] about w',
// unstretched (the Rust ggx_visible_stretched_len).
fn ms_ggx_cap_normal_stretched(w: vec3<f32>, stretch: vec3<f32>, u: vec2<f32>, len: f32) -> vec3<f32> {
    let inv = 1.0 / len;
    let x = stretch.x * w.x * inv;
    let y = stretch.y * w.y * inv;
    let z = stretch.z * w.z * inv;
    let cs = ms_cos_sin_turn(u.x);
    // cz + z = (1 − u₁)(1 + z) formed without the cancellation (u₁ → 1); sin² = (1 − cz)
    // (1 + cz) = u₁(above (1 + z) + x² + y²), a sum of positive terms (1 − cz² cancels at
    // the poles, cz → ±1).
    let above = (1.0 - u.y) * (1.0 + z);
    let sin = sqrt(max(u.y * (above * (1.0 + z) + (x * x + y * y)), 0.0));
    let h = vec3<f32>(stretch.x * (sin * cs.x + x), stretch.y * (sin * cs.y + y), stretch.z * above);
    let n = 1.0 / sqrt(h.x * h.x + h.y * h.y + h.z * h.z);
    return h * n;
}

// The spherical-cap visible normal at roughness (αx, αy) (the stretch (αx, αy, 1)).
fn ms_ggx_cap_normal(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>, len: f32) -> vec3<f32> {
    return ms_ggx_cap_normal_stretched(w, vec3<f32>(alpha, 1.0), u, len);
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

// microsurface WGSL library: the fitted tables (tables.wgsl). Generated by
// crates/microsurface-gpu/tools/tables.rs (examples/translate.rs) from the Rust library;
// do not edit.
//
// Every table is in one read-only storage buffer of vec4<f32>, `ms_tables`: the rows of
// generated/microsurface_tables.bin (little-endian f32; `microsurface_gpu::TABLES` in
// Rust), MS_TABLES_ROWS of them, each table from its _AT row. The shader that includes
// the library says where the buffer is bound, by two constants of its own,
//   const MS_TABLES_GROUP: u32 = …;
//   const MS_TABLES_BINDING: u32 = …;
// and binds it there when it calls a function that reads a table (Beckmann, Double
// GGX, the Exponential NDF, and the run-time distribution MsMicrofacet over them).
@group(MS_TABLES_GROUP) @binding(MS_TABLES_BINDING)
var<storage, read> ms_tables: array<vec4<f32>>;

// Beckmann's special functions (beckmann_tables.rs): per segment the degree-7 polynomial in s
// ∈ [−1, 1) (2 vec4, s⁰ first), from the Rust f64 functions of microsurface::fast::beckmann.
const MS_BK_SEGMENTS_LOG2: u32 = 2u;

// erfcx(x) = e^{x²} erfc x on [2^−14, 2^5) (fit error 4.3e-8 relative).
const MS_BK_ERFCX_K0: i32 = -14;
const MS_BK_ERFCX_K1: i32 = 5;
const MS_BK_ERFCX_AT: u32 = 0u; // 152 rows

// r(a) = 1 − √π a erfcx(a) on [2^−14, 2^5) (fit error 5.8e-8 relative).
const MS_BK_ERFC_RATIO_K0: i32 = -14;
const MS_BK_ERFC_RATIO_K1: i32 = 5;
const MS_BK_ERFC_RATIO_AT: u32 = 152u; // 152 rows

// erfinv(1 − q)/(1 − q) on q ∈ [2^−25, 1) (fit error 5.3e-8 relative).
const MS_BK_ERFINV_Q_K0: i32 = -25;
const MS_BK_ERFINV_Q_K1: i32 = 0;
const MS_BK_ERFINV_Q_AT: u32 = 304u; // 200 rows

// erfinv(v)/v as a function of w = −ln(1 − v²) on [2^4, 2^7) (fit error 4.0e-8 relative).
const MS_BK_ERFINV_W_K0: i32 = 4;
const MS_BK_ERFINV_W_K1: i32 = 7;
const MS_BK_ERFINV_W_AT: u32 = 504u; // 24 rows

// e^z K₀(z) on [2^−14, 2^9) (the K0 NDF's profile) (fit error 5.3e-8 relative).
const MS_SF_K0E_K0: i32 = -14;
const MS_SF_K0E_K1: i32 = 9;
const MS_SF_K0E_AT: u32 = 528u; // 184 rows

// e^y E₁(y) on [2^−24, 2^9) (the Ei NDF's profile) (fit error 6.1e-8 relative).
const MS_SF_E1X_K0: i32 = -24;
const MS_SF_E1X_K1: i32 = 9;
const MS_SF_E1X_AT: u32 = 712u; // 264 rows

// erfinv(2u − 1) at u = 2^−1074, where the Rust samplers clamp u = 0.
const MS_BK_QUANTILE_EDGE: f32 = -2.7200563e1;

// Double GGX Λ(x), x = α² tan²θ/2: the Rust DGGX32 (f32 cubics), bit for bit.
const MS_DG_LAMBDA_K0: i32 = -30;
const MS_DG_LAMBDA_K1: i32 = 16;
const MS_DG_LAMBDA_M: u32 = 3u;
const MS_DG_LAMBDA_AT: u32 = 976u; // 368 rows

// Double GGX slope kernel G(1/y), y = tan²θ/α²: the Rust DGGX_D (degree 9, f64) rounded to
// f32 (largest relative change 5.8e-8).
const MS_DG_D_K0: i32 = -30;
const MS_DG_D_K1: i32 = 30;
const MS_DG_D_M: u32 = 2u;
const MS_DG_D_AT: u32 = 1344u; // 720 rows

// Exponential Λ(√q), q = z² < 64: the Rust EXPONENTIAL32_QA (f32 cubics), bit for bit.
const MS_EXP_QA_K0: i32 = -24;
const MS_EXP_QA_K1: i32 = 6;
const MS_EXP_QA_M: u32 = 5u;
const MS_EXP_QA_AT: u32 = 2064u; // 960 rows

// Exponential Λ(√q), 64 ≤ q < 4096: the Rust EXPONENTIAL32_QB (f32 cubics), bit for bit.
const MS_EXP_QB_K0: i32 = 6;
const MS_EXP_QB_K1: i32 = 12;
const MS_EXP_QB_M: u32 = 7u;
const MS_EXP_QB_AT: u32 = 3024u; // 768 rows

// Exponential Λ(z) e^z on octaves of z: the Rust EXPONENTIAL_FAR (degree 6, f64) rounded to
// f32 (largest relative change 4.4e-8).
const MS_EXP_FAR_K0: i32 = 5;
const MS_EXP_FAR_K1: i32 = 9;
const MS_EXP_FAR_M: u32 = 3u;
const MS_EXP_FAR_AT: u32 = 3792u; // 64 rows

// The Exp(1) ziggurat's layers, f(x) = e^{−x} (the Rust ZIG_EXP_X and ZIG_EXP_F, rounded to
// f32): row i = (x_i, f(x_i), x_{i+1}, f(x_{i+1})).
const MS_ZIG_EXP_AT: u32 = 3856u; // 256 rows

// The half-normal ziggurat's layers, f(x) = e^{−x²/2} (the Rust ZIG_NORMAL_X and
// ZIG_NORMAL_F, rounded to f32): row i = (x_i, f(x_i), x_{i+1}, f(x_{i+1})).
const MS_ZIG_NORMAL_AT: u32 = 4112u; // 256 rows

// The buffer's length in rows.
const MS_TABLES_ROWS: u32 = 4368u;

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

// The next uniform of the stream as the Rust f64 draw (the top 53 bits over 2^53, the Rust
// next_uniform::<f64>()) rounded to f32, below 1.
fn ms_stream_next_wide(state: ptr<function, vec2<u32>>) -> f32 {
    let z = ms_stream_next_u64(state);
    let v = f32(z.y) * 2.3283064365386963e-10 + f32(z.x >> 11u) * 1.1102230246251565e-16;
    return min(v, 0.99999994);
}

// A source of uniforms for a rejection sampler: the Rust samplers' closures, on the GPU. `first`
// (u itself) is returned first where `used` < 2, then the stream of u, as f32 draws (the top 24
// bits: the Rust f32 paths' `next_uniform::<f32>`) or, where `wide` is 1, as the f64 draws the
// Rust mixtures' samplers take, rounded to f32 (ms_stream_next_wide).
struct MsSource {
    state: vec2<u32>,
    first: vec2<f32>,
    used: u32,
    wide: u32,
}

// The stream of u alone, f32 draws (Double GGX's and the Exponential NDF's samplers).
fn ms_source_stream(u: vec2<f32>) -> MsSource {
    return MsSource(ms_stream_new(u), u, 2u, 0u);
}

// The stream of u alone, its f64 draws rounded to f32 (the mixtures' D·cos sampler, whose
// warp takes u itself).
fn ms_source_stream_wide(u: vec2<f32>) -> MsSource {
    return MsSource(ms_stream_new(u), u, 2u, 1u);
}

// u's two uniforms, then the stream's f64 draws (the mixtures' posterior sampler).
fn ms_source_after_u(u: vec2<f32>) -> MsSource {
    return MsSource(ms_stream_new(u), u, 0u, 1u);
}

fn ms_source_next(src: ptr<function, MsSource>) -> f32 {
    if (*src).used < 2u {
        let v = select((*src).first.y, (*src).first.x, (*src).used == 0u);
        (*src).used = (*src).used + 1u;
        return v;
    }
    // (Through a local: naga's SPIR-V writer does not take a pointer to the member.)
    var state = (*src).state;
    var v: f32;
    if (*src).wide == 1u {
        v = ms_stream_next_wide(&state);
    } else {
        v = ms_stream_next(&state);
    }
    (*src).state = state;
    return v;
}

// A variate of a ziggurat's density from w ∈ [0, 1) (the Rust fast::ziggurat::sample over
// its generated layers, the rows at `at` of tables.wgsl, in f32): layer i = ⌊256w⌋, x =
// (256w − i)x_i, kept when below x_{i+1}; else the tail (layer 0) or the wedge's height test
// against f(x) (e^{−x}, or e^{−x²/2} where `normal`), with further uniforms from the
// source. The tail beyond r = x₁: r + Exp(1) for e^{−x}; Marsaglia's 1964 method for the
// normal (r + a, a ~ Exp(r), kept when 2b > a², b ~ Exp(1)).
fn ms_zig_sample(at: u32, normal: bool, w: f32, src: ptr<function, MsSource>) -> f32 {
    var y = w * 256.0;
    var k = u32(max(y, 0.0));
    var i = k & 255u;
    var layer = ms_tables[at + i];
    var x = (y - f32(k)) * layer.x;
    if x < layer.z {
        return x;
    }
    // Each pass keeps its candidate with probability ≥ 0.98; the cap (the Rust one) only
    // guarantees termination.
    for (var n = 0; n < 64; n++) {
        if x != x {
            return x;
        }
        if i == 0u {
            let r = layer.z;
            if !normal {
                return r - log(1.0 - ms_source_next(src));
            }
            for (var j = 0; j < 64; j++) {
                let a = -log(1.0 - ms_source_next(src)) / r;
                let b = -log(1.0 - ms_source_next(src));
                if 2.0 * b > a * a {
                    return r + a;
                }
            }
            return r;
        }
        let h = layer.y + ms_source_next(src) * (layer.w - layer.y);
        var f = exp(-x);
        if normal {
            f = exp(-0.5 * x * x);
        }
        if h < f {
            return x;
        }
        y = ms_source_next(src) * 256.0;
        k = u32(y);
        i = k & 255u;
        layer = ms_tables[at + i];
        x = (y - f32(k)) * layer.x;
        if x < layer.z {
            return x;
        }
    }
    return x;
}

// An Exp(1) variate from w ∈ [0, 1) (the Rust fast::ziggurat::exp1; Marsaglia & Tsang 2000).
fn ms_zig_exp1(w: f32, src: ptr<function, MsSource>) -> f32 {
    return ms_zig_sample(MS_ZIG_EXP_AT, false, w, src);
}

// A half-normal variate |Z| from w ∈ [0, 1) (the Rust fast::ziggurat::half_normal).
fn ms_zig_half_normal(w: f32, src: ptr<function, MsSource>) -> f32 {
    return ms_zig_sample(MS_ZIG_NORMAL_AT, true, w, src);
}

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

// microsurface WGSL library: GTR, Burley's generalized Trowbridge–Reitz NDF (gtr.wgsl).
//
// The Rust `Microfacet<f32, Gtr>` (crates/microsurface/src/distribution/microfacet.rs over
// the fast path fast::gtr::FittedGtr; ndf/gtr.rs and sampling/dcos.rs for the formulas), in
// f32. Sources: Burley 2012, "Physically-Based Shading at Disney", appendix B (D, its
// normalisation, the D·cos inversion), and the GTR page of d'Eon's "A Hitchhiker's Guide to
// Multiple Scattering" (the Smith Λ and σ of GTR).
//
//   D(m) = c x^{−γ},  x = sin²θm + α² cos²θm = m.x² + m.y² + (α m.z)²  (0 for m.z ≤ 0)
//   c = (γ − 1)(α² − 1)/(π(1 − α^{2(1−γ)}))  (γ = 1: (α² − 1)/(π ln α²))
//   Λ(w) = ∫_a^∞ (q/a − 1) P2(q) dq, a = cot θ (Smith's, over GTR's slope marginal P2),
//          fitted per (α, γ) (the tables below),  G1 = 1/(1 + Λ),  G2 = 1/(1 + Λo + Λi) or
//          G1 G1
//   D_w(m) = G1(w)(w·m)D(m)/|w.z|
//
// GTR is isotropic at every γ but 2, where it is GGX (anisotropic allowed): there every
// function here calls GGX's with `alpha`, as the Rust type does. Otherwise a material is one
// (α, γ): its table holds α, and `alpha` is not read (pass vec2(α, α), which the door's
// ms_effectively_smooth reads). A material's table (written by the Rust
// `microsurface_gpu::Tables::add_gtr` from the Rust fast path's own FittedGtr) lies in the
// library's buffer `ms_tables` from the material's row `table`:
//   row 0: (γ, α, kind, σ(0)); kind 0: GGX (γ = 2; no further rows), 1: the Λ rows are the
//          Rust f32 cubics (one vec4 each), 2: the Rust f64 rows of Λ (degree 4) rounded to
//          f32 (two vec4 each), 3: the same of ln Λ (large γ: Λ spans decades per row)
//   row 1: (ln c, c, m₀, m₁): Λ ≈ m₀/a − ½ + m₁a below the u table (a = cot θ)
//   row 2: (K₀, K₁, off_u, off_w): Λ ≈ (K₀ + K₁/a²)/a² past the w table; per side the row
//          of t is (bits of t ≫ 18) − off
//   row 3: (2^k0 of the u table, 2^k0 of the w table, Λ rows, 0)
//   rows 4–6: Burley's quantile constants (L = ln α², k = 1 − γ, kL, 1 where e^{kL} passes
//          f32's range), (e^{kL}, e^{kL} − 1, e^{−kL}, e^{−kL} − 1) (saturated at f32's
//          largest), ((e^{kL} − 1)/kL, (e^{−kL} − 1)/(−kL), ln(e^{|kL|} − 1), 1 where e^{−kL}
//          passes f32's range)
//   row 7: (the D·cos envelope's first row, its pieces, the first moment's first row, its
//          pieces), relative to `table`
//   rows 8…: the Λ rows: 32 an octave of t, the u table (t = cos θ < ½) then the w table
//          (t = 1 − cos θ ≤ ½), each a polynomial in s ∈ [−1, 1) (s⁰ first)
//   then the visible sampler's two radial envelopes (below), two vec4 per piece.
//
// Λ: the side's table at t by the bits of t (the Rust lambda32, bit for bit where the Rust
// type has its f32 table), the two-term ends past the tables. D·cos: Burley's closed-form
// inversion for tan²θ, azimuth 2πu₁ (the Rust warp: the same normal for the same u, to f32's
// rounding). Visible normals: the Rust rejection sampler (FittedGtr::sample_visible) over the
// uniform stream of u: the same candidates, so mostly the same normal.

// Rows before a GTR table's Λ rows.
const MS_GTR_HEADER: u32 = 8u;
// f32's largest finite value.
const MS_F32_MAX: f32 = 3.4028235e38;

// Whether the material at `table` is GGX (γ = 2).
fn ms_gtr_is_ggx(table: u32) -> bool {
    return ms_tables[table].z < 0.5;
}

// ln(1 + t) for t > −1 without losing small t (ms_bk_ln_1m at −t): 2 atanh(t/(2 + t)) by
// its series on [−½, 1] (|t/(2 + t)| ≤ ⅓, truncation below 2e-9 relative), log(1 + t)
// outside (1 + t outside [0.5, 2], where the shading language's log is within 3 ulp; inside
// it has an absolute error of 2^−21, which would be all of a small result's digits).
fn ms_gtr_ln_1p(t: f32) -> f32 {
    if t <= 1.0 {
        return ms_bk_ln_1m(-t);
    }
    return log(1.0 + t);
}

// ln v for v > 0, relatively accurate everywhere: ms_gtr_ln_1p(v − 1) on [0.5, 2] (v − 1
// exact there), log(v) outside.
fn ms_gtr_ln(v: f32) -> f32 {
    if v >= 0.5 && v <= 2.0 {
        return ms_gtr_ln_1p(v - 1.0);
    }
    return log(v);
}

// ln(1 + x)/x (1 at x = 0).
fn ms_gtr_ln_1p_over_x(x: f32) -> f32 {
    if x == 0.0 {
        return 1.0;
    }
    return ms_gtr_ln_1p(x) / x;
}

// (e^x − 1)/x (1 at x = 0).
fn ms_gtr_expm1_over_x(x: f32) -> f32 {
    if x == 0.0 {
        return 1.0;
    }
    return ms_expm1(x) / x;
}

// D(wm) (the Rust FittedGtr::d_vec): c/x at γ = 1, else e^{ln c − γ ln x} (one exponential
// for the product, which stays finite where c or x^{−γ} alone would not); D(1) past
// wm.z = 1, 0 on and below the horizon, NaN for NaN.
fn ms_gtr_d(wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    let head = ms_tables[table];
    if head.z < 0.5 {
        return ms_ggx_d(wm, alpha);
    }
    let z = wm.z;
    if !(z > 0.0) {
        return select(0.0, z, z != z);
    }
    let a = head.y;
    var x = a * a;
    if z <= 1.0 {
        let az = a * z;
        x = wm.x * wm.x + wm.y * wm.y + az * az;
    }
    let norm = ms_tables[table + 1u];
    if head.x == 1.0 {
        return norm.y / x;
    }
    return exp(norm.x - head.x * log(x));
}

// Λ past the tables at a = cot θ (the Rust lambda_cot_ends, which the Rust f32 path reaches
// through its f64 lambda_cot): the grazing end m₀/a − ½ + m₁a for a < 1 (+∞ at a = 0), else
// (K₀ + K₁ r²) r² with r² = 1/a² (0 at a = +∞, the normal); NaN for NaN.
fn ms_gtr_lambda_cot_ends(table: u32, a: f32) -> f32 {
    if a != a {
        return a;
    }
    if a < 1.0 {
        let m = ms_tables[table + 1u];
        return m.z / a - 0.5 + m.w * a;
    }
    let k = ms_tables[table + 2u];
    let r2 = 1.0 / (a * a);
    return (k.x + k.y * r2) * r2;
}

// Smith Λ(w), Λ(−w) = Λ(w), for w of any length (the Rust FittedGtr::lambda_vec in f32):
// cos θ = u = |z|/n, n = √(s² + z²), s² = x² + y²; the u table below u = ½, the w table at
// t = 1 − u = s²/(n(n + |z|)) from there (formed from the vector: 1 − u of a rounded unit
// vector has lost its digits near the normal), by t's bits (row and position s), then the
// row's polynomial by Horner's rule (exp of it where the rows hold ln Λ); past the tables
// the ends at cot θ = |z|/s. +∞ on the horizon, 0 at the normal.
fn ms_gtr_lambda(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    if ms_gtr_is_ggx(table) {
        return ms_ggx_lambda(w, alpha);
    }
    let head = ms_tables[table];
    let lay = ms_tables[table + 2u];
    let lim = ms_tables[table + 3u];
    let z = abs(w.z);
    let s2 = w.x * w.x + w.y * w.y;
    let n = sqrt(s2 + z * z);
    let u = z / n;
    var t = u;
    var off = lay.z;
    var lo = lim.x;
    if u >= 0.5 {
        t = s2 / (n * (n + z));
        off = lay.w;
        lo = lim.y;
    }
    // (False for NaN.)
    if t >= lo {
        let bits = bitcast<u32>(t);
        let row = u32(clamp(i32(bits >> 18u) - i32(off), 0, i32(lim.z) - 1));
        let s = bitcast<f32>(0x40000000u | ((bits << 14u) >> 9u)) - 3.0;
        if head.z < 1.5 {
            return ms_fam_cubic(ms_tables[table + MS_GTR_HEADER + row], s);
        }
        let i = table + MS_GTR_HEADER + 2u * row;
        let c = ms_tables[i];
        let c4 = ms_tables[i + 1u].x;
        let p = (((c4 * s + c.w) * s + c.z) * s + c.y) * s + c.x;
        if head.z < 2.5 {
            return p;
        }
        return exp(p);
    }
    return ms_gtr_lambda_cot_ends(table, z / sqrt(s2));
}

// G1(w).
fn ms_gtr_g1(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return 1.0 / (1.0 + ms_gtr_lambda(w, alpha, table));
}

// Height-correlated G2(wo, wi).
fn ms_gtr_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return 1.0 / (1.0 + (ms_gtr_lambda(wo, alpha, table) + ms_gtr_lambda(wi, alpha, table)));
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_gtr_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_gtr_g1(wo, alpha, table) * ms_gtr_g1(wi, alpha, table);
}

// The visible-normal density D_w(wm) = G1(w)(w·wm)D(wm)/|w.z|; w.z < 0 mirrored; 0 at grazing
// w and for wm facing away from w (GGX's closed form at γ = 2).
fn ms_gtr_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    if ms_gtr_is_ggx(table) {
        return ms_ggx_pdf(w, wm, alpha);
    }
    let z = abs(w.z);
    var c = ms_dot(w, wm);
    if w.z < 0.0 {
        c = -c;
    }
    if !(c > 0.0 && z > 0.0) {
        return select(0.0, c, c != c);
    }
    return ms_gtr_g1(w, alpha, table) * c * ms_gtr_d(wm, alpha, table) / z;
}

// The density of ms_gtr_sample_dcos: D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_gtr_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_gtr_d(wm, alpha, table) * wm.z;
}

// ln(1 + f(e^{±kL} − 1)) (the Rust Burley::tan2's ln_pos_sum) for f ∈ [0, 1], given
// e^{±kL} − 1 (`minus_one`), the sum 1 + f(e^{±kL} − 1) as two positive terms (`sum`), and
// whether e^{±kL} passes f32's range (`over`: then from its logarithm, ln f + ln(e^{|kL|} −
// 1), for every f: ln(1 + eˢ) = s + ln(1 + e^{−s}), or ln(1 + eˢ) below s = 0).
fn ms_gtr_ln_pos_sum(f: f32, minus_one: f32, sum: f32, over: bool, ln_em1_abs: f32) -> f32 {
    if over {
        let s = ms_gtr_ln(f) + ln_em1_abs;
        if s > 0.0 {
            return s + ms_gtr_ln_1p(exp(-s));
        }
        return ms_gtr_ln_1p(exp(s));
    }
    let y = f * minus_one;
    if abs(y) < 0.5 {
        return ms_gtr_ln_1p(y);
    }
    return ms_gtr_ln(sum);
}

// tan²θ at the slope CDF's quantile ξ ∈ (0, 1) (the Rust Burley::tan2, Burley 2012 appendix
// B eqs. 3–9, for ℓ = ln w and k = 1 − γ: e^{kℓ} = (1 − ξ)e^{kL} + ξ, e^{k(ℓ − L)} = (1 − ξ) +
// ξe^{−kL}, tan²θ = e^ℓ expm1(L − ℓ)/expm1(ℓ)); near γ = 1 or α = 1 (|kL| < ½) with L divided
// out analytically.
fn ms_gtr_tan2(table: u32, xi: f32) -> f32 {
    let b0 = ms_tables[table + 4u];
    let b1 = ms_tables[table + 5u];
    let b2 = ms_tables[table + 6u];
    let l = b0.x;
    let k = b0.y;
    let kl = b0.z;
    let f = 1.0 - xi;
    if abs(kl) < 0.5 {
        let ell_over_l = f * b2.x * ms_gtr_ln_1p_over_x(f * b1.y);
        let rest_over_l = xi * b2.y * ms_gtr_ln_1p_over_x(xi * b1.w);
        let ell = ell_over_l * l;
        let rest = rest_over_l * l;
        return exp(ell) * (rest_over_l / ell_over_l) * ms_gtr_expm1_over_x(rest)
            / ms_gtr_expm1_over_x(ell);
    }
    let ell = ms_gtr_ln_pos_sum(f, b1.y, f * b1.x + xi, b0.w > 0.5, b2.z) / k;
    let rest = -ms_gtr_ln_pos_sum(xi, b1.w, f + xi * b1.z, b2.w > 0.5, b2.z) / k;
    return exp(ell) * ms_expm1(rest) / ms_expm1(ell);
}

// A normal distributed as D(m) cos θm with its pdf (the Rust FittedGtr::sample_dcos): tan θ
// = √tan²θ(u₀) (0 at u₀ ≤ 0, ∞ at u₀ ≥ 1), azimuth 2πu₁, m ∝ (r cos φ, r sin φ, 1), or
// divided by r past r = 1 (the Rust normal_from_polar). GGX's at γ = 2.
fn ms_gtr_sample_dcos(alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    if ms_gtr_is_ggx(table) {
        return ms_ggx_sample_dcos(alpha, u);
    }
    let xi = u.x;
    var r = xi;
    if xi <= 0.0 {
        r = 0.0;
    } else if xi >= 1.0 {
        r = ms_inf();
    } else if xi == xi {
        r = sqrt(ms_gtr_tan2(table, xi));
    }
    let cs = ms_cos_sin_turn(u.y);
    var v: vec3<f32>;
    if r > 1.0 {
        v = vec3<f32>(cs.x, cs.y, 1.0 / r);
    } else {
        v = vec3<f32>(r * cs.x, r * cs.y, 1.0);
    }
    let wm = ms_unit_normal(v);
    return MsSample(wm, ms_gtr_pdf_dcos(wm, alpha, table));
}

// The visible sampler's radial envelopes (the Rust vndf.rs `Radial`): an exact sampler of
// GTR's radial slope density in t = ln r², p(t) ∝ e^{φ(t)},
//   φ(t) = k t + (γ − 2) ln(1 + eᵗ) − γ ln(α² + eᵗ)
// (k = 1: D·cos slopes; k = 3/2: their first moment), by rejection from a piecewise
// envelope whose pieces an alias table picks. Each piece is two vec4:
//   finite piece: A = (r₀, dr, s₀, s₁), B = (h, the column's prob, its alias, 0): the
//     candidate r = r₀ + v dr is kept without φ when keep ≤ s₀ + s₁v (the squeeze), else
//     when keep ≤ e^{φ(t) − t/2 − h};
//   tail (the first and the last piece): A = (a, β, e, squeeze), B = (e^{βw} − 1 (−1), prob,
//     alias, 1): t = a + ln(1 + v(e^{βw} − 1))/β, kept below the squeeze, else when keep ≤
//     e^{φ(t) − e − β(t − a)}.
// (h and e hold the Rust envelope's maximum `top` added in: the density's scale.)

// φ(t) at x = eᵗ = r² of the envelope with power k.
fn ms_gtr_phi(k: f32, gamma: f32, a2: f32, t: f32, x: f32) -> f32 {
    return k * t + (gamma - 2.0) * ms_gtr_ln_1p(x) - gamma * log(a2 + x);
}

// The alias table's column of v ∈ [0, 1] among n: (⌊vn⌋ (at most n − 1), vn less it), the
// product formed exactly (v's 24-bit significand times n, a 64-bit integer) and the fraction
// rounded once, as the Rust f64 product is exact: an f32 product would round away up to
// log₂ n of the fraction's bits, the position within the piece.
fn ms_gtr_column(v: f32, n: u32) -> vec2<f32> {
    let b = bitcast<u32>(v);
    let e = (b >> 23u) & 0xffu;
    var i = 0u;
    var frac = v * f32(n);
    // v = significand · 2^−shift; shift ≥ 64 leaves vn below 2^−40 (i = 0, the product's
    // rounding relative); zero, subnormal and non-finite v as the f32 product.
    if e > 0u && e < 255u && 150u - e < 64u {
        let shift = 150u - e;
        let p = ms_u32_mul_wide((b & 0x7fffffu) | 0x800000u, n);
        // 2^−shift (a normal f32 for shift < 127; ldexp's exponent operand does not
        // translate to HLSL).
        let scale = bitcast<f32>((127u - shift) << 23u);
        if shift < 32u {
            i = (p.x >> shift) | (p.y << (32u - shift));
            frac = f32(p.x & ((1u << shift) - 1u)) * scale;
        } else {
            let s = shift - 32u;
            i = p.y >> s;
            let hi = p.y & ((1u << s) - 1u);
            frac = (f32(hi) * 4294967296.0 + f32(p.x)) * scale;
        }
    }
    if i > n - 1u {
        frac = frac + f32(i - (n - 1u));
        i = n - 1u;
    }
    return vec2<f32>(f32(i), frac);
}

// A radius from the envelope of power k (its pieces at row `at`, n of them) from v (the
// column of the alias table from its integer part, the piece and the position within it
// from the fraction), with 1 where `keep` (uniform in [0, 1)) lies below the density's ratio
// to the envelope, else 0 (the Rust Radial::radius and radius_slow: the position v₂ within
// the piece is the fraction's, r and the squeeze affine in it).
fn ms_gtr_radius(table: u32, at: u32, n: u32, k: f32, v: f32, keep: f32) -> vec2<f32> {
    let col = ms_gtr_column(v, n);
    let i = u32(col.x);
    let frac = col.y;
    let own = ms_tables[at + 2u * i + 1u];
    var j = i;
    var v2 = frac / own.y;
    if !(frac < own.y) {
        j = u32(own.z);
        v2 = (frac - own.y) / (1.0 - own.y);
    }
    v2 = min(v2, 1.0);
    let pa = ms_tables[at + 2u * j];
    let pb = ms_tables[at + 2u * j + 1u];
    let head = ms_tables[table];
    let a2 = head.y * head.y;
    if pb.w < 0.5 {
        let r = pa.x + v2 * pa.y;
        if keep <= pa.z + pa.w * v2 {
            return vec2<f32>(r, 1.0);
        }
        let x = r * r;
        let t = log(x);
        let ratio = exp(ms_gtr_phi(k, head.x, a2, t, x) - 0.5 * t - pb.x);
        return vec2<f32>(r, select(0.0, 1.0, keep <= ratio));
    }
    let t = pa.x + ms_gtr_ln_1p(v2 * pb.x) / pa.y;
    let r = exp(0.5 * t);
    if keep <= pa.w {
        return vec2<f32>(r, 1.0);
    }
    let ratio = exp(ms_gtr_phi(k, head.x, a2, t, r * r) - (pa.z + pa.y * (t - pa.x)));
    return vec2<f32>(r, select(0.0, 1.0, keep <= ratio));
}

// A visible normal for w (w.z < 0 mirrored) from u (the Rust FittedGtr::sample_visible): in
// w's slope frame (w = (s cos φ, s sin φ, c)) the visible slopes have the density (c + sx)⁺
// P22, drawn from the envelope c + s x⁺ in two parts: c P22 (mass c; D·cos slopes, the
// azimuth uniform, a candidate with x < 0 kept with probability (c + s x)/c) and s x⁺ P22
// (mass s σ(0): the first-moment radius, an azimuth with density ∝ cos⁺: sin ψ uniform). u
// drives the first candidate (u₀ the part and the azimuth, u₁ the radius), the stream of u
// the keep tests and the later candidates, in the Rust order. At most 64 candidates (each
// kept with probability above 0.49).
fn ms_gtr_sample_wm(w: vec3<f32>, u: vec2<f32>, table: u32) -> vec3<f32> {
    let head = ms_tables[table];
    let env = ms_tables[table + 7u];
    var sign = 1.0;
    if w.z < 0.0 {
        sign = -1.0;
    }
    let sx = sign * w.x;
    let sy = sign * w.y;
    let c = sign * w.z;
    let s = sqrt(sx * sx + sy * sy);
    if !(c + s <= MS_F32_MAX) {
        return vec3<f32>(bitcast<f32>(0x7fc00000u));
    }
    var cp = 1.0;
    var sp = 0.0;
    if s != 0.0 {
        cp = sx / s;
        sp = sy / s;
    }
    let e = c;
    let g = s * head.w;
    let total = e + g;
    // (Capped: at grazing w or normal incidence a mass is 0 and its reciprocal infinite;
    // the capped products stay in [0, 1) where they are used.)
    let inv_p = min(total / e, MS_F32_MAX);
    let inv_g = min(1.0 / g, MS_F32_MAX);
    var state = ms_stream_new(u);
    var v0 = u.x;
    var v1 = u.y;
    // The candidate's radius and its unit azimuth (dx, dy) in the slope frame.
    var dx = 1.0;
    var dy = 0.0;
    var radius = 0.0;
    for (var n = 0; n < 64; n++) {
        if n > 0 {
            v0 = ms_stream_next(&state);
            v1 = ms_stream_next(&state);
        }
        // d = v₀(e + g) − e, the part's boundary, as v₀g − (1 − v₀)e (1 − v₀ exact near 1):
        // its rounding then stays within ε of g, where v₀(e + g) − e would leave ε(e + g),
        // all of a small g's digits at normal incidence (the first moment's azimuth below
        // reads them).
        let d = v0 * g - (1.0 - v0) * e;
        let first = d < 0.0;
        let keep = ms_stream_next(&state);
        var rr: vec2<f32>;
        if first {
            rr = ms_gtr_radius(table, table + u32(env.x), u32(env.y), 1.0, v1, keep);
        } else {
            rr = ms_gtr_radius(table, table + u32(env.z), u32(env.w), 1.5, v1, keep);
        }
        if rr.y < 0.5 {
            continue;
        }
        let r = rr.x;
        radius = r;
        if first {
            let turn = v0 * inv_p;
            let cs = ms_cos_sin_turn(turn);
            dx = cs.x;
            dy = cs.y;
            // x ≥ 0 read from the turn itself; else the stream's next uniform decides.
            if abs(turn - 0.5) >= 0.25 {
                break;
            }
            if ms_stream_next(&state) * c <= c + s * (r * dx) {
                break;
            }
        } else {
            // sin ψ = 2d/g − 1, uniform; cos ψ = √((1 − sin ψ)(1 + sin ψ)) from 1 + sin ψ =
            // 2(v₀ − ω) and 1 − sin ψ = 2((1 − v₀) + ω), ω = (1 − v₀)e/g, and sin ψ from
            // whichever of them is the smaller, not from a rounded sin ψ: near ψ = ±90° that
            // would leave cos ψ about √ε of its digits in f32 (the Rust f64 arithmetic keeps
            // them).
            let omega = (1.0 - v0) * e * inv_g;
            let plus = 2.0 * (v0 - omega);
            let minus = 2.0 * ((1.0 - v0) + omega);
            dx = sqrt(max(minus * plus, 0.0));
            dy = select(1.0 - minus, plus - 1.0, plus < 1.0);
            break;
        }
    }
    // The slopes r(dx, dy) rotated back to w's azimuth: m ∝ (r p, r q, 1), or (p, q, 1/r)
    // past r = 1 (no overflow up to r = ∞), normalised.
    let p = cp * dx - sp * dy;
    let q = sp * dx + cp * dy;
    var v = vec3<f32>(radius * p, radius * q, 1.0);
    if radius > 1.0 {
        v = vec3<f32>(p, q, 1.0 / radius);
    }
    return ms_facing(ms_unit_normal(v), w);
}

// A visible normal for w (w.z < 0 mirrored) from u, with its pdf (at w normalised); GGX's
// spherical caps at γ = 2.
fn ms_gtr_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    if ms_gtr_is_ggx(table) {
        return ms_ggx_sample(w, alpha, u);
    }
    let wm = ms_gtr_sample_wm(w, u, table);
    return MsSample(wm, ms_gtr_pdf(ms_unit(w), wm, alpha, table));
}

// microsurface WGSL library: the Ei NDF, anisotropic (ei.wgsl).
//
// The Rust `Microfacet<f32, Ei>` (crates/microsurface/src/fast/fitted.rs, the family's fast
// path; ndf/ei.rs for the formulas: the Ei_NDF page of d'Eon's "A Hitchhiker's Guide to
// Multiple Scattering"), in f32. A uniform superposition of Beckmann NDFs over roughness² ∈ (0, α²].
// Its Λ₁ lives in a shape table (mixture.wgsl; `microsurface_gpu::Tables::add_shape(NdfKind::
// Ei, None)` in Rust, one table for every roughness: the NDF is shape invariant).
//
//   D(m) = f₁(r)/(αx αy z⁴),  f₁(r) = E₁(r²)/π  (e^y E₁(y) from the MS_SF_E1X table)
//   Λ(w) = Λ₁(cot θ/α̃) from the table,  G1 = 1/(1 + Λ),  G2 = 1/(1 + Λo + Λi) or G1 G1
//
// D·cos and visible normals: exact samplers over the mixture (ms_mixture_sample_dcos_wm: β
// from the prior, then Beckmann's D·cos warp; ms_mixture_sample_wm: the posterior, then
// Beckmann's stream sampler), the Rust samplers' distributions, not their normals.

// ln f₁ at r: ln(e^y E₁(y)) − y − ln π, y = r²; below y = 2^−24, e^y E₁(y) = −γ_E − 2 ln r
// (from r: y itself may leave f32's normals).
fn ms_ei_ln_profile(r: f32) -> f32 {
    let y = r * r;
    if y < 5.9604645e-8 {
        return log(-MS_EULER_GAMMA - 2.0 * log(r)) - y - log(MS_PI);
    }
    return log(ms_e1x(y)) - y - log(MS_PI);
}

// ln D(wm) for wm above the horizon (−1e30, D = 0, on and below it; NaN for NaN), +1e30 (D = +∞) at the pole (r = 0).
fn ms_ei_ln_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return select(-1e30, wm.z, wm.z != wm.z);
    }
    let r = ms_mixture_r(wm, alpha);
    if r == 0.0 {
        return 1e30;
    }
    return ms_mixture_ln_d(ms_ei_ln_profile(r), wm, alpha);
}

// D(wm); 0 on and below the horizon, +∞ at the pole, NaN for NaN.
fn ms_ei_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let ln_d = ms_ei_ln_d(wm, alpha);
    if ln_d >= 1e30 {
        return ms_inf();
    }
    return exp(ln_d);
}

// Smith Λ(w), Λ(−w) = Λ(w), from the shape table at `table`.
fn ms_ei_lambda(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_shape_lambda(table, w, alpha);
}

// G1(w).
fn ms_ei_g1(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g1(table, w, alpha);
}

// Height-correlated G2(wo, wi).
fn ms_ei_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2(table, wo, wi, alpha);
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_ei_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2_separable(table, wo, wi, alpha);
}

// The visible-normal density D_w(wm) (w.z < 0 mirrored).
fn ms_ei_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_pdf(table, w, wm, alpha, ms_ei_ln_d(wm, alpha));
}

// The D·cos density D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_ei_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_ei_d(wm, alpha) * wm.z;
}

// A D·cos normal from u, with its pdf.
fn ms_ei_sample_dcos(alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_dcos_wm(table, alpha, u);
    return MsSample(wm, ms_ei_pdf_dcos(wm, alpha));
}

// A visible normal for w (w.z < 0 mirrored) from u, with its pdf.
fn ms_ei_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_wm(table, w, alpha, u);
    return MsSample(wm, ms_ei_pdf(ms_unit(w), wm, alpha, table));
}

// microsurface WGSL library: the Erfc NDF, anisotropic (erfc.wgsl).
//
// The Rust `Microfacet<f32, Erfc>` (crates/microsurface/src/fast/fitted.rs, the family's fast
// path; ndf/erfc.rs for the formulas: the Erfc_NDF page of d'Eon's "A Hitchhiker's Guide to
// Multiple Scattering"), in f32. A uniform superposition of Beckmann NDFs over roughness ∈ (0, α].
// Its Λ₁ lives in a shape table (mixture.wgsl; `microsurface_gpu::Tables::add_shape(NdfKind::
// Erfc, None)` in Rust, one table for every roughness: the NDF is shape invariant).
//
//   D(m) = f₁(r)/(αx αy z⁴),  f₁(r) = erfc(r)/(2√π r)  (erfc = erfcx e^{−r²}, erfcx from Beckmann's table)
//   Λ(w) = Λ₁(cot θ/α̃) from the table,  G1 = 1/(1 + Λ),  G2 = 1/(1 + Λo + Λi) or G1 G1
//
// D·cos and visible normals: exact samplers over the mixture (ms_mixture_sample_dcos_wm: β
// from the prior, then Beckmann's D·cos warp; ms_mixture_sample_wm: the posterior, then
// Beckmann's stream sampler), the Rust samplers' distributions, not their normals.

// ln f₁ at r: ln(erfcx(r)/(2√π r)) − r².
fn ms_erfc_ln_profile(r: f32) -> f32 {
    return log(ms_bk_erfcx(r) / (2.0 * MS_SQRT_PI * r)) - r * r;
}

// ln D(wm) for wm above the horizon (−1e30, D = 0, on and below it; NaN for NaN), +1e30 (D = +∞) at the pole (r = 0).
fn ms_erfc_ln_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return select(-1e30, wm.z, wm.z != wm.z);
    }
    let r = ms_mixture_r(wm, alpha);
    if r == 0.0 {
        return 1e30;
    }
    return ms_mixture_ln_d(ms_erfc_ln_profile(r), wm, alpha);
}

// D(wm); 0 on and below the horizon, +∞ at the pole, NaN for NaN.
fn ms_erfc_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let ln_d = ms_erfc_ln_d(wm, alpha);
    if ln_d >= 1e30 {
        return ms_inf();
    }
    return exp(ln_d);
}

// Smith Λ(w), Λ(−w) = Λ(w), from the shape table at `table`.
fn ms_erfc_lambda(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_shape_lambda(table, w, alpha);
}

// G1(w).
fn ms_erfc_g1(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g1(table, w, alpha);
}

// Height-correlated G2(wo, wi).
fn ms_erfc_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2(table, wo, wi, alpha);
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_erfc_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2_separable(table, wo, wi, alpha);
}

// The visible-normal density D_w(wm) (w.z < 0 mirrored).
fn ms_erfc_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_pdf(table, w, wm, alpha, ms_erfc_ln_d(wm, alpha));
}

// The D·cos density D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_erfc_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_erfc_d(wm, alpha) * wm.z;
}

// A D·cos normal from u, with its pdf.
fn ms_erfc_sample_dcos(alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_dcos_wm(table, alpha, u);
    return MsSample(wm, ms_erfc_pdf_dcos(wm, alpha));
}

// A visible normal for w (w.z < 0 mirrored) from u, with its pdf.
fn ms_erfc_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_wm(table, w, alpha, u);
    return MsSample(wm, ms_erfc_pdf(ms_unit(w), wm, alpha, table));
}

// microsurface WGSL library: the K0 NDF, anisotropic (k0.wgsl).
//
// The Rust `Microfacet<f32, K0>` (crates/microsurface/src/fast/fitted.rs, the family's fast
// path; ndf/k0.rs for the formulas: the K0_NDF page of d'Eon's "A Hitchhiker's Guide to
// Multiple Scattering"), in f32. The Gamma(1) superposition of Beckmann NDFs over roughness α√t.
// Its Λ₁ lives in a shape table (mixture.wgsl; `microsurface_gpu::Tables::add_shape(NdfKind::
// K0, None)` in Rust, one table for every roughness: the NDF is shape invariant).
//
//   D(m) = f₁(r)/(αx αy z⁴),  f₁(r) = 2K₀(2r)/π  (e^z K₀(z) from the MS_SF_K0E table)
//   Λ(w) = Λ₁(cot θ/α̃) from the table,  G1 = 1/(1 + Λ),  G2 = 1/(1 + Λo + Λi) or G1 G1
//
// D·cos and visible normals: exact samplers over the mixture (ms_mixture_sample_dcos_wm: β
// from the prior, then Beckmann's D·cos warp; ms_mixture_sample_wm: the posterior, then
// Beckmann's stream sampler), the Rust samplers' distributions, not their normals.

// ln f₁ at r: ln(2 e^z K₀(z)/π) − z, z = 2r.
fn ms_k0_ln_profile(r: f32) -> f32 {
    let z = 2.0 * r;
    return log(2.0 * ms_k0e(z) / MS_PI) - z;
}

// ln D(wm) for wm above the horizon (−1e30, D = 0, on and below it; NaN for NaN), +1e30 (D = +∞) at the pole (r = 0).
fn ms_k0_ln_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return select(-1e30, wm.z, wm.z != wm.z);
    }
    let r = ms_mixture_r(wm, alpha);
    if r == 0.0 {
        return 1e30;
    }
    return ms_mixture_ln_d(ms_k0_ln_profile(r), wm, alpha);
}

// D(wm); 0 on and below the horizon, +∞ at the pole, NaN for NaN.
fn ms_k0_d(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let ln_d = ms_k0_ln_d(wm, alpha);
    if ln_d >= 1e30 {
        return ms_inf();
    }
    return exp(ln_d);
}

// Smith Λ(w), Λ(−w) = Λ(w), from the shape table at `table`.
fn ms_k0_lambda(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_shape_lambda(table, w, alpha);
}

// G1(w).
fn ms_k0_g1(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g1(table, w, alpha);
}

// Height-correlated G2(wo, wi).
fn ms_k0_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2(table, wo, wi, alpha);
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_k0_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_g2_separable(table, wo, wi, alpha);
}

// The visible-normal density D_w(wm) (w.z < 0 mirrored).
fn ms_k0_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_mixture_pdf(table, w, wm, alpha, ms_k0_ln_d(wm, alpha));
}

// The D·cos density D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_k0_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_k0_d(wm, alpha) * wm.z;
}

// A D·cos normal from u, with its pdf.
fn ms_k0_sample_dcos(alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_dcos_wm(table, alpha, u);
    return MsSample(wm, ms_k0_pdf_dcos(wm, alpha));
}

// A visible normal for w (w.z < 0 mirrored) from u, with its pdf.
fn ms_k0_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    let wm = ms_mixture_sample_wm(table, w, alpha, u);
    return MsSample(wm, ms_k0_pdf(ms_unit(w), wm, alpha, table));
}

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

// microsurface WGSL library: a material's distribution chosen at run time (microfacet.wgsl),
// the WGSL counterpart of the Rust `MicrofacetDistribution` door that the BSDFs use. A
// renderer that knows its NDF calls the per-NDF functions (ms_ggx_d, …) directly.

// Which NDF (`ndf`: an MS_NDF_* constant) at roughness (αx, αy), and for an NDF with a
// table of its own (a shape table: Student-T, Ei, Erfc, K0, Bessel-K; GTR's material table)
// the table's first row in `ms_tables` (`microsurface_gpu::Tables::add_shape` or `add_gtr`
// gives it; 0 and unused for the others). Every NDF but GGX reads the library's buffer
// (tables.wgsl), so a shader that takes this door binds it. GTR's α is its table's (αx = αy
// = α; at γ = 2, GGX's, any (αx, αy)).
struct MsMicrofacet {
    ndf: u32,
    alpha: vec2<f32>,
    table: u32,
}

const MS_NDF_GGX: u32 = 0u;
const MS_NDF_BECKMANN: u32 = 1u;
const MS_NDF_DOUBLE_GGX: u32 = 2u;
const MS_NDF_EXPONENTIAL: u32 = 3u;
const MS_NDF_GTR: u32 = 4u;
const MS_NDF_STUDENT_T: u32 = 5u;
const MS_NDF_EI: u32 = 6u;
const MS_NDF_ERFC: u32 = 7u;
const MS_NDF_K0: u32 = 8u;
const MS_NDF_BESSEL_K: u32 = 9u;

// The NDFs this pipeline's door may meet, one bit each (1 << MS_NDF_*): a pipeline-overridable
// constant, every NDF by default. A shader whose materials use a few NDFs sets it when it
// creates its pipeline (wgpu: `compilation_options.constants`, "MS_DOOR_NDFS"), and the
// compiler drops the other NDFs' code from the door: every NDF inlined into every kernel costs
// registers and code size even where its branch is never taken (BENCHMARKS.md). A material of
// an NDF outside the mask meets the door's default answers (D = 0, …).
override MS_DOOR_NDFS: u32 = 0xffffffffu;

fn ms_door_has(ndf: u32) -> bool {
    return (MS_DOOR_NDFS & (1u << ndf)) != 0u;
}

// D(wm); 0 below the horizon (and for an NDF this library does not have).
fn ms_d(mf: MsMicrofacet, wm: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_d(wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_d(wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_d(wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_d(wm, mf.alpha, mf.table);
    }
    return 0.0;
}

// Smith Λ(w).
fn ms_lambda(mf: MsMicrofacet, w: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_lambda(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_lambda(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_lambda(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_lambda(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_lambda(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_lambda(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_lambda(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_lambda(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_lambda(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_lambda(w, mf.alpha, mf.table);
    }
    return 0.0;
}

// G1(w).
fn ms_g1(mf: MsMicrofacet, w: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_g1(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_g1(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_g1(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_g1(w, mf.alpha);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_g1(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_g1(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_g1(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_g1(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_g1(w, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_g1(w, mf.alpha, mf.table);
    }
    return 0.0;
}

// Height-correlated G2(wo, wi).
fn ms_g2(mf: MsMicrofacet, wo: vec3<f32>, wi: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_g2(wo, wi, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_g2(wo, wi, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_g2(wo, wi, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_g2(wo, wi, mf.alpha);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_g2(wo, wi, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_g2(wo, wi, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_g2(wo, wi, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_g2(wo, wi, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_g2(wo, wi, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_g2(wo, wi, mf.alpha, mf.table);
    }
    return 0.0;
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_g2_separable(mf: MsMicrofacet, wo: vec3<f32>, wi: vec3<f32>) -> f32 {
    return ms_g1(mf, wo) * ms_g1(mf, wi);
}

// The visible-normal density D_w(wm).
fn ms_pdf(mf: MsMicrofacet, w: vec3<f32>, wm: vec3<f32>) -> f32 {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_pdf(w, wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_pdf(w, wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_pdf(w, wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_pdf(w, wm, mf.alpha);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_pdf(w, wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_pdf(w, wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_pdf(w, wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_pdf(w, wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_pdf(w, wm, mf.alpha, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_pdf(w, wm, mf.alpha, mf.table);
    }
    return 0.0;
}

// The D·cos density D(wm) cos θm (0 for wm.z ≤ 0): the density of ms_sample_dcos.
fn ms_pdf_dcos(mf: MsMicrofacet, wm: vec3<f32>) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_d(mf, wm) * wm.z;
}

// A visible normal for w from u ∈ [0, 1)², with its pdf.
fn ms_sample(mf: MsMicrofacet, w: vec3<f32>, u: vec2<f32>) -> MsSample {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_sample(w, mf.alpha, u);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_sample(w, mf.alpha, u);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_sample(w, mf.alpha, u);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_sample(w, mf.alpha, u);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_sample(w, mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_sample(w, mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_sample(w, mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_sample(w, mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_sample(w, mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_sample(w, mf.alpha, u, mf.table);
    }
    return MsSample(vec3<f32>(0.0, 0.0, 1.0), 0.0);
}

// A normal distributed as D(m) cos θm, with its pdf.
fn ms_sample_dcos(mf: MsMicrofacet, u: vec2<f32>) -> MsSample {
    if mf.ndf == MS_NDF_GGX && ms_door_has(MS_NDF_GGX) {
        return ms_ggx_sample_dcos(mf.alpha, u);
    }
    if mf.ndf == MS_NDF_BECKMANN && ms_door_has(MS_NDF_BECKMANN) {
        return ms_beckmann_sample_dcos(mf.alpha, u);
    }
    if mf.ndf == MS_NDF_DOUBLE_GGX && ms_door_has(MS_NDF_DOUBLE_GGX) {
        return ms_double_ggx_sample_dcos(mf.alpha, u);
    }
    if mf.ndf == MS_NDF_EXPONENTIAL && ms_door_has(MS_NDF_EXPONENTIAL) {
        return ms_exponential_sample_dcos(mf.alpha, u);
    }
    if mf.ndf == MS_NDF_STUDENT_T && ms_door_has(MS_NDF_STUDENT_T) {
        return ms_student_t_sample_dcos(mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_EI && ms_door_has(MS_NDF_EI) {
        return ms_ei_sample_dcos(mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_ERFC && ms_door_has(MS_NDF_ERFC) {
        return ms_erfc_sample_dcos(mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_K0 && ms_door_has(MS_NDF_K0) {
        return ms_k0_sample_dcos(mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_BESSEL_K && ms_door_has(MS_NDF_BESSEL_K) {
        return ms_bessel_k_sample_dcos(mf.alpha, u, mf.table);
    }
    if mf.ndf == MS_NDF_GTR && ms_door_has(MS_NDF_GTR) {
        return ms_gtr_sample_dcos(mf.alpha, u, mf.table);
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
// of `scattering::lut` (the CLI's `microsurface lut --kind albedo` and `--kind albedo-avg`);
// the rough dielectric's, as `scattering::CompensatedDielectric`, at the end of the file.
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
//
// Sampling, as the Rust type: Kulla–Conty takes the added lobes with probability
// q = 1 − E_s(μo), transmission within them with probability k_s, each a cosine-weighted
// direction on its side; the single-scattering sample otherwise; pdf = (1 − q) pdf_ss +
// q ((1 − k_s) or k_s)|cos θi|/π. As the conductor's, the sampler returns the
// single-scattering f at its wi, and the including shader adds the lobe with E_t(|cos θi|) of
// the sampled side (ms_dielectric_kulla_conty_sample_f). Turquin samples and weighs as the
// single-scattering lobes, f over E_s(μo). e_o and k_o depend on wo only: look them up before
// sampling.

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

// Kulla–Conty's probability density of the dielectric's added lobes at wi (the Rust type's
// `pdf_ms`): a cosine-weighted direction on wi's side, times that side's probability within
// the added lobes, k_o across the surface and 1 − k_o on wo's side (k_o = k_s of wo's side s).
fn ms_dielectric_kulla_conty_lobe_pdf(wo: vec3<f32>, wi: vec3<f32>, k_o: f32) -> f32 {
    let crossed = (wi.z < 0.0) != (wo.z < 0.0);
    let side = select(1.0 - k_o, k_o, crossed);
    return side * abs(wi.z) / MS_PI;
}

// The Kulla–Conty compensated dielectric's pdf (`CompensatedDielectric::pdf`): the mixture
// (1 − q) pdf_ss + q ms_dielectric_kulla_conty_lobe_pdf, q = ms_kulla_conty_p_ms(e_o), e_o =
// E_s(|cos θo|) of wo's side s, k_o = k_s; a smooth interface's 0 (its delta lobes). Turquin's
// pdf is the single-scattering one, ms_dielectric_pdf.
fn ms_dielectric_pdf_kulla_conty(d: MsDielectric, wo: vec3<f32>, wi: vec3<f32>, e_o: f32,
    k_o: f32) -> f32 {
    let p = ms_dielectric_pdf(d, wo, wi);
    if ms_dielectric_smooth(d) {
        return p;
    }
    let q = ms_kulla_conty_p_ms(e_o);
    return (1.0 - q) * p + q * ms_dielectric_kulla_conty_lobe_pdf(wo, wi, k_o);
}

// The Kulla–Conty compensated dielectric's sample (`CompensatedDielectric::sample`): with
// probability q = 1 − E_s(μo) (uc < q) the added lobes, across the surface where uc/q < k_o
// (transmission) and on wo's side otherwise, a cosine-weighted direction from u; else the
// single-scattering sample (ms_dielectric_sample) from (uc − q)/(1 − q) (at most 1 − 2⁻²⁴) and
// the same u. A smooth interface's sample is the single-scattering one (delta lobes,
// MS_SAMPLE_SPECULAR). pdf: ms_dielectric_pdf_kulla_conty at wi (rejected where it is not
// ms_usable, or wi on the horizon); MS_SAMPLE_TRANSMISSION and eta = η' where wi crossed the
// surface. f is the single-scattering f at wi, ms_dielectric_eval: the added lobe needs
// E_t(|cos θi|) of wi's side t at the sampled direction, which the caller looks up and adds
// with ms_dielectric_kulla_conty_sample_f.
fn ms_dielectric_sample_kulla_conty(d: MsDielectric, wo: vec3<f32>, uc: f32, u: vec2<f32>,
    e_o: f32, k_o: f32) -> MsBsdfSample {
    let none = MsBsdfSample(vec3<f32>(0.0), 0.0, vec3<f32>(0.0), 0u, 1.0);
    if ms_on_horizon(wo.z) {
        return none;
    }
    if ms_dielectric_smooth(d) {
        return ms_dielectric_sample(d, wo, uc, u);
    }
    let q = ms_kulla_conty_p_ms(e_o);
    var wi: vec3<f32>;
    if uc < q {
        let crossed = uc / q < k_o;
        wi = ms_cosine_hemisphere(u);
        if (wo.z > 0.0) == crossed {
            wi.z = -wi.z;
        }
    } else {
        // (Below 1: the f32 remap could round up to 1, where a total internal reflection,
        // R = 1, would take the refraction and be rejected.)
        let s = ms_dielectric_sample(d, wo, min((uc - q) / (1.0 - q), 0.99999994), u);
        if (s.flags & MS_SAMPLE_VALID) == 0u || (s.flags & MS_SAMPLE_SPECULAR) != 0u {
            return s;
        }
        wi = s.wi;
    }
    let pdf = ms_dielectric_pdf_kulla_conty(d, wo, wi, e_o, k_o);
    if !ms_usable(pdf) || wi.z == 0.0 {
        return none;
    }
    let f = vec3<f32>(ms_dielectric_eval(d, wo, wi));
    if (wi.z < 0.0) != (wo.z < 0.0) {
        let etap = select(1.0 / d.eta, d.eta, wo.z > 0.0);
        return MsBsdfSample(wi, pdf, f, MS_SAMPLE_VALID | MS_SAMPLE_TRANSMISSION, etap);
    }
    return MsBsdfSample(wi, pdf, f, MS_SAMPLE_VALID, 1.0);
}

// A ms_dielectric_sample_kulla_conty sample's f completed with the added lobe:
// + ms_dielectric_kulla_conty_lobe(d, wo, s.wi, e_o, e_i, e_avg_i, k_o), e_i = E_t(|cos θi|)
// and e_avg_i = E_avg,t of the side t of s.wi (a delta or rejected sample as it is). Equal to
// ms_dielectric_eval_kulla_conty at s.wi.
fn ms_dielectric_kulla_conty_sample_f(s: MsBsdfSample, d: MsDielectric, wo: vec3<f32>,
    e_o: f32, e_i: f32, e_avg_i: f32, k_o: f32) -> MsBsdfSample {
    if (s.flags & MS_SAMPLE_VALID) == 0u || (s.flags & MS_SAMPLE_SPECULAR) != 0u {
        return s;
    }
    let lobe = ms_dielectric_kulla_conty_lobe(d, wo, s.wi, e_o, e_i, e_avg_i, k_o);
    return MsBsdfSample(s.wi, s.pdf, s.f + lobe, s.flags, s.eta);
}

// The Turquin compensated dielectric's sample (`CompensatedDielectric::sample`,
// Scheme::Turquin): the single-scattering sample with its own f over e_o = E_s(|cos θo|) of
// wo's side (as it is where e_o is not positive; a delta lobe as it is; a scaled f that
// overflows is rejected); the pdf is ms_dielectric_pdf.
fn ms_dielectric_sample_turquin(d: MsDielectric, wo: vec3<f32>, uc: f32, u: vec2<f32>,
    e_o: f32) -> MsBsdfSample {
    let s = ms_dielectric_sample(d, wo, uc, u);
    if (s.flags & MS_SAMPLE_VALID) == 0u || (s.flags & MS_SAMPLE_SPECULAR) != 0u
        || !(e_o > 0.0) {
        return s;
    }
    let f = s.f / e_o;
    if !all(f <= vec3<f32>(3.4028235e38)) {
        return MsBsdfSample(vec3<f32>(0.0), 0.0, vec3<f32>(0.0), 0u, 1.0);
    }
    return MsBsdfSample(s.wi, s.pdf, f, s.flags, s.eta);
}
