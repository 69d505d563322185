//! `profsubd profile [INPUT.json] -o OUT.obj [--targets TARGETS.txt]`: the Hui–Lai profile
//! construction. Without INPUT it builds the bundled bottle (`examples/profiles/bottle.json`).
//! [`FitFlags`] (`--boundary`, `--crease`, `--crease-sharpness`, shared with `revolve` and
//! `sweep`) override the JSON's `boundary`, `crease_method` and `crease_sharpness`.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use clap::Args;

use super::{BoundaryArg, CreaseArg, SubdivFlags};
use crate::construct::profile::{build, ProfileInput};
use crate::error::{Error, Result};
use crate::io::obj::write_obj_file;
use crate::mesh::SHARPNESS_INFINITE;
use crate::options::{BoundaryInterpolation, CreaseMethod};

/// The built-in model: `examples/profiles/bottle.json`.
pub const DEFAULT_MODEL: &str = include_str!("../../examples/profiles/bottle.json");

/// Arguments of `profile`.
#[derive(Debug, Args)]
pub struct ProfileArgs {
    /// JSON input: `{"c1": [[x,z],...], "c2": [[y,z],...], ...}` (see the README for every
    /// key and its default). Without it, the built-in bottle.
    #[arg(value_name = "INPUT.json")]
    pub input: Option<PathBuf>,
    /// The OBJ file to write (control mesh with crease, corner and option tags).
    #[arg(short, long, value_name = "OUT.obj")]
    pub output: PathBuf,
    /// Also write the data point each control vertex interpolates: one `x y z` line per
    /// vertex, in vertex order.
    #[arg(long, value_name = "TARGETS.txt")]
    pub targets: Option<PathBuf>,
    /// Subdivision options and crease sharpness.
    #[command(flatten)]
    pub fit: FitFlags,
}

/// Flags of the constructions (`profile`, `revolve`, `sweep`) that override their JSON input.
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
    /// Replace the input's settings by the flags that were given.
    pub fn apply(
        &self,
        boundary: &mut BoundaryInterpolation,
        crease_method: &mut CreaseMethod,
        crease_sharpness: &mut f32,
    ) {
        let explicit = SubdivFlags {
            boundary: self.boundary,
            crease: self.crease,
            triangles: None,
        }
        .partial();
        *boundary = explicit.boundary.unwrap_or(*boundary);
        *crease_method = explicit.crease_method.unwrap_or(*crease_method);
        *crease_sharpness = self.crease_sharpness.unwrap_or(*crease_sharpness);
    }
}

/// `--crease-sharpness`: `infinite` or a finite number >= 0.
fn parse_sharpness(text: &str) -> std::result::Result<f32, String> {
    if text == "infinite" {
        return Ok(SHARPNESS_INFINITE);
    }
    match text.parse::<f32>() {
        Ok(s) if s.is_finite() && s >= 0.0 => Ok(s),
        _ => Err(format!(
            "`{text}` is not `infinite` or a finite number >= 0"
        )),
    }
}

/// Read and parse the input (or the built-in model).
pub fn read_input(path: Option<&Path>) -> Result<ProfileInput> {
    match path {
        None => ProfileInput::from_json(DEFAULT_MODEL, Path::new("<built-in bottle>")),
        Some(p) => {
            let text = std::fs::read_to_string(p).map_err(|e| Error::Io {
                path: p.to_path_buf(),
                message: e.to_string(),
            })?;
            ProfileInput::from_json(&text, p)
        }
    }
}

/// Run `profile`; returns exit code 0 on success. Nothing is written on error.
pub fn run(args: &ProfileArgs) -> Result<i32> {
    let mut input = read_input(args.input.as_deref())?;
    args.fit.apply(
        &mut input.boundary,
        &mut input.crease_method,
        &mut input.crease_sharpness,
    );
    let model = build(&input)?;
    let targets = args.targets.as_ref().map(|_| {
        let mut s = String::with_capacity(model.targets.len() * 60);
        for p in &model.targets {
            let _ = writeln!(s, "{} {} {}", p.x, p.y, p.z);
        }
        s
    });
    write_obj_file(&model.mesh, &args.output)?;
    if let (Some(path), Some(text)) = (&args.targets, targets) {
        std::fs::write(path, text).map_err(|e| Error::Io {
            path: path.clone(),
            message: e.to_string(),
        })?;
    }
    let m = &model.mesh;
    println!(
        "wrote {} ({} vertices, {} quads, {} creases, {} corners; ends {:?}/{:?}; fit residual \
         {:.3e} <= {:.3e})",
        args.output.display(),
        m.num_vertices(),
        m.num_faces(),
        m.creases().len(),
        m.corners().len(),
        model.ends[0],
        model.ends[1],
        model.fit.residual,
        model.fit.tolerance
    );
    Ok(0)
}
