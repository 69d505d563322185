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
    fn builds_a_tee_and_refuses_two_pipes() {
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
        assert_eq!(call(3, &mut out), profsubd_status::PROFSUBD_OK);
        assert!(!out.is_null());
        unsafe { profsubd_fitted_free(out) };
    }
}
