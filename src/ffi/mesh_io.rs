//! OBJ files (with OpenSubdiv's tags) to and from mesh handles, and the reader's warnings.

use std::ffi::c_char;

use crate::ffi::error::FfiError;
use crate::ffi::handle::{self, into_raw};
use crate::ffi::mesh::{count_query, mesh_arg, profsubd_mesh, MeshData};
use crate::ffi::panic::status_call;
use crate::ffi::ptr::{arg_out, arg_path};
use crate::ffi::status::profsubd_status;
use crate::io::obj::{read_obj_file, write_obj_file};

/// Read an OBJ file with OpenSubdiv's tag lines (`t crease`, `t corner`, `t hole`,
/// `t interpolateboundary`, `t creasemethod`, `t smoothtriangles`); `*out` receives the mesh.
/// Tags the reader ignores are kept as warnings (`profsubd_mesh_get_warning`). Errors:
/// `PROFSUBD_ERROR_IO` (cannot read), `PROFSUBD_ERROR_PARSE` (malformed; the message gives
/// file, line and what was expected), `PROFSUBD_ERROR_INVALID_MESH`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_read_obj(
    path: *const c_char,
    out: *mut *mut profsubd_mesh,
) -> profsubd_status {
    status_call(|| {
        let path = arg_path(path, "path")?;
        let out = arg_out(out, "out")?;
        let read = read_obj_file(&path)?;
        out.write(into_raw(MeshData::with_warnings(read.mesh, read.warnings)));
        Ok(())
    })
}

/// Write the mesh as OBJ with its tags; reading the file back gives the same mesh, bit for
/// bit. An existing file is replaced. Errors: `PROFSUBD_ERROR_IO`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_write_obj(
    mesh: *const profsubd_mesh,
    path: *const c_char,
) -> profsubd_status {
    status_call(|| {
        let m = mesh_arg(mesh, "mesh")?;
        let path = arg_path(path, "path")?;
        write_obj_file(m, &path)?;
        Ok(())
    })
}

/// Number of warnings the OBJ reader gave for this mesh (0 for a mesh not read from a file).
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_num_warnings(
    mesh: *const profsubd_mesh,
    out: *mut usize,
) -> profsubd_status {
    count_query(mesh, out, |m| m.warnings().len())
}

/// Warning number `index` (0-based), as "file:line: what was ignored". `*out` receives a
/// string owned by the mesh, valid until the mesh is freed. An index not below
/// `profsubd_mesh_num_warnings` gives `PROFSUBD_ERROR_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn profsubd_mesh_get_warning(
    mesh: *const profsubd_mesh,
    index: usize,
    out: *mut *const c_char,
) -> profsubd_status {
    status_call(|| {
        let warnings = handle::borrow(mesh, "mesh")?.warnings();
        let out = arg_out(out, "out")?;
        let w = warnings.get(index).ok_or_else(|| {
            FfiError::invalid_argument(format!(
                "warning index {index} is out of range; the mesh has {} warnings",
                warnings.len()
            ))
        })?;
        out.write(w.as_ptr());
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::error::last_error;
    use crate::ffi::mesh::{profsubd_mesh_free, profsubd_mesh_num_creases};
    use crate::ffi::status::profsubd_status::*;
    use std::ffi::{CStr, CString};
    use std::ptr::{null, null_mut};

    const CUBE_FACE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n\
                             t crease 2/1/0 0 1 2.5\nt vertexedit 0/0/0\n";

    fn c_path(p: &std::path::Path) -> CString {
        CString::new(p.to_str().unwrap()).unwrap()
    }

    fn read(path: &CStr) -> (profsubd_status, *mut profsubd_mesh) {
        let mut m = null_mut();
        let s = unsafe { profsubd_mesh_read_obj(path.as_ptr(), &mut m) };
        (s, m)
    }

    #[test]
    fn read_write_round_trip_keeps_tags_and_warnings() {
        let dir = tempfile::tempdir().unwrap();
        let a = dir.path().join("a.obj");
        std::fs::write(&a, CUBE_FACE).unwrap();
        let (s, m) = read(&c_path(&a));
        assert_eq!(s, PROFSUBD_OK, "{}", last_error());
        unsafe {
            let mut n = 0;
            assert_eq!(profsubd_mesh_num_warnings(m, &mut n), PROFSUBD_OK);
            assert_eq!(n, 1);
            let mut w = null();
            assert_eq!(profsubd_mesh_get_warning(m, 0, &mut w), PROFSUBD_OK);
            let text = CStr::from_ptr(w).to_str().unwrap();
            assert!(text.contains("a.obj:7"), "{text}");
            assert_eq!(
                profsubd_mesh_get_warning(m, 1, &mut w),
                PROFSUBD_ERROR_INVALID_ARGUMENT
            );
            assert_eq!(
                last_error(),
                "warning index 1 is out of range; the mesh has 1 warnings"
            );

            let b = dir.path().join("b.obj");
            assert_eq!(profsubd_mesh_write_obj(m, c_path(&b).as_ptr()), PROFSUBD_OK);
            let (s, m2) = read(&c_path(&b));
            assert_eq!(s, PROFSUBD_OK);
            let (m1, m2r) = (mesh_arg(m, "m").unwrap(), mesh_arg(m2, "m").unwrap());
            assert_eq!(m1, m2r);
            assert_eq!(profsubd_mesh_num_creases(m2, &mut n), PROFSUBD_OK);
            assert_eq!(n, 1);
            assert_eq!(profsubd_mesh_num_warnings(m2, &mut n), PROFSUBD_OK);
            assert_eq!(n, 0);
            profsubd_mesh_free(m);
            profsubd_mesh_free(m2);
        }
    }

    #[test]
    fn file_errors_have_their_status_and_say_where() {
        let dir = tempfile::tempdir().unwrap();
        let missing = dir.path().join("missing.obj");
        let (s, m) = read(&c_path(&missing));
        assert_eq!((s, m), (PROFSUBD_ERROR_IO, null_mut()));
        assert!(last_error().contains("missing.obj"), "{}", last_error());

        let bad = dir.path().join("bad.obj");
        std::fs::write(&bad, "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 x\n").unwrap();
        let (s, m) = read(&c_path(&bad));
        assert_eq!((s, m), (PROFSUBD_ERROR_PARSE, null_mut()));
        assert!(last_error().contains("bad.obj:4"), "{}", last_error());

        let two = dir.path().join("two.obj");
        std::fs::write(&two, "v 0 0 0\nv 1 0 0\nf 1 2\n").unwrap();
        let (s, _) = read(&c_path(&two));
        assert!(
            matches!(s, PROFSUBD_ERROR_PARSE | PROFSUBD_ERROR_INVALID_MESH),
            "{s:?}"
        );

        std::fs::write(&bad, CUBE_FACE).unwrap();
        let (s, m) = read(&c_path(&bad));
        assert_eq!(s, PROFSUBD_OK);
        let unwritable = c_path(&dir.path().join("no/such/dir/x.obj"));
        unsafe {
            assert_eq!(
                profsubd_mesh_write_obj(m, unwritable.as_ptr()),
                PROFSUBD_ERROR_IO
            );
            profsubd_mesh_free(m);
        }
    }

    #[test]
    fn null_empty_and_invalid_arguments_are_rejected() {
        let mut m = null_mut();
        let mut n = 0;
        let mut w = null();
        let mut fake = [0u64; 8];
        let f = fake.as_mut_ptr().cast::<profsubd_mesh>().cast_const();
        unsafe {
            assert_eq!(
                profsubd_mesh_read_obj(null(), &mut m),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(last_error(), "argument `path` is NULL");
            assert_eq!(
                profsubd_mesh_read_obj(c"x.obj".as_ptr(), null_mut()),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(
                profsubd_mesh_read_obj(c"".as_ptr(), &mut m),
                PROFSUBD_ERROR_INVALID_ARGUMENT
            );
            assert_eq!(
                profsubd_mesh_write_obj(null(), c"x.obj".as_ptr()),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(
                profsubd_mesh_write_obj(f, c"x.obj".as_ptr()),
                PROFSUBD_ERROR_INVALID_HANDLE
            );
            assert_eq!(
                profsubd_mesh_num_warnings(null(), &mut n),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(
                profsubd_mesh_num_warnings(f, &mut n),
                PROFSUBD_ERROR_INVALID_HANDLE
            );
            assert_eq!(
                profsubd_mesh_get_warning(null(), 0, &mut w),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(
                profsubd_mesh_get_warning(f, 0, &mut w),
                PROFSUBD_ERROR_INVALID_HANDLE
            );
            let q = crate::ffi::mesh::new_mesh_handle(crate::test_support::quad_mesh());
            assert_eq!(
                profsubd_mesh_write_obj(q, null()),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(
                profsubd_mesh_num_warnings(q, null_mut()),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(
                profsubd_mesh_get_warning(q, 0, null_mut()),
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            profsubd_mesh_free(q);
        }
        assert_eq!((m, n, w, fake), (null_mut(), 0, null(), [0; 8]));
        assert!(!std::path::Path::new("x.obj").exists());
    }
}
