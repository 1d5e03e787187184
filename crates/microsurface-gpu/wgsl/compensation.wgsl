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
