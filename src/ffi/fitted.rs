//! The accessors shared by the C result objects of fitted constructions
//! (`profsubd_profile`, `profsubd_swept`): fitted mesh, data points, fit residual. Each C
//! function is a one-line call into these.

use glam::DVec3;

use crate::construct::design::SurfaceReport;
use crate::construct::profile::ProfileModel;
use crate::construct::sweep::SweptSurface;
use crate::error::Result;
use crate::ffi::handle::{self, Handle};
use crate::ffi::mesh::{new_mesh_handle, profsubd_mesh};
use crate::ffi::panic::status_call;
use crate::ffi::ptr::{arg_out, arg_out_opt, copy_slice};
use crate::ffi::status::profsubd_status;
use crate::fit::FitReport;
use crate::mesh::Mesh;

/// A fitted model: a control mesh whose vertices' limit positions are the data points.
pub trait Fitted {
    /// The fitted control mesh.
    fn mesh(&self) -> &Mesh;
    /// The data point of each control vertex, in vertex order.
    fn targets(&self) -> &[DVec3];
    /// The achieved residual and its tolerance.
    fn fit(&self) -> &FitReport;
    /// Distance to the design surface, folds, undulation (computed on the first call).
    fn surface_report(&self) -> Result<&SurfaceReport>;
}

/// Both constructions' results hold the three as fields of the same names.
macro_rules! fitted_fields {
    ($($t:ty),*) => {$(
        impl Fitted for $t {
            fn mesh(&self) -> &Mesh {
                &self.mesh
            }
            fn targets(&self) -> &[DVec3] {
                &self.targets
            }
            fn fit(&self) -> &FitReport {
                &self.fit
            }
            fn surface_report(&self) -> Result<&SurfaceReport> {
                <$t>::surface_report(self)
            }
        }
    )*};
}

fitted_fields!(ProfileModel, SweptSurface);

/// `*out` = a new mesh handle with a copy of the fitted mesh behind `model` (named `name`).
pub unsafe fn get_mesh<H: Handle>(
    model: *const H,
    name: &str,
    out: *mut *mut profsubd_mesh,
) -> profsubd_status
where
    H::Inner: Fitted,
{
    status_call(|| {
        let out = arg_out(out, "out")?;
        out.write(new_mesh_handle(handle::borrow(model, name)?.mesh().clone()));
        Ok(())
    })
}

/// Copy out the data points, 3 doubles each (copy-out protocol in doubles).
pub unsafe fn get_targets<H: Handle>(
    model: *const H,
    name: &str,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> profsubd_status
where
    H::Inner: Fitted,
{
    copy_slice(
        (model, name),
        (out, "out", capacity, needed),
        (1, "doubles"),
        |m| {
            let targets = m.targets();
            Ok((3 * targets.len(), targets.iter().flat_map(|t| t.to_array())))
        },
    )
}

/// Write the fit's residual and tolerance to the outputs that are not NULL.
pub unsafe fn get_fit_residual<H: Handle>(
    model: *const H,
    name: &str,
    residual: *mut f64,
    tolerance: *mut f64,
) -> profsubd_status
where
    H::Inner: Fitted,
{
    status_call(|| {
        let fit = handle::borrow(model, name)?.fit();
        let (r, t) = (
            arg_out_opt(residual, "residual")?,
            arg_out_opt(tolerance, "tolerance")?,
        );
        if let Some(r) = r {
            r.write(fit.residual);
        }
        if let Some(t) = t {
            t.write(fit.tolerance);
        }
        Ok(())
    })
}

/// Write the largest and mean distance from the limit surface to the design surface (over
/// the bounding-box diagonal) to the outputs that are not NULL.
pub unsafe fn get_design_distance<H: Handle>(
    model: *const H,
    name: &str,
    max: *mut f64,
    mean: *mut f64,
) -> profsubd_status
where
    H::Inner: Fitted,
{
    status_call(|| {
        let model = handle::borrow(model, name)?;
        let (max, mean) = (arg_out_opt(max, "max")?, arg_out_opt(mean, "mean")?);
        let report = model.surface_report()?;
        if let Some(m) = max {
            m.write(report.max_design_distance);
        }
        if let Some(m) = mean {
            m.write(report.mean_design_distance);
        }
        Ok(())
    })
}

/// Write the number of folded faces, the worst normal reversal (degrees) and the undulation
/// (bending energy over the design surface's) to the outputs that are not NULL.
pub unsafe fn get_surface_quality<H: Handle>(
    model: *const H,
    name: &str,
    folded_faces: *mut usize,
    worst_reversal_deg: *mut f64,
    undulation: *mut f64,
) -> profsubd_status
where
    H::Inner: Fitted,
{
    status_call(|| {
        let model = handle::borrow(model, name)?;
        let (folded, worst, und) = (
            arg_out_opt(folded_faces, "folded_faces")?,
            arg_out_opt(worst_reversal_deg, "worst_reversal_deg")?,
            arg_out_opt(undulation, "undulation")?,
        );
        let report = model.surface_report()?;
        if let Some(o) = folded {
            o.write(report.folded_faces);
        }
        if let Some(o) = worst {
            o.write(report.worst_reversal_deg);
        }
        if let Some(o) = und {
            o.write(report.undulation);
        }
        Ok(())
    })
}
