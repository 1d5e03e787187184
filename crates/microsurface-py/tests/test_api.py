"""Directions, samplers, BSDFs and multiple scattering from Python: equal to the Rust
library's values, shaped by NumPy's rules, sampled from the stated densities (χ² with
scipy), interruptible.

Run: pip install ./crates/microsurface-py pytest scipy && pytest crates/microsurface-py/tests
(the comparisons with the Rust command line need it built: cargo build --release, or
MICROSURFACE_CLI=path).
"""

import json
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest
from scipy import stats

import microsurface as mf

ROOT = os.path.join(os.path.dirname(__file__), "..", "..", "..")
CLI = os.environ.get("MICROSURFACE_CLI", os.path.join(ROOT, "target", "release", "microsurface"))


def cli(command, lines):
    if not os.path.exists(CLI):
        # (CI names it: missing there is a failure.)
        assert "MICROSURFACE_CLI" not in os.environ, f"MICROSURFACE_CLI={CLI} does not exist"
        pytest.skip(f"the command line is not built ({CLI}); cargo build --release")
    out = subprocess.run([CLI, command], input="\n".join(json.dumps(x) for x in lines), capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
    return [json.loads(x) for x in out.stdout.splitlines()]


def unit(v):
    v = np.asarray(v, dtype=np.float64)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def hemisphere(n, rng, lower=False):
    w = unit(rng.normal(size=(n, 3)))
    w[:, 2] = np.abs(w[:, 2]) * (-1 if lower else 1)
    return w


# ---- Equal to Rust, bit for bit.


def test_cosine_functions_equal_the_command_line():
    ndfs = [
        ("ggx", {}, mf.GGX(0.3)),
        ("beckmann", {}, mf.Beckmann(0.7)),
        ("gtr", {"gamma": 1.5}, mf.GTR(0.2, 1.5)),
        ("student_t", {"gamma": 2.5}, mf.StudentT(0.4, 2.5)),
        ("ei", {}, mf.Ei(0.3)),
        ("bessel_k", {"a": 0.7}, mf.BesselK(0.5, 0.7)),
        ("gen_exponential", {"gamma": 3.0}, mf.GenExponential(0.5, 3.0)),
    ]
    us = [0.01, 0.3, 0.5, 0.99, 0.999999]  # (D(1) = ∞ for Ei: JSON has no ∞)
    for name, shape, n in ndfs:
        for q, method in [("d", n.d), ("lambda", n.lambda_), ("sigma", n.sigma), ("g1", n.g1)]:
            lines = [dict(ndf=name, alpha=n.alpha, quantity=q, u=u, **shape) for u in us]
            want = [r["value"] for r in cli("eval", lines)]
            got = method(np.array(us))
            if name == "ggx" and q != "sigma":
                # GGX's D, Λ and G1 run the fast closed forms (fast::ggx, fast::batch: their
                # own rounding, within a few ulps of the exact path the CLI evaluates).
                np.testing.assert_allclose(got, want, rtol=3e-15, atol=0)
            else:
                assert got.tolist() == want, (name, q)


def test_bsdfs_equal_the_command_line():
    # Both run the library's run-time door (AnyMicrofacet: the fast kernels; the generalised
    # exponential's exact path inside it): the same bits.
    wo, wi, wt = [0.0, 0.6, 0.8], [0.6, 0.0, 0.8], [0.0, -0.6, -0.8]
    gold = dict(eta=[0.2, 0.9, 1.1], k=[3.9, 2.4, 2.2])
    cases = [
        ("conductor", dict(ndf="student_t", gamma=2.5, alpha=[0.3, 0.2], **gold),
         mf.Conductor(mf.StudentT(0.3, 2.5, alpha_y=0.2), **gold)),
        ("dielectric", dict(ndf="ei", alpha=0.3, eta=1.5), mf.Dielectric(mf.Ei(0.3), 1.5)),
        ("conductor", dict(ndf="gtr", gamma=1.5, alpha=0.3, **gold), mf.Conductor(mf.GTR(0.3, 1.5), **gold)),
        ("conductor", dict(ndf="exponential", alpha=[0.3, 0.5], **gold),
         mf.Conductor(mf.Exponential(0.3, alpha_y=0.5), **gold)),
        ("dielectric", dict(ndf="bessel_k", a=0.7, alpha=0.4, eta=1.5), mf.Dielectric(mf.BesselK(0.4, 0.7), 1.5)),
        ("dielectric", dict(ndf="double_ggx", alpha=0.4, eta=1.33), mf.Dielectric(mf.DoubleGGX(0.4), 1.33)),
        ("dielectric", dict(ndf="ggx", alpha=0.8, eta=1.5, g2="correlated_beta"),
         mf.Dielectric(mf.GGX(0.8), 1.5, masking="correlated_beta")),
        ("conductor", dict(ndf="gen_exponential", gamma=1.5, alpha=0.3, **gold),
         mf.Conductor(mf.GenExponential(0.3, 1.5), **gold)),
    ]
    for kind, spec, b in cases:
        for w in (wi, wt):
            [r] = cli("bsdf", [dict(bsdf=kind, op="eval", wo=wo, wi=w, **spec)])
            f = np.atleast_1d(b.eval(np.array(wo), np.array(w)))
            assert f.tolist() == r["f"][: len(f)]
            assert b.pdf(np.array(wo), np.array(w)) == r["pdf"]
        for u in ([0.3, 0.2, 0.7], [0.9, 0.5, 0.5]):
            [r] = cli("bsdf", [dict(bsdf=kind, op="sample", wo=wo, u=u, **spec)])
            s = b.sample(np.array(wo), np.array(u))
            assert s.wi.tolist() == r["wi"]
            assert s.pdf == r["pdf"]
            assert np.atleast_1d(s.f).tolist() == r["f"][: np.size(s.f)]
            assert s.lobe == {"reflection": 1, "transmission": 2}[r["kind"]]


# ---- Shapes, dtypes, agreement between the cosine and direction forms.


EVERY_CLASS = [(mf.GGX, {}), (mf.Beckmann, {}), (mf.DoubleGGX, {}), (mf.Exponential, {}), (mf.Ei, {}),
               (mf.Erfc, {}), (mf.K0, {}), (mf.GTR, {"gamma": 1.5}), (mf.StudentT, {"gamma": 3.0}),
               (mf.BesselK, {"a": 0.7}), (mf.GenExponential, {"gamma": 3.0})]


@pytest.mark.parametrize("cls,shape", EVERY_CLASS, ids=[c.__name__ for c, _ in EVERY_CLASS])
def test_parameters_broadcast_with_every_method(cls, shape):
    # SciPy's frozen distributions: parameters (n, 1) against arguments (m,) give (n, m),
    # each row bit for bit the object of that row's parameters, for every method.
    alpha = np.array([0.2, 0.6])[:, None]
    u = np.array([-0.4, 0.0, 0.1, 0.5, 0.95, 1.0])
    w = unit([[0.3, 0.1, 0.9], [0.2, -0.5, 0.4], [0.0, 0.6, 0.8], [0.9, 0.0, 0.2], [0.1, 0.1, -0.9], [1.0, 0.0, 0.0]])
    uu = np.array([[0.1, 0.2], [0.5, 0.5], [0.9, 0.3], [0.7, 0.99], [0.0, 0.0], [0.3, 0.6]])
    b = cls(alpha, **shape)
    assert b.param_shape == (2, 1) and np.array_equal(b.alpha, alpha)
    cos = [(f, (u,)) for f in ("d", "lambda_", "sigma", "g1")]
    cos += [(f, (u, u[::-1])) for f in ("g2", "g2_separable")] + [("p22", (u, u[::-1])), ("p2", (u,))]
    dirs = [(f, (w,)) for f in ("d_wm", "lambda_w", "g1_w", "sigma_w", "pdf_dcos")]
    dirs += [("pdf_visible", (w, w[::-1])), ("g2_w", (w, w[::-1]))]
    for i, a in enumerate(alpha[:, 0]):
        one = cls(a, **shape)
        for name, args in cos + dirs:
            got = getattr(b, name)(*args)
            assert got.shape == (2, 6), name
            assert np.array_equal(got[i], getattr(one, name)(*args), equal_nan=True), name
        for name, args in cos[:6]:
            got = getattr(b, name)(*args, fast=True)
            assert np.array_equal(got[i], getattr(one, name)(*args, fast=True), equal_nan=True), name
        for got, want in [(b.sample_visible(w, uu), one.sample_visible(w, uu)), (b.sample_dcos(uu), one.sample_dcos(uu))]:
            assert got.wm.shape == (2, 6, 3) and got.pdf.shape == (2, 6)
            assert np.array_equal(got.wm[i], want.wm) and np.array_equal(got.pdf[i], want.pdf)
    # float32 arguments give float32, whatever the parameters' dtype.
    assert b.d(np.float32([0.5, 0.7])).dtype == np.float32
    assert b.lambda_(np.float32(0.5)).shape == (2, 1)


def test_every_parameter_may_be_an_array():
    u = np.array([0.2, 0.7])
    # A shape parameter, αy, both with α: broadcast together.
    gamma = np.array([1.2, 2.0, 3.0])
    g = mf.GTR(0.3, gamma=gamma)
    assert g.lambda_(u[:, None]).shape == (2, 3)
    for j, c in enumerate(gamma):
        assert np.array_equal(g.lambda_(u[:, None])[:, j], mf.GTR(0.3, c).lambda_(u))
    assert g.sampler == "rejection" and mf.GTR(0.3, [2.0, 2.0]).sampler == "warp"
    an = mf.Beckmann(np.array([0.3, 0.5]), alpha_y=np.array([[0.1], [0.3], [0.5]]))
    assert an.param_shape == (3, 2)
    w = unit([0.3, 0.4, 0.5])
    want = [[mf.Beckmann(a, alpha_y=ay).d_wm(w) for a in (0.3, 0.5)] for ay in (0.1, 0.3, 0.5)]
    assert np.array_equal(an.d_wm(w), want)
    with pytest.raises(ValueError, match="anisotropic"):
        an.d(0.5)
    with pytest.raises(ValueError, match=r"do not broadcast together: alpha \(2,\), alpha_y \(3,\)"):
        mf.GGX([0.1, 0.2], alpha_y=[0.1, 0.2, 0.3])
    with pytest.raises(ValueError, match=r"1 of 3 elements of alpha are not valid \(the first: \[2\], alpha = -1.0\)"):
        mf.GGX([0.1, 0.2, -1.0])
    with pytest.raises(ValueError, match=r"gamma.*elements of alpha and gamma are not valid \(the first: \[0, 1\]"):
        mf.GTR([[0.1], [0.2]], [1.0, 0.0])
    # The BSDFs: η (and k, the channels their last axis) per element, with the NDF's arrays.
    wo, wi = unit([0.1, 0.2, 0.9]), unit([-0.3, 0.1, 0.8])
    alpha = np.array([0.2, 0.6])
    eta = np.array([[0.2, 0.9, 1.1], [0.3, 1.0, 1.2]])
    c = mf.Conductor(mf.GGX(alpha), eta=eta, k=[3.9, 2.4, 2.2])
    f = c.eval(wo, wi)
    assert f.shape == (2, 3) and c.channels == 3
    for i in range(2):
        assert np.array_equal(f[i], mf.Conductor(mf.GGX(alpha[i]), eta=eta[i], k=[3.9, 2.4, 2.2]).eval(wo, wi))
    d = mf.Dielectric(mf.GGX(0.3), np.array([1.3, 1.5, 0.7]))
    wt = unit([0.2, 0.1, -0.9])
    assert np.array_equal(d.eval(wo, wt), [mf.Dielectric(mf.GGX(0.3), e).eval(wo, wt) for e in (1.3, 1.5, 0.7)])
    s = d.sample(wo, [0.3, 0.4, 0.5])
    assert s.wi.shape == (3, 3) and s.lobe.shape == (3,)
    with pytest.raises(ValueError, match="eta"):
        mf.Dielectric(mf.GGX(0.3), [1.5, 1.0])
    # Objects of arrays: repr evaluates back under `import numpy as np` (np.array), ==,
    # hash and pickle by value.
    import pickle
    for x in (g, an, c, d, mf.StudentT(np.array([0.3, 0.4]), 2.5, exact=True)):
        assert "np.array(" in repr(x) and "numpy.array(" not in repr(x)
        y = eval(repr(x), {"microsurface": mf, "np": np})
        assert y == x and hash(y) == hash(x) and pickle.loads(pickle.dumps(x)) == x
    assert mf.GGX([0.1, 0.2]) != mf.GGX([0.1, 0.3]) and mf.GGX([0.1]) != mf.GGX(0.1)
    # One material only: the albedo table.
    with pytest.raises(ValueError, match="one material"):
        mf.AlbedoTable(mf.GGX([0.3, 0.5]))


@pytest.mark.parametrize("exact", [True, False])
def test_direction_forms_agree_with_the_cosine_forms(exact):
    # The exact path to its own accuracy; the fast kernels (the default) to theirs: closed
    # forms for GGX and Beckmann, fitted tables of Λ (≤ 1e-7 relative) for the others.
    u = np.linspace(0.02, 0.999, 50)
    phi = np.linspace(0, 6, 50)
    s = np.sqrt(1 - u * u)
    w = np.stack([s * np.cos(phi), s * np.sin(phi), u], axis=-1)
    for cls, args in [(mf.GGX, (0.3,)), (mf.Beckmann, (0.5,)), (mf.GTR, (0.2, 1.2)), (mf.StudentT, (0.3, 4.0)),
                      (mf.K0, (0.4,)), (mf.DoubleGGX, (0.3,))]:
        n = cls(*args, exact=exact)
        if exact:
            d, lam = 1e-12, 1e-10
        else:
            d, lam = {mf.GGX: (1e-13, 1e-13), mf.Beckmann: (1e-12, 1e-12)}.get(cls, (1e-11, 1e-7))
        np.testing.assert_allclose(n.d_wm(w), n.d(u), rtol=d)
        np.testing.assert_allclose(n.lambda_w(w), n.lambda_(u), rtol=lam)
        np.testing.assert_allclose(n.g1_w(w), n.g1(u), rtol=max(lam, 1e-12))
        np.testing.assert_allclose(n.sigma_w(w), n.sigma(u), rtol=max(lam, 1e-10))
        np.testing.assert_allclose(n.g2_w(w, w[::-1]), n.g2(u, u[::-1]), rtol=max(lam, 1e-12))
        np.testing.assert_allclose(n.g2_w(w, w[::-1], separable=True), n.g2_separable(u, u[::-1]),
                                   rtol=max(lam, 1e-12))
        np.testing.assert_allclose(n.pdf_dcos(w), n.d(u) * u, rtol=max(d, 1e-12))


def test_direction_shapes_and_dtypes():
    g = mf.GGX(0.3, 0.1)
    w = unit(np.random.default_rng(0).normal(size=(4, 5, 3)))
    assert g.lambda_w(w).shape == (4, 5)
    assert g.pdf_visible(w[:, :1], w).shape == (4, 5)  # (4, 1) with (4, 5)
    assert g.lambda_w(w.astype(np.float32)).dtype == np.float32
    assert np.ndim(g.d_wm([0.0, 0.0, 1.0])) == 0
    with pytest.raises(ValueError, match="last axis of length 3"):
        g.d_wm(np.zeros((4, 2)))
    with pytest.raises(ValueError):
        g.pdf_visible(w, w[:3])  # (4, 5) with (3, 5): not broadcastable
    assert np.isnan(g.lambda_w([np.nan, 0.0, 1.0]))


def test_dtype_rules_and_type_errors():
    # Issue 47: float32 in either byte order and float16 give float32 (SciPy computes
    # float16 in float32); a Python float beside a float32 array is a weak scalar (NumPy 2's
    # NEP 50) and keeps float32; float64, ints and bools give float64. Strings, complex and
    # object values raise TypeError (a string was parsed, a complex number lost its
    # imaginary part), for arguments and NDF parameters alike.
    g = mf.GGX(0.3)
    x32 = np.array([0.2, 0.5], dtype=np.float32)
    for x in [x32, x32.astype(">f4"), x32.astype(np.float16), np.float32(0.5)]:
        assert g.d(x).dtype == np.float32, x.dtype
        np.testing.assert_allclose(g.d(x), g.d(np.asarray(x, np.float64)), rtol=1e-6)
    w32 = np.array([[0.6, 0.0, 0.8]], dtype=np.float32)
    assert g.pdf_visible(w32, w32).dtype == np.float32
    assert g.g2(x32, 0.5).dtype == np.float32
    assert g.g2(x32, np.float64(0.5)).dtype == np.float64
    for x in [np.array([0.5]), 0.5, 1, np.array([1, 0]), np.array([True])]:
        assert np.asarray(g.d(x)).dtype == np.float64
    for bad in ["0.5", 0.5 + 1j, np.array(["0.5"]), np.array([0.5 + 0j]), np.array([object()])]:
        with pytest.raises(TypeError):
            g.d(bad)
    for bad in ["0.3", 0.3 + 0j, np.array(["0.3"])]:
        with pytest.raises(TypeError):
            mf.GGX(bad)


def test_samplers_take_scipy_sizes_with_parameter_arrays():
    # Issue 47: n (SciPy's size) as an int or a tuple; without it, one draw per element of
    # the parameter arrays (a roughness map: one sample per texel), each its own uniforms;
    # the same as the per-element objects given the same uniforms.
    alpha = np.array([[0.1, 0.3, 0.6], [0.2, 0.4, 0.9]])
    g = mf.GGX(alpha)
    w = [0.6, 0.0, 0.8]
    s = g.sample_visible(w, np.random.default_rng(3))
    assert s.wm.shape == (2, 3, 3) and s.pdf.shape == (2, 3)
    assert len(np.unique(s.wm[..., 0])) == 6  # not one pair of uniforms for all
    u = np.random.default_rng(3).random((2, 3, 2))
    np.testing.assert_array_equal(s.wm, g.sample_visible(w, u).wm)
    for i in range(2):
        for j in range(3):
            one = mf.GGX(alpha[i, j]).sample_visible(w, u[i, j])
            np.testing.assert_allclose(one.wm, s.wm[i, j], rtol=0, atol=1e-15)
    assert g.sample_dcos(np.random.default_rng(1)).wm.shape == (2, 3, 3)
    assert g.sample_visible(w, np.random.default_rng(1), (4, 2, 3)).wm.shape == (4, 2, 3, 3)
    one = mf.GGX(0.3)
    assert one.sample_visible(w, np.random.default_rng(1), (5, 2)).wm.shape == (5, 2, 3)
    assert one.sample_visible(w, np.random.default_rng(1), 7).wm.shape == (7, 3)
    assert one.sample_visible(w, np.random.default_rng(1)).wm.shape == (3,)
    assert one.sample_visible(np.tile(w, (4, 1)), np.random.default_rng(1)).wm.shape == (4, 3)
    b = mf.Conductor(g)
    assert b.sample([0.6, 0.0, 0.8], np.random.default_rng(2)).wi.shape == (2, 3, 3)
    with pytest.raises(TypeError):
        one.sample_visible(w, np.random.default_rng(1), "3")
    with pytest.raises(ValueError):
        one.sample_visible(w, np.random.default_rng(1), (3, -1))


def test_single_directions_equal_the_array_path():
    # One direction given as a list, a tuple or a 1-D float64 array (with Python-number
    # uniforms, μ, φ) takes a path without NumPy's conversions: the same values, bit for bit,
    # and the same types (NumPy float64 scalars, float64 arrays of the core's length) as a
    # batch of one through the array path. Anything else (float32, non-contiguous, wrong
    # lengths, bools) takes the array path, errors included.
    tiny = np.nextafter(0, 1)
    ws = [[0.6, 0.0, 0.8], [0, 0, 1], [1.0, 0.0, 0.0], [0.3, -0.4, -0.866], [1.0, 0.0, tiny], [0.0, 0.0, 0.0],
          [np.nan, 0.0, 1.0], [np.inf, 0.0, 1.0]]
    us = [[0.25, 0.75], [0.0, 0.0], [1 - 2**-53, 0.5]]
    u3s = [[0.25, 0.75, 0.1], [0.0, 0.0, 1 - 2**-53]]

    def same(one, batch):
        if isinstance(one, tuple):
            assert type(one) is type(batch) and len(one) == len(batch)
            for a, b in zip(one, batch):
                same(a, b)
            return
        b = batch[0]
        assert type(one) is type(b) and np.shape(one) == np.shape(b), (type(one), type(b))
        assert np.asarray(one).dtype == np.asarray(b).dtype
        np.testing.assert_array_equal(one, b)

    def check(f, *args):
        # Every argument in each single form against the batch of one.
        batch = f(*[np.asarray(a, dtype=np.float64)[None] if isinstance(a, list) else np.asarray([a]) for a in args])
        same(f(*args), batch)
        same(f(*[tuple(a) if isinstance(a, list) else a for a in args]), batch)
        same(f(*[np.asarray(a, dtype=np.float64) if isinstance(a, list) else a for a in args]), batch)

    for n in [mf.GGX(0.3, 0.1), mf.Beckmann(0.5), mf.StudentT(0.3, 4.0), mf.Ei(0.4), mf.GTR(0.2, 1.5)]:
        for w in ws:
            for f in (n.d_wm, n.lambda_w, n.g1_w, n.sigma_w, n.pdf_dcos):
                check(f, w)
            for v in ws[:4]:
                check(n.pdf_visible, w, v)
                check(n.g2_w, w, v)
                check(lambda a, b: n.g2_w(a, b, separable=True), w, v)
            if w[2] > 0 and np.isfinite(w).all():
                for u in us:
                    check(n.sample_visible, w, u)
        for u in us:
            check(n.sample_dcos, u)
        for b in (mf.Conductor(n, eta=[0.2, 0.9, 1.1], k=[3.9, 2.4, 2.2]), mf.Dielectric(n, 1.5)):
            for w in ws[:5]:
                for v in ws[:5]:
                    check(b.eval, w, v)
                    check(b.pdf, w, v)
                for u in u3s:
                    check(b.sample, w, u)
    g = mf.Beckmann(0.5)
    check(lambda mu, phi: g.albedo(mu, phi, walks=500, seed=3), 0.5, 0.25)
    check(lambda mu: mf.single_scattering_albedo(g, mu), 0.7)
    # The array path's answers for what the single path declines.
    g = mf.GGX(0.3)
    assert g.lambda_w(np.array([0.6, 0, 0.8], dtype=np.float32)).dtype == np.float32
    assert g.lambda_w(np.array([0.6, 9, 0, 9, 0.8])[::2]) == g.lambda_w([0.6, 0, 0.8])
    assert g.lambda_w([True, False, True]) == g.lambda_w([1.0, 0.0, 1.0])
    with pytest.raises(ValueError, match="last axis of length 3"):
        g.d_wm([0.0, 1.0])
    with pytest.raises(ValueError, match="last axis of length 3"):
        g.d_wm((0.0, 0.0, 1.0, 0.0))


# ---- Samplers.


@pytest.mark.parametrize(
    "n", [mf.GGX(0.3, 0.1), mf.Beckmann(0.6), mf.GTR(0.3, 1.0), mf.StudentT(0.3, 2.5), mf.Ei(0.4), mf.Exponential(0.2)]
)
def test_sample_visible_contract(n):
    rng = np.random.default_rng(1)
    w = hemisphere(2000, rng)
    w[::2] *= -1  # below the horizon: mirrored
    s = n.sample_visible(w, rng.random((2000, 2)))
    assert s.wm.shape == (2000, 3) and s.pdf.shape == (2000,)
    np.testing.assert_allclose(np.linalg.norm(s.wm, axis=-1), 1.0, atol=1e-14)
    side = np.where(w[:, 2] < 0, -1.0, 1.0)
    assert np.all(np.sum(w * s.wm, axis=-1) * side > 0) and np.all(s.wm[:, 2] > 0)
    assert np.array_equal(s.pdf, n.pdf_visible(w, s.wm))
    # A Generator and n: the same as drawing the uniforms first.
    a = n.sample_visible(w[0], np.random.default_rng(7), n=100)
    b = n.sample_visible(w[0], np.random.default_rng(7).random((100, 2)))
    assert np.array_equal(a.wm, b.wm)
    with pytest.raises(ValueError, match="Generator"):
        n.sample_visible(w[0], np.zeros((3, 2)), n=3)


def cell_probabilities(pdf, nt, nphi, order=6):
    """∫ pdf over cells of (θ, φ) ∈ [0, π/2] × [0, 2π) by Gauss–Legendre per cell (dω = sin θ dθ dφ:
    a pole of D at the normal, D ~ θ^−β with β < 2, is bounded there)."""
    x, wt = np.polynomial.legendre.leggauss(order)
    x, wt = (x + 1) / 2, wt / 2
    te = np.linspace(0, np.pi / 2, nt + 1)
    pe = np.linspace(0, 2 * np.pi, nphi + 1)
    t = te[:-1, None] + np.diff(te)[:, None] * x[None, :]  # (nt, order)
    p = pe[:-1, None] + np.diff(pe)[:, None] * x[None, :]
    T = t[:, None, :, None]
    P = p[None, :, None, :]
    m = np.stack(np.broadcast_arrays(np.sin(T) * np.cos(P), np.sin(T) * np.sin(P), np.cos(T)), axis=-1)
    f = pdf(m) * np.sin(T)  # (nt, nphi, order, order)
    w2 = wt[:, None] * wt[None, :]
    return np.sum(f * w2, axis=(-2, -1)) * np.diff(te)[:, None] * np.diff(pe)[None, :]


def histogram(w, nt, nphi):
    theta = np.arccos(np.clip(w[:, 2], -1, 1))
    phi = np.mod(np.arctan2(w[:, 1], w[:, 0]), 2 * np.pi)
    counts, _, _ = np.histogram2d(theta, phi, bins=[nt, nphi], range=[[0, np.pi / 2], [0, 2 * np.pi]])
    return counts


def chi2_pvalue(counts, expected):
    # Cells with small expectations pooled into one (the usual rule: ≥ 5).
    small = expected < 5
    obs = np.append(counts[~small], counts[small].sum())
    exp = np.append(expected[~small], expected[small].sum())
    if exp[-1] == 0:
        obs, exp = obs[:-1], exp[:-1]
    exp = exp * obs.sum() / exp.sum()
    return stats.chisquare(obs, exp).pvalue


@pytest.mark.parametrize(
    "n, w",
    [
        (mf.GGX(0.4, 0.15), [0.5, 0.3, 0.81]),
        (mf.Beckmann(0.5), [0.8, 0.0, 0.6]),
        (mf.StudentT(0.35, 3.0, alpha_y=0.6), [-0.3, 0.5, 0.81]),
        (mf.StudentT(0.35, 3.0, alpha_y=0.6, exact=True), [-0.3, 0.5, 0.81]),
        (mf.StudentT(0.35, 3.0, alpha_y=0.6, exact=True, sampler="warp"), [-0.3, 0.5, 0.81]),
        (mf.GTR(0.3, 1.5), [0.6, 0.0, 0.8]),
        (mf.Exponential(0.3, 0.5), [0.2, 0.5, 0.84]),
        (mf.Ei(0.4, exact=True, sampler="warp"), [0.8, 0.0, 0.6]),
        (mf.BesselK(0.3, 0.7, alpha_y=0.5), [0.7, 0.1, 0.2]),
        (mf.Erfc(0.6), [0.0, 0.9, 0.1]),
        (mf.GenExponential(0.4, 1.3), [0.0, 0.6, 0.8]),
        (mf.DoubleGGX(0.3), [0.0, 0.0, -1.0]),
    ],
)
def test_sample_visible_chi2(n, w):
    w = unit(w)
    samples = 100_000
    s = n.sample_visible(w, np.random.default_rng(3), n=samples)
    nu, nphi = 16, 24
    counts = histogram(s.wm, nu, nphi)
    expected = samples * cell_probabilities(lambda m: n.pdf_visible(w, m), nu, nphi)
    assert abs(expected.sum() / samples - 1) < 2e-3
    assert chi2_pvalue(counts.ravel(), expected.ravel()) > 1e-4


def test_sample_dcos_chi2():
    n = mf.Exponential(0.5, 0.3)
    samples = 100_000
    s = n.sample_dcos(np.random.default_rng(4), n=samples)
    assert np.array_equal(s.pdf, n.pdf_dcos(s.wm))
    nu, nphi = 16, 24
    counts = histogram(s.wm, nu, nphi)
    expected = samples * cell_probabilities(n.pdf_dcos, nu, nphi, order=8)
    assert chi2_pvalue(counts.ravel(), expected.ravel()) > 1e-4


def test_conductor_sample_chi2_with_rejections():
    b = mf.Conductor(mf.GGX(0.5, 0.25), eta=1.5, k=3.0)
    wo = unit([0.7, 0.2, 0.3])
    samples = 100_000
    s = b.sample(wo, np.random.default_rng(5), n=samples)
    ok = s.lobe == 1
    assert np.all(s.pdf[~ok] == 0) and np.all(s.wi[~ok] == 0)
    nu, nphi = 16, 24
    counts = histogram(s.wi[ok], nu, nphi)
    expected = samples * cell_probabilities(lambda w: b.pdf(wo, w), nu, nphi, order=8)
    # The rejected samples (reflections below the horizon) are the rest of the probability.
    obs = np.append(counts.ravel(), (~ok).sum())
    exp = np.append(expected.ravel(), samples - expected.sum())
    assert chi2_pvalue(obs, exp) > 1e-4


# ---- BSDFs.


@pytest.mark.parametrize("scattering", ["single", "kulla_conty", "turquin", "walk"])
def test_bsdf_sample_weights_match_eval_and_pdf(scattering):
    rng = np.random.default_rng(6)
    wo = hemisphere(300, rng)
    for b in [
        mf.Conductor(mf.Beckmann(0.4), eta=[0.2, 0.9, 1.1], k=[3.9, 2.4, 2.2], scattering=scattering),
        mf.Dielectric(mf.GGX(0.3), 1.5, scattering=scattering),
    ]:
        s = b.sample(wo, rng.random((300, 3)))
        ok = s.lobe > 0
        assert ok.mean() > 0.8
        if scattering == "walk":
            # (f is the walk's estimate; pdf its MIS proxy: pdf matches.)
            np.testing.assert_allclose(s.pdf[ok], b.pdf(wo[ok], s.wi[ok]), rtol=1e-12)
            continue
        np.testing.assert_allclose(s.pdf[ok], b.pdf(wo[ok], s.wi[ok]), rtol=1e-9)
        np.testing.assert_allclose(s.f[ok], b.eval(wo[ok], s.wi[ok]), rtol=1e-9)


def test_white_furnace():
    rng = np.random.default_rng(8)
    mu = np.array([0.2, 0.6, 0.95])
    wo = np.stack([np.sqrt(1 - mu**2), 0 * mu, mu], axis=-1)
    for scattering, tol in [("kulla_conty", 0.01), ("turquin", 0.01)]:
        b = mf.Conductor(mf.GGX(0.8), scattering=scattering)
        for w in wo:
            s = b.sample(w, rng, n=200_000)
            ok = s.lobe > 0
            est = np.sum(s.f[ok] * s.wi[ok, 2] / s.pdf[ok]) / len(s.pdf)
            assert abs(est - 1) < tol, (scattering, w, est)
    # The walk with F = 1 mirrors: every walk leaves with weight 1.
    a = mf.Beckmann(1.0).albedo(mu, walks=20_000)
    np.testing.assert_allclose(a.total, 1.0, atol=1e-12)
    assert a.reflect.shape == (3, 4)
    # Its order 1 is the single-scattering albedo (quadrature), within the walk's error.
    e1 = mf.single_scattering_albedo(mf.Beckmann(1.0), mu)
    assert np.all(np.abs(a.reflect[:, 0] - e1) < 5 * a.reflect_stderr[:, 0] + 1e-4)
    t = mf.AlbedoTable(mf.Beckmann(1.0))
    np.testing.assert_allclose(t.e(mu), e1, rtol=2e-3)
    assert 0 < t.e_avg < 1 and abs(t.lost_avg - (1 - t.e_avg)) < 1e-3
    # Dielectric facets: reflect + transmit = 1 in total (no absorption).
    d = mf.GGX(0.5).albedo(0.7, walks=20_000, eta=1.5)
    assert abs(d.total - 1) < 1e-12 and d.transmit.sum() > 0.5


def test_anisotropic_albedo_table():
    # An anisotropic material's table holds E(μ, φ) (issue 45): its values are the mean over
    # the azimuth, pickling keeps the azimuth's harmonics, and saving to a file of E(μ) is
    # refused rather than losing them.
    import pickle
    t = mf.AlbedoTable(mf.GGX(0.6, alpha_y=0.15))
    mean = mf.AlbedoTable._restore(list(t.values))
    assert t != mean and pickle.loads(pickle.dumps(t)) == t
    assert hash(pickle.loads(pickle.dumps(t))) == hash(t)
    with pytest.raises(ValueError, match="anisotropic"):
        t.save("/tmp/microsurface-aniso-table.npy")


def test_albedo_over_alpha_arrays():
    # A table over (α, μ) in one call equals one material per α.
    alpha = np.array([0.2, 0.7])[:, None]
    mu = np.array([0.3, 0.9])
    g = mf.GGX(alpha)
    t = mf.single_scattering_albedo(g, mu)
    assert t.shape == (2, 2)
    for i, a in enumerate(alpha[:, 0]):
        assert np.array_equal(t[i], mf.single_scattering_albedo(mf.GGX(a), mu))
    w = g.albedo(mu, walks=2000)
    assert w.reflect.shape == (2, 2, 4)
    # (Each element has its own stream: seed + index; the second row's are indices 2, 3.)
    assert np.array_equal(w.reflect[0], mf.GGX(0.2).albedo(mu, walks=2000).reflect)
    an = mf.Beckmann([0.4, 0.8], alpha_y=[0.2, 0.4]).albedo(0.5, walks=1000)
    assert an.total.shape == (2,) and np.all(an.total == 1.0)


def test_bsdf_errors():
    g = mf.GGX(0.3)
    for kwargs, match in [
        (dict(eta=[1.0, 2.0], k=[1.0]), "channels"),
        (dict(eta=[1.0, 2.0], k=[1.0, 2.0]), "1 or 3 channels"),
        (dict(k=[1.0]), "k needs eta"),
        (dict(eta=-1.0), "positive"),
        (dict(masking="nope"), "masking"),
        (dict(scattering="nope"), "scattering"),
        (dict(scattering="walk", masking="separable"), "correlated"),
    ]:
        with pytest.raises(ValueError, match=match):
            mf.Conductor(g, **kwargs)
    with pytest.raises(ValueError, match="eta"):
        mf.Dielectric(g, 1.0)
    with pytest.raises(ValueError, match="transport"):
        mf.Dielectric(g, 1.5, transport="x")
    with pytest.raises(ValueError, match="correlated"):
        mf.Dielectric(g, 1.5, masking="correlated_beta", scattering="walk")
    with pytest.raises(ValueError, match="last axis of length 3"):
        mf.Dielectric(g, 1.5).sample([0, 0, 1.0], [0.5, 0.5])
    with pytest.raises(ValueError, match="finite Lambda"):
        mf.StudentT(0.3, 1.2).sample_visible([0, 0, 1.0], [0.5, 0.5])
    with pytest.raises(ValueError, match="sampler"):
        mf.Ei(0.3, sampler="fast")
    with pytest.raises(ValueError, match="exact=True"):
        mf.Ei(0.3, sampler="warp")
    assert mf.Ei(0.3).sampler == "posterior" and mf.Ei(0.3, exact=True).sampler == "posterior"
    assert mf.Ei(0.3, exact=True, sampler="warp").sampler == "warp"
    assert mf.GGX(0.3).sampler == "warp" and mf.GGX(0.3, exact=True, sampler="warp").sampler == "warp"
    assert mf.GTR(0.3, 1.5).sampler == "rejection" and mf.GTR(0.3, 2.0).sampler == "warp"
    assert mf.GTR(0.3, 1.5, exact=True).sampler == "warp"
    assert mf.StudentT(0.3, 1.2).sampler == "posterior"


# ---- Ctrl-C.


def test_ctrl_c_interrupts_a_long_call():
    def interrupt(signum, frame):
        raise KeyboardInterrupt

    old = signal.signal(signal.SIGALRM, interrupt)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.3)
        start = time.monotonic()
        with pytest.raises(KeyboardInterrupt):
            # ~10⁴ elements of 10⁵ walks: minutes of work.
            mf.GGX(0.5).albedo(np.linspace(0.1, 1, 10_000), walks=100_000)
        assert time.monotonic() - start < 3.0
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def interrupt_latency(call):
    """Seconds from a SIGINT, sent 0.2 s into `call` (which must run far longer), to the
    KeyboardInterrupt it raises."""
    sent = []

    def send():
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    old = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.2, send)
    try:
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            call()
        return time.monotonic() - sent[0]
    finally:
        timer.cancel()
        timer.join()
        signal.signal(signal.SIGINT, old)


@pytest.mark.parametrize(
    "call",
    [
        # The slowest exact quantity of a cosine: Bessel-K's Λ at a = 0.1 (~0.1 ms an element
        # by quadrature; 2·10⁶ elements: minutes), where the loop's first check came after
        # 2^16 elements (seconds to a minute).
        lambda: mf.BesselK(0.4, 0.1).lambda_(np.linspace(0.01, 1.0, 2_000_000)),
        # The slowest exact sampler: Student-T's exact inversion near γ = 3/2 (~20 ms a sample).
        lambda: mf.StudentT(0.3, 1.51, exact=True, sampler="warp").sample_visible(
            [0.6, 0.0, 0.8], np.random.default_rng(1), 100_000
        ),
        # A walk of 10⁵ steps an element (the albedo by order).
        lambda: mf.GGX(0.5).albedo(np.linspace(0.1, 1, 10_000), walks=100_000),
    ],
    ids=["besselk_lambda", "student_t_exact_warp", "walk_albedo"],
)
def test_ctrl_c_latency(call):
    # The contract: Ctrl-C raises KeyboardInterrupt within 0.5 s whatever an element costs
    # (the loop's chunks are sized to ~50 ms by time; 0.5 s leaves 10× for a chunk that runs
    # past its estimate on a loaded machine).
    latency = interrupt_latency(call)
    print(f"Ctrl-C latency: {latency:.3f} s")
    assert latency < 0.5


@pytest.mark.parametrize(
    "call",
    [
        # An anisotropic Student-T albedo table (no table shipped: 33 × 9 quadratures, seconds).
        lambda: mf.AlbedoTable(mf.StudentT(0.31, 2.5, alpha_y=0.17)),
        # A walk table of 10⁷ walks a cell (minutes).
        lambda: mf.table(mf.GGX(0.3), alpha=[0.3, 0.5], mu=np.linspace(0.1, 1, 8), walks=10_000_000),
        # A dielectric LUT (32² × 16 × 2 quadratures).
        lambda: mf.lut(mf.GGX(0.3), "dielectric", size=32),
    ],
    ids=["albedo_table", "walk_table", "dielectric_lut"],
)
def test_ctrl_c_stops_the_work(call):
    # Issue 47: KeyboardInterrupt came at once, but the threads computed on (both cores
    # busy) and the next call waited behind them (a 10⁶-element g1 took 32 s after an
    # interrupted table). Now the interrupt cancels the library's loop: after it the process
    # uses (almost) no CPU — a loop still running on two cores would use ~2 s of it in the
    # second measured — and the next call runs at once.
    latency = interrupt_latency(call)
    assert latency < 2.0
    before = time.process_time()
    time.sleep(1.0)
    assert time.process_time() - before < 0.5
    x = np.linspace(0.01, 1.0, 1_000_000)
    g = mf.GGX(0.3).g1(x)
    assert g.shape == x.shape and np.all(np.isfinite(g))


@pytest.mark.parametrize("nth", [1, 2])
def test_ctrl_c_while_numpy_api_loads_is_a_keyboard_interrupt(nth):
    # rust-numpy fetches NumPy's C API by running Python code (numpy.lib.NumpyVersion), and
    # panicked (PanicException, which `except KeyboardInterrupt` misses) when a Ctrl-C
    # interrupted it at the first call. Here the nth call of NumpyVersion is interrupted: the
    # module's own run at import (1) or rust-numpy's after it (2).
    code = f"""
import numpy, numpy.lib
real, calls = numpy.lib.NumpyVersion, []
def interrupted(*args):
    calls.append(1)
    if len(calls) == {nth}:
        raise KeyboardInterrupt
    return real(*args)
numpy.lib.NumpyVersion = interrupted
try:
    import microsurface
    microsurface.GGX(0.3).d(numpy.linspace(0.0, 1.0, 10))
except KeyboardInterrupt:
    raise SystemExit(3)
raise SystemExit(4)
"""
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 3 and "PanicException" not in r.stderr, (r.returncode, r.stderr)


def test_readme_python_snippets_run():
    with open(os.path.join(ROOT, "README.md")) as fh:
        text = fh.read()
    blocks = [b.split("```", 1)[0] for b in text.split("```python\n")[1:]]
    assert blocks
    for b in blocks:
        exec(compile(b, "README.md", "exec"), {})


@pytest.mark.parametrize("name", ["ndf_curves", "sample_histogram", "albedo_orders"])
def test_examples_run(name, tmp_path):
    if "MICROSURFACE_EXAMPLES" not in os.environ:
        pytest.importorskip("matplotlib")
    path = os.path.join(ROOT, "examples", "python", f"{name}.py")
    out = tmp_path / f"{name}.png"
    subprocess.run([sys.executable, path, str(out)], check=True, capture_output=True)
    assert out.stat().st_size > 10_000


def test_fast_paths_at_every_length():
    # Lengths around the kernels' blocks (4 096), the parallel threshold (16 384) and the
    # chunks (2^20 for float32): each element as its own call.
    g = mf.GGX(0.3)
    rng = np.random.default_rng(11)
    for n in [1, 4095, 4096, 4097, 10_000, 16_383, 16_384, 16_385, 70_001, (1 << 20) + 3]:
        u = rng.random(n)
        for dtype in (np.float64, np.float32):
            x = u.astype(dtype)
            for f in (g.d, g.lambda_, g.g1):
                got = f(x)
                idx = rng.integers(0, n, 50)
                assert np.array_equal(got[idx], np.array([f(x[i]) for i in idx])), (n, dtype, f.__name__)
                a = np.full(n, 0.3, dtype=dtype)
                assert np.array_equal(getattr(mf.GGX(a), f.__name__)(x), got), (n, dtype)


def test_seeded_fuzz_no_panic_at_the_edges():
    # The contract's edges through every method (a Rust panic would surface as
    # pyo3_runtime.PanicException, a BaseException): finite in-contract input gives finite
    # output, samples are unit normals visible from w, NaN gives NaN (out-of-domain input
    # raises: test_hostile_input_through_every_public_function).
    rng = np.random.default_rng(2026)
    tiny = np.nextafter(0, 1)
    us = np.array([0.0, -0.0, 1.0, 1 + 2.2e-16, tiny, 1e-300, 0.5, -0.5, -1.0, np.nan, np.inf, 1e300])
    edge_w = np.array(
        [[0, 0, 1.0], [1.0, 0, 0], [0, 0, -1.0], [1, 0, tiny], [1, 0, -tiny], [0.6, 0, 0.8], [0, 0, 0], [np.nan, 0, 1]]
    )
    u2 = np.array([[0.0, 0.0], [1 - 2**-53, 1 - 2**-53], [0.0, 1 - 2**-53], [0.5, 0.5]])
    ndfs = [mf.GGX(1e-6), mf.GGX(1e6, 1e-3), mf.Beckmann(0.3, 0.9), mf.GTR(0.2, 0.5), mf.DoubleGGX(2.0),
            mf.Exponential(0.05), mf.StudentT(0.3, 1.51), mf.Ei(0.3), mf.Erfc(0.7), mf.K0(0.3),
            mf.BesselK(0.4, 0.5), mf.GenExponential(0.5, 20.0)]
    for n in ndfs:
        # (Cosines in [-1, 1] and NaN; slopes any number; the functions of a cosine of the
        # isotropic material, the fast path's too.)
        cos = us[~(np.abs(us) > 1)]
        if n.alpha == n.alpha_y:
            for fast in (False, True):
                for f in (n.d, n.lambda_, n.sigma, n.g1):
                    f(cos, fast=fast)
                n.g2(cos[:, None], cos, fast=fast)
            n.p2(us)
            n.p22(us[:, None], us)
        for f in (n.d_wm, n.lambda_w, n.g1_w, n.sigma_w, n.pdf_dcos):
            f(edge_w)
        n.pdf_visible(edge_w[:, None], edge_w)
        # (Few samples: the family's exact warps invert quadratures, up to milliseconds each.)
        w = unit(rng.normal(size=(40, 3)))
        w[:10, 2] = np.abs(w[:10, 2]) * 1e-12
        for uu in (u2, rng.random((40, 2))):
            s = n.sample_visible(w[: len(uu)], uu)
            ok = np.abs(w[: len(uu), 2]) > 0
            np.testing.assert_allclose(np.linalg.norm(s.wm[ok], axis=-1), 1, atol=1e-12)
            assert np.all(s.wm[ok, 2] > 0) and np.all(np.isfinite(s.pdf[ok]))
            d = n.sample_dcos(uu)
            assert np.all(np.isfinite(d.wm)) and np.all(d.wm[:, 2] >= 0)
        for b in (mf.Conductor(n, eta=[0.2, 0.9, 1.1], k=[3.9, 2.4, 2.2]), mf.Dielectric(n, 1.5), mf.Dielectric(n, 1 / 1.5)):
            b.eval(edge_w[:, None], edge_w)
            b.pdf(edge_w[:, None], edge_w)
            u3 = np.concatenate([np.zeros((1, 3)), np.full((1, 3), 1 - 2**-53), rng.random((10, 3))])
            s = b.sample(edge_w[:, None], u3)
            ok = s.lobe > 0
            assert np.all(np.isfinite(s.f[ok])) and np.all(s.pdf[ok] > 0) and np.all(np.isfinite(s.pdf[ok]))


def test_version_is_cargos():
    # __version__ is compiled in from Cargo.toml (PEP 440's spelling), the wheel's version.
    from importlib import metadata

    assert mf.__version__ == metadata.version("microsurface")
    with open(os.path.join(os.path.dirname(__file__), "..", "Cargo.toml")) as fh:
        cargo = next(line.split('"')[1] for line in fh if line.startswith("version"))
    assert mf.__version__ == cargo.replace("-rc.", "rc").replace("-alpha.", "a").replace("-beta.", "b")


# ---- The input contract (issue 36).


def raises(match, f, *args, **kwargs):
    with pytest.raises(ValueError, match=match):
        f(*args, **kwargs)


def all_nan(*xs):
    return all(np.all(np.isnan(x)) for x in xs)


@pytest.mark.parametrize("ndf", [mf.GGX(0.3), mf.BesselK(0.4, 0.5, exact=True)], ids=["ggx_fast", "besselk_exact"])
def test_hostile_input_through_every_public_function(ndf):
    # NaN values give NaN (the element is not computed: a walk or a sampler would make numbers
    # of it); finite values outside their domain, walks < 1 and negative sizes raise
    # ValueError naming the argument; parameters raise the library's ValueError, NaN
    # included. Scalars, arrays and float32 (the engine's three paths).
    nan, inf, up = np.nan, np.inf, [0.0, 0.0, 1.0]
    w_nan = [nan, 0.0, 1.0]
    rng = np.random.default_rng(36)
    bsdfs = [mf.Conductor(ndf), mf.Conductor(ndf, eta=[0.2, 0.9, 1.1], k=[3.9, 2.4, 2.2]), mf.Dielectric(ndf, 1.5)]
    table = mf.AlbedoTable(ndf)
    # (The same NDF with its α as an array of one: the parameter arrays' path.)
    shape = [] if ndf.shape is None else [ndf.shape]
    arr = type(ndf)(np.array([ndf.alpha]), *shape, exact=ndf.exact)

    # NaN in, NaN out.
    for f in (ndf.d, ndf.lambda_, ndf.sigma, ndf.g1, ndf.p2):
        assert all_nan(f(nan), f(np.float32(nan)), f([0.5, nan])[1], f(np.array([nan], np.float32)), getattr(arr, f.__name__)([nan]))
    for f in (ndf.g2, ndf.g2_separable, ndf.p22):
        assert all_nan(f(nan, 0.5), f(0.5, nan), f([0.5, nan], 0.5)[1], getattr(arr, f.__name__)(nan, 0.5))
    for f in (ndf.d_wm, ndf.lambda_w, ndf.g1_w, ndf.sigma_w, ndf.pdf_dcos):
        assert all_nan(f(w_nan), f([w_nan, w_nan])) and not np.isnan(f([up, w_nan])[0])
    assert all_nan(table.e(nan), table.e([0.5, nan])[1]) and not np.isnan(table.e([0.5, nan])[0])
    for f in (ndf.g2_w, ndf.pdf_visible, *(b.eval for b in bsdfs), *(b.pdf for b in bsdfs)):
        assert all_nan(f(w_nan, up), f(up, w_nan), f([up, w_nan], up)[1])
    for s in (ndf.sample_visible(up, [nan, 0.5]), ndf.sample_visible(w_nan, [0.5, 0.5]), ndf.sample_dcos([0.5, nan])):
        assert all_nan(s.wm, s.pdf)
    s = ndf.sample_visible([up, up], [[0.5, 0.5], [0.5, nan]])
    assert all_nan(s.wm[1], s.pdf[1]) and np.all(np.isfinite(s.wm[0]))
    for b in bsdfs:
        for s in (b.sample(up, [nan, 0.5, 0.5]), b.sample(w_nan, [0.5, 0.5, 0.5])):
            # (A NaN element is a rejected sample: lobe 0, not specular; its numbers NaN.)
            assert all_nan(s.wi, s.f, s.pdf, s.eta) and s.lobe == 0 and not s.specular
    for a in (ndf.albedo(nan, walks=10), ndf.albedo(0.5, phi=nan, walks=10), arr.albedo([nan], walks=10)):
        assert all_nan(*a)
    assert all_nan(mf.single_scattering_albedo(ndf, nan), mf.single_scattering_albedo(ndf, 0.5, phi=[nan]))
    # Slopes take any number, ±∞ included.
    assert ndf.p2(inf) == 0 and ndf.p22(inf, -inf) == 0

    # Out of the domain: ValueError naming the argument (for an array, how many and the first).
    cos = r"must be in \[-1, 1\]"
    # (Within 4ε of ±1 is a rounded cosine, taken as ±1: test_rounded_cosines_are_taken_as_one.)
    for bad in (1.5, -1.000000000000002, inf, -inf):
        for f in (ndf.d, ndf.lambda_, ndf.sigma, ndf.g1):
            raises(f"u {cos} \\(got {bad}\\)", f, bad)
            raises(f"u {cos}: 1 of 2 elements are not \\(the first: u\\[1\\] = {bad}\\)", f, [0.5, bad])
            if abs(np.float32(bad)) > 1:  # (-1 - 2e-15 is -1 in float32)
                raises(f"u {cos}", f, np.array([bad], np.float32))
            raises(f"u {cos}", getattr(arr, f.__name__), [bad])
        for f in (ndf.g2, ndf.g2_separable):
            raises(f"u_o {cos}", f, bad, 0.5)
            raises(f"u_i {cos}: 1 of 3 elements", f, 0.5, [0.5, bad, nan])
        raises(f"mu {cos}", ndf.albedo, bad, walks=10)
        raises(f"mu {cos}", ndf.albedo, [[0.5, bad]], walks=10)
        raises(f"mu {cos}", mf.single_scattering_albedo, ndf, bad)
        raises(f"mu {cos}", table.e, [bad])
    raises(r"u must be in \[-1, 1\]: 2 of 4 elements are not \(the first: u\[0, 1\] = 1.5\)", ndf.sigma, [[0.5, 1.5], [2.0, nan]])
    uni = r"u must be in \[0, 1\)"
    for bad in (1.0, -0.25, 1.5, inf):
        raises(f"{uni}: 1 of 2 elements are not \\(the first: u\\[0\\] = {bad}\\)", ndf.sample_visible, up, [bad, 0.5])
        raises(f"{uni}: 1 of 4 elements are not \\(the first: u\\[1, 1\\] = {bad}\\)", ndf.sample_dcos, [[0.5, 0.5], [0.5, bad]])
        for b in bsdfs:
            raises(uni, b.sample, up, [0.5, 0.5, bad])
    for bad in (inf, -inf):
        raises(r"phi must be finite \(got", ndf.albedo, 0.5, phi=bad, walks=10)
        raises(r"phi must be finite: 1 of 2", mf.single_scattering_albedo, ndf, 0.5, phi=[0.0, bad])
    for walks in (0, -1):
        raises(f"walks must be at least 1 \\(got {walks}\\)", ndf.albedo, 0.5, walks=walks)
    raises(r"seed must be in \[0, 2\*\*64\) \(got -1\)", ndf.albedo, 0.5, walks=10, seed=-1)
    raises(r"n must be at least 0 \(got -1\)", ndf.sample_visible, up, rng, -1)
    raises(r"n must be at least 0 \(got -1\)", ndf.sample_dcos, rng, -1)
    for b in bsdfs:
        raises(r"n must be at least 0 \(got -1\)", b.sample, up, rng, -1)
    assert ndf.sample_dcos(rng, 0).wm.shape == (0, 3)

    # Parameters keep their ValueErrors, NaN included, as numbers and arrays.
    cls = type(ndf)
    raises("alpha", cls, nan, *shape)
    raises(r"alpha.*: 1 of 2 elements of alpha are not valid \(the first: \[1\], alpha = nan", cls, [0.3, nan], *shape)
    raises("alpha", cls, [0.0], *shape)
    raises("alpha", cls, 0.3, *shape, alpha_y=[0.3, -1.0])
    raises("eta", ndf.albedo, 0.5, walks=10, eta=nan)
    raises("eta", mf.Dielectric, ndf, nan)
    raises("eta", mf.Conductor, ndf, eta=nan)
    raises("finite", mf.Conductor, ndf, eta=1.5, k=nan)
    for cls in (mf.GGX, mf.Beckmann, mf.DoubleGGX, mf.Exponential, mf.Ei, mf.Erfc, mf.K0):
        raises("alpha", cls, nan)
        raises("alpha", cls, 0.3, alpha_y=nan)
    for cls, shape in ((mf.GTR, "gamma"), (mf.StudentT, "gamma"), (mf.BesselK, "a"), (mf.GenExponential, "gamma")):
        raises("alpha", cls, nan, 2.5)
        raises(shape, cls, 0.3, nan)


def test_rounded_cosines_are_taken_as_one():
    # A cosine from a rounded dot product of unit vectors can exceed 1 by a few ulps: within
    # 4ε it is in the domain and answered as ±1 (the Rust contract's u = 1 + 2ε), beyond it
    # raises.
    g = mf.GGX(0.3)
    for k in (1, 2, 4):
        u = 1 + k * 2.0**-52
        assert g.lambda_(u) == g.lambda_(1.0) and g.d(u) == g.d(1.0) and g.sigma(-u) == g.sigma(-1.0)
    with pytest.raises(ValueError, match=r"u must be in \[-1, 1\]"):
        g.lambda_(1 + 5 * 2.0**-52)
    # float32: within 4 of float32's ε (GGX's f32 kernels, and the engine for the others).
    for ndf in (g, mf.Beckmann(0.3)):
        u32 = np.array([1, 1 + 2.0**-23, 1 + 2.0**-21, -1 - 2.0**-22], np.float32)
        assert np.all(np.isfinite(ndf.lambda_(u32))) and np.all(ndf.lambda_(u32)[:3] == ndf.lambda_(np.float32(1)))
        with pytest.raises(ValueError, match=r"u must be in \[-1, 1\]"):
            ndf.lambda_(np.array([1 + 2.0**-20], np.float32))


def _every_ndf():
    # Every class, plain and shaped, anisotropic, on the exact path, with the warp sampler.
    return [
        mf.GGX(0.5), mf.GGX(0.3, 0.1), mf.Beckmann(1e-6, exact=True), mf.DoubleGGX(2.0),
        mf.Exponential(0.05), mf.Ei(0.3), mf.Erfc(0.7, exact=True, sampler="warp"), mf.K0(0.3),
        mf.GTR(0.2, 0.5), mf.GTR(0.3, gamma=2.0, alpha_y=0.2), mf.StudentT(0.3, 2.5),
        mf.StudentT(0.3, 1.2), mf.BesselK(0.4, a=0.7), mf.GenExponential(0.3, 8.0),
        mf.GGX(0.1 + 0.2),  # (a float whose shortest repr is long)
    ]


def test_ndfs_are_ordinary_python_objects():
    import copy
    import pickle

    ndfs = _every_ndf()
    for n in ndfs:
        # repr evaluates back to an equal NDF (numbers as Python writes them: exact).
        back = eval(repr(n), {"microsurface": mf})
        assert type(back) is type(n) and back == n and hash(back) == hash(n), repr(n)
        assert repr(n).startswith(f"microsurface.{type(n).__name__}(")
        # pickle (every protocol), copy and deepcopy round-trip to an equal NDF that computes
        # the same values.
        for proto in range(pickle.HIGHEST_PROTOCOL + 1):
            p = pickle.loads(pickle.dumps(n, protocol=proto))
            assert type(p) is type(n) and p == n and hash(p) == hash(n)
            assert (p.alpha, p.alpha_y, p.shape, p.exact, p.sampler) == (n.alpha, n.alpha_y, n.shape, n.exact, n.sampler)
        assert copy.copy(n) == n and copy.deepcopy(n) == n
        w = np.array([0.6, 0.0, 0.8])
        if n.name != "student_t" or n.shape > 1.5:
            assert pickle.loads(pickle.dumps(n)).lambda_w(w) == n.lambda_w(w)
    # == and hash by the class and the parameters.
    assert mf.GGX(0.5) == mf.GGX(0.5) and mf.GGX(0.5) != mf.GGX(0.5000000000000001)
    assert mf.GGX(0.5) != mf.Beckmann(0.5) and mf.GGX(0.5) != mf.GGX(0.5, exact=True)
    assert mf.GTR(0.3, 2.0) != mf.GGX(0.3)  # (the same D, another class)
    assert mf.GGX(0.5) != 0.5 and mf.GGX(0.5) != "ggx"
    assert len({mf.GGX(0.5), mf.GGX(0.5), mf.Beckmann(0.5), *ndfs, *ndfs}) == len(set(map(repr, ndfs)) | {repr(mf.Beckmann(0.5))})


def test_ndfs_cross_process_boundaries():
    # multiprocessing (and joblib, which pickles the same way) sends NDFs to workers.
    from concurrent.futures import ProcessPoolExecutor

    ndfs = [mf.GGX(0.3), mf.StudentT(0.4, 3.0), mf.BesselK(0.4, a=0.7, exact=True)]
    u = np.linspace(0.1, 0.9, 5)
    with ProcessPoolExecutor(2) as pool:
        got = list(pool.map(_lambda_of, ndfs, [u] * len(ndfs)))
    for n, g in zip(ndfs, got):
        assert np.array_equal(g, n.lambda_(u))


def _lambda_of(n, u):
    return n.lambda_(u)


def test_bsdfs_are_ordinary_python_objects():
    import copy
    import pickle

    g = mf.GGX(0.3, 0.2)
    bsdfs = [
        mf.Conductor(g), mf.Conductor(g, 0.2, 3.9), mf.Conductor(g, [0.18, 0.42, 1.37], np.array([3.4, 2.4, 1.8])),
        mf.Conductor(mf.BesselK(0.4, a=0.7), 1.5, masking="separable"),
        mf.Conductor(mf.GGX(0.4), 1.5, 2.0, scattering="kulla_conty"),
        mf.Conductor(mf.Beckmann(0.5, exact=True), scattering="walk"),
        mf.Dielectric(g, 1.5), mf.Dielectric(mf.StudentT(0.3, 2.5), 1 / 1.5, masking="correlated_beta", transport="importance"),
    ]
    wo, wi = np.array([0.0, 0.6, 0.8]), np.array([0.48, 0.0, 0.877])
    for b in bsdfs:
        back = eval(repr(b), {"microsurface": mf})
        assert type(back) is type(b) and back == b and hash(back) == hash(b), repr(b)
        for proto in range(pickle.HIGHEST_PROTOCOL + 1):
            p = pickle.loads(pickle.dumps(b, protocol=proto))
            assert type(p) is type(b) and p == b and hash(p) == hash(b)
            assert np.array_equal(p.eval(wo, wi), b.eval(wo, wi)) and p.pdf(wo, wi) == b.pdf(wo, wi)
        assert copy.copy(b) == b and copy.deepcopy(b) == b
    assert mf.Conductor(g, 0.2, 3.9) != mf.Conductor(g, 0.2, 3.8) and mf.Dielectric(g, 1.5) != mf.Conductor(g, 1.5)
    assert mf.Conductor(g, [0.2], [3.9]) == mf.Conductor(g, 0.2, 3.9)  # (channels normalised)
    assert len({*bsdfs, *bsdfs}) == len(bsdfs)


def test_matched_alpha():
    # The matched NDF's quantity equals the reference's (Rust: AnyNdf::matched, tested there
    # for every NDF and quantity); ndf as a class, a name or an instance.
    ref = mf.GGX(0.3)
    u45 = np.sqrt(0.5)
    b = mf.matched_alpha(mf.Beckmann, ref)
    assert type(b) is mf.Beckmann and abs(b.g1(u45) / ref.g1(u45) - 1) < 1e-12
    s = mf.matched_alpha("student_t:4", ref, by="sigma0")
    assert type(s) is mf.StudentT and s.shape == 4.0 and abs(s.sigma(0.0) / ref.sigma(0.0) - 1) < 1e-10
    assert mf.matched_alpha("student_t:4", ref, by="mean_slope").alpha == pytest.approx(s.alpha, rel=1e-12)
    g = mf.matched_alpha(mf.GTR(1.0, 1.5, exact=True), ref, by="dcos_median")
    assert type(g) is mf.GTR and g.shape == 1.5 and g.exact
    # The D·cos median: GGX's radial CDF r²/(α² + r²) has its median at r = α; the matched
    # GTR's samples have the same median (200 000 samples: the median's standard error ~0.3 %).
    rng = np.random.default_rng(5)
    wm = g.sample_dcos(rng, 200_000).wm
    assert abs(np.median(np.hypot(wm[:, 0], wm[:, 1]) / wm[:, 2]) / 0.3 - 1) < 0.015
    with pytest.raises(ValueError, match="gamma"):
        mf.matched_alpha(mf.GTR, ref)
    with pytest.raises(ValueError, match="no alpha"):
        mf.matched_alpha("student_t:1.4", ref, by="sigma0")
    with pytest.raises(ValueError, match="g1_45"):
        mf.matched_alpha(mf.Beckmann, ref, by="rms")


def test_walk_eval_samples_and_seed_equal_the_command_line():
    # eval(wo, wi, samples, seed): the mean of `samples` walks from the stream seed (+ the
    # element's index), the command line's op eval_ms for one element, bit for bit.
    gold = dict(eta=[0.2, 0.9, 1.1], k=[3.9, 2.4, 2.2])
    b = mf.Conductor(mf.GGX(0.5), scattering="walk", **gold)
    wo, wi = [0.0, 0.6, 0.8], [0.6, 0.0, 0.8]
    f = b.eval(np.array(wo), np.array(wi), samples=500, seed=7)
    [r] = cli("bsdf", [dict(bsdf="conductor", op="eval_ms", ndf="ggx", alpha=0.5, wo=wo, wi=wi, samples=500, seed=7, **gold)])
    assert f.tolist() == r["total"]
    assert np.array_equal(f, b.eval(wo, wi, samples=500, seed=7))
    assert not np.array_equal(f, b.eval(wo, wi, samples=500, seed=8))
    # Element i draws from seed + i·φ: a batch's first element is the single call's.
    fb = b.eval(np.array([wo, wo]), np.array(wi), samples=500, seed=7)
    assert np.array_equal(fb[0], f) and not np.array_equal(fb[1], f)
    with pytest.raises(ValueError, match="walk model"):
        mf.Conductor(mf.GGX(0.5)).eval(wo, wi, samples=10)
    with pytest.raises(ValueError, match="samples must be at least 1"):
        b.eval(wo, wi, samples=0)


def test_dielectric_single_scattering_albedo_by_masking():
    # The two transmission maskings the issue measured apart (GGX α = 1, μ = 0.05, η = 1.5):
    # pbrt's 1/(1 + Λo + Λi) transmits 0.728, the exact B(1 + Λo, 1 + Λi) 0.050, and the
    # exact one is the random walk's order 1 (within 4σ of 10⁵ walks).
    g = mf.GGX(1.0)
    pbrt = mf.single_scattering_albedo(g, 0.05, eta=1.5)
    exact = mf.single_scattering_albedo(g, 0.05, eta=1.5, masking="exact")
    assert isinstance(pbrt, mf.DielectricAlbedo)
    assert abs(pbrt.transmit - 0.728) < 5e-3 and abs(exact.transmit - 0.050) < 5e-3
    assert pbrt.reflect == exact.reflect  # (a reflection's G2 is the same in both)
    w = g.albedo(0.05, walks=100_000, eta=1.5, seed=3)
    assert abs(w.transmit[0] - exact.transmit) < 4 * w.transmit_stderr[0] + 2e-5
    assert abs(w.reflect[0] - exact.reflect) < 4 * w.reflect_stderr[0] + 2e-5
    # η broadcasts with mu; from inside (μ < 0) and η < 1 too.
    a = mf.single_scattering_albedo(mf.GGX(0.3), np.array([0.3, -0.3])[:, None], eta=[1.5, 0.7])
    assert a.reflect.shape == (2, 2) and np.all((a.reflect + a.transmit) <= 1 + 2e-5)
    with pytest.raises(ValueError, match="eta"):
        mf.single_scattering_albedo(g, 0.5, eta=[1.5, 1.0])
    with pytest.raises(ValueError, match="masking"):
        mf.single_scattering_albedo(g, 0.5, eta=1.5, masking="walk")


def test_float32_in_float32_out_of_the_albedos():
    g = mf.GGX(0.4)
    mu = np.float32([0.3, 0.8])
    a = g.albedo(mu, walks=200)
    assert all(x.dtype == np.float32 for x in a)
    assert mf.single_scattering_albedo(g, mu).dtype == np.float32
    assert mf.single_scattering_albedo(g, mu, eta=np.float32(1.5)).reflect.dtype == np.float32
    assert mf.single_scattering_albedo(g, mu.astype(np.float64)).dtype == np.float64


def test_table_equals_the_command_line(tmp_path):
    # microsurface.table is `microsurface table`: the same options, the same bits.
    out = tmp_path / "cli.mfa"
    args = ["--ndf", "gtr", "--gamma", "1.5", "--alpha", "0.3:0.8:2", "--mu", "0.5:1:2", "--walks", "2000", "--seed", "3"]
    if not os.path.exists(CLI):
        pytest.skip("the command line is not built")
    subprocess.run([CLI, "table", *args, "--out", str(out)], check=True, capture_output=True)
    want = mf.read_table(out)
    got = mf.table("gtr:1.5", [0.3, 0.8], [0.5, 1.0], walks=2000, seed=3, out=tmp_path / "py.mfa")
    assert got.quantities == want.quantities and got.quantities[:2] == ("r1", "r1_se")
    assert got.values.dtype == np.float32 and got.values.shape == (2, 2, 22)
    assert np.array_equal(got.values, want.values) and np.array_equal(got.alpha, want.alpha)
    assert (tmp_path / "py.mfa").read_bytes() == out.read_bytes()
    # The furnace's walk conserves energy: e = 1 in every cell.
    assert np.all(got.values[:, :, got.quantities.index("e")] == 1.0)
    for kwargs, match in [(dict(material="dielectric"), "needs eta"), (dict(method="mc"), "method"),
                          (dict(material="glass"), "material"), (dict(walks=0), "walks")]:
        with pytest.raises(ValueError, match=match):
            mf.table("ggx", [0.3], [0.5], **kwargs)
    with pytest.raises(ValueError, match="mu"):
        mf.table("ggx", [0.3], [1.5])


def test_lut_equals_the_command_line(tmp_path):
    # microsurface.lut is `microsurface lut`: the library's table, the CLI's .npy its float32.
    got = mf.lut(mf.GGX, "dfg", size=3)
    assert got.axes == ("sqrt_alpha", "mu") and got.channels == ("A", "B", "C")
    assert got.values.dtype == np.float64 and got.values.shape == (3, 3, 3)
    assert np.allclose(got.coords[1], [1 / 6, 0.5, 5 / 6]) and np.allclose(got.params[0], got.coords[0] ** 2)
    # A + B is the conductor's albedo E.
    e = mf.lut("ggx", "albedo", size=3)
    assert np.allclose(got.values[..., 0] + got.values[..., 1], e.values[..., 0], rtol=0, atol=1e-13)
    d = mf.lut(mf.Beckmann, "dielectric", size=2, eta_size=2, nodes="edges")
    assert d.axes == ("side", "eta", "sqrt_alpha", "mu") and d.values.shape == (2, 2, 2, 2, 2)
    assert np.array_equal(d.params[1], [1.0, 3.0]) and np.array_equal(d.params[0], [1.0, -1.0])
    if os.path.exists(CLI):
        out = tmp_path / "t.npy"
        subprocess.run([CLI, "lut", "--ndf", "ggx", "--kind", "dfg", "--size", "3", "--check", "0",
                        "--out", str(out)], check=True, capture_output=True)
        assert np.array_equal(np.load(out), got.values.astype(np.float32))
    for kwargs, match in [(dict(kind="dgf"), "table kind"), (dict(kind="dfg", size=1), "size"),
                          (dict(kind="dfg", mu_axis="cos"), "mu axis"), (dict(kind="dfg", nodes="ends"), "layout"),
                          (dict(kind="dfg", alpha_max=0.0), "alpha"), (dict(kind="dfg", level=9), "level"),
                          (dict(kind="dfg", size=-1), "size")]:
        with pytest.raises(ValueError, match=match):
            mf.lut("ggx", **kwargs)


def test_table_progress_uses_tqdm_where_installed(monkeypatch):
    # progress=True drives a tqdm bar (a stand-in module here: tqdm is optional) to the
    # table's total units of work; without tqdm it is silent.
    import types

    seen = {}

    class Bar:
        def __init__(self, total):
            self.total, self.n = total, 0

        def update(self, k):
            self.n += k

        def close(self):
            seen["done"] = (self.n, self.total)

    monkeypatch.setitem(sys.modules, "tqdm", types.SimpleNamespace(tqdm=Bar))
    mf.table("ggx", [0.3, 0.5], [0.5, 1.0], walks=70_000, progress=True)
    n, total = seen["done"]
    assert total >= 4 and n == total
    # AlbedoTable: a computed table's 33 nodes (Student-T has no shipped table).
    mf.AlbedoTable(mf.StudentT(0.37, 3.3), progress=True)
    assert seen["done"] == (33, 33)
    monkeypatch.setitem(sys.modules, "tqdm", None)  # (import fails: silent)
    mf.table("ggx", [0.3], [0.5], walks=100, progress=True)


def test_albedo_table_nodes_save_and_load(tmp_path):
    t = mf.AlbedoTable(mf.Exponential(0.4))
    assert t.mu.shape == t.values.shape == (33,) and t.mu[0] == 1e-6 and t.mu[-1] == 1.0
    # (The interpolant passes through the nodes at √μ = k/32; the grazing node's value,
    # E(1e-6), stands at √μ = 0.)
    assert np.allclose(t.e(t.mu[1:]), t.values[1:], rtol=0, atol=1e-15)
    t.save(tmp_path / "e.npy")
    u = mf.AlbedoTable.load(tmp_path / "e.npy")
    assert np.array_equal(u.values, t.values) and u.e_avg == t.e_avg
    t.save(tmp_path / "e.mfa")
    v = mf.AlbedoTable.load(tmp_path / "e.mfa")
    np.testing.assert_allclose(v.values, t.values, rtol=6e-8)  # (the format's float32)
    r = mf.read_table(tmp_path / "e.mfa")
    assert r.quantities == ("e1",) and r.alpha.tolist() == [0.4]
    v.save(tmp_path / "again.mfa")  # (the NDF and α travel with it)
    with pytest.raises(ValueError, match="npy"):
        mf.AlbedoTable.load(tmp_path / "e.npy").save(tmp_path / "x.mfa")
    with pytest.raises(ValueError, match="must end"):
        t.save(tmp_path / "e.csv")
    np.save(tmp_path / "bad.npy", np.stack([np.linspace(0, 1, 8), np.ones(8)], -1))
    with pytest.raises(ValueError, match="uniform in sqrt"):
        mf.AlbedoTable.load(tmp_path / "bad.npy")


def test_albedo_by_any_number_of_orders():
    # orders=K: the last axis K (1, …, K − 1, ≥ K); the same walks give the same low orders,
    # and the orders from 4 up sum to the default's ≥ 4.
    g = mf.GGX(1.5)
    a4 = g.albedo([0.3, 0.7], walks=5000, eta=1.5, seed=2)
    a9 = g.albedo([0.3, 0.7], walks=5000, eta=1.5, seed=2, orders=9)
    assert a9.reflect.shape == (2, 9) and a9.transmit_stderr.shape == (2, 9)
    assert np.array_equal(a9.reflect[:, :3], a4.reflect[:, :3])
    np.testing.assert_allclose(a9.transmit[:, 3:].sum(-1), a4.transmit[:, 3], rtol=1e-12)
    assert np.array_equal(a9.total, a4.total)
    assert g.albedo(0.5, walks=100, orders=1).reflect.shape == (1,)
    for bad in (0, 1001):
        with pytest.raises(ValueError, match="orders"):
            g.albedo(0.5, walks=10, orders=bad)


def test_replace_keeps_the_other_parameters():
    n = mf.StudentT(0.3, 2.5, alpha_y=0.6, exact=True, sampler="warp")
    m = n.replace(alpha=0.5)
    assert m == mf.StudentT(0.5, 2.5, alpha_y=0.6, exact=True, sampler="warp")
    assert n.replace(gamma=np.array([3.0, 4.0])).param_shape == (2,)
    assert mf.GGX(0.3).replace(alpha=0.7) == mf.GGX(0.7)
    with pytest.raises(TypeError, match="gamma"):
        mf.GGX(0.3).replace(gamma=2.0)
    with pytest.raises(ValueError, match="alpha"):
        n.replace(alpha=-1.0)


def test_progress_bars_follow_the_loop(monkeypatch):
    # progress=True on the albedos: a tqdm bar (a stand-in here) driven to the element count.
    import types

    bars = []

    class Bar:
        def __init__(self, total):
            self.total, self.n = total, 0
            bars.append(self)

        def update(self, k):
            self.n += k

        def close(self):
            pass

    monkeypatch.setitem(sys.modules, "tqdm", types.SimpleNamespace(tqdm=Bar))
    g = mf.GGX(np.array([0.2, 0.5, 0.9])[:, None])
    g.albedo(np.linspace(0.1, 1, 5), walks=200, progress=True)
    mf.single_scattering_albedo(g, np.linspace(0.1, 1, 5), progress=True)
    assert [(b.n, b.total) for b in bars] == [(15, 15), (15, 15)]


def test_matched_alpha_over_parameter_arrays():
    # The reference's arrays and an instance's shape array broadcast: one match per element.
    ref = mf.GGX(np.array([0.1, 0.3, 0.6])[:, None])
    s = mf.matched_alpha(mf.StudentT(1.0, np.array([1.6, 2.5, 8.0])), ref, by="sigma0")
    assert type(s) is mf.StudentT and s.param_shape == (3, 3)
    for i, a in enumerate([0.1, 0.3, 0.6]):
        for j, g in enumerate([1.6, 2.5, 8.0]):
            one = mf.matched_alpha(f"student_t:{g}", mf.GGX(a), by="sigma0")
            assert s.alpha[i, j] == one.alpha
    b = mf.matched_alpha(mf.Beckmann, mf.GGX([0.3, 0.5]))
    assert b.alpha.shape == (2,) and b.alpha[1] == mf.matched_alpha(mf.Beckmann, mf.GGX(0.5)).alpha
    with pytest.raises(ValueError, match="no alpha"):
        mf.matched_alpha("student_t:1.4", mf.GGX([0.3, 0.5]), by="sigma0")


def test_albedo_table_is_an_ordinary_object():
    import copy
    import pickle

    t = mf.AlbedoTable(mf.GTR(0.4, 1.5))
    for u in (pickle.loads(pickle.dumps(t)), copy.copy(t), copy.deepcopy(t)):
        assert u == t and hash(u) == hash(t) and np.array_equal(u.values, t.values) and u.e_avg == t.e_avg
    assert "gtr:1.5 at alpha=0.4" in repr(t) and t != mf.AlbedoTable(mf.GTR(0.5, 1.5))
