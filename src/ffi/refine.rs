//! Uniform refinement through the C API.

use crate::ffi::mesh::{mesh_arg, new_mesh_handle, profsubd_mesh};
use crate::ffi::options::{profsubd_options, resolve};
use crate::ffi::panic::status_call;
use crate::ffi::ptr::arg_out;
use crate::ffi::status::profsubd_status;
use crate::refine::refine_uniform;

/// Refine `mesh` uniformly `level` times (0 to 8) with Catmull-Clark; `*out` receives the
/// refined mesh, which the caller releases with `profsubd_mesh_free`.
///
/// `options` may be NULL: the mesh's tags and the defaults apply. The refined mesh is in
/// OpenSubdiv Far's order (`TopologyRefiner::RefineUniform`): vertices are the children of
/// the vertices, then of the faces, then of the edges; faces are the quads of each parent
/// face in turn; positions equal `PrimvarRefinerReal<double>::Interpolate`. It carries the
/// decayed crease and corner sharpness, the holes and the options used as tags.
///
/// Errors: `PROFSUBD_ERROR_NULL_ARGUMENT` (mesh or out NULL), `PROFSUBD_ERROR_INVALID_HANDLE`,
/// `PROFSUBD_ERROR_INVALID_ARGUMENT` for a level above 8 or a refined mesh above 2^26 face
/// indices (a memory bound), or an out-of-range option.
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
        let refined = refine_uniform(m, &opts, level)?;
        out.write(new_mesh_handle(refined));
        Ok(())
    })
}
