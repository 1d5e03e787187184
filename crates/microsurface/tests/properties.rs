//! Property tests over the whole parameter domain: α ∈ [1e-6, 1e6] (log-uniform, plus the
//! edges 1e-4 and 10 the issue names), γ ∈ (0, 100], every direction including u = 0, ±1.
//!
//! D ≥ 0, 0 ≤ G1 ≤ 1, 0 ≤ G2 ≤ 1, σ ≥ 0, σ(u) − σ(−u) = u, Λ decreasing in u, and no NaN or
//! infinity anywhere. The exceptions are true values: Λ(0) = +∞ by definition, and the poles
//! of the singular NDFs (D(1) = P22(0, 0) = +∞ for Ei, Erfc, K0 and Bessel-K a ≤ 1; P2(0) = +∞
//! for Erfc and Bessel-K a ≤ ½), and +∞ where the true value overflows (Bessel-K a < 1:
//! P22 ~ r^{2a−2}).

mod common;

use common::overflows_truly;
use microsurface::{AnyNdf, Ndf, NdfKind};
use proptest::prelude::*;

fn kind() -> impl Strategy<Value = NdfKind> {
    prop::sample::select(NdfKind::ALL.to_vec())
}

fn alpha() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-6.0f64..6.0).prop_map(|e| 10f64.powf(e)),
        prop::sample::select(vec![
            1e-6,
            1e-4,
            0.01,
            1.0 - 1e-12,
            1.0,
            1.0 + 1e-12,
            10.0,
            1e6
        ]),
    ]
}

fn gamma() -> impl Strategy<Value = f64> {
    prop_oneof![
        (1e-3f64..100.0),
        (-3.0f64..2.0).prop_map(|e| 10f64.powf(e)),
        prop::sample::select(vec![0.5, 1.0 - 1e-12, 1.0, 1.0 + 1e-12, 1.5, 2.0, 100.0]),
    ]
}

fn cosine() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-1.0f64..=1.0),
        (-300.0f64..0.0).prop_map(|e| 10f64.powf(e)),
        (-300.0f64..0.0).prop_map(|e| 1.0 - 10f64.powf(e)),
        prop::sample::select(vec![0.0, -0.0, 1.0, -1.0, 1e-300, 1.0 - 1e-16]),
    ]
}

fn slope() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-10.0f64..10.0),
        (-300.0f64..300.0).prop_map(|e| 10f64.powf(e)),
        prop::sample::select(vec![0.0, -0.0, 1e-300, 1e300]),
    ]
}

/// γ of GTR as drawn; the family's shapes mapped into their ranges (Student-T above its
/// pole γ = 3/2, where Λ is finite).
fn shape_for(kind: NdfKind, g: f64) -> Option<f64> {
    match kind {
        NdfKind::Gtr => Some(g),
        NdfKind::StudentT => Some(1.5 + 1e-9 + g),
        NdfKind::BesselK => Some(g.clamp(0.1, 100.0)),
        NdfKind::GenExponential => Some(g.clamp(0.1, 20.0)),
        _ => None,
    }
}

fn ndf() -> impl Strategy<Value = AnyNdf> {
    (kind(), alpha(), gamma()).prop_map(|(k, a, g)| AnyNdf::new(k, a, shape_for(k, g)).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn values_are_finite_and_in_range(n in ndf(), u in cosine(), v in cosine(), p in slope(), q in slope()) {
        let d = n.d(u);
        let pole = n.singular_at_pole() && u >= 1.0 && d == f64::INFINITY;
        prop_assert!(d.is_finite() && d >= 0.0 || pole, "{n:?} D({u}) = {d}");
        if u <= 0.0 { prop_assert_eq!(d, 0.0); }
        let s = n.sigma(u);
        prop_assert!(s.is_finite() && s >= 0.0, "{n:?} σ({u}) = {s}");
        let g1 = n.g1(u);
        prop_assert!((0.0..=1.0).contains(&g1), "{n:?} G1({u}) = {g1}");
        let g2 = n.g2(u, v);
        prop_assert!((0.0..=1.0).contains(&g2), "{n:?} G2({u},{v}) = {g2}");
        prop_assert!(g2 <= g1.min(n.g1(v)) * (1.0 + 1e-12), "G2 ≤ min G1");
        let gs = n.g2_separable(u, v);
        prop_assert!((0.0..=1.0).contains(&gs));
        if u != 0.0 {
            let l = n.lambda(u.abs());
            // (+∞ where the true Λ exceeds f64::MAX: Λ > σ(0)/|u| − ½, which overflows for
            // |u| below ~σ(0)/1.8e308, e.g. the generalised exponential at α = 1e6, γ = 0.1,
            // σ(0) = 2.2e19, u = 9.7e-290.)
            let overflows = n.sigma(0.0) / u.abs() - 0.5 >= f64::MAX;
            prop_assert!(l.is_finite() && l >= 0.0 || (l == f64::INFINITY && (u.abs() < 1e-290 || overflows)),
                "{n:?} Λ({u}) = {l}");
        }
        let p22 = n.p22(p, q);
        let pole = p22 == f64::INFINITY
            && ((n.singular_at_pole() && p == 0.0 && q == 0.0)
                || overflows_truly(|x| n.p22(x, 0.0), p.hypot(q), 1e6));
        prop_assert!(p22.is_finite() && p22 >= 0.0 || pole, "{n:?} P22({p},{q}) = {p22}");
        let p2 = n.p2(p);
        let pole = p2 == f64::INFINITY
            && ((n.p2_singular_at_zero() && p == 0.0) || overflows_truly(|x| n.p2(x), p, 1e6));
        prop_assert!(p2.is_finite() && p2 >= 0.0 || pole, "{n:?} P2({p}) = {p2}");
        if let Some(f) = n.f(p) {
            let pole = f == f64::INFINITY
                && ((n.singular_at_pole() && p == 0.0) || overflows_truly(|x| n.f(x).unwrap(), p, 1e6));
            prop_assert!(f.is_finite() && f >= 0.0 || pole, "{n:?} f({p}) = {f}");
        }
    }

    #[test]
    fn sigma_difference_is_u(n in ndf(), u in cosine()) {
        let (a, b) = (n.sigma(u), n.sigma(-u));
        // σ(u) − σ(−u) = u, to a few ulps of the larger side.
        let tol = 4.0 * f64::EPSILON * a.max(b);
        prop_assert!(((a - b) - u).abs() <= tol, "{n:?}: σ({u}) − σ(−{u}) = {} ≠ {u}", a - b);
    }

    #[test]
    fn lambda_decreases(n in ndf(), u in cosine(), v in cosine()) {
        let (lo, hi) = (u.abs().min(v.abs()), u.abs().max(v.abs()));
        if lo == 0.0 {
            return Ok(()); // Λ(0) = +∞: nothing to order
        }
        let (l_lo, l_hi) = (n.lambda(lo), n.lambda(hi));
        // Non-increasing, up to the rounding of the two evaluations.
        prop_assert!(l_lo >= l_hi * (1.0 - 1e-12) - 1e-300, "{n:?}: Λ({lo}) = {l_lo} < Λ({hi}) = {l_hi}");
    }
}
