//! The message getters of the C API: the last error of the calling thread and the fixed
//! description of a status (apart from `error` and `status`, which the panic guard uses).

use std::ffi::c_char;

use crate::ffi::error::last_error_ptr;
use crate::ffi::panic::guard;
use crate::ffi::status::profsubd_status;

/// The message of the most recent call on this thread that returned a `profsubd_status`:
/// "" if that call returned `PROFSUBD_OK`. Never NULL. The string belongs to the library and
/// stays valid until the next profsubd call on the same thread; copy it to keep it.
#[no_mangle]
pub extern "C" fn profsubd_last_error_message() -> *const c_char {
    guard(last_error_ptr)
}

/// A fixed description of a status number: "unknown status" for a number that is none.
/// The string is static: never free it.
#[no_mangle]
pub extern "C" fn profsubd_status_string(status: i32) -> *const c_char {
    guard(|| {
        profsubd_status::from_code(status)
            .map_or(c"unknown status", profsubd_status::description)
            .as_ptr()
    })
}
