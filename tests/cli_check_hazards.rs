//! `profsubd check`'s OpenSubdiv 3.5 hazards: one test per kind with the exact vertices
//! and faces, worked out by hand from the meshes' tags (comments), text and `--json`; none
//! on clean shapes; the exit code is unchanged (hazards are warnings).

#[path = "support/osd_shapes.rs"]
#[allow(dead_code)] // the shapes folder only, not its index
mod osd_shapes;

#[path = "support/cli.rs"]
mod cli;

use std::path::{Path, PathBuf};

use cli::{profsubd, stdout, write_input};

/// One entry of `osd_hazards`: kind, vertices, faces.
type Found = (String, Vec<u32>, Vec<u32>);

/// `check --json` on `path` with `flags`: exit code and the `osd_hazards` array.
fn hazards(path: &Path, flags: &[&str]) -> (i32, Vec<Found>) {
    let mut args = vec!["check", "--json", path.to_str().unwrap()];
    args.extend_from_slice(flags);
    let o = profsubd(&args);
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON report");
    let list = |v: &serde_json::Value| -> Vec<u32> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_u64().unwrap() as u32)
            .collect()
    };
    let found = json["osd_hazards"]
        .as_array()
        .expect("osd_hazards array")
        .iter()
        .map(|h| {
            assert!(!h["affects"].as_array().unwrap().is_empty());
            assert!(h["figure"].as_str().unwrap().len() > 40);
            (
                h["kind"].as_str().unwrap().to_string(),
                list(&h["vertices"]),
                list(&h["faces"]),
            )
        })
        .collect();
    (o.status.code().unwrap(), found)
}

fn kinds(found: &[Found]) -> Vec<&str> {
    found.iter().map(|(k, _, _)| k.as_str()).collect()
}

fn of<'a>(
    found: &'a [(String, Vec<u32>, Vec<u32>)],
    kind: &str,
) -> &'a (String, Vec<u32>, Vec<u32>) {
    found
        .iter()
        .find(|(k, _, _)| k == kind)
        .unwrap_or_else(|| panic!("no {kind} hazard in {found:?}"))
}

fn shape(dir: &Path, name: &str) -> PathBuf {
    dir.join(format!("{name}.obj"))
}

#[test]
fn darts_on_the_inf_crease_shapes() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    // 5 x 5 vertex grid: vertex 17 has the one infinitely sharp edge 16-17; 6 and 16 have
    // three or four, 8, 11, 13, 18 two (creases). Its faces are 9, 10, 13, 14 (row-major 4 x 4).
    let (code, found) = hazards(&shape(&dir, "catmark_inf_crease0"), &[]);
    assert_eq!(code, 0);
    assert_eq!(kinds(&found), ["dart", "primvar_limit"]);
    assert_eq!(of(&found, "dart").1, [17]);
    assert_eq!(of(&found, "dart").2, [9, 10, 13, 14]);
    assert_eq!(of(&found, "primvar_limit").1, [17]);
    // Vertex 0 (interior, six faces) has the one sharp edge 0-4; vertex 4 is on the boundary.
    let (code, found) = hazards(&shape(&dir, "catmark_inf_crease1"), &[]);
    assert_eq!(code, 0);
    assert_eq!(kinds(&found), ["dart", "primvar_limit"]);
    assert_eq!(of(&found, "dart").1, [0]);
    assert_eq!(of(&found, "dart").2, [0, 1, 2, 3, 4, 5]);
}

#[test]
fn chaikin_only_under_chaikin() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    // Two crease rings 0-2-4-...-22-0 and 1-3-...-23-1 with sharpness 1, 2, 3, 4, 5, 5, 5, 4,
    // 3, 2, 1, 5 along them, rungs 0-1, 10-11, 12-13, 22-23 at 5: every vertex but 10, 11,
    // 12, 13 (all three edges at 5) meets different sharpness.
    let chaikin: Vec<u32> = (0..10).chain(14..24).collect();
    for (name, flags) in [
        ("catmark_chaikin1", &[][..]),
        ("catmark_chaikin0", &["--crease", "chaikin"][..]),
    ] {
        let (code, found) = hazards(&shape(&dir, name), flags);
        assert_eq!(code, 0);
        assert_eq!(kinds(&found), ["chaikin", "primvar_limit"], "{name}");
        assert_eq!(of(&found, "chaikin").1, chaikin, "{name}");
        // Every vertex has a semi-sharp edge: PrimvarRefiner::Limit is wrong at all 24.
        assert_eq!(of(&found, "primvar_limit").1, (0..24).collect::<Vec<u32>>());
    }
    for (name, flags) in [
        ("catmark_chaikin0", &[][..]),
        ("catmark_chaikin1", &["--crease", "uniform"][..]),
    ] {
        let (_, found) = hazards(&shape(&dir, name), flags);
        assert_eq!(kinds(&found), ["primvar_limit"], "{name}");
    }
}

#[test]
fn interior_valence_2_vertices_of_both_val2_interior_shapes() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    // 0-based: 16 (faces `13 14 15 17`, `13 17 15 16`) and 17 have no sharpness around;
    // 30 lies on the infinitely sharp creases 30-31 and 30-33; 64, 69, 82, 88, 92 have
    // boundary edges (sharp) in their faces; 59, 60, 95 none.
    for path in [
        shape(&dir, "catmark_val2_interior"),
        dir.join("v3_6_0/catmark_val2_interior.obj"),
    ] {
        let (code, found) = hazards(&path, &[]);
        assert_eq!(code, 0);
        assert_eq!(
            kinds(&found),
            ["valence2_sharp", "valence2", "primvar_limit"]
        );
        assert_eq!(of(&found, "valence2_sharp").1, [30, 64, 69, 82, 88, 92]);
        assert_eq!(of(&found, "valence2").1, [16, 17, 59, 60, 95]);
    }
    // 3.6.0 adds semi-sharp creases 87-88, 88-92, 92-91: PrimvarRefiner::Limit is wrong at
    // 87 and 91 too.
    let (_, old) = hazards(&shape(&dir, "catmark_val2_interior"), &[]);
    let (_, new) = hazards(&dir.join("v3_6_0/catmark_val2_interior.obj"), &[]);
    let valence2: Vec<u32> = vec![16, 17, 30, 59, 60, 64, 69, 82, 88, 92, 95];
    assert_eq!(of(&old, "primvar_limit").1, valence2);
    let mut with_creases = valence2.clone();
    with_creases.extend([87, 91]);
    with_creases.sort();
    assert_eq!(of(&new, "primvar_limit").1, with_creases);
}

#[test]
fn a_valence_2_dart_and_its_neighbour() {
    // A 3 x 3 grid of quads whose centre quad 5-6-10-9 is split by vertex 16 into 5-6-10-16
    // and 5-16-10-9; edge 5-16 infinitely sharp. 16: interior, two faces, one sharp edge (a
    // valence-2 dart); 5: interior, five edges, one of them sharp (a dart).
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::new();
    for j in 0..4 {
        for i in 0..4 {
            text.push_str(&format!("v {i} {j} 0\n"));
        }
    }
    text.push_str("v 1.6 1.4 0\n");
    for j in 0..3 {
        for i in 0..3 {
            let a = 4 * j + i + 1;
            if (i, j) == (1, 1) {
                text.push_str("f 6 7 11 17\nf 6 17 11 10\n");
            } else {
                text.push_str(&format!("f {} {} {} {}\n", a, a + 1, a + 5, a + 4));
            }
        }
    }
    text.push_str("t crease 2/1/0 5 16 10\n");
    let path = write_input(dir.path(), "val2_dart.obj", &text);
    let (code, found) = hazards(&path, &[]);
    assert_eq!(code, 0);
    assert_eq!(kinds(&found), ["dart", "valence2_dart", "primvar_limit"]);
    // Faces 0-3 and 6-9 are the grid's others, 4 and 5 the split centre: those at 5.
    assert_eq!(of(&found, "dart").1, [5]);
    assert_eq!(of(&found, "dart").2, [0, 1, 3, 4, 5]);
    // Two face-rings out from the faces at 16 is the whole mesh.
    assert_eq!(of(&found, "valence2_dart").1, [16]);
    assert_eq!(of(&found, "valence2_dart").2, (0..10).collect::<Vec<u32>>());
    assert_eq!(of(&found, "primvar_limit").1, [5, 16]);
}

#[test]
fn faces_repeating_a_vertex() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    // Every odd face is `x y 5 5` (1-based): vertex 4 repeated by faces 1, 3, ..., 15.
    let (code, found) = hazards(&shape(&dir, "catmark_nonman_quadpole8"), &[]);
    assert_eq!(code, 2, "not a manifold: exit code as before");
    assert_eq!(kinds(&found), ["repeated_vertex"]);
    assert_eq!(of(&found, "repeated_vertex").1, [4]);
    assert_eq!(
        of(&found, "repeated_vertex").2,
        (0..8).map(|k| 2 * k + 1).collect::<Vec<u32>>()
    );
}

#[test]
fn no_hazards_on_clean_shapes_and_text_output() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    for name in ["catmark_cube", "catmark_torus"] {
        let (code, found) = hazards(&shape(&dir, name), &[]);
        assert_eq!((code, found.len()), (0, 0), "{name}");
        let o = profsubd(&["check", shape(&dir, name).to_str().unwrap()]);
        assert!(stdout(&o).contains("\nopensubdiv 3.5 hazards: 0\n"));
    }
    let o = profsubd(&[
        "check",
        shape(&dir, "catmark_inf_crease0").to_str().unwrap(),
    ]);
    let text = stdout(&o);
    assert!(text.contains("\nopensubdiv 3.5 hazards: 2\nhazard dart: vertices 1 [17], faces 4 [9 10 13 14] (Bfr, Far::PatchTable, Osd): "), "{text}");
    assert!(text.contains("\nhazard primvar_limit: vertices 1 [17] (Far::PrimvarRefiner::Limit): "));
    assert!(text.ends_with("result: manifold mesh\n"));
}
