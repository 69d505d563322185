//! Tessellation of the exact limit surface: triangles (or quads) whose vertices lie on it.
//!
//! Every parametric face (see [`crate::eval::ptex`]: a quad, or one sub-face of an N-gon) is
//! cut into an `n × n` grid of its `(u, v)` square, `n` being the face's rate:
//! - **uniform** ([`Rate::Uniform`]`(N)`): `n = N` on quads and `⌈N/2⌉` on an N-gon's
//!   sub-faces (each covers half of the face's edges, so the N-gon's edges get `N` segments,
//!   or `N + 1` for odd `N`, like a quad's);
//! - **adaptive** ([`Rate::Tolerance`]`(t)`): `n` from the face's second differences, then
//!   raised on the faces where a triangle is farther than `0.8 t` from the surface at its
//!   check points ([`CHECK_POINTS`], compared with the surface at the same `(u, v)`), until
//!   none is or the face reaches
//!   [`TessellateOptions::max_rate`] (listed in [`Tessellation::unmet`] if still over).
//!
//! **Watertight by construction.** A point of the tessellation is named by where it lies on
//! the control mesh — a control vertex, the `m`-th of `R` points of a control edge, the
//! `j`-th point of the spoke from an N-gon's edge midpoint to its centre, an N-gon's centre,
//! or a point inside one parametric face — and evaluated once, by the first face that asks
//! for it. Each control edge has one segment count `R`, the largest its faces ask for (even
//! when an N-gon touches it, so that its midpoint is a point); a face whose own rate is lower
//! joins its sides to its inner grid with a strip of triangles ([`mod@stitch`]), so no vertex
//! lies on another face's edge: no T-junction.
//!
//! **Positions** are the evaluator's ([`Evaluator::evaluate`]) at the point's recorded
//! `(face, u, v)` ([`Tessellation::points`]), exact on the limit surface.
//!
//! **Normals** are `normalize(du × dv)` of the exact derivatives. Across an infinitely sharp
//! crease (a non-boundary edge of sharpness ≥ 10, or a vertex that is a corner or touches
//! such an edge) the surface has no single normal, so such a point gets one normal per
//! control face, from that face's own evaluation ([`Tessellation::normals`] indexed per
//! polygon corner by [`Tessellation::face_normals`]). Everywhere else a point has one normal
//! (semi-sharp creases are smooth in the limit). Where the derivatives are parallel (a
//! degenerate parameterization) the normal is the normalized sum of the tessellation's
//! polygon normals around the point. [`Tessellation::vertex_normals`] gives one normal per
//! vertex (the normalized sum of its normals), for formats with a single normal per vertex.
//!
//! **Holes** and faces without limit surface ([`crate::eval::surface`]) are left out.
//!
//! Output order is deterministic: control faces in order, sub-faces in corner order, the
//! polygons of a face row by row, then the transition strips side by side.

pub mod report;
pub mod stitch;

use std::collections::HashMap;

use glam::DVec3;

use crate::catmark::crease::is_infinite;
use crate::catmark::Rule;
use crate::error::{Error, Result};
use crate::eval::{Evaluator, LimitSample};
use crate::topology::Level;
pub use report::EdgeReport;
use stitch::{stitch, Spot, Stitched};

/// Largest rate (segments per side of a parametric face) accepted.
pub const MAX_RATE: u32 = 4096;

/// Most grid cells (the sum of every parametric face's rate²) one tessellation makes: 2^24,
/// about 33 million triangles, as many as the refiner's [`crate::refine::MAX_REFINED_FACE_INDICES`]
/// allow quads. Checked from the rates before anything is built: a cube at rate 4096 asks
/// for 10^8 cells, gigabytes.
pub const MAX_CELLS: u64 = 1 << 24;

/// How finely to cut each parametric face.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rate {
    /// `N × N` cells per quad (N-gons: see the module doc), 1 ≤ N ≤ [`MAX_RATE`].
    Uniform(u32),
    /// Chordal tolerance in model units (> 0): no triangle farther from the surface.
    Tolerance(f64),
}

/// Options of [`tessellate`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TessellateOptions {
    /// Uniform rate or chordal tolerance.
    pub rate: Rate,
    /// Keep grid cells as quads (transition strips stay triangles); else split each cell
    /// along its shorter diagonal.
    pub quads: bool,
    /// Highest rate the adaptive mode gives a face (1..=[`MAX_RATE`]).
    pub max_rate: u32,
}

impl Default for TessellateOptions {
    /// Uniform rate 4, triangles, adaptive rates up to 64.
    fn default() -> Self {
        TessellateOptions {
            rate: Rate::Uniform(4),
            quads: false,
            max_rate: 64,
        }
    }
}

/// Where a tessellation vertex was evaluated: Ptex face and `(u, v)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfacePoint {
    /// Parametric (Ptex) face.
    pub face: u32,
    /// Parameter u.
    pub u: f64,
    /// Parameter v.
    pub v: f64,
}

/// A tessellated limit surface (see the [module documentation](self)).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Tessellation {
    /// Vertex positions, on the limit surface.
    pub positions: Vec<DVec3>,
    /// Where each vertex was evaluated.
    pub points: Vec<SurfacePoint>,
    /// One unit normal per vertex (split normals averaged).
    pub vertex_normals: Vec<DVec3>,
    /// Unit normals, split along infinitely sharp creases.
    pub normals: Vec<DVec3>,
    /// Polygon sizes (3, or 4 with [`TessellateOptions::quads`]).
    pub face_sizes: Vec<u32>,
    /// Polygon vertices, counter-clockwise seen from the side `du × dv` points to.
    pub face_vertices: Vec<u32>,
    /// Normal index of each polygon corner (parallel to `face_vertices`).
    pub face_normals: Vec<u32>,
    /// Parametric (Ptex) face each polygon lies in.
    pub face_ptex: Vec<u32>,
    /// `(u, v)` of each polygon corner in that parametric face (parallel to `face_vertices`).
    pub corner_uv: Vec<[f64; 2]>,
    /// Adaptive mode: the parametric faces that reached [`TessellateOptions::max_rate`] and
    /// still miss the tolerance at a check point (near extraordinary vertices of high valence
    /// the error falls slowly with the rate); empty otherwise.
    pub unmet: Vec<u32>,
}

impl Tessellation {
    /// Number of vertices.
    pub fn num_vertices(&self) -> usize {
        self.positions.len()
    }

    /// Number of polygons.
    pub fn num_faces(&self) -> usize {
        self.face_sizes.len()
    }

    /// Triangles (quads split along their shorter diagonal), counter-clockwise.
    pub fn triangles(&self) -> Vec<[u32; 3]> {
        let mut out = Vec::with_capacity(self.face_sizes.len() * 2);
        let mut start = 0;
        for &size in &self.face_sizes {
            let c = &self.face_vertices[start..start + size as usize];
            if size == 3 {
                out.push([c[0], c[1], c[2]]);
            } else {
                let [a, b] = split_quad(&self.positions, [c[0], c[1], c[2], c[3]]);
                out.push([c[a[0]], c[a[1]], c[a[2]]]);
                out.push([c[b[0]], c[b[1]], c[b[2]]]);
            }
            start += size as usize;
        }
        out
    }
}

/// The two triangles of a cell of a parametric face whose corners `at_vertex` are control
/// vertices: split through that vertex when exactly one diagonal has one, else along the
/// shorter diagonal. At a valence-2 vertex the two faces' corner cells share both sides, so
/// a split along the other diagonal would give both the same triangle (a non-manifold edge).
fn split_cell(positions: &[DVec3], q: [u32; 4], at_vertex: [bool; 4]) -> [[usize; 3]; 2] {
    match (at_vertex[0] || at_vertex[2], at_vertex[1] || at_vertex[3]) {
        (true, false) => [[0, 1, 2], [0, 2, 3]],
        (false, true) => [[0, 1, 3], [1, 2, 3]],
        _ => split_quad(positions, q),
    }
}

/// The two triangles (as corner positions 0-3) of quad `q` split along its shorter diagonal
/// (0-2 on a tie).
fn split_quad(positions: &[DVec3], q: [u32; 4]) -> [[usize; 3]; 2] {
    let p = |k: usize| positions[q[k] as usize];
    if p(0).distance_squared(p(2)) <= p(1).distance_squared(p(3)) {
        [[0, 1, 2], [0, 2, 3]]
    } else {
        [[0, 1, 3], [1, 2, 3]]
    }
}

/// Where a point lies on the control mesh: its identity, shared by every face that has it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum Key {
    Vertex(u32),
    /// Point `m` of `R` along control edge `e`, counted from its first vertex (0 < m < R).
    Edge(u32, u32),
    /// Point `j` of the spoke of N-gon `f` from its edge `k`'s midpoint to its centre.
    Spoke(u32, u32, u32),
    Centre(u32),
    /// A point inside parametric face `p`.
    Inner(u32, u32, u32),
}

/// Tessellate the limit surface of `ev` (see the [module documentation](self)).
///
/// Errors ([`Error::InvalidArgument`]): a rate outside `1..=MAX_RATE`, a tolerance that is
/// not positive and finite, `max_rate` outside `1..=MAX_RATE`, rates that would make more
/// than [`MAX_CELLS`] cells (checked before building; in adaptive mode when a raise would);
/// errors of evaluation.
pub fn tessellate(ev: &Evaluator, options: &TessellateOptions) -> Result<Tessellation> {
    if !(1..=MAX_RATE).contains(&options.max_rate) {
        return Err(Error::invalid_argument(format!(
            "max rate {} is outside 1..={MAX_RATE}",
            options.max_rate
        )));
    }
    let level = Level::from_mesh_with_options(ev.mesh(), ev.options());
    let plan = Plan::new(ev, &level);
    match options.rate {
        Rate::Uniform(n) => {
            if !(1..=MAX_RATE).contains(&n) {
                return Err(Error::invalid_argument(format!(
                    "rate {n} is outside 1..={MAX_RATE}"
                )));
            }
            let rates = plan.uniform_rates(n);
            plan.build(&rates, options.quads)
        }
        Rate::Tolerance(t) => {
            if !(t > 0.0 && t.is_finite()) {
                return Err(Error::invalid_argument(format!(
                    "tolerance {t} must be positive and finite"
                )));
            }
            let mut rates = plan.estimated_rates(t, options.max_rate)?;
            loop {
                let mut tess = plan.build(&rates, options.quads)?;
                let over = faces_over_tolerance(ev, &tess, CHECK_MARGIN * t)?;
                let mut raised = false;
                for &p in &over {
                    let r = &mut rates[p as usize];
                    let next = (*r + (*r).div_ceil(2)).min(options.max_rate);
                    raised |= next > *r;
                    *r = next;
                }
                if !raised {
                    tess.unmet = over;
                    return Ok(tess);
                }
            }
        }
    }
}

/// The control mesh's topology as the tessellation walks it.
struct Plan<'a> {
    ev: &'a Evaluator,
    level: &'a Level,
    /// Whether each control face has a limit surface.
    has_surface: Vec<bool>,
    /// Whether each control vertex needs one normal per face.
    sharp_vertex: Vec<bool>,
}

impl<'a> Plan<'a> {
    fn new(ev: &'a Evaluator, level: &'a Level) -> Plan<'a> {
        let ptex = ev.ptex_faces();
        let has_surface = (0..level.num_faces())
            .map(|f| ev.has_surface(ptex.first_of(f)))
            .collect();
        let sharp_edge = |e: u32| {
            is_infinite(level.edge_sharpness(e as usize)) && !level.is_edge_boundary(e as usize)
        };
        let sharp_vertex = (0..level.num_vertices())
            .map(|v| {
                is_infinite(level.vertex_sharpness(v))
                    || level.vertex_rule(v) == Rule::Corner
                    || level.vertex_edges(v).iter().any(|&e| sharp_edge(e))
            })
            .collect();
        Plan {
            ev,
            level,
            has_surface,
            sharp_vertex,
        }
    }

    fn uniform_rates(&self, n: u32) -> Vec<u32> {
        let mut rates = Vec::with_capacity(self.ev.num_parametric_faces());
        for f in 0..self.level.num_faces() {
            let size = self.level.face_vertices(f).len();
            if size == 4 {
                rates.push(n);
            } else {
                rates.extend(std::iter::repeat(n.div_ceil(2)).take(size));
            }
        }
        rates
    }

    /// Rates from second differences of the derivatives on an 8 × 8 grid: a triangle of a
    /// cell of size `h` deviates from the surface by about `h²/8 (|Puu| + 2|Puv| + |Pvv|)`.
    fn estimated_rates(&self, tol: f64, max_rate: u32) -> Result<Vec<u32>> {
        const M: usize = 8;
        let mut rates = Vec::with_capacity(self.ev.num_parametric_faces());
        for p in 0..self.ev.num_parametric_faces() as u32 {
            if !self.ev.has_surface(p) {
                rates.push(1);
                continue;
            }
            let mut grid = Vec::with_capacity((M + 1) * (M + 1));
            for j in 0..=M {
                for i in 0..=M {
                    grid.push(
                        self.ev
                            .evaluate(p, i as f64 / M as f64, j as f64 / M as f64)?,
                    );
                }
            }
            let at = |i: usize, j: usize| grid[j * (M + 1) + i];
            let mut bound: f64 = 0.0;
            for j in 0..M {
                for i in 0..M {
                    let puu = (at(i + 1, j).du - at(i, j).du).length() * M as f64;
                    let puv = (at(i, j + 1).du - at(i, j).du).length() * M as f64;
                    let pvv = (at(i, j + 1).dv - at(i, j).dv).length() * M as f64;
                    bound = bound.max(puu + 2.0 * puv + pvv);
                }
            }
            let n = (bound / (8.0 * tol)).sqrt().ceil();
            rates.push(if n.is_finite() {
                (n as u32).clamp(1, max_rate)
            } else {
                max_rate
            });
        }
        Ok(rates)
    }

    /// Segment count of each control edge, and of each N-gon spoke (indexed by face-vertex
    /// offset), from the parametric faces' rates.
    fn edge_and_spoke_rates(&self, rates: &[u32]) -> (Vec<u32>, Vec<u32>) {
        let level = self.level;
        let ptex = self.ev.ptex_faces();
        let mut edge = vec![0u32; level.num_edges()];
        let mut even = vec![false; level.num_edges()];
        let mut spoke = vec![0u32; level.num_face_vertices_total()];
        for f in 0..level.num_faces() {
            if !self.has_surface[f] {
                continue;
            }
            let edges = level.face_edges(f);
            let first = ptex.first_of(f) as usize;
            let size = edges.len();
            for (k, &e) in edges.iter().enumerate() {
                let e = e as usize;
                if size == 4 {
                    edge[e] = edge[e].max(rates[first]);
                } else {
                    let sub = rates[first + k].max(rates[first + (k + 1) % size]);
                    edge[e] = edge[e].max(2 * sub);
                    even[e] = true;
                    spoke[level.face_offset(f) + k] = sub;
                }
            }
        }
        for (r, even) in edge.iter_mut().zip(even) {
            if even && *r % 2 == 1 {
                *r += 1;
            }
        }
        (edge, spoke)
    }

    /// Key of point `k` along edge `e` (segment count `r`) counted from vertex `from`.
    fn edge_key(&self, e: u32, from: u32, k: u32, r: u32) -> Key {
        let [a, b] = self.level.edge_vertices(e as usize);
        let m = if a == from { k } else { r - k };
        if m == 0 {
            Key::Vertex(a)
        } else if m == r {
            Key::Vertex(b)
        } else {
            Key::Edge(e, m)
        }
    }

    /// The key of `spot` in parametric face `p` (control face `f`, sub-face `sub`).
    #[allow(clippy::too_many_arguments)]
    fn key(
        &self,
        f: usize,
        sub: Option<usize>,
        p: u32,
        spot: Spot,
        edge_rate: &[u32],
        spoke_rate: &[u32],
    ) -> Key {
        let verts = self.level.face_vertices(f);
        let edges = self.level.face_edges(f);
        let Some(k) = sub else {
            return match spot {
                Spot::Corner(c) => Key::Vertex(verts[c as usize]),
                Spot::Side(s, j) => {
                    let e = edges[s as usize];
                    self.edge_key(e, verts[s as usize], j, edge_rate[e as usize])
                }
                Spot::Inner(i, j) => Key::Inner(p, i, j),
            };
        };
        let size = verts.len();
        let prev = (k + size - 1) % size;
        let (e, ep) = (edges[k], edges[prev]);
        let (r, rp) = (edge_rate[e as usize], edge_rate[ep as usize]);
        let off = self.level.face_offset(f);
        let spoke = |k: usize, j: u32| {
            let s = spoke_rate[off + k];
            if j == 0 {
                let r = edge_rate[edges[k] as usize];
                self.edge_key(edges[k], verts[k], r / 2, r)
            } else if j == s {
                Key::Centre(f as u32)
            } else {
                Key::Spoke(f as u32, k as u32, j)
            }
        };
        match spot {
            Spot::Corner(0) => Key::Vertex(verts[k]),
            Spot::Corner(1) => self.edge_key(e, verts[k], r / 2, r),
            Spot::Corner(2) => Key::Centre(f as u32),
            Spot::Corner(_) => self.edge_key(ep, verts[prev], rp / 2, rp),
            Spot::Side(0, j) => self.edge_key(e, verts[k], j, r),
            Spot::Side(1, j) => spoke(k, j),
            Spot::Side(2, j) => spoke(prev, spoke_rate[off + prev] - j),
            Spot::Side(_, j) => self.edge_key(ep, verts[prev], rp / 2 + j, rp),
            Spot::Inner(i, j) => Key::Inner(p, i, j),
        }
    }

    fn is_sharp(&self, key: Key) -> bool {
        match key {
            Key::Vertex(v) => self.sharp_vertex[v as usize],
            Key::Edge(e, _) => {
                is_infinite(self.level.edge_sharpness(e as usize))
                    && !self.level.is_edge_boundary(e as usize)
            }
            _ => false,
        }
    }

    fn build(&self, rates: &[u32], quads: bool) -> Result<Tessellation> {
        let cells: u64 = rates.iter().map(|&r| u64::from(r) * u64::from(r)).sum();
        if cells > MAX_CELLS {
            return Err(Error::invalid_argument(format!(
                "tessellating {} parametric faces at these rates would make {cells} cells, above the limit {MAX_CELLS}",
                rates.len()
            )));
        }
        let ev = self.ev;
        let level = self.level;
        let ptex = ev.ptex_faces();
        let (edge_rate, spoke_rate) = self.edge_and_spoke_rates(rates);
        let mut t = Tessellation::default();
        let mut points: HashMap<Key, u32> = HashMap::new();
        let mut sharp = Vec::new();
        // Normal of each non-split point, and of each (split point, control face).
        let mut normal_of: HashMap<(u32, u32), u32> = HashMap::new();
        for f in 0..level.num_faces() {
            if !self.has_surface[f] {
                continue;
            }
            let size = level.face_vertices(f).len();
            let first = ptex.first_of(f);
            let count = if size == 4 { 1 } else { size };
            for k in 0..count {
                let p = first + k as u32;
                let sub = (size != 4).then_some(k);
                let sides: [u32; 4] = match sub {
                    None => {
                        let e = level.face_edges(f);
                        [0, 1, 2, 3].map(|s| edge_rate[e[s] as usize])
                    }
                    Some(k) => {
                        let e = level.face_edges(f);
                        let off = level.face_offset(f);
                        let prev = (k + size - 1) % size;
                        [
                            edge_rate[e[k] as usize] / 2,
                            spoke_rate[off + k],
                            spoke_rate[off + prev],
                            edge_rate[e[prev] as usize] / 2,
                        ]
                    }
                };
                let st: Stitched = stitch(rates[p as usize], sides);
                let mut ids = Vec::with_capacity(st.points.len());
                let mut normal_ids = Vec::with_capacity(st.points.len());
                for &(spot, [u, v]) in &st.points {
                    let key = self.key(f, sub, p, spot, &edge_rate, &spoke_rate);
                    let mut sample: Option<LimitSample> = None;
                    let id = match points.get(&key) {
                        Some(&id) => id,
                        None => {
                            let s = ev.evaluate(p, u, v)?;
                            sample = Some(s);
                            let id = t.positions.len() as u32;
                            t.positions.push(s.position);
                            t.points.push(SurfacePoint { face: p, u, v });
                            sharp.push(self.is_sharp(key));
                            points.insert(key, id);
                            id
                        }
                    };
                    let nkey = (
                        id,
                        if sharp[id as usize] {
                            f as u32
                        } else {
                            u32::MAX
                        },
                    );
                    let nid = match normal_of.get(&nkey) {
                        Some(&n) => n,
                        None => {
                            let s = match sample {
                                Some(s) => s,
                                None => ev.evaluate(p, u, v)?,
                            };
                            t.normals.push(s.normal());
                            let n = (t.normals.len() - 1) as u32;
                            normal_of.insert(nkey, n);
                            n
                        }
                    };
                    ids.push(id);
                    normal_ids.push(nid);
                }
                let mut start = 0;
                for &size in &st.sizes {
                    let c = &st.corners[start..start + size as usize];
                    let pieces: Vec<Vec<usize>> = if size == 4 && !quads {
                        let q = [0, 1, 2, 3].map(|i| ids[c[i] as usize]);
                        let at_vertex = [0, 1, 2, 3].map(|i| {
                            let spot = st.points[c[i] as usize].0;
                            matches!(
                                self.key(f, sub, p, spot, &edge_rate, &spoke_rate),
                                Key::Vertex(_)
                            )
                        });
                        split_cell(&t.positions, q, at_vertex)
                            .iter()
                            .map(|tri| tri.iter().map(|&i| c[i] as usize).collect())
                            .collect()
                    } else {
                        vec![c.iter().map(|&i| i as usize).collect()]
                    };
                    for piece in pieces {
                        t.face_sizes.push(piece.len() as u32);
                        t.face_ptex.push(p);
                        for i in piece {
                            t.face_vertices.push(ids[i]);
                            t.face_normals.push(normal_ids[i]);
                            t.corner_uv.push(st.points[i].1);
                        }
                    }
                    start += size as usize;
                }
            }
        }
        fill_degenerate_normals(&mut t);
        Ok(t)
    }
}

/// Polygon normals (area-weighted) summed into the normals that are zero, and the
/// per-vertex normals.
fn fill_degenerate_normals(t: &mut Tessellation) {
    let mut sums = vec![DVec3::ZERO; t.normals.len()];
    let mut vertex = vec![DVec3::ZERO; t.positions.len()];
    let mut start = 0;
    for &size in &t.face_sizes {
        let c = &t.face_vertices[start..start + size as usize];
        let p = |i: usize| t.positions[c[i] as usize];
        let mut area = DVec3::ZERO;
        for i in 1..size as usize - 1 {
            area += (p(i) - p(0)).cross(p(i + 1) - p(0));
        }
        for i in 0..size as usize {
            sums[t.face_normals[start + i] as usize] += area;
        }
        start += size as usize;
    }
    for (n, s) in t.normals.iter_mut().zip(&sums) {
        if *n == DVec3::ZERO {
            *n = s.normalize_or_zero();
        }
    }
    let mut seen = vec![false; t.normals.len()];
    for (&v, &n) in t.face_vertices.iter().zip(&t.face_normals) {
        if !std::mem::replace(&mut seen[n as usize], true) {
            vertex[v as usize] += t.normals[n as usize];
        }
    }
    t.vertex_normals = vertex.into_iter().map(DVec3::normalize_or_zero).collect();
}

/// Barycentric check points of a triangle: the points of its 4-division lattice other than
/// its corners (edge points included: an edge's deviation is the same from both sides).
pub const CHECK_POINTS: [[f64; 3]; 12] = [
    [0.75, 0.25, 0.0],
    [0.5, 0.5, 0.0],
    [0.25, 0.75, 0.0],
    [0.0, 0.75, 0.25],
    [0.0, 0.5, 0.5],
    [0.0, 0.25, 0.75],
    [0.25, 0.0, 0.75],
    [0.5, 0.0, 0.5],
    [0.75, 0.0, 0.25],
    [0.5, 0.25, 0.25],
    [0.25, 0.5, 0.25],
    [0.25, 0.25, 0.5],
];

/// Fraction of the tolerance the check points must meet, a margin for the deviation between
/// them.
const CHECK_MARGIN: f64 = 0.8;

/// Largest distance, over the barycentric points `bary`, between a point of polygon `k`'s
/// triangles and the limit surface at the same `(u, v)` of its parametric face.
pub fn chordal_error(
    ev: &Evaluator,
    t: &Tessellation,
    start: usize,
    size: usize,
    ptex: u32,
    bary: &[[f64; 3]],
) -> Result<f64> {
    let mut worst: f64 = 0.0;
    for k in 1..size - 1 {
        let c = [start, start + k, start + k + 1];
        for b in bary {
            let mut uv = [0.0; 2];
            let mut pos = DVec3::ZERO;
            for i in 0..3 {
                uv[0] += b[i] * t.corner_uv[c[i]][0];
                uv[1] += b[i] * t.corner_uv[c[i]][1];
                pos += b[i] * t.positions[t.face_vertices[c[i]] as usize];
            }
            let s = ev.evaluate(ptex, uv[0].clamp(0.0, 1.0), uv[1].clamp(0.0, 1.0))?;
            worst = worst.max(s.position.distance(pos));
        }
    }
    Ok(worst)
}

/// Parametric faces with a polygon farther than `tol` from the surface at a check point
/// (quads are checked as the fan of triangles from their first corner).
fn faces_over_tolerance(ev: &Evaluator, t: &Tessellation, tol: f64) -> Result<Vec<u32>> {
    let mut over = Vec::new();
    let mut start = 0;
    for (k, &size) in t.face_sizes.iter().enumerate() {
        let p = t.face_ptex[k];
        if over.last() != Some(&p)
            && chordal_error(ev, t, start, size as usize, p, &CHECK_POINTS)? > tol
        {
            over.push(p);
        }
        start += size as usize;
    }
    Ok(over)
}

#[cfg(test)]
mod tests;
