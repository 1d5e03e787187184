//! The floating-point trait of every precision-generic path (the renderer layer's f32 and
//! f64): below every folder that computes, so that none imports another for it.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// The floating-point operations the precision-generic paths need; implemented for f32 and
/// f64 (public as `microsurface::Real` and `microsurface::fast::Real`).
pub trait Real:
    Copy
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    const ZERO: Self;
    const ONE: Self;
    const HALF: Self;
    const PI: Self;
    /// e^{−x} is 0 in this precision beyond this x.
    const EXP_ZERO: Self;
    /// Whether this is f32: the fitted paths with a native single-precision form (f32
    /// tables and arithmetic) take it on this constant, a branch the compiler removes.
    const IS_F32: bool;
    /// Widening to f64 (exact).
    fn to_f64(self) -> f64;
    /// Rounding from f64.
    fn from_f64(x: f64) -> Self;
    /// To f32 (the identity for f32; rounding for f64, never taken where `IS_F32` is false).
    fn to_f32(self) -> f32;
    /// From f32 (exact).
    fn from_f32(x: f32) -> Self;
    fn sqrt(self) -> Self;
    fn exp(self) -> Self;
    fn sin_cos(self) -> (Self, Self);
    fn max(self, o: Self) -> Self;
    fn min(self, o: Self) -> Self;
    fn abs(self) -> Self;
}

macro_rules! real {
    ($t:ty, $zero:expr, $is_f32:expr) => {
        impl Real for $t {
            const EXP_ZERO: Self = $zero;
            const IS_F32: bool = $is_f32;
            #[inline(always)]
            fn to_f64(self) -> f64 {
                self as f64
            }
            #[inline(always)]
            fn from_f64(x: f64) -> Self {
                x as $t
            }
            #[inline(always)]
            fn to_f32(self) -> f32 {
                self as f32
            }
            #[inline(always)]
            fn from_f32(x: f32) -> Self {
                x as $t
            }
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const HALF: Self = 0.5;
            const PI: Self = std::f64::consts::PI as $t;
            #[inline(always)]
            fn sqrt(self) -> Self {
                <$t>::sqrt(self)
            }
            #[inline(always)]
            fn exp(self) -> Self {
                <$t>::exp(self)
            }
            #[inline(always)]
            fn sin_cos(self) -> (Self, Self) {
                <$t>::sin_cos(self)
            }
            #[inline(always)]
            fn max(self, o: Self) -> Self {
                <$t>::max(self, o)
            }
            #[inline(always)]
            fn min(self, o: Self) -> Self {
                <$t>::min(self, o)
            }
            #[inline(always)]
            fn abs(self) -> Self {
                <$t>::abs(self)
            }
        }
    };
}
// e^{−x} underflows past 745.2 in f64 and past 103.98 in f32.
real!(f64, 745.2, false);
real!(f32, 103.98, true);
