//! The options object: an opaque handle with one setter per setting.
//!
//! Chosen over a struct with a size field for ABI evolution: a new setting is a new setter
//! (and a new field in [`OptionsData`]), so programs built against an older header keep
//! working unchanged and never see a layout change. Settings not set stay unset, so the
//! precedence rule holds: explicit option > the mesh file's tag > default.

use std::borrow::Cow;

use crate::construct::sweep::frames::FrameKind;
use crate::construct::Settings;
use crate::ffi::error::{enum_arg, FfiResult};
use crate::ffi::handle::{self, Handle};
use crate::ffi::panic::{guard, status_call};
use crate::ffi::ptr::arg_out;
use crate::ffi::status::profsubd_status;
use crate::mesh::Mesh;
use crate::options::{
    BoundaryInterpolation, CreaseMethod, PartialOptions, SubdivOptions, TriangleSubdivision,
};
use crate::refine::VertexOrder;

/// Values for `profsubd_options_set_boundary` (passed as `int32_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum profsubd_boundary {
    /// No boundary interpolation: faces on the boundary have no limit surface.
    PROFSUBD_BOUNDARY_NONE = 0,
    /// Boundary edges are infinitely sharp.
    PROFSUBD_BOUNDARY_EDGE_ONLY = 1,
    /// Boundary edges sharp, and boundary vertices with one face are sharp corners (the default).
    PROFSUBD_BOUNDARY_EDGE_AND_CORNER = 2,
}

/// Values for `profsubd_options_set_crease_method` (passed as `int32_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum profsubd_crease_method {
    /// Sharpness decreases by 1 per level (the default).
    PROFSUBD_CREASE_UNIFORM = 0,
    /// Chaikin's rule: child sharpness averages neighbouring crease sharpness.
    PROFSUBD_CREASE_CHAIKIN = 1,
}

/// Values for `profsubd_options_set_triangle_rule` (passed as `int32_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum profsubd_triangle_rule {
    /// The Catmull-Clark rule on triangles too (the default).
    PROFSUBD_TRIANGLES_CATMARK = 0,
    /// OpenSubdiv's smooth-triangle weights.
    PROFSUBD_TRIANGLES_SMOOTH = 1,
}

/// Subdivision and evaluation settings (opaque). Create with `profsubd_options_new`, release
/// with `profsubd_options_free`. Functions taking a `const profsubd_options *` accept NULL,
/// meaning "nothing set": the mesh's tags and the defaults apply.
pub struct profsubd_options {
    _private: [u8; 0],
}

/// What a `profsubd_options` handle holds: plain data, so that this module imports none of
/// the modules whose setters write it. Helpers adding settings add fields here.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct OptionsData {
    /// Subdivision rules set explicitly by the caller.
    pub subdiv: PartialOptions,
    /// The constructions' shared settings (their boundary and crease method are `subdiv`'s:
    /// see [`OptionsData::settings`]); setters in `src/ffi/construct.rs`.
    pub settings: Settings,
    /// The construction inputs' settings (sampling, revolution angle, sweep frame...).
    pub construct: ConstructOptions,
    /// Order of the child vertices of uniform refinement (`src/ffi/refine.rs`).
    pub order: VertexOrder,
    /// Threads for building evaluators and their batches of points (0: all cores).
    pub threads: usize,
}

/// The settings of the construction inputs an options object holds; unset ones take the
/// input's defaults.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ConstructOptions {
    /// Sample intervals along the profile, and around the axis (profile, revolution) or
    /// along the trajectory (sweep).
    pub samples: Option<[u32; 2]>,
    /// Revolution angle, degrees.
    pub angle_deg: Option<f64>,
    /// Whether the sweep's profile and trajectory are closed.
    pub closed: [bool; 2],
    /// Frame along the sweep's trajectory.
    pub frame: Option<FrameKind>,
    /// Profile scale at the start and end of the trajectory.
    pub scale: Option<[f64; 2]>,
    /// Profile the sweep morphs into.
    pub profile_end: Option<Vec<[f64; 2]>>,
    /// Point indices forced to be corners: profile, trajectory.
    pub corners: [Vec<usize>; 2],
}

impl OptionsData {
    /// The constructions' settings: those set, with the boundary interpolation and crease
    /// method set by `profsubd_options_set_boundary` / `_set_crease_method` (default
    /// otherwise).
    pub fn settings(&self) -> Settings {
        let d = Settings::default();
        Settings {
            boundary: self.subdiv.boundary.unwrap_or(d.boundary),
            crease_method: self.subdiv.crease_method.unwrap_or(d.crease_method),
            ..self.settings.clone()
        }
    }
}

/// The options behind `options`, or nothing set for NULL.
pub unsafe fn options_or_default<'a>(
    options: *const profsubd_options,
) -> FfiResult<Cow<'a, OptionsData>> {
    if options.is_null() {
        Ok(Cow::Owned(OptionsData::default()))
    } else {
        handle::borrow(options, "options").map(Cow::Borrowed)
    }
}

impl Handle for profsubd_options {
    type Inner = OptionsData;
    const MAGIC: u64 = u64::from_le_bytes(*b"psd-OPTS");
    const NAME: &'static str = "profsubd_options";
}

/// The subdivision options for `mesh`: those set in `options` (NULL: none), then the mesh's
/// tags, then the defaults.
pub unsafe fn resolve(options: *const profsubd_options, mesh: &Mesh) -> FfiResult<SubdivOptions> {
    let explicit = if options.is_null() {
        PartialOptions::default()
    } else {
        handle::borrow(options, "options")?.subdiv
    };
    Ok(explicit.over(mesh.options()).resolve())
}

/// Create an options object with nothing set; `*out` receives it.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_new(out: *mut *mut profsubd_options) -> profsubd_status {
    status_call(|| {
        arg_out(out, "out")?.write(handle::into_raw(OptionsData::default()));
        Ok(())
    })
}

/// Release an options object. NULL is a no-op.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_free(options: *mut profsubd_options) {
    guard(|| handle::free(options))
}

/// Set the boundary interpolation: `PROFSUBD_BOUNDARY_NONE`, `PROFSUBD_BOUNDARY_EDGE_ONLY` or
/// `PROFSUBD_BOUNDARY_EDGE_AND_CORNER`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_boundary(
    options: *mut profsubd_options,
    boundary: i32,
) -> profsubd_status {
    status_call(|| {
        let o = handle::borrow_mut(options, "options")?;
        use profsubd_boundary::*;
        let table = [
            (PROFSUBD_BOUNDARY_NONE as i32, BoundaryInterpolation::None),
            (
                PROFSUBD_BOUNDARY_EDGE_ONLY as i32,
                BoundaryInterpolation::EdgeOnly,
            ),
            (
                PROFSUBD_BOUNDARY_EDGE_AND_CORNER as i32,
                BoundaryInterpolation::EdgeAndCorner,
            ),
        ];
        o.subdiv.boundary = Some(enum_arg("boundary", boundary, &table)?);
        Ok(())
    })
}

/// Set the crease method: `PROFSUBD_CREASE_UNIFORM` or `PROFSUBD_CREASE_CHAIKIN`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_crease_method(
    options: *mut profsubd_options,
    method: i32,
) -> profsubd_status {
    status_call(|| {
        let o = handle::borrow_mut(options, "options")?;
        use profsubd_crease_method::*;
        let table = [
            (PROFSUBD_CREASE_UNIFORM as i32, CreaseMethod::Uniform),
            (PROFSUBD_CREASE_CHAIKIN as i32, CreaseMethod::Chaikin),
        ];
        o.subdiv.crease_method = Some(enum_arg("crease method", method, &table)?);
        Ok(())
    })
}

/// Set how many threads an evaluator built with these options (`profsubd_evaluator_new`)
/// uses for its build and its batches of points, and the constructions' fits (limit
/// stencils and solve) and `profsubd_refine_uniform` use: 0 (the default) for all cores, 1 for the calling thread only
/// (`profsubd_evaluator_set_threads` changes an evaluator's afterwards). Results are bit for
/// bit the same for every setting.
///
/// Errors: `PROFSUBD_ERROR_NULL_ARGUMENT` for a NULL `options`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_threads(
    options: *mut profsubd_options,
    threads: usize,
) -> profsubd_status {
    status_call(|| {
        let o = handle::borrow_mut(options, "options")?;
        o.threads = threads;
        o.settings.control = o.settings.control.clone().with_threads(threads);
        Ok(())
    })
}

/// Set the triangle rule: `PROFSUBD_TRIANGLES_CATMARK` or `PROFSUBD_TRIANGLES_SMOOTH`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_triangle_rule(
    options: *mut profsubd_options,
    rule: i32,
) -> profsubd_status {
    status_call(|| {
        let o = handle::borrow_mut(options, "options")?;
        use profsubd_triangle_rule::*;
        let table = [
            (
                PROFSUBD_TRIANGLES_CATMARK as i32,
                TriangleSubdivision::Catmark,
            ),
            (
                PROFSUBD_TRIANGLES_SMOOTH as i32,
                TriangleSubdivision::Smooth,
            ),
        ];
        o.subdiv.triangles = Some(enum_arg("triangle rule", rule, &table)?);
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::error::last_error;
    use crate::ffi::status::profsubd_status::*;
    use std::ptr::{null, null_mut};
    const BOUNDARY_NONE: i32 = profsubd_boundary::PROFSUBD_BOUNDARY_NONE as i32;
    const BOUNDARY_EDGE_ONLY: i32 = profsubd_boundary::PROFSUBD_BOUNDARY_EDGE_ONLY as i32;
    const CREASE_CHAIKIN: i32 = profsubd_crease_method::PROFSUBD_CREASE_CHAIKIN as i32;
    const TRIANGLES_SMOOTH: i32 = profsubd_triangle_rule::PROFSUBD_TRIANGLES_SMOOTH as i32;

    fn new_options() -> *mut profsubd_options {
        let mut o = null_mut();
        assert_eq!(unsafe { profsubd_options_new(&mut o) }, PROFSUBD_OK);
        assert!(!o.is_null());
        o
    }

    #[test]
    fn setters_store_explicit_values() {
        let o = new_options();
        unsafe {
            assert_eq!(
                handle::borrow(o, "o").unwrap().subdiv,
                PartialOptions::default()
            );
            assert_eq!(profsubd_options_set_boundary(o, BOUNDARY_NONE), PROFSUBD_OK);
            assert_eq!(
                profsubd_options_set_crease_method(o, CREASE_CHAIKIN),
                PROFSUBD_OK
            );
            assert_eq!(
                profsubd_options_set_triangle_rule(o, TRIANGLES_SMOOTH),
                PROFSUBD_OK
            );
            let expected = PartialOptions {
                boundary: Some(BoundaryInterpolation::None),
                crease_method: Some(CreaseMethod::Chaikin),
                triangles: Some(TriangleSubdivision::Smooth),
            };
            assert_eq!(handle::borrow(o, "o").unwrap().subdiv, expected);
            assert_eq!(
                profsubd_options_set_boundary(o, BOUNDARY_EDGE_ONLY),
                PROFSUBD_OK
            );
            assert_eq!(
                handle::borrow(o, "o").unwrap().subdiv.boundary,
                Some(BoundaryInterpolation::EdgeOnly)
            );
            profsubd_options_free(o);
        }
    }

    #[test]
    fn out_of_range_values_are_rejected_and_leave_the_setting_alone() {
        let o = new_options();
        unsafe {
            for v in [-1, 3, i32::MAX, i32::MIN] {
                assert_eq!(
                    profsubd_options_set_boundary(o, v),
                    PROFSUBD_ERROR_INVALID_ARGUMENT
                );
                assert_eq!(
                    last_error(),
                    format!("boundary value {v} is out of range; expected 0, 1 or 2")
                );
            }
            for v in [-1, 2, i32::MAX] {
                assert_eq!(
                    profsubd_options_set_crease_method(o, v),
                    PROFSUBD_ERROR_INVALID_ARGUMENT
                );
                assert_eq!(
                    profsubd_options_set_triangle_rule(o, v),
                    PROFSUBD_ERROR_INVALID_ARGUMENT
                );
            }
            assert_eq!(
                handle::borrow(o, "o").unwrap().subdiv,
                PartialOptions::default()
            );
            profsubd_options_free(o);
        }
    }

    #[test]
    fn null_and_foreign_handles_are_rejected() {
        unsafe {
            assert_eq!(
                profsubd_options_new(null_mut()),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(last_error(), "argument `out` is NULL");
            assert_eq!(
                profsubd_options_set_boundary(null_mut(), 0),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(
                profsubd_options_set_crease_method(null_mut(), 0),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(
                profsubd_options_set_triangle_rule(null_mut(), 0),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            let mut fake = [0u64; 4];
            let f = fake.as_mut_ptr().cast::<profsubd_options>();
            assert_eq!(
                profsubd_options_set_boundary(f, 0),
                PROFSUBD_ERROR_INVALID_HANDLE
            );
            assert_eq!(
                profsubd_options_set_crease_method(f, 0),
                PROFSUBD_ERROR_INVALID_HANDLE
            );
            assert_eq!(
                profsubd_options_set_triangle_rule(f, 0),
                PROFSUBD_ERROR_INVALID_HANDLE
            );
            profsubd_options_free(f);
            assert!(last_error().contains("not a live profsubd_options"));
            assert_eq!(fake, [0; 4]);
            profsubd_options_free(null_mut());
            assert!(resolve(f, &crate::test_support::quad_mesh()).is_err());
        }
    }

    #[test]
    fn resolve_applies_caller_then_mesh_then_default() {
        let mut parts = crate::test_support::quad_mesh().into_parts();
        parts.options.boundary = Some(BoundaryInterpolation::EdgeOnly);
        parts.options.crease_method = Some(CreaseMethod::Chaikin);
        let mesh = Mesh::from_parts(parts).unwrap();
        let o = new_options();
        unsafe {
            profsubd_options_set_boundary(o, BOUNDARY_NONE);
            let r = resolve(o, &mesh).unwrap();
            assert_eq!(r.boundary, BoundaryInterpolation::None);
            assert_eq!(r.crease_method, CreaseMethod::Chaikin);
            assert_eq!(r.triangles, TriangleSubdivision::Catmark);
            let r = resolve(null(), &mesh).unwrap();
            assert_eq!(r.boundary, BoundaryInterpolation::EdgeOnly);
            profsubd_options_free(o);
        }
    }
}
