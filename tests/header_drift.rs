//! The committed `include/profsubd.h` must be exactly what cbindgen generates from the
//! sources and `cbindgen.toml`, and must declare nothing outside the `profsubd_` namespace.

use std::path::Path;

const REGENERATE: &str = "cbindgen --config cbindgen.toml --output include/profsubd.h";

fn generate(root: &Path) -> String {
    let config =
        cbindgen::Config::from_file(root.join("cbindgen.toml")).expect("cbindgen.toml must parse");
    let bindings = cbindgen::Builder::new()
        .with_crate(root)
        .with_config(config)
        .generate()
        .expect("cbindgen must generate the header");
    let mut out = Vec::new();
    bindings.write(&mut out);
    String::from_utf8(out).expect("header is UTF-8")
}

#[test]
fn committed_header_matches_cbindgen_output() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let generated = generate(root);
    let committed = std::fs::read_to_string(root.join("include/profsubd.h"))
        .unwrap_or_else(|e| panic!("include/profsubd.h: {e}; create it with `{REGENERATE}`"));
    if generated == committed {
        return;
    }
    let (g, c): (Vec<&str>, Vec<&str>) = (generated.lines().collect(), committed.lines().collect());
    let first = g
        .iter()
        .zip(&c)
        .position(|(a, b)| a != b)
        .unwrap_or(g.len().min(c.len()));
    let show = |lines: &[&str]| {
        lines
            .iter()
            .skip(first)
            .take(6)
            .copied()
            .collect::<Vec<_>>()
            .join("\n")
    };
    panic!(
        "include/profsubd.h is out of date (first difference at line {}; generated {} lines, \
         committed {}).\n--- generated:\n{}\n--- committed:\n{}\nRegenerate it from the \
         repository root with:\n    {REGENERATE}\nand commit the result.",
        first + 1,
        g.len(),
        c.len(),
        show(&g),
        show(&c),
    );
}

/// Every macro, type and function the header declares starts with `PROFSUBD_`/`profsubd_`:
/// a public constant elsewhere in the crate must not leak into the C namespace.
#[test]
fn header_declares_only_prefixed_names() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let header = generate(root);
    let mut names = Vec::new();
    for line in header.lines() {
        if let Some(rest) = line.strip_prefix("#define ") {
            names.push(rest.split_whitespace().next().unwrap_or(""));
        } else if let Some(pointer) = line
            .strip_prefix("typedef ")
            .and_then(|rest| rest.split_once("(*"))
        {
            // A function pointer type: `typedef R (*name)(args);`.
            names.push(pointer.1.split(')').next().unwrap_or(""));
        } else if let Some(rest) = line.strip_prefix("typedef ") {
            names.push(
                rest.trim_end_matches(['{', ' '])
                    .rsplit(' ')
                    .next()
                    .unwrap_or(""),
            );
        } else if let Some(end) = line.find('(') {
            if line.starts_with(|c: char| c.is_ascii_alphabetic()) {
                names.push(line[..end].rsplit([' ', '*']).next().unwrap_or(""));
            }
        } else if line.starts_with("} ") && line.ends_with(';') {
            names.push(line.trim_start_matches("} ").trim_end_matches(';'));
        }
    }
    assert!(names.len() > 20, "too few declarations found: {names:?}");
    let stray: Vec<_> = names
        .iter()
        .filter(|n| !n.starts_with("profsubd_") && !n.starts_with("PROFSUBD_"))
        .collect();
    assert!(
        stray.is_empty(),
        "names outside the profsubd namespace in the header: {stray:?}; add them to \
         [export] exclude in cbindgen.toml (or make them non-public) and regenerate"
    );
}

/// The version macros written in cbindgen.toml follow Cargo.toml's version.
#[test]
fn version_macros_match_the_crate_version() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let header = generate(root);
    for (part, value) in [
        ("MAJOR", env!("CARGO_PKG_VERSION_MAJOR")),
        ("MINOR", env!("CARGO_PKG_VERSION_MINOR")),
        ("PATCH", env!("CARGO_PKG_VERSION_PATCH")),
    ] {
        let line = format!("#define PROFSUBD_VERSION_{part} {value}");
        assert!(
            header.lines().any(|l| l == line),
            "the header lacks `{line}`: update after_includes in cbindgen.toml to the version \
             in Cargo.toml, then run {REGENERATE}"
        );
    }
}
