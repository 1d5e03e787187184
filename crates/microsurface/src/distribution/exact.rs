//! [`Exact`], the validated f64 path of every NDF: see the [`crate::distribution`] docs.

// `!(x > 0)` is the NaN-aware test (false for NaN) on a generic `Real`, on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::kernels::{Isotropic, Microsurface, Shaped, Stretched};
use super::{MicrofacetDistribution, Sample};
use crate::math::vec3::Vec3;
use crate::sampling::visible::UnitSlopes;
use crate::{Gtr, ParamError};

/// The exact path of a [`Microfacet`] material (f64): see [`Microfacet::exact`].
///
/// [`Microfacet`]: crate::Microfacet
/// [`Microfacet::exact`]: crate::Microfacet::exact
#[derive(Clone, Copy, Debug)]
pub struct Exact {
    pub(super) alpha: (f64, f64),
    pub(super) inner: ExactInner,
}

#[derive(Clone, Copy, Debug)]
pub(super) enum ExactInner {
    Stretched(Stretched),
    Gtr(Isotropic<Gtr>),
    Shaped(Shaped),
}

impl Exact {
    /// The exact path of NDF `kind` at roughness (αx, αy) with its shape parameter `gamma`
    /// where it has one ([`crate::NdfKind::shape_name`]: γ of GTR, Student-T and the
    /// generalised exponential, a of Bessel-K), for an NDF chosen at run time (command lines,
    /// sweeps); [`Microfacet::exact`] is the same for a material built at compile time. GTR:
    /// isotropic at γ ≠ 2, as [`Microfacet::gtr`]. The family's other NDFs (Student-T, Ei,
    /// Erfc, K0, Bessel-K, generalised exponential) are anisotropic by stretching, with visible
    /// normals by the exact slope-space inversion (quadratures: tens to hundreds of
    /// microseconds a sample, the most at grazing incidence; BENCHMARKS.md); Student-T needs
    /// γ > 3/2 here (Λ is infinite below; just above, most visible normals lie within 1e-300
    /// of the horizon: [`crate::sampling::radial`]). Typed errors as the constructors'.
    ///
    /// [`Microfacet::exact`]: crate::Microfacet::exact
    /// [`Microfacet::gtr`]: crate::Microfacet::gtr
    pub fn new(
        kind: crate::NdfKind,
        alpha_x: f64,
        alpha_y: f64,
        gamma: Option<f64>,
    ) -> Result<Exact, ParamError> {
        use crate::NdfKind as K;
        let (ax, ay) = (
            crate::error::check_alpha(alpha_x)?,
            crate::error::check_alpha(alpha_y)?,
        );
        let unit = match kind {
            K::Beckmann => UnitSlopes::Beckmann,
            K::Ggx => UnitSlopes::Ggx,
            K::DoubleGgx => UnitSlopes::DoubleGgx,
            K::Exponential => UnitSlopes::Exponential,
            K::StudentT | K::Ei | K::Erfc | K::K0 | K::BesselK | K::GenExponential => {
                let (unit, posterior) = shaped_unit(kind, gamma)?;
                return Ok(Exact {
                    alpha: (ax, ay),
                    inner: ExactInner::Shaped(Shaped::from_unit(unit, posterior, ax, ay)?),
                });
            }
            K::Gtr => {
                let gamma = crate::error::check_gamma(gamma.unwrap_or(f64::NAN))?;
                if gamma == 2.0 {
                    UnitSlopes::Ggx
                } else if ax != ay {
                    return Err(ParamError::Anisotropic(gamma));
                } else {
                    return Ok(Exact {
                        alpha: (ax, ay),
                        inner: ExactInner::Gtr(Isotropic(Gtr::new(ax, gamma)?)),
                    });
                }
            }
        };
        Ok(Exact::stretched(unit, ax, ay))
    }

    pub(super) fn stretched(kind: UnitSlopes, ax: f64, ay: f64) -> Exact {
        Exact {
            alpha: (ax, ay),
            inner: ExactInner::Stretched(Stretched::raw(kind, ax, ay)),
        }
    }

    /// The projected area σ(w) = ∫ max(0, w·m) D(m) dm = |w.z| (1 + Λ(w)) (finite at grazing,
    /// where it is σ(0) of the azimuth), for w mirrored to the upper hemisphere.
    pub fn sigma(&self, w: [f64; 3]) -> f64 {
        let w = Vec3::from(w);
        self.surface().sigma(if w.z < 0.0 { -w } else { w })
    }

    fn surface(&self) -> &dyn Microsurface {
        match &self.inner {
            ExactInner::Stretched(s) => s,
            ExactInner::Gtr(g) => g,
            ExactInner::Shaped(g) => g,
        }
    }

    /// The u that [`MicrofacetDistribution::sample`] maps to wm (the exact samplers are invertible
    /// warps); NaN for a normal no sampler returns.
    ///
    /// **Accuracy**: u to ~1e-15 wherever the sampled slope is representable. The one limit is
    /// Student-T just above γ = 3/2, whose visible slopes lie beyond f64 for most u (the
    /// size-biased prior Gamma(γ − 3/2) has its mass at β far below 1e-300): the sampler returns
    /// the normal at the largest slope it holds (wm.z ≈ 1e-150 and below), and the inverse
    /// returns the u of that normal, not the one drawn (measured: γ = 1.5001, α = 1.41, wo at
    /// 156°: 1480 of a 40² grid of u beyond it, γ = 1.500001 all; tests/hardening.rs).
    pub fn invert(&self, w: [f64; 3], wm: [f64; 3]) -> [f64; 2] {
        self.surface().invert_visible(Vec3::from(w), Vec3::from(wm))
    }

    /// The u that [`MicrofacetDistribution::sample_dcos`] maps to wm.
    pub fn invert_dcos(&self, wm: [f64; 3]) -> [f64; 2] {
        self.surface().invert_dcos(Vec3::from(wm))
    }
}

impl MicrofacetDistribution<f64> for Exact {
    fn alpha(&self) -> (f64, f64) {
        self.alpha
    }
    fn ndf(&self) -> Option<(crate::NdfKind, Option<f64>)> {
        Some(match &self.inner {
            ExactInner::Stretched(s) => (s.kind().kind(), None),
            ExactInner::Gtr(g) => (crate::NdfKind::Gtr, Some(g.0.gamma())),
            ExactInner::Shaped(g) => (g.unit().kind(), g.unit().shape()),
        })
    }
    fn d(&self, wm: [f64; 3]) -> f64 {
        self.surface().d(Vec3::from(wm))
    }
    fn lambda(&self, w: [f64; 3]) -> f64 {
        self.surface().lambda(Vec3::from(w))
    }
    fn sample_wm(&self, w: [f64; 3], u: [f64; 2]) -> [f64; 3] {
        self.surface()
            .sample_visible(Vec3::from(w), super::below_one(u))
            .into()
    }
    /// As the trait's: for the Beckmann mixtures of the family (Student-T, Ei, Erfc, K0,
    /// Bessel-K) above the horizon, the posterior of the mixing variable
    /// (`Shaped::sample_visible_stream`: ≤ 2 candidates on average, then Beckmann's stream
    /// sampler; Bessel-K's exact warp inverts a CDF that integrates K_ν); `None` otherwise.
    fn sample_wm_stream(&self, v: [f64; 3], uniform: &mut dyn FnMut() -> f64) -> Option<[f64; 3]> {
        match &self.inner {
            ExactInner::Shaped(s) => s
                .sample_visible_stream(Vec3::from(v), uniform)
                .map(Into::into),
            _ => None,
        }
    }
    fn sample_dcos(&self, u: [f64; 2]) -> Sample<f64> {
        let s = self.surface();
        let wm = s.sample_dcos(super::below_one(u));
        Sample {
            wm: wm.into(),
            pdf: s.pdf_dcos(wm),
        }
    }
    /// As the trait's, for w and wm of any finite nonzero length (normalised here), in the
    /// form max(0, w·wm) D(wm)/σ(w) (finite at grazing w).
    fn d_visible(&self, w: [f64; 3], wm: [f64; 3]) -> f64 {
        let (w, wm) = (Vec3::from(w).to_unit(), Vec3::from(wm).to_unit());
        let w = if w.z < 0.0 { -w } else { w };
        let c = w.dot(wm);
        if !(c > 0.0 && wm.z > 0.0) {
            return if c.is_nan() || wm.z.is_nan() {
                f64::NAN
            } else {
                0.0
            };
        }
        let s = self.surface();
        let d = s.d(wm);
        if d.is_finite() {
            return c * d / s.sigma(w);
        }
        // D overflows toward the horizon where it grows there (Student-T at γ < 2: D ~
        // u^{2γ−4}) while the density does not: c · D cos θm/σ/cos θm, D cos θm from
        // the D·cos density, which such an NDF forms without the overflow (divided by
        // cos θm last: c/cos θm alone can overflow).
        c * s.pdf_dcos(wm) / s.sigma(w) / wm.z
    }
    /// As the trait's, for wm of any finite nonzero length (normalised here).
    fn pdf_dcos(&self, wm: [f64; 3]) -> f64 {
        self.surface().pdf_dcos(Vec3::from(wm))
    }
}

/// The α = 1 member of a family kind at `shape` and its posterior sampler, validated
/// (Student-T needs a finite Λ), from this thread's last one where the shape is the same:
/// its normalisation (Γ functions) is then not recomputed for each material of a
/// textured α (BENCHMARKS.md, "Materials per call").
fn shaped_unit(
    kind: crate::NdfKind,
    shape: Option<f64>,
) -> Result<(crate::AnyNdf, Option<crate::ndf::mixture::Posterior>), ParamError> {
    use std::cell::Cell;
    type Unit = (crate::AnyNdf, Option<crate::ndf::mixture::Posterior>);
    thread_local! {
        static LAST: Cell<Option<((crate::NdfKind, u64), Unit)>> = const { Cell::new(None) };
    }
    let key = super::shape_key(kind, shape);
    if let Some((k, unit)) = LAST.with(|c| c.get()) {
        if k == key {
            return Ok(unit);
        }
    }
    let ndf = crate::AnyNdf::new(kind, 1.0, shape)?;
    if let crate::AnyNdf::StudentT(t) = ndf {
        if !t.has_finite_lambda() {
            return Err(ParamError::Shape {
                name: "student_t gamma (visible normals and G need a finite Lambda)",
                range: "(1.5, 1e6]",
                value: t.gamma(),
            });
        }
    }
    let unit = Shaped::unit_of(&ndf);
    LAST.with(|c| c.set(Some((key, unit))));
    Ok(unit)
}
