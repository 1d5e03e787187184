//! The run-time door: `AnyMicrofacet<F>` returns bit-identical values, samples and pdfs to
//! the static `Microfacet<F, N>` for every NDF (f32 and f64, isotropic and anisotropic,
//! normal to grazing incidence, edge uniforms), and the exact path for the generalised
//! exponential; NDF specs parse case-insensitively with aliases and errors that list the
//! valid names.

use microsurface::fast::Real;
use microsurface::{
    AnyMicrofacet, Beckmann, BesselK, DoubleGgx, Ei, Erfc, Exact, Exponential, Ggx, Gtr,
    Microfacet, MicrofacetDistribution, NdfKind, NdfSpec, SpecError, StudentT, K0,
};

/// Directions from the normal to the horizon (and below), several azimuths.
fn directions<F: Real>() -> Vec<[F; 3]> {
    let mut out = Vec::new();
    for &theta in &[
        0.0f64,
        0.3,
        1.0,
        1.4,
        1.5607,
        std::f64::consts::FRAC_PI_2 - 1e-7,
    ] {
        for &phi in &[0.0f64, 0.7, 2.0, 4.0] {
            let (s, c) = theta.sin_cos();
            for sign in [1.0, -1.0] {
                out.push([s * phi.cos(), s * phi.sin(), sign * c].map(F::from_f64));
            }
        }
    }
    out
}

fn uniforms<F: Real>() -> Vec<[F; 2]> {
    let one_minus = if F::IS_F32 {
        1.0 - f32::EPSILON as f64 / 2.0
    } else {
        1.0 - f64::EPSILON / 2.0
    };
    let mut out = vec![
        [0.0, 0.0],
        [one_minus, one_minus],
        [0.0, one_minus],
        [0.5, 0.25],
    ];
    for i in 0..8 {
        out.push([
            (i as f64 * 0.618034) % 1.0,
            (i as f64 * 0.381966 + 0.1) % 1.0,
        ]);
    }
    out.into_iter().map(|u| u.map(F::from_f64)).collect()
}

fn same<F: Real>(a: F, b: F, what: &str) {
    let (a, b) = (a.to_f64(), b.to_f64());
    assert!(
        a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
        "{what}: {a:e} vs {b:e}"
    );
}

fn same3<F: Real>(a: [F; 3], b: [F; 3], what: &str) {
    for k in 0..3 {
        same(a[k], b[k], what);
    }
}

/// Every method of the direction trait, bit for bit.
fn identical<F: Real, A: MicrofacetDistribution<F>, B: MicrofacetDistribution<F>>(
    a: &A,
    b: &B,
    name: &str,
) {
    let ws = directions::<F>();
    let us = uniforms::<F>();
    assert_eq!(a.ndf(), b.ndf(), "{name}: ndf");
    assert_eq!(a.effectively_smooth(), b.effectively_smooth(), "{name}");
    same(a.alpha().0, b.alpha().0, name);
    same(a.alpha().1, b.alpha().1, name);
    for &w in &ws {
        same(a.d(w), b.d(w), &format!("{name} d {:?}", w.map(F::to_f64)));
        same(a.lambda(w), b.lambda(w), &format!("{name} lambda"));
        same(a.g1(w), b.g1(w), &format!("{name} g1"));
        same(a.pdf_dcos(w), b.pdf_dcos(w), &format!("{name} pdf_dcos"));
        for &v in ws.iter().step_by(5) {
            same(a.g2(w, v), b.g2(w, v), &format!("{name} g2"));
            same(a.g2_separable(w, v), b.g2_separable(w, v), name);
            same(
                a.d_visible(w, v),
                b.d_visible(w, v),
                &format!("{name} d_visible"),
            );
            same(a.pdf(w, v), b.pdf(w, v), &format!("{name} pdf"));
        }
        for &u in &us {
            let (sa, sb) = (a.sample(w, u), b.sample(w, u));
            same3(
                sa.wm,
                sb.wm,
                &format!(
                    "{name} sample {:?} {:?}",
                    w.map(F::to_f64),
                    u.map(F::to_f64)
                ),
            );
            same(sa.pdf, sb.pdf, &format!("{name} sample pdf"));
            same3(a.sample_wm(w, u), b.sample_wm(w, u), name);
            let (mut s1, mut s2) = (0.1f64, 0.1f64);
            let mut next1 = || {
                s1 = (s1 * 1.618034 + 0.137) % 1.0;
                F::from_f64(s1)
            };
            let ra = a.sample_wm_stream(w, &mut next1);
            let mut next2 = || {
                s2 = (s2 * 1.618034 + 0.137) % 1.0;
                F::from_f64(s2)
            };
            let rb = b.sample_wm_stream(w, &mut next2);
            match (ra, rb) {
                (Some(x), Some(y)) => same3(x, y, &format!("{name} stream")),
                (None, None) => {}
                _ => panic!("{name}: sample_wm_stream Some/None differ"),
            }
        }
    }
    for &u in &us {
        let (sa, sb) = (a.sample_dcos(u), b.sample_dcos(u));
        same3(sa.wm, sb.wm, &format!("{name} sample_dcos"));
        same(sa.pdf, sb.pdf, &format!("{name} sample_dcos pdf"));
    }
}

fn every_ndf<F: Real>() {
    for (ax, ay) in [(0.3, 0.3), (0.5, 0.12), (1.5e-6, 1.5e-6), (2.0, 0.7)] {
        let (fx, fy) = (F::from_f64(ax), F::from_f64(ay));
        let any = |kind, shape| AnyMicrofacet::<F>::new(kind, fx, fy, shape).unwrap();
        let iso = ax == ay;
        identical(
            &any(NdfKind::Ggx, None),
            &Microfacet::<F, Ggx>::new(fx, fy).unwrap(),
            "ggx",
        );
        identical(
            &any(NdfKind::Beckmann, None),
            &Microfacet::<F, Beckmann>::new(fx, fy).unwrap(),
            "beckmann",
        );
        identical(
            &any(NdfKind::DoubleGgx, None),
            &Microfacet::<F, DoubleGgx>::new(fx, fy).unwrap(),
            "double_ggx",
        );
        identical(
            &any(NdfKind::Exponential, None),
            &Microfacet::<F, Exponential>::new(fx, fy).unwrap(),
            "exponential",
        );
        let gammas: &[f64] = if iso { &[2.0, 1.5, 0.7] } else { &[2.0] };
        for &g in gammas {
            identical(
                &any(NdfKind::Gtr, Some(g)),
                &Microfacet::<F, Gtr>::gtr(fx, fy, g).unwrap(),
                "gtr",
            );
        }
        for g in [2.5, 8.0] {
            identical(
                &any(NdfKind::StudentT, Some(g)),
                &Microfacet::<F, StudentT>::with_shape(fx, fy, Some(g)).unwrap(),
                "student_t",
            );
        }
        identical(
            &any(NdfKind::Ei, None),
            &Microfacet::<F, Ei>::with_shape(fx, fy, None).unwrap(),
            "ei",
        );
        identical(
            &any(NdfKind::Erfc, None),
            &Microfacet::<F, Erfc>::with_shape(fx, fy, None).unwrap(),
            "erfc",
        );
        identical(
            &any(NdfKind::K0, None),
            &Microfacet::<F, K0>::with_shape(fx, fy, None).unwrap(),
            "k0",
        );
        identical(
            &any(NdfKind::BesselK, Some(0.7)),
            &Microfacet::<F, BesselK>::with_shape(fx, fy, Some(0.7)).unwrap(),
            "bessel_k",
        );
    }
}

#[test]
fn bit_identical_to_the_static_type_f64() {
    every_ndf::<f64>();
}

#[test]
fn bit_identical_to_the_static_type_f32() {
    every_ndf::<f32>();
}

/// The generalised exponential runs its exact path: the same bits as `Exact` in f64, and
/// its values rounded to f32 in f32.
#[test]
fn gen_exponential_is_the_exact_path() {
    let any = AnyMicrofacet::<f64>::new(NdfKind::GenExponential, 0.4, 0.25, Some(1.5)).unwrap();
    assert!(!any.is_fast());
    let exact = Exact::new(NdfKind::GenExponential, 0.4, 0.25, Some(1.5)).unwrap();
    let w = [0.3, -0.2, 0.932737905308881];
    same(any.d(w), exact.d(w), "d");
    same(any.lambda(w), exact.lambda(w), "lambda");
    let (a, b) = (any.sample(w, [0.3, 0.8]), exact.sample(w, [0.3, 0.8]));
    same3(a.wm, b.wm, "sample");
    same(a.pdf, b.pdf, "pdf");
    let any32 = AnyMicrofacet::<f32>::new(NdfKind::GenExponential, 0.4, 0.25, Some(1.5)).unwrap();
    let exact = Exact::new(
        NdfKind::GenExponential,
        f64::from(0.4f32),
        f64::from(0.25f32),
        Some(1.5),
    )
    .unwrap();
    let w32 = w.map(|x| x as f32);
    let w64 = w32.map(f64::from);
    assert_eq!(any32.lambda(w32), exact.lambda(w64) as f32);
    assert_eq!(any32.d(w32), exact.d(w64) as f32);
}

#[test]
fn every_kind_builds_reports_itself_and_runs_fast_but_one() {
    for kind in NdfKind::ALL {
        let shape = kind.shape_name().map(|n| if n == "a" { 0.7 } else { 2.5 });
        let m = AnyMicrofacet::<f32>::new(kind, 0.3, 0.3, shape).unwrap();
        assert_eq!(m.kind(), kind);
        assert_eq!(m.spec(), NdfSpec { kind, shape }, "{kind}");
        assert_eq!(m.ndf(), Some((kind, shape)), "{kind}");
        assert_eq!(m.is_fast(), kind != NdfKind::GenExponential);
        assert_eq!(m.exact().ndf(), Some((kind, shape)), "{kind}");
        let s = m.sample([0.6, 0.0, 0.8], [0.25, 0.5]);
        assert!(s.pdf > 0.0 && s.pdf.is_finite(), "{kind}: {s:?}");
    }
}

#[test]
fn specs_parse_case_insensitively_with_aliases() {
    let cases: &[(&str, NdfKind, Option<f64>)] = &[
        ("ggx", NdfKind::Ggx, None),
        ("GGX", NdfKind::Ggx, None),
        ("trowbridge_reitz", NdfKind::Ggx, None),
        ("Trowbridge-Reitz", NdfKind::Ggx, None),
        ("Beckmann", NdfKind::Beckmann, None),
        ("student_t:2.5", NdfKind::StudentT, Some(2.5)),
        ("Student_T:2.5", NdfKind::StudentT, Some(2.5)),
        ("student-t: 4", NdfKind::StudentT, Some(4.0)),
        ("gtr:1.5", NdfKind::Gtr, Some(1.5)),
        ("GTR:2", NdfKind::Gtr, Some(2.0)),
        ("bessel_k:0.7", NdfKind::BesselK, Some(0.7)),
        ("BesselK:0.7", NdfKind::BesselK, Some(0.7)),
        ("double_ggx", NdfKind::DoubleGgx, None),
        ("Exponential", NdfKind::Exponential, None),
        ("EI", NdfKind::Ei, None),
        ("erfc", NdfKind::Erfc, None),
        ("K0", NdfKind::K0, None),
        (
            "generalized_exponential:1.5",
            NdfKind::GenExponential,
            Some(1.5),
        ),
    ];
    for &(text, kind, shape) in cases {
        let spec: NdfSpec = text.parse().unwrap_or_else(|e| panic!("{text}: {e}"));
        assert_eq!(spec, NdfSpec { kind, shape }, "{text}");
        // Display round-trips.
        assert_eq!(spec.to_string().parse::<NdfSpec>().unwrap(), spec);
        let m = AnyMicrofacet::<f64>::parse(text, 0.3, 0.3).unwrap();
        assert_eq!(m.kind(), kind);
    }
    for kind in NdfKind::ALL {
        assert_eq!(kind.name().to_uppercase().parse::<NdfKind>().unwrap(), kind);
        for alias in kind.aliases() {
            assert_eq!(alias.parse::<NdfKind>().unwrap(), kind, "{alias}");
        }
    }
}

#[test]
fn spec_errors_say_what_is_wrong() {
    let err = |s: &str| s.parse::<NdfSpec>().unwrap_err().to_string();
    let e = err("phong");
    for kind in NdfKind::ALL {
        assert!(e.contains(kind.name()), "{e}");
    }
    assert!(err("gtr").contains("gamma"), "{}", err("gtr"));
    assert!(err("bessel_k").contains(" a "), "{}", err("bessel_k"));
    assert!(err("ggx:2").contains("no shape"), "{}", err("ggx:2"));
    assert!(err("gtr:abc").contains("number"), "{}", err("gtr:abc"));
    assert!(matches!(
        "student_t:1.2".parse::<NdfSpec>(),
        Ok(NdfSpec {
            kind: NdfKind::StudentT,
            ..
        })
    ));
    // Ranges are checked where the material is built.
    let e = AnyMicrofacet::<f64>::parse("student_t:1.2", 0.3, 0.3).unwrap_err();
    assert!(matches!(e, SpecError::Param(_)), "{e}");
    let e = AnyMicrofacet::<f64>::parse("gtr:1.5", 0.3, 0.2).unwrap_err();
    assert!(e.to_string().contains("anisotropic"), "{e}");
    assert!(AnyMicrofacet::<f32>::parse("ggx", f32::NAN, 0.3).is_err());
    // A long name is clipped in the message.
    let long = "x".repeat(100_000);
    assert!(err(&long).len() < 400);
}

/// The process-wide fit cache: materials of one family shape at other α, built after the
/// shape's first material, give the bits of a material built alone.
#[test]
fn fits_are_shared_across_materials() {
    let a = AnyMicrofacet::<f64>::parse("bessel_k:3.25", 0.3, 0.3).unwrap();
    for i in 0..100 {
        let alpha = 0.1 + 0.01 * i as f64;
        let _ = AnyMicrofacet::<f64>::parse("bessel_k:3.25", alpha, alpha).unwrap();
    }
    let b = AnyMicrofacet::<f64>::parse("bessel_k:3.25", 0.3, 0.3).unwrap();
    let c = Microfacet::<f64, BesselK>::with_shape(0.3, 0.3, Some(3.25)).unwrap();
    for w in directions::<f64>() {
        same(a.lambda(w), b.lambda(w), "cached lambda");
        same(a.lambda(w), c.lambda(w), "cached lambda");
    }
}
