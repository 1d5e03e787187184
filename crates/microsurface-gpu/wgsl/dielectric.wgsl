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
