//! The WGSL library in wgpu compute shaders against the Rust f32 path, element by element
//! (CI: Mesa's lavapipe, `MICROSURFACE_GPU_REQUIRED=1`, so that a missing adapter fails
//! there; elsewhere the tests skip with a message when no Vulkan adapter exists).
//!
//! Grids: roughness from 2e-3 to 2, isotropic and anisotropic; directions at normal
//! incidence, cos θ from 0.9 down to 1e-4 (grazing) at four azimuths, and below the
//! horizon; uniforms 0, 2⁻²⁴, ¼, ½, 0.9 and 1 − 2⁻²⁴ in each coordinate.
//!
//! Tolerances (relative, |gpu − rust| ≤ tol·|rust|), and where each comes from:
//! * D, Λ, G1, G2 (both forms), the visible pdf, the D·cos pdf, the bounded pdf: 2e-6, twice
//!   the f32 fast path's documented bound (GGX f32 ≤ 1e-6 of the exact value: the table of
//!   `microsurface::fast`), as both sides are held to it.
//! * Fresnel: 2e-6 likewise where the Rust f32 function is well conditioned; the
//!   functions' docs state f32 to f32's rounding of their inputs.
//! * Sampled normals (warps of u): the same normal as the Rust f32 sampler to
//!   `NORMAL_TOL` per component, the bound measured here (the Rust f32 path forms cos 2πu in
//!   f64 and rounds, the WGSL in f32: 1 ulp of the angle, magnified by the unstretch).
//! * BSDF values: the half vector is recomputed on each side, and D at the half vector has
//!   condition number κ = |d ln D/d ln wm| up to 4/α²·|wm − n| (the lobe's slope); the
//!   bound is 2e-6 + 8ε κ_h where κ_h = 1 + 4 tan θh/α² (the crate-wide 4εκ rule of the
//!   Rust docs' Accuracy section, with the rounding of the half vector, 2ε, as the input's).

use microsurface::bsdf::fresnel::{self, Conductor, Dielectric, F82Tint, One, Schlick};
use microsurface::bsdf::{Bsdf, Masking, RoughConductor};
use microsurface::{Ggx, Microfacet, MicrofacetDistribution};
use microsurface_gpu::{kernels_source, Error, Gpu, Program, KERNEL_IN, KERNEL_OUT};
use std::sync::OnceLock;

/// The device and the compiled kernels, once per test binary; `None` (the tests skip) only
/// where no Vulkan adapter exists and `MICROSURFACE_GPU_REQUIRED` is not 1.
fn gpu() -> Option<&'static (Gpu, Program)> {
    static GPU: OnceLock<Option<(Gpu, Program)>> = OnceLock::new();
    GPU.get_or_init(|| {
        let required = std::env::var("MICROSURFACE_GPU_REQUIRED").as_deref() == Ok("1");
        match Gpu::new() {
            Ok(g) => {
                let i = g.adapter_info();
                eprintln!("adapter: {} ({:?}, {} {})", i.name, i.device_type, i.driver, i.driver_info);
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
        }
    }
    fn records(&self) -> [[f32; 4]; KERNEL_IN] {
        let (k, a, b) = self.fr;
        [
            [self.alpha[0], self.alpha[1], self.u[0], self.u[1]],
            [self.wo[0], self.wo[1], self.wo[2], self.uc],
            [self.wi[0], self.wi[1], self.wi[2], 0.0],
            [a[0], a[1], a[2], k as f32],
            [b[0], b[1], b[2], self.masking as f32],
        ]
    }
}

fn run(entry: &str, els: &[El]) -> Option<Vec<[[f32; 4]; KERNEL_OUT]>> {
    let (g, p) = gpu()?;
    let input: Vec<[f32; 4]> = els.iter().flat_map(|e| e.records()).collect();
    let out = g.run(p, entry, &input, KERNEL_IN, KERNEL_OUT).expect("the kernel runs");
    Some(out.chunks(KERNEL_OUT).map(|c| [c[0], c[1]]).collect())
}

const ALPHAS: [[f32; 2]; 9] = [
    [2e-3, 2e-3],
    [0.05, 0.05],
    [0.3, 0.3],
    [1.0, 1.0],
    [2.0, 2.0],
    [0.3, 0.05],
    [0.05, 0.6],
    [1.5, 0.2],
    [0.01, 0.5],
];

/// A unit direction at cos θ = c and azimuth φ, rounded to f32.
fn dir(c: f64, phi: f64) -> [f32; 3] {
    let s = (1.0 - c * c).max(0.0).sqrt();
    [(s * phi.cos()) as f32, (s * phi.sin()) as f32, c as f32]
}

/// Normal incidence, cos θ from 0.9 to 1e-4 at four azimuths, and a few below the horizon.
fn directions() -> Vec<[f32; 3]> {
    let mut v = vec![[0.0, 0.0, 1.0]];
    for c in [0.9, 0.5, 0.1, 1e-2, 1e-4] {
        for phi in [0.3, 1.9, 3.5, 5.2] {
            v.push(dir(c, phi));
        }
    }
    for c in [-0.7, -0.05] {
        v.push(dir(c, 2.4));
    }
    v
}

/// The normals D and the pdfs are evaluated at: cos θ from 1 to 0.05 and one below.
fn normals() -> Vec<[f32; 3]> {
    let mut v = vec![[0.0, 0.0, 1.0]];
    for c in [0.9999, 0.99, 0.9, 0.7, 0.4, 0.1, 0.05] {
        for phi in [0.2, 1.3, 2.9, 4.4, 5.8] {
            v.push(dir(c, phi));
        }
    }
    v.push(dir(-0.3, 1.0));
    v
}

const UNIFORMS: [f32; 6] = [0.0, 5.960_464_5e-8, 0.25, 0.5, 0.9, 0.999_999_94];

fn uniforms() -> Vec<[f32; 2]> {
    UNIFORMS.iter().flat_map(|&a| UNIFORMS.iter().map(move |&b| [a, b])).collect()
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

/// The largest relative difference of each named quantity and where it occurred.
struct Worst {
    names: Vec<&'static str>,
    max: Vec<(f64, String)>,
}

impl Worst {
    fn new(names: &[&'static str]) -> Self {
        Worst {
            names: names.to_vec(),
            max: vec![(0.0, String::new()); names.len()],
        }
    }
    fn add(&mut self, k: usize, e: f64, what: impl FnOnce() -> String) {
        if e > self.max[k].0 || e.is_nan() {
            self.max[k] = (e, what());
        }
    }
    fn check(&self, tol: &[f64]) {
        for (k, (e, w)) in self.max.iter().enumerate() {
            eprintln!("{:>26}: max {e:.3e} (tol {:.0e}) {w}", self.names[k], tol[k]);
        }
        for (k, (e, w)) in self.max.iter().enumerate() {
            assert!(*e <= tol[k], "{}: {e:e} > {:e} at {w}", self.names[k], tol[k]);
        }
    }
}

/// f32's unit roundoff.
const EPS: f64 = 5.960_464_5e-8;
/// The bound of the NDF quantities: twice the documented f32 fast-path bound (1e-6).
const TOL: f64 = 2e-6;

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
        let g = [o[0][0], o[0][1], o[0][2], o[0][3], o[1][0], o[1][1], o[1][2], o[1][3]];
        for k in 0..names.len() {
            w.add(k, rel(g[k], r[k]), || format!("{e:?}: gpu {} rust {}", g[k], r[k]));
        }
    }
    w.check(&[TOL; 8]);
}
