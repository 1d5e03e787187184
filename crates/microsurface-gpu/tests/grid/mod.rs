//! What the GPU tests share: the grids (roughness, directions, normals and uniforms, from
//! normal incidence to grazing and below the horizon, and the edge uniforms 0 and 1 − 2⁻²⁴),
//! the worst-error bookkeeping (`Worst`, `vec_diff`), and the f32 bounds of each NDF's D and
//! Λ (`d_bound`, `lambda_bound`; their derivations are here).
#![allow(dead_code)] // (each test file uses its part)

/// Roughness (αx, αy): isotropic from 2e-3 to 2, and anisotropic both ways.
pub const ALPHAS: [[f32; 2]; 9] = [
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
pub fn dir(c: f64, phi: f64) -> [f32; 3] {
    let s = (1.0 - c * c).max(0.0).sqrt();
    [(s * phi.cos()) as f32, (s * phi.sin()) as f32, c as f32]
}

/// Normal incidence, cos θ from 0.9 to 1e-4 at four azimuths, a few below the horizon, and
/// one on it.
pub fn directions() -> Vec<[f32; 3]> {
    let mut v = vec![[0.0, 0.0, 1.0]];
    for c in [0.9, 0.5, 0.1, 1e-2, 1e-4] {
        for phi in [0.3, 1.9, 3.5, 5.2] {
            v.push(dir(c, phi));
        }
    }
    for c in [-0.7, -0.05] {
        v.push(dir(c, 2.4));
    }
    // On the horizon: Λ = +∞, G1 = G2 = 0, the pdfs 0, a conductor's sample rejected.
    v.push([0.6, 0.8, 0.0]);
    v
}

/// The normals D and the pdfs are evaluated at: cos θ from 1 to 0.05 and one below.
pub fn normals() -> Vec<[f32; 3]> {
    let mut v = vec![[0.0, 0.0, 1.0]];
    for c in [0.9999, 0.99, 0.9, 0.7, 0.4, 0.1, 0.05] {
        for phi in [0.2, 1.3, 2.9, 4.4, 5.8] {
            v.push(dir(c, phi));
        }
    }
    v.push(dir(-0.3, 1.0));
    v
}

pub const UNIFORMS: [f32; 6] = [0.0, 5.960_464_5e-8, 0.25, 0.5, 0.9, 0.999_999_94];

pub fn uniforms() -> Vec<[f32; 2]> {
    UNIFORMS
        .iter()
        .flat_map(|&a| UNIFORMS.iter().map(move |&b| [a, b]))
        .collect()
}

/// The largest component difference of two unit vectors.
pub fn vec_diff(a: [f32; 3], b: [f32; 3]) -> f64 {
    (0..3)
        .map(|k| (a[k] as f64 - b[k] as f64).abs())
        .fold(0.0, f64::max)
}

/// The largest error of each named quantity (a relative difference, or a ratio to its
/// bound) and where it occurred; each test file reports and asserts it (`check`).
pub struct Worst {
    pub names: Vec<&'static str>,
    pub max: Vec<(f64, String)>,
}

impl Worst {
    pub fn new(names: &[&'static str]) -> Self {
        Worst {
            names: names.to_vec(),
            max: vec![(0.0, String::new()); names.len()],
        }
    }
    pub fn add(&mut self, k: usize, e: f64, what: impl FnOnce() -> String) {
        if e > self.max[k].0 || e.is_nan() {
            self.max[k] = (e, what());
        }
    }
}

/// f32's unit roundoff.
pub const EPS: f64 = 5.960_464_5e-8;
/// The bound of the NDF quantities: twice the documented f32 fast-path bound (1e-6), both
/// sides held to it.
pub const TOL: f64 = 2e-6;

/// The NDF tags of `MsMicrofacet` (microfacet.wgsl's MS_NDF_*).
pub const NDF_GGX: u32 = 0;
pub const NDF_BECKMANN: u32 = 1;
pub const NDF_DOUBLE_GGX: u32 = 2;
pub const NDF_EXPONENTIAL: u32 = 3;

/// D's relative bound at wm for the NDF `ndf`:
/// * GGX: `TOL` (the WGSL is the Rust f32 path operation for operation).
/// * Beckmann: the exponent e = ((x/αx)² + (y/αy)²)/z² carries a few roundings (4ε e) and
///   Vulkan may take its exponential to (3 + 2e) ulp: `TOL` + (8 + 24e)ε, with a margin for
///   the normalisation's products.
/// * Double GGX: the Rust path is f64; here y = q/z² carries ~5 roundings and D's condition
///   number in y is at most ~2 (G(1/y) ≈ 1 − 4y near the normal, ~ ln y/y² at grazing), the
///   kernel table rounded to f32 moves by ≤ 5.8e-8 (the generator measures it) and its
///   evaluation and the normalisation add a few ε: `TOL` + 32ε.
/// * Exponential: the exponent e = 2√q/z carries a few roundings (4ε e) and Vulkan allows
///   its exponential (3 + 2e) ulp: `TOL` + (8 + 24e)ε.
pub fn d_bound(ndf: u32, wm: [f32; 3], alpha: [f32; 2]) -> f64 {
    let (x, y, z) = (
        wm[0] as f64 / alpha[0] as f64,
        wm[1] as f64 / alpha[1] as f64,
        wm[2] as f64,
    );
    match ndf {
        NDF_BECKMANN | NDF_EXPONENTIAL => {
            let q = x * x + y * y;
            let e = match (z > 0.0, ndf == NDF_BECKMANN) {
                (false, _) => 0.0,
                (true, true) => q / (z * z),
                (true, false) => 2.0 * q.sqrt() / z,
            };
            TOL + (8.0 + 24.0 * e) * EPS
        }
        NDF_DOUBLE_GGX => TOL + 32.0 * EPS,
        _ => TOL,
    }
}

/// cot θ̃ of w at the roughness, |w.z|/√(αx²w.x² + αy²w.y²) (f64; +∞ at the normal).
pub fn cot(w: [f32; 3], alpha: [f32; 2]) -> f64 {
    let (x, y) = (alpha[0] as f64 * w[0] as f64, alpha[1] as f64 * w[1] as f64);
    (w[2] as f64).abs() / (x * x + y * y).sqrt()
}

/// Λ's relative bound at w for the NDF `ndf`:
/// * GGX, Double GGX: `TOL`. Double GGX's Λ is the Rust f32 path operation for operation (x
///   in f32, the same f32 cubics), and Λ's condition number in x is at most about 1 (Λ ~
///   x ln x near the normal, ~√x at grazing), so a device's contraction of x's few roundings
///   costs a few ε; the ends (f32 expansions here, the rounded f64 ones in Rust) agree to
///   their truncation, below 1e-9.
/// * Beckmann: a = cot θ̃'s rounding (2ε) times Λ's condition number in a (2a² + 1 + …) and
///   e^{−a²}'s allowance (3 + 2a² ulp): `TOL` + 16ε(1 + 2a²).
/// * Exponential: the Rust f32 path forms q = z² in f64, here in f32 (~6 roundings), and
///   Λ's condition number in z is about 1 + z (Λ ~ 2/(πz) at grazing, ~ e^{−z}/√z near the
///   normal); past z = 64 Vulkan allows e^{−z} 3 + 2z ulp: `TOL` + 16ε(1 + z).
pub fn lambda_bound(ndf: u32, w: [f32; 3], alpha: [f32; 2]) -> f64 {
    let cot = cot(w, alpha);
    match ndf {
        NDF_BECKMANN => {
            let a = cot.min(1e3);
            TOL + 16.0 * EPS * (1.0 + 2.0 * a * a)
        }
        // (Past z = 200 Λ is below 1e-86: 0 in f32 on both sides.)
        NDF_EXPONENTIAL => TOL + 16.0 * EPS * (1.0 + (2.0 * cot).min(200.0)),
        _ => TOL,
    }
}

/// |g − r|/|r| (0 where equal, or where they differ by less than 1e-36: a subnormal factor
/// a device may flush); +∞ where exactly one is 0, NaN or infinite.
pub fn rel_flushed(g: f32, r: f32) -> f64 {
    if g == r || (g as f64 - r as f64).abs() <= 1e-36 {
        return 0.0;
    }
    let (g, r) = (g as f64, r as f64);
    if !(g.is_finite() && r.is_finite()) || r == 0.0 {
        return f64::INFINITY;
    }
    (g - r).abs() / r.abs()
}

/// |w||m|/|w·m| (f64), the cancellation of the visible pdf's dot product (1e12 capped).
pub fn visible_cancellation(w: [f32; 3], m: [f32; 3]) -> f64 {
    let d: f64 = (0..3).map(|k| w[k] as f64 * m[k] as f64).sum();
    (1.0 / d.abs()).min(1e12)
}

/// The eight quantities of the NDF comparisons (the test kernels' `ms_k_family_eval`), each
/// over its bound.
pub const QUANTITIES: [&str; 8] = [
    "D / bound",
    "Λ / bound",
    "G1 / bound",
    "G2 correlated / bound",
    "G2 separable / bound",
    "visible pdf / bound",
    "D·cos pdf / bound",
    "G1(wm) / bound",
];

/// The Rust f32 values of [`QUANTITIES`] at (wo, wm).
pub fn rust_quantities(
    m: &dyn microsurface::MicrofacetDistribution<f32>,
    wo: [f32; 3],
    wm: [f32; 3],
) -> [f32; 8] {
    [
        m.d(wm),
        m.lambda(wo),
        m.g1(wo),
        m.g2(wo, wm),
        m.g2_separable(wo, wm),
        m.pdf(wo, wm),
        m.pdf_dcos(wm),
        m.g1(wm),
    ]
}

/// The GPU's [`QUANTITIES`]: `ms_k_family_eval`'s two records.
pub fn gpu_quantities(o: &[[f32; 4]; 2]) -> [f32; 8] {
    [
        o[0][0], o[0][1], o[0][2], o[0][3], o[1][0], o[1][1], o[1][2], o[1][3],
    ]
}

/// The bounds of [`QUANTITIES`] from Λ's bounds at wo and wm (`bo`, `bi`), Λ's values there
/// (`lo`, `li`), D's bound `d` and the directions: G1 = 1/(1 + Λ) and G2 take Λ's relative
/// error times Λ/(1 + Λ) (≤ 1), plus `TOL`; the separable G2 both G1's; the visible pdf G1's
/// and D's plus 8ε times the dot product's cancellation.
pub fn quantity_bounds(
    (bo, bi): (f64, f64),
    (lo, li): (f64, f64),
    d: f64,
    wo: [f32; 3],
    wm: [f32; 3],
) -> [f64; 8] {
    let frac = |l: f64| if l.is_finite() { l / (1.0 + l) } else { 1.0 };
    let g1 = TOL + bo * frac(lo);
    let g1m = TOL + bi * frac(li);
    let g2 = TOL + bo.max(bi) * frac(lo + li);
    let pdf = g1 + d + 8.0 * EPS * visible_cancellation(wo, wm);
    [d, bo, g1, g2, g1 + g1m + TOL, pdf, d, g1m]
}

impl Worst {
    /// Prints every maximum and asserts each within its bound (≤ 1).
    pub fn check_within_bounds(&self) {
        for (k, (e, w)) in self.max.iter().enumerate() {
            eprintln!("{:>28}: max {e:.3e} of its bound {w}", self.names[k]);
        }
        for (k, (e, w)) in self.max.iter().enumerate() {
            assert!(*e <= 1.0, "{}: {e:e} of its bound at {w}", self.names[k]);
        }
    }
}

/// The relative condition number of `f` (positive) in its argument's scale: |d ln f/d ln t|
/// at t = 1, by a central difference (f64).
pub fn condition(f: impl Fn(f64) -> f64) -> f64 {
    let (h, f0) = (1e-6, f(1.0));
    if !(f0 > 0.0 && f0.is_finite()) {
        return 0.0;
    }
    let (p, q) = (f(1.0 + h), f(1.0 - h));
    if !(p > 0.0 && q > 0.0) {
        return 0.0;
    }
    ((p / q).ln() / (2.0 * h)).abs()
}

/// Λ's bound at w for an NDF with a shape table, from the f64 material: `TOL`; the rounding
/// of z = cot θ/α̃ (a few ε) times Λ's condition number in z (numerically, from the Rust f64
/// Λ: ~1 at grazing, the tail's power 2γ − 2 near the normal for Student-T, 2z² or 2z for
/// the exponential tails); and, where the rows hold 256 log₂ Λ₁ (p), their f32 rounding, ε|p|
/// in p, which is ln 2 ε|log₂ Λ| in Λ, with exp2's Vulkan allowance (3 + 2|log₂ Λ| ulp).
pub fn shaped_lambda_bound(m: &dyn microsurface::MicrofacetDistribution<f64>, w: [f32; 3]) -> f64 {
    let w = w.map(f64::from);
    let lambda = m.lambda(w);
    let x = if lambda > 0.0 && lambda.is_finite() {
        lambda.log2().abs()
    } else {
        0.0
    };
    let kappa = condition(|t| m.lambda([w[0], w[1], w[2] * t]));
    TOL + 8.0 * EPS * (1.0 + kappa) + 8.0 * EPS * (1.0 + x)
}

/// D's bound at wm for an NDF with a shape table: D = exp(ln f₁(r) − ln(αx αy) − 4 ln z).
/// r² carries ~5 roundings and ln f₁ is the profile's formula (Student-T: γ ln(1 + t); the
/// others: a fitted table within 1e-7 of the Rust f64 function, and a logarithm), so ln D
/// moves by 8ε times D's condition number in r² (numerically, from the Rust f64 D) plus the
/// table's 1e-7, plus Vulkan's allowance for the logarithms (2^−21 absolute each near 1, up to
/// four) and the exponential ((3 + 2|ln D|) ulp).
pub fn shaped_d_bound(m: &dyn microsurface::MicrofacetDistribution<f64>, wm: [f32; 3]) -> f64 {
    let wm = wm.map(f64::from);
    let d = m.d(wm);
    let ln_d = if d > 0.0 && d.is_finite() {
        d.ln().abs()
    } else {
        0.0
    };
    // (Scaling the horizontal components scales r² by t²: half the condition in t.)
    let kappa = 0.5 * condition(|t| m.d([wm[0] * t, wm[1] * t, wm[2]]));
    TOL + 1e-7 + 4.0 * 4.768_371_6e-7 + EPS * (8.0 + 2.0 * ln_d + 8.0 * kappa)
}
