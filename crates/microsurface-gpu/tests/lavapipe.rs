//! The WGSL library in wgpu compute shaders against the Rust f32 path, element by element
//! (CI: Mesa's lavapipe, `MICROSURFACE_GPU_REQUIRED=1`, so that a missing adapter fails
//! there; elsewhere the tests skip with a message when no Vulkan adapter exists).
//!
//! Grids: roughness from 2e-3 to 2, isotropic and anisotropic; directions at normal
//! incidence, cos θ from 0.9 down to 1e-4 (grazing) at four azimuths, and below the
//! horizon; uniforms 0, 2⁻²⁴, ¼, ½, 0.9 and 1 − 2⁻²⁴ in each coordinate.
//!
//! Tolerances, and where each comes from. They are the f32 bounds of the Rust docs, and
//! where a quantity is ill-conditioned, what its conditioning makes of f32 roundings,
//! computed per element in f64, so that they hold on any device that rounds as Vulkan
//! allows (measured on lavapipe and on an NVIDIA H200: BENCHMARKS.md):
//! * D, Λ, G1, G2 (both forms), the visible, D·cos and bounded pdfs: relative 2e-6 (`TOL`),
//!   twice the f32 fast path's documented bound (GGX f32 ≤ 1e-6 of the exact value: the
//!   table of `microsurface::fast`), as both sides are held to it.
//! * Sampled normals (warps of u): the Rust f32 sampler's normal to `NORMAL_TOL` = 16ε per
//!   component (the Rust f32 path forms cos 2πu in f64 and rounds, the WGSL in f32), times
//!   the cancellation of the caps' unnormalised normal where the cap point nears −w'
//!   (`cap_bound`; the caps' sine itself is formed without cancellation); a pdf at its
//!   own normal to `TOL` plus the dot product's cancellation at the visible edge, except on
//!   the bounded cap's edge, where its indicator is decided by rounding.
//! * Fresnel: `TOL` plus 16ε times the formula's cancellation (`fresnel_cancellation`: η → 1,
//!   the critical angle, F82-tint's subtraction), inside each function's contract.
//! * BSDF values: `BSDF_TOL` (three of `TOL`: D, G2 and F each held to it) plus what the half
//!   vector's rounding δ = 2 · 4ε(1 + η')/|η' wi + wo| (the Rust docs' δ, once per side; a
//!   sampled normal's bound where larger) costs D (δ(1 + 4 tan θh/α²): D's condition number,
//!   the crate-wide 4εκ rule of the Rust docs' Accuracy section) and the Fresnel factor
//!   (from the Rust function at cos θ ± δ, and its formula's cancellation): `value_tol`.
//!   A sample's accept/reject and lobe decisions must agree except where the normal's bound
//!   reaches the decision's margin (`decision_is_close`).

use microsurface::bsdf::fresnel::{self, Conductor, Dielectric, F82Tint, One, Schlick};
use microsurface::bsdf::{Bsdf, Lobe, Masking, RoughConductor, RoughDielectric, Transport};
use microsurface::{Ggx, Microfacet, MicrofacetDistribution};
use microsurface_gpu::{kernels_source, Error, Gpu, Program, Tables, KERNEL_IN, KERNEL_OUT};
use std::sync::OnceLock;

mod grid;
use grid::{
    d_bound, directions, lambda_bound, normals, shaped_d_bound, shaped_lambda_bound, uniforms,
    vec_diff, Worst, ALPHAS, EPS, NDF_BECKMANN, NDF_DOUBLE_GGX, NDF_EXPONENTIAL, NDF_GGX, TOL,
};

/// The device and the compiled kernels, once per test binary; `None` (the tests skip) only
/// where no Vulkan adapter exists and `MICROSURFACE_GPU_REQUIRED` is not 1.
fn gpu() -> Option<&'static (Gpu, Program)> {
    static GPU: OnceLock<Option<(Gpu, Program)>> = OnceLock::new();
    GPU.get_or_init(|| {
        let required = std::env::var("MICROSURFACE_GPU_REQUIRED").as_deref() == Ok("1");
        match Gpu::with_tables(&materials().1) {
            Ok(g) => {
                let i = g.adapter_info();
                eprintln!(
                    "adapter: {} ({:?}, {} {})",
                    i.name, i.device_type, i.driver, i.driver_info
                );
                let p = g.program(&kernels_source()).expect("the kernels validate");
                Some((g, p))
            }
            Err(Error::NoAdapter(m)) if !required => {
                eprintln!(
                    "SKIPPED: no Vulkan adapter ({m}); install Mesa's lavapipe \
                     (Debian: mesa-vulkan-drivers) to run the GPU comparison"
                );
                None
            }
            Err(e) => panic!("MICROSURFACE_GPU_REQUIRED=1 or a device error: {e}"),
        }
    })
    .as_ref()
}

/// One kernel element: (αx, αy, u), (wo, uc), (wi, ndf), (Fresnel a, kind), (b, masking).
#[derive(Clone, Copy, Debug)]
struct El {
    alpha: [f32; 2],
    u: [f32; 2],
    wo: [f32; 3],
    uc: f32,
    wi: [f32; 3],
    fr: (u32, [f32; 3], [f32; 3]),
    masking: u32,
    /// The NDF tag (MsMicrofacet's MS_NDF_*; GGX but in `bsdfs_of_every_ndf_match_rust_f32`)
    /// and its table's row in the bound buffer (`materials()`; 0 for GGX).
    ndf: u32,
    table: u32,
}

impl El {
    fn new(alpha: [f32; 2], wo: [f32; 3], wi: [f32; 3], u: [f32; 2]) -> Self {
        El {
            alpha,
            u,
            wo,
            uc: 0.5,
            wi,
            fr: (0, [1.0; 3], [0.0; 3]),
            masking: 0,
            ndf: NDF_GGX,
            table: 0,
        }
    }
    fn records(&self) -> [[f32; 4]; KERNEL_IN] {
        let (k, a, b) = self.fr;
        [
            [self.alpha[0], self.alpha[1], self.u[0], self.u[1]],
            [self.wo[0], self.wo[1], self.wo[2], self.uc],
            [
                self.wi[0],
                self.wi[1],
                self.wi[2],
                (self.ndf + 16 * self.table) as f32,
            ],
            [a[0], a[1], a[2], k as f32],
            [b[0], b[1], b[2], self.masking as f32],
        ]
    }
}

fn run(entry: &str, els: &[El]) -> Option<Vec<[[f32; 4]; KERNEL_OUT]>> {
    let (g, p) = gpu()?;
    let input: Vec<[f32; 4]> = els.iter().flat_map(|e| e.records()).collect();
    let out = g
        .run(p, entry, &input, KERNEL_IN, KERNEL_OUT)
        .expect("the kernel runs");
    Some(out.chunks(KERNEL_OUT).map(|c| [c[0], c[1]]).collect())
}

/// |g − r|/|r| (0 where both are equal, +∞ included; +∞ where exactly one is 0, NaN or
/// infinite).
fn rel(g: f32, r: f32) -> f64 {
    if g == r {
        return 0.0;
    }
    let (g, r) = (g as f64, r as f64);
    if !(g.is_finite() && r.is_finite()) || r == 0.0 {
        return f64::INFINITY;
    }
    (g - r).abs() / r.abs()
}

impl Worst {
    fn check(&self, tol: &[f64]) {
        for (k, (e, w)) in self.max.iter().enumerate() {
            eprintln!(
                "{:>26}: max {e:.3e} (tol {:.0e}) {w}",
                self.names[k], tol[k]
            );
        }
        for (k, (e, w)) in self.max.iter().enumerate() {
            assert!(
                *e <= tol[k],
                "{}: {e:e} > {:e} at {w}",
                self.names[k],
                tol[k]
            );
        }
    }
}

#[test]
fn ggx_d_lambda_g1_g2_pdfs_match_rust_f32() {
    let mut els = Vec::new();
    for &a in &ALPHAS {
        for &wo in &directions() {
            for &wm in &normals() {
                els.push(El::new(a, wo, wm, [0.5; 2]));
            }
        }
    }
    let Some(out) = run("ms_k_ggx_eval", &els) else {
        return;
    };
    let names = [
        "D",
        "Λ",
        "G1",
        "G2 correlated",
        "G2 separable",
        "visible pdf",
        "D·cos pdf",
        "bounded pdf",
    ];
    let mut w = Worst::new(&names);
    for (e, o) in els.iter().zip(&out) {
        let m = Microfacet::<f32, Ggx>::new(e.alpha[0], e.alpha[1]).unwrap();
        let (wo, wm) = (e.wo, e.wi);
        let r = [
            m.d(wm),
            m.lambda(wo),
            m.g1(wo),
            m.g2(wo, wm),
            m.g2_separable(wo, wm),
            m.pdf(wo, wm),
            m.pdf_dcos(wm),
            m.pdf_bounded(wo, wm),
        ];
        let g = [
            o[0][0], o[0][1], o[0][2], o[0][3], o[1][0], o[1][1], o[1][2], o[1][3],
        ];
        for k in 0..names.len() {
            w.add(k, rel(g[k], r[k]), || {
                format!("{e:?}: gpu {} rust {}", g[k], r[k])
            });
        }
    }
    w.check(&[TOL; 8]);
}

/// The sampled normals' bound per component, 16ε: the Rust f32 samplers form cos 2πu in f64
/// and round it (½ ulp), the WGSL forms it in f32 (a few ulp), and the cap point and the
/// unstretch round once more on each side. Measured on lavapipe over the grids below
/// (anisotropy up to 50:1): 4ε (BENCHMARKS.md).
const NORMAL_TOL: f64 = 16.0 * EPS;

/// The bound of a sampled normal's components at the element's uniforms: `NORMAL_TOL` times
/// the cancellation of the unnormalised normal h = (αx(sin cos φ + x), αy(sin sin φ + y),
/// h.z) (the cap point plus the stretched w' = (x, y, z), unstretched): Σ|terms|/|h|. Both
/// sides form the cap's sine without cancellation (sin² = u₁(above (1 + z) + x² + y²), and
/// the bounded cap's analogue, sums of positive terms), so each term of h carries a few ε
/// relative on each side, and h's components move by 16ε times the sum of their terms'
/// magnitudes; the unit normal by that over |h|. The factor is 1 to √3 except where the cap
/// point nears −w' (u₁ → 1, φ opposite w'), the sampler's own conditioning. Replayed in f64.
fn cap_bound(e: &El, bounded: bool) -> f64 {
    let (ax, ay) = (e.alpha[0] as f64, e.alpha[1] as f64);
    let mut w = e.wo.map(f64::from);
    let n = w.iter().map(|x| x * x).sum::<f64>().sqrt();
    w = w.map(|x| x / n);
    let down = w[2] < 0.0;
    if down {
        w = w.map(|x| -x);
    }
    let st = [ax * w[0], ay * w[1], w[2]];
    let len = st.iter().map(|x| x * x).sum::<f64>().sqrt();
    let ws = st.map(|x| x / len);
    let (u0, u1) = (e.u[0] as f64, e.u[1] as f64);
    let (sphi, cphi) = (std::f64::consts::TAU * u0).sin_cos();
    // The cap's lower bound −b: w'.z for the full cap, k w'.z for the bounded one.
    let b = if bounded && !down {
        let a = ax.min(ay).min(1.0);
        let sxy = 1.0 + (w[0] * w[0] + w[1] * w[1]).sqrt();
        (1.0 - a * a) * sxy * sxy / (sxy * sxy + a * a * w[2] * w[2]) * ws[2]
    } else {
        ws[2]
    };
    let above = (1.0 - u1) * (1.0 + b);
    let sin = (u1 * (1.0 + b) * (2.0 - u1 * (1.0 + b))).max(0.0).sqrt();
    let h = [
        ax * (sin * cphi + ws[0]),
        ay * (sin * sphi + ws[1]),
        above + (ws[2] - b),
    ];
    let terms = ax * ((sin * cphi).abs() + ws[0].abs())
        + ay * ((sin * sphi).abs() + ws[1].abs())
        + above
        + (ws[2] - b).abs();
    let hl = h.iter().map(|x| x * x).sum::<f64>().sqrt().max(1e-30);
    NORMAL_TOL * (terms / hl).max(1.0)
}

/// Whether a normal wm (f64) lies within rounding of the bounded cap's edge for w, where
/// `pdf_bounded`'s indicator (the reflected cap point at or above −b) is decided by rounding:
/// within 16ε αmax/αmin of it (the unstretch's magnification of the normal's rounding).
fn near_bounded_edge(wo: [f32; 3], wm: [f64; 3], alpha: [f32; 2]) -> bool {
    let (ax, ay) = (alpha[0] as f64, alpha[1] as f64);
    let mut w = wo.map(f64::from);
    let n = w.iter().map(|x| x * x).sum::<f64>().sqrt();
    w = w.map(|x| x / n);
    let down = w[2] < 0.0;
    if down {
        w = w.map(|x| -x);
    }
    let st = [ax * w[0], ay * w[1], w[2]];
    let len = st.iter().map(|x| x * x).sum::<f64>().sqrt();
    let ws = st.map(|x| x / len);
    let b = if down {
        ws[2]
    } else {
        let a = ax.min(ay).min(1.0);
        let sxy = 1.0 + (w[0] * w[0] + w[1] * w[1]).sqrt();
        (1.0 - a * a) * sxy * sxy / (sxy * sxy + a * a * w[2] * w[2]) * ws[2]
    };
    let m = [wm[0] / ax, wm[1] / ay, wm[2]];
    let ml = m.iter().map(|x| x * x).sum::<f64>().sqrt();
    let m = m.map(|x| x / ml);
    let d = m[0] * ws[0] + m[1] * ws[1] + m[2] * ws[2];
    let cz = 2.0 * d * m[2] - ws[2];
    (cz + b).abs() <= 16.0 * EPS * ax.max(ay) / ax.min(ay)
}

/// Σ|wᵢ mᵢ|/|w·m|: how much the dot product w·m, a factor of the visible pdfs, magnifies the
/// roughness of its terms (large for a normal nearly perpendicular to w, the cap's edge).
fn dot_cancellation(w: [f32; 3], m: [f32; 3]) -> f64 {
    let t: Vec<f64> = (0..3).map(|k| w[k] as f64 * m[k] as f64).collect();
    let sum = t.iter().sum::<f64>().abs();
    (t.iter().map(|x| x.abs()).sum::<f64>() / sum.max(1e-300)).max(1.0)
}

#[test]
fn ggx_samplers_give_the_rust_f32_normals() {
    let mut els = Vec::new();
    for &a in &ALPHAS {
        for &wo in &directions() {
            for &u in &uniforms() {
                els.push(El::new(a, wo, [0.0, 0.0, 1.0], u));
            }
        }
    }
    let (Some(vis), Some(bounded)) = (run("ms_k_ggx_sample", &els), run("ms_k_ggx_bounded", &els))
    else {
        return;
    };
    let names = [
        "visible normal / bound",
        "visible pdf at it / bound",
        "D·cos normal / bound",
        "D·cos pdf at it / bound",
        "bounded normal / bound",
        "bounded pdf at it / bound",
    ];
    let mut w = Worst::new(&names);
    for ((e, o), b) in els.iter().zip(&vis).zip(&bounded) {
        let m = Microfacet::<f32, Ggx>::new(e.alpha[0], e.alpha[1]).unwrap();
        let what = |g: [f32; 4], r: [f32; 3], p: f32| {
            move || format!("{e:?}: gpu {g:?} rust {r:?} (pdf {p})")
        };
        let s = m.sample(e.wo, e.u);
        let g = o[0];
        w.add(
            0,
            vec_diff([g[0], g[1], g[2]], s.wm) / cap_bound(e, false),
            what(g, s.wm, s.pdf),
        );
        // The pdf at the GPU's own normal: the pdf arithmetic apart from the normal's.
        let p = m.pdf(e.wo, [g[0], g[1], g[2]]);
        let tol = TOL + 8.0 * EPS * dot_cancellation(e.wo, [g[0], g[1], g[2]]);
        w.add(1, rel(g[3], p) / tol, what(g, s.wm, p));
        let s = m.sample_dcos(e.u);
        let g = o[1];
        w.add(
            2,
            vec_diff([g[0], g[1], g[2]], s.wm) / NORMAL_TOL,
            what(g, s.wm, s.pdf),
        );
        let p = m.pdf_dcos([g[0], g[1], g[2]]);
        w.add(3, rel(g[3], p) / TOL, what(g, s.wm, p));
        let s = m.sample_bounded(e.wo, e.u);
        let g = b[0];
        w.add(
            4,
            vec_diff([g[0], g[1], g[2]], s.wm) / cap_bound(e, true),
            what(g, s.wm, s.pdf),
        );
        // (Not at a normal on the bounded cap's edge, where the pdf's indicator is decided by
        // rounding.)
        if !near_bounded_edge(e.wo, [g[0] as f64, g[1] as f64, g[2] as f64], e.alpha) {
            let p = m.pdf_bounded(e.wo, [g[0], g[1], g[2]]);
            let tol = TOL + 8.0 * EPS * dot_cancellation(e.wo, [g[0], g[1], g[2]]);
            w.add(5, rel(g[3], p) / tol, what(g, s.wm, p));
        }
    }
    w.check(&[1.0; 6]);
}

#[test]
fn ggx_bounded_reflection_pdf_matches_rust_f32() {
    let mut els = Vec::new();
    for &a in &ALPHAS {
        for &wo in &directions() {
            for &wi in &directions() {
                els.push(El::new(a, wo, wi, [0.5; 2]));
            }
        }
    }
    let Some(out) = run("ms_k_ggx_bounded", &els) else {
        return;
    };
    let mut w = Worst::new(&["bounded reflection pdf"]);
    for (e, o) in els.iter().zip(&out) {
        let m = Microfacet::<f32, Ggx>::new(e.alpha[0], e.alpha[1]).unwrap();
        let r = m.pdf_bounded_reflection(e.wo, e.wi);
        let (wm, _, _) = half_vector_delta(e.wo, e.wi, 1.0, None);
        if near_bounded_edge(e.wo, wm, e.alpha) {
            // (wi on the horizon reflects exactly at the cap's edge.)
            continue;
        }
        w.add(0, rel(o[1][0], r), || {
            format!("{e:?}: gpu {} rust {r}", o[1][0])
        });
    }
    w.check(&[TOL]);
}

/// The Fresnel terms of the tests: (kind, a, b) as `MsFresnel`.
fn fresnels() -> Vec<(u32, [f32; 3], [f32; 3])> {
    vec![
        (0, [1.0; 3], [0.0; 3]),
        (1, [1.5, 0.0, 0.0], [0.0; 3]),
        (1, [1.0 / 1.5, 0.0, 0.0], [0.0; 3]),
        (2, [0.2, 1.1, 1.5], [3.9, 2.2, 0.0]),
        (2, [0.14, 0.42, 1.37], [3.98, 2.38, 1.6]),
        (3, [0.04, 0.5, 0.95], [0.0; 3]),
        (4, [0.9, 0.6, 0.3], [0.7, 1.0, 0.2]),
    ]
}

/// The cancellation factor of a Fresnel formula at cos θ = c (a = η or F0, b = k or the
/// tint), evaluated in f64: the sum of the magnitudes of the terms over the magnitude of the
/// result, the factor by which the formula magnifies its operations' roundings. The
/// dielectric's (η² cos θi − η cos θt)/(η² cos θi + η cos θt) and (cos θi − η cos θt)/(…) cancel
/// as η → 1 (and the conductor with them at k = 0); F82-tint subtracts its tint term.
/// Schlick adds positive terms (1).
fn fresnel_cancellation(k: usize, c: f64, a: f64, b: f64) -> f64 {
    let dielectric = |c: f64, eta: f64| {
        let (c, eta) = if c < 0.0 { (-c, 1.0 / eta) } else { (c, eta) };
        let c = c.min(1.0);
        let ect2 = eta * eta - (1.0 - c * c);
        if eta == 1.0 || c == 0.0 || ect2 <= 0.0 {
            return 1.0;
        }
        let (ect, e2c) = (ect2.sqrt(), eta * eta * c);
        // η ≤ 1: η² cos²θt = η² − sin²θi itself cancels toward the critical angle, and the
        // subtractions below magnify that error of η cos θt in turn.
        let k2 = if eta > 1.0 {
            1.0
        } else {
            1.0 + (eta * eta + (1.0 - c * c)) / ect2
        };
        k2 * ((e2c + ect) / (e2c - ect).abs()).max((c + ect) / (c - ect).abs())
    };
    match k {
        0 => dielectric(c, a),
        1 | 4 if b == 0.0 => dielectric(c.max(0.0), a),
        3 => {
            let mu = c.clamp(0.0, 1.0);
            let m = 1.0 - mu;
            let m5 = m.powi(5);
            let mb: f64 = 6.0 / 7.0;
            let t = (a + (1.0 - a) * mb.powi(5)) * (1.0 - b) / (mb.powi(6) / 7.0);
            let terms = [a, (1.0 - a) * m5, t * mu * m5 * m];
            let r = terms[0] + terms[1] - terms[2];
            (terms.iter().map(|x| x.abs()).sum::<f64>() / r.abs()).max(1.0)
        }
        _ => 1.0,
    }
}

#[test]
fn fresnel_matches_rust_f32() {
    let mut els = Vec::new();
    let params: [(f32, f32); 10] = [
        (1.5, 0.0),
        (1.0 / 1.5, 0.0),
        (1.0, 0.0),
        (1.0001, 0.0),
        (3.0, 0.5),
        (0.2, 3.9),
        (0.05, 0.1),
        (2e18, 2e18),
        (0.9, 0.7),
        (0.04, 1.0),
    ];
    for &(x, y) in &params {
        for i in 0..=40 {
            let c = -1.0 + i as f32 / 20.0;
            for c in [c, c * 1e-3] {
                let mut e = El::new([0.3; 2], [0.0, 0.0, c], [0.0, 0.0, 1.0], [0.5; 2]);
                e.fr = (2, [x; 3], [y; 3]);
                els.push(e);
            }
        }
    }
    let Some(out) = run("ms_k_fresnel", &els) else {
        return;
    };
    let names = [
        "dielectric / bound",
        "conductor / bound",
        "Schlick / bound",
        "F82-tint / bound",
        "MsFresnel (conductor) / bound",
    ];
    let mut w = Worst::new(&names);
    for (e, o) in els.iter().zip(&out) {
        let (c, x, y) = (e.wo[2], e.fr.1[0], e.fr.2[0]);
        let r = [
            fresnel::dielectric(c, x),
            fresnel::conductor(c, x, y),
            fresnel::schlick(c, x),
            fresnel::f82_tint(c, x, y),
            fresnel::conductor(c, x, y),
        ];
        let g = [o[0][0], o[0][1], o[0][2], o[0][3], o[1][0]];
        for k in 0..names.len() {
            // Schlick and F82-tint take F0 = a in [0, 1] (their contract); the element's a
            // is an index of refraction for the other two.
            if (k == 2 || k == 3) && !(0.0..=1.0).contains(&x) {
                continue;
            }
            let tol = TOL + 16.0 * EPS * fresnel_cancellation(k, c as f64, x as f64, y as f64);
            w.add(k, rel(g[k], r[k]) / tol, || {
                format!("cos {c} a {x} b {y}: gpu {} rust {}", g[k], r[k])
            });
        }
    }
    w.check(&[1.0; 5]);
}

/// The Rust conductor of an element (its Fresnel kind and masking).
fn rust_conductor(e: &El) -> Box<dyn Bsdf<f32, Value = [f32; 3]>> {
    let m = Microfacet::<f32, Ggx>::new(e.alpha[0], e.alpha[1]).unwrap();
    let masking = [
        Masking::Correlated,
        Masking::Separable,
        Masking::CorrelatedBeta,
    ][e.masking as usize];
    let (k, a, b) = e.fr;
    match k {
        0 => Box::new(RoughConductor::new(m, One::<3>).with_masking(masking)),
        1 => Box::new(RoughConductor::new(m, Dielectric { eta: a[0] }).with_masking(masking)),
        2 => Box::new(RoughConductor::new(m, Conductor { eta: a, k: b }).with_masking(masking)),
        3 => Box::new(RoughConductor::new(m, Schlick { f0: a }).with_masking(masking)),
        _ => Box::new(RoughConductor::new(m, F82Tint { f0: a, h: b }).with_masking(masking)),
    }
}

/// The conductor grid: every roughness (and an effectively smooth one), every Fresnel term,
/// the three maskings, directions × (directions or uniforms).
fn conductor_els(second: &[[f32; 3]], us: &[[f32; 2]]) -> Vec<El> {
    let mut els = Vec::new();
    let mut alphas = ALPHAS.to_vec();
    alphas.push([5e-4, 5e-4]);
    for (i, &a) in alphas.iter().enumerate() {
        for (j, fr) in fresnels().into_iter().enumerate() {
            for &wo in &directions() {
                for &wi in second {
                    for &u in us {
                        let mut e = El::new(a, wo, wi, u);
                        e.fr = fr;
                        e.masking = ((i + j) % 3) as u32;
                        els.push(e);
                    }
                }
            }
        }
    }
    els
}

/// How far the half vector of (wo, wi) may move between two f32 evaluations: twice the Rust
/// docs' δ = 4ε(1 + η')/|η' wi + wo| (each side rounds it once; η' = 1 for a reflection), and
/// for a sampled wi at least the sampled normal's bound (`cap_bound`). Returns (wm in f64,
/// η', δ).
fn half_vector_delta(
    wo: [f32; 3],
    wi: [f32; 3],
    eta: f32,
    sampled: Option<f64>,
) -> ([f64; 3], f64, f64) {
    let (o, i) = (wo.map(f64::from), wi.map(f64::from));
    let etap = if o[2] * i[2] > 0.0 {
        1.0
    } else if o[2] > 0.0 {
        eta as f64
    } else {
        1.0 / eta as f64
    };
    let sum = [etap * i[0] + o[0], etap * i[1] + o[1], etap * i[2] + o[2]];
    let len = sum.iter().map(|x| x * x).sum::<f64>().sqrt();
    let mut wm = sum.map(|x| x / len.max(1e-300));
    if wm[2] < 0.0 {
        wm = wm.map(|x| -x);
    }
    let mut delta = 2.0 * 4.0 * EPS * (1.0 + etap) / len.max(1e-30);
    if let Some(bound) = sampled {
        delta = delta.max(bound);
    }
    (wm, etap, delta)
}

/// Three of the NDF quantities' bound (2e-6 each): a BSDF value is a product of D, G2 (or
/// G1) and F, each held to it, and a few divisions.
const BSDF_TOL: f64 = 3.0 * TOL;

/// The relative bound of a BSDF value (f or pdf) whose half vector wm may move by δ:
/// `BSDF_TOL` plus what the move costs D, δ(1 + 4 tan θh/α²) (D's condition
/// number in the normal, α the smaller roughness: the crate-wide 4εκ rule of the Rust docs'
/// Accuracy section), plus what it costs the Fresnel factor `fr` at c = |wo·wm|, measured as
/// the largest change of fr(c ± δ) relative to `weight(fr(c))` (fr itself, or 1 − fr for a
/// transmission): finite near the dielectric's critical angle, where fr has a square-root
/// edge; and what the Fresnel formula's own cancellation costs, 16ε times `formula`
/// (`fresnel_cancellation`).
fn value_tol(
    wm: [f64; 3],
    alpha: [f32; 2],
    delta: f64,
    c: f64,
    fr: &dyn Fn(f64) -> f64,
    weight: &dyn Fn(f64) -> f64,
    formula: f64,
) -> f64 {
    let a = alpha[0].min(alpha[1]) as f64;
    let z = wm[2].clamp(1e-6, 1.0);
    let tan = (1.0 - z * z).max(0.0).sqrt() / z;
    let d_term = delta * (1.0 + 4.0 * tan / (a * a));
    let f0 = fr(c);
    let df = (fr(c + delta) - f0).abs().max((fr(c - delta) - f0).abs());
    let w = weight(f0);
    let f_term = if w > 0.0 {
        (df + 16.0 * EPS * formula * f0) / w
    } else {
        0.0
    };
    BSDF_TOL + d_term + f_term
}

/// The element's Fresnel term, channel `ch`, as a function of cos θ (f64).
fn fresnel_fn(e: &El, ch: usize) -> impl Fn(f64) -> f64 {
    let (k, a, b) = e.fr;
    let (x, y) = (a[ch] as f64, b[ch] as f64);
    move |c: f64| match k {
        0 => 1.0,
        1 => fresnel::dielectric(c, x),
        2 => fresnel::conductor(c, x, y),
        3 => fresnel::schlick(c, x),
        _ => fresnel::f82_tint(c, x, y),
    }
}

/// The conductor's bound at (wo, wi), channel `ch` (see [`value_tol`]).
fn conductor_tol(e: &El, wi: [f32; 3], ch: usize, sampled: Option<f64>) -> f64 {
    let (wm, _, delta) = half_vector_delta(e.wo, wi, 1.0, sampled);
    let c = (0..3).map(|k| e.wo[k] as f64 * wm[k]).sum::<f64>().abs();
    // (The element's Fresnel kind as `fresnel_cancellation`'s function index.)
    let (kind, a, b) = e.fr;
    let formula = match kind {
        1 => fresnel_cancellation(0, c, a[ch] as f64, 0.0),
        2 => fresnel_cancellation(1, c, a[ch] as f64, b[ch] as f64),
        4 => fresnel_cancellation(3, c, a[ch] as f64, b[ch] as f64),
        _ => 1.0,
    };
    value_tol(wm, e.alpha, delta, c, &fresnel_fn(e, ch), &|f| f, formula)
}

#[test]
fn conductor_eval_and_pdf_match_rust_f32() {
    let els = conductor_els(&directions(), &[[0.5; 2]]);
    let Some(out) = run("ms_k_conductor_eval", &els) else {
        return;
    };
    let names = ["eval / bound", "pdf / bound", "eval_pdf = (eval, pdf)"];
    let mut w = Worst::new(&names);
    for (e, o) in els.iter().zip(&out) {
        let c = rust_conductor(e);
        let (f, p) = (c.eval(e.wo, e.wi), c.pdf(e.wo, e.wi));
        for (ch, &r) in f.iter().enumerate() {
            let tol = conductor_tol(e, e.wi, ch, None);
            w.add(0, rel(o[0][ch], r) / tol, || {
                format!("{e:?}: gpu {:?} rust {f:?}", o[0])
            });
        }
        // (The pdf has no Fresnel factor: F = 1's bound.)
        let (wm, _, delta) = half_vector_delta(e.wo, e.wi, 1.0, None);
        let tol = value_tol(wm, e.alpha, delta, 1.0, &|_| 1.0, &|f| f, 0.0);
        w.add(1, rel(o[0][3], p) / tol, || {
            format!("{e:?}: gpu {} rust {p}", o[0][3])
        });
        let same = (0..4).all(|k| o[0][k] == o[1][k]);
        w.add(2, if same { 0.0 } else { 1.0 }, || {
            format!("{e:?}: {:?} {:?}", o[0], o[1])
        });
    }
    w.check(&[1.0, 1.0, 0.0]);
}

#[test]
fn conductor_samples_match_rust_f32() {
    let els = conductor_els(&[[0.0, 0.0, 1.0]], &uniforms());
    let Some(out) = run("ms_k_conductor_sample", &els) else {
        return;
    };
    let names = ["validity", "wi", "pdf / bound", "f / bound"];
    let mut w = Worst::new(&names);
    for (e, o) in els.iter().zip(&out) {
        let c = rust_conductor(e);
        let s = c.sample(e.wo, e.uc, e.u);
        let flags = o[1][3] as u32;
        let g_wi = [o[0][0], o[0][1], o[0][2]];
        let what = || format!("{e:?}: gpu {o:?} rust {s:?}");
        // (A decision within reach of the normal's bound may go either way.)
        let close = decision_is_close(e, false);
        let Some(s) = s else {
            let differs = flags & 1 != 0 && !close;
            w.add(0, if differs { 1.0 } else { 0.0 }, what);
            continue;
        };
        let expect = 1 | if s.specular { 2 } else { 0 };
        w.add(0, if flags != expect && !close { 1.0 } else { 0.0 }, what);
        if flags != expect {
            continue;
        }
        // wi = 2(wo·wm)wm − wo doubles the normal's difference.
        w.add(1, vec_diff(g_wi, s.wi) / (2.0 * cap_bound(e, false)), what);
        let (wm, _, delta) = half_vector_delta(e.wo, s.wi, 1.0, Some(cap_bound(e, false)));
        let tol = value_tol(wm, e.alpha, delta, 1.0, &|_| 1.0, &|f| f, 0.0);
        w.add(2, rel(o[0][3], s.pdf) / tol, what);
        for (ch, (&g, &r)) in o[1].iter().zip(&s.f).enumerate() {
            w.add(
                3,
                rel(g, r) / conductor_tol(e, s.wi, ch, Some(cap_bound(e, false))),
                what,
            );
        }
    }
    w.check(&[0.0, 1.0, 1.0, 1.0]);
}

/// Whether a sample's accept/reject or lobe decision lies within reach of the sampled normal's
/// bound (`cap_bound`), where the two sides may decide differently: replayed in f64 at the
/// f64 sampler's normal for the same u (the same warp), the margins of the reflected (or
/// refracted) direction's height, of uc against R (a dielectric), and of sin²θt against 1
/// (total internal reflection), each against what the normal's move changes it by.
fn decision_is_close(e: &El, dielectric: bool) -> bool {
    use microsurface::bsdf::frame::{reflect, refract};
    let bound = cap_bound(e, false);
    let m = Microfacet::<f64, Ggx>::new(e.alpha[0] as f64, e.alpha[1] as f64).unwrap();
    let wo = e.wo.map(f64::from);
    let wm = m.sample_wm(wo, [e.u[0] as f64, e.u[1] as f64]);
    let close_z = |wi: [f64; 3], scale: f64| wi[2].abs() <= 2.0 * bound * scale + 1e-18;
    if !dielectric {
        return close_z(reflect(wo, wm), 1.0);
    }
    let eta = e.fr.1[0] as f64;
    let c = wo[0] * wm[0] + wo[1] * wm[1] + wo[2] * wm[2];
    let r = fresnel::dielectric(c, eta);
    let dr = (fresnel::dielectric(c + bound, eta) - r)
        .abs()
        .max((fresnel::dielectric(c - bound, eta) - r).abs());
    if (e.uc as f64 - r).abs() <= dr + EPS || close_z(reflect(wo, wm), 1.0) {
        return true;
    }
    // Refraction: sin²θt = |t|²/η'² moves by up to 2·bound/η'²; wi's height by 2·bound·η'.
    let etap = if c < 0.0 { 1.0 / eta } else { eta };
    let t2 = 1.0 - c * c;
    let sin2 = t2 / (etap * etap);
    let etap_max = etap.max(1.0 / etap);
    (sin2 - 1.0).abs() <= 2.0 * bound / (etap * etap)
        || refract(wo, wm, eta).is_some_and(|(wi, _)| close_z(wi, etap_max))
}

/// Directions of both hemispheres: [`directions`] and their mirror images below.
fn both_sides() -> Vec<[f32; 3]> {
    let mut v = directions();
    let below: Vec<[f32; 3]> = v
        .iter()
        .filter(|w| w[2] > 0.0)
        .map(|w| [w[0], -w[1], -w[2]])
        .collect();
    v.extend(below);
    v
}

/// The dielectric grid: every roughness (and an effectively smooth one), η from 1/2.4 to 2.4
/// (1, the pass-through, included), both maskings the WGSL has, both transports.
fn dielectric_els(second: &[[f32; 3]], us: &[[f32; 2]], ucs: &[f32]) -> Vec<El> {
    let mut els = Vec::new();
    let mut alphas = ALPHAS.to_vec();
    alphas.push([5e-4, 5e-4]);
    for (i, &a) in alphas.iter().enumerate() {
        for (j, &eta) in [1.5f32, 1.0 / 1.5, 2.4, 1.0 / 2.4, 1.0, 1.0001]
            .iter()
            .enumerate()
        {
            for &wo in &both_sides() {
                for &wi in second {
                    for &u in us {
                        for &uc in ucs {
                            let mut e = El::new(a, wo, wi, u);
                            e.uc = uc;
                            e.fr = (1, [eta, 0.0, 0.0], [((i + j) % 2) as f32, 0.0, 0.0]);
                            e.masking = ((i + 2 * j) % 2) as u32;
                            els.push(e);
                        }
                    }
                }
            }
        }
    }
    els
}

fn rust_dielectric(e: &El) -> RoughDielectric<f32, Microfacet<f32, Ggx>> {
    let m = Microfacet::<f32, Ggx>::new(e.alpha[0], e.alpha[1]).unwrap();
    let masking = [Masking::Correlated, Masking::Separable][e.masking as usize];
    let transport = [Transport::Radiance, Transport::Importance][e.fr.2[0] as usize];
    RoughDielectric::new(m, e.fr.1[0])
        .unwrap()
        .with_masking(masking)
        .with_transport(transport)
}

/// The dielectric's bound at (wo, wi) (see [`value_tol`]): the half vector of a refraction
/// moves by up to 1/|η' wi + wo| more than a reflection's, and the Fresnel factor is R for a
/// reflection, 1 − R for a transmission.
fn dielectric_tol(e: &El, wi: [f32; 3], sampled: Option<f64>) -> f64 {
    let eta = e.fr.1[0];
    let (wm, _, delta) = half_vector_delta(e.wo, wi, eta, sampled);
    let c = (0..3).map(|k| e.wo[k] as f64 * wm[k]).sum::<f64>();
    let r = move |c: f64| fresnel::dielectric(c, eta as f64);
    let formula = fresnel_cancellation(0, c, eta as f64, 0.0);
    if e.wo[2] * wi[2] > 0.0 {
        value_tol(wm, e.alpha, delta, c, &r, &|f| f, formula)
    } else {
        value_tol(wm, e.alpha, delta, c, &r, &|f| 1.0 - f, formula)
    }
}

#[test]
fn dielectric_eval_and_pdf_match_rust_f32() {
    let els = dielectric_els(&both_sides(), &[[0.5; 2]], &[0.5]);
    let Some(out) = run("ms_k_dielectric_eval", &els) else {
        return;
    };
    let names = ["eval / bound", "pdf / bound"];
    let mut w = Worst::new(&names);
    for (e, o) in els.iter().zip(&out) {
        let d = rust_dielectric(e);
        let (f, p) = (d.eval(e.wo, e.wi)[0], d.pdf(e.wo, e.wi));
        let tol = dielectric_tol(e, e.wi, None);
        let what = || format!("{e:?}: gpu {:?} rust {f} {p}", o[0]);
        w.add(0, rel(o[0][0], f) / tol, what);
        w.add(1, rel(o[0][1], p) / tol, what);
    }
    w.check(&[1.0, 1.0]);
}

#[test]
fn dielectric_samples_match_rust_f32() {
    let els = dielectric_els(&[[0.0, 0.0, 1.0]], &uniforms(), &[0.02, 0.5, 0.97]);
    let Some(out) = run("ms_k_dielectric_sample", &els) else {
        return;
    };
    let names = ["validity, lobe", "wi", "pdf / bound", "f / bound", "η'"];
    let mut w = Worst::new(&names);
    for (e, o) in els.iter().zip(&out) {
        let d = rust_dielectric(e);
        let s = d.sample(e.wo, e.uc, e.u);
        let flags = o[1][2] as u32;
        let g_wi = [o[0][0], o[0][1], o[0][2]];
        let what = || format!("{e:?}: gpu {o:?} rust {s:?}");
        // (A decision within reach of the normal's bound may go either way.)
        let close = decision_is_close(e, true);
        let Some(s) = s else {
            let differs = flags & 1 != 0 && !close;
            w.add(0, if differs { 1.0 } else { 0.0 }, what);
            continue;
        };
        let expect =
            1 | if s.specular { 2 } else { 0 } | if s.lobe == Lobe::Transmission { 4 } else { 0 };
        w.add(0, if flags != expect && !close { 1.0 } else { 0.0 }, what);
        if flags != expect {
            continue;
        }
        // The refraction of the normal's difference grows with η' (2 · the normal's bound · η'),
        // and cos θt = √(1 − sin²θt) magnifies sin²θt's move (≤ 4 · bound/η'², plus its
        // rounding) by 1/(2 cos θt) toward a grazing refraction.
        let bound = cap_bound(e, false);
        let etap = s.eta.max(1.0 / s.eta) as f64;
        let mut wi_tol = 2.0 * bound * etap;
        if s.lobe == Lobe::Transmission {
            let e2 = (s.eta as f64) * (s.eta as f64);
            wi_tol += (4.0 * bound / e2 + 8.0 * EPS) / (2.0 * (s.wi[2] as f64).abs().max(1e-30));
        }
        w.add(1, vec_diff(g_wi, s.wi) / wi_tol, what);
        let tol = dielectric_tol(e, s.wi, Some(cap_bound(e, false)));
        w.add(2, rel(o[0][3], s.pdf) / tol, what);
        w.add(3, rel(o[1][0], s.f[0]) / tol, what);
        w.add(4, rel(o[1][1], s.eta), what);
    }
    w.check(&[0.0, 1.0, 1.0, 1.0, 0.0]);
}

// Beckmann. The WGSL evaluates in f32 what the Rust f32 path evaluates in f64 and rounds
// (Λ, the samplers), so the bounds are those of f32 arithmetic on the formulas, through
// each quantity's condition number, with Vulkan's allowance for exp (3 + 2|x| ulp).

/// |g − r|/|r| as `rel`, with differences below 1e-36 taken as 0: Λ past a ≈ 9 is
/// subnormal, and a pdf within 2⁶ of the least normal f32 has a subnormal factor on the way
/// (D, then times G1 c/z), which a device may flush to zero.
fn rel_normal(g: f32, r: f32) -> f64 {
    if (g as f64 - r as f64).abs() <= 1e-36 {
        return 0.0;
    }
    rel(g, r)
}

#[test]
fn beckmann_d_lambda_g1_g2_pdfs_match_rust_f32() {
    use microsurface::Beckmann;
    let mut els = Vec::new();
    for &a in &ALPHAS {
        for &wo in &directions() {
            for &wm in &normals() {
                els.push(El::new(a, wo, wm, [0.5; 2]));
            }
        }
    }
    let Some(out) = run("ms_k_beckmann_eval", &els) else {
        return;
    };
    let names = [
        "D / bound",
        "Λ / bound",
        "G1 / bound",
        "G2 correlated / bound",
        "G2 separable / bound",
        "visible pdf / bound",
        "D·cos pdf / bound",
        "MsMicrofacet pdf / bound",
    ];
    let mut w = Worst::new(&names);
    for (e, o) in els.iter().zip(&out) {
        let m = Microfacet::<f32, Beckmann>::new(e.alpha[0], e.alpha[1]).unwrap();
        let (wo, wm) = (e.wo, e.wi);
        let r = [
            m.d(wm),
            m.lambda(wo),
            m.g1(wo),
            m.g2(wo, wm),
            m.g2_separable(wo, wm),
            m.pdf(wo, wm),
            m.pdf_dcos(wm),
            m.pdf(wo, wm),
        ];
        let g = [
            o[0][0], o[0][1], o[0][2], o[0][3], o[1][0], o[1][1], o[1][2], o[1][3],
        ];
        // G1 = 1/(1 + Λ) and G2 take Λ's relative error times Λ/(1 + Λ) (≤ 1).
        let (lo, li) = (m.lambda(wo) as f64, m.lambda(wm) as f64);
        let (bo, bi) = (
            lambda_bound(NDF_BECKMANN, wo, e.alpha),
            lambda_bound(NDF_BECKMANN, wm, e.alpha),
        );
        let frac = |l: f64| if l.is_finite() { l / (1.0 + l) } else { 1.0 };
        let g1 = TOL + bo * frac(lo);
        let g2 = TOL + bo.max(bi) * frac(lo + li);
        let d = d_bound(NDF_BECKMANN, wm, e.alpha);
        let pdf = g1 + d + 8.0 * EPS * dot_cancellation(wo, wm);
        let tol = [d, bo, g1, g2, 2.0 * g1 + TOL, pdf, d, pdf];
        for k in 0..names.len() {
            w.add(k, rel_normal(g[k], r[k]) / tol[k], || {
                format!("{e:?}: gpu {} rust {} (bound {:e})", g[k], r[k], tol[k])
            });
        }
    }
    w.check(&[1.0; 8]);
}

/// The bound of a Beckmann visible normal's components at the element's uniforms, from the
/// conditioning of the slope inversion, replayed in f64 at the slopes (x̃, ỹ) of the Rust f64
/// sampler's normal: x̃ solves F = N(X) − u₀Z = 0, whose f32 evaluation rounds by a few ε
/// times the magnitudes of its terms T (a's rounding moves F by no more), so x̃ moves by
/// 32ε T/N′(x̃), N′ = (x̃ + a)e^{−x̃²}/√π, plus 8ε(1 + |x̃|) (the stopping rule and the
/// tables' fit, 1e-7); ỹ by 8ε(1 + |ỹ|); at normal incidence x̃ is Gaussian as ỹ. Then the
/// rotation and unstretch, p = αx(cos φ x̃ − sin φ ỹ), q = αy(sin φ x̃ + cos φ ỹ), move p and
/// q by those plus 4ε of their terms, and the unit normal (p, q, 1)/L by (δp + δq)/L, plus
/// `NORMAL_TOL` for the normalisation on both sides.
fn beckmann_normal_bound(e: &El) -> f64 {
    use microsurface::fast::beckmann::erfcx;
    use microsurface::Beckmann;
    let (ax, ay) = (e.alpha[0] as f64, e.alpha[1] as f64);
    let w64 = e.wo.map(f64::from);
    let u64 = [e.u[0] as f64, e.u[1] as f64];
    let m = Microfacet::<f64, Beckmann>::new(ax, ay).unwrap();
    let n = m.sample(w64, u64).wm;
    let sign = if w64[2] < 0.0 { -1.0 } else { 1.0 };
    let (sx, sy, c) = (sign * ax * w64[0], sign * ay * w64[1], sign * w64[2]);
    let h = (sx * sx + sy * sy).sqrt();
    let (cp, sp) = if h > 0.0 {
        (sx / h, sy / h)
    } else {
        (1.0, 0.0)
    };
    let (p, q) = (n[0] / n[2], n[1] / n[2]);
    let (px, qy) = (p / ax, q / ay);
    let (x, y) = (cp * px + sp * qy, -sp * px + cp * qy);
    let dy = 8.0 * EPS * (1.0 + y.abs());
    let dx = if h > 0.0 {
        let a = c / h;
        let u = u64[0];
        let ea = (-a * a).exp();
        let erfc_a = erfcx(a) * ea;
        let half_ea = 0.5 * ea / std::f64::consts::PI.sqrt();
        let z = 0.5 * a * (2.0 - erfc_a) + half_ea;
        let ex = (-x * x).exp();
        let ec = erfcx(x.abs()) * ex;
        let half_e = 0.5 * ex / std::f64::consts::PI.sqrt();
        let t = if x <= 0.0 {
            0.5 * a * (ec + erfc_a) + half_e + half_ea + u * z
        } else {
            (1.0 - u) * z + 0.5 * a * ec + half_e
        };
        let dn = (x + a) * ex / std::f64::consts::PI.sqrt();
        (32.0 * EPS * t / dn.max(1e-300)).min(1e3) + 8.0 * EPS * (1.0 + x.abs())
    } else {
        8.0 * EPS * (1.0 + x.abs())
    };
    let dp = ax * (cp.abs() * dx + sp.abs() * dy + 4.0 * EPS * ((cp * x).abs() + (sp * y).abs()));
    let dq = ay * (sp.abs() * dx + cp.abs() * dy + 4.0 * EPS * ((sp * x).abs() + (cp * y).abs()));
    let l = (p * p + q * q + 1.0).sqrt();
    NORMAL_TOL + (dp + dq) / l
}

#[test]
fn beckmann_samplers_give_the_rust_f32_normals() {
    use microsurface::Beckmann;
    let mut els = Vec::new();
    for &a in &ALPHAS {
        for &wo in &directions() {
            for &u in &uniforms() {
                els.push(El::new(a, wo, [0.0, 0.0, 1.0], u));
            }
        }
    }
    let Some(out) = run("ms_k_beckmann_sample", &els) else {
        return;
    };
    let names = [
        "visible normal / bound",
        "visible pdf at it / bound",
        "D·cos normal / bound",
        "D·cos pdf at it / bound",
    ];
    let mut w = Worst::new(&names);
    for (e, o) in els.iter().zip(&out) {
        let m = Microfacet::<f32, Beckmann>::new(e.alpha[0], e.alpha[1]).unwrap();
        let what = |g: [f32; 4], r: [f32; 3], p: f32| {
            move || format!("{e:?}: gpu {g:?} rust {r:?} (pdf {p})")
        };
        let s = m.sample(e.wo, e.u);
        let g = o[0];
        let gm = [g[0], g[1], g[2]];
        // u₀ = 0 at cot θ̃ > 9: the root is the end X = −a, but N and N′ underflow over a
        // whole interval of X before it (e^{−X²} below the least f32 past |X| = 9.3, the
        // least f64 past 26.6), where F = −u₀Z = 0 to rounding: each iteration stops at a
        // point of that interval (the Rust f32 sampler at X ≈ −11 for a = 41), a normal of
        // density below 1e-37 either way. Not compared.
        if !(e.u[0] == 0.0 && grid::cot(e.wo, e.alpha) > 9.0) {
            w.add(
                0,
                vec_diff(gm, s.wm) / beckmann_normal_bound(e),
                what(g, s.wm, s.pdf),
            );
        }
        // The pdf at the GPU's own normal: the pdf arithmetic apart from the normal's.
        let p = m.pdf(e.wo, gm);
        let tol = TOL
            + d_bound(NDF_BECKMANN, gm, e.alpha)
            + lambda_bound(NDF_BECKMANN, e.wo, e.alpha)
            + 8.0 * EPS * dot_cancellation(e.wo, gm);
        w.add(1, rel_normal(g[3], p) / tol, what(g, s.wm, p));
        // D·cos: r = √(−ln(1 − u₀)) from a series or log (a few ε), the azimuth as GGX's.
        let s = m.sample_dcos(e.u);
        let g = o[1];
        let gm = [g[0], g[1], g[2]];
        w.add(2, vec_diff(gm, s.wm) / NORMAL_TOL, what(g, s.wm, s.pdf));
        let p = m.pdf_dcos(gm);
        w.add(
            3,
            rel_normal(g[3], p) / d_bound(NDF_BECKMANN, gm, e.alpha),
            what(g, s.wm, p),
        );
    }
    w.check(&[1.0; 4]);
}

// The BSDFs over the other NDFs of the run-time door (MsMicrofacet): the WGSL conductor and
// dielectric are NDF-agnostic (they call ms_d, ms_g2, ms_pdf, …), so this checks the door's
// dispatch and each NDF inside the BSDF formulas, against `RoughConductor` and
// `RoughDielectric` over `AnyMicrofacet<f32>`.

/// A material of the BSDF test over the run-time door: its name, the Rust material, the tag
/// and table row of `MsMicrofacet`, and the roughness its table serves (GTR's table is one α's;
/// `None`: every roughness of the grid).
struct Mat {
    name: &'static str,
    kind: microsurface::NdfKind,
    shape: Option<f64>,
    ndf: u32,
    table: u32,
    alpha: Option<[f32; 2]>,
}

/// The door's materials past GGX, with the tables they read (the library's and the shapes'
/// and GTR materials' own), built once per test binary.
fn materials() -> &'static (Vec<Mat>, Tables) {
    use microsurface::NdfKind as K;
    static M: OnceLock<(Vec<Mat>, Tables)> = OnceLock::new();
    M.get_or_init(|| {
        let mut t = Tables::new();
        let mut v = Vec::new();
        for (name, kind, ndf) in [
            ("Beckmann", K::Beckmann, NDF_BECKMANN),
            ("Double GGX", K::DoubleGgx, NDF_DOUBLE_GGX),
            ("Exponential", K::Exponential, NDF_EXPONENTIAL),
        ] {
            v.push(Mat {
                name,
                kind,
                shape: None,
                ndf,
                table: 0,
                alpha: None,
            });
        }
        for (name, kind, shape, ndf) in [
            ("Student-T γ = 2.5", K::StudentT, Some(2.5), 5),
            ("Ei", K::Ei, None, 6),
            ("Erfc", K::Erfc, None, 7),
            ("K0", K::K0, None, 8),
            ("Bessel-K a = 2.5", K::BesselK, Some(2.5), 9),
        ] {
            let table = t.add_shape(kind, shape).expect("a shape table");
            v.push(Mat {
                name,
                kind,
                shape,
                ndf,
                table,
                alpha: None,
            });
        }
        for (name, gamma) in [("GTR γ = 1.5", 1.5), ("GTR γ = 3", 3.0)] {
            let a = 0.3f32;
            let table = t.add_gtr(a as f64, gamma).expect("a GTR material");
            v.push(Mat {
                name,
                kind: K::Gtr,
                shape: Some(gamma),
                ndf: 4,
                table,
                alpha: Some([a, a]),
            });
        }
        (v, t)
    })
}

/// How much D moves when wm moves by δ (f64, relative), from the Rust f64 material: the
/// central differences of D along two tangents of wm give its gradient, |∇D| δ plus the second
/// difference's term bounds the move in any direction (to second order).
fn d_move(m: &dyn MicrofacetDistribution<f64>, wm: [f64; 3], delta: f64) -> f64 {
    let d0 = m.d(wm);
    if !(d0 > 0.0 && delta > 0.0 && d0.is_finite()) {
        return 0.0;
    }
    // Two unit tangents of wm.
    let t1 = if wm[2].abs() < 0.9 {
        let l = (wm[0] * wm[0] + wm[1] * wm[1]).sqrt();
        [-wm[1] / l, wm[0] / l, 0.0]
    } else {
        let l = (wm[1] * wm[1] + wm[2] * wm[2]).sqrt();
        [0.0, wm[2] / l, -wm[1] / l]
    };
    let t2 = [
        wm[1] * t1[2] - wm[2] * t1[1],
        wm[2] * t1[0] - wm[0] * t1[2],
        wm[0] * t1[1] - wm[1] * t1[0],
    ];
    let at = |t: [f64; 3], s: f64| {
        let v = [wm[0] + s * t[0], wm[1] + s * t[1], wm[2] + s * t[2]];
        let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        m.d([v[0] / n, v[1] / n, v[2] / n])
    };
    let (mut grad2, mut curv) = (0.0f64, 0.0f64);
    for t in [t1, t2] {
        let (p, q) = (at(t, delta), at(t, -delta));
        grad2 += ((p - q) / 2.0).powi(2);
        curv = curv.max(((p + q) / 2.0 - d0).abs());
    }
    (grad2.sqrt() + curv) / d0
}

/// A BSDF value's bound (f or pdf) over the door's NDF: `TOL` (the Fresnel factor's and the
/// divisions' roundings), D's bound at wm (`grid::shaped_d_bound`: from the Rust f64 D's
/// condition number, the tables' rounding and Vulkan's allowances) and what δ's move of wm
/// costs it (`d_move`), Λ's bounds at wo and wi (`grid::shaped_lambda_bound`; G2 = 1/(1 +
/// Λo + Λi) or the G1 product take at most their sum), and the Fresnel factor's move as in
/// `value_tol`.
#[allow(clippy::too_many_arguments)]
fn ndf_value_tol(
    m64: &dyn MicrofacetDistribution<f64>,
    e: &El,
    wi: [f32; 3],
    wm: [f64; 3],
    delta: f64,
    c: f64,
    fr: &dyn Fn(f64) -> f64,
    weight: &dyn Fn(f64) -> f64,
    formula: f64,
) -> f64 {
    let f0 = fr(c);
    let df = (fr(c + delta) - f0).abs().max((fr(c - delta) - f0).abs());
    let w = weight(f0);
    let f_term = if w > 0.0 {
        (df + 16.0 * EPS * formula * f0) / w
    } else {
        0.0
    };
    TOL + shaped_d_bound(m64, wm.map(|x| x as f32))
        + d_move(m64, wm, delta)
        + shaped_lambda_bound(m64, e.wo)
        + shaped_lambda_bound(m64, wi)
        + f_term
}

/// The conductor's and dielectric's eval and pdf over every NDF of the door but GGX (whose
/// BSDFs the tests above check), through `MsMicrofacet` with the materials' tables, against
/// `RoughConductor` and `RoughDielectric` over `AnyMicrofacet<f32>`: every roughness (GTR: its
/// table's α), F = 1 and Schlick (conductor; both maskings), η = 1.5 and 1/1.5 from both
/// sides (dielectric), directions × directions.
#[test]
fn bsdfs_of_every_ndf_match_rust_f32() {
    use microsurface::AnyMicrofacet;
    let (mats, _) = materials();
    let (mut conductors, mut dielectrics) = (Vec::new(), Vec::new());
    let (mut cmat, mut dmat) = (Vec::new(), Vec::new());
    for (k, mat) in mats.iter().enumerate() {
        let alphas = match mat.alpha {
            Some(a) => vec![a],
            None => ALPHAS.to_vec(),
        };
        for (i, &a) in alphas.iter().enumerate() {
            for &wo in &both_sides() {
                for &wi in &both_sides() {
                    for (j, fr) in [(0, [1.0; 3], [0.0; 3]), (3, [0.04, 0.5, 0.95], [0.0; 3])]
                        .into_iter()
                        .enumerate()
                    {
                        let mut e = El::new(a, wo, wi, [0.5; 2]);
                        e.ndf = mat.ndf;
                        e.table = mat.table;
                        e.fr = fr;
                        e.masking = ((i + j) % 2) as u32;
                        if wo[2] > 0.0 && wi[2] > 0.0 {
                            conductors.push(e);
                            cmat.push(k);
                        }
                        let mut d = e;
                        let eta = [1.5f32, 1.0 / 1.5][j];
                        d.fr = (1, [eta, 0.0, 0.0], [0.0; 3]);
                        dielectrics.push(d);
                        dmat.push(k);
                    }
                }
            }
        }
    }
    let (Some(co), Some(di)) = (
        run("ms_k_conductor_eval", &conductors),
        run("ms_k_dielectric_eval", &dielectrics),
    ) else {
        return;
    };
    let names = [
        "conductor eval / bound",
        "conductor pdf / bound",
        "dielectric eval / bound",
        "dielectric pdf / bound",
    ];
    let mut w: Vec<Worst> = mats.iter().map(|_| Worst::new(&names)).collect();
    let material = |k: usize, e: &El| {
        let m = &mats[k];
        let m32 = AnyMicrofacet::<f32>::new(m.kind, e.alpha[0], e.alpha[1], m.shape).unwrap();
        let m64 = AnyMicrofacet::<f64>::new(m.kind, e.alpha[0] as f64, e.alpha[1] as f64, m.shape)
            .unwrap();
        (m32, m64)
    };
    // A value whose D at the half vector is subnormal in f32 may be 0 on a device that flushes
    // subnormals (Vulkan allows it without shaderDenormPreserveFloat32; lavapipe does): the
    // D factor is then 0 on the way, where Rust (no flush) keeps the digits that the division
    // by the cosines brings back into f32's normals.
    let flushed = |g: f32, r: f32, d: f32| g == 0.0 && d.abs() < f32::MIN_POSITIVE && r != 0.0;
    for ((e, o), &k) in conductors.iter().zip(&co).zip(&cmat) {
        let (m, m64) = material(k, e);
        let d32 = {
            let (wm, _, _) = half_vector_delta(e.wo, e.wi, 1.0, None);
            m.d(wm.map(|x| x as f32))
        };
        let masking = [Masking::Correlated, Masking::Separable][e.masking as usize];
        let (f, p) = if e.fr.0 == 0 {
            let c = RoughConductor::new(m, One::<3>).with_masking(masking);
            (c.eval(e.wo, e.wi), c.pdf(e.wo, e.wi))
        } else {
            let c = RoughConductor::new(m, Schlick { f0: e.fr.1 }).with_masking(masking);
            (c.eval(e.wo, e.wi), c.pdf(e.wo, e.wi))
        };
        let (wm, _, delta) = half_vector_delta(e.wo, e.wi, 1.0, None);
        let c = (0..3).map(|q| e.wo[q] as f64 * wm[q]).sum::<f64>().abs();
        for (ch, &r) in f.iter().enumerate() {
            let tol = ndf_value_tol(&m64, e, e.wi, wm, delta, c, &fresnel_fn(e, ch), &|f| f, 1.0);
            let x = if flushed(o[0][ch], r, d32) {
                0.0
            } else {
                rel_normal(o[0][ch], r) / tol
            };
            w[k].add(0, x, || {
                format!("{e:?}: gpu {:?} rust {f:?} (bound {tol:e})", o[0])
            });
        }
        let tol = ndf_value_tol(&m64, e, e.wi, wm, delta, 1.0, &|_| 1.0, &|f| f, 0.0);
        let x = if flushed(o[0][3], p, d32) {
            0.0
        } else {
            rel_normal(o[0][3], p) / tol
        };
        w[k].add(1, x, || {
            format!("{e:?}: gpu {} rust {p} (bound {tol:e})", o[0][3])
        });
    }
    for ((e, o), &k) in dielectrics.iter().zip(&di).zip(&dmat) {
        let (m, m64) = material(k, e);
        let d32 = {
            let (wm, _, _) = half_vector_delta(e.wo, e.wi, e.fr.1[0], None);
            m.d(wm.map(|x| x as f32))
        };
        let masking = [Masking::Correlated, Masking::Separable][e.masking as usize];
        let eta = e.fr.1[0];
        let d = RoughDielectric::new(m, eta).unwrap().with_masking(masking);
        let (f, p) = (d.eval(e.wo, e.wi)[0], d.pdf(e.wo, e.wi));
        let (wm, _, delta) = half_vector_delta(e.wo, e.wi, eta, None);
        let c = (0..3).map(|q| e.wo[q] as f64 * wm[q]).sum::<f64>();
        let r = move |c: f64| fresnel::dielectric(c, eta as f64);
        let formula = fresnel_cancellation(0, c, eta as f64, 0.0);
        let tol = if e.wo[2] * e.wi[2] > 0.0 {
            ndf_value_tol(&m64, e, e.wi, wm, delta, c, &r, &|f| f, formula)
        } else {
            ndf_value_tol(&m64, e, e.wi, wm, delta, c, &r, &|f| 1.0 - f, formula)
        };
        let what = || format!("{e:?}: gpu {:?} rust {f} {p} (bound {tol:e})", o[0]);
        let x = if flushed(o[0][0], f, d32) {
            0.0
        } else {
            rel_normal(o[0][0], f) / tol
        };
        w[k].add(2, x, what);
        let x = if flushed(o[0][1], p, d32) {
            0.0
        } else {
            rel_normal(o[0][1], p) / tol
        };
        w[k].add(3, x, what);
    }
    for (mat, w) in mats.iter().zip(&w) {
        eprintln!("{}:", mat.name);
        w.check(&[1.0; 4]);
    }
}
