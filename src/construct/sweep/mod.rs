//! General sweeps: a planar profile moved along a 3-D trajectory; the JSON/Rust input, the
//! grid of data points it defines, and [`build`].
//!
//! - [`frames`]: fixed, Frenet and rotation-minimizing frames along a sampled trajectory;
//! - [`profile`]: the swept profile, its samples, scaling and morphing;
//! - [`trajectory`]: the validated trajectory, its samples and their frames.
//!
//! ```json
//! { "profile": [[a,b],...], "closed_profile": true, "trajectory": [[x,y,z],...],
//!   "closed_trajectory": false, "frame": "rmf", "samples_profile": 16,
//!   "samples_trajectory": 32, "scale": [1, 1], "profile_end": [[a,b],...],
//!   "interpolation": "spline", "sharp_angle_deg": 30,
//!   "corners": {"profile": [2], "trajectory": [5]}, "crease_sharpness": "infinite",
//!   "boundary": "edge-and-corner", "crease_method": "uniform" }
//! ```
//! Only `profile` and `trajectory` are required; an unknown key is an error. The keys
//! `interpolation`, `sharp_angle_deg`, `crease_sharpness`, `boundary`, `crease_method` are
//! the shared [`Settings`] (`caps` must stay `"open"`: a sweep has no caps). Defaults:
//! `closed_profile` = `closed_trajectory` = `false`, `frame` = `"rmf"` (or `"fixed"`,
//! `"frenet"`, see [`frames`]), `samples_profile` = 16 and `samples_trajectory` = 32
//! sample *intervals* (a closed curve has as many samples, an open one one more),
//! `scale` = `[1, 1]` (the profile is scaled linearly from the first to the second factor
//! along the trajectory's length), `profile_end` = none (with it, the profile morphs linearly
//! into this second profile, which must have the same point count), `interpolation` =
//! `"spline"` (`"polyline"` takes the points literally), `sharp_angle_deg` = 30 (points turning
//! by more are corners), `corners` = none (point indices forced to be corners; for an open
//! curve only interior points), `crease_sharpness` = `"infinite"` (or a number ≥ 0, as in the
//! profile construction), `boundary` = `"edge-and-corner"` (`"edge-only"`, `"none"`) and
//! `crease_method` = `"uniform"` (`"chaikin"`): the options the mesh is fitted under and
//! tagged with. Profile coordinates `(a, b)` run along the frame's normal and
//! binormal; the profile's origin follows the trajectory.
//!
//! Features: a profile corner becomes a column of crease edges along the sweep direction, a
//! trajectory corner a ring of crease edges across it (its section is mitered, see
//! [`frames`]). Faces are oriented outward for a closed profile (whichever way it
//! runs); for an open profile the normal is `profile direction × sweep direction`.

pub mod frames;
pub mod profile;
pub mod trajectory;

use std::path::Path;

use glam::DVec3;
use serde::Deserialize;

use crate::construct::design::{parts_lattice, Design, DesignLattice};
use crate::construct::fitted::Fitted;
use crate::construct::grid_mesh::{grid_mesh, grid_mesh_coords, GridEnd, SweepGrid};
use crate::construct::settings::{Caps, Settings, MAX_SAMPLES, MAX_SAMPLE_PRODUCT};
use crate::error::{Error, Result};
use crate::mesh::MeshParts;
use frames::FrameKind;
use profile::SweptProfile;
use trajectory::{Trajectory, TrajectorySample};

/// A sweep: profile, trajectory, frame and sampling (the shared settings are
/// [`Settings`]). See the module documentation for the JSON form and the defaults.
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
    /// Point indices forced to be corners. Default none.
    #[serde(default)]
    pub corners: SweepCorners,
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
            corners: SweepCorners::default(),
        }
    }

    /// Parse the JSON form into the input and its settings; `path` only names the input in
    /// messages.
    pub fn from_json(text: &str, path: &Path) -> Result<(SweepInput, Settings)> {
        crate::construct::settings::parse_json(text, path)
    }

    /// Both scale factors must be finite and positive.
    pub fn check_scale(scale: [f64; 2]) -> Result<()> {
        if scale.iter().all(|s| s.is_finite() && *s > 0.0) {
            Ok(())
        } else {
            Err(Error::invalid_argument(format!(
                "scale = [{}, {}]: both factors must be finite and positive",
                scale[0], scale[1]
            )))
        }
    }

    fn check_settings(&self, settings: &Settings) -> Result<()> {
        let (np, nt) = (self.samples_profile, self.samples_trajectory);
        if !Settings::samples_ok(np, nt, 1) {
            return Err(Error::invalid_argument(format!(
                "samples_profile = {np} and samples_trajectory = {nt}: each must be 1..={MAX_SAMPLES} \
                 and their product at most {MAX_SAMPLE_PRODUCT}"
            )));
        }
        settings.check()?;
        settings.check_fit_budget(np, nt)?;
        if settings.caps != Caps::Open {
            return Err(Error::invalid_argument(
                "caps = \"flat\": a sweep has no caps (close the profile instead)",
            ));
        }
        Self::check_scale(self.scale)?;
        if self.closed_trajectory && (self.scale[0] != self.scale[1] || self.profile_end.is_some())
        {
            return Err(Error::invalid_argument(
                "a closed trajectory needs the same profile at both ends: equal scale factors \
                 and no profile_end (the surface would not close)",
            ));
        }
        Ok(())
    }

    /// Sample the sweep: validate everything and compute the grid of data points.
    ///
    /// Errors ([`Error::InvalidArgument`]) with a message naming the culprit: bad counts or
    /// settings, the profile or trajectory errors of [`SweptProfile::new`] and
    /// [`Trajectory::new`], a frame that cannot be built (see [`frames`]).
    pub fn grid(&self, settings: &Settings) -> Result<SweepGrid> {
        self.check_settings(settings)?;
        let sharp = settings.sharp_angle_deg.to_radians();
        let profile = SweptProfile::new(
            &self.profile,
            self.profile_end.as_deref(),
            self.closed_profile,
            settings.interpolation,
            sharp,
            &self.corners.profile,
        )?;
        let points: Vec<DVec3> = self.trajectory.iter().map(|&p| DVec3::from(p)).collect();
        let trajectory = Trajectory::new(
            &points,
            self.closed_trajectory,
            settings.interpolation,
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
            crease_sharpness: settings.crease_sharpness,
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
    pub fn mesh_parts(&self, settings: &Settings) -> Result<MeshParts> {
        grid_mesh(&self.grid(settings)?, &|_, _| DVec3::ZERO)
    }

    /// [`SweepInput::mesh_parts`] and the design surface on every face's lattice
    /// ([`crate::construct::design`]). A sweep's frames exist only at trajectory samples,
    /// so its design surface is the same sweep sampled up to [`DESIGN_REFINEMENT`] times
    /// more densely each way, bilinear between those samples (the data points are every
    /// `r`-th of the finer grid's where the runs between corners split evenly; the
    /// report's distance shows where they do not).
    pub fn cage(&self, settings: &Settings) -> Result<(MeshParts, DesignLattice)> {
        let grid = self.grid(settings)?;
        let (parts, coords) = grid_mesh_coords(&grid, &|_, _| DVec3::ZERO)?;
        let r = [DESIGN_REFINEMENT, 4, 2, 1]
            .into_iter()
            .find(|&r| {
                Settings::samples_ok(self.samples_profile * r, self.samples_trajectory * r, 1)
            })
            .unwrap_or(1);
        let mut fine = self.clone();
        fine.samples_profile *= r;
        fine.samples_trajectory *= r;
        let fine = fine.grid(settings)?;
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
        let lattice = parts_lattice(&parts, &coords, &design, &settings.control)?;
        Ok((parts, lattice))
    }
}

/// The sweep of `input` under `settings`, fitted: the exact limit surface passes through
/// every data point. Errors: those of [`SweepInput::grid`] ([`Error::InvalidArgument`] for
/// bad input or settings) and of the fit.
pub fn build(input: &SweepInput, settings: &Settings) -> Result<Fitted> {
    let (parts, design) = input.cage(settings)?;
    Fitted::fit(parts, settings, design)
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
mod tests {
    use super::*;
    use crate::curves::Interpolation;
    use crate::test_support::circle2;

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
        let g = input.grid(&Settings::default()).unwrap();
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
        let g = input.grid(&Settings::default()).unwrap();
        assert_eq!(g.crease_columns, vec![0, 2, 4, 6]);
        assert!(g.crease_rings.is_empty());
        // Clockwise profile: faces must be flipped.
        input.profile.reverse();
        assert!(input.grid(&Settings::default()).unwrap().flip);
    }

    #[test]
    fn l_shaped_trajectory_gives_a_mitered_crease_ring() {
        let mut input = SweepInput::new(
            circle2(8, 0.25),
            vec![[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 2.0, 0.0]],
        );
        input.closed_profile = true;
        input.samples_trajectory = 8;
        let g = input.grid(&Settings::default()).unwrap();
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
        assert!(input.grid(&Settings::default()).is_ok());
        input.profile = circle2(16, 2.2);
        let e = input.grid(&Settings::default()).unwrap_err();
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
        assert!(input
            .grid(&Settings::default())
            .unwrap()
            .crease_columns
            .is_empty());
        input.corners = SweepCorners {
            profile: vec![1],
            trajectory: vec![2],
        };
        let g = input.grid(&Settings::default()).unwrap();
        assert_eq!(g.crease_columns, vec![2]);
        assert_eq!(g.crease_rings, vec![4]);
        input.corners.trajectory = vec![3];
        assert!(
            matches!(input.grid(&Settings::default()), Err(Error::InvalidArgument(m)) if m.contains("corner 3"))
        );
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
        let g = input.grid(&Settings::default()).unwrap();
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
        let (i, _) = SweepInput::from_json(
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
        let (i, s) = SweepInput::from_json(
            r#"{"profile": [[0,0],[1,0]], "trajectory": [[0,0,0],[0,0,1]], "frame": "frenet", "interpolation": "polyline"}"#,
            p,
        )
        .unwrap();
        assert_eq!(i.frame, FrameKind::Frenet);
        assert_eq!(s.interpolation, Interpolation::Polyline);
        let msg = |f: &dyn Fn(&mut SweepInput, &mut Settings)| {
            let mut i = SweepInput::new(
                vec![[0.0, 0.0], [1.0, 0.0]],
                vec![[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 2.0]],
            );
            let mut s = Settings::default();
            f(&mut i, &mut s);
            match i.grid(&s) {
                Err(Error::InvalidArgument(m)) => m,
                other => panic!("expected an error, got {other:?}"),
            }
        };
        assert!(msg(&|i, _| i.samples_profile = 0).contains("samples_profile = 0"));
        assert!(msg(&|i, _| i.samples_trajectory = 100_000).contains("4096"));
        assert!(msg(&|i, _| i.scale = [1.0, 0.0]).contains("positive"));
        assert!(msg(&|i, _| {
            i.closed_trajectory = true;
            i.scale = [1.0, 2.0];
        })
        .contains("closed trajectory"));
        assert!(msg(&|i, _| i.trajectory[1] = i.trajectory[0]).contains("coincide"));
        assert!(msg(&|i, _| i.profile = vec![[0.0, 0.0]])
            .contains("profile: an open curve needs at least 2"));
        assert!(msg(&|i, _| {
            i.trajectory = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]];
            i.frame = FrameKind::Frenet;
        })
        .contains("undefined everywhere"));
        assert!(msg(&|_, s| s.sharp_angle_deg = f64::NAN).contains("sharp_angle_deg"));
    }
}
