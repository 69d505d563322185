//! C API of revolutions and sweeps: curves as caller arrays, settings on the options object,
//! and a result object holding the fitted mesh and its data points.
//!
//! The profile construction's `profsubd_options_set_interpolation`,
//! `profsubd_options_set_sharp_angle` and `profsubd_options_set_crease_sharpness`, and the
//! subdivision options' `profsubd_options_set_boundary` and
//! `profsubd_options_set_crease_method` (what the surface is fitted under and tagged with),
//! apply here too; the setters below add the settings of revolutions and sweeps.

use crate::construct::sweep::frames::FrameKind;
use crate::construct::sweep::revolve::RevolveInput;
use crate::construct::sweep::sweep::SweepInput;
use crate::construct::sweep::{revolve, sweep, SweptSurface};
use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::fitted;
use crate::ffi::handle::{self, Handle};
use crate::ffi::mesh::profsubd_mesh;
use crate::ffi::options::{profsubd_options, OptionsData};
use crate::ffi::panic::{guard, status_call};
use crate::ffi::ptr::{arg_out, arg_slice};
use crate::ffi::status::profsubd_status;

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

/// Revolution and sweep settings held by an options object; unset ones take the documented
/// defaults (16 profile intervals, 32 around or along the trajectory, a full turn, open
/// curves, rotation-minimizing frame, scale 1, no end profile).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SweepSettings {
    /// Sample intervals along the profile and around the axis / along the trajectory.
    pub samples: Option<[u32; 2]>,
    /// Revolution angle, degrees.
    pub angle_deg: Option<f64>,
    /// Whether the profile and the trajectory are closed.
    pub closed: Option<[bool; 2]>,
    /// Frame along the trajectory.
    pub frame: Option<FrameKind>,
    /// Profile scale at the start and end of the trajectory.
    pub scale: Option<[f64; 2]>,
    /// Profile to morph into.
    pub profile_end: Option<Vec<[f64; 2]>>,
    /// Point indices forced to be corners: profile, trajectory.
    pub corners: [Vec<usize>; 2],
}

/// A built revolution or sweep (opaque): the fitted mesh and the data points. Release with
/// `profsubd_swept_free`.
pub struct profsubd_swept {
    _private: [u8; 0],
}

impl Handle for profsubd_swept {
    type Inner = SweptSurface;
    const MAGIC: u64 = u64::from_le_bytes(*b"psd-SWPT");
    const NAME: &'static str = "profsubd_swept";
}

/// `n` points of `N` doubles at `p`.
unsafe fn tuples<const N: usize>(p: *const f64, n: usize, name: &str) -> FfiResult<Vec<[f64; N]>> {
    let len = n
        .checked_mul(N)
        .ok_or_else(|| FfiError::invalid_argument(format!("{name}: {n} points is absurd")))?;
    Ok(arg_slice(p, len, name)?
        .chunks_exact(N)
        .map(|c| std::array::from_fn(|i| c[i]))
        .collect())
}

/// The options' settings (NULL: none).
unsafe fn settings(options: *const profsubd_options) -> FfiResult<Option<&'static OptionsData>> {
    if options.is_null() {
        return Ok(None);
    }
    handle::borrow(options, "options").map(Some)
}

/// Build a surface of revolution: `profile` holds `num_points` points `(r, z)` (2 doubles
/// each), bottom to top, `r >= 0`; they are turned about the z axis. Settings (`options` may
/// be NULL): `profsubd_options_set_sweep_samples` (profile intervals, intervals around; default
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
    out: *mut *mut profsubd_swept,
) -> profsubd_status {
    status_call(|| {
        let out = arg_out(out, "out")?;
        let mut input = RevolveInput::new(tuples::<2>(profile, num_points, "profile")?);
        if let Some(o) = settings(options)? {
            let (p, s) = (&o.profile, &o.sweep);
            input.interpolation = p.interpolation.unwrap_or(input.interpolation);
            input.sharp_angle_deg = p.sharp_angle_deg.unwrap_or(input.sharp_angle_deg);
            input.caps = p.caps.unwrap_or(input.caps);
            if let Some([a, b]) = s.samples {
                (input.samples_profile, input.samples_around) = (a as usize, b as usize);
            }
            input.angle_deg = s.angle_deg.unwrap_or(input.angle_deg);
            input.corners = s.corners[0].clone();
            input.crease_sharpness = p.crease_sharpness.unwrap_or(input.crease_sharpness);
            input.boundary = o.subdiv.boundary.unwrap_or(input.boundary);
            input.crease_method = o.subdiv.crease_method.unwrap_or(input.crease_method);
        }
        out.write(handle::into_raw(revolve(&input)?));
        Ok(())
    })
}

/// Sweep a planar profile along a trajectory: `profile` holds `num_profile_points` points
/// `(a, b)` (2 doubles each; `a` along the frame's normal, `b` along its binormal),
/// `trajectory` holds `num_trajectory_points` points `(x, y, z)` (3 doubles each). Settings
/// (`options` may be NULL): `profsubd_options_set_sweep_samples` (profile intervals,
/// trajectory intervals; default 16, 32), `_set_sweep_closed`, `_set_sweep_frame`,
/// `_set_sweep_scale`, `_set_sweep_profile_end`, `_set_sweep_corners`, the profile
/// construction's interpolation, sharp angle and crease sharpness, and the boundary
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
    out: *mut *mut profsubd_swept,
) -> profsubd_status {
    status_call(|| {
        let out = arg_out(out, "out")?;
        let mut input = SweepInput::new(
            tuples::<2>(profile, num_profile_points, "profile")?,
            tuples::<3>(trajectory, num_trajectory_points, "trajectory")?,
        );
        if let Some(o) = settings(options)? {
            let (p, s) = (&o.profile, &o.sweep);
            input.interpolation = p.interpolation.unwrap_or(input.interpolation);
            input.sharp_angle_deg = p.sharp_angle_deg.unwrap_or(input.sharp_angle_deg);
            if let Some([a, b]) = s.samples {
                (input.samples_profile, input.samples_trajectory) = (a as usize, b as usize);
            }
            if let Some([a, b]) = s.closed {
                (input.closed_profile, input.closed_trajectory) = (a, b);
            }
            input.frame = s.frame.unwrap_or(input.frame);
            input.scale = s.scale.unwrap_or(input.scale);
            input.profile_end = s.profile_end.clone();
            input.corners.profile = s.corners[0].clone();
            input.corners.trajectory = s.corners[1].clone();
            input.crease_sharpness = p.crease_sharpness.unwrap_or(input.crease_sharpness);
            input.boundary = o.subdiv.boundary.unwrap_or(input.boundary);
            input.crease_method = o.subdiv.crease_method.unwrap_or(input.crease_method);
        }
        out.write(handle::into_raw(sweep(&input)?));
        Ok(())
    })
}

/// Release a revolution or sweep. NULL is a no-op.
#[no_mangle]
pub unsafe extern "C" fn profsubd_swept_free(swept: *mut profsubd_swept) {
    guard(|| handle::free(swept))
}

/// A new mesh handle (caller-owned) with the fitted control mesh: quads, crease and corner
/// tags, option tags.
#[no_mangle]
pub unsafe extern "C" fn profsubd_swept_get_mesh(
    swept: *const profsubd_swept,
    out: *mut *mut profsubd_mesh,
) -> profsubd_status {
    fitted::get_mesh(swept, "swept", out)
}

/// Copy the data points: 3 doubles per control vertex, in vertex order; vertex `i`'s limit
/// position equals point `i`. `capacity` and `*needed` count doubles; copy-out protocol as
/// `profsubd_mesh_get_positions`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_swept_get_targets(
    swept: *const profsubd_swept,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    fitted::get_targets(swept, "swept", out, capacity, needed)
}

/// The fit's achieved residual (largest distance between a vertex's limit position and its
/// data point) and the tolerance it met (1e-10 × the data points' bounding-box diagonal).
/// Either output may be NULL.
#[no_mangle]
pub unsafe extern "C" fn profsubd_swept_get_fit_residual(
    swept: *const profsubd_swept,
    residual: *mut f64,
    tolerance: *mut f64,
) -> profsubd_status {
    fitted::get_fit_residual(swept, "swept", residual, tolerance)
}

/// The largest and mean distance from the limit surface to the design surface between the
/// data points, over the limit surface's bounding-box diagonal: the limit and the design
/// surface sampled at the same 5 × 5 parameters per face (the design parameter bilinear
/// between the face's data points' parameters), measured along the design surface's
/// normal (see the README, "Valid surfaces"). Computed (with the fold check) on the first
/// call of this or `profsubd_swept_get_surface_quality`. Either output may be NULL.
#[no_mangle]
pub unsafe extern "C" fn profsubd_swept_get_design_distance(
    swept: *const profsubd_swept,
    max: *mut f64,
    mean: *mut f64,
) -> profsubd_status {
    fitted::get_design_distance(swept, "swept", max, mean)
}

/// The number of control faces whose limit surface folds (the fold check's criterion, `eval::folds`,
/// with default settings), the worst normal reversal in degrees (above 90 where it folds)
/// and the undulation: the limit surface's bending energy over the design surface's
/// (1 = as fair as the design). Any output may be NULL.
#[no_mangle]
pub unsafe extern "C" fn profsubd_swept_get_surface_quality(
    swept: *const profsubd_swept,
    folded_faces: *mut usize,
    worst_reversal_deg: *mut f64,
    undulation: *mut f64,
) -> profsubd_status {
    fitted::get_surface_quality(swept, "swept", folded_faces, worst_reversal_deg, undulation)
}

unsafe fn set(
    options: *mut profsubd_options,
    apply: impl FnOnce(&mut SweepSettings) -> FfiResult<()>,
) -> profsubd_status {
    status_call(|| apply(&mut handle::borrow_mut(options, "options")?.sweep))
}

/// Set the sample intervals: along the profile, and around the axis (revolution) or along
/// the trajectory (sweep); each 1 to 4096 (the build checks the rest: a multiple of 4 around a
/// smooth pole, ...).
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_sweep_samples(
    options: *mut profsubd_options,
    samples_profile: u32,
    samples_path: u32,
) -> profsubd_status {
    set(options, |s| {
        if !(1..=4096).contains(&samples_profile) || !(1..=4096).contains(&samples_path) {
            return Err(FfiError::invalid_argument(format!(
                "sweep samples {samples_profile}, {samples_path} must each be between 1 and 4096"
            )));
        }
        s.samples = Some([samples_profile, samples_path]);
        Ok(())
    })
}

/// Set the angle of a revolution in degrees, in (0, 360] (360: a closed full turn).
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_revolve_angle(
    options: *mut profsubd_options,
    degrees: f64,
) -> profsubd_status {
    set(options, |s| {
        if !(degrees > 0.0 && degrees <= 360.0) {
            return Err(FfiError::invalid_argument(format!(
                "revolve angle {degrees} must be in (0, 360] degrees"
            )));
        }
        s.angle_deg = Some(degrees);
        Ok(())
    })
}

fn flag(value: i32, name: &str) -> FfiResult<bool> {
    match value {
        0 => Ok(false),
        1 => Ok(true),
        v => Err(FfiError::invalid_argument(format!(
            "{name} value {v} is out of range; expected 0 or 1"
        ))),
    }
}

/// Set whether the sweep's profile and trajectory are closed (0 open, 1 closed; default 0).
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_sweep_closed(
    options: *mut profsubd_options,
    closed_profile: i32,
    closed_trajectory: i32,
) -> profsubd_status {
    set(options, |s| {
        s.closed = Some([
            flag(closed_profile, "closed_profile")?,
            flag(closed_trajectory, "closed_trajectory")?,
        ]);
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
    set(options, |s| {
        s.frame = Some(match frame {
            v if v == PROFSUBD_FRAME_FIXED as i32 => FrameKind::Fixed,
            v if v == PROFSUBD_FRAME_FRENET as i32 => FrameKind::Frenet,
            v if v == PROFSUBD_FRAME_RMF as i32 => FrameKind::RotationMinimizing,
            v => {
                return Err(FfiError::invalid_argument(format!(
                    "frame value {v} is out of range; expected 0, 1 or 2"
                )))
            }
        });
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
    set(options, |s| {
        if !(start.is_finite() && end.is_finite() && start > 0.0 && end > 0.0) {
            return Err(FfiError::invalid_argument(format!(
                "sweep scale {start}, {end}: both must be finite and positive"
            )));
        }
        s.scale = Some([start, end]);
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
    set(options, |s| {
        s.profile_end = if points.is_null() && num_points == 0 {
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
    set(options, |s| {
        let list = |p: *const u32, n: usize, name: &str| -> FfiResult<Vec<usize>> {
            Ok(arg_slice(p, n, name)?.iter().map(|&i| i as usize).collect())
        };
        s.corners = [
            list(profile_corners, num_profile, "profile_corners")?,
            list(trajectory_corners, num_trajectory, "trajectory_corners")?,
        ];
        Ok(())
    })
}

#[cfg(test)]
#[path = "sweep_tests.rs"]
mod tests;
