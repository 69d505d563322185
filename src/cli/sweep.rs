//! `profsubd sweep INPUT.json -o OUT.obj [--targets TARGETS.txt]`: a planar profile swept
//! along a 3-D trajectory (JSON keys and defaults: [`crate::construct::sweep::sweep`](mod@crate::construct::sweep::sweep)).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use clap::Args;

use super::profile::FitFlags;
use crate::construct::sweep::sweep::SweepInput;
use crate::construct::sweep::{sweep, SweptSurface};
use crate::error::{Error, Result};
use crate::io::obj::write_obj_file;

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

/// Output flags of `sweep` and `revolve`.
#[derive(Debug, Args)]
pub struct SurfaceOutput {
    /// The OBJ file to write (control mesh with crease, corner and option tags).
    #[arg(short, long, value_name = "OUT.obj")]
    pub output: PathBuf,
    /// Also write the data point each control vertex interpolates: one `x y z` line per
    /// vertex, in vertex order.
    #[arg(long, value_name = "TARGETS.txt")]
    pub targets: Option<PathBuf>,
}

/// The text of `path`.
pub(crate) fn read_text(path: &Path) -> Result<String> {
    std::fs::read_to_string(path).map_err(|e| Error::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}

/// Write the mesh (and the targets when asked), then a one-line summary on stdout.
pub(crate) fn write_surface(s: &SweptSurface, out: &SurfaceOutput) -> Result<()> {
    let output = &out.output;
    write_obj_file(&s.mesh, output)?;
    if let Some(path) = &out.targets {
        let mut text = String::with_capacity(s.targets.len() * 60);
        for p in &s.targets {
            let _ = writeln!(text, "{} {} {}", p.x, p.y, p.z);
        }
        std::fs::write(path, text).map_err(|e| Error::Io {
            path: path.clone(),
            message: e.to_string(),
        })?;
    }
    let m = &s.mesh;
    println!(
        "wrote {} ({} vertices, {} quads, {} creases, {} corners; fit residual {:.3e} <= {:.3e})",
        output.display(),
        m.num_vertices(),
        m.num_faces(),
        m.creases().len(),
        m.corners().len(),
        s.fit.residual,
        s.fit.tolerance
    );
    Ok(())
}

/// Run `sweep`; returns exit code 0 on success. Nothing is written on error.
pub fn run(args: &SweepArgs) -> Result<i32> {
    let mut input = SweepInput::from_json(&read_text(&args.input)?, &args.input)?;
    let i = &mut input;
    args.fit.apply(
        &mut i.boundary,
        &mut i.crease_method,
        &mut i.crease_sharpness,
    );
    write_surface(&sweep(&input)?, &args.out)?;
    Ok(0)
}
