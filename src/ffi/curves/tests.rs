//! Both sketch-curve entry points against the Rust construction, and their bad input.

use std::ptr::{null, null_mut};

use super::*;
use crate::construct::Settings;
use crate::ffi::construct::profsubd_options_set_samples;
use crate::ffi::error::last_error;
use crate::ffi::fitted::{profsubd_fitted_free, profsubd_fitted_get_targets};
use crate::ffi::options::{profsubd_options_free, profsubd_options_new};
use crate::ffi::status::profsubd_status::*;

/// A saddle z = x² − y² over [-1, 1]² from its 4 boundary sides (5 points each) and one
/// stroke on it: the points one curve after the other, and the curve sizes.
fn saddle() -> (Vec<f64>, Vec<usize>) {
    let z = |x: f64, y: f64| x * x - y * y;
    let side = |a: [f64; 2], b: [f64; 2]| -> Vec<f64> {
        (0..5)
            .flat_map(|i| {
                let t = i as f64 / 4.0;
                let (x, y) = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]));
                [x, y, z(x, y)]
            })
            .collect()
    };
    let curves = [
        side([-1.0, -1.0], [1.0, -1.0]),
        side([1.0, -1.0], [1.0, 1.0]),
        side([1.0, 1.0], [-1.0, 1.0]),
        side([-1.0, 1.0], [-1.0, -1.0]),
        side([-0.5, -0.3], [0.5, 0.4]),
    ];
    (
        curves.concat(),
        curves.iter().map(|c| c.len() / 3).collect(),
    )
}

/// The targets of a fitted handle.
unsafe fn targets(f: *const profsubd_fitted) -> Vec<f64> {
    let mut n = 0;
    let _ = profsubd_fitted_get_targets(f, null_mut(), 0, &mut n);
    let mut out = vec![0.0; n];
    assert_eq!(
        profsubd_fitted_get_targets(f, out.as_mut_ptr(), n, &mut n),
        PROFSUBD_OK
    );
    out
}

/// Both entry points at 6 × 6 samples give the Rust build's data points, bit for bit.
#[test]
fn both_entry_points_build_what_the_rust_api_builds() {
    let (points, sizes) = saddle();
    let up = [0.0, 0.0, 1.0];
    unsafe {
        let mut o = null_mut();
        assert_eq!(profsubd_options_new(&mut o), PROFSUBD_OK);
        assert_eq!(profsubd_options_set_samples(o, 6, 6), PROFSUBD_OK);
        for method in [Method::Attraction, Method::Fair] {
            let mut out = null_mut();
            let st = match method {
                Method::Attraction => profsubd_curves(
                    points.as_ptr(),
                    sizes.as_ptr(),
                    4,
                    1,
                    1.0,
                    up.as_ptr(),
                    o,
                    &mut out,
                ),
                Method::Fair => profsubd_curves_fair(
                    points.as_ptr(),
                    sizes.as_ptr(),
                    4,
                    1,
                    up.as_ptr(),
                    o,
                    &mut out,
                ),
            };
            assert_eq!(st, PROFSUBD_OK, "{method:?}: {}", last_error());
            // The fair entry point passes tau = 2: its blended start points are the fair
            // solve's starting guess, so the rounding depends on it.
            let tau = if method == Method::Fair { 2.0 } else { 1.0 };
            let mut input = read_curves(
                points.as_ptr(),
                sizes.as_ptr(),
                4,
                1,
                tau,
                up.as_ptr(),
                method,
            )
            .unwrap();
            input.samples = [6, 6];
            let want = build(&input, &Settings::default()).unwrap();
            let want: Vec<f64> = want.targets.iter().flat_map(|t| t.to_array()).collect();
            assert_eq!(targets(out), want, "{method:?}");
            profsubd_fitted_free(out);
        }
        profsubd_options_free(o);
    }
}

/// Bad input to either entry point: its specific status and message, `*out` untouched.
#[test]
fn bad_input_gives_a_specific_status_and_leaves_the_output_untouched() {
    let (points, sizes) = saddle();
    let up = [0.0, 0.0, 1.0];
    let mut nan = points.clone();
    nan[7] = f64::NAN;
    let mut short = sizes.clone();
    short[4] = 1; // the stroke of 1 point (the others follow on in the array)
                  // (points, sizes, boundary, interior, tau, normal, status, message)
    type Case<'a> = (
        *const f64,
        *const usize,
        usize,
        usize,
        f64,
        *const f64,
        profsubd_status,
        &'a str,
    );
    let p = points.as_ptr();
    let s = sizes.as_ptr();
    let cases: Vec<Case> = vec![
        (
            null(),
            s,
            4,
            1,
            2.0,
            null(),
            PROFSUBD_ERROR_NULL_ARGUMENT,
            "points",
        ),
        (
            p,
            null(),
            4,
            1,
            2.0,
            null(),
            PROFSUBD_ERROR_NULL_ARGUMENT,
            "curve_sizes",
        ),
        (
            nan.as_ptr(),
            s,
            4,
            1,
            2.0,
            null(),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "not finite",
        ),
        (
            p,
            s,
            2,
            0,
            2.0,
            null(),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "3 or 4 curves",
        ),
        (
            p,
            s,
            5,
            0,
            2.0,
            null(),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "3 or 4 curves",
        ),
        (
            p,
            short.as_ptr(),
            4,
            1,
            2.0,
            null(),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "interior 0: an open curve needs at least 2 points",
        ),
        (
            p,
            s,
            usize::MAX,
            1,
            2.0,
            null(),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "curve counts",
        ),
        (
            p,
            s,
            4,
            1,
            2.0,
            [0.0, 1.0, 0.0].as_ptr(),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "no area",
        ),
        (
            p,
            s,
            4,
            1,
            2.0,
            [f64::NAN, 0.0, 1.0].as_ptr(),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "must be finite and non-zero",
        ),
        (
            p,
            s,
            4,
            1,
            -1.0,
            up.as_ptr(),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "tau = -1",
        ),
        (
            p,
            s,
            4,
            1,
            f64::NAN,
            up.as_ptr(),
            PROFSUBD_ERROR_INVALID_ARGUMENT,
            "tau = NaN",
        ),
    ];
    // An address no handle has: the call must leave it as it is.
    let sentinel = 0x10 as *mut profsubd_fitted;
    unsafe {
        for (k, &(pts, sz, nb, ni, tau, normal, status, message)) in cases.iter().enumerate() {
            for fair in [false, true] {
                // tau is not an argument of the fair entry point.
                if fair && tau != 2.0 {
                    continue;
                }
                let mut out = sentinel;
                let got = if fair {
                    profsubd_curves_fair(pts, sz, nb, ni, normal, null(), &mut out)
                } else {
                    profsubd_curves(pts, sz, nb, ni, tau, normal, null(), &mut out)
                };
                let what = format!("case {k}, fair {fair}: {}", last_error());
                assert_eq!(got, status, "{what}");
                assert!(last_error().contains(message), "{what}");
                assert_eq!(out, sentinel, "{what}");
            }
        }
        // NULL output location.
        assert_eq!(
            profsubd_curves_fair(
                points.as_ptr(),
                sizes.as_ptr(),
                4,
                1,
                up.as_ptr(),
                null(),
                null_mut()
            ),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert_eq!(
            profsubd_curves(
                points.as_ptr(),
                sizes.as_ptr(),
                4,
                1,
                2.0,
                up.as_ptr(),
                null(),
                null_mut()
            ),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
    }
}
