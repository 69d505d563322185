//! `profsubd_refine_uniform` called as C would: results equal the Rust API's, options
//! override tags, bad input gives the documented status and writes nothing.

use std::ptr;

use glam::DVec3;
use profsubd::ffi::error::last_error;
use profsubd::ffi::mesh::{mesh_arg, new_mesh_handle, profsubd_mesh, profsubd_mesh_free};
use profsubd::ffi::options::{
    profsubd_options, profsubd_options_free, profsubd_options_new, profsubd_options_set_boundary,
};
use profsubd::ffi::refine::{profsubd_options_set_vertex_order, profsubd_refine_uniform};
use profsubd::ffi::status::profsubd_status::{self, *};
use profsubd::refine::{refine_uniform, refine_uniform_ordered, VertexOrder};
use profsubd::{BoundaryInterpolation, Mesh, MeshParts, SubdivOptions};

fn quad() -> Mesh {
    Mesh::from_parts(MeshParts {
        positions: vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ],
        face_sizes: vec![4],
        face_indices: vec![0, 1, 2, 3],
        ..Default::default()
    })
    .unwrap()
}

unsafe fn refine(
    mesh: *const profsubd_mesh,
    options: *const profsubd_options,
    level: u32,
) -> (profsubd_status, *mut profsubd_mesh) {
    let mut out: *mut profsubd_mesh = ptr::null_mut();
    let st = profsubd_refine_uniform(mesh, options, level, &mut out);
    (st, out)
}

#[test]
fn refines_like_the_rust_api_and_applies_options() {
    unsafe {
        let m = new_mesh_handle(quad());
        let (st, out) = refine(m, ptr::null(), 2);
        assert_eq!(st, PROFSUBD_OK);
        let expected = refine_uniform(&quad(), &SubdivOptions::default(), 2).unwrap();
        assert_eq!(mesh_arg(out, "out").unwrap(), &expected);
        profsubd_mesh_free(out);

        let mut o: *mut profsubd_options = ptr::null_mut();
        assert_eq!(profsubd_options_new(&mut o), PROFSUBD_OK);
        assert_eq!(profsubd_options_set_boundary(o, 1), PROFSUBD_OK);
        let (st, out) = refine(m, o, 1);
        assert_eq!(st, PROFSUBD_OK);
        let r = mesh_arg(out, "out").unwrap();
        // Edge-only: the corner moves along the boundary curves.
        assert_eq!(r.positions()[0], DVec3::new(0.125, 0.125, 0.0));
        assert_eq!(r.options().boundary, Some(BoundaryInterpolation::EdgeOnly));
        profsubd_mesh_free(out);
        profsubd_options_free(o);
        profsubd_mesh_free(m);
    }
}

#[test]
fn bad_input_gives_a_status_and_no_output() {
    unsafe {
        let m = new_mesh_handle(quad());
        let mut out: *mut profsubd_mesh = ptr::null_mut();
        assert_eq!(
            profsubd_refine_uniform(ptr::null(), ptr::null(), 1, &mut out),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert!(last_error().contains("mesh"));
        assert!(out.is_null());
        assert_eq!(
            profsubd_refine_uniform(m, ptr::null(), 1, ptr::null_mut()),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert!(last_error().contains("out"));
        let (st, out) = refine(m, ptr::null(), 9);
        assert_eq!(st, PROFSUBD_ERROR_INVALID_ARGUMENT);
        assert!(
            last_error().contains("above the maximum 8"),
            "{}",
            last_error()
        );
        assert!(out.is_null());
        // A mesh handle where options are expected, and the reverse.
        let (st, out) = refine(m, m.cast(), 1);
        assert_eq!(st, PROFSUBD_ERROR_INVALID_HANDLE);
        assert!(out.is_null());
        let mut o: *mut profsubd_options = ptr::null_mut();
        assert_eq!(profsubd_options_new(&mut o), PROFSUBD_OK);
        let (st, out) = refine(o.cast(), ptr::null(), 1);
        assert_eq!(st, PROFSUBD_ERROR_INVALID_HANDLE);
        assert!(out.is_null());
        profsubd_options_free(o);
        profsubd_mesh_free(m);
    }
}

#[test]
fn vertex_order_setting() {
    unsafe {
        let m = new_mesh_handle(quad());
        let mut o: *mut profsubd_options = ptr::null_mut();
        assert_eq!(profsubd_options_new(&mut o), PROFSUBD_OK);
        assert_eq!(
            profsubd_options_set_vertex_order(o, 2),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("vertex order value 2"));
        assert_eq!(
            profsubd_options_set_vertex_order(ptr::null_mut(), 1),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert_eq!(profsubd_options_set_vertex_order(o, 1), PROFSUBD_OK);
        let (st, out) = refine(m, o, 2);
        assert_eq!(st, PROFSUBD_OK);
        let expected = refine_uniform_ordered(
            &quad(),
            &SubdivOptions::default(),
            2,
            VertexOrder::FacesFirst,
        )
        .unwrap();
        assert_eq!(mesh_arg(out, "out").unwrap(), &expected);
        // Faces first: vertex 0 is the face point of the first level-1 quad.
        assert_eq!(expected.positions()[0], DVec3::new(0.25, 0.25, 0.0));
        profsubd_mesh_free(out);
        profsubd_options_free(o);
        profsubd_mesh_free(m);
    }
}
