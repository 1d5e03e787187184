// The throughput kernels of examples/gpu_bench.rs, compiled after the library. Each
// invocation draws its inputs from a hash of its index (PCG, Jarzynski & Olano 2020), runs the
// function ITER times and writes one sum (so that nothing is optimised away); the
// `bench_inputs` kernel does the same without the library call: the inputs' own cost.
//
// ms_in[0] = (αx, αy, n as f32 bits, seed as f32 bits); ms_in[1] = (the door's NDF, its
// table's row, as u32 bits; 0, 0).

@group(0) @binding(0) var<storage, read> ms_in: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> ms_out: array<f32>;
const MS_TABLES_GROUP: u32 = 1u;
const MS_TABLES_BINDING: u32 = 0u;

const ITER: u32 = 8u;

fn pcg(v: u32) -> u32 {
    let s = v * 747796405u + 2891336453u;
    let w = ((s >> ((s >> 28u) + 4u)) ^ s) * 277803737u;
    return (w >> 22u) ^ w;
}

fn u01(h: u32) -> f32 {
    return f32(h >> 8u) * (1.0 / 16777216.0);
}

struct Input {
    wo: vec3<f32>,
    wi: vec3<f32>,
    u: vec2<f32>,
}

// Directions with cos θ in [0.05, 1] at any azimuth, and two uniforms.
fn input(i: u32, j: u32) -> Input {
    let seed = bitcast<u32>(ms_in[0].w);
    let h0 = pcg(i * ITER + j + seed);
    let h1 = pcg(h0);
    let h2 = pcg(h1);
    let h3 = pcg(h2);
    let h4 = pcg(h3);
    let co = 0.05 + 0.95 * u01(h0);
    let so = sqrt(max(1.0 - co * co, 0.0));
    let po = ms_cos_sin_turn(u01(h1));
    let ci = 0.05 + 0.95 * u01(h2);
    let si = sqrt(max(1.0 - ci * ci, 0.0));
    let pi = ms_cos_sin_turn(u01(h3));
    let wo = vec3<f32>(so * po.x, so * po.y, co);
    let wi = vec3<f32>(si * pi.x, si * pi.y, ci);
    return Input(wo, wi, vec2<f32>(u01(h4), u01(pcg(h4))));
}

fn index(id: vec3<u32>, groups: vec3<u32>) -> u32 {
    return id.x + id.y * groups.x * 64u;
}

fn gold() -> MsConductor {
    let fr = MsFresnel(MS_FRESNEL_CONDUCTOR, vec3<f32>(0.143, 0.374, 1.442),
        vec3<f32>(3.983, 2.385, 1.603));
    return MsConductor(MsMicrofacet(MS_NDF_GGX, ms_in[0].xy, 0u), fr, MS_MASKING_CORRELATED);
}

@compute @workgroup_size(64)
fn bench_inputs(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = index(id, groups);
    if i >= bitcast<u32>(ms_in[0].z) {
        return;
    }
    var acc = 0.0;
    for (var j = 0u; j < ITER; j++) {
        let x = input(i, j);
        acc += x.wo.x + x.wi.y + x.u.x;
    }
    ms_out[i] = acc;
}

@compute @workgroup_size(64)
fn bench_ggx_sample(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = index(id, groups);
    if i >= bitcast<u32>(ms_in[0].z) {
        return;
    }
    let a = ms_in[0].xy;
    var acc = 0.0;
    for (var j = 0u; j < ITER; j++) {
        let x = input(i, j);
        let s = ms_ggx_sample(x.wo, a, x.u);
        acc += s.wm.x + s.pdf;
    }
    ms_out[i] = acc;
}

@compute @workgroup_size(64)
fn bench_ggx_sample_bounded(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = index(id, groups);
    if i >= bitcast<u32>(ms_in[0].z) {
        return;
    }
    let a = ms_in[0].xy;
    var acc = 0.0;
    for (var j = 0u; j < ITER; j++) {
        let x = input(i, j);
        let s = ms_ggx_sample_bounded(x.wo, a, x.u);
        acc += s.wm.x + s.pdf;
    }
    ms_out[i] = acc;
}

@compute @workgroup_size(64)
fn bench_ggx_d_g2(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = index(id, groups);
    if i >= bitcast<u32>(ms_in[0].z) {
        return;
    }
    let a = ms_in[0].xy;
    var acc = 0.0;
    for (var j = 0u; j < ITER; j++) {
        let x = input(i, j);
        acc += ms_ggx_d(x.wi, a) * ms_ggx_g2(x.wo, x.wi, a);
    }
    ms_out[i] = acc;
}

@compute @workgroup_size(64)
fn bench_conductor_eval_pdf(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = index(id, groups);
    if i >= bitcast<u32>(ms_in[0].z) {
        return;
    }
    let c = gold();
    var acc = 0.0;
    for (var j = 0u; j < ITER; j++) {
        let x = input(i, j);
        let f = ms_conductor_eval_pdf(c, x.wo, x.wi);
        acc += f.x + f.y + f.z + f.w;
    }
    ms_out[i] = acc;
}

@compute @workgroup_size(64)
fn bench_conductor_sample(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = index(id, groups);
    if i >= bitcast<u32>(ms_in[0].z) {
        return;
    }
    let c = gold();
    var acc = 0.0;
    for (var j = 0u; j < ITER; j++) {
        let x = input(i, j);
        let s = ms_conductor_sample(c, x.wo, 0.5, x.u);
        acc += s.wi.x + s.pdf + s.f.y;
    }
    ms_out[i] = acc;
}

fn glass() -> MsDielectric {
    return MsDielectric(MsMicrofacet(MS_NDF_GGX, ms_in[0].xy, 0u), 1.5, MS_MASKING_CORRELATED,
        MS_TRANSPORT_RADIANCE);
}

@compute @workgroup_size(64)
fn bench_dielectric_eval_pdf(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = index(id, groups);
    if i >= bitcast<u32>(ms_in[0].z) {
        return;
    }
    let d = glass();
    var acc = 0.0;
    for (var j = 0u; j < ITER; j++) {
        let x = input(i, j);
        // Half the pairs transmitted: wi mirrored below on odd j.
        var wi = x.wi;
        if (j & 1u) == 1u {
            wi.z = -wi.z;
        }
        acc += ms_dielectric_eval(d, x.wo, wi) + ms_dielectric_pdf(d, x.wo, wi);
    }
    ms_out[i] = acc;
}

@compute @workgroup_size(64)
fn bench_dielectric_sample(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = index(id, groups);
    if i >= bitcast<u32>(ms_in[0].z) {
        return;
    }
    let d = glass();
    var acc = 0.0;
    for (var j = 0u; j < ITER; j++) {
        let x = input(i, j);
        let s = ms_dielectric_sample(d, x.wo, x.wi.x * 0.5 + 0.5, x.u);
        acc += s.wi.x + s.pdf + s.f.y;
    }
    ms_out[i] = acc;
}

// The material of ms_in[1] (the NDF and its table's row, as u32 bits) through MsMicrofacet at
// (αx, αy) = ms_in[0].xy: a visible normal + pdf, and D · G2.
fn door() -> MsMicrofacet {
    let p = ms_in[1];
    return MsMicrofacet(bitcast<u32>(p.x), ms_in[0].xy, bitcast<u32>(p.y));
}

@compute @workgroup_size(64)
fn bench_door_sample(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = index(id, groups);
    if i >= bitcast<u32>(ms_in[0].z) {
        return;
    }
    let mf = door();
    var acc = 0.0;
    for (var j = 0u; j < ITER; j++) {
        let x = input(i, j);
        let s = ms_sample(mf, x.wo, x.u);
        acc += s.wm.x + s.pdf;
    }
    ms_out[i] = acc;
}

@compute @workgroup_size(64)
fn bench_door_d_g2(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = index(id, groups);
    if i >= bitcast<u32>(ms_in[0].z) {
        return;
    }
    let mf = door();
    var acc = 0.0;
    for (var j = 0u; j < ITER; j++) {
        let x = input(i, j);
        acc += ms_d(mf, x.wi) * ms_g2(mf, x.wo, x.wi);
    }
    ms_out[i] = acc;
}
