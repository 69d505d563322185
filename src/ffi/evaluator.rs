//! The evaluator handle: exact limit positions and derivatives at `(face, u, v)` points.

use std::mem::MaybeUninit;

use glam::DVec3;

use crate::eval::evaluator::{BatchOutput, NoSurface};
use crate::eval::{require_surface, Domain, Evaluator, LimitSample};
use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::handle::{self, Handle};
use crate::ffi::mesh::{mesh_arg, profsubd_mesh};
use crate::ffi::options::{options_or_default, profsubd_options, resolve};
use crate::ffi::panic::{guard, status_call};
use crate::ffi::ptr::{arg_out, arg_slice, fill, CopyOut};
use crate::ffi::status::profsubd_status;

/// An exact Catmull-Clark limit evaluator for one mesh and one set of options (opaque; safe
/// to share between threads for evaluation; `profsubd_evaluator_update_positions` replaces
/// the control points' positions, keeping the topology). Create with `profsubd_evaluator_new`, release
/// with `profsubd_evaluator_free`.
///
/// Points are `(face, u, v)` with OpenSubdiv's Ptex parameterization: on a mesh of quads,
/// `face` is the face index and `(u, v)` in `[0, 1]²` has corner 0 at (0,0), corner 1 at
/// (1,0), corner 2 at (1,1), corner 3 at (0,1). A face with N != 4 vertices is N consecutive
/// parametric faces (sub-face k: (0,0) at vertex k, (1,0) at the middle of edge k -> k+1,
/// (1,1) at the face centre, (0,1) at the middle of edge k-1 -> k), as `Far::PtexIndices`
/// numbers them; `profsubd_evaluator_face_to_parametric` gives the numbers.
/// `profsubd_evaluator_evaluate_points` also takes Bfr's parameterization
/// (`PROFSUBD_DOMAIN_BFR`) and marks points without limit surface instead of failing.
pub struct profsubd_evaluator {
    _private: [u8; 0],
}

impl Handle for profsubd_evaluator {
    type Inner = Evaluator;
    const MAGIC: u64 = u64::from_le_bytes(*b"psd-EVAL");
    const NAME: &'static str = "profsubd_evaluator";
}

pub(crate) unsafe fn evaluator_arg<'a>(p: *const profsubd_evaluator) -> FfiResult<&'a Evaluator> {
    handle::borrow(p, "evaluator")
}

/// Build an evaluator for `mesh` under `options` (NULL: the mesh's tags, then the defaults).
/// The mesh is copied: it may be freed afterwards. Cost: proportional to the mesh, plus a
/// little more around extraordinary vertices and semi-sharp features; on the threads
/// `profsubd_options_set_threads` sets (default all cores), the result the same for any. The
/// options' progress callback and memory budget apply (`profsubd_options_set_progress`,
/// `_set_memory_budget`): `PROFSUBD_ERROR_CANCELLED`, `PROFSUBD_ERROR_LIMIT_EXCEEDED`.
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
        let o = options_or_default(options)?;
        let ev = Evaluator::build_on(m, &opts, o.threads, &o.settings.control)?;
        out.write(handle::into_raw(ev));
        Ok(())
    })
}

/// Replace the control points' positions: `xyz` holds `3 * n` doubles (x y z per control
/// vertex, in vertex order), `n` the mesh's vertex count. The evaluator then gives exactly
/// (bit for bit) what one built with these positions gives, for the cost of running its
/// stored stencils rather than a build: the topology (patches, refined neighbourhoods) is
/// kept. Not concurrently with other calls on the same evaluator.
///
/// Errors: `PROFSUBD_ERROR_INVALID_ARGUMENT` for `n` not the mesh's vertex count or a
/// non-finite coordinate, `PROFSUBD_ERROR_NULL_ARGUMENT` for a NULL `evaluator` or `xyz`.
/// The evaluator is unchanged on error.
#[no_mangle]
pub unsafe extern "C" fn profsubd_evaluator_update_positions(
    evaluator: *mut profsubd_evaluator,
    xyz: *const f64,
    n: usize,
) -> profsubd_status {
    status_call(|| {
        let ev = handle::borrow_mut(evaluator, "evaluator")?;
        let nv = ev.mesh().num_vertices();
        if n != nv {
            // Checked before `xyz` is read: `3 * n` doubles may not be there.
            return Err(FfiError::invalid_argument(format!(
                "{n} positions given for a mesh of {nv} vertices"
            )));
        }
        let flat = arg_slice(xyz, 3 * n, "xyz")?;
        let positions: Vec<DVec3> = flat.chunks_exact(3).map(DVec3::from_slice).collect();
        ev.set_positions(&positions)?;
        Ok(())
    })
}

/// Set how many threads `profsubd_evaluator_evaluate` and
/// `profsubd_evaluator_evaluate_points` use: `threads` = 0 (the default) for all cores, 1 for
/// the calling thread only (`profsubd_evaluator_update_positions` is one pass on the calling
/// thread). Results are bit for bit the same for every setting. Not concurrently with other
/// calls on the same evaluator.
///
/// Errors: `PROFSUBD_ERROR_NULL_ARGUMENT` for a NULL `evaluator`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_evaluator_set_threads(
    evaluator: *mut profsubd_evaluator,
    threads: usize,
) -> profsubd_status {
    status_call(|| {
        handle::borrow_mut(evaluator, "evaluator")?.set_threads(threads);
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

/// An optional output array of `n` items of `width` elements each.
pub(crate) unsafe fn optional_out<'a, T>(
    p: *mut T,
    n: usize,
    width: usize,
    name: &str,
) -> FfiResult<Option<&'a mut [MaybeUninit<T>]>> {
    if p.is_null() {
        return Ok(None);
    }
    CopyOut::new(n, std::ptr::null_mut())?
        .buffer(p, width, name)
        .map(Some)
}

/// An optional output array of `n` points (3 doubles each).
pub(crate) unsafe fn optional_points<'a>(
    p: *mut f64,
    n: usize,
    name: &str,
) -> FfiResult<Option<&'a mut [MaybeUninit<f64>]>> {
    optional_out(p, n, 3, name)
}

/// Values for the `domain` of `profsubd_evaluator_evaluate_points` (passed as `int32_t`):
/// how a point `(face, u, v)` is meant.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum profsubd_domain {
    /// OpenSubdiv's Ptex faces (`Far::PtexIndices`, `Far::PatchMap`): `face` is a parametric
    /// face (a quad is one, a face with N != 4 vertices N, one per corner), `(u, v)` in
    /// `[0, 1]²`. The domain of `profsubd_evaluator_evaluate`.
    PROFSUBD_DOMAIN_PTEX = 0,
    /// Bfr's base faces (`Bfr::SurfaceFactory`, `Bfr::Parameterization`): `face` is the
    /// control face; a quad has `(u, v)` in `[0, 1]²`, any other face (triangles too) N
    /// sub-faces of side 1/2 tiled row by row in ceil(sqrt(N)) columns, sub-face k (Ptex
    /// coordinates (s, t)) at `(k % columns + s / 2, k / columns + t / 2)`. Derivatives are
    /// with respect to these (u, v): twice the Ptex ones on a sub-face.
    PROFSUBD_DOMAIN_BFR = 1,
}

pub(crate) fn domain_arg(domain: i32) -> FfiResult<Domain> {
    use profsubd_domain::*;
    match domain {
        d if d == PROFSUBD_DOMAIN_PTEX as i32 => Ok(Domain::Ptex),
        d if d == PROFSUBD_DOMAIN_BFR as i32 => Ok(Domain::Bfr),
        d => Err(FfiError::invalid_argument(format!(
            "domain value {d} is out of range; expected 0 (PROFSUBD_DOMAIN_PTEX) or 1 \
             (PROFSUBD_DOMAIN_BFR)"
        ))),
    }
}

fn strict_arg(strict: i32) -> FfiResult<bool> {
    match strict {
        0 => Ok(false),
        1 => Ok(true),
        s => Err(FfiError::invalid_argument(format!(
            "strict value {s} is out of range; expected 0 or 1"
        ))),
    }
}

/// The arguments of a batch of points evaluated at `(faces[i], u[i], v[i])` in `domain` and
/// written as positions, optional derivatives and an optional has-surface mask: read and
/// checked in one place for every entry point that evaluates points (the evaluator's, the
/// offset's). Nothing is written until [`PointArgs::write`].
pub(crate) struct PointArgs<'a> {
    /// How the points are meant.
    pub domain: Domain,
    /// The points' faces.
    pub faces: &'a [u32],
    /// Their `u`.
    pub u: &'a [f64],
    /// Their `v`.
    pub v: &'a [f64],
    positions: &'a mut [MaybeUninit<f64>],
    du: Option<&'a mut [MaybeUninit<f64>]>,
    dv: Option<&'a mut [MaybeUninit<f64>]>,
    has_surface: Option<&'a mut [MaybeUninit<u8>]>,
}

impl<'a> PointArgs<'a> {
    /// Read the C arguments of `n` points (`positions` required, `du`, `dv`, `has_surface`
    /// may be NULL). Errors: a bad domain, a NULL input or `positions` with points to hold.
    #[allow(clippy::too_many_arguments)]
    pub(crate) unsafe fn read(
        domain: i32,
        faces: *const u32,
        u: *const f64,
        v: *const f64,
        n: usize,
        positions: *mut f64,
        du: *mut f64,
        dv: *mut f64,
        has_surface: *mut u8,
    ) -> FfiResult<PointArgs<'a>> {
        Ok(PointArgs {
            domain: domain_arg(domain)?,
            faces: arg_slice(faces, n, "faces")?,
            u: arg_slice(u, n, "u")?,
            v: arg_slice(v, n, "v")?,
            positions: CopyOut::new(n, std::ptr::null_mut())?.buffer(positions, 3, "positions")?,
            du: optional_points(du, n, "du")?,
            dv: optional_points(dv, n, "dv")?,
            has_surface: optional_out(has_surface, n, 1, "has_surface")?,
        })
    }

    /// Write one sample a point (`None`: NaN and has-surface 0).
    pub(crate) fn write(self, samples: &[Option<LimitSample>]) {
        write_marked(samples, self.positions, self.du, self.dv, self.has_surface);
    }

    /// The output arrays, for [`Evaluator::evaluate_batch`] to write into.
    fn output(self) -> PointsOut<'a> {
        PointsOut {
            positions: self.positions,
            du: self.du,
            dv: self.dv,
            has_surface: self.has_surface,
        }
    }
}

/// A batch's output arrays (a piece of them on each thread): what
/// [`Evaluator::evaluate_batch`] writes each sample into, once.
struct PointsOut<'a> {
    positions: &'a mut [MaybeUninit<f64>],
    du: Option<&'a mut [MaybeUninit<f64>]>,
    dv: Option<&'a mut [MaybeUninit<f64>]>,
    has_surface: Option<&'a mut [MaybeUninit<u8>]>,
}

/// Both parts of an optional output split after `n` items.
fn split_opt<T>(a: Option<&mut [T]>, n: usize) -> (Option<&mut [T]>, Option<&mut [T]>) {
    match a {
        Some(a) => {
            let (x, y) = a.split_at_mut(n);
            (Some(x), Some(y))
        }
        None => (None, None),
    }
}

/// `value`'s coordinates into point `k` of `dst`.
#[inline]
fn put3(dst: &mut [MaybeUninit<f64>], k: usize, value: DVec3) {
    for (d, x) in dst[3 * k..3 * k + 3].iter_mut().zip(value.to_array()) {
        d.write(x);
    }
}

impl BatchOutput for PointsOut<'_> {
    fn split(self, n: usize) -> (Self, Self) {
        let (p0, p1) = self.positions.split_at_mut(3 * n);
        let (du0, du1) = split_opt(self.du, 3 * n);
        let (dv0, dv1) = split_opt(self.dv, 3 * n);
        let (m0, m1) = split_opt(self.has_surface, n);
        (
            PointsOut {
                positions: p0,
                du: du0,
                dv: dv0,
                has_surface: m0,
            },
            PointsOut {
                positions: p1,
                du: du1,
                dv: dv1,
                has_surface: m1,
            },
        )
    }

    #[inline]
    fn put(&mut self, k: usize, sample: Option<LimitSample>) {
        let s = sample.unwrap_or(LimitSample::NO_SURFACE);
        put3(self.positions, k, s.position);
        if let Some(du) = self.du.as_deref_mut() {
            put3(du, k, s.du);
        }
        if let Some(dv) = self.dv.as_deref_mut() {
            put3(dv, k, s.dv);
        }
        if let Some(mask) = self.has_surface.as_deref_mut() {
            mask[k].write(u8::from(sample.is_some()));
        }
    }
}

/// Write the samples (`None`: NaN) and the has-surface mask into the caller's buffers.
pub(crate) fn write_marked(
    samples: &[Option<LimitSample>],
    pos: &mut [MaybeUninit<f64>],
    du: Option<&mut [MaybeUninit<f64>]>,
    dv: Option<&mut [MaybeUninit<f64>]>,
    has_surface: Option<&mut [MaybeUninit<u8>]>,
) {
    let plain: Vec<LimitSample> = samples
        .iter()
        .map(|s| s.unwrap_or(LimitSample::NO_SURFACE))
        .collect();
    write_points(Some(pos), &plain, |s| s.position);
    write_points(du, &plain, |s| s.du);
    write_points(dv, &plain, |s| s.dv);
    if let Some(mask) = has_surface {
        fill(mask, samples.iter().map(|s| u8::from(s.is_some())));
    }
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
/// interpolation "none"). Nothing is written on error. This is
/// `profsubd_evaluator_evaluate_points` with `PROFSUBD_DOMAIN_PTEX`, `strict` = 1 and no mask.
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
    profsubd_evaluator_evaluate_points(
        evaluator,
        profsubd_domain::PROFSUBD_DOMAIN_PTEX as i32,
        1,
        faces,
        u,
        v,
        n,
        positions,
        du,
        dv,
        std::ptr::null_mut(),
    )
}

/// Evaluate per-vertex data of `dim` doubles (a primvar: colours, UVs as vertex data,
/// displacements) at `n` points `(faces[i], u[i], v[i])` (Ptex domain, as
/// `profsubd_evaluator_evaluate`): `data` holds `dim * num_vertices` doubles, vertex after
/// vertex, `num_vertices` the mesh's vertex count; the limit values go into `values` and,
/// when not NULL, the derivatives with respect to u and v into `du` and `dv` (`dim` doubles
/// per point each). With `dim` = 3 and the control positions as `data` the result is bit for
/// bit `profsubd_evaluator_evaluate`'s. Cost: a pass over the evaluator's stored stencils
/// per three components, then the points; threads as `profsubd_evaluator_set_threads`.
///
/// Errors (`PROFSUBD_ERROR_INVALID_ARGUMENT`): `dim` 0, `num_vertices` not the mesh's
/// vertex count, a non-finite value in `data`, the point errors of
/// `profsubd_evaluator_evaluate` (message naming the point); `PROFSUBD_ERROR_NULL_ARGUMENT`
/// for a NULL `evaluator`, or a NULL `data`, `faces`, `u`, `v` or `values` with data to
/// hold. Nothing is written on error.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn profsubd_evaluator_evaluate_primvar(
    evaluator: *const profsubd_evaluator,
    data: *const f64,
    dim: usize,
    num_vertices: usize,
    faces: *const u32,
    u: *const f64,
    v: *const f64,
    n: usize,
    values: *mut f64,
    du: *mut f64,
    dv: *mut f64,
) -> profsubd_status {
    status_call(|| {
        let ev = evaluator_arg(evaluator)?;
        let nv = ev.mesh().num_vertices();
        if num_vertices != nv {
            // Checked before `data` is read: `dim * num_vertices` doubles may not be there.
            return Err(FfiError::invalid_argument(format!(
                "num_vertices is {num_vertices}; the mesh has {nv} vertices"
            )));
        }
        if dim == 0 {
            return Err(FfiError::invalid_argument(
                "primvar width (dim) must be at least 1",
            ));
        }
        let len = dim
            .checked_mul(nv)
            .ok_or_else(|| FfiError::invalid_argument(format!("dim {dim} is absurdly large")))?;
        let data = arg_slice(data, len, "data")?;
        let faces = arg_slice(faces, n, "faces")?;
        let us = arg_slice(u, n, "u")?;
        let vs = arg_slice(v, n, "v")?;
        let out = CopyOut::new(n, std::ptr::null_mut())?.buffer(values, dim, "values")?;
        let du = optional_out(du, n, dim, "du")?;
        let dv = optional_out(dv, n, dim, "dv")?;
        let p = ev.evaluate_primvar(data, dim, faces, us, vs)?;
        fill(out, p.values);
        if let Some(du) = du {
            fill(du, p.du);
        }
        if let Some(dv) = dv {
            fill(dv, p.dv);
        }
        Ok(())
    })
}

/// Evaluate `n` points `(faces[i], u[i], v[i])` given in `domain` (a `profsubd_domain`
/// value): limit position into `positions` (3 doubles per point), and, when not NULL, the
/// derivatives with respect to the domain's u and v into `du` and `dv` (3 doubles per point
/// each) and into `has_surface[i]` 1 for a point of the limit surface, 0 for a point without
/// one (a hole; under boundary interpolation "none", a face at the boundary).
///
/// A point without limit surface gets NaN in `positions`, `du` and `dv` (and 0 in
/// `has_surface`), the others are evaluated: one such point does not fail the batch. With
/// `strict` = 1 it does: `PROFSUBD_ERROR_INVALID_ARGUMENT` naming the first such point, and
/// nothing is written (`strict` = 0: marking).
///
/// Errors (`PROFSUBD_ERROR_INVALID_ARGUMENT`, message naming the point): `domain` or
/// `strict` out of range, a face out of range, (u, v) NaN or outside the domain (for
/// `PROFSUBD_DOMAIN_BFR`, in a gap between sub-face squares too). Nothing is written on
/// error.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn profsubd_evaluator_evaluate_points(
    evaluator: *const profsubd_evaluator,
    domain: i32,
    strict: i32,
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
        let ev = evaluator_arg(evaluator)?;
        let strict = strict_arg(strict)?;
        let args = PointArgs::read(domain, faces, u, v, n, positions, du, dv, has_surface)?;
        let no_surface = if strict {
            NoSurface::Strict
        } else {
            NoSurface::Mark
        };
        let (domain, points) = (args.domain, (args.faces, args.u, args.v));
        ev.evaluate_batch(domain, points, no_surface, args.output())?;
        Ok(())
    })
}

/// Exact limit position of every control vertex, in vertex order, into `positions` (3
/// doubles per vertex), and when not NULL the derivatives into `du` and `dv` (3 doubles per
/// vertex each, with respect to the (u, v) of the vertex's first face, as OpenSubdiv orders
/// faces around a vertex). A vertex without limit surface (isolated, or all its faces holes)
/// gets NaN; `profsubd_evaluator_limit_vertices_masked` also says which. `capacity` and
/// `*needed` count vertices (copy-out protocol).
#[no_mangle]
pub unsafe extern "C" fn profsubd_evaluator_limit_vertices(
    evaluator: *const profsubd_evaluator,
    positions: *mut f64,
    du: *mut f64,
    dv: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    profsubd_evaluator_limit_vertices_masked(
        evaluator,
        0,
        positions,
        du,
        dv,
        std::ptr::null_mut(),
        capacity,
        needed,
    )
}

/// Like `profsubd_evaluator_limit_vertices`, and when `has_surface` is not NULL, 1 per vertex
/// with a limit position, 0 per vertex without (isolated, or all its faces holes: OpenSubdiv
/// gives a vertex a limit when one of its faces has a limit surface), whose entries in
/// `positions`, `du` and `dv` are NaN. With `strict` = 1 a vertex without limit surface is
/// an error instead (`PROFSUBD_ERROR_INVALID_ARGUMENT` naming the first one; nothing
/// written). `capacity` and `*needed` count vertices (copy-out protocol).
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn profsubd_evaluator_limit_vertices_masked(
    evaluator: *const profsubd_evaluator,
    strict: i32,
    positions: *mut f64,
    du: *mut f64,
    dv: *mut f64,
    has_surface: *mut u8,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    status_call(|| {
        let ev = evaluator_arg(evaluator)?;
        let strict = strict_arg(strict)?;
        let c = CopyOut::new(capacity, needed)?;
        let pos = c.buffer(positions, 3, "positions")?;
        let du = optional_points(du, capacity, "du")?;
        let dv = optional_points(dv, capacity, "dv")?;
        let mask = optional_out(has_surface, capacity, 1, "has_surface")?;
        let n = ev.mesh().num_vertices();
        let samples = if n <= capacity {
            ev.vertex_limits()?
        } else {
            Vec::new()
        };
        if strict {
            require_surface(samples.clone(), "vertex")?;
        }
        c.finish(n, "vertices", || write_marked(&samples, pos, du, dv, mask))
    })
}

#[cfg(test)]
mod tests;
