//! Where OpenSubdiv 3.5 is not exact or not safe on a mesh ([`crate::mesh::osd_hazards()`]):
//! the vertices and faces of each hazard kind.

use crate::ffi::error::{enum_arg, FfiError};
use crate::ffi::mesh::profsubd_mesh;
use crate::ffi::options::{profsubd_options, resolve};
use crate::ffi::ptr::copy_slice;
use crate::ffi::status::profsubd_status;
use crate::mesh::{osd_hazards, HazardKind};

/// Kinds of OpenSubdiv 3.5 hazard, for `profsubd_mesh_get_osd_hazard_vertices` and
/// `_faces` (passed as `int32_t`). What each means, and the figures measured by the
/// conformance suite: README, section on `profsubd check`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum profsubd_osd_hazard {
    /// Interior vertex with one infinitely sharp edge: Bfr, Far's PatchTable and Osd use the
    /// smooth limit mask at their last isolation level.
    PROFSUBD_OSD_HAZARD_DART = 0,
    /// Interior valence-2 dart: 3.5's `Far::SourcePatch` writes out of bounds (Bfr crashes,
    /// the PatchTable is silently wrong).
    PROFSUBD_OSD_HAZARD_VALENCE2_DART = 1,
    /// Interior valence-2 vertex with sharp features in its faces: 3.5's Bfr is not safe.
    PROFSUBD_OSD_HAZARD_VALENCE2_SHARP = 2,
    /// Other interior valence-2 vertex: Bfr's topology cache can mix up its faces.
    PROFSUBD_OSD_HAZARD_VALENCE2 = 3,
    /// Semi-sharp edges of different sharpness meet under Chaikin creasing: Bfr is not exact.
    PROFSUBD_OSD_HAZARD_CHAIKIN = 4,
    /// A face repeats the vertex.
    PROFSUBD_OSD_HAZARD_REPEATED_VERTEX = 5,
    /// `Far::PrimvarRefiner::Limit` is not the limit at the vertex.
    PROFSUBD_OSD_HAZARD_PRIMVAR_LIMIT = 6,
}

fn kind_of(kind: i32) -> Result<HazardKind, FfiError> {
    use profsubd_osd_hazard::*;
    let table = [
        (PROFSUBD_OSD_HAZARD_DART as i32, HazardKind::Dart),
        (
            PROFSUBD_OSD_HAZARD_VALENCE2_DART as i32,
            HazardKind::Valence2Dart,
        ),
        (
            PROFSUBD_OSD_HAZARD_VALENCE2_SHARP as i32,
            HazardKind::Valence2Sharp,
        ),
        (PROFSUBD_OSD_HAZARD_VALENCE2 as i32, HazardKind::Valence2),
        (PROFSUBD_OSD_HAZARD_CHAIKIN as i32, HazardKind::Chaikin),
        (
            PROFSUBD_OSD_HAZARD_REPEATED_VERTEX as i32,
            HazardKind::RepeatedVertex,
        ),
        (
            PROFSUBD_OSD_HAZARD_PRIMVAR_LIMIT as i32,
            HazardKind::PrimvarLimit,
        ),
    ];
    enum_arg("hazard kind", kind, &table)
}

/// A copy-out of the vertices (`faces` false) or faces of hazard `kind`.
unsafe fn copy_hazard(
    mesh: *const profsubd_mesh,
    options: *const profsubd_options,
    kind: i32,
    (out, capacity, needed): (*mut u32, usize, *mut usize),
    faces: bool,
) -> profsubd_status {
    copy_slice(
        (mesh, "mesh"),
        (out, "out", capacity, needed),
        (1, if faces { "faces" } else { "vertices" }),
        |m| {
            let kind = kind_of(kind)?;
            let opts = resolve(options, m.mesh())?;
            let list = osd_hazards(m.mesh(), &opts)
                .into_iter()
                .find(|h| h.kind == kind)
                .map(|h| if faces { h.faces } else { h.vertices })
                .unwrap_or_default();
            Ok((list.len(), list.into_iter()))
        },
    )
}

/// Copy the vertices of OpenSubdiv 3.5 hazard `kind` (a `profsubd_osd_hazard` value) on
/// `mesh` under `options` (NULL: the mesh's tags and the defaults), in increasing order;
/// none (`*needed` = 0) if the mesh has no such hazard. `capacity` and `*needed` count
/// vertices. A `kind` out of range gives `PROFSUBD_ERROR_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_get_osd_hazard_vertices(
    mesh: *const profsubd_mesh,
    options: *const profsubd_options,
    kind: i32,
    out: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_hazard(mesh, options, kind, (out, capacity, needed), false)
}

/// Copy the faces (not holes) on which OpenSubdiv 3.5 is wrong or unsafe for hazard `kind`,
/// in increasing order (see `profsubd_mesh_get_osd_hazard_vertices`; none for
/// `PROFSUBD_OSD_HAZARD_PRIMVAR_LIMIT`, a per-vertex hazard). `capacity` and `*needed`
/// count faces.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_get_osd_hazard_faces(
    mesh: *const profsubd_mesh,
    options: *const profsubd_options,
    kind: i32,
    out: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_hazard(mesh, options, kind, (out, capacity, needed), true)
}
