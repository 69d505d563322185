//! C API of sweeps: profile and trajectory as caller arrays, settings on the options
//! object (`src/ffi/construct.rs`), the result a `profsubd_fitted`.

use crate::construct::sweep::{build, SweepInput};
use crate::ffi::construct::{construct, tuples};
use crate::ffi::fitted::profsubd_fitted;
use crate::ffi::options::profsubd_options;
use crate::ffi::status::profsubd_status;

/// Sweep a planar profile along a trajectory: `profile` holds `num_profile_points` points
/// `(a, b)` (2 doubles each; `a` along the frame's normal, `b` along its binormal),
/// `trajectory` holds `num_trajectory_points` points `(x, y, z)` (3 doubles each). Settings
/// (`options` may be NULL): `profsubd_options_set_samples` (profile intervals,
/// trajectory intervals; default 16, 32), `_set_sweep_closed`, `_set_sweep_frame`,
/// `_set_sweep_scale`, `_set_sweep_profile_end`, `_set_sweep_corners`, the
/// interpolation, sharp angle and crease sharpness, and the boundary
/// interpolation and crease method the surface is fitted under and tagged with. Errors:
/// `PROFSUBD_ERROR_INVALID_ARGUMENT` for bad curves or settings (coincident points, a
/// crossing profile, a frame that cannot be built, boundary interpolation none with an open
/// boundary...; the message says which), `PROFSUBD_ERROR_NUMERICAL` if the fit misses its
/// tolerance.
#[no_mangle]
pub unsafe extern "C" fn profsubd_sweep(
    profile: *const f64,
    num_profile_points: usize,
    trajectory: *const f64,
    num_trajectory_points: usize,
    options: *const profsubd_options,
    out: *mut *mut profsubd_fitted,
) -> profsubd_status {
    let read = || {
        Ok(SweepInput::new(
            tuples::<2>(profile, num_profile_points, "profile")?,
            tuples::<3>(trajectory, num_trajectory_points, "trajectory")?,
        ))
    };
    construct(out, options, read, build)
}
