//! Matched roughness (`AnyNdf::matched`): for every NDF and every quantity, the matched NDF's
//! quantity equals the reference's to the exact path's accuracy; matching an NDF to itself
//! gives its α back; the mean slope is π σ(0) (the identity behind `MatchBy::MeanSlope`,
//! checked by quadrature of the radial slope density); the unreachable cases are typed
//! errors.

use microsurface::check::quad;
use microsurface::ndf::{MatchBy, MatchError};
use microsurface::{AnyNdf, Ndf, NdfKind, RadialSlopes};

/// Every NDF with a shape where it needs one (Student-T above γ = 3/2: σ(0) finite).
fn every() -> Vec<(NdfKind, Option<f64>)> {
    NdfKind::ALL
        .iter()
        .map(|&k| {
            let shape = match k {
                NdfKind::Gtr => Some(1.5),
                NdfKind::StudentT => Some(4.0),
                NdfKind::BesselK => Some(0.7),
                NdfKind::GenExponential => Some(3.0),
                _ => None,
            };
            (k, shape)
        })
        .collect()
}

#[test]
fn matched_quantities_equal_the_reference() {
    for reference in [
        AnyNdf::new(NdfKind::Ggx, 0.3, None).unwrap(),
        AnyNdf::new(NdfKind::Beckmann, 0.35, None).unwrap(),
        AnyNdf::new(NdfKind::StudentT, 1.2, Some(2.5)).unwrap(),
    ] {
        for (kind, shape) in every() {
            for by in MatchBy::ALL {
                let m = AnyNdf::matched(kind, shape, &reference, by)
                    .unwrap_or_else(|e| panic!("{kind:?} {by}: {e}"));
                let (got, want) = (by.of(&m), by.of(&reference));
                if by == MatchBy::G1At45 {
                    // (And Λ(45°), which carries the match where G1 rounds to 1.)
                    let l = |n: &AnyNdf| n.lambda(std::f64::consts::FRAC_1_SQRT_2);
                    let rel = (l(&m) / l(&reference) - 1.0).abs();
                    assert!(rel <= 1e-10, "{kind:?} Λ(45°): {rel:e}");
                }
                // (The exact path's accuracy: quadratures and the quantile's Newton steps
                // ≤ 1e-10; the bisection's bracket adds < 1e-16.)
                let rel = (got / want - 1.0).abs();
                assert!(rel <= 1e-10, "{kind:?} {by}: {got} vs {want} ({rel:e})");
                assert_eq!(m.kind(), kind);
                assert_eq!(m.shape(), shape.filter(|_| kind.shape_name().is_some()));
            }
        }
    }
}

#[test]
fn matching_an_ndf_to_itself_gives_its_alpha() {
    for (kind, shape) in every() {
        for alpha in [1e-3, 0.3, 7.0] {
            let n = AnyNdf::new(kind, alpha, shape).unwrap();
            for by in MatchBy::ALL {
                let m = AnyNdf::matched(kind, shape, &n, by).unwrap();
                if by == MatchBy::G1At45 && n.lambda(std::f64::consts::FRAC_1_SQRT_2) == 0.0 {
                    // (Λ(45°) underflows, e^{−1/α²} for Beckmann at α = 1e-3: every smaller
                    // α matches too; the match is one of them.)
                    assert_eq!(m.lambda(std::f64::consts::FRAC_1_SQRT_2), 0.0, "{kind:?}");
                    continue;
                }
                let rel = (m.alpha() / alpha - 1.0).abs();
                assert!(
                    rel <= 1e-9,
                    "{kind:?} α={alpha} {by}: {} ({rel:e})",
                    m.alpha()
                );
            }
        }
    }
}

#[test]
fn mean_slope_is_pi_sigma_zero() {
    // E[tan θm] under D cos θm = ∫ r p(r) dr with p the radial slope density, against
    // π σ(0); and so the two matches give the same α.
    for (kind, shape) in every() {
        let n = AnyNdf::new(kind, 0.4, shape).unwrap();
        let mean = quad::integrate_to_inf(|r| r * n.slope_pdf(r), 0.0, 0.4, 1e-12).value;
        let rel = (mean / (std::f64::consts::PI * n.sigma_zero()) - 1.0).abs();
        assert!(
            rel < 1e-8,
            "{kind:?}: E[r] = {mean}, π σ(0) = {} ({rel:e})",
            std::f64::consts::PI * n.sigma_zero()
        );
        let g = AnyNdf::new(NdfKind::Ggx, 0.3, None).unwrap();
        let a = AnyNdf::matched(kind, shape, &g, MatchBy::MeanSlope).unwrap();
        let b = AnyNdf::matched(kind, shape, &g, MatchBy::SigmaZero).unwrap();
        assert!((a.alpha() / b.alpha() - 1.0).abs() < 1e-12, "{kind:?}");
    }
}

#[test]
fn unreachable_matches_are_typed_errors() {
    let g = AnyNdf::new(NdfKind::Ggx, 0.3, None).unwrap();
    // Student-T at γ ≤ 3/2: σ(0) = ∞ at every α.
    let heavy = AnyNdf::new(NdfKind::StudentT, 0.3, Some(1.4)).unwrap();
    assert!(matches!(
        AnyNdf::matched(NdfKind::Ggx, None, &heavy, MatchBy::SigmaZero),
        Err(MatchError::Unreachable { .. })
    ));
    assert!(matches!(
        AnyNdf::matched(NdfKind::StudentT, Some(1.4), &g, MatchBy::SigmaZero),
        Err(MatchError::Unreachable { .. })
    ));
    assert!(matches!(
        AnyNdf::matched(NdfKind::Gtr, Some(-1.0), &g, MatchBy::G1At45),
        Err(MatchError::Param(_))
    ));
    assert_eq!("G1_45".parse::<MatchBy>(), Ok(MatchBy::G1At45));
    assert!("rms".parse::<MatchBy>().is_err());
    let e = AnyNdf::matched(NdfKind::StudentT, Some(1.4), &g, MatchBy::SigmaZero).unwrap_err();
    assert!(e.to_string().contains("sigma0"), "{e}");
}
