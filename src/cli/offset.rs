//! `profsubd offset MESH.obj --thickness C --at POINTS.txt [--derivs] [--outward]
//! [--level L | --tolerance T] [--accept-folds]`: the offset of the limit surface by a
//! Bézier crust ([`crate::construct::shell`]) at given `(face, u, v)` points.
//!
//! Output as `limit --at`: one line per point, `x y z` of the offset, with `--derivs` its
//! derivatives `dux duy duz dvx dvy dvz`; `nan` where there is no limit surface. With
//! `--tolerance` the crust level is chosen and reported on stderr with the measured
//! thickness. Nothing is printed on error.

use std::path::PathBuf;

use clap::Args;

use super::limit::{print_samples, read_points, DomainArg};
use super::{read_mesh, SubdivFlags};
use crate::construct::shell::{offset_within, OffsetSettings, OffsetSurface, Side};
use crate::error::Result;
use crate::eval::{Domain, LimitSample};

/// Arguments of `offset`.
#[derive(Debug, Args)]
pub struct OffsetArgs {
    /// The OBJ mesh.
    #[arg(value_name = "MESH.obj")]
    pub input: PathBuf,
    /// The thickness c (model units, > 0).
    #[arg(long, value_name = "C")]
    pub thickness: f64,
    /// The points, one `face u v` per line, as `limit --at` reads them.
    #[arg(long, value_name = "POINTS.txt")]
    pub at: PathBuf,
    /// How `face u v` is meant (as `limit --domain`).
    #[arg(long, value_enum, value_name = "DOMAIN", default_value = "ptex")]
    pub domain: DomainArg,
    /// Append the derivatives of the offset with respect to u and v.
    #[arg(long)]
    pub derivs: bool,
    /// Side, crust level or tolerance, folds.
    #[command(flatten)]
    pub offset: OffsetFlags,
    /// Subdivision options.
    #[command(flatten)]
    pub options: SubdivFlags,
}

/// The offset flags `offset` and `shell` share.
#[derive(Debug, Clone, Args)]
pub struct OffsetFlags {
    /// Offset along the normal S_u x S_v instead of against it (inward is the default).
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

impl OffsetFlags {
    /// The offset settings of these flags and thickness `c`.
    pub fn settings(&self, thickness: f64) -> OffsetSettings {
        OffsetSettings {
            thickness,
            side: if self.outward {
                Side::Outward
            } else {
                Side::Inward
            },
            level: self.level,
            accept_folds: self.accept_folds,
        }
    }

    /// The offset of `mesh` under `options` these flags ask for; with a tolerance, the
    /// chosen level and measured thickness go to stderr.
    pub fn offset(
        &self,
        mesh: &crate::mesh::Mesh,
        options: &crate::options::SubdivOptions,
        thickness: f64,
    ) -> Result<OffsetSurface> {
        let settings = self.settings(thickness);
        match self.tolerance {
            None => OffsetSurface::new(mesh, options, settings),
            Some(t) => {
                let (offset, r) = offset_within(mesh, options, settings, t)?;
                eprintln!(
                    "level {}: thickness / c min {:.6} max {:.6} mean {:.6} at {} samples",
                    r.level, r.min, r.max, r.mean, r.samples
                );
                Ok(offset)
            }
        }
    }
}

/// Run `offset`; returns exit code 0 on success.
pub fn run(args: &OffsetArgs) -> Result<i32> {
    let mesh = read_mesh(&args.input)?;
    let options = args.options.partial().over(mesh.options()).resolve();
    let points = read_points(&args.at)?;
    let offset = args.offset.offset(&mesh, &options, args.thickness)?;
    let domain = match args.domain {
        DomainArg::Ptex => Domain::Ptex,
        DomainArg::Bfr => Domain::Bfr,
    };
    let faces: Vec<u32> = points.iter().map(|p| p.face).collect();
    let u: Vec<f64> = points.iter().map(|p| p.u).collect();
    let v: Vec<f64> = points.iter().map(|p| p.v).collect();
    let samples: Vec<Option<LimitSample>> = offset
        .evaluate_points(domain, &faces, &u, &v)?
        .into_iter()
        .map(|o| o.map(|o| o.offset()))
        .collect();
    print_samples(&samples, args.derivs)?;
    Ok(0)
}
