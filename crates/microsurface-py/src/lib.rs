//! Python bindings of `microsurface` (issue 23): every NDF as a class with its quantities,
//! directions, samplers and albedos vectorised over NumPy arrays, the BSDFs and the albedo
//! tables. The package (`python/microsurface`) re-exports this module, `_microsurface`.
//!
//! The isotropic functions of a cosine are the library's exact f64 path ([`AnyNdf`]) (or,
//! with `fast=True`, the fast material's), except GGX's D, Λ and G1, which run the fast
//! closed forms (`microsurface::fast::ggx`, the slice
//! forms of `fast::batch`; within 3e-15 of the exact path) and for float32 input their f32
//! slice forms. Directions, samplers, BSDFs and walks run one material (`material`): the
//! library's run-time door [`microsurface::AnyMicrofacet`] (the fast kernels of every NDF) by
//! default, or [`Exact`] with `exact=True`. A float64 result is bit for bit what the Rust
//! call returns (tests/test_api.py compares with the `microsurface` command line).
//!
//! The files, by concept:
//!
//! - `lib.rs`: this page, the `#[pymodule]` (the registration order is the module's
//!   `__all__`) and `__version__`.
//! - `engine.rs`: the vectorising engine every method goes through: NumPy broadcasting with
//!   core axes, the GIL-free chunked loop with Ctrl-C between chunks, one element as Python
//!   numbers and lists without NumPy; its front ends (`apply` for scalar arguments,
//!   `apply_vec` and `map_vec` for directions) and the package's named tuples.
//! - `kernel.rs`: GGX's fast paths for D, Λ and G1 of a cosine (the library's slice forms,
//!   float32 in f32).
//! - `material.rs`: the material of the direction methods, samplers, BSDFs and walks:
//!   `AnyMicrofacet<f64>` (fast) or `Exact` with the posterior or warp visible sampler.
//! - `params.rs`: parameters as numbers or arrays (SciPy's frozen distributions): broadcast
//!   and validated at construction, appended to every method's arguments, one material per
//!   element.
//! - `ndf.rs`: the NDF classes (`NDF` and its eleven subclasses): the functions of a cosine
//!   and of directions, the samplers, `NDF.albedo`.
//! - `bsdf.rs`: the BSDF classes (`BSDF`, `Conductor`, `Dielectric`) over every scattering
//!   model.
//! - `albedo.rs`: the walk albedo by order (`NDF.albedo`'s body),
//!   `single_scattering_albedo`, `AlbedoTable`.
//! - `bench.rs`: `_rust_slice_ns`, a benchmark hook for benchmark.py, not API.
//!
//! [`AnyNdf`]: microsurface::AnyNdf
//! [`Exact`]: microsurface::Exact

mod albedo;
mod bench;
mod bsdf;
mod engine;
mod kernel;
mod material;
mod ndf;
mod params;

use pyo3::prelude::*;

/// A Cargo (SemVer) version in PEP 440's spelling: `1.0.0-rc.1` → `1.0.0rc1`, `1.2.3-alpha.2`
/// → `1.2.3a2`, `1.2.3-beta.1` → `1.2.3b1`; anything else (a release) as it is.
fn pep440(v: &str) -> String {
    let Some((release, pre)) = v.split_once('-') else {
        return v.to_string();
    };
    let (tag, n) = pre.split_once('.').unwrap_or((pre, "0"));
    let tag = match tag {
        "alpha" | "a" => "a",
        "beta" | "b" => "b",
        "rc" => "rc",
        _ => return v.to_string(),
    };
    format!("{release}{tag}{n}")
}

/// NumPy's C array API (and rust-numpy's borrow checker), fetched at import, before any
/// call. rust-numpy fetches them at their first use and panics if that fails; its fetch runs
/// Python code (numpy.lib.NumpyVersion, the import of numpy._core.multiarray), where a
/// Ctrl-C raises KeyboardInterrupt, which it turned into a PanicException at the first call
/// (issue 36). Here the same Python code runs first with its errors propagated (a Ctrl-C is
/// KeyboardInterrupt from the import), then rust-numpy's fetch, whose remaining window (its
/// second NumpyVersion call) is guarded: a panic there is KeyboardInterrupt again.
fn init_numpy_api(py: Python<'_>) -> PyResult<()> {
    let np = engine::numpy(py)?;
    let version = np.getattr("__version__")?;
    let v = py
        .import("numpy.lib")?
        .getattr("NumpyVersion")?
        .call1((version,))?;
    let major: u32 = v.getattr("major")?.extract()?;
    py.import(if major >= 2 {
        "numpy._core.multiarray"
    } else {
        "numpy.core.multiarray"
    })?;
    let touch = || {
        use numpy::PyArrayMethods;
        let a = numpy::PyArray1::<f64>::zeros(py, 0, false);
        drop(a.readwrite());
        drop(numpy::PyArray1::<f32>::zeros(py, 0, false).readonly());
    };
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(touch)).map_err(|panic| {
        let msg = panic
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default();
        if msg.contains("KeyboardInterrupt") {
            pyo3::exceptions::PyKeyboardInterrupt::new_err(())
        } else {
            pyo3::exceptions::PyImportError::new_err(format!(
                "NumPy's array API could not be loaded: {msg}"
            ))
        }
    })
}

#[pymodule]
fn _microsurface(m: &Bound<'_, PyModule>) -> PyResult<()> {
    init_numpy_api(m.py())?;
    // (Cargo's version in PEP 440's spelling, as maturin writes the wheel's: 1.0.0-rc.1 is
    // 1.0.0rc1.)
    m.add("__version__", pep440(env!("CARGO_PKG_VERSION")))?;
    ndf::register(m)?;
    bsdf::register(m)?;
    albedo::register(m)?;
    bench::register(m)?;
    Ok(())
}
