//! Progress reports and cancellation of the long computations: albedo tables
//! ([`crate::scattering::AlbedoTable::new_with_progress`]), engine LUTs
//! ([`crate::scattering::lut::Lut::compute`]) and walk tables
//! ([`crate::scattering::table::Grid::generate`]).
//!
//! Each takes a `&dyn` [`Progress`]: any `Fn(done, total) + Sync` closure (reported to,
//! never cancelled), or a [`Cancellable`], a closure with a [`Cancel`] token that another
//! thread may trip (a Ctrl-C handler, a UI's stop button, Python's KeyboardInterrupt). The
//! loops ask after each unit of work (a node, a chunk of walks: at most tenths of a second
//! each) and, once cancelled, stop taking new work and return [`Cancelled`] (or their error
//! type's `Cancelled`); nothing partial is cached.

use std::fmt;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// What a long computation reports to, and asks whether to stop.
pub trait Progress: Sync {
    /// `done` of `total` units are finished (called from any thread, in any order).
    fn report(&self, done: usize, total: usize);
    /// Whether to stop: asked before each unit of work.
    fn cancelled(&self) -> bool {
        false
    }
}

impl<P: Fn(usize, usize) + Sync> Progress for P {
    fn report(&self, done: usize, total: usize) {
        self(done, total)
    }
}

/// A cancellation flag shared by clones (`Arc<AtomicBool>`): [`Cancel::cancel`] on one
/// clone is seen by every other.
#[derive(Clone, Debug, Default)]
pub struct Cancel(Arc<AtomicBool>);

impl Cancel {
    /// A token not yet cancelled.
    pub fn new() -> Self {
        Self::default()
    }
    /// Asks every computation holding a clone to stop.
    pub fn cancel(&self) {
        self.0.store(true, Ordering::Relaxed);
    }
    /// Whether [`Cancel::cancel`] was called.
    pub fn is_cancelled(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }
}

/// A progress closure with a cancellation token.
#[derive(Clone, Debug)]
pub struct Cancellable<P> {
    /// Told `(done, total)`.
    pub progress: P,
    /// Asked whether to stop.
    pub cancel: Cancel,
}

impl<P: Fn(usize, usize) + Sync> Progress for Cancellable<P> {
    fn report(&self, done: usize, total: usize) {
        (self.progress)(done, total)
    }
    fn cancelled(&self) -> bool {
        self.cancel.is_cancelled()
    }
}

/// A computation stopped by its [`Cancel`] token.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Cancelled;

impl fmt::Display for Cancelled {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("cancelled")
    }
}

impl std::error::Error for Cancelled {}
