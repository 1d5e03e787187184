//! The rest of the book's NDF family (Student-T, Ei, Erfc, K0, Bessel-K, generalised
//! exponential): the special cases against the existing NDFs, the limits and the pole of
//! Student-T, spot values from mpmath, the parameter ranges, and the exact samplers'
//! round trips. (Reference records: tests/reference.rs; identities: tests/identities.rs;
//! χ²: tests/chi2.rs.)

use microsurface::{
    AnyNdf, Beckmann, BesselK, Exact, Exponential, GenExponential, Ggx, MicrofacetDistribution,
    Ndf, NdfKind, ParamError, RadialSlopes, StudentT, K0,
};

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        return 0.0;
    }
    (a - b).abs() / a.abs().max(b.abs())
}

const US: [f64; 9] = [1e-6, 0.02, 0.2, 0.45, 0.7, 0.9, 0.99, 0.999_999, 1.0];
const SLOPES: [f64; 7] = [0.0, 1e-4, 0.05, 0.4, 1.3, 4.0, 30.0];

/// Every quantity of `a` against `b` (b at the roughness given), worst relative difference.
fn worst(a: &AnyNdf, b: &AnyNdf) -> f64 {
    let mut w = 0.0f64;
    for u in US {
        for v in [a.d(u) - 0.0, a.lambda(u), a.sigma(u), a.sigma(-u), a.g1(u)]
            .iter()
            .zip([b.d(u), b.lambda(u), b.sigma(u), b.sigma(-u), b.g1(u)])
        {
            let r = rel(*v.0, v.1);
            assert!(!r.is_nan(), "{} vs {} at u = {u}", a.name(), b.name());
            if v.0.abs() > 1e-300 || v.1.abs() > 1e-300 {
                w = w.max(r);
            }
        }
    }
    for p in SLOPES {
        for (x, y) in [
            (a.p2(p), b.p2(p)),
            (a.p22(p, 0.3), b.p22(p, 0.3)),
            (a.slope_ccdf(p), b.slope_ccdf(p)),
            (a.slope_cdf(p), b.slope_cdf(p)),
        ] {
            if x.abs() > 1e-300 || y.abs() > 1e-300 {
                w = w.max(rel(x, y));
            }
        }
    }
    w
}

fn any(kind: NdfKind, alpha: f64, shape: Option<f64>) -> AnyNdf {
    AnyNdf::new(kind, alpha, shape).unwrap()
}

/// Student-T γ = 2 ≡ GGX; Bessel-K a = 1 ≡ K0 and a = 3/2 ≡ Exponential; the generalised
/// exponential γ = 2 ≡ Beckmann and γ = 1 ≡ Exponential(2α): every quantity, to 1e-13 where
/// both sides are closed forms and 1e-12 where one is a quadrature.
#[test]
fn special_cases() {
    for alpha in [0.01, 0.3, 1.0, 2.5] {
        let cases = [
            (
                any(NdfKind::StudentT, alpha, Some(2.0)),
                any(NdfKind::Ggx, alpha, None),
                1e-13,
            ),
            (
                any(NdfKind::BesselK, alpha, Some(1.0)),
                any(NdfKind::K0, alpha, None),
                1e-12,
            ),
            (
                any(NdfKind::BesselK, alpha, Some(1.5)),
                any(NdfKind::Exponential, alpha, None),
                1e-12,
            ),
            (
                any(NdfKind::GenExponential, alpha, Some(2.0)),
                any(NdfKind::Beckmann, alpha, None),
                1e-12,
            ),
            (
                any(NdfKind::GenExponential, alpha, Some(1.0)),
                any(NdfKind::Exponential, 2.0 * alpha, None),
                1e-12,
            ),
        ];
        for (a, b, tol) in cases {
            let w = worst(&a, &b);
            println!(
                "{} {:?} α={alpha} vs {}: {w:.2e}",
                a.name(),
                a.shape(),
                b.name()
            );
            assert!(
                w <= tol,
                "{} {:?} α={alpha} vs {}: {w:e}",
                a.name(),
                a.shape(),
                b.name()
            );
        }
    }
}

/// Student-T → Beckmann as γ → ∞ (relative difference O((r/α)⁴/γ)); Bessel-K at large a with
/// α√a fixed → Beckmann (O(1/a)).
#[test]
fn limits() {
    let b = Beckmann::new(0.3).unwrap();
    let t = StudentT::new(0.3, 1e6).unwrap();
    for u in [0.3, 0.6, 0.9, 0.99] {
        // D: (1 + x²/(γ−1))^{−γ} e^{x²} − 1 ≈ x⁴/(2γ) − x²/γ, x = tan θ/α.
        let x2 = (1.0 - u * u) / (u * u * 0.09);
        assert!(
            rel(t.d(u), b.d(u)) < (x2 * x2 + x2) / 1e6 + 1e-10,
            "D u={u}"
        );
        // Λ: the tail beyond cot θ decides, where the exponent differs by ~x_c⁴/(2γ).
        let xc2 = u * u / ((1.0 - u * u) * 0.09);
        assert!(
            rel(t.lambda(u), b.lambda(u)) < (x2 + xc2).powi(2) / 1e6 + 1e-10,
            "Λ u={u}"
        );
        // Bessel-K: the difference falls like 1/a (once x⁴/a ≪ 1: near the normal only).
        if u > 0.3 {
            continue;
        }
        let d = |a: f64| {
            rel(
                BesselK::new(0.3 / a.sqrt(), a).unwrap().lambda(u),
                b.lambda(u),
            )
        };
        let ratio = d(25.0) / d(100.0);
        assert!((3.5..4.5).contains(&ratio), "Bessel-K Λ u={u}: {ratio}");
    }
}

/// Student-T's pole: Λ and σ are infinite for γ ≤ 3/2 (G1 = 0), and the direction API says so.
#[test]
fn student_t_below_the_pole() {
    for g in [1.0 + 1e-12, 1.2, 1.5] {
        let t = StudentT::new(0.3, g).unwrap();
        assert!(!t.has_finite_lambda());
        assert_eq!(t.lambda(0.5), f64::INFINITY);
        assert_eq!(t.g1(0.5), 0.0);
        assert_eq!(t.sigma_zero(), f64::INFINITY);
        // D is normalised all the same (∫ 2π r P22 dr = 1 − Q(∞)).
        assert_eq!(t.slope_ccdf(0.0), 1.0);
        assert!(t.d(0.5).is_finite() && t.p2(0.2).is_finite());
        let err = Exact::new(NdfKind::StudentT, 0.3, 0.3, Some(g)).unwrap_err();
        assert!(matches!(err, ParamError::Shape { .. }), "{err}");
    }
    // Just above: finite, large, and growing as 1/(2γ − 3).
    let l1 = StudentT::new(0.3, 1.5 + 1e-6).unwrap().lambda(0.5);
    let l2 = StudentT::new(0.3, 1.5 + 2e-6).unwrap().lambda(0.5);
    assert!(l1.is_finite() && l1 > 1e4, "{l1}");
    assert!((l1 / l2 - 2.0).abs() < 1e-3, "{l1} {l2}");
}

/// Parameter ranges: typed errors with the NDF's name.
#[test]
fn shape_ranges() {
    let bad = [
        (NdfKind::StudentT, 1.0),
        (NdfKind::StudentT, 2e6),
        (NdfKind::StudentT, f64::NAN),
        (NdfKind::BesselK, 0.09),
        (NdfKind::BesselK, 101.0),
        (NdfKind::BesselK, f64::INFINITY),
        (NdfKind::GenExponential, 0.05),
        (NdfKind::GenExponential, 21.0),
        (NdfKind::GenExponential, -1.0),
    ];
    for (kind, v) in bad {
        let e = AnyNdf::new(kind, 0.3, Some(v)).unwrap_err();
        let msg = e.to_string();
        assert!(msg.starts_with(kind.name()), "{msg}");
        assert!(Exact::new(kind, 0.3, 0.3, Some(v)).is_err());
    }
    for kind in [NdfKind::StudentT, NdfKind::BesselK, NdfKind::GenExponential] {
        assert!(
            AnyNdf::new(kind, 0.3, None).is_err(),
            "{kind}: shape required"
        );
    }
    for kind in NdfKind::FAMILY {
        assert!(AnyNdf::new(kind, 0.0, Some(2.0)).is_err());
    }
}

/// mpmath at 30 digits (scripts/reference.py's routes: closed form, Smith, delta, CCDF and
/// mixture integrals agree to 1e-19), α = 0.4, u = 0.7.
#[test]
fn spot_values() {
    let cases: [(AnyNdf, f64); 5] = [
        (
            any(NdfKind::StudentT, 0.4, Some(2.5)),
            0.011558334792630308062,
        ),
        (any(NdfKind::K0, 0.4, None), 0.0007589590612387241326),
        (any(NdfKind::Ei, 0.4, None), 2.1411729765019448321e-6),
        (
            any(NdfKind::BesselK, 0.4, Some(1.7)),
            0.002147483582189558633,
        ),
        (
            any(NdfKind::GenExponential, 0.4, Some(3.0)),
            1.4375129356412679751e-10,
        ),
    ];
    for (n, want) in cases {
        let got = n.lambda(0.7);
        assert!(
            rel(got, want) < 1e-13,
            "{} Λ(0.7) = {got:e}, want {want:e}",
            n.name()
        );
    }
    // K0's Λ is e^{−2x}/(4x): the Exponential NDF at a = 3/2, K0 at a = 1 (closed forms).
    let k = K0::new(0.4).unwrap();
    let x = 0.7 / (1.0 - 0.49f64).sqrt() / 0.4;
    assert!(rel(k.lambda(0.7), (-2.0 * x).exp() / (4.0 * x)) < 1e-15);
    let _ = (
        Ggx::new(0.3),
        Exponential::new(0.3),
        GenExponential::new(0.3, 2.0),
    );
}

/// The exact samplers of the family (D·cos and visible normals through [`Exact`]) are
/// invertible warps: the inverse returns the uniforms.
#[test]
fn samplers_round_trip() {
    let shapes = [
        (NdfKind::StudentT, Some(1.8)),
        (NdfKind::Ei, None),
        (NdfKind::Erfc, None),
        (NdfKind::K0, None),
        (NdfKind::BesselK, Some(0.7)),
        (NdfKind::GenExponential, Some(5.0)),
    ];
    let wi = [0.6, 0.3, 0.742_462_120_245_875];
    for (kind, shape) in shapes {
        let e = Exact::new(kind, 0.4, 0.15, shape).unwrap();
        for u in [[0.1, 0.2], [0.5, 0.9], [0.93, 0.01], [0.999, 0.5]] {
            let s = e.sample_dcos(u);
            let back = e.invert_dcos(s.wm);
            assert!(
                (back[0] - u[0]).abs() < 1e-9 && (back[1] - u[1]).abs() < 1e-9,
                "{kind} D·cos {u:?} → {back:?}"
            );
            assert!(s.pdf > 0.0 && s.pdf.is_finite());
            let m = e.sample_wm(wi, u);
            let back = e.invert(wi, m);
            assert!(
                (back[0] - u[0]).abs() < 1e-8 && (back[1] - u[1]).abs() < 1e-8,
                "{kind} visible {u:?} → {back:?}"
            );
            let dot = wi[0] * m[0] + wi[1] * m[1] + wi[2] * m[2];
            assert!(dot > 0.0 && m[2] > 0.0, "{kind}: {m:?} not visible");
        }
    }
}
