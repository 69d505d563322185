//! Shared code of the fuzz targets: the C API (bindgen's translation of
//! `include/profsubd.h`, see `build.rs`) and the contract every mesh they obtain must satisfy.

use std::ffi::CStr;

// Links the library, whose `#[no_mangle]` functions the header declares.
use profsubd as _;

/// The C API as the header declares it.
#[allow(
    non_camel_case_types,
    non_upper_case_globals,
    non_snake_case,
    dead_code
)]
pub mod capi {
    include!(concat!(env!("OUT_DIR"), "/profsubd.rs"));
}

pub use capi::*;

/// The calling thread's last error message: never empty after a failed call.
pub fn last_error() -> String {
    unsafe { CStr::from_ptr(profsubd_last_error_message()) }
        .to_string_lossy()
        .into_owned()
}

/// A status that is not OK must come with a message.
pub fn check_error(status: profsubd_status, what: &str) {
    if status != PROFSUBD_OK {
        assert!(
            !last_error().is_empty(),
            "{what}: status {status} without a message"
        );
    }
}

/// Small deterministic stream of numbers drawn from the fuzzer's bytes (zeros when they run out).
pub struct Bytes<'a>(pub &'a [u8]);

impl Bytes<'_> {
    pub fn u8(&mut self) -> u8 {
        match self.0.split_first() {
            Some((b, rest)) => {
                self.0 = rest;
                *b
            }
            None => 0,
        }
    }
    pub fn u16(&mut self) -> u16 {
        u16::from_le_bytes([self.u8(), self.u8()])
    }
    /// In [0, 1], both ends reachable.
    pub fn unit(&mut self) -> f64 {
        f64::from(self.u16()) / f64::from(u16::MAX)
    }
}

/// The contract of a valid mesh: its control points' bounding box holds every limit point
/// (Catmull-Clark masks, crease rules included, are convex combinations), evaluation at
/// points in the domain succeeds or marks the point as having no surface, and refinement
/// keeps the refined points in the same box.
pub fn check_mesh(mesh: *const profsubd_mesh, params: &mut Bytes) {
    let (lo, hi) = bounding_box(mesh);
    let slack = 1e-9 * (1.0 + (0..3).map(|k| (hi[k] - lo[k]).abs()).fold(0.0, f64::max));
    let inside = |p: &[f64]| (0..3).all(|k| p[k] >= lo[k] - slack && p[k] <= hi[k] + slack);

    let mut evaluator: *mut profsubd_evaluator = std::ptr::null_mut();
    let status = unsafe { profsubd_evaluator_new(mesh, std::ptr::null(), &mut evaluator) };
    check_error(status, "evaluator_new");
    if status == PROFSUBD_OK {
        let mut nfaces = 0usize;
        assert_eq!(
            unsafe { profsubd_evaluator_num_parametric_faces(evaluator, &mut nfaces) },
            PROFSUBD_OK
        );
        let n = 16usize;
        let faces: Vec<u32> = (0..n)
            .map(|_| (usize::from(params.u16()) % nfaces.max(1)) as u32)
            .collect();
        let u: Vec<f64> = (0..n).map(|_| params.unit()).collect();
        let v: Vec<f64> = (0..n).map(|_| params.unit()).collect();
        let (mut p, mut du, mut dv, mut has) = (
            vec![0.0; 3 * n],
            vec![0.0; 3 * n],
            vec![0.0; 3 * n],
            vec![0u8; n],
        );
        let status = unsafe {
            profsubd_evaluator_evaluate_points(
                evaluator,
                0,
                0,
                faces.as_ptr(),
                u.as_ptr(),
                v.as_ptr(),
                n,
                p.as_mut_ptr(),
                du.as_mut_ptr(),
                dv.as_mut_ptr(),
                has.as_mut_ptr(),
            )
        };
        check_error(status, "evaluate_points");
        assert_eq!(
            status,
            PROFSUBD_OK,
            "in-domain points must evaluate: {}",
            last_error()
        );
        for i in 0..n {
            let q = &p[3 * i..3 * i + 3];
            if has[i] == 1 {
                assert!(
                    inside(q),
                    "limit point {q:?} (face {}, u {}, v {}) outside the control box {lo:?}..{hi:?}",
                    faces[i],
                    u[i],
                    v[i]
                );
            } else {
                assert!(
                    q.iter().all(|x| x.is_nan()),
                    "a point without surface must be NaN"
                );
            }
        }
        unsafe { profsubd_evaluator_free(evaluator) };
    }

    let level = u32::from(params.u8() % 3);
    let mut refined: *mut profsubd_mesh = std::ptr::null_mut();
    let status = unsafe { profsubd_refine_uniform(mesh, std::ptr::null(), level, &mut refined) };
    check_error(status, "refine_uniform");
    if status == PROFSUBD_OK {
        let (rlo, rhi) = bounding_box(refined);
        assert!(
            inside(&rlo) && inside(&rhi),
            "refined points outside the control box"
        );
        unsafe { profsubd_mesh_free(refined) };
    }
}

/// Bounding box of the mesh's control points (an empty box if it has none).
pub fn bounding_box(mesh: *const profsubd_mesh) -> ([f64; 3], [f64; 3]) {
    let mut nv = 0usize;
    assert_eq!(
        unsafe { profsubd_mesh_num_vertices(mesh, &mut nv) },
        PROFSUBD_OK
    );
    let mut pos = vec![0.0; 3 * nv];
    let mut needed = 0usize;
    assert_eq!(
        unsafe { profsubd_mesh_get_positions(mesh, pos.as_mut_ptr(), 3 * nv, &mut needed) },
        PROFSUBD_OK
    );
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in pos.chunks_exact(3) {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (lo, hi)
}
