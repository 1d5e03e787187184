//! What a renderer imports in one line: `use microsurface::prelude::*;`. The materials
//! (static [`Microfacet`], run-time [`AnyMicrofacet`], the NDF names), the direction trait,
//! the BSDF trait and every BSDF, the Fresnel terms, the shading frame and the typed errors.

pub use crate::bsdf::frame::Frame;
pub use crate::bsdf::fresnel::{self, Fresnel};
pub use crate::bsdf::{
    Bsdf, BsdfSample, Lobe, Masking, RoughConductor, RoughDielectric, Transport,
};
pub use crate::distribution::{AnyMicrofacet, Microfacet, MicrofacetDistribution, Sample};
pub use crate::ndf::{
    Beckmann, BesselK, DoubleGgx, Ei, Erfc, Exponential, Ggx, Gtr, NdfKind, NdfSpec, SpecError,
    StudentT, K0,
};
pub use crate::scattering::{
    CompensatedConductor, CompensatedDielectric, DielectricFacets, MirrorFacets,
    MultipleScattering, Scheme,
};
pub use crate::{ParamError, Real};
