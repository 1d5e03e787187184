//! The lookup tables real-time engines load: the directional albedo of a rough conductor
//! and its average, the split-sum terms of image-based lighting, and a rough dielectric's
//! reflected and transmitted albedo from both sides, for every NDF, on the grids and
//! parametrisations engines sample (values only: the CLI's `lut` command writes them as
//! `.npy`, PNG, OpenEXR, KTX2 and source arrays).
//!
//! # Quantities ([`LutKind`])
//!
//! Every table is single scattering with the height-correlated G2 = 1/(1 + Λo + Λi) (the
//! library's BSDFs' default, pbrt-v4's), wo = (sin θo cos φ, sin θo sin φ, μ), integrated over
//! the microfacet normal m (the rule of
//! [`single_scattering_albedo_dielectric`](super::single_scattering_albedo_dielectric), level
//! [`LutSpec::level`]; c = wo·m, wr the reflection of wo about m):
//!
//! * [`LutKind::Albedo`]: E(μ) = (1/μ)∫ D(m) c G2(wo, wr) dm, the F = 1 conductor
//!   ([`single_scattering_albedo`](super::single_scattering_albedo)): Kulla & Conty 2017's
//!   E(μ), Turquin 2019's E.
//! * [`LutKind::AlbedoAvg`]: E_avg = 2∫₀¹ E(μ) μ dμ (Kulla & Conty's average), by 32-point
//!   Gauss–Legendre in √μ (4 panels of 8).
//! * [`LutKind::Dfg`]: the split sum of Karis 2013 ("Real Shading in Unreal Engine 4", eq. 3
//!   onwards) with Hoffman's F82-tint term: the same integral weighted by
//!   A: 1 − (1 − c)⁵, B: (1 − c)⁵ and C: c(1 − c)⁶, so that for Schlick's
//!   F = F0 + (1 − F0)(1 − c)⁵ the albedo is F0·A + B, and for F82-tint
//!   ([`crate::bsdf::fresnel::f82_tint`]: F = Schlick − a c(1 − c)⁶) it is F0·A + B − a·C
//!   (the model before its clamp to [0, 1], as OpenPBR's split sum takes it). A + B = E.
//! * [`LutKind::Dielectric`]: a rough dielectric interface's R(μ) and T(μ), the shares of
//!   the energy from wo that single scattering reflects and transmits
//!   ([`single_scattering_albedo_dielectric`](super::single_scattering_albedo_dielectric):
//!   exact Fresnel, importance transport; 1 − R − T is what multiple scattering would add),
//!   from outside (relative index η, the `side` axis' node 0) and from inside (1/η, node 1),
//!   the two tables of two-sided Kulla–Conty compensation. Cycles keeps the inside as a
//!   separate table; here it is the outer axis of one.
//! * [`LutKind::DielectricAvg`]: 2∫ R μ dμ and 2∫ T μ dμ, as for `AlbedoAvg`.
//!
//! # Axes: texel centres or edges
//!
//! [`Nodes::Centres`] (the default) puts an axis' n nodes at the texture coordinates
//! xᵢ = (i + ½)/n, the centres of a texture's n texels: a shader samples the table with the
//! hardware's linear filter at the coordinate of its parameter and clamp-to-edge addressing,
//! which is [`Lut::lookup`] exactly (Filament's and Unreal's DFG tables are laid out so); no
//! node sits at μ = 0 or α = 0, and the half texels at both ends are clamped.
//! [`Nodes::Edges`] puts them at xᵢ = i/(n − 1), both ends included (Cycles'
//! `lookup_table_read`: t = x(n − 1)); a texture sampler reaches them at
//! (x(n − 1) + ½)/n. Its end nodes are limits: α = 0 is taken at [`crate::ALPHA_MIN`] and
//! μ = 0 at [`MU_MIN`] (the grazing limit), η = 1 is the index-matched interface; the aspect
//! axis keeps texel centres (αy/αx = 0 is no material). The coordinate of each parameter:
//!
//! | axis | coordinate x ∈ [0, 1] | parameter |
//! |---|---|---|
//! | `mu` ([`MuAxis::Cos`]) | μ | μ = x |
//! | `sqrt_mu` ([`MuAxis::SqrtCos`]) | √μ (denser at grazing angles, where E changes fastest) | μ = x² |
//! | `sqrt_alpha` ([`RoughnessAxis::SqrtAlpha`]) | √(α/α_max), or (αx αy)^¼/√α_max: perceptual roughness | α = α_max x² |
//! | `alpha` ([`RoughnessAxis::Alpha`]) | α/α_max | α = α_max x |
//! | `aspect` (anisotropic tables) | αy/αx | αx = α/√x, αy = α√x (α = √(αx αy)) |
//! | `eta` | √((η − 1)/2), as Cycles maps η | η = 1 + 2x², η ∈ [1, 3] |
//! | `side` | the node index: 0 outside (η), 1 inside (1/η) | not interpolated |
//!
//! Anisotropic tables (`aspect_size` > 0) hold the average over the azimuth of wo
//! (trapezoidal rule on 32 intervals of [0, π], which converges geometrically: E is even and
//! π-periodic in φ; 8 intervals were 2e-4 off at αy/αx = ¼, grazing), which is what an
//! isotropic compensation lobe needs.
//!
//! # Layout and accuracy
//!
//! [`Lut::values`] is row-major over [`Lut::axes`] (outermost first: side, eta, aspect,
//! roughness, mu, the ones the kind has), then the channels. [`Lut::error`] measures what a
//! shader would see: [`Lut::lookup`] against the quadrature one level finer at the midpoints
//! between the nodes, and halfway into the clamped border on both ends of each axis (the
//! error of the filter dominates: 4e-2 for GGX's 16 × 16 albedo at grazing μ, where E
//! changes fastest; a `sqrt_mu` axis or more nodes bring it down). The nodes themselves, at
//! the default level 4, are within 1e-8 of an independent adaptive rule over wi asked for
//! 1e-9 (tests/lut.rs: GGX and Beckmann 6e-15, Double GGX 1.2e-9; the split sum against the
//! Schlick and F82-tint conductors' own `eval` 2e-15), the averages within 1e-6 of the
//! compensation tables', the anisotropic average within 1e-9 of a 64-point one; the
//! dielectric's within 1.7e-5 (the accuracy of
//! [`single_scattering_albedo_dielectric`](super::single_scattering_albedo_dielectric)).

use std::fmt;
use std::str::FromStr;
use std::sync::atomic::{AtomicUsize, Ordering};

use crate::bsdf::Masking;
use crate::scattering::albedo::over_normals_weighted;
use crate::scattering::progress::Progress;
use crate::{AnyMicrofacet, NdfSpec, ParamError};

/// What a table holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LutKind {
    /// E(μ, α) of the F = 1 conductor; channel `E`.
    Albedo,
    /// E_avg(α); channel `E_avg`.
    AlbedoAvg,
    /// The split-sum terms over (μ, α); channels `A`, `B`, `C`.
    Dfg,
    /// A dielectric's R and T over (side, η, α, μ); channels `R`, `T`.
    Dielectric,
    /// Their averages over (side, η, α); channels `R_avg`, `T_avg`.
    DielectricAvg,
}

impl LutKind {
    /// Every kind.
    pub const ALL: [LutKind; 5] = [
        LutKind::Albedo,
        LutKind::AlbedoAvg,
        LutKind::Dfg,
        LutKind::Dielectric,
        LutKind::DielectricAvg,
    ];

    /// The name the CLI takes (`albedo`, `albedo-avg`, `dfg`, `dielectric`,
    /// `dielectric-avg`).
    pub fn name(self) -> &'static str {
        match self {
            LutKind::Albedo => "albedo",
            LutKind::AlbedoAvg => "albedo-avg",
            LutKind::Dfg => "dfg",
            LutKind::Dielectric => "dielectric",
            LutKind::DielectricAvg => "dielectric-avg",
        }
    }

    /// The channels' names, in storage order.
    pub fn channels(self) -> &'static [&'static str] {
        match self {
            LutKind::Albedo => &["E"],
            LutKind::AlbedoAvg => &["E_avg"],
            LutKind::Dfg => &["A", "B", "C"],
            LutKind::Dielectric => &["R", "T"],
            LutKind::DielectricAvg => &["R_avg", "T_avg"],
        }
    }

    fn dielectric(self) -> bool {
        matches!(self, LutKind::Dielectric | LutKind::DielectricAvg)
    }

    fn average(self) -> bool {
        matches!(self, LutKind::AlbedoAvg | LutKind::DielectricAvg)
    }
}

impl FromStr for LutKind {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        LutKind::ALL
            .into_iter()
            .find(|k| k.name().eq_ignore_ascii_case(s))
            .ok_or_else(|| {
                let names: Vec<_> = LutKind::ALL.iter().map(|k| k.name()).collect();
                format!("unknown table kind '{s}' (one of {})", names.join(", "))
            })
    }
}

/// The coordinate of the μ axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MuAxis {
    /// x = μ (`mu`).
    Cos,
    /// x = √μ (`sqrt_mu`).
    SqrtCos,
}

/// The coordinate of the roughness axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RoughnessAxis {
    /// x = √(α/α_max) (`sqrt_alpha`), the perceptual roughness of engines.
    SqrtAlpha,
    /// x = α/α_max (`alpha`).
    Alpha,
}

impl FromStr for MuAxis {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "mu" => Ok(MuAxis::Cos),
            "sqrt_mu" => Ok(MuAxis::SqrtCos),
            _ => Err(format!("unknown mu axis '{s}' (mu or sqrt_mu)")),
        }
    }
}

impl FromStr for RoughnessAxis {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "sqrt_alpha" => Ok(RoughnessAxis::SqrtAlpha),
            "alpha" => Ok(RoughnessAxis::Alpha),
            _ => Err(format!(
                "unknown roughness axis '{s}' (sqrt_alpha or alpha)"
            )),
        }
    }
}

/// What to tabulate and on which grid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LutSpec {
    /// The NDF (and its shape parameter).
    pub ndf: NdfSpec,
    pub kind: LutKind,
    /// Nodes along μ and along the roughness, [`MIN_NODES`] to [`MAX_NODES`] (engines use
    /// 16 to 128).
    pub size: usize,
    /// Nodes along η (dielectric kinds; Cycles uses 16).
    pub eta_size: usize,
    /// Nodes along the aspect αy/αx; 0 for an isotropic table.
    pub aspect_size: usize,
    pub mu_axis: MuAxis,
    pub roughness_axis: RoughnessAxis,
    /// α at roughness coordinate 1 (1: the roughness engines expose).
    pub alpha_max: f64,
    /// The level of the tanh-sinh rule (step 2^−level), 2 to 7.
    pub level: u32,
    /// Where the nodes of μ, the roughness and η sit.
    pub nodes: Nodes,
}

/// Where an axis' nodes sit: see the [module docs](self).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Nodes {
    /// xᵢ = (i + ½)/n (`centres`): a texture's texel centres.
    Centres,
    /// xᵢ = i/(n − 1) (`edges`): both ends are nodes.
    Edges,
}

impl FromStr for Nodes {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "centres" | "centers" => Ok(Nodes::Centres),
            "edges" => Ok(Nodes::Edges),
            _ => Err(format!("unknown node layout '{s}' (centres or edges)")),
        }
    }
}

/// The smallest μ a table computes: μ = 0 (an edge node, or [`Lut::exact`] there) is the
/// grazing limit, taken here (the integrals at wo on the horizon are 0, not their limit).
pub const MU_MIN: f64 = 1e-6;

/// Fewest nodes along an axis (a linear filter needs two).
pub const MIN_NODES: usize = 2;
/// Most nodes along an axis (4096: far past any engine's table, and a bound on the work).
pub const MAX_NODES: usize = 4096;

impl LutSpec {
    /// The defaults for `kind` of `ndf`: 32 nodes along μ (coordinate μ) and √α (α_max = 1),
    /// 16 along η, isotropic, at texel centres, level 4.
    pub fn new(ndf: NdfSpec, kind: LutKind) -> LutSpec {
        LutSpec {
            ndf,
            kind,
            size: 32,
            eta_size: 16,
            aspect_size: 0,
            mu_axis: MuAxis::Cos,
            roughness_axis: RoughnessAxis::SqrtAlpha,
            alpha_max: 1.0,
            level: 4,
            nodes: Nodes::Centres,
        }
    }

    fn validate(&self) -> Result<(), LutError> {
        let nodes = |name: &'static str, n: usize| {
            if (MIN_NODES..=MAX_NODES).contains(&n) {
                Ok(())
            } else {
                Err(LutError::Nodes { axis: name, n })
            }
        };
        nodes("size", self.size)?;
        if self.kind.dielectric() {
            nodes("eta", self.eta_size)?;
        }
        if self.aspect_size != 0 {
            nodes("aspect", self.aspect_size)?;
        }
        if !(2..=7).contains(&self.level) {
            return Err(LutError::Level(self.level));
        }
        if !(crate::ALPHA_MIN..=crate::ALPHA_MAX).contains(&self.alpha_max) {
            return Err(ParamError::Alpha(self.alpha_max).into());
        }
        // The extreme nodes' materials are built here: a bad shape, or GTR's anisotropy,
        // fails before the work starts.
        for r in [0.0, 1.0] {
            let alpha = self.alpha_at(r);
            for s in self.aspects() {
                let (ax, ay) = stretch(alpha, s);
                AnyMicrofacet::<f64>::new(self.ndf.kind, ax, ay, self.ndf.shape)?;
            }
        }
        Ok(())
    }

    fn alpha_at(&self, x: f64) -> f64 {
        match self.roughness_axis {
            RoughnessAxis::SqrtAlpha => self.alpha_max * x * x,
            RoughnessAxis::Alpha => self.alpha_max * x,
        }
    }

    fn mu_at(&self, x: f64) -> f64 {
        match self.mu_axis {
            MuAxis::Cos => x,
            MuAxis::SqrtCos => x * x,
        }
    }

    fn aspects(&self) -> Vec<f64> {
        if self.aspect_size == 0 {
            vec![1.0]
        } else {
            centres(self.aspect_size)
        }
    }
}

/// (αx, αy) of roughness α = √(αx αy) and aspect s = αy/αx, each taken into the accepted
/// range (α = 0 at roughness 0 is the smooth limit, taken at α = 1e-6; αy = 0 at aspect 0,
/// and αx = ∞, at the range's ends).
fn stretch(alpha: f64, s: f64) -> (f64, f64) {
    let r = s.sqrt();
    let clamp = |a: f64| a.clamp(crate::ALPHA_MIN, crate::ALPHA_MAX);
    (clamp(alpha / r), clamp(alpha * r))
}

/// η at coordinate x (Cycles' map).
fn eta_at(x: f64) -> f64 {
    1.0 + 2.0 * x * x
}

/// The texel centres (i + ½)/n.
fn centres(n: usize) -> Vec<f64> {
    coords(n, Nodes::Centres)
}

/// The nodes' coordinates of an axis of n ≥ 2 nodes.
fn coords(n: usize, nodes: Nodes) -> Vec<f64> {
    match nodes {
        Nodes::Centres => (0..n).map(|i| (i as f64 + 0.5) / n as f64).collect(),
        Nodes::Edges => (0..n).map(|i| i as f64 / (n - 1) as f64).collect(),
    }
}

/// Why a table cannot be made.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LutError {
    /// An axis' node count outside [`MIN_NODES`, `MAX_NODES`].
    Nodes { axis: &'static str, n: usize },
    /// A quadrature level outside 2 to 7.
    Level(u32),
    /// A node's material was rejected (α_max, the shape, GTR's anisotropy).
    Param(ParamError),
    /// Stopped by the progress' [`crate::scattering::Cancel`] token.
    Cancelled,
}

impl fmt::Display for LutError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            LutError::Nodes { axis, n } => write!(
                f,
                "{axis} must be {MIN_NODES} to {MAX_NODES} nodes, got {n}"
            ),
            LutError::Level(l) => write!(f, "the quadrature level must be 2 to 7, got {l}"),
            LutError::Param(e) => write!(f, "{e}"),
            LutError::Cancelled => f.write_str("cancelled"),
        }
    }
}

impl std::error::Error for LutError {}

impl From<ParamError> for LutError {
    fn from(e: ParamError) -> Self {
        LutError::Param(e)
    }
}

/// One axis of a table.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    /// `side`, `eta`, `aspect`, `sqrt_alpha`/`alpha`, `mu`/`sqrt_mu` (the coordinate's name).
    pub name: &'static str,
    /// The parameter at coordinate x, as a formula (`alpha = 1 * x^2`).
    pub map: String,
    /// The coordinates of the nodes (the side's are 0 and 1).
    pub coords: Vec<f64>,
    /// Where they sit (the side's: `Edges`).
    pub nodes: Nodes,
    /// The parameter at each node (μ, α, αy/αx, η; the side's ±1: wo.z's sign).
    pub params: Vec<f64>,
    /// Whether [`Lut::lookup`] interpolates along it (all but `side`).
    pub interpolated: bool,
}

/// The error of a table as a shader sees it ([`Lut::error`]) over a set of points.
#[derive(Clone, Debug, PartialEq)]
pub struct ErrorStat {
    /// Largest |lookup − quadrature| over the points and channels.
    pub max_abs: f64,
    /// Its place: the coordinates, then the channel.
    pub at: (Vec<f64>, usize),
    /// Root mean square over the points and channels.
    pub rms: f64,
    /// How many points were measured.
    pub points: usize,
}

/// [`Lut::error`]: inside the texel centres, and in the clamped border.
#[derive(Clone, Debug, PartialEq)]
pub struct LutAccuracy {
    /// At the midpoints between nodes (every coordinate between the first and last texel
    /// centres): the linear filter's error.
    pub interior: ErrorStat,
    /// Where some coordinate is halfway into the border (between 0 and the first centre,
    /// or the last and 1), which clamp-to-edge addressing answers with the edge texel.
    pub border: ErrorStat,
}

/// A computed table: see the [module docs](self).
#[derive(Clone, Debug, PartialEq)]
pub struct Lut {
    pub spec: LutSpec,
    /// Outermost first.
    pub axes: Vec<Axis>,
    pub channels: &'static [&'static str],
    /// Row-major over the axes, then the channels.
    pub values: Vec<f64>,
}

/// The parameter point of a node or any coordinate.
#[derive(Clone, Copy)]
struct Point {
    inside: bool,
    eta: f64,
    aspect: f64,
    alpha: f64,
    mu: f64,
}

impl Lut {
    /// Computes the table of `spec` (every core with the `rayon` feature; the values do not
    /// depend on the thread count), reporting `(done, total)` to `progress` after each node
    /// (from any thread) and asking it before each whether to stop
    /// ([`crate::scattering::Progress`]; [`LutError::Cancelled`] then).
    pub fn compute(spec: &LutSpec, progress: &dyn Progress) -> Result<Lut, LutError> {
        spec.validate()?;
        let axes = Lut::axes_of(spec);
        let dims: Vec<usize> = axes.iter().map(|a| a.coords.len()).collect();
        let total: usize = dims.iter().product();
        let done = AtomicUsize::new(0);
        let node = |i: usize| -> Result<Vec<f64>, LutError> {
            if progress.cancelled() {
                return Err(LutError::Cancelled);
            }
            let coords = unravel(i, &dims)
                .iter()
                .zip(&axes)
                .map(|(&j, a)| a.coords[j])
                .collect::<Vec<_>>();
            let v = quantity(spec, &axes, &coords, spec.level);
            progress.report(done.fetch_add(1, Ordering::Relaxed) + 1, total);
            Ok(v)
        };
        #[cfg(feature = "rayon")]
        let rows: Vec<Vec<f64>> = {
            use rayon::prelude::*;
            (0..total)
                .into_par_iter()
                .map(node)
                .collect::<Result<_, _>>()?
        };
        #[cfg(not(feature = "rayon"))]
        let rows: Vec<Vec<f64>> = (0..total).map(node).collect::<Result<_, _>>()?;
        Ok(Lut {
            spec: *spec,
            axes,
            channels: spec.kind.channels(),
            values: rows.concat(),
        })
    }

    fn axes_of(spec: &LutSpec) -> Vec<Axis> {
        let mut axes = Vec::new();
        let axis = |name, map: String, nodes: Nodes, n: usize, f: &dyn Fn(f64) -> f64| {
            let coords = coords(n, nodes);
            Axis {
                name,
                map,
                params: coords.iter().map(|&x| f(x)).collect(),
                coords,
                nodes,
                interpolated: true,
            }
        };
        let nodes = spec.nodes;
        if spec.kind.dielectric() {
            axes.push(Axis {
                name: "side",
                map: "0: wo outside (eta), 1: wo inside (1/eta)".into(),
                coords: vec![0.0, 1.0],
                params: vec![1.0, -1.0],
                nodes: Nodes::Edges,
                interpolated: false,
            });
            axes.push(axis(
                "eta",
                "eta = 1 + 2 x^2".into(),
                nodes,
                spec.eta_size,
                &eta_at,
            ));
        }
        if spec.aspect_size > 0 {
            axes.push(axis(
                "aspect",
                "alpha_y/alpha_x = x".into(),
                Nodes::Centres,
                spec.aspect_size,
                &|x| x,
            ));
        }
        let a = spec.alpha_max;
        let (name, map) = match spec.roughness_axis {
            RoughnessAxis::SqrtAlpha => ("sqrt_alpha", format!("alpha = {a:?} x^2")),
            RoughnessAxis::Alpha => ("alpha", format!("alpha = {a:?} x")),
        };
        axes.push(axis(name, map, nodes, spec.size, &|x| spec.alpha_at(x)));
        if !spec.kind.average() {
            let (name, map) = match spec.mu_axis {
                MuAxis::Cos => ("mu", "mu = x"),
                MuAxis::SqrtCos => ("sqrt_mu", "mu = x^2"),
            };
            axes.push(axis(name, map.into(), nodes, spec.size, &|x| spec.mu_at(x)));
        }
        axes
    }

    /// The node counts, outermost first.
    pub fn dims(&self) -> Vec<usize> {
        self.axes.iter().map(|a| a.coords.len()).collect()
    }

    /// The table at coordinates `x` (one per axis; the side's rounded to its node):
    /// multilinear between the nodes, clamped to the end nodes outside them (texel centres:
    /// the value a GPU's linear filter returns, in f64; edges: Cycles' lookup). `x` of the wrong length, or NaN, gives
    /// NaN channels.
    pub fn lookup(&self, x: &[f64]) -> Vec<f64> {
        let c = self.channels.len();
        if x.len() != self.axes.len() || x.iter().any(|v| v.is_nan()) {
            return vec![f64::NAN; c];
        }
        // Per axis: two node indices and their weights.
        let taps: Vec<[(usize, f64); 2]> = self
            .axes
            .iter()
            .zip(x)
            .map(|(a, &x)| {
                let n = a.coords.len();
                if !a.interpolated {
                    let i = (x.clamp(0.0, 1.0) * (n - 1) as f64).round() as usize;
                    return [(i, 1.0), (i, 0.0)];
                }
                let t = match a.nodes {
                    Nodes::Centres => x * n as f64 - 0.5,
                    Nodes::Edges => x * (n - 1) as f64,
                }
                .clamp(0.0, (n - 1) as f64);
                let i = (t.floor() as usize).min(n - 2);
                let f = t - i as f64;
                [(i, 1.0 - f), (i + 1, f)]
            })
            .collect();
        let dims = self.dims();
        let mut out = vec![0.0; c];
        for corner in 0..(1usize << taps.len()) {
            let mut w = 1.0;
            let mut index = 0;
            for (k, t) in taps.iter().enumerate() {
                let (i, wk) = t[(corner >> k) & 1];
                w *= wk;
                index = index * dims[k] + i;
            }
            if w != 0.0 {
                for (o, v) in out.iter_mut().zip(&self.values[index * c..(index + 1) * c]) {
                    *o += w * v;
                }
            }
        }
        out
    }

    /// The quantity itself at texture coordinates `x` in [0, 1] (any, not only nodes; the
    /// side's rounded), by the quadrature at `level` (clamped to 2 to 7). Where a coordinate
    /// maps outside the accepted roughness (α = 0 at roughness 0, αy = 0 at aspect 0), α is
    /// taken at [`crate::ALPHA_MIN`] (or [`crate::ALPHA_MAX`]), and μ below [`MU_MIN`] at
    /// it. Coordinates outside [0, 1], NaN, or of the wrong count give NaN.
    pub fn exact(&self, x: &[f64], level: u32) -> Vec<f64> {
        if x.len() != self.axes.len() || x.iter().any(|v| !(0.0..=1.0).contains(v)) {
            return vec![f64::NAN; self.channels.len()];
        }
        quantity(&self.spec, &self.axes, x, level.clamp(2, 7))
    }

    /// The error a shader sees: [`Lut::lookup`] against [`Lut::exact`] one level finer than
    /// the table, on the product grid of, per axis, the midpoints between nodes (at most
    /// `per_axis` of them, evenly strided, the first and last always) and the two points
    /// halfway into the clamped border (texel-centred axes; an edge-aligned one has none);
    /// every node of `side`. Reported apart: the interior (every coordinate a midpoint) and
    /// the border (some coordinate clamped).
    pub fn error(&self, per_axis: usize, progress: &dyn Progress) -> LutAccuracy {
        let per_axis = per_axis.max(2);
        let probes: Vec<Vec<f64>> = self
            .axes
            .iter()
            .map(|a| {
                let n = a.coords.len();
                if !a.interpolated {
                    return a.coords.clone();
                }
                let mids = n - 1;
                let take = mids.min(per_axis);
                let mut xs: Vec<f64> = (0..take)
                    .map(|k| {
                        let j = if take == 1 {
                            0
                        } else {
                            k * (mids - 1) / (take - 1)
                        };
                        match a.nodes {
                            Nodes::Centres => (j as f64 + 1.0) / n as f64,
                            Nodes::Edges => (j as f64 + 0.5) / (n - 1) as f64,
                        }
                    })
                    .collect();
                if a.nodes == Nodes::Centres {
                    xs.push(0.25 / n as f64);
                    xs.push(1.0 - 0.25 / n as f64);
                }
                xs
            })
            .collect();
        let dims: Vec<usize> = probes.iter().map(Vec::len).collect();
        let total: usize = dims.iter().product();
        let done = AtomicUsize::new(0);
        let level = (self.spec.level + 1).min(7);
        let point = |i: usize| -> (Vec<f64>, Vec<f64>) {
            let x: Vec<f64> = unravel(i, &dims)
                .iter()
                .zip(&probes)
                .map(|(&j, p)| p[j])
                .collect();
            let diff = self
                .lookup(&x)
                .iter()
                .zip(self.exact(&x, level))
                .map(|(a, b)| (a - b).abs())
                .collect();
            progress.report(done.fetch_add(1, Ordering::Relaxed) + 1, total);
            (x, diff)
        };
        #[cfg(feature = "rayon")]
        let all: Vec<(Vec<f64>, Vec<f64>)> = {
            use rayon::prelude::*;
            (0..total).into_par_iter().map(point).collect()
        };
        #[cfg(not(feature = "rayon"))]
        let all: Vec<(Vec<f64>, Vec<f64>)> = (0..total).map(point).collect();
        let n_border: Vec<usize> = self.axes.iter().map(|a| a.coords.len()).collect();
        let mut stats = [(); 2].map(|_| (0.0f64, (Vec::new(), 0usize), 0.0f64, 0usize, 0usize));
        for (x, diff) in all {
            let border = x
                .iter()
                .zip(&self.axes)
                .zip(&n_border)
                .any(|((&x, a), &n)| {
                    a.interpolated
                        && a.nodes == Nodes::Centres
                        && (x < 0.5 / n as f64 || x > 1.0 - 0.5 / n as f64)
                });
            let s = &mut stats[border as usize];
            s.3 += 1;
            for (c, d) in diff.into_iter().enumerate() {
                // A NaN difference is the worst error there is.
                let d = if d.is_nan() { f64::INFINITY } else { d };
                s.2 += d * d;
                s.4 += 1;
                if d > s.0 || s.1 .0.is_empty() {
                    s.0 = d;
                    s.1 = (x.clone(), c);
                }
            }
        }
        let [interior, border] = stats.map(|(max_abs, at, sum, points, count)| ErrorStat {
            max_abs,
            at,
            rms: (sum / count.max(1) as f64).sqrt(),
            points,
        });
        LutAccuracy { interior, border }
    }
}

/// The multi-index of flat index `i` over `dims` (outermost first).
fn unravel(mut i: usize, dims: &[usize]) -> Vec<usize> {
    let mut out = vec![0; dims.len()];
    for k in (0..dims.len()).rev() {
        out[k] = i % dims[k];
        i /= dims[k];
    }
    out
}

/// 32-point Gauss–Legendre on [0, 1] (4 panels of the library's 8-point rule), for the
/// averages 2∫E μ dμ = ∫₀¹ E(x²) 4x³ dx.
fn gl32() -> impl Iterator<Item = (f64, f64)> {
    use crate::math::quad::GL8;
    (0..4).flat_map(|p| {
        GL8.iter()
            .map(move |&(x, w)| ((p as f64 + x) / 4.0, w / 4.0))
    })
}

/// The channels at coordinates `x` (one per axis).
fn quantity(spec: &LutSpec, axes: &[Axis], x: &[f64], level: u32) -> Vec<f64> {
    let mut p = Point {
        inside: false,
        eta: 1.0,
        aspect: 1.0,
        alpha: 1.0,
        mu: 1.0,
    };
    for (a, &x) in axes.iter().zip(x) {
        match a.name {
            "side" => p.inside = x >= 0.5,
            "eta" => p.eta = eta_at(x),
            "aspect" => p.aspect = x,
            "mu" | "sqrt_mu" => p.mu = spec.mu_at(x).max(MU_MIN),
            _ => p.alpha = spec.alpha_at(x),
        }
    }
    let (ax, ay) = stretch(p.alpha, p.aspect);
    let Ok(dist) = AnyMicrofacet::<f64>::new(spec.ndf.kind, ax, ay, spec.ndf.shape) else {
        return vec![f64::NAN; spec.kind.channels().len()];
    };
    let at_mu = |mu: f64| -> Vec<f64> { directional(spec.kind, &dist, &p, mu, level) };
    if spec.kind.average() {
        let mut sum = vec![0.0; spec.kind.channels().len()];
        for (x, w) in gl32() {
            for (s, v) in sum.iter_mut().zip(at_mu(x * x)) {
                *s += 4.0 * w * x * x * x * v;
            }
        }
        sum
    } else {
        at_mu(p.mu)
    }
}

/// Intervals of the trapezoidal rule over wo's azimuth φ ∈ [0, π] (anisotropic tables).
const AZIMUTH_INTERVALS: usize = 32;

/// The anisotropic average's nodes and weights: the trapezoidal rule over [0, π] on
/// [`AZIMUTH_INTERVALS`] intervals, folded onto [0, π/2] by E's symmetry (D even in x and in
/// y, so E(φ) = E(−φ) = E(π − φ)).
fn azimuths() -> Vec<(f64, f64)> {
    let n = AZIMUTH_INTERVALS / 2;
    (0..=n)
        .map(|k| {
            let phi = std::f64::consts::FRAC_PI_2 * k as f64 / n as f64;
            let w = if k == 0 || k == n { 0.5 } else { 1.0 };
            (phi, w / n as f64)
        })
        .collect()
}

/// The directional channels at cos θo = μ (averaged over wo's azimuth when anisotropic).
fn directional(
    kind: LutKind,
    dist: &AnyMicrofacet<f64>,
    p: &Point,
    mu: f64,
    level: u32,
) -> Vec<f64> {
    let st = ((1.0 - mu) * (1.0 + mu)).max(0.0).sqrt();
    let azimuths = if p.aspect == 1.0 {
        vec![(0.0, 1.0)]
    } else {
        azimuths()
    };
    let mut out = vec![0.0; kind.channels().len()];
    for (phi, w) in azimuths {
        let (sp, cp) = phi.sin_cos();
        let z = if p.inside { -mu } else { mu };
        let wo = [st * cp, st * sp, z];
        let v: Vec<f64> = match kind {
            LutKind::Albedo | LutKind::AlbedoAvg => {
                let (r, _) =
                    over_normals_weighted(dist, wo, None, Masking::Correlated, level, |_| [1.0]);
                r.to_vec()
            }
            LutKind::Dfg => {
                let (r, _) =
                    over_normals_weighted(dist, wo, None, Masking::Correlated, level, |c| {
                        let m = (1.0 - c).max(0.0);
                        let m5 = m * m * m * m * m;
                        [1.0 - m5, m5, c * m5 * m]
                    });
                r.to_vec()
            }
            LutKind::Dielectric | LutKind::DielectricAvg => {
                let (r, t) = over_normals_weighted(
                    dist,
                    wo,
                    Some(p.eta),
                    Masking::Correlated,
                    level,
                    |_| [1.0],
                );
                vec![r[0], t[0]]
            }
        };
        for (o, v) in out.iter_mut().zip(v) {
            *o += w * v;
        }
    }
    out
}
