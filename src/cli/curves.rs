//! `profsubd curves INPUT.json -o OUT.obj [--targets TARGETS.txt]`: a patch through
//! unorganized 3-D sketch curves (JSON keys and defaults: [`crate::construct::curves`]).

use std::path::PathBuf;

use clap::Args;

use super::construct::{run as run_construction, FitFlags, SurfaceOutput};
use crate::construct::curves::{build, CurvesInput};
use crate::construct::settings::read_json;
use crate::error::Result;

/// Arguments of `curves`.
#[derive(Debug, Args)]
pub struct CurvesArgs {
    /// JSON input: `{"boundary": [[[x,y,z],...], ...], "interior": [...], "tau": 2,
    /// "samples": [16, 16], "projection": "auto"}` (see the README for every key).
    #[arg(value_name = "INPUT.json")]
    pub input: PathBuf,
    /// Where to write.
    #[command(flatten)]
    pub out: SurfaceOutput,
    /// Subdivision options and crease sharpness.
    #[command(flatten)]
    pub fit: FitFlags,
}

/// Run `curves`; returns exit code 0 on success. Nothing is written on error.
pub fn run(args: &CurvesArgs) -> Result<i32> {
    let input = read_json::<CurvesInput>(&args.input)?;
    run_construction(input, build, &args.out, &args.fit)
}
