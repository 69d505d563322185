//! The exact limit surface at any `(face, u, v)`: position and first derivatives.
//!
//! Faces are addressed by OpenSubdiv's Ptex numbering (see [`super::ptex`]), or with
//! [`Evaluator::evaluate_in`] in Bfr's tiled domain too (see [`super::domain`]); faces
//! without limit surface are marked ([`super::surface`]). Each parametric
//! face is the root of a quadtree built at construction: a quad whose corners are regular is a
//! bicubic B-spline leaf (`super::patch_regular`); any other quad is refined one level —
//! only its neighbourhood, see `super::patch_topology` — and each of its four children is
//! treated the same way, down to [`CACHE_DEPTH`]. Below that depth (only near extraordinary
//! vertices, darts and slowly decaying sharpness) a point is evaluated by refining its
//! neighbourhood further on the spot until it falls into a regular sub-patch. A point exactly
//! on a vertex that never becomes regular (an extraordinary vertex, a dart, ...) takes the
//! vertex's exact limit. Derivatives are with respect to the Ptex face's `(u, v)`: a leaf at
//! depth `d` is scaled by `2^d`.
//!
//! The build looks at topology only: every point a patch or a deep fragment needs is
//! recorded as the weighted sum refinement computes it with (module `points`), and the
//! positions are run through that program afterwards — at construction, and again by
//! [`Evaluator::set_positions`], which gives bit for bit the evaluator built with the new
//! positions. Leaves and deep fragments hold indices into the program's points (as Far's
//! patches index its refined and local points), so an update computes the points and
//! nothing else.
//!
//! Evaluation allocates nothing except below [`CACHE_DEPTH`]; the evaluator is immutable
//! while evaluating and `Sync`, so many threads may evaluate at once.

use glam::DVec3;

use super::bspline::BicubicPatch;
use super::domain::Domain;
use super::patch_regular::{regular_patch, PatchPoints, NO_POINT};
use super::patch_topology::Neighbourhood;
use super::points::PointProgram;
use super::ptex::PtexFaces;
use super::sample::LimitSample;
use crate::control::{Control, SplitPoll};
use crate::error::{Error, Result};
use crate::mesh::Mesh;
use crate::options::SubdivOptions;
use crate::refine::step::refine_last;
use crate::refine::{interpolate, Primvar, VertexOrder};
use crate::topology::Level;

pub(crate) use batch::{BatchOutput, NoSurface};
use build::Builder;
pub use primvar::PrimvarSamples;

/// Depth to which irregular faces are refined and cached at construction.
pub const CACHE_DEPTH: u32 = 5;

/// Depth to which the faces around a face that repeats a vertex are cached at construction,
/// refining the whole fragment around it from its base level each time, as long as that
/// fragment stays within 16,384 faces.
pub const DEGENERATE_DEPTH: u32 = 6;

/// Largest refined fragment (faces) [`Evaluator::build_from_root`] builds.
const DEGENERATE_BUDGET: usize = 16_384;

/// Deepest on-the-spot refinement; a point still not in a regular sub-patch there is within
/// `2^-MAX_DEPTH` of a vertex and takes that vertex's limit.
const MAX_DEPTH: u32 = 96;

/// One quadtree node.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Node {
    /// A regular leaf: index into `patches`.
    Patch(u32),
    /// Refined: the four children are nodes `first..first + 4`, in quadrant order
    /// (0 at `(0,0)`, 1 at `(1,0)`, 2 at `(1,1)`, 3 at `(0,1)`).
    Split(u32),
    /// Not regular at the cache depth: index into `deep` (the neighbourhood, refined on demand).
    Deep(u32),
    /// A face without limit surface (hole, or boundary rule "none").
    NoSurface,
}

/// Exact Catmull-Clark limit evaluator for one control mesh and one set of options.
#[derive(Debug, Clone)]
pub struct Evaluator {
    mesh: Mesh,
    options: SubdivOptions,
    ptex: PtexFaces,
    /// The root node of each parametric face (held here rather than in `nodes`: one memory
    /// access less per evaluation).
    roots: Vec<Node>,
    nodes: Vec<Node>,
    /// Every point of `program` under the current positions.
    points: Vec<DVec3>,
    /// Each leaf's control points as points of `program`; the slots beyond a sharp side
    /// name point 0 (the phantom construction overwrites them).
    patch_points: Vec<PatchPoints>,
    deep: Vec<DeepFragment>,
    /// Every point the leaves and deep fragments read, over the control points.
    program: PointProgram,
    /// Threads for batches of points (0: all cores).
    threads: usize,
}

/// Estimated bytes of the evaluator of `mesh` (what [`Evaluator::with_control`] checks
/// against the memory budget): about 1 KiB per parametric face (a bicubic patch of 16
/// points and its program, and the quadtree's refined leaves near extraordinary vertices)
/// and 64 bytes per face-vertex index (topology of the base level and the copied mesh).
pub fn evaluator_bytes(mesh: &Mesh) -> u64 {
    let ptex: u64 = mesh
        .face_sizes()
        .iter()
        .map(|&n| if n == 4 { 1 } else { u64::from(n) })
        .sum();
    1024 * ptex + 64 * mesh.face_indices().len() as u64
}

/// A fragment refined on demand at evaluation (a [`Node::Deep`]).
#[derive(Debug, Clone)]
struct DeepFragment {
    nb: Neighbourhood,
    /// Each vertex as a point of the evaluator's program.
    points: Vec<u32>,
}

impl Evaluator {
    /// Build the evaluator of `mesh` under `options` (the caller's resolved options; the
    /// mesh's own tags are not consulted here).
    ///
    /// Errors: [`Error::InvalidMesh`] when the mesh has more parametric faces than fit in
    /// `u32`; errors of the refinement of an irregular neighbourhood.
    pub fn new(mesh: &Mesh, options: &SubdivOptions) -> Result<Evaluator> {
        Evaluator::build_on(mesh, options, 0, &Control::NONE)
    }

    /// [`Evaluator::new`] built on `threads` threads (0: all cores), which it keeps for
    /// batches of points ([`Evaluator::set_threads`]). The result does not depend on it,
    /// bit for bit.
    ///
    /// Errors: as [`Evaluator::new`].
    pub fn with_threads(mesh: &Mesh, options: &SubdivOptions, threads: usize) -> Result<Evaluator> {
        Evaluator::build_on(mesh, options, threads, &Control::NONE)
    }

    /// [`Evaluator::new`] with progress, cancellation and a memory budget: `control` is
    /// polled through the setup before the first face (the Ptex numbering, the mesh's
    /// neighbourhood and its base level's passes, at fraction 0), at every face of the build
    /// (0–95 %) and every thousand or so points of the positions' pass (95–100 %), and
    /// the build is refused before allocating when [`evaluator_bytes`] is above the budget.
    ///
    /// Errors: those of [`Evaluator::new`]; [`Error::Cancelled`] and
    /// [`Error::LimitExceeded`] from `control`.
    pub fn with_control(
        mesh: &Mesh,
        options: &SubdivOptions,
        control: &Control,
    ) -> Result<Evaluator> {
        Evaluator::build_on(mesh, options, 0, control)
    }

    /// [`Evaluator::with_threads`] and [`Evaluator::with_control`] at once.
    ///
    /// Errors: those of [`Evaluator::with_control`].
    pub fn build_on(
        mesh: &Mesh,
        options: &SubdivOptions,
        threads: usize,
        control: &Control,
    ) -> Result<Evaluator> {
        control.report(0.0)?;
        control.check_memory(
            &format!("the evaluator of a mesh of {} faces", mesh.num_faces()),
            evaluator_bytes(mesh),
        )?;
        let mut ev = Evaluator::topology(mesh, options, threads, &control.stage(0.0, 0.95))?;
        ev.program
            .run_polled(mesh.positions(), &mut ev.points, &control.stage(0.95, 1.0))?;
        control.report(1.0)?;
        Ok(ev)
    }

    /// The structure of the evaluator of `mesh`: quadtrees, patches and deep fragments as
    /// points of the program, no positions yet. Contiguous ranges of faces are built on
    /// `threads` threads and joined in face order: the same evaluator as one thread builds.
    /// The first range reports to `progress` (its fraction stands for the whole: the ranges
    /// are equal); a cancel there stops the other ranges at their next face.
    fn topology(
        mesh: &Mesh,
        options: &SubdivOptions,
        threads: usize,
        progress: &Control,
    ) -> Result<Evaluator> {
        // The setup before the first face (tens of milliseconds on a large mesh, mostly the
        // base level behind `faces_without_surface`) is polled at fraction 0.
        let setup = progress.stage(0.0, 0.0);
        let ptex = PtexFaces::new(mesh)?;
        setup.report(0.0)?;
        let global = Neighbourhood::from_mesh(mesh, options);
        setup.report(0.0)?;
        let no_surface = faces_without_surface(mesh, options, &setup)?;
        let split = SplitPoll::default();
        let parts = super::parallel::map_ranges(mesh.num_faces(), threads, |faces| {
            let mut b = Builder::new(options, mesh.num_vertices());
            let reporter = (faces.start == 0).then_some(progress);
            b.faces(mesh, &global, &no_surface, faces, reporter, &split)?;
            Ok(b)
        });
        let mut parts = parts.into_iter();
        let mut whole = parts.next().expect("at least one range")?;
        for part in parts {
            whole.append(part?);
        }
        let Builder {
            roots,
            nodes,
            mut patch_points,
            mut deep,
            mut program,
            ..
        } = whole;
        let mut kept: Vec<&mut [u32]> = patch_points
            .iter_mut()
            .map(|p| &mut p.vertices[..])
            .collect();
        kept.extend(deep.iter_mut().map(|d| &mut d.points[..]));
        program.prune(&mut kept);
        // Evaluation then gathers 16 points without a branch per point.
        for p in &mut patch_points {
            for v in &mut p.vertices {
                if *v == NO_POINT {
                    *v = 0;
                }
            }
        }
        Ok(Evaluator {
            mesh: mesh.clone(),
            options: *options,
            ptex,
            roots,
            nodes,
            points: Vec::new(),
            patch_points,
            deep,
            program,
            threads,
        })
    }

    /// Replace the control points' positions (one per control vertex, in vertex order): the
    /// evaluator then evaluates exactly as one built from the mesh with these positions (bit
    /// for bit), at the cost of a pass over its points rather than a build.
    ///
    /// Errors ([`Error::InvalidArgument`]; the evaluator is unchanged): not one position per
    /// control vertex, a non-finite coordinate.
    pub fn set_positions(&mut self, positions: &[DVec3]) -> Result<()> {
        let nv = self.mesh.num_vertices();
        if positions.len() != nv {
            return Err(Error::invalid_argument(format!(
                "{} positions given for a mesh of {nv} vertices",
                positions.len()
            )));
        }
        if let Some((i, p)) = positions.iter().enumerate().find(|(_, p)| !p.is_finite()) {
            return Err(Error::invalid_argument(format!(
                "position {i} has a non-finite coordinate ({} {} {})",
                p.x, p.y, p.z
            )));
        }
        self.update(positions);
        self.mesh.set_positions(positions);
        Ok(())
    }

    /// The points from `positions` (checked), into the points' own buffer.
    fn update(&mut self, positions: &[DVec3]) {
        self.program.run_into(positions, &mut self.points);
    }

    /// Set how many threads batches of points ([`Evaluator::evaluate_many`],
    /// [`Evaluator::evaluate_points`]) run on: 0 (the default) for all cores (a position
    /// update is one pass over the points, on the calling thread). The results do not
    /// depend on it, bit for bit.
    pub fn set_threads(&mut self, threads: usize) {
        self.threads = threads;
    }

    /// The thread setting ([`Evaluator::set_threads`]; 0: all cores).
    pub fn threads(&self) -> usize {
        self.threads
    }

    /// Number of points the evaluator computes from the control points (control points
    /// included) on each [`Evaluator::set_positions`].
    pub fn num_points(&self) -> usize {
        self.program.num_points()
    }

    /// The options this evaluator applies.
    pub fn options(&self) -> &SubdivOptions {
        &self.options
    }

    /// The control mesh.
    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// The Ptex numbering of the mesh's faces (how `face` in [`Evaluator::evaluate`] is meant).
    pub fn ptex_faces(&self) -> &PtexFaces {
        &self.ptex
    }

    /// Number of parametric faces: the valid range of `face` in [`Evaluator::evaluate`].
    pub fn num_parametric_faces(&self) -> usize {
        self.ptex.len()
    }

    /// Limit position and derivatives at `(u, v)` of parametric face `face`.
    ///
    /// Errors ([`Error::InvalidArgument`]): `face` out of range, `u` or `v` outside `[0, 1]`
    /// or NaN, a hole face, a face without limit surface (boundary interpolation "none").
    pub fn evaluate(&self, face: u32, u: f64, v: f64) -> Result<LimitSample> {
        self.evaluate_with(&self.points, face, u, v)
    }

    /// [`Evaluator::evaluate`] under `points` (the program's points from the positions or
    /// from three components of a primvar).
    fn evaluate_with(&self, points: &[DVec3], face: u32, u: f64, v: f64) -> Result<LimitSample> {
        let Some(&root) = self.roots.get(face as usize) else {
            return Err(Error::invalid_argument(format!(
                "face {face} is out of range; the mesh has {} parametric faces",
                self.roots.len()
            )));
        };
        if !(0.0..=1.0).contains(&u) || !(0.0..=1.0).contains(&v) {
            return Err(Error::invalid_argument(format!(
                "(u, v) = ({u}, {v}) on face {face} is outside [0, 1]"
            )));
        }
        let (node, s, t, scale, _) = self.descend(root, u, v);
        match node {
            Node::Patch(p) => {
                let (position, ds, dt) = self.evaluate_leaf(points, p, s, t);
                Ok(LimitSample {
                    position,
                    du: ds * scale,
                    dv: dt * scale,
                })
            }
            Node::Deep(d) => self.evaluate_fragment(points, d, s, t, scale),
            Node::NoSurface => Err(self.no_surface_error(face)),
            Node::Split(_) => unreachable!("a descent ends below every split"),
        }
    }

    /// [`Evaluator::evaluate_deep`] in deep fragment `d` under `points`.
    fn evaluate_fragment(
        &self,
        points: &[DVec3],
        d: u32,
        s: f64,
        t: f64,
        scale: f64,
    ) -> Result<LimitSample> {
        let fragment = &self.deep[d as usize];
        let vertices: Vec<DVec3> = fragment
            .points
            .iter()
            .map(|&p| points[p as usize])
            .collect();
        self.evaluate_deep(&fragment.nb, &vertices, s, t, scale)
    }

    /// The node below `root` that holds `(u, v)` (never a split), the point's coordinates
    /// in it, the derivatives' scale (`2^depth`) and its depth.
    #[inline]
    fn descend(&self, root: Node, u: f64, v: f64) -> (Node, f64, f64, f64, u8) {
        let (mut node, mut s, mut t, mut scale, mut depth) = (root, u, v, 1.0, 0u8);
        while let Node::Split(first) = node {
            let (q, cs, ct) = quadrant(s, t);
            node = self.nodes[(first + q) as usize];
            (s, t, scale, depth) = (cs, ct, scale * 2.0, depth + 1);
        }
        (node, s, t, scale, depth)
    }

    /// Position and derivatives at `(s, t)` of leaf `leaf` under `points`: the patch's
    /// points are read where they are, copied only to build phantom points.
    #[inline]
    fn evaluate_leaf(&self, points: &[DVec3], leaf: u32, s: f64, t: f64) -> (DVec3, DVec3, DVec3) {
        let leaf = &self.patch_points[leaf as usize];
        if leaf.boundary == 0 {
            BicubicPatch::evaluate_indexed(points, &leaf.vertices, s, t)
        } else {
            let control = leaf.vertices.map(|v| points[v as usize]);
            BicubicPatch::with_boundary(control, leaf.boundary).evaluate(s, t)
        }
    }

    /// The bicubic patch of parametric face `face` when the whole face is one regular leaf
    /// ([`Evaluator::evaluate`] there is `patch.evaluate(u, v)` bit for bit, unscaled),
    /// `None` otherwise: for callers that keep their own per-face data beside the patch
    /// (the shell's crust), so that one read serves both.
    pub(crate) fn root_patch(&self, face: u32) -> Option<BicubicPatch> {
        match self.roots.get(face as usize)? {
            Node::Patch(p) => {
                let leaf = &self.patch_points[*p as usize];
                let control = leaf.vertices.map(|v| self.points[v as usize]);
                Some(BicubicPatch::with_boundary(control, leaf.boundary))
            }
            _ => None,
        }
    }

    fn no_surface_error(&self, face: u32) -> Error {
        let base = self.ptex.locate(face).map_or(face, |(f, _)| f);
        if self.mesh.holes().contains(&base) {
            Error::invalid_argument(format!("face {face} is a hole: it has no limit surface"))
        } else {
            Error::invalid_argument(format!(
                "face {face} has no limit surface: it touches the boundary and the boundary \
                 interpolation is \"none\""
            ))
        }
    }

    /// Exact limit position and derivatives at every control vertex, in vertex order (see
    /// [`super::vertex_limit`] for the derivatives' convention), [`LimitSample::NO_SURFACE`]
    /// for a vertex without limit surface.
    ///
    /// Errors: as [`super::limit_vertex_samples`].
    pub fn limit_vertices(&self) -> Result<Vec<LimitSample>> {
        super::limit_vertex_samples(&self.mesh, &self.options)
    }

    /// Evaluate many points; `faces`, `u` and `v` must have the same length. Stops at the
    /// first bad point, naming its index; a point without limit surface is a bad point here
    /// (see [`Evaluator::evaluate_points`] for the marking alternative).
    pub fn evaluate_many(&self, faces: &[u32], u: &[f64], v: &[f64]) -> Result<Vec<LimitSample>> {
        let mut out = vec![LimitSample::default(); faces.len()];
        self.evaluate_batch(Domain::Ptex, (faces, u, v), NoSurface::Error, &mut out[..])?;
        Ok(out)
    }

    /// Whether parametric (Ptex) face `face` has a limit surface (see [`super::surface`]);
    /// false when out of range.
    pub fn has_surface(&self, face: u32) -> bool {
        self.roots
            .get(face as usize)
            .is_some_and(|&r| r != Node::NoSurface)
    }

    /// Limit position and derivatives at `(face, u, v)` given in `domain` (see
    /// [`super::domain`]; derivatives in that domain's units), or `None` where there is no
    /// limit surface (a hole, a face under boundary interpolation "none" that touches the
    /// boundary).
    ///
    /// Errors ([`Error::InvalidArgument`]): `face` out of range, `(u, v)` NaN or outside the
    /// domain.
    pub fn evaluate_in(
        &self,
        domain: Domain,
        face: u32,
        u: f64,
        v: f64,
    ) -> Result<Option<LimitSample>> {
        let p = self.ptex.locate_in(domain, face, u, v)?;
        if !self.has_surface(p.face) {
            return Ok(None);
        }
        let s = self.evaluate(p.face, p.u, p.v)?;
        Ok(Some(LimitSample {
            position: s.position,
            du: s.du * p.derivative_scale,
            dv: s.dv * p.derivative_scale,
        }))
    }

    /// [`Evaluator::evaluate_in`] for many points (`faces`, `u` and `v` of the same length):
    /// `None` for each point without limit surface, the others evaluated. Stops only at a
    /// bad point (naming its index); [`super::require_surface`] turns the result into the
    /// strict form.
    pub fn evaluate_points(
        &self,
        domain: Domain,
        faces: &[u32],
        u: &[f64],
        v: &[f64],
    ) -> Result<Vec<Option<LimitSample>>> {
        let mut out = vec![None; faces.len()];
        self.evaluate_batch(domain, (faces, u, v), NoSurface::Mark, &mut out[..])?;
        Ok(out)
    }

    /// Exact limit position and derivatives at every control vertex, in vertex order, `None`
    /// for a vertex without limit surface (see [`super::surface`]).
    ///
    /// Errors: as [`super::limit_vertex_samples`].
    pub fn vertex_limits(&self) -> Result<Vec<Option<LimitSample>>> {
        Ok(self
            .limit_vertices()?
            .into_iter()
            .map(|s| s.has_surface().then_some(s))
            .collect())
    }

    /// Refine `nb` (vertex positions `positions`) on the spot until `(s, t)` lies in a
    /// regular sub-patch.
    fn evaluate_deep(
        &self,
        nb: &Neighbourhood,
        positions: &[DVec3],
        s: f64,
        t: f64,
        scale: f64,
    ) -> Result<LimitSample> {
        let mut owned;
        let (mut nb, mut positions) = (nb, positions);
        let (mut s, mut t, mut scale) = (s, t, scale);
        for _ in CACHE_DEPTH..MAX_DEPTH {
            if let Some(p) = regular_patch(nb, 0, &self.options, positions) {
                let (position, ds, dt) = p.evaluate(s, t);
                return Ok(LimitSample {
                    position,
                    du: ds * scale,
                    dv: dt * scale,
                });
            }
            if let Some(k) = corner_at(s, t) {
                if let Some(sample) =
                    super::patch_corner::corner_limit(nb, positions, k, &self.options, scale)?
                {
                    return Ok(sample);
                }
            }
            let (refined, refined_positions) = refine_fragment(nb, positions, &self.options);
            let (q, cs, ct) = quadrant(s, t);
            let (cut, globals) = refined.around_face(q);
            let cut_positions: Vec<DVec3> = globals
                .iter()
                .map(|&g| refined_positions[g as usize])
                .collect();
            owned = (cut, cut_positions);
            (nb, positions) = (&owned.0, &owned.1);
            (s, t, scale) = (cs, ct, scale * 2.0);
        }
        let k = nearest_corner(s, t);
        super::patch_corner::corner_limit(nb, positions, k, &self.options, scale)?.ok_or_else(
            || {
                Error::NumericalFailure(format!(
                    "no regular sub-patch within {MAX_DEPTH} levels of refinement"
                ))
            },
        )
    }
}

/// `eval(faces[i], u[i], v[i])` for every point, on `threads` threads (0: all cores); the
/// three lists must have the same length. An [`Error::InvalidArgument`] names the point (the
/// first bad one, whatever the thread count); other errors pass unchanged.
pub(crate) fn each_point<T: Send>(
    faces: &[u32],
    u: &[f64],
    v: &[f64],
    threads: usize,
    eval: impl Fn(u32, f64, f64) -> Result<T> + Sync,
) -> Result<Vec<T>> {
    check_point_lists(faces, u, v)?;
    super::parallel::try_map(faces.len(), threads, |i| {
        eval(faces[i], u[i], v[i]).map_err(|e| match e {
            Error::InvalidArgument(m) => Error::InvalidArgument(format!("point {i}: {m}")),
            other => other,
        })
    })
}

/// A batch's `faces`, `u` and `v` must have the same length ([`Error::InvalidArgument`]).
fn check_point_lists(faces: &[u32], u: &[f64], v: &[f64]) -> Result<()> {
    if faces.len() != u.len() || faces.len() != v.len() {
        return Err(Error::invalid_argument(format!(
            "{} faces, {} u and {} v values: the three lists must have the same length",
            faces.len(),
            u.len(),
            v.len()
        )));
    }
    Ok(())
}

/// One level of refinement of fragment `nb` with vertex data `values`; the children of its
/// face 0 are faces `0..n` of the result (Far's child order).
fn refine_fragment<T: Primvar>(
    nb: &Neighbourhood,
    values: &[T],
    options: &SubdivOptions,
) -> (Neighbourhood, Vec<T>) {
    let level = nb.level(options);
    let r = refine_last(&level, VertexOrder::VerticesFirst);
    let child_values = interpolate(&level, &r, values);
    (nb.refined(&level, &r), child_values)
}

/// The quadrant of `(s, t)` and the coordinates in it. Quadrant `q` is child `q` of a quad
/// in Far's refinement, with the same orientation.
#[inline]
fn quadrant(s: f64, t: f64) -> (u32, f64, f64) {
    let right = s >= 0.5;
    let top = t >= 0.5;
    let q = match (right, top) {
        (false, false) => 0,
        (true, false) => 1,
        (true, true) => 2,
        (false, true) => 3,
    };
    let cs = if right { 2.0 * s - 1.0 } else { 2.0 * s };
    let ct = if top { 2.0 * t - 1.0 } else { 2.0 * t };
    (q, cs, ct)
}

/// The corner `(s, t)` is exactly on, if any.
fn corner_at(s: f64, t: f64) -> Option<usize> {
    match (s, t) {
        (0.0, 0.0) => Some(0),
        (1.0, 0.0) => Some(1),
        (1.0, 1.0) => Some(2),
        (0.0, 1.0) => Some(3),
        _ => None,
    }
}

fn nearest_corner(s: f64, t: f64) -> usize {
    match (s >= 0.5, t >= 0.5) {
        (false, false) => 0,
        (true, false) => 1,
        (true, true) => 2,
        (false, true) => 3,
    }
}

/// Faces with no limit surface: holes, and under boundary interpolation "none" the faces at
/// a boundary or non-manifold vertex with a boundary edge not tagged infinitely sharp — the
/// holes of the base [`Level`], which follows Far's rule (see [`super::surface`]). The base
/// level's passes poll `control`.
fn faces_without_surface(
    mesh: &Mesh,
    options: &SubdivOptions,
    control: &Control,
) -> Result<Vec<bool>> {
    let level = Level::from_mesh_polled(mesh, options, control)?;
    Ok((0..mesh.num_faces())
        .map(|f| level.is_face_hole(f))
        .collect())
}

mod batch;
mod build;
mod primvar;
#[cfg(test)]
mod tests;
