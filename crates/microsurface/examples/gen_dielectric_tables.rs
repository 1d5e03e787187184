//! Generates the shipped dielectric compensation tables, `data/compensation/*-dielectric.mfd`
//! (the format: `microsurface::scattering::dielectric_table_bytes`), for Beckmann, GGX, Double
//! GGX, the Exponential NDF and GTR γ = 1:
//!
//! ```text
//! cargo run --release -p microsurface --example gen_dielectric_tables [THREADS [NAME ...]]
//! ```

use microsurface::scattering::dielectric_table_bytes;
use microsurface::NdfKind;

fn main() {
    let threads = std::env::args()
        .nth(1)
        .and_then(|t| t.parse().ok())
        .unwrap_or(2);
    // Only the NDFs named after the thread count, if any.
    let only: Vec<String> = std::env::args().skip(2).collect();
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/data/compensation");
    for (kind, gamma, name) in [
        (NdfKind::Beckmann, None, "beckmann"),
        (NdfKind::Ggx, None, "ggx"),
        (NdfKind::DoubleGgx, None, "double_ggx"),
        (NdfKind::Exponential, None, "exponential"),
        (NdfKind::Gtr, Some(1.0), "gtr1"),
    ] {
        if !only.is_empty() && !only.iter().any(|o| o == name) {
            continue;
        }
        let t = std::time::Instant::now();
        let bytes = dielectric_table_bytes(kind, gamma, threads).expect("valid NDF parameters");
        let path = format!("{dir}/{name}-dielectric.mfd");
        std::fs::write(&path, &bytes).expect("write the table");
        eprintln!(
            "{path}: {} bytes, {:.0} s",
            bytes.len(),
            t.elapsed().as_secs_f64()
        );
    }
}
