//! Energy compensation: see the [`crate::scattering`] docs.
//!
//! [`AlbedoTable`] and [`DielectricTables`] (the shipped data, its file format and its
//! generator) are in `tables.rs`; the compensated BSDFs in `conductor.rs` and
//! `dielectric.rs`.

mod conductor;
mod dielectric;
mod tables;

pub use conductor::CompensatedConductor;
pub use dielectric::CompensatedDielectric;

pub use tables::{dielectric_table_bytes, AlbedoTable, DielectricTables, AZIMUTHS, SHIPPED_ETAS};

/// Which compensation: see the [module docs](crate::scattering).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scheme {
    /// An added diffuse-like lobe (Kulla & Conty 2017).
    KullaConty,
    /// The single-scattering lobe scaled (Turquin 2019).
    Turquin,
}
