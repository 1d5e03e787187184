"""Microfacet theory from NumPy: the Rust library `microsurface`.

Every NDF of the library is a class (``GGX(alpha, alpha_y=None)``, ``GTR(alpha, gamma)``,
``StudentT(alpha, gamma)``, ``BesselK(alpha, a)``, ...) whose quantities are vectorised
methods: NumPy arrays of any shape (or scalars) in, arrays of the broadcast shape out,
float32 for float32 input and float64 otherwise, computed in Rust on every core (f64, the
library's exact path; float32 results are the f64 values rounded once).

* Functions of a cosine (the isotropic NDF; ``alpha=`` broadcasts an array of roughnesses):
  ``d``, ``lambda_``, ``sigma``, ``g1``, ``g2``, ``g2_separable``, ``p22``, ``p2``.
* Functions of directions (unit vectors on the last axis, anisotropic): ``d_wm``,
  ``lambda_w``, ``g1_w``, ``sigma_w``, ``g2_w``, ``pdf_visible``, ``pdf_dcos``; the samplers
  ``sample_visible(w, u)`` and ``sample_dcos(u)`` with uniforms u (last axis 2) or
  ``(rng, n)`` for a ``numpy.random.Generator`` (the Beckmann mixtures Student-T, Ei, Erfc, K0
  and Bessel-K by the posterior of the mixing variable, ~0.2 µs; ``sampler='warp'`` at
  construction for the exact inversion, a warp of u).
* Multiple scattering: ``ndf.albedo(mu, walks=...)`` by order (the random walk),
  ``single_scattering_albedo(ndf, mu)`` (quadrature), both with ``alpha=`` arrays for
  (α, μ) tables, and ``AlbedoTable(ndf)`` (the compensation table).
* BSDFs: ``Conductor(ndf, eta, k)`` and ``Dielectric(ndf, eta)`` with ``eval``, ``pdf`` and
  ``sample``, single scattering or with multiple scattering (``scattering='kulla_conty'``,
  ``'turquin'`` or ``'walk'``).

Bad parameters raise ``ValueError`` with the library's message; NaN propagates; Ctrl-C
interrupts long calls. See ``help(microsurface.NDF)`` for the quantities and their accuracy.
"""

from ._microsurface import (  # noqa: F401
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
    single_scattering_albedo,
)
from ._types import Albedo, BSDFSample, Sample  # noqa: F401

__all__ = [
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
    "Sample",
    "BSDFSample",
    "Albedo",
]
