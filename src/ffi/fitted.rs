//! The result object of every construction, `profsubd_fitted`: the fitted control mesh, the
//! data points it interpolates, the fit residual and the surface report
//! ([`crate::construct::Fitted`]).

use std::sync::Arc;

use crate::construct::Fitted;
use crate::ffi::handle::{self, Handle};
use crate::ffi::mesh::{profsubd_mesh, MeshData};
use crate::ffi::panic::{guard, status_call};
use crate::ffi::ptr::{arg_out, arg_out_opt, copy_slice};
use crate::ffi::status::profsubd_status;

/// A fitted construction (opaque): made by `profsubd_profile_build`,
/// `profsubd_profile_build_default`, `profsubd_revolve` or `profsubd_sweep`; released with
/// `profsubd_fitted_free`. Immutable: usable from several threads at once.
pub struct profsubd_fitted {
    _private: [u8; 0],
}

impl Handle for profsubd_fitted {
    type Inner = Fitted;
    const MAGIC: u64 = u64::from_le_bytes(*b"psd-FITD");
    const NAME: &'static str = "profsubd_fitted";
}

/// `*out` = a new handle for the result of a construction.
pub fn new_fitted_handle(fitted: Fitted) -> *mut profsubd_fitted {
    handle::into_raw(fitted)
}

/// Release a fitted construction. NULL is a no-op. Meshes taken from it stay valid.
#[no_mangle]
pub unsafe extern "C" fn profsubd_fitted_free(fitted: *mut profsubd_fitted) {
    guard(|| handle::free(fitted))
}

/// A new mesh handle (caller-owned, released with `profsubd_mesh_free`) with the fitted
/// control mesh: quads, crease and corner tags, option tags. The mesh is shared, not copied.
#[no_mangle]
pub unsafe extern "C" fn profsubd_fitted_get_mesh(
    fitted: *const profsubd_fitted,
    out: *mut *mut profsubd_mesh,
) -> profsubd_status {
    status_call(|| {
        let out = arg_out(out, "out")?;
        let mesh = Arc::clone(&handle::borrow(fitted, "fitted")?.mesh);
        out.write(handle::into_raw(MeshData::shared(mesh)));
        Ok(())
    })
}

/// Copy the data points: 3 doubles per control vertex, in vertex order; vertex `i`'s limit
/// position equals point `i`. `capacity` and `*needed` count doubles; copy-out protocol as
/// `profsubd_mesh_get_positions`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_fitted_get_targets(
    fitted: *const profsubd_fitted,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (fitted, "fitted"),
        (out, "out", capacity, needed),
        (1, "doubles"),
        |f: &Fitted| {
            let targets = &f.targets;
            Ok((3 * targets.len(), targets.iter().flat_map(|t| t.to_array())))
        },
    )
}

/// The fit's achieved residual (largest distance between a vertex's limit position and its
/// data point) and the tolerance it met (1e-10 × the data points' bounding-box diagonal).
/// Either output may be NULL.
#[no_mangle]
pub unsafe extern "C" fn profsubd_fitted_get_fit_residual(
    fitted: *const profsubd_fitted,
    residual: *mut f64,
    tolerance: *mut f64,
) -> profsubd_status {
    status_call(|| {
        let fit = handle::borrow(fitted, "fitted")?.fit;
        let (r, t) = (
            arg_out_opt(residual, "residual")?,
            arg_out_opt(tolerance, "tolerance")?,
        );
        if let Some(r) = r {
            r.write(fit.residual);
        }
        if let Some(t) = t {
            t.write(fit.tolerance);
        }
        Ok(())
    })
}

/// The fit's condition estimate (`κ × diagonal / smallest spacing` between neighbouring
/// data points; see the README, "Reliability"): how much a relative change of the data can
/// grow relative to the smallest sample spacing. Constructions refuse fits above 1e8
/// (`PROFSUBD_ERROR_NUMERICAL`, "ill-conditioned fit").
#[no_mangle]
pub unsafe extern "C" fn profsubd_fitted_get_fit_condition(
    fitted: *const profsubd_fitted,
    condition: *mut f64,
) -> profsubd_status {
    status_call(|| {
        let fit = handle::borrow(fitted, "fitted")?.fit;
        arg_out(condition, "condition")?.write(fit.condition);
        Ok(())
    })
}

/// The largest and mean distance from the limit surface to the design surface between the
/// data points, over the limit surface's bounding-box diagonal: the limit and the design
/// surface sampled at the same 5 × 5 parameters per face (the design parameter bilinear
/// between the face's data points' parameters), measured along the design surface's
/// normal (see the README, "Valid surfaces"). Computed (with the fold check) on the first
/// call of this or `profsubd_fitted_get_surface_quality`. Either output may be NULL.
#[no_mangle]
pub unsafe extern "C" fn profsubd_fitted_get_design_distance(
    fitted: *const profsubd_fitted,
    max: *mut f64,
    mean: *mut f64,
) -> profsubd_status {
    status_call(|| {
        let fitted = handle::borrow(fitted, "fitted")?;
        let (max, mean) = (arg_out_opt(max, "max")?, arg_out_opt(mean, "mean")?);
        let report = fitted.surface_report()?;
        if let Some(m) = max {
            m.write(report.max_design_distance);
        }
        if let Some(m) = mean {
            m.write(report.mean_design_distance);
        }
        Ok(())
    })
}

/// The number of control faces whose limit surface folds (the fold check's criterion,
/// `eval::folds`, with default settings), the worst normal reversal in degrees (above 90
/// where it folds) and the undulation: the limit surface's bending energy over the design
/// surface's (1 = as fair as the design). Any output may be NULL.
#[no_mangle]
pub unsafe extern "C" fn profsubd_fitted_get_surface_quality(
    fitted: *const profsubd_fitted,
    folded_faces: *mut usize,
    worst_reversal_deg: *mut f64,
    undulation: *mut f64,
) -> profsubd_status {
    status_call(|| {
        let fitted = handle::borrow(fitted, "fitted")?;
        let (folded, worst, und) = (
            arg_out_opt(folded_faces, "folded_faces")?,
            arg_out_opt(worst_reversal_deg, "worst_reversal_deg")?,
            arg_out_opt(undulation, "undulation")?,
        );
        let report = fitted.surface_report()?;
        if let Some(o) = folded {
            o.write(report.folded_faces);
        }
        if let Some(o) = worst {
            o.write(report.worst_reversal_deg);
        }
        if let Some(o) = und {
            o.write(report.undulation);
        }
        Ok(())
    })
}
