//! Python bindings of `microfacet` (issue 23, first part): every NDF as a class with its
//! quantities vectorised over NumPy arrays.
//!
//! The arrays are converted and broadcast by NumPy itself (`numpy.asarray`,
//! `numpy.broadcast_arrays`, in C); the loop over the elements is Rust's, with the GIL
//! released, on every core (rayon) above 16 384 elements. float32 input gives float32 output
//! (the f64 value rounded once), anything else float64; all-scalar input gives a NumPy scalar.

use microfacet::{AnyNdf, Ndf, NdfKind};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::sync::GILOnceCell;
use pyo3::types::{PyFloat, PyInt};
use rayon::prelude::*;

/// Above this many elements the loop runs on rayon's pool.
const PARALLEL: usize = 1 << 14;

/// `f` over the elements of the arguments (broadcast together), as the module docs say.
fn apply<'py, const K: usize>(
    py: Python<'py>,
    args: [&Bound<'py, PyAny>; K],
    f: impl Fn([f64; K]) -> f64 + Sync,
) -> PyResult<PyObject> {
    // Python floats, NumPy float64 scalars (a float subclass) and ints only: no array, the
    // value as a NumPy float64 scalar, as a ufunc returns (0.13 µs a call against ~2.5 µs
    // through the array path's NumPy calls).
    if args
        .iter()
        .all(|a| a.is_instance_of::<PyFloat>() || a.is_exact_instance_of::<PyInt>())
    {
        let mut x = [0.0; K];
        for (x, a) in x.iter_mut().zip(args) {
            *x = a.extract::<f64>()?;
        }
        return Ok(float64(py)?.call1((f(x),))?.unbind());
    }
    let np = py.import("numpy")?;
    let float64 = np.getattr("float64")?;
    let float32 = np.getattr("float32")?;
    let (mut f32, mut scalar) = (true, true);
    let mut wide = Vec::with_capacity(K);
    for x in args {
        let a = np.call_method1("asarray", (x,))?;
        f32 &= a.getattr("dtype")?.eq(&float32)?;
        scalar &= a.getattr("ndim")?.extract::<usize>()? == 0;
        // (No copy for float64 input.)
        let kwargs = pyo3::types::PyDict::new(py);
        kwargs.set_item("copy", false)?;
        wide.push(a.call_method("astype", (&float64,), Some(&kwargs))?);
    }
    // Broadcast by NumPy's rules (and errors), then flat contiguous copies.
    let views: Vec<Bound<'py, PyAny>> = if K == 1 {
        wide
    } else {
        np.call_method1("broadcast_arrays", pyo3::types::PyTuple::new(py, wide)?)?
            .try_iter()?
            .collect::<PyResult<_>>()?
    };
    let shape = views[0].getattr("shape")?;
    let flat: Vec<Bound<'py, PyArray1<f64>>> = views
        .iter()
        .map(|v| {
            Ok(np
                .call_method1("ascontiguousarray", (v,))?
                .call_method1("reshape", (-1,))?
                .downcast_into::<PyArray1<f64>>()?)
        })
        .collect::<PyResult<_>>()?;
    let readonly: Vec<_> = flat.iter().map(|a| a.readonly()).collect();
    let slices: Vec<&[f64]> = readonly
        .iter()
        .map(|r| r.as_slice())
        .collect::<Result<_, _>>()?;
    let n = slices[0].len();
    let at = |i: usize| f(std::array::from_fn(|k| slices[k][i]));
    let values: Vec<f64> = py.allow_threads(|| {
        if n >= PARALLEL {
            (0..n).into_par_iter().map(at).collect()
        } else {
            (0..n).map(at).collect()
        }
    });
    let mut out = PyArray1::from_vec(py, values)
        .into_any()
        .call_method1("reshape", (shape,))?;
    if f32 {
        out = out.call_method1("astype", (float32,))?;
    }
    if scalar {
        // (A NumPy scalar, as a ufunc gives for scalar input.)
        out = out.get_item(())?;
    }
    Ok(out.unbind())
}

/// numpy.float64, looked up once.
fn float64(py: Python<'_>) -> PyResult<&Bound<'_, PyAny>> {
    static FLOAT64: GILOnceCell<PyObject> = GILOnceCell::new();
    Ok(FLOAT64
        .get_or_try_init(py, || {
            Ok::<_, PyErr>(py.import("numpy")?.getattr("float64")?.unbind())
        })?
        .bind(py))
}

fn value_error(e: microfacet::ParamError) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// A microfacet NDF of the library (the base class of ``GGX``, ``Beckmann``, ``GTR``, ...).
///
/// Conventions (the crate's): u = cos θ of the microfacet normal (D) or of a direction (Λ, σ,
/// G1, G2); slopes (p, q) = −(x, y)/z of the normal. D is normalised so that the projected
/// area of the microsurface is 1: ∫ D(m) cos θm dm = 1; D(u) = 0 for u ≤ 0. Values are the
/// library's exact f64 path: closed forms to ≤ 1e-13 relative, numerical quantities (the
/// family's Λ by quadrature, Bessel-K, the generalised exponential) to ≤ 1e-10, measured
/// against mpmath (the crate's tests and README).
#[pyclass(subclass, module = "microfacet")]
pub struct NDF {
    ndf: AnyNdf,
}

impl NDF {
    fn build(kind: NdfKind, alpha: f64, shape: Option<f64>) -> PyResult<Self> {
        Ok(NDF {
            ndf: AnyNdf::new(kind, alpha, shape).map_err(value_error)?,
        })
    }
}

#[pymethods]
impl NDF {
    /// The roughness α.
    #[getter]
    fn alpha(&self) -> f64 {
        self.ndf.alpha()
    }

    /// The shape parameter (γ of GTR, Student-T and the generalised exponential, a of
    /// Bessel-K), or None.
    #[getter]
    fn shape(&self) -> Option<f64> {
        self.ndf.shape()
    }

    /// The NDF's name, as the command line spells it (``ggx``, ``student_t``, ...).
    #[getter]
    fn name(&self) -> &'static str {
        self.ndf.kind().name()
    }

    fn __repr__(&self) -> String {
        match self.ndf.shape() {
            Some(s) => format!(
                "microfacet.NDF({}, alpha={}, shape={s})",
                self.name(),
                self.alpha()
            ),
            None => format!("microfacet.NDF({}, alpha={})", self.name(), self.alpha()),
        }
    }

    /// D(u): the density of microfacet normals per solid angle at u = cos θm (0 for u ≤ 0;
    /// +∞ at u = 1 for the NDFs with a pole there: Ei, Erfc, K0, Bessel-K a ≤ 1).
    fn d(&self, py: Python<'_>, u: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        let n = self.ndf;
        apply(py, [u], move |[u]| n.d(u))
    }

    /// Smith's Λ(u) of a direction at u = cos θ (Λ(|u|) for u < 0; +∞ at u = 0; 0 at 1).
    /// (``lambda`` is a Python keyword.)
    fn lambda_(&self, py: Python<'_>, u: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        let n = self.ndf;
        apply(py, [u], move |[u]| n.lambda(u))
    }

    /// The projected area σ(u) = ∫ max(0, ω·m) D(m) dm of a direction at signed u = cos θ
    /// (σ(u) = u(1 + Λ(u)) above the horizon, |u| Λ(|u|) below; σ(0) finite).
    fn sigma(&self, py: Python<'_>, u: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        let n = self.ndf;
        apply(py, [u], move |[u]| n.sigma(u))
    }

    /// Smith's masking G1(u) = 1/(1 + Λ(|u|)).
    fn g1(&self, py: Python<'_>, u: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        let n = self.ndf;
        apply(py, [u], move |[u]| n.g1(u))
    }

    /// Height-correlated masking-shadowing G2(u_o, u_i) = 1/(1 + Λ(u_o) + Λ(u_i)) (Heitz
    /// 2014), broadcast over both arguments.
    fn g2(
        &self,
        py: Python<'_>,
        u_o: &Bound<'_, PyAny>,
        u_i: &Bound<'_, PyAny>,
    ) -> PyResult<PyObject> {
        let n = self.ndf;
        apply(py, [u_o, u_i], move |[a, b]| n.g2(a, b))
    }

    /// Separable masking-shadowing G1(u_o) G1(u_i), broadcast over both arguments.
    fn g2_separable(
        &self,
        py: Python<'_>,
        u_o: &Bound<'_, PyAny>,
        u_i: &Bound<'_, PyAny>,
    ) -> PyResult<PyObject> {
        let n = self.ndf;
        apply(py, [u_o, u_i], move |[a, b]| n.g2_separable(a, b))
    }

    /// The slope density P22(p, q) = D(u) u⁴ (u = 1/√(1 + p² + q²)), broadcast over p and q.
    fn p22(
        &self,
        py: Python<'_>,
        p: &Bound<'_, PyAny>,
        q: &Bound<'_, PyAny>,
    ) -> PyResult<PyObject> {
        let n = self.ndf;
        apply(py, [p, q], move |[p, q]| n.p22(p, q))
    }

    /// The marginal slope density P2(p) = ∫ P22(p, q) dq.
    fn p2(&self, py: Python<'_>, p: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        let n = self.ndf;
        apply(py, [p], move |[p]| n.p2(p))
    }
}

/// The classes of the NDFs without a shape parameter: `Name(alpha)`.
macro_rules! plain {
    ($($(#[$doc:meta])* $name:ident => $kind:ident;)*) => {$(
        $(#[$doc])*
        #[pyclass(extends = NDF, module = "microfacet")]
        pub struct $name;

        #[pymethods]
        impl $name {
            #[new]
            fn new(alpha: f64) -> PyResult<(Self, NDF)> {
                Ok(($name, NDF::build(NdfKind::$kind, alpha, None)?))
            }
        }
    )*};
}

/// The classes of the NDFs with a shape parameter: `Name(alpha, shape)`.
macro_rules! shaped {
    ($($(#[$doc:meta])* $name:ident => $kind:ident, $shape:ident;)*) => {$(
        $(#[$doc])*
        #[pyclass(extends = NDF, module = "microfacet")]
        pub struct $name;

        #[pymethods]
        impl $name {
            #[new]
            fn new(alpha: f64, $shape: f64) -> PyResult<(Self, NDF)> {
                Ok(($name, NDF::build(NdfKind::$kind, alpha, Some($shape))?))
            }
        }
    )*};
}

plain! {
    /// Beckmann(alpha): D = e^{−tan²θ/α²}/(π α² cos⁴θ), α ∈ [1e-6, 1e6].
    Beckmann => Beckmann;
    /// GGX(alpha) (Trowbridge–Reitz): D = α²/(π cos⁴θ (α² + tan²θ)²), α ∈ [1e-6, 1e6].
    GGX => Ggx;
    /// DoubleGGX(alpha): d'Eon's Double GGX NDF (a Gamma-1 mixture of GGX).
    DoubleGGX => DoubleGgx;
    /// Exponential(alpha): d'Eon's Exponential NDF, P22 = 2 e^{−2r/α}/(π α²).
    Exponential => Exponential;
    /// Ei(alpha): P22 = E₁(r²/α²)/(π α²) (a uniform mixture of Beckmann in β²).
    Ei => Ei;
    /// Erfc(alpha): P22 = erfc(r/α)/(2√π α r) (a uniform mixture of Beckmann in β).
    Erfc => Erfc;
    /// K0(alpha): P22 = 2 K₀(2r/α)/(π α²) (Bessel-K at a = 1).
    K0 => K0;
}

shaped! {
    /// GTR(alpha, gamma): Burley's generalised Trowbridge–Reitz, γ ∈ (0, 100] (γ = 2 is GGX).
    GTR => Gtr, gamma;
    /// StudentT(alpha, gamma): Ribardière et al. 2017, γ > 1 (Λ, σ finite for γ > 3/2; GGX
    /// at γ = 2, Beckmann as γ → ∞).
    StudentT => StudentT, gamma;
    /// BesselK(alpha, a): P22 = (2/(π α² Γ(a))) x^{a−1} K_{a−1}(2x), x = r/α, a ∈ [0.1, 100]
    /// (K0 at a = 1, the Exponential NDF at a = 3/2).
    BesselK => BesselK, a;
    /// GenExponential(alpha, gamma): P22 ∝ e^{−(r/α)^γ}, γ ∈ [0.1, 20] (Beckmann at γ = 2).
    GenExponential => GenExponential, gamma;
}

#[pymodule]
fn _microfacet(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<NDF>()?;
    m.add_class::<Beckmann>()?;
    m.add_class::<GGX>()?;
    m.add_class::<DoubleGGX>()?;
    m.add_class::<Exponential>()?;
    m.add_class::<Ei>()?;
    m.add_class::<Erfc>()?;
    m.add_class::<K0>()?;
    m.add_class::<GTR>()?;
    m.add_class::<StudentT>()?;
    m.add_class::<BesselK>()?;
    m.add_class::<GenExponential>()?;
    Ok(())
}
