"""The Python bindings against the committed mpmath reference data and NumPy's rules.

Run: pip install ./crates/microsurface-py pytest && pytest crates/microsurface-py/tests
"""

import glob
import json
import os

import numpy as np
import pytest

import microsurface

DATA = os.path.join(os.path.dirname(__file__), "..", "..", "microsurface", "tests", "data")

CLASSES = {
    "beckmann": microsurface.Beckmann,
    "ggx": microsurface.GGX,
    "double_ggx": microsurface.DoubleGGX,
    "exponential": microsurface.Exponential,
    "ei": microsurface.Ei,
    "erfc": microsurface.Erfc,
    "k0": microsurface.K0,
    "gtr": microsurface.GTR,
    "student_t": microsurface.StudentT,
    "bessel_k": microsurface.BesselK,
    "gen_exponential": microsurface.GenExponential,
}


def build(record):
    cls = CLASSES[record["ndf"]]
    alpha = float(record["alpha"])
    if record.get("gamma") is None:
        return cls(alpha)
    return cls(alpha, float(record["gamma"]))


def records():
    files = [os.path.join(DATA, "reference.json")] + sorted(glob.glob(os.path.join(DATA, "extra-*.json")))
    out = []
    for f in files:
        with open(f) as fh:
            out.extend(json.load(fh)["records"])
    return out


def value(n, r):
    q = r["quantity"]
    if q == "D":
        return n.d(float(r["u"]))
    if q == "Lambda":
        return n.lambda_(float(r["u"]))
    if q == "sigma":
        return n.sigma(float(r["u"]))
    if q == "G1":
        return n.g1(float(r["u"]))
    if q == "P2":
        return n.p2(float(r["p"]))
    if q == "P22":
        return n.p22(float(r["p"]), float(r["q"]))
    return None


def test_every_reference_value():
    """Every committed mpmath value (classic NDFs and the family) within the library's
    documented accuracy: 1e-13 for closed forms, 1e-10 for numerical quantities (we hold all
    to 1e-10 here; the Rust suite holds the closed forms to 1e-13), exact zeros as zeros."""
    checked = 0
    worst = 0.0
    for r in records():
        if r["quantity"] not in ("D", "Lambda", "sigma", "G1", "P2", "P22"):
            continue
        n = build(r)
        got = value(n, r)
        want = r["f64"]
        assert isinstance(got, np.float64)
        if want == 0.0 or not np.isfinite(want):
            assert got == want or (want == 0.0 and abs(got) < 1e-300), (r, got)
        else:
            rel = abs(got - want) / abs(want)
            worst = max(worst, rel)
            assert rel <= 1e-10, (r, got)
        checked += 1
    assert checked > 3000
    print(f"{checked} reference values, worst relative error {worst:.2e}")


def test_dtypes_and_scalars():
    g = microsurface.GGX(0.3)
    assert isinstance(g.d(0.5), np.float64)
    assert isinstance(g.d(np.float32(0.5)), np.float32)
    assert g.d(np.array([0.5], dtype=np.float32)).dtype == np.float32
    assert g.d([0.5, 0.6]).dtype == np.float64
    assert g.d(np.array([1, 0])).dtype == np.float64  # integers: float64
    # float32 results are the float64 values rounded once, except GGX's D, Λ and G1, which run
    # the library's f32 slice forms (f32 arithmetic, within 6e-7 of the exact value).
    u = np.linspace(0.01, 1.0, 101)
    t = microsurface.StudentT(0.3, 2.5)
    assert np.array_equal(t.lambda_(u.astype(np.float32)), t.lambda_(u.astype(np.float32).astype(np.float64)).astype(np.float32))
    assert np.array_equal(g.sigma(u.astype(np.float32)), g.sigma(u.astype(np.float32).astype(np.float64)).astype(np.float32))
    u32 = np.concatenate([u, [0.0, -0.3, 1e-40, np.nan]]).astype(np.float32)
    for f in (g.d, g.lambda_, g.g1):
        got, want = f(u32), f(u32.astype(np.float64))
        assert got.dtype == np.float32
        with np.errstate(over="ignore"):  # (Λ(1e-40) overflows f32: ∞ in both)
            want = want.astype(np.float32)
        np.testing.assert_allclose(got, want, rtol=6e-7, atol=0)
        # A float32 scalar, array or 0-d array, or α as a float32 array: the same f32 path.
        assert all(f(x) == f(np.array([x]))[0] or np.isnan(x) for x in u32)
        assert np.array_equal(getattr(microsurface.GGX(np.float32(0.3)), f.__name__)(u32), got, equal_nan=True)
    # Python and NumPy float64 scalars take a path without arrays: the same values, bit for bit.
    for x in np.linspace(-1.0, 1.0, 35):
        assert g.lambda_(float(x)) == g.lambda_(np.array([x]))[0]
        assert g.g2(float(x), 0.7) == g.g2(np.array(x), np.array(0.7))
        assert isinstance(g.sigma(x), np.float64) and g.sigma(x) == g.sigma(np.array([x]))[0]
    assert isinstance(g.d(1), np.float64) and g.d(1) == g.d(1.0)
    # Mixed precision, as NumPy 2 (NEP 50): a Python float is weak and takes float32's
    # precision; a float64 array or NumPy float64 scalar wins.
    assert g.g2(np.float32(0.5), 0.5).dtype == np.float32
    assert g.g2(np.float32(0.5), np.float64(0.5)).dtype == np.float64
    assert g.g2(np.float32(0.5), np.array(0.5)).dtype == np.float64


def test_broadcasting():
    t = microsurface.StudentT(0.3, 2.5)
    a = np.linspace(0.1, 0.9, 6).reshape(2, 1, 3)
    b = np.linspace(0.2, 1.0, 4).reshape(4, 1)
    got = t.g2(a, b)
    assert got.shape == (2, 4, 3)
    want = np.array([[[t.g2(float(x), float(y)) for x in row] for y in b.ravel()] for row in a.reshape(2, 3)])
    assert np.array_equal(got, want)  # bit for bit: the same Rust function per element
    assert t.p22(np.zeros((3, 1)), np.zeros((1, 5))).shape == (3, 5)
    # Non-contiguous input.
    u = np.linspace(0.0, 1.0, 20)[::3]
    assert np.array_equal(t.d(u), np.array([t.d(float(x)) for x in u]))
    with pytest.raises(ValueError):
        t.g2(np.zeros(3), np.zeros(4))


def test_large_arrays_match_the_scalar_calls():
    """Above 16 384 elements the loop runs in parallel without the GIL: the same values."""
    b = microsurface.BesselK(0.4, 1.7)
    u = np.random.default_rng(3).random(40_000)
    many = b.lambda_(u)
    idx = np.arange(0, 40_000, 997)
    assert np.array_equal(many[idx], np.array([b.lambda_(float(x)) for x in u[idx]]))


def test_nan_and_edges():
    g = microsurface.GGX(0.3)
    assert np.isnan(g.d(np.nan)) and np.isnan(g.lambda_(np.nan))
    assert g.d(-0.5) == 0.0 and g.lambda_(0.0) == np.inf and g.g1(0.0) == 0.0


def test_errors():
    with pytest.raises(ValueError, match="alpha"):
        microsurface.GGX(0.0)
    with pytest.raises(ValueError, match="gamma"):
        microsurface.GTR(0.3, -1.0)
    with pytest.raises(ValueError):
        microsurface.BesselK(0.3, 0.01)
    with pytest.raises(ValueError):
        microsurface.StudentT(0.3, 1.0)
    # Strings and objects are not numbers: TypeError, as SciPy's real functions.
    with pytest.raises(TypeError):
        microsurface.GGX(0.3).d("x")
    with pytest.raises(TypeError):
        microsurface.GGX(0.3).d(object())


def test_stubs_name_every_class_and_method():
    from microsurface import _microsurface

    with open(os.path.join(os.path.dirname(microsurface.__file__), "_microsurface.pyi")) as fh:
        stubs = fh.read()
    for name in dir(_microsurface):
        obj = getattr(_microsurface, name)
        if name.startswith("_"):
            continue
        if isinstance(obj, type):
            assert f"class {name}" in stubs, name
            for attr in vars(obj):
                if not attr.startswith("_"):
                    assert f"def {attr}(" in stubs, (name, attr)
        elif callable(obj):
            assert f"def {name}(" in stubs, name


def test_attributes_and_help():
    b = microsurface.BesselK(0.4, 1.5)
    assert b.alpha == 0.4 and b.shape == 1.5 and b.name == "bessel_k"
    assert isinstance(b, microsurface.NDF)
    assert "Smith" in microsurface.NDF.lambda_.__doc__
    assert "1e-13" in microsurface.NDF.__doc__
