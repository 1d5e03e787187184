"""Microfacet theory from NumPy: the Rust library `microsurface`.

Every NDF of the library is a class (``GGX(alpha, alpha_y=None)``, ``GTR(alpha, gamma)``,
``StudentT(alpha, gamma)``, ``BesselK(alpha, a)``, ...) whose quantities are vectorised
methods: NumPy arrays of any shape (or scalars) in, arrays of the broadcast shape out,
float32 for float32 input and float64 otherwise, computed in Rust on every core (f64;
float32 results are the f64 values rounded once, except GGX's D, Λ and G1 in f32).

Parameters are numbers or arrays, as SciPy's frozen distributions: ``GGX(np.array([0.1,
0.3])[:, None]).d(u)`` has the shape of the parameters broadcast with ``u``, one material
per element (``GTR(0.3, gamma=[1.5, 2.5])``, ``Beckmann(a, alpha_y=ay)``, a BSDF's ``eta``
and ``k``, whose last axis is the channels); never a Python loop.

* Functions of a cosine (the isotropic NDF): ``d``, ``lambda_``, ``sigma``, ``g1``, ``g2``,
  ``g2_separable``, ``p22``, ``p2``: the library's exact path (the research values), or with
  ``fast=True`` the renderer's fast kernels (every NDF but the slope densities and the
  generalised exponential, which have none).
* Functions of directions (unit vectors on the last axis, anisotropic): ``d_wm``,
  ``lambda_w``, ``g1_w``, ``sigma_w``, ``g2_w``, ``pdf_visible``, ``pdf_dcos``; the samplers
  ``sample_visible(w, u)`` and ``sample_dcos(u)`` with uniforms u (last axis 2) or
  ``(rng, n)`` for a ``numpy.random.Generator``. They, the BSDFs and the albedos run the
  renderer's fast kernels by default (the Rust ``AnyMicrofacet``: closed forms for GGX and
  Beckmann, fitted tables of Λ within 1e-7 relative for the others, the generalised
  exponential's exact path), and the exact path with ``exact=True`` at construction
  (``GGX(0.3, exact=True)``; 10²–10⁴ times slower for the NDFs without closed forms). The
  Beckmann mixtures Student-T, Ei, Erfc, K0 and Bessel-K sample by the posterior of the
  mixing variable (~0.2 µs) on both paths; ``exact=True, sampler='warp'`` draws them by the
  exact inversion, a warp of u.
* Multiple scattering: ``ndf.albedo(mu, walks=...)`` by order (the random walk),
  ``single_scattering_albedo(ndf, mu)`` (quadrature), both over parameter arrays for
  (α, μ) tables, ``AlbedoTable(ndf)`` (the compensation table, one material; its nodes
  ``mu`` and ``values``, ``save``/``load`` as ``.npy`` or the command line's ``.mfa``), and
  ``table(ndf, alpha, mu, ...)``, the command line's ``microsurface table`` (walk or
  quadrature, every material, ``progress=True`` for a tqdm bar), with ``read_table``.
* Matched roughness: ``matched_alpha(ndf, reference, by="g1_45")``, the NDF ``ndf`` (a
  class, a name such as ``"student_t:4"``, or an instance) at the α whose G1 at 45°
  (``"sigma0"``, ``"mean_slope"``, ``"dcos_median"``) equals the reference's.
* BSDFs: ``Conductor(ndf, eta, k)`` and ``Dielectric(ndf, eta)`` with ``eval``, ``pdf`` and
  ``sample``, single scattering or with multiple scattering (``scattering='kulla_conty'``,
  ``'turquin'`` or ``'walk'``).

NDFs and BSDFs are ordinary immutable Python objects: ``repr`` evaluates back
(``microsurface.GTR(0.3, gamma=1.5)``), ``==`` and ``hash`` compare the class and the
parameters, and ``pickle``, ``copy`` and ``deepcopy`` round-trip them (so joblib and
multiprocessing pass them to workers).

The input contract: a NaN value gives NaN (every output of that element: a sampler's wm
and pdf, an albedo's fields; a BSDF sample's lobe is 0). A value outside its domain raises
``ValueError`` naming the argument (for an array, how many elements are bad and the first):
cosines ``u``, ``u_o``, ``u_i``, ``mu`` in [-1, 1] (a rounded cosine within 4ε beyond is taken as
±1); uniforms in [0, 1); ``phi`` finite;
``walks`` ≥ 1, ``n`` ≥ 0, ``seed`` in [0, 2**64). Slopes ``p``, ``q`` take any number.
Parameters (``alpha``, shapes, ``eta``; numbers or every element of an array) raise
``ValueError`` with the library's message, NaN included (for an array, how many elements
are bad and the first). Ctrl-C raises ``KeyboardInterrupt`` within 0.5 s in
any call (the loop checks by time), except inside one element that alone runs longer
(``walks`` of many millions). See ``help(microsurface.NDF)`` for the quantities and their
accuracy.
"""

from ._microsurface import (  # noqa: F401
    __version__,
    BSDF,
    NDF,
    AlbedoTable,
    Beckmann,
    BesselK,
    Conductor,
    Dielectric,
    DoubleGGX,
    Ei,
    Erfc,
    Exponential,
    GenExponential,
    GGX,
    GTR,
    K0,
    StudentT,
    lut,
    matched_alpha,
    read_table,
    single_scattering_albedo,
    table,
)
from ._types import Albedo, BSDFSample, DielectricAlbedo, Lut, Sample, Table  # noqa: F401

__all__ = [
    "__version__",
    "NDF",
    "Beckmann",
    "BesselK",
    "DoubleGGX",
    "Ei",
    "Erfc",
    "Exponential",
    "GenExponential",
    "GGX",
    "GTR",
    "K0",
    "StudentT",
    "BSDF",
    "Conductor",
    "Dielectric",
    "AlbedoTable",
    "single_scattering_albedo",
    "matched_alpha",
    "table",
    "read_table",
    "lut",
    "Lut",
    "Sample",
    "BSDFSample",
    "Albedo",
    "DielectricAlbedo",
    "Table",
]
