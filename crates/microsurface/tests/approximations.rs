//! The Exponential page's approximations, measured against the exact values. The figures
//! asserted here are the ones stated in `exponential::approx`'s docs (and derivations.md C).

use microsurface::ndf::exponential::approx::{ei_g1, ei_sigma, g1_rational};
use microsurface::{Exponential, Ndf};

/// ζ = cot θ/α on a log grid over [1e-3, 1e3]; G1 depends on u and α only through ζ.
fn zetas() -> impl Iterator<Item = f64> {
    (0..=3000).map(|k| 10f64.powf(-3.0 + 6.0 * k as f64 / 3000.0))
}

fn u_of(zeta: f64, alpha: f64) -> f64 {
    let c = zeta * alpha; // cot θ
    c / (1.0 + c * c).sqrt()
}

#[test]
fn ei_g1_with_alpha_scaled_by_1_7() {
    let exact = Exponential::new(1.0).unwrap();
    let (mut worst, mut at) = (0.0f64, 0.0);
    for z in zetas() {
        let u = u_of(z, 1.0);
        let e = (ei_g1(u, 1.7) - exact.g1(u)).abs();
        if e > worst {
            (worst, at) = (e, z);
        }
    }
    println!("Ei G1(u, 1.7α): max abs error {worst:.3e} at ζ = {at:.3}");
    assert!((3.0e-3..3.1e-3).contains(&worst), "{worst}");
    assert!((1.0..1.5).contains(&at), "{at}");
}

#[test]
fn rational_g1_fit() {
    let exact = Exponential::new(1.0).unwrap();
    let (mut vs_exact, mut vs_ei) = (0.0f64, 0.0f64);
    for z in zetas() {
        let u = u_of(z, 1.0);
        vs_exact = vs_exact.max((g1_rational(u, 1.0) - exact.g1(u)).abs());
        if z / 1.7 < 1.5 {
            vs_ei = vs_ei.max((g1_rational(u, 1.0) - ei_g1(u, 1.7)).abs());
        }
    }
    println!("G1approx: max abs error {vs_exact:.3e} vs exact, {vs_ei:.3e} vs Ei G1(1.7α)");
    assert!((3.0e-3..3.1e-3).contains(&vs_exact), "{vs_exact}");
    assert!(vs_ei < 3.5e-5, "{vs_ei}");
    // The jump at the x = 1.5 switch (derivations.md C): 0.99939 → 1.
    let u = u_of(1.5 * 1.7 * (1.0 - 1e-12), 1.0);
    assert!((g1_rational(u, 1.0) - 0.99939).abs() < 1e-5);
}

#[test]
fn ei_sigma_with_alpha_scaled_by_1_7() {
    // derivations.md C: 2.1e-4 (α = 0.05), 1.7e-3 (0.5), 2.5e-3 (1.0) over u ∈ [−1, 1].
    for (alpha, expected) in [(0.05, 2.1e-4), (0.5, 1.7e-3), (1.0, 2.5e-3)] {
        let exact = Exponential::new(alpha).unwrap();
        let worst = (0..=2000)
            .map(|k| -1.0 + 2.0 * k as f64 / 2000.0)
            .map(|u| (ei_sigma(u, 1.7 * alpha) - exact.sigma(u)).abs())
            .fold(0.0, f64::max);
        println!("Ei σ(u, 1.7α) at α = {alpha}: max abs error {worst:.3e}");
        assert!((worst / expected - 1.0).abs() < 0.1, "α = {alpha}: {worst}");
    }
}
