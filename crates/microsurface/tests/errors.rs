//! Bad parameters are rejected at construction with a typed error that says what is wrong;
//! evaluation is total at the edges of the domain.

use microsurface::{AnyNdf, Beckmann, DoubleGgx, Exponential, Ggx, Gtr, Ndf, NdfKind, ParamError};

#[test]
fn bad_alpha_is_rejected_by_every_ndf() {
    for a in [
        f64::NAN,
        0.0,
        -0.0,
        -1.0,
        f64::INFINITY,
        f64::NEG_INFINITY,
        1e-7,
        1e7,
    ] {
        assert!(matches!(Beckmann::new(a), Err(ParamError::Alpha(_))));
        for kind in NdfKind::ALL {
            let err = AnyNdf::new(kind, a, Some(2.5)).unwrap_err();
            assert!(matches!(err, ParamError::Alpha(_)), "{kind} α={a}: {err:?}");
            let msg = err.to_string();
            assert!(msg.contains("alpha"), "{msg}");
            // (The value as written, in scientific notation past 1e7 and below 1e-4.)
            assert!(
                msg.contains(&format!("{a}")) || msg.contains(&format!("{a:e}")),
                "{msg}"
            );
        }
    }
    assert!(Ggx::new(0.0).is_err());
    assert!(DoubleGgx::new(-2.0).is_err());
    assert!(Exponential::new(f64::NAN).is_err());
}

#[test]
fn bad_gamma_is_rejected() {
    for g in [f64::NAN, 0.0, -1.0, 100.5, f64::INFINITY] {
        let err = Gtr::new(0.3, g).unwrap_err();
        assert!(matches!(err, ParamError::Gamma(_)), "γ={g}: {err:?}");
        assert!(err.to_string().contains("gamma"), "{err}");
    }
    // GTR without γ through AnyNdf is a γ error, not a panic.
    let err = AnyNdf::new(NdfKind::Gtr, 0.3, None).unwrap_err();
    assert!(matches!(err, ParamError::Gamma(_)));
}

/// The shape parameters at the ends of each kind's accepted range (and GTR's γ = 1), or
/// `[None]` for a kind without one.
fn edge_shapes(kind: NdfKind) -> Vec<Option<f64>> {
    match kind {
        NdfKind::Gtr => vec![Some(1.0)],
        NdfKind::StudentT => vec![Some(1.0 + 1e-12), Some(1e6)],
        NdfKind::BesselK => vec![Some(0.1), Some(100.0)],
        NdfKind::GenExponential => vec![Some(0.1), Some(20.0)],
        _ => vec![None],
    }
}

/// Shapes where Λ and σ are finite: the ends of the ranges, Student-T above its pole γ = 3/2.
fn finite_shapes(kind: NdfKind) -> Vec<Option<f64>> {
    match kind {
        NdfKind::Gtr => vec![Some(1.5)],
        NdfKind::StudentT => vec![Some(1.5 + 1e-9), Some(2.5), Some(1e6)],
        _ => edge_shapes(kind),
    }
}

#[test]
fn domain_edges_are_accepted() {
    for a in [1e-6, 1e-4, 1.0, 10.0, 1e6] {
        for kind in NdfKind::ALL {
            for g in edge_shapes(kind) {
                AnyNdf::new(kind, a, g).unwrap();
            }
        }
    }
    for g in [1e-9, 0.5, 1.0, 1.0 + 1e-12, 100.0] {
        Gtr::new(0.5, g).unwrap();
    }
}

#[test]
fn evaluation_at_the_edges() {
    for kind in NdfKind::ALL {
        for (a, g) in [1e-4, 0.3, 1.0, 10.0]
            .into_iter()
            .flat_map(|a| finite_shapes(kind).into_iter().map(move |g| (a, g)))
        {
            let n = AnyNdf::new(kind, a, g).unwrap();
            // Normal incidence: no masking; σ(±1) = (1±1)/2.
            assert_eq!(n.lambda(1.0), 0.0);
            assert_eq!(n.g1(1.0), 1.0);
            assert_eq!(n.sigma(1.0), 1.0);
            assert_eq!(n.sigma(-1.0), 0.0);
            // Grazing: Λ = ∞, G1 = 0, σ(0) finite and positive.
            assert_eq!(n.lambda(0.0), f64::INFINITY);
            assert_eq!(n.g1(0.0), 0.0);
            assert_eq!(n.g2(0.0, 0.5), 0.0);
            let s0 = n.sigma(0.0);
            assert!(s0.is_finite() && s0 > 0.0, "{kind} σ(0) = {s0}");
            // Below the horizon: D = 0; Heitz's Λ(−u) = −1 − Λ(u).
            assert_eq!(n.d(-0.5), 0.0);
            assert_eq!(n.d(0.0), 0.0);
            assert_eq!(n.lambda(-0.5), -1.0 - n.lambda(0.5));
            // Inputs a rounding error outside [−1, 1] are clamped, not NaN.
            assert_eq!(n.d(1.0 + 1e-15), n.d(1.0));
            assert_eq!(n.sigma(-1.0 - 1e-15), 0.0);
            // NaN in gives NaN out (the only NaN the library returns).
            assert!(n.d(f64::NAN).is_nan());
            assert!(n.sigma(f64::NAN).is_nan());
        }
    }
}

#[test]
fn sigma_zero_limits_match_errata() {
    // derivations.md E: σ(0) = √π α/2 (Double GGX), α/2 (GGX), α/(2√π) (Beckmann), α/π (Exponential).
    let a = 0.37;
    let sp = std::f64::consts::PI.sqrt();
    let close = |x: f64, y: f64| (x / y - 1.0).abs() < 1e-15;
    assert!(close(DoubleGgx::new(a).unwrap().sigma(0.0), sp * a / 2.0));
    assert!(close(Ggx::new(a).unwrap().sigma(0.0), a / 2.0));
    assert!(close(Beckmann::new(a).unwrap().sigma(0.0), a / (2.0 * sp)));
    assert!(close(
        Exponential::new(a).unwrap().sigma(0.0),
        a / std::f64::consts::PI
    ));
    // σ is continuous at 0 from both sides.
    for kind in NdfKind::ALL {
        let n = AnyNdf::new(kind, a, Some(2.5)).unwrap();
        let s0 = n.sigma(0.0);
        for u in [1e-9, -1e-9] {
            assert!(
                (n.sigma(u) / s0 - 1.0).abs() < 1e-7,
                "{kind} σ({u}) vs σ(0)"
            );
        }
    }
}
