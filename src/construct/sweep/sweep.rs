//! General sweeps: the JSON/Rust input and the grid of data points it defines.
//!
//! ```json
//! { "profile": [[a,b],...], "closed_profile": true, "trajectory": [[x,y,z],...],
//!   "closed_trajectory": false, "frame": "rmf", "samples_profile": 16,
//!   "samples_trajectory": 32, "scale": [1, 1], "profile_end": [[a,b],...],
//!   "interpolation": "spline", "sharp_angle_deg": 30,
//!   "corners": {"profile": [2], "trajectory": [5]}, "crease_sharpness": "infinite",
//!   "boundary": "edge-and-corner", "crease_method": "uniform" }
//! ```
//! Only `profile` and `trajectory` are required; an unknown key is an error. Defaults:
//! `closed_profile` = `closed_trajectory` = `false`, `frame` = `"rmf"` (or `"fixed"`,
//! `"frenet"`, see [`super::frames`]), `samples_profile` = 16 and `samples_trajectory` = 32
//! sample *intervals* (a closed curve has as many samples, an open one one more),
//! `scale` = `[1, 1]` (the profile is scaled linearly from the first to the second factor
//! along the trajectory's length), `profile_end` = none (with it, the profile morphs linearly
//! into this second profile, which must have the same point count), `interpolation` =
//! `"spline"` (`"polyline"` takes the points literally), `sharp_angle_deg` = 30 (points turning
//! by more are corners), `corners` = none (point indices forced to be corners; for an open
//! curve only interior points), `crease_sharpness` = `"infinite"` (or a number ≥ 0, as in the
//! profile construction), `boundary` = `"edge-and-corner"` (`"edge-only"`, `"none"`) and
//! `crease_method` = `"uniform"` (`"chaikin"`): the options the mesh is fitted under and
//! tagged with ([`crate::fit::cage`]). Profile coordinates `(a, b)` run along the frame's normal and
//! binormal; the profile's origin follows the trajectory.
//!
//! Features: a profile corner becomes a column of crease edges along the sweep direction, a
//! trajectory corner a ring of crease edges across it (its section is mitered, see
//! [`super::frames`]). Faces are oriented outward for a closed profile (whichever way it
//! runs); for an open profile the normal is `profile direction × sweep direction`.

use std::path::Path;

use glam::DVec3;
use serde::Deserialize;

use super::frames::FrameKind;
use super::mesh::{grid_mesh, grid_mesh_coords};
use super::profile::SweptProfile;
use super::trajectory::{Trajectory, TrajectorySample};
use crate::construct::design::{parts_lattice, Design, DesignLattice};
use crate::construct::profile::input::{
    check_crease_sharpness, default_crease_sharpness, deserialize_sharpness,
};
use crate::construct::profile::input::{MAX_SAMPLES, MAX_SAMPLE_PRODUCT};
use crate::curves::Interpolation;
use crate::error::{Error, Result};
use crate::fit::FitOptions;
use crate::mesh::MeshParts;
use crate::options::{BoundaryInterpolation, CreaseMethod};

/// A sweep: profile, trajectory, frame and sampling. See the module documentation for the
/// JSON form and the defaults.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepInput {
    /// Profile points `(a, b)` in the frame's (normal, binormal) plane.
    pub profile: Vec<[f64; 2]>,
    /// Whether the profile's last point joins its first. Default false.
    #[serde(default)]
    pub closed_profile: bool,
    /// Trajectory points `(x, y, z)`.
    pub trajectory: Vec<[f64; 3]>,
    /// Whether the trajectory's last point joins its first. Default false.
    #[serde(default)]
    pub closed_trajectory: bool,
    /// Frame along the trajectory. Default rotation-minimizing.
    #[serde(default)]
    pub frame: FrameKind,
    /// Sample intervals along the profile. Default 16.
    #[serde(default = "default_samples_profile")]
    pub samples_profile: usize,
    /// Sample intervals along the trajectory. Default 32.
    #[serde(default = "default_samples_trajectory")]
    pub samples_trajectory: usize,
    /// Profile scale at the start and at the end of the trajectory. Default `[1, 1]`.
    #[serde(default = "default_scale")]
    pub scale: [f64; 2],
    /// Profile to morph into along the trajectory (same point count). Default none.
    #[serde(default)]
    pub profile_end: Option<Vec<[f64; 2]>>,
    /// How the points of both curves are joined. Default spline.
    #[serde(default)]
    pub interpolation: Interpolation,
    /// Turning angle (degrees) above which a point is a corner. Default 30.
    #[serde(default = "default_sharp_angle")]
    pub sharp_angle_deg: f64,
    /// Point indices forced to be corners. Default none.
    #[serde(default)]
    pub corners: SweepCorners,
    /// Sharpness of the crease columns (profile corners) and rings (trajectory corners):
    /// a number ≥ 0 (10 or more: infinitely sharp), or `"infinite"` (the default).
    #[serde(
        default = "default_crease_sharpness",
        deserialize_with = "deserialize_sharpness"
    )]
    pub crease_sharpness: f32,
    /// Boundary interpolation for the fit and the tags (open curves have boundaries).
    /// Default edge-and-corner.
    #[serde(default)]
    pub boundary: BoundaryInterpolation,
    /// Crease decay for the fit and the tags. Default uniform.
    #[serde(default)]
    pub crease_method: CreaseMethod,
}

/// Point indices forced to be corners, per curve.
#[derive(Debug, Clone, PartialEq, Eq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepCorners {
    /// Corner point indices of the profile (and of `profile_end`).
    #[serde(default)]
    pub profile: Vec<usize>,
    /// Corner point indices of the trajectory.
    #[serde(default)]
    pub trajectory: Vec<usize>,
}

fn default_samples_profile() -> usize {
    16
}
fn default_samples_trajectory() -> usize {
    32
}
fn default_scale() -> [f64; 2] {
    [1.0, 1.0]
}
fn default_sharp_angle() -> f64 {
    30.0
}

/// Whether sample interval counts `a` (at least `min_a`) and `b` (at least 1) are within the
/// limits the profile construction accepts.
pub(super) fn sample_counts_ok(a: usize, b: usize, min_a: usize) -> bool {
    let max = MAX_SAMPLES as usize;
    (min_a..=max).contains(&a)
        && (1..=max).contains(&b)
        && (a as u64) * (b as u64) <= MAX_SAMPLE_PRODUCT
}

/// How the first or last ring of a grid is finished.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GridEnd {
    /// Left open: boundary edges.
    Open,
    /// Closed at one tip vertex at this point, tagged as an infinitely sharp corner.
    Tip(DVec3),
    /// Closed by a grid cap through a smooth pole.
    Smooth,
    /// Closed by a flat grid cap, creased where it meets the side.
    Flat,
}

/// The data points of a sweep on a grid, with what the mesh needs to know about it.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepGrid {
    /// One ring per trajectory sample, each with one data point per profile sample.
    pub rings: Vec<Vec<DVec3>>,
    /// Whether each ring is closed (closed profile).
    pub ring_closed: bool,
    /// Whether the last ring joins the first (closed trajectory).
    pub rings_closed: bool,
    /// Rings at trajectory corners: crease rings across the sweep.
    pub crease_rings: Vec<usize>,
    /// Profile samples at profile corners: crease columns along the sweep.
    pub crease_columns: Vec<usize>,
    /// Whether faces must be reversed to face outward (a clockwise closed profile).
    pub flip: bool,
    /// How the first and the last ring are finished.
    pub ends: [GridEnd; 2],
    /// Sharpness of the crease rings and columns.
    pub crease_sharpness: f32,
}

impl SweepInput {
    /// An input with the given curves and every setting at its default.
    pub fn new(profile: Vec<[f64; 2]>, trajectory: Vec<[f64; 3]>) -> SweepInput {
        SweepInput {
            profile,
            closed_profile: false,
            trajectory,
            closed_trajectory: false,
            frame: FrameKind::default(),
            samples_profile: default_samples_profile(),
            samples_trajectory: default_samples_trajectory(),
            scale: default_scale(),
            profile_end: None,
            interpolation: Interpolation::default(),
            sharp_angle_deg: default_sharp_angle(),
            corners: SweepCorners::default(),
            crease_sharpness: default_crease_sharpness(),
            boundary: BoundaryInterpolation::default(),
            crease_method: CreaseMethod::default(),
        }
    }

    /// The subdivision options the surface is fitted under.
    pub fn fit_options(&self) -> FitOptions {
        FitOptions::new(self.boundary, self.crease_method)
    }

    /// Parse the JSON form; `path` only names the input in messages.
    pub fn from_json(text: &str, path: &Path) -> Result<SweepInput> {
        crate::io::json::parse_json(text, path)
    }

    fn check_settings(&self) -> Result<()> {
        let (np, nt) = (self.samples_profile, self.samples_trajectory);
        if !sample_counts_ok(np, nt, 1) {
            return Err(Error::invalid_argument(format!(
                "samples_profile = {np} and samples_trajectory = {nt}: each must be 1..={MAX_SAMPLES} \
                 and their product at most {MAX_SAMPLE_PRODUCT}"
            )));
        }
        if !(self.sharp_angle_deg.is_finite() && (0.0..=180.0).contains(&self.sharp_angle_deg)) {
            return Err(Error::invalid_argument(format!(
                "sharp_angle_deg = {} must be a number of degrees in 0..=180",
                self.sharp_angle_deg
            )));
        }
        if self.scale.iter().any(|s| !s.is_finite() || *s <= 0.0) {
            return Err(Error::invalid_argument(format!(
                "scale = [{}, {}]: both factors must be finite and positive",
                self.scale[0], self.scale[1]
            )));
        }
        if self.closed_trajectory && (self.scale[0] != self.scale[1] || self.profile_end.is_some())
        {
            return Err(Error::invalid_argument(
                "a closed trajectory needs the same profile at both ends: equal scale factors \
                 and no profile_end (the surface would not close)",
            ));
        }
        check_crease_sharpness(self.crease_sharpness)
    }

    /// Sample the sweep: validate everything and compute the grid of data points.
    ///
    /// Errors ([`Error::InvalidArgument`]) with a message naming the culprit: bad counts or
    /// settings, the profile or trajectory errors of [`SweptProfile::new`] and
    /// [`Trajectory::new`], a frame that cannot be built (see [`super::frames`]).
    pub fn grid(&self) -> Result<SweepGrid> {
        self.check_settings()?;
        let sharp = self.sharp_angle_deg.to_radians();
        let profile = SweptProfile::new(
            &self.profile,
            self.profile_end.as_deref(),
            self.closed_profile,
            self.interpolation,
            sharp,
            &self.corners.profile,
        )?;
        let points: Vec<DVec3> = self.trajectory.iter().map(|&p| DVec3::from(p)).collect();
        let trajectory = Trajectory::new(
            &points,
            self.closed_trajectory,
            self.interpolation,
            sharp,
            &self.corners.trajectory,
        )?;
        let section = profile.sample(self.samples_profile)?;
        let samples = trajectory.samples(self.samples_trajectory, self.frame)?;
        let mut rings = Vec::with_capacity(samples.len());
        for (i, t) in samples.iter().enumerate() {
            let scale = self.scale[0] + (self.scale[1] - self.scale[0]) * t.fraction;
            let ring: Vec<DVec3> = section
                .at(t.fraction, scale)
                .map(|p| t.frame.place(p.x, p.y))
                .collect();
            if self.frame != FrameKind::Fixed {
                check_no_fold(i, t, &ring)?;
            }
            rings.push(ring);
        }
        Ok(SweepGrid {
            rings,
            ring_closed: section.closed,
            rings_closed: self.closed_trajectory,
            crease_rings: (0..samples.len()).filter(|&i| samples[i].corner).collect(),
            crease_columns: section.corners,
            flip: section.clockwise,
            ends: [GridEnd::Open; 2],
            crease_sharpness: self.crease_sharpness,
        })
    }
}

/// Error if a section point lies at or beyond the trajectory's centre of curvature: moving
/// frames sweep it backwards there, folding the surface (`1 − κ·(d·N) ≤ 0` for the offset `d`).
fn check_no_fold(i: usize, t: &TrajectorySample, ring: &[DVec3]) -> Result<()> {
    let worst = ring
        .iter()
        .map(|p| (*p - t.frame.origin).dot(t.curvature))
        .fold(f64::NEG_INFINITY, f64::max);
    if worst >= 1.0 {
        return Err(Error::invalid_argument(format!(
            "the profile reaches past the trajectory's centre of curvature at trajectory sample \
             {i} (radius of curvature {:.6}): the swept surface would fold; make the profile \
             smaller or the bend wider",
            1.0 / t.curvature.length()
        )));
    }
    Ok(())
}

/// Most sample intervals of the design grid per interval of the sweep's grid (each way);
/// fewer when the finer grid would pass the sample limits.
pub const DESIGN_REFINEMENT: usize = 8;

impl SweepInput {
    /// Quad mesh parts of the sweep, each vertex at its data point (the fitter's input).
    pub fn mesh_parts(&self) -> Result<MeshParts> {
        grid_mesh(&self.grid()?, &|_, _| DVec3::ZERO)
    }

    /// [`SweepInput::mesh_parts`] and the design surface on every face's lattice
    /// ([`crate::construct::design`]). A sweep's frames exist only at trajectory samples,
    /// so its design surface is the same sweep sampled up to [`DESIGN_REFINEMENT`] times
    /// more densely each way, bilinear between those samples (the data points are every
    /// `r`-th of the finer grid's where the runs between corners split evenly; the
    /// report's distance shows where they do not).
    pub fn cage(&self) -> Result<(MeshParts, DesignLattice)> {
        let grid = self.grid()?;
        let (parts, coords) = grid_mesh_coords(&grid, &|_, _| DVec3::ZERO)?;
        let r = [DESIGN_REFINEMENT, 4, 2, 1]
            .into_iter()
            .find(|&r| sample_counts_ok(self.samples_profile * r, self.samples_trajectory * r, 1))
            .unwrap_or(1);
        let mut fine = self.clone();
        fine.samples_profile *= r;
        fine.samples_trajectory *= r;
        let fine = fine.grid()?;
        let intervals = |n: usize, closed: bool| (if closed { n } else { n - 1 }).max(1) as f64;
        let scale = [
            intervals(fine.rings.len(), fine.rings_closed)
                / intervals(grid.rings.len(), grid.rings_closed),
            intervals(fine.rings[0].len(), fine.ring_closed)
                / intervals(grid.rings[0].len(), grid.ring_closed),
        ];
        let design = GridDesign {
            grid: fine,
            scale,
            coarse: [grid.rings.len(), grid.rings[0].len()],
        };
        let lattice = parts_lattice(&parts, &coords, &design);
        Ok((parts, lattice))
    }
}

/// A sweep's design surface: a finer sample grid of it, bilinear between samples.
struct GridDesign {
    grid: SweepGrid,
    /// Finer intervals per coarse interval: along the sweep, along the profile.
    scale: [f64; 2],
    /// Coarse rings and points per ring (the periods of closed curves).
    coarse: [usize; 2],
}

impl GridDesign {
    /// Fine grid point at integer indices, wrapping closed curves and clamping open ones.
    fn at(&self, i: i64, j: i64) -> DVec3 {
        let (rows, cols) = (
            self.grid.rings.len() as i64,
            self.grid.rings[0].len() as i64,
        );
        let wrap = |x: i64, n: i64, closed: bool| {
            if closed {
                x.rem_euclid(n)
            } else {
                x.clamp(0, n - 1)
            }
        };
        let i = wrap(i, rows, self.grid.rings_closed) as usize;
        let j = wrap(j, cols, self.grid.ring_closed) as usize;
        self.grid.rings[i][j]
    }
}

impl Design for GridDesign {
    fn side(&self, s: f64, theta: f64) -> DVec3 {
        let (x, y) = (s * self.scale[0], theta * self.scale[1]);
        let (i, j) = (x.floor(), y.floor());
        let (fx, fy) = (x - i, y - j);
        let (i, j) = (i as i64, j as i64);
        self.at(i, j) * ((1.0 - fx) * (1.0 - fy))
            + self.at(i + 1, j) * (fx * (1.0 - fy))
            + self.at(i + 1, j + 1) * (fx * fy)
            + self.at(i, j + 1) * ((1.0 - fx) * fy)
    }

    fn angle(&self, theta: f64) -> f64 {
        theta
    }

    fn cap(&self, _end: usize, _rho: f64, _theta: f64) -> DVec3 {
        unreachable!("sweeps have no caps")
    }

    fn periods(&self) -> [Option<f64>; 2] {
        [
            self.grid.rings_closed.then_some(self.coarse[0] as f64),
            self.grid.ring_closed.then_some(self.coarse[1] as f64),
        ]
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::math;
    use std::f64::consts::TAU;

    /// `n` points on the circle of radius `r` about the origin, counter-clockwise.
    pub(in crate::construct::sweep) fn circle2(n: usize, r: f64) -> Vec<[f64; 2]> {
        (0..n)
            .map(|i| {
                let t = TAU * i as f64 / n as f64;
                [r * math::cos(t), r * math::sin(t)]
            })
            .collect()
    }

    fn circle3(n: usize, r: f64) -> Vec<[f64; 3]> {
        circle2(n, r)
            .into_iter()
            .map(|[x, y]| [x, y, 0.0])
            .collect()
    }

    #[test]
    fn circle_along_circle_samples_a_torus() {
        let mut input = SweepInput::new(circle2(16, 0.5), circle3(16, 2.0));
        input.closed_profile = true;
        input.closed_trajectory = true;
        let g = input.grid().unwrap();
        assert_eq!(g.rings.len(), 32);
        assert!(g.rings.iter().all(|r| r.len() == 16));
        assert!(g.ring_closed && g.rings_closed && !g.flip);
        assert!(g.crease_rings.is_empty() && g.crease_columns.is_empty());
        let mut worst: f64 = 0.0;
        for p in g.rings.iter().flatten() {
            let q = ((p.truncate().length() - 2.0).powi(2) + p.z * p.z).sqrt();
            worst = worst.max((q - 0.5).abs());
        }
        assert!(worst < 2e-4, "torus deviation {worst}");
    }

    #[test]
    fn square_profile_on_closed_curve_gives_four_crease_columns_and_no_ring() {
        let mut input = SweepInput::new(
            vec![[-0.2, -0.2], [0.2, -0.2], [0.2, 0.2], [-0.2, 0.2]],
            circle3(16, 3.0),
        );
        input.closed_profile = true;
        input.closed_trajectory = true;
        input.samples_profile = 8;
        let g = input.grid().unwrap();
        assert_eq!(g.crease_columns, vec![0, 2, 4, 6]);
        assert!(g.crease_rings.is_empty());
        // Clockwise profile: faces must be flipped.
        input.profile.reverse();
        assert!(input.grid().unwrap().flip);
    }

    #[test]
    fn l_shaped_trajectory_gives_a_mitered_crease_ring() {
        let mut input = SweepInput::new(
            circle2(8, 0.25),
            vec![[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 2.0, 0.0]],
        );
        input.closed_profile = true;
        input.samples_trajectory = 8;
        let g = input.grid().unwrap();
        assert_eq!(g.crease_rings, vec![4]);
        // Every corner-ring point lies on the miter plane x − 2 = −y... i.e. (x−2) + y = 0.
        for p in &g.rings[4] {
            assert!((p.x - 2.0 + p.y).abs() < 1e-12, "{p}");
        }
    }

    #[test]
    fn a_profile_wider_than_the_bend_is_refused() {
        let mut input = SweepInput::new(circle2(16, 0.5), circle3(24, 2.0));
        input.closed_profile = true;
        input.closed_trajectory = true;
        assert!(input.grid().is_ok());
        input.profile = circle2(16, 2.2);
        let e = input.grid().unwrap_err();
        assert!(matches!(e, Error::InvalidArgument(m) if m.contains("centre of curvature")));
    }

    #[test]
    fn forced_corners_give_crease_columns_and_rings() {
        let mut input = SweepInput::new(
            vec![[0.0, 0.0], [1.0, 0.0], [2.0, 0.1], [3.0, 0.0]],
            vec![
                [0.0, 0.0, 0.0],
                [0.0, 0.0, 1.0],
                [0.0, 0.1, 2.0],
                [0.0, 0.0, 3.0],
            ],
        );
        (input.samples_profile, input.samples_trajectory) = (6, 6);
        assert!(input.grid().unwrap().crease_columns.is_empty());
        input.corners = SweepCorners {
            profile: vec![1],
            trajectory: vec![2],
        };
        let g = input.grid().unwrap();
        assert_eq!(g.crease_columns, vec![2]);
        assert_eq!(g.crease_rings, vec![4]);
        input.corners.trajectory = vec![3];
        assert!(matches!(input.grid(), Err(Error::InvalidArgument(m)) if m.contains("corner 3")));
    }

    #[test]
    fn scale_and_morph_follow_the_trajectory_fraction() {
        let mut input = SweepInput::new(
            vec![[1.0, 0.0], [1.0, 1.0]],
            vec![[0.0, 0.0, 0.0], [0.0, 0.0, 4.0]],
        );
        input.scale = [1.0, 3.0];
        input.samples_trajectory = 4;
        input.samples_profile = 1;
        input.profile_end = Some(vec![[2.0, 0.0], [2.0, 1.0]]);
        let g = input.grid().unwrap();
        // Straight trajectory along z: normal from the least aligned axis (x), binormal y.
        assert_eq!(
            g.rings[0],
            vec![DVec3::new(1.0, 0.0, 0.0), DVec3::new(1.0, 1.0, 0.0)]
        );
        // Half way: scale 2, profile (1.5, ·).
        assert_eq!(
            g.rings[2],
            vec![DVec3::new(3.0, 0.0, 2.0), DVec3::new(3.0, 2.0, 2.0)]
        );
        assert_eq!(
            g.rings[4],
            vec![DVec3::new(6.0, 0.0, 4.0), DVec3::new(6.0, 3.0, 4.0)]
        );
    }

    #[test]
    fn json_defaults_unknown_keys_and_bad_settings() {
        let p = Path::new("in.json");
        let i = SweepInput::from_json(
            r#"{"profile": [[0,0],[1,0]], "trajectory": [[0,0,0],[0,0,1]]}"#,
            p,
        )
        .unwrap();
        assert_eq!(
            i,
            SweepInput::new(
                vec![[0.0, 0.0], [1.0, 0.0]],
                vec![[0.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
            )
        );
        let e = SweepInput::from_json(r#"{"profile": [], "trajectory": [], "frames": "rmf"}"#, p)
            .unwrap_err();
        assert!(
            matches!(e, Error::Parse { message, .. } if message.contains("unknown field `frames`"))
        );
        let e = SweepInput::from_json(r#"{"profile": [], "trajectory": [], "frame": "bishop"}"#, p)
            .unwrap_err();
        assert!(matches!(e, Error::Parse { .. }));
        let i = SweepInput::from_json(
            r#"{"profile": [[0,0],[1,0]], "trajectory": [[0,0,0],[0,0,1]], "frame": "frenet", "interpolation": "polyline"}"#,
            p,
        )
        .unwrap();
        assert_eq!(i.frame, FrameKind::Frenet);
        assert_eq!(i.interpolation, Interpolation::Polyline);
        let msg = |f: &dyn Fn(&mut SweepInput)| {
            let mut i = SweepInput::new(
                vec![[0.0, 0.0], [1.0, 0.0]],
                vec![[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 2.0]],
            );
            f(&mut i);
            match i.grid() {
                Err(Error::InvalidArgument(m)) => m,
                other => panic!("expected an error, got {other:?}"),
            }
        };
        assert!(msg(&|i| i.samples_profile = 0).contains("samples_profile = 0"));
        assert!(msg(&|i| i.samples_trajectory = 100_000).contains("4096"));
        assert!(msg(&|i| i.scale = [1.0, 0.0]).contains("positive"));
        assert!(msg(&|i| {
            i.closed_trajectory = true;
            i.scale = [1.0, 2.0];
        })
        .contains("closed trajectory"));
        assert!(msg(&|i| i.trajectory[1] = i.trajectory[0]).contains("coincide"));
        assert!(msg(&|i| i.profile = vec![[0.0, 0.0]])
            .contains("profile: an open curve needs at least 2"));
        assert!(msg(&|i| {
            i.trajectory = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]];
            i.frame = FrameKind::Frenet;
        })
        .contains("undefined everywhere"));
        assert!(msg(&|i| i.sharp_angle_deg = f64::NAN).contains("sharp_angle_deg"));
    }
}
