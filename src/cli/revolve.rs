//! `profsubd revolve INPUT.json -o OUT.obj [--targets TARGETS.txt]`: a profile `(r, z)`
//! turned about the z axis (JSON keys and defaults: [`crate::construct::sweep::revolve`](mod@crate::construct::sweep::revolve)).

use std::path::PathBuf;

use clap::Args;

use super::profile::FitFlags;
use super::sweep::{read_text, write_surface, SurfaceOutput};
use crate::construct::sweep::revolve;
use crate::construct::sweep::revolve::RevolveInput;
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
    let mut input = RevolveInput::from_json(&read_text(&args.input)?, &args.input)?;
    let i = &mut input;
    args.fit.apply(
        &mut i.boundary,
        &mut i.crease_method,
        &mut i.crease_sharpness,
    );
    write_surface(&revolve(&input)?, &args.out)?;
    Ok(0)
}
