//! Writes the generated translations of the WGSL library (crates/microsurface-gpu/generated/):
//! `cargo run -p microsurface-gpu --example translate`. CI validates them with
//! glslangValidator (GLSL) and spirv-val (SPIR-V); `tests/generated.rs` checks they are
//! current.

#[path = "../tools/translate.rs"]
mod translate;

fn main() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let files = translate::translate().unwrap_or_else(|e| panic!("translation failed: {e}"));
    let _ = std::fs::remove_dir_all(root.join("generated/glsl"));
    for (path, bytes) in files {
        let p = root.join(&path);
        std::fs::create_dir_all(p.parent().expect("a parent")).expect("the folder");
        std::fs::write(&p, &bytes).expect("the file");
        println!("{path} ({} bytes)", bytes.len());
    }
}
