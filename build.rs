//! Build script: gives the shared library a versioned SONAME (`libprofsubd.so.<major>`) on ELF
//! targets, so programs linked against it record the ABI major version, as C libraries do.
//! CMake installs `libprofsubd.so.<version>` with the `.so.<major>` and `.so` symlinks.

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
    }
}
