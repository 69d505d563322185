//! Generalized B-spline (GBS) refinement through the C API.

use crate::ffi::mesh::{mesh_arg, new_mesh_handle, profsubd_mesh};
use crate::ffi::panic::status_call;
use crate::ffi::ptr::arg_out;
use crate::ffi::status::profsubd_status;
use crate::gbs::{refine_gbs, GbsOptions};

/// Refine `mesh` `level` times (0 to 8) with generalized B-spline subdivision of order
/// `order` (3..8) and level-0 tension `tension` (> −1; cos(π/n) makes n-column circles exact,
/// 1 polynomial splines); `*out` receives the refined mesh (faces and positions, no tags),
/// which the caller releases with `profsubd_mesh_free`.
///
/// Even orders split every face into quads in OpenSubdiv Far's vertex-first order (children
/// of the vertices, then of the faces, then of the edges; each parent face's quads in turn),
/// so a child is found from its parent exactly as in `profsubd_refine_uniform`; at order 4
/// and tension 1 the positions are Catmull–Clark's with edge-only boundaries. Odd orders
/// refine on the Doo–Sabin split: child face `f` is face `f`'s corners, then one quad per
/// interior edge, then one face per interior vertex. The mesh's infinitely sharp creases and
/// corners follow the curve rule (even orders only); boundaries are edge-only (even) or free
/// (odd).
///
/// Errors: `PROFSUBD_ERROR_NULL_ARGUMENT` (mesh or out NULL), `PROFSUBD_ERROR_INVALID_HANDLE`,
/// `PROFSUBD_ERROR_INVALID_ARGUMENT` for an order outside 3..8, a tension not finite or
/// ≤ −1, a level above 8 or a refined mesh above 2^26 face indices;
/// `PROFSUBD_ERROR_INVALID_MESH` for a non-manifold mesh, holes, semi-sharp tags, tags at odd
/// orders, or (odd orders) an inconsistently oriented mesh or an interior vertex of valence 2.
#[no_mangle]
pub unsafe extern "C" fn profsubd_gbs_refine(
    mesh: *const profsubd_mesh,
    order: u32,
    tension: f64,
    level: u32,
    out: *mut *mut profsubd_mesh,
) -> profsubd_status {
    status_call(|| {
        let m = mesh_arg(mesh, "mesh")?;
        let out = arg_out(out, "out")?;
        let refined = refine_gbs(m, &GbsOptions { order, tension }, level)?;
        out.write(new_mesh_handle(refined.to_mesh()?));
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::error::last_error;
    use crate::ffi::mesh::profsubd_mesh_free;
    use crate::mesh::Crease;
    use crate::test_support::unit_cube;

    /// The unit cube with `creases`, as a C handle.
    fn cube(creases: Vec<Crease>) -> *mut profsubd_mesh {
        new_mesh_handle(unit_cube(creases))
    }

    #[test]
    fn refines_a_cube_and_refuses_bad_arguments() {
        use profsubd_status::*;
        let mesh = cube(Vec::new());
        let sentinel = 0x10 as *mut profsubd_mesh;
        let mut out = sentinel;
        let call = |m, order, tension, level, out| unsafe {
            profsubd_gbs_refine(m, order, tension, level, out)
        };
        for (order, tension, level, status, says) in [
            (2, 1.0, 1, PROFSUBD_ERROR_INVALID_ARGUMENT, "order"),
            (9, 1.0, 1, PROFSUBD_ERROR_INVALID_ARGUMENT, "order"),
            (4, -1.0, 1, PROFSUBD_ERROR_INVALID_ARGUMENT, "tension"),
            (4, f64::NAN, 1, PROFSUBD_ERROR_INVALID_ARGUMENT, "tension"),
            (
                4,
                f64::INFINITY,
                1,
                PROFSUBD_ERROR_INVALID_ARGUMENT,
                "tension",
            ),
            (4, 1.0, 9, PROFSUBD_ERROR_INVALID_ARGUMENT, "level"),
        ] {
            assert_eq!(call(mesh, order, tension, level, &mut out), status);
            assert!(last_error().contains(says), "{}", last_error());
            assert_eq!(out, sentinel, "output untouched on error");
        }
        assert_eq!(
            call(std::ptr::null(), 4, 1.0, 1, &mut out),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert_eq!(
            call(mesh, 4, 1.0, 1, std::ptr::null_mut()),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert_eq!(out, sentinel);
        let creased = cube(vec![Crease {
            vertices: [0, 1],
            sharpness: 2.0,
        }]);
        assert_eq!(
            call(creased, 4, 1.0, 1, &mut out),
            PROFSUBD_ERROR_INVALID_MESH
        );
        assert!(
            last_error().contains("infinitely sharp"),
            "{}",
            last_error()
        );
        assert_eq!(out, sentinel);
        unsafe { profsubd_mesh_free(creased) };
        for (order, faces) in [(4, 24), (3, 26)] {
            assert_eq!(call(mesh, order, 0.5, 1, &mut out), PROFSUBD_OK);
            assert_eq!(last_error(), "");
            let refined = unsafe { mesh_arg(out, "out") }.unwrap();
            assert_eq!(refined.num_faces(), faces, "order {order}");
            unsafe { profsubd_mesh_free(out) };
            out = sentinel;
        }
        unsafe { profsubd_mesh_free(mesh) };
    }
}
