//! Small face neighbourhoods for the (face, u, v) evaluator.
//!
//! A [`Neighbourhood`] is a mesh fragment in flat arrays (faces, vertex-to-face incidence,
//! crease and corner tags) built either from a whole control mesh or as the faces around one
//! face `F`: every face that shares a vertex with it, and under Chaikin creasing also every
//! face around the far end `r` of a semi-sharp edge at a corner of `F`. That fragment is
//! exactly what one level of Catmull-Clark refinement needs to produce the face's children
//! *and their own fragments* correctly: vertex points need their vertex's faces, edge points
//! the faces of their edge and their rule, which follows the sharpness of the edge's two
//! child halves; under Chaikin the half at `r` averages the semi-sharp edges around `r`, so
//! all of `r`'s edges must be there (without them an edge point next to `F` takes the dart
//! rule instead of the crease rule, or the reverse, and the error reaches `F`'s
//! descendants a few levels down). The child fragments satisfy the same condition: the far
//! ends of semi-sharp edges at a child's corners are edge points of such edges or vertex
//! points of `F`'s corners, whose edges' sharpness comes from edges around `F`'s corners and
//! the `r`s. So the evaluator refines small fragments instead of the whole mesh. Vertices
//! and edges at the rim of a fragment come out wrong after refinement; they are never used.

use std::collections::HashMap;

use glam::DVec3;

use crate::catmark::crease::is_semi_sharp;
use crate::mesh::{Corner, Crease, Mesh, MeshParts};
use crate::options::{CreaseMethod, PartialOptions, SubdivOptions};
use crate::refine::{corners_of, creases_of_child, Refinement};
use crate::topology::{Level, Tags};

/// Largest fragment whose vertices [`Neighbourhood::around_face`] renumbers through a table
/// as long as the fragment; from a larger one (a whole control mesh, a deeply refined
/// fragment) it uses a hash map rather than fill such a table for every face.
const DENSE_REMAP_LIMIT: usize = 4096;

/// How [`Neighbourhood::cut`] renumbers the vertices of the fragment it cuts from: a table as
/// long as that fragment (all `u32::MAX` outside a cut), or a hash map for one cut from a
/// large fragment.
pub enum Remap {
    /// One entry per vertex.
    Dense(Vec<u32>),
    /// The vertices seen so far.
    Sparse(HashMap<u32, u32>),
}

impl Remap {
    fn get(&self, v: u32) -> u32 {
        match self {
            Remap::Dense(t) => t[v as usize],
            Remap::Sparse(m) => m.get(&v).copied().unwrap_or(u32::MAX),
        }
    }

    fn set(&mut self, v: u32, local: u32) {
        match self {
            Remap::Dense(t) => t[v as usize] = local,
            Remap::Sparse(m) => {
                m.insert(v, local);
            }
        }
    }
}

/// The topology of a mesh fragment with the adjacency the evaluator's patch tests need.
/// Vertex data (positions, or the evaluator's point numbers) travel beside it, one value
/// per vertex, mapped through [`Neighbourhood::around_face`]'s vertex list.
#[derive(Debug, Clone, PartialEq)]
pub struct Neighbourhood {
    face_offsets: Vec<u32>,
    face_indices: Vec<u32>,
    vf_offsets: Vec<u32>,
    vf_faces: Vec<u32>,
    /// Beside `vf_faces`: where the vertex is in each of its faces.
    vf_locals: Vec<u32>,
    /// Crease tags as ((smaller, larger) vertex index, sharpness), sorted by key, one per
    /// key; absent = 0. A sorted list, not a hash map: fragments hold a handful of tags and
    /// are built by the hundred thousand.
    edge_tags: Vec<((u32, u32), f32)>,
    /// The tags of edges whose smaller vertex is `v` are `edge_tags[tag_starts[v]..
    /// tag_starts[v + 1]]` (empty without tags): the patch test looks tags up millions of
    /// times.
    tag_starts: Vec<u32>,
    /// Corner tags, one per vertex (0 = none).
    vertex_tags: Vec<f32>,
    /// Vertices that descend from an edge point of a refinement: Far gives an edge's child
    /// vertex sharpness 0 and sharpens vertices from topology (non-manifold, boundary
    /// corner) only at the base level, so the patch tests must not sharpen these, although
    /// a fragment read as a base mesh would (the child of an edge with two faces of opposite
    /// orientation is a non-manifold vertex with as many faces as edges).
    edge_descendants: Vec<bool>,
    /// Chaikin creasing: [`Neighbourhood::around_face`] adds the faces around the far ends of
    /// semi-sharp edges at the face's corners (see the module doc).
    chaikin: bool,
    /// The order of the faces in the whole mesh refined as far as this fragment (Far's face
    /// order): refinement starts the order round each vertex where Far does (see
    /// [`crate::topology::Level::from_mesh_ranked`]).
    face_ranks: Vec<u32>,
}

/// Crease tags as a sorted list, one per edge: Far keeps the last value given for an edge,
/// and so does this (the sort is stable, and `dedup_by` keeps the first of a run, into which
/// the later value is copied).
fn sorted_edge_tags(creases: &[Crease]) -> Vec<((u32, u32), f32)> {
    let mut edge_tags: Vec<((u32, u32), f32)> = creases
        .iter()
        .map(|c| {
            let [a, b] = c.vertices;
            ((a.min(b), a.max(b)), c.sharpness)
        })
        .collect();
    edge_tags.sort_by_key(|&(key, _)| key);
    edge_tags.dedup_by(|later, first| {
        let same = later.0 == first.0;
        if same {
            first.1 = later.1;
        }
        same
    });
    edge_tags
}

/// Per-vertex corner sharpness of `nv` vertices from corner tags.
fn vertex_tags_of(nv: usize, corners: &[Corner]) -> Vec<f32> {
    let mut vertex_tags = vec![0.0f32; nv];
    for c in corners {
        vertex_tags[c.vertex as usize] = c.sharpness;
    }
    vertex_tags
}

impl Neighbourhood {
    /// The whole of `mesh` (its topology and tags; vertex `v` is control vertex `v`), to be
    /// cut into fragments for refinement under `options`.
    pub fn from_mesh(mesh: &Mesh, options: &SubdivOptions) -> Neighbourhood {
        let nv = mesh.num_vertices();
        Neighbourhood {
            chaikin: options.crease_method == CreaseMethod::Chaikin,
            face_ranks: (0..mesh.num_faces() as u32).collect(),
            ..Neighbourhood::assemble(
                nv,
                mesh.face_offsets().to_vec(),
                mesh.face_indices().to_vec(),
                sorted_edge_tags(mesh.creases()),
                vertex_tags_of(nv, mesh.corners()),
                vec![false; nv],
            )
        }
    }

    /// This fragment as a base [`Level`] under `options`, its faces ranked as the whole mesh
    /// ranks them, to be refined by [`crate::refine::refine`].
    pub fn level(&self, options: &SubdivOptions) -> Level {
        let creases = self.edge_tags.iter().map(|&((a, b), s)| ([a, b], s));
        let corners = (0..self.num_vertices() as u32)
            .map(|v| (v, self.vertex_tags[v as usize]))
            .filter(|&(_, s)| s > 0.0);
        let tags = Tags {
            creases,
            corners,
            holes: &[],
        };
        Level::from_faces(
            self.num_vertices(),
            &self.face_offsets,
            &self.face_indices,
            tags,
            options,
            Some(&self.face_ranks),
        )
    }

    /// The child of `self` after refinement `r` of `level` (a level of `self`: its
    /// [`Neighbourhood::level`], or a refined level of the same fragment, as deep as `self`),
    /// vertices in Far's default order (children of vertices, of faces, then of edges),
    /// keeping track of which vertices descend from edge points. Tags are the child's
    /// sharpness less what Far derives from topology, which a fragment read as a base level
    /// derives again: the creases of sharp edge halves, the sharp vertices that their parent
    /// vertex's topology did not sharpen.
    pub fn refined(&self, level: &Level, r: &Refinement) -> Neighbourhood {
        let child = &r.child;
        let nv = child.num_vertices();
        let boundary = level.options().boundary;
        let sharpened = |cv: usize| {
            r.child_vertex_parent_vertex(cv)
                .is_some_and(|v| level.vertex_topology(v).is_sharpened(boundary))
        };
        let mut nb = Neighbourhood {
            chaikin: self.chaikin,
            face_ranks: vec![0; child.num_faces()],
            ..Neighbourhood::assemble(
                nv,
                child.face_offsets.clone(),
                child.face_verts.clone(),
                sorted_edge_tags(&creases_of_child(level, r)),
                vertex_tags_of(nv, &corners_of(child, sharpened)),
                vec![false; nv],
            )
        };
        let parent_nv = self.num_vertices();
        nb.edge_descendants[..parent_nv].copy_from_slice(&self.edge_descendants);
        nb.edge_descendants[parent_nv + self.num_faces()..].fill(true);
        // Far numbers the children of the faces in face order: those of a face come after
        // the children of every face ranked before it.
        let mut by_rank: Vec<u32> = (0..self.num_faces() as u32).collect();
        by_rank.sort_unstable_by_key(|&f| self.face_ranks[f as usize]);
        let mut first_child = vec![0u32; self.num_faces()];
        let mut next = 0u32;
        for &f in &by_rank {
            first_child[f as usize] = next;
            next += self.face(f).len() as u32;
        }
        let mut c = 0;
        for f in 0..self.num_faces() as u32 {
            for j in 0..self.face(f).len() as u32 {
                nb.face_ranks[c] = first_child[f as usize] + j;
                c += 1;
            }
        }
        nb
    }

    fn assemble(
        nv: usize,
        face_offsets: Vec<u32>,
        face_indices: Vec<u32>,
        edge_tags: Vec<((u32, u32), f32)>,
        vertex_tags: Vec<f32>,
        edge_descendants: Vec<bool>,
    ) -> Neighbourhood {
        let mut vf_offsets = vec![0u32; nv + 1];
        for &v in &face_indices {
            vf_offsets[v as usize + 1] += 1;
        }
        for i in 0..nv {
            vf_offsets[i + 1] += vf_offsets[i];
        }
        let mut fill = vf_offsets.clone();
        let mut vf_faces = vec![0u32; face_indices.len()];
        let mut vf_locals = vec![0u32; face_indices.len()];
        for f in 0..face_offsets.len() - 1 {
            let face = &face_indices[face_offsets[f] as usize..face_offsets[f + 1] as usize];
            for (i, &v) in face.iter().enumerate() {
                let slot = &mut fill[v as usize];
                // A face that repeats a vertex is listed once per occurrence, the occurrences
                // next to each other; the patch tests treat such vertices as irregular.
                vf_faces[*slot as usize] = f as u32;
                vf_locals[*slot as usize] = i as u32;
                *slot += 1;
            }
        }
        let mut tag_starts = Vec::new();
        if !edge_tags.is_empty() {
            tag_starts = vec![0u32; nv + 1];
            for &((a, _), _) in &edge_tags {
                tag_starts[a as usize + 1] += 1;
            }
            for i in 0..nv {
                tag_starts[i + 1] += tag_starts[i];
            }
        }
        Neighbourhood {
            face_offsets,
            face_indices,
            vf_offsets,
            vf_faces,
            vf_locals,
            edge_tags,
            tag_starts,
            vertex_tags,
            edge_descendants,
            chaikin: false,
            face_ranks: Vec::new(),
        }
    }

    /// Number of vertices.
    pub fn num_vertices(&self) -> usize {
        self.vertex_tags.len()
    }

    /// Number of faces.
    pub fn num_faces(&self) -> usize {
        self.face_offsets.len() - 1
    }

    /// Vertices of face `f`.
    #[inline]
    pub fn face(&self, f: u32) -> &[u32] {
        &self.face_indices
            [self.face_offsets[f as usize] as usize..self.face_offsets[f as usize + 1] as usize]
    }

    /// Where face `f`'s vertices start in the list of all faces' vertices: the index of its
    /// first child face after refinement (children follow their parent's corners).
    #[inline]
    pub fn face_offset(&self, f: u32) -> u32 {
        self.face_offsets[f as usize]
    }

    /// Faces incident to vertex `v` (a face repeating `v` appears once per occurrence).
    #[inline]
    pub fn vertex_faces(&self, v: u32) -> &[u32] {
        &self.vf_faces
            [self.vf_offsets[v as usize] as usize..self.vf_offsets[v as usize + 1] as usize]
    }

    /// For each face of [`Neighbourhood::vertex_faces`], the position of `v` in it (each
    /// occurrence of `v` in a face that repeats it, in order).
    #[inline]
    pub fn vertex_face_locals(&self, v: u32) -> &[u32] {
        &self.vf_locals
            [self.vf_offsets[v as usize] as usize..self.vf_offsets[v as usize + 1] as usize]
    }

    /// The crease tag of edge `(a, b)` (0 when untagged).
    #[inline]
    pub fn edge_tag(&self, a: u32, b: u32) -> f32 {
        if self.edge_tags.is_empty() {
            return 0.0;
        }
        let (lo, hi) = (a.min(b), a.max(b));
        let from = self.tag_starts[lo as usize] as usize;
        let to = self.tag_starts[lo as usize + 1] as usize;
        self.edge_tags[from..to]
            .iter()
            .find(|&&((_, x), _)| x == hi)
            .map_or(0.0, |&(_, s)| s)
    }

    /// The corner tag of vertex `v` (0 when untagged).
    #[inline]
    pub fn vertex_tag(&self, v: u32) -> f32 {
        self.vertex_tags[v as usize]
    }

    /// Whether vertex `v` descends from an edge point of a refinement (see the field).
    #[inline]
    pub fn is_edge_descendant(&self, v: u32) -> bool {
        self.edge_descendants[v as usize]
    }

    /// The faces sharing a vertex with face `f` (under Chaikin creasing also those around the
    /// far ends of semi-sharp edges at `f`'s corners), as a new fragment whose face 0 is `f`
    /// and whose vertices 0..n are `f`'s vertices in order, with the vertex of `self` each
    /// of its vertices is.
    pub fn around_face(&self, f: u32) -> (Neighbourhood, Vec<u32>) {
        let mut faces = Vec::new();
        self.faces_around(f, &mut faces);
        let mut remap = if self.num_vertices() <= DENSE_REMAP_LIMIT {
            Remap::Dense(vec![u32::MAX; self.num_vertices()])
        } else {
            Remap::Sparse(HashMap::new())
        };
        self.cut(&faces, &mut remap)
    }

    /// Replace `faces` with `f` and the faces [`Neighbourhood::around_face`] cuts out with
    /// it, `f` first.
    pub fn faces_around(&self, f: u32, faces: &mut Vec<u32>) {
        faces.clear();
        faces.push(f);
        let corners = self.face(f);
        for &v in corners {
            self.add_faces_around(v, faces);
        }
        if self.chaikin && !self.edge_tags.is_empty() {
            for &c in corners {
                for &g in self.vertex_faces(c) {
                    let face = self.face(g);
                    let n = face.len();
                    for (i, &x) in face.iter().enumerate() {
                        if x != c {
                            continue;
                        }
                        for r in [face[(i + 1) % n], face[(i + n - 1) % n]] {
                            if !corners.contains(&r) && is_semi_sharp(self.edge_tag(c, r)) {
                                self.add_faces_around(r, faces);
                            }
                        }
                    }
                }
            }
        }
    }

    /// Faces `faces` of `self` as a new fragment, in that order, with the vertex of `self`
    /// each of its vertices is (numbered in order of first use). `remap` maps vertices of
    /// `self` to the fragment's while cutting; a dense one is all `u32::MAX` before and after.
    pub fn cut(&self, faces: &[u32], remap: &mut Remap) -> (Neighbourhood, Vec<u32>) {
        let mut globals: Vec<u32> = Vec::with_capacity(faces.len() * 2 + 4);
        let mut vertex_tags = Vec::with_capacity(faces.len() * 2 + 4);
        let mut edge_descendants = Vec::with_capacity(faces.len() * 2 + 4);
        let mut face_offsets = Vec::with_capacity(faces.len() + 1);
        let mut face_indices = Vec::with_capacity(faces.len() * 4);
        face_offsets.push(0u32);
        for &g in faces {
            for &v in self.face(g) {
                let known = remap.get(v);
                let local = if known != u32::MAX {
                    known
                } else {
                    let local = globals.len() as u32;
                    remap.set(v, local);
                    globals.push(v);
                    vertex_tags.push(self.vertex_tags[v as usize]);
                    edge_descendants.push(self.edge_descendants[v as usize]);
                    local
                };
                face_indices.push(local);
            }
            face_offsets.push(face_indices.len() as u32);
        }
        if let Remap::Dense(table) = remap {
            for &v in &globals {
                table[v as usize] = u32::MAX;
            }
        }
        let mut edge_tags = Vec::new();
        if !self.edge_tags.is_empty() {
            for w in face_offsets.windows(2) {
                let face = &face_indices[w[0] as usize..w[1] as usize];
                for (i, &a) in face.iter().enumerate() {
                    let b = face[(i + 1) % face.len()];
                    let s = self.edge_tag(globals[a as usize], globals[b as usize]);
                    if s > 0.0 {
                        edge_tags.push(((a.min(b), a.max(b)), s));
                    }
                }
            }
            // An interior edge is seen from both its faces, with the same tag.
            edge_tags.sort_unstable_by_key(|&(key, _)| key);
            edge_tags.dedup_by_key(|&mut (key, _)| key);
        }
        let nb = Neighbourhood {
            chaikin: self.chaikin,
            face_ranks: faces.iter().map(|&g| self.face_ranks[g as usize]).collect(),
            ..Neighbourhood::assemble(
                globals.len(),
                face_offsets,
                face_indices,
                edge_tags,
                vertex_tags,
                edge_descendants,
            )
        };
        (nb, globals)
    }

    /// Append the faces around `v` that `faces` does not hold yet.
    fn add_faces_around(&self, v: u32, faces: &mut Vec<u32>) {
        for &g in self.vertex_faces(v) {
            if !faces.contains(&g) {
                faces.push(g);
            }
        }
    }

    /// This fragment with `positions` (one per vertex) as a [`Mesh`] with `options`
    /// attached. Not validated again: a fragment is cut from a valid mesh (its faces, and
    /// only the tags of its own edges), which `from_parts` accepts (checked in debug builds).
    pub fn to_mesh(&self, options: &SubdivOptions, positions: &[DVec3]) -> Mesh {
        let creases: Vec<Crease> = self
            .edge_tags
            .iter()
            .map(|&((a, b), s)| Crease {
                vertices: [a, b],
                sharpness: s,
            })
            .collect();
        let corners = self
            .vertex_tags
            .iter()
            .enumerate()
            .filter(|(_, &s)| s > 0.0)
            .map(|(v, &s)| Corner {
                vertex: v as u32,
                sharpness: s,
            })
            .collect();
        let face_sizes = self.face_offsets.windows(2).map(|w| w[1] - w[0]).collect();
        let parts = MeshParts {
            positions: positions.to_vec(),
            face_sizes,
            face_indices: self.face_indices.clone(),
            creases,
            corners,
            holes: Vec::new(),
            options: PartialOptions {
                boundary: Some(options.boundary),
                crease_method: Some(options.crease_method),
                triangles: Some(options.triangles),
            },
        };
        debug_assert!(Mesh::from_parts(parts.clone()).is_ok());
        Mesh::from_trusted_parts(parts, self.face_offsets.clone())
    }
}
