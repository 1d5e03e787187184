"""Microfacet normal distribution functions from NumPy: the Rust library `microfacet`.

Every NDF of the library is a class (``GGX(alpha)``, ``GTR(alpha, gamma)``, ``StudentT(alpha,
gamma)``, ``BesselK(alpha, a)``, ...) whose quantities are vectorised methods: NumPy arrays of
any shape (or scalars) in, arrays of the broadcast shape out, float32 for float32 input and
float64 otherwise, computed in Rust (f64, the library's exact path; float32 results are the
f64 values rounded). Bad parameters raise ``ValueError`` with the library's message; NaN
propagates. See ``help(microfacet.NDF)`` for the quantities and their accuracy.
"""

from ._microfacet import (  # noqa: F401
    NDF,
    Beckmann,
    BesselK,
    DoubleGGX,
    Ei,
    Erfc,
    Exponential,
    GenExponential,
    GGX,
    GTR,
    K0,
    StudentT,
)

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
]
