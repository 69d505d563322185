use std::mem::size_of;
use std::ptr::{null, null_mut};

use super::*;
use crate::construct::Settings;
use crate::ffi::construct::*;
use crate::ffi::error::last_error;
use crate::ffi::fitted::*;
use crate::ffi::handle;
use crate::ffi::mesh::{mesh_arg, profsubd_mesh_free};
use crate::ffi::options::{profsubd_options_free, profsubd_options_new};
use crate::ffi::status::profsubd_status::*;

/// A double cone: c1 as (x, z) pairs, 9 points.
fn cone() -> Vec<f64> {
    (0..=8)
        .flat_map(|i| {
            let z = i as f64 / 4.0 - 1.0;
            [1.0 - z.abs(), z]
        })
        .collect()
}

fn curves(c: &[f64]) -> profsubd_profile_curves {
    profsubd_profile_curves {
        struct_size: size_of::<profsubd_profile_curves>(),
        c1: c.as_ptr(),
        c1_points: c.len() / 2,
        c2: c.as_ptr(),
        c2_points: c.len() / 2,
        c3: null(),
        c3_points: 0,
        c4: null(),
        c4_points: 0,
        c1_corners: null(),
        c1_num_corners: 0,
        c2_corners: null(),
        c2_num_corners: 0,
        c3_corners: null(),
        c3_num_corners: 0,
        c4_corners: null(),
        c4_num_corners: 0,
    }
}

fn options() -> *mut profsubd_options {
    let mut o = null_mut();
    assert_eq!(unsafe { profsubd_options_new(&mut o) }, PROFSUBD_OK);
    o
}

#[test]
fn builds_the_same_model_as_the_rust_api() {
    let c = cone();
    let o = options();
    unsafe {
        assert_eq!(profsubd_options_set_samples(o, 6, 8), PROFSUBD_OK);
        let mut p = null_mut();
        assert_eq!(profsubd_profile_build(&curves(&c), o, &mut p), PROFSUBD_OK);
        let mut m = null_mut();
        assert_eq!(profsubd_fitted_get_mesh(p, &mut m), PROFSUBD_OK);
        let pts: Vec<[f64; 2]> = c.chunks(2).map(|q| [q[0], q[1]]).collect();
        let mut input = ProfileInput::new(pts.clone(), pts);
        input.around = 8;
        input.along = 6;
        let model = build(&input, &Settings::default()).unwrap();
        assert_eq!(mesh_arg(m, "m").unwrap(), &*model.mesh);
        let mut needed = 0;
        assert_eq!(
            profsubd_fitted_get_targets(p, null_mut(), 0, &mut needed),
            PROFSUBD_ERROR_BUFFER_TOO_SMALL
        );
        assert_eq!(needed, 3 * model.targets.len());
        let mut t = vec![0.0; needed];
        assert_eq!(
            profsubd_fitted_get_targets(p, t.as_mut_ptr(), t.len(), &mut needed),
            PROFSUBD_OK
        );
        let expect: Vec<f64> = model.targets.iter().flat_map(|v| v.to_array()).collect();
        assert_eq!(t, expect);
        let (mut r, mut tol) = (f64::NAN, f64::NAN);
        assert_eq!(
            profsubd_fitted_get_fit_residual(p, &mut r, &mut tol),
            PROFSUBD_OK
        );
        assert!(r <= tol && tol > 0.0);
        // The surface report, computed once, through both getters.
        let report = model.surface_report().unwrap();
        let (mut max, mut mean, mut folded, mut worst, mut und) =
            (f64::NAN, f64::NAN, usize::MAX, f64::NAN, f64::NAN);
        assert_eq!(
            profsubd_fitted_get_design_distance(p, &mut max, &mut mean),
            PROFSUBD_OK
        );
        assert_eq!(
            (max, mean),
            (report.max_design_distance, report.mean_design_distance)
        );
        assert!(mean > 0.0 && mean <= max && max < 0.05, "{max} {mean}");
        assert_eq!(
            profsubd_fitted_get_surface_quality(p, &mut folded, &mut worst, &mut und),
            PROFSUBD_OK
        );
        assert_eq!(
            (folded, worst, und),
            (0, report.worst_reversal_deg, report.undulation)
        );
        assert_eq!(
            profsubd_fitted_get_surface_quality(p, null_mut(), null_mut(), null_mut()),
            PROFSUBD_OK
        );
        profsubd_mesh_free(m);
        profsubd_fitted_free(p);
        profsubd_options_free(o);
    }
}

#[test]
fn bad_inputs_and_settings_give_specific_statuses() {
    let c = cone();
    let o = options();
    unsafe {
        for v in [0, 4100] {
            assert_eq!(
                profsubd_options_set_samples(o, 12, v),
                PROFSUBD_ERROR_INVALID_ARGUMENT
            );
        }
        assert_eq!(
            profsubd_options_set_samples(o, 0, 8),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        // Around not a multiple of 4: refused when the model is built.
        assert_eq!(profsubd_options_set_samples(o, 12, 6), PROFSUBD_OK);
        let mut p = null_mut();
        assert_eq!(
            profsubd_profile_build(&curves(&c), o, &mut p),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("multiple of 4"));
        assert!(p.is_null());
        profsubd_options_free(o);
        let o = options();
        for a in [0.0, -5.0, 181.0, f64::NAN] {
            assert_eq!(
                profsubd_options_set_sharp_angle(o, a),
                PROFSUBD_ERROR_INVALID_ARGUMENT
            );
        }
        for s in [-1.0, f32::NAN, f32::INFINITY] {
            assert_eq!(
                profsubd_options_set_crease_sharpness(o, s),
                PROFSUBD_ERROR_INVALID_ARGUMENT
            );
        }
        assert_eq!(
            profsubd_options_set_interpolation(o, 2),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            profsubd_options_set_caps(o, -1),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            handle::borrow(o, "o").unwrap().settings,
            Settings::default()
        );
        assert_eq!(profsubd_options_set_interpolation(o, 1), PROFSUBD_OK);
        assert_eq!(profsubd_options_set_caps(o, 1), PROFSUBD_OK);
        assert_eq!(profsubd_options_set_sharp_angle(o, 45.0), PROFSUBD_OK);
        assert_eq!(profsubd_options_set_crease_sharpness(o, 2.0), PROFSUBD_OK);
        assert_eq!(
            profsubd_options_set_samples(null_mut(), 8, 8),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );

        let mut p = null_mut();
        assert_eq!(
            profsubd_profile_build(null(), o, &mut p),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        let mut d = curves(&c);
        assert_eq!(
            profsubd_profile_build(&d, o, null_mut()),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        d.struct_size = 8;
        assert_eq!(
            profsubd_profile_build(&d, o, &mut p),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("struct_size"));
        let mut d = curves(&c);
        d.c2 = null();
        assert_eq!(
            profsubd_profile_build(&d, o, &mut p),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        let mut d = curves(&c);
        d.c1_points = 1;
        assert_eq!(
            profsubd_profile_build(&d, o, &mut p),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("at least 2 points"));
        let mut nan = c.clone();
        nan[5] = f64::NAN;
        let d = curves(&nan);
        assert_eq!(
            profsubd_profile_build(&d, o, &mut p),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("not a finite number"));
        let mut rev: Vec<f64> = c.chunks(2).rev().flatten().copied().collect();
        rev.truncate(c.len());
        let mut d = curves(&c);
        d.c2 = rev.as_ptr();
        assert_eq!(
            profsubd_profile_build(&d, o, &mut p),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("bottom to top"));
        let bad_corner = [99u32];
        let mut d = curves(&c);
        d.c1_corners = bad_corner.as_ptr();
        d.c1_num_corners = 1;
        assert_eq!(
            profsubd_profile_build(&d, o, &mut p),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(p.is_null());

        let mut fake = [0u64; 4];
        let f = fake.as_mut_ptr().cast::<profsubd_fitted>();
        let mut m = null_mut();
        assert_eq!(
            profsubd_fitted_get_mesh(f, &mut m),
            PROFSUBD_ERROR_INVALID_HANDLE
        );
        assert_eq!(
            profsubd_fitted_get_targets(f, null_mut(), 0, null_mut()),
            PROFSUBD_ERROR_INVALID_HANDLE
        );
        assert_eq!(
            profsubd_fitted_get_fit_residual(null(), null_mut(), null_mut()),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert_eq!(
            profsubd_fitted_get_design_distance(null(), null_mut(), null_mut()),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert_eq!(
            profsubd_fitted_get_surface_quality(f, null_mut(), null_mut(), null_mut()),
            PROFSUBD_ERROR_INVALID_HANDLE
        );
        profsubd_fitted_free(null_mut());
        profsubd_options_free(o);
    }
}

#[test]
fn the_default_model_is_the_bundled_bottle_in_one_call_or_from_its_curves() {
    let (input, settings) = default_model();
    let expect = build(&input, &settings).unwrap();
    unsafe {
        let mut one = null_mut();
        assert_eq!(
            profsubd_profile_build_default(null(), &mut one),
            PROFSUBD_OK
        );
        let mut c = profsubd_profile_curves::empty();
        let (mut along, mut around) = (0, 0);
        assert_eq!(
            profsubd_profile_default_curves(&mut c, &mut along, &mut around),
            PROFSUBD_OK
        );
        assert_eq!((along, around), (20, 16));
        assert_eq!((c.c1_points, c.c2_points, c.c3_points), (8, 8, 0));
        assert_eq!(
            std::slice::from_raw_parts(c.c1, 2 * c.c1_points)[2..4],
            [1.2, 0.0]
        );
        let o = options();
        assert_eq!(profsubd_options_set_samples(o, along, around), PROFSUBD_OK);
        let mut two = null_mut();
        assert_eq!(profsubd_profile_build(&c, o, &mut two), PROFSUBD_OK);
        for f in [one, two] {
            let mut m = null_mut();
            assert_eq!(profsubd_fitted_get_mesh(f, &mut m), PROFSUBD_OK);
            assert_eq!(mesh_arg(m, "m").unwrap(), &*expect.mesh);
            profsubd_mesh_free(m);
            profsubd_fitted_free(f);
        }
        // The handle shares the mesh of the fitted construction: no copy.
        let mut f = null_mut();
        assert_eq!(profsubd_profile_build_default(o, &mut f), PROFSUBD_OK);
        let mut m = null_mut();
        assert_eq!(profsubd_fitted_get_mesh(f, &mut m), PROFSUBD_OK);
        let shared = &handle::borrow(f, "f").unwrap().mesh;
        assert!(std::ptr::eq(mesh_arg(m, "m").unwrap(), &**shared));
        profsubd_fitted_free(f);
        assert_eq!(mesh_arg(m, "m").unwrap(), &*expect.mesh);
        profsubd_mesh_free(m);
        // Errors leave the outputs alone.
        let mut bad = profsubd_profile_curves::empty();
        bad.struct_size = 4;
        assert_eq!(
            profsubd_profile_default_curves(&mut bad, null_mut(), null_mut()),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(bad.c1.is_null() && bad.struct_size == 4);
        assert_eq!(
            profsubd_profile_build_default(o, null_mut()),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        profsubd_options_free(o);
    }
}
