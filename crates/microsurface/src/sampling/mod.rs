//! Sampling of the 1-D NDF types (the research layer): the D·cos radial slope CDFs, their
//! quantiles and the warps built on them ([`RadialSlopes`]), the visible-slope CDFs of the
//! α = 1 distributions and their inversion ([`UnitSlopes`]), and the pages' own stochastic
//! samplers ([`stochastic`], behind `rand::distr::Distribution`). A renderer samples through
//! [`crate::distribution`]'s materials, whose samplers are built on these.

pub(crate) mod dcos;
pub mod stochastic;
pub(crate) mod visible;

pub use dcos::*;
pub use visible::*;
