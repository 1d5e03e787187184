#!/usr/bin/env python3
"""microsurface's rough conductor and dielectric against Mitsuba 3's roughconductor and
roughdielectric (PyPI `mitsuba`, variant scalar_rgb), GGX and Beckmann, separable G (Mitsuba's
G is the product of two G1), anisotropic conductor, isotropic dielectric (η = 1.5, radiance
transport), through `microsurface bsdf` (JSON lines). Skips (exit 0) when Mitsuba is not
installed, unless MITSUBA_REQUIRED is set; .ci/run installs it and sets it.

Conventions: Mitsuba's si.wi is microsurface's wo (toward the viewer), its `wo` argument is our
wi, and its eval returns f·|cos θi|; both pdfs are per unit solid angle of wi.

Bounds (relative, per value, where the value exceeds 1e-4 of the lobe's peak scale):
* GGX: Mitsuba evaluates in float32 (scalar_rgb); agreement to 1e-5 in f and pdf (measured:
  1.0e-6 at most over these 2400 pairs, 8 f32 ulps, what D and G1 inherit from the f32
  rounding of the half vector and of the cosines near grazing; the bound leaves 10×). The
  measured maxima are printed.
* Beckmann: Mitsuba's G1 is Walter et al. 2007's rational approximation of
  2/(1 + erf(a) + e^{−a²}/(a√π)), whose relative error reaches 3.1e-3 (a ≈ 1.6, measured
  below); f carries two G1 (6.3e-3) and the pdf one (3.1e-3, and so Mitsuba's visible-normal
  pdf integrates to 1 ± 3e-3). Compared with those bounds plus the f32 allowance.

Usage: scripts/mitsuba_compare.py [path/to/microsurface]   (default target/release/microsurface)
"""
import json
import math
import random
import subprocess
import sys

import os

try:
    import mitsuba as mi
except ImportError:
    if os.environ.get("MITSUBA_REQUIRED"):
        print("mitsuba_compare: mitsuba is not installed, and MITSUBA_REQUIRED is set")
        sys.exit(1)
    print("mitsuba_compare: mitsuba is not installed (pip install mitsuba): skipped")
    sys.exit(0)

mi.set_variant("scalar_rgb")
BIN = sys.argv[1] if len(sys.argv) > 1 else "target/release/microsurface"
F32 = 1e-5
# Walter et al. 2007's Beckmann G1 approximation against the exact one: its worst relative
# error over a = cot θ/α, measured here (the bound the Beckmann comparison is held to).
def g1_exact(a):
    return 2.0 / (1.0 + math.erf(a) + math.exp(-a * a) / (a * math.sqrt(math.pi)))

def g1_walter(a):
    if a >= 1.6:
        return 1.0
    return (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a)

WALTER = max(abs(g1_walter(a) / g1_exact(a) - 1.0) for a in [k * 1e-4 for k in range(1, 200000)])

def direction(rng, below=False, max_deg=85.0):
    t = math.radians(max_deg) * math.sqrt(rng.random())
    p = 2.0 * math.pi * rng.random()
    z = math.cos(t)
    return [math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), -z if below else z]

def ours(lines):
    out = subprocess.run([BIN, "bsdf"], input="\n".join(json.dumps(l) for l in lines) + "\n",
                         capture_output=True, text=True, check=True).stdout.splitlines()
    return [json.loads(l) for l in out]

def mitsuba_bsdf(kind, ndf, ax, ay):
    if kind == "conductor":
        d = {"type": "roughconductor", "distribution": ndf, "alpha_u": ax, "alpha_v": ay,
             "eta": 0.42, "k": 2.38, "sample_visible": True}
    else:
        d = {"type": "roughdielectric", "distribution": ndf, "alpha": ax,
             "int_ior": 1.5, "ext_ior": 1.0, "sample_visible": True}
    return mi.load_dict(d)

def mitsuba_eval(b, wo, wi):
    si = mi.SurfaceInteraction3f()
    si.wi = mi.Vector3f(*wo)
    si.sh_frame = mi.Frame3f(mi.Vector3f(0, 0, 1))
    ctx = mi.BSDFContext()
    v = b.eval(ctx, si, mi.Vector3f(*wi))
    p = b.pdf(ctx, si, mi.Vector3f(*wi))
    return [float(v[0]), float(v[1]), float(v[2])], float(p)

def rel(a, b, scale):
    return abs(a - b) / max(abs(b), scale)

failures = 0
rng = random.Random(7)
print(f"mitsuba_compare: Mitsuba {mi.__version__}, scalar_rgb; Walter's Beckmann G1 "
      f"approximation: max relative error {WALTER:.2e}")
for kind, ndf, (ax, ay) in [
    ("conductor", "ggx", (0.3, 0.3)),
    ("conductor", "ggx", (0.5, 0.1)),
    ("conductor", "beckmann", (0.3, 0.3)),
    ("conductor", "beckmann", (0.2, 0.6)),
    ("dielectric", "ggx", (0.3, 0.3)),
    ("dielectric", "beckmann", (0.3, 0.3)),
]:
    b = mitsuba_bsdf(kind, ndf, ax, ay)
    pairs = []
    for k in range(400):
        wo = direction(rng)
        wi = direction(rng, below=(kind == "dielectric" and k % 2 == 1))
        pairs.append((wo, wi))
    req = []
    for wo, wi in pairs:
        line = {"bsdf": kind, "ndf": ndf, "alpha": [ax, ay] if kind == "conductor" else ax,
                "g2": "separable", "op": "eval", "wo": wo, "wi": wi}
        if kind == "conductor":
            line.update({"eta": [0.42] * 3, "k": [2.38] * 3})
        else:
            line["eta"] = 1.5
        req.append(line)
    got = ours(req)
    ms = [mitsuba_eval(b, wo, wi) for wo, wi in pairs]
    # The scale below which values are compared absolutely: 1e-4 of the largest.
    fscale = 1e-4 * max(max(m[0][1] for m in ms), 1e-30)
    pscale = 1e-4 * max(max(m[1] for m in ms), 1e-30)
    tol_f = F32 + (2 * WALTER if ndf == "beckmann" else 0.0)
    tol_p = F32 + (WALTER if ndf == "beckmann" else 0.0)
    worst_f = worst_p = 0.0
    for (wo, wi), g, (mf, mp) in zip(pairs, got, ms):
        if "error" in g:
            print(f"  ours: {g}")
            failures += 1
            continue
        cos_i = abs(wi[2])
        ef = rel(g["f"][1] * cos_i, mf[1], fscale)
        ep = rel(g["pdf"], mp, pscale)
        worst_f, worst_p = max(worst_f, ef), max(worst_p, ep)
        if ef > tol_f or ep > tol_p:
            failures += 1
            if failures < 10:
                print(f"  {kind} {ndf} α=({ax},{ay}) wo={wo} wi={wi}: f·cos {g['f'][1] * cos_i:.6e} "
                      f"vs {mf[1]:.6e}, pdf {g['pdf']:.6e} vs {mp:.6e}")
    print(f"  {kind:10} {ndf:8} α=({ax},{ay}): worst relative f·cos {worst_f:.2e} (bound "
          f"{tol_f:.1e}), pdf {worst_p:.2e} (bound {tol_p:.1e}), {len(pairs)} pairs")
if failures:
    print(f"mitsuba_compare: {failures} values outside the bounds")
    sys.exit(1)
print("mitsuba_compare: every value within its bound")
