//! Errors of the C layer and the per-thread last error message.

use std::cell::RefCell;
use std::ffi::{c_char, CString};

use crate::error::Error;
use crate::ffi::status::profsubd_status::{self, *};

/// An error as a C caller sees it: a status and a message. Besides the crate's [`Error`]
/// kinds it has the statuses that only exist at the C boundary (NULL, buffer, handle).
#[derive(Debug, Clone, PartialEq)]
pub struct FfiError {
    /// The status returned to the caller.
    pub status: profsubd_status,
    /// The message `profsubd_last_error_message` returns.
    pub message: String,
}

/// Result of the C layer's internal steps.
pub type FfiResult<T> = std::result::Result<T, FfiError>;

impl FfiError {
    /// An error with this status and message.
    pub fn new(status: profsubd_status, message: impl Into<String>) -> Self {
        FfiError {
            status,
            message: message.into(),
        }
    }

    /// The required pointer argument `name` is NULL.
    pub fn null_argument(name: &str) -> Self {
        Self::new(
            PROFSUBD_ERROR_NULL_ARGUMENT,
            format!("argument `{name}` is NULL"),
        )
    }

    /// An argument out of range.
    pub fn invalid_argument(message: impl Into<String>) -> Self {
        Self::new(PROFSUBD_ERROR_INVALID_ARGUMENT, message)
    }
}

/// The `int32_t` value `value` of the enumerated input `what` as the Rust value `table`
/// pairs it with (each C constant with its Rust value). Errors: `what value V is out of
/// range; expected 0, 1 or 2` (or `0 to 6` for longer tables).
pub fn enum_arg<T: Copy>(what: &str, value: i32, table: &[(i32, T)]) -> FfiResult<T> {
    if let Some(&(_, t)) = table.iter().find(|(v, _)| *v == value) {
        return Ok(t);
    }
    let values: Vec<String> = table.iter().map(|(v, _)| v.to_string()).collect();
    let allowed = match values.as_slice() {
        [] => String::from("nothing"),
        [one] => one.clone(),
        [first @ .., last] if first.len() < 3 => format!("{} or {last}", first.join(", ")),
        [first, .., last] => format!("{first} to {last}"),
    };
    Err(FfiError::invalid_argument(format!(
        "{what} value {value} is out of range; expected {allowed}"
    )))
}

impl From<Error> for FfiError {
    fn from(e: Error) -> Self {
        FfiError {
            status: profsubd_status::from(&e),
            message: e.to_string(),
        }
    }
}

thread_local! {
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

/// Record `message` as this thread's last error (interior NUL bytes become spaces).
pub fn set_last_error(message: &str) {
    let bytes: Vec<u8> = message
        .bytes()
        .map(|b| if b == 0 { b' ' } else { b })
        .collect();
    // No NUL left, so this cannot fail; the fallback keeps the function panic-free.
    let c = CString::new(bytes).unwrap_or_default();
    LAST_ERROR.with(|e| *e.borrow_mut() = c);
}

/// Make this thread's last error the empty string (cheap when it already is).
pub fn clear_last_error() {
    LAST_ERROR.with(|e| {
        if !e.borrow().is_empty() {
            *e.borrow_mut() = CString::default();
        }
    });
}

/// This thread's last error message, as Rust text (for tests and Rust callers of the C layer).
pub fn last_error() -> String {
    LAST_ERROR.with(|e| e.borrow().to_string_lossy().into_owned())
}

/// This thread's last error message as a C string, valid until the next call that sets or
/// clears it on this thread.
pub fn last_error_ptr() -> *const c_char {
    LAST_ERROR.with(|e| e.borrow().as_ptr())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::message::profsubd_last_error_message;
    use std::ffi::CStr;

    fn c_message() -> String {
        unsafe { CStr::from_ptr(profsubd_last_error_message()) }
            .to_str()
            .unwrap()
            .to_owned()
    }

    #[test]
    fn message_is_per_thread_and_cleared() {
        set_last_error("first\0part");
        assert_eq!(c_message(), "first part");
        std::thread::spawn(|| assert_eq!(c_message(), ""))
            .join()
            .unwrap();
        assert_eq!(c_message(), "first part");
        clear_last_error();
        assert_eq!(c_message(), "");
    }

    #[test]
    fn crate_errors_keep_their_message() {
        let e = FfiError::from(Error::invalid_mesh("face 3 has 2 vertices"));
        assert_eq!(e.status, PROFSUBD_ERROR_INVALID_MESH);
        assert_eq!(e.message, "invalid mesh: face 3 has 2 vertices");
    }

    #[test]
    fn enum_args_map_their_table_and_name_the_allowed_values() {
        let two = [(0, 'a'), (1, 'b')];
        assert_eq!(enum_arg("x", 1, &two), Ok('b'));
        let e = enum_arg("x", 2, &two).unwrap_err();
        assert_eq!(e.status, PROFSUBD_ERROR_INVALID_ARGUMENT);
        assert_eq!(e.message, "x value 2 is out of range; expected 0 or 1");
        let three = [(0, 'a'), (1, 'b'), (2, 'c')];
        let e = enum_arg("y", -1, &three).unwrap_err();
        assert_eq!(e.message, "y value -1 is out of range; expected 0, 1 or 2");
        let seven: Vec<(i32, i32)> = (0..7).map(|v| (v, v)).collect();
        let e = enum_arg("z", 7, &seven).unwrap_err();
        assert_eq!(e.message, "z value 7 is out of range; expected 0 to 6");
    }
}
