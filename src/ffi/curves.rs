//! C API of the sketch-curves construction: the curves as one caller array of points with
//! their counts, τ and the projection as arguments, the other settings on the options
//! object (`src/ffi/construct.rs`), the result a `profsubd_fitted`.

use crate::construct::curves::{build, CurvesInput, Method, Projection};
use crate::ffi::construct::{construct, tuples};
use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::fitted::profsubd_fitted;
use crate::ffi::options::profsubd_options;
use crate::ffi::ptr::arg_slice;
use crate::ffi::status::profsubd_status;

/// Build a patch through unorganized 3-D sketch curves (Qin & Wright): `num_boundary` (3 or
/// 4) boundary curves in order around the patch, then `num_interior` interior curves;
/// `curve_sizes` holds the point count of each (`num_boundary + num_interior` entries) and
/// `points` all their points one curve after the other, 3 doubles `(x, y, z)` each. `tau`
/// is the attraction exponent (>= 0; the paper's default 2). `projection_normal`: 3 doubles,
/// the normal of the projection plane, or NULL for the best-fit plane of all points. Settings
/// (`options` may be NULL): `profsubd_options_set_samples` (quads along the first and the
/// second boundary curve; default 16, 16), the interpolation, and the boundary interpolation
/// and crease method the surface is fitted under and tagged with. Errors:
/// `PROFSUBD_ERROR_INVALID_ARGUMENT` for bad curves or settings (fewer than 3 or more than 4
/// boundary curves, a curve with fewer than 2 points, NaN, tau < 0, no projection plane, a
/// boundary whose projection folds, a fitted limit surface that folds: refused, the message
/// naming the folded faces; the message says which), `PROFSUBD_ERROR_NULL_ARGUMENT`
/// for a NULL array with a non-zero count, `PROFSUBD_ERROR_NUMERICAL` if the fit misses its
/// tolerance.
#[no_mangle]
pub unsafe extern "C" fn profsubd_curves(
    points: *const f64,
    curve_sizes: *const usize,
    num_boundary: usize,
    num_interior: usize,
    tau: f64,
    projection_normal: *const f64,
    options: *const profsubd_options,
    out: *mut *mut profsubd_fitted,
) -> profsubd_status {
    construct(
        out,
        options,
        || {
            read_curves(
                points,
                curve_sizes,
                num_boundary,
                num_interior,
                tau,
                projection_normal,
                Method::Attraction,
            )
        },
        build,
    )
}

/// [`profsubd_curves`] with the fair method (`"method": "fair"`): the mesh's vertices on a
/// curve are curve points, the others minimize the discrete bending energy of the limit
/// surface instead of following the attraction blend (no `tau`). Same arguments, settings
/// and errors as `profsubd_curves`, plus `PROFSUBD_ERROR_LIMIT_EXCEEDED` if the energy's
/// factor is above the options' memory budget.
#[no_mangle]
pub unsafe extern "C" fn profsubd_curves_fair(
    points: *const f64,
    curve_sizes: *const usize,
    num_boundary: usize,
    num_interior: usize,
    projection_normal: *const f64,
    options: *const profsubd_options,
    out: *mut *mut profsubd_fitted,
) -> profsubd_status {
    let read = || {
        read_curves(
            points,
            curve_sizes,
            num_boundary,
            num_interior,
            2.0,
            projection_normal,
            Method::Fair,
        )
    };
    construct(out, options, read, build)
}

/// The input of [`profsubd_curves`] and [`profsubd_curves_fair`] from the caller's arrays.
unsafe fn read_curves(
    points: *const f64,
    curve_sizes: *const usize,
    num_boundary: usize,
    num_interior: usize,
    tau: f64,
    projection_normal: *const f64,
    method: Method,
) -> FfiResult<CurvesInput> {
    let count = num_boundary
        .checked_add(num_interior)
        .ok_or_else(|| FfiError::invalid_argument("curve counts are absurd"))?;
    let sizes = arg_slice(curve_sizes, count, "curve_sizes")?;
    let total = sizes
        .iter()
        .try_fold(0usize, |a, &n| a.checked_add(n))
        .ok_or_else(|| FfiError::invalid_argument("curve_sizes: the total is absurd"))?;
    let all = tuples::<3>(points, total, "points")?;
    let mut curves = Vec::with_capacity(count);
    let mut start = 0;
    for &n in sizes {
        curves.push(all[start..start + n].to_vec());
        start += n;
    }
    let interior = curves.split_off(num_boundary);
    let mut input = CurvesInput::new(curves);
    input.interior = interior;
    input.tau = tau;
    input.method = method;
    if !projection_normal.is_null() {
        let n = tuples::<3>(projection_normal, 1, "projection_normal")?;
        input.projection = Projection::Normal(n[0]);
    }
    Ok(input)
}

#[cfg(test)]
mod tests;
