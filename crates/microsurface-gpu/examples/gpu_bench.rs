//! Throughput of the WGSL library on the first Vulkan adapter: samples and BSDF evaluations
//! per second, with the adapter printed.
//!
//! ```text
//! cargo build --release -p microsurface-gpu --example gpu_bench
//! target/release/examples/gpu_bench [log2 of the invocations, default 24] [rounds, default 9]
//! ```
//!
//! Each kernel (examples/gpu_bench.wgsl) runs 2^k invocations of 8 evaluations each, on
//! inputs hashed from the invocation's index on the GPU (no upload), and writes one sum per
//! invocation (no readback is timed). The time of a dispatch is the GPU's own, from timestamp
//! queries at the compute pass's start and end where the device has them, else the wall time
//! of submit + wait; the figure is the median over the rounds after one warm-up. The
//! `inputs` row is the kernel without the library call: the hashing's own cost, included in
//! the other rows. At the end, the same operations on one CPU thread through the Rust f32
//! path (`Microfacet<f32, Ggx>`, `RoughConductor`), for scale.

use microsurface::bsdf::fresnel::Conductor;
use microsurface::bsdf::{Bsdf, RoughConductor, RoughDielectric};
use microsurface::{Ggx, Microfacet, MicrofacetDistribution, NdfKind};
use microsurface_gpu::{groups, Gpu, Tables, WGSL};
use std::time::Instant;

/// Evaluations per invocation (ITER in the WGSL).
const ITER: u64 = 8;
const ALPHA: [f32; 2] = [0.3, 0.15];

/// The GGX and BSDF kernels (the door's NDF unused: GGX).
const KERNELS: [(&str, &str); 8] = [
    ("bench_inputs", "inputs (hash, directions; no library call)"),
    (
        "bench_ggx_sample",
        "GGX visible normal + pdf (spherical caps)",
    ),
    ("bench_ggx_sample_bounded", "GGX bounded VNDF + pdf"),
    ("bench_ggx_d_g2", "GGX D · G2 (height-correlated)"),
    (
        "bench_conductor_eval_pdf",
        "GGX conductor eval_pdf (complex Fresnel)",
    ),
    (
        "bench_conductor_sample",
        "GGX conductor sample (complex Fresnel)",
    ),
    (
        "bench_dielectric_eval_pdf",
        "GGX dielectric eval + pdf (η = 1.5)",
    ),
    ("bench_dielectric_sample", "GGX dielectric sample (η = 1.5)"),
];

/// The other NDFs through the door (`bench_door_sample`, `bench_door_d_g2`): name, MS_NDF_*,
/// and the material's own table where it has one (GTR at α = ALPHA[0], γ = 1.5).
type Shape = Option<(NdfKind, Option<f64>)>;
const DOOR: [(&str, u32, Shape); 9] = [
    ("Beckmann", 1, None),
    ("Double GGX", 2, None),
    ("Exponential", 3, None),
    ("GTR γ = 1.5 (α 0.3)", 4, None),
    ("Student-T γ = 2.5", 5, Some((NdfKind::StudentT, Some(2.5)))),
    ("Ei", 6, Some((NdfKind::Ei, None))),
    ("Erfc", 7, Some((NdfKind::Erfc, None))),
    ("K0", 8, Some((NdfKind::K0, None))),
    ("Bessel-K a = 1.5", 9, Some((NdfKind::BesselK, Some(1.5)))),
];

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let log2: u32 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(24);
    let rounds: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(9).max(1);
    // The door's materials' tables (GTR's at its α; the shapes').
    let mut tables = Tables::new();
    let gtr = tables
        .add_gtr(ALPHA[0] as f64, 1.5)
        .expect("a GTR material");
    let rows: Vec<u32> = DOOR
        .iter()
        .map(|&(_, ndf, shape)| match shape {
            Some((kind, s)) => tables.add_shape(kind, s).expect("a shape table"),
            None if ndf == 4 => gtr,
            None => 0,
        })
        .collect();
    let gpu = match Gpu::with_tables(&tables) {
        Ok(g) => g,
        Err(e) => {
            eprintln!("gpu_bench: {e}");
            std::process::exit(2);
        }
    };
    let info = gpu.adapter_info();
    println!(
        "adapter: {} ({:?}, {:?}; vendor {:#06x} device {:#06x}; driver {} {})",
        info.name,
        info.device_type,
        info.backend,
        info.vendor,
        info.device,
        info.driver,
        info.driver_info
    );
    let n: u64 = 1 << log2;
    println!(
        "{n} invocations × {ITER} evaluations per dispatch, median of {rounds} rounds; timing: {}",
        if gpu.has_timestamps() {
            "GPU timestamp queries (pass start to end)"
        } else {
            "wall clock, submit to wait"
        }
    );
    let source = format!("{WGSL}\n{}", include_str!("gpu_bench.wgsl"));
    let program = gpu.program(&source).unwrap_or_else(|e| panic!("{e}"));
    let params = gpu.storage(32);
    let set_params = |alpha: [f32; 2], ndf: u32, row: u32| {
        let p = [
            [
                alpha[0],
                alpha[1],
                f32::from_bits(n as u32),
                f32::from_bits(0x9e37_79b9),
            ],
            [f32::from_bits(ndf), f32::from_bits(row), 0.0, 0.0],
        ];
        gpu.queue()
            .write_buffer(&params, 0, bytemuck::cast_slice(&p));
    };
    set_params(ALPHA, 0, 0);
    let out = gpu.storage(n * 4);
    let bind = gpu.bind(&program, &params, &out);
    println!(
        "{:<46} {:>12} {:>16}",
        "kernel", "ms/dispatch", "evaluations/s"
    );
    let time_kernel = |entry: &str, label: &str, constants: &[(&str, f64)]| {
        let pipeline = gpu
            .pipeline_with(&program, entry, constants)
            .unwrap_or_else(|e| panic!("{e}"));
        let mut times = Vec::new();
        for r in 0..=rounds {
            let t = dispatch(&gpu, &pipeline, &bind, n);
            if r > 0 {
                times.push(t);
            }
        }
        times.sort_by(f64::total_cmp);
        let t = times[times.len() / 2];
        println!(
            "{label:<46} {:>12.3} {:>16.3e}",
            t * 1e3,
            (n * ITER) as f64 / t
        );
    };
    for (entry, label) in KERNELS {
        time_kernel(entry, label, &[]);
    }
    for (&(name, ndf, _), &row) in DOOR.iter().zip(&rows) {
        // (GTR's table is isotropic: its α for both.)
        let alpha = if ndf == 4 { [ALPHA[0]; 2] } else { ALPHA };
        set_params(alpha, ndf, row);
        // The door as a renderer of one NDF specialises it (MS_DOOR_NDFS = that NDF's bit),
        // and as one that may meet any (the default).
        let one = [("MS_DOOR_NDFS", (1u32 << ndf) as f64)];
        for (how, constants) in [("", &one[..]), (", any NDF", &[][..])] {
            time_kernel(
                "bench_door_sample",
                &format!("{name} visible normal + pdf{how}"),
                constants,
            );
            time_kernel("bench_door_d_g2", &format!("{name} D · G2{how}"), constants);
        }
    }
    cpu_reference();
}

/// One dispatch of `pipeline` over n invocations: its GPU time in seconds (timestamps), or
/// the wall time of submit + wait.
fn dispatch(gpu: &Gpu, pipeline: &wgpu::ComputePipeline, bind: &wgpu::BindGroup, n: u64) -> f64 {
    let device = gpu.device();
    let queries = gpu.has_timestamps().then(|| {
        let set = device.create_query_set(&wgpu::QuerySetDescriptor {
            label: Some("timestamps"),
            ty: wgpu::QueryType::Timestamp,
            count: 2,
        });
        let resolve = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("resolve"),
            size: 16,
            usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let read = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("timestamps read"),
            size: 16,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        (set, resolve, read)
    });
    let mut enc = device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
    {
        let mut pass = enc.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: None,
            timestamp_writes: queries.as_ref().map(|(set, _, _)| {
                wgpu::ComputePassTimestampWrites {
                    query_set: set,
                    beginning_of_pass_write_index: Some(0),
                    end_of_pass_write_index: Some(1),
                }
            }),
        });
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, bind, &[]);
        pass.set_bind_group(1, gpu.tables(), &[]);
        let (x, y) = groups(n);
        pass.dispatch_workgroups(x, y, 1);
    }
    if let Some((set, resolve, read)) = &queries {
        enc.resolve_query_set(set, 0..2, resolve, 0);
        enc.copy_buffer_to_buffer(resolve, 0, read, 0, 16);
    }
    let start = Instant::now();
    gpu.queue().submit([enc.finish()]);
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .expect("the dispatch completes");
    let wall = start.elapsed().as_secs_f64();
    let Some((_, _, read)) = queries else {
        return wall;
    };
    let (tx, rx) = std::sync::mpsc::channel();
    read.slice(..).map_async(wgpu::MapMode::Read, move |r| {
        let _ = tx.send(r);
    });
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .expect("the readback completes");
    rx.recv().expect("mapped").expect("mapped");
    let view = read.get_mapped_range(..).expect("mapped");
    let t: &[u64] = bytemuck::cast_slice(&view[..]);
    let ticks = t[1].wrapping_sub(t[0]) as f64;
    drop(view);
    read.unmap();
    ticks * gpu.queue().get_timestamp_period() as f64 * 1e-9
}

/// A CPU input: (wo, wi, u).
type Input = ([f32; 3], [f32; 3], [f32; 2]);

/// The same operations through the Rust f32 path on one CPU thread (2^20 evaluations each,
/// inputs precomputed), for scale.
fn cpu_reference() {
    let m = Microfacet::<f32, Ggx>::new(ALPHA[0], ALPHA[1]).expect("α in range");
    let gold = RoughConductor::new(
        m.clone(),
        Conductor {
            eta: [0.143f32, 0.374, 1.442],
            k: [3.983, 2.385, 1.603],
        },
    );
    let mut s = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 40) as f32 / 16_777_216.0
    };
    let dir = |c: f32, v: f32| {
        let sn = (1.0 - c * c).max(0.0).sqrt();
        let (si, co) = (std::f32::consts::TAU * v).sin_cos();
        [sn * co, sn * si, c]
    };
    let k = 1 << 20;
    let inputs: Vec<Input> = (0..k)
        .map(|_| {
            let wo = dir(0.05 + 0.95 * next(), next());
            let wi = dir(0.05 + 0.95 * next(), next());
            (wo, wi, [next(), next()])
        })
        .collect();
    println!("CPU, one thread, Rust f32 path (for scale):");
    let time = |label: &str, f: &dyn Fn(&Input) -> f32| {
        let mut best = f64::INFINITY;
        let mut acc = 0.0f32;
        for _ in 0..3 {
            let t = Instant::now();
            for x in &inputs {
                acc += f(std::hint::black_box(x));
            }
            best = best.min(t.elapsed().as_secs_f64());
        }
        std::hint::black_box(acc);
        println!("{label:<46} {:>12} {:>16.3e}", "", k as f64 / best);
    };
    time("GGX visible normal + pdf (spherical caps)", &|x| {
        let s = m.sample(x.0, x.2);
        s.wm[0] + s.pdf
    });
    time("GGX bounded VNDF + pdf", &|x| {
        let s = m.sample_bounded(x.0, x.2);
        s.wm[0] + s.pdf
    });
    time("GGX D · G2 (height-correlated)", &|x| {
        m.d(x.1) * m.g2(x.0, x.1)
    });
    time("GGX conductor eval_pdf (complex Fresnel)", &|x| {
        let (f, p) = gold.eval_pdf(x.0, x.1);
        f[0] + f[1] + f[2] + p
    });
    let glass = RoughDielectric::new(m.clone(), 1.5f32).unwrap();
    time("GGX conductor sample (complex Fresnel)", &|x| {
        gold.sample(x.0, 0.5, x.2)
            .map_or(0.0, |s| s.wi[0] + s.pdf + s.f[1])
    });
    time("GGX dielectric eval + pdf (η = 1.5)", &|x| {
        // (Half the pairs transmitted, as in the GPU kernel.)
        let wi = if x.2[0] < 0.5 {
            x.1
        } else {
            [x.1[0], x.1[1], -x.1[2]]
        };
        glass.eval(x.0, wi)[0] + glass.pdf(x.0, wi)
    });
    time("GGX dielectric sample (η = 1.5)", &|x| {
        glass
            .sample(x.0, x.1[0] * 0.5 + 0.5, x.2)
            .map_or(0.0, |s| s.wi[0] + s.pdf + s.f[1])
    });
}
