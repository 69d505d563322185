//! Uniform refinement through the C API, and its one setting (the child vertex order).

use crate::ffi::error::enum_arg;
use crate::ffi::handle;
use crate::ffi::mesh::{mesh_arg, new_mesh_handle, profsubd_mesh};
use crate::ffi::options::{options_or_default, profsubd_options, resolve};
use crate::ffi::panic::status_call;
use crate::ffi::ptr::arg_out;
use crate::ffi::status::profsubd_status;
use crate::refine::{refine_uniform_with, VertexOrder};

/// Values for `profsubd_options_set_vertex_order` (passed as `int32_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum profsubd_vertex_order {
    /// Children of vertices, then of faces, then of edges (Far's default; the default).
    PROFSUBD_ORDER_VERTICES_FIRST = 0,
    /// Children of faces, then of edges, then of vertices (Far's `orderVerticesFromFacesFirst`).
    PROFSUBD_ORDER_FACES_FIRST = 1,
}

/// Set the order of the vertices of refined meshes (`PROFSUBD_ORDER_VERTICES_FIRST`, the
/// default, or `PROFSUBD_ORDER_FACES_FIRST`). Errors: `PROFSUBD_ERROR_NULL_ARGUMENT`,
/// `PROFSUBD_ERROR_INVALID_HANDLE`, `PROFSUBD_ERROR_INVALID_ARGUMENT` for another value
/// (the setting is then unchanged).
#[no_mangle]
pub unsafe extern "C" fn profsubd_options_set_vertex_order(
    options: *mut profsubd_options,
    order: i32,
) -> profsubd_status {
    status_call(|| {
        let o = handle::borrow_mut(options, "options")?;
        use profsubd_vertex_order::*;
        let table = [
            (
                PROFSUBD_ORDER_VERTICES_FIRST as i32,
                VertexOrder::VerticesFirst,
            ),
            (PROFSUBD_ORDER_FACES_FIRST as i32, VertexOrder::FacesFirst),
        ];
        o.order = enum_arg("vertex order", order, &table)?;
        Ok(())
    })
}

/// Refine `mesh` uniformly `level` times (0 to 8) with Catmull-Clark; `*out` receives the
/// refined mesh, which the caller releases with `profsubd_mesh_free`.
///
/// `options` may be NULL: the mesh's tags and the defaults apply. The refined mesh is in
/// OpenSubdiv Far's order (`TopologyRefiner::RefineUniform`): vertices are the children of
/// the vertices, then of the faces, then of the edges (or faces, edges, vertices with
/// `PROFSUBD_ORDER_FACES_FIRST`); faces are the quads of each parent face in turn; positions
/// equal `PrimvarRefinerReal<double>::Interpolate`. It carries the decayed crease and corner
/// sharpness, the holes and the options used as tags. The positions are computed on the
/// threads `profsubd_options_set_threads` sets (default all cores), bit for bit the same for
/// any count.
///
/// Errors: `PROFSUBD_ERROR_NULL_ARGUMENT` (mesh or out NULL), `PROFSUBD_ERROR_INVALID_HANDLE`,
/// `PROFSUBD_ERROR_INVALID_ARGUMENT` for a level above 8 or a refined mesh above 2^26 face
/// indices (a memory bound); the options' progress callback and memory budget apply
/// (`PROFSUBD_ERROR_CANCELLED`, `PROFSUBD_ERROR_LIMIT_EXCEEDED`).
#[no_mangle]
pub unsafe extern "C" fn profsubd_refine_uniform(
    mesh: *const profsubd_mesh,
    options: *const profsubd_options,
    level: u32,
    out: *mut *mut profsubd_mesh,
) -> profsubd_status {
    status_call(|| {
        let m = mesh_arg(mesh, "mesh")?;
        let out = arg_out(out, "out")?;
        let opts = resolve(options, m)?;
        let o = options_or_default(options)?;
        let refined = refine_uniform_with(m, &opts, level, o.order, &o.settings.control)?;
        out.write(new_mesh_handle(refined));
        Ok(())
    })
}
