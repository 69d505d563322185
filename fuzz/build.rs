//! The fuzz targets call the library through bindgen's translation of the committed C header,
//! so they exercise exactly the C ABI and do not depend on the crate's module layout.
fn main() {
    let header = "../include/profsubd.h";
    println!("cargo:rerun-if-changed={header}");
    let out = std::path::PathBuf::from(std::env::var("OUT_DIR").unwrap()).join("profsubd.rs");
    bindgen::Builder::default()
        .header(header)
        .allowlist_function("profsubd_.*")
        .allowlist_type("profsubd_.*")
        .allowlist_var("PROFSUBD_.*")
        .prepend_enum_name(false)
        .generate()
        .expect("bindgen must translate include/profsubd.h (needs libclang)")
        .write_to_file(out)
        .unwrap();
}
