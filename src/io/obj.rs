//! Wavefront OBJ with OpenSubdiv's tag lines, as read by OpenSubdiv's regression harness
//! (`regression/common/shape_utils.cpp`) and applied by `far_utils.h`.
//!
//! # What is read
//! - `v x y z [w]`: a vertex (`w` ignored). Coordinates are parsed as `f64` (OpenSubdiv's
//!   harness reads `float`); a non-finite coordinate is an error.
//! - `f a b c ...`: a face with at least 3 vertices. Indices are 1-based; a negative index
//!   counts back from the last vertex read so far (`-1` = last). Of the `a/b/c`, `a//c` and
//!   `a/b` forms only the vertex index (before the first `/`) is used.
//! - `t NAME ni/nf/ns ints floats strings`: a tag (indices 0-based):
//!   - `crease 2/1/0 v0 v1 s`, `crease 2k/1/0 ...` (k edges, one sharpness),
//!     `crease 2k/k/0 ...` (k edges, one sharpness each; OpenSubdiv's harness pairs those
//!     floats with the wrong edges, no OpenSubdiv shape uses the form);
//!   - `corner n/1/0 v.. s` and `corner n/n/0 v.. s..`;
//!   - `hole n/0/0 f..`;
//!   - `interpolateboundary 1/0/0 B`: 0 none, 1 edge-and-corner, 2 edge-only;
//!   - `creasemethod 0/0/1 normal|chaikin`; `smoothtriangles 0/0/1 catmark|smooth`.
//!
//!   A repeated `interpolateboundary`, `creasemethod` or `smoothtriangles` tag overrides the
//!   earlier one (with a warning), as in the harness. A tag absent from the file leaves the
//!   option unset in [`Mesh::options`], so the caller's option or the default applies.
//! - Face-varying tags (`facevaryinginterpolateboundary`, `facevaryingpropagatecorners`) and
//!   hierarchical edits (`vertexedit`, `edgeedit`, `faceedit`, unsupported by OpenSubdiv 3)
//!   are ignored with a warning; so is any other unknown tag or statement. Nothing is
//!   dropped silently: every warning names the file and line.
//! - `vt`, `vn`, `g`, `o`, `s`, `usemtl`, `mtllib`, blank lines and `#` comments are ignored.
//!
//! # Negative sharpness
//! OpenSubdiv's harness clamps a negative sharpness to 0. The reader does the same, with a
//! warning, so every OpenSubdiv file loads; the [`Mesh`] API itself rejects negative
//! sharpness, because from a program it is a bug, not a file convention.
//!
//! # Errors
//! Malformed lines, indices out of range (vertex, crease, corner, hole) and creases on a
//! vertex pair no face joins are [`Error::Parse`] with the file, the 1-based line and what
//! was expected.
//!
//! # Writing
//! [`to_obj_string`] writes vertices with the shortest decimal that reads back to the same
//! `f64` (and sharpness to the same `f32`), faces 1-based, then the option tags the mesh
//! carries, one `t crease 2/1/0`/`t corner 1/1/0` line per crease and corner in order, and
//! one `t hole` line: reading it back gives a mesh equal bit for bit.

mod read;
mod write;

use std::path::Path;

use crate::error::{Error, Result};
use crate::mesh::Mesh;

pub use read::parse_obj;
pub use write::to_obj_string;
pub(crate) use write::Num;

/// A mesh read from an OBJ file, with what the reader ignored.
#[derive(Debug, Clone, PartialEq)]
pub struct ObjRead {
    /// The validated mesh.
    pub mesh: Mesh,
    /// One message per ignored tag or statement and per clamped value, each starting with
    /// `file:line:`.
    pub warnings: Vec<String>,
}

/// Largest OBJ file [`read_obj_file`] reads (1 GiB, about 20 million vertices and faces): a
/// larger file is refused before any of it is read.
pub const MAX_OBJ_BYTES: u64 = 1 << 30;

/// Read and parse the OBJ file at `path`; see the [module documentation](self).
///
/// Errors: [`Error::Io`] if the file cannot be read, [`Error::Parse`] for a
/// malformed file or one above [`MAX_OBJ_BYTES`], [`Error::InvalidMesh`] for a mesh OpenSubdiv could not take.
pub fn read_obj_file(path: &Path) -> Result<ObjRead> {
    // Refuse an absurd file before reading it into memory.
    if let Ok(meta) = std::fs::metadata(path) {
        if meta.len() > MAX_OBJ_BYTES {
            return Err(Error::Parse {
                path: path.to_path_buf(),
                line: 0,
                message: format!(
                    "the file is {} bytes, above the OBJ reader's limit of {MAX_OBJ_BYTES} bytes",
                    meta.len()
                ),
            });
        }
    }
    let bytes = std::fs::read(path).map_err(|e| Error::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    // Bytes that are not UTF-8 can only matter in comments and names, which are ignored.
    parse_obj(&String::from_utf8_lossy(&bytes), path)
}

/// Write `mesh` to `path` as OBJ with OpenSubdiv tags ([`to_obj_string`]).
///
/// Errors: [`Error::Io`] if the file cannot be written.
pub fn write_obj_file(mesh: &Mesh, path: &Path) -> Result<()> {
    std::fs::write(path, to_obj_string(mesh)).map_err(|e| Error::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}

#[cfg(test)]
mod tests;
