//! The VNDF rejection sampler of [`FittedGtr`]: radii from piecewise envelopes over
//! t = ln r² (flat in r, exponential tails), chosen by an alias table and built at
//! construction ([`FittedGtr::new`]); see [`FittedGtr::sample_visible`].

use super::FittedGtr;
use crate::math::real::Real;

impl FittedGtr {
    /// A visible normal for the unit direction w (mirrored if w.z < 0), distributed exactly
    /// as max(0, w·m) D(m)/σ(w), by rejection in slope space; evaluated in f64 (f32 rounds
    /// once).
    ///
    /// With w = (s cos φ, s sin φ, c), the visible slopes (x along φ, y across) have the
    /// density (c + s x)⁺ P22(x, y). The envelope c + s x⁺ has two parts, sampled exactly:
    /// * c · P22 (mass c): D·cos slopes, the radius from a piecewise envelope (flat in r,
    ///   exponential in t = ln r² for the tails; see `Radial`, built at construction), the
    ///   azimuth uniform;
    /// * s x⁺ P22 (mass s σ(0)): the radius from the first-moment density r² P22(r) (the
    ///   same construction), and an azimuth ψ with density ∝ cos⁺ψ (sin ψ uniform).
    ///
    /// A radius is kept with probability density/envelope (≥ 0.986 on average, over α ∈
    /// [1e-6, 1e6], γ ∈ [0.01, 100]); a D·cos candidate with x < 0 then with probability
    /// (c + s x)⁺/c. The part is decided by a multiplication and x ≥ 0 from the azimuth's
    /// turn itself, so both branches resolve early on the candidate's chain. At least half of all
    /// candidates are kept (σ(w) ≥ max(c, s σ(0))); the mean number is in tests/fast.rs.
    ///
    /// `u` drives the first candidate (u₀ picks the part and then the azimuth, u₁ the radius);
    /// `uniform` supplies one or two more uniforms per candidate, and two per rejected one.
    /// Not a warp of u alone (no inverse), unlike [`crate::Isotropic`]'s sampler.
    #[inline]
    pub(crate) fn sample_visible<F: Real>(
        &self,
        w: [F; 3],
        u: [F; 2],
        uniform: &mut impl FnMut() -> F,
    ) -> [F; 3] {
        let (c, s, cp, sp) = crate::fast::slope_frame(w, 1.0, 1.0);
        if !(c + s).is_finite() {
            // NaN in w (the loop below would never accept).
            return [F::from_f64(f64::NAN); 3];
        }
        // The envelope's masses: c for D·cos, s σ(0) for the first moment.
        // p_dcos = e/(e + g); its reciprocal and 1/g are computed once, off the candidates'
        // chain, and the part is decided by a multiplication.
        let (e, g) = (c, s * self.sigma0);
        let total = e + g;
        // (Capped at f64::MAX: at a grazing w (c → 0) or at normal incidence (s = 0) a
        // mass is 0 or subnormal and its reciprocal infinite; the capped products stay in
        // [0, 1) where they are used, never 0 · ∞.)
        let (inv_p, inv_g) = ((total / e).min(f64::MAX), (1.0 / g).min(f64::MAX));
        let (mut v0, mut v1) = (u[0].to_f64(), u[1].to_f64());
        let (mut x, mut y, mut radius) = (0.0, 0.0, 0.0);
        // At most 64 candidates: each is kept with probability above 0.49, so the cap (which
        // only guarantees termination for a `uniform` that returns NaN) is reached with
        // probability below 1e-18.
        for i in 0..64 {
            if i > 0 {
                v0 = uniform().to_f64();
                v1 = uniform().to_f64();
            }
            // v0 < p_dcos ⇔ d < 0; d/g is the uniform within the first-moment part.
            let d = v0 * total - e;
            let first = d < 0.0;
            let radial = if first { &self.dcos } else { &self.moment };
            let Some(r) = radial.radius(v1, uniform().to_f64()) else {
                continue;
            };
            radius = r;
            if first {
                let turn = v0 * inv_p;
                let (cs, sn) = crate::fast::cos_sin_turn(turn);
                (x, y) = (r * cs, r * sn);
                // x ≥ 0 (cos 2πv ≥ 0) read from the turn itself, early on the chain.
                if (turn - 0.5).abs() >= 0.25 || uniform().to_f64() * c <= c + s * x {
                    break;
                }
            } else {
                let sn = 2.0 * (d * inv_g) - 1.0;
                // (The max: sn may round past 1.)
                (x, y) = (r * ((1.0 - sn) * (1.0 + sn)).max(0.0).sqrt(), r * sn);
                break;
            }
        }
        // (x, y) has length r in both parts (to rounding), so the normal's length comes
        // from r alone.
        crate::fast::facing(crate::fast::normal_from_slopes_r(x, y, radius, (cp, sp)), w)
    }
}

/// The largest |β − ½| w of a flat piece (its envelope wastes at most about half of this).
const FLAT_SLOPE: f64 = 1.0 / 32.0;

/// One piece of the envelope over t = ln r²: on the interval from `a`
/// over a width `w` (w = +∞: the right tail; w = −∞: the left tail, t ≤ a) the envelope of
/// the log-density is `e0 + beta (t − a)` (for a finite piece, the bound its flat envelope
/// in r is taken from).
#[derive(Clone, Copy, Debug)]
struct Piece {
    /// A lower bound of e^{φ − envelope} on the piece.
    squeeze: f64,
    a: f64,
    w: f64,
    beta: f64,
    e0: f64,
    /// expm1(β w): −1 for the tails.
    em1: f64,
    /// Finite pieces: the envelope is flat in r, from `r0` over `dr`, at the log height `h`
    /// (relative to `top`) of the density in r, e^{φ − t/2}; a candidate r0 + v dr is kept
    /// without φ when `keep` ≤ s0 + s1 v.
    r0: f64,
    dr: f64,
    h: f64,
    s0: f64,
    s1: f64,
}

impl Piece {
    /// ∫ e^{e0 + β(t − a)} dt over a tail, 2 e^h dr over a finite piece (the same measure:
    /// p(t) dt = 2 e^{φ − t/2} dr).
    fn mass(&self) -> f64 {
        if self.w.is_finite() {
            return 2.0 * self.h.exp() * self.dr;
        }
        let width = if self.beta == 0.0 {
            self.w.abs()
        } else {
            (self.em1 / self.beta).abs()
        };
        self.e0.exp() * width
    }

    /// t with density ∝ e^{β(t − a)} on the piece, from v ∈ [0, 1).
    #[inline(always)]
    fn sample(&self, v: f64) -> f64 {
        if self.beta == 0.0 {
            return self.a + v * self.w;
        }
        self.a + (v * self.em1).ln_1p() / self.beta
    }
}

/// An exact sampler of the radial slope density of GTR in t = ln r²,
/// p(t) ∝ e^{φ(t)}, φ(t) = k t + (γ − 2) ln(1 + eᵗ) − γ ln(α² + eᵗ)
/// (k = 1: D·cos slopes, P22 r dr; k = 3/2: the first moment, r P22 r dr), by rejection from
/// a piecewise envelope chosen by an alias table.
///
/// On every piece a linear function of t bounds φ rigorously, for every γ: −γ ln(α² + eᵗ)
/// is concave, so its tangent at the piece's middle lies above it; (γ − 2) ln(1 + eᵗ) is
/// concave for γ < 2 (tangent) and convex for γ ≥ 2 (chord). Between t₋ = ln(min(1, α²) ε)
/// and t₊ = ln(max(1, α²)/ε), ε = 1e-4/(1 + γ), the pieces are then flat in r: the density
/// in r, 2e^{φ − t/2}, lies below the largest value of that linear bound less t/2 on the
/// piece (at one of its ends), so a candidate is r₀ + v·dr, one multiply-add, with no
/// logarithm or exponential. Pieces have width at most min(1/4, 1/(2√γ)) in t (the
/// tangent's gap below γw²/16 ≤ 1/64) and are halved until |β − ½|w ≤ 1/32 (the flat
/// envelope's waste, β the bound's slope; 1/8 where φ is below 1 % of its peak; at least
/// 1/16 of the first width). The squeeze is affine in v: the gap's e^{gap} times the chord
/// (β > ½) or tangent (β < ½) bound of e^{(β − ½)(t − a)} in v. The two tails beyond t±
/// are exponential pieces in t (their slopes, about k and k − 2, keep them integrable),
/// sampled out of line. Measured (unit test): envelope efficiency ≥ 0.986, squeezed share
/// ≥ 0.974, 300 to 660 pieces for α ∈ [0.05, 1], γ ∈ [0.5, 3].
#[derive(Clone, Debug)]
pub(super) struct Radial {
    k: f64,
    /// The largest envelope exponent, subtracted from every piece's.
    top: f64,
    gamma: f64,
    /// α².
    a2: f64,
    pieces: Vec<Piece>,
    /// Vose's alias table over the pieces, each column's two halves resolved: r and the
    /// squeeze as affine functions of the column's fraction.
    slots: Vec<Slot>,
}

/// One column of the alias table: `own` below `prob`, `other` above.
#[derive(Clone, Copy, Debug)]
struct Slot {
    prob: f64,
    own: Half,
    other: Half,
}

/// One half of a column, for the column's fraction frac ∈ [0, 1): r = off + frac·scale,
/// kept without φ when keep ≤ s0 + s1·frac (s0 = −1 for a tail piece, which always takes
/// the slow path). (Where a half's share 1 − prob is tiny, its scale is large and r rounds
/// by up to ulp(off): a relative 1e-16/(1 − prob) of the piece, inside the envelope's margin
/// of 1e-9 for every half drawn with probability above 1e-7.)
#[derive(Clone, Copy, Debug)]
struct Half {
    off: f64,
    scale: f64,
    s0: f64,
    s1: f64,
    piece: u32,
}

/// ln(eˢ + eᵗ) without overflow, and its derivative in t (the logistic of t − s).
fn log_add_exp(s: f64, t: f64) -> (f64, f64) {
    let d = t - s;
    let value = s.max(t) + (-d.abs()).exp().ln_1p();
    (value, 1.0 / (1.0 + (-d).exp()))
}

impl Radial {
    pub(super) fn new(alpha: f64, gamma: f64, k: f64) -> Self {
        let la = 2.0 * alpha.ln();
        let eps_ln = (1e-4 / (1.0 + gamma)).ln();
        let (t_lo, t_hi) = (la.min(0.0) + eps_ln, la.max(0.0) - eps_ln);
        let width = 0.25f64.min(0.5 / gamma.sqrt());
        let n = ((t_hi - t_lo) / width).ceil().max(1.0) as usize;
        let width = (t_hi - t_lo) / n as f64;
        let a_part = |t: f64| {
            let (l1, d1) = log_add_exp(0.0, t);
            ((gamma - 2.0) * l1, (gamma - 2.0) * d1)
        };
        let b_part = |t: f64| {
            let (l2, d2) = log_add_exp(la, t);
            (-gamma * l2, -gamma * d2)
        };
        // (a, w, β, envelope at a) for each piece, tails first and last.
        let mut raw = Vec::with_capacity(n + 2);
        // Left tail t ≤ t₋: tangents of the concave parts; for γ ≥ 2, (γ − 2) ln(1 + eᵗ) is
        // increasing, so its value at t₋ bounds it.
        let (a0, a0d) = a_part(t_lo);
        let (b0, b0d) = b_part(t_lo);
        let a0d = if gamma >= 2.0 { 0.0 } else { a0d };
        raw.push((
            t_lo,
            f64::NEG_INFINITY,
            k + a0d + b0d,
            k * t_lo + a0 + b0,
            f64::NEG_INFINITY,
        ));
        let w0 = width;
        // φ's largest value (on a grid): pieces where φ is within a factor 100 of it hold
        // almost all of the mass and get the tight FLAT_SLOPE, the others 4× wider.
        let phi = |t: f64| k * t + a_part(t).0 + b_part(t).0;
        let peak = (0..=4 * n)
            .map(|j| phi(t_lo + j as f64 * w0 / 4.0))
            .fold(f64::NEG_INFINITY, f64::max);
        let mut a = t_lo;
        while a < t_hi {
            let mut width = w0.min(t_hi - a);
            loop {
                let b = a + width;
                let m = a + 0.5 * width;
                let ((aa, _), (ab, _), (am, amd)) = (a_part(a), a_part(b), a_part(m));
                let ((ba, _), (bb, _), (bm, bmd)) = (b_part(a), b_part(b), b_part(m));
                // The tangents at m, at the ends.
                let (ta_a, ta_b) = (am - amd * (m - a), am + amd * (b - m));
                let (tb_a, tb_b) = (bm - bmd * (m - a), bm + bmd * (b - m));
                // The envelope of the A part, and a lower bound of (A − its envelope): a concave
                // difference (tangent case) or one above a linear function (chord case: A lies
                // above its tangent) takes its least value at an end.
                let (a_at_a, a_slope, a_gap) = if gamma >= 2.0 {
                    (aa, (ab - aa) / width, (ta_a - aa).min(ta_b - ab))
                } else {
                    (ta_a, amd, (aa - ta_a).min(ab - ta_b))
                };
                let b_gap = (ba - tb_a).min(bb - tb_b);
                let beta = k + a_slope + bmd;
                let limit = if phi(m) > peak - 4.6 {
                    FLAT_SLOPE
                } else {
                    4.0 * FLAT_SLOPE
                };
                // Halved no further than w0/16: at large γ the slopes reach ~γ, and the piece
                // count stays bounded (the efficiency there is checked in the unit test).
                if (beta - 0.5).abs() * width > limit && width > w0 / 16.0 {
                    width *= 0.5;
                    continue;
                }
                raw.push((a, width, beta, k * a + a_at_a + tb_a, a_gap + b_gap));
                a = b.min(t_hi);
                break;
            }
        }
        // Right tail t ≥ t₊: for γ ≥ 2, ln(1 + eᵗ) = t + ln(1 + e^{−t}) ≤ t + ln(1 + e^{−t₊}).
        let (a1, a1d) = a_part(t_hi);
        let (b1, b1d) = b_part(t_hi);
        let a1d = if gamma >= 2.0 { gamma - 2.0 } else { a1d };
        raw.push((
            t_hi,
            f64::INFINITY,
            k + a1d + b1d,
            k * t_hi + a1 + b1,
            f64::NEG_INFINITY,
        ));
        // Exponents relative to the largest (the density's scale cancels), plus a margin of
        // 1e-9 over the rounding of φ (|φ| ≲ 1e4), so that the envelope stays above φ.
        let top = raw
            .iter()
            .map(|r| r.3.max(r.3 + r.2 * if r.1.is_finite() { r.1 } else { 0.0 }))
            .fold(f64::NEG_INFINITY, f64::max);
        let pieces: Vec<Piece> = raw
            .into_iter()
            .map(|(a, w, beta, e, gap)| {
                // The squeeze: below e^{gap}, less the two margins, a candidate is kept
                // without evaluating φ (0 for the tails, which always evaluate it).
                let squeeze = (gap - 3e-9).exp();
                let e0 = e - top + 1e-9;
                let (mut r0, mut dr, mut h, mut s0, mut s1) = (0.0, 0.0, 0.0, 0.0, 0.0);
                if w.is_finite() {
                    r0 = (0.5 * a).exp();
                    dr = (0.5 * (a + w)).exp() - r0;
                    let b = (beta - 0.5) * w;
                    h = e0 - 0.5 * a + b.max(0.0);
                    if b >= 0.0 {
                        (s0, s1) = (squeeze * (1.0 - b), squeeze * b);
                    } else {
                        (s0, s1) = (squeeze, squeeze * 2.0 * (beta - 0.5) * (0.5 * w).exp_m1());
                    }
                }
                Piece {
                    squeeze,
                    a,
                    w,
                    beta,
                    e0,
                    em1: (beta * w).exp_m1(),
                    r0,
                    dr,
                    h,
                    s0,
                    s1,
                }
            })
            .collect();
        let (prob, alias) = alias_table(&pieces.iter().map(Piece::mass).collect::<Vec<_>>());
        let side = |j: usize, lo: f64, len: f64| {
            let p = &pieces[j];
            // Tails, and halves too thin for an affine map (a share 1 − prob or prob of
            // ~1e-300, drawn with that probability): the slow path, from v2.
            if !p.w.is_finite() || !(p.dr / len).is_finite() {
                return Half {
                    off: 0.0,
                    scale: 0.0,
                    s0: -1.0,
                    s1: 0.0,
                    piece: j as u32,
                };
            }
            let scale = p.dr / len;
            let s1 = p.s1 / len;
            Half {
                off: p.r0 - lo * scale,
                scale,
                s0: p.s0 - lo * s1,
                s1,
                piece: j as u32,
            }
        };
        let slots = (0..prob.len())
            .map(|i| Slot {
                prob: prob[i],
                own: side(i, 0.0, prob[i]),
                other: side(alias[i] as usize, prob[i], 1.0 - prob[i]),
            })
            .collect();
        Radial {
            k,
            top,
            gamma,
            a2: alpha * alpha,
            pieces,
            slots,
        }
    }

    /// The envelope as the GPU crate lays it out (see [`super::RadialLayout`]).
    pub(super) fn layout(&self) -> super::RadialLayout {
        let pieces = self
            .pieces
            .iter()
            .zip(&self.slots)
            .map(|(p, slot)| super::RadialPiece {
                tail: !p.w.is_finite(),
                a: p.a,
                beta: p.beta,
                e0: p.e0,
                em1: p.em1,
                squeeze: p.squeeze,
                r0: p.r0,
                dr: p.dr,
                s0: p.s0,
                s1: p.s1,
                h: p.h,
                prob: slot.prob,
                alias: slot.other.piece,
            })
            .collect();
        super::RadialLayout {
            k: self.k,
            top: self.top,
            pieces,
        }
    }

    /// φ(t) − envelope(t) ≤ 0 on piece `p` (the tests' reference form, without overflow
    /// at any t).
    #[cfg(test)]
    fn log_ratio(&self, p: &Piece, t: f64) -> f64 {
        let (l1, _) = log_add_exp(0.0, t);
        let (l2, _) = log_add_exp(self.a2.ln(), t);
        let envelope = self.top + p.e0 + p.beta * (t - p.a);
        self.k * t + (self.gamma - 2.0) * l1 - self.gamma * l2 - envelope
    }

    /// A radius r from the envelope, from v ∈ [0, 1) (the column of the alias table from
    /// its integer part, the half and the position within the piece from the fraction),
    /// kept if `keep` (uniform in [0, 1)) is below the ratio of the density to the
    /// envelope; None if rejected. The squeeze (a lower bound of that ratio, affine in the
    /// position) decides most candidates without φ; the rest, and the tails, are out of line.
    #[inline(always)]
    fn radius(&self, v: f64, keep: f64) -> Option<f64> {
        let n = self.slots.len();
        let f = v * n as f64;
        let i = (f as usize).min(n - 1);
        let frac = f - i as f64;
        let slot = &self.slots[i];
        let own = frac < slot.prob;
        let half = if own { &slot.own } else { &slot.other };
        let r = half.off + frac * half.scale;
        if keep <= half.s0 + half.s1 * frac {
            return Some(r);
        }
        self.radius_slow(slot, own, frac, r, keep)
    }

    /// φ evaluated (from r, three logarithms): a flat piece's full test, or a tail's
    /// candidate (t = ln r² from the piece's exponential, then its squeeze and test).
    #[cold]
    #[inline(never)]
    fn radius_slow(&self, slot: &Slot, own: bool, frac: f64, r: f64, keep: f64) -> Option<f64> {
        let half = if own { &slot.own } else { &slot.other };
        let p = &self.pieces[half.piece as usize];
        // The position within the piece, for the halves the fast path cannot map.
        let v2 = || {
            let v2 = if own {
                frac / slot.prob
            } else {
                (frac - slot.prob) / (1.0 - slot.prob)
            };
            v2.min(1.0)
        };
        if p.w.is_finite() {
            let r = if half.s0 == -1.0 {
                p.r0 + v2() * p.dr
            } else {
                r
            };
            let x = r * r;
            let t = x.ln();
            return (keep <= (self.phi(t, x) - self.top - 0.5 * t - p.h).exp()).then_some(r);
        }
        let t = p.sample(v2());
        let r = (0.5 * t).exp();
        if keep <= p.squeeze {
            return Some(r);
        }
        let envelope = self.top + p.e0 + p.beta * (t - p.a);
        (keep <= (self.phi(t, r * r) - envelope).exp()).then_some(r)
    }

    /// φ(t) = k t + (γ − 2) ln(1 + x) − γ ln(α² + x) at x = eᵗ = r².
    fn phi(&self, t: f64, x: f64) -> f64 {
        self.k * t + (self.gamma - 2.0) * x.ln_1p() - self.gamma * (self.a2 + x).ln()
    }
}

/// Vose's alias table for the weights `m` (not necessarily normalised).
fn alias_table(m: &[f64]) -> (Vec<f64>, Vec<u32>) {
    let n = m.len();
    let total: f64 = m.iter().sum();
    let mut scaled: Vec<f64> = m.iter().map(|x| x * n as f64 / total).collect();
    let mut prob = vec![1.0; n];
    let mut alias: Vec<u32> = (0..n as u32).collect();
    let (mut small, mut large): (Vec<usize>, Vec<usize>) = (0..n).partition(|&i| scaled[i] < 1.0);
    while let (Some(s), Some(&l)) = (small.pop(), large.last()) {
        prob[s] = scaled[s];
        alias[s] = l as u32;
        scaled[l] -= 1.0 - scaled[s];
        if scaled[l] < 1.0 {
            large.pop();
            small.push(l);
        }
    }
    // What is left has weight 1 up to rounding.
    (prob, alias)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The envelope lies above φ everywhere (densely sampled, tails included), and the alias
    /// table picks each piece with probability proportional to its mass.
    #[test]
    fn envelope_bounds_phi_and_alias_table_is_exact() {
        let (mut least, mut least_squeezed) = (f64::INFINITY, f64::INFINITY);
        for alpha in [1e-6, 1e-3, 0.05, 0.3, 0.999, 1.0, 1.001, 1.7, 1e3, 1e6] {
            for gamma in [
                0.01, 0.1, 0.5, 1.0, 1.5, 1.999, 2.0, 2.001, 3.0, 10.0, 100.0,
            ] {
                for k in [1.0, 1.5] {
                    let r = Radial::new(alpha, gamma, k);
                    let mut worst = f64::NEG_INFINITY;
                    for p in &r.pieces {
                        if p.w.is_finite() {
                            // Flat in r: e^{φ − t/2 − top} ≤ e^h, and the squeeze s0 + s1 v
                            // below the ratio, at r = r0 + v dr.
                            for j in 0..=64 {
                                let v = j as f64 / 64.0;
                                let rr = p.r0 + v * p.dr;
                                let t = 2.0 * rr.ln();
                                let ratio =
                                    r.log_ratio(p, t) + p.e0 + p.beta * (t - p.a) - 0.5 * t - p.h;
                                worst = worst.max(ratio);
                                assert!(
                                    p.s0 + p.s1 * v <= ratio.exp(),
                                    "α={alpha} γ={gamma} t={t}"
                                );
                            }
                            continue;
                        }
                        let (lo, hi) = if p.w.is_finite() {
                            (p.a, p.a + p.w)
                        } else if p.w > 0.0 {
                            (p.a, p.a + 60.0)
                        } else {
                            (p.a - 60.0, p.a)
                        };
                        for j in 0..=64 {
                            let t = lo + (hi - lo) * j as f64 / 64.0;
                            let ratio = r.log_ratio(p, t);
                            worst = worst.max(ratio);
                            assert!(p.squeeze <= ratio.exp(), "α={alpha} γ={gamma} t={t}");
                        }
                    }
                    assert!(worst <= 0.0, "α={alpha} γ={gamma} k={k}: {worst}");
                    // Alias table: P(piece i) = Σ over columns of its share.
                    let n = r.slots.len();
                    let mut got = vec![0.0; n];
                    for (i, slot) in r.slots.iter().enumerate() {
                        assert_eq!(slot.own.piece as usize, i);
                        // Each half maps its range of the fraction onto its piece.
                        for (half, lo, hi) in
                            [(&slot.own, 0.0, slot.prob), (&slot.other, slot.prob, 1.0)]
                        {
                            let p = &r.pieces[half.piece as usize];
                            if p.w.is_finite() && half.s0 != -1.0 {
                                let (a, b) =
                                    (half.off + lo * half.scale, half.off + hi * half.scale);
                                let tol = 1e-12 * (p.r0 + p.dr) / (hi - lo);
                                assert!(
                                    (a - p.r0).abs() <= tol && (b - p.r0 - p.dr).abs() <= tol,
                                    "α={alpha} γ={gamma} {a} {b} {} {} {lo} {hi}",
                                    p.r0,
                                    p.r0 + p.dr
                                );
                            }
                        }
                        got[i] += slot.prob / n as f64;
                        got[slot.other.piece as usize] += (1.0 - slot.prob) / n as f64;
                    }
                    let masses: Vec<f64> = r.pieces.iter().map(Piece::mass).collect();
                    let total: f64 = masses.iter().sum();
                    for i in 0..n {
                        assert!(
                            (got[i] - masses[i] / total).abs() < 1e-12,
                            "α={alpha} γ={gamma} piece {i}"
                        );
                    }
                    // The envelope is tight: its mass over the density's is the mean number
                    // of radial candidates (φ integrated by the trapezoidal rule in t).
                    let h = 1e-3;
                    let (lo, hi) = (r.pieces[0].a - 60.0, r.pieces[n - 1].a + 120.0);
                    let steps = ((hi - lo) / h) as usize;
                    let phi = |t: f64| {
                        let (l1, _) = log_add_exp(0.0, t);
                        let (l2, _) = log_add_exp(r.a2.ln(), t);
                        (k * t + (gamma - 2.0) * l1 - gamma * l2 - r.top).exp()
                    };
                    let integral: f64 =
                        (0..=steps).map(|j| phi(lo + j as f64 * h)).sum::<f64>() * h;
                    let efficiency = integral / total;
                    least = least.min(efficiency);
                    // The squeeze's share: candidates decided without evaluating φ.
                    let squeezed: f64 = r
                        .pieces
                        .iter()
                        .map(|p| {
                            let share = if p.w.is_finite() {
                                p.s0 + 0.5 * p.s1
                            } else {
                                p.squeeze
                            };
                            p.mass() * share
                        })
                        .sum::<f64>()
                        / total;
                    least_squeezed = least_squeezed.min(squeezed);
                    assert!(
                        efficiency > 0.95 && efficiency < 1.0 + 1e-6,
                        "α={alpha} γ={gamma} k={k}: {efficiency}"
                    );
                }
            }
        }
        println!(
            "least envelope efficiency: {least:.4}, least squeezed share: {least_squeezed:.4}"
        );
    }
}
