//! Tests of the fold-check C functions: the Rust API's answer through the C ABI, bad input.

use std::ptr::{null, null_mut};

use super::*;
use crate::eval::folds::find_folds;
use crate::ffi::error::last_error;
use crate::ffi::evaluator::{profsubd_evaluator_free, profsubd_evaluator_new};
use crate::ffi::mesh::{new_mesh_handle, profsubd_mesh_free};
use crate::ffi::status::profsubd_status::*;
use crate::mesh::Mesh;
use crate::test_support::grid;

/// An 8 × 8 planar grid with vertex (4, 4) pushed 2.3 along +x: folds in faces 28 and 36
/// (see the library's tests for why).
fn folded_evaluator() -> *mut profsubd_evaluator {
    let mut parts = grid(8, |_, _| 0.0);
    parts.positions[4 * 9 + 4].x += 2.3;
    let m = new_mesh_handle(Mesh::from_parts(parts).unwrap());
    let mut ev = null_mut();
    unsafe {
        assert_eq!(profsubd_evaluator_new(m, null(), &mut ev), PROFSUBD_OK);
        profsubd_mesh_free(m);
    }
    ev
}

#[test]
fn check_folds_reports_what_the_rust_api_reports() {
    let ev = folded_evaluator();
    unsafe {
        let mut report = null_mut();
        assert_eq!(profsubd_check_folds(ev, null(), &mut report), PROFSUBD_OK);
        let rust = find_folds(
            handle::borrow::<profsubd_evaluator>(ev, "ev").unwrap(),
            &FoldSettings::default(),
        )
        .unwrap();
        let mut s = std::mem::zeroed::<profsubd_fold_summary>();
        assert_eq!(
            profsubd_fold_report_get_summary(report, &mut s),
            PROFSUBD_OK
        );
        assert_eq!(s.num_folded_faces, 2);
        assert_eq!(s.faces_checked, 64);
        assert_eq!(s.samples, rust.samples);
        assert_eq!(s.worst_reversal_deg, 180.0);
        let (f, u, v) = rust.worst_at.unwrap();
        assert_eq!((s.worst_face, s.worst_u, s.worst_v), (f as i64, u, v));
        assert_eq!(s.min_relative_jacobian, rust.min_relative_jacobian);
        // Copy-out: too small first (buffer untouched, needed set), then exact.
        let mut faces = [7u32; 2];
        let mut needed = 0usize;
        assert_eq!(
            profsubd_fold_report_get_folded_faces(report, faces.as_mut_ptr(), 1, &mut needed),
            PROFSUBD_ERROR_BUFFER_TOO_SMALL
        );
        assert_eq!((needed, faces), (2, [7, 7]));
        assert_eq!(
            profsubd_fold_report_get_folded_faces(report, faces.as_mut_ptr(), 2, &mut needed),
            PROFSUBD_OK
        );
        assert_eq!(faces, [28, 36]);
        profsubd_fold_report_free(report);
        // Denser settings through the struct.
        let dense = profsubd_fold_settings {
            samples_per_edge: 17,
            adaptive_depth: 2,
            refine_turn_deg: 30.0,
        };
        assert_eq!(profsubd_check_folds(ev, &dense, &mut report), PROFSUBD_OK);
        assert_eq!(
            profsubd_fold_report_get_summary(report, &mut s),
            PROFSUBD_OK
        );
        assert_eq!(s.num_folded_faces, 2);
        profsubd_fold_report_free(report);
        profsubd_evaluator_free(ev);
    }
}

#[test]
fn bad_input_gives_a_status_and_leaves_outputs_alone() {
    let ev = folded_evaluator();
    let sentinel = 0x5eed as *mut profsubd_fold_report;
    unsafe {
        let mut report = sentinel;
        assert_eq!(
            profsubd_check_folds(null(), null(), &mut report),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert!(last_error().contains("evaluator"));
        assert_eq!(report, sentinel);
        assert_eq!(
            profsubd_check_folds(ev, null(), null_mut()),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        let bad = profsubd_fold_settings {
            samples_per_edge: 1,
            adaptive_depth: 4,
            refine_turn_deg: 45.0,
        };
        assert_eq!(
            profsubd_check_folds(ev, &bad, &mut report),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("samples per edge"));
        assert_eq!(report, sentinel);
        // An evaluator is not a fold report.
        let mut s = std::mem::zeroed::<profsubd_fold_summary>();
        assert_eq!(
            profsubd_fold_report_get_summary(ev.cast(), &mut s),
            PROFSUBD_ERROR_INVALID_HANDLE
        );
        assert_eq!(s.num_folded_faces, 0);
        profsubd_fold_report_free(null_mut());
        profsubd_evaluator_free(ev);
    }
}
