//! Numerical quadrature: double-exponential (tanh-sinh) rules, used by the exact numerical
//! quantities (GTR Λ, σ, P2 for general γ; the Exponential NDF's Λ and σ; Double GGX P2; the
//! family's Λ where it has no closed form) and by the identity checks in
//! [`crate::check::verify`]. Λ, G1 and σ, which sweeps call most, take fixed rules
//! ([`to_inf_fixed`], [`integrate_fixed_positive`], [`to_inf_fixed_peaked`]) at a level each caller
//! has measured against the adaptive rule, instead of the adaptive rule per call.
//!
//! Tanh-sinh (Takahasi & Mori 1974; Bailey, Jeyabalan & Li 2005) converges double-exponentially
//! for integrands analytic in the open interval, even with integrable end-point singularities,
//! and clusters nodes at both ends, which resolves the narrow end-point layers of our
//! integrands (small α, grazing directions). Nodes are placed relative to the nearer end so that
//! an integrand sees the distance to an end point without cancellation.
//!
//! Accuracy: the level is refined (halving the step) until two successive levels agree to the
//! requested relative tolerance; the returned `error` is that difference, which over-estimates
//! the true error of the finer level for analytic integrands. If level 8 (about 2000 nodes) is
//! reached without convergence the interval is bisected (up to depth 12).

/// The result of a quadrature: value, an error estimate and the number of integrand evaluations.
#[derive(Clone, Copy, Debug)]
pub struct Quad {
    pub value: f64,
    pub error: f64,
    pub evals: usize,
}

/// Gauss–Legendre nodes and weights on [0, 1], 8 points (exact for degree 15: the cubic
/// interpolant times μ on each interval, and the smooth Fresnel averages).
pub const GL8: [(f64, f64); 8] = [
    (0.019_855_071_751_231_856, 0.050_614_268_145_188_13),
    (0.101_666_761_293_186_63, 0.111_190_517_226_687_24),
    (0.237_233_795_041_835_5, 0.156_853_322_938_943_64),
    (0.408_282_678_752_175_1, 0.181_341_891_689_181_0),
    (0.591_717_321_247_824_9, 0.181_341_891_689_181_0),
    (0.762_766_204_958_164_5, 0.156_853_322_938_943_64),
    (0.898_333_238_706_813_4, 0.111_190_517_226_687_24),
    (0.980_144_928_248_768_1, 0.050_614_268_145_188_13),
];

/// The n-point Gauss–Legendre rule on [0, 1] for n = 8k, k = 1 … 8 (exact for degree 2n − 1),
/// formed once per process by Newton's iteration on P_n (nodes and weights to the
/// rounding; the 8-point rule equals [`GL8`] within 1e-16, tested below). `None` for other n.
pub fn gauss_legendre(n: usize) -> Option<&'static [(f64, f64)]> {
    static RULES: [std::sync::OnceLock<Vec<(f64, f64)>>; 8] =
        [const { std::sync::OnceLock::new() }; 8];
    if n == 0 || !n.is_multiple_of(8) || n > 64 {
        return None;
    }
    Some(RULES[n / 8 - 1].get_or_init(|| {
        let mut rule: Vec<(f64, f64)> = (0..n)
            .map(|i| {
                // Tricomi's first guess, then Newton on P_n(x) (three steps reach the rounding
                // from it; six for margin).
                let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
                let mut dp = 1.0;
                for _ in 0..6 {
                    let (mut p0, mut p1) = (1.0, x);
                    for k in 2..=n {
                        let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                        p0 = p1;
                        p1 = p2;
                    }
                    dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                    x -= p1 / dp;
                }
                (0.5 * (1.0 - x), 1.0 / ((1.0 - x * x) * dp * dp))
            })
            .collect();
        rule.sort_by(|a, b| a.0.total_cmp(&b.0));
        rule
    }))
}

/// Largest abscissa parameter of the usual rule: at t = 4 the distance of a node to the end
/// point is below 1e-37 of the interval length, far beyond what a bounded or log-singular
/// integrand needs.
const T_MAX: f64 = 4.0;
/// How far [`integrate`] and [`integrate_to_inf`] reach where an end point's terms are still
/// significant at t = 4: t = 6, 1e-275 of the interval. A power singularity x^{−1+δ} (Bessel-K's
/// P22 at a = 0.1, a Gamma(0.1) weight, Student-T's tail near γ = 3/2 under x = s/(1 − s))
/// holds a share ~ d^δ of its mass within d of the end: (1e-37)^0.1 = 2e-4 would be lost at
/// t = 4, (1e-275)^0.1 = 3e-28 at t = 6.
const T_EXT: f64 = 6.0;
/// Deepest level: step 2⁻⁸.
const MAX_LEVEL: u32 = 8;
/// The absolute floor of [`integrate`] and [`integrate_to_inf`]: an integral whose value has
/// underflowed (the crate promises 1e-300 absolute there) is done once its error is below
/// this. Without it a relative tolerance is never met on subnormal integrands and the rule
/// refines and bisects to its limits: a GTR P2 at α = 1e-2, γ = 70, p = 1e10 (≈ 1e-305) took
/// one second, and `verify` minutes.
pub const UNDERFLOW_FLOOR: f64 = 1e-305;
const HALF_PI: f64 = std::f64::consts::FRAC_PI_2;

/// ∫₀¹ g(s, 1−s) ds, where g receives both s and its complement 1 − s, each computed without
/// cancellation. Tolerance is relative to the result (with `abs_tol` as an absolute floor).
pub fn tanh_sinh01(g: &dyn Fn(f64, f64) -> f64, rel_tol: f64, abs_tol: f64) -> Quad {
    adaptive(g, 0.0, 1.0, rel_tol, abs_tol, 0)
}

fn adaptive(
    g: &dyn Fn(f64, f64) -> f64,
    lo: f64,
    hi: f64,
    rel_tol: f64,
    abs_tol: f64,
    depth: u32,
) -> Quad {
    let q = tanh_sinh_sub(g, lo, hi, rel_tol, abs_tol);
    let tol = (rel_tol * q.value.abs()).max(abs_tol);
    // Bisect only if not converged; 12 levels narrow the interval by 4096.
    if q.error <= tol || depth >= 12 {
        return q;
    }
    let mid = 0.5 * (lo + hi);
    let a = adaptive(g, lo, mid, rel_tol, 0.5 * abs_tol, depth + 1);
    let b = adaptive(g, mid, hi, rel_tol, 0.5 * abs_tol, depth + 1);
    Quad {
        value: a.value + b.value,
        error: a.error + b.error,
        evals: q.evals + a.evals + b.evals,
    }
}

/// A node of the finest tanh-sinh rule on [0, 1], at parameter t ≥ 0 (and its mirror −t):
/// the distance 1/(1 + e^{π sinh t}) of x = ½(1 ± tanh(π/2 sinh t)) to the nearer end point,
/// and the weight (π/2) cosh t / cosh²(π/2 sinh t) of dx/dt at step 1.
#[derive(Clone, Copy)]
struct Node {
    dist: f64,
    w: f64,
}

/// The nodes t = k 2^−MAX_LEVEL, k = 0 ..= T_MAX 2^MAX_LEVEL: they do not depend on the
/// integrand, and forming one (sinh, exp and two cosh) costs about as much as evaluating a
/// typical integrand of ours, so they are computed once per process (1 025 nodes, 16 KiB).
fn nodes() -> &'static [Node] {
    static NODES: std::sync::OnceLock<Vec<Node>> = std::sync::OnceLock::new();
    NODES.get_or_init(|| {
        let steps = (T_EXT as usize) << MAX_LEVEL;
        (0..=steps)
            .map(|k| {
                let t = k as f64 / (1u64 << MAX_LEVEL) as f64;
                let sh = t.sinh();
                let ch = (HALF_PI * sh).cosh();
                Node {
                    dist: 1.0 / (1.0 + (2.0 * HALF_PI * sh).exp()),
                    w: HALF_PI * t.cosh() / (ch * ch),
                }
            })
            .collect()
    })
}

/// Tanh-sinh on the sub-interval [lo, hi] of [0, 1].
fn tanh_sinh_sub(
    g: &dyn Fn(f64, f64) -> f64,
    lo: f64,
    hi: f64,
    rel_tol: f64,
    abs_tol: f64,
) -> Quad {
    let half = 0.5 * (hi - lo);
    let nodes = nodes();
    let mut evals = 0usize;
    // The node at parameter ±t, t = j 2^−MAX_LEVEL: x = mid ± half·tanh(π/2 sinh t), placed
    // from the nearer end point (its distance half·2/(1 + e^{π sinh t}) formed directly).
    let mut eval = |j: usize, negative: bool| -> f64 {
        let Node { dist, w } = nodes[j];
        let (dist, w) = (2.0 * half * dist, half * w);
        if w == 0.0 || dist == 0.0 {
            return 0.0;
        }
        let (s, sc) = if negative {
            let s = lo + dist;
            (s, 1.0 - s)
        } else {
            let sc = (1.0 - hi) + dist;
            (1.0 - sc, sc)
        };
        evals += 1;
        let v = g(s, sc) * w;
        if v.is_finite() {
            v
        } else {
            0.0
        }
    };
    // Level ℓ has step h = 2^−ℓ; its node k sits at j = k 2^{MAX_LEVEL − ℓ} in `nodes`.
    let stride = 1usize << MAX_LEVEL;
    let mut last = (T_MAX as usize) << MAX_LEVEL;
    let mut h = 1.0;
    let mut sum = eval(0, false);
    let mut edge = 0.0;
    for j in (stride..=last).step_by(stride) {
        edge = eval(j, false) + eval(j, true);
        sum += edge;
    }
    // The reach grows (to T_EXT) while the outermost terms still matter: only end-point
    // singularities of power type pay for the extra nodes (bounded integrands have terms
    // ~ 1e-35 of the sum there).
    while edge.abs() > 1e-3 * rel_tol * sum.abs() && last + stride < nodes.len() {
        last += stride;
        edge = eval(last, false) + eval(last, true);
        sum += edge;
    }
    let mut prev = sum * h;
    let mut error = f64::INFINITY;
    let mut value = prev;
    for level in 1..=MAX_LEVEL {
        h *= 0.5;
        // The new nodes of this level: odd multiples of its step.
        let stride = 1usize << (MAX_LEVEL - level);
        for j in (stride..=last).step_by(2 * stride) {
            sum += eval(j, false) + eval(j, true);
        }
        value = sum * h;
        error = (value - prev).abs();
        // Two agreeing levels: the finer one is already far more accurate than their gap.
        if error <= (rel_tol * value.abs()).max(abs_tol) {
            break;
        }
        prev = value;
    }
    Quad {
        value,
        error,
        evals,
    }
}

/// ∫_a^b f(x) dx by the tanh-sinh rule of step 2^−level without refinement (at most
/// 2^{level+3} + 1 nodes): for integrands that are smooth, or have end-point singularities, but
/// may have a kink inside (where the adaptive rule would refine for nothing), when a relative
/// accuracy of about 1e-6 is enough (the χ² harness's expected counts). Every node to |t| = 4.
pub fn integrate_fixed(f: impl Fn(f64) -> f64, a: f64, b: f64, level: u32) -> f64 {
    fixed_finite(f, a, b, level, false)
}

/// [`integrate_fixed`] for an integrand positive on (a, b) at a level the caller has
/// measured to suffice (the exact Λ of the NDFs without a closed form): each side of t = 0
/// is summed outward and stops after three consecutive terms below 1e-18 of a nonzero sum
/// (the integrand has decayed past what the sum can hold). (Not for an integrand that may
/// vanish on a stretch and rise again toward an end: the χ² harness's cells are that.)
pub fn integrate_fixed_positive(f: impl Fn(f64) -> f64, a: f64, b: f64, level: u32) -> f64 {
    fixed_finite(f, a, b, level, true)
}

fn fixed_finite(f: impl Fn(f64) -> f64, a: f64, b: f64, level: u32, stop_early: bool) -> f64 {
    let half = 0.5 * (b - a);
    let nodes = nodes();
    fixed_sum(
        |j, upper| {
            let Node { dist, w } = nodes[j];
            let (dist, w) = (2.0 * half * dist, half * w);
            if !(w > 0.0 && dist > 0.0) {
                return 0.0;
            }
            let v = f(if upper { b - dist } else { a + dist }) * w;
            if v.is_finite() {
                v
            } else {
                0.0
            }
        },
        level,
        stop_early,
    )
}

/// Σ of a tanh-sinh rule's terms at step 2^−level, `term(j, upper)` the term at t = ±j
/// 2^−MAX_LEVEL (upper: t > 0): the centre, then each side outward to |t| = 4, or with
/// `stop_early` until three consecutive terms fall below 1e-18 of a nonzero sum (the
/// integrand has decayed past what the sum can hold); times the step.
fn fixed_sum(term: impl Fn(usize, bool) -> f64, level: u32, stop_early: bool) -> f64 {
    let level = level.min(MAX_LEVEL);
    let stride = 1usize << (MAX_LEVEL - level);
    let reach = (T_MAX as usize) << MAX_LEVEL;
    let mut sum = term(0, true);
    for upper in [false, true] {
        let mut small = 0;
        let mut j = stride;
        let mut side = 0.0;
        while j <= reach {
            let v = term(j, upper);
            side += v;
            if stop_early && sum + side != 0.0 && v.abs() <= 1e-18 * (sum + side).abs() {
                small += 1;
                if small == 3 {
                    break;
                }
            } else {
                small = 0;
            }
            j += stride;
        }
        sum += side;
    }
    sum * 0.5f64.powi(level as i32)
}

/// ∫_a^∞ f(x) dx by the tanh-sinh rule of step 2^−level under the map of [`integrate_to_inf`]
/// (x = a + L s/(1 − s)), without refinement: a fixed rule for integrands whose caller has
/// scaled the map to them (L where the integrand changes character), so that one level is
/// known to suffice (the exact Λ of the NDFs without a closed form: `math::smith`), positive
/// on the half line: summed as [`integrate_fixed_positive`] is.
pub fn to_inf_fixed(f: impl Fn(f64) -> f64, a: f64, scale: f64, level: u32) -> f64 {
    let nodes = nodes();
    fixed_sum(
        |j, toward_inf| {
            let Node { dist, w } = nodes[j];
            // s on [0, 1] at distance `dist` from its nearer end: s = dist toward a, 1 − dist
            // toward ∞; x = a + L s/(1 − s), dx = L/(1 − s)² ds.
            let (s, sc) = if toward_inf {
                (1.0 - dist, dist)
            } else {
                (dist, 1.0 - dist)
            };
            if !(w > 0.0 && sc > 0.0 && s > 0.0) {
                return 0.0;
            }
            let v = f(a + scale * s / sc) * (0.5 * w) * scale / (sc * sc);
            if v.is_finite() {
                v
            } else {
                0.0
            }
        },
        level,
        true,
    )
}

/// ∫₀^∞ f(x) dx for a positive integrand with one peak at x = `peak` > 0, by fixed rules of
/// step 2^−level split there: [0, peak] (tanh-sinh clusters its nodes at the peak, an end
/// point) and [peak, ∞) under [`to_inf_fixed`]'s map scaled to the peak's width, estimated
/// from the curvature of ln f at the peak (three more evaluations; the peak itself where the
/// curvature says nothing). A peak far from the origin and narrow against its distance (a
/// mixture's weight times e^{−x²/m} at large x) is a feature one fixed rule over the whole
/// half line would not resolve.
pub fn to_inf_fixed_peaked(f: impl Fn(f64) -> f64, peak: f64, level: u32) -> f64 {
    let h = 0.1;
    let (f0, fp, fm) = (f(peak), f(peak * (1.0 + h)), f(peak * (1.0 - h)));
    let c2 = (fp.ln() + fm.ln() - 2.0 * f0.ln()) / ((h * peak) * (h * peak));
    let width = if c2 < 0.0 && c2.is_finite() {
        (1.0 / (-c2).sqrt()).min(peak)
    } else {
        peak
    };
    integrate_fixed_positive(&f, 0.0, peak, level) + to_inf_fixed(&f, peak, width, level)
}

/// The tanh-sinh rule of step 2^−level on [0, 1] from the cached nodes (`nodes`): (distance
/// of the node to the nearer end, whether that end is 1, weight), for t ∈ [−3.2, 3.2]
/// (beyond, the nodes lie within 3e-17 of an end) and weights above 1e-18. For callers
/// that apply one rule to many integrands over moving intervals (the dielectric albedo's
/// nested integrals).
pub fn rule01(level: u32) -> Vec<(f64, bool, f64)> {
    let level = level.min(MAX_LEVEL);
    let h = 0.5f64.powi(level as i32);
    let stride = 1usize << (MAX_LEVEL - level);
    let mut rule = Vec::new();
    for (i, node) in nodes().iter().step_by(stride).enumerate() {
        let t = i as f64 * h;
        let w = 0.5 * h * node.w;
        if t > 3.2 || !(w > 1e-18 && node.dist > 0.0) {
            continue;
        }
        if i > 0 {
            rule.push((node.dist, false, w));
        }
        rule.push((node.dist, i > 0, w));
    }
    rule
}

/// The nodes and weights of the tanh-sinh rule of step 2^−level for ∫₀^∞ w(t) f(t) dt under
/// t = L s/(1 − s): returns (t_i, w(t_i) × quadrature weight), dropping nodes whose weight is
/// below 1e-20 of the largest (they cannot change a sum of bounded f at 1e-16). A fixed rule
/// to be reused for many f that are smooth in t.
pub fn half_line_rule(w: impl Fn(f64) -> f64, scale: f64, level: u32) -> Vec<(f64, f64)> {
    let h = 0.5f64.powi(level as i32);
    let mut nodes = Vec::new();
    let mut k = -((T_MAX / h) as i64);
    while k as f64 * h <= T_MAX {
        let t = k as f64 * h;
        let sh = t.sinh();
        let e = (std::f64::consts::PI * sh.abs()).exp();
        let dist = 1.0 / (1.0 + e); // distance of s to the nearer end of [0, 1]
        let ch = (HALF_PI * sh).cosh();
        let ws = 0.5 * HALF_PI * t.cosh() / (ch * ch);
        let (s, sc) = if t < 0.0 {
            (dist, 1.0 - dist)
        } else {
            (1.0 - dist, dist)
        };
        if ws > 0.0 && sc > 0.0 {
            let x = scale * s / sc;
            let jac = scale / (sc * sc);
            let weight = w(x) * ws * jac * h;
            if weight.is_finite() && weight > 0.0 {
                nodes.push((x, weight));
            }
        }
        k += 1;
    }
    let max = nodes.iter().map(|n| n.1).fold(0.0, f64::max);
    nodes.retain(|n| n.1 > 1e-20 * max);
    nodes
}

/// ∫_a^b f(x) dx.
pub fn integrate(f: impl Fn(f64) -> f64, a: f64, b: f64, rel_tol: f64) -> Quad {
    let len = b - a;
    let g = |s: f64, sc: f64| {
        let x = if s < 0.5 { a + len * s } else { b - len * sc };
        f(x)
    };
    let q = tanh_sinh01(&g, rel_tol, UNDERFLOW_FLOOR / len.abs());
    Quad {
        value: q.value * len,
        error: q.error * len.abs(),
        evals: q.evals,
    }
}

/// ∫_a^∞ f(x) dx via x = a + L s/(1−s); `scale` L > 0 is where the integrand changes character.
/// Integrands decaying like x⁻² or faster map to bounded integrands on [0, 1].
pub fn integrate_to_inf(f: impl Fn(f64) -> f64, a: f64, scale: f64, rel_tol: f64) -> Quad {
    integrate_scaled(f, a, f64::INFINITY, scale, rel_tol)
}

/// ∫_a^b f(x) dx (a < b ≤ ∞) via x = a + L s/(1 − s + ρ s), ρ = L/(b − a): the map of
/// [`integrate_to_inf`] (which it is at b = ∞) bent to end at b, for an integrand that
/// changes character at the scale L near a but is cut at a finite b: one that still decays
/// slowly there, like x^{−1−ε}, stays bounded by ~ρ^{ε−1}/L^ε at s = 1 instead of becoming
/// the end-point singularity (1 − s)^{ε−1} of the half-line map.
pub fn integrate_scaled(f: impl Fn(f64) -> f64, a: f64, b: f64, scale: f64, rel_tol: f64) -> Quad {
    let rho = scale / (b - a);
    let g = |s: f64, sc: f64| {
        // (= sc at b = ∞.)
        let den = sc + rho * s;
        if den <= 0.0 {
            return 0.0;
        }
        let x = a + scale * s / den;
        f(x) * scale / (den * den)
    };
    tanh_sinh01(&g, rel_tol, UNDERFLOW_FLOOR)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polynomial_and_singular() {
        let q = integrate(|x| x * x, 0.0, 3.0, 1e-14);
        assert!((q.value - 9.0).abs() < 1e-13, "{q:?}");
        let q = integrate(|x| 1.0 / x.sqrt(), 0.0, 1.0, 1e-14);
        assert!((q.value - 2.0).abs() < 1e-12, "{q:?}");
        let q = integrate(|x| -x.ln(), 0.0, 1.0, 1e-14);
        assert!((q.value - 1.0).abs() < 1e-13, "{q:?}");
    }

    #[test]
    fn half_line() {
        let q = integrate_to_inf(|x| (-x).exp(), 0.0, 1.0, 1e-14);
        assert!((q.value - 1.0).abs() < 1e-13, "{q:?}");
        let q = integrate_to_inf(|x| 1.0 / (1.0 + x * x), 0.0, 1.0, 1e-14);
        assert!((q.value - HALF_PI).abs() < 1e-13, "{q:?}");
        // A narrow peak far from the scale: Gaussian of width 1e-3 at the origin.
        let q = integrate_to_inf(|x| (-(x / 1e-3).powi(2)).exp(), 0.0, 1.0, 1e-13);
        let exact = 1e-3 * std::f64::consts::PI.sqrt() / 2.0;
        assert!((q.value / exact - 1.0).abs() < 1e-12, "{q:?}");
    }

    #[test]
    fn scaled_to_a_finite_end() {
        // ∫_0^{1e3} (1 + x)^{−1−ε} dx = (1 − 1001^{−ε})/ε, ε = 2e-6: a tail cut while flat.
        let eps = 2e-6;
        let q = integrate_scaled(|x| (1.0 + x).powf(-1.0 - eps), 0.0, 1e3, 1.0, 1e-13);
        let exact = -(-eps * 1001f64.ln()).exp_m1() / eps;
        assert!((q.value / exact - 1.0).abs() < 1e-12, "{q:?} vs {exact}");
        // b = ∞ is the half-line map.
        let f = |x: f64| 1.0 / (1.0 + x * x);
        let (a, b) = (
            integrate_scaled(f, 0.0, f64::INFINITY, 1.0, 1e-14),
            integrate_to_inf(f, 0.0, 1.0, 1e-14),
        );
        assert_eq!(a.value, b.value);
    }

    #[test]
    fn gauss_legendre_rules_integrate_polynomials() {
        let r8 = super::gauss_legendre(8).unwrap();
        for (a, b) in r8.iter().zip(super::GL8) {
            assert!(
                (a.0 - b.0).abs() < 3e-16 && (a.1 - b.1).abs() < 3e-16,
                "{a:?} {b:?}"
            );
        }
        for n in (8..=64).step_by(8) {
            let rule = super::gauss_legendre(n).unwrap();
            // ∫₀¹ x^m dx = 1/(m + 1), exact for m ≤ 2n − 1.
            for m in [0, 1, 5, 2 * n - 1] {
                let got: f64 = rule.iter().map(|&(x, w)| w * x.powi(m as i32)).sum();
                assert!(
                    (got - 1.0 / (m + 1) as f64).abs() < 1e-14,
                    "n {n} m {m}: {got}"
                );
            }
        }
        assert!(super::gauss_legendre(12).is_none() && super::gauss_legendre(72).is_none());
    }
}
