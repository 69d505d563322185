//! The one status enum of the C API, with stable numbers.

use std::ffi::CStr;

use crate::error::Error;

/// Outcome of a C API call. The numbers are stable: codes may be added, never renumbered.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum profsubd_status {
    /// Success.
    PROFSUBD_OK = 0,
    /// A required pointer argument was NULL.
    PROFSUBD_ERROR_NULL_ARGUMENT = 1,
    /// An argument is out of its documented range (bad size, unknown enumerated value,
    /// count too large, misaligned pointer...).
    PROFSUBD_ERROR_INVALID_ARGUMENT = 2,
    /// The mesh data is not a mesh OpenSubdiv could take (index out of range, face with fewer
    /// than 3 vertices, non-finite coordinate, NaN or negative sharpness...).
    PROFSUBD_ERROR_INVALID_MESH = 3,
    /// The operation needs a 2-manifold mesh and this one is not.
    PROFSUBD_ERROR_NON_MANIFOLD = 4,
    /// Reading or writing a file failed.
    PROFSUBD_ERROR_IO = 5,
    /// A file is malformed (the message gives file, line and what was expected).
    PROFSUBD_ERROR_PARSE = 6,
    /// The caller's buffer is too small; the needed count was written to `*needed`.
    PROFSUBD_ERROR_BUFFER_TOO_SMALL = 7,
    /// A numerical procedure failed (singular system, no convergence).
    PROFSUBD_ERROR_NUMERICAL = 8,
    /// A handle is not a live object of the expected kind (freed, or another kind).
    PROFSUBD_ERROR_INVALID_HANDLE = 9,
    /// The progress callback returned non-zero: the work stopped, outputs are untouched.
    PROFSUBD_ERROR_CANCELLED = 10,
    /// A size above a documented ceiling, or work whose estimated memory exceeds the budget
    /// set with `profsubd_options_set_memory_budget`, refused before allocating.
    PROFSUBD_ERROR_LIMIT_EXCEEDED = 11,
    /// A bug in profsubd was caught (a Rust panic); the message says where.
    PROFSUBD_ERROR_INTERNAL = 99,
}

use profsubd_status::*;

/// Every status, in numeric order.
const ALL: [profsubd_status; 13] = [
    PROFSUBD_OK,
    PROFSUBD_ERROR_NULL_ARGUMENT,
    PROFSUBD_ERROR_INVALID_ARGUMENT,
    PROFSUBD_ERROR_INVALID_MESH,
    PROFSUBD_ERROR_NON_MANIFOLD,
    PROFSUBD_ERROR_IO,
    PROFSUBD_ERROR_PARSE,
    PROFSUBD_ERROR_BUFFER_TOO_SMALL,
    PROFSUBD_ERROR_NUMERICAL,
    PROFSUBD_ERROR_INVALID_HANDLE,
    PROFSUBD_ERROR_CANCELLED,
    PROFSUBD_ERROR_LIMIT_EXCEEDED,
    PROFSUBD_ERROR_INTERNAL,
];

impl profsubd_status {
    /// The status with number `code`, if there is one.
    pub fn from_code(code: i32) -> Option<profsubd_status> {
        ALL.into_iter().find(|s| *s as i32 == code)
    }

    /// A short, fixed description.
    pub fn description(self) -> &'static CStr {
        match self {
            PROFSUBD_OK => c"success",
            PROFSUBD_ERROR_NULL_ARGUMENT => c"a required pointer argument is NULL",
            PROFSUBD_ERROR_INVALID_ARGUMENT => c"invalid argument",
            PROFSUBD_ERROR_INVALID_MESH => c"invalid mesh",
            PROFSUBD_ERROR_NON_MANIFOLD => c"the mesh is not manifold",
            PROFSUBD_ERROR_IO => c"input/output error",
            PROFSUBD_ERROR_PARSE => c"malformed input file",
            PROFSUBD_ERROR_BUFFER_TOO_SMALL => c"buffer too small",
            PROFSUBD_ERROR_NUMERICAL => c"numerical failure",
            PROFSUBD_ERROR_INVALID_HANDLE => c"invalid handle (freed, or another kind of object)",
            PROFSUBD_ERROR_CANCELLED => c"cancelled by the progress callback",
            PROFSUBD_ERROR_LIMIT_EXCEEDED => c"above a size limit or the memory budget",
            PROFSUBD_ERROR_INTERNAL => c"internal error (a bug in profsubd)",
        }
    }
}

impl From<&Error> for profsubd_status {
    fn from(e: &Error) -> Self {
        match e {
            Error::InvalidArgument(_) => PROFSUBD_ERROR_INVALID_ARGUMENT,
            Error::InvalidMesh(_) => PROFSUBD_ERROR_INVALID_MESH,
            Error::NonManifold(_) => PROFSUBD_ERROR_NON_MANIFOLD,
            Error::Io { .. } => PROFSUBD_ERROR_IO,
            Error::Parse { .. } => PROFSUBD_ERROR_PARSE,
            Error::NumericalFailure(_) => PROFSUBD_ERROR_NUMERICAL,
            Error::Cancelled(_) => PROFSUBD_ERROR_CANCELLED,
            Error::LimitExceeded(_) => PROFSUBD_ERROR_LIMIT_EXCEEDED,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::message::profsubd_status_string;
    use std::path::PathBuf;

    #[test]
    fn numbers_are_the_agreed_ones() {
        let expected = [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 99];
        let got: Vec<i32> = ALL.iter().map(|s| *s as i32).collect();
        assert_eq!(got, expected);
        assert_eq!(std::mem::size_of::<profsubd_status>(), 4);
    }

    #[test]
    fn every_error_maps_to_its_status() {
        let cases = [
            (Error::invalid_argument("x"), 2),
            (Error::invalid_mesh("x"), 3),
            (Error::NonManifold("x".into()), 4),
            (
                Error::Io {
                    path: PathBuf::from("a"),
                    message: "m".into(),
                },
                5,
            ),
            (
                Error::Parse {
                    path: PathBuf::from("a"),
                    line: 3,
                    message: "m".into(),
                },
                6,
            ),
            (Error::NumericalFailure("x".into()), 8),
            (Error::Cancelled("x".into()), 10),
            (Error::LimitExceeded("x".into()), 11),
        ];
        for (e, code) in cases {
            assert_eq!(profsubd_status::from(&e) as i32, code, "{e}");
        }
    }

    #[test]
    fn status_string_covers_known_and_unknown_codes() {
        let s = |c| {
            unsafe { CStr::from_ptr(profsubd_status_string(c)) }
                .to_str()
                .unwrap()
        };
        assert_eq!(s(0), "success");
        assert_eq!(s(7), "buffer too small");
        assert_eq!(s(99), "internal error (a bug in profsubd)");
        assert_eq!(s(10), "cancelled by the progress callback");
        assert_eq!(s(12), "unknown status");
        assert_eq!(s(-1), "unknown status");
        assert_eq!(s(i32::MIN), "unknown status");
    }
}
