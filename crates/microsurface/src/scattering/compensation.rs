//! Energy compensation: see the [`crate::scattering`] docs.

// `!(x > 0)` is the NaN-aware test (false for NaN), on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::bsdf::fresnel::Fresnel;
use crate::bsdf::{Bsdf, BsdfSample, Lobe, RoughConductor, RoughDielectric, Transport};
use crate::distribution::{cached, FitCache, MicrofacetDistribution, Sample};
use crate::fast::Real;
use crate::scattering::table::Grid;
use crate::scattering::walk::single_scattering_albedo_tol;
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
const GL8: [(f64, f64); 8] = [
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
    /// materials in their range, else **computed** ([`AlbedoTable::compute`], 30–300 ms) on
    /// the material's f64 twin (the same NDF, α and shape through [`crate::AnyMicrofacet`];
    /// a distribution that does not name its NDF, [`MicrofacetDistribution::ndf`], is evaluated in its
    /// own precision). Computed tables of the library's materials are cached for the
    /// process, so the compensated BSDFs of one material share one table.
    pub fn new<F: Real, D: MicrofacetDistribution<F>>(dist: &D) -> Arc<Self> {
        static TABLES: FitCache<(NdfKind, u64, u64, u64), AlbedoTable> = OnceLock::new();
        let (ax, ay) = (dist.alpha().0.to_f64(), dist.alpha().1.to_f64());
        let Some((kind, shape)) = dist.ndf() else {
            return Arc::new(Self::compute(&Widened(dist, PhantomData)));
        };
        if ax == ay {
            if let Some(t) = Self::shipped(kind, shape, ax) {
                return Arc::new(t);
            }
        }
        let key = (
            kind,
            shape.unwrap_or(0.0).to_bits(),
            ax.to_bits(),
            ay.to_bits(),
        );
        let made: Result<_, std::convert::Infallible> = cached(&TABLES, key, || {
            Ok(match AnyMicrofacet::<f64>::new(kind, ax, ay, shape) {
                Ok(twin) => Self::compute(&twin),
                Err(_) => Self::compute(&Widened(dist, PhantomData)),
            })
        });
        match made {
            Ok(t) => t,
        }
    }

    /// The table of `dist` computed here: 33 quadratures of the single-scattering albedo
    /// (measured, GGX and the Exponential NDF: 30–130 ms at α ≥ 0.3, 260–310 ms at α = 0.05,
    /// where the lobe is narrow).
    pub fn compute<D: MicrofacetDistribution<f64>>(dist: &D) -> Self {
        let (ax, ay) = dist.alpha();
        let azimuths: &[f64] = if ax == ay {
            &[0.0]
        } else {
            &[0.0, 0.25, 0.5, 0.75]
        };
        Self::from_fn(|mu| {
            let st = ((1.0 - mu) * (1.0 + mu)).sqrt();
            azimuths
                .iter()
                .map(|&p| {
                    let (sp, cp) = (p * std::f64::consts::FRAC_PI_2).sin_cos();
                    single_scattering_albedo_tol(dist, [st * cp, st * sp, mu], TABLE_TOL)
                })
                .sum::<f64>()
                / azimuths.len() as f64
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
    include_bytes!("../../data/compensation/beckmann.mfa"),
    include_bytes!("../../data/compensation/ggx.mfa"),
    include_bytes!("../../data/compensation/double_ggx.mfa"),
    include_bytes!("../../data/compensation/exponential.mfa"),
    include_bytes!("../../data/compensation/gtr1.mfa"),
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

/// Which compensation: see the [module docs](crate::scattering).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scheme {
    /// An added diffuse-like lobe (Kulla & Conty 2017).
    KullaConty,
    /// The single-scattering lobe scaled (Turquin 2019).
    Turquin,
}

/// A rough conductor with its lost energy put back: [`Bsdf`] like the single-scattering
/// [`RoughConductor`] (f32 or f64; the table and the added lobe in f64), whose F = 1 white
/// furnace is 1 within the table's interpolation error.
#[derive(Clone, Debug)]
pub struct CompensatedConductor<F, D, Fr, const N: usize> {
    ss: RoughConductor<F, D, Fr, N>,
    table: Arc<AlbedoTable>,
    scheme: Scheme,
    /// Kulla–Conty's F_ms per channel; Turquin's F0.
    factor: [f64; N],
}

impl<F: Real, D: MicrofacetDistribution<F>, Fr: Fresnel<F, N>, const N: usize>
    CompensatedConductor<F, D, Fr, N>
{
    /// The compensated conductor of `dist` and `fresnel` (height-correlated G2), with
    /// [`AlbedoTable::new`]'s table: shipped (microseconds), or **computed here** for a
    /// material the library does not ship (30–300 ms, once per material and process: the
    /// table is cached and shared by every Fresnel term and scheme of the material).
    pub fn new(dist: D, fresnel: Fr, scheme: Scheme) -> Self {
        let table = AlbedoTable::new(&dist);
        Self::from_table(dist, fresnel, scheme, table)
    }

    /// The same with a table built before (one table serves every Fresnel term and scheme
    /// of a distribution; it must be `dist`'s). No computation.
    pub fn from_table(
        dist: D,
        fresnel: Fr,
        scheme: Scheme,
        table: impl Into<Arc<AlbedoTable>>,
    ) -> Self {
        let table = table.into();
        let eval = |mu: f64| fresnel.eval(F::from_f64(mu)).map(F::to_f64);
        let factor = match scheme {
            Scheme::Turquin => eval(1.0),
            Scheme::KullaConty => {
                // F_avg = 2∫F(μ)μ dμ, 8-point Gauss–Legendre on 16 intervals.
                let mut f_avg = [0.0; N];
                for k in 0..16 {
                    for (x, w) in GL8 {
                        let mu = (k as f64 + x) / 16.0;
                        let f = eval(mu);
                        for c in 0..N {
                            f_avg[c] += 2.0 * w / 16.0 * f[c] * mu;
                        }
                    }
                }
                let e = table.e_avg();
                f_avg.map(|f| f * f * e / (1.0 - f * (1.0 - e)))
            }
        };
        CompensatedConductor {
            ss: RoughConductor::new(dist, fresnel),
            table,
            scheme,
            factor,
        }
    }

    /// The albedo table.
    pub fn table(&self) -> &Arc<AlbedoTable> {
        &self.table
    }

    /// The single-scattering conductor underneath.
    pub fn single_scattering(&self) -> &RoughConductor<F, D, Fr, N> {
        &self.ss
    }

    /// Kulla–Conty's lobe f_ms(μo, μi) without F_ms (0 unless both are above the surface).
    fn f_ms(&self, mu_o: f64, mu_i: f64) -> f64 {
        if !(mu_o > 0.0 && mu_i > 0.0) {
            return 0.0;
        }
        let (eo, ei) = (self.table.e(mu_o), self.table.e(mu_i));
        // (The clamped lobe and its own normalisation: f ≥ 0 where the interpolant overshoots
        // 1, and the lobe still integrates to 1 − E(μo).)
        let den = std::f64::consts::PI * self.table.lost_avg();
        if !(den > 0.0) {
            return 0.0;
        }
        (1.0 - eo).max(0.0) * (1.0 - ei).max(0.0) / den
    }

    /// Kulla–Conty's probability of sampling the added lobe: 1 − E(μo), its share of the
    /// energy with F = 1.
    fn p_ms(&self, mu_o: f64) -> f64 {
        (1.0 - self.table.e(mu_o)).clamp(0.0, 1.0)
    }
}

impl<F: Real, D: MicrofacetDistribution<F>, Fr: Fresnel<F, N>, const N: usize> Bsdf<F>
    for CompensatedConductor<F, D, Fr, N>
{
    type Value = [F; N];

    fn eval(&self, wo: [F; 3], wi: [F; 3]) -> [F; N] {
        let f = self.ss.eval(wo, wi).map(F::to_f64);
        let (zo, zi) = (wo[2].to_f64(), wi[2].to_f64());
        match self.scheme {
            Scheme::Turquin => {
                let e = self.table.e(zo.abs());
                std::array::from_fn(|c| F::from_f64(f[c] * (1.0 + self.factor[c] * (1.0 - e) / e)))
            }
            Scheme::KullaConty => {
                // (Both sides as the single-scattering lobe: wo and wi in one hemisphere.)
                let ms = if zo * zi > 0.0 {
                    self.f_ms(zo.abs(), zi.abs())
                } else {
                    0.0
                };
                std::array::from_fn(|c| F::from_f64(f[c] + ms * self.factor[c]))
            }
        }
    }

    fn pdf(&self, wo: [F; 3], wi: [F; 3]) -> F {
        let p = self.ss.pdf(wo, wi);
        match self.scheme {
            Scheme::Turquin => p,
            Scheme::KullaConty => {
                let (zo, zi) = (wo[2].to_f64(), wi[2].to_f64());
                let q = self.p_ms(zo.abs());
                let cos = if zo * zi > 0.0 { zi.abs() } else { 0.0 };
                F::from_f64((1.0 - q) * p.to_f64() + q * cos / std::f64::consts::PI)
            }
        }
    }

    fn sample(&self, wo: [F; 3], uc: F, u: [F; 2]) -> Option<BsdfSample<F, [F; N]>> {
        match self.scheme {
            Scheme::Turquin => {
                let s = self.ss.sample(wo, uc, u)?;
                if s.specular {
                    return Some(s);
                }
                let f = self.eval(wo, s.wi);
                Some(BsdfSample { f, ..s })
            }
            Scheme::KullaConty => {
                let q = self.p_ms(wo[2].to_f64().abs());
                let uc = uc.to_f64();
                let wi = if uc < q {
                    // A cosine-weighted direction on wo's side.
                    let [x, y, z] = crate::bsdf::frame::cosine_hemisphere(u.map(F::to_f64));
                    [x, y, if wo[2] < F::ZERO { -z } else { z }].map(F::from_f64)
                } else {
                    let s = self.ss.sample(wo, F::from_f64((uc - q) / (1.0 - q)), u)?;
                    if s.specular {
                        return Some(s);
                    }
                    s.wi
                };
                let pdf = self.pdf(wo, wi);
                if !(pdf > F::ZERO && pdf.to_f64().is_finite()) {
                    return None;
                }
                Some(BsdfSample {
                    wi,
                    f: self.eval(wo, wi),
                    pdf,
                    lobe: Lobe::Reflection,
                    specular: false,
                    eta: F::ONE,
                })
            }
        }
    }
}

/// The tables of a rough dielectric interface (relative index η = η_inside/η_outside): the
/// single-scattering albedo, reflection plus transmission, from outside (η) and from inside
/// (1/η), [`crate::scattering::single_scattering_albedo_dielectric`] at 65 nodes uniform in √μ
/// (twice a conductor's), at the rule's level 3 (within 1.2e-4 of level 7 in the worst case
/// measured, Double GGX; the furnace stays within 1e-3 with it). Shipped for the library's
/// isotropic materials at the common indices [`SHIPPED_ETAS`] ([`DielectricTables::new`]);
/// computed otherwise: 130 quadratures, measured 0.5–0.8 s for an isotropic material, four
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
    /// else **computed** ([`DielectricTables::compute`], 0.5–0.8 s isotropic) on the
    /// material's f64 twin, as [`AlbedoTable::new`], and cached for the process by
    /// (material, η).
    pub fn new<F: Real, D: MicrofacetDistribution<F>>(dist: &D, eta: f64) -> Arc<Self> {
        type Key = (NdfKind, u64, u64, u64, u64);
        static TABLES: FitCache<Key, DielectricTables> = OnceLock::new();
        let (ax, ay) = (dist.alpha().0.to_f64(), dist.alpha().1.to_f64());
        let Some((kind, shape)) = dist.ndf() else {
            return Arc::new(Self::compute(&Widened(dist, PhantomData), eta));
        };
        if ax == ay {
            if let Some(t) = Self::shipped(kind, shape, ax, eta) {
                return Arc::new(t);
            }
        }
        let bits = shape.unwrap_or(0.0).to_bits();
        let key = (kind, bits, ax.to_bits(), ay.to_bits(), eta.to_bits());
        let made: Result<_, std::convert::Infallible> = cached(&TABLES, key, || {
            Ok(match AnyMicrofacet::<f64>::new(kind, ax, ay, shape) {
                Ok(twin) => Self::compute(&twin, eta),
                Err(_) => Self::compute(&Widened(dist, PhantomData), eta),
            })
        });
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
    /// features that move with η, see the notes of issue 21), α outside the range or
    /// other NDFs. Equal to a computed table at the α nodes (to f32 rounding, 4e-8) and
    /// within 2e-4 between them (1.7e-4 measured for GGX and Beckmann at α = 2.9, seen from
    /// inside at grazing μ; 1e-5 or less at α ≤ 0.6; tests/compensate.rs).
    pub fn shipped(kind: NdfKind, gamma: Option<f64>, alpha: f64, eta: f64) -> Option<Self> {
        let file = shipped_file(kind, gamma)?;
        // (A relative 1e-12 of slack: an η written with its digits.)
        let matches = |x: f64| (x - eta).abs() <= 1e-12 * x;
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
                            crate::scattering::walk::single_scattering_albedo_dielectric_level(
                                dist,
                                [st * cp, st * sp, z * mu],
                                eta,
                                crate::scattering::walk::G2Form::Approximate,
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
    include_bytes!("../../data/compensation/beckmann-dielectric.mfd"),
    include_bytes!("../../data/compensation/ggx-dielectric.mfd"),
    include_bytes!("../../data/compensation/double_ggx-dielectric.mfd"),
    include_bytes!("../../data/compensation/exponential-dielectric.mfd"),
    include_bytes!("../../data/compensation/gtr1-dielectric.mfd"),
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

/// F_avg = 2∫F(μ)μ dμ of the dielectric Fresnel term at relative index η (from the side
/// where the ray meets η). Below the critical angle (η < 1: μ < μc = √(1 − η²)) F = 1 and
/// contributes μc²; above it μ = μc + (1 − μc)t² removes F's square-root edge at μc, and
/// 8-point Gauss–Legendre on 32 intervals in t is exact to 1e-20 (against mpmath, η = 1.5,
/// 1/1.5, 2.42, 1/2.42, 1/1.05; without the split the kink cost 2e-4).
fn dielectric_f_avg(eta: f64) -> f64 {
    let mc = if eta < 1.0 {
        ((1.0 - eta) * (1.0 + eta)).sqrt()
    } else {
        0.0
    };
    let mut f_avg = mc * mc;
    for k in 0..32 {
        for (x, w) in GL8 {
            let t = (k as f64 + x) / 32.0;
            let mu = mc + (1.0 - mc) * t * t;
            f_avg += 2.0 * w / 32.0
                * crate::bsdf::fresnel::dielectric(mu, eta)
                * mu
                * (1.0 - mc)
                * 2.0
                * t;
        }
    }
    f_avg
}

/// A rough dielectric with its lost energy put back: [`Bsdf`] like the single-scattering
/// [`RoughDielectric`] (f32 or f64, grey f in N channels; the tables and the added lobes in
/// f64), whose white furnace (reflection plus transmission, importance
/// transport) is 1 from both sides within the tables' interpolation error.
///
/// * **Kulla & Conty 2017**, two-sided: from side s (outside or inside) the lost energy
///   1 − E_s(μo) is split into a reflected share 1 − k_s, lobe
///   (1 − k_s)(1 − E_s(μo))(1 − E_s(μi))/(π(1 − E_avg,s)), and a transmitted share k_s, lobe
///   k_s(1 − E_s(μo))(1 − E_s̄(μi))/(π(1 − E_avg,s̄)) (s̄ the other side), each of which
///   integrates to its share. k_out = 1 − F_avg(η), the share a smooth interface transmits
///   on average; k_in follows from reciprocity, which for importance transport is
///   f(out → in) = η² f(in → out): k_in = k_out (1 − E_avg,out)/(η²(1 − E_avg,in)); where
///   that exceeds 1 both are scaled down together. With radiance transport the transmitted
///   lobe is divided by η'², as [`RoughDielectric`]'s.
/// * **Turquin 2019**: the single-scattering lobes scaled by 1/E_s(μo) (a dielectric keeps
///   all its energy, so the factor 1 + F0(1 − E)/E of the conductor becomes 1/E); sampling
///   is the single-scattering lobes'; not reciprocal (nor is Turquin's conductor).
///
/// Sampling (Kulla–Conty): the added lobes with probability 1 − E_s(μo) (transmission
/// within them with probability k_s), cosine-weighted on their side; the single-scattering
/// lobes otherwise. An interface at η = 1 or in the smooth limit is the single-scattering
/// one (its delta lobes lose nothing).
#[derive(Clone, Debug)]
pub struct CompensatedDielectric<F, D, const N: usize = 3> {
    ss: RoughDielectric<F, D, N>,
    tables: Arc<DielectricTables>,
    scheme: Scheme,
    /// k_out, k_in.
    k: [f64; 2],
    transport: Transport,
    smooth: bool,
}

impl<F: Real, D: MicrofacetDistribution<F>> CompensatedDielectric<F, D, 3> {
    /// The compensated interface of `dist` at relative index η (> 0), radiance transport, f
    /// in three (RGB) channels, with [`DielectricTables::new`]'s tables: shipped
    /// (microseconds), or **computed here** for a material or η the library does not ship
    /// (0.5–0.8 s isotropic, once per (material, η) and process: the tables are cached).
    pub fn new(dist: D, eta: F, scheme: Scheme) -> Self {
        let tables = DielectricTables::new(&dist, eta.to_f64());
        Self::from_tables(dist, eta, scheme, tables)
    }

    /// The same with tables computed before (they must be `dist`'s at this η). No
    /// computation.
    pub fn from_tables(
        dist: D,
        eta: F,
        scheme: Scheme,
        tables: impl Into<Arc<DielectricTables>>,
    ) -> Self {
        let tables = tables.into();
        let smooth = eta == F::ONE || dist.effectively_smooth();
        let eta64 = eta.to_f64();
        let (lo, li) = (tables.outside.lost_avg(), tables.inside.lost_avg());
        let k_out = 1.0 - dielectric_f_avg(eta64);
        let mut k = [k_out, k_out * lo / (eta64 * eta64 * li)];
        if !(k[1] <= 1.0) {
            // (Also a lossless side, li = 0, whose lobes are 0 anyway.)
            let s = if k[1] > 1.0 { 1.0 / k[1] } else { 0.0 };
            k = [k[0] * s, k[1] * s];
        }
        CompensatedDielectric {
            ss: RoughDielectric::new(dist, eta),
            tables,
            scheme,
            k,
            transport: Transport::Radiance,
            smooth,
        }
    }
}

impl<F: Real, D: MicrofacetDistribution<F>, const N: usize> CompensatedDielectric<F, D, N> {
    /// The same interface with f in M channels.
    pub fn with_channels<const M: usize>(self) -> CompensatedDielectric<F, D, M> {
        CompensatedDielectric {
            ss: self.ss.with_channels(),
            tables: self.tables,
            scheme: self.scheme,
            k: self.k,
            transport: self.transport,
            smooth: self.smooth,
        }
    }

    /// The same for the other transport direction.
    pub fn with_transport(mut self, transport: Transport) -> Self {
        self.ss = self.ss.with_transport(transport);
        self.transport = transport;
        self
    }

    /// The tables.
    pub fn tables(&self) -> &Arc<DielectricTables> {
        &self.tables
    }

    /// The single-scattering interface underneath.
    pub fn single_scattering(&self) -> &RoughDielectric<F, D, N> {
        &self.ss
    }

    /// The table of a side (0 outside, 1 inside).
    fn table(&self, side: usize) -> &AlbedoTable {
        if side == 0 {
            &self.tables.outside
        } else {
            &self.tables.inside
        }
    }

    /// Kulla–Conty's added f(wo, wi): the reflected lobe of wo's side, or the transmitted one
    /// (divided by η'² for radiance transport).
    fn f_ms(&self, wo: [f64; 3], wi: [f64; 3]) -> f64 {
        let (mo, mi) = (wo[2].abs(), wi[2].abs());
        if !(mo > 0.0 && mi > 0.0) {
            return 0.0;
        }
        let s = usize::from(wo[2] < 0.0);
        let lost = 1.0 - self.table(s).e(mo);
        let crossed = (wi[2] < 0.0) != (wo[2] < 0.0);
        let t = if crossed { 1 - s } else { s };
        let share = if crossed { self.k[s] } else { 1.0 - self.k[s] };
        let den = std::f64::consts::PI * self.table(t).lost_avg();
        if !(den > 0.0 && lost > 0.0) {
            return 0.0;
        }
        let f = share * lost * (1.0 - self.table(t).e(mi)).max(0.0) / den;
        if crossed && self.transport == Transport::Radiance {
            let eta = self.ss.eta().to_f64();
            let etap = if s == 0 { eta } else { 1.0 / eta };
            f / (etap * etap)
        } else {
            f
        }
    }

    /// Kulla–Conty's probability of sampling the added lobes: 1 − E_s(μo).
    fn p_ms(&self, wo: [f64; 3]) -> f64 {
        let s = usize::from(wo[2] < 0.0);
        (1.0 - self.table(s).e(wo[2].abs())).clamp(0.0, 1.0)
    }

    /// Turquin's factor 1/E_s(μo).
    fn scale(&self, wo: [f64; 3]) -> f64 {
        let s = usize::from(wo[2] < 0.0);
        let e = self.table(s).e(wo[2].abs());
        if e > 0.0 {
            1.0 / e
        } else {
            1.0
        }
    }

    /// The density of a cosine-weighted direction on wi's side, times the probability of
    /// that side within the added lobes.
    fn pdf_ms(&self, wo: [f64; 3], wi: [f64; 3]) -> f64 {
        let s = usize::from(wo[2] < 0.0);
        let crossed = (wi[2] < 0.0) != (wo[2] < 0.0);
        let side = if crossed { self.k[s] } else { 1.0 - self.k[s] };
        side * wi[2].abs() / std::f64::consts::PI
    }

    /// f in one channel.
    fn eval_grey(&self, wo: [F; 3], wi: [F; 3]) -> F {
        let f = self.ss.eval_grey(wo, wi);
        if self.smooth {
            return f;
        }
        let (o, i) = (wo.map(F::to_f64), wi.map(F::to_f64));
        F::from_f64(match self.scheme {
            Scheme::Turquin => f.to_f64() * self.scale(o),
            Scheme::KullaConty => f.to_f64() + self.f_ms(o, i),
        })
    }

    /// A sample with f in one channel.
    fn sample_grey(&self, wo: [F; 3], uc: F, u: [F; 2]) -> Option<BsdfSample<F, F>> {
        if self.smooth {
            return self.ss.sample_grey(wo, uc, u);
        }
        let o = wo.map(F::to_f64);
        match self.scheme {
            Scheme::Turquin => {
                let s = self.ss.sample_grey(wo, uc, u)?;
                Some(BsdfSample {
                    f: F::from_f64(s.f.to_f64() * self.scale(o)),
                    ..s
                })
            }
            Scheme::KullaConty => {
                let q = self.p_ms(o);
                let ucf = uc.to_f64();
                let wi = if ucf < q {
                    // The added lobes: the side by k_s, then a cosine-weighted direction.
                    let s = usize::from(o[2] < 0.0);
                    let v = ucf / q;
                    let crossed = v < self.k[s];
                    let [x, y, z] = crate::bsdf::frame::cosine_hemisphere(u.map(F::to_f64));
                    let up = (o[2] > 0.0) != crossed;
                    [x, y, if up { z } else { -z }].map(F::from_f64)
                } else {
                    let s = self
                        .ss
                        .sample_grey(wo, F::from_f64((ucf - q) / (1.0 - q)), u)?;
                    s.wi
                };
                let pdf = self.pdf(wo, wi);
                if !(pdf > F::ZERO && pdf.to_f64().is_finite()) || wi[2] == F::ZERO {
                    return None;
                }
                let crossed = (wi[2] < F::ZERO) != (wo[2] < F::ZERO);
                let eta = self.ss.eta();
                Some(BsdfSample {
                    wi,
                    f: self.eval_grey(wo, wi),
                    pdf,
                    lobe: if crossed {
                        Lobe::Transmission
                    } else {
                        Lobe::Reflection
                    },
                    specular: false,
                    eta: match (crossed, wo[2] > F::ZERO) {
                        (false, _) => F::ONE,
                        (true, true) => eta,
                        (true, false) => F::ONE / eta,
                    },
                })
            }
        }
    }
}

impl<F: Real, D: MicrofacetDistribution<F>, const N: usize> Bsdf<F>
    for CompensatedDielectric<F, D, N>
{
    type Value = [F; N];

    fn eval(&self, wo: [F; 3], wi: [F; 3]) -> [F; N] {
        [self.eval_grey(wo, wi); N]
    }

    fn pdf(&self, wo: [F; 3], wi: [F; 3]) -> F {
        let p = self.ss.pdf_grey(wo, wi);
        if self.smooth || self.scheme == Scheme::Turquin {
            return p;
        }
        let (o, i) = (wo.map(F::to_f64), wi.map(F::to_f64));
        let q = self.p_ms(o);
        F::from_f64((1.0 - q) * p.to_f64() + q * self.pdf_ms(o, i))
    }

    fn sample(&self, wo: [F; 3], uc: F, u: [F; 2]) -> Option<BsdfSample<F, [F; N]>> {
        self.sample_grey(wo, uc, u).map(|s| s.map_f(|f| [f; N]))
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

#[cfg(test)]
mod tests {
    use super::dielectric_f_avg;

    /// The hemispherical Fresnel average against the reciprocity of the averaged
    /// transmittance, 1 − F_avg(1/η) = (1 − F_avg(η))/η² (the kink at the critical angle
    /// is on the 1/η side), and against values integrated with mpmath (30 digits).
    #[test]
    fn fresnel_average() {
        for eta in [1.05, 1.33, 1.5, 2.42, 3.0] {
            let (out, inside) = (dielectric_f_avg(eta), dielectric_f_avg(1.0 / eta));
            assert!(
                ((1.0 - inside) - (1.0 - out) / (eta * eta)).abs() < 1e-14,
                "η={eta}: {out} {inside}"
            );
        }
        for (eta, want) in [
            (1.5, 0.091_777_959_342_351_21),
            (1.0 / 1.5, 0.596_345_759_707_711_8),
            (2.42, 0.212_540_794_738_842_13),
            (1.0 / 2.42, 0.865_538_691_813_886),
        ] {
            assert!((dielectric_f_avg(eta) - want).abs() < 1e-15, "η={eta}");
        }
    }
}
