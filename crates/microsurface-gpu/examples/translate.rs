//! Writes the generated translations of the WGSL library (crates/microsurface-gpu/generated/):
//! `cargo run -p microsurface-gpu --example translate`, and the Beckmann tables of the library
//! itself (wgsl/beckmann_tables.wgsl, from the Rust f64 functions). CI validates them with
//! glslangValidator (GLSL) and spirv-val (SPIR-V); `tests/generated.rs` checks they are
//! current.

#[path = "../tools/translate.rs"]
mod translate;

#[path = "../tools/beckmann_tables.rs"]
mod beckmann_tables;

fn main() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    // The Beckmann tables first: the library (and so the translations) includes them. A
    // change of them needs a second run for the translations (tests/generated.rs says so).
    let tables = beckmann_tables::wgsl();
    let path = root.join("wgsl/beckmann_tables.wgsl");
    if std::fs::read_to_string(&path).ok().as_deref() != Some(tables.as_str()) {
        std::fs::write(&path, &tables).expect("wgsl/beckmann_tables.wgsl");
        println!(
            "wgsl/beckmann_tables.wgsl ({} bytes): run again for the translations",
            tables.len()
        );
    }
    let files = translate::translate().unwrap_or_else(|e| panic!("translation failed: {e}"));
    let _ = std::fs::remove_dir_all(root.join("generated/glsl"));
    for (path, bytes) in files {
        let p = root.join(&path);
        std::fs::create_dir_all(p.parent().expect("a parent")).expect("the folder");
        std::fs::write(&p, &bytes).expect("the file");
        println!("{path} ({} bytes)", bytes.len());
    }
}
