//! The NDF classes: the base class `NDF` (an isotropic [`AnyNdf`] for the functions of a
//! cosine, the anisotropic [`Material`] for the functions of directions, the samplers, and
//! the walk albedo, whose body is in `albedo`) and its subclasses, one per NDF (`GGX`,
//! `Beckmann`, ..., `GTR`, `StudentT`, `BesselK`, `GenExponential`).

// (The structs carry the classes' Python names: NDF, GGX, GTR.)
#![allow(clippy::upper_case_acronyms)]

use crate::albedo;
use crate::engine::{apply, apply_vec, named, uniforms, v3, value_error, Domain, Item, PARALLEL};
use crate::engine::{is_number, Args};
use crate::kernel::{apply_kernel, Kernel, BLOCK, Q};
use crate::material::{mixture, with_isotropic, with_material, Material, Sampler, P};
use crate::params::{self, Arrays, Param};
use microsurface::{
    AnyMicrofacet, AnyNdf, Exact, MicrofacetDistribution, Ndf, NdfKind, ParamError,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use std::sync::OnceLock;

/// A microfacet NDF of the library (the base class of ``GGX``, ``Beckmann``, ``GTR``, ...).
///
/// Conventions (the crate's): u = cos θ of the microfacet normal (D) or of a direction (Λ, σ,
/// G1, G2); slopes (p, q) = −(x, y)/z of the normal; directions are unit vectors (x, y, z)
/// in the local frame, z the macro normal, as the last axis of an array. D is normalised so
/// that the projected area of the microsurface is 1: ∫ D(m) cos θm dm = 1; D(u) = 0 for
/// u ≤ 0.
///
/// Every class takes ``alpha`` and an optional ``alpha_y`` (anisotropic by stretching; GTR
/// only at γ = 2), its shape parameter where it has one, ``exact=False`` and
/// ``sampler='posterior'``. The functions of a cosine (``d``, ``lambda_``, ...) are the
/// isotropic NDF's; the functions of directions (``d_wm``, ``lambda_w``, ``pdf_visible``,
/// ``sample_visible``, ...), the BSDFs built on the NDF and its albedos are the anisotropic
/// material's.
///
/// **Parameters as arrays** (SciPy's frozen distributions): ``alpha``, ``alpha_y`` and the
/// shape may each be a number or an array. The arrays broadcast together when the object is
/// built (``param_shape``), and in every method with the method's arguments: the output has
/// the broadcast shape, one material per element (``GGX(np.array([0.1, 0.3])[:, None]).d(u)``
/// is (2, len(u))), computed in one loop in Rust. A material is built once for a run of
/// elements with the same parameters; the fast path of GTR fits Λ per (α, γ) (1–90 ms each,
/// cached for the process) and the family per shape, so sweep those over few distinct
/// values, or use the exact path (the functions of a cosine by default). Every element is
/// validated at construction (a bad one raises ValueError with its index). The output's
/// dtype follows the method's arguments, not the parameters'.
///
/// **Input.** NaN values give NaN outputs; cosines (``u``, ``u_o``, ``u_i``, ``mu``)
/// outside [−1, 1] (by more than 4ε: a rounded cosine is taken as ±1), uniforms outside
/// [0, 1), an infinite ``phi``, ``walks`` < 1 and ``n`` <
/// 0 raise ``ValueError`` naming the argument; parameters raise the library's
/// ``ValueError``, NaN included. Ctrl-C raises ``KeyboardInterrupt``.
///
/// **Two paths.** The functions of a cosine are, by default, the library's exact f64 path
/// (the research values): closed forms to ≤ 1e-13 relative, numerical quantities (the
/// family's Λ by quadrature, Bessel-K, the generalised exponential) to ≤ 1e-10, measured
/// against mpmath (the crate's tests and README); float32 input gives the float64 value
/// rounded once, except GGX's D, Λ and G1, which run the library's fast slice forms (in f64
/// within 3e-15 of the exact path, in f32 in f32 arithmetic, within 6e-7). With
/// ``fast=True`` (``d``, ``lambda_``, ``sigma``, ``g1``, ``g2``, ``g2_separable``) they run
/// the renderer's fast kernels instead, the same ones as the directions below, at the
/// direction of cosine u: closed forms for GGX (≤ 1e-14 relative of the exact path) and
/// Beckmann (≤ 1e-12), fitted tables of Λ (≤ 1e-7 relative; D exact or ≤ 1e-11) for the
/// others; the slope densities and the generalised exponential have no fast path and run
/// the exact one. The fast bounds are relative for values above 1e-200 and absolute
/// (1e-200) below, as the fitted tables state (near the normal Ei's and Erfc's fast Λ
/// stops at ~1e-301 where the exact one falls to 0), and hold for D in the normal range
/// (where D is subnormal, Beckmann's at θ = 83° for α = 0.3, the two paths round
/// differently). ``g2(u_o[:, None], u_i)`` evaluates Λ per pair: over an outer grid, Λ of
/// each cosine once (``lambda_``) and 1/(1 + Λo + Λi) are faster. Everything of
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
    kind: NdfKind,
    /// α (αx of an anisotropic material), αy (None: α) and the shape, numbers or arrays.
    alpha: Param,
    alpha_y: Option<Param>,
    shape: Option<Param>,
    /// ``exact=True``: the directions on the exact path.
    exact: bool,
    /// The exact path's sampler (``sampler=``).
    sampler: Sampler,
    /// The parameter arrays' broadcast shape; None where every parameter is a number.
    batch: Option<Vec<usize>>,
    /// Whether αy = α at every element (the functions of a cosine need it).
    isotropic: bool,
    /// How `sample_visible` draws (`NDF.sampler`).
    sampler_name: &'static str,
    /// Every parameter a number: the isotropic NDF and the direction API's material.
    one: Option<One>,
}

/// The NDF of an object whose parameters are numbers.
#[derive(Clone)]
struct One {
    ndf: AnyNdf,
    p: P,
    /// The direction API's material, built at its first use (the fast path's fits), or why
    /// this material has none (Student-T at γ ≤ 3/2: Λ = ∞).
    material: OnceLock<Result<Material, ParamError>>,
}

/// The quantities of a cosine.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Cos {
    D,
    Lambda,
    Sigma,
    G1,
    G2,
    G2Separable,
    P22,
    P2,
}

impl Cos {
    /// The exact path's value (the library's `Ndf` methods).
    #[inline]
    fn exact(self, n: &AnyNdf, x: &[f64]) -> f64 {
        match self {
            Cos::D => n.d(x[0]),
            Cos::Lambda => n.lambda(x[0]),
            Cos::Sigma => n.sigma(x[0]),
            Cos::G1 => n.g1(x[0]),
            Cos::G2 => n.g2(x[0], x[1]),
            Cos::G2Separable => n.g2_separable(x[0], x[1]),
            Cos::P22 => n.p22(x[0], x[1]),
            Cos::P2 => n.p2(x[0]),
        }
    }

    /// Whether `fast=True` has a path of its own (the slope densities have none).
    fn has_fast(self) -> bool {
        !matches!(self, Cos::P22 | Cos::P2)
    }

    /// The fast path's value: the renderer's material (isotropic) at the direction of cosine
    /// u in the xz plane, with the cosine functions' conventions: D(u ≤ 0) = 0, Λ(u < 0) =
    /// −1 − Λ(|u|), σ(u < 0) = |u| Λ(|u|), G1 and G2 of |u|.
    #[inline(always)]
    fn fast(self, m: &AnyMicrofacet<f64>, x: &[f64]) -> f64 {
        match self {
            Cos::D => m.d(w(x[0])),
            Cos::Lambda => {
                let u = x[0];
                let l = m.lambda(w(u));
                if u < 0.0 {
                    -1.0 - l
                } else {
                    l
                }
            }
            Cos::Sigma => {
                let u = x[0];
                let l = m.lambda(w(u));
                if u != 0.0 && l.is_finite() {
                    if u > 0.0 {
                        u + u * l
                    } else {
                        -u * l
                    }
                } else {
                    // (On the horizon, Λ = ∞: the exact σ(0).)
                    m.exact().sigma(w(u))
                }
            }
            Cos::G1 => m.g1(w(x[0])),
            Cos::G2 => m.g2(w(x[0]), w(x[1])),
            Cos::G2Separable => m.g2_separable(w(x[0]), w(x[1])),
            Cos::P22 | Cos::P2 => unreachable!("no fast path: has_fast"),
        }
    }

    /// [`Cos::fast`] over blocks of cosines (`u`, and `v` for G2), `self` matched once per
    /// block and the loop over one material, whose run-time dispatch LLVM hoists out of it
    /// (the door's methods are inlined whole); NaN in, NaN out.
    fn fast_block(self, m: &AnyMicrofacet<f64>, u: &[f64], v: Option<&[f64]>, out: &mut [f64]) {
        macro_rules! each {
            (|$u:ident| $e:expr) => {{
                for (o, &$u) in out.iter_mut().zip(u) {
                    *o = if $u.is_nan() { $u } else { $e };
                }
            }};
        }
        macro_rules! each2 {
            (|$a:ident, $b:ident| $e:expr) => {{
                let v = v.expect("two cosines");
                for ((o, &$a), &$b) in out.iter_mut().zip(u).zip(v) {
                    *o = if $a.is_nan() || $b.is_nan() {
                        f64::NAN
                    } else {
                        $e
                    };
                }
            }};
        }
        match self {
            Cos::D => each!(|u| m.d(w(u))),
            Cos::Lambda => each!(|u| Cos::Lambda.fast(m, &[u])),
            Cos::Sigma => each!(|u| Cos::Sigma.fast(m, &[u])),
            Cos::G1 => each!(|u| m.g1(w(u))),
            Cos::G2 => each2!(|a, b| m.g2(w(a), w(b))),
            Cos::G2Separable => each2!(|a, b| m.g2_separable(w(a), w(b))),
            Cos::P22 | Cos::P2 => unreachable!("no fast path: has_fast"),
        }
    }

    /// The GGX closed form's slice kernel, where it has one.
    fn kernel(self, kind: NdfKind) -> Option<Kernel> {
        let q = match self {
            Cos::D => Q::D,
            Cos::Lambda => Q::Lambda,
            Cos::G1 => Q::G1,
            _ => return None,
        };
        Kernel::of(kind, q)
    }
}

/// The quantities of directions that the blocks evaluate (σ goes through `Material::sigma`).
#[derive(Clone, Copy)]
enum Dir {
    D,
    Lambda,
    G1,
    G2,
    G2Separable,
    Pdf,
    PdfDcos,
}

impl Dir {
    /// Every quantity, in the order of their discriminants.
    const ALL: [Dir; 7] = [
        Dir::D,
        Dir::Lambda,
        Dir::G1,
        Dir::G2,
        Dir::G2Separable,
        Dir::Pdf,
        Dir::PdfDcos,
    ];

    /// The quantity at one or two directions.
    #[inline(always)]
    fn eval<M: MicrofacetDistribution<f64>>(self, m: &M, a: [f64; 3], b: [f64; 3]) -> f64 {
        match self {
            Dir::D => m.d(a),
            Dir::Lambda => m.lambda(a),
            Dir::G1 => m.g1(a),
            Dir::G2 => m.g2(a, b),
            Dir::G2Separable => m.g2_separable(a, b),
            Dir::Pdf => m.pdf(a, b),
            Dir::PdfDcos => m.pdf_dcos(a),
        }
    }

    /// Over a block of directions (`x`, and `y` for the two-direction quantities, 3 numbers
    /// each), `self` matched once and the loop over one material (whose dispatch LLVM then
    /// hoists); NaN in any number of an element gives NaN.
    fn block<M: MicrofacetDistribution<f64>>(
        self,
        m: &M,
        x: &[f64],
        y: Option<&[f64]>,
        out: &mut [f64],
    ) {
        // (One function per quantity, the quantity a constant in it: inlined into one
        // function, the seven loops exhausted LLVM's inlining budget, and Double GGX's D was
        // then called per element, 1.7× the Rust loop.)
        #[inline(never)]
        fn run<M: MicrofacetDistribution<f64>, const Q: u8>(
            m: &M,
            x: &[f64],
            y: Option<&[f64]>,
            out: &mut [f64],
        ) {
            let q = Dir::ALL[Q as usize];
            // (A one-direction quantity reads x twice: the loop is the same.)
            let y = y.unwrap_or(x);
            let (x, y) = (&x[..3 * out.len()], &y[..3 * out.len()]);
            out.iter_mut().enumerate().for_each(|(k, o)| {
                let a = [x[3 * k], x[3 * k + 1], x[3 * k + 2]];
                let b = [y[3 * k], y[3 * k + 1], y[3 * k + 2]];
                let nan = a.iter().chain(&b).fold(false, |n, v| n | v.is_nan());
                *o = if nan { f64::NAN } else { q.eval(m, a, b) };
            });
        }
        match self {
            Dir::D => run::<M, 0>(m, x, y, out),
            Dir::Lambda => run::<M, 1>(m, x, y, out),
            Dir::G1 => run::<M, 2>(m, x, y, out),
            Dir::G2 => run::<M, 3>(m, x, y, out),
            Dir::G2Separable => run::<M, 4>(m, x, y, out),
            Dir::Pdf => run::<M, 5>(m, x, y, out),
            Dir::PdfDcos => run::<M, 6>(m, x, y, out),
        }
    }
}

/// The unit direction of cosine u in the xz plane (the fast path's argument for the
/// functions of a cosine: an isotropic material reads only its z).
#[inline(always)]
fn w(u: f64) -> [f64; 3] {
    [((1.0 - u) * (1.0 + u)).max(0.0).sqrt(), 0.0, u]
}

/// The ValueError of a cosine function called on an anisotropic material.
fn anisotropic() -> PyErr {
    PyValueError::new_err(
        "the functions of a cosine are isotropic: this material is anisotropic (alpha_y != alpha); use the direction methods (d_wm, lambda_w, ...)",
    )
}

impl NDF {
    fn build(
        py: Python<'_>,
        kind: NdfKind,
        alpha: &Bound<'_, PyAny>,
        alpha_y: Option<&Bound<'_, PyAny>>,
        shape: Option<&Bound<'_, PyAny>>,
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
        let alpha = Param::new(py, alpha, "alpha")?;
        let mut alpha_y = alpha_y.map(|a| Param::new(py, a, "alpha_y")).transpose()?;
        // (αy equal to α as numbers is the isotropic material: written without it.)
        if let (Some(ay), Some(a)) = (alpha_y.as_ref().and_then(Param::num), alpha.num()) {
            if ay.to_bits() == a.to_bits() {
                alpha_y = None;
            }
        }
        let shape_name = kind.shape_name().unwrap_or("shape");
        let shape = shape.map(|s| Param::new(py, s, shape_name)).transpose()?;
        let mut named = vec![("alpha", &alpha)];
        if let Some(ay) = &alpha_y {
            named.push(("alpha_y", ay));
        }
        if let Some(s) = &shape {
            named.push((shape_name, s));
        }
        let batch = params::broadcast(py, &named)?;
        // Every element: the isotropic NDF (its functions of a cosine) and the direction
        // API's parameters, checked cheaply on the exact path (the fast material, whose fits
        // take milliseconds, is built at its first use). Student-T below γ = 3/2 keeps its
        // isotropic functions (D, P22, P2 are finite there; only Λ and what needs it are
        // not): its direction API's error comes at its use.
        let isotropic = std::cell::Cell::new(true);
        let rejection = std::cell::Cell::new(false);
        let (has_ay, has_shape) = (alpha_y.is_some(), shape.is_some());
        let check = |v: &[f64]| -> Result<P, ParamError> {
            let a = v[0];
            let ay = if has_ay { v[1] } else { a };
            let s = has_shape.then(|| v[v.len() - 1]);
            AnyNdf::new(kind, a, s)?;
            match Exact::new(kind, a, ay, s) {
                Err(ParamError::Shape { .. }) if kind == NdfKind::StudentT && ay == a => {}
                Err(e) => return Err(e),
                Ok(_) => {}
            }
            isotropic.set(isotropic.get() && ay == a);
            rejection.set(rejection.get() || (kind == NdfKind::Gtr && s != Some(2.0)));
            Ok(P {
                alpha: a,
                alpha_y: ay,
                shape: s,
            })
        };
        let one = match &batch {
            None => {
                let v: Vec<f64> = named.iter().map(|(_, p)| p.num().unwrap()).collect();
                let p = check(&v).map_err(value_error)?;
                let ndf = AnyNdf::new(kind, p.alpha, p.shape).map_err(value_error)?;
                let material = OnceLock::new();
                if let Err(e) = Exact::new(kind, p.alpha, p.alpha_y, p.shape) {
                    let _ = material.set(Err(e));
                }
                Some(One { ndf, p, material })
            }
            Some(b) => {
                params::validate(py, &named, b, |v| check(v).map(|_| ()))?;
                None
            }
        };
        let sampler_name = match sampler {
            Sampler::Warp => "warp",
            Sampler::Posterior if mixture(kind) => "posterior",
            Sampler::Posterior if exact => "warp",
            Sampler::Posterior => match kind {
                NdfKind::DoubleGgx | NdfKind::Exponential => "rejection",
                NdfKind::Gtr if rejection.get() => "rejection",
                _ => "warp",
            },
        };
        Ok(NDF {
            kind,
            alpha,
            alpha_y,
            shape,
            exact,
            sampler,
            batch,
            isotropic: isotropic.get(),
            sampler_name,
            one,
        })
    }

    /// `sampler` as the constructor takes it.
    fn sampler_arg(&self) -> &'static str {
        match self.sampler {
            Sampler::Posterior => "posterior",
            Sampler::Warp => "warp",
        }
    }

    /// The parameter arrays, as the engine's arguments (α, αy, the shape: those that are
    /// arrays, in this order); empty where every parameter is a number.
    pub fn arrays<'py>(&self, py: Python<'py>) -> Arrays<'py> {
        let shape_name = self.kind.shape_name().unwrap_or("shape");
        [
            (Some(&self.alpha), "alpha"),
            (self.alpha_y.as_ref(), "alpha_y"),
            (self.shape.as_ref(), shape_name),
        ]
        .into_iter()
        .filter_map(|(p, name)| match p {
            Some(Param::Arr(a)) => Some((a.bind(py).clone(), name)),
            _ => None,
        })
        .collect()
    }

    /// One element's parameters from the values of [`NDF::arrays`] there (in their order).
    #[inline]
    pub fn p_of(&self, v: &[f64]) -> P {
        if let Some(one) = &self.one {
            return one.p;
        }
        let mut v = v.iter().copied();
        let mut get = |p: &Param| match p {
            Param::Num(x) => *x,
            Param::Arr(_) => v.next().expect("one value per array"),
        };
        let alpha = get(&self.alpha);
        let alpha_y = self.alpha_y.as_ref().map_or(alpha, &mut get);
        let shape = self.shape.as_ref().map(&mut get);
        P {
            alpha,
            alpha_y,
            shape,
        }
    }

    /// `f` of the direction API's material at `p` (built once for a run of elements with the
    /// same parameters; this object's own where its parameters are numbers).
    #[inline]
    pub fn with_material<R>(&self, p: P, f: impl FnOnce(&Material) -> R) -> Result<R, ParamError> {
        if let Some(one) = &self.one {
            return match self.get_material(one) {
                Ok(m) => Ok(f(m)),
                Err(e) => Err(*e),
            };
        }
        with_material(self.kind, p, self.exact, self.sampler, f)
    }

    /// The direction API's material, or why there is none; built at the first call.
    fn get_material<'a>(&self, one: &'a One) -> &'a Result<Material, ParamError> {
        one.material.get_or_init(|| {
            let p = one.p;
            Material::new(
                self.kind,
                p.alpha,
                p.alpha_y,
                p.shape,
                self.exact,
                self.sampler,
            )
        })
    }

    /// The direction API's one material (or why there is none, as a ValueError); ValueError
    /// for an object of parameter arrays (one material per element: `AlbedoTable`).
    pub fn material(&self) -> PyResult<&Material> {
        match &self.one {
            Some(one) => self.get_material(one).as_ref().map_err(|e| value_error(*e)),
            None => Err(PyValueError::new_err(
                "this needs one material: the NDF's parameters are arrays (build one per element)",
            )),
        }
    }

    /// The parameter arrays' broadcast shape (empty where every parameter is a number).
    pub fn param_shape_vec(&self) -> Vec<usize> {
        self.batch.clone().unwrap_or_default()
    }

    /// Whether the parameters are arrays.
    pub fn batched(&self) -> bool {
        self.one.is_none()
    }

    /// `f(material, i, a, out)` for every element i of the arguments `items` broadcast with
    /// the parameter arrays (a: the arguments' numbers), with the element's material.
    pub fn each<'py>(
        &self,
        py: Python<'py>,
        items: &[Item<'_, 'py>],
        outs: &[usize],
        parallel: usize,
        f: impl Fn(&Material, usize, &[&[f64]], &mut [f64]) + Sync,
    ) -> PyResult<Vec<PyObject>> {
        if self.one.is_some() {
            let m = self.material()?;
            return apply_vec(py, items, outs, parallel, |i, a, o| {
                f(m, i, a, o);
                Ok(())
            });
        }
        let arrays = self.arrays(py);
        let all = params::with_arrays(items, &arrays);
        let k = items.len();
        apply_vec(py, &all, outs, parallel, |i, a, o| {
            let v: [f64; 3] = std::array::from_fn(|j| a.get(k + j).map_or(0.0, |s| s[0]));
            let p = self.p_of(&v[..a.len() - k]);
            self.with_material(p, |m| f(m, i, &a[..k], o))
        })
    }

    /// A quantity of directions (`dirs`: one or two direction arguments): in blocks over one
    /// material where the parameters are numbers, else per element (as [`NDF::map`]).
    fn dir<'py>(
        &self,
        py: Python<'py>,
        q: Dir,
        dirs: &[(&Bound<'py, PyAny>, &str)],
    ) -> PyResult<PyObject> {
        let items: Vec<Item<'_, 'py>> = dirs.iter().map(|&(a, n)| (a, 3, n, Domain::Any)).collect();
        if self.one.is_none() || crate::engine::one_element(&items) {
            return self.map(py, &items, |m, a| {
                q.eval(m, v3(a[0]), a.get(1).map_or([0.0; 3], |b| v3(b)))
            });
        }
        let m = self.material()?;
        let a = Args::new(py, &items)?;
        let x = a.slice(0)?;
        let y = if items.len() > 1 {
            Some(a.slice(1)?)
        } else {
            None
        };
        let mut out = a.run_blocks(py, 1, &[0], BLOCK, PARALLEL, |start, o| {
            let r = 3 * start..3 * (start + o.len());
            let y = y.map(|y| &y[r.clone()]);
            match m {
                Material::Fast(d) => q.block(d, &x[r], y, o),
                m => q.block(m, &x[r], y, o),
            }
            Ok(())
        })?;
        Ok(out.remove(0))
    }

    /// One number per element of direction arguments (as [`NDF::each`]).
    fn map<'py>(
        &self,
        py: Python<'py>,
        items: &[Item<'_, 'py>],
        f: impl Fn(&Material, &[&[f64]]) -> f64 + Sync,
    ) -> PyResult<PyObject> {
        let mut o = self.each(py, items, &[0], PARALLEL, |m, _, a, o| o[0] = f(m, a))?;
        Ok(o.remove(0))
    }

    /// A quantity of a cosine over `args` (cosines or slopes, broadcast together and with
    /// the parameter arrays): the exact path, GGX's closed forms, or (`fast`) the fast
    /// material's.
    fn cos<'py>(
        &self,
        py: Python<'py>,
        q: Cos,
        args: &[(&Bound<'py, PyAny>, &str, Domain<'_>)],
        fast: bool,
    ) -> PyResult<PyObject> {
        if !self.isotropic {
            return Err(anisotropic());
        }
        let kind = self.kind;
        if let (Some(k), [(u, _, _)]) = (q.kernel(kind), args) {
            let alpha = match &self.alpha {
                Param::Arr(a) => Some(a.bind(py)),
                Param::Num(_) => None,
            };
            let alpha0 = self.alpha.num().unwrap_or(f64::NAN);
            return apply_kernel(py, u, alpha, alpha0, k, q == Cos::Lambda);
        }
        let fast = fast && q.has_fast();
        if let Some(one) = &self.one {
            if fast {
                let p = one.p;
                let m =
                    AnyMicrofacet::new(kind, p.alpha, p.alpha_y, p.shape).map_err(value_error)?;
                // (No fast path: the generalised exponential's is its exact one.)
                if m.is_fast() {
                    return fast_cos(py, q, &m, args);
                }
            }
            let n = one.ndf;
            return apply(py, args, move |x| Ok(q.exact(&n, x)));
        }
        let arrays = self.arrays(py);
        let mut all: Vec<(&Bound<'py, PyAny>, &str, Domain<'_>)> = args.to_vec();
        all.extend(
            arrays
                .iter()
                .map(|(a, name)| (a, *name, crate::engine::FIXED)),
        );
        let k = args.len();
        apply(py, &all, |x| {
            let p = self.p_of(&x[k..]);
            if fast {
                let y = with_material(kind, p, false, self.sampler, |m| match m {
                    Material::Fast(m) if m.is_fast() => Some(q.fast(m, &x[..k])),
                    _ => None,
                })?;
                if let Some(y) = y {
                    return Ok(y);
                }
            }
            with_isotropic(kind, p.alpha, p.shape, |n| q.exact(n, &x[..k]))
        })
    }

    /// The parameters as `(name, param)`, for `==`, `hash` and `repr`.
    fn named(&self) -> Vec<(&'static str, Option<&Param>)> {
        vec![
            ("alpha", Some(&self.alpha)),
            (
                self.kind.shape_name().unwrap_or("shape"),
                self.shape.as_ref(),
            ),
            ("alpha_y", self.alpha_y.as_ref()),
        ]
    }
}

/// [`Cos::fast`] of one material over cosine arguments broadcast together: numbers without
/// arrays, arrays in blocks of [`BLOCK`] ([`Cos::fast_block`]).
fn fast_cos<'py>(
    py: Python<'py>,
    q: Cos,
    m: &AnyMicrofacet<f64>,
    args: &[(&Bound<'py, PyAny>, &str, Domain<'_>)],
) -> PyResult<PyObject> {
    if args.iter().all(|a| is_number(a.0)) {
        return apply(py, args, |x| Ok(q.fast(m, x)));
    }
    let items: Vec<Item<'_, 'py>> = args.iter().map(|&(a, name, d)| (a, 0, name, d)).collect();
    let a = Args::new(py, &items)?;
    let u = a.slice(0)?;
    let v = if args.len() > 1 {
        Some(a.slice(1)?)
    } else {
        None
    };
    let mut out = a.run_blocks(py, 1, &[0], BLOCK, PARALLEL, |start, o| {
        let range = start..start + o.len();
        q.fast_block(m, &u[range.clone()], v.map(|v| &v[range]), o);
        Ok(())
    })?;
    Ok(out.remove(0))
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
    /// The roughness α (αx of an anisotropic material): a float, or the array given.
    #[getter]
    fn alpha<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.alpha.object(py)
    }

    /// αy (α for an isotropic material): a float, or the array given.
    #[getter]
    fn alpha_y<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.alpha_y.as_ref().unwrap_or(&self.alpha).object(py)
    }

    /// The shape parameter (γ of GTR, Student-T and the generalised exponential, a of
    /// Bessel-K; a float or the array given), or None.
    #[getter]
    fn shape<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        self.shape.as_ref().map(|s| s.object(py)).transpose()
    }

    /// The broadcast shape of the parameter arrays (``()`` where every parameter is a
    /// number): every method's output has the shape of its arguments broadcast with it.
    #[getter]
    fn param_shape<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(py, self.batch.clone().unwrap_or_default())
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
        self.sampler_name
    }

    /// The NDF's name, as the command line spells it (``ggx``, ``student_t``, ...).
    #[getter]
    fn name(&self) -> &'static str {
        self.kind.name()
    }

    /// The constructor call that builds this NDF, evaluable back (with ``import numpy as
    /// np`` for parameter arrays): ``microsurface.GTR(0.3, gamma=1.5, alpha_y=0.2, exact=True)``,
    /// ``microsurface.GGX(np.array([0.1, 0.2]))`` (numbers as Python writes them, so the
    /// round trip is exact; defaults left out).
    fn __repr__(slf: &Bound<'_, Self>) -> PyResult<String> {
        let py = slf.py();
        let this = slf.get();
        let mut s = format!(
            "microsurface.{}({}",
            slf.get_type().name()?,
            this.alpha.repr(py)?
        );
        for (name, p) in &this.named()[1..] {
            if let Some(p) = p {
                s += &format!(", {name}={}", p.repr(py)?);
            }
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
        let mut args = vec![this.alpha.object(py)?];
        if let Some(s) = &this.shape {
            args.push(s.object(py)?);
        }
        args.push(match &this.alpha_y {
            Some(ay) => ay.object(py)?,
            None => py.None().into_bound(py),
        });
        args.push(this.exact.into_pyobject(py)?.to_owned().into_any());
        args.push(this.sampler_arg().into_pyobject(py)?.into_any());
        Ok((slf.get_type().into_any(), PyTuple::new(py, args)?))
    }

    /// The same NDF with some of its parameters changed (``dataclasses.replace``'s way):
    /// ``replace(alpha=..., alpha_y=..., gamma=... or a=..., exact=..., sampler=...)``, the
    /// others kept (an isotropic NDF stays isotropic at a new α). TypeError for another
    /// name.
    #[pyo3(signature = (**changes))]
    fn replace<'py>(
        slf: &Bound<'py, Self>,
        changes: Option<&Bound<'py, pyo3::types::PyDict>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let py = slf.py();
        let this = slf.get();
        let kwargs = pyo3::types::PyDict::new(py);
        kwargs.set_item("alpha", this.alpha.object(py)?)?;
        let shape_name = this.kind.shape_name();
        if let (Some(s), Some(name)) = (&this.shape, shape_name) {
            kwargs.set_item(name, s.object(py)?)?;
        }
        if let Some(ay) = &this.alpha_y {
            kwargs.set_item("alpha_y", ay.object(py)?)?;
        }
        kwargs.set_item("exact", this.exact)?;
        kwargs.set_item("sampler", this.sampler_arg())?;
        for (k, v) in changes.into_iter().flatten() {
            let name: String = k.extract()?;
            let known = ["alpha", "alpha_y", "exact", "sampler"].contains(&name.as_str())
                || Some(name.as_str()) == shape_name;
            if !known {
                return Err(pyo3::exceptions::PyTypeError::new_err(format!(
                    "replace() got an unexpected parameter {name:?}"
                )));
            }
            kwargs.set_item(k, v)?;
        }
        slf.get_type().call((), Some(&kwargs))
    }

    /// An NDF is immutable: its copy is itself (its cached fast-path material shared).
    fn __copy__(slf: PyRef<'_, Self>) -> PyRef<'_, Self> {
        slf
    }

    /// As ``__copy__``.
    fn __deepcopy__<'py>(slf: PyRef<'py, Self>, _memo: &Bound<'py, PyAny>) -> PyRef<'py, Self> {
        slf
    }

    /// Equal when of the same class with the same parameters (α, αy, shape: equal numbers,
    /// or arrays of the same shape and values; ``exact``, ``sampler``).
    fn __eq__(slf: &Bound<'_, Self>, other: &Bound<'_, PyAny>) -> PyResult<bool> {
        let Ok(o) = other.downcast::<NDF>() else {
            return Ok(false);
        };
        let py = slf.py();
        let (a, b) = (slf.get(), o.get());
        if !slf.get_type().is(o.get_type()) || a.exact != b.exact || a.sampler != b.sampler {
            return Ok(false);
        }
        for ((_, x), (_, y)) in a.named().into_iter().zip(b.named()) {
            let same = match (x, y) {
                (None, None) => true,
                (Some(x), Some(y)) => x.same(py, y)?,
                _ => false,
            };
            if !same {
                return Ok(false);
            }
        }
        Ok(true)
    }

    /// By the parameters ``==`` compares.
    fn __hash__(slf: &Bound<'_, Self>) -> PyResult<isize> {
        let py = slf.py();
        let this = slf.get();
        let mut h = std::collections::hash_map::DefaultHasher::new();
        std::hash::Hash::hash(&slf.get_type().name()?.to_string(), &mut h);
        for (_, p) in this.named() {
            std::hash::Hash::hash(&p.map(|p| p.hash_key(py)).transpose()?, &mut h);
        }
        std::hash::Hash::hash(&(this.exact, this.sampler_arg()), &mut h);
        Ok(std::hash::Hasher::finish(&h) as isize)
    }

    /// D(u): the density of microfacet normals per solid angle at u = cos θm ∈ [−1, 1] (0
    /// for u ≤ 0; +∞ at u = 1 for the NDFs with a pole there: Ei, Erfc, K0, Bessel-K a ≤ 1).
    /// ``fast=True``: the renderer's fast path (see the class).
    #[pyo3(signature = (u, fast = false))]
    fn d(&self, py: Python<'_>, u: &Bound<'_, PyAny>, fast: bool) -> PyResult<PyObject> {
        self.cos(py, Cos::D, &[cosine(u, "u")], fast)
    }

    /// Smith's Λ(u) of a direction at u = cos θ: +∞ at u = 0, 0 at 1, and for u < 0 Heitz's
    /// extension Λ(u) = −1 − Λ(|u|) (so that σ(u) = u(1 + Λ(u)) for every u ≠ 0), as the
    /// Rust ``Ndf::lambda``. (``lambda`` is a Python keyword.) ``fast`` as for ``d``.
    #[pyo3(signature = (u, fast = false))]
    fn lambda_(&self, py: Python<'_>, u: &Bound<'_, PyAny>, fast: bool) -> PyResult<PyObject> {
        self.cos(py, Cos::Lambda, &[cosine(u, "u")], fast)
    }

    /// The projected area σ(u) = ∫ max(0, ω·m) D(m) dm of a direction at signed u = cos θ
    /// (σ(u) = u(1 + Λ(u)) above the horizon, |u| Λ(|u|) below; σ(0) finite). ``fast`` as
    /// for ``d``.
    #[pyo3(signature = (u, fast = false))]
    fn sigma(&self, py: Python<'_>, u: &Bound<'_, PyAny>, fast: bool) -> PyResult<PyObject> {
        self.cos(py, Cos::Sigma, &[cosine(u, "u")], fast)
    }

    /// Smith's masking G1(u) = 1/(1 + Λ(|u|)). ``fast`` as for ``d``.
    #[pyo3(signature = (u, fast = false))]
    fn g1(&self, py: Python<'_>, u: &Bound<'_, PyAny>, fast: bool) -> PyResult<PyObject> {
        self.cos(py, Cos::G1, &[cosine(u, "u")], fast)
    }

    /// Height-correlated masking-shadowing G2(u_o, u_i) = 1/(1 + Λ(|u_o|) + Λ(|u_i|))
    /// (Heitz 2014), broadcast over both arguments. ``fast`` as for ``d``.
    #[pyo3(signature = (u_o, u_i, fast = false))]
    fn g2(
        &self,
        py: Python<'_>,
        u_o: &Bound<'_, PyAny>,
        u_i: &Bound<'_, PyAny>,
        fast: bool,
    ) -> PyResult<PyObject> {
        let args = [cosine(u_o, "u_o"), cosine(u_i, "u_i")];
        self.cos(py, Cos::G2, &args, fast)
    }

    /// Separable masking-shadowing G1(u_o) G1(u_i), broadcast over both arguments.
    #[pyo3(signature = (u_o, u_i, fast = false))]
    fn g2_separable(
        &self,
        py: Python<'_>,
        u_o: &Bound<'_, PyAny>,
        u_i: &Bound<'_, PyAny>,
        fast: bool,
    ) -> PyResult<PyObject> {
        let args = [cosine(u_o, "u_o"), cosine(u_i, "u_i")];
        self.cos(py, Cos::G2Separable, &args, fast)
    }

    /// The slope density P22(p, q) = D(u) u⁴ (u = 1/√(1 + p² + q²)), broadcast over p and
    /// q (the exact path: the renderer's has no slope densities).
    fn p22(
        &self,
        py: Python<'_>,
        p: &Bound<'_, PyAny>,
        q: &Bound<'_, PyAny>,
    ) -> PyResult<PyObject> {
        self.cos(py, Cos::P22, &[slope(p, "p"), slope(q, "q")], false)
    }

    /// The marginal slope density P2(p) = ∫ P22(p, q) dq (the exact path).
    fn p2(&self, py: Python<'_>, p: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        self.cos(py, Cos::P2, &[slope(p, "p")], false)
    }

    // ---- Directions: the anisotropic material (Rust: microsurface::AnyMicrofacet, or
    // microsurface::Exact with exact=True; the Distribution trait). Arrays of unit vectors,
    // last axis 3.

    /// D(wm) of unit normals wm (shape (..., 3)); 0 for wm.z ≤ 0.
    fn d_wm(&self, py: Python<'_>, wm: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        self.dir(py, Dir::D, &[(wm, "wm")])
    }

    /// Smith Λ(w) of directions w (the side w comes from; +∞ on the horizon).
    fn lambda_w(&self, py: Python<'_>, w: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        self.dir(py, Dir::Lambda, &[(w, "w")])
    }

    /// G1(w) = 1/(1 + Λ(w)).
    fn g1_w(&self, py: Python<'_>, w: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        self.dir(py, Dir::G1, &[(w, "w")])
    }

    /// The projected area σ(w) = |w.z|(1 + Λ(w)) (finite on the horizon), w mirrored to
    /// the upper hemisphere.
    fn sigma_w(&self, py: Python<'_>, w: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        self.map(py, &[(w, 3, "w", Domain::Any)], |e, a| e.sigma(v3(a[0])))
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
        let q = if separable { Dir::G2Separable } else { Dir::G2 };
        self.dir(py, q, &[(wo, "wo"), (wi, "wi")])
    }

    /// The visible-normal density D_w(wm) = G1(w) max(0, w·wm) D(wm)/|w.z| per solid angle
    /// of wm (w.z < 0: that of −w), the pdf of ``sample_visible``.
    fn pdf_visible(
        &self,
        py: Python<'_>,
        w: &Bound<'_, PyAny>,
        wm: &Bound<'_, PyAny>,
    ) -> PyResult<PyObject> {
        self.dir(py, Dir::Pdf, &[(w, "w"), (wm, "wm")])
    }

    /// Visible normals for directions w: ``sample_visible(w, u)`` with uniforms u of shape
    /// (..., 2) in [0, 1) (broadcast with w's batch shape; others raise ValueError, NaN gives
    /// NaN), or ``sample_visible(w, rng, n)``
    /// with a ``numpy.random.Generator``: ``n`` (an int or a tuple, SciPy's ``size``) draws
    /// uniforms of shape (*n, 2); ``n=None`` one pair per element of w's batch broadcast
    /// with the parameter arrays (a roughness map: one sample per texel). Returns
    /// ``Sample(wm, pdf)``: unit normals (..., 3) and their densities ``pdf_visible(w,
    /// wm)``. Samplers of the exact distribution (χ²-tested in the crate; ``sampler`` says
    /// which): each wm is a deterministic function of (w, u).
    #[pyo3(signature = (w, u, n = None))]
    fn sample_visible(
        &self,
        py: Python<'_>,
        w: &Bound<'_, PyAny>,
        u: &Bound<'_, PyAny>,
        n: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyObject> {
        let u = uniforms(py, u, n, 2, &[(w, 3)], &self.param_shape_vec())?;
        let items = [(w, 3, "w", Domain::Any), (&u, 2, "u", Domain::Uniform)];
        self.samples(py, &items, |e, a| e.sample(v3(a[0]), [a[1][0], a[1][1]]))
    }

    /// The density D(wm) cos θm of ``sample_dcos`` (0 for wm.z ≤ 0).
    fn pdf_dcos(&self, py: Python<'_>, wm: &Bound<'_, PyAny>) -> PyResult<PyObject> {
        self.dir(py, Dir::PdfDcos, &[(wm, "wm")])
    }

    /// Normals distributed as D(m) cos θm: ``sample_dcos(u)`` (u of shape (..., 2)) or
    /// ``sample_dcos(rng, n)`` (``n`` an int or a tuple; ``None``: one per element of the
    /// parameter arrays); returns ``Sample(wm, pdf)``.
    #[pyo3(signature = (u, n = None))]
    fn sample_dcos(
        &self,
        py: Python<'_>,
        u: &Bound<'_, PyAny>,
        n: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyObject> {
        let u = uniforms(py, u, n, 2, &[], &self.param_shape_vec())?;
        self.samples(py, &[(&u, 2, "u", Domain::Uniform)], |e, a| {
            e.sample_dcos([a[0][0], a[0][1]])
        })
    }

    // ---- Multiple scattering.

    /// The albedo of the microsurface by scattering order, by Heitz et al.'s random walk
    /// (2016; uniform heights), from directions at cos θo = ``mu`` and azimuth ``phi``
    /// (broadcast together, and with the parameter arrays: tables over (α, μ) in one call):
    /// F = 1 mirror facets (the white furnace, a conductor's energy), or dielectric facets
    /// of relative index ``eta``. ``walks`` walks per element, seeded by ``seed`` and the
    /// element's index (the same numbers whatever the threads). Returns ``Albedo(reflect,
    /// reflect_stderr, transmit, transmit_stderr, total, total_stderr)``: reflect and
    /// transmit of shape (..., ``orders``) for the orders 1, 2, …, ``orders`` − 1 and
    /// ≥ ``orders`` (default 4: 1, 2, 3, ≥ 4; the same walks give the same lower orders for
    /// any ``orders``, 1 ≤ ``orders`` ≤ 1000), with their standard errors; total (...) is
    /// reflect + transmit summed over orders (an F = 1 furnace conserves energy walk by
    /// walk: its total is 1 with standard error 0). ``progress=True``: a tqdm bar over the
    /// elements where tqdm is installed (silent otherwise). ``mu`` ∈ [−1, 1],
    /// ``phi`` finite, ``walks`` ≥ 1 (else ValueError); a NaN ``mu`` or ``phi`` gives NaN
    /// fields. The walk runs this NDF's path (fast by default, ``exact=True`` the exact one).
    /// Dielectric facets: order 1 is single scattering with the exact height-correlated
    /// transmission masking B(1 + Λo, 1 + Λi) (``single_scattering_albedo(ndf, mu, eta=eta,
    /// masking='exact')``; ``Dielectric(..., masking='correlated_beta')``), not pbrt's
    /// 1/(1 + Λo + Λi), the ``Dielectric`` BSDF's default (``masking='pbrt'`` there).
    #[pyo3(signature = (mu, phi = None, walks = 100_000, seed = 0, eta = None, orders = 4, progress = false))]
    #[allow(clippy::too_many_arguments)]
    fn albedo(
        &self,
        py: Python<'_>,
        mu: &Bound<'_, PyAny>,
        phi: Option<&Bound<'_, PyAny>>,
        walks: i64,
        seed: i128,
        eta: Option<f64>,
        orders: i64,
        progress: bool,
    ) -> PyResult<PyObject> {
        albedo::walk(self, py, mu, phi, walks, seed, eta, orders, progress)
    }
}

impl NDF {
    /// ``Sample(wm, pdf)`` of a sampler per element (parallel from 256 elements: the exact
    /// samplers of the family invert quadratures).
    fn samples<'py>(
        &self,
        py: Python<'py>,
        items: &[Item<'_, 'py>],
        f: impl Fn(&Material, &[&[f64]]) -> microsurface::Sample<f64> + Sync,
    ) -> PyResult<PyObject> {
        let o = self.each(py, items, &[3, 0], 256, |m, _, a, o| {
            let s = f(m, a);
            o[..3].copy_from_slice(&s.wm);
            o[3] = s.pdf;
        })?;
        named(py, "Sample", o)
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
            /// The NDF's name as the library spells it (`matched_alpha` reads it).
            #[classattr]
            fn _kind() -> &'static str {
                NdfKind::$kind.name()
            }

            #[new]
            #[pyo3(signature = (alpha, alpha_y = None, exact = false, sampler = "posterior"))]
            fn new(
                py: Python<'_>,
                alpha: &Bound<'_, PyAny>,
                alpha_y: Option<&Bound<'_, PyAny>>,
                exact: bool,
                sampler: &str,
            ) -> PyResult<(Self, NDF)> {
                let ndf = NDF::build(py, NdfKind::$kind, alpha, alpha_y, None, exact, sampler)?;
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
            /// The NDF's name as the library spells it (`matched_alpha` reads it).
            #[classattr]
            fn _kind() -> &'static str {
                NdfKind::$kind.name()
            }

            #[new]
            #[pyo3(signature = (alpha, $shape, alpha_y = None, exact = false, sampler = "posterior"))]
            fn new(
                py: Python<'_>,
                alpha: &Bound<'_, PyAny>,
                $shape: &Bound<'_, PyAny>,
                alpha_y: Option<&Bound<'_, PyAny>>,
                exact: bool,
                sampler: &str,
            ) -> PyResult<(Self, NDF)> {
                let ndf = NDF::build(py, NdfKind::$kind, alpha, alpha_y, Some($shape), exact, sampler)?;
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

/// What [`kind_of`] finds: the NDF, its shape, the class of results and their keywords.
pub type KindOf<'py> = (
    NdfKind,
    Option<f64>,
    Bound<'py, PyAny>,
    Bound<'py, pyo3::types::PyDict>,
);

/// The NDF kind and shape of `ndf`: a class (without a shape parameter), a spec string
/// (`"student_t:4"`) or an instance of one material; with the class to build results of and
/// the instance's keywords (`exact`, `sampler`).
pub fn kind_of<'py>(py: Python<'py>, ndf: &Bound<'py, PyAny>) -> PyResult<KindOf<'py>> {
    let module = py.import("microsurface._microsurface")?;
    let class_of = |kind: NdfKind| -> PyResult<Bound<'py, PyAny>> {
        for name in module.dir()? {
            let c = module.getattr(name.downcast::<pyo3::types::PyString>()?)?;
            if c.getattr("_kind")
                .is_ok_and(|k| k.eq(kind.name()).unwrap_or(false))
            {
                return Ok(c);
            }
        }
        Err(PyValueError::new_err(format!("no class for {kind}")))
    };
    let kwargs = pyo3::types::PyDict::new(py);
    if let Ok(n) = ndf.downcast::<NDF>() {
        let n = n.get();
        let Some(o) = &n.one else {
            return Err(PyValueError::new_err(
                "ndf must be one material (its parameters numbers)",
            ));
        };
        kwargs.set_item("exact", n.exact)?;
        kwargs.set_item("sampler", n.sampler_arg())?;
        return Ok((n.kind, o.p.shape, ndf.get_type().into_any(), kwargs));
    }
    if let Ok(spec) = ndf.extract::<String>() {
        let spec: microsurface::NdfSpec = spec
            .parse()
            .map_err(|e: microsurface::SpecError| PyValueError::new_err(e.to_string()))?;
        return Ok((spec.kind, spec.shape, class_of(spec.kind)?, kwargs));
    }
    let kind: String = ndf
        .getattr("_kind")
        .map_err(|_| {
            PyValueError::new_err("ndf must be an NDF class, a name ('student_t:4') or an NDF")
        })?
        .extract()?;
    let kind: NdfKind = kind
        .parse()
        .map_err(|e: microsurface::ndf::UnknownNdf| PyValueError::new_err(e.to_string()))?;
    if let Some(shape_name) = kind.shape_name() {
        return Err(PyValueError::new_err(format!(
            "{kind} needs its {shape_name}: pass a name ('{kind}:<{shape_name}>') or an instance"
        )));
    }
    Ok((kind, None, ndf.clone(), kwargs))
}

/// matched_alpha(ndf, reference, by='g1_45'): the NDF ``ndf`` at the roughness α whose
/// quantity ``by`` equals the NDF ``reference``'s (matched roughness; Rust:
/// ``AnyNdf::matched``). ``ndf``: a class (``microsurface.Beckmann``; a class with a shape
/// parameter needs it: pass a name or an instance), a name (``"beckmann"``,
/// ``"student_t:4"``, ``"gtr:1.5"``: the command line's specs) or an NDF instance (its shape,
/// ``exact`` and ``sampler`` kept, its α replaced). ``by``: ``"g1_45"`` (Smith's G1 at
/// θ = 45°), ``"sigma0"`` (the projected area at grazing σ(0)), ``"mean_slope"`` (E[tan θm]
/// under D cos θm, = π σ(0): the same match as ``"sigma0"``), ``"dcos_median"`` (the
/// median of tan θm under D cos θm). Returns an instance of the NDF's class. Bisection in
/// ln α over [1e-6, 1e6] on the exact path: the matched quantity equals the reference's to
/// ≤ 1e-10 relative. Parameter arrays (the reference's, an instance's shape) broadcast: the
/// result's α is an array, one match per element. ValueError where no α matches (σ(0) = ∞
/// for Student-T at γ ≤ 3/2; G1 at 45° of a smooth Beckmann, α ≲ 0.3, below any GGX's) or
/// for an anisotropic reference.
#[pyfunction]
#[pyo3(signature = (ndf, reference, by = "g1_45"))]
fn matched_alpha<'py>(
    py: Python<'py>,
    ndf: &Bound<'py, PyAny>,
    reference: PyRef<'py, NDF>,
    by: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let by: microsurface::ndf::MatchBy = by
        .parse()
        .map_err(|e: microsurface::ndf::MatchError| PyValueError::new_err(e.to_string()))?;
    if !reference.isotropic {
        return Err(PyValueError::new_err(
            "matched_alpha: the reference must be isotropic (alpha_y = alpha)",
        ));
    }
    // An instance's shape may be an array (then its α is not used); else kind_of's.
    let (kind, shape, class, kwargs, shape_array) = match ndf.downcast::<NDF>() {
        Ok(n) if n.get().batched() => {
            let g = n.get();
            let kwargs = pyo3::types::PyDict::new(py);
            kwargs.set_item("exact", g.exact)?;
            kwargs.set_item("sampler", g.sampler_arg())?;
            let (shape, array) = match &g.shape {
                Some(Param::Num(x)) => (Some(*x), None),
                Some(Param::Arr(a)) => (None, Some(a.bind(py).clone())),
                None => (None, None),
            };
            (g.kind, shape, ndf.get_type().into_any(), kwargs, array)
        }
        _ => {
            let (kind, shape, class, kwargs) = kind_of(py, ndf)?;
            (kind, shape, class, kwargs, None)
        }
    };
    let match_one = |r: &AnyNdf, shape: Option<f64>| {
        AnyNdf::matched(kind, shape, r, by)
            .map(|m| m.alpha())
            .map_err(|e| PyValueError::new_err(e.to_string()))
    };
    let alpha: Bound<'py, PyAny> = match (&reference.one, &shape_array) {
        (Some(one), None) => {
            let a = py.allow_threads(|| match_one(&one.ndf, shape))?;
            a.into_pyobject(py)?.into_any()
        }
        _ => {
            // Parameter arrays: one match per element of the reference's arrays broadcast
            // with the NDF's shape array (each a bisection: microseconds to a millisecond).
            let arrays = reference.arrays(py);
            let mut args: Vec<(&Bound<'py, PyAny>, &str, Domain<'_>)> = arrays
                .iter()
                .map(|(a, n)| (a, *n, crate::engine::FIXED))
                .collect();
            if let Some(s) = &shape_array {
                args.push((s, "shape", crate::engine::FIXED));
            }
            let nr = arrays.len();
            let has_shape_array = shape_array.is_some();
            let reference: &NDF = &reference;
            let failure = std::sync::Mutex::new(None);
            let out = apply(py, &args, |x| {
                let p = reference.p_of(&x[..nr]);
                let s = if has_shape_array { Some(x[nr]) } else { shape };
                let r = AnyNdf::new(reference.kind, p.alpha, p.shape)?;
                match AnyNdf::matched(kind, s, &r, by) {
                    Ok(m) => Ok(m.alpha()),
                    Err(e) => {
                        failure.lock().unwrap().get_or_insert(e.to_string());
                        Ok(f64::NAN)
                    }
                }
            })?;
            if let Some(e) = failure.into_inner().unwrap() {
                return Err(PyValueError::new_err(e));
            }
            out.into_bound(py)
        }
    };
    let mut args = vec![alpha];
    if kind.shape_name().is_some() {
        args.push(match (&shape_array, shape) {
            (Some(a), _) => a.clone(),
            (None, s) => s.into_pyobject(py)?.into_any(),
        });
    }
    class.call(PyTuple::new(py, args)?, Some(&kwargs))
}

/// Adds `NDF` and its subclasses to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(matched_alpha, m)?)?;
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
