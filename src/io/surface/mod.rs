//! Writers for tessellated limit surfaces ([`Tessellation`]): STL (binary and ASCII), OFF,
//! PLY (binary, with normals) and OBJ (with `vn`). Bytes are deterministic: the same
//! tessellation and options give the same file.
//!
//! What each format keeps:
//! - **STL**: triangles only (quads split along their shorter diagonal), unindexed, each
//!   with its geometric unit normal; coordinates as `f32` in binary, shortest round-trip
//!   decimals of the `f64` in ASCII.
//! - **OFF**: indexed polygons (triangles or quads), exact `f64` decimals, no normals.
//! - **PLY**: binary little-endian, `double` positions and per-vertex normals
//!   ([`Tessellation::vertex_normals`]: split normals averaged), polygons as `uchar`-counted
//!   `uint` lists.
//! - **OBJ**: `v`, `vn` (split along infinitely sharp creases) and `f v//vn`, 1-based.
//!
//! Every writer takes an [`UpAxis`]; positions and normals are rotated to it.

mod obj;
mod off;
mod ply;
mod stl;

use std::path::Path;

use glam::DVec3;

use super::up_axis::UpAxis;
use crate::error::{Error, Result};
use crate::tessellate::Tessellation;

/// A file format for tessellations.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SurfaceFormat {
    /// Binary STL.
    Stl,
    /// ASCII STL.
    StlAscii,
    /// Object File Format (text).
    Off,
    /// Binary little-endian PLY with normals.
    Ply,
    /// Wavefront OBJ with normals.
    Obj,
}

impl SurfaceFormat {
    /// The format of a file name's extension (`.stl` is binary STL), case-insensitive.
    ///
    /// Errors ([`Error::InvalidArgument`]): no extension or an unknown one.
    pub fn from_path(path: &Path) -> Result<SurfaceFormat> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("stl") => Ok(SurfaceFormat::Stl),
            Some("off") => Ok(SurfaceFormat::Off),
            Some("ply") => Ok(SurfaceFormat::Ply),
            Some("obj") => Ok(SurfaceFormat::Obj),
            _ => Err(Error::invalid_argument(format!(
                "cannot tell the format of {} from its extension (.stl, .off, .ply, .obj); \
                 give --format",
                path.display()
            ))),
        }
    }
}

/// The bytes of `t` in `format`, with `up` as the up axis.
pub fn surface_to_bytes(t: &Tessellation, format: SurfaceFormat, up: UpAxis) -> Vec<u8> {
    let positions: Vec<DVec3> = t.positions.iter().map(|&p| up.from_z_up(p)).collect();
    let rotate = |n: &[DVec3]| n.iter().map(|&n| up.from_z_up(n)).collect::<Vec<_>>();
    let polygons = Polygons {
        positions: &positions,
        sizes: &t.face_sizes,
        vertices: &t.face_vertices,
    };
    match format {
        SurfaceFormat::Stl => stl::binary(&positions, &t.triangles()),
        SurfaceFormat::StlAscii => stl::ascii(&positions, &t.triangles()).into_bytes(),
        SurfaceFormat::Off => off::off(&polygons).into_bytes(),
        SurfaceFormat::Ply => ply::ply(&polygons, &rotate(&t.vertex_normals)),
        SurfaceFormat::Obj => {
            obj::obj(&polygons, &rotate(&t.normals), &t.face_normals).into_bytes()
        }
    }
}

/// Write `t` to `path` in `format` ([`surface_to_bytes`]).
///
/// Errors: [`Error::Io`] if the file cannot be written.
pub fn write_surface_file(
    t: &Tessellation,
    path: &Path,
    format: SurfaceFormat,
    up: UpAxis,
) -> Result<()> {
    std::fs::write(path, surface_to_bytes(t, format, up)).map_err(|e| Error::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}

/// Indexed polygons with positions already in the file's axes.
struct Polygons<'a> {
    positions: &'a [DVec3],
    sizes: &'a [u32],
    vertices: &'a [u32],
}

impl Polygons<'_> {
    /// Each polygon's vertex indices, in order.
    fn each(&self) -> impl Iterator<Item = &[u32]> {
        let mut start = 0;
        self.sizes.iter().map(move |&s| {
            let c = &self.vertices[start..start + s as usize];
            start += s as usize;
            c
        })
    }
}

#[cfg(test)]
mod tests;
