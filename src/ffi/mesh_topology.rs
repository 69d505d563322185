//! Topology queries on a mesh handle: OpenSubdiv's edges, vertex valences and the
//! validation report.

use std::borrow::Cow;
use std::mem::size_of;
use std::ops::Deref;

use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::handle;
use crate::ffi::mesh::{count_query, profsubd_mesh, MeshData};
use crate::ffi::options::{profsubd_options, resolve};
use crate::ffi::panic::status_call;
use crate::ffi::ptr::{arg_ref, copy_slice};
use crate::ffi::status::profsubd_status;
use crate::mesh::validate::MeshReport;
use crate::topology::Level;

/// Number of edges, as OpenSubdiv's level 0 counts them (a vertex pair used twice by one
/// face, or a degenerate pair, counts once per use).
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_num_edges(
    mesh: *const profsubd_mesh,
    out: *mut usize,
) -> profsubd_status {
    count_query(mesh, out, |m| m.level().num_edges())
}

/// Copy the edges: 2 vertex indices per edge, in OpenSubdiv's level-0 edge order (faces in
/// order, each face's edges in order, an edge numbered when first met). `capacity` and
/// `*needed` count edges (`vertices` holds `2 * capacity` indices).
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_get_edges(
    mesh: *const profsubd_mesh,
    vertices: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (mesh, "mesh"),
        (vertices, "vertices", capacity, needed),
        (2, "edges"),
        |m| {
            Ok(per_component(
                m.level(),
                Level::num_edges,
                Level::edge_vertices,
            ))
        },
    )
}

/// Copy the valence of each vertex: the number of edges incident to it (0 for a vertex in
/// no face). `capacity` and `*needed` count vertices.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_get_valences(
    mesh: *const profsubd_mesh,
    out: *mut u32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_slice(
        (mesh, "mesh"),
        (out, "out", capacity, needed),
        (1, "vertices"),
        |m| {
            Ok(per_component(m.level(), Level::num_vertices, |l, v| {
                [l.valence(v) as u32]
            }))
        },
    )
}

/// The base level under `options` (NULL: the mesh's tags and the defaults): the cached one
/// when the options resolve to the mesh's own.
unsafe fn level_for<'a>(
    m: &'a MeshData,
    options: *const profsubd_options,
) -> FfiResult<Cow<'a, Level>> {
    let opts = resolve(options, m.mesh())?;
    Ok(if opts == m.mesh().options().resolve() {
        Cow::Borrowed(m.level())
    } else {
        Cow::Owned(Level::from_mesh_with_options(m.mesh(), &opts))
    })
}

/// The count and the values (`value(level, i)` flattened, `i` below `count(level)`) of one
/// property of every edge or every vertex of `level`, for [`copy_slice`].
fn per_component<'a, V: IntoIterator + 'a>(
    level: impl Deref<Target = Level> + 'a,
    count: fn(&Level) -> usize,
    value: impl Fn(&Level, usize) -> V + 'a,
) -> (usize, impl Iterator<Item = V::Item> + 'a) {
    let n = count(&level);
    (n, (0..n).flat_map(move |i| value(&level, i)))
}

/// A copy-out query of one `f32` per edge or vertex of the base level under `options`.
unsafe fn copy_level_floats(
    mesh: *const profsubd_mesh,
    options: *const profsubd_options,
    (out, capacity, needed): (*mut f32, usize, *mut usize),
    unit: &str,
    count: fn(&Level) -> usize,
    value: fn(&Level, usize) -> f32,
) -> profsubd_status {
    copy_slice(
        (mesh, "mesh"),
        (out, "out", capacity, needed),
        (1, unit),
        |m| {
            let level = level_for(m, options)?;
            Ok(per_component(level, count, move |l, i| [value(l, i)]))
        },
    )
}

/// Copy the sharpness OpenSubdiv's Far gives each edge before refinement
/// (`Far::TopologyLevel::GetEdgeSharpness` of level 0), in `profsubd_mesh_get_edges` order:
/// the crease tags, with boundary and non-manifold edges infinitely sharp (10). `options`
/// may be NULL (the mesh's tags and the defaults apply). `capacity` and `*needed` count edges.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_get_edge_sharpness(
    mesh: *const profsubd_mesh,
    options: *const profsubd_options,
    out: *mut f32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_level_floats(
        mesh,
        options,
        (out, capacity, needed),
        "edges",
        Level::num_edges,
        Level::edge_sharpness,
    )
}

/// Copy the sharpness Far gives each vertex before refinement
/// (`Far::TopologyLevel::GetVertexSharpness` of level 0): the corner tags, with the corners
/// of the boundary (one face, two edges) infinitely sharp under
/// `PROFSUBD_BOUNDARY_EDGE_AND_CORNER` and non-manifold vertices sharpened as Far does.
/// `options` may be NULL. `capacity` and `*needed` count vertices.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_get_vertex_sharpness(
    mesh: *const profsubd_mesh,
    options: *const profsubd_options,
    out: *mut f32,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status {
    copy_level_floats(
        mesh,
        options,
        (out, capacity, needed),
        "vertices",
        Level::num_vertices,
        Level::vertex_sharpness,
    )
}

/// What a CAD user must know about a mesh before relying on it (see `profsubd_mesh_check`).
/// Edges are counted by vertex pair: a *boundary* edge is used by one face, a
/// *non-manifold* edge by more than two, an *inconsistent* edge twice in the same direction.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct profsubd_mesh_report {
    /// Set by the caller to `sizeof(profsubd_mesh_report)` before the call; the library sets
    /// it to the number of bytes it filled.
    pub struct_size: usize,
    /// Number of vertices, isolated ones included.
    pub num_vertices: usize,
    /// Number of edges, as OpenSubdiv counts them (`profsubd_mesh_num_edges`).
    pub num_edges: usize,
    /// Number of faces.
    pub num_faces: usize,
    /// Vertex pairs used by exactly one face.
    pub num_boundary_edges: usize,
    /// Connected pieces of the boundary edges.
    pub num_boundary_loops: usize,
    /// Vertex pairs used by more than two faces.
    pub num_non_manifold_edges: usize,
    /// Vertices OpenSubdiv tags non-manifold (bow-ties, non-manifold edges, no face).
    pub num_non_manifold_vertices: usize,
    /// Vertices in no face.
    pub num_isolated_vertices: usize,
    /// Faces in which some vertex appears more than once.
    pub num_faces_with_repeated_vertices: usize,
    /// Connected pieces of faces (joined through shared vertices).
    pub num_components: usize,
    /// V - E + F.
    pub euler_characteristic: i64,
    /// 1 if no non-manifold edge or vertex, no isolated vertex and no face repeating a
    /// vertex; else 0.
    pub is_manifold: i32,
    /// 1 if no edge is used twice in the same direction; else 0.
    pub is_consistently_oriented: i32,
    /// Vertex pairs used twice in the same direction (a flipped face).
    pub num_inconsistent_edges: usize,
}

impl From<&MeshReport> for profsubd_mesh_report {
    fn from(r: &MeshReport) -> Self {
        profsubd_mesh_report {
            struct_size: size_of::<profsubd_mesh_report>(),
            num_vertices: r.num_vertices,
            num_edges: r.num_edges,
            num_faces: r.num_faces,
            num_boundary_edges: r.boundary_edges.len(),
            num_boundary_loops: r.num_boundary_loops,
            num_non_manifold_edges: r.non_manifold_edges.len(),
            num_non_manifold_vertices: r.non_manifold_vertices.len(),
            num_isolated_vertices: r.isolated_vertices.len(),
            num_faces_with_repeated_vertices: r.faces_with_repeated_vertices.len(),
            num_components: r.num_components,
            euler_characteristic: r.euler_characteristic,
            is_manifold: r.is_manifold().into(),
            is_consistently_oriented: r.is_consistently_oriented().into(),
            num_inconsistent_edges: r.inconsistent_edges.len(),
        }
    }
}

/// Check the caller's `struct_size` before writing a report there.
unsafe fn report_out(out: *mut profsubd_mesh_report) -> FfiResult<*mut profsubd_mesh_report> {
    let size = *arg_ref(out.cast_const().cast::<usize>(), "out")?;
    let ours = size_of::<profsubd_mesh_report>();
    if size < ours {
        return Err(FfiError::invalid_argument(format!(
            "out->struct_size is {size}, smaller than the first version of the struct; set it \
             to sizeof(profsubd_mesh_report) ({ours})"
        )));
    }
    Ok(out)
}

/// Examine the mesh and fill `*out`. The caller sets `out->struct_size =
/// sizeof(profsubd_mesh_report)` first (a smaller value gives
/// `PROFSUBD_ERROR_INVALID_ARGUMENT`); a larger struct from a newer header is filled up to
/// the fields this library knows, and `out->struct_size` is set to the bytes filled.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_check(
    mesh: *const profsubd_mesh,
    out: *mut profsubd_mesh_report,
) -> profsubd_status {
    status_call(|| {
        let m = handle::borrow(mesh, "mesh")?;
        let out = report_out(out)?;
        let report = profsubd_mesh_report::from(&m.mesh().check());
        out.write(report);
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::error::last_error;
    use crate::ffi::mesh::{new_mesh_handle, profsubd_mesh_free};
    use crate::ffi::status::profsubd_status::*;
    use crate::mesh::{Mesh, MeshParts};
    use glam::DVec3;
    use std::ptr::{null, null_mut};

    /// A 2x2 grid of quads (9 vertices, 12 edges) with the top-right quad flipped when
    /// `flip` is set.
    fn grid(flip: bool) -> *mut profsubd_mesh {
        let positions = (0..9)
            .map(|i| DVec3::new((i % 3) as f64, (i / 3) as f64, 0.0))
            .collect();
        let mut face_indices = vec![0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7];
        if flip {
            face_indices[12..].reverse();
        }
        let mesh = Mesh::from_parts(MeshParts {
            positions,
            face_sizes: vec![4; 4],
            face_indices,
            ..Default::default()
        })
        .unwrap();
        new_mesh_handle(mesh)
    }

    #[test]
    fn edges_follow_opensubdiv_order_and_valences_count_them() {
        let m = grid(false);
        unsafe {
            let mut n = 0;
            assert_eq!(profsubd_mesh_num_edges(m, &mut n), PROFSUBD_OK);
            assert_eq!(n, 12);
            let mut edges = [0u32; 24];
            assert_eq!(
                profsubd_mesh_get_edges(m, edges.as_mut_ptr(), 12, &mut n),
                PROFSUBD_OK
            );
            // Face 0 gives edges 0-3, face 1 adds 1-2, 2-5, 5-4 (4-1 is known), and so on.
            let expected = [
                [0, 1],
                [1, 4],
                [4, 3],
                [3, 0],
                [1, 2],
                [2, 5],
                [5, 4],
                [4, 7],
                [7, 6],
                [6, 3],
                [5, 8],
                [8, 7],
            ];
            assert_eq!(
                edges.chunks(2).map(|e| [e[0], e[1]]).collect::<Vec<_>>(),
                expected
            );
            assert_eq!(n, 12);
            let mut valences = [0u32; 9];
            assert_eq!(
                profsubd_mesh_get_valences(m, valences.as_mut_ptr(), 9, &mut n),
                PROFSUBD_OK
            );
            assert_eq!(valences, [2, 3, 2, 3, 4, 3, 2, 3, 2]);
            let mut small = [9u32; 23];
            assert_eq!(
                profsubd_mesh_get_edges(m, small.as_mut_ptr(), 11, &mut n),
                PROFSUBD_ERROR_BUFFER_TOO_SMALL
            );
            assert_eq!((n, small), (12, [9; 23]));
            assert_eq!(
                profsubd_mesh_get_valences(m, null_mut(), 0, &mut n),
                PROFSUBD_ERROR_BUFFER_TOO_SMALL
            );
            assert_eq!(n, 9);
            profsubd_mesh_free(m);
        }
    }

    #[test]
    fn sharpness_is_what_far_assigns_under_the_options() {
        let mut parts = Mesh::from_parts(MeshParts {
            positions: (0..9)
                .map(|i| DVec3::new((i % 3) as f64, (i / 3) as f64, 0.0))
                .collect(),
            face_sizes: vec![4; 4],
            face_indices: vec![0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7],
            ..Default::default()
        })
        .unwrap()
        .into_parts();
        parts.creases.push(crate::mesh::Crease {
            vertices: [4, 1],
            sharpness: 2.5,
        });
        parts.corners.push(crate::mesh::Corner {
            vertex: 4,
            sharpness: 1.25,
        });
        let m = new_mesh_handle(Mesh::from_parts(parts).unwrap());
        let mut o = null_mut();
        let (mut edges, mut verts, mut n) = ([0f32; 12], [0f32; 9], 0);
        unsafe {
            assert_eq!(
                profsubd_mesh_get_edge_sharpness(m, null(), edges.as_mut_ptr(), 12, &mut n),
                PROFSUBD_OK
            );
            // Edge order as in the test above: 1-4 is edge 1; 4-5 (6), 4-7 (7), 3-4 (2) are
            // interior; the rest are boundary.
            let inf = 10.0;
            let expected = [inf, 2.5, 0.0, inf, inf, inf, 0.0, 0.0, inf, inf, inf, inf];
            assert_eq!((edges, n), (expected, 12));
            assert_eq!(
                profsubd_mesh_get_vertex_sharpness(m, null(), verts.as_mut_ptr(), 9, &mut n),
                PROFSUBD_OK
            );
            assert_eq!(verts, [inf, 0.0, inf, 0.0, 1.25, 0.0, inf, 0.0, inf]);
            // Edge-only boundaries: the four corners are no longer sharpened.
            crate::ffi::options::profsubd_options_new(&mut o);
            crate::ffi::options::profsubd_options_set_boundary(o, 1);
            assert_eq!(
                profsubd_mesh_get_vertex_sharpness(m, o, verts.as_mut_ptr(), 9, &mut n),
                PROFSUBD_OK
            );
            assert_eq!(verts, [0.0, 0.0, 0.0, 0.0, 1.25, 0.0, 0.0, 0.0, 0.0]);
            let mut small = [7f32; 8];
            assert_eq!(
                profsubd_mesh_get_vertex_sharpness(m, o, small.as_mut_ptr(), 8, &mut n),
                PROFSUBD_ERROR_BUFFER_TOO_SMALL
            );
            assert_eq!((small, n), ([7.0; 8], 9));
            // Bad options handle, NULL buffer.
            let fake = [0u64; 4];
            let f = fake.as_ptr().cast::<profsubd_options>();
            assert_eq!(
                profsubd_mesh_get_edge_sharpness(m, f, edges.as_mut_ptr(), 12, &mut n),
                PROFSUBD_ERROR_INVALID_HANDLE
            );
            assert_eq!(
                profsubd_mesh_get_vertex_sharpness(m, null(), null_mut(), 9, &mut n),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            crate::ffi::options::profsubd_options_free(o);
            profsubd_mesh_free(m);
        }
    }

    #[test]
    fn report_counts_boundary_and_orientation() {
        let m = grid(false);
        let mut r = profsubd_mesh_report {
            struct_size: size_of::<profsubd_mesh_report>(),
            ..Default::default()
        };
        unsafe {
            assert_eq!(profsubd_mesh_check(m, &mut r), PROFSUBD_OK);
            profsubd_mesh_free(m);
        }
        let expected = profsubd_mesh_report {
            struct_size: size_of::<profsubd_mesh_report>(),
            num_vertices: 9,
            num_edges: 12,
            num_faces: 4,
            num_boundary_edges: 8,
            num_boundary_loops: 1,
            num_components: 1,
            euler_characteristic: 1,
            is_manifold: 1,
            is_consistently_oriented: 1,
            ..Default::default()
        };
        assert_eq!(r, expected);
        let m = grid(true);
        unsafe {
            assert_eq!(profsubd_mesh_check(m, &mut r), PROFSUBD_OK);
            profsubd_mesh_free(m);
        }
        assert_eq!((r.is_consistently_oriented, r.is_manifold), (0, 0));
        assert_eq!(r.num_inconsistent_edges, 2);
    }

    #[test]
    fn report_struct_size_is_checked_and_larger_structs_are_filled_in_part() {
        let m = grid(false);
        let ours = size_of::<profsubd_mesh_report>();
        unsafe {
            let mut r = profsubd_mesh_report {
                struct_size: ours - 8,
                ..Default::default()
            };
            assert_eq!(
                profsubd_mesh_check(m, &mut r),
                PROFSUBD_ERROR_INVALID_ARGUMENT
            );
            assert!(last_error().contains("set it to sizeof(profsubd_mesh_report)"));
            assert_eq!(r.num_vertices, 0);
            // A newer, larger struct: our part is filled, the rest left alone.
            #[repr(C)]
            struct Newer {
                report: profsubd_mesh_report,
                extra: u64,
            }
            let mut newer = Newer {
                report: profsubd_mesh_report {
                    struct_size: ours + 8,
                    ..Default::default()
                },
                extra: 77,
            };
            assert_eq!(profsubd_mesh_check(m, &mut newer.report), PROFSUBD_OK);
            assert_eq!(
                (
                    newer.report.struct_size,
                    newer.report.num_edges,
                    newer.extra
                ),
                (ours, 12, 77)
            );
            profsubd_mesh_free(m);
        }
    }

    #[test]
    fn null_and_invalid_handles_are_rejected() {
        let m = grid(false);
        let mut fake = [0u64; 8];
        let f = fake.as_mut_ptr().cast::<profsubd_mesh>();
        let mut n = 0;
        let mut buf = [0u32; 24];
        let mut fbuf = [0f32; 12];
        let mut r = profsubd_mesh_report {
            struct_size: size_of::<profsubd_mesh_report>(),
            ..Default::default()
        };
        unsafe {
            for (h, status) in [
                (null(), PROFSUBD_ERROR_NULL_ARGUMENT),
                (f.cast_const(), PROFSUBD_ERROR_INVALID_HANDLE),
            ] {
                assert_eq!(profsubd_mesh_num_edges(h, &mut n), status);
                assert_eq!(
                    profsubd_mesh_get_edges(h, buf.as_mut_ptr(), 12, &mut n),
                    status
                );
                assert_eq!(
                    profsubd_mesh_get_valences(h, buf.as_mut_ptr(), 9, &mut n),
                    status
                );
                assert_eq!(profsubd_mesh_check(h, &mut r), status);
                let fs = fbuf.as_mut_ptr();
                assert_eq!(
                    profsubd_mesh_get_edge_sharpness(h, null(), fs, 12, &mut n),
                    status
                );
                assert_eq!(
                    profsubd_mesh_get_vertex_sharpness(h, null(), fs, 9, &mut n),
                    status
                );
            }
            assert_eq!(
                profsubd_mesh_num_edges(m, null_mut()),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(
                profsubd_mesh_get_edges(m, null_mut(), 12, &mut n),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(
                last_error(),
                "argument `vertices` is NULL but capacity is 12"
            );
            assert_eq!(
                profsubd_mesh_get_valences(m, null_mut(), 9, &mut n),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(
                profsubd_mesh_check(m, null_mut()),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            profsubd_mesh_free(m);
        }
        assert_eq!((n, buf, r.num_vertices, fake), (0, [0; 24], 0, [0; 8]));
    }
}
