//! Parameters as arrays, SciPy's frozen distributions' way: every
//! parameter of a class (α, αy, γ or a; η and k of the BSDFs) is a number or an array. The
//! arrays broadcast with each other when the object is built (a shape error names each
//! parameter's shape, a bad element its index) and, in every method, with the method's
//! arguments as one more argument each (core 0): one material per element, built from the
//! element's parameters in the loop, never a Python loop. Where consecutive elements share
//! their parameters (parameters (n, 1) against arguments (m,)), the material of the last one
//! is reused ([`Recent`]: one per thread), so a GTR or family fit is made once per distinct
//! material, not per element.

use crate::engine::numpy;
use microsurface::ParamError;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use std::cell::RefCell;

/// One parameter as given: a number, or a float64 array of its own shape (a copy, read-only:
/// the object is immutable).
#[derive(Debug)]
pub enum Param {
    Num(f64),
    Arr(Py<PyAny>),
}

impl Clone for Param {
    fn clone(&self) -> Self {
        match self {
            Param::Num(x) => Param::Num(*x),
            Param::Arr(a) => Python::with_gil(|py| Param::Arr(a.clone_ref(py))),
        }
    }
}

impl Param {
    /// `x` as a parameter: a Python number or a 0-d array is a number; anything else NumPy
    /// converts to a float64 array (copied, made read-only). ValueError naming `name` for what
    /// is neither.
    pub fn new(py: Python<'_>, x: &Bound<'_, PyAny>, name: &str) -> PyResult<Param> {
        if crate::engine::is_number(x) {
            return Ok(Param::Num(x.extract::<f64>()?));
        }
        let np = numpy(py)?;
        // (Real numbers only, as the arguments: "0.3" and complex values raise TypeError
        // rather than being parsed or losing their imaginary part.)
        // (One conversion: the float64 copy below is made from this array when there is one.)
        let raw = np.call_method1("asarray", (x,)).ok();
        let kind: String = raw
            .as_ref()
            .and_then(|a| {
                a.getattr("dtype")
                    .ok()?
                    .getattr("kind")
                    .ok()?
                    .extract()
                    .ok()
            })
            .unwrap_or_default();
        if matches!(kind.as_str(), "U" | "S" | "c" | "O" | "V" | "M" | "m") {
            return Err(pyo3::exceptions::PyTypeError::new_err(format!(
                "{name} must be a real number or an array of real numbers"
            )));
        }
        let a = np
            .call_method1("array", (raw.as_ref().unwrap_or(x), "float64"))
            .map_err(|e| {
                PyValueError::new_err(format!(
                    "{name} must be a number or an array of numbers ({e})"
                ))
            })?;
        if a.getattr("ndim")?.extract::<usize>()? == 0 {
            return Ok(Param::Num(a.call_method0("item")?.extract()?));
        }
        a.getattr("flags")?.setattr("writeable", false)?;
        Ok(Param::Arr(a.unbind()))
    }

    /// The number, if it is one.
    pub fn num(&self) -> Option<f64> {
        match self {
            Param::Num(x) => Some(*x),
            Param::Arr(_) => None,
        }
    }

    /// As a Python object (a float or the array), for `__reduce__` and the engine.
    pub fn object<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(match self {
            Param::Num(x) => x.into_pyobject(py)?.into_any(),
            Param::Arr(a) => a.bind(py).clone(),
        })
    }

    /// Its shape (`()` for a number).
    pub fn shape(&self, py: Python<'_>) -> PyResult<Vec<usize>> {
        match self {
            Param::Num(_) => Ok(Vec::new()),
            Param::Arr(a) => a.bind(py).getattr("shape")?.extract(),
        }
    }

    /// As the constructor call takes it back: Python's repr of a float (exact), or
    /// `np.array([...])` of the array's nested lists (each float's repr: exact), evaluable under
    /// `import numpy as np`.
    pub fn repr(&self, py: Python<'_>) -> PyResult<String> {
        match self {
            Param::Num(x) => Ok(x.into_pyobject(py)?.repr()?.to_string()),
            Param::Arr(a) => Ok(format!(
                "np.array({})",
                a.bind(py).call_method0("tolist")?.repr()?
            )),
        }
    }

    /// Equal values: the same number (by its bits), or arrays of the same shape and values.
    pub fn same(&self, py: Python<'_>, other: &Param) -> PyResult<bool> {
        match (self, other) {
            (Param::Num(a), Param::Num(b)) => Ok(a.to_bits() == b.to_bits()),
            (Param::Arr(a), Param::Arr(b)) => numpy(py)?
                .call_method1("array_equal", (a.bind(py), b.bind(py)))?
                .is_truthy(),
            _ => Ok(false),
        }
    }

    /// What `hash` reads: the number's bits, or the array's shape and bytes.
    pub fn hash_key(&self, py: Python<'_>) -> PyResult<(Vec<usize>, Vec<u8>)> {
        match self {
            Param::Num(x) => Ok((Vec::new(), x.to_bits().to_le_bytes().to_vec())),
            Param::Arr(a) => Ok((
                self.shape(py)?,
                a.bind(py).call_method0("tobytes")?.extract()?,
            )),
        }
    }
}

/// The broadcast shape of the array parameters among `named` (None where every one is a
/// number); ValueError listing each parameter's shape where they do not broadcast.
pub fn broadcast(py: Python<'_>, named: &[(&str, &Param)]) -> PyResult<Option<Vec<usize>>> {
    let arrays: Vec<(&str, Vec<usize>)> = named
        .iter()
        .filter(|(_, p)| matches!(p, Param::Arr(_)))
        .map(|(n, p)| Ok((*n, p.shape(py)?)))
        .collect::<PyResult<_>>()?;
    if arrays.is_empty() {
        return Ok(None);
    }
    let shapes = PyTuple::new(
        py,
        arrays
            .iter()
            .map(|(_, s)| PyTuple::new(py, s))
            .collect::<PyResult<Vec<_>>>()?,
    )?;
    match numpy(py)?.call_method1("broadcast_shapes", shapes) {
        Ok(s) => Ok(Some(s.extract()?)),
        Err(_) => {
            let list: Vec<String> = arrays
                .iter()
                .map(|(n, s)| Ok(format!("{n} {}", PyTuple::new(py, s)?.repr()?)))
                .collect::<PyResult<_>>()?;
            Err(PyValueError::new_err(format!(
                "the parameters' shapes do not broadcast together: {}",
                list.join(", ")
            )))
        }
    }
}

/// Every element of the parameters `named` (broadcast to `shape`) through `check`, which
/// takes one value per parameter in their order: the first element it refuses raises
/// ValueError with its index and the library's message.
pub fn validate(
    py: Python<'_>,
    named: &[(&str, &Param)],
    shape: &[usize],
    check: impl Fn(&[f64]) -> Result<(), ParamError>,
) -> PyResult<()> {
    let np = numpy(py)?;
    let full = PyTuple::new(py, shape)?;
    let flats: Vec<Vec<f64>> = named
        .iter()
        .map(|(_, p)| {
            let b = np.call_method1("broadcast_to", (p.object(py)?, &full))?;
            np.call_method1("ravel", (b,))?
                .call_method0("tolist")?
                .extract::<Vec<f64>>()
        })
        .collect::<PyResult<_>>()?;
    let n: usize = shape.iter().product();
    let mut v = vec![0.0; named.len()];
    let mut first = None;
    let mut bad = 0usize;
    for i in 0..n {
        for (x, f) in v.iter_mut().zip(&flats) {
            *x = f[i];
        }
        if let Err(e) = check(&v) {
            bad += 1;
            first.get_or_insert((i, e, v.clone()));
        }
    }
    if let Some((i, e, v)) = first {
        let index: Vec<String> = np
            .call_method1("unravel_index", (i, &full))?
            .extract::<Vec<usize>>()?
            .iter()
            .map(usize::to_string)
            .collect();
        let values: Vec<String> = named
            .iter()
            .zip(&v)
            .map(|((name, _), x)| Ok(format!("{name} = {}", x.into_pyobject(py)?.repr()?)))
            .collect::<PyResult<_>>()?;
        let arrays: Vec<&str> = named
            .iter()
            .filter(|(_, p)| matches!(p, Param::Arr(_)))
            .map(|(name, _)| *name)
            .collect();
        return Err(PyValueError::new_err(format!(
            "{e}: {bad} of {n} elements of {} are not valid (the first: [{}], {})",
            arrays.join(" and "),
            index.join(", "),
            values.join(", ")
        )));
    }
    Ok(())
}

/// The value most recently built for a key, one per thread: the materials of consecutive
/// elements with the same parameters are built once.
pub struct Recent<K: 'static, V: 'static>(&'static std::thread::LocalKey<RefCell<Option<(K, V)>>>);

impl<K: PartialEq + 'static, V: 'static> Recent<K, V> {
    pub const fn new(cell: &'static std::thread::LocalKey<RefCell<Option<(K, V)>>>) -> Self {
        Recent(cell)
    }

    /// `f` of the value for `key`: this thread's last one if its key equals `key`, else
    /// `make`'s, kept.
    pub fn with<R, E>(
        &self,
        key: K,
        make: impl FnOnce() -> Result<V, E>,
        f: impl FnOnce(&V) -> R,
    ) -> Result<R, E> {
        self.0.with(|cell| {
            let mut slot = cell.borrow_mut();
            match &*slot {
                Some((k, v)) if *k == key => return Ok(f(v)),
                _ => {}
            }
            let v = make()?;
            let r = f(&v);
            *slot = Some((key, v));
            Ok(r)
        })
    }
}

/// The parameter arrays of an object, as the engine's arguments: each with its name, in the
/// object's order (the numbers are left out: the loop reads them from the object).
pub type Arrays<'py> = Vec<(Bound<'py, PyAny>, &'static str)>;

/// `items` (a method's arguments) followed by the parameter arrays `arrays` (core 0, any
/// value: validated when the object was built), so that the engine broadcasts them together.
pub fn with_arrays<'a, 'py>(
    items: &[crate::engine::Item<'a, 'py>],
    arrays: &'a Arrays<'py>,
) -> Vec<crate::engine::Item<'a, 'py>> {
    let mut all = items.to_vec();
    all.extend(
        arrays
            .iter()
            .map(|(a, name)| (a, 0, *name, crate::engine::FIXED)),
    );
    all
}
