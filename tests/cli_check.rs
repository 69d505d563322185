//! The `profsubd` binary on real files: exact output, exit codes, error messages.

#[path = "support/osd_shapes.rs"]
mod osd_shapes;

#[path = "support/cli.rs"]
mod cli;

use cli::{example_file, profsubd, stderr, stdout, write_input};
use profsubd::mesh::HazardKind;

#[test]
fn convert_overrides_the_option_tags_and_keeps_the_rest() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("cube.obj");
    let input = example_file("meshes", "cube_creased", "obj");
    let o = profsubd(&[
        "convert",
        input.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--boundary",
        "edge-only",
        "--crease",
        "chaikin",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(
        stdout(&o),
        format!(
            "wrote {} (8 vertices, 6 faces, 5 creases, 1 corners, 0 holes)\n",
            out.display()
        )
    );
    assert_eq!(stderr(&o), "");
    let text = std::fs::read_to_string(&out).unwrap();
    let tags: Vec<&str> = text.lines().filter(|l| l.starts_with("t ")).collect();
    assert_eq!(
        tags,
        [
            "t interpolateboundary 1/0/0 2",
            "t creasemethod 0/0/1 chaikin",
            "t crease 2/1/0 4 5 2",
            "t crease 2/1/0 5 6 2",
            "t crease 2/1/0 6 7 2",
            "t crease 2/1/0 7 4 2",
            "t crease 2/1/0 1 5 10",
            "t corner 1/1/0 2 3",
        ]
    );
    let faces: Vec<&str> = text.lines().filter(|l| l.starts_with("f ")).collect();
    assert_eq!(faces[0], "f 1 4 3 2");
    assert_eq!(faces.len(), 6);
}

#[test]
fn convert_reports_a_missing_input_and_a_bad_flag() {
    let o = profsubd(&["convert", "/nonexistent/in.obj", "-o", "/tmp/never.obj"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(
        stderr(&o),
        "profsubd: error: /nonexistent/in.obj: No such file or directory (os error 2)\n"
    );
    let input = example_file("meshes", "cube_creased", "obj");
    let o = profsubd(&[
        "convert",
        input.to_str().unwrap(),
        "-o",
        "/tmp/never.obj",
        "--boundary",
        "sometimes",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("invalid value 'sometimes' for '--boundary <RULE>'"));
}

#[test]
fn help_lists_the_subcommands_and_exit_codes() {
    let o = profsubd(&["--help"]);
    assert_eq!(o.status.code(), Some(0));
    let text = stdout(&o);
    assert!(text.contains("convert"), "{text}");
    assert!(text.contains("Exit codes: 0 success, 1 error"), "{text}");
}

#[test]
fn convert_reports_ignored_tags_on_stderr() {
    let dir = tempfile::tempdir().unwrap();
    let input = write_input(
        dir.path(),
        "in.obj",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nt vertexedit 1/0/0 0\n",
    );
    let out = dir.path().join("out.obj");
    let o = profsubd(&[
        "convert",
        input.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        stderr(&o),
        format!(
            "profsubd: warning: {}:5: ignored hierarchical edit `vertexedit` \
             (not supported by OpenSubdiv 3 either)\n",
            input.display()
        )
    );
    let written = std::fs::read_to_string(&out).unwrap();
    assert!(written.ends_with("v 1 1 0\nf 1 2 3\n"), "{written}");
}

#[test]
fn check_accepts_the_bundled_example() {
    let input = example_file("meshes", "cube_creased", "obj");
    let o = profsubd(&["check", input.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stderr(&o), "");
    let expected = format!(
        "mesh: {}\n\
         vertices: 8\n\
         edges: 12\n\
         faces: 6 (sizes 4:6)\n\
         valences: 3:8\n\
         boundary: closed\n\
         components: 1\n\
         euler characteristic: 2\n\
         non-manifold edges: 0\n\
         inconsistently oriented edges: 0\n\
         non-manifold vertices: 0\n\
         isolated vertices: 0\n\
         faces with repeated vertices: 0\n\
         creases: 5 (sharpness 2 to 10, 1 infinitely sharp)\n\
         corners: 1 (sharpness 3 to 3, 0 infinitely sharp)\n\
         holes: 0\n\
         boundary interpolation: edge-and-corner (file tag)\n\
         crease method: uniform (default)\n\
         triangles: catmark (default)\n\
         opensubdiv 3.5 hazards: 2\n\
         hazard dart: vertices 2 [1 5], faces 4 [0 1 2 3] (Bfr, Far::PatchTable, Osd): {}\n\
         hazard primvar_limit: vertices 6 [1 2 4 5 6 7] (Far::PrimvarRefiner::Limit): {}\n\
         result: manifold mesh\n",
        input.display(),
        HazardKind::Dart.figure(),
        HazardKind::PrimvarLimit.figure(),
    );
    assert_eq!(stdout(&o), expected);
}

#[test]
fn check_exits_2_on_a_mesh_that_loads_but_is_not_a_manifold() {
    let dir = tempfile::tempdir().unwrap();
    // Three triangles on edge 0-1 (a fin), a flipped quad next to the first triangle
    // and a vertex in no face; a hole on the quad.
    let input = write_input(
        dir.path(),
        "fin.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 9 9 9\nv -1 1 0\nv -1 0 0\n\
         f 1 2 3\nf 2 1 4\nf 1 2 5\nf 3 1 8 7\n\
         t crease 2/1/0 0 1 1.5\nt crease 2/1/0 0 2 10\nt hole 1/0/0 3\n",
    );
    let o = profsubd(&["check", input.to_str().unwrap(), "--crease", "chaikin"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let expected = format!(
        "mesh: {}\n\
         vertices: 8\n\
         edges: 10\n\
         faces: 4 (sizes 3:3 4:1)\n\
         valences: 0:1 2:4 3:1 4:1 5:1\n\
         boundary: 8 edges in 1 loop [1-2 0-3 3-1 1-4 4-0 0-7 7-6 6-2]\n\
         components: 1\n\
         euler characteristic: 2\n\
         non-manifold edges: 1 [0-1]\n\
         inconsistently oriented edges: 1 [2-0]\n\
         non-manifold vertices: 4 [0 1 2 5]\n\
         isolated vertices: 1 [5]\n\
         faces with repeated vertices: 0\n\
         creases: 2 (sharpness 1.5 to 10, 1 infinitely sharp)\n\
         corners: 0\n\
         holes: 1 [3]\n\
         boundary interpolation: edge-and-corner (default)\n\
         crease method: chaikin (command line)\n\
         triangles: catmark (default)\n\
         opensubdiv 3.5 hazards: 0\n\
         result: not a manifold (1 non-manifold edges, 1 inconsistently oriented edges, \
         4 non-manifold vertices, 1 isolated vertices)\n",
        input.display()
    );
    assert_eq!(stdout(&o), expected);

    let o = profsubd(&["check", "--json", input.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let json: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let expected = serde_json::json!({
        "mesh": input.display().to_string(),
        "num_vertices": 8, "num_edges": 10, "num_faces": 4,
        "face_sizes": {"3": 3, "4": 1},
        "valences": {"0": 1, "2": 4, "3": 1, "4": 1, "5": 1},
        "boundary_edges": [[1, 2], [0, 3], [3, 1], [1, 4], [4, 0], [0, 7], [7, 6], [6, 2]],
        "num_boundary_loops": 1,
        "non_manifold_edges": [[0, 1]],
        "inconsistent_edges": [[2, 0]],
        "non_manifold_vertices": [0, 1, 2, 5],
        "isolated_vertices": [5],
        "faces_with_repeated_vertices": [],
        "num_components": 1,
        "euler_characteristic": 2,
        "is_manifold": false, "is_closed": false, "is_consistently_oriented": false,
        "creases": [{"vertices": [0, 1], "sharpness": 1.5}, {"vertices": [0, 2], "sharpness": 10.0}],
        "corners": [],
        "holes": [3],
        "options": {
            "boundary_interpolation": {"value": "edge-and-corner", "source": "default"},
            "crease_method": {"value": "uniform", "source": "default"},
            "triangles": {"value": "catmark", "source": "default"},
        },
        "osd_hazards": [],
    });
    assert_eq!(json, expected);
}

#[test]
fn check_exits_1_with_the_reason_on_an_invalid_file() {
    let dir = tempfile::tempdir().unwrap();
    let input = write_input(
        dir.path(),
        "bad.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt crease 2/1/0 0 1\n",
    );
    let o = profsubd(&["check", input.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(stdout(&o), "");
    assert_eq!(
        stderr(&o),
        format!(
            "profsubd: error: {}:5: tag `crease` announces 2/1/0 arguments but has 2 values\n",
            input.display()
        )
    );
    write_input(
        dir.path(),
        "bad.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt crease 2/1/0 0 1 -1\n",
    );
    let o = profsubd(&["check", input.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        stderr(&o),
        format!(
            "profsubd: warning: {}:5: negative sharpness -1 in tag `crease` clamped to 0\n",
            input.display()
        )
    );
    assert!(stdout(&o).contains("creases: 1 (sharpness 0 to 0, 0 infinitely sharp)\n"));
}

#[test]
fn check_exit_codes_on_the_osd_shapes_flag_exactly_the_non_manifold_ones() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let mut flagged = Vec::new();
    for row in osd_shapes::index(&dir) {
        let o = profsubd(&["check", row.path.to_str().unwrap()]);
        match o.status.code() {
            Some(0) => assert!(stdout(&o).ends_with("result: manifold mesh\n")),
            Some(2) => flagged.push(row.name.clone()),
            other => panic!("{}: exit {other:?}: {}", row.name, stderr(&o)),
        }
        let counts = format!("vertices: {}\n", row.verts);
        assert!(stdout(&o).contains(&counts), "{}", row.name);
    }
    assert_eq!(
        flagged,
        [
            "catmark_fan",
            "catmark_gregory_test4",
            "catmark_nonman_bareverts",
            "catmark_nonman_edge100",
            "catmark_nonman_edges",
            "catmark_nonman_quadpole360",
            "catmark_nonman_quadpole64",
            "catmark_nonman_quadpole8",
            "catmark_nonman_verts",
            "catmark_val2_nonman",
        ]
    );
}
