//! Every construction on arbitrary input. The first byte picks the construction: profile,
//! revolve, sweep, curves or blend from the rest read as its JSON input (construction and
//! settings keys, parsed by the crate's JSON reader as the command line and the Python
//! package read it), or the shell through the C API (`profsubd_shell` on the OBJ that
//! follows three parameter bytes). Sample counts are capped (24 × 24; curves 16 × 16, blend
//! GBS level 2, shell level 1 and OBJ inputs of 8 KiB) so that one input stays fast: a flat-cap
//! layout search refused at 48 × 32 samples took 2.5 s of CPU, at 24 × 24 0.11 s, and such
//! inputs held the fuzzer to ~100 exec/s (the library's own ceilings are far above). Any
//! panic is a finding, and so is a result that breaks the contract: a fit residual above
//! its tolerance, a non-finite control point, a target count that is not the vertex count, a
//! condition estimate above the refused bound, a mesh that is not manifold; each result is
//! then handed to the C API (`profsubd_mesh_read_obj` of its OBJ) for the mesh contract
//! (`check_mesh`: evaluation at random points inside the control points' bounding box,
//! refinement). Seeds: `fuzz/corpus/construction/` (the examples' JSON and small OBJ
//! meshes, prefixed with their kind byte).
#![no_main]

use std::ffi::CString;
use std::io::Write;
use std::path::{Path, PathBuf};

use libfuzzer_sys::fuzz_target;
use profsubd::construct::blend::{self, BlendInput};
use profsubd::construct::curves;
use profsubd::construct::settings::parse_json;
use profsubd::{profile, revolve, sweep, CurvesInput, Fitted, ProfileInput, RevolveInput};
use profsubd::{Mesh, SweepInput};
use profsubd_fuzz::*;

/// Largest sample interval count per direction the target builds.
const CAP: u32 = 24;
/// Largest quad count per direction of a curves patch.
const CURVES_CAP: usize = 16;
/// Largest GBS level of a blend.
const BLEND_LEVEL_CAP: u32 = 2;
/// Largest OBJ input of the shell, bytes.
const SHELL_MAX_BYTES: usize = 8192;

/// A temporary file of this process named `name`, holding `bytes`.
fn temp_file(name: &str, bytes: &[u8]) -> PathBuf {
    let path = std::env::temp_dir().join(format!("profsubd-fuzz-{}-{name}", std::process::id()));
    std::fs::File::create(&path)
        .unwrap()
        .write_all(bytes)
        .unwrap();
    path
}

/// `mesh` through the C API: read back from its OBJ, then the mesh contract.
fn check_through_c(mesh: &Mesh, params: &mut Bytes) {
    let path = temp_file("built.obj", profsubd::io::obj::to_obj_string(mesh).as_bytes());
    let c_path = CString::new(path.to_str().unwrap()).unwrap();
    let mut c_mesh: *mut profsubd_mesh = std::ptr::null_mut();
    let status = unsafe { profsubd_mesh_read_obj(c_path.as_ptr(), &mut c_mesh) };
    assert_eq!(status, PROFSUBD_OK, "a construction's OBJ must read back: {}", last_error());
    check_mesh(c_mesh, params);
    unsafe { profsubd_mesh_free(c_mesh) };
}

fn check(result: profsubd::Result<Fitted>, params: &mut Bytes) {
    let Ok(f) = result else { return };
    assert_eq!(f.targets.len(), f.mesh.num_vertices(), "one target per vertex");
    assert!(
        f.fit.residual <= f.fit.tolerance,
        "residual {} above tolerance {}",
        f.fit.residual,
        f.fit.tolerance
    );
    assert!(f.mesh.positions().iter().all(|p| p.is_finite()), "non-finite control point");
    assert!(f.fit.condition <= profsubd::MAX_FIT_CONDITION, "condition {}", f.fit.condition);
    assert!(f.mesh.check().is_manifold(), "non-manifold construction: {:?}", f.mesh.check());
    check_through_c(&f.mesh, params);
}

/// The shell through the C API: `data` = thickness, level, flags bytes, then an OBJ.
fn shell(data: &[u8]) {
    if data.len() < 3 || data.len() > SHELL_MAX_BYTES {
        return;
    }
    let (params, obj) = data.split_at(3);
    let path = temp_file("shell-in.obj", obj);
    let c_path = CString::new(path.to_str().unwrap()).unwrap();
    let mut mesh: *mut profsubd_mesh = std::ptr::null_mut();
    if unsafe { profsubd_mesh_read_obj(c_path.as_ptr(), &mut mesh) } != PROFSUBD_OK {
        return;
    }
    // Thickness from 1/64 to 4 (0 and 255 stand for the invalid 0 and NaN).
    let thickness = match params[0] {
        0 => 0.0,
        255 => f64::NAN,
        t => f64::from(t) / 64.0,
    };
    let level = u32::from(params[1] % 2);
    let flags = i32::from(params[2] % 4);
    let mut fitted: *mut profsubd_fitted = std::ptr::null_mut();
    let status = unsafe {
        profsubd_shell(mesh, thickness, level, 0.0, flags, std::ptr::null(), &mut fitted)
    };
    check_error(status, "shell");
    if status == PROFSUBD_OK {
        let mut solid: *mut profsubd_mesh = std::ptr::null_mut();
        assert_eq!(unsafe { profsubd_fitted_get_mesh(fitted, &mut solid) }, PROFSUBD_OK);
        let mut report: profsubd_mesh_report = unsafe { std::mem::zeroed() };
        report.struct_size = std::mem::size_of::<profsubd_mesh_report>();
        assert_eq!(unsafe { profsubd_mesh_check(solid, &mut report) }, PROFSUBD_OK);
        assert_eq!(report.is_manifold, 1, "non-manifold shell");
        check_mesh(solid, &mut Bytes(obj));
        unsafe {
            profsubd_mesh_free(solid);
            profsubd_fitted_free(fitted);
        }
    } else {
        assert!(fitted.is_null(), "output written on error");
    }
    unsafe { profsubd_mesh_free(mesh) };
}

fuzz_target!(|data: &[u8]| {
    let Some((&kind, rest)) = data.split_first() else { return };
    if kind % 6 == 5 {
        return shell(rest);
    }
    let Ok(text) = std::str::from_utf8(rest) else { return };
    let path = Path::new("fuzz.json");
    // Evaluation points and the refinement level come from the input's bytes too.
    let params = &mut Bytes(rest);
    match kind % 6 {
        0 => {
            if let Ok((mut i, s)) = ProfileInput::from_json(text, path) {
                (i.along, i.around) = (i.along.min(CAP), i.around.min(CAP));
                check(profile::build(&i, &s), params);
            }
        }
        1 => {
            if let Ok((mut i, s)) = RevolveInput::from_json(text, path) {
                i.samples_profile = i.samples_profile.min(CAP as usize);
                i.samples_around = i.samples_around.min(CAP as usize);
                check(revolve::build(&i, &s), params);
            }
        }
        2 => {
            if let Ok((mut i, s)) = SweepInput::from_json(text, path) {
                i.samples_profile = i.samples_profile.min(CAP as usize);
                i.samples_trajectory = i.samples_trajectory.min(CAP as usize);
                check(sweep::build(&i, &s), params);
            }
        }
        3 => {
            if let Ok((mut i, s)) = CurvesInput::from_json(text, path) {
                i.samples = i.samples.map(|n| n.min(CURVES_CAP));
                check(curves::build(&i, &s), params);
            }
        }
        _ => {
            if let Ok((mut i, s)) = parse_json::<BlendInput>(text, path) {
                i.gbs_level = i.gbs_level.min(BLEND_LEVEL_CAP);
                check(blend::build(&i, &s), params);
            }
        }
    }
});
