//! D·cos sampling: the radial CDFs against quadrature of the density, quantile round trips,
//! and the warp's inverse.

use microfacet::sample::{invert_dcos, pdf_dcos, sample_dcos};
use microfacet::{quad, AnyNdf, Ndf, NdfKind, RadialSlopes};

fn family() -> Vec<AnyNdf> {
    let mut v = Vec::new();
    for a in [1e-4, 0.05, 0.3, 1.0, 2.0] {
        for k in NdfKind::ALL {
            if k == NdfKind::Gtr {
                for g in [0.5, 1.0, 1.0 + 1e-12, 1.5, 2.0, 3.7] {
                    v.push(AnyNdf::new(k, a, Some(g)).unwrap());
                }
                v.push(AnyNdf::new(k, 1.0 + 1e-12, Some(2.5)).unwrap());
            } else {
                v.push(AnyNdf::new(k, a, None).unwrap());
            }
        }
    }
    v
}

#[test]
fn radial_cdf_is_the_integral_of_the_density() {
    for n in family() {
        let a = n.alpha();
        for x in [0.01, 0.3, 1.0, 3.0] {
            let r = a * x;
            let q = quad::integrate(|s| n.slope_pdf(s), 0.0, r, 1e-14).value;
            let (f, fc) = (n.slope_cdf(r), n.slope_ccdf(r));
            assert!(
                (f - q).abs() <= 1e-12 * q.max(1e-300) + 1e-300,
                "{n:?} F({r}) = {f} vs ∫ = {q}"
            );
            assert!((f + fc - 1.0).abs() < 1e-15, "{n:?} F + (1 − F) at {r}");
        }
    }
}

#[test]
fn quantile_round_trips() {
    for n in family() {
        for xi in [1e-12, 1e-6, 0.01, 0.3, 0.5, 0.7, 0.99, 1.0 - 1e-9] {
            let r = n.slope_quantile(xi);
            assert!(r.is_finite() && r >= 0.0, "{n:?} r({xi}) = {r}");
            let back = if xi <= 0.5 {
                n.slope_cdf(r)
            } else {
                1.0 - n.slope_ccdf(r)
            };
            let err = if xi <= 0.5 {
                (back - xi).abs() / xi
            } else {
                (n.slope_ccdf(r) - (1.0 - xi)).abs() / (1.0 - xi)
            };
            assert!(
                err < 1e-12,
                "{n:?} ξ = {xi}: r = {r}, back = {back}, rel err {err:e}"
            );
        }
    }
}

#[test]
fn dcos_warp_inverts() {
    for n in family() {
        for u in [
            [0.1, 0.2],
            [0.5, 0.9],
            [0.93, 0.01],
            [1e-7, 0.5],
            [0.999999, 0.75],
        ] {
            let wm = sample_dcos(&n, u);
            assert!(
                (wm.length() - 1.0).abs() < 1e-15 && wm.z > 0.0,
                "{n:?} {u:?} {wm:?}"
            );
            assert!(pdf_dcos(&n, wm).is_finite());
            let back = invert_dcos(&n, wm);
            for k in 0..2 {
                assert!((back[k] - u[k]).abs() < 1e-12, "{n:?} {u:?} → {back:?}");
            }
        }
    }
}

#[test]
fn dcos_pdf_is_normalised() {
    for n in family() {
        if n.alpha() < 0.01 {
            continue; // the u-space integral is ill-conditioned there (see verify::u_space_tol)
        }
        // ∫ D(m) cos θm dm over the hemisphere = 2π ∫₀¹ D(u) u du.
        let q = quad::integrate(
            |u| pdf_dcos(&n, microfacet::Vec3::new((1.0 - u * u).sqrt(), 0.0, u)),
            0.0,
            1.0,
            1e-14,
        );
        let total = 2.0 * std::f64::consts::PI * q.value;
        assert!((total - 1.0).abs() < 1e-11, "{n:?}: {total}");
    }
}
