//! What the report's sections share: grids of sample points, the NDFs' short names and the
//! materials of the BSDF sections (through the run-time door).

use microsurface::{AnyMicrofacet, NdfKind};

pub(super) fn grid(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| a + (b - a) * i as f64 / (n - 1) as f64)
        .collect()
}

/// The short name of an NDF in plot titles.
pub(super) fn short(kind: NdfKind) -> &'static str {
    match kind {
        NdfKind::Beckmann => "Beckmann",
        NdfKind::Ggx => "GGX",
        NdfKind::Gtr => "GTR",
        NdfKind::DoubleGgx => "Double GGX",
        NdfKind::Exponential => "Exponential",
        NdfKind::StudentT => "Student-T",
        NdfKind::Ei => "Ei",
        NdfKind::Erfc => "Erfc",
        NdfKind::K0 => "K0",
        NdfKind::BesselK => "Bessel-K",
        NdfKind::GenExponential => "GenExp",
    }
}

/// The f64 material of `kind` at (α, α) (GTR at γ) through the run-time door. (These
/// sections cover [`NdfKind::CLASSIC`]: GTR is the one with a shape.)
pub(super) fn material(kind: NdfKind, alpha: f64, gamma: f64) -> AnyMicrofacet<f64> {
    let shape = kind.shape_name().map(|_| gamma);
    AnyMicrofacet::new(kind, alpha, alpha, shape).expect("the report's parameters are valid")
}
