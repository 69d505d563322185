//! `profsubd limit` prints exactly the numbers of the C API and the Rust API, in both modes,
//! and rejects bad input with a clear message.

#[path = "support/cli.rs"]
mod cli;

use std::path::PathBuf;
use std::ptr::null_mut;

use cli::{assert_refused, example_file, numbers, profsubd, stderr, stdout, write_input};

use profsubd::eval::{limit_vertex_samples, Evaluator};
use profsubd::ffi::evaluator::{
    profsubd_evaluator_evaluate, profsubd_evaluator_free, profsubd_evaluator_new,
};
use profsubd::ffi::mesh::profsubd_mesh_free;
use profsubd::ffi::mesh_io::profsubd_mesh_read_obj;
use profsubd::ffi::status::profsubd_status;
use profsubd::io::obj::read_obj_file;

fn example() -> PathBuf {
    example_file("meshes", "cube_creased", "obj")
}

#[test]
fn vertex_mode_prints_the_vertex_limits() {
    let path = example();
    let o = profsubd(&["limit", path.to_str().unwrap(), "--derivs"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mesh = read_obj_file(&path).unwrap().mesh;
    let want = limit_vertex_samples(&mesh, &mesh.options().resolve()).unwrap();
    let got = numbers(&o);
    assert_eq!(got.len(), mesh.num_vertices());
    for (g, w) in got.iter().zip(&want) {
        let w: Vec<f64> = [w.position, w.du, w.dv]
            .iter()
            .flat_map(|d| d.to_array())
            .collect();
        assert_eq!(g, &w);
    }
    let o = profsubd(&["limit", path.to_str().unwrap()]);
    assert!(numbers(&o).iter().all(|l| l.len() == 3));
}

#[test]
fn point_mode_prints_what_the_c_api_returns() {
    let dir = tempfile::tempdir().unwrap();
    let points: Vec<(u32, f64, f64)> = (0..60)
        .map(|i| {
            let t = f64::from(i);
            (
                i % 6,
                (t * 0.618_033_988_75).fract(),
                (t * 0.414_213_562_37).fract(),
            )
        })
        .chain([(0, 0.0, 0.0), (5, 1.0, 1.0), (3, 0.5, 1.0)])
        .collect();
    let text: String = points
        .iter()
        .map(|(f, u, v)| format!("{f} {u} {v}\n"))
        .collect();
    let pts = write_input(dir.path(), "pts.txt", &format!("# face u v\n{text}"));
    let path = example();
    let args = [
        "limit",
        path.to_str().unwrap(),
        "--at",
        pts.to_str().unwrap(),
        "--derivs",
        "--crease",
        "chaikin",
    ];
    let o = profsubd(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let got = numbers(&o);
    // The thread count changes nothing (the default is all cores).
    for threads in ["1", "3"] {
        let t = profsubd(&[&args[..], &["--threads", threads]].concat());
        assert!(t.status.success(), "{}", stderr(&t));
        assert_eq!(t.stdout, o.stdout, "--threads {threads}");
    }

    let n = points.len();
    let faces: Vec<u32> = points.iter().map(|p| p.0).collect();
    let us: Vec<f64> = points.iter().map(|p| p.1).collect();
    let vs: Vec<f64> = points.iter().map(|p| p.2).collect();
    let (mut p, mut du, mut dv) = (vec![0.0; 3 * n], vec![0.0; 3 * n], vec![0.0; 3 * n]);
    let cpath = std::ffi::CString::new(path.to_str().unwrap()).unwrap();
    unsafe {
        let mut m = null_mut();
        assert_eq!(
            profsubd_mesh_read_obj(cpath.as_ptr(), &mut m),
            profsubd_status::PROFSUBD_OK
        );
        let mut opts = null_mut();
        profsubd::ffi::options::profsubd_options_new(&mut opts);
        profsubd::ffi::options::profsubd_options_set_crease_method(
            opts,
            profsubd::ffi::options::profsubd_crease_method::PROFSUBD_CREASE_CHAIKIN as i32,
        );
        // Built on one thread here, on all cores by the command above.
        assert_eq!(
            profsubd::ffi::options::profsubd_options_set_threads(opts, 1),
            profsubd_status::PROFSUBD_OK
        );
        assert_eq!(
            profsubd::ffi::options::profsubd_options_set_threads(null_mut(), 1),
            profsubd_status::PROFSUBD_ERROR_NULL_ARGUMENT
        );
        let mut ev = null_mut();
        assert_eq!(
            profsubd_evaluator_new(m, opts, &mut ev),
            profsubd_status::PROFSUBD_OK
        );
        let st = profsubd_evaluator_evaluate(
            ev,
            faces.as_ptr(),
            us.as_ptr(),
            vs.as_ptr(),
            n,
            p.as_mut_ptr(),
            du.as_mut_ptr(),
            dv.as_mut_ptr(),
        );
        assert_eq!(st, profsubd_status::PROFSUBD_OK);
        profsubd_evaluator_free(ev);
        profsubd::ffi::options::profsubd_options_free(opts);
        profsubd_mesh_free(m);
    }
    assert_eq!(got.len(), n);
    for i in 0..n {
        let want: Vec<f64> = [&p, &du, &dv]
            .iter()
            .flat_map(|a| a[3 * i..3 * i + 3].to_vec())
            .collect();
        assert_eq!(got[i], want, "point {i}");
    }
    // And the Rust API agrees with both.
    let mesh = read_obj_file(&path).unwrap().mesh;
    let mut options = mesh.options().resolve();
    options.crease_method = profsubd::CreaseMethod::Chaikin;
    let ev = Evaluator::new(&mesh, &options).unwrap();
    assert_eq!(
        ev.evaluate(faces[7], us[7], vs[7])
            .unwrap()
            .position
            .to_array(),
        got[7][..3]
    );
}

#[test]
fn bad_input_is_reported_with_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = example();
    for (text, expect) in [
        (
            "0 0.5 0.5\n6 0.5 0.5\n",
            "pts.txt:2: invalid argument: face 6 is out of range",
        ),
        (
            "0 1.5 0.5\n",
            "pts.txt:1: invalid argument: (u, v) = (1.5, 0.5) on face 0 is outside [0, 1]",
        ),
        ("0 NaN 0.5\n", "outside [0, 1]"),
        ("0 0.5\n", "pts.txt:1: expected `face u v`"),
    ] {
        let pts = write_input(dir.path(), "pts.txt", text);
        let o = profsubd(&[
            "limit",
            path.to_str().unwrap(),
            "--at",
            pts.to_str().unwrap(),
        ]);
        assert_refused(&o, expect, &[], text);
    }
    let o = profsubd(&["limit", "/nonexistent/mesh.obj"]);
    assert_refused(&o, "/nonexistent/mesh.obj", &[], "a missing mesh");
    // A hole face.
    let text = std::fs::read_to_string(&path).unwrap() + "t hole 1/0/0 2\n";
    let holed = write_input(dir.path(), "holed.obj", &text);
    let pts = write_input(dir.path(), "hole.txt", "2 0.5 0.5\n");
    let o = profsubd(&[
        "limit",
        holed.to_str().unwrap(),
        "--at",
        pts.to_str().unwrap(),
    ]);
    // No surface: `nan` for every number, or with --strict an error naming the line.
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stdout(&o), "nan nan nan\n");
    let o = profsubd(&[
        "limit",
        holed.to_str().unwrap(),
        "--at",
        pts.to_str().unwrap(),
        "--strict",
    ]);
    assert_refused(
        &o,
        "hole.txt:1: face 2 has no limit surface (--strict)",
        &[],
        "--strict",
    );
}
