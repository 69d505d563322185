//! The four silhouettes as curves, their corners, and what happens at each end.
//!
//! Curves keep their input coordinates `(w, z)`: `w` is x for `c1`, `c3` and y for `c2`,
//! `c4`. An end where both widths `c1 − c3` and `c2 − c4` vanish (within 1e-9 of the model
//! size) is a *pole*; it is *pointed* when a corner is forced there or when some curve meets
//! the axis at more than half the sharp angle from the perpendicular (so the curve and its
//! mirror image turn by more than the sharp angle), and *smooth* otherwise. At a smooth pole
//! each spline is clamped perpendicular to the axis, so the surface has a tangent plane
//! there.

use crate::math;
use glam::{DVec2, DVec3};

use super::input::ProfileInput;
use crate::construct::settings::{Caps, Settings};
use crate::curves::corners::{detect_corners, one_sided_tangent_within};
use crate::curves::{EndCondition, Interpolation, PlanarCurve};
use crate::error::{Error, Result};

/// Names of the curves in messages.
pub const NAMES: [&str; 4] = ["c1", "c2", "c3", "c4"];

/// How one end of the surface is closed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EndKind {
    /// Open boundary ring.
    Open,
    /// Flat grid cap, creased along its border.
    Flat,
    /// Pole where the curves meet the axis at an angle: one vertex, an infinitely sharp corner.
    Tip,
    /// Pole where the curves meet the axis perpendicularly: closed by a grid cap of quads.
    Smooth,
}

/// One silhouette, ready to sample.
#[derive(Debug, Clone)]
pub struct Silhouette {
    /// The curve through the points.
    pub curve: PlanarCurve,
    /// Interior point indices that are corners (creases).
    pub sharp: Vec<usize>,
    /// Interior point indices that get a ring: the corners, or every point of a polyline.
    pub breaks: Vec<usize>,
}

/// The four silhouettes and the kinds of the bottom and top ends.
#[derive(Debug, Clone)]
pub struct Silhouettes {
    /// `c1 … c4`.
    pub curves: [Silhouette; 4],
    /// Bottom and top.
    pub ends: [EndKind; 2],
    /// Bounding-box diagonal of all input points.
    pub size: f64,
}

fn to_points(name: &str, pts: &[[f64; 2]]) -> Result<Vec<DVec2>> {
    if pts.len() < 2 {
        return Err(Error::invalid_argument(format!(
            "{name} needs at least 2 points, got {}",
            pts.len()
        )));
    }
    if let Some((i, p)) = pts
        .iter()
        .enumerate()
        .find(|(_, p)| !p[0].is_finite() || !p[1].is_finite())
    {
        return Err(Error::invalid_argument(format!(
            "{name} point {i} ({}, {}) is not a finite number",
            p[0], p[1]
        )));
    }
    Ok(pts.iter().map(|p| DVec2::new(p[0], p[1])).collect())
}

fn mirrored(pts: &[DVec2]) -> Vec<DVec2> {
    pts.iter().map(|p| DVec2::new(-p.x, p.y)).collect()
}

impl Silhouettes {
    /// Check and build the curves of `input` (settings are assumed checked).
    pub fn new(input: &ProfileInput, settings: &Settings) -> Result<Silhouettes> {
        let c1 = to_points("c1", &input.c1)?;
        let c2 = to_points("c2", &input.c2)?;
        let c3 = match &input.c3 {
            Some(c) => to_points("c3", c)?,
            None => mirrored(&c1),
        };
        let c4 = match &input.c4 {
            Some(c) => to_points("c4", c)?,
            None => mirrored(&c2),
        };
        let pts = [c1, c2, c3, c4];
        if input.c3.is_none() {
            wrong_side("c1", &pts[0])?;
        }
        if input.c4.is_none() {
            wrong_side("c2", &pts[1])?;
        }
        let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
        for p in pts.iter().flatten() {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        // Diagonal of the 3-D box: x from c1/c3, y from c2/c4, z from all.
        let size = (hi - lo).length().max(f64::MIN_POSITIVE);
        for (i, p) in pts.iter().enumerate() {
            let (z0, z1) = (p[0].y, p[p.len() - 1].y);
            if z1.partial_cmp(&z0) != Some(std::cmp::Ordering::Greater) {
                return Err(Error::invalid_argument(format!(
                    "{} runs from z = {z0} to z = {z1}; every curve must run from bottom to top \
                     (curves of opposite direction or a flat curve cannot be blended)",
                    NAMES[i]
                )));
            }
        }
        let forced = [
            &input.corners.c1,
            &input.corners.c2,
            &input.corners.c3,
            &input.corners.c4,
        ];
        for (i, f) in forced.iter().enumerate() {
            if let Some(&k) = f.iter().find(|&&k| k >= pts[i].len()) {
                return Err(Error::invalid_argument(format!(
                    "corners: {} has no point {k} (it has {} points)",
                    NAMES[i],
                    pts[i].len()
                )));
            }
            if i >= 2 && !f.is_empty() && [&input.c3, &input.c4][i - 2].is_none() {
                return Err(Error::invalid_argument(format!(
                    "corners: {} is the mirror of {}; give its corners on {}",
                    NAMES[i],
                    NAMES[i - 2],
                    NAMES[i - 2]
                )));
            }
        }
        // Mirrored curves share the corners of their originals.
        let forced_of = |i: usize| -> &Vec<usize> {
            match (i, &input.c3, &input.c4) {
                (2, None, _) => forced[0],
                (3, _, None) => forced[1],
                _ => forced[i],
            }
        };
        let tol = 1e-9 * size;
        let sharp_angle = settings.sharp_angle_deg.to_radians();
        let mut ends = [EndKind::Open; 2];
        for (e, end) in ends.iter_mut().enumerate() {
            let at = |i: usize| {
                if e == 0 {
                    pts[i][0]
                } else {
                    pts[i][pts[i].len() - 1]
                }
            };
            let wx = at(0).x - at(2).x;
            let wy = at(1).x - at(3).x;
            let which = ["bottom", "top"][e];
            if wx < -tol || wy < -tol {
                return Err(Error::invalid_argument(format!(
                    "at the {which} the curves cross the axis (c1 − c3 = {wx}, c2 − c4 = {wy}); \
                     c1/c2 must stay on the + side of c3/c4"
                )));
            }
            *end = match (wx <= tol, wy <= tol) {
                (true, true) => {
                    let z: Vec<f64> = (0..4).map(|i| at(i).y).collect();
                    if z.iter().any(|&zi| (zi - z[0]).abs() > tol) {
                        return Err(Error::invalid_argument(format!(
                            "the curves meet the axis at the {which} at different heights \
                             (z = {} {} {} {}); they must meet at one pole",
                            z[0], z[1], z[2], z[3]
                        )));
                    }
                    let index = |i: usize| if e == 0 { 0 } else { pts[i].len() - 1 };
                    let pointed = (0..4).any(|i| {
                        let near = detect_corners(&pts[i], sharp_angle);
                        let t = one_sided_tangent_within(&pts[i], index(i), e == 0, &near);
                        forced_of(i).contains(&index(i))
                            || 2.0 * math::asin(t.y.abs().clamp(0.0, 1.0)) > sharp_angle
                    });
                    if pointed {
                        EndKind::Tip
                    } else {
                        EndKind::Smooth
                    }
                }
                (false, false) => match settings.caps {
                    Caps::Open => EndKind::Open,
                    Caps::Flat => EndKind::Flat,
                },
                _ => {
                    return Err(Error::invalid_argument(format!(
                        "at the {which} only one pair of curves meets the axis (c1 − c3 = {wx}, \
                         c2 − c4 = {wy}): the end would be a slit; make both widths zero or both \
                         positive"
                    )))
                }
            };
            if !matches!(end, EndKind::Tip | EndKind::Smooth) {
                for i in 0..4 {
                    let k = if e == 0 { 0 } else { pts[i].len() - 1 };
                    if forced_of(i).contains(&k) {
                        return Err(Error::invalid_argument(format!(
                            "corners: {} point {k} is an open end, not a pole; only interior \
                             points and poles can be corners",
                            NAMES[i]
                        )));
                    }
                }
            }
        }
        let build = |i: usize| -> Result<Silhouette> {
            let p = &pts[i];
            let n = p.len();
            let mut sharp: Vec<usize> = detect_corners(p, sharp_angle);
            sharp.extend(forced_of(i).iter().filter(|&&k| k > 0 && k + 1 < n));
            sharp.sort_unstable();
            sharp.dedup();
            // Outward along w: + for c1, c2, − for c3, c4.
            let out = if i < 2 { 1.0 } else { -1.0 };
            let cond = |e: usize| match ends[e] {
                EndKind::Smooth => {
                    EndCondition::Tangent(DVec3::new(if e == 0 { out } else { -out }, 0.0, 0.0))
                }
                _ => EndCondition::Natural,
            };
            let curve = PlanarCurve::new(p, settings.interpolation, &sharp, [cond(0), cond(1)])
                .map_err(|e| match e {
                    Error::InvalidArgument(m) => {
                        Error::invalid_argument(format!("{}: {m}", NAMES[i]))
                    }
                    other => other,
                })?;
            let breaks = match settings.interpolation {
                Interpolation::Spline => sharp.clone(),
                Interpolation::Polyline => (1..n - 1).collect(),
            };
            Ok(Silhouette {
                curve,
                sharp,
                breaks,
            })
        };
        Ok(Silhouettes {
            curves: [build(0)?, build(1)?, build(2)?, build(3)?],
            ends,
            size,
        })
    }
}

fn wrong_side(name: &str, pts: &[DVec2]) -> Result<()> {
    match pts.iter().enumerate().find(|(_, p)| p.x < 0.0) {
        Some((i, p)) => Err(Error::invalid_argument(format!(
            "{name} point {i} ({}, {}) crosses the axis: with its mirror image as the opposite \
             silhouette, {name} must have coordinates >= 0",
            p.x, p.y
        ))),
        None => Ok(()),
    }
}
