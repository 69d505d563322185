//! The fold check through the C ABI: `profsubd_check_folds` (and
//! `profsubd_check_folds_with_options`, with progress, cancellation and a memory budget)
//! samples an evaluator's limit surface and returns a fold-report handle with a summary getter and a copy-out of the
//! folded faces (the criterion is [`crate::eval::folds`]'s).

use crate::eval::folds::{find_folds_with, FoldReport, FoldSettings};
use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::evaluator::profsubd_evaluator;
use crate::ffi::handle::{self, Handle};
use crate::ffi::options::{options_or_default, profsubd_options};
use crate::ffi::panic::{guard, status_call};
use crate::ffi::ptr::{arg_out, copy_slice};
use crate::ffi::status::profsubd_status;

/// How densely `profsubd_check_folds` samples (NULL for the defaults 9, 4, 45).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct profsubd_fold_settings {
    /// Samples along each edge of a parametric face's base lattice, 2..=1025 (default 9).
    pub samples_per_edge: usize,
    /// How many times a lattice cell may be halved, next to extraordinary or non-smooth
    /// corners and where the normal turns fast, 0..=16 (default 4).
    pub adaptive_depth: usize,
    /// A cell whose corner normals turn by more than this many degrees is refined, in
    /// (0, 180] (default 45).
    pub refine_turn_deg: f64,
}

/// The summary of a fold report.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct profsubd_fold_summary {
    /// Folded control faces (0: the surface is fold-free).
    pub num_folded_faces: usize,
    /// Parametric faces checked (faces without limit surface are skipped).
    pub faces_checked: usize,
    /// Limit evaluations made.
    pub samples: usize,
    /// Largest angle (degrees) between a sample's normal and its parametric face's mean
    /// normal; above 90 the surface is reversed there.
    pub worst_reversal_deg: f64,
    /// Parametric face of that sample, -1 when no sample has a normal.
    pub worst_face: i64,
    /// `u` of that sample (0 when `worst_face` is -1).
    pub worst_u: f64,
    /// `v` of that sample (0 when `worst_face` is -1).
    pub worst_v: f64,
    /// Minimum over samples of `(du x dv) . n_mean / typical |du x dv|` of the face;
    /// negative where the surface is reversed; +infinity when no sample counts.
    pub min_relative_jacobian: f64,
}

/// The result of `profsubd_check_folds` (opaque, immutable, safe to share between threads).
/// Release with `profsubd_fold_report_free`.
pub struct profsubd_fold_report {
    _private: [u8; 0],
}

impl Handle for profsubd_fold_report {
    type Inner = FoldReport;
    const MAGIC: u64 = u64::from_le_bytes(*b"psd-FOLD");
    const NAME: &'static str = "profsubd_fold_report";
}

unsafe fn settings_arg(p: *const profsubd_fold_settings) -> FfiResult<FoldSettings> {
    if p.is_null() {
        return Ok(FoldSettings::default());
    }
    let s = *crate::ffi::ptr::arg_ref(p, "settings")?;
    Ok(FoldSettings {
        samples_per_edge: s.samples_per_edge,
        adaptive_depth: s.adaptive_depth,
        refine_turn_deg: s.refine_turn_deg,
    })
}

/// Sample the limit surface of `evaluator` and report where it folds: a sample whose normal
/// is more than 90 degrees from its parametric face's mean normal, or a normal that jumps by
/// more than 90 degrees across a cell of the finest sampling lattice; creases and corners,
/// where the normal jumps between faces, are not folds (see the README, "Surface validity").
/// `settings` may be NULL (defaults). The work is bounded: at most 2^26 limit evaluations
/// in all (the base lattices, faces x `samples_per_edge`^2, are checked against it before any
/// evaluation; the adaptive halving as it samples) and 2^21 samples in one face
/// (`profsubd_check_folds_with_options` adds progress, cancellation and a memory budget).
/// Errors: `PROFSUBD_ERROR_INVALID_ARGUMENT` for settings out of range;
/// `PROFSUBD_ERROR_LIMIT_EXCEEDED` above those ceilings (the message names the figures and
/// the face). `*out` is untouched on error.
#[no_mangle]
pub unsafe extern "C" fn profsubd_check_folds(
    evaluator: *const profsubd_evaluator,
    settings: *const profsubd_fold_settings,
    out: *mut *mut profsubd_fold_report,
) -> profsubd_status {
    profsubd_check_folds_with_options(evaluator, settings, std::ptr::null(), out)
}

/// `profsubd_check_folds` with the progress callback and memory budget of `options` (NULL:
/// neither; its other settings do not apply): the callback is called through the mesh's base
/// level, at each parametric face and every 16,384 samples inside one, and a non-zero return
/// stops the check with `PROFSUBD_ERROR_CANCELLED`; the check is refused with
/// `PROFSUBD_ERROR_LIMIT_EXCEEDED` before any evaluation when its estimated memory (about 64
/// bytes per face-vertex index of the mesh plus 160 bytes per sample of one face's base
/// lattice) is above the budget, and when the adaptive halving of one face would pass it.
/// Errors: those of `profsubd_check_folds`; `PROFSUBD_ERROR_INVALID_HANDLE` for `options`.
/// `*out` is untouched on error.
#[no_mangle]
pub unsafe extern "C" fn profsubd_check_folds_with_options(
    evaluator: *const profsubd_evaluator,
    settings: *const profsubd_fold_settings,
    options: *const profsubd_options,
    out: *mut *mut profsubd_fold_report,
) -> profsubd_status {
    status_call(|| {
        let ev = handle::borrow::<profsubd_evaluator>(evaluator, "evaluator")?;
        let s = settings_arg(settings)?;
        let o = options_or_default(options)?;
        let out = arg_out(out, "out")?;
        let report = find_folds_with(ev, &s, &o.settings.control)?;
        out.write(handle::into_raw(report));
        Ok(())
    })
}

/// Release a fold report (NULL is a no-op).
#[no_mangle]
pub unsafe extern "C" fn profsubd_fold_report_free(report: *mut profsubd_fold_report) {
    guard(|| handle::free(report))
}

/// The report's counts, worst reversal and where, and minimum relative Jacobian.
#[no_mangle]
pub unsafe extern "C" fn profsubd_fold_report_get_summary(
    report: *const profsubd_fold_report,
    out: *mut profsubd_fold_summary,
) -> profsubd_status {
    status_call(|| {
        let r = handle::borrow::<profsubd_fold_report>(report, "report")?;
        let out = arg_out(out, "out")?;
        let (face, u, v) = r
            .worst_at
            .map_or((-1, 0.0, 0.0), |(f, u, v)| (f as i64, u, v));
        out.write(profsubd_fold_summary {
            num_folded_faces: r.folded_faces.len(),
            faces_checked: r.faces_checked,
            samples: r.samples,
            worst_reversal_deg: r.worst_reversal_deg,
            worst_face: face,
            worst_u: u,
            worst_v: v,
            min_relative_jacobian: r.min_relative_jacobian,
        });
        Ok(())
    })
}

/// Copy the folded control faces' indices (ascending) into `out`. `capacity` and
/// `*needed` count faces (copy-out protocol).
#[no_mangle]
pub unsafe extern "C" fn profsubd_fold_report_get_folded_faces(
    report: *const profsubd_fold_report,
    out: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (report, "report"),
        (out, "out", capacity, needed),
        (1, "faces"),
        |r: &FoldReport| {
            let faces = r
                .folded_faces
                .iter()
                .map(|f| {
                    u32::try_from(f.face).map_err(|_| {
                        FfiError::invalid_argument(format!("face {} exceeds uint32_t", f.face))
                    })
                })
                .collect::<FfiResult<Vec<u32>>>()?;
            Ok((faces.len(), faces))
        },
    )
}

#[cfg(test)]
mod tests;
