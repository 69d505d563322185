//! The settings every construction shares, with their defaults and their checks: written
//! once here, read by the JSON inputs, the C options object and the command line alike.
//!
//! In a construction's JSON input these are top-level keys beside the construction's own
//! (`"sharp_angle_deg": 30, "crease_sharpness": "infinite", "interpolation": "spline",
//! "caps": "open", "boundary": "edge-and-corner", "crease_method": "uniform"`); an unknown
//! key is an error.

use std::path::Path;

use serde::de::DeserializeOwned;
use serde::{Deserialize, Deserializer};

use crate::control::Control;
use crate::curves::Interpolation;
use crate::error::{Error, Result};
use crate::fit::FitOptions;
use crate::mesh::SHARPNESS_INFINITE;
use crate::options::{BoundaryInterpolation, CreaseMethod};

/// Largest accepted sample interval count along either direction of a construction.
pub const MAX_SAMPLES: u32 = 4096;
/// Largest accepted product of the two sample interval counts.
pub const MAX_SAMPLE_PRODUCT: u64 = 4_000_000;

/// What closes an end of the surface that does not meet the axis (profiles, revolutions).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Caps {
    /// The end stays an open boundary. The default.
    #[default]
    Open,
    /// The end is closed by a flat cap, with a crease where it meets the side.
    Flat,
}

/// The settings shared by every construction. [`Settings::default`] holds the defaults;
/// [`Settings::check`] the checks.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Settings {
    /// A point where a curve turns by more than this many degrees is a corner, in
    /// `(0, 180]`. Default 30.
    #[serde(default = "default_sharp_angle")]
    pub sharp_angle_deg: f64,
    /// Sharpness of the crease edges at corners: a finite number ≥ 0 (10 and above is
    /// infinitely sharp); `"infinite"` in JSON. Default infinitely sharp.
    #[serde(
        default = "default_crease_sharpness",
        deserialize_with = "deserialize_sharpness"
    )]
    pub crease_sharpness: f32,
    /// How curve points are joined. Default spline.
    #[serde(default)]
    pub interpolation: Interpolation,
    /// What closes open ends (profiles and revolutions; a sweep refuses flat caps).
    /// Default open.
    #[serde(default)]
    pub caps: Caps,
    /// Boundary interpolation the mesh is fitted under and tagged with. Default
    /// edge-and-corner.
    #[serde(default)]
    pub boundary: BoundaryInterpolation,
    /// Crease method the mesh is fitted under and tagged with. Default uniform.
    #[serde(default)]
    pub crease_method: CreaseMethod,
    /// Progress hook, cancellation and memory budget ([`crate::control`]): polled by the
    /// fit of every construction ([`crate::construct::Fitted::fit`]). Not a JSON key.
    /// Default: none.
    #[serde(skip)]
    pub control: Control,
}

/// The JSON keys of [`Settings`] (a construction's JSON input splits on them).
pub(crate) const KEYS: [&str; 6] = [
    "sharp_angle_deg",
    "crease_sharpness",
    "interpolation",
    "caps",
    "boundary",
    "crease_method",
];

fn default_sharp_angle() -> f64 {
    Settings::DEFAULT.sharp_angle_deg
}

fn default_crease_sharpness() -> f32 {
    Settings::DEFAULT.crease_sharpness
}

impl Default for Settings {
    fn default() -> Self {
        Settings::DEFAULT
    }
}

/// Reads `crease_sharpness`: a number or `"infinite"`.
fn deserialize_sharpness<'de, D: Deserializer<'de>>(d: D) -> std::result::Result<f32, D::Error> {
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

impl Settings {
    /// The defaults: corners above 30°, infinitely sharp creases, splines, open ends,
    /// boundary edge-and-corner, uniform creasing.
    pub const DEFAULT: Settings = Settings {
        sharp_angle_deg: 30.0,
        crease_sharpness: SHARPNESS_INFINITE,
        interpolation: Interpolation::Spline,
        caps: Caps::Open,
        boundary: BoundaryInterpolation::EdgeAndCorner,
        crease_method: CreaseMethod::Uniform,
        control: Control::NONE,
    };

    /// The subdivision options the construction is fitted under.
    pub fn fit_options(&self) -> FitOptions {
        FitOptions::new(self.boundary, self.crease_method)
    }

    /// Check every setting: [`Settings::check_sharp_angle`],
    /// [`Settings::check_crease_sharpness`].
    pub fn check(&self) -> Result<()> {
        Self::check_sharp_angle(self.sharp_angle_deg)?;
        Self::check_crease_sharpness(self.crease_sharpness)
    }

    /// The corner angle must be in `(0, 180]` degrees.
    pub fn check_sharp_angle(degrees: f64) -> Result<()> {
        check_degrees("sharp_angle_deg", degrees, 180.0)
    }

    /// The crease sharpness must be a finite number ≥ 0.
    pub fn check_crease_sharpness(sharpness: f32) -> Result<()> {
        if sharpness.is_finite() && sharpness >= 0.0 {
            Ok(())
        } else {
            Err(Error::invalid_argument(format!(
                "crease_sharpness = {sharpness} must be a finite number >= 0"
            )))
        }
    }

    /// Whether sample interval counts `a` (at least `min_a`) and `b` (at least 1) are within
    /// [`MAX_SAMPLES`] each and [`MAX_SAMPLE_PRODUCT`] together.
    pub fn samples_ok(a: usize, b: usize, min_a: usize) -> bool {
        let max = MAX_SAMPLES as usize;
        (min_a..=max).contains(&a)
            && (1..=max).contains(&b)
            && (a as u64) * (b as u64) <= MAX_SAMPLE_PRODUCT
    }

    /// The memory budget of [`Settings::control`] against the fit of an `a` × `b` sample
    /// grid (about `(a + 1)(b + 1)` vertices, estimated as the fit itself does): what a
    /// construction checks with its sample counts, before it samples anything. Errors:
    /// [`Error::LimitExceeded`].
    pub fn check_fit_budget(&self, a: usize, b: usize) -> Result<()> {
        let vertices = (a + 1).saturating_mul(b + 1);
        self.control.check_memory(
            &format!("the fit of {a} × {b} samples"),
            crate::fit::fit_bytes(vertices, vertices.saturating_mul(4)),
        )
    }

    /// One sample interval count `n` named `name` must be in `1..=`[`MAX_SAMPLES`] (what
    /// a setter can check before the construction knows the other count).
    pub fn check_sample_count(name: &str, n: u32) -> Result<()> {
        if (1..=MAX_SAMPLES).contains(&n) {
            Ok(())
        } else {
            Err(Error::invalid_argument(format!(
                "{name} = {n} must be between 1 and {MAX_SAMPLES}"
            )))
        }
    }
}

/// An angle `name` = `degrees` must be in `(0, max]`.
pub(crate) fn check_degrees(name: &str, degrees: f64, max: f64) -> Result<()> {
    if degrees > 0.0 && degrees <= max {
        Ok(())
    } else {
        Err(Error::invalid_argument(format!(
            "{name} = {degrees} must be in (0, {max}]"
        )))
    }
}

/// Parse a construction's JSON input `text` (from `path`, which only names it in messages):
/// the keys of [`Settings`] give the settings, the others (and a settings key whose value is
/// an array) the construction's input `T`.
///
/// Errors: [`Error::Parse`] for a syntax error (with its line), a document that is not an
/// object, an unknown key or a bad value (line 0: the document was already read).
pub fn parse_json<T: DeserializeOwned>(text: &str, path: &Path) -> Result<(T, Settings)> {
    let mut input: serde_json::Map<String, serde_json::Value> =
        crate::io::json::parse_json(text, path)?;
    // No setting is an array: an array under a settings key is the construction's own (the
    // sketch-curves construction's `boundary` curves).
    let keys: Vec<&str> = KEYS
        .into_iter()
        .filter(|k| !input.get(*k).is_some_and(|v| v.is_array()))
        .collect();
    let settings: serde_json::Map<String, serde_json::Value> =
        keys.iter().filter_map(|k| input.remove_entry(*k)).collect();
    let value = |e: serde_json::Error| Error::Parse {
        path: path.to_path_buf(),
        line: 0,
        message: e.to_string(),
    };
    let input = T::deserialize(serde_json::Value::Object(input)).map_err(value)?;
    let settings = Settings::deserialize(serde_json::Value::Object(settings)).map_err(value)?;
    Ok((input, settings))
}

/// [`parse_json`] of the file at `path`. Errors: [`Error::Io`] if it cannot be read, then
/// those of [`parse_json`].
pub fn read_json<T: DeserializeOwned>(path: &Path) -> Result<(T, Settings)> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    parse_json(&text, path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_and_checks() {
        let s = Settings::default();
        assert_eq!(s.sharp_angle_deg, 30.0);
        assert_eq!(s.crease_sharpness, SHARPNESS_INFINITE);
        assert!(s.check().is_ok());
        for bad in [0.0, -1.0, 180.5, f64::NAN] {
            let e = Settings::check_sharp_angle(bad).unwrap_err().to_string();
            assert!(
                e.contains("sharp_angle_deg") && e.contains("(0, 180]"),
                "{e}"
            );
        }
        assert!(Settings::check_sharp_angle(180.0).is_ok());
        for bad in [-1.0, f32::NAN, f32::INFINITY] {
            assert!(Settings::check_crease_sharpness(bad).is_err());
        }
        assert!(Settings::samples_ok(4096, 976, 1));
        assert!(!Settings::samples_ok(4096, 977, 1));
        assert!(!Settings::samples_ok(2, 5, 3));
        let e = Settings::check_sample_count("along", 0)
            .unwrap_err()
            .to_string();
        assert!(e.contains("along = 0 must be between 1 and 4096"), "{e}");
    }
}
