//! The textbook C baseline (c/baseline.c), exposed as safe functions for the benchmarks, and
//! [`pin_to_cpu`] for the benchmark's pinned thread pool. This crate is not part of the
//! library: it exists so that `cargo bench -p microsurface-bench` measures our functions and a
//! hand-written C equivalent side by side in one process.

#![allow(unsafe_code)] // FFI to the C baseline and to the OS's affinity call, confined to this file.

mod ffi {
    extern "C" {
        pub fn c_ggx_d(u: f64, alpha: f64) -> f64;
        pub fn c_ggx_lambda(u: f64, alpha: f64) -> f64;
        pub fn c_beckmann_d(u: f64, alpha: f64) -> f64;
        pub fn c_beckmann_lambda(u: f64, alpha: f64) -> f64;
        pub fn c_ggx_d_f(u: f32, alpha: f32) -> f32;
        pub fn c_ggx_lambda_f(u: f32, alpha: f32) -> f32;
        pub fn c_beckmann_d_f(u: f32, alpha: f32) -> f32;
        pub fn c_beckmann_lambda_f(u: f32, alpha: f32) -> f32;
        pub fn c_beckmann_vndf(
            vx: f64,
            vy: f64,
            vz: f64,
            ax: f64,
            ay: f64,
            u1: f64,
            u2: f64,
            out: *mut f64,
        );
        pub fn c_ggx_vndf(
            vx: f64,
            vy: f64,
            vz: f64,
            ax: f64,
            ay: f64,
            u1: f64,
            u2: f64,
            out: *mut f64,
        );
    }
}

/// GGX D (C baseline).
pub fn ggx_d(u: f64, alpha: f64) -> f64 {
    // SAFETY: a pure C function of two doubles.
    unsafe { ffi::c_ggx_d(u, alpha) }
}

/// GGX Λ (C baseline).
pub fn ggx_lambda(u: f64, alpha: f64) -> f64 {
    // SAFETY: a pure C function of two doubles.
    unsafe { ffi::c_ggx_lambda(u, alpha) }
}

/// Beckmann D (C baseline).
pub fn beckmann_d(u: f64, alpha: f64) -> f64 {
    // SAFETY: a pure C function of two doubles.
    unsafe { ffi::c_beckmann_d(u, alpha) }
}

/// Beckmann Λ (C baseline, the cancelling textbook form).
pub fn beckmann_lambda(u: f64, alpha: f64) -> f64 {
    // SAFETY: a pure C function of two doubles.
    unsafe { ffi::c_beckmann_lambda(u, alpha) }
}

/// Beckmann visible normal, pbrt-v3's inversion (C baseline).
pub fn beckmann_vndf(v: [f64; 3], ax: f64, ay: f64, u: [f64; 2]) -> [f64; 3] {
    let mut out = [0.0; 3];
    // SAFETY: `out` is a valid array of three doubles that the C function writes.
    unsafe { ffi::c_beckmann_vndf(v[0], v[1], v[2], ax, ay, u[0], u[1], out.as_mut_ptr()) };
    out
}

/// GGX visible normal, Heitz 2018 (C baseline).
pub fn ggx_vndf(v: [f64; 3], ax: f64, ay: f64, u: [f64; 2]) -> [f64; 3] {
    let mut out = [0.0; 3];
    // SAFETY: `out` is a valid array of three doubles that the C function writes.
    unsafe { ffi::c_ggx_vndf(v[0], v[1], v[2], ax, ay, u[0], u[1], out.as_mut_ptr()) };
    out
}

/// GGX D in f32 (C baseline).
pub fn ggx_d_f32(u: f32, alpha: f32) -> f32 {
    // SAFETY: a pure C function of two floats.
    unsafe { ffi::c_ggx_d_f(u, alpha) }
}

/// GGX Λ in f32 (C baseline).
pub fn ggx_lambda_f32(u: f32, alpha: f32) -> f32 {
    // SAFETY: a pure C function of two floats.
    unsafe { ffi::c_ggx_lambda_f(u, alpha) }
}

/// Beckmann D in f32 (C baseline).
pub fn beckmann_d_f32(u: f32, alpha: f32) -> f32 {
    // SAFETY: a pure C function of two floats.
    unsafe { ffi::c_beckmann_d_f(u, alpha) }
}

/// Beckmann Λ in f32 (C baseline).
pub fn beckmann_lambda_f32(u: f32, alpha: f32) -> f32 {
    // SAFETY: a pure C function of two floats.
    unsafe { ffi::c_beckmann_lambda_f(u, alpha) }
}

/// Restricts the calling thread to CPU `cpu` (Linux: `sched_setaffinity`); false where that
/// failed or the OS has no such call. For the benchmark's pool of rayon workers pinned one to
/// a CPU: this machine's kernel packs runnable threads onto fewer vCPUs
/// (`sched_vcpu_pack` on its command line), which put both workers of the default pool on one
/// vCPU in about half of the passes (BENCHMARKS.md).
pub fn pin_to_cpu(cpu: usize) -> bool {
    #[cfg(target_os = "linux")]
    {
        if cpu >= libc::CPU_SETSIZE as usize {
            return false;
        }
        // SAFETY: cpu_set_t is plain data (all zeros is the empty set), CPU_SET writes a bit
        // below CPU_SETSIZE (checked above), and sched_setaffinity(0, …) reads the set for the
        // calling thread.
        unsafe {
            let mut set: libc::cpu_set_t = std::mem::zeroed();
            libc::CPU_SET(cpu, &mut set);
            libc::sched_setaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &set) == 0
        }
    }
    #[cfg(not(target_os = "linux"))]
    {
        let _ = cpu;
        false
    }
}
