//! Comparing regenerated example output with the checked-in files, and running the CLI:
//! `mod mesh_compare;` via `#[path = "support/mesh_compare.rs"]` in a test crate.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use glam::DVec3;
use profsubd::Mesh;

/// `examples/<dir>/<name>.<ext>` in the repository.
pub fn example_file(dir: &str, name: &str, ext: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(dir)
        .join(format!("{name}.{ext}"))
}

/// Run the `profsubd` binary with `args`.
pub fn run_cli(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_profsubd"))
        .args(args)
        .output()
        .expect("run profsubd")
}

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
