//! Library version, from the crate version in Cargo.toml.

use std::ffi::c_char;

use crate::ffi::panic::guard;

const VERSION: &std::ffi::CStr = match std::ffi::CStr::from_bytes_with_nul(
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_bytes(),
) {
    Ok(v) => v,
    Err(_) => panic!("crate version contains a NUL byte"),
};

/// Decimal digits of a Cargo version component.
const fn parse(s: &str) -> u32 {
    let b = s.as_bytes();
    let mut i = 0;
    let mut v = 0u32;
    while i < b.len() {
        v = v * 10 + (b[i] - b'0') as u32;
        i += 1;
    }
    v
}

/// The library's version as "MAJOR.MINOR.PATCH" (static; never free it). Compare
/// `profsubd_version_major()` with the `PROFSUBD_VERSION_MAJOR` macro to check that the
/// header and the loaded library agree.
#[no_mangle]
pub extern "C" fn profsubd_version_string() -> *const c_char {
    guard(|| VERSION.as_ptr())
}

/// The library's major version.
#[no_mangle]
pub extern "C" fn profsubd_version_major() -> u32 {
    guard(|| parse(env!("CARGO_PKG_VERSION_MAJOR")))
}

/// The library's minor version.
#[no_mangle]
pub extern "C" fn profsubd_version_minor() -> u32 {
    guard(|| parse(env!("CARGO_PKG_VERSION_MINOR")))
}

/// The library's patch version.
#[no_mangle]
pub extern "C" fn profsubd_version_patch() -> u32 {
    guard(|| parse(env!("CARGO_PKG_VERSION_PATCH")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn functions_report_the_crate_version() {
        let s = unsafe { std::ffi::CStr::from_ptr(profsubd_version_string()) };
        let expected = format!(
            "{}.{}.{}",
            profsubd_version_major(),
            profsubd_version_minor(),
            profsubd_version_patch()
        );
        assert_eq!(s.to_str().unwrap(), expected);
        assert_eq!(expected, env!("CARGO_PKG_VERSION"));
        assert_eq!(parse("120"), 120);
    }
}
