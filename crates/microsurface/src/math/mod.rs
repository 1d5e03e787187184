//! The numerical internals (crate-private): special functions, tanh-sinh quadrature (the one
//! rule, its nodes cached), safeguarded Newton, the Smith integral, a 3-vector and the one
//! random generator.

pub(crate) mod dirs;
pub(crate) mod quad;
pub(crate) mod real;
pub(crate) mod rng;
pub(crate) mod smith;
pub(crate) mod solve;
pub(crate) mod special;
pub(crate) mod vec3;
