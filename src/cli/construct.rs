//! What every construction subcommand (`profile`, `revolve`, `sweep`) shares: reading the
//! JSON input, the flags that override its settings, writing the mesh and the data points,
//! and the one-line summary. A subcommand declares its input type and calls [`run`].

use std::fmt::Write as _;
use std::path::PathBuf;

use clap::Args;

use super::{BoundaryArg, CreaseArg, SubdivFlags};
use crate::construct::{Fitted, Settings};
use crate::error::{Error, Result};
use crate::io::obj::write_obj_file;
use crate::mesh::SHARPNESS_INFINITE;

/// Output flags of the constructions.
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

/// Flags of the constructions that override their JSON input's settings.
#[derive(Debug, Clone, Default, Args)]
pub struct FitFlags {
    /// Boundary interpolation the mesh is fitted under and tagged with; overrides the JSON's
    /// `boundary` [default without either: edge-and-corner].
    #[arg(long, value_enum, value_name = "RULE")]
    pub boundary: Option<BoundaryArg>,
    /// Crease method the mesh is fitted under and tagged with; overrides the JSON's
    /// `crease_method` [default without either: uniform].
    #[arg(long, value_enum, value_name = "METHOD")]
    pub crease: Option<CreaseArg>,
    /// Sharpness of the crease edges at corners: a number >= 0 or `infinite`; overrides the
    /// JSON's `crease_sharpness` [default without either: infinite].
    #[arg(long, value_name = "SHARPNESS", value_parser = parse_sharpness)]
    pub crease_sharpness: Option<f32>,
}

impl FitFlags {
    /// Replace the settings by the flags that were given.
    pub fn apply(&self, settings: &mut Settings) {
        let explicit = SubdivFlags {
            boundary: self.boundary,
            crease: self.crease,
            triangles: None,
        }
        .partial();
        settings.boundary = explicit.boundary.unwrap_or(settings.boundary);
        settings.crease_method = explicit.crease_method.unwrap_or(settings.crease_method);
        settings.crease_sharpness = self.crease_sharpness.unwrap_or(settings.crease_sharpness);
    }
}

/// `--crease-sharpness`: `infinite` or a number that [`Settings::check_crease_sharpness`]
/// accepts.
fn parse_sharpness(text: &str) -> std::result::Result<f32, String> {
    let value = if text == "infinite" {
        SHARPNESS_INFINITE
    } else {
        text.parse::<f32>()
            .map_err(|_| format!("`{text}` is not `infinite` or a finite number >= 0"))?
    };
    Settings::check_crease_sharpness(value)
        .map(|()| value)
        .map_err(|_| format!("`{text}` is not `infinite` or a finite number >= 0"))
}

/// Run a construction: apply the flags to the settings read with `input`, build, write the
/// outputs and print the summary. Returns exit code 0; nothing is written on error.
pub fn run<I>(
    (input, mut settings): (I, Settings),
    build: fn(&I, &Settings) -> Result<Fitted>,
    out: &SurfaceOutput,
    flags: &FitFlags,
) -> Result<i32> {
    flags.apply(&mut settings);
    settings.control = super::progress::control("fitting");
    let fitted = build(&input, &settings)?;
    super::progress::check_interrupted()?;
    write_fitted(&fitted, out)?;
    Ok(0)
}

/// Write the mesh (and the targets when asked), then a one-line summary on stdout.
pub(crate) fn write_fitted(s: &Fitted, out: &SurfaceOutput) -> Result<()> {
    let output = &out.output;
    let targets = out.targets.as_ref().map(|_| {
        let mut text = String::with_capacity(s.targets.len() * 60);
        for p in &s.targets {
            let _ = writeln!(text, "{} {} {}", p.x, p.y, p.z);
        }
        text
    });
    write_obj_file(&s.mesh, output)?;
    if let (Some(path), Some(text)) = (&out.targets, targets) {
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
