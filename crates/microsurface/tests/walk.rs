//! The microsurface random walk (Heitz et al. 2016) for every NDF: energy conservation of the
//! F = 1 conductor, order 1 against the deterministic single-scattering albedo, independence
//! of the height distribution, the paper's GGX figures, and the quadrature itself against an
//! independent rule.

use microsurface::bsdf::fresnel::One;
use microsurface::bsdf::{Bsdf, Masking, RoughConductor, RoughDielectric, Transport};
use microsurface::scattering::{
    albedo, albedo_orders, single_scattering_albedo, DielectricFacets, Facets, Heights,
    MirrorFacets, MultipleScattering, RandomWalk, WalkRng,
};
use microsurface::{
    Beckmann, DoubleGgx, Exponential, Ggx, Gtr, Microfacet, MicrofacetDistribution,
};

fn wo(mu: f64) -> [f64; 3] {
    [(1.0 - mu * mu).sqrt(), 0.0, mu]
}

/// Runs `$body` with `$d` bound to each NDF's f64 material at (αx, αy) (GTR at γ = 1.5,
/// isotropic) and `$name` to its name.
macro_rules! each_ndf {
    ($ax:expr, $ay:expr, |$name:ident, $d:ident| $body:block) => {{
        let (ax, ay): (f64, f64) = ($ax, $ay);
        {
            let ($name, $d) = ("GGX", Microfacet::<f64, Ggx>::new(ax, ay).unwrap());
            $body
        }
        {
            let ($name, $d) = (
                "Beckmann",
                Microfacet::<f64, Beckmann>::new(ax, ay).unwrap(),
            );
            $body
        }
        {
            let ($name, $d) = (
                "Double GGX",
                Microfacet::<f64, DoubleGgx>::new(ax, ay).unwrap(),
            );
            $body
        }
        {
            let ($name, $d) = (
                "Exponential",
                Microfacet::<f64, Exponential>::new(ax, ay).unwrap(),
            );
            $body
        }
        if ax == ay {
            let ($name, $d) = (
                "GTR γ=1.5",
                Microfacet::<f64, Gtr>::gtr(ax, ay, 1.5).unwrap(),
            );
            $body
        }
    }};
}

/// F = 1: every walk leaves with weight 1 (none cut, none failed), so the total albedo is 1
/// exactly; and order 1 matches the deterministic E₁ within 4 standard errors (Šidák over the
/// grid is not needed at 4σ: 60 tests, a false alarm 4e-3 in all).
#[test]
fn furnace_and_order_one() {
    for (ax, ay) in [(0.1, 0.1), (0.5, 0.5), (1.0, 1.0), (2.0, 2.0), (0.6, 0.2)] {
        for mu in [0.2, 0.5, 0.9] {
            each_ndf!(ax, ay, |name, d| {
                let e1 = single_scattering_albedo(&d, wo(mu));
                let s = RandomWalk::new(d, Heights::Uniform);
                let a = albedo(&s, &MirrorFacets(One::<1>), wo(mu), 200_000, 7);
                let (a, total) = (a.reflect, a.total.mean);
                println!(
                    "{name:12} α=({ax},{ay}) μ={mu}: E1 {:.5}±{:.5} (quadrature {e1:.5}) E2 {:.5} E3 {:.5} E4+ {:.5} total {}",
                    a.orders[0], a.stderr[0], a.orders[1], a.orders[2], a.orders[3], total
                );
                assert_eq!(total, 1.0, "{name} α=({ax},{ay}) μ={mu}: energy {}", total);
                // (Plus the quadrature's own 1e-9: at α = 0.1, μ = 0.9, Beckmann's every walk
                // ends after one bounce, a standard error of 0.)
                assert!(
                    (a.orders[0] - e1).abs() <= 4.0 * a.stderr[0] + 1e-9,
                    "{name} α=({ax},{ay}) μ={mu}: E1 walk {} ± {} vs quadrature {e1}",
                    a.orders[0],
                    a.stderr[0]
                );
            });
        }
    }
}

/// The albedo by any number of orders (`albedo_orders`): at 4 orders it is `albedo`, bit
/// for bit; at 12 the same walks give the same orders below the last bin, and the orders
/// from 4 up sum to `albedo`'s "≥ 4" (to rounding); the totals are equal. A rough GGX
/// dielectric (α = 1.5, η = 1.5, μ = 0.3), whose walks reach high orders.
#[test]
fn albedo_by_any_number_of_orders() {
    let s = RandomWalk::new(
        Microfacet::<f64, Ggx>::new(1.5, 1.5).unwrap(),
        Heights::Uniform,
    );
    let f = DielectricFacets::new(1.5).unwrap();
    let a = albedo(&s, &f, wo(0.3), 50_000, 11);
    let four = albedo_orders(&s, &f, wo(0.3), 50_000, 11, 4);
    let twelve = albedo_orders(&s, &f, wo(0.3), 50_000, 11, 12);
    for (by4, side, side12) in [
        (&a.reflect, &four.reflect, &twelve.reflect),
        (&a.transmit, &four.transmit, &twelve.transmit),
    ] {
        for (k, e) in side.iter().enumerate() {
            assert_eq!((by4.orders[k], by4.stderr[k]), (e.mean, e.stderr));
        }
        for k in 0..3 {
            assert_eq!(side[k], side12[k]);
        }
        let tail: f64 = side12[3..].iter().map(|e| e.mean).sum();
        assert!(
            (tail - by4.orders[3]).abs() <= 1e-12,
            "{tail} vs {}",
            by4.orders[3]
        );
    }
    let high: f64 = twelve.reflect[5..]
        .iter()
        .chain(&twelve.transmit[5..])
        .map(|e| e.mean)
        .sum();
    assert!(high > 0.0, "orders ≥ 6 carry energy here");
    assert_eq!(a.total, twelve.total);
    assert_eq!(a.reflect.total, twelve.reflect_total.mean);
}

/// A dielectric (η = 1.5, from outside and from inside): the walk's order 1, reflection and
/// transmission, matches the deterministic single-scattering albedo with the exact
/// height-correlated G2 (`single_scattering_albedo_dielectric_level`, `Masking::CorrelatedBeta`)
/// within 4 standard errors (plus the quadrature's 2e-5) over a grid of every NDF, α and μ.
#[test]
fn dielectric_order_one() {
    use microsurface::scattering::{single_scattering_albedo_dielectric_level, DielectricFacets};
    for (ax, ay) in [(0.3, 0.3), (1.0, 1.0), (0.6, 0.2)] {
        for mu in [0.15, 0.5, 0.9] {
            for z in [1.0, -1.0] {
                each_ndf!(ax, ay, |name, d| {
                    let w = wo(mu);
                    let w = [w[0], w[1], z * w[2]];
                    let (r, t) = single_scattering_albedo_dielectric_level(
                        &d,
                        w,
                        1.5,
                        Masking::CorrelatedBeta,
                        4,
                    );
                    let s = RandomWalk::new(d, Heights::Uniform);
                    let a = albedo(&s, &DielectricFacets::new(1.5).unwrap(), w, 100_000, 3);
                    for (lobe, q, est) in [
                        ("reflection", r, a.reflect),
                        ("transmission", t, a.transmit),
                    ] {
                        assert!(
                            (est.orders[0] - q).abs() <= 4.0 * est.stderr[0] + 2e-5,
                            "{name} α=({ax},{ay}) wo={w:?} {lobe}: walk {} ± {} vs quadrature {q}",
                            est.orders[0],
                            est.stderr[0]
                        );
                    }
                });
            }
        }
    }
}

/// The BSDF does not depend on the height distribution: uniform and Gaussian heights give the
/// same albedo per order within 4 combined standard errors.
#[test]
fn heights_do_not_matter() {
    for (ax, ay) in [(0.3, 0.3), (1.0, 1.0), (1.5, 0.5)] {
        each_ndf!(ax, ay, |name, d| {
            let mu = 0.4;
            let u = albedo(
                &RandomWalk::new(d.clone(), Heights::Uniform),
                &MirrorFacets(One::<1>),
                wo(mu),
                200_000,
                1,
            )
            .reflect;
            let g = albedo(
                &RandomWalk::new(d, Heights::Gaussian),
                &MirrorFacets(One::<1>),
                wo(mu),
                200_000,
                2,
            )
            .reflect;
            for k in 0..4 {
                let sd = u.stderr[k].hypot(g.stderr[k]);
                assert!(
                    (u.orders[k] - g.orders[k]).abs() <= 4.0 * sd,
                    "{name} α=({ax},{ay}) order {}: uniform {} vs Gaussian {} (σ {sd})",
                    k + 1,
                    u.orders[k],
                    g.orders[k]
                );
            }
        });
    }
}

/// The figures the issue quotes for a white-furnace GGX conductor at α = 1, μ = 0.5: about
/// 45 % single scattering, 33 % order 2, 15 % order 3, 7 % beyond (read off the paper's
/// plots, to about a percent).
#[test]
fn paper_ggx_figures() {
    let d = Microfacet::<f64, Ggx>::new(1.0, 1.0).unwrap();
    let a = albedo(
        &RandomWalk::new(d, Heights::Uniform),
        &MirrorFacets(One::<1>),
        wo(0.5),
        400_000,
        3,
    )
    .reflect;
    println!("{a:?}");
    for (got, want) in a.orders.iter().zip([0.45, 0.33, 0.15, 0.07]) {
        assert!((got - want).abs() < 0.02, "{:?}", a.orders);
    }
}

/// The deterministic E₁ against a 3000 × 3000 midpoint rule in (μ, φ) (an independent rule:
/// the integrand is smooth at α = 0.5 and 1, so the rule converges as 1/n²).
#[test]
fn single_scattering_quadrature() {
    for a in [0.5, 1.0] {
        let d = Microfacet::<f64, Ggx>::new(a, a).unwrap();
        for mu_o in [0.3, 0.8] {
            let o = wo(mu_o);
            let q = single_scattering_albedo(&d, o);
            let n = 3000;
            let mut sum = 0.0;
            for i in 0..n {
                let mu = (i as f64 + 0.5) / n as f64;
                let s = (1.0 - mu * mu).sqrt();
                for j in 0..n {
                    let phi = std::f64::consts::TAU * (j as f64 + 0.5) / n as f64;
                    let wi = [s * phi.cos(), s * phi.sin(), mu];
                    let h = [o[0] + wi[0], o[1] + wi[1], o[2] + wi[2]];
                    let l = (h[0] * h[0] + h[1] * h[1] + h[2] * h[2]).sqrt();
                    let wh = [h[0] / l, h[1] / l, h[2] / l];
                    sum += d.d(wh) * d.g2(o, wi) / (4.0 * mu_o);
                }
            }
            let mid = sum * std::f64::consts::TAU / (n * n) as f64;
            println!("α={a} μ={mu_o}: quadrature {q:.10} midpoint {mid:.10}");
            assert!((q - mid).abs() < 1e-6 * q, "{q} vs {mid}");
        }
    }
}

/// Runs `$body` with `$d` bound to each NDF's f64 material at isotropic α (GTR at γ = 1.5).
macro_rules! each_iso {
    ($a:expr, |$name:ident, $d:ident| $body:block) => {
        each_ndf!($a, $a, |$name, $d| $body)
    };
}

/// A direction at cos θ = μ and azimuth φ.
fn dir(mu: f64, phi: f64) -> [f64; 3] {
    let s = ((1.0 - mu) * (1.0 + mu)).max(0.0).sqrt();
    [s * phi.cos(), s * phi.sin(), mu]
}

/// ∫ f(wo, wi)|cos θi| dωi over the sphere by the stochastic evaluation: wi from the
/// single-scattering BSDF's sampler or a cosine lobe (on a random side for a dielectric),
/// each with probability ½ (the balance of both densities). Returns the mean and standard
/// error over `n` samples.
fn eval_integral<D, Fa>(
    ms: &MultipleScattering<D, Fa, 1>,
    single: &impl Bsdf<f64>,
    wo: [f64; 3],
    n: u64,
    seed: u64,
) -> (f64, f64)
where
    D: MicrofacetDistribution<f64>,
    Fa: Facets<1>,
{
    let transmits = ms.facets().interface_eta().is_some();
    let mut rng = WalkRng::new(seed);
    let (mut s, mut s2) = (0.0, 0.0);
    for _ in 0..n {
        let wi = if rng.next_open() < 0.5 {
            match single.sample(wo, rng.next_open(), [rng.next_open(), rng.next_open()]) {
                Some(x) => x.wi,
                None => continue,
            }
        } else {
            let w = dir(
                rng.next_open().sqrt(),
                2.0 * std::f64::consts::PI * rng.next_open(),
            );
            let down = if transmits {
                rng.next_open() < 0.5
            } else {
                false
            };
            let flip = (wo[2] < 0.0) != down;
            if flip {
                [w[0], w[1], -w[2]]
            } else {
                w
            }
        };
        let cos = wi[2].abs() * std::f64::consts::FRAC_1_PI;
        let pdf = 0.5 * single.pdf(wo, wi) + 0.5 * if transmits { 0.5 * cos } else { cos };
        let e = ms.surface().eval(ms.facets(), wo, wi, &mut rng);
        let x = (e[0][0] + e[1][0] + e[2][0] + e[3][0]) / pdf;
        s += x;
        s2 += x * x;
    }
    let m = s / n as f64;
    (m, ((s2 / n as f64 - m * m).max(0.0) / n as f64).sqrt())
}

/// The white furnace through the **eval estimator** integrated over the sphere (not the
/// walk's own weights, which conserve by construction): the F = 1 conductor's ∫ f|cos θi|
/// is 1, and a dielectric's reflection plus transmission is 1 from either side, within 4
/// standard errors, for every NDF, α up to 2. (Importance transport: the walk's own.)
#[test]
fn eval_white_furnace() {
    for a in [0.2, 0.6, 1.0, 2.0] {
        for mu in [0.3, 0.8] {
            each_iso!(a, |name, d| {
                let c = MultipleScattering::new(d.clone(), MirrorFacets(One::<1>));
                let single = RoughConductor::new(d.clone(), One::<1>);
                let (m, e) = eval_integral(&c, &single, wo(mu), 20_000, 11);
                println!("{name:12} α={a} μ={mu}: conductor ∫f cos = {m:.4} ± {e:.4}");
                assert!(
                    (m - 1.0).abs() <= 4.0 * e,
                    "{name} α={a} μ={mu}: conductor {m} ± {e}"
                );
                for (eta, side) in [(1.5, 1.0), (1.5, -1.0)] {
                    let w = [wo(mu)[0], 0.0, side * mu];
                    let t = MultipleScattering::<_, _, 1>::new(
                        d.clone(),
                        DielectricFacets::new(eta).unwrap(),
                    )
                    .with_transport(Transport::Importance);
                    let single = RoughDielectric::new(d.clone(), eta)
                        .unwrap()
                        .with_transport(Transport::Importance);
                    let (m, e) = eval_integral(&t, &single, w, 20_000, 12);
                    println!(
                        "{name:12} α={a} μ={}: dielectric R + T = {m:.4} ± {e:.4}",
                        w[2]
                    );
                    assert!(
                        (m - 1.0).abs() <= 4.0 * e,
                        "{name} α={a} μ={}: dielectric R + T {m} ± {e}",
                        w[2]
                    );
                }
            });
        }
    }
}

/// Order 1 of the stochastic evaluation is the single-scattering BSDF with the
/// height-correlated G2: the F = 1 conductor's and the dielectric's reflection exactly
/// `bsdf::RoughConductor`'s and `bsdf::RoughDielectric`'s (1/(1 + Λo + Λi)), the dielectric's
/// transmission `RoughDielectric`'s with `Masking::CorrelatedBeta`, the exact
/// height-correlated B(1 + Λo, 1 + Λi) (Heitz 2014, section 6). Within 4 standard errors at pairs of
/// directions over the lobes, every NDF, from both sides of the dielectric.
#[test]
fn eval_order_one_is_single_scattering() {
    for a in [0.3, 1.0] {
        each_iso!(a, |name, d| {
            let c = MultipleScattering::new(d.clone(), MirrorFacets(One::<1>));
            let single = RoughConductor::new(d.clone(), One::<1>);
            for (wo, wi) in [
                (dir(0.7, 0.0), dir(0.6, 3.0)),
                (dir(0.3, 0.0), dir(0.9, 0.5)),
                (dir(0.5, 0.0), dir(0.2, 2.0)),
            ] {
                let got = c.eval_orders(wo, wi, 40_000, 5)[0];
                let want = single.eval(wo, wi)[0];
                // (Where Λ(wi) underflows to 0, every sample is the same, to rounding.)
                assert!(
                    (got.orders[0] - want).abs() <= 4.0 * got.stderr[0] + 1e-12 * want,
                    "{name} α={a} conductor {wo:?} {wi:?}: {} ± {} vs {want}",
                    got.orders[0],
                    got.stderr[0]
                );
            }
            for eta in [1.5, 1.0 / 1.5] {
                let t = MultipleScattering::<_, _, 1>::new(
                    d.clone(),
                    DielectricFacets::new(eta).unwrap(),
                )
                .with_transport(Transport::Importance);
                let single = RoughDielectric::new(d.clone(), eta)
                    .unwrap()
                    .with_transport(Transport::Importance)
                    .with_masking(Masking::CorrelatedBeta);
                for (wo, wi) in [
                    (dir(0.7, 0.0), dir(0.6, 3.0)),
                    (dir(0.6, 0.0), dir(-0.8, 3.1)),
                    (dir(0.9, 0.0), dir(-0.5, 2.9)),
                    (dir(-0.7, 0.0), dir(0.9, 3.0)),
                ] {
                    let got = t.eval_orders(wo, wi, 40_000, 6)[0];
                    let want = single.eval(wo, wi)[0];
                    println!(
                        "{name:12} α={a} η={eta:.3} {wo:?} → {wi:?}: {} ± {} vs {want}",
                        got.orders[0], got.stderr[0]
                    );
                    assert!(
                        (got.orders[0] - want).abs() <= 4.0 * got.stderr[0] + 1e-12 * want,
                        "{name} α={a} η={eta} {wo:?} {wi:?}: {} ± {} vs {want}",
                        got.orders[0],
                        got.stderr[0]
                    );
                }
            }
        });
    }
}

/// Reciprocity of the stochastic evaluation in expectation: the conductor's
/// f(wo, wi) = f(wi, wo), and the dielectric's (radiance transport)
/// η_i² f(wo, wi) = η_o² f(wi, wo) with η_o, η_i the indices of wo's and wi's media (the
/// single-scattering `Dielectric`'s own relation), for the total over orders, within 4
/// combined standard errors, every NDF.
#[test]
fn eval_reciprocity() {
    for a in [0.5, 1.5] {
        each_iso!(a, |name, d| {
            let c = MultipleScattering::new(d.clone(), MirrorFacets(One::<1>));
            let t =
                MultipleScattering::<_, _, 1>::new(d.clone(), DielectricFacets::new(1.5).unwrap());
            for (wo, wi) in [
                (dir(0.8, 0.0), dir(0.3, 2.0)),
                (dir(0.4, 0.0), dir(0.5, 1.0)),
            ] {
                let f = c.eval_orders(wo, wi, 40_000, 1)[0];
                let b = c.eval_orders(wi, wo, 40_000, 2)[0];
                let sd = f.total_stderr.hypot(b.total_stderr);
                assert!(
                    (f.total - b.total).abs() <= 4.0 * sd,
                    "{name} α={a} conductor {wo:?} {wi:?}: {} vs {} (σ {sd})",
                    f.total,
                    b.total
                );
            }
            for (wo, wi) in [
                (dir(0.8, 0.0), dir(-0.3, 2.0)),
                (dir(0.4, 0.0), dir(-0.9, 3.0)),
            ] {
                // wo outside (η_o = 1), wi inside (η_i = 1.5).
                let f = t.eval_orders(wo, wi, 40_000, 3)[0];
                let b = t.eval_orders(wi, wo, 40_000, 4)[0];
                let (x, y) = (2.25 * f.total, b.total);
                let sd = (2.25 * f.total_stderr).hypot(b.total_stderr);
                println!("{name:12} α={a} dielectric {wo:?} {wi:?}: {x} vs {y} (σ {sd})");
                assert!(
                    (x - y).abs() <= 4.0 * sd,
                    "{name} α={a} dielectric {wo:?} {wi:?}: {x} vs {y} (σ {sd})"
                );
            }
        });
    }
}

/// The walk's sampling and the stochastic evaluation describe the same BSDF: the share of
/// walks that leave in each band of cos θi (8 per side) equals ∫ f|cos θi| dωi over the
/// band by the evaluation (wi uniform in the band's cos θ and azimuth), within 4 combined
/// standard errors: the F = 1 conductor and the dielectric (η = 1.5, from both sides),
/// GGX, Beckmann and Exponential. Bands that fewer than 1 walk in 1000 reaches are not
/// compared: there the evaluation's samples are nearly all 0 with rare large values (a
/// dielectric's grazing transmission beyond the critical angle is reached only by order
/// ≥ 2), its standard error from 20 000 samples is unreliable, and the test would measure
/// the tail of the estimate, not the BSDF (at 2·10⁶ samples both sides agree there, e.g.
/// Beckmann α = 0.4, band 1 inside: sampled 1.1e-4, evaluated 1.4e-4 ± noise).
#[test]
fn sampling_matches_evaluation() {
    const BANDS: usize = 8;
    fn check<D: MicrofacetDistribution<f64>, Fa: Facets<1>>(
        name: &str,
        ms: &MultipleScattering<D, Fa, 1>,
        wo: [f64; 3],
    ) {
        let sides: &[f64] = if ms.facets().interface_eta().is_some() {
            &[1.0, -1.0]
        } else {
            &[1.0]
        };
        let n = 200_000u64;
        let mut rng = WalkRng::new(9);
        let mut counts = [0u64; 2 * BANDS];
        for _ in 0..n {
            if let Some(p) = ms.surface().walk(ms.facets(), wo, &mut rng) {
                let side = usize::from(p.w[2] < 0.0);
                let band = ((p.w[2].abs() * BANDS as f64) as usize).min(BANDS - 1);
                counts[side * BANDS + band] += 1;
            }
        }
        for (s, &sign) in sides.iter().enumerate() {
            for b in 0..BANDS {
                let p = counts[s * BANDS + b] as f64 / n as f64;
                if p < 1e-3 {
                    continue;
                }
                let sd_p = (p * (1.0 - p) / n as f64).sqrt();
                let m = 20_000u64;
                let (mut sum, mut sum2) = (0.0, 0.0);
                for _ in 0..m {
                    let mu = (b as f64 + rng.next_open()) / BANDS as f64;
                    let wi = dir(sign * mu, 2.0 * std::f64::consts::PI * rng.next_open());
                    let e = ms.surface().eval(ms.facets(), wo, wi, &mut rng);
                    let x = (e[0][0] + e[1][0] + e[2][0] + e[3][0])
                        * (2.0 * std::f64::consts::PI / BANDS as f64);
                    sum += x;
                    sum2 += x * x;
                }
                let q = sum / m as f64;
                let sd_q = ((sum2 / m as f64 - q * q).max(0.0) / m as f64).sqrt();
                let sd = sd_p.hypot(sd_q);
                assert!(
                    (p - q).abs() <= 4.0 * sd + 1e-9,
                    "{name} wo={wo:?} side {sign} band {b}: sampled {p} vs evaluated {q} (σ {sd})"
                );
            }
        }
    }
    for a in [0.4, 1.2] {
        macro_rules! cases {
            ($name:expr, $d:expr) => {{
                let d = $d;
                check(
                    $name,
                    &MultipleScattering::new(d.clone(), MirrorFacets(One::<1>)),
                    dir(0.5, 0.3),
                );
                let t = MultipleScattering::<_, _, 1>::new(d, DielectricFacets::new(1.5).unwrap());
                check($name, &t, dir(0.6, 0.0));
                check($name, &t, dir(-0.8, 1.0));
            }};
        }
        cases!("GGX", Microfacet::<f64, Ggx>::new(a, a).unwrap());
        cases!(
            "Beckmann",
            Microfacet::<f64, Beckmann>::new(a, 0.6 * a).unwrap()
        );
        cases!(
            "Exponential",
            Microfacet::<f64, Exponential>::new(a, a).unwrap()
        );
    }
}

/// χ² of `d`'s stream sampler for v (100 000 normals, 16² cells of `reference`'s D·cos
/// coordinates) against max(0, v·m) D(m)/σ: p above `level`, no bad sample, ∫pdf = 1 to 2e-3;
/// every normal above the horizon and facing v.
#[allow(clippy::too_many_arguments)]
fn stream_chi2<D: MicrofacetDistribution<f64>>(
    label: &str,
    d: &D,
    v: [f64; 3],
    sigma: f64,
    reference: &microsurface::Exact,
    rng: &mut microsurface::check::chi2::SplitMix64,
    seed: u64,
    level: f64,
) {
    use microsurface::check::chi2::{chi2_test, DcosCoordinates};
    use microsurface::Vec3;
    let r = chi2_test(
        |_| {
            let m = d
                .sample_wm_stream(v, &mut || 0.5 * (2.0 * rng.next_f64()).max(f64::EPSILON))
                .expect("a normal");
            assert!(m[2] > 0.0 && m[0] * v[0] + m[1] * v[1] + m[2] * v[2] > 0.0);
            Vec3::from(m)
        },
        |m| {
            let m: [f64; 3] = m.into();
            (m[0] * v[0] + m[1] * v[1] + m[2] * v[2]).max(0.0) * d.d(m) / sigma
        },
        &DcosCoordinates(reference),
        100_000,
        16,
        seed,
    );
    assert!(
        r.p_value > level && r.bad_samples == 0 && (r.pdf_integral - 1.0).abs() < 2e-3,
        "{label}: {r:?}"
    );
}

/// The stream samplers of visible normals (`MicrofacetDistribution::sample_wm_stream`, which the walk
/// uses instead of the warps and of its rejection from the mirror image; GGX, Beckmann,
/// Double GGX): χ² against max(0, v·m) D(m)/σ(v), σ = |v.z| Λ(v) below and v.z(1 + Λ(v))
/// above; below isotropic and anisotropic, 45° and 89° (Beckmann's two envelopes both),
/// above anisotropic at normal incidence, 30° and 80°; every sample a unit normal with
/// m.z > 0 and v·m > 0; the NDFs without one answer `None`.
#[test]
fn visible_normals_from_a_stream() {
    use microsurface::check::chi2::{sidak, SplitMix64};
    use microsurface::{Exact, NdfKind};
    fn check<D: MicrofacetDistribution<f64>>(
        name: &str,
        d: D,
        kind: NdfKind,
        ax: f64,
        ay: f64,
        level: f64,
    ) {
        let reference = Exact::new(NdfKind::Ggx, 1.5 * ax, 1.5 * ay, None).unwrap();
        let mut rng = SplitMix64(kind as u64);
        let above: &[f64] = if ax == ay { &[] } else { &[0.0, 30.0, 80.0] };
        let below = [45.0f64, 89.0].map(|d| -d);
        for &deg in above.iter().chain(&below) {
            let (s, c) = deg.abs().to_radians().sin_cos();
            let v = [s * 0.8, s * 0.6, c * deg.signum()];
            let sigma = if deg < 0.0 {
                c * d.lambda(v)
            } else {
                c * (1.0 + d.lambda(v))
            };
            stream_chi2(
                &format!("{name} α=({ax},{ay}) θ={deg}"),
                &d,
                v,
                sigma,
                &reference,
                &mut rng,
                (deg + 100.0) as u64,
                level,
            );
        }
    }
    let level = sidak(0.01, 3 * (2 * 2 + 3));
    for &(ax, ay) in &[(0.4, 0.4), (0.8, 0.2)] {
        check(
            "GGX",
            Microfacet::<f64, Ggx>::new(ax, ay).unwrap(),
            NdfKind::Ggx,
            ax,
            ay,
            level,
        );
        check(
            "Beckmann",
            Microfacet::<f64, Beckmann>::new(ax, ay).unwrap(),
            NdfKind::Beckmann,
            ax,
            ay,
            level,
        );
        check(
            "Double GGX",
            Microfacet::<f64, DoubleGgx>::new(ax, ay).unwrap(),
            NdfKind::DoubleGgx,
            ax,
            ay,
            level,
        );
        let e = Microfacet::<f64, Exponential>::new(ax, ay).unwrap();
        assert!(e.sample_wm_stream([0.6, 0.0, -0.8], &mut || 0.5).is_none());
    }
}

/// The family's Beckmann mixtures (Student-T, Ei, Erfc, K0, Bessel-K) through `Exact`'s
/// stream sampler (the posterior of the mixing variable, then Beckmann's): χ² against
/// max(0, v·m) D(m)/(v.z(1 + Λ(v))) at normal incidence, 30° and 80°, isotropic and
/// anisotropic, shapes at both ends of their ranges (coordinates: the same NDF's D·cos warp at
/// 1.5α; for Bessel-K, Erfc's or GGX's); `None` below the horizon and for the
/// generalised exponential (no such sampler).
#[test]
fn family_visible_normals_from_a_stream() {
    use microsurface::check::chi2::{sidak, SplitMix64};
    use microsurface::{AnyNdf, Exact, NdfKind};
    let cases = [
        (NdfKind::StudentT, Some(1.6)),
        (NdfKind::StudentT, Some(2.5)),
        (NdfKind::StudentT, Some(40.0)),
        (NdfKind::Ei, None),
        (NdfKind::Erfc, None),
        (NdfKind::K0, None),
        (NdfKind::BesselK, Some(0.3)),
        (NdfKind::BesselK, Some(2.5)),
        (NdfKind::BesselK, Some(20.0)),
    ];
    // (Isotropic at 30°, anisotropic at normal incidence and 80°: ~20 s in all.)
    let settings = [((0.4, 0.4), 30.0f64), ((0.8, 0.2), 0.0), ((0.8, 0.2), 80.0)];
    let level = sidak(0.01, cases.len() * settings.len());
    for (i, &(kind, shape)) in cases.iter().enumerate() {
        for &((ax, ay), deg) in &settings {
            let d = Exact::new(kind, ax, ay, shape).unwrap();
            // (Bessel-K's own D·cos warp would cost ~0.4 ms a sample, its CDF a quadrature:
            // there Erfc's coordinates where D has a pole (P22 ~ 1/r), GGX's elsewhere.)
            let singular = AnyNdf::new(kind, 1.0, shape).unwrap().singular_at_pole();
            let reference = match kind {
                NdfKind::BesselK if singular => Exact::new(NdfKind::Erfc, 1.5 * ax, 1.5 * ay, None),
                NdfKind::BesselK => Exact::new(NdfKind::Ggx, 1.5 * ax, 1.5 * ay, None),
                _ => Exact::new(kind, 1.5 * ax, 1.5 * ay, shape),
            }
            .unwrap();
            let mut rng = SplitMix64(i as u64 + 100);
            assert!(d.sample_wm_stream([0.6, 0.0, -0.8], &mut || 0.5).is_none());
            let (s, c) = deg.to_radians().sin_cos();
            let v = [s * 0.8, s * 0.6, c];
            let sigma = c * (1.0 + d.lambda(v));
            stream_chi2(
                &format!("{kind} {shape:?} α=({ax},{ay}) θ={deg}"),
                &d,
                v,
                sigma,
                &reference,
                &mut rng,
                deg as u64 + 7,
                level,
            );
        }
    }
    let g = Exact::new(NdfKind::GenExponential, 0.4, 0.4, Some(3.0)).unwrap();
    assert!(g.sample_wm_stream([0.0, 0.0, 1.0], &mut || 0.5).is_none());
}

/// The rest of the family through the exact path (`Exact`: stretched α = 1 member, visible
/// normals by the posterior stream sampler for the Beckmann mixtures): the F = 1 furnace
/// conserves energy exactly, and order 1 matches the deterministic E₁ within 4σ.
#[test]
fn family_furnace_and_order_one() {
    use microsurface::{Exact, NdfKind};
    for (kind, shape) in [
        (NdfKind::StudentT, Some(2.5)),
        (NdfKind::K0, None),
        (NdfKind::Ei, None),
        (NdfKind::Erfc, None),
        (NdfKind::BesselK, Some(2.5)),
    ] {
        // (A walk through the exact path, visible normals by the posterior stream sampler,
        // costs 1 µs (Student-T, K0) to 50 µs (Bessel-K: Λ integrates K_ν); the E₁ quadrature
        // 0.01–4 s here. K0, Ei and Erfc have a pole of D at the normal: their E₁ is the
        // integral over the normal, which this test checks against the walk; Bessel-K a ≤ 1
        // takes the same path, 15 s at a = 0.3: not here.)
        let d = Exact::new(kind, 0.6, 0.3, shape).unwrap();
        let w = wo(0.4);
        let e1 = single_scattering_albedo(&d, w);
        let s = RandomWalk::new(d, Heights::Uniform);
        let walks = 20_000;
        let a = albedo(&s, &MirrorFacets(One::<1>), w, walks, 11);
        println!(
            "{kind}: E1 {:.4}±{:.4} (quadrature {e1:.4}), E2+ {:.4}, total {}",
            a.reflect.orders[0],
            a.reflect.stderr[0],
            a.reflect.total - a.reflect.orders[0],
            a.total.mean
        );
        assert_eq!(a.total.mean, 1.0, "{kind}: energy");
        assert!(
            (a.reflect.orders[0] - e1).abs() <= 4.0 * a.reflect.stderr[0] + 1e-9,
            "{kind}: E1 walk {} ± {} vs quadrature {e1}",
            a.reflect.orders[0],
            a.reflect.stderr[0]
        );
    }
}

/// The walk under multiple importance sampling (`MultipleScattering::pdf`, the stand-in the
/// weights use): one pixel under a white furnace plus a sky dome, L = 1 + 4 max(0, cos θ),
/// light-sampled in proportion to L. One BSDF sample and one light sample combined by the
/// power heuristic (the light sample weighted by one stochastic `eval`) are no noisier
/// than the BSDF sample alone, and agree with it in the mean within 4 standard errors: the
/// F = 1 GGX conductor at α ∈ {0.05, 0.1, 0.5}, θo ∈ {0°, 45°}. The variance ratio is at
/// most 1.003 at 10⁶ samples (BENCHMARKS.md, "The walk under MIS"); the bound 1.05 leaves
/// room for the spread of a ratio from 20 000 samples (0.953 to 1.004 here), and the
/// previous stand-in, single scattering plus a cosine term, measured 4.9 to 50 at these
/// pixels.
/// Every pdf is at least single scattering's (the floor is added to it).
#[test]
fn mis_under_a_sky_is_no_noisier_than_bsdf_sampling() {
    use std::f64::consts::PI;
    let l = |w: [f64; 3]| 1.0 + 4.0 * w[2].max(0.0);
    // ∫L = 4π + 4π.
    let p_l = |w: [f64; 3]| l(w) / (8.0 * PI);
    let power = |p: f64, q: f64| {
        if p > 0.0 {
            p * p / (p * p + q * q)
        } else {
            0.0
        }
    };
    for a in [0.05, 0.1, 0.5] {
        let d = Microfacet::<f64, Ggx>::new(a, a).unwrap();
        let ms = MultipleScattering::new(d.clone(), MirrorFacets(One::<1>));
        let single = RoughConductor::new(d, One::<1>);
        for mu in [1.0, 0.5f64.sqrt()] {
            let wo = wo(mu);
            let n = 20_000;
            let mut rng = WalkRng::new(17);
            let (mut b, mut b2, mut m, mut m2) = (0.0, 0.0, 0.0, 0.0);
            for _ in 0..n {
                let u = [rng.next_open(), rng.next_open(), rng.next_open()];
                let (xb, wb) = match ms.sample(wo, u[0], [u[1], u[2]]) {
                    Some(s) => {
                        assert!(s.pdf >= single.pdf(wo, s.wi), "α={a} {wo:?} {:?}", s.wi);
                        let x = s.f[0] * s.wi[2] / s.pdf * l(s.wi);
                        (x, x * power(s.pdf, p_l(s.wi)))
                    }
                    None => (0.0, 0.0),
                };
                // The light sample: half uniform on the sphere, half cosine about the zenith.
                let (u0, c) = (rng.next_open(), rng.next_open());
                let c = if u0 < 0.5 { 1.0 - 2.0 * c } else { c.sqrt() };
                let w = dir(c, 2.0 * PI * rng.next_open());
                let xl = if w[2] > 0.0 {
                    let p = ms.pdf(wo, w);
                    assert!(p >= single.pdf(wo, w), "α={a} {wo:?} {w:?}");
                    power(p_l(w), p) * ms.eval(wo, w)[0] * w[2] * l(w) / p_l(w)
                } else {
                    0.0
                };
                let x = wb + xl;
                b += xb;
                b2 += xb * xb;
                m += x;
                m2 += x * x;
            }
            let n = n as f64;
            let (vb, vm) = (b2 / n - (b / n).powi(2), m2 / n - (m / n).powi(2));
            let sd = ((vb + vm) / n).sqrt();
            println!(
                "α={a} μ={mu:.3}: BSDF {:.4} (var {vb:.4e}), MIS {:.4} (var ratio {:.4})",
                b / n,
                m / n,
                vm / vb
            );
            assert!(vm <= 1.05 * vb, "α={a} μ={mu}: Var MIS {vm} vs BSDF {vb}");
            assert!(
                (m - b).abs() / n <= 4.0 * sd,
                "α={a} μ={mu}: MIS {} vs BSDF {} (σ {sd})",
                m / n,
                b / n
            );
        }
    }
}
