//! `profsubd offset` prints exactly the Rust API's offset (on all cores), and `profsubd
//! offset` / `profsubd shell` refuse bad input with a message and write nothing.

#[path = "support/cli.rs"]
mod cli;

use std::path::{Path, PathBuf};

use cli::{assert_refused, example_file, numbers, profsubd, stderr, write_input};
use profsubd::construct::shell::{OffsetSettings, OffsetSurface};
use profsubd::eval::Domain;
use profsubd::io::obj::read_obj_file;

fn vase() -> PathBuf {
    example_file("profiles", "vase", "obj")
}

/// Three quads on one edge.
const NON_MANIFOLD: &str = "v 0 0 0\nv 0 1 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 1 0\n\
                            v 0 0 1\nv 0 1 1\nf 1 3 4 2\nf 2 6 5 1\nf 1 7 8 2\n";

#[test]
fn offset_prints_the_rust_offset_to_the_bit() {
    let dir = tempfile::tempdir().unwrap();
    let mesh = read_obj_file(&vase()).unwrap().mesh;
    let n = mesh.num_faces() as u32;
    let points: Vec<(u32, f64, f64)> = (0..2000u32)
        .map(|i| {
            let t = f64::from(i);
            (
                (i * 7919) % n,
                (t * 0.618_033_988_75).fract(),
                (t * 0.414_213_562_37).fract(),
            )
        })
        .collect();
    let text: String = points
        .iter()
        .map(|(f, u, v)| format!("{f} {u} {v}\n"))
        .collect();
    let pts = write_input(dir.path(), "pts.txt", &text);
    let c = 0.01 * mesh.bounding_box_diagonal();
    let o = profsubd(&[
        "offset",
        vase().to_str().unwrap(),
        "--thickness",
        &c.to_string(),
        "--at",
        pts.to_str().unwrap(),
        "--derivs",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let offset =
        OffsetSurface::new(&mesh, &mesh.options().resolve(), OffsetSettings::new(c)).unwrap();
    let faces: Vec<u32> = points.iter().map(|p| p.0).collect();
    let u: Vec<f64> = points.iter().map(|p| p.1).collect();
    let v: Vec<f64> = points.iter().map(|p| p.2).collect();
    let want = offset
        .evaluate_points(Domain::Ptex, &faces, &u, &v)
        .unwrap();
    let got = numbers(&o);
    assert_eq!(got.len(), want.len());
    for (g, w) in got.iter().zip(&want) {
        let w = w.unwrap().offset();
        let w: Vec<f64> = [w.position, w.du, w.dv]
            .iter()
            .flat_map(|d| d.to_array())
            .collect();
        assert_eq!(g, &w);
    }
}

#[test]
fn bad_input_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let bad_mesh = write_input(dir.path(), "book.obj", NON_MANIFOLD);
    let pts = write_input(dir.path(), "pts.txt", "0 0.5 0.5\n");
    let (obj, stl) = (dir.path().join("out.obj"), dir.path().join("out.stl"));
    let cases: [(&Path, &str, &str); 3] = [
        (&bad_mesh, "0.1", "manifold"),
        (&vase(), "-1", "thickness"),
        (&vase(), "NaN", "thickness"),
    ];
    for (mesh, c, says) in cases {
        let o = profsubd(&[
            "shell",
            mesh.to_str().unwrap(),
            "--thickness",
            c,
            "-o",
            obj.to_str().unwrap(),
            "--stl",
            stl.to_str().unwrap(),
        ]);
        assert_refused(&o, says, &[&obj, &stl], &format!("shell {c}"));
        let o = profsubd(&[
            "offset",
            mesh.to_str().unwrap(),
            "--thickness",
            c,
            "--at",
            pts.to_str().unwrap(),
        ]);
        assert_refused(&o, says, &[], &format!("offset {c}"));
    }
}
