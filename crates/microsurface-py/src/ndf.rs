//! The NDF classes: the base class `NDF` (an isotropic [`AnyNdf`] for the functions of a
//! cosine, the anisotropic [`Material`] for the functions of directions, the samplers, and
//! the walk albedo, whose body is in `albedo`) and its subclasses, one per NDF (`GGX`,
//! `Beckmann`, ..., `GTR`, `StudentT`, `BesselK`, `GenExponential`).

// (The structs carry the classes' Python names: NDF, GGX, GTR.)
#![allow(clippy::upper_case_acronyms)]

use crate::albedo;
use crate::engine::{
    apply, apply_vec, map_vec, named, uniforms, v3, value_error, Domain, Item, PARALLEL,
};
use crate::kernel::{apply_kernel, Kernel, Q};
use crate::material::{Material, Sampler};
use microsurface::{AnyNdf, Exact, MicrofacetDistribution, Ndf, NdfKind, ParamError};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use std::sync::OnceLock;

/// ``Sample(wm, pdf)`` of a sampler per element (parallel from 256 elements: the exact
/// samplers of the family invert quadratures).
fn samples<'py>(
    py: Python<'py>,
    items: &[Item<'_, 'py>],
    f: impl Fn(&[&[f64]]) -> microsurface::Sample<f64> + Sync,
) -> PyResult<PyObject> {
    let o = apply_vec(py, items, &[3, 0], 256, |_, a, o| {
        let s = f(a);
        o[..3].copy_from_slice(&s.wm);
        o[3] = s.pdf;
        Ok(())
    })?;
    named(py, "Sample", o)
}

/// A microfacet NDF of the library (the base class of ``GGX``, ``Beckmann``, ``GTR``, ...).
///
/// Conventions (the crate's): u = cos θ of the microfacet normal (D) or of a direction (Λ, σ,
/// G1, G2); slopes (p, q) = −(x, y)/z of the normal; directions are unit vectors (x, y, z)
/// in the local frame, z the macro normal, as the last axis of an array. D is normalised so
/// that the projected area of the microsurface is 1: ∫ D(m) cos θm dm = 1; D(u) = 0 for
/// u ≤ 0.
///
/// Every class takes ``alpha`` and an optional ``alpha_y`` (anisotropic by stretching; GTR
/// only at γ = 2), ``exact=False`` and ``sampler='posterior'``. The functions of a cosine
/// (``d``, ``lambda_``, ...) are the isotropic NDF's, at ``alpha`` or at an array ``alpha=``
/// broadcast with the arguments; the functions of directions (``d_wm``, ``lambda_w``,
/// ``pdf_visible``, ``sample_visible``, ...), the BSDFs built on the NDF and its albedos are
/// the anisotropic material's.
///
/// **Input.** NaN values give NaN outputs; cosines (``u``, ``u_o``, ``u_i``, ``mu``)
/// outside [−1, 1] (by more than 4ε: a rounded cosine is taken as ±1), uniforms outside
/// [0, 1), an infinite ``phi``, ``walks`` < 1 and ``n`` <
/// 0 raise ``ValueError`` naming the argument; parameters raise the library's
/// ``ValueError``, NaN included. Ctrl-C raises ``KeyboardInterrupt``.
///
/// **Two paths.** The functions of a cosine are always the library's exact f64 path (the
/// research values): closed forms to ≤ 1e-13 relative, numerical quantities (the family's
/// Λ by quadrature, Bessel-K, the generalised exponential) to ≤ 1e-10, measured against
/// mpmath (the crate's tests and README); float32 input gives the float64 value rounded
/// once, except GGX's D, Λ and G1, which run the library's fast slice forms (in f64 within
/// 3e-15 of the exact path, in f32 in f32 arithmetic, within 6e-7). Everything of
/// directions runs, by default, the renderer's fast kernels (Rust: ``AnyMicrofacet<f64>``,
/// bit for bit what a Rust renderer and the ``microsurface`` command line compute): closed
/// forms for GGX (≤ 1e-14 relative of the exact path) and Beckmann (≤ 1e-12); fitted
/// tables of Λ for Double GGX, the Exponential NDF, GTR and the Beckmann mixtures
/// (Student-T, Ei, Erfc, K0, Bessel-K), ≤ 1e-7 relative (D exact or ≤ 1e-11); the
/// generalised exponential has no fast path and runs its exact one either way. Their
/// samplers draw the exact distributions (χ²-tested). ``exact=True`` runs the exact path
/// for the directions too (the validated kernels: 10²–10⁴ times slower for the NDFs
/// without closed forms), with ``sampler`` choosing how the Beckmann mixtures draw visible
/// normals (see ``sampler``). The fits of the fast path are made at the first direction
/// call and cached for the process (GTR: per (α, γ), 1–90 ms; the family: per shape,
/// 1–3 ms, Bessel-K ~0.1 s).
///
/// **Python objects.** Immutable: ``repr`` is the constructor call that builds it
/// (``microsurface.GTR(0.3, gamma=1.5)``), ``==`` and ``hash`` compare the class and the
/// parameters, ``pickle``, ``copy`` and ``deepcopy`` round-trip it.
#[pyclass(subclass, frozen, module = "microsurface")]
#[derive(Clone)]
pub struct NDF {
    ndf: AnyNdf,
    alpha_y: f64,
    /// ``exact=True``: the directions on the exact path.
    exact: bool,
    /// The exact path's sampler (``sampler=``).
    sampler: Sampler,
    /// The direction API's material, built at its first use (the fast path's fits), or why
    /// this material has none (Student-T at γ ≤ 3/2: Λ = ∞).
    material: OnceLock<Result<Material, ParamError>>,
}

impl NDF {
    fn build(
        kind: NdfKind,
        alpha: f64,
        alpha_y: Option<f64>,
        shape: Option<f64>,
        exact: bool,
        sampler: &str,
    ) -> PyResult<Self> {
        let sampler = match sampler {
            "posterior" => Sampler::Posterior,
            "warp" if exact => Sampler::Warp,
            "warp" => {
                return Err(PyValueError::new_err(
                    "sampler='warp' (the exact inversion) is the exact path's: pass exact=True (the fast path draws the Beckmann mixtures by the posterior)",
                ))
            }
            _ => {
                return Err(PyValueError::new_err(format!(
                    "sampler must be 'posterior' or 'warp' (got {sampler:?})"
                )))
            }
        };
        let ndf = AnyNdf::new(kind, alpha, shape).map_err(value_error)?;
        let alpha_y = alpha_y.unwrap_or(alpha);
        // (The parameters of the direction API validated here, cheaply, on the exact path:
        // the fast material, whose fits take milliseconds, is built at its first use.)
        let material = OnceLock::new();
        match Exact::new(kind, alpha, alpha_y, shape) {
            // (Student-T below γ = 3/2 keeps its isotropic functions: D, P22, P2 are
            // finite there; only Λ and what needs it are not.)
            Err(e @ ParamError::Shape { .. }) if kind == NdfKind::StudentT && alpha_y == alpha => {
                let _ = material.set(Err(e));
            }
            Err(e) => return Err(value_error(e)),
            Ok(_) => {}
        }
        Ok(NDF {
            ndf,
            alpha_y,
            exact,
            sampler,
            material,
        })
    }

    /// The parameters `==` and `hash` compare: the kind, α, αy and the shape by their bits
    /// (−0.0 cannot reach them: α > 0), `exact` and the sampler.
    fn key(&self) -> (&'static str, u64, u64, Option<u64>, bool, &'static str) {
        (
            self.ndf.kind().name(),
            self.ndf.alpha().to_bits(),
            self.alpha_y.to_bits(),
            self.ndf.shape().map(f64::to_bits),
            self.exact,
            self.sampler_arg(),
        )
    }

    /// `sampler` as the constructor takes it.
    fn sampler_arg(&self) -> &'static str {
        match self.sampler {
            Sampler::Posterior => "posterior",
            Sampler::Warp => "warp",
        }
    }

    /// The fast path of quantity q, where it is the closed form (GGX).
    fn kernel(&self, q: Q) -> Option<Kernel> {
        Kernel::of(self.ndf.kind(), q)
    }

    /// The same NDF at roughness α (αy scaled with it), for the `alpha=` arrays of the
    /// albedo functions; this material at None (no array given).
    pub fn material_at(&self, alpha: Option<f64>) -> Result<Material, ParamError> {
        let Some(alpha) = alpha else {
            return self.get_material().clone();
        };
        let ay = alpha * (self.alpha_y / self.ndf.alpha());
        let (kind, shape) = (self.ndf.kind(), self.ndf.shape());
        Material::new(kind, alpha, ay, shape, self.exact, self.sampler)
    }

    /// Whether α is a valid roughness of this material's `alpha=` arrays (αy scaled with it;
    /// the exact path's check, cheap, where building the fast material fits tables).
    pub fn check_alpha(&self, alpha: f64) -> Result<(), ParamError> {
        let ay = alpha * (self.alpha_y / self.ndf.alpha());
        Exact::new(self.ndf.kind(), alpha, ay, self.ndf.shape()).map(|_| ())
    }

    /// The direction API's material, or why there is none; built at the first call.
    fn get_material(&self) -> &Result<Material, ParamError> {
        self.material.get_or_init(|| {
            let (kind, shape) = (self.ndf.kind(), self.ndf.shape());
            let ax = self.ndf.alpha();
            Material::new(kind, ax, self.alpha_y, shape, self.exact, self.sampler)
        })
    }

    /// The direction API's material (or why there is none, as a ValueError).
    pub fn material(&self) -> PyResult<&Material> {
        self.get_material().as_ref().map_err(|e| value_error(*e))
    }

    /// The isotropic NDF at each α of `alpha` (broadcast with the arguments), or this one.
    /// `args`: the arguments with their names and domains (cosines, slopes).
    fn iso<'py, const K: usize>(
        &self,
        py: Python<'py>,
        args: [(&Bound<'py, PyAny>, &str, Domain<'_>); K],
        alpha: Option<&Bound<'py, PyAny>>,
        kernel: Option<Kernel>,
        f: impl Fn(&AnyNdf, [f64; K]) -> f64 + Sync,
    ) -> PyResult<PyObject> {
        if let (Some(k), [(u, _, _)]) = (kernel, &args[..]) {
            if alpha.is_some() || self.alpha_y == self.ndf.alpha() {
                return apply_kernel(py, self.ndf.kind(), u, alpha, self.ndf.alpha(), k);
            }
        }
        match alpha {
            None => {
                if self.alpha_y != self.ndf.alpha() {
                    return Err(PyValueError::new_err(
                        "the functions of a cosine are isotropic: this material is anisotropic (alpha_y != alpha); use the direction methods (d_wm, lambda_w, ...) or pass alpha=",
                    ));
                }
                let n = self.ndf;
                apply(py, args, move |x| Ok(f(&n, x)))
            }
            Some(alpha) => {
                let (kind, shape) = (self.ndf.kind(), self.ndf.shape());
                let check = |a: f64| AnyNdf::new(kind, a, shape).map(|_| ());
                // [args..., alpha] through a K + 1 array: the engine's K is const.
                let items: Vec<Item<'_, 'py>> = args
                    .iter()
                    .map(|&(a, name, d)| (a, 0, name, d))
                    .chain(std::iter::once((alpha, 0, "alpha", Domain::Param(&check))))
                    .collect();
                let mut out = apply_vec(py, &items, &[0], PARALLEL, |_, a, o| {
                    let n = AnyNdf::new(kind, a[K][0], shape)?;
                    o[0] = f(&n, std::array::from_fn(|k| a[k][0]));
                    Ok(())
                })?;
                Ok(out.remove(0))
            }
        }
    }
}

/// A cosine argument (u, u_o, u_i): [−1, 1].
fn cosine<'a, 'py>(
    u: &'a Bound<'py, PyAny>,
    name: &'a str,
) -> (&'a Bound<'py, PyAny>, &'a str, Domain<'a>) {
    (u, name, Domain::Cosine)
}

/// A slope argument (p, q): any number.
fn slope<'a, 'py>(
    p: &'a Bound<'py, PyAny>,
    name: &'a str,
) -> (&'a Bound<'py, PyAny>, &'a str, Domain<'a>) {
    (p, name, Domain::Any)
}

#[pymethods]
impl NDF {
    /// The roughness α (αx of an anisotropic material).
    #[getter]
    fn alpha(&self) -> f64 {
        self.ndf.alpha()
    }

    /// αy (α for an isotropic material).
    #[getter]
    fn alpha_y(&self) -> f64 {
        self.alpha_y
    }

    /// The shape parameter (γ of GTR, Student-T and the generalised exponential, a of
    /// Bessel-K), or None.
    #[getter]
    fn shape(&self) -> Option<f64> {
        self.ndf.shape()
    }

    /// Whether the directions, samplers, BSDFs and albedos run the exact path
    /// (``exact=True`` at construction) rather than the fast kernels (the default).
    #[getter]
    fn exact(&self) -> bool {
        self.exact
    }

    /// How ``sample_visible`` (and the BSDFs' ``sample``) draw visible normals. Every
    /// sampler draws the exact distribution; they differ in how wm depends on u. 'warp': an
    /// invertible warp of u (GGX, Beckmann and the generalised exponential on either path;
    /// every NDF with ``exact=True``, except the Beckmann mixtures by default). 'posterior':
    /// the Beckmann mixtures (Student-T, Ei, Erfc, K0, Bessel-K) by the posterior of the
    /// mixing variable, then Beckmann's visible normals (~0.2 µs a sample; uniforms from a
    /// stream seeded by u, so deterministic in u but not a warp of it), on both paths.
    /// 'rejection': the fast samplers of Double GGX, the Exponential NDF and GTR at γ ≠ 2
    /// (u for the first candidate, a stream seeded by u after it). ``exact=True,
    /// sampler='warp'`` draws the Beckmann mixtures by the exact inversion (a warp of u; it
    /// inverts quadratures, 8 µs to 3 ms a sample, 20 ms near Student-T's γ = 3/2).
    #[getter]
    fn sampler(&self) -> &'static str {
        match self.get_material() {
            Ok(m) => m.sampler_name(),
            // (No direction API: Student-T at γ ≤ 3/2.)
            Err(_) if self.sampler == Sampler::Posterior => "posterior",
            Err(_) => "warp",
        }
    }

    /// The NDF's name, as the command line spells it (``ggx``, ``student_t``, ...).
    #[getter]
    fn name(&self) -> &'static str {
        self.ndf.kind().name()
    }

    /// The constructor call that builds this NDF, evaluable back:
    /// ``microsurface.GTR(0.3, gamma=1.5, alpha_y=0.2, exact=True)`` (numbers as Python
    /// writes them, so the round trip is exact; defaults left out).
    fn __repr__(slf: &Bound<'_, Self>) -> PyResult<String> {
        let py = slf.py();
        let this = slf.get();
        let num = |x: f64| -> PyResult<String> { Ok(x.into_pyobject(py)?.repr()?.to_string()) };
        let mut s = format!(
            "microsurface.{}({}",
            slf.get_type().name()?,
            num(this.ndf.alpha())?
        );
        if let (Some(shape), Some(name)) = (this.ndf.shape(), this.ndf.kind().shape_name()) {
            s += &format!(", {name}={}", num(shape)?);
        }
        if this.alpha_y != this.ndf.alpha() {
            s += &format!(", alpha_y={}", num(this.alpha_y)?);
        }
        if this.exact {
            s += ", exact=True";
        }
        if this.sampler == Sampler::Warp {
            s += ", sampler='warp'";
        }
        Ok(s + ")")
    }

    /// The constructor's arguments (``pickle``, ``copy``; joblib and multiprocessing pass
    /// NDFs this way): (class, (alpha[, shape], alpha_y, exact, sampler)).
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        let this = slf.get();
        let sampler = this.sampler_arg();
        let args = match this.ndf.shape() {
            Some(shape) => {
                (this.ndf.alpha(), shape, this.alpha_y, this.exact, sampler).into_pyobject(py)?
            }
            None => (this.ndf.alpha(), this.alpha_y, this.exact, sampler).into_pyobject(py)?,
        };
        Ok((slf.get_type().into_any(), args))
    }

    /// An NDF is immutable: its copy is itself (its cached fast-path material shared).
    fn __copy__(slf: PyRef<'_, Self>) -> PyRef<'_, Self> {
        slf
    }

    /// As ``__copy__``.
    fn __deepcopy__<'py>(slf: PyRef<'py, Self>, _memo: &Bound<'py, PyAny>) -> PyRef<'py, Self> {
        slf
    }

    /// Equal when of the same class with the same parameters (α, αy, shape, ``exact``,
    /// ``sampler``).
    fn __eq__(slf: &Bound<'_, Self>, other: &Bound<'_, PyAny>) -> bool {
        let Ok(o) = other.downcast::<NDF>() else {
            return false;
        };
        slf.get_type().is(o.get_type()) && slf.get().key() == o.get().key()
    }

    /// By the parameters ``==`` compares.
    fn __hash__(slf: &Bound<'_, Self>) -> PyResult<isize> {
        let key = slf.get().key();
        let mut h = std::collections::hash_map::DefaultHasher::new();
        std::hash::Hash::hash(&slf.get_type().name()?.to_string(), &mut h);
        std::hash::Hash::hash(&key, &mut h);
        Ok(std::hash::Hasher::finish(&h) as isize)
    }

    /// D(u): the density of microfacet normals per solid angle at u = cos θm ∈ [−1, 1] (0 for u ≤ 0;
    /// +∞ at u = 1 for the NDFs with a pole there: Ei, Erfc, K0, Bessel-K a ≤ 1).
    /// ``alpha``: an array of roughnesses broadcast with u (default: this NDF's).
    #[pyo3(signature = (u, alpha = None))]
    fn d(
        &self,
        py: Python<'_>,
        u: &Bound<'_, PyAny>,
        alpha: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyObject> {
        self.iso(py, [cosine(u, "u")], alpha, self.kernel(Q::D), |n, [u]| {
            n.d(u)
        })
    }

    /// Smith's Λ(u) of a direction at u = cos θ (Λ(|u|) for u < 0; +∞ at u = 0; 0 at 1).
    /// (``lambda`` is a Python keyword.) ``alpha`` as for ``d``.
    #[pyo3(signature = (u, alpha = None))]
    fn lambda_(
        &self,
        py: Python<'_>,
        u: &Bound<'_, PyAny>,
        alpha: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyObject> {
        self.iso(
            py,
            [cosine(u, "u")],
            alpha,
            self.kernel(Q::Lambda),
            |n, [u]| n.lambda(u),
        )
    }

    /// The projected area σ(u) = ∫ max(0, ω·m) D(m) dm of a direction at signed u = cos θ
    /// (σ(u) = u(1 + Λ(u)) above the horizon, |u| Λ(|u|) below; σ(0) finite). ``alpha`` as
    /// for ``d``.
    #[pyo3(signature = (u, alpha = None))]
    fn sigma(
        &self,
        py: Python<'_>,
        u: &Bound<'_, PyAny>,
        alpha: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyObject> {
        self.iso(py, [cosine(u, "u")], alpha, None, |n, [u]| n.sigma(u))
    }

    /// Smith's masking G1(u) = 1/(1 + Λ(|u|)). ``alpha`` as for ``d``.
    #[pyo3(signature = (u, alpha = None))]
    fn g1(
        &self,
        py: Python<'_>,
        u: &Bound<'_, PyAny>,
        alpha: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyObject> {
        self.iso(py, [cosine(u, "u")], alpha, self.kernel(Q::G1), |n, [u]| {
            n.g1(u)
        })
    }

    /// Height-correlated masking-shadowing G2(u_o, u_i) = 1/(1 + Λ(u_o) + Λ(u_i)) (Heitz
    /// 2014), broadcast over both arguments. ``alpha`` as for ``d``.
    #[pyo3(signature = (u_o, u_i, alpha = None))]
    fn g2(
        &self,
        py: Python<'_>,
        u_o: &Bound<'_, PyAny>,
        u_i: &Bound<'_, PyAny>,
        alpha: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyObject> {
        self.iso(
            py,
            [cosine(u_o, "u_o"), cosine(u_i, "u_i")],
            alpha,
            None,
            |n, [a, b]| n.g2(a, b),
        )
    }

    /// Separable masking-shadowing G1(u_o) G1(u_i), broadcast over both arguments.
    #[pyo3(signature = (u_o, u_i, alpha = None))]
    fn g2_separable(
        &self,
        py: Python<'_>,
        u_o: &Bound<'_, PyAny>,
        u_i: &Bound<'_, PyAny>,
        alpha: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyObject> {
        self.iso(
            py,
            [cosine(u_o, "u_o"), cosine(u_i, "u_i")],
            alpha,
            None,
            |n, [a, b]| n.g2_separable(a, b),
        )
    }

    /// The slope density P22(p, q) = D(u) u⁴ (u = 1/√(1 + p² + q²)), broadcast over p and q.
    #[pyo3(signature = (p, q, alpha = None))]
    fn p22(
        &self,
        py: Python<'_>,
        p: &Bound<'_, PyAny>,
        q: &Bound<'_, PyAny>,
        alpha: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyObject> {
        self.iso(
            py,
            [slope(p, "p"), slope(q, "q")],
            alpha,
            None,
            |n, [p, q]| n.p22(p, q),
        )
    }

    /// The marginal slope density P2(p) = ∫ P22(p, q) dq.
    #[pyo3(signature = (p, alpha = None))]
    fn p2(
        &self,
        py: Python<'_>,
        p: &Bound<'_, PyAny>,
        alpha: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyObject> {
        self.iso(py, [slope(p, "p")], alpha, None, |n, [p]| n.p2(p))
    }

    // ---- Directions: the anisotropic material (Rust: microsurface::AnyMicrofacet, or
    // microsurface::Exact with exact=True; the Distribution trait). Arrays of unit vectors,
    // last axis 3.

    /// D(wm) of unit normals wm (shape (..., 3)); 0 for wm.z ≤ 0.
    fn d_wm(&self, py: Python<'_>, wm: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        let e = self.material()?;
        map_vec(py, &[(wm, 3, "wm", Domain::Any)], |a| e.d(v3(a[0])))
    }

    /// Smith Λ(w) of directions w (the side w comes from; +∞ on the horizon).
    fn lambda_w(&self, py: Python<'_>, w: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        let e = self.material()?;
        map_vec(py, &[(w, 3, "w", Domain::Any)], |a| e.lambda(v3(a[0])))
    }

    /// G1(w) = 1/(1 + Λ(w)).
    fn g1_w(&self, py: Python<'_>, w: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        let e = self.material()?;
        map_vec(py, &[(w, 3, "w", Domain::Any)], |a| e.g1(v3(a[0])))
    }

    /// The projected area σ(w) = |w.z|(1 + Λ(w)) (finite on the horizon), w mirrored to
    /// the upper hemisphere.
    fn sigma_w(&self, py: Python<'_>, w: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        let e = self.material()?;
        map_vec(py, &[(w, 3, "w", Domain::Any)], |a| e.sigma(v3(a[0])))
    }

    /// Height-correlated G2(wo, wi) = 1/(1 + Λ(wo) + Λ(wi)); ``separable=True``:
    /// G1(wo) G1(wi).
    #[pyo3(signature = (wo, wi, separable = false))]
    fn g2_w(
        &self,
        py: Python<'_>,
        wo: &Bound<'_, PyAny>,
        wi: &Bound<'_, PyAny>,
        separable: bool,
    ) -> PyResult<PyObject> {
        let e = self.material()?;
        map_vec(
            py,
            &[(wo, 3, "wo", Domain::Any), (wi, 3, "wi", Domain::Any)],
            |a| {
                let (wo, wi) = (v3(a[0]), v3(a[1]));
                if separable {
                    e.g2_separable(wo, wi)
                } else {
                    e.g2(wo, wi)
                }
            },
        )
    }

    /// The visible-normal density D_w(wm) = G1(w) max(0, w·wm) D(wm)/|w.z| per solid angle
    /// of wm (w.z < 0: that of −w), the pdf of ``sample_visible``.
    fn pdf_visible(
        &self,
        py: Python<'_>,
        w: &Bound<'_, PyAny>,
        wm: &Bound<'_, PyAny>,
    ) -> PyResult<PyObject> {
        let e = self.material()?;
        map_vec(
            py,
            &[(w, 3, "w", Domain::Any), (wm, 3, "wm", Domain::Any)],
            |a| e.pdf(v3(a[0]), v3(a[1])),
        )
    }

    /// Visible normals for directions w: ``sample_visible(w, u)`` with uniforms u of shape
    /// (..., 2) in [0, 1) (broadcast with w's batch shape; others raise ValueError, NaN gives
    /// NaN), or ``sample_visible(w, rng, n)``
    /// with a ``numpy.random.Generator`` (n × 2 uniforms drawn from it). Returns
    /// ``Sample(wm, pdf)``: unit normals (..., 3) and their densities ``pdf_visible(w,
    /// wm)``. Samplers of the exact distribution (χ²-tested in the crate; ``sampler`` says
    /// which): each wm is a deterministic function of (w, u).
    #[pyo3(signature = (w, u, n = None))]
    fn sample_visible(
        &self,
        py: Python<'_>,
        w: &Bound<'_, PyAny>,
        u: &Bound<'_, PyAny>,
        n: Option<i64>,
    ) -> PyResult<PyObject> {
        let e = self.material()?;
        let u = uniforms(py, u, n, 2)?;
        samples(
            py,
            &[(w, 3, "w", Domain::Any), (&u, 2, "u", Domain::Uniform)],
            |a| e.sample(v3(a[0]), [a[1][0], a[1][1]]),
        )
    }

    /// The density D(wm) cos θm of ``sample_dcos`` (0 for wm.z ≤ 0).
    fn pdf_dcos(&self, py: Python<'_>, wm: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        let e = self.material()?;
        map_vec(py, &[(wm, 3, "wm", Domain::Any)], |a| e.pdf_dcos(v3(a[0])))
    }

    /// Normals distributed as D(m) cos θm: ``sample_dcos(u)`` (u of shape (..., 2)) or
    /// ``sample_dcos(rng, n)``; returns ``Sample(wm, pdf)``.
    #[pyo3(signature = (u, n = None))]
    fn sample_dcos(
        &self,
        py: Python<'_>,
        u: &Bound<'_, PyAny>,
        n: Option<i64>,
    ) -> PyResult<PyObject> {
        let e = self.material()?;
        let u = uniforms(py, u, n, 2)?;
        samples(py, &[(&u, 2, "u", Domain::Uniform)], |a| {
            e.sample_dcos([a[0][0], a[0][1]])
        })
    }

    // ---- Multiple scattering.

    /// The albedo of the microsurface by scattering order, by Heitz et al.'s random walk
    /// (2016; uniform heights), from directions at cos θo = ``mu`` and azimuth ``phi``
    /// (broadcast together): F = 1 mirror facets (the white furnace, a conductor's
    /// energy), or dielectric facets of relative index ``eta``. ``walks`` walks per
    /// element, seeded by ``seed`` and the element's index (the same numbers whatever the
    /// threads). Returns ``Albedo(reflect, reflect_stderr, transmit, transmit_stderr,
    /// total, total_stderr)``: reflect and transmit of shape (..., 4) for the orders 1, 2,
    /// 3 and ≥ 4, with their standard errors; total (...) is reflect + transmit summed
    /// over orders. ``mu`` ∈ [−1, 1], ``phi`` finite, ``walks`` ≥ 1 (else ValueError); a NaN
    /// ``mu`` or ``phi`` gives NaN fields. ``alpha``: an array of roughnesses broadcast with mu and phi (αy scaled
    /// with α), for tables over (α, μ) in one call. The walk runs this NDF's path (fast by
    /// default, ``exact=True`` the exact one).
    #[pyo3(signature = (mu, phi = None, walks = 100_000, seed = 0, eta = None, alpha = None))]
    #[allow(clippy::too_many_arguments)]
    fn albedo(
        &self,
        py: Python<'_>,
        mu: &Bound<'_, PyAny>,
        phi: Option<&Bound<'_, PyAny>>,
        walks: i64,
        seed: i128,
        eta: Option<f64>,
        alpha: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyObject> {
        albedo::walk(self, py, mu, phi, walks, seed, eta, alpha)
    }
}

/// The classes of the NDFs without a shape parameter: `Name(alpha, alpha_y=None, exact=False,
/// sampler='posterior')`.
macro_rules! plain {
    ($($(#[$doc:meta])* $name:ident => $kind:ident;)*) => {$(
        $(#[$doc])*
        ///
        /// Directions, samplers, BSDFs and albedos run the fast kernels; ``exact=True``: the
        /// exact path, with ``sampler='posterior'`` or ``'warp'`` (see ``NDF``).
        #[pyclass(extends = NDF, module = "microsurface")]
        pub struct $name;

        #[pymethods]
        impl $name {
            #[new]
            #[pyo3(signature = (alpha, alpha_y = None, exact = false, sampler = "posterior"))]
            fn new(
                alpha: f64,
                alpha_y: Option<f64>,
                exact: bool,
                sampler: &str,
            ) -> PyResult<(Self, NDF)> {
                let ndf = NDF::build(NdfKind::$kind, alpha, alpha_y, None, exact, sampler)?;
                Ok(($name, ndf))
            }
        }
    )*};
}

/// The classes of the NDFs with a shape parameter: `Name(alpha, shape, alpha_y=None,
/// exact=False, sampler='posterior')`.
macro_rules! shaped {
    ($($(#[$doc:meta])* $name:ident => $kind:ident, $shape:ident;)*) => {$(
        $(#[$doc])*
        ///
        /// Directions, samplers, BSDFs and albedos run the fast kernels; ``exact=True``: the
        /// exact path, with ``sampler='posterior'`` or ``'warp'`` (see ``NDF``).
        #[pyclass(extends = NDF, module = "microsurface")]
        pub struct $name;

        #[pymethods]
        impl $name {
            #[new]
            #[pyo3(signature = (alpha, $shape, alpha_y = None, exact = false, sampler = "posterior"))]
            fn new(
                alpha: f64,
                $shape: f64,
                alpha_y: Option<f64>,
                exact: bool,
                sampler: &str,
            ) -> PyResult<(Self, NDF)> {
                let ndf = NDF::build(NdfKind::$kind, alpha, alpha_y, Some($shape), exact, sampler)?;
                Ok(($name, ndf))
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

/// Adds `NDF` and its subclasses to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
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
