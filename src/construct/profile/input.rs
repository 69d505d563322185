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
//! `along` = 12, `corners` = none. The other keys are the shared [`Settings`]
//! (`sharp_angle_deg` 30, `crease_sharpness` `"infinite"`, `interpolation` `"spline"`,
//! `caps` `"open"`, `boundary` `"edge-and-corner"`, `crease_method` `"uniform"`).

use std::path::Path;

use serde::Deserialize;

use crate::construct::settings::{Settings, MAX_SAMPLES, MAX_SAMPLE_PRODUCT};
use crate::error::{Error, Result};

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

/// Four planar silhouettes and their sampling (the shared settings are [`Settings`]).
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
    /// Point indices forced to be corners (an end index forces a pointed pole).
    #[serde(default)]
    pub corners: ForcedCorners,
}

fn default_around() -> u32 {
    16
}
fn default_along() -> u32 {
    12
}

impl ProfileInput {
    /// An input with the two given silhouettes (mirrored for `c3`, `c4`) and the default
    /// sampling.
    pub fn new(c1: Vec<[f64; 2]>, c2: Vec<[f64; 2]>) -> Self {
        ProfileInput {
            c1,
            c2,
            c3: None,
            c4: None,
            around: default_around(),
            along: default_along(),
            corners: ForcedCorners::default(),
        }
    }

    /// Parse the JSON form into the input and its settings; `path` only names the input in
    /// messages.
    pub fn from_json(text: &str, path: &Path) -> Result<(Self, Settings)> {
        crate::construct::settings::parse_json(text, path)
    }

    /// Check the sampling and `settings` (not the curves): `around` a multiple of 4 in
    /// range, `along` in range, their product bounded, then [`Settings::check`].
    pub fn check_settings(&self, settings: &Settings) -> Result<()> {
        if self.around < 4 || self.around % 4 != 0 || self.around > MAX_SAMPLES {
            return Err(Error::invalid_argument(format!(
                "around = {} must be a multiple of 4 between 4 and {MAX_SAMPLES}",
                self.around
            )));
        }
        Settings::check_sample_count("along", self.along)?;
        if self.around as u64 * self.along as u64 > MAX_SAMPLE_PRODUCT {
            return Err(Error::invalid_argument(format!(
                "around × along = {} × {} exceeds {MAX_SAMPLE_PRODUCT} samples",
                self.around, self.along
            )));
        }
        settings.check()?;
        settings.check_fit_budget(self.along as usize, self.around as usize)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::construct::settings::Caps;
    use crate::curves::Interpolation;

    fn parse(s: &str) -> Result<(ProfileInput, Settings)> {
        ProfileInput::from_json(s, Path::new("<test>"))
    }

    #[test]
    fn defaults_and_full_form() {
        let (p, s) = parse(r#"{"c1": [[0,0],[1,1],[0,2]], "c2": [[0,0],[2,1],[0,2]]}"#).unwrap();
        assert_eq!(s, Settings::default());
        assert_eq!(
            p,
            ProfileInput::new(
                vec![[0.0, 0.0], [1.0, 1.0], [0.0, 2.0]],
                vec![[0.0, 0.0], [2.0, 1.0], [0.0, 2.0]]
            )
        );
        let (p, s) = parse(
            r#"{"c1": [[0,0],[1,1]], "c2": [[0,0],[1,1]], "c3": [[0,0],[-1,1]],
                "c4": [[0,0],[-1,1]], "around": 8, "along": 3, "sharp_angle_deg": 45,
                "crease_sharpness": 2.5, "interpolation": "polyline",
                "corners": {"c2": [1]}, "caps": "flat"}"#,
        )
        .unwrap();
        assert_eq!((p.around, p.along, s.crease_sharpness), (8, 3, 2.5));
        assert_eq!(s.interpolation, Interpolation::Polyline);
        assert_eq!(p.corners.c2, vec![1]);
        assert_eq!(s.caps, Caps::Flat);
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
        let mut s = Settings::default();
        p.around = 18;
        assert!(
            matches!(p.check_settings(&s), Err(Error::InvalidArgument(m)) if m.contains("multiple of 4"))
        );
        p.around = 16;
        p.along = 0;
        assert!(p.check_settings(&s).is_err());
        p.along = 4000;
        p.around = 4000;
        assert!(
            matches!(p.check_settings(&s), Err(Error::InvalidArgument(m)) if m.contains("exceeds"))
        );
        p.around = 16;
        p.along = 8;
        s.sharp_angle_deg = f64::NAN;
        assert!(p.check_settings(&s).is_err());
        s.sharp_angle_deg = 30.0;
        s.crease_sharpness = -1.0;
        assert!(p.check_settings(&s).is_err());
        s.crease_sharpness = 3.0;
        assert!(p.check_settings(&s).is_ok());
    }
}
