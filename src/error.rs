//! The one error type of the library.
//!
//! Each variant maps to one `profsubd_status` code of the C API (see [`crate::ffi`]), so a
//! C caller and a Rust caller see the same classification and the same message.

use std::path::PathBuf;

/// Result alias used throughout the crate.
pub type Result<T> = std::result::Result<T, Error>;

/// Everything that can go wrong, classified the way a caller needs to react to it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// An argument is out of its documented range (NaN, negative count, unknown option value...).
    #[error("invalid argument: {0}")]
    InvalidArgument(String),
    /// A mesh that OpenSubdiv's Far could not take either (index out of range, face with
    /// fewer than 3 vertices, non-finite coordinate, bad tag...).
    #[error("invalid mesh: {0}")]
    InvalidMesh(String),
    /// A mesh that is valid for subdivision but not for a construction that needs a
    /// 2-manifold (non-manifold edge or vertex).
    #[error("non-manifold mesh: {0}")]
    NonManifold(String),
    /// Reading or writing a file failed.
    #[error("{}: {message}", path.display())]
    Io {
        /// The file concerned.
        path: PathBuf,
        /// What the operating system said.
        message: String,
    },
    /// A text input (OBJ, JSON, point list) is malformed.
    #[error("{}:{line}: {message}", path.display())]
    Parse {
        /// The file concerned (`<memory>` for in-memory input).
        path: PathBuf,
        /// 1-based line number, 0 when not known.
        line: usize,
        /// What was expected and what was found.
        message: String,
    },
    /// A numerical procedure did not reach its tolerance (singular system, no convergence).
    #[error("numerical failure: {0}")]
    NumericalFailure(String),
    /// The caller's progress callback asked to stop ([`crate::control`]); nothing was
    /// written.
    #[error("cancelled: {0}")]
    Cancelled(String),
    /// A request above a documented size ceiling or the caller's memory budget, refused
    /// before allocating.
    #[error("limit exceeded: {0}")]
    LimitExceeded(String),
}

impl Error {
    /// Shorthand for [`Error::InvalidArgument`].
    pub fn invalid_argument(msg: impl Into<String>) -> Self {
        Error::InvalidArgument(msg.into())
    }

    /// Shorthand for [`Error::InvalidMesh`].
    pub fn invalid_mesh(msg: impl Into<String>) -> Self {
        Error::InvalidMesh(msg.into())
    }
}
