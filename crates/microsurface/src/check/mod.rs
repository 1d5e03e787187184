//! Checks a researcher runs against the library: the identities that tie the quantities
//! together, each as a residual against an independent quadrature ([`verify`]), and the χ²
//! goodness-of-fit harness of the samplers ([`chi2`]).

pub mod chi2;
#[cfg(test)]
mod fast_samplers;
pub mod verify;

/// Tanh-sinh quadrature as the checks use it (adaptive, finite and half-infinite
/// intervals), for a researcher's own identities.
pub mod quad {
    pub use crate::math::quad::{integrate, integrate_to_inf, Quad};
}
