//! How thick the offset really is: the distance from `O(face, u, v)` to the limit surface
//! `S`, measured by projecting `O` onto `S`, and the crust level that keeps it within a
//! tolerance of the thickness `c`.
//!
//! The projection runs Gauss–Newton on `|S(u, v) − O|²` over the refined face of the point
//! and every refined face sharing a vertex with it, starting from the point's own
//! parameter (the centre on the other faces), clamped to each face's square; the nearest
//! result is the foot. The search stays on the point's *sheet*: faces joined across edges
//! that are not infinitely sharp. Next to a crease the thickness is so the distance to the
//! point's own side of the crease (the other side is a different wall of the solid); at
//! the crease itself the mitered offset is `c / cos(θ/2)` from the crease curve (see
//! [`super::corners`]), and `c` from each side's tangent plane.
//!
//! Samples are taken on an `n × n` lattice of cell centres `((i + ½)/n, (j + ½)/n)` of every
//! parametric face of the input mesh: odd `n` never hits a refined face's corner, where the
//! crust is exact and the error would look like zero.

use glam::DVec3;

use super::offset::{OffsetSettings, OffsetSurface, MAX_LEVEL};
use crate::catmark::crease::is_infinite;
use crate::error::{Error, Result};
use crate::eval::Evaluator;
use crate::mesh::Mesh;
use crate::options::SubdivOptions;
use crate::topology::Level;

/// Gauss–Newton steps of one projection.
const MAX_STEPS: usize = 40;

/// Lattice cells a side of every input face at which the tolerance is checked.
pub const TOLERANCE_LATTICE: usize = 5;

/// Thickness statistics of an offset, relative to its thickness `c`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThicknessReport {
    /// The crust level measured.
    pub level: u32,
    /// Points measured.
    pub samples: usize,
    /// Smallest distance from `O` to `S`, over `c`.
    pub min: f64,
    /// Largest, over `c`.
    pub max: f64,
    /// Mean, over `c`.
    pub mean: f64,
    /// Largest `|distance − c|`, in model units.
    pub max_error: f64,
}

/// The faces of the refined mesh near each face, on its sheet.
#[derive(Debug, Clone)]
pub struct Neighbours {
    near: Vec<Vec<u32>>,
}

impl Neighbours {
    /// The neighbours of every face of `ev`'s mesh.
    pub fn new(ev: &Evaluator) -> Neighbours {
        let mesh: &Mesh = ev.mesh();
        let level = Level::from_mesh_with_options(mesh, ev.options());
        let sheet = sheets(&level);
        let near = (0..level.num_faces())
            .map(|f| {
                let mut list = vec![f as u32];
                for &v in level.face_vertices(f) {
                    for &g in level.vertex_faces(v as usize) {
                        if sheet[g as usize] == sheet[f] && !list.contains(&g) {
                            list.push(g);
                        }
                    }
                }
                list
            })
            .collect();
        Neighbours { near }
    }
}

/// The sheet of every face: faces joined across edges that are not infinitely sharp.
fn sheets(level: &Level) -> Vec<usize> {
    let mut parent: Vec<usize> = (0..level.num_faces()).collect();
    fn root(p: &mut [usize], mut x: usize) -> usize {
        while p[x] != x {
            p[x] = p[p[x]];
            x = p[x];
        }
        x
    }
    for e in 0..level.num_edges() {
        if is_infinite(level.edge_sharpness(e)) {
            continue;
        }
        let faces = level.edge_faces(e);
        for w in faces.windows(2) {
            let (a, b) = (
                root(&mut parent, w[0] as usize),
                root(&mut parent, w[1] as usize),
            );
            parent[a.max(b)] = a.min(b);
        }
    }
    (0..parent.len()).map(|f| root(&mut parent, f)).collect()
}

/// The distance from `q` to the limit surface near face `face` of `ev`'s mesh, starting at
/// `(u, v)` there.
pub fn distance_to_surface(
    ev: &Evaluator,
    near: &Neighbours,
    q: DVec3,
    face: u32,
    u: f64,
    v: f64,
) -> Result<f64> {
    let mut best = f64::INFINITY;
    for &g in &near.near[face as usize] {
        if !ev.has_surface(g) {
            continue;
        }
        let start = if g == face { (u, v) } else { (0.5, 0.5) };
        best = best.min(project(ev, g, q, start)?);
    }
    Ok(best)
}

/// Gauss–Newton projection of `q` onto face `g`, clamped to its square.
fn project(ev: &Evaluator, g: u32, q: DVec3, (mut u, mut v): (f64, f64)) -> Result<f64> {
    let mut d = f64::INFINITY;
    for _ in 0..MAX_STEPS {
        let s = ev.evaluate(g, u, v)?;
        let r = s.position - q;
        d = d.min(r.length());
        let (a, b, c) = (s.du.dot(s.du), s.du.dot(s.dv), s.dv.dot(s.dv));
        let det = a * c - b * b;
        if det.abs() <= 1e-300 {
            break;
        }
        let (gu, gv) = (s.du.dot(r), s.dv.dot(r));
        let du = -(c * gu - b * gv) / det;
        let dv = -(a * gv - b * gu) / det;
        let (nu, nv) = ((u + du).clamp(0.0, 1.0), (v + dv).clamp(0.0, 1.0));
        if (nu - u).abs() < 1e-15 && (nv - v).abs() < 1e-15 {
            break;
        }
        (u, v) = (nu, nv);
    }
    let last = (ev.evaluate(g, u, v)?.position - q).length();
    Ok(d.min(last))
}

/// Thickness statistics of `offset` on an `n × n` lattice of cell centres of every
/// parametric face of the input mesh.
pub fn measure(offset: &OffsetSurface, n: usize) -> Result<ThicknessReport> {
    let near = Neighbours::new(offset.fine());
    let c = offset.settings().thickness;
    let (mut min, mut max, mut sum, mut count, mut worst) =
        (f64::INFINITY, 0.0f64, 0.0, 0usize, 0.0f64);
    for face in 0..offset.num_parametric_faces() {
        for i in 0..n {
            for j in 0..n {
                let (u, v) = ((i as f64 + 0.5) / n as f64, (j as f64 + 0.5) / n as f64);
                let (g, s, t, _) = offset.locate(face, u, v)?;
                if !offset.fine().has_surface(g) {
                    continue;
                }
                let o = offset.evaluate_fine(g, s, t, 1.0)?;
                let d = distance_to_surface(offset.fine(), &near, o.position, g, s, t)?;
                min = min.min(d / c);
                max = max.max(d / c);
                sum += d / c;
                count += 1;
                worst = worst.max((d - c).abs());
            }
        }
    }
    Ok(ThicknessReport {
        level: offset.settings().level,
        samples: count,
        min,
        max,
        mean: sum / count.max(1) as f64,
        max_error: worst,
    })
}

/// The offset at the lowest crust level from `settings.level` on whose thickness is within
/// `tolerance` of `c` at every sample of [`TOLERANCE_LATTICE`], with its report.
///
/// Errors: [`Error::InvalidArgument`] for a tolerance that is not finite and > 0;
/// [`Error::NumericalFailure`] when no level up to [`MAX_LEVEL`] (or [`MAX_FINE_FACES`])
/// meets it, the message giving the error reached at each level and, where a finer crust
/// folds, the fold error naming the face and the crease or corner vertex next to it; the
/// errors of [`OffsetSurface::new`] at the first level.
pub fn offset_within(
    mesh: &Mesh,
    options: &SubdivOptions,
    settings: OffsetSettings,
    tolerance: f64,
) -> Result<(OffsetSurface, ThicknessReport)> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(Error::invalid_argument(format!(
            "tolerance = {tolerance} must be a finite number > 0"
        )));
    }
    let mut reached = Vec::new();
    for level in settings.level..=MAX_LEVEL {
        let offset = match OffsetSurface::new(mesh, options, OffsetSettings { level, ..settings }) {
            Ok(o) => o,
            // A finer crust can fold where a coarser one did not (refined faces next to a
            // crease narrower than the miter's sideways reach): say how far it got.
            Err(e) if level > settings.level => {
                reached.push(format!("level {level}: {e}"));
                break;
            }
            Err(e) => return Err(e),
        };
        let report = measure(&offset, TOLERANCE_LATTICE)?;
        if report.max_error <= tolerance {
            return Ok((offset, report));
        }
        reached.push(format!("level {}: {:.3e}", report.level, report.max_error));
        // Refined faces grow 4× a level: stop before the next one gets too large.
        if offset.fine().mesh().num_faces() * 4 > MAX_FINE_FACES {
            break;
        }
    }
    Err(Error::NumericalFailure(format!(
        "no crust level keeps the thickness within {tolerance} of {}: largest error {}",
        settings.thickness,
        reached.join(", ")
    )))
}

/// Most refined faces [`offset_within`] goes to.
pub const MAX_FINE_FACES: usize = 1 << 20;
