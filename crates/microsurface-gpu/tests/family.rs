//! Double GGX and the Exponential NDF in WGSL (double_ggx.wgsl, exponential.wgsl,
//! stream.wgsl) against the Rust f32 path, element by element, as tests/lavapipe.rs does for
//! GGX and Beckmann (the same grids: roughness 2e-3 to 2, isotropic and anisotropic; normal
//! incidence to cos θ = 1e-4 and below the horizon; uniforms 0, 2⁻²⁴, ¼, ½, 0.9, 1 − 2⁻²⁴),
//! through the test kernels of `kernels.wgsl` (the tables bound as `microsurface_gpu::TABLES`).
//!
//! Bounds, per element, from the f32 bounds of the Rust docs and each quantity's
//! conditioning (`TOL` = 2e-6: twice the f32 fast paths' documented 1e-6):
//! * D and Λ: `grid::d_bound` and `grid::lambda_bound` (each NDF's derivation is there).
//! * G1 = 1/(1 + Λ), G2: Λ's bound times Λ/(1 + Λ) (≤ 1), plus `TOL`; the visible pdf: G1's
//!   and D's plus 8ε times the dot product's cancellation |w||m|/|w·m|.
//! * D·cos normals: 16ε per component (`NORMAL_TOL`, as GGX's): the stream's uniforms are
//!   bit for bit the Rust ones; the ziggurat's x = (256w − i)xᵢ with xᵢ rounded to f32, the
//!   tail's −ln(1 − v) (Vulkan: 2^−21 absolute, below ε of t ≥ 7.7) and ln(1 − u₀) cost t
//!   (or r) a few ε, the azimuth's cos/sin as GGX's. The ziggurat's accept decisions are
//!   compared in f32 here and f64 in Rust; they differ only where x lies within an ulp of a
//!   layer edge or of e^{−x} (probability ~1e-7 per draw), which these grids do not meet.
//! * The uniform stream: bit for bit (the first two 64-bit outputs of SplitMix64 seeded
//!   from u, against the Rust `UniformStream`'s f64 and f32 draws).

use microsurface::distribution::UniformStream;
use microsurface::{
    AnyMicrofacet, DoubleGgx, Exponential, Microfacet, MicrofacetDistribution, NdfKind,
};
use microsurface_gpu::{kernels_source, Error, Gpu, Program, Tables, KERNEL_IN, KERNEL_OUT};
use std::sync::OnceLock;

mod grid;
use grid::{
    d_bound, directions, gpu_quantities, lambda_bound, normals, quantity_bounds, rel_flushed,
    rust_quantities, shaped_d_bound, shaped_lambda_bound, uniforms, vec_diff, visible_cancellation,
    Worst, ALPHAS, EPS, NDF_DOUBLE_GGX, NDF_EXPONENTIAL, QUANTITIES, TOL,
};

/// The device and the compiled kernels, once per test binary; `None` (the tests skip) only
/// where no Vulkan adapter exists and `MICROSURFACE_GPU_REQUIRED` is not 1.
fn gpu() -> Option<&'static (Gpu, Program)> {
    static GPU: OnceLock<Option<(Gpu, Program)>> = OnceLock::new();
    GPU.get_or_init(|| {
        let required = std::env::var("MICROSURFACE_GPU_REQUIRED").as_deref() == Ok("1");
        let mut tables = Tables::new();
        let rows: Vec<u32> = SHAPED
            .iter()
            .map(|&(kind, shape, _)| tables.add_shape(kind, shape).expect("a shape table"))
            .collect();
        let _ = SHAPE_ROWS.set(rows);
        match Gpu::with_tables(&tables) {
            Ok(g) => {
                let p = g.program(&kernels_source()).expect("the kernels validate");
                Some((g, p))
            }
            Err(Error::NoAdapter(m)) if !required => {
                eprintln!("SKIPPED: no Vulkan adapter ({m})");
                None
            }
            Err(e) => panic!("MICROSURFACE_GPU_REQUIRED=1 or a device error: {e}"),
        }
    })
    .as_ref()
}

/// The NDFs with shape tables, with their shapes and MsMicrofacet tags: Student-T near the
/// pole at 3/2, GGX's neighbour, and two where the tails approach Beckmann's; Ei, Erfc, K0;
/// Bessel-K with a pole at the normal (a = 0.4) and without (a = 2.5).
const SHAPED: [(NdfKind, Option<f64>, u32); 9] = [
    (NdfKind::StudentT, Some(1.8), 5),
    (NdfKind::StudentT, Some(2.5), 5),
    (NdfKind::StudentT, Some(10.0), 5),
    (NdfKind::StudentT, Some(40.0), 5),
    (NdfKind::Ei, None, 6),
    (NdfKind::Erfc, None, 7),
    (NdfKind::K0, None, 8),
    (NdfKind::BesselK, Some(0.4), 9),
    (NdfKind::BesselK, Some(2.5), 9),
];
/// The first four of SHAPED are Student-T.
const STUDENT_T_GAMMAS: [f64; 4] = [1.8, 2.5, 10.0, 40.0];
/// Their shape tables' rows in the bound buffer.
static SHAPE_ROWS: OnceLock<Vec<u32>> = OnceLock::new();
/// An element's `ndf` for SHAPED[k]: 16 + k.
const NDF_SHAPED: u32 = 16;
/// The Student-T ones (SHAPED[0..4]).
const NDF_STUDENT_T_SHAPES: u32 = NDF_SHAPED;

/// The kind and shape of an element with a shape table (`None` for the other NDFs).
fn shaped(e: &El) -> Option<(NdfKind, Option<f64>)> {
    (e.ndf >= NDF_SHAPED).then(|| {
        let (kind, shape, _) = SHAPED[(e.ndf - NDF_SHAPED) as usize];
        (kind, shape)
    })
}

/// Student-T's γ of an element (`None` for the other NDFs).
fn student_t_gamma(e: &El) -> Option<f64> {
    match shaped(e) {
        Some((NdfKind::StudentT, g)) => g,
        _ => None,
    }
}

/// Record 2's w of an element: the NDF plus 16 times its shape table's row.
fn ndf_code(e: &El) -> f32 {
    if e.ndf >= NDF_SHAPED {
        let k = (e.ndf - NDF_SHAPED) as usize;
        let row = SHAPE_ROWS.get().expect("the tables")[k];
        (SHAPED[k].2 + 16 * row) as f32
    } else {
        e.ndf as f32
    }
}

/// One kernel element: (αx, αy, u), wo, (wm, ndf).
#[derive(Clone, Copy, Debug)]
struct El {
    ndf: u32,
    alpha: [f32; 2],
    u: [f32; 2],
    wo: [f32; 3],
    wm: [f32; 3],
}

fn run(entry: &str, els: &[El]) -> Option<Vec<[[f32; 4]; KERNEL_OUT]>> {
    let (g, p) = gpu()?;
    let input: Vec<[f32; 4]> = els
        .iter()
        .flat_map(|e| {
            [
                [e.alpha[0], e.alpha[1], e.u[0], e.u[1]],
                [e.wo[0], e.wo[1], e.wo[2], 0.5],
                [e.wm[0], e.wm[1], e.wm[2], ndf_code(e)],
                [1.0, 1.0, 1.0, 0.0],
                [0.0; 4],
            ]
        })
        .collect();
    let out = g
        .run(p, entry, &input, KERNEL_IN, KERNEL_OUT)
        .expect("the kernel runs");
    Some(out.chunks(KERNEL_OUT).map(|c| [c[0], c[1]]).collect())
}

/// A sampled normal's components: 16ε (see the module docs).
const NORMAL_TOL: f64 = 16.0 * EPS;

/// The Rust f32 material of an element.
fn rust(e: &El) -> Box<dyn MicrofacetDistribution<f32>> {
    let [ax, ay] = e.alpha;
    if let Some((kind, shape)) = shaped(e) {
        return Box::new(AnyMicrofacet::<f32>::new(kind, ax, ay, shape).unwrap());
    }
    if e.ndf == NDF_DOUBLE_GGX {
        Box::new(Microfacet::<f32, DoubleGgx>::new(ax, ay).unwrap())
    } else {
        Box::new(Microfacet::<f32, Exponential>::new(ax, ay).unwrap())
    }
}

#[test]
fn family_d_lambda_g1_g2_pdfs_match_rust_f32() {
    let mut els = Vec::new();
    for ndf in [NDF_DOUBLE_GGX, NDF_EXPONENTIAL] {
        for &alpha in &ALPHAS {
            for &wo in &directions() {
                for &wm in &normals() {
                    els.push(El {
                        ndf,
                        alpha,
                        u: [0.5; 2],
                        wo,
                        wm,
                    });
                }
            }
        }
    }
    let Some(out) = run("ms_k_family_eval", &els) else {
        return;
    };
    let names = QUANTITIES;
    let mut w = [Worst::new(&names), Worst::new(&names)];
    for (e, o) in els.iter().zip(&out) {
        let m = rust(e);
        let (wo, wm) = (e.wo, e.wm);
        let r = rust_quantities(&*m, wo, wm);
        let g = gpu_quantities(o);
        let (lo, li) = (m.lambda(wo) as f64, m.lambda(wm) as f64);
        let (bo, bi) = (
            lambda_bound(e.ndf, wo, e.alpha),
            lambda_bound(e.ndf, wm, e.alpha),
        );
        let d = d_bound(e.ndf, wm, e.alpha);
        let tol = quantity_bounds((bo, bi), (lo, li), d, wo, wm);
        let k = (e.ndf - NDF_DOUBLE_GGX) as usize;
        for q in 0..names.len() {
            w[k].add(q, rel_flushed(g[q], r[q]) / tol[q], || {
                format!("{e:?}: gpu {} rust {} (bound {:e})", g[q], r[q], tol[q])
            });
        }
    }
    eprintln!("Double GGX:");
    w[0].check_within_bounds();
    eprintln!("Exponential:");
    w[1].check_within_bounds();
}

#[test]
fn family_dcos_samplers_give_the_rust_f32_normals() {
    let mut els = Vec::new();
    for ndf in [NDF_DOUBLE_GGX, NDF_EXPONENTIAL] {
        for &alpha in &ALPHAS {
            for &u in &uniforms() {
                els.push(El {
                    ndf,
                    alpha,
                    u,
                    wo: [0.0, 0.0, 1.0],
                    wm: [0.0, 0.0, 1.0],
                });
            }
        }
    }
    let Some(out) = run("ms_k_family_sample", &els) else {
        return;
    };
    let names = ["D·cos normal / bound", "D·cos pdf at it / bound"];
    let mut w = [Worst::new(&names), Worst::new(&names)];
    for (e, o) in els.iter().zip(&out) {
        let m = rust(e);
        let k = (e.ndf - NDF_DOUBLE_GGX) as usize;
        let s = m.sample_dcos(e.u);
        let g = [o[0][0], o[0][1], o[0][2]];
        let what = || format!("{e:?}: gpu {:?} rust {:?}", o[0], s.wm);
        w[k].add(0, vec_diff(g, s.wm) / NORMAL_TOL, what);
        let p = m.pdf_dcos(g);
        w[k].add(
            1,
            rel_flushed(o[0][3], p) / d_bound(e.ndf, g, e.alpha),
            || format!("{e:?}: gpu {} rust {p}", o[0][3]),
        );
    }
    eprintln!("Double GGX:");
    w[0].check_within_bounds();
    eprintln!("Exponential:");
    w[1].check_within_bounds();
}

/// SplitMix64 (crates/microsurface/src/math/rng.rs, private there), for the low 11 bits of
/// each output, which no Rust draw exposes; its top 53 bits are checked against the Rust
/// `UniformStream` itself below.
fn splitmix(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

#[test]
fn uniform_stream_is_the_rust_one_bit_for_bit() {
    // The grid's uniforms, subnormal and signed zeros, and 4096 pseudo-random f32 pairs in
    // [0, 1) (every bit pattern of the mantissa and exponent exercised).
    let mut us: Vec<[f32; 2]> = uniforms();
    let specials = [0.0, -0.0, f32::from_bits(1), 1e-40, 1.1754942e-38, 0.5, 1.0];
    for &a in &specials {
        for &b in &specials {
            us.push([a, b]);
        }
    }
    let mut st = 0x1234_5678_9abc_def0u64;
    for _ in 0..4096 {
        let a = (splitmix(&mut st) >> 40) as f32 / 16_777_216.0;
        let b = f32::from_bits((splitmix(&mut st) >> 32) as u32 & 0x3f7f_ffff);
        us.push([a, b]);
    }
    let els: Vec<El> = us
        .iter()
        .map(|&u| El {
            ndf: NDF_DOUBLE_GGX,
            alpha: [0.5; 2],
            u,
            wo: [0.0, 0.0, 1.0],
            wm: [0.0, 0.0, 1.0],
        })
        .collect();
    let Some(out) = run("ms_k_stream", &els) else {
        return;
    };
    for (u, o) in us.iter().zip(&out) {
        // The Rust seed, as UniformStream::new forms it.
        let mut state = (u[0] as f64).to_bits()
            ^ (u[1] as f64).to_bits().rotate_left(29)
            ^ 0x243F_6A88_85A3_08D3;
        let mut rs64 = UniformStream::new(*u);
        let mut rs32 = UniformStream::new(*u);
        for (k, q) in o.iter().enumerate() {
            let g = q.iter().rev().fold(0u64, |acc, &h| (acc << 16) | h as u64);
            let reference = splitmix(&mut state);
            let top53 = (rs64.next_uniform::<f64>() * 9_007_199_254_740_992.0) as u64;
            let v32: f32 = rs32.next_uniform();
            assert_eq!(top53, reference >> 11, "the reference copy at {u:?}");
            assert_eq!(g >> 11, top53, "output {k} at {u:?}: {g:#x}");
            assert_eq!(g, reference, "output {k} at {u:?}: {g:#x}");
            assert_eq!(
                (g >> 40) as f32 / 16_777_216.0,
                v32,
                "f32 draw {k} at {u:?}"
            );
        }
    }
    eprintln!("{} seeds: the first two outputs equal", us.len());
}

/// The visible-normal samplers through `ms_sample` (the run-time door) against the Rust
/// `sample` for the same u, over the grids. Both draw over the same uniform stream and keep
/// the same candidates unless an accept test falls on either side of its f32 (here) and f64
/// (Rust) arithmetic; the same draw then differs by the f32 evaluation of its slopes. The
/// Exponential's are a few ε of its logarithms and azimuth (5e-6 at most on these grids).
/// Double GGX's t comes from a ziggurat whose input is the f32 product v·(1/p) (Rust: f64),
/// whose low bits are the position within a layer: t carries ~2^−16 of it, the normal up to
/// 8e-4 on these grids (at α = 0.05, grazing). Asserted: at least 99.5 % of the normals lie
/// within 1e-3 of the Rust ones, and every normal is a unit vector above the horizon, facing
/// wo, with the pdf at it (here) equal to the Rust pdf at it to the pdf's bound. The
/// distribution itself is `visible_samplers_are_chi2_consistent_with_rust`'s.
#[test]
fn family_visible_samplers_give_the_rust_f32_normals() {
    // Double GGX, the Exponential NDF, then every SHAPED material.
    let ndfs: Vec<u32> = [NDF_DOUBLE_GGX, NDF_EXPONENTIAL]
        .into_iter()
        .chain((0..SHAPED.len() as u32).map(|k| NDF_SHAPED + k))
        .collect();
    let index = |ndf: u32| ndfs.iter().position(|&x| x == ndf).expect("a tested NDF");
    let mut els = Vec::new();
    for &ndf in &ndfs {
        for &alpha in &ALPHAS {
            for &wo in &directions() {
                for &u in &uniforms() {
                    els.push(El {
                        ndf,
                        alpha,
                        u,
                        wo,
                        wm: [0.0, 0.0, 1.0],
                    });
                }
            }
        }
    }
    let Some(out) = run("ms_k_family_sample", &els) else {
        return;
    };
    let names = ["visible pdf at the normal / bound"];
    let mut w: Vec<Worst> = ndfs.iter().map(|_| Worst::new(&names)).collect();
    let (mut same, mut worst_same) = (vec![0usize; ndfs.len()], vec![0f64; ndfs.len()]);
    let mut n = vec![0usize; ndfs.len()];
    // The mixtures' D·cos normals (β from the prior over the stream, then Beckmann's warp:
    // the Rust fast path's draws), the same-draw count as the visible ones'.
    let (mut dcos_same, mut dcos_n, mut dcos_worst) = (0usize, 0usize, 0f64);
    for (e, o) in els.iter().zip(&out) {
        let m = rust(e);
        let k = index(e.ndf);
        n[k] += 1;
        if e.ndf >= NDF_SHAPED && student_t_gamma(e).is_none() && e.wo == [0.0, 0.0, 1.0] {
            dcos_n += 1;
            let d = vec_diff([o[0][0], o[0][1], o[0][2]], m.sample_dcos(e.u).wm);
            if d <= 1e-3 {
                dcos_same += 1;
                dcos_worst = dcos_worst.max(d);
            }
        }
        let g = [o[1][0], o[1][1], o[1][2]];
        let r = m.sample(e.wo, e.u).wm;
        let d = vec_diff(g, r);
        if d > 1e-3 && e.ndf >= NDF_SHAPED {
            eprintln!(
                "DBG {} u {:?} wo {:?} a {:?} g {g:?} r {r:?}",
                e.ndf, e.u, e.wo, e.alpha
            );
        }
        if d <= 1e-3 {
            same[k] += 1;
            worst_same[k] = worst_same[k].max(d);
        }
        let len: f64 = g.iter().map(|&x| x as f64 * x as f64).sum::<f64>().sqrt();
        let sign = if e.wo[2] < 0.0 { -1.0 } else { 1.0 };
        let facing: f64 = (0..3).map(|q| sign * e.wo[q] as f64 * g[q] as f64).sum();
        assert!(
            (len - 1.0).abs() <= 4.0 * EPS && g[2] >= 0.0 && facing > 0.0,
            "{e:?}: gpu normal {g:?} (|m| − 1 = {:e}, wo·m = {facing:e})",
            len - 1.0
        );
        let p = m.pdf(e.wo, g);
        let lo = m.lambda(e.wo) as f64;
        let (bo, bd) = if e.ndf >= NDF_SHAPED {
            let m64 = rust64(e);
            (shaped_lambda_bound(&m64, e.wo), shaped_d_bound(&m64, g))
        } else {
            (
                lambda_bound(e.ndf, e.wo, e.alpha),
                d_bound(e.ndf, g, e.alpha),
            )
        };
        let g1 = TOL + bo * if lo.is_finite() { lo / (1.0 + lo) } else { 1.0 };
        let tol = g1 + bd + 8.0 * EPS * visible_cancellation(e.wo, g);
        w[k].add(0, rel_flushed(o[1][3], p) / tol, || {
            format!("{e:?}: gpu {} rust {p}", o[1][3])
        });
    }
    eprintln!(
        "the mixtures' D·cos: {dcos_same} of {dcos_n} normals the Rust draw (largest difference {dcos_worst:.2e})"
    );
    assert!(
        dcos_same as f64 >= 0.995 * dcos_n as f64,
        "the mixtures' D·cos: only {dcos_same} of {dcos_n} normals are the Rust draw"
    );
    for (k, &ndf) in ndfs.iter().enumerate() {
        let name = match ndf {
            NDF_DOUBLE_GGX => "Double GGX".to_string(),
            NDF_EXPONENTIAL => "Exponential".to_string(),
            _ => format!("{:?}", SHAPED[(ndf - NDF_SHAPED) as usize]),
        };
        eprintln!(
            "{name}: {} of {} normals the Rust draw (largest difference {:.2e})",
            same[k], n[k], worst_same[k]
        );
        w[k].check_within_bounds();
        assert!(
            same[k] as f64 >= 0.995 * n[k] as f64,
            "{name}: only {} of {} normals are the Rust draw",
            same[k],
            n[k]
        );
    }
}

/// The upper 1e-6 quantile of χ² with `df` degrees of freedom (Wilson–Hilferty; within 1 %
/// of the exact quantile from df = 30).
fn chi2_quantile_1e6(df: f64) -> f64 {
    let z = 4.753_424; // Φ⁻¹(1 − 1e-6)
    let a = 2.0 / (9.0 * df);
    df * (1.0 - a + z * a.sqrt()).powi(3)
}

/// The histogram of normals over 16 bins of cos θm (between `edges`, 15 of them) and 32 of φm.
fn histogram(edges: &[f32], normals: impl Iterator<Item = [f32; 3]>) -> Vec<f64> {
    let mut h = vec![0.0; 16 * 32];
    for m in normals {
        let z = edges.partition_point(|&e| e <= m[2]);
        let phi = (m[1] as f64).atan2(m[0] as f64) / std::f64::consts::TAU + 0.5;
        let p = ((phi * 32.0) as usize).min(31);
        h[z * 32 + p] += 1.0;
    }
    h
}

/// The two-sample χ² of two histograms of equal totals: Σ (a − b)²/(a + b) over the bins
/// either hits, and that number of bins.
fn chi2_two_sample(a: &[f64], b: &[f64]) -> (f64, usize) {
    let (mut chi2, mut bins) = (0.0, 0usize);
    for (x, y) in a.iter().zip(b) {
        if x + y > 0.0 {
            chi2 += (x - y) * (x - y) / (x + y);
            bins += 1;
        }
    }
    (chi2, bins)
}

/// The samplers' distributions: 2^18 GPU normals (`ms_sample` and `ms_sample_dcos`,
/// pseudo-random u) against 2^18 Rust ones (`sample`, `sample_dcos`, independent u) per
/// material and direction, a two-sample χ² over 512 bins, 32 of φm by 16 of cos θm between
/// the quantiles of 2^14 more Rust normals (so that each holds about as many: the peak is
/// resolved at every α) (Σ (a − b)²/(a + b) over the bins either hits, χ² with one degree
/// fewer than those bins), at p = 1e-6. The Rust samplers are χ²-tested against their pdfs
/// (crates/microsurface/tests/chi2.rs), so this makes the GPU ones consistent with the Rust
/// pdf. Grazing, oblique and normal incidence, isotropic and anisotropic roughness; Double
/// GGX, the Exponential NDF, Student-T (γ = 2.5 and 10), Ei, Erfc, K0 and Bessel-K (a = 0.4,
/// 2.5) (the mixtures' samplers draw other uniforms than the Rust ones: the same distribution, not the same
/// normals).
#[test]
fn samplers_are_chi2_consistent_with_rust() {
    const N: usize = 1 << 18;
    let configs: Vec<(u32, [f32; 2], [f32; 3])> = [
        NDF_DOUBLE_GGX,
        NDF_EXPONENTIAL,
        NDF_STUDENT_T_SHAPES + 1,
        NDF_STUDENT_T_SHAPES + 2,
        NDF_SHAPED + 4,
        NDF_SHAPED + 5,
        NDF_SHAPED + 6,
        NDF_SHAPED + 7,
        NDF_SHAPED + 8,
    ]
    .iter()
    .flat_map(|&ndf| {
        [
            (ndf, [0.5, 0.5], [0.0, 0.0, 1.0]),
            (ndf, [0.3, 0.8], grid::dir(0.5, 0.5)),
            (ndf, [0.7, 0.7], grid::dir(0.05, 2.0)),
        ]
    })
    .collect();
    let mut st = 0x5eed_0fc4_15a3_d00d_u64;
    let mut uniform = move || (splitmix(&mut st) >> 40) as f32 / 16_777_216.0;
    let edges_of = |mut z: Vec<f32>| {
        z.sort_by(f32::total_cmp);
        (1..16).map(|q| z[q << 10]).collect::<Vec<f32>>()
    };
    for &(ndf, alpha, wo) in &configs {
        let probe = El {
            ndf,
            alpha,
            u: [0.0; 2],
            wo,
            wm: [0.0; 3],
        };
        let m = rust(&probe);
        let visible_edges = edges_of(
            (0..1 << 14)
                .map(|_| m.sample(wo, [uniform(), uniform()]).wm[2])
                .collect(),
        );
        let dcos_edges = edges_of(
            (0..1 << 14)
                .map(|_| m.sample_dcos([uniform(), uniform()]).wm[2])
                .collect(),
        );
        let mut els = Vec::with_capacity(N);
        let (mut visible, mut dcos) = (Vec::with_capacity(N), Vec::with_capacity(N));
        for _ in 0..N {
            els.push(El {
                u: [uniform(), uniform()],
                ..probe
            });
            visible.push(m.sample(wo, [uniform(), uniform()]).wm);
            dcos.push(m.sample_dcos([uniform(), uniform()]).wm);
        }
        // (One dispatch per configuration: a storage binding holds at most 128 MiB.)
        let Some(out) = run("ms_k_family_sample", &els) else {
            return;
        };
        for (what, edges, gpu, cpu) in [
            (
                "visible",
                &visible_edges,
                histogram(
                    &visible_edges,
                    out.iter().map(|o| [o[1][0], o[1][1], o[1][2]]),
                ),
                histogram(&visible_edges, visible.iter().copied()),
            ),
            (
                "D·cos",
                &dcos_edges,
                histogram(&dcos_edges, out.iter().map(|o| [o[0][0], o[0][1], o[0][2]])),
                histogram(&dcos_edges, dcos.iter().copied()),
            ),
        ] {
            let _ = edges;
            let (chi2, bins) = chi2_two_sample(&gpu, &cpu);
            let limit = chi2_quantile_1e6((bins - 1) as f64);
            eprintln!(
                "ndf {ndf} α {alpha:?} wo {wo:?} {what}: χ² {chi2:.1} over {bins} bins (limit {limit:.1})"
            );
            assert!(
                chi2 <= limit,
                "ndf {ndf} α {alpha:?} wo {wo:?} {what}: χ² {chi2:.1} > {limit:.1} ({bins} bins)"
            );
        }
    }
}

/// The f64 material of an element with a shape table.
fn rust64(e: &El) -> AnyMicrofacet<f64> {
    let (kind, shape) = shaped(e).expect("a shape table");
    AnyMicrofacet::<f64>::new(kind, e.alpha[0] as f64, e.alpha[1] as f64, shape).unwrap()
}

#[test]
fn shaped_d_lambda_g1_g2_pdfs_match_rust_f32() {
    let mut els = Vec::new();
    for k in 0..SHAPED.len() as u32 {
        for &alpha in &ALPHAS {
            for &wo in &directions() {
                for &wm in &normals() {
                    els.push(El {
                        ndf: NDF_SHAPED + k,
                        alpha,
                        u: [0.5; 2],
                        wo,
                        wm,
                    });
                }
            }
        }
    }
    let Some(out) = run("ms_k_family_eval", &els) else {
        return;
    };
    let names = QUANTITIES;
    let mut w: Vec<Worst> = SHAPED.iter().map(|_| Worst::new(&names)).collect();
    for (e, o) in els.iter().zip(&out) {
        let m = rust(e);
        let m64 = rust64(e);
        let (wo, wm) = (e.wo, e.wm);
        let r = rust_quantities(&*m, wo, wm);
        let gpu = gpu_quantities(o);
        let (lo, li) = (m.lambda(wo) as f64, m.lambda(wm) as f64);
        let (bo, bi) = (shaped_lambda_bound(&m64, wo), shaped_lambda_bound(&m64, wm));
        let d = shaped_d_bound(&m64, wm);
        let tol = quantity_bounds((bo, bi), (lo, li), d, wo, wm);
        let k = (e.ndf - NDF_SHAPED) as usize;
        for q in 0..names.len() {
            w[k].add(q, rel_flushed(gpu[q], r[q]) / tol[q], || {
                format!("{e:?}: gpu {} rust {} (bound {:e})", gpu[q], r[q], tol[q])
            });
        }
    }
    for (k, (kind, shape, _)) in SHAPED.iter().enumerate() {
        eprintln!("{kind:?} {shape:?}:");
        w[k].check_within_bounds();
    }
}

/// Student-T's D·cos sampler is the Rust warp (the radial quantile r² = (γ − 1)
/// expm1(−ln(1 − u₀)/(γ − 1)), then the polar normal), so the same u gives the same normal:
/// within 16ε plus r's relative error ρ times the normal's sensitivity to ln r (≤ ½, times
/// the anisotropy max(αx/αy, αy/αx)). ρ is half of r²'s: ln(1 − u₀) a few ε, x = −ln(1 −
/// u₀)/(γ − 1) one more, expm1's condition number 1 + x and its own evaluation (the series
/// below ½, e^x − 1 above, Vulkan's exp within 3 + 2x ulp, magnified at most 2.6 by the
/// subtraction): 8ε(1 + x) + 16ε.
#[test]
fn student_t_dcos_sampler_gives_the_rust_f32_normals() {
    let mut els = Vec::new();
    for k in 0..STUDENT_T_GAMMAS.len() as u32 {
        for &alpha in &ALPHAS {
            for &u in &uniforms() {
                els.push(El {
                    ndf: NDF_STUDENT_T_SHAPES + k,
                    alpha,
                    u,
                    wo: [0.0, 0.0, 1.0],
                    wm: [0.0, 0.0, 1.0],
                });
            }
        }
    }
    let Some(out) = run("ms_k_family_sample", &els) else {
        return;
    };
    let names = ["D·cos normal / bound", "D·cos pdf at it / bound"];
    let mut w = Worst::new(&names);
    for (e, o) in els.iter().zip(&out) {
        let m = rust(e);
        let g = student_t_gamma(e).expect("Student-T");
        let s = m.sample_dcos(e.u);
        let gm = [o[0][0], o[0][1], o[0][2]];
        let x = -(-(e.u[0] as f64)).ln_1p() / (g - 1.0);
        let aniso = (e.alpha[0] / e.alpha[1]).max(e.alpha[1] / e.alpha[0]) as f64;
        let tol = NORMAL_TOL + 0.5 * aniso * (8.0 * EPS * (1.0 + x) + 16.0 * EPS);
        w.add(0, vec_diff(gm, s.wm) / tol, || {
            format!("{e:?}: gpu {:?} rust {:?} (bound {tol:e})", o[0], s.wm)
        });
        let p = m.pdf_dcos(gm);
        w.add(
            1,
            rel_flushed(o[0][3], p) / shaped_d_bound(&rust64(e), gm),
            || format!("{e:?}: gpu {} rust {p}", o[0][3]),
        );
    }
    w.check_within_bounds();
}
