//! C API of thin shells: offset evaluation at `(face, u, v)` points and the hollow solid
//! (a `profsubd_fitted`), both from a mesh handle and the offset's settings.

use crate::construct::shell::{build, OffsetSettings, OffsetSurface, ShellInput, Side};
use crate::eval::LimitSample;
use crate::ffi::construct::{construct, TakeOptions};
use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::evaluator::PointArgs;
use crate::ffi::fitted::profsubd_fitted;
use crate::ffi::mesh::{mesh_arg, profsubd_mesh};
use crate::ffi::options::{profsubd_options, resolve, OptionsData};
use crate::ffi::panic::status_call;
use crate::ffi::status::profsubd_status;

/// Bits of the `flags` of `profsubd_offset_evaluate` and `profsubd_shell`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum profsubd_offset_flags {
    /// Offset along the normal `S_u x S_v` (default: against it, inward).
    PROFSUBD_OFFSET_OUTWARD = 1,
    /// Accept an offset that folds instead of failing.
    PROFSUBD_OFFSET_ACCEPT_FOLDS = 2,
}

/// The offset settings of the C arguments.
fn settings(thickness: f64, level: u32, flags: i32) -> FfiResult<OffsetSettings> {
    use profsubd_offset_flags::*;
    let known = PROFSUBD_OFFSET_OUTWARD as i32 | PROFSUBD_OFFSET_ACCEPT_FOLDS as i32;
    if flags & !known != 0 {
        return Err(FfiError::invalid_argument(format!(
            "flags = {flags} has bits other than PROFSUBD_OFFSET_OUTWARD (1) and \
             PROFSUBD_OFFSET_ACCEPT_FOLDS (2)"
        )));
    }
    let s = OffsetSettings {
        thickness,
        side: if flags & PROFSUBD_OFFSET_OUTWARD as i32 != 0 {
            Side::Outward
        } else {
            Side::Inward
        },
        level,
        accept_folds: flags & PROFSUBD_OFFSET_ACCEPT_FOLDS as i32 != 0,
    };
    s.check()?;
    Ok(s)
}

/// A tolerance argument: 0 for none, else finite and > 0 (checked by the build).
fn tolerance_arg(t: f64) -> Option<f64> {
    (t != 0.0).then_some(t)
}

/// The offset `O = S - D` of `mesh`'s limit surface under `options` (NULL: the mesh's tags,
/// then the defaults) by `thickness` (> 0) at `n` points `(faces[i], u[i], v[i])` given in
/// `domain` (`PROFSUBD_DOMAIN_PTEX` or `_BFR`): `positions` (3 doubles a point) and, when
/// not NULL, `du` and `dv` (the offset's derivatives, in the domain's units) and
/// `has_surface` (0 where there is no limit surface: NaN written). The crust is built on
/// the surface refined `level` times (0 to 6; 0: the paper's scheme), or with a positive
/// `tolerance` (model units) at the lowest level from `level` on whose measured thickness is within
/// it of `thickness` (0: no tolerance). `flags`: `PROFSUBD_OFFSET_OUTWARD`,
/// `PROFSUBD_OFFSET_ACCEPT_FOLDS`. The offset is built at each call (cost of an evaluator of
/// the refined mesh): batch the points on the evaluator's threads (all cores; the result
/// does not depend on them). Errors (nothing written): `PROFSUBD_ERROR_INVALID_ARGUMENT` for
/// thickness not > 0 or NaN, a bad level, flag or tolerance, a vertex without normal or a
/// crease too sharp to miter (naming the vertex), an offset that folds (naming where)
/// without `PROFSUBD_OFFSET_ACCEPT_FOLDS`, a bad point (naming its index);
/// `PROFSUBD_ERROR_NON_MANIFOLD` for a non-manifold mesh; `PROFSUBD_ERROR_NUMERICAL` for a
/// tolerance no level meets.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn profsubd_offset_evaluate(
    mesh: *const profsubd_mesh,
    options: *const profsubd_options,
    thickness: f64,
    level: u32,
    tolerance: f64,
    flags: i32,
    domain: i32,
    faces: *const u32,
    u: *const f64,
    v: *const f64,
    n: usize,
    positions: *mut f64,
    du: *mut f64,
    dv: *mut f64,
    has_surface: *mut u8,
) -> profsubd_status {
    status_call(|| {
        let m = mesh_arg(mesh, "mesh")?;
        let opts = resolve(options, m)?;
        let s = settings(thickness, level, flags)?;
        let args = PointArgs::read(domain, faces, u, v, n, positions, du, dv, has_surface)?;
        let offset = match tolerance_arg(tolerance) {
            None => OffsetSurface::new(m, &opts, s)?,
            Some(t) => crate::construct::shell::offset_within(m, &opts, s, t)?.0,
        };
        let samples: Vec<Option<LimitSample>> = offset
            .evaluate_points(args.domain, args.faces, args.u, args.v)?
            .into_iter()
            .map(|o| o.map(|o| o.offset()))
            .collect();
        args.write(&samples);
        Ok(())
    })
}

impl TakeOptions for ShellInput {
    /// The shell takes its subdivision options from the mesh's tags.
    fn take(&mut self, _: &OptionsData) {}
}

/// Build the hollow solid of `mesh` (manifold; its tags give the subdivision options): the
/// outer wall (the mesh refined `level` times, same limit surface), the inner wall at the
/// offset by `thickness` (same topology, faces reversed), and for open surfaces a rim of
/// quads creased infinitely sharp where it meets the walls, fitted so that its limit
/// passes through the outer limit and the offset at every vertex (`profsubd_fitted_get_targets`).
/// `level`, `tolerance` and `flags` as in `profsubd_offset_evaluate`; `options` may be
/// NULL (the construction settings do not apply). Errors: those of
/// `profsubd_offset_evaluate`'s offset; `PROFSUBD_ERROR_NUMERICAL` if the fit misses its
/// tolerance.
#[no_mangle]
pub unsafe extern "C" fn profsubd_shell(
    mesh: *const profsubd_mesh,
    thickness: f64,
    level: u32,
    tolerance: f64,
    flags: i32,
    options: *const profsubd_options,
    out: *mut *mut profsubd_fitted,
) -> profsubd_status {
    let read = || {
        Ok(ShellInput {
            mesh: mesh_arg(mesh, "mesh")?.clone(),
            offset: settings(thickness, level, flags)?,
            tolerance: tolerance_arg(tolerance),
        })
    };
    construct(out, options, read, build)
}
