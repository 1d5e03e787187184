//! The vectorising engine every method goes through: NumPy broadcasting of the arguments
//! (with core axes: a direction is the last axis of length 3, a pair of uniforms of length
//! 2), the loop over the elements in Rust without the GIL (rayon above a size), Ctrl-C
//! between chunks, and the outputs shaped and typed as NumPy's ufuncs would.
//!
//! Rules: every argument is converted by `numpy.asarray`; the batch shapes (the shapes
//! without the core axes) broadcast by `numpy.broadcast_shapes`. If every argument is
//! float32, the outputs are float32 (each value the f64 result rounded once), else float64.
//! If the broadcast batch shape is `()`, an output without a core axis is a NumPy scalar (as
//! a ufunc gives for scalars). One element given as Python numbers and lists, tuples or 1-D
//! float64 arrays of the core lengths skips NumPy altogether ([`run_single`]: the same
//! values and types, 20–30× less time a call).
//!
//! The methods call the front ends at the end of the file: [`apply`] (numbers broadcast
//! together, the functions of a cosine), [`apply_vec`] and [`map_vec`] (directions and
//! uniforms with their core axes), and build the package's named tuples with [`named`].

use microsurface::ParamError;
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::sync::GILOnceCell;
use pyo3::types::{PyDict, PySlice, PyTuple};
use rayon::prelude::*;
use std::time::{Duration, Instant};

/// A Python float (NumPy's float64 scalar is one), or an int: the scalar paths' input, which
/// needs no array.
pub fn is_number(a: &Bound<'_, PyAny>) -> bool {
    use pyo3::types::{PyFloat, PyInt};
    a.is_instance_of::<PyFloat>() || a.is_exact_instance_of::<PyInt>()
}

/// numpy, imported once.
pub fn numpy(py: Python<'_>) -> PyResult<&Bound<'_, PyAny>> {
    static NUMPY: GILOnceCell<PyObject> = GILOnceCell::new();
    Ok(NUMPY
        .get_or_try_init(py, || {
            Ok::<_, PyErr>(py.import("numpy")?.into_any().unbind())
        })?
        .bind(py))
}

/// numpy.float64, looked up once.
pub fn float64(py: Python<'_>) -> PyResult<&Bound<'_, PyAny>> {
    static FLOAT64: GILOnceCell<PyObject> = GILOnceCell::new();
    Ok(FLOAT64
        .get_or_try_init(py, || {
            Ok::<_, PyErr>(numpy(py)?.getattr("float64")?.unbind())
        })?
        .bind(py))
}

/// The library's typed error as Python's ValueError, with its message.
pub fn value_error(e: ParamError) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// The arguments of one call, broadcast: flat float64 arrays (contiguous; no copy for
/// contiguous float64 input of the broadcast shape).
pub struct Args<'py> {
    arrays: Vec<PyReadonlyArray1<'py, f64>>,
    /// The broadcast batch shape.
    batch: Vec<usize>,
    /// The number of elements (the product of `batch`).
    n: usize,
    /// Whether every argument was float32.
    f32: bool,
}

impl<'py> Args<'py> {
    /// `items`: (the argument, its core length (0: one number per element), its name).
    pub fn new(py: Python<'py>, items: &[(&Bound<'py, PyAny>, usize, &str)]) -> PyResult<Self> {
        let np = numpy(py)?;
        let float32 = np.getattr("float32")?;
        let mut f32 = true;
        let mut wide = Vec::with_capacity(items.len());
        let mut batches = Vec::with_capacity(items.len());
        for &(x, core, name) in items {
            let a = np.call_method1("asarray", (x,))?;
            f32 &= a.getattr("dtype")?.eq(&float32)?;
            let shape: Vec<usize> = a.getattr("shape")?.extract()?;
            if core > 0 && shape.last() != Some(&core) {
                return Err(PyValueError::new_err(format!(
                    "{name} must have a last axis of length {core} (got shape {shape:?})"
                )));
            }
            // (A core is one trailing axis.)
            batches.push(PyTuple::new(
                py,
                &shape[..shape.len() - usize::from(core > 0)],
            )?);
            let kwargs = PyDict::new(py);
            kwargs.set_item("copy", false)?;
            wide.push(a.call_method("astype", (float64(py)?,), Some(&kwargs))?);
        }
        let batch: Vec<usize> = np
            .call_method1("broadcast_shapes", PyTuple::new(py, batches)?)?
            .extract()?;
        let n = batch.iter().product();
        let mut arrays = Vec::with_capacity(items.len());
        for (a, &(_, core, _)) in wide.into_iter().zip(items) {
            let mut full = batch.clone();
            if core > 0 {
                full.push(core);
            }
            let b = np.call_method1("broadcast_to", (a, PyTuple::new(py, &full)?))?;
            let flat = np
                .call_method1("ascontiguousarray", (b,))?
                .call_method1("reshape", (-1,))?
                .downcast_into::<PyArray1<f64>>()?;
            arrays.push(flat.readonly());
        }
        Ok(Args {
            arrays,
            batch,
            n,
            f32,
        })
    }

    /// The flat data of argument k.
    pub fn slice(&self, k: usize) -> PyResult<&[f64]> {
        Ok(self.arrays[k].as_slice()?)
    }

    /// Run `f(i, out)` for every element i (out: `width` numbers), and shape the outputs:
    /// `outs` lists each output's core length (0: one number per element), in the order
    /// they lie in `out`. `parallel`: from how many elements rayon's pool is used.
    pub fn run(
        &self,
        py: Python<'py>,
        width: usize,
        outs: &[usize],
        parallel: usize,
        f: impl Fn(usize, &mut [f64]) -> Result<(), ParamError> + Sync,
    ) -> PyResult<Vec<PyObject>> {
        let data = compute(py, self.n, width, parallel, f)?;
        self.shape(py, data.into_any(), width, outs)
    }

    /// The same over blocks of `block` elements: `f(start, out)` fills out (block × width
    /// numbers, the last block shorter) for the elements from `start` (slice kernels).
    pub fn run_blocks(
        &self,
        py: Python<'py>,
        width: usize,
        outs: &[usize],
        block: usize,
        parallel: usize,
        f: impl Fn(usize, &mut [f64]) -> Result<(), ParamError> + Sync,
    ) -> PyResult<Vec<PyObject>> {
        let data = compute_blocks(py, self.n, width, block, parallel, f)?;
        self.shape(py, data.into_any(), width, outs)
    }

    /// The outputs of `data` (n × width, row-major), as [`Args::run`] says.
    fn shape(
        &self,
        py: Python<'py>,
        all: Bound<'py, PyAny>,
        width: usize,
        outs: &[usize],
    ) -> PyResult<Vec<PyObject>> {
        let np = numpy(py)?;
        let mut result = Vec::with_capacity(outs.len());
        let mut offset = 0;
        for &core in outs {
            let mut full = self.batch.clone();
            if core > 0 {
                full.push(core);
            }
            let mut out = if outs.len() == 1 {
                all.call_method1("reshape", (PyTuple::new(py, &full)?,))?
            } else {
                // Columns offset..offset + core of the (n, width) block, then contiguous.
                let rows = all.call_method1("reshape", ((self.n, width),))?;
                let cols = if core == 0 {
                    rows.get_item((py.Ellipsis(), offset))?
                } else {
                    let s = PySlice::new(py, offset as isize, (offset + core) as isize, 1);
                    rows.get_item((py.Ellipsis(), s))?
                };
                np.call_method1("ascontiguousarray", (cols,))?
                    .call_method1("reshape", (PyTuple::new(py, &full)?,))?
            };
            if self.f32 {
                out = out.call_method1("astype", (np.getattr("float32")?,))?;
            }
            if full.is_empty() {
                out = out.get_item(())?;
            }
            result.push(out.unbind());
            offset += core.max(1);
        }
        Ok(result)
    }
}

/// `f(i, out)` for i < n into an n × width block: [`compute_blocks`] one element at a time.
pub fn compute(
    py: Python<'_>,
    n: usize,
    width: usize,
    parallel: usize,
    f: impl Fn(usize, &mut [f64]) -> Result<(), ParamError> + Sync,
) -> PyResult<Bound<'_, PyArray1<f64>>> {
    compute_blocks(py, n, width, 1, parallel, |start, out| {
        out.chunks_mut(width)
            .enumerate()
            .try_for_each(|(k, o)| f(start + k, o))
    })
}

/// `f(start, out)` over blocks of `block` elements (the last one shorter) into an n × width
/// array: chunks of blocks that grow while they take under 50 ms, the signals checked
/// (Ctrl-C raises KeyboardInterrupt) after each chunk, the GIL released meanwhile, rayon's
/// pool from `parallel` elements a chunk. The first error stops the loop.
pub fn compute_blocks(
    py: Python<'_>,
    n: usize,
    width: usize,
    block: usize,
    parallel: usize,
    f: impl Fn(usize, &mut [f64]) -> Result<(), ParamError> + Sync,
) -> PyResult<Bound<'_, PyArray1<f64>>> {
    compute_blocks_of(py, n, width, block, parallel, "float64", f)
}

/// [`compute_blocks`] into an array of T (`dtype` its NumPy name).
pub fn compute_blocks_of<'py, T: numpy::Element + Send>(
    py: Python<'py>,
    n: usize,
    width: usize,
    block: usize,
    parallel: usize,
    dtype: &str,
    f: impl Fn(usize, &mut [T]) -> Result<(), ParamError> + Sync,
) -> PyResult<Bound<'py, PyArray1<T>>> {
    let out = empty::<T>(py, n * width, dtype)?;
    let mut rw = out.readwrite();
    let data = rw.as_slice_mut()?;
    if width == 0 || n == 0 {
        drop(rw);
        return Ok(out);
    }
    // (Slice kernels (blocks): 2^20 elements, about a millisecond, before the first check:
    // each check takes the GIL back and ends a rayon join, ~20 µs, which at 0.1 ns an element
    // doubled a float32 call over 10⁶ elements when it came every 2^16. Other cheap elements:
    // 2^16; expensive ones (walks, quadratures: a small `parallel`) one per thread.)
    let mut chunk = if block > 1 {
        1 << 20
    } else if parallel >= 1024 {
        1 << 16
    } else {
        rayon::current_num_threads()
    };
    let mut start = 0;
    let result: PyResult<()> = py.allow_threads(|| {
        while start < n {
            let end = (start + chunk).min(n);
            let t = Instant::now();
            let rows = &mut data[start * width..end * width];
            let r: Result<(), ParamError> = if end - start >= parallel {
                rows.par_chunks_mut(block * width)
                    .enumerate()
                    .try_for_each(|(k, out)| f(start + k * block, out))
            } else {
                rows.chunks_mut(block * width)
                    .enumerate()
                    .try_for_each(|(k, out)| f(start + k * block, out))
            };
            r.map_err(value_error)?;
            start = end;
            if start < n {
                Python::with_gil(|py| py.check_signals())?;
                if t.elapsed() < Duration::from_millis(50) {
                    chunk = chunk.saturating_mul(2);
                }
            }
        }
        Ok(())
    });
    drop(rw);
    result.map(|()| out)
}

/// An uninitialised NumPy array of n elements (`numpy.empty`: NumPy's allocator, which
/// reuses freed blocks, where a zeroed Rust vector of megabytes takes fresh pages and their
/// faults, ~0.05 ns an element); every element is written before it is returned.
pub fn empty<'py, T: numpy::Element>(
    py: Python<'py>,
    n: usize,
    dtype: &str,
) -> PyResult<Bound<'py, PyArray1<T>>> {
    Ok(numpy(py)?
        .call_method1("empty", (n, dtype))?
        .downcast_into::<PyArray1<T>>()?)
}

/// A uniform source: an array of uniforms (last axis `k`), or a `numpy.random.Generator`
/// from which n × k (or k, without n) uniforms are drawn.
pub fn uniforms<'py>(
    py: Python<'py>,
    u: &Bound<'py, PyAny>,
    n: Option<usize>,
    k: usize,
) -> PyResult<Bound<'py, PyAny>> {
    static GENERATOR: GILOnceCell<PyObject> = GILOnceCell::new();
    let generator = GENERATOR
        .get_or_try_init(py, || {
            Ok::<_, PyErr>(numpy(py)?.getattr("random")?.getattr("Generator")?.unbind())
        })?
        .bind(py);
    if u.is_instance(generator)? {
        return match n {
            Some(n) => u.call_method1("random", ((n, k),)),
            None => u.call_method1("random", (k,)),
        };
    }
    if n.is_some() {
        return Err(PyValueError::new_err(
            "n is the number of samples to draw from a numpy.random.Generator; an array of uniforms says it by its shape",
        ));
    }
    Ok(u.clone())
}

/// One element given without a batch, read without NumPy's conversions: every argument a
/// Python number (core 0) or a list, tuple or 1-D float64 array of exactly its core length
/// of Python numbers (floats, NumPy float64 scalars, ints); the numbers back to back, or
/// `None` for anything else (batches, float32, other types: the array path decides).
fn single_numbers(items: &[(&Bound<'_, PyAny>, usize, &str)]) -> Option<Vec<f64>> {
    use pyo3::types::PyList;
    let number = |a: &Bound<'_, PyAny>| is_number(a).then(|| a.extract::<f64>().ok())?;
    let mut x = Vec::with_capacity(8);
    for &(a, core, _) in items {
        if core == 0 {
            x.push(number(a)?);
        } else if a.is_instance_of::<PyTuple>() || a.is_instance_of::<PyList>() {
            if a.len().ok()? != core {
                return None;
            }
            for e in a.try_iter().ok()? {
                x.push(number(&e.ok()?)?);
            }
        } else {
            let v = a.downcast::<PyArray1<f64>>().ok()?.try_readonly().ok()?;
            let v = v.as_slice().ok()?;
            if v.len() != core {
                return None;
            }
            x.extend_from_slice(v);
        }
    }
    Some(x)
}

/// [`Args::run`] for one element given without a batch ([`single_numbers`]): `f(0, a, out)`
/// with a the arguments' numbers split by their cores, without the GIL, and the outputs as
/// the array path shapes a batch of `()` (a NumPy float64 scalar for core 0, a float64
/// array of the core's length otherwise). `None` where the arguments are not of that form.
/// About 0.3 µs a call where NumPy's conversions and shaping take ~6 µs (BENCHMARKS.md).
pub fn run_single(
    py: Python<'_>,
    items: &[(&Bound<'_, PyAny>, usize, &str)],
    outs: &[usize],
    f: impl Fn(usize, &[&[f64]], &mut [f64]) -> Result<(), ParamError> + Sync,
) -> PyResult<Option<Vec<PyObject>>> {
    let Some(x) = single_numbers(items) else {
        return Ok(None);
    };
    let width: usize = outs.iter().map(|&c| c.max(1)).sum();
    let mut out = vec![0.0; width];
    let cores: Vec<usize> = items.iter().map(|i| i.1).collect();
    py.allow_threads(|| {
        let mut a: Vec<&[f64]> = Vec::with_capacity(cores.len());
        let mut rest = &x[..];
        for &core in &cores {
            let (head, tail) = rest.split_at(core.max(1));
            a.push(head);
            rest = tail;
        }
        f(0, &a, &mut out)
    })
    .map_err(value_error)?;
    let mut result = Vec::with_capacity(outs.len());
    let mut offset = 0;
    for &core in outs {
        result.push(if core == 0 {
            float64(py)?.call1((out[offset],))?.unbind()
        } else {
            PyArray1::from_slice(py, &out[offset..offset + core])
                .into_any()
                .unbind()
        });
        offset += core.max(1);
    }
    Ok(Some(result))
}

/// `f()` on a thread of its own while this one waits without the GIL, checking the signals
/// every 50 ms: Ctrl-C raises KeyboardInterrupt at once (the computation, which cannot be
/// cut short from outside, finishes in the background and is dropped).
pub fn interruptible<T: Send + 'static>(
    py: Python<'_>,
    f: impl FnOnce() -> T + Send + 'static,
) -> PyResult<T> {
    use std::sync::mpsc::{channel, RecvTimeoutError};
    let (tx, rx) = channel();
    std::thread::spawn(move || {
        // (Fails only when the caller was interrupted and dropped the receiver.)
        let _ = tx.send(f());
    });
    py.allow_threads(move || loop {
        match rx.recv_timeout(Duration::from_millis(50)) {
            Ok(v) => return Ok(v),
            Err(RecvTimeoutError::Timeout) => Python::with_gil(|py| py.check_signals())?,
            Err(RecvTimeoutError::Disconnected) => {
                return Err(pyo3::exceptions::PyRuntimeError::new_err(
                    "the computation failed (a panic in the library: please report it)",
                ))
            }
        }
    })
}

// ---- The front ends of the NDF and BSDF methods: scalar or direction arguments, and the
// package's named tuples.

/// Above this many elements a cheap function's loop runs on rayon's pool.
pub const PARALLEL: usize = 1 << 14;

/// `f` over the elements of scalar arguments broadcast together (the isotropic quantities).
pub fn apply<'py, const K: usize>(
    py: Python<'py>,
    args: [&Bound<'py, PyAny>; K],
    f: impl Fn([f64; K]) -> Result<f64, ParamError> + Sync,
) -> PyResult<PyObject> {
    // Python floats, NumPy float64 scalars (a float subclass) and ints only: no array, the
    // value as a NumPy float64 scalar, as a ufunc returns (0.13 µs a call against ~2.5 µs
    // through the array path's NumPy calls).
    if args.iter().all(|a| is_number(a)) {
        let mut x = [0.0; K];
        for (x, a) in x.iter_mut().zip(args) {
            *x = a.extract::<f64>()?;
        }
        return Ok(float64(py)?.call1((f(x).map_err(value_error)?,))?.unbind());
    }
    let items: Vec<_> = args.iter().map(|&a| (a, 0, "argument")).collect();
    let a = Args::new(py, &items)?;
    let s: Vec<&[f64]> = (0..K).map(|k| a.slice(k)).collect::<PyResult<_>>()?;
    let mut out = a.run(py, 1, &[0], PARALLEL, |i, o| {
        o[0] = f(std::array::from_fn(|k| s[k][i]))?;
        Ok(())
    })?;
    Ok(out.remove(0))
}

/// Direction arguments (core length 3, or 2 for uniforms) to `width` outputs per element.
pub fn apply_vec<'py>(
    py: Python<'py>,
    items: &[(&Bound<'py, PyAny>, usize, &str)],
    outs: &[usize],
    parallel: usize,
    f: impl Fn(usize, &[&[f64]], &mut [f64]) -> Result<(), ParamError> + Sync,
) -> PyResult<Vec<PyObject>> {
    if let Some(o) = run_single(py, items, outs, &f)? {
        return Ok(o);
    }
    let a = Args::new(py, items)?;
    let s: Vec<&[f64]> = (0..items.len())
        .map(|k| a.slice(k))
        .collect::<PyResult<_>>()?;
    let cores: Vec<usize> = items.iter().map(|i| i.1.max(1)).collect();
    let width = outs.iter().map(|&c| c.max(1)).sum();
    a.run(py, width, outs, parallel, |i, o| {
        let e: Vec<&[f64]> = s
            .iter()
            .zip(&cores)
            .map(|(s, &c)| &s[i * c..(i + 1) * c])
            .collect();
        f(i, &e, o)
    })
}

/// One number per element of direction arguments (cheap: rayon from [`PARALLEL`]).
pub fn map_vec<'py>(
    py: Python<'py>,
    items: &[(&Bound<'py, PyAny>, usize, &str)],
    f: impl Fn(&[&[f64]]) -> f64 + Sync,
) -> PyResult<PyObject> {
    let mut o = apply_vec(py, items, &[0], PARALLEL, |_, a, o| {
        o[0] = f(a);
        Ok(())
    })?;
    Ok(o.remove(0))
}

/// A direction argument's three numbers (a core of length 3) as a vector.
pub fn v3(s: &[f64]) -> [f64; 3] {
    [s[0], s[1], s[2]]
}

/// A named tuple of the package (`Sample`, `BSDFSample`, `Albedo`), built from `fields`.
pub fn named<'py>(py: Python<'py>, name: &str, fields: Vec<PyObject>) -> PyResult<PyObject> {
    static TYPES: pyo3::sync::GILOnceCell<PyObject> = pyo3::sync::GILOnceCell::new();
    let types = TYPES.get_or_try_init(py, || {
        Ok::<_, PyErr>(py.import("microsurface._types")?.into_any().unbind())
    })?;
    let cls = types.bind(py).getattr(name)?;
    Ok(cls.call1(pyo3::types::PyTuple::new(py, fields)?)?.unbind())
}
