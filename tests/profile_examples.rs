//! The bundled profile examples: each regenerates to its checked-in OBJ (same topology and
//! tags, positions within 1e-9 × diagonal) and targets file (the C++ harness reads both), has the promised topology, and the CLI writes
//! the same mesh plus one target line per vertex; bad input writes nothing.

#[path = "support/cli.rs"]
mod cli;
#[path = "support/mesh_compare.rs"]
mod mesh_compare;

use std::collections::HashMap;
use std::path::PathBuf;

use cli::{assert_refused, example_file, profsubd, stderr, write_input};
use mesh_compare::{assert_same, assert_targets};

use profsubd::construct::settings::read_json;
use profsubd::io::obj::read_obj_file;
use profsubd::profile::{build, build_cage, default_model, EndKind, ProfileInput};
use profsubd::Mesh;

const EXAMPLES: [&str; 4] = ["bottle", "vase", "mouse", "spinning_top"];

fn example(name: &str, ext: &str) -> PathBuf {
    example_file("profiles", name, ext)
}

/// Edge face counts and vertex valences.
fn topology(m: &Mesh) -> (HashMap<(u32, u32), usize>, Vec<usize>) {
    let mut edges = HashMap::new();
    for f in 0..m.num_faces() {
        let face = m.face(f);
        for i in 0..face.len() {
            let (a, b) = (face[i], face[(i + 1) % face.len()]);
            *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
    }
    let mut val = vec![0; m.num_vertices()];
    for &(a, b) in edges.keys() {
        val[a as usize] += 1;
        val[b as usize] += 1;
    }
    (edges, val)
}

#[test]
fn examples_regenerate_to_their_checked_in_obj_files() {
    for name in EXAMPLES {
        let (input, settings) = read_json::<ProfileInput>(&example(name, "json")).unwrap();
        let model = build(&input, &settings).unwrap();
        let ends = build_cage(&input, &settings).unwrap().ends;
        let stored = read_obj_file(&example(name, "obj")).unwrap().mesh;
        assert_same(&model.mesh, &stored, name);
        let tol = 1e-12 * model.mesh.bounding_box_diagonal();
        assert_targets(&example(name, "targets.txt"), &model.targets, tol, name);
        assert!(model.fit.residual <= 1e-10 * model.mesh.bounding_box_diagonal());
        assert!(model.mesh.face_sizes().iter().all(|&n| n == 4));
        let (edges, val) = topology(&model.mesh);
        let tips: Vec<u32> = model.mesh.corners().iter().map(|c| c.vertex).collect();
        for (v, &n) in val.iter().enumerate() {
            let boundary_vertex = edges
                .iter()
                .any(|(&(a, b), &c)| c == 1 && (a as usize == v || b as usize == v));
            if !tips.contains(&(v as u32)) && !boundary_vertex {
                assert!((3..=5).contains(&n), "{name}: vertex {v} has valence {n}");
            }
        }
        let closed = !ends.contains(&EndKind::Open);
        let boundary = edges.values().filter(|&&c| c == 1).count();
        assert!(edges.values().all(|&c| c <= 2), "{name}: non-manifold edge");
        if closed {
            assert_eq!(boundary, 0, "{name}");
            let euler = val.len() as i64 - edges.len() as i64 + model.mesh.num_faces() as i64;
            assert_eq!(euler, 2, "{name}");
        } else {
            assert_eq!(boundary, input.around as usize, "{name}: one open ring");
        }
    }
}

#[test]
fn cli_builds_the_default_bottle_with_targets() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("model.obj");
    let targets = dir.path().join("targets.txt");
    let o = profsubd(&[
        "profile",
        "-o",
        out.to_str().unwrap(),
        "--targets",
        targets.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let written = read_obj_file(&out).unwrap().mesh;
    let stored = read_obj_file(&example("bottle", "obj")).unwrap().mesh;
    assert_same(&written, &stored, "default model");
    let (input, settings) = default_model();
    let model = build(&input, &settings).unwrap();
    let lines: Vec<String> = std::fs::read_to_string(&targets)
        .unwrap()
        .lines()
        .map(String::from)
        .collect();
    assert_eq!(lines.len(), written.num_vertices());
    for (line, t) in lines.iter().zip(&model.targets) {
        let xyz: Vec<f64> = line.split(' ').map(|s| s.parse().unwrap()).collect();
        assert_eq!(xyz, t.to_array().to_vec());
    }
}

#[test]
fn cli_rejects_bad_input_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("model.obj");
    for (json, expect) in [
        (
            r#"{"c1": [[0,0]], "c2": [[0,0],[1,1]]}"#,
            "at least 2 points",
        ),
        (
            r#"{"c1": [[0,0],[1,1],[0,2]], "c2": [[0,0],[1,1],[0,2]], "around": 6}"#,
            "multiple of 4",
        ),
        (
            r#"{"c1": [[0,0],[1,1],[0,2]], "c2": [[0,2],[1,1],[0,0]]}"#,
            "bottom to top",
        ),
        (
            r#"{"c1": [[0,0],[-1,1],[0,2]], "c2": [[0,0],[1,1],[0,2]]}"#,
            "crosses the axis",
        ),
        (
            r#"{"c1": [[0,0],[1,1],[0,2]], "c2": [[0,0],[1,1],[0,2]], "colour": 1}"#,
            "unknown field",
        ),
        (
            r#"{"c1": [[0,0],[1,1],[0,2]], "c2": [[0,0],[1,1],[0,2]], "along": 100000}"#,
            "along",
        ),
    ] {
        let input = write_input(dir.path(), "in.json", json);
        let o = profsubd(&[
            "profile",
            input.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ]);
        assert_refused(&o, expect, &[&out], json);
    }
    let o = profsubd(&[
        "profile",
        "/nonexistent/in.json",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_refused(&o, "/nonexistent/in.json", &[&out], "a missing input");
}
