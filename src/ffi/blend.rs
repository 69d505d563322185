//! C API of the N-way pipe blend: the pipes as a caller array, the GBS order, tension and
//! shape parameters as arguments, fit settings on the options object, the result a
//! `profsubd_fitted`.

use glam::DVec3;

use crate::construct::blend::{build, BlendInput, Pipe};
use crate::ffi::construct::{construct, tuples, TakeOptions};
use crate::ffi::fitted::profsubd_fitted;
use crate::ffi::options::{profsubd_options, OptionsData};
use crate::ffi::status::profsubd_status;

impl TakeOptions for BlendInput {
    /// The blend has no sample counts; its parameters are the entry point's arguments.
    fn take(&mut self, _o: &OptionsData) {}
}

/// Blend `num_pipes` pipes (3 to 8) at a junction with generalized B-spline subdivision and
/// fit a Catmull–Clark mesh to the result: `pipes` holds 8 doubles per pipe, the end centre
/// at the junction (x, y, z), the axis away from it (x, y, z), the radius and the length.
/// `columns` is the number of control points round each pipe (3..16), `order` the GBS
/// order (3..8), `tension` the level-0 tension (NaN: cos(π/columns), the pipes' exact
/// circles), `alpha` and `k_alpha` the centre and valley shape parameters, `gbs_level`
/// (1..4 for even orders, 1..2 for odd) the GBS level whose faces the Catmull–Clark mesh
/// refines. The boundary interpolation and crease method come from `options` (may be
/// NULL). Errors: `PROFSUBD_ERROR_INVALID_ARGUMENT` for bad pipes or parameters (the message
/// says which), `PROFSUBD_ERROR_NUMERICAL` if the fit misses its tolerance.
#[no_mangle]
#[allow(clippy::too_many_arguments)] // one C entry point, each value a plain argument
pub unsafe extern "C" fn profsubd_blend(
    pipes: *const f64,
    num_pipes: usize,
    columns: u32,
    order: u32,
    tension: f64,
    alpha: f64,
    k_alpha: f64,
    gbs_level: u32,
    options: *const profsubd_options,
    out: *mut *mut profsubd_fitted,
) -> profsubd_status {
    let read = || {
        let pipes = tuples::<8>(pipes, num_pipes, "pipes")?
            .into_iter()
            .map(|p| Pipe {
                end: DVec3::new(p[0], p[1], p[2]),
                axis: DVec3::new(p[3], p[4], p[5]),
                radius: p[6],
                length: p[7],
            })
            .collect();
        Ok(BlendInput {
            columns: columns as usize,
            order,
            tension: (!tension.is_nan()).then_some(tension),
            alpha,
            k_alpha,
            gbs_level,
            ..BlendInput::new(pipes)
        })
    };
    construct(out, options, read, build)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::fitted::profsubd_fitted_free;

    #[test]
    fn builds_a_tee_and_refuses_bad_input() {
        #[rustfmt::skip]
        let pipes = [
            2.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 4.0,
            -2.0, 0.0, 0.0, -1.0, 0.0, 0.0, 1.0, 4.0,
            0.0, 2.0, 0.0, 0.0, 1.0, 0.0, 0.6, 4.0,
        ];
        let mut out: *mut profsubd_fitted = std::ptr::null_mut();
        let call = |n: usize, out: &mut *mut profsubd_fitted| unsafe {
            profsubd_blend(
                pipes.as_ptr(),
                n,
                5,
                3,
                f64::NAN,
                0.3,
                0.5,
                1,
                std::ptr::null(),
                out,
            )
        };
        assert_eq!(
            call(2, &mut out),
            profsubd_status::PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(out.is_null(), "output untouched on error");
        // Each bad input: a specific message, the output untouched.
        let refuse = |pipes: &[f64], order: u32, tension: f64, says: &str| {
            let mut out: *mut profsubd_fitted = std::ptr::null_mut();
            let status = unsafe {
                profsubd_blend(
                    pipes.as_ptr(),
                    pipes.len() / 8,
                    4,
                    order,
                    tension,
                    0.3,
                    0.5,
                    1,
                    std::ptr::null(),
                    &mut out,
                )
            };
            assert_eq!(status, profsubd_status::PROFSUBD_ERROR_INVALID_ARGUMENT);
            let message = unsafe {
                std::ffi::CStr::from_ptr(crate::ffi::message::profsubd_last_error_message())
            };
            assert!(message.to_str().unwrap().contains(says), "{message:?}");
            assert!(out.is_null(), "{says}: output untouched on error");
        };
        refuse(&pipes[..8], 4, f64::NAN, "3 to 8 pipes");
        refuse(&pipes, 2, f64::NAN, "order 2");
        refuse(&pipes, 9, f64::NAN, "order 9");
        refuse(&pipes, 4, -1.0, "tension");
        let with = |at: usize, values: &[f64]| {
            let mut p = pipes;
            p[at..at + values.len()].copy_from_slice(values);
            p
        };
        refuse(&with(22, &[0.0]), 4, f64::NAN, "radius");
        refuse(&with(22, &[-0.5]), 4, f64::NAN, "radius");
        refuse(
            &with(16, &[0.5, 2.0, 0.0, 1.0, 0.0, 0.0]),
            4,
            f64::NAN,
            "parallel",
        );
        refuse(
            &with(16, &[2.0, 0.0, 0.0, 1.0, 1.0, 0.0]),
            4,
            f64::NAN,
            "coincident",
        );
        refuse(
            &with(16, &[2.0, 1.5, 0.0, 1.0, 0.2, 0.0]),
            4,
            f64::NAN,
            "intersect before the junction",
        );
        assert_eq!(call(3, &mut out), profsubd_status::PROFSUBD_OK);
        assert!(!out.is_null());
        unsafe { profsubd_fitted_free(out) };
    }
}
