//! The fast samplers (crate-internal since `Microfacet` is their public door) against the
//! exact samplers and the visible distribution: warps matched to rounding, rejection samplers
//! by χ², their extra uniforms injected at the edges (0, just below 1, NaN), f32 against f64.
//! (Moved from tests/fast.rs when the samplers became `pub(crate)`; here, beside the χ²
//! harness it uses, so that `fast` does not import `check`.)

use crate::distribution::kernels::{Microsurface, Stretched};
use crate::distribution::{Exact, MicrofacetDistribution};
use crate::fast::{beckmann, ggx};
use crate::{Gtr, Ndf, NdfKind, UnitSlopes, Vec3};

/// The reference coordinates' exact GGX at (αx, αy).
fn ggx_exact(ax: f64, ay: f64) -> Exact {
    Exact::new(NdfKind::Ggx, ax, ay, None).unwrap()
}

/// Log-spaced points from `lo` to `hi`, with an irrational stride so they fall between nodes.
fn logspace(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f64> {
    let (a, b) = (lo.ln(), hi.ln());
    (0..n).map(move |i| (a + (b - a) * ((i as f64 * 0.618_033_988_749_895) % 1.0)).exp())
}

#[test]
fn ggx_fast_vndf_is_the_visible_distribution() {
    use crate::check::chi2::{chi2_test, DcosCoordinates};
    let m = ggx_exact(0.3, 0.1);
    let coords = ggx_exact(0.45, 0.15);
    for w in [Vec3::new(0.6, 0.0, 0.8), Vec3::new(0.1, -0.7, 0.707)] {
        let w = w.normalize();
        let r = chi2_test(
            |u| {
                let f = ggx::sample_visible([w.x, w.y, w.z], 0.3, 0.1, u);
                Vec3::new(f[0], f[1], f[2])
            },
            |wm| m.pdf(w.into(), wm.into()),
            &DcosCoordinates(&coords),
            100_000,
            24,
            5,
        );
        println!("fast GGX VNDF: p = {:.3e}", r.p_value);
        assert_eq!(r.bad_samples, 0);
        assert!(
            r.p_value > 1e-4 && (r.pdf_integral - 1.0).abs() < 1e-4,
            "{r:?}"
        );
        // f32 gives the same normals to single precision.
        let u = [0.37, 0.81];
        let (a, b) = (
            ggx::sample_visible([w.x, w.y, w.z], 0.3, 0.1, u),
            ggx::sample_visible([w.x as f32, w.y as f32, w.z as f32], 0.3, 0.1, [0.37, 0.81]),
        );
        for k in 0..3 {
            assert!((a[k] - b[k] as f64).abs() < 1e-6);
        }
    }
}
#[test]
fn beckmann_fast_vndf_is_the_exact_warp() {
    // The unit-slope warp against the exact sampler (safeguarded Newton to a few ulp): the
    // exact x̃ loses ~ε/density in the tails, so compare where u is within [1e-6, 1 − 1e-6].
    let (mut ex, mut ey) = (0.0f64, 0.0f64);
    let mut cots: Vec<f64> = logspace(1e-6, 1e6, 60).collect();
    cots.extend([0.0, f64::INFINITY]);
    for &a in &cots {
        for j in 0..97 {
            let u1 = match j {
                0 => 1e-6,
                96 => 1.0 - 1e-6,
                _ => (j as f64 + 0.137) / 97.0,
            };
            let u = [u1, 1.0 - u1 * 0.71];
            let (x, y) = beckmann::sample_visible11(a, u);
            let (xe, ye) = UnitSlopes::Beckmann.sample(a, u);
            ex = ex.max((x - xe).abs() / (1.0 + xe.abs()));
            ey = ey.max((y - ye).abs() / (1.0 + ye.abs()));
        }
        // The ends stay finite and inside [−a, 8], and the warp is monotone in u₁ from 1e-12
        // on. Below, N(X) = uZ cancels (as in the exact sampler): x̃ + a is resolved only to
        // ~1e-16 of the scale, so the order of x̃ at u₁ = 1e-100 and 1e-20 is noise.
        let mut last = f64::NEG_INFINITY;
        for u1 in [
            0.0,
            1e-300,
            1e-100,
            1e-20,
            1e-12,
            1e-9,
            0.5,
            1.0 - 1e-12,
            1.0 - 1e-16,
            1.0,
        ] {
            let (x, y) = beckmann::sample_visible11(a, [u1, u1]);
            assert!(x.is_finite() && y.is_finite(), "a {a} u {u1}: {x} {y}");
            assert!(x >= -a && x <= 8.0, "a {a} u {u1}: {x}");
            if u1 >= 1e-12 {
                assert!(x >= last, "a {a} u {u1}: {x} after {last}");
                last = x;
            }
        }
    }
    println!("fast Beckmann VNDF warp: x̃ {ex:.2e}, ỹ {ey:.2e}");
    // Both bounds are the exact sampler's: it solves ½ + ½ erf ỹ = u (and N = uZ) with an
    // absolute residual of ~1e-16, so at u = 1e-6 from an end its answer is off by ~ε/density
    // ~ 1e-11; the fast erfinv is checked on its own to 2e-15 above.
    assert!(ex < 1e-11 && ey < 1e-11, "{ex} {ey}");
    // Directions: against Stretched (anisotropic, below the horizon mirrored, normal and
    // grazing incidence), and f32 against f64.
    let mut worst = 0.0f64;
    let mut worst32 = 0.0f64;
    for (ax, ay) in [(0.3, 0.3), (0.05, 0.8), (1.7, 0.2)] {
        let m = Stretched::new(UnitSlopes::Beckmann, ax, ay).unwrap();
        for (k, w) in [
            Vec3::new(0.6, 0.0, 0.8),
            Vec3::new(0.1, -0.7, 0.707),
            Vec3::new(-0.3, 0.2, -0.9),
            Vec3::new(0.0, 0.0, 1.0),
            Vec3::new(0.8, 0.6, 0.0),
        ]
        .into_iter()
        .enumerate()
        {
            let w = w.normalize();
            for j in 0..50 {
                let u = [
                    (j as f64 + 0.5) / 50.0,
                    ((j * 7 + k) % 50) as f64 / 50.0 + 0.01,
                ];
                let f = beckmann::sample_visible([w.x, w.y, w.z], ax, ay, u);
                let e = m.sample_visible(w, u);
                let dot = f[0] * e.x + f[1] * e.y + f[2] * e.z;
                worst = worst.max((1.0 - dot).max(0.0).sqrt());
                let f32 = beckmann::sample_visible(
                    [w.x as f32, w.y as f32, w.z as f32],
                    ax as f32,
                    ay as f32,
                    [u[0] as f32, u[1] as f32],
                );
                for i in 0..3 {
                    worst32 = worst32.max((f32[i] as f64 - f[i]).abs());
                }
            }
        }
        // u at and past the ends: a unit normal, never NaN.
        for u in [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [2.0, -1.0]] {
            let f = beckmann::sample_visible([0.6, 0.0, 0.8], ax, ay, u);
            let l = (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
            assert!((l - 1.0).abs() < 1e-12 && f[2] > 0.0, "{u:?} {f:?}");
        }
    }
    println!("fast Beckmann VNDF directions: {worst:.2e} rad (≈), f32 {worst32:.2e}");
    assert!(worst < 1e-7 && worst32 < 1e-6, "{worst} {worst32}");
}
/// The fast Beckmann warp's hot path (issue 35) piece by piece, over (t, u) on a grid dense
/// in both ends of its range: the guess table within 3e-4 of min(1, X + a) (measured 2.8e-4;
/// the order-five step is sized for it: its error ~(K·3e-4)⁵/K, K ~ 1/(X + a) or 2|X|, stays
/// below 1e-17 of X), and the one step against the bracketed loop converged, in units of the
/// rounding that both carry, ε·Z/N′(X) (tests/fast.rs holds both to mpmath in that unit).
#[test]
fn beckmann_one_step_warp() {
    let (mut eg, mut es) = (0.0f64, 0.0f64);
    let mut us: Vec<f64> = (0..2000).map(|j| (j as f64 + 0.5) / 2000.0).collect();
    for k in 0..=21 {
        us.push(2f64.powi(-k) * 0.7);
        us.push(1.0 - 2f64.powi(-k) * 0.7);
    }
    us.extend([beckmann::U_LO, beckmann::U_HI, 0.5]);
    let sqrt_pi = std::f64::consts::PI.sqrt();
    for i in 0..=200 {
        let t = i as f64 / 200.0;
        let a = if t == 0.0 { 1e300 } else { (1.0 - t) / t };
        let z = 0.5 * a * libm::erfc(-a) + (-a * a).exp() / (2.0 * sqrt_pi);
        for &u in us
            .iter()
            .filter(|&&u| (beckmann::U_LO..=beckmann::U_HI).contains(&u))
        {
            let x = beckmann::visible_x_loop(a, t, u);
            let density = (x + a) * (-x * x).exp() / sqrt_pi;
            eg = eg.max((beckmann::guess(t, u) - x).abs() / (x + a).min(1.0));
            let d = beckmann::visible_x_hot(a, t, u, f64::exp) - x;
            es = es.max(d.abs() * density / (f64::EPSILON * z));
        }
    }
    // A negative a (out of contract) is the loop's a = 0.
    for u in [0.3, 0.7] {
        let (x, x0) = (
            beckmann::sample_visible11(-1.0, [u, 0.5]).0,
            beckmann::sample_visible11(0.0, [u, 0.5]).0,
        );
        assert!((x - x0).abs() < 1e-14, "{x} {x0}");
    }
    println!(
        "Beckmann warp: guess {eg:.2e} of min(1, X + a), one step {es:.2} ε·Z/N′ from the loop"
    );
    // (Measured 6.7: the step and the loop are each within ~4 ε·Z/N′ of the quantile,
    // tests/fast.rs, so up to twice that apart.)
    assert!(eg < 3e-4 && es < 10.0, "{eg:e} {es}");
}

/// χ² of the fast rejection samplers of the superpositions (Double GGX, Exponential) against
/// max(0, w·m) D(m)/σ(w) of the exact NDF, over α, anisotropy and incidence; also the mean
/// number of uniforms each takes, the mirror for w.z < 0 and f32 against f64.
#[test]
fn mixture_fast_vndf_is_the_visible_distribution() {
    use crate::check::chi2::{chi2_test, sidak, DcosCoordinates, SplitMix64};
    use crate::fast::{double_ggx, exponential};
    type Sampler = fn([f64; 3], f64, f64, [f64; 2], &mut dyn FnMut() -> f64) -> [f64; 3];
    let samplers: [(UnitSlopes, Sampler); 2] = [
        (UnitSlopes::DoubleGgx, |w, ax, ay, u, f| {
            double_ggx::sample_visible(w, ax, ay, u, &mut || f())
        }),
        (UnitSlopes::Exponential, |w, ax, ay, u, f| {
            exponential::sample_visible(w, ax, ay, u, &mut || f())
        }),
    ];
    let alphas = [0.05, 0.3, 1.0, 2.0];
    let degs = [0.0, 45.0, 80.0, 89.0];
    let level = sidak(0.01, samplers.len() * alphas.len() * 2 * degs.len());
    for (kind, sample) in samplers {
        let mut most_uniforms: f64 = 0.0;
        for &a in &alphas {
            for (ax, ay) in [(a, a), (a, 0.4 * a)] {
                let m = Stretched::new(kind, ax, ay).unwrap();
                let coords = ggx_exact(1.5 * ax, 1.5 * ay);
                for deg in degs {
                    let t = f64::to_radians(deg);
                    let w = Vec3::new(0.8 * t.sin(), 0.6 * t.sin(), t.cos());
                    let mut rng = SplitMix64(deg as u64 + (ax * 1e4) as u64 + (ay * 1e6) as u64);
                    let mut count = 0usize;
                    let n = 100_000;
                    // σ once (the exact Exponential σ is a quadrature).
                    let sigma = m.sigma(w);
                    let r = chi2_test(
                        |u| {
                            let mut next = || {
                                count += 1;
                                rng.next_f64()
                            };
                            let f = sample([w.x, w.y, w.z], ax, ay, u, &mut next);
                            Vec3::new(f[0], f[1], f[2])
                        },
                        |wm| (w.dot(wm)).max(0.0) * m.d(wm) / sigma,
                        &DcosCoordinates(&coords),
                        n,
                        24,
                        7 + deg as u64,
                    );
                    let per_sample = count as f64 / n as f64;
                    most_uniforms = most_uniforms.max(per_sample);
                    println!(
                        "fast {kind:?} VNDF α=({ax},{ay}) θ={deg}°: p = {:.3e}, ∫pdf = {:.6}, \
                         {per_sample:.2} extra uniforms a sample",
                        r.p_value, r.pdf_integral
                    );
                    assert_eq!(r.bad_samples, 0, "{kind:?} {ax} {ay} {deg}");
                    assert!(
                        r.p_value > level && (r.pdf_integral - 1.0).abs() < 1e-4,
                        "{kind:?} α=({ax},{ay}) θ={deg}°: {r:?}"
                    );
                }
            }
        }
        println!("fast {kind:?} VNDF: at most {most_uniforms:.2} extra uniforms a sample");
        // Mirror: w and −w give the same normal from the same uniforms; f32 follows f64.
        let w = [0.3, -0.5, 0.2f64];
        let l = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
        let w = [w[0] / l, w[1] / l, w[2] / l];
        for k in 0..1000 {
            let u = [
                (k as f64 + 0.5) / 1000.0,
                ((k * 7919) % 1000) as f64 / 1000.0,
            ];
            let (mut r1, mut r2) = (SplitMix64(k), SplitMix64(k));
            let up = sample(w, 0.4, 0.2, u, &mut || r1.next_f64());
            let down = sample([-w[0], -w[1], -w[2]], 0.4, 0.2, u, &mut || r2.next_f64());
            assert_eq!(up, down);
        }
        // f32 in (the same f32 directions, roughness and uniforms, widened for the f64
        // call): the normals agree to single precision. (The selection is not a smooth warp
        // of its uniforms: the ziggurat's layers scale a uniform's low bits by up to 2 200, so
        // inputs must match exactly for the outputs to.)
        let w32 = [w[0] as f32, w[1] as f32, w[2] as f32];
        let w64 = w32.map(f64::from);
        let (ax32, ay32) = (0.4f32, 0.2f32);
        let (ax64, ay64) = (f64::from(ax32), f64::from(ay32));
        let (mut r, mut r32) = (SplitMix64(3), SplitMix64(3));
        for k in 0..1000 {
            let u32 = [(k as f32 + 0.5) / 1000.0, 0.37];
            let a = sample(w64, ax64, ay64, u32.map(f64::from), &mut || {
                f64::from(r.next_f64() as f32)
            });
            let mut next32 = || r32.next_f64() as f32;
            let b = match kind {
                UnitSlopes::DoubleGgx => {
                    double_ggx::sample_visible(w32, ax32, ay32, u32, &mut next32)
                }
                _ => exponential::sample_visible(w32, ax32, ay32, u32, &mut next32),
            };
            for i in 0..3 {
                assert!((a[i] - b[i] as f64).abs() < 1e-7, "{kind:?} {a:?} {b:?}");
            }
        }
    }
}

/// The fast rejection samplers stay finite unit upper-hemisphere vectors at the ends of the
/// domain: normal and grazing incidence, extreme roughness, uniforms at 0 and just below 1;
/// NaN in gives NaN out (and terminates).
#[test]
fn mixture_fast_vndf_edges() {
    use crate::fast::{double_ggx, exponential};
    let below_one = 1.0 - f64::EPSILON / 2.0;
    let dirs = [
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0],
        [0.6, 0.8, 0.0],
        [0.0, 0.6, -0.8],
    ];
    for w in dirs {
        for a in [1e-6, 1e-3, 1.0, 1e3, 1e6] {
            for (ax, ay) in [(a, a), (a, 1.0)] {
                for v in [0.0, 0.5, below_one] {
                    for u in [[0.0, 0.0], [below_one, below_one], [0.5, 0.0]] {
                        let outs = [
                            double_ggx::sample_visible(w, ax, ay, u, &mut || v),
                            exponential::sample_visible(w, ax, ay, u, &mut || v),
                        ];
                        for m in outs {
                            let len = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt();
                            assert!(
                                m.iter().all(|x| x.is_finite())
                                    && m[2] >= 0.0
                                    && (len - 1.0).abs() < 1e-12,
                                "w={w:?} α=({ax},{ay}) v={v} u={u:?}: {m:?}"
                            );
                        }
                    }
                }
            }
        }
    }
    let nan = f64::NAN;
    let m = double_ggx::sample_visible([nan, 0.0, 1.0], 0.3, 0.3, [0.5, 0.5], &mut || 0.5);
    assert!(m[0].is_nan());
    let m = exponential::sample_visible([0.0, 0.0, 1.0], nan, 0.3, [0.5, 0.5], &mut || 0.5);
    assert!(m[0].is_nan());
    // A uniform source that returns NaN still terminates.
    let m = double_ggx::sample_visible([0.6, 0.0, 0.8], 0.3, 0.3, [0.5, 0.5], &mut || nan);
    assert!(m.iter().all(|x| !x.is_infinite()));
    let m = exponential::sample_visible([0.6, 0.0, 0.8], 0.3, 0.3, [0.5, 0.5], &mut || nan);
    assert!(m.iter().all(|x| !x.is_infinite()));
}

/// χ² of the fast GTR visible-normal sampler (rejection from per-material envelopes) against
/// max(0, w·m) D(m)/σ(w) of the exact GTR, over α, γ and incidence; the mean number of
/// uniforms; f32 against f64; the ends of the domain.
#[test]
fn gtr_fast_vndf_is_the_visible_distribution() {
    use crate::check::chi2::{chi2_test, sidak, DcosCoordinates, SplitMix64};
    use crate::fast::gtr::FittedGtr as FastGtr;
    let alphas = [0.05, 0.3, 1.0, 1.7];
    let gammas = [0.5, 1.0, 1.5, 2.0, 3.0, 10.0];
    let degs = [0.0, 45.0, 80.0, 89.0];
    let level = sidak(0.01, alphas.len() * gammas.len() * degs.len());
    let mut most_uniforms: f64 = 0.0;
    for &a in &alphas {
        for &g in &gammas {
            let exact = Gtr::new(a, g).unwrap();
            let fast = FastGtr::new(a, g).unwrap();
            // GTR with γ ≤ 1 keeps much of its visible area at grazing normals as α → 0
            // (derivations.md E): a near-specular reference grid would lump it into a few cells.
            let ref_alpha = if exact.d(0.5) > 0.05 { 1.0 } else { 1.5 * a };
            let coords = ggx_exact(ref_alpha, ref_alpha);
            for deg in degs {
                let t = f64::to_radians(deg);
                let w = Vec3::new(0.8 * t.sin(), 0.6 * t.sin(), t.cos());
                let sigma = exact.sigma(w.z);
                let mut rng = SplitMix64(deg as u64 + (a * 1e4) as u64 + (g * 1e6) as u64);
                let mut count = 0usize;
                let n = 100_000;
                let r = chi2_test(
                    |u| {
                        let mut next = || {
                            count += 1;
                            rng.next_f64()
                        };
                        let f = fast.sample_visible([w.x, w.y, w.z], u, &mut next);
                        Vec3::new(f[0], f[1], f[2])
                    },
                    |wm| w.dot(wm).max(0.0) * exact.d(wm.z) / sigma,
                    &DcosCoordinates(&coords),
                    n,
                    24,
                    11 + deg as u64,
                );
                let per_sample = count as f64 / n as f64;
                most_uniforms = most_uniforms.max(per_sample);
                println!(
                    "fast GTR VNDF α={a} γ={g} θ={deg}°: p = {:.3e}, ∫pdf = {:.6}, \
                     {per_sample:.2} extra uniforms a sample",
                    r.p_value, r.pdf_integral
                );
                assert_eq!(r.bad_samples, 0, "α={a} γ={g} θ={deg}°");
                assert!(
                    r.p_value > level && (r.pdf_integral - 1.0).abs() < 1e-4,
                    "α={a} γ={g} θ={deg}°: {r:?}"
                );
            }
        }
    }
    println!("fast GTR VNDF: at most {most_uniforms:.2} extra uniforms a sample");
    // f32 (the same f32 uniforms, widened for the f64 call), and the mirror for w.z < 0.
    let fast = FastGtr::new(0.4, 1.3).unwrap();
    let w32 = [0.3f32, -0.5, 0.81];
    let w64 = w32.map(f64::from);
    let (mut r, mut r32, mut rm) = (SplitMix64(3), SplitMix64(3), SplitMix64(3));
    for k in 0..1000 {
        let u32 = [(k as f32 + 0.5) / 1000.0, 0.37];
        let a = fast.sample_visible(w64, u32.map(f64::from), &mut || {
            f64::from(r.next_f64() as f32)
        });
        let b = fast.sample_visible(w32, u32, &mut || r32.next_f64() as f32);
        let m = fast.sample_visible(w32.map(|x| -x), u32, &mut || rm.next_f64() as f32);
        assert_eq!(b, m);
        for i in 0..3 {
            assert!((a[i] - b[i] as f64).abs() < 1e-7, "{a:?} {b:?}");
        }
    }
    // The ends: finite unit upper-hemisphere normals.
    let below_one = 1.0 - f64::EPSILON / 2.0;
    for (a, g) in [
        (1e-3, 0.1),
        (1e-3, 100.0),
        (1e3, 0.1),
        (1e3, 100.0),
        (1.0, 2.0),
    ] {
        let fast = FastGtr::new(a, g).unwrap();
        for w in [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 0.6, -0.8]] {
            for v in [0.0, 0.5, below_one] {
                for u in [[0.0, 0.0], [below_one, below_one], [0.5, 0.0]] {
                    let m = fast.sample_visible(w, u, &mut || v);
                    let len = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt();
                    assert!(
                        m.iter().all(|x| x.is_finite()) && m[2] >= 0.0 && (len - 1.0).abs() < 1e-12,
                        "α={a} γ={g} w={w:?} v={v} u={u:?}: {m:?}"
                    );
                }
            }
        }
    }
    // Random draws: unit normals to rounding (their length comes from the slope radius
    // alone, `normal_from_slopes_r`).
    let mut rng = SplitMix64(11);
    for (a, g) in [(0.05, 0.5), (0.3, 1.5), (1.7, 10.0)] {
        let fast = FastGtr::new(a, g).unwrap();
        let mut worst = 0.0f64;
        for _ in 0..20_000 {
            let t = 1.5 * rng.next_f64();
            let w = [t.sin(), 0.0, t.cos()];
            let u = [rng.next_f64(), rng.next_f64()];
            let m = fast.sample_visible(w, u, &mut || rng.next_f64());
            worst = worst.max(((m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt() - 1.0).abs());
        }
        assert!(worst < 1e-14, "α={a} γ={g}: {worst:e}");
    }
    let nan = f64::NAN;
    let m = fast.sample_visible([nan, 0.0, 1.0], [0.5, 0.5], &mut || 0.5);
    assert!(m[0].is_nan());
    let m = fast.sample_visible([0.6, 0.0, 0.8], [0.5, 0.5], &mut || nan);
    assert!(m.iter().all(|x| !x.is_infinite()));
}
/// The fast D·cos samplers. GGX, Beckmann and GTR are warps of u: they must match the exact
/// samplers' normals (`Stretched`, `Isotropic`) to rounding. Double GGX and the Exponential
/// NDF take one extra uniform: χ² against D(m) cos θm of the exact NDF (Šidák-corrected at
/// 0.01), isotropic and 2.5:1 anisotropic. All: finite unit upper-hemisphere normals for u
/// at 0 and 1 and extreme α, NaN for NaN, and f32 within 1e-7 of f64 for the same uniforms.
#[test]
fn fast_dcos_samplers() {
    use crate::check::chi2::{chi2_test, sidak, DcosCoordinates, SplitMix64};
    use crate::distribution::kernels::Isotropic;
    use crate::fast::gtr::FittedGtr as FastGtr;
    use crate::fast::{double_ggx, exponential};
    // The largest coordinate difference of two normals.
    let diff = |a: [f64; 3], b: Vec3| {
        (a[0] - b.x)
            .abs()
            .max((a[1] - b.y).abs())
            .max((a[2] - b.z).abs())
    };
    // The warps, against the exact samplers.
    let mut rng = SplitMix64(5);
    let mut worst: f64 = 0.0;
    for &(ax, ay) in &[
        (0.05, 0.05),
        (0.3, 0.12),
        (1.0, 1.0),
        (2.0, 0.8),
        (1e-4, 1e-4),
        (50.0, 50.0),
    ] {
        let eg = ggx_exact(ax, ay);
        let eb = Stretched::new(UnitSlopes::Beckmann, ax, ay).unwrap();
        for _ in 0..2000 {
            let u = [rng.next_f64(), rng.next_f64()];
            for (got, want) in [
                (
                    ggx::sample_dcos(ax, ay, u),
                    Vec3::from(eg.sample_dcos(u).wm),
                ),
                (beckmann::sample_dcos(ax, ay, u), eb.sample_dcos(u)),
            ] {
                let d = diff(got, want);
                worst = worst.max(d);
                assert!(d <= 1e-12, "α=({ax},{ay}) u={u:?}: {got:?} vs {want:?}");
            }
        }
    }
    for &(a, g) in &[
        (0.05, 0.5),
        (0.3, 1.0),
        (0.3, 1.5),
        (1.0, 3.0),
        (1.7, 10.0),
        (1e-3, 2.0),
    ] {
        let fast = FastGtr::new(a, g).unwrap();
        let exact = Isotropic(Gtr::new(a, g).unwrap());
        for _ in 0..2000 {
            let u = [rng.next_f64(), rng.next_f64()];
            let (got, want) = (fast.sample_dcos(u), exact.sample_dcos(u));
            let d = diff(got, want);
            worst = worst.max(d);
            assert!(d <= 1e-12, "GTR α={a} γ={g} u={u:?}: {got:?} vs {want:?}");
        }
    }
    println!("fast D·cos warps: largest difference from the exact samplers {worst:.1e}");

    // The superpositions, by χ².
    type Sampler = fn(f64, f64, [f64; 2], &mut dyn FnMut() -> f64) -> [f64; 3];
    let samplers: [(UnitSlopes, Sampler); 2] = [
        (UnitSlopes::DoubleGgx, |ax, ay, u, f| {
            double_ggx::sample_dcos(ax, ay, u, &mut || f())
        }),
        (UnitSlopes::Exponential, |ax, ay, u, f| {
            exponential::sample_dcos(ax, ay, u, &mut || f())
        }),
    ];
    let alphas = [0.05, 0.3, 1.0, 2.0];
    let level = sidak(0.01, samplers.len() * alphas.len() * 2);
    for (kind, sample) in samplers {
        for &a in &alphas {
            for (ax, ay) in [(a, a), (a, 0.4 * a)] {
                let m = Stretched::new(kind, ax, ay).unwrap();
                let coords = ggx_exact(1.5 * ax, 1.5 * ay);
                let mut rng = SplitMix64((ax * 1e4) as u64 + (ay * 1e6) as u64);
                let r = chi2_test(
                    |u| {
                        let f = sample(ax, ay, u, &mut || rng.next_f64());
                        Vec3::new(f[0], f[1], f[2])
                    },
                    |wm| m.d(wm) * wm.z.max(0.0),
                    &DcosCoordinates(&coords),
                    100_000,
                    24,
                    17,
                );
                println!(
                    "fast {kind:?} D·cos α=({ax},{ay}): p = {:.3e}, ∫pdf = {:.6}",
                    r.p_value, r.pdf_integral
                );
                assert_eq!(r.bad_samples, 0, "{kind:?} {ax} {ay}");
                assert!(
                    r.p_value > level && (r.pdf_integral - 1.0).abs() < 1e-4,
                    "{kind:?} D·cos α=({ax},{ay}): {r:?}"
                );
            }
        }
    }

    // The ends: u at 0 and just below/at 1, extreme α; finite unit normals with z ≥ 0.
    let gtr = FastGtr::new(0.3, 1.5).unwrap();
    let below_one = 1.0 - f64::EPSILON / 2.0;
    for ax in [1e-6, 0.3, 1e6] {
        for u0 in [0.0, 1e-300, 0.5, below_one, 1.0] {
            for u1 in [0.0, 0.25, below_one] {
                for v in [0.0, 0.5, below_one] {
                    let u = [u0, u1];
                    for m in [
                        ggx::sample_dcos(ax, 0.5 * ax, u),
                        beckmann::sample_dcos(ax, 0.5 * ax, u),
                        double_ggx::sample_dcos(ax, 0.5 * ax, u, &mut || v),
                        exponential::sample_dcos(ax, 0.5 * ax, u, &mut || v),
                        gtr.sample_dcos(u),
                    ] {
                        let len = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt();
                        assert!(
                            m.iter().all(|x| x.is_finite())
                                && m[2] >= 0.0
                                && (len - 1.0).abs() < 1e-15,
                            "α {ax} u {u:?} v {v}: {m:?}"
                        );
                    }
                }
            }
        }
    }
    // NaN in, NaN out.
    let nan = [f64::NAN, 0.5];
    for m in [
        ggx::sample_dcos(0.3, 0.3, nan),
        beckmann::sample_dcos(0.3, 0.3, nan),
        double_ggx::sample_dcos(0.3, 0.3, nan, &mut || 0.5),
        exponential::sample_dcos(0.3, 0.3, nan, &mut || 0.5),
        gtr.sample_dcos(nan),
    ] {
        assert!(m.iter().any(|x| x.is_nan()), "{m:?}");
    }
    // f32 follows f64 for the same (f32) uniforms.
    let mut rng = SplitMix64(9);
    for _ in 0..1000 {
        let u32s = [rng.next_f64() as f32, rng.next_f64() as f32];
        let v32 = rng.next_f64() as f32;
        let u = u32s.map(f64::from);
        let v = f64::from(v32);
        let pairs: [([f64; 3], [f32; 3]); 5] = [
            (
                ggx::sample_dcos(0.4, 0.2, u),
                ggx::sample_dcos(0.4f32, 0.2, u32s),
            ),
            (
                beckmann::sample_dcos(0.4, 0.2, u),
                beckmann::sample_dcos(0.4f32, 0.2, u32s),
            ),
            (
                double_ggx::sample_dcos(0.4, 0.2, u, &mut || v),
                double_ggx::sample_dcos(0.4f32, 0.2, u32s, &mut || v32),
            ),
            (
                exponential::sample_dcos(0.4, 0.2, u, &mut || v),
                exponential::sample_dcos(0.4f32, 0.2, u32s, &mut || v32),
            ),
            (gtr.sample_dcos(u), gtr.sample_dcos(u32s)),
        ];
        for (a, b) in pairs {
            for i in 0..3 {
                assert!((a[i] - f64::from(b[i])).abs() < 1e-7, "{a:?} {b:?}");
            }
        }
    }
}

/// The exact samplers' generic polar inversion of the visible slopes (what GTR uses) on an NDF
/// that also has a closed-form sampler: χ² against max(0, w·m) D(m)/σ(w).
#[test]
fn polar_inversion_on_beckmann() {
    use crate::check::chi2::{chi2_test, DcosCoordinates};
    use crate::distribution::kernels::Isotropic;
    let m = Isotropic(crate::Beckmann::new(0.3).unwrap());
    let coords = ggx_exact(0.45, 0.45);
    let t = 60f64.to_radians();
    let wi = Vec3::new(t.sin() * 0.8, t.sin() * 0.6, t.cos());
    let sigma = m.sigma(wi);
    let r = chi2_test(
        |u| m.sample_visible(wi, u),
        |wm| wi.dot(wm).max(0.0) * m.d(wm) / sigma,
        &DcosCoordinates(&coords),
        20_000,
        24,
        3060,
    );
    assert_eq!(r.bad_samples, 0);
    assert!(
        (r.pdf_integral - 1.0).abs() < 1e-4,
        "∫ pdf = {}",
        r.pdf_integral
    );
    assert!(r.p_value > 1e-4, "p = {:e}", r.p_value);
}

/// The GGX spherical-cap samplers (visible and bounded) in f32 against f64 at the same
/// uniforms near the caps' poles: u₁ = 1 − 2⁻²⁴ at a small α (the cap point near −w', its
/// height cz → −1) and u₁ ∈ {0, 2⁻²⁴} at a large one (cz → 1). The f32 sampler's roundings
/// (the stretched w', cos and sin of 2πu₀, the sine of the cap and the cap's height, each a
/// few ε relative) move the unnormalised normal h = (αx(sin cos φ + x), αy(sin sin φ + y),
/// h.z) by at most 8ε times the sum of its terms' magnitudes: `8ε Σ/|h|` per component of
/// the unit normal (the cancellation of sin cos φ + x where the cap point nears −w' is the
/// sampler's own conditioning, which no formulation removes). Before sin² was formed
/// without the cancellation of 1 − cz², these cases were off by up to 1.2e-1 (visible) and
/// 4.4e-3 (bounded), √ε-scale where the bound is ε-scale.
#[test]
fn ggx_cap_samplers_f32_hold_f64_at_the_poles() {
    use crate::{Ggx, Microfacet};
    const EPS: f64 = 5.960_464_5e-8;
    let top = 1.0 - 5.960_464_5e-8_f32;
    let cases: [([f32; 2], f32); 8] = [
        ([0.002, 0.002], top),
        ([0.002, 0.002], 0.999),
        ([0.002, 0.05], top),
        ([0.05, 0.002], top),
        ([2.0, 2.0], 0.0),
        ([2.0, 2.0], 5.960_464_5e-8),
        ([2.0, 0.3], 0.0),
        ([1.0, 1.0], 5.960_464_5e-8),
    ];
    let dirs: Vec<[f64; 3]> = [1.0, 0.9, 0.5, 0.1, 1e-4, -0.6]
        .iter()
        .flat_map(|&c: &f64| {
            [0.3, 2.0, 4.1].map(|p: f64| {
                let s = (1.0 - c * c).sqrt();
                [s * p.cos(), s * p.sin(), c]
            })
        })
        .collect();
    let mut worst = [(0.0f64, String::new()), (0.0, String::new())];
    for (alpha, u1) in cases {
        let m32 = Microfacet::<f32, Ggx>::new(alpha[0], alpha[1]).unwrap();
        let m64 = Microfacet::<f64, Ggx>::new(alpha[0] as f64, alpha[1] as f64).unwrap();
        let (ax, ay) = (alpha[0] as f64, alpha[1] as f64);
        for d in &dirs {
            let w32 = d.map(|x| x as f32);
            let w = w32.map(f64::from);
            for u0 in [0.0f32, 0.13, 0.37, 0.5, 0.81] {
                let u = [u0, u1];
                let u64 = [u0 as f64, u1 as f64];
                for (k, bounded) in [false, true].into_iter().enumerate() {
                    let (a, b) = if bounded {
                        (m32.sample_bounded(w32, u).wm, m64.sample_bounded(w, u64).wm)
                    } else {
                        (m32.sample(w32, u).wm, m64.sample(w, u64).wm)
                    };
                    // The terms of h in f64 (w mirrored up; the bounded cap's from the
                    // f64 sampler's own formulas).
                    let n = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
                    let v = if w[2] < 0.0 {
                        w.map(|x| -x / n)
                    } else {
                        w.map(|x| x / n)
                    };
                    let st = [ax * v[0], ay * v[1], v[2]];
                    let len = (st[0] * st[0] + st[1] * st[1] + st[2] * st[2]).sqrt();
                    let ws = st.map(|x| x / len);
                    let bz = if bounded && w[2] > 0.0 {
                        let a = ax.min(ay).min(1.0);
                        let s = 1.0 + (v[0] * v[0] + v[1] * v[1]).sqrt();
                        (1.0 - a * a) * s * s / (s * s + a * a * v[2] * v[2]) * ws[2]
                    } else {
                        ws[2]
                    };
                    let u1 = u1 as f64;
                    let above = (1.0 - u1) * (1.0 + bz);
                    let sin = (u1 * (1.0 + bz) * (2.0 - u1 * (1.0 + bz))).max(0.0).sqrt();
                    let (sp, cp) = (std::f64::consts::TAU * u64[0]).sin_cos();
                    let h = [
                        ax * (sin * cp + ws[0]),
                        ay * (sin * sp + ws[1]),
                        above + (ws[2] - bz),
                    ];
                    let terms = ax * ((sin * cp).abs() + ws[0].abs())
                        + ay * ((sin * sp).abs() + ws[1].abs())
                        + above
                        + (ws[2] - bz).abs();
                    let hl = (h[0] * h[0] + h[1] * h[1] + h[2] * h[2]).sqrt();
                    let bound = 8.0 * EPS * terms / hl;
                    let err = (0..3)
                        .map(|i| (a[i] as f64 - b[i]).abs())
                        .fold(0.0, f64::max);
                    if err / bound > worst[k].0 {
                        worst[k] = (
                            err / bound,
                            format!("α {alpha:?} w {w32:?} u {u:?}: f32 {a:?} f64 {b:?}"),
                        );
                    }
                }
            }
        }
    }
    for (k, name) in ["visible", "bounded"].iter().enumerate() {
        println!(
            "{name}: max error / bound {:.3} at {}",
            worst[k].0, worst[k].1
        );
        assert!(worst[k].0 <= 1.0, "{name}: {:?}", worst[k]);
    }
}
