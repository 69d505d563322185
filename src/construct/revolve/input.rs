//! The input of a revolution and its JSON form (see [`crate::construct::revolve`]).

use std::path::Path;

use serde::Deserialize;

use crate::construct::settings::{check_degrees, Settings, MAX_SAMPLES, MAX_SAMPLE_PRODUCT};
use crate::error::{Error, Result};

/// A surface of revolution (the shared settings are [`Settings`]). See the module
/// documentation of [`crate::construct::revolve`] for the JSON form and defaults.
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
    /// Profile point indices forced to be corners (an end on the axis: a pointed pole).
    /// Default none.
    #[serde(default)]
    pub corners: Vec<usize>,
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

impl RevolveInput {
    /// An input with the given profile and every setting at its default.
    pub fn new(profile: Vec<[f64; 2]>) -> RevolveInput {
        RevolveInput {
            profile,
            angle_deg: default_angle(),
            samples_profile: default_samples_profile(),
            samples_around: default_samples_around(),
            corners: Vec::new(),
        }
    }

    /// Parse the JSON form into the input and its settings; `path` only names the input in
    /// messages.
    pub fn from_json(text: &str, path: &Path) -> Result<(RevolveInput, Settings)> {
        crate::construct::settings::parse_json(text, path)
    }

    /// Whether the revolution is a full turn.
    pub fn full_turn(&self) -> bool {
        self.angle_deg == 360.0
    }

    /// The angle turned must be in `(0, 360]` degrees.
    pub fn check_angle(degrees: f64) -> Result<()> {
        check_degrees("angle_deg", degrees, 360.0)
    }

    /// Check the sampling, the angle and `settings`.
    pub fn check_settings(&self, settings: &Settings) -> Result<()> {
        let (np, na) = (self.samples_profile, self.samples_around);
        if !Settings::samples_ok(na, np, 3) {
            return Err(Error::invalid_argument(format!(
                "samples_profile = {np} and samples_around = {na}: samples_profile must be \
                 1..={MAX_SAMPLES}, samples_around 3..={MAX_SAMPLES}, their product at most \
                 {MAX_SAMPLE_PRODUCT}"
            )));
        }
        Self::check_angle(self.angle_deg)?;
        settings.check()?;
        settings.check_fit_budget(np, na)
    }
}
