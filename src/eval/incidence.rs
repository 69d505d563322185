//! Vertex neighbourhoods as OpenSubdiv's Vtr builds them at level 0: edges numbered on
//! first sight, non-manifold edges and vertices tagged, incident faces and edges of manifold
//! vertices ordered counter-clockwise, and the sharpness Far assigns before refinement
//! (boundary and non-manifold edges infinitely sharp, corners per the boundary rule).

use crate::mesh::Mesh;
use crate::options::{BoundaryInterpolation, SubdivOptions};

use super::rules::{self, INFINITE};

/// Level-0 topology and sharpness of a mesh, as the vertex-limit code needs it.
pub(crate) struct Incidence {
    /// End vertices of each edge.
    pub edge_verts: Vec<[u32; 2]>,
    /// Faces of each edge.
    pub edge_faces: Vec<Vec<u32>>,
    /// Edge of each face-vertex (edge from that vertex to the next in the face).
    pub face_edges: Vec<u32>,
    /// Edge sharpness after Far's sharpening.
    pub edge_sharpness: Vec<f32>,
    /// Incident edges of each vertex (counter-clockwise for manifold vertices).
    pub vert_edges: Vec<Vec<u32>>,
    /// Incident faces of each vertex (counter-clockwise for manifold vertices).
    pub vert_faces: Vec<Vec<u32>>,
    /// Vertex is non-manifold.
    pub vert_nonmanifold: Vec<bool>,
    /// Vertex sharpness after Far's sharpening.
    pub vert_sharpness: Vec<f32>,
}

impl Incidence {
    /// Build the level-0 topology of `mesh` under `options`.
    pub fn new(mesh: &Mesh, options: &SubdivOptions) -> Incidence {
        let nv = mesh.num_vertices();
        let offsets = mesh.face_offsets();
        let fv = mesh.face_indices();
        let mut inc = Incidence {
            edge_verts: Vec::new(),
            edge_faces: Vec::new(),
            face_edges: vec![0; fv.len()],
            edge_sharpness: Vec::new(),
            vert_edges: vec![Vec::new(); nv],
            vert_faces: vec![Vec::new(); nv],
            vert_nonmanifold: vec![false; nv],
            vert_sharpness: vec![0.0; nv],
        };
        let mut nonmanifold_edges = Vec::new();
        for f in 0..mesh.num_faces() {
            let (a, b) = (offsets[f] as usize, offsets[f + 1] as usize);
            let n = b - a;
            for i in 0..n {
                let (v0, v1) = (fv[a + i], fv[a + (i + 1) % n]);
                let mut edge = None;
                if v0 == v1 {
                    nonmanifold_edges.push(inc.edge_verts.len());
                } else {
                    edge = inc.find_edge(v0, v1);
                    if let Some(e) = edge {
                        let faces = &inc.edge_faces[e];
                        if *faces.last().unwrap() == f as u32 {
                            nonmanifold_edges.push(e);
                            nonmanifold_edges.push(inc.edge_verts.len());
                            edge = None;
                        } else if faces.len() > 1 || v0 == inc.edge_verts[e][0] {
                            nonmanifold_edges.push(e);
                        }
                    }
                }
                let e = edge.unwrap_or_else(|| {
                    let e = inc.edge_verts.len();
                    inc.edge_verts.push([v0, v1]);
                    inc.edge_faces.push(Vec::new());
                    inc.vert_edges[v0 as usize].push(e as u32);
                    inc.vert_edges[v1 as usize].push(e as u32);
                    e
                });
                inc.edge_faces[e].push(f as u32);
                inc.vert_faces[v0 as usize].push(f as u32);
                inc.face_edges[a + i] = e as u32;
            }
        }
        let mut edge_nonmanifold = vec![false; inc.edge_verts.len()];
        for &e in &nonmanifold_edges {
            edge_nonmanifold[e] = true;
            let [a, b] = inc.edge_verts[e];
            inc.vert_nonmanifold[a as usize] = true;
            inc.vert_nonmanifold[b as usize] = true;
        }
        for v in 0..nv {
            if !inc.vert_nonmanifold[v] {
                match inc.ordered(mesh, v as u32) {
                    Some((faces, edges)) => {
                        inc.vert_faces[v] = faces;
                        inc.vert_edges[v] = edges;
                    }
                    None => inc.vert_nonmanifold[v] = true,
                }
            }
        }
        inc.assign_sharpness(mesh, options, &edge_nonmanifold);
        inc
    }

    /// First edge joining `v0` and `v1` among `v0`'s edges (`Vtr::Level::findEdge`).
    pub fn find_edge(&self, v0: u32, v1: u32) -> Option<usize> {
        self.vert_edges[v0 as usize]
            .iter()
            .map(|&e| e as usize)
            .find(|&e| {
                let [a, b] = self.edge_verts[e];
                (a == v0 && b == v1) || (a == v1 && b == v0)
            })
    }

    /// The vertex at the other end of edge `e` from `v`.
    pub fn other_end(&self, e: u32, v: u32) -> u32 {
        let [a, b] = self.edge_verts[e as usize];
        if a == v {
            b
        } else {
            a
        }
    }

    /// Faces and edges of `v` in counter-clockwise order, or `None` if `v` is not
    /// locally manifold (`Vtr::Level::orderVertexFacesAndEdges`).
    fn ordered(&self, mesh: &Mesh, v: u32) -> Option<(Vec<u32>, Vec<u32>)> {
        let vedges = &self.vert_edges[v as usize];
        let vfaces = &self.vert_faces[v as usize];
        let (nf, ne) = (vfaces.len(), vedges.len());
        if nf == 0 || ne < 2 || ne > nf + 1 {
            return None;
        }
        let position = |f: u32| mesh.face(f as usize).iter().position(|&x| x == v).unwrap();
        let face_edge =
            |f: u32, i: usize| self.face_edges[mesh.face_offsets()[f as usize] as usize + i];
        let (mut face, mut corner, start_edge) = if ne == nf {
            let f = vfaces[0];
            let c = position(f);
            (f, c, face_edge(f, c))
        } else {
            let mut found = None;
            for &e in vedges {
                if self.edge_faces[e as usize].len() == 1 {
                    let f = self.edge_faces[e as usize][0];
                    let c = position(f);
                    found = Some((f, c, e));
                    if e == face_edge(f, c) {
                        break;
                    }
                }
            }
            found?
        };
        let mut faces = vec![face];
        let mut edges = vec![start_edge];
        let mut prev_edge = start_edge;
        while edges.len() < ne {
            let size = mesh.face_sizes()[face as usize] as usize;
            let next = face_edge(face, (corner + size - 1) % size);
            if next == prev_edge || next == start_edge {
                return None;
            }
            edges.push(next);
            if faces.len() < nf {
                let ef = &self.edge_faces[next as usize];
                if ef.is_empty() || (ef.len() == 1 && ef[0] == face) {
                    return None;
                }
                face = if ef[0] == face { ef[1] } else { ef[0] };
                let size = mesh.face_sizes()[face as usize] as usize;
                corner = (0..size).find(|&i| face_edge(face, i) == next)?;
                faces.push(face);
            }
            prev_edge = next;
        }
        Some((faces, edges))
    }

    /// Far's `prepareComponentTagsAndSharpness` for vertex data.
    fn assign_sharpness(&mut self, mesh: &Mesh, options: &SubdivOptions, nonmanifold: &[bool]) {
        self.edge_sharpness = vec![0.0; self.edge_verts.len()];
        for c in mesh.creases() {
            if let Some(e) = self.find_edge(c.vertices[0], c.vertices[1]) {
                self.edge_sharpness[e] = c.sharpness;
            }
        }
        for c in mesh.corners() {
            self.vert_sharpness[c.vertex as usize] = c.sharpness;
        }
        for e in 0..self.edge_verts.len() {
            if self.edge_faces[e].len() < 2 || nonmanifold[e] {
                self.edge_sharpness[e] = INFINITE;
            }
        }
        let sharpen_corners = options.boundary == BoundaryInterpolation::EdgeAndCorner;
        for v in 0..self.vert_edges.len() {
            let edges = &self.vert_edges[v];
            let nfaces = self.vert_faces[v].len();
            let boundary = edges
                .iter()
                .filter(|&&e| self.edge_faces[e as usize].len() < 2)
                .count();
            let nm_edges = edges.iter().filter(|&&e| nonmanifold[e as usize]).count();
            let topological_corner = nfaces == 1 && edges.len() == 2;
            if topological_corner && sharpen_corners {
                self.vert_sharpness[v] = INFINITE;
            } else if self.vert_nonmanifold[v]
                && !(nm_edges == 2 && boundary == 0 && nfaces > edges.len())
            {
                self.vert_sharpness[v] = INFINITE;
            }
        }
    }

    /// Sharpness of the edges incident to `v`, in its edge order.
    pub fn incident_sharpness(&self, v: u32) -> Vec<f32> {
        self.vert_edges[v as usize]
            .iter()
            .map(|&e| self.edge_sharpness[e as usize])
            .collect()
    }

    /// Whether `v` is infinitely sharp at level 0 (a corner forever).
    pub fn is_permanent_corner(&self, v: u32) -> bool {
        let inf_edges = self.vert_edges[v as usize]
            .iter()
            .filter(|&&e| rules::is_infinite(self.edge_sharpness[e as usize]))
            .count();
        rules::is_infinite(self.vert_sharpness[v as usize]) || inf_edges > 2
    }
}
