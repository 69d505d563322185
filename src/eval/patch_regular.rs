//! When is a quad's limit surface a bicubic B-spline patch, and which 16 points define it.
//!
//! The surface over a quad `F` only depends on `F`'s four corners and the faces and edges
//! around them. It is the uniform bicubic B-spline of the 4×4 grid around `F` when every
//! corner `c` is, *on `F`'s side of the infinitely sharp edges at `c`*, one of:
//!
//! - **smooth**: no sharp edge and no vertex sharpness at `c`, manifold, 4 quads around it;
//! - **crease**: exactly two sharp edges at `c`, both infinitely sharp (boundary edges are),
//!   no vertex sharpness, one of them an edge of `F`, and `F` plus the quad across `F`'s
//!   other edge at `c` filling the sector between them — the crease rule then makes the
//!   crease a cubic B-spline and the sector a B-spline with a reflected phantom row, whatever
//!   lies beyond the crease;
//! - **corner**: the corner rule holds (vertex infinitely sharp, or three or more sharp edges,
//!   all infinitely sharp) and both of `F`'s edges at `c` are infinitely sharp.
//!
//! Any remaining finite sharpness at a corner (edge or vertex) means "refine further". These
//! conditions are preserved by refinement, which is why the patch is exact. Effective
//! sharpness follows `Far::TopologyRefinerFactory`: boundary and non-manifold edges are
//! infinitely sharp, a corner with one face is infinitely sharp under edge-and-corner
//! interpolation, a non-manifold vertex of the base level is infinitely sharp unless it sits
//! on an interior non-manifold crease (refined vertices that descend from edge points are
//! never sharpened from topology: [`Neighbourhood::is_edge_descendant`]).

use glam::DVec3;

use super::bspline::{BicubicPatch, BoundaryMask};
use super::patch_topology::Neighbourhood;
use crate::mesh::SHARPNESS_INFINITE;
use crate::options::{BoundaryInterpolation, SubdivOptions};

/// Most edges at a vertex the patch test looks at; more means "irregular".
const MAX_VALENCE: usize = 32;

/// One edge at a vertex `c`: the other end and how the faces around `c` use it.
#[derive(Debug, Clone, Copy, Default)]
struct EdgeAt {
    other: u32,
    /// Faces traversing `c → other`.
    out: u16,
    /// Faces traversing `other → c`.
    inc: u16,
}

impl EdgeAt {
    fn count(&self) -> u16 {
        self.out + self.inc
    }
    fn is_manifold(&self) -> bool {
        self.out == 1 && self.inc == 1
    }
}

/// The vertices after and before position `i` of `face` (branches, not `%`: this runs
/// millions of times while an evaluator is built).
#[inline]
fn neighbours(face: &[u32], i: usize) -> (u32, u32) {
    let n = face.len();
    let next = if i + 1 == n { face[0] } else { face[i + 1] };
    let prev = if i == 0 { face[n - 1] } else { face[i - 1] };
    (next, prev)
}

/// The edges at vertex `c` and whether `c` repeats in one of its faces.
struct VertexStar {
    edges: [EdgeAt; MAX_VALENCE],
    len: usize,
}

impl VertexStar {
    /// `None` when `c` is too complex for a regular patch (repeated in a face, too many edges).
    fn gather(nb: &Neighbourhood, c: u32) -> Option<VertexStar> {
        let mut star = VertexStar {
            edges: [EdgeAt::default(); MAX_VALENCE],
            len: 0,
        };
        for &g in nb.vertex_faces(c) {
            let face = nb.face(g);
            let i = face.iter().position(|&x| x == c)?;
            if face[i + 1..].contains(&c) {
                return None;
            }
            let (next, prev) = neighbours(face, i);
            star.add(next, true)?;
            star.add(prev, false)?;
        }
        Some(star)
    }

    fn add(&mut self, other: u32, outgoing: bool) -> Option<()> {
        let k = match self.edges[..self.len].iter().position(|e| e.other == other) {
            Some(k) => k,
            None => {
                if self.len == MAX_VALENCE {
                    return None;
                }
                self.edges[self.len].other = other;
                self.len += 1;
                self.len - 1
            }
        };
        if outgoing {
            self.edges[k].out += 1;
        } else {
            self.edges[k].inc += 1;
        }
        Some(())
    }

    fn edges(&self) -> &[EdgeAt] {
        &self.edges[..self.len]
    }

    fn find(&self, other: u32) -> Option<&EdgeAt> {
        self.edges().iter().find(|e| e.other == other)
    }
}

/// Effective sharpness of edge `(c, e.other)`.
fn edge_sharpness(nb: &Neighbourhood, c: u32, e: &EdgeAt) -> f32 {
    if !e.is_manifold() {
        SHARPNESS_INFINITE
    } else {
        nb.edge_tag(c, e.other)
    }
}

/// What a corner of a quad contributes to the patch test.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum CornerKind {
    Smooth,
    /// Crease along one of the face's edges at the corner (the boundary mask says which).
    Crease,
    Corner,
    Irregular,
}

fn is_infinite(s: f32) -> bool {
    s >= SHARPNESS_INFINITE
}

/// True when two faces at `c` share more than two vertices. That happens below a face that
/// repeats a vertex: its children meet along two distinct edges joining the same pair of
/// vertices, which a fragment keyed by vertex pairs cannot tell from one manifold edge.
fn faces_overlap(nb: &Neighbourhood, c: u32) -> bool {
    let faces = nb.vertex_faces(c);
    for (i, &a) in faces.iter().enumerate() {
        for &b in &faces[i + 1..] {
            let shared = nb.face(a).iter().filter(|x| nb.face(b).contains(x)).count();
            if a == b || shared > 2 {
                return true;
            }
        }
    }
    false
}

/// Classify corner `k` of quad `f`, whose vertex has the edges `star`, from the counts and
/// tags of its edges and faces ([`regular_patch`] also checks [`faces_overlap`]).
fn corner_kind_by_counts(
    nb: &Neighbourhood,
    f: u32,
    k: usize,
    star: &VertexStar,
    options: &SubdivOptions,
) -> CornerKind {
    let face = nb.face(f);
    let c = face[k];
    let (next, prev) = neighbours(face, k);
    let nfaces = nb.vertex_faces(c).len();
    let nedges = star.len;
    let mut infinite = 0;
    let mut nonmanifold_edges = 0;
    let mut boundary_edges = 0;
    for e in star.edges() {
        let s = edge_sharpness(nb, c, e);
        if s > 0.0 && !is_infinite(s) {
            return CornerKind::Irregular;
        }
        infinite += usize::from(is_infinite(s));
        boundary_edges += usize::from(e.count() == 1);
        nonmanifold_edges += usize::from(e.count() != 1 && !e.is_manifold());
    }
    let manifold = nonmanifold_edges == 0 && is_single_fan(nb, c, f, nfaces);
    let mut vertex = nb.vertex_tag(c);
    if nfaces == 1 && nedges == 2 && options.boundary == BoundaryInterpolation::EdgeAndCorner {
        vertex = SHARPNESS_INFINITE;
    }
    // Far leaves the vertex of an interior non-manifold crease (two non-manifold edges, no
    // boundary, more faces than edges) alone.
    // Only base vertices are sharpened from topology.
    let on_nonmanifold_crease = nonmanifold_edges == 2 && boundary_edges == 0 && nfaces > nedges;
    if !manifold && !on_nonmanifold_crease && !nb.is_edge_descendant(c) {
        vertex = SHARPNESS_INFINITE;
    }
    if vertex > 0.0 && !is_infinite(vertex) {
        return CornerKind::Irregular;
    }
    let sharp_next = star
        .find(next)
        .map(|e| is_infinite(edge_sharpness(nb, c, e)));
    let sharp_prev = star
        .find(prev)
        .map(|e| is_infinite(edge_sharpness(nb, c, e)));
    let (Some(sharp_next), Some(sharp_prev)) = (sharp_next, sharp_prev) else {
        return CornerKind::Irregular;
    };
    let corner_rule = vertex > 0.0 || infinite > 2;
    if corner_rule {
        return if sharp_next && sharp_prev {
            CornerKind::Corner
        } else {
            CornerKind::Irregular
        };
    }
    match infinite {
        0 if manifold && nfaces == 4 && nedges == 4 && all_quads(nb, c) => CornerKind::Smooth,
        2 if sharp_next != sharp_prev => {
            // The sector on F's side: F and the quad across F's smooth edge, which must
            // itself end on the other sharp edge.
            let smooth_end = if sharp_next { prev } else { next };
            match across(nb, f, c, smooth_end) {
                Some((g, beyond)) if nb.face(g).len() == 4 => {
                    let e = star.find(beyond);
                    if e.is_some_and(|e| is_infinite(edge_sharpness(nb, c, e))) {
                        CornerKind::Crease
                    } else {
                        CornerKind::Irregular
                    }
                }
                _ => CornerKind::Irregular,
            }
        }
        _ => CornerKind::Irregular,
    }
}

fn all_quads(nb: &Neighbourhood, c: u32) -> bool {
    nb.vertex_faces(c).iter().all(|&g| nb.face(g).len() == 4)
}

/// The face other than `f` on edge `(c, d)` and, in it, the vertex next to `c` that is not
/// `d`. `None` unless the edge has exactly one other face.
fn across(nb: &Neighbourhood, f: u32, c: u32, d: u32) -> Option<(u32, u32)> {
    let mut found = None;
    for &g in nb.vertex_faces(c) {
        if g == f {
            continue;
        }
        let face = nb.face(g);
        let i = face.iter().position(|&x| x == c)?;
        let (nx, pv) = neighbours(face, i);
        let other = if nx == d {
            pv
        } else if pv == d {
            nx
        } else {
            continue;
        };
        if found.is_some() {
            return None;
        }
        found = Some((g, other));
    }
    found
}

/// True when the faces around `c` form one fan (walking across manifold edges from `f`
/// reaches all `nfaces` of them).
fn is_single_fan(nb: &Neighbourhood, c: u32, f: u32, nfaces: usize) -> bool {
    let mut visited = 1;
    for forward in [true, false] {
        let mut g = f;
        loop {
            let face = nb.face(g);
            let Some(i) = face.iter().position(|&x| x == c) else {
                return false;
            };
            let (next, prev) = neighbours(face, i);
            let d = if forward { next } else { prev };
            match across(nb, g, c, d) {
                Some((h, _)) if h == f => return visited == nfaces,
                Some((h, _)) => {
                    visited += 1;
                    if visited > nfaces {
                        return false;
                    }
                    g = h;
                }
                None => break,
            }
        }
    }
    visited == nfaces
}

/// Grid slots of the two outer points across edge `k` (next to corner `k`, next to corner
/// `k + 1`), and of the diagonal point at corner `k`.
const ACROSS_SLOTS: [(usize, usize); 4] = [(1, 2), (7, 11), (14, 13), (8, 4)];
const DIAGONAL_SLOTS: [usize; 4] = [0, 3, 15, 12];
const CORNER_SLOTS: [usize; 4] = [5, 6, 10, 9];

/// The bicubic patch of face `f` when its limit surface is one, else `None`.
pub fn regular_patch(nb: &Neighbourhood, f: u32, options: &SubdivOptions) -> Option<BicubicPatch> {
    let face = nb.face(f);
    if face.len() != 4 {
        return None;
    }
    for k in 0..4 {
        if face[k + 1..].contains(&face[k]) {
            return None;
        }
    }
    let mut kinds = [CornerKind::Irregular; 4];
    let mut stars: [Option<VertexStar>; 4] = [None, None, None, None];
    for k in 0..4 {
        let star = VertexStar::gather(nb, face[k])?;
        kinds[k] = corner_kind_by_counts(nb, f, k, &star, options);
        // A seemingly regular corner whose faces overlap in more than an edge is irregular.
        if kinds[k] == CornerKind::Irregular || faces_overlap(nb, face[k]) {
            return None;
        }
        stars[k] = Some(star);
    }
    let mut boundary: BoundaryMask = 0;
    let mut pts = [DVec3::ZERO; 16];
    for k in 0..4 {
        let (c, d) = (face[k], face[(k + 1) % 4]);
        pts[CORNER_SLOTS[k]] = nb.position(c);
        let sharp = stars[k]
            .as_ref()
            .and_then(|s| s.find(d).map(|e| is_infinite(edge_sharpness(nb, c, e))))?;
        if sharp {
            boundary |= 1 << k;
            continue;
        }
        let (_, at_c) = across(nb, f, c, d)?;
        let (_, at_d) = across(nb, f, d, c)?;
        pts[ACROSS_SLOTS[k].0] = nb.position(at_c);
        pts[ACROSS_SLOTS[k].1] = nb.position(at_d);
    }
    for k in 0..4 {
        if kinds[k] != CornerKind::Smooth {
            continue;
        }
        let c = face[k];
        let (g_next, _) = across(nb, f, c, face[(k + 1) % 4])?;
        let (g_prev, _) = across(nb, f, c, face[(k + 3) % 4])?;
        let g = *nb
            .vertex_faces(c)
            .iter()
            .find(|&&g| g != f && g != g_next && g != g_prev)?;
        let gf = nb.face(g);
        let i = gf.iter().position(|&x| x == c)?;
        pts[DIAGONAL_SLOTS[k]] = nb.position(gf[(i + 2) % 4]);
    }
    Some(BicubicPatch::with_boundary(pts, boundary))
}

/// True when vertex `v` has a boundary edge (one face) that is not tagged infinitely sharp:
/// under boundary interpolation "none", Far gives the faces at such a vertex no limit surface.
pub fn has_soft_boundary_edge(nb: &Neighbourhood, v: u32) -> bool {
    match VertexStar::gather(nb, v) {
        Some(star) => star
            .edges()
            .iter()
            .any(|e| e.count() == 1 && !is_infinite(nb.edge_tag(v, e.other))),
        // A vertex repeated in a face or with very many edges: decide from the faces alone.
        None => soft_boundary_by_scan(nb, v),
    }
}

fn soft_boundary_by_scan(nb: &Neighbourhood, v: u32) -> bool {
    let mut ends: Vec<u32> = Vec::new();
    for &g in nb.vertex_faces(v) {
        let face = nb.face(g);
        let n = face.len();
        for i in 0..n {
            if face[i] == v {
                ends.push(face[(i + 1) % n]);
                ends.push(face[(i + n - 1) % n]);
            }
        }
    }
    // A face that repeats `v` consecutively has a degenerate edge (v, v): an edge of its own
    // with that one face, so a boundary edge that no tag can sharpen (as in Vtr).
    if ends.contains(&v) {
        return true;
    }
    ends.sort_unstable();
    let mut i = 0;
    while i < ends.len() {
        let mut j = i;
        while j < ends.len() && ends[j] == ends[i] {
            j += 1;
        }
        if j - i == 1 && !is_infinite(nb.edge_tag(v, ends[i])) {
            return true;
        }
        i = j;
    }
    false
}
