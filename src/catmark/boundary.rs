//! Boundary interpolation and non-manifold features: the sharpness OpenSubdiv's Far gives
//! boundary and non-manifold edges and vertices before refinement, under each
//! [`BoundaryInterpolation`] rule (`Far::TopologyRefinerFactoryBase::prepareComponentTagsAndSharpness`).
//!
//! - Every boundary edge and every non-manifold edge is infinitely sharp, under every rule.
//! - *Edge and corner*: a vertex with one face and two edges is an infinitely sharp corner.
//! - Non-manifold vertices are infinitely sharp, except on an interior non-manifold crease
//!   (two non-manifold edges, no boundary edge, more faces than edges), where the two
//!   infinitely sharp edges make the crease rule apply.
//! - *None*: faces around a boundary vertex with a boundary edge that the caller did not make
//!   infinitely sharp become holes (no limit surface); vertex data is still refined as
//!   under *edge only*.

use super::crease::{is_infinite, SHARPNESS_INFINITE};
use crate::options::BoundaryInterpolation;

/// Sharpness Far uses for an edge tagged with sharpness `tagged`.
pub fn edge_sharpness(tagged: f32, is_boundary: bool, is_non_manifold: bool) -> f32 {
    if is_boundary || is_non_manifold {
        SHARPNESS_INFINITE
    } else {
        tagged
    }
}

/// Topology around a vertex, as the boundary rules see it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct VertexTopology {
    /// Number of incident faces (a face that uses the vertex twice counts twice).
    pub num_faces: usize,
    /// Number of incident edges.
    pub num_edges: usize,
    /// Whether the vertex is non-manifold.
    pub non_manifold: bool,
    /// Number of incident non-manifold edges.
    pub non_manifold_edges: usize,
    /// Number of incident boundary edges.
    pub boundary_edges: usize,
}

impl VertexTopology {
    /// One face and two edges: a corner of the boundary.
    pub fn is_topological_corner(&self) -> bool {
        self.num_faces == 1 && self.num_edges == 2
    }

    /// Whether Far makes this vertex infinitely sharp, whatever its tag.
    pub fn is_sharpened(&self, rule: BoundaryInterpolation) -> bool {
        if self.is_topological_corner() && rule == BoundaryInterpolation::EdgeAndCorner {
            return true;
        }
        self.non_manifold
            && !(self.non_manifold_edges == 2
                && self.boundary_edges == 0
                && self.num_faces > self.num_edges)
    }
}

/// Sharpness Far uses for a vertex tagged with sharpness `tagged`.
pub fn vertex_sharpness(
    tagged: f32,
    topology: &VertexTopology,
    rule: BoundaryInterpolation,
) -> f32 {
    if topology.is_sharpened(rule) {
        SHARPNESS_INFINITE
    } else {
        tagged
    }
}

/// Under [`BoundaryInterpolation::None`], whether the faces around a vertex become holes:
/// the vertex is on a boundary or non-manifold, and one of its boundary edges was not tagged
/// infinitely sharp. `boundary_edge_tags` holds the *tagged* sharpness of its boundary edges.
pub fn faces_become_holes(
    rule: BoundaryInterpolation,
    topology: &VertexTopology,
    boundary_edge_tags: impl IntoIterator<Item = f32>,
) -> bool {
    if rule != BoundaryInterpolation::None {
        return false;
    }
    if topology.num_edges == topology.num_faces && !topology.non_manifold {
        return false;
    }
    boundary_edge_tags.into_iter().any(|s| !is_infinite(s))
}

#[cfg(test)]
mod tests {
    use super::*;
    use BoundaryInterpolation::{EdgeAndCorner, EdgeOnly, None};

    fn topo(num_faces: usize, num_edges: usize) -> VertexTopology {
        VertexTopology {
            num_faces,
            num_edges,
            non_manifold: false,
            non_manifold_edges: 0,
            boundary_edges: if num_faces < num_edges { 2 } else { 0 },
        }
    }

    #[test]
    fn boundary_edges_and_corners() {
        assert_eq!(edge_sharpness(0.5, true, false), 10.0);
        assert_eq!(edge_sharpness(0.5, false, true), 10.0);
        assert_eq!(edge_sharpness(0.5, false, false), 0.5);
        let corner = topo(1, 2);
        assert_eq!(vertex_sharpness(0.0, &corner, EdgeAndCorner), 10.0);
        assert_eq!(vertex_sharpness(0.0, &corner, EdgeOnly), 0.0);
        assert_eq!(vertex_sharpness(2.0, &corner, None), 2.0);
        assert_eq!(vertex_sharpness(0.0, &topo(2, 3), EdgeAndCorner), 0.0);
    }

    #[test]
    fn non_manifold_vertices() {
        let mut fin = topo(3, 2);
        fin.non_manifold = true;
        fin.non_manifold_edges = 2;
        // Interior non-manifold crease: not sharpened.
        assert_eq!(vertex_sharpness(0.0, &fin, EdgeOnly), 0.0);
        fin.boundary_edges = 1;
        assert_eq!(vertex_sharpness(0.0, &fin, EdgeOnly), 10.0);
        let mut bowtie = topo(2, 4);
        bowtie.non_manifold = true;
        assert_eq!(vertex_sharpness(0.0, &bowtie, EdgeOnly), 10.0);
    }

    #[test]
    fn holes_under_boundary_none() {
        let b = topo(2, 3);
        assert!(faces_become_holes(None, &b, [0.0, 0.0]));
        assert!(!faces_become_holes(None, &b, [10.0, 10.0]));
        assert!(!faces_become_holes(EdgeOnly, &b, [0.0]));
        assert!(!faces_become_holes(None, &topo(4, 4), [0.0]));
    }
}
