//! The fast paths against the exact f64 paths (the bounds stated in `fast`'s docs).

use microfacet::fast::{beckmann, ggx};
use microfacet::{Beckmann, Ggx, Microsurface, Ndf, Stretched, UnitSlopes, Vec3};

fn grid() -> Vec<(f64, f64)> {
    let mut v = Vec::new();
    for i in 0..=60 {
        let alpha = 10f64.powf(-3.0 + 3.3 * i as f64 / 60.0); // 1e-3 … 2
        for j in 0..=200 {
            let u = if j < 100 {
                10f64.powf(-3.0 + 3.0 * j as f64 / 100.0)
            } else {
                1.0 - 10f64.powf(-1.0 - 14.0 * (j - 100) as f64 / 100.0)
            };
            v.push((u, alpha));
        }
    }
    v
}

fn rel(x: f64, y: f64) -> f64 {
    if x == y {
        0.0
    } else {
        (x - y).abs() / x.abs().max(y.abs())
    }
}

#[test]
fn ggx_fast_paths() {
    let (mut e64, mut e32) = (0.0f64, 0.0f64);
    for (u, a) in grid() {
        let n = Ggx::new(a).unwrap();
        for (fast64, fast32, exact) in [
            (ggx::d(u, a), ggx::d(u as f32, a as f32) as f64, n.d(u)),
            (
                ggx::lambda(u, a),
                ggx::lambda(u as f32, a as f32) as f64,
                n.lambda(u),
            ),
            (ggx::g1(u, a), ggx::g1(u as f32, a as f32) as f64, n.g1(u)),
        ] {
            e64 = e64.max(rel(fast64, exact));
            // f32 is judged against the exact value at the f32-rounded inputs.
            let _ = fast32;
        }
        let (u32_, a32) = (u as f32 as f64, a as f32 as f64);
        let n32 = Ggx::new(a32).unwrap();
        e32 = e32
            .max(rel(ggx::d(u32_ as f32, a32 as f32) as f64, n32.d(u32_)))
            .max(rel(
                ggx::lambda(u32_ as f32, a32 as f32) as f64,
                n32.lambda(u32_),
            ))
            .max(rel(ggx::g1(u32_ as f32, a32 as f32) as f64, n32.g1(u32_)));
    }
    println!("GGX fast: f64 {e64:.2e}, f32 {e32:.2e}");
    assert!(e64 <= 1e-14, "{e64}");
    assert!(e32 <= 1e-6, "{e32}");
    // G2 and the edges.
    let n = Ggx::new(0.3).unwrap();
    assert!(rel(ggx::g2(0.4, 0.8, 0.3), n.g2(0.4, 0.8)) < 1e-15);
    assert_eq!(ggx::d(0.0, 0.3), 0.0);
    assert_eq!(ggx::d(-0.5f32, 0.3), 0.0);
    assert_eq!(ggx::lambda(1.0, 0.3), 0.0);
}

#[test]
fn beckmann_fast_paths() {
    let (mut e64_d, mut e64_l, mut e32) = (0.0f64, 0.0f64, 0.0f64);
    for (u, a) in grid() {
        let n = Beckmann::new(a).unwrap();
        let exact_d = n.d(u);
        if exact_d > 1e-300 {
            e64_d = e64_d.max(rel(beckmann::d(u, a), exact_d));
        }
        if u < 1.0 {
            let exact_l = n.lambda(u);
            if exact_l > 1e-300 {
                e64_l = e64_l.max(rel(beckmann::lambda(u, a), exact_l));
            }
        }
        let (u32_, a32) = (u as f32 as f64, a as f32 as f64);
        let n32 = Beckmann::new(a32).unwrap();
        let tan2_over_a2 = (1.0 - u32_ * u32_) / (u32_ * u32_ * a32 * a32);
        if tan2_over_a2 < 80.0 && u32_ < 1.0 {
            e32 = e32.max(rel(
                beckmann::d(u32_ as f32, a32 as f32) as f64,
                n32.d(u32_),
            ));
            let l = n32.lambda(u32_);
            if l > 1e-30 {
                e32 = e32.max(rel(beckmann::lambda(u32_ as f32, a32 as f32) as f64, l));
            }
        }
    }
    println!("Beckmann fast: f64 D {e64_d:.2e}, Λ {e64_l:.2e}; f32 {e32:.2e}");
    assert!(e64_d <= 1e-12, "{e64_d}");
    assert!(e64_l <= 1e-12, "{e64_l}");
    assert!(e32 <= 2e-5, "{e32}");
}

#[test]
fn ggx_fast_vndf_is_the_visible_distribution() {
    use microfacet::chi2::{chi2_test, DcosCoordinates};
    let m = Stretched::new(UnitSlopes::Ggx, 0.3, 0.1).unwrap();
    let coords = Stretched::new(UnitSlopes::Ggx, 0.45, 0.15).unwrap();
    for w in [Vec3::new(0.6, 0.0, 0.8), Vec3::new(0.1, -0.7, 0.707)] {
        let w = w.normalize();
        let r = chi2_test(
            |u| {
                let f = ggx::sample_visible([w.x, w.y, w.z], 0.3, 0.1, u);
                Vec3::new(f[0], f[1], f[2])
            },
            |wm| m.pdf_visible(w, wm),
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
