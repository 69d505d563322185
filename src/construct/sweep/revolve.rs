//! Surfaces of revolution: a profile `(r, z)` turned about the z axis.
//!
//! ```json
//! { "profile": [[r,z],...], "angle_deg": 360, "samples_profile": 16, "samples_around": 32,
//!   "interpolation": "spline", "sharp_angle_deg": 30, "corners": [3],
//!   "crease_sharpness": "infinite", "boundary": "edge-and-corner", "crease_method": "uniform",
//!   "caps": "open" }
//! ```
//! Only `profile` is required (points from bottom to top, `r ≥ 0`); an unknown key is an
//! error. Defaults: `angle_deg` = 360 (a full turn, closed; less than 360 leaves boundary
//! edges along the first and last meridians), `samples_profile` = 16 sample intervals from
//! bottom to top, `samples_around` = 32 meridian intervals, `interpolation` = `"spline"`,
//! `sharp_angle_deg` = 30, `corners` = none (profile point indices forced to be corners),
//! `crease_sharpness` = `"infinite"` (or a number ≥ 0, as in the profile construction; tips
//! stay infinitely sharp corners), `boundary` = `"edge-and-corner"` (`"edge-only"`, `"none"`)
//! and `crease_method` = `"uniform"` (`"chaikin"`): the options the mesh is fitted under and
//! tagged with ([`crate::fit::cage`]); `caps` = `"open"`. With `"caps": "flat"` the solid is closed by flat caps, creased where
//! they meet the side or each other: ends off the axis get a flat disc (full turn) or sector
//! (partial turn), and a partial turn's start and end meridian planes get flat caps between
//! the profile and the axis (layouts: [`super::wedge`]). Caps on a full turn whose ends are
//! both on the axis are refused (nothing to close).
//!
//! *Poles*: a profile end on the axis (`r = 0`) closes the surface there. The profile is
//! extended by its mirror image across the axis before it is interpolated, so the spline is
//! symmetric and meets the axis at a right angle unless the mirrored curve has a corner there:
//! a profile end whose chord turns (with its mirror) by more than `sharp_angle_deg`, i.e. meets
//! the axis at more than half that angle from the perpendicular, is a *pointed pole* (a tip
//! vertex tagged as an infinitely sharp corner, like a cone's apex); otherwise it is a *smooth
//! pole*, closed by a grid cap of quads (valence 3 and 4 only, see
//! [`crate::construct::pole_cap`]). On a full turn `samples_around` must be a multiple of 4
//! for a smooth pole or a flat cap and even for a tip. On a partial turn a pole lies on both
//! boundary meridians; it is closed by a sector of quads whose apex is tagged as an
//! infinitely sharp corner ([`super::wedge`]; `samples_around` a multiple of 4). Profile
//! corners give crease rings.

use crate::math;
use std::f64::consts::TAU;
use std::path::Path;

use glam::{DVec2, DVec3};
use serde::Deserialize;

use super::mesh::grid_mesh_coords;
use super::profile::check_no_crossing;
use super::sweep::{sample_counts_ok, GridEnd, SweepGrid};
use super::wedge::wedge_parts;
use crate::construct::design::{parts_lattice, Design, DesignLattice};
use crate::construct::equidistribute::place_samples;
use crate::construct::pole_cap::{cap_depths, grid_cap_depth};
use crate::construct::profile::input::{
    check_crease_sharpness, default_crease_sharpness, deserialize_sharpness,
};
use crate::construct::profile::input::{MAX_SAMPLES, MAX_SAMPLE_PRODUCT};
use crate::construct::profile::Caps;
use crate::curves::corners::detect_chord_corners;
use crate::curves::{Interpolation, SpaceCurve};
use crate::error::{Error, Result};
use crate::fit::FitOptions;
use crate::mesh::MeshParts;
use crate::options::{BoundaryInterpolation, CreaseMethod};

/// A surface of revolution. See the module documentation for the JSON form and defaults.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RevolveInput {
    /// Profile points `(r, z)`, bottom to top, `r ≥ 0`.
    pub profile: Vec<[f64; 2]>,
    /// Angle turned, degrees, `0 < angle ≤ 360`. Default 360.
    #[serde(default = "default_angle")]
    pub angle_deg: f64,
    /// Sample intervals along the profile. Default 16.
    #[serde(default = "default_samples_profile")]
    pub samples_profile: usize,
    /// Sample intervals around the axis. Default 32.
    #[serde(default = "default_samples_around")]
    pub samples_around: usize,
    /// How the points are joined. Default spline.
    #[serde(default)]
    pub interpolation: Interpolation,
    /// Turning angle (degrees) above which a point is a corner. Default 30.
    #[serde(default = "default_sharp_angle")]
    pub sharp_angle_deg: f64,
    /// Profile point indices forced to be corners (an end on the axis: a pointed pole).
    /// Default none.
    #[serde(default)]
    pub corners: Vec<usize>,
    /// Sharpness of the crease rings at profile corners (tips stay infinitely sharp): a
    /// number ≥ 0, or `"infinite"` (the default).
    #[serde(
        default = "default_crease_sharpness",
        deserialize_with = "deserialize_sharpness"
    )]
    pub crease_sharpness: f32,
    /// Boundary rule of the fit and the mesh's tag (matters for a partial turn). Default
    /// edge-and-corner.
    #[serde(default)]
    pub boundary: BoundaryInterpolation,
    /// Crease method of the fit and the mesh's tag. Default uniform.
    #[serde(default)]
    pub crease_method: CreaseMethod,
    /// `"flat"`: close the solid with flat caps (see [`super::wedge`]). Default `"open"`.
    #[serde(default)]
    pub caps: Caps,
}

fn default_angle() -> f64 {
    360.0
}
fn default_samples_profile() -> usize {
    16
}
fn default_samples_around() -> usize {
    32
}
fn default_sharp_angle() -> f64 {
    30.0
}

/// The validated profile of a revolution, mirrored across the axis at its poles.
#[derive(Debug, Clone, PartialEq)]
pub struct RevolvedProfile {
    curve: SpaceCurve,
    /// Parameter range of the user's profile on `curve`.
    range: [f64; 2],
    /// Which ends are on the axis.
    on_axis: [bool; 2],
}

impl RevolvedProfile {
    /// Validate and interpolate the profile; points in `forced` are corners (an end on the
    /// axis: a pointed pole). Errors ([`Error::InvalidArgument`]): those of
    /// [`SpaceCurve::new`], a negative `r` (the profile crosses the axis), an interior point on
    /// the axis, a profile that crosses itself, a forced corner that is neither interior nor an
    /// end on the axis.
    pub fn new(
        points: &[[f64; 2]],
        interpolation: Interpolation,
        sharp_angle: f64,
        forced: &[usize],
    ) -> Result<RevolvedProfile> {
        let lifted: Vec<DVec3> = points.iter().map(|p| DVec3::new(p[0], p[1], 0.0)).collect();
        SpaceCurve::new("profile", &lifted, false, Interpolation::Polyline, &[])?;
        if let Some(i) = points.iter().position(|p| p[0] < 0.0) {
            return Err(Error::invalid_argument(format!(
                "profile point {i} has r = {} < 0: the profile crosses the axis",
                points[i][0]
            )));
        }
        let n = points.len();
        if let Some(i) = (1..n - 1).find(|&i| points[i][0] == 0.0) {
            return Err(Error::invalid_argument(format!(
                "profile point {i} is on the axis; only the first and last point may be"
            )));
        }
        check_no_crossing("profile", points, false)?;
        let on_axis = [points[0][0] == 0.0, points[n - 1][0] == 0.0];
        let mirror = |p: &DVec3| DVec3::new(-p.x, p.y, 0.0);
        let mut all: Vec<DVec3> = Vec::with_capacity(2 * n);
        let closed = on_axis[0] && on_axis[1];
        let first;
        if closed {
            if n < 3 {
                return Err(Error::invalid_argument(
                    "profile: a profile with both ends on the axis needs a point off the axis",
                ));
            }
            first = 0;
            all.extend_from_slice(&lifted);
            all.extend(lifted[1..n - 1].iter().rev().map(mirror));
        } else {
            if on_axis[0] {
                all.extend(lifted[1..].iter().rev().map(mirror));
            }
            first = all.len();
            all.extend_from_slice(&lifted);
            if on_axis[1] {
                all.extend(lifted[..n - 1].iter().rev().map(mirror));
            }
        }
        let mut corners = detect_chord_corners(&all, closed, sharp_angle);
        for &c in forced {
            if c >= n || ((c == 0 || c == n - 1) && !on_axis[usize::from(c != 0)]) {
                return Err(Error::invalid_argument(format!(
                    "profile: corner {c} is not an interior point or an end on the axis \
                     (0 <= index < {n})"
                )));
            }
            corners.push(first + c);
            // Its mirror image too, so that the spline stays symmetric about the axis.
            if c > 0 && c < n - 1 {
                if on_axis[1] {
                    corners.push(2 * n - 2 - c);
                } else if on_axis[0] {
                    corners.push(n - 1 - c);
                }
            }
        }
        let curve = SpaceCurve::new("profile", &all, closed, interpolation, &corners)?;
        let range = [curve.knots()[first], curve.knots()[first + n - 1]];
        Ok(RevolvedProfile {
            curve,
            range,
            on_axis,
        })
    }

    /// `(r, z)` at parameter `s` of the (mirrored) curve.
    pub fn point(&self, s: f64) -> DVec2 {
        self.curve.eval(s, false).position.truncate()
    }

    /// Parameter range `[bottom, top]` of the user's profile.
    pub fn range(&self) -> [f64; 2] {
        self.range
    }

    /// The end kind at the bottom (`0`) or top (`1`): open, tip or smooth pole.
    pub fn end(&self, which: usize) -> GridEnd {
        if !self.on_axis[which] {
            return GridEnd::Open;
        }
        let s = self.range[which];
        let tip = self
            .curve
            .corners()
            .iter()
            .any(|&c| self.curve.knots()[c] == s);
        if tip {
            GridEnd::Tip(DVec3::new(0.0, 0.0, self.point(s).y))
        } else {
            GridEnd::Smooth
        }
    }
}

/// The point at `(r, z)` turned by `theta` radians about the z axis.
pub fn revolve_point(p: DVec2, theta: f64) -> DVec3 {
    DVec3::new(p.x * math::cos(theta), p.x * math::sin(theta), p.y)
}

impl RevolveInput {
    /// An input with the given profile and every setting at its default.
    pub fn new(profile: Vec<[f64; 2]>) -> RevolveInput {
        RevolveInput {
            profile,
            angle_deg: default_angle(),
            samples_profile: default_samples_profile(),
            samples_around: default_samples_around(),
            interpolation: Interpolation::default(),
            sharp_angle_deg: default_sharp_angle(),
            corners: Vec::new(),
            crease_sharpness: default_crease_sharpness(),
            boundary: BoundaryInterpolation::default(),
            crease_method: CreaseMethod::default(),
            caps: Caps::Open,
        }
    }

    /// The subdivision options the surface is fitted under.
    pub fn fit_options(&self) -> FitOptions {
        FitOptions::new(self.boundary, self.crease_method)
    }

    /// Parse the JSON form; `path` only names the input in messages.
    pub fn from_json(text: &str, path: &Path) -> Result<RevolveInput> {
        crate::io::json::parse_json(text, path)
    }

    /// Whether the revolution is a full turn.
    pub fn full_turn(&self) -> bool {
        self.angle_deg == 360.0
    }

    fn check_settings(&self) -> Result<()> {
        let (np, na) = (self.samples_profile, self.samples_around);
        if !sample_counts_ok(na, np, 3) {
            return Err(Error::invalid_argument(format!(
                "samples_profile = {np} and samples_around = {na}: samples_profile must be \
                 1..={MAX_SAMPLES}, samples_around 3..={MAX_SAMPLES}, their product at most \
                 {MAX_SAMPLE_PRODUCT}"
            )));
        }
        if !(self.angle_deg > 0.0 && self.angle_deg <= 360.0) {
            return Err(Error::invalid_argument(format!(
                "angle_deg = {} must be in (0, 360]",
                self.angle_deg
            )));
        }
        if !(self.sharp_angle_deg.is_finite() && (0.0..=180.0).contains(&self.sharp_angle_deg)) {
            return Err(Error::invalid_argument(format!(
                "sharp_angle_deg = {} must be a number of degrees in 0..=180",
                self.sharp_angle_deg
            )));
        }
        check_crease_sharpness(self.crease_sharpness)
    }

    /// Validate and interpolate the profile.
    pub fn profile_curve(&self) -> Result<RevolvedProfile> {
        self.check_settings()?;
        RevolvedProfile::new(
            &self.profile,
            self.interpolation,
            self.sharp_angle_deg.to_radians(),
            &self.corners,
        )
    }

    /// Sample the revolution: rings from bottom to top (poles excluded), each with one data
    /// point per meridian. Errors ([`Error::InvalidArgument`]): bad settings or profile (see
    /// [`RevolvedProfile::new`]), a pole on a partial turn, `samples_around` not a multiple
    /// of 4 with a smooth pole or odd with a tip, too few profile intervals to leave two
    /// rings between two poles.
    pub fn grid(&self, profile: &RevolvedProfile) -> Result<SweepGrid> {
        Ok(self.rings(profile)?.0)
    }

    /// Quad mesh parts of the revolution, each vertex at its data point (the fitter's input):
    /// the grid of [`RevolveInput::grid`] with its poles capped, cap vertices placed on the
    /// surface by [`cap_point`].
    pub fn mesh_parts(&self) -> Result<MeshParts> {
        Ok(self.cage()?.0)
    }

    /// [`RevolveInput::mesh_parts`] and the design surface (the surface of revolution of the
    /// profile curve) on every face's lattice ([`crate::construct::design`]).
    pub fn cage(&self) -> Result<(MeshParts, DesignLattice)> {
        let profile = self.profile_curve()?;
        let (grid, ring_s) = self.rings(&profile)?;
        let design = RevolveDesign {
            profile: &profile,
            ring_s: &ring_s,
            ends: grid.ends,
            step: self.angle_deg.to_radians() / self.samples_around as f64,
            period: self.full_turn().then_some(self.samples_around as f64),
        };
        let (parts, coords) = if self.full_turn() {
            grid_mesh_coords(&grid, &|end, v| design.cap(end, v.radius, TAU * v.turn))?
        } else {
            wedge_parts(self, &profile, &grid, &ring_s)?
        };
        let lattice = parts_lattice(&parts, &coords, &design);
        Ok((parts, lattice))
    }

    /// Check the end kinds against the angle, the caps and `samples_around`.
    fn check_ends(&self, ends: &[GridEnd; 2]) -> Result<()> {
        let na = self.samples_around;
        let capped = self.caps == Caps::Flat;
        if capped && self.full_turn() && !ends.contains(&GridEnd::Open) {
            return Err(Error::invalid_argument(
                "caps = \"flat\" on a full turn of a profile with both ends on the axis: the \
                 surface is already closed, there is nothing to cap",
            ));
        }
        if !self.full_turn() {
            let sectors = capped || ends.iter().any(|e| *e != GridEnd::Open);
            if sectors && na % 4 != 0 {
                return Err(Error::invalid_argument(format!(
                    "samples_around = {na}: a partial revolution with caps or with an end on \
                     the axis closes its ends with sector caps, which need a multiple of 4"
                )));
            }
            return Ok(());
        }
        for (which, e) in ends.iter().enumerate() {
            let name = ["bottom", "top"][which];
            match e {
                GridEnd::Smooth if na % 4 != 0 => {
                    return Err(Error::invalid_argument(format!(
                        "samples_around = {na}: a smooth pole (the {name} end) is closed by a grid \
                         cap, which needs a multiple of 4"
                    )))
                }
                GridEnd::Open if capped && na % 4 != 0 => {
                    return Err(Error::invalid_argument(format!(
                        "samples_around = {na}: the flat cap of the {name} end is a grid cap, \
                         which needs a multiple of 4"
                    )))
                }
                GridEnd::Tip(_) if na % 2 != 0 => {
                    return Err(Error::invalid_argument(format!(
                    "samples_around = {na}: a pointed pole (the {name} end) needs an even number"
                )))
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// The grid and the profile parameter of each ring.
    fn rings(&self, profile: &RevolvedProfile) -> Result<(SweepGrid, Vec<f64>)> {
        let mut ends = [profile.end(0), profile.end(1)];
        self.check_ends(&ends)?;
        let na = self.samples_around;
        let [s0, s1] = profile.range();
        let mut samples = profile
            .curve
            .sample_range("profile", s0, s1, self.samples_profile)?;
        let poles = ends.iter().filter(|e| **e != GridEnd::Open).count();
        // Two poles need two rings: caps or fans closing one ring from both sides would
        // leave vertices of valence 2.
        if samples.len() < 2 * poles {
            return Err(Error::invalid_argument(format!(
                "samples_profile = {}: a profile with two poles needs at least 3 intervals (two rings \
                 between the poles)",
                self.samples_profile
            )));
        }
        place_samples(&mut samples, ends.map(|e| e == GridEnd::Smooth), |s| {
            profile.point(s)
        });
        // Samples each end's cap or tip replaces: one (the pole) for a tip; a smooth pole
        // several, so that its cap's cells are about as large as the faces around it: a full
        // turn's grid cap `grid_cap_depth` (its `k / 2` squares), a partial turn's sector `k`
        // (its radial lines have `k` intervals), either bounded by `cap_depths`.
        let mut depth = ends.map(|e| usize::from(e != GridEnd::Open));
        let breaks: Vec<usize> = (0..samples.len())
            .filter(|&i| i == 0 || i + 1 == samples.len() || samples[i].corner)
            .collect();
        let runs: Vec<usize> = breaks.windows(2).map(|w| w[1] - w[0]).collect();
        let caps = cap_depths(
            ends.map(|e| e == GridEnd::Smooth),
            ends.map(|e| matches!(e, GridEnd::Tip(_))),
            &runs,
            if self.full_turn() {
                grid_cap_depth(na)
            } else {
                na / 4
            },
        );
        for e in 0..2 {
            if ends[e] == GridEnd::Smooth {
                depth[e] = caps[e];
            }
        }
        samples.truncate(samples.len() - depth[1]);
        samples.drain(..depth[0]);
        let (count, closed) = if self.full_turn() {
            (na, true)
        } else {
            (na + 1, false)
        };
        if let Some(c) = samples.iter().find(|c| profile.point(c.s).x < 0.0) {
            return Err(Error::invalid_argument(format!(
                "the spline through the profile crosses the axis (r = {} at z = {}); add \
                 points there or use \"interpolation\": \"polyline\"",
                profile.point(c.s).x,
                profile.point(c.s).y
            )));
        }
        if self.caps == Caps::Flat {
            for e in ends.iter_mut().filter(|e| **e == GridEnd::Open) {
                *e = GridEnd::Flat;
            }
        }
        let step = self.angle_deg.to_radians() / na as f64;
        let rings = samples
            .iter()
            .map(|c| {
                let p = profile.point(c.s);
                (0..count)
                    .map(|m| revolve_point(p, step * m as f64))
                    .collect()
            })
            .collect();
        let grid = SweepGrid {
            rings,
            ring_closed: closed,
            rings_closed: false,
            crease_rings: (0..samples.len()).filter(|&i| samples[i].corner).collect(),
            crease_columns: Vec::new(),
            flip: false,
            ends,
            crease_sharpness: self.crease_sharpness,
        };
        Ok((grid, samples.iter().map(|c| c.s).collect()))
    }
}

/// The surface of revolution in the design coordinates of [`grid_mesh_coords`]: ring index
/// `s` (the profile parameter linear between rings), meridian index `θ` (`θ × step`
/// radians); a smooth pole's cap or a tip's fan at relative radius `ρ` by [`cap_point`], a
/// flat cap the end ring's circle scaled by `ρ`.
struct RevolveDesign<'a> {
    profile: &'a RevolvedProfile,
    ring_s: &'a [f64],
    ends: [GridEnd; 2],
    step: f64,
    /// Meridian intervals of a full turn.
    period: Option<f64>,
}

impl Design for RevolveDesign<'_> {
    fn side(&self, s: f64, theta: f64) -> DVec3 {
        let last = self.ring_s.len() - 1;
        let i = (s.floor().max(0.0) as usize).min(last.saturating_sub(1));
        let f = s - i as f64;
        let t = if last == 0 {
            self.ring_s[0]
        } else {
            self.ring_s[i] + f * (self.ring_s[i + 1] - self.ring_s[i])
        };
        revolve_point(self.profile.point(t), self.angle(theta))
    }

    fn angle(&self, theta: f64) -> f64 {
        theta * self.step
    }

    fn cap(&self, end: usize, rho: f64, theta: f64) -> DVec3 {
        let ring = self.ring_s[if end == 0 { 0 } else { self.ring_s.len() - 1 }];
        if self.ends[end] == GridEnd::Flat {
            let p = self.profile.point(ring);
            return revolve_point(DVec2::new(rho * p.x, p.y), theta);
        }
        let pole = self.profile.range()[end];
        cap_point(self.profile, ring, pole, rho, theta / TAU)
    }

    fn periods(&self) -> [Option<f64>; 2] {
        [None, self.period]
    }
}

/// Data point of a smooth-pole cap vertex at relative radius `radius` (1 at the last ring,
/// 0 at the pole) and `turn` (fraction of a full turn): the profile parameter is interpolated
/// linearly between the pole and the ring, then turned.
pub fn cap_point(
    profile: &RevolvedProfile,
    ring_s: f64,
    pole_s: f64,
    radius: f64,
    turn: f64,
) -> DVec3 {
    revolve_point(
        profile.point(pole_s + radius * (ring_s - pole_s)),
        TAU * turn,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn semicircle(n: usize, r: f64) -> Vec<[f64; 2]> {
        (0..=n)
            .map(|i| {
                let t = -PI / 2.0 + PI * i as f64 / n as f64;
                [
                    if i == 0 || i == n {
                        0.0
                    } else {
                        r * math::cos(t)
                    },
                    r * math::sin(t),
                ]
            })
            .collect()
    }

    #[test]
    fn semicircle_gives_a_sphere_with_two_smooth_poles() {
        let input = RevolveInput::new(semicircle(12, 1.5));
        let prof = input.profile_curve().unwrap();
        assert_eq!(prof.end(0), GridEnd::Smooth);
        assert_eq!(prof.end(1), GridEnd::Smooth);
        // The mirrored spline meets the axis at a right angle.
        let d = prof.curve.eval(prof.range()[0], false).d1;
        assert!(d.y.abs() < 1e-12 * d.length(), "{d}");
        let g = input.grid(&prof).unwrap();
        // 17 samples; each pole's grid cap (k = 8: depth 2) replaces the pole and 1 ring.
        assert_eq!(g.rings.len(), 13);
        assert!(g.rings.iter().all(|r| r.len() == 32));
        let worst = g
            .rings
            .iter()
            .flatten()
            .map(|p| (p.length() - 1.5).abs())
            .fold(0.0, f64::max);
        assert!(worst < 1e-4, "{worst}");
        assert!(g.crease_rings.is_empty());
    }

    #[test]
    fn segments_give_cylinder_and_cone_with_a_tip() {
        let input = RevolveInput::new(vec![[1.0, 0.0], [1.0, 2.0]]);
        let prof = input.profile_curve().unwrap();
        assert_eq!([prof.end(0), prof.end(1)], [GridEnd::Open, GridEnd::Open]);
        let g = input.grid(&prof).unwrap();
        assert_eq!(g.rings.len(), 17);
        // Meridian 8 of 32 is a quarter turn.
        assert!((g.rings[8][8] - DVec3::new(0.0, 1.0, 1.0)).length() < 1e-15);
        let cone = RevolveInput::new(vec![[1.0, 0.0], [0.0, 2.0]]);
        let prof = cone.profile_curve().unwrap();
        assert_eq!(prof.end(1), GridEnd::Tip(DVec3::new(0.0, 0.0, 2.0)));
        let g = cone.grid(&prof).unwrap();
        assert_eq!(g.rings.len(), 16);
        let p = g.rings[4][0];
        assert!(
            (p.x - 0.75).abs() < 1e-14 && (p.z - 0.5).abs() < 1e-14,
            "{p}"
        );
    }

    #[test]
    fn partial_turn_is_open_and_corners_crease_rings() {
        let mut input = RevolveInput::new(vec![[1.0, 0.0], [1.0, 1.0], [0.5, 1.5]]);
        input.angle_deg = 90.0;
        input.samples_around = 4;
        let g = input.grid(&input.profile_curve().unwrap()).unwrap();
        assert!(!g.ring_closed);
        assert_eq!(g.rings[0].len(), 5);
        let k = g.crease_rings[0];
        assert_eq!(g.crease_rings.len(), 1);
        assert_eq!(g.rings[k][0], DVec3::new(1.0, 0.0, 1.0));
        assert!((g.rings[k][4] - DVec3::new(0.0, 1.0, 1.0)).length() < 1e-15);
    }

    #[test]
    fn forced_corners_crease_a_ring_and_sharpen_a_pole() {
        let mut input = RevolveInput::new(semicircle(12, 1.0));
        input.corners = vec![6, 12];
        let prof = input.profile_curve().unwrap();
        assert_eq!(prof.end(0), GridEnd::Smooth);
        assert_eq!(prof.end(1), GridEnd::Tip(DVec3::new(0.0, 0.0, 1.0)));
        // The equator ring is creased, and the spline is still symmetric about the axis.
        let g = input.grid(&prof).unwrap();
        assert_eq!(g.crease_rings.len(), 1);
        let equator = &g.rings[g.crease_rings[0]];
        assert!(equator
            .iter()
            .all(|p| p.z.abs() < 1e-15 && (p.length() - 1.0).abs() < 1e-15));
        let d = prof.curve.eval(prof.range()[0], false).d1;
        assert!(d.y.abs() < 1e-12 * d.length(), "{d}");
        input.corners = vec![13];
        assert!(input.profile_curve().is_err());
        let mut open = RevolveInput::new(vec![[1.0, 0.0], [1.0, 1.0], [0.5, 2.0]]);
        open.corners = vec![0];
        let e = open.profile_curve().unwrap_err();
        assert!(matches!(e, Error::InvalidArgument(m) if m.contains("corner 0")));
    }

    #[test]
    fn bad_revolutions_are_refused() {
        let msg = |f: &dyn Fn(&mut RevolveInput)| {
            let mut i = RevolveInput::new(semicircle(8, 1.0));
            f(&mut i);
            match i.profile_curve().and_then(|p| i.grid(&p)) {
                Err(Error::InvalidArgument(m)) => m,
                other => panic!("expected an error, got {other:?}"),
            }
        };
        assert!(msg(&|i| i.profile[3][0] = -0.1).contains("crosses the axis"));
        assert!(msg(&|i| i.profile[3][0] = 0.0).contains("on the axis; only"));
        assert!(msg(&|i| i.samples_around = 30).contains("multiple of 4"));
        assert!(msg(&|i| (i.angle_deg, i.samples_around) = (180.0, 30)).contains("sector caps"));
        assert!(msg(&|i| i.caps = Caps::Flat).contains("nothing to cap"));
        assert!(msg(&|i| i.angle_deg = 0.0).contains("(0, 360]"));
        assert!(msg(&|i| i.profile = vec![[1.0, 0.0]]).contains("at least 2"));
        assert!(msg(&|i| i.profile = vec![[1.0, 0.0], [1.0, f64::NAN]]).contains("not finite"));
        assert!(
            msg(&|i| i.profile = vec![[1.0, 0.0], [2.0, 1.0], [2.0, 0.0], [1.0, 1.0]])
                .contains("crosses itself")
        );
        assert!(msg(&|i| i.samples_profile = 2).contains("at least 3 intervals"));
        let e = RevolveInput::from_json(
            r#"{"profile": [[1,0],[1,1]], "angle": 90}"#,
            Path::new("r.json"),
        )
        .unwrap_err();
        assert!(
            matches!(e, Error::Parse { message, .. } if message.contains("unknown field `angle`"))
        );
    }
}
