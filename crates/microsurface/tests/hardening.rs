//! Regression tests of the outside fuzzer's findings (the hardening issue after 1.0's
//! architecture), each its reproducer: the samplers' pdf at non-unit w, GGX's G2 where both
//! G1 are small, the family's `ndf()`, Fresnel at the ends of its parameters, the frame's
//! fallback, the compensated dielectric's horizon, the table files' shape parameter, the D·cos
//! pdf near a pole, Student-T's visible sampler near γ = 3/2 and its D·cos sampler near γ = 1,
//! D far in the tails, f32 D near a narrow pole, and the rough dielectric's transmission at
//! η ≈ 1. Then the contract fuzz's (issue 34, item 2: tests/fuzz.rs's BSDF, Fresnel and
//! compensation suites): Fresnel at grazing for an index ≈ 1 and at tiny, subnormal and
//! huge indices, a zero Fresnel channel at a singular pole, the refraction at a tiny η,
//! samples whose pdf or D had passed through subnormals, an f32 sample whose f overflowed,
//! the conductor's reciprocity, and f32 indices of the shipped dielectric tables. Then
//! issue 47's inputs: a bad η refused where it enters, the walk at η = 1 a delta, f32 α at
//! the documented minimum, u = 1 read below 1, "did you mean" for misspelt names, and the
//! frame of no normal.

use microsurface::bsdf::frame::Frame;
use microsurface::bsdf::fresnel::{conductor, f82_tint};
use microsurface::bsdf::Bsdf;
use microsurface::scattering::table::{Grid, Material, Method, Spec};
use microsurface::scattering::{CompensatedConductor, CompensatedDielectric, Scheme};
use microsurface::{
    AnyMicrofacet, BesselK, Ei, Exact, Ggx, Microfacet, MicrofacetDistribution, NdfKind,
};

/// The sample's pdf is the density at the unit w, whatever w's length (1: the door's
/// samplers took the pdf at the w they were given, 0 at 5e299 and 1.42 at 5e-300).
#[test]
fn sample_pdf_at_any_length() {
    let unit = [0.6, 0.0, 0.8];
    for kind in NdfKind::ALL {
        let shape = some_shape(kind);
        let m = AnyMicrofacet::<f64>::new(kind, 0.3, 0.3, shape).unwrap();
        let want = m.sample(unit, [0.3, 0.6]);
        for s in [3e299 / 0.6, 5.0, 0.1, 3e-300 / 0.6] {
            let got = m.sample(unit.map(|x| x * s), [0.3, 0.6]);
            assert!(
                (got.pdf - want.pdf).abs() <= 1e-12 * want.pdf && want.pdf > 0.0,
                "{kind} |w| = {s}: {} vs {}",
                got.pdf,
                want.pdf
            );
        }
        let m32 = AnyMicrofacet::<f32>::new(kind, 0.3, 0.3, shape).unwrap();
        let w32 = [0.6f32, 0.0, 0.8];
        let want = m32.sample(w32, [0.3, 0.6]).pdf;
        let got = m32.sample(w32.map(|x| x * 1e30), [0.3, 0.6]).pdf;
        assert!(
            (got - want).abs() <= 1e-5 * want,
            "{kind} f32: {got} vs {want}"
        );
    }
    let g = Microfacet::<f64, Ggx>::new(0.3, 0.3).unwrap();
    let want = g.sample_bounded([0.6, 0.0, 0.8], [0.3, 0.6]);
    let got = g.sample_bounded([3e299, 0.0, 4e299], [0.3, 0.6]);
    assert!(got.pdf.is_finite() && (got.pdf - want.pdf).abs() <= 1e-12 * want.pdf);
    for k in 0..3 {
        assert!(
            (got.wm[k] - want.wm[k]).abs() < 1e-15,
            "{:?} vs {:?}",
            got.wm,
            want.wm
        );
    }
}

/// GGX's height-correlated G2 where both G1 are small: G2 = g/(2 − g) (1.0000000027e-8 came
/// out against 1e-8).
#[test]
fn ggx_g2_without_cancellation() {
    use microsurface::fast::ggx;
    let g: f64 = ggx::g1(1e-8, 1.0);
    let want = g / (2.0 - g);
    assert!((ggx::g2(1e-8, 1e-8, 1.0) - want).abs() <= 4e-16 * want);
}

/// The family's materials name their NDF and shape (Ei reported (Gtr, NaN), Bessel-K a = 1
/// (Gtr, 1): the compensation then took GTR γ = 1's shipped table).
#[test]
fn family_materials_name_themselves() {
    let ei = Microfacet::<f64, Ei>::with_shape(0.5, 0.5, None).unwrap();
    assert_eq!(ei.ndf(), Some((NdfKind::Ei, None)));
    let b = Microfacet::<f64, BesselK>::with_shape(0.5, 0.5, Some(1.0)).unwrap();
    assert_eq!(b.ndf(), Some((NdfKind::BesselK, Some(1.0))));
    // Its compensated white furnace (F = 1) is 1 with its own table, not GTR's.
    let c = CompensatedConductor::new(b, microsurface::bsdf::fresnel::One::<1>, Scheme::Turquin);
    let e_gtr1 = AnyMicrofacet::<f64>::parse("gtr:1", 0.5, 0.5).unwrap();
    let t_gtr1 = microsurface::scattering::AlbedoTable::new(&e_gtr1);
    assert!((c.table().e(0.9) - t_gtr1.e(0.9)).abs() > 0.05);
}

/// Fresnel at the ends: n = 1 at grazing is 0 (was NaN), huge k → 1 (was NaN: k² overflowed),
/// F82-tint never negative (−0.0326 at f0 = 0, h = 0) nor above 1.
#[test]
fn fresnel_at_the_ends() {
    assert_eq!(conductor(0.0, 1.0, 0.0), 0.0);
    for (eta, k) in [(1.5, 1e200), (1.5, 1e300), (1e200, 0.0), (1e300, 1e300)] {
        for c in [0.0, 0.5, 1.0] {
            let f: f64 = conductor(c, eta, k);
            assert!((f - 1.0).abs() < 1e-12, "{c} {eta} {k}: {f}");
        }
    }
    for c in [0.0f32, 0.5, 1.0] {
        let f = conductor(c, 1.5f32, 1e20);
        assert!((f - 1.0).abs() < 1e-6, "{c}: {f}");
    }
    // Continuity across the switch to the divided-through form.
    let (a, b): (f64, f64) = (conductor(0.3, 2.0, 0.99e150), conductor(0.3, 2.0, 1.01e150));
    assert!((a - b).abs() < 1e-12, "{a} {b}");
    for h in [0.0, 0.3, 1.0, 1.5] {
        for f0 in [0.0, 0.04, 0.5, 1.0] {
            for k in 0..=100 {
                let v = f82_tint(k as f64 / 100.0, f0, h);
                assert!((0.0..=1.0).contains(&v), "{f0} {h}: {v}");
            }
        }
    }
}

/// A tangent parallel to the normal falls back to `from_normal` (the rounding residue was
/// kept as the tangent: s·n = −0.447).
#[test]
fn frame_tangent_parallel_to_the_normal() {
    let f = Frame::from_normal_tangent([0.6, 0.8, 0.0], [1.8, 2.4, 0.0]);
    let d = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    assert!(d(f.s, f.n).abs() < 1e-15 && (d(f.s, f.s) - 1.0).abs() < 1e-15);
    assert_eq!(f.s, Frame::from_normal([0.6, 0.8, 0.0]).s);
    let g = Frame::from_normal_tangent([0.0, 0.0, 1.0], [1.0, 1e-3, 0.3]);
    assert!(d(g.s, g.n).abs() < 1e-16 && g.s[0] > 0.99);
}

/// The compensated BSDFs reject a sample from wo on the horizon, as the single-scattering
/// ones (it returned f 0, pdf 2.9e-7).
#[test]
fn compensated_samples_from_the_horizon() {
    let d = Microfacet::<f64, Ggx>::new(0.3, 0.3).unwrap();
    let glass = CompensatedDielectric::new(d.clone(), 1.5, Scheme::KullaConty).unwrap();
    assert!(glass.sample([1.0, 0.0, 0.0], 0.0, [0.3, 0.6]).is_none());
    let gold = microsurface::bsdf::fresnel::Conductor {
        eta: [0.2; 3],
        k: [3.9; 3],
    };
    let metal = CompensatedConductor::new(d, gold, Scheme::KullaConty);
    assert!(metal.sample([1.0, 0.0, 0.0], 0.0, [0.3, 0.6]).is_none());
}

/// Table files keep every kind's shape parameter (Student-T's γ came back `None`).
#[test]
fn table_files_keep_the_shape() {
    for (kind, shape) in [
        (NdfKind::StudentT, 2.5),
        (NdfKind::BesselK, 0.7),
        (NdfKind::Gtr, 1.5),
    ] {
        let spec = Spec {
            ndf: kind,
            gamma: Some(shape),
            material: Material::Furnace,
            method: Method::Walk { walks: 20, seed: 1 },
            alpha: vec![0.3],
            mu: vec![0.5],
        };
        let g = Grid::generate(&spec, &|_, _| {}).unwrap();
        let back = Grid::from_bytes(&g.to_bytes()).unwrap();
        assert_eq!(back.spec.gamma, Some(shape), "{kind}");
        assert_eq!(back.spec, spec);
    }
}

/// The D·cos pdf of a normal a slope 1.2e-8 from the pole of a narrow Erfc lobe: finite, the
/// exact path's value (∞ came out: the cosine rounded to 1, D(1) = ∞).
#[test]
fn pdf_dcos_near_the_pole() {
    use microsurface::sampling::pdf_dcos;
    use microsurface::{AnyNdf, Exact, Vec3};
    for kind in [NdfKind::Erfc, NdfKind::Ei, NdfKind::K0] {
        let n = AnyNdf::new(kind, 1e-6, None).unwrap();
        let wm = [1.2e-8, 0.0, 1.0];
        let got = pdf_dcos(&n, Vec3::new(wm[0], wm[1], wm[2]));
        let want = Exact::new(kind, 1e-6, 1e-6, None).unwrap().pdf_dcos(wm);
        assert!(
            got.is_finite() && (got - want).abs() <= 1e-12 * want,
            "{kind}: {got} vs {want}"
        );
    }
}

/// Student-T's D·cos sampler near γ = 1, where the slope quantile's e^{−ln(1−ξ)/(γ−1)}
/// overflows while the slope does not (a horizon normal with pdf 0 came out): the normal
/// mpmath gives (m.z = 1.52026109131556428e-158) and its pdf (2.94456900855253096e153, where
/// D itself overflows).
#[test]
fn student_t_dcos_deep_tail() {
    use microsurface::sampling::{invert_dcos, pdf_dcos, sample_dcos};
    use microsurface::AnyNdf;
    let n = AnyNdf::new(
        NdfKind::StudentT,
        1.7421709987848043e-4,
        Some(1.0001584514173987),
    )
    .unwrap();
    let u = [0.1124482969676256, 0.769620109323919];
    let m = sample_dcos(&n, u);
    let rel = |a: f64, b: f64| ((a - b) / b).abs();
    assert!(rel(m.z, 1.520_261_091_315_564_3e-158) < 1e-12, "{m:?}");
    assert!((m.x.hypot(m.y) - 1.0).abs() < 1e-15);
    let pdf = pdf_dcos(&n, m);
    assert!(rel(pdf, 2.944_569_008_552_531e153) < 1e-12, "{pdf}");
    let back = invert_dcos(&n, m);
    assert!(
        (back[0] - u[0]).abs() < 1e-12 && (back[1] - u[1]).abs() < 1e-12,
        "{back:?}"
    );
}

/// D far in the tail, where an intermediate exponential turns subnormal before D does
/// (Student-T γ = 4.94 at u = 1e-30: 5.8e-7 off, exact and fast paths; mpmath
/// 5.3610729023263829e-194). The tails of every NDF are in tests/data/extra-tails.json.
#[test]
fn d_without_subnormal_intermediates() {
    use microsurface::{Ndf, StudentT};
    let (a, g) = (3.5376889982760974e-3, 4.939988403849865);
    let want = 5.361_072_902_326_383e-194;
    let exact = StudentT::new(a, g).unwrap().d(1e-30);
    assert!(((exact - want) / want).abs() < 1e-13, "{exact:e}");
    let w = [1.0, 0.0, 1e-30];
    let fast = Microfacet::<f64, microsurface::StudentT>::with_shape(a, a, Some(g))
        .unwrap()
        .d(w);
    assert!(((fast - want) / want).abs() < 1e-13, "{fast:e}");
}

/// f32 isotropic D near the pole of a narrow lobe from the vector, not from its rounded
/// cosine (Beckmann α = 2e-3 at a normal 1.4e-3 off the pole was 1.3 % off, the Exponential
/// NDF 1.9 %; Double GGX and GTR too): against the exact D of the same f32 vector (taken
/// exactly into f64), within the f32 paths' documented bounds.
#[test]
fn f32_d_from_the_vector() {
    let x = 0.0014f32;
    let wm = [x, 0.0, (1.0 - x * x).sqrt()];
    let w64 = wm.map(f64::from);
    let n = (w64[0] * w64[0] + w64[2] * w64[2]).sqrt();
    let w64 = w64.map(|c| c / n);
    for (kind, a, shape) in [
        (NdfKind::Beckmann, 2e-3, None),
        (NdfKind::Exponential, 2e-3, None),
        (NdfKind::DoubleGgx, 2e-3, None),
        (NdfKind::Gtr, 2e-3, Some(1.5)),
        (NdfKind::Gtr, 2e-3, Some(1.0)),
        (NdfKind::Ggx, 2e-3, None),
        (NdfKind::StudentT, 2e-3, Some(3.0)),
    ] {
        let m = AnyMicrofacet::<f32>::new(kind, a, a, shape).unwrap();
        let want = m.exact().d(w64);
        let got = m.d(wm) as f64;
        assert!(
            ((got - want) / want).abs() < 2e-5,
            "{kind}: {got:e} vs {want:e}"
        );
    }
}

/// Student-T just above γ = 3/2 from a grazing direction: the visible sampler returns at
/// once (it took 40 s: its tail quadrature, whose integrand per ln r falls like r^{−2e-6},
/// bisected to its depth limit at every CDF evaluation) and its inverse recovers u (0.77385
/// came back for 0.7736, for a normal at slope ~1e99 whose true CDF is 4.6e-4: the truncated
/// quadrature missed 99.98 % of the visible mass, most of which lies beyond slope 1e300).
/// u₀ beyond C(R_MAX) gives the normal at R_MAX, visible from w.
#[test]
fn student_t_near_the_pole_samples_and_inverts() {
    use microsurface::sampling::radial::R_MAX;
    use microsurface::{Exact, Vec3};
    let (ax, ay) = (1.4147301446990699, 1.0);
    let e = Exact::new(NdfKind::StudentT, ax, ay, Some(1.500001)).unwrap();
    // The fuzzer's reproducer.
    let w = [0.7454082234490719, -0.6666082660862364, 1e-300];
    let s = e.sample(w, [0.9643072374426719, 0.5]);
    let wm = Vec3::from(s.wm);
    assert!((wm.length() - 1.0).abs() < 1e-15 && wm.z > 0.0, "{wm:?}");
    assert!(wm.dot(Vec3::from(w)) > 0.0, "{wm:?}");
    assert!(s.pdf.is_finite() && s.pdf > 0.0, "{}", s.pdf);
    let horizon = e.invert(w, s.wm);
    assert!(
        horizon[0] < 2e-3 && (horizon[1] - 0.5).abs() < 1e-12,
        "{horizon:?}"
    );

    // The sampler's normaliser, whose mass at γ = 1.500001 lies mostly beyond the quadrature
    // (the power-law tail), against a(1 + Λ) from Student-T's Λ series (by cot θ = a); on
    // both sides of γ = 7/4, where the tail's quadrature changes (κ = 2γ − 3 = 1/2).
    for gamma in [1.500001, 1.6, 1.7499, 1.7501, 2.5] {
        let n = microsurface::StudentT::new(1.0, gamma).unwrap();
        let unit = Exact::new(NdfKind::StudentT, 1.0, 1.0, Some(gamma)).unwrap();
        for a in [1e-300, 1e-9, 0.11, 3.0, 1e5] {
            let want = a * (1.0 + unit.lambda([1.0, 0.0, a]));
            let z = microsurface::sampling::radial::normaliser(&n, a);
            assert!(
                (z / want - 1.0).abs() < 1e-12,
                "γ = {gamma} a = {a}: {z} vs {want}"
            );
        }
    }

    let dirs = [
        [-0.819, 0.556, 0.141],
        w,
        [0.6, 0.0, 1e-9],
        [0.3, -0.4, -0.5],
        [0.05, 0.02, 0.99],
    ];
    for gamma in [1.500001, 1.6, 2.5] {
        let e = Exact::new(NdfKind::StudentT, ax, ay, Some(gamma)).unwrap();
        for w in dirs {
            let wu = Vec3::from(w).normalize();
            let wu = if wu.z < 0.0 { -wu } else { wu };
            let edge = e.invert(w, e.sample(w, [1.0 - 1e-16, 0.5]).wm)[0];
            for u in [
                [1e-4, 0.3],
                [5e-4, 0.9],
                [0.02, 0.6],
                [0.3, 0.1],
                [0.7736, 0.4048],
                [0.97, 0.999],
            ] {
                let s = e.sample(w, u);
                let wm = Vec3::from(s.wm);
                assert!(
                    (wm.length() - 1.0).abs() < 1e-15 && wm.z > 0.0 && wm.dot(wu) > 0.0,
                    "γ = {gamma} w = {w:?} u = {u:?}: {wm:?}"
                );
                assert!(
                    s.pdf.is_finite() && s.pdf > 0.0,
                    "γ = {gamma}: pdf {}",
                    s.pdf
                );
                let back = e.invert(w, s.wm);
                assert!((back[1] - u[1]).abs() < 1e-12, "{back:?} vs {u:?}");
                if u[0] < edge {
                    assert!(
                        (back[0] - u[0]).abs() < 1e-12,
                        "γ = {gamma} w = {w:?}: {back:?} vs {u:?}"
                    );
                } else {
                    // Beyond the slopes f64 holds: the normal at R_MAX.
                    assert!(
                        gamma < 1.6 && back[0] <= u[0],
                        "γ = {gamma}: {back:?} vs {u:?}"
                    );
                    let r = (wm.x / ax).hypot(wm.y / ay) / wm.z;
                    assert!((r / R_MAX - 1.0).abs() < 1e-12, "{r:e}");
                }
            }
        }
    }
}

/// A transmission at η = 1 + 2⁻⁵² between nearly opposite grazing directions, through an
/// extremely anisotropic surface (αx/αy = 6e11): f and the pdf finite and ≥ 0 (NaN came out:
/// η' wi + wo nearly vanishes, and formed plainly it kept only the rounding of η' wi, so the
/// half vector's direction was arbitrary and the Jacobian's denominator wi·wm + wo·wm/η'
/// cancelled to 0; 0/0 where D underflowed). For every NDF, f32 and f64.
#[test]
fn transmission_at_eta_near_one_stays_finite() {
    use microsurface::bsdf::RoughDielectric;
    use microsurface::{Beckmann, Real, K0};
    fn check<F: Real, D: MicrofacetDistribution<F>>(
        label: &str,
        d: D,
        eta: F,
        wo: [F; 3],
        wi: [F; 3],
    ) {
        let b = RoughDielectric::new(d, eta).unwrap();
        // Both ways: the other side's η' too.
        for (wo, wi) in [(wo, wi), (wi, wo)] {
            let f = b.eval(wo, wi).map(|x| x.to_f64());
            let p = b.pdf(wo, wi).to_f64();
            let ok = |x: f64| x.is_finite() && x >= 0.0;
            assert!(
                f.iter().all(|&x| ok(x)) && ok(p),
                "{label}: f {f:?} pdf {p}"
            );
        }
    }
    let (ax, ay) = (1.0000000000000002e-6, 5.818873172482334e5);
    let wo = [
        0.48044038804613187,
        0.8770273847116077,
        5.2286799907616075e-80,
    ];
    let wi = [
        -0.4804403880461318,
        -0.8770273847116076,
        -7.469542843945155e-80,
    ];
    // The fuzzer's reproducer (K0), then GGX and Beckmann, both η just above and below 1,
    // directions exactly opposite and at the f64 horizon floor.
    let cases64 = [
        (wo, wi),
        (wo, wo.map(|x| -x)),
        (
            [0.6, 0.8, 1.0000000000000001e-150],
            [-0.6, -0.8, -1.0000000000000002e-150],
        ),
        ([0.6, 0.0, 0.8], [-0.6, 0.0, -0.8]),
    ];
    for eta in [1.0000000000000002, 0.9999999999999999] {
        for (wo, wi) in cases64 {
            for (ax, ay) in [(ax, ay), (ay, ax), (0.3, 0.3)] {
                let l = format!("η = {eta} α = ({ax}, {ay}) {wo:?} {wi:?}");
                let k0 = Microfacet::<f64, K0>::with_shape(ax, ay, None).unwrap();
                check(&format!("K0 {l}"), k0, eta, wo, wi);
                check(
                    &format!("GGX {l}"),
                    Microfacet::<f64, Ggx>::new(ax, ay).unwrap(),
                    eta,
                    wo,
                    wi,
                );
                let b = Microfacet::<f64, Beckmann>::new(ax, ay).unwrap();
                check(&format!("Beckmann {l}"), b, eta, wo, wi);
            }
        }
    }
    // f32: η = 1 + 2⁻²³, the directions at its horizon floor (1e-18).
    let to32 = |v: [f64; 3]| v.map(|x| x as f32);
    let cases32 = [
        (to32(wo), [-0.48044038f32, -0.8770274, -2e-18]),
        ([0.6f32, 0.8, 1e-18], [-0.6f32, -0.8, -1e-18]),
        ([0.6f32, 0.0, 0.8], [-0.6f32, 0.0, -0.8]),
    ];
    for eta in [1.0000001f32, 0.99999994] {
        for (wo, wi) in cases32 {
            let wo = if wo[2] == 0.0 {
                [wo[0], wo[1], 2e-18]
            } else {
                wo
            };
            for (ax, ay) in [(2e-6f32, 5.8e5f32), (5.8e5, 2e-6), (0.3, 0.3)] {
                let l = format!("f32 η = {eta} α = ({ax}, {ay}) {wo:?} {wi:?}");
                let k0 = Microfacet::<f32, K0>::with_shape(ax, ay, None).unwrap();
                check(&format!("K0 {l}"), k0, eta, wo, wi);
                check(
                    &format!("GGX {l}"),
                    Microfacet::<f32, Ggx>::new(ax, ay).unwrap(),
                    eta,
                    wo,
                    wi,
                );
                let b = Microfacet::<f32, Beckmann>::new(ax, ay).unwrap();
                check(&format!("Beckmann {l}"), b, eta, wo, wi);
            }
        }
    }
}

/// The walk BSDF from a direction of length 1e300 (in contract: any finite nonzero length):
/// the walk stepped heights for a unit vector with the raw one and never ended (hours); now
/// the same sample, f and pdf as from the unit direction, the same pdf, and a finite eval.
#[test]
fn walk_bsdf_at_any_length() {
    use microsurface::bsdf::fresnel::One;
    use microsurface::scattering::{MirrorFacets, MultipleScattering};
    let g = Microfacet::<f64, Ggx>::new(0.3, 0.3).unwrap();
    let ms = MultipleScattering::new(g, MirrorFacets(One::<1>));
    let (wo, wi) = ([0.0, 0.6, 0.8], [0.6, 0.0, 0.8]);
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
    let want = ms.sample(wo, 0.4, [0.3, 0.6]).unwrap();
    for s in [1e300, 1e-300] {
        let wo_s = wo.map(|x| x * s);
        let got = ms.sample(wo_s, 0.4, [0.3, 0.6]).unwrap();
        assert!(
            close(got.pdf, want.pdf) && close(got.f[0], want.f[0]),
            "{got:?} vs {want:?}"
        );
        assert!((0..3).all(|k| (got.wi[k] - want.wi[k]).abs() < 1e-12));
        let wi_s = wi.map(|x| x * s);
        // (eval is a stochastic estimate seeded by the directions' bits: finite and positive.)
        let f = ms.eval(wo_s, wi_s)[0];
        assert!(f.is_finite() && f > 0.0, "{f}");
        assert!(close(ms.pdf(wo_s, wi_s), ms.pdf(wo, wi)));
    }
}

/// Fresnel where its cosines cancel: η = 1 is no interface at every cos θ (the dielectric
/// gave R = 1e-3 at cos θ = 1e-8 and 1 at 1e-9, the complex index n = 1 gave F = 1 at 1e-9:
/// 1 − sin²θ/η² lost cos θt), and the two forms agree near grazing at η ≈ 1 (5.6e-11 apart
/// at η = 1 + 1e-9, cos θ = 1.4e-6).
#[test]
fn fresnel_at_grazing_near_index_one() {
    use microsurface::bsdf::fresnel::dielectric;
    for c in [1e-300, 1e-20, 1e-9, 1e-8, 1e-3, 0.5, 1.0] {
        assert_eq!(dielectric(c, 1.0), 0.0, "{c}");
        assert_eq!(dielectric(-c, 1.0), 0.0, "{c}");
        assert_eq!(conductor(c, 1.0, 0.0), 0.0, "{c}");
    }
    for (c, eta) in [
        (1.4102246917088355e-6, 1.000000001),
        (1.1408136438209473e-6, 1.000000001),
    ] {
        let (d, k): (f64, f64) = (dielectric(c, eta), conductor(c, eta, 0.0));
        assert!((d - k).abs() < 1e-14 && d > 0.8 && d < 1.0, "{d} {k}");
    }
    let (d, k): (f32, f32) = (
        dielectric(0.99999857, 2.3386985e-3),
        conductor(0.99999857, 2.3386985e-3, 0.0),
    );
    assert!(
        (d - k).abs() < 1e-6,
        "f32: {d} vs {k} (3.6e-5 apart before)"
    );
}

/// Fresnel at the ends of the index range: a conductor below |n| = 1e-75 (f32: 1e-9) is a
/// mirror (NaN came out: n² underflowed in 1/n²), at n = f64::MAX seen at grazing 1
/// (NaN: 1/s of a subnormal s overflowed in the ratios' scaling), never above 1 (1 + 4e-16
/// at n = 1e-9 (1 + i)); a dielectric seen from inside at a subnormal η (1/η = ∞) reflects
/// everything (NaN).
#[test]
fn fresnel_at_extreme_indices() {
    use microsurface::bsdf::fresnel::dielectric;
    for c in [0.0, 0.3, 1.0] {
        let f: f64 = conductor(c, 1e-300, 0.0);
        assert_eq!(f, 1.0, "{c}");
        assert_eq!(conductor(c, 1e-300f64, 1e-300), 1.0);
        assert_eq!(conductor(c as f32, 1e-30f32, 0.0), 1.0);
        let d: f64 = dielectric(-c.max(1e-300), 5e-324);
        assert_eq!(d, 1.0, "{c}");
    }
    let f: f64 = conductor(0.0, f64::MAX, 9.409114874380895e-3);
    assert_eq!(f, 1.0);
    let f: f64 = conductor(0.7912130912580625, 1e-9, 1e-9);
    assert!((0.999..=1.0).contains(&f), "{f}");
}

/// A conductor's channel with F = 0 reflects nothing, also at a singular NDF's pole where
/// D = +∞ (0 · ∞ gave NaN: K0 in f32 with Schlick F0 = 0, wo = wi = −z).
#[test]
fn zero_fresnel_channel_at_the_pole() {
    use microsurface::bsdf::fresnel::Schlick;
    use microsurface::bsdf::RoughConductor;
    let m = AnyMicrofacet::<f32>::new(NdfKind::K0, 1.1976708e-5, 2.4527725e5, None).unwrap();
    let b = RoughConductor::new(
        m,
        Schlick {
            f0: [0.0f32, 0.04, 0.5],
        },
    );
    let f = b.eval([0.0, 0.0, -1.0], [0.0, 0.0, -1.0]);
    assert!(f[0] == 0.0 && f[1] == f32::INFINITY, "{f:?}");
}

/// The refraction at a tiny relative index is a unit vector (|wt| = 0.99989 at η = 1e-6:
/// 1 − cos²θi lost sin θi near normal incidence; then 1 + 2e-10 while wi's part along the
/// interface kept a component along n at the rounding of 1).
#[test]
fn refraction_at_a_tiny_index_is_unit() {
    use microsurface::bsdf::frame::{normalize, refract};
    let n: [f64; 3] = normalize([1e-7, -3e-7, 1.0]);
    for wi in [
        [0.0, 0.0, 1.0],
        [2e-7, 1e-7, 1.0],
        normalize([3e-7, 0.0, 1.0]),
    ] {
        for eta in [1e-6, 1e-3, 1e6] {
            if let Some((wt, _)) = refract(normalize(wi), n, eta) {
                let l = (wt[0] * wt[0] + wt[1] * wt[1] + wt[2] * wt[2]).sqrt();
                assert!((l - 1.0).abs() < 1e-14, "η = {eta}: |wt| = {l}");
            }
        }
    }
    let b = microsurface::bsdf::RoughDielectric::new(
        AnyMicrofacet::<f64>::new(
            NdfKind::DoubleGgx,
            1.0000000000000004,
            1.0000000000000004,
            None,
        )
        .unwrap(),
        1e-6,
    )
    .unwrap();
    if let Some(s) = b.sample([0.0, 0.0, 1.0], 0.999999999, [0.18398373624911346, 0.0]) {
        let l = (s.wi[0] * s.wi[0] + s.wi[1] * s.wi[1] + s.wi[2] * s.wi[2]).sqrt();
        assert!((l - 1.0).abs() < 1e-14, "{s:?}");
    }
}

/// The weight f|cos θi|/pdf of a sample, per channel.
fn weight<F: microsurface::Real>(s: &microsurface::bsdf::BsdfSample<F, [F; 3]>) -> f64 {
    let c = s.wi[2].to_f64().abs();
    s.f.iter()
        .map(|x| x.to_f64() * c / s.pdf.to_f64())
        .fold(0.0, f64::max)
}

/// A sample carries a weight G2/G1 ≤ 1 (F = 1) to rounding: samples whose pdf or D had
/// passed through subnormal products are rejected (weights of 1.0018 in f32 at a pdf of
/// 1.5e-44, 1.0017 in f64 at a pdf of 4e-301 from D = 1e-321, 1 + 9e-7 where η ≈ 1's
/// Jacobian 1/s² lifted a subnormal D back, 1 + 4e-12 at a pdf of 2.3e-293).
#[test]
fn samples_from_subnormals_are_rejected() {
    use microsurface::bsdf::{Masking, RoughDielectric, Transport};
    let ok = |w: f64| w <= 1.0 + 1e-9;
    let m32 = AnyMicrofacet::<f32>::new(NdfKind::Beckmann, 4.8287145e-3, 1.0, None).unwrap();
    let b32 = RoughDielectric::new(m32, 966.9001f32)
        .unwrap()
        .with_masking(Masking::Separable)
        .with_transport(Transport::Importance);
    if let Some(s) = b32.sample(
        [-2.2544164e-5f32, -6.118743e-5, 1.0],
        0.99999994,
        [0.13955802, 1e-45],
    ) {
        assert!(ok(weight(&s)), "{s:?}: weight {}", weight(&s));
    }
    // (NDF, αx, αy, η, masking, transport, wo, uc, u.)
    type Case = (
        NdfKind,
        f64,
        f64,
        f64,
        Masking,
        Transport,
        [f64; 3],
        f64,
        [f64; 2],
    );
    let cases: [Case; 3] = [
        (
            NdfKind::Beckmann,
            2.5989706571101174e3,
            2.5989706571101174e3,
            1e-6,
            Masking::Correlated,
            Transport::Importance,
            [-0.6871926064711165, 0.7264752725395637, 1e-20],
            0.92435079341754,
            [0.8753781679351919, 1e-310],
        ),
        (
            NdfKind::Beckmann,
            1.2117124342391022e-2,
            1.2117124342391022e-2,
            0.9999999999999999,
            Masking::CorrelatedBeta,
            Transport::Radiance,
            [-0.0, -0.0, 1.0],
            0.5420285100722243,
            [5e-324, 0.17704751170266742],
        ),
        (
            NdfKind::Beckmann,
            8.26128440092048e4,
            1e-6,
            2.9091381326430453e-3,
            Masking::Correlated,
            Transport::Radiance,
            [-0.42991001496221365, -0.9028717400800566, 1e-20],
            0.9269380632219982,
            [0.848804851692736, 1e-310],
        ),
    ];
    for (kind, ax, ay, eta, mk, tr, wo, uc, u) in cases {
        let m = AnyMicrofacet::<f64>::new(kind, ax, ay, None).unwrap();
        let b = RoughDielectric::new(m, eta)
            .unwrap()
            .with_masking(mk)
            .with_transport(tr);
        if let Some(s) = b.sample(wo, uc, u) {
            let bound = if s.wi[2] * wo[2] < 0.0 && tr == Transport::Radiance {
                1.0 / (s.eta * s.eta)
            } else {
                1.0
            };
            assert!(
                weight(&s) <= bound * (1.0 + 1e-9),
                "{s:?}: weight {}",
                weight(&s)
            );
        }
    }
}

/// An f32 sample's f is finite: the generalised exponential runs in f64, and its D rounded
/// to f32 overflowed where f did not (f = ∞ or NaN with a finite pdf); such a sample is
/// rejected.
#[test]
fn f32_sample_f_stays_finite() {
    use microsurface::bsdf::{Masking, RoughDielectric, Transport};
    // (αx, αy, γ, η, masking, transport, wo, uc, u.)
    type Case = (
        f32,
        f32,
        f64,
        f32,
        Masking,
        Transport,
        [f32; 3],
        f32,
        [f32; 2],
    );
    let cases: [Case; 3] = [
        (
            6.972285e4,
            3.0346302,
            0.1,
            0.99999994,
            Masking::CorrelatedBeta,
            Transport::Radiance,
            [0.82625395, 0.5445855, -0.14398293],
            0.25,
            [0.25, 0.47776532],
        ),
        (
            1e6,
            1e6,
            0.1,
            1.0001,
            Masking::Separable,
            Transport::Importance,
            [0.0152829895, -0.90468943, 0.42579746],
            0.99999994,
            [0.71219546, 0.567456],
        ),
        (
            4.3215936e-6,
            1e3,
            0.1,
            0.37164146,
            Masking::Correlated,
            Transport::Radiance,
            [-0.20501842, -0.6257599, -0.7525902],
            0.7553412,
            [0.99999994, 0.5284126],
        ),
    ];
    for (ax, ay, g, eta, mk, tr, wo, uc, u) in cases {
        let m = AnyMicrofacet::<f32>::new(NdfKind::GenExponential, ax, ay, Some(g)).unwrap();
        let b = RoughDielectric::new(m, eta)
            .unwrap()
            .with_masking(mk)
            .with_transport(tr);
        if let Some(s) = b.sample(wo, uc, u) {
            assert!(
                s.f.iter().all(|x| x.is_finite()) && weight(&s).is_finite(),
                "{s:?}"
            );
        }
    }
}

/// The rough conductor is reciprocal to the bit, f(wo, wi) = f(wi, wo): F at the mean of
/// |wo·wm| and |wi·wm| and G2's Λo + Λi added first (a dielectric Fresnel term at η = 1,
/// whose F is all rounding, gave 1.6e7 against 9.0e6 at grazing backscatter).
#[test]
fn conductor_reciprocity_to_the_bit() {
    use microsurface::bsdf::fresnel::{Dielectric, Schlick};
    use microsurface::bsdf::{Masking, RoughConductor};
    let m = AnyMicrofacet::<f64>::new(NdfKind::Erfc, 1.0000000000000004, 0.9999999999999998, None)
        .unwrap();
    let pairs = [
        (
            [
                0.43580301219516976,
                0.9000420737730082,
                1.0000000000000004e-8,
            ],
            [-0.43580301219516976, -0.9000420737730082, 1.4e-8],
        ),
        (
            [0.6401913449549881, -0.7682154918020877, 1e-20],
            [0.885536096845651, -0.40027137053920464, 0.23581486617691527],
        ),
        ([0.6, 0.0, 0.8], [-0.3, 0.2, 0.93]),
    ];
    for mk in [
        Masking::Correlated,
        Masking::Separable,
        Masking::CorrelatedBeta,
    ] {
        let a = RoughConductor::new(m.clone(), Dielectric { eta: 1.0 }).with_masking(mk);
        let b = RoughConductor::new(
            m.clone(),
            Schlick {
                f0: [0.04, 0.5, 0.9],
            },
        )
        .with_masking(mk);
        for (wo, wi) in pairs {
            let (x, y): ([f64; 3], [f64; 3]) = (a.eval(wo, wi), a.eval(wi, wo));
            assert_eq!(x, y, "{mk:?} {wo:?} {wi:?}");
            assert_eq!(b.eval(wo, wi), b.eval(wi, wo), "{mk:?} {wo:?} {wi:?}");
        }
    }
}

/// An f32 index of the shipped dielectric tables finds them (1.33f32 is 1.33 + 3e-8, which
/// missed them: the tables were computed, a second, for every f32 compensated dielectric).
#[test]
fn shipped_dielectric_tables_at_f32_indices() {
    use microsurface::scattering::DielectricTables;
    for eta in [1.33f32, 1.5, 2.42, 1.0 / 1.5] {
        assert!(
            DielectricTables::shipped(NdfKind::Ggx, None, 0.5, eta as f64).is_some(),
            "{eta}"
        );
    }
}

/// Turquin's compensated conductor scales its single-scattering sample's own f (it took
/// eval's at the sampled wi, whose recomputed half vector rounded onto Erfc's pole: f = ∞
/// with a finite pdf).
#[test]
fn turquin_sample_keeps_its_f() {
    use microsurface::bsdf::fresnel::Schlick;
    let m = AnyMicrofacet::<f64>::new(
        NdfKind::Erfc,
        0.05699642902645688,
        0.05699642902645688,
        None,
    )
    .unwrap();
    let b = CompensatedConductor::new(
        m,
        Schlick {
            f0: [0.34196597129697504, 1.0, 1e-9],
        },
        Scheme::Turquin,
    );
    for (wo, uc, u) in [
        (
            [
                0.9883405047845698,
                0.15225979969178233,
                1.3778863906237667e-34,
            ],
            0.25,
            [0.5738731689743743, 1e-300],
        ),
        (
            [0.9407102640122038, 0.33921114247926737, 1e-40],
            0.49333297347627114,
            [0.9683256126940536, 0.0],
        ),
        (
            [-0.42869177956923926, 0.44486510656591344, 0.786332242178748],
            0.5496390368701861,
            [0.7723042000168664, 1e-310],
        ),
    ] {
        if let Some(s) = b.sample(wo, uc, u) {
            assert!(
                s.f.iter().all(|x| x.is_finite()) && s.pdf.is_finite(),
                "{s:?}"
            );
        }
    }
}

/// The random walk's BSDF in f32 answers 0 on f32's horizon, as the single-scattering ones
/// (f = ∞ at wi.z = 1e-40: its 1/|cos θi| overflowed f32).
#[test]
fn walk_bsdf_f32_horizon() {
    use microsurface::bsdf::fresnel;
    use microsurface::scattering::{MirrorFacets, MultipleScattering};
    let m = AnyMicrofacet::<f64>::new(NdfKind::StudentT, 30.0, 30.0, Some(1.6)).unwrap();
    let gold = fresnel::Conductor {
        eta: [1000.0, 0.2, 1.0],
        k: [0.10827366413957763, 3.9, 0.0],
    };
    let b = MultipleScattering::new(m, MirrorFacets(gold));
    let f: [f32; 3] = b.eval(
        [0.14900278f32, 0.98883677, -1e-45],
        [-0.73614454, -0.67682433, -1e-40],
    );
    assert!(f.iter().all(|x| x.is_finite() && *x >= 0.0), "{f:?}");
}

/// The exact visible density where D overflows and the density does not (the fuzz suite's
/// one failure at scale 14): Student-T at γ = 1.5 + 1e-9, α = 7e4 grows like
/// D ~ u^{2γ−4} toward the horizon, past f64::MAX at cos θm = 1.4e-305 while
/// G1 D (w·m)/cos θo is about 1e296. Checked against the same density at cos θm = 1.4e-300
/// (D finite there), which it must exceed by the factor 1e5^{4−2γ} (w·m moves by 1e-300).
#[test]
fn exact_visible_pdf_where_d_overflows() {
    let g = 1.5 + 1e-9;
    let e = Exact::new(NdfKind::StudentT, 7e4, 7e4, Some(g)).unwrap();
    let w = [0.6, 0.0, 0.8];
    let far = e.pdf(w, [1.0, 0.0, 1.4e-305]);
    let near = e.pdf(w, [1.0, 0.0, 1.4e-300]);
    assert!(
        far.is_finite() && near.is_finite() && near > 0.0,
        "{far} {near}"
    );
    let want = 1e5f64.powf(4.0 - 2.0 * g);
    assert!(
        (far / near / want - 1.0).abs() < 1e-6,
        "{far} {near} {want}"
    );
}

/// Issue 47, item 3: a relative index is checked where it enters (η = 0 made every value NaN,
/// η < 0 gave plausible-looking transmission): RoughDielectric, CompensatedDielectric and the
/// walk's DielectricFacets refuse NaN, ±∞, 0 and negative η with `ParamError::Eta`.
#[test]
fn bad_indices_are_refused_where_they_enter() {
    use microsurface::bsdf::RoughDielectric;
    use microsurface::scattering::DielectricFacets;
    use microsurface::ParamError;
    let d = Microfacet::<f64, Ggx>::new(0.3, 0.3).unwrap();
    for eta in [0.0, -1.0, -0.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let want = |e: ParamError| matches!(e, ParamError::Eta(x) if x.to_bits() == eta.to_bits());
        assert!(
            RoughDielectric::new(d.clone(), eta).is_err_and(want),
            "{eta}"
        );
        assert!(
            CompensatedDielectric::new(d.clone(), eta, Scheme::KullaConty).is_err_and(want),
            "{eta}"
        );
        assert!(DielectricFacets::new(eta).is_err_and(want), "{eta}");
    }
    for eta in [1e-300, 0.5, 1.0, 1.5, 1e300] {
        assert!(RoughDielectric::new(d.clone(), eta).is_ok(), "{eta}");
        assert!(
            DielectricFacets::new(eta).is_ok_and(|f| f.index() == eta),
            "{eta}"
        );
    }
    let e = RoughDielectric::new(d, 0.0).unwrap_err().to_string();
    assert!(e.starts_with("eta") && e.len() < 100, "{e}");
}

/// Issue 47, item 3: the walk's interface at η = 1 is no interface, a delta lobe straight
/// through (it returned f = 2.8e32 with pdf 2.5e32): eval and pdf 0, the sample −wo with
/// weight f|cos θi|/pdf = 1, as RoughDielectric's at η = 1.
#[test]
fn walk_at_index_one_is_a_delta() {
    use microsurface::bsdf::RoughDielectric;
    use microsurface::scattering::{DielectricFacets, MultipleScattering};
    let d = Microfacet::<f64, Ggx>::new(0.5, 0.5).unwrap();
    let walk = MultipleScattering::<_, _, 1>::new(d.clone(), DielectricFacets::new(1.0).unwrap());
    let single = RoughDielectric::new(d, 1.0).unwrap();
    let wo = [0.36, 0.0, 0.8];
    let s = walk.sample(wo, 0.4, [0.3, 0.7]).expect("a sample");
    let n = (0.36f64 * 0.36 + 0.64).sqrt();
    for (a, b) in s.wi.iter().zip([-0.36 / n, 0.0, -0.8 / n]) {
        assert!((a - b).abs() < 1e-15, "{:?}", s.wi);
    }
    assert!(s.specular);
    assert!((s.f[0] * s.wi[2].abs() / s.pdf - 1.0).abs() < 1e-15);
    let t = single.sample(wo, 0.4, [0.3, 0.7]).expect("a sample");
    assert!(t.specular && (t.f[0] * t.wi[2].abs() / t.pdf - 1.0).abs() < 1e-12);
    assert_eq!(walk.eval(wo, s.wi), [0.0]);
    assert_eq!(walk.pdf(wo, s.wi), 0.0);
}

/// Issue 47, item 3: the documented minimum α is accepted in f32, where 1e-6 has no exact
/// value (1e-6f32 is below 1e-6 as an f64), by every door constructor; just below it is not.
#[test]
fn f32_alpha_at_the_documented_minimum() {
    for kind in NdfKind::ALL {
        let shape = some_shape(kind);
        assert!(
            AnyMicrofacet::<f32>::new(kind, 1e-6, 1e-6, shape).is_ok(),
            "{kind}"
        );
        assert!(
            AnyMicrofacet::<f32>::new(kind, 1e6, 1e6, shape).is_ok(),
            "{kind}"
        );
    }
    assert!(AnyMicrofacet::<f32>::parse("ggx", 1e-6, 1e-6).is_ok());
    assert!(AnyMicrofacet::<f32>::new(NdfKind::Ggx, 0.99e-6, 0.99e-6, None).is_err());
    assert!(AnyMicrofacet::<f64>::new(NdfKind::Ggx, 0.99e-6, 0.99e-6, None).is_err());
}

/// Issue 47, item 3: u = 1 (a generator that rounds returns it) is read as the largest value
/// below 1 by the door's samplers, as pbrt's OneMinusEpsilon: the normal is not on the
/// horizon, and the dielectric's sample at u = (1, 1) exists (it was None).
#[test]
fn u_of_one_is_below_one() {
    use microsurface::bsdf::RoughDielectric;
    for kind in NdfKind::ALL {
        let m = AnyMicrofacet::<f32>::new(kind, 0.3, 0.3, some_shape(kind)).unwrap();
        let wo = [0.3f32, 0.2, 0.932];
        for u in [[1.0f32, 1.0], [0.5, 1.0], [1.0, 0.5]] {
            let s = m.sample(wo, u);
            assert!(
                s.wm[2] > 0.0 && s.pdf > 0.0 && s.pdf.is_finite(),
                "{kind} {u:?}: {s:?}"
            );
            let c = m.sample_dcos(u);
            assert!(c.wm[2] > 0.0 && c.pdf.is_finite(), "{kind} {u:?}: {c:?}");
        }
        let glass = RoughDielectric::new(m, 1.5f32).unwrap();
        assert!(glass.sample(wo, 0.5, [1.0, 1.0]).is_some(), "{kind}");
    }
}

/// Issue 47, item 4: a misspelt NDF name gets a suggestion; a name far from every one does
/// not.
#[test]
fn misspelt_names_get_a_suggestion() {
    for (typo, want) in [
        ("beckman", NdfKind::Beckmann),
        ("GGX ", NdfKind::Ggx),
        ("studnet_t", NdfKind::StudentT),
        ("bessel-j", NdfKind::BesselK),
        ("exponental", NdfKind::Exponential),
    ] {
        match typo.parse::<NdfKind>() {
            Ok(k) => assert_eq!(k, want, "{typo}"),
            Err(e) => {
                assert_eq!(e.suggestion(), Some(want), "{typo}");
                assert!(
                    e.to_string()
                        .contains(&format!("did you mean '{}'", want.name())),
                    "{e}"
                );
            }
        }
    }
    let e = "foo".parse::<NdfKind>().unwrap_err();
    assert_eq!(e.suggestion(), None);
    assert!(!e.to_string().contains("did you mean"));
    let e = "x".repeat(100_000).parse::<NdfKind>().unwrap_err();
    assert_eq!(e.suggestion(), None);
    assert!(e.to_string().len() < 400);
}

/// A shape in range for each kind that has one (γ = 2.5, a = 0.7).
fn some_shape(kind: NdfKind) -> Option<f64> {
    kind.shape_name().map(|n| if n == "a" { 0.7 } else { 2.5 })
}

/// Issue 47, item 3: a normal with no direction gives the documented all-NaN frame (not a
/// plausible one), in both precisions.
#[test]
fn frame_of_no_normal_is_nan() {
    for n in [
        [0.0, 0.0, 0.0],
        [f64::NAN, 0.0, 1.0],
        [f64::INFINITY, 0.0, 0.0],
    ] {
        let f = Frame::from_normal(n);
        assert!(
            f.s.iter().chain(&f.t).chain(&f.n).all(|x| x.is_nan()),
            "{n:?}: {f:?}"
        );
        let f32_ = Frame::from_normal(n.map(|x| x as f32));
        assert!(f32_.n.iter().all(|x| x.is_nan()), "{n:?}");
    }
}

/// Issue 47, item 7 (the outside fuzzer): GGX's G2 where the product of the two G1
/// underflows (α = 18.14, u_o = 1.354e-231, u_i = 1.650e-106: 0 for 1.49e-232), against
/// 1/(1 + Λo + Λi) from the exact Λ, in f64, and the f32 form at its own tiny product.
#[test]
fn ggx_g2_where_the_product_underflows() {
    use microsurface::fast::ggx;
    use microsurface::Ndf;
    let exact = microsurface::Ggx::new(18.14).unwrap();
    for (uo, ui) in [
        (1.354e-231, 1.650e-106),
        (1e-200, 1e-200),
        (1e-300, 0.5),
        (1e-170, 1e-160),
    ] {
        let want = 1.0 / (1.0 + exact.lambda(uo) + exact.lambda(ui));
        let got = ggx::g2(uo, ui, 18.14);
        assert!(
            (got - want).abs() <= 1e-14 * want,
            "{uo:e} {ui:e}: {got:e} vs {want:e}"
        );
        assert_eq!(ggx::g2(ui, uo, 18.14), got);
    }
    let (uo, ui) = (1e-25f32, 1e-20f32);
    let want = 1.0 / (1.0 + exact.lambda(uo as f64) + exact.lambda(ui as f64));
    let got = ggx::g2(uo, ui, 18.14f32) as f64;
    assert!((got - want).abs() <= 1e-6 * want, "{got:e} vs {want:e}");
    assert_eq!(ggx::g2(0.0, 0.5, 1.0), 0.0);
    assert_eq!(ggx::g2(0.0f32, 0.0, 1.0), 0.0);
}

/// Issue 47, item 7: an f32 direction of subnormal components (−9.09e-42, 8.34e-41,
/// 1.64e-41) is the unit direction it points along: its visible pdf was NaN (1/|w|
/// overflowed f32), every door NDF; and `sample_bounded` gave NaN normals.
#[test]
fn f32_subnormal_directions_sample_as_their_unit() {
    let tiny = [-9.09e-42f32, 8.34e-41, 1.64e-41];
    let n = {
        let t = tiny.map(f64::from);
        let l = (t[0] * t[0] + t[1] * t[1] + t[2] * t[2]).sqrt();
        t.map(|x| (x / l) as f32)
    };
    for kind in NdfKind::ALL {
        let m = AnyMicrofacet::<f32>::new(kind, 2.5244, 2.5244, some_shape(kind)).unwrap();
        // (The fuzzer's u: a normal at the edge of the visible ones, w·m ≈ 0, where the pdf
        // is 0 or tiny by rounding; finite is what it must be.)
        let a = m.sample(tiny, [0.0, 0.80414]);
        assert!(a.pdf.is_finite() && a.pdf >= 0.0, "{kind}: {a:?}");
        let (a, b) = (m.sample(tiny, [0.4, 0.80414]), m.sample(n, [0.4, 0.80414]));
        assert!(
            b.pdf > 0.0 && (a.pdf - b.pdf).abs() <= 1e-4 * b.pdf,
            "{kind}: {a:?} vs {b:?}"
        );
    }
    let g = Microfacet::<f32, Ggx>::new(37.69, 1e6).unwrap();
    let s = g.sample_bounded([4.26e-41, 1.17e-41, 9.88e-41], [0.0, 0.37209]);
    assert!(s.wm.iter().all(|x| x.is_finite()), "{s:?}");
}

/// Issue 47, item 7: the fitted Student-T D far in its tail, where the α = 1 profile
/// underflows but D is a normal float (γ = 4.93999, α = 1e3, u = 6.46e-41: 0 for 5.90e-211),
/// against the exact NDF.
#[test]
fn fitted_d_in_the_underflowing_tail() {
    use microsurface::fast::fitted::FittedShape;
    use microsurface::Ndf;
    let unit = microsurface::AnyNdf::new(NdfKind::StudentT, 1.0, Some(4.93999)).unwrap();
    let fit = FittedShape::new(&unit).unwrap();
    for (alpha, u) in [(1e3, 6.46e-41), (1e3, 1e-50), (10.0, 1e-45), (1e-3, 1e-30)] {
        let want = microsurface::AnyNdf::new(NdfKind::StudentT, alpha, Some(4.93999))
            .unwrap()
            .d(u);
        let got: f64 = fit.d(u, alpha);
        assert!(
            (got - want).abs() <= 1e-7 * want,
            "α {alpha} u {u:e}: {got:e} vs {want:e}"
        );
    }
}

/// Issue 47, item 4: one convention for the albedo below the surface: E(μ < 0) = E(|μ|)
/// (the BSDFs are two-sided) from the table (it was E(0): 0.999995 for −0.5), the quadrature
/// (it was 0) and the direction form alike.
#[test]
fn albedo_below_the_surface_is_the_mirror_image() {
    use microsurface::scattering::{single_scattering_albedo, AlbedoTable};
    let d = AnyMicrofacet::<f64>::new(NdfKind::Ggx, 0.5, 0.5, None).unwrap();
    let t = AlbedoTable::new(&d);
    for mu in [0.1f64, 0.5, 0.9] {
        let s = (1.0 - mu * mu).sqrt();
        let (up, down) = ([s, 0.0, mu], [-s, 0.0, -mu]);
        assert_eq!(t.e(-mu), t.e(mu));
        assert_eq!(t.e_dir(down), t.e_dir(up));
        let (a, b) = (
            single_scattering_albedo(&d, up),
            single_scattering_albedo(&d, down),
        );
        assert_eq!(a, b);
        assert!((t.e(mu) - a).abs() < 1e-3, "{mu}: {} vs {a}", t.e(mu));
    }
}

/// Issue 47, item 7: the door's D·cos pdf where D overflows at a subnormal wm.z but D·cos is
/// finite (Student-T α = 1.524e-3, γ = 1.5016, wm = (0.2107, −0.9775, 9.672e-319): +∞ for
/// 1.63e-5), through `Microfacet` and `AnyMicrofacet` alike, equal to the exact path's.
#[test]
fn dcos_pdf_where_d_overflows() {
    let wm = [0.2107, -0.9775, 9.672e-319];
    let exact = Exact::new(NdfKind::StudentT, 1.524e-3, 1.524e-3, Some(1.5016)).unwrap();
    let want = exact.pdf_dcos(wm);
    assert!(want.is_finite() && want > 0.0, "{want:e}");
    let door =
        AnyMicrofacet::<f64>::new(NdfKind::StudentT, 1.524e-3, 1.524e-3, Some(1.5016)).unwrap();
    assert_eq!(door.pdf_dcos(wm), want);
    let direct =
        Microfacet::<f64, microsurface::StudentT>::with_shape(1.524e-3, 1.524e-3, Some(1.5016))
            .unwrap();
    assert_eq!(direct.pdf_dcos(wm), want);
    assert_eq!(door.pdf_dcos([0.6, 0.0, 0.0]), 0.0);
    assert!(door.pdf_dcos([0.6, 0.0, f64::NAN]).is_nan());
}

/// Issue 47, item 7: the f32 door's G1 near the normal at large α (Double GGX α = 254.36 at
/// w ≈ (0.024, 0.0295, 0.99928) was 6e-6 off against the documented 4e-6; Exponential and GTR
/// likewise, 2 % at α = 1e4): Λ now from the vector, as D. Within 4e-6 of the exact path for
/// every NDF over directions up to 6° from the normal, α = 100 and 254.36.
#[test]
fn f32_g1_near_the_normal_at_large_alpha() {
    for kind in NdfKind::ALL {
        let shape = some_shape(kind);
        for a in [100.0f32, 254.36] {
            let m = AnyMicrofacet::<f32>::new(kind, a, a, shape).unwrap();
            let e = Exact::new(kind, a as f64, a as f64, shape).unwrap();
            let mut worst = 0.0f64;
            for k in 0..200 {
                let t = 1e-4 + 0.1 * k as f64 / 200.0;
                let w = [t * 0.63, t * 0.776, 1.0];
                let l = (w[0] * w[0] + w[1] * w[1] + 1.0f64).sqrt();
                let w32 = w.map(|x| (x / l) as f32);
                let g = e.g1(w32.map(f64::from));
                worst = worst.max((f64::from(m.g1(w32)) - g).abs() / g);
            }
            assert!(worst <= 4e-6, "{kind} α {a}: {worst:e}");
        }
    }
}

/// Student-T at γ = 10⁶ (α = 1e-3): every identity of `verify` within its tolerance (the
/// inverse-Gamma superposition was 3.7e-10 against 1e-10 while the Gamma density's exponent
/// cancelled terms of size k ln k; `special::gamma_pdf` now takes Loader's saddle-point form).
#[test]
fn student_t_identities_at_huge_gamma() {
    use microsurface::check::verify::ndf_checks;
    use microsurface::ndf::{AnyNdf, StudentT};
    for gamma in [1e4, 1e6] {
        let ndf = AnyNdf::StudentT(StudentT::new(1e-3, gamma).unwrap());
        let checks = ndf_checks(&ndf);
        assert!(checks.len() >= 10, "{} checks", checks.len());
        for c in &checks {
            assert!(
                c.pass() && c.skipped.is_none(),
                "{} {}: {:e} against {:e} ({:?})",
                c.subject,
                c.identity,
                c.residual,
                c.tol,
                c.skipped
            );
        }
    }
}
