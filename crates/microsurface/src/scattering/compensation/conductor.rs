//! The compensated rough conductor.

// `!(x > 0)` is the NaN-aware test (false for NaN), on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::tables::AlbedoTable;
use super::Scheme;
use crate::bsdf::fresnel::Fresnel;
use crate::bsdf::{Bsdf, BsdfSample, Lobe, RoughConductor};
use crate::distribution::MicrofacetDistribution;
use crate::math::real::Real;
use std::sync::Arc;

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
    /// material the library does not ship (tens to hundreds of milliseconds, once per
    /// material and process: the table is cached and shared by every Fresnel term and scheme
    /// of the material).
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
                let e = table.e_avg();
                fresnel.average().map(|f| f * f * e / (1.0 - f * (1.0 - e)))
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

    /// Kulla–Conty's lobe f_ms(wo, wi) without F_ms (0 unless both are off the horizon):
    /// (1 − E(wo))(1 − E(wi))/(π(1 − E_avg)), E of the direction (its azimuth too, for an
    /// anisotropic material), whose integral against cos θi is 1 − E(wo) exactly.
    fn f_ms(&self, wo: [f64; 3], wi: [f64; 3]) -> f64 {
        if !(wo[2].abs() > 0.0 && wi[2].abs() > 0.0) {
            return 0.0;
        }
        let (eo, ei) = (self.table.e_dir(wo), self.table.e_dir(wi));
        // (The clamped lobe and its own normalisation: f ≥ 0 where the interpolant overshoots
        // 1, and the lobe still integrates to 1 − E(μo).)
        let den = std::f64::consts::PI * self.table.lost_avg();
        if !(den > 0.0) {
            return 0.0;
        }
        (1.0 - eo).max(0.0) * (1.0 - ei).max(0.0) / den
    }

    /// Kulla–Conty's probability of sampling the added lobe: 1 − E(wo), its share of the
    /// energy with F = 1.
    fn p_ms(&self, wo: [f64; 3]) -> f64 {
        (1.0 - self.table.e_dir(wo)).clamp(0.0, 1.0)
    }
}

impl<F: Real, D: MicrofacetDistribution<F>, Fr: Fresnel<F, N>, const N: usize> Bsdf<F>
    for CompensatedConductor<F, D, Fr, N>
{
    type Value = [F; N];

    fn eval(&self, wo: [F; 3], wi: [F; 3]) -> [F; N] {
        let f = self.ss.eval(wo, wi).map(F::to_f64);
        let (wo64, wi64) = (wo.map(F::to_f64), wi.map(F::to_f64));
        let (zo, zi) = (wo64[2], wi64[2]);
        match self.scheme {
            Scheme::Turquin => {
                let e = self.table.e_dir(wo64);
                std::array::from_fn(|c| F::from_f64(f[c] * (1.0 + self.factor[c] * (1.0 - e) / e)))
            }
            Scheme::KullaConty => {
                // (Both sides as the single-scattering lobe: wo and wi in one hemisphere.)
                let ms = if zo * zi > 0.0 {
                    self.f_ms(wo64, wi64)
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
                let q = self.p_ms(wo.map(F::to_f64));
                let cos = if zo * zi > 0.0 { zi.abs() } else { 0.0 };
                F::from_f64((1.0 - q) * p.to_f64() + q * cos / std::f64::consts::PI)
            }
        }
    }

    fn sample(&self, wo: [F; 3], uc: F, u: [F; 2]) -> Option<BsdfSample<F, [F; N]>> {
        // (As the single-scattering lobe: wo on the horizon is a rejected sample.)
        if crate::bsdf::on_horizon(wo[2]) {
            return None;
        }
        match self.scheme {
            Scheme::Turquin => {
                let s = self.ss.sample(wo, uc, u)?;
                if s.specular {
                    return Some(s);
                }
                // The sample's own f scaled (eval at its wi would recompute the half vector,
                // which can round onto a singular NDF's pole: f = ∞ with the sample's finite
                // pdf, Erfc at α = 0.057).
                let e = self.table.e_dir(wo.map(F::to_f64));
                let f = std::array::from_fn(|c| {
                    F::from_f64(s.f[c].to_f64() * (1.0 + self.factor[c] * (1.0 - e) / e))
                });
                if !f.iter().all(|x: &F| x.to_f64().is_finite()) {
                    return None;
                }
                Some(BsdfSample { f, ..s })
            }
            Scheme::KullaConty => {
                let q = self.p_ms(wo.map(F::to_f64));
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
                if !crate::bsdf::usable(pdf) {
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
