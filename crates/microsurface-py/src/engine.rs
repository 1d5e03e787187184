//! The vectorising engine every method goes through: NumPy broadcasting of the arguments
//! (with core axes: a direction is the last axis of length 3, a pair of uniforms of length
//! 2), the loop over the elements in Rust without the GIL (rayon above a size), Ctrl-C
//! between chunks, and the outputs shaped and typed as NumPy's ufuncs would.
//!
//! Rules: every argument is converted by `numpy.asarray`; the batch shapes (the shapes
//! without the core axes) broadcast by `numpy.broadcast_shapes`. If every argument is
//! float32 (either byte order; float16, computed in f32, as SciPy's ufuncs do) or a Python
//! float or int (a weak scalar, NumPy 2's NEP 50), and one at least is an array or NumPy
//! scalar, the outputs are float32 (each value the f64 result rounded once), else float64.
//! Strings, complex numbers and objects raise TypeError.
//! If the broadcast batch shape is `()`, an output without a core axis is a NumPy scalar (as
//! a ufunc gives for scalars). One element given as Python numbers and lists, tuples or 1-D
//! float64 arrays of the core lengths skips NumPy altogether ([`run_single`]: the same
//! values and types, 20–30× less time a call).
//!
//! The input contract (issue 36), enforced here for every method: each argument has a
//! [`Domain`]. NaN is in every domain of a value, and an element with a NaN value gives NaN
//! outputs without running the computation; a finite (or infinite) value outside its
//! domain (a cosine outside [−1, 1], a uniform outside [0, 1), an infinite azimuth) raises
//! ValueError naming the argument, with, for an array, how many elements are bad and the
//! first. Parameter arrays (α) raise the library's ValueError, NaN included.
//!
//! The methods call the front ends at the end of the file: [`apply`] (numbers broadcast
//! together, the functions of a cosine), [`apply_vec`] and [`map_vec`] (directions and
//! uniforms with their core axes), and build the package's named tuples with [`named`].

use microsurface::scattering::Cancel;
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

/// What an argument's numbers may be: the input contract's domains (see the module's page).
#[derive(Clone, Copy)]
pub enum Domain<'a> {
    /// Any number, ±∞ included (slopes, the components of directions); NaN gives NaN.
    Any,
    /// A cosine (u, μ): [−1, 1], and within 4ε beyond (a rounded unit vector's cosine, which
    /// the library takes as ±1, as its contract has 1 + 2ε); NaN gives NaN.
    Cosine,
    /// A uniform: [0, 1); NaN gives NaN.
    Uniform,
    /// A finite number (an azimuth); NaN gives NaN.
    Finite,
    /// An object's parameter array (α, γ, η, ...), validated when the object was built: not
    /// checked again, and not counted in the output's dtype (which follows the method's
    /// arguments).
    Fixed(std::marker::PhantomData<&'a ()>),
}

/// The domain of an object's parameter arrays.
pub const FIXED: Domain<'static> = Domain::Fixed(std::marker::PhantomData);

/// The largest |u| a cosine may have: 1 and 4ε beyond (see [`Domain::Cosine`]).
const COSINE_MAX: f64 = 1.0 + 4.0 * f64::EPSILON;

/// Whether a value lies outside a domain, written without branches and false for NaN (which
/// a value may be), so that a pass over an array vectorises: a cosine beyond ±[`COSINE_MAX`],
/// a uniform outside [0, 1), an infinite number.
#[inline(always)]
fn bad_cosine(x: f64) -> bool {
    x.abs() > COSINE_MAX
}
#[inline(always)]
// (Not `!(0.0..1.0).contains(&x)`, which is true for NaN and branches.)
#[allow(clippy::manual_range_contains)]
fn bad_uniform(x: f64) -> bool {
    (x < 0.0) | (x >= 1.0)
}
#[inline(always)]
fn bad_finite(x: f64) -> bool {
    x.abs() == f64::INFINITY
}

/// A float the domain checks read in its own precision (no conversion a lane: float32 arrays
/// are tested four to a vector), each test false for NaN and branch-free.
pub trait Lane: Copy + Sync + Into<f64> {
    /// |x| > m (m representable in Self: 1 + 4ε of the precision, or the largest finite).
    fn abs_gt(self, m: f64) -> bool;
    /// x outside [0, 1).
    fn outside_unit(self) -> bool;
}

impl Lane for f64 {
    #[inline(always)]
    fn abs_gt(self, m: f64) -> bool {
        self.abs() > m
    }
    #[inline(always)]
    fn outside_unit(self) -> bool {
        bad_uniform(self)
    }
}

impl Lane for f32 {
    #[inline(always)]
    fn abs_gt(self, m: f64) -> bool {
        // (m as f32: 1 + 4ε₃₂ exactly; f64::MAX rounds to f32's ∞, which |x| never exceeds, so
        // the finite test is |x| == ∞ there.)
        let m = m as f32;
        if m == f32::INFINITY {
            self.abs() == m
        } else {
            self.abs() > m
        }
    }
    #[inline(always)]
    // (Not `!(0.0..1.0).contains(&x)`, which is true for NaN and branches.)
    #[allow(clippy::manual_range_contains)]
    fn outside_unit(self) -> bool {
        (self < 0.0) | (self >= 1.0)
    }
}

impl Domain<'_> {
    /// Whether x is allowed (for a value: NaN, or in the domain).
    fn ok(&self, x: f64) -> bool {
        match self {
            Domain::Any => true,
            Domain::Cosine => !bad_cosine(x),
            Domain::Uniform => !bad_uniform(x),
            Domain::Finite => !bad_finite(x),
            Domain::Fixed(_) => true,
        }
    }

    /// Whether a NaN of this argument makes the element's outputs NaN.
    fn value(&self) -> bool {
        !matches!(self, Domain::Fixed(_))
    }

    /// Why x is not allowed, for the message (a parameter: the library's whole message).
    fn why(&self) -> String {
        match self {
            Domain::Any => String::new(),
            Domain::Cosine => "must be in [-1, 1]".into(),
            Domain::Uniform => "must be in [0, 1)".into(),
            Domain::Finite => "must be finite".into(),
            Domain::Fixed(_) => String::new(),
        }
    }
}

/// An argument of a call: (the value, its core length (0: one number per element), its
/// name, its domain).
pub type Item<'a, 'py> = (&'a Bound<'py, PyAny>, usize, &'a str, Domain<'a>);

/// ValueError unless every number of `data` (argument `name`'s, broadcast) is in `domain`.
/// The fast pass over the data the loop reads; on failure the message counts the bad
/// elements of the argument as given (`given`: it as an array of its own shape).
/// `single`: the argument came as float32, whose rounded cosines reach 4 of its own ε
/// beyond ±1.
pub fn check_domain<T: Lane>(
    py: Python<'_>,
    data: &[T],
    name: &str,
    domain: Domain<'_>,
    given: &Bound<'_, PyAny>,
    single: bool,
) -> PyResult<()> {
    if matches!(domain, Domain::Any | Domain::Fixed(_)) {
        return Ok(());
    }
    // One loop per domain, its test branch-free (an OR over a block, which the compiler
    // vectorises: a test through the `Domain` match per element cost ~1 ns an element, 5–10×
    // GGX's D itself); rayon above PARALLEL elements. A parameter's test is the library's.
    fn any_bad<T: Copy + Sync>(data: &[T], bad: impl Fn(T) -> bool + Sync) -> bool {
        let block = |c: &[T]| c.iter().fold(false, |acc, &x| acc | bad(x));
        if data.len() >= PARALLEL {
            data.par_chunks(PARALLEL).any(block)
        } else {
            block(data)
        }
    }
    let cosine_max = if single {
        1.0 + 4.0 * f64::from(f32::EPSILON)
    } else {
        COSINE_MAX
    };
    let bad = match domain {
        Domain::Any | Domain::Fixed(_) => false,
        Domain::Cosine => any_bad(data, |x| x.abs_gt(cosine_max)),
        Domain::Uniform => any_bad(data, |x| x.outside_unit()),
        Domain::Finite => any_bad(data, |x| x.abs_gt(f64::MAX)),
    };
    if !bad {
        return Ok(());
    }
    Err(domain_error(py, name, domain, given))
}

/// [`check_domain`] for one element given as numbers: `x`, the items' numbers back to back
/// (each its core's count, one for core 0).
pub fn check_numbers(py: Python<'_>, items: &[Item<'_, '_>], x: &[f64]) -> PyResult<()> {
    let mut rest = x;
    for &(given, core, name, domain) in items {
        let (head, tail) = rest.split_at(core.max(1));
        if !head.iter().all(|&v| domain.ok(v)) {
            return Err(domain_error(py, name, domain, given));
        }
        rest = tail;
    }
    Ok(())
}

/// The ValueError of argument `name` (`given`, not all in `domain`): the value for a
/// number, else how many elements are bad and the first, by its index.
fn domain_error(py: Python<'_>, name: &str, domain: Domain<'_>, given: &Bound<'_, PyAny>) -> PyErr {
    let describe = || -> PyResult<String> {
        let np = numpy(py)?;
        let a = np.call_method1("asarray", (given, float64(py)?))?;
        let shape: Vec<usize> = a.getattr("shape")?.extract()?;
        let flat: Vec<f64> = a.call_method1("reshape", (-1,))?.extract()?;
        let bad: Vec<usize> = (0..flat.len()).filter(|&i| !domain.ok(flat[i])).collect();
        let Some(&first) = bad.first() else {
            return Ok(format!("{name} is out of its domain"));
        };
        // (Debug: 1.0, not 1, as Python writes it.)
        let x = flat[first];
        let why = domain.why();
        if shape.is_empty() {
            return Ok(format!("{name} {why} (got {x:?})"));
        }
        let index: Vec<usize> = np
            .call_method1("unravel_index", (first, PyTuple::new(py, &shape)?))?
            .extract()?;
        let index: Vec<String> = index.iter().map(|i| i.to_string()).collect();
        let (bad, all, index) = (bad.len(), flat.len(), index.join(", "));
        Ok(format!(
            "{name} {why}: {bad} of {all} elements are not (the first: {name}[{index}] = {x:?})"
        ))
    };
    match describe() {
        Ok(m) => PyValueError::new_err(m),
        Err(e) => e,
    }
}

/// Whether an element's numbers (`x[k]`: argument k's, `domains[k]` its domain) have a NaN
/// value: then its outputs are NaN and the computation does not run.
fn nan_value(x: &[&[f64]], domains: &[Domain<'_>]) -> bool {
    x.iter()
        .zip(domains)
        .any(|(x, d)| d.value() && x.iter().any(|v| v.is_nan()))
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
    /// `items`: the arguments ([`Item`]), each checked against its domain.
    pub fn new(py: Python<'py>, items: &[Item<'_, 'py>]) -> PyResult<Self> {
        let np = numpy(py)?;
        let mut f32 = true;
        let mut arguments = false;
        let mut wide = Vec::with_capacity(items.len());
        let mut batches = Vec::with_capacity(items.len());
        let mut singles = Vec::with_capacity(items.len());
        for &(x, core, name, domain) in items {
            let a = np.call_method1("asarray", (x,))?;
            let dtype = a.getattr("dtype")?;
            let kind: String = dtype.getattr("kind")?.extract()?;
            // Real numbers only: NumPy's asarray turns "0.5" into a string array that
            // astype(float64) would parse, and a complex value would lose its imaginary part
            // (SciPy's real functions raise TypeError for both, and for objects).
            if !matches!(kind.as_str(), "f" | "i" | "u" | "b") {
                return Err(pyo3::exceptions::PyTypeError::new_err(format!(
                    "{name} must be real numbers (got dtype {})",
                    dtype.str()?
                )));
            }
            // float32 in either byte order, and float16 (computed in f32, as SciPy's
            // ufuncs do), give float32 results.
            let itemsize: usize = dtype.getattr("itemsize")?.extract()?;
            let single = kind == "f" && itemsize <= 4;
            singles.push(single);
            // (A parameter array does not choose the dtype: the arguments do; with none,
            // float64. A Python float or int is a weak scalar, NumPy 2's NEP 50: it takes
            // the arrays' precision, so g1(float32 array, 0.5) is float32.)
            let fixed = matches!(domain, Domain::Fixed(_));
            let weak = x.is_exact_instance_of::<pyo3::types::PyFloat>()
                || x.is_exact_instance_of::<pyo3::types::PyInt>();
            f32 &= single || fixed || weak;
            arguments |= !fixed && !weak;
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
        for ((a, &(_, core, name, domain)), single) in wide.into_iter().zip(items).zip(singles) {
            let mut full = batch.clone();
            if core > 0 {
                full.push(core);
            }
            let b = np.call_method1("broadcast_to", (&a, PyTuple::new(py, &full)?))?;
            let flat = np
                .call_method1("ascontiguousarray", (b,))?
                .call_method1("reshape", (-1,))?
                .downcast_into::<PyArray1<f64>>()?;
            let flat = flat.readonly();
            check_domain(py, flat.as_slice()?, name, domain, &a, single)?;
            arrays.push(flat);
        }
        Ok(Args {
            arrays,
            batch,
            n,
            f32: f32 && arguments,
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
/// array: chunks sized by time (about [`CHUNK`] each, whatever an element costs), the
/// signals checked (Ctrl-C raises KeyboardInterrupt) after each chunk, the GIL released
/// meanwhile, rayon's pool from `parallel` elements a chunk. The first error stops the loop.
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

/// The time a chunk of the loop aims at: Ctrl-C is answered within a chunk, so 50 ms keeps
/// the answer under 0.5 s (the contract) even where a chunk runs 10× its estimate (elements
/// of uneven cost), while a check (~20 µs: the GIL taken back, a rayon join ended) costs
/// under 0.1 %.
pub const CHUNK: Duration = Duration::from_millis(50);

/// How much a chunk may grow over the last one: the cost estimate, from the elements done,
/// is trusted within 8× (a chunk that takes the estimate's time at 8× the elements stays
/// within 0.5 s where the first ones ran 10× slower than the next: a slow region of u).
const GROWTH: f64 = 8.0;

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
    // (The first chunk: one element a thread, whatever the elements cost (a quadrature or a
    // walk of 10⁵ steps as well as a closed form); then chunks sized to take about CHUNK by
    // the time the last one took, growing at most GROWTH×. Cheap elements reach chunks of
    // millions in a few steps. Slice kernels (block > 1: GGX's closed forms, ≤ 2 ns an
    // element) start at 2^20 elements, ~1 ms: each check takes the GIL back and ends a rayon
    // join, ~20 µs, and the ramp's three checks and single-threaded first chunk had made a
    // float32 call over 10⁶ elements 2–3× slower.)
    let threads = rayon::current_num_threads();
    let mut chunk = if block > 1 { 1 << 20 } else { threads };
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
            let took = t.elapsed().as_secs_f64();
            let done = end - start;
            start = end;
            if start < n {
                Python::with_gil(|py| {
                    py.check_signals()?;
                    progress_update(py, start, n)
                })?;
                let scale = (CHUNK.as_secs_f64() / took.max(1e-9)).min(GROWTH);
                // (Whole blocks: a slice kernel's block starts at a multiple of `block`.)
                chunk = (((done as f64 * scale) as usize).div_ceil(block) * block).max(block);
            }
        }
        Ok(())
    });
    drop(rw);
    if result.is_ok() {
        progress_update(py, n, n)?;
    }
    result.map(|()| out)
}

thread_local! {
    /// The progress bar of the call running on this thread (`with_progress`), and the
    /// elements it has been told of.
    static PROGRESS: std::cell::RefCell<Option<(PyObject, usize)>> =
        const { std::cell::RefCell::new(None) };
}

/// `f()` with a progress bar over the elements of its loop where `on` (tqdm's, where tqdm is
/// installed; silent otherwise): the loop ([`compute_blocks_of`]) updates it after each
/// chunk, with the GIL it takes for Ctrl-C anyway.
pub fn with_progress<R>(py: Python<'_>, on: bool, f: impl FnOnce() -> PyResult<R>) -> PyResult<R> {
    let bar = if on { tqdm(py)? } else { None };
    let Some(bar) = bar else {
        return f();
    };
    PROGRESS.with(|p| *p.borrow_mut() = Some((bar.clone_ref(py), 0)));
    let r = f();
    PROGRESS.with(|p| p.borrow_mut().take());
    bar.bind(py).call_method0("close")?;
    r
}

/// A new tqdm bar (total set by the loop), or None where tqdm is not installed.
pub fn tqdm(py: Python<'_>) -> PyResult<Option<PyObject>> {
    let Ok(module) = py.import("tqdm") else {
        return Ok(None);
    };
    let kwargs = PyDict::new(py);
    kwargs.set_item("total", 0)?;
    Ok(Some(
        module.getattr("tqdm")?.call((), Some(&kwargs))?.unbind(),
    ))
}

/// Tells this thread's progress bar, if any, that `done` of `n` elements are done.
fn progress_update(py: Python<'_>, done: usize, n: usize) -> PyResult<()> {
    PROGRESS.with(|p| {
        let mut p = p.borrow_mut();
        let Some((bar, shown)) = p.as_mut() else {
            return Ok(());
        };
        let bar = bar.bind(py);
        bar.setattr("total", n)?;
        bar.call_method1("update", (done.saturating_sub(*shown),))?;
        *shown = done.max(*shown);
        Ok(())
    })
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
/// from which uniforms are drawn: with `n` (SciPy's `size`: an int or a tuple of ints) an
/// array of shape (*n, k); without it one draw per element of the call's batch, the
/// broadcast of `args`' batch shapes (each argument with its core length) and `params` (the
/// parameter arrays' shape), as SciPy's `rvs(size=None)` with array parameters draws one
/// variate per parameter element.
pub fn uniforms<'py>(
    py: Python<'py>,
    u: &Bound<'py, PyAny>,
    n: Option<&Bound<'py, PyAny>>,
    k: usize,
    args: &[(&Bound<'py, PyAny>, usize)],
    params: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    let size: Option<Vec<usize>> = match n {
        None => None,
        Some(n) if n.is_none() => None,
        Some(n) => Some(match n.extract::<i64>() {
            Ok(v) => vec![count(v, "n", 0)?],
            Err(_) => {
                let t: Vec<i64> = n.extract().map_err(|_| {
                    pyo3::exceptions::PyTypeError::new_err("n must be an int or a tuple of ints")
                })?;
                t.into_iter()
                    .map(|v| count(v, "n", 0))
                    .collect::<PyResult<_>>()?
            }
        }),
    };
    static GENERATOR: GILOnceCell<PyObject> = GILOnceCell::new();
    let generator = GENERATOR
        .get_or_try_init(py, || {
            Ok::<_, PyErr>(numpy(py)?.getattr("random")?.getattr("Generator")?.unbind())
        })?
        .bind(py);
    if u.is_instance(generator)? {
        let mut shape = match size {
            Some(s) => s,
            None => {
                let np = numpy(py)?;
                let mut shapes = vec![PyTuple::new(py, params)?];
                for &(a, core) in args {
                    let s: Vec<usize> = np.call_method1("shape", (a,))?.extract()?;
                    let keep = s.len().saturating_sub(usize::from(core > 0));
                    shapes.push(PyTuple::new(py, &s[..keep])?);
                }
                np.call_method1("broadcast_shapes", PyTuple::new(py, shapes)?)?
                    .extract()?
            }
        };
        shape.push(k);
        return u.call_method1("random", (PyTuple::new(py, shape)?,));
    }
    if size.is_some() {
        return Err(PyValueError::new_err(
            "n is the number of samples to draw from a numpy.random.Generator; an array of uniforms says it by its shape",
        ));
    }
    Ok(u.clone())
}

/// A count argument (`n` samples, `walks`) as a size: ValueError naming it below `min`.
pub fn count(v: i64, name: &str, min: i64) -> PyResult<usize> {
    if v < min {
        return Err(PyValueError::new_err(format!(
            "{name} must be at least {min} (got {v})"
        )));
    }
    Ok(v as usize)
}

/// One element given without a batch, read without NumPy's conversions: every argument a
/// Python number (core 0) or a list, tuple or 1-D float64 array of exactly its core length
/// of Python numbers (floats, NumPy float64 scalars, ints); the numbers back to back, or
/// `None` for anything else (batches, float32, other types: the array path decides).
fn single_numbers(items: &[Item<'_, '_>]) -> Option<Vec<f64>> {
    use pyo3::types::PyList;
    let number = |a: &Bound<'_, PyAny>| is_number(a).then(|| a.extract::<f64>().ok())?;
    let mut x = Vec::with_capacity(8);
    for &(a, core, _, _) in items {
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

/// Whether the arguments are one element given without a batch (the form [`run_single`]
/// takes: Python numbers, and lists, tuples or 1-D float64 arrays of their core's length).
pub fn one_element(items: &[Item<'_, '_>]) -> bool {
    single_numbers(items).is_some()
}

/// [`Args::run`] for one element given without a batch ([`single_numbers`]): `f(0, a, out)`
/// with a the arguments' numbers split by their cores, without the GIL, and the outputs as
/// the array path shapes a batch of `()` (a NumPy float64 scalar for core 0, a float64
/// array of the core's length otherwise). `None` where the arguments are not of that form.
/// The domains checked and NaN values as in [`guarded`]. About 0.3 µs a call where NumPy's
/// conversions and shaping take ~6 µs (BENCHMARKS.md).
pub fn run_single(
    py: Python<'_>,
    items: &[Item<'_, '_>],
    outs: &[usize],
    f: impl Fn(usize, &[&[f64]], &mut [f64]) -> Result<(), ParamError> + Sync,
) -> PyResult<Option<Vec<PyObject>>> {
    let Some(x) = single_numbers(items) else {
        return Ok(None);
    };
    let width: usize = outs.iter().map(|&c| c.max(1)).sum();
    let mut out = vec![0.0; width];
    check_numbers(py, items, &x)?;
    let mut a: Vec<&[f64]> = Vec::with_capacity(items.len());
    let mut rest = &x[..];
    for &(_, core, _, _) in items {
        let (head, tail) = rest.split_at(core.max(1));
        a.push(head);
        rest = tail;
    }
    let domains: Vec<Domain<'_>> = items.iter().map(|i| i.3).collect();
    let f = guarded(&domains, &f);
    py.allow_threads(|| f(0, &a, &mut out))
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

/// `f` where no value of the element is NaN; NaN outputs where one is (NaN in, NaN out:
/// the computation, a walk or a sampler, would make numbers of it).
fn guarded<'a>(
    domains: &'a [Domain<'a>],
    f: &'a (impl Fn(usize, &[&[f64]], &mut [f64]) -> Result<(), ParamError> + Sync),
) -> impl Fn(usize, &[&[f64]], &mut [f64]) -> Result<(), ParamError> + Sync + 'a {
    move |i, a, o| {
        if nan_value(a, domains) {
            o.fill(f64::NAN);
            return Ok(());
        }
        f(i, a, o)
    }
}

/// `f(cancel)` on a thread of its own while this one waits without the GIL, checking the
/// signals every 50 ms: Ctrl-C raises KeyboardInterrupt at once and trips `cancel`, which
/// the library's long loops ask before each unit of work
/// (`microsurface::scattering::Progress`), so the computation stops too; the interrupt
/// waits up to [`WIND_DOWN`] for it, so that the next call finds the cores free. `tick` is
/// called with the GIL at each check (a progress bar's update) and once at the end.
pub fn interruptible_ticking<T: Send + 'static>(
    py: Python<'_>,
    f: impl FnOnce(Cancel) -> T + Send + 'static,
    mut tick: impl FnMut(Python<'_>) -> PyResult<()> + Send,
) -> PyResult<T> {
    use std::sync::mpsc::{channel, RecvTimeoutError};
    let (tx, rx) = channel();
    let cancel = Cancel::new();
    let token = cancel.clone();
    std::thread::spawn(move || {
        // (Fails only when the caller was interrupted and dropped the receiver.)
        let _ = tx.send(f(token));
    });
    py.allow_threads(move || loop {
        match rx.recv_timeout(Duration::from_millis(50)) {
            Ok(v) => {
                Python::with_gil(&mut tick)?;
                return Ok(v);
            }
            Err(RecvTimeoutError::Timeout) => {
                let checked = Python::with_gil(|py| {
                    py.check_signals()?;
                    tick(py)
                });
                if let Err(e) = checked {
                    cancel.cancel();
                    // (The loop ends within one unit of work; its result is dropped.)
                    let _ = rx.recv_timeout(WIND_DOWN);
                    return Err(e);
                }
            }
            Err(RecvTimeoutError::Disconnected) => {
                return Err(pyo3::exceptions::PyRuntimeError::new_err(
                    "the computation failed (a panic in the library: please report it)",
                ))
            }
        }
    })
}

/// How long an interrupt waits for the cancelled computation to stop: a unit of work (a
/// table's node, a chunk of walks) takes at most tenths of a second.
const WIND_DOWN: Duration = Duration::from_millis(1500);

// ---- The front ends of the NDF and BSDF methods: scalar or direction arguments, and the
// package's named tuples.

/// Above this many elements a cheap function's loop runs on rayon's pool.
pub const PARALLEL: usize = 1 << 14;

/// The most arguments of core 0 [`apply`] takes (a cosine function's two, and three
/// parameters).
pub const MAX_ARGS: usize = 8;

/// `f` over the elements of scalar arguments broadcast together (the isotropic quantities,
/// with their parameter arrays), each argument with its name and domain ([`Item`] of core
/// 0); `f` gets one number per argument, in their order.
pub fn apply<'py>(
    py: Python<'py>,
    args: &[(&Bound<'py, PyAny>, &str, Domain<'_>)],
    f: impl Fn(&[f64]) -> Result<f64, ParamError> + Sync,
) -> PyResult<PyObject> {
    let k = args.len();
    assert!(k <= MAX_ARGS, "apply takes at most {MAX_ARGS} arguments");
    let items: Vec<Item<'_, 'py>> = args.iter().map(|&(a, name, d)| (a, 0, name, d)).collect();
    let domains: Vec<Domain<'_>> = args.iter().map(|a| a.2).collect();
    // Python floats, NumPy float64 scalars (a float subclass) and ints only: no array, the
    // value as a NumPy float64 scalar, as a ufunc returns (0.13 µs a call against ~2.5 µs
    // through the array path's NumPy calls).
    if args.iter().all(|a| is_number(a.0)) {
        let mut x = [0.0; MAX_ARGS];
        for (x, a) in x.iter_mut().zip(args) {
            *x = a.0.extract::<f64>()?;
        }
        let x = &x[..k];
        check_numbers(py, &items, x)?;
        let y = if nan_of(x, &domains) {
            f64::NAN
        } else {
            f(x).map_err(value_error)?
        };
        return Ok(float64(py)?.call1((y,))?.unbind());
    }
    let a = Args::new(py, &items)?;
    let s: Vec<&[f64]> = (0..k).map(|j| a.slice(j)).collect::<PyResult<_>>()?;
    let mut out = a.run(py, 1, &[0], PARALLEL, |i, o| {
        let mut x = [0.0; MAX_ARGS];
        for (x, s) in x.iter_mut().zip(&s) {
            *x = s[i];
        }
        let x = &x[..k];
        o[0] = if nan_of(x, &domains) { f64::NAN } else { f(x)? };
        Ok(())
    })?;
    Ok(out.remove(0))
}

/// [`nan_value`] of one number per argument (no allocation: the cheap quantities' loop).
fn nan_of(x: &[f64], domains: &[Domain<'_>]) -> bool {
    x.iter().zip(domains).any(|(v, d)| d.value() && v.is_nan())
}

/// Arguments with cores (3: a direction, 2 or 3: uniforms, 0: one number) to `outs`
/// outputs per element (their core lengths), `f(i, a, out)` for element i with a the
/// arguments' numbers; the domains checked, and NaN outputs for an element with a NaN value
/// ([`guarded`]).
pub fn apply_vec<'py>(
    py: Python<'py>,
    items: &[Item<'_, 'py>],
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
    let domains: Vec<Domain<'_>> = items.iter().map(|i| i.3).collect();
    let f = guarded(&domains, &f);
    let width = outs.iter().map(|&c| c.max(1)).sum();
    assert!(
        s.len() <= MAX_ARGS,
        "apply_vec takes at most {MAX_ARGS} arguments"
    );
    a.run(py, width, outs, parallel, |i, o| {
        // (On the stack: an allocation per element cost more than GGX's pdf itself.)
        let mut e: [&[f64]; MAX_ARGS] = [&[]; MAX_ARGS];
        for ((e, s), &c) in e.iter_mut().zip(&s).zip(&cores) {
            *e = &s[i * c..(i + 1) * c];
        }
        f(i, &e[..s.len()], o)
    })
}

/// One number per element of direction arguments (cheap: rayon from [`PARALLEL`]).
pub fn map_vec<'py>(
    py: Python<'py>,
    items: &[Item<'_, 'py>],
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
