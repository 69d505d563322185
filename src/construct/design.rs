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
//! lattices (1 = as fair as the design; wiggles the design does not have raise it; normals
//! from lattice differences on both, so the discretization is the same; cells at a point
//! where the lattice's two derivatives are nearly parallel, such as a flat cap's corner on a
//! straight crease, where the limit's Jacobian vanishes, are left out of both).

use crate::math;
use std::f64::consts::TAU;
use std::sync::{Arc, OnceLock};

use glam::{DVec2, DVec3};

use crate::control::Control;
use crate::error::Result;
use crate::eval::folds::{find_folds_with, FoldSettings};
use crate::eval::Evaluator;
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
            // noise: none, and its cells are left out of the bending energy.
            if normal.length() < DEGENERATE_SINE * du.length() * dv.length() {
                DVec3::ZERO
            } else {
                normal.normalize()
            }
        })
        .collect()
}

/// Bending energy `∫ |∇n|² dA = ∫ (κ₁² + κ₂²) dA` of one face's lattice surface: per cell,
/// `tr(G⁻¹ H) √det G` with `G` the Gram matrix of the cell's edge vectors and `H` that of
/// its normal differences. It does not depend on the parameterization (up to the
/// discretization), so the limit and the design surface compare even where their
/// parameterizations differ.
fn bending_energy(p: &[DVec3], normal: &[DVec3]) -> f64 {
    let n = LATTICE + 1;
    let mut total = 0.0;
    for j in 0..LATTICE {
        for i in 0..LATTICE {
            let k = j * n + i;
            let (a, b) = (p[k + 1] - p[k], p[k + n] - p[k]);
            if [k, k + 1, k + n].iter().any(|&c| normal[c] == DVec3::ZERO) {
                continue;
            }
            let (na, nb) = (normal[k + 1] - normal[k], normal[k + n] - normal[k]);
            let (g11, g12, g22) = (a.dot(a), a.dot(b), b.dot(b));
            let det = g11 * g22 - g12 * g12;
            if det <= 0.0 {
                continue;
            }
            let (h11, h12, h22) = (na.dot(na), na.dot(nb), nb.dot(nb));
            total += (g22 * h11 - 2.0 * g12 * h12 + g11 * h22) / det * det.sqrt();
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
/// ([`find_folds_with`]).
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
    let mut limit = Vec::with_capacity(per_face);
    let points = design.points_with(&poll)?;
    let faces = points.len() / per_face;
    for (f, want) in points.chunks(per_face).enumerate() {
        poll.step(f, faces)?;
        if !ev.has_surface(f as u32) {
            continue;
        }
        limit.clear();
        for k in 0..per_face {
            let (u, v) = lattice_uv(k);
            limit.push(ev.evaluate(f as u32, u, v)?.position);
        }
        let normals = lattice_normals(want);
        for ((p, d), n) in limit.iter().zip(want).zip(&normals) {
            let e = (*p - *d).dot(*n).abs();
            max = max.max(e);
            offset = offset.max(p.distance(*d));
            sum += e;
            count += 1;
        }
        limit_energy += bending_energy(&limit, &lattice_normals(&limit));
        design_energy += bending_energy(want, &normals);
    }
    let folds = find_folds_with(&ev, &FoldSettings::default(), control)?;
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
        let e = bending_energy(&p, &lattice_normals(&p));
        assert!((e / (2.0 * area / (r * r)) - 1.0).abs() < 0.02, "{e}");
        let flat: Vec<DVec3> = p.iter().map(|q| DVec3::new(q.y, q.z, 0.0)).collect();
        assert!(bending_energy(&flat, &lattice_normals(&flat)) < 1e-20);
    }
}
