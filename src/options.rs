//! Subdivision options, as OpenSubdiv's `Sdc::Options` for the Catmark scheme.
//!
//! Precedence everywhere: an explicit option given by the caller overrides a tag carried by
//! the mesh file, which overrides the default. Defaults are USD's: boundary interpolation
//! edge-and-corner, uniform creasing, Catmark triangle rule.

/// How boundary edges and vertices are treated (`Sdc::Options::VtxBoundaryInterpolation`).
/// In JSON inputs: `"none"`, `"edge-only"`, `"edge-and-corner"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum BoundaryInterpolation {
    /// No boundary interpolation: faces on the boundary have no limit surface
    /// (`VTX_BOUNDARY_NONE`, OBJ tag value 0).
    None,
    /// Boundary edges are infinitely sharp creases (`VTX_BOUNDARY_EDGE_ONLY`, OBJ tag value 2).
    EdgeOnly,
    /// Boundary edges are sharp and boundary vertices with one face are sharp corners
    /// (`VTX_BOUNDARY_EDGE_AND_CORNER`, OBJ tag value 1). The default.
    #[default]
    EdgeAndCorner,
}

impl BoundaryInterpolation {
    /// Every rule, in OpenSubdiv's enum order: for code and tests that try each.
    ///
    /// ```
    /// use profsubd::BoundaryInterpolation;
    /// assert_eq!(BoundaryInterpolation::ALL.len(), 3);
    /// assert_eq!(BoundaryInterpolation::ALL[2], BoundaryInterpolation::default());
    /// ```
    pub const ALL: [BoundaryInterpolation; 3] = [
        BoundaryInterpolation::None,
        BoundaryInterpolation::EdgeOnly,
        BoundaryInterpolation::EdgeAndCorner,
    ];
}

/// How semi-sharp crease sharpness decays (`Sdc::Options::CreasingMethod`).
/// In JSON inputs: `"uniform"`, `"chaikin"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum CreaseMethod {
    /// Sharpness decreases by 1 per level (`CREASE_UNIFORM`, OBJ `normal`). The default.
    #[default]
    Uniform,
    /// Chaikin's rule: child sharpness averages neighbouring crease sharpness (`CREASE_CHAIKIN`).
    Chaikin,
}

/// Rule for triangles (`Sdc::Options::TriangleSubdivision`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum TriangleSubdivision {
    /// Plain Catmull-Clark face/edge/vertex points (`TRI_SUB_CATMARK`). The default.
    #[default]
    Catmark,
    /// Loop-like weights for triangles to reduce artefacts (`TRI_SUB_SMOOTH`).
    Smooth,
}

/// A complete set of options, every field resolved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct SubdivOptions {
    /// Boundary interpolation rule.
    pub boundary: BoundaryInterpolation,
    /// Crease decay rule.
    pub crease_method: CreaseMethod,
    /// Triangle rule.
    pub triangles: TriangleSubdivision,
}

/// Options that may or may not be set: what a mesh file's tags or a caller specify.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct PartialOptions {
    /// Boundary interpolation, if specified.
    pub boundary: Option<BoundaryInterpolation>,
    /// Crease method, if specified.
    pub crease_method: Option<CreaseMethod>,
    /// Triangle rule, if specified.
    pub triangles: Option<TriangleSubdivision>,
}

impl PartialOptions {
    /// Fields set in `self` win over those in `lower`.
    pub fn over(self, lower: PartialOptions) -> PartialOptions {
        PartialOptions {
            boundary: self.boundary.or(lower.boundary),
            crease_method: self.crease_method.or(lower.crease_method),
            triangles: self.triangles.or(lower.triangles),
        }
    }

    /// Fill unset fields with the defaults.
    pub fn resolve(self) -> SubdivOptions {
        let d = SubdivOptions::default();
        SubdivOptions {
            boundary: self.boundary.unwrap_or(d.boundary),
            crease_method: self.crease_method.unwrap_or(d.crease_method),
            triangles: self.triangles.unwrap_or(d.triangles),
        }
    }
}
