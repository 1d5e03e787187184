//! The library's one random generator: SplitMix64 (Steele, Lea & Flood 2014), 64 bits of
//! state, a Weyl increment and a 64-bit finaliser. Every stream in the library is one of
//! these: the rejection samplers' [`crate::distribution::UniformStream`] (seeded by the bits
//! of u), the random walk's [`crate::scattering::WalkRng`] and the χ² harness's uniforms.

/// SplitMix64 with its state public (the χ² harness and the tests seed it directly).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    /// The next 64 random bits.
    #[inline(always)]
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1) with 53 random bits.
    #[inline(always)]
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / 9_007_199_254_740_992.0)
    }
}
