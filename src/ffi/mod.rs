//! The C ABI, declared in `include/profsubd.h` (generated from this module by cbindgen).
//!
//! This module is the only place where `unsafe` code touches pointers given by C callers.
//! Every exported function goes through [`panic::guard`] (directly, or through
//! [`panic::status_call`] for functions returning a [`profsubd_status`]), so a panic never
//! unwinds into C: it becomes `PROFSUBD_ERROR_INTERNAL` with a message. Pointer arguments are
//! checked by the helpers of [`ptr`] and handles by [`handle`], never by hand.
//!
//! # Rules for C callers (stated once, valid for every function)
//!
//! - **Status**: every function returns a `profsubd_status`, except the `_free` functions and
//!   the version and message getters. On any error *no output is written*, with one documented
//!   exception: `PROFSUBD_ERROR_BUFFER_TOO_SMALL` writes the needed count to `*needed`.
//! - **Messages**: `profsubd_last_error_message()` describes the most recent call on the
//!   calling thread that returned a status ("" if it returned `PROFSUBD_OK`). The string is
//!   owned by the library and valid until the next profsubd call on that thread.
//! - **Ownership**: a handle returned through an `out` parameter (`profsubd_mesh **out`) is
//!   owned by the caller, who releases it with the matching `_free` function (`_free(NULL)` is a
//!   no-op). Input arrays and strings are only read during the call and copied where kept: the
//!   caller keeps ownership. Strings returned as `const char *` are owned by the library.
//! - **Pointers**: `const T *` arguments are read-only. A required pointer that is NULL gives
//!   `PROFSUBD_ERROR_NULL_ARGUMENT`; an array pointer may be NULL only when its count is 0.
//!   Pointers must be aligned for their type. Paths are NUL-terminated byte strings (UTF-8 or
//!   the platform's encoding).
//! - **Counts** are in elements of the array concerned (doubles, indices, creases...), never
//!   bytes; each function says which.
//! - **Handles** carry a tag checked on entry and changed on free, so a handle of another kind
//!   or a garbage pointer gives `PROFSUBD_ERROR_INVALID_HANDLE`. Detection of an already freed
//!   handle is best effort (the memory may have been reused): never use a freed handle.
//! - **Threads**: meshes (and other result objects) are immutable after creation and may be
//!   used from several threads at once. An options object is written by its setters: do not
//!   set options on one thread while another thread uses the same object. The last error
//!   message is per thread. The library has no global mutable state.
//! - **Enumerated inputs** are `int32_t` with named constants (`PROFSUBD_BOUNDARY_NONE`...); a
//!   value out of range gives `PROFSUBD_ERROR_INVALID_ARGUMENT`.
//!
//! # Adding to the C API
//!
//! Put the functions in a file of this module; return [`profsubd_status`] through
//! [`panic::status_call`]; check pointers with [`ptr`] and handles with [`handle`]; give named
//! values as a `#[repr(C)]` enum (cbindgen is told to skip `const` items, so that constants of
//! other modules never reach the header; list an enum no signature mentions under
//! `[export] include` in `cbindgen.toml`); then regenerate the header with
//! `cbindgen --config cbindgen.toml --output include/profsubd.h` and add bad-input tests.
//!
//! The Rust functions are `unsafe` because they trust these rules for the pointers they cannot
//! check (a non-NULL pointer must point to as many readable or writable elements as its count
//! says); clippy's per-function `# Safety` section is replaced by this list.

#![allow(non_camel_case_types)]
#![allow(clippy::missing_safety_doc)]

pub mod blend;
pub mod construct;
pub mod control;
pub mod curves;
pub mod error;
pub mod evaluator;
pub mod fitted;
pub mod folds;
pub mod gbs;
pub mod handle;
pub mod limit;
pub mod mesh;
pub mod mesh_io;
pub mod mesh_topology;
pub mod message;
pub mod options;
pub mod osd_hazards;
pub mod panic;
pub mod profile;
pub mod ptr;
pub mod refine;
pub mod revolve;
pub mod shell;
pub mod status;
pub mod sweep;
pub mod tessellate;
pub mod version;

pub use evaluator::profsubd_evaluator;
pub use fitted::profsubd_fitted;
pub use folds::profsubd_fold_report;
pub use limit::profsubd_stencil_table;
pub use mesh::{profsubd_mesh, profsubd_mesh_desc};
pub use mesh_topology::profsubd_mesh_report;
pub use options::profsubd_options;
pub use status::profsubd_status;
pub use tessellate::profsubd_tessellation;
