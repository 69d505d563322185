//! Folds of the limit surface: where the normal `du × dv` turns through zero and comes back
//! reversed, so that the surface doubles back on itself inside a face.
//!
//! [`find_folds`] samples every parametric (Ptex) face that has a limit surface on a lattice
//! of `samples_per_edge × samples_per_edge` points (corners and edges included) and refines
//! the lattice, by halving cells, up to `adaptive_depth` times: in cells next to an
//! extraordinary or non-smooth corner of the face, and in cells whose corner normals turn by
//! more than `refine_turn_deg` or oppose the face's reference normal. Every sample uses the
//! evaluator's exact derivatives; the normal is `du × dv` of the face's own parameterization,
//! so a crease or corner, where the normal jumps *between* faces, never shows.
//!
//! At a face corner on a smooth interior vertex the sample is the evaluator's exact limit
//! there (at an extraordinary vertex the limit tangent plane of [`super::vertex_limit`],
//! since `du × dv` of the limit parameterization vanishes or diverges there). At a corner
//! that is not a smooth interior point (boundary, sharp edge or vertex, non-manifold), each
//! face has its own one-sided normal while the vertex limit reports one face's, so the
//! sample is taken [`CORNER_INSET`] inside the face instead; so too at interior valence-2
//! vertices, where the vertex limit's tangents are OpenSubdiv's approximate masks.
//!
//! The criterion. The *reference normal* of a Ptex face is its mean unit normal (trapezoid
//! rule on the base lattice, in the face's parameter; samples at irregular corners and in
//! bend zones left out; the centre sample's normal if that mean vanishes). A face **folds**
//! when
//! - a sample's unit normal makes more than 90° with the reference normal (the surface is
//!   reversed there: it has turned back over itself), or
//! - two corner samples of a cell of the finest lattice (after all refinement) are more than
//!   90° apart: the normal jumps there however fine the sampling, as it does where a planar
//!   piece folds in its plane and `du × dv` passes through zero.
//!
//! In space a fold is generically not a zero of `du × dv` (that needs `du ∥ dv`, two
//! conditions) but a tight smooth bend through which the normal turns by nearly 180°; the
//! first test catches it, the second catches the in-plane folds of flat caps at any
//! resolution. What is not a fold:
//! - two samples far apart in one face more than 90° apart (on a coarse cube's limit surface
//!   opposite corners of a face are 109° apart): only the turn within one finest cell counts;
//! - a crease or corner, where the normal jumps *between* faces: each face is evaluated on
//!   its own side;
//! - the bend of a *semi-sharp* crease of sharpness `s`, which lies inside the faces next to
//!   the edge, within `min(1, 4 · 2^-ceil(s))` of it in the face's parameter (and around a
//!   semi-sharp vertex): samples there count for nothing;
//! - the direction-dependent normal at a cone point (an infinitely sharp vertex with smooth
//!   edges, sampled one-sidedly): cells touching such a corner have no turn verdict.
//!
//! A face whose normals legitimately spread more than 90° from their mean (a very coarse face
//! on a tight bend) is reported; the check is meant for meshes fine enough that the normal of
//! a fold-free face stays within 90° of its mean.

use crate::math;
use std::collections::HashMap;

use glam::DVec3;

use super::Evaluator;
use crate::catmark::crease::is_infinite;
use crate::control::Control;
use crate::error::{Error, Result};
use crate::topology::Level;

/// Offset (in the face's `u` and `v`) at which a corner that is not a smooth interior point
/// is sampled: the face's one-sided normal, as close to the corner as makes no difference.
pub const CORNER_INSET: f64 = 1.0 / 1_048_576.0;

/// Largest `samples_per_edge` accepted.
const MAX_SAMPLES_PER_EDGE: usize = 1025;

/// Largest `adaptive_depth` accepted.
const MAX_ADAPTIVE_DEPTH: usize = 16;

/// Most limit evaluations one [`find_folds`] call makes, base lattices and adaptive halving
/// together: 2^26. The base lattices (parametric faces with a surface × `samples_per_edge`²)
/// are checked against it from the counts, before any evaluation; the adaptive halving,
/// which depends on the surface, counts its samples as it makes them, and the call is
/// refused when they would pass it (so after at most this many evaluations). What that
/// takes depends on where the samples fall: about 1 µs each on regular patches, up to
/// ~40 µs deep next to an extraordinary vertex (a smooth cube's face halved everywhere to
/// depth 16: 2^21 samples in 79 s on the loaded 2-core machine of 2026-12-02); a caller
/// that cannot wait polls through [`find_folds_with`].
pub const MAX_FOLD_SAMPLES: u64 = 1 << 26;

/// Most samples of one parametric face, base lattice and adaptive halving together: 2^21,
/// twice the largest base lattice (1025²). Each is kept until the face is done (about
/// [`SAMPLE_BYTES`]), so this bounds the call's memory to about 320 MiB beside the mesh's
/// base level.
pub const MAX_FACE_SAMPLES: usize = 1 << 21;

/// Estimated bytes a sample takes while its face is checked (a 64-byte entry of a hash table
/// between half and seven eighths full), for the memory budget.
pub const SAMPLE_BYTES: u64 = 160;

/// New samples of one face between two polls inside it (a face of many samples takes
/// milliseconds).
const FACE_POLL: usize = 1 << 14;

/// How densely [`find_folds`] samples.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FoldSettings {
    /// Samples along each edge of a parametric face's base lattice (at least 2; default 9).
    pub samples_per_edge: usize,
    /// How many times a lattice cell may be halved: next to extraordinary or non-smooth
    /// corners, and where the normal turns by more than `refine_turn_deg` across a cell or
    /// opposes the reference normal (at most 16; default 4).
    pub adaptive_depth: usize,
    /// A cell whose corner normals turn by more than this (degrees) is refined (default 45).
    pub refine_turn_deg: f64,
}

impl Default for FoldSettings {
    fn default() -> Self {
        FoldSettings {
            samples_per_edge: 9,
            adaptive_depth: 4,
            refine_turn_deg: 45.0,
        }
    }
}

/// One control face whose limit surface folds.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FoldedFace {
    /// Base (control) face index.
    pub face: usize,
    /// The Ptex face (of this control face) with the largest reversal.
    pub ptex_face: usize,
    /// Samples whose normal is more than 90° from their Ptex face's reference normal.
    pub reversed_samples: usize,
    /// Largest angle (degrees) between a sample's normal and its Ptex face's reference normal.
    pub worst_reversal_deg: f64,
    /// Largest angle (degrees) between the corner normals of one finest lattice cell.
    pub max_turn_deg: f64,
}

/// What [`find_folds`] found.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FoldReport {
    /// The folded control faces, in face order.
    pub folded_faces: Vec<FoldedFace>,
    /// Largest angle (degrees), over all samples, between a sample's normal and its Ptex
    /// face's reference normal; above 90 the surface is reversed there.
    pub worst_reversal_deg: f64,
    /// Where that angle is: (Ptex face, u, v); `None` when no sample has a normal.
    pub worst_at: Option<(usize, f64, f64)>,
    /// Minimum over samples of `(du × dv) · n_ref / typical |du × dv|` of the sample's Ptex
    /// face (`n_ref` the unit reference normal, typical the trapezoid mean of `|du × dv|` on
    /// the base lattice); negative where the surface is reversed. Samples at irregular
    /// corners, whose derivative lengths are a convention, are left out; near an
    /// extraordinary vertex of valence above 4 the value tends to 0 by nature.
    /// `+inf` when no sample counts.
    pub min_relative_jacobian: f64,
    /// Parametric (Ptex) faces checked (faces without limit surface are skipped).
    pub faces_checked: usize,
    /// Limit evaluations made.
    pub samples: usize,
}

impl FoldReport {
    /// True when no face folds.
    pub fn is_fold_free(&self) -> bool {
        self.folded_faces.is_empty()
    }

    /// The folded control faces' indices, ascending.
    pub fn folded_face_indices(&self) -> Vec<usize> {
        self.folded_faces.iter().map(|f| f.face).collect()
    }
}

/// Sample the limit surface of `evaluator` as [`FoldSettings`] says and report its folds
/// (the criterion is in the [module documentation](self)).
///
/// Errors: [`Error::InvalidArgument`] for `samples_per_edge` outside `2..=1025`,
/// `adaptive_depth` above 16 or a `refine_turn_deg` outside `(0, 180]`;
/// [`Error::LimitExceeded`] when the base lattices would take more than
/// [`MAX_FOLD_SAMPLES`] evaluations (refused before any), or when the adaptive halving
/// reaches that total or [`MAX_FACE_SAMPLES`] in one face; errors of the evaluation
/// ([`Error::NumericalFailure`]).
pub fn find_folds(evaluator: &Evaluator, settings: &FoldSettings) -> Result<FoldReport> {
    find_folds_with(evaluator, settings, &Control::NONE)
}

/// [`find_folds`] with progress, cancellation and a memory budget: `control` is polled
/// through the mesh's base level (at fraction 0), at each parametric face (their share of
/// the faces done) and every 16,384 samples inside one, and at the end (1); the check is
/// refused before any evaluation or callback when [`fold_check_bytes`] is above the budget,
/// and when a face's samples would pass it.
///
/// Errors: those of [`find_folds`]; [`Error::Cancelled`] and [`Error::LimitExceeded`] from
/// `control`.
pub fn find_folds_with(
    evaluator: &Evaluator,
    settings: &FoldSettings,
    control: &Control,
) -> Result<FoldReport> {
    check_folds(evaluator, settings, control, MAX_FOLD_SAMPLES)
}

/// The fold check a construction runs on its own result (default settings): bounded by
/// the construction's sample ceilings ([`crate::construct::settings::MAX_SAMPLE_PRODUCT`]
/// faces) rather than by [`MAX_FOLD_SAMPLES`], so that every mesh a construction may build
/// is checked; per face and under the memory budget as [`find_folds_with`]. Polled at the
/// end fraction of `control` (the check follows the fit).
pub(crate) fn construction_folds(evaluator: &Evaluator, control: &Control) -> Result<FoldReport> {
    let poll = control.stage(1.0, 1.0);
    check_folds(evaluator, &FoldSettings::default(), &poll, u64::MAX)
}

/// Estimated bytes of a fold check of `evaluator` at `samples_per_edge` (what
/// [`find_folds_with`] checks against the memory budget): the mesh's base level (about 64
/// bytes per face-vertex index) and one face's base lattice of samples ([`SAMPLE_BYTES`]
/// each).
pub fn fold_check_bytes(evaluator: &Evaluator, samples_per_edge: usize) -> u64 {
    level_bytes(evaluator) + SAMPLE_BYTES * (samples_per_edge as u64).pow(2)
}

fn level_bytes(evaluator: &Evaluator) -> u64 {
    64 * evaluator.mesh().face_indices().len() as u64
}

/// The ceilings of one call, fixed before its first evaluation, and what their messages say.
struct Limits<'c> {
    /// Most evaluations of the call.
    total: u64,
    /// Most samples of one face: [`MAX_FACE_SAMPLES`], or fewer under the memory budget
    /// (then the budget is what stops a face).
    per_face: usize,
    level_bytes: u64,
    control: &'c Control,
    faces: u64,
    settings: FoldSettings,
}

impl<'c> Limits<'c> {
    /// The limits of checking `evaluator` at `settings` with `total` evaluations at most
    /// under `control`'s memory budget. Errors ([`Error::LimitExceeded`]): the base lattices
    /// above `total`, or their estimated bytes ([`fold_check_bytes`]) above the budget.
    fn new(
        evaluator: &Evaluator,
        settings: &FoldSettings,
        control: &'c Control,
        total: u64,
    ) -> Result<Limits<'c>> {
        let nptex = evaluator.num_parametric_faces() as u32;
        let faces = (0..nptex).filter(|&p| evaluator.has_surface(p)).count() as u64;
        let n = settings.samples_per_edge;
        let base = faces.saturating_mul((n as u64).pow(2));
        if base > total {
            return Err(Error::LimitExceeded(format!(
                "the fold check of {faces} parametric faces at {n} × {n} samples makes {base} \
                 limit evaluations before any adaptive halving, above the limit of {total}"
            )));
        }
        control.check_memory(
            &format!("the fold check of {faces} parametric faces at {n} × {n} samples"),
            fold_check_bytes(evaluator, n),
        )?;
        let level_bytes = level_bytes(evaluator);
        // The most samples of one face the budget leaves room for.
        let by_budget = control.memory_budget().map(|b| {
            usize::try_from(b.saturating_sub(level_bytes) / SAMPLE_BYTES).unwrap_or(usize::MAX)
        });
        Ok(Limits {
            total,
            per_face: by_budget.map_or(MAX_FACE_SAMPLES, |b| b.min(MAX_FACE_SAMPLES)),
            level_bytes,
            control,
            faces,
            settings: *settings,
        })
    }

    /// The refusal when `made` evaluations of the call so far, `in_face` of them in
    /// parametric face `ptex`, leave no room for one more.
    fn refuse(&self, ptex: u32, made: u64, in_face: usize) -> Error {
        let n = self.settings.samples_per_edge;
        let depth = self.settings.adaptive_depth;
        if made >= self.total {
            return Error::LimitExceeded(format!(
                "the fold check reached its limit of {} limit evaluations at parametric face \
                 {ptex} (its base lattices, {} faces at {n} × {n} samples, take {}; the rest is \
                 adaptive halving up to depth {depth}): lower adaptive_depth or samples_per_edge",
                self.total,
                self.faces,
                self.faces * (n as u64).pow(2)
            ));
        }
        if self.per_face < MAX_FACE_SAMPLES {
            let what = format!("the fold check's samples of parametric face {ptex}");
            let bytes = self.level_bytes + SAMPLE_BYTES * (in_face as u64 + 1);
            if let Err(e) = self.control.check_memory(&what, bytes) {
                return e;
            }
        }
        Error::LimitExceeded(format!(
            "parametric face {ptex} needs more than {} samples at {n} × {n} with adaptive \
             depth {depth}, the limit of one face: lower adaptive_depth or samples_per_edge",
            self.per_face
        ))
    }
}

/// [`find_folds_with`] with `total` evaluations at most.
fn check_folds(
    evaluator: &Evaluator,
    settings: &FoldSettings,
    control: &Control,
    total: u64,
) -> Result<FoldReport> {
    check_settings(settings)?;
    let limits = Limits::new(evaluator, settings, control, total)?;
    let nptex = evaluator.num_parametric_faces();
    control.report(0.0)?;
    let mesh = evaluator.mesh();
    let level = Level::from_mesh_polled(mesh, evaluator.options(), &control.stage(0.0, 0.0))?;
    let mut report = FoldReport {
        folded_faces: Vec::new(),
        worst_reversal_deg: 0.0,
        worst_at: None,
        min_relative_jacobian: f64::INFINITY,
        faces_checked: 0,
        samples: 0,
    };
    for ptex in 0..nptex as u32 {
        control.step(ptex as usize, nptex)?;
        if !evaluator.has_surface(ptex) {
            continue;
        }
        let Some((base, sub)) = evaluator.ptex_faces().locate(ptex) else {
            continue;
        };
        let shape = face_shape(&level, mesh.face(base as usize), sub);
        let room = Room {
            limits: &limits,
            made: report.samples as u64,
            fraction: ptex as f64 / nptex as f64,
        };
        let face = FaceCheck::run(evaluator, ptex, shape, settings, room)?;
        report.faces_checked += 1;
        report.samples += face.samples;
        report.min_relative_jacobian = report.min_relative_jacobian.min(face.min_rel_jacobian);
        if let Some(at) = face.worst_at {
            if report.worst_at.is_none() || face.worst_angle > report.worst_reversal_deg {
                report.worst_reversal_deg = face.worst_angle;
                report.worst_at = Some((ptex as usize, at.0, at.1));
            }
        }
        if face.reversed > 0 || face.max_turn > 90.0 {
            merge_folded(
                &mut report.folded_faces,
                base as usize,
                ptex as usize,
                &face,
            );
        }
    }
    control.report(1.0)?;
    Ok(report)
}

fn check_settings(s: &FoldSettings) -> Result<()> {
    if !(2..=MAX_SAMPLES_PER_EDGE).contains(&s.samples_per_edge) {
        return Err(Error::invalid_argument(format!(
            "samples per edge {} is outside 2..={MAX_SAMPLES_PER_EDGE}",
            s.samples_per_edge
        )));
    }
    if s.adaptive_depth > MAX_ADAPTIVE_DEPTH {
        return Err(Error::invalid_argument(format!(
            "adaptive depth {} is above {MAX_ADAPTIVE_DEPTH}",
            s.adaptive_depth
        )));
    }
    if !(s.refine_turn_deg > 0.0 && s.refine_turn_deg <= 180.0) {
        return Err(Error::invalid_argument(format!(
            "refinement turn {} degrees is outside (0, 180]",
            s.refine_turn_deg
        )));
    }
    Ok(())
}

/// Record a folded Ptex face under its control face (sub-faces of one face are consecutive).
fn merge_folded(list: &mut Vec<FoldedFace>, base: usize, ptex: usize, f: &FaceCheck) {
    if let Some(last) = list.last_mut().filter(|l| l.face == base) {
        last.reversed_samples += f.reversed;
        last.max_turn_deg = last.max_turn_deg.max(f.max_turn);
        if f.worst_angle > last.worst_reversal_deg {
            last.worst_reversal_deg = f.worst_angle;
            last.ptex_face = ptex;
        }
        return;
    }
    list.push(FoldedFace {
        face: base,
        ptex_face: ptex,
        reversed_samples: f.reversed,
        worst_reversal_deg: f.worst_angle,
        max_turn_deg: f.max_turn,
    });
}

/// How a corner of a Ptex face is sampled.
#[derive(Debug, Clone, Copy, PartialEq)]
struct CornerKind {
    /// A smooth interior point: evaluate exactly there (else [`CORNER_INSET`] inside).
    exact: bool,
    /// Not a regular smooth point: refine the lattice next to it, and leave its derivative
    /// lengths (a convention, or degenerate) out of the Jacobian statistics.
    irregular: bool,
}

fn vertex_kind(level: &Level, v: u32) -> CornerKind {
    let v = v as usize;
    let smooth = !level.is_vertex_boundary(v)
        && !level.is_vertex_non_manifold(v)
        && level.vertex_sharpness(v) == 0.0
        && level
            .vertex_edges(v)
            .iter()
            .all(|&e| level.edge_sharpness(e as usize) == 0.0);
    // At interior valence-2 vertices the vertex limit's tangents are OpenSubdiv's
    // approximate masks, not the limit tangent plane: sample those one-sidedly too.
    CornerKind {
        exact: smooth && level.valence(v) >= 3,
        irregular: !(smooth && level.valence(v) == 4),
    }
}

/// The midpoint of edge `a`-`b`, a corner of a sub-face: a regular point after one
/// refinement, smooth unless the edge is a boundary or sharp.
fn midpoint_kind(level: &Level, a: u32, b: u32) -> CornerKind {
    let smooth = level.find_edge(a as usize, b as usize).is_some_and(|e| {
        let e = e as usize;
        !level.is_edge_boundary(e)
            && !level.is_edge_non_manifold(e)
            && level.edge_sharpness(e) == 0.0
    });
    CornerKind {
        exact: smooth,
        irregular: !smooth,
    }
}

/// What a Ptex face's sampling needs to know of its control face.
#[derive(Debug, Clone, Copy, PartialEq)]
struct FaceShape {
    /// Corners 0..4 at `(0,0)`, `(1,0)`, `(1,1)`, `(0,1)`.
    corners: [CornerKind; 4],
    /// Width of the bend zone of each side (0 at `v = 0`, 1 at `u = 1`, 2 at `v = 1`, 3 at
    /// `u = 0`) and radius of each corner's (max-norm), in the face's `(u, v)`.
    side_bend: [f64; 4],
    corner_bend: [f64; 4],
}

impl FaceShape {
    /// Whether `(u, v)` is in a bend zone: next to a semi-sharp edge or vertex, where the
    /// normal legitimately turns by up to the crease's angle within the face.
    fn in_bend(&self, u: f64, v: f64) -> bool {
        let to_side = [v, 1.0 - u, 1.0 - v, u];
        let corner = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        (0..4).any(|k| {
            to_side[k] < self.side_bend[k]
                || (u - corner[k].0).abs().max((v - corner[k].1).abs()) < self.corner_bend[k]
        })
    }
}

/// Width, in a face's parameter, of the strip next to an edge (or around a vertex) of
/// sharpness `s` in which a semi-sharp crease bends the surface: the crease stays sharp for
/// `ceil(s)` refinements, so its bend lies within a few faces of level `ceil(s)` (four, to
/// cover the bicubic supports) of it. Zero for smooth and infinitely sharp features.
fn bend_width(s: f32) -> f64 {
    if s <= 0.0 || is_infinite(s) {
        return 0.0;
    }
    (4.0 * 0.5f64.powi(s.ceil() as i32)).min(1.0)
}

fn edge_sharpness(level: &Level, a: u32, b: u32) -> f32 {
    level
        .find_edge(a as usize, b as usize)
        .map_or(0.0, |e| level.edge_sharpness(e as usize))
}

/// The shape of a Ptex face: for a quad, its vertices and edges; for sub-face `k` of
/// another face, its vertex `k`, the midpoint towards the next vertex, the face centre (an
/// extraordinary smooth point) and the midpoint from the previous vertex, the halves of the
/// two edges at vertex `k` (at twice the scale: the sub-face spans half the face) and two
/// interior sides.
fn face_shape(level: &Level, face: &[u32], sub: Option<u32>) -> FaceShape {
    let vertex_bend = |v: u32| bend_width(level.vertex_sharpness(v as usize));
    match sub {
        None => {
            let side = |k: usize| bend_width(edge_sharpness(level, face[k], face[(k + 1) % 4]));
            FaceShape {
                corners: [0, 1, 2, 3].map(|k| vertex_kind(level, face[k])),
                side_bend: [0, 1, 2, 3].map(side),
                corner_bend: [0, 1, 2, 3].map(|k| vertex_bend(face[k])),
            }
        }
        Some(k) => {
            let n = face.len();
            let k = k as usize;
            let (prev, here, next) = (face[(k + n - 1) % n], face[k], face[(k + 1) % n]);
            let half = |a: u32, b: u32| (2.0 * bend_width(edge_sharpness(level, a, b))).min(1.0);
            FaceShape {
                corners: [
                    vertex_kind(level, here),
                    midpoint_kind(level, here, next),
                    CornerKind {
                        exact: true,
                        irregular: true,
                    },
                    midpoint_kind(level, prev, here),
                ],
                side_bend: [half(here, next), 0.0, 0.0, half(prev, here)],
                corner_bend: [(2.0 * vertex_bend(here)).min(1.0), 0.0, 0.0, 0.0],
            }
        }
    }
}

/// One sample: `du × dv`, its direction, and whether its length counts.
#[derive(Debug, Clone, Copy)]
struct Sample {
    jacobian: DVec3,
    unit: DVec3,
    /// Derivative lengths are a convention (irregular corner): direction only.
    conventional: bool,
    /// In a bend zone ([`FaceShape::in_bend`]): left out of the statistics.
    bend: bool,
}

/// What one face may still sample, and where it polls.
struct Room<'a> {
    limits: &'a Limits<'a>,
    /// Evaluations of the call before this face.
    made: u64,
    /// The call's fraction at this face.
    fraction: f64,
}

/// The check of one Ptex face, on an integer lattice of `m + 1` points per edge, where
/// `m = (samples_per_edge - 1) · 2^adaptive_depth`, point `(i, j)` at `(i/m, j/m)`.
struct FaceCheck<'a> {
    ev: &'a Evaluator,
    room: Room<'a>,
    face: u32,
    shape: FaceShape,
    m: u32,
    max_depth: u32,
    refine_cos: f64,
    cache: HashMap<(u32, u32), Sample>,
    reference: DVec3,
    typical: f64,
    samples: usize,
    reversed: usize,
    worst_angle: f64,
    worst_at: Option<(f64, f64)>,
    min_rel_jacobian: f64,
    max_turn: f64,
}

impl<'a> FaceCheck<'a> {
    fn run(
        ev: &'a Evaluator,
        face: u32,
        shape: FaceShape,
        s: &FoldSettings,
        room: Room<'a>,
    ) -> Result<FaceCheck<'a>> {
        let n = s.samples_per_edge as u32;
        let step = 1u32 << s.adaptive_depth;
        let mut fc = FaceCheck {
            ev,
            room,
            face,
            shape,
            m: (n - 1) * step,
            max_depth: s.adaptive_depth as u32,
            refine_cos: math::cos(s.refine_turn_deg.to_radians()),
            cache: HashMap::new(),
            reference: DVec3::ZERO,
            typical: 0.0,
            samples: 0,
            reversed: 0,
            worst_angle: 0.0,
            worst_at: None,
            min_rel_jacobian: f64::INFINITY,
            max_turn: 0.0,
        };
        let (mut sum, mut sum_len, mut weights) = (DVec3::ZERO, 0.0, 0.0);
        for j in 0..n {
            for i in 0..n {
                let s = fc.sample(i * step, j * step)?;
                if !s.conventional && !s.bend {
                    let w = trapezoid(i, n) * trapezoid(j, n);
                    sum += w * s.unit;
                    sum_len += w * s.jacobian.length();
                    weights += w;
                }
            }
        }
        fc.reference = sum.normalize_or_zero();
        if fc.reference == DVec3::ZERO {
            let c = fc.m / 2;
            fc.reference = fc.sample(c, c)?.unit;
        }
        fc.typical = if weights > 0.0 {
            sum_len / weights
        } else {
            0.0
        };
        // The base lattice (and the centre, if it was needed) in a fixed order.
        for j in 0..n {
            for i in 0..n {
                fc.record((i * step, j * step));
            }
        }
        let c = fc.m / 2;
        if (c % step != 0) && fc.cache.contains_key(&(c, c)) {
            fc.record((c, c));
        }
        for j in 0..n - 1 {
            for i in 0..n - 1 {
                fc.cell(i * step, j * step, step, 0)?;
            }
        }
        Ok(fc)
    }

    /// The sample at lattice point `(i, j)`, evaluated once.
    fn sample(&mut self, i: u32, j: u32) -> Result<Sample> {
        if let Some(&s) = self.cache.get(&(i, j)) {
            return Ok(s);
        }
        let limits = self.room.limits;
        let made = self.room.made + self.samples as u64;
        if made >= limits.total || self.samples >= limits.per_face {
            return Err(limits.refuse(self.face, made, self.samples));
        }
        if self.samples > 0 && self.samples % FACE_POLL == 0 {
            limits.control.report(self.room.fraction)?;
        }
        let m = self.m;
        let (mut u, mut v) = (f64::from(i) / f64::from(m), f64::from(j) / f64::from(m));
        let mut conventional = false;
        if let Some(k) = self.corner_at(i, j) {
            let kind = self.shape.corners[k];
            conventional = kind.irregular;
            if !kind.exact {
                u = if i == 0 {
                    CORNER_INSET
                } else {
                    1.0 - CORNER_INSET
                };
                v = if j == 0 {
                    CORNER_INSET
                } else {
                    1.0 - CORNER_INSET
                };
            }
        }
        let e = self.ev.evaluate(self.face, u, v)?;
        let jacobian = e.du.cross(e.dv);
        let s = Sample {
            jacobian,
            unit: jacobian.normalize_or_zero(),
            conventional,
            bend: self.shape.in_bend(u, v),
        };
        self.samples += 1;
        self.cache.insert((i, j), s);
        if self.reference != DVec3::ZERO {
            self.record((i, j));
        }
        Ok(s)
    }

    /// Which face corner lattice point `(i, j)` is, if any.
    fn corner_at(&self, i: u32, j: u32) -> Option<usize> {
        let m = self.m;
        match (i, j) {
            (0, 0) => Some(0),
            (i, 0) if i == m => Some(1),
            (i, j) if i == m && j == m => Some(2),
            (0, j) if j == m => Some(3),
            _ => None,
        }
    }

    /// Add a cached sample to the statistics (once the reference normal is known).
    fn record(&mut self, key: (u32, u32)) {
        let s = self.cache[&key];
        if s.unit == DVec3::ZERO || s.bend || self.reference == DVec3::ZERO {
            return;
        }
        let cos = s.unit.dot(self.reference);
        let angle = math::acos(cos.clamp(-1.0, 1.0)).to_degrees();
        if cos < 0.0 {
            self.reversed += 1;
        }
        if self.worst_at.is_none() || angle > self.worst_angle {
            self.worst_angle = angle;
            let m = f64::from(self.m);
            self.worst_at = Some((f64::from(key.0) / m, f64::from(key.1) / m));
        }
        if !s.conventional && self.typical > 0.0 {
            let rel = s.jacobian.dot(self.reference) / self.typical;
            self.min_rel_jacobian = self.min_rel_jacobian.min(rel);
        }
    }

    /// Check the cell with lower-left lattice point `(i, j)` and side `size`, refining it
    /// while it may hide a fold.
    fn cell(&mut self, i: u32, j: u32, size: u32, depth: u32) -> Result<()> {
        let pts = [(i, j), (i + size, j), (i + size, j + size), (i, j + size)];
        let mut units = [DVec3::ZERO; 4];
        let mut bend = false;
        for (k, &(a, b)) in pts.iter().enumerate() {
            let s = self.sample(a, b)?;
            units[k] = s.unit;
            bend |= s.bend;
        }
        let min_cos = min_pair_cos(&units);
        if depth < self.max_depth {
            let opposes = !bend && units.iter().any(|u| u.dot(self.reference) < 0.0);
            let at_irregular = pts.iter().any(|&(a, b)| {
                self.corner_at(a, b)
                    .is_some_and(|k| self.shape.corners[k].irregular)
            });
            if min_cos < self.refine_cos || opposes || at_irregular {
                let h = size / 2;
                for (a, b) in [(i, j), (i + h, j), (i + h, j + h), (i, j + h)] {
                    self.cell(a, b, h, depth + 1)?;
                }
                return Ok(());
            }
        }
        // At a corner sampled one-sidedly (a cone point such as an infinitely sharp vertex
        // with smooth edges) the normal legitimately depends on the direction of approach.
        let at_cone = pts.iter().any(|&(a, b)| {
            self.corner_at(a, b)
                .is_some_and(|k| !self.shape.corners[k].exact)
        });
        if !at_cone && !bend {
            let turn = math::acos(min_cos.clamp(-1.0, 1.0)).to_degrees();
            self.max_turn = self.max_turn.max(turn);
        }
        Ok(())
    }
}

/// The smallest cosine between two of the cell's corner normals (zero normals left out).
fn min_pair_cos(units: &[DVec3; 4]) -> f64 {
    let mut min = 1.0f64;
    for a in 0..4 {
        for b in a + 1..4 {
            if units[a] != DVec3::ZERO && units[b] != DVec3::ZERO {
                min = min.min(units[a].dot(units[b]));
            }
        }
    }
    min
}

/// Trapezoid weight of lattice index `i` of `n`.
fn trapezoid(i: u32, n: u32) -> f64 {
    if i == 0 || i == n - 1 {
        0.5
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests;
