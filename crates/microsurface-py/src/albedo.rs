//! The albedos of an NDF's material: by scattering order through Heitz et al.'s random walk
//! (the body of `NDF.albedo`), the single-scattering albedo by quadrature
//! (`single_scattering_albedo`), and the tables of energy compensation (`AlbedoTable`).

use crate::engine::{count, map_vec, named, Domain, Item};
use crate::ndf::NDF;
use microsurface::scattering::table::{Grid, Material as TableMaterial, Method, Spec};
use microsurface::scattering::Cancellable;
use microsurface::scattering::{
    self, AlbedoTable as Table, DielectricFacets, Heights, MirrorFacets, RandomWalk,
};
use microsurface::{MicrofacetDistribution, NdfKind};
use numpy::PyArray1;
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
#[allow(clippy::too_many_arguments)]
pub fn walk(
    ndf: &NDF,
    py: Python<'_>,
    mu: &Bound<'_, PyAny>,
    phi: Option<&Bound<'_, PyAny>>,
    walks: i64,
    seed: i128,
    eta: Option<f64>,
    orders: i64,
    progress: bool,
) -> PyResult<PyObject> {
    if !ndf.batched() {
        ndf.material()?;
    }
    let walks = count(walks, "walks", 1)? as u64;
    // (At most 1000 bins: an order of thousands is reached only at α ≳ 300.)
    let k = count(orders, "orders", 1)?;
    if k > 1000 {
        return Err(PyValueError::new_err(format!(
            "orders must be at most 1000 (got {orders})"
        )));
    }
    let seed = u64::try_from(seed)
        .map_err(|_| PyValueError::new_err(format!("seed must be in [0, 2**64) (got {seed})")))?;
    if let Some(eta) = eta {
        if !(eta > 0.0 && eta.is_finite() && eta != 1.0) {
            return Err(PyValueError::new_err(format!(
                "eta must be a positive finite number other than 1 (got {eta})"
            )));
        }
    }
    let facets = eta
        .map(DielectricFacets::new)
        .transpose()
        .map_err(crate::engine::value_error)?;
    let zero = zero_like(py, mu)?;
    let items = items(mu, phi.unwrap_or(&zero));
    let o = crate::engine::with_progress(py, progress, || {
        ndf.each(py, &items, &[k, k, k, k, 0, 0], 2, |d, i, a, o| {
            let surface = RandomWalk::new(d.clone(), Heights::Uniform);
            let wo = wo_of(a[0][0], a[1][0]);
            // (One stream per element, whatever thread runs it.)
            let seed = seed.wrapping_add((i as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15));
            let r = match facets {
                None => scattering::albedo_orders(
                    &surface,
                    &MirrorFacets(microsurface::bsdf::fresnel::One::<1>),
                    wo,
                    walks,
                    seed,
                    k,
                ),
                Some(f) => scattering::albedo_orders(&surface, &f, wo, walks, seed, k),
            };
            for (j, side) in [&r.reflect, &r.transmit].into_iter().enumerate() {
                let at = 2 * j * k;
                for (n, e) in side.iter().enumerate() {
                    o[at + n] = e.mean;
                    o[at + k + n] = e.stderr;
                }
            }
            o[4 * k] = r.total.mean;
            o[4 * k + 1] = r.total.stderr;
        })
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
/// relative requested, 1e-6 guaranteed; the random walk's order 1); μ < 0 is the mirror
/// image, E(|μ|), as ``AlbedoTable.e`` and ``albedo`` have it (the BSDFs are two-sided). With ``eta`` (the
/// relative index η_inside/η_outside, a number or an array broadcast with mu; η > 0, ≠ 1):
/// the rough dielectric's ``DielectricAlbedo(reflect, transmit)`` from the side of mu's sign
/// (μ < 0: from inside), with Fresnel at each microfacet (within 1.7e-5 by the library's
/// level-4 tanh-sinh rule over the microfacet normal). ``masking`` chooses the transmission's
/// masking-shadowing: ``'pbrt'`` (the default; 1/(1 + Λo + Λi), pbrt-v4's and
/// ``Dielectric``'s default, ``masking='correlated'`` there) or ``'exact'`` (the exact
/// height-correlated B(1 + Λo, 1 + Λi) of a transmission, ``masking='correlated_beta'``:
/// the random walk's order 1). The two differ most at grazing angles on rough surfaces
/// (GGX α = 1, μ = 0.05: transmission 0.728 by pbrt's form, 0.050 by the exact one).
/// ``progress=True``: a tqdm bar over the elements where tqdm is installed (silent
/// otherwise). The generalised exponential's quadratures take seconds an element.
#[pyfunction]
#[pyo3(signature = (ndf, mu, phi = None, eta = None, masking = "pbrt", progress = false))]
fn single_scattering_albedo(
    py: Python<'_>,
    ndf: PyRef<'_, NDF>,
    mu: &Bound<'_, PyAny>,
    phi: Option<&Bound<'_, PyAny>>,
    eta: Option<&Bound<'_, PyAny>>,
    masking: &str,
    progress: bool,
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
        let mut o = crate::engine::with_progress(py, progress, || {
            ndf.each(py, &items, &[0], 2, |d, _, a, o| {
                o[0] = scattering::single_scattering_albedo(d, wo_of(a[0][0], a[1][0]));
            })
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
    let o = crate::engine::with_progress(py, progress, || {
        ndf.each(py, &items, &[0, 0], 2, |d, _, a, o| {
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
        })
    })?;
    named(py, "DielectricAlbedo", o)
}

/// AlbedoTable(ndf): the directional albedo E(μ) of the single-scattering conductor with
/// F = 1 (height-correlated G2) and its cosine-weighted average, as energy compensation
/// uses them: interpolated from the tables the library ships where ``ndf`` is one of them
/// (isotropic GGX, Beckmann, Double GGX, the Exponential NDF, GTR γ ∈ {1, 2}, α ∈ [0.01,
/// 4]), else 33 quadratures computed here on the material's fast kernels (tens of
/// milliseconds to seconds, minutes for the generalised exponential; Ctrl-C interrupts the
/// wait; ``progress=True``: a tqdm bar over the nodes where tqdm is installed) and kept for
/// the process: the compensated BSDFs of the same material reuse them.
#[pyclass(frozen, module = "microsurface")]
pub struct AlbedoTable {
    table: std::sync::Arc<Table>,
    /// The material it is of (NDF, shape, α), where known: what the command line's format
    /// records.
    source: Option<(NdfKind, Option<f64>, f64)>,
}

/// The NDF spec of a table of the command line's binary form (`microsurface table`).
fn grid_of(kind: NdfKind, shape: Option<f64>, alpha: Vec<f64>, mu: Vec<f64>) -> Spec {
    Spec {
        ndf: kind,
        gamma: shape,
        material: TableMaterial::Furnace,
        method: Method::Quadrature,
        alpha,
        mu,
    }
}

#[pymethods]
impl AlbedoTable {
    #[new]
    #[pyo3(signature = (ndf, progress = false))]
    fn new(py: Python<'_>, ndf: PyRef<'_, NDF>, progress: bool) -> PyResult<Self> {
        let d = ndf.material()?.clone();
        let source = d.ndf().map(|(kind, shape)| (kind, shape, d.alpha().0));
        let source = source.filter(|_| d.alpha().0 == d.alpha().1);
        let progress = Progress::new(py, progress)?;
        let counts = progress.counts();
        let report = move |done: usize, total: usize| counts.set(done as u64, total as u64);
        let table = crate::engine::interruptible_ticking(
            py,
            move |cancel| {
                Table::new_with_progress(
                    &d,
                    &Cancellable {
                        progress: report,
                        cancel,
                    },
                )
            },
            progress.ticker(),
        )?
        .map_err(|_| pyo3::exceptions::PyKeyboardInterrupt::new_err(()))?;
        progress.close(py)?;
        Ok(AlbedoTable { table, source })
    }

    /// The same table from its node values, material and (an anisotropic material's)
    /// azimuthal harmonics (`__reduce__`'s inverse, not API).
    #[staticmethod]
    #[pyo3(signature = (values, source = None, harmonics = Vec::new()))]
    fn _restore(
        values: Vec<f64>,
        source: Option<(String, Option<f64>, f64)>,
        harmonics: Vec<Vec<f64>>,
    ) -> PyResult<Self> {
        let table = Table::from_harmonics(values, harmonics).ok_or_else(|| {
            PyValueError::new_err("at least 4 finite values expected, and harmonics as long")
        })?;
        let source = source
            .map(|(kind, shape, alpha)| {
                kind.parse::<NdfKind>()
                    .map(|k| (k, shape, alpha))
                    .map_err(|e| PyValueError::new_err(e.to_string()))
            })
            .transpose()?;
        Ok(AlbedoTable {
            table: std::sync::Arc::new(table),
            source,
        })
    }

    /// Pickle, copy: the node values (exact), the material it is of, and an anisotropic
    /// material's azimuthal harmonics (E(μ, φ)).
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, pyo3::types::PyTuple>)> {
        let py = slf.py();
        let this = slf.get();
        let source = this.source.map(|(k, s, a)| (k.name(), s, a));
        let args = (
            this.table.values().to_vec(),
            source,
            this.table.harmonics().to_vec(),
        )
            .into_pyobject(py)?;
        Ok((slf.get_type().getattr("_restore")?, args))
    }

    /// ``AlbedoTable(<ndf at α>, 33 nodes, E_avg = ...)``: what it is of (not evaluable: a
    /// table is computed; ``pickle`` and ``save``/``load`` round-trip it).
    fn __repr__(&self) -> String {
        let of = match self.source {
            Some((k, Some(s), a)) => format!("{k}:{s} at alpha={a}, "),
            Some((k, None, a)) => format!("{k} at alpha={a}, "),
            None => String::new(),
        };
        format!(
            "AlbedoTable({of}{} nodes, e_avg={})",
            self.table.values().len(),
            self.table.e_avg()
        )
    }

    /// Equal when of the same node values and material.
    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        let Ok(o) = other.downcast::<AlbedoTable>() else {
            return false;
        };
        let o = o.get();
        self.table.values() == o.table.values()
            && self.table.harmonics() == o.table.harmonics()
            && self.source == o.source
    }

    /// By the node values' bits and the material.
    fn __hash__(&self) -> isize {
        let mut h = std::collections::hash_map::DefaultHasher::new();
        for v in self
            .table
            .values()
            .iter()
            .chain(self.table.harmonics().iter().flatten())
        {
            std::hash::Hash::hash(&v.to_bits(), &mut h);
        }
        std::hash::Hash::hash(
            &self
                .source
                .map(|(k, s, a)| (k.name(), s.map(f64::to_bits), a.to_bits())),
            &mut h,
        );
        std::hash::Hasher::finish(&h) as isize
    }

    /// The nodes' μ (uniform in √μ; the grazing node at μ = 1e-6), float64.
    #[getter]
    fn mu<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_vec(py, self.table.mu())
    }

    /// E at the nodes, float64: the interpolant passes through them at √μ = k/(n − 1) (the
    /// grazing node's value, E(1e-6), stands at √μ = 0). For an anisotropic material, whose
    /// albedo depends on wo's azimuth too (its compensated BSDFs read E(μ, φ)), the mean over
    /// the azimuth.
    #[getter]
    fn values<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.table.values())
    }

    /// Writes the table: ``.npy``, an (n, 2) float64 array of (μ, E) at the nodes (exact);
    /// ``.mfa``, the command line's binary form (``microsurface table --method quadrature``:
    /// its header names the NDF, α and the nodes; values in float32, as that format keeps
    /// them), for a table made from one isotropic NDF.
    fn save(&self, py: Python<'_>, path: std::path::PathBuf) -> PyResult<()> {
        if self.table.is_azimuthal() {
            // (The files hold E(μ); an anisotropic material's E(μ, φ) would lose its azimuth.)
            return Err(PyValueError::new_err(
                "an anisotropic material's table depends on the azimuth too: pickle it instead",
            ));
        }
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        match ext {
            "npy" => {
                let np = crate::engine::numpy(py)?;
                let a = np.call_method1("stack", ((self.mu(py), self.values(py)),))?;
                let a = a.call_method0("transpose")?;
                np.call_method1("save", (path, a))?;
                Ok(())
            }
            "mfa" => {
                let Some((kind, shape, alpha)) = self.source else {
                    return Err(PyValueError::new_err(
                        "a .mfa table names its NDF and α: this table was not made from one isotropic NDF (save it as .npy)",
                    ));
                };
                let grid = Grid {
                    spec: grid_of(kind, shape, vec![alpha], self.table.mu()),
                    quantities: vec!["e1".to_string()],
                    values: self.table.values().iter().map(|&v| v as f32).collect(),
                };
                std::fs::write(&path, grid.to_bytes())
                    .map_err(|e| pyo3::exceptions::PyOSError::new_err(e.to_string()))
            }
            _ => Err(PyValueError::new_err(
                "path must end in .npy or .mfa (the command line's binary form)",
            )),
        }
    }

    /// Reads a table ``save`` wrote (``.npy``), or a table of the command line's binary form
    /// (``.mfa``: quantity ``e1``, at α node ``alpha_index``, its μ nodes those of a table
    /// uniform in √μ, as ``microsurface table --method quadrature --mu 0:1:N:sqrt`` writes).
    #[staticmethod]
    #[pyo3(signature = (path, alpha_index = 0))]
    fn load(py: Python<'_>, path: std::path::PathBuf, alpha_index: usize) -> PyResult<Self> {
        let bad = |m: String| PyValueError::new_err(format!("{}: {m}", path.display()));
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        let (mu, values, source) = match ext {
            "npy" => {
                let a = crate::engine::numpy(py)?.call_method1("load", (&path,))?;
                let shape: Vec<usize> = a.getattr("shape")?.extract()?;
                if shape.len() != 2 || shape[1] != 2 {
                    return Err(bad(format!(
                        "an (n, 2) array of (mu, E) expected, got shape {shape:?}"
                    )));
                }
                let rows: Vec<[f64; 2]> = a.call_method0("tolist")?.extract()?;
                (
                    rows.iter().map(|r| r[0]).collect::<Vec<_>>(),
                    rows.iter().map(|r| r[1]).collect::<Vec<_>>(),
                    None,
                )
            }
            "mfa" => {
                let bytes = std::fs::read(&path)
                    .map_err(|e| pyo3::exceptions::PyOSError::new_err(e.to_string()))?;
                let g = Grid::from_bytes(&bytes).map_err(|e| bad(e.0))?;
                let q = g.quantities.iter().position(|q| q == "e1").ok_or_else(|| {
                    bad("no quantity e1 (the single-scattering albedo: --method quadrature)".into())
                })?;
                if alpha_index >= g.spec.alpha.len() {
                    return Err(bad(format!(
                        "alpha_index {alpha_index}: the table has {} alpha nodes",
                        g.spec.alpha.len()
                    )));
                }
                let values = (0..g.spec.mu.len())
                    .map(|im| f64::from(g.value(alpha_index, im, q)))
                    .collect();
                let alpha = g.spec.alpha[alpha_index];
                (
                    g.spec.mu.clone(),
                    values,
                    Some((g.spec.ndf, g.spec.gamma, alpha)),
                )
            }
            _ => {
                return Err(PyValueError::new_err(
                    "path must end in .npy or .mfa (the command line's binary form)",
                ))
            }
        };
        let table = Table::from_values(values)
            .ok_or_else(|| bad("at least 4 finite values expected".into()))?;
        let nodes = table.mu();
        // (The grazing node: 0 as `microsurface table --mu 0:1:N:sqrt` writes it, or the
        // library's 1e-6, where it takes the albedo's limit.)
        let off =
            |(k, (a, b)): (usize, (&f64, &f64))| (a - b).abs() > 1e-12 && !(k == 0 && *a == 0.0);
        if mu.len() != nodes.len() || mu.iter().zip(&nodes).enumerate().any(off) {
            return Err(bad(format!(
                "the mu nodes are not uniform in sqrt(mu) ({} nodes from 1e-6 to 1)",
                nodes.len()
            )));
        }
        Ok(AlbedoTable {
            table: std::sync::Arc::new(table),
            source,
        })
    }

    /// E(μ), cubic in √μ between the nodes, vectorised over μ; μ < 0 is E(|μ|), as
    /// ``single_scattering_albedo`` and ``albedo`` have it.
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

/// A long call's progress: the counts its worker sets (done, total; from any thread) and the
/// tqdm bar (where `progress=True` and tqdm is installed) that a ticker brings up to date
/// with the GIL, every 50 ms of [`crate::engine::interruptible_ticking`]'s wait.
struct Progress {
    bar: Option<PyObject>,
    counts: std::sync::Arc<Counts>,
}

/// (done, total) of a worker.
#[derive(Default)]
struct Counts([std::sync::atomic::AtomicU64; 2]);

impl Counts {
    fn set(&self, done: u64, total: u64) {
        self.0[0].store(done, std::sync::atomic::Ordering::Relaxed);
        self.0[1].store(total, std::sync::atomic::Ordering::Relaxed);
    }
}

impl Progress {
    fn new(py: Python<'_>, on: bool) -> PyResult<Self> {
        Ok(Progress {
            bar: if on { crate::engine::tqdm(py)? } else { None },
            counts: Default::default(),
        })
    }

    /// The counts, for the worker.
    fn counts(&self) -> std::sync::Arc<Counts> {
        self.counts.clone()
    }

    /// The bar's update, for the wait.
    fn ticker(&self) -> impl FnMut(Python<'_>) -> PyResult<()> + Send + use<> {
        let bar = self
            .bar
            .as_ref()
            .map(|b| Python::with_gil(|py| b.clone_ref(py)));
        let counts = self.counts.clone();
        let mut shown = 0u64;
        move |py| {
            let Some(b) = &bar else {
                return Ok(());
            };
            let b = b.bind(py);
            let done = counts.0[0].load(std::sync::atomic::Ordering::Relaxed);
            let total = counts.0[1].load(std::sync::atomic::Ordering::Relaxed);
            b.setattr("total", total)?;
            b.call_method1("update", (done.saturating_sub(shown),))?;
            shown = shown.max(done);
            Ok(())
        }
    }

    fn close(&self, py: Python<'_>) -> PyResult<()> {
        if let Some(b) = &self.bar {
            b.bind(py).call_method0("close")?;
        }
        Ok(())
    }
}

/// The `Table` named tuple of a grid: its nodes, quantity names and values (α, μ, quantity).
fn table_tuple(py: Python<'_>, g: &Grid) -> PyResult<PyObject> {
    let (na, nm, nq) = (g.spec.alpha.len(), g.spec.mu.len(), g.quantities.len());
    let values = PyArray1::from_slice(py, &g.values)
        .into_any()
        .call_method1("reshape", ((na, nm, nq),))?;
    named(
        py,
        "Table",
        vec![
            PyArray1::from_slice(py, &g.spec.alpha).into_any().unbind(),
            PyArray1::from_slice(py, &g.spec.mu).into_any().unbind(),
            pyo3::types::PyTuple::new(py, &g.quantities)?
                .into_any()
                .unbind(),
            values.unbind(),
        ],
    )
}

/// table(ndf, alpha, mu, material='furnace', eta=None, k=None, rho=None, method='walk',
/// walks=100000, seed=0, out=None, progress=False): the albedo table over (α, μ) of the
/// command line's ``microsurface table`` (the same options, the same numbers: the library's
/// ``scattering::table::Grid::generate``, deterministic for any thread count). ``ndf``: a
/// class, a name (``"gtr:1.5"``) or an NDF (its kind and shape); ``alpha``, ``mu``: the nodes
/// (α > 0; μ in (0, 1], and [−1, 0) for a dielectric: from inside); ``material``:
/// ``'furnace'`` (F = 1), ``'conductor'`` (``eta``, ``k``), ``'dielectric'`` (``eta``) or
/// ``'diffuse'`` (``rho``, default 1); ``method``: ``'walk'`` (``walks`` per cell from
/// ``seed``: orders 1, 2, 3, ≥ 4 per side with standard errors) or ``'quadrature'`` (the
/// single-scattering albedo ``e1`` of the furnace). ``out``: also write it in the command
/// line's binary form (``.mfa``). ``progress=True``: a tqdm bar where tqdm is installed
/// (silent otherwise). Runs on every core; Ctrl-C interrupts it. Returns ``Table(alpha, mu,
/// quantities, values)``, values float32 of shape (len(alpha), len(mu), len(quantities)).
#[pyfunction]
#[pyo3(signature = (ndf, alpha, mu, material = "furnace", eta = None, k = None, rho = None, method = "walk", walks = 100_000, seed = 0, out = None, progress = false))]
#[allow(clippy::too_many_arguments)]
fn table(
    py: Python<'_>,
    ndf: &Bound<'_, PyAny>,
    alpha: Vec<f64>,
    mu: Vec<f64>,
    material: &str,
    eta: Option<f64>,
    k: Option<f64>,
    rho: Option<f64>,
    method: &str,
    walks: i64,
    seed: i128,
    out: Option<std::path::PathBuf>,
    progress: bool,
) -> PyResult<PyObject> {
    let (kind, shape, _, _) = crate::ndf::kind_of(py, ndf)?;
    let need = |x: Option<f64>, what: &str| {
        x.ok_or_else(|| PyValueError::new_err(format!("material '{material}' needs {what}")))
    };
    let material = match material {
        "furnace" => TableMaterial::Furnace,
        "conductor" => TableMaterial::Conductor {
            eta: need(eta, "eta and k")?,
            k: need(k, "eta and k")?,
        },
        "dielectric" => TableMaterial::Dielectric {
            eta: need(eta, "eta")?,
        },
        "diffuse" => TableMaterial::Diffuse {
            rho: rho.unwrap_or(1.0),
        },
        _ => {
            return Err(PyValueError::new_err(format!(
            "material must be 'furnace', 'conductor', 'dielectric' or 'diffuse' (got {material:?})"
        )))
        }
    };
    let seed = u64::try_from(seed)
        .map_err(|_| PyValueError::new_err(format!("seed must be in [0, 2**64) (got {seed})")))?;
    let method = match method {
        "walk" => Method::Walk {
            walks: count(walks, "walks", 1)? as u64,
            seed,
        },
        "quadrature" => Method::Quadrature,
        _ => {
            return Err(PyValueError::new_err(format!(
                "method must be 'walk' or 'quadrature' (got {method:?})"
            )))
        }
    };
    let spec = Spec {
        ndf: kind,
        gamma: shape,
        material,
        method,
        alpha,
        mu,
    };
    spec.validate().map_err(|e| PyValueError::new_err(e.0))?;
    let progress = Progress::new(py, progress)?;
    let counts = progress.counts();
    let work = move |cancel| {
        let progress = Cancellable {
            progress: move |done: usize, total: usize| counts.set(done as u64, total as u64),
            cancel,
        };
        Grid::generate(&spec, &progress)
    };
    let grid = crate::engine::interruptible_ticking(py, work, progress.ticker())?
        .map_err(|e| PyValueError::new_err(e.0))?;
    progress.close(py)?;
    if let Some(path) = out {
        if path.extension().and_then(|e| e.to_str()) != Some("mfa") {
            return Err(PyValueError::new_err(
                "out must end in .mfa (the command line's binary form)",
            ));
        }
        std::fs::write(&path, grid.to_bytes())
            .map_err(|e| pyo3::exceptions::PyOSError::new_err(e.to_string()))?;
    }
    table_tuple(py, &grid)
}

/// read_table(path): a table of the command line's binary form (``.mfa``, as ``table`` and
/// ``microsurface table`` write it) as ``Table(alpha, mu, quantities, values)``.
#[pyfunction]
fn read_table(py: Python<'_>, path: std::path::PathBuf) -> PyResult<PyObject> {
    let bytes =
        std::fs::read(&path).map_err(|e| pyo3::exceptions::PyOSError::new_err(e.to_string()))?;
    let g = Grid::from_bytes(&bytes)
        .map_err(|e| PyValueError::new_err(format!("{}: {}", path.display(), e.0)))?;
    table_tuple(py, &g)
}

/// lut(ndf, kind, size=32, eta_size=16, aspect_size=0, mu_axis='mu',
/// roughness_axis='sqrt_alpha', alpha_max=1.0, nodes='centres', level=4, progress=False):
/// the tables real-time engines load, the command line's ``microsurface lut`` (the library's
/// ``scattering::lut``, the same numbers before the file's rounding). ``kind``: ``'albedo'``
/// (E(μ, α) of the F = 1 conductor), ``'albedo-avg'`` (E_avg(α)), ``'dfg'`` (the split sum's
/// A, B, C: Schlick's albedo F0·A + B, F82-tint's F0·A + B − a·C), ``'dielectric'`` (R, T over
/// (side, η, α, μ); side 0 from outside at η, 1 from inside at 1/η) or ``'dielectric-avg'``.
/// ``size`` nodes along μ and the roughness, ``eta_size`` along η = 1 + 2x², ``aspect_size``
/// along αy/αx (anisotropic, averaged over the azimuth; 0: isotropic); ``mu_axis``
/// ``'mu'`` or ``'sqrt_mu'``, ``roughness_axis`` ``'sqrt_alpha'`` (α = α_max x²) or
/// ``'alpha'``; ``nodes`` ``'centres'`` (x = (i + ½)/n, a GPU's linear filter) or
/// ``'edges'`` (x = i/(n − 1)); ``level`` the quadrature's (2 to 7). Every core; Ctrl-C
/// interrupts it. Returns ``Lut(axes, coords, params, channels, values)``: the axes' names,
/// their nodes' coordinates and parameters (μ, α, η, αy/αx; the side's ±1), the channels'
/// names, and ``values`` (float64, the axes' node counts then the channels).
#[pyfunction]
#[pyo3(signature = (ndf, kind, size = 32, eta_size = 16, aspect_size = 0, mu_axis = "mu", roughness_axis = "sqrt_alpha", alpha_max = 1.0, nodes = "centres", level = 4, progress = false))]
#[allow(clippy::too_many_arguments)]
fn lut(
    py: Python<'_>,
    ndf: &Bound<'_, PyAny>,
    kind: &str,
    size: i64,
    eta_size: i64,
    aspect_size: i64,
    mu_axis: &str,
    roughness_axis: &str,
    alpha_max: f64,
    nodes: &str,
    level: i64,
    progress: bool,
) -> PyResult<PyObject> {
    use microsurface::scattering::lut::{Lut, LutSpec};
    let (kind_ndf, shape, _, _) = crate::ndf::kind_of(py, ndf)?;
    let bad = |e: String| PyValueError::new_err(e);
    let ndf_spec = microsurface::NdfSpec::new(kind_ndf, shape).map_err(|e| bad(e.to_string()))?;
    let mut spec = LutSpec::new(ndf_spec, kind.parse().map_err(bad)?);
    spec.size = count(size, "size", 0)?;
    spec.eta_size = count(eta_size, "eta_size", 0)?;
    spec.aspect_size = count(aspect_size, "aspect_size", 0)?;
    spec.mu_axis = mu_axis.parse().map_err(bad)?;
    spec.roughness_axis = roughness_axis.parse().map_err(bad)?;
    spec.alpha_max = alpha_max;
    spec.nodes = nodes.parse().map_err(bad)?;
    spec.level = u32::try_from(count(level, "level", 0)?).unwrap_or(u32::MAX);
    let progress = Progress::new(py, progress)?;
    let counts = progress.counts();
    let work = move |cancel| {
        let progress = Cancellable {
            progress: move |done: usize, total: usize| counts.set(done as u64, total as u64),
            cancel,
        };
        Lut::compute(&spec, &progress)
    };
    let table = crate::engine::interruptible_ticking(py, work, progress.ticker())?
        .map_err(|e| bad(e.to_string()))?;
    progress.close(py)?;
    let mut shape: Vec<usize> = table.dims();
    shape.push(table.channels.len());
    let values = PyArray1::from_slice(py, &table.values)
        .into_any()
        .call_method1("reshape", (shape,))?;
    let axes: Vec<&str> = table.axes.iter().map(|a| a.name).collect();
    let tuple_of = |xs: Vec<PyObject>| -> PyResult<PyObject> {
        Ok(pyo3::types::PyTuple::new(py, xs)?.into_any().unbind())
    };
    let coords = table
        .axes
        .iter()
        .map(|a| PyArray1::from_slice(py, &a.coords).into_any().unbind())
        .collect();
    let params = table
        .axes
        .iter()
        .map(|a| PyArray1::from_slice(py, &a.params).into_any().unbind())
        .collect();
    named(
        py,
        "Lut",
        vec![
            pyo3::types::PyTuple::new(py, axes)?.into_any().unbind(),
            tuple_of(coords)?,
            tuple_of(params)?,
            pyo3::types::PyTuple::new(py, table.channels)?
                .into_any()
                .unbind(),
            values.unbind(),
        ],
    )
}

/// Adds `AlbedoTable`, `single_scattering_albedo`, `table` and `read_table` to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(table, m)?)?;
    m.add_function(wrap_pyfunction!(read_table, m)?)?;
    m.add_function(wrap_pyfunction!(lut, m)?)?;
    m.add_class::<AlbedoTable>()?;
    m.add_function(wrap_pyfunction!(single_scattering_albedo, m)?)?;
    Ok(())
}
