//! A benchmark hook, not API: `_rust_slice_ns`, which benchmark.py calls to time the Rust
//! slice forms in the Python process beside the Python calls. Its leading underscore keeps
//! it out of the package's namespace and its stubs; it may change with the benchmark.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use rayon::prelude::*;

/// A slice form: (u, α, out).
type Slice<T> = fn(&[T], &[T], &mut [T]);

/// The median over `reps` runs of `run`, in ns per element of n.
fn median(reps: usize, n: usize, mut run: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..reps.max(1))
        .map(|_| {
            let start = std::time::Instant::now();
            run();
            start.elapsed().as_secs_f64() * 1e9 / n as f64
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

/// The Rust slice forms' own speed in this process, for the benchmark script
/// (benchmark.py): GGX `quantity` ('d' or 'lambda') over n uniform cosines at α in f64 or
/// (`f32`) f32, into a preallocated output, on one thread and on rayon's pool in pieces of
/// 16 384; median ns per element of `reps`.
#[pyfunction]
fn _rust_slice_ns(
    py: Python<'_>,
    quantity: &str,
    n: usize,
    alpha: f64,
    reps: usize,
    f32: bool,
) -> PyResult<(f64, f64)> {
    use microsurface::fast::batch;
    let (f, g): (Slice<f64>, Slice<f32>) = match quantity {
        "d" => (batch::ggx_d, batch::ggx_d_f32),
        "lambda" => (batch::ggx_lambda, batch::ggx_lambda_f32),
        _ => return Err(PyValueError::new_err("quantity: 'd' or 'lambda'")),
    };
    fn both<T: Copy + Send + Sync + Default>(
        u: &[T],
        alpha: T,
        reps: usize,
        f: fn(&[T], &[T], &mut [T]),
    ) -> (f64, f64) {
        let n = u.len();
        let a = vec![alpha; n];
        let mut out = vec![T::default(); n];
        let one = median(reps, n, || f(u, &a, &mut out));
        let par = median(reps, n, || {
            out.par_chunks_mut(1 << 14)
                .zip(u.par_chunks(1 << 14).zip(a.par_chunks(1 << 14)))
                .for_each(|(o, (u, a))| f(u, a, o))
        });
        (one, par)
    }
    Ok(py.allow_threads(|| {
        let mut s = 0x9E37_79B9_7F4A_7C15u64;
        let u: Vec<f64> = (0..n)
            .map(|_| {
                s = s
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                ((s >> 11) as f64 + 0.5) / (1u64 << 53) as f64
            })
            .collect();
        if f32 {
            let u: Vec<f32> = u.iter().map(|&x| x as f32).collect();
            both(&u, alpha as f32, reps, g)
        } else {
            both(&u, alpha, reps, f)
        }
    }))
}

/// The Rust loop that the Python fast path of every NDF is measured against (benchmark.py's
/// `fast` table): `quantity` ('d', 'lambda', 'g1' of n uniform cosines, at the direction
/// (√(1 − u²), 0, u) formed in the loop; 'pdf': the visible density of n pairs of upper-hemisphere directions)
/// of the material `spec` (a spec string: 'ggx', 'gtr:1.5', ...) at α through the library's
/// run-time door ([`microsurface::AnyMicrofacet<f64>`]), for every element into a
/// preallocated output, on one thread and on rayon's pool in pieces of 16 384; median ns per
/// element of `reps`. (The door's scalar kernels in a plain loop: the slice form of the NDFs
/// that have no `fast::batch` kernel.)
#[pyfunction]
fn _rust_fast_ns(
    py: Python<'_>,
    spec: &str,
    quantity: &str,
    n: usize,
    alpha: f64,
    reps: usize,
) -> PyResult<(f64, f64)> {
    use microsurface::{AnyMicrofacet, MicrofacetDistribution};
    let m = AnyMicrofacet::<f64>::parse(spec, alpha, alpha)
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    if !matches!(quantity, "d" | "lambda" | "g1" | "pdf") {
        return Err(PyValueError::new_err(
            "quantity: 'd', 'lambda', 'g1' or 'pdf'",
        ));
    }
    Ok(py.allow_threads(|| {
        let mut s = 0x9E37_79B9_7F4A_7C15u64;
        let mut uniform = || {
            s = s
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            ((s >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        };
        let dir = |u: f64, phi: f64| {
            let st = ((1.0 - u) * (1.0 + u)).sqrt();
            [st * phi.cos(), st * phi.sin(), u]
        };
        // (Element i reads x[3i..3i+3] and, for the pdf, y[3i..3i+3].)
        let mut x = vec![0.0; 3 * n];
        let mut y = vec![0.0; 3 * n];
        for i in 0..n {
            let (a, b) = if quantity == "pdf" {
                (
                    dir(uniform(), std::f64::consts::TAU * uniform()),
                    dir(uniform(), std::f64::consts::TAU * uniform()),
                )
            } else {
                (dir(uniform(), 0.0), [0.0; 3])
            };
            x[3 * i..3 * i + 3].copy_from_slice(&a);
            y[3 * i..3 * i + 3].copy_from_slice(&b);
        }
        // (A function of a cosine takes the cosine: the direction is formed in the loop, as
        // the Python call forms it; the pdf takes two directions.)
        let f = |x: &[f64], y: &[f64], out: &mut [f64]| {
            let w = |k: usize| dir(x[3 * k + 2], 0.0);
            match quantity {
                "d" => out.iter_mut().enumerate().for_each(|(k, o)| *o = m.d(w(k))),
                "lambda" => out
                    .iter_mut()
                    .enumerate()
                    .for_each(|(k, o)| *o = m.lambda(w(k))),
                "g1" => out
                    .iter_mut()
                    .enumerate()
                    .for_each(|(k, o)| *o = m.g1(w(k))),
                _ => out.iter_mut().enumerate().for_each(|(k, o)| {
                    let a = [x[3 * k], x[3 * k + 1], x[3 * k + 2]];
                    *o = m.pdf(a, [y[3 * k], y[3 * k + 1], y[3 * k + 2]])
                }),
            }
        };
        let mut out = vec![0.0; n];
        let one = median(reps, n, || f(&x, &y, &mut out));
        let par = median(reps, n, || {
            out.par_chunks_mut(1 << 14)
                .zip(x.par_chunks(3 << 14).zip(y.par_chunks(3 << 14)))
                .for_each(|(o, (x, y))| f(x, y, o))
        });
        (one, par)
    }))
}

/// Adds the benchmark hooks to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_rust_slice_ns, m)?)?;
    m.add_function(wrap_pyfunction!(_rust_fast_ns, m)?)?;
    Ok(())
}
