//! Writes the generated translations of the WGSL library (crates/microsurface-gpu/generated/):
//! `cargo run -p microsurface-gpu --example translate`, and the generated tables of the library
//! itself (wgsl/beckmann_tables.wgsl, from the Rust f64 functions; wgsl/family_tables.wgsl,
//! from the Rust tables of Double GGX and the Exponential NDF). CI validates them with
//! glslangValidator (GLSL) and spirv-val (SPIR-V); `tests/generated.rs` checks they are
//! current.

#[path = "../tools/translate.rs"]
mod translate;

#[path = "../tools/beckmann_tables.rs"]
mod beckmann_tables;

#[path = "../tools/family_tables.rs"]
mod family_tables;

fn main() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    // The tables first: the library (and so the translations) includes them. A
    // change of them needs a second run for the translations (tests/generated.rs says so).
    for (name, tables) in [
        ("wgsl/beckmann_tables.wgsl", beckmann_tables::wgsl()),
        ("wgsl/family_tables.wgsl", family_tables::wgsl()),
    ] {
        let path = root.join(name);
        if std::fs::read_to_string(&path).ok().as_deref() != Some(tables.as_str()) {
            std::fs::write(&path, &tables).expect(name);
            println!(
                "{name} ({} bytes): run again for the translations",
                tables.len()
            );
        }
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
