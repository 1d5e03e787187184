//! What the GPU tests share: the grids (roughness, directions, normals and uniforms, from
//! normal incidence to grazing and below the horizon, and the edge uniforms 0 and 1 − 2⁻²⁴),
//! and the worst-error bookkeeping (`Worst`, `vec_diff`).
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
