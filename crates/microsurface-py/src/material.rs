//! The material every method of an NDF object runs: the library's exact path
//! ([`microsurface::Exact`]) with one choice of visible-normal sampler.

use microsurface::distribution::UniformStream;
use microsurface::{Distribution, Exact, NdfKind, Sample};

/// How visible normals are drawn.
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

/// [`Exact`] with `sample_wm` by the chosen sampler; every other method is Exact's.
#[derive(Clone, Copy, Debug)]
pub struct Material {
    pub exact: Exact,
    pub sampler: Sampler,
}

impl Material {
    pub fn new(exact: Exact, sampler: Sampler) -> Self {
        let mixture = matches!(
            exact.ndf(),
            Some((
                NdfKind::StudentT | NdfKind::Ei | NdfKind::Erfc | NdfKind::K0 | NdfKind::BesselK,
                _
            ))
        );
        Material {
            exact,
            sampler: if mixture { sampler } else { Sampler::Warp },
        }
    }
}

impl Distribution<f64> for Material {
    fn alpha(&self) -> (f64, f64) {
        self.exact.alpha()
    }
    fn ndf(&self) -> Option<(NdfKind, Option<f64>)> {
        self.exact.ndf()
    }
    fn d(&self, wm: [f64; 3]) -> f64 {
        self.exact.d(wm)
    }
    fn lambda(&self, w: [f64; 3]) -> f64 {
        self.exact.lambda(w)
    }
    fn g1(&self, w: [f64; 3]) -> f64 {
        self.exact.g1(w)
    }
    fn g2(&self, wo: [f64; 3], wi: [f64; 3]) -> f64 {
        self.exact.g2(wo, wi)
    }
    fn g2_separable(&self, wo: [f64; 3], wi: [f64; 3]) -> f64 {
        self.exact.g2_separable(wo, wi)
    }
    fn d_visible(&self, w: [f64; 3], wm: [f64; 3]) -> f64 {
        self.exact.d_visible(w, wm)
    }
    fn pdf(&self, w: [f64; 3], wm: [f64; 3]) -> f64 {
        self.exact.pdf(w, wm)
    }
    fn sample_wm(&self, w: [f64; 3], u: [f64; 2]) -> [f64; 3] {
        if self.sampler == Sampler::Posterior {
            // (w.z < 0 mirrored, as the trait's samplers; the stream sampler answers above
            // the horizon, else None: then the warp.)
            let v = if w[2] < 0.0 { [-w[0], -w[1], -w[2]] } else { w };
            let mut stream = UniformStream::new(u);
            if let Some(m) = self
                .exact
                .sample_wm_stream(v, &mut || stream.next_uniform::<f64>())
            {
                return m;
            }
        }
        self.exact.sample_wm(w, u)
    }
    fn sample_wm_stream(&self, v: [f64; 3], uniform: &mut dyn FnMut() -> f64) -> Option<[f64; 3]> {
        self.exact.sample_wm_stream(v, uniform)
    }
    fn sample_dcos(&self, u: [f64; 2]) -> Sample<f64> {
        self.exact.sample_dcos(u)
    }
    fn pdf_dcos(&self, wm: [f64; 3]) -> f64 {
        self.exact.pdf_dcos(wm)
    }
    fn effectively_smooth(&self) -> bool {
        self.exact.effectively_smooth()
    }
}
