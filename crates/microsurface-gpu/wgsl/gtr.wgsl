// microsurface WGSL library: GTR, Burley's generalized Trowbridge–Reitz NDF (gtr.wgsl).
//
// The Rust `Microfacet<f32, Gtr>` (crates/microsurface/src/distribution/microfacet.rs over
// the fast path fast::gtr::FittedGtr; ndf/gtr.rs and sampling/dcos.rs for the formulas), in
// f32. Sources: Burley 2012, "Physically-Based Shading at Disney", appendix B (D, its
// normalisation, the D·cos inversion), and the GTR page of d'Eon's "A Hitchhiker's Guide to
// Multiple Scattering" (the Smith Λ and σ of GTR).
//
//   D(m) = c x^{−γ},  x = sin²θm + α² cos²θm = m.x² + m.y² + (α m.z)²  (0 for m.z ≤ 0)
//   c = (γ − 1)(α² − 1)/(π(1 − α^{2(1−γ)}))  (γ = 1: (α² − 1)/(π ln α²))
//   Λ(w) = ∫_a^∞ (q/a − 1) P2(q) dq, a = cot θ (Smith's, over GTR's slope marginal P2),
//          fitted per (α, γ) (the tables below),  G1 = 1/(1 + Λ),  G2 = 1/(1 + Λo + Λi) or
//          G1 G1
//   D_w(m) = G1(w)(w·m)D(m)/|w.z|
//
// GTR is isotropic at every γ but 2, where it is GGX (anisotropic allowed): there every
// function here calls GGX's with `alpha`, as the Rust type does. Otherwise a material is one
// (α, γ): its table holds α, and `alpha` is not read (pass vec2(α, α), which the door's
// ms_effectively_smooth reads). A material's table (written by the Rust
// `microsurface_gpu::Tables::add_gtr` from the Rust fast path's own FittedGtr) lies in the
// library's buffer `ms_tables` from the material's row `table`:
//   row 0: (γ, α, kind, σ(0)); kind 0: GGX (γ = 2; no further rows), 1: the Λ rows are the
//          Rust f32 cubics (one vec4 each), 2: the Rust f64 rows of Λ (degree 4) rounded to
//          f32 (two vec4 each), 3: the same of ln Λ (large γ: Λ spans decades per row)
//   row 1: (ln c, c, m₀, m₁): Λ ≈ m₀/a − ½ + m₁a below the u table (a = cot θ)
//   row 2: (K₀, K₁, off_u, off_w): Λ ≈ (K₀ + K₁/a²)/a² past the w table; per side the row
//          of t is (bits of t ≫ 18) − off
//   row 3: (2^k0 of the u table, 2^k0 of the w table, Λ rows, 0)
//   rows 4–6: Burley's quantile constants (L = ln α², k = 1 − γ, kL, 1 where e^{kL} passes
//          f32's range), (e^{kL}, e^{kL} − 1, e^{−kL}, e^{−kL} − 1) (saturated at f32's
//          largest), ((e^{kL} − 1)/kL, (e^{−kL} − 1)/(−kL), ln(e^{|kL|} − 1), 1 where e^{−kL}
//          passes f32's range)
//   row 7: (the D·cos envelope's first row, its pieces, the first moment's first row, its
//          pieces), relative to `table`
//   rows 8…: the Λ rows: 32 an octave of t, the u table (t = cos θ < ½) then the w table
//          (t = 1 − cos θ ≤ ½), each a polynomial in s ∈ [−1, 1) (s⁰ first)
//   then the visible sampler's two radial envelopes (below), two vec4 per piece.
//
// Λ: the side's table at t by the bits of t (the Rust lambda32, bit for bit where the Rust
// type has its f32 table), the two-term ends past the tables. D·cos: Burley's closed-form
// inversion for tan²θ, azimuth 2πu₁ (the Rust warp: the same normal for the same u, to f32's
// rounding). Visible normals: the Rust rejection sampler (FittedGtr::sample_visible) over the
// uniform stream of u: the same candidates, so mostly the same normal.

// Rows before a GTR table's Λ rows.
const MS_GTR_HEADER: u32 = 8u;
// f32's largest finite value.
const MS_F32_MAX: f32 = 3.4028235e38;

// Whether the material at `table` is GGX (γ = 2).
fn ms_gtr_is_ggx(table: u32) -> bool {
    return ms_tables[table].z < 0.5;
}

// ln(1 + t) for t > −1 without losing small t (ms_bk_ln_1m at −t): 2 atanh(t/(2 + t)) by
// its series on [−½, 1] (|t/(2 + t)| ≤ ⅓, truncation below 2e-9 relative), log(1 + t)
// outside (1 + t outside [0.5, 2], where the shading language's log is within 3 ulp; inside
// it has an absolute error of 2^−21, which would be all of a small result's digits).
fn ms_gtr_ln_1p(t: f32) -> f32 {
    if t <= 1.0 {
        return ms_bk_ln_1m(-t);
    }
    return log(1.0 + t);
}

// ln v for v > 0, relatively accurate everywhere: ms_gtr_ln_1p(v − 1) on [0.5, 2] (v − 1
// exact there), log(v) outside.
fn ms_gtr_ln(v: f32) -> f32 {
    if v >= 0.5 && v <= 2.0 {
        return ms_gtr_ln_1p(v - 1.0);
    }
    return log(v);
}

// ln(1 + x)/x (1 at x = 0).
fn ms_gtr_ln_1p_over_x(x: f32) -> f32 {
    if x == 0.0 {
        return 1.0;
    }
    return ms_gtr_ln_1p(x) / x;
}

// (e^x − 1)/x (1 at x = 0).
fn ms_gtr_expm1_over_x(x: f32) -> f32 {
    if x == 0.0 {
        return 1.0;
    }
    return ms_expm1(x) / x;
}

// D(wm) (the Rust FittedGtr::d_vec): c/x at γ = 1, else e^{ln c − γ ln x} (one exponential
// for the product, which stays finite where c or x^{−γ} alone would not); D(1) past
// wm.z = 1, 0 on and below the horizon, NaN for NaN.
fn ms_gtr_d(wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    let head = ms_tables[table];
    if head.z < 0.5 {
        return ms_ggx_d(wm, alpha);
    }
    let z = wm.z;
    if !(z > 0.0) {
        return select(0.0, z, z != z);
    }
    let a = head.y;
    var x = a * a;
    if z <= 1.0 {
        let az = a * z;
        x = wm.x * wm.x + wm.y * wm.y + az * az;
    }
    let norm = ms_tables[table + 1u];
    if head.x == 1.0 {
        return norm.y / x;
    }
    return exp(norm.x - head.x * log(x));
}

// Λ past the tables at a = cot θ (the Rust lambda_cot_ends, which the Rust f32 path reaches
// through its f64 lambda_cot): the grazing end m₀/a − ½ + m₁a for a < 1 (+∞ at a = 0), else
// (K₀ + K₁ r²) r² with r² = 1/a² (0 at a = +∞, the normal); NaN for NaN.
fn ms_gtr_lambda_cot_ends(table: u32, a: f32) -> f32 {
    if a != a {
        return a;
    }
    if a < 1.0 {
        let m = ms_tables[table + 1u];
        return m.z / a - 0.5 + m.w * a;
    }
    let k = ms_tables[table + 2u];
    let r2 = 1.0 / (a * a);
    return (k.x + k.y * r2) * r2;
}

// Smith Λ(w), Λ(−w) = Λ(w), for w of any length (the Rust FittedGtr::lambda_vec in f32):
// cos θ = u = |z|/n, n = √(s² + z²), s² = x² + y²; the u table below u = ½, the w table at
// t = 1 − u = s²/(n(n + |z|)) from there (formed from the vector: 1 − u of a rounded unit
// vector has lost its digits near the normal), by t's bits (row and position s), then the
// row's polynomial by Horner's rule (exp of it where the rows hold ln Λ); past the tables
// the ends at cot θ = |z|/s. +∞ on the horizon, 0 at the normal.
fn ms_gtr_lambda(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    if ms_gtr_is_ggx(table) {
        return ms_ggx_lambda(w, alpha);
    }
    let head = ms_tables[table];
    let lay = ms_tables[table + 2u];
    let lim = ms_tables[table + 3u];
    let z = abs(w.z);
    let s2 = w.x * w.x + w.y * w.y;
    let n = sqrt(s2 + z * z);
    let u = z / n;
    var t = u;
    var off = lay.z;
    var lo = lim.x;
    if u >= 0.5 {
        t = s2 / (n * (n + z));
        off = lay.w;
        lo = lim.y;
    }
    // (False for NaN.)
    if t >= lo {
        let bits = bitcast<u32>(t);
        let row = u32(clamp(i32(bits >> 18u) - i32(off), 0, i32(lim.z) - 1));
        let s = bitcast<f32>(0x40000000u | ((bits << 14u) >> 9u)) - 3.0;
        if head.z < 1.5 {
            return ms_fam_cubic(ms_tables[table + MS_GTR_HEADER + row], s);
        }
        let i = table + MS_GTR_HEADER + 2u * row;
        let c = ms_tables[i];
        let c4 = ms_tables[i + 1u].x;
        let p = (((c4 * s + c.w) * s + c.z) * s + c.y) * s + c.x;
        if head.z < 2.5 {
            return p;
        }
        return exp(p);
    }
    return ms_gtr_lambda_cot_ends(table, z / sqrt(s2));
}

// G1(w).
fn ms_gtr_g1(w: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return 1.0 / (1.0 + ms_gtr_lambda(w, alpha, table));
}

// Height-correlated G2(wo, wi).
fn ms_gtr_g2(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return 1.0 / (1.0 + (ms_gtr_lambda(wo, alpha, table) + ms_gtr_lambda(wi, alpha, table)));
}

// Separable G2(wo, wi) = G1(wo) G1(wi).
fn ms_gtr_g2_separable(wo: vec3<f32>, wi: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    return ms_gtr_g1(wo, alpha, table) * ms_gtr_g1(wi, alpha, table);
}

// The visible-normal density D_w(wm) = G1(w)(w·wm)D(wm)/|w.z|; w.z < 0 mirrored; 0 at grazing
// w and for wm facing away from w (GGX's closed form at γ = 2).
fn ms_gtr_pdf(w: vec3<f32>, wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    if ms_gtr_is_ggx(table) {
        return ms_ggx_pdf(w, wm, alpha);
    }
    let z = abs(w.z);
    var c = ms_dot(w, wm);
    if w.z < 0.0 {
        c = -c;
    }
    if !(c > 0.0 && z > 0.0) {
        return select(0.0, c, c != c);
    }
    return ms_gtr_g1(w, alpha, table) * c * ms_gtr_d(wm, alpha, table) / z;
}

// The density of ms_gtr_sample_dcos: D(wm) cos θm (0 for wm.z ≤ 0).
fn ms_gtr_pdf_dcos(wm: vec3<f32>, alpha: vec2<f32>, table: u32) -> f32 {
    if !(wm.z > 0.0) {
        return 0.0;
    }
    return ms_gtr_d(wm, alpha, table) * wm.z;
}

// ln(1 + f(e^{±kL} − 1)) (the Rust Burley::tan2's ln_pos_sum) for f ∈ [0, 1], given
// e^{±kL} − 1 (`minus_one`), the sum 1 + f(e^{±kL} − 1) as two positive terms (`sum`), and
// whether e^{±kL} passes f32's range (`over`: then from its logarithm, ln f + ln(e^{|kL|} −
// 1), for every f: ln(1 + eˢ) = s + ln(1 + e^{−s}), or ln(1 + eˢ) below s = 0).
fn ms_gtr_ln_pos_sum(f: f32, minus_one: f32, sum: f32, over: bool, ln_em1_abs: f32) -> f32 {
    if over {
        let s = ms_gtr_ln(f) + ln_em1_abs;
        if s > 0.0 {
            return s + ms_gtr_ln_1p(exp(-s));
        }
        return ms_gtr_ln_1p(exp(s));
    }
    let y = f * minus_one;
    if abs(y) < 0.5 {
        return ms_gtr_ln_1p(y);
    }
    return ms_gtr_ln(sum);
}

// tan²θ at the slope CDF's quantile ξ ∈ (0, 1) (the Rust Burley::tan2, Burley 2012 appendix
// B eqs. 3–9, for ℓ = ln w and k = 1 − γ: e^{kℓ} = (1 − ξ)e^{kL} + ξ, e^{k(ℓ − L)} = (1 − ξ) +
// ξe^{−kL}, tan²θ = e^ℓ expm1(L − ℓ)/expm1(ℓ)); near γ = 1 or α = 1 (|kL| < ½) with L divided
// out analytically.
fn ms_gtr_tan2(table: u32, xi: f32) -> f32 {
    let b0 = ms_tables[table + 4u];
    let b1 = ms_tables[table + 5u];
    let b2 = ms_tables[table + 6u];
    let l = b0.x;
    let k = b0.y;
    let kl = b0.z;
    let f = 1.0 - xi;
    if abs(kl) < 0.5 {
        let ell_over_l = f * b2.x * ms_gtr_ln_1p_over_x(f * b1.y);
        let rest_over_l = xi * b2.y * ms_gtr_ln_1p_over_x(xi * b1.w);
        let ell = ell_over_l * l;
        let rest = rest_over_l * l;
        return exp(ell) * (rest_over_l / ell_over_l) * ms_gtr_expm1_over_x(rest)
            / ms_gtr_expm1_over_x(ell);
    }
    let ell = ms_gtr_ln_pos_sum(f, b1.y, f * b1.x + xi, b0.w > 0.5, b2.z) / k;
    let rest = -ms_gtr_ln_pos_sum(xi, b1.w, f + xi * b1.z, b2.w > 0.5, b2.z) / k;
    return exp(ell) * ms_expm1(rest) / ms_expm1(ell);
}

// A normal distributed as D(m) cos θm with its pdf (the Rust FittedGtr::sample_dcos): tan θ
// = √tan²θ(u₀) (0 at u₀ ≤ 0, ∞ at u₀ ≥ 1), azimuth 2πu₁, m ∝ (r cos φ, r sin φ, 1), or
// divided by r past r = 1 (the Rust normal_from_polar). GGX's at γ = 2.
fn ms_gtr_sample_dcos(alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    if ms_gtr_is_ggx(table) {
        return ms_ggx_sample_dcos(alpha, u);
    }
    let xi = u.x;
    var r = xi;
    if xi <= 0.0 {
        r = 0.0;
    } else if xi >= 1.0 {
        r = ms_inf();
    } else if xi == xi {
        r = sqrt(ms_gtr_tan2(table, xi));
    }
    let cs = ms_cos_sin_turn(u.y);
    var v: vec3<f32>;
    if r > 1.0 {
        v = vec3<f32>(cs.x, cs.y, 1.0 / r);
    } else {
        v = vec3<f32>(r * cs.x, r * cs.y, 1.0);
    }
    let wm = ms_unit_normal(v);
    return MsSample(wm, ms_gtr_pdf_dcos(wm, alpha, table));
}

// The visible sampler's radial envelopes (the Rust vndf.rs `Radial`): an exact sampler of
// GTR's radial slope density in t = ln r², p(t) ∝ e^{φ(t)},
//   φ(t) = k t + (γ − 2) ln(1 + eᵗ) − γ ln(α² + eᵗ)
// (k = 1: D·cos slopes; k = 3/2: their first moment), by rejection from a piecewise
// envelope whose pieces an alias table picks. Each piece is two vec4:
//   finite piece: A = (r₀, dr, s₀, s₁), B = (h, the column's prob, its alias, 0): the
//     candidate r = r₀ + v dr is kept without φ when keep ≤ s₀ + s₁v (the squeeze), else
//     when keep ≤ e^{φ(t) − t/2 − h};
//   tail (the first and the last piece): A = (a, β, e, squeeze), B = (e^{βw} − 1 (−1), prob,
//     alias, 1): t = a + ln(1 + v(e^{βw} − 1))/β, kept below the squeeze, else when keep ≤
//     e^{φ(t) − e − β(t − a)}.
// (h and e hold the Rust envelope's maximum `top` added in: the density's scale.)

// φ(t) at x = eᵗ = r² of the envelope with power k.
fn ms_gtr_phi(k: f32, gamma: f32, a2: f32, t: f32, x: f32) -> f32 {
    return k * t + (gamma - 2.0) * ms_gtr_ln_1p(x) - gamma * log(a2 + x);
}

// The alias table's column of v ∈ [0, 1] among n: (⌊vn⌋ (at most n − 1), vn less it), the
// product formed exactly (v's 24-bit significand times n, a 64-bit integer) and the fraction
// rounded once, as the Rust f64 product is exact: an f32 product would round away up to
// log₂ n of the fraction's bits, the position within the piece.
fn ms_gtr_column(v: f32, n: u32) -> vec2<f32> {
    let b = bitcast<u32>(v);
    let e = (b >> 23u) & 0xffu;
    var i = 0u;
    var frac = v * f32(n);
    // v = significand · 2^−shift; shift ≥ 64 leaves vn below 2^−40 (i = 0, the product's
    // rounding relative); zero, subnormal and non-finite v as the f32 product.
    if e > 0u && e < 255u && 150u - e < 64u {
        let shift = 150u - e;
        let p = ms_u32_mul_wide((b & 0x7fffffu) | 0x800000u, n);
        // 2^−shift (a normal f32 for shift < 127; ldexp's exponent operand does not
        // translate to HLSL).
        let scale = bitcast<f32>((127u - shift) << 23u);
        if shift < 32u {
            i = (p.x >> shift) | (p.y << (32u - shift));
            frac = f32(p.x & ((1u << shift) - 1u)) * scale;
        } else {
            let s = shift - 32u;
            i = p.y >> s;
            let hi = p.y & ((1u << s) - 1u);
            frac = (f32(hi) * 4294967296.0 + f32(p.x)) * scale;
        }
    }
    if i > n - 1u {
        frac = frac + f32(i - (n - 1u));
        i = n - 1u;
    }
    return vec2<f32>(f32(i), frac);
}

// A radius from the envelope of power k (its pieces at row `at`, n of them) from v (the
// column of the alias table from its integer part, the piece and the position within it
// from the fraction), with 1 where `keep` (uniform in [0, 1)) lies below the density's ratio
// to the envelope, else 0 (the Rust Radial::radius and radius_slow: the position v₂ within
// the piece is the fraction's, r and the squeeze affine in it).
fn ms_gtr_radius(table: u32, at: u32, n: u32, k: f32, v: f32, keep: f32) -> vec2<f32> {
    let col = ms_gtr_column(v, n);
    let i = u32(col.x);
    let frac = col.y;
    let own = ms_tables[at + 2u * i + 1u];
    var j = i;
    var v2 = frac / own.y;
    if !(frac < own.y) {
        j = u32(own.z);
        v2 = (frac - own.y) / (1.0 - own.y);
    }
    v2 = min(v2, 1.0);
    let pa = ms_tables[at + 2u * j];
    let pb = ms_tables[at + 2u * j + 1u];
    let head = ms_tables[table];
    let a2 = head.y * head.y;
    if pb.w < 0.5 {
        let r = pa.x + v2 * pa.y;
        if keep <= pa.z + pa.w * v2 {
            return vec2<f32>(r, 1.0);
        }
        let x = r * r;
        let t = log(x);
        let ratio = exp(ms_gtr_phi(k, head.x, a2, t, x) - 0.5 * t - pb.x);
        return vec2<f32>(r, select(0.0, 1.0, keep <= ratio));
    }
    let t = pa.x + ms_gtr_ln_1p(v2 * pb.x) / pa.y;
    let r = exp(0.5 * t);
    if keep <= pa.w {
        return vec2<f32>(r, 1.0);
    }
    let ratio = exp(ms_gtr_phi(k, head.x, a2, t, r * r) - (pa.z + pa.y * (t - pa.x)));
    return vec2<f32>(r, select(0.0, 1.0, keep <= ratio));
}

// A visible normal for w (w.z < 0 mirrored) from u (the Rust FittedGtr::sample_visible): in
// w's slope frame (w = (s cos φ, s sin φ, c)) the visible slopes have the density (c + sx)⁺
// P22, drawn from the envelope c + s x⁺ in two parts: c P22 (mass c; D·cos slopes, the
// azimuth uniform, a candidate with x < 0 kept with probability (c + s x)/c) and s x⁺ P22
// (mass s σ(0): the first-moment radius, an azimuth with density ∝ cos⁺: sin ψ uniform). u
// drives the first candidate (u₀ the part and the azimuth, u₁ the radius), the stream of u
// the keep tests and the later candidates, in the Rust order. At most 64 candidates (each
// kept with probability above 0.49).
fn ms_gtr_sample_wm(w: vec3<f32>, u: vec2<f32>, table: u32) -> vec3<f32> {
    let head = ms_tables[table];
    let env = ms_tables[table + 7u];
    var sign = 1.0;
    if w.z < 0.0 {
        sign = -1.0;
    }
    let sx = sign * w.x;
    let sy = sign * w.y;
    let c = sign * w.z;
    let s = sqrt(sx * sx + sy * sy);
    if !(c + s <= MS_F32_MAX) {
        return vec3<f32>(bitcast<f32>(0x7fc00000u));
    }
    var cp = 1.0;
    var sp = 0.0;
    if s != 0.0 {
        cp = sx / s;
        sp = sy / s;
    }
    let e = c;
    let g = s * head.w;
    let total = e + g;
    // (Capped: at grazing w or normal incidence a mass is 0 and its reciprocal infinite;
    // the capped products stay in [0, 1) where they are used.)
    let inv_p = min(total / e, MS_F32_MAX);
    let inv_g = min(1.0 / g, MS_F32_MAX);
    var state = ms_stream_new(u);
    var v0 = u.x;
    var v1 = u.y;
    // The candidate's radius and its unit azimuth (dx, dy) in the slope frame.
    var dx = 1.0;
    var dy = 0.0;
    var radius = 0.0;
    for (var n = 0; n < 64; n++) {
        if n > 0 {
            v0 = ms_stream_next(&state);
            v1 = ms_stream_next(&state);
        }
        // d = v₀(e + g) − e, the part's boundary, as v₀g − (1 − v₀)e (1 − v₀ exact near 1):
        // its rounding then stays within ε of g, where v₀(e + g) − e would leave ε(e + g),
        // all of a small g's digits at normal incidence (the first moment's azimuth below
        // reads them).
        let d = v0 * g - (1.0 - v0) * e;
        let first = d < 0.0;
        let keep = ms_stream_next(&state);
        var rr: vec2<f32>;
        if first {
            rr = ms_gtr_radius(table, table + u32(env.x), u32(env.y), 1.0, v1, keep);
        } else {
            rr = ms_gtr_radius(table, table + u32(env.z), u32(env.w), 1.5, v1, keep);
        }
        if rr.y < 0.5 {
            continue;
        }
        let r = rr.x;
        radius = r;
        if first {
            let turn = v0 * inv_p;
            let cs = ms_cos_sin_turn(turn);
            dx = cs.x;
            dy = cs.y;
            // x ≥ 0 read from the turn itself; else the stream's next uniform decides.
            if abs(turn - 0.5) >= 0.25 {
                break;
            }
            if ms_stream_next(&state) * c <= c + s * (r * dx) {
                break;
            }
        } else {
            // sin ψ = 2d/g − 1, uniform; cos ψ = √((1 − sin ψ)(1 + sin ψ)) from 1 + sin ψ =
            // 2(v₀ − ω) and 1 − sin ψ = 2((1 − v₀) + ω), ω = (1 − v₀)e/g, and sin ψ from
            // whichever of them is the smaller, not from a rounded sin ψ: near ψ = ±90° that
            // would leave cos ψ about √ε of its digits in f32 (the Rust f64 arithmetic keeps
            // them).
            let omega = (1.0 - v0) * e * inv_g;
            let plus = 2.0 * (v0 - omega);
            let minus = 2.0 * ((1.0 - v0) + omega);
            dx = sqrt(max(minus * plus, 0.0));
            dy = select(1.0 - minus, plus - 1.0, plus < 1.0);
            break;
        }
    }
    // The slopes r(dx, dy) rotated back to w's azimuth: m ∝ (r p, r q, 1), or (p, q, 1/r)
    // past r = 1 (no overflow up to r = ∞), normalised.
    let p = cp * dx - sp * dy;
    let q = sp * dx + cp * dy;
    var v = vec3<f32>(radius * p, radius * q, 1.0);
    if radius > 1.0 {
        v = vec3<f32>(p, q, 1.0 / radius);
    }
    return ms_facing(ms_unit_normal(v), w);
}

// A visible normal for w (w.z < 0 mirrored) from u, with its pdf (at w normalised); GGX's
// spherical caps at γ = 2.
fn ms_gtr_sample(w: vec3<f32>, alpha: vec2<f32>, u: vec2<f32>, table: u32) -> MsSample {
    if ms_gtr_is_ggx(table) {
        return ms_ggx_sample(w, alpha, u);
    }
    let wm = ms_gtr_sample_wm(w, u, table);
    return MsSample(wm, ms_gtr_pdf(ms_unit(w), wm, alpha, table));
}
