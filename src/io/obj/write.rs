//! The OBJ writer: shortest round-trip numbers, OpenSubdiv tag lines.

use std::fmt::{Display, LowerExp, Write};

use crate::mesh::Mesh;
use crate::options::{BoundaryInterpolation, CreaseMethod, TriangleSubdivision};

/// The OBJ text of `mesh`: `v` lines, 1-based `f` lines, then the tags (options the mesh
/// carries, creases and corners in order, holes). Reading it with
/// [`parse_obj`](super::parse_obj) gives back an equal mesh, every coordinate and
/// sharpness bit for bit.
pub fn to_obj_string(mesh: &Mesh) -> String {
    let mut out = String::with_capacity(32 * (mesh.num_vertices() + mesh.face_indices().len()));
    out.push_str("# written by profsubd; tags as OpenSubdiv's regression shapes\n");
    for p in mesh.positions() {
        let _ = writeln!(out, "v {} {} {}", Num(p.x), Num(p.y), Num(p.z));
    }
    for f in 0..mesh.num_faces() {
        out.push('f');
        for &v in mesh.face(f) {
            let _ = write!(out, " {}", v as u64 + 1);
        }
        out.push('\n');
    }
    let options = mesh.options();
    if let Some(b) = options.boundary {
        let value = match b {
            BoundaryInterpolation::None => 0,
            BoundaryInterpolation::EdgeAndCorner => 1,
            BoundaryInterpolation::EdgeOnly => 2,
        };
        let _ = writeln!(out, "t interpolateboundary 1/0/0 {value}");
    }
    if let Some(m) = options.crease_method {
        let value = match m {
            CreaseMethod::Uniform => "normal",
            CreaseMethod::Chaikin => "chaikin",
        };
        let _ = writeln!(out, "t creasemethod 0/0/1 {value}");
    }
    if let Some(t) = options.triangles {
        let value = match t {
            TriangleSubdivision::Catmark => "catmark",
            TriangleSubdivision::Smooth => "smooth",
        };
        let _ = writeln!(out, "t smoothtriangles 0/0/1 {value}");
    }
    for c in mesh.creases() {
        let [a, b] = c.vertices;
        let _ = writeln!(out, "t crease 2/1/0 {a} {b} {}", Num(c.sharpness));
    }
    for c in mesh.corners() {
        let _ = writeln!(out, "t corner 1/1/0 {} {}", c.vertex, Num(c.sharpness));
    }
    if !mesh.holes().is_empty() {
        let _ = write!(out, "t hole {}/0/0", mesh.holes().len());
        for h in mesh.holes() {
            let _ = write!(out, " {h}");
        }
        out.push('\n');
    }
    out
}

/// A float printed with the fewest digits that parse back to the same value: plain decimal
/// for ordinary magnitudes, exponent form (`1e-7`) for very small or large ones so that
/// no number turns into hundreds of digits.
pub(crate) struct Num<T>(pub(crate) T);

impl<T: Display + LowerExp + Into<f64> + Copy> Display for Num<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let magnitude = self.0.into().abs();
        if magnitude == 0.0 || (1e-5..1e16).contains(&magnitude) || !magnitude.is_finite() {
            write!(f, "{}", self.0)
        } else {
            write!(f, "{:e}", self.0)
        }
    }
}
