//! A refined [`Level`] back to a [`Mesh`], with the sharpness that came from tags written as
//! tags, and the sharpness Far derives from topology (boundaries, non-manifold features,
//! boundary corners) left for the reader of the mesh to derive again.

use glam::DVec3;

use crate::error::Result;
use crate::mesh::{Corner, Crease, Mesh, MeshParts};
use crate::options::PartialOptions;
use crate::topology::Level;

pub(super) fn to_mesh(level: &Level, positions: Vec<DVec3>) -> Result<Mesh> {
    let options = *level.options();
    let nf = level.num_faces();
    let creases = (0..level.num_edges())
        .filter(|&e| {
            level.edge_sharpness(e) > 0.0
                && !level.is_edge_boundary(e)
                && !level.is_edge_non_manifold(e)
        })
        .map(|e| Crease {
            vertices: level.edge_vertices(e),
            sharpness: level.edge_sharpness(e),
        })
        .collect();
    let corners = (0..level.num_vertices())
        .filter(|&v| {
            level.vertex_sharpness(v) > 0.0
                && !level.vertex_topology(v).is_sharpened(options.boundary)
        })
        .map(|v| Corner {
            vertex: v as u32,
            sharpness: level.vertex_sharpness(v),
        })
        .collect();
    let face_indices: Vec<u32> = (0..nf)
        .flat_map(|f| level.face_vertices(f).iter().copied())
        .collect();
    let parts = MeshParts {
        positions,
        face_sizes: (0..nf)
            .map(|f| level.face_vertices(f).len() as u32)
            .collect(),
        face_indices,
        creases,
        corners,
        holes: (0..nf as u32)
            .filter(|&f| level.is_face_hole(f as usize))
            .collect(),
        options: PartialOptions {
            boundary: Some(options.boundary),
            crease_method: Some(options.crease_method),
            triangles: Some(options.triangles),
        },
    };
    Mesh::from_parts(parts)
}
