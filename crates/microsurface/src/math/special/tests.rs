//! The special functions against mpmath (tests/data/special.json, scripts/special_reference.py).
//! The bounds asserted here are the ones stated in `mod.rs`. (Unit tests: the special
//! functions are crate-private.)

use crate::math::special;
use serde_json::Value;

fn data() -> Value {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/special.json"
    ))
    .unwrap();
    serde_json::from_str(&text).unwrap()
}

fn max_rel(name: &str, f: impl Fn(f64) -> f64) -> f64 {
    max_rel_in(name, 0.0, f64::INFINITY, f)
}

/// Largest relative error over the reference points with lo ≤ x ≤ hi.
fn max_rel_in(name: &str, lo: f64, hi: f64, f: impl Fn(f64) -> f64) -> f64 {
    let d = data();
    let pts = d[name].as_array().unwrap();
    assert!(pts.len() >= 40, "{name}: too few points");
    let mut worst: f64 = 0.0;
    for pt in pts {
        let x = pt[0].as_f64().unwrap();
        if !(lo..=hi).contains(&x) {
            continue;
        }
        let want = pt[1].as_f64().unwrap();
        let got = f(x);
        let err = if want == 0.0 {
            got.abs()
        } else {
            ((got - want) / want).abs()
        };
        assert!(err.is_finite(), "{name}({x}) = {got}, want {want}");
        worst = worst.max(err);
    }
    println!("{name:20} max rel err {worst:.2e}");
    worst
}

#[test]
fn libm_functions() {
    assert!(max_rel("erf", special::erf) <= 3e-16);
    // Used only for x ≤ 3 (Beckmann Λ, the Ei approximation); musl's erfc is off by up to
    // 5e-14 in the far tail (x ≈ 15), which the library never evaluates.
    assert!(max_rel_in("erfc", 0.0, 3.0, special::erfc) <= 3e-16);
    assert!(max_rel("erfc", special::erfc) <= 1e-13);
}

#[test]
fn cephes_functions() {
    // Used only for x < 1 (Double GGX kernel); Cephes' E1 loses up to 3e-14 near x ≈ 200.
    assert!(max_rel_in("e1", 0.0, 1.0, special::e1) <= 5e-15);
    assert!(max_rel("e1", special::e1) <= 5e-14);
    assert!(max_rel("k0e", special::k0e) <= 5e-15);
    assert!(max_rel("k1e", special::k1e) <= 5e-15);
    assert!(max_rel("elliprd_0_y_1", |y| special::elliprd(0.0, y, 1.0)) <= 5e-15);
}

#[test]
fn cancellation_free_combinations() {
    assert!(max_rel("erfc_ratio_tail", special::erfc_ratio_tail) <= 2e-15);
    assert!(max_rel("dggx_g", special::dggx_g) <= 1e-14);
    assert!(max_rel("bessel_k_sum_m1", special::bessel_k_sum_m1) <= 4e-15);
}

#[test]
fn hypergeometric_u_identity_holds_in_mpmath() {
    // √π U(−½, 0, 2x) = x eˣ (K₀(x) + K₁(x)) (derivations.md A.5), checked by the script at 30 digits.
    assert!(data()["u_identity_max_rel"].as_f64().unwrap() < 1e-25);
}

/// ln K_ν(z) of real order (the trapezoidal rule of `special::ln_bessel_k`) against mpmath
/// over ν ∈ [0, 100] and z ∈ [5e-324, 1e4]: the error of ln K, |Δ ln K| (K's relative error),
/// within 3(1e-15 + ε(|ln K| + z)), the rounding of ln K itself and the conditioning of
/// e^{−z} (as `src/special/mod.rs` states).
#[test]
fn ln_bessel_k_matches_mpmath() {
    let d = data();
    let pts = d["ln_bessel_k"].as_array().unwrap();
    assert!(pts.len() >= 500);
    let (mut worst, mut at) = (0.0f64, (0.0, 0.0));
    for pt in pts {
        let (nu, z, want) = (
            pt[0].as_f64().unwrap(),
            pt[1].as_f64().unwrap(),
            pt[2].as_f64().unwrap(),
        );
        let got = special::ln_bessel_k(nu, z);
        let scaled = (got - want).abs() / (1e-15 + f64::EPSILON * (want.abs() + z));
        assert!(scaled.is_finite(), "ln K_{nu}({z}) = {got}, want {want}");
        if scaled > worst {
            (worst, at) = (scaled, (nu, z));
        }
    }
    println!(
        "ln_bessel_k: worst |Δ ln K| / (1e-15 + ε(|ln K| + z)) = {worst:.2} at ν = {}, z = {}",
        at.0, at.1
    );
    assert!(worst <= 3.0, "{worst:e} at ν = {}, z = {}", at.0, at.1);
}

/// B(1 + x, 1 + y) (`special::beta_1p`) against mpmath over x ≤ y ∈ [0, 1e300] (both
/// branches, both sides of 1 + y = 10): relative error within 4ε(1 + |ln B|), as `mod.rs`
/// states, where B is a normal number (below 1e-300 only that it is as small); symmetric;
/// the edges exact: 1 at (0, 0), 0 at ∞, NaN outside [0, ∞].
#[test]
fn beta_1p_matches_mpmath() {
    let d = data();
    let pts = d["beta_1p"].as_array().unwrap();
    assert!(pts.len() >= 300);
    let (mut worst, mut at) = (0.0f64, (0.0, 0.0));
    for pt in pts {
        let (x, y, want) = (
            pt[0].as_f64().unwrap(),
            pt[1].as_f64().unwrap(),
            pt[2].as_f64().unwrap(),
        );
        let got = special::beta_1p(x, y);
        assert_eq!(
            got.to_bits(),
            special::beta_1p(y, x).to_bits(),
            "({x}, {y})"
        );
        assert!((0.0..=1.0).contains(&got), "B(1 + {x}, 1 + {y}) = {got}");
        if want < 1e-300 {
            assert!(got < 1e-299, "B(1 + {x}, 1 + {y}) = {got}, want {want}");
            continue;
        }
        let scaled = ((got - want) / want).abs() / (f64::EPSILON * (1.0 + want.ln().abs()));
        if scaled > worst {
            (worst, at) = (scaled, (x, y));
        }
    }
    println!(
        "beta_1p: worst |ΔB/B| / (ε(1 + |ln B|)) = {worst:.2} at x = {}, y = {}",
        at.0, at.1
    );
    assert!(worst <= 4.0, "{worst} at x = {}, y = {}", at.0, at.1);
    assert_eq!(special::beta_1p(0.0, 0.0), 1.0);
    // (p + q overflows: B(1 + f64::MAX, 1) = 1/(1 + f64::MAX), a subnormal of ~50 bits.)
    let b = special::beta_1p(f64::MAX, 0.0);
    assert!((b * f64::MAX - 1.0).abs() < 1e-10, "{b:e}");
    assert_eq!(special::beta_1p(f64::MAX, f64::MAX), 0.0);
    for x in [0.0, 1.0, 1e300, f64::INFINITY] {
        assert_eq!(special::beta_1p(x, f64::INFINITY), 0.0);
        assert_eq!(special::beta_1p(f64::INFINITY, x), 0.0);
    }
    for (x, y) in [
        (f64::NAN, 1.0),
        (1.0, f64::NAN),
        (-1e-300, 0.0),
        (0.0, -2.0),
    ] {
        assert!(special::beta_1p(x, y).is_nan(), "({x}, {y})");
    }
}

/// The Gamma(k) density (`special::gamma_pdf`) against mpmath, k from 0.3 to 1e9, across the
/// peak and its tails: within 2ε(1 + |ln p|) relative from k = 10 (the exponent's own
/// rounding), 2ε(1 + |k − 1||ln t| + t + |ln Γ(k)|) below (the direct exponent's terms).
#[test]
fn gamma_pdf_matches_mpmath() {
    let d = data();
    let pts = d["gamma_pdf"].as_array().unwrap();
    assert!(pts.len() >= 90);
    let mut worst = 0.0f64;
    for pt in pts {
        let (k, t, want) = (
            pt[0].as_f64().unwrap(),
            pt[1].as_f64().unwrap(),
            pt[2].as_f64().unwrap(),
        );
        let got = special::gamma_pdf(k, t);
        let scale = if k >= 10.0 {
            1.0 + want.ln().abs()
        } else {
            1.0 + (k - 1.0).abs() * t.ln().abs() + t + special::ln_gamma(k).abs()
        };
        let err = ((got - want) / want).abs() / (f64::EPSILON * scale);
        assert!(
            err <= 2.0,
            "gamma_pdf({k}, {t}) = {got:e}, want {want:e} ({err:.2} of ε·scale)"
        );
        worst = worst.max(err);
    }
    println!("gamma_pdf max rel err {worst:.2} of ε·scale");
    for (k, t) in [
        (2.0, 0.0),
        (2.0, -1.0),
        (2.0, f64::INFINITY),
        (1e6, f64::NAN),
    ] {
        assert_eq!(special::gamma_pdf(k, t), 0.0);
    }
}
