//! `profsubd profile [INPUT.json] -o OUT.obj [--targets TARGETS.txt]`: the Hui–Lai profile
//! construction. Without INPUT it builds the built-in bottle
//! ([`crate::construct::profile::DEFAULT_MODEL_JSON`]).

use std::path::PathBuf;

use clap::Args;

use super::construct::{run as run_construction, FitFlags, SurfaceOutput};
use crate::construct::profile::{build, default_model};
use crate::construct::settings::read_json;
use crate::error::Result;

/// Arguments of `profile`.
#[derive(Debug, Args)]
pub struct ProfileArgs {
    /// JSON input: `{"c1": [[x,z],...], "c2": [[y,z],...], ...}` (see the README for every
    /// key and its default). Without it, the built-in bottle.
    #[arg(value_name = "INPUT.json")]
    pub input: Option<PathBuf>,
    /// Where to write.
    #[command(flatten)]
    pub out: SurfaceOutput,
    /// Subdivision options and crease sharpness.
    #[command(flatten)]
    pub fit: FitFlags,
}

/// Run `profile`; returns exit code 0 on success. Nothing is written on error.
pub fn run(args: &ProfileArgs) -> Result<i32> {
    let input = match &args.input {
        None => default_model(),
        Some(p) => read_json(p)?,
    };
    run_construction(input, build, &args.out, &args.fit)
}
