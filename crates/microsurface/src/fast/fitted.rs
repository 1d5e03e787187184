//! The family's fast path: Λ of any shape-invariant Beckmann mixture (Student-T, Ei, Erfc,
//! K0, Bessel-K) from a table fitted once per shape at construction, and its samplers.
//!
//! Every member is shape invariant, so Λ(u; α) = Λ₁(z) with z = cot θ/α: one table of the α = 1
//! member serves every roughness, and anisotropy through z = |w.z|/|(αx wx, αy wy)|, formed
//! from the direction vector (not from its cosine, whose 1 − u² near the normal carries u's
//! rounding).
//! [`FittedShape::new`] fits log₂ Λ₁ by Chebyshev interpolation of the exact Λ (degree 6, eighth
//! octaves of z, the layout of `fit`) on [2^−24, 2^k₁), re-expanded to degree 4 on 32 rows
//! per octave; evaluation is the row's polynomial and one exponential, `arith::exp2_256` (the table
//! holds 256 log₂ Λ₁: a table of 256 powers 2^(j/256) and a quadratic, 5e-10, inlined: faster than
//! libm's `exp` there; BENCHMARKS.md compares a Λ(w) with GGX's closed form through the same type).
//! Where Λ₁ itself fits as well (within 1e-8 at every segment's ends and middle: Student-T at
//! γ ≤ 3, whose power-law tail has a bounded log-derivative) the table holds Λ₁ and there is no
//! exponential ([`FittedShape::is_direct`]), which is faster. The exponential tails of the others
//! need the logarithm. ln Λ₁ is smooth on both sides: ~ln(σ₁(0)/z) at grazing, and near the normal
//! −z² (Ei, Erfc: Beckmann-like tails), −2z (K0, Bessel-K: exponential ones) or −(2γ − 2) ln z
//! (Student-T's power law), where Λ₁ itself falls by orders of magnitude across a segment and no
//! short polynomial follows it in relative terms. The ends:
//! * z < 2^−24: Λ₁ = σ₁(0)/z − ½ (the next term, z P2₁(0)/2, or z ln z where P2₁(0) = ∞, is
//!   below 1e-13 relative there);
//! * z ≥ 2^k₁: exponential tails — the table runs until Λ₁ < 1e-300 and is 0 beyond (k₁ ≤ 10);
//!   Student-T — Λ₁ = K z^{−p}(1 + K₂/z²), p = 2γ − 2 (its P2 ~ q^{1−2γ}(1 + c/q²)^{½−γ},
//!   c = γ − 1, expands in γc/q²), matched to the exact Λ₁ at 2^k₁ and 2^{k₁+1}, with
//!   2^k₁ ≥ 2^10 γ (the next term is O((γ²/z²)²) ≤ 1e-12 relative; at 2^10 √(γ − 1) it was
//!   3.6e-7 at γ = 50), or the table runs until Λ₁ underflows where that comes first.
//!
//! Accuracy (tests/fast.rs, every member over its shape range, z from 1e-9 to 1e6): relative
//! ≤ 1e-7 where Λ ≥ 1e-200; below, a segment with a node under 1e-300 returns 2^−1000 ≈ 9e-302
//! (there Λ₁ falls by up to 1e-73 across an eighth octave, Ei at z ≈ 26; the value keeps the
//! exponential's argument in its range), so the error is absolute, ≤ 1e-200, and
//! G1 = 1/(1 + Λ) is 1 either way.
//!
//! D is the exact closed form (f64) at the normal's stretched slopes — for Bessel-K, whose
//! closed form needs K_ν of real order (a trapezoidal rule per call), from a table of
//! ln K_ν(y) + y fitted per shape (`BesselProfile`: within 1e-13 + 8ε(|ln K| + y) of the
//! exact ln K_ν, so D within about 1e-12 relative, the exact form's own rounding) — and the
//! samplers: D·cos by the radial quantile of the α = 1 member for Student-T (closed form), by
//! the prior's β and Beckmann's D·cos for the others (`sample_dcos`), visible normals by the
//! mixing variable's posterior (`mixture::Posterior`; then
//! Beckmann's stream sampler; a fraction of a microsecond), its uniforms after u's from a
//! [`crate::distribution::UniformStream`] seeded by u. Accuracy and cost: tests/fast.rs and
//! BENCHMARKS.md (the family's fast path).

use super::fit;
use crate::error::ParamError;
use crate::ndf::mixture::Posterior;
use crate::ndf::Ndf;
use crate::sampling::dcos::RadialSlopes;
use crate::AnyNdf;

/// Coefficients per fitted segment (degree 6).
const N_FIT: usize = 7;
/// 2^M_FIT fitted segments per octave of z.
const M_FIT: u32 = 3;
/// Coefficients per row of the evaluated table (degree 4), on 2^M rows per octave: each
/// fitted segment re-expanded onto 4 equal pieces (no new exact evaluations), as GTR's
/// tables are (fast::gtr): a shorter dependency chain than the degree-6 Estrin scheme
/// (BENCHMARKS.md).
const N: usize = 5;
const M: u32 = M_FIT + 2;
/// The table starts at z = 2^K0 (the grazing end, module docs).
const K0: i32 = -24;
/// The tables end at most here: Λ₁ underflows before z = 2^10 for every member and shape
/// with an exponential tail (Bessel-K's e^{−2z} at z ≈ 350); Student-T's power law goes on,
/// to 2^10 γ at most (the module docs).
const K_MAX: i32 = 40;
/// Below this Λ₁ is treated as 0 (a segment with a node below it evaluates to e^{−800} = 0).
const TINY: f64 = 1e-300;
/// 256 log₂ Λ₁ of an underflowed segment: 2^−1000 = 9e-302 (within the absolute 1e-200
/// of the module docs, and inside [`super::arith::exp2_256`]'s range, which has no check).
const LOG2_ZERO: f64 = -1000.0 * 256.0;
/// The largest relative error of a Λ₁ table at the fitted segments' ends and middles for
/// which it replaces the log₂ Λ₁ table (10× inside the 1e-7 required, as fast::gtr's).
const DIRECT_TOL: f64 = 1e-8;

/// Bessel-K's K_ν table: 2^MK rows per octave of y = 2x, degree NK − 1, on [2^KK0, 2^KK1):
/// within 1e-13 + 8ε(|ln K| + y) of `ln_bessel_k` (the unit test below, every a), the range
/// where P22₁ is neither on the small-argument series (x < 1e-150) nor below 1e-300 (y ≳ 700).
const NK: usize = 8;
const MK: u32 = 4;
const KK0: i32 = -20;
const KK1: i32 = 10;

/// Bessel-K's profile P22₁(x) = 2 x^ν K_ν(2x)/(π Γ(a)), ν = a − 1, from a table of
/// g(y) = ln K_ν(y) + y fitted per shape (ν is fixed by the shape; the linear part of
/// ln K_ν, −y, taken out, g is smooth on octaves of y: ~ln Γ(|ν|)/2 + |ν| ln(2/y) or
/// ln ln(2/y) at small y, −½ ln(2y/π) at large y): ln P22₁ = ν ln x + g(2x) − 2x + c, one
/// polynomial, a logarithm and an exponential instead of the trapezoidal rule of
/// `ln_bessel_k` per call.
#[derive(Clone, Debug)]
struct BesselProfile {
    nu: f64,
    /// ln 2 − ln Γ(a) − ln π.
    c: f64,
    coef: Vec<[f64; NK]>,
}

impl BesselProfile {
    fn new(a: f64) -> Self {
        use crate::math::special::{ln_bessel_k, ln_gamma};
        let nu = a - 1.0;
        BesselProfile {
            nu,
            c: std::f64::consts::LN_2 - ln_gamma(a) - std::f64::consts::PI.ln(),
            coef: fit::fit_octaves::<NK>(KK0, KK1, MK, |y| ln_bessel_k(nu, y) + y),
        }
    }

    /// P22₁(x) where 2x is in the table (`None` elsewhere, NaN included).
    #[inline]
    fn p22(&self, x: f64) -> Option<f64> {
        let y = 2.0 * x;
        if !(y >= fit::pow2(KK0) && y < fit::pow2(KK1)) {
            return None;
        }
        let g = fit::eval(&self.coef, KK0, MK, y);
        Some((self.nu * x.ln() + g - y + self.c).exp())
    }
}

/// Λ₁ past the table.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Tail {
    /// 0 (the table runs until Λ₁ underflows).
    Zero,
    /// e^{ln K − p ln z}(1 + K₂/z²).
    Power { p: f64, ln_k: f64, k2: f64 },
}

/// [`FittedShape::layout`]: the fitted Λ₁ table and the posterior's parameters, for the GPU
/// crate's table generator (not an API).
#[doc(hidden)]
#[derive(Clone, Copy, Debug)]
pub struct ShapeLayout<'a> {
    /// The rows' coefficients (degree 4 in s ∈ [−1, 1), s⁰ first), 2^5 rows per octave of z
    /// from 2^−24.
    pub rows: &'a [[f64; N]],
    /// Whether the rows hold Λ₁ itself (else 256 log₂ Λ₁).
    pub direct: bool,
    /// The table ends at z = 2^k1.
    pub k1: i32,
    /// σ₁(0), the grazing end's Λ₁ = σ₁(0)/z − ½.
    pub sigma0: f64,
    /// Past the table: `None` for 0, `Some([p, ln K, K₂])` for e^{ln K − p ln z}(1 + K₂/z²).
    pub tail: Option<[f64; 3]>,
    /// The mixing density (its parameter k inside: Student-T γ − 1, Bessel-K a, K0 1).
    pub mixing: crate::ndf::mixture::Mixing,
    /// The mixing density's parameter k (0 for the uniform mixings).
    pub mixing_k: f64,
    /// ν = a − 1 where D needs Bessel-K's K_ν profile (`None` for the members whose D is a
    /// cheap closed form).
    pub bessel_nu: Option<f64>,
    /// E[β] of the prior at α = 1.
    pub mean_beta: f64,
}

/// A Beckmann-mixture member prepared for fast Λ, G1, G2 and sampling (see the module docs).
#[derive(Clone, Debug)]
pub struct FittedShape {
    /// The α = 1 member.
    unit: AnyNdf,
    posterior: Posterior,
    /// σ₁(0) = E[p₊] of the α = 1 member.
    sigma0: f64,
    /// 256 log₂ Λ₁ (or Λ₁ where `direct`) on the rows of [2^K0, 2^k1).
    coef: Vec<[f64; N]>,
    direct: bool,
    k1: i32,
    tail: Tail,
    /// Bessel-K's profile table (`None` for the other members, whose D is a cheap closed
    /// form).
    bessel: Option<BesselProfile>,
}

impl FittedShape {
    /// The table of `ndf`'s shape (its α is not used): Student-T (γ > 3/2: Λ is infinite
    /// below), Ei, Erfc, K0 or Bessel-K; `ParamError::Shape` for Student-T γ ≤ 3/2 and for
    /// the NDFs that are not Beckmann mixtures with a posterior sampler. Evaluates the exact Λ
    /// at 7 nodes of 8 segments per octave over 30–44 octaves (1.6k–2.5k evaluations; Bessel-K,
    /// whose Λ integrates K_ν, tens of microseconds each).
    pub fn new(ndf: &AnyNdf) -> Result<FittedShape, ParamError> {
        let posterior =
            ndf.beckmann_mixing()
                .and_then(Posterior::new)
                .ok_or(ParamError::Shape {
                    name:
                        "fitted family member (Student-T with gamma > 1.5, Ei, Erfc, K0, Bessel-K)",
                    range: "(1.5, 1e6]",
                    value: ndf.shape().unwrap_or(f64::NAN),
                })?;
        let unit = ndf.with_alpha(1.0);
        // (At z itself: through a rounded cosine the nodes would carry its rounding, 3e-7 of
        // Λ at z ≈ 8500 for Student-T γ = 10.)
        let lambda = |z: f64| unit.lambda_x(z).unwrap_or(f64::NAN);
        // The first octave where Λ₁ underflows (every tail gets there, Student-T's power law
        // only at large γ).
        let mut k_zero = 4;
        while k_zero < K_MAX && lambda(fit::pow2(k_zero)) >= TINY {
            k_zero += 1;
        }
        let (k1, tail) = match unit {
            AnyNdf::StudentT(t) => {
                // Past 2^10 γ: P2 ~ q^{1−2γ}(1 + c/q²)^{½−γ} (c = γ − 1) expands in γc/q²,
                // so the two-term tail's next term is O((γ²/z²)²) ≤ 1e-12 relative.
                let g = t.gamma();
                let k_power = g.log2().ceil() as i32 + 10;
                let k1 = k_power.min(k_zero);
                let (z1, z2) = (fit::pow2(k1), fit::pow2(k1 + 1));
                let (l1, l2) = (lambda(z1), lambda(z2));
                let tail = if l1 < TINY || l2 < TINY {
                    Tail::Zero
                } else {
                    // ρ = Λ(z2) z2^p/(Λ(z1) z1^p) = (1 + K₂/z2²)/(1 + K₂/z1²).
                    let p = 2.0 * g - 2.0;
                    let rho = (l2.ln() - l1.ln() + p * (z2.ln() - z1.ln())).exp();
                    let k2 = (rho - 1.0) / (1.0 / (z2 * z2) - rho / (z1 * z1));
                    let ln_k = l1.ln() + p * z1.ln() - (k2 / (z1 * z1)).ln_1p();
                    Tail::Power { p, ln_k, k2 }
                };
                (k1, tail)
            }
            _ => (k_zero, Tail::Zero),
        };
        let values = fit::octave_node_values::<N_FIT>(K0, k1, M_FIT, lambda);
        // The fitted segments of g(Λ) re-expanded onto the rows (`zero`: a segment with an
        // underflowed node).
        let table = |g: fn(f64) -> f64, zero: f64| -> Vec<[f64; N]> {
            let pieces = 1usize << (M - M_FIT);
            values
                .iter()
                .flat_map(|v| {
                    let ok = v.iter().all(|&l| l >= TINY && l.is_finite());
                    let c = fit::chebyshev_coefficients(&v.map(g));
                    (0..pieces).map(move |j| {
                        let mut row = [0.0; N];
                        if !ok {
                            row[0] = zero;
                            return row;
                        }
                        // Piece j of the segment's s ∈ [−1, 1], as t ∈ [−1, 1].
                        let h = 2.0 / pieces as f64;
                        fit::chebyshev_fit::<N>(|t| {
                            fit::poly(&c, -1.0 + h * (j as f64 + 0.5 * (t + 1.0)))
                        })
                    })
                })
                .collect()
        };
        // Λ itself where that is accurate (no exponential at evaluation): Student-T's power
        // law at small γ, as GTR's tables (within DIRECT_TOL at every segment's ends and
        // middle, against new exact values); 256 log₂ Λ otherwise.
        let mut direct = false;
        let mut coef = Vec::new();
        if matches!(tail, Tail::Power { .. }) {
            let d = table(|l| l, 0.0);
            let per = 1usize << M_FIT;
            let ok = (0..values.len()).all(|i| {
                let lo = fit::pow2(K0 + (i / per) as i32) * (1.0 + (i % per) as f64 / per as f64);
                let w = fit::pow2(K0 + (i / per) as i32) / per as f64;
                [lo, lo + 0.5 * w, lo + w * (1.0 - 1e-15)].iter().all(|&z| {
                    let want = lambda(z);
                    want < TINY || ((fit::eval(&d, K0, M, z) - want) / want).abs() <= DIRECT_TOL
                })
            });
            if ok {
                direct = true;
                coef = d;
            }
        }
        if !direct {
            coef = table(|l| 256.0 * l.log2(), LOG2_ZERO);
        }
        let bessel = match unit {
            AnyNdf::BesselK(b) => Some(BesselProfile::new(b.a())),
            _ => None,
        };
        Ok(FittedShape {
            sigma0: unit.sigma(0.0),
            unit,
            posterior,
            coef,
            direct,
            k1,
            tail,
            bessel,
        })
    }

    /// The table and sampler parameters as the GPU crate lays them out (not an API).
    #[doc(hidden)]
    pub fn layout(&self) -> ShapeLayout<'_> {
        let (mixing_k, mean_beta) = self.posterior.parameters();
        ShapeLayout {
            rows: &self.coef,
            direct: self.direct,
            k1: self.k1,
            sigma0: self.sigma0,
            tail: match self.tail {
                Tail::Zero => None,
                Tail::Power { p, ln_k, k2 } => Some([p, ln_k, k2]),
            },
            mixing: self.posterior.mixing(),
            mixing_k,
            bessel_nu: self.bessel.as_ref().map(|b| b.nu),
            mean_beta,
        }
    }

    /// Whether the table holds Λ itself (no exponential at evaluation) rather than log₂ Λ.
    pub fn is_direct(&self) -> bool {
        self.direct
    }

    /// The α = 1 member.
    pub fn unit(&self) -> &AnyNdf {
        &self.unit
    }

    /// Λ₁(z), z = cot θ/α ≥ 0 (+∞ at 0, 0 at ∞, NaN for NaN).
    #[inline]
    pub fn lambda_z(&self, z: f64) -> f64 {
        if z >= fit::pow2(K0) && z < fit::pow2(self.k1) {
            let p = fit::eval(&self.coef, K0, M, z);
            // (A per-material constant: the branch is always predicted.)
            return if self.direct {
                p
            } else {
                super::arith::exp2_256(p)
            };
        }
        self.lambda_ends(z)
    }

    #[cold]
    #[inline(never)]
    fn lambda_ends(&self, z: f64) -> f64 {
        if z < fit::pow2(K0) {
            return self.sigma0 / z - 0.5;
        }
        match self.tail {
            _ if z.is_nan() => z,
            Tail::Zero => 0.0,
            Tail::Power { p, ln_k, k2 } => (ln_k - p * z.ln()).exp() * (1.0 + k2 / (z * z)),
        }
    }

    /// Λ(u) at roughness α, u ∈ [0, 1] (the contract's edges as the other fast paths: +∞ at
    /// ±0, Λ(|u|) below 0, 0 past 1, NaN for NaN); evaluated in f64.
    #[inline]
    pub fn lambda<F: super::Real>(&self, u: F, alpha: F) -> F {
        let (u, a) = (u.to_f64(), alpha.to_f64());
        if !(u > 0.0 && u <= 1.0) {
            return F::from_f64(super::lambda_at_edge(u, |v| self.lambda_u(v, a)));
        }
        F::from_f64(self.lambda_u(u, a))
    }

    /// Λ of the direction w at (αx, αy) from its cot θ/α̃ = |w.z|/|(αx wx, αy wy)| (any
    /// length; the projected roughness α̃ implicit): accurate near the normal, where the
    /// cosine alone would lose cot θ to 1 − u²'s rounding. +∞ on the horizon and for w = 0,
    /// NaN for NaN; evaluated in f64.
    #[inline]
    pub fn lambda_vec<F: super::Real>(&self, w: [F; 3], ax: F, ay: F) -> F {
        let (x, y, z) = (
            ax.to_f64() * w[0].to_f64(),
            ay.to_f64() * w[1].to_f64(),
            w[2].to_f64().abs(),
        );
        let h = (x * x + y * y).sqrt();
        if z == 0.0 {
            // (The horizon and w = 0: Λ = ∞, G1 = 0, as the other fast paths.)
            return F::from_f64(if h.is_nan() { h } else { f64::INFINITY });
        }
        F::from_f64(self.lambda_z(z / h))
    }

    #[inline(always)]
    fn lambda_u(&self, u: f64, a: f64) -> f64 {
        self.lambda_z(u / (a * ((1.0 - u) * (1.0 + u)).sqrt()))
    }

    /// D(u) at roughness α: f(tan θ/α)/(α² u⁴), the exact profile f of the α = 1 member (f64;
    /// the edges, and cosines below 1e-60 where u⁴ would underflow, by the exact NDF).
    #[inline]
    pub fn d<F: super::Real>(&self, u: F, alpha: F) -> F {
        let (u, a) = (u.to_f64(), alpha.to_f64());
        if !(u > 1e-60 && u < 1.0) {
            return F::from_f64(self.d_edges(u, a));
        }
        let x = ((1.0 - u) * (1.0 + u)).sqrt() / (u * a);
        let f = match self.bessel.as_ref().and_then(|b| b.p22(x)) {
            Some(f) => f,
            None => self.unit.f(x).unwrap_or(f64::NAN),
        };
        // (Where the profile underflows, far in its tail, D = f/(α² u⁴) may still be a normal
        // float: the exact NDF computes it in logarithms. Student-T γ = 4.94 at α = 1e3,
        // u = 6.5e-41 gave 0 for 5.9e-211.)
        if f < 1e-280 {
            return F::from_f64(self.d_edges(u, a));
        }
        let u2 = u * u;
        F::from_f64(f / (a * a * u2 * u2))
    }

    /// D of the unit normal wm at (αx, αy) through its stretched slopes
    /// g = (x/(αx z), y/(αy z)): P22₁(g)/(αx αy z⁴) (in logarithms below z = 1e-60, where z⁴
    /// underflows; `None` on and below the horizon and for NaN). From the vector, not the cosine: near the pole the cosine
    /// rounds to 1 below slopes ~1e-8 in f64 (~3e-4 in f32), where D(1) is the pole, +∞, of Ei,
    /// Erfc, K0 and Bessel-K a ≤ 1 while D at the slopes is finite; and elsewhere sin²θ from
    /// 1 − u² carries u's rounding, ε/(1 − u), which P22's exponent multiplies (6e-11 of D at
    /// Student-T γ = 50, 1 − u = 5e-5).
    #[inline]
    pub fn d_vec(&self, wm: [f64; 3], ax: f64, ay: f64) -> Option<f64> {
        let z = wm[2];
        // (NaN fails too.)
        if z.is_nan() || z <= 0.0 {
            return None;
        }
        if let Some(b) = &self.bessel {
            if z > 1e-60 {
                let (gx, gy) = (wm[0] / (ax * z), wm[1] / (ay * z));
                if let Some(p) = b.p22((gx * gx + gy * gy).sqrt()) {
                    let z2 = z * z;
                    return Some(p / (ax * ay * z2 * z2));
                }
            }
        }
        Some(self.unit.d_stretched(wm, ax, ay))
    }

    #[cold]
    #[inline(never)]
    fn d_edges(&self, u: f64, a: f64) -> f64 {
        // (The exact NDF at α, clamped into the accepted range: a projected roughness can
        // round past its end; NaN gives NaN.)
        match AnyNdf::new(self.unit.kind(), a.clamp(1e-6, 1e6), self.unit.shape()) {
            Ok(n) => n.d(u),
            Err(_) => f64::NAN,
        }
    }

    /// A D·cos normal at (αx, αy). Student-T: tan θ = r from the α = 1 radial quantile of u₀
    /// (closed form), stretched, azimuth 2πu₁: a warp of u. The others: D·cos of a
    /// superposition of normalised Beckmann components is their D·cos mixed by the prior,
    /// so β from the prior over the [`crate::distribution::UniformStream`] of u (not u itself,
    /// which drives the warp), then Beckmann's D·cos warp of u at β(αx, αy): exact in
    /// distribution and a few Gamma or uniform draws where the radial quantile took a Newton
    /// inversion of a quadrature-backed CDF (microseconds); not a warp of u alone. (The GPU
    /// library's sampler is the same, draw for draw.)
    #[inline]
    pub fn sample_dcos<F: super::Real>(&self, ax: f64, ay: f64, u: [F; 2]) -> [F; 3] {
        if matches!(self.unit, AnyNdf::StudentT(_)) {
            let r = self.unit.slope_quantile(u[0].to_f64());
            return super::normal_from_polar(r, super::cos_sin_turn(u[1].to_f64()), ax, ay);
        }
        let mut s = crate::distribution::UniformStream::new(u);
        let mut ln_beta = self
            .posterior
            .draw_prior_ln_beta(&mut || s.next_uniform::<f64>());
        if ln_beta.is_nan() {
            // (64 rejections of the Gamma variate: probability below 1e-80.)
            ln_beta = self.posterior.parameters().1.ln();
        }
        // β (αx, αy) within [1e-290, 1e290], as the visible sampler's.
        let (lo, hi) = (ax.min(ay).ln(), ax.max(ay).ln());
        let beta = ln_beta.clamp(-667.0 - lo, 667.0 - hi).exp();
        let m = super::beckmann::sample_dcos(beta * ax, beta * ay, [u[0].to_f64(), u[1].to_f64()]);
        [F::from_f64(m[0]), F::from_f64(m[1]), F::from_f64(m[2])]
    }

    /// A visible normal for w (mirrored below the horizon) at (αx, αy) from u and, for
    /// further candidates, the [`crate::distribution::UniformStream`] of u: the posterior
    /// sampler; where it gives up (probability ~1e-19) or w lies on the horizon, Beckmann's
    /// warp at the mean roughness (a visible normal, not this NDF's distribution).
    #[inline]
    pub fn sample_visible<F: super::Real>(&self, w: [F; 3], ax: f64, ay: f64, u: [F; 2]) -> [F; 3] {
        let v = crate::math::vec3::Vec3::from(w.map(|x| x.to_f64())).to_unit();
        let v = if v.z < 0.0 { -v } else { v };
        let mut s = crate::distribution::UniformStream::new(u);
        let mut first = [u[0].to_f64(), u[1].to_f64()].into_iter();
        let mut next = || first.next().unwrap_or_else(|| s.next_uniform::<f64>());
        match self
            .posterior
            .sample_visible::<F>(v.into(), ax, ay, &mut next)
        {
            Some(m) => m,
            None => super::beckmann::sample_visible(w, F::from_f64(ax), F::from_f64(ay), u),
        }
    }

    /// [`crate::MicrofacetDistribution::sample_wm_stream`]: the posterior sampler above the horizon,
    /// `None` below.
    #[inline]
    pub fn sample_visible_stream<F: super::Real>(
        &self,
        v: [F; 3],
        ax: f64,
        ay: f64,
        uniform: &mut dyn FnMut() -> F,
    ) -> Option<[F; 3]> {
        let v = crate::math::vec3::Vec3::from(v.map(|x| x.to_f64())).to_unit();
        self.posterior
            .sample_visible::<F>(v.into(), ax, ay, &mut || uniform().to_f64())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::special::ln_bessel_k;

    /// Bessel-K's profile table against `ln_bessel_k` over its whole range, at every a's
    /// end and between: within 1e-13 + 8ε(|ln K| + y) in ln K (the relative error of D;
    /// the polynomial's own rounding is a few ε|ln K|, as `ln_bessel_k`'s, 3ε(|ln K| + y)),
    /// 64 points per octave (between the fit's nodes).
    #[test]
    fn bessel_profile_table() {
        for a in [
            0.1, 0.3, 0.5, 0.7, 0.95, 1.0, 1.05, 1.5, 2.5, 7.0, 30.0, 100.0,
        ] {
            let t = BesselProfile::new(a);
            let nu = a - 1.0;
            let mut worst = 0.0f64;
            for k in KK0 * 64..KK1 * 64 {
                let y = 2f64.powf(k as f64 / 64.0 + 0.37 / 64.0);
                let want = ln_bessel_k(nu, y);
                let got = fit::eval(&t.coef, KK0, MK, y) - y;
                let err = (got - want).abs() / (1e-13 + 8.0 * f64::EPSILON * (want.abs() + y));
                worst = worst.max(err);
            }
            println!("a = {a}: worst {worst:.2} of 1e-13 + 8ε(|ln K| + y)");
            assert!(worst <= 1.0, "a = {a}: {worst} of the bound");
        }
    }

    /// D of a Bessel-K material from the table equals the exact closed form to 1e-12.
    #[test]
    fn bessel_d_from_the_table() {
        for a in [0.1, 0.7, 1.0, 2.5, 100.0] {
            let unit = AnyNdf::new(crate::NdfKind::BesselK, 1.0, Some(a)).unwrap();
            let fitted = FittedShape::new(&unit).unwrap();
            for k in 1..400 {
                let t = k as f64 / 400.0 * 1.55;
                let wm = [t.sin() * 0.6, t.sin() * 0.8, t.cos()];
                let (ax, ay) = (0.3, 0.17);
                let want = unit.d_stretched(wm, ax, ay);
                let got = fitted.d_vec(wm, ax, ay).unwrap();
                assert!(
                    (got - want).abs() <= 1e-12 * want || want < 1e-300,
                    "a = {a}, θ = {t}: {got} vs {want}"
                );
                let u = wm[2];
                let (g, w) = (fitted.d(u, 0.3), unit.with_alpha(0.3).d(u));
                assert!(
                    (g - w).abs() <= 1e-12 * w || w < 1e-300,
                    "a = {a}: {g} vs {w}"
                );
            }
        }
    }
}
