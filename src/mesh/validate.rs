//! What a CAD user must know about a mesh before relying on it: boundary, non-manifold
//! edges and vertices, orientation, isolated vertices, faces that repeat a vertex,
//! components and Euler characteristic.
//!
//! Built on the base [`Level`] (OpenSubdiv's topology), and using the same definitions as
//! the topology notes of the OpenSubdiv shapes' `INDEX.tsv`, so the numbers can be checked
//! against them. Edges are judged by vertex pair, uniting the separate edges OpenSubdiv
//! makes for a pair used twice by one face or for a degenerate pair:
//! - a *boundary edge* is a vertex pair used by exactly one face side;
//! - a *non-manifold edge* is a vertex pair used by more than two face sides;
//! - an *inconsistently oriented edge* is a pair used twice in the same direction (a
//!   flipped face);
//! - a degenerate pair (both ends the same vertex, from a face such as `f 4 3 5 5`) is
//!   counted by the same rules; its face is reported as repeating a vertex;
//! - a *non-manifold vertex* is one OpenSubdiv tags non-manifold: on an edge it tags
//!   non-manifold (the three kinds above and pairs used twice by one face), with faces that
//!   do not form a single fan (a bow-tie), or in no face;
//! - an *isolated vertex* is in no face (it is also a non-manifold vertex);
//! - *boundary loops* are the connected pieces of the boundary edges (two loops that
//!   touch at a vertex count as one);
//! - *components* are the pieces of the faces connected through shared vertices (isolated
//!   vertices are not counted);
//! - the *Euler characteristic* is V − E + F over all vertices, OpenSubdiv's edges and all
//!   faces.
//!
//! A mesh is *manifold* when it has no non-manifold edge or vertex, no isolated vertex and
//! no face that repeats a vertex. As OpenSubdiv tags the vertices of a flipped edge, an
//! inconsistently oriented mesh is never manifold.

use std::collections::{BTreeMap, HashMap};

use super::Mesh;
use crate::topology::Level;

/// The findings of [`check`]. Edges are given by their two vertices (in the order of
/// OpenSubdiv's first edge on that pair), vertices and faces by index; all lists are in
/// increasing order of OpenSubdiv's edge, vertex or face numbers.
#[derive(Debug, Clone, PartialEq, Eq, Default, serde::Serialize)]
pub struct MeshReport {
    /// Number of vertices, isolated ones included.
    pub num_vertices: usize,
    /// Number of edges as OpenSubdiv counts them.
    pub num_edges: usize,
    /// Number of faces.
    pub num_faces: usize,
    /// Number of faces of each size (size → count).
    pub face_sizes: BTreeMap<usize, usize>,
    /// Number of vertices of each valence, i.e. number of incident edges (valence → count).
    pub valences: BTreeMap<usize, usize>,
    /// Vertex pairs used by exactly one face side.
    pub boundary_edges: Vec<[u32; 2]>,
    /// Number of connected pieces of the boundary edges.
    pub num_boundary_loops: usize,
    /// Vertex pairs used by more than two face sides.
    pub non_manifold_edges: Vec<[u32; 2]>,
    /// Vertex pairs used twice in the same direction.
    pub inconsistent_edges: Vec<[u32; 2]>,
    /// Vertices OpenSubdiv tags non-manifold (isolated vertices included).
    pub non_manifold_vertices: Vec<u32>,
    /// Vertices in no face.
    pub isolated_vertices: Vec<u32>,
    /// Faces in which some vertex appears more than once.
    pub faces_with_repeated_vertices: Vec<u32>,
    /// Number of connected pieces of faces (joined through shared vertices).
    pub num_components: usize,
    /// V − E + F.
    pub euler_characteristic: i64,
}

impl MeshReport {
    /// No non-manifold edge or vertex, no isolated vertex, no face repeating a vertex.
    pub fn is_manifold(&self) -> bool {
        self.non_manifold_edges.is_empty()
            && self.non_manifold_vertices.is_empty()
            && self.isolated_vertices.is_empty()
            && self.faces_with_repeated_vertices.is_empty()
    }

    /// No edge is used twice in the same direction.
    pub fn is_consistently_oriented(&self) -> bool {
        self.inconsistent_edges.is_empty()
    }

    /// No boundary edge.
    pub fn is_closed(&self) -> bool {
        self.boundary_edges.is_empty()
    }
}

impl Mesh {
    /// The validation report of this mesh; see [`check`].
    pub fn check(&self) -> MeshReport {
        check(self)
    }
}

/// Examine `mesh`; see the [module documentation](self) for the definitions.
pub fn check(mesh: &Mesh) -> MeshReport {
    let level = Level::from_mesh(mesh);
    let (nv, ne, nf) = (level.num_vertices(), level.num_edges(), level.num_faces());
    let mut report = MeshReport {
        num_vertices: nv,
        num_edges: ne,
        num_faces: nf,
        euler_characteristic: nv as i64 - ne as i64 + nf as i64,
        ..Default::default()
    };
    for f in 0..nf {
        let verts = level.face_vertices(f);
        *report.face_sizes.entry(verts.len()).or_default() += 1;
        if (1..verts.len()).any(|i| verts[..i].contains(&verts[i])) {
            report.faces_with_repeated_vertices.push(f as u32);
        }
    }
    for v in 0..nv {
        *report.valences.entry(level.valence(v)).or_default() += 1;
        if level.vertex_faces(v).is_empty() {
            report.isolated_vertices.push(v as u32);
        }
        if level.is_vertex_non_manifold(v) {
            report.non_manifold_vertices.push(v as u32);
        }
    }
    for pair in edge_pairs(&level) {
        let list = match pair.sides.as_slice() {
            [_] => &mut report.boundary_edges,
            [s, t] if s == t => &mut report.inconsistent_edges,
            [_, _] => continue,
            _ => &mut report.non_manifold_edges,
        };
        list.push(pair.vertices);
    }

    let mut on_boundary = vec![false; nv];
    for &v in report.boundary_edges.iter().flatten() {
        on_boundary[v as usize] = true;
    }
    report.num_boundary_loops = count_pieces(report.boundary_edges.iter().copied(), &on_boundary);
    let in_face: Vec<bool> = (0..nv).map(|v| !level.vertex_faces(v).is_empty()).collect();
    report.num_components = count_pieces(
        (0..nf).flat_map(|f| {
            let verts = level.face_vertices(f);
            verts.iter().skip(1).map(move |&w| [verts[0], w])
        }),
        &in_face,
    );
    report
}

/// The uses of one vertex pair by face sides.
struct EdgePair {
    /// The vertices of OpenSubdiv's first edge on the pair.
    vertices: [u32; 2],
    /// The vertex each face side starts from, one entry per use.
    sides: Vec<u32>,
}

/// OpenSubdiv's edges grouped by vertex pair, in the order of each pair's first edge.
fn edge_pairs(level: &Level) -> Vec<EdgePair> {
    let mut pairs: Vec<EdgePair> = Vec::with_capacity(level.num_edges());
    let mut slot: HashMap<[u32; 2], usize> = HashMap::with_capacity(level.num_edges());
    for e in 0..level.num_edges() {
        let [a, b] = level.edge_vertices(e);
        let i = *slot.entry([a.min(b), a.max(b)]).or_insert_with(|| {
            pairs.push(EdgePair {
                vertices: [a, b],
                sides: Vec::new(),
            });
            pairs.len() - 1
        });
        let starts = level
            .edge_faces(e)
            .iter()
            .zip(level.edge_face_local_indices(e))
            .map(|(&f, &k)| level.face_vertices(f as usize)[k as usize]);
        pairs[i].sides.extend(starts);
    }
    pairs
}

/// Number of connected pieces among the vertices `v` with `counted[v]`, joined by `links`.
fn count_pieces(links: impl Iterator<Item = [u32; 2]>, counted: &[bool]) -> usize {
    let mut parent: Vec<usize> = (0..counted.len()).collect();
    for [a, b] in links {
        let (ra, rb) = (find(&mut parent, a as usize), find(&mut parent, b as usize));
        parent[ra] = rb;
    }
    (0..counted.len())
        .filter(|&v| counted[v] && find(&mut parent, v) == v)
        .count()
}

/// Union-find root of `i`, halving the path on the way.
fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

#[cfg(test)]
mod tests;
