//! One GBS refinement step on the shared [`Level`] topology: even orders on the
//! Catmull–Clark quad split (child components in Far's order, so a child is found from its
//! parent exactly as for [`crate::refine_uniform`]), odd orders on the Doo–Sabin dual split.

use glam::DVec3;

use super::rules::{centroid, curve_vertex, face_corner, smooth_edge, vertex_weights};
use crate::catmark::crease::is_infinite;
use crate::error::{Error, Result};
use crate::mesh::{Mesh, MeshParts};
use crate::options::{BoundaryInterpolation, SubdivOptions};
use crate::refine::{refine as quad_split, VertexOrder};
use crate::topology::Level;

/// The options GBS levels are built with: boundary edges are infinitely sharp and boundary
/// corners are not (the boundary is one curve through them).
pub(crate) fn level_options() -> SubdivOptions {
    SubdivOptions {
        boundary: BoundaryInterpolation::EdgeOnly,
        ..Default::default()
    }
}

/// How a vertex moves: by the surface rule, along its curve (two infinitely sharp edges,
/// given as the vertices across them), or not at all.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum VertexKind {
    Smooth,
    Crease([u32; 2], [u32; 2]),
    Corner,
}

/// Classify vertex `v`: an infinitely sharp corner tag or more than two infinitely sharp
/// edges (boundary edges included) make a corner, exactly two a crease, fewer the smooth
/// rule (a dart is smooth, as in Catmull–Clark).
pub(crate) fn vertex_kind(level: &Level, v: usize) -> VertexKind {
    if is_infinite(level.vertex_sharpness(v)) {
        return VertexKind::Corner;
    }
    let sharp: Vec<u32> = level
        .vertex_edges(v)
        .iter()
        .copied()
        .filter(|&e| is_infinite(level.edge_sharpness(e as usize)))
        .collect();
    match sharp[..] {
        [a, b] => {
            let other = |e: u32| {
                let [x, y] = level.edge_vertices(e as usize);
                if x as usize == v {
                    y
                } else {
                    x
                }
            };
            VertexKind::Crease([a, b], [other(a), other(b)])
        }
        [] | [_] => VertexKind::Smooth,
        _ => VertexKind::Corner,
    }
}

/// Check that `level` is one GBS refines: manifold, no holes, every edge and vertex tag
/// smooth or infinitely sharp, and (odd orders) no creases or corners but the boundary's.
pub(crate) fn check_level(level: &Level, order: u32) -> Result<()> {
    let bad = |msg: String| Err(Error::invalid_mesh(msg));
    for v in 0..level.num_vertices() {
        if level.is_vertex_non_manifold(v) {
            return bad(format!(
                "vertex {v} is non-manifold; GBS needs a manifold mesh"
            ));
        }
        let s = level.vertex_sharpness(v);
        if s > 0.0 && (!is_infinite(s) || order % 2 == 1) {
            return bad(format!(
                "vertex {v} has sharpness {s}: GBS takes infinitely sharp corners (even orders only)"
            ));
        }
        if level.vertex_faces(v).is_empty() {
            return bad(format!("vertex {v} is on no face"));
        }
    }
    for e in 0..level.num_edges() {
        let s = level.edge_sharpness(e);
        let tagged = s > 0.0 && !level.is_edge_boundary(e);
        if tagged && (!is_infinite(s) || order % 2 == 1) {
            return bad(format!(
                "edge {e} has sharpness {s}: GBS takes infinitely sharp creases (even orders only)"
            ));
        }
    }
    if let Some(f) = (0..level.num_faces()).find(|&f| level.is_face_hole(f)) {
        return bad(format!("face {f} is a hole; GBS has no holes"));
    }
    Ok(())
}

fn face_centroids(level: &Level, p: &[DVec3]) -> Vec<DVec3> {
    (0..level.num_faces())
        .map(|f| centroid(level.face_vertices(f).iter().map(|&i| p[i as usize])))
        .collect()
}

fn edge_midpoints(level: &Level, p: &[DVec3]) -> Vec<DVec3> {
    (0..level.num_edges())
        .map(|e| {
            let [a, b] = level.edge_vertices(e);
            (p[a as usize] + p[b as usize]) / 2.0
        })
        .collect()
}

/// The even-order step: midpoint insertion and the tension smoothing (rules M and T; the
/// averaging passes U are [`average`]). Child components in Far's vertex-first order.
pub(crate) fn even_step(level: &Level, p: &[DVec3], v: f64) -> (Level, Vec<DVec3>) {
    let r = quad_split(level, VertexOrder::VerticesFirst);
    let faces = face_centroids(level, p);
    let mids = edge_midpoints(level, p);
    let mut child = vec![DVec3::ZERO; r.child.num_vertices()];
    for (f, &c) in faces.iter().enumerate() {
        child[r.face_child_vertex(f) as usize] = c;
    }
    for (e, &m) in mids.iter().enumerate() {
        let ef = level.edge_faces(e);
        let q = if is_infinite(level.edge_sharpness(e)) {
            m
        } else {
            smooth_edge(m, faces[ef[0] as usize], faces[ef[1] as usize], v)
        };
        child[r.edge_child_vertex(e) as usize] = q;
    }
    for (i, &pi) in p.iter().enumerate() {
        let q = match vertex_kind(level, i) {
            VertexKind::Corner => pi,
            VertexKind::Crease([a, b], _) => {
                curve_vertex(pi, mids[a as usize], mids[b as usize], v)
            }
            VertexKind::Smooth => {
                let edges = level.vertex_edges(i);
                let (alpha, beta, gamma) = vertex_weights(edges.len(), v);
                let m = centroid(edges.iter().map(|&e| mids[e as usize]));
                let f = centroid(level.vertex_faces(i).iter().map(|&f| faces[f as usize]));
                pi * alpha + m * beta + f * gamma
            }
        };
        child[r.vertex_child_vertex(i) as usize] = q;
    }
    (r.child, child)
}

/// One averaging pass U: a smooth vertex becomes the average of its faces' centroids (mask
/// `[1 2 1] ⊗ [1 2 1] / 16` on a regular grid), a crease vertex `(q₋ + 2q + q₊)/4` along its
/// curve, a corner stays.
pub(crate) fn average(level: &Level, p: &[DVec3]) -> Vec<DVec3> {
    let faces = face_centroids(level, p);
    (0..p.len())
        .map(|i| match vertex_kind(level, i) {
            VertexKind::Corner => p[i],
            VertexKind::Crease(_, [a, b]) => (p[a as usize] + p[i] * 2.0 + p[b as usize]) / 4.0,
            VertexKind::Smooth => {
                centroid(level.vertex_faces(i).iter().map(|&f| faces[f as usize]))
            }
        })
        .collect()
}

/// Where the faces of an odd-order step come from: child face `f` is face `f`'s (the same
/// index at every level), then one per interior edge, then one per interior vertex.
#[derive(Debug, Clone)]
pub(crate) struct DualFaces {
    /// The child face of each edge (`None` on the boundary).
    pub edge: Vec<Option<u32>>,
    /// The child face of each vertex (`None` on the boundary).
    pub vertex: Vec<Option<u32>>,
}

/// Whether edge `e` gets a face in an odd-order step.
fn has_edge_face(level: &Level, e: usize) -> bool {
    level.edge_faces(e).len() == 2
}

/// The child faces of `level`'s edges and vertices in [`odd_step`]'s numbering.
pub(crate) fn dual_faces(level: &Level) -> DualFaces {
    let mut next = level.num_faces() as u32;
    let mut number = |has: bool| {
        has.then(|| {
            next += 1;
            next - 1
        })
    };
    let edge = (0..level.num_edges())
        .map(|e| number(has_edge_face(level, e)))
        .collect();
    let vertex = (0..level.num_vertices())
        .map(|v| number(!level.is_vertex_boundary(v)))
        .collect();
    DualFaces { edge, vertex }
}

/// The odd-order step C: one point per face corner (rule [`face_corner`]) and the Doo–Sabin
/// faces: one per face (its corners in order), one quad per interior edge, one per interior
/// vertex (its faces' corners, counter-clockwise). Boundary edges and vertices get no face:
/// an odd-order boundary is free and shrinks as Doo–Sabin's does.
///
/// Child vertex `face_offset(f) + i` is corner `i` of face `f`.
pub(crate) fn odd_step(level: &Level, p: &[DVec3], v: f64) -> Result<(Level, Vec<DVec3>)> {
    let faces = face_centroids(level, p);
    let mids = edge_midpoints(level, p);
    let mut child = Vec::with_capacity(level.num_face_vertices_total());
    let (mut sizes, mut indices) = (Vec::new(), Vec::new());
    for (f, &centre) in faces.iter().enumerate() {
        let (fv, fe) = (level.face_vertices(f), level.face_edges(f));
        let n = fv.len();
        for i in 0..n {
            let (prev, next) = (fe[(i + n - 1) % n] as usize, fe[i] as usize);
            child.push(face_corner(
                p[fv[i] as usize],
                mids[prev],
                mids[next],
                centre,
                v,
            ));
        }
        let off = level.face_offset(f) as u32;
        sizes.push(n as u32);
        indices.extend(off..off + n as u32);
    }
    let slot = |f: u32, local: usize| {
        let n = level.face_vertices(f as usize).len();
        level.face_offset(f as usize) as u32 + (local % n) as u32
    };
    for e in 0..level.num_edges() {
        let (ef, el) = (level.edge_faces(e), level.edge_face_local_indices(e));
        if !has_edge_face(level, e) {
            continue;
        }
        let (f1, i1, f2, i2) = (ef[0], el[0] as usize, ef[1], el[1] as usize);
        if level.face_vertices(f1 as usize)[i1] == level.face_vertices(f2 as usize)[i2] {
            return Err(Error::invalid_mesh(format!(
                "edge {e}: its faces are not consistently oriented"
            )));
        }
        // f1 runs a → b along the edge, f2 runs b → a.
        let (p1a, p1b) = (slot(f1, i1), slot(f1, i1 + 1));
        let (q2b, q2a) = (slot(f2, i2), slot(f2, i2 + 1));
        sizes.push(4);
        indices.extend([p1b, p1a, q2a, q2b]);
    }
    for i in 0..level.num_vertices() {
        if level.is_vertex_boundary(i) {
            continue;
        }
        let (vf, vl) = (level.vertex_faces(i), level.vertex_face_local_indices(i));
        if vf.len() < 3 {
            return Err(Error::invalid_mesh(format!(
                "vertex {i} has valence {}: an odd-order step would make a face of fewer than 3 sides",
                vf.len()
            )));
        }
        sizes.push(vf.len() as u32);
        indices.extend(vf.iter().zip(vl).map(|(&f, &l)| slot(f, l as usize)));
    }
    let mesh = Mesh::from_parts(MeshParts {
        positions: child,
        face_sizes: sizes,
        face_indices: indices,
        ..Default::default()
    })?;
    let level = Level::from_mesh_with_options(&mesh, &level_options());
    Ok((level, mesh.into_parts().positions))
}
