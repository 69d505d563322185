//! The validated profile of a revolution, the point turned about the axis, and the data
//! points of pole caps.

use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::construct::grid_mesh::GridEnd;
use crate::construct::sweep::profile::check_no_crossing;
use crate::curves::corners::detect_chord_corners;
use crate::curves::{Interpolation, SpaceCurve};
use crate::error::{Error, Result};

/// The validated profile of a revolution, mirrored across the axis at its poles.
#[derive(Debug, Clone, PartialEq)]
pub struct RevolvedProfile {
    pub(crate) curve: SpaceCurve,
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
    DVec3::new(
        p.x * crate::math::cos(theta),
        p.x * crate::math::sin(theta),
        p.y,
    )
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

/// Slope of [`sector_point`]'s radial grading at the apex: the samples a sector replaces are
/// graded towards the pole (spacing halved there, for a full turn's grid cap), but a
/// partial turn's apex is an infinitely sharp corner whose first steps may be longer. With
/// slope 1.8 the capped and open sphere and spheroid wedges of aspect 0.3, 0.375 and 3 are
/// within 1e-3 of their diagonal at 32 × 16 at 90°, 180° and 270° (measured: 1.5 left the
/// oblate 90° wedge at 1.04e-3, 1.0 (no grading) 1.3e-3; 2.0 the prolate 270° at 1.1e-3).
const APEX_SLOPE: f64 = 1.8;

/// Data point of a partial turn's pole-sector vertex at relative radius `rho` (0 at the pole,
/// 1 on the ring) and angle `theta` (radians). The profile parameter follows the samples the
/// sector's radial lines replace (`params`, pole first, at least two), piecewise linearly
/// in `rho` graded by `rho + (APEX_SLOPE − 1) rho (1 − rho)²` (increasing, slope 1 at the
/// ring): the radial steps continue the side's ring spacing, which is equidistributed in
/// curvature. Spreading them evenly in the curve parameter instead put the sector's
/// valence-3 quarter points where the profile bends most (an oblate spheroid's equator)
/// with steps longer than the side's there, and the partial turns of ellipsoids were
/// 1.7e-3 to 4.3e-3 of their diagonal from the design at 32 × 16.
pub fn sector_point(profile: &RevolvedProfile, params: &[f64], rho: f64, theta: f64) -> DVec3 {
    let steps = (params.len() - 1) as f64;
    let graded = rho + (APEX_SLOPE - 1.0) * rho * (1.0 - rho) * (1.0 - rho);
    let t = (graded * steps).clamp(0.0, steps);
    let i = (t.floor() as usize).min(params.len() - 2);
    let f = t - i as f64;
    revolve_point(
        profile.point(params[i] + f * (params[i + 1] - params[i])),
        theta,
    )
}
