//! `profsubd shell MESH.obj --thickness C -o SHELL.obj [--stl SHELL.stl] [--targets T.txt]
//! [--level L | --tolerance T] [--outward] [--accept-folds]`: the hollow solid of a
//! surface ([`crate::construct::shell`]): outer wall, inner wall at the offset, and a rim
//! with infinitely sharp creases for open surfaces, fitted so that its limit passes
//! through the outer limit and the offset at every vertex. Nothing is written on error.

use std::path::PathBuf;

use clap::Args;

use super::construct::{write_fitted, SurfaceOutput};
use super::offset::OffsetFlags;
use super::read_mesh;
use crate::construct::shell::hollow_solid;
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
    /// Side (--outward: the inner wall outside), crust level or tolerance, folds.
    #[command(flatten)]
    pub offset: OffsetFlags,
}

/// Run `shell`; returns exit code 0 on success.
pub fn run(args: &ShellArgs) -> Result<i32> {
    let mesh = read_mesh(&args.input)?;
    let options = mesh.options().resolve();
    let offset = args.offset.offset(&mesh, &options, args.thickness)?;
    let fitted = hollow_solid(&offset, &super::progress::control("fitting"))?;
    super::progress::check_interrupted()?;
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
