//! The material every direction method, sampler, BSDF and walk of an NDF object runs: the
//! library's run-time door ([`AnyMicrofacet<f64>`], the fast kernels; the default), or its
//! exact path ([`Exact`], `exact=True`) with one choice of visible-normal sampler.

use microsurface::distribution::UniformStream;
use microsurface::{AnyMicrofacet, Exact, MicrofacetDistribution, NdfKind, ParamError, Sample};

/// How the exact path draws visible normals.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sampler {
    /// The exact inversion (a warp of u: invertible, stratifiable; for the family it inverts
    /// quadratures: 8 µs (Student-T γ = 4) to 3 ms (Bessel-K a = 100) a sample, and
    /// 20 ms for Student-T near γ = 3/2).
    Warp,
    /// For the Beckmann mixtures (Student-T, Ei, Erfc, K0, Bessel-K): the posterior of the
    /// mixing variable, then Beckmann's visible normals (`Exact::sample_wm_stream`: exact in
    /// distribution, ~0.2 µs), from the uniforms of a SplitMix64 stream seeded by u's bits
    /// (`UniformStream`: deterministic in u, not a warp of it). The other NDFs: the warp.
    Posterior,
}

/// Whether `kind` is one of the family's Beckmann mixtures (the posterior sampler's NDFs).
pub fn mixture(kind: NdfKind) -> bool {
    matches!(
        kind,
        NdfKind::StudentT | NdfKind::Ei | NdfKind::Erfc | NdfKind::K0 | NdfKind::BesselK
    )
}

/// One material: the fast door, or the exact path with its sampler.
#[derive(Clone, Debug)]
pub enum Material {
    /// [`AnyMicrofacet`]: the fast kernels of every NDF (the generalised exponential's exact
    /// path inside it), bit-identical to the library's static `Microfacet<f64, N>`.
    Fast(AnyMicrofacet<f64>),
    /// [`Exact`] with `sample_wm` by the chosen sampler; every other method is Exact's.
    Exact { exact: Exact, sampler: Sampler },
}

impl Material {
    /// NDF `kind` at (αx, αy) with its shape, on the fast door or (`exact`) the exact path
    /// with `sampler` (the warp for every NDF but the Beckmann mixtures).
    pub fn new(
        kind: NdfKind,
        alpha_x: f64,
        alpha_y: f64,
        shape: Option<f64>,
        exact: bool,
        sampler: Sampler,
    ) -> Result<Self, ParamError> {
        if !exact {
            return AnyMicrofacet::new(kind, alpha_x, alpha_y, shape).map(Material::Fast);
        }
        Ok(Material::Exact {
            exact: Exact::new(kind, alpha_x, alpha_y, shape)?,
            sampler: if mixture(kind) {
                sampler
            } else {
                Sampler::Warp
            },
        })
    }

    /// Whether this material runs a fast path (the fast door, and an NDF that has one: every
    /// NDF but the generalised exponential).
    pub fn is_fast(&self) -> bool {
        matches!(self, Material::Fast(m) if m.is_fast())
    }

    /// The exact path of this material.
    pub fn exact(&self) -> Exact {
        match self {
            Material::Fast(m) => m.exact(),
            Material::Exact { exact, .. } => *exact,
        }
    }

    /// How `sample_wm` draws: 'warp' (an invertible warp of u), 'posterior' (the mixing
    /// variable's posterior, from a stream seeded by u) or 'rejection' (the fast samplers of
    /// Double GGX, the Exponential NDF and GTR at γ ≠ 2: u for the first candidate, a stream
    /// seeded by u for the rest).
    pub fn sampler_name(&self) -> &'static str {
        match self {
            Material::Exact {
                sampler: Sampler::Posterior,
                ..
            } => "posterior",
            Material::Exact { .. } => "warp",
            Material::Fast(m) => match m.spec().kind {
                k if mixture(k) => "posterior",
                NdfKind::DoubleGgx | NdfKind::Exponential => "rejection",
                NdfKind::Gtr if m.spec().shape != Some(2.0) => "rejection",
                _ => "warp",
            },
        }
    }

    /// The projected area σ(w) = |w.z|(1 + Λ(w)), w mirrored to the upper hemisphere; on the
    /// horizon (where Λ = ∞), on the exact path and for the generalised exponential (no fast
    /// path), the exact path's σ.
    pub fn sigma(&self, w: [f64; 3]) -> f64 {
        if let Material::Fast(m) = self {
            if !m.is_fast() {
                return m.exact().sigma(w);
            }
            let v = if w[2] < 0.0 { w.map(|x| -x) } else { w };
            let lambda = m.lambda(v);
            if v[2] > 0.0 && lambda.is_finite() {
                return v[2] + v[2] * lambda;
            }
            if v.iter().any(|x| x.is_nan()) {
                return f64::NAN;
            }
        }
        self.exact().sigma(w)
    }
}

/// `$body` with `$d` bound to the material's [`MicrofacetDistribution`].
macro_rules! both {
    ($self:expr, |$d:ident| $body:expr) => {
        match $self {
            Material::Fast($d) => $body,
            Material::Exact { exact: $d, .. } => $body,
        }
    };
}

impl MicrofacetDistribution<f64> for Material {
    #[inline]
    fn alpha(&self) -> (f64, f64) {
        both!(self, |d| d.alpha())
    }
    fn ndf(&self) -> Option<(NdfKind, Option<f64>)> {
        both!(self, |d| d.ndf())
    }
    #[inline]
    fn d(&self, wm: [f64; 3]) -> f64 {
        both!(self, |d| d.d(wm))
    }
    #[inline]
    fn lambda(&self, w: [f64; 3]) -> f64 {
        both!(self, |d| d.lambda(w))
    }
    #[inline]
    fn g1(&self, w: [f64; 3]) -> f64 {
        both!(self, |d| d.g1(w))
    }
    #[inline]
    fn g2(&self, wo: [f64; 3], wi: [f64; 3]) -> f64 {
        both!(self, |d| d.g2(wo, wi))
    }
    #[inline]
    fn g2_separable(&self, wo: [f64; 3], wi: [f64; 3]) -> f64 {
        both!(self, |d| d.g2_separable(wo, wi))
    }
    #[inline]
    fn d_visible(&self, w: [f64; 3], wm: [f64; 3]) -> f64 {
        both!(self, |d| d.d_visible(w, wm))
    }
    #[inline]
    fn pdf(&self, w: [f64; 3], wm: [f64; 3]) -> f64 {
        both!(self, |d| d.pdf(w, wm))
    }
    #[inline]
    fn sample_wm(&self, w: [f64; 3], u: [f64; 2]) -> [f64; 3] {
        match self {
            Material::Fast(m) => m.sample_wm(w, u),
            Material::Exact { exact, sampler } => {
                if *sampler == Sampler::Posterior {
                    // (w.z < 0 mirrored, as the trait's samplers; the stream sampler answers
                    // above the horizon, else None: then the warp.)
                    let v = if w[2] < 0.0 { [-w[0], -w[1], -w[2]] } else { w };
                    let mut stream = UniformStream::new(u);
                    if let Some(m) = exact.sample_wm_stream(v, &mut || stream.next_uniform::<f64>())
                    {
                        return m;
                    }
                }
                exact.sample_wm(w, u)
            }
        }
    }
    #[inline]
    fn sample(&self, w: [f64; 3], u: [f64; 2]) -> Sample<f64> {
        if let Material::Fast(m) = self {
            return m.sample(w, u);
        }
        let wm = self.sample_wm(w, u);
        Sample {
            wm,
            pdf: self.pdf(w, wm),
        }
    }
    #[inline]
    fn sample_wm_stream(&self, v: [f64; 3], uniform: &mut dyn FnMut() -> f64) -> Option<[f64; 3]> {
        both!(self, |d| d.sample_wm_stream(v, uniform))
    }
    #[inline]
    fn sample_dcos(&self, u: [f64; 2]) -> Sample<f64> {
        both!(self, |d| d.sample_dcos(u))
    }
    #[inline]
    fn pdf_dcos(&self, wm: [f64; 3]) -> f64 {
        both!(self, |d| d.pdf_dcos(wm))
    }
    #[inline]
    fn effectively_smooth(&self) -> bool {
        both!(self, |d| d.effectively_smooth())
    }
}

/// One element's parameters: α, αy and the shape (γ or a), as the engine's loop reads them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct P {
    pub alpha: f64,
    pub alpha_y: f64,
    pub shape: Option<f64>,
}

/// What an isotropic NDF is built from: the NDF, α's and the shape's bits.
type IsoKey = (NdfKind, u64, Option<u64>);

/// What a material is built from: the NDF, its parameters' bits, the path and the sampler.
type Key = (NdfKind, u64, u64, Option<u64>, bool, Sampler);

thread_local! {
    static MATERIALS: std::cell::RefCell<Option<(Key, Material)>> =
        const { std::cell::RefCell::new(None) };
    static ISOTROPIC: std::cell::RefCell<Option<(IsoKey, microsurface::AnyNdf)>> =
        const { std::cell::RefCell::new(None) };
}

/// `f` of the material of NDF `kind` at `p` on the path `exact` with `sampler`, built once
/// for a run of elements with the same parameters ([`crate::params::Recent`]).
pub fn with_material<R>(
    kind: NdfKind,
    p: P,
    exact: bool,
    sampler: Sampler,
    f: impl FnOnce(&Material) -> R,
) -> Result<R, ParamError> {
    let key = (
        kind,
        p.alpha.to_bits(),
        p.alpha_y.to_bits(),
        p.shape.map(f64::to_bits),
        exact,
        sampler,
    );
    crate::params::Recent::new(&MATERIALS).with(
        key,
        || Material::new(kind, p.alpha, p.alpha_y, p.shape, exact, sampler),
        f,
    )
}

/// `f` of the isotropic NDF `kind` at (α, shape) (the functions of a cosine' exact path),
/// built once for a run of elements with the same parameters.
pub fn with_isotropic<R>(
    kind: NdfKind,
    alpha: f64,
    shape: Option<f64>,
    f: impl FnOnce(&microsurface::AnyNdf) -> R,
) -> Result<R, ParamError> {
    let key = (kind, alpha.to_bits(), shape.map(f64::to_bits));
    crate::params::Recent::new(&ISOTROPIC).with(
        key,
        || microsurface::AnyNdf::new(kind, alpha, shape),
        f,
    )
}
