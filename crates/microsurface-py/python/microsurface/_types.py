"""The named tuples the samplers and albedos return."""

from typing import NamedTuple

import numpy as np


class Sample(NamedTuple):
    """Sampled microfacet normals ``wm`` (..., 3) and their densities ``pdf`` (...)."""

    wm: np.ndarray
    pdf: np.ndarray


class BSDFSample(NamedTuple):
    """Sampled directions of a BSDF: ``wi`` (..., 3), ``f`` (..., or ..., channels), ``pdf``,
    ``lobe`` (int8: 0 rejected, 1 reflection, 2 transmission), ``specular`` (bool: a delta
    lobe's weights) and ``eta`` (the relative index along the path; 1 for a reflection)."""

    wi: np.ndarray
    f: np.ndarray
    pdf: np.ndarray
    lobe: np.ndarray
    specular: np.ndarray
    eta: np.ndarray


class Albedo(NamedTuple):
    """The albedo by scattering order (the last axis of ``reflect`` and ``transmit``: orders
    1, 2, …, K − 1 and ≥ K for ``albedo(..., orders=K)``, default 4) with standard errors,
    and the total over sides and orders."""

    reflect: np.ndarray
    reflect_stderr: np.ndarray
    transmit: np.ndarray
    transmit_stderr: np.ndarray
    total: np.ndarray
    total_stderr: np.ndarray


class DielectricAlbedo(NamedTuple):
    """The single-scattering albedo of a rough dielectric: the energy ``reflect``ed back to
    the side of incidence and ``transmit``ted through, each of the arguments' shape."""

    reflect: np.ndarray
    transmit: np.ndarray


class Table(NamedTuple):
    """An albedo table over (α, μ) (``microsurface.table``, ``read_table``; the command line's
    ``microsurface table``): the nodes ``alpha`` and ``mu``, the ``quantities``' names
    (``e1``; or ``r1``…``r4``, ``r``, ``t1``…``t4``, ``t``, ``e`` and their ``_se`` standard
    errors for the walk) and ``values`` (float32, (len(alpha), len(mu), len(quantities)))."""

    alpha: np.ndarray
    mu: np.ndarray
    quantities: tuple
    values: np.ndarray


class Lut(NamedTuple):
    """A table real-time engines load (``microsurface.lut``; the command line's
    ``microsurface lut``): the ``axes``' names (outermost first: side, eta, aspect,
    sqrt_alpha or alpha, mu or sqrt_mu, those the kind has), each axis' node ``coords``
    (texture coordinates in [0, 1]) and ``params`` (μ, α, η, αy/αx; the side's ±1), the
    ``channels``' names and ``values`` (float64, the node counts then the channels)."""

    axes: tuple
    coords: tuple
    params: tuple
    channels: tuple
    values: np.ndarray
