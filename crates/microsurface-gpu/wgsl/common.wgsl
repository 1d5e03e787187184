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
