// microsurface WGSL library: the rejection samplers' uniform stream and the Exp(1) ziggurat
// (stream.wgsl).
//
// The Rust samplers of Double GGX and the Exponential NDF draw uniforms beyond u from
// `UniformStream` (crates/microsurface/src/distribution/mod.rs): SplitMix64 (Steele, Lea &
// Flood 2014; math/rng.rs) seeded by the bits of u as f64, a ^ rotl(b, 29) ^ 0x243F6A8885A308D3,
// each f32 uniform the top 24 bits of an output over 2^24. WGSL has only 32-bit integers: a
// 64-bit word is vec2<u32>(low, high), and the add, the multiplications and the shifts are
// written out on the halves (the multiplications through 16-bit limbs), so the stream is the
// Rust one bit for bit (tests/family.rs). The state lives in the caller's function variable.

// a + b (mod 2^64).
fn ms_u64_add(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    let lo = a.x + b.x;
    return vec2<u32>(lo, a.y + b.y + select(0u, 1u, lo < a.x));
}

// The full 64-bit product of two u32, by 16-bit limbs (every partial sum fits in u32).
fn ms_u32_mul_wide(x: u32, y: u32) -> vec2<u32> {
    let x0 = x & 0xffffu;
    let x1 = x >> 16u;
    let y0 = y & 0xffffu;
    let y1 = y >> 16u;
    let p00 = x0 * y0;
    let p01 = x0 * y1;
    let p10 = x1 * y0;
    let p11 = x1 * y1;
    let mid = (p00 >> 16u) + (p01 & 0xffffu) + (p10 & 0xffffu);
    return vec2<u32>((mid << 16u) | (p00 & 0xffffu), p11 + (p01 >> 16u) + (p10 >> 16u) + (mid >> 16u));
}

// a · b (mod 2^64): the low halves' full product, the cross terms into the high half.
fn ms_u64_mul(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    let p = ms_u32_mul_wide(a.x, b.x);
    return vec2<u32>(p.x, p.y + a.x * b.y + a.y * b.x);
}

// a ^ (a >> k) for 0 < k < 32.
fn ms_u64_xorshift(a: vec2<u32>, k: u32) -> vec2<u32> {
    return a ^ vec2<u32>((a.x >> k) | (a.y << (32u - k)), a.y >> k);
}

// The bits of the f64 of an f32 (exact: subnormal f32 become normal f64; infinities and
// NaN keep their class).
fn ms_f64_bits(v: f32) -> vec2<u32> {
    let b = bitcast<u32>(v);
    let sign = b & 0x80000000u;
    let e = (b >> 23u) & 0xffu;
    var man = b & 0x7fffffu;
    var e64: u32;
    if e == 0u {
        if man == 0u {
            return vec2<u32>(0u, sign);
        }
        // man · 2^−149 with its leading bit at p: 2^{p−149}(1 + the bits below p).
        let p = firstLeadingBit(man);
        e64 = p + 874u;
        man = (man << (23u - p)) & 0x7fffffu;
    } else if e == 255u {
        e64 = 2047u;
    } else {
        e64 = e + 896u;
    }
    return vec2<u32>(man << 29u, sign | (e64 << 20u) | (man >> 3u));
}

// The stream of u: SplitMix64's state a ^ rotl(b, 29) ^ 0x243F6A8885A308D3, a and b the f64
// bits of u₀ and u₁ (the Rust UniformStream::new).
fn ms_stream_new(u: vec2<f32>) -> vec2<u32> {
    let a = ms_f64_bits(u.x);
    let b = ms_f64_bits(u.y);
    let rot = vec2<u32>((b.x << 29u) | (b.y >> 3u), (b.y << 29u) | (b.x >> 3u));
    return a ^ rot ^ vec2<u32>(0x85a308d3u, 0x243f6a88u);
}

// SplitMix64's next 64 bits (the Rust SplitMix64::next_u64).
fn ms_stream_next_u64(state: ptr<function, vec2<u32>>) -> vec2<u32> {
    *state = ms_u64_add(*state, vec2<u32>(0x7f4a7c15u, 0x9e3779b9u));
    var z = ms_u64_mul(ms_u64_xorshift(*state, 30u), vec2<u32>(0x1ce4e5b9u, 0xbf58476du));
    z = ms_u64_mul(ms_u64_xorshift(z, 27u), vec2<u32>(0x133111ebu, 0x94d049bbu));
    return ms_u64_xorshift(z, 31u);
}

// The next uniform in [0, 1): the top 24 bits over 2^24 (the Rust next_uniform::<f32>).
fn ms_stream_next(state: ptr<function, vec2<u32>>) -> f32 {
    let z = ms_stream_next_u64(state);
    return f32(z.y >> 8u) * (1.0 / 16777216.0);
}

// The next uniform of the stream as the Rust f64 draw (the top 53 bits over 2^53, the Rust
// next_uniform::<f64>()) rounded to f32, below 1.
fn ms_stream_next_wide(state: ptr<function, vec2<u32>>) -> f32 {
    let z = ms_stream_next_u64(state);
    let v = f32(z.y) * 2.3283064365386963e-10 + f32(z.x >> 11u) * 1.1102230246251565e-16;
    return min(v, 0.99999994);
}

// A source of uniforms for a rejection sampler: the Rust samplers' closures, on the GPU. `first`
// (u itself) is returned first where `used` < 2, then the stream of u, as f32 draws (the top 24
// bits: the Rust f32 paths' `next_uniform::<f32>`) or, where `wide` is 1, as the f64 draws the
// Rust mixtures' samplers take, rounded to f32 (ms_stream_next_wide).
struct MsSource {
    state: vec2<u32>,
    first: vec2<f32>,
    used: u32,
    wide: u32,
}

// The stream of u alone, f32 draws (Double GGX's and the Exponential NDF's samplers).
fn ms_source_stream(u: vec2<f32>) -> MsSource {
    return MsSource(ms_stream_new(u), u, 2u, 0u);
}

// The stream of u alone, its f64 draws rounded to f32 (the mixtures' D·cos sampler, whose
// warp takes u itself).
fn ms_source_stream_wide(u: vec2<f32>) -> MsSource {
    return MsSource(ms_stream_new(u), u, 2u, 1u);
}

// u's two uniforms, then the stream's f64 draws (the mixtures' posterior sampler).
fn ms_source_after_u(u: vec2<f32>) -> MsSource {
    return MsSource(ms_stream_new(u), u, 0u, 1u);
}

fn ms_source_next(src: ptr<function, MsSource>) -> f32 {
    if (*src).used < 2u {
        let v = select((*src).first.y, (*src).first.x, (*src).used == 0u);
        (*src).used = (*src).used + 1u;
        return v;
    }
    // (Through a local: naga's SPIR-V writer does not take a pointer to the member.)
    var state = (*src).state;
    var v: f32;
    if (*src).wide == 1u {
        v = ms_stream_next_wide(&state);
    } else {
        v = ms_stream_next(&state);
    }
    (*src).state = state;
    return v;
}

// A variate of a ziggurat's density from w ∈ [0, 1) (the Rust fast::ziggurat::sample over
// its generated layers, the rows at `at` of tables.wgsl, in f32): layer i = ⌊256w⌋, x =
// (256w − i)x_i, kept when below x_{i+1}; else the tail (layer 0) or the wedge's height test
// against f(x) (e^{−x}, or e^{−x²/2} where `normal`), with further uniforms from the
// source. The tail beyond r = x₁: r + Exp(1) for e^{−x}; Marsaglia's 1964 method for the
// normal (r + a, a ~ Exp(r), kept when 2b > a², b ~ Exp(1)).
fn ms_zig_sample(at: u32, normal: bool, w: f32, src: ptr<function, MsSource>) -> f32 {
    var y = w * 256.0;
    var k = u32(max(y, 0.0));
    var i = k & 255u;
    var layer = ms_tables[at + i];
    var x = (y - f32(k)) * layer.x;
    if x < layer.z {
        return x;
    }
    // Each pass keeps its candidate with probability ≥ 0.98; the cap (the Rust one) only
    // guarantees termination.
    for (var n = 0; n < 64; n++) {
        if x != x {
            return x;
        }
        if i == 0u {
            let r = layer.z;
            if !normal {
                return r - log(1.0 - ms_source_next(src));
            }
            for (var j = 0; j < 64; j++) {
                let a = -log(1.0 - ms_source_next(src)) / r;
                let b = -log(1.0 - ms_source_next(src));
                if 2.0 * b > a * a {
                    return r + a;
                }
            }
            return r;
        }
        let h = layer.y + ms_source_next(src) * (layer.w - layer.y);
        var f = exp(-x);
        if normal {
            f = exp(-0.5 * x * x);
        }
        if h < f {
            return x;
        }
        y = ms_source_next(src) * 256.0;
        k = u32(y);
        i = k & 255u;
        layer = ms_tables[at + i];
        x = (y - f32(k)) * layer.x;
        if x < layer.z {
            return x;
        }
    }
    return x;
}

// An Exp(1) variate from w ∈ [0, 1) (the Rust fast::ziggurat::exp1; Marsaglia & Tsang 2000).
fn ms_zig_exp1(w: f32, src: ptr<function, MsSource>) -> f32 {
    return ms_zig_sample(MS_ZIG_EXP_AT, false, w, src);
}

// A half-normal variate |Z| from w ∈ [0, 1) (the Rust fast::ziggurat::half_normal).
fn ms_zig_half_normal(w: f32, src: ptr<function, MsSource>) -> f32 {
    return ms_zig_sample(MS_ZIG_NORMAL_AT, true, w, src);
}
