//! Helpers shared by the fuzz and property suites.

/// Whether an infinite f(x) is the true value overflowing. A density that grows at most like
/// x^{−2} as x → 0 (every singularity and grazing growth of ours) falls by at most 1e12 when x
/// grows by `step` = 1e6, so the first finite value along x·step^k must be at least 1e296
/// (f64::MAX × 1e-12). A spurious +∞ is followed by an ordinary value.
pub fn overflows_truly(f: impl Fn(f64) -> f64, x: f64, step: f64) -> bool {
    let mut y = x.abs();
    for _ in 0..120 {
        y *= step;
        let v = f(y);
        if v.is_finite() {
            return v >= 1e296;
        }
    }
    false
}
