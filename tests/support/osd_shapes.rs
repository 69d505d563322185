//! Locating OpenSubdiv's regression shapes for tests: `mod osd_shapes;` via
//! `#[path = "support/osd_shapes.rs"]` in a test crate.

use std::path::{Path, PathBuf};

/// One row of the shapes' `INDEX.tsv`.
#[allow(dead_code)] // each test crate reads the columns it needs
pub struct IndexRow {
    /// Shape name, the file stem.
    pub name: String,
    /// The `.obj` file.
    pub path: PathBuf,
    /// Number of vertices.
    pub verts: usize,
    /// Number of faces.
    pub faces: usize,
    /// Column `has_creases`.
    pub has_creases: bool,
    /// Column `has_corners`.
    pub has_corners: bool,
    /// Column `boundary`: `none`, `edge`, `edgeandcorner` or `untagged`.
    pub boundary: String,
    /// Column `notes`.
    pub notes: String,
}

/// The OpenSubdiv shapes folder: `$PROFSUBD_OSD_SHAPES`, else
/// `<repo>/../shared/conformance/osd_shapes`. `None`, with a notice on stderr, if absent.
pub fn shapes_dir() -> Option<PathBuf> {
    let dir = std::env::var_os("PROFSUBD_OSD_SHAPES")
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/conformance/osd_shapes")
        });
    if dir.is_dir() {
        Some(dir)
    } else {
        eprintln!(
            "NOTICE: OpenSubdiv shapes folder {} not found (set PROFSUBD_OSD_SHAPES); \
             skipping the shape tests, the generated-mesh tests still run",
            dir.display()
        );
        None
    }
}

/// The rows of `INDEX.tsv` in `dir`.
pub fn index(dir: &Path) -> Vec<IndexRow> {
    let text = std::fs::read_to_string(dir.join("INDEX.tsv")).expect("INDEX.tsv");
    text.lines()
        .skip(1)
        .filter(|l| !l.trim().is_empty())
        .map(|row| {
            let c: Vec<&str> = row.split('\t').collect();
            IndexRow {
                name: c[0].to_string(),
                path: dir.join(format!("{}.obj", c[0])),
                verts: c[1].parse().expect("verts"),
                faces: c[2].parse().expect("faces"),
                has_creases: c[4] == "yes",
                has_corners: c[5] == "yes",
                boundary: c[6].to_string(),
                notes: c.get(7).unwrap_or(&"").to_string(),
            }
        })
        .collect()
}
