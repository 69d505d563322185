//! The evaluator's points as a program over the control points: what lets an evaluator be
//! built from topology alone and take new positions (or any vertex data) cheaply.
//!
//! Every vertex of every refined fragment the evaluator keeps is a *local point*: the
//! weighted sum that refinement computed it with ([`crate::refine::interpolate`]), its
//! terms in the same order with the same weights, over control points and earlier local
//! points. Replaying the program on positions repeats refinement's arithmetic operation for
//! operation, so an evaluator given new positions is bit for bit the one built with them
//! (it is how every evaluator gets its positions). Like Far's refinement stencils, but
//! factorized level by level rather than flattened onto the control points: a point deep
//! under a semi-sharp crease has a handful of terms, not the 30-odd control points it
//! depends on.

use std::collections::HashMap;

use glam::DVec3;

use crate::refine::{interpolate, Primvar, Refinement};
use crate::topology::Level;

/// Local points as weighted sums of earlier points. Point `i < num_control` is control
/// point `i`; point `num_control + k` is row `k`.
///
/// Neighbouring fragments refine the same vertices again from the same points with the same
/// weights; such a point is recorded once (by its terms, which fix its value bit for bit).
#[derive(Debug, Clone, Default)]
pub(crate) struct PointProgram {
    num_control: u32,
    offsets: Vec<u32>,
    sources: Vec<u32>,
    weights: Vec<f64>,
    /// The first local point with the terms of a given hash (while recording).
    by_terms: HashMap<u64, u32>,
}

/// A hash of a point's terms (sources and weights' bits), for [`PointProgram::by_terms`].
fn hash_terms(sources: &[u32], weights: &[f64]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for (&s, &w) in sources.iter().zip(weights) {
        for x in [u64::from(s), w.to_bits()] {
            h = (h ^ x).wrapping_mul(0x0000_0100_0000_01b3);
            h ^= h >> 29;
        }
    }
    h
}

/// Bit marking a term of [`Recorded`] as a child vertex of the same refinement (face points,
/// which edge and vertex points read) rather than a parent vertex.
const CHILD: u32 = 1 << 31;

/// Terms a [`Recorded`] value holds without allocating: enough for face and edge points of
/// quads and vertex points up to valence 5.
const INLINE_TERMS: usize = 11;

/// A refined vertex as the weighted sum interpolation built: its terms over parent vertices
/// and (with [`CHILD`]) earlier child vertices, in the order they were added (the first
/// [`INLINE_TERMS`] in place, the rest in `spill`: a build records millions).
#[derive(Debug, Clone)]
struct Recorded {
    /// This vertex: its parent index, or [`CHILD`] | its child index once complete.
    own: u32,
    len: u32,
    inline: [(u32, f64); INLINE_TERMS],
    spill: Vec<(u32, f64)>,
}

impl Recorded {
    fn of(own: u32) -> Recorded {
        Recorded {
            own,
            len: 0,
            inline: [(0, 0.0); INLINE_TERMS],
            spill: Vec::new(),
        }
    }

    fn terms(&self) -> impl Iterator<Item = &(u32, f64)> {
        let n = (self.len as usize).min(INLINE_TERMS);
        self.inline[..n].iter().chain(&self.spill)
    }
}

impl Primvar for Recorded {
    fn zero() -> Self {
        Recorded::of(0)
    }
    fn add_weighted(&mut self, src: &Self, weight: f64) {
        let term = (src.own, weight);
        match self.inline.get_mut(self.len as usize) {
            Some(slot) => *slot = term,
            None => self.spill.push(term),
        }
        self.len += 1;
    }
    fn finish(&mut self, child: u32) {
        self.own = CHILD | child;
    }
}

impl PointProgram {
    /// A program over `num_control` control points, with no local points yet.
    pub fn new(num_control: usize) -> PointProgram {
        PointProgram {
            num_control: num_control as u32,
            offsets: vec![0],
            sources: Vec::new(),
            weights: Vec::new(),
            by_terms: HashMap::new(),
        }
    }

    /// Number of points: control and local.
    pub fn num_points(&self) -> usize {
        self.num_control as usize + self.offsets.len() - 1
    }

    /// The point with these terms: an earlier one with the same terms, else a new one.
    fn push(&mut self, terms: impl IntoIterator<Item = (u32, f64)>) -> u32 {
        let start = self.sources.len();
        for (s, w) in terms {
            self.sources.push(s);
            self.weights.push(w);
        }
        let h = hash_terms(&self.sources[start..], &self.weights[start..]);
        if let Some(&p) = self.by_terms.get(&h) {
            let k = p as usize - self.num_control as usize;
            let (a, b) = (self.offsets[k] as usize, self.offsets[k + 1] as usize);
            let same = self.sources[a..b] == self.sources[start..]
                && self.weights[a..b]
                    .iter()
                    .zip(&self.weights[start..])
                    .all(|(x, y)| x.to_bits() == y.to_bits());
            if same {
                self.sources.truncate(start);
                self.weights.truncate(start);
                return p;
            }
        }
        self.offsets.push(self.sources.len() as u32);
        let p = self.num_points() as u32 - 1;
        self.by_terms.entry(h).or_insert(p);
        p
    }

    /// The points of the child of refinement `r` of `level`, whose vertices are points
    /// `parent`, recorded as new local points; returns the child vertices' points. Face
    /// points come first, then edge points, then vertex points: the order refinement
    /// completes them in, so that every term reads an earlier point.
    pub fn record(&mut self, level: &Level, r: &Refinement, parent: &[u32]) -> Vec<u32> {
        let src: Vec<Recorded> = (0..level.num_vertices() as u32).map(Recorded::of).collect();
        let dst = interpolate(level, r, &src);
        let mut points = vec![0u32; dst.len()];
        let first_face = r.face_child_vertex(0) as usize;
        let faces = first_face..first_face + level.num_faces();
        let first_edge = r.edge_child_vertex(0) as usize;
        let edges = first_edge..first_edge + level.num_edges();
        let first_vertex = r.vertex_child_vertex(0) as usize;
        let vertices = first_vertex..first_vertex + level.num_vertices();
        for cv in faces.chain(edges).chain(vertices) {
            let terms = dst[cv].terms().map(|&(s, w)| {
                let p = if s & CHILD != 0 {
                    points[(s & !CHILD) as usize]
                } else {
                    parent[s as usize]
                };
                (p, w)
            });
            points[cv] = self.push(terms);
        }
        points
    }

    /// Every point's value from the control points' `control` (one per control point):
    /// each local point summed as refinement sums it.
    ///
    /// Panics if `control` has fewer values than the program has control points.
    pub fn run(&self, control: &[DVec3]) -> Vec<DVec3> {
        let nc = self.num_control as usize;
        let mut values = Vec::with_capacity(self.num_points());
        values.extend_from_slice(&control[..nc]);
        for w in self.offsets.windows(2) {
            let (a, b) = (w[0] as usize, w[1] as usize);
            let mut acc = DVec3::ZERO;
            for (&s, &wt) in self.sources[a..b].iter().zip(&self.weights[a..b]) {
                acc.add_weighted(&values[s as usize], wt);
            }
            values.push(acc);
        }
        values
    }

    /// Keep only the points `roots` name and those they read, numbered in the same order;
    /// `roots` are renumbered in place. Ends the recording (no more merging of equal points).
    pub fn prune(&mut self, roots: &mut [&mut [u32]]) {
        let nc = self.num_control as usize;
        let np = self.num_points();
        let mut needed = vec![false; np];
        for list in roots.iter() {
            for &p in list.iter() {
                if p != u32::MAX {
                    needed[p as usize] = true;
                }
            }
        }
        for p in (nc..np).rev() {
            if needed[p] {
                let k = p - nc;
                let (a, b) = (self.offsets[k] as usize, self.offsets[k + 1] as usize);
                for &s in &self.sources[a..b] {
                    needed[s as usize] = true;
                }
            }
        }
        let mut renumber: Vec<u32> = (0..nc as u32).collect();
        renumber.resize(np, u32::MAX);
        let mut kept = PointProgram::new(nc);
        for p in nc..np {
            if !needed[p] {
                continue;
            }
            let k = p - nc;
            let (a, b) = (self.offsets[k] as usize, self.offsets[k + 1] as usize);
            let terms = self.sources[a..b]
                .iter()
                .zip(&self.weights[a..b])
                .map(|(&s, &w)| (renumber[s as usize], w));
            renumber[p] = kept.push(terms);
        }
        for list in roots.iter_mut() {
            for p in list.iter_mut() {
                if *p != u32::MAX {
                    *p = renumber[*p as usize];
                }
            }
        }
        kept.by_terms = HashMap::new();
        *self = kept;
    }
}
