//! Lookup tables for real-time engines: the file formats they are written in.
pub mod format;
