//! `profsubd blend`: a junction from JSON to a fitted OBJ and its data points, `--gbs-level`,
//! and bad input refused with a message and nothing written.

#[path = "support/cli.rs"]
mod cli;

use cli::{assert_refused, example_file, profsubd, stdout, write_input};

#[test]
fn writes_the_mesh_and_reports_the_surface_distance() {
    let dir = tempfile::tempdir().unwrap();
    let input = example_file("blends", "tee", "json");
    let (obj, targets) = (dir.path().join("t.obj"), dir.path().join("t.txt"));
    let out = profsubd(&[
        "blend",
        input.to_str().unwrap(),
        "-o",
        obj.to_str().unwrap(),
        "--targets",
        targets.to_str().unwrap(),
        "--gbs-level",
        "2",
    ]);
    assert!(out.status.success(), "{out:?}");
    let text = stdout(&out);
    assert!(
        text.contains("distance between the GBS and Catmull-Clark limit surfaces"),
        "{text}"
    );
    let mesh = profsubd::io::obj::read_obj_file(&obj).unwrap().mesh;
    // Level 2 has 16 quads per level-0 quad (and per N-gon side): 4 × level 1's.
    let level1 = profsubd::io::obj::read_obj_file(&example_file("blends", "tee", "obj"))
        .unwrap()
        .mesh;
    assert_eq!(mesh.num_faces(), 4 * level1.num_faces());
    let lines = std::fs::read_to_string(&targets).unwrap().lines().count();
    assert_eq!(lines, mesh.num_vertices());
}

/// The valences the CLI reports, as (valence, count) pairs of the GBS control mesh and of
/// the Catmull–Clark result.
fn reported_valences(stdout: &str) -> [Vec<(usize, usize)>; 2] {
    let line = stdout
        .lines()
        .find_map(|l| l.strip_prefix("valences: GBS control mesh "))
        .unwrap_or_else(|| panic!("no valence line in {stdout}"));
    let (gbs, cc) = line.split_once("; Catmull-Clark result ").unwrap();
    let cc = cc.split(" (").next().unwrap();
    let parse = |s: &str| {
        s.split(", ")
            .map(|p| {
                let (v, n) = p.split_once(" x ").unwrap();
                (v.parse().unwrap(), n.parse().unwrap())
            })
            .collect()
    };
    [parse(gbs), parse(cc)]
}

#[test]
fn reports_valences_and_none_is_the_pipe_count() {
    let dir = tempfile::tempdir().unwrap();
    for (name, pipes) in [("six_way", 6), ("six_way_k3_cos", 6), ("tee", 3)] {
        let input = example_file("blends", name, "json");
        let obj = dir.path().join(format!("{name}.obj"));
        let out = profsubd(&[
            "blend",
            input.to_str().unwrap(),
            "-o",
            obj.to_str().unwrap(),
        ]);
        assert!(out.status.success(), "{out:?}");
        let text = stdout(&out);
        let mesh = profsubd::io::obj::read_obj_file(&obj).unwrap().mesh;
        let [gbs, cc] = reported_valences(&text);
        let total: usize = cc.iter().map(|&(_, n)| n).sum();
        assert_eq!(total, mesh.num_vertices(), "{name}: {text}");
        for (what, list) in [("GBS", &gbs), ("Catmull-Clark", &cc)] {
            let most = list.iter().map(|&(v, _)| v).max().unwrap();
            // Valences do not grow with N: at most 5 (ring corners), so no vertex of
            // valence N for N ≥ 6.
            assert!(
                most <= 5 && (pipes < 6 || most < pipes),
                "{name} {what}: {list:?}"
            );
        }
    }
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
        (
            r#"{"pipes": [{"end": [2,0,0], "axis": [1,0,0], "radius": 1, "length": 4}]}"#,
            "3 to 8 pipes",
        ),
    ];
    // Three good pipes with one key of one pipe (or the blend) replaced.
    let three = |pipe: usize, key: &str, value: &str, extra: &str| {
        let mut pipes = [
            ("[2,0,0]", "[1,0,0]", "1", "4"),
            ("[-2,0,0]", "[-1,0,0]", "1", "4"),
            ("[0,2,0]", "[0,1,0]", "1", "4"),
        ];
        match key {
            "end" => pipes[pipe].0 = value,
            "axis" => pipes[pipe].1 = value,
            "radius" => pipes[pipe].2 = value,
            _ => {}
        }
        let list: Vec<String> = pipes
            .iter()
            .map(|(e, a, r, l)| {
                format!(r#"{{"end": {e}, "axis": {a}, "radius": {r}, "length": {l}}}"#)
            })
            .collect();
        format!(r#"{{"pipes": [{}]{extra}}}"#, list.join(", "))
    };
    let more = [
        (
            three(2, "end", "[0.5,2,0]", "").replace("[0,1,0]", "[1,0,0]"),
            "parallel",
        ),
        (
            three(2, "end", "[2,0,0]", "").replace("[0,1,0]", "[1,1,0]"),
            "coincident",
        ),
        (three(2, "radius", "0", ""), "radius"),
        (three(0, "", "", r#", "order": 9"#), "order 9"),
        (three(0, "", "", r#", "order": 2"#), "order 2"),
        (three(0, "", "", r#", "tension": -1"#), "tension"),
        (
            three(2, "end", "[2,1.5,0]", "").replace("[0,1,0]", "[1,0.2,0]"),
            "intersect before the junction",
        ),
    ];
    let cases: Vec<(String, &str)> = cases
        .iter()
        .map(|(j, m)| (j.to_string(), *m))
        .chain(more)
        .collect();
    for (i, (json, message)) in cases.iter().enumerate() {
        let input = write_input(dir.path(), &format!("{i}.json"), json);
        let obj = dir.path().join(format!("{i}.obj"));
        let out = profsubd(&[
            "blend",
            input.to_str().unwrap(),
            "-o",
            obj.to_str().unwrap(),
        ]);
        assert_refused(&out, message, &[&obj], &i.to_string());
    }
}
