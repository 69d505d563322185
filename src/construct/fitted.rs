//! The result of every construction: the fitted control mesh, the data points it
//! interpolates, how well it met them, and its surface report against the design surface.

use std::sync::Arc;

use glam::DVec3;

use crate::construct::design::{DesignLattice, SurfaceReport};
use crate::construct::settings::Settings;
use crate::control::Control;
use crate::error::{Error, Result};
use crate::eval::folds::construction_folds;
use crate::eval::Evaluator;
use crate::fit::{fit_cage, FitOptions, FitReport, FittedCage, Role};
use crate::mesh::{Mesh, MeshParts};

/// Folded faces named in a refusal's message; the count says how many there are in all.
const MAX_LISTED: usize = 12;

/// A fitted construction: a control mesh whose vertices' exact limit positions are the data
/// points.
#[derive(Debug, Clone)]
pub struct Fitted {
    /// The control mesh: quads, crease and corner tags, the fit's subdivision options as
    /// option tags. Shared (`Arc`) with the handles that hand it out.
    pub mesh: Arc<Mesh>,
    /// The data point of each vertex, in vertex order: its limit position.
    pub targets: Vec<DVec3>,
    /// The achieved fit residual and its tolerance.
    pub fit: FitReport,
    /// The design surface on every face's lattice ([`crate::construct::design`]).
    pub design: DesignLattice,
}

impl Fitted {
    /// Fit `parts` (each vertex at its data point) under the settings' subdivision options,
    /// which the mesh also gets as option tags: the exact limit surface then passes through
    /// every data point, to 1e-10 × their diagonal. `design` is the design surface on the
    /// faces' lattice.
    ///
    /// The settings' [`crate::Control`] is polled at every stage (mesh check, stencils,
    /// each solver iteration) and its memory budget checked before the fit allocates: a
    /// construction that ends here is cancellable and bounded with no code of its own.
    ///
    /// Errors: [`crate::Error::InvalidArgument`] for a cage that is not a valid mesh or whose
    /// data points no limit surface reaches (boundary interpolation *none* at an open
    /// boundary); [`crate::Error::NumericalFailure`] if the fit misses its tolerance or is
    /// ill-conditioned; [`crate::Error::Cancelled`], [`crate::Error::LimitExceeded`] from
    /// the control.
    pub fn fit(parts: MeshParts, settings: &Settings, design: DesignLattice) -> Result<Fitted> {
        Fitted::fit_free(parts, settings, design, &[])
    }

    /// [`Fitted::fit`], except for the vertices whose `roles` (empty: none) are not
    /// [`Role::Interpolate`]: they are not data points, and their limit positions become
    /// their targets. [`Role::Keep`]: no data constrain the surface there (inside a flat
    /// cap, whose creased rim carries its shape), so they keep their cage positions as
    /// control points (an interpolating fit would bend the cap to pass through them,
    /// overshooting in-plane where the layout's cells change size). [`Role::Fair`]: their
    /// control points minimise the net's bending energy ([`crate::fit::bending`]).
    pub(crate) fn fit_free(
        parts: MeshParts,
        settings: &Settings,
        design: DesignLattice,
        roles: &[Role],
    ) -> Result<Fitted> {
        Fitted::fit_with(
            parts,
            settings.fit_options(),
            &settings.control,
            design,
            roles,
        )
    }

    /// [`Fitted::fit_free`] under explicit fit options and control instead of a
    /// construction's [`Settings`]: for a construction whose subdivision options come from
    /// its input (the shell fits under the input mesh's tags).
    pub(crate) fn fit_with(
        parts: MeshParts,
        options: FitOptions,
        control: &Control,
        design: DesignLattice,
        roles: &[Role],
    ) -> Result<Fitted> {
        let FittedCage { mesh, targets, fit } = fit_cage(parts, options, roles, control)?;
        Ok(Fitted {
            mesh: Arc::new(mesh),
            targets,
            fit,
            design,
        })
    }

    /// Distance to the design surface between the data points, folds and undulation of the
    /// fitted limit surface ([`crate::construct::design::surface_report`]), computed on the
    /// first call. Errors: those of the evaluation.
    pub fn surface_report(&self) -> Result<&SurfaceReport> {
        self.design.report(&self.mesh)
    }

    /// [`Fitted::surface_report`] polling `control` while it is computed (a construction's
    /// own fold checks: cancellable like the rest of the call).
    pub(crate) fn surface_report_with(&self, control: &Control) -> Result<&SurfaceReport> {
        self.design.report_with(&self.mesh, control)
    }

    /// `self` if its limit surface does not fold ([`Fitted::surface_report`]); otherwise an
    /// [`Error::InvalidArgument`] naming `what`, the folded face count, the folded faces and
    /// where the worst reversal lies, then `hint` (what to change): a construction whose
    /// layout is not known to be fold-free for every input refuses rather than return a
    /// folded surface. Errors: those of the evaluation.
    /// `control` is polled while the report is computed ([`DesignLattice::report_with`]).
    pub(crate) fn refuse_folds(self, what: &str, hint: &str, control: &Control) -> Result<Fitted> {
        let folded = self.surface_report_with(control)?.folded_faces;
        if folded == 0 {
            return Ok(self);
        }
        // Only on refusal: which faces and where the worst reversal is, for the message.
        let poll = control.stage(1.0, 1.0);
        let ev = Evaluator::with_control(&self.mesh, &self.mesh.options().resolve(), &poll)?;
        let folds = construction_folds(&ev, control)?;
        let (face, u, v) = folds.worst_at.unwrap_or((0, 0.5, 0.5));
        let p = ev.evaluate(face as u32, u, v)?.position;
        let faces = folds.folded_face_indices();
        let mut list: Vec<String> = faces
            .iter()
            .take(MAX_LISTED)
            .map(usize::to_string)
            .collect();
        if faces.len() > MAX_LISTED {
            list.push("...".to_string());
        }
        Err(Error::invalid_argument(format!(
            "{what}: the fitted limit surface would fold in {folded} faces ({}; worst normal \
             reversal {:.0}° in face {face}, near ({:.6}, {:.6}, {:.6})); refused rather than \
             returned folded (the fold check of profsubd check --surface); {hint}",
            list.join(", "),
            folds.worst_reversal_deg,
            p.x,
            p.y,
            p.z
        )))
    }
}
