//! C API of the profile construction: curves as caller arrays, settings on the options
//! object (`src/ffi/construct.rs`), the result a `profsubd_fitted`; and the built-in model.

use std::mem::size_of;
use std::sync::OnceLock;

use crate::construct::profile::{build, default_model, ProfileInput};
use crate::ffi::construct::{construct, indices, tuples};
use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::fitted::profsubd_fitted;
use crate::ffi::options::profsubd_options;
use crate::ffi::panic::status_call;
use crate::ffi::ptr::{arg_out, arg_out_opt, arg_ref};
use crate::ffi::status::profsubd_status;

/// The four silhouettes as caller arrays. Each curve is `N` points of 2 doubles `(w, z)`,
/// bottom to top: `w` is x for `c1` (+x side) and `c3` (−x side), y for `c2` (+y) and `c4`
/// (−y). `c3` / `c4` NULL with 0 points: the mirror of `c1` / `c2`. `cK_corners` lists point
/// indices forced to be corners (may be NULL when its count is 0). Zero-initialize, set
/// `struct_size`, then the arrays you have.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct profsubd_profile_curves {
    /// Must be `sizeof(profsubd_profile_curves)`.
    pub struct_size: usize,
    /// `2 * c1_points` doubles.
    pub c1: *const f64,
    /// Points of `c1` (at least 2).
    pub c1_points: usize,
    /// `2 * c2_points` doubles.
    pub c2: *const f64,
    /// Points of `c2` (at least 2).
    pub c2_points: usize,
    /// `2 * c3_points` doubles, or NULL for the mirror of `c1`.
    pub c3: *const f64,
    /// Points of `c3` (0: mirror of `c1`).
    pub c3_points: usize,
    /// `2 * c4_points` doubles, or NULL for the mirror of `c2`.
    pub c4: *const f64,
    /// Points of `c4` (0: mirror of `c2`).
    pub c4_points: usize,
    /// Forced corner point indices of `c1`.
    pub c1_corners: *const u32,
    /// Number of forced corners of `c1`.
    pub c1_num_corners: usize,
    /// Forced corner point indices of `c2`.
    pub c2_corners: *const u32,
    /// Number of forced corners of `c2`.
    pub c2_num_corners: usize,
    /// Forced corner point indices of `c3`.
    pub c3_corners: *const u32,
    /// Number of forced corners of `c3`.
    pub c3_num_corners: usize,
    /// Forced corner point indices of `c4`.
    pub c4_corners: *const u32,
    /// Number of forced corners of `c4`.
    pub c4_num_corners: usize,
}

/// `curves` is not NULL and its `struct_size` is ours.
unsafe fn check_struct_size(curves: *const profsubd_profile_curves) -> FfiResult<()> {
    let size = *arg_ref(curves.cast::<usize>(), "curves")?;
    let ours = size_of::<profsubd_profile_curves>();
    if size != ours {
        return Err(FfiError::invalid_argument(format!(
            "curves->struct_size is {size}; set it to sizeof(profsubd_profile_curves) ({ours})"
        )));
    }
    Ok(())
}

unsafe fn read_input(curves: *const profsubd_profile_curves) -> FfiResult<ProfileInput> {
    check_struct_size(curves)?;
    let c = &*curves;
    let mut input = ProfileInput::new(
        tuples::<2>(c.c1, c.c1_points, "c1")?,
        tuples::<2>(c.c2, c.c2_points, "c2")?,
    );
    if c.c3_points > 0 || !c.c3.is_null() {
        input.c3 = Some(tuples::<2>(c.c3, c.c3_points, "c3")?);
    }
    if c.c4_points > 0 || !c.c4.is_null() {
        input.c4 = Some(tuples::<2>(c.c4, c.c4_points, "c4")?);
    }
    input.corners.c1 = indices(c.c1_corners, c.c1_num_corners, "c1_corners")?;
    input.corners.c2 = indices(c.c2_corners, c.c2_num_corners, "c2_corners")?;
    input.corners.c3 = indices(c.c3_corners, c.c3_num_corners, "c3_corners")?;
    input.corners.c4 = indices(c.c4_corners, c.c4_num_corners, "c4_corners")?;
    Ok(input)
}

/// Build a profile model: blend the sweeps of the four curves, sample data points, build
/// the quad cage (pole caps, tips, creases) and fit it so that the exact limit surface
/// passes through every data point. `options` may be NULL (defaults): samples
/// (`profsubd_options_set_samples`: rings along, meridians around; a multiple of 4 around),
/// sharp angle, crease sharpness, interpolation, caps, and the boundary interpolation and
/// crease method the model is fitted under and tagged with (default edge-and-corner and
/// uniform; the triangle rule does not apply to the all-quad mesh). Errors:
/// `PROFSUBD_ERROR_INVALID_ARGUMENT` for bad curves or settings (fewer than 2 points, NaN,
/// curves running top to bottom, a curve crossing the axis, unequal pole heights, boundary
/// interpolation none with an open end, whose data points no limit surface reaches, ...; the
/// message says which), `PROFSUBD_ERROR_NUMERICAL` if the fit misses its tolerance.
#[no_mangle]
pub unsafe extern "C" fn profsubd_profile_build(
    curves: *const profsubd_profile_curves,
    options: *const profsubd_options,
    out: *mut *mut profsubd_fitted,
) -> profsubd_status {
    construct(out, options, || read_input(curves), build)
}

/// The built-in model's curves as flat arrays, made once (immutable, shared by all threads).
fn default_curves() -> &'static (ProfileInput, [Vec<f64>; 2]) {
    static CURVES: OnceLock<(ProfileInput, [Vec<f64>; 2])> = OnceLock::new();
    CURVES.get_or_init(|| {
        let (input, _) = default_model();
        let flat = |c: &[[f64; 2]]| c.iter().flatten().copied().collect();
        let arrays = [flat(&input.c1), flat(&input.c2)];
        (input, arrays)
    })
}

/// The built-in model's curves (a bottle: `c1` and `c2`, `c3` and `c4` their mirrors, no
/// forced corners) into `*curves`, whose `struct_size` the caller sets; the arrays are owned
/// by the library and valid for the life of the program. `*along_profile` and
/// `*around` (either may be NULL) receive the model's samples (rings, meridians), to pass to
/// `profsubd_options_set_samples` for the model as built by
/// `profsubd_profile_build_default`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_profile_default_curves(
    curves: *mut profsubd_profile_curves,
    along_profile: *mut u32,
    around: *mut u32,
) -> profsubd_status {
    status_call(|| {
        check_struct_size(curves)?;
        let c = arg_out(curves, "curves")?;
        let (along, around) = (
            arg_out_opt(along_profile, "along_profile")?,
            arg_out_opt(around, "around")?,
        );
        let (input, [c1, c2]) = default_curves();
        c.write(profsubd_profile_curves {
            c1: c1.as_ptr(),
            c1_points: input.c1.len(),
            c2: c2.as_ptr(),
            c2_points: input.c2.len(),
            ..profsubd_profile_curves::empty()
        });
        if let Some(a) = along {
            a.write(input.along);
        }
        if let Some(a) = around {
            a.write(input.around);
        }
        Ok(())
    })
}

/// Build the built-in model (a bottle; its curves: `profsubd_profile_default_curves`) in one
/// call, as `profsubd_profile_build` does: `options` may be NULL; samples set in it replace
/// the model's (20 rings, 16 meridians), and its other settings apply as they do there.
#[no_mangle]
pub unsafe extern "C" fn profsubd_profile_build_default(
    options: *const profsubd_options,
    out: *mut *mut profsubd_fitted,
) -> profsubd_status {
    construct(out, options, || Ok(default_curves().0.clone()), build)
}

impl profsubd_profile_curves {
    /// No curves, `struct_size` set.
    fn empty() -> Self {
        profsubd_profile_curves {
            struct_size: size_of::<profsubd_profile_curves>(),
            c1: std::ptr::null(),
            c1_points: 0,
            c2: std::ptr::null(),
            c2_points: 0,
            c3: std::ptr::null(),
            c3_points: 0,
            c4: std::ptr::null(),
            c4_points: 0,
            c1_corners: std::ptr::null(),
            c1_num_corners: 0,
            c2_corners: std::ptr::null(),
            c2_num_corners: 0,
            c3_corners: std::ptr::null(),
            c3_num_corners: 0,
            c4_corners: std::ptr::null(),
            c4_num_corners: 0,
        }
    }
}

#[cfg(test)]
mod tests;
