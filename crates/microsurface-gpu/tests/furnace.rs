//! The compensated conductor of `wgsl/compensation.wgsl` on the GPU, reading the engines'
//! tables (`microsurface::scattering::lut`, GGX, `LutKind::Albedo` and `LutKind::AlbedoAvg`,
//! 32 and 64 nodes) from a storage buffer, and its white furnace there (CI: Mesa's lavapipe,
//! `MICROSURFACE_GPU_REQUIRED=1`; elsewhere the GPU tests skip without a Vulkan adapter).
//!
//! * The lookup: the WGSL filter against `Lut::lookup` at coordinates inside, between and
//!   outside the texel centres, 0 and 1 and past them, within the f32 rounding of the blend.
//! * The furnace: ∫ f(wo, wi) cos θi dωi of the F = 1 compensated conductor, every value of f
//!   from the WGSL on a product rule in (μi, φi) built here, summed in f64. With E the exact
//!   single-scattering albedo and E_l the table's lookup, the furnace is 1 + E(μo) − E_l(μo)
//!   for Kulla–Conty (with E_avg the average of the looked-up E) and E(μo)/E_l(μo) for
//!   Turquin: the tests hold the GPU's sums to these identities within the rule's and f32's
//!   error, and report |furnace − 1|, the table's own interpolation error.

use microsurface::bsdf::fresnel::One;
use microsurface::bsdf::{Bsdf, RoughConductor};
use microsurface::scattering::lut::{Lut, LutKind, LutSpec};
use microsurface::scattering::single_scattering_albedo;
use microsurface::{Ggx, Microfacet, NdfKind, NdfSpec};
use microsurface_gpu::{groups, Error, Gpu, WGSL};
use std::sync::{mpsc, OnceLock};

/// The test kernels: the library's lookups and compensated conductor over a table in a
/// storage buffer (binding 2) laid out as a header of four f32 (the roughness and μ node
/// counts, the offsets of the two E_avg rows) and the tables.
const KERNELS: &str = r#"
@group(0) @binding(0) var<storage, read> fz_in: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> fz_out: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read> lut: array<f32>;

// E(μ, α) row-major [roughness][μ] from lut[4]; E_avg(α) at lut[lut[2]] (the AlbedoAvg
// table: the exact average) and at lut[lut[3]] (the average of the looked-up E).
const FZ_E: u32 = 4u;

fn fz_n_alpha() -> u32 {
    return u32(lut[0]);
}

fn fz_n_mu() -> u32 {
    return u32(lut[1]);
}

// E at the roughness tap r and the μ coordinate x.
fn fz_albedo(r: MsLutTap, x: f32) -> f32 {
    let n = fz_n_mu();
    let m = ms_lut_tap(x, n);
    return ms_lut_bilerp(r, m, lut[FZ_E + ms_lut_index(r.i, m.i, n)],
        lut[FZ_E + ms_lut_index(r.i + 1u, m.i, n)], lut[FZ_E + ms_lut_index(r.i, m.i + 1u, n)],
        lut[FZ_E + ms_lut_index(r.i + 1u, m.i + 1u, n)]);
}

// The E_avg row at offset `at`, at the roughness tap r.
fn fz_albedo_avg(r: MsLutTap, at: u32) -> f32 {
    return ms_lut_lerp(r, lut[at + r.i], lut[at + r.i + 1u]);
}

fn fz_index(id: vec3<u32>, groups: vec3<u32>) -> u32 {
    return id.x + id.y * groups.x * 64u;
}

// In: (x_roughness, x_mu, αx, αy). Out: (E, E_avg exact, E_avg of the lookup, the roughness
// coordinate of (αx, αy)).
@compute @workgroup_size(64)
fn fz_lookup(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = fz_index(id, groups);
    if i >= arrayLength(&fz_in) {
        return;
    }
    let x = fz_in[i];
    let r = ms_lut_tap(x.x, fz_n_alpha());
    fz_out[i] = vec4<f32>(fz_albedo(r, x.y), fz_albedo_avg(r, u32(lut[2])),
        fz_albedo_avg(r, u32(lut[3])), ms_lut_roughness_coord(x.zw, 1.0));
}

// In: (wo, α), (wi, 0). Out: f(wo, wi) of the F = 1 GGX conductor (channel x), compensated:
// (Kulla–Conty with the exact E_avg, Kulla–Conty with the lookup's E_avg, Turquin, none).
@compute @workgroup_size(64)
fn fz_furnace(@builtin(global_invocation_id) id: vec3<u32>,
    @builtin(num_workgroups) groups: vec3<u32>) {
    let i = fz_index(id, groups);
    if i >= arrayLength(&fz_in) / 2u {
        return;
    }
    let a = fz_in[2u * i];
    let wo = a.xyz;
    let wi = fz_in[2u * i + 1u].xyz;
    let alpha = vec2<f32>(a.w);
    let one = vec3<f32>(1.0);
    let c = MsConductor(MsMicrofacet(MS_NDF_GGX, alpha), MsFresnel(MS_FRESNEL_ONE, one, one),
        MS_MASKING_CORRELATED);
    let r = ms_lut_tap(ms_lut_roughness_coord(alpha, 1.0), fz_n_alpha());
    let e_o = fz_albedo(r, abs(wo.z));
    let e_i = fz_albedo(r, abs(wi.z));
    let avg_x = fz_albedo_avg(r, u32(lut[2]));
    let avg_l = fz_albedo_avg(r, u32(lut[3]));
    let kc_x = ms_conductor_eval_kulla_conty(c, wo, wi, e_o, e_i, avg_x,
        ms_kulla_conty_f_ms(one, avg_x));
    let kc_l = ms_conductor_eval_kulla_conty(c, wo, wi, e_o, e_i, avg_l,
        ms_kulla_conty_f_ms(one, avg_l));
    let tq = ms_conductor_eval_turquin(c, wo, wi, e_o, one);
    fz_out[i] = vec4<f32>(kc_x.x, kc_l.x, tq.x, ms_conductor_eval(c, wo, wi).x);
}
"#;

/// The device with the kernels compiled against a three-binding layout (the crate's
/// `Program` has two), once per test binary; `None` (the tests skip) only where no Vulkan
/// adapter exists and `MICROSURFACE_GPU_REQUIRED` is not 1.
struct Runner {
    gpu: Gpu,
    layout: wgpu::BindGroupLayout,
    lookup: wgpu::ComputePipeline,
    furnace: wgpu::ComputePipeline,
}

fn runner() -> Option<&'static Runner> {
    static R: OnceLock<Option<Runner>> = OnceLock::new();
    R.get_or_init(|| {
        let required = std::env::var("MICROSURFACE_GPU_REQUIRED").as_deref() == Ok("1");
        let gpu = match Gpu::new() {
            Ok(g) => g,
            Err(Error::NoAdapter(m)) if !required => {
                eprintln!("SKIPPED: no Vulkan adapter ({m})");
                return None;
            }
            Err(e) => panic!("MICROSURFACE_GPU_REQUIRED=1 or a device error: {e}"),
        };
        let i = gpu.adapter_info();
        eprintln!("adapter: {} ({:?}, {})", i.name, i.device_type, i.driver);
        let device = gpu.device();
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("furnace"),
            source: wgpu::ShaderSource::Wgsl(format!("{WGSL}\n{KERNELS}").into()),
        });
        let entry = |binding, read_only| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("furnace"),
            entries: &[entry(0, true), entry(1, false), entry(2, true)],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("furnace"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = |name: &str| {
            device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some(name),
                layout: Some(&pipeline_layout),
                module: &module,
                entry_point: Some(name),
                compilation_options: Default::default(),
                cache: None,
            })
        };
        let (lookup, furnace) = (pipeline("fz_lookup"), pipeline("fz_furnace"));
        if let Some(e) = pollster::block_on(scope.pop()) {
            panic!("the kernels do not validate: {e}");
        }
        Some(Runner {
            layout,
            lookup,
            furnace,
            gpu,
        })
    })
    .as_ref()
}

impl Runner {
    /// Runs `pipeline` over `input` (`per_in` records an element, one record out) with the
    /// table buffer `lut`.
    fn run(
        &self,
        pipeline: &wgpu::ComputePipeline,
        input: &[[f32; 4]],
        per_in: usize,
        lut: &[f32],
    ) -> Vec<[f32; 4]> {
        let (device, queue) = (self.gpu.device(), self.gpu.queue());
        let n = input.len() / per_in;
        let in_buf = self.gpu.storage((input.len() * 16) as u64);
        queue.write_buffer(&in_buf, 0, bytemuck::cast_slice(input));
        let lut_buf = self.gpu.storage((lut.len() * 4) as u64);
        queue.write_buffer(&lut_buf, 0, bytemuck::cast_slice(lut));
        let out_bytes = (n * 16) as u64;
        let out_buf = self.gpu.storage(out_bytes);
        let read = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: out_bytes.max(16),
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("furnace"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: in_buf.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: out_buf.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: lut_buf.as_entire_binding(),
                },
            ],
        });
        let mut enc =
            device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        {
            let mut pass = enc.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &bind, &[]);
            let (x, y) = groups(n as u64);
            pass.dispatch_workgroups(x, y, 1);
        }
        enc.copy_buffer_to_buffer(&out_buf, 0, &read, 0, out_bytes.max(16));
        queue.submit([enc.finish()]);
        let (tx, rx) = mpsc::channel();
        read.slice(..).map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .expect("the device finishes");
        rx.recv().expect("mapped").expect("mapped");
        let view = read.get_mapped_range(..).expect("the mapped range");
        let out = bytemuck::cast_slice(&view[..n * 16]).to_vec();
        drop(view);
        read.unmap();
        out
    }
}

/// GGX's E and E_avg tables of `size` nodes (the `Lut` defaults: μ and √α, α_max 1).
fn tables(size: usize) -> (Lut, Lut) {
    static T: OnceLock<std::sync::Mutex<Vec<(usize, Lut, Lut)>>> = OnceLock::new();
    let cache = T.get_or_init(Default::default);
    let mut cache = cache.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, e, a)) = cache.iter().find(|t| t.0 == size) {
        return (e.clone(), a.clone());
    }
    let ndf = NdfSpec::new(NdfKind::Ggx, None).expect("GGX");
    let make = |kind| {
        let mut spec = LutSpec::new(ndf, kind);
        spec.size = size;
        Lut::compute(&spec, &|_, _| {}).expect("the table")
    };
    let (e, a) = (make(LutKind::Albedo), make(LutKind::AlbedoAvg));
    cache.push((size, e.clone(), a.clone()));
    (e, a)
}

/// Per roughness node, 2∫E_l(μ)μ dμ of the looked-up E (linear between the μ texel centres,
/// the edge values outside them): exact, by Simpson's rule on each piece (a cubic).
fn lookup_average(e: &Lut) -> Vec<f64> {
    let n = e.dims()[1];
    let c = |j: usize| (j as f64 + 0.5) / n as f64;
    e.values
        .chunks(n)
        .map(|row| {
            let mut s = row[0] * c(0) * c(0) + row[n - 1] * (1.0 - c(n - 1) * c(n - 1));
            for j in 0..n - 1 {
                let (a, b) = (c(j), c(j + 1));
                let m = 0.5 * (a + b);
                let vm = 0.5 * (row[j] + row[j + 1]);
                s += 2.0 * (b - a) / 6.0 * (row[j] * a + 4.0 * vm * m + row[j + 1] * b);
            }
            s
        })
        .collect()
}

/// The buffer the kernels read: header, E, the exact E_avg, the lookup's E_avg.
fn lut_buffer(e: &Lut, avg: &Lut) -> Vec<f32> {
    let dims = e.dims();
    let at_x = 4 + e.values.len();
    let at_l = at_x + avg.values.len();
    let mut b = vec![dims[0] as f32, dims[1] as f32, at_x as f32, at_l as f32];
    b.extend(e.values.iter().map(|&v| v as f32));
    b.extend(avg.values.iter().map(|&v| v as f32));
    b.extend(lookup_average(e).iter().map(|&v| v as f32));
    b
}

const U: f64 = f32::EPSILON as f64 / 2.0;

/// The WGSL filter against `Lut::lookup` (of the f32 table, in f64) at the coordinates a
/// shader passes: the texel centres, midpoints between them, points just beside each centre,
/// the clamped border (0, a quarter texel, the first and last centres), 0 and 1 exactly and
/// past them. Bound, from f32's rounding: t = x·n − ½ rounds twice (|δt| ≤ 2u·n, u = 2⁻²⁴;
/// floor and t − ⌊t⌋ are exact, and where ⌊t⌋ flips the blend is continuous), which moves the
/// value by |δt| times the slope between the neighbouring nodes; the weights 1 − f and their
/// products round (2u each) and the four-term sum adds 3u: 8u times the largest node more.
/// (The roughness coordinate √(√(αx αy)): the product's rounding, quartered by the two roots,
/// and each root's, which Vulkan allows as its inverse square root's 2 ulp and a division's
/// 2.5 (9u), the inner one halved by the outer: 14u; 16u.)
#[test]
fn lookup_matches_the_rust_filter() {
    let Some(r) = runner() else { return };
    for size in [32, 64] {
        let (e, avg) = tables(size);
        let lut = lut_buffer(&e, &avg);
        // The reference: the table as the GPU holds it (f32), filtered in f64.
        let mut e32 = e.clone();
        e32.values.iter_mut().for_each(|v| *v = *v as f32 as f64);
        let mut avg32 = avg.clone();
        avg32.values.iter_mut().for_each(|v| *v = *v as f32 as f64);
        let mut avg_l = avg.clone();
        avg_l.values = lookup_average(&e)
            .iter()
            .map(|&v| v as f32 as f64)
            .collect();
        let n = size as f64;
        let mut xs = vec![-0.25, 0.0, 0.25 / n, 1.0 - 0.25 / n, 1.0, 1.25, 0.3, 0.6543];
        for i in 0..size {
            let c = (i as f64 + 0.5) / n;
            xs.extend([c, c + 0.5 / n, c - 1e-6, c + 1e-6, c + 0.123 / n]);
        }
        let xs: Vec<f32> = xs.iter().map(|&x| x as f32).collect();
        let alphas = [[0.05f32, 0.05], [0.3, 0.05], [1.0, 0.25], [0.7, 0.7]];
        let mut input = Vec::new();
        for (k, &xr) in xs.iter().enumerate() {
            for &xm in &xs {
                let a = alphas[k % alphas.len()];
                input.push([xr, xm, a[0], a[1]]);
            }
        }
        let out = r.run(&r.lookup, &input, 1, &lut);
        let (mut worst, mut worst_avg, mut worst_coord) = (0.0f64, 0.0f64, 0.0f64);
        for (x, g) in input.iter().zip(&out) {
            let (xr, xm) = (x[0] as f64, x[1] as f64);
            // The slopes between the neighbours the filter blends (per unit t).
            let slope = |l: &Lut, xs: &[f64], axis: usize| {
                let nn = l.dims()[axis] as f64;
                let mut lo = xs.to_vec();
                let mut hi = xs.to_vec();
                lo[axis] = xs[axis] - 1.0 / nn;
                hi[axis] = xs[axis] + 1.0 / nn;
                let v = l.lookup(xs)[0];
                (l.lookup(&lo)[0] - v)
                    .abs()
                    .max((l.lookup(&hi)[0] - v).abs())
            };
            let want = e32.lookup(&[xr, xm])[0];
            let bound =
                2.0 * U * n * (slope(&e32, &[xr, xm], 0) + slope(&e32, &[xr, xm], 1)) + 8.0 * U;
            let d = (g[0] as f64 - want).abs();
            assert!(
                d <= bound,
                "size {size}: E at ({xr}, {xm}): GPU {} Rust {want} (bound {bound:e})",
                g[0]
            );
            worst = worst.max(d / bound);
            for (l, gv) in [(&avg32, g[1]), (&avg_l, g[2])] {
                let want = l.lookup(&[xr])[0];
                let bound = 2.0 * U * n * slope(l, &[xr], 0) + 8.0 * U;
                let d = (gv as f64 - want).abs();
                assert!(
                    d <= bound,
                    "size {size}: E_avg at {xr}: GPU {gv} Rust {want}"
                );
                worst_avg = worst_avg.max(d / bound);
            }
            let want = (x[2] as f64 * x[3] as f64).sqrt().sqrt();
            let d = (g[3] as f64 - want).abs() / want;
            assert!(
                d <= 16.0 * U,
                "roughness coordinate of {x:?}: {} vs {want}",
                g[3]
            );
            worst_coord = worst_coord.max(d / (16.0 * U));
        }
        println!(
            "size {size}: {} lookups; largest error / bound: E {worst:.3}, E_avg {worst_avg:.3}, \
             roughness coordinate {worst_coord:.3}",
            input.len()
        );
    }
}

/// Tanh-sinh nodes and weights on [a, b] at step 2^−level (x = a + (b − a)(1 + tanh(π/2 sinh
/// t))/2, each node's distance from its nearer end formed without cancellation), until the
/// weights fall below 1e-18 of the panel.
fn tanh_sinh(a: f64, b: f64, level: u32) -> Vec<(f64, f64)> {
    let h = 0.5f64.powi(level as i32);
    let len = b - a;
    let half_pi = std::f64::consts::FRAC_PI_2;
    let mut nodes = vec![(a + 0.5 * len, len * h * half_pi * 0.5)];
    for k in 1.. {
        let t = k as f64 * h;
        let q = (-2.0 * half_pi * t.sinh()).exp();
        let d = len * q / (1.0 + q);
        let w = len * h * half_pi * t.cosh() * 2.0 * q / ((1.0 + q) * (1.0 + q));
        if w < 1e-18 * len {
            break;
        }
        nodes.push((a + d, w));
        nodes.push((b - d, w));
    }
    nodes
}

/// The product rule of the furnace at μo for a table of n μ nodes: (μi, φi, weight with the
/// cosine and the φ symmetry folded in). μi in panels split at μo (the mirror direction's μ,
/// where the single-scattering lobe peaks) and at the n texel centres (where the looked-up E,
/// linear between them, has kinks: Kulla–Conty's lobe is a polynomial on each panel); the
/// two panels at μo at level `near`, the others at `far`. φi ∈ [0, π] (f is even in φi; the
/// mirror at π, an end of the panel, where tanh-sinh's nodes crowd) at level `phi`.
fn rule(mu_o: f64, n: usize, near: u32, far: u32, phi: u32) -> Vec<(f64, f64, f64)> {
    let mut cuts: Vec<f64> = vec![0.0, mu_o, 1.0];
    cuts.extend((0..n).map(|j| (j as f64 + 0.5) / n as f64));
    cuts.sort_by(f64::total_cmp);
    cuts.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    let phis = tanh_sinh(0.0, std::f64::consts::PI, phi);
    let mut out = Vec::new();
    for p in cuts.windows(2) {
        let level = if p[0] == mu_o || p[1] == mu_o {
            near
        } else {
            far
        };
        for (mu, wm) in tanh_sinh(p[0], p[1], level) {
            for &(ph, wp) in &phis {
                out.push((mu, ph, 2.0 * wm * wp * mu));
            }
        }
    }
    out
}

/// wo at μo (φo = 0) and wi at (μi, φi).
fn direction(mu: f64, phi: f64) -> [f64; 3] {
    let s = ((1.0 - mu) * (1.0 + mu)).max(0.0).sqrt();
    [s * phi.cos(), s * phi.sin(), mu]
}

const ALPHAS: [f64; 7] = [0.05, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0];
const MUS: [f64; 8] = [0.05, 0.1, 0.2, 0.35, 0.5, 0.7, 0.85, 1.0];
/// The rule's levels: the panels at μo, the others, φ.
const LEVELS: (u32, u32, u32) = (4, 2, 4);

/// The rule integrates the single-scattering lobe (the Rust f64 conductor, F = 1) to its
/// albedo, `single_scattering_albedo` (adaptive, 1e-9): what the furnace's sums inherit.
#[test]
fn the_rule_integrates_the_single_scattering_lobe() {
    let mut worst = 0.0f64;
    for &alpha in &ALPHAS {
        let d = Microfacet::<f64, Ggx>::new(alpha, alpha).expect("α");
        let b = RoughConductor::new(d.clone(), One::<1>);
        for &mu_o in &MUS {
            let wo = direction(mu_o, 0.0);
            let e = single_scattering_albedo(&d, wo);
            let nodes = rule(mu_o, 32, LEVELS.0, LEVELS.1, LEVELS.2);
            let q: f64 = nodes
                .iter()
                .map(|&(mu, ph, w)| w * b.eval(wo, direction(mu, ph))[0])
                .sum();
            println!(
                "α {alpha} μo {mu_o}: {} nodes, rule − E = {:.2e}",
                nodes.len(),
                q - e
            );
            worst = worst.max((q - e).abs());
        }
    }
    println!("largest |rule − E| {worst:.2e}");
}

/// One furnace point: the rule's sums of the GPU's f cos θi for the four lobes (Kulla–Conty
/// with the exact E_avg, with the lookup's, Turquin, none), E and E_l (f64, the f32 table).
struct Point {
    alpha: f64,
    mu_o: f64,
    sums: [f64; 4],
    e: f64,
    e_l: f64,
}

/// The furnace over ALPHAS × MUS with the tables of `size` nodes, on the GPU.
fn furnace(r: &Runner, size: usize) -> Vec<Point> {
    let (e, avg) = tables(size);
    let lut = lut_buffer(&e, &avg);
    let mut e32 = e.clone();
    e32.values.iter_mut().for_each(|v| *v = *v as f32 as f64);
    let mut points = Vec::new();
    for &alpha in &ALPHAS {
        let d = Microfacet::<f64, Ggx>::new(alpha, alpha).expect("α");
        let mut input = Vec::new();
        let mut rules = Vec::new();
        for &mu_o in &MUS {
            let wo = direction(mu_o, 0.0).map(|v| v as f32);
            let nodes = rule(mu_o, size, LEVELS.0, LEVELS.1, LEVELS.2);
            for &(mu, ph, _) in &nodes {
                let wi = direction(mu, ph).map(|v| v as f32);
                input.push([wo[0], wo[1], wo[2], alpha as f32]);
                input.push([wi[0], wi[1], wi[2], 0.0]);
            }
            rules.push(nodes);
        }
        let out = r.run(&r.furnace, &input, 2, &lut);
        let mut at = 0;
        for (&mu_o, nodes) in MUS.iter().zip(&rules) {
            let mut sums = [0.0f64; 4];
            for (&(_, _, w), g) in nodes.iter().zip(&out[at..]) {
                for (s, &v) in sums.iter_mut().zip(g) {
                    *s += w * v as f64;
                }
            }
            at += nodes.len();
            let x = [(alpha as f32 as f64).sqrt(), mu_o as f32 as f64];
            points.push(Point {
                alpha,
                mu_o,
                sums,
                e: single_scattering_albedo(&d, direction(mu_o, 0.0)),
                e_l: e32.lookup(&x)[0],
            });
        }
    }
    points
}

/// The slope of `l`'s filter per unit of an axis' t at `x`: the largest change over one texel
/// either way (what a rounding of t moves the value by, per unit).
fn slope(l: &Lut, x: &[f64], axis: usize) -> f64 {
    let n = l.dims()[axis] as f64;
    let (mut lo, mut hi) = (x.to_vec(), x.to_vec());
    lo[axis] -= 1.0 / n;
    hi[axis] += 1.0 / n;
    let v = l.lookup(x)[0];
    (l.lookup(&lo)[0] - v)
        .abs()
        .max((l.lookup(&hi)[0] - v).abs())
}

/// The white furnace of the F = 1 compensated GGX conductor on the GPU, at α ∈ [0.05, 1] and
/// μo ∈ [0.05, 1] with tables of 32 and 64 nodes. The sums against their identities:
///
/// * single scattering: the rule integrates the lobe to 1e-10 in f64
///   (`the_rule_integrates_the_single_scattering_lobe`); the GPU's f are f32 (each within the
///   bounds of tests/lavapipe.rs: 6e-6 relative plus the half vector's rounding times D's
///   condition number, largest on a narrow lobe's flanks), so the sum is held to `SS_TOL`.
/// * Kulla–Conty's added energy, KC − ss (with E_avg the lookup's average), is 1 − E_l(μo)
///   within: e_o's lookup (the filter's bound of `lookup_matches_the_rust_filter`), the
///   lobe's normalisation 1 − E_avg from f32 nodes and an f32 blend (6u/(1 − E_avg)
///   relative: the nodes' and average's roundings over what is lost), F_ms's and the
///   products' roundings (8u relative), and each f + f_ms's rounding (4u absolute over the sum).
/// * Turquin: TQ = ss (1 + (1 − E_l)/E_l) within e_o's lookup error through 1/E_l², and the
///   scale's roundings (4u relative).
///
/// Then |KC − 1 − (E − E_l)| and |TQ − E/E_l| follow, and |furnace − 1| is reported: it is
/// the table's own filter error E − E_l (Turquin: over E_l).
#[test]
fn white_furnace_on_the_gpu() {
    let Some(r) = runner() else { return };
    // (Measured 1.4e-6 on lavapipe, at α = 0.05, μo = 0.05; elsewhere ≤ 2e-7.)
    const SS_TOL: f64 = 5e-6;
    for size in [32usize, 64] {
        let t = std::time::Instant::now();
        let points = furnace(r, size);
        let (e, _) = tables(size);
        let mut e32 = e.clone();
        e32.values.iter_mut().for_each(|v| *v = *v as f32 as f64);
        let avg_l = lookup_average(&e32);
        let n = size as f64;
        let (mut worst_kc, mut worst_kcx, mut worst_tq, mut worst_id, mut gap) =
            (0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64);
        let mut over = Vec::new();
        for p in &points {
            let [kx, kl, tq, ss] = p.sums;
            let at = format!("size {size} α {} μo {}", p.alpha, p.mu_o);
            assert!((ss - p.e).abs() <= SS_TOL, "{at}: ss {ss} E {}", p.e);
            let x = [(p.alpha as f32 as f64).sqrt(), p.mu_o as f32 as f64];
            let lookup = 2.0 * U * n * (slope(&e32, &x, 0) + slope(&e32, &x, 1)) + 8.0 * U;
            // E_avg of the lookup at the table's roughness (row averages blended as the E).
            let t_r = (x[0] * n - 0.5).clamp(0.0, n - 1.0);
            let i = (t_r.floor() as usize).min(size - 2);
            let f = t_r - i as f64;
            let e_avg = (1.0 - f) * avg_l[i] + f * avg_l[i + 1];
            let lost = 1.0 - p.e_l;
            let ms_tol = lookup + lost * (6.0 * U / (1.0 - e_avg) + 8.0 * U) + 4.0 * U;
            let ms = kl - ss;
            assert!(
                (ms - lost).abs() <= ms_tol,
                "{at}: KC − ss {ms} against 1 − E_l {lost} (bound {ms_tol:e})"
            );
            let tq_tol = ss * (lookup / (p.e_l * p.e_l) + 4.0 * U / p.e_l);
            let want = ss / p.e_l;
            assert!(
                (tq - want).abs() <= tq_tol,
                "{at}: Turquin {tq} against ss/E_l {want} (bound {tq_tol:e})"
            );
            // The furnace's identities, from the two above and the single-scattering sum.
            let id_kc = (kl - 1.0) - (p.e - p.e_l);
            let id_tq = tq - p.e / p.e_l;
            assert!(id_kc.abs() <= SS_TOL + ms_tol, "{at}: {id_kc:e}");
            assert!(id_tq.abs() <= SS_TOL / p.e_l + tq_tol, "{at}: {id_tq:e}");
            worst_id = worst_id.max(id_kc.abs()).max(id_tq.abs());
            worst_kc = worst_kc.max((kl - 1.0).abs());
            worst_kcx = worst_kcx.max((kx - 1.0).abs());
            worst_tq = worst_tq.max((tq - 1.0).abs());
            gap = gap.max((kx - kl).abs());
            if (kl - 1.0).abs() > 1e-3 {
                over.push(format!("(α {}, μo {}): {:+.1e}", p.alpha, p.mu_o, kl - 1.0));
            }
        }
        println!(
            "size {size} ({:.0} s, {} points): max |furnace − 1| Kulla–Conty {worst_kc:.2e} \
             (with the exact E_avg {worst_kcx:.2e}; the two differ by ≤ {gap:.1e}), Turquin \
             {worst_tq:.2e}; identities within {worst_id:.1e}",
            t.elapsed().as_secs_f64(),
            points.len()
        );
        println!("  Kulla–Conty past 1e-3 at {}", over.join(", "));
    }
}

/// The furnace at other table sizes, by its identity (the GPU's sums are 1 + E − E_l within
/// 2e-6, `white_furnace_on_the_gpu`): E − E_l with E_l blended from the four nodes around
/// (√α, μo), each node's E by `single_scattering_albedo` (the table's nodes, to 1e-8).
#[test]
fn furnace_by_table_size() {
    let e_at = |alpha: f64, mu: f64| {
        let d = Microfacet::<f64, Ggx>::new(alpha, alpha).expect("α");
        single_scattering_albedo(&d, direction(mu, 0.0))
    };
    for size in [32usize, 64, 128, 256, 512] {
        let n = size as f64;
        let tap = |x: f64| {
            let t = (x * n - 0.5).clamp(0.0, n - 1.0);
            let i = (t.floor() as usize).min(size - 2);
            (i, t - i as f64)
        };
        let centre = |i: usize| (i as f64 + 0.5) / n;
        let (mut worst, mut worst_inside) = (0.0f64, 0.0f64);
        let mut over = Vec::new();
        for &alpha in &ALPHAS {
            let (ir, fr) = tap(alpha.sqrt());
            for &mu_o in &MUS {
                let (im, fm) = tap(mu_o);
                let v = |a: usize, b: usize| e_at(centre(ir + a).powi(2), centre(im + b));
                let e_l = (1.0 - fr) * (1.0 - fm) * v(0, 0)
                    + fr * (1.0 - fm) * v(1, 0)
                    + (1.0 - fr) * fm * v(0, 1)
                    + fr * fm * v(1, 1);
                let d = e_at(alpha, mu_o) - e_l;
                worst = worst.max(d.abs());
                let inside = alpha.sqrt() <= centre(size - 1) && mu_o <= centre(size - 1);
                if inside {
                    worst_inside = worst_inside.max(d.abs());
                }
                if d.abs() > 1e-3 {
                    over.push(format!("(α {alpha}, μo {mu_o}) {d:+.1e}"));
                }
            }
        }
        println!(
            "size {size}: max |furnace − 1| {worst:.2e}, inside the last texel centres \
             {worst_inside:.2e}; past 1e-3: {}",
            over.join(", ")
        );
        // The filter's error falls as 1/n² between the centres (measured 2.6e-3, 1.6e-3,
        // 1.8e-4 at 32, 64, 128 nodes, largest at α = 0.05, μo = 0.05, where E bends most
        // along a linear μ axis): 1e-3 from 128 nodes on. Past the last centre (α = 1 is half
        // a texel beyond it) clamp-to-edge's error falls only as 1/n: 4.7e-3 at 128.
        if size >= 128 {
            assert!(worst_inside <= 1e-3, "size {size}: {worst_inside:e}");
        }
    }
}
