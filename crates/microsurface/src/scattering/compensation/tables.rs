//! The albedo tables of energy compensation: [`AlbedoTable`], [`DielectricTables`], the
//! shipped data and its file format, and the dielectric tables' generator.

// `!(x > 0)` is the NaN-aware test (false for NaN), on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::distribution::{cached, FitCache, MicrofacetDistribution, Sample};
use crate::fast::Real;
use crate::scattering::albedo::single_scattering_albedo_tol;
use crate::scattering::table::Grid;
use crate::AnyMicrofacet;
use crate::NdfKind;
use std::marker::PhantomData;
use std::sync::{Arc, OnceLock};

/// The table's quadrature tolerance (relative): far below the interpolation's 1e-5 to 1e-4.
const TABLE_TOL: f64 = 1e-7;

/// Nodes of a conductor's table (and the shipped ones), uniform in √μ on [0, 1].
const NODES: usize = 33;

/// Nodes of a dielectric's tables: twice as dense, for the fast change of E near the
/// critical angle seen from inside (with 33 nodes the interpolation error reached 1.1e-3
/// there at α = 0.1, η = 1.5).
const DIELECTRIC_NODES: usize = 65;

/// Gauss–Legendre nodes and weights on [0, 1], 8 points (exact for degree 15: the cubic
/// interpolant times μ on each interval, and the smooth Fresnel averages).
pub(crate) const GL8: [(f64, f64); 8] = [
    (0.019_855_071_751_231_856, 0.050_614_268_145_188_13),
    (0.101_666_761_293_186_63, 0.111_190_517_226_687_24),
    (0.237_233_795_041_835_5, 0.156_853_322_938_943_64),
    (0.408_282_678_752_175_1, 0.181_341_891_689_181_0),
    (0.591_717_321_247_824_9, 0.181_341_891_689_181_0),
    (0.762_766_204_958_164_5, 0.156_853_322_938_943_64),
    (0.898_333_238_706_813_4, 0.111_190_517_226_687_24),
    (0.980_144_928_248_768_1, 0.050_614_268_145_188_13),
];

/// E(μ) of one material and its average: see the [module docs](crate::scattering).
#[derive(Clone, Debug, PartialEq)]
pub struct AlbedoTable {
    /// E at √μ = k/(n − 1), n ≥ 4 nodes.
    e: Vec<f64>,
    e_avg: f64,
    /// 2∫max(0, 1 − E(μ))μ dμ of the interpolant (see [`AlbedoTable::lost_avg`]).
    lost_avg: f64,
}

impl AlbedoTable {
    /// The table of `dist` (f32 or f64): interpolated from the tables the library ships
    /// ([`AlbedoTable::shipped`]; microseconds) where `dist` is one of the library's isotropic
    /// materials in their range, else **computed** ([`AlbedoTable::compute`], tens to hundreds of
    /// milliseconds) on
    /// the material's f64 twin (the same NDF, α and shape through [`crate::AnyMicrofacet`];
    /// a distribution that does not name its NDF, [`MicrofacetDistribution::ndf`], is evaluated in its
    /// own precision). Computed tables of the library's materials are cached for the
    /// process, so the compensated BSDFs of one material share one table.
    pub fn new<F: Real, D: MicrofacetDistribution<F>>(dist: &D) -> Arc<Self> {
        Self::new_with_progress(dist, &|_, _| {})
    }

    /// [`AlbedoTable::new`], calling `progress(done, total)` after each node a computed table
    /// evaluates (from the computing thread; never for a shipped or cached table): for a
    /// caller that shows progress (the Python package's `progress=True`; the generalised
    /// exponential's table takes minutes).
    pub fn new_with_progress<F: Real, D: MicrofacetDistribution<F>>(
        dist: &D,
        progress: &(dyn Fn(usize, usize) + Sync),
    ) -> Arc<Self> {
        static TABLES: TableCache<AlbedoTable> = OnceLock::new();
        table_of(
            dist,
            &TABLES,
            0,
            Self::shipped,
            |twin| Self::compute_with_progress(twin, progress),
            || Self::compute_with_progress(&Widened(dist, PhantomData), progress),
        )
    }

    /// The table of `dist` computed here: 33 quadratures of the single-scattering albedo
    /// (tens of milliseconds; hundreds at small α, where the lobe is narrow).
    pub fn compute<D: MicrofacetDistribution<f64>>(dist: &D) -> Self {
        Self::compute_with_progress(dist, &|_, _| {})
    }

    /// [`AlbedoTable::compute`], calling `progress(done, total)` after each node.
    pub fn compute_with_progress<D: MicrofacetDistribution<f64>>(
        dist: &D,
        progress: &(dyn Fn(usize, usize) + Sync),
    ) -> Self {
        let (ax, ay) = dist.alpha();
        let azimuths: &[f64] = if ax == ay {
            &[0.0]
        } else {
            &[0.0, 0.25, 0.5, 0.75]
        };
        let done = std::sync::atomic::AtomicUsize::new(0);
        Self::from_fn(|mu| {
            let st = ((1.0 - mu) * (1.0 + mu)).sqrt();
            let e = azimuths
                .iter()
                .map(|&p| {
                    let (sp, cp) = (p * std::f64::consts::FRAC_PI_2).sin_cos();
                    single_scattering_albedo_tol(dist, [st * cp, st * sp, mu], TABLE_TOL)
                })
                .sum::<f64>()
                / azimuths.len() as f64;
            let k = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(k, NODES);
            e
        })
    }

    /// The table of the albedo function `e` (evaluated at the 33 nodes).
    pub fn from_fn(e: impl Fn(f64) -> f64) -> Self {
        Self::from_fn_nodes(NODES, e)
    }

    /// The same on `n` nodes uniform in √μ (n ≥ 4; fewer are taken as 4).
    pub fn from_fn_nodes(n: usize, e: impl Fn(f64) -> f64) -> Self {
        let n = n.max(4);
        Self::from_nodes((0..n).map(|k| e(node_mu(k, n))).collect())
    }

    /// The table of an isotropic material of NDF `kind` (GTR: γ) at α from the tables the
    /// library ships: E(μ) at the 33 nodes over 61 values of α log-uniform on
    /// [0.01, 4] (`data/compensation/*.mfa`, [`crate::scattering::table`]'s binary form, made by
    /// `microsurface table --method quadrature --ndf NAME --alpha 0.01:4:61:log --mu 0:1:33:sqrt`),
    /// cubic Lagrange in ln α. For GGX, Beckmann, Double GGX, the Exponential NDF, and GTR
    /// at γ = 1 (Burley's clearcoat) and γ = 2 (GGX); `None` elsewhere (other γ, α outside
    /// the range) or if a shipped file does not read (never, tests/compensate.rs reads
    /// them all).
    pub fn shipped(kind: NdfKind, gamma: Option<f64>, alpha: f64) -> Option<Self> {
        let file = shipped_file(kind, gamma)?;
        let grid = shipped_grid(file)?;
        let la = alpha.ln();
        let nodes = &grid.spec.alpha;
        let (l0, l1) = (nodes[0].ln(), nodes[nodes.len() - 1].ln());
        // (A relative 1e-12 of slack: α = 4 itself, through ln and back.)
        if !(la >= l0 - 1e-12 && la <= l1 + 1e-12) {
            return None;
        }
        let x =
            ((la - l0) / (l1 - l0) * (nodes.len() - 1) as f64).clamp(0.0, (nodes.len() - 1) as f64);
        Some(Self::from_nodes(
            (0..NODES)
                .map(|k| lagrange4(x, nodes.len(), |j| grid.value(j, k, 0) as f64))
                .collect(),
        ))
    }

    /// The table of E at the nodes, with E_avg of its interpolant.
    fn from_nodes(e: Vec<f64>) -> Self {
        let n = e.len();
        let mut t = AlbedoTable {
            e,
            e_avg: 0.0,
            lost_avg: 0.0,
        };
        // E_avg = 2∫E μ dμ = 4∫E(s²) s³ ds over the interpolant, interval by interval.
        let h = 1.0 / (n - 1) as f64;
        let (mut sum, mut lost) = (0.0, 0.0);
        for k in 0..n - 1 {
            for (x, w) in GL8 {
                let s = (k as f64 + x) * h;
                let e = t.e_at_s(s);
                sum += w * h * e * s * s * s;
                lost += w * h * (1.0 - e).max(0.0) * s * s * s;
            }
        }
        t.e_avg = 4.0 * sum;
        t.lost_avg = 4.0 * lost;
        t
    }

    /// The table of E at `values.len()` nodes uniform in √μ ([`AlbedoTable::mu`]), as
    /// [`AlbedoTable::values`] gives them (a table saved and read back); `None` for fewer than
    /// 4 nodes or a value that is not finite.
    pub fn from_values(values: Vec<f64>) -> Option<Self> {
        (values.len() >= 4 && values.iter().all(|v| v.is_finite()))
            .then(|| Self::from_nodes(values))
    }

    /// E at the nodes (the interpolant passes through them).
    pub fn values(&self) -> &[f64] {
        &self.e
    }

    /// The nodes' μ: s² for s = k/(n − 1) uniform, the grazing node at μ = 1e-6 (the
    /// albedo's limit there).
    pub fn mu(&self) -> Vec<f64> {
        let n = self.e.len();
        (0..n).map(|k| node_mu(k, n)).collect()
    }

    /// E(μ) for μ ∈ [0, 1] (clamped), by the interpolant.
    pub fn e(&self, mu: f64) -> f64 {
        self.e_at_s(mu.clamp(0.0, 1.0).sqrt())
    }

    /// E_avg = 2∫E(μ)μ dμ of the interpolant.
    pub fn e_avg(&self) -> f64 {
        self.e_avg
    }

    /// 2∫max(0, 1 − E(μ))μ dμ of the interpolant: 1 − E_avg, except where the interpolant
    /// overshoots 1 (a nearly lossless material, E within the interpolation error of 1 over
    /// part of the range): the normalisation of a lobe ∝ max(0, 1 − E(μi)), which is what a
    /// BSDF can use (f ≥ 0) and must integrate to its share exactly.
    pub fn lost_avg(&self) -> f64 {
        self.lost_avg
    }

    /// The cubic Lagrange interpolant through the four nodes nearest s = √μ.
    fn e_at_s(&self, s: f64) -> f64 {
        let n = self.e.len();
        lagrange4(s.clamp(0.0, 1.0) * (n - 1) as f64, n, |j| self.e[j])
    }
}

/// Which shipped file (of Beckmann, GGX, Double GGX, Exponential, GTR γ = 1) holds the
/// material `kind` (GTR: γ), in both the conductor's and the dielectric's lists; GTR at
/// γ = 2 is GGX; `None` for other γ.
fn shipped_file(kind: NdfKind, gamma: Option<f64>) -> Option<usize> {
    Some(match (kind, gamma) {
        (NdfKind::Gtr, Some(2.0)) => 1,
        (NdfKind::Gtr, Some(1.0)) => 4,
        (NdfKind::Gtr, _) => return None,
        (NdfKind::Ggx, _) => 1,
        (NdfKind::Beckmann, _) => 0,
        (NdfKind::DoubleGgx, _) => 2,
        (NdfKind::Exponential, _) => 3,
        _ => return None,
    })
}

/// μ at node k of n: s² for s = k/(n − 1), the grazing node at μ = 1e-6 (the albedo's
/// limit there: the lobe is a continuous function of μ, and E(1e-6) differs from the
/// limit by O(1e-6)).
fn node_mu(k: usize, n: usize) -> f64 {
    let s = k as f64 / (n - 1) as f64;
    (s * s).max(1e-6)
}

/// The cubic Lagrange interpolant at x (in node units, 0 ≤ x ≤ n − 1) through the four
/// nodes of `value` nearest it (n ≥ 4).
fn lagrange4(x: f64, n: usize, value: impl Fn(usize) -> f64) -> f64 {
    let k = (x.floor() as usize).clamp(1, n - 3) - 1;
    let t = x - k as f64;
    let mut v = 0.0;
    for j in 0..4 {
        let mut l = 1.0;
        for m in 0..4 {
            if m != j {
                l *= (t - m as f64) / (j as f64 - m as f64);
            }
        }
        v += l * value(k + j);
    }
    v
}

/// The shipped tables: Beckmann, GGX, Double GGX, Exponential, GTR γ = 1.
const SHIPPED: [&[u8]; 5] = [
    include_bytes!("../../../data/compensation/beckmann.mfa"),
    include_bytes!("../../../data/compensation/ggx.mfa"),
    include_bytes!("../../../data/compensation/double_ggx.mfa"),
    include_bytes!("../../../data/compensation/exponential.mfa"),
    include_bytes!("../../../data/compensation/gtr1.mfa"),
];

/// The shipped table `i`, read once.
fn shipped_grid(i: usize) -> Option<&'static Grid> {
    static GRIDS: [OnceLock<Option<Grid>>; 5] = [const { OnceLock::new() }; 5];
    GRIDS[i]
        .get_or_init(|| {
            Grid::from_bytes(SHIPPED[i])
                .ok()
                .filter(|g| g.spec.mu.len() == NODES && g.spec.alpha.len() >= 4)
        })
        .as_ref()
}

/// The tables of a rough dielectric interface (relative index η = η_inside/η_outside): the
/// single-scattering albedo, reflection plus transmission, from outside (η) and from inside
/// (1/η), [`crate::scattering::single_scattering_albedo_dielectric`] at 65 nodes uniform in √μ
/// (twice a conductor's), at the rule's level 3 (within 1.2e-4 of level 7 in the worst case
/// measured, Double GGX; the furnace stays within 1e-3 with it). Shipped for the library's
/// isotropic materials at the common indices [`SHIPPED_ETAS`] ([`DielectricTables::new`]);
/// computed otherwise: 130 quadratures, under a second for an isotropic material, four
/// times that for an anisotropic one (the mean over four azimuths of wo, as
/// [`AlbedoTable::compute`]).
#[derive(Clone, Debug, PartialEq)]
pub struct DielectricTables {
    /// E(μ) from outside.
    pub outside: AlbedoTable,
    /// E(μ) from inside.
    pub inside: AlbedoTable,
}

impl DielectricTables {
    /// The tables of `dist` (f32 or f64) at relative index η: interpolated from the tables
    /// the library ships ([`DielectricTables::shipped`]; microseconds) where `dist` is one of
    /// the library's isotropic materials, α in [0.01, 4] and η one of the shipped indices,
    /// else **computed** ([`DielectricTables::compute`], under a second isotropic) on the
    /// material's f64 twin, as [`AlbedoTable::new`], and cached for the process by
    /// (material, η).
    pub fn new<F: Real, D: MicrofacetDistribution<F>>(dist: &D, eta: f64) -> Arc<Self> {
        static TABLES: TableCache<DielectricTables> = OnceLock::new();
        table_of(
            dist,
            &TABLES,
            eta.to_bits(),
            |kind, shape, alpha| Self::shipped(kind, shape, alpha, eta),
            |twin| Self::compute(twin, eta),
            || Self::compute(&Widened(dist, PhantomData), eta),
        )
    }

    /// The tables of an isotropic material of NDF `kind` (GTR: γ ∈ {1, 2}) at α from the
    /// shipped data (`data/compensation/*-dielectric.mfd`, written by
    /// `examples/gen_dielectric_tables.rs` with [`dielectric_table_bytes`]) for the common
    /// indices η ∈ [`SHIPPED_ETAS`] (water, pbrt's and Mitsuba's default glass 1.5, 1.6, 2,
    /// diamond; 1/η too, the same interface seen from inside): both sides' E at the 65 √μ
    /// nodes over 49 values of α log-uniform on [0.01, 4], cubic Lagrange in ln α. `None`
    /// for other η (an η between them is not interpolated: E(μ) seen from inside has
    /// features that move with η: the critical angle, seen from inside), α outside the range or
    /// other NDFs. Equal to a computed table at the α nodes (to f32 rounding, 4e-8) and
    /// within 2e-4 between them (1.7e-4 measured for GGX and Beckmann at α = 2.9, seen from
    /// inside at grazing μ; 1e-5 or less at α ≤ 0.6; tests/compensate.rs).
    pub fn shipped(kind: NdfKind, gamma: Option<f64>, alpha: f64, eta: f64) -> Option<Self> {
        let file = shipped_file(kind, gamma)?;
        // (A relative 1e-7 of slack: an η written with its digits, or rounded to f32 (1.33f32
        // is 1.33 + 3e-8, which missed the tables and computed them, a second); E moves by
        // far less than the interpolation's 2e-4 over it.)
        let matches = |x: f64| (x - eta).abs() <= 1e-7 * x;
        let (je, flip) = match SHIPPED_ETAS.iter().position(|&x| matches(x)) {
            Some(j) => (j, false),
            None => (SHIPPED_ETAS.iter().position(|&x| matches(1.0 / x))?, true),
        };
        let data = shipped_dielectric(file)?;
        let (a0, a1, na) = SHIP_ALPHA;
        let (la, l0, l1) = (alpha.ln(), a0.ln(), a1.ln());
        if !(la >= l0 - 1e-12 && la <= l1 + 1e-12) {
            return None;
        }
        let x = ((la - l0) / (l1 - l0) * (na - 1) as f64).clamp(0.0, (na - 1) as f64);
        let side = |s: usize| {
            AlbedoTable::from_nodes(
                (0..DIELECTRIC_NODES)
                    .map(|k| {
                        lagrange4(x, na, |ia| {
                            data[((ia * SHIPPED_ETAS.len() + je) * 2 + s) * DIELECTRIC_NODES + k]
                                as f64
                        })
                    })
                    .collect(),
            )
        };
        let (outside, inside) = if flip {
            (side(1), side(0))
        } else {
            (side(0), side(1))
        };
        Some(DielectricTables { outside, inside })
    }

    /// The tables of `dist` with relative index `eta` (> 0, finite; η = 1 gives E = 1).
    pub fn compute<D: MicrofacetDistribution<f64>>(dist: &D, eta: f64) -> Self {
        let (ax, ay) = dist.alpha();
        let azimuths: &[f64] = if ax == ay {
            &[0.0]
        } else {
            &[0.0, 0.25, 0.5, 0.75]
        };
        let side = |z: f64| {
            AlbedoTable::from_fn_nodes(DIELECTRIC_NODES, |mu| {
                let st = ((1.0 - mu) * (1.0 + mu)).sqrt();
                azimuths
                    .iter()
                    .map(|&p| {
                        let (sp, cp) = (p * std::f64::consts::FRAC_PI_2).sin_cos();
                        let (r, t) =
                            crate::scattering::albedo::single_scattering_albedo_dielectric_level(
                                dist,
                                [st * cp, st * sp, z * mu],
                                eta,
                                crate::bsdf::Masking::Correlated,
                                3,
                            );
                        r + t
                    })
                    .sum::<f64>()
                    / azimuths.len() as f64
            })
        };
        if eta == 1.0 {
            let one = AlbedoTable::from_fn_nodes(DIELECTRIC_NODES, |_| 1.0);
            return DielectricTables {
                outside: one.clone(),
                inside: one,
            };
        }
        DielectricTables {
            outside: side(1.0),
            inside: side(-1.0),
        }
    }
}

/// The indices the dielectric tables are shipped for (and their reciprocals, from inside):
/// water, 1.5 (pbrt-v4's and Mitsuba 3's default glass), 1.6, 2 and diamond.
pub const SHIPPED_ETAS: [f64; 5] = [1.33, 1.5, 1.6, 2.0, 2.42];

/// The shipped dielectric tables' α nodes: 49 log-uniform on [0.01, 4] (as the conductor's
/// range; cubic Lagrange in ln α between them).
const SHIP_ALPHA: (f64, f64, usize) = (0.01, 4.0, 49);

/// The shipped dielectric tables: Beckmann, GGX, Double GGX, Exponential, GTR γ = 1.
const SHIPPED_DIELECTRIC: [&[u8]; 5] = [
    include_bytes!("../../../data/compensation/beckmann-dielectric.mfd"),
    include_bytes!("../../../data/compensation/ggx-dielectric.mfd"),
    include_bytes!("../../../data/compensation/double_ggx-dielectric.mfd"),
    include_bytes!("../../../data/compensation/exponential-dielectric.mfd"),
    include_bytes!("../../../data/compensation/gtr1-dielectric.mfd"),
];

/// The shipped dielectric table `i` (its values), read and checked once: the header must
/// name this build's grid (see [`dielectric_table_bytes`]).
fn shipped_dielectric(i: usize) -> Option<&'static [f32]> {
    static DATA: [OnceLock<Option<Vec<f32>>>; 5] = [const { OnceLock::new() }; 5];
    DATA[i]
        .get_or_init(|| {
            let b = SHIPPED_DIELECTRIC[i];
            let header = dielectric_header();
            let count = SHIP_ALPHA.2 * SHIPPED_ETAS.len() * 2 * DIELECTRIC_NODES;
            if b.len() != header.len() + 4 * count || b[..header.len()] != header[..] {
                return None;
            }
            Some(
                b[header.len()..]
                    .chunks_exact(4)
                    .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
                    .collect(),
            )
        })
        .as_deref()
}

/// The shipped dielectric files' header: "MFDIELE1", then n_α, n_η, n_μ (u32, little
/// endian), α_min, α_max and the η values (f64, little endian).
fn dielectric_header() -> Vec<u8> {
    let mut b = b"MFDIELE1".to_vec();
    for n in [SHIP_ALPHA.2, SHIPPED_ETAS.len(), DIELECTRIC_NODES] {
        b.extend_from_slice(&(n as u32).to_le_bytes());
    }
    for x in [SHIP_ALPHA.0, SHIP_ALPHA.1].iter().chain(&SHIPPED_ETAS) {
        b.extend_from_slice(&x.to_le_bytes());
    }
    b
}

/// The shipped dielectric file of NDF `kind` (GTR: γ), computed here on `threads` threads
/// (about a minute of one core per NDF): the header ("MFDIELE1",
/// n_α, n_η, n_μ as u32, α_min, α_max, the η values as f64, little endian), then E as f32
/// little endian in the order (α_i, η_j, side, μ_k): α_i log-uniform on [α_min, α_max],
/// side 0 from outside (η_j), 1 from inside (1/η_j), μ_k the 65 √μ nodes of a dielectric
/// [`AlbedoTable`]; E the single-scattering interface's reflection plus transmission
/// ([`crate::scattering::single_scattering_albedo_dielectric`] at the rule's level 3, as
/// [`DielectricTables::compute`]).
pub fn dielectric_table_bytes(
    kind: NdfKind,
    gamma: Option<f64>,
    threads: usize,
) -> Result<Vec<u8>, crate::ParamError> {
    let (a0, a1, na) = SHIP_ALPHA;
    let alphas: Vec<f64> = (0..na)
        .map(|i| (a0.ln() + (a1.ln() - a0.ln()) * i as f64 / (na - 1) as f64).exp())
        .collect();
    fn row<D: MicrofacetDistribution<f64>>(d: &D) -> Vec<f32> {
        let mut out = Vec::new();
        for eta in SHIPPED_ETAS {
            let t = DielectricTables::compute(d, eta);
            for side in [&t.outside, &t.inside] {
                out.extend(side.e.iter().map(|&x| x as f32));
            }
        }
        out
    }
    let materials = alphas
        .iter()
        .map(|&a| AnyMicrofacet::<f64>::new(kind, a, a, gamma))
        .collect::<Result<Vec<_>, _>>()?;
    let threads = threads.max(1);
    let mut rows: Vec<(usize, Vec<f32>)> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..threads)
            .map(|t| {
                let materials = &materials;
                scope.spawn(move || {
                    (0..materials.len())
                        .filter(|i| i % threads == t)
                        .map(|i| (i, row(&materials[i])))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap())
            .collect()
    });
    rows.sort_by_key(|r| r.0);
    let mut b = dielectric_header();
    for v in rows.iter().flat_map(|r| &r.1) {
        b.extend_from_slice(&v.to_le_bytes());
    }
    Ok(b)
}

/// The process-wide cache of computed tables, by (kind, shape, αx, αy, and the dielectric's
/// η: 0 for a conductor's table), as bits.
type TableCache<T> = FitCache<(NdfKind, u64, u64, u64, u64), T>;

/// The table of `dist` (both [`AlbedoTable::new`] and [`DielectricTables::new`]): `shipped`
/// for an isotropic material of the library where it has one; else `compute` on the
/// material's f64 twin (the same NDF, α and shape through [`AnyMicrofacet`]) once per
/// material, `extra` and process (`cache`); a distribution that does not name its NDF, or
/// whose twin cannot be built, by `widened` (in its own precision, not cached).
fn table_of<F: Real, D: MicrofacetDistribution<F>, T>(
    dist: &D,
    cache: &'static TableCache<T>,
    extra: u64,
    shipped: impl FnOnce(NdfKind, Option<f64>, f64) -> Option<T>,
    compute: impl FnOnce(&AnyMicrofacet<f64>) -> T,
    widened: impl FnOnce() -> T,
) -> Arc<T> {
    let (ax, ay) = (dist.alpha().0.to_f64(), dist.alpha().1.to_f64());
    let Some((kind, shape)) = dist.ndf() else {
        return Arc::new(widened());
    };
    if ax == ay {
        if let Some(t) = shipped(kind, shape, ax) {
            return Arc::new(t);
        }
    }
    let bits = shape.unwrap_or(0.0).to_bits();
    let key = (kind, bits, ax.to_bits(), ay.to_bits(), extra);
    let made: Result<_, std::convert::Infallible> = cached(cache, key, || {
        Ok(match AnyMicrofacet::<f64>::new(kind, ax, ay, shape) {
            Ok(twin) => compute(&twin),
            Err(_) => widened(),
        })
    });
    match made {
        Ok(t) => t,
    }
}

/// A distribution of precision F seen as an f64 one (arguments rounded to F, values
/// widened): the tables of a distribution that does not name its NDF.
struct Widened<'a, F, D>(&'a D, PhantomData<F>);

impl<F: Real, D: MicrofacetDistribution<F>> MicrofacetDistribution<f64> for Widened<'_, F, D> {
    fn alpha(&self) -> (f64, f64) {
        let (ax, ay) = self.0.alpha();
        (ax.to_f64(), ay.to_f64())
    }
    fn d(&self, wm: [f64; 3]) -> f64 {
        self.0.d(wm.map(F::from_f64)).to_f64()
    }
    fn lambda(&self, w: [f64; 3]) -> f64 {
        self.0.lambda(w.map(F::from_f64)).to_f64()
    }
    fn g1(&self, w: [f64; 3]) -> f64 {
        self.0.g1(w.map(F::from_f64)).to_f64()
    }
    fn pdf(&self, w: [f64; 3], wm: [f64; 3]) -> f64 {
        self.0.pdf(w.map(F::from_f64), wm.map(F::from_f64)).to_f64()
    }
    fn d_visible(&self, w: [f64; 3], wm: [f64; 3]) -> f64 {
        self.0
            .d_visible(w.map(F::from_f64), wm.map(F::from_f64))
            .to_f64()
    }
    fn sample_wm(&self, w: [f64; 3], u: [f64; 2]) -> [f64; 3] {
        self.0
            .sample_wm(w.map(F::from_f64), u.map(F::from_f64))
            .map(F::to_f64)
    }
    fn sample_wm_stream(&self, v: [f64; 3], uniform: &mut dyn FnMut() -> f64) -> Option<[f64; 3]> {
        self.0
            .sample_wm_stream(v.map(F::from_f64), &mut || F::from_f64(uniform()))
            .map(|m| m.map(F::to_f64))
    }
    fn sample_dcos(&self, u: [f64; 2]) -> Sample<f64> {
        let s = self.0.sample_dcos(u.map(F::from_f64));
        Sample {
            wm: s.wm.map(F::to_f64),
            pdf: s.pdf.to_f64(),
        }
    }
    fn pdf_dcos(&self, wm: [f64; 3]) -> f64 {
        self.0.pdf_dcos(wm.map(F::from_f64)).to_f64()
    }
    fn effectively_smooth(&self) -> bool {
        self.0.effectively_smooth()
    }
}
