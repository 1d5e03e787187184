"""D(θ), Λ(θ) and G1(θ) of every NDF at matched roughness, as the NDF pages plot them.

Run: pip install ./crates/microsurface-py matplotlib && python examples/python/ndf_curves.py
Writes ndf_curves.png (or the path given as the first argument).
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import microsurface  # noqa: E402

ALPHA = 0.3
NDFS = [
    microsurface.Beckmann(ALPHA),
    microsurface.GGX(ALPHA),
    microsurface.GTR(ALPHA, 1.5),
    microsurface.DoubleGGX(ALPHA),
    microsurface.Exponential(ALPHA),
    microsurface.StudentT(ALPHA, 4.0),
    microsurface.Ei(ALPHA),
    microsurface.Erfc(ALPHA),
    microsurface.K0(ALPHA),
    microsurface.BesselK(ALPHA, 2.5),
    microsurface.GenExponential(ALPHA, 4.0),
]


def label(n):
    return n.name if n.shape is None else f"{n.name} ({n.shape:g})"


def main(out):
    theta = np.linspace(0.0, np.pi / 2, 400)[1:-1]
    u = np.cos(theta)
    deg = np.degrees(theta)
    fig, (ax_d, ax_l, ax_g) = plt.subplots(1, 3, figsize=(17, 4.5))
    for ax in (ax_d, ax_l, ax_g):
        ax.set_prop_cycle(color=plt.cm.tab20(np.linspace(0.0, 1.0, 20))[: len(NDFS)])
    for n in NDFS:
        # Every quantity takes the whole array at once: no loop in Python.
        ax_d.semilogy(deg, n.d(u), label=label(n))
        ax_l.semilogy(deg, n.lambda_(u), label=label(n))
        ax_g.plot(deg, n.g1(u), label=label(n))
    ax_d.set(xlabel="θm (degrees)", ylabel="D(cos θm)", title=f"D, α = {ALPHA}")
    ax_d.set_ylim(1e-6, 1e3)
    ax_l.set(xlabel="θ (degrees)", ylabel="Λ(cos θ)", title="Smith Λ")
    ax_l.set_ylim(1e-8, 1e2)
    ax_g.set(xlabel="θ (degrees)", ylabel="G1(cos θ)", title="Smith G1 = 1/(1 + Λ)")
    ax_g.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "ndf_curves.png")
