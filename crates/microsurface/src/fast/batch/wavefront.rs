//! The wavefront slices: one material over structure-of-arrays directions ([`Vectors`],
//! [`VectorsMut`]), GGX and Beckmann visible normals and the GGX conductor's eval, pdf and
//! sample ([`GgxConductor`]); branch-free lanes, a per-block flag array, flagged lanes by
//! the scalar calls. Compiled per instruction set and dispatched as the per-u slices
//! ([`super`]).

// `!(x > 0)` is the NaN-aware test (false for NaN) on a generic `Real`, on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::{simd, Simd, BLOCK};
use crate::bsdf::{Bsdf, Masking};
use crate::distribution::MicrofacetDistribution;
use crate::math::real::Real;

/// Vectors in structure-of-arrays form, a wavefront renderer's layout: element i is
/// `(x[i], y[i], z[i])`. The slices must have equal lengths.
#[derive(Clone, Copy, Debug)]
pub struct Vectors<'a, F> {
    pub x: &'a [F],
    pub y: &'a [F],
    pub z: &'a [F],
}

/// Output vectors in structure-of-arrays form (each slice at least as long as the inputs).
#[derive(Debug)]
pub struct VectorsMut<'a, F> {
    pub x: &'a mut [F],
    pub y: &'a mut [F],
    pub z: &'a mut [F],
}

/// The GGX conductor the BSDF slices take: an f32 or f64 [`crate::Microfacet`] GGX with the
/// exact complex-IOR Fresnel term, RGB.
pub type GgxConductor<F> = crate::bsdf::RoughConductor<
    F,
    crate::Microfacet<F, crate::Ggx>,
    crate::bsdf::fresnel::Conductor<F, 3>,
    3,
>;

/// (cos 2πv, sin 2πv) for a uniform v in the precision of F, branch-free (the slice kernels'
/// azimuth): f64 is [`crate::fast::cos_sin_turn`]; f32 the same reduction to the nearest quarter
/// turn, then Taylor polynomials to x⁹ (sin) and x⁸ (cos) on |x| ≤ π/4 in f32 (the next
/// terms are below 2.5e-8; the f32 roundings give about 1e-7).
#[inline(always)]
fn cos_sin_turn_f<F: Real>(v: F) -> (F, F) {
    if !F::IS_F32 {
        let (c, s) = crate::fast::cos_sin_turn(v.to_f64());
        return (F::from_f64(c), F::from_f64(s));
    }
    let v = v.to_f32();
    // 1.5·2^23: adding it rounds to an integer held in the low mantissa bits.
    const MAGIC: f32 = 12_582_912.0;
    let t = 4.0 * v + MAGIC;
    let k = t.to_bits();
    let r = v - (t - MAGIC) * 0.25;
    let x = std::f32::consts::TAU * r;
    let x2 = x * x;
    let s = x
        * (1.0
            + x2 * (-1.0 / 6.0
                + x2 * (1.0 / 120.0 + x2 * (-1.0 / 5040.0 + x2 * (1.0 / 362_880.0)))));
    let c = 1.0 + x2 * (-0.5 + x2 * (1.0 / 24.0 + x2 * (-1.0 / 720.0 + x2 * (1.0 / 40_320.0))));
    // k odd: (c, s) → (−s, c); k & 2: both negated.
    let odd = (k & 1).wrapping_neg();
    let flip = (k & 2) << 30;
    let c1 = (c.to_bits() & !odd) | ((-s).to_bits() & odd);
    let s1 = (s.to_bits() & !odd) | (c.to_bits() & odd);
    (
        F::from_f32(f32::from_bits(c1 ^ flip)),
        F::from_f32(f32::from_bits(s1 ^ flip)),
    )
}

/// Panics unless every input slice has length n and every output at least n (the slice
/// functions' one panic, as slice indexing's).
fn check_lengths(n: usize, inputs: &[usize], outputs: &[usize]) {
    assert!(
        inputs.iter().all(|&l| l == n) && outputs.iter().all(|&l| l >= n),
        "slice lengths differ"
    );
}

/// One lane of the GGX visible-normal slice: spherical caps (Dupuy & Benyoub 2023) as
/// [`crate::fast::ggx_visible_stretched_len`], branch-free, with the flag of the lanes the scalar
/// sampler redoes: a stretched direction whose squared length leaves [1e-24, 1e24] (f32) or
/// [1e-200, 1e200] (f64) (a non-unit or extreme direction), a normal that does not face w
/// strictly (the scalar path's `facing` fix), and NaN.
#[inline(always)]
fn ggx_vndf_lane<F: Real>(w: [F; 3], ax: F, ay: F, u: [F; 2]) -> ([F; 3], bool) {
    let s = if w[2] < F::ZERO { -F::ONE } else { F::ONE };
    let (wx, wy, wz) = (s * w[0], s * w[1], s * w[2]);
    let (x, y) = (ax * wx, ay * wy);
    let n2 = x * x + y * y + wz * wz;
    let inv = F::ONE / n2.sqrt();
    let (x, y, z) = (x * inv, y * inv, wz * inv);
    let (c, sn) = cos_sin_turn_f(u[0]);
    let above = (F::ONE - u[1]) * (F::ONE + z);
    // sin²θ without the cancellation at the cap's poles, as the scalar sampler.
    let sin = (u[1] * (above * (F::ONE + z) + (x * x + y * y)))
        .max(F::ZERO)
        .sqrt();
    let (hx, hy, hz) = (ax * (sin * c + x), ay * (sin * sn + y), above);
    let inv = F::ONE / (hx * hx + hy * hy + hz * hz).sqrt();
    let m = [hx * inv, hy * inv, hz * inv];
    let (lo, hi) = if F::IS_F32 {
        (1e-24, 1e24)
    } else {
        (1e-200, 1e200)
    };
    let facing = m[0] * wx + m[1] * wy + m[2] * wz;
    let ok = n2 >= F::from_f64(lo) && n2 <= F::from_f64(hi) && facing > F::ZERO;
    (m, !ok)
}

/// The GGX visible-normal slice in the precision of F (see [`ggx_sample_visible_f32`]).
#[inline(always)]
fn ggx_vndf_slice<F: Real>(
    m: &crate::Microfacet<F, crate::Ggx>,
    w: Vectors<'_, F>,
    u0: &[F],
    u1: &[F],
    out: VectorsMut<'_, F>,
) {
    let n = w.x.len();
    check_lengths(
        n,
        &[w.y.len(), w.z.len(), u0.len(), u1.len()],
        &[out.x.len(), out.y.len(), out.z.len()],
    );
    let (ax, ay) = m.alpha();
    let mut start = 0;
    while start < n {
        let end = (start + BLOCK).min(n);
        // The lanes the scalar sampler redoes, recorded in the vectorised pass.
        let mut flags = [false; BLOCK];
        for i in start..end {
            let (v, bad) = ggx_vndf_lane([w.x[i], w.y[i], w.z[i]], ax, ay, [u0[i], u1[i]]);
            out.x[i] = v[0];
            out.y[i] = v[1];
            out.z[i] = v[2];
            flags[i - start] = bad;
        }
        for i in start..end {
            if flags[i - start] {
                let v = m.sample_wm([w.x[i], w.y[i], w.z[i]], [u0[i], u1[i]]);
                (out.x[i], out.y[i], out.z[i]) = (v[0], v[1], v[2]);
            }
        }
        start = end;
    }
}

dispatched! {
/// GGX visible normals for a slice of directions (one material; w of any finite nonzero
/// length, mirrored if w.z < 0, as [`MicrofacetDistribution::sample_wm`]): element i is the
/// normal for `(w[i], [u0[i], u1[i]])`, by the scalar sampler's spherical caps with the
/// azimuth's cosine and sine from a polynomial in f32 (the normal within a few f32 ulps of
/// the scalar's, magnified by the anisotropy: 2e-6 at αx/αy = 2000, tests/wavefront.rs).
/// Lanes the vectorised formula does not cover (extreme lengths, a normal that must be
/// tipped to face w) get the scalar sampler's answer. Panics if the lengths differ (as slice
/// indexing does).
pub fn ggx_sample_visible_f32(
    m: &crate::Microfacet<f32, crate::Ggx>,
    w: Vectors<'_, f32>,
    u0: &[f32],
    u1: &[f32],
    out: VectorsMut<'_, f32>,
) {
    ggx_vndf_slice(m, w, u0, u1, out);
}
}

dispatched! {
/// [`ggx_sample_visible_f32`] in f64, where it returns the scalar sampler's bits.
pub fn ggx_sample_visible_f64(
    m: &crate::Microfacet<f64, crate::Ggx>,
    w: Vectors<'_, f64>,
    u0: &[f64],
    u1: &[f64],
    out: VectorsMut<'_, f64>,
) {
    ggx_vndf_slice(m, w, u0, u1, out);
}
}

/// The Beckmann visible-normal slice in the precision of F (see
/// [`beckmann_sample_visible_f32`]): [`crate::fast::beckmann`]'s lanes, branch-free over
/// contiguous blocks (their table rows gathered), the flagged ones by the scalar sampler.
#[inline(always)]
fn beckmann_vndf_slice<F: Real>(
    m: &crate::Microfacet<F, crate::Beckmann>,
    w: Vectors<'_, F>,
    u0: &[F],
    u1: &[F],
    out: VectorsMut<'_, F>,
) {
    let n = w.x.len();
    check_lengths(
        n,
        &[w.y.len(), w.z.len(), u0.len(), u1.len()],
        &[out.x.len(), out.y.len(), out.z.len()],
    );
    let (ax, ay) = m.alpha();
    let mut start = 0;
    while start < n {
        let end = (start + BLOCK).min(n);
        // The block's normals and the lanes the scalar sampler redoes, in arrays of the
        // block's own: the lanes read tables at computed rows, and with their stores going
        // straight to the output slices the compiler could not rule out that a store lands
        // in a table (it would need run-time overlap checks it cannot form for computed
        // rows), and kept the loop scalar.
        let mut v = [[F::ZERO; BLOCK]; 3];
        let mut flags = [false; BLOCK];
        for i in start..end {
            let (m, bad) = crate::fast::beckmann::sample_visible_lane(
                [w.x[i], w.y[i], w.z[i]],
                ax,
                ay,
                [u0[i], u1[i]],
            );
            let j = i - start;
            (v[0][j], v[1][j], v[2][j], flags[j]) = (m[0], m[1], m[2], bad);
        }
        out.x[start..end].copy_from_slice(&v[0][..end - start]);
        out.y[start..end].copy_from_slice(&v[1][..end - start]);
        out.z[start..end].copy_from_slice(&v[2][..end - start]);
        for i in start..end {
            if flags[i - start] {
                let v = m.sample_wm([w.x[i], w.y[i], w.z[i]], [u0[i], u1[i]]);
                (out.x[i], out.y[i], out.z[i]) = (v[0], v[1], v[2]);
            }
        }
        start = end;
    }
}

dispatched! {
/// Beckmann visible normals for a slice of directions (as [`ggx_sample_visible_f32`]): the
/// scalar sampler's exact warp in lanes ([`crate::fast::beckmann`]: the table guess and one
/// step of order five, evaluated in f64 and rounded once, as the scalar f32 path), with e^x
/// from [`crate::fast::arith`] where the scalar sampler calls libm: the normals within
/// a few f64 ulps of the scalar's, magnified by the anisotropy (6e-15 at αx/αy = 2000 in f64;
/// the same f32 in the tests, tests/wavefront.rs). Lanes the one-step path does not cover
/// (u₁ within 2^−11 of 0 or 2^−21 of 1, normal incidence, extreme lengths, a normal that
/// must be tipped to face w) get the scalar sampler's answer.
pub fn beckmann_sample_visible_f32(
    m: &crate::Microfacet<f32, crate::Beckmann>,
    w: Vectors<'_, f32>,
    u0: &[f32],
    u1: &[f32],
    out: VectorsMut<'_, f32>,
) {
    beckmann_vndf_slice(m, w, u0, u1, out);
}
}

dispatched! {
/// [`beckmann_sample_visible_f32`] in f64.
pub fn beckmann_sample_visible_f64(
    m: &crate::Microfacet<f64, crate::Beckmann>,
    w: Vectors<'_, f64>,
    u0: &[f64],
    u1: &[f64],
    out: VectorsMut<'_, f64>,
) {
    beckmann_vndf_slice(m, w, u0, u1, out);
}
}

/// GGX Λ of a unit direction at (αx, αy), branch-free (+∞ or NaN at z = 0: flagged by the
/// callers).
#[inline(always)]
fn ggx_lambda_lane<F: Real>(w: [F; 3], ax: F, ay: F) -> F {
    let (x, y, z) = (ax * w[0], ay * w[1], w[2].abs());
    let t = x * x + y * y;
    let z2 = z * z;
    t / ((F::ONE + F::ONE) * (z2 + z * (z2 + t).sqrt()))
}

/// One lane of the GGX conductor's eval and pdf (wo, wi unit), branch-free: f = F(wo·wm)
/// D G2/(4|cos θo cos θi|), pdf = G1(wo) D/(4|cos θo|) with wm the half vector, 0 where wo
/// and wi lie on opposite sides; the flag marks the lanes the scalar BSDF redoes (within
/// 1e-6 of the horizon, a half vector of length below 1e-6, NaN, a value not finite).
#[inline(always)]
fn conductor_lane<F: Real>(
    ax: F,
    ay: F,
    fr: &crate::bsdf::fresnel::Conductor<F, 3>,
    masking: Masking,
    wo: [F; 3],
    wi: [F; 3],
) -> ([F; 3], F, bool) {
    let (co, ci) = (wo[2], wi[2]);
    let same = co * ci > F::ZERO;
    let h = [wo[0] + wi[0], wo[1] + wi[1], co + ci];
    let hl2 = h[0] * h[0] + h[1] * h[1] + h[2] * h[2];
    let sign = if h[2] < F::ZERO { -F::ONE } else { F::ONE };
    let inv = sign / hl2.sqrt();
    let wm = [h[0] * inv, h[1] * inv, h[2] * inv];
    // D at wm (wm.z ≥ 0 here), GGX's vector form.
    let (x, y, z) = (wm[0] / ax, wm[1] / ay, wm[2]);
    let t = x * x + y * y + z * z;
    let d = F::ONE / (F::PI * ax * ay * t * t);
    let (lo, li) = (ggx_lambda_lane(wo, ax, ay), ggx_lambda_lane(wi, ax, ay));
    let g2 = match masking {
        // (A conductor only reflects: both height-correlated forms are 1/(1 + Λo + Λi).)
        Masking::Correlated | Masking::CorrelatedBeta => F::ONE / (F::ONE + (lo + li)),
        Masking::Separable => F::ONE / ((F::ONE + lo) * (F::ONE + li)),
    };
    // (F at the mean of |wo·wm| and |wi·wm|, as the scalar BSDF.)
    let c = F::HALF
        * ((wo[0] * wm[0] + wo[1] * wm[1] + co * wm[2]).abs()
            + (wi[0] * wm[0] + wi[1] * wm[1] + ci * wm[2]).abs());
    let k = d * g2 / (F::from_f64(4.0) * (co * ci).abs());
    let f = std::array::from_fn(|j| crate::bsdf::fresnel::conductor(c, fr.eta[j], fr.k[j]) * k);
    let pdf = d / ((F::ONE + lo) * F::from_f64(4.0) * co.abs());
    let floor = F::from_f64(1e-6);
    let ok = co.abs() >= floor && ci.abs() >= floor && hl2 >= floor * floor;
    let f = f.map(|v| if same { v } else { F::ZERO });
    let pdf = if same { pdf } else { F::ZERO };
    let finite = f[0].to_f64().is_finite()
        && f[1].to_f64().is_finite()
        && f[2].to_f64().is_finite()
        && pdf.to_f64().is_finite();
    (f, pdf, !(ok && finite))
}

/// The GGX conductor's eval and pdf slices (see [`ggx_conductor_eval_f32`]).
#[inline(always)]
fn conductor_eval_slice<F: Real>(
    b: &GgxConductor<F>,
    wo: Vectors<'_, F>,
    wi: Vectors<'_, F>,
    f: [&mut [F]; 3],
    pdf: &mut [F],
) {
    let n = wo.x.len();
    check_lengths(
        n,
        &[wo.y.len(), wo.z.len(), wi.x.len(), wi.y.len(), wi.z.len()],
        &[f[0].len(), f[1].len(), f[2].len(), pdf.len()],
    );
    let [f0, f1, f2] = f;
    let m = b.distribution();
    let (fr, masking) = b.fresnel_masking();
    let (ax, ay) = m.alpha();
    if m.effectively_smooth() {
        // A delta lobe: f and pdf are 0 for every pair of directions (the scalar's answer).
        for v in [&mut *f0, &mut *f1, &mut *f2, &mut *pdf] {
            v[..n].fill(F::ZERO);
        }
        return;
    }
    let mut start = 0;
    while start < n {
        let end = (start + BLOCK).min(n);
        let mut flags = [false; BLOCK];
        for i in start..end {
            let o = [wo.x[i], wo.y[i], wo.z[i]];
            let v = [wi.x[i], wi.y[i], wi.z[i]];
            let (fv, p, bad) = conductor_lane(ax, ay, fr, masking, o, v);
            (f0[i], f1[i], f2[i], pdf[i]) = (fv[0], fv[1], fv[2], p);
            flags[i - start] = bad;
        }
        for i in start..end {
            if flags[i - start] {
                let o = [wo.x[i], wo.y[i], wo.z[i]];
                let v = [wi.x[i], wi.y[i], wi.z[i]];
                let fv = b.eval(o, v);
                (f0[i], f1[i], f2[i], pdf[i]) = (fv[0], fv[1], fv[2], b.pdf(o, v));
            }
        }
        start = end;
    }
}

dispatched! {
/// The GGX conductor's f (RGB, one slice per channel) and pdf for a slice of direction pairs
/// `(wo[i], wi[i])`, unit vectors: [`Bsdf::eval`] and [`Bsdf::pdf`] element by element (the
/// same formulas, to a few ulp: the half vector is normalised by one division), with the
/// lanes near the horizon or degenerate redone by the scalar BSDF. Panics if the lengths
/// differ.
pub fn ggx_conductor_eval_f32(
    b: &GgxConductor<f32>,
    wo: Vectors<'_, f32>,
    wi: Vectors<'_, f32>,
    f: [&mut [f32]; 3],
    pdf: &mut [f32],
) {
    conductor_eval_slice(b, wo, wi, f, pdf);
}
}

dispatched! {
/// [`ggx_conductor_eval_f32`] in f64.
pub fn ggx_conductor_eval_f64(
    b: &GgxConductor<f64>,
    wo: Vectors<'_, f64>,
    wi: Vectors<'_, f64>,
    f: [&mut [f64]; 3],
    pdf: &mut [f64],
) {
    conductor_eval_slice(b, wo, wi, f, pdf);
}
}

/// The GGX conductor's sample slices (see [`ggx_conductor_sample_f32`]).
#[inline(always)]
fn conductor_sample_slice<F: Real>(
    b: &GgxConductor<F>,
    wo: Vectors<'_, F>,
    u0: &[F],
    u1: &[F],
    wi: VectorsMut<'_, F>,
    f: [&mut [F]; 3],
    pdf: &mut [F],
) {
    let n = wo.x.len();
    check_lengths(
        n,
        &[wo.y.len(), wo.z.len(), u0.len(), u1.len()],
        &[
            f[0].len(),
            f[1].len(),
            f[2].len(),
            pdf.len(),
            wi.x.len(),
            wi.y.len(),
            wi.z.len(),
        ],
    );
    let [f0, f1, f2] = f;
    let m = b.distribution();
    let (fr, masking) = b.fresnel_masking();
    let (ax, ay) = m.alpha();
    let smooth = m.effectively_smooth();
    let mut start = 0;
    while start < n {
        let end = (start + BLOCK).min(n);
        // The lanes the scalar sampler redoes (all of them for a delta lobe).
        let mut flags = [smooth; BLOCK];
        if !smooth {
            for i in start..end {
                let o = [wo.x[i], wo.y[i], wo.z[i]];
                let (wm, bad_m) = ggx_vndf_lane(o, ax, ay, [u0[i], u1[i]]);
                let c = o[0] * wm[0] + o[1] * wm[1] + o[2] * wm[2];
                let v = [
                    (c + c) * wm[0] - o[0],
                    (c + c) * wm[1] - o[1],
                    (c + c) * wm[2] - o[2],
                ];
                let (fv, p, bad_f) = conductor_lane(ax, ay, fr, masking, o, v);
                (wi.x[i], wi.y[i], wi.z[i]) = (v[0], v[1], v[2]);
                (f0[i], f1[i], f2[i], pdf[i]) = (fv[0], fv[1], fv[2], p);
                // Rejected (wi on the other side: pdf 0) or flagged: the scalar decides.
                flags[i - start] = bad_m | bad_f | !crate::bsdf::usable(p);
            }
        }
        for i in start..end {
            if flags[i - start] {
                let o = [wo.x[i], wo.y[i], wo.z[i]];
                let (v, fv, p) = match b.sample(o, F::ZERO, [u0[i], u1[i]]) {
                    Some(s) => (s.wi, s.f, s.pdf),
                    None => ([F::ZERO; 3], [F::ZERO; 3], F::ZERO),
                };
                (wi.x[i], wi.y[i], wi.z[i]) = (v[0], v[1], v[2]);
                (f0[i], f1[i], f2[i], pdf[i]) = (fv[0], fv[1], fv[2], p);
            }
        }
        start = end;
    }
}

dispatched! {
/// The GGX conductor's samples for a slice of outgoing directions `wo[i]` (unit) and uniforms
/// `(u0[i], u1[i])`: wi, f (RGB) and pdf as [`Bsdf::sample`] element by element (its visible
/// normal by [`ggx_sample_visible_f32`]'s lanes, then the reflection and the eval lane). A
/// rejected sample (the scalar's `None`: wi below the horizon, wo on it) is written as
/// wi = 0, f = 0, pdf = 0; a delta lobe (α < 1e-3) as the scalar's mirror sample. Panics if
/// the lengths differ.
pub fn ggx_conductor_sample_f32(
    b: &GgxConductor<f32>,
    wo: Vectors<'_, f32>,
    u0: &[f32],
    u1: &[f32],
    wi: VectorsMut<'_, f32>,
    f: [&mut [f32]; 3],
    pdf: &mut [f32],
) {
    conductor_sample_slice(b, wo, u0, u1, wi, f, pdf);
}
}

dispatched! {
/// [`ggx_conductor_sample_f32`] in f64.
pub fn ggx_conductor_sample_f64(
    b: &GgxConductor<f64>,
    wo: Vectors<'_, f64>,
    u0: &[f64],
    u1: &[f64],
    wi: VectorsMut<'_, f64>,
    f: [&mut [f64]; 3],
    pdf: &mut [f64],
) {
    conductor_sample_slice(b, wo, u0, u1, wi, f, pdf);
}
}
