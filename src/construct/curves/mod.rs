//! Surfaces from unorganized 3-D sketch curves (Qin & Wright, "Universal attraction
//! force-inspired freeform surface modeling for 3D sketching"): 3 or 4 rough boundary curves
//! and any number of interior curves become an open Catmull–Clark surface through them.
//!
//! ```json
//! { "boundary": [[[x,y,z],...], [[x,y,z],...], [[x,y,z],...], [[x,y,z],...]],
//!   "interior": [[[x,y,z],...], ...], "tau": 2, "samples": [16, 16],
//!   "projection": "auto", "method": "attraction", "interpolation": "spline" }
//! ```
//! Keys: `boundary` (required: 3 or 4 point lists in order around the patch; each runs on
//! from the previous one: a curve whose end is nearer the previous curve's end than its start
//! is is taken reversed; ends may leave gaps, *open corners*), `interior` (default none: curves
//! in any position and direction, crossing the boundary or not; the parts outside it are
//! clipped), `tau` (τ ≥ 0 of eqs. (5)–(7), default 2), `samples` (`[nu, nv]` quads along the
//! first and second boundary curve's directions, default `[16, 16]`; a 3-sided patch uses
//! `k = ⌈max(nu, nv)/2⌉`, see [`grid`]), `projection` (`"auto"`, the default: the best-fit
//! plane of all curve points; or a normal `[x, y, z]`), `method` (`"attraction"`, the
//! default: the paper's blend; `"fair"`: [`Method::Fair`]). The shared [`Settings`] keys apply
//! (`interpolation`: curves as splines or polylines; `crease_method`: what the mesh is fitted
//! under; `caps` must stay `"open"`). Here `boundary` is the curves (an array); the boundary
//! *rule* the mesh is fitted under (default edge-and-corner) then comes from the command
//! line's `--boundary` or the C options, since a settings value is never an array (see
//! [`crate::construct::settings::parse_json`]). An unknown key is an error.
//!
//! Steps: curves ([`SpaceCurve`]s through the points) → projection on a plane
//! ([`projection`]) → pre-images in the unit square ([`preimage`]: boundary to the square's
//! sides by chord length, Coons map inside, inverted by Newton for the interior curves) →
//! the attraction blend on a grid of the square ([`blend`], the paper's eqs. (5)–(8), nodes
//! moved onto the interior curves' pre-images, [`grid`]) → the Catmull–Clark control mesh
//! whose exact limit surface passes through every blended point ([`Fitted::fit`]).
//!
//! Orientation: the square is mapped counter-clockwise onto the plane (the plane's normal is
//! flipped if the boundary runs clockwise round it), so the surface's normal follows the
//! boundary's order by the right-hand rule.

pub mod blend;
#[cfg(test)]
mod fair_tests;
pub mod grid;
pub mod preimage;
pub mod projection;
#[cfg(test)]
mod tests;

use std::path::Path;

use glam::{DVec2, DVec3};
use serde::{Deserialize, Deserializer};

use crate::construct::design::{design_lattice, Design, DesignCoord, DesignLattice};
use crate::construct::fitted::Fitted;
use crate::construct::settings::{Caps, Settings, MAX_SAMPLES, MAX_SAMPLE_PRODUCT};
use crate::curves::SpaceCurve;
use crate::error::{Error, Result};
use crate::fit::fair;
use crate::mesh::MeshParts;
use blend::Blend;
use grid::SquareGrid;
use preimage::{Boundary, Interior, Side};
use projection::Plane;

/// The plane the curves are projected on.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Projection {
    /// The best-fit plane of all curve points (JSON `"auto"`). The default.
    #[default]
    Auto,
    /// The plane through the points' centroid with this normal (JSON `[x, y, z]`).
    Normal([f64; 3]),
}

impl<'de> Deserialize<'de> for Projection {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Spec {
            Normal([f64; 3]),
            Word(String),
        }
        match Spec::deserialize(d)? {
            Spec::Normal(n) => Ok(Projection::Normal(n)),
            Spec::Word(w) if w == "auto" => Ok(Projection::Auto),
            Spec::Word(w) => Err(serde::de::Error::custom(format!(
                "projection must be \"auto\" or a normal [x, y, z], got \"{w}\""
            ))),
        }
    }
}

/// How the points of the grid between the curves are found.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// The paper's attraction blend, eqs. (5)–(8), at every node (JSON `"attraction"`). The
    /// default.
    #[default]
    Attraction,
    /// Variational (JSON `"fair"`): the nodes on a curve keep their curve points; the others
    /// minimize the discrete thin-plate energy `∫ |ΔS|²` of the limit surface over the
    /// projection plane, each node over its Coons-map point (`fit::fair`). `tau` is
    /// not used.
    Fair,
}

/// Sketch curves to a surface: see the module documentation for the JSON form and defaults.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CurvesInput {
    /// 3 or 4 boundary curves in order around the patch.
    pub boundary: Vec<Vec<[f64; 3]>>,
    /// Interior curves. Default none.
    #[serde(default)]
    pub interior: Vec<Vec<[f64; 3]>>,
    /// The attraction exponent τ ≥ 0. Default 2.
    #[serde(default = "default_tau")]
    pub tau: f64,
    /// Quads `[nu, nv]` along the first and second boundary curve. Default `[16, 16]`.
    #[serde(default = "default_samples")]
    pub samples: [usize; 2],
    /// The projection plane. Default auto.
    #[serde(default)]
    pub projection: Projection,
    /// The attraction blend or the fair variant. Default the blend.
    #[serde(default)]
    pub method: Method,
}

fn default_tau() -> f64 {
    2.0
}
fn default_samples() -> [usize; 2] {
    [16, 16]
}

/// Parameter steps per quad of the grid with which an interior curve's pre-image is sampled.
const PREIMAGE_STEPS_PER_QUAD: usize = 8;

impl CurvesInput {
    /// An input with these boundary curves and every other key at its default.
    pub fn new(boundary: Vec<Vec<[f64; 3]>>) -> CurvesInput {
        CurvesInput {
            boundary,
            interior: Vec::new(),
            tau: default_tau(),
            samples: default_samples(),
            projection: Projection::Auto,
            method: Method::Attraction,
        }
    }

    /// Parse the JSON form into the input and its settings; `path` only names the input in
    /// messages.
    pub fn from_json(text: &str, path: &Path) -> Result<(CurvesInput, Settings)> {
        crate::construct::settings::parse_json(text, path)
    }

    /// τ must be finite and ≥ 0.
    pub fn check_tau(tau: f64) -> Result<()> {
        if tau.is_finite() && tau >= 0.0 {
            Ok(())
        } else {
            Err(Error::invalid_argument(format!(
                "tau = {tau} must be a finite number >= 0"
            )))
        }
    }

    fn check(&self, settings: &Settings) -> Result<()> {
        settings.check()?;
        if settings.caps != Caps::Open {
            return Err(Error::invalid_argument(
                "caps = \"flat\": a patch from sketch curves has no caps",
            ));
        }
        Self::check_tau(self.tau)?;
        let [nu, nv] = self.samples;
        if !Settings::samples_ok(nu, nv, 1) {
            return Err(Error::invalid_argument(format!(
                "samples = [{nu}, {nv}]: each must be 1..={MAX_SAMPLES} and their product at \
                 most {MAX_SAMPLE_PRODUCT}"
            )));
        }
        let n = self.boundary.len();
        if !(3..=4).contains(&n) {
            return Err(Error::invalid_argument(format!(
                "boundary: 3 or 4 curves are needed around the patch, got {n}"
            )));
        }
        Ok(())
    }

    /// The curves' pre-images and the blend (every check of the input).
    ///
    /// Errors ([`Error::InvalidArgument`], naming the culprit): bad settings, τ, samples or
    /// boundary count; a curve with fewer than 2 points, a non-finite coordinate or
    /// coinciding consecutive points; no projection plane; a boundary whose projection has no
    /// area, crosses itself or whose Coons map folds; an interior curve wholly outside.
    pub fn blend(&self, settings: &Settings) -> Result<Blend> {
        self.check(settings)?;
        let curve = |what: String, points: &[[f64; 3]]| {
            let p: Vec<DVec3> = points.iter().map(|&q| DVec3::from(q)).collect();
            SpaceCurve::new(&what, &p, false, settings.interpolation, &[])
        };
        let mut loop_: Vec<SpaceCurve> = Vec::with_capacity(4);
        for (k, points) in self.boundary.iter().enumerate() {
            let mut c = curve(format!("boundary {k}"), points)?;
            if let Some(prev) = loop_.last() {
                let end = prev.eval(prev.length(), true).position;
                let (first, last) = (c.points()[0], c.points()[c.points().len() - 1]);
                if end.distance(last) < end.distance(first) {
                    let mut rev = points.clone();
                    rev.reverse();
                    c = curve(format!("boundary {k}"), &rev)?;
                }
            }
            loop_.push(c);
        }
        let interior: Vec<SpaceCurve> = self
            .interior
            .iter()
            .enumerate()
            .map(|(k, p)| curve(format!("interior {k}"), p))
            .collect::<Result<_>>()?;
        let all: Vec<DVec3> = loop_
            .iter()
            .chain(&interior)
            .flat_map(|c| c.points().iter().copied())
            .collect();
        let plane = match self.projection {
            Projection::Auto => Plane::best_fit(&all)?,
            Projection::Normal(n) => Plane::with_normal(&all, n)?,
        };
        let three_sided = loop_.len() == 3;
        let side = |c: &SpaceCurve, reversed: bool| Side::Curve {
            curve: c.clone(),
            reversed,
        };
        let sides = if three_sided {
            let apex =
                (loop_[1].points()[loop_[1].points().len() - 1] + loop_[2].points()[0]) * 0.5;
            [
                side(&loop_[0], false),
                side(&loop_[1], false),
                Side::Point(apex),
                side(&loop_[2], true),
            ]
        } else {
            [
                side(&loop_[0], false),
                side(&loop_[1], false),
                side(&loop_[2], true),
                side(&loop_[3], true),
            ]
        };
        let boundary = Boundary::new(sides, plane, three_sided)?;
        let segments = PREIMAGE_STEPS_PER_QUAD * self.samples[0].max(self.samples[1]).max(8);
        let interior = interior
            .into_iter()
            .enumerate()
            .map(|(k, c)| Interior::new(&format!("interior {k}"), c, &boundary, segments))
            .collect::<Result<_>>()?;
        Ok(Blend {
            boundary,
            interior,
            tau: self.tau,
        })
    }

    /// The nodes in the square for these samples ([`grid`]).
    pub fn grid(&self, blend: &Blend) -> SquareGrid {
        let [nu, nv] = self.samples;
        if blend.boundary.three_sided {
            SquareGrid::three_sided(nu.max(nv).div_ceil(2), blend)
        } else {
            SquareGrid::four_sided(nu, nv, blend)
        }
    }

    /// The cage and the design lattice: the design surface is the blend itself, at the
    /// bilinear interpolation of a face's corner `(u, v)`. Under [`Method::Attraction`] each
    /// vertex is at its blended point; under [`Method::Fair`] the vertices on a curve are
    /// (their blended point is the curve point) and the others minimize the thin-plate
    /// energy of the surface over the projection plane, the vertices placed in the plane by
    /// the Coons map (`fit::fair`, started from their blended points).
    pub fn cage(&self, settings: &Settings) -> Result<(MeshParts, DesignLattice)> {
        let blend = self.blend(settings)?;
        let grid = self.grid(&blend);
        let mut parts = grid.parts(&blend, &settings.control)?;
        let coords: Vec<DesignCoord> = grid
            .uv
            .iter()
            .map(|p| DesignCoord::Side { s: p.x, theta: p.y })
            .collect();
        let lattice = design_lattice(
            &grid.faces,
            &coords,
            &parts.positions,
            &BlendDesign(&blend),
            &settings.control,
        )?;
        if self.method == Method::Fair {
            let fixed: Vec<bool> = grid.uv.iter().map(|&p| blend.on_curve(p)).collect();
            let plane: Vec<DVec2> = grid
                .uv
                .iter()
                .map(|p| blend.boundary.map(p.x, p.y))
                .collect();
            let rows = fair::laplacian_rows(&grid.faces, &plane)?;
            parts.positions = fair::minimize(&rows, &fixed, &parts.positions, &settings.control)?;
        }
        Ok((parts, lattice))
    }
}

/// The blend as a design surface: side `(s, θ)` = `(u, v)`.
struct BlendDesign<'a>(&'a Blend);

impl Design for BlendDesign<'_> {
    fn side(&self, s: f64, theta: f64) -> DVec3 {
        self.0.point(DVec2::new(s, theta))
    }
    fn angle(&self, theta: f64) -> f64 {
        theta
    }
    fn cap(&self, _end: usize, _rho: f64, _theta: f64) -> DVec3 {
        unreachable!("a sketch patch has no caps")
    }
    fn periods(&self) -> [Option<f64>; 2] {
        [None, None]
    }
}

/// The surface of `input`'s curves under `settings`, fitted: the exact limit surface passes
/// through every blended point. The blend's layout is not fold-free: with interior curves the
/// fitted limit surface can fold as the samples grow (the grid nodes crowd onto the curves'
/// pre-images while the blend has ridges along them), so every build runs the fold check and
/// refuses a folded surface.
///
/// Errors: those of [`CurvesInput::blend`] ([`Error::InvalidArgument`]) and of the fit; and
/// [`Error::InvalidArgument`] if the limit surface folds, naming the folded faces and where
/// the worst reversal lies.
pub fn build(input: &CurvesInput, settings: &Settings) -> Result<Fitted> {
    let (parts, design) = input.cage(settings)?;
    let [nu, nv] = input.samples;
    Fitted::fit(parts, settings, design)?.refuse_folds(
        &format!(
            "curves ({} interior, {}, {nu} x {nv} samples)",
            input.interior.len(),
            match input.method {
                Method::Attraction => format!("tau = {}", input.tau),
                Method::Fair => "method fair".to_string(),
            }
        ),
        "fewer samples or another tau give another layout",
        &settings.control,
    )
}
