//! The mesh handle: creation from caller arrays, counts and copy-out queries.

use std::ffi::CString;
use std::mem::size_of;
use std::sync::{Arc, OnceLock};

use glam::DVec3;

use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::handle::{self, Handle};
use crate::ffi::panic::{guard, status_call};
use crate::ffi::ptr::{all_of, arg_out, arg_slice, copy_slice, fill, CopyOut};
use crate::ffi::status::profsubd_status;
use crate::mesh::{Corner, Crease, Mesh, MeshParts, MAX_COMPONENTS};
use crate::topology::Level;

/// A validated control mesh (opaque, immutable, safe to share between threads). Create with
/// `profsubd_mesh_new` or `profsubd_mesh_read_obj`; release with `profsubd_mesh_free`.
pub struct profsubd_mesh {
    _private: [u8; 0],
}

/// What a `profsubd_mesh` handle holds.
#[derive(Debug)]
pub struct MeshData {
    /// Shared with the fitted construction it came from, if any (meshes are immutable).
    mesh: Arc<Mesh>,
    /// What the OBJ reader ignored, for `profsubd_mesh_get_warning`.
    warnings: Vec<CString>,
    /// The base level (edges, valences), built on first use; `OnceLock` keeps the handle
    /// shareable between threads.
    level: OnceLock<Level>,
}

impl MeshData {
    /// Wrap a mesh.
    pub fn new(mesh: Mesh) -> Self {
        Self::with_warnings(mesh, Vec::new())
    }

    /// Share a mesh (no copy).
    pub fn shared(mesh: Arc<Mesh>) -> Self {
        MeshData {
            mesh,
            warnings: Vec::new(),
            level: OnceLock::new(),
        }
    }

    /// Wrap a mesh read with `warnings` (interior NUL bytes become spaces).
    pub fn with_warnings(mesh: Mesh, warnings: Vec<String>) -> Self {
        let warnings = warnings
            .into_iter()
            .map(|w| CString::new(w.replace('\0', " ")).unwrap_or_default())
            .collect();
        MeshData {
            mesh: Arc::new(mesh),
            warnings,
            level: OnceLock::new(),
        }
    }

    /// The mesh.
    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// The reader's warnings.
    pub fn warnings(&self) -> &[CString] {
        &self.warnings
    }

    /// The mesh's base level in OpenSubdiv's component order.
    pub fn level(&self) -> &Level {
        self.level.get_or_init(|| Level::from_mesh(&self.mesh))
    }
}

impl Handle for profsubd_mesh {
    type Inner = MeshData;
    const MAGIC: u64 = u64::from_le_bytes(*b"psd-MESH");
    const NAME: &'static str = "profsubd_mesh";
}

/// A new caller-owned mesh handle (for functions that produce meshes).
pub fn new_mesh_handle(mesh: Mesh) -> *mut profsubd_mesh {
    handle::into_raw(MeshData::new(mesh))
}

/// The mesh behind the handle argument `name`.
pub unsafe fn mesh_arg<'a>(p: *const profsubd_mesh, name: &str) -> FfiResult<&'a Mesh> {
    handle::borrow(p, name).map(MeshData::mesh)
}

/// Caller arrays describing a mesh, as OpenSubdiv's `Far::TopologyDescriptor`. All counts
/// are in elements of the array named; an array may be NULL when its count is 0. The arrays
/// are copied: the caller keeps ownership. Zero-initialize the struct (`= {0}` in C, `{}` in
/// C++), set `struct_size`, then the arrays you have.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct profsubd_mesh_desc {
    /// Must be `sizeof(profsubd_mesh_desc)`: lets later versions extend the struct.
    pub struct_size: usize,
    /// `3 * num_vertices` coordinates, x y z per vertex; all finite.
    pub positions: *const f64,
    /// Number of vertices (at most `INT32_MAX`).
    pub num_vertices: usize,
    /// `num_faces` vertex counts, each at least 3.
    pub face_sizes: *const u32,
    /// Number of faces (at least 1, at most `INT32_MAX`).
    pub num_faces: usize,
    /// `num_face_indices` 0-based vertex indices, face after face.
    pub face_indices: *const u32,
    /// Number of face indices: the sum of `face_sizes` (at most `INT32_MAX`).
    pub num_face_indices: usize,
    /// `2 * num_creases` vertex indices: the two ends of each sharp edge.
    pub crease_vertices: *const u32,
    /// `num_creases` sharpness values, each >= 0 (10 or more is infinitely sharp).
    pub crease_sharpness: *const f32,
    /// Number of sharp edges.
    pub num_creases: usize,
    /// `num_corners` vertex indices of sharp vertices.
    pub corner_vertices: *const u32,
    /// `num_corners` sharpness values, each >= 0.
    pub corner_sharpness: *const f32,
    /// Number of sharp vertices.
    pub num_corners: usize,
    /// `num_holes` 0-based indices of faces that are holes.
    pub hole_faces: *const u32,
    /// Number of hole faces.
    pub num_holes: usize,
}

/// Reject counts above what OpenSubdiv can index, before any array is read.
fn check_count(name: &str, n: usize) -> FfiResult<()> {
    if n > MAX_COMPONENTS {
        return Err(FfiError::invalid_argument(format!(
            "desc->{name} is {n}; the limit is {MAX_COMPONENTS}"
        )));
    }
    Ok(())
}

/// `n` items of `width` elements: cannot overflow on 64-bit targets after [`check_count`],
/// checked for 32-bit ones.
fn elements(n: usize, width: usize, name: &str) -> FfiResult<usize> {
    n.checked_mul(width).ok_or_else(|| {
        FfiError::invalid_argument(format!("desc->{name} is {n}: too large for this platform"))
    })
}

/// Read the descriptor: its size first, so a smaller (older or garbage) struct is never read past.
unsafe fn read_desc(desc: *const profsubd_mesh_desc) -> FfiResult<profsubd_mesh_desc> {
    let size = *crate::ffi::ptr::arg_ref(desc.cast::<usize>(), "desc")?;
    let ours = size_of::<profsubd_mesh_desc>();
    if size != ours {
        let why = if size < ours {
            "smaller than the first version of the struct"
        } else {
            "larger than this library knows: the program was built against a newer profsubd.h"
        };
        return Err(FfiError::invalid_argument(format!(
            "desc->struct_size is {size}, {why}; set it to sizeof(profsubd_mesh_desc) ({ours})"
        )));
    }
    Ok(*desc)
}

unsafe fn parts_from_desc(d: &profsubd_mesh_desc) -> FfiResult<MeshParts> {
    for (name, n) in [
        ("num_vertices", d.num_vertices),
        ("num_faces", d.num_faces),
        ("num_face_indices", d.num_face_indices),
        ("num_creases", d.num_creases),
        ("num_corners", d.num_corners),
        ("num_holes", d.num_holes),
    ] {
        check_count(name, n)?;
    }
    let positions = arg_slice(
        d.positions,
        elements(d.num_vertices, 3, "num_vertices")?,
        "desc->positions",
    )?;
    let crease_vertices = arg_slice(
        d.crease_vertices,
        elements(d.num_creases, 2, "num_creases")?,
        "desc->crease_vertices",
    )?;
    let crease_sharpness = arg_slice(d.crease_sharpness, d.num_creases, "desc->crease_sharpness")?;
    let corner_vertices = arg_slice(d.corner_vertices, d.num_corners, "desc->corner_vertices")?;
    let corner_sharpness = arg_slice(d.corner_sharpness, d.num_corners, "desc->corner_sharpness")?;
    Ok(MeshParts {
        positions: positions
            .chunks_exact(3)
            .map(|p| DVec3::new(p[0], p[1], p[2]))
            .collect(),
        face_sizes: arg_slice(d.face_sizes, d.num_faces, "desc->face_sizes")?.to_vec(),
        face_indices: arg_slice(d.face_indices, d.num_face_indices, "desc->face_indices")?.to_vec(),
        creases: crease_vertices
            .chunks_exact(2)
            .zip(crease_sharpness)
            .map(|(v, &sharpness)| Crease {
                vertices: [v[0], v[1]],
                sharpness,
            })
            .collect(),
        corners: corner_vertices
            .iter()
            .zip(corner_sharpness)
            .map(|(&vertex, &sharpness)| Corner { vertex, sharpness })
            .collect(),
        holes: arg_slice(d.hole_faces, d.num_holes, "desc->hole_faces")?.to_vec(),
        options: Default::default(),
    })
}

/// Build a mesh from caller arrays (copied); `*out` receives the new handle. Errors:
/// `PROFSUBD_ERROR_INVALID_ARGUMENT` for a wrong `struct_size` or a count above `INT32_MAX`,
/// `PROFSUBD_ERROR_NULL_ARGUMENT` for a NULL array with a non-zero count,
/// `PROFSUBD_ERROR_INVALID_MESH` for data OpenSubdiv cannot take (index out of range, face
/// with fewer than 3 vertices, face sizes not adding up to `num_face_indices`, NaN or
/// infinite coordinate, NaN or negative sharpness, crease on two vertices that share no
/// edge, no faces).
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_new(
    desc: *const profsubd_mesh_desc,
    out: *mut *mut profsubd_mesh,
) -> profsubd_status {
    status_call(|| {
        let out = arg_out(out, "out")?;
        let parts = parts_from_desc(&read_desc(desc)?)?;
        out.write(new_mesh_handle(Mesh::from_parts(parts)?));
        Ok(())
    })
}

/// Release a mesh. NULL is a no-op.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_free(mesh: *mut profsubd_mesh) {
    guard(|| handle::free(mesh))
}

/// A count query: check both pointers, then write `count(mesh)`.
pub(crate) unsafe fn count_query(
    mesh: *const profsubd_mesh,
    out: *mut usize,
    count: impl FnOnce(&MeshData) -> usize,
) -> profsubd_status {
    status_call(|| {
        let m = handle::borrow(mesh, "mesh")?;
        let out = arg_out(out, "out")?;
        out.write(count(m));
        Ok(())
    })
}

/// Number of vertices.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_num_vertices(
    mesh: *const profsubd_mesh,
    out: *mut usize,
) -> profsubd_status {
    count_query(mesh, out, |m| m.mesh.num_vertices())
}

/// Number of faces.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_num_faces(
    mesh: *const profsubd_mesh,
    out: *mut usize,
) -> profsubd_status {
    count_query(mesh, out, |m| m.mesh.num_faces())
}

/// Number of face vertex indices (the sum of the face sizes).
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_num_face_indices(
    mesh: *const profsubd_mesh,
    out: *mut usize,
) -> profsubd_status {
    count_query(mesh, out, |m| m.mesh.face_indices().len())
}

/// Number of sharp edges (crease tags).
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_num_creases(
    mesh: *const profsubd_mesh,
    out: *mut usize,
) -> profsubd_status {
    count_query(mesh, out, |m| m.mesh.creases().len())
}

/// Number of sharp vertices (corner tags).
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_num_corners(
    mesh: *const profsubd_mesh,
    out: *mut usize,
) -> profsubd_status {
    count_query(mesh, out, |m| m.mesh.corners().len())
}

/// Number of hole faces.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_num_holes(
    mesh: *const profsubd_mesh,
    out: *mut usize,
) -> profsubd_status {
    count_query(mesh, out, |m| m.mesh.holes().len())
}

/// Copy the vertex positions: 3 doubles (x y z) per vertex. `capacity` and `*needed` count
/// doubles (`3 * num_vertices`). Copy-out protocol: `out` may be NULL only when `capacity`
/// is 0; if `capacity` is too small, `PROFSUBD_ERROR_BUFFER_TOO_SMALL` is returned, the
/// needed count is written to `*needed` (when `needed` is not NULL) and `out` is untouched;
/// on success `*needed` receives the count copied. The same protocol holds for every
/// `profsubd_*_get_*` function.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_get_positions(
    mesh: *const profsubd_mesh,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (mesh, "mesh"),
        (out, "out", capacity, needed),
        (1, "doubles"),
        |m| {
            let ps = m.mesh.positions();
            Ok((3 * ps.len(), ps.iter().flat_map(|p| p.to_array())))
        },
    )
}

/// Copy the number of vertices of each face. `capacity` and `*needed` count faces.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_get_face_sizes(
    mesh: *const profsubd_mesh,
    out: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (mesh, "mesh"),
        (out, "out", capacity, needed),
        (1, "faces"),
        |m| Ok(all_of(m.mesh.face_sizes())),
    )
}

/// Copy the face vertex indices (0-based, face after face). `capacity` and `*needed` count
/// indices.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_get_face_indices(
    mesh: *const profsubd_mesh,
    out: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (mesh, "mesh"),
        (out, "out", capacity, needed),
        (1, "indices"),
        |m| Ok(all_of(m.mesh.face_indices())),
    )
}

/// Copy the hole faces (0-based face indices). `capacity` and `*needed` count holes.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_get_holes(
    mesh: *const profsubd_mesh,
    faces: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (mesh, "mesh"),
        (faces, "faces", capacity, needed),
        (1, "holes"),
        |m| Ok(all_of(m.mesh.holes())),
    )
}

/// A copy-out query of the crease or corner tags: `W` vertex indices per tag into
/// `vertices`, one sharpness per tag into `sharpness`.
unsafe fn copy_tags<K, const W: usize>(
    mesh: *const profsubd_mesh,
    (vertices, sharpness): (*mut u32, *mut f32),
    capacity: usize,
    needed: *mut usize,
    unit: &str,
    tags: fn(&Mesh) -> &[K],
    tag: fn(&K) -> ([u32; W], f32),
) -> profsubd_status {
    status_call(|| {
        let m = mesh_arg(mesh, "mesh")?;
        let c = CopyOut::new(capacity, needed)?;
        let vs = c.buffer(vertices, W, "vertices")?;
        let ss = c.buffer(sharpness, 1, "sharpness")?;
        let tags = tags(m);
        c.finish(tags.len(), unit, || {
            fill(vs, tags.iter().flat_map(|k| tag(k).0));
            fill(ss, tags.iter().map(|k| tag(k).1));
        })
    })
}

/// Copy the sharp edges: 2 vertex indices per crease into `vertices` and one sharpness per
/// crease into `sharpness`. `capacity` and `*needed` count creases (`vertices` holds
/// `2 * capacity` indices).
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_get_creases(
    mesh: *const profsubd_mesh,
    vertices: *mut u32,
    sharpness: *mut f32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_tags(
        mesh,
        (vertices, sharpness),
        capacity,
        needed,
        "creases",
        Mesh::creases,
        |k: &Crease| (k.vertices, k.sharpness),
    )
}

/// Copy the sharp vertices: one vertex index and one sharpness per corner. `capacity` and
/// `*needed` count corners.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_get_corners(
    mesh: *const profsubd_mesh,
    vertices: *mut u32,
    sharpness: *mut f32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_tags(
        mesh,
        (vertices, sharpness),
        capacity,
        needed,
        "corners",
        Mesh::corners,
        |k: &Corner| ([k.vertex], k.sharpness),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::error::last_error;
    use crate::ffi::status::profsubd_status::*;
    use std::ptr::{null, null_mut};

    type Count = unsafe extern "C" fn(*const profsubd_mesh, *mut usize) -> profsubd_status;
    const COUNTS: [Count; 6] = [
        profsubd_mesh_num_vertices,
        profsubd_mesh_num_faces,
        profsubd_mesh_num_face_indices,
        profsubd_mesh_num_creases,
        profsubd_mesh_num_corners,
        profsubd_mesh_num_holes,
    ];

    /// Two quads sharing edge 1-4, with a crease on it, a corner and a hole.
    struct Arrays {
        positions: Vec<f64>,
        face_sizes: Vec<u32>,
        face_indices: Vec<u32>,
        crease_vertices: Vec<u32>,
        crease_sharpness: Vec<f32>,
        corner_vertices: Vec<u32>,
        corner_sharpness: Vec<f32>,
        hole_faces: Vec<u32>,
    }

    fn two_quads() -> Arrays {
        Arrays {
            positions: vec![
                0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 2.0, 0.0, 0.5, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 2.0,
                1.0, -0.25,
            ],
            face_sizes: vec![4, 4],
            face_indices: vec![0, 1, 4, 3, 1, 2, 5, 4],
            crease_vertices: vec![1, 4],
            crease_sharpness: vec![2.5],
            corner_vertices: vec![0],
            corner_sharpness: vec![10.0],
            hole_faces: vec![1],
        }
    }

    fn desc(a: &Arrays) -> profsubd_mesh_desc {
        profsubd_mesh_desc {
            struct_size: size_of::<profsubd_mesh_desc>(),
            positions: a.positions.as_ptr(),
            num_vertices: a.positions.len() / 3,
            face_sizes: a.face_sizes.as_ptr(),
            num_faces: a.face_sizes.len(),
            face_indices: a.face_indices.as_ptr(),
            num_face_indices: a.face_indices.len(),
            crease_vertices: a.crease_vertices.as_ptr(),
            crease_sharpness: a.crease_sharpness.as_ptr(),
            num_creases: a.crease_sharpness.len(),
            corner_vertices: a.corner_vertices.as_ptr(),
            corner_sharpness: a.corner_sharpness.as_ptr(),
            num_corners: a.corner_sharpness.len(),
            hole_faces: a.hole_faces.as_ptr(),
            num_holes: a.hole_faces.len(),
        }
    }

    /// `profsubd_mesh_new` on `d`: the status, and the message on failure.
    fn try_new(d: &profsubd_mesh_desc) -> (profsubd_status, String) {
        let sentinel = 0x10 as *mut profsubd_mesh;
        let mut out = sentinel;
        let s = unsafe { profsubd_mesh_new(d, &mut out) };
        if s == PROFSUBD_OK {
            unsafe { profsubd_mesh_free(out) };
        } else {
            assert_eq!(out, sentinel, "output written on error");
        }
        (s, last_error())
    }

    fn new_mesh(a: &Arrays) -> *mut profsubd_mesh {
        let mut m = null_mut();
        assert_eq!(unsafe { profsubd_mesh_new(&desc(a), &mut m) }, PROFSUBD_OK);
        m
    }

    #[test]
    fn round_trip_copies_everything_back() {
        let a = two_quads();
        let m = new_mesh(&a);
        unsafe {
            let count =
                |f: unsafe extern "C" fn(*const profsubd_mesh, *mut usize) -> profsubd_status| {
                    let mut n = usize::MAX;
                    assert_eq!(f(m, &mut n), PROFSUBD_OK);
                    n
                };
            assert_eq!(count(profsubd_mesh_num_vertices), 6);
            assert_eq!(count(profsubd_mesh_num_faces), 2);
            assert_eq!(count(profsubd_mesh_num_face_indices), 8);
            assert_eq!(count(profsubd_mesh_num_creases), 1);
            assert_eq!(count(profsubd_mesh_num_corners), 1);
            assert_eq!(count(profsubd_mesh_num_holes), 1);

            let mut pos = vec![0.0; 18];
            let mut needed = 0;
            assert_eq!(
                profsubd_mesh_get_positions(m, pos.as_mut_ptr(), 18, &mut needed),
                PROFSUBD_OK
            );
            assert_eq!((pos, needed), (a.positions.clone(), 18));
            let mut fs = vec![0; 2];
            assert_eq!(
                profsubd_mesh_get_face_sizes(m, fs.as_mut_ptr(), 2, null_mut()),
                PROFSUBD_OK
            );
            assert_eq!(fs, a.face_sizes);
            let mut fi = vec![0; 10];
            assert_eq!(
                profsubd_mesh_get_face_indices(m, fi.as_mut_ptr(), 10, &mut needed),
                PROFSUBD_OK
            );
            assert_eq!(
                (&fi[..8], &fi[8..], needed),
                (&a.face_indices[..], &[0, 0][..], 8)
            );
            let (mut cv, mut cs) = (vec![0; 2], vec![0.0; 1]);
            assert_eq!(
                profsubd_mesh_get_creases(m, cv.as_mut_ptr(), cs.as_mut_ptr(), 1, &mut needed),
                PROFSUBD_OK
            );
            assert_eq!((cv, cs, needed), (vec![1, 4], vec![2.5], 1));
            let (mut kv, mut ks) = (vec![9; 1], vec![0.0; 1]);
            assert_eq!(
                profsubd_mesh_get_corners(m, kv.as_mut_ptr(), ks.as_mut_ptr(), 1, &mut needed),
                PROFSUBD_OK
            );
            assert_eq!((kv, ks), (vec![0], vec![10.0]));
            let mut h = vec![0; 1];
            assert_eq!(
                profsubd_mesh_get_holes(m, h.as_mut_ptr(), 1, &mut needed),
                PROFSUBD_OK
            );
            assert_eq!(h, vec![1]);
            profsubd_mesh_free(m);
        }
    }

    #[test]
    fn too_small_buffers_report_needed_and_stay_untouched() {
        let a = two_quads();
        let m = new_mesh(&a);
        unsafe {
            let mut needed = 0;
            // Size query: NULL buffer with capacity 0.
            assert_eq!(
                profsubd_mesh_get_positions(m, null_mut(), 0, &mut needed),
                PROFSUBD_ERROR_BUFFER_TOO_SMALL
            );
            assert_eq!(needed, 18);
            assert_eq!(
                last_error(),
                "buffer too small: capacity is 0 doubles, 18 needed"
            );
            let mut pos = [7.0; 17];
            assert_eq!(
                profsubd_mesh_get_positions(m, pos.as_mut_ptr(), 17, null_mut()),
                PROFSUBD_ERROR_BUFFER_TOO_SMALL
            );
            assert_eq!(pos, [7.0; 17]);
            let mut fi = [7; 7];
            assert_eq!(
                profsubd_mesh_get_face_indices(m, fi.as_mut_ptr(), 7, &mut needed),
                PROFSUBD_ERROR_BUFFER_TOO_SMALL
            );
            assert_eq!((fi, needed), ([7; 7], 8));
            assert_eq!(
                profsubd_mesh_get_face_sizes(m, null_mut(), 0, &mut needed),
                PROFSUBD_ERROR_BUFFER_TOO_SMALL
            );
            assert_eq!(needed, 2);
            for f in [profsubd_mesh_get_creases, profsubd_mesh_get_corners] {
                needed = 0;
                assert_eq!(
                    f(m, null_mut(), null_mut(), 0, &mut needed),
                    PROFSUBD_ERROR_BUFFER_TOO_SMALL
                );
                assert_eq!(needed, 1);
            }
            assert_eq!(
                profsubd_mesh_get_holes(m, null_mut(), 0, &mut needed),
                PROFSUBD_ERROR_BUFFER_TOO_SMALL
            );
            profsubd_mesh_free(m);
        }
    }

    #[test]
    fn absurd_capacities_are_rejected() {
        let a = two_quads();
        let m = new_mesh(&a);
        let mut buf = [0u32; 4];
        let mut d = [0f64; 4];
        let mut n = 0;
        unsafe {
            let s = profsubd_mesh_get_positions(m, d.as_mut_ptr(), usize::MAX / 4, &mut n);
            assert_eq!(s, PROFSUBD_ERROR_INVALID_ARGUMENT);
            assert!(last_error().contains("larger than any buffer can be"));
            let s = profsubd_mesh_get_creases(m, buf.as_mut_ptr(), null_mut(), usize::MAX, &mut n);
            assert_eq!(s, PROFSUBD_ERROR_INVALID_ARGUMENT);
            assert_eq!(
                last_error(),
                "capacity 18446744073709551615 is absurdly large"
            );
            profsubd_mesh_free(m);
        }
        assert_eq!((buf, d, n), ([0; 4], [0.0; 4], 0));
    }

    #[test]
    fn empty_data_needs_no_buffer() {
        let mut a = two_quads();
        a.crease_vertices.clear();
        a.crease_sharpness.clear();
        let m = new_mesh(&a);
        let mut needed = 5;
        unsafe {
            assert_eq!(
                profsubd_mesh_get_creases(m, null_mut(), null_mut(), 0, &mut needed),
                PROFSUBD_OK
            );
            assert_eq!(needed, 0);
            profsubd_mesh_free(m);
        }
    }

    #[test]
    fn null_arguments_are_named() {
        let a = two_quads();
        let m = new_mesh(&a);
        let mut n = 0usize;
        let mut buf = [0u32; 8];
        let mut fbuf = [0f32; 8];
        let mut dbuf = [0f64; 18];
        unsafe {
            for f in COUNTS {
                assert_eq!(f(null(), &mut n), PROFSUBD_ERROR_NULL_ARGUMENT);
                assert_eq!(last_error(), "argument `mesh` is NULL");
                assert_eq!(f(m, null_mut()), PROFSUBD_ERROR_NULL_ARGUMENT);
                assert_eq!(last_error(), "argument `out` is NULL");
            }
            assert_eq!(
                profsubd_mesh_get_positions(null(), dbuf.as_mut_ptr(), 18, &mut n),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(
                profsubd_mesh_get_positions(m, null_mut(), 18, &mut n),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(last_error(), "argument `out` is NULL but capacity is 18");
            type U32s = unsafe extern "C" fn(
                *const profsubd_mesh,
                *mut u32,
                usize,
                *mut usize,
            ) -> profsubd_status;
            let u32s: [U32s; 3] = [
                profsubd_mesh_get_face_sizes,
                profsubd_mesh_get_face_indices,
                profsubd_mesh_get_holes,
            ];
            for f in u32s {
                assert_eq!(
                    f(null(), buf.as_mut_ptr(), 8, &mut n),
                    PROFSUBD_ERROR_NULL_ARGUMENT
                );
                assert_eq!(f(m, null_mut(), 8, &mut n), PROFSUBD_ERROR_NULL_ARGUMENT);
            }
            for f in [profsubd_mesh_get_creases, profsubd_mesh_get_corners] {
                assert_eq!(
                    f(null(), buf.as_mut_ptr(), fbuf.as_mut_ptr(), 1, &mut n),
                    PROFSUBD_ERROR_NULL_ARGUMENT
                );
                assert_eq!(
                    f(m, null_mut(), fbuf.as_mut_ptr(), 1, &mut n),
                    PROFSUBD_ERROR_NULL_ARGUMENT
                );
                assert_eq!(
                    last_error(),
                    "argument `vertices` is NULL but capacity is 1"
                );
                assert_eq!(
                    f(m, buf.as_mut_ptr(), null_mut(), 1, &mut n),
                    PROFSUBD_ERROR_NULL_ARGUMENT
                );
                assert_eq!(
                    last_error(),
                    "argument `sharpness` is NULL but capacity is 1"
                );
            }
            assert_eq!(buf, [0; 8]);
            // NULL desc / NULL out.
            let mut out = null_mut();
            assert_eq!(
                profsubd_mesh_new(null(), &mut out),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(last_error(), "argument `desc` is NULL");
            assert_eq!(
                profsubd_mesh_new(&desc(&a), null_mut()),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert!(out.is_null());
            profsubd_mesh_free(null_mut());
            profsubd_mesh_free(m);
        }
    }

    #[test]
    fn invalid_handles_are_rejected() {
        let mut o = null_mut();
        let mut n = 0usize;
        let mut fake = [0u64; 16];
        unsafe {
            crate::ffi::options::profsubd_options_new(&mut o);
            for h in [o.cast::<profsubd_mesh>(), fake.as_mut_ptr().cast()] {
                for f in COUNTS {
                    assert_eq!(f(h, &mut n), PROFSUBD_ERROR_INVALID_HANDLE);
                }
                assert_eq!(
                    last_error(),
                    "argument `mesh` is not a live profsubd_mesh (freed, or another kind of object)"
                );
                assert_eq!(
                    profsubd_mesh_get_positions(h, null_mut(), 0, &mut n),
                    PROFSUBD_ERROR_INVALID_HANDLE
                );
                assert_eq!(
                    profsubd_mesh_get_face_sizes(h, null_mut(), 0, &mut n),
                    PROFSUBD_ERROR_INVALID_HANDLE
                );
                assert_eq!(
                    profsubd_mesh_get_face_indices(h, null_mut(), 0, &mut n),
                    PROFSUBD_ERROR_INVALID_HANDLE
                );
                assert_eq!(
                    profsubd_mesh_get_holes(h, null_mut(), 0, &mut n),
                    PROFSUBD_ERROR_INVALID_HANDLE
                );
                assert_eq!(
                    profsubd_mesh_get_creases(h, null_mut(), null_mut(), 0, &mut n),
                    PROFSUBD_ERROR_INVALID_HANDLE
                );
                assert_eq!(
                    profsubd_mesh_get_corners(h, null_mut(), null_mut(), 0, &mut n),
                    PROFSUBD_ERROR_INVALID_HANDLE
                );
                profsubd_mesh_free(h);
                assert!(last_error().contains("not a live profsubd_mesh"));
            }
            assert_eq!(n, 0);
            assert_eq!(fake, [0; 16]);
            // The options object survived the attempt to free it as a mesh.
            assert_eq!(
                crate::ffi::options::profsubd_options_set_boundary(o, 1),
                PROFSUBD_OK
            );
            crate::ffi::options::profsubd_options_free(o);
        }
    }

    #[test]
    fn struct_size_is_checked_before_reading_the_rest() {
        let a = two_quads();
        let mut d = desc(&a);
        for bad in [0, 8, size_of::<profsubd_mesh_desc>() - 8] {
            d.struct_size = bad;
            let (s, msg) = try_new(&d);
            assert_eq!(s, PROFSUBD_ERROR_INVALID_ARGUMENT);
            assert!(msg.contains("smaller than the first version"), "{msg}");
        }
        // Only the size field is readable here: a smaller struct must not be read further.
        let tiny: usize = 8;
        let mut out = null_mut();
        let s = unsafe { profsubd_mesh_new((&tiny as *const usize).cast(), &mut out) };
        assert_eq!(s, PROFSUBD_ERROR_INVALID_ARGUMENT);
        d.struct_size = size_of::<profsubd_mesh_desc>() + 8;
        let (s, msg) = try_new(&d);
        assert_eq!(s, PROFSUBD_ERROR_INVALID_ARGUMENT);
        assert!(msg.contains("newer profsubd.h"), "{msg}");
    }

    #[test]
    fn absurd_counts_are_rejected_before_reading() {
        let a = two_quads();
        let limit = MAX_COMPONENTS + 1;
        let setters: [fn(&mut profsubd_mesh_desc, usize); 6] = [
            |d, n| d.num_vertices = n,
            |d, n| d.num_faces = n,
            |d, n| d.num_face_indices = n,
            |d, n| d.num_creases = n,
            |d, n| d.num_corners = n,
            |d, n| d.num_holes = n,
        ];
        for set in setters {
            for n in [limit, usize::MAX / 2, usize::MAX] {
                let mut d = desc(&a);
                set(&mut d, n);
                let (s, msg) = try_new(&d);
                assert_eq!(s, PROFSUBD_ERROR_INVALID_ARGUMENT, "{msg}");
                assert!(msg.contains("the limit is 2147483647"), "{msg}");
            }
        }
    }

    #[test]
    fn null_arrays_with_counts_are_rejected() {
        let a = two_quads();
        type Breaker = fn(&mut profsubd_mesh_desc);
        let setters: [(Breaker, &str); 8] = [
            (|d| d.positions = null(), "desc->positions"),
            (|d| d.face_sizes = null(), "desc->face_sizes"),
            (|d| d.face_indices = null(), "desc->face_indices"),
            (|d| d.crease_vertices = null(), "desc->crease_vertices"),
            (|d| d.crease_sharpness = null(), "desc->crease_sharpness"),
            (|d| d.corner_vertices = null(), "desc->corner_vertices"),
            (|d| d.corner_sharpness = null(), "desc->corner_sharpness"),
            (|d| d.hole_faces = null(), "desc->hole_faces"),
        ];
        for (set, name) in setters {
            let mut d = desc(&a);
            set(&mut d);
            let (s, msg) = try_new(&d);
            assert_eq!(s, PROFSUBD_ERROR_NULL_ARGUMENT);
            assert!(
                msg.starts_with(&format!("argument `{name}` is NULL but its count is")),
                "{msg}"
            );
        }
    }

    #[test]
    fn invalid_meshes_are_rejected_with_the_reason() {
        type Breaker = fn(&mut Arrays);
        let cases: [(Breaker, &str); 8] = [
            (
                |a| a.positions[4] = f64::NAN,
                "vertex 1 has a non-finite coordinate",
            ),
            (
                |a| a.positions[0] = f64::INFINITY,
                "vertex 0 has a non-finite coordinate",
            ),
            (|a| a.face_indices[5] = 6, "refers to vertex 6"),
            (|a| a.face_sizes = vec![2, 6], "at least 3"),
            (|a| a.face_sizes = vec![4, 3], "face sizes add up to 7"),
            (
                |a| a.crease_sharpness[0] = f32::NAN,
                "sharpness must be a number",
            ),
            (|a| a.crease_vertices = vec![0, 2], "not joined by an edge"),
            (|a| a.hole_faces[0] = 2, "hole face 2 is out of range"),
        ];
        for (break_it, why) in cases {
            let mut a = two_quads();
            break_it(&mut a);
            let (s, msg) = try_new(&desc(&a));
            assert_eq!(s, PROFSUBD_ERROR_INVALID_MESH, "{msg}");
            assert!(msg.contains(why), "{msg} should contain {why}");
        }
        let mut a = two_quads();
        a.corner_sharpness[0] = -1.0;
        assert_eq!(try_new(&desc(&a)).0, PROFSUBD_ERROR_INVALID_MESH);
        let mut d = desc(&a);
        d.num_faces = 0;
        d.num_face_indices = 0;
        assert_eq!(try_new(&d).0, PROFSUBD_ERROR_INVALID_MESH);
    }

    #[test]
    fn misaligned_arrays_are_rejected() {
        let a = two_quads();
        let mut d = desc(&a);
        d.positions = unsafe { d.positions.cast::<u8>().add(4).cast() };
        d.num_vertices = 5;
        let (s, msg) = try_new(&d);
        assert_eq!(s, PROFSUBD_ERROR_INVALID_ARGUMENT);
        assert!(
            msg.contains("`desc->positions` is not aligned to 8 bytes"),
            "{msg}"
        );
    }

    #[test]
    fn handles_are_usable_from_several_threads() {
        let a = two_quads();
        let m = new_mesh(&a) as usize;
        let threads: Vec<_> = (0..4)
            .map(|_| {
                std::thread::spawn(move || {
                    let mut n = 0;
                    let s = unsafe { profsubd_mesh_num_face_indices(m as *const _, &mut n) };
                    (s, n)
                })
            })
            .collect();
        for t in threads {
            assert_eq!(t.join().unwrap(), (PROFSUBD_OK, 8));
        }
        unsafe { profsubd_mesh_free(m as *mut _) };
    }
}
