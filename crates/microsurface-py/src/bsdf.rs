//! The BSDFs: the base class `BSDF` (eval, pdf, sample over any [`Bsdf`] of the library,
//! its value written as channels) and its subclasses `Conductor` and `Dielectric`, with
//! their scattering model (single scattering, Kulla–Conty or Turquin energy compensation,
//! the random walk).

use crate::engine::{apply_vec, map_vec, named, v3, Domain};
use crate::material::Material;
use crate::ndf::NDF;
use microsurface::bsdf::fresnel::{self, Fresnel};
use microsurface::bsdf::{self, Bsdf, Lobe, Masking, Transport};
use microsurface::scattering::{
    CompensatedConductor, CompensatedDielectric, DielectricFacets, Facets, MirrorFacets,
    MultipleScattering, Scheme,
};
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
    fn channels(&self) -> usize;
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
    fn channels(&self) -> usize {
        B::Value::N
    }
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

/// A number or a sequence of numbers per channel.
fn channels(x: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Vec<f64>>> {
    match x {
        None => Ok(None),
        Some(x) => match x.extract::<f64>() {
            Ok(v) => Ok(Some(vec![v])),
            Err(_) => Ok(Some(x.extract::<Vec<f64>>()?)),
        },
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
        Model::Walk => Box::new(MultipleScattering::new(d, MirrorFacets(fr))),
    }
}

/// The methods of both BSDF classes.
#[pyclass(name = "BSDF", subclass, frozen, module = "microsurface")]
pub struct PyBsdf {
    inner: Box<dyn AnyBsdf>,
    /// The constructor's arguments, normalised (channels as tuples of floats): what
    /// `__reduce__` passes back, `__repr__` writes and `==` compares.
    args: Py<PyTuple>,
    /// Their names, for `__repr__`'s keywords (the first, the NDF, is positional).
    names: &'static [&'static str],
}

impl PyBsdf {
    fn new(
        py: Python<'_>,
        inner: Box<dyn AnyBsdf>,
        args: Vec<PyObject>,
        names: &'static [&'static str],
    ) -> PyResult<Self> {
        Ok(PyBsdf {
            inner,
            args: PyTuple::new(py, args)?.unbind(),
            names,
        })
    }
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
            s += &a.repr()?.to_string();
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
        Ok(slf.get_type().is(o.get_type()) && slf.get().args.bind(py).eq(o.get().args.bind(py))?)
    }

    /// By the arguments ``==`` compares.
    fn __hash__(slf: &Bound<'_, Self>) -> PyResult<isize> {
        slf.get().args.bind(slf.py()).hash()
    }

    /// The number of channels of f (1 for a dielectric and a one-channel conductor).
    #[getter]
    fn channels(&self) -> usize {
        self.inner.channels()
    }

    /// f(wo, wi) without the cosine, for directions of shape (..., 3) broadcast together:
    /// shape (...) for one channel, (..., channels) otherwise. The walk model returns one
    /// stochastic estimate (unbiased; seeded by the directions).
    fn eval(
        &self,
        py: Python<'_>,
        wo: &Bound<'_, PyAny>,
        wi: &Bound<'_, PyAny>,
    ) -> PyResult<PyObject> {
        let c = self.inner.channels();
        let b = &self.inner;
        let outs = [if c == 1 { 0 } else { c }];
        let mut o = apply_vec(
            py,
            &[(wo, 3, "wo", Domain::Any), (wi, 3, "wi", Domain::Any)],
            &outs,
            256,
            |_, a, o| {
                b.eval(v3(a[0]), v3(a[1]), o);
                Ok(())
            },
        )?;
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
        let b = &self.inner;
        map_vec(
            py,
            &[(wo, 3, "wo", Domain::Any), (wi, 3, "wi", Domain::Any)],
            |a| b.pdf(v3(a[0]), v3(a[1])),
        )
    }

    /// Directions wi from wo: ``sample(wo, u)`` with uniforms u of shape (..., 3) (the lobe
    /// choice, then the normal's two), or ``sample(wo, rng, n)`` with a
    /// ``numpy.random.Generator``. Returns ``BSDFSample(wi, f, pdf, lobe, specular, eta)``;
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
        n: Option<i64>,
    ) -> PyResult<PyObject> {
        let c = self.inner.channels();
        let b = &self.inner;
        let u = crate::engine::uniforms(py, u, n, 3)?;
        let outs = [3, if c == 1 { 0 } else { c }, 0, 0, 0, 0];
        let mut o = apply_vec(
            py,
            &[(wo, 3, "wo", Domain::Any), (&u, 3, "u", Domain::Uniform)],
            &outs,
            256,
            |_, a, o| {
                b.sample(v3(a[0]), a[1][0], [a[1][1], a[1][2]], o);
                Ok(())
            },
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
        let d = ndf.get().material()?.clone();
        let (eta, k) = (channels(eta)?, channels(k)?);
        let args = vec![
            ndf.clone().into_any().unbind(),
            eta.clone()
                .map(|v| PyTuple::new(py, v))
                .transpose()?
                .into_pyobject(py)?
                .into_any()
                .unbind(),
            k.clone()
                .map(|v| PyTuple::new(py, v))
                .transpose()?
                .into_pyobject(py)?
                .into_any()
                .unbind(),
            masking.into_pyobject(py)?.into_any().unbind(),
            scattering.into_pyobject(py)?.into_any().unbind(),
        ];
        let m = self::masking(masking)?;
        let model = self::model(scattering, m)?;
        let inner = match (eta, k) {
            (None, None) => conductor_of::<1, _>(d, fresnel::One::<1>, m, model),
            (Some(eta), k) => {
                let k = k.unwrap_or_else(|| vec![0.0; eta.len()]);
                if k.len() != eta.len() || eta.is_empty() {
                    return Err(PyValueError::new_err(
                        "eta and k must have the same number of channels (at least one)",
                    ));
                }
                if eta.iter().chain(&k).any(|x| !x.is_finite()) || eta.iter().any(|&x| x <= 0.0) {
                    return Err(PyValueError::new_err(
                        "eta must be positive and finite, k finite",
                    ));
                }
                match eta.len() {
                    1 => conductor_of::<1, _>(
                        d,
                        fresnel::Conductor {
                            eta: [eta[0]],
                            k: [k[0]],
                        },
                        m,
                        model,
                    ),
                    3 => conductor_of::<3, _>(
                        d,
                        fresnel::Conductor {
                            eta: [eta[0], eta[1], eta[2]],
                            k: [k[0], k[1], k[2]],
                        },
                        m,
                        model,
                    ),
                    n => {
                        return Err(PyValueError::new_err(format!(
                            "1 or 3 channels are supported (got {n})"
                        )))
                    }
                }
            }
            (None, Some(_)) => return Err(PyValueError::new_err("k needs eta")),
        };
        Ok((
            Conductor,
            PyBsdf::new(
                py,
                inner,
                args,
                &["ndf", "eta", "k", "masking", "scattering"],
            )?,
        ))
    }
}

/// Dielectric(ndf, eta, masking='correlated', transport='radiance', scattering='single'):
/// a rough dielectric interface of relative index η = η_inside/η_outside (η > 0, ≠ 1),
/// reflection and transmission (Walter et al. 2007), as pbrt-v4's; transport 'radiance'
/// divides a transmitted f by η'² (Veach 1997, §5.2). ``masking``: 'correlated'
/// (1/(1 + Λo + Λi) for both lobes, pbrt-v4's), 'separable' (G1(wo) G1(wi), Mitsuba's) or
/// 'correlated_beta' (a transmission's exact height-correlated B(1 + Λo, 1 + Λi), the
/// random walk's order 1; see the crate's ``bsdf::Masking``); single scattering only. ``scattering`` as for
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
        eta: f64,
        masking: &str,
        transport: &str,
        scattering: &str,
    ) -> PyResult<(Self, PyBsdf)> {
        let py = ndf.py();
        let d = ndf.get().material()?.clone();
        let args = vec![
            ndf.clone().into_any().unbind(),
            eta.into_pyobject(py)?.into_any().unbind(),
            masking.into_pyobject(py)?.into_any().unbind(),
            transport.into_pyobject(py)?.into_any().unbind(),
            scattering.into_pyobject(py)?.into_any().unbind(),
        ];
        if !(eta > 0.0 && eta.is_finite() && eta != 1.0) {
            return Err(PyValueError::new_err(format!(
                "eta must be a positive finite number other than 1 (got {eta})"
            )));
        }
        let m = self::masking(masking)?;
        let t = self::transport(transport)?;
        let inner: Box<dyn AnyBsdf> = match self::model(scattering, m)? {
            // (One channel: a dielectric's f is grey.)
            Model::Single => Box::new(
                bsdf::RoughDielectric::new(d, eta)
                    .with_channels::<1>()
                    .with_masking(m)
                    .with_transport(t),
            ),
            Model::Compensated(s) => Box::new(
                CompensatedDielectric::new(d, eta, s)
                    .with_channels::<1>()
                    .with_transport(t),
            ),
            Model::Walk => Box::new(
                MultipleScattering::<_, _, 1>::new(d, DielectricFacets(eta)).with_transport(t),
            ),
        };
        Ok((
            Dielectric,
            PyBsdf::new(
                py,
                inner,
                args,
                &["ndf", "eta", "masking", "transport", "scattering"],
            )?,
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
