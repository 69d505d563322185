//! `profsubd check --surface` and `eval::folds::find_folds` on real meshes: the folds of the
//! examples as committed before the fold-free constructions (kept in `tests/fixtures/folded/`),
//! none on OpenSubdiv shapes and analytic surfaces that do not fold. The C++ harness
//! (`ctest -R conformance_folds`) finds the same folded faces with OpenSubdiv's Bfr.

#[path = "support/osd_shapes.rs"]
#[allow(dead_code)] // the shape index is not needed here
mod osd_shapes;

#[allow(dead_code)]
#[path = "support/arc.rs"]
mod arc;
#[path = "support/cli.rs"]
mod cli;

use std::f64::consts::{PI, TAU};
use std::path::{Path, PathBuf};
use std::process::Output;

use arc::arc;
use cli::{assert_refused, example_file, profsubd, stdout};
use profsubd::eval::folds::{find_folds, FoldReport, FoldSettings};
use profsubd::eval::Evaluator;
use profsubd::io::obj::read_obj_file;
use profsubd::Mesh;
use profsubd::RevolveInput;
use profsubd::SweepInput;
use profsubd::{revolve, sweep, Settings};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/folded")
        .join(name)
}

fn check_surface(path: &Path) -> (Output, serde_json::Value) {
    let o = profsubd(&["check", "--surface", path.to_str().unwrap(), "--json"]);
    let json = serde_json::from_slice(&o.stdout).expect("JSON report");
    (o, json)
}

fn folded_faces(json: &serde_json::Value) -> Vec<usize> {
    json["surface"]["folded_face_indices"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f.as_u64().unwrap() as usize)
        .collect()
}

fn folds(mesh: &Mesh) -> FoldReport {
    let ev = Evaluator::new(mesh, &mesh.options().resolve()).unwrap();
    find_folds(&ev, &FoldSettings::default()).unwrap()
}

#[test]
fn the_bottle_fixture_folds_in_four_faces_of_its_flat_base() {
    let path = fixture("bottle.obj");
    let (o, json) = check_surface(&path);
    assert_eq!(o.status.code(), Some(3));
    assert_eq!(folded_faces(&json), vec![288, 291, 300, 303]);
    // Reversed in the plane of the base: the normal turns by exactly 180°.
    assert_eq!(json["surface"]["worst_reversal_deg"], 180.0);
    assert!(json["surface"]["min_relative_jacobian"].as_f64().unwrap() < 0.0);
    let mesh = read_obj_file(&path).unwrap().mesh;
    for f in folded_faces(&json) {
        for &v in mesh.face(f) {
            assert_eq!(
                mesh.positions()[v as usize].z,
                0.0,
                "face {f}: not on the base"
            );
        }
    }
    // The human report says the same.
    let text = stdout(&profsubd(&["check", "--surface", path.to_str().unwrap()]));
    assert!(
        text.contains("folded faces: 4 [288 291 300 303]\n"),
        "{text}"
    );
    assert!(text.contains("surface: folds (4 faces)\n"), "{text}");
}

#[test]
fn the_wine_glass_fixture_folds_in_its_foot_and_at_the_bottom_of_its_bowl() {
    let path = fixture("wine_glass.obj");
    let (o, json) = check_surface(&path);
    assert_eq!(o.status.code(), Some(3));
    let faces = folded_faces(&json);
    assert_eq!(faces.len(), 96);
    // All in the two grid caps (the last 128 faces): the flat foot at z = 0, and the smooth
    // pole where the profile ends on the axis inside the bowl, at z = 3.55.
    assert!(
        faces.iter().all(|&f| (1472..1600).contains(&f)),
        "{faces:?}"
    );
    let mesh = read_obj_file(&path).unwrap().mesh;
    let (mut foot, mut bowl) = (0, 0);
    for &f in &faces {
        let z: Vec<f64> = mesh
            .face(f)
            .iter()
            .map(|&v| mesh.positions()[v as usize].z)
            .collect();
        if z.iter().all(|&z| z == 0.0) {
            foot += 1;
        } else if z.iter().all(|&z| (z - 3.55).abs() < 0.01) {
            bowl += 1;
        } else {
            panic!("face {f} at z {z:?}: neither in the foot nor at the bowl's pole");
        }
    }
    assert_eq!((foot, bowl), (48, 48));
    assert_eq!(json["surface"]["worst_reversal_deg"], 180.0);
}

#[test]
fn check_without_surface_or_on_a_fold_free_mesh_keeps_exit_code_0() {
    let cube = example_file("meshes", "cube_creased", "obj");
    let (o, json) = check_surface(&cube);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(json["surface"]["fold_free"], true);
    let plain = profsubd(&["check", fixture("bottle.obj").to_str().unwrap()]);
    assert_eq!(plain.status.code(), Some(0));
    // --samples needs --surface; a bad count is an error (exit 1).
    let bad = profsubd(&[
        "check",
        "--surface",
        "--samples",
        "1",
        cube.to_str().unwrap(),
    ]);
    assert_refused(&bad, "samples per edge 1", &[], "--samples 1");
}

#[test]
fn opensubdiv_shapes_that_do_not_fold_are_fold_free() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    for name in [
        "catmark_cube",
        "catmark_torus",
        "catmark_pawn",
        "catmark_helmet",
        "catmark_bishop",
        "catmark_cube_corner4",
        "catmark_cube_creases2",
        "catmark_pyramid_creases0",
        "catmark_nonquads",
        "catmark_xord_interior",
        "catmark_gregory_test8",
        "catmark_fan",
    ] {
        let mesh = read_obj_file(&dir.join(format!("{name}.obj")))
            .unwrap()
            .mesh;
        let r = folds(&mesh);
        assert!(r.is_fold_free(), "{name}: {:?}", r.folded_faces);
        assert!(
            r.worst_reversal_deg < 90.0,
            "{name}: {}",
            r.worst_reversal_deg
        );
        assert!(
            r.min_relative_jacobian > 0.0,
            "{name}: {}",
            r.min_relative_jacobian
        );
    }
}

#[test]
fn analytic_torus_cylinder_and_cone_do_not_fold() {
    let mut profile = arc(64, 0.5, 0.0, TAU);
    profile.pop();
    let mut trajectory: Vec<[f64; 3]> = arc(96, 2.0, 0.0, TAU)
        .into_iter()
        .map(|[x, y]| [x, y, 0.0])
        .collect();
    trajectory.pop();
    let mut input = SweepInput::new(profile, trajectory);
    input.closed_profile = true;
    input.closed_trajectory = true;
    let torus = sweep::build(&input, &Settings::default()).unwrap();
    let r = folds(&torus.mesh);
    assert!(r.is_fold_free(), "torus: {:?}", r.folded_faces);
    // A fine torus: no face's normal turns far from its mean.
    assert!(r.worst_reversal_deg < 45.0, "{}", r.worst_reversal_deg);
    for (name, profile) in [
        ("cylinder", vec![[1.0, 0.0], [1.0, 2.0]]),
        ("cone", vec![[1.0, 0.0], [0.0, 2.0]]),
        ("half torus", {
            let mut p = arc(48, 0.5, -PI / 2.0, PI / 2.0);
            p.iter_mut().for_each(|q| q[0] += 1.5);
            p
        }),
    ] {
        let s = revolve::build(&RevolveInput::new(profile), &Settings::default()).unwrap();
        let r = folds(&s.mesh);
        assert!(r.is_fold_free(), "{name}: {:?}", r.folded_faces);
    }
}
