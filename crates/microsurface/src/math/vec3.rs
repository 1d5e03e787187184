//! A minimal concrete 3-vector for directions in the local shading frame (z = macro normal).

use std::ops::{Add, Mul, Neg, Sub};

/// A 3-vector of f64.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Vec3 {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

impl Vec3 {
    pub const Z: Vec3 = Vec3 {
        x: 0.0,
        y: 0.0,
        z: 1.0,
    };

    #[inline]
    pub const fn new(x: f64, y: f64, z: f64) -> Self {
        Vec3 { x, y, z }
    }

    #[inline]
    pub fn dot(self, o: Vec3) -> f64 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// |self| to ~1 ulp for every finite vector (the crate-private `hypot`: a sum of squares where the squares are safe).
    #[inline]
    pub fn length(self) -> f64 {
        let s = self.x * self.x + self.y * self.y + self.z * self.z;
        if (SQUARES_SAFE_LO..SQUARES_SAFE_HI).contains(&s) {
            s.sqrt()
        } else {
            self.x.hypot(self.y).hypot(self.z)
        }
    }

    /// The unit vector along `self`; the zero vector (or a non-finite one) maps to +z, so
    /// that nothing downstream sees a NaN.
    #[inline]
    pub fn normalize(self) -> Vec3 {
        let l = self.length();
        if l > 0.0 && l.is_finite() {
            Vec3::new(self.x / l, self.y / l, self.z / l)
        } else {
            Vec3::Z
        }
    }

    /// The unit vector along `self` for any finite nonzero vector (lengths from subnormal to
    /// f64::MAX: the length is formed without over- or underflow); NaN components for a zero
    /// or non-finite vector, which has no direction.
    #[inline]
    pub fn to_unit(self) -> Vec3 {
        let s = self.x * self.x + self.y * self.y + self.z * self.z;
        if (SQUARES_SAFE_LO..SQUARES_SAFE_HI).contains(&s) {
            let l = s.sqrt();
            return Vec3::new(self.x / l, self.y / l, self.z / l);
        }
        // Divided by the largest magnitude first: the length of (1.7e308, 0, 1.7e308)
        // itself overflows.
        let m = self.x.abs().max(self.y.abs()).max(self.z.abs());
        if !(m > 0.0 && m.is_finite()) || self.x.is_nan() || self.y.is_nan() || self.z.is_nan() {
            return Vec3::new(f64::NAN, f64::NAN, f64::NAN);
        }
        let v = Vec3::new(self.x / m, self.y / m, self.z / m);
        let l = v.length();
        Vec3::new(v.x / l, v.y / l, v.z / l)
    }

    /// The unit normal with slopes (p, q): (−p, −q, 1)/√(1 + p² + q²), computed without
    /// overflow for huge slopes.
    #[inline]
    pub fn from_slopes(p: f64, q: f64) -> Vec3 {
        let s = p.abs().max(q.abs());
        if s > 1e150 {
            // Grazing normal: the z component underflows relative to the slopes.
            let (pp, qq) = (p / s, q / s);
            let l = pp.hypot(qq);
            return Vec3::new(-pp / l, -qq / l, 1.0 / (s * l));
        }
        Vec3::new(-p, -q, 1.0).normalize()
    }
}

/// Where a sum of squares is formed without loss: above 1e-290 a square that underflowed
/// (below 1e-308) changes the sum by < 1e-18 relative; below 1e290 nothing overflows.
const SQUARES_SAFE_LO: f64 = 1e-290;
const SQUARES_SAFE_HI: f64 = 1e290;

/// √(x² + y²) to ~1 ulp without spurious over- or underflow: the plain square root of the sum
/// where the squares are safe, libm's `hypot` (slower, and a large share of a χ² test's
/// time: BENCHMARKS.md) only outside that range.
#[inline]
pub(crate) fn hypot(x: f64, y: f64) -> f64 {
    let s = x * x + y * y;
    if (SQUARES_SAFE_LO..SQUARES_SAFE_HI).contains(&s) {
        s.sqrt()
    } else {
        x.hypot(y)
    }
}

impl Add for Vec3 {
    type Output = Vec3;
    #[inline]
    fn add(self, o: Vec3) -> Vec3 {
        Vec3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl Sub for Vec3 {
    type Output = Vec3;
    #[inline]
    fn sub(self, o: Vec3) -> Vec3 {
        Vec3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl Mul<f64> for Vec3 {
    type Output = Vec3;
    #[inline]
    fn mul(self, s: f64) -> Vec3 {
        Vec3::new(self.x * s, self.y * s, self.z * s)
    }
}

impl Neg for Vec3 {
    type Output = Vec3;
    #[inline]
    fn neg(self) -> Vec3 {
        Vec3::new(-self.x, -self.y, -self.z)
    }
}

impl From<[f64; 3]> for Vec3 {
    #[inline]
    fn from(v: [f64; 3]) -> Vec3 {
        Vec3::new(v[0], v[1], v[2])
    }
}

impl From<Vec3> for [f64; 3] {
    #[inline]
    fn from(v: Vec3) -> [f64; 3] {
        [v.x, v.y, v.z]
    }
}
