//! C API of the profile construction: curves as caller arrays, settings on the options
//! object, and a result object holding the fitted mesh and its data points.

use std::mem::size_of;

use crate::construct::profile::{build, Caps, ProfileInput, ProfileModel};
use crate::curves::Interpolation;
use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::fitted;
use crate::ffi::handle::{self, Handle};
use crate::ffi::mesh::profsubd_mesh;
use crate::ffi::options::profsubd_options;
use crate::ffi::panic::{guard, status_call};
use crate::ffi::ptr::{arg_out, arg_ref, arg_slice};
use crate::ffi::status::profsubd_status;

/// Values for `profsubd_options_set_interpolation` (passed as `int32_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum profsubd_interpolation {
    /// C² cubic spline with chord-length parameter, broken at corners (the default).
    PROFSUBD_INTERPOLATION_SPLINE = 0,
    /// Straight segments between the points.
    PROFSUBD_INTERPOLATION_POLYLINE = 1,
}

/// Values for `profsubd_options_set_caps` (passed as `int32_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum profsubd_caps {
    /// Ends that do not meet the axis stay open boundaries (the default).
    PROFSUBD_CAPS_OPEN = 0,
    /// Such ends are closed by flat caps, creased where they meet the side.
    PROFSUBD_CAPS_FLAT = 1,
}

/// Profile settings held by an options object; unset ones take the documented defaults
/// (around 16, along 12, sharp angle 30°, infinitely sharp creases, spline, open ends).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ProfileSettings {
    /// Meridians.
    pub around: Option<u32>,
    /// Ring intervals.
    pub along: Option<u32>,
    /// Corner angle in degrees.
    pub sharp_angle_deg: Option<f64>,
    /// Crease sharpness.
    pub crease_sharpness: Option<f32>,
    /// Point interpolation.
    pub interpolation: Option<Interpolation>,
    /// End caps.
    pub caps: Option<Caps>,
}

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

/// A built profile model (opaque): the fitted mesh and the data points. Release with
/// `profsubd_profile_free`.
pub struct profsubd_profile {
    _private: [u8; 0],
}

impl Handle for profsubd_profile {
    type Inner = ProfileModel;
    const MAGIC: u64 = u64::from_le_bytes(*b"psd-PROF");
    const NAME: &'static str = "profsubd_profile";
}

unsafe fn points(p: *const f64, n: usize, name: &str) -> FfiResult<Vec<[f64; 2]>> {
    let len = n
        .checked_mul(2)
        .ok_or_else(|| FfiError::invalid_argument(format!("{name}_points {n} is absurd")))?;
    Ok(arg_slice(p, len, name)?
        .chunks_exact(2)
        .map(|c| [c[0], c[1]])
        .collect())
}

unsafe fn corners(p: *const u32, n: usize, name: &str) -> FfiResult<Vec<usize>> {
    Ok(arg_slice(p, n, name)?.iter().map(|&i| i as usize).collect())
}

unsafe fn read_input(
    curves: *const profsubd_profile_curves,
    options: *const profsubd_options,
) -> FfiResult<ProfileInput> {
    let size = *arg_ref(curves.cast::<usize>(), "curves")?;
    let ours = size_of::<profsubd_profile_curves>();
    if size != ours {
        return Err(FfiError::invalid_argument(format!(
            "curves->struct_size is {size}; set it to sizeof(profsubd_profile_curves) ({ours})"
        )));
    }
    let c = &*curves;
    let mut input = ProfileInput::new(
        points(c.c1, c.c1_points, "c1")?,
        points(c.c2, c.c2_points, "c2")?,
    );
    if c.c3_points > 0 || !c.c3.is_null() {
        input.c3 = Some(points(c.c3, c.c3_points, "c3")?);
    }
    if c.c4_points > 0 || !c.c4.is_null() {
        input.c4 = Some(points(c.c4, c.c4_points, "c4")?);
    }
    input.corners.c1 = corners(c.c1_corners, c.c1_num_corners, "c1_corners")?;
    input.corners.c2 = corners(c.c2_corners, c.c2_num_corners, "c2_corners")?;
    input.corners.c3 = corners(c.c3_corners, c.c3_num_corners, "c3_corners")?;
    input.corners.c4 = corners(c.c4_corners, c.c4_num_corners, "c4_corners")?;
    if !options.is_null() {
        let o = handle::borrow(options, "options")?;
        input.boundary = o.subdiv.boundary.unwrap_or(input.boundary);
        input.crease_method = o.subdiv.crease_method.unwrap_or(input.crease_method);
        let s = o.profile;
        input.around = s.around.unwrap_or(input.around);
        input.along = s.along.unwrap_or(input.along);
        input.sharp_angle_deg = s.sharp_angle_deg.unwrap_or(input.sharp_angle_deg);
        input.crease_sharpness = s.crease_sharpness.unwrap_or(input.crease_sharpness);
        input.interpolation = s.interpolation.unwrap_or(input.interpolation);
        input.caps = s.caps.unwrap_or(input.caps);
    }
    Ok(input)
}

/// Build a profile model: blend the sweeps of the four curves, sample data points, build
/// the quad cage (pole caps, tips, creases) and fit it so that the exact limit surface
/// passes through every data point. `options` may be NULL (defaults). The model is fitted
/// under, and tagged with, the options' boundary interpolation and crease method
/// (`profsubd_options_set_boundary`, `profsubd_options_set_crease_method`; default
/// edge-and-corner and uniform; the triangle rule does not apply to the all-quad mesh).
/// Errors: `PROFSUBD_ERROR_INVALID_ARGUMENT` for bad curves or settings (fewer than 2 points,
/// NaN, curves running top to bottom, a curve crossing the axis, unequal pole heights,
/// boundary interpolation none with an open end, whose data points no limit surface reaches,
/// ...; the message says which), `PROFSUBD_ERROR_NUMERICAL` if the fit misses its
/// tolerance.
#[no_mangle]
pub unsafe extern "C" fn profsubd_profile_build(
    curves: *const profsubd_profile_curves,
    options: *const profsubd_options,
    out: *mut *mut profsubd_profile,
) -> profsubd_status {
    status_call(|| {
        let out = arg_out(out, "out")?;
        let input = read_input(curves, options)?;
        out.write(handle::into_raw(build(&input)?));
        Ok(())
    })
}

/// Release a profile model. NULL is a no-op.
#[no_mangle]
pub unsafe extern "C" fn profsubd_profile_free(profile: *mut profsubd_profile) {
    guard(|| handle::free(profile))
}

/// A new mesh handle (caller-owned) with the model's fitted control mesh: quads, crease and
/// corner tags, option tags.
#[no_mangle]
pub unsafe extern "C" fn profsubd_profile_get_mesh(
    profile: *const profsubd_profile,
    out: *mut *mut profsubd_mesh,
) -> profsubd_status {
    fitted::get_mesh(profile, "profile", out)
}

/// Copy the data points: 3 doubles per control vertex, in vertex order; vertex `i`'s limit
/// position equals point `i`. `capacity` and `*needed` count doubles; copy-out protocol as
/// `profsubd_mesh_get_positions`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_profile_get_targets(
    profile: *const profsubd_profile,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    fitted::get_targets(profile, "profile", out, capacity, needed)
}

/// The fit's achieved residual (largest distance between a vertex's limit position and its
/// data point) and the tolerance it met (1e-10 × the data points' bounding-box diagonal).
/// Either output may be NULL.
#[no_mangle]
pub unsafe extern "C" fn profsubd_profile_get_fit_residual(
    profile: *const profsubd_profile,
    residual: *mut f64,
    tolerance: *mut f64,
) -> profsubd_status {
    fitted::get_fit_residual(profile, "profile", residual, tolerance)
}

/// The largest and mean distance from the limit surface to the design surface between the
/// data points, over the limit surface's bounding-box diagonal: the limit and the design
/// surface sampled at the same 5 × 5 parameters per face (the design parameter bilinear
/// between the face's data points' parameters), measured along the design surface's
/// normal (see the README, "Valid surfaces"). Computed (with the fold check) on the first
/// call of this or `profsubd_profile_get_surface_quality`. Either output may be NULL.
#[no_mangle]
pub unsafe extern "C" fn profsubd_profile_get_design_distance(
    profile: *const profsubd_profile,
    max: *mut f64,
    mean: *mut f64,
) -> profsubd_status {
    fitted::get_design_distance(profile, "profile", max, mean)
}

/// The number of control faces whose limit surface folds (the fold check's criterion, `eval::folds`,
/// with default settings), the worst normal reversal in degrees (above 90 where it folds)
/// and the undulation: the limit surface's bending energy over the design surface's
/// (1 = as fair as the design). Any output may be NULL.
#[no_mangle]
pub unsafe extern "C" fn profsubd_profile_get_surface_quality(
    profile: *const profsubd_profile,
    folded_faces: *mut usize,
    worst_reversal_deg: *mut f64,
    undulation: *mut f64,
) -> profsubd_status {
    fitted::get_surface_quality(
        profile,
        "profile",
        folded_faces,
        worst_reversal_deg,
        undulation,
    )
}

unsafe fn set(
    options: *mut profsubd_options,
    apply: impl FnOnce(&mut ProfileSettings) -> FfiResult<()>,
) -> profsubd_status {
    status_call(|| apply(&mut handle::borrow_mut(options, "options")?.profile))
}

/// Set the number of meridians (vertices per ring): a multiple of 4, 4 to 4096.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_around(
    options: *mut profsubd_options,
    around: u32,
) -> profsubd_status {
    set(options, |s| {
        if around < 4 || around % 4 != 0 || around > 4096 {
            return Err(FfiError::invalid_argument(format!(
                "around = {around} must be a multiple of 4 between 4 and 4096"
            )));
        }
        s.around = Some(around);
        Ok(())
    })
}

/// Set the number of ring intervals from bottom to top: 1 to 4096.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_along(
    options: *mut profsubd_options,
    along: u32,
) -> profsubd_status {
    set(options, |s| {
        if !(1..=4096).contains(&along) {
            return Err(FfiError::invalid_argument(format!(
                "along = {along} must be between 1 and 4096"
            )));
        }
        s.along = Some(along);
        Ok(())
    })
}

/// Set the corner angle in degrees, in (0, 180]: a curve turning by more is creased there.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_sharp_angle(
    options: *mut profsubd_options,
    degrees: f64,
) -> profsubd_status {
    set(options, |s| {
        if !(degrees > 0.0 && degrees <= 180.0) {
            return Err(FfiError::invalid_argument(format!(
                "sharp angle {degrees} must be in (0, 180] degrees"
            )));
        }
        s.sharp_angle_deg = Some(degrees);
        Ok(())
    })
}

/// Set the sharpness of crease edges at corners (profiles, revolutions and sweeps): a finite
/// number >= 0 (10 or more is infinitely sharp, the default).
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_crease_sharpness(
    options: *mut profsubd_options,
    sharpness: f32,
) -> profsubd_status {
    set(options, |s| {
        if !(sharpness.is_finite() && sharpness >= 0.0) {
            return Err(FfiError::invalid_argument(format!(
                "crease sharpness {sharpness} must be a finite number >= 0"
            )));
        }
        s.crease_sharpness = Some(sharpness);
        Ok(())
    })
}

/// Set how curve points are joined: `PROFSUBD_INTERPOLATION_SPLINE` or
/// `PROFSUBD_INTERPOLATION_POLYLINE`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_interpolation(
    options: *mut profsubd_options,
    interpolation: i32,
) -> profsubd_status {
    use profsubd_interpolation::*;
    set(options, |s| {
        s.interpolation = Some(match interpolation {
            v if v == PROFSUBD_INTERPOLATION_SPLINE as i32 => Interpolation::Spline,
            v if v == PROFSUBD_INTERPOLATION_POLYLINE as i32 => Interpolation::Polyline,
            v => {
                return Err(FfiError::invalid_argument(format!(
                    "interpolation value {v} is out of range; expected 0 or 1"
                )))
            }
        });
        Ok(())
    })
}

/// Set what closes ends that do not meet the axis: `PROFSUBD_CAPS_OPEN` or
/// `PROFSUBD_CAPS_FLAT`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_caps(
    options: *mut profsubd_options,
    caps: i32,
) -> profsubd_status {
    use profsubd_caps::*;
    set(options, |s| {
        s.caps = Some(match caps {
            v if v == PROFSUBD_CAPS_OPEN as i32 => Caps::Open,
            v if v == PROFSUBD_CAPS_FLAT as i32 => Caps::Flat,
            v => {
                return Err(FfiError::invalid_argument(format!(
                    "caps value {v} is out of range; expected 0 or 1"
                )))
            }
        });
        Ok(())
    })
}

#[cfg(test)]
#[path = "profile_tests.rs"]
mod tests;
