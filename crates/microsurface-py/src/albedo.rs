//! The albedos of an NDF's material: by scattering order through Heitz et al.'s random walk
//! (the body of `NDF.albedo`), the single-scattering albedo by quadrature
//! (`single_scattering_albedo`), and the tables of energy compensation (`AlbedoTable`).

use crate::engine::{count, map_vec, named, Domain, Item};
use crate::ndf::NDF;
use microsurface::scattering::{
    self, AlbedoTable as Table, DielectricFacets, Heights, MirrorFacets, RandomWalk,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyFloat;

/// The direction at cos θ = mu and azimuth phi (mu in [−1, 1]: the engine checks it).
fn wo_of(mu: f64, phi: f64) -> [f64; 3] {
    let st = ((1.0 - mu) * (1.0 + mu)).max(0.0).sqrt();
    [st * phi.cos(), st * phi.sin(), mu]
}

/// `NDF.albedo` (its docstring there): the random walk's albedo by order of `ndf`'s
/// material at each element.
pub fn walk(
    ndf: &NDF,
    py: Python<'_>,
    mu: &Bound<'_, PyAny>,
    phi: Option<&Bound<'_, PyAny>>,
    walks: i64,
    seed: i128,
    eta: Option<f64>,
) -> PyResult<PyObject> {
    if !ndf.batched() {
        ndf.material()?;
    }
    let walks = count(walks, "walks", 1)? as u64;
    let seed = u64::try_from(seed)
        .map_err(|_| PyValueError::new_err(format!("seed must be in [0, 2**64) (got {seed})")))?;
    if let Some(eta) = eta {
        if !(eta > 0.0 && eta.is_finite() && eta != 1.0) {
            return Err(PyValueError::new_err(format!(
                "eta must be a positive finite number other than 1 (got {eta})"
            )));
        }
    }
    let zero = zero_like(py, mu)?;
    let items = items(mu, phi.unwrap_or(&zero));
    let o = ndf.each(py, &items, &[4, 4, 4, 4, 0, 0], 2, |d, i, a, o| {
        let surface = RandomWalk::new(d.clone(), Heights::Uniform);
        let wo = wo_of(a[0][0], a[1][0]);
        // (One stream per element, whatever thread runs it.)
        let seed = seed.wrapping_add((i as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15));
        let r = match eta {
            None => scattering::albedo(
                &surface,
                &MirrorFacets(microsurface::bsdf::fresnel::One::<1>),
                wo,
                walks,
                seed,
            ),
            Some(eta) => scattering::albedo(&surface, &DielectricFacets(eta), wo, walks, seed),
        };
        o[0..4].copy_from_slice(&r.reflect.orders);
        o[4..8].copy_from_slice(&r.reflect.stderr);
        o[8..12].copy_from_slice(&r.transmit.orders);
        o[12..16].copy_from_slice(&r.transmit.stderr);
        o[16] = r.total.mean;
        o[17] = r.total.stderr;
    })?;
    named(py, "Albedo", o)
}

/// The arguments of the albedos: mu (a cosine) and phi (finite).
fn items<'a, 'py>(mu: &'a Bound<'py, PyAny>, phi: &'a Bound<'py, PyAny>) -> Vec<Item<'a, 'py>> {
    vec![
        (mu, 0, "mu", Domain::Cosine),
        (phi, 0, "phi", Domain::Finite),
    ]
}

/// A zero azimuth of `mu`'s precision (float32 for float32 mu: the output's dtype follows
/// the arguments, and a default argument must not change it).
fn zero_like<'py>(py: Python<'py>, mu: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    let np = crate::engine::numpy(py)?;
    let float32 = np.getattr("float32")?;
    if np
        .call_method1("asarray", (mu,))?
        .getattr("dtype")?
        .eq(&float32)?
    {
        return float32.call1((0.0,));
    }
    Ok(PyFloat::new(py, 0.0).into_any())
}

/// The single-scattering albedo of the NDF's material by quadrature, at cos θo = ``mu`` and
/// azimuth ``phi``, broadcast together and with the NDF's parameter arrays (tables over
/// (α, μ) in one call). Each element is a quadrature (milliseconds; the family's singular
/// members longer): parallel, Ctrl-C between chunks. The integrand runs the NDF's path (the
/// fast kernels, or the exact path with ``exact=True``).
///
/// Without ``eta``: E₁(wo) of the F = 1 conductor with the height-correlated G2 (≤ 1e-9
/// relative requested, 1e-6 guaranteed; the random walk's order 1). With ``eta`` (the
/// relative index η_inside/η_outside, a number or an array broadcast with mu; η > 0, ≠ 1):
/// the rough dielectric's ``DielectricAlbedo(reflect, transmit)`` from the side of mu's sign
/// (μ < 0: from inside), with Fresnel at each microfacet (within 1.7e-5 by the library's
/// level-4 tanh-sinh rule over the microfacet normal). ``masking`` chooses the transmission's
/// masking-shadowing: ``'pbrt'`` (the default; 1/(1 + Λo + Λi), pbrt-v4's and
/// ``Dielectric``'s default, ``masking='correlated'`` there) or ``'exact'`` (the exact
/// height-correlated B(1 + Λo, 1 + Λi) of a transmission, ``masking='correlated_beta'``:
/// the random walk's order 1). The two differ most at grazing angles on rough surfaces
/// (GGX α = 1, μ = 0.05: transmission 0.728 by pbrt's form, 0.050 by the exact one).
#[pyfunction]
#[pyo3(signature = (ndf, mu, phi = None, eta = None, masking = "pbrt"))]
fn single_scattering_albedo(
    py: Python<'_>,
    ndf: PyRef<'_, NDF>,
    mu: &Bound<'_, PyAny>,
    phi: Option<&Bound<'_, PyAny>>,
    eta: Option<&Bound<'_, PyAny>>,
    masking: &str,
) -> PyResult<PyObject> {
    if !ndf.batched() {
        ndf.material()?;
    }
    let masking = match masking {
        "pbrt" => microsurface::bsdf::Masking::Correlated,
        "exact" => microsurface::bsdf::Masking::CorrelatedBeta,
        _ => {
            return Err(PyValueError::new_err(format!(
                "masking must be 'pbrt' or 'exact' (got {masking:?})"
            )))
        }
    };
    let zero = zero_like(py, mu)?;
    let mut items = items(mu, phi.unwrap_or(&zero));
    let Some(eta) = eta else {
        let mut o = ndf.each(py, &items, &[0], 2, |d, _, a, o| {
            o[0] = scattering::single_scattering_albedo(d, wo_of(a[0][0], a[1][0]));
        })?;
        return Ok(o.remove(0));
    };
    // η: positive, finite, not 1 (every element), as the Dielectric's.
    let np = crate::engine::numpy(py)?;
    let e = np.call_method1("asarray", (eta, "float64"))?;
    let ok = |x: f64| x > 0.0 && x.is_finite() && x != 1.0;
    let values: Vec<f64> = np
        .call_method1("ravel", (&e,))?
        .call_method0("tolist")?
        .extract()?;
    if let Some(bad) = values.iter().find(|&&x| !ok(x)) {
        return Err(PyValueError::new_err(format!(
            "eta must be a positive finite number other than 1 (got {bad})"
        )));
    }
    items.push((eta, 0, "eta", Domain::Finite));
    let o = ndf.each(py, &items, &[0, 0], 2, |d, _, a, o| {
        let (mu, phi, eta) = (a[0][0], a[1][0], a[2][0]);
        let (r, t) = scattering::single_scattering_albedo_dielectric_level(
            d,
            wo_of(mu, phi),
            eta,
            masking,
            4,
        );
        o[0] = r;
        o[1] = t;
    })?;
    named(py, "DielectricAlbedo", o)
}

/// AlbedoTable(ndf): the directional albedo E(μ) of the single-scattering conductor with
/// F = 1 (height-correlated G2) and its cosine-weighted average, as energy compensation
/// uses them: interpolated from the tables the library ships where ``ndf`` is one of them
/// (isotropic GGX, Beckmann, Double GGX, the Exponential NDF, GTR γ ∈ {1, 2}, α ∈ [0.01,
/// 4]), else 33 quadratures computed here on the material's fast kernels (tens of
/// milliseconds to seconds; Ctrl-C interrupts the wait) and kept for the process: the
/// compensated BSDFs of the same material reuse them.
#[pyclass(frozen, module = "microsurface")]
pub struct AlbedoTable {
    table: std::sync::Arc<Table>,
}

#[pymethods]
impl AlbedoTable {
    #[new]
    fn new(py: Python<'_>, ndf: PyRef<'_, NDF>) -> PyResult<Self> {
        let d = ndf.material()?.clone();
        let table = crate::engine::interruptible(py, move || Table::new(&d))?;
        Ok(AlbedoTable { table })
    }

    /// E(μ), cubic in √μ between the nodes, vectorised over μ.
    fn e(&self, py: Python<'_>, mu: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        let t = &self.table;
        map_vec(py, &[(mu, 0, "mu", Domain::Cosine)], |a| t.e(a[0][0]))
    }

    /// E_avg = 2∫E(μ)μ dμ.
    #[getter]
    fn e_avg(&self) -> f64 {
        self.table.e_avg()
    }

    /// The energy single scattering loses, averaged: 2∫max(0, 1 − E(μ))μ dμ.
    #[getter]
    fn lost_avg(&self) -> f64 {
        self.table.lost_avg()
    }
}

/// Adds `AlbedoTable` and `single_scattering_albedo` to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<AlbedoTable>()?;
    m.add_function(wrap_pyfunction!(single_scattering_albedo, m)?)?;
    Ok(())
}
