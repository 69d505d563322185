//! `profsubd refine` on real files: the written mesh equals the library's refinement, tags
//! carry the decayed sharpness, bad input gives a clear error.

#[path = "support/cli.rs"]
mod cli;

use std::path::{Path, PathBuf};
use std::process::Output;

use cli::{assert_refused, example_file, profsubd, stderr};
use profsubd::io::obj::read_obj_file;
use profsubd::refine::{refine_uniform, refine_uniform_ordered, VertexOrder};
use profsubd::{BoundaryInterpolation, SubdivOptions};

fn refine_to(input: &Path, level: &str, out: &Path) -> Output {
    profsubd(&[
        "refine",
        input.to_str().unwrap(),
        "--level",
        level,
        "-o",
        out.to_str().unwrap(),
    ])
}

fn cube() -> PathBuf {
    example_file("meshes", "cube_creased", "obj")
}

#[test]
fn refine_writes_far_ordered_mesh_with_decayed_tags() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("r.obj");
    let input = cube();
    let o = refine_to(&input, "2", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let written = read_obj_file(&out).unwrap().mesh;
    assert_eq!(written.num_vertices(), 98);
    assert_eq!(written.num_faces(), 96);
    // Top creases (2) have decayed to 0; the infinitely sharp edge is 4 edges of 10;
    // the corner of sharpness 3 is now 1.
    assert_eq!(written.creases().len(), 4);
    assert!(written.creases().iter().all(|c| c.sharpness == 10.0));
    assert_eq!(written.corners().len(), 1);
    assert_eq!(written.corners()[0].vertex, 2);
    assert_eq!(written.corners()[0].sharpness, 1.0);
    let base = read_obj_file(&input).unwrap().mesh;
    let lib = refine_uniform(&base, &base.options().resolve(), 2).unwrap();
    assert_eq!(written.positions(), lib.positions());
    assert_eq!(written.face_indices(), lib.face_indices());
    assert_eq!(
        written.options().boundary,
        Some(BoundaryInterpolation::EdgeAndCorner)
    );
    assert_eq!(lib.options().resolve(), SubdivOptions::default());
}

#[test]
fn faces_first_order_under_both_spellings() {
    let dir = tempfile::tempdir().unwrap();
    let input = cube();
    let base = read_obj_file(&input).unwrap().mesh;
    let opts = base.options().resolve();
    let lib = refine_uniform_ordered(&base, &opts, 2, VertexOrder::FacesFirst).unwrap();
    let default = refine_uniform(&base, &opts, 2).unwrap();
    assert_ne!(lib.positions(), default.positions());
    for flag in ["--faces-first", "--face-verts-first"] {
        let out = dir.path().join("r.obj");
        let (i, o) = (input.to_str().unwrap(), out.to_str().unwrap());
        let run = profsubd(&["refine", i, "--level", "2", flag, "-o", o]);
        assert!(run.status.success(), "{flag}: {}", stderr(&run));
        let written = read_obj_file(&out).unwrap().mesh;
        assert_eq!(written.positions(), lib.positions(), "{flag}");
        assert_eq!(written.face_indices(), lib.face_indices(), "{flag}");
    }
}

#[test]
fn refine_rejects_bad_input() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("r.obj");
    let input = cube();
    let o = refine_to(&input, "9", &out);
    assert_refused(&o, "above the maximum 8", &[&out], "level 9");
    let o = refine_to(Path::new("/nonexistent/mesh.obj"), "1", &out);
    assert_refused(&o, "/nonexistent/mesh.obj", &[&out], "a missing mesh");
}

/// `--threads N` splits the positions of each level over N threads (level 6 of the cube:
/// 6144 parent faces, enough for 3 threads) and writes the same bytes as one thread and as
/// the default (all cores), which equal the library's refinement.
#[test]
fn threads_flag_writes_the_same_file() {
    let dir = tempfile::tempdir().unwrap();
    let input = cube();
    let i = input.to_str().unwrap();
    let run = |threads: Option<&str>| {
        let out = dir
            .path()
            .join(format!("r{}.obj", threads.unwrap_or("default")));
        let o = out.to_str().unwrap();
        let mut args = vec!["refine", i, "--level", "6", "-o", o];
        args.extend(threads.map(|t| ["--threads", t]).into_iter().flatten());
        let r = profsubd(&args);
        assert!(r.status.success(), "{threads:?}: {}", stderr(&r));
        std::fs::read(&out).unwrap()
    };
    let one = run(Some("1"));
    assert_eq!(run(Some("3")), one, "3 threads");
    assert_eq!(run(None), one, "all cores");
    let written = read_obj_file(&dir.path().join("r1.obj")).unwrap().mesh;
    let base = read_obj_file(&input).unwrap().mesh;
    let lib = refine_uniform(&base, &base.options().resolve(), 6).unwrap();
    assert_eq!(written.num_faces(), 6 * 4usize.pow(6));
    assert_eq!(written.positions(), lib.positions());
    assert_eq!(written.face_indices(), lib.face_indices());
    let out = dir.path().join("bad.obj");
    let o = out.to_str().unwrap();
    let bad = profsubd(&["refine", i, "--level", "1", "--threads=two", "-o", o]);
    let err = stderr(&bad);
    assert!(!bad.status.success() && err.contains("--threads"), "{err}");
    assert!(!out.exists());
}
