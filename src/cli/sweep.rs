//! `profsubd sweep INPUT.json -o OUT.obj [--targets TARGETS.txt]`: a planar profile swept
//! along a 3-D trajectory (JSON keys and defaults: [`crate::construct::sweep`]).

use std::path::PathBuf;

use clap::Args;

use super::construct::{run as run_construction, FitFlags, SurfaceOutput};
use crate::construct::settings::read_json;
use crate::construct::sweep::{build, SweepInput};
use crate::error::Result;

/// Arguments of `sweep`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    /// JSON input: `{"profile": [[a,b],...], "trajectory": [[x,y,z],...], ...}` (see the
    /// README for every key and its default).
    #[arg(value_name = "INPUT.json")]
    pub input: PathBuf,
    /// Where to write.
    #[command(flatten)]
    pub out: SurfaceOutput,
    /// Subdivision options and crease sharpness.
    #[command(flatten)]
    pub fit: FitFlags,
}

/// Run `sweep`; returns exit code 0 on success. Nothing is written on error.
pub fn run(args: &SweepArgs) -> Result<i32> {
    let input = read_json::<SweepInput>(&args.input)?;
    run_construction(input, build, &args.out, &args.fit)
}
