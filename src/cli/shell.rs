//! `profsubd shell MESH.obj --thickness C -o SHELL.obj [--stl SHELL.stl] [--targets T.txt]
//! [--level L | --tolerance T] [--outward] [--accept-folds]`: the hollow solid of a
//! surface ([`crate::construct::shell`]): outer wall, inner wall at the offset, and a rim
//! with infinitely sharp creases for open surfaces, fitted so that its limit passes
//! through the outer limit and the offset at every vertex. Nothing is written on error.

use std::path::PathBuf;

use clap::Args;

use super::construct::{write_fitted, SurfaceOutput};
use super::offset::OffsetArgs;
use super::read_mesh;
use crate::construct::shell::{hollow_solid, ShellInput};
use crate::error::Result;
use crate::eval::Evaluator;
use crate::io::surface::{write_surface_file, SurfaceFormat};
use crate::io::up_axis::UpAxis;
use crate::tessellate::{tessellate, TessellateOptions};

/// Arguments of `shell`.
#[derive(Debug, Args)]
pub struct ShellArgs {
    /// The OBJ mesh of the outer wall (manifold; its tags give the subdivision options).
    #[arg(value_name = "MESH.obj")]
    pub input: PathBuf,
    /// The thickness c (model units, > 0).
    #[arg(long, value_name = "C")]
    pub thickness: f64,
    /// Where to write.
    #[command(flatten)]
    pub out: SurfaceOutput,
    /// Also write a binary STL of the solid's limit surface (tessellated at rate 4 a face).
    #[arg(long, value_name = "SHELL.stl")]
    pub stl: Option<PathBuf>,
    /// The inner wall outside (along S_u x S_v) instead of inside.
    #[arg(long)]
    pub outward: bool,
    /// The crust's refinement level (0: the paper's scheme on the mesh itself).
    #[arg(
        long,
        value_name = "L",
        default_value_t = 0,
        conflicts_with = "tolerance"
    )]
    pub level: u32,
    /// Choose the lowest level at which |thickness - c| <= T at every sample (model units).
    #[arg(long, value_name = "T")]
    pub tolerance: Option<f64>,
    /// Accept an offset that folds instead of failing.
    #[arg(long)]
    pub accept_folds: bool,
}

/// Run `shell`; returns exit code 0 on success.
pub fn run(args: &ShellArgs) -> Result<i32> {
    let mesh = read_mesh(&args.input)?;
    let settings =
        OffsetArgs::settings_of(args.thickness, args.outward, args.level, args.accept_folds);
    let input = ShellInput {
        mesh,
        offset: settings,
        tolerance: args.tolerance,
    };
    let (offset, report) = input.offset()?;
    if let Some(r) = report {
        eprintln!(
            "level {}: thickness / c min {:.6} max {:.6} mean {:.6} at {} samples",
            r.level, r.min, r.max, r.mean, r.samples
        );
    }
    let fitted = hollow_solid(&offset)?;
    // Tessellate before writing anything, so that a failure writes nothing.
    let stl = match &args.stl {
        Some(path) => {
            let ev = Evaluator::new(&fitted.mesh, &fitted.mesh.options().resolve())?;
            Some((path, tessellate(&ev, &TessellateOptions::default())?))
        }
        None => None,
    };
    write_fitted(&fitted, &args.out)?;
    if let Some((path, t)) = stl {
        write_surface_file(&t, path, SurfaceFormat::Stl, UpAxis::Z)?;
        println!("wrote {} ({} triangles)", path.display(), t.num_faces());
    }
    Ok(0)
}
