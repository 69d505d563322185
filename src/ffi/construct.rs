//! The construction settings of the options object: one setter per setting, each checked by
//! the Rust check of that setting ([`Settings`], [`RevolveInput::check_angle`],
//! [`SweepInput::check_scale`]), and how a construction's input takes them.
//!
//! `profsubd_options_set_boundary` and `profsubd_options_set_crease_method` (what the
//! surface is fitted under and tagged with) apply to the constructions too.

use crate::construct::curves::CurvesInput;
use crate::construct::profile::ProfileInput;
use crate::construct::revolve::RevolveInput;
use crate::construct::settings::Caps;
use crate::construct::sweep::frames::FrameKind;
use crate::construct::sweep::SweepInput;
use crate::construct::{Fitted, Settings};
use crate::curves::curve::MAX_CURVE_POINTS;
use crate::curves::Interpolation;
use crate::error::{Error, Result};
use crate::ffi::error::{enum_arg, FfiError, FfiResult};
use crate::ffi::fitted::{new_fitted_handle, profsubd_fitted};
use crate::ffi::handle;
use crate::ffi::options::{options_or_default, profsubd_options, OptionsData};
use crate::ffi::panic::status_call;
use crate::ffi::ptr::{arg_out, arg_slice};
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

/// Values for `profsubd_options_set_sweep_frame` (passed as `int32_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum profsubd_sweep_frame {
    /// Translation only: the start frame everywhere.
    PROFSUBD_FRAME_FIXED = 0,
    /// Frenet frame, carried over where the curvature vanishes, never flipping at inflections.
    PROFSUBD_FRAME_FRENET = 1,
    /// Rotation-minimizing frame (double reflection), closing twist spread (the default).
    PROFSUBD_FRAME_RMF = 2,
}

/// A construction input that takes the options' settings.
pub trait TakeOptions {
    /// Overwrite the fields the options set.
    fn take(&mut self, o: &OptionsData);
}

impl TakeOptions for ProfileInput {
    fn take(&mut self, o: &OptionsData) {
        if let Some([along, around]) = o.construct.samples {
            (self.along, self.around) = (along, around);
        }
    }
}

impl TakeOptions for RevolveInput {
    fn take(&mut self, o: &OptionsData) {
        let c = &o.construct;
        if let Some([a, b]) = c.samples {
            (self.samples_profile, self.samples_around) = (a as usize, b as usize);
        }
        self.angle_deg = c.angle_deg.unwrap_or(self.angle_deg);
        self.corners = c.corners[0].clone();
    }
}

impl TakeOptions for CurvesInput {
    fn take(&mut self, o: &OptionsData) {
        if let Some([nu, nv]) = o.construct.samples {
            self.samples = [nu as usize, nv as usize];
        }
    }
}

impl TakeOptions for SweepInput {
    fn take(&mut self, o: &OptionsData) {
        let c = &o.construct;
        if let Some([a, b]) = c.samples {
            (self.samples_profile, self.samples_trajectory) = (a as usize, b as usize);
        }
        [self.closed_profile, self.closed_trajectory] = c.closed;
        self.frame = c.frame.unwrap_or(self.frame);
        self.scale = c.scale.unwrap_or(self.scale);
        self.profile_end = c.profile_end.clone();
        self.corners.profile = c.corners[0].clone();
        self.corners.trajectory = c.corners[1].clone();
    }
}

/// The body of every construction's C entry point: `*out` = a new `profsubd_fitted` with
/// `build` of the input `read` gives, with the settings of `options` (NULL: none) applied.
pub unsafe fn construct<I: TakeOptions>(
    out: *mut *mut profsubd_fitted,
    options: *const profsubd_options,
    read: impl FnOnce() -> FfiResult<I>,
    build: fn(&I, &Settings) -> Result<Fitted>,
) -> profsubd_status {
    status_call(|| {
        let out = arg_out(out, "out")?;
        let mut input = read()?;
        let o = options_or_default(options)?;
        input.take(&o);
        out.write(new_fitted_handle(build(&input, &o.settings())?));
        Ok(())
    })
}

/// `n` points of `N` doubles at `p`.
pub unsafe fn tuples<const N: usize>(
    p: *const f64,
    n: usize,
    name: &str,
) -> FfiResult<Vec<[f64; N]>> {
    if n > MAX_CURVE_POINTS {
        // Before reading (or copying) the caller's array.
        return Err(Error::LimitExceeded(format!(
            "{name}: {n} points, above the limit of {MAX_CURVE_POINTS}"
        ))
        .into());
    }
    let len = n
        .checked_mul(N)
        .ok_or_else(|| FfiError::invalid_argument(format!("{name}: {n} points is absurd")))?;
    Ok(arg_slice(p, len, name)?
        .chunks_exact(N)
        .map(|c| std::array::from_fn(|i| c[i]))
        .collect())
}

/// `n` point indices at `p`.
pub unsafe fn indices(p: *const u32, n: usize, name: &str) -> FfiResult<Vec<usize>> {
    Ok(arg_slice(p, n, name)?.iter().map(|&i| i as usize).collect())
}

unsafe fn set(
    options: *mut profsubd_options,
    apply: impl FnOnce(&mut OptionsData) -> FfiResult<()>,
) -> profsubd_status {
    status_call(|| apply(handle::borrow_mut(options, "options")?))
}

/// Set the sample intervals: along the profile (a profile model's rings, a revolution's or
/// sweep's profile intervals), and around the axis (a profile model's meridians, a
/// revolution's intervals around) or along the trajectory (a sweep); each 1 to 4096. The
/// build checks the rest (a multiple of 4 around a profile model or a smooth pole, the
/// product at most 4,000,000, ...). Defaults: 12 and 16 for a profile model, 16 and 32 for
/// revolutions and sweeps.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_samples(
    options: *mut profsubd_options,
    along_profile: u32,
    around_or_along_path: u32,
) -> profsubd_status {
    set(options, |o| {
        Settings::check_sample_count("samples along the profile", along_profile)?;
        Settings::check_sample_count("samples around or along the path", around_or_along_path)?;
        o.construct.samples = Some([along_profile, around_or_along_path]);
        Ok(())
    })
}

/// Set the corner angle in degrees, in (0, 180]: a curve turning by more is creased there.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_sharp_angle(
    options: *mut profsubd_options,
    degrees: f64,
) -> profsubd_status {
    set(options, |o| {
        Settings::check_sharp_angle(degrees)?;
        o.settings.sharp_angle_deg = degrees;
        Ok(())
    })
}

/// Set the sharpness of crease edges at corners: a finite number >= 0 (10 or more is
/// infinitely sharp, the default).
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_crease_sharpness(
    options: *mut profsubd_options,
    sharpness: f32,
) -> profsubd_status {
    set(options, |o| {
        Settings::check_crease_sharpness(sharpness)?;
        o.settings.crease_sharpness = sharpness;
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
    let table = [
        (PROFSUBD_INTERPOLATION_SPLINE as i32, Interpolation::Spline),
        (
            PROFSUBD_INTERPOLATION_POLYLINE as i32,
            Interpolation::Polyline,
        ),
    ];
    set(options, |o| {
        o.settings.interpolation = enum_arg("interpolation", interpolation, &table)?;
        Ok(())
    })
}

/// Set what closes ends that do not meet the axis (profile models, revolutions):
/// `PROFSUBD_CAPS_OPEN` or `PROFSUBD_CAPS_FLAT`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_caps(
    options: *mut profsubd_options,
    caps: i32,
) -> profsubd_status {
    use profsubd_caps::*;
    let table = [
        (PROFSUBD_CAPS_OPEN as i32, Caps::Open),
        (PROFSUBD_CAPS_FLAT as i32, Caps::Flat),
    ];
    set(options, |o| {
        o.settings.caps = enum_arg("caps", caps, &table)?;
        Ok(())
    })
}

/// Set the angle of a revolution in degrees, in (0, 360] (360: a closed full turn).
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_revolve_angle(
    options: *mut profsubd_options,
    degrees: f64,
) -> profsubd_status {
    set(options, |o| {
        RevolveInput::check_angle(degrees)?;
        o.construct.angle_deg = Some(degrees);
        Ok(())
    })
}

/// Set whether the sweep's profile and trajectory are closed (0 open, 1 closed; default 0).
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_sweep_closed(
    options: *mut profsubd_options,
    closed_profile: i32,
    closed_trajectory: i32,
) -> profsubd_status {
    let flag = [(0, false), (1, true)];
    set(options, |o| {
        o.construct.closed = [
            enum_arg("closed_profile", closed_profile, &flag)?,
            enum_arg("closed_trajectory", closed_trajectory, &flag)?,
        ];
        Ok(())
    })
}

/// Set the sweep's frame: `PROFSUBD_FRAME_FIXED`, `PROFSUBD_FRAME_FRENET` or
/// `PROFSUBD_FRAME_RMF`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_sweep_frame(
    options: *mut profsubd_options,
    frame: i32,
) -> profsubd_status {
    use profsubd_sweep_frame::*;
    let table = [
        (PROFSUBD_FRAME_FIXED as i32, FrameKind::Fixed),
        (PROFSUBD_FRAME_FRENET as i32, FrameKind::Frenet),
        (PROFSUBD_FRAME_RMF as i32, FrameKind::RotationMinimizing),
    ];
    set(options, |o| {
        o.construct.frame = Some(enum_arg("frame", frame, &table)?);
        Ok(())
    })
}

/// Set the profile's scale at the start and at the end of the trajectory (finite, > 0;
/// linear in between; default 1 and 1).
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_sweep_scale(
    options: *mut profsubd_options,
    start: f64,
    end: f64,
) -> profsubd_status {
    set(options, |o| {
        SweepInput::check_scale([start, end])?;
        o.construct.scale = Some([start, end]);
        Ok(())
    })
}

/// Set a second profile (`num_points` points `(a, b)`, 2 doubles each, copied) that the
/// profile morphs into along the trajectory; it must have as many points as the profile.
/// NULL with 0 points removes it.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_sweep_profile_end(
    options: *mut profsubd_options,
    points: *const f64,
    num_points: usize,
) -> profsubd_status {
    set(options, |o| {
        o.construct.profile_end = if points.is_null() && num_points == 0 {
            None
        } else {
            Some(tuples::<2>(points, num_points, "points")?)
        };
        Ok(())
    })
}

/// Set the point indices forced to be corners: `num_profile` indices of profile points
/// (revolutions and sweeps; for a revolution an end on the axis becomes a pointed pole) and
/// `num_trajectory` indices of trajectory points (sweeps). Copied; NULL with 0 clears a list.
/// Indices are checked when the surface is built.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_sweep_corners(
    options: *mut profsubd_options,
    profile_corners: *const u32,
    num_profile: usize,
    trajectory_corners: *const u32,
    num_trajectory: usize,
) -> profsubd_status {
    set(options, |o| {
        o.construct.corners = [
            indices(profile_corners, num_profile, "profile_corners")?,
            indices(trajectory_corners, num_trajectory, "trajectory_corners")?,
        ];
        Ok(())
    })
}

#[cfg(test)]
mod tests;
