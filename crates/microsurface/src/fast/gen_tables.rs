//! Generates `src/fast/tables.rs`, the octave tables of the fast Double GGX and Exponential Λ
//! (Chebyshev interpolation of the exact, reference-checked Λ), of erfcx and erfinv (for the
//! fast Beckmann Λ and sampler) and the ziggurats' layers, and reports the fit errors measured
//! between the nodes (the fast Beckmann visible-normal warp's own tables come from
//! `scripts/beckmann_vndf_tables.py`):
//!
//! ```text
//! cargo test --release -p microsurface --lib gen_tables -- --ignored --nocapture
//! ```
//!
//! (a unit test, ignored in the default run: it needs the crate's private special functions,
//! and it overwrites `src/fast/tables.rs`).
//!
//! tests/fast.rs checks the result over the whole domain against the exact paths.

use crate::fast::fit::{eval, eval32, eval_narrow, fit_octaves};
use crate::{Exponential, Ndf};
use std::fmt::Write;

/// Double GGX: Λ(x) = (x eˣ(K₀(x) + K₁(x)) − 1)/2, x = α² tan²θ/2 (exact in x).
fn dggx(x: f64) -> f64 {
    0.5 * crate::math::special::bessel_k_sum_m1(x)
}

/// Exponential: Λ(z), z = 2 cot θ/α, through the shape invariance: u = 1/√2 (cot θ = 1
/// to within an ulp) and α = 2/z.
fn exponential(z: f64) -> f64 {
    Exponential::new(2.0 / z)
        .unwrap()
        .lambda(std::f64::consts::FRAC_1_SQRT_2)
}

/// erfcx(x) = e^{x²} erfc(x): below 2 from libm's erfc times e^{x²} with x² split exactly into
/// hi + lo (so the exponential adds no error of its own), from 2 on the continued fraction
/// 1/(√π (x + k)) of `special::erfc_ratio_tail`.
fn erfcx(x: f64) -> f64 {
    if x < 2.0 {
        let hi = x * x;
        let lo = x.mul_add(x, -hi);
        libm::erfc(x) * hi.exp() * (1.0 + lo)
    } else {
        1.0 / (std::f64::consts::PI.sqrt() * (x + crate::math::special::erfc_ratio_tail(x)))
    }
}

/// r(a) = 1 − √π a erfcx(a), the factor of Beckmann's Λ = e^{−a²} r(a)/(2a√π): below 2 from
/// [`erfcx`] (cancelling at most a factor 10), from 2 on k/(a + k) with k the continued fraction.
fn erfc_ratio(a: f64) -> f64 {
    if a < 2.0 {
        1.0 - std::f64::consts::PI.sqrt() * a * erfcx(a)
    } else {
        let k = crate::math::special::erfc_ratio_tail(a);
        k / (a + k)
    }
}

/// erfinv(v)/v at w = −ln(1 − v²), by bisection to the last bit: on libm's erf for v < 1/2,
/// and in the tail on ln erfc y = ln erfcx(y) − y² against ln q = −w − ln(1 + v), q = 1 − v
/// (logarithms, so that q below the normal range, w > 708, keeps its accuracy).
fn erfinv_ratio(w: f64) -> f64 {
    let v = (-(-w).exp_m1()).sqrt();
    let y = if v < 0.5 {
        bisect(|y| libm::erf(y) < v, 0.0, 1.0)
    } else {
        let ln_q = -w - v.ln_1p();
        bisect(|y| erfcx(y).ln() - y * y > ln_q, 0.0, 40.0)
    };
    y / v
}

/// The boundary of a predicate that holds below it and fails above, to the last bit.
fn bisect(below: impl Fn(f64) -> bool, mut lo: f64, mut hi: f64) -> f64 {
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            return mid;
        }
        if below(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
}

/// The layers of a 256-layer ziggurat (Marsaglia and Tsang 2000) for the decreasing density
/// `f` on [0, ∞) with f(0) = 1, inverse `f_inv` and tail mass `tail(r)` = ∫_r^∞ f: writes
/// `{name}_X` (x₀ = V/f(r), x₁ = r, …, x₂₅₆ = 0) and `{name}_F` (f(xᵢ), f(x₂₅₆) = 1).
/// Every layer has the area V = r f(r) + tail(r): xᵢ₊₁ = f⁻¹(f(xᵢ) + V/xᵢ), and r is
/// bisected to the last bit so that the top layer x₂₅₅(1 − f(x₂₅₅)) closes on V. Returns
/// the largest relative deviation of a layer's area (from the stored values) from V.
fn ziggurat(
    out: &mut String,
    name: &str,
    what: &str,
    f: impl Fn(f64) -> f64,
    f_inv: impl Fn(f64) -> f64,
    tail: impl Fn(f64) -> f64,
) -> f64 {
    // The layers for a base r; None when the stack reaches f(0) before the top layer (r too
    // small, so V too large).
    let layers = |r: f64| -> Option<(f64, [f64; 257])> {
        let v = r * f(r) + tail(r);
        let mut x = [0.0; 257];
        x[0] = v / f(r);
        x[1] = r;
        for i in 1..255 {
            let y = f(x[i]) + v / x[i];
            if y >= 1.0 {
                return None;
            }
            x[i + 1] = f_inv(y);
        }
        Some((v, x))
    };
    // The top layer's area less V: negative (or None) for r too small, positive for too large.
    let excess = |r: f64| match layers(r) {
        None => -1.0,
        Some((v, x)) => x[255] * (1.0 - f(x[255])) - v,
    };
    let r = bisect(|r| excess(r) < 0.0, 1.0, 20.0);
    let (v, x) = layers(r).unwrap();
    let fx: Vec<f64> = x.iter().map(|&xi| f(xi)).collect();
    let mut worst = ((x[0] * fx[1] - v) / v).abs();
    for i in 1..256 {
        worst = worst.max(((x[i] * (fx[i + 1] - fx[i]) - v) / v).abs());
    }
    writeln!(out, "/// {what}: 256 layers of area V = {v:e}, base r = {r:e}; layer areas within {worst:.1e} of V (relative).").unwrap();
    for (suffix, t) in [("X", &x[..]), ("F", &fx[..])] {
        let row: Vec<String> = t.iter().map(|v| format!("{v:e}")).collect();
        writeln!(out, "pub static {name}_{suffix}: [f64; 257] = [").unwrap();
        for chunk in row.chunks(4) {
            writeln!(out, "    {},", chunk.join(", ")).unwrap();
        }
        writeln!(out, "];").unwrap();
    }
    eprintln!("{name}: r = {r}, V = {v:e}, layer areas within {worst:.2e}");
    worst
}

/// Fits `f` on [2^k0, 2^k1) and writes the table; returns the largest relative error at 16
/// points inside every segment.
fn table<const N: usize>(
    out: &mut String,
    name: &str,
    what: &str,
    range: (i32, i32, u32),
    f: impl Fn(f64) -> f64,
) -> f64 {
    let (t, worst) = table_octaves::<N>(out, name, what, range, f);
    write_rows(out, name, "f64", &t);
    worst
}

/// [`table`] without the rows: writes the constants, returns the rows and the fit error.
fn table_octaves<const N: usize>(
    out: &mut String,
    name: &str,
    what: &str,
    (k0, k1, m): (i32, i32, u32),
    f: impl Fn(f64) -> f64,
) -> (Vec<[f64; N]>, f64) {
    let t = fit_octaves::<N>(k0, k1, m, &f);
    let mut worst = 0.0f64;
    for e in k0..k1 {
        for j in 0..(16 << m) {
            let x = 2f64.powi(e) * (1.0 + (j as f64 + 0.37) / (16 << m) as f64);
            let (a, b) = (eval(&t, k0, m, x), f(x));
            worst = worst.max(((a - b) / b).abs());
        }
    }
    writeln!(out, "/// {what}: x ∈ [2^{k0}, 2^{k1}), 2^{m} segments per octave, degree {}; fit error {worst:.1e} (relative, 16 points per segment).", N - 1).unwrap();
    write_range(out, name, (k0, k1, m));
    eprintln!("{name}: {} segments, fit error {worst:.2e}", t.len());
    (t, worst)
}

/// Writes a table's `{name}_K0`, `_K1` and `_M`.
fn write_range(out: &mut String, name: &str, (k0, k1, m): (i32, i32, u32)) {
    writeln!(out, "pub const {name}_K0: i32 = {k0};").unwrap();
    writeln!(out, "pub const {name}_K1: i32 = {k1};").unwrap();
    writeln!(out, "pub const {name}_M: u32 = {m};").unwrap();
}

/// The f64 fit of `f` on [2^k0, 2^k1), its coefficients rounded to f32.
fn fit32<const N: usize>((k0, k1, m): (i32, i32, u32), f: impl Fn(f64) -> f64) -> Vec<[f32; N]> {
    fit_octaves::<N>(k0, k1, m, f)
        .iter()
        .map(|r| r.map(|c| c as f32))
        .collect()
}

/// [`table`] for the native f32 paths: the f64 fit's coefficients rounded to f32, written as
/// `[[f32; N]; _]`; returns the largest relative error of [`eval32`] (f32 arithmetic) against
/// `f`, at every 509th f32 of the range (about 8 000 points per octave).
fn table32<const N: usize>(
    out: &mut String,
    name: &str,
    what: &str,
    (k0, k1, m): (i32, i32, u32),
    f: impl Fn(f64) -> f64,
) -> f64 {
    let t = fit32::<N>((k0, k1, m), &f);
    let mut worst = 0.0f64;
    let (mut x, hi) = (2f32.powi(k0), 2f32.powi(k1));
    while x < hi {
        let (a, b) = (eval32(&t, k0, m, x) as f64, f(x as f64));
        worst = worst.max(((a - b) / b).abs());
        x = f32::from_bits(x.to_bits() + 509);
    }
    writeln!(out, "/// {what}, f32: x ∈ [2^{k0}, 2^{k1}), 2^{m} segments per octave, degree {}; error {worst:.1e} (relative, f32 arithmetic, every 509th f32).", N - 1).unwrap();
    write_range(out, name, (k0, k1, m));
    write_rows(out, name, "f32", &t);
    eprintln!("{name}: {} segments, f32 error {worst:.2e}", t.len());
    worst
}

/// [`table`] with the coefficients rounded to f32 and evaluated in f32 at an f64 x
/// ([`eval_narrow`]):
/// writes `[[f32; N]; _]`, returns the largest relative error at 16 points per segment.
fn table_narrow<const N: usize>(
    out: &mut String,
    name: &str,
    what: &str,
    (k0, k1, m): (i32, i32, u32),
    f: impl Fn(f64) -> f64,
) -> f64 {
    let t = fit32::<N>((k0, k1, m), &f);
    let mut worst = 0.0f64;
    for e in k0..k1 {
        for j in 0..(16 << m) {
            let x = 2f64.powi(e) * (1.0 + (j as f64 + 0.37) / (16 << m) as f64);
            let (a, b) = (f64::from(eval_narrow(&t, k0, m, x)), f(x));
            worst = worst.max(((a - b) / b).abs());
        }
    }
    writeln!(out, "/// {what}, f32 (x in f64): x ∈ [2^{k0}, 2^{k1}), 2^{m} segments per octave, degree {}; error {worst:.1e} (relative, 16 points per segment).", N - 1).unwrap();
    write_range(out, name, (k0, k1, m));
    write_rows(out, name, "f32", &t);
    eprintln!("{name}: {} segments, error {worst:.2e}", t.len());
    worst
}

/// Writes `pub static {name}` with the rows `t` (`ty` is their type's name, f64 or f32).
fn write_rows<T: std::fmt::LowerExp, const N: usize>(
    out: &mut String,
    name: &str,
    ty: &str,
    t: &[[T; N]],
) {
    writeln!(out, "pub static {name}: [[{ty}; {N}]; {}] = [", t.len()).unwrap();
    for c in t {
        let row: Vec<String> = c.iter().map(|v| format!("{v:e}")).collect();
        writeln!(out, "    [{}],", row.join(", ")).unwrap();
    }
    writeln!(out, "];").unwrap();
}

#[test]
#[ignore = "regenerates src/fast/tables.rs (minutes)"]
fn gen_tables() {
    let mut out = String::new();
    out.push_str("//! @generated by `cargo test --release -p microsurface --lib gen_tables -- --ignored` (src/fast/gen_tables.rs); do not edit.\n//! Monomial coefficients in s ∈ [−1, 1] per segment (see `fit.rs`).\n\n");
    let e1 = table::<6>(&mut out, "DGGX", "Double GGX Λ(x)", (-30, 16, 3), dggx);
    out.push('\n');
    // The f32 path: cubics suffice for 2e-6 (Λ's condition number in x is at most ~1, so x
    // computed in f32 costs a few ulp, not more).
    let e1_32 = table32::<4>(&mut out, "DGGX32", "Double GGX Λ(x)", (-30, 16, 3), dggx);
    out.push('\n');
    // Double GGX D = G(1/y)/(π α² u⁴), y = tan²θ/α² = (1 − u)(1 + u)/(α²u²) (one division):
    // the slope kernel G = c²((1 + c) e^c E₁(c) − 1) at c = 1/y, from 1 near the normal to
    // ~ln(y)/y² at grazing, on octaves of y.
    let e8 = table::<10>(&mut out, "DGGX_D", "Double GGX G(1/y)", (-30, 30, 2), |y| {
        crate::math::special::dggx_g(1.0 / y)
    });
    out.push('\n');
    // The Exponential NDF: Λ itself as a function of q = z² (one division from (u, α), no
    // square root) on octaves of q, 8 segments per octave up to q = 64 (z = 8) and 32 from
    // there to q = 4096 (z = 64), where an octave of q spans z ∈ [8, 11.3) … [45, 64): the
    // segments stay narrow enough in z (≤ 0.7) for e^{−z} to be a polynomial, so no
    // exponential at run time. Beyond, Λ e^z on octaves of z, and one exponential restores
    // the factor.
    let lambda_q = |q: f64| exponential(q.sqrt());
    let (a, e2) = table_octaves::<6>(
        &mut out,
        "EXPONENTIAL_QA",
        "Exponential Λ(√q)",
        (-24, 6, 4),
        lambda_q,
    );
    let (b, e6) = table_octaves::<6>(
        &mut out,
        "EXPONENTIAL_QB",
        "Exponential Λ(√q)",
        (6, 12, 6),
        lambda_q,
    );
    writeln!(
        out,
        "/// Both, in one array: rows 0 .. EXPONENTIAL_QB_ROW0 for QA, then QB."
    )
    .unwrap();
    writeln!(out, "pub const EXPONENTIAL_QB_ROW0: usize = {};", a.len()).unwrap();
    write_rows(&mut out, "EXPONENTIAL_Q", "f64", &[a, b].concat());
    out.push('\n');
    // The f32 path: q stays in f64 (Λ ~ e^{−z} has a condition number of about z in z, up
    // to 64 here, so q rounded to f32 would cost up to ~2e-6), but cubics with f32
    // coefficients on finer segments suffice: the segments span at most ~0.17 in z.
    let e9 = table_narrow::<4>(
        &mut out,
        "EXPONENTIAL32_QA",
        "Exponential Λ(√q)",
        (-24, 6, 5),
        lambda_q,
    );
    out.push('\n');
    let e10 = table_narrow::<4>(
        &mut out,
        "EXPONENTIAL32_QB",
        "Exponential Λ(√q)",
        (6, 12, 7),
        lambda_q,
    );
    out.push('\n');
    let e7 = table::<7>(
        &mut out,
        "EXPONENTIAL_FAR",
        "Exponential Λ(z) e^z",
        (5, 9, 3),
        |z| exponential(z) * z.exp(),
    );
    out.push('\n');
    let e3 = table::<11>(
        &mut out,
        "ERFCX",
        "erfcx(x) = e^{x²} erfc x",
        (-30, 5, 3),
        erfcx,
    );
    out.push('\n');
    let e5 = table::<11>(
        &mut out,
        "ERFC_RATIO",
        "r(a) = 1 − √π a erfcx(a)",
        (-30, 5, 3),
        erfc_ratio,
    );
    out.push('\n');
    let e4 = table::<11>(
        &mut out,
        "ERFINV",
        "erfinv(v)/v at w = −ln(1 − v²)",
        (-30, 10, 3),
        erfinv_ratio,
    );
    out.push('\n');
    // Exp(1) and the half-normal |N(0, 1)| for the fast samplers' variates (`fast::ziggurat`).
    let z1 = ziggurat(
        &mut out,
        "ZIG_EXP",
        "Ziggurat of e^{−x} (Exp(1))",
        |x| (-x).exp(),
        |y| -y.ln(),
        |r| (-r).exp(),
    );
    out.push('\n');
    let z2 = ziggurat(
        &mut out,
        "ZIG_NORMAL",
        "Ziggurat of e^{−x²/2} (the half-normal)",
        |x| (-0.5 * x * x).exp(),
        |y| (-2.0 * y.ln()).sqrt(),
        |r| (std::f64::consts::PI / 2.0).sqrt() * libm::erfc(r / std::f64::consts::SQRT_2),
    );
    assert!(z1 < 1e-12 && z2 < 1e-12, "ziggurat layers unequal");
    assert!(
        e1 < 1e-8 && e2 < 1e-8 && e6 < 1e-8 && e7 < 1e-8 && e8 < 1e-8,
        "fit error too large"
    );
    // f32 tables: well inside the 2e-6 required of the f32 paths, leaving room for the
    // rounding of their inputs.
    assert!(
        e1_32 < 5e-7 && e9 < 5e-7 && e10 < 5e-7,
        "f32 fit error too large"
    );
    // The references are good to a few ulp (libm erf, and r cancels up to 10× below 2).
    assert!(
        e3 < 5e-15 && e4 < 5e-15 && e5 < 5e-15,
        "fit error too large"
    );
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/src/fast/tables.rs");
    std::fs::write(path, out).expect("src/fast/tables.rs is writable");
    eprintln!("wrote {path}");
}
