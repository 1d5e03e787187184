// The test kernels of Double GGX and the Exponential NDF (family_kernels.wgsl), compiled
// after the library, FAMILY_WGSL and kernels.wgsl (its bindings and ms_k_index). The NDF is
// record 2's w: 2 Double GGX, 3 Exponential.

const MS_K_DOUBLE_GGX: u32 = 2u;

// D(wm), Λ(wo), G1(wo), G2(wo, wm); separable G2, D_wo(wm), D(wm) cos θm, G1(wm).
@compute @workgroup_size(64)
fn ms_k_family_eval(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let a = ms_in[i * MS_K_IN].xy;
    let wo = ms_in[i * MS_K_IN + 1u].xyz;
    let r2 = ms_in[i * MS_K_IN + 2u];
    let wm = r2.xyz;
    if u32(r2.w) == MS_K_DOUBLE_GGX {
        ms_out[i * MS_K_OUT] = vec4<f32>(ms_double_ggx_d(wm, a), ms_double_ggx_lambda(wo, a),
            ms_double_ggx_g1(wo, a), ms_double_ggx_g2(wo, wm, a));
        ms_out[i * MS_K_OUT + 1u] = vec4<f32>(ms_double_ggx_g2_separable(wo, wm, a),
            ms_double_ggx_pdf(wo, wm, a), ms_double_ggx_pdf_dcos(wm, a), ms_double_ggx_g1(wm, a));
    } else {
        ms_out[i * MS_K_OUT] = vec4<f32>(ms_exponential_d(wm, a), ms_exponential_lambda(wo, a),
            ms_exponential_g1(wo, a), ms_exponential_g2(wo, wm, a));
        ms_out[i * MS_K_OUT + 1u] = vec4<f32>(ms_exponential_g2_separable(wo, wm, a),
            ms_exponential_pdf(wo, wm, a), ms_exponential_pdf_dcos(wm, a), ms_exponential_g1(wm, a));
    }
}

// The D·cos normal of u with its pdf; the stream's first f32 uniform and ziggurat variate.
@compute @workgroup_size(64)
fn ms_k_family_sample(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = ms_k_index(id, groups);
    if i == arrayLength(&ms_in) / MS_K_IN {
        return;
    }
    let r0 = ms_in[i * MS_K_IN];
    var t: MsSample;
    if u32(ms_in[i * MS_K_IN + 2u].w) == MS_K_DOUBLE_GGX {
        t = ms_double_ggx_sample_dcos(r0.xy, r0.zw);
    } else {
        t = ms_exponential_sample_dcos(r0.xy, r0.zw);
    }
    var state = ms_stream_new(r0.zw);
    let v = ms_stream_next(&state);
    let e = ms_zig_exp1(v, &state);
    ms_out[i * MS_K_OUT] = vec4<f32>(t.wm, t.pdf);
    ms_out[i * MS_K_OUT + 1u] = vec4<f32>(v, e, 0.0, 0.0);
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
