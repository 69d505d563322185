//! Tests of the limit-stencil C functions, bad input first.

use std::ptr::{null, null_mut};

use glam::DVec3;

use super::*;
use crate::eval::vertex_limit_stencils;
use crate::ffi::error::last_error;
use crate::ffi::mesh::{new_mesh_handle, profsubd_mesh_free};
use crate::ffi::options::{profsubd_options_free, profsubd_options_new};
use crate::ffi::status::profsubd_status::*;
use crate::mesh::{Crease, Mesh};
use crate::options::SubdivOptions;
use crate::test_support::unit_cube;

/// A closed cube with one semi-sharp crease and a dart.
fn mesh() -> Mesh {
    unit_cube(vec![
        Crease {
            vertices: [0, 1],
            sharpness: 1.5,
        },
        Crease {
            vertices: [6, 7],
            sharpness: 10.0,
        },
    ])
}

fn table(quantity: i32) -> *mut profsubd_stencil_table {
    let m = new_mesh_handle(mesh());
    let mut t = null_mut();
    unsafe {
        assert_eq!(
            profsubd_limit_stencils_new(m, null(), quantity, &mut t),
            PROFSUBD_OK
        );
        profsubd_mesh_free(m);
    }
    t
}

#[test]
fn bad_input_gives_specific_statuses_and_writes_nothing() {
    let m = new_mesh_handle(mesh());
    unsafe {
        let mut t = null_mut();
        assert_eq!(
            profsubd_limit_stencils_new(null(), null(), 0, &mut t),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert!(t.is_null());
        assert_eq!(
            profsubd_limit_stencils_new(m, null(), 0, null_mut()),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert_eq!(
            profsubd_limit_stencils_new(m, null(), 3, &mut t),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(
            last_error().contains("quantity value 3"),
            "{}",
            last_error()
        );
        assert!(t.is_null());
        // a handle of another kind
        let mut o = null_mut();
        assert_eq!(profsubd_options_new(&mut o), PROFSUBD_OK);
        let mut n = 0usize;
        assert_eq!(
            profsubd_stencil_table_num_rows(o.cast(), &mut n),
            PROFSUBD_ERROR_INVALID_HANDLE
        );
        assert_eq!(
            profsubd_limit_stencils_new(o.cast(), null(), 0, &mut t),
            PROFSUBD_ERROR_INVALID_HANDLE
        );
        profsubd_options_free(o);
        assert_eq!(
            profsubd_stencil_table_num_entries(null(), &mut n),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        profsubd_mesh_free(m);
        profsubd_stencil_table_free(null_mut());
    }
    let t = table(0);
    unsafe {
        let mut needed = 0usize;
        let mut small = [7u32; 3];
        assert_eq!(
            profsubd_stencil_table_get_offsets(t, small.as_mut_ptr(), 3, &mut needed),
            PROFSUBD_ERROR_BUFFER_TOO_SMALL
        );
        assert_eq!(needed, 9);
        assert_eq!(small, [7; 3]);
        assert_eq!(
            profsubd_stencil_table_get_weights(t, null_mut(), 4, &mut needed),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        // too few points for the stencils
        let pts = [0.0f64; 9];
        let mut out = [0.0f64; 24];
        assert_eq!(
            profsubd_stencil_table_apply(t, pts.as_ptr(), 3, out.as_mut_ptr(), 8, &mut needed),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            profsubd_stencil_table_apply(t, null(), 8, out.as_mut_ptr(), 8, &mut needed),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert_eq!(
            profsubd_stencil_table_apply(t, pts.as_ptr(), 3, out.as_mut_ptr(), 2, &mut needed),
            PROFSUBD_ERROR_BUFFER_TOO_SMALL
        );
        assert_eq!(needed, 8);
        profsubd_stencil_table_free(t);
    }
}

#[test]
fn tables_copy_out_and_apply_as_the_rust_api() {
    let want = vertex_limit_stencils(&mesh(), &SubdivOptions::default()).unwrap();
    let points: Vec<f64> = mesh()
        .positions()
        .iter()
        .flat_map(|p| p.to_array())
        .collect();
    for (q, rust) in [(0, &want.position), (1, &want.du), (2, &want.dv)] {
        let t = table(q);
        unsafe {
            let (mut rows, mut entries) = (0usize, 0usize);
            assert_eq!(profsubd_stencil_table_num_rows(t, &mut rows), PROFSUBD_OK);
            assert_eq!(
                profsubd_stencil_table_num_entries(t, &mut entries),
                PROFSUBD_OK
            );
            assert_eq!((rows, entries), (8, rust.num_entries()));
            let mut offsets = vec![0u32; rows + 1];
            let mut indices = vec![0u32; entries];
            let mut weights = vec![0.0f64; entries];
            let mut needed = 0usize;
            assert_eq!(
                profsubd_stencil_table_get_offsets(t, offsets.as_mut_ptr(), rows + 1, &mut needed),
                PROFSUBD_OK
            );
            assert_eq!(needed, rows + 1);
            assert_eq!(
                profsubd_stencil_table_get_indices(t, indices.as_mut_ptr(), entries, null_mut()),
                PROFSUBD_OK
            );
            assert_eq!(
                profsubd_stencil_table_get_weights(t, weights.as_mut_ptr(), entries, null_mut()),
                PROFSUBD_OK
            );
            assert_eq!(
                (&offsets, &indices, &weights),
                (&rust.offsets, &rust.indices, &rust.weights)
            );
            let mut out = vec![0.0f64; 24];
            assert_eq!(
                profsubd_stencil_table_apply(
                    t,
                    points.as_ptr(),
                    8,
                    out.as_mut_ptr(),
                    8,
                    &mut needed
                ),
                PROFSUBD_OK
            );
            assert_eq!(needed, 8);
            let expect: Vec<f64> = rust
                .apply(mesh().positions())
                .unwrap()
                .iter()
                .flat_map(|p| p.to_array())
                .collect();
            assert_eq!(out, expect);
            profsubd_stencil_table_free(t);
        }
    }
}

#[test]
fn a_vertex_without_surface_has_an_empty_row_applied_as_nan() {
    // The cube with an isolated ninth vertex.
    let mut parts = mesh().into_parts();
    parts.positions.push(DVec3::splat(3.0));
    let m = new_mesh_handle(Mesh::from_parts(parts).unwrap());
    let points: Vec<f64> = (0..27).map(|i| f64::from(i) * 0.1).collect();
    for q in 0..3 {
        unsafe {
            let mut t = null_mut();
            assert_eq!(
                profsubd_limit_stencils_new(m, null(), q, &mut t),
                PROFSUBD_OK
            );
            let mut offsets = [0u32; 10];
            let mut needed = 0;
            assert_eq!(
                profsubd_stencil_table_get_offsets(t, offsets.as_mut_ptr(), 10, &mut needed),
                PROFSUBD_OK
            );
            assert!((0..8).all(|i| offsets[i] < offsets[i + 1]), "{offsets:?}");
            assert_eq!(offsets[8], offsets[9]);
            let mut out = [0.0f64; 27];
            assert_eq!(
                profsubd_stencil_table_apply(
                    t,
                    points.as_ptr(),
                    9,
                    out.as_mut_ptr(),
                    9,
                    &mut needed
                ),
                PROFSUBD_OK
            );
            assert!(out[..24].iter().all(|x| x.is_finite()));
            assert!(out[24..].iter().all(|x| x.is_nan()));
            profsubd_stencil_table_free(t);
        }
    }
    unsafe { profsubd_mesh_free(m) };
}
