//! D·cos sampling: the radial CDFs against quadrature of the density, quantile round trips,
//! and the warp's inverse.

use microsurface::check::quad;
use microsurface::sampling::{invert_dcos, pdf_dcos, sample_dcos};
use microsurface::{AnyNdf, Ndf, NdfKind, RadialSlopes};

/// The family's shapes: the ends of each range and the special cases.
fn shapes(k: NdfKind) -> Option<Vec<f64>> {
    match k {
        NdfKind::StudentT => Some(vec![1.2, 1.5 + 1e-9, 2.0, 7.0, 1e3]),
        NdfKind::BesselK => Some(vec![0.1, 0.3, 0.5, 1.0, 1.5, 7.0, 100.0]),
        NdfKind::GenExponential => Some(vec![0.1, 0.5, 1.0, 2.0, 7.0, 20.0]),
        _ => None,
    }
}

fn family() -> Vec<AnyNdf> {
    let mut v = Vec::new();
    for a in [1e-4, 0.05, 0.3, 1.0, 2.0] {
        for k in NdfKind::ALL {
            if k == NdfKind::Gtr {
                for g in [0.5, 1.0, 1.0 + 1e-12, 1.5, 2.0, 3.7] {
                    v.push(AnyNdf::new(k, a, Some(g)).unwrap());
                }
                v.push(AnyNdf::new(k, 1.0 + 1e-12, Some(2.5)).unwrap());
            } else if let Some(shapes) = shapes(k) {
                for g in shapes {
                    v.push(AnyNdf::new(k, a, Some(g)).unwrap());
                }
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
            // In y = ln(r/s): the density's pole at s = 0 (Bessel-K a < ½: s^{2a−1}) becomes
            // an exponential tail, which tanh-sinh in s truncates (3e-9 short at a = 0.1).
            let pdf_y = |y: f64| {
                let s = r * (-y).exp();
                n.slope_pdf(s) * s
            };
            let q = quad::integrate_to_inf(pdf_y, 0.0, 1.0, 1e-14).value;
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
            // (Ill-conditioned there, see verify::u_space_tol: GTR γ = 3.7 at α = 1e-4 gives
            // 1 − 3.6e-11.)
            continue;
        }
        // ∫ D(m) cos θm dm over the hemisphere = 2π ∫ D cos θ sin θ dθ, in θ: in u = cos θ
        // the pole of Erfc's D ~ (1 − u)^{−½} lies within an ulp of u = 1 (4e-7 of the mass
        // at α = 0.05), and small α crowd the mass there. A break at 10α, the peak's scale;
        // above π/4 in π/2 − θ, where the tail of Student-T γ → 1 (mass ~ (π/2 − θ)^{2γ−2})
        // needs the distance to the horizon exactly; below 10α in y = ln(10α/θ), where the
        // pole of Bessel-K a < ½ (D cos θ sin θ ~ θ^{2a−1}) is an exponential tail.
        let f = |t: f64| pdf_dcos(&n, microsurface::Vec3::new(t.sin(), 0.0, t.cos())) * t.sin();
        let g = |t: f64| pdf_dcos(&n, microsurface::Vec3::new(t.cos(), 0.0, t.sin())) * t.cos();
        let quarter = std::f64::consts::FRAC_PI_4;
        let c = (10.0 * n.alpha()).min(quarter);
        let f_y = |y: f64| {
            let t = c * (-y).exp();
            f(t) * t
        };
        let q = quad::integrate_to_inf(f_y, 0.0, 1.0, 1e-14).value
            + quad::integrate(f, c, quarter, 1e-14).value
            + quad::integrate(g, 0.0, quarter, 1e-14).value;
        let total = 2.0 * std::f64::consts::PI * q;
        assert!((total - 1.0).abs() < 1e-11, "{n:?}: {total}");
    }
}

mod visible {
    use microsurface::{
        DoubleGgx, Exact, Exponential, MicrofacetDistribution, Ndf, NdfKind, UnitSlopes, Vec3,
    };

    const KINDS: [NdfKind; 4] = [
        NdfKind::Beckmann,
        NdfKind::Ggx,
        NdfKind::DoubleGgx,
        NdfKind::Exponential,
    ];

    fn dirs() -> Vec<Vec3> {
        let mut v = vec![Vec3::Z, Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, -1.0, 0.0)];
        for deg in [10.0f64, 45.0, 80.0, 89.9] {
            let t = deg.to_radians();
            v.push(Vec3::new(t.sin() * 0.6, t.sin() * 0.8, t.cos()));
            v.push(Vec3::new(-t.sin(), 0.0, -t.cos())); // up-welling
        }
        v
    }

    #[test]
    fn mixture_components_reproduce_the_closed_forms() {
        // The fixed mixing rule against the library's own P2 (independent closed forms).
        let (d, e) = (DoubleGgx::new(1.0).unwrap(), Exponential::new(1.0).unwrap());
        // (Beyond x ≈ 10, where P2 < 1e-8 of its peak, the fixed rule keeps only absolute accuracy.)
        for x in [0.0, 0.01, 0.3, 1.0, 4.0, 8.0] {
            let rd = (UnitSlopes::DoubleGgx.p2(x) / d.p2(x) - 1.0).abs();
            let re = (UnitSlopes::Exponential.p2(x) / e.p2(x) - 1.0).abs();
            assert!(rd < 1e-12 && re < 1e-12, "x = {x}: {rd:e} {re:e}");
        }
    }

    #[test]
    fn visible_warp_inverts_and_stays_finite() {
        for kind in KINDS {
            for (ax, ay) in [(0.3, 0.3), (1e-4, 1e-4), (2.0, 0.5)] {
                let m = Exact::new(kind, ax, ay, None).unwrap();
                for w in dirs() {
                    for u in [[0.1, 0.2], [0.5, 0.5], [0.97, 0.03], [1e-6, 0.999]] {
                        let wm = Vec3::from(m.sample_wm(w.into(), u));
                        assert!(
                            wm.z > 0.0 && (wm.length() - 1.0).abs() < 1e-14,
                            "{kind:?} {w:?} {u:?}: {wm:?}"
                        );
                        let p = m.pdf(w.into(), wm.into());
                        assert!(p.is_finite() && p >= 0.0, "{kind:?} pdf {p}");
                        if ax >= 0.3 && w.z.abs() < 1.0 {
                            let back = m.invert(w.into(), wm.into());
                            for k in 0..2 {
                                assert!(
                                    (back[k] - u[k]).abs() < 1e-9,
                                    "{kind:?} α=({ax},{ay}) w={w:?} {u:?} → {back:?}"
                                );
                            }
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn direction_api_edges() {
        for kind in KINDS {
            let m = Exact::new(kind, 0.4, 0.2, None).unwrap();
            let wm = [0.1, 0.2, 1.0f64];
            let wm = wm.map(|x| x / (0.05f64 + 1.0).sqrt());
            // Grazing and up-welling directions: finite, G1 and G2 in [0, 1] (1 at normal
            // incidence, 0 at grazing), the visible density finite, σ finite and positive.
            for w in dirs() {
                let g = m.g1(w.into());
                assert!((0.0..=1.0).contains(&g), "{kind:?} G1({w:?}) = {g}");
                if w.z == 0.0 {
                    assert_eq!(g, 0.0);
                }
                if w.z.abs() == 1.0 {
                    assert_eq!(g, 1.0);
                }
                let g2 = m.g2(w.into(), [0.0, 0.0, 1.0]);
                assert!((0.0..=1.0).contains(&g2));
                assert!(m.d_visible(w.into(), wm).is_finite());
                let sigma = m.sigma(w.into());
                assert!(sigma.is_finite() && sigma > 0.0);
            }
            assert_eq!(m.d([1.0, 0.0, 0.0]), 0.0);
            assert_eq!(m.d([0.0, 0.0, -1.0]), 0.0);
            // Isotropic case: D and Λ agree with the scalar API.
            let iso = Exact::new(kind, 0.3, 0.3, None).unwrap();
            let n = microsurface::AnyNdf::new(kind, 0.3, None).unwrap();
            for deg in [5.0f64, 40.0, 75.0] {
                let t = deg.to_radians();
                let w = Vec3::new(t.sin() * 0.6, t.sin() * 0.8, t.cos());
                let close = |x: f64, y: f64| (x - y).abs() <= 1e-12 * x.abs().max(y.abs());
                assert!(close(iso.d(w.into()), n.d(w.z)), "{kind:?} D");
                assert!(close(iso.lambda(w.into()), n.lambda(w.z)), "{kind:?} Λ");
                assert!(close(iso.sigma(w.into()), n.sigma(w.z)), "{kind:?} σ");
            }
        }
    }
}

#[test]
fn gtr_visible_warp_inverts() {
    use microsurface::{Exact, MicrofacetDistribution, NdfKind, Vec3};
    for (a, g) in [(0.05, 0.5), (0.3, 1.0), (0.3, 2.5), (1.0, 1.5), (2.0, 3.0)] {
        let m = Exact::new(NdfKind::Gtr, a, a, Some(g)).unwrap();
        for deg in [0.0f64, 30.0, 80.0, 89.0, 90.0, 120.0] {
            let t = deg.to_radians();
            let w = Vec3::new(t.sin() * 0.8, t.sin() * 0.6, t.cos());
            for u in [[0.1, 0.2], [0.5, 0.5], [0.97, 0.03], [1e-6, 0.999]] {
                let wm = Vec3::from(m.sample_wm(w.into(), u));
                assert!(
                    wm.z > 0.0 && (wm.length() - 1.0).abs() < 1e-14,
                    "α={a} γ={g} {deg}° {u:?}: {wm:?}"
                );
                if w.dot(Vec3::Z).abs() > 1e-12 && w.z.abs() < 1.0 - 1e-12 {
                    assert!(
                        wm.dot(if w.z < 0.0 { -w } else { w }) >= -1e-12,
                        "back-facing visible normal"
                    );
                }
                let back = m.invert(w.into(), wm.into());
                if deg != 0.0 {
                    for k in 0..2 {
                        assert!(
                            (back[k] - u[k]).abs() < 1e-9,
                            "α={a} γ={g} {deg}° {u:?} → {back:?}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn ggx_bounded_vndf_properties() {
    use microsurface::bsdf::frame::{dot, reflect};
    use microsurface::{Ggx, Microfacet, MicrofacetDistribution};
    for (ax, ay) in [(0.05, 0.05), (0.3, 0.1), (1.0, 1.0), (2.0, 0.5)] {
        let m = Microfacet::<f64, Ggx>::new(ax, ay).unwrap();
        for deg in [0.0f64, 30.0, 70.0, 89.0] {
            let t = deg.to_radians();
            let wi = [t.sin() * 0.6, t.sin() * 0.8, t.cos()];
            for u in [[0.1, 0.2], [0.5, 0.5], [0.9, 0.97]] {
                let s = m.sample_bounded(wi, u);
                let wm = s.wm;
                assert!(wm[2] > 0.0 && (dot(wm, wm).sqrt() - 1.0).abs() < 1e-14);
                assert_eq!(s.pdf, m.pdf_bounded(wi, wm));
                // The pdf of the reflected direction is the normal's pdf over 4|wi·m|, and
                // never falls below the unbounded sampler's (the cap only shrinks).
                let wo = reflect(wi, wm);
                let p = m.pdf_bounded_reflection(wi, wo);
                let direct = s.pdf / (4.0 * dot(wi, wm).abs());
                assert!((p / direct - 1.0).abs() < 1e-12, "{p} vs {direct}");
                assert!(s.pdf >= m.pdf(wi, wm) * (1.0 - 1e-12));
            }
        }
    }
}

#[test]
fn gtr_quantile_matches_burleys_special_forms() {
    // Burley 2012 appendix B, with ξ = P(cos θh ≥ u) (derivations.md B.3):
    // γ = 1: cos²θ = (α^{2(1−ξ)} − 1)/(α² − 1)          (eq 5)
    // γ = 3/2: w = (1 + (1−ξ)(1/α − 1))^{−2}, cos²θ = (w − 1)/(α² − 1)   (eq 7)
    // γ = 2: cos²θ = (1 − ξ)/(1 + (α² − 1) ξ)            (eq 9)
    // γ general: w^{1−γ} = 1 + (1−ξ)(α^{2(1−γ)} − 1)       (eq 3)
    use microsurface::{Gtr, RadialSlopes};
    for a in [0.05f64, 0.3, 0.8, 2.0] {
        for xi in [0.01, 0.2, 0.5, 0.9, 0.999] {
            let cos2_of = |g: f64| {
                let r = Gtr::new(a, g).unwrap().slope_quantile(xi);
                1.0 / (1.0 + r * r)
            };
            let a2 = a * a;
            let eq5 = (a2.powf(1.0 - xi) - 1.0) / (a2 - 1.0);
            let w7 = (1.0 + (1.0 - xi) * (1.0 / a - 1.0)).powi(-2);
            let eq7 = (w7 - 1.0) / (a2 - 1.0);
            let eq9 = (1.0 - xi) / (1.0 + (a2 - 1.0) * xi);
            let g = 3.3;
            let w3 = (1.0 + (1.0 - xi) * (a2.powf(1.0 - g) - 1.0)).powf(1.0 / (1.0 - g));
            let eq3 = (w3 - 1.0) / (a2 - 1.0);
            for (name, got, want) in [
                ("eq 5", cos2_of(1.0), eq5),
                ("eq 7", cos2_of(1.5), eq7),
                ("eq 9", cos2_of(2.0), eq9),
                ("eq 3", cos2_of(g), eq3),
            ] {
                // The printed forms lose digits near ξ → 1 (cos θ → 0); 1e-12 covers them here.
                assert!(
                    (got / want - 1.0).abs() < 1e-12,
                    "α={a} ξ={xi} {name}: {got} vs {want}"
                );
            }
        }
    }
}
