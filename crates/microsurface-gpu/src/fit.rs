//! Octave tables of degree-7 polynomials, as the library's WGSL evaluates them
//! (`ms_bk_segment` + `ms_bk_poly`): x ∈ [2^k0, 2^k1) in four segments per octave, each
//! segment's Chebyshev interpolant of f at its eight Chebyshev nodes, re-expressed in
//! monomials of s ∈ [−1, 1) (s⁰ first). Shared by the table generator (`tools/`) and
//! [`crate::Tables`]' per-shape tables; not an API.

/// Coefficients per segment (degree 7): two `vec4`.
pub const DEGREE: usize = 7;
/// Segments per octave, 2^M.
pub const M: u32 = 2;

/// x at position s ∈ [−1, 1] of segment `j` of the table starting at 2^k0.
pub fn x_at(k0: i32, j: usize, s: f64) -> f64 {
    let per = 1usize << M;
    let (oct, seg) = (j / per, j % per);
    let base = 2f64.powi(k0 + oct as i32);
    base * (1.0 + (seg as f64 + 0.5 * (s + 1.0)) / per as f64)
}

/// The segments of [2^k0, 2^k1).
pub fn segments(k0: i32, k1: i32) -> usize {
    ((k1 - k0) as usize) << M
}

/// The monomial coefficients in s of the Chebyshev interpolant of f on segment `j` of the
/// table starting at 2^k0.
pub fn fit(f: &dyn Fn(f64) -> f64, k0: i32, j: usize) -> [f64; DEGREE + 1] {
    let n = DEGREE + 1;
    let theta = |k: usize| std::f64::consts::PI * (k as f64 + 0.5) / n as f64;
    let vals: Vec<f64> = (0..n).map(|k| f(x_at(k0, j, theta(k).cos()))).collect();
    // Chebyshev coefficients c_i = (2/n) Σ f(s_k) T_i(s_k) (c_0 halved).
    let mut cheb = vec![0.0; n];
    for (i, c) in cheb.iter_mut().enumerate() {
        let sum: f64 = vals
            .iter()
            .enumerate()
            .map(|(k, v)| v * (i as f64 * theta(k)).cos())
            .sum();
        *c = 2.0 * sum / n as f64;
    }
    cheb[0] *= 0.5;
    // T_i in monomials: T_0 = 1, T_1 = s, T_{i+1} = 2s T_i − T_{i−1}.
    let mut mono = [0.0; DEGREE + 1];
    let mut t_prev = vec![0.0; n];
    let mut t_cur = vec![0.0; n];
    t_prev[0] = 1.0;
    t_cur[1] = 1.0;
    mono[0] += cheb[0];
    mono[1] += cheb[1];
    for c in cheb.iter().skip(2) {
        let mut next = vec![0.0; n];
        for k in 0..n {
            if k > 0 {
                next[k] += 2.0 * t_cur[k - 1];
            }
            next[k] -= t_prev[k];
        }
        for k in 0..n {
            mono[k] += c * next[k];
        }
        t_prev = t_cur;
        t_cur = next;
    }
    mono
}

/// Σ c_k s^k (Horner, f64) of f32 coefficients.
pub fn horner(c: &[f32], s: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &k| acc * s + k as f64)
}
