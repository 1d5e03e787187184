//! Identity checks: every identity of the source pages, evaluated by independent numerical
//! integration ([`crate::check::quad`]) for any NDF, returning the residual achieved. This is the
//! library side of `microsurface verify` and of the identity tests.
//!
//! Residuals are relative: |lhs − rhs| / max(|lhs|, |rhs|) (0 when both are 0), maximised over
//! the sample points of a check. Each check passes when its residual is at most its tolerance:
//! [`TOL`], or [`u_space_tol`] for the checks that integrate over u at very small α. Every
//! accepted parameter is checked, except Student-T's Λ integrals below
//! [`STUDENT_T_CHECKED_GAMMA_MIN`] (their quadratures cannot reach the mass; such a check is
//! reported as skipped, with the reason, and passes).

use crate::math::quad::{integrate, integrate_to_inf};
use crate::math::smith::{delta_sigma, delta_sigma_at};
use crate::ndf::mixture::{superpose_beckmann, superpose_ggx, Mixing};
use crate::{AnyNdf, DoubleGgx, Exponential, Ggx, Gtr, Ndf, NdfKind, RadialSlopes};
use std::f64::consts::PI;

/// Tolerance on every residual. The quadratures are asked for 1e-13 and typically reach it;
/// 1e-10 is the accuracy promised for the library's own numerical quantities.
pub const TOL: f64 = 1e-10;

/// Tolerance of the checks that integrate over u = cos θ (∫ D cos, the delta integral).
///
/// Near the normal D varies on the scale α² in u (GTR: α²/γ, since D ∝ (α² + 2(1 − u))^{−γ}
/// there), so rounding a quadrature node u = 1 − ε to f64 (an error of up to ulp(1)/2)
/// changes D by up to ~ε_mach/α² relative (GTR: γ ε_mach/α² for γ > 1): below α ≈ 1.5e-3
/// such a check cannot be more accurate than that, whatever the library does. The
/// slope-space checks (∫∫ P22 = 1 among them) have no such floor.
pub fn u_space_tol(alpha: f64, gamma: Option<f64>) -> f64 {
    let width = gamma.unwrap_or(1.0).max(1.0);
    TOL.max(width * f64::EPSILON / (alpha * alpha))
}

/// Direction cosines at which pointwise identities are checked.
pub const US: [f64; 6] = [0.02, 0.2, 0.5, 0.8, 0.95, 0.999];
/// Slopes at which slope identities are checked.
pub const PS: [f64; 5] = [0.0, 0.01, 0.3, 1.0, 5.0];

/// One identity check.
#[derive(Clone, Debug)]
pub struct Check {
    /// NDF and parameters, e.g. `gtr α=0.3 γ=1.5`.
    pub subject: String,
    /// The identity, in the pages' notation.
    pub identity: String,
    /// Largest relative residual over the check's sample points.
    pub residual: f64,
    /// Tolerance.
    pub tol: f64,
    /// Why the check was not made (its residual is then NaN): parameters where its
    /// quadrature cannot resolve the integral (see [`ndf_checks`]).
    pub skipped: Option<&'static str>,
}

impl Check {
    /// Passed, or skipped (a NaN residual of a check that was made fails).
    pub fn pass(&self) -> bool {
        self.skipped.is_some() || self.residual <= self.tol
    }
}

/// Below this γ, Student-T's Λ-integral checks are skipped: Λ ∝ 1/(2γ − 3) comes from the
/// tail P2 ~ p^{1−2γ}, whose mass within the double range (slopes to 1e308) falls short of the
/// whole by (1e308)^{−(2γ−3)} ≥ 1e-10 below γ ≈ 1.52, and the quadratures lose it
/// before that (measured: 5e-10 at 1.53, 1e-11 at 1.54). The values there are checked
/// against mpmath instead (tests/data, γ = 1.2 and 1.6).
pub const STUDENT_T_CHECKED_GAMMA_MIN: f64 = 1.55;

/// Why the heavy-tailed Student-T's Λ checks are skipped ([`STUDENT_T_CHECKED_GAMMA_MIN`]).
const HEAVY_TAIL: &str =
    "Student-T below γ = 1.55: Λ lives at slopes beyond the quadratures' reach";

/// Which NDFs and parameters to sweep.
#[derive(Clone, Debug)]
pub struct Sweep {
    pub kinds: Vec<NdfKind>,
    pub alphas: Vec<f64>,
    /// The shape parameters of the kinds that have one ([`NdfKind::shape_name`]): γ of GTR,
    /// Student-T and the generalised exponential, a of Bessel-K. A kind with a shape that is
    /// missing here is swept over [`default_shapes`].
    pub shapes: Vec<(NdfKind, Vec<f64>)>,
}

/// The default shape parameters of a kind: GTR γ across the special cases 1, 3/2, 2 and
/// general values on both sides of 1; Student-T near the pole γ = 3/2, at GGX (2) and heavy to
/// near-Beckmann; Bessel-K a = 1 (K0), 3/2 (Exponential) and on both sides; the generalised
/// exponential from stretched tails to a near-flat disk, with γ = 1 and 2 (Exponential(2α),
/// Beckmann). (Student-T between γ = 3/2 and [`STUDENT_T_CHECKED_GAMMA_MIN`] skips its Λ
/// integrals: see there.)
pub fn default_shapes(kind: NdfKind) -> Vec<f64> {
    match kind {
        NdfKind::Gtr => vec![0.5, 1.0, 1.5, 2.0, 2.7, 4.0],
        NdfKind::StudentT => vec![2.0, 3.5, 40.0],
        NdfKind::BesselK => vec![0.6, 5.0],
        NdfKind::GenExponential => vec![0.5, 1.0, 2.0, 4.0, 12.0],
        _ => Vec::new(),
    }
}

impl Sweep {
    /// Every NDF at the given roughness values, shapes by [`default_shapes`].
    pub fn with_alphas(alphas: Vec<f64>) -> Self {
        Sweep {
            kinds: NdfKind::ALL.to_vec(),
            alphas,
            shapes: Vec::new(),
        }
    }

    /// The shape parameters swept for `kind` (`[None]` for a kind without one).
    pub fn shapes_of(&self, kind: NdfKind) -> Vec<Option<f64>> {
        if kind.shape_name().is_none() {
            return vec![None];
        }
        match self.shapes.iter().find(|(k, _)| *k == kind) {
            Some((_, v)) => v.iter().map(|&g| Some(g)).collect(),
            None => default_shapes(kind).into_iter().map(Some).collect(),
        }
    }
}

impl Default for Sweep {
    /// Every NDF; α from specular to beyond 1 (GTR normalisation for α < 1 and α > 1); the
    /// shapes of [`default_shapes`].
    fn default() -> Self {
        Sweep::with_alphas(vec![0.02, 0.2, 0.6, 1.0, 1.7])
    }
}

/// Below this magnitude both sides count as underflowed and are compared absolutely
/// (the "absolute 1e-300"): quadratures of e^{−5000}-sized integrands return
/// subnormal dust rather than exact zeros.
pub const UNDERFLOW: f64 = 1e-300;

/// Below this magnitude the slope-space quadratures (Λ by the Smith integral, P2 by ∫ P22 dq)
/// are not run: their integrands reach the subnormal range, where the relative tolerance can
/// never be met and the adaptive rule refines to its limit (minutes at GTR α = 1e-3, γ = 52,
/// u = 0.8: Λ = 1.5e-299). The library's value there is within its absolute promise (1e-300)
/// or it would show at the larger values of the same check.
pub const RESOLVABLE: f64 = 1e-280;

/// [`rel`] of the library's `value` and a quadrature, the quadrature run only where `value`
/// is at least [`RESOLVABLE`] (a NaN value still fails).
fn rel_resolvable(value: f64, quadrature: impl FnOnce() -> f64) -> f64 {
    if value.abs() < RESOLVABLE {
        return 0.0;
    }
    rel(value, quadrature())
}

/// Relative difference, 0 when equal or both below [`UNDERFLOW`], NaN-propagating.
pub fn rel(a: f64, b: f64) -> f64 {
    if a == b || (a.abs() < UNDERFLOW && b.abs() < UNDERFLOW) {
        return 0.0;
    }
    (a - b).abs() / a.abs().max(b.abs())
}

fn max_over<T: Copy>(xs: &[T], f: impl Fn(T) -> f64) -> f64 {
    xs.iter().map(|&x| f(x)).fold(0.0, |m, r| {
        if r.is_nan() || m.is_nan() {
            f64::NAN
        } else {
            m.max(r)
        }
    })
}

/// One unit of the sweep: one material's checks, or the cross-NDF checks at one α.
#[derive(Clone, Copy)]
enum Job {
    Material(NdfKind, f64, Option<f64>),
    Family(f64),
}

impl Job {
    fn run(self, sweep: &Sweep) -> Vec<Check> {
        match self {
            Job::Material(kind, alpha, shape) => match AnyNdf::new(kind, alpha, shape) {
                Ok(ndf) => ndf_checks(&ndf),
                Err(_) => vec![Check {
                    subject: subject(kind, alpha, shape),
                    identity: "parameters accepted".into(),
                    residual: f64::NAN,
                    tol: TOL,
                    skipped: None,
                }],
            },
            Job::Family(alpha) => family_checks(sweep, alpha),
        }
    }
}

/// Runs the sweep, calling `report` with each check in sweep order as soon as it and every
/// check before it are done. With the `rayon` feature the materials run on every core (the
/// order of the checks, and so the output, is the same).
pub fn run(sweep: &Sweep, mut report: impl FnMut(&Check)) -> Vec<Check> {
    let mut jobs = Vec::new();
    for &kind in &sweep.kinds {
        for shape in sweep.shapes_of(kind) {
            for &alpha in &sweep.alphas {
                jobs.push(Job::Material(kind, alpha, shape));
            }
        }
    }
    jobs.extend(sweep.alphas.iter().map(|&a| Job::Family(a)));
    let mut all = Vec::new();
    let mut emit = |checks: Vec<Check>| {
        for c in checks {
            report(&c);
            all.push(c);
        }
    };
    #[cfg(feature = "rayon")]
    {
        use rayon::prelude::*;
        use std::collections::BTreeMap;
        let (tx, rx) = std::sync::mpsc::channel();
        let jobs = &jobs;
        std::thread::scope(|s| {
            s.spawn(move || {
                jobs.par_iter()
                    .enumerate()
                    .for_each_with(tx, |tx, (i, job)| {
                        // (The receiver lives until every job is done; a failed send
                        // can only follow a panic there, which the scope re-raises.)
                        let _ = tx.send((i, job.run(sweep)));
                    });
            });
            // Emit in sweep order: hold results that arrive before their predecessors.
            let mut pending = BTreeMap::new();
            let mut next = 0;
            for (i, checks) in rx {
                pending.insert(i, checks);
                while let Some(checks) = pending.remove(&next) {
                    emit(checks);
                    next += 1;
                }
            }
        });
    }
    #[cfg(not(feature = "rayon"))]
    for job in jobs {
        emit(job.run(sweep));
    }
    all
}

fn subject(kind: NdfKind, alpha: f64, shape: Option<f64>) -> String {
    match shape {
        Some(g) if kind == NdfKind::BesselK => format!("{kind} α={alpha} a={g}"),
        Some(g) => format!("{kind} α={alpha} γ={g}"),
        None => format!("{kind} α={alpha}"),
    }
}

/// The identities every NDF satisfies.
pub fn ndf_checks(ndf: &AnyNdf) -> Vec<Check> {
    let s = subject(ndf.kind(), ndf.alpha(), ndf.shape());
    let alpha = ndf.alpha();
    let mut out = Vec::new();
    let mut push_tol = |identity: &str, residual: f64, tol: f64| {
        out.push(Check {
            subject: s.clone(),
            identity: identity.to_string(),
            residual,
            tol,
            skipped: None,
        })
    };
    // (The u-space floor's width factor is GTR's γ; the other shapes do not narrow D near
    // the normal below α².)
    let gtr_gamma = if ndf.kind() == NdfKind::Gtr {
        ndf.shape()
    } else {
        None
    };
    let u_tol = u_space_tol(alpha, gtr_gamma);
    push_tol(
        "∫ D(m) cos θm dm = 1",
        (normalisation_d(ndf) - 1.0).abs(),
        u_tol,
    );
    push_tol(
        "σ(u) = ∫ D(ui) Δσ(u,ui) dui (delta integral)",
        max_over(&[-0.95, -0.5, -0.1, 0.0, 0.1, 0.5, 0.95], |u| {
            rel(ndf.sigma(u), sigma_by_delta_integral(ndf, u))
        }),
        u_tol,
    );
    let mut push = |identity: &str, residual: f64| push_tol(identity, residual, TOL);
    if ndf.kind() == NdfKind::BesselK {
        // (Its P22 costs a Bessel function of real order, ~5 µs: the nested 2-D rule would
        // take half a minute per material; the polar form is the same integral.)
        push(
            "2π ∫₀^∞ r P22(r) dr = 1 (∫∫ P22 in polar form)",
            (normalisation_p22_polar(ndf) - 1.0).abs(),
        );
    } else {
        push("∫∫ P22 dp dq = 1", (normalisation_p22(ndf) - 1.0).abs());
    }
    push(
        "P22(p,q) = D(u) u⁴",
        max_over(&PS, |p| {
            let q = 0.37;
            let u = 1.0 / (1.0 + p * p + q * q).sqrt();
            rel(ndf.p22(p, q), ndf.d(u) * u.powi(4))
        }),
    );
    push(
        "P2(p) = ∫ P22(p,q) dq",
        // (P2(0) = ∞ for Erfc and Bessel-K a ≤ ½: the quadrature of a log- or
        // power-singular P22 at the origin diverges with it; checked at p > 0.)
        max_over(&PS, |p| {
            let v = ndf.p2(p);
            if v == f64::INFINITY && p == 0.0 {
                return 0.0;
            }
            rel_resolvable(v, || p2_by_quadrature(ndf, p))
        }),
    );
    if ndf.f(0.0).is_some() {
        push(
            "f(x) = α² P22(αx, 0), independent of α",
            max_over(&[0.0, 0.1, 0.7, 1.5, 4.0], |x| {
                rel(ndf.f(x).unwrap(), alpha * alpha * ndf.p22(alpha * x, 0.0))
            }),
        );
    }
    push(
        "Λ(u) = (1/a)∫_a^∞ (q−a) P2(q) dq",
        max_over(&US, |u| {
            rel_resolvable(ndf.lambda(u), || lambda_by_slope_integral(ndf, u))
        }),
    );
    push(
        "Λ(u) = (1/π)∫₀^∞ Q(cot θ cosh s) sinh s tanh s ds (CCDF route)",
        max_over(&US, |u| {
            rel_resolvable(ndf.lambda(u), || lambda_by_ccdf_integral(ndf, u))
        }),
    );
    push(
        "Q(T) = ∫_T^∞ 2π r P22(r) dr",
        max_over(&[0.01, 0.3, 1.0, 3.0], |t| {
            let t = t * alpha;
            rel_resolvable(ndf.slope_ccdf(t), || q_by_radial_integral(ndf, t))
        }),
    );
    if let Some(m) = ndf.beckmann_mixing() {
        let name = m.name();
        push(
            &format!("D, P2 = {name} superpositions of Beckmann D, P2"),
            max_over(&US, |u| {
                let p = 1.0 / u - 1.0;
                rel(ndf.d(u), superpose_beckmann(m, alpha, |b| b.d(u)))
                    .max(rel(ndf.p2(p), superpose_beckmann(m, alpha, |b| b.p2(p))))
            }),
        );
        push(
            &format!("Λ, σ(±u) = {name} superpositions of Beckmann Λ, σ"),
            max_over(&US, |u| {
                rel_resolvable(ndf.lambda(u), || {
                    superpose_beckmann(m, alpha, |b| b.lambda(u))
                })
                .max(rel(
                    ndf.sigma(u),
                    superpose_beckmann(m, alpha, |b| b.sigma(u)),
                ))
                .max(rel_resolvable(ndf.sigma(-u), || {
                    superpose_beckmann(m, alpha, |b| b.sigma(-u))
                }))
            }),
        );
    }
    push(
        "(1+Λ(u)) u = σ(u)",
        max_over(&US, |u| rel((1.0 + ndf.lambda(u)) * u, ndf.sigma(u))),
    );
    push(
        "Λ(u) u = σ(−u)",
        max_over(&US, |u| rel(ndf.lambda(u) * u, ndf.sigma(-u))),
    );
    if matches!(ndf, AnyNdf::StudentT(t) if t.gamma() < STUDENT_T_CHECKED_GAMMA_MIN) {
        // (The integrals of Λ and σ over P2, Q, D or the mixing law; the pointwise
        // identities stand.)
        for c in &mut out {
            if c.identity.contains("Λ(u) = ")
                || c.identity.contains("superpositions of Beckmann Λ")
                || c.identity.contains("delta integral")
            {
                c.skipped = Some(HEAVY_TAIL);
                c.residual = f64::NAN;
            }
        }
    }
    out
}

/// The cap near the normal that the u-space checks take in slope coordinates: tan θ < r_c = α,
/// i.e. u > u_c = 1/√(1 + α²); returns (u_c, r_c). A u-space node there carries the rounding
/// of 1 − u (relative ε/(1 − u)), which D amplifies by its width α² in u (a narrow lobe, the
/// disk edge of the generalised exponential at α = 1e-6 lies within 5e-13 of u = 1) or by
/// its singularity (Ei, Erfc, K0, Bessel-K a ≤ 1: D(1) = +∞, and a node that rounds to 1
/// sees ∞ while [1 − ulp, 1] holds mass); in slope coordinates the same integral is resolved
/// on the scale α. The u-space part keeps the floor of [`u_space_tol`].
fn cap(ndf: &impl Ndf) -> (f64, f64) {
    let rc = ndf.alpha();
    (1.0 / (1.0 + rc * rc).sqrt(), rc)
}

/// 2π ∫₀¹ D(u) u du: u-space below the cap, 2π ∫₀^{r_c} r P22(r) dr above (`cap`).
pub fn normalisation_d(ndf: &impl Ndf) -> f64 {
    let (uc, rc) = cap(ndf);
    let u_part = integrate(|u| ndf.d(u) * u, 0.0, uc, 1e-14).value;
    let r_part = integrate(|r| r * ndf.p22(r, 0.0), 0.0, rc, 1e-14).value;
    2.0 * PI * (u_part + r_part)
}

/// ∫∫ P22 dp dq over the plane, as nested 1-D quadratures over the quarter plane.
pub fn normalisation_p22(ndf: &impl Ndf) -> f64 {
    let s = ndf.alpha();
    4.0 * integrate_to_inf(
        |p| integrate_to_inf(|q| ndf.p22(p, q), 0.0, s, 1e-14).value,
        0.0,
        s,
        1e-14,
    )
    .value
}

/// ∫∫ P22 dp dq in polar coordinates, 2π ∫₀^∞ r P22(r, 0) dr (isotropic NDFs).
pub fn normalisation_p22_polar(ndf: &impl Ndf) -> f64 {
    2.0 * PI * integrate_to_inf(|r| r * ndf.p22(r, 0.0), 0.0, ndf.alpha(), 1e-14).value
}

/// ∫ P22(p, q) dq. At p = 0 in q = t⁴, which smooths a P22 that is integrably singular at the
/// origin (Bessel-K a < 1: P22 ~ r^{2a−2}; Ei, K0: log).
pub fn p2_by_quadrature(ndf: &impl Ndf, p: f64) -> f64 {
    let s = (p * p + ndf.alpha() * ndf.alpha()).sqrt();
    if p == 0.0 {
        return 2.0
            * integrate_to_inf(
                |t| {
                    let t3 = t * t * t;
                    4.0 * t3 * ndf.p22(0.0, t3 * t)
                },
                0.0,
                s.sqrt().sqrt(),
                1e-14,
            )
            .value;
    }
    2.0 * integrate_to_inf(|q| ndf.p22(p, q), 0.0, s, 1e-14).value
}

/// Smith's Λ(u) = (1/a) ∫_a^∞ (q − a) P2(q) dq, a = cot θ, from the NDF's P2.
pub fn lambda_by_slope_integral(ndf: &impl Ndf, u: f64) -> f64 {
    let a = u / ((1.0 - u) * (1.0 + u)).sqrt();
    let s = ndf.alpha().min(a.max(ndf.alpha() * 1e-3));
    integrate_to_inf(|d| d * ndf.p2(a + d), 0.0, s, 1e-13).value / a
}

/// Λ(u) = (1/π) ∫₀^∞ Q(μ cosh s) sinh s tanh s ds, μ = cot θ, Q the D·cos radial slope
/// CCDF (the CCDF route: a smooth positive integrand, no P2 needed), split where μ cosh s = α.
pub fn lambda_by_ccdf_integral(ndf: &AnyNdf, u: f64) -> f64 {
    let mu = u / ((1.0 - u) * (1.0 + u)).sqrt();
    let f = |s: f64| ndf.slope_ccdf(mu * s.cosh()) * s.sinh() * s.tanh();
    let alpha = ndf.alpha();
    let edge = if mu < alpha {
        (alpha / mu).acosh()
    } else {
        0.0
    };
    let inner = if edge > 0.0 {
        integrate(f, 0.0, edge, 1e-13).value
    } else {
        0.0
    };
    (inner + integrate_to_inf(|d| f(edge + d), 0.0, 1.0, 1e-13).value) / PI
}

/// Q(T) = ∫_T^∞ 2π r P22(r) dr.
pub fn q_by_radial_integral(ndf: &impl Ndf, t: f64) -> f64 {
    let s = t.max(ndf.alpha());
    2.0 * PI * integrate_to_inf(|d| (t + d) * ndf.p22(t + d, 0.0), 0.0, s, 1e-13).value
}

/// σ(u) = ∫₀¹ D(ui) Δσ(u, ui) dui, split at the kink ui = √(1−u²) of the kernel; within the
/// cap (`cap`) in slope coordinates, ∫₀^{r_c} r P22(r) √(1 + r²) Δσ(u, ui(r)) dr, with the kink
/// at tan θ = |u|/√(1 − u²) there if it falls inside.
pub fn sigma_by_delta_integral(ndf: &impl Ndf, u: f64) -> f64 {
    let (uc, rc) = cap(ndf);
    let kink = ((1.0 - u) * (1.0 + u)).sqrt();
    let r_kink = u.abs() / kink;
    let f = |ui: f64| ndf.d(ui) * delta_sigma(u, ui);
    let g = |r: f64| {
        // ui = 1/√(1 + r²) and √(1 − ui²) = r ui, formed from r (no 1 − ui² cancellation).
        let s = (1.0 + r * r).sqrt();
        r * ndf.p22(r, 0.0) * s * delta_sigma_at(u, 1.0 / s, r / s)
    };
    let pieces = |h: &dyn Fn(f64) -> f64, lo: f64, mid: f64, hi: f64| {
        if mid > lo && mid < hi {
            integrate(h, lo, mid, 1e-13).value + integrate(h, mid, hi, 1e-13).value
        } else {
            integrate(h, lo, hi, 1e-13).value
        }
    };
    pieces(&f, 0.0, kink, uc) + pieces(&g, 0.0, r_kink, rc)
}
/// The superposition identities and GTR γ = 2 ≡ GGX, at roughness α.
pub fn family_checks(sweep: &Sweep, alpha: f64) -> Vec<Check> {
    let has = |k| sweep.kinds.contains(&k);
    let mut out = Vec::new();
    let mut push = |subject: String, identity: &str, residual: f64| {
        out.push(Check {
            subject,
            identity: identity.to_string(),
            residual,
            tol: TOL,
            skipped: None,
        })
    };
    let us_signed = [-0.8, -0.3, 0.0, 0.3, 0.8];
    if has(NdfKind::Ggx) {
        let ggx = Ggx::new(alpha).expect("sweep α valid");
        let s = format!("ggx α={alpha}");
        for m in [Mixing::Frechet2, Mixing::Gamma1] {
            push(
                s.clone(),
                &format!("D_GGX = {} superposition of Beckmann D", m.name()),
                max_over(&US, |u| {
                    rel(ggx.d(u), superpose_beckmann(m, alpha, |b| b.d(u)))
                }),
            );
            push(
                s.clone(),
                &format!("Λ_GGX = {} superposition of Beckmann Λ", m.name()),
                max_over(&US, |u| {
                    rel(ggx.lambda(u), superpose_beckmann(m, alpha, |b| b.lambda(u)))
                }),
            );
        }
    }
    if has(NdfKind::DoubleGgx) {
        let dggx = DoubleGgx::new(alpha).expect("sweep α valid");
        let s = format!("double_ggx α={alpha}");
        let m = Mixing::Gamma1;
        push(
            s.clone(),
            "D_DGGX = Gamma-1 superposition of GGX D",
            max_over(&US, |u| rel(dggx.d(u), superpose_ggx(m, alpha, |g| g.d(u)))),
        );
        push(
            s.clone(),
            "σ_DGGX = Gamma-1 superposition of GGX σ",
            max_over(&us_signed, |u| {
                rel(dggx.sigma(u), superpose_ggx(m, alpha, |g| g.sigma(u)))
            }),
        );
        push(
            s,
            "Λ_DGGX = Gamma-1 superposition of GGX Λ",
            max_over(&US, |u| {
                rel(dggx.lambda(u), superpose_ggx(m, alpha, |g| g.lambda(u)))
            }),
        );
    }
    if has(NdfKind::Exponential) {
        let e = Exponential::new(alpha).expect("sweep α valid");
        let s = format!("exponential α={alpha}");
        for m in [Mixing::Gamma32, Mixing::Chi3] {
            push(
                s.clone(),
                &format!("D_Exp = {} superposition of Beckmann D", m.name()),
                max_over(&US, |u| {
                    rel(e.d(u), superpose_beckmann(m, alpha, |b| b.d(u)))
                }),
            );
            push(
                s.clone(),
                &format!("σ_Exp = {} superposition of Beckmann σ", m.name()),
                max_over(&us_signed, |u| {
                    rel(e.sigma(u), superpose_beckmann(m, alpha, |b| b.sigma(u)))
                }),
            );
        }
    }
    // The family's special cases: each pair compared in D, P2, Λ, σ(−u) and Q.
    let same = |a: &AnyNdf, b: &AnyNdf| {
        max_over(&US, |u| {
            let p = 1.0 / u - 1.0;
            rel(a.d(u), b.d(u))
                .max(rel(a.p2(p), b.p2(p)))
                .max(rel(a.lambda(u), b.lambda(u)))
                .max(rel(a.sigma(-u), b.sigma(-u)))
                .max(rel(a.slope_ccdf(p), b.slope_ccdf(p)))
        })
    };
    let any = |k: NdfKind, a: f64, g: Option<f64>| AnyNdf::new(k, a, g).expect("valid");
    let cases = [
        (
            NdfKind::StudentT,
            Some(2.0),
            NdfKind::Ggx,
            1.0,
            "Student-T γ = 2 ≡ GGX",
        ),
        (
            NdfKind::BesselK,
            Some(1.0),
            NdfKind::K0,
            1.0,
            "Bessel-K a = 1 ≡ K0",
        ),
        (
            NdfKind::BesselK,
            Some(1.5),
            NdfKind::Exponential,
            1.0,
            "Bessel-K a = 3/2 ≡ Exponential",
        ),
        (
            NdfKind::GenExponential,
            Some(2.0),
            NdfKind::Beckmann,
            1.0,
            "generalised exponential γ = 2 ≡ Beckmann",
        ),
        (
            NdfKind::GenExponential,
            Some(1.0),
            NdfKind::Exponential,
            2.0,
            "generalised exponential γ = 1 ≡ Exponential(2α)",
        ),
    ];
    for (k, g, other, scale, label) in cases {
        if has(k) && (alpha * scale) <= crate::error::ALPHA_MAX {
            let a = any(k, alpha, g);
            let b = any(other, alpha * scale, None);
            push(subject(k, alpha, g), label, same(&a, &b));
        }
    }
    if has(NdfKind::Gtr) && has(NdfKind::Ggx) {
        let ggx = Ggx::new(alpha).expect("sweep α valid");
        // A γ an ulp away from 2 takes the general (numerical) path: an independent route.
        let near2 = Gtr::new(alpha, 2.0 + 4.0 * f64::EPSILON).expect("valid");
        let exact2 = Gtr::new(alpha, 2.0).expect("valid");
        let s = format!("gtr α={alpha} γ=2");
        for (label, g) in [("γ = 2", exact2), ("γ = 2(1+2ε), numerical path", near2)] {
            push(
                s.clone(),
                &format!("GTR {label} ≡ GGX (D, P2, Λ, σ)"),
                max_over(&US, |u| {
                    let p = 1.0 / u - 1.0;
                    rel(g.d(u), ggx.d(u))
                        .max(rel(g.p2(p), ggx.p2(p)))
                        .max(rel(g.lambda(u), ggx.lambda(u)))
                        .max(rel(g.sigma(-u), ggx.sigma(-u)))
                }),
            );
        }
    }
    out
}
