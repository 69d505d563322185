//! Limit stencils through the C ABI: the exact limit position (or derivative) of every
//! control vertex as weights on the control vertices, in a stencil-table handle with count
//! getters, copy-outs (CSR arrays) and an apply function.

use crate::control::Control;
use crate::eval::vertex_limit::limit_stencils_with;
use crate::eval::{vertex_limit_stencils, StencilTable};
use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::handle::{self, Handle};
use crate::ffi::mesh::{mesh_arg, profsubd_mesh};
use crate::ffi::options::{options_or_default, profsubd_options, resolve};
use crate::ffi::panic::{guard, status_call};
use crate::ffi::ptr::{all_of, arg_out, arg_slice, copy_slice, fill, CopyOut};
use crate::ffi::status::profsubd_status;

/// Values for the `quantity` of `profsubd_limit_stencils_new` (passed as `int32_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum profsubd_limit_quantity {
    /// Limit position.
    PROFSUBD_LIMIT_POSITION = 0,
    /// Derivative with respect to u at the corner of the vertex's first face (OpenSubdiv's
    /// first face around the vertex that is not a hole).
    PROFSUBD_LIMIT_DU = 1,
    /// Derivative with respect to v at that corner.
    PROFSUBD_LIMIT_DV = 2,
}

/// A table of stencils (opaque, immutable, safe to share between threads): row `i` is a
/// weighted sum of control vertices. Create with `profsubd_limit_stencils_new`, release with
/// `profsubd_stencil_table_free`. Stored in compressed sparse rows: row `i` has the entries
/// `offsets[i] .. offsets[i + 1] - 1` of `indices` (control vertices) and `weights`.
pub struct profsubd_stencil_table {
    _private: [u8; 0],
}

impl Handle for profsubd_stencil_table {
    type Inner = StencilTable;
    const MAGIC: u64 = u64::from_le_bytes(*b"psd-STNC");
    const NAME: &'static str = "profsubd_stencil_table";
}

unsafe fn table_arg<'a>(p: *const profsubd_stencil_table) -> FfiResult<&'a StencilTable> {
    handle::borrow(p, "table")
}

/// Build the limit stencils of every control vertex of `mesh` under `options` (NULL: the
/// mesh's tags, then the defaults), one row per vertex in vertex order. `quantity` is
/// `PROFSUBD_LIMIT_POSITION` (the exact limit position, also at darts and semi-sharp
/// features), `PROFSUBD_LIMIT_DU` or `PROFSUBD_LIMIT_DV`. A vertex without limit surface
/// (isolated, or all its faces holes) has an empty row (`offsets[i] == offsets[i + 1]`),
/// which `profsubd_stencil_table_apply` turns into NaN; every other row has entries. Position
/// stencils are built on the threads `profsubd_options_set_threads` sets (default all cores),
/// the table the same for any.
#[no_mangle]
pub unsafe extern "C" fn profsubd_limit_stencils_new(
    mesh: *const profsubd_mesh,
    options: *const profsubd_options,
    quantity: i32,
    out: *mut *mut profsubd_stencil_table,
) -> profsubd_status {
    status_call(|| {
        let m = mesh_arg(mesh, "mesh")?;
        let out = arg_out(out, "out")?;
        let opts = resolve(options, m)?;
        let threads = options_or_default(options)?.threads;
        use profsubd_limit_quantity::*;
        let table = match quantity {
            q if q == PROFSUBD_LIMIT_POSITION as i32 => {
                limit_stencils_with(m, &opts, &Control::NONE.with_threads(threads))?
            }
            q if q == PROFSUBD_LIMIT_DU as i32 => vertex_limit_stencils(m, &opts)?.du,
            q if q == PROFSUBD_LIMIT_DV as i32 => vertex_limit_stencils(m, &opts)?.dv,
            q => {
                return Err(FfiError::invalid_argument(format!(
                    "limit quantity value {q} is out of range; expected 0, 1 or 2"
                )))
            }
        };
        out.write(handle::into_raw(table));
        Ok(())
    })
}

/// Release a stencil table (NULL is a no-op).
#[no_mangle]
pub unsafe extern "C" fn profsubd_stencil_table_free(table: *mut profsubd_stencil_table) {
    guard(|| handle::free(table))
}

/// Number of rows (stencils) of the table.
#[no_mangle]
pub unsafe extern "C" fn profsubd_stencil_table_num_rows(
    table: *const profsubd_stencil_table,
    out: *mut usize,
) -> profsubd_status {
    status_call(|| {
        let t = table_arg(table)?;
        arg_out(out, "out")?.write(t.num_rows());
        Ok(())
    })
}

/// Total number of (index, weight) entries of the table.
#[no_mangle]
pub unsafe extern "C" fn profsubd_stencil_table_num_entries(
    table: *const profsubd_stencil_table,
    out: *mut usize,
) -> profsubd_status {
    status_call(|| {
        let t = table_arg(table)?;
        arg_out(out, "out")?.write(t.num_entries());
        Ok(())
    })
}

/// Copy the row offsets (rows + 1 values, the last one the entry count) into `out`.
/// `capacity` and `*needed` count offsets (copy-out protocol).
#[no_mangle]
pub unsafe extern "C" fn profsubd_stencil_table_get_offsets(
    table: *const profsubd_stencil_table,
    out: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (table, "table"),
        (out, "out", capacity, needed),
        (1, "offsets"),
        |t| Ok(all_of(&t.offsets)),
    )
}

/// Copy the control vertex of every entry into `out`. `capacity` and `*needed` count
/// entries (copy-out protocol).
#[no_mangle]
pub unsafe extern "C" fn profsubd_stencil_table_get_indices(
    table: *const profsubd_stencil_table,
    out: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (table, "table"),
        (out, "out", capacity, needed),
        (1, "entries"),
        |t| Ok(all_of(&t.indices)),
    )
}

/// Copy the weight of every entry into `out`. `capacity` and `*needed` count entries
/// (copy-out protocol).
#[no_mangle]
pub unsafe extern "C" fn profsubd_stencil_table_get_weights(
    table: *const profsubd_stencil_table,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (table, "table"),
        (out, "out", capacity, needed),
        (1, "entries"),
        |t| Ok(all_of(&t.weights)),
    )
}

/// Apply every row to `points` (`num_points` points of 3 doubles, one per control vertex)
/// and write one point (3 doubles) per row into `out`; an empty row (no limit surface) gives
/// NaN. `capacity` and `*needed` count points
/// (copy-out protocol). Errors: `PROFSUBD_ERROR_INVALID_ARGUMENT` if a stencil refers to a
/// control vertex beyond `num_points`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_stencil_table_apply(
    table: *const profsubd_stencil_table,
    points: *const f64,
    num_points: usize,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    status_call(|| {
        let t = table_arg(table)?;
        let len = num_points.checked_mul(3).ok_or_else(|| {
            FfiError::invalid_argument(format!("num_points {num_points} is absurdly large"))
        })?;
        let flat = arg_slice(points, len, "points")?;
        let c = CopyOut::new(capacity, needed)?;
        let buf = c.buffer(out, 3, "out")?;
        let pts: Vec<glam::DVec3> = flat
            .chunks_exact(3)
            .map(|p| glam::DVec3::new(p[0], p[1], p[2]))
            .collect();
        let rows = t.num_rows();
        let result = if rows <= capacity {
            t.apply(&pts)?
        } else {
            Vec::new()
        };
        c.finish(rows, "points", || {
            fill(buf, result.iter().flat_map(|p| p.to_array()))
        })
    })
}

#[cfg(test)]
mod tests;
