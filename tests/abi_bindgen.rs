//! The header and the shared library cannot disagree: bindgen translates
//! `include/profsubd.h` at test time, a caller program (`tests/abi/calls.rs`) written against
//! that translation is compiled, linked to the built `libprofsubd.so` with every declared
//! function referenced, and run (round trip, copy-out, NULL, bad handles, messages). The
//! library's exported `profsubd_` symbols must also be exactly the header's functions.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The cdylib built by this same `cargo test`: `target/<profile>/deps/` next to this test's
/// executable (cargo copies it up to `target/<profile>/` only on `cargo build`, so that copy
/// may be stale).
fn cdylib() -> PathBuf {
    let name = format!(
        "{}profsubd{}",
        std::env::consts::DLL_PREFIX,
        std::env::consts::DLL_SUFFIX
    );
    let exe = std::env::current_exe().unwrap();
    let deps = exe.parent().expect("test executable has a directory");
    let lib = deps.join(&name);
    assert!(
        lib.exists(),
        "{} is missing: cargo builds it with the library (crate-type cdylib)",
        lib.display()
    );
    lib
}

/// The SONAME recorded in the library (build.rs sets `libprofsubd.so.<major>`), if any.
fn soname(lib: &Path) -> Option<String> {
    let out = Command::new("objdump").arg("-p").arg(lib).output().ok()?;
    String::from_utf8_lossy(&out.stdout).lines().find_map(|l| {
        let mut f = l.split_whitespace();
        (f.next() == Some("SONAME")).then(|| f.next().map(str::to_owned))?
    })
}

/// A directory where the library is found under its file name and its SONAME, as an
/// installed library is (the program records the SONAME and looks for it at run time).
fn link_dir(lib: &Path, work: &Path) -> PathBuf {
    let dir = work.join("lib");
    std::fs::create_dir_all(&dir).unwrap();
    let names = [lib.file_name().unwrap().to_string_lossy().into_owned()]
        .into_iter()
        .chain(soname(lib));
    for name in names {
        let link = dir.join(name);
        let _ = std::fs::remove_file(&link);
        std::os::unix::fs::symlink(lib, &link).unwrap();
    }
    dir
}

/// bindgen's Rust translation of the header.
fn bindings() -> String {
    bindgen::Builder::default()
        .header(root().join("include/profsubd.h").to_string_lossy())
        .allowlist_function("profsubd_.*")
        .allowlist_type("profsubd_.*")
        .allowlist_var("PROFSUBD_.*")
        .prepend_enum_name(false)
        .layout_tests(true)
        .generate()
        .expect("bindgen must translate include/profsubd.h (needs libclang)")
        .to_string()
}

/// The function names declared in bindgen's output.
fn declared_functions(bindings: &str) -> BTreeSet<String> {
    bindings
        .split("pub fn ")
        .skip(1)
        .map(|rest| rest.split('(').next().unwrap().trim().to_owned())
        .collect()
}

/// The `profsubd_` functions the shared library exports.
fn exported_functions(lib: &Path) -> BTreeSet<String> {
    let out = Command::new("nm")
        .args(["-D", "--defined-only"])
        .arg(lib)
        .output()
        .expect("cannot run nm (binutils)");
    assert!(out.status.success(), "nm failed on {}", lib.display());
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| {
            let mut f = l.split_whitespace();
            let (kind, name) = (f.nth(1)?, f.next()?);
            (kind == "T" && name.starts_with("profsubd_")).then(|| name.to_owned())
        })
        .collect()
}

#[test]
fn header_and_library_agree() {
    let lib = cdylib();
    let bindings = bindings();
    let declared = declared_functions(&bindings);
    assert!(
        declared.len() >= 25,
        "too few functions found: {declared:?}"
    );
    let exported = exported_functions(&lib);
    let only_header: Vec<_> = declared.difference(&exported).collect();
    let only_library: Vec<_> = exported.difference(&declared).collect();
    assert!(
        only_header.is_empty() && only_library.is_empty(),
        "declared in the header but not exported: {only_header:?}; exported but not in the \
         header: {only_library:?} (regenerate: cbindgen --config cbindgen.toml --output \
         include/profsubd.h)"
    );

    let work = Path::new(env!("CARGO_TARGET_TMPDIR")).join("abi_bindgen");
    std::fs::create_dir_all(&work).unwrap();
    let bindings_rs = work.join("bindings.rs");
    std::fs::write(&bindings_rs, &bindings).unwrap();
    // Referencing every declared function makes the linker resolve each one.
    let symbols_rs = work.join("symbols.rs");
    let entries: String = declared
        .iter()
        .map(|f| format!("        (\"{f}\", {f} as usize),\n"))
        .collect();
    std::fs::write(
        &symbols_rs,
        format!("fn symbols() -> Vec<(&'static str, usize)> {{\n    vec![\n{entries}    ]\n}}\n"),
    )
    .unwrap();

    let program = work.join("calls");
    let lib_dir = link_dir(&lib, &work);
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let out = Command::new(rustc)
        .args(["--edition", "2021", "-o"])
        .arg(&program)
        .arg(root().join("tests/abi/calls.rs"))
        .arg("-L")
        .arg(format!("native={}", lib_dir.display()))
        .args(["-l", "dylib=profsubd"])
        .arg(format!("-Clink-arg=-Wl,-rpath,{}", lib_dir.display()))
        .arg("-Clink-arg=-Wl,-z,now")
        .env("PROFSUBD_BINDINGS", &bindings_rs)
        .env("PROFSUBD_SYMBOLS", &symbols_rs)
        .output()
        .expect("cannot run rustc");
    assert!(
        out.status.success(),
        "the caller program does not compile or link against the header and library:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );

    let desc_size = std::mem::size_of::<profsubd::ffi::profsubd_mesh_desc>();
    let report_size = std::mem::size_of::<profsubd::ffi::profsubd_mesh_report>();
    let run = Command::new(&program)
        .arg(desc_size.to_string())
        .arg(report_size.to_string())
        .arg(&work)
        .arg(root().join("examples/meshes/cube_creased.obj"))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "calls through the header failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(stdout.contains("checks passed"), "{stdout}");
    println!("{stdout}");
}
