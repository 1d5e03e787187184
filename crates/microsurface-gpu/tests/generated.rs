//! The committed translations (generated/) are what `examples/translate.rs` writes now: a
//! change of the WGSL library without regenerating them fails here.

#[path = "../tools/translate.rs"]
mod translate;

#[path = "../tools/beckmann_tables.rs"]
mod beckmann_tables;

#[path = "../tools/family_tables.rs"]
mod family_tables;

#[path = "../tools/tables.rs"]
mod tables;

/// wgsl/tables.wgsl and generated/microsurface_tables.bin are what the generator writes
/// from the Rust library now (and each table within its fit or rounding bound: the generator
/// panics otherwise).
#[test]
fn tables_are_current() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let (wgsl, bin) = tables::generate();
    let on_disk = std::fs::read_to_string(root.join("wgsl/tables.wgsl")).unwrap_or_default();
    assert!(
        on_disk == wgsl,
        "wgsl/tables.wgsl is stale: run `cargo run -p microsurface-gpu --example translate`"
    );
    assert!(
        microsurface_gpu::TABLES == bin.as_slice(),
        "generated/microsurface_tables.bin is stale: run `cargo run -p microsurface-gpu --example translate`"
    );
}

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

/// The README's WGSL snippet (the block after "## GPU") compiles with the library in front:
/// naga parses and validates it, as wgpu would.
#[test]
fn readme_wgsl_snippet_validates_with_the_library() {
    let readme = include_str!("../../../README.md");
    let section = readme
        .split("## GPU")
        .nth(1)
        .expect("the README has a GPU section");
    let snippet = section
        .split("```wgsl\n")
        .nth(1)
        .and_then(|s| s.split("```").next())
        .expect("the GPU section has a wgsl block");
    let source = format!("{}\n{snippet}", microsurface_gpu::WGSL);
    let module = naga::front::wgsl::parse_str(&source)
        .unwrap_or_else(|e| panic!("{}", e.emit_to_string(&source)));
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::empty(),
    )
    .validate(&module)
    .unwrap_or_else(|e| panic!("{}", e.emit_to_string(&source)));
}
