//! The validation report on OpenSubdiv's regression shapes, checked against the topology
//! notes of the shapes' `INDEX.tsv` (boundary edges, face sizes, non-manifold findings).

#[path = "support/osd_shapes.rs"]
mod osd_shapes;

use std::collections::BTreeMap;

use osd_shapes::{index, shapes_dir};
use profsubd::io::obj::read_obj_file;

/// The shapes the shapes' README flags non-manifold.
const NON_MANIFOLD: [&str; 10] = [
    "catmark_fan",
    "catmark_gregory_test4",
    "catmark_nonman_bareverts",
    "catmark_nonman_edge100",
    "catmark_nonman_edges",
    "catmark_nonman_quadpole8",
    "catmark_nonman_quadpole64",
    "catmark_nonman_quadpole360",
    "catmark_nonman_verts",
    "catmark_val2_nonman",
];

/// The number written before `what` in the notes (`open (24 boundary edges)` gives 24 for
/// `" boundary edges"`), 0 if absent.
fn noted(notes: &str, what: &str) -> usize {
    notes
        .find(what)
        .map(|end| {
            let start = notes[..end]
                .rfind(|c: char| !c.is_ascii_digit())
                .map_or(0, |i| i + 1);
            notes[start..end].parse().unwrap()
        })
        .unwrap_or(0)
}

#[test]
fn reports_agree_with_the_shape_index() {
    let Some(dir) = shapes_dir() else { return };
    let mut flagged = Vec::new();
    for row in index(&dir) {
        let name = row.name.as_str();
        let r = read_obj_file(&row.path).unwrap().mesh.check();
        let notes = row.notes.as_str();
        assert_eq!(
            r.boundary_edges.len(),
            noted(notes, " boundary edges"),
            "{name}"
        );
        assert_eq!(r.is_closed(), !notes.contains("open ("), "{name}");
        let sizes: BTreeMap<usize, usize> = match notes.find("face sizes ") {
            Some(i) => notes[i + 11..]
                .split(';')
                .next()
                .unwrap()
                .split_whitespace()
                .map(|kv| {
                    let (k, v) = kv.split_once(':').unwrap();
                    (k.parse().unwrap(), v.parse().unwrap())
                })
                .collect(),
            None => BTreeMap::from([(4, row.faces)]),
        };
        assert_eq!(r.face_sizes, sizes, "{name}");
        let findings = [
            (r.non_manifold_edges.len(), " edges with >2 faces"),
            (
                r.inconsistent_edges.len(),
                " edges with inconsistent orientation",
            ),
            (r.non_manifold_vertices.len(), " non-manifold vertices"),
            (r.isolated_vertices.len(), " isolated vertices"),
            (
                r.faces_with_repeated_vertices.len(),
                " faces with repeated vertices",
            ),
        ];
        for (count, what) in findings {
            assert_eq!(count, noted(notes, what), "{name}:{what}");
        }
        assert_eq!(r.is_manifold(), !notes.contains("non-manifold ("), "{name}");
        if !r.is_manifold() {
            flagged.push(row.name.clone());
        }
    }
    flagged.sort();
    let mut expected: Vec<String> = NON_MANIFOLD.iter().map(|s| s.to_string()).collect();
    expected.sort();
    assert_eq!(flagged, expected);
}

#[test]
fn closed_shapes_have_the_expected_euler_characteristic() {
    let Some(dir) = shapes_dir() else { return };
    // Spheres (χ = 2 each; val2_back2back is four two-face spheres), a torus (χ = 0) and
    // a tetrahedral frame (genus 3, χ = -4).
    let expected = [
        ("catmark_cube", 2, 1),
        ("catmark_pyramid", 2, 1),
        ("catmark_smoothtris0", 2, 1),
        ("catmark_torus", 0, 1),
        ("catmark_toroidal_tet", -4, 1),
        ("catmark_val2_back2back", 8, 4),
    ];
    for (name, chi, components) in expected {
        let r = read_obj_file(&dir.join(format!("{name}.obj")))
            .unwrap()
            .mesh
            .check();
        assert_eq!(r.euler_characteristic, chi, "{name}");
        assert_eq!(r.num_components, components, "{name}");
        assert!(
            r.is_closed() && r.is_manifold() && r.is_consistently_oriented(),
            "{name}"
        );
        assert_eq!(r.num_boundary_loops, 0, "{name}");
    }
}
