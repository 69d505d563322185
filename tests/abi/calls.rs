//! A C caller written in Rust: it sees the library only through bindgen's translation of
//! `include/profsubd.h` (included below) and is linked against the built `libprofsubd.so`.
//! Compiled and run by `tests/abi_bindgen.rs`; arguments: the Rust-side sizes of
//! `profsubd_mesh_desc` and `profsubd_mesh_report`, a scratch directory, and the bundled
//! example `examples/meshes/cube_creased.obj`.

#![allow(
    non_camel_case_types,
    non_upper_case_globals,
    non_snake_case,
    dead_code
)]

include!(env!("PROFSUBD_BINDINGS"));
include!(env!("PROFSUBD_SYMBOLS"));

use std::ffi::{CStr, CString};
use std::ptr::{null, null_mut};

fn last_error() -> String {
    unsafe { CStr::from_ptr(profsubd_last_error_message()) }
        .to_string_lossy()
        .into_owned()
}

fn check(status: profsubd_status, expected: profsubd_status, what: &str) {
    assert_eq!(
        status,
        expected,
        "{what}: status {status}, message `{}`",
        last_error()
    );
}

struct Square {
    positions: Vec<f64>,
    face_sizes: Vec<u32>,
    face_indices: Vec<u32>,
    crease_vertices: Vec<u32>,
    crease_sharpness: Vec<f32>,
    corner_vertices: Vec<u32>,
    corner_sharpness: Vec<f32>,
}

impl Square {
    /// A 2x1 strip of quads with a crease on the middle edge and a corner.
    fn new() -> Self {
        Square {
            positions: vec![
                0.0,
                0.0,
                0.0,
                0.5,
                0.0,
                0.1,
                1.0,
                0.0,
                0.0,
                0.0,
                1.0,
                0.0,
                0.5,
                1.0,
                0.1,
                1.0,
                1.0,
                1.0 / 3.0,
            ],
            face_sizes: vec![4, 4],
            face_indices: vec![0, 1, 4, 3, 1, 2, 5, 4],
            crease_vertices: vec![1, 4],
            crease_sharpness: vec![1.5],
            corner_vertices: vec![2],
            corner_sharpness: vec![10.0],
        }
    }

    fn desc(&self) -> profsubd_mesh_desc {
        profsubd_mesh_desc {
            struct_size: std::mem::size_of::<profsubd_mesh_desc>(),
            positions: self.positions.as_ptr(),
            num_vertices: self.positions.len() / 3,
            face_sizes: self.face_sizes.as_ptr(),
            num_faces: self.face_sizes.len(),
            face_indices: self.face_indices.as_ptr(),
            num_face_indices: self.face_indices.len(),
            crease_vertices: self.crease_vertices.as_ptr(),
            crease_sharpness: self.crease_sharpness.as_ptr(),
            num_creases: self.crease_sharpness.len(),
            corner_vertices: self.corner_vertices.as_ptr(),
            corner_sharpness: self.corner_sharpness.as_ptr(),
            num_corners: self.corner_sharpness.len(),
            hole_faces: null(),
            num_holes: 0,
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let rust_desc_size: usize = args[1].parse().unwrap();
    let rust_report_size: usize = args[2].parse().unwrap();
    let work = std::path::PathBuf::from(&args[3]);
    let cube = CString::new(args[4].as_str()).unwrap();
    let mut checks = 0;

    // Every function the header declares resolved to an address in the library.
    for (name, address) in symbols() {
        assert_ne!(address, 0, "{name} did not resolve");
        checks += 1;
    }

    // Layouts: bindgen (clang reading the header) and rustc agree.
    assert_eq!(std::mem::size_of::<profsubd_mesh_desc>(), rust_desc_size);
    assert_eq!(
        std::mem::size_of::<profsubd_mesh_report>(),
        rust_report_size
    );
    checks += 1;

    unsafe {
        // Versions.
        assert_eq!(profsubd_version_major(), PROFSUBD_VERSION_MAJOR);
        assert_eq!(profsubd_version_minor(), PROFSUBD_VERSION_MINOR);
        assert_eq!(profsubd_version_patch(), PROFSUBD_VERSION_PATCH);
        let v = CStr::from_ptr(profsubd_version_string())
            .to_str()
            .unwrap()
            .to_owned();
        assert_eq!(
            v,
            format!("{PROFSUBD_VERSION_MAJOR}.{PROFSUBD_VERSION_MINOR}.{PROFSUBD_VERSION_PATCH}")
        );
        let s = |c| {
            CStr::from_ptr(profsubd_status_string(c))
                .to_str()
                .unwrap()
                .to_owned()
        };
        assert_eq!(
            s(PROFSUBD_ERROR_BUFFER_TOO_SMALL as i32),
            "buffer too small"
        );
        assert_eq!(s(12345), "unknown status");
        checks += 2;

        // Round trip.
        let sq = Square::new();
        let mut mesh = null_mut();
        check(
            profsubd_mesh_new(&sq.desc(), &mut mesh),
            PROFSUBD_OK,
            "mesh_new",
        );
        assert_eq!(last_error(), "");
        let mut n = 0usize;
        type Count = unsafe extern "C" fn(*const profsubd_mesh, *mut usize) -> profsubd_status;
        let counts: [(Count, &str, usize); 6] = [
            (profsubd_mesh_num_vertices, "num_vertices", 6),
            (profsubd_mesh_num_faces, "num_faces", 2),
            (profsubd_mesh_num_face_indices, "num_face_indices", 8),
            (profsubd_mesh_num_creases, "num_creases", 1),
            (profsubd_mesh_num_corners, "num_corners", 1),
            (profsubd_mesh_num_holes, "num_holes", 0),
        ];
        for (count, what, expected) in counts {
            check(count(mesh, &mut n), PROFSUBD_OK, what);
            assert_eq!(n, expected, "{what}");
        }
        let mut positions = vec![0.0f64; 18];
        check(
            profsubd_mesh_get_positions(mesh, positions.as_mut_ptr(), 18, &mut n),
            PROFSUBD_OK,
            "get_positions",
        );
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&positions), bits(&sq.positions));
        assert_eq!(n, 18);
        let mut indices = vec![0u32; 8];
        check(
            profsubd_mesh_get_face_indices(mesh, indices.as_mut_ptr(), 8, null_mut()),
            PROFSUBD_OK,
            "get_face_indices",
        );
        assert_eq!(indices, sq.face_indices);
        let (mut cv, mut cs) = ([0u32; 2], [0f32; 1]);
        check(
            profsubd_mesh_get_creases(mesh, cv.as_mut_ptr(), cs.as_mut_ptr(), 1, &mut n),
            PROFSUBD_OK,
            "get_creases",
        );
        assert_eq!((cv, cs, n), ([1, 4], [1.5], 1));
        let (mut kv, mut ks) = ([0u32; 1], [0f32; 1]);
        check(
            profsubd_mesh_get_corners(mesh, kv.as_mut_ptr(), ks.as_mut_ptr(), 1, &mut n),
            PROFSUBD_OK,
            "get_corners",
        );
        assert_eq!((kv, ks), ([2], [10.0]));
        checks += 10;

        // Too small: needed reported, buffer untouched.
        let mut small = [-1.0f64; 5];
        n = 0;
        check(
            profsubd_mesh_get_positions(mesh, small.as_mut_ptr(), 5, &mut n),
            PROFSUBD_ERROR_BUFFER_TOO_SMALL,
            "small positions",
        );
        assert_eq!((n, small), (18, [-1.0; 5]));
        assert_eq!(
            last_error(),
            "buffer too small: capacity is 5 doubles, 18 needed"
        );
        n = 0;
        check(
            profsubd_mesh_get_face_sizes(mesh, null_mut(), 0, &mut n),
            PROFSUBD_ERROR_BUFFER_TOO_SMALL,
            "size query",
        );
        assert_eq!(n, 2);
        checks += 2;

        // NULL arguments.
        check(
            profsubd_mesh_num_vertices(null(), &mut n),
            PROFSUBD_ERROR_NULL_ARGUMENT,
            "NULL mesh",
        );
        assert_eq!(last_error(), "argument `mesh` is NULL");
        check(
            profsubd_mesh_num_vertices(mesh, null_mut()),
            PROFSUBD_ERROR_NULL_ARGUMENT,
            "NULL out",
        );
        let mut other = null_mut();
        check(
            profsubd_mesh_new(null(), &mut other),
            PROFSUBD_ERROR_NULL_ARGUMENT,
            "NULL desc",
        );
        check(
            profsubd_mesh_new(&sq.desc(), null_mut()),
            PROFSUBD_ERROR_NULL_ARGUMENT,
            "NULL out",
        );
        assert!(other.is_null());
        check(
            profsubd_mesh_get_positions(mesh, null_mut(), 3, &mut n),
            PROFSUBD_ERROR_NULL_ARGUMENT,
            "NULL buffer",
        );
        checks += 5;

        // Bad descriptors and meshes.
        let mut d = sq.desc();
        d.struct_size = 16;
        check(
            profsubd_mesh_new(&d, &mut other),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "struct_size",
        );
        let mut d = sq.desc();
        d.num_faces = usize::MAX;
        check(
            profsubd_mesh_new(&d, &mut other),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "absurd count",
        );
        let mut bad = Square::new();
        bad.positions[7] = f64::NAN;
        check(
            profsubd_mesh_new(&bad.desc(), &mut other),
            PROFSUBD_ERROR_INVALID_MESH,
            "NaN",
        );
        assert_eq!(
            last_error(),
            "invalid mesh: vertex 2 has a non-finite coordinate (1 NaN 0)"
        );
        let mut bad = Square::new();
        bad.face_sizes = vec![2, 6];
        check(
            profsubd_mesh_new(&bad.desc(), &mut other),
            PROFSUBD_ERROR_INVALID_MESH,
            "2-gon",
        );
        assert!(other.is_null());
        checks += 4;

        // Options, and handles of the wrong kind.
        let mut options = null_mut();
        check(
            profsubd_options_new(&mut options),
            PROFSUBD_OK,
            "options_new",
        );
        check(
            profsubd_options_set_boundary(options, PROFSUBD_BOUNDARY_EDGE_ONLY as i32),
            PROFSUBD_OK,
            "set_boundary",
        );
        check(
            profsubd_options_set_boundary(options, 3),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "3",
        );
        check(
            profsubd_options_set_crease_method(options, -1),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "-1",
        );
        check(
            profsubd_options_set_triangle_rule(options, 2),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "2",
        );
        check(
            profsubd_mesh_num_vertices(options.cast(), &mut n),
            PROFSUBD_ERROR_INVALID_HANDLE,
            "options as mesh",
        );
        check(
            profsubd_options_set_boundary(mesh.cast(), 0),
            PROFSUBD_ERROR_INVALID_HANDLE,
            "mesh as options",
        );
        assert!(last_error().contains("not a live profsubd_options"));
        profsubd_options_free(options);
        profsubd_options_free(null_mut());
        checks += 5;

        // Topology: OpenSubdiv's edges of the strip, valences, the report.
        check(
            profsubd_mesh_num_edges(mesh, &mut n),
            PROFSUBD_OK,
            "num_edges",
        );
        assert_eq!(n, 7);
        let mut edges = [0u32; 14];
        check(
            profsubd_mesh_get_edges(mesh, edges.as_mut_ptr(), 7, &mut n),
            PROFSUBD_OK,
            "get_edges",
        );
        assert_eq!(edges, [0, 1, 1, 4, 4, 3, 3, 0, 1, 2, 2, 5, 5, 4]);
        let mut valences = [0u32; 6];
        check(
            profsubd_mesh_get_valences(mesh, valences.as_mut_ptr(), 6, &mut n),
            PROFSUBD_OK,
            "get_valences",
        );
        assert_eq!(valences, [2, 3, 2, 2, 3, 2]);
        let mut edge_sharpness = [0f32; 7];
        check(
            profsubd_mesh_get_edge_sharpness(mesh, null(), edge_sharpness.as_mut_ptr(), 7, &mut n),
            PROFSUBD_OK,
            "get_edge_sharpness",
        );
        assert_eq!(edge_sharpness, [10.0, 1.5, 10.0, 10.0, 10.0, 10.0, 10.0]);
        let mut vertex_sharpness = [0f32; 6];
        check(
            profsubd_mesh_get_vertex_sharpness(
                mesh,
                null(),
                vertex_sharpness.as_mut_ptr(),
                6,
                &mut n,
            ),
            PROFSUBD_OK,
            "get_vertex_sharpness",
        );
        assert_eq!(vertex_sharpness, [10.0, 0.0, 10.0, 10.0, 0.0, 10.0]);
        let mut report: profsubd_mesh_report = std::mem::zeroed();
        report.struct_size = std::mem::size_of::<profsubd_mesh_report>();
        check(profsubd_mesh_check(mesh, &mut report), PROFSUBD_OK, "check");
        assert_eq!(
            (
                report.num_vertices,
                report.num_edges,
                report.num_faces,
                report.num_boundary_edges
            ),
            (6, 7, 2, 6)
        );
        assert_eq!((report.num_boundary_loops, report.num_components), (1, 1));
        assert_eq!(report.euler_characteristic, 1);
        assert_eq!(
            (report.is_manifold, report.is_consistently_oriented),
            (1, 1)
        );
        report.struct_size = 8;
        check(
            profsubd_mesh_check(mesh, &mut report),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "size",
        );
        checks += 6;

        // OBJ: write, read back, same data; the bundled example; a missing file.
        let path = CString::new(work.join("strip.obj").to_str().unwrap()).unwrap();
        check(
            profsubd_mesh_write_obj(mesh, path.as_ptr()),
            PROFSUBD_OK,
            "write_obj",
        );
        let mut back = null_mut();
        check(
            profsubd_mesh_read_obj(path.as_ptr(), &mut back),
            PROFSUBD_OK,
            "read_obj",
        );
        let mut again = vec![0.0f64; 18];
        check(
            profsubd_mesh_get_positions(back, again.as_mut_ptr(), 18, &mut n),
            PROFSUBD_OK,
            "positions read back",
        );
        assert_eq!(bits(&again), bits(&sq.positions));
        check(
            profsubd_mesh_get_creases(back, cv.as_mut_ptr(), cs.as_mut_ptr(), 1, &mut n),
            PROFSUBD_OK,
            "creases read back",
        );
        assert_eq!((cv, cs), ([1, 4], [1.5]));
        check(
            profsubd_mesh_num_warnings(back, &mut n),
            PROFSUBD_OK,
            "num_warnings",
        );
        assert_eq!(n, 0);
        let mut warning = null();
        check(
            profsubd_mesh_get_warning(back, 0, &mut warning),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "no warning 0",
        );
        profsubd_mesh_free(back);
        let mut cube_mesh = null_mut();
        check(
            profsubd_mesh_read_obj(cube.as_ptr(), &mut cube_mesh),
            PROFSUBD_OK,
            "cube",
        );
        check(
            profsubd_mesh_num_edges(cube_mesh, &mut n),
            PROFSUBD_OK,
            "cube edges",
        );
        assert_eq!(n, 12);
        check(
            profsubd_mesh_num_creases(cube_mesh, &mut n),
            PROFSUBD_OK,
            "cube creases",
        );
        assert_eq!(n, 5);
        check(
            profsubd_mesh_check(cube_mesh, &mut report),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "8",
        );
        report.struct_size = std::mem::size_of::<profsubd_mesh_report>();
        check(
            profsubd_mesh_check(cube_mesh, &mut report),
            PROFSUBD_OK,
            "cube check",
        );
        assert_eq!(
            (report.euler_characteristic, report.num_boundary_edges),
            (2, 0)
        );
        profsubd_mesh_free(cube_mesh);
        let missing = CString::new(work.join("missing.obj").to_str().unwrap()).unwrap();
        check(
            profsubd_mesh_read_obj(missing.as_ptr(), &mut back),
            PROFSUBD_ERROR_IO,
            "missing",
        );
        assert!(last_error().contains("missing.obj"));
        check(
            profsubd_mesh_read_obj(null(), &mut back),
            PROFSUBD_ERROR_NULL_ARGUMENT,
            "NULL path",
        );
        check(
            profsubd_mesh_write_obj(mesh, null()),
            PROFSUBD_ERROR_NULL_ARGUMENT,
            "NULL path",
        );
        checks += 6;

        profsubd_mesh_free(mesh);
        profsubd_mesh_free(null_mut());
    }
    println!("{checks} checks passed through the header's declarations");
}
