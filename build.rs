//! Build script: gives the shared library a versioned SONAME (`libprofsubd.so.<major>`) on ELF
//! targets, so programs linked against it record the ABI major version, as C libraries do.
//! CMake installs `libprofsubd.so.<version>` with the `.so.<major>` and `.so` symlinks.
//!
//! So that the build tree is usable as is (a program linked with `-Ltarget/release
//! -lprofsubd` records `libprofsubd.so.<major>` and must find it there), the script also
//! makes the symlink `libprofsubd.so.<major> -> libprofsubd.so` in the profile's output
//! folder (`target/<profile>`, the third parent of `OUT_DIR`); it dangles until the linker
//! writes the library.

use std::env;

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let os = env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let elf = matches!(
        os.as_str(),
        "linux" | "android" | "freebsd" | "netbsd" | "openbsd" | "dragonfly" | "illumos"
    );
    if elf {
        let major = env::var("CARGO_PKG_VERSION_MAJOR").unwrap_or_else(|_| "0".to_string());
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libprofsubd.so.{major}");
        link_soname(&format!("libprofsubd.so.{major}"));
    }
}

/// `target/<profile>/<soname> -> libprofsubd.so`, replacing an older link; a failure is only
/// a warning (the CMake build makes the same link).
#[cfg(unix)]
fn link_soname(soname: &str) {
    let Some(out_dir) = env::var_os("OUT_DIR") else {
        return;
    };
    let Some(profile_dir) = std::path::Path::new(&out_dir).ancestors().nth(3) else {
        return;
    };
    let link = profile_dir.join(soname);
    let _ = std::fs::remove_file(&link);
    if let Err(e) = std::os::unix::fs::symlink("libprofsubd.so", &link) {
        println!("cargo:warning=could not create {}: {e}", link.display());
    }
}

#[cfg(not(unix))]
fn link_soname(_soname: &str) {}
