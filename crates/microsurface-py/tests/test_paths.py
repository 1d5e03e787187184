"""The two paths of the direction API: the fast kernels (the default; the library's
``AnyMicrofacet``) agree with the exact path (``exact=True``) within the fast paths'
documented bounds, for every NDF; the exact path is one keyword away and is what it says.

Bounds (the library's fast/mod.rs, tests/fast.rs; f64, relative where the value exceeds
1e-200, absolute 1e-200 below, as the fitted tables state): the fitted tables of Λ (Double
GGX, the Exponential NDF, GTR, the Beckmann mixtures) 1e-7; D closed or exact (the fitted
kinds' D within 1e-11); GGX's and Beckmann's closed forms 1e-14 and 1e-12, compared here
within 2e-12 and 1e-11: the exact path's own error near the normal, where Λ is small, is
larger than theirs (GGX at cos θ = 0.9988: the exact path 7e-13 from mpmath, the fast one
2e-16). The generalised exponential has no fast path: the same bits on both.
"""

import numpy as np
import pytest

import microsurface as mf

# (constructor, args, relative bound of the fast path against the exact one)
NDFS = [
    (mf.GGX, (0.3,), 2e-12),
    (mf.Beckmann, (0.3,), 1e-11),
    (mf.GTR, (0.3, 1.5), 1e-7),
    (mf.GTR, (0.3, 1.0), 1e-7),
    (mf.DoubleGGX, (0.3,), 1e-7),
    (mf.Exponential, (0.3,), 1e-7),
    (mf.StudentT, (0.3, 2.5), 1e-7),
    (mf.Ei, (0.3,), 1e-7),
    (mf.Erfc, (0.3,), 1e-7),
    (mf.K0, (0.3,), 1e-7),
    (mf.BesselK, (0.3, 0.7), 1e-7),
    (mf.GenExponential, (0.3, 1.5), 0.0),
]
IDS = [f"{c.__name__}{a}" for c, a, _ in NDFS]


def directions(n, rng):
    # Grazing to normal (cos θ from 1e-3 to 1), every azimuth; the upper hemisphere.
    mu = np.concatenate([np.geomspace(1e-3, 1, n // 2), rng.random(n - n // 2)])
    phi = rng.random(n) * 2 * np.pi
    s = np.sqrt(1 - mu * mu)
    w = np.stack([s * np.cos(phi), s * np.sin(phi), mu], axis=-1)
    return w


def close(fast, exact, rtol, what):
    fast, exact = np.asarray(fast), np.asarray(exact)
    assert np.array_equal(np.isfinite(fast), np.isfinite(exact)), what
    if rtol == 0:
        assert np.array_equal(fast, exact), what
        return
    finite = np.isfinite(exact)
    big = finite & (np.abs(exact) >= 1e-200)
    err = np.max(np.abs(fast[big] / exact[big] - 1), initial=0)
    assert err <= rtol, (what, err)
    assert np.all(fast[~finite] == exact[~finite]), what
    small = finite & ~big
    assert np.all(np.abs(fast[small] - exact[small]) <= 1e-200), what


@pytest.mark.parametrize("cls, args, rtol", NDFS, ids=IDS)
@pytest.mark.parametrize("alpha_y", [None, 0.5])
def test_fast_default_agrees_with_the_exact_path(cls, args, rtol, alpha_y):
    if alpha_y is not None and cls is mf.GTR:
        alpha_y = None  # (GTR is anisotropic only at γ = 2: GGX)
    rng = np.random.default_rng(33)
    fast = cls(*args, alpha_y=alpha_y)
    exact = cls(*args, alpha_y=alpha_y, exact=True)
    assert not fast.exact and exact.exact and "exact=True" in repr(exact)
    w = directions(400, rng)
    wm = directions(400, rng)
    # D of a fitted kind is exact or a closed form; Λ carries the fit's error, and with it
    # G1, σ and the visible density (G1 · D).
    close(fast.d_wm(wm), exact.d_wm(wm), min(rtol, 1e-11), "D")
    close(fast.lambda_w(w), exact.lambda_w(w), rtol, "Λ")
    close(fast.g1_w(w), exact.g1_w(w), rtol, "G1")
    close(fast.sigma_w(w), exact.sigma_w(w), rtol, "σ")
    close(fast.g2_w(w, wm), exact.g2_w(w, wm), rtol, "G2")
    close(fast.pdf_visible(w, wm), exact.pdf_visible(w, wm), 2 * rtol, "pdf")
    close(fast.pdf_dcos(wm), exact.pdf_dcos(wm), min(rtol, 1e-11), "pdf_dcos")
    # A BSDF eval: D G2 F/(4|cos θo||cos θi|) (the conductor), with transmission (the
    # dielectric), and their pdfs, over both hemispheres for wi.
    wi = wm.copy()
    wi[::2] *= -1
    gold = dict(eta=[0.2, 0.9, 1.1], k=[3.9, 2.4, 2.2])
    for make in (lambda n: mf.Conductor(n, **gold), lambda n: mf.Dielectric(n, 1.5)):
        b, e = make(fast), make(exact)
        close(b.eval(w, wi), e.eval(w, wi), 2 * rtol, "BSDF eval")
        close(b.pdf(w, wi), e.pdf(w, wi), 2 * rtol, "BSDF pdf")


@pytest.mark.parametrize("cls, args, rtol", NDFS, ids=IDS)
def test_fast_samplers_draw_the_exact_paths_density(cls, args, rtol):
    # Each path's samples carry its own pdf; evaluated by the other path, the same density
    # within the bound (the distributions are the same; the χ² tests in test_api.py check
    # that the samples follow them).
    rng = np.random.default_rng(5)
    fast, exact = cls(*args), cls(*args, exact=True)
    w = directions(200, rng)
    u = rng.random((200, 2))
    for a, b in ((fast, exact), (exact, fast)):
        s = a.sample_visible(w, u)
        assert np.array_equal(s.pdf, a.pdf_visible(w, s.wm))
        close(b.pdf_visible(w, s.wm), s.pdf, 2 * rtol, "sample pdf")
        d = a.sample_dcos(u)
        close(b.pdf_dcos(d.wm), d.pdf, min(rtol, 1e-11), "dcos pdf")


def test_the_exact_path_is_reachable():
    # The exact path is what the cosine forms (always exact) compute, to its own accuracy,
    # where the fitted tables of the fast path differ from it (by less than 1e-7).
    u = np.geomspace(1e-3, 1, 200)
    w = np.stack([np.sqrt(1 - u * u), 0 * u, u], axis=-1)
    for cls, args in [(mf.Exponential, (0.3,)), (mf.Ei, (0.3,)), (mf.GTR, (0.3, 1.5)), (mf.DoubleGGX, (0.4,))]:
        fast, exact = cls(*args), cls(*args, exact=True)
        np.testing.assert_allclose(exact.lambda_w(w), fast.lambda_(u), rtol=1e-10)
        assert not np.array_equal(fast.lambda_w(w), exact.lambda_w(w)), cls
    # The exact inversion of the Beckmann mixtures: a warp of u, monotone in u[0] along a
    # line of fixed u[1] (the posterior sampler of either path is not).
    warp = mf.Ei(0.3, exact=True, sampler="warp")
    assert warp.sampler == "warp"
    u = np.stack([np.linspace(0.05, 0.95, 40), np.full(40, 0.1)], axis=-1)
    wm = warp.sample_visible([0.0, 0.0, 1.0], u).wm
    r = np.hypot(wm[:, 0], wm[:, 1])
    assert np.all(np.diff(r) > 0)
    # The albedos follow the path: the walk and the quadrature run it (exact and fast agree
    # within the walk's error; the quadratures within the fits' bound).
    for cls, args in [(mf.Exponential, (0.4,)), (mf.StudentT, (0.4, 3.0))]:
        fast, exact = cls(*args), cls(*args, exact=True)
        e_fast = mf.single_scattering_albedo(fast, [0.3, 0.8])
        e_exact = mf.single_scattering_albedo(exact, [0.3, 0.8])
        np.testing.assert_allclose(e_fast, e_exact, rtol=1e-6)
        a, b = fast.albedo(0.5, walks=4000, seed=1), exact.albedo(0.5, walks=4000, seed=1)
        assert a.total == 1.0 and b.total == 1.0
        assert np.all(np.abs(a.reflect - b.reflect) < 5 * np.hypot(a.reflect_stderr, b.reflect_stderr) + 1e-9)


def test_path_keywords():
    with pytest.raises(ValueError, match="exact=True"):
        mf.StudentT(0.3, 2.5, sampler="warp")
    for exact in (False, True):
        # Student-T at γ ≤ 3/2: the isotropic functions work, the direction API raises.
        t = mf.StudentT(0.3, 1.2, exact=exact)
        assert np.isfinite(t.d(0.5))
        with pytest.raises(ValueError, match="finite Lambda"):
            t.lambda_w([0.0, 0.6, 0.8])
        with pytest.raises(ValueError, match="finite Lambda"):
            mf.Conductor(t)
        with pytest.raises(ValueError):
            mf.StudentT(0.3, 1.2, alpha_y=0.4, exact=exact)
    # GTR is anisotropic only at γ = 2, on both paths.
    for exact in (False, True):
        with pytest.raises(ValueError):
            mf.GTR(0.3, 1.5, alpha_y=0.4, exact=exact)
        assert mf.GTR(0.3, 2.0, alpha_y=0.4, exact=exact).lambda_w([0.6, 0.0, 0.8]) > 0


@pytest.mark.parametrize("cls,args,rtol", NDFS, ids=IDS)
def test_fast_cosine_functions_within_the_fast_bounds(cls, args, rtol):
    # fast=True: the functions of a cosine on the renderer's kernels (at the direction of
    # cosine u), within the same bounds of the exact path (the default), below the horizon
    # too (Λ(u < 0) = −1 − Λ(|u|), σ(u < 0) = |u| Λ(|u|)); u = 0 gives Λ = ∞ and σ(0) on both.
    n = cls(*args)
    u = np.concatenate([np.geomspace(1e-3, 1, 200), -np.geomspace(1e-3, 1, 50), [0.0, -0.0]])
    for name in ("d", "lambda_", "sigma", "g1"):
        f = getattr(n, name)
        close(f(u, fast=True), f(u), rtol, name)
    close(n.g2(u[:, None], u[::7], fast=True), n.g2(u[:, None], u[::7]), rtol, "g2")
    close(n.g2_separable(u[:, None], u[::7], fast=True), n.g2_separable(u[:, None], u[::7]), rtol, "g2_separable")
    # The slope densities have no fast path: the exact values.
    assert n.lambda_(-0.5) == -1 - n.lambda_(0.5) and n.lambda_(-0.0) == np.inf
