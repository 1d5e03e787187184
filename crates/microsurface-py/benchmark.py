"""Speed of the Python bindings against hand-written NumPy and the Rust slice forms, in one run.

Run: python crates/microsurface-py/benchmark.py  (after pip install ./crates/microsurface-py)

Per element over 10⁶ uniform cosines at α = 0.3 (median of the rounds):
* ours: ``microsurface.GGX(0.3).d(u)`` and ``.lambda_(u)`` with u float64 / float32 (a fresh
  output array every call, as NumPy's);
* NumPy written by hand: the closed forms D = α²/(π ((1 − u)(1 + u) + α²u²)²) and
  Λ = (√(1 + α²(1 − u²)/u²) − 1)/2, in the input's dtype;
* Rust: the library's slice forms of the same precision (``fast::batch::ggx_d``,
  ``ggx_lambda``, ``ggx_d_f32``, ``ggx_lambda_f32``) over preallocated buffers, on one thread
  and on rayon's pool (pieces of 16 384), timed inside Rust in this process;
* the call overhead for a Python float.
The issue's targets: ≥ 3× hand NumPy; within 1.3× of the Rust slice forms; ≤ 1 µs a scalar.
"""

import time

import numpy as np

import microsurface
from microsurface import _microsurface

N = 1_000_000
ROUNDS = 21
ALPHA = 0.3


def median_ns(f, rounds=ROUNDS, n=N):
    f()
    t = []
    for _ in range(rounds):
        start = time.perf_counter()
        f()
        t.append((time.perf_counter() - start) * 1e9 / n)
    return float(np.median(t))


def numpy_d(u):
    a2 = u.dtype.type(ALPHA * ALPHA)
    t = (1 - u) * (1 + u) + u * u * a2
    return a2 / (u.dtype.type(np.pi) * t * t)


def numpy_lambda(u):
    a2 = u.dtype.type(ALPHA * ALPHA)
    return (np.sqrt(1 + a2 * (1 - u * u) / (u * u)) - 1) / 2


def main():
    g = microsurface.GGX(ALPHA)
    u64 = np.random.default_rng(1).random(N)
    rows = []
    for name, ours, hand, rust in [("D", g.d, numpy_d, "d"), ("Λ", g.lambda_, numpy_lambda, "lambda")]:
        for dtype in (np.float64, np.float32):
            one, par = _microsurface._rust_slice_ns(rust, N, ALPHA, ROUNDS, dtype == np.float32)
            u = u64.astype(dtype)
            t_ours = median_ns(lambda: ours(u))
            t_hand = median_ns(lambda: hand(u))
            rows.append((f"GGX {name} {np.dtype(dtype).name}", t_ours, t_hand, one, par))
    print(f"per element, 10⁶ elements, median of {ROUNDS} (ns); Rust: slice form on one thread | rayon")
    print(f"{'':18} {'ours':>6} {'NumPy':>7} {'× NumPy':>8} {'Rust 1':>7} {'Rust par':>9} {'ours/Rust par':>14}")
    for label, t_ours, t_hand, one, par in rows:
        print(f"{label:18} {t_ours:6.2f} {t_hand:7.2f} {t_hand / t_ours:7.2f}× {one:7.2f} {par:9.2f} {t_ours / par:13.2f}×")
    x = 0.5
    t_scalar = median_ns(lambda: [g.d(x) for _ in range(10_000)], n=10_000)
    print(f"scalar call g.d(0.5) (Python float): {t_scalar / 1000:.3f} µs")
    # One direction as a list (the path without NumPy's conversions) against the same
    # direction as a batch of one (the array path).
    w, u = [0.6, 0.0, 0.8], [0.3, 0.7]
    wb, ub = np.array([w]), np.array([u])
    for label, one, batch in [
        ("g.d_wm(w)", lambda: g.d_wm(w), lambda: g.d_wm(wb)),
        ("g.pdf_visible(w, w)", lambda: g.pdf_visible(w, w), lambda: g.pdf_visible(wb, wb)),
        ("g.sample_visible(w, u)", lambda: g.sample_visible(w, u), lambda: g.sample_visible(wb, ub)),
    ]:
        t_one = median_ns(lambda: [one() for _ in range(10_000)], n=10_000)
        t_batch = median_ns(lambda: [batch() for _ in range(10_000)], n=10_000)
        print(f"single direction {label}: {t_one / 1000:.3f} µs (a batch of one: {t_batch / 1000:.2f} µs)")


if __name__ == "__main__":
    main()
