//! The bundled sweep examples (`examples/sweeps/`): each regenerates to its checked-in OBJ,
//! and its data points to the checked-in `.targets.txt`, has the promised topology and crease
//! structure, and the CLI writes the same mesh plus one
//! target line per vertex; bad input writes nothing.

#[path = "support/cli.rs"]
mod cli;
#[path = "support/mesh_compare.rs"]
mod mesh_compare;
#[allow(dead_code)]
#[path = "support/swept.rs"]
mod swept;

use std::path::PathBuf;

use cli::{assert_refused, example_file, profsubd, stderr, write_input};
use mesh_compare::{assert_same, assert_targets};
use profsubd::construct::settings::read_json;
use profsubd::io::obj::read_obj_file;
use profsubd::mesh::validate::check;
use profsubd::RevolveInput;
use profsubd::SweepInput;
use profsubd::{revolve, sweep, Fitted};
use swept::crease_degrees;

fn example(name: &str, ext: &str) -> PathBuf {
    example_file("sweeps", name, ext)
}

fn build(name: &str) -> Fitted {
    let path = example(name, "json");
    if name.starts_with("wine_glass") || name == "vase_cutaway" {
        let (input, settings) = read_json::<RevolveInput>(&path).unwrap();
        revolve::build(&input, &settings).unwrap()
    } else {
        let (input, settings) = read_json::<SweepInput>(&path).unwrap();
        sweep::build(&input, &settings).unwrap()
    }
}

#[test]
fn examples_regenerate_with_their_topology() {
    for name in [
        "wine_glass",
        "torus_knot_tube",
        "handrail",
        "wine_glass_cutaway",
        "vase_cutaway",
    ] {
        let s = build(name);
        let stored = read_obj_file(&example(name, "obj")).unwrap().mesh;
        assert_same(&s.mesh, &stored, name);
        // The checked-in data points (what the C++ harness compares OpenSubdiv's limit with).
        let tol = 1e-9 * s.mesh.bounding_box_diagonal();
        assert_targets(&example(name, "targets.txt"), &s.targets, tol, name);
        assert!(s.fit.residual <= 1e-10 * s.mesh.bounding_box_diagonal());
        assert!(s.mesh.face_sizes().iter().all(|&n| n == 4));
        let r = check(&s.mesh);
        assert!(r.is_manifold() && r.is_consistently_oriented(), "{name}");
        match name {
            // A closed glass (outer wall, rim, inner bowl) with smooth poles at the foot and
            // at the bottom of the bowl: a sphere; 32 meridians, creases on whole rings.
            "wine_glass" => {
                assert!(r.is_closed());
                assert_eq!(r.euler_characteristic, 2);
                assert_eq!(r.valences.keys().copied().collect::<Vec<_>>(), vec![3, 4]);
                assert_eq!(s.mesh.creases().len() % 32, 0);
                assert_eq!(crease_degrees(&s), vec![0, s.mesh.creases().len(), 0, 0]);
            }
            // A closed tube: a torus, all regular, no creases.
            "torus_knot_tube" => {
                assert!(r.is_closed());
                assert_eq!(r.euler_characteristic, 0);
                assert_eq!(r.valences.keys().copied().collect::<Vec<_>>(), vec![4]);
                assert!(s.mesh.creases().is_empty());
            }
            // An open square tube: 4 crease lines along it (49 rings) and 2 crease rings of 8
            // edges at the two trajectory corners; where they cross, 4 crease edges meet.
            "handrail" => {
                assert_eq!(r.num_boundary_loops, 2);
                assert_eq!(s.mesh.creases().len(), 4 * 48 + 2 * 8);
                assert_eq!(crease_degrees(&s)[3], 8);
            }
            // 270° cutaways closed by flat caps (sectors at ends off the axis, both meridian
            // planes); the glass's ends are smooth poles on the meridians. Creases meet three
            // or four at a time at corner-tagged vertices only (no crease ends, no darts):
            // the apexes, the meridian ends of the crease rings and of the flat ends' arcs,
            // and where a flat sector's bisector or a meridian cap's row from a reflex
            // corner (creased across the cap) meets the arc or the axis.
            "wine_glass_cutaway" | "vase_cutaway" => {
                assert!(r.is_closed());
                assert_eq!(r.euler_characteristic, 2);
                assert!(r.valences.keys().all(|v| (3..=5).contains(v)), "{name}");
                let degrees = crease_degrees(&s);
                assert_eq!(degrees[0], 0, "{name}");
                // Four creases: glass 2 × 3 reflex corners (foot top, stem foot, bowl foot),
                // the 3 axis vertices their rows reach, the 2 apexes (with the bisector,
                // creased from pole to pole along the middle meridian) and the 6 crease
                // rings' vertices on that meridian; vase 2 apexes (with the bisector),
                // 2 × 1 reflex corner (the neck) and 1 axis vertex.
                let four = if name == "vase_cutaway" { 5 } else { 17 };
                assert_eq!(degrees[3], four, "{name}");
                assert_eq!(s.mesh.corners().len(), degrees[2] + four, "{name}");
                // Glass: 6 crease rings (foot edge, foot top, stem ×2, bowl, rim) at both
                // meridians and the middle one, 2 poles, 3 axis vertices; vase: 2 flat ends
                // (apex, 2 arc ends and the bisector's end each), 3 crease rings, 1 axis
                // vertex.
                let expect = if name == "vase_cutaway" { 15 } else { 23 };
                assert_eq!(s.mesh.corners().len(), expect, "{name}");
            }
            _ => unreachable!(),
        }
    }
}

#[test]
fn cli_writes_the_mesh_and_targets_and_nothing_on_error() {
    let dir = tempfile::tempdir().unwrap();
    for (cmd, name) in [("revolve", "wine_glass"), ("sweep", "handrail")] {
        let obj = dir.path().join(format!("{name}.obj"));
        let targets = dir.path().join(format!("{name}.txt"));
        let out = profsubd(&[
            cmd,
            example(name, "json").to_str().unwrap(),
            "-o",
            obj.to_str().unwrap(),
            "--targets",
            targets.to_str().unwrap(),
        ]);
        assert!(out.status.success(), "{}", stderr(&out));
        let s = build(name);
        assert_same(&read_obj_file(&obj).unwrap().mesh, &s.mesh, name);
        let lines: Vec<String> = std::fs::read_to_string(&targets)
            .unwrap()
            .lines()
            .map(String::from)
            .collect();
        assert_eq!(lines.len(), s.mesh.num_vertices());
        let first: Vec<f64> = lines[0].split(' ').map(|x| x.parse().unwrap()).collect();
        assert_eq!(first, vec![s.targets[0].x, s.targets[0].y, s.targets[0].z]);
    }
    // Bad input: the message names the culprit, exit code 1, no file written.
    let obj = dir.path().join("bad.obj");
    for (cmd, json, expect) in [
        (
            "revolve",
            r#"{"profile": [[1, 0], [-1, 1]]}"#,
            "crosses the axis",
        ),
        (
            "revolve",
            r#"{"profile": [[0, -1], [1, 0], [0, 1]], "caps": "flat"}"#,
            "nothing to cap",
        ),
        (
            "revolve",
            r#"{"profile": [[1, 0], [1, 1]], "angle_deg": 90, "caps": "round"}"#,
            "unknown variant `round`",
        ),
        (
            "revolve",
            r#"{"profile": [[1, 0], [1, 1]], "angle_deg": 0}"#,
            "(0, 360]",
        ),
        (
            "sweep",
            r#"{"profile": [[0, 0], [1, 0]], "trajectory": [[0, 0, 0], [0, 0, 0]]}"#,
            "coincide",
        ),
        (
            "sweep",
            r#"{"profile": [[0, 0], [1, 0]], "trajectory": [[0, 0, 0], [0, 0, 1]], "frame": "frenet"}"#,
            "undefined everywhere",
        ),
        (
            "sweep",
            r#"{"profile": [[0,0],[1,1],[1,0],[0,1]], "closed_profile": true, "trajectory": [[0,0,0],[0,0,1]]}"#,
            "crosses itself",
        ),
        (
            "sweep",
            r#"{"profile": [[0, 0], [1, 0]], "trajectory": [[0, 0, 0], [0, 0, 1]], "twist": 1}"#,
            "unknown field `twist`",
        ),
    ] {
        let bad = write_input(dir.path(), "bad.json", json);
        let out = profsubd(&[cmd, bad.to_str().unwrap(), "-o", obj.to_str().unwrap()]);
        assert_refused(&out, expect, &[&obj], &format!("{cmd} {json}"));
    }
}
