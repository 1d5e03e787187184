//! `microsurface report [--out DIR]`: the source pages reproduced from our own code, as one
//! self-contained HTML page (inline SVG, no scripts, no network): per NDF, D(θ), σ against the
//! projected-area integral, Λ and G1 (with the Exponential page's approximations and their
//! error), the slope densities, sample histograms against their pdfs, the superposition
//! identities, and the table of every identity from `verify`; then a comparison of the NDFs
//! at matched roughness.

mod bsdf;
mod common;
mod ms;
mod svg;

use common::{grid, short};
use microsurface::check::chi2::SplitMix64;
use microsurface::check::verify::{run as run_checks, sigma_by_delta_integral, Sweep};
use microsurface::ndf::exponential::approx::{ei_g1, g1_rational};
use microsurface::ndf::mixture::{superpose_beckmann, superpose_ggx, Mixing};
use microsurface::ndf::MatchBy;
use microsurface::{AnyNdf, Exact, MicrofacetDistribution, Ndf, NdfKind, Vec3};
use std::fmt::Write as _;
use std::process::ExitCode;
use std::time::Instant;
use svg::{esc, Plot, Series, Style};

const ALPHAS: [f64; 3] = [0.1, 0.3, 0.6];
const GAMMAS: [f64; 4] = [0.5, 1.0, 1.5, 2.5];

fn ndf(kind: NdfKind, alpha: f64, gamma: Option<f64>) -> AnyNdf {
    AnyNdf::new(kind, alpha, gamma).expect("report parameters are valid")
}

/// The NDF instances a section shows: three roughnesses (the Exponential NDF page's own α =
/// 0.8 and 2.1 beside 0.3), or (GTR) four γ at α = 0.3.
fn members(kind: NdfKind) -> Vec<(String, AnyNdf)> {
    let alphas: &[f64] = match kind {
        NdfKind::Exponential => &[0.3, 0.8, 2.1],
        _ => &ALPHAS,
    };
    // The family's shape parameters at α = 0.3: the pages' ranges (Student-T from near the
    // pole γ = 3/2 to near-Beckmann; Bessel-K across a = 1 (K0) and 3/2 (Exponential); the
    // generalised exponential from stretched tails to a near-flat disk).
    let shapes: &[f64] = match kind {
        NdfKind::StudentT => &[1.6, 2.0, 4.0, 20.0],
        NdfKind::BesselK => &[0.5, 1.0, 1.5, 4.0],
        NdfKind::GenExponential => &[0.5, 1.0, 2.0, 8.0],
        _ => &[],
    };
    if let Some(name) = kind.shape_name().filter(|_| kind != NdfKind::Gtr) {
        return shapes
            .iter()
            .map(|&g| (format!("α=0.3 {name}={g}"), ndf(kind, 0.3, Some(g))))
            .collect();
    }
    if kind == NdfKind::Gtr {
        GAMMAS
            .iter()
            .map(|&g| (format!("α=0.3 γ={g}"), ndf(kind, 0.3, Some(g))))
            .collect()
    } else {
        alphas
            .iter()
            .map(|&a| (format!("α={a}"), ndf(kind, a, None)))
            .collect()
    }
}

/// The two instances of the σ and slope-density plots: the first two members, and for GTR
/// the GTR page's γ = 1.5 at two roughnesses.
fn pair(kind: NdfKind) -> Vec<(String, AnyNdf)> {
    if kind == NdfKind::Gtr {
        [0.3, 0.6]
            .iter()
            .map(|&a| (format!("α={a} γ=1.5"), ndf(kind, a, Some(1.5))))
            .collect()
    } else {
        members(kind).into_iter().take(2).collect()
    }
}

/// The section heading of an NDF.
fn heading(kind: NdfKind) -> &'static str {
    match kind {
        NdfKind::Beckmann => "Beckmann",
        NdfKind::Ggx => "GGX (Trowbridge–Reitz)",
        NdfKind::Gtr => "GTR (generalized Trowbridge–Reitz, exponent γ)",
        NdfKind::DoubleGgx => "Double GGX",
        NdfKind::Exponential => "Exponential NDF",
        NdfKind::StudentT => "Student-T (shape γ)",
        NdfKind::Ei => "Ei NDF",
        NdfKind::Erfc => "Erfc NDF",
        NdfKind::K0 => "K0 NDF",
        NdfKind::BesselK => "Bessel-K (shape a)",
        NdfKind::GenExponential => "Generalised exponential (exponent γ)",
    }
}

/// The NDF's defining D and where it comes from, for captions.
fn source(kind: NdfKind) -> &'static str {
    match kind {
        NdfKind::Beckmann => {
            "D = exp(−tan²θ/α²)/(π α² cos⁴θ) (d'Eon, Hitchhiker's Guide, GGX page; exponent \
             corrected, derivations.md A.2)"
        }
        NdfKind::Ggx => {
            "D = α²/(π cos⁴θ (α² + tan²θ)²) (Walter et al. 2007; d'Eon, Hitchhiker's Guide, GGX page)"
        }
        NdfKind::Gtr => {
            "D = c/(1 + (α² − 1) cos²θ)^γ, c from Burley 2012 appendix B eq. 1 (d'Eon, \
             Hitchhiker's Guide, GTR page)"
        }
        NdfKind::DoubleGgx => {
            "D = ∫₀^∞ e^{−t} D_GGX(α/√t) dt, closed form with E₁ (d'Eon, Hitchhiker's Guide, \
             Double GGX page)"
        }
        NdfKind::Exponential => {
            "D = 2 exp(−2 tanθ/α)/(π α² cos⁴θ) (d'Eon, Hitchhiker's Guide, Exponential NDF page)"
        }
        NdfKind::StudentT => {
            "D = (1 + tan²θ/(α²(γ−1)))^{−γ}/(π α² cos⁴θ), γ = 2 is GGX, γ → ∞ Beckmann \
             (Ribardière et al. 2017; d'Eon, Hitchhiker's Guide, StudentT NDF page)"
        }
        NdfKind::Ei => {
            "D = E₁(tan²θ/α²)/(π α² cos⁴θ), Beckmann uniform in roughness² ∈ (0, α²] (d'Eon, \
             Hitchhiker's Guide, Ei NDF page)"
        }
        NdfKind::Erfc => {
            "D = erfc(tanθ/α)/(2√π α tanθ cos⁴θ), Beckmann uniform in roughness ∈ (0, α] \
             (d'Eon, Hitchhiker's Guide, Erfc NDF page)"
        }
        NdfKind::K0 => {
            "D = 2 K₀(2 tanθ/α)/(π α² cos⁴θ), Bessel-K at a = 1 (d'Eon, Hitchhiker's Guide, \
             K0 NDF page)"
        }
        NdfKind::BesselK => {
            "D = 2 (tanθ/α)^{a−1} K_{a−1}(2 tanθ/α)/(π α² Γ(a) cos⁴θ), a Gamma(a) mixture of \
             Beckmann; a = 1 is K0, a = 3/2 the Exponential NDF (d'Eon, Hitchhiker's Guide, \
             BesselK NDF page)"
        }
        NdfKind::GenExponential => {
            "D = exp(−(tanθ/α)^γ)/(π α² Γ(1 + 2/γ) cos⁴θ), γ = 2 is Beckmann, γ = 1 the \
             Exponential NDF at 2α (d'Eon, Hitchhiker's Guide, GenExponential NDF page)"
        }
    }
}

fn d_plot(kind: NdfKind) -> Plot {
    let mut p = Plot::new(format!("{}: D(θm)", short(kind)), "θm (degrees)", "D")
        .log_y()
        .caption(format!(
            "The NDF against the microfacet normal's angle. {}.",
            source(kind)
        ));
    for (label, n) in members(kind) {
        let pts = grid(0.0, 89.5, 180)
            .into_iter()
            .map(|t| (t, n.d(t.to_radians().cos())))
            .collect();
        p = p.with(Series::new(label, pts, Style::Line));
    }
    p
}

fn sigma_plot(kind: NdfKind) -> Plot {
    let mut p = Plot::new(
        format!("{}: σ(u), formula vs ∫ D Δσ", short(kind)),
        "u = cos θ",
        "σ(u)",
    )
    .caption(
        "Projected area σ(u) = u(1 + Λ(u)) (u > 0), uΛ(u) seen from below (lines), against the \
         independent integral ∫₀¹ D(uᵢ) Δσ(u, uᵢ) duᵢ over the projected-area kernel (markers; \
         d'Eon, Hitchhiker's Guide, GGX page; derivations.md B.1).",
    );
    for (k, (label, n)) in pair(kind).into_iter().enumerate() {
        let line = grid(-1.0, 1.0, 121)
            .into_iter()
            .map(|u| (u, n.sigma(u)))
            .collect();
        let dots = grid(-0.95, 0.95, 20)
            .into_iter()
            .map(|u| (u, sigma_by_delta_integral(&n, u)))
            .collect();
        p = p
            .with(Series::new(format!("{label} σ"), line, Style::Line).color(k))
            .with(Series::new(format!("{label} ∫DΔσ"), dots, Style::Markers).color(k));
    }
    p
}

fn lambda_plot(kind: NdfKind) -> Plot {
    let mut p = Plot::new(format!("{}: Smith Λ(u)", short(kind)), "u = cos θ", "Λ")
        .log_y()
        .caption(
            "Smith's Λ(u) = (1/a)∫ₐ^∞ (q − a) P2(q) dq, a = cot θ (Heitz 2014); closed forms \
             or the Smith integral by quadrature (crate docs per NDF).",
        );
    for (label, n) in members(kind) {
        let pts = grid(0.02, 0.999, 120)
            .into_iter()
            .map(|u| (u, n.lambda(u)))
            .collect();
        p = p.with(Series::new(label, pts, Style::Line));
    }
    p
}

fn g1_plot(kind: NdfKind) -> Plot {
    let mut p = Plot::new(format!("{}: G1(u)", short(kind)), "u = cos θ", "G1").caption(
        if kind == NdfKind::Exponential {
            "Smith masking G1 = 1/(1 + Λ) (Heitz 2014), with the Exponential NDF page's two \
             approximations at α = 0.3: G1 of the Ei NDF at 1.7α, and the rational fit \
             G1approx (derivations.md A.13, C); their differences are in the residual plot."
        } else {
            "Smith masking G1 = 1/(1 + Λ) (Heitz 2014)."
        },
    );
    for (label, n) in members(kind) {
        let pts = grid(0.0, 1.0, 121)
            .into_iter()
            .map(|u| (u, n.g1(u)))
            .collect();
        p = p.with(Series::new(label, pts, Style::Line));
    }
    if kind == NdfKind::Exponential {
        let a = 0.3;
        let us = grid(0.0, 1.0, 121);
        p = p
            .with(Series::new(
                "Ei G1(u, 1.7α), α=0.3",
                us.iter().map(|&u| (u, ei_g1(u, 1.7 * a))).collect(),
                Style::Dashed,
            ))
            .with(Series::new(
                "G1approx, α=0.3",
                us.iter().map(|&u| (u, g1_rational(u, a))).collect(),
                Style::Crosses,
            ));
    }
    p
}

fn approx_error_plot() -> Plot {
    let exact = ndf(NdfKind::Exponential, 1.0, None);
    let zs: Vec<f64> = (0..=200)
        .map(|k| 10f64.powf(-2.0 + 4.0 * k as f64 / 200.0))
        .collect();
    let u = |z: f64| z / (1.0 + z * z).sqrt();
    Plot::new(
        "Exponential: error of the page's G1 approximations",
        "log10(cot θ / α)",
        "|G1 approx − G1 exact|",
    )
    .log_y()
    .caption(
        "Both approximations of the Exponential NDF page against the exact G1 (derivations.md \
         A.14: Λ = (2K₁(z) − Ki₁(z))/π): errors up to 3.1e-3 at cot θ/α ≈ 1.2 (any α); \
         G1approx jumps to 1 at its x = 1.5 switch (derivations.md C).",
    )
    .with(Series::new(
        "Ei G1(u, 1.7α)",
        zs.iter()
            .map(|&z| (z.log10(), (ei_g1(u(z), 1.7) - exact.g1(u(z))).abs()))
            .collect(),
        Style::Line,
    ))
    .with(Series::new(
        "G1approx",
        zs.iter()
            .map(|&z| (z.log10(), (g1_rational(u(z), 1.0) - exact.g1(u(z))).abs()))
            .collect(),
        Style::Dashed,
    ))
}

fn ei_sigma_plot() -> Plot {
    use microsurface::ndf::exponential::approx::ei_sigma;
    let mut p = Plot::new(
        "Exponential: σ(u) exact vs the page's Ei σ(u, 1.7α)",
        "u = cos θ",
        "σ(u)",
    )
    .caption(
        "The Exponential NDF page's approximation of σ by the Ei NDF's exact σ at 1.7α \
         (derivations.md B.7, C), at the page's α = 0.8 and 2.1; they coincide at plot \
         scale: the residual plot shows the difference.",
    );
    for a in [0.8, 2.1] {
        let n = ndf(NdfKind::Exponential, a, None);
        let us = grid(-1.0, 1.0, 121);
        p = p
            .with(Series::new(
                format!("exact α={a}"),
                us.iter().map(|&u| (u, n.sigma(u))).collect(),
                Style::Line,
            ))
            .with(Series::new(
                format!("Ei σ(u, 1.7α) α={a}"),
                us.iter().map(|&u| (u, ei_sigma(u, 1.7 * a))).collect(),
                Style::Dashed,
            ));
    }
    p
}

/// The residuals of the Exponential page's approximations that coincide with what they
/// approximate at plot scale: Ei σ(u, 1.7α) − σ(u), and G1approx − Ei G1(u, 1.7α).
fn exponential_residual_plots() -> Vec<Plot> {
    use microsurface::ndf::exponential::approx::ei_sigma;
    let us = grid(-1.0, 1.0, 241);
    let mut sigma = Plot::new(
        "Exponential: Ei σ(u, 1.7α) − σ(u)",
        "u = cos θ",
        "difference",
    )
    .caption(
        "The residual of the page's σ approximation (previous plot's curves): at most 2.3e-3 \
         (α = 0.8) and 3.0e-3 (α = 2.1) over u ∈ [−1, 1] (derivations.md C).",
    );
    for a in [0.8, 2.1] {
        let n = ndf(NdfKind::Exponential, a, None);
        sigma = sigma.with(Series::new(
            format!("α={a}"),
            us.iter()
                .map(|&u| (u, ei_sigma(u, 1.7 * a) - n.sigma(u)))
                .collect(),
            Style::Line,
        ));
    }
    let a = 0.3;
    let us = grid(0.0, 1.0, 401);
    let g1 = Plot::new(
        "Exponential: G1approx − Ei G1(u, 1.7α), α = 0.3",
        "u = cos θ",
        "difference",
    )
    .caption(
        "The rational G1approx is a fit of the Ei approximation, not of the exact G1: within \
         3.4e-5 of it below its switch at x = cot θ/(1.7α) = 1.5, where it jumps to 1 \
         (derivations.md C).",
    )
    .with(Series::new(
        "G1approx − Ei G1",
        us.iter()
            .map(|&u| (u, g1_rational(u, a) - ei_g1(u, 1.7 * a)))
            .collect(),
        Style::Line,
    ));
    vec![sigma, g1]
}

/// GTR's D for α on both sides of 1 (α > 1 is allowed: D then grows towards grazing).
fn gtr_alpha_plot() -> Plot {
    let mut p = Plot::new("GTR γ=1.5: D(θm) for α < 1 and α > 1", "θm (degrees)", "D")
        .log_y()
        .caption(
            "GTR allows α > 1 (derivations.md E): D then grows towards grazing, largest at \
             θm = 90°; α = 1 is the uniform 1/π for every γ.",
        );
    for a in [0.1, 0.6, 1.0, 1.5] {
        let n = ndf(NdfKind::Gtr, a, Some(1.5));
        let pts = grid(0.0, 89.5, 180)
            .into_iter()
            .map(|t| (t, n.d(t.to_radians().cos())))
            .collect();
        p = p.with(Series::new(format!("α={a}"), pts, Style::Line));
    }
    p
}

fn slope_plot(kind: NdfKind) -> Plot {
    let mut p = Plot::new(
        format!("{}: slope densities", short(kind)),
        "p",
        "P2(p), P22(p, 0)",
    )
    .log_y()
    .caption(
        "Slope densities: P22(p, q) = D(u) u⁴ (u = 1/√(1 + p² + q²)) along q = 0, and the \
         marginal P2(p) = ∫ P22(p, q) dq (GTR: the ₂F₁ form of derivations.md A.9; Double GGX: \
         A.16; Exponential: A.14).",
    );
    for (label, n) in pair(kind) {
        let ps = grid(-3.0, 3.0, 161);
        p = p
            .with(Series::new(
                format!("P2 {label}"),
                ps.iter().map(|&x| (x, n.p2(x))).collect(),
                Style::Line,
            ))
            .with(Series::new(
                format!("P22 {label}"),
                ps.iter().map(|&x| (x, n.p22(x, 0.0))).collect(),
                Style::Dashed,
            ));
    }
    p
}

/// The density per degree of θm of `samples` normals from `draw`, in 60 bins over [0°, 90°]
/// (bin centre, density).
fn theta_histogram(samples: usize, mut draw: impl FnMut() -> Vec3) -> Vec<(f64, f64)> {
    let bins = 60;
    let width = 90.0 / bins as f64;
    let mut counts = vec![0.0; bins];
    for _ in 0..samples {
        let theta = draw().z.clamp(-1.0, 1.0).acos().to_degrees();
        counts[((theta / width) as usize).min(bins - 1)] += 1.0;
    }
    counts
        .iter()
        .enumerate()
        .map(|(i, c)| ((i as f64 + 0.5) * width, c / (samples as f64 * width)))
        .collect()
}

/// Histogram of θm of samples against the density of θm: 2π sin θ cos θ D(cos θ) for D·cos,
/// sin θ times the φ-integral of the visible density for visible normals (per degree).
fn histogram_plot(kind: NdfKind, visible: bool) -> Plot {
    use std::f64::consts::PI;
    // GTR at γ = 1.5; the family at a middle shape of its members.
    let shape = match kind {
        NdfKind::Gtr => Some(1.5),
        NdfKind::StudentT | NdfKind::GenExponential => Some(4.0),
        NdfKind::BesselK => Some(1.5),
        _ => None,
    };
    let n = ndf(kind, 0.3, shape);
    let m = Exact::new(kind, n.alpha(), n.alpha(), n.shape()).expect("valid parameters");
    let wi = {
        let t = 60f64.to_radians();
        Vec3::new(t.sin(), 0.0, t.cos())
    };
    // (Bessel-K's D·cos quantile is a Newton iteration on a superposition quadrature, ~0.2 ms.)
    let samples = match (visible, kind) {
        (true, _) | (false, NdfKind::BesselK) => 20_000,
        (false, _) => 100_000,
    };
    let mut rng = SplitMix64(11);
    // The Beckmann mixtures of the family sample visible normals from a uniform stream (the
    // mixing variable's posterior); the others by the exact warp of u.
    let posterior = m
        .sample_wm_stream(wi.into(), &mut || rng.next_f64())
        .is_some();
    let hist = theta_histogram(samples, || {
        let u = [rng.next_f64(), rng.next_f64()];
        if visible && posterior {
            let mut next = || 0.5 * (2.0 * rng.next_f64()).max(f64::EPSILON);
            Vec3::from(
                m.sample_wm_stream(wi.into(), &mut next)
                    .expect("a stream sampler"),
            )
        } else if visible {
            Vec3::from(m.sample_wm(wi.into(), u))
        } else {
            Vec3::from(m.sample_dcos(u).wm)
        }
    });
    let density = |deg: f64| {
        let t = deg.to_radians();
        let (s, c) = t.sin_cos();
        let per_rad = if visible {
            // sin θ ∫ d_visible dφ over the circle at θ (midpoint rule: smooth and periodic).
            let k = 256;
            let ring: f64 = (0..k)
                .map(|j| {
                    let phi = 2.0 * PI * (j as f64 + 0.5) / k as f64;
                    m.d_visible(wi.into(), [s * phi.cos(), s * phi.sin(), c])
                })
                .sum();
            s * ring * 2.0 * PI / k as f64
        } else {
            2.0 * PI * s * c * n.d(c)
        };
        per_rad * PI / 180.0
    };
    let curve = grid(0.1, 89.9, 200)
        .into_iter()
        .map(|d| (d, density(d)))
        .collect();
    let what = if visible {
        "visible normals, θi = 60°"
    } else {
        "D·cos"
    };
    let label = if kind == NdfKind::Gtr {
        "α=0.3 γ=1.5"
    } else {
        "α=0.3"
    };
    let caption = if visible && posterior {
        "Histogram of θm of the library's visible-normal sampler for this Beckmann mixture \
         (the mixing variable drawn from its posterior given wi by rejection, then that \
         Beckmann component's visible normal) for θi = 60°, against its pdf integrated over \
         azimuth: sin θ ∫ G1(wi) max(0, wi·m) D(m)/cos θi dφ."
    } else if visible {
        "Histogram of θm of the library's visible-normal sampler (exact inversion, Heitz & \
         d'Eon 2014) for θi = 60°, against its pdf integrated over azimuth: \
         sin θ ∫ G1(wi) max(0, wi·m) D(m)/cos θi dφ."
    } else {
        "Histogram of θm of the library's D·cos sampler (exact inversion of the radial slope \
         CDF; GTR: Burley 2012 appendix B eqs. 3–9), against 2π sin θ cos θ D(cos θ)."
    };
    Plot::new(
        format!("{} {label}: {what}", short(kind)),
        "θm (degrees)",
        "density per degree",
    )
    .caption(caption)
    .with(Series::new(format!("{samples} samples"), hist, Style::Bars))
    .with(Series::new("pdf", curve, Style::Line))
}

/// One superposition identity: the closed form as a dense curve (400 points, no kinks), and
/// each mixture at its own 30 angles (the mixtures' grids interleave, and the second draws
/// crosses, so neither hides the other).
fn superposition_plot(
    title: &str,
    caption: &str,
    y: &str,
    closed: impl Fn(f64) -> f64,
    mixes: &[(&str, &dyn Fn(f64) -> f64)],
) -> Plot {
    let theta = |u: f64| u.acos().to_degrees();
    let dense = grid(0.05, 0.999, 400);
    let mut p = Plot::new(title, "θ (degrees)", y)
        .log_y()
        .caption(caption)
        .with(Series::new(
            "closed form",
            dense.iter().map(|&u| (theta(u), closed(u))).collect(),
            Style::Line,
        ));
    let n = 30;
    for (k, (name, mix)) in mixes.iter().enumerate() {
        // Angles offset by a fraction of the spacing per mixture.
        let offset = (k as f64 + 0.5) / mixes.len() as f64;
        let us = (0..n).map(|i| 0.05 + (0.999 - 0.05) * (i as f64 + offset) / n as f64);
        let style = if k == 0 {
            Style::Markers
        } else {
            Style::Crosses
        };
        p = p.with(Series::new(
            *name,
            us.map(|u| (theta(u), mix(u))).collect(),
            style,
        ));
    }
    p
}

/// The pages' superposition identities as overlaid curves.
fn superposition_plots(kind: NdfKind) -> Vec<Plot> {
    let a = 0.3;
    if !matches!(
        kind,
        NdfKind::Ggx | NdfKind::DoubleGgx | NdfKind::Exponential
    ) {
        return Vec::new();
    }
    let g = ndf(kind, a, None);
    match kind {
        NdfKind::Ggx => vec![
            superposition_plot(
                "GGX D as superpositions of Beckmann D (α=0.3)",
                "GGX is a Fréchet-2 (over the roughness) and a Gamma-1 (over 1/roughness²) \
                 superposition of Beckmann (d'Eon, Hitchhiker's Guide, GGX page; derivations.md \
                 A.2, B.2): both mixtures by quadrature against the closed form.",
                "D",
                |u| g.d(u),
                &[
                    ("Fréchet-2", &|u| {
                        superpose_beckmann(Mixing::Frechet2, a, |b| b.d(u))
                    }),
                    ("Gamma-1", &|u| {
                        superpose_beckmann(Mixing::Gamma1, a, |b| b.d(u))
                    }),
                ],
            ),
            superposition_plot(
                "GGX Λ as a Gamma-1 superposition of Beckmann Λ",
                "Λ is linear in P22, so GGX's Λ is the same Gamma-1 mixture of Beckmann's Λ \
                 (d'Eon, Hitchhiker's Guide, GGX page).",
                "Λ",
                |u| g.lambda(u),
                &[("Gamma-1", &|u| {
                    superpose_beckmann(Mixing::Gamma1, a, |b| b.lambda(u))
                })],
            ),
        ],
        NdfKind::DoubleGgx => {
            vec![
            superposition_plot(
                "Double GGX D as a Gamma-1 superposition of GGX D",
                "Double GGX is to GGX what GGX is to Beckmann: D = ∫₀^∞ e^{−t} D_GGX(α/√t) dt \
                 (d'Eon, Hitchhiker's Guide, Double GGX page; derivations.md A.4, B.4).",
                "D",
                |u| g.d(u),
                &[("Gamma-1", &|u| superpose_ggx(Mixing::Gamma1, a, |c| c.d(u)))],
            ),
            superposition_plot(
                "Double GGX Λ as a Gamma-1 superposition of GGX Λ",
                "Λ = (x eˣ(K₀(x) + K₁(x)) − 1)/2, x = α² tan²θ/2 (derivations.md A.5), against \
                 the Gamma-1 mixture of GGX's Λ.",
                "Λ",
                |u| g.lambda(u),
                &[("Gamma-1", &|u| superpose_ggx(Mixing::Gamma1, a, |c| c.lambda(u)))],
            ),
        ]
        }
        NdfKind::Exponential => vec![superposition_plot(
            "Exponential D as superpositions of Beckmann D",
            "The Exponential NDF as Gamma(3/2) (roughness α√m) and Chi-3 (roughness αm/√2) \
             superpositions of Beckmann (d'Eon, Hitchhiker's Guide, Exponential NDF page; \
             derivations.md B.6).",
            "D",
            |u| g.d(u),
            &[
                ("Gamma(3/2)", &|u| {
                    superpose_beckmann(Mixing::Gamma32, a, |b| b.d(u))
                }),
                ("Chi-3", &|u| {
                    superpose_beckmann(Mixing::Chi3, a, |b| b.d(u))
                }),
            ],
        )],
        _ => Vec::new(),
    }
}

/// The Exponential NDF page's own sampler (three Gaussians and one uniform, the Chi-3
/// superposition: `stochastic::ExponentialChi3`) at the page's α = 0.8: a histogram of θm
/// against the D·cos density.
fn chi3_histogram_plot() -> Plot {
    use microsurface::sampling::stochastic::ExponentialChi3;
    use rand::distr::Distribution;
    use rand::SeedableRng;
    use std::f64::consts::PI;
    let alpha = 0.8;
    let n = ndf(NdfKind::Exponential, alpha, None);
    let sampler = ExponentialChi3::new(alpha).expect("α = 0.8 is valid");
    let mut rng = rand_xorshift::XorShiftRng::seed_from_u64(5);
    let samples = 100_000;
    let hist = theta_histogram(samples, || sampler.sample(&mut rng));
    let curve = grid(0.1, 89.9, 200)
        .into_iter()
        .map(|d| {
            let (s, c) = d.to_radians().sin_cos();
            (d, 2.0 * PI * s * c * n.d(c) * PI / 180.0)
        })
        .collect();
    Plot::new(
        "Exponential α=0.8: the page's 3-Gaussian sampler",
        "θm (degrees)",
        "density per degree",
    )
    .caption(
        "The Exponential NDF page's stochastic sampler: cos θm = 1/√(1 − (α²/2)(g₁² + g₂² + \
         g₃²) ln u₁), three Gaussians and one uniform (the Chi-3 superposition; derivations.md \
         B.6), against 2π sin θ cos θ D(cos θ).",
    )
    .with(Series::new(format!("{samples} samples"), hist, Style::Bars))
    .with(Series::new("pdf", curve, Style::Line))
}

/// α at which NDF `kind` (shape `gamma`) matches GGX at α = 0.3 by `by` (the library's
/// matched roughness, `AnyNdf::matched`).
fn matched_alpha(kind: NdfKind, gamma: Option<f64>, by: MatchBy) -> f64 {
    let ggx = ndf(NdfKind::Ggx, 0.3, None);
    AnyNdf::matched(kind, gamma, &ggx, by)
        .expect("every plotted NDF has a match for GGX at 0.3")
        .alpha()
}

fn comparison_plots() -> Vec<Plot> {
    let kinds: Vec<(NdfKind, Option<f64>, &str)> = vec![
        (NdfKind::Beckmann, None, "Beckmann"),
        (NdfKind::Ggx, None, "GGX"),
        (NdfKind::Gtr, Some(1.5), "GTR γ=1.5"),
        (NdfKind::DoubleGgx, None, "Double GGX"),
        (NdfKind::Exponential, None, "Exponential"),
        (NdfKind::StudentT, Some(4.0), "Student-T γ=4"),
        (NdfKind::Ei, None, "Ei"),
        (NdfKind::Erfc, None, "Erfc"),
        (NdfKind::K0, None, "K0"),
        (NdfKind::BesselK, Some(3.0), "Bessel-K a=3"),
        (NdfKind::GenExponential, Some(4.0), "GenExp γ=4"),
    ];
    let ts = grid(0.0, 89.5, 180);
    let us = grid(0.0, 1.0, 101);
    let u45 = std::f64::consts::FRAC_1_SQRT_2;
    let d_of = |n: &AnyNdf| ts.iter().map(|&t| (t, n.d(t.to_radians().cos()))).collect();
    let g1_of = |n: &AnyNdf| us.iter().map(|&u| (u, n.g1(u))).collect();
    let mut same = Plot::new("All NDFs at α = 0.3: D(θm)", "θm (degrees)", "D")
        .log_y()
        .caption(
            "Every NDF at the same α = 0.3 (GTR at γ = 1.5, the shapes as labelled): α is not \
             comparable across NDFs (mean slopes differ by several times); the next plots match \
             a quantity instead.",
        );
    let mut by_g1 = Plot::new(
        "Matched masking: G1(45°) as GGX α=0.3's",
        "θm (degrees)",
        "D",
    )
    .log_y();
    let mut by_g1_g1 = Plot::new("Matched masking: G1(u)", "u = cos θ", "G1").caption(
        "G1 of the NDFs matched at 45° (previous plot): equal at u = 0.707 by construction, \
         apart towards grazing.",
    );
    let mut by_slope = Plot::new(
        "Matched mean slope: σ(0) as GGX α=0.3's",
        "θm (degrees)",
        "D",
    )
    .log_y()
    .caption(
        "Each NDF's α chosen so that σ(0) = E[max(0, p)], the mean projected slope (GGX: α/2 \
         = 0.15; derivations.md E), equals GGX α = 0.3's: the same grazing projected area.",
    );
    let mut beckmann_alpha = 0.0;
    for (k, g, name) in kinds {
        same = same.with(Series::new(name, d_of(&ndf(k, 0.3, g)), Style::Line));
        let a = matched_alpha(k, g, MatchBy::G1At45);
        if k == NdfKind::Beckmann {
            beckmann_alpha = a;
        }
        let m = ndf(k, a, g);
        by_g1 = by_g1.with(Series::new(
            format!("{name} α={a:.3}"),
            d_of(&m),
            Style::Line,
        ));
        by_g1_g1 = by_g1_g1.with(Series::new(
            format!("{name} α={a:.3}"),
            g1_of(&m),
            Style::Line,
        ));
        let a = matched_alpha(k, g, MatchBy::SigmaZero);
        by_slope = by_slope.with(Series::new(
            format!("{name} α={a:.3}"),
            d_of(&ndf(k, a, g)),
            Style::Line,
        ));
    }
    let by_g1 = by_g1.caption(format!(
        "Each NDF's α chosen so that its masking at 45° incidence equals GGX α = 0.3's \
         (G1(45°) = {:.4}): the masking at moderate angles matches; the peaks and tails of D \
         do not, and the α differ widely (Beckmann {beckmann_alpha:.3}): α is each NDF's own \
         scale, not a common roughness.",
        ndf(NdfKind::Ggx, 0.3, None).g1(u45)
    ));
    vec![same, by_g1, by_g1_g1, by_slope]
}

/// Today's date (UTC) as YYYY-MM-DD, from the system clock (civil-from-days, Hinnant's
/// algorithm; no date crate for one stamp).
fn utc_date() -> String {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let z = (secs / 86_400) as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1_460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}")
}

/// The identity checks as a matrix (NDF and parameters × identity: the worst residual and
/// whether it passed), then every check, folded.
fn identity_tables(
    body: &mut String,
    checks: &[microsurface::check::verify::Check],
    failed: usize,
) {
    let mut subjects: Vec<&str> = Vec::new();
    let mut identities: Vec<&str> = Vec::new();
    for c in checks {
        if !subjects.contains(&c.subject.as_str()) {
            subjects.push(&c.subject);
        }
        if !identities.contains(&c.identity.as_str()) {
            identities.push(&c.identity);
        }
    }
    let _ = write!(
        body,
        r#"<section id="verify"><h2>Identities (microsurface verify): {} checks, {} failed</h2><p>Each identity of the pages checked by an independent numerical integral or superposition (<code>microsurface verify</code>). Cells: the largest relative residual over the check's sample points; red where it exceeds its tolerance (1e-10, or the u-space floor ε·max(1, γ)/α² of checks that integrate over u); empty where the identity does not apply.</p><div class="matrix"><table><tr><th>NDF</th>"#,
        checks.len(),
        failed
    );
    for id in &identities {
        let _ = write!(body, "<th>{}</th>", esc(id));
    }
    body.push_str("</tr>");
    for sub in &subjects {
        let _ = write!(body, "<tr><th>{}</th>", esc(sub));
        for id in &identities {
            match checks
                .iter()
                .find(|c| c.subject == *sub && c.identity == *id)
            {
                Some(c) => {
                    let class = if c.pass() { "pass" } else { "fail" };
                    let _ = write!(body, r#"<td class="{class}">{:.1e}</td>"#, c.residual);
                }
                None => body.push_str("<td></td>"),
            }
        }
        body.push_str("</tr>");
    }
    let _ = write!(
        body,
        r#"</table></div><details><summary>All {} checks, one per row</summary><table><tr><th></th><th>residual</th><th>tolerance</th><th>NDF</th><th>identity</th></tr>"#,
        checks.len()
    );
    for c in checks {
        let (class, word) = if c.pass() {
            ("pass", "PASS")
        } else {
            ("fail", "FAIL")
        };
        let _ = write!(
            body,
            r#"<tr><td class="{class}">{word}</td><td>{:.2e}</td><td>{:.0e}</td><td>{}</td><td>{}</td></tr>"#,
            c.residual,
            c.tol,
            esc(&c.subject),
            esc(&c.identity)
        );
    }
    body.push_str("</table></details></section>");
}

const CSS: &str =
    "body{font-family:sans-serif;max-width:1400px;margin:auto;padding:1em;color:#222}\
h1{font-size:1.6em}h2{border-bottom:2px solid #1f77b4;padding-top:.6em}\
.plots{display:flex;flex-wrap:wrap;gap:10px}\
table{border-collapse:collapse;font-size:12px}td,th{border:1px solid #ccc;padding:2px 6px}\
.pass{color:#2a7a2a}.fail{color:#b00;font-weight:bold}nav a{margin-right:1em}\
figure{margin:0;width:440px}figcaption{font-size:12px;color:#444;margin:2px 4px 8px}\
.def{font-size:14px;color:#333}.stamp{font-size:12px;color:#666}\
.matrix{overflow-x:auto}.matrix th{font-size:11px;font-weight:normal;text-align:left}.matrix td{white-space:nowrap}";

/// One NDF's section of the page.
fn section(kind: NdfKind, progress: &(impl Fn(&str) + Sync)) -> String {
    let mut html = String::new();
    progress(&format!("section {kind}"));
    let _ = write!(
        html,
        r#"<section id="{kind}" class="ndf"><h2>{}</h2><p class="def">{}.</p><div class="plots">"#,
        heading(kind),
        esc(source(kind))
    );
    let mut plots = vec![
        d_plot(kind),
        sigma_plot(kind),
        lambda_plot(kind),
        g1_plot(kind),
        slope_plot(kind),
        histogram_plot(kind, false),
        histogram_plot(kind, true),
    ];
    if kind == NdfKind::Exponential {
        plots.push(approx_error_plot());
        plots.push(ei_sigma_plot());
        plots.extend(exponential_residual_plots());
        plots.push(chi3_histogram_plot());
    }
    if kind == NdfKind::Gtr {
        plots.insert(1, gtr_alpha_plot());
    }
    plots.extend(superposition_plots(kind));
    for p in plots {
        html.push_str(&p.to_html());
    }
    html.push_str("</div></section>");
    html
}

pub fn run(args: &[String]) -> Result<ExitCode, String> {
    let mut out = std::path::PathBuf::from("report");
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        match flag.as_str() {
            "--out" => out = it.next().ok_or("report: --out needs a directory")?.into(),
            other => {
                return Err(format!(
                    "report: unknown option '{}' (see `microsurface report --help`)",
                    crate::clip(other)
                ))
            }
        }
    }
    // Fail before the minutes of computing if the page could not be written.
    std::fs::create_dir_all(&out)
        .map_err(|e| format!("report: cannot create {}: {e}", out.display()))?;
    let path = out.join("index.html");
    let probe = out.join(".microsurface-report-probe");
    std::fs::write(&probe, b"")
        .and_then(|()| std::fs::remove_file(&probe))
        .map_err(|e| format!("report: cannot write in {}: {e}", out.display()))?;
    let start = Instant::now();
    let progress = |what: &str| eprintln!("[{:5.1} s] {what}", start.elapsed().as_secs_f64());
    let mut body = String::new();
    let _ = write!(
        body,
        "<h1>microsurface — the NDF pages, reproduced and verified</h1>\
<p>Every curve below is computed by this library; markers are independent numerical \
integrals or superpositions; histograms are samples of the library's samplers. Sources: \
d'Eon, <i>A Hitchhiker's Guide to Multiple Scattering</i> (2020) and its NDF pages; Burley \
2012, <i>Physically-Based Shading at Disney</i>, appendix B; corrections and derivations \
beyond them in the repository's <code>docs/derivations.md</code>.</p>\
<p class=\"stamp\">Generated by <code>microsurface report</code>, microsurface {}, on {} (UTC).</p><nav>",
        env!("CARGO_PKG_VERSION"),
        utc_date()
    );
    for k in NdfKind::ALL {
        let _ = write!(body, r##"<a href="#{k}">{}</a>"##, short(k));
    }
    body.push_str(
        r##"<a href="#comparison">comparison</a><a href="#bsdf">BSDFs</a><a href="#verify">identity table</a></nav>"##,
    );

    // (The sections are independent: with the CLI's rayon they run on every core.)
    let sections: Vec<String> = {
        use rayon::prelude::*;
        NdfKind::ALL
            .par_iter()
            .map(|&kind| section(kind, &progress))
            .collect()
    };
    for html in sections {
        body.push_str(&html);
    }

    progress("comparison");
    body.push_str(r#"<section id="comparison"><h2>Comparison of the NDFs</h2><div class="plots">"#);
    for p in comparison_plots() {
        body.push_str(&p.to_html());
    }
    body.push_str("</div></section>");

    progress("BSDFs");
    body.push_str(
        r#"<section id="bsdf"><h2>Rough conductor and dielectric BSDFs, every NDF</h2><p class="def">The renderer-facing types (<code>Microfacet</code>, <code>bsdf::RoughConductor</code>, <code>bsdf::RoughDielectric</code>, f64, pbrt-v4's conventions): their lobes, their samplers against their pdfs, and the energy a single-scattering BSDF loses.</p><div class="plots">"#,
    );
    for p in bsdf::plots() {
        body.push_str(&p.to_html());
    }
    body.push_str("</div></section>");

    progress("multiple scattering");
    body.push_str(
        r#"<section id="multiple-scattering"><h2>Multiple scattering, every NDF</h2><p class="def">The microsurface random walk (<code>walk</code>, Heitz, Hanika, d'Eon &amp; Dachsbacher 2016) by scattering order, the single-scattering albedo tables the library ships, and energy compensation (<code>compensate</code>: Kulla &amp; Conty 2017, Turquin 2019).</p><div class="plots">"#,
    );
    for p in ms::plots() {
        body.push_str(&p.to_html());
    }
    body.push_str("</div></section>");

    progress("identity checks (verify)");
    // The default sweep, with Bessel-K at a = 5 only (its checks cost seconds per material:
    // a K_ν of real order inside every quadrature; a = 1 and 3/2 enter through the special
    // cases, a = 0.6 is in tests/identities.rs).
    let mut sweep = Sweep::default();
    sweep.shapes.push((NdfKind::BesselK, vec![5.0]));
    let checks = run_checks(&sweep, |_| {});
    let failed = checks.iter().filter(|c| !c.pass()).count();
    identity_tables(&mut body, &checks, failed);

    let html = format!(
        "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>microsurface report</title><style>{CSS}</style></head><body>{body}</body></html>\n"
    );
    std::fs::write(&path, html)
        .map_err(|e| format!("report: cannot write {}: {e}", path.display()))?;
    progress(&format!("wrote {}", path.display()));
    Ok(if failed == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    })
}
