//! The wavefront slices (`fast::batch`: GGX and Beckmann visible normals, the GGX conductor's
//! eval, pdf and sample) against the scalar `Microfacet` and `Bsdf` calls, element by element,
//! on every instruction set this CPU has, f32 and f64: random directions over the sphere
//! (grazing, below the horizon and non-unit ones for the samplers), anisotropic roughness, and
//! a smooth material.

use microsurface::bsdf::fresnel;
use microsurface::bsdf::{Bsdf, RoughConductor};
use microsurface::fast::batch::{self, GgxConductor, Simd, Vectors, VectorsMut};
use microsurface::{Beckmann, Ggx, Microfacet, MicrofacetDistribution, Real};

/// SplitMix64 uniforms in [0, 1).
struct Rng(u64);
impl Rng {
    fn f64(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// n directions in SoA: uniform on the sphere, a tenth within 1e-4 of the horizon, and (for
/// the samplers, `hostile`) a tenth scaled by 1e±30 or exactly on the horizon.
fn directions(r: &mut Rng, n: usize, hostile: bool) -> [Vec<f64>; 3] {
    let mut v: [Vec<f64>; 3] = Default::default();
    for k in 0..n {
        let z = if k % 10 == 3 {
            (r.f64() - 0.5) * 2e-4
        } else {
            2.0 * r.f64() - 1.0
        };
        let p = std::f64::consts::TAU * r.f64();
        let s = (1.0 - z * z).sqrt();
        let mut w = [s * p.cos(), s * p.sin(), z];
        if hostile && k % 10 == 7 {
            let scale = [1e-30, 1e30, 1.0][k % 3];
            w = w.map(|x| x * scale);
            if k % 3 == 2 {
                w[2] = 0.0;
            }
        }
        for c in 0..3 {
            v[c].push(w[c]);
        }
    }
    v
}

fn conv<F: Real>(v: &[f64]) -> Vec<F> {
    v.iter().map(|&x| F::from_f64(x)).collect()
}

fn sets() -> Vec<Simd> {
    [Simd::Generic, Simd::Avx2, Simd::Avx512]
        .into_iter()
        .filter(|&s| s <= batch::detected_simd())
        .collect()
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a == b) || (a.is_nan() && b.is_nan()) || (a - b).abs() <= tol * a.abs().max(b.abs())
}

/// GGX and Beckmann visible normals: the slice against `sample_wm`, per element, components
/// within `tol` (GGX: the f32 azimuth polynomial; Beckmann: the slices' e^x from
/// `fast::arith` where the scalar sampler calls libm, ~1e-16 apart in x̃, which the f32
/// normal rounds away or onto the neighbouring f32).
macro_rules! vndf_test {
    ($name:ident, $F:ty, $ggx:path, $beckmann:path, $tol:expr) => {
        #[test]
        fn $name() {
            let mut r = Rng(1);
            let n = 5000;
            let w = directions(&mut r, n, true).map(|c| conv::<$F>(&c));
            let u0: Vec<$F> = (0..n)
                .map(|k| if k % 97 == 0 { 0.0 } else { r.f64() as $F })
                .collect();
            let u1: Vec<$F> = (0..n)
                .map(|k| {
                    if k % 89 == 0 {
                        1.0 - <$F>::EPSILON
                    } else {
                        r.f64() as $F
                    }
                })
                .collect();
            let mut out: [Vec<$F>; 3] = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
            for simd in sets() {
                batch::cap_simd(Some(simd));
                for (ax, ay) in [(0.3, 0.3), (0.5, 0.05), (1e-3, 2.0), (1.0, 1.0)] {
                    let g = Microfacet::<$F, Ggx>::new(ax, ay).unwrap();
                    let b = Microfacet::<$F, Beckmann>::new(ax, ay).unwrap();
                    for beckmann in [false, true] {
                        {
                            let wv = Vectors {
                                x: &w[0],
                                y: &w[1],
                                z: &w[2],
                            };
                            let [ox, oy, oz] = &mut out;
                            let o = VectorsMut {
                                x: ox,
                                y: oy,
                                z: oz,
                            };
                            if beckmann {
                                $beckmann(&b, wv, &u0, &u1, o);
                            } else {
                                $ggx(&g, wv, &u0, &u1, o);
                            }
                        }
                        let mut worst = 0.0f64;
                        for i in 0..n {
                            let wi = [w[0][i], w[1][i], w[2][i]];
                            let ui = [u0[i], u1[i]];
                            let want = if beckmann {
                                b.sample_wm(wi, ui)
                            } else {
                                g.sample_wm(wi, ui)
                            };
                            let got = [out[0][i], out[1][i], out[2][i]];
                            for c in 0..3 {
                                let (a, e) = (got[c] as f64, want[c] as f64);
                                assert!(
                                    a.is_finite() == e.is_finite(),
                                    "{simd:?} {i}: {got:?} {want:?}"
                                );
                                if a.is_finite() {
                                    worst = worst.max((a - e).abs());
                                }
                            }
                        }
                        println!(
                            "{simd:?} {} α=({ax},{ay}) beckmann={beckmann}: worst {worst:e}",
                            stringify!($F)
                        );
                        assert!(worst <= $tol, "{simd:?} α=({ax},{ay}): {worst:e}");
                    }
                }
            }
            batch::cap_simd(None);
        }
    };
}

vndf_test!(
    vndf_slices_f32,
    f32,
    batch::ggx_sample_visible_f32,
    batch::beckmann_sample_visible_f32,
    2e-6
);
vndf_test!(
    vndf_slices_f64,
    f64,
    batch::ggx_sample_visible_f64,
    batch::beckmann_sample_visible_f64,
    1e-13
);

/// The GGX conductor's eval, pdf and sample slices against the scalar BSDF, per element.
macro_rules! conductor_test {
    ($name:ident, $F:ty, $eval:path, $sample:path, $tol:expr) => {
        #[test]
        fn $name() {
            let mut r = Rng(2);
            let n = 4000;
            let wo = directions(&mut r, n, false).map(|c| conv::<$F>(&c));
            let wi = directions(&mut r, n, false).map(|c| conv::<$F>(&c));
            let u0: Vec<$F> = (0..n).map(|_| r.f64() as $F).collect();
            let u1: Vec<$F> = (0..n).map(|_| r.f64() as $F).collect();
            let gold = fresnel::Conductor { eta: [0.14, 0.42, 1.37], k: [3.98, 2.38, 1.60] };
            let zeros = || -> [Vec<$F>; 3] { [vec![0.0; n], vec![0.0; n], vec![0.0; n]] };
            for simd in sets() {
                batch::cap_simd(Some(simd));
                for (ax, ay, separable) in
                    [(0.3, 0.3, false), (0.5, 0.05, true), (1.0, 2.0, false), (1e-4, 1e-4, false)]
                {
                    let mut b: GgxConductor<$F> =
                        RoughConductor::new(Microfacet::<$F, Ggx>::new(ax, ay).unwrap(), gold);
                    if separable {
                        b = b.with_masking(microsurface::bsdf::Masking::Separable);
                    }
                    let (mut f, mut pdf) = (zeros(), vec![0.0; n]);
                    {
                        let [f0, f1, f2] = &mut f;
                        $eval(
                            &b,
                            Vectors { x: &wo[0], y: &wo[1], z: &wo[2] },
                            Vectors { x: &wi[0], y: &wi[1], z: &wi[2] },
                            [f0, f1, f2],
                            &mut pdf,
                        );
                    }
                    let mut worst = 0.0f64;
                    for i in 0..n {
                        let (o, v) = ([wo[0][i], wo[1][i], wo[2][i]], [wi[0][i], wi[1][i], wi[2][i]]);
                        let (fe, pe) = (b.eval(o, v), b.pdf(o, v));
                        for (a, e) in [(f[0][i], fe[0]), (f[1][i], fe[1]), (f[2][i], fe[2]), (pdf[i], pe)] {
                            let (a, e) = (a as f64, e as f64);
                            assert!(close(a, e, $tol), "{simd:?} eval {i}: {a} vs {e}");
                            if e != 0.0 {
                                worst = worst.max((a - e).abs() / e.abs());
                            }
                        }
                    }
                    let (mut wis, mut f, mut pdf) = (zeros(), zeros(), vec![0.0; n]);
                    {
                        let [x, y, z] = &mut wis;
                        let [f0, f1, f2] = &mut f;
                        $sample(
                            &b,
                            Vectors { x: &wo[0], y: &wo[1], z: &wo[2] },
                            &u0,
                            &u1,
                            VectorsMut { x, y, z },
                            [f0, f1, f2],
                            &mut pdf,
                        );
                    }
                    let mut rejected = 0;
                    for i in 0..n {
                        let o = [wo[0][i], wo[1][i], wo[2][i]];
                        let got = ([wis[0][i], wis[1][i], wis[2][i]], [f[0][i], f[1][i], f[2][i]], pdf[i]);
                        match b.sample(o, 0.0, [u0[i], u1[i]]) {
                            None => {
                                rejected += 1;
                                assert_eq!(got.2, 0.0, "{simd:?} sample {i}: rejected by the scalar");
                            }
                            Some(s) => {
                                assert!(got.2 > 0.0, "{simd:?} sample {i}: rejected by the slice");
                                for c in 0..3 {
                                    let (a, e) = (got.0[c] as f64, s.wi[c] as f64);
                                    assert!((a - e).abs() <= 10.0 * $tol, "{simd:?} wi {i}: {a} vs {e}");
                                    let (a, e) = (got.1[c] as f64, s.f[c] as f64);
                                    assert!(close(a, e, 50.0 * $tol), "{simd:?} f {i}: {a} vs {e}");
                                }
                                assert!(close(got.2 as f64, s.pdf as f64, 50.0 * $tol), "{simd:?} pdf {i}");
                            }
                        }
                    }
                    println!(
                        "{simd:?} {} α=({ax},{ay}): eval worst {worst:e}, {rejected} rejected of {n}",
                        stringify!($F)
                    );
                }
            }
            batch::cap_simd(None);
        }
    };
}

conductor_test!(
    conductor_slices_f32,
    f32,
    batch::ggx_conductor_eval_f32,
    batch::ggx_conductor_sample_f32,
    2e-6
);
conductor_test!(
    conductor_slices_f64,
    f64,
    batch::ggx_conductor_eval_f64,
    batch::ggx_conductor_sample_f64,
    1e-13
);
