//! The random walk's BSDF (`scattering::MultipleScattering`) under multiple importance
//! sampling (MIS): the variance of one pixel's estimator of
//! Lo(wo) = ∫ f(wo, wi) L(wi) |cos θi| dωi with BSDF sampling alone, and with one BSDF and
//! one light sample combined by the power heuristic, for several stand-ins for the BSDF's
//! density in the weights (the BSDF's `pdf`: the walk's density has no closed form).
//! BENCHMARKS.md ("The walk under MIS") has the tables and the runs:
//!
//! ```text
//! cargo run --release -p microsurface --example walk_mis [SAMPLES [SEED]]   # the study
//! cargo run --release -p microsurface --example walk_mis api [SAMPLES [SEED]]
//! cargo run --release -p microsurface --example walk_mis peff [SAMPLES]
//! ```
//!
//! * The study: an F = 1 GGX conductor, α ∈ {0.05, 0.1, 0.2, 0.5, 1, 2}, θo ∈ {0°, 45°,
//!   75°}, under three environments over the whole sphere, each light-sampled in proportion
//!   to its radiance L (an environment map's importance sampling, p_L = L/∫L): `sky`, the
//!   white furnace (1) plus a dome 4 max(0, cos θ); `sun`, the furnace plus 500 in a cap of
//!   5° (about as much power as the furnace); `lamp`, the furnace plus 50 in a cap of 15°;
//!   the caps at wo's mirror direction (`spec`) or at θ = 50° across the plane of incidence
//!   (`off`). Every column uses the same walks and light directions (common random
//!   numbers), so the columns differ by their weights alone.
//! * `api`: the library's conductor, dielectric (η = 1.5) and diffuse-facet walk BSDFs
//!   through the `Bsdf` trait (`sample`, `eval`, `pdf`), the caps off the specular direction.
//! * `peff`: the balance-optimal stand-in for the evaluation's noise, E[X²]/E[X] for X one
//!   `eval` times |cos θi|, beyond single scattering's p1: what the floor of
//!   `MultipleScattering::pdf` is fitted to.

use microsurface::bsdf::fresnel::One;
use microsurface::prelude::*;
use microsurface::scattering::{AlbedoTable, MirrorFacets, MultipleScattering, WalkRng};
use std::f64::consts::{FRAC_1_PI, PI};

type Dist = Microfacet<f64, Ggx>;

/// L(w) = 1 (the furnace) + S max(0, w.z) (a sky dome, brightest at the zenith) + Ls in a
/// cap (a sun), light-sampled in proportion to L.
struct Env {
    dome: f64,
    center: [f64; 3],
    cos_cap: f64,
    radiance: f64,
    /// Ω of the cap and Φ = ∫L = 4π + π S + Ls Ω.
    omega: f64,
    phi: f64,
    frame: Frame<f64>,
}

impl Env {
    fn new(dome: f64, center: [f64; 3], cap_deg: f64, radiance: f64) -> Self {
        let cos_cap = cap_deg.to_radians().cos();
        let omega = 2.0 * PI * (1.0 - cos_cap);
        Env {
            dome,
            center,
            cos_cap,
            radiance,
            omega,
            phi: 4.0 * PI + PI * dome + radiance * omega,
            frame: Frame::from_normal(center),
        }
    }

    fn l(&self, w: [f64; 3]) -> f64 {
        let c = w[0] * self.center[0] + w[1] * self.center[1] + w[2] * self.center[2];
        let sun = if c >= self.cos_cap {
            self.radiance
        } else {
            0.0
        };
        1.0 + self.dome * w[2].max(0.0) + sun
    }

    fn max_l(&self) -> f64 {
        1.0 + self.dome + self.radiance
    }

    fn pdf(&self, w: [f64; 3]) -> f64 {
        self.l(w) / self.phi
    }

    fn sample(&self, rng: &mut WalkRng) -> [f64; 3] {
        let (u0, u1, u2) = (rng.next_open() * self.phi, rng.next_open(), rng.next_open());
        let p = 2.0 * PI * u2;
        if u0 < self.radiance * self.omega {
            let c = 1.0 - u1 * (1.0 - self.cos_cap);
            let s = ((1.0 - c) * (1.0 + c)).max(0.0).sqrt();
            self.frame.from_local([s * p.cos(), s * p.sin(), c])
        } else if u0 < self.radiance * self.omega + PI * self.dome {
            // Cosine-weighted about the zenith.
            let c = u1.sqrt();
            let s = ((1.0 - c) * (1.0 + c)).max(0.0).sqrt();
            [s * p.cos(), s * p.sin(), c]
        } else {
            let c = 1.0 - 2.0 * u1;
            let s = ((1.0 - c) * (1.0 + c)).max(0.0).sqrt();
            [s * p.cos(), s * p.sin(), c]
        }
    }
}

/// What the proxies need about the material at one wo.
struct Material {
    ms: MultipleScattering<Dist, MirrorFacets<One<1>>, 1>,
    single: RoughConductor<f64, Dist, One<1>, 1>,
    table: AlbedoTable,
}

/// The MIS proxies compared (the BSDF side's density in the power heuristic).
#[derive(Clone, Copy)]
enum Proxy {
    /// The library's stand-in before this study (its docs: the paper's MIS proxy):
    /// (1 − q) p1 + q |cos θi|/π with q = 1 − G1(wo) clamped to [0.05, 0.95].
    Paper,
    /// Single scattering's f|cos θi| (F = 1) plus Kulla–Conty's multiple-scattering lobe:
    /// a density (∫ = E(μo) + 1 − E(μo) = 1) shaped as the walk's exits are.
    Kc,
    /// p1 + β |cos θi|/π (not a density).
    Cosine(f64),
    /// p1 + 3 max(1, α) |cos θi|/π + b/(π α² max(|cos θi|, 0.01)): the library's form
    /// with another b.
    Spikes(f64),
    /// `MultipleScattering::pdf` (the form above with b = 0.05).
    Library,
}

fn proxy_name(p: Proxy) -> String {
    match p {
        Proxy::Paper => "paper".into(),
        Proxy::Kc => "ss+KC".into(),
        Proxy::Cosine(b) => format!("p1+{b}c/π"),
        Proxy::Spikes(b) => format!("b={b}"),
        Proxy::Library => "library".into(),
    }
}

fn proxy(p: Proxy, m: &Material, alpha: f64, wo: [f64; 3], wi: [f64; 3]) -> f64 {
    // (Below the horizon, and NaN, the conductor has no density.)
    if wi[2].is_nan() || wi[2] <= 0.0 {
        return 0.0;
    }
    let cos = wi[2] * FRAC_1_PI;
    let p1 = || m.single.pdf(wo, wi);
    match p {
        Proxy::Paper => {
            let q = (1.0 - m.single.distribution().g1(wo)).clamp(0.05, 0.95);
            (1.0 - q) * p1() + q * cos
        }
        Proxy::Kc => {
            m.single.eval(wo, wi)[0] * wi[2]
                + (1.0 - m.table.e(wo[2])).max(0.0) * (1.0 - m.table.e(wi[2])).max(0.0) * cos
                    / m.table.lost_avg()
        }
        Proxy::Cosine(b) => p1() + b * cos,
        Proxy::Spikes(b) => {
            p1() + 3.0 * alpha.max(1.0) * cos + b * FRAC_1_PI / (alpha * alpha * wi[2].max(0.01))
        }
        Proxy::Library => m.ms.pdf(wo, wi),
    }
}

/// The power heuristic's weight of a strategy of density `p` against one of density `q`.
fn power(p: f64, q: f64) -> f64 {
    if p > 0.0 {
        p * p / (p * p + q * q)
    } else {
        0.0
    }
}

#[derive(Default, Clone)]
struct Stat {
    n: f64,
    s: f64,
    s2: f64,
}

impl Stat {
    fn add(&mut self, x: f64) {
        self.n += 1.0;
        self.s += x;
        self.s2 += x * x;
    }
    fn mean(&self) -> f64 {
        self.s / self.n
    }
    fn var(&self) -> f64 {
        (self.s2 / self.n - self.mean().powi(2)).max(0.0) * self.n / (self.n - 1.0)
    }
    fn se(&self) -> f64 {
        (self.var() / self.n).sqrt()
    }
}

/// The balance-optimal competitor of a light sample, p_eff = E[X²]/E[X] for X = ê|cos θi|,
/// ê one stochastic evaluation (for an exact evaluation p_eff = f|cos θi|, the walk's own
/// density), less single scattering's sampling density p1, in absolute units (per
/// steradian), averaged over four azimuths of wi (0, 60°, 120°, 180° from wo's).
fn peff(samples: u64) {
    let thetas = [10.0f64, 30.0, 50.0, 70.0, 80.0, 85.0];
    println!("p_eff − p1 (sr⁻¹), mean over 4 azimuths; columns θi = {thetas:?}");
    for alpha in [0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 4.0] {
        let d = Dist::new(alpha, alpha).unwrap();
        let ms = MultipleScattering::new(d.clone(), MirrorFacets(One::<1>));
        let single = RoughConductor::new(d.clone(), One::<1>);
        for theta_o in [0.0f64, 45.0, 75.0] {
            let t = theta_o.to_radians();
            let wo = [t.sin(), 0.0, t.cos()];
            print!("α={alpha:<5} θo={theta_o:<3}");
            for ti in thetas {
                let mut excess = 0.0;
                for pi in [0.0f64, 60.0, 120.0, 180.0] {
                    let (ti, pi) = (ti.to_radians(), pi.to_radians());
                    let wi = [ti.sin() * pi.cos(), ti.sin() * pi.sin(), ti.cos()];
                    let mut rng = WalkRng::new(7);
                    let (mut s1, mut s2) = (0.0, 0.0);
                    for _ in 0..samples {
                        let e = ms.surface().eval(ms.facets(), wo, wi, &mut rng);
                        let x = e[0][0] + e[1][0] + e[2][0] + e[3][0];
                        s1 += x;
                        s2 += x * x;
                    }
                    excess += 0.25 * (s2 / s1 - single.pdf(wo, wi));
                }
                print!(" {excess:>8.3}");
            }
            println!();
        }
    }
}

/// One pixel through the `Bsdf` trait itself (`sample`, `eval`, `pdf`): the variance of BSDF
/// sampling alone, and Var MIS/Var BSDF with the BSDF's own `pdf`, and the fireflies per 10⁶.
fn pixel(
    bsdf: &impl Bsdf<f64, Value = [f64; 1]>,
    wo: [f64; 3],
    env: &Env,
    samples: u64,
    seed: u64,
) -> (f64, f64, f64, f64, f64, f64) {
    let mut rng = WalkRng::new(seed);
    let (mut b, mut m) = (Stat::default(), Stat::default());
    let mut xs = Vec::with_capacity(samples as usize);
    for _ in 0..samples {
        let u = [rng.next_open(), rng.next_open(), rng.next_open()];
        let (xb, w_b) = match bsdf.sample(wo, u[0], [u[1], u[2]]) {
            Some(s) => {
                let x = s.f[0] * s.wi[2].abs() / s.pdf * env.l(s.wi);
                (x, power(s.pdf, env.pdf(s.wi)))
            }
            None => (0.0, 0.0),
        };
        b.add(xb);
        let wl = env.sample(&mut rng);
        let pl = env.pdf(wl);
        let fl = bsdf.eval(wo, wl)[0] * wl[2].abs() * env.l(wl) / pl;
        let x = w_b * xb + power(pl, bsdf.pdf(wo, wl)) * fl;
        m.add(x);
        xs.push(x);
    }
    let bound = (20.0 * b.mean()).max(env.max_l());
    let fireflies = xs.iter().filter(|&&x| x > bound).count() as f64 * 1e6 / samples as f64;
    let dev = (m.mean() - b.mean()).abs() / m.se().hypot(b.se());
    (
        b.var(),
        m.var() / b.var(),
        fireflies,
        dev,
        b.mean(),
        m.mean(),
    )
}

/// The library's walk BSDFs through the `Bsdf` trait: the conductor, a dielectric (η = 1.5,
/// seen from outside; the environment covers both sides) and diffuse facets (ρ = 0.9).
fn api(samples: u64, seed: u64) {
    use microsurface::scattering::{DielectricFacets, DiffuseFacets};
    println!("Through the Bsdf trait, {samples} samples a pixel, seed {seed}: Var BSDF, Var MIS/Var BSDF, fireflies per 10⁶, |Δ|/σ");
    for (env_name, dome, cap_deg, radiance) in [
        ("sky", 4.0, 5.0, 0.0),
        ("sun", 0.0, 5.0, 500.0),
        ("lamp", 0.0, 15.0, 50.0),
    ] {
        let off = 50f64.to_radians();
        let env = Env::new(dome, [0.0, off.sin(), off.cos()], cap_deg, radiance);
        for alpha in [0.05, 0.1, 0.5] {
            let d = Dist::new(alpha, alpha).unwrap();
            let conductor = MultipleScattering::new(d.clone(), MirrorFacets(One::<1>));
            let dielectric =
                MultipleScattering::<_, _, 1>::new(d.clone(), DielectricFacets::new(1.5).unwrap());
            let diffuse = MultipleScattering::<_, _, 1>::new(d.clone(), DiffuseFacets(0.9));
            for theta_o in [0.0f64, 45.0, 75.0] {
                let t = theta_o.to_radians();
                let wo = [t.sin(), 0.0, t.cos()];
                print!("{env_name:>5} α={alpha:<5} θo={theta_o:<3}");
                for (name, r) in [
                    ("conductor", pixel(&conductor, wo, &env, samples, seed)),
                    ("dielectric", pixel(&dielectric, wo, &env, samples, seed)),
                    ("diffuse", pixel(&diffuse, wo, &env, samples, seed)),
                ] {
                    print!(
                        " | {name} {:>9.3e} {:>7.3} {:>5} {:>4.2} {:.4} {:.4}",
                        r.0, r.1, r.2, r.3, r.4, r.5
                    );
                }
                println!();
            }
        }
    }
}

fn main() {
    if std::env::args().nth(1).as_deref() == Some("peff") {
        let n = std::env::args()
            .nth(2)
            .and_then(|a| a.parse().ok())
            .unwrap_or(100_000);
        return peff(n);
    }
    if std::env::args().nth(1).as_deref() == Some("api") {
        let arg = |k: usize, d: u64| {
            std::env::args()
                .nth(k)
                .and_then(|a| a.parse().ok())
                .unwrap_or(d)
        };
        return api(arg(2, 200_000), arg(3, 1));
    }
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("a number"))
        .collect();
    let samples = args.first().copied().unwrap_or(200_000.0) as u64;
    let seed = args.get(1).copied().unwrap_or(1.0) as u64;
    let proxies = [
        Proxy::Paper,
        Proxy::Kc,
        Proxy::Cosine(10.0),
        Proxy::Spikes(0.015),
        Proxy::Spikes(0.025),
        Proxy::Library,
    ];
    println!("GGX F = 1 conductor, {samples} samples a pixel, seed {seed}.");
    println!("Var BSDF: BSDF sampling alone (the walk); then Var MIS/Var BSDF and fireflies");
    println!("(samples above max(20 × mean, max L), which BSDF sampling never returns) per 10⁶");
    println!("for each proxy; `GGX ss`: the same ratio for the single-scattering conductor");
    println!("(exact f and pdf); |Δ|/σ: the largest gap between a MIS mean and the BSDF mean.");
    print!(
        "{:>5} {:>5} {:>3} {:>4} {:>9} {:>7}",
        "env", "α", "θo", "cap", "Var BSDF", "mean"
    );
    for p in proxies {
        print!(" {:>12}", proxy_name(p));
    }
    println!(" {:>7} {:>5}", "GGX ss", "|Δ|/σ");
    for (env_name, dome, cap_deg, radiance) in [
        ("sky", 4.0, 5.0, 0.0),
        ("sun", 0.0, 5.0, 500.0),
        ("lamp", 0.0, 15.0, 50.0),
    ] {
        for alpha in [0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 4.0] {
            let d = Dist::new(alpha, alpha).unwrap();
            let m = Material {
                ms: MultipleScattering::new(d.clone(), MirrorFacets(One::<1>)),
                single: RoughConductor::new(d.clone(), One::<1>),
                table: AlbedoTable::compute(&d),
            };
            for theta_o in [0.0f64, 45.0, 75.0] {
                let t = theta_o.to_radians();
                let wo = [t.sin(), 0.0, t.cos()];
                let off = 50f64.to_radians();
                let caps: &[(&str, [f64; 3])] = if radiance > 0.0 {
                    &[
                        ("spec", [-t.sin(), 0.0, t.cos()]),
                        ("off", [0.0, off.sin(), off.cos()]),
                    ]
                } else {
                    &[("-", [0.0, 0.0, 1.0])]
                };
                for &(cap_name, center) in caps {
                    let env = Env::new(dome, center, cap_deg, radiance);
                    let mut rng = WalkRng::new(
                        seed ^ (alpha.to_bits() >> 3) ^ theta_o.to_bits() ^ center[1].to_bits(),
                    );
                    let mut b = Stat::default();
                    let mut xs = vec![Vec::with_capacity(samples as usize); proxies.len()];
                    let (mut ss_b, mut ss_mis) = (Stat::default(), Stat::default());
                    for _ in 0..samples {
                        // The BSDF sample: the walk (its weight is 1 here, F = 1, unless cut).
                        let walked = m.ms.surface().walk(m.ms.facets(), wo, &mut rng);
                        let (wb, xb) = match walked {
                            Some(p) => (p.w, p.weight[0] * env.l(p.w)),
                            None => ([0.0, 0.0, 1.0], 0.0),
                        };
                        b.add(xb);
                        let pl_b = env.pdf(wb);
                        // The light sample and its stochastic evaluation.
                        let wl = env.sample(&mut rng);
                        let pl = env.pdf(wl);
                        let fl = if wl[2] > 0.0 {
                            let e = m.ms.surface().eval(m.ms.facets(), wo, wl, &mut rng);
                            (e[0][0] + e[1][0] + e[2][0] + e[3][0]) * env.l(wl) / pl
                        } else {
                            0.0
                        };
                        for (k, &p) in proxies.iter().enumerate() {
                            let w_b = power(proxy(p, &m, alpha, wo, wb), pl_b);
                            let w_l = power(pl, proxy(p, &m, alpha, wo, wl));
                            xs[k].push(w_b * xb + w_l * fl);
                        }
                        // The single-scattering conductor, the same way.
                        let u = [rng.next_open(), rng.next_open(), rng.next_open()];
                        let (xs_b, ws_b, ps_b) = match m.single.sample(wo, u[0], [u[1], u[2]]) {
                            Some(s) => (s.f[0] * s.wi[2] / s.pdf * env.l(s.wi), s.wi, s.pdf),
                            None => (0.0, [0.0, 0.0, 1.0], 0.0),
                        };
                        ss_b.add(xs_b);
                        let fs_l = m.single.eval(wo, wl)[0] * wl[2].max(0.0) * env.l(wl) / pl;
                        ss_mis.add(
                            power(ps_b, env.pdf(ws_b)) * xs_b
                                + power(pl, m.single.pdf(wo, wl)) * fs_l,
                        );
                    }
                    print!(
                        "{env_name:>5} {alpha:>5} {theta_o:>3} {cap_name:>4} {:>9.3e} {:>7.3}",
                        b.var(),
                        b.mean()
                    );
                    let bound = (20.0 * b.mean()).max(env.max_l());
                    let mut dev: f64 = 0.0;
                    for x in &xs {
                        let mut s = Stat::default();
                        let mut fireflies = 0u64;
                        for &x in x {
                            s.add(x);
                            fireflies += u64::from(x > bound);
                        }
                        print!(
                            " {:>6.3}/{:<5}",
                            s.var() / b.var(),
                            (fireflies as f64 * 1e6 / samples as f64).round()
                        );
                        dev = dev.max((s.mean() - b.mean()).abs() / s.se().hypot(b.se()));
                    }
                    println!(" {:>7.3} {dev:>5.2}", ss_mis.var() / ss_b.var());
                }
            }
        }
    }
}
