//! `profsubd revolve INPUT.json -o OUT.obj [--targets TARGETS.txt]`: a profile `(r, z)`
//! turned about the z axis (JSON keys and defaults: [`crate::construct::sweep::revolve`]).

use std::path::PathBuf;

use clap::Args;

use super::sweep::{read_text, write_surface};
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
    /// The OBJ file to write (control mesh with crease, corner and option tags).
    #[arg(short, long, value_name = "OUT.obj")]
    pub output: PathBuf,
    /// Also write the data point each control vertex interpolates: one `x y z` line per
    /// vertex, in vertex order.
    #[arg(long, value_name = "TARGETS.txt")]
    pub targets: Option<PathBuf>,
}

/// Run `revolve`; returns exit code 0 on success. Nothing is written on error.
pub fn run(args: &RevolveArgs) -> Result<i32> {
    let input = RevolveInput::from_json(&read_text(&args.input)?, &args.input)?;
    write_surface(&revolve(&input)?, &args.output, args.targets.as_deref())?;
    Ok(0)
}
