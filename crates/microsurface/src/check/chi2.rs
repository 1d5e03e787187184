//! A reusable χ² goodness-of-fit harness for direction samplers (after Mitsuba 3's `chi2.py`).
//!
//! Samples are binned on a grid over coordinates (s, t) ∈ [0, 1)² that a [`Coordinates`] map
//! assigns to directions; the expected count of each cell is n ∫∫_cell pdf(ω(s, t)) J(s, t) ds dt
//! (a fixed 33 × 33-node tanh-sinh rule per cell, which tolerates the integrable singularity
//! of a tail heavier than the reference's at the grid's edge; a jump of the pdf inside a cell,
//! as in the bounded VNDF, is integrated only to ~1e-3 of that cell), cells expecting fewer than 5 samples are pooled, and the χ²
//! statistic is turned into a p-value with the regularised upper incomplete gamma function.
//! The caller compares the p-value with a significance corrected for the number of tests
//! (Šidák: 1 − (1 − 0.01)^{1/N}).
//!
//! The default coordinates are those of the D·cos warp of a *reference* NDF (the inverse
//! warp `invert_dcos`), in which D·cos of that reference is uniform: cells then follow the
//! lobe at any roughness, where a plain (φ, cos θ) grid would put a specular lobe in one cell.
//! A sampler is never tested in its own coordinates (that would be circular).

use crate::distribution::{Exact, MicrofacetDistribution};
use crate::math::vec3::Vec3;

/// A map from directions to [0, 1)² and back, with the Jacobian |dω/(ds dt)|.
pub trait Coordinates {
    /// (s, t) of a direction (wm.z > 0).
    fn unit_of(&self, w: Vec3) -> [f64; 2];
    /// The direction at (s, t) and the solid angle per unit area there.
    fn direction_at(&self, u: [f64; 2]) -> (Vec3, f64);
    /// Whether w lies in the region the grid covers (the upper hemisphere by default).
    fn covers(&self, w: Vec3) -> bool {
        w.z > 0.0
    }
}

/// The D·cos warp of a reference material's exact path: J = 1/(D(ω) cos θ).
pub struct DcosCoordinates<'a>(pub &'a Exact);

impl Coordinates for DcosCoordinates<'_> {
    fn unit_of(&self, w: Vec3) -> [f64; 2] {
        self.0.invert_dcos(w.into())
    }
    fn direction_at(&self, u: [f64; 2]) -> (Vec3, f64) {
        let s = self.0.sample_dcos(u);
        (s.wm.into(), if s.pdf > 0.0 { 1.0 / s.pdf } else { 0.0 })
    }
}

/// Coordinates for heavy tails: GGX's D·cos warp at roughness α, isotropic, counted from the
/// horizon and raised to a power q ≥ 1: s = W^{1/q}, W = 1 − F = α² cos²θ/(α² cos²θ + sin²θ)
/// the mass of GGX's D·cos beyond θ (in closed form, so that directions near the horizon keep
/// full precision at s → 0), φ = 2πt. The Jacobian
/// |dω/(ds dt)| = 2π q s^{q−1} α²/(2 cos θ (W + α²(1 − W))²)
/// goes to 0 like s^{q/2−1} at the horizon. A density that grows like cos^{−β} θ there (a
/// visible-normal pdf of a power-law NDF, P22 ~ r^{−2γ}: D·(wi·m) ~ cos^{2γ−4} θ) is, in
/// (s, t), ~ s^{q(γ − 3/2) − 1}: bounded for q ≥ 1/(γ − 3/2). In D·cos coordinates of any
/// reference it would be a singularity at the grid's edge s → 1, where f64 cannot resolve
/// 1 − s below 1e-16 (Student-T γ = 1.55: 2.6 % of that row's integral lies there).
pub struct TailCoordinates {
    pub alpha: f64,
    pub q: f64,
}

impl Coordinates for TailCoordinates {
    fn unit_of(&self, w: Vec3) -> [f64; 2] {
        let l = w.length();
        let (c, s2) = (w.z / l, (w.x * w.x + w.y * w.y) / (l * l));
        let a2c2 = self.alpha * self.alpha * c * c;
        let big_w = a2c2 / (a2c2 + s2);
        let mut phi = w.y.atan2(w.x) / std::f64::consts::TAU;
        if phi < 0.0 {
            phi += 1.0;
        }
        [big_w.powf(1.0 / self.q).clamp(0.0, 1.0), phi.min(1.0)]
    }
    fn direction_at(&self, u: [f64; 2]) -> (Vec3, f64) {
        let (s, a2) = (u[0], self.alpha * self.alpha);
        let w = s.powf(self.q);
        let den = w + a2 * (1.0 - w);
        let c2 = w / den;
        let (c, sin) = (c2.sqrt(), (a2 * (1.0 - w) / den).sqrt());
        let (sp, cp) = (std::f64::consts::TAU * u[1]).sin_cos();
        let jac =
            std::f64::consts::TAU * self.q * s.powf(self.q - 1.0) * a2 / (2.0 * c * den * den);
        (
            Vec3::new(sin * cp, sin * sp, c),
            if jac.is_finite() { jac } else { 0.0 },
        )
    }
}

/// GGX's D·cos warp at roughness α about an axis: the hemisphere around `axis` (a unit
/// vector), for lobes that are not centred on the normal (a BSDF's reflection and
/// transmission lobes). In closed form (tan²θ = α²s/(1 − s), φ = 2πt; J = 1/(D cos θ)), a
/// few tens of nanoseconds per node.
pub struct AxisCoordinates {
    alpha: f64,
    frame: crate::bsdf::frame::Frame<f64>,
}

impl AxisCoordinates {
    /// GGX's D·cos warp at roughness α in a frame whose z is `axis`.
    pub fn new(alpha: f64, axis: Vec3) -> Self {
        AxisCoordinates {
            alpha,
            frame: crate::bsdf::frame::Frame::from_normal(axis.into()),
        }
    }

    /// D(θ) cos θ of GGX at cos θ = c.
    fn dcos(&self, c: f64) -> f64 {
        let a2 = self.alpha * self.alpha;
        let t = (1.0 - c) * (1.0 + c) + c * c * a2;
        a2 * c / (std::f64::consts::PI * t * t)
    }
}

impl Coordinates for AxisCoordinates {
    fn unit_of(&self, w: Vec3) -> [f64; 2] {
        let l = self.frame.to_local(w.into());
        let (s2, c2) = (l[0] * l[0] + l[1] * l[1], l[2] * l[2]);
        // s = tan²θ/(α² + tan²θ) = sin²θ/(α² cos²θ + sin²θ).
        let s = s2 / (self.alpha * self.alpha * c2 + s2);
        let mut phi = l[1].atan2(l[0]) / std::f64::consts::TAU;
        if phi < 0.0 {
            phi += 1.0;
        }
        [s.clamp(0.0, 1.0), phi.min(1.0)]
    }
    fn direction_at(&self, u: [f64; 2]) -> (Vec3, f64) {
        // cos²θ = (1 − s)/(1 − s + α² s).
        let (s, a2) = (u[0], self.alpha * self.alpha);
        let c2 = (1.0 - s) / (1.0 - s + a2 * s);
        let c = c2.sqrt();
        let sin = (1.0 - c2).max(0.0).sqrt();
        let (sp, cp) = (std::f64::consts::TAU * u[1]).sin_cos();
        let w = self.frame.from_local([sin * cp, sin * sp, c]);
        let p = self.dcos(c);
        (Vec3::from(w), if p > 0.0 { 1.0 / p } else { 0.0 })
    }
    fn covers(&self, w: Vec3) -> bool {
        self.frame.to_local(w.into())[2] > 0.0
    }
}

/// The outcome of one test.
#[derive(Clone, Debug)]
pub struct Chi2 {
    pub statistic: f64,
    pub dof: usize,
    pub p_value: f64,
    /// Σ over cells of the expected counts divided by n: the pdf's integral over the sphere
    /// region covered by the coordinates (should be 1).
    pub pdf_integral: f64,
    /// Samples that were not finite unit vectors in the upper hemisphere.
    pub bad_samples: usize,
}

/// The harness's uniforms: the library's generator ([`SplitMix64::next_f64`]).
pub use crate::math::rng::SplitMix64;

/// Runs a χ² test of `sample` (mapping uniforms to directions) against `pdf` (w.r.t. solid
/// angle) with `n` samples on a `res × res` grid of `coords`.
pub fn chi2_test(
    mut sample: impl FnMut([f64; 2]) -> Vec3,
    pdf: impl Fn(Vec3) -> f64,
    coords: &impl Coordinates,
    n: usize,
    res: usize,
    seed: u64,
) -> Chi2 {
    let mut rng = SplitMix64(seed);
    let mut bad = 0;
    let (observed, _) = histogram(
        || {
            let w = sample([rng.next_f64(), rng.next_f64()]);
            let ok = unit(w) && w.z > 0.0;
            if !ok {
                bad += 1;
                return None;
            }
            Some(w)
        },
        coords,
        n,
        res,
    );
    let mut r = statistic(&observed, &expected(&pdf, coords, n, res, 2), None, n);
    r.bad_samples = bad;
    r
}

/// A χ² test of a sampler whose directions cover the sphere and which may reject (a BSDF):
/// `sample` draws its own uniforms from the generator and returns `None` for a rejected
/// sample; directions in `coords`' region ([`Coordinates::covers`]) are binned on its grid,
/// and everything else (rejections and the rest of the sphere) makes one more cell, expecting
/// n − Σ the grid's expectations (the total probability is 1 by construction). The
/// `pdf_integral` returned is that of the region.
pub fn chi2_test_region(
    mut sample: impl FnMut(&mut SplitMix64) -> Option<Vec3>,
    pdf: impl Fn(Vec3) -> f64,
    coords: &impl Coordinates,
    n: usize,
    res: usize,
    seed: u64,
) -> Chi2 {
    let mut rng = SplitMix64(seed);
    let mut bad = 0;
    let (observed, outside) = histogram(
        || {
            let w = sample(&mut rng)?;
            let ok = unit(w);
            if !ok {
                bad += 1;
                return None;
            }
            Some(w)
        },
        coords,
        n,
        res,
    );
    let mut r = statistic(
        &observed,
        &expected(&pdf, coords, n, res, 2),
        Some(outside),
        n,
    );
    r.bad_samples = bad;
    r
}

/// [`chi2_test_region`] with the expected counts given (n ∫∫_cell pdf J per cell, from
/// another route than the pdf: a push-forward quadrature, say, where the pdf has a
/// singularity no cell rule integrates); `pdf_integral` is their sum over n.
pub fn chi2_test_region_expected(
    mut sample: impl FnMut(&mut SplitMix64) -> Option<Vec3>,
    expected: &[f64],
    coords: &impl Coordinates,
    n: usize,
    res: usize,
    seed: u64,
) -> Chi2 {
    let mut rng = SplitMix64(seed);
    let (observed, outside) = histogram(|| sample(&mut rng), coords, n, res);
    statistic(&observed, expected, Some(outside), n)
}

/// The cell of `coords`' `res × res` grid that w falls in (None outside its region).
pub fn cell_of(coords: &impl Coordinates, w: Vec3, res: usize) -> Option<usize> {
    if !coords.covers(w) {
        return None;
    }
    let [s, t] = coords.unit_of(w);
    let i = ((s * res as f64) as usize).min(res - 1);
    let j = ((t * res as f64) as usize).min(res - 1);
    Some(i * res + j)
}

/// A finite unit vector (to 1e-9): what a sampler must return.
fn unit(w: Vec3) -> bool {
    w.x.is_finite() && w.y.is_finite() && w.z.is_finite() && (w.length() - 1.0).abs() < 1e-9
}

/// Counts per cell of the directions `coords` covers, and the number of the rest.
fn histogram(
    mut sample: impl FnMut() -> Option<Vec3>,
    coords: &impl Coordinates,
    n: usize,
    res: usize,
) -> (Vec<f64>, f64) {
    let mut observed = vec![0.0f64; res * res];
    let mut outside = 0.0;
    for _ in 0..n {
        let Some(w) = sample() else {
            outside += 1.0;
            continue;
        };
        match cell_of(coords, w, res) {
            Some(c) => observed[c] += 1.0,
            None => outside += 1.0,
        }
    }
    (observed, outside)
}

/// The expected count of each cell: n ∫∫_cell pdf J.
fn expected(
    pdf: &impl Fn(Vec3) -> f64,
    coords: &impl Coordinates,
    n: usize,
    res: usize,
    level: u32,
) -> Vec<f64> {
    let h = 1.0 / res as f64;
    let density = |s: f64, t: f64| {
        let (w, jac) = coords.direction_at([s, t]);
        let p = pdf(w) * jac;
        (if p.is_finite() { p } else { 0.0 }, w.z > 0.0)
    };
    let mut expected = vec![0.0f64; res * res];
    for i in 0..res {
        let (s0, s1) = (i as f64 * h, (i + 1) as f64 * h);
        for j in 0..res {
            let (t0, t1) = (j as f64 * h, (j + 1) as f64 * h);
            expected[i * res + j] =
                cell_integral(&density, [s0, s1], [t0, t1], 0, level) * n as f64;
        }
    }
    expected
}

/// ∫∫ density over the cell: the fixed tanh-sinh rule of `level` (33 × 33 nodes at level 2;
/// level 1, 17 × 17, integrated a BSDF's transmission lobe only to 1e-2), or, where the density may jump
/// inside the cell (its support ends there, or the horizon crosses it: zero at some of a
/// 5 × 5 grid of probes and not at others, or directions on both sides of the surface —
/// the horizon cutting a BSDF lobe, a reflection lobe meeting a transmission lobe, a bounded
/// VNDF's cap), the sum over its quarters, down to 1/16 of the cell per side. A jump inside
/// a cell costs the fixed rule ~1e-2 of the cell; confined to the few sixteenths it
/// crosses, ~1e-3 of the cell.
fn cell_integral(
    density: &impl Fn(f64, f64) -> (f64, bool),
    s: [f64; 2],
    t: [f64; 2],
    depth: u32,
    level: u32,
) -> f64 {
    if depth < 4 {
        let (mut zero, mut positive, mut above, mut below) = (false, false, false, false);
        for a in 0..5 {
            for b in 0..5 {
                let x = s[0] + (s[1] - s[0]) * (0.02 + 0.24 * a as f64);
                let y = t[0] + (t[1] - t[0]) * (0.02 + 0.24 * b as f64);
                let (p, up) = density(x, y);
                if p > 0.0 {
                    positive = true;
                } else {
                    zero = true;
                }
                if up {
                    above = true;
                } else {
                    below = true;
                }
            }
        }
        if (zero && positive) || (above && below) {
            let (sm, tm) = (0.5 * (s[0] + s[1]), 0.5 * (t[0] + t[1]));
            return [[s[0], sm], [sm, s[1]]]
                .iter()
                .flat_map(|&si| [[t[0], tm], [tm, t[1]]].map(move |ti| (si, ti)))
                .map(|(si, ti)| cell_integral(density, si, ti, depth + 1, level))
                .sum();
        }
    }
    crate::math::quad::integrate_fixed(
        |x| crate::math::quad::integrate_fixed(|y| density(x, y).0, t[0], t[1], level),
        s[0],
        s[1],
        level,
    )
}

/// The χ² statistic of the cells (with the outside cell, if any, expecting n − Σ expected),
/// pooling cells that expect fewer than 5 samples.
fn statistic(observed: &[f64], expected: &[f64], outside: Option<f64>, n: usize) -> Chi2 {
    let total: f64 = expected.iter().sum();
    let n = n as f64;
    let pdf_integral = total / n;
    // Pool cells expecting fewer than 5 samples (in increasing order of expectation).
    let mut cells: Vec<(f64, f64)> = expected
        .iter()
        .copied()
        .zip(observed.iter().copied())
        .collect();
    if let Some(o) = outside {
        cells.push(((n - total).max(0.0), o));
    }
    cells.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (mut pool_e, mut pool_o) = (0.0, 0.0);
    let mut statistic = 0.0;
    let mut dof = 0usize;
    for (e, o) in cells {
        if e < 5.0 {
            pool_e += e;
            pool_o += o;
            continue;
        }
        statistic += (o - e) * (o - e) / e;
        dof += 1;
    }
    if pool_e > 0.0 || pool_o > 0.0 {
        statistic += (pool_o - pool_e) * (pool_o - pool_e) / pool_e.max(1e-300);
        dof += 1;
    }
    let dof = dof.saturating_sub(1).max(1);
    let p_value = spec_math::cephes64::igamc(dof as f64 / 2.0, statistic / 2.0);
    Chi2 {
        statistic,
        dof,
        p_value,
        pdf_integral,
        bad_samples: 0,
    }
}

/// Šidák-corrected per-test significance for `tests` tests at overall level `alpha`.
pub fn sidak(alpha: f64, tests: usize) -> f64 {
    1.0 - (1.0 - alpha).powf(1.0 / tests as f64)
}
