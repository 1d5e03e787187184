//! The report's BSDF section (issue 20): polar plots of f·cos in the plane of incidence for
//! θo ∈ {0°, 45°, 75°}, conductor and dielectric (reflection and transmission), histograms of
//! the BSDF samplers' directions against their pdf, and the single-scattering albedo against
//! α for every NDF (the energy a single-scattering BSDF loses: the motivation for multiple
//! scattering). Everything from the library's `Microfacet` and `bsdf` types, in f64.

use super::common::{grid, material, short};
use super::svg::{Plot, Series, Style};
use microsurface::bsdf::fresnel::{self, One};
use microsurface::bsdf::{Bsdf, RoughConductor, RoughDielectric};
use microsurface::check::chi2::SplitMix64;
use microsurface::NdfKind;
use std::f64::consts::PI;

/// The plots' roughness (isotropic), GTR's γ, the dielectric's η and the conductor (gold's
/// green channel, η = 0.42, k = 2.38).
const ALPHA: f64 = 0.3;
const GAMMA: f64 = 1.5;
const ETA: f64 = 1.5;
const GOLD_G: fresnel::Conductor<f64, 1> = fresnel::Conductor {
    eta: [0.42],
    k: [2.38],
};
const THETA_O: [f64; 3] = [0.0, 45.0, 75.0];

fn label(kind: NdfKind) -> String {
    if kind == NdfKind::Gtr {
        format!("{} α={ALPHA} γ={GAMMA}", short(kind))
    } else {
        format!("{} α={ALPHA}", short(kind))
    }
}

fn wo_at(deg: f64) -> [f64; 3] {
    let t = deg.to_radians();
    [t.sin(), 0.0, t.cos()]
}

/// The lobe f·|cos θi| in the plane of incidence as a polar curve: the point r·wi for wi
/// at signed angle θ from the normal (θ ∈ (−90°, 90°): above; `below`: the same under the
/// surface).
fn polar(f_cos: impl Fn([f64; 3]) -> f64, below: bool) -> Vec<(f64, f64)> {
    grid(-89.9, 89.9, 721)
        .into_iter()
        .map(|deg| {
            let t = deg.to_radians();
            let wi = [t.sin(), 0.0, if below { -t.cos() } else { t.cos() }];
            let r = f_cos(wi);
            (r * wi[0], r * wi[2])
        })
        .collect()
}

/// The conductor's and the dielectric's polar plots for one NDF.
fn polar_plots(kind: NdfKind) -> Vec<Plot> {
    {
        let d = material(kind, ALPHA, GAMMA);
        let conductor = RoughConductor::new(d.clone(), GOLD_G);
        let dielectric = RoughDielectric::new(d, ETA).expect("the report's η is valid");
        let mut pc = Plot::new(
            format!("{}: rough conductor, f·cos θi", label(kind)),
            "x (plane of incidence)",
            "z (normal)",
        )
        .equal_aspect()
        .caption(
            "The lobe f(wo, wi)|cos θi| of the rough conductor (gold, green channel: η = 0.42, \
             k = 2.38, exact complex Fresnel; height-correlated G2) as a polar curve in the \
             plane of incidence, wo at θo = 0°, 45°, 75° on the +x side: f = F(wo·wm) D(wm) \
             G2(wo, wi)/(4|cos θo cos θi|) (Walter et al. 2007, eq. 20; pbrt-v4 conventions).",
        );
        // Reflection and transmission apart: at η = 1.5 the transmitted lobe's peak is ten
        // times the reflected one's, which one equal-aspect plot would flatten.
        let mut pr = Plot::new(
            format!("{}: rough dielectric η = {ETA}, reflection", label(kind)),
            "x (plane of incidence)",
            "z (normal)",
        )
        .equal_aspect()
        .caption(
            "The rough dielectric's reflection (η = 1.5, wo outside): f|cos θi| as a polar \
             curve in the plane of incidence, f = F(wo·wm) D G2/(4|cos θo cos θi|) with the \
             exact unpolarised Fresnel reflectance (Walter et al. 2007, eq. 20).",
        );
        let mut pt = Plot::new(
            format!("{}: rough dielectric η = {ETA}, transmission", label(kind)),
            "x (plane of incidence)",
            "z (normal)",
        )
        .equal_aspect()
        .caption(
            "The rough dielectric's transmission (η = 1.5, wo outside, radiance transport), \
             under the surface: f = |wi·wm||wo·wm| D G2 (1 − F)/(|cos θo cos θi| (wi·wm + \
             wo·wm/η)²)/η² (Walter et al. 2007, eq. 21, in pbrt-v4's form), f|cos θi| as a \
             polar curve.",
        );
        for (k, &deg) in THETA_O.iter().enumerate() {
            let wo = wo_at(deg);
            let name = format!("θo = {deg}°");
            pc = pc.with(
                Series::new(
                    name.clone(),
                    polar(|wi| conductor.eval(wo, wi)[0] * wi[2].abs(), false),
                    Style::Line,
                )
                .color(k),
            );
            pr = pr.with(
                Series::new(
                    name.clone(),
                    polar(|wi| dielectric.eval(wo, wi)[0] * wi[2].abs(), false),
                    Style::Line,
                )
                .color(k),
            );
            pt = pt.with(
                Series::new(
                    name,
                    polar(|wi| dielectric.eval(wo, wi)[0] * wi[2].abs(), true),
                    Style::Line,
                )
                .color(k),
            );
        }
        vec![pc, pr, pt]
    }
}

/// Histogram of θi (0° to 180°: above, then below the surface) of a BSDF's samples for wo at
/// 45°, against the pdf integrated over the azimuth (per degree).
fn sample_histogram<B: Bsdf<f64>>(title: String, caption: &str, b: &B) -> Plot {
    let wo = wo_at(45.0);
    let (samples, bins) = (40_000usize, 90usize);
    let width = 180.0 / bins as f64;
    let mut counts = vec![0.0; bins];
    let mut rng = SplitMix64(21);
    for _ in 0..samples {
        let (uc, u) = (rng.next_f64(), [rng.next_f64(), rng.next_f64()]);
        if let Some(s) = b.sample(wo, uc, u) {
            let theta = s.wi[2].clamp(-1.0, 1.0).acos().to_degrees();
            counts[((theta / width) as usize).min(bins - 1)] += 1.0;
        }
    }
    let hist = counts
        .iter()
        .enumerate()
        .map(|(i, c)| ((i as f64 + 0.5) * width, c / (samples as f64 * width)))
        .collect();
    // sin θ ∫ pdf dφ at θ (midpoint rule over 720 azimuths), per degree.
    let density = |deg: f64| {
        let t = deg.to_radians();
        let (s, c) = t.sin_cos();
        let k = 720;
        let ring: f64 = (0..k)
            .map(|j| {
                let phi = 2.0 * PI * (j as f64 + 0.5) / k as f64;
                b.pdf(wo, [s * phi.cos(), s * phi.sin(), c])
            })
            .sum();
        s * ring * 2.0 * PI / k as f64 * PI / 180.0
    };
    let curve = grid(0.1, 179.9, 360)
        .into_iter()
        .filter(|d| (d - 90.0).abs() > 0.15)
        .map(|d| (d, density(d)))
        .collect();
    Plot::new(
        title,
        "θi (degrees; > 90°: transmitted)",
        "density per degree",
    )
    .caption(caption)
    .with(Series::new(format!("{samples} samples"), hist, Style::Bars))
    .with(Series::new("pdf", curve, Style::Line))
}

fn histogram_plots(kind: NdfKind) -> Vec<Plot> {
    {
        let d = material(kind, ALPHA, GAMMA);
        let conductor = RoughConductor::new(d.clone(), GOLD_G);
        let dielectric = RoughDielectric::new(d, ETA).expect("the report's η is valid");
        vec![
            sample_histogram(
                format!("{}: conductor samples, θo = 45°", label(kind)),
                "Histogram of θi of the rough conductor's sampler (a visible normal, then the \
                 mirror direction; samples reflected below the horizon are rejected, so the \
                 bars hold 1 minus the rejected fraction) against its pdf, \
                 D_wo(wm)/(4|wo·wm|), integrated over the azimuth.",
                &conductor,
            ),
            sample_histogram(
                format!("{}: dielectric samples, θo = 45°, η = {ETA}", label(kind)),
                "Histogram of θi of the rough dielectric's sampler (a visible normal, then \
                 reflection or refraction chosen with probability F) against its pdf, \
                 integrated over the azimuth: reflection (θi < 90°) and transmission \
                 (θi > 90°, with the refraction Jacobian of Walter et al. 2007, eq. 17).",
                &dielectric,
            ),
        ]
    }
}

/// The single-scattering albedo E(θo) = ∫ f cos θi dωi of the conductor with F = 1, by the
/// sampler's weights f cos/pdf over a 128 × 128 grid of stratified uniforms (jittered): the
/// fraction of the energy a single-scattering microfacet BSDF keeps.
fn albedo(kind: NdfKind, alpha: f64, theta_o: f64) -> f64 {
    {
        let d = material(kind, alpha, GAMMA);
        let b = RoughConductor::new(d, One::<1>);
        let wo = wo_at(theta_o);
        let n = 128;
        let mut rng = SplitMix64(5);
        let mut sum = 0.0;
        for i in 0..n {
            for j in 0..n {
                let u = [
                    (i as f64 + rng.next_f64()) / n as f64,
                    (j as f64 + rng.next_f64()) / n as f64,
                ];
                if let Some(s) = b.sample(wo, 0.5, u) {
                    sum += s.f[0] * s.wi[2].abs() / s.pdf;
                }
            }
        }
        sum / (n * n) as f64
    }
}

fn albedo_plots() -> Vec<Plot> {
    let alphas: Vec<f64> = (0..=24)
        .map(|k| 0.02 * (100f64).powf(k as f64 / 24.0))
        .collect();
    THETA_O
        .iter()
        .filter(|&&t| t != 45.0)
        .map(|&theta_o| {
            let mut p = Plot::new(
                format!("Single-scattering albedo, θo = {theta_o}°"),
                "α (log₁₀)",
                "E = ∫ f cos θi dωi (F = 1)",
            )
            .caption(
                "The directional albedo of a single-scattering rough conductor with F = 1 \
                 (height-correlated G2), E(θo) = ∫ D G2/(4 cos θo) dωi, against roughness, \
                 every NDF (GTR at γ = 1.5): 1 − E is the energy lost to the paths that leave \
                 after more than one bounce on the microsurface, which the multiple-scattering \
                 model restores. Estimated from the BSDF sampler's weights over 128² \
                 stratified uniforms.",
            );
            for (k, kind) in NdfKind::CLASSIC.into_iter().enumerate() {
                let pts = alphas
                    .iter()
                    .map(|&a| (a.log10(), albedo(kind, a, theta_o)))
                    .collect();
                p = p.with(Series::new(short(kind), pts, Style::Line).color(k));
            }
            p
        })
        .collect()
}

/// Every plot of the BSDF section, in order.
pub fn plots() -> Vec<Plot> {
    let mut v = Vec::new();
    for kind in NdfKind::CLASSIC {
        v.extend(polar_plots(kind));
        v.extend(histogram_plots(kind));
    }
    v.extend(albedo_plots());
    v
}
