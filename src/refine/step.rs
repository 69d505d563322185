//! One level of uniform Catmull-Clark refinement of the topology and sharpness
//! (`Vtr::internal::QuadRefinement` + `Vtr::internal::Refinement`).
//!
//! Child components and their order:
//! - faces: one quad per parent face-vertex, parent face after parent face (child `j` of face
//!   `f` holds the corner at face vertex `j`);
//! - edges: first one per parent face-vertex (from the face point to the edge point of face
//!   edge `j`), then two per parent edge (child `j` ends at the child of edge vertex `j`);
//! - vertices: children of parent vertices, then of faces, then of edges
//!   ([`VertexOrder::VerticesFirst`], Far's default), or faces, edges, vertices
//!   ([`VertexOrder::FacesFirst`], Far's `orderVerticesFromFacesFirst`).
//!
//! The child's incidence lists are filled in Vtr's order, which fixes the order in which
//! later levels sum their weights.

use super::super::topology::Level;
use super::ranges::fill_pass;
use crate::catmark::crease::{
    is_infinite, is_semi_sharp, is_sharp, subdivide_edge_sharpness_at_vertex,
    subdivide_vertex_sharpness, vertex_rule, SHARPNESS_INFINITE,
};
use crate::catmark::Rule;
use crate::control::Control;
use crate::error::Result;

/// Order of the child vertices in a refined level.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum VertexOrder {
    /// Children of vertices, then of faces, then of edges (Far's default).
    #[default]
    VerticesFirst,
    /// Children of faces, then of edges, then of vertices.
    FacesFirst,
}

/// A parent level refined once: the child [`Level`] and the parent-to-child index maps.
#[derive(Debug, Clone, PartialEq)]
pub struct Refinement {
    /// The refined level.
    pub child: Level,
    order: VertexOrder,
    parent_counts: [u32; 4],
}

impl Refinement {
    /// The vertex order of the child.
    pub fn order(&self) -> VertexOrder {
        self.order
    }
    fn first_from_vertices(&self) -> u32 {
        let [_, nf, ne, _] = self.parent_counts;
        match self.order {
            VertexOrder::VerticesFirst => 0,
            VertexOrder::FacesFirst => nf + ne,
        }
    }
    fn first_from_faces(&self) -> u32 {
        match self.order {
            VertexOrder::VerticesFirst => self.parent_counts[0],
            VertexOrder::FacesFirst => 0,
        }
    }
    fn first_from_edges(&self) -> u32 {
        let [nv, nf, _, _] = self.parent_counts;
        match self.order {
            VertexOrder::VerticesFirst => nv + nf,
            VertexOrder::FacesFirst => nf,
        }
    }
    /// Child vertex of parent vertex `v`.
    pub fn vertex_child_vertex(&self, v: usize) -> u32 {
        self.first_from_vertices() + v as u32
    }
    /// The parent vertex of child vertex `cv`, if `cv` is the child of a vertex.
    pub fn child_vertex_parent_vertex(&self, cv: usize) -> Option<usize> {
        let v = cv.checked_sub(self.first_from_vertices() as usize)?;
        (v < self.parent_counts[0] as usize).then_some(v)
    }
    /// Child vertex (face point) of parent face `f`.
    pub fn face_child_vertex(&self, f: usize) -> u32 {
        self.first_from_faces() + f as u32
    }
    /// Child vertex (edge point) of parent edge `e`.
    pub fn edge_child_vertex(&self, e: usize) -> u32 {
        self.first_from_edges() + e as u32
    }
    /// Child face `j` of parent face `f` (the quad at its face vertex `j`), given `f`'s
    /// offset in the parent's face-vertex array.
    pub fn face_child_face(parent: &Level, f: usize, j: usize) -> u32 {
        (parent.face_offset(f) + j) as u32
    }
    /// Child edge `j` of parent edge `e` (the half at edge vertex `j`).
    pub fn edge_child_edge(&self, e: usize, j: usize) -> u32 {
        self.parent_counts[3] + 2 * e as u32 + j as u32
    }
}

/// Rows of an incidence relation with local indices, appended one row at a time.
#[derive(Default)]
struct Rows {
    offsets: Vec<u32>,
    members: Vec<u32>,
    locals: Vec<u32>,
}

impl Rows {
    fn with_capacity(rows: usize, members: usize) -> Rows {
        let mut offsets = Vec::with_capacity(rows + 1);
        offsets.push(0);
        Rows {
            offsets,
            members: Vec::with_capacity(members),
            locals: Vec::with_capacity(members),
        }
    }
    fn push(&mut self, member: u32, local: u32) {
        self.members.push(member);
        self.locals.push(local);
    }
    fn end_row(&mut self) {
        self.offsets.push(self.members.len() as u32);
    }
}

/// Refine `parent` once (uniformly), with child vertices in `order`, on the calling thread
/// (the evaluators call this within their own threads).
pub fn refine(parent: &Level, order: VertexOrder) -> Refinement {
    refine_polled(parent, order, true, &one_thread()).expect(NEVER_CANCELLED)
}

/// A control without hook, on the calling thread only.
fn one_thread() -> Control {
    Control::NONE.with_threads(1)
}

/// What a refinement without a progress hook cannot fail with.
const NEVER_CANCELLED: &str = "a control without a hook never cancels";

/// [`refine`] with only the child's face-vertices, sharpness and rules (Far's "minimal
/// topology" for the last level): enough to interpolate into the child and to write its
/// faces out, not to query its edges' or vertices' neighbourhoods or refine it further.
pub(crate) fn refine_last(parent: &Level, order: VertexOrder) -> Refinement {
    refine_polled(parent, order, false, &one_thread()).expect(NEVER_CANCELLED)
}

/// [`refine`] (`full`) or [`refine_last`] reporting to `control` through each pass over the
/// parent's faces and edges, the child faces on `control`'s threads (the rest on the calling
/// thread).
///
/// Errors: [`crate::Error::Cancelled`] from `control`.
pub(crate) fn refine_polled(
    parent: &Level,
    order: VertexOrder,
    full: bool,
    control: &Control,
) -> Result<Refinement> {
    let nv = parent.num_vertices();
    let nf = parent.num_faces();
    let ne = parent.num_edges();
    let nfv = parent.num_face_vertices_total();
    let mut r = Refinement {
        child: Level {
            options: parent.options,
            depth: parent.depth + 1,
            face_offsets: Vec::new(),
            face_verts: Vec::new(),
            face_edges: Vec::new(),
            face_holes: Vec::new(),
            edge_verts: Vec::new(),
            edge_face_offsets: Vec::new(),
            edge_faces: Vec::new(),
            edge_face_locals: Vec::new(),
            edge_non_manifold: Vec::new(),
            edge_sharpness: Vec::new(),
            vert_face_offsets: Vec::new(),
            vert_faces: Vec::new(),
            vert_face_locals: Vec::new(),
            vert_edge_offsets: Vec::new(),
            vert_edges: Vec::new(),
            vert_edge_locals: Vec::new(),
            vert_non_manifold: Vec::new(),
            vert_sharpness: Vec::new(),
            vert_rules: Vec::new(),
        },
        order,
        parent_counts: [nv as u32, nf as u32, ne as u32, nfv as u32],
    };
    // Rough shares of the passes' time: they only place the reports within the stage.
    let [faces, sharpness, relations] = if full {
        [0.25, 0.35, 0.9]
    } else {
        [0.5, 0.8, 0.8]
    };
    let child = build_faces(parent, &r, full, &control.stage(0.0, faces))?;
    r.child.face_offsets = child.0;
    r.child.face_verts = child.1;
    r.child.face_edges = child.2;
    r.child.face_holes = child.3;
    build_edge_sharpness(parent, &mut r, &control.stage(faces, sharpness))?;
    build_vertices(parent, &mut r);
    if full {
        let half = (sharpness + relations) / 2.0;
        build_edge_relations(parent, &mut r, &control.stage(sharpness, half))?;
        build_vertex_relations(parent, &mut r, &control.stage(half, relations))?;
    }
    control.report(relations)?;
    r.child.vert_rules = child_rules(parent, &r);
    Ok(r)
}

/// Rules of the child vertices from the parent, as Vtr propagates them: face points are
/// smooth; an edge point follows the sharp halves of its edge; a vertex's child keeps a smooth
/// parent's rule and otherwise counts its sharp child edges. (The same as classifying each
/// child vertex from its own edges, without needing the child's vertex-edge relation.)
fn child_rules(parent: &Level, r: &Refinement) -> Vec<Rule> {
    let child = &r.child;
    let mut rules = vec![Rule::Smooth; child.num_vertices()];
    for v in 0..parent.num_vertices() {
        if parent.vertex_rule(v) == Rule::Smooth {
            continue;
        }
        let sharp = parent
            .vertex_edges(v)
            .iter()
            .zip(parent.vertex_edge_local_indices(v))
            .filter(|&(&e, &k)| {
                is_sharp(child.edge_sharpness(r.edge_child_edge(e as usize, k as usize) as usize))
            })
            .count();
        let cv = r.vertex_child_vertex(v) as usize;
        rules[cv] = vertex_rule(child.vertex_sharpness(cv), sharp);
    }
    for e in 0..parent.num_edges() {
        if parent.edge_sharpness(e) <= 0.0 {
            continue;
        }
        let sharp = (0..2)
            .filter(|&j| is_sharp(child.edge_sharpness(r.edge_child_edge(e, j) as usize)))
            .count();
        rules[r.edge_child_vertex(e) as usize] = vertex_rule(0.0, sharp);
    }
    rules
}

type FaceArrays = (Vec<u32>, Vec<u32>, Vec<u32>, Vec<bool>);

/// Child face-vertices and face-edges (`populateFaceVerticesFromParentFaces`,
/// `populateFaceEdgesFromParentFaces`) and hole tags. The child faces are filled in
/// contiguous ranges on `control`'s threads, each from its parent face alone.
fn build_faces(
    parent: &Level,
    r: &Refinement,
    with_edges: bool,
    control: &Control,
) -> Result<FaceArrays> {
    let nfv = parent.num_face_vertices_total();
    let offsets: Vec<u32> = (0..=nfv as u32).map(|i| 4 * i).collect();
    let (first_v, first_f, first_e) = (
        r.vertex_child_vertex(0),
        r.face_child_vertex(0),
        r.edge_child_vertex(0),
    );
    let share = if with_edges { 0.5 } else { 1.0 };
    // Order within the child quad: for a parent quad, rotated so that the corner vertex
    // keeps its position j (slot k holds (j + k) mod 4); otherwise corner first.
    let rotation = |n: usize, j: usize| if n == 4 { j } else { 0 };
    let mut verts = vec![[0u32; 4]; nfv];
    fill_pass(&mut verts, &control.stage(0.0, share), |cursor, c| {
        let (f, j) = parent_face(parent, cursor, c);
        let fv = parent.face_vertices(f);
        let fe = parent.face_edges(f);
        let n = fv.len();
        let j_prev = if j > 0 { j - 1 } else { n - 1 };
        let rot = rotation(n, j);
        let mut quad = [0u32; 4];
        quad[rot] = first_v + fv[j];
        quad[(rot + 1) & 3] = first_e + fe[j];
        quad[(rot + 2) & 3] = first_f + f as u32;
        quad[(rot + 3) & 3] = first_e + fe[j_prev];
        quad
    })?;
    let mut edges = vec![[0u32; 4]; if with_edges { nfv } else { 0 }];
    fill_pass(&mut edges, &control.stage(share, 1.0), |cursor, c| {
        let (f, j) = parent_face(parent, cursor, c);
        let fv = parent.face_vertices(f);
        let fe = parent.face_edges(f);
        let n = fv.len();
        let j_prev = if j > 0 { j - 1 } else { n - 1 };
        let corner = fv[j];
        let prev = parent.edge_vertices(fe[j_prev] as usize);
        let next = parent.edge_vertices(fe[j] as usize);
        let corner_in_prev = if prev[0] != prev[1] {
            (prev[0] != corner) as usize
        } else {
            1
        };
        let corner_in_next = if next[0] != next[1] {
            (next[0] != corner) as usize
        } else {
            0
        };
        let rot = rotation(n, j);
        let mut quad = [0u32; 4];
        quad[rot] = r.edge_child_edge(fe[j] as usize, corner_in_next);
        quad[(rot + 1) & 3] = c as u32;
        quad[(rot + 2) & 3] = (c - j + j_prev) as u32;
        quad[(rot + 3) & 3] = r.edge_child_edge(fe[j_prev] as usize, corner_in_prev);
        quad
    })?;
    let mut holes = vec![false; nfv];
    for f in 0..parent.num_faces() {
        if parent.is_face_hole(f) {
            let base = parent.face_offset(f);
            holes[base..base + parent.face_vertices(f).len()].fill(true);
        }
    }
    Ok((
        offsets,
        verts.into_flattened(),
        edges.into_flattened(),
        holes,
    ))
}

/// The parent face of child face `c` and the corner it holds, through `cursor`: the parent
/// face of the range's previous child face (none yet at the range's start).
fn parent_face(parent: &Level, cursor: &mut Option<usize>, c: usize) -> (usize, usize) {
    let offsets = &parent.face_offsets;
    let f = cursor.get_or_insert_with(|| offsets.partition_point(|&o| o as usize <= c) - 1);
    while offsets[*f + 1] as usize <= c {
        *f += 1;
    }
    (*f, c - offsets[*f] as usize)
}

/// Child edge sharpness (`subdivideEdgeSharpness`) and non-manifold tags.
fn build_edge_sharpness(parent: &Level, r: &mut Refinement, control: &Control) -> Result<()> {
    let nfv = parent.num_face_vertices_total();
    let ne = parent.num_edges();
    let total = nfv + 2 * ne;
    let mut sharpness = vec![0.0f32; total];
    let mut non_manifold = vec![false; total];
    let method = parent.options.crease_method;
    let mut around: Vec<f32> = Vec::new();
    for e in 0..ne {
        control.step(e, ne)?;
        let p = parent.edge_sharpness(e);
        let nm = parent.is_edge_non_manifold(e);
        for (j, &end) in parent.edge_vertices(e).iter().enumerate() {
            let c = nfv + 2 * e + j;
            non_manifold[c] = nm;
            sharpness[c] = if is_infinite(p) {
                SHARPNESS_INFINITE
            } else if is_semi_sharp(p) {
                around.clear();
                around.extend(
                    parent
                        .vertex_edges(end as usize)
                        .iter()
                        .map(|&x| parent.edge_sharpness(x as usize)),
                );
                subdivide_edge_sharpness_at_vertex(method, p, &around)
            } else {
                0.0
            };
        }
    }
    r.child.edge_sharpness = sharpness;
    r.child.edge_non_manifold = non_manifold;
    Ok(())
}

/// Child edge-vertices and edge-faces (`populateEdgeVerticesFrom*`, `populateEdgeFacesFrom*`).
fn build_edge_relations(parent: &Level, r: &mut Refinement, control: &Control) -> Result<()> {
    let nfv = parent.num_face_vertices_total();
    let ne = parent.num_edges();
    let total = nfv + 2 * ne;
    let mut edge_verts = Vec::with_capacity(total);
    let mut faces = Rows::with_capacity(total, 2 * nfv + 2 * parent.edge_faces.len());
    // Faces then edges, one step each.
    let steps = parent.num_faces() + ne;
    for f in 0..parent.num_faces() {
        control.step(f, steps)?;
        let fe = parent.face_edges(f);
        let n = fe.len();
        for (j, &e) in fe.iter().enumerate() {
            edge_verts.push([r.face_child_vertex(f), r.edge_child_vertex(e as usize)]);
            let j_next = if j + 1 < n { j + 1 } else { 0 };
            let quad = n == 4;
            faces.push(
                Refinement::face_child_face(parent, f, j),
                if quad { j_next as u32 } else { 1 },
            );
            faces.push(
                Refinement::face_child_face(parent, f, j_next),
                if quad { ((j_next + 2) & 3) as u32 } else { 2 },
            );
            faces.end_row();
        }
    }
    for e in 0..ne {
        control.step(parent.num_faces() + e, steps)?;
        let ev = parent.edge_vertices(e);
        let ef = parent.edge_faces(e);
        let el = parent.edge_face_local_indices(e);
        for (j, &end) in ev.iter().enumerate() {
            edge_verts.push([r.edge_child_vertex(e), r.vertex_child_vertex(end as usize)]);
            for (&pf, &in_face) in ef.iter().zip(el) {
                let pf = pf as usize;
                let in_face = in_face as usize;
                let fv = parent.face_vertices(pf);
                let child_of_edge = if ev[0] == ev[1] {
                    j
                } else {
                    (fv[in_face] != ev[j]) as usize
                };
                let mut child_in_face = in_face + child_of_edge;
                if child_in_face == fv.len() {
                    child_in_face = 0;
                }
                let local = if fv.len() == 4 {
                    in_face as u32
                } else if child_of_edge == 1 {
                    3
                } else {
                    0
                };
                faces.push(
                    Refinement::face_child_face(parent, pf, child_in_face),
                    local,
                );
            }
            faces.end_row();
        }
    }
    let c = &mut r.child;
    c.edge_verts = edge_verts;
    c.edge_face_offsets = faces.offsets;
    c.edge_faces = faces.members;
    c.edge_face_locals = faces.locals;
    Ok(())
}

/// The three groups of child vertices, in child index order.
fn groups(order: VertexOrder) -> [u8; 3] {
    const VERTS: u8 = 0;
    const FACES: u8 = 1;
    const EDGES: u8 = 2;
    match order {
        VertexOrder::VerticesFirst => [VERTS, FACES, EDGES],
        VertexOrder::FacesFirst => [FACES, EDGES, VERTS],
    }
}

/// Child vertex sharpness (`subdivideVertexSharpness`) and non-manifold tags.
fn build_vertices(parent: &Level, r: &mut Refinement) {
    let nv = parent.num_vertices();
    let nf = parent.num_faces();
    let ne = parent.num_edges();
    let total = nv + nf + ne;
    let mut sharpness = Vec::with_capacity(total);
    let mut non_manifold = Vec::with_capacity(total);
    for group in groups(r.order) {
        match group {
            0 => {
                for v in 0..nv {
                    let s = parent.vertex_sharpness(v);
                    sharpness.push(if is_infinite(s) {
                        SHARPNESS_INFINITE
                    } else if is_semi_sharp(s) {
                        subdivide_vertex_sharpness(s)
                    } else {
                        0.0
                    });
                }
                non_manifold.extend_from_slice(&parent.vert_non_manifold);
            }
            1 => {
                sharpness.resize(sharpness.len() + nf, 0.0);
                non_manifold.resize(non_manifold.len() + nf, false);
            }
            _ => {
                sharpness.resize(sharpness.len() + ne, 0.0);
                non_manifold.extend_from_slice(&parent.edge_non_manifold);
            }
        }
    }
    r.child.vert_sharpness = sharpness;
    r.child.vert_non_manifold = non_manifold;
}

/// Child vertex-faces and vertex-edges (`populateVertexFacesFrom*`, `populateVertexEdgesFrom*`).
fn build_vertex_relations(parent: &Level, r: &mut Refinement, control: &Control) -> Result<()> {
    let nv = parent.num_vertices();
    let nf = parent.num_faces();
    let ne = parent.num_edges();
    let total = nv + nf + ne;
    let nfv = parent.num_face_vertices_total();
    let mut vfaces = Rows::with_capacity(
        total,
        nfv + 2 * parent.edge_faces.len() + parent.vert_faces.len(),
    );
    let mut vedges = Rows::with_capacity(
        total,
        nfv + parent.edge_faces.len() + 2 * ne + parent.vert_edges.len(),
    );
    // Vertices, faces and edges in the order of their groups, one step each.
    let mut done = 0;
    for group in groups(r.order) {
        match group {
            0 => {
                for v in 0..nv {
                    control.step(done + v, total)?;
                    for (&pf, &k) in parent
                        .vertex_faces(v)
                        .iter()
                        .zip(parent.vertex_face_local_indices(v))
                    {
                        let quad = parent.face_vertices(pf as usize).len() == 4;
                        vfaces.push(
                            Refinement::face_child_face(parent, pf as usize, k as usize),
                            if quad { k } else { 0 },
                        );
                    }
                    vfaces.end_row();
                    for (&pe, &k) in parent
                        .vertex_edges(v)
                        .iter()
                        .zip(parent.vertex_edge_local_indices(v))
                    {
                        vedges.push(r.edge_child_edge(pe as usize, k as usize), 1);
                    }
                    vedges.end_row();
                }
            }
            1 => {
                for f in 0..nf {
                    control.step(done + f, total)?;
                    let n = parent.face_vertices(f).len();
                    for j in 0..n {
                        let local = if n == 4 { ((j + 2) & 3) as u32 } else { 2 };
                        vfaces.push(Refinement::face_child_face(parent, f, j), local);
                    }
                    vfaces.end_row();
                    let base = parent.face_offset(f);
                    for j in 0..n {
                        let leading = if j > 0 { j - 1 } else { n - 1 };
                        vedges.push((base + leading) as u32, 0);
                    }
                    vedges.end_row();
                }
            }
            _ => {
                for e in 0..ne {
                    control.step(done + e, total)?;
                    push_edge_vertex_rows(parent, r, e, &mut vfaces, &mut vedges);
                }
            }
        }
        done += [nv, nf, ne][group as usize];
    }
    let c = &mut r.child;
    c.vert_face_offsets = vfaces.offsets;
    c.vert_faces = vfaces.members;
    c.vert_face_locals = vfaces.locals;
    c.vert_edge_offsets = vedges.offsets;
    c.vert_edges = vedges.members;
    c.vert_edge_locals = vedges.locals;
    Ok(())
}

/// Faces and edges around the child vertex of parent edge `e`
/// (`populateVertexFacesFromParentEdges`, `populateVertexEdgesFromParentEdges`).
fn push_edge_vertex_rows(
    parent: &Level,
    r: &Refinement,
    e: usize,
    vfaces: &mut Rows,
    vedges: &mut Rows,
) {
    let ef = parent.edge_faces(e);
    let el = parent.edge_face_local_indices(e);
    let ev = parent.edge_vertices(e);
    for (&pf, &in_face) in ef.iter().zip(el) {
        let n = parent.face_vertices(pf as usize).len();
        let c0 = in_face as usize;
        let c1 = if c0 + 1 == n { 0 } else { c0 + 1 };
        let quad = n == 4;
        vfaces.push(
            Refinement::face_child_face(parent, pf as usize, c1),
            if quad { c0 as u32 } else { 3 },
        );
        vfaces.push(
            Refinement::face_child_face(parent, pf as usize, c0),
            if quad { c1 as u32 } else { 1 },
        );
    }
    vfaces.end_row();

    let start = vedges.members.len();
    vedges.push(r.edge_child_edge(e, 0), 0);
    vedges.push(r.edge_child_edge(e, 1), 0);
    for (i, (&pf, &in_face)) in ef.iter().zip(el).enumerate() {
        vedges.push(
            (parent.face_offset(pf as usize) + in_face as usize) as u32,
            1,
        );
        if i == 0 {
            // Put the first face's edge between the two halves, so that the edges turn
            // counter-clockwise around the new vertex.
            let m = &mut vedges.members[start..];
            let l = &mut vedges.locals[start..];
            if ev[0] != ev[1] && parent.face_vertices(pf as usize)[in_face as usize] == ev[0] {
                m.swap(0, 1);
                l.swap(0, 1);
            }
            m.swap(1, 2);
            l.swap(1, 2);
        }
    }
    vedges.end_row();
}
