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
