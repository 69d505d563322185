use crate::math;
use std::ptr::{null, null_mut};

use super::*;
use crate::construct::{revolve, sweep};
use crate::ffi::error::last_error;
use crate::ffi::fitted::*;
use crate::ffi::mesh::{mesh_arg, profsubd_mesh_free};
use crate::ffi::options::{profsubd_options_free, profsubd_options_new};
use crate::ffi::revolve::profsubd_revolve;
use crate::ffi::status::profsubd_status::*;
use crate::ffi::sweep::profsubd_sweep;

fn options() -> *mut profsubd_options {
    let mut o = null_mut();
    assert_eq!(unsafe { profsubd_options_new(&mut o) }, PROFSUBD_OK);
    o
}

fn circle(n: usize, r: f64, dims: usize) -> Vec<f64> {
    (0..n)
        .flat_map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            [r * math::cos(t), r * math::sin(t), 0.0]
                .into_iter()
                .take(dims)
        })
        .collect()
}

unsafe fn mesh_of(s: *const profsubd_fitted) -> crate::Mesh {
    let mut m = null_mut();
    assert_eq!(profsubd_fitted_get_mesh(s, &mut m), PROFSUBD_OK);
    let mesh = mesh_arg(m, "m").unwrap().clone();
    profsubd_mesh_free(m);
    mesh
}

#[test]
fn revolve_and_sweep_build_what_the_rust_api_builds() {
    let o = options();
    unsafe {
        // A cone, 8 intervals up, 12 around, polyline.
        let cone = [1.0, 0.0, 0.0, 2.0];
        assert_eq!(profsubd_options_set_samples(o, 8, 12), PROFSUBD_OK);
        assert_eq!(profsubd_options_set_interpolation(o, 1), PROFSUBD_OK);
        let mut s = null_mut();
        assert_eq!(profsubd_revolve(cone.as_ptr(), 2, o, &mut s), PROFSUBD_OK);
        let mut input = RevolveInput::new(vec![[1.0, 0.0], [0.0, 2.0]]);
        input.samples_profile = 8;
        input.samples_around = 12;
        let polyline = Settings {
            interpolation: Interpolation::Polyline,
            ..Settings::default()
        };
        let expect = revolve::build(&input, &polyline).unwrap();
        assert_eq!(mesh_of(s), *expect.mesh);
        // Targets: copy-out protocol.
        let mut needed = 0;
        let mut small = [0.0; 3];
        assert_eq!(
            profsubd_fitted_get_targets(s, small.as_mut_ptr(), 3, &mut needed),
            PROFSUBD_ERROR_BUFFER_TOO_SMALL
        );
        assert_eq!(needed, 3 * expect.targets.len());
        assert_eq!(small, [0.0; 3]);
        let mut all = vec![0.0; needed];
        assert_eq!(
            profsubd_fitted_get_targets(s, all.as_mut_ptr(), needed, null_mut()),
            PROFSUBD_OK
        );
        assert_eq!(all[3..6], expect.targets[1].to_array());
        let (mut r, mut t) = (f64::NAN, f64::NAN);
        assert_eq!(
            profsubd_fitted_get_fit_residual(s, &mut r, &mut t),
            PROFSUBD_OK
        );
        assert!(r <= t && t == expect.fit.tolerance);
        let report = expect.surface_report().unwrap();
        let (mut max, mut folded, mut und) = (f64::NAN, usize::MAX, f64::NAN);
        assert_eq!(
            profsubd_fitted_get_design_distance(s, &mut max, null_mut()),
            PROFSUBD_OK
        );
        assert_eq!(max, report.max_design_distance);
        assert_eq!(
            profsubd_fitted_get_surface_quality(s, &mut folded, null_mut(), &mut und),
            PROFSUBD_OK
        );
        assert_eq!((folded, und), (report.folded_faces, report.undulation));
        profsubd_fitted_free(s);

        // A torus with a scaled, closed profile along a closed trajectory.
        let (p, tr) = (circle(16, 0.5, 2), circle(24, 2.0, 3));
        assert_eq!(profsubd_options_set_interpolation(o, 0), PROFSUBD_OK);
        assert_eq!(profsubd_options_set_samples(o, 8, 16), PROFSUBD_OK);
        assert_eq!(profsubd_options_set_sweep_closed(o, 1, 1), PROFSUBD_OK);
        assert_eq!(
            profsubd_options_set_sweep_frame(o, profsubd_sweep_frame::PROFSUBD_FRAME_FRENET as i32),
            PROFSUBD_OK
        );
        assert_eq!(profsubd_options_set_sweep_scale(o, 1.5, 1.5), PROFSUBD_OK);
        let (pc, tc) = ([4u32], [6u32]);
        assert_eq!(
            profsubd_options_set_sweep_corners(o, pc.as_ptr(), 1, tc.as_ptr(), 1),
            PROFSUBD_OK
        );
        let mut s = null_mut();
        assert_eq!(
            profsubd_sweep(p.as_ptr(), 16, tr.as_ptr(), 24, o, &mut s),
            PROFSUBD_OK
        );
        let mut input = SweepInput::new(
            p.chunks(2).map(|c| [c[0], c[1]]).collect(),
            tr.chunks(3).map(|c| [c[0], c[1], c[2]]).collect(),
        );
        (input.samples_profile, input.samples_trajectory) = (8, 16);
        (input.closed_profile, input.closed_trajectory) = (true, true);
        input.frame = FrameKind::Frenet;
        input.scale = [1.5, 1.5];
        input.corners.profile = vec![4];
        input.corners.trajectory = vec![6];
        let expect = sweep::build(&input, &Settings::default()).unwrap().mesh;
        // One crease line along the tube and one crease ring across it.
        assert_eq!(expect.creases().len(), 16 + 8);
        assert_eq!(mesh_of(s), *expect);
        profsubd_fitted_free(s);
        profsubd_options_free(o);
    }
}

#[test]
fn capped_partial_revolution_through_the_c_api() {
    let o = options();
    unsafe {
        let vase = [1.0, 0.0, 1.4, 0.8, 1.3, 2.0, 0.9, 3.0, 0.9, 3.6];
        assert_eq!(profsubd_options_set_samples(o, 8, 16), PROFSUBD_OK);
        assert_eq!(profsubd_options_set_revolve_angle(o, 270.0), PROFSUBD_OK);
        let flat = profsubd_caps::PROFSUBD_CAPS_FLAT as i32;
        assert_eq!(profsubd_options_set_caps(o, flat), PROFSUBD_OK);
        let mut s = null_mut();
        assert_eq!(profsubd_revolve(vase.as_ptr(), 5, o, &mut s), PROFSUBD_OK);
        let mut input = RevolveInput::new(vase.chunks(2).map(|c| [c[0], c[1]]).collect());
        (input.samples_profile, input.samples_around) = (8, 16);
        input.angle_deg = 270.0;
        let flat = Settings {
            caps: Caps::Flat,
            ..Settings::default()
        };
        let expect = revolve::build(&input, &flat).unwrap().mesh;
        let report = crate::mesh::validate::check(&expect);
        assert!(report.is_closed() && report.euler_characteristic == 2);
        assert_eq!(mesh_of(s), *expect);
        profsubd_fitted_free(s);
        // Caps on a full turn of a profile with both ends on the axis: nothing to close.
        let sphere = [0.0, -1.0, 1.0, 0.0, 0.0, 1.0];
        assert_eq!(profsubd_options_set_revolve_angle(o, 360.0), PROFSUBD_OK);
        let mut s = null_mut();
        assert_eq!(
            profsubd_revolve(sphere.as_ptr(), 3, o, &mut s),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("nothing to cap"), "{}", last_error());
        assert!(s.is_null());
        // Partial turn with caps and samples around not a multiple of 4.
        assert_eq!(profsubd_options_set_revolve_angle(o, 90.0), PROFSUBD_OK);
        assert_eq!(profsubd_options_set_samples(o, 8, 10), PROFSUBD_OK);
        assert_eq!(
            profsubd_revolve(vase.as_ptr(), 5, o, &mut s),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("multiple of 4"), "{}", last_error());
        assert!(s.is_null());
        assert_eq!(
            profsubd_options_set_caps(o, 2),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        profsubd_options_free(o);
    }
}

#[test]
fn bad_input_gives_a_specific_status_and_no_output() {
    let o = options();
    unsafe {
        let line = [1.0, 0.0, 1.0, 1.0];
        let mut s = null_mut();
        assert_eq!(
            profsubd_revolve(null(), 2, null(), &mut s),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert_eq!(
            profsubd_revolve(line.as_ptr(), 2, null(), null_mut()),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        let crossing = [1.0, 0.0, -1.0, 1.0];
        assert_eq!(
            profsubd_revolve(crossing.as_ptr(), 2, null(), &mut s),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("crosses the axis"));
        assert!(s.is_null());
        let traj = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        assert_eq!(
            profsubd_sweep(line.as_ptr(), 2, traj.as_ptr(), 2, null(), &mut s),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("coincide"), "{}", last_error());
        let straight = [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 2.0];
        assert_eq!(profsubd_options_set_sweep_frame(o, 1), PROFSUBD_OK);
        assert_eq!(
            profsubd_sweep(line.as_ptr(), 2, straight.as_ptr(), 3, o, &mut s),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("undefined everywhere"));
        assert!(s.is_null());
        assert_eq!(
            profsubd_sweep(line.as_ptr(), usize::MAX, straight.as_ptr(), 3, o, &mut s),
            PROFSUBD_ERROR_LIMIT_EXCEEDED
        );
        // Setters refuse out-of-range values.
        assert_eq!(
            profsubd_options_set_sweep_frame(o, 3),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            profsubd_options_set_sweep_closed(o, 2, 0),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            profsubd_options_set_samples(o, 0, 8),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            profsubd_options_set_revolve_angle(o, 400.0),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            profsubd_options_set_revolve_angle(o, f64::NAN),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            profsubd_options_set_sweep_scale(o, 1.0, -1.0),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            profsubd_options_set_sweep_profile_end(o, null(), 3),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert_eq!(
            profsubd_options_set_sweep_profile_end(null_mut(), null(), 0),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        // Forced corners: checked at build time.
        let corners = [5u32];
        assert_eq!(
            profsubd_options_set_sweep_corners(o, corners.as_ptr(), 1, null(), 0),
            PROFSUBD_OK
        );
        assert_eq!(
            profsubd_revolve(line.as_ptr(), 2, o, &mut s),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("corner 5"), "{}", last_error());
        assert!(s.is_null());
        assert_eq!(
            profsubd_options_set_sweep_corners(o, null(), 1, null(), 0),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        // A handle of another kind.
        assert_eq!(
            profsubd_fitted_get_mesh(o.cast::<profsubd_fitted>(), &mut null_mut()),
            PROFSUBD_ERROR_INVALID_HANDLE
        );
        profsubd_fitted_free(null_mut());
        profsubd_options_free(o);
    }
}
