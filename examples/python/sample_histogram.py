"""Visible normals sampled by the library against their density: the histogram of θm of
2·10⁵ samples from ``sample_visible`` over the marginal pdf ∫ D_wi(θm, φ) dφ (integrated here
from ``pdf_visible``), for GGX and Student-T at three incidence angles, as the sampling pages
show them.

Run: pip install ./crates/microsurface-py matplotlib && python examples/python/sample_histogram.py
Writes sample_histogram.png (or the path given as the first argument).
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import microsurface  # noqa: E402

SAMPLES = 200_000
NDFS = [microsurface.GGX(0.4), microsurface.StudentT(0.4, 2.0 + 1.0)]
ANGLES = [0.0, 45.0, 80.0]


def marginal(n, wi, theta):
    """p(θm) = ∫ D_wi(m) sin θm dφ over φ by the trapezoidal rule (periodic: spectrally accurate)."""
    phi = np.linspace(0.0, 2 * np.pi, 256, endpoint=False)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    m = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], axis=-1)
    return n.pdf_visible(wi, m).mean(axis=1) * 2 * np.pi * np.sin(theta)


def main(out):
    rng = np.random.default_rng(1)
    fig, axes = plt.subplots(len(NDFS), len(ANGLES), figsize=(13, 7), squeeze=False)
    for row, n in zip(axes, NDFS):
        for ax, deg in zip(row, ANGLES):
            t = np.radians(deg)
            wi = np.array([np.sin(t), 0.0, np.cos(t)])
            s = n.sample_visible(wi, rng, n=SAMPLES)  # (n, 3) normals and their pdfs
            theta_m = np.arccos(np.clip(s.wm[:, 2], -1, 1))
            ax.hist(np.degrees(theta_m), bins=90, range=(0, 90), density=True, alpha=0.5, label="samples")
            grid = np.linspace(1e-4, np.pi / 2 - 1e-4, 400)
            ax.plot(np.degrees(grid), marginal(n, wi, grid) * np.pi / 180, "k", lw=1, label="pdf")
            name = n.name if n.shape is None else f"{n.name} γ = {n.shape:g}"
            ax.set(title=f"{name}, α = {n.alpha}, θi = {deg:g}°", xlabel="θm (degrees)")
            ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "sample_histogram.png")
