//! χ² goodness-of-fit of every sampler: D·cos and visible normals, for every NDF with
//! directions (Beckmann, GGX, Double GGX, Exponential; isotropic and anisotropic; GTR's D·cos),
//! α ∈ {0.05, 0.3, 1.0, 2.0}, incidence {0°, 45°, 80°, 89°}. Each test also checks that the
//! pdf integrates to 1 over the sphere and that every sample is a finite upper-hemisphere unit
//! vector. Significance 0.01 overall, Šidák-corrected over all tests of this file.
//!
//! `cargo test` runs a fast subset; the full sweep is `#[ignore]`d and run by .ci/run
//! (`cargo test --release -- --ignored`).

use microsurface::check::chi2::{chi2_test, sidak, Coordinates, DcosCoordinates, TailCoordinates};
use microsurface::sampling::{pdf_dcos, sample_dcos};
use microsurface::{
    AnyNdf, Exact, Gtr, Microfacet, MicrofacetDistribution, Ndf, NdfKind, UnitSlopes, Vec3,
};

const KINDS: [NdfKind; 4] = [
    NdfKind::Beckmann,
    NdfKind::Ggx,
    NdfKind::DoubleGgx,
    NdfKind::Exponential,
];
const ALPHAS: [f64; 4] = [0.05, 0.3, 1.0, 2.0];
const INCIDENCE_DEG: [f64; 4] = [0.0, 45.0, 80.0, 89.0];
/// Upper bound on the number of tests in this file (for the Šidák correction).
/// (The last terms: the family sweep, 96; the heavy-tail cases, 3; the posterior's range
/// ends, 8; the fast Beckmann warp, 4 × 4 × 3 in the sweep and 2 × 4 in the subset.)
const TESTS: usize = 4 * 4 * 2 * (4 + 1)
    + 4 * 5
    + 4 * 3
    + 4 * 4 * 4
    + 4
    + 4 * 4 * 2
    + 3 * 32
    + 6
    + 12
    + 12 * 2 * 4
    + 96
    + 3
    + 8
    + 4 * 4 * 3
    + 2 * 4;

fn direction(deg: f64) -> Vec3 {
    let t = deg.to_radians();
    // A generic azimuth, so that anisotropic tests are not aligned with the axes.
    Vec3::new(t.sin() * 0.8, t.sin() * 0.6, t.cos())
}

/// The reference coordinates: GGX's D·cos warp at 1.5 times the roughness (heavy tails, a
/// different warp from every sampler under test).
fn reference(ax: f64, ay: f64) -> Exact {
    Exact::new(NdfKind::Ggx, 1.5 * ax, 1.5 * ay, None).unwrap()
}

fn check(label: &str, r: microsurface::check::chi2::Chi2) {
    check_with(label, r, 1e-4)
}

/// `pdf_tol`: how well the cell rule integrates the pdf (see `check`).
fn check_with(label: &str, r: microsurface::check::chi2::Chi2, pdf_tol: f64) {
    let level = sidak(0.01, TESTS);
    println!(
        "{label:50} χ² = {:9.1} dof = {:4} p = {:.3e}  ∫pdf = {:.6}",
        r.statistic, r.dof, r.p_value, r.pdf_integral
    );
    assert_eq!(r.bad_samples, 0, "{label}: bad samples");
    // The cell rule (33 × 33 tanh-sinh nodes) integrates the visible pdf's kink at w·m = 0
    // to ~3e-5 at grazing incidence; a sampler whose pdf is not normalised fails far above.
    assert!(
        (r.pdf_integral - 1.0).abs() < pdf_tol,
        "{label}: ∫ pdf = {}",
        r.pdf_integral
    );
    assert!(
        r.p_value > level,
        "{label}: p = {:e} < {level:e}",
        r.p_value
    );
}

/// χ² of a visible-normal sampler against max(0, wi·m) D(m)/σ(wi), built from the exact
/// path's own D and σ (so the sampler's pdf code is not what it is tested against).
fn check_visible(
    label: &str,
    m: &Exact,
    wi: Vec3,
    coords: &Exact,
    n: usize,
    seed: u64,
    sample: impl FnMut([f64; 2]) -> Vec3,
) {
    check_visible_in(label, m, wi, &DcosCoordinates(coords), n, seed, sample);
}

fn check_visible_in(
    label: &str,
    m: &Exact,
    wi: Vec3,
    coords: &impl Coordinates,
    n: usize,
    seed: u64,
    mut sample: impl FnMut([f64; 2]) -> Vec3,
) {
    let sigma = m.sigma(wi.into());
    let pdf = |wm: Vec3| {
        let d = wi.dot(wm);
        if d <= 0.0 {
            0.0
        } else {
            d * m.d(wm.into()) / sigma
        }
    };
    check(label, chi2_test(&mut sample, pdf, coords, n, 24, seed));
}

fn run_stretched(kind: NdfKind, ax: f64, ay: f64, deg: Option<f64>, n: usize) {
    let m = Exact::new(kind, ax, ay, None).unwrap();
    let coords = reference(ax, ay);
    let c = DcosCoordinates(&coords);
    let seed = (ax * 1e3) as u64 ^ ((ay * 1e5) as u64) << 8 ^ kind as u64;
    match deg {
        None => check(
            &format!("{kind:?} α=({ax},{ay}) D·cos"),
            chi2_test(
                |u| m.sample_dcos(u).wm.into(),
                |w| m.pdf_dcos(w.into()),
                &c,
                n,
                24,
                seed,
            ),
        ),
        Some(deg) => {
            let wi = direction(deg);
            check_visible(
                &format!("{kind:?} α=({ax},{ay}) visible θi={deg}°"),
                &m,
                wi,
                &coords,
                n,
                seed + deg as u64,
                |u| m.sample_wm(wi.into(), u).into(),
            );
        }
    }
}

fn samples(kind: NdfKind) -> usize {
    match kind {
        NdfKind::Beckmann | NdfKind::Ggx => 200_000,
        _ => 20_000,
    }
}

/// The rest of the family through the exact path (radial visible inversion on the stretched
/// α = 1 member): D·cos and visible normals against the exact D and σ.
fn run_family(kind: NdfKind, shape: Option<f64>, ax: f64, ay: f64, deg: Option<f64>, n: usize) {
    let m = Exact::new(kind, ax, ay, shape).unwrap();
    // Where D(1) = ∞ (Ei, Erfc, K0, Bessel-K a ≤ 1) GGX's coordinates put a log singularity
    // along the whole edge u₀ = 0 (the pole) that the cell rule does not integrate (Ei failed
    // with χ² = 1020 on 336 dof while its quantile, CDF and D agree with mpmath): there the
    // coordinates are the same NDF's D·cos warp at 1.5 times the roughness (same singularity,
    // a finite density ratio; still a different warp from the sampler's).
    // Student-T's power-law tail too (γ = 1.55: P22 ~ r^{−3.1}): in GGX's coordinates at
    // α = 0.05 its grazing mass lies in the last row of cells, which the cell rule
    // under-integrates (∫pdf = 0.937 at θi = 80°). Its visible normals are tested in
    // TailCoordinates (GGX's D·cos mass counted from the horizon, raised to the power
    // q = 1/(γ − 3/2), which bounds the visible density there): in D·cos coordinates the
    // visible density grows like 1/cos θm toward the horizon relative to them, a (1 − s)^−0.9
    // singularity at the grid's edge that f64 cannot resolve (∫pdf = 0.987 and 0.974 at
    // θi = 80° and 89°, where a direct quadrature in (θ, φ) gives 0.99997).
    // Bessel-K's normals lie at the roughness α√a (its Gamma(a) mixing puts β² = α² t at
    // t ~ a): at a = 100, α = 0.05 GGX's coordinates at 1.5α put them in the last rows of
    // cells, which the cell rule under-integrated (∫pdf = 1.000165 with p = 0.34): there the
    // coordinates are GGX's at 1.5α√a.
    let singular = AnyNdf::new(kind, 1.0, shape).unwrap().d(1.0).is_infinite();
    let coords = if singular || kind == NdfKind::StudentT {
        Exact::new(kind, 1.5 * ax, 1.5 * ay, shape).unwrap()
    } else if let (NdfKind::BesselK, Some(a)) = (kind, shape) {
        reference(ax * a.sqrt(), ay * a.sqrt())
    } else {
        reference(ax, ay)
    };
    let seed = (ax * 1e3) as u64 ^ ((ay * 1e5) as u64) << 8 ^ (kind as u64) << 20;
    let label = format!("{kind:?} {shape:?} α=({ax},{ay})");
    // The generalised exponential below γ = 1: its normals lie at tan θ ~ α (20 ln 2)^{1/γ}
    // (at γ = 0.1 the median is at cos θm ~ 1e-12), out of every reference's D·cos
    // coordinates but the grid's last row: TailCoordinates with q set so that the median
    // normal of the same NDF at 1.5α (its D·cos warp at u = ½) lands at s = ½.
    let tail = match (kind, shape) {
        (NdfKind::GenExponential, Some(g)) if g < 1.0 => {
            let a = 1.5 * ax.max(ay);
            let c = Exact::new(kind, a, a, shape)
                .unwrap()
                .sample_dcos([0.5, 0.0])
                .wm[2];
            let w = a * a * c * c / (a * a * c * c + (1.0 - c) * (1.0 + c));
            Some(TailCoordinates {
                alpha: a,
                q: (w.ln() / 0.5f64.ln()).max(1.0),
            })
        }
        _ => None,
    };
    let dcos = match tail {
        Some(t) => Grid::Tail(t),
        None => Grid::Dcos(DcosCoordinates(&coords)),
    };
    match deg {
        None => check(
            &format!("{label} D·cos"),
            chi2_test(
                |u| m.sample_dcos(u).wm.into(),
                |w| m.pdf_dcos(w.into()),
                &dcos,
                n,
                24,
                seed,
            ),
        ),
        Some(deg) => {
            let wi = direction(deg);
            let label = format!("{label} visible θi={deg}°");
            let sample = |u| m.sample_wm(wi.into(), u).into();
            let visible = match (kind, shape) {
                (NdfKind::StudentT, Some(g)) => Grid::Tail(student_t_tail(g, ax, ay)),
                _ => dcos,
            };
            check_visible_in(&label, &m, wi, &visible, n, seed + deg as u64, sample);
        }
    }
}

/// Student-T's visible normals' coordinates: q = 1/(γ − 3/2) bounds the visible density at
/// the horizon (TailCoordinates), at the reference roughness 1.5α.
fn student_t_tail(gamma: f64, ax: f64, ay: f64) -> TailCoordinates {
    TailCoordinates {
        alpha: 1.5 * ax.max(ay),
        q: (1.0 / (gamma - 1.5)).max(1.0),
    }
}

/// The coordinates of one test: a reference's D·cos warp or tail coordinates.
enum Grid<'a> {
    Dcos(DcosCoordinates<'a>),
    Tail(TailCoordinates),
}

impl Coordinates for Grid<'_> {
    fn unit_of(&self, w: Vec3) -> [f64; 2] {
        match self {
            Grid::Dcos(c) => c.unit_of(w),
            Grid::Tail(c) => c.unit_of(w),
        }
    }
    fn direction_at(&self, u: [f64; 2]) -> (Vec3, f64) {
        match self {
            Grid::Dcos(c) => c.direction_at(u),
            Grid::Tail(c) => c.direction_at(u),
        }
    }
}

/// One shape per family member for the default run: the members whose exact warps take at
/// most ~0.2 ms a sample (BENCHMARKS.md, issue 22; Bessel-K's since its K_ν stopped running
/// to its node cap).
const FAMILY: [(NdfKind, Option<f64>); 6] = [
    (NdfKind::StudentT, Some(1.8)),
    (NdfKind::GenExponential, Some(6.0)),
    (NdfKind::K0, None),
    (NdfKind::Ei, None),
    (NdfKind::Erfc, None),
    (NdfKind::BesselK, Some(2.5)),
];

/// The family's exact samplers in the default run, one shape each: D·cos and visible
/// normals. The shape ranges' ends are in `family_sweep` (and the posterior sampler's in
/// `family_posterior_range_ends`).
#[test]
fn family_fast_subset() {
    for (kind, shape) in FAMILY {
        run_family(kind, shape, 0.3, 0.3, None, 10_000);
        run_family(kind, shape, 0.5, 0.15, Some(60.0), 10_000);
    }
}

/// The family over its shape ranges: the ends of each range, two roughnesses, D·cos and three
/// incidences. By hand (the exact visible samplers of Ei, Erfc and Bessel-K integrate inside
/// their CDF inversions, and Bessel-K a ≤ 1 also its coordinates' warp: its cases take ~4
/// CPU-minutes each; .ci/run skips it for time). `MICROSURFACE_SWEEP=student_t,bessel_k` runs only the NDFs named,
/// `MICROSURFACE_SWEEP=bessel_k=100` one shape of one.
#[test]
#[ignore = "the family's whole grid, many CPU-minutes: run by hand"]
fn family_sweep() {
    let mut cases = Vec::new();
    for (kind, shapes) in [
        (NdfKind::StudentT, vec![Some(1.55), Some(4.0), Some(1e4)]),
        (NdfKind::Ei, vec![None]),
        (NdfKind::Erfc, vec![None]),
        (NdfKind::K0, vec![None]),
        (NdfKind::BesselK, vec![Some(0.1), Some(2.5), Some(100.0)]),
        (
            NdfKind::GenExponential,
            vec![Some(0.1), Some(1.7), Some(20.0)],
        ),
    ] {
        let only = std::env::var("MICROSURFACE_SWEEP").ok();
        for shape in shapes {
            // "name" runs every shape of that NDF, "name=shape" one of them.
            if let Some(only) = &only {
                let this = |k: &str| match k.trim().split_once('=') {
                    Some((name, s)) => name == kind.name() && s.parse::<f64>().ok() == shape,
                    None => k.trim() == kind.name(),
                };
                if !only.split(',').any(this) {
                    continue;
                }
            }
            for (ax, ay) in [(0.05, 0.05), (1.0, 0.4)] {
                for deg in [None, Some(0.0), Some(80.0), Some(89.0)] {
                    cases.push((kind, shape, ax, ay, deg));
                }
            }
        }
    }
    on_every_core(&cases, |&(kind, shape, ax, ay, deg)| {
        run_family(kind, shape, ax, ay, deg, 10_000)
    });
}

/// Student-T's heaviest tail at the smallest roughness, from grazing incidences: the cases
/// that need TailCoordinates (see run_family). By hand: ~10 s on 2 cores (165 s while the
/// warp's tail quadrature near γ = 3/2 ran to its bisection limit, milliseconds a sample);
/// family_sweep includes them.
#[test]
#[ignore = "~10 s: run by hand (family_sweep has these cases)"]
fn student_t_heavy_tail_visible() {
    let cases = [(80.0, 0.05), (89.0, 0.05), (89.0, 1.0)];
    on_every_core(&cases, |&(deg, a)| {
        run_family(NdfKind::StudentT, Some(1.55), a, a, Some(deg), 10_000)
    });
}

#[test]
fn fast_subset() {
    for kind in KINDS {
        run_stretched(kind, 0.3, 0.3, None, samples(kind));
        run_stretched(kind, 0.3, 0.3, Some(45.0), samples(kind));
        run_stretched(kind, 0.5, 0.1, Some(80.0), samples(kind));
    }
}

/// The fast Beckmann visible normals (`Microfacet`'s warp: the table guess and one step of
/// order five, issue 35; and the wavefront slice's lanes) against max(0, wi·m) D(m)/σ(wi) of
/// the exact path: a subset here, the whole grid in [`fast_beckmann_visible_sweep`].
#[test]
fn fast_beckmann_visible() {
    for (ax, ay) in [(0.3, 0.3), (0.5, 0.1)] {
        run_fast_beckmann(ax, ay, 45.0, true);
        run_fast_beckmann(ax, ay, 89.0, false);
    }
}

/// [`fast_beckmann_visible`] over four roughnesses (anisotropic among them) and four
/// incidences, normal and grazing included, f64, f32 and the slice.
#[test]
#[ignore = "full sweep: run by .ci/run with --ignored"]
fn fast_beckmann_visible_sweep() {
    let mut cases = Vec::new();
    for (ax, ay) in [(0.05, 0.05), (0.3, 0.3), (0.5, 0.1), (1.0, 2.0)] {
        for deg in INCIDENCE_DEG {
            cases.push((ax, ay, deg));
        }
    }
    on_every_core(&cases, |&(ax, ay, deg)| {
        run_fast_beckmann(ax, ay, deg, true)
    });
}

/// χ² of the fast Beckmann sampler at (αx, αy) and θi in f64, and with `all` in f32 and
/// through the f64 slice (one element a call: the lanes' arithmetic, not their speed).
fn run_fast_beckmann(ax: f64, ay: f64, deg: f64, all: bool) {
    use microsurface::fast::batch::{beckmann_sample_visible_f64, Vectors, VectorsMut};
    use microsurface::Beckmann;
    let m = Exact::new(NdfKind::Beckmann, ax, ay, None).unwrap();
    let coords = reference(ax, ay);
    let fast = Microfacet::<f64, Beckmann>::new(ax, ay).unwrap();
    let fast32 = Microfacet::<f32, Beckmann>::new(ax as f32, ay as f32).unwrap();
    let wi = direction(deg);
    let seed = 35 + ((ax * 1e3) as u64 ^ (((ay * 1e5) as u64) << 8) ^ ((deg as u64) << 20));
    let n = samples(NdfKind::Beckmann);
    let label = |what: &str| format!("fast Beckmann{what} α=({ax},{ay}) visible θi={deg}°");
    check_visible(&label(""), &m, wi, &coords, n, seed, |u| {
        fast.sample_wm(wi.into(), u).into()
    });
    if !all {
        return;
    }
    let w32 = [wi.x as f32, wi.y as f32, wi.z as f32];
    check_visible(&label(" f32"), &m, wi, &coords, n, seed + 1, |u| {
        let n = fast32.sample_wm(w32, [u[0] as f32, u[1] as f32]);
        // (The harness asks for unit length to 1e-9; an f32 normal is unit to its
        // rounding, ~6e-8.)
        Vec3::new(n[0] as f64, n[1] as f64, n[2] as f64).normalize()
    });
    check_visible(&label(" slice"), &m, wi, &coords, n, seed + 2, |u| {
        let (mut x, mut y, mut z) = ([0.0], [0.0], [0.0]);
        beckmann_sample_visible_f64(
            &fast,
            Vectors {
                x: &[wi.x],
                y: &[wi.y],
                z: &[wi.z],
            },
            &[u[0]],
            &[u[1]],
            VectorsMut {
                x: &mut x,
                y: &mut y,
                z: &mut z,
            },
        );
        Vec3::new(x[0], y[0], z[0])
    });
}

#[test]
fn gtr_dcos() {
    for &a in &ALPHAS {
        for g in [0.5, 1.0, 1.5, 2.0, 3.0] {
            let gtr = Gtr::new(a, g).unwrap();
            let coords = reference(a, a);
            let r = chi2_test(
                |u| sample_dcos(&gtr, u),
                |w| pdf_dcos(&gtr, w),
                &DcosCoordinates(&coords),
                100_000,
                24,
                (a * 1e3) as u64 + (g * 10.0) as u64,
            );
            check(&format!("GTR α={a} γ={g} D·cos"), r);
        }
    }
}

/// GTR's exact visible-normal sampler (the polar inversion of its visible slopes).
fn run_gtr(a: f64, g: f64, deg: f64, samples: usize) {
    use microsurface::Ndf;
    let label = format!("GTR α={a} γ={g}");
    let m = Exact::new(NdfKind::Gtr, a, a, Some(g)).unwrap();
    // GTR with γ ≤ 1 is not specular as α → 0 (derivations.md E): most of its visible area is at
    // grazing normals, which a near-specular reference grid lumps into a few cells.
    let coords = if Gtr::new(a, g).unwrap().d(0.5) > 0.05 {
        reference(1.0, 1.0)
    } else {
        reference(a, a)
    };
    let wi = direction(deg);
    check_visible(
        &format!("{label} visible θi={deg}° (polar inversion)"),
        &m,
        wi,
        &coords,
        samples,
        (a * 1e4) as u64 + deg as u64,
        |u| m.sample_wm(wi.into(), u).into(),
    );
}

#[test]
fn gtr_visible_fast() {
    // (The same polar method on Beckmann, which also has a closed-form sampler, is a unit test
    // of the crate: microsurface.rs.)
    run_gtr(0.3, 1.5, 45.0, 20_000);
    run_gtr(1.7, 0.6, 80.0, 20_000);
}

#[test]
#[ignore = "full sweep: run by .ci/run with --ignored"]
fn gtr_visible_sweep() {
    let mut cases = Vec::new();
    for &a in &ALPHAS {
        for g in [0.5, 1.0, 1.5, 2.5] {
            for deg in INCIDENCE_DEG {
                cases.push((a, g, deg));
            }
        }
    }
    on_every_core(&cases, |&(a, g, deg)| run_gtr(a, g, deg, 20_000));
}

/// Runs `f` on each case, the cases spread over the cores (they are independent; each
/// test keeps its own seed, so the results do not depend on the thread count).
fn on_every_core<T: Sync>(cases: &[T], f: impl Fn(&T) + Sync) {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    std::thread::scope(|scope| {
        for t in 0..threads {
            let f = &f;
            scope.spawn(move || cases.iter().skip(t).step_by(threads).for_each(f));
        }
    });
}

#[test]
#[ignore = "full sweep: run by .ci/run with --ignored"]
fn full_sweep() {
    let mut cases = Vec::new();
    for kind in KINDS {
        for &a in &ALPHAS {
            for (ax, ay) in [(a, a), (a, 0.4 * a)] {
                cases.push((kind, ax, ay, None));
                for deg in INCIDENCE_DEG {
                    cases.push((kind, ax, ay, Some(deg)));
                }
            }
        }
    }
    on_every_core(&cases, |&(kind, ax, ay, deg)| {
        run_stretched(kind, ax, ay, deg, samples(kind))
    });
}

#[test]
fn stochastic_samplers() {
    use microsurface::sampling::stochastic::{
        DoubleGgxMixture, ExponentialChi3, GgxBeckmannMixture,
    };
    use microsurface::{DoubleGgx, Exponential, Ggx};
    use rand::distr::Distribution;
    use rand::SeedableRng;
    use rand_xorshift::XorShiftRng;
    /// χ² of a stochastic D·cos sampler against D(m) cos θm of the NDF it represents.
    fn one(
        label: &str,
        s: &impl Distribution<Vec3>,
        n: &impl microsurface::Ndf,
        coords: &Exact,
        rng: &mut XorShiftRng,
    ) {
        let r = chi2_test(
            |_| s.sample(rng),
            |w| pdf_dcos(n, w),
            &DcosCoordinates(coords),
            100_000,
            24,
            0,
        );
        check(label, r);
    }
    for &a in &ALPHAS {
        let coords = reference(a, a);
        let mut rng = XorShiftRng::seed_from_u64((a * 1000.0) as u64);
        let rng = &mut rng;
        one(
            &format!("Double GGX α={a} Gamma-1 mixture of GGX"),
            &DoubleGgxMixture::new(a).unwrap(),
            &DoubleGgx::new(a).unwrap(),
            &coords,
            rng,
        );
        one(
            &format!("GGX α={a} Gamma-1 mixture of Beckmann"),
            &GgxBeckmannMixture::new(a).unwrap(),
            &Ggx::new(a).unwrap(),
            &coords,
            rng,
        );
        one(
            &format!("Exponential α={a} Chi-3 (3 Gaussians, 1 uniform)"),
            &ExponentialChi3::new(a).unwrap(),
            &Exponential::new(a).unwrap(),
            &coords,
            rng,
        );
    }
}

#[test]
fn ggx_bounded_vndf() {
    for &a in &ALPHAS {
        for (ax, ay) in [(a, a), (a, 0.4 * a)] {
            let m = Microfacet::<f64, microsurface::Ggx>::new(ax, ay).unwrap();
            let coords = reference(ax, ay);
            for deg in INCIDENCE_DEG {
                let wi = direction(deg);
                // The bounded pdf jumps to 0 where the reflection would leave the hemisphere;
                // the cells do not follow that curve, and the cell rule then integrates the
                // pdf to a few 1e-3 only (measured ≤ 4.3e-3, anisotropic at normal incidence).
                // Its normalisation holds by construction: uniform on a cap of height 1 + b
                // instead of 1 + w'.z, with the density scaled by (1 + w'.z)/(1 + b).
                check_with(
                    &format!("GGX bounded α=({ax},{ay}) θi={deg}°"),
                    chi2_test(
                        |u| m.sample_bounded(wi.into(), u).wm.into(),
                        |wm| m.pdf_bounded(wi.into(), wm.into()),
                        &DcosCoordinates(&coords),
                        100_000,
                        24,
                        (ax * 1e3) as u64 + deg as u64,
                    ),
                    5e-3,
                );
            }
        }
    }
}

#[test]
#[ignore = "slow (~0.3 ms a sample): run by .ci/run with --ignored"]
fn visible_mixture_posterior_sampler() {
    posterior_sampler(false);
}

#[test]
#[ignore = "the whole grid, ~3 CPU-minutes: run by hand (.ci/run skips it for time)"]
fn visible_mixture_posterior_sampler_full() {
    posterior_sampler(true);
}

/// χ² of the stochastic posterior sampler of the superpositions (`stochastic::VisibleMixture`,
/// the slow reference method: ~0.3 ms a sample) at 5000 samples a test: the whole grid
/// (kinds × α × iso/aniso × incidence, 96 tests) with `full`, else one roughness and
/// anisotropy per kind at every incidence (12 tests; CI's share: the method is the same code
/// at every α, and the production samplers run the whole grid above).
fn posterior_sampler(full: bool) {
    use microsurface::sampling::stochastic::VisibleMixture;
    use rand::distr::Distribution;
    use rand::SeedableRng;
    use rand_xorshift::XorShiftRng;
    let mut all = Vec::new();
    for (j, kind) in [
        UnitSlopes::DoubleGgx,
        UnitSlopes::Exponential,
        UnitSlopes::Ggx,
    ]
    .into_iter()
    .enumerate()
    {
        for (ai, &a) in ALPHAS.iter().enumerate() {
            for (aniso, (ax, ay)) in [(a, a), (a, 0.4 * a)].into_iter().enumerate() {
                if !full && (ai != (j + 1) % ALPHAS.len() || aniso != j % 2) {
                    continue;
                }
                for deg in INCIDENCE_DEG {
                    all.push((kind, ax, ay, deg));
                }
            }
        }
    }
    on_every_core(&all, |&(kind, ax, ay, deg)| {
        let nk = match kind {
            UnitSlopes::DoubleGgx => NdfKind::DoubleGgx,
            UnitSlopes::Exponential => NdfKind::Exponential,
            _ => NdfKind::Ggx,
        };
        let target = Exact::new(nk, ax, ay, None).unwrap();
        let wi = direction(deg);
        let sampler = VisibleMixture::new(kind, ax, ay, wi).unwrap();
        let coords = reference(ax, ay);
        let mut rng = XorShiftRng::seed_from_u64(deg as u64 + kind as u64 + (ax * 1e4) as u64);
        check_visible(
            &format!("{kind:?} α=({ax},{ay}) visible θi={deg}° (posterior)"),
            &target,
            wi,
            &coords,
            5_000,
            0,
            |_| sampler.sample(&mut rng),
        );
    });
}

/// The posterior visible sampler of the Beckmann mixtures (`Exact::sample_wm_stream`, the
/// sampler of the fast path and of the Python bindings' default) at the ends of the shape
/// ranges, where the warps are too slow for CI: Student-T γ = 1.55 and 1e4, Bessel-K a = 0.1
/// and 100, at a narrow isotropic and a wide anisotropic roughness, from θi = 80°.
#[test]
fn family_posterior_range_ends() {
    use microsurface::distribution::UniformStream;
    let cases = [
        (NdfKind::StudentT, Some(1.55)),
        (NdfKind::StudentT, Some(1e4)),
        (NdfKind::BesselK, Some(0.1)),
        (NdfKind::BesselK, Some(100.0)),
    ];
    let all: Vec<_> = cases
        .iter()
        .flat_map(|&c| [(c, 0.05, 0.05), (c, 1.0, 0.4)])
        .collect();
    on_every_core(&all, |&((kind, shape), ax, ay)| {
        let ex = Exact::new(kind, ax, ay, shape).unwrap();
        let wi = direction(80.0);
        let label = format!("{kind} {shape:?} α=({ax},{ay}) posterior visible θi=80°");
        let sample = |u: [f64; 2]| {
            let mut s = UniformStream::new(u);
            Vec3::from(
                ex.sample_wm_stream(wi.into(), &mut || s.next_uniform::<f64>())
                    .expect("above the horizon"),
            )
        };
        let seed = 71 + (ax * 100.0) as u64;
        match (kind, shape) {
            (NdfKind::StudentT, Some(g)) if g < 2.0 => {
                let tail = student_t_tail(g, ax, ay);
                check_visible_in(&label, &ex, wi, &tail, 20_000, seed, sample);
            }
            (NdfKind::BesselK, Some(a)) if a <= 1.0 => {
                let coords = Exact::new(NdfKind::Erfc, 1.5 * ax, 1.5 * ay, None).unwrap();
                check_visible(&label, &ex, wi, &coords, 20_000, seed, sample);
            }
            _ => check_visible(&label, &ex, wi, &reference(ax, ay), 20_000, seed, sample),
        }
    });
}

/// The family's fast path (`Microfacet::with_shape`: visible normals from u and its
/// `UniformStream` through the mixing variable's posterior, D·cos by the radial quantile)
/// against the exact path's densities: every Beckmann-mixture member, anisotropic, θi = 60°
/// and D·cos; f64 and, for Student-T, f32.
#[test]
fn family_fast_path() {
    use microsurface::{BesselK, Ei, Erfc, Microfacet, MicrofacetDistribution, StudentT, K0};
    fn run<D: MicrofacetDistribution<f64>>(label: &str, m: &D, ex: &Exact, coords: &Exact) {
        let wi = direction(60.0);
        check_visible(
            &format!("{label} fast visible θi=60°"),
            ex,
            wi,
            coords,
            20_000,
            61,
            |u| m.sample_wm(wi.into(), u).into(),
        );
        check(
            &format!("{label} fast D·cos"),
            chi2_test(
                |u| m.sample_dcos(u).wm.into(),
                |w| ex.pdf_dcos(w.into()),
                &DcosCoordinates(coords),
                20_000,
                24,
                62,
            ),
        );
    }
    let (ax, ay) = (0.5, 0.15);
    for (kind, shape) in [
        (NdfKind::StudentT, Some(2.5)),
        (NdfKind::Ei, None),
        (NdfKind::Erfc, None),
        (NdfKind::K0, None),
        (NdfKind::BesselK, Some(0.3)),
        (NdfKind::BesselK, Some(4.0)),
    ] {
        let ex = Exact::new(kind, ax, ay, shape).unwrap();
        // (As run_family: the same NDF's warp at 1.5α where D has a pole, except Bessel-K,
        // whose warp inverts a quadrature: Erfc's there; GGX's elsewhere.)
        let singular = AnyNdf::new(kind, 1.0, shape).unwrap().singular_at_pole();
        let coords = match (kind, singular) {
            (NdfKind::BesselK, true) => Exact::new(NdfKind::Erfc, 1.5 * ax, 1.5 * ay, None),
            (_, true) => Exact::new(kind, 1.5 * ax, 1.5 * ay, shape),
            (_, false) => Ok(reference(ax, ay)),
        }
        .unwrap();
        let label = format!("{kind} {shape:?} α=({ax},{ay})");
        match kind {
            NdfKind::StudentT => {
                run(
                    &label,
                    &Microfacet::<f64, StudentT>::with_shape(ax, ay, shape).unwrap(),
                    &ex,
                    &coords,
                );
                // f32: the same sampler, its normals rounded once (renormalised in f64 for the
                // histogram's unit test; their f32 unit length is the fuzz suite's).
                let m32 =
                    Microfacet::<f32, StudentT>::with_shape(ax as f32, ay as f32, shape).unwrap();
                let ex32 = Exact::new(kind, ax as f32 as f64, ay as f32 as f64, shape).unwrap();
                let wi = direction(60.0);
                let wi32 = [wi.x as f32, wi.y as f32, wi.z as f32];
                check_visible(
                    &format!("{label} fast f32 visible θi=60°"),
                    &ex32,
                    Vec3::from(wi32.map(|x| x as f64)),
                    &coords,
                    20_000,
                    63,
                    |u| {
                        Vec3::from(
                            m32.sample_wm(wi32, [u[0] as f32, u[1] as f32])
                                .map(|x| x as f64),
                        )
                        .to_unit()
                    },
                );
            }
            NdfKind::Ei => run(
                &label,
                &Microfacet::<f64, Ei>::with_shape(ax, ay, shape).unwrap(),
                &ex,
                &coords,
            ),
            NdfKind::Erfc => run(
                &label,
                &Microfacet::<f64, Erfc>::with_shape(ax, ay, shape).unwrap(),
                &ex,
                &coords,
            ),
            NdfKind::K0 => run(
                &label,
                &Microfacet::<f64, K0>::with_shape(ax, ay, shape).unwrap(),
                &ex,
                &coords,
            ),
            _ => run(
                &label,
                &Microfacet::<f64, BesselK>::with_shape(ax, ay, shape).unwrap(),
                &ex,
                &coords,
            ),
        }
    }
}
