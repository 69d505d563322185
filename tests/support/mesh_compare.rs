//! Comparing regenerated example output with the checked-in files: `mod mesh_compare;` via
//! `#[path = "support/mesh_compare.rs"]` in a test crate (running the CLI and the examples'
//! paths: `support/cli.rs`).

use std::path::Path;

use glam::DVec3;
use profsubd::Mesh;

/// Same faces, tags and options; positions equal within `1e-9 ×` the diagonal.
pub fn assert_same(a: &Mesh, b: &Mesh, what: &str) {
    assert_eq!(a.face_sizes(), b.face_sizes(), "{what}");
    assert_eq!(a.face_indices(), b.face_indices(), "{what}");
    assert_eq!(a.creases(), b.creases(), "{what}");
    assert_eq!(a.corners(), b.corners(), "{what}");
    assert_eq!(a.options(), b.options(), "{what}");
    let tol = 1e-9 * a.bounding_box_diagonal();
    for (i, (p, q)) in a.positions().iter().zip(b.positions()).enumerate() {
        assert!((*p - *q).length() <= tol, "{what}: vertex {i} {p} vs {q}");
    }
}

/// The targets file at `path` (3 numbers per point) holds `targets` within `tol`.
pub fn assert_targets(path: &Path, targets: &[DVec3], tol: f64, what: &str) {
    let text = std::fs::read_to_string(path).unwrap();
    let stored: Vec<f64> = text
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    assert_eq!(stored.len(), 3 * targets.len(), "{what}");
    for (t, q) in targets.iter().zip(stored.chunks(3)) {
        assert!(
            t.distance(DVec3::from_slice(q)) <= tol,
            "{what}: target {t}"
        );
    }
}
