# Type stubs for the compiled module (see the docstrings for formulas and accuracy).
from typing import Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from ._types import Albedo, BSDFSample, DielectricAlbedo, Lut, Sample, Table

ArrayLike = Union[float, int, npt.ArrayLike]
# float32 in → float32 out, otherwise float64; scalars in → a NumPy scalar out.
Result = Union[np.float64, np.float32, npt.NDArray[np.float64], npt.NDArray[np.float32]]
# An array of uniforms in [0, 1) (last axis 2, or 3 for a BSDF), or a Generator (with n >= 0).
Uniforms = Union[npt.ArrayLike, np.random.Generator]
# A parameter (alpha, alpha_y, gamma, a, eta, k): a number, or an array; the arrays of an
# object broadcast together (SciPy's frozen distributions) and with every method's
# arguments: one material per element. A conductor's eta and k: their last axis the channels.
Param = Union[float, npt.ArrayLike]
Channels = Union[float, Sequence[float], npt.ArrayLike]

# The input contract (the package's docstring): NaN values give NaN; cosines (u, u_o, u_i,
# mu) outside [-1, 1], uniforms outside [0, 1), an infinite phi, walks < 1, n < 0 and a seed
# outside [0, 2**64) raise ValueError naming the argument; parameters (alpha, shapes, eta,
# numbers or arrays) raise ValueError, NaN included; Ctrl-C raises KeyboardInterrupt.

# The package's version (Cargo's, in PEP 440's spelling: 1.0.0rc1).
__version__: str

class NDF:
    # Ordinary immutable Python objects: repr evaluates back (microsurface.GTR(0.3,
    # gamma=1.5)), == and hash by class and parameters, pickle/copy/deepcopy round-trip.
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[type, tuple]: ...
    # The same NDF with some parameters changed (alpha, alpha_y, gamma/a, exact, sampler).
    def replace(self, **changes: object) -> "NDF": ...
    @property
    def alpha(self) -> Param: ...
    @property
    def alpha_y(self) -> Param: ...
    @property
    def shape(self) -> Optional[Param]: ...
    # The parameter arrays' broadcast shape (() where every parameter is a number).
    @property
    def param_shape(self) -> Tuple[int, ...]: ...
    @property
    def name(self) -> str: ...
    # The path of the directions, samplers, BSDFs and albedos: the fast kernels (the default)
    # or, constructed with exact=True, the exact path. The functions of a cosine are exact.
    @property
    def exact(self) -> bool: ...
    # 'warp', 'posterior' (the Beckmann mixtures) or 'rejection' (the fast samplers of Double
    # GGX, the Exponential NDF and GTR at γ != 2); sampler='warp' needs exact=True.
    @property
    def sampler(self) -> str: ...
    # Functions of a cosine (isotropic): u, u_o, u_i in [-1, 1], slopes p, q any number; the
    # exact path, or with fast=True the renderer's (the class docstring gives both accuracies).
    def d(self, u: ArrayLike, fast: bool = False) -> Result: ...
    def lambda_(self, u: ArrayLike, fast: bool = False) -> Result: ...
    def sigma(self, u: ArrayLike, fast: bool = False) -> Result: ...
    def g1(self, u: ArrayLike, fast: bool = False) -> Result: ...
    def g2(self, u_o: ArrayLike, u_i: ArrayLike, fast: bool = False) -> Result: ...
    def g2_separable(self, u_o: ArrayLike, u_i: ArrayLike, fast: bool = False) -> Result: ...
    def p22(self, p: ArrayLike, q: ArrayLike) -> Result: ...
    def p2(self, p: ArrayLike) -> Result: ...
    # Functions of directions (last axis 3; anisotropic).
    def d_wm(self, wm: npt.ArrayLike) -> Result: ...
    def lambda_w(self, w: npt.ArrayLike) -> Result: ...
    def g1_w(self, w: npt.ArrayLike) -> Result: ...
    def sigma_w(self, w: npt.ArrayLike) -> Result: ...
    def g2_w(self, wo: npt.ArrayLike, wi: npt.ArrayLike, separable: bool = False) -> Result: ...
    def pdf_visible(self, w: npt.ArrayLike, wm: npt.ArrayLike) -> Result: ...
    def sample_visible(self, w: npt.ArrayLike, u: Uniforms, n: Optional[Union[int, Tuple[int, ...]]] = None) -> Sample: ...
    def pdf_dcos(self, wm: npt.ArrayLike) -> Result: ...
    def sample_dcos(self, u: Uniforms, n: Optional[Union[int, Tuple[int, ...]]] = None) -> Sample: ...
    # Multiple scattering (the random walk): mu in [-1, 1], phi finite, walks >= 1.
    def albedo(
        self,
        mu: ArrayLike,
        phi: Optional[ArrayLike] = None,
        walks: int = 100000,
        seed: int = 0,
        eta: Optional[float] = None,
        orders: int = 4,
        progress: bool = False,
    ) -> Albedo: ...

class Beckmann(NDF):
    def __init__(
        self, alpha: Param, alpha_y: Optional[Param] = None, exact: bool = False, sampler: str = "posterior"
    ) -> None: ...

class GGX(NDF):
    def __init__(
        self, alpha: Param, alpha_y: Optional[Param] = None, exact: bool = False, sampler: str = "posterior"
    ) -> None: ...

class DoubleGGX(NDF):
    def __init__(
        self, alpha: Param, alpha_y: Optional[Param] = None, exact: bool = False, sampler: str = "posterior"
    ) -> None: ...

class Exponential(NDF):
    def __init__(
        self, alpha: Param, alpha_y: Optional[Param] = None, exact: bool = False, sampler: str = "posterior"
    ) -> None: ...

class Ei(NDF):
    def __init__(
        self, alpha: Param, alpha_y: Optional[Param] = None, exact: bool = False, sampler: str = "posterior"
    ) -> None: ...

class Erfc(NDF):
    def __init__(
        self, alpha: Param, alpha_y: Optional[Param] = None, exact: bool = False, sampler: str = "posterior"
    ) -> None: ...

class K0(NDF):
    def __init__(
        self, alpha: Param, alpha_y: Optional[Param] = None, exact: bool = False, sampler: str = "posterior"
    ) -> None: ...

class GTR(NDF):
    def __init__(
        self,
        alpha: Param,
        gamma: Param,
        alpha_y: Optional[Param] = None,
        exact: bool = False,
        sampler: str = "posterior",
    ) -> None: ...

class StudentT(NDF):
    def __init__(
        self,
        alpha: Param,
        gamma: Param,
        alpha_y: Optional[Param] = None,
        exact: bool = False,
        sampler: str = "posterior",
    ) -> None: ...

class BesselK(NDF):
    def __init__(
        self,
        alpha: Param,
        a: Param,
        alpha_y: Optional[Param] = None,
        exact: bool = False,
        sampler: str = "posterior",
    ) -> None: ...

class GenExponential(NDF):
    def __init__(
        self,
        alpha: Param,
        gamma: Param,
        alpha_y: Optional[Param] = None,
        exact: bool = False,
        sampler: str = "posterior",
    ) -> None: ...

class BSDF:
    # Ordinary immutable Python objects, as NDF: repr evaluates back, ==, hash, pickle.
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[type, tuple]: ...
    @property
    def channels(self) -> int: ...
    def eval(self, wo: npt.ArrayLike, wi: npt.ArrayLike) -> Result: ...
    def pdf(self, wo: npt.ArrayLike, wi: npt.ArrayLike) -> Result: ...
    def sample(self, wo: npt.ArrayLike, u: Uniforms, n: Optional[Union[int, Tuple[int, ...]]] = None) -> BSDFSample: ...

class Conductor(BSDF):
    def __init__(
        self,
        ndf: NDF,
        eta: Optional[Channels] = None,
        k: Optional[Channels] = None,
        masking: str = "correlated",
        scattering: str = "single",
    ) -> None: ...

class Dielectric(BSDF):
    def __init__(
        self,
        ndf: NDF,
        eta: Param,
        masking: str = "correlated",
        transport: str = "radiance",
        scattering: str = "single",
    ) -> None: ...

class AlbedoTable:
    # Pickle, copy, ==, hash by node values and material; repr says what it is of.
    def __init__(self, ndf: NDF, progress: bool = False) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    # The nodes (uniform in sqrt(mu)) and E there.
    @property
    def mu(self) -> npt.NDArray[np.float64]: ...
    @property
    def values(self) -> npt.NDArray[np.float64]: ...
    # .npy ((n, 2): mu, E) or .mfa (the command line's binary form).
    def save(self, path: str) -> None: ...
    @staticmethod
    def load(path: str, alpha_index: int = 0) -> "AlbedoTable": ...
    def e(self, mu: ArrayLike) -> Result: ...
    @property
    def e_avg(self) -> float: ...
    @property
    def lost_avg(self) -> float: ...

# Matched roughness: ndf a class, a name ("student_t:4") or an instance; by "g1_45",
# "sigma0", "mean_slope" or "dcos_median". Returns an instance of the NDF's class.
def matched_alpha(ndf: Union[type, str, NDF], reference: NDF, by: str = "g1_45") -> NDF: ...

# Without eta: the F = 1 conductor's E1 (an array); with eta: DielectricAlbedo(reflect,
# transmit) of the rough dielectric, masking "pbrt" (1/(1 + Λo + Λi)) or "exact" (B(1 + Λo, 1 + Λi)).
def single_scattering_albedo(
    ndf: NDF,
    mu: ArrayLike,
    phi: Optional[ArrayLike] = None,
    eta: Optional[ArrayLike] = None,
    masking: str = "pbrt",
    progress: bool = False,
) -> Union[Result, DielectricAlbedo]: ...

# The command line's `microsurface table`: the albedo over (alpha, mu) by the walk or quadrature.
def table(
    ndf: Union[type, str, NDF],
    alpha: Sequence[float],
    mu: Sequence[float],
    material: str = "furnace",
    eta: Optional[float] = None,
    k: Optional[float] = None,
    rho: Optional[float] = None,
    method: str = "walk",
    walks: int = 100000,
    seed: int = 0,
    out: Optional[str] = None,
    progress: bool = False,
) -> Table: ...
def read_table(path: str) -> Table: ...

# The command line's `microsurface lut`: the tables real-time engines load.
def lut(
    ndf: Union[type, str, NDF],
    kind: str,
    size: int = 32,
    eta_size: int = 16,
    aspect_size: int = 0,
    mu_axis: str = "mu",
    roughness_axis: str = "sqrt_alpha",
    alpha_max: float = 1.0,
    nodes: str = "centres",
    level: int = 4,
    progress: bool = False,
) -> Lut: ...
