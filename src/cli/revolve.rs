//! `profsubd revolve INPUT.json -o OUT.obj [--targets TARGETS.txt]`: a profile `(r, z)`
//! turned about the z axis (JSON keys and defaults: [`crate::construct::revolve`]).

use std::path::PathBuf;

use clap::Args;

use super::construct::{run as run_construction, FitFlags, SurfaceOutput};
use crate::construct::revolve::{build, RevolveInput};
use crate::construct::settings::read_json;
use crate::error::Result;

/// Arguments of `revolve`.
#[derive(Debug, Args)]
pub struct RevolveArgs {
    /// JSON input: `{"profile": [[r,z],...], "angle_deg": 360, ...}` (see the README for
    /// every key and its default).
    #[arg(value_name = "INPUT.json")]
    pub input: PathBuf,
    /// Where to write.
    #[command(flatten)]
    pub out: SurfaceOutput,
    /// Subdivision options and crease sharpness.
    #[command(flatten)]
    pub fit: FitFlags,
}

/// Run `revolve`; returns exit code 0 on success. Nothing is written on error.
pub fn run(args: &RevolveArgs) -> Result<i32> {
    let input = read_json::<RevolveInput>(&args.input)?;
    run_construction(input, build, &args.out, &args.fit)
}
