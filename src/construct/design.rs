//! How a fitted construction compares with its design surface between the data points.
//!
//! Every construction samples an exact *design surface* (the blended quadrant sweeps of the
//! profile construction, the surface of revolution, the sweep) at known parameters: each
//! control vertex's data point is the design surface at its [`DesignCoord`]. Inside a face
//! the design parameter is the bilinear interpolation of the face's corner parameters in the
//! face's own `(u, v)`: along rings and meridians `(s, θ)` (unwrapped across a closed
//! seam), and in a cap, whose centre has no angle, the Cartesian chart `ρ (cos θ, sin θ)` of
//! the unit disc, ring vertices at `ρ = 1`. A face with a corner in a flat meridian cap of a
//! partial revolution ([`DesignCoord::Planar`]) is compared with the bilinear interpolation
//! of its corners' data points, which lie in the cap's plane. So the *distance to the design surface* at
//! `(face, u, v)` is `|(limit(face, u, v) − d) · n|` with `d` the design point at the
//! bilinear parameter and `n` the design surface's unit normal there: to first order the
//! distance from the limit point to the design surface. The full `|limit − d|`, which also
//! counts the limit's parameterization sliding along the design surface, is reported as the
//! parameter offset.
//!
//! [`DesignLattice`] holds the design points of every face on a lattice of
//! `(LATTICE + 1)²` parameters (computed once, when the construction is built, or on first use
//! for a [`DesignLattice::deferred`] one);
//! [`surface_report`] evaluates the fitted limit at the same parameters and reports the
//! largest and mean distance over the bounding-box diagonal, the folds
//! ([`crate::eval::folds::find_folds`]) and an undulation ratio: the bending energy
//! `∫ (κ₁² + κ₂²) dA` of the limit surface over the design surface's, both measured on the
//! lattices (1 = as fair as the design; wiggles the design does not have raise it). The
//! limit's normals are exact (the evaluator's `du × dv`, taken just inside the face where
//! the Jacobian vanishes, as at a flat cap's grid corner spanning a straight angle on a
//! crease); the design's come from second-order lattice differences, oriented as the
//! limit's and filled from their neighbours where the design chart degenerates (against
//! fourth-order differences they change a sphere's ratio by 0.3% at 16 × 8). Each lattice
//! cell contributes its shape operator's squared norm, from its mean chords and mean normal
//! differences, times its area: robust where a cell's corner has a zero Jacobian.
//! Difference normals of the limit, used before, reversed in the skewed cells of flat
//! meridian caps next to the axis (planar, no bending at all) and made the capped goblet's
//! undulation 348 at 64 × 32 (now 0.99, the open turn's).

use crate::math;
use std::f64::consts::TAU;
use std::sync::{Arc, OnceLock};

use glam::{DVec2, DVec3};

use crate::control::Control;
use crate::error::Result;
use crate::eval::folds::construction_folds;
use crate::eval::{Evaluator, LimitSample};
use crate::mesh::{Mesh, MeshParts};

/// Lattice intervals per face edge at which the design and the limit are compared.
pub const LATTICE: usize = 4;

/// Where a vertex's data point lies on the design surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DesignCoord {
    /// On the side: ring parameter `s` and meridian parameter `theta`.
    Side {
        /// Ring (profile) parameter.
        s: f64,
        /// Meridian parameter (an angle for revolutions).
        theta: f64,
    },
    /// In the cap (or sector) closing end `end` (0 first ring, 1 last): relative radius
    /// `rho` (1 on the ring it closes) and angle `theta` (radians).
    Cap {
        /// 0: the first ring's end, 1: the last ring's.
        end: usize,
        /// Relative radius.
        rho: f64,
        /// Angle, radians.
        theta: f64,
    },
    /// In a flat region whose design is the plane through its data points (the meridian
    /// caps of a partial revolution).
    Planar,
}

/// The design surface of a construction, in the coordinates of [`DesignCoord`].
pub trait Design {
    /// The side at `(s, theta)`.
    fn side(&self, s: f64, theta: f64) -> DVec3;
    /// The angle (radians) of the side's meridian parameter `theta` (where a cap meets the
    /// side).
    fn angle(&self, theta: f64) -> f64;
    /// The cap of `end` at relative radius `rho` and angle `theta` (radians).
    fn cap(&self, end: usize, rho: f64, theta: f64) -> DVec3;
    /// The periods of `s` and `theta` along closed rings or a closed sweep (`None`: open).
    fn periods(&self) -> [Option<f64>; 2];
}

/// Computes a deferred lattice's design points ([`DesignLattice::deferred`]), polling the
/// control it is given.
type LatticeSource = dyn Fn(&Control) -> Result<Vec<DVec3>> + Send + Sync;

/// The design surface of every face on its `(LATTICE + 1)²` lattice, face by face, `u`
/// fastest, and the [`SurfaceReport`] of the fitted mesh once computed.
#[derive(Clone, Default)]
pub struct DesignLattice {
    points: OnceLock<Vec<DVec3>>,
    /// Where the points come from when first asked for (none: given).
    source: Option<Arc<LatticeSource>>,
    report: OnceLock<SurfaceReport>,
}

impl std::fmt::Debug for DesignLattice {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("DesignLattice")
            .field("points", &self.points.get().map(Vec::len))
            .field("report", &self.report.get())
            .finish()
    }
}

impl DesignLattice {
    /// A lattice of given design points (face by face, `u` fastest), for constructions
    /// whose design surface is sampled directly (the GBS blend, shells).
    pub fn from_points(points: Vec<DVec3>) -> DesignLattice {
        DesignLattice {
            points: OnceLock::from(points),
            ..DesignLattice::default()
        }
    }

    /// A lattice whose points `source` computes on first use ([`DesignLattice::points`], the
    /// surface report): a construction that is never asked for its report does not pay
    /// for the lattice. `source` gets the control of the call that needs the points.
    pub fn deferred(
        source: impl Fn(&Control) -> Result<Vec<DVec3>> + Send + Sync + 'static,
    ) -> DesignLattice {
        DesignLattice {
            source: Some(Arc::new(source)),
            ..DesignLattice::default()
        }
    }

    /// The design points (face by face, `u` fastest), computed on the first call if
    /// deferred. Errors: those of the deferred computation.
    pub fn points(&self) -> Result<&[DVec3]> {
        self.points_with(&Control::NONE)
    }

    /// [`DesignLattice::points`] polling `control` while computing them.
    fn points_with(&self, control: &Control) -> Result<&[DVec3]> {
        if let Some(p) = self.points.get() {
            return Ok(p);
        }
        let p = match &self.source {
            Some(source) => source(control)?,
            None => Vec::new(),
        };
        Ok(self.points.get_or_init(|| p))
    }

    /// The [`surface_report`] of `mesh` (the fitted mesh of these faces), computed on the
    /// first call and kept. Errors: those of [`surface_report`].
    pub fn report(&self, mesh: &Mesh) -> Result<&SurfaceReport> {
        self.report_with(mesh, &Control::NONE)
    }

    /// [`DesignLattice::report`] polling `control` while computing it
    /// ([`surface_report_with`]); a cancelled computation keeps nothing.
    pub fn report_with(&self, mesh: &Mesh, control: &Control) -> Result<&SurfaceReport> {
        if let Some(r) = self.report.get() {
            return Ok(r);
        }
        let r = surface_report_with(mesh, self, control)?;
        Ok(self.report.get_or_init(|| r))
    }
}

/// What [`surface_report`] measured.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceReport {
    /// Largest distance from the limit surface to the design surface at the lattice
    /// parameters (along the design surface's normal), over the limit surface's
    /// bounding-box diagonal.
    pub max_design_distance: f64,
    /// Mean of those distances over the diagonal.
    pub mean_design_distance: f64,
    /// Largest distance between the limit and the design point of one lattice parameter
    /// (normal and tangential: how far the limit's parameterization slides along the design
    /// surface, too), over the diagonal.
    pub max_parameter_offset: f64,
    /// Control faces whose limit surface folds ([`crate::eval::folds::find_folds`], default settings).
    pub folded_faces: usize,
    /// Largest normal reversal found, degrees (above 90 where the surface folds).
    pub worst_reversal_deg: f64,
    /// Bending energy `∫ (κ₁² + κ₂²) dA` of the limit surface over the design surface's,
    /// both from their lattices (1 = as fair as the design).
    pub undulation: f64,
    /// The limit surface's bending energy `∫ (κ₁² + κ₂²) dA` on the lattices (exact
    /// normals; see the module documentation): dimensionless, the same at every scale.
    pub limit_bending_energy: f64,
    /// The design surface's bending energy on the same lattices.
    pub design_bending_energy: f64,
}

/// The lattice parameter `(u, v)` of point `k` of a face's lattice.
fn lattice_uv(k: usize) -> (f64, f64) {
    let n = LATTICE + 1;
    (
        (k % n) as f64 / LATTICE as f64,
        (k / n) as f64 / LATTICE as f64,
    )
}

/// Unwrap `x` to within half a period of `reference`.
fn unwrap(x: f64, reference: f64, period: Option<f64>) -> f64 {
    match period {
        Some(p) => x - p * ((x - reference) / p).round(),
        None => x,
    }
}

/// Bilinear interpolation of four corner values at `(u, v)` (Ptex corner order).
pub(crate) fn bilinear<T>(c: [T; 4], u: f64, v: f64) -> T
where
    T: std::ops::Mul<f64, Output = T> + std::ops::Add<Output = T> + Copy,
{
    c[0] * ((1.0 - u) * (1.0 - v))
        + c[1] * (u * (1.0 - v))
        + c[2] * (u * v)
        + c[3] * ((1.0 - u) * v)
}

/// How one face's design points are found.
enum Chart {
    /// `(s, θ)` corners, unwrapped against corner 0.
    Side([DVec2; 4]),
    /// Cartesian disc corners of the cap of an end.
    Cap(usize, [DVec2; 4]),
    /// Corner data points of a flat face.
    Planar([DVec3; 4]),
}

/// The design lattice of the quads `faces` (vertex ids; Ptex face `f` is quad `f`) whose
/// vertices' data points `points` lie on `design` at `coords`. `control` is polled once per
/// face at its start fraction (the layout comes before the fit, whose stages report the
/// fractions): on a large cage this is the longest un-fitted stage of a construction.
///
/// Errors: [`crate::Error::Cancelled`] from `control`.
pub fn design_lattice(
    faces: &[[u32; 4]],
    coords: &[DesignCoord],
    points: &[DVec3],
    design: &dyn Design,
    control: &Control,
) -> Result<DesignLattice> {
    lattice_points(faces, coords, points, design, control).map(DesignLattice::from_points)
}

/// The points of [`design_lattice`] (for a [`DesignLattice::deferred`] source).
///
/// Errors: [`crate::Error::Cancelled`] from `control`.
pub fn lattice_points(
    faces: &[[u32; 4]],
    coords: &[DesignCoord],
    points: &[DVec3],
    design: &dyn Design,
    control: &Control,
) -> Result<Vec<DVec3>> {
    let [ps, pt] = design.periods();
    let poll = control.stage(0.0, 0.0);
    let mut out = Vec::with_capacity(faces.len() * (LATTICE + 1) * (LATTICE + 1));
    for (i, f) in faces.iter().enumerate() {
        poll.step(i, faces.len())?;
        let c = f.map(|v| coords[v as usize]);
        let cap_end = c.iter().find_map(|c| match c {
            DesignCoord::Cap { end, .. } => Some(*end),
            _ => None,
        });
        let chart = if c.contains(&DesignCoord::Planar) {
            Chart::Planar(f.map(|v| points[v as usize]))
        } else if let Some(end) = cap_end {
            Chart::Cap(
                end,
                c.map(|c| match c {
                    DesignCoord::Cap { rho, theta, .. } => DVec2::from_angle(theta) * rho,
                    DesignCoord::Side { theta, .. } => DVec2::from_angle(design.angle(theta)),
                    DesignCoord::Planar => unreachable!("a planar corner makes a planar chart"),
                }),
            )
        } else {
            let side = c.map(|c| match c {
                DesignCoord::Side { s, theta } => DVec2::new(s, theta),
                _ => unreachable!("only side corners are left"),
            });
            Chart::Side(
                side.map(|p| DVec2::new(unwrap(p.x, side[0].x, ps), unwrap(p.y, side[0].y, pt))),
            )
        };
        for k in 0..(LATTICE + 1) * (LATTICE + 1) {
            let (u, v) = lattice_uv(k);
            out.push(match chart {
                Chart::Side(c) => {
                    let q = bilinear(c, u, v);
                    design.side(q.x, q.y)
                }
                Chart::Cap(end, c) => {
                    let q = bilinear(c, u, v);
                    let theta = if q.length() > 0.0 {
                        math::atan2(q.y, q.x)
                    } else {
                        0.0
                    };
                    design.cap(end, q.length(), theta.rem_euclid(TAU))
                }
                Chart::Planar(c) => bilinear(c, u, v),
            });
        }
    }
    Ok(out)
}

/// Smallest sine between a lattice point's two difference derivatives for which it gets a
/// normal ([`lattice_normals`]).
const DEGENERATE_SINE: f64 = 0.05;

/// Sine between the evaluator's `du` and `dv` below which the limit's normal is not taken
/// from them (a zero Jacobian, as at a grid corner spanning a straight angle on a crease,
/// where `du × dv` is rounding noise of either sign): it is taken a little inside the face
/// instead ([`limit_lattice`]). Well above the noise (~1e-14), far below any cell's sine.
const ZERO_JACOBIAN_SINE: f64 = 1e-6;

/// Parameter steps towards the face's centre tried, in turn, at a zero Jacobian: the first
/// whose `du × dv` clears [`ZERO_JACOBIAN_SINE`] gives the normal. Along the bisector of a
/// straight-angle corner `du × dv` can vanish to second order, so the first steps may not.
const INSIDE: [f64; 5] = [1e-6, 1e-5, 1e-4, 1e-3, 1e-2];

/// Unit normals of one face's `(LATTICE + 1)²` lattice points from second-order lattice
/// differences (central inside, one-sided three-point on the face's edges; zero where the
/// two derivatives are within [`DEGENERATE_SINE`] of parallel).
fn lattice_normals(p: &[DVec3]) -> Vec<DVec3> {
    let n = LATTICE + 1;
    // Derivative along a line of lattice points `line(0..=LATTICE)` at index `k`.
    let derivative = |line: &dyn Fn(usize) -> DVec3, k: usize| match k {
        0 => (line(1) * 4.0 - line(0) * 3.0 - line(2)) * 0.5,
        k if k == LATTICE => (line(k) * 3.0 - line(k - 1) * 4.0 + line(k - 2)) * 0.5,
        k => (line(k + 1) - line(k - 1)) * 0.5,
    };
    (0..n * n)
        .map(|k| {
            let (i, j) = (k % n, k / n);
            let du = derivative(&|a| p[j * n + a], i);
            let dv = derivative(&|b| p[b * n + i], j);
            let normal = du.cross(dv);
            // Where the parameterization degenerates (a flat cap's corner on a straight
            // crease, whose limit Jacobian vanishes there), the difference normal is
            // noise: none (see `design_normals`).
            if normal.length() < DEGENERATE_SINE * du.length() * dv.length() {
                DVec3::ZERO
            } else {
                normal.normalize()
            }
        })
        .collect()
}

/// The limit surface of Ptex face `face` on its lattice: positions into `points` and exact
/// unit normals `du × dv` from the evaluator into `normals` (both cleared first). Where the
/// Jacobian vanishes ([`ZERO_JACOBIAN_SINE`]), the normal is taken a step ([`INSIDE`])
/// towards the face's centre: the limit of the normals there, wherever the surface is
/// smooth (exact on a plane); where no step clears it, from the neighbours
/// ([`fill_normals`]).
///
/// Errors: those of [`Evaluator::evaluate`].
fn limit_lattice(
    ev: &Evaluator,
    face: u32,
    points: &mut Vec<DVec3>,
    normals: &mut Vec<DVec3>,
) -> Result<()> {
    points.clear();
    normals.clear();
    for k in 0..(LATTICE + 1) * (LATTICE + 1) {
        let (u, v) = lattice_uv(k);
        let s = ev.evaluate(face, u, v)?;
        points.push(s.position);
        let normal = |s: &LimitSample| {
            let n = s.du.cross(s.dv);
            (n.length() > ZERO_JACOBIAN_SINE * s.du.length() * s.dv.length()).then(|| n.normalize())
        };
        let mut found = normal(&s);
        for step in INSIDE {
            if found.is_some() {
                break;
            }
            let inside = |x: f64| x + step * (0.5 - x).signum();
            found = normal(&ev.evaluate(face, inside(u), inside(v))?);
        }
        normals.push(found.unwrap_or(DVec3::ZERO));
    }
    fill_normals(normals);
    Ok(())
}

/// The design surface's normals for its bending energy: the difference normals `normals`
/// ([`lattice_normals`]) turned to the side of the limit's `limit` at the same lattice
/// points, and filled where they are zero ([`fill_normals`]). The design surface's
/// orientation is the limit's: a flat meridian cap's design chart (the bilinear
/// interpolation of a non-convex quad's corners) may reverse inside the face while the
/// plane it covers does not bend.
fn design_normals(normals: &[DVec3], limit: &[DVec3]) -> Vec<DVec3> {
    let mut out: Vec<DVec3> = normals
        .iter()
        .zip(limit)
        .map(|(n, l)| if n.dot(*l) < 0.0 { -*n } else { *n })
        .collect();
    fill_normals(&mut out);
    out
}

/// Replace each zero normal of a face's lattice by the mean direction of its nonzero
/// neighbours on the lattice (the face's, if none is). Exact on a plane, where design charts
/// degenerate (a flat meridian cap's sliver quads, most of whose lattice points have no
/// difference normal); on the limit a point of no normal is isolated (a zero Jacobian).
fn fill_normals(normals: &mut [DVec3]) {
    let n = LATTICE + 1;
    let known: Vec<DVec3> = normals.to_vec();
    let whole: DVec3 = known.iter().sum();
    for (k, normal) in normals.iter_mut().enumerate() {
        if *normal != DVec3::ZERO {
            continue;
        }
        let (i, j) = (k % n, k / n);
        let near: DVec3 = (j.saturating_sub(1)..(j + 2).min(n))
            .flat_map(|b| (i.saturating_sub(1)..(i + 2).min(n)).map(move |a| b * n + a))
            .map(|c| known[c])
            .sum();
        *normal = if near != DVec3::ZERO { near } else { whole }.normalize_or_zero();
    }
}

/// Bending energy `∫ |∇n|² dA = ∫ (κ₁² + κ₂²) dA` of one face's lattice surface with unit
/// normals `normal`: per cell, `tr(G⁻¹ H) √det G` with `G` the Gram matrix of the cell's two
/// mean chords (the means of its opposite edges) and `H` that of the normals' mean
/// differences along them. `√det G` is the cell's vector area `½ |d₁ × d₂|` (its diagonals
/// `d₁`, `d₂`), so a cell at a zero Jacobian (a corner spanning a straight angle, whose two
/// edges there are parallel) is weighted by its true area and resolved by its other two
/// edges; a cell without area (to rounding) has no energy. The estimate does not depend on
/// the parameterization (up to the discretization), so the limit and the design surface
/// compare even where their parameterizations differ; on a sphere with exact normals
/// (`n = x / r`: `H = G / r²`) it is exactly `2 / r²` times the cells' area.
fn bending_energy(p: &[DVec3], normal: &[DVec3]) -> f64 {
    let n = LATTICE + 1;
    let mut total = 0.0;
    for j in 0..LATTICE {
        for i in 0..LATTICE {
            let k = j * n + i;
            let [c0, c1, c2, c3] = [k, k + 1, k + n + 1, k + n];
            let mean = |x: &[DVec3], from: [usize; 2], to: [usize; 2]| {
                (x[to[0]] - x[from[0]] + x[to[1]] - x[from[1]]) * 0.5
            };
            let (a, b) = (mean(p, [c0, c3], [c1, c2]), mean(p, [c0, c1], [c3, c2]));
            let (na, nb) = (
                mean(normal, [c0, c3], [c1, c2]),
                mean(normal, [c0, c1], [c3, c2]),
            );
            let (g11, g12, g22) = (a.dot(a), a.dot(b), b.dot(b));
            let det = g11 * g22 - g12 * g12;
            if det <= (f64::EPSILON * g11) * (f64::EPSILON * g22) {
                continue;
            }
            let (h11, h12, h22) = (na.dot(na), na.dot(nb), nb.dot(nb));
            total += (g22 * h11 - 2.0 * g12 * h12 + g11 * h22) / det.sqrt();
        }
    }
    total
}

/// Compare the fitted `mesh` (all quads, Ptex face = face) with its design lattice: distances,
/// folds and undulation (see the module documentation).
///
/// Errors: those of [`Evaluator::new`], [`Evaluator::evaluate`] and
/// [`crate::eval::folds::find_folds`].
pub fn surface_report(mesh: &Mesh, design: &DesignLattice) -> Result<SurfaceReport> {
    surface_report_with(mesh, design, &Control::NONE)
}

/// [`surface_report`] polling `control` at its end fraction (the report follows the fit):
/// in the evaluator build, at each face of the lattice comparison and of the fold search
/// ([`crate::eval::folds::find_folds_with`]).
///
/// Errors: those of [`surface_report`]; [`crate::Error::Cancelled`] from `control`.
pub fn surface_report_with(
    mesh: &Mesh,
    design: &DesignLattice,
    control: &Control,
) -> Result<SurfaceReport> {
    let poll = control.stage(1.0, 1.0);
    let ev = Evaluator::with_control(mesh, &mesh.options().resolve(), &poll)?;
    let per_face = (LATTICE + 1) * (LATTICE + 1);
    let diagonal = mesh.bounding_box_diagonal().max(f64::MIN_POSITIVE);
    let (mut max, mut sum, mut count, mut offset) = (0.0f64, 0.0, 0usize, 0.0f64);
    let (mut limit_energy, mut design_energy) = (0.0, 0.0);
    let (mut limit, mut limit_normals) = (Vec::with_capacity(per_face), Vec::new());
    let points = design.points_with(&poll)?;
    let faces = points.len() / per_face;
    for (f, want) in points.chunks(per_face).enumerate() {
        poll.step(f, faces)?;
        if !ev.has_surface(f as u32) {
            continue;
        }
        limit_lattice(&ev, f as u32, &mut limit, &mut limit_normals)?;
        let normals = lattice_normals(want);
        for ((p, d), n) in limit.iter().zip(want).zip(&normals) {
            let e = (*p - *d).dot(*n).abs();
            max = max.max(e);
            offset = offset.max(p.distance(*d));
            sum += e;
            count += 1;
        }
        limit_energy += bending_energy(&limit, &limit_normals);
        design_energy += bending_energy(want, &design_normals(&normals, &limit_normals));
    }
    let folds = construction_folds(&ev, control)?;
    Ok(SurfaceReport {
        max_design_distance: max / diagonal,
        mean_design_distance: sum / count.max(1) as f64 / diagonal,
        max_parameter_offset: offset / diagonal,
        folded_faces: folds.folded_faces.len(),
        worst_reversal_deg: folds.worst_reversal_deg,
        undulation: if design_energy > 0.0 {
            limit_energy / design_energy
        } else {
            1.0
        },
        limit_bending_energy: limit_energy,
        design_bending_energy: design_energy,
    })
}

/// The design lattice of quad mesh parts whose vertices lie on `design` at `coords`, polling
/// `control` ([`design_lattice`]).
pub fn parts_lattice(
    parts: &MeshParts,
    coords: &[DesignCoord],
    design: &dyn Design,
    control: &Control,
) -> Result<DesignLattice> {
    design_lattice(
        &quad_faces(parts),
        coords,
        &parts.positions,
        design,
        control,
    )
}

/// The faces of quad mesh parts, as [`design_lattice`] takes them.
pub fn quad_faces(parts: &MeshParts) -> Vec<[u32; 4]> {
    parts
        .face_indices
        .chunks_exact(4)
        .map(|f| [f[0], f[1], f[2], f[3]])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unit sphere by angles: side `(s, θ)` = latitude, longitude; caps at the poles.
    struct Sphere;
    impl Design for Sphere {
        fn side(&self, s: f64, theta: f64) -> DVec3 {
            DVec3::new(
                math::cos(s) * math::cos(theta),
                math::cos(s) * math::sin(theta),
                math::sin(s),
            )
        }
        fn angle(&self, theta: f64) -> f64 {
            theta
        }
        fn cap(&self, end: usize, rho: f64, theta: f64) -> DVec3 {
            let lat = (std::f64::consts::FRAC_PI_2 - 0.5 * rho) * if end == 0 { -1.0 } else { 1.0 };
            self.side(lat, theta)
        }
        fn periods(&self) -> [Option<f64>; 2] {
            [None, Some(TAU)]
        }
    }

    /// The lattice of one quad on the sphere with these corner coordinates.
    fn one_face(coords: &[DesignCoord]) -> DesignLattice {
        design_lattice(
            &[[0, 1, 2, 3]],
            coords,
            &[DVec3::ZERO; 4],
            &Sphere,
            &Control::NONE,
        )
        .unwrap()
    }

    #[test]
    fn lattices_interpolate_corner_parameters_across_seams_and_caps() {
        let coords = [
            DesignCoord::Side { s: 0.0, theta: 6.0 },
            DesignCoord::Side { s: 0.0, theta: 0.1 },
            DesignCoord::Side { s: 0.2, theta: 0.1 },
            DesignCoord::Side { s: 0.2, theta: 6.0 },
        ];
        let l = one_face(&coords);
        // The middle of the face straddles θ = 0 (6.0 and 0.1 + 2π average to ≈ 0.05 − π/…).
        let mid = l.points().unwrap()[(LATTICE + 1) * (LATTICE / 2) + LATTICE / 2];
        let theta = 0.5 * (6.0 + 0.1 + TAU);
        assert!((mid - Sphere.side(0.1, theta)).length() < 1e-14, "{mid}");
        // A cap face with the pole as a corner: the chart is Cartesian, the pole has no angle.
        let coords = [
            DesignCoord::Cap {
                end: 1,
                rho: 0.0,
                theta: 0.0,
            },
            DesignCoord::Cap {
                end: 1,
                rho: 0.5,
                theta: 0.0,
            },
            DesignCoord::Cap {
                end: 1,
                rho: 0.5,
                theta: 1.0,
            },
            DesignCoord::Cap {
                end: 1,
                rho: 0.5,
                theta: 2.0,
            },
        ];
        let l = one_face(&coords);
        assert!((l.points().unwrap()[0] - DVec3::Z).length() < 1e-14);
        let last = l.points().unwrap()[(LATTICE + 1) * (LATTICE + 1) - 1];
        assert!((last - Sphere.cap(1, 0.5, 1.0)).length() < 1e-14);
    }

    #[test]
    fn bending_energy_of_a_sphere_patch_is_twice_its_area_over_r_squared() {
        // κ₁ = κ₂ = 1 / r: the energy is 2 A / r². A patch of a sphere of radius 2.
        let r = 2.0;
        let p: Vec<DVec3> = (0..(LATTICE + 1) * (LATTICE + 1))
            .map(|k| {
                let (u, v) = lattice_uv(k);
                let (lat, lon) = (0.2 * u - 0.1, 0.2 * v);
                DVec3::new(
                    math::cos(lat) * math::cos(lon),
                    math::cos(lat) * math::sin(lon),
                    math::sin(lat),
                ) * r
            })
            .collect();
        let area = r * r * 0.2 * 2.0 * math::sin(0.1f64);
        // With difference normals (the design's) and with exact ones (the limit's: x / r).
        let exact: Vec<DVec3> = p.iter().map(|q| *q / r).collect();
        for normals in [lattice_normals(&p), exact] {
            let e = bending_energy(&p, &normals);
            assert!((e / (2.0 * area / (r * r)) - 1.0).abs() < 0.02, "{e}");
        }
        let flat: Vec<DVec3> = p.iter().map(|q| DVec3::new(q.y, q.z, 0.0)).collect();
        assert!(bending_energy(&flat, &lattice_normals(&flat)) < 1e-20);
    }

    /// The limit lattice and bending energy of every face of `mesh`.
    fn limit_energies(mesh: &Mesh) -> Vec<(Vec<DVec3>, Vec<DVec3>, f64)> {
        let ev = Evaluator::new(mesh, &mesh.options().resolve()).unwrap();
        (0..ev.num_parametric_faces() as u32)
            .map(|f| {
                let (mut p, mut n) = (Vec::new(), Vec::new());
                limit_lattice(&ev, f, &mut p, &mut n).unwrap();
                let e = bending_energy(&p, &n);
                (p, n, e)
            })
            .collect()
    }

    #[test]
    fn a_plane_with_a_zero_jacobian_corner_has_no_bending_energy() {
        // One quad in a tilted plane whose corner 1 lies on the segment from corner 0 to
        // corner 2: the quad spans a straight angle there, where the limit's du and dv are
        // parallel (zero Jacobian, `du × dv` rounding noise of either sign).
        let (e1, e2) = (
            DVec3::new(1.0, 2.0, 3.0).normalize(),
            DVec3::new(3.0, 0.0, -1.0).normalize(),
        );
        let at = |x: f64, y: f64| DVec3::new(0.3, -0.2, 0.5) + e1 * x + e2 * y;
        let mesh = Mesh::from_parts(MeshParts {
            positions: vec![at(0.0, 0.0), at(1.0, 0.0), at(2.0, 0.0), at(0.4, 1.0)],
            face_sizes: vec![4],
            face_indices: vec![0, 1, 2, 3],
            ..Default::default()
        })
        .unwrap();
        let ev = Evaluator::new(&mesh, &mesh.options().resolve()).unwrap();
        let corner = ev.evaluate(0, 1.0, 0.0).unwrap();
        assert!(
            corner.du.cross(corner.dv).length()
                < ZERO_JACOBIAN_SINE * corner.du.length() * corner.dv.length()
        );
        let plane = e1.cross(e2).normalize();
        let [(_, normals, energy)] = limit_energies(&mesh).try_into().unwrap();
        let side = normals[0].dot(plane).signum();
        for n in &normals {
            assert!((n.dot(plane) - side).abs() < 1e-12, "{n} {plane}");
        }
        assert!(energy < 1e-20, "{energy}");
    }

    #[test]
    fn flat_meridian_caps_have_no_bending_energy() {
        // A flat-based bottle turned 90° with flat meridian caps: the cap in the plane y = 0
        // is planar (its control points are), so its bending energy is zero. Difference
        // normals of the limit lattice reversed in the skewed cells next to the axis and gave
        // its two faces there 228 each (the whole side: 6.4).
        let mut input = crate::RevolveInput::new(vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.8],
            [0.45, 2.5],
            [0.45, 3.2],
        ]);
        (input.angle_deg, input.samples_around, input.samples_profile) = (90.0, 32, 16);
        let settings = crate::Settings {
            caps: crate::Caps::Flat,
            ..Default::default()
        };
        let turn = crate::revolve::build(&input, &settings).unwrap();
        let (mut cap, mut side) = (0, 0.0);
        for (p, _, e) in limit_energies(&turn.mesh) {
            if p.iter().all(|q| q.y == 0.0) {
                assert!(e < 1e-20, "{e}");
                cap += 1;
            } else {
                side += e;
            }
        }
        assert!(cap > 8, "{cap}");
        // The side: a surface of revolution of about the profile's energy.
        assert!((5.0..8.0).contains(&side), "{side}");
    }
}
