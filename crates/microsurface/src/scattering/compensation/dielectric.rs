//! The compensated rough dielectric.

// `!(x > 0)` is the NaN-aware test (false for NaN), on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::tables::{AlbedoTable, DielectricTables};
use super::Scheme;
use crate::bsdf::fresnel::dielectric_average;
use crate::bsdf::{Bsdf, BsdfSample, Lobe, RoughDielectric, Transport};
use crate::distribution::MicrofacetDistribution;
use crate::math::real::Real;
use std::sync::Arc;

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
///
/// The single-scattering lobes have the default G2 ([`crate::bsdf::Masking::Correlated`]),
/// the one the tables are computed for (shipped and computed alike), so the type offers no
/// other masking: compensating [`crate::bsdf::Masking::CorrelatedBeta`]'s much smaller
/// grazing transmission would need its own tables.
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
    /// (under a second isotropic, once per (material, η) and process: the tables are cached).
    /// [`crate::ParamError::Eta`] for η NaN, infinite or ≤ 0.
    pub fn new(dist: D, eta: F, scheme: Scheme) -> Result<Self, crate::ParamError> {
        crate::error::check_eta(eta.to_f64())?;
        let tables = DielectricTables::new(&dist, eta.to_f64());
        Self::from_tables(dist, eta, scheme, tables)
    }

    /// The same with tables computed before (they must be `dist`'s at this η). No
    /// computation. [`crate::ParamError::Eta`] for η NaN, infinite or ≤ 0, as
    /// [`RoughDielectric::new`].
    pub fn from_tables(
        dist: D,
        eta: F,
        scheme: Scheme,
        tables: impl Into<Arc<DielectricTables>>,
    ) -> Result<Self, crate::ParamError> {
        let tables = tables.into();
        let smooth = eta == F::ONE || dist.effectively_smooth();
        let eta64 = eta.to_f64();
        let (lo, li) = (tables.outside.lost_avg(), tables.inside.lost_avg());
        let k_out = 1.0 - dielectric_average(eta64);
        let mut k = [k_out, k_out * lo / (eta64 * eta64 * li)];
        if !(k[1] <= 1.0) {
            // (Also a lossless side, li = 0, whose lobes are 0 anyway.)
            let s = if k[1] > 1.0 { 1.0 / k[1] } else { 0.0 };
            k = [k[0] * s, k[1] * s];
        }
        Ok(CompensatedDielectric {
            ss: RoughDielectric::new(dist, eta)?,
            tables,
            scheme,
            k,
            transport: Transport::Radiance,
            smooth,
        })
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

    /// Kulla–Conty's transmitted shares (k_out, k_in), as this interface uses them (scaled
    /// together where k_in would pass 1), and the smooth interface's Fresnel average
    /// F_avg(η) = 2∫F(μ)μ dμ from outside that k_out = 1 − F_avg comes from: the numbers a
    /// GPU form of the type takes (`microsurface-gpu`'s tests feed them to its WGSL). Not part
    /// of the stable API.
    #[doc(hidden)]
    pub fn kulla_conty_shares(&self) -> ([f64; 2], f64) {
        (self.k, dielectric_average(self.ss.eta().to_f64()))
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
        let lost = 1.0 - self.table(s).e_dir(wo);
        let crossed = (wi[2] < 0.0) != (wo[2] < 0.0);
        let t = if crossed { 1 - s } else { s };
        let share = if crossed { self.k[s] } else { 1.0 - self.k[s] };
        let den = std::f64::consts::PI * self.table(t).lost_avg();
        if !(den > 0.0 && lost > 0.0) {
            return 0.0;
        }
        let f = share * lost * (1.0 - self.table(t).e_dir(wi)).max(0.0) / den;
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
        (1.0 - self.table(s).e_dir(wo)).clamp(0.0, 1.0)
    }

    /// Turquin's factor 1/E_s(μo).
    fn scale(&self, wo: [f64; 3]) -> f64 {
        let s = usize::from(wo[2] < 0.0);
        let e = self.table(s).e_dir(wo);
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
        // (As the single-scattering interface: wo on the horizon is a rejected sample.)
        if crate::bsdf::on_horizon(wo[2]) {
            return None;
        }
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
                if !crate::bsdf::usable(pdf) || wi[2] == F::ZERO {
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
