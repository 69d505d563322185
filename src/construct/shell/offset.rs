//! Offset evaluation: `O(face, u, v) = S − D`, the exact limit surface `S` minus the Bézier
//! crust `D` ([`super::crust`]) of the face at the crust's level, with its first derivatives.
//!
//! The crust is built on the surface refined `level` times ([`OffsetSurface::new`]): the
//! refined control mesh has the same limit surface, four times as many faces per level, and
//! so more corners where the offset is exactly `c` away. A point `(face, u, v)` of the
//! input mesh (Ptex or Bfr's domain, as the evaluator takes it) is mapped to its face at
//! that level: a quad's child `q` covers quadrant `q` of its parameter square with the same
//! orientation, and the children of an N-gon are its Ptex sub-faces. Derivatives are
//! returned with respect to the caller's `(u, v)`.
//!
//! A mesh with faces other than quads is offset at level 1 or more: at level 0 the crust of
//! an N-gon's sub-faces would have corners at its edge midpoints, which the quad across the
//! edge does not have, and the offset would tear along that edge.

use glam::DVec3;

use super::corners::corner_directions;
use super::crust::Crust;
use crate::error::{Error, Result};
use crate::eval::bspline::BicubicPatch;
use crate::eval::evaluator::each_point;
use crate::eval::ptex::PtexFaces;
use crate::eval::{Domain, Evaluator, LimitSample};
use crate::mesh::Mesh;
use crate::options::SubdivOptions;
use crate::refine::refine_uniform;

/// Deepest crust level accepted.
pub const MAX_LEVEL: u32 = 6;

/// Which side of the surface the offset goes to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Side {
    /// Against the normal `S_u × S_v` (into a closed, outward-oriented solid). The default.
    #[default]
    Inward,
    /// Along the normal.
    Outward,
}

/// The settings of an offset.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OffsetSettings {
    /// The thickness `c` (model units, finite, > 0).
    pub thickness: f64,
    /// Which side the offset goes to.
    pub side: Side,
    /// The crust's refinement level (0: the paper's scheme on the input mesh).
    pub level: u32,
    /// Accept points where the offset folds (`(O_u × O_v) · n ≤ 0`) instead of failing.
    pub accept_folds: bool,
}

impl OffsetSettings {
    /// Thickness `c` inward, level 0, folds refused.
    pub fn new(thickness: f64) -> OffsetSettings {
        OffsetSettings {
            thickness,
            side: Side::Inward,
            level: 0,
            accept_folds: false,
        }
    }

    /// The thickness must be finite and > 0, the level at most [`MAX_LEVEL`].
    pub fn check(&self) -> Result<()> {
        if !(self.thickness.is_finite() && self.thickness > 0.0) {
            return Err(Error::invalid_argument(format!(
                "thickness = {} must be a finite number > 0",
                self.thickness
            )));
        }
        if self.level > MAX_LEVEL {
            return Err(Error::invalid_argument(format!(
                "crust level {} is above the maximum {MAX_LEVEL}",
                self.level
            )));
        }
        Ok(())
    }
}

/// One point of the offset surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OffsetSample {
    /// Position of the offset `O`.
    pub position: DVec3,
    /// `∂O/∂u`.
    pub du: DVec3,
    /// `∂O/∂v`.
    pub dv: DVec3,
    /// The limit surface `S` at the same parameter.
    pub surface: LimitSample,
}

impl OffsetSample {
    /// Whether the offset folds here: `(O_u × O_v) · (S_u × S_v) ≤ 0` (the offset's
    /// orientation is reversed or degenerate: the thickness passed one centre of curvature),
    /// or `O_u · S_u ≤ 0` or `O_v · S_v ≤ 0` (it passed both, as inside a sphere thinner
    /// than the thickness, where the orientation comes back).
    pub fn folds(&self) -> bool {
        self.folds_inner()
    }

    /// The offset's own position and derivatives, as a [`LimitSample`] (what the CLI and
    /// the C API print and write).
    pub fn offset(&self) -> LimitSample {
        LimitSample {
            position: self.position,
            du: self.du,
            dv: self.dv,
        }
    }

    fn folds_inner(&self) -> bool {
        let s = &self.surface;
        self.du.cross(self.dv).dot(s.du.cross(s.dv)) <= 0.0
            || self.du.dot(s.du) <= 0.0
            || self.dv.dot(s.dv) <= 0.0
    }
}

/// The offset of one mesh's limit surface: build once, evaluate many points.
#[derive(Debug, Clone)]
pub struct OffsetSurface {
    settings: OffsetSettings,
    /// The input mesh's parametric faces.
    ptex: PtexFaces,
    /// First level-1 face of each control face of the input mesh (level ≥ 1).
    first_child: Vec<u32>,
    /// Whether each control face of the input is a quad.
    quad: Vec<bool>,
    /// The evaluator of the mesh refined `level` times (all quads when level ≥ 1).
    fine: Evaluator,
    /// The signed corner vector of every vertex of the refined mesh (`O = S − D`).
    corners: Vec<DVec3>,
    /// Per refined face, its crust (built once, so a point reads one face's coefficients
    /// instead of four vertices' vectors) and beside it the face's bicubic patch when the
    /// face is one regular leaf of the evaluator: one read serves both.
    faces: Vec<FaceRecord>,
    /// The crease vertex whose miter each refined vertex carries (fold messages).
    mitered_from: Vec<Option<u32>>,
}

/// What evaluating a point of one refined face reads.
#[derive(Debug, Clone)]
struct FaceRecord {
    crust: Crust,
    /// The surface, when the face is one bicubic patch ([`Evaluator::evaluate`] otherwise).
    leaf: Option<BicubicPatch>,
}

/// Whether every face of `mesh` is a quad.
fn all_quads(mesh: &Mesh) -> bool {
    mesh.face_sizes().iter().all(|&n| n == 4)
}

impl OffsetSurface {
    /// The offset of `mesh`'s limit surface under `options`. The crust level is
    /// `settings.level`, raised to 1 for a mesh with faces other than quads.
    ///
    /// Errors: [`Error::NonManifold`] for a non-manifold mesh; [`Error::InvalidArgument`]: a
    /// bad thickness or level; a vertex without normal or a crease too sharp to miter ([`super::corners`]); with
    /// `accept_folds` false, an offset that folds on the lattice of
    /// [`FOLD_LATTICE`]` + 1` points a side of every refined face (the thickness is beyond
    /// the local radius of curvature on the concave side), naming the face and point.
    pub fn new(mesh: &Mesh, options: &SubdivOptions, settings: OffsetSettings) -> Result<Self> {
        settings.check()?;
        let report = crate::mesh::validate::check(mesh);
        if !report.is_manifold() {
            return Err(Error::NonManifold(format!(
                "an offset needs a manifold mesh: {} non-manifold edges, {} non-manifold \
                 vertices (first: {:?}), {} faces repeating a vertex",
                report.non_manifold_edges.len(),
                report.non_manifold_vertices.len(),
                report.non_manifold_vertices.first(),
                report.faces_with_repeated_vertices.len()
            )));
        }
        let level = if all_quads(mesh) {
            settings.level
        } else {
            settings.level.max(1)
        };
        let fine_mesh = refine_uniform(mesh, options, level)?;
        let fine = Evaluator::new(&fine_mesh, options)?;
        let base_vertices = mesh.num_vertices();
        let name = |v: usize| {
            if level == 0 || v < base_vertices {
                format!("vertex {v}")
            } else {
                format!("vertex {v} of the mesh refined {level} times")
            }
        };
        let sign = match settings.side {
            Side::Inward => 1.0,
            Side::Outward => -1.0,
        };
        let (directions, mitered_from) = corner_directions(&fine, settings.thickness, &name)?;
        let corners: Vec<DVec3> = directions
            .into_iter()
            .map(|m| m * (sign * settings.thickness))
            .collect();
        let faces = (0..fine_mesh.num_faces())
            .map(|g| {
                let f = fine_mesh.face(g);
                FaceRecord {
                    crust: Crust::new(&[0, 1, 2, 3].map(|k| corners[f[k] as usize])),
                    leaf: fine.root_patch(g as u32),
                }
            })
            .collect();
        let mut first_child = Vec::with_capacity(mesh.num_faces());
        let mut next = 0u32;
        for &n in mesh.face_sizes() {
            first_child.push(next);
            next += n;
        }
        let offset = OffsetSurface {
            settings: OffsetSettings { level, ..settings },
            ptex: PtexFaces::new(mesh)?,
            first_child,
            quad: mesh.face_sizes().iter().map(|&n| n == 4).collect(),
            fine,
            corners,
            faces,
            mitered_from,
        };
        if !settings.accept_folds {
            offset.check_folds()?;
        }
        Ok(offset)
    }

    /// The settings, with the level actually used.
    pub fn settings(&self) -> &OffsetSettings {
        &self.settings
    }

    /// The number of parametric (Ptex) faces of the input mesh.
    pub fn num_parametric_faces(&self) -> u32 {
        self.ptex.len() as u32
    }

    /// The evaluator of the refined mesh the crust is built on.
    pub fn fine(&self) -> &Evaluator {
        &self.fine
    }

    /// The signed corner vector of each vertex of the refined mesh: the offset there is the
    /// vertex's limit position minus this.
    pub fn corner_vectors(&self) -> &[DVec3] {
        &self.corners
    }

    /// The offset at `(u, v)` of face `face` of the refined mesh (its own parameters),
    /// derivatives multiplied by `scale`.
    ///
    /// Errors ([`Error::InvalidArgument`]): as [`Evaluator::evaluate`].
    pub fn evaluate_fine(&self, face: u32, u: f64, v: f64, scale: f64) -> Result<OffsetSample> {
        if !(0.0..=1.0).contains(&u) || !(0.0..=1.0).contains(&v) {
            // The evaluator's message.
            self.fine.evaluate(face, u, v)?;
        }
        self.sample(face, u, v, scale)
    }

    /// [`OffsetSurface::evaluate_fine`] at `(u, v)` in `[0, 1]²`.
    #[inline]
    fn sample(&self, face: u32, u: f64, v: f64, scale: f64) -> Result<OffsetSample> {
        let Some(record) = self.faces.get(face as usize) else {
            return Err(Error::invalid_argument(format!(
                "face {face} is out of range; the mesh has {} parametric faces",
                self.faces.len()
            )));
        };
        let s = match &record.leaf {
            Some(patch) => {
                let (position, du, dv) = patch.evaluate(u, v);
                LimitSample { position, du, dv }
            }
            None => self.fine.evaluate(face, u, v)?,
        };
        let (value, du, dv) = record.crust.evaluate(u, v);
        let mut o = OffsetSample {
            position: s.position - value,
            du: s.du - du,
            dv: s.dv - dv,
            surface: s,
        };
        if scale != 1.0 {
            for d in [&mut o.du, &mut o.dv, &mut o.surface.du, &mut o.surface.dv] {
                *d *= scale;
            }
        }
        Ok(o)
    }

    /// The refined face, its `(u, v)` and the derivative factor of Ptex point
    /// `(face, u, v)` of the input mesh.
    #[inline]
    pub fn locate(&self, face: u32, u: f64, v: f64) -> Result<(u32, f64, f64, f64)> {
        if self.settings.level == 0 {
            return Ok((face, u, v, 1.0));
        }
        let (control, sub) = self.ptex.locate(face).ok_or_else(|| {
            Error::invalid_argument(format!(
                "face {face} is out of range; the mesh has {} parametric faces",
                self.ptex.len()
            ))
        })?;
        let c = control as usize;
        let (mut g, mut s, mut t, mut scale) = if self.quad[c] {
            let (q, s, t) = quadrant(u, v);
            (self.first_child[c] + q, s, t, 2.0)
        } else {
            (self.first_child[c] + sub.unwrap_or(0), u, v, 1.0)
        };
        for _ in 1..self.settings.level {
            let (q, cs, ct) = quadrant(s, t);
            (g, s, t, scale) = (4 * g + q, cs, ct, scale * 2.0);
        }
        Ok((g, s, t, scale))
    }

    /// The offset at Ptex point `(face, u, v)` of the input mesh. Folds are not checked
    /// here ([`OffsetSample::folds`]).
    ///
    /// Errors ([`Error::InvalidArgument`]): as [`Evaluator::evaluate`].
    #[inline]
    pub fn evaluate(&self, face: u32, u: f64, v: f64) -> Result<OffsetSample> {
        if !(0.0..=1.0).contains(&u) || !(0.0..=1.0).contains(&v) {
            return Err(Error::invalid_argument(format!(
                "(u, v) = ({u}, {v}) on face {face} is outside [0, 1]"
            )));
        }
        let (g, s, t, scale) = self.locate(face, u, v)?;
        self.sample(g, s, t, scale)
    }

    /// The offset at many points given in `domain` (derivatives in its units), `None` where
    /// there is no limit surface ([`OffsetSurface::evaluate_in`] at each point), on the
    /// evaluator's threads ([`OffsetSurface::set_threads`]; the result does not depend on
    /// them, bit for bit).
    ///
    /// Errors: lists of different lengths ([`Error::InvalidArgument`]); the error of the
    /// lowest failing point, an [`Error::InvalidArgument`] prefixed by `point {i}: ` (a bad
    /// point, a fold), other kinds unchanged.
    pub fn evaluate_points(
        &self,
        domain: Domain,
        faces: &[u32],
        u: &[f64],
        v: &[f64],
    ) -> Result<Vec<Option<OffsetSample>>> {
        each_point(faces, u, v, self.fine.threads(), |f, u, v| {
            self.evaluate_in(domain, f, u, v)
        })
    }

    /// The offset at `(face, u, v)` given in `domain` (derivatives in its units), `None`
    /// where there is no limit surface. With `accept_folds` false in the settings a point
    /// where the offset folds is an error naming it.
    ///
    /// Errors ([`Error::InvalidArgument`]): a bad point (as [`Evaluator::evaluate_in`]); a
    /// folded point. [`Error::NumericalFailure`] as [`Evaluator::evaluate`].
    pub fn evaluate_in(
        &self,
        domain: Domain,
        face: u32,
        u: f64,
        v: f64,
    ) -> Result<Option<OffsetSample>> {
        let p = self.ptex.locate_in(domain, face, u, v)?;
        let (g, s, t, scale) = self.locate(p.face, p.u, p.v)?;
        if !self.fine.has_surface(g) {
            return Ok(None);
        }
        let mut o = self.sample(g, s, t, scale)?;
        if !self.settings.accept_folds && o.folds() {
            return Err(Error::invalid_argument(fold_message(
                &format!("face {face}"),
                u,
                v,
                self.settings.thickness,
            )));
        }
        for d in [&mut o.du, &mut o.dv, &mut o.surface.du, &mut o.surface.dv] {
            *d *= p.derivative_scale;
        }
        Ok(Some(o))
    }

    /// Set how many threads batches of points ([`OffsetSurface::evaluate_points`]) run on:
    /// 0 (the default) for all cores, as [`Evaluator::set_threads`].
    pub fn set_threads(&mut self, threads: usize) {
        self.fine.set_threads(threads);
    }

    /// Fail at the first refined face whose offset folds on its fold lattice.
    fn check_folds(&self) -> Result<()> {
        let n = FOLD_LATTICE;
        for g in 0..self.fine.mesh().num_faces() as u32 {
            if !self.fine.has_surface(g) {
                continue;
            }
            for i in 0..=n {
                for j in 0..=n {
                    let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                    let o = self.evaluate_fine(g, u, v, 1.0)?;
                    // At a corner where the surface's own parameterization degenerates the
                    // orientation test says nothing.
                    let normal = o.surface.du.cross(o.surface.dv);
                    if normal.length() > 0.0 && o.folds() {
                        let refined = match self.settings.level {
                            0 => String::new(),
                            l => format!(" of the mesh refined {l} times"),
                        };
                        let at = format!("face {g}{refined}");
                        // Next to a crease the miter's sideways shift is the likely cause.
                        let face = self.fine.mesh().face(g as usize);
                        let why = match face.iter().find_map(|&v| self.mitered_from[v as usize]) {
                            Some(x) => format!(
                                "next to the crease or corner at vertex {x}{refined}, whose \
                                 mitered corner vector moves the offset sideways by more than \
                                 the refined faces there are wide (corners of three or more \
                                 sectors, sides narrower than the feathering); use a coarser \
                                 crust level, a smaller thickness,"
                            ),
                            None => "the thickness exceeds the radius of curvature on the \
                                     concave side; use a smaller thickness,"
                                .to_string(),
                        };
                        return Err(Error::invalid_argument(format!(
                            "{}: {why} or accept folds",
                            fold_message(&at, u, v, self.settings.thickness)
                        )));
                    }
                }
            }
        }
        Ok(())
    }
}

/// Intervals a side of the lattice on which [`OffsetSurface::new`] looks for folds.
pub const FOLD_LATTICE: usize = 4;

fn fold_message(at: &str, u: f64, v: f64, c: f64) -> String {
    format!("the offset by thickness {c} folds at {at}, (u, v) = ({u}, {v}): (O_u x O_v) . n <= 0")
}

/// The quadrant of `(s, t)` (child `q` of a quad, same orientation) and the coordinates in
/// it, as the evaluator descends.
fn quadrant(s: f64, t: f64) -> (u32, f64, f64) {
    let (right, top) = (s >= 0.5, t >= 0.5);
    let q = match (right, top) {
        (false, false) => 0,
        (true, false) => 1,
        (true, true) => 2,
        (false, true) => 3,
    };
    (
        q,
        if right { 2.0 * s - 1.0 } else { 2.0 * s },
        if top { 2.0 * t - 1.0 } else { 2.0 * t },
    )
}
