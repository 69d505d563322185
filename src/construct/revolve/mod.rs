//! Surfaces of revolution: a profile `(r, z)` turned about the z axis.
//!
//! ```json
//! { "profile": [[r,z],...], "angle_deg": 360, "samples_profile": 16, "samples_around": 32,
//!   "interpolation": "spline", "sharp_angle_deg": 30, "corners": [3],
//!   "crease_sharpness": "infinite", "boundary": "edge-and-corner", "crease_method": "uniform",
//!   "caps": "open" }
//! ```
//! Only `profile` is required (points from bottom to top, `r ≥ 0`); an unknown key is an
//! error. `interpolation`, `sharp_angle_deg`, `crease_sharpness`, `boundary`, `crease_method`
//! and `caps` are the shared [`Settings`]; the rest is [`RevolveInput`] ([`input`], the
//! profile curve in [`profile`], [`build`] here). Defaults: `angle_deg` = 360 (a full turn, closed; less than 360 leaves boundary
//! edges along the first and last meridians), `samples_profile` = 16 sample intervals from
//! bottom to top, `samples_around` = 32 meridian intervals, `interpolation` = `"spline"`,
//! `sharp_angle_deg` = 30, `corners` = none (profile point indices forced to be corners),
//! `crease_sharpness` = `"infinite"` (or a number ≥ 0, as in the profile construction; tips
//! stay infinitely sharp corners), `boundary` = `"edge-and-corner"` (`"edge-only"`, `"none"`)
//! and `crease_method` = `"uniform"` (`"chaikin"`): the options the mesh is fitted under and
//! tagged with; `caps` = `"open"`. With `"caps": "flat"` the solid is closed by flat caps, creased where
//! they meet the side or each other: ends off the axis get a flat disc (full turn) or sector
//! (partial turn), and a partial turn's start and end meridian planes get flat caps between
//! the profile and the axis (layouts: [`wedge`]). Caps on a full turn whose ends are
//! both on the axis are refused (nothing to close).
//!
//! *Poles*: a profile end on the axis (`r = 0`) closes the surface there. The profile is
//! extended by its mirror image across the axis before it is interpolated, so the spline is
//! symmetric and meets the axis at a right angle unless the mirrored curve has a corner there:
//! a profile end whose chord turns (with its mirror) by more than `sharp_angle_deg`, i.e. meets
//! the axis at more than half that angle from the perpendicular, is a *pointed pole* (a tip
//! vertex tagged as an infinitely sharp corner, like a cone's apex); otherwise it is a *smooth
//! pole*, closed by a grid cap of quads (valence 3 and 4 only, see
//! `crate::construct::pole_cap`). On a full turn `samples_around` must be a multiple of 4
//! for a smooth pole or a flat cap and even for a tip. On a partial turn a pole lies on both
//! boundary meridians; it is closed by a sector of quads whose apex is tagged as an
//! infinitely sharp corner ([`wedge`]; `samples_around` a multiple of 4). Profile
//! corners give crease rings.

pub mod input;
pub mod profile;
pub mod wedge;

use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::construct::design::{parts_lattice, Design, DesignLattice};
use crate::construct::equidistribute::place_samples;
use crate::construct::fitted::Fitted;
use crate::construct::grid_mesh::{grid_mesh_coords, GridEnd, SweepGrid};
use crate::construct::pole_cap::{cap_depths, grid_cap_depth};
use crate::construct::settings::{Caps, Settings};
use crate::curves::CurveSample;
use crate::error::{Error, Result};
use crate::fit::Role;
use crate::mesh::MeshParts;
pub use input::RevolveInput;
pub use profile::{cap_point, revolve_point, sector_point, RevolvedProfile};
use wedge::{wedge_parts, CapLayout};

/// What [`RevolveInput::rings`] lays out along the profile.
struct Rings {
    /// The rings of data points (poles excluded).
    grid: SweepGrid,
    /// The profile parameter of each ring.
    ring_s: Vec<f64>,
    /// Each end's pole-sector radial samples, from the pole outwards (empty: none, or a
    /// full turn).
    radial: [Vec<f64>; 2],
    /// Whether the pole sectors' runs were widened ([`widen_pole_runs`]).
    widened: bool,
}

impl RevolveInput {
    /// Validate and interpolate the profile.
    pub fn profile_curve(&self, settings: &Settings) -> Result<RevolvedProfile> {
        self.check_settings(settings)?;
        RevolvedProfile::new(
            &self.profile,
            settings.interpolation,
            settings.sharp_angle_deg.to_radians(),
            &self.corners,
        )
    }

    /// Sample the revolution: rings from bottom to top (poles excluded), each with one data
    /// point per meridian. Errors ([`Error::InvalidArgument`]): bad settings or profile (see
    /// [`RevolvedProfile::new`]), a pole on a partial turn, `samples_around` not a multiple
    /// of 4 with a smooth pole or odd with a tip, too few profile intervals to leave two
    /// rings between two poles.
    pub fn grid(&self, settings: &Settings, profile: &RevolvedProfile) -> Result<SweepGrid> {
        Ok(self.rings(settings, profile, None)?.grid)
    }

    /// Quad mesh parts of the revolution, each vertex at its data point (the fitter's input):
    /// the grid of [`RevolveInput::grid`] with its poles capped, cap vertices placed on the
    /// surface by [`cap_point`].
    pub fn mesh_parts(&self, settings: &Settings) -> Result<MeshParts> {
        Ok(self.cage(settings)?.0)
    }

    /// [`RevolveInput::mesh_parts`] and the design surface (the surface of revolution of the
    /// profile curve) on every face's lattice ([`crate::construct::design`]).
    pub fn cage(&self, settings: &Settings) -> Result<(MeshParts, DesignLattice)> {
        let (parts, lattice, _) = self.layout(settings, None, false)?.0;
        Ok((parts, lattice))
    }

    /// [`RevolveInput::cage`], and which vertices are free of data (the flat meridian caps'
    /// inside and axis, [`wedge`]): the fit keeps them as control points. `pole_room`: a
    /// partial turn's pole sectors get room ([`widen_pole_runs`]); the `bool`: whether that
    /// changed the rings. `rungs`: the meridian caps are laid out as [`CapLayout::Rungs`]
    /// (else Coons grids, then Winslow-relaxed ones).
    #[allow(clippy::type_complexity)]
    fn layout(
        &self,
        settings: &Settings,
        pole_room: Option<usize>,
        rungs: bool,
    ) -> Result<((MeshParts, DesignLattice, Vec<Role>), bool)> {
        let profile = self.profile_curve(settings)?;
        let rings = self.rings(settings, &profile, pole_room)?;
        let (grid, ring_s, radial) = (&rings.grid, &rings.ring_s, &rings.radial);
        // The meridian caps' layout depends on the sectors' radial lines: where it folds
        // with the side's spacing, the sectors spread evenly in the curve parameter; only
        // where both fold, the caps' grids are smoothed, in the same order.
        let even = Default::default();
        let spreads = if radial.iter().any(|r| !r.is_empty()) {
            vec![radial, &even]
        } else {
            vec![radial]
        };
        let mut first_error = None;
        let caps: &[CapLayout] = if rungs {
            &[CapLayout::Rungs]
        } else {
            &[CapLayout::Coons, CapLayout::Winslow]
        };
        for &cap in caps {
            for &spread in &spreads {
                match self.layout_with(settings, &profile, grid, ring_s, spread, cap) {
                    Ok(layout) => return Ok((layout, rings.widened)),
                    Err(e @ Error::InvalidArgument(_)) => {
                        first_error.get_or_insert(e);
                    }
                    Err(e) => return Err(e),
                }
            }
        }
        Err(first_error.expect("at least one layout is tried"))
    }

    /// [`RevolveInput::layout`] with the pole sectors' radial samples `radial` (empty: evenly
    /// in the curve parameter, [`cap_point`]; a full turn has none) and the meridian caps'
    /// `layout` ([`wedge_parts`]).
    fn layout_with(
        &self,
        settings: &Settings,
        profile: &RevolvedProfile,
        grid: &SweepGrid,
        ring_s: &[f64],
        radial: &[Vec<f64>; 2],
        cap: CapLayout,
    ) -> Result<(MeshParts, DesignLattice, Vec<Role>)> {
        let design = RevolveDesign {
            profile,
            ring_s,
            radial,
            ends: grid.ends,
            step: self.angle_deg.to_radians() / self.samples_around as f64,
            period: self.full_turn().then_some(self.samples_around as f64),
        };
        let (parts, coords, roles) = if self.full_turn() {
            let (parts, coords) =
                grid_mesh_coords(grid, &|end, v| design.cap(end, v.radius, TAU * v.turn))?;
            (parts, coords, Vec::new())
        } else {
            wedge_parts(self, settings, profile, grid, ring_s, radial, cap)?
        };
        let lattice = parts_lattice(&parts, &coords, &design, &settings.control)?;
        Ok((parts, lattice, roles))
    }

    /// Check the end kinds against the angle, the caps and `samples_around`.
    fn check_ends(&self, caps: Caps, ends: &[GridEnd; 2]) -> Result<()> {
        let na = self.samples_around;
        let capped = caps == Caps::Flat;
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

    /// The grid, the profile parameter of each ring and the pole sectors' radial samples;
    /// `pole_room`: on a partial turn, the runs of pole sectors widened by
    /// [`widen_pole_runs`].
    fn rings(
        &self,
        settings: &Settings,
        profile: &RevolvedProfile,
        pole_room: Option<usize>,
    ) -> Result<Rings> {
        let mut ends = [profile.end(0), profile.end(1)];
        self.check_ends(settings.caps, &ends)?;
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
        let sector = |e: GridEnd| !self.full_turn() && matches!(e, GridEnd::Tip(_));
        let mut widened = false;
        if let (Some(want), false) = (pole_room, self.full_turn()) {
            let poles = ends.map(|e| e != GridEnd::Open);
            if let Some(wide) = widen_pole_runs(&samples, poles, want) {
                (samples, widened) = (wide, true);
            }
        }
        place_samples(&mut samples, ends.map(|e| e == GridEnd::Smooth), |s| {
            profile.point(s)
        });
        // Samples each end's cap or tip replaces: one (the pole) for a full turn's tip; a
        // smooth pole (and a partial turn's tip, also closed by a sector) several, so that
        // its cap's cells are about as large as the faces around it: a full turn's grid cap
        // `grid_cap_depth` (its `k / 2` squares), a partial turn's sector `k` (its radial
        // lines have `k` intervals), either bounded by `cap_depths`.
        let mut depth = ends.map(|e| usize::from(e != GridEnd::Open));
        let breaks: Vec<usize> = (0..samples.len())
            .filter(|&i| i == 0 || i + 1 == samples.len() || samples[i].corner)
            .collect();
        let runs: Vec<usize> = breaks.windows(2).map(|w| w[1] - w[0]).collect();
        let caps = cap_depths(
            ends.map(|e| e == GridEnd::Smooth || sector(e)),
            ends.map(|e| matches!(e, GridEnd::Tip(_)) && !sector(e)),
            &runs,
            if self.full_turn() {
                grid_cap_depth(na)
            } else {
                na / 4
            },
        );
        for e in 0..2 {
            if ends[e] == GridEnd::Smooth || sector(ends[e]) {
                depth[e] = caps[e];
            }
        }
        let last = samples.len() - 1;
        let radial = [0, 1].map(|e| {
            if self.full_turn() || !(ends[e] == GridEnd::Smooth || sector(ends[e])) {
                return Vec::new();
            }
            let span = if e == 0 {
                0..=depth[0]
            } else {
                last - depth[1]..=last
            };
            let mut s: Vec<f64> = samples[span].iter().map(|c| c.s).collect();
            if e == 1 {
                s.reverse();
            }
            s
        });
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
        if settings.caps == Caps::Flat {
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
            crease_sharpness: settings.crease_sharpness,
        };
        Ok(Rings {
            grid,
            ring_s: samples.iter().map(|c| c.s).collect(),
            radial,
            widened,
        })
    }
}

/// The samples with the runs (between breakpoints) at a pole (`poles`) given at least
/// `want` intervals each, taken one at a time from the other run whose intervals are
/// shortest in parameter (keeping one each), each run sampled uniformly in parameter as
/// [`crate::curves::SpaceCurve::sample_range`] does; `None` if no run changes. A partial
/// turn's pole sector has `k` radial intervals whatever the profile intervals it replaces;
/// when its run has only one or two (a goblet's nearly flat lid at 16 x 8), the sector's
/// `k` small cells meet one long profile interval, and the fit folded there even faired.
/// With `k + 1` intervals the sector replaces `k` of them, and its cells are about as long
/// as the side's next to it, as on the flat-based bottle that works.
fn widen_pole_runs(
    samples: &[CurveSample],
    poles: [bool; 2],
    want: usize,
) -> Option<Vec<CurveSample>> {
    let n = samples.len();
    let breaks: Vec<usize> = (0..n)
        .filter(|&i| i == 0 || i + 1 == n || samples[i].corner)
        .collect();
    let mut count: Vec<usize> = breaks.windows(2).map(|w| w[1] - w[0]).collect();
    let runs = count.len();
    if runs < 2 {
        return None;
    }
    let length: Vec<f64> = breaks
        .windows(2)
        .map(|w| samples[w[1]].s - samples[w[0]].s)
        .collect();
    let pole_runs: Vec<usize> = [(0, poles[0]), (runs - 1, poles[1])]
        .into_iter()
        .filter_map(|(r, p)| p.then_some(r))
        .collect();
    let before = count.clone();
    for &run in &pole_runs {
        while count[run] < want {
            let donor = (0..runs)
                .filter(|d| !pole_runs.contains(d) && count[*d] > 1)
                .min_by(|&a, &b| {
                    (length[a] / count[a] as f64).total_cmp(&(length[b] / count[b] as f64))
                });
            let Some(d) = donor else { break };
            count[d] -= 1;
            count[run] += 1;
        }
    }
    if count == before {
        return None;
    }
    let mut out = Vec::with_capacity(n);
    for (r, w) in breaks.windows(2).enumerate() {
        let (s0, s1) = (samples[w[0]].s, samples[w[1]].s);
        out.extend((0..count[r]).map(|j| CurveSample {
            s: s0 + (s1 - s0) * j as f64 / count[r] as f64,
            corner: j == 0 && samples[w[0]].corner,
        }));
    }
    out.push(samples[n - 1]);
    Some(out)
}

/// The surface of revolution in the design coordinates of [`grid_mesh_coords`]: ring index
/// `s` (the profile parameter linear between rings), meridian index `θ` (`θ × step`
/// radians); a smooth pole's cap or a tip's fan at relative radius `ρ` by [`cap_point`], a
/// flat cap the end ring's circle scaled by `ρ`.
struct RevolveDesign<'a> {
    profile: &'a RevolvedProfile,
    ring_s: &'a [f64],
    /// A partial turn's sector ends: the profile parameters of the samples its radial lines
    /// replace, pole first ([`sector_point`]); empty otherwise.
    radial: &'a [Vec<f64>; 2],
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
        if !self.radial[end].is_empty() {
            return sector_point(self.profile, &self.radial[end], rho, theta);
        }
        let pole = self.profile.range()[end];
        cap_point(self.profile, ring, pole, rho, theta / TAU)
    }

    fn periods(&self) -> [Option<f64>; 2] {
        [None, self.period]
    }
}

/// The surface of revolution of `input` under `settings`, fitted: the exact limit surface
/// passes through every data point. Errors: those of [`RevolveInput::cage`]
/// ([`Error::InvalidArgument`] for bad input or settings) and of the fit; and, for a partial
/// turn, [`Error::InvalidArgument`] if its limit surface folds (the wedge layouts are not
/// fold-free for every profile and sampling, [`wedge`]; checked by the fold check). A
/// partial turn whose interpolating fit folds is fitted once more with its pole sectors'
/// inner vertices faired instead of interpolated (those points are then not interpolated:
/// `targets` holds their limit positions); if that folds too, or the first layout has no
/// unfolded meridian cap, the same two fits are tried on the rings with the pole sectors'
/// runs widened to `k / 2 + 1`, then `k + 1` profile intervals (`n = 4k` meridian
/// intervals; `widen_pole_runs`), and the turn is refused only if every one folds. With
/// flat caps, each ring placement whose fits fold is tried once more with the meridian caps
/// laid out as rungs ([`wedge::CapLayout::Rungs`], whose limit is ruled and cannot fold
/// between the end rows) before the next placement. Turns whose first layout fits without
/// folding are unchanged.
pub fn build(input: &RevolveInput, settings: &Settings) -> Result<Fitted> {
    if input.full_turn() {
        let ((parts, design, roles), _) = input.layout(settings, None, false)?;
        return Fitted::fit_free(parts, settings, design, &roles);
    }
    // The rings as sampled first; only where that layout or its fit folds, the pole
    // sectors' runs widened to `k / 2 + 1` intervals (the sector's `k` radial intervals
    // over about 2 profile intervals, the ratio of a full turn's grid cap), then to `k + 1`
    // ([`widen_pole_runs`]).
    let k = input.samples_around / 4;
    let rungs: &[bool] = if settings.caps == Caps::Flat {
        &[false, true]
    } else {
        &[false]
    };
    let mut outcome = None;
    for (room, rungs) in [None, Some(k / 2 + 1), Some(k + 1)]
        .into_iter()
        .flat_map(|room| rungs.iter().map(move |&r| (room, r)))
    {
        let layout = match input.layout(settings, room, rungs) {
            Ok((_, false)) if room.is_some() => continue,
            Ok((layout, _)) => layout,
            Err(e @ Error::InvalidArgument(_)) => {
                outcome.get_or_insert(Err(e));
                continue;
            }
            Err(e) => return Err(e),
        };
        let (parts, design, roles) = layout;
        let fitted = fit_partial(parts, design, &roles, settings)?;
        let folded = fitted.surface_report_with(&settings.control)?.folded_faces > 0;
        if !folded || !matches!(outcome, Some(Ok(_))) {
            outcome = Some(Ok(fitted));
        }
        if !folded {
            break;
        }
    }
    outcome
        .expect("the first layout is always tried")?
        .refuse_folds(
            &format!(
                "partial revolution ({}°, {} x {} samples)",
                input.angle_deg, input.samples_around, input.samples_profile
            ),
            "other sample counts give other layouts",
            &settings.control,
        )
}

/// A partial turn's fit: every data point interpolated first; only where that folds are the
/// pole sectors' inner data points released and their control points faired ([`wedge`]).
fn fit_partial(
    parts: MeshParts,
    design: DesignLattice,
    roles: &[Role],
    settings: &Settings,
) -> Result<Fitted> {
    let interpolating: Vec<Role> = roles
        .iter()
        .map(|&r| match r {
            Role::Fair => Role::Interpolate,
            r => r,
        })
        .collect();
    let first = Fitted::fit_free(parts.clone(), settings, design.clone(), &interpolating)?;
    let folded = first.surface_report_with(&settings.control)?.folded_faces;
    if folded == 0 || interpolating == roles {
        Ok(first)
    } else {
        Fitted::fit_free(parts, settings, design, roles)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;
    use std::path::Path;

    const D: Settings = Settings::DEFAULT;

    fn semicircle(n: usize, r: f64) -> Vec<[f64; 2]> {
        (0..=n)
            .map(|i| {
                let t = -PI / 2.0 + PI * i as f64 / n as f64;
                [
                    if i == 0 || i == n {
                        0.0
                    } else {
                        r * crate::math::cos(t)
                    },
                    r * crate::math::sin(t),
                ]
            })
            .collect()
    }

    #[test]
    fn semicircle_gives_a_sphere_with_two_smooth_poles() {
        let input = RevolveInput::new(semicircle(12, 1.5));
        let prof = input.profile_curve(&D).unwrap();
        assert_eq!(prof.end(0), GridEnd::Smooth);
        assert_eq!(prof.end(1), GridEnd::Smooth);
        // The mirrored spline meets the axis at a right angle.
        let d = prof.curve.eval(prof.range()[0], false).d1;
        assert!(d.y.abs() < 1e-12 * d.length(), "{d}");
        let g = input.grid(&D, &prof).unwrap();
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
        let prof = input.profile_curve(&D).unwrap();
        assert_eq!([prof.end(0), prof.end(1)], [GridEnd::Open, GridEnd::Open]);
        let g = input.grid(&D, &prof).unwrap();
        assert_eq!(g.rings.len(), 17);
        // Meridian 8 of 32 is a quarter turn.
        assert!((g.rings[8][8] - DVec3::new(0.0, 1.0, 1.0)).length() < 1e-15);
        let cone = RevolveInput::new(vec![[1.0, 0.0], [0.0, 2.0]]);
        let prof = cone.profile_curve(&D).unwrap();
        assert_eq!(prof.end(1), GridEnd::Tip(DVec3::new(0.0, 0.0, 2.0)));
        let g = cone.grid(&D, &prof).unwrap();
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
        let g = input.grid(&D, &input.profile_curve(&D).unwrap()).unwrap();
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
        let prof = input.profile_curve(&D).unwrap();
        assert_eq!(prof.end(0), GridEnd::Smooth);
        assert_eq!(prof.end(1), GridEnd::Tip(DVec3::new(0.0, 0.0, 1.0)));
        // The equator ring is creased, and the spline is still symmetric about the axis.
        let g = input.grid(&D, &prof).unwrap();
        assert_eq!(g.crease_rings.len(), 1);
        let equator = &g.rings[g.crease_rings[0]];
        assert!(equator
            .iter()
            .all(|p| p.z.abs() < 1e-15 && (p.length() - 1.0).abs() < 1e-15));
        let d = prof.curve.eval(prof.range()[0], false).d1;
        assert!(d.y.abs() < 1e-12 * d.length(), "{d}");
        input.corners = vec![13];
        assert!(input.profile_curve(&D).is_err());
        let mut open = RevolveInput::new(vec![[1.0, 0.0], [1.0, 1.0], [0.5, 2.0]]);
        open.corners = vec![0];
        let e = open.profile_curve(&D).unwrap_err();
        assert!(matches!(e, Error::InvalidArgument(m) if m.contains("corner 0")));
    }

    #[test]
    fn pole_runs_are_widened_from_the_finest_other_run() {
        let at = |s: f64, corner: bool| CurveSample { s, corner };
        // Runs [0, 1] (1 interval, a pole), [1, 4] (3), [4, 5] (2), [5, 6] (1, a pole).
        let samples = [
            at(0.0, false),
            at(1.0, true),
            at(2.0, false),
            at(3.0, false),
            at(4.0, true),
            at(4.5, false),
            at(5.0, true),
            at(6.0, false),
        ];
        let wide = widen_pole_runs(&samples, [true, true], 2).unwrap();
        // The bottom pole's run takes one from [4, 5] (the shortest intervals, 0.5), the
        // top's one from [1, 4] ([4, 5] is down to one interval).
        let s: Vec<f64> = wide.iter().map(|c| c.s).collect();
        assert_eq!(s, [0.0, 0.5, 1.0, 2.5, 4.0, 5.0, 5.5, 6.0]);
        let corners: Vec<bool> = wide.iter().map(|c| c.corner).collect();
        assert_eq!(
            corners,
            [false, false, true, false, true, true, false, false]
        );
        assert!(widen_pole_runs(&samples, [false, false], 2).is_none());
        assert!(widen_pole_runs(&samples, [true, true], 1).is_none());
    }

    #[test]
    fn bad_revolutions_are_refused() {
        let msg = |f: &dyn Fn(&mut RevolveInput, &mut Settings)| {
            let mut i = RevolveInput::new(semicircle(8, 1.0));
            let mut s = D;
            f(&mut i, &mut s);
            match i.profile_curve(&s).and_then(|p| i.grid(&s, &p)) {
                Err(Error::InvalidArgument(m)) => m,
                other => panic!("expected an error, got {other:?}"),
            }
        };
        assert!(msg(&|i, _| i.profile[3][0] = -0.1).contains("crosses the axis"));
        assert!(msg(&|i, _| i.profile[3][0] = 0.0).contains("on the axis; only"));
        assert!(msg(&|i, _| i.samples_around = 30).contains("multiple of 4"));
        assert!(msg(&|i, _| (i.angle_deg, i.samples_around) = (180.0, 30)).contains("sector caps"));
        assert!(msg(&|_, s| s.caps = Caps::Flat).contains("nothing to cap"));
        assert!(msg(&|i, _| i.angle_deg = 0.0).contains("(0, 360]"));
        assert!(msg(&|i, _| i.profile = vec![[1.0, 0.0]]).contains("at least 2"));
        assert!(msg(&|i, _| i.profile = vec![[1.0, 0.0], [1.0, f64::NAN]]).contains("not finite"));
        assert!(
            msg(&|i, _| i.profile = vec![[1.0, 0.0], [2.0, 1.0], [2.0, 0.0], [1.0, 1.0]])
                .contains("crosses itself")
        );
        assert!(msg(&|i, _| i.samples_profile = 2).contains("at least 3 intervals"));
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
