//! Safeguarded Newton iteration for monotone equations, used to invert the cumulative
//! distributions of the samplers (and so to make every sampler an invertible warp).

/// Solves f(x) = 0 for x in [lo, hi], where f is increasing with f(lo) ≤ 0 ≤ f(hi), and `df`
/// is its derivative. Newton steps are taken when they stay inside the bracket, bisection
/// otherwise; stops when the bracket or the step is below 4 ulp of x. Returns the midpoint of
/// the final bracket if f never changes sign (the caller passes a valid bracket).
pub fn newton_bracketed(
    f: impl Fn(f64) -> f64,
    df: impl Fn(f64) -> f64,
    mut lo: f64,
    mut hi: f64,
    guess: f64,
) -> f64 {
    let mut x = if guess > lo && guess < hi {
        guess
    } else {
        0.5 * (lo + hi)
    };
    // 200 iterations: bisection alone halves a [−745, 745] bracket to an ulp in ~60 steps.
    for _ in 0..200 {
        let fx = f(x);
        if fx == 0.0 {
            return x;
        }
        if fx < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let d = df(x);
        let mut next = x - fx / d;
        let tol = 4.0 * f64::EPSILON * x.abs().max(f64::MIN_POSITIVE);
        // (Converged before the bracket test: a step below an ulp rounds next onto x, the
        // bracket's end, and must not send it to the midpoint.)
        if (next - x).abs() <= tol {
            return next;
        }
        if !(next > lo && next < hi && next.is_finite()) {
            next = 0.5 * (lo + hi);
        }
        if (hi - lo) <= tol {
            return next;
        }
        x = next;
    }
    x
}
