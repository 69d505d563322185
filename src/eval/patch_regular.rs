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

/// A face at a vertex `c`: the vertices after and before `c` in it, the vertex opposite `c`
/// in a quad, and which of the face's two edges at `c` are infinitely sharp. A classified
/// vertex keeps its faces as these (in `vertex_faces` order), so that the tests of the
/// four quads it is a corner of read them instead of walking the fragment again.
#[derive(Debug, Clone, Copy)]
struct FanFace {
    face: u32,
    next: u32,
    prev: u32,
    /// The vertex opposite `c` when the face is a quad, else [`NO_POINT`].
    opposite: u32,
    /// The edges `(c, next)` and `(c, prev)` in the star of `c` while it is classified.
    edges: [u8; 2],
    /// [`SHARP_NEXT`] and [`SHARP_PREV`]: which of these edges are infinitely sharp.
    sharp: u8,
}

const SHARP_NEXT: u8 = 1;
const SHARP_PREV: u8 = 2;

impl FanFace {
    fn is_quad(&self) -> bool {
        self.opposite != NO_POINT
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
/// `fan`: the faces at `c`, none repeating `c`.
fn faces_overlap(nb: &Neighbourhood, c: u32, fan: &[FanFace]) -> bool {
    if fan.iter().all(FanFace::is_quad) {
        // Each quad's vertices other than `c`; two quads that share `c` overlap when two of
        // these (counted in the first quad with repetition) are also the other's.
        let others = |g: &FanFace| [g.next, g.opposite, g.prev];
        for (i, a) in fan.iter().enumerate() {
            let a = others(a);
            for b in &fan[i + 1..] {
                let b = others(b);
                let shared = a.iter().filter(|x| b.contains(x)).count();
                if shared >= 2 {
                    return true;
                }
            }
        }
        return false;
    }
    let faces = nb.vertex_faces(c);
    for (i, &a) in faces.iter().enumerate() {
        let face_a = nb.face(a);
        for &b in &faces[i + 1..] {
            if a == b {
                return true;
            }
            let face_b = nb.face(b);
            let mut shared = 0;
            for x in face_a {
                if face_b.contains(x) {
                    shared += 1;
                }
            }
            if shared > 2 {
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

/// Whether the crease vertex whose faces are `fan` is a crease corner of quad `f`, whose
/// edge `(c, smooth_end)` is the smooth one: the sector on `f`'s side is `f` and the quad
/// across that edge, which must itself end on the other sharp edge.
fn crease_fits(fan: &[FanFace], f: u32, smooth_end: u32) -> bool {
    match across(fan, f, smooth_end) {
        Some(g) if g.is_quad() => {
            let sharp = if g.next == smooth_end {
                SHARP_PREV
            } else {
                SHARP_NEXT
            };
            g.sharp & sharp != 0
        }
        _ => false,
    }
}

/// The face other than `f` among the faces `fan` at `c` on edge `(c, d)`; `None` unless the
/// edge has exactly one other face there.
fn across(fan: &[FanFace], f: u32, d: u32) -> Option<&FanFace> {
    let mut found = None;
    for g in fan {
        if g.face == f || (g.next != d && g.prev != d) {
            continue;
        }
        if found.is_some() {
            return None;
        }
        found = Some(g);
    }
    found
}

/// The vertex next to `c` in fan face `g` that is not `d` (`d` one of them).
fn other_side(g: &FanFace, d: u32) -> u32 {
    if g.next == d {
        g.prev
    } else {
        g.next
    }
}

/// True when the faces `fan` around a vertex form one fan (walking across manifold edges
/// from the first reaches all of them).
fn is_single_fan(fan: &[FanFace]) -> bool {
    let nfaces = fan.len();
    let f = fan[0].face;
    let mut visited = 1;
    for forward in [true, false] {
        // `c` is in each face once, so a face's entry is the face.
        let mut at = &fan[0];
        loop {
            let d = if forward { at.next } else { at.prev };
            match across(fan, at.face, d) {
                Some(h) if h.face == f => return visited == nfaces,
                Some(h) => {
                    visited += 1;
                    if visited > nfaces {
                        return false;
                    }
                    at = h;
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

/// The patch test's working memory, reused from face to face of one fragment, and each
/// vertex's [`VertexClass`] and faces once known: every vertex is a corner of four faces,
/// and most of the test does not depend on the face.
pub struct PatchTest {
    /// The edges at the vertex being classified.
    star: [EdgeAt; MAX_VALENCE],
    star_len: usize,
    /// Per vertex of the fragment [`PatchTest::start`] was given.
    classes: Vec<VertexClass>,
    /// Per vertex of that fragment, once classified: its faces, `fans[a..b]`.
    spans: Vec<(u32, u32)>,
    fans: Vec<FanFace>,
}

impl Default for PatchTest {
    fn default() -> PatchTest {
        PatchTest::new()
    }
}

impl PatchTest {
    /// A test that remembers nothing between faces until [`PatchTest::start`].
    pub fn new() -> PatchTest {
        PatchTest {
            star: [EdgeAt::default(); MAX_VALENCE],
            star_len: 0,
            classes: Vec::new(),
            spans: Vec::new(),
            fans: Vec::new(),
        }
    }

    /// Start testing the faces of a fragment of `num_vertices` vertices.
    pub fn start(&mut self, num_vertices: usize) {
        self.classes.clear();
        self.classes.resize(num_vertices, VertexClass::Unknown);
        self.spans.clear();
        self.spans.resize(num_vertices, (0, 0));
        self.fans.clear();
    }

    /// Add the edge from the classified vertex to `other` (`outgoing`: as the faces
    /// traverse it) to the star; its index, `None` past [`MAX_VALENCE`] edges.
    fn add(&mut self, other: u32, outgoing: bool) -> Option<u8> {
        let len = self.star_len;
        let k = match self.star[..len].iter().position(|e| e.other == other) {
            Some(k) => k,
            None => {
                if len == MAX_VALENCE {
                    return None;
                }
                self.star[len] = EdgeAt {
                    other,
                    out: 0,
                    inc: 0,
                };
                self.star_len += 1;
                len
            }
        };
        if outgoing {
            self.star[k].out += 1;
        } else {
            self.star[k].inc += 1;
        }
        Some(k as u8)
    }

    /// The faces of `c` appended to `fans` with the star of `c`; `None` when `c` is too
    /// complex for a regular patch (repeated in a face, too many edges).
    fn fill(&mut self, nb: &Neighbourhood, c: u32) -> Option<()> {
        self.star_len = 0;
        let faces = nb.vertex_faces(c);
        // A face that repeats `c` is listed once per occurrence, one after the other.
        if faces.windows(2).any(|w| w[0] == w[1]) {
            return None;
        }
        for (&g, &i) in faces.iter().zip(nb.vertex_face_locals(c)) {
            let face = nb.face(g);
            let i = i as usize;
            let (next, prev) = neighbours(face, i);
            let next_edge = self.add(next, true)?;
            let prev_edge = self.add(prev, false)?;
            let opposite = if face.len() == 4 {
                face[(i + 2) % 4]
            } else {
                NO_POINT
            };
            self.fans.push(FanFace {
                face: g,
                next,
                prev,
                opposite,
                edges: [next_edge, prev_edge],
                sharp: 0,
            });
        }
        Some(())
    }

    /// Classify vertex `c` from its star, its edges' and faces' counts and tags, and
    /// [`faces_overlap`]; its faces are appended to `fans` (from `fans.len()` before the
    /// call), their sharp edges marked. Effective sharpness as the module doc says.
    fn classify(&mut self, nb: &Neighbourhood, c: u32, options: &SubdivOptions) -> VertexClass {
        let first = self.fans.len();
        if self.fill(nb, c).is_none() {
            return VertexClass::Irregular;
        }
        let nfaces = self.fans.len() - first;
        let nedges = self.star_len;
        let mut infinite = 0;
        let mut nonmanifold_edges = 0;
        let mut boundary_edges = 0;
        let mut sharp = 0u32;
        for (k, e) in self.star[..nedges].iter().enumerate() {
            let s = edge_sharpness(nb, c, e);
            if s > 0.0 && !is_infinite(s) {
                return VertexClass::Irregular;
            }
            if is_infinite(s) {
                infinite += 1;
                sharp |= 1 << k;
            }
            boundary_edges += usize::from(e.count() == 1);
            nonmanifold_edges += usize::from(e.count() != 1 && !e.is_manifold());
        }
        for g in &mut self.fans[first..] {
            let [next, prev] = g.edges.map(|k| u8::from(sharp & (1 << k) != 0));
            g.sharp = (next * SHARP_NEXT) | (prev * SHARP_PREV);
        }
        let fan = &self.fans[first..];
        // Whether the faces form one fan does not depend on the face the walk starts from.
        let manifold = nonmanifold_edges == 0 && is_single_fan(fan);
        let mut vertex = nb.vertex_tag(c);
        if nfaces == 1 && nedges == 2 && options.boundary == BoundaryInterpolation::EdgeAndCorner {
            vertex = SHARPNESS_INFINITE;
        }
        // Far leaves the vertex of an interior non-manifold crease (two non-manifold edges,
        // no boundary, more faces than edges) alone.
        // Only base vertices are sharpened from topology.
        let on_nonmanifold_crease =
            nonmanifold_edges == 2 && boundary_edges == 0 && nfaces > nedges;
        if !manifold && !on_nonmanifold_crease && !nb.is_edge_descendant(c) {
            vertex = SHARPNESS_INFINITE;
        }
        if vertex > 0.0 && !is_infinite(vertex) {
            return VertexClass::Irregular;
        }
        let class = if vertex > 0.0 || infinite > 2 {
            VertexClass::CornerRule
        } else if infinite == 0
            && manifold
            && nfaces == 4
            && nedges == 4
            && fan.iter().all(FanFace::is_quad)
        {
            VertexClass::Smooth
        } else if infinite == 2 {
            VertexClass::Crease
        } else {
            VertexClass::Irregular
        };
        // A seemingly regular corner whose faces overlap in more than an edge is irregular.
        if class != VertexClass::Irregular && faces_overlap(nb, c, fan) {
            VertexClass::Irregular
        } else {
            class
        }
    }

    /// The class of vertex `c` and its faces' span in `fans`, remembered when `c` is a
    /// vertex of the started fragment.
    fn class(
        &mut self,
        nb: &Neighbourhood,
        c: u32,
        options: &SubdivOptions,
    ) -> (VertexClass, (u32, u32)) {
        match self.classes.get(c as usize) {
            Some(&VertexClass::Unknown) => {
                let first = self.fans.len() as u32;
                let class = self.classify(nb, c, options);
                let span = (first, self.fans.len() as u32);
                self.classes[c as usize] = class;
                self.spans[c as usize] = span;
                (class, span)
            }
            Some(&known) => (known, self.spans[c as usize]),
            None => {
                let first = self.fans.len() as u32;
                let class = self.classify(nb, c, options);
                (class, (first, self.fans.len() as u32))
            }
        }
    }

    /// [`regular_patch_points`] for a face of the fragment of the last
    /// [`PatchTest::start`] (or of any fragment if none).
    pub fn points(
        &mut self,
        nb: &Neighbourhood,
        f: u32,
        options: &SubdivOptions,
    ) -> Option<PatchPoints> {
        let mark = self.fans.len();
        let started = nb.num_vertices() <= self.classes.len();
        let found = self.points_in(nb, f, options);
        if !started {
            // Faces of vertices not remembered: not needed after this face.
            self.fans.truncate(mark);
        }
        found
    }

    fn points_in(
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
        let mut spans = [(0, 0); 4];
        for k in 0..4 {
            (classes[k], spans[k]) = self.class(nb, face[k], options);
            if classes[k] == VertexClass::Irregular {
                return None;
            }
        }
        let fans = &self.fans;
        let fan = |k: usize| &fans[spans[k].0 as usize..spans[k].1 as usize];
        // Edge `k` (corner `k` to `k + 1`) is sharp as its first corner sees it; the edges
        // at a smooth vertex are all smooth.
        let mut boundary: BoundaryMask = 0;
        for (k, &class) in classes.iter().enumerate() {
            if class == VertexClass::Smooth {
                continue;
            }
            let at = fan(k).iter().find(|g| g.face == f)?;
            let sharp_next = at.sharp & SHARP_NEXT != 0;
            let sharp_prev = at.sharp & SHARP_PREV != 0;
            let fits = if class == VertexClass::CornerRule {
                sharp_next && sharp_prev
            } else {
                let smooth_end = if sharp_next { at.prev } else { at.next };
                sharp_next != sharp_prev && crease_fits(fan(k), f, smooth_end)
            };
            if !fits {
                return None;
            }
            if sharp_next {
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
            let g = across(fan(k), f, d)?;
            pts[ACROSS_SLOTS[k].0] = other_side(g, d);
            pts[ACROSS_SLOTS[k].1] = if g.is_quad() {
                g.opposite
            } else {
                let gf = nb.face(g.face);
                let j = gf.iter().position(|&x| x == d)?;
                other_neighbour(gf, j, c)
            };
        }
        for k in 0..4 {
            if classes[k] != VertexClass::Smooth {
                continue;
            }
            let fan = fan(k);
            let g_next = across(fan, f, face[(k + 1) % 4])?.face;
            let g_prev = across(fan, f, face[(k + 3) % 4])?.face;
            let g = fan
                .iter()
                .find(|g| g.face != f && g.face != g_next && g.face != g_prev)?;
            pts[DIAGONAL_SLOTS[k]] = g.opposite;
        }
        Some(PatchPoints {
            vertices: pts,
            boundary,
        })
    }
}

/// The vertex next to `c` in `face` (where `c` is at `i`) that is not `d`.
fn other_neighbour(face: &[u32], i: usize, d: u32) -> u32 {
    let (next, prev) = neighbours(face, i);
    if next == d {
        prev
    } else {
        next
    }
}
