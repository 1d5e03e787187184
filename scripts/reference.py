#!/usr/bin/env python3
"""Extra high-precision reference values for microfacet (mpmath), beyond shared/reference.

Covers what the shared sample does not: tiny and large alpha, alpha and gamma within 1e-12 of
the removable singularities of GTR, general gamma, grazing and near-normal directions, and the
slope marginals near p = 0. Each Lambda is computed by two independent routes (the Smith
integral over P2, and the projected-area "delta integral" over D) and the record keeps their
agreement.

Usage: python3 scripts/reference.py [NDF ...] > crates/microfacet/tests/data/extra-NAME.json
(no NDF: all of them; the test reads every tests/data/extra-*.json)
Needs: pip install mpmath  (runs in a few minutes on 2 cores)
"""
import json
import sys
from mpmath import mp, mpf, sqrt, exp, pi, log, expm1, hyp2f1, besselk, struvel, hyperu, e1, quad, inf, acos, erfc, gamma as G

mp.dps = 30


def dec(x):
    """The exact value of the double nearest to x, as an mpf."""
    return mpf(float(x))


# ---- NDF definitions (in slope space, radial P22(r), and D(u)) ----
def gtr_c(a, g):
    """Burley's constant. Near alpha = 1 and gamma = 1 it is 0/0: with alpha - 1 and gamma - 1
    of order 1e-12, 1 - alpha^(2-2 gamma) is ~1e-24 and a 30-digit evaluation keeps only six
    digits of it, so the constant is evaluated with 100 guard digits."""
    with mp.workdps(mp.dps + 100):
        if a == 1:
            return +(1 / pi)
        if g == 1:
            return +((a**2 - 1) / (pi * log(a**2)))
        return +((g - 1) * (a**2 - 1) / (pi * (1 - (a**2) ** (1 - g))))


def make(ndf, a, g=None):
    if ndf == "beckmann":
        P = lambda r: exp(-r**2 / a**2) / (pi * a**2)
        P2 = lambda p: exp(-p**2 / a**2) / (sqrt(pi) * a)
    elif ndf == "ggx":
        P = lambda r: a**2 / (pi * (r**2 + a**2) ** 2)
        P2 = lambda p: a**2 / (2 * (p**2 + a**2) ** mpf(1.5))
    elif ndf == "double_ggx":
        def P(r):
            if r == 0:
                return 1 / (pi * a**2)
            c = a**2 / r**2
            # the bracket cancels like 1/c^2 (derivations.md D): add guard digits
            with mp.workdps(mp.dps + 20 + int(2 * mp.log10(1 + c))):
                return +(a**2 * ((1 + c) * exp(c) * e1(c) - 1) / (pi * r**4))
        def P2(p):
            if p == 0:
                return sqrt(pi) / (4 * a)
            c = a**2 / p**2
            return sqrt(pi) * a**2 / (4 * abs(p) ** 3) * hyperu(mpf(1.5), 1, c)
    elif ndf == "exponential":
        P = lambda r: 2 * exp(-2 * r / a) / (pi * a**2)
        def P2(p):
            if p == 0:
                return 2 / (pi * a)
            return 4 * abs(p) / (pi * a**2) * besselk(1, 2 * abs(p) / a)
    elif ndf == "gtr":
        c = gtr_c(a, g)
        P = lambda r: c * (1 + r**2) ** (g - 2) * (r**2 + a**2) ** (-g)
        def P2(p):
            z = (1 - a**2) / (1 + p**2)
            return pi * c / 2 * (1 + p**2) ** (g - 2) * (a**2 + p**2) ** (mpf(1) / 2 - g) * hyp2f1(mpf(1) / 2, 2 - g, 2, z)
    D = lambda u: P(sqrt(1 - u**2) / u) / u**4 if u > 0 else mpf(0)
    return D, P, P2


def lambda_closed(ndf, a, g, u):
    """Closed forms of Lambda where they exist (None otherwise), with guard digits for the
    cancellations listed in docs/derivations.md, section D."""
    b = u / sqrt(1 - u**2)  # cot(theta)
    if ndf == "beckmann":
        x = b / a
        with mp.workdps(mp.dps + 20 + int(2 * mp.log10(1 + x))):
            return +((exp(-x * x) / (x * sqrt(pi)) - erfc(x)) / 2)
    if ndf == "ggx":
        with mp.workdps(mp.dps + 40):
            return +((-1 + sqrt(1 + (a / b) ** 2)) / 2)
    if ndf == "double_ggx":
        with mp.workdps(mp.dps + 40):
            return +((sqrt(pi) * hyperu(-mpf(1) / 2, 0, (a / b) ** 2) - 1) / 2)
    if ndf == "exponential":
        # derivations.md A.14: Lambda = (2 K1(z) - Ki1(z))/pi with the Bickley function
        # Ki1(z) = pi/2 - (pi z/2)[K0(z) L_{-1}(z) + K1(z) L0(z)], which cancels down to
        # ~e^{-z}: z/ln(10) guard digits. (A quadrature of K0 from z to infinity at 30-80
        # digits was found to be off by up to 5e-9 for z ~ 600.)
        z = 2 * b / a
        if z > 800:
            return mpf(0)  # Lambda ~ e^{-z} < 1e-300: below the f64 range, the record is skipped
        with mp.workdps(mp.dps + 30 + int(z / mp.log(10))):
            ki1 = pi / 2 - pi * z / 2 * (besselk(0, z) * struvel(-1, z) + besselk(1, z) * struvel(0, z))
            return +((2 * besselk(1, z) - ki1) / pi)
    if ndf == "gtr" and g == 1:
        with mp.workdps(mp.dps + 60):
            s = sqrt(1 + (1 / u**2 - 1) * a**2)
            return +((-1 + u * s + u * log(1 + 1 / u) - u * log(1 + s)) / (2 * u * log(a)))
    return None


def breaks(a0, scale, n=12):
    pts = [a0]
    s = scale
    for _ in range(n):
        pts.append(a0 + s)
        s *= 4
    return pts + [inf]


def lambda_smith(P2, u, a):
    """Lambda(u) = (1/b) int_b^inf (q - b) P2(q) dq, b = cot(theta)."""
    b = u / sqrt(1 - u**2)
    return quad(lambda q: (q - b) * P2(q), breaks(b, a / 64)) / b


def delta_kernel(u, ui):
    A = u * ui
    B = sqrt(1 - u**2) * sqrt(1 - ui**2)
    if A >= B:
        return 2 * pi * A
    if A <= -B:
        return mpf(0)
    return 2 * (sqrt(B**2 - A**2) + A * acos(-A / B))


def lambda_delta(D, u, a):
    """Lambda(u) = sigma(-u)/u with sigma(-u) = int_0^sqrt(1-u^2) D(ui) Delta(-u, ui) dui."""
    top = sqrt(1 - u**2)
    # the NDF's width in ui near 1 is ~a^2/2; split there
    pts = sorted(set([mpf(0), top] + [x for x in [1 - a**2 * k for k in (0.5, 2, 8, 32)] if 0 < x < top]))
    return quad(lambda ui: D(ui) * delta_kernel(-u, ui), pts) / u


def rec(ndf, a, g, quantity, value, methods, **inputs):
    value = mp.mpf(value)
    r = {"ndf": ndf, "alpha": repr(float(a)), "gamma": (repr(float(g)) if g is not None else None), "quantity": quantity}
    for k, v in inputs.items():
        r[k] = repr(float(v))
    r["value"] = mp.nstr(value, 25)
    r["f64"] = float(value)
    vals = list(methods.values())
    diffs = [abs(v - vals[0]) / abs(vals[0]) for v in vals[1:] if vals[0] != 0]
    r["methods"] = {k: mp.nstr(v, 25) for k, v in methods.items()}
    r["max_rel_diff"] = mp.nstr(max(diffs), 3) if diffs else None
    # agreement with the best independent method: a record needs one confirmation
    r["min_rel_diff"] = mp.nstr(min(diffs), 3) if diffs else None
    return r


def main():
    out = []
    dropped = []
    alphas = ["0.001", "0.03", "0.4", "2.5", "10"]
    near_one = [1 - 1e-12, 1 + 1e-12]
    us = ["0.02", "0.3", "0.7", "0.95", "0.999999"]
    ps = ["0", "0.001", "0.2", "1.5", "30"]
    cases = []
    for ndf in ["beckmann", "ggx", "double_ggx", "exponential"]:
        for a in alphas:
            cases.append((ndf, dec(a), None))
    for g in ["0.5", "0.999999999999", "1.000000000001", "1.3", "2.5"]:
        for a in ["0.01", "2.5"] + near_one:
            cases.append(("gtr", dec(a), dec(g)))
    for g in ["1", "2"]:
        for a in near_one:
            cases.append(("gtr", dec(a), dec(g)))
    only = sys.argv[1:]
    for ndf, a, g in cases:
        if only and ndf not in only:
            continue
        D, P, P2 = make(ndf, a, g)
        for us_ in us:
            u = dec(us_)
            out.append(rec(ndf, a, g, "D", D(u), {"closed form": D(u)}, u=u))
            if D(u) != 0 and not mp.isfinite(D(u)):
                raise SystemExit("bad D")
            # Lambda by two routes; skip where it underflows double precision entirely
            l1 = lambda_smith(P2, u, a)
            closed = lambda_closed(ndf, a, g, u)
            m = {}
            if closed is not None:
                m["closed form"] = closed
            m["Smith integral over P2"] = l1
            m["delta integral sigma(-u)/u over D"] = lambda_delta(D, u, a)
            l1 = list(m.values())[0]
            if abs(l1) < mpf("1e-300"):
                continue  # below the f64 range: nothing to test
            r = rec(ndf, a, g, "Lambda", l1, m, u=u)
            if r["min_rel_diff"] is not None and mpf(r["min_rel_diff"]) >= mpf("1e-15"):
                dropped.append(r)
                continue  # unconfirmed: neither it nor G1, sigma derived from it are kept
            out.append(r)
            out.append(rec(ndf, a, g, "G1", 1 / (1 + l1), {"1/(1+Lambda)": 1 / (1 + l1)}, u=u))
            out.append(rec(ndf, a, g, "sigma", u * (1 + l1), {"u(1+Lambda)": u * (1 + l1)}, u=u))
            out.append(rec(ndf, a, g, "sigma", u * l1, {"u Lambda": u * l1}, u=-u))
        for ps_ in ps:
            p = dec(ps_)
            v = P2(p)
            m = {"closed form": v, "integral of P22 dq": 2 * quad(lambda q: P(sqrt(p**2 + q**2)), breaks(0, a / 16))}
            out.append(rec(ndf, a, g, "P2", v, m, p=p))
            q = dec("0.25")
            out.append(rec(ndf, a, g, "P22", P(sqrt(p**2 + q**2)), {"closed form": P(sqrt(p**2 + q**2))}, p=p, q=q))
        print(f"{ndf} a={float(a)} g={g}: {len(out)} records", file=sys.stderr)
    # Keep only values that at least one independent method confirms to 1e-15 (mpmath's
    # quadratures cannot always resolve the extreme peaks; unconfirmed records are dropped).
    kept = [r for r in out if r["min_rel_diff"] is None or mpf(r["min_rel_diff"]) < mpf("1e-15")]
    dropped += [r for r in out if r not in kept]
    for r in dropped:
        print(f"dropped (best confirmation {r['min_rel_diff']}): {r['ndf']} a={r['alpha']} g={r['gamma']} {r['quantity']} u={r.get('u')} p={r.get('p')}", file=sys.stderr)
    out = kept
    worst = max((mpf(r["min_rel_diff"]) for r in out if r["min_rel_diff"]), default=0)
    meta = {"description": "extra reference values (scripts/reference.py, mpmath)", "dps": mp.dps,
            "n_records": len(out), "n_dropped_unconfirmed": len(dropped), "worst_confirmation": mp.nstr(worst, 3)}
    json.dump({"meta": meta, "records": out}, sys.stdout, indent=0)


if __name__ == "__main__":
    main()
