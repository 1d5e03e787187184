//! The albedo tables of energy compensation: [`AlbedoTable`], [`DielectricTables`], the
//! shipped data and its file format, and the dielectric tables' generator.

// `!(x > 0)` is the NaN-aware test (false for NaN), on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::distribution::{cached, FitCache, MicrofacetDistribution, Sample};
use crate::math::quad::GL8;
use crate::math::real::Real;
use crate::scattering::albedo::single_scattering_albedo_tol;
use crate::scattering::progress::{Cancelled, Progress};
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

/// E(μ) of one material and its average: see the [module docs](crate::scattering).
///
/// An anisotropic material's albedo depends on wo's azimuth φ too (a GGX α = (0.9, 0.2)
/// conductor loses 8 % of the energy at μ = 0.2 seen along the smooth axis and a fifth of it
/// along the rough one), so its table holds E(μ, φ) as a cosine series in 2φ: E is even in φ
/// and symmetric about φ = π/2 (the NDF's mirror symmetries), so E(μ, φ) =
/// Σ_{m<M} c_m(μ) cos 2mφ, whose coefficients come from the albedo at the M azimuths
/// φ_j = jπ/(2(M − 1)) (the cosine transform of Chebyshev–Lobatto interpolation in cos 2φ:
/// spectrally accurate in the azimuth), each cubic in √μ as the isotropic table. c₀ is the
/// mean over the azimuth ([`AlbedoTable::e`], [`AlbedoTable::values`]); [`AlbedoTable::e_dir`]
/// is E at a direction.
#[derive(Clone, Debug, PartialEq)]
pub struct AlbedoTable {
    /// E (the mean over wo's azimuth, c₀) at √μ = k/(n − 1), n ≥ 4 nodes.
    e: Vec<f64>,
    /// c_m at the same nodes for m = 1 … M − 1, m-major (empty: isotropic).
    harmonics: Vec<Vec<f64>>,
    e_avg: f64,
    /// (1/π)∫max(0, 1 − E(w)) cos θ dω of the interpolant (see [`AlbedoTable::lost_avg`]).
    lost_avg: f64,
}

/// Azimuths of an anisotropic material's table (M): φ_j = jπ/16 on [0, π/2]. The albedo's
/// change with the azimuth is smooth (the projected roughness αx² cos²φ + αy² sin²φ): with 9
/// azimuths E(wo) at azimuths between them is within 3.9e-4 of the quadrature for GGX at
/// aspects 4 and 4.5, 5.7e-5 for Beckmann at 3 (tests/compensate.rs), the size of the
/// interpolation in √μ.
pub const AZIMUTHS: usize = 9;

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
        match Self::new_with_progress(dist, &|_, _| {}) {
            Ok(t) => t,
            Err(Cancelled) => unreachable!("a plain closure is never cancelled"),
        }
    }

    /// [`AlbedoTable::new`], calling `progress(done, total)` after each node a computed table
    /// evaluates (from the computing thread; never for a shipped or cached table): for a
    /// caller that shows progress (the Python package's `progress=True`; the generalised
    /// exponential's table takes minutes), and asking it before each node whether to stop
    /// ([`crate::scattering::Progress`]): [`Cancelled`] then, and nothing is cached.
    pub fn new_with_progress<F: Real, D: MicrofacetDistribution<F>>(
        dist: &D,
        progress: &dyn Progress,
    ) -> Result<Arc<Self>, Cancelled> {
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
        match Self::compute_with_progress(dist, &|_, _| {}) {
            Ok(t) => t,
            Err(Cancelled) => unreachable!("a plain closure is never cancelled"),
        }
    }

    /// [`AlbedoTable::compute`], reporting to `progress` after each node and asking it
    /// before each whether to stop ([`Cancelled`] then).
    pub fn compute_with_progress<D: MicrofacetDistribution<f64>>(
        dist: &D,
        progress: &dyn Progress,
    ) -> Result<Self, Cancelled> {
        let (ax, ay) = dist.alpha();
        let azimuths = if ax == ay { 1 } else { AZIMUTHS };
        let done = std::sync::atomic::AtomicUsize::new(0);
        let stopped = std::sync::atomic::AtomicBool::new(false);
        let table = Self::from_fn_azimuthal(NODES, azimuths, |mu, phi| {
            if stopped.load(std::sync::atomic::Ordering::Relaxed) || progress.cancelled() {
                stopped.store(true, std::sync::atomic::Ordering::Relaxed);
                return 1.0;
            }
            let st = ((1.0 - mu) * (1.0 + mu)).sqrt();
            let (sp, cp) = phi.sin_cos();
            let e = single_scattering_albedo_tol(dist, [st * cp, st * sp, mu], TABLE_TOL);
            let k = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress.report(k, NODES * azimuths);
            e
        });
        if stopped.load(std::sync::atomic::Ordering::Relaxed) {
            return Err(Cancelled);
        }
        Ok(table)
    }

    /// The table of the albedo function `e(μ, φ)` of wo's cosine and azimuth, at `n` nodes
    /// uniform in √μ (n ≥ 4; fewer are taken as 4) and `m` azimuths φ_j = jπ/(2(m − 1)) on
    /// [0, π/2] (m ≤ 1: isotropic, `e` called at φ = 0): `e` must be even in φ and symmetric
    /// about π/2, as every NDF of the library is under its mirror symmetries.
    pub fn from_fn_azimuthal(n: usize, m: usize, e: impl Fn(f64, f64) -> f64) -> Self {
        let n = n.max(4);
        if m <= 1 {
            return Self::from_nodes((0..n).map(|k| e(node_mu(k, n), 0.0)).collect());
        }
        let steps = (m - 1) as f64;
        let samples: Vec<Vec<f64>> = (0..m)
            .map(|j| {
                let phi = j as f64 * std::f64::consts::FRAC_PI_2 / steps;
                (0..n).map(|k| e(node_mu(k, n), phi)).collect()
            })
            .collect();
        // The cosine transform of the samples in θ = 2φ at θ_j = jπ/(m − 1): c_q =
        // (2/(m − 1)) Σ″_j E_j cos(qjπ/(m − 1)) (Σ″: the end terms halved), with c₀ and
        // c_{m−1} halved, so that E(θ) = Σ_q c_q cos qθ passes through the samples.
        let coef: Vec<Vec<f64>> = (0..m)
            .map(|q| {
                let end = if q == 0 || q == m - 1 { 0.5 } else { 1.0 };
                (0..n)
                    .map(|k| {
                        let sum: f64 = (0..m)
                            .map(|j| {
                                let w = if j == 0 || j == m - 1 { 0.5 } else { 1.0 };
                                let c = (std::f64::consts::PI * (q * j) as f64 / steps).cos();
                                w * samples[j][k] * c
                            })
                            .sum();
                        end * 2.0 / steps * sum
                    })
                    .collect()
            })
            .collect();
        let mut coef = coef.into_iter();
        let e0 = coef.next().expect("m ≥ 2 rows");
        Self::from_parts(e0, coef.collect())
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
        let (j0, w) = lagrange4_weights(x, nodes.len());
        Some(Self::from_nodes(
            (0..NODES)
                .map(|k| (0..4).map(|j| w[j] * grid.value(j0 + j, k, 0) as f64).sum())
                .collect(),
        ))
    }

    /// The table of E at the nodes, with E_avg of its interpolant.
    fn from_nodes(e: Vec<f64>) -> Self {
        Self::from_parts(e, Vec::new())
    }

    /// The table of c₀ and the azimuthal harmonics at the nodes, with E_avg and the lost
    /// average of its interpolant.
    fn from_parts(e: Vec<f64>, harmonics: Vec<Vec<f64>>) -> Self {
        let n = e.len();
        let mut t = AlbedoTable {
            e,
            harmonics,
            e_avg: 0.0,
            lost_avg: 0.0,
        };
        // E_avg = 2∫E μ dμ = 4∫E(s²) s³ ds over the interpolant, by the rule's points (fixed
        // for n, their interpolation weights formed once: a table is built per material of a
        // textured α); the harmonics average to 0 over the azimuth. The lost average over the
        // azimuth too, by the midpoint rule on 32 azimuths of [0, π/2] (exact for the series'
        // terms, which are polynomials of degree ≤ 16 in cos 2φ, away from max's kink).
        let c2s: Vec<f64> = (0..32)
            .map(|j| (2.0 * (j as f64 + 0.5) * std::f64::consts::FRAC_PI_2 / 32.0).cos())
            .collect();
        let (mut sum, mut lost) = (0.0, 0.0);
        let mut c = vec![0.0; t.harmonics.len()];
        for p in gl_points(n).iter() {
            let at = |row: &[f64]| -> f64 { (0..4).map(|j| p.weights[j] * row[p.first + j]).sum() };
            let e = at(&t.e);
            sum += p.w * e;
            if t.harmonics.is_empty() {
                lost += p.w * (1.0 - e).max(0.0);
                continue;
            }
            for (c, h) in c.iter_mut().zip(&t.harmonics) {
                *c = at(h);
            }
            let l = c2s
                .iter()
                .map(|&c2| (1.0 - e - cosine_series(c.iter().copied(), c2)).max(0.0))
                .sum::<f64>();
            lost += p.w * l / c2s.len() as f64;
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

    /// E at the nodes (the interpolant passes through them); for an anisotropic material,
    /// its mean over wo's azimuth (c₀).
    pub fn values(&self) -> &[f64] {
        &self.e
    }

    /// The azimuthal harmonics c₁ … c_{M−1} at the nodes (empty for an isotropic
    /// material): E(μ, φ) = Σ_m c_m(μ) cos 2mφ with c₀ = [`AlbedoTable::values`].
    pub fn harmonics(&self) -> &[Vec<f64>] {
        &self.harmonics
    }

    /// The table of [`AlbedoTable::values`] and [`AlbedoTable::harmonics`] (a table saved and
    /// read back); `None` for fewer than 4 nodes, rows of other lengths or a value that is
    /// not finite.
    pub fn from_harmonics(values: Vec<f64>, harmonics: Vec<Vec<f64>>) -> Option<Self> {
        let ok = values.len() >= 4
            && values.iter().all(|v| v.is_finite())
            && harmonics
                .iter()
                .all(|h| h.len() == values.len() && h.iter().all(|v| v.is_finite()));
        ok.then(|| Self::from_parts(values, harmonics))
    }

    /// Whether E depends on wo's azimuth (an anisotropic material's table).
    pub fn is_azimuthal(&self) -> bool {
        !self.harmonics.is_empty()
    }

    /// E at the unit direction w (its side ignored: μ = |w.z|, clamped to [0, 1] as
    /// [`AlbedoTable::e`]'s; the azimuth from (w.x, w.y) at any length), by the interpolant:
    /// E(μ, φ) of an anisotropic material's table, E(μ) of an isotropic one (exactly
    /// [`AlbedoTable::e`]). NaN in, NaN out. Accuracy: the cubic's in √μ (module docs) and,
    /// in the azimuth, the cosine series' ([`AZIMUTHS`]: together within 3.9e-4 of the
    /// quadrature at GGX aspects of 4 and 4.5, tests/compensate.rs).
    pub fn e_dir(&self, w: [f64; 3]) -> f64 {
        if self.harmonics.is_empty() {
            return self.e(w[2].abs());
        }
        // cos 2φ = (x² − y²)/(x² + y²), scaled by max(|x|, |y|) (no overflow or underflow
        // of the squares); at the pole every azimuth is the same direction.
        let r = w[0].abs().max(w[1].abs());
        let c2 = if r > 0.0 {
            let (x, y) = (w[0] / r, w[1] / r);
            (x * x - y * y) / (x * x + y * y)
        } else if w[0].is_nan() || w[1].is_nan() {
            f64::NAN
        } else {
            1.0
        };
        let mu = w[2].abs();
        if mu.is_nan() {
            return f64::NAN;
        }
        self.e_at(mu.min(1.0).sqrt(), c2)
    }

    /// E at √μ = s and cos 2φ = c2: Σ_m c_m(s) T_m(c2) (cos 2mφ = T_m(cos 2φ), by the
    /// Chebyshev recurrence).
    fn e_at(&self, s: f64, c2: f64) -> f64 {
        let n = self.e.len();
        let x = s.clamp(0.0, 1.0) * (n - 1) as f64;
        let (k, w) = lagrange4_weights(x, n);
        let at = |row: &[f64]| -> f64 { (0..4).map(|j| w[j] * row[k + j]).sum() };
        at(&self.e) + cosine_series(self.harmonics.iter().map(|h| at(h)), c2)
    }

    /// The nodes' μ: s² for s = k/(n − 1) uniform, the grazing node at μ = 1e-6 (the
    /// albedo's limit there).
    pub fn mu(&self) -> Vec<f64> {
        let n = self.e.len();
        (0..n).map(|k| node_mu(k, n)).collect()
    }

    /// E(μ) for μ ∈ [−1, 1] by the interpolant: μ < 0 is the mirror image, E(|μ|) (the
    /// BSDFs are two-sided, as [`crate::scattering::single_scattering_albedo`] and
    /// [`AlbedoTable::e_dir`] have it); |μ| past 1 is clamped.
    pub fn e(&self, mu: f64) -> f64 {
        self.e_at_s(mu.abs().min(1.0).sqrt())
    }

    /// E_avg = (1/π)∫E(w) cos θ dω = 2∫E(μ)μ dμ of the interpolant (E averaged over wo's
    /// azimuth where it depends on it).
    pub fn e_avg(&self) -> f64 {
        self.e_avg
    }

    /// (1/π)∫max(0, 1 − E(w)) cos θ dω of the interpolant (2∫max(0, 1 − E(μ))μ dμ where E
    /// does not depend on the azimuth): 1 − E_avg, except where the interpolant
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
    let (k, w) = lagrange4_weights(x, n);
    (0..4).map(|j| w[j] * value(k + j)).sum()
}

/// Σ_m c[m − 1] T_m(c2) for m = 1 … (cos 2mφ = T_m(cos 2φ), by the Chebyshev recurrence;
/// c2 clamped to [−1, 1]).
fn cosine_series(c: impl Iterator<Item = f64>, c2: f64) -> f64 {
    let c2 = c2.clamp(-1.0, 1.0);
    let (mut prev, mut t, mut v) = (1.0, c2, 0.0);
    for cm in c {
        v += t * cm;
        (prev, t) = (t, 2.0 * c2 * t - prev);
    }
    v
}

/// The first of the four nodes nearest x (in node units, 0 ≤ x ≤ n − 1, n ≥ 4) and their
/// cubic Lagrange weights at x.
fn lagrange4_weights(x: f64, n: usize) -> (usize, [f64; 4]) {
    let k = (x.floor() as usize).clamp(1, n - 3) - 1;
    let t = x - k as f64;
    // l_j(t) = Π_{m≠j} (t − m)/(j − m) on the nodes 0 … 3.
    let (a, b, c, d) = (t, t - 1.0, t - 2.0, t - 3.0);
    (
        k,
        [
            -b * c * d / 6.0,
            a * c * d / 2.0,
            -a * b * d / 2.0,
            a * b * c / 6.0,
        ],
    )
}

/// One point of the Gauss–Legendre rule of a table's E_avg (8 points on each interval of
/// s = √μ): the first node of its interpolation, the four weights, and the rule's weight
/// times s³ (E_avg = 4∫E(s²)s³ ds).
#[derive(Clone)]
struct GlPoint {
    first: usize,
    weights: [f64; 4],
    w: f64,
}

/// The rule's points for a table of n nodes (33 or 65: formed once per process; other n
/// each time).
fn gl_points(n: usize) -> std::borrow::Cow<'static, [GlPoint]> {
    fn make(n: usize) -> Vec<GlPoint> {
        let h = 1.0 / (n - 1) as f64;
        (0..n - 1)
            .flat_map(|k| {
                GL8.iter().map(move |&(x, w)| {
                    let s = (k as f64 + x) * h;
                    let (first, weights) = lagrange4_weights(s * (n - 1) as f64, n);
                    GlPoint {
                        first,
                        weights,
                        w: w * h * s * s * s,
                    }
                })
            })
            .collect()
    }
    static CONDUCTOR: OnceLock<Vec<GlPoint>> = OnceLock::new();
    static DIELECTRIC: OnceLock<Vec<GlPoint>> = OnceLock::new();
    match n {
        NODES => CONDUCTOR.get_or_init(|| make(NODES)).as_slice().into(),
        DIELECTRIC_NODES => DIELECTRIC
            .get_or_init(|| make(DIELECTRIC_NODES))
            .as_slice()
            .into(),
        _ => make(n).into(),
    }
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
/// computed otherwise: 130 quadratures, under a second for an isotropic material, nine
/// times that for an anisotropic one (E(μ, φ) at [`AZIMUTHS`] azimuths of wo, as
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
        let made: Result<_, std::convert::Infallible> = table_of(
            dist,
            &TABLES,
            eta.to_bits(),
            |kind, shape, alpha| Self::shipped(kind, shape, alpha, eta),
            |twin| Ok(Self::compute(twin, eta)),
            || Ok(Self::compute(&Widened(dist, PhantomData), eta)),
        );
        match made {
            Ok(t) => t,
        }
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
        let (i0, w) = lagrange4_weights(x, na);
        let side = |s: usize| {
            AlbedoTable::from_nodes(
                (0..DIELECTRIC_NODES)
                    .map(|k| {
                        (0..4)
                            .map(|j| {
                                let ia = i0 + j;
                                w[j] * data[((ia * SHIPPED_ETAS.len() + je) * 2 + s)
                                    * DIELECTRIC_NODES
                                    + k] as f64
                            })
                            .sum()
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
        let azimuths = if ax == ay { 1 } else { AZIMUTHS };
        let side = |z: f64| {
            AlbedoTable::from_fn_azimuthal(DIELECTRIC_NODES, azimuths, |mu, phi| {
                let st = ((1.0 - mu) * (1.0 + mu)).sqrt();
                let (sp, cp) = phi.sin_cos();
                let (r, t) = crate::scattering::albedo::single_scattering_albedo_dielectric_level(
                    dist,
                    [st * cp, st * sp, z * mu],
                    eta,
                    crate::bsdf::Masking::Correlated,
                    3,
                );
                r + t
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
fn table_of<F: Real, D: MicrofacetDistribution<F>, T, E>(
    dist: &D,
    cache: &'static TableCache<T>,
    extra: u64,
    shipped: impl FnOnce(NdfKind, Option<f64>, f64) -> Option<T>,
    compute: impl FnOnce(&AnyMicrofacet<f64>) -> Result<T, E>,
    widened: impl FnOnce() -> Result<T, E>,
) -> Result<Arc<T>, E> {
    let (ax, ay) = (dist.alpha().0.to_f64(), dist.alpha().1.to_f64());
    let Some((kind, shape)) = dist.ndf() else {
        return widened().map(Arc::new);
    };
    if ax == ay {
        if let Some(t) = shipped(kind, shape, ax) {
            return Ok(Arc::new(t));
        }
    }
    let bits = shape.unwrap_or(0.0).to_bits();
    let key = (kind, bits, ax.to_bits(), ay.to_bits(), extra);
    // (An Err, a cancelled computation, is not cached.)
    cached(cache, key, || {
        match AnyMicrofacet::<f64>::new(kind, ax, ay, shape) {
            Ok(twin) => compute(&twin),
            Err(_) => widened(),
        }
    })
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
