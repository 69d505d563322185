//! A refined [`Level`] back to a [`Mesh`], with the sharpness that came from tags written as
//! tags, and the sharpness Far derives from topology (boundaries, non-manifold features,
//! boundary corners) left for the reader of the mesh to derive again.

use glam::DVec3;

use super::step::Refinement;
use crate::mesh::{Corner, Crease, Mesh, MeshParts};
use crate::options::{BoundaryInterpolation, PartialOptions};
use crate::topology::Level;

/// Whether an edge's sharpness is written as a tag: sharp, and not sharpened by Far itself.
/// Under boundary interpolation *none*, boundary edges are written too: their tags decide
/// which faces become holes, and the refined level's holes are written explicitly.
fn is_tagged(
    sharpness: f32,
    boundary: bool,
    non_manifold: bool,
    rule: BoundaryInterpolation,
) -> bool {
    sharpness > 0.0 && !non_manifold && (!boundary || rule == BoundaryInterpolation::None)
}

/// The crease tags of a complete level, in edge order.
pub(super) fn creases_of(level: &Level) -> Vec<Crease> {
    (0..level.num_edges())
        .filter(|&e| {
            is_tagged(
                level.edge_sharpness(e),
                level.is_edge_boundary(e),
                level.is_edge_non_manifold(e),
                level.options().boundary,
            )
        })
        .map(|e| Crease {
            vertices: level.edge_vertices(e),
            sharpness: level.edge_sharpness(e),
        })
        .collect()
}

/// The crease tags of the child of `r`, in child edge order, from the parent: only halves of
/// parent edges can be sharp, and a half is a boundary or non-manifold edge when its parent is.
pub(crate) fn creases_of_child(parent: &Level, r: &Refinement) -> Vec<Crease> {
    let mut out = Vec::new();
    for e in 0..parent.num_edges() {
        let (boundary, nm) = (parent.is_edge_boundary(e), parent.is_edge_non_manifold(e));
        for (j, &end) in parent.edge_vertices(e).iter().enumerate() {
            let s = r.child.edge_sharpness(r.edge_child_edge(e, j) as usize);
            if is_tagged(s, boundary, nm, parent.options().boundary) {
                out.push(Crease {
                    vertices: [r.edge_child_vertex(e), r.vertex_child_vertex(end as usize)],
                    sharpness: s,
                });
            }
        }
    }
    out
}

/// The corner tags of `level` (whose edge and vertex relations may be absent): its sharp
/// vertices, except those `sharpened(v)` says Far sharpens from topology alone (asked only of
/// sharp vertices).
pub(crate) fn corners_of(level: &Level, sharpened: impl Fn(usize) -> bool) -> Vec<Corner> {
    (0..level.num_vertices())
        .filter(|&v| level.vertex_sharpness(v) > 0.0 && !sharpened(v))
        .map(|v| Corner {
            vertex: v as u32,
            sharpness: level.vertex_sharpness(v),
        })
        .collect()
}

/// `level` with its positions, corners and creases as a mesh.
///
/// The mesh is built without validation: a level refined from a valid mesh is valid (its
/// faces index its vertices, its creases are halves of sharp parent edges, positions are
/// weighted averages of finite positions); the refine tests validate the output.
pub(super) fn to_mesh(
    level: Level,
    positions: Vec<DVec3>,
    corners: Vec<Corner>,
    creases: Vec<Crease>,
) -> Mesh {
    let options = *level.options();
    let nf = level.num_faces();
    let face_sizes = level.face_offsets.windows(2).map(|w| w[1] - w[0]).collect();
    let holes = (0..nf as u32)
        .filter(|&f| level.is_face_hole(f as usize))
        .collect();
    let parts = MeshParts {
        positions,
        face_sizes,
        face_indices: level.face_verts,
        creases,
        corners,
        holes,
        options: PartialOptions {
            boundary: Some(options.boundary),
            crease_method: Some(options.crease_method),
            triangles: Some(options.triangles),
        },
    };
    Mesh::from_trusted_parts(parts, level.face_offsets)
}
