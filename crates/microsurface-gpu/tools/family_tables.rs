//! The blocks of Double GGX and the Exponential NDF in the tables buffer (`tools/tables.rs`), written
//! from the Rust library's own tables (`microsurface::fast::tables`, generated there by
//! `gen_tables.rs`), never refitted or retyped: the f32 Λ tables (`DGGX32`,
//! `EXPONENTIAL32_QA`, `EXPONENTIAL32_QB`) bit for bit, and the f64 ones that the WGSL needs
//! in f32 (the Double GGX slope kernel `DGGX_D`, the Exponential far table
//! `EXPONENTIAL_FAR`, the ziggurats' layers `ZIG_*`: Exp(1) and the half normal) rounded to f32, their coefficients
//! below the least normal f32 written as 0 (a device may flush them; their terms are below
//! 2^−126 of the row's value).
//!
//! The rounding of an f64 table costs each row at most Σ|c_j| 2^−24 absolutely; the
//! generator measures the relative difference of the rounded row from the f64 row (both
//! evaluated in f64) on 64 points per segment and panics past `ROUND_TOL`.

use super::tables::Block;
use microsurface::fast::tables as t;

/// The largest relative change of an f64 table's value by the rounding of its coefficients
/// to f32: a few units of f32's 2^−24 (the constant coefficient alone is up to 2^−24, the
/// others add their magnitudes' share); the WGSL's own f32 evaluation then adds a few ε.
const ROUND_TOL: f64 = 2.5e-7;

/// f32 of an f64 coefficient, 0 below the least normal f32.
fn narrow(c: f64) -> f32 {
    let v = c as f32;
    if v.abs() < f32::MIN_POSITIVE {
        0.0
    } else {
        v
    }
}

/// Σ c_k s^k in f64 (Horner).
fn horner64(c: &[f64], s: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &k| acc * s + k)
}

/// One octave table's block: its K0/K1/M and its rows, each padded with zeros to `per` vec4.
fn table(
    name: &str,
    what: &str,
    (k0, k1, m): (i32, i32, u32),
    rows: &[Vec<f32>],
    per: usize,
) -> Block {
    assert_eq!(rows.len(), ((k1 - k0) as usize) << m, "{name}: rows");
    let mut out = Vec::with_capacity(rows.len() * per);
    for r in rows {
        let mut r = r.clone();
        r.resize(4 * per, 0.0);
        out.extend(r.chunks(4).map(|q| [q[0], q[1], q[2], q[3]]));
    }
    Block {
        name: name.into(),
        what: what.into(),
        consts: vec![
            format!("const {name}_K0: i32 = {k0};"),
            format!("const {name}_K1: i32 = {k1};"),
            format!("const {name}_M: u32 = {m}u;"),
        ],
        rows: out,
    }
}

/// An f64 table rounded to f32, with the largest relative change of its values (64 points
/// per segment) checked against `ROUND_TOL`.
fn rounded<const N: usize>(name: &str, rows: &[[f64; N]]) -> (Vec<Vec<f32>>, f64) {
    let mut worst = 0.0f64;
    let out: Vec<Vec<f32>> = rows
        .iter()
        .map(|r| {
            let c: Vec<f32> = r.iter().map(|&x| narrow(x)).collect();
            let c64: Vec<f64> = c.iter().map(|&x| x as f64).collect();
            for k in 0..64 {
                let s = -1.0 + 2.0 * (k as f64 + 0.5) / 64.0;
                let v = horner64(r, s);
                worst = worst.max(((horner64(&c64, s) - v) / v).abs());
            }
            c
        })
        .collect();
    assert!(
        worst <= ROUND_TOL,
        "{name}: rounding {worst:e} > {ROUND_TOL:e}"
    );
    (out, worst)
}

/// An f32 table as rows.
fn exact<const N: usize>(rows: &[[f32; N]]) -> Vec<Vec<f32>> {
    rows.iter().map(|r| r.to_vec()).collect()
}

/// A ziggurat's layers as rows (x_i, f_i, x_{i+1}, f_{i+1}), i < 256, rounded to f32: one
/// fetch gives a layer's both edges.
fn ziggurat(name: &str, what: &str, x: &[f64], f: &[f64]) -> Block {
    assert!(
        x.len() == 257 && f.len() == 257,
        "a ziggurat has 256 layers"
    );
    Block {
        name: name.into(),
        what: format!("{what}: row i = (x_i, f(x_i), x_{{i+1}}, f(x_{{i+1}}))."),
        consts: Vec::new(),
        rows: (0..256)
            .map(|i| [x[i] as f32, f[i] as f32, x[i + 1] as f32, f[i + 1] as f32])
            .collect(),
    }
}

/// The blocks of Double GGX and the Exponential NDF. Octave tables as fast::fit's: x ∈
/// [2^K0, 2^K1), 2^M segments per octave, each segment's polynomial in s ∈ [−1, 1) (s⁰
/// first, zero-padded to whole vec4). Panics if a rounded table moves past `ROUND_TOL`.
pub fn blocks() -> Vec<Block> {
    let mut out = Vec::new();
    out.push(table(
        "MS_DG_LAMBDA",
        "Double GGX Λ(x), x = α² tan²θ/2: the Rust DGGX32 (f32 cubics), bit for bit.",
        (t::DGGX32_K0, t::DGGX32_K1, t::DGGX32_M),
        &exact(&t::DGGX32),
        1,
    ));
    let (rows, worst) = rounded("MS_DG_D", &t::DGGX_D);
    out.push(table(
        "MS_DG_D",
        &format!(
            "Double GGX slope kernel G(1/y), y = tan²θ/α²: the Rust DGGX_D (degree 9, f64) \
             rounded to f32 (largest relative change {worst:.1e})."
        ),
        (t::DGGX_D_K0, t::DGGX_D_K1, t::DGGX_D_M),
        &rows,
        3,
    ));
    out.push(table(
        "MS_EXP_QA",
        "Exponential Λ(√q), q = z² < 64: the Rust EXPONENTIAL32_QA (f32 cubics), bit for bit.",
        (
            t::EXPONENTIAL32_QA_K0,
            t::EXPONENTIAL32_QA_K1,
            t::EXPONENTIAL32_QA_M,
        ),
        &exact(&t::EXPONENTIAL32_QA),
        1,
    ));
    out.push(table(
        "MS_EXP_QB",
        "Exponential Λ(√q), 64 ≤ q < 4096: the Rust EXPONENTIAL32_QB (f32 cubics), bit for bit.",
        (
            t::EXPONENTIAL32_QB_K0,
            t::EXPONENTIAL32_QB_K1,
            t::EXPONENTIAL32_QB_M,
        ),
        &exact(&t::EXPONENTIAL32_QB),
        1,
    ));
    let (rows, worst) = rounded("MS_EXP_FAR", &t::EXPONENTIAL_FAR);
    out.push(table(
        "MS_EXP_FAR",
        &format!(
            "Exponential Λ(z) e^z on octaves of z: the Rust EXPONENTIAL_FAR (degree 6, f64) \
             rounded to f32 (largest relative change {worst:.1e})."
        ),
        (
            t::EXPONENTIAL_FAR_K0,
            t::EXPONENTIAL_FAR_K1,
            t::EXPONENTIAL_FAR_M,
        ),
        &rows,
        2,
    ));
    out.push(ziggurat(
        "MS_ZIG_EXP",
        "The Exp(1) ziggurat's layers, f(x) = e^{−x} (the Rust ZIG_EXP_X and ZIG_EXP_F, rounded to f32)",
        &t::ZIG_EXP_X,
        &t::ZIG_EXP_F,
    ));
    out.push(ziggurat(
        "MS_ZIG_NORMAL",
        "The half-normal ziggurat's layers, f(x) = e^{−x²/2} (the Rust ZIG_NORMAL_X and ZIG_NORMAL_F, rounded to f32)",
        &t::ZIG_NORMAL_X,
        &t::ZIG_NORMAL_F,
    ));
    out
}
