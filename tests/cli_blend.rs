//! `profsubd blend`: a junction from JSON to a fitted OBJ and its data points, `--gbs-level`,
//! and bad input refused with a message and nothing written.

use std::process::Command;

fn blend(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_profsubd"))
        .arg("blend")
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn writes_the_mesh_and_reports_the_surface_distance() {
    let dir = tempfile::tempdir().unwrap();
    let input = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/blends/tee.json");
    let (obj, targets) = (dir.path().join("t.obj"), dir.path().join("t.txt"));
    let out = blend(&[
        input,
        "-o",
        obj.to_str().unwrap(),
        "--targets",
        targets.to_str().unwrap(),
        "--gbs-level",
        "2",
    ]);
    assert!(out.status.success(), "{out:?}");
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(
        stdout.contains("distance between the GBS and Catmull-Clark limit surfaces"),
        "{stdout}"
    );
    let mesh = profsubd::io::obj::read_obj_file(&obj).unwrap().mesh;
    // Level 2 has 16 quads per level-0 quad (and per N-gon side): 4 × level 1's.
    let level1 =
        profsubd::io::obj::read_obj_file(std::path::Path::new(&input.replace(".json", ".obj")))
            .unwrap()
            .mesh;
    assert_eq!(mesh.num_faces(), 4 * level1.num_faces());
    let lines = std::fs::read_to_string(&targets).unwrap().lines().count();
    assert_eq!(lines, mesh.num_vertices());
}

#[test]
fn bad_input_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            r#"{"pipes": [{"end": [2,0,0], "axis": [1,0,0], "radius": 1, "length": 4},
                       {"end": [-2,0,0], "axis": [-1,0,0], "radius": 1, "length": 4}]}"#,
            "3 to 8 pipes",
        ),
        (
            r#"{"pipes": [{"end": [2,0,0], "axis": [1,0,0], "radius": 1, "length": 4},
                       {"end": [-2,0,0], "axis": [-1,0,0], "radius": 1, "length": 4},
                       {"end": [0,2,0], "axis": [0,1,0], "radius": -1, "length": 4}]}"#,
            "radius",
        ),
        (r#"{"pipes": [], "order": 4}"#, "3 to 8 pipes"),
        (
            r#"{"pipes": [{"end": [2,0,0], "axis": [1,0,0], "radius": 1, "length": 4},
                       {"end": [-2,0,0], "axis": [-1,0,0], "radius": 1, "length": 4},
                       {"end": [0,2,0], "axis": [0,1,0], "radius": 1, "length": 4}], "order": 5,
                "gbs_level": 3}"#,
            "gbs_level 3 is outside 1..=2 for order 5",
        ),
        (r#"{"pipes": [], "colour": 1}"#, "colour"),
    ];
    for (i, (json, message)) in cases.iter().enumerate() {
        let input = dir.path().join(format!("{i}.json"));
        std::fs::write(&input, json).unwrap();
        let obj = dir.path().join(format!("{i}.obj"));
        let out = blend(&[input.to_str().unwrap(), "-o", obj.to_str().unwrap()]);
        assert!(!out.status.success());
        let stderr = String::from_utf8(out.stderr).unwrap();
        assert!(stderr.contains(message), "{i}: {stderr}");
        assert!(!obj.exists(), "{i}");
    }
}
