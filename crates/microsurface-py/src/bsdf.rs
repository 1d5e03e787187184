//! The BSDFs: the base class `BSDF` (eval, pdf, sample over any [`Bsdf`] of the library,
//! its value written as channels) and its subclasses `Conductor` and `Dielectric`, with
//! their scattering model (single scattering, Kulla–Conty or Turquin energy compensation,
//! the random walk).

use crate::engine::{apply_vec, named, v3, Domain, Item};
use crate::material::Material;
use crate::ndf::NDF;
use crate::params::{self, Param};
use microsurface::bsdf::fresnel::{self, Fresnel};
use microsurface::bsdf::{self, Bsdf, Lobe, Masking, Transport};
use microsurface::scattering::{
    CompensatedConductor, CompensatedDielectric, DielectricFacets, Facets, MirrorFacets,
    MultipleScattering, Scheme,
};
use microsurface::ParamError;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

/// f's channels: a dielectric's one, a conductor's N.
trait Channels: Copy {
    const N: usize;
    fn write(&self, out: &mut [f64]);
}

impl<const M: usize> Channels for [f64; M] {
    const N: usize = M;
    fn write(&self, out: &mut [f64]) {
        out[..M].copy_from_slice(self);
    }
}

/// A BSDF of any model, its value written as channels.
trait AnyBsdf: Send + Sync {
    /// The walk model's f as the mean of `samples` stochastic evaluations from the stream
    /// `seed` (`MultipleScattering::eval_orders`); the deterministic models' own f.
    fn eval_mean(&self, wo: [f64; 3], wi: [f64; 3], samples: u64, seed: u64, out: &mut [f64]) {
        let _ = (samples, seed);
        self.eval(wo, wi, out)
    }
    fn eval(&self, wo: [f64; 3], wi: [f64; 3], out: &mut [f64]);
    fn pdf(&self, wo: [f64; 3], wi: [f64; 3]) -> f64;
    /// wi (3), f (channels), pdf, lobe (0 rejected, 1 reflection, 2 transmission),
    /// specular (0/1), η'.
    fn sample(&self, wo: [f64; 3], uc: f64, u: [f64; 2], out: &mut [f64]);
}

impl<B: Bsdf<f64> + Send + Sync> AnyBsdf for B
where
    B::Value: Channels,
{
    fn eval(&self, wo: [f64; 3], wi: [f64; 3], out: &mut [f64]) {
        Bsdf::eval(self, wo, wi).write(out);
    }
    fn pdf(&self, wo: [f64; 3], wi: [f64; 3]) -> f64 {
        Bsdf::pdf(self, wo, wi)
    }
    fn sample(&self, wo: [f64; 3], uc: f64, u: [f64; 2], out: &mut [f64]) {
        let c = B::Value::N;
        match Bsdf::sample(self, wo, uc, u) {
            Some(s) => {
                out[..3].copy_from_slice(&s.wi);
                s.f.write(&mut out[3..3 + c]);
                out[3 + c] = s.pdf;
                out[4 + c] = match s.lobe {
                    Lobe::Reflection => 1.0,
                    Lobe::Transmission => 2.0,
                };
                out[5 + c] = if s.specular { 1.0 } else { 0.0 };
                out[6 + c] = s.eta;
            }
            // (Zeros: no direction, f = pdf = 0, lobe 0.)
            None => out.fill(0.0),
        }
    }
}

/// The walk's BSDF, with its averaged evaluation.
struct Walk<D, Fa, const N: usize>(MultipleScattering<D, Fa, N>);

impl<D, Fa, const N: usize> AnyBsdf for Walk<D, Fa, N>
where
    D: microsurface::MicrofacetDistribution<f64> + Send + Sync,
    Fa: Facets<N> + Send + Sync,
    MultipleScattering<D, Fa, N>: Bsdf<f64, Value = [f64; N]>,
{
    fn eval_mean(&self, wo: [f64; 3], wi: [f64; 3], samples: u64, seed: u64, out: &mut [f64]) {
        let e = self.0.eval_orders(wo, wi, samples, seed);
        for (o, e) in out.iter_mut().zip(&e) {
            *o = e.total;
        }
    }
    fn eval(&self, wo: [f64; 3], wi: [f64; 3], out: &mut [f64]) {
        AnyBsdf::eval(&self.0, wo, wi, out)
    }
    fn pdf(&self, wo: [f64; 3], wi: [f64; 3]) -> f64 {
        AnyBsdf::pdf(&self.0, wo, wi)
    }
    fn sample(&self, wo: [f64; 3], uc: f64, u: [f64; 2], out: &mut [f64]) {
        AnyBsdf::sample(&self.0, wo, uc, u, out)
    }
}

fn masking(s: &str) -> PyResult<Masking> {
    match s {
        "correlated" => Ok(Masking::Correlated),
        "separable" => Ok(Masking::Separable),
        "correlated_beta" => Ok(Masking::CorrelatedBeta),
        _ => Err(PyValueError::new_err(format!(
            "masking must be 'correlated', 'separable' or 'correlated_beta' (got {s:?})"
        ))),
    }
}

fn transport(s: &str) -> PyResult<Transport> {
    match s {
        "radiance" => Ok(Transport::Radiance),
        "importance" => Ok(Transport::Importance),
        _ => Err(PyValueError::new_err(format!(
            "transport must be 'radiance' or 'importance' (got {s:?})"
        ))),
    }
}

/// The scattering model.
#[derive(Clone, Copy, PartialEq)]
enum Model {
    Single,
    Compensated(Scheme),
    Walk,
}

fn model(s: &str, m: Masking) -> PyResult<Model> {
    let model = match s {
        "single" => Model::Single,
        "kulla_conty" => Model::Compensated(Scheme::KullaConty),
        "turquin" => Model::Compensated(Scheme::Turquin),
        "walk" => Model::Walk,
        _ => {
            return Err(PyValueError::new_err(format!(
                "scattering must be 'single', 'kulla_conty', 'turquin' or 'walk' (got {s:?})"
            )))
        }
    };
    if model != Model::Single && m != Masking::Correlated {
        return Err(PyValueError::new_err(
            "the multiple-scattering models use the height-correlated G2: masking='correlated'",
        ));
    }
    Ok(model)
}

/// What a BSDF is built from, beside its NDF's material: the model and its settings, and
/// the Fresnel parameters of one element (η and k per channel; a dielectric's one η).
#[derive(Clone)]
struct Recipe {
    dielectric: bool,
    channels: usize,
    masking: Masking,
    transport: Transport,
    model: Model,
}

impl Recipe {
    /// The BSDF of material `d` with `eta` (and `k`; empty: F = 1 for a conductor).
    /// (`Err` for an η the library refuses: NaN, infinite or ≤ 0.)
    fn build(&self, d: Material, eta: &[f64], k: &[f64]) -> Result<Box<dyn AnyBsdf>, ParamError> {
        let (m, t) = (self.masking, self.transport);
        if self.dielectric {
            let eta = eta[0];
            return Ok(match self.model {
                // (One channel: a dielectric's f is grey.)
                Model::Single => Box::new(
                    bsdf::RoughDielectric::new(d, eta)?
                        .with_channels::<1>()
                        .with_masking(m)
                        .with_transport(t),
                ),
                Model::Compensated(s) => Box::new(
                    CompensatedDielectric::new(d, eta, s)?
                        .with_channels::<1>()
                        .with_transport(t),
                ),
                Model::Walk => Box::new(Walk(
                    MultipleScattering::<_, _, 1>::new(d, DielectricFacets::new(eta)?)
                        .with_transport(t),
                )),
            });
        }
        let model = self.model;
        Ok(match (eta.len(), k.len()) {
            (0, _) => conductor_of::<1, _>(d, fresnel::One::<1>, m, model),
            (1, _) => conductor_of::<1, _>(
                d,
                fresnel::Conductor {
                    eta: [eta[0]],
                    k: [k.first().copied().unwrap_or(0.0)],
                },
                m,
                model,
            ),
            _ => conductor_of::<3, _>(
                d,
                fresnel::Conductor {
                    eta: [eta[0], eta[1], eta[2]],
                    k: if k.is_empty() {
                        [0.0; 3]
                    } else {
                        [k[0], k[1], k[2]]
                    },
                },
                m,
                model,
            ),
        })
    }
}

fn conductor_of<const N: usize, Fr>(
    d: Material,
    fr: Fr,
    m: Masking,
    model: Model,
) -> Box<dyn AnyBsdf>
where
    Fr: Fresnel<f64, N> + Send + Sync + 'static,
    MirrorFacets<Fr>: Facets<N>,
{
    match model {
        Model::Single => Box::new(bsdf::RoughConductor::new(d, fr).with_masking(m)),
        Model::Compensated(s) => Box::new(CompensatedConductor::new(d, fr, s)),
        Model::Walk => Box::new(Walk(MultipleScattering::new(d, MirrorFacets(fr)))),
    }
}

/// A Fresnel parameter (η, k): a number, a sequence per channel (its last axis: the
/// conductor's channels), or an array of them per element (the leading axes: the batch).
struct Channel {
    param: Param,
    /// The numbers of one element's channels, where it is one element.
    one: Option<Vec<f64>>,
}

impl Channel {
    /// `x` as a conductor's per-channel parameter (`channel`: the last axis is the
    /// channels) or a dielectric's number (`!channel`); each value through `ok`.
    fn new(
        py: Python<'_>,
        x: &Bound<'_, PyAny>,
        name: &str,
        channel: bool,
        ok: fn(f64) -> bool,
        want: &str,
    ) -> PyResult<Self> {
        let param = Param::new(py, x, name)?;
        let np = crate::engine::numpy(py)?;
        let values: Vec<f64> = np
            .call_method1("ravel", (param.object(py)?,))?
            .call_method0("tolist")?
            .extract()?;
        if values.is_empty() || !values.iter().all(|&v| ok(v)) {
            return Err(PyValueError::new_err(format!(
                "{name} must be {want} (got {})",
                param.repr(py)?
            )));
        }
        let shape = param.shape(py)?;
        let one = match (&param, channel) {
            (Param::Num(x), _) => Some(vec![*x]),
            (Param::Arr(_), true) if shape.len() == 1 => Some(values),
            _ => None,
        };
        Ok(Channel { param, one })
    }

    /// The number of channels (the last axis of a conductor's parameter; 1 for a number).
    fn channels(&self, py: Python<'_>) -> PyResult<usize> {
        Ok(self.param.shape(py)?.last().copied().unwrap_or(1))
    }
}

/// Per-element BSDFs of one object, each built once for a run of elements with the same
/// parameters: the key is the object's id and the element's parameters' bits.
type BsdfKey = Vec<u64>;

thread_local! {
    static BSDFS: std::cell::RefCell<Option<(BsdfKey, Box<dyn AnyBsdf>)>> =
        const { std::cell::RefCell::new(None) };
}

/// A BSDF object's ids (each one's own key prefix in [`BSDFS`]).
static NEXT_ID: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

/// A BSDF whose parameters are arrays: its parts, each element's BSDF built in the loop.
struct Batch {
    id: u64,
    ndf: NDF,
    eta: Option<Channel>,
    k: Option<Channel>,
    recipe: Recipe,
}

/// The BSDF of one object: one, or one per element.
enum Inner {
    One(Box<dyn AnyBsdf>),
    Batch(Box<Batch>),
}

/// The methods of both BSDF classes.
#[pyclass(name = "BSDF", subclass, frozen, module = "microsurface")]
pub struct PyBsdf {
    inner: Inner,
    /// f's channels.
    channels: usize,
    /// Whether the model is the random walk (stochastic eval).
    walk: bool,
    /// The constructor's arguments, normalised (channels as tuples of floats): what
    /// `__reduce__` passes back, `__repr__` writes and `==` compares.
    args: Py<PyTuple>,
    /// Their names, for `__repr__`'s keywords (the first, the NDF, is positional).
    names: &'static [&'static str],
}

impl PyBsdf {
    /// The BSDF of `ndf` with the Fresnel parameters `eta` and `k` (None: absent) by
    /// `recipe`: one, where every parameter is a number (or a conductor's sequence of
    /// channels), else one per element.
    fn new(
        py: Python<'_>,
        ndf: &Bound<'_, NDF>,
        eta: Option<Channel>,
        k: Option<Channel>,
        recipe: Recipe,
        args: Vec<PyObject>,
        names: &'static [&'static str],
    ) -> PyResult<Self> {
        let channels = recipe.channels;
        let walk = recipe.model == Model::Walk;
        let n = ndf.get();
        let one = |c: &Option<Channel>| c.as_ref().map_or(Some(Vec::new()), |c| c.one.clone());
        let inner = match (n.batched(), one(&eta), one(&k)) {
            (false, Some(e), Some(kk)) => Inner::One(
                recipe
                    .build(n.material()?.clone(), &e, &kk)
                    .map_err(crate::engine::value_error)?,
            ),
            _ => {
                // (The shapes: the NDF's parameters, η's and k's batch axes broadcast.)
                let np = crate::engine::numpy(py)?;
                let mut shapes = vec![PyTuple::new(py, n.param_shape_vec())?];
                for c in [&eta, &k].into_iter().flatten() {
                    let mut s = c.param.shape(py)?;
                    if !recipe.dielectric {
                        s.pop();
                    }
                    shapes.push(PyTuple::new(py, s)?);
                }
                np.call_method1("broadcast_shapes", PyTuple::new(py, shapes)?)
                    .map_err(|_| {
                        PyValueError::new_err(
                            "the parameters' shapes (the NDF's, eta's and k's, less their channel axis) do not broadcast together",
                        )
                    })?;
                Inner::Batch(Box::new(Batch {
                    id: NEXT_ID.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
                    ndf: n.clone(),
                    eta,
                    k,
                    recipe,
                }))
            }
        };
        Ok(PyBsdf {
            inner,
            channels,
            walk,
            args: PyTuple::new(py, args)?.unbind(),
            names,
        })
    }

    /// `f(bsdf, a, out)` for every element of the arguments `items` (a: their numbers),
    /// broadcast with the parameter arrays, with the element's BSDF.
    fn each<'py>(
        &self,
        py: Python<'py>,
        items: &[Item<'_, 'py>],
        outs: &[usize],
        f: impl Fn(&dyn AnyBsdf, &[&[f64]], &mut [f64]) + Sync,
    ) -> PyResult<Vec<PyObject>> {
        self.each_indexed(py, items, outs, |b, _, a, o| f(b, a, o))
    }

    /// [`PyBsdf::each`] with the element's index: `f(bsdf, i, a, out)`.
    fn each_indexed<'py>(
        &self,
        py: Python<'py>,
        items: &[Item<'_, 'py>],
        outs: &[usize],
        f: impl Fn(&dyn AnyBsdf, usize, &[&[f64]], &mut [f64]) + Sync,
    ) -> PyResult<Vec<PyObject>> {
        let b = match &self.inner {
            Inner::One(b) => {
                return apply_vec(py, items, outs, 256, |i, a, o| {
                    f(b.as_ref(), i, a, o);
                    Ok(())
                })
            }
            Inner::Batch(b) => b,
        };
        let mut arrays = b.ndf.arrays(py);
        let nd = arrays.len();
        let mut all = items.to_vec();
        let mut cores = Vec::new();
        for (c, name) in [(&b.eta, "eta"), (&b.k, "k")] {
            if let Some(c) = c {
                arrays.push((c.param.object(py)?, name));
                cores.push(if b.recipe.dielectric || c.param.num().is_some() {
                    0
                } else {
                    c.channels(py)?
                });
            }
        }
        let k0 = items.len();
        for (j, (a, name)) in arrays.iter().enumerate() {
            let core = if j < nd { 0 } else { cores[j - nd] };
            all.push((a, core, *name, crate::engine::FIXED));
        }
        let has_eta = b.eta.is_some();
        apply_vec(py, &all, outs, 256, |i, a, o| {
            let v: Vec<f64> = a[k0..k0 + nd].iter().map(|s| s[0]).collect();
            let p = b.ndf.p_of(&v);
            let rest = &a[k0 + nd..];
            let (eta, k): (&[f64], &[f64]) = match (has_eta, rest.len()) {
                (true, 2) => (rest[0], rest[1]),
                (true, 1) => (rest[0], &[]),
                _ => (&[], &[]),
            };
            let mut key = vec![b.id, p.alpha.to_bits(), p.alpha_y.to_bits()];
            key.extend(p.shape.map(f64::to_bits));
            key.extend(eta.iter().chain(k).map(|x| x.to_bits()));
            let recent = params::Recent::new(&BSDFS);
            b.ndf.with_material(p, |m| {
                recent.with(
                    key,
                    || b.recipe.build(m.clone(), eta, k),
                    |bsdf| f(bsdf.as_ref(), i, &a[..k0], o),
                )
            })?
        })
    }
}

/// `repr` of a constructor argument, evaluable back: an array as ``np.array([...])`` (the
/// name NumPy's users import it as).
fn arg_repr(py: Python<'_>, a: &Bound<'_, PyAny>) -> PyResult<String> {
    if a.is_instance(&crate::engine::numpy(py)?.getattr("ndarray")?)? {
        return Ok(format!("np.array({})", a.call_method0("tolist")?.repr()?));
    }
    Ok(a.repr()?.to_string())
}

#[pymethods]
impl PyBsdf {
    /// The constructor call that builds this BSDF, evaluable back:
    /// ``microsurface.Conductor(microsurface.GGX(0.3), eta=(0.2,), k=(3.9,), masking='correlated', scattering='single')``.
    fn __repr__(slf: &Bound<'_, Self>) -> PyResult<String> {
        let py = slf.py();
        let args = slf.get().args.bind(py);
        let mut s = format!("microsurface.{}(", slf.get_type().name()?);
        for (i, (a, name)) in args.iter().zip(slf.get().names).enumerate() {
            if i > 0 {
                s += &format!(", {name}=");
            }
            s += &arg_repr(py, &a)?;
        }
        Ok(s + ")")
    }

    /// The constructor's arguments (``pickle``, ``copy``; joblib and multiprocessing).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> (Bound<'py, PyAny>, Bound<'py, PyTuple>) {
        (
            slf.get_type().into_any(),
            slf.get().args.bind(slf.py()).clone(),
        )
    }

    /// A BSDF is immutable: its copy is itself.
    fn __copy__(slf: PyRef<'_, Self>) -> PyRef<'_, Self> {
        slf
    }

    /// As ``__copy__``.
    fn __deepcopy__<'py>(slf: PyRef<'py, Self>, _memo: &Bound<'py, PyAny>) -> PyRef<'py, Self> {
        slf
    }

    /// Equal when of the same class with equal arguments (the NDF by its own ``==``).
    fn __eq__(slf: &Bound<'_, Self>, other: &Bound<'_, PyAny>) -> PyResult<bool> {
        let Ok(o) = other.downcast::<PyBsdf>() else {
            return Ok(false);
        };
        let py = slf.py();
        if !slf.get_type().is(o.get_type()) {
            return Ok(false);
        }
        let np = crate::engine::numpy(py)?;
        let ndarray = np.getattr("ndarray")?;
        for (a, b) in slf
            .get()
            .args
            .bind(py)
            .iter()
            .zip(o.get().args.bind(py).iter())
        {
            let same = if a.is_instance(&ndarray)? || b.is_instance(&ndarray)? {
                np.call_method1("array_equal", (&a, &b))?.is_truthy()?
                    && a.is_instance(&ndarray)? == b.is_instance(&ndarray)?
            } else {
                a.eq(&b)?
            };
            if !same {
                return Ok(false);
            }
        }
        Ok(true)
    }

    /// By the arguments ``==`` compares (their ``repr``).
    fn __hash__(slf: &Bound<'_, Self>) -> PyResult<isize> {
        Self::__repr__(slf)?.into_pyobject(slf.py())?.hash()
    }

    /// The number of channels of f (1 for a dielectric and a one-channel conductor).
    #[getter]
    fn channels(&self) -> usize {
        self.channels
    }

    /// f(wo, wi) without the cosine, for directions of shape (..., 3) broadcast together:
    /// shape (...) for one channel, (..., channels) otherwise. The walk model returns one
    /// stochastic estimate (unbiased; seeded by the directions), or with ``samples`` (≥ 1)
    /// and ``seed`` the mean of ``samples`` estimates from the stream ``seed`` and the
    /// element's index (the command line's ``samples``; the same numbers whatever the
    /// threads). ``samples`` and ``seed`` are the walk model's (ValueError for the others).
    #[pyo3(signature = (wo, wi, samples = None, seed = None))]
    fn eval(
        &self,
        py: Python<'_>,
        wo: &Bound<'_, PyAny>,
        wi: &Bound<'_, PyAny>,
        samples: Option<i64>,
        seed: Option<i128>,
    ) -> PyResult<PyObject> {
        let c = self.channels;
        let outs = [if c == 1 { 0 } else { c }];
        let items = [(wo, 3, "wo", Domain::Any), (wi, 3, "wi", Domain::Any)];
        if samples.is_none() && seed.is_none() {
            let mut o = self.each(py, &items, &outs, |b, a, o| b.eval(v3(a[0]), v3(a[1]), o))?;
            return Ok(o.remove(0));
        }
        if !self.walk {
            return Err(PyValueError::new_err(
                "samples and seed are the walk model's (scattering='walk'): this BSDF's eval is deterministic",
            ));
        }
        let samples = crate::engine::count(samples.unwrap_or(1), "samples", 1)? as u64;
        let seed = seed.unwrap_or(0);
        let seed = u64::try_from(seed).map_err(|_| {
            PyValueError::new_err(format!("seed must be in [0, 2**64) (got {seed})"))
        })?;
        let mut o = self.each_indexed(py, &items, &outs, |b, i, a, o| {
            let seed = seed.wrapping_add((i as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15));
            b.eval_mean(v3(a[0]), v3(a[1]), samples, seed, o);
        })?;
        Ok(o.remove(0))
    }

    /// The density of ``sample``'s wi per unit solid angle (0 for delta lobes; the walk
    /// model's stand-in for multiple importance sampling, see the crate's
    /// MultipleScattering).
    fn pdf(
        &self,
        py: Python<'_>,
        wo: &Bound<'_, PyAny>,
        wi: &Bound<'_, PyAny>,
    ) -> PyResult<PyObject> {
        let mut o = self.each(
            py,
            &[(wo, 3, "wo", Domain::Any), (wi, 3, "wi", Domain::Any)],
            &[0],
            |b, a, o| o[0] = b.pdf(v3(a[0]), v3(a[1])),
        )?;
        Ok(o.remove(0))
    }

    /// Directions wi from wo: ``sample(wo, u)`` with uniforms u of shape (..., 3) (the lobe
    /// choice, then the normal's two), or ``sample(wo, rng, n)`` with a
    /// ``numpy.random.Generator`` (``n`` an int or a tuple, SciPy's ``size``; ``None``: one
    /// draw per element of wo's batch broadcast with the NDF's parameter arrays). Returns ``BSDFSample(wi, f, pdf, lobe, specular, eta)``;
    /// a rejected sample (a reflection below the horizon, wo on it, ...) has wi = 0, f = 0,
    /// pdf = 0 and lobe 0 (else 1 reflection, 2 transmission); specular marks the delta
    /// lobes of a smooth surface (α < 1e-3), whose f and pdf are weights; eta is the
    /// relative index along the path (1 for a reflection).
    #[pyo3(signature = (wo, u, n = None))]
    fn sample(
        &self,
        py: Python<'_>,
        wo: &Bound<'_, PyAny>,
        u: &Bound<'_, PyAny>,
        n: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyObject> {
        let c = self.channels;
        let params = match &self.inner {
            Inner::One(_) => Vec::new(),
            Inner::Batch(b) => b.ndf.param_shape_vec(),
        };
        let u = crate::engine::uniforms(py, u, n, 3, &[(wo, 3)], &params)?;
        let outs = [3, if c == 1 { 0 } else { c }, 0, 0, 0, 0];
        let mut o = self.each(
            py,
            &[(wo, 3, "wo", Domain::Any), (&u, 3, "u", Domain::Uniform)],
            &outs,
            |b, a, o| b.sample(v3(a[0]), a[1][0], [a[1][1], a[1][2]], o),
        )?;
        // (lobe as int8, specular as bool; an element with a NaN value, all NaN from the
        // engine, is a rejected sample there: lobe 0, not specular.)
        let np = crate::engine::numpy(py)?;
        for (k, dtype) in [(3, "int8"), (4, "bool_")] {
            let kwargs = pyo3::types::PyDict::new(py);
            kwargs.set_item("nan", 0.0)?;
            o[k] = np
                .call_method("nan_to_num", (o[k].bind(py),), Some(&kwargs))?
                .call_method1("astype", (np.getattr(dtype)?,))?
                .unbind();
        }
        named(py, "BSDFSample", o)
    }
}

/// Conductor(ndf, eta=None, k=None, masking='correlated', scattering='single'): a rough
/// conductor of the material ``ndf`` (any NDF class, anisotropic included, on its path: the
/// fast kernels, or the exact path for an NDF made with ``exact=True``), with the exact
/// Fresnel reflectance of the complex index η + ik: floats for one channel, sequences of N
/// for N channels (RGB: 3); eta=None is F = 1 (the white furnace). ``scattering``:
/// 'single' (D G2 F/(4|cos θo||cos θi|), pbrt-v4's and Mitsuba's lobe), 'kulla_conty' or
/// 'turquin' (energy compensation from the albedo table: shipped for GGX, Beckmann, Double
/// GGX, the Exponential NDF and GTR at γ = 1, 2; computed otherwise), or 'walk' (the
/// exact multiple scattering of Heitz et al. 2016 by the microsurface random walk;
/// stochastic eval).
#[pyclass(extends = PyBsdf, frozen, module = "microsurface")]
pub struct Conductor;

#[pymethods]
impl Conductor {
    #[new]
    #[pyo3(signature = (ndf, eta = None, k = None, masking = "correlated", scattering = "single"))]
    fn new(
        ndf: Bound<'_, NDF>,
        eta: Option<&Bound<'_, PyAny>>,
        k: Option<&Bound<'_, PyAny>>,
        masking: &str,
        scattering: &str,
    ) -> PyResult<(Self, PyBsdf)> {
        let py = ndf.py();
        let positive = |x: f64| x > 0.0 && x.is_finite();
        let eta = eta
            .map(|e| Channel::new(py, e, "eta", true, positive, "positive and finite"))
            .transpose()?;
        let k = k
            .map(|k| Channel::new(py, k, "k", true, f64::is_finite, "finite"))
            .transpose()?;
        let channels = match (&eta, &k) {
            (None, None) => 1,
            (Some(e), k) => {
                let c = e.channels(py)?;
                if let Some(k) = k {
                    if k.channels(py)? != c {
                        return Err(PyValueError::new_err(
                            "eta and k must have the same number of channels (their last axis)",
                        ));
                    }
                }
                if c != 1 && c != 3 {
                    return Err(PyValueError::new_err(format!(
                        "1 or 3 channels are supported (got {c})"
                    )));
                }
                c
            }
            (None, Some(_)) => return Err(PyValueError::new_err("k needs eta")),
        };
        // (Sequences of channels as tuples, as given before arrays: what repr writes.)
        let arg = |c: &Option<Channel>| -> PyResult<PyObject> {
            Ok(match c {
                None => py.None(),
                Some(Channel { one: Some(v), .. }) => PyTuple::new(py, v)?.into_any().unbind(),
                Some(c) => c.param.object(py)?.unbind(),
            })
        };
        let args = vec![
            ndf.clone().into_any().unbind(),
            arg(&eta)?,
            arg(&k)?,
            masking.into_pyobject(py)?.into_any().unbind(),
            scattering.into_pyobject(py)?.into_any().unbind(),
        ];
        let m = self::masking(masking)?;
        let recipe = Recipe {
            dielectric: false,
            channels,
            masking: m,
            transport: Transport::Radiance,
            model: self::model(scattering, m)?,
        };
        let names = &["ndf", "eta", "k", "masking", "scattering"];
        Ok((
            Conductor,
            PyBsdf::new(py, &ndf, eta, k, recipe, args, names)?,
        ))
    }
}

/// Dielectric(ndf, eta, masking='correlated', transport='radiance', scattering='single'):
/// a rough dielectric interface of relative index η = η_inside/η_outside (η > 0, ≠ 1),
/// reflection and transmission (Walter et al. 2007), as pbrt-v4's; transport 'radiance'
/// divides a transmitted f by η'² (Veach 1997, §5.2). ``masking``: 'correlated'
/// (1/(1 + Λo + Λi) for both lobes, pbrt-v4's), 'separable' (G1(wo) G1(wi), Mitsuba's) or
/// 'correlated_beta' (a transmission's exact height-correlated B(1 + Λo, 1 + Λi), the
/// random walk's order 1; see the crate's ``bsdf::Masking``); single scattering only. The
/// two transmission forms differ most at grazing angles on rough surfaces: GGX α = 1,
/// μ = 0.05, η = 1.5 transmits 0.728 by 'correlated', 0.050 by 'correlated_beta' (their
/// albedos: ``single_scattering_albedo(ndf, mu, eta=..., masking='pbrt' | 'exact')``). ``scattering`` as for
/// ``Conductor`` ('kulla_conty'/'turquin' use the dielectric tables, computed here). The
/// NDF's path (fast, or ``exact=True``) as for ``Conductor``.
#[pyclass(extends = PyBsdf, frozen, module = "microsurface")]
pub struct Dielectric;

#[pymethods]
impl Dielectric {
    #[new]
    #[pyo3(signature = (ndf, eta, masking = "correlated", transport = "radiance", scattering = "single"))]
    fn new(
        ndf: Bound<'_, NDF>,
        eta: &Bound<'_, PyAny>,
        masking: &str,
        transport: &str,
        scattering: &str,
    ) -> PyResult<(Self, PyBsdf)> {
        let py = ndf.py();
        let ok = |x: f64| x > 0.0 && x.is_finite() && x != 1.0;
        let eta = Channel::new(
            py,
            eta,
            "eta",
            false,
            ok,
            "a positive finite number other than 1",
        )?;
        let args = vec![
            ndf.clone().into_any().unbind(),
            eta.param.object(py)?.unbind(),
            masking.into_pyobject(py)?.into_any().unbind(),
            transport.into_pyobject(py)?.into_any().unbind(),
            scattering.into_pyobject(py)?.into_any().unbind(),
        ];
        let m = self::masking(masking)?;
        let recipe = Recipe {
            dielectric: true,
            channels: 1,
            masking: m,
            transport: self::transport(transport)?,
            model: self::model(scattering, m)?,
        };
        let names = &["ndf", "eta", "masking", "transport", "scattering"];
        Ok((
            Dielectric,
            PyBsdf::new(py, &ndf, Some(eta), None, recipe, args, names)?,
        ))
    }
}

/// Adds `BSDF`, `Conductor` and `Dielectric` to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyBsdf>()?;
    m.add_class::<Conductor>()?;
    m.add_class::<Dielectric>()?;
    Ok(())
}
