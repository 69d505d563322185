//! `profsubd_mesh_new` from arrays drawn from the fuzzer's bytes: any face sizes (valences),
//! indices (out of range, repeated in a face, non-manifold edges), creases and corners
//! (NaN, negative, infinite sharpness, edges that do not exist), holes, non-finite
//! coordinates; then the mesh contract (evaluation, refinement; `check_mesh`).
#![no_main]

use libfuzzer_sys::fuzz_target;
use profsubd_fuzz::*;

/// Sharpness values worth hitting, including the invalid ones.
const SHARPNESS: [f32; 8] = [0.0, 0.5, 1.0, 2.7, 10.0, -1.0, f32::NAN, f32::INFINITY];

fuzz_target!(|data: &[u8]| {
    let mut b = Bytes(data);
    let nv = usize::from(b.u8() % 40) + 1;
    let nf = usize::from(b.u8() % 24) + 1;
    // A few more indices than vertices, so that out-of-range ones occur.
    let index = |b: &mut Bytes| u32::from(b.u8()) % (nv as u32 + 2);
    let positions: Vec<f64> = (0..3 * nv)
        .map(|_| match b.u8() {
            255 => f64::NAN,
            254 => f64::INFINITY,
            x => f64::from(x) / 16.0 - 4.0,
        })
        .collect();
    let face_sizes: Vec<u32> = (0..nf).map(|_| u32::from(b.u8() % 7)).collect();
    let mut face_indices: Vec<u32> = Vec::new();
    for &n in &face_sizes {
        for _ in 0..n {
            face_indices.push(index(&mut b));
        }
    }
    // Sometimes a count that does not match the face sizes.
    if b.u8() == 7 {
        face_indices.pop();
    }
    let nc = usize::from(b.u8() % 8);
    let crease_vertices: Vec<u32> = (0..2 * nc).map(|_| index(&mut b)).collect();
    let crease_sharpness: Vec<f32> = (0..nc)
        .map(|_| SHARPNESS[usize::from(b.u8() % 8)])
        .collect();
    let nk = usize::from(b.u8() % 4);
    let corner_vertices: Vec<u32> = (0..nk).map(|_| index(&mut b)).collect();
    let corner_sharpness: Vec<f32> = (0..nk)
        .map(|_| SHARPNESS[usize::from(b.u8() % 8)])
        .collect();
    let nh = usize::from(b.u8() % 3);
    let hole_faces: Vec<u32> = (0..nh)
        .map(|_| u32::from(b.u8()) % (nf as u32 + 1))
        .collect();
    let desc = profsubd_mesh_desc {
        struct_size: std::mem::size_of::<profsubd_mesh_desc>(),
        positions: positions.as_ptr(),
        num_vertices: nv,
        face_sizes: face_sizes.as_ptr(),
        num_faces: nf,
        face_indices: face_indices.as_ptr(),
        num_face_indices: face_indices.len(),
        crease_vertices: crease_vertices.as_ptr(),
        crease_sharpness: crease_sharpness.as_ptr(),
        num_creases: nc,
        corner_vertices: corner_vertices.as_ptr(),
        corner_sharpness: corner_sharpness.as_ptr(),
        num_corners: nk,
        hole_faces: hole_faces.as_ptr(),
        num_holes: nh,
    };
    let mut mesh: *mut profsubd_mesh = std::ptr::null_mut();
    let status = unsafe { profsubd_mesh_new(&desc, &mut mesh) };
    check_error(status, "mesh_new");
    if status == PROFSUBD_OK {
        check_mesh(mesh, &mut b);
        unsafe { profsubd_mesh_free(mesh) };
    } else {
        assert!(mesh.is_null(), "output written on error");
    }
});
