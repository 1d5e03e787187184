#!/usr/bin/env python3
"""Reference values (mpmath, 30 digits) for the special functions microsurface uses.

Usage: python3 scripts/special_reference.py > crates/microsurface/tests/data/special.json
"""
import json
from mpmath import mp, mpf, e1, besselk, erf, erfc, exp, sqrt, pi, elliprd, hyperu

mp.dps = 30


def grid(lo, hi, n):
    return [float(mpf(lo) * (mpf(hi) / mpf(lo)) ** (mpf(k) / (n - 1))) for k in range(n)]


out = {}
xs = grid("1e-6", "700", 80)
out["erf"] = [[x, float(erf(mpf(x)))] for x in grid("1e-6", "6", 60)]
out["erfc"] = [[x, float(erfc(mpf(x)))] for x in grid("1e-6", "26", 60)]
out["e1"] = [[x, float(e1(mpf(x)))] for x in xs]
out["k0e"] = [[x, float(exp(mpf(x)) * besselk(0, mpf(x)))] for x in xs]
out["k1e"] = [[x, float(exp(mpf(x)) * besselk(1, mpf(x)))] for x in xs]
# erfc continued-fraction tail: k with sqrt(pi) x e^{x^2} erfc(x) = x/(x+k)
def tail(x):
    x = mpf(x)
    r = sqrt(pi) * x * exp(x * x) * erfc(x)
    return x / r - x
out["erfc_ratio_tail"] = [[x, float(tail(x))] for x in grid("2", "1e4", 40)]
# Double GGX kernel G(c) = c^2 [(1+c) e^c E1(c) - 1]
def G(c):
    c = mpf(c)
    with mp.workdps(60 + int(2 * mp.log10(1 + c))):
        return c * c * ((1 + c) * exp(c) * e1(c) - 1)
out["dggx_g"] = [[c, float(G(c))] for c in grid("1e-8", "1e8", 80)]
# S(x) - 1 with S(x) = x e^x (K0 + K1) = sqrt(pi) U(-1/2, 0, 2x)
def S1(x):
    x = mpf(x)
    with mp.workdps(60):
        return x * exp(x) * (besselk(0, x) + besselk(1, x)) - 1
out["bessel_k_sum_m1"] = [[x, float(S1(x))] for x in grid("1e-10", "1e4", 80)]
# check of the U identity the library relies on (derivations.md A.5)
out["u_identity_max_rel"] = float(max(abs(sqrt(pi) * hyperu(-0.5, 0, 2 * mpf(x)) - (S1(x) + 1)) / (S1(x) + 1) for x in grid("1e-3", "50", 10)))
# ln K_nu(z) of real order over the orders and arguments the Bessel-K NDF reaches
# (nu = a - 1, a - 1/2, a for a in [0.1, 100]; z = 2x from subnormal slopes to the tail)
out["ln_bessel_k"] = [
    [nu, z, float(mp.log(besselk(mpf(nu), mpf(z))))]
    for nu in [0.0, 0.1, 0.4, 0.5, 0.9, 1.5, 2.0, 2.5, 10.0, 49.5, 99.5, 100.0]
    for z in grid("1e-300", "1e4", 48) + [1e-310, 5e-324, 1.5e-150, 2.5e-150]
]
# B(1 + x, 1 + y) = Gamma(1 + x) Gamma(1 + y) / Gamma(2 + x + y) (special::beta_1p, the
# transmitted path's height-correlated masking): x <= y over [0, 1e300], both sides of the
# branch at 1 + y = 10. The working precision holds 1 + x and 2 + x + y exactly (1e300 needs
# ~1000 bits: at 30 digits 2 + x + y would round to 1 + x and B(1 + 1e300, 1) come out as 1);
# B by mpmath's beta, confirmed by exp of the loggamma difference to 1e-25.
BETA_ARGS = [0.0, 1e-12, 1e-6, 0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 8.5, 8.999, 9.0, 9.001, 9.5,
             12.0, 30.0, 100.0, 1e3, 1e5, 1e8, 1e12, 1e20, 1e50, 1e100, 1e200, 1e300]


def beta_1p(x, y):
    with mp.workprec(1400):
        a, b = 1 + mpf(x), 1 + mpf(y)
        v = mp.beta(a, b)
        w = exp(mp.loggamma(a) + mp.loggamma(b) - mp.loggamma(a + b))
        assert abs(v - w) <= mpf("1e-25") * v, (x, y)
        return float(v)


out["beta_1p"] = [[x, y, beta_1p(x, y)] for i, x in enumerate(BETA_ARGS) for y in BETA_ARGS[i:]]
# Carlson R_D(0, y, 1)
out["elliprd_0_y_1"] = [[y, float(elliprd(0, mpf(y), 1))] for y in grid("1e-6", "1e6", 60)]
# The Gamma(k) density t^(k-1) e^(-t) / Gamma(k) (special::gamma_pdf, the Student-T, K0 and
# Bessel-K mixings): small and large k, t across the peak (t = k(1 + j/sqrt(k))) and far out.
def gamma_pdf(k, t):
    with mp.workdps(60):
        k, t = mpf(k), mpf(t)
        return float(exp((k - 1) * mp.log(t) - t - mp.loggamma(k)))


GAMMA_K = [0.3, 0.5, 1.0, 2.5, 9.99, 10.0, 11.0, 50.0, 1e3, 999999.0, 1e9]


def gamma_points(k):
    """t across the density: the peak's neighbourhood t = k(1 + j/sqrt(k)) from k = 1, a
    logarithmic spread below it."""
    if k < 1:
        return [1e-6, 0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 20.0, 100.0]
    return [float(mpf(k) * (1 + mpf(j) / mp.sqrt(k)))
            for j in [-0.9, -0.5, -0.1, 0.0, 0.001, 0.3, 1.0, 3.0, 10.0]]


out["gamma_pdf"] = [[k, t, gamma_pdf(k, t)] for k in GAMMA_K for t in gamma_points(k)]
print(json.dumps(out, indent=0))
