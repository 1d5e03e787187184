//! The committed translations (generated/) are what `examples/translate.rs` writes now: a
//! change of the WGSL library without regenerating them fails here.

#[path = "../tools/translate.rs"]
mod translate;

#[test]
fn generated_files_are_current() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let files = translate::translate().expect("the library translates");
    let mut names: Vec<String> = files.iter().map(|(p, _)| p.clone()).collect();
    for (path, bytes) in &files {
        let on_disk = std::fs::read(root.join(path)).unwrap_or_default();
        assert!(
            &on_disk == bytes,
            "{path} is stale: run `cargo run -p microsurface-gpu --example translate`"
        );
    }
    // No stale GLSL file of an entry point that is gone.
    let mut glsl: Vec<String> = std::fs::read_dir(root.join("generated/glsl"))
        .expect("generated/glsl")
        .map(|e| {
            format!(
                "generated/glsl/{}",
                e.expect("an entry").file_name().to_string_lossy()
            )
        })
        .collect();
    glsl.sort();
    names.retain(|n| n.starts_with("generated/glsl/"));
    names.sort();
    assert_eq!(
        glsl, names,
        "generated/glsl holds other files than the entry points'"
    );
}
