//! Compiles the textbook C baseline with -O3 -march=native (bench-only crate).
fn main() {
    println!("cargo:rerun-if-changed=c/baseline.c");
    cc::Build::new()
        .file("c/baseline.c")
        .opt_level(3)
        .flag_if_supported("-march=native")
        .flag_if_supported("-fno-math-errno")
        .compile("microfacet_baseline");
}
