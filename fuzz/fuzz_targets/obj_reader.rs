//! The OBJ reader (`profsubd_mesh_read_obj`) on arbitrary bytes, then the mesh contract
//! (evaluation, refinement; `profsubd_fuzz::check_mesh`) on whatever it accepts. The last 48
//! bytes (when there are more than 64) choose the evaluation points and refinement level.
#![no_main]

use std::ffi::CString;
use std::io::Write;

use libfuzzer_sys::fuzz_target;
use profsubd_fuzz::*;

fuzz_target!(|data: &[u8]| {
    let split = if data.len() > 64 {
        data.len() - 48
    } else {
        data.len()
    };
    let (text, params) = data.split_at(split);
    let path = std::env::temp_dir().join(format!("profsubd-fuzz-{}.obj", std::process::id()));
    std::fs::File::create(&path)
        .unwrap()
        .write_all(text)
        .unwrap();
    let c_path = CString::new(path.to_str().unwrap()).unwrap();
    let mut mesh: *mut profsubd_mesh = std::ptr::null_mut();
    let status = unsafe { profsubd_mesh_read_obj(c_path.as_ptr(), &mut mesh) };
    check_error(status, "mesh_read_obj");
    if status == PROFSUBD_OK {
        check_mesh(mesh, &mut Bytes(params));
        unsafe { profsubd_mesh_free(mesh) };
    } else {
        assert!(mesh.is_null(), "output written on error");
    }
});
