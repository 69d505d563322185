//! The evaluator handle: exact limit positions and derivatives at `(face, u, v)` points.

use std::mem::MaybeUninit;

use crate::eval::{Evaluator, LimitSample};
use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::handle::{self, Handle};
use crate::ffi::mesh::{mesh_arg, profsubd_mesh};
use crate::ffi::options::{profsubd_options, resolve};
use crate::ffi::panic::{guard, status_call};
use crate::ffi::ptr::{arg_out, arg_slice, fill, CopyOut};
use crate::ffi::status::profsubd_status;

/// An exact Catmull-Clark limit evaluator for one mesh and one set of options (opaque,
/// immutable, safe to share between threads). Create with `profsubd_evaluator_new`, release
/// with `profsubd_evaluator_free`.
///
/// Points are `(face, u, v)` with OpenSubdiv's Ptex parameterization: on a mesh of quads,
/// `face` is the face index and `(u, v)` in `[0, 1]²` has corner 0 at (0,0), corner 1 at
/// (1,0), corner 2 at (1,1), corner 3 at (0,1). A face with N != 4 vertices is N consecutive
/// parametric faces (sub-face k: (0,0) at vertex k, (1,0) at the middle of edge k -> k+1,
/// (1,1) at the face centre, (0,1) at the middle of edge k-1 -> k), as `Far::PtexIndices`
/// numbers them; `profsubd_evaluator_face_to_parametric` gives the numbers.
pub struct profsubd_evaluator {
    _private: [u8; 0],
}

impl Handle for profsubd_evaluator {
    type Inner = Evaluator;
    const MAGIC: u64 = u64::from_le_bytes(*b"psd-EVAL");
    const NAME: &'static str = "profsubd_evaluator";
}

unsafe fn evaluator_arg<'a>(p: *const profsubd_evaluator) -> FfiResult<&'a Evaluator> {
    handle::borrow(p, "evaluator")
}

/// Build an evaluator for `mesh` under `options` (NULL: the mesh's tags, then the defaults).
/// The mesh is copied: it may be freed afterwards. Cost: proportional to the mesh, plus a
/// little more around extraordinary vertices and semi-sharp features.
#[no_mangle]
pub unsafe extern "C" fn profsubd_evaluator_new(
    mesh: *const profsubd_mesh,
    options: *const profsubd_options,
    out: *mut *mut profsubd_evaluator,
) -> profsubd_status {
    status_call(|| {
        let m = mesh_arg(mesh, "mesh")?;
        let out = arg_out(out, "out")?;
        let opts = resolve(options, m)?;
        let ev = Evaluator::new(m, &opts)?;
        out.write(handle::into_raw(ev));
        Ok(())
    })
}

/// Release an evaluator (NULL is a no-op).
#[no_mangle]
pub unsafe extern "C" fn profsubd_evaluator_free(evaluator: *mut profsubd_evaluator) {
    guard(|| handle::free(evaluator))
}

/// Number of parametric (Ptex) faces: the valid range of `faces[i]` in
/// `profsubd_evaluator_evaluate` (equal to the face count on a mesh of quads).
#[no_mangle]
pub unsafe extern "C" fn profsubd_evaluator_num_parametric_faces(
    evaluator: *const profsubd_evaluator,
    out: *mut usize,
) -> profsubd_status {
    status_call(|| {
        let ev = evaluator_arg(evaluator)?;
        arg_out(out, "out")?.write(ev.num_parametric_faces());
        Ok(())
    })
}

/// The parametric faces of control face `face`: `*first` and `*count` (1 for a quad, N for
/// a face with N != 4 vertices, one per corner).
#[no_mangle]
pub unsafe extern "C" fn profsubd_evaluator_face_to_parametric(
    evaluator: *const profsubd_evaluator,
    face: u32,
    first: *mut u32,
    count: *mut u32,
) -> profsubd_status {
    status_call(|| {
        let ev = evaluator_arg(evaluator)?;
        let (first, count) = (arg_out(first, "first")?, arg_out(count, "count")?);
        let nf = ev.mesh().num_faces();
        if face as usize >= nf {
            return Err(FfiError::invalid_argument(format!(
                "face {face} is out of range; the mesh has {nf} faces"
            )));
        }
        let size = ev.mesh().face_sizes()[face as usize];
        first.write(ev.ptex_faces().first_of(face as usize));
        count.write(if size == 4 { 1 } else { size });
        Ok(())
    })
}

/// An optional output array of `n` points (3 doubles each).
unsafe fn optional_points<'a>(
    p: *mut f64,
    n: usize,
    name: &str,
) -> FfiResult<Option<&'a mut [MaybeUninit<f64>]>> {
    if p.is_null() {
        return Ok(None);
    }
    CopyOut::new(n, std::ptr::null_mut())?
        .buffer(p, 3, name)
        .map(Some)
}

fn write_points(
    dst: Option<&mut [MaybeUninit<f64>]>,
    samples: &[LimitSample],
    pick: impl Fn(&LimitSample) -> glam::DVec3,
) {
    if let Some(dst) = dst {
        fill(dst, samples.iter().flat_map(|s| pick(s).to_array()));
    }
}

/// Evaluate `n` points `(faces[i], u[i], v[i])`: limit position into `positions` (3 doubles
/// per point, x y z), and, when not NULL, the derivatives with respect to u into `du` and
/// with respect to v into `dv` (3 doubles per point each). The unit normal is
/// `normalize(du × dv)`.
///
/// Errors (`PROFSUBD_ERROR_INVALID_ARGUMENT`, message naming the point): a face out of range,
/// u or v outside [0, 1] or NaN, a hole face, a face without limit surface (boundary
/// interpolation "none"). Nothing is written on error.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn profsubd_evaluator_evaluate(
    evaluator: *const profsubd_evaluator,
    faces: *const u32,
    u: *const f64,
    v: *const f64,
    n: usize,
    positions: *mut f64,
    du: *mut f64,
    dv: *mut f64,
) -> profsubd_status {
    status_call(|| {
        let ev = evaluator_arg(evaluator)?;
        let faces = arg_slice(faces, n, "faces")?;
        let us = arg_slice(u, n, "u")?;
        let vs = arg_slice(v, n, "v")?;
        let pos = CopyOut::new(n, std::ptr::null_mut())?.buffer(positions, 3, "positions")?;
        let du = optional_points(du, n, "du")?;
        let dv = optional_points(dv, n, "dv")?;
        let samples = ev.evaluate_many(faces, us, vs)?;
        write_points(Some(pos), &samples, |s| s.position);
        write_points(du, &samples, |s| s.du);
        write_points(dv, &samples, |s| s.dv);
        Ok(())
    })
}

/// Exact limit position of every control vertex, in vertex order, into `positions` (3
/// doubles per vertex), and when not NULL the derivatives into `du` and `dv` (3 doubles per
/// vertex each, with respect to the (u, v) of the vertex's first face, as OpenSubdiv orders
/// faces around a vertex). `capacity` and `*needed` count vertices (copy-out protocol).
#[no_mangle]
pub unsafe extern "C" fn profsubd_evaluator_limit_vertices(
    evaluator: *const profsubd_evaluator,
    positions: *mut f64,
    du: *mut f64,
    dv: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    status_call(|| {
        let ev = evaluator_arg(evaluator)?;
        let c = CopyOut::new(capacity, needed)?;
        let pos = c.buffer(positions, 3, "positions")?;
        let du = optional_points(du, capacity, "du")?;
        let dv = optional_points(dv, capacity, "dv")?;
        let n = ev.mesh().num_vertices();
        let samples = if n <= capacity {
            ev.limit_vertices()?
        } else {
            Vec::new()
        };
        c.finish(n, "vertices", || {
            write_points(Some(pos), &samples, |s| s.position);
            write_points(du, &samples, |s| s.du);
            write_points(dv, &samples, |s| s.dv);
        })
    })
}

#[cfg(test)]
#[path = "evaluator_tests.rs"]
mod tests;
