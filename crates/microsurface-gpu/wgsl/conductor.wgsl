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
