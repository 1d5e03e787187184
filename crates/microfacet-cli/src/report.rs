//! `microfacet report [--out DIR]`: the source pages reproduced from our own code, as one
//! self-contained HTML page (inline SVG, no scripts, no network): per NDF, D(θ), σ against the
//! projected-area integral, Λ and G1 (with the Exponential page's approximations and their
//! error), the slope densities, sample histograms against their pdfs, the superposition
//! identities, and the table of every identity from `verify`; then a comparison of the NDFs
//! at matched roughness.

use crate::svg::{esc, Plot, Series, Style};
use microfacet::chi2::SplitMix64;
use microfacet::exponential::approx::{ei_g1, g1_rational};
use microfacet::mixture::{superpose_beckmann, superpose_ggx, Mixing};
use microfacet::verify::{run as run_checks, sigma_by_delta_integral, Sweep};
use microfacet::{AnyNdf, Isotropic, Microsurface, Ndf, NdfKind, Vec3};
use std::fmt::Write as _;
use std::process::ExitCode;
use std::time::Instant;

const ALPHAS: [f64; 3] = [0.1, 0.3, 0.6];
const GAMMAS: [f64; 4] = [0.5, 1.0, 1.5, 2.5];

fn grid(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| a + (b - a) * i as f64 / (n - 1) as f64)
        .collect()
}

fn ndf(kind: NdfKind, alpha: f64, gamma: Option<f64>) -> AnyNdf {
    AnyNdf::new(kind, alpha, gamma).expect("report parameters are valid")
}

/// The NDF instances a section shows: three roughnesses, or (GTR) four γ at α = 0.3.
fn members(kind: NdfKind) -> Vec<(String, AnyNdf)> {
    if kind == NdfKind::Gtr {
        GAMMAS
            .iter()
            .map(|&g| (format!("α=0.3 γ={g}"), ndf(kind, 0.3, Some(g))))
            .collect()
    } else {
        ALPHAS
            .iter()
            .map(|&a| (format!("α={a}"), ndf(kind, a, None)))
            .collect()
    }
}

fn d_plot(kind: NdfKind) -> Plot {
    let mut p = Plot::new(format!("{kind}: D(θm)"), "θm (degrees)", "D").log_y();
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
        format!("{kind}: σ(u), formula vs ∫ D Δσ"),
        "u = cos θ",
        "σ(u)",
    );
    for (label, n) in members(kind).into_iter().take(2) {
        let line = grid(-1.0, 1.0, 121)
            .into_iter()
            .map(|u| (u, n.sigma(u)))
            .collect();
        let dots = grid(-0.95, 0.95, 20)
            .into_iter()
            .map(|u| (u, sigma_by_delta_integral(&n, u)))
            .collect();
        p = p
            .with(Series::new(format!("{label} σ"), line, Style::Line))
            .with(Series::new(format!("{label} ∫DΔσ"), dots, Style::Markers));
    }
    p
}

fn lambda_plot(kind: NdfKind) -> Plot {
    let mut p = Plot::new(format!("{kind}: Smith Λ(u)"), "u = cos θ", "Λ").log_y();
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
    let mut p = Plot::new(format!("{kind}: G1(u)"), "u = cos θ", "G1");
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
                Style::Markers,
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
        "exponential: error of the page's G1 approximations",
        "log10(cot θ / α)",
        "|G1 approx − G1 exact|",
    )
    .log_y()
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
    use microfacet::exponential::approx::ei_sigma;
    let mut p = Plot::new(
        "exponential: σ(u) exact vs the page's Ei σ(u, 1.7α)",
        "u = cos θ",
        "σ(u)",
    );
    for a in [0.3, 1.0] {
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

/// GTR's D for α on both sides of 1 (α > 1 is allowed: D then grows towards grazing).
fn gtr_alpha_plot() -> Plot {
    let mut p = Plot::new("gtr γ=1.5: D(θm) for α < 1 and α > 1", "θm (degrees)", "D").log_y();
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
    let mut p = Plot::new(format!("{kind}: slope densities"), "p", "P2(p), P22(p, 0)").log_y();
    for (label, n) in members(kind).into_iter().take(2) {
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

/// Histogram of θm of samples against the density of θm: 2π sin θ cos θ D(cos θ) for D·cos,
/// sin θ times the φ-integral of the visible density for visible normals (per degree).
fn histogram_plot(kind: NdfKind, visible: bool) -> Plot {
    use std::f64::consts::PI;
    let n = if kind == NdfKind::Gtr {
        ndf(kind, 0.3, Some(1.5))
    } else {
        ndf(kind, 0.3, None)
    };
    let m = Isotropic(n);
    let wi = {
        let t = 60f64.to_radians();
        Vec3::new(t.sin(), 0.0, t.cos())
    };
    let samples = if visible { 20_000 } else { 100_000 };
    let bins = 60;
    let width = 90.0 / bins as f64;
    let mut counts = vec![0.0; bins];
    let mut rng = SplitMix64(11);
    for _ in 0..samples {
        let u = [rng.next_f64(), rng.next_f64()];
        let wm = if visible {
            m.sample_visible(wi, u)
        } else {
            m.sample_dcos(u)
        };
        let theta = wm.z.clamp(-1.0, 1.0).acos().to_degrees();
        let b = ((theta / width) as usize).min(bins - 1);
        counts[b] += 1.0;
    }
    let hist = counts
        .iter()
        .enumerate()
        .map(|(i, c)| ((i as f64 + 0.5) * width, c / (samples as f64 * width)))
        .collect();
    let density = |deg: f64| {
        let t = deg.to_radians();
        let (s, c) = t.sin_cos();
        let per_rad = if visible {
            // sin θ ∫ d_visible dφ over the circle at θ (midpoint rule: smooth and periodic).
            let k = 256;
            let ring: f64 = (0..k)
                .map(|j| {
                    let phi = 2.0 * PI * (j as f64 + 0.5) / k as f64;
                    m.d_visible(wi, Vec3::new(s * phi.cos(), s * phi.sin(), c))
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
    Plot::new(
        format!("{kind} {label}: {what}"),
        "θm (degrees)",
        "density per degree",
    )
    .with(Series::new(format!("{samples} samples"), hist, Style::Bars))
    .with(Series::new("pdf", curve, Style::Line))
}

/// The pages' superposition identities as overlaid curves.
fn superposition_plots(kind: NdfKind) -> Vec<Plot> {
    let us = grid(0.05, 0.999, 60);
    let a = 0.3;
    let mut out = Vec::new();
    let thetas = |v: &Vec<f64>| v.iter().map(|u| u.acos().to_degrees()).collect::<Vec<_>>();
    let t = thetas(&us);
    let mk = |title: String, closed: Vec<f64>, mixes: Vec<(&str, Vec<f64>)>, y: &str| {
        let mut p = Plot::new(title, "θ (degrees)", y).log_y().with(Series::new(
            "closed form",
            t.iter().copied().zip(closed).collect(),
            Style::Line,
        ));
        for (name, v) in mixes {
            p = p.with(Series::new(
                name,
                t.iter().copied().zip(v).collect(),
                Style::Markers,
            ));
        }
        p
    };
    match kind {
        NdfKind::Ggx => {
            let g = ndf(kind, a, None);
            out.push(mk(
                "GGX D as superpositions of Beckmann D (α=0.3)".into(),
                us.iter().map(|&u| g.d(u)).collect(),
                vec![
                    (
                        "Fréchet-2",
                        us.iter()
                            .map(|&u| superpose_beckmann(Mixing::Frechet2, a, |b| b.d(u)))
                            .collect(),
                    ),
                    (
                        "Gamma-1",
                        us.iter()
                            .map(|&u| superpose_beckmann(Mixing::Gamma1, a, |b| b.d(u)))
                            .collect(),
                    ),
                ],
                "D",
            ));
            out.push(mk(
                "GGX Λ as a Gamma-1 superposition of Beckmann Λ".into(),
                us.iter().map(|&u| g.lambda(u)).collect(),
                vec![(
                    "Gamma-1",
                    us.iter()
                        .map(|&u| superpose_beckmann(Mixing::Gamma1, a, |b| b.lambda(u)))
                        .collect(),
                )],
                "Λ",
            ));
        }
        NdfKind::DoubleGgx => {
            let g = ndf(kind, a, None);
            out.push(mk(
                "Double GGX D as a Gamma-1 superposition of GGX D".into(),
                us.iter().map(|&u| g.d(u)).collect(),
                vec![(
                    "Gamma-1",
                    us.iter()
                        .map(|&u| superpose_ggx(Mixing::Gamma1, a, |c| c.d(u)))
                        .collect(),
                )],
                "D",
            ));
            out.push(mk(
                "Double GGX Λ as a Gamma-1 superposition of GGX Λ".into(),
                us.iter().map(|&u| g.lambda(u)).collect(),
                vec![(
                    "Gamma-1",
                    us.iter()
                        .map(|&u| superpose_ggx(Mixing::Gamma1, a, |c| c.lambda(u)))
                        .collect(),
                )],
                "Λ",
            ));
        }
        NdfKind::Exponential => {
            let g = ndf(kind, a, None);
            out.push(mk(
                "Exponential D as superpositions of Beckmann D".into(),
                us.iter().map(|&u| g.d(u)).collect(),
                vec![
                    (
                        "Gamma(3/2)",
                        us.iter()
                            .map(|&u| superpose_beckmann(Mixing::Gamma32, a, |b| b.d(u)))
                            .collect(),
                    ),
                    (
                        "Chi-3",
                        us.iter()
                            .map(|&u| superpose_beckmann(Mixing::Chi3, a, |b| b.d(u)))
                            .collect(),
                    ),
                ],
                "D",
            ));
        }
        _ => {}
    }
    out
}

/// α at which `kind` has the same G1 at 45° as GGX with α = 0.3 (bisection in ln α).
fn matched_alpha(kind: NdfKind, gamma: Option<f64>) -> f64 {
    let u45 = std::f64::consts::FRAC_1_SQRT_2;
    let target = ndf(NdfKind::Ggx, 0.3, None).g1(u45);
    let (mut lo, mut hi) = (1e-3f64.ln(), 10f64.ln());
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if ndf(kind, mid.exp(), gamma).g1(u45) > target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (0.5 * (lo + hi)).exp()
}

fn comparison_plots() -> Vec<Plot> {
    let kinds: Vec<(NdfKind, Option<f64>, &str)> = vec![
        (NdfKind::Beckmann, None, "Beckmann"),
        (NdfKind::Ggx, None, "GGX"),
        (NdfKind::Gtr, Some(1.5), "GTR γ=1.5"),
        (NdfKind::DoubleGgx, None, "Double GGX"),
        (NdfKind::Exponential, None, "Exponential"),
    ];
    let ts = grid(0.0, 89.5, 180);
    let mut same = Plot::new("All NDFs at α = 0.3: D(θm)", "θm (degrees)", "D").log_y();
    let mut matched =
        Plot::new("Matched G1(45°) (= GGX α=0.3): D(θm)", "θm (degrees)", "D").log_y();
    let mut g1 = Plot::new("Matched G1(45°): G1(u)", "u = cos θ", "G1");
    for (k, g, name) in kinds {
        let n = ndf(k, 0.3, g);
        same = same.with(Series::new(
            name,
            ts.iter().map(|&t| (t, n.d(t.to_radians().cos()))).collect(),
            Style::Line,
        ));
        let a = matched_alpha(k, g);
        let m = ndf(k, a, g);
        matched = matched.with(Series::new(
            format!("{name} α={a:.3}"),
            ts.iter().map(|&t| (t, m.d(t.to_radians().cos()))).collect(),
            Style::Line,
        ));
        g1 = g1.with(Series::new(
            format!("{name} α={a:.3}"),
            grid(0.0, 1.0, 101)
                .into_iter()
                .map(|u| (u, m.g1(u)))
                .collect(),
            Style::Line,
        ));
    }
    vec![same, matched, g1]
}

const CSS: &str =
    "body{font-family:sans-serif;max-width:1400px;margin:auto;padding:1em;color:#222}\
h1{font-size:1.6em}h2{border-bottom:2px solid #1f77b4;padding-top:.6em}\
.plots{display:flex;flex-wrap:wrap;gap:10px}\
table{border-collapse:collapse;font-size:12px}td,th{border:1px solid #ccc;padding:2px 6px}\
.pass{color:#2a7a2a}.fail{color:#b00;font-weight:bold}nav a{margin-right:1em}";

pub fn run(args: &[String]) -> Result<ExitCode, String> {
    let mut out = std::path::PathBuf::from("report");
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        match flag.as_str() {
            "--out" => out = it.next().ok_or("report: --out needs a directory")?.into(),
            other => return Err(format!("report: unknown option '{other}'")),
        }
    }
    let start = Instant::now();
    let progress = |what: &str| eprintln!("[{:5.1} s] {what}", start.elapsed().as_secs_f64());
    let mut body = String::new();
    let _ = write!(
        body,
        "<h1>microfacet — the NDF pages, reproduced and verified</h1>\
<p>Every curve below is computed by this library; markers are independent numerical \
integrals or superpositions; histograms are samples of the library's samplers. \
Generated by <code>microfacet report</code>.</p><nav>"
    );
    for k in NdfKind::ALL {
        let _ = write!(body, r##"<a href="#{k}">{k}</a>"##);
    }
    body.push_str(
        r##"<a href="#comparison">comparison</a><a href="#verify">identity table</a></nav>"##,
    );

    for kind in NdfKind::ALL {
        progress(&format!("section {kind}"));
        let _ = write!(
            body,
            r#"<section id="{kind}" class="ndf"><h2>{kind}</h2><div class="plots">"#
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
        }
        if kind == NdfKind::Gtr {
            plots.insert(1, gtr_alpha_plot());
        }
        plots.extend(superposition_plots(kind));
        for p in plots {
            body.push_str(&p.to_svg());
        }
        body.push_str("</div></section>");
    }

    progress("comparison");
    body.push_str(
        r#"<section id="comparison"><h2>Comparison at matched roughness</h2><div class="plots">"#,
    );
    for p in comparison_plots() {
        body.push_str(&p.to_svg());
    }
    body.push_str("</div></section>");

    progress("identity checks (verify)");
    let checks = run_checks(&Sweep::default(), |_| {});
    let failed = checks.iter().filter(|c| !c.pass()).count();
    let _ = write!(
        body,
        r#"<section id="verify"><h2>Identities (microfacet verify): {} checks, {} failed</h2><table><tr><th></th><th>residual</th><th>tolerance</th><th>NDF</th><th>identity</th></tr>"#,
        checks.len(),
        failed
    );
    for c in &checks {
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
    body.push_str("</table></section>");

    let html = format!(
        "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>microfacet report</title><style>{CSS}</style></head><body>{body}</body></html>\n"
    );
    std::fs::create_dir_all(&out)
        .map_err(|e| format!("report: cannot create {}: {e}", out.display()))?;
    let path = out.join("index.html");
    std::fs::write(&path, html)
        .map_err(|e| format!("report: cannot write {}: {e}", path.display()))?;
    progress(&format!("wrote {}", path.display()));
    Ok(if failed == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    })
}
