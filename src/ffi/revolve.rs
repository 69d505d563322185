//! C API of revolutions: the profile as a caller array, settings on the options object
//! (`src/ffi/construct.rs`), the result a `profsubd_fitted`.

use crate::construct::revolve::{build, RevolveInput};
use crate::ffi::construct::{construct, tuples};
use crate::ffi::fitted::profsubd_fitted;
use crate::ffi::options::profsubd_options;
use crate::ffi::status::profsubd_status;

/// Build a surface of revolution: `profile` holds `num_points` points `(r, z)` (2 doubles
/// each), bottom to top, `r >= 0`; they are turned about the z axis. Settings (`options` may
/// be NULL): `profsubd_options_set_samples` (profile intervals, intervals around; default
/// 16, 32), `profsubd_options_set_revolve_angle` (default 360),
/// `profsubd_options_set_sweep_corners` (its profile list), the profile construction's
/// interpolation, sharp angle, crease sharpness and caps (`profsubd_options_set_caps`:
/// `PROFSUBD_CAPS_FLAT` closes the solid with flat caps, creased infinitely sharp where they
/// meet: discs or sectors at ends off the axis, and on a partial turn the start and end
/// meridian planes), and the boundary interpolation and crease method the model is fitted
/// under and tagged with (default edge-and-corner, uniform). Ends on the axis become smooth
/// poles (quad caps) or tips (corner-tagged); on a partial turn, sectors of quads with a
/// corner-tagged apex. Errors: `PROFSUBD_ERROR_INVALID_ARGUMENT` for a bad profile or
/// settings (also boundary interpolation none with an open boundary; the message says which),
/// `PROFSUBD_ERROR_NUMERICAL` if the fit misses its tolerance.
#[no_mangle]
pub unsafe extern "C" fn profsubd_revolve(
    profile: *const f64,
    num_points: usize,
    options: *const profsubd_options,
    out: *mut *mut profsubd_fitted,
) -> profsubd_status {
    let read = || {
        Ok(RevolveInput::new(tuples::<2>(
            profile, num_points, "profile",
        )?))
    };
    construct(out, options, read, build)
}
