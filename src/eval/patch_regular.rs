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

use std::borrow::Cow;

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

/// Most faces at a vertex whose neighbours [`VertexStar`] keeps; more (only at odd
/// non-manifold vertices) are read from the fragment again when needed.
const FAN_CAPACITY: usize = MAX_VALENCE;

/// A face at a vertex `c` with the vertices after and before `c` in it.
#[derive(Debug, Clone, Copy, Default)]
struct FanFace {
    face: u32,
    next: u32,
    prev: u32,
}

/// The edges at vertex `c`, and its faces in `vertex_faces` order with their neighbours of
/// `c` (the patch test walks them many times; reading them off the fragment each time costs
/// more than the rest of the test).
struct VertexStar {
    edges: [EdgeAt; MAX_VALENCE],
    len: usize,
    fan: [FanFace; FAN_CAPACITY],
    /// Faces at `c`; all of them are in `fan` when at most [`FAN_CAPACITY`].
    fan_len: usize,
}

impl VertexStar {
    fn new() -> VertexStar {
        VertexStar {
            edges: [EdgeAt::default(); MAX_VALENCE],
            len: 0,
            fan: [FanFace::default(); FAN_CAPACITY],
            fan_len: 0,
        }
    }

    /// The star of `c` into `self` (reused: a star is a few hundred bytes); `None` when `c`
    /// is too complex for a regular patch (repeated in a face, too many edges).
    fn fill(&mut self, nb: &Neighbourhood, c: u32) -> Option<()> {
        self.len = 0;
        self.fan_len = 0;
        for &g in nb.vertex_faces(c) {
            let face = nb.face(g);
            let i = face.iter().position(|&x| x == c)?;
            if face[i + 1..].contains(&c) {
                return None;
            }
            let (next, prev) = neighbours(face, i);
            self.add(next, true)?;
            self.add(prev, false)?;
            if let Some(slot) = self.fan.get_mut(self.fan_len) {
                *slot = FanFace {
                    face: g,
                    next,
                    prev,
                };
            }
            self.fan_len += 1;
        }
        Some(())
    }

    /// The faces at `c` (this star's vertex) in `vertex_faces` order, from the stored fan
    /// or, past its capacity, read from the fragment again.
    fn faces(&self, nb: &Neighbourhood, c: u32) -> Cow<'_, [FanFace]> {
        if self.fan_len <= FAN_CAPACITY {
            return Cow::Borrowed(&self.fan[..self.fan_len]);
        }
        let read = nb.vertex_faces(c).iter().map(|&g| {
            let face = nb.face(g);
            // `c` is in each of its faces exactly once (else there is no star).
            let i = face.iter().position(|&x| x == c).unwrap_or(0);
            let (next, prev) = neighbours(face, i);
            FanFace {
                face: g,
                next,
                prev,
            }
        });
        Cow::Owned(read.collect())
    }

    fn add(&mut self, other: u32, outgoing: bool) -> Option<()> {
        let k = match self.edges[..self.len].iter().position(|e| e.other == other) {
            Some(k) => k,
            None => {
                if self.len == MAX_VALENCE {
                    return None;
                }
                self.edges[self.len] = EdgeAt {
                    other,
                    out: 0,
                    inc: 0,
                };
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

fn is_infinite(s: f32) -> bool {
    s >= SHARPNESS_INFINITE
}

/// True when two faces at `c` share more than two vertices. That happens below a face that
/// repeats a vertex: its children meet along two distinct edges joining the same pair of
/// vertices, which a fragment keyed by vertex pairs cannot tell from one manifold edge.
fn faces_overlap(nb: &Neighbourhood, c: u32) -> bool {
    let faces = nb.vertex_faces(c);
    for (i, &a) in faces.iter().enumerate() {
        let face_a = nb.face(a);
        for &b in &faces[i + 1..] {
            if a == b {
                return true;
            }
            let face_b = nb.face(b);
            let mut shared = face_a.iter().filter(|x| face_b.contains(x));
            if shared.nth(2).is_some() {
                return true;
            }
        }
    }
    false
}

/// What a vertex is as the corner of a quad, whatever the quad: the part of the patch test
/// that does not depend on the face (Far tags each vertex of a level once, too).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum VertexClass {
    /// Not classified yet.
    Unknown,
    /// A corner of no regular patch.
    Irregular,
    /// A smooth corner of each of its quads.
    Smooth,
    /// The corner rule applies: a corner of the quads whose two edges at it are infinitely
    /// sharp.
    CornerRule,
    /// Two infinitely sharp edges: a crease corner of the quads whose sector is one quad
    /// on each side of the smooth edge (checked per face, [`crease_fits`]).
    Crease,
}

/// Classify vertex `c` from its star (filled here into `star`), its edges' and faces'
/// counts and tags, and [`faces_overlap`]. Effective sharpness as the module doc says.
fn classify(
    nb: &Neighbourhood,
    c: u32,
    star: &mut VertexStar,
    options: &SubdivOptions,
) -> VertexClass {
    if star.fill(nb, c).is_none() {
        return VertexClass::Irregular;
    }
    let faces = nb.vertex_faces(c);
    let nfaces = faces.len();
    let nedges = star.len;
    let mut infinite = 0;
    let mut nonmanifold_edges = 0;
    let mut boundary_edges = 0;
    for e in star.edges() {
        let s = edge_sharpness(nb, c, e);
        if s > 0.0 && !is_infinite(s) {
            return VertexClass::Irregular;
        }
        infinite += usize::from(is_infinite(s));
        boundary_edges += usize::from(e.count() == 1);
        nonmanifold_edges += usize::from(e.count() != 1 && !e.is_manifold());
    }
    // Whether the faces form one fan does not depend on the face the walk starts from.
    let manifold = nonmanifold_edges == 0 && is_single_fan(nb, star, c, faces[0], nfaces);
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
        return VertexClass::Irregular;
    }
    let class = if vertex > 0.0 || infinite > 2 {
        VertexClass::CornerRule
    } else if infinite == 0 && manifold && nfaces == 4 && nedges == 4 && all_quads(nb, c) {
        VertexClass::Smooth
    } else if infinite == 2 {
        VertexClass::Crease
    } else {
        VertexClass::Irregular
    };
    // A seemingly regular corner whose faces overlap in more than an edge is irregular.
    if class != VertexClass::Irregular && faces_overlap(nb, c) {
        VertexClass::Irregular
    } else {
        class
    }
}

/// Whether the crease vertex `c` (star `star`) is a crease corner of quad `f`, whose edge
/// `(c, smooth_end)` is the smooth one: the sector on `f`'s side is `f` and the quad across
/// that edge, which must itself end on the other sharp edge.
fn crease_fits(nb: &Neighbourhood, star: &VertexStar, f: u32, c: u32, smooth_end: u32) -> bool {
    match across(nb, star, f, c, smooth_end) {
        Some((g, beyond)) if nb.face(g).len() == 4 => star
            .find(beyond)
            .is_some_and(|e| is_infinite(edge_sharpness(nb, c, e))),
        _ => false,
    }
}

fn all_quads(nb: &Neighbourhood, c: u32) -> bool {
    nb.vertex_faces(c).iter().all(|&g| nb.face(g).len() == 4)
}

/// The face other than `f` on edge `(c, d)` and, in it, the vertex next to `c` that is not
/// `d`. `None` unless the edge has exactly one other face. `star` is `c`'s.
fn across(nb: &Neighbourhood, star: &VertexStar, f: u32, c: u32, d: u32) -> Option<(u32, u32)> {
    let mut found = None;
    for g in star.faces(nb, c).iter() {
        if g.face == f {
            continue;
        }
        let other = if g.next == d {
            g.prev
        } else if g.prev == d {
            g.next
        } else {
            continue;
        };
        if found.is_some() {
            return None;
        }
        found = Some((g.face, other));
    }
    found
}

/// True when the faces around `c` (whose star is `star`) form one fan (walking across
/// manifold edges from `f` reaches all `nfaces` of them).
fn is_single_fan(nb: &Neighbourhood, star: &VertexStar, c: u32, f: u32, nfaces: usize) -> bool {
    let mut visited = 1;
    for forward in [true, false] {
        let mut g = f;
        loop {
            let Some(&at) = star.faces(nb, c).iter().find(|e| e.face == g) else {
                return false;
            };
            let d = if forward { at.next } else { at.prev };
            match across(nb, star, g, c, d) {
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

/// The 16 control points of a regular patch as vertices of its fragment ([`NO_POINT`] for
/// the points beyond a sharp side, which [`BicubicPatch::with_boundary`] replaces), and its
/// sharp sides.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PatchPoints {
    /// Vertex of each control point, `points[4 * j + i]` as in [`BicubicPatch`].
    pub vertices: [u32; 16],
    /// The sides on an infinitely sharp edge.
    pub boundary: BoundaryMask,
}

/// A control point a patch does not read (beyond a sharp side).
pub const NO_POINT: u32 = u32::MAX;

impl PatchPoints {
    /// The patch with `value(v)` at each vertex `v` it reads (zero elsewhere, to be replaced
    /// by phantom points).
    #[inline]
    pub fn patch(&self, value: impl Fn(u32) -> DVec3) -> BicubicPatch {
        let pts = self
            .vertices
            .map(|v| if v == NO_POINT { DVec3::ZERO } else { value(v) });
        BicubicPatch::with_boundary(pts, self.boundary)
    }
}

/// The bicubic patch of face `f` with vertex positions `positions` when its limit surface is
/// one, else `None`.
pub fn regular_patch(
    nb: &Neighbourhood,
    f: u32,
    options: &SubdivOptions,
    positions: &[DVec3],
) -> Option<BicubicPatch> {
    regular_patch_points(nb, f, options).map(|p| p.patch(|v| positions[v as usize]))
}

/// Which vertices of `nb` define face `f`'s bicubic patch when its limit surface is one,
/// else `None`.
pub fn regular_patch_points(
    nb: &Neighbourhood,
    f: u32,
    options: &SubdivOptions,
) -> Option<PatchPoints> {
    PatchTest::new().points(nb, f, options)
}

/// The patch test's working memory, reused from face to face of one fragment (a star is a
/// few hundred bytes to clear otherwise), and each vertex's [`VertexClass`] once known:
/// every vertex is a corner of four faces, and most of the test does not depend on the face.
pub struct PatchTest {
    star: VertexStar,
    /// Per vertex of the fragment [`PatchTest::start`] was given.
    classes: Vec<VertexClass>,
}

impl Default for PatchTest {
    fn default() -> PatchTest {
        PatchTest::new()
    }
}

/// The face other than `f` on edge `(c, d)` (`c` in it once) and the position of `c` in it;
/// `None` unless the edge has exactly one other face. As [`across`], without a star.
fn across_at(nb: &Neighbourhood, f: u32, c: u32, d: u32) -> Option<(u32, usize)> {
    let mut found = None;
    for &g in nb.vertex_faces(c) {
        if g == f {
            continue;
        }
        let face = nb.face(g);
        let i = face.iter().position(|&x| x == c)?;
        let (next, prev) = neighbours(face, i);
        if next != d && prev != d {
            continue;
        }
        if found.is_some() {
            return None;
        }
        found = Some((g, i));
    }
    found
}

/// The vertex next to `c` in `face` (where `c` is at `i`) that is not `d`, as [`across`]
/// picks it.
fn other_neighbour(face: &[u32], i: usize, d: u32) -> u32 {
    let (next, prev) = neighbours(face, i);
    if next == d {
        prev
    } else {
        next
    }
}

impl PatchTest {
    /// A test that remembers nothing between faces until [`PatchTest::start`].
    pub fn new() -> PatchTest {
        PatchTest {
            star: VertexStar::new(),
            classes: Vec::new(),
        }
    }

    /// Start testing the faces of a fragment of `num_vertices` vertices.
    pub fn start(&mut self, num_vertices: usize) {
        self.classes.clear();
        self.classes.resize(num_vertices, VertexClass::Unknown);
    }

    /// The class of vertex `c`, remembered when `c` is a vertex of the started fragment.
    fn class(&mut self, nb: &Neighbourhood, c: u32, options: &SubdivOptions) -> VertexClass {
        match self.classes.get(c as usize) {
            Some(&VertexClass::Unknown) => {
                let class = classify(nb, c, &mut self.star, options);
                self.classes[c as usize] = class;
                class
            }
            Some(&known) => known,
            None => classify(nb, c, &mut self.star, options),
        }
    }

    /// Whether corner `k` of quad `f` (vertex of class `class`, not smooth) fits a regular
    /// patch, and if so whether `f`'s edge after it (from corner `k` to `k + 1`) is
    /// infinitely sharp.
    fn sharp_corner(
        &mut self,
        nb: &Neighbourhood,
        f: u32,
        k: usize,
        class: VertexClass,
    ) -> Option<bool> {
        let face = nb.face(f);
        let c = face[k];
        let (next, prev) = neighbours(face, k);
        let star = &mut self.star;
        star.fill(nb, c)?;
        let sharp_next = is_infinite(edge_sharpness(nb, c, star.find(next)?));
        let sharp_prev = is_infinite(edge_sharpness(nb, c, star.find(prev)?));
        let fits = if class == VertexClass::CornerRule {
            sharp_next && sharp_prev
        } else {
            let smooth_end = if sharp_next { prev } else { next };
            sharp_next != sharp_prev && crease_fits(nb, star, f, c, smooth_end)
        };
        fits.then_some(sharp_next)
    }

    /// [`regular_patch_points`] for a face of the fragment of the last
    /// [`PatchTest::start`] (or of any fragment if none).
    pub fn points(
        &mut self,
        nb: &Neighbourhood,
        f: u32,
        options: &SubdivOptions,
    ) -> Option<PatchPoints> {
        let face = nb.face(f);
        if face.len() != 4 {
            return None;
        }
        for k in 0..4 {
            if face[k + 1..].contains(&face[k]) {
                return None;
            }
        }
        let mut classes = [VertexClass::Irregular; 4];
        for k in 0..4 {
            classes[k] = self.class(nb, face[k], options);
            if classes[k] == VertexClass::Irregular {
                return None;
            }
        }
        // Edge `k` (corner `k` to `k + 1`) is sharp as its first corner sees it; the edges
        // at a smooth vertex are all smooth.
        let mut boundary: BoundaryMask = 0;
        for (k, &class) in classes.iter().enumerate() {
            if class != VertexClass::Smooth && self.sharp_corner(nb, f, k, class)? {
                boundary |= 1 << k;
            }
        }
        let mut pts = [NO_POINT; 16];
        for k in 0..4 {
            let (c, d) = (face[k], face[(k + 1) % 4]);
            pts[CORNER_SLOTS[k]] = c;
            if boundary & (1 << k) != 0 {
                continue;
            }
            let (g, i) = across_at(nb, f, c, d)?;
            let gf = nb.face(g);
            let j = gf.iter().position(|&x| x == d)?;
            pts[ACROSS_SLOTS[k].0] = other_neighbour(gf, i, d);
            pts[ACROSS_SLOTS[k].1] = other_neighbour(gf, j, c);
        }
        for k in 0..4 {
            if classes[k] != VertexClass::Smooth {
                continue;
            }
            let c = face[k];
            let (g_next, _) = across_at(nb, f, c, face[(k + 1) % 4])?;
            let (g_prev, _) = across_at(nb, f, c, face[(k + 3) % 4])?;
            let g = *nb
                .vertex_faces(c)
                .iter()
                .find(|&&g| g != f && g != g_next && g != g_prev)?;
            let gf = nb.face(g);
            let i = gf.iter().position(|&x| x == c)?;
            pts[DIAGONAL_SLOTS[k]] = gf[(i + 2) % 4];
        }
        Some(PatchPoints {
            vertices: pts,
            boundary,
        })
    }
}
