//! The library's layers (issue 46): the folder-level import graph of `src/`, read from its
//! `crate::X` paths (comments and strings left out, a file's trailing `#[cfg(test)] mod
//! tests` too), against the intended order, lowest first:
//!
//! math, error → ndf → sampling → fast → distribution → bsdf → check → scattering → prelude
//!
//! An edge that runs upward is a defect of the layering. Those that exist today are listed in
//! [`KNOWN_UPWARD`], the debt issue 46 pays off (they make one cycle of five folders: bsdf, distribution, fast, ndf, sampling); the test
//! fails for any other upward edge (a new one), and for a listed edge that is gone (remove
//! it from the list, so that it cannot come back). The same reading as
//! `../shared/tools/layers.py`, which prints the graph.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The intended order, lowest first (a folder uses only folders before it).
const ORDER: &[&str] = &[
    "math",
    "error",
    "ndf",
    "sampling",
    "fast",
    "distribution",
    "bsdf",
    "check",
    "scattering",
    "prelude",
];

/// The upward edges of today, (from, to): the six-folder cycle's.
const KNOWN_UPWARD: &[(&str, &str)] = &[
    ("fast", "bsdf"),
    ("fast", "distribution"),
    ("ndf", "fast"),
    ("sampling", "distribution"),
];

/// The source without comments and string literals.
fn strip(src: &str) -> String {
    let b = src.as_bytes();
    let mut out = String::with_capacity(src.len());
    let mut i = 0;
    while i < b.len() {
        if b[i..].starts_with(b"//") {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if b[i..].starts_with(b"/*") {
            let mut depth = 0;
            while i < b.len() {
                if b[i..].starts_with(b"/*") {
                    depth += 1;
                    i += 2;
                } else if b[i..].starts_with(b"*/") {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
        } else if b[i] == b'"' {
            i += 1;
            while i < b.len() && b[i] != b'"' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            i += 1;
            out.push_str("\"\"");
        } else if b[i] == b'\'' && i + 2 < b.len() && (b[i + 2] == b'\'' || b[i + 1] == b'\\') {
            // A char literal ('"' would open a string): skipped to its closing quote.
            i += 1;
            while i < b.len() && b[i] != b'\'' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            i += 1;
        } else {
            let c = src[i..].chars().next().unwrap_or(' ');
            out.push(c);
            i += c.len_utf8();
        }
    }
    out
}

/// The top-level modules a (stripped) source names through `crate::X` or `crate::{X, …}`.
fn refs(src: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let ident = |s: &str| -> String {
        s.chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
            .collect()
    };
    let mut rest = src;
    while let Some(k) = rest.find("crate::") {
        // (Not the tail of another identifier: `$crate::`, `my_crate::`.)
        let before = rest[..k].chars().next_back();
        let after = rest[k + 7..].trim_start();
        if !before.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_' || c == '$') {
            if let Some(group) = after.strip_prefix('{') {
                let end = group.find('}').unwrap_or(group.len());
                // Top-level names of the group: those at brace depth 0.
                let mut depth = 0;
                let mut start = true;
                for (j, c) in group[..end].char_indices() {
                    match c {
                        '{' => depth += 1,
                        '}' => depth -= 1,
                        ',' if depth == 0 => start = true,
                        c if start && depth == 0 && !c.is_whitespace() => {
                            out.insert(ident(&group[j..]));
                            start = false;
                        }
                        _ => {}
                    }
                }
            } else {
                out.insert(ident(after));
            }
        }
        rest = &rest[k + 7..];
    }
    out.retain(|s| s.chars().next().is_some_and(|c| c.is_ascii_lowercase()));
    out
}

/// The edges (from, to) between top-level modules, with a file of each.
fn graph(src: &Path) -> BTreeMap<(String, String), String> {
    fn walk(dir: &Path, files: &mut Vec<std::path::PathBuf>) {
        for e in std::fs::read_dir(dir).expect("src is readable").flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, files);
            } else if p.extension().is_some_and(|x| x == "rs") {
                files.push(p);
            }
        }
    }
    let mut files = Vec::new();
    walk(src, &mut files);
    let top = |p: &Path| -> Option<String> {
        let rel = p.strip_prefix(src).ok()?;
        let mut parts = rel.components();
        let first = parts.next()?.as_os_str().to_string_lossy().into_owned();
        if parts.next().is_none() {
            let name = first.trim_end_matches(".rs").to_string();
            return (name != "lib" && name != "main").then_some(name);
        }
        Some(first)
    };
    let tops: BTreeSet<String> = files.iter().filter_map(|p| top(p)).collect();
    let mut edges = BTreeMap::new();
    for p in &files {
        let Some(t) = top(p) else { continue };
        let text = std::fs::read_to_string(p).expect("a source file is readable");
        let s = strip(&text);
        // A file's trailing test module is tests, not layering.
        let s = match s.find("#[cfg(test)]\nmod tests") {
            Some(k) => &s[..k],
            None => &s[..],
        };
        for r in refs(s) {
            if r != t && tops.contains(&r) {
                let rel = p.strip_prefix(src).unwrap_or(p).display().to_string();
                edges.entry((t.clone(), r)).or_insert(rel);
            }
        }
    }
    edges
}

#[test]
fn layers_run_one_way_but_for_the_known_debt() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let edges = graph(&src);
    let rank = |m: &str| ORDER.iter().position(|&o| o == m);
    let mut upward = BTreeSet::new();
    for ((from, to), file) in &edges {
        let (Some(a), Some(b)) = (rank(from), rank(to)) else {
            panic!("{from} or {to} is not in ORDER: place the new folder in the layer map");
        };
        // (math and error are one layer: both below everything else.)
        if a < b && !(a <= 1 && b <= 1) {
            upward.insert((from.clone(), to.clone(), file.clone()));
        }
    }
    let known: BTreeSet<(String, String)> = KNOWN_UPWARD
        .iter()
        .map(|&(a, b)| (a.to_string(), b.to_string()))
        .collect();
    let new: Vec<_> = upward
        .iter()
        .filter(|(a, b, _)| !known.contains(&(a.clone(), b.clone())))
        .collect();
    assert!(
        new.is_empty(),
        "upward imports (against the layer order {ORDER:?}): {new:?}"
    );
    let found: BTreeSet<(String, String)> = upward
        .iter()
        .map(|(a, b, _)| (a.clone(), b.clone()))
        .collect();
    let gone: Vec<_> = known.difference(&found).collect();
    assert!(
        gone.is_empty(),
        "known upward edges no longer present: remove them from KNOWN_UPWARD: {gone:?}"
    );
    assert!(
        edges.len() > 20,
        "the graph was read: {} edges",
        edges.len()
    );
}

#[test]
fn the_reader_sees_through_comments_strings_and_groups() {
    let s = strip(
        "use crate::{bsdf::Frame, fast::{Real, arith}};\n// crate::ndf\nlet x = \"crate::check\";\n/* crate::sampling */ let c = '\"'; crate::math::quad::GL8;",
    );
    let r = refs(&s);
    let want: BTreeSet<String> = ["bsdf", "fast", "math"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    assert_eq!(r, want);
}
