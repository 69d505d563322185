//! [`Level`]: one level of a subdivision hierarchy as flat adjacency arrays, with OpenSubdiv
//! Vtr's component order and Far's sharpness.

use crate::catmark::boundary::VertexTopology;
use crate::catmark::Rule;
use crate::options::SubdivOptions;

/// A mesh level: faces, edges and vertices with all six incidence relations, sharpness and
/// vertex rules (`Vtr::internal::Level`).
///
/// Component order is OpenSubdiv's: at the base level, edges are numbered as
/// `Level::completeTopologyFromFaceVertices` creates them (faces in order, each face's edges
/// in order, a new edge on first sight; an edge that is degenerate or already used by the same
/// face gets a new instance). The faces and edges around a manifold vertex are in
/// counter-clockwise order, starting as Vtr starts (first face for an interior vertex, the
/// leading boundary edge for a boundary vertex); around non-manifold vertices they stay in the
/// order they were met. Refined levels follow Vtr's `QuadRefinement` order (see
/// [`crate::refine`]).
///
/// Sharpness is the one Far refines with: tags from the mesh, with boundary and non-manifold
/// edges and vertices sharpened as [`crate::catmark::boundary`] describes.
#[derive(Debug, Clone, PartialEq)]
pub struct Level {
    pub(crate) options: SubdivOptions,
    pub(crate) depth: u32,

    pub(crate) face_offsets: Vec<u32>,
    pub(crate) face_verts: Vec<u32>,
    pub(crate) face_edges: Vec<u32>,
    pub(crate) face_holes: Vec<bool>,

    pub(crate) edge_verts: Vec<[u32; 2]>,
    pub(crate) edge_face_offsets: Vec<u32>,
    pub(crate) edge_faces: Vec<u32>,
    pub(crate) edge_face_locals: Vec<u32>,
    pub(crate) edge_non_manifold: Vec<bool>,
    pub(crate) edge_sharpness: Vec<f32>,

    pub(crate) vert_face_offsets: Vec<u32>,
    pub(crate) vert_faces: Vec<u32>,
    pub(crate) vert_face_locals: Vec<u32>,
    pub(crate) vert_edge_offsets: Vec<u32>,
    pub(crate) vert_edges: Vec<u32>,
    pub(crate) vert_edge_locals: Vec<u32>,
    pub(crate) vert_non_manifold: Vec<bool>,
    pub(crate) vert_sharpness: Vec<f32>,
    pub(crate) vert_rules: Vec<Rule>,
}

fn range(offsets: &[u32], i: usize) -> std::ops::Range<usize> {
    offsets[i] as usize..offsets[i + 1] as usize
}

impl Level {
    /// The options this level was built and is refined with.
    pub fn options(&self) -> &SubdivOptions {
        &self.options
    }
    /// Refinement depth: 0 for the base level.
    pub fn depth(&self) -> u32 {
        self.depth
    }
    /// Number of vertices.
    pub fn num_vertices(&self) -> usize {
        self.vert_sharpness.len()
    }
    /// Number of edges.
    pub fn num_edges(&self) -> usize {
        self.edge_verts.len()
    }
    /// Number of faces.
    pub fn num_faces(&self) -> usize {
        self.face_offsets.len() - 1
    }
    /// Total number of face-vertex indices.
    pub fn num_face_vertices_total(&self) -> usize {
        self.face_verts.len()
    }

    /// Vertices of face `f`, in order. Panics if `f` is out of range (as do all queries).
    pub fn face_vertices(&self, f: usize) -> &[u32] {
        &self.face_verts[range(&self.face_offsets, f)]
    }
    /// Edges of face `f`: edge `i` joins face vertices `i` and `i + 1`.
    pub fn face_edges(&self, f: usize) -> &[u32] {
        &self.face_edges[range(&self.face_offsets, f)]
    }
    /// Offset of face `f`'s first vertex in the flat face-vertex array.
    pub fn face_offset(&self, f: usize) -> usize {
        self.face_offsets[f] as usize
    }
    /// Whether face `f` is a hole (tagged, or excluded by boundary interpolation *none*).
    pub fn is_face_hole(&self, f: usize) -> bool {
        self.face_holes[f]
    }

    /// The two vertices of edge `e` (in the order the edge was first met).
    pub fn edge_vertices(&self, e: usize) -> [u32; 2] {
        self.edge_verts[e]
    }
    /// Faces incident to edge `e`.
    pub fn edge_faces(&self, e: usize) -> &[u32] {
        &self.edge_faces[range(&self.edge_face_offsets, e)]
    }
    /// For each face of [`Level::edge_faces`], the position of edge `e` in that face.
    pub fn edge_face_local_indices(&self, e: usize) -> &[u32] {
        &self.edge_face_locals[range(&self.edge_face_offsets, e)]
    }
    /// Whether edge `e` has fewer than two faces.
    pub fn is_edge_boundary(&self, e: usize) -> bool {
        self.edge_face_offsets[e + 1] - self.edge_face_offsets[e] < 2
    }
    /// Whether edge `e` is non-manifold (more than two faces, degenerate, repeated in a face,
    /// or used in the same direction by two faces).
    pub fn is_edge_non_manifold(&self, e: usize) -> bool {
        self.edge_non_manifold[e]
    }
    /// Sharpness of edge `e`.
    pub fn edge_sharpness(&self, e: usize) -> f32 {
        self.edge_sharpness[e]
    }

    /// Faces incident to vertex `v` (counter-clockwise for a manifold vertex).
    pub fn vertex_faces(&self, v: usize) -> &[u32] {
        &self.vert_faces[range(&self.vert_face_offsets, v)]
    }
    /// For each face of [`Level::vertex_faces`], the position of `v` in that face.
    pub fn vertex_face_local_indices(&self, v: usize) -> &[u32] {
        &self.vert_face_locals[range(&self.vert_face_offsets, v)]
    }
    /// Edges incident to vertex `v` (counter-clockwise for a manifold vertex, the edge
    /// leading each face of [`Level::vertex_faces`] first).
    pub fn vertex_edges(&self, v: usize) -> &[u32] {
        &self.vert_edges[range(&self.vert_edge_offsets, v)]
    }
    /// For each edge of [`Level::vertex_edges`], which end of the edge `v` is (0 or 1).
    pub fn vertex_edge_local_indices(&self, v: usize) -> &[u32] {
        &self.vert_edge_locals[range(&self.vert_edge_offsets, v)]
    }
    /// Number of edges incident to vertex `v`.
    pub fn valence(&self, v: usize) -> usize {
        (self.vert_edge_offsets[v + 1] - self.vert_edge_offsets[v]) as usize
    }
    /// Whether vertex `v` has an incident boundary edge.
    pub fn is_vertex_boundary(&self, v: usize) -> bool {
        self.vertex_edges(v)
            .iter()
            .any(|&e| self.is_edge_boundary(e as usize))
    }
    /// Whether vertex `v` is non-manifold (on a non-manifold edge, or its faces do not form
    /// one fan).
    pub fn is_vertex_non_manifold(&self, v: usize) -> bool {
        self.vert_non_manifold[v]
    }
    /// Sharpness of vertex `v`.
    pub fn vertex_sharpness(&self, v: usize) -> f32 {
        self.vert_sharpness[v]
    }
    /// Subdivision rule of vertex `v`, from its sharpness and its sharp edges.
    pub fn vertex_rule(&self, v: usize) -> Rule {
        self.vert_rules[v]
    }
    /// The topology of vertex `v` as the boundary rules see it.
    pub fn vertex_topology(&self, v: usize) -> VertexTopology {
        let edges = self.vertex_edges(v);
        VertexTopology {
            num_faces: self.vertex_faces(v).len(),
            num_edges: edges.len(),
            non_manifold: self.vert_non_manifold[v],
            non_manifold_edges: edges
                .iter()
                .filter(|&&e| self.edge_non_manifold[e as usize])
                .count(),
            boundary_edges: edges
                .iter()
                .filter(|&&e| self.is_edge_boundary(e as usize))
                .count(),
        }
    }

    /// The first edge around `v0` (in [`Level::vertex_edges`] order) joining it to `v1`; for
    /// `v0 == v1`, the first degenerate edge at `v0` (`Vtr::Level::findEdge`).
    pub fn find_edge(&self, v0: usize, v1: usize) -> Option<u32> {
        find_edge_in(
            &self.edge_verts,
            self.vertex_edges(v0),
            v0 as u32,
            v1 as u32,
        )
    }
}

/// `Level::findEdge` over a given list of edges around `v0`.
pub(crate) fn find_edge_in(
    edge_verts: &[[u32; 2]],
    v0_edges: &[u32],
    v0: u32,
    v1: u32,
) -> Option<u32> {
    v0_edges.iter().copied().find(|&e| {
        let [a, b] = edge_verts[e as usize];
        if v0 != v1 {
            a == v1 || b == v1
        } else {
            a == b
        }
    })
}
