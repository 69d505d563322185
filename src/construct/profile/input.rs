//! The input of the profile construction and its JSON form.
//!
//! ```json
//! { "c1": [[x,z],...], "c2": [[y,z],...], "c3": [[x,z],...], "c4": [[y,z],...],
//!   "around": 16, "along": 12, "sharp_angle_deg": 30, "crease_sharpness": "infinite",
//!   "interpolation": "spline", "corners": {"c1": [4]}, "caps": "open",
//!   "boundary": "edge-and-corner", "crease_method": "uniform" }
//! ```
//! Only `c1` and `c2` are required; an unknown key is an error. Defaults:
//! `c3` = mirror of `c1` about x = 0, `c4` = mirror of `c2` about y = 0, `around` = 16,
//! `along` = 12, `sharp_angle_deg` = 30, `crease_sharpness` = `"infinite"` (or a number
//! `0..=10`; 10 and above is infinitely sharp), `interpolation` = `"spline"`, `corners` = none,
//! `caps` = `"open"`, `boundary` = `"edge-and-corner"` (or `"edge-only"`, `"none"`),
//! `crease_method` = `"uniform"` (or `"chaikin"`): the subdivision options the mesh is fitted
//! under and tagged with (see [`crate::fit::cage`]).

use std::path::Path;

use serde::{Deserialize, Deserializer};

use crate::curves::Interpolation;
use crate::error::{Error, Result};
use crate::fit::FitOptions;
use crate::mesh::SHARPNESS_INFINITE;
use crate::options::{BoundaryInterpolation, CreaseMethod};

/// Largest accepted `around` and `along`.
pub const MAX_SAMPLES: u32 = 4096;
/// Largest accepted `around × along`.
pub const MAX_SAMPLE_PRODUCT: u64 = 4_000_000;

/// What closes an end of the surface whose curves do not meet the axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Caps {
    /// The end stays an open boundary. The default.
    #[default]
    Open,
    /// The end is closed by a flat grid cap, with a crease where it meets the side.
    Flat,
}

/// Point indices forced to be corners, per curve (`c3`/`c4` only when those are given).
#[derive(Debug, Clone, PartialEq, Eq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ForcedCorners {
    /// Corner point indices of `c1`.
    #[serde(default)]
    pub c1: Vec<usize>,
    /// Corner point indices of `c2`.
    #[serde(default)]
    pub c2: Vec<usize>,
    /// Corner point indices of `c3`.
    #[serde(default)]
    pub c3: Vec<usize>,
    /// Corner point indices of `c4`.
    #[serde(default)]
    pub c4: Vec<usize>,
}

/// Four planar silhouettes and the sampling and feature settings.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProfileInput {
    /// The +x silhouette, points `(x, z)`, bottom to top.
    pub c1: Vec<[f64; 2]>,
    /// The +y silhouette, points `(y, z)`, bottom to top.
    pub c2: Vec<[f64; 2]>,
    /// The −x silhouette `(x, z)` (x ≤ the axis); `None`: the mirror of `c1` about x = 0.
    #[serde(default)]
    pub c3: Option<Vec<[f64; 2]>>,
    /// The −y silhouette `(y, z)`; `None`: the mirror of `c2` about y = 0.
    #[serde(default)]
    pub c4: Option<Vec<[f64; 2]>>,
    /// Meridians (vertices per ring); a multiple of 4, 4..=[`MAX_SAMPLES`] (at least 8 when
    /// a pole is pointed: its tip gets valence `around / 2`). Default 16.
    #[serde(default = "default_around")]
    pub around: u32,
    /// Ring intervals from bottom to top, 1..=[`MAX_SAMPLES`]. Default 12.
    #[serde(default = "default_along")]
    pub along: u32,
    /// A point where a curve turns by more than this many degrees is a corner. Default 30.
    #[serde(default = "default_sharp_angle")]
    pub sharp_angle_deg: f64,
    /// Sharpness of the crease edges at corners; `"infinite"` (10) by default.
    #[serde(
        default = "default_crease_sharpness",
        deserialize_with = "deserialize_sharpness"
    )]
    pub crease_sharpness: f32,
    /// How the points are joined. Default spline.
    #[serde(default)]
    pub interpolation: Interpolation,
    /// Point indices forced to be corners (an end index forces a pointed pole).
    #[serde(default)]
    pub corners: ForcedCorners,
    /// What closes open ends. Default open.
    #[serde(default)]
    pub caps: Caps,
    /// Boundary interpolation the mesh is fitted under and tagged with. Default
    /// edge-and-corner.
    #[serde(default)]
    pub boundary: BoundaryInterpolation,
    /// Crease method the mesh is fitted under and tagged with. Default uniform.
    #[serde(default)]
    pub crease_method: CreaseMethod,
}

fn default_around() -> u32 {
    16
}
fn default_along() -> u32 {
    12
}
fn default_sharp_angle() -> f64 {
    30.0
}
/// The default `crease_sharpness`: infinitely sharp.
pub fn default_crease_sharpness() -> f32 {
    SHARPNESS_INFINITE
}

/// Reads `crease_sharpness`: a number or `"infinite"` (shared by the sweep inputs).
pub fn deserialize_sharpness<'de, D: Deserializer<'de>>(
    d: D,
) -> std::result::Result<f32, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Spec {
        Number(f32),
        Word(String),
    }
    match Spec::deserialize(d)? {
        Spec::Number(x) => Ok(x),
        Spec::Word(w) if w == "infinite" => Ok(SHARPNESS_INFINITE),
        Spec::Word(w) => Err(serde::de::Error::custom(format!(
            "crease_sharpness must be \"infinite\" or a number, got \"{w}\""
        ))),
    }
}

impl ProfileInput {
    /// An input with the two given silhouettes (mirrored for `c3`, `c4`) and every setting
    /// at its default.
    pub fn new(c1: Vec<[f64; 2]>, c2: Vec<[f64; 2]>) -> Self {
        ProfileInput {
            c1,
            c2,
            c3: None,
            c4: None,
            around: default_around(),
            along: default_along(),
            sharp_angle_deg: default_sharp_angle(),
            crease_sharpness: default_crease_sharpness(),
            interpolation: Interpolation::default(),
            corners: ForcedCorners::default(),
            caps: Caps::default(),
            boundary: BoundaryInterpolation::default(),
            crease_method: CreaseMethod::default(),
        }
    }

    /// The subdivision options the model is fitted under.
    pub fn fit_options(&self) -> FitOptions {
        FitOptions::new(self.boundary, self.crease_method)
    }

    /// Parse the JSON form; `path` only names the input in messages.
    pub fn from_json(text: &str, path: &Path) -> Result<Self> {
        crate::io::json::parse_json(text, path)
    }

    /// Check the settings (not the curves): `around` a multiple of 4 in range, `along` in
    /// range, their product bounded, the angle in `(0, 180]`, the sharpness a number ≥ 0.
    pub fn check_settings(&self) -> Result<()> {
        if self.around < 4 || self.around % 4 != 0 || self.around > MAX_SAMPLES {
            return Err(Error::invalid_argument(format!(
                "around = {} must be a multiple of 4 between 4 and {MAX_SAMPLES}",
                self.around
            )));
        }
        if self.along < 1 || self.along > MAX_SAMPLES {
            return Err(Error::invalid_argument(format!(
                "along = {} must be between 1 and {MAX_SAMPLES}",
                self.along
            )));
        }
        if self.around as u64 * self.along as u64 > MAX_SAMPLE_PRODUCT {
            return Err(Error::invalid_argument(format!(
                "around × along = {} × {} exceeds {MAX_SAMPLE_PRODUCT} samples",
                self.around, self.along
            )));
        }
        if !(self.sharp_angle_deg > 0.0 && self.sharp_angle_deg <= 180.0) {
            return Err(Error::invalid_argument(format!(
                "sharp_angle_deg = {} must be in (0, 180]",
                self.sharp_angle_deg
            )));
        }
        check_crease_sharpness(self.crease_sharpness)
    }
}

/// `crease_sharpness` must be a finite number ≥ 0 (shared by the sweep inputs).
pub fn check_crease_sharpness(sharpness: f32) -> Result<()> {
    if sharpness.is_finite() && sharpness >= 0.0 {
        Ok(())
    } else {
        Err(Error::invalid_argument(format!(
            "crease_sharpness = {sharpness} must be a finite number >= 0"
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(s: &str) -> Result<ProfileInput> {
        ProfileInput::from_json(s, Path::new("<test>"))
    }

    #[test]
    fn defaults_and_full_form() {
        let p = parse(r#"{"c1": [[0,0],[1,1],[0,2]], "c2": [[0,0],[2,1],[0,2]]}"#).unwrap();
        assert_eq!(
            p,
            ProfileInput::new(
                vec![[0.0, 0.0], [1.0, 1.0], [0.0, 2.0]],
                vec![[0.0, 0.0], [2.0, 1.0], [0.0, 2.0]]
            )
        );
        let p = parse(
            r#"{"c1": [[0,0],[1,1]], "c2": [[0,0],[1,1]], "c3": [[0,0],[-1,1]],
                "c4": [[0,0],[-1,1]], "around": 8, "along": 3, "sharp_angle_deg": 45,
                "crease_sharpness": 2.5, "interpolation": "polyline",
                "corners": {"c2": [1]}, "caps": "flat"}"#,
        )
        .unwrap();
        assert_eq!((p.around, p.along, p.crease_sharpness), (8, 3, 2.5));
        assert_eq!(p.interpolation, Interpolation::Polyline);
        assert_eq!(p.corners.c2, vec![1]);
        assert_eq!(p.caps, Caps::Flat);
    }

    #[test]
    fn rejects_unknown_keys_and_bad_values() {
        let e = parse(r#"{"c1": [[0,0],[1,1]], "c2": [[0,0],[1,1]], "arround": 8}"#);
        assert!(matches!(e, Err(Error::Parse { message, .. }) if message.contains("arround")));
        let e = parse(r#"{"c1": [[0,0],[1,1]], "c2": [[0,0],[1,1]], "crease_sharpness": "big"}"#);
        assert!(matches!(e, Err(Error::Parse { message, .. }) if message.contains("infinite")));
        let e = parse(r#"{"c1": [[0,0],[1,1]], "c2": [[0,0],[1,1]], "corners": {"c5": [1]}}"#);
        assert!(e.is_err());
        let e = parse(r#"{"c1": [[0,0],[1,1]]}"#);
        assert!(matches!(e, Err(Error::Parse { message, .. }) if message.contains("c2")));
        let mut p = ProfileInput::new(vec![], vec![]);
        p.around = 18;
        assert!(
            matches!(p.check_settings(), Err(Error::InvalidArgument(m)) if m.contains("multiple of 4"))
        );
        p.around = 16;
        p.along = 0;
        assert!(p.check_settings().is_err());
        p.along = 4000;
        p.around = 4000;
        assert!(
            matches!(p.check_settings(), Err(Error::InvalidArgument(m)) if m.contains("exceeds"))
        );
        p.around = 16;
        p.along = 8;
        p.sharp_angle_deg = f64::NAN;
        assert!(p.check_settings().is_err());
        p.sharp_angle_deg = 30.0;
        p.crease_sharpness = -1.0;
        assert!(p.check_settings().is_err());
        p.crease_sharpness = 3.0;
        assert!(p.check_settings().is_ok());
    }
}
