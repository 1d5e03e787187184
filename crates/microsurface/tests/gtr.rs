//! GTR's special cases: Burley's constants (eqs 1, 4, 6, 8), and continuity of the general
//! (numerical) path into the closed forms at γ = 1, 3/2, 2 and α = 1.

use microsurface::{Ggx, Gtr, Ndf};
use std::f64::consts::PI;

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        ((a - b) / b).abs()
    }
}

#[test]
fn burley_constants() {
    for a in [1e-4f64, 0.1, 0.5, 0.9, 1.5, 10.0] {
        let c1 = (a * a - 1.0) / (PI * (a * a).ln());
        assert!(rel(Gtr::new(a, 1.0).unwrap().c(), c1) < 1e-14, "γ=1 α={a}");
        let c32 = a * (1.0 + a) / (2.0 * PI);
        assert!(
            rel(Gtr::new(a, 1.5).unwrap().c(), c32) < 1e-14,
            "γ=3/2 α={a}"
        );
        let c2 = a * a / PI;
        assert!(rel(Gtr::new(a, 2.0).unwrap().c(), c2) < 1e-14, "γ=2 α={a}");
        let g = 3.3;
        let cg = (g - 1.0) * (a * a - 1.0) / (PI * (1.0 - (a * a).powf(1.0 - g)));
        assert!(rel(Gtr::new(a, g).unwrap().c(), cg) < 1e-13, "γ={g} α={a}");
    }
    // α = 1: D ≡ 1/π for every γ, and no 0/0 within 1e-12 of it.
    for g in [0.2, 1.0, 1.0 + 1e-12, 1.5, 2.0, 7.0] {
        for a in [1.0, 1.0 - 1e-12, 1.0 + 1e-12] {
            let n = Gtr::new(a, g).unwrap();
            for u in [1e-9, 0.3, 1.0] {
                assert!(
                    rel(n.d(u), 1.0 / PI) < 1e-11,
                    "α={a} γ={g} u={u}: {}",
                    n.d(u)
                );
            }
        }
    }
}

#[test]
fn general_path_meets_the_special_forms() {
    for a in [0.05, 0.4, 1.0 + 1e-9, 2.5] {
        for (special, eps) in [(1.0, 1e-12), (1.5, 1e-13), (2.0, 1e-13)] {
            let exact = Gtr::new(a, special).unwrap();
            for g in [special - eps, special + eps] {
                let near = Gtr::new(a, g).unwrap();
                for u in [0.05, 0.5, 0.99] {
                    for (name, x, y) in [
                        ("D", near.d(u), exact.d(u)),
                        ("Λ", near.lambda(u), exact.lambda(u)),
                        ("σ(−u)", near.sigma(-u), exact.sigma(-u)),
                    ] {
                        // The true change over |γ − γ₀| ≤ 1e-12 is below 1e-10 relative.
                        assert!(rel(x, y) < 1e-10, "α={a} γ={g} {name}({u}): {x} vs {y}");
                    }
                }
                for p in [0.0, 0.3, 4.0] {
                    assert!(
                        rel(near.p2(p), exact.p2(p)) < 1e-10,
                        "α={a} γ={g} P2({p}): {} vs {}",
                        near.p2(p),
                        exact.p2(p)
                    );
                }
            }
        }
    }
}

#[test]
fn gamma_two_is_ggx() {
    for a in [1e-3, 0.3, 1.0, 4.0] {
        let (gtr, ggx) = (Gtr::new(a, 2.0).unwrap(), Ggx::new(a).unwrap());
        for u in [-0.5, 0.0, 0.2, 0.7, 1.0] {
            assert!(rel(gtr.d(u), ggx.d(u)) < 1e-15 || gtr.d(u) == ggx.d(u));
            assert!(rel(gtr.sigma(u), ggx.sigma(u)) < 1e-15);
            assert!(rel(gtr.g1(u), ggx.g1(u)) < 1e-15 || gtr.g1(u) == ggx.g1(u));
        }
        for (p, q) in [(0.0, 0.0), (0.3, -1.2), (7.0, 0.1)] {
            assert!(rel(gtr.p22(p, q), ggx.p22(p, q)) < 1e-14);
            assert!(rel(gtr.p2(p), ggx.p2(p)) < 1e-15);
        }
    }
}

#[test]
fn gamma_below_one_is_not_specular() {
    // derivations.md E: for γ < 1, c → (1 − γ)/π as α → 0 and D → (1 − γ)/(π (1 − u²)^γ).
    let g = 0.5;
    let n = Gtr::new(1e-6, g).unwrap();
    assert!(rel(n.c(), (1.0 - g) / PI) < 1e-6);
    let u: f64 = 0.6;
    assert!(rel(n.d(u), (1.0 - g) / (PI * (1.0 - u * u).powf(g))) < 1e-6);
}
