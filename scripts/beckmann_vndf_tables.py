#!/usr/bin/env python3
"""Tables of the fast Beckmann visible-normal warp (mpmath), written as Rust.

Usage: python3 scripts/beckmann_vndf_tables.py > crates/microsurface/src/fast/beckmann_tables.rs
       python3 scripts/beckmann_vndf_tables.py --reference > crates/microsurface/tests/data/beckmann-vndf.json
(the second: X at ~1300 (a, u), across both tables' ranges and beyond them, for tests/fast.rs)
Needs: pip install mpmath  (seconds)

`fast::beckmann` inverts the visible slope CDF of the alpha = 1 Beckmann NDF (Heitz & d'Eon
2014): for a direction with cot(theta) = a the slope X has the density (X + a) e^{-X^2}/(sqrt(pi) Z)
on X > -a, with

    N(X) = a/2 (erfc(-X) - erfc a) - (e^{-X^2} - e^{-a^2})/(2 sqrt(pi)),   Z = a + L(a),
    L(a) = a Lambda(a) = e^{-a^2}/(2 sqrt(pi)) - a/2 erfc a,

and X solves N(X) = u Z. Both tables are functions of t = 1/(1 + a) in [0, 1] (t = 0 is normal
incidence, a = infinity):

* L: 64 equal intervals of t, on each the Chebyshev interpolant of L at 9 points as a
  polynomial in s in [-1, 1], its constant term split into a head and a tail (two doubles), so
  that the sum rounds once: L is within about an ulp of L's own size where it matters (the
  sampler's N(X) - uZ cancels against it in the lower tail). Below t = 1/8 (a > 7) the rows
  are 0: L < 2e-24 there, below the rounding of Z = a + L > 7.
* X0: the initial guess of X, on cells of (t, octave of v), v = u below 1/2 and 1 - u above
  (exact there), each the 4 x 4 Chebyshev interpolant of X as a polynomial in (r, s), r and s
  the cell's coordinates in [-1, 1], in f32: 16 t-intervals x 10 octaves [2^-11, 2^-1) below
  1/2, 8 x 20 octaves [2^-21, 2^-1) above, in one table (the cells below 1/2 first, each side
  row-major in t). Guess error about 2e-4 of min(1, X + a) (tests/fast.rs measures it), which
  the one step of order five in fast::beckmann takes below the rounding of N(X) itself.

And the slope y = erfinv(2u - 1), the other half of the warp, without a logarithm:

* ERFINV_Q: erfinv(v)/v at v = 1 - q on octaves of q in [2^-60, 1), 8 segments each, the
  Chebyshev interpolant at 10 points of each (in mpmath at 60 digits: erfinv loses a digit
  per decade of q near v = 1). Interpolation error about 2e-16, relative.
"""
import math
import sys
from mpmath import mp, mpf, erfc, exp, sqrt, pi, cos, matrix, lu_solve

mp.dps = 30

C0 = 1 / (2 * sqrt(pi))

L_INTERVALS, L_POINTS = 64, 9
X0_T = (16, 8)  # t-intervals below and above u = 1/2
X0_K = (10, 20)  # octaves of v below and above u = 1/2
X0_N = 4  # points per cell side (cubic in r and in s)


def L(a):
    """a Lambda(a) for the Beckmann NDF (a >= 0, mpf)."""
    return C0 * exp(-a * a) - a / 2 * erfc(a)


def quantile(a, u):
    """X with N(X) = u Z, to ~1e-25: bisection in floats, then Newton in mpmath."""
    af, uf = float(a), float(u)
    sp = math.sqrt(math.pi)
    zf = af / 2 * math.erfc(-af) + math.exp(-af * af) / (2 * sp) if af < 1e8 else af

    def f(x):
        # N(x) - uZ from the side without cancellation
        if x <= 0:
            return af / 2 * (math.erfc(-x) - math.erfc(af)) - (math.exp(-x * x) - math.exp(-af * af)) / (2 * sp) - uf * zf
        return (1 - uf) * zf - af / 2 * math.erfc(x) - math.exp(-x * x) / (2 * sp)

    lo, hi = -af, 9.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            break
        if f(mid) < 0:
            lo = mid
        else:
            hi = mid
    x = mpf(0.5 * (lo + hi))
    a, u = mpf(a), mpf(u)
    z = a + L(a)
    for _ in range(4):
        if x <= 0:
            fx = a / 2 * (erfc(-x) - erfc(a)) - (exp(-x * x) - exp(-a * a)) / (2 * sqrt(pi)) - u * z
        else:
            fx = (1 - u) * z - a / 2 * erfc(x) - exp(-x * x) / (2 * sqrt(pi))
        x -= fx / ((x + a) * exp(-x * x) / sqrt(pi))
    return x


def gaussian_quantile(u):
    """erfinv(2u - 1), the a = infinity limit (t = 0)."""
    from mpmath import erfinv
    return erfinv(2 * mpf(u) - 1)


def chebyshev_points(n):
    return [cos(pi * (k + mpf(1) / 2) / n) for k in range(n)]


def monomial_fit(points, values):
    """Coefficients c_j of sum c_j s^j through (points, values) (n x n Vandermonde, mpmath)."""
    n = len(points)
    return lu_solve(matrix([[p**j for j in range(n)] for p in points]), matrix(values))


def a_of(t):
    return (1 - t) / t


def l_table():
    rows = []
    s_pts = chebyshev_points(L_POINTS)
    for i in range(L_INTERVALS):
        t0, t1 = mpf(i) / L_INTERVALS, mpf(i + 1) / L_INTERVALS
        if t1 <= mpf(1) / 8:
            rows.append([0.0] * (L_POINTS + 1))
            continue
        vals = [L(a_of(t0 + (s + 1) / 2 * (t1 - t0))) for s in s_pts]
        c = monomial_fit(s_pts, vals)
        head = float(c[0])
        rows.append([head, float(c[0] - head)] + [float(c[j]) for j in range(1, L_POINTS)])
    return rows


def x0_table(upper):
    nt, nk = X0_T[upper], X0_K[upper]
    pts = chebyshev_points(X0_N)
    cells = []
    for it in range(nt):
        t0, t1 = mpf(it) / nt, mpf(it + 1) / nt
        for k in range(nk):
            v0 = mpf(2) ** (k - nk - 1)
            grid = []  # grid[i][j]: X at (r_i, s_j)
            for r in pts:
                t = t0 + (r + 1) / 2 * (t1 - t0)
                row = []
                for s in pts:
                    v = v0 * (1 + (s + 1) / 2)
                    u = 1 - v if upper else v
                    row.append(quantile(a_of(t), u))
                grid.append(row)
            # in s for each r, then in r for each power of s
            by_s = [monomial_fit(pts, grid[i]) for i in range(X0_N)]
            c = [[mpf(0)] * X0_N for _ in range(X0_N)]
            for j in range(X0_N):
                col = monomial_fit(pts, [by_s[i][j] for i in range(X0_N)])
                for i in range(X0_N):
                    c[i][j] = col[i]
            cells.append([float(c[i][j]) for i in range(X0_N) for j in range(X0_N)])
    return cells


ERFINV_Q_K0, ERFINV_Q_M, ERFINV_Q_POINTS = -60, 3, 10


def erfinv_q_table():
    """Rows of erfinv(1 - q)/(1 - q) on the octave segments of [2^K0, 1) (fit.rs's layout)."""
    rows = []
    pts = chebyshev_points(ERFINV_Q_POINTS)
    with mp.workdps(60):
        def ratio(q):
            v = 1 - q
            return sqrt(pi) / 2 if v == 0 else mp.erfinv(v) / v
        for e in range(ERFINV_Q_K0, 0):
            lo = mpf(2) ** e
            h = lo / 2**ERFINV_Q_M
            for j in range(2**ERFINV_Q_M):
                x0 = lo + j * h
                c = monomial_fit(pts, [ratio(x0 + (s + 1) / 2 * h) for s in pts])
                rows.append([float(c[i]) for i in range(ERFINV_Q_POINTS)])
    return rows


def f32(x):
    """The shortest decimal that reads back as the f32 nearest to x."""
    import struct
    y = struct.unpack("f", struct.pack("f", x))[0]
    for digits in range(6, 12):
        s = f"{y:.{digits}e}"
        if struct.unpack("f", struct.pack("f", float(s)))[0] == y:
            return s
    return repr(y)


def main():
    out = sys.stdout
    out.write("//! @generated by `python3 scripts/beckmann_vndf_tables.py` (mpmath); do not edit.\n")
    out.write("//! The fast Beckmann visible-normal warp's tables (see the script and `fast::beckmann`).\n\n")
    out.write(f"/// Intervals of t in [`BECKMANN_L`].\n")
    out.write(f"pub const L_INTERVALS: usize = {L_INTERVALS};\n")
    out.write(f"/// L(a) = aΛ(a) = e^{{−a²}}/(2√π) − (a/2) erfc a on {L_INTERVALS} intervals of t = 1/(1 + a):\n")
    out.write("/// per interval [head, tail, c₁, …, c₈], L = head + (tail + Σ c_j s^j), s ∈ [−1, 1].\n")
    out.write(f"pub static BECKMANN_L: [[f64; {L_POINTS + 1}]; {L_INTERVALS}] = [\n")
    for row in l_table():
        out.write("    [" + ", ".join(repr(x + 0.0) for x in row) + "],\n")
    out.write("];\n\n")
    rows = erfinv_q_table()
    out.write(f"/// erfinv(v)/v at v = 1 − q, q ∈ [2^{ERFINV_Q_K0}, 1): octaves of q, 2^{ERFINV_Q_M} segments each (fit.rs's layout).\n")
    out.write(f"pub const ERFINV_Q_K0: i32 = {ERFINV_Q_K0};\n")
    out.write(f"/// See [`ERFINV_Q_K0`].\n")
    out.write(f"pub const ERFINV_Q_M: u32 = {ERFINV_Q_M};\n")
    out.write(f"/// See [`ERFINV_Q_K0`].\n")
    out.write(f"pub static ERFINV_Q: [[f64; {ERFINV_Q_POINTS}]; {len(rows)}] = [\n")
    for row in rows:
        out.write("    [" + ", ".join(repr(x + 0.0) for x in row) + "],\n")
    out.write("];\n\n")
    nt, nk = X0_T, X0_K
    out.write("/// Intervals of t of [`BECKMANN_X0`] below and above u = ½.\n")
    out.write(f"pub const X0_T: [usize; 2] = [{nt[0]}, {nt[1]}];\n")
    out.write("/// Octaves of v (u below ½, 1 − u above) of [`BECKMANN_X0`]: [2^−(K+1), ½).\n")
    out.write(f"pub const X0_K: [usize; 2] = [{nk[0]}, {nk[1]}];\n")
    out.write(f"/// Initial guess of the visible slope X: {nt[0]} intervals of t × {nk[0]} octaves [2^{-nk[0] - 1}, ½) of\n")
    out.write(f"/// v = u for u < ½ (cells it·{nk[0]} + octave), then {nt[1]} × {nk[1]} octaves [2^{-nk[1] - 1}, ½) of v = 1 − u for\n")
    out.write(f"/// u ≥ ½ (cells {nt[0] * nk[0]} + it·{nk[1]} + octave); per cell X ≈ Σ c[4i + j] rⁱ sʲ, r and s ∈ [−1, 1] the\n")
    out.write("/// position in the t-interval and in the octave.\n")
    out.write(f"pub static BECKMANN_X0: super::Cells<{nt[0] * nk[0] + nt[1] * nk[1]}> = super::Cells([\n")
    for upper in (0, 1):
        for cell in x0_table(upper):
            out.write("    [" + ", ".join(f32(x + 0.0) for x in cell) + "],\n")
    out.write("]);\n")


def reference():
    """[a, u, X] records: a grid of t with fixed and seeded-random u (both ends of the hot
    range and past them included), and seeded-random (t, u) with a third of u log-uniform
    in [2^-20, 1)."""
    import json
    import random
    rng = random.Random(35)
    pts = []
    ts = [i / 40 + 0.0125 for i in range(40)] + [1e-3, 0.999, 0.9999]
    us = [0.5, 0.25, 0.75, 1 / 2048 * 1.01, 1 / 4096, 1e-6, 0.01, 0.05, 0.1, 0.9, 0.99, 0.999,
          1 - 2**-16, 1 - 2**-21 * 1.01, 1 - 2**-23]
    for t in ts:
        for u in us + [rng.random() for _ in range(12)]:
            pts.append((a_of(mpf(t)), u))
    for _ in range(300):
        t = rng.random()
        u = 2 ** (-20 * rng.random()) if rng.random() < 0.3 else rng.random()
        pts.append((a_of(mpf(t)), u))
    recs = []
    for a, u in pts:
        a = float(a)
        recs.append([a, u, float(quantile(a, u))])
    json.dump({"note": "X solving N(X) = uZ for the alpha = 1 Beckmann visible slope at "
               "cot(theta) = a (scripts/beckmann_vndf_tables.py --reference, mpmath)",
               "records": recs}, sys.stdout, indent=None)
    sys.stdout.write("\n")


if __name__ == "__main__":
    if sys.argv[1:] == ["--reference"]:
        reference()
    else:
        main()
