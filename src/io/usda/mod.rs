//! USD ASCII (`.usda`): a control mesh as a `UsdGeomMesh` with its subdivision tags.
//!
//! # What is written
//! One stage with `defaultPrim = "mesh"` and `upAxis` ("Z", or "Y" with points written as
//! `(x, z, -y)`: see [`UpAxis`]), holding `def Mesh "mesh"` with:
//! - `faceVertexCounts`, `faceVertexIndices`, `points` (`point3f[]`: USD stores points as
//!   32-bit floats, so coordinates are rounded to `f32`), `extent` (of the points written),
//!   `orientation = "rightHanded"`;
//! - `subdivisionScheme = "catmullClark"`, `interpolateBoundary` (`none`, `edgeOnly`,
//!   `edgeAndCorner`), `triangleSubdivisionRule` (`catmullClark`, `smooth`), from the mesh's
//!   options with profsubd's defaults for unset ones (they equal USD's fallbacks);
//! - `creaseIndices` / `creaseLengths` / `creaseSharpnesses`: consecutive creases of the
//!   mesh with one sharpness that continue each other (`(a, b)` then `(b, c)`) form one
//!   chain `a b c` with one sharpness, so reading it back gives the same creases in the same
//!   order;
//! - `cornerIndices` / `cornerSharpnesses`, `holeIndices` (each only when non-empty).
//!
//! USD has no crease method: a mesh with Chaikin creasing gets `customData = { string
//! profsubdCreaseMethod = "chaikin" }` on the prim, which profsubd reads back and other
//! programs ignore (they apply uniform creasing), and [`to_usda`] returns a warning.
//!
//! # What is read
//! The first `def Mesh` prim of the file and the stage's `upAxis`, with the attributes above
//! (a per-edge `creaseSharpnesses`, one value per edge of the chains, is accepted too);
//! other attributes, prims and metadata are skipped. A left-handed mesh is an error. Text
//! written by USD itself (`UsdStage::Export`) reads as well.

mod parse;

use std::fmt::Write;
use std::path::Path;

use glam::DVec3;

use super::obj::Num;
use super::up_axis::UpAxis;
use crate::error::{Error, Result};
use crate::mesh::{Crease, Mesh};
use crate::options::{BoundaryInterpolation, CreaseMethod, TriangleSubdivision};

pub use parse::parse_usda;

/// The USDA text of `mesh` with `up` as the stage's up axis, and the warnings (Chaikin
/// creasing, which USD cannot express).
pub fn to_usda(mesh: &Mesh, up: UpAxis) -> (String, Vec<String>) {
    let options = mesh.options().resolve();
    let mut warnings = Vec::new();
    let mut out = String::new();
    let _ = write!(
        out,
        "#usda 1.0\n(\n    defaultPrim = \"mesh\"\n    doc = \"written by profsubd\"\n    upAxis = \"{}\"\n)\n\n",
        up.name()
    );
    out.push_str("def Mesh \"mesh\"");
    if options.crease_method == CreaseMethod::Chaikin {
        out.push_str(
            " (\n    customData = {\n        string profsubdCreaseMethod = \"chaikin\"\n    }\n)",
        );
        warnings.push(
            "USD has no crease method: Chaikin creasing is kept as custom data \
             (profsubdCreaseMethod), other programs will use uniform creasing"
                .to_string(),
        );
    }
    out.push_str("\n{\n");
    let points: Vec<[f32; 3]> = mesh
        .positions()
        .iter()
        .map(|&p| up.from_z_up(p).to_array().map(|x| x as f32))
        .collect();
    let (mut lo, mut hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
    for p in &points {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let v3 = |p: &[f32; 3]| format!("({}, {}, {})", Num(p[0]), Num(p[1]), Num(p[2]));
    let list = |items: Vec<String>| format!("[{}]", items.join(", "));
    let ints = |xs: &[u32]| list(xs.iter().map(u32::to_string).collect());
    let floats = |xs: &[f32]| list(xs.iter().map(|&x| Num(x).to_string()).collect());
    let mut attr = |decl: &str, value: String| {
        let _ = writeln!(out, "    {decl} = {value}");
    };
    if !points.is_empty() {
        attr("float3[] extent", list(vec![v3(&lo), v3(&hi)]));
    }
    attr("int[] faceVertexCounts", ints(mesh.face_sizes()));
    attr("int[] faceVertexIndices", ints(mesh.face_indices()));
    attr("uniform token orientation", "\"rightHanded\"".to_string());
    attr("point3f[] points", list(points.iter().map(v3).collect()));
    attr(
        "uniform token subdivisionScheme",
        "\"catmullClark\"".to_string(),
    );
    let boundary = match options.boundary {
        BoundaryInterpolation::None => "none",
        BoundaryInterpolation::EdgeOnly => "edgeOnly",
        BoundaryInterpolation::EdgeAndCorner => "edgeAndCorner",
    };
    attr(
        "uniform token interpolateBoundary",
        format!("\"{boundary}\""),
    );
    let triangles = match options.triangles {
        TriangleSubdivision::Catmark => "catmullClark",
        TriangleSubdivision::Smooth => "smooth",
    };
    attr(
        "uniform token triangleSubdivisionRule",
        format!("\"{triangles}\""),
    );
    let chains = crease_chains(mesh.creases());
    if !chains.is_empty() {
        let indices: Vec<u32> = chains.iter().flat_map(|(c, _)| c.iter().copied()).collect();
        let lengths: Vec<u32> = chains.iter().map(|(c, _)| c.len() as u32).collect();
        let sharp: Vec<f32> = chains.iter().map(|&(_, s)| s).collect();
        attr("int[] creaseIndices", ints(&indices));
        attr("int[] creaseLengths", ints(&lengths));
        attr("float[] creaseSharpnesses", floats(&sharp));
    }
    if !mesh.corners().is_empty() {
        let v: Vec<u32> = mesh.corners().iter().map(|c| c.vertex).collect();
        let s: Vec<f32> = mesh.corners().iter().map(|c| c.sharpness).collect();
        attr("int[] cornerIndices", ints(&v));
        attr("float[] cornerSharpnesses", floats(&s));
    }
    if !mesh.holes().is_empty() {
        attr("int[] holeIndices", ints(mesh.holes()));
    }
    out.push_str("}\n");
    (out, warnings)
}

/// Consecutive creases that continue each other with the same sharpness, as vertex chains.
fn crease_chains(creases: &[Crease]) -> Vec<(Vec<u32>, f32)> {
    let mut chains: Vec<(Vec<u32>, f32)> = Vec::new();
    for c in creases {
        if let Some((chain, s)) = chains.last_mut() {
            if *s == c.sharpness && chain.last() == Some(&c.vertices[0]) {
                chain.push(c.vertices[1]);
                continue;
            }
        }
        chains.push((c.vertices.to_vec(), c.sharpness));
    }
    chains
}

/// Write `mesh` to `path` as USDA ([`to_usda`]); returns the warnings.
///
/// Errors: [`Error::Io`] if the file cannot be written.
pub fn write_usda_file(mesh: &Mesh, path: &Path, up: UpAxis) -> Result<Vec<String>> {
    let (text, warnings) = to_usda(mesh, up);
    std::fs::write(path, text).map_err(|e| Error::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    Ok(warnings)
}

/// Read the USDA file at `path` ([`parse_usda`]); positions in profsubd's Z-up axes.
///
/// Errors: [`Error::Io`], [`Error::Parse`], [`Error::InvalidMesh`].
pub fn read_usda_file(path: &Path) -> Result<Mesh> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    parse_usda(&text, path)
}

/// Positions of a file with up axis `up` in Z-up axes.
fn to_z_up(points: Vec<DVec3>, up: UpAxis) -> Vec<DVec3> {
    points.into_iter().map(|p| up.to_z_up(p)).collect()
}

#[cfg(test)]
mod tests;
