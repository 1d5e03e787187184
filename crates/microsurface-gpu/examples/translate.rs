//! Writes the generated translations of the WGSL library (crates/microsurface-gpu/generated/):
//! `cargo run -p microsurface-gpu --example translate`, and the generated tables of the library
//! itself (tools/tables.rs: wgsl/tables.wgsl, the buffer's layout, and
//! generated/microsurface_tables.bin, its rows). CI validates them with
//! glslangValidator (GLSL) and spirv-val (SPIR-V); `tests/generated.rs` checks they are
//! current.

#[path = "../tools/translate.rs"]
mod translate;

#[path = "../tools/beckmann_tables.rs"]
mod beckmann_tables;

#[path = "../tools/family_tables.rs"]
mod family_tables;

#[path = "../tools/tables.rs"]
mod tables;

fn main() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    // The tables first: the library (and so the translations) includes them. A
    // change of them needs a second run for the translations (tests/generated.rs says so).
    let (wgsl, bin) = tables::generate();
    let stale = std::fs::read_to_string(root.join("wgsl/tables.wgsl"))
        .ok()
        .as_deref()
        != Some(wgsl.as_str());
    std::fs::write(root.join("wgsl/tables.wgsl"), &wgsl).expect("wgsl/tables.wgsl");
    std::fs::write(root.join("generated/microsurface_tables.bin"), &bin).expect("the tables");
    if stale {
        println!(
            "wgsl/tables.wgsl ({} bytes): run again for the translations",
            wgsl.len()
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
