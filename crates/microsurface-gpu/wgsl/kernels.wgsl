// The test kernels (kernels.wgsl): compute entry points that run the library element by
// element for the crate's tests against the Rust f32 path, and the entry points of the
// translated files (generated/), through which every library function is reachable.
//
// One element is five vec4 in (`ms_in`) and two vec4 out (`ms_out`):
//   in  0: (αx, αy, u₀, u₁)      1: (wo, uc)        2: (wi or wm, the NDF as f32)
//       3: (Fresnel a, kind)     4: (Fresnel b, masking)
// Dispatch: workgroups of 64, in x then y (the element index is x + y·64·(workgroups in x)).

@group(0) @binding(0) var<storage, read> ms_in: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> ms_out: array<vec4<f32>>;
// The library's tables (microsurface_gpu::TABLES).
const MS_TABLES_GROUP: u32 = 1u;
const MS_TABLES_BINDING: u32 = 0u;

const MS_K_IN: u32 = 5u;
const MS_K_OUT: u32 = 2u;

// The element index, or the element count where this invocation has none.
fn ms_k_index(id: vec3<u32>, groups: vec3<u32>) -> u32 {
    let i = id.x + id.y * groups.x * 64u;
    let n = arrayLength(&ms_in) / MS_K_IN;
    if i >= n {
        return n;
    }
    return i;
}

// The element's material: record 2's w is the NDF plus 16 times its shape table's row.
fn ms_k_microfacet(r0: vec4<f32>, r2: vec4<f32>) -> MsMicrofacet {
    let code = u32(r2.w);
    return MsMicrofacet(code & 15u, r0.xy, code >> 4u);
}

fn ms_k_conductor(i: u32) -> MsConductor {
    let r0 = ms_in[i * MS_K_IN];
    let r2 = ms_in[i * MS_K_IN + 2u];
    let r3 = ms_in[i * MS_K_IN + 3u];
    let r4 = ms_in[i * MS_K_IN + 4u];
    let mf = ms_k_microfacet(r0, r2);
    return MsConductor(mf, MsFresnel(u32(r3.w), r3.xyz, r4.xyz), u32(r4.w));
}

// D(wm), Λ(wo), G1(wo), G2(wo, wm); separable G2, D_wo(wm), D(wm) cos θm, the bounded pdf.
@compute @workgroup_size(64)
fn ms_k_ggx_eval(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let a = ms_in[i * MS_K_IN].xy;
    let wo = ms_in[i * MS_K_IN + 1u].xyz;
    let wm = ms_in[i * MS_K_IN + 2u].xyz;
    ms_out[i * MS_K_OUT] = vec4<f32>(ms_ggx_d(wm, a), ms_ggx_lambda(wo, a), ms_ggx_g1(wo, a),
        ms_ggx_g2(wo, wm, a));
    ms_out[i * MS_K_OUT + 1u] = vec4<f32>(ms_ggx_g2_separable(wo, wm, a), ms_ggx_pdf(wo, wm, a),
        ms_ggx_pdf_dcos(wm, a), ms_ggx_pdf_bounded(wo, wm, a));
}

// Beckmann: D(wm), Λ(wo), G1(wo), G2(wo, wm); separable G2, D_wo(wm), D(wm) cos θm, and
// D_wo(wm) through MsMicrofacet (the run-time door).
@compute @workgroup_size(64)
fn ms_k_beckmann_eval(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let a = ms_in[i * MS_K_IN].xy;
    let wo = ms_in[i * MS_K_IN + 1u].xyz;
    let wm = ms_in[i * MS_K_IN + 2u].xyz;
    ms_out[i * MS_K_OUT] = vec4<f32>(ms_beckmann_d(wm, a), ms_beckmann_lambda(wo, a),
        ms_beckmann_g1(wo, a), ms_beckmann_g2(wo, wm, a));
    ms_out[i * MS_K_OUT + 1u] = vec4<f32>(ms_beckmann_g2_separable(wo, wm, a),
        ms_beckmann_pdf(wo, wm, a), ms_beckmann_pdf_dcos(wm, a),
        ms_pdf(MsMicrofacet(MS_NDF_BECKMANN, a, 0u), wo, wm));
}

// Beckmann: the visible normal of wo and u with its pdf (through MsMicrofacet); the D·cos
// normal of u with its pdf.
@compute @workgroup_size(64)
fn ms_k_beckmann_sample(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let r0 = ms_in[i * MS_K_IN];
    let wo = ms_in[i * MS_K_IN + 1u].xyz;
    let s = ms_sample(MsMicrofacet(MS_NDF_BECKMANN, r0.xy, 0u), wo, r0.zw);
    let t = ms_beckmann_sample_dcos(r0.xy, r0.zw);
    ms_out[i * MS_K_OUT] = vec4<f32>(s.wm, s.pdf);
    ms_out[i * MS_K_OUT + 1u] = vec4<f32>(t.wm, t.pdf);
}

// The visible normal of wo and u with its pdf; the D·cos normal of u with its pdf.
@compute @workgroup_size(64)
fn ms_k_ggx_sample(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let r0 = ms_in[i * MS_K_IN];
    let wo = ms_in[i * MS_K_IN + 1u].xyz;
    let s = ms_ggx_sample(wo, r0.xy, r0.zw);
    let t = ms_ggx_sample_dcos(r0.xy, r0.zw);
    ms_out[i * MS_K_OUT] = vec4<f32>(s.wm, s.pdf);
    ms_out[i * MS_K_OUT + 1u] = vec4<f32>(t.wm, t.pdf);
}

// The bounded visible normal of wo and u with its pdf; the bounded reflection pdf of (wo, wi).
@compute @workgroup_size(64)
fn ms_k_ggx_bounded(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let r0 = ms_in[i * MS_K_IN];
    let wo = ms_in[i * MS_K_IN + 1u].xyz;
    let wi = ms_in[i * MS_K_IN + 2u].xyz;
    let s = ms_ggx_sample_bounded(wo, r0.xy, r0.zw);
    ms_out[i * MS_K_OUT] = vec4<f32>(s.wm, s.pdf);
    ms_out[i * MS_K_OUT + 1u] = vec4<f32>(ms_ggx_pdf_bounded_reflection(wo, wi, r0.xy), 0.0, 0.0,
        0.0);
}

// At cos θ = wo.z: dielectric(η = a.x), conductor(a.x, b.x), Schlick(a.x), F82-tint(a.x, b.x);
// the element's Fresnel term (kind, a, b) by ms_fresnel_eval.
@compute @workgroup_size(64)
fn ms_k_fresnel(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let c = ms_in[i * MS_K_IN + 1u].z;
    let fr = ms_k_conductor(i).fresnel;
    ms_out[i * MS_K_OUT] = vec4<f32>(ms_fresnel_dielectric(c, fr.a.x),
        ms_fresnel_conductor(c, fr.a.x, fr.b.x), ms_fresnel_schlick(c, fr.a.x),
        ms_fresnel_f82_tint(c, fr.a.x, fr.b.x));
    ms_out[i * MS_K_OUT + 1u] = vec4<f32>(ms_fresnel_eval(fr, c), 0.0);
}

// The element's conductor at (wo, wi): (eval, pdf); eval_pdf.
@compute @workgroup_size(64)
fn ms_k_conductor_eval(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let c = ms_k_conductor(i);
    let wo = ms_in[i * MS_K_IN + 1u].xyz;
    let wi = ms_in[i * MS_K_IN + 2u].xyz;
    ms_out[i * MS_K_OUT] = vec4<f32>(ms_conductor_eval(c, wo, wi), ms_conductor_pdf(c, wo, wi));
    ms_out[i * MS_K_OUT + 1u] = ms_conductor_eval_pdf(c, wo, wi);
}

// The element's conductor sampled at (wo, uc, u): (wi, pdf), (f, flags).
@compute @workgroup_size(64)
fn ms_k_conductor_sample(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let c = ms_k_conductor(i);
    let r0 = ms_in[i * MS_K_IN];
    let r1 = ms_in[i * MS_K_IN + 1u];
    let s = ms_conductor_sample(c, r1.xyz, r1.w, r0.zw);
    ms_out[i * MS_K_OUT] = vec4<f32>(s.wi, s.pdf);
    ms_out[i * MS_K_OUT + 1u] = vec4<f32>(s.f, f32(s.flags));
}

fn ms_k_dielectric(i: u32) -> MsDielectric {
    let r0 = ms_in[i * MS_K_IN];
    let r2 = ms_in[i * MS_K_IN + 2u];
    let r3 = ms_in[i * MS_K_IN + 3u];
    let r4 = ms_in[i * MS_K_IN + 4u];
    return MsDielectric(ms_k_microfacet(r0, r2), r3.x, u32(r4.w), u32(r4.x));
}

// The element's dielectric (η = Fresnel a.x, transport = b.x, masking) at (wo, wi):
// (eval, pdf).
@compute @workgroup_size(64)
fn ms_k_dielectric_eval(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let d = ms_k_dielectric(i);
    let wo = ms_in[i * MS_K_IN + 1u].xyz;
    let wi = ms_in[i * MS_K_IN + 2u].xyz;
    ms_out[i * MS_K_OUT] = vec4<f32>(ms_dielectric_eval(d, wo, wi), ms_dielectric_pdf(d, wo, wi),
        0.0, 0.0);
    ms_out[i * MS_K_OUT + 1u] = vec4<f32>(0.0);
}

// The element's dielectric sampled at (wo, uc, u): (wi, pdf), (f, η', flags, 0).
@compute @workgroup_size(64)
fn ms_k_dielectric_sample(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let d = ms_k_dielectric(i);
    let r0 = ms_in[i * MS_K_IN];
    let r1 = ms_in[i * MS_K_IN + 1u];
    let s = ms_dielectric_sample(d, r1.xyz, r1.w, r0.zw);
    ms_out[i * MS_K_OUT] = vec4<f32>(s.wi, s.pdf);
    ms_out[i * MS_K_OUT + 1u] = vec4<f32>(s.f.x, s.eta, f32(s.flags), 0.0);
}

// Double GGX and the Exponential NDF: the NDF is record 2's w (MS_NDF_DOUBLE_GGX or
// MS_NDF_EXPONENTIAL).

// D(wm), Λ(wo), G1(wo), G2(wo, wm); separable G2, D_wo(wm), D(wm) cos θm, G1(wm), all
// through the run-time door MsMicrofacet (record 2's w: the NDF plus 16 × its table's row).
@compute @workgroup_size(64)
fn ms_k_family_eval(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let r0 = ms_in[i * MS_K_IN];
    let wo = ms_in[i * MS_K_IN + 1u].xyz;
    let r2 = ms_in[i * MS_K_IN + 2u];
    let wm = r2.xyz;
    let mf = ms_k_microfacet(r0, r2);
    ms_out[i * MS_K_OUT] = vec4<f32>(ms_d(mf, wm), ms_lambda(mf, wo), ms_g1(mf, wo),
        ms_g2(mf, wo, wm));
    ms_out[i * MS_K_OUT + 1u] = vec4<f32>(ms_g2_separable(mf, wo, wm), ms_pdf(mf, wo, wm),
        ms_pdf_dcos(mf, wm), ms_g1(mf, wm));
}

// The D·cos normal of u with its pdf; the visible normal for wo of u with its pdf, through
// the run-time door MsMicrofacet.
@compute @workgroup_size(64)
fn ms_k_family_sample(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let r0 = ms_in[i * MS_K_IN];
    let wo = ms_in[i * MS_K_IN + 1u].xyz;
    let mf = ms_k_microfacet(r0, ms_in[i * MS_K_IN + 2u]);
    let t = ms_sample_dcos(mf, r0.zw);
    let v = ms_sample(mf, wo, r0.zw);
    ms_out[i * MS_K_OUT] = vec4<f32>(t.wm, t.pdf);
    ms_out[i * MS_K_OUT + 1u] = vec4<f32>(v.wm, v.pdf);
}

// The uniform stream of u (record 0's zw): its first two 64-bit outputs as 16-bit pieces
// (exact in f32), low first.
@compute @workgroup_size(64)
fn ms_k_stream(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    var state = ms_stream_new(ms_in[i * MS_K_IN].zw);
    for (var k = 0u; k < 2u; k++) {
        let z = ms_stream_next_u64(&state);
        ms_out[i * MS_K_OUT + k] = vec4<f32>(f32(z.x & 0xffffu), f32(z.x >> 16u),
            f32(z.y & 0xffffu), f32(z.y >> 16u));
    }
}
