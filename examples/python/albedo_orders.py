"""The albedo of a rough mirror (F = 1) by scattering order, from the microsurface random walk
(Heitz et al. 2016): E₁, E₂, E₃ and E≥4 against cos θo for GGX and Beckmann at three
roughnesses, with the single-scattering albedo by quadrature over E₁ (they agree within the
walk's error; the rest, 1 − E₁, is the energy single-scattering models lose).

Run: pip install ./crates/microsurface-py matplotlib && python examples/python/albedo_orders.py
Writes albedo_orders.png (or the path given as the first argument).
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import microsurface  # noqa: E402

WALKS = 20_000
ALPHAS = [0.2, 0.6, 1.0]


def main(out):
    mu = np.linspace(0.05, 1.0, 20)
    fig, axes = plt.subplots(2, len(ALPHAS), figsize=(13, 7), squeeze=False)
    for row, cls in zip(axes, [microsurface.GGX, microsurface.Beckmann]):
        for ax, alpha in zip(row, ALPHAS):
            n = cls(alpha)
            a = n.albedo(mu, walks=WALKS)  # every μ at once, on every core
            e1 = microsurface.single_scattering_albedo(n, mu)
            for k, label in enumerate(["order 1", "order 2", "order 3", "orders ≥ 4"]):
                ax.errorbar(mu, a.reflect[:, k], yerr=a.reflect_stderr[:, k], fmt=".", label=label)
            ax.plot(mu, e1, "k-", lw=1, label="E₁ (quadrature)")
            ax.plot(mu, a.total, "k:", lw=1, label="total")
            ax.set(title=f"{n.name}, α = {alpha}", xlabel="cos θo", ylim=(0, 1.05))
    axes[0][0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "albedo_orders.png")
