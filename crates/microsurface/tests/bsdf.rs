//! The renderer-facing layer: `Microfacet` against the exact path, samples against their
//! pdfs, and the BSDFs (χ² of sampling against the pdf over the whole sphere, the pdf's
//! integral against the rejected fraction, reciprocity, energy, the smooth limit).
//!
//! `cargo test` runs a subset of the χ² grid; the full grid (every NDF × α {0.05, 0.3, 1} ×
//! θo {0°, 45°, 80°, 89°} × η {1.5, 1/1.5} × iso/aniso) is `#[ignore]`d and run by .ci/run.

// Index loops over the NDFs (k names the NDF in several tables); the NaN-aware `!(x > 0)`.
#![allow(
    clippy::needless_range_loop,
    clippy::neg_cmp_op_on_partial_ord,
    clippy::too_many_arguments,
    clippy::type_complexity
)]

use microsurface::bsdf::frame::{dot, normalize, refract};
use microsurface::bsdf::fresnel::{self, One};
use microsurface::bsdf::{Bsdf, Lobe, Masking, RoughConductor, RoughDielectric, Transport};
use microsurface::check::chi2::{
    cell_of, chi2_test, chi2_test_region, chi2_test_region_expected, sidak, AxisCoordinates,
    Coordinates, DcosCoordinates, SplitMix64,
};
use microsurface::{
    AnyMicrofacet, Beckmann, DoubleGgx, Exact, Exponential, Ggx, Gtr, Microfacet,
    MicrofacetDistribution, NdfKind, Real, Vec3,
};

/// Every NDF as a fast f64 material and its exact path; GTR at γ = 1.5 (isotropic only)
/// and γ = 2 (anisotropic: GGX).
#[derive(Clone, Debug)]
enum Any<F: Real> {
    Ggx(Microfacet<F, Ggx>),
    Beckmann(Microfacet<F, Beckmann>),
    DoubleGgx(Microfacet<F, DoubleGgx>),
    Exponential(Microfacet<F, Exponential>),
    Gtr(Microfacet<F, Gtr>),
}

macro_rules! each {
    ($any:expr, $m:ident => $body:expr) => {
        match $any {
            Any::Ggx($m) => $body,
            Any::Beckmann($m) => $body,
            Any::DoubleGgx($m) => $body,
            Any::Exponential($m) => $body,
            Any::Gtr($m) => $body,
        }
    };
}

const NAMES: [&str; 5] = ["ggx", "beckmann", "double_ggx", "exponential", "gtr"];

fn material<F: Real>(k: usize, ax: F, ay: F) -> Any<F> {
    match k {
        0 => Any::Ggx(Microfacet::new(ax, ay).unwrap()),
        1 => Any::Beckmann(Microfacet::new(ax, ay).unwrap()),
        2 => Any::DoubleGgx(Microfacet::new(ax, ay).unwrap()),
        3 => Any::Exponential(Microfacet::new(ax, ay).unwrap()),
        _ => {
            let gamma = if ax == ay { 1.5 } else { 2.0 };
            Any::Gtr(Microfacet::gtr(ax, ay, gamma).unwrap())
        }
    }
}

fn exact<F: Real>(m: &Any<F>) -> Exact {
    each!(m, x => x.exact())
}

/// A unit direction at polar angle θ (degrees) and a generic azimuth.
fn direction(deg: f64) -> [f64; 3] {
    let t = deg.to_radians();
    [t.sin() * 0.8, t.sin() * 0.6, t.cos()]
}

fn random_direction(rng: &mut SplitMix64) -> [f64; 3] {
    let z = 2.0 * rng.next_f64() - 1.0;
    let phi = std::f64::consts::TAU * rng.next_f64();
    let r = (1.0 - z * z).max(0.0).sqrt();
    [r * phi.cos(), r * phi.sin(), z]
}

/// (x, y) rescaled so that x² + y² = 1 − z².
fn unit_with_z(v: [f64; 3]) -> [f64; 3] {
    let h = (v[0] * v[0] + v[1] * v[1]).sqrt();
    let s = ((1.0 - v[2]) * (1.0 + v[2])).max(0.0).sqrt();
    if h == 0.0 {
        return [0.0, 0.0, v[2].signum()];
    }
    [v[0] * s / h, v[1] * s / h, v[2]]
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / b.abs().max(1e-300)
    }
}

/// The fast f64 and f32 paths against the exact one: D, G1 and the visible pdf, at random
/// normals and directions, isotropic and anisotropic (G1 rather than Λ: near normal
/// incidence Λ ~ α²(1 − z²)/4 is as ill-conditioned in a rounded unit vector as 1 − z², for
/// every method; G1 is not). Bounds: the fast paths' documented
/// ones (GGX 1e-14 / 1e-6, Beckmann 1e-12 / 2e-5, fitted 1e-7 / 2e-6), plus the
/// projected-roughness arithmetic of the anisotropic path (a few ulp).
#[test]
fn fast_paths_match_the_exact_path() {
    let mut rng = SplitMix64(20);
    for k in 0..5 {
        for &(ax, ay) in &[
            (0.05, 0.05),
            (0.3, 0.3),
            (1.0, 1.0),
            (0.3, 0.08),
            (0.05, 1.0),
            (1.5, 0.4),
        ] {
            let m64 = material::<f64>(k, ax, ay);
            let m32 = material::<f32>(k, ax as f32, ay as f32);
            let ex = exact(&m64);
            let (tol64, tol32) = match (k, ax == ay) {
                (0, _) => (1e-13, 2e-6),
                (1, _) => (1e-11, 4e-5),
                (4, false) => (1e-13, 2e-6),
                // Anisotropic fitted paths in f32: the projected roughness α̃ is rounded to
                // f32 (6e-8) and Λ's condition number in α reaches ~100 where Λ is small
                // (the Exponential NDF's Λ ~ e^{−2 cot θ/α}).
                (_, false) => (2e-7, 1e-5),
                _ => (2e-7, 4e-6),
            };
            let (mut worst64, mut worst32) = (0.0f64, 0.0f64);
            for _ in 0..2000 {
                let w = random_direction(&mut rng);
                let mut wm = random_direction(&mut rng);
                wm[2] = wm[2].abs();
                let w32 = w.map(|x| x as f32);
                let wm32 = wm.map(|x| x as f32);
                let (d, l, p) = (ex.d(wm), ex.g1(w), ex.pdf(w, wm));
                let (d64, l64, p64) = each!(&m64, m => (m.d(wm), m.g1(w), m.pdf(w, wm)));
                // The exact values at the f32-rounded inputs (their rounding is not the f32
                // path's error). A rounded f32 vector is unit only to 6e-8, which at
                // α = 0.05 moves D by 2e-5 through tan²θ/α², and it is read one way or the
                // other: from z (the scalar paths) or as a direction (GGX's vector forms).
                // Both unit vectors are references; the nearer one counts.
                let (wr1, wmr1) = (
                    unit_with_z(w32.map(|x| x as f64)),
                    unit_with_z(wm32.map(|x| x as f64)),
                );
                let (wr2, wmr2) = (
                    normalize(w32.map(|x| x as f64)),
                    normalize(wm32.map(|x| x as f64)),
                );
                let (dr, lr, pr) = (
                    [ex.d(wmr1), ex.d(wmr2)],
                    [ex.g1(wr1), ex.g1(wr2)],
                    [ex.pdf(wr1, wmr1), ex.pdf(wr2, wmr2)],
                );
                let wr = wr1;
                let wmr = wmr1;
                // The pdf's w·wm in F: a dot product's rounding (1e-16, 6e-8 absolute)
                // relative to itself.
                let c = dot(w, wm).abs().max(1e-300);
                let c32 = dot(wr, wmr).abs().max(1e-300);
                let (d32, l32, p32) = each!(&m32, m => (m.d(wm32), m.g1(w32), m.pdf(w32, wm32)));
                for (a, b, cond) in [(d64, d, 0.0), (l64, l, 0.0), (p64, p, 4e-16 / c)] {
                    if b.abs() > 1e-280 && b.is_finite() {
                        worst64 = worst64.max(rel(a, b) - cond);
                    }
                }
                for (a, b, cond) in [
                    (d32 as f64, dr, 0.0),
                    (l32 as f64, lr, 0.0),
                    (p32 as f64, pr, 2.4e-7 / c32),
                ] {
                    if b[0].abs() > 1e-30 && b[0].abs() < 1e30 {
                        worst32 = worst32.max(rel(a, b[0]).min(rel(a, b[1])) - cond);
                    }
                }
            }
            println!(
                "{:12} α = ({ax}, {ay}): f64 {worst64:.2e} f32 {worst32:.2e}",
                NAMES[k]
            );
            assert!(
                worst64 <= tol64,
                "{} ({ax}, {ay}) f64: {worst64:e}",
                NAMES[k]
            );
            assert!(
                worst32 <= tol32,
                "{} ({ax}, {ay}) f32: {worst32:e}",
                NAMES[k]
            );
        }
    }
}

/// Every sample carries its pdf, is a unit normal visible from w, and the sampler is the
/// visible distribution (χ² against the fast pdf, which `fast_paths_match_the_exact_path`
/// holds to the exact one within 2e-7: the exact superpositions' quadratures made this test
/// take 4 minutes).
#[test]
fn samples_carry_their_pdf_and_follow_it() {
    let level = sidak(0.01, 5 * 4 * 3);
    let mut rng = SplitMix64(7);
    for k in 0..5 {
        for &(ax, ay) in &[(0.3, 0.3), (0.5, 0.12)] {
            let m = material::<f64>(k, ax, ay);
            for deg in [0.0, 60.0, 85.0] {
                let w = direction(deg);
                // Samples' own pdfs.
                for _ in 0..500 {
                    let u = [rng.next_f64(), rng.next_f64()];
                    let s = each!(&m, x => x.sample(w, u));
                    let p = each!(&m, x => x.pdf(w, s.wm));
                    assert_eq!(s.pdf, p);
                    assert!(s.pdf > 0.0 && s.pdf.is_finite());
                    assert!((dot(s.wm, s.wm) - 1.0).abs() < 1e-12 && dot(w, s.wm) > 0.0);
                }
                let reference = Exact::new(NdfKind::Ggx, 1.5 * ax, 1.5 * ay, None).unwrap();
                let r = chi2_test(
                    |u| Vec3::from(each!(&m, x => x.sample_wm(w, u))),
                    |wm| each!(&m, x => x.pdf(w, wm.into())),
                    &DcosCoordinates(&reference),
                    100_000,
                    24,
                    (k * 100 + deg as usize) as u64,
                );
                println!(
                    "{:12} ({ax}, {ay}) θ = {deg:2}: χ² {:8.1} dof {:4} p {:.3e} ∫pdf {:.6}",
                    NAMES[k], r.statistic, r.dof, r.p_value, r.pdf_integral
                );
                assert_eq!(r.bad_samples, 0);
                assert!((r.pdf_integral - 1.0).abs() < 1e-4);
                assert!(
                    r.p_value > level,
                    "{} θ = {deg}: p = {:e}",
                    NAMES[k],
                    r.p_value
                );
            }
        }
    }
}

/// The lobes' directions for wo: the mirror direction, and the refracted one (for a
/// conductor, or where the macro interface reflects totally, the mirror's opposite).
fn lobe_axes(wo: [f64; 3], eta: Option<f64>) -> [Vec3; 2] {
    let r = [-wo[0], -wo[1], wo[2]];
    let t = eta
        .and_then(|e| refract(wo, [0.0, 0.0, 1.0], e))
        .map(|(t, _)| t)
        .unwrap_or([-r[0], -r[1], -r[2]]);
    [Vec3::from(r), Vec3::from(t)]
}

/// χ² of a BSDF's sampling against its pdf on the hemispheres about each lobe's direction
/// (the D·cos warp of a reference lobe about it: cells follow the lobe), each test with one
/// more cell for everything outside its hemisphere (rejections included), and the fraction
/// of samples in each hemisphere against the pdf's integral there. For a conductor the two
/// hemispheres are complementary, and the pdf's integral over the sphere is the fraction of
/// samples kept (the rest are reflections below the horizon).
fn check_bsdf<B: Bsdf<f64>>(
    label: &str,
    b: &B,
    wo: [f64; 3],
    alpha: f64,
    eta: Option<f64>,
    n: usize,
    level: f64,
    expected: Option<&[Vec<f64>; 2]>,
) {
    check_bsdf_axes(
        label,
        b,
        wo,
        alpha,
        eta,
        lobe_axes(wo, eta),
        n,
        level,
        expected,
    );
}

/// [`check_bsdf`] on the hemispheres about the given axes (complementary for a conductor).
#[allow(clippy::too_many_arguments)]
fn check_bsdf_axes<B: Bsdf<f64>>(
    label: &str,
    b: &B,
    wo: [f64; 3],
    alpha: f64,
    eta: Option<f64>,
    axes: [Vec3; 2],
    n: usize,
    level: f64,
    expected: Option<&[Vec<f64>; 2]>,
) {
    let (res, ar) = (RES, reference_alpha(alpha));
    let mut integral = 0.0;
    let mut kept = 0usize;
    for (side, axis) in axes.into_iter().enumerate() {
        let coords = AxisCoordinates::new(ar, axis);
        let (mut count, mut inside) = (0usize, 0usize);
        let mut draw = |rng: &mut SplitMix64| {
            let uc = rng.next_f64();
            let u = [rng.next_f64(), rng.next_f64()];
            let s = b.sample(wo, uc, u)?;
            count += 1;
            assert!(s.pdf > 0.0 && s.pdf.is_finite(), "{label}: pdf {}", s.pdf);
            let p = b.pdf(wo, s.wi);
            assert!(
                rel(p, s.pdf) < 1e-9,
                "{label}: sample pdf {} vs pdf {p}",
                s.pdf
            );
            let wi = Vec3::from(s.wi);
            inside += usize::from(wi.dot(axis) > 0.0);
            Some(wi)
        };
        let seed = 1000 + side as u64;
        let r = match expected {
            None => chi2_test_region(&mut draw, |wi| b.pdf(wo, wi.into()), &coords, n, res, seed),
            Some(e) => chi2_test_region_expected(&mut draw, &e[side], &coords, n, res, seed),
        };
        kept = count;
        integral += r.pdf_integral;
        let frac = inside as f64 / n as f64;
        println!(
            "{label:60} side {side}: χ² {:8.1} dof {:4} p {:.3e} ∫pdf {:.5} (fraction {frac:.5})",
            r.statistic, r.dof, r.p_value, r.pdf_integral
        );
        assert_eq!(r.bad_samples, 0, "{label}");
        assert!(
            r.p_value > level,
            "{label} side {side}: p = {:e}",
            r.p_value
        );
        // 4σ of the binomial, plus the cell rule's error where the horizon cuts a lobe.
        let sd = (frac * (1.0 - frac) / n as f64).sqrt();
        assert!(
            (r.pdf_integral - frac).abs() < 4.0 * sd + 2e-3,
            "{label} side {side}: ∫pdf {} vs {frac}",
            r.pdf_integral
        );
    }
    if eta.is_none() {
        let p = kept as f64 / n as f64;
        let sd = (p * (1.0 - p) / n as f64).sqrt();
        println!("{label:60} ∫pdf = {integral:.5}, kept {p:.5}");
        assert!(
            (integral - p).abs() < 4.0 * sd + 2e-3,
            "{label}: ∫pdf {integral} vs kept {p}"
        );
    }
}

/// The cells of each χ² grid (24 × 24 per lobe hemisphere).
const RES: usize = 24;

/// The reference lobe of the χ² cells: as wide as the BSDF's, within [0.15, 0.5] (at grazing
/// incidence the reflection lobe is squashed against the horizon: wider cells there
/// integrated the pdf only to 4e-3 at α = 1).
fn reference_alpha(alpha: f64) -> f64 {
    (1.5 * alpha).clamp(0.15, 0.5)
}

/// The sampled directions of several BSDFs on one distribution as a quadrature (per BSDF
/// `etas[b]`: None for a conductor, Some(η) for a dielectric): the visible-normal density on
/// a 2500 × 2500 midpoint grid of GGX's D·cos warp about the normal (at `reference`, the
/// smaller α: a node every few hundredths of the lobe's width near the normal, where the
/// Exponential NDF has its cusp), each node carried to its reflected and refracted
/// directions with weights R and T (a conductor: the reflection, weight 1; the sampler's own
/// rejections dropped), and handed to `node(b, wi, weight)`. One pass for every BSDF (the
/// visible density, the grid's cost, is theirs in common).
///
/// Why: for narrow lobes at grazing incidence the transmitted angle is stationary at the
/// critical angle (the refraction of a ray grazing its facet), so at θo ≥ 80° the pdf of
/// wi has an integrable fold singularity along a curve through the refracted direction. No fixed
/// cell rule integrates that: at α = 0.05, θo = 89°, the cell integrals of the pdf moved by
/// up to 9 % between 64² and 128² cells (and the reflection lobe, squashed against the
/// horizon, lost 4e-3 of its integral at α = 1). Pushed forward from the normals, where the density
/// is smooth, the expected counts need no Jacobian (the pdf function's Jacobian is the one
/// the other configurations and frame.rs's finite differences test); 6·10⁶ nodes leave
/// thousands per cell, so that their binning is exact to ~1 %, below the counts' noise.
fn pushforward<D: MicrofacetDistribution<f64>>(
    dist: &D,
    wo: [f64; 3],
    etas: &[Option<f64>],
    reference: f64,
    node: &mut dyn FnMut(usize, [f64; 3], f64),
) {
    let grid = 2500;
    let coords = AxisCoordinates::new(reference, Vec3::new(0.0, 0.0, 1.0));
    for i in 0..grid {
        // s = 1 − (1 − v)², ds = 2(1 − v) dv: nodes crowd toward the horizon, where the
        // visible density at grazing wo keeps mass (GGX's tail, weighted by w·m/cos θo ≈ 60
        // at 89°: 0.3 % of it lay beyond a uniform grid's last node).
        let v = (i as f64 + 0.5) / grid as f64;
        let s = 1.0 - (1.0 - v) * (1.0 - v);
        for j in 0..grid {
            let u = [s, (j as f64 + 0.5) / grid as f64];
            let (wm, jac) = coords.direction_at(u);
            let wm: [f64; 3] = wm.into();
            let weight = dist.pdf(wo, wm) * jac * 2.0 * (1.0 - v) / (grid * grid) as f64;
            if !(weight > 0.0) {
                continue;
            }
            let wr = microsurface::bsdf::frame::reflect(wo, wm);
            let above = wr[2] * wo[2] > 1e-150;
            for (b, &eta) in etas.iter().enumerate() {
                let r = eta.map_or(1.0, |eta| fresnel::dielectric(dot(wo, wm), eta));
                if above {
                    node(b, wr, weight * r);
                }
                if let Some((wt, _)) = eta.and_then(|eta| refract(wo, wm, eta)) {
                    if wt[2] * wo[2] < -1e-150 {
                        node(b, wt, weight * (1.0 - r));
                    }
                }
            }
        }
    }
}

const ALPHAS: [f64; 3] = [0.05, 0.3, 1.0];
const THETAS: [f64; 4] = [0.0, 45.0, 80.0, 89.0];
const ETAS: [f64; 2] = [1.5, 1.0 / 1.5];
const GRID_TESTS: usize = 5 * 3 * 4 * 2 * (2 + 2 * 2);

fn bsdf_grid(full: bool) {
    let level = sidak(0.01, GRID_TESTS);
    let mut configs = Vec::new();
    for k in 0..5 {
        for (ai, &alpha) in ALPHAS.iter().enumerate() {
            for aniso in [false, true] {
                // The subset: one roughness and one incidence pattern per NDF.
                if !full && (ai != k % 3 || aniso != (k % 2 == 1)) {
                    continue;
                }
                for (ti, &deg) in THETAS.iter().enumerate() {
                    if !full && ti != (k + 1) % 4 && ti != 1 {
                        continue;
                    }
                    configs.push((k, alpha, aniso, deg));
                }
            }
        }
    }
    // The configurations are independent: spread them over the cores.
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    std::thread::scope(|scope| {
        for t in 0..threads {
            let configs = &configs;
            scope.spawn(move || {
                for &(k, alpha, aniso, deg) in configs.iter().skip(t).step_by(threads) {
                    let (ax, ay) = if aniso { (alpha, 0.4 * alpha) } else { (alpha, alpha) };
                    let m = material::<f64>(k, ax, ay);
                    let wo = direction(deg);
                    let n = 100_000;
                    let label = format!("{} α = ({ax}, {ay}) θo = {deg}", NAMES[k]);
                    each!(&m, x => {
                        // Grazing incidence: expected counts pushed forward from the normals
                        // (see `pushforward`).
                        let grazing = wo[2] < 0.2;
                        let etas = [None, Some(ETAS[0]), Some(ETAS[1])];
                        // Per BSDF and lobe side, the expected counts (grazing incidence).
                        let expected: Option<Vec<[Vec<f64>; 2]>> = grazing.then(|| {
                            let cells: Vec<[AxisCoordinates; 2]> = etas
                                .iter()
                                .map(|&e| lobe_axes(wo, e).map(|axis| AxisCoordinates::new(reference_alpha(alpha), axis)))
                                .collect();
                            let mut ex = vec![[vec![0.0; RES * RES], vec![0.0; RES * RES]]; etas.len()];
                            pushforward(x, wo, &etas, ax.min(ay), &mut |b, wi, weight| {
                                for side in 0..2 {
                                    if let Some(c) = cell_of(&cells[b][side], Vec3::from(wi), RES) {
                                        ex[b][side][c] += n as f64 * weight;
                                    }
                                }
                            });
                            ex
                        });
                        let ex = |b: usize| expected.as_ref().map(|e| &e[b]);
                        let c = RoughConductor::new(x.clone(), fresnel::Conductor { eta: [0.2], k: [3.9] });
                        check_bsdf(&format!("conductor {label}"), &c, wo, alpha, None, n, level, ex(0));
                        for (j, eta) in ETAS.into_iter().enumerate() {
                            let d = RoughDielectric::new(x.clone(), eta).unwrap();
                            check_bsdf(&format!("dielectric η = {eta:.3} {label}"), &d, wo, alpha, Some(eta), n, level, ex(j + 1));
                        }
                    });
                }
            });
        }
    });
}

#[test]
fn bsdf_sampling_matches_its_pdf() {
    bsdf_grid(false);
}

#[test]
#[ignore]
fn bsdf_sampling_matches_its_pdf_full() {
    bsdf_grid(true);
}

/// f(wo, wi) = f(wi, wo) for conductors; for dielectrics (radiance transport) the
/// generalised reciprocity f(wi, wo) = η'² f(wo, wi), η' relative to wo, and symmetry for
/// importance transport f(wi, wo) = f(wo, wi)·η'²/η'² ... the same relation without the
/// radiance factor (checked through radiance transport only).
#[test]
fn reciprocity() {
    let mut rng = SplitMix64(3);
    for k in 0..5 {
        let m = material::<f64>(k, 0.4, if k == 4 { 0.4 } else { 0.2 });
        each!(&m, x => {
            let c = RoughConductor::new(x.clone(), fresnel::Schlick { f0: [0.9, 0.6, 0.3] });
            let d = RoughDielectric::new(x.clone(), 1.5).unwrap();
            let mut checked = 0;
            for _ in 0..4000 {
                let (wo, wi) = (random_direction(&mut rng), random_direction(&mut rng));
                let (a, b) = (c.eval(wo, wi), c.eval(wi, wo));
                for ch in 0..3 {
                    assert!(rel(a[ch], b[ch]) < 1e-12 || (a[ch] - b[ch]).abs() < 1e-300, "{}: {a:?} {b:?}", NAMES[k]);
                }
                let (f, g) = (d.eval(wo, wi)[0], d.eval(wi, wo)[0]);
                if f > 0.0 {
                    checked += 1;
                    let etap: f64 = if wo[2] * wi[2] > 0.0 { 1.0 } else if wo[2] > 0.0 { 1.5 } else { 1.0 / 1.5 };
                    // (Rounding magnified by the cancellation in wi·wm + wo·wm/η' near
                    // the lobe's edge: measured up to 1e-8 in 10⁵ pairs.)
                    assert!(rel(g, etap * etap * f) < 1e-7, "{}: {f} {g} η' {etap}", NAMES[k]);
                } else {
                    assert_eq!(g, 0.0);
                }
            }
            assert!(checked > 1000);
        });
    }
}

/// Energy: every sample's weight f|cos θi|/pdf is G2/G1(wo) ≤ 1 for the F = 1 conductor and
/// for the dielectric under importance transport (the Fresnel choice cancels R or T), so
/// ∫ f cos ≤ 1 everywhere; and the white-furnace albedo by sampling matches ∫ f cos by
/// quadrature-free Monte Carlo over the sphere (two estimators of one integral).
#[test]
fn single_scattering_loses_energy_never_gains() {
    let mut rng = SplitMix64(11);
    for k in 0..5 {
        for alpha in [0.05, 0.3, 1.0] {
            let m = material::<f64>(k, alpha, alpha);
            each!(&m, x => {
                let c = RoughConductor::new(x.clone(), One::<1>);
                let d = RoughDielectric::new(x.clone(), 1.5).unwrap().with_transport(Transport::Importance);
                for deg in [0.0, 45.0, 80.0, 89.0] {
                    let wo = direction(deg);
                    let (mut e_c, mut e_d, mut v_c) = (0.0, 0.0, 0.0);
                    let n = 20_000;
                    for _ in 0..n {
                        let (uc, u) = (rng.next_f64(), [rng.next_f64(), rng.next_f64()]);
                        if let Some(s) = c.sample(wo, uc, u) {
                            let wgt: f64 = s.f[0] * s.wi[2].abs() / s.pdf;
                            assert!(wgt <= 1.0 + 1e-9, "{} conductor weight {wgt}", NAMES[k]);
                            e_c += wgt;
                            v_c += wgt * wgt;
                        }
                        if let Some(s) = d.sample(wo, uc, u) {
                            let wgt = s.f[0] * s.wi[2].abs() / s.pdf;
                            assert!(wgt <= 1.0 + 1e-9, "{} dielectric weight {wgt}", NAMES[k]);
                            e_d += wgt;
                        }
                    }
                    let nf = n as f64;
                    let (e_c, e_d) = (e_c / nf, e_d / nf);
                    let var_c = (v_c / nf - e_c * e_c) / nf;
                    assert!(e_c <= 1.0 && e_d <= 1.0 && e_c > 0.1, "{} {alpha} {deg}: {e_c} {e_d}", NAMES[k]);
                    // The same albedo from cosine-weighted directions over the hemisphere
                    // (an independent estimator of ∫ f cos: eval only), within 5 standard
                    // errors of the two.
                    let (mut e_u, mut v_u) = (0.0, 0.0);
                    for _ in 0..n {
                        let (r, phi) = (rng.next_f64().sqrt(), std::f64::consts::TAU * rng.next_f64());
                        let wi = [r * phi.cos(), r * phi.sin(), (1.0 - r * r).max(0.0).sqrt()];
                        let x = c.eval(wo, wi)[0] * std::f64::consts::PI;
                        e_u += x;
                        v_u += x * x;
                    }
                    let e_u = e_u / nf;
                    let var_u = (v_u / nf - e_u * e_u) / nf;
                    let sd = (var_u + var_c).sqrt();
                    // (At α = 0.05 cosine-weighted directions rarely find the lobe, and the
                    // estimator's own variance estimate is then meaningless.)
                    assert!(alpha < 0.3 || (e_u - e_c).abs() < 5.0 * sd + 1e-3, "{} {alpha} {deg}: {e_u} vs {e_c} (σ {sd:.1e})", NAMES[k]);
                }
            });
        }
    }
}

/// Below α = 1e-3 the BSDFs are delta lobes (pbrt-v4's EffectivelySmooth).
#[test]
fn the_smooth_limit() {
    let wo = normalize([0.3, 0.2, 0.9]);
    let m = Microfacet::<f64, Ggx>::new(1e-4, 1e-4).unwrap();
    let metal = fresnel::Conductor {
        eta: [0.2],
        k: [3.9],
    };
    let c = RoughConductor::new(m.clone(), metal);
    let s = c.sample(wo, 0.5, [0.3, 0.3]).unwrap();
    assert!(s.specular && s.lobe == Lobe::Reflection && s.pdf == 1.0);
    assert_eq!(s.wi, [-wo[0], -wo[1], wo[2]]);
    assert!(rel(s.f[0] * s.wi[2], fresnel::conductor(wo[2], 0.2, 3.9)) < 1e-15);
    assert_eq!(c.eval(wo, s.wi), [0.0]);
    assert_eq!(c.pdf(wo, s.wi), 0.0);
    let d = RoughDielectric::new(m, 1.5).unwrap();
    let r = fresnel::dielectric(wo[2], 1.5);
    let s = d.sample(wo, 0.99, [0.3, 0.3]).unwrap();
    assert!(s.specular && s.lobe == Lobe::Transmission && rel(s.pdf, 1.0 - r) < 1e-15);
    assert!(rel(s.f[0] * s.wi[2].abs() * 1.5 * 1.5, 1.0 - r) < 1e-14);
    let s = d.sample(wo, 0.0, [0.3, 0.3]).unwrap();
    assert!(s.specular && s.lobe == Lobe::Reflection && rel(s.pdf, r) < 1e-15);
}

/// The BSDFs over the exact path agree with the fast ones (eval and pdf), and Mitsuba's
/// separable G2 is G1 G1.
#[test]
fn exact_and_fast_bsdfs_agree() {
    let mut rng = SplitMix64(5);
    for k in 0..5 {
        let m = material::<f64>(k, 0.35, if k == 4 { 0.35 } else { 0.15 });
        let ex = exact(&m);
        each!(&m, x => {
            let a = RoughConductor::new(x.clone(), One::<1>).with_masking(Masking::Separable);
            let b = RoughConductor::new(ex, One::<1>).with_masking(Masking::Separable);
            let c = RoughDielectric::new(x.clone(), 1.33).unwrap();
            let e = RoughDielectric::new(ex, 1.33).unwrap();
            let tol = if k <= 1 { 1e-10 } else { 1e-6 };
            for _ in 0..2000 {
                let (wo, wi) = (random_direction(&mut rng), random_direction(&mut rng));
                assert!(rel(a.eval(wo, wi)[0], b.eval(wo, wi)[0]) < tol || b.eval(wo, wi)[0] < 1e-300);
                assert!(rel(a.pdf(wo, wi), b.pdf(wo, wi)) < tol || b.pdf(wo, wi) < 1e-300);
                assert!(rel(c.eval(wo, wi)[0], e.eval(wo, wi)[0]) < tol || e.eval(wo, wi)[0] < 1e-300);
                assert!(rel(c.pdf(wo, wi), e.pdf(wo, wi)) < tol || e.pdf(wo, wi) < 1e-300);
                let g = x.g2_separable(wo, wi);
                assert!(rel(g, x.g1(wo) * x.g1(wi)) < 1e-15);
            }
        });
    }
}

/// The compensated conductors (Kulla & Conty's added lobe sampled with probability 1 − E(μo),
/// Turquin's scaled lobe): χ² of sampling against the pdf over the sphere, every NDF, as the
/// single-scattering BSDFs above.
#[test]
fn compensated_sampling_matches_its_pdf() {
    use microsurface::scattering::{CompensatedConductor, Scheme};
    let level = sidak(0.01, 5 * 2 * 2 * 2);
    for k in 0..5 {
        let m = material::<f64>(k, 0.6, 0.6);
        each!(&m, x => {
            for scheme in [Scheme::KullaConty, Scheme::Turquin] {
                let b = CompensatedConductor::new(x.clone(), fresnel::Conductor { eta: [0.2], k: [3.9] }, scheme);
                let wo = direction(45.0);
                let label = format!("{} compensated {scheme:?} α = 0.6 θo = 45", NAMES[k]);
                check_bsdf(&label, &b, wo, 0.6, None, 100_000, level, None);
            }
        });
    }
}

/// The compensated dielectrics (Kulla & Conty's two-sided added lobes, sampled with
/// probability 1 − E(μo), transmission within them with probability k): χ² of sampling
/// against the pdf over the sphere, every NDF, from outside and from inside. The cells are on the hemispheres about ±z, not about the lobes: the added
/// lobes are cosine lobes on both sides, whose kink at the horizon the cell rule integrates
/// only to ~1e-2 where a lobe axis's hemisphere straddles it (∫pdf 0.379 against a sampled
/// fraction of 0.365 for Double GGX, whose added share is large); about ±z the horizon is
/// the cells' edge.
#[test]
fn compensated_dielectric_sampling_matches_its_pdf() {
    use microsurface::scattering::{CompensatedDielectric, DielectricTables, Scheme};
    let level = sidak(0.01, 5 * 2 * 2);
    for k in 0..5 {
        let m = material::<f64>(k, 0.6, 0.6);
        each!(&m, x => {
            let tables = DielectricTables::new(x, 1.5);
            // (Turquin's sampling is the single-scattering interface's, χ²-tested above.)
            for scheme in [Scheme::KullaConty] {
                let b = CompensatedDielectric::from_tables(x.clone(), 1.5, scheme, tables.clone()).unwrap();
                for z in [1.0, -1.0] {
                    let w = direction(45.0);
                    let wo = [w[0], w[1], z * w[2]];
                    let label = format!("{} compensated dielectric {scheme:?} α = 0.6 wo.z = {:.2}", NAMES[k], wo[2]);
                    let axes = [Vec3::new(0.0, 0.0, 1.0), Vec3::new(0.0, 0.0, -1.0)];
                    check_bsdf_axes(&label, &b, wo, 0.6, Some(1.5), axes, 100_000, level, None);
                }
            }
        });
    }
}

/// `Masking::CorrelatedBeta`, a transmission's exact height-correlated G2 = B(1 + Λo, 1 + Λi):
/// its G2 against the integral that defines it, ∫₀¹ c^Λo (1 − c)^Λi dc (the library's
/// tanh-sinh rule, where both Λ ≤ 50: beyond, the integrand is a spike at an end point),
/// and 1/(1 + Λo + Λi) for a reflection; the dielectric's reflected f and every pdf
/// bit-identical to the default's (the masking changes transmitted f only), transmitted f
/// the default's times the ratio of the two G2 (where f is a normal number of F); f ≥ 0 and
/// finite; a sample's f and pdf those of eval and pdf at its wi, as closely as the default's
/// are (in f32 the BSDF's own rounding, the half vector recomputed from a rounded wi near a
/// lobe's edge, reaches 1.5e-3 for both); sample weights f|cos θi|/pdf ≤ 1 (importance
/// transport: a refraction's weight is (1 + Λo) B ≤ 1). Every NDF, η = 1.5 and 1/1.5, f64
/// and f32.
#[test]
fn correlated_beta_masking() {
    /// `tol_ratio`: f against the default's times the G2 ratio (the rounding of a few
    /// products); `tol_sample`: how much further from eval and pdf a sample may be than the
    /// default's same sample.
    fn check<F: Real>(tol_ratio: f64, tol_sample: f64) {
        // (Below, f is subnormal in F and its relative rounding unbounded.)
        let normal = if F::IS_F32 { 1e-30 } else { 1e-300 };
        let mut rng = SplitMix64(17);
        let (mut worst_ratio, mut worst_sample, mut excess) = (0.0f64, 0.0f64, 0.0f64);
        for k in 0..5 {
            for alpha in [0.3, 1.0] {
                let m = material::<F>(k, F::from_f64(alpha), F::from_f64(alpha));
                each!(&m, x => {
                    for eta in [1.5, 1.0 / 1.5] {
                        let a = RoughDielectric::new(x.clone(), F::from_f64(eta)).unwrap()
                            .with_transport(Transport::Importance);
                        let b = a.clone().with_masking(Masking::CorrelatedBeta);
                        let mut refracted = 0;
                        for _ in 0..3000 {
                            let wo = random_direction(&mut rng).map(F::from_f64);
                            let wi = random_direction(&mut rng).map(F::from_f64);
                            let (fa, fb) = (a.eval(wo, wi)[0].to_f64(), b.eval(wo, wi)[0].to_f64());
                            assert!(fb.is_finite() && fb >= 0.0, "{} f {fb}", NAMES[k]);
                            assert_eq!(a.pdf(wo, wi).to_f64().to_bits(), b.pdf(wo, wi).to_f64().to_bits());
                            let gb = Masking::CorrelatedBeta.g2(x, wo, wi).to_f64();
                            let gc = Masking::Correlated.g2(x, wo, wi).to_f64();
                            if wo[2] * wi[2] > F::ZERO {
                                assert_eq!(fa.to_bits(), fb.to_bits());
                                assert_eq!(gb.to_bits(), gc.to_bits());
                                continue;
                            }
                            let (lo, li) = (x.lambda(wo).to_f64(), x.lambda(wi).to_f64());
                            // (B ≤ 1/(1 + Λo + Λi); the two are rounded separately in f32.)
                            assert!((0.0..=1.0).contains(&gb) && gb <= gc * (1.0 + 1e-6), "{} B {gb} > {gc}", NAMES[k]);
                            if !F::IS_F32 && lo <= 50.0 && li <= 50.0 {
                                let q = microsurface::check::quad::integrate(
                                    |c| if c > 0.0 && c < 1.0 { (lo * c.ln() + li * (-c).ln_1p()).exp() } else { 0.0 },
                                    0.0,
                                    1.0,
                                    1e-13,
                                )
                                .value;
                                assert!(rel(gb, q) < 1e-11, "{} Λ = ({lo}, {li}): B {gb} vs ∫ {q}", NAMES[k]);
                            }
                            if fa > normal {
                                refracted += 1;
                                worst_ratio = worst_ratio.max(rel(fb, fa * gb / gc));
                            }
                        }
                        assert!(refracted > 100, "{} η = {eta}: {refracted}", NAMES[k]);
                        for _ in 0..3000 {
                            let wo = random_direction(&mut rng).map(F::from_f64);
                            let (uc, u) = (F::from_f64(rng.next_f64()), [rng.next_f64(), rng.next_f64()].map(F::from_f64));
                            let (Some(s), Some(t)) = (b.sample(wo, uc, u), a.sample(wo, uc, u)) else {
                                continue;
                            };
                            let (f, p) = (s.f[0].to_f64(), s.pdf.to_f64());
                            assert!(f.is_finite() && f >= 0.0 && p > 0.0 && p.is_finite());
                            assert!(f * s.wi[2].to_f64().abs() / p <= 1.0 + tol_sample, "{} weight", NAMES[k]);
                            let e = rel(f, b.eval(wo, s.wi)[0].to_f64()).max(rel(p, b.pdf(wo, s.wi).to_f64()));
                            let e_default = rel(t.f[0].to_f64(), a.eval(wo, t.wi)[0].to_f64())
                                .max(rel(t.pdf.to_f64(), a.pdf(wo, t.wi).to_f64()));
                            worst_sample = worst_sample.max(e);
                            excess = excess.max(e - e_default);
                        }
                    }
                });
            }
        }
        println!(
            "{}: f against the default's times the G2 ratio within {worst_ratio:.1e}; samples against eval and pdf within {worst_sample:.1e}, {excess:.1e} beyond the default's",
            if F::IS_F32 { "f32" } else { "f64" }
        );
        assert!(
            worst_ratio < tol_ratio && excess < tol_sample,
            "{worst_ratio:e} {excess:e}"
        );
    }
    check::<f64>(1e-14, 1e-10);
    check::<f32>(1e-6, 1e-5);
}

/// `Masking::CorrelatedBeta` toward the horizon (Λ up to ~1e300 in f64, ~1e30 in f32): G2
/// in [0, 1], the dielectric's eval, pdf and samples finite and ≥ 0 for wo and wi from 1e-300
/// (f64) or 1e-30 (f32) of the horizon to normal, both sides; every NDF at α = 0.3 and 1.
/// (Λ = ∞ itself, B = 0, is `special::beta_1p`'s unit test.)
#[test]
fn correlated_beta_at_the_horizon() {
    fn check<F: Real>(zs: &[f64]) {
        let dirs: Vec<[F; 3]> = zs
            .iter()
            .flat_map(|&z| [z, -z])
            .enumerate()
            .map(|(i, z)| {
                let phi = 0.7 * i as f64;
                let s = ((1.0 - z) * (1.0 + z)).sqrt();
                [s * phi.cos(), s * phi.sin(), z].map(F::from_f64)
            })
            .collect();
        for k in 0..5 {
            for alpha in [0.3, 1.0] {
                let m = material::<F>(k, F::from_f64(alpha), F::from_f64(alpha));
                each!(&m, x => {
                    let b = RoughDielectric::new(x.clone(), F::from_f64(1.5)).unwrap()
                        .with_masking(Masking::CorrelatedBeta);
                    for &w in &dirs {
                        for &v in &dirs {
                            let g = Masking::CorrelatedBeta.g2(x, w, v).to_f64();
                            assert!((0.0..=1.0).contains(&g), "{} {:?} {:?}: G2 {g}", NAMES[k], w.map(F::to_f64), v.map(F::to_f64));
                            let (f, p) = (b.eval(w, v)[0].to_f64(), b.pdf(w, v).to_f64());
                            assert!(f.is_finite() && f >= 0.0 && p.is_finite() && p >= 0.0, "{}: f {f} pdf {p}", NAMES[k]);
                        }
                        for u in [[0.5, 0.5], [0.999, 0.01], [1e-7, 0.3]] {
                            for uc in [0.0, 0.5, 0.999] {
                                if let Some(s) = b.sample(w, F::from_f64(uc), u.map(F::from_f64)) {
                                    let (f, p) = (s.f[0].to_f64(), s.pdf.to_f64());
                                    assert!(f.is_finite() && f >= 0.0 && p > 0.0 && p.is_finite(), "{}: sample f {f} pdf {p}", NAMES[k]);
                                }
                            }
                        }
                    }
                });
            }
        }
    }
    check::<f64>(&[1e-300, 1e-160, 1e-40, 1e-20, 1e-10, 1e-4, 0.05, 1.0]);
    check::<f32>(&[1e-30, 1e-17, 1e-10, 1e-4, 0.05, 1.0]);
}

/// The albedo of `Masking::CorrelatedBeta`'s dielectric (η = 1.5, importance transport, both
/// sides, μ from grazing to normal): the quadrature over the normal
/// (`single_scattering_albedo_dielectric_level`) at level 4 against level 5 within 3e-5, and
/// against a Monte Carlo estimate from the BSDF's own samples within 4σ, reflection and
/// transmission, every NDF at α = 0.5 and 1; and GGX's against the random walk's order 1
/// (its next-event-free albedo by order, `scattering::albedo`) within 4 combined σ, where the
/// default (pbrt-v4's 1/(1 + Λo + Λi)) is hundreds of σ away at μ = 0.05 (tests/walk.rs
/// holds the quadrature to the walk over a grid of every NDF at μ ≥ 0.15).
#[test]
fn correlated_beta_albedo_is_the_walks_order_one() {
    use microsurface::scattering::{
        albedo, single_scattering_albedo_dielectric_level as quadrature, DielectricFacets, Heights,
        RandomWalk,
    };
    let mut rng = SplitMix64(23);
    for k in 0..5 {
        for alpha in [0.5, 1.0] {
            let m = material::<f64>(k, alpha, alpha);
            each!(&m, x => {
                let b = RoughDielectric::new(x.clone(), 1.5).unwrap()
                    .with_transport(Transport::Importance)
                    .with_masking(Masking::CorrelatedBeta);
                for mu in [0.05f64, 0.5, 1.0] {
                    for z in [1.0, -1.0] {
                        let wo = [(1.0 - mu * mu).sqrt() * 0.6, (1.0 - mu * mu).sqrt() * 0.8, z * mu];
                        let (r4, t4) = quadrature(x, wo, 1.5, Masking::CorrelatedBeta, 4);
                        let (r5, t5) = quadrature(x, wo, 1.5, Masking::CorrelatedBeta, 5);
                        assert!(
                            (r4 - r5).abs() < 3e-5 && (t4 - t5).abs() < 3e-5,
                            "{} α={alpha} wo={wo:?}: level 4 ({r4}, {t4}) vs 5 ({r5}, {t5})", NAMES[k]
                        );
                        let n = 50_000;
                        let (mut s, mut s2) = ([0.0; 2], [0.0; 2]);
                        for _ in 0..n {
                            let (uc, u) = (rng.next_f64(), [rng.next_f64(), rng.next_f64()]);
                            if let Some(x) = b.sample(wo, uc, u) {
                                let w = x.f[0] * x.wi[2].abs() / x.pdf;
                                let side = usize::from(x.wi[2] * wo[2] < 0.0);
                                s[side] += w;
                                s2[side] += w * w;
                            }
                        }
                        let nf = n as f64;
                        for (side, q) in [r5, t5].into_iter().enumerate() {
                            let m = s[side] / nf;
                            let sd = ((s2[side] / nf - m * m).max(0.0) / nf).sqrt();
                            assert!(
                                (m - q).abs() <= 4.0 * sd + 1e-6,
                                "{} α={alpha} wo={wo:?} {}: quadrature {q} vs Monte Carlo {m} (σ {sd:.1e})",
                                NAMES[k], ["reflection", "transmission"][side]
                            );
                        }
                        if k != 0 {
                            continue;
                        }
                        // GGX: the BSDF's transmitted albedo against the walk's order 1.
                        let walk = RandomWalk::new(x.clone(), Heights::Uniform);
                        let walks = 200_000;
                        let a = albedo(&walk, &DielectricFacets::new(1.5).unwrap(), wo, walks, 29);
                        let m = s[1] / nf;
                        // (A walk's weight is ≤ 1, so one walk moves the estimate by ≤ 1/walks:
                        // the floor of its error where it saw no transmission at all, as from
                        // inside at α = 1, μ = 0.05, where the albedo is 1e-6.)
                        let sd_walk = a.transmit.stderr[0].max(1.0 / walks as f64);
                        let sd = (((s2[1] / nf - m * m).max(0.0) / nf) + sd_walk * sd_walk).sqrt();
                        let (_, t_default) = quadrature(x, wo, 1.5, Masking::Correlated, 4);
                        println!(
                            "GGX α={alpha} μ={:5}: transmitted {m:.5} (BSDF), {:.5} ± {:.1e} (walk order 1; combined σ {sd:.1e}), default {t_default:.5} ({:.0}σ away)",
                            wo[2], a.transmit.orders[0], a.transmit.stderr[0], (t_default - a.transmit.orders[0]) / sd
                        );
                        assert!(
                            (m - a.transmit.orders[0]).abs() <= 4.0 * sd + 1e-6,
                            "α={alpha} wo={wo:?}: BSDF {m} vs walk {} (σ {sd:.1e})", a.transmit.orders[0]
                        );
                        if mu == 0.05 {
                            assert!((t_default - a.transmit.orders[0]).abs() > 100.0 * sd, "the default's gap at α={alpha} wo={wo:?}");
                        }
                    }
                }
            });
        }
    }
}

/// `Bsdf::eval_pdf` is (eval, pdf) bit for bit: every NDF through the run-time door, f32 and
/// f64, isotropic and anisotropic, a gold conductor (its override), a dielectric (the
/// default), over random pairs of directions with the horizon and the pole among them.
#[test]
fn eval_pdf_is_eval_and_pdf_bit_for_bit() {
    fn run<F: Real>() {
        let mut rng = SplitMix64(0xe7a1_9df0);
        let gold = fresnel::Conductor {
            eta: [0.18, 0.42, 1.37].map(F::from_f64),
            k: [3.42, 2.35, 1.77].map(F::from_f64),
        };
        fn check<F: Real>(b: &impl Bsdf<F, Value = [F; 3]>, wo: [F; 3], wi: [F; 3], kind: NdfKind) {
            let same = |a: F, b: F| a.to_f64().to_bits() == b.to_f64().to_bits();
            let (f, p) = b.eval_pdf(wo, wi);
            let (fe, pe) = (b.eval(wo, wi), b.pdf(wo, wi));
            assert!(
                same(p, pe) && (0..3).all(|k| same(f[k], fe[k])),
                "{kind} {:?} {:?}",
                wo.map(F::to_f64),
                wi.map(F::to_f64)
            );
        }
        for kind in NdfKind::ALL {
            let shape = kind.shape_name().map(|n| if n == "a" { 0.7 } else { 2.5 });
            for (ax, ay) in [(0.3, 0.3), (0.05, 0.6)] {
                let Ok(m) = AnyMicrofacet::<F>::new(kind, F::from_f64(ax), F::from_f64(ay), shape)
                else {
                    continue; // (GTR is isotropic but at γ = 2)
                };
                let c = RoughConductor::new(m.clone(), gold);
                let d = RoughDielectric::new(m, F::from_f64(1.5)).unwrap();
                for i in 0..400 {
                    let wo = random_direction(&mut rng);
                    let wi = match i % 4 {
                        0 => [-wo[0], -wo[1], wo[2]],
                        1 => [wo[0], wo[1], 0.0],
                        _ => random_direction(&mut rng),
                    };
                    let (wo, wi) = (wo.map(F::from_f64), wi.map(F::from_f64));
                    check(&c, wo, wi, kind);
                    check(&d, wo, wi, kind);
                }
            }
        }
    }
    run::<f32>();
    run::<f64>();
}
