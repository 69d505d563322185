//! The one mechanism every exported function goes through: panics are caught here.
//!
//! A panic unwinding into C is undefined behaviour, so [`guard`] runs the body under
//! `catch_unwind` and turns a panic into a value the caller can handle
//! (`PROFSUBD_ERROR_INTERNAL` with the panic message, or a neutral value for functions
//! without a status). [`status_call`] adds the status protocol on top: clear the last error,
//! run, record the error's message.

use std::any::Any;
use std::ffi::c_char;
use std::panic::{catch_unwind, AssertUnwindSafe};

use crate::ffi::error::{clear_last_error, set_last_error, FfiResult};
use crate::ffi::status::profsubd_status::{self, *};

/// What an exported function returns when its body panicked.
pub trait OnPanic {
    /// The value returned after a caught panic.
    fn on_panic() -> Self;
}

impl OnPanic for profsubd_status {
    fn on_panic() -> Self {
        PROFSUBD_ERROR_INTERNAL
    }
}

impl OnPanic for () {
    fn on_panic() -> Self {}
}

impl OnPanic for u32 {
    fn on_panic() -> Self {
        0
    }
}

impl OnPanic for *const c_char {
    /// The empty string, so that string getters never return NULL.
    fn on_panic() -> Self {
        c"".as_ptr()
    }
}

/// Run `body`; if it panics, record the panic as this thread's last error and return
/// [`OnPanic::on_panic`]. Every exported function is a call to this (or to [`status_call`]).
pub fn guard<R: OnPanic>(body: impl FnOnce() -> R) -> R {
    // AssertUnwindSafe: after a panic nothing the body touched is used again; outputs are
    // only written at the end of a successful body.
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(r) => r,
        Err(payload) => {
            set_last_error(&panic_message(payload.as_ref()));
            R::on_panic()
        }
    }
}

/// Run `body` under [`guard`] with the status protocol: the last error is cleared first and
/// set to the error's message on failure.
pub fn status_call(body: impl FnOnce() -> FfiResult<()>) -> profsubd_status {
    clear_last_error();
    guard(|| match body() {
        Ok(()) => PROFSUBD_OK,
        Err(e) => {
            set_last_error(&e.message);
            e.status
        }
    })
}

fn panic_message(payload: &(dyn Any + Send)) -> String {
    let what = payload
        .downcast_ref::<&str>()
        .copied()
        .or_else(|| payload.downcast_ref::<String>().map(String::as_str))
        .unwrap_or("(no message)");
    format!("internal error: profsubd panicked ({what}); please report this bug")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::error::{last_error, FfiError};

    #[test]
    fn a_panic_becomes_internal_error_with_its_message() {
        let n = 3;
        let s = status_call(|| panic!("index {n} out of range"));
        assert_eq!(s, PROFSUBD_ERROR_INTERNAL);
        assert_eq!(
            last_error(),
            "internal error: profsubd panicked (index 3 out of range); please report this bug"
        );
        let s = status_call(|| std::panic::panic_any(42u8));
        assert_eq!(s, PROFSUBD_ERROR_INTERNAL);
        assert!(last_error().contains("(no message)"));
    }

    #[test]
    fn value_getters_get_neutral_values_after_a_panic() {
        let p: *const c_char = guard(|| panic!("boom"));
        assert_eq!(unsafe { std::ffi::CStr::from_ptr(p) }.to_bytes(), b"");
        assert_eq!(guard(|| -> u32 { panic!("boom") }), 0);
        assert!(last_error().contains("boom"));
    }

    #[test]
    fn status_protocol_sets_and_clears_the_message() {
        let s = status_call(|| Err(FfiError::invalid_argument("bad value 7")));
        assert_eq!(s, PROFSUBD_ERROR_INVALID_ARGUMENT);
        assert_eq!(last_error(), "bad value 7");
        assert_eq!(status_call(|| Ok(())), PROFSUBD_OK);
        assert_eq!(last_error(), "");
    }
}
