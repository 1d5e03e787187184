//! GTR at any γ: Λ, σ, G1, G2 from an octave table built for one (α, γ) at construction.
//!
//! GTR is not shape invariant: Λ depends on cot θ, α and γ, a three-parameter function no
//! static table covers at 1e-7. A renderer fixes (α, γ) per material, so [`FittedGtr::new`] fits
//! Λ for that material by Chebyshev interpolation of the exact Smith integral
//! ([`crate::Gtr::lambda_cot`]), degree 6, on octave segments of t, in two tables:
//! * the **u table**, t = u = cos θ < ½ (the grazing side), eighth octaves;
//! * the **w table**, t = w = 1 − u ≤ ½ (the normal side; 1 − u is exact there), quarter
//!   octaves (w ~ 1/(2 cot²θ) near the normal, so that is an eighth octave of cot θ).
//!
//! Seven coefficients on short segments rather than nine on segments twice as long (an earlier
//! layout, as accurate, and slower: BENCHMARKS.md). The fit is then re-expanded, without new
//! evaluations of the exact Λ, into the tables that are evaluated: degree 4 on 32 rows per octave
//! on both sides (quarters of the u segments, eighths of the w segments; within 3e-9 of the fit),
//! so the lookup's shifts are constants and the polynomial is shorter (faster, scalar and slice
//! kernels: BENCHMARKS.md; 42 KiB at α = 0.3, γ = 1.5), and for f32, where Λ itself is tabulated,
//! cubics on the same rows in f32 (17 KiB; [`FittedGtr::has_f32_table`]).
//!
//! So Λ(u) needs no square root and no division: the side picks the table's offset by an
//! index (no branch to mispredict on random directions), then one polynomial. From one set
//! of exact values [`FittedGtr::new`] builds each table twice and keeps one kind:
//! * **Λ itself**, if it is accurate: within 1e-8 at every segment end (`DIRECT_TOL`), and
//!   no value near underflow. Evaluation is then the polynomial alone. This holds for every
//!   α at γ ≤ 3 and for most α at γ ≤ 5 ([`FittedGtr::is_direct`] tells which; tests/fast.rs
//!   records the census).
//! * **ln Λ** otherwise, plus one exponential at evaluation. For large γ and small α, Λ falls
//!   like cot^{−2γ}θ near the normal: by 2^25 ≈ 3·10^7 across one segment (an eighth octave
//!   of cot θ) at γ = 100.
//!   No short polynomial follows that in relative terms, while ln Λ stays smooth. Where Λ
//!   underflows (γ ≳ 30 with small α: Λ ~ α^{2γ} near the normal), a segment with any node
//!   below 1e-300 returns 0. So Λ is relatively accurate where it exceeds 1e-280 (a
//!   segment spans at most a factor 3·10^7 there) and absolutely below.
//!
//! Construction evaluates the exact Λ about 1 500 times (184 rows of 7 nodes at α = 0.3,
//! γ = 1.5, plus the segment ends for the accuracy check): milliseconds at γ = 1, 2 (closed
//! forms), tens of milliseconds at other γ (the Smith integral), the most at small α and
//! large γ (BENCHMARKS.md). [`FittedGtr::lambda_cot`] takes cot θ = a directly and
//! forms u = a/r and w = 1/(r(r + a)), r = √(1 + a²), both without cancellation.
//!
//! Range: the features of P22 = c(1 + r²)^{γ−2}(r² + α²)^{−γ} lie at slopes r ~ α, 1 and √γ
//! (where ((1 + r²)/(α² + r²))^γ settles). With s₋ = min(α, 1)/max(1, √γ) and
//! s₊ = max(α, 1, √γ), the tables span cot θ from about 2^−10 s₋ (u table) to 2^10 s₊
//! (w table); beyond them two terms of each end's expansion, matched to the exact Λ at the
//! table's end and a factor 2 beyond it:
//! * near the normal (P22 ~ c r⁻⁴ past every feature, with corrections in powers of r⁻²):
//!   Λ = K/a² + K₂/a⁴ (the next term is O((s₊/a)⁴) relative);
//! * grazing: Λ = m/a − 1/2 + m₁a (Λ = M₁/a − ∫_a^∞ P2 + …, P2 even: the next term is
//!   O((a/s₋)⁴) relative).
//!
//! Measured by tests/fast.rs over its domain: with the tables ending at 2^7 the ends erred by
//! 1.8e-7 (α = 1e3, γ = 100), at 2^8 by 1.1e-8 (the 16× per power of 2 that O(a⁴)
//! predicts); at 2^9 and at 2^10 (kept, for margin) the worst error is the tables' own,
//! 5.2e-9 for the fit (6.3e-9 for the re-expanded rows evaluated). With one term the ends
//! needed 2^18, and the tables 1.7 times the fitted rows (312 against 184 at α = 0.3,
//! γ = 1.5).
//!
//! Accuracy: relative error ≤ 1e-7 required; tests/fast.rs measures it over u ∈ (0, 1] for
//! α ∈ [1e-3, 1e3], γ ∈ [0.1, 100].

mod vndf;

use super::{fit, Real};
use crate::error::ParamError;
use crate::ndf::Ndf;
use vndf::Radial;

/// Coefficients per fitted segment (degree 6).
const N_FIT: usize = 7;
/// 2^M fitted segments per octave of u.
const M: u32 = 3;
/// 2^M_W fitted segments per octave of w = 1 − u: w ~ 1/(2a²) near the normal, so an octave
/// of w is half an octave of a, and M_W = M − 1 keeps the resolution in a. (Eighth octaves
/// of a with degree 6 meet the tolerance; quarter octaves needed degree 8.)
const M_W: u32 = M - 1;
/// Coefficients per row of the f64 table (degree 4), on 2^M_T rows per octave on both sides:
/// each fitted segment is re-expanded (no new evaluation of the exact Λ) onto 4 (u) or 8
/// (w) equal pieces, as the Chebyshev interpolant of its polynomial there. One resolution
/// for both sides makes every shift of the lookup a constant, and a degree-4 polynomial is
/// a shorter chain, faster (BENCHMARKS.md). The pieces follow the fit within
/// 3e-9 (the unit test below). Degree 4 on 16 rows per octave deviated by 9e-8 (α = 1e-3,
/// γ = 3; Λ ~ 1/u at grazing bends most); degree 5 on 16 held 2e-9 and was slower.
const N: usize = 5;
const M_T: u32 = 5;
/// Coefficients per row of the f32 table (degree 3: two operations fewer than degree 4),
/// re-expanded from the fit like the f64 table, on the same rows (so the same layout). A
/// cubic on a whole fitted segment errs by 1.5e-6 at grazing, and on halves of the u
/// side's segments (16 rows per octave) it still missed [`F32_TOL`] at γ ≥ 2 with α ≤ 0.3.
const N32: usize = 4;
/// The largest relative deviation of an f32 row (f32 arithmetic) from its fitted
/// polynomial, at 17 points per piece, for which the f32 table is kept: with the fit's 1e-8
/// and a few ulp from the f32 inputs, the f32 path stays inside 1e-6, half the 2e-6
/// required.
const F32_TOL: f64 = 5e-7;
/// The table reaches 2^SPAN beyond the outermost feature scale on each side, where the two-term
/// asymptotic ends take over (module docs).
const SPAN: i32 = 10;
/// Below this Λ is treated as underflowed (see the module docs).
const TINY: f64 = 1e-300;
/// The largest relative error, at the segment ends, for which the table of Λ itself replaces
/// that of ln Λ: 10× inside the required 1e-7, and near the log table's own error (about
/// 4e-9; 5e-9 sent α = 1e-3, γ = 3 to the log table, by 5.3e-9). It admits every α at
/// γ ≤ 3 and most at γ ≤ 5 (the census is in tests/fast.rs).
const DIRECT_TOL: f64 = 1e-8;

/// a = cot θ from u = cos θ.
fn a_of_u(u: f64) -> f64 {
    u / ((1.0 - u) * (1.0 + u)).sqrt()
}

/// a = cot θ from w = 1 − cos θ (accurate near the normal, where u would cancel).
fn a_of_w(w: f64) -> f64 {
    (1.0 - w) / (w * (2.0 - w)).sqrt()
}

/// One of the two Λ tables (2^M_T rows per octave on both): the row of t is
/// (bits of t) >> (52 − M_T) less `off` (the biased exponent and top M_T mantissa bits
/// index the rows; `off` holds the first octave's index and the side's first row), and
/// `lo` = 2^k0 (below it t is past the table: the asymptotic ends).
#[derive(Clone, Copy, Debug)]
struct Side {
    off: u64,
    lo: f64,
}

/// x^{−γ} in D: by a division at γ = 1 and 2, else by ln and exp.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Power {
    One,
    Two,
    General,
}

/// A GTR NDF prepared for fast Λ, σ, G1 and G2.
#[derive(Clone, Debug)]
pub struct FittedGtr {
    alpha: f64,
    gamma: f64,
    /// The rows of the u table (t = u < ½, octaves from 2^u_k0), then those of the w table
    /// (t = 1 − u ≤ ½, octaves from 2^w_k0), from row `w_row0`.
    coef: Vec<[f64; N]>,
    /// The two tables' layouts, [u table, w table]: indexed by the side, not selected, so
    /// that the compiler cannot turn the choice into a branch (which random directions
    /// would mispredict).
    sides: [Side; 2],
    /// Whether `coef` holds Λ itself or ln Λ.
    direct: bool,
    /// The largest deviation of `coef`'s rows from the fit they were re-expanded from
    /// (relative for Λ, absolute for ln Λ; checked by the unit tests).
    piece_dev: f64,
    /// The f32 table: the rows of `coef` as cubics in f32 (the same layout); empty where Λ
    /// is not direct or a cubic misses [`F32_TOL`] (the f32 entry points then evaluate in
    /// f64).
    coef32: Vec<[f32; N32]>,
    /// Per side [u, w]: `Side`'s offset and 2^k0 for the bits of an f32 t (23 mantissa
    /// bits, exponent bias 127).
    off32: [u32; 2],
    lo32: [f32; 2],
    /// Λ ≈ m/a − 1/2 + m₁a below `u_lo` (a = cot θ): [m, m₁].
    m: [f64; 2],
    /// Λ ≈ K/a² + K₂/a⁴ past `w_lo`: [K, K₂].
    k: [f64; 2],
    sigma0: f64,
    /// D's normalisation c and its log (finite where c underflows).
    c: f64,
    ln_c: f64,
    /// Which power of x D takes.
    power: Power,
    exact: crate::Gtr,
    /// Radial samplers for the visible normals: D·cos slopes and their first moment.
    dcos: Radial,
    moment: Radial,
}

impl FittedGtr {
    /// Fits Λ for α ∈ [1e-6, 1e6], γ ∈ (0, 100] (validated as in [`crate::Gtr::new`]).
    pub fn new(alpha: f64, gamma: f64) -> Result<Self, ParamError> {
        let exact = crate::Gtr::new(alpha, gamma)?;
        let s_lo = alpha.min(1.0) / gamma.sqrt().max(1.0);
        let s_hi = alpha.max(1.0).max(gamma.sqrt());
        // Grazing side: u ≈ a below the features, from 2^−SPAN s₋ up to u = ½.
        let u_k0 = s_lo.log2().floor() as i32 - SPAN;
        // Normal side: w = 1 − u ≈ 1/(2a²) past the features, from a ≥ 2^SPAN s₊ up to
        // w = ½ (u = ½ itself gets a row of its own, below).
        let w_k0 = -2 * (SPAN + s_hi.log2().ceil() as i32) - 1;
        let ln_lambda = |a: f64| exact.lambda_cot(a).max(TINY).ln();
        // ln Λ at every segment's Chebyshev points: the log tables, and Λ itself from the
        // same evaluations.
        let mut ln_values = fit::octave_node_values::<N_FIT>(u_k0, -1, M, |u| ln_lambda(a_of_u(u)));
        let w_row0 = ln_values.len();
        ln_values.extend(fit::octave_node_values::<N_FIT>(w_k0, -1, M_W, |w| {
            ln_lambda(a_of_w(w))
        }));
        // w = ½ itself (u = ½) lies in the next octave, at the start (s = −1) of its first
        // segment: one more row, constant, holding the exact value there (the rest of that
        // octave, up to the singular w = 1, is never read).
        ln_values.push([ln_lambda(a_of_w(0.5)); N_FIT]);
        let direct_coef: Vec<[f64; N_FIT]> = ln_values
            .iter()
            .map(|v| fit::chebyshev_coefficients(&v.map(f64::exp)))
            .collect();
        let mut coef: Vec<[f64; N_FIT]> =
            ln_values.iter().map(fit::chebyshev_coefficients).collect();
        let last = ln_values.len() - 1; // the constant row at w = ½
        let direct = !ln_values
            .iter()
            .flatten()
            .any(|&v| v.is_nan() || v <= 1e-280f64.ln())
            && Self::direct_is_accurate(&exact, (u_k0, M), &direct_coef[..w_row0], a_of_u)
            && Self::direct_is_accurate(&exact, (w_k0, M_W), &direct_coef[w_row0..last], a_of_w);
        if direct {
            coef = direct_coef;
        }
        for c in coef.iter_mut().filter(|_| !direct) {
            // A node at the floor: the segment reaches the underflow (see the module docs).
            if (0..N_FIT).any(|k| {
                let s = (std::f64::consts::PI * (k as f64 + 0.5) / N_FIT as f64).cos();
                fit::poly(c, s) <= TINY.ln() + 1e-6
            }) {
                *c = [0.0; N_FIT];
                c[0] = -800.0; // e^{−800} = 0
            }
        }
        let (fit_u, fit_w) = coef.split_at(w_row0);
        // The f64 table: the fitted rows re-expanded onto 2^M_T rows per octave (the
        // constant row at w = ½ among the w rows: its first piece is the row w = ½ reads).
        let (u_rows, e_u) = re_expand::<f64, N>(fit_u, M_T - M, direct, |x| x);
        let (w_rows, e_w) = re_expand::<f64, N>(fit_w, M_T - M_W, direct, |x| x);
        let w_row0_t = u_rows.len();
        let table = [u_rows, w_rows].concat();
        // The f32 table, where Λ itself is tabulated and cubics hold F32_TOL.
        let coef32 = if direct {
            let (u32_rows, e_u) = re_expand::<f32, N32>(fit_u, M_T - M, true, |x| x as f32);
            let (w32_rows, e_w) = re_expand::<f32, N32>(fit_w, M_T - M_W, true, |x| x as f32);
            if e_u.max(e_w) <= F32_TOL {
                [u32_rows, w32_rows].concat()
            } else {
                Vec::new()
            }
        } else {
            Vec::new()
        };
        // Each side's first octave's index in the bits of t, less its first row.
        let off32 = |k0: i32, row0: usize| (((127 + k0) as u32) << M_T).wrapping_sub(row0 as u32);
        let off64 = |k0: i32, row0: usize| (((1023 + k0) as u64) << M_T).wrapping_sub(row0 as u64);
        let (u_lo, w_lo) = (2f64.powi(u_k0), 2f64.powi(w_k0));
        let (a_lo, a_hi) = (a_of_u(u_lo), a_of_w(w_lo));
        Ok(FittedGtr {
            alpha,
            gamma,
            coef: table,
            sides: [
                Side {
                    off: off64(u_k0, 0),
                    lo: u_lo,
                },
                Side {
                    off: off64(w_k0, w_row0_t),
                    lo: w_lo,
                },
            ],
            direct,
            piece_dev: e_u.max(e_w),
            coef32,
            off32: [off32(u_k0, 0), off32(w_k0, w_row0_t)],
            lo32: [u_lo as f32, w_lo as f32],
            m: Self::two_terms(|a| (exact.lambda_cot(a) + 0.5) * a, a_lo, 0.5 * a_lo),
            k: Self::two_terms(
                |x| exact.lambda_cot(1.0 / x) / (x * x),
                1.0 / a_hi,
                0.5 / a_hi,
            ),
            sigma0: exact.sigma(0.0),
            c: exact.c(),
            ln_c: exact.ln_c(),
            power: if gamma == 1.0 {
                Power::One
            } else if gamma == 2.0 {
                Power::Two
            } else {
                Power::General
            },
            exact,
            dcos: Radial::new(alpha, gamma, 1.0),
            moment: Radial::new(alpha, gamma, 1.5),
        })
    }

    /// [c₀, c₁] of g(x) = c₀ + c₁x² through g at x₁ and x₂ (the asymptotic ends, matched where
    /// the tables stop: g = (Λ + ½)a, x = a on the grazing side; g = Λa², x = 1/a near the
    /// normal).
    fn two_terms(g: impl Fn(f64) -> f64, x1: f64, x2: f64) -> [f64; 2] {
        let y1 = g(x1);
        let y2 = g(x2);
        let c1 = (y1 - y2) / (x1 * x1 - x2 * x2);
        [y1 - c1 * x1 * x1, c1]
    }

    /// Whether one table of Λ itself (first octave 2^k0, variable t with a = `a_of(t)`) is as
    /// accurate as that of ln Λ: at every segment boundary both neighbouring polynomials
    /// within [`DIRECT_TOL`] of the exact Λ there. Interpolation at the Chebyshev points errs
    /// most at a segment's ends (the node polynomial peaks there), so the ends measure the
    /// fit; tests/fast.rs checks the result over the whole domain.
    fn direct_is_accurate(
        exact: &crate::Gtr,
        (k0, m): (i32, u32),
        direct: &[[f64; N_FIT]],
        a_of: fn(f64) -> f64,
    ) -> bool {
        let per = 1usize << m;
        // Row i covers [t_i, t_{i+1}); Λ at each boundary once.
        let t = |i: usize| 2f64.powi(k0 + (i / per) as i32) * (1.0 + (i % per) as f64 / per as f64);
        let want: Vec<f64> = (0..=direct.len())
            .map(|i| exact.lambda_cot(a_of(t(i))))
            .collect();
        let ok = |got: f64, want: f64| ((got - want) / want).abs() <= DIRECT_TOL;
        direct
            .iter()
            .enumerate()
            .all(|(i, c)| ok(fit::poly(c, -1.0), want[i]) && ok(fit::poly(c, 1.0), want[i + 1]))
    }

    /// Whether the table holds Λ itself (no exponential at evaluation; moderate γ) rather
    /// than ln Λ.
    pub fn is_direct(&self) -> bool {
        self.direct
    }

    /// The largest deviation of the evaluated f64 table from the fitted polynomials it was
    /// re-expanded from (relative where Λ itself is tabulated, absolute in ln Λ otherwise),
    /// at 17 points per row: it adds to the fit's own error (tests/fast.rs measures the
    /// sum against the exact Λ). At most 3e-9 over α ∈ [1e-6, 1e6], γ ∈ [0.01, 100].
    pub fn reexpansion_error(&self) -> f64 {
        self.piece_dev
    }

    /// Whether the f32 entry points evaluate Λ natively in f32 (a table of cubics, f32
    /// arithmetic); else they evaluate in f64 and round once.
    pub fn has_f32_table(&self) -> bool {
        !self.coef32.is_empty()
    }

    /// α.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// γ.
    pub fn gamma(&self) -> f64 {
        self.gamma
    }

    /// The table's value (Λ, or ln Λ if not [`FittedGtr::is_direct`]) at t = u (`normal_side`
    /// false) or t = 1 − u, and whether t is inside the table (false for NaN and past the
    /// ends). No branch: the side indexes the layout, so there is neither a branch that
    /// random directions would mispredict nor a select the compiler could turn into one.
    #[inline(always)]
    pub(crate) fn table_at(&self, normal_side: bool, t: f64) -> (f64, bool) {
        self.table_on(self.sides[usize::from(normal_side)], t)
    }

    /// [`FittedGtr::table_at`] with the side's layout chosen by selects, for the slice kernels:
    /// in vector code a select is a blend, cheaper than gathering the layout per lane.
    #[inline(always)]
    pub(crate) fn table_at_lanes(&self, normal_side: bool, t: f64) -> (f64, bool) {
        let [u, w] = self.sides;
        let side = Side {
            off: if normal_side { w.off } else { u.off },
            lo: if normal_side { w.lo } else { u.lo },
        };
        self.table_on(side, t)
    }

    /// The value and the inside flag of [`FittedGtr::table_at`] on one side's table.
    #[inline(always)]
    fn table_on(&self, side: Side, t: f64) -> (f64, bool) {
        // (Clamped: t below the table wraps to a huge index; the flag sends it to the ends.)
        let row =
            ((t.to_bits() >> (52 - M_T)).wrapping_sub(side.off) as usize).min(self.coef.len() - 1);
        let (_, s) = fit::octave_segment(0, M_T, t);
        // Estrin's scheme for the scalar path too, unlike `fit::poly`'s Horner for five
        // coefficients: with Horner's rule GTR's scalar Λ measured no faster (5.2 against
        // 5.1 ns, and 6.7 against 5.7 in the bench's table of every quantity), and a table of
        // ln Λ would part the slice from the scalar path (Λ = e^p magnifies p's rounding by
        // |p|, up to ~700).
        (fit::estrin(&self.coef[row], s), t >= side.lo)
    }

    /// Rows in the tables (never 0; asserting that lets the slice kernel's row clamp drop
    /// its bounds check, so the loop vectorises).
    pub(crate) fn rows(&self) -> usize {
        self.coef.len()
    }

    /// Λ at a = cot θ ≥ 0 (+∞ at a = 0, 0 at a = +∞).
    #[inline(always)]
    pub fn lambda_cot(&self, a: f64) -> f64 {
        // u = a/r and w = 1 − u = 1/(r(r + a)), r = √(1 + a²), both without cancellation;
        // past 1e150 (a² would overflow) and for NaN the ends answer.
        let r = (1.0 + a * a).sqrt();
        let (u, w) = (a / r, 1.0 / (r * (r + a)));
        let normal_side = u >= 0.5;
        let (p, inside) = self.table_at(normal_side, if normal_side { w } else { u });
        if inside && a < 1e150 {
            return if self.direct { p } else { p.exp() };
        }
        self.lambda_cot_ends(a)
    }

    /// Λ past the tables (out of line): u ∉ (0, 1] first (+∞ at ±0, 0 past 1, Λ(|u|) below
    /// 0, NaN for NaN: u outside [0, 1] falls outside the tables), then the asymptotic ends.
    #[cold]
    #[inline(never)]
    fn lambda_outside(&self, u: f64) -> f64 {
        if !(u > 0.0 && u <= 1.0) {
            return super::lambda_at_edge(u, |v| self.lambda(v));
        }
        self.lambda_cot_ends(u / ((1.0 - u) * (1.0 + u)).sqrt())
    }

    /// Λ beyond the tables (the asymptotic ends; out of line, rarely reached) and NaN. The
    /// tables reach past a = 1 on both sides, so a < 1 here is the grazing end.
    #[cold]
    #[inline(never)]
    fn lambda_cot_ends(&self, a: f64) -> f64 {
        if a < 1.0 {
            return self.m[0] / a - 0.5 + self.m[1] * a;
        }
        if a.is_nan() {
            return a;
        }
        let r = 1.0 / a;
        (self.k[0] + self.k[1] * (r * r)) * (r * r)
    }

    /// D(u) for every u: c x^{−γ}, x = (1 − u)(1 + u) + (αu)² (a sum of positive terms); c/x
    /// and c/x² at γ = 1 and 2, else e^{ln c − γ ln x}: libm's ln and exp cost less than its
    /// pow, and ln c keeps the
    /// product finite where c or x^{−γ} alone would leave the f64 range. The error is the
    /// exponent's rounding, which grows with |ln c| and γ|ln x| (up to ~2 700 at γ = 100,
    /// α = 1e-6): tests/fast.rs measures 1.1e-13 relative over α ∈ [1e-3, 1e3],
    /// γ ∈ [0.1, 100] (7e-15 at γ ≤ 3), f32 6e-8. u outside (0, 1] and NaN take the exact
    /// path.
    #[inline]
    pub fn d<F: Real>(&self, u: F) -> F {
        let u = u.to_f64();
        if !(u > 0.0 && u <= 1.0) {
            return F::from_f64(self.d_outside(u));
        }
        let ua = self.alpha * u;
        F::from_f64(self.d_x((1.0 - u) * (1.0 + u) + ua * ua))
    }

    /// D of the unit normal wm: x = sin²θ + (α cos θ)² from the vector's x² + y² (where the
    /// scalar form's 1 − u² has lost the digits of a rounded near-normal vector: f32 wm.z
    /// carries 6e-8, a relative 6e-8/(1 − u) of 1 − u²); wm.z outside (0, 1] as [`Self::d`].
    #[inline]
    pub fn d_vec<F: Real>(&self, wm: [F; 3]) -> F {
        let u = wm[2].to_f64();
        if !(u > 0.0 && u <= 1.0) {
            return F::from_f64(self.d_outside(u));
        }
        let (x, y) = (wm[0].to_f64(), wm[1].to_f64());
        let ua = self.alpha * u;
        F::from_f64(self.d_x(x * x + y * y + ua * ua))
    }

    /// c x^{−γ} at x = sin²θ + (α cos θ)² > 0.
    #[inline(always)]
    fn d_x(&self, x: f64) -> f64 {
        // γ = 1 (Burley's clearcoat) and γ = 2 (GGX) need no logarithm; the test is on a
        // material constant, so it predicts.
        match self.power {
            Power::One => self.c / x,
            Power::Two => self.c / (x * x),
            Power::General => (self.ln_c - self.gamma * x.ln()).exp(),
        }
    }

    /// D outside (0, 1]: 0 below the horizon, D(1) above 1, NaN for NaN.
    #[cold]
    #[inline(never)]
    fn d_outside(&self, u: f64) -> f64 {
        self.exact.d(u)
    }

    /// Λ(u) for 0 ≤ u ≤ 1 (−0 and 1 + 2ε included): the u table below u = ½, the w table at w = 1 − u (exact) from
    /// there; no square root or division on the way. In f32, where the material has an f32
    /// table ([`FittedGtr::has_f32_table`]), that table in f32 arithmetic (Λ's condition number in
    /// t is about 1 at both ends); otherwise, and past the tables, the f64 path rounded once.
    #[inline]
    pub fn lambda<F: Real>(&self, u: F) -> F {
        if F::IS_F32 && !self.coef32.is_empty() {
            return F::from_f32(self.lambda32(u.to_f32()));
        }
        let u = u.to_f64();
        let normal_side = u >= 0.5;
        let (p, inside) = self.table_at(normal_side, if normal_side { 1.0 - u } else { u });
        F::from_f64(if inside {
            if self.direct {
                p
            } else {
                p.exp()
            }
        } else {
            self.lambda_outside(u)
        })
    }

    /// Λ(w) from a direction w of any length (Λ(−w) = Λ(w)): cos θ = |z|/n and, on the
    /// normal's side, t = 1 − cos θ = s²/(n(n + |z|)), s² = x² + y², n = √(s² + z²), formed
    /// from the vector. The scalar path's 1 − u of a rounded f32 unit vector has lost its
    /// digits near the normal (G1 2 % off at α = 1e4, 1 − z = 5e-7); this form keeps them,
    /// and keeps the f32 table and f32 arithmetic of [`FittedGtr::lambda`] (the GPU's
    /// `ms_gtr_lambda` is the same arithmetic). In f64, [`FittedGtr::lambda_cot`] at
    /// cot θ = |z|/s.
    #[inline]
    pub fn lambda_vec<F: Real>(&self, w: [F; 3]) -> F {
        if F::IS_F32 && !self.coef32.is_empty() {
            let [x, y, z] = w.map(F::to_f32);
            let z = z.abs();
            let s2 = x * x + y * y;
            let n = (s2 + z * z).sqrt();
            let u = z / n;
            let normal_side = u >= 0.5;
            let t = if normal_side { s2 / (n * (n + z)) } else { u };
            return F::from_f32(match self.table32(normal_side, t) {
                Some(v) => v,
                None => self.lambda_vec_ends(w.map(F::to_f64)) as f32,
            });
        }
        F::from_f64(self.lambda_vec_ends(w.map(F::to_f64)))
    }

    /// [`FittedGtr::lambda_vec`] in f64 (and the f32 path past its table: the zero vector
    /// and NaN included, which give NaN).
    #[inline]
    fn lambda_vec_ends(&self, w: [f64; 3]) -> f64 {
        let [x, y, z] = w;
        self.lambda_cot(z.abs() / (x * x + y * y).sqrt())
    }

    /// Λ from the f32 table (see [`FittedGtr::lambda`]); `coef32` is not empty.
    #[inline(always)]
    fn lambda32(&self, u: f32) -> f32 {
        let normal_side = u >= 0.5;
        match self.table32(normal_side, if normal_side { 1.0 - u } else { u }) {
            Some(v) => v,
            None => self.lambda32_ends(u),
        }
    }

    /// The f32 table at t = u (`normal_side` false) or t = 1 − u, or None where t is
    /// outside it (and for NaN).
    #[inline(always)]
    fn table32(&self, normal_side: bool, t: f32) -> Option<f32> {
        let side = usize::from(normal_side);
        // The exponent and top M_T mantissa bits less the side's offset are the row
        // (clamped: t below the table wraps to a huge index, and answers from the ends below).
        let row = ((t.to_bits() >> (23 - M_T)).wrapping_sub(self.off32[side]) as usize)
            .min(self.coef32.len() - 1);
        let (_, s) = fit::octave_segment32(0, M_T, t);
        // 2^k0 is an f32 (k0 ≥ −126: the w table starts at 2^−61 at α = 1e6).
        (t >= self.lo32[side]).then(|| fit::poly(&self.coef32[row], s))
    }

    /// Λ past the f32 table (and NaN): the f64 path, rounded.
    #[cold]
    #[inline(never)]
    fn lambda32_ends(&self, u: f32) -> f32 {
        self.lambda(f64::from(u)) as f32
    }

    /// G1(u) = 1/(1 + Λ(u)) for 0 ≤ u ≤ 1, in the precision of F (Λ's, see [`FittedGtr::lambda`]).
    #[inline]
    pub fn g1<F: Real>(&self, u: F) -> F {
        F::ONE / (F::ONE + self.lambda(u))
    }

    /// Height-correlated G2 = 1/(1 + Λ(u_o) + Λ(u_i)).
    #[inline]
    pub fn g2<F: Real>(&self, u_o: F, u_i: F) -> F {
        F::ONE / (F::ONE + self.lambda(u_o) + self.lambda(u_i))
    }

    /// A normal distributed as D(m) cos θm, u ∈ [0, 1]²: Burley's closed-form inversion
    /// (Burley 2012, appendix B, eqs. 3–9, in the stable arrangement of the exact path,
    /// [`crate::sampling::RadialSlopes`]) for tan θ = F⁻¹(u₀), azimuth 2πu₁; a warp of u with the
    /// exact sampler's accuracy. Evaluated in f64; the material's exponentials of ±kL are
    /// constants (`Burley`, shared with the exact path), which leaves five libm calls.
    /// (`arith`'s functions, tried here, were slower: this chain is bound by latency.)
    #[inline]
    pub(crate) fn sample_dcos<F: Real>(&self, u: [F; 2]) -> [F; 3] {
        use crate::sampling::dcos::RadialSlopes;
        let r = self.exact.slope_quantile(u[0].to_f64());
        super::normal_from_polar(r, super::cos_sin_turn(u[1].to_f64()), 1.0, 1.0)
    }

    /// The tables and the samplers' constants as the GPU crate lays them out (not an API).
    #[doc(hidden)]
    pub fn layout(&self) -> GtrLayout<'_> {
        let b = self.exact.burley();
        GtrLayout {
            alpha: self.alpha,
            gamma: self.gamma,
            direct: self.direct,
            rows: &self.coef,
            rows32: &self.coef32,
            off32: self.off32,
            lo32: self.lo32,
            m: self.m,
            k: self.k,
            sigma0: self.sigma0,
            c: self.c,
            ln_c: self.ln_c,
            burley: [
                b.l,
                b.k,
                b.kl,
                b.e,
                b.em1,
                b.e_neg,
                b.em1_neg,
                b.ex,
                b.ex_neg,
                b.ln_em1_abs,
            ],
            dcos: self.dcos.layout(),
            moment: self.moment.layout(),
        }
    }

    /// σ(u) for u ∈ [−1, 1].
    #[inline]
    pub fn sigma<F: Real>(&self, u: F) -> F {
        super::sigma_from_lambda(u, F::from_f64(self.sigma0), |v| self.lambda(v))
    }
}

/// What the GPU crate's table of a [`FittedGtr`] holds (not an API): the Λ tables (the f64
/// rows of degree 4 and, where there is one, the f32 cubics on the same rows), their lookup
/// offsets and ends, D's normalisation, Burley's constants of the D·cos quantile and the
/// visible sampler's two radial envelopes.
#[doc(hidden)]
#[derive(Clone, Debug)]
pub struct GtrLayout<'a> {
    pub alpha: f64,
    pub gamma: f64,
    /// Whether `rows` hold Λ itself (else ln Λ).
    pub direct: bool,
    /// The f64 rows (degree 4 in s ∈ [−1, 1), s⁰ first): the u table's, then the w table's.
    pub rows: &'a [[f64; N]],
    /// The f32 cubics on the same rows (empty where there are none).
    pub rows32: &'a [[f32; N32]],
    /// Per side [u, w]: the row of t is (bits of the f32 t) >> 18 less this (wrapping).
    pub off32: [u32; 2],
    /// Per side: 2^k0, below which t is past the table.
    pub lo32: [f32; 2],
    /// Λ ≈ m₀/a − ½ + m₁a at the grazing end (a = cot θ).
    pub m: [f64; 2],
    /// Λ ≈ (K₀ + K₁/a²)/a² near the normal.
    pub k: [f64; 2],
    pub sigma0: f64,
    /// D = c x^{−γ}, x = sin²θ + α² cos²θ; ln c (finite where c underflows).
    pub c: f64,
    pub ln_c: f64,
    /// Burley's quantile constants: L = ln α², k = 1 − γ, kL, e^{kL}, e^{kL} − 1, e^{−kL},
    /// e^{−kL} − 1, (e^{kL} − 1)/(kL), (e^{−kL} − 1)/(−kL), ln(e^{|kL|} − 1).
    pub burley: [f64; 10],
    /// The visible sampler's radial envelopes: D·cos slopes and the first moment.
    pub dcos: RadialLayout,
    pub moment: RadialLayout,
}

/// One radial envelope of the visible sampler (see `vndf.rs`), for the GPU crate.
#[doc(hidden)]
#[derive(Clone, Debug)]
pub struct RadialLayout {
    /// The density's power k of t = ln r² (1: D·cos, 3/2: the first moment).
    pub k: f64,
    /// The largest envelope exponent (subtracted from every piece's).
    pub top: f64,
    /// The pieces in order, the left tail first and the right tail last.
    pub pieces: Vec<RadialPiece>,
}

/// One piece of a radial envelope and its column of the alias table (column i's own piece is
/// piece i), for the GPU crate.
#[doc(hidden)]
#[derive(Clone, Copy, Debug)]
pub struct RadialPiece {
    /// Whether the piece is a tail (infinite width: t sampled from its exponential).
    pub tail: bool,
    /// Tails: t = a + ln(1 − v)/β, envelope exponent e0 + β(t − a) (relative to `top`),
    /// kept without φ below `squeeze`.
    pub a: f64,
    pub beta: f64,
    pub e0: f64,
    pub em1: f64,
    pub squeeze: f64,
    /// Finite pieces: r = r0 + v dr, kept without φ when keep ≤ s0 + s1 v, else against
    /// e^{φ − top − t/2 − h}.
    pub r0: f64,
    pub dr: f64,
    pub s0: f64,
    pub s1: f64,
    pub h: f64,
    /// The alias table's column: its own piece below `prob`, piece `alias` above.
    pub prob: f64,
    pub alias: u32,
}

/// Re-expands each fitted row (a polynomial in s ∈ [−1, 1]) onto its 2^split equal pieces:
/// on each, the degree B − 1 Chebyshev interpolant of the row in the piece's own s ∈ [−1, 1],
/// with coefficients rounded by `round` (to f64 or f32) and evaluated in that precision. No
/// exact Λ is evaluated. Returns the rows, in order, and their largest deviation from the
/// fitted rows at 17 points per piece (relative if `relative`, else absolute: for ln Λ).
fn re_expand<T: Real, const B: usize>(
    rows: &[[f64; N_FIT]],
    split: u32,
    relative: bool,
    round: impl Fn(f64) -> T,
) -> (Vec<[T; B]>, f64) {
    let pieces = 1usize << split;
    let width = 1.0 / pieces as f64; // half a piece's width in s
    let mut out = Vec::with_capacity(rows.len() * pieces);
    let mut worst = 0.0f64;
    for c in rows {
        for p in 0..pieces {
            // Piece p in the row's s: −1 + (2p + 1 + s') width, s' ∈ [−1, 1].
            let row = |s: f64| fit::poly(c, -1.0 + (2 * p + 1) as f64 * width + s * width);
            let r = fit::chebyshev_fit::<B>(row).map(&round);
            for k in 0..=16 {
                let s = -1.0 + k as f64 / 8.0;
                let (got, want) = (fit::poly(&r, round(s)).to_f64(), row(s));
                let scale = if relative { want.abs() } else { 1.0 };
                worst = worst.max((got - want).abs() / scale);
            }
            out.push(r);
        }
    }
    (out, worst)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The f64 table's rows, re-expanded onto 32 rows per octave, follow the fitted
    /// polynomials to 1e-8 (Λ relative, ln Λ absolute) over the whole parameter domain; and
    /// every material at γ ≤ 3 gets the f32 table.
    #[test]
    fn reexpanded_rows_follow_the_fit() {
        let mut worst = 0.0f64;
        for alpha in [1e-6, 1e-3, 0.05, 0.3, 1.0, 1.7, 1e3, 1e6] {
            for gamma in [0.01, 0.1, 0.5, 1.0, 1.5, 2.0, 3.0, 10.0, 100.0] {
                let g = FittedGtr::new(alpha, gamma).unwrap();
                assert!(
                    g.piece_dev <= 1e-8,
                    "α = {alpha}, γ = {gamma}: {:e}",
                    g.piece_dev
                );
                worst = worst.max(g.piece_dev);
                // The f32 table, where there is one, has the f64 table's layout.
                assert!(!g.has_f32_table() || g.coef32.len() == g.coef.len());
                if gamma <= 3.0 && (1e-3..=1e3).contains(&alpha) {
                    assert!(g.has_f32_table(), "α = {alpha}, γ = {gamma}");
                }
            }
        }
        println!("GTR re-expanded rows: within {worst:.2e} of the fit");
        // Table sizes at α = 0.3, γ = 1.5 (BENCHMARKS.md quotes them).
        let g = FittedGtr::new(0.3, 1.5).unwrap();
        println!(
            "α = 0.3, γ = 1.5: {} f64 rows ({} KiB), {} f32 rows ({} KiB)",
            g.coef.len(),
            g.coef.len() * N * 8 / 1024,
            g.coef32.len(),
            g.coef32.len() * N32 * 4 / 1024
        );
    }
}
