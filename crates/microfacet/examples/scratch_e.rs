use microfacet::{AnyNdf, Distribution, Exact, NdfKind, RadialSlopes};
fn main() {
    let n = AnyNdf::new(NdfKind::Ei, 0.3, None).unwrap();
    let e = Exact::new(NdfKind::Ei, 0.3, 0.3, None).unwrap();
    let mut s = 12345u64;
    let mut next = || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let rs = [0.05, 0.1, 0.2, 0.3, 0.5, 1.0];
    let mut counts = [0usize; 6];
    let mut pdfratio = 0.0;
    let nn = 200000;
    for _ in 0..nn {
        let u = [next(), next()];
        let smp = e.sample_dcos(u);
        let wm = smp.wm;
        let t = (wm[0].hypot(wm[1])) / wm[2];
        for (k, &r) in rs.iter().enumerate() {
            if t < r {
                counts[k] += 1;
            }
        }
        pdfratio += smp.pdf / e.pdf_dcos(wm);
    }
    for (k, &r) in rs.iter().enumerate() {
        println!(
            "r {r}: sampled {:.5} cdf {:.5}",
            counts[k] as f64 / nn as f64,
            n.slope_cdf(r)
        );
    }
    println!("pdf ratio {}", pdfratio / nn as f64);
    // pdf vs D·cos
    let wm = [0.1f64, 0.05, (1.0f64 - 0.0125).sqrt()];
    println!("pdf_dcos {} d*cos {}", e.pdf_dcos(wm), e.d(wm) * wm[2]);
    use microfacet::Ndf;
    println!("Ndf d {}", n.d(wm[2]) * wm[2]);
}
