//! The options object: an opaque handle with one setter per setting.
//!
//! Chosen over a struct with a size field for ABI evolution: a new setting is a new setter
//! (and a new field in [`OptionsData`]), so programs built against an older header keep
//! working unchanged and never see a layout change. Settings not set stay unset, so the
//! precedence rule holds: explicit option > the mesh file's tag > default.

use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::handle::{self, Handle};
use crate::ffi::panic::{guard, status_call};
use crate::ffi::ptr::arg_out;
use crate::ffi::status::profsubd_status;
use crate::mesh::Mesh;
use crate::options::{
    BoundaryInterpolation, CreaseMethod, PartialOptions, SubdivOptions, TriangleSubdivision,
};

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

/// What a `profsubd_options` handle holds. Helpers adding settings add fields here.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct OptionsData {
    /// Subdivision rules set explicitly by the caller.
    pub subdiv: PartialOptions,
    /// Profile construction settings (`src/ffi/profile.rs`).
    pub profile: crate::ffi::profile::ProfileSettings,
    /// Revolution and sweep settings (`src/ffi/sweep.rs`).
    pub sweep: crate::ffi::sweep::SweepSettings,
    /// Uniform refinement settings (`src/ffi/refine.rs`).
    pub refine: crate::ffi::refine::RefineSettings,
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

fn out_of_range(what: &str, value: i32, allowed: &str) -> FfiError {
    FfiError::invalid_argument(format!(
        "{what} value {value} is out of range; expected {allowed}"
    ))
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
        o.subdiv.boundary = Some(match boundary {
            v if v == PROFSUBD_BOUNDARY_NONE as i32 => BoundaryInterpolation::None,
            v if v == PROFSUBD_BOUNDARY_EDGE_ONLY as i32 => BoundaryInterpolation::EdgeOnly,
            v if v == PROFSUBD_BOUNDARY_EDGE_AND_CORNER as i32 => {
                BoundaryInterpolation::EdgeAndCorner
            }
            v => return Err(out_of_range("boundary", v, "0, 1 or 2")),
        });
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
        o.subdiv.crease_method = Some(match method {
            v if v == PROFSUBD_CREASE_UNIFORM as i32 => CreaseMethod::Uniform,
            v if v == PROFSUBD_CREASE_CHAIKIN as i32 => CreaseMethod::Chaikin,
            v => return Err(out_of_range("crease method", v, "0 or 1")),
        });
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
        o.subdiv.triangles = Some(match rule {
            v if v == PROFSUBD_TRIANGLES_CATMARK as i32 => TriangleSubdivision::Catmark,
            v if v == PROFSUBD_TRIANGLES_SMOOTH as i32 => TriangleSubdivision::Smooth,
            v => return Err(out_of_range("triangle rule", v, "0 or 1")),
        });
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
            assert!(resolve(f, &crate::ffi::mesh::tests::quad_mesh()).is_err());
        }
    }

    #[test]
    fn resolve_applies_caller_then_mesh_then_default() {
        let mut parts = crate::ffi::mesh::tests::quad_mesh().into_parts();
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
