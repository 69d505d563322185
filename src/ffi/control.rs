//! Progress, cancellation and the memory budget on the options object: the C face of
//! [`crate::control::Control`], which the options' settings carry to every construction,
//! evaluator build and refinement that takes the options.

use std::ffi::{c_int, c_void};

use crate::control::{Control, Progress};
use crate::ffi::handle;
use crate::ffi::options::profsubd_options;
use crate::ffi::panic::status_call;
use crate::ffi::status::profsubd_status;

/// A progress callback: `fraction` of the work done, in `[0, 1]`, non-decreasing within a
/// call; `user` as given to `profsubd_options_set_progress`. Return 0 to continue, non-zero
/// to cancel (the call then returns `PROFSUBD_ERROR_CANCELLED`).
pub type profsubd_progress_fn =
    Option<unsafe extern "C" fn(fraction: f64, user: *mut c_void) -> c_int>;

/// The caller's callback and its pointer.
struct CProgress {
    callback: unsafe extern "C" fn(f64, *mut c_void) -> c_int,
    user: *mut c_void,
}

// SAFETY: the callback is called only on the thread that made the call it reports on; the
// header documents that sharing `user` between threads running calls at once is the caller's
// business.
unsafe impl Send for CProgress {}
unsafe impl Sync for CProgress {}

impl Progress for CProgress {
    fn report(&self, fraction: f64) -> bool {
        // SAFETY: a function pointer the caller gave for this purpose, with its own `user`.
        unsafe { (self.callback)(fraction, self.user) != 0 }
    }
}

/// Set the progress callback of the work done with `options`: every construction
/// (`profsubd_profile_build`, `profsubd_revolve`, `profsubd_sweep`, ...: the fit and its
/// stages, BiCGSTAB iterations, dense LU columns), `profsubd_evaluator_new` (its setup, each
/// face, its positions), `profsubd_refine_uniform` (each level) and
/// `profsubd_check_folds_with_options` (each face). It is called on the calling thread at the start,
/// regularly (at most about a thousand times per stage) and at the end of the work; when it
/// returns non-zero the call stops within one step and returns `PROFSUBD_ERROR_CANCELLED`,
/// its outputs untouched and nothing leaked. `callback` NULL removes it. Calls sharing the
/// options object on several threads call the callback concurrently with the same `user`.
///
/// Errors: `PROFSUBD_ERROR_NULL_ARGUMENT` / `PROFSUBD_ERROR_INVALID_HANDLE` for `options`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_progress(
    options: *mut profsubd_options,
    callback: profsubd_progress_fn,
    user: *mut c_void,
) -> profsubd_status {
    status_call(|| {
        let o = handle::borrow_mut(options, "options")?;
        let budget = o.settings.control.memory_budget();
        let control = Control::NONE
            .with_memory_budget(budget)
            .with_threads(o.threads);
        o.settings.control = match callback {
            Some(callback) => control.with_progress(CProgress { callback, user }),
            None => control,
        };
        Ok(())
    })
}

/// Set the memory budget of the work done with `options` (constructions, evaluator build,
/// refinement, `profsubd_check_folds_with_options`), in bytes; 0 (the default) for none. A call estimates its largest
/// allocations from its sizes before making them and returns
/// `PROFSUBD_ERROR_LIMIT_EXCEEDED` when the estimate is above the budget (the message gives
/// both figures).
///
/// Errors: `PROFSUBD_ERROR_NULL_ARGUMENT` / `PROFSUBD_ERROR_INVALID_HANDLE` for `options`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_memory_budget(
    options: *mut profsubd_options,
    bytes: u64,
) -> profsubd_status {
    status_call(|| {
        let o = handle::borrow_mut(options, "options")?;
        let control = std::mem::take(&mut o.settings.control);
        o.settings.control = control.with_memory_budget((bytes > 0).then_some(bytes));
        Ok(())
    })
}
