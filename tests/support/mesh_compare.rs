//! Comparing a regenerated mesh with a checked-in one: `mod mesh_compare;` via
//! `#[path = "support/mesh_compare.rs"]` in a test crate.

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
