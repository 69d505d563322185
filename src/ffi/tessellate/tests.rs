//! Tests of the tessellation C functions, bad input first.

use std::ptr::{null, null_mut};

use super::*;
use crate::eval::Evaluator;
use crate::ffi::error::last_error;
use crate::ffi::evaluator::{profsubd_evaluator_free, profsubd_evaluator_new};
use crate::ffi::mesh::{new_mesh_handle, profsubd_mesh_free};
use crate::ffi::status::profsubd_status::*;
use crate::mesh::Mesh;
use crate::options::SubdivOptions;
use crate::test_support::unit_cube;

fn cube() -> Mesh {
    unit_cube(Vec::new())
}

fn evaluator() -> *mut profsubd_evaluator {
    let m = new_mesh_handle(cube());
    let mut ev = null_mut();
    unsafe {
        assert_eq!(profsubd_evaluator_new(m, null(), &mut ev), PROFSUBD_OK);
        profsubd_mesh_free(m);
    }
    ev
}

#[test]
fn bad_arguments_give_statuses_and_leave_outputs() {
    let ev = evaluator();
    let mut out = null_mut();
    unsafe {
        assert_eq!(
            profsubd_tessellation_new_uniform(null(), 2, 0, &mut out),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert_eq!(
            profsubd_tessellation_new_uniform(ev, 0, 0, &mut out),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("rate 0"), "{}", last_error());
        assert_eq!(
            profsubd_tessellation_new_adaptive(ev, -1.0, 8, 0, &mut out),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            profsubd_tessellation_new_adaptive(ev, 1e-3, 0, 0, &mut out),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(out.is_null());
        let wrong = ev.cast::<profsubd_tessellation>();
        let mut n = 5usize;
        assert_eq!(
            profsubd_tessellation_counts(
                wrong,
                &mut n,
                null_mut(),
                null_mut(),
                null_mut(),
                null_mut()
            ),
            PROFSUBD_ERROR_INVALID_HANDLE
        );
        assert_eq!(n, 5);
        assert_eq!(
            profsubd_tessellation_new_uniform(ev, 2, 1, &mut out),
            PROFSUBD_OK
        );
        let path = c"/nonexistent-dir/x.stl";
        assert_eq!(
            profsubd_tessellation_write(out, path.as_ptr(), 0, 0),
            PROFSUBD_ERROR_IO
        );
        assert_eq!(
            profsubd_tessellation_write(out, path.as_ptr(), 5, 0),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            profsubd_tessellation_write(out, path.as_ptr(), 0, 2),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        profsubd_tessellation_free(out);
        profsubd_evaluator_free(ev);
    }
}

#[test]
fn getters_copy_the_rust_tessellation() {
    let ev = evaluator();
    let rust = tessellate(
        &Evaluator::new(&cube(), &SubdivOptions::default()).unwrap(),
        &TessellateOptions {
            rate: Rate::Uniform(3),
            ..TessellateOptions::default()
        },
    )
    .unwrap();
    let mut t = null_mut();
    unsafe {
        assert_eq!(
            profsubd_tessellation_new_uniform(ev, 3, 0, &mut t),
            PROFSUBD_OK
        );
        let (mut nv, mut nf, mut nfv, mut nn, mut nu) = (0, 0, 0, 0, 9);
        assert_eq!(
            profsubd_tessellation_counts(t, &mut nv, &mut nf, &mut nfv, &mut nn, &mut nu),
            PROFSUBD_OK
        );
        assert_eq!((nv, nf, nfv, nn, nu), (56, 108, 324, 56, 0));
        let mut needed = 0;
        let mut pos = vec![0.0; 3 * nv];
        assert_eq!(
            profsubd_tessellation_get_positions(t, pos.as_mut_ptr(), nv, &mut needed),
            PROFSUBD_OK
        );
        assert_eq!(needed, nv);
        let want: Vec<f64> = rust.positions.iter().flat_map(|p| p.to_array()).collect();
        assert_eq!(pos, want);
        let mut fv = vec![0u32; nfv];
        assert_eq!(
            profsubd_tessellation_get_face_vertices(t, fv.as_mut_ptr(), nfv, &mut needed),
            PROFSUBD_OK
        );
        assert_eq!(fv, rust.face_vertices);
        let mut small = vec![0u32; 2];
        assert_eq!(
            profsubd_tessellation_get_face_sizes(t, small.as_mut_ptr(), 2, &mut needed),
            PROFSUBD_ERROR_BUFFER_TOO_SMALL
        );
        assert_eq!(needed, nf);
        let mut pts = vec![0.0; 3 * nv];
        assert_eq!(
            profsubd_tessellation_get_vertex_points(t, pts.as_mut_ptr(), nv, &mut needed),
            PROFSUBD_OK
        );
        assert_eq!(pts[0] as u32, rust.points[0].face);
        profsubd_tessellation_free(t);
        profsubd_evaluator_free(ev);
    }
}
