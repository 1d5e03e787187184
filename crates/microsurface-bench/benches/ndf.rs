//! Per-call cost of the exact f64 library against the textbook C baseline, measured side by
//! side in one process: `cargo bench -p microsurface-bench`. Inputs are random (u, α) (and γ),
//! 4096 of them cycled, so no call sees a repeated value. Each figure is the median of 15 runs.
//! Results and their discussion: BENCHMARKS.md.

use microsurface::distribution::Shape;
use microsurface::fast::Real;
use microsurface::sampling::sample_dcos;
use microsurface::{
    AnyNdf, Beckmann, DoubleGgx, Exact, Exponential, Ggx, Gtr, Microfacet, MicrofacetDistribution,
    Ndf, NdfKind, Vec3,
};
use microsurface_bench as c;
use std::hint::black_box;
use std::time::Instant;

const N: usize = 4096;

struct Inputs {
    u: Vec<f64>,
    alpha: Vec<f64>,
    gamma: Vec<f64>,
    xi: Vec<[f64; 2]>,
    w: Vec<Vec3>,
}

fn inputs() -> Inputs {
    let mut s = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut i = Inputs {
        u: vec![],
        alpha: vec![],
        gamma: vec![],
        xi: vec![],
        w: vec![],
    };
    for _ in 0..N {
        i.u.push(0.02 + 0.97 * next());
        i.alpha.push(0.05 + 0.95 * next());
        i.gamma.push(0.5 + 2.5 * next());
        i.xi.push([next(), next()]);
        let t: f64 = 1.5 * next();
        let p = std::f64::consts::TAU * next();
        i.w.push(Vec3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos()));
    }
    i
}

/// Median ns per call of `f(i)` over 15 runs of `calls` calls. Not inlined: each closure gets
/// a loop function of its own, as in a user's code, instead of sharing registers and code
/// placement with the rest of a long benchmark function (which cost the Exponential σ(−u)
/// 2 ns, 8.8 against 10.7 ns, in one measurement).
#[inline(never)]
fn time(calls: usize, mut f: impl FnMut(usize) -> f64) -> f64 {
    let mut runs = Vec::new();
    for _ in 0..15 {
        let start = Instant::now();
        let mut acc = 0.0;
        for k in 0..calls {
            acc += f(k % N);
        }
        black_box(acc);
        runs.push(start.elapsed().as_secs_f64() * 1e9 / calls as f64);
    }
    runs.sort_by(f64::total_cmp);
    runs[runs.len() / 2]
}

/// Median ns per call of `f` and of `g`, over 15 rounds in which they run in turn (so that a
/// slow stretch of the machine falls on both alike): the pairs of the type-vs-free rows.
#[inline(never)]
fn paired(
    calls: usize,
    mut f: impl FnMut(usize) -> f64,
    mut g: impl FnMut(usize) -> f64,
) -> (f64, f64) {
    let (mut tf, mut tg) = (Vec::new(), Vec::new());
    for _ in 0..15 {
        tf.push(once(calls, &mut f));
        tg.push(once(calls, &mut g));
    }
    (median(tf), median(tg))
}

/// ns per call of one run of `calls` calls of `f` (its own loop function).
#[inline(never)]
fn once(calls: usize, f: &mut impl FnMut(usize) -> f64) -> f64 {
    let start = Instant::now();
    let mut acc = 0.0;
    for k in 0..calls {
        acc += f(k % N);
    }
    black_box(acc);
    start.elapsed().as_secs_f64() * 1e9 / calls as f64
}

/// A visible normal from the renderer-facing type (whose implementation the fast samplers
/// are), the material built in the call (its validation, about a nanosecond, is in the
/// figure).
#[inline(always)]
fn type_vndf<N: Shape<Data = ()>, F: Real>(w: [F; 3], a: F, xi: [F; 2]) -> [F; 3] {
    Microfacet::<F, N>::new(a, a).unwrap().sample_wm(w, xi)
}

/// A D·cos normal from the renderer-facing type (as [`type_vndf`]).
#[inline(always)]
fn type_dcos<N: Shape<Data = ()>, F: Real>(a: F, xi: [F; 2]) -> [F; 3] {
    Microfacet::<F, N>::new(a, a).unwrap().sample_dcos(xi).wm
}

/// Prepared GTR materials in both precisions (the fitted tables are built once per material).
struct GtrMaterials {
    m64: Vec<Microfacet<f64, Gtr>>,
    m32: Vec<Microfacet<f32, Gtr>>,
}

impl GtrMaterials {
    fn new(alpha: impl Fn(usize) -> f64, gamma: impl Fn(usize) -> f64) -> Self {
        GtrMaterials {
            m64: (0..64)
                .map(|k| Microfacet::gtr(alpha(k), alpha(k), gamma(k)).unwrap())
                .collect(),
            m32: (0..64)
                .map(|k| Microfacet::gtr(alpha(k) as f32, alpha(k) as f32, gamma(k)).unwrap())
                .collect(),
        }
    }
}

/// The material of input k in the precision of F.
trait PickGtr<F: Real> {
    fn pick(&self, k: usize) -> &Microfacet<F, Gtr>;
}
impl PickGtr<f64> for GtrMaterials {
    fn pick(&self, k: usize) -> &Microfacet<f64, Gtr> {
        &self.m64[k % 64]
    }
}
impl PickGtr<f32> for GtrMaterials {
    fn pick(&self, k: usize) -> &Microfacet<f32, Gtr> {
        &self.m32[k % 64]
    }
}

fn row(name: &str, ns: f64, base: Option<(&str, f64)>) {
    match base {
        Some((b, t)) => println!("{name:44} {ns:10.1} ns   {:6.2}× {b}", ns / t),
        None => println!("{name:44} {ns:10.1} ns"),
    }
}

fn main() {
    let i = inputs();
    let big = 400_000;
    if std::env::var("MICROSURFACE_BENCH").as_deref() == Ok("vndf") {
        // Only the fast samplers (a quick loop while working on them).
        use microsurface::fast::ggx as fg;
        let lambda = time(big, |k| fg::lambda(black_box(i.u[k]), i.alpha[k]));
        let vndf = time(big, |k| {
            let w = i.w[k];
            type_vndf::<Ggx, f64>([w.x, w.y, w.z], i.alpha[k], black_box(i.xi[k]))[2]
        });
        row("us fast GGX Λ f64", lambda, None);
        row("us fast GGX VNDF f64", vndf, None);
        mixture_vndf(&i, big, lambda, vndf);
        return;
    }
    if std::env::var("MICROSURFACE_BENCH").as_deref() == Ok("sampler") {
        // GGX and Beckmann visible normals through the public door against the C GGX
        // sampler, each pair interleaved (issue 35's first two targets).
        samplers_vs_c(&i, big);
        return;
    }
    if std::env::var("MICROSURFACE_BENCH").as_deref() == Ok("exact") {
        // The exact path's Λ, G1 and σ(−u) of every NDF (issue 35, target 6).
        exact_path(&i);
        return;
    }
    if std::env::var("MICROSURFACE_BENCH").as_deref() == Ok("walk") {
        // Only the microsurface random walk.
        walks(&i);
        return;
    }
    if std::env::var("MICROSURFACE_BENCH").as_deref() == Ok("walk-lanes") {
        // The interleaved walks of `albedo` against one walk after another (target 7).
        walk_lanes();
        return;
    }
    if std::env::var("MICROSURFACE_BENCH").as_deref() == Ok("wavefront") {
        // Only the wavefront slices.
        wavefront(&i);
        return;
    }
    if std::env::var("MICROSURFACE_BENCH").as_deref() == Ok("type") {
        // Only the Microfacet type against the fast free functions.
        microfacet_type(&i, big);
        return;
    }
    if std::env::var("MICROSURFACE_BENCH").as_deref() == Ok("construct") {
        // Materials built per call (issue 45): construction per NDF, first use and after,
        // the compensated BSDFs, and the textured rows.
        construction(&i);
        return;
    }
    if std::env::var("MICROSURFACE_BENCH").as_deref() == Ok("any") {
        // Only the run-time door against the static type.
        any_door(&i, big);
        return;
    }
    if std::env::var("MICROSURFACE_BENCH").as_deref() == Ok("matrix") {
        // Only the table of every fast quantity.
        matrix(&i, big);
        return;
    }
    if std::env::var("MICROSURFACE_BENCH").as_deref() == Ok("fitted") {
        // Only the fitted fast paths and the slices (a quick loop while working on them).
        use microsurface::fast::ggx as fg;
        let (u32s, a32s): (Vec<f32>, Vec<f32>) = (
            i.u.iter().map(|&x| x as f32).collect(),
            i.alpha.iter().map(|&x| x as f32).collect(),
        );
        let l64 = time(big, |k| fg::lambda(black_box(i.u[k]), i.alpha[k]));
        let l32 = time(big, |k| fg::lambda(black_box(u32s[k]), a32s[k]) as f64);
        let exact = time(big, |k| {
            Ggx::new(i.alpha[k]).unwrap().lambda(black_box(i.u[k]))
        });
        row("us fast GGX Λ f64", l64, None);
        row("us fast GGX Λ f32", l32, None);
        row("us GGX Λ", exact, None);
        fitted_fast_paths(&i, big, l64, l32, exact);
        batches(&i);
        return;
    }
    println!(
        "{:44} {:>13}   ratio",
        "function (f64, random inputs)", "per call"
    );

    // GGX and Beckmann against the C baseline.
    let c_ggx_d = time(big, |k| c::ggx_d(black_box(i.u[k]), i.alpha[k]));
    let ggx_d = time(big, |k| Ggx::new(i.alpha[k]).unwrap().d(black_box(i.u[k])));
    row("C  GGX D", c_ggx_d, None);
    row("us GGX D", ggx_d, Some(("C GGX D", c_ggx_d)));
    let c_ggx_l = time(big, |k| c::ggx_lambda(black_box(i.u[k]), i.alpha[k]));
    let ggx_l = time(big, |k| {
        Ggx::new(i.alpha[k]).unwrap().lambda(black_box(i.u[k]))
    });
    row("C  GGX Λ", c_ggx_l, None);
    row("us GGX Λ", ggx_l, Some(("C GGX Λ", c_ggx_l)));
    let c_ggx_g1 = time(big, |k| {
        1.0 / (1.0 + c::ggx_lambda(black_box(i.u[k]), i.alpha[k]))
    });
    let ggx_g1 = time(big, |k| Ggx::new(i.alpha[k]).unwrap().g1(black_box(i.u[k])));
    row("C  GGX G1", c_ggx_g1, None);
    row("us GGX G1", ggx_g1, Some(("C GGX G1", c_ggx_g1)));
    let ggx_g2 = time(big, |k| {
        Ggx::new(i.alpha[k])
            .unwrap()
            .g2(black_box(i.u[k]), i.u[(k + 1) % N])
    });
    row(
        "us GGX G2 (height-correlated)",
        ggx_g2,
        Some(("C GGX G1", c_ggx_g1)),
    );
    let c_b_d = time(big, |k| c::beckmann_d(black_box(i.u[k]), i.alpha[k]));
    let b_d = time(big, |k| {
        Beckmann::new(i.alpha[k]).unwrap().d(black_box(i.u[k]))
    });
    row("C  Beckmann D", c_b_d, None);
    row("us Beckmann D", b_d, Some(("C Beckmann D", c_b_d)));
    let c_b_l = time(big, |k| c::beckmann_lambda(black_box(i.u[k]), i.alpha[k]));
    let b_l = time(big, |k| {
        Beckmann::new(i.alpha[k]).unwrap().lambda(black_box(i.u[k]))
    });
    row("C  Beckmann Λ", c_b_l, None);
    row("us Beckmann Λ", b_l, Some(("C Beckmann Λ", c_b_l)));
    let c_vndf = time(big, |k| {
        let w = i.w[k];
        c::ggx_vndf([w.x, w.y, w.z], i.alpha[k], i.alpha[k], black_box(i.xi[k]))[2]
    });
    let vndf = time(big, |k| {
        let a = i.alpha[k];
        Exact::new(NdfKind::Ggx, a, a, None)
            .unwrap()
            .sample_wm(i.w[k].into(), black_box(i.xi[k]))[2]
    });
    row("C  GGX VNDF (Heitz 2018)", c_vndf, None);
    row(
        "us GGX VNDF (spherical caps)",
        vndf,
        Some(("C GGX VNDF", c_vndf)),
    );

    // The fast paths (microsurface::fast) against the same C baseline, f64 and f32.
    use microsurface::fast::{beckmann as fb, ggx as fg};
    let (u32s, a32s): (Vec<f32>, Vec<f32>) = (
        i.u.iter().map(|&x| x as f32).collect(),
        i.alpha.iter().map(|&x| x as f32).collect(),
    );
    let pairs: [(&str, f64, f64); 4] = [
        (
            "GGX D",
            c_ggx_d,
            time(big, |k| fg::d(black_box(i.u[k]), i.alpha[k])),
        ),
        (
            "GGX Λ",
            c_ggx_l,
            time(big, |k| fg::lambda(black_box(i.u[k]), i.alpha[k])),
        ),
        (
            "Beckmann D",
            c_b_d,
            time(big, |k| fb::d(black_box(i.u[k]), i.alpha[k])),
        ),
        (
            "Beckmann Λ",
            c_b_l,
            time(big, |k| fb::lambda(black_box(i.u[k]), i.alpha[k])),
        ),
    ];
    let fast_ggx_lambda_64 = pairs[1].2;
    for (name, c_t, t) in pairs {
        row(&format!("us fast {name} f64"), t, Some(("C f64", c_t)));
    }
    let fast_g1 = time(big, |k| fg::g1(black_box(i.u[k]), i.alpha[k]));
    row("us fast GGX G1 f64", fast_g1, Some(("C f64", c_ggx_g1)));
    let fast_vndf = time(big, |k| {
        let w = i.w[k];
        type_vndf::<Ggx, f64>([w.x, w.y, w.z], i.alpha[k], black_box(i.xi[k]))[2]
    });
    row("us fast GGX VNDF f64", fast_vndf, Some(("C f64", c_vndf)));
    let c_b_vndf = time(big, |k| {
        let w = i.w[k];
        c::beckmann_vndf([w.x, w.y, w.z], i.alpha[k], i.alpha[k], black_box(i.xi[k]))[2]
    });
    let fast_b_vndf = time(big, |k| {
        let w = i.w[k];
        type_vndf::<Beckmann, f64>([w.x, w.y, w.z], i.alpha[k], black_box(i.xi[k]))[2]
    });
    let fast_b_vndf32 = time(big, |k| {
        let w = i.w[k];
        let xi = black_box(i.xi[k]);
        type_vndf::<Beckmann, f32>(
            [w.x as f32, w.y as f32, w.z as f32],
            a32s[k],
            [xi[0] as f32, xi[1] as f32],
        )[2] as f64
    });
    row("C  Beckmann VNDF (pbrt-v3)", c_b_vndf, None);
    row(
        "us fast Beckmann VNDF f64",
        fast_b_vndf,
        Some(("C Beckmann VNDF", c_b_vndf)),
    );
    row(
        "us fast Beckmann VNDF f32",
        fast_b_vndf32,
        Some(("C Beckmann VNDF", c_b_vndf)),
    );
    // The baseline samples the same distribution by the mirrored warp (its x̃ is our −x̃):
    // C(u₁, u₂) = ours(1 − u₁, 1 − u₂) up to its 1e-5 CDF tolerance and single-precision erfinv,
    // except within 0.8° of the normal, where it switches to a polar warp.
    let mut worst = 0.0f64;
    for k in 0..N {
        let (w, a, xi) = (i.w[k], i.alpha[k], i.xi[k]);
        if xi[0] < 1e-3 || xi[0] > 1.0 - 1e-3 || xi[1] < 1e-3 || xi[1] > 1.0 - 1e-3 {
            continue; // the baseline clamps u to 1e-6 and erfinv to ±0.99999
        }
        let stretched = Vec3::new(a * w.x, a * w.y, w.z).normalize();
        if stretched.z > 0.9999 {
            continue;
        }
        let m = c::beckmann_vndf([w.x, w.y, w.z], a, a, xi);
        let n = type_vndf::<Beckmann, f64>([w.x, w.y, w.z], a, [1.0 - xi[0], 1.0 - xi[1]]);
        let dot = m[0] * n[0] + m[1] * n[1] + m[2] * n[2];
        worst = worst.max(dot.min(1.0).acos());
    }
    println!(
        "   (C and fast Beckmann VNDF, same warp: largest angle between them {worst:.1e} rad)"
    );
    let f32_pairs: [(&str, f64, f64); 4] = [
        (
            "GGX D",
            time(big, |k| c::ggx_d_f32(black_box(u32s[k]), a32s[k]) as f64),
            time(big, |k| fg::d(black_box(u32s[k]), a32s[k]) as f64),
        ),
        (
            "GGX Λ",
            time(big, |k| {
                c::ggx_lambda_f32(black_box(u32s[k]), a32s[k]) as f64
            }),
            time(big, |k| fg::lambda(black_box(u32s[k]), a32s[k]) as f64),
        ),
        (
            "Beckmann D",
            time(big, |k| {
                c::beckmann_d_f32(black_box(u32s[k]), a32s[k]) as f64
            }),
            time(big, |k| fb::d(black_box(u32s[k]), a32s[k]) as f64),
        ),
        (
            "Beckmann Λ",
            time(big, |k| {
                c::beckmann_lambda_f32(black_box(u32s[k]), a32s[k]) as f64
            }),
            time(big, |k| fb::lambda(black_box(u32s[k]), a32s[k]) as f64),
        ),
    ];
    let fast_ggx_lambda_32 = f32_pairs[1].2;
    for (name, c_t, t) in f32_pairs {
        row(&format!("C  {name} f32"), c_t, None);
        row(&format!("us fast {name} f32"), t, Some(("C f32", c_t)));
    }

    fitted_fast_paths(&i, big, fast_ggx_lambda_64, fast_ggx_lambda_32, ggx_l);
    mixture_vndf(&i, big, fast_ggx_lambda_64, fast_vndf);
    matrix(&i, big);
    batches(&i);
    microfacet_type(&i, big);
    wavefront(&i);
    walks(&i);

    // Every other NDF against our GGX Λ.
    let base = Some(("our GGX Λ", ggx_l));
    let few = 20_000;
    for (name, make) in [
        ("Beckmann", 0usize),
        ("Double GGX", 1),
        ("Exponential", 2),
        ("GTR (γ ∈ [0.5, 3])", 3),
    ] {
        let ndf = |k: usize| -> AnyNdf {
            let a = i.alpha[k];
            match make {
                0 => AnyNdf::Beckmann(Beckmann::new(a).unwrap()),
                1 => AnyNdf::DoubleGgx(DoubleGgx::new(a).unwrap()),
                2 => AnyNdf::Exponential(Exponential::new(a).unwrap()),
                _ => AnyNdf::Gtr(Gtr::new(a, i.gamma[k]).unwrap()),
            }
        };
        let calls = if make >= 2 { few } else { big };
        row(
            &format!("us {name} Λ"),
            time(calls, |k| ndf(k).lambda(black_box(i.u[k]))),
            base,
        );
        row(
            &format!("us {name} σ(−u)"),
            time(calls, |k| ndf(k).sigma(-black_box(i.u[k]))),
            base,
        );
        row(
            &format!("us {name} D·cos sample"),
            time(calls, |k| sample_dcos(&ndf(k), black_box(i.xi[k])).z),
            base,
        );
        let vcalls = if make >= 1 { 2_000 } else { big / 4 };
        row(
            &format!("us {name} VNDF sample"),
            time(vcalls, |k| {
                let n = ndf(k);
                let a = n.alpha();
                Exact::new(n.kind(), a, a, n.shape())
                    .unwrap()
                    .sample_wm(i.w[k].into(), black_box(i.xi[k]))[2]
            }),
            base,
        );
    }
}

/// Double GGX, Exponential and GTR fast Λ, σ(−u), G1 in f64 and f32, against our fast GGX Λ
/// in the same precision (and our exact GGX Λ). GTR: 64 prepared materials with random
/// (α, γ), the call's material chosen by the input index.
fn fitted_fast_paths(i: &Inputs, calls: usize, ggx64: f64, ggx32: f64, exact_ggx: f64) {
    use microsurface::fast::{double_ggx as dg, exponential as ex, gtr::FittedGtr as FastGtr};
    println!();
    println!("fitted fast paths (per call; ratio to our fast GGX Λ of the same precision, and to our exact GGX Λ)");
    let (u32s, a32s): (Vec<f32>, Vec<f32>) = (
        i.u.iter().map(|&x| x as f32).collect(),
        i.alpha.iter().map(|&x| x as f32).collect(),
    );
    let start = Instant::now();
    let materials: Vec<FastGtr> = (0..64)
        .map(|k| FastGtr::new(i.alpha[k], i.gamma[k]).unwrap())
        .collect();
    let build_ms = start.elapsed().as_secs_f64() * 1e3 / 64.0;
    let direct = materials.iter().filter(|g| g.is_direct()).count();
    let fit_row = |name: &str, t64: f64, t32: f64| {
        println!(
            "{:44} {t64:10.1} ns   {:6.2}× fast GGX Λ f64  {:6.2}× exact GGX Λ",
            format!("us fast {name} f64"),
            t64 / ggx64,
            t64 / exact_ggx
        );
        println!(
            "{:44} {t32:10.1} ns   {:6.2}× fast GGX Λ f32",
            format!("us fast {name} f32"),
            t32 / ggx32
        );
    };
    macro_rules! both {
        ($f64:expr, $f32:expr) => {
            (time(calls, $f64), time(calls, $f32))
        };
    }
    let m = |k: usize| &materials[k % 64];
    let rows: [(&str, (f64, f64)); 9] = [
        (
            "Double GGX Λ",
            both!(
                |k| dg::lambda(black_box(i.u[k]), i.alpha[k]),
                |k| dg::lambda(black_box(u32s[k]), a32s[k]) as f64
            ),
        ),
        (
            "Double GGX σ(−u)",
            both!(
                |k| dg::sigma(-black_box(i.u[k]), i.alpha[k]),
                |k| dg::sigma(-black_box(u32s[k]), a32s[k]) as f64
            ),
        ),
        (
            "Double GGX G1",
            both!(
                |k| dg::g1(black_box(i.u[k]), i.alpha[k]),
                |k| dg::g1(black_box(u32s[k]), a32s[k]) as f64
            ),
        ),
        (
            "Exponential Λ",
            both!(
                |k| ex::lambda(black_box(i.u[k]), i.alpha[k]),
                |k| ex::lambda(black_box(u32s[k]), a32s[k]) as f64
            ),
        ),
        (
            "Exponential σ(−u)",
            both!(
                |k| ex::sigma(-black_box(i.u[k]), i.alpha[k]),
                |k| ex::sigma(-black_box(u32s[k]), a32s[k]) as f64
            ),
        ),
        (
            "Exponential G1",
            both!(
                |k| ex::g1(black_box(i.u[k]), i.alpha[k]),
                |k| ex::g1(black_box(u32s[k]), a32s[k]) as f64
            ),
        ),
        (
            "GTR Λ (64 materials)",
            both!(
                |k| m(k).lambda(black_box(i.u[k])),
                |k| m(k).lambda(black_box(u32s[k])) as f64
            ),
        ),
        (
            "GTR σ(−u) (64 materials)",
            both!(
                |k| m(k).sigma(-black_box(i.u[k])),
                |k| m(k).sigma(-black_box(u32s[k])) as f64
            ),
        ),
        (
            "GTR G1 (64 materials)",
            both!(
                |k| m(k).g1(black_box(i.u[k])),
                |k| m(k).g1(black_box(u32s[k])) as f64
            ),
        ),
    ];
    for (name, (t64, t32)) in rows {
        fit_row(name, t64, t32);
    }
    // One material: the same lookups, without the 64 materials' tables competing for cache.
    let one = &materials[5];
    let (t64, t32) = both!(
        |k| one.lambda(black_box(i.u[k])),
        |k| one.lambda(black_box(u32s[k])) as f64
    );
    fit_row("GTR Λ (1 material)", t64, t32);
    println!(
        "{:44} {build_ms:10.1} ms per material (mean of 64, α ∈ [0.05, 1], γ ∈ [0.5, 3]; {direct} of 64 tabulate Λ itself)",
        "GTR fast construction"
    );
    family_fast_paths(i, calls);
}

/// The family's fast path (`Microfacet::with_shape`, issue 22): Λ(w) of random directions
/// through the `Microfacet` type against `Microfacet<_, Ggx>`'s in the same run, f64 and
/// f32, and each shape's construction (the fit of log₂ Λ₁).
fn family_fast_paths(i: &Inputs, calls: usize) {
    use microsurface::{BesselK, Ei, Erfc, StudentT, K0};
    println!();
    println!("family fast paths: Microfacet Λ(w), α = 0.3, random directions (ratio to Microfacet<_, Ggx> Λ(w) of the same precision)");
    let w64: Vec<[f64; 3]> = i.w.iter().map(|w| [w.x, w.y, w.z]).collect();
    let w32: Vec<[f32; 3]> = w64.iter().map(|w| w.map(|x| x as f32)).collect();
    let g64 = Microfacet::<f64, Ggx>::new(0.3, 0.3).unwrap();
    let g32 = Microfacet::<f32, Ggx>::new(0.3, 0.3).unwrap();
    let base64 = time(calls, |k| g64.lambda(black_box(w64[k])));
    let base32 = time(calls, |k| g32.lambda(black_box(w32[k])) as f64);
    println!("{:44} {base64:10.1} ns | f32 {base32:6.1} ns", "GGX Λ(w)");
    macro_rules! family {
        ($name:expr, $t:ty, $shape:expr) => {{
            let t = Instant::now();
            let m64 = Microfacet::<f64, $t>::with_shape(0.3, 0.3, $shape).unwrap();
            let build = t.elapsed().as_secs_f64() * 1e3;
            let m32 = Microfacet::<f32, $t>::with_shape(0.3, 0.3, $shape).unwrap();
            let t64 = time(calls, |k| m64.lambda(black_box(w64[k])));
            let t32 = time(calls, |k| m32.lambda(black_box(w32[k])) as f64);
            println!(
                "{:44} {t64:10.1} ns {:5.2}× | f32 {t32:6.1} ns {:5.2}× | built in {build:.1} ms",
                format!("{} Λ(w)", $name),
                t64 / base64,
                t32 / base32
            );
        }};
    }
    family!("Student-T γ = 2.5", StudentT, Some(2.5));
    family!("Student-T γ = 50", StudentT, Some(50.0));
    family!("Ei", Ei, None);
    family!("Erfc", Erfc, None);
    family!("K0", K0, None);
    family!("Bessel-K a = 1.5", BesselK, Some(1.5));
    // D·cos: the fast path (the prior's β and Beckmann's D·cos for all but Student-T) against
    // the radial quantile of the exact path (`Exact`, what the fast path inverted before).
    println!();
    println!("family D·cos sampling, f64, α = 0.3 (ns per sample; the exact path's radial quantile for scale)");
    use microsurface::{Exact, NdfKind};
    for (name, kind, shape) in [
        ("Student-T γ = 2.5", NdfKind::StudentT, Some(2.5)),
        ("Ei", NdfKind::Ei, None),
        ("Erfc", NdfKind::Erfc, None),
        ("K0", NdfKind::K0, None),
        ("Bessel-K a = 1.5", NdfKind::BesselK, Some(1.5)),
    ] {
        let fast = microsurface::AnyMicrofacet::<f64>::new(kind, 0.3, 0.3, shape).unwrap();
        let exact = Exact::new(kind, 0.3, 0.3, shape).unwrap();
        let t_fast = time(calls, |k| fast.sample_dcos(black_box(i.xi[k])).wm[2]);
        let t_exact = time((calls / 100).max(100), |k| {
            exact.sample_dcos(black_box(i.xi[k])).wm[2]
        });
        println!(
            "{:44} fast {t_fast:8.1} ns | exact (radial quantile) {t_exact:9.1} ns ({:6.1}×)",
            name,
            t_exact / t_fast
        );
    }
}

/// The run-time door: `AnyMicrofacet<F>` (materials built from a kind chosen at run time)
/// against the static `Microfacet<F, N>` of the same material, for every NDF with a fast
/// path, f64: Λ(w), a visible-normal sample with its pdf, and a rough-conductor eval+pdf
/// (gold, RGB), each the median of 15 runs, the two interleaved in one process; the ratio is
/// the door's cost (the issue-35 target: ≤ 1.1×).
fn any_door(i: &Inputs, calls: usize) {
    use microsurface::bsdf::fresnel::Conductor;
    use microsurface::bsdf::{Bsdf, RoughConductor};
    use microsurface::{AnyMicrofacet, BesselK, DoubleGgx, Ei, Erfc, Exponential, StudentT, K0};
    println!();
    println!("the run-time door: AnyMicrofacet<f64> / Microfacet<f64, N> (α = 0.3 × 0.2, random directions)");
    let w: Vec<[f64; 3]> = i.w.iter().map(|w| [w.x, w.y, w.z]).collect();
    let gold = Conductor {
        eta: [0.14, 0.42, 1.37],
        k: [3.98, 2.38, 1.60],
    };
    fn rows<D: MicrofacetDistribution<f64> + Clone>(
        name: &str,
        s: D,
        a: AnyMicrofacet<f64>,
        i: &Inputs,
        w: &[[f64; 3]],
        gold: Conductor<f64, 3>,
        calls: usize,
    ) {
        let n = w.len();
        let (cs, ca) = (
            RoughConductor::new(s.clone(), gold),
            RoughConductor::new(a.clone(), gold),
        );
        let lam = |d: &dyn Fn(usize) -> f64| time(calls, d);
        let (ls, la) = (
            lam(&|k| s.lambda(black_box(w[k]))),
            lam(&|k| a.lambda(black_box(w[k]))),
        );
        let (ss, sa) = (
            time(calls, |k| s.sample(black_box(w[k]), i.xi[k]).pdf),
            time(calls, |k| a.sample(black_box(w[k]), i.xi[k]).pdf),
        );
        let (es, ea) = (
            time(calls, |k| {
                let wi = w[(k + 1) % n];
                cs.eval(black_box(w[k]), wi)[1] + cs.pdf(w[k], wi)
            }),
            time(calls, |k| {
                let wi = w[(k + 1) % n];
                ca.eval(black_box(w[k]), wi)[1] + ca.pdf(w[k], wi)
            }),
        );
        println!(
            "{name:20} Λ {ls:6.1} / {la:6.1} ns {:5.2}× | sample {ss:6.1} / {sa:6.1} ns {:5.2}× | conductor eval+pdf {es:6.1} / {ea:6.1} ns {:5.2}×",
            la / ls,
            sa / ss,
            ea / es
        );
    }
    // Materials built per shading point with a textured α: the first of a shape fits Λ₁,
    // the others find the fit in the process-wide cache.
    for spec in ["student_t:2.5", "ei", "bessel_k:0.7", "ggx"] {
        let t = Instant::now();
        let first = AnyMicrofacet::<f32>::parse(spec, 0.25, 0.25).unwrap();
        let first_ms = t.elapsed().as_secs_f64() * 1e3;
        let t = Instant::now();
        let mut acc = first.alpha().0;
        for k in 0..10_000 {
            let a = (0.05 + 0.9 * k as f64 / 10_000.0) as f32;
            acc += AnyMicrofacet::<f32>::parse(spec, a, a).unwrap().alpha().0;
        }
        black_box(acc);
        let per = t.elapsed().as_secs_f64() * 1e9 / 10_000.0;
        println!("{spec:20} first material {first_ms:8.2} ms (the fit, or none); then {per:8.1} ns a material (10⁴ distinct α)");
    }
    let (ax, ay) = (0.3, 0.2);
    let any = |spec: &str| AnyMicrofacet::<f64>::parse(spec, ax, ay).unwrap();
    rows(
        "GGX",
        Microfacet::<f64, Ggx>::new(ax, ay).unwrap(),
        any("ggx"),
        i,
        &w,
        gold,
        calls,
    );
    rows(
        "Beckmann",
        Microfacet::<f64, Beckmann>::new(ax, ay).unwrap(),
        any("beckmann"),
        i,
        &w,
        gold,
        calls,
    );
    rows(
        "Double GGX",
        Microfacet::<f64, DoubleGgx>::new(ax, ay).unwrap(),
        any("double_ggx"),
        i,
        &w,
        gold,
        calls,
    );
    rows(
        "Exponential",
        Microfacet::<f64, Exponential>::new(ax, ay).unwrap(),
        any("exponential"),
        i,
        &w,
        gold,
        calls,
    );
    let gtr = |g| Microfacet::<f64, Gtr>::gtr(ax, ax, g).unwrap();
    rows(
        "GTR γ = 1.5 (iso)",
        gtr(1.5),
        AnyMicrofacet::parse("gtr:1.5", ax, ax).unwrap(),
        i,
        &w,
        gold,
        calls,
    );
    rows(
        "Student-T γ = 2.5",
        Microfacet::<f64, StudentT>::with_shape(ax, ay, Some(2.5)).unwrap(),
        any("student_t:2.5"),
        i,
        &w,
        gold,
        calls,
    );
    rows(
        "Ei",
        Microfacet::<f64, Ei>::with_shape(ax, ay, None).unwrap(),
        any("ei"),
        i,
        &w,
        gold,
        calls,
    );
    rows(
        "Erfc",
        Microfacet::<f64, Erfc>::with_shape(ax, ay, None).unwrap(),
        any("erfc"),
        i,
        &w,
        gold,
        calls,
    );
    rows(
        "K0",
        Microfacet::<f64, K0>::with_shape(ax, ay, None).unwrap(),
        any("k0"),
        i,
        &w,
        gold,
        calls,
    );
    rows(
        "Bessel-K a = 0.7",
        Microfacet::<f64, BesselK>::with_shape(ax, ay, Some(0.7)).unwrap(),
        any("bessel_k:0.7"),
        i,
        &w,
        gold,
        calls,
    );
}

/// Every quantity of every fast path in f64 and f32, one row per NDF: D, Λ, G1, G2
/// (height-correlated, u_i from the next input), σ(−u), D·cos sampling and VNDF sampling. The
/// samplers are [`Microfacet`]'s (built in the call for the four NDFs without a per-material
/// table); the superpositions draw their extra uniforms from its `UniformStream`, whose cost
/// is included; GTR uses 64 prepared materials, chosen by the input index (and a row of 64
/// at γ = 1, Burley's clearcoat).
fn matrix(i: &Inputs, calls: usize) {
    use microsurface::fast::gtr::FittedGtr as FastGtr;
    use microsurface::fast::Real;
    use microsurface::fast::{beckmann as fb, double_ggx as dg, exponential as ex, ggx as fg};
    let xorshift = |seed: u64| {
        let mut state = seed;
        move || {
            state ^= state >> 12;
            state ^= state << 25;
            state ^= state >> 27;
            (state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
        }
    };
    let mut next64 = xorshift(0x9e37_79b9_7f4a_7c15);
    let mut next_inner = xorshift(0x9e37_79b9_7f4a_7c15);
    let mut next32 = move || next_inner() as f32;
    let u32s: Vec<f32> = i.u.iter().map(|&x| x as f32).collect();
    let a32s: Vec<f32> = i.alpha.iter().map(|&x| x as f32).collect();
    let w64: Vec<[f64; 3]> = i.w.iter().map(|w| [w.x, w.y, w.z]).collect();
    let w32: Vec<[f32; 3]> = w64.iter().map(|w| w.map(|x| x as f32)).collect();
    let xi32: Vec<[f32; 2]> = i.xi.iter().map(|x| x.map(|x| x as f32)).collect();
    let materials: Vec<FastGtr> = (0..64)
        .map(|k| FastGtr::new(i.alpha[k], i.gamma[k]).unwrap())
        .collect();
    let m = |k: usize| &materials[k % 64];
    // Burley's clearcoat lobe: γ = 1 (closed-form Λ nodes and D without a logarithm).
    let clearcoat: Vec<FastGtr> = (0..64)
        .map(|k| FastGtr::new(i.alpha[k], 1.0).unwrap())
        .collect();
    let m1 = |k: usize| &clearcoat[k % 64];
    let gtr = GtrMaterials::new(|k| i.alpha[k], |k| i.gamma[k]);
    let gtr1 = GtrMaterials::new(|k| i.alpha[k], |_| 1.0);
    // One cell: the expression timed over the f64 inputs, then over their f32 roundings.
    macro_rules! cell {
        (|$k:ident, $u:ident, $u2:ident, $a:ident, $w:ident, $xi:ident, $next:ident| $e:expr) => {{
            let t64 = time(calls, |$k| {
                let ($u, $u2, $a) = (black_box(i.u[$k]), i.u[($k + 1) % N], i.alpha[$k]);
                let ($w, $xi, $next) = (w64[$k], black_box(i.xi[$k]), &mut next64);
                let _ = (&$u, &$u2, &$a, &$w, &$xi, &$next);
                ($e).to_f64()
            });
            let t32 = time(calls, |$k| {
                let ($u, $u2, $a) = (black_box(u32s[$k]), u32s[($k + 1) % N], a32s[$k]);
                let ($w, $xi, $next) = (w32[$k], black_box(xi32[$k]), &mut next32);
                let _ = (&$u, &$u2, &$a, &$w, &$xi, &$next);
                ($e).to_f64()
            });
            format!("{t64:5.1} /{t32:5.1}")
        }};
    }
    // A row for prepared GTR materials, picked by `$m(k)`.
    macro_rules! gtr_cells {
        ($m:ident, $mm:ident) => {
            [
                cell!(|k, u, u2, a, w, xi, next| $m(k).d(u)),
                cell!(|k, u, u2, a, w, xi, next| $m(k).lambda(u)),
                cell!(|k, u, u2, a, w, xi, next| $m(k).g1(u)),
                cell!(|k, u, u2, a, w, xi, next| $m(k).g2(u, u2)),
                cell!(|k, u, u2, a, w, xi, next| $m(k).sigma(-u)),
                cell!(|k, u, u2, a, w, xi, next| PickGtr::pick(&$mm, k).sample_dcos(xi).wm[2]),
                cell!(|k, u, u2, a, w, xi, next| PickGtr::pick(&$mm, k).sample_wm(w, xi)[2]),
            ]
        };
    }
    println!();
    println!("every fast quantity (ns per call, f64 / f32; random inputs; G2 height-correlated; samplers include their extra uniforms)");
    println!(
        "{:22} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12}",
        "NDF", "D", "Λ", "G1", "G2", "σ(−u)", "D·cos", "VNDF"
    );
    let rows: [(&str, [String; 7]); 6] = [
        (
            "GGX",
            [
                cell!(|k, u, u2, a, w, xi, next| fg::d(u, a)),
                cell!(|k, u, u2, a, w, xi, next| fg::lambda(u, a)),
                cell!(|k, u, u2, a, w, xi, next| fg::g1(u, a)),
                cell!(|k, u, u2, a, w, xi, next| fg::g2(u, u2, a)),
                cell!(|k, u, u2, a, w, xi, next| fg::sigma(-u, a)),
                cell!(|k, u, u2, a, w, xi, next| type_dcos::<Ggx, _>(a, xi)[2]),
                cell!(|k, u, u2, a, w, xi, next| type_vndf::<Ggx, _>(w, a, xi)[2]),
            ],
        ),
        (
            "Beckmann",
            [
                cell!(|k, u, u2, a, w, xi, next| fb::d(u, a)),
                cell!(|k, u, u2, a, w, xi, next| fb::lambda(u, a)),
                cell!(|k, u, u2, a, w, xi, next| fb::g1(u, a)),
                cell!(|k, u, u2, a, w, xi, next| fb::g2(u, u2, a)),
                cell!(|k, u, u2, a, w, xi, next| fb::sigma(-u, a)),
                cell!(|k, u, u2, a, w, xi, next| type_dcos::<Beckmann, _>(a, xi)[2]),
                cell!(|k, u, u2, a, w, xi, next| type_vndf::<Beckmann, _>(w, a, xi)[2]),
            ],
        ),
        (
            "Double GGX",
            [
                cell!(|k, u, u2, a, w, xi, next| dg::d(u, a)),
                cell!(|k, u, u2, a, w, xi, next| dg::lambda(u, a)),
                cell!(|k, u, u2, a, w, xi, next| dg::g1(u, a)),
                cell!(|k, u, u2, a, w, xi, next| dg::g2(u, u2, a)),
                cell!(|k, u, u2, a, w, xi, next| dg::sigma(-u, a)),
                cell!(|k, u, u2, a, w, xi, next| type_dcos::<DoubleGgx, _>(a, xi)[2]),
                cell!(|k, u, u2, a, w, xi, next| type_vndf::<DoubleGgx, _>(w, a, xi)[2]),
            ],
        ),
        (
            "Exponential",
            [
                cell!(|k, u, u2, a, w, xi, next| ex::d(u, a)),
                cell!(|k, u, u2, a, w, xi, next| ex::lambda(u, a)),
                cell!(|k, u, u2, a, w, xi, next| ex::g1(u, a)),
                cell!(|k, u, u2, a, w, xi, next| ex::g2(u, u2, a)),
                cell!(|k, u, u2, a, w, xi, next| ex::sigma(-u, a)),
                cell!(|k, u, u2, a, w, xi, next| type_dcos::<Exponential, _>(a, xi)[2]),
                cell!(|k, u, u2, a, w, xi, next| type_vndf::<Exponential, _>(w, a, xi)[2]),
            ],
        ),
        ("GTR (64 materials)", gtr_cells!(m, gtr)),
        ("GTR γ = 1 (64 α)", gtr_cells!(m1, gtr1)),
    ];
    for (name, cells) in rows {
        println!("{name:22} {}", cells.join(" "));
    }
}

/// The fast visible-normal samplers of the superpositions through [`Microfacet`] (rejection;
/// their extra uniforms come from its `UniformStream`, whose cost is in the figures), against
/// our fast GGX Λ and our fast GGX VNDF (f64).
fn mixture_vndf(i: &Inputs, calls: usize, ggx_lambda: f64, ggx_vndf: f64) {
    println!();
    println!("fast VNDF sampling (per sample, extra uniforms included; ratio to our fast GGX Λ f64 and to our fast GGX VNDF of the same precision)");
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        (state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    };
    // The f32 rows draw f32 uniforms as an f32 renderer does (pbrt's Uniform<float>): the
    // top 24 bits of the same xorshift64*, scaled; not f64 uniforms rounded.
    let mut state32 = 0x9e37_79b9_7f4a_7c15u64;
    let mut next32 = move || {
        state32 ^= state32 >> 12;
        state32 ^= state32 << 25;
        state32 ^= state32 >> 27;
        (state32.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 40) as f32 * (1.0 / (1u32 << 24) as f32)
    };
    let a32s: Vec<f32> = i.alpha.iter().map(|&x| x as f32).collect();
    let gtr = GtrMaterials::new(|k| i.alpha[k], |k| i.gamma[k]);
    let w = |k: usize| [i.w[k].x, i.w[k].y, i.w[k].z];
    // f32 inputs converted once, as a renderer working in f32 would hold them (and as the
    // f32 GGX sampler below reads them).
    let w32s: Vec<[f32; 3]> = (0..N).map(|k| w(k).map(|x| x as f32)).collect();
    let xi32s: Vec<[f32; 2]> = i.xi.iter().map(|x| x.map(|x| x as f32)).collect();
    let w32 = |k: usize| w32s[k];
    let xi32 = |k: usize| xi32s[k];
    let ggx_vndf32 = time(calls, |k| {
        type_vndf::<Ggx, f32>(w32(k), a32s[k], black_box(xi32(k)))[2] as f64
    });
    println!(
        "{:44} {ggx_vndf32:10.1} ns",
        "us fast GGX VNDF f32 (the f32 rows' base)"
    );
    let rows = [
        (
            "uniforms alone (2 per call)",
            time(calls, |k| black_box(next()) + next() + k as f64),
        ),
        (
            "uniforms alone (2 per call) f32",
            time(calls, |k| {
                f64::from(black_box(next32()) + next32()) + k as f64
            }),
        ),
        (
            "Double GGX VNDF f64",
            time(calls, |k| {
                type_vndf::<DoubleGgx, f64>(w(k), i.alpha[k], black_box(i.xi[k]))[2]
            }),
        ),
        (
            "Double GGX VNDF f32",
            time(calls, |k| {
                type_vndf::<DoubleGgx, f32>(w32(k), a32s[k], black_box(xi32(k)))[2] as f64
            }),
        ),
        (
            "Exponential VNDF f64",
            time(calls, |k| {
                type_vndf::<Exponential, f64>(w(k), i.alpha[k], black_box(i.xi[k]))[2]
            }),
        ),
        (
            "Exponential VNDF f32",
            time(calls, |k| {
                type_vndf::<Exponential, f32>(w32(k), a32s[k], black_box(xi32(k)))[2] as f64
            }),
        ),
        (
            "GTR VNDF (64 materials) f64",
            time(calls, |k| {
                PickGtr::<f64>::pick(&gtr, k).sample_wm(w(k), black_box(i.xi[k]))[2]
            }),
        ),
        (
            "GTR VNDF (64 materials) f32",
            time(calls, |k| {
                PickGtr::<f32>::pick(&gtr, k).sample_wm(w32(k), black_box(xi32(k)))[2] as f64
            }),
        ),
    ];
    for (name, t) in rows {
        let base = if name.ends_with("f32") {
            ggx_vndf32
        } else {
            ggx_vndf
        };
        println!(
            "{:44} {t:10.1} ns   {:6.2}× fast GGX Λ  {:6.2}× fast GGX VNDF",
            format!("us fast {name}"),
            t / ggx_lambda,
            t / base
        );
    }
}

/// One timed pass of the slice benchmarks, writing into the buffer it is given.
type Pass<'a> = &'a mut dyn FnMut(&mut [f64]);

/// Runs `passes` in turn, `rounds` times, each into a buffer of `len` elements: per pass, the
/// ns per element of each round (a pass covering `elements` elements). Running them in turn
/// lets a stretch of time in which the machine runs slower fall on all of them alike
/// instead of on one pass's block of rounds.
fn timed_rounds<const K: usize>(
    rounds: usize,
    len: usize,
    elements: usize,
    mut passes: [Pass; K],
) -> [Vec<f64>; K] {
    let mut runs = [const { Vec::new() }; K];
    let mut o = vec![0.0; len];
    for _ in 0..rounds {
        for (f, r) in passes.iter_mut().zip(runs.iter_mut()) {
            let start = Instant::now();
            f(&mut o);
            black_box(&o);
            r.push(start.elapsed().as_secs_f64() * 1e9 / elements as f64);
        }
    }
    runs
}

/// The median of a pass's rounds.
fn median(mut r: Vec<f64>) -> f64 {
    r.sort_by(f64::total_cmp);
    r[r.len() / 2]
}

/// 10⁶-element slices: the scalar fast path in a plain loop, the slice function, and the
/// slice function on every core (rayon), per element.
fn batches(i: &Inputs) {
    use microsurface::fast::{
        batch, double_ggx as dg, exponential as ex, gtr::FittedGtr as FastGtr,
    };
    use microsurface::fast::{beckmann as fb, ggx as fg};
    const LEN: usize = 1_000_000;
    const ROUNDS: usize = 21;
    let u: Vec<f64> = (0..LEN)
        .map(|k| i.u[k % N] * (1.0 - 1e-9 * (k / N) as f64))
        .collect();
    let a: Vec<f64> = (0..LEN).map(|k| i.alpha[(k * 7 + 3) % N]).collect();
    let mut out = vec![0.0; LEN];
    let threads = rayon::current_num_threads();
    // The same number of workers, each pinned to its own CPU.
    let cpus = std::thread::available_parallelism().map_or(1, |n| n.get());
    let pinned = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .start_handler(move |k| {
            // (A failure only leaves that worker unpinned, as in the default pool.)
            let _ = microsurface_bench::pin_to_cpu(k % cpus);
        })
        .build()
        .expect("a second rayon pool");
    println!();
    println!("slices of 10⁶ (ns per element, median of {ROUNDS} rounds, each running the five in turn): indexed loop | iterator loop | slice fn (× indexed, × iterator) | rayon on {threads} threads (× slice fn; rounds below 1.5×) | the same, workers pinned one per CPU");
    // The five forms of one row run in turn, round after round (`timed_rounds`). Per form:
    // the median ns per element; for the rayon forms also how many rounds ran below 1.5× the
    // same round's slice fn.
    let rounds = |fs: [Pass; 5]| -> ([f64; 5], [usize; 2]) {
        let runs = timed_rounds(ROUNDS, LEN, LEN, fs);
        let slow = [3, 4].map(|j| {
            (0..ROUNDS)
                .filter(|&k| runs[2][k] / runs[j][k] < 1.5)
                .count()
        });
        (runs.map(median), slow)
    };
    let line = |name: &str,
                ([t_idx, t_iter, t_slice, t_par, t_pin], [slow, slow_pin]): (
        [f64; 5],
        [usize; 2],
    )| {
        println!(
            "{:34} {:7.2} | {:7.2} | {:7.2} ({:5.2}×, {:5.2}×) | {:7.2} ({:5.2}×; {:2} of {ROUNDS}) | {:7.2} ({:5.2}×; {:2} of {ROUNDS})",
            name,
            t_idx,
            t_iter,
            t_slice,
            t_idx / t_slice,
            t_iter / t_slice,
            t_par,
            t_slice / t_par,
            slow,
            t_pin,
            t_slice / t_pin,
            slow_pin
        );
    };
    // The loops call the scalar function directly (inlined, as in a user's loop), not
    // through a pointer, in the two ways a user writes them: indexing the slices (a bounds
    // check per access, which keeps LLVM from vectorising the loop) and zipping their
    // iterators (no checks: LLVM vectorises the closed forms' loops, GGX D, Λ and G1, for
    // SSE2 by itself).
    macro_rules! case {
        ($name:expr, $scalar:path, $slice:path) => {{
            let times = rounds([
                &mut |o| {
                    for k in 0..LEN {
                        o[k] = $scalar(u[k], a[k]);
                    }
                },
                &mut |o| {
                    for (o, (&u, &a)) in o.iter_mut().zip(u.iter().zip(&a)) {
                        *o = $scalar(u, a);
                    }
                },
                &mut |o| $slice(&u, &a, o),
                &mut |o| batch::par::map(&u, &a, o, $slice),
                &mut |o| pinned.install(|| batch::par::map(&u, &a, o, $slice)),
            ]);
            line($name, times);
        }};
    }
    case!("GGX D", fg::d, batch::ggx_d);
    case!("GGX Λ", fg::lambda, batch::ggx_lambda);
    case!("GGX G1", fg::g1, batch::ggx_g1);
    case!("Beckmann D", fb::d, batch::beckmann_d);
    case!("Double GGX Λ", dg::lambda, batch::double_ggx_lambda);
    case!("Exponential Λ", ex::lambda, batch::exponential_lambda);
    let g = FastGtr::new(0.3, 1.5).unwrap();
    let times = rounds([
        &mut |o| {
            for k in 0..LEN {
                o[k] = g.lambda(u[k]);
            }
        },
        &mut |o| {
            for (o, &u) in o.iter_mut().zip(&u) {
                *o = g.lambda(u);
            }
        },
        &mut |o| batch::gtr_lambda(&g, &u, o),
        &mut |o| batch::par::gtr_lambda(&g, &u, o),
        &mut |o| pinned.install(|| batch::par::gtr_lambda(&g, &u, o)),
    ]);
    line("GTR Λ (α 0.3, γ 1.5)", times);

    // The same loop and slice fn on the first 2^15 elements (768 KiB of u, α and out: inside
    // this CPU's 2 MiB L2), 32 times per pass: what the kernels cost when memory traffic is
    // not the bound (GGX D's is, at 10⁶; BENCHMARKS.md).
    const SMALL: usize = 1 << 15;
    println!();
    println!("cache-resident slices ({SMALL} elements, 32 times per pass; ns per element, median of {ROUNDS} rounds): indexed loop | iterator loop | slice fn (× indexed, × iterator)");
    let (us, as_) = (&u[..SMALL], &a[..SMALL]);
    // As in `case!`, the loops call the scalar function directly (inlined), not through a
    // pointer, indexed and zipped.
    macro_rules! cached {
        ($name:expr, $scalar:path, $slice:path) => {{
            let runs = timed_rounds(
                ROUNDS,
                SMALL,
                32 * SMALL,
                [
                    &mut |o| {
                        for _ in 0..32 {
                            for k in 0..SMALL {
                                o[k] = $scalar(us[k], as_[k]);
                            }
                            black_box(&mut *o);
                        }
                    },
                    &mut |o| {
                        for _ in 0..32 {
                            for (o, (&u, &a)) in o.iter_mut().zip(us.iter().zip(as_)) {
                                *o = $scalar(u, a);
                            }
                            black_box(&mut *o);
                        }
                    },
                    &mut |o| {
                        for _ in 0..32 {
                            $slice(us, as_, o);
                            black_box(&mut *o);
                        }
                    },
                ],
            );
            let [t_idx, t_iter, t_slice] = runs.map(median);
            println!(
                "{:34} {t_idx:7.2} | {t_iter:7.2} | {t_slice:7.2} ({:5.2}×, {:5.2}×)",
                $name,
                t_idx / t_slice,
                t_iter / t_slice
            );
        }};
    }
    cached!("GGX D", fg::d, batch::ggx_d);
    cached!("GGX Λ", fg::lambda, batch::ggx_lambda);
    cached!("GGX G1", fg::g1, batch::ggx_g1);

    // The same slice functions capped at each instruction set this CPU has.
    let levels: Vec<batch::Simd> = [batch::Simd::Generic, batch::Simd::Avx2, batch::Simd::Avx512]
        .into_iter()
        .filter(|&l| l <= batch::detected_simd())
        .collect();
    println!();
    println!("slice fn per instruction set (ns per element, median of 11 passes): {levels:?}");
    let gtr = |u: &[f64], _: &[f64], o: &mut [f64]| batch::gtr_lambda(&g, u, o);
    type SliceFn<'a> = &'a dyn Fn(&[f64], &[f64], &mut [f64]);
    let cases: [(&str, SliceFn); 7] = [
        ("GGX D", &batch::ggx_d),
        ("GGX Λ", &batch::ggx_lambda),
        ("GGX G1", &batch::ggx_g1),
        ("Beckmann D", &batch::beckmann_d),
        ("Double GGX Λ", &batch::double_ggx_lambda),
        ("Exponential Λ", &batch::exponential_lambda),
        ("GTR Λ (α 0.3, γ 1.5)", &gtr),
    ];
    // The dispatch check (issue 19): the build `simd()` picks must not be slower than a
    // narrower one (an AVX-512 build had been 5–13× slower than AVX2 on AMD Zen 5, from
    // gathers and scatters on contiguous data). 25 % is far above the rounds' spread.
    let mut slow_picks = Vec::new();
    for (name, f) in cases {
        let times: Vec<f64> = levels
            .iter()
            .map(|&l| {
                batch::cap_simd(Some(l));
                let [runs] = timed_rounds(11, LEN, LEN, [&mut |o| f(&u, &a, o)]);
                median(runs)
            })
            .collect();
        batch::cap_simd(None);
        let shown: Vec<String> = times.iter().map(|t| format!("{t:7.2}")).collect();
        println!("{name:34} {}", shown.join(" | "));
        let picked = *times.last().expect("the generic build is always there");
        let best = times.iter().copied().fold(f64::INFINITY, f64::min);
        if picked > 1.25 * best {
            slow_picks.push(format!(
                "{name}: the dispatched {:?} build takes {picked:.2} ns, a narrower one {best:.2}",
                batch::simd()
            ));
        }
    }
    black_box(&mut out);
    assert!(
        slow_picks.is_empty(),
        "DISPATCH CHECK FAILED (a wider build is slower):\n{}",
        slow_picks.join("\n")
    );
    println!(
        "dispatch check: the picked build ({:?}) is within 25 % of the fastest for every row",
        batch::simd()
    );
}

/// The renderer-facing [`microsurface::Microfacet`] type against the fast free functions it
/// wraps, per NDF, f64 and f32: D(wm), Λ(w), G1(w) and the visible-normal sample (with its
/// pdf, as `sample` returns it, and without, `sample_wm`), isotropic and anisotropic
/// (αy = αx/2). 64 materials (built before timing, as a renderer builds its materials); the
/// free functions read the same α. The samplers are the type's only (the free samplers are
/// its implementation and no longer public; BENCHMARKS.md has the last side-by-side run).
fn microfacet_type(i: &Inputs, calls: usize) {
    use microsurface::fast::{beckmann as fb, double_ggx as dg, exponential as ex, ggx as fg};
    println!();
    println!("the Microfacet type against the fast free functions (ns per call; ratio type/free; aniso: αy = αx/2)");
    println!(
        "{:24} {:>20} {:>20} {:>20} {:>14} {:>14}",
        "NDF, precision",
        "D free/type",
        "Λ free/type",
        "G1 free/type",
        "VNDF free/type",
        "sample+pdf"
    );
    macro_rules! ndf_rows {
        ($F:ty, $N:ty, $name:expr, $free:ident) => {{
            let w: Vec<[$F; 3]> =
                i.w.iter()
                    .map(|w| [w.x as $F, w.y as $F, w.z as $F])
                    .collect();
            let xi: Vec<[$F; 2]> = i.xi.iter().map(|x| x.map(|x| x as $F)).collect();
            // 64 materials, the call's chosen by the input index (a renderer's few
            // materials stay in cache); the free functions read the same α.
            let a: Vec<$F> = (0..N).map(|k| i.alpha[k % 64] as $F).collect();
            let iso: Vec<Microfacet<$F, $N>> = a[..64]
                .iter()
                .map(|&a| Microfacet::new(a, a).unwrap())
                .collect();
            let aniso: Vec<Microfacet<$F, $N>> = a[..64]
                .iter()
                .map(|&a| Microfacet::new(a, 0.5 * a).unwrap())
                .collect();
            for (label, m) in [("iso", &iso), ("aniso", &aniso)] {
                let t = [
                    paired(
                        calls,
                        |k| $free::d(black_box(w[k][2]), a[k]).to_f64(),
                        |k| m[k % 64].d(black_box(w[k])).to_f64(),
                    ),
                    paired(
                        calls,
                        |k| $free::lambda(black_box(w[k][2]), a[k]).to_f64(),
                        |k| m[k % 64].lambda(black_box(w[k])).to_f64(),
                    ),
                    paired(
                        calls,
                        |k| $free::g1(black_box(w[k][2]), a[k]).to_f64(),
                        |k| m[k % 64].g1(black_box(w[k])).to_f64(),
                    ),
                ];
                let vndf = time(calls, |k| {
                    m[k % 64].sample_wm(w[k], black_box(xi[k]))[2].to_f64()
                });
                let pdf = time(calls, |k| {
                    m[k % 64].sample(w[k], black_box(xi[k])).pdf.to_f64()
                });
                let cell = |j: usize| {
                    let (f, t) = t[j];
                    format!("{f:5.1}/{t:5.1} {:4.2}×", t / f)
                };
                println!(
                    "{:24} {:>20} {:>20} {:>20} {:>14} {:>14}",
                    format!("{} {} {label}", $name, stringify!($F)),
                    cell(0),
                    cell(1),
                    cell(2),
                    format!("{vndf:5.1}"),
                    format!("{pdf:5.1}")
                );
            }
        }};
    }
    macro_rules! both {
        ($N:ty, $name:expr, $free:ident) => {
            ndf_rows!(f64, $N, $name, $free);
            ndf_rows!(f32, $N, $name, $free);
        };
    }
    both!(microsurface::Ggx, "GGX", fg);
    both!(microsurface::Beckmann, "Beckmann", fb);
    both!(microsurface::DoubleGgx, "Double GGX", dg);
    both!(microsurface::Exponential, "Exponential", ex);
}

/// Median ns per element of each pass over 21 rounds in which the passes run in turn.
fn in_turn<const K: usize>(elements: usize, mut passes: [&mut dyn FnMut(); K]) -> [f64; K] {
    let mut runs = [const { Vec::new() }; K];
    for _ in 0..21 {
        for (f, r) in passes.iter_mut().zip(runs.iter_mut()) {
            let start = Instant::now();
            f();
            r.push(start.elapsed().as_secs_f64() * 1e9 / elements as f64);
        }
    }
    runs.map(median)
}

/// The wavefront slices (issue 20, item 6): GGX and Beckmann visible normals and the GGX
/// conductor's eval and sample over 2^14 elements (cache-resident, as a renderer's wavefront
/// of one material), against a loop over the scalar `Microfacet`/`Bsdf` calls and against
/// the BSDF's NDF parts (D, G2, the RGB conductor Fresnel, and for sampling the visible
/// normal) timed as loops of their own.
fn wavefront(i: &Inputs) {
    use microsurface::bsdf::fresnel::{self, Fresnel};
    use microsurface::bsdf::{Bsdf, RoughConductor};
    use microsurface::fast::batch::{self, GgxConductor, Vectors, VectorsMut};
    const LEN: usize = 1 << 14;
    println!();
    println!(
        "wavefront slices of 2^14 (ns per element, median of 21 rounds run in turn; one material, α = (0.3, 0.15); {:?} dispatch)",
        batch::simd()
    );
    macro_rules! rows {
        ($F:ty, $vndf:path, $bvndf:path, $eval:path, $sample:path) => {{
            let wo: [Vec<$F>; 3] = [0, 1, 2].map(|c| {
                (0..LEN)
                    .map(|k| {
                        let w = i.w[k % N];
                        [w.x, w.y, w.z][c] as $F
                    })
                    .collect()
            });
            // wi: the mirror of wo about a perturbed normal (mostly the same hemisphere).
            let wi: [Vec<$F>; 3] = [0, 1, 2].map(|c| {
                (0..LEN)
                    .map(|k| {
                        let w = i.w[(k * 7 + 1) % N];
                        [w.x, w.y, w.z][c] as $F
                    })
                    .collect()
            });
            let u0: Vec<$F> = (0..LEN).map(|k| i.xi[k % N][0] as $F).collect();
            let u1: Vec<$F> = (0..LEN).map(|k| i.xi[k % N][1] as $F).collect();
            let ggx = Microfacet::<$F, Ggx>::new(0.3, 0.15).unwrap();
            let beck = Microfacet::<$F, Beckmann>::new(0.3, 0.15).unwrap();
            let gold = fresnel::Conductor { eta: [0.14, 0.42, 1.37], k: [3.98, 2.38, 1.60] };
            let b: GgxConductor<$F> = RoughConductor::new(ggx.clone(), gold);
            let mut o: [Vec<$F>; 3] = [vec![0.0; LEN], vec![0.0; LEN], vec![0.0; LEN]];
            let mut o2: [Vec<$F>; 3] = [vec![0.0; LEN], vec![0.0; LEN], vec![0.0; LEN]];
            let mut p: Vec<$F> = vec![0.0; LEN];
            let name = stringify!($F);
            // Visible normals.
            let [ox, oy, oz] = &mut o;
            let mut loop_g = || {
                for k in 0..LEN {
                    let m = ggx.sample_wm([wo[0][k], wo[1][k], wo[2][k]], [u0[k], u1[k]]);
                    (ox[k], oy[k], oz[k]) = (m[0], m[1], m[2]);
                }
                black_box(&ox);
            };
            let [qx, qy, qz] = &mut o2;
            let mut slice_g = || {
                $vndf(
                    &ggx,
                    Vectors { x: &wo[0], y: &wo[1], z: &wo[2] },
                    &u0,
                    &u1,
                    VectorsMut { x: qx, y: qy, z: qz },
                );
                black_box(&qx);
            };
            let [g_loop, g_slice] = in_turn(LEN, [&mut loop_g, &mut slice_g]);
            let [ox, oy, oz] = &mut o;
            let mut loop_b = || {
                for k in 0..LEN {
                    let m = beck.sample_wm([wo[0][k], wo[1][k], wo[2][k]], [u0[k], u1[k]]);
                    (ox[k], oy[k], oz[k]) = (m[0], m[1], m[2]);
                }
                black_box(&ox);
            };
            let [qx, qy, qz] = &mut o2;
            let mut slice_b = || {
                $bvndf(
                    &beck,
                    Vectors { x: &wo[0], y: &wo[1], z: &wo[2] },
                    &u0,
                    &u1,
                    VectorsMut { x: qx, y: qy, z: qz },
                );
                black_box(&qx);
            };
            let [b_loop, b_slice] = in_turn(LEN, [&mut loop_b, &mut slice_b]);
            println!(
                "GGX VNDF {name}: loop {g_loop:5.2} | slice {g_slice:5.2} ({:4.2}× the loop)",
                g_loop / g_slice
            );
            println!(
                "Beckmann VNDF {name}: loop {b_loop:5.2} | slice {b_slice:5.2} ({:4.2}× the loop; {:4.2}× GGX's slice)",
                b_loop / b_slice,
                b_slice / g_slice
            );
            // The conductor's eval + pdf, and its parts.
            let [ox, oy, oz] = &mut o;
            let mut loop_e = || {
                for k in 0..LEN {
                    let (a, c) = ([wo[0][k], wo[1][k], wo[2][k]], [wi[0][k], wi[1][k], wi[2][k]]);
                    let (f, pdf) = b.eval_pdf(a, c);
                    (ox[k], oy[k], oz[k], p[k]) = (f[0], f[1], f[2], pdf);
                }
                black_box(&ox);
            };
            let [qx, qy, qz] = &mut o2;
            let mut pp: Vec<$F> = vec![0.0; LEN];
            let mut slice_e = || {
                $eval(
                    &b,
                    Vectors { x: &wo[0], y: &wo[1], z: &wo[2] },
                    Vectors { x: &wi[0], y: &wi[1], z: &wi[2] },
                    [&mut *qx, &mut *qy, &mut *qz],
                    &mut pp,
                );
                black_box(&qx);
            };
            // The parts: D at the normal, G2 of the pair, the RGB Fresnel at its cosine (the
            // half vector itself not included).
            let mut acc = vec![0.0 as $F; LEN];
            let mut parts_e = || {
                for k in 0..LEN {
                    let (a, c) = ([wo[0][k], wo[1][k], wo[2][k]], [wi[0][k], wi[1][k], wi[2][k]]);
                    let fr = gold.eval(a[2].abs());
                    acc[k] = ggx.d(a) + ggx.g2(a, c) + fr[0] + fr[1] + fr[2];
                }
                black_box(&acc);
            };
            let [e_loop, e_slice, e_parts] =
                in_turn(LEN, [&mut loop_e, &mut slice_e, &mut parts_e]);
            println!(
                "GGX conductor eval+pdf {name}: loop {e_loop:5.2} | slice {e_slice:5.2} ({:4.2}× the loop) | parts (D, G2, Fresnel) {e_parts:5.2}: loop {:4.2}×, slice {:4.2}× the parts",
                e_loop / e_slice,
                e_loop / e_parts,
                e_slice / e_parts
            );
            // The conductor's sample, and its parts (the visible normal, D, G2, Fresnel).
            let [ox, oy, oz] = &mut o;
            let mut loop_s = || {
                for k in 0..LEN {
                    let a = [wo[0][k], wo[1][k], wo[2][k]];
                    match b.sample(a, 0.0, [u0[k], u1[k]]) {
                        Some(s) => (ox[k], oy[k], oz[k], p[k]) = (s.f[0], s.f[1], s.f[2], s.pdf),
                        None => p[k] = 0.0,
                    }
                }
                black_box(&ox);
            };
            let [qx, qy, qz] = &mut o2;
            let (mut wx, mut wy, mut wz) = (vec![0.0; LEN], vec![0.0; LEN], vec![0.0; LEN]);
            let mut slice_s = || {
                $sample(
                    &b,
                    Vectors { x: &wo[0], y: &wo[1], z: &wo[2] },
                    &u0,
                    &u1,
                    VectorsMut { x: &mut wx, y: &mut wy, z: &mut wz },
                    [&mut *qx, &mut *qy, &mut *qz],
                    &mut pp,
                );
                black_box(&qx);
            };
            let mut parts_s = || {
                for k in 0..LEN {
                    let a = [wo[0][k], wo[1][k], wo[2][k]];
                    let m = ggx.sample_wm(a, [u0[k], u1[k]]);
                    let fr = gold.eval(m[2]);
                    acc[k] = ggx.d(m) + ggx.g2(a, m) + fr[0] + fr[1] + fr[2];
                }
                black_box(&acc);
            };
            let [s_loop, s_slice, s_parts] =
                in_turn(LEN, [&mut loop_s, &mut slice_s, &mut parts_s]);
            println!(
                "GGX conductor sample {name}: loop {s_loop:5.2} | slice {s_slice:5.2} ({:4.2}× the loop) | parts (VNDF, D, G2, Fresnel) {s_parts:5.2}: loop {:4.2}×, slice {:4.2}× the parts",
                s_loop / s_slice,
                s_loop / s_parts,
                s_slice / s_parts
            );
        }};
    }
    rows!(
        f32,
        batch::ggx_sample_visible_f32,
        batch::beckmann_sample_visible_f32,
        batch::ggx_conductor_eval_f32,
        batch::ggx_conductor_sample_f32
    );
    rows!(
        f64,
        batch::ggx_sample_visible_f64,
        batch::beckmann_sample_visible_f64,
        batch::ggx_conductor_eval_f64,
        batch::ggx_conductor_sample_f64
    );
}

/// The microsurface random walk (issue 21): walks per second for an F = 1 conductor at
/// α = 0.5, μ = 0.5, every NDF, one core and both cores (rayon::join of two halves with
/// their own seeds), in the same run as the fast GGX VNDF sampler (the walk's inner step).
fn walks(i: &Inputs) {
    use microsurface::bsdf::fresnel::One;
    use microsurface::scattering::{albedo, Heights, MirrorFacets, RandomWalk};
    println!();
    let vndf = time(400_000, |k| {
        let w = i.w[k];
        type_vndf::<Ggx, f64>([w.x, w.y, w.z], 0.5, black_box(i.xi[k]))[2]
    });
    println!("microsurface walks (F = 1 conductor, α = 0.5, μ = 0.5; million walks per second, median of 5; GGX VNDF in this run {vndf:.1} ns)");
    let wo = [0.75f64.sqrt(), 0.0, 0.5];
    macro_rules! rate {
        ($name:expr, $d:expr) => {
            rate!($name, $d, 400_000u64)
        };
        ($name:expr, $d:expr, $n:expr) => {{
            let s = RandomWalk::new($d, Heights::Uniform);
            let n: u64 = $n;
            let mut one = Vec::new();
            let mut two = Vec::new();
            let mut pair = Vec::new();
            for r in 0..5 {
                let t = Instant::now();
                black_box(albedo(&s, &MirrorFacets(One::<1>), wo, n, r));
                one.push(n as f64 / t.elapsed().as_secs_f64() / 1e6);
                let t = Instant::now();
                let (a, b) = rayon::join(
                    || albedo(&s, &MirrorFacets(One::<1>), wo, n, 2 * r + 100),
                    || albedo(&s, &MirrorFacets(One::<1>), wo, n, 2 * r + 101),
                );
                black_box((a, b));
                two.push(2.0 * n as f64 / t.elapsed().as_secs_f64() / 1e6);
                // The machine's own pair scaling: the same two calls on two OS threads, no
                // rayon (its ceiling for rayon).
                let t = Instant::now();
                std::thread::scope(|sc| {
                    let h = sc.spawn(|| albedo(&s, &MirrorFacets(One::<1>), wo, n, 2 * r + 200));
                    black_box(albedo(&s, &MirrorFacets(One::<1>), wo, n, 2 * r + 201));
                    black_box(h.join().ok());
                });
                pair.push(2.0 * n as f64 / t.elapsed().as_secs_f64() / 1e6);
            }
            let (one, two, pair) = (median(one), median(two), median(pair));
            println!(
                "{:24} {one:7.3} M/s one core | {two:7.3} M/s rayon ({:4.2}×) | {pair:7.3} M/s two threads ({:4.2}×)",
                $name,
                two / one,
                pair / one
            );
        }};
    }
    rate!("GGX", Microfacet::<f64, Ggx>::new(0.5, 0.5).unwrap());
    rate!(
        "Beckmann",
        Microfacet::<f64, Beckmann>::new(0.5, 0.5).unwrap()
    );
    rate!(
        "Double GGX",
        Microfacet::<f64, DoubleGgx>::new(0.5, 0.5).unwrap()
    );
    rate!(
        "Exponential",
        Microfacet::<f64, Exponential>::new(0.5, 0.5).unwrap()
    );
    rate!(
        "GTR γ = 1.5",
        Microfacet::<f64, Gtr>::gtr(0.5, 0.5, 1.5).unwrap()
    );
    // The exact path (`Exact`, f64 kernels with quadratures where the NDF needs them): GGX
    // as its baseline, then the family (visible normals by the Beckmann mixtures' posterior
    // stream sampler; fewer walks where Λ is a quadrature).
    use microsurface::{Exact, NdfKind};
    let exact = |kind, shape| Exact::new(kind, 0.5, 0.5, shape).unwrap();
    rate!("Exact GGX", exact(NdfKind::Ggx, None), 100_000);
    rate!(
        "Exact Student-T γ = 2.5",
        exact(NdfKind::StudentT, Some(2.5)),
        100_000
    );
    rate!("Exact K0", exact(NdfKind::K0, None), 100_000);
    rate!("Exact Ei", exact(NdfKind::Ei, None), 20_000);
    rate!("Exact Erfc", exact(NdfKind::Erfc, None), 20_000);
    rate!(
        "Exact Bessel-K a = 2.5",
        exact(NdfKind::BesselK, Some(2.5)),
        4_000
    );
    // The family's fast path (fitted Λ; the same posterior sampler).
    use microsurface::{BesselK, Ei, StudentT};
    rate!(
        "Fast Student-T γ = 2.5",
        Microfacet::<f64, StudentT>::with_shape(0.5, 0.5, Some(2.5)).unwrap()
    );
    rate!(
        "Fast Ei",
        Microfacet::<f64, Ei>::with_shape(0.5, 0.5, None).unwrap()
    );
    rate!(
        "Fast Bessel-K a = 2.5",
        Microfacet::<f64, BesselK>::with_shape(0.5, 0.5, Some(2.5)).unwrap()
    );
}

/// `albedo_orders` (interleaved walks) against `albedo_orders_serial` (one walk after
/// another, the code before), F = 1 conductor, GGX and Beckmann, α ∈ {0.1, 0.5, 1},
/// μ ∈ {0.2, 0.8}, one core: the two in turn in each round, 200 000 walks each, the ratio per
/// round (the first of the two alternating); medians over the rounds.
fn walk_lanes() {
    use microsurface::bsdf::fresnel::One;
    use microsurface::scattering::{
        albedo_orders, albedo_orders_serial, Heights, MirrorFacets, RandomWalk,
    };
    let rounds: usize = std::env::var("MICROSURFACE_ROUNDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(9);
    println!("walks interleaved vs serial (F = 1 conductor; M walks/s one core, median of {rounds} rounds; ratio per round)");
    macro_rules! row {
        ($name:expr, $n:ty) => {
            for alpha in [0.1, 0.5, 1.0] {
                for mu in [0.2f64, 0.8] {
                    let s = RandomWalk::new(
                        Microfacet::<f64, $n>::new(alpha, alpha).unwrap(),
                        Heights::Uniform,
                    );
                    let wo = [((1.0 - mu) * (1.0 + mu)).sqrt(), 0.0, mu];
                    let n = 200_000u64;
                    let (mut a, mut b, mut r) = (Vec::new(), Vec::new(), Vec::new());
                    for k in 0..rounds {
                        let serial = || {
                            let t = Instant::now();
                            black_box(albedo_orders_serial(
                                &s,
                                &MirrorFacets(One::<1>),
                                wo,
                                n,
                                k as u64,
                                4,
                            ));
                            t.elapsed().as_secs_f64()
                        };
                        let lanes = || {
                            let t = Instant::now();
                            black_box(albedo_orders(
                                &s,
                                &MirrorFacets(One::<1>),
                                wo,
                                n,
                                k as u64,
                                4,
                            ));
                            t.elapsed().as_secs_f64()
                        };
                        // (The two in turn, the first alternating between rounds.)
                        let (ts, tl) = if k % 2 == 0 {
                            let ts = serial();
                            (ts, lanes())
                        } else {
                            let tl = lanes();
                            (serial(), tl)
                        };
                        a.push(n as f64 / ts / 1e6);
                        b.push(n as f64 / tl / 1e6);
                        r.push(ts / tl);
                    }
                    println!(
                        "{:9} α = {alpha:3} μ = {mu}: serial {:6.3}  2 lanes {:6.3} M/s {:5.3}×",
                        $name,
                        median(a),
                        median(b),
                        median(r)
                    );
                }
            }
        };
    }
    row!("GGX", Ggx);
    row!("Beckmann", Beckmann);
}

/// Visible normals through `Microfacet` (the material built in each call, as a renderer with
/// textured roughness does), `sample_wm` and `sample` (with its pdf), f64 and f32, each in
/// rounds interleaved with the C GGX sampler (Heitz 2018, f64): the ratios are per round.
fn samplers_vs_c(i: &Inputs, calls: usize) {
    let w32: Vec<[f32; 3]> =
        i.w.iter()
            .map(|w| [w.x as f32, w.y as f32, w.z as f32])
            .collect();
    let xi32: Vec<[f32; 2]> = i.xi.iter().map(|x| [x[0] as f32, x[1] as f32]).collect();
    let a32: Vec<f32> = i.alpha.iter().map(|&a| a as f32).collect();
    let c_vndf = |k: usize| {
        let w = i.w[k];
        c::ggx_vndf([w.x, w.y, w.z], i.alpha[k], i.alpha[k], black_box(i.xi[k]))[2]
    };
    let pair = |name: &str, f: &mut dyn FnMut(usize) -> f64| {
        let (mut ratios, mut ts, mut tc) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..15 {
            let c = once(calls, &mut |k| c_vndf(k));
            let t = once(calls, &mut |k| f(k));
            ratios.push(t / c);
            ts.push(t);
            tc.push(c);
        }
        println!(
            "{name:44} {:7.2} ns  C {:6.2} ns  {:5.2}× C GGX VNDF",
            median(ts),
            median(tc),
            median(ratios)
        );
    };
    macro_rules! door {
        ($n:ty, $name:expr) => {
            pair(concat!($name, " sample_wm f64"), &mut |k| {
                let (w, a) = (i.w[k], i.alpha[k]);
                Microfacet::<f64, $n>::new(a, a)
                    .unwrap()
                    .sample_wm([w.x, w.y, w.z], black_box(i.xi[k]))[2]
            });
            pair(concat!($name, " sample f64 (with pdf)"), &mut |k| {
                let (w, a) = (i.w[k], i.alpha[k]);
                let s = Microfacet::<f64, $n>::new(a, a)
                    .unwrap()
                    .sample([w.x, w.y, w.z], black_box(i.xi[k]));
                s.wm[2] + s.pdf
            });
            pair(concat!($name, " sample_wm f32"), &mut |k| {
                let a = a32[k];
                Microfacet::<f32, $n>::new(a, a)
                    .unwrap()
                    .sample_wm(w32[k], black_box(xi32[k]))[2] as f64
            });
            pair(concat!($name, " sample f32 (with pdf)"), &mut |k| {
                let a = a32[k];
                let s = Microfacet::<f32, $n>::new(a, a)
                    .unwrap()
                    .sample(w32[k], black_box(xi32[k]));
                (s.wm[2] + s.pdf) as f64
            });
        };
    }
    door!(Ggx, "GGX");
    // The pdf alone at precomputed normals (where `sample`'s extra time goes).
    let wm64: Vec<[f64; 3]> = (0..N)
        .map(|k| {
            let (w, a) = (i.w[k], i.alpha[k]);
            Microfacet::<f64, Ggx>::new(a, a)
                .unwrap()
                .sample_wm([w.x, w.y, w.z], i.xi[k])
        })
        .collect();
    let wm32: Vec<[f32; 3]> = wm64.iter().map(|m| m.map(|x| x as f32)).collect();
    pair("GGX pdf f64", &mut |k| {
        let (w, a) = (i.w[k], i.alpha[k]);
        Microfacet::<f64, Ggx>::new(a, a)
            .unwrap()
            .pdf([w.x, w.y, w.z], black_box(wm64[k]))
    });
    pair("GGX pdf f32", &mut |k| {
        let a = a32[k];
        Microfacet::<f32, Ggx>::new(a, a)
            .unwrap()
            .pdf(w32[k], black_box(wm32[k])) as f64
    });
    door!(Beckmann, "Beckmann");
    vndf_slices_vs_c(i, calls);
}

/// The GGX visible-normal slices (`fast::batch::ggx_sample_visible_f32/_f64`, one material
/// α = 0.3, N elements) on each instruction set this CPU has (`batch::cap_simd`), ns per
/// element against the C GGX sampler at α = 0.3 over the same elements, interleaved: the
/// median of 15 per-round ratios (issue 35, target 3).
fn vndf_slices_vs_c(i: &Inputs, calls: usize) {
    use microsurface::fast::batch::{self, Simd, Vectors, VectorsMut};
    let c = |k: usize| {
        let w = i.w[k];
        c::ggx_vndf([w.x, w.y, w.z], 0.3, 0.3, black_box(i.xi[k]))[2]
    };
    let rounds = (calls / N).max(1);
    macro_rules! isa_rows {
        ($F:ty, $slice:path) => {{
            let w: [Vec<$F>; 3] =
                [0, 1, 2].map(|j| i.w.iter().map(|v| [v.x, v.y, v.z][j] as $F).collect());
            let u0: Vec<$F> = i.xi.iter().map(|x| x[0] as $F).collect();
            let u1: Vec<$F> = i.xi.iter().map(|x| x[1] as $F).collect();
            let m = Microfacet::<$F, Ggx>::new(0.3, 0.3).unwrap();
            let mut o: [Vec<$F>; 3] = [vec![0.0; N], vec![0.0; N], vec![0.0; N]];
            for isa in [Simd::Generic, Simd::Avx2, Simd::Avx512] {
                if isa > batch::detected_simd() {
                    continue;
                }
                batch::cap_simd(Some(isa));
                let (mut ratios, mut ts) = (Vec::new(), Vec::new());
                for _ in 0..15 {
                    let tc = once(rounds * N, &mut |k| c(k));
                    let start = Instant::now();
                    for _ in 0..rounds {
                        let [ox, oy, oz] = &mut o;
                        $slice(
                            &m,
                            Vectors {
                                x: &w[0],
                                y: &w[1],
                                z: &w[2],
                            },
                            &u0,
                            &u1,
                            VectorsMut {
                                x: ox,
                                y: oy,
                                z: oz,
                            },
                        );
                        black_box(&o);
                    }
                    let t = start.elapsed().as_secs_f64() * 1e9 / (rounds * N) as f64;
                    ratios.push(t / tc);
                    ts.push(t);
                }
                batch::cap_simd(None);
                println!(
                    "{:44} {:7.2} ns  {:5.3}× C GGX VNDF",
                    format!("GGX VNDF slice {} {:?}", stringify!($F), isa),
                    median(ts),
                    median(ratios)
                );
            }
        }};
    }
    isa_rows!(f32, batch::ggx_sample_visible_f32);
    isa_rows!(f64, batch::ggx_sample_visible_f64);
}

/// µs a call of the exact (research) path's Λ, G1 and σ(−u) for every NDF, the material built
/// per call (as a sweep over α does), at random α ∈ [0.05, 1], u ∈ [0.02, 0.99] and the
/// shapes listed; GGX's closed form as the baseline.
fn exact_path(i: &Inputs) {
    use microsurface::{AnyNdf, NdfKind::*};
    let cases: [(microsurface::NdfKind, Option<f64>); 16] = [
        (Ggx, None),
        (Beckmann, None),
        (DoubleGgx, None),
        (Exponential, None),
        (Gtr, Some(1.5)),
        (Gtr, Some(0.7)),
        (Gtr, Some(3.3)),
        (StudentT, Some(2.5)),
        (StudentT, Some(30.0)),
        (Ei, None),
        (Erfc, None),
        (K0, None),
        (BesselK, Some(0.4)),
        (BesselK, Some(3.0)),
        (GenExponential, Some(0.4)),
        (GenExponential, Some(8.0)),
    ];
    println!(
        "{:36} {:>10} {:>10} {:>10}",
        "exact path, µs a call", "Λ", "G1", "σ(−u)"
    );
    for (kind, shape) in cases {
        let calls = if kind == GenExponential { 100 } else { 2_000 };
        let ndf = |k: usize| AnyNdf::new(kind, i.alpha[k], shape).unwrap();
        let l = time(calls, |k| ndf(k).lambda(black_box(i.u[k])));
        let g = time(calls, |k| ndf(k).g1(black_box(i.u[k])));
        let s = time(calls, |k| ndf(k).sigma(-black_box(i.u[k])));
        let name = match shape {
            Some(x) => format!("{kind} {x}"),
            None => kind.to_string(),
        };
        println!(
            "{name:36} {:10.2} {:10.2} {:10.2}",
            l * 1e-3,
            g * 1e-3,
            s * 1e-3
        );
    }
}

/// Construction per call (issue 45): for every NDF of the door, f32 and f64, the first
/// material of its shape in the process (the one-time fit, if any) and then materials at
/// α drawn per call from 4096 distinct values, each built through `AnyMicrofacet::new`,
/// against GGX's in the same run; the compensated BSDFs built per call; and the textured
/// rows: α per call from a 256² texture, the material and its BSDF built at each call, then
/// a sample and eval_pdf through `Box<dyn Bsdf>`, against one constant material.
fn construction(i: &Inputs) {
    use microsurface::bsdf::fresnel::Conductor;
    use microsurface::bsdf::{Bsdf, RoughConductor};
    use microsurface::scattering::{CompensatedConductor, CompensatedDielectric, Scheme};
    use microsurface::AnyMicrofacet;
    println!();
    println!("construction: AnyMicrofacet::<F>::new(kind, α, α, shape), α per call in [0.05, 1] (ns per material; ratio to GGX's in the same run)");
    let kinds: [(NdfKind, Option<f64>); 11] = [
        (NdfKind::Ggx, None),
        (NdfKind::Beckmann, None),
        (NdfKind::DoubleGgx, None),
        (NdfKind::Exponential, None),
        (NdfKind::Gtr, Some(1.5)),
        (NdfKind::StudentT, Some(2.5)),
        (NdfKind::Ei, None),
        (NdfKind::Erfc, None),
        (NdfKind::K0, None),
        (NdfKind::BesselK, Some(0.7)),
        (NdfKind::GenExponential, Some(1.0)),
    ];
    let a32: Vec<f32> = i.alpha.iter().map(|&a| a as f32).collect();
    // GTR's construction is milliseconds per new α today: fewer calls, so that the row ends.
    let calls_of = |k: NdfKind| if k == NdfKind::Gtr { 64 } else { 200_000 };
    let build64 = |k: NdfKind, s: Option<f64>, calls: usize| {
        time(calls, |j| {
            let m = AnyMicrofacet::<f64>::new(k, black_box(i.alpha[j]), i.alpha[j], s).unwrap();
            black_box(&m);
            m.is_fast() as u8 as f64
        })
    };
    let build32 = |k: NdfKind, s: Option<f64>, calls: usize| {
        time(calls, |j| {
            let m = AnyMicrofacet::<f32>::new(k, black_box(a32[j]), a32[j], s).unwrap();
            black_box(&m);
            m.is_fast() as u8 as f64
        })
    };
    let (g64, g32) = (
        build64(NdfKind::Ggx, None, 200_000),
        build32(NdfKind::Ggx, None, 200_000),
    );
    for (k, s) in kinds {
        let t = Instant::now();
        let first = AnyMicrofacet::<f64>::new(k, 0.3, 0.3, s).unwrap();
        let first_ms = t.elapsed().as_secs_f64() * 1e3;
        black_box(first);
        let (t64, t32) = (build64(k, s, calls_of(k)), build32(k, s, calls_of(k)));
        let name = match s {
            Some(x) => format!("{k}:{x}"),
            None => k.to_string(),
        };
        println!(
            "{name:24} first use {first_ms:9.3} ms | after: f64 {t64:10.1} ns {:8.2}× | f32 {t32:10.1} ns {:8.2}×{}",
            t64 / g64,
            t32 / g32,
            if k == NdfKind::Gtr {
                " (64 α cycled, each fitted once: every new α is a first use)"
            } else {
                ""
            }
        );
    }
    println!();
    println!("compensated construction, f32, α per call (ns per BSDF; isotropic, gold's complex Fresnel)");
    let gold = Conductor {
        eta: [0.14f32, 0.42, 1.37],
        k: [3.98, 2.38, 1.60],
    };
    for (k, s) in [(NdfKind::Ggx, None), (NdfKind::Beckmann, None)] {
        let iso = time(20_000, |j| {
            let m = AnyMicrofacet::<f32>::new(k, a32[j], a32[j], s).unwrap();
            let b = CompensatedConductor::new(m, gold, Scheme::KullaConty);
            black_box(&b);
            b.table().e_avg()
        });
        let turquin = time(20_000, |j| {
            let m = AnyMicrofacet::<f32>::new(k, a32[j], a32[j], s).unwrap();
            let b = CompensatedConductor::new(m, gold, Scheme::Turquin);
            black_box(&b);
            b.table().e_avg()
        });
        let table = time(20_000, |j| {
            let m = AnyMicrofacet::<f32>::new(k, a32[j], a32[j], s).unwrap();
            microsurface::scattering::AlbedoTable::new(&m).e_avg()
        });
        let die = time(20_000, |j| {
            let m = AnyMicrofacet::<f32>::new(k, a32[j], a32[j], s).unwrap();
            let b = CompensatedDielectric::new(m, 1.5f32, Scheme::KullaConty).unwrap();
            black_box(&b);
            b.tables().outside.e_avg()
        });
        println!(
            "{k:24} conductor: Kulla–Conty {iso:8.1} ns, Turquin {turquin:8.1} ns, its table alone {table:8.1} ns | dielectric η = 1.5 {die:8.1} ns"
        );
    }
    println!();
    println!("textured: α per call from a 256² texture, material + RoughConductor built per call, sample + eval_pdf through Box<dyn Bsdf<f32>> (ns per call; ratio to one constant material)");
    let mut s = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 40) as f32 / (1u64 << 24) as f32
    };
    let texture: Vec<f32> = (0..256 * 256).map(|_| 0.05 + 0.95 * next()).collect();
    let w32: Vec<[f32; 3]> =
        i.w.iter()
            .map(|w| [w.x as f32, w.y as f32, w.z as f32])
            .collect();
    let xi32: Vec<[f32; 2]> = i.xi.iter().map(|x| [x[0] as f32, x[1] as f32]).collect();
    type Dyn = Box<dyn Bsdf<f32, Value = [f32; 3]>>;
    for (k, s) in kinds {
        if k == NdfKind::Gtr {
            // (Milliseconds per new α today: the row would not end.)
            println!(
                "{:24} (per-α fit: not measured textured)",
                format!("{k}:1.5")
            );
            continue;
        }
        let calls = if k == NdfKind::GenExponential {
            2_000
        } else {
            100_000
        };
        let constant: Dyn = Box::new(RoughConductor::new(
            AnyMicrofacet::<f32>::new(k, 0.3, 0.3, s).unwrap(),
            gold,
        ));
        let step = |b: &Dyn, j: usize| {
            let wo = w32[j];
            let wo = [wo[0], wo[1], wo[2].abs().max(1e-3)];
            match b.sample(wo, 0.5, xi32[j]) {
                Some(smp) => b.eval_pdf(wo, smp.wi).1 as f64,
                None => 0.0,
            }
        };
        let mut tex_at = 0usize;
        let textured = time(calls, |j| {
            tex_at = (tex_at + 40_503) & 0xffff;
            let a = texture[tex_at];
            let b: Dyn = Box::new(RoughConductor::new(
                AnyMicrofacet::<f32>::new(k, a, a, s).unwrap(),
                gold,
            ));
            step(&b, j)
        });
        let fixed = time(calls, |j| step(&constant, j));
        let name = match s {
            Some(x) => format!("{k}:{x}"),
            None => k.to_string(),
        };
        println!(
            "{name:24} textured {textured:10.1} ns | constant {fixed:10.1} ns | {:6.2}×",
            textured / fixed
        );
    }
}
