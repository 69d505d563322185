//! Tests of the evaluator C functions, bad input first.

use std::ptr::{null, null_mut};

use glam::DVec3;

use super::*;
use crate::eval::limit_vertex_samples;
use crate::ffi::error::last_error;
use crate::ffi::mesh::{new_mesh_handle, profsubd_mesh_free};
use crate::ffi::status::profsubd_status::*;
use crate::mesh::{Mesh, MeshParts};
use crate::options::SubdivOptions;

/// A closed cube, with a triangle fan replacing its top (mixed face sizes).
fn mesh() -> Mesh {
    let mut positions: Vec<DVec3> = (0..8)
        .map(|k| DVec3::new((k & 1) as f64, ((k >> 1) & 1) as f64, ((k >> 2) & 1) as f64))
        .collect();
    positions.push(DVec3::new(0.5, 0.5, 1.3));
    Mesh::from_parts(MeshParts {
        positions,
        face_sizes: vec![4, 4, 4, 4, 4, 3, 3, 3, 3],
        face_indices: vec![
            0, 2, 3, 1, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5, 4, 5, 8, 5, 7, 8, 7, 6, 8,
            6, 4, 8,
        ],
        holes: vec![1],
        ..Default::default()
    })
    .unwrap()
}

fn evaluator() -> *mut profsubd_evaluator {
    let m = new_mesh_handle(mesh());
    let mut ev = null_mut();
    unsafe {
        assert_eq!(profsubd_evaluator_new(m, null(), &mut ev), PROFSUBD_OK);
        profsubd_mesh_free(m);
    }
    ev
}

#[test]
fn evaluate_returns_what_the_rust_api_returns() {
    let ev = evaluator();
    let rust = Evaluator::new(&mesh(), &SubdivOptions::default()).unwrap();
    let faces = [0u32, 2, 5, 7, 16];
    let u = [0.25, 0.0, 0.5, 1.0, 0.9];
    let v = [0.75, 0.0, 0.5, 0.3, 0.1];
    let (mut p, mut du, mut dv) = ([0.0; 15], [0.0; 15], [0.0; 15]);
    unsafe {
        let mut n = 0;
        assert_eq!(
            profsubd_evaluator_num_parametric_faces(ev, &mut n),
            PROFSUBD_OK
        );
        assert_eq!(n, 5 + 4 * 3);
        let (mut first, mut count) = (0, 0);
        assert_eq!(
            profsubd_evaluator_face_to_parametric(ev, 6, &mut first, &mut count),
            PROFSUBD_OK
        );
        assert_eq!((first, count), (8, 3));
        let st = profsubd_evaluator_evaluate(
            ev,
            faces.as_ptr(),
            u.as_ptr(),
            v.as_ptr(),
            5,
            p.as_mut_ptr(),
            du.as_mut_ptr(),
            dv.as_mut_ptr(),
        );
        assert_eq!(st, PROFSUBD_OK, "{}", last_error());
        // Derivatives are optional.
        let mut p2 = [0.0; 15];
        let st = profsubd_evaluator_evaluate(
            ev,
            faces.as_ptr(),
            u.as_ptr(),
            v.as_ptr(),
            5,
            p2.as_mut_ptr(),
            null_mut(),
            null_mut(),
        );
        assert_eq!(st, PROFSUBD_OK);
        assert_eq!(p, p2);
        profsubd_evaluator_free(ev);
    }
    for i in 0..5 {
        let s = rust.evaluate(faces[i], u[i], v[i]).unwrap();
        assert_eq!(&p[3 * i..3 * i + 3], &s.position.to_array());
        assert_eq!(&du[3 * i..3 * i + 3], &s.du.to_array());
        assert_eq!(&dv[3 * i..3 * i + 3], &s.dv.to_array());
    }
}

#[test]
fn bad_input_gives_a_status_and_a_message_and_writes_nothing() {
    let ev = evaluator();
    let mut p = [7.0; 3];
    let f = [0u32];
    let half = [0.5];
    unsafe {
        let call = |ev, faces: &[u32], u: f64, v: f64, out: *mut f64| {
            profsubd_evaluator_evaluate(ev, faces.as_ptr(), &u, &v, 1, out, null_mut(), null_mut())
        };
        assert_eq!(
            call(null(), &f, 0.5, 0.5, p.as_mut_ptr()),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        let garbage = [0u64; 4];
        assert_eq!(
            call(garbage.as_ptr().cast(), &f, 0.5, 0.5, p.as_mut_ptr()),
            PROFSUBD_ERROR_INVALID_HANDLE
        );
        assert_eq!(
            call(ev, &[17], 0.5, 0.5, p.as_mut_ptr()),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(
            last_error().contains("face 17 is out of range"),
            "{}",
            last_error()
        );
        assert_eq!(
            call(ev, &f, -0.1, 0.5, p.as_mut_ptr()),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("outside [0, 1]"));
        assert_eq!(
            call(ev, &f, 0.5, f64::NAN, p.as_mut_ptr()),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            call(ev, &[1], 0.5, 0.5, p.as_mut_ptr()),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("point 0 has no limit surface"));
        assert_eq!(
            call(ev, &f, 0.5, 0.5, null_mut()),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert_eq!(p, [7.0; 3]);
        let st = profsubd_evaluator_evaluate(
            ev,
            null(),
            half.as_ptr(),
            half.as_ptr(),
            1,
            p.as_mut_ptr(),
            null_mut(),
            null_mut(),
        );
        assert_eq!(st, PROFSUBD_ERROR_NULL_ARGUMENT);
        // n = 0 with NULL arrays is a valid empty call.
        let st = profsubd_evaluator_evaluate(
            ev,
            null(),
            null(),
            null(),
            0,
            null_mut(),
            null_mut(),
            null_mut(),
        );
        assert_eq!(st, PROFSUBD_OK);
        let (mut a, mut b) = (0, 0);
        assert_eq!(
            profsubd_evaluator_face_to_parametric(ev, 9, &mut a, &mut b),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        let mut out = null_mut();
        assert_eq!(
            profsubd_evaluator_new(null(), null(), &mut out),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        let m = new_mesh_handle(mesh());
        assert_eq!(
            profsubd_evaluator_new(m, null(), null_mut()),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        // A mesh handle is not an evaluator.
        let mut n = 0;
        assert_eq!(
            profsubd_evaluator_num_parametric_faces(m.cast(), &mut n),
            PROFSUBD_ERROR_INVALID_HANDLE
        );
        profsubd_mesh_free(m);
        profsubd_evaluator_free(ev);
        profsubd_evaluator_free(null_mut());
    }
}

#[test]
fn limit_vertices_follow_the_copy_out_protocol() {
    let ev = evaluator();
    let want = limit_vertex_samples(&mesh(), &SubdivOptions::default()).unwrap();
    let mut p = vec![0.0; 27];
    let mut du = vec![0.0; 27];
    let mut needed = 0;
    unsafe {
        let st = profsubd_evaluator_limit_vertices(
            ev,
            p.as_mut_ptr(),
            null_mut(),
            null_mut(),
            2,
            &mut needed,
        );
        assert_eq!(st, PROFSUBD_ERROR_BUFFER_TOO_SMALL);
        assert_eq!(needed, 9);
        assert_eq!(p, vec![0.0; 27]);
        let st = profsubd_evaluator_limit_vertices(
            ev,
            null_mut(),
            null_mut(),
            null_mut(),
            0,
            &mut needed,
        );
        assert_eq!(st, PROFSUBD_ERROR_BUFFER_TOO_SMALL);
        let st = profsubd_evaluator_limit_vertices(
            ev,
            p.as_mut_ptr(),
            du.as_mut_ptr(),
            null_mut(),
            9,
            &mut needed,
        );
        assert_eq!(st, PROFSUBD_OK, "{}", last_error());
        profsubd_evaluator_free(ev);
    }
    for (i, s) in want.iter().enumerate() {
        assert_eq!(&p[3 * i..3 * i + 3], &s.position.to_array());
        assert_eq!(&du[3 * i..3 * i + 3], &s.du.to_array());
    }
}

#[test]
fn corners_at_extraordinary_vertices_are_the_vertex_limits() {
    let ev = Evaluator::new(&mesh(), &SubdivOptions::default()).unwrap();
    let limits = ev.limit_vertices().unwrap();
    // Face 0 = (0, 2, 3, 1): every corner is a valence-3 vertex.
    for (k, (u, v)) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
        .into_iter()
        .enumerate()
    {
        let s = ev.evaluate(0, u, v).unwrap();
        let w = limits[[0, 2, 3, 1][k]];
        assert!((s.position - w.position).length() < 1e-15, "corner {k}");
        assert!(s.normal().dot(w.normal()) > 1.0 - 1e-12, "corner {k}");
    }
    // The apex of the triangle fan is vertex 2 of triangle 5 (Ptex faces 5..8): corner
    // (0, 0) of its sub-face 2.
    let apex = ev.evaluate(5 + 2, 0.0, 0.0).unwrap();
    assert!((apex.position - limits[8].position).length() < 1e-15);
}

/// The test mesh with one more, isolated, vertex (9): no limit surface there.
fn evaluator_with_isolated_vertex() -> *mut profsubd_evaluator {
    let mut parts = mesh().into_parts();
    parts.positions.push(DVec3::splat(4.0));
    let m = new_mesh_handle(Mesh::from_parts(parts).unwrap());
    let mut ev = null_mut();
    unsafe {
        assert_eq!(profsubd_evaluator_new(m, null(), &mut ev), PROFSUBD_OK);
        profsubd_mesh_free(m);
    }
    ev
}

const PTEX: i32 = profsubd_domain::PROFSUBD_DOMAIN_PTEX as i32;
const BFR: i32 = profsubd_domain::PROFSUBD_DOMAIN_BFR as i32;

#[test]
fn evaluate_points_marks_points_without_surface_and_takes_both_domains() {
    let ev = evaluator();
    let rust = Evaluator::new(&mesh(), &SubdivOptions::default()).unwrap();
    // Ptex: face 1 is a hole; face 7 is sub-face 2 of triangle 5. Bfr: the same points,
    // sub-face 2 of a triangle at tile (0, 1).
    let (pf, pu, pv) = ([0u32, 1, 7], [0.25, 0.5, 0.5], [0.75, 0.5, 0.25]);
    let (bf, bu, bv) = ([0u32, 1, 5], [0.25, 0.5, 0.25], [0.75, 0.5, 1.125]);
    let mut out = [[0.0f64; 9]; 6];
    let mut masks = [[7u8; 3]; 2];
    unsafe {
        for (d, (f, u, v)) in [(PTEX, (&pf, &pu, &pv)), (BFR, (&bf, &bu, &bv))] {
            let k = if d == PTEX { 0 } else { 3 };
            let [p, du, dv] = &mut out[k..k + 3] else {
                unreachable!()
            };
            let st = profsubd_evaluator_evaluate_points(
                ev,
                d,
                0,
                f.as_ptr(),
                u.as_ptr(),
                v.as_ptr(),
                3,
                p.as_mut_ptr(),
                du.as_mut_ptr(),
                dv.as_mut_ptr(),
                masks[k / 3].as_mut_ptr(),
            );
            assert_eq!(st, PROFSUBD_OK, "{}", last_error());
        }
        // Strict: the hole fails the batch, naming the point, and nothing is written.
        let mut p = [5.0f64; 9];
        let mut mask = [5u8; 3];
        let st = profsubd_evaluator_evaluate_points(
            ev,
            PTEX,
            1,
            pf.as_ptr(),
            pu.as_ptr(),
            pv.as_ptr(),
            3,
            p.as_mut_ptr(),
            null_mut(),
            null_mut(),
            mask.as_mut_ptr(),
        );
        assert_eq!(st, PROFSUBD_ERROR_INVALID_ARGUMENT);
        assert!(
            last_error().contains("point 1 has no limit surface (strict mode)"),
            "{}",
            last_error()
        );
        assert_eq!((p, mask), ([5.0; 9], [5; 3]));
        // Strict without such a point; no mask or derivatives asked for.
        let st = profsubd_evaluator_evaluate_points(
            ev,
            BFR,
            1,
            bf.as_ptr(),
            bu.as_ptr(),
            bv.as_ptr(),
            1,
            p.as_mut_ptr(),
            null_mut(),
            null_mut(),
            null_mut(),
        );
        assert_eq!(st, PROFSUBD_OK);
        assert_eq!(p[..3], out[0][..3]);
        profsubd_evaluator_free(ev);
    }
    assert_eq!(masks, [[1, 0, 1]; 2]);
    for i in [0, 2] {
        let s = rust.evaluate(pf[i], pu[i], pv[i]).unwrap();
        let scale = if i == 2 { 2.0 } else { 1.0 };
        let r = 3 * i..3 * i + 3;
        assert_eq!(out[0][r.clone()], s.position.to_array());
        assert_eq!(out[1][r.clone()], s.du.to_array());
        assert_eq!(out[3][r.clone()], s.position.to_array());
        assert_eq!(out[4][r.clone()], (s.du * scale).to_array());
        assert_eq!(out[5][r], (s.dv * scale).to_array());
    }
    for (k, a) in out.iter().enumerate() {
        assert!(a[3..6].iter().all(|x| x.is_nan()), "{k}: {a:?}");
    }
}

#[test]
fn evaluate_points_rejects_bad_input_and_writes_nothing() {
    let ev = evaluator();
    let (f, h) = ([0u32], [0.5]);
    let mut p = [3.0f64; 3];
    let mut mask = [3u8];
    unsafe {
        let call = |ev, domain, strict, faces: &[u32], u: f64, p: *mut f64, mask: *mut u8| {
            profsubd_evaluator_evaluate_points(
                ev,
                domain,
                strict,
                faces.as_ptr(),
                &u,
                h.as_ptr(),
                1,
                p,
                null_mut(),
                null_mut(),
                mask,
            )
        };
        let pm = (p.as_mut_ptr(), mask.as_mut_ptr());
        assert_eq!(
            call(null(), PTEX, 0, &f, 0.5, pm.0, pm.1),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        let garbage = [0u64; 4];
        assert_eq!(
            call(garbage.as_ptr().cast(), PTEX, 0, &f, 0.5, pm.0, pm.1),
            PROFSUBD_ERROR_INVALID_HANDLE
        );
        assert_eq!(
            call(ev, 2, 0, &f, 0.5, pm.0, pm.1),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("domain value 2"), "{}", last_error());
        assert_eq!(
            call(ev, PTEX, -1, &f, 0.5, pm.0, pm.1),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("strict value -1"), "{}", last_error());
        assert_eq!(
            call(ev, BFR, 0, &[9], 0.5, pm.0, pm.1),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("point 0: face 9 is out of range; the mesh has 9 faces"));
        // Triangle 5 in Bfr's domain: (0.6, 0.5) is in the gap between sub-face squares.
        assert_eq!(
            call(ev, BFR, 0, &[5], 0.6, pm.0, pm.1),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("outside the Bfr domain of face 5"));
        assert_eq!(
            call(ev, PTEX, 0, &f, f64::NAN, pm.0, pm.1),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            call(ev, PTEX, 0, &f, 0.5, null_mut(), pm.1),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        let st = profsubd_evaluator_evaluate_points(
            ev,
            PTEX,
            0,
            null(),
            h.as_ptr(),
            h.as_ptr(),
            1,
            p.as_mut_ptr(),
            null_mut(),
            null_mut(),
            null_mut(),
        );
        assert_eq!(st, PROFSUBD_ERROR_NULL_ARGUMENT);
        assert_eq!((p, mask), ([3.0; 3], [3]));
        profsubd_evaluator_free(ev);
    }
}

#[test]
fn limit_vertices_mark_the_isolated_vertex() {
    let ev = evaluator_with_isolated_vertex();
    let (mut p, mut du, mut dv) = (vec![0.0; 30], vec![0.0; 30], vec![0.0; 30]);
    let mut mask = vec![7u8; 10];
    let mut needed = 0;
    // Positions into `out`, no derivatives or mask.
    let positions_only = |ev, strict, out: &mut Vec<f64>, needed: &mut usize| unsafe {
        profsubd_evaluator_limit_vertices_masked(
            ev,
            strict,
            out.as_mut_ptr(),
            null_mut(),
            null_mut(),
            null_mut(),
            10,
            needed,
        )
    };
    unsafe {
        for (capacity, want) in [(9, PROFSUBD_ERROR_BUFFER_TOO_SMALL), (10, PROFSUBD_OK)] {
            let st = profsubd_evaluator_limit_vertices_masked(
                ev,
                0,
                p.as_mut_ptr(),
                du.as_mut_ptr(),
                dv.as_mut_ptr(),
                mask.as_mut_ptr(),
                capacity,
                &mut needed,
            );
            assert_eq!(st, want, "{}", last_error());
            assert_eq!(needed, 10);
            if capacity == 9 {
                assert_eq!((p[0], mask[0]), (0.0, 7), "nothing written");
            }
        }
        // The plain call writes the same, NaN included.
        let mut q = vec![0.0; 30];
        let st = profsubd_evaluator_limit_vertices(
            ev,
            q.as_mut_ptr(),
            null_mut(),
            null_mut(),
            10,
            null_mut(),
        );
        assert_eq!(st, PROFSUBD_OK);
        assert!(q[..27] == p[..27] && q[27..].iter().all(|x| x.is_nan()));
        // Strict: an error naming the vertex, nothing written.
        let mut r = vec![1.0; 30];
        assert_eq!(
            positions_only(ev, 1, &mut r, &mut needed),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("vertex 9 has no limit surface"));
        assert_eq!(
            positions_only(ev, 2, &mut r, &mut needed),
            PROFSUBD_ERROR_INVALID_ARGUMENT
        );
        assert_eq!(
            positions_only(null(), 0, &mut r, &mut needed),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        assert_eq!(r, vec![1.0; 30]);
        profsubd_evaluator_free(ev);
    }
    let want = limit_vertex_samples(&mesh(), &SubdivOptions::default()).unwrap();
    assert_eq!(mask, [1, 1, 1, 1, 1, 1, 1, 1, 1, 0]);
    for (i, s) in want.iter().enumerate() {
        assert_eq!(&p[3 * i..3 * i + 3], &s.position.to_array());
        assert_eq!(&dv[3 * i..3 * i + 3], &s.dv.to_array());
    }
    for a in [&p, &du, &dv] {
        assert!(a[27..].iter().all(|x| x.is_nan()));
    }
}

/// Positions and derivatives (9 doubles a point, all positions first) and the surface mask
/// at `(faces[i], u[i], v[i])` through the C API, Ptex domain, marking.
fn evaluate_marked(
    ev: *const profsubd_evaluator,
    faces: &[u32],
    u: &[f64],
    v: &[f64],
) -> (Vec<f64>, Vec<u8>) {
    let n = faces.len();
    let mut out = vec![0.0; 9 * n];
    let mut mask = vec![0u8; n];
    let (p, rest) = out.split_at_mut(3 * n);
    let (du, dv) = rest.split_at_mut(3 * n);
    unsafe {
        let st = profsubd_evaluator_evaluate_points(
            ev,
            profsubd_domain::PROFSUBD_DOMAIN_PTEX as i32,
            0,
            faces.as_ptr(),
            u.as_ptr(),
            v.as_ptr(),
            n,
            p.as_mut_ptr(),
            du.as_mut_ptr(),
            dv.as_mut_ptr(),
            mask.as_mut_ptr(),
        );
        assert_eq!(st, PROFSUBD_OK, "{}", last_error());
    }
    (out, mask)
}

/// [`evaluate_marked`] at `(face, 0.3, 0.6)` for every parametric face.
fn evaluate_all(ev: *const profsubd_evaluator) -> Vec<f64> {
    let faces: Vec<u32> = (0..17).collect();
    evaluate_marked(ev, &faces, &[0.3; 17], &[0.6; 17]).0
}

#[test]
fn update_positions_equals_a_fresh_build_and_rejects_bad_input_unchanged() {
    let ev = evaluator();
    let before = evaluate_all(ev);
    let moved: Vec<f64> = mesh()
        .positions()
        .iter()
        .enumerate()
        .flat_map(|(i, p)| {
            let q = *p * 1.5 + DVec3::new(0.1 * i as f64, -0.2, crate::math::sin(i as f64));
            [q.x, q.y, q.z]
        })
        .collect();
    let mut parts = mesh().into_parts();
    parts.positions = moved.chunks_exact(3).map(DVec3::from_slice).collect();
    let fresh = {
        let m = new_mesh_handle(Mesh::from_parts(parts).unwrap());
        let mut fresh = null_mut();
        unsafe {
            assert_eq!(profsubd_evaluator_new(m, null(), &mut fresh), PROFSUBD_OK);
            profsubd_mesh_free(m);
        }
        fresh
    };
    let mut bad = moved.clone();
    bad[7] = f64::NAN;
    unsafe {
        let cases: [(
            *mut profsubd_evaluator,
            *const f64,
            usize,
            profsubd_status,
            &str,
        ); 5] = [
            (
                ev,
                moved.as_ptr(),
                8,
                PROFSUBD_ERROR_INVALID_ARGUMENT,
                "8 positions given for a mesh of 9 vertices",
            ),
            (
                ev,
                moved.as_ptr(),
                usize::MAX,
                PROFSUBD_ERROR_INVALID_ARGUMENT,
                "for a mesh of 9 vertices",
            ),
            (
                ev,
                bad.as_ptr(),
                9,
                PROFSUBD_ERROR_INVALID_ARGUMENT,
                "position 2 has a non-finite coordinate",
            ),
            (ev, null(), 9, PROFSUBD_ERROR_NULL_ARGUMENT, "xyz"),
            (
                null_mut(),
                moved.as_ptr(),
                9,
                PROFSUBD_ERROR_NULL_ARGUMENT,
                "evaluator",
            ),
        ];
        for (e, xyz, n, status, message) in cases {
            assert_eq!(profsubd_evaluator_update_positions(e, xyz, n), status);
            assert!(last_error().contains(message), "{}", last_error());
            let same: Vec<u64> = evaluate_all(ev).iter().map(|x| x.to_bits()).collect();
            let want: Vec<u64> = before.iter().map(|x| x.to_bits()).collect();
            assert_eq!(same, want, "the evaluator changed on error");
        }
        assert_eq!(
            profsubd_evaluator_update_positions(ev, moved.as_ptr(), 9),
            PROFSUBD_OK
        );
        let got: Vec<u64> = evaluate_all(ev).iter().map(|x| x.to_bits()).collect();
        let want: Vec<u64> = evaluate_all(fresh).iter().map(|x| x.to_bits()).collect();
        assert_eq!(got, want);
        assert_ne!(evaluate_all(ev)[..3], before[..3]);
        profsubd_evaluator_free(ev);
        profsubd_evaluator_free(fresh);
    }
}

#[test]
fn thread_count_changes_nothing_in_the_results() {
    let ev = evaluator();
    // Enough points for several threads; every parametric face, corners included.
    let n = 20_000;
    let faces: Vec<u32> = (0..n).map(|i| (i * 7 % 17) as u32).collect();
    let u: Vec<f64> = (0..n).map(|i| ((i * 37) % 101) as f64 / 100.0).collect();
    let v: Vec<f64> = (0..n).map(|i| ((i * 53) % 97) as f64 / 96.0).collect();
    let run = |threads: usize| {
        assert_eq!(
            unsafe { profsubd_evaluator_set_threads(ev, threads) },
            PROFSUBD_OK
        );
        let (out, mask) = evaluate_marked(ev, &faces, &u, &v);
        let bits: Vec<u64> = out.iter().map(|x| x.to_bits()).collect();
        (bits, mask)
    };
    let one = run(1);
    assert!(
        one.1.contains(&0) && one.1.contains(&1),
        "holes and surface both present"
    );
    for threads in [0, 2, 3, 8] {
        assert_eq!(run(threads), one, "{threads} threads");
    }
    unsafe {
        assert_eq!(
            profsubd_evaluator_set_threads(null_mut(), 2),
            PROFSUBD_ERROR_NULL_ARGUMENT
        );
        // The first bad point is named whatever the thread count.
        let mut bad_u = u.clone();
        bad_u[n - 10] = 2.0;
        bad_u[15_000] = -1.0;
        let mut p = vec![0.0; 3 * n];
        for threads in [1, 4] {
            assert_eq!(profsubd_evaluator_set_threads(ev, threads), PROFSUBD_OK);
            let st = profsubd_evaluator_evaluate_points(
                ev,
                profsubd_domain::PROFSUBD_DOMAIN_PTEX as i32,
                0,
                faces.as_ptr(),
                bad_u.as_ptr(),
                v.as_ptr(),
                n,
                p.as_mut_ptr(),
                null_mut(),
                null_mut(),
                null_mut(),
            );
            assert_eq!(st, PROFSUBD_ERROR_INVALID_ARGUMENT);
            assert!(
                last_error().contains(": point 15000: (u, v) = (-1,"),
                "{}",
                last_error()
            );
        }
        profsubd_evaluator_free(ev);
    }
}

#[test]
fn evaluate_primvar_is_evaluate_for_the_positions_and_rejects_bad_input_writing_nothing() {
    let ev = evaluator();
    let faces = [0u32, 2, 5, 7, 16];
    let u = [0.25, 0.0, 0.5, 1.0, 0.9];
    let v = [0.75, 0.0, 0.5, 0.3, 0.1];
    let xyz: Vec<f64> = mesh()
        .positions()
        .iter()
        .flat_map(|p| p.to_array())
        .collect();
    let (mut p, mut du, mut dv) = ([0.0; 15], [0.0; 15], [0.0; 15]);
    let (mut q, mut qu, mut qv) = ([0.0; 15], [0.0; 15], [0.0; 15]);
    let bits = |x: &[f64]| x.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    unsafe {
        let (f, us, vs) = (faces.as_ptr(), u.as_ptr(), v.as_ptr());
        let st = profsubd_evaluator_evaluate(
            ev,
            f,
            us,
            vs,
            5,
            p.as_mut_ptr(),
            du.as_mut_ptr(),
            dv.as_mut_ptr(),
        );
        assert_eq!(st, PROFSUBD_OK);
        let st = profsubd_evaluator_evaluate_primvar(
            ev,
            xyz.as_ptr(),
            3,
            9,
            f,
            us,
            vs,
            5,
            q.as_mut_ptr(),
            qu.as_mut_ptr(),
            qv.as_mut_ptr(),
        );
        assert_eq!(st, PROFSUBD_OK, "{}", last_error());
        assert_eq!(
            (bits(&q), bits(&qu), bits(&qv)),
            (bits(&p), bits(&du), bits(&dv))
        );

        // Width 1, the z coordinate alone, derivatives not asked for.
        let z: Vec<f64> = xyz.iter().skip(2).step_by(3).copied().collect();
        let mut w = [0.0; 5];
        let st = profsubd_evaluator_evaluate_primvar(
            ev,
            z.as_ptr(),
            1,
            9,
            f,
            us,
            vs,
            5,
            w.as_mut_ptr(),
            null_mut(),
            null_mut(),
        );
        assert_eq!(st, PROFSUBD_OK, "{}", last_error());
        assert_eq!(
            bits(&w),
            bits(&p.iter().skip(2).step_by(3).copied().collect::<Vec<_>>())
        );

        let mut nan = z.clone();
        nan[4] = f64::INFINITY;
        let hole = [1u32; 5];
        let cases: [(
            *const profsubd_evaluator,
            *const f64,
            usize,
            usize,
            *const u32,
            profsubd_status,
            &str,
        ); 7] = [
            (
                ev,
                z.as_ptr(),
                0,
                9,
                f,
                PROFSUBD_ERROR_INVALID_ARGUMENT,
                "width (dim) must be at least 1",
            ),
            (
                ev,
                z.as_ptr(),
                1,
                8,
                f,
                PROFSUBD_ERROR_INVALID_ARGUMENT,
                "num_vertices is 8; the mesh has 9",
            ),
            (
                ev,
                z.as_ptr(),
                usize::MAX,
                9,
                f,
                PROFSUBD_ERROR_INVALID_ARGUMENT,
                "absurdly large",
            ),
            (
                ev,
                nan.as_ptr(),
                1,
                9,
                f,
                PROFSUBD_ERROR_INVALID_ARGUMENT,
                "primvar value 4 (vertex 4, component 0) is not finite",
            ),
            (
                ev,
                z.as_ptr(),
                1,
                9,
                hole.as_ptr(),
                PROFSUBD_ERROR_INVALID_ARGUMENT,
                "point 0: face 1 is a hole",
            ),
            (ev, null(), 1, 9, f, PROFSUBD_ERROR_NULL_ARGUMENT, "data"),
            (
                null(),
                z.as_ptr(),
                1,
                9,
                f,
                PROFSUBD_ERROR_NULL_ARGUMENT,
                "evaluator",
            ),
        ];
        for (e, data, dim, nv, fc, status, message) in cases {
            let mut out = [-7.0; 5];
            let mut out_du = [-7.0; 5];
            let st = profsubd_evaluator_evaluate_primvar(
                e,
                data,
                dim,
                nv,
                fc,
                us,
                vs,
                5,
                out.as_mut_ptr(),
                out_du.as_mut_ptr(),
                null_mut(),
            );
            assert_eq!(st, status, "{message}: {}", last_error());
            assert!(last_error().contains(message), "{}", last_error());
            assert!(
                out.iter().chain(&out_du).all(|&x| x == -7.0),
                "{message}: written on error"
            );
        }
        let st = profsubd_evaluator_evaluate_primvar(
            ev,
            z.as_ptr(),
            1,
            9,
            f,
            us,
            vs,
            5,
            null_mut(),
            null_mut(),
            null_mut(),
        );
        assert_eq!(st, PROFSUBD_ERROR_NULL_ARGUMENT);
        assert!(last_error().contains("values"), "{}", last_error());
        profsubd_evaluator_free(ev);
    }
}
