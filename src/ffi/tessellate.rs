//! Tessellation of the limit surface through the C ABI (see [`crate::tessellate`]): a
//! tessellation handle built from an evaluator, with count getters, copy-outs and a writer
//! (STL, OFF, PLY, OBJ).

use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::evaluator::{evaluator_arg, profsubd_evaluator};
use crate::ffi::handle::{self, Handle};
use crate::ffi::panic::{guard, status_call};
use crate::ffi::ptr::{all_of, arg_out, arg_path, copy_slice};
use crate::ffi::status::profsubd_status;
use crate::io::surface::{write_surface_file, SurfaceFormat};
use crate::io::up_axis::UpAxis;
use crate::tessellate::{tessellate, Rate, TessellateOptions, Tessellation};

/// Values for the `format` of `profsubd_tessellation_write` (passed as `int32_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum profsubd_surface_format {
    /// Binary STL (triangles, `float` coordinates).
    PROFSUBD_FORMAT_STL = 0,
    /// ASCII STL.
    PROFSUBD_FORMAT_STL_ASCII = 1,
    /// OFF.
    PROFSUBD_FORMAT_OFF = 2,
    /// Binary PLY with per-vertex normals.
    PROFSUBD_FORMAT_PLY = 3,
    /// OBJ with normals (split along infinitely sharp creases).
    PROFSUBD_FORMAT_OBJ = 4,
}

/// Values for `up` (passed as `int32_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum profsubd_up_axis {
    /// Z up: coordinates unchanged.
    PROFSUBD_UP_Z = 0,
    /// Y up: `(x, y, z)` written as `(x, z, -y)`.
    PROFSUBD_UP_Y = 1,
}

/// A tessellated limit surface (opaque, immutable, safe to share between threads). Create
/// with `profsubd_tessellation_new_uniform` or `profsubd_tessellation_new_adaptive`, release
/// with `profsubd_tessellation_free`. Vertices lie on the limit surface; polygons are
/// counter-clockwise seen from the side `du x dv` points to.
pub struct profsubd_tessellation {
    _private: [u8; 0],
}

impl Handle for profsubd_tessellation {
    type Inner = Tessellation;
    const MAGIC: u64 = u64::from_le_bytes(*b"psd-TESS");
    const NAME: &'static str = "profsubd_tessellation";
}

unsafe fn tess_arg<'a>(p: *const profsubd_tessellation) -> FfiResult<&'a Tessellation> {
    handle::borrow(p, "tessellation")
}

unsafe fn build(
    ev: *const profsubd_evaluator,
    rate: Rate,
    max_rate: u32,
    quads: i32,
    out: *mut *mut profsubd_tessellation,
) -> profsubd_status {
    status_call(|| {
        let ev = evaluator_arg(ev)?;
        let out = arg_out(out, "out")?;
        let options = TessellateOptions {
            rate,
            quads: quads != 0,
            max_rate,
        };
        out.write(handle::into_raw(tessellate(ev, &options)?));
        Ok(())
    })
}

/// Tessellate uniformly: `rate` x `rate` cells per quad, `ceil(rate / 2)` per sub-face of
/// an N-gon (1 <= rate <= 4096). `quads` non-zero keeps grid cells as quads. Errors:
/// `PROFSUBD_ERROR_INVALID_ARGUMENT` for a rate out of range or more than 2^24 cells in all
/// (checked before building).
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_new_uniform(
    evaluator: *const profsubd_evaluator,
    rate: u32,
    quads: i32,
    out: *mut *mut profsubd_tessellation,
) -> profsubd_status {
    build(evaluator, Rate::Uniform(rate), 64, quads, out)
}

/// Tessellate adaptively: no triangle farther than `tolerance` (model units, > 0) from the
/// limit surface at its check points, rates up to `max_rate` (1..=4096; faces that reach it
/// and still miss are counted by `profsubd_tessellation_num_unmet`). Errors:
/// `PROFSUBD_ERROR_INVALID_ARGUMENT` for a tolerance that is not positive and finite, a
/// `max_rate` out of range, or rates that would make more than 2^24 cells in all.
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_new_adaptive(
    evaluator: *const profsubd_evaluator,
    tolerance: f64,
    max_rate: u32,
    quads: i32,
    out: *mut *mut profsubd_tessellation,
) -> profsubd_status {
    build(evaluator, Rate::Tolerance(tolerance), max_rate, quads, out)
}

/// Release a tessellation (NULL is a no-op).
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_free(tessellation: *mut profsubd_tessellation) {
    guard(|| handle::free(tessellation))
}

/// Write counts: vertices, polygons, face-vertex entries, normals, parametric faces that
/// missed the tolerance at the maximum rate. Any output pointer may be NULL.
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_counts(
    tessellation: *const profsubd_tessellation,
    num_vertices: *mut usize,
    num_faces: *mut usize,
    num_face_vertices: *mut usize,
    num_normals: *mut usize,
    num_unmet: *mut usize,
) -> profsubd_status {
    status_call(|| {
        let t = tess_arg(tessellation)?;
        for (p, v) in [
            (num_vertices, t.num_vertices()),
            (num_faces, t.num_faces()),
            (num_face_vertices, t.face_vertices.len()),
            (num_normals, t.normals.len()),
            (num_unmet, t.unmet.len()),
        ] {
            if let Some(o) = crate::ffi::ptr::arg_out_opt(p, "count")? {
                o.write(v);
            }
        }
        Ok(())
    })
}

/// Copy the vertex positions (3 doubles per vertex). `capacity` and `*needed` count
/// vertices (copy-out protocol).
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_get_positions(
    tessellation: *const profsubd_tessellation,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (tessellation, "tessellation"),
        (out, "out", capacity, needed),
        (3, "vertices"),
        |t: &Tessellation| {
            Ok((
                t.positions.len(),
                t.positions.iter().flat_map(|p| p.to_array()),
            ))
        },
    )
}

/// Copy one unit normal per vertex (3 doubles; split normals averaged). `capacity` and
/// `*needed` count vertices.
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_get_vertex_normals(
    tessellation: *const profsubd_tessellation,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (tessellation, "tessellation"),
        (out, "out", capacity, needed),
        (3, "vertices"),
        |t: &Tessellation| {
            Ok((
                t.vertex_normals.len(),
                t.vertex_normals.iter().flat_map(|p| p.to_array()),
            ))
        },
    )
}

/// Copy the normals (3 doubles each), split along infinitely sharp creases; polygon
/// corners index them (`profsubd_tessellation_get_face_normals`). `capacity` and
/// `*needed` count normals.
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_get_normals(
    tessellation: *const profsubd_tessellation,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (tessellation, "tessellation"),
        (out, "out", capacity, needed),
        (3, "normals"),
        |t: &Tessellation| Ok((t.normals.len(), t.normals.iter().flat_map(|p| p.to_array()))),
    )
}

/// Copy the polygon sizes (3 or 4). `capacity` and `*needed` count polygons.
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_get_face_sizes(
    tessellation: *const profsubd_tessellation,
    out: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (tessellation, "tessellation"),
        (out, "out", capacity, needed),
        (1, "faces"),
        |t: &Tessellation| Ok(all_of(&t.face_sizes)),
    )
}

/// Copy the polygon vertex indices (0-based), polygon after polygon. `capacity` and
/// `*needed` count face-vertex entries.
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_get_face_vertices(
    tessellation: *const profsubd_tessellation,
    out: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (tessellation, "tessellation"),
        (out, "out", capacity, needed),
        (1, "face-vertex entries"),
        |t: &Tessellation| Ok(all_of(&t.face_vertices)),
    )
}

/// Copy the normal index of each polygon corner. `capacity` and `*needed` count
/// face-vertex entries.
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_get_face_normals(
    tessellation: *const profsubd_tessellation,
    out: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (tessellation, "tessellation"),
        (out, "out", capacity, needed),
        (1, "face-vertex entries"),
        |t: &Tessellation| Ok(all_of(&t.face_normals)),
    )
}

/// Copy the parametric (Ptex) face of each polygon. `capacity` and `*needed` count
/// polygons.
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_get_face_ptex(
    tessellation: *const profsubd_tessellation,
    out: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (tessellation, "tessellation"),
        (out, "out", capacity, needed),
        (1, "faces"),
        |t: &Tessellation| Ok(all_of(&t.face_ptex)),
    )
}

/// Copy the `(u, v)` of each polygon corner in its parametric face (2 doubles).
/// `capacity` and `*needed` count face-vertex entries.
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_get_corner_uv(
    tessellation: *const profsubd_tessellation,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (tessellation, "tessellation"),
        (out, "out", capacity, needed),
        (2, "face-vertex entries"),
        |t: &Tessellation| Ok((t.corner_uv.len(), t.corner_uv.iter().flat_map(|uv| *uv))),
    )
}

/// Copy where each vertex was evaluated: `face u v` as 3 doubles (the Ptex face as a
/// double, exact). `capacity` and `*needed` count vertices.
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_get_vertex_points(
    tessellation: *const profsubd_tessellation,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (tessellation, "tessellation"),
        (out, "out", capacity, needed),
        (3, "vertices"),
        |t: &Tessellation| {
            Ok((
                t.points.len(),
                t.points.iter().flat_map(|p| [p.face as f64, p.u, p.v]),
            ))
        },
    )
}

/// Write the tessellation to `path` in `format` (`PROFSUBD_FORMAT_*`) with `up`
/// (`PROFSUBD_UP_Z` or `PROFSUBD_UP_Y`). Errors: `PROFSUBD_ERROR_INVALID_ARGUMENT` for a
/// value out of range, `PROFSUBD_ERROR_IO` if the file cannot be written.
#[no_mangle]
pub unsafe extern "C" fn profsubd_tessellation_write(
    tessellation: *const profsubd_tessellation,
    path: *const std::ffi::c_char,
    format: i32,
    up: i32,
) -> profsubd_status {
    status_call(|| {
        let t = tess_arg(tessellation)?;
        let path = arg_path(path, "path")?;
        let format = match format {
            0 => SurfaceFormat::Stl,
            1 => SurfaceFormat::StlAscii,
            2 => SurfaceFormat::Off,
            3 => SurfaceFormat::Ply,
            4 => SurfaceFormat::Obj,
            f => {
                return Err(FfiError::invalid_argument(format!(
                    "format value {f} is out of range; expected 0..=4"
                )))
            }
        };
        let up = match up {
            0 => UpAxis::Z,
            1 => UpAxis::Y,
            u => {
                return Err(FfiError::invalid_argument(format!(
                    "up axis value {u} is out of range; expected 0 (z) or 1 (y)"
                )))
            }
        };
        write_surface_file(t, &path, format, up)?;
        Ok(())
    })
}

#[cfg(test)]
mod tests;
