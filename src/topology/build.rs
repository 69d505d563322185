//! Building the base [`Level`] from a [`Mesh`], as OpenSubdiv's
//! `Far::TopologyRefinerFactory<TopologyDescriptor>` does: edges from face vertices
//! (`Vtr::Level::completeTopologyFromFaceVertices`), non-manifold detection, counter-clockwise
//! ordering around manifold vertices, local indices, then tags and sharpness under the
//! boundary rule.

use super::level::{find_edge_in, Level};
use crate::catmark::boundary;
use crate::catmark::crease::{is_sharp, vertex_rule};
use crate::control::Control;
use crate::error::Result;
use crate::mesh::Mesh;
use crate::options::{BoundaryInterpolation, SubdivOptions};

impl Level {
    /// The base level of `mesh` under the options the mesh carries (file tags, defaults for
    /// the rest).
    pub fn from_mesh(mesh: &Mesh) -> Level {
        Level::from_mesh_with_options(mesh, &mesh.options().resolve())
    }

    /// The base level of `mesh` under `options` (which decide the boundary sharpening).
    pub fn from_mesh_with_options(mesh: &Mesh, options: &SubdivOptions) -> Level {
        Level::from_mesh_ranked(mesh, options, None)
    }

    /// [`Level::from_mesh_with_options`] reporting to `control` through its passes over the
    /// faces (edges found, 0–50 %) and the vertices (counter-clockwise order, 50–80 %), then
    /// before the local indices (80 %) and the tags (90 %): a base level of a large mesh is
    /// tens of milliseconds, too long to leave a cancel request waiting.
    ///
    /// Errors: [`crate::Error::Cancelled`] from `control`.
    pub(crate) fn from_mesh_polled(
        mesh: &Mesh,
        options: &SubdivOptions,
        control: &Control,
    ) -> Result<Level> {
        let mut level = topology_from_face_vertices(
            mesh.num_vertices(),
            mesh.face_offsets(),
            mesh.face_indices(),
            *options,
            None,
            control,
        )?;
        control.report(0.9)?;
        level.assign_tags_and_sharpness(tags_of(mesh));
        control.report(1.0)?;
        Ok(level)
    }

    /// [`Level::from_mesh_with_options`] for a fragment of a larger mesh: `ranks[f]` orders
    /// the fragment's faces as that mesh orders them, so that the counter-clockwise order
    /// round an interior vertex starts at the same face as there (Far starts at the vertex's
    /// first face in face order). Chaikin creasing sums the sharpness around a vertex in that
    /// order, in `f32`, so the start shows in the last bits.
    pub fn from_mesh_ranked(mesh: &Mesh, options: &SubdivOptions, ranks: Option<&[u32]>) -> Level {
        Level::from_faces(
            mesh.num_vertices(),
            mesh.face_offsets(),
            mesh.face_indices(),
            tags_of(mesh),
            options,
            ranks,
        )
    }

    /// [`Level::from_mesh_ranked`] from flat face arrays and tags rather than a [`Mesh`]
    /// (a fragment of a refined mesh, which needs no validation again): `nv` vertices, face
    /// `f` the vertices `face_indices[face_offsets[f]..face_offsets[f + 1]]`.
    pub(crate) fn from_faces(
        nv: usize,
        face_offsets: &[u32],
        face_indices: &[u32],
        tags: Tags<impl Iterator<Item = ([u32; 2], f32)>, impl Iterator<Item = (u32, f32)>>,
        options: &SubdivOptions,
        ranks: Option<&[u32]>,
    ) -> Level {
        let mut level = topology_from_face_vertices(
            nv,
            face_offsets,
            face_indices,
            *options,
            ranks,
            &Control::NONE,
        )
        .expect("a control without a hook never cancels");
        level.assign_tags_and_sharpness(tags);
        level
    }

    /// `Vtr::Level::orderVertexFacesAndEdges`: the faces and edges around `v` in
    /// counter-clockwise order into `faces` and `edges`, and where the walk met `v` in each
    /// face into `locals` (all cleared first), or `None` if they do not form a single fan.
    fn ordered_faces_and_edges(
        &self,
        v: usize,
        ranks: Option<&[u32]>,
        faces: &mut Vec<u32>,
        edges: &mut Vec<u32>,
        locals: &mut Vec<u32>,
    ) -> Option<()> {
        let v_edges = self.vertex_edges(v);
        let v_faces = self.vertex_faces(v);
        let (fc, ec) = (v_faces.len(), v_edges.len());
        if fc == 0 || ec < 2 || ec > fc + 1 {
            return None;
        }
        let pos = |s: &[u32], x: u32| s.iter().position(|&y| y == x);
        let (mut f_start, mut e_start, mut fv_start);
        if ec == fc {
            f_start = match ranks {
                Some(r) => *v_faces.iter().min_by_key(|&&f| r[f as usize])?,
                None => v_faces[0],
            };
            fv_start = pos(self.face_vertices(f_start as usize), v as u32)?;
            e_start = self.face_edges(f_start as usize)[fv_start];
        } else {
            let mut found = None;
            for &e in v_edges {
                let ef = self.edge_faces(e as usize);
                if ef.len() == 1 {
                    let f = ef[0];
                    let fv = pos(self.face_vertices(f as usize), v as u32)?;
                    found = Some((f, e, fv));
                    // The leading boundary edge is the one that starts at `v` in its face.
                    if e == self.face_edges(f as usize)[fv] {
                        break;
                    }
                }
            }
            (f_start, e_start, fv_start) = found?;
        }
        faces.clear();
        edges.clear();
        locals.clear();
        faces.push(f_start);
        edges.push(e_start);
        locals.push(fv_start as u32);
        let e_first = e_start;
        while edges.len() < ec {
            let f_edges = self.face_edges(f_start as usize);
            let fe_next = if fv_start > 0 {
                fv_start - 1
            } else {
                f_edges.len() - 1
            };
            let e_next = f_edges[fe_next];
            if e_next == e_start || e_next == e_first {
                return None;
            }
            edges.push(e_next);
            if faces.len() < fc {
                let ef = self.edge_faces(e_next as usize);
                if ef.is_empty() || (ef.len() == 1 && ef[0] == f_start) {
                    return None;
                }
                f_start = if ef[0] == f_start { ef[1] } else { ef[0] };
                fv_start = pos(self.face_edges(f_start as usize), e_next)?;
                faces.push(f_start);
                locals.push(fv_start as u32);
            }
            e_start = e_next;
        }
        Some(())
    }

    /// The vertex-edge part of `Vtr::Level::populateLocalIndices` (the vertex-face and
    /// edge-face local indices are filled as those relations are built).
    fn populate_vertex_edge_locals(&mut self) {
        let mut ve_locals = vec![0u32; self.vert_edges.len()];
        for v in 0..self.num_vertices() {
            let r = self.vert_edge_offsets[v] as usize..self.vert_edge_offsets[v + 1] as usize;
            let first = r.start;
            for i in r {
                let e = self.vert_edges[i];
                let [a, b] = self.edge_verts[e as usize];
                ve_locals[i] = if a != b {
                    (v as u32 == b) as u32
                } else {
                    (i > first && self.vert_edges[i - 1] == e) as u32
                };
            }
        }
        self.vert_edge_locals = ve_locals;
    }

    /// Mesh tags, then Far's boundary and non-manifold sharpening, holes and vertex rules.
    fn assign_tags_and_sharpness(
        &mut self,
        tags: Tags<impl Iterator<Item = ([u32; 2], f32)>, impl Iterator<Item = (u32, f32)>>,
    ) {
        for ([a, b], s) in tags.creases {
            if let Some(e) = self.find_edge(a as usize, b as usize) {
                self.edge_sharpness[e as usize] = s;
            }
        }
        for (v, s) in tags.corners {
            self.vert_sharpness[v as usize] = s;
        }
        for &h in tags.holes {
            self.face_holes[h as usize] = true;
        }
        let rule = self.options.boundary;
        // Holes from boundary interpolation "none" look at the tagged sharpness, before the
        // boundary edges are sharpened.
        let vertices = if rule == BoundaryInterpolation::None {
            0..self.num_vertices()
        } else {
            0..0
        };
        for v in vertices {
            let topo = self.vertex_topology(v);
            let tags = self
                .vertex_edges(v)
                .iter()
                .filter(|&&e| self.edge_faces(e as usize).len() == 1)
                .map(|&e| self.edge_sharpness[e as usize]);
            if boundary::faces_become_holes(rule, &topo, tags) {
                for i in self.vert_face_offsets[v]..self.vert_face_offsets[v + 1] {
                    let f = self.vert_faces[i as usize];
                    self.face_holes[f as usize] = true;
                }
            }
        }
        for e in 0..self.num_edges() {
            self.edge_sharpness[e] = boundary::edge_sharpness(
                self.edge_sharpness[e],
                self.is_edge_boundary(e),
                self.edge_non_manifold[e],
            );
        }
        for v in 0..self.num_vertices() {
            let topo = self.vertex_topology(v);
            self.vert_sharpness[v] =
                boundary::vertex_sharpness(self.vert_sharpness[v], &topo, rule);
        }
        self.update_vertex_rules();
    }

    /// Rule of every vertex from its sharpness and the number of sharp incident edges.
    fn update_vertex_rules(&mut self) {
        self.vert_rules = (0..self.num_vertices())
            .map(|v| {
                let sharp = self
                    .vertex_edges(v)
                    .iter()
                    .filter(|&&e| is_sharp(self.edge_sharpness[e as usize]))
                    .count();
                vertex_rule(self.vert_sharpness[v], sharp)
            })
            .collect();
    }
}

/// The tags a base level is built with: crease `(edge vertices, sharpness)` pairs (a later
/// tag of the same edge wins), corner `(vertex, sharpness)` pairs and hole faces.
pub(crate) struct Tags<'a, C, V> {
    /// Edge sharpness tags.
    pub creases: C,
    /// Vertex sharpness tags.
    pub corners: V,
    /// Faces tagged as holes.
    pub holes: &'a [u32],
}

/// The crease, corner and hole tags of `mesh`.
fn tags_of(
    mesh: &Mesh,
) -> Tags<'_, impl Iterator<Item = ([u32; 2], f32)> + '_, impl Iterator<Item = (u32, f32)> + '_> {
    Tags {
        creases: mesh.creases().iter().map(|c| (c.vertices, c.sharpness)),
        corners: mesh.corners().iter().map(|c| (c.vertex, c.sharpness)),
        holes: mesh.holes(),
    }
}

/// Offsets of rows of the given lengths (`offsets[i]..offsets[i + 1]` is row `i`).
fn offsets_of(lengths: impl IntoIterator<Item = u32>) -> Vec<u32> {
    let lengths = lengths.into_iter();
    let mut offsets = Vec::with_capacity(lengths.size_hint().0 + 1);
    let mut total = 0u32;
    offsets.push(0);
    for n in lengths {
        total += n;
        offsets.push(total);
    }
    offsets
}

/// `Vtr::Level::completeTopologyFromFaceVertices`, then orientation and local indices.
///
/// Flat arrays throughout: vertex-face rows are counted first; vertex-edge rows get room for
/// two edges per incident face-vertex (the most a face-vertex can create) and are compacted
/// at the end; edge-face rows are filled once all edges are known, in the order the faces
/// met the edge. `control` is polled as [`Level::from_mesh_polled`] says (up to 80 %).
fn topology_from_face_vertices(
    nv: usize,
    face_offsets: &[u32],
    face_indices: &[u32],
    options: SubdivOptions,
    ranks: Option<&[u32]>,
    control: &Control,
) -> Result<Level> {
    let nf = face_offsets.len() - 1;
    let face_offsets = face_offsets.to_vec();
    let face_verts = face_indices.to_vec();
    let nfv = face_verts.len();
    let mut face_edges = vec![0u32; nfv];

    let mut occurrences = vec![0u32; nv];
    for &v in &face_verts {
        occurrences[v as usize] += 1;
    }
    let vert_face_offsets = offsets_of(occurrences.iter().copied());
    let mut vert_faces = vec![0u32; nfv];
    // Beside `vert_faces`: where the vertex is in each face, in face order (a face that
    // repeats the vertex gives its positions in order, as `positions_in_row` does).
    let mut vert_face_locals = vec![0u32; nfv];
    let mut repeats = false;
    let mut vf_fill: Vec<u32> = vert_face_offsets[..nv].to_vec();
    // Vertex-edge rows with room for 2 edges per face-vertex; `ve_len` used so far.
    let mut ve_room = vec![0u32; 2 * nfv];
    let mut ve_len = vec![0u32; nv];
    let ve_start = |v: u32| 2 * vert_face_offsets[v as usize] as usize;

    let mut edge_verts: Vec<[u32; 2]> = Vec::with_capacity(nfv);
    // Per edge: its number of faces so far and the last of them.
    let mut edge_num_faces: Vec<u32> = Vec::with_capacity(nfv);
    let mut edge_last_face: Vec<u32> = Vec::with_capacity(nfv);
    let mut non_manifold_edges: Vec<u32> = Vec::new();

    let faces_pass = control.stage(0.0, 0.5);
    for f in 0..nf {
        faces_pass.step(f, nf)?;
        let (start, end) = (face_offsets[f] as usize, face_offsets[f + 1] as usize);
        let n = end - start;
        for i in 0..n {
            let v0 = face_verts[start + i];
            let v1 = face_verts[start + (i + 1) % n];
            let mut edge = None;
            if v0 != v1 {
                let s0 = ve_start(v0);
                let around = &ve_room[s0..s0 + ve_len[v0 as usize] as usize];
                edge = find_edge_in(&edge_verts, around, v0, v1);
            } else {
                non_manifold_edges.push(edge_verts.len() as u32);
            }
            if let Some(e) = edge {
                let e_us = e as usize;
                if edge_last_face[e_us] == f as u32 {
                    // The edge is already in this face: a new instance.
                    non_manifold_edges.push(e);
                    non_manifold_edges.push(edge_verts.len() as u32);
                    edge = None;
                } else if edge_num_faces[e_us] > 1 || v0 == edge_verts[e_us][0] {
                    // A third face, or a second face with the same direction.
                    non_manifold_edges.push(e);
                }
            }
            let e = match edge {
                Some(e) => e,
                None => {
                    let e = edge_verts.len() as u32;
                    edge_verts.push([v0, v1]);
                    edge_num_faces.push(0);
                    edge_last_face.push(u32::MAX);
                    for end in [v0, v1] {
                        let len = &mut ve_len[end as usize];
                        ve_room[ve_start(end) + *len as usize] = e;
                        *len += 1;
                    }
                    e
                }
            };
            edge_num_faces[e as usize] += 1;
            edge_last_face[e as usize] = f as u32;
            let slot = &mut vf_fill[v0 as usize];
            repeats |= *slot > vert_face_offsets[v0 as usize]
                && vert_faces[*slot as usize - 1] == f as u32;
            vert_faces[*slot as usize] = f as u32;
            vert_face_locals[*slot as usize] = i as u32;
            *slot += 1;
            face_edges[start + i] = e;
        }
    }
    let ne = edge_verts.len();
    let edge_face_offsets = offsets_of(edge_num_faces.iter().copied());
    let mut edge_faces = vec![0u32; edge_face_offsets[ne] as usize];
    // Beside `edge_faces`: where the edge is in each face (positions in order for a face
    // that uses the edge twice, as `positions_in_row` gives them).
    let mut edge_face_locals = vec![0u32; edge_face_offsets[ne] as usize];
    let mut ef_fill: Vec<u32> = edge_face_offsets[..ne].to_vec();
    for f in 0..nf {
        let edges = &face_edges[face_offsets[f] as usize..face_offsets[f + 1] as usize];
        for (i, &e) in edges.iter().enumerate() {
            let slot = &mut ef_fill[e as usize];
            edge_faces[*slot as usize] = f as u32;
            edge_face_locals[*slot as usize] = i as u32;
            *slot += 1;
        }
    }
    let vert_edge_offsets = offsets_of(ve_len.iter().copied());
    let mut vert_edges = Vec::with_capacity(vert_edge_offsets[nv] as usize);
    for v in 0..nv as u32 {
        let s0 = ve_start(v);
        vert_edges.extend_from_slice(&ve_room[s0..s0 + ve_len[v as usize] as usize]);
    }
    let mut edge_non_manifold = vec![false; ne];
    let mut vert_non_manifold = vec![false; nv];
    for &e in &non_manifold_edges {
        edge_non_manifold[e as usize] = true;
        let [a, b] = edge_verts[e as usize];
        vert_non_manifold[a as usize] = true;
        vert_non_manifold[b as usize] = true;
    }
    let mut level = Level {
        options,
        depth: 0,
        face_offsets,
        face_verts,
        face_edges,
        face_holes: vec![false; nf],
        edge_verts,
        edge_face_offsets,
        edge_faces,
        edge_face_locals,
        edge_non_manifold,
        edge_sharpness: vec![0.0; ne],
        vert_face_offsets,
        vert_faces,
        vert_face_locals,
        vert_edge_offsets,
        vert_edges,
        vert_edge_locals: Vec::new(),
        vert_non_manifold,
        vert_sharpness: vec![0.0; nv],
        vert_rules: Vec::new(),
    };
    let (mut faces, mut edges, mut locals) = (Vec::new(), Vec::new(), Vec::new());
    let vertices_pass = control.stage(0.5, 0.8);
    for v in 0..nv {
        vertices_pass.step(v, nv)?;
        if level.vert_non_manifold[v] {
            continue;
        }
        match level.ordered_faces_and_edges(v, ranks, &mut faces, &mut edges, &mut locals) {
            Some(()) => {
                let fr =
                    level.vert_face_offsets[v] as usize..level.vert_face_offsets[v + 1] as usize;
                level.vert_faces[fr.clone()].copy_from_slice(&faces);
                // Where the walk met `v` is its position in each face unless a face repeats
                // a vertex (then the search's convention applies).
                let met_v = |(&f, &i): (&u32, &u32)| {
                    level.face_verts[level.face_offsets[f as usize] as usize + i as usize]
                        == v as u32
                };
                if repeats || !faces.iter().zip(&locals).all(met_v) {
                    positions_in_row(v as u32, &faces, &mut locals, |f| level.face_vertices(f));
                }
                level.vert_face_locals[fr].copy_from_slice(&locals);
                let er =
                    level.vert_edge_offsets[v] as usize..level.vert_edge_offsets[v + 1] as usize;
                level.vert_edges[er].copy_from_slice(&edges);
            }
            None => level.vert_non_manifold[v] = true,
        }
    }
    control.report(0.8)?;
    level.populate_vertex_edge_locals();
    Ok(level)
}

/// For each face `f` of `faces` (the faces listed for component `c`), the position of `c`
/// in `items(f)`, into `locals` (replaced). A face listed twice in a row uses the component
/// twice: the search continues past the previous position.
fn positions_in_row<'a>(
    c: u32,
    faces: &[u32],
    locals: &mut Vec<u32>,
    items: impl Fn(usize) -> &'a [u32],
) {
    locals.clear();
    let mut last: Option<u32> = None;
    for (i, &f) in faces.iter().enumerate() {
        let start = if last == Some(f) {
            locals[i - 1] as usize + 1
        } else {
            0
        };
        let list = items(f as usize);
        let at = list[start..]
            .iter()
            .position(|&x| x == c)
            .map_or(list.len(), |p| p + start);
        locals.push(at as u32);
        last = Some(f);
    }
}
