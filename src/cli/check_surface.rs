//! The `--surface` part of `profsubd check`: folds of the limit surface
//! ([`crate::eval::folds`]), as text lines and as a JSON object.

use std::fmt::Write;

use crate::error::Result;
use crate::eval::folds::{find_folds, FoldReport, FoldSettings};
use crate::eval::Evaluator;
use crate::mesh::Mesh;
use crate::options::SubdivOptions;

/// Exit code of `check --surface` when the limit surface folds.
pub const EXIT_FOLDED: i32 = 3;

/// How many folded faces the text lists before it says "...".
const LISTED: usize = 8;

/// Check the limit surface of `mesh` under `options` for folds.
pub fn check(mesh: &Mesh, options: &SubdivOptions, settings: &FoldSettings) -> Result<FoldReport> {
    find_folds(&Evaluator::new(mesh, options)?, settings)
}

/// The text lines of the fold report.
pub fn format_folds(r: &FoldReport, settings: &FoldSettings) -> String {
    let mut out = String::new();
    let mut line = |name: &str, value: String| {
        let _ = writeln!(out, "{name}: {value}");
    };
    line(
        "surface samples",
        format!(
            "{} on {} parametric faces ({} per edge, adaptive depth {})",
            r.samples, r.faces_checked, settings.samples_per_edge, settings.adaptive_depth
        ),
    );
    let faces = r.folded_face_indices();
    let shown: Vec<String> = faces.iter().take(LISTED).map(usize::to_string).collect();
    let more = if faces.len() > LISTED { " ..." } else { "" };
    line(
        "folded faces",
        if faces.is_empty() {
            "0".to_string()
        } else {
            format!("{} [{}{more}]", faces.len(), shown.join(" "))
        },
    );
    if let Some((face, u, v)) = r.worst_at {
        line(
            "worst normal turn from face mean",
            format!(
                "{:.3} deg at parametric face {face} (u {u}, v {v})",
                r.worst_reversal_deg
            ),
        );
    }
    line(
        "min relative jacobian",
        format!("{:.6}", r.min_relative_jacobian),
    );
    line(
        "surface",
        if r.is_fold_free() {
            "fold-free".to_string()
        } else {
            format!("folds ({} faces)", faces.len())
        },
    );
    out
}

/// The fold report as JSON (full lists).
pub fn json_folds(r: &FoldReport, settings: &FoldSettings) -> serde_json::Value {
    serde_json::json!({
        "fold_free": r.is_fold_free(),
        "folded_face_indices": r.folded_face_indices(),
        "folded_faces": r.folded_faces,
        "worst_reversal_deg": r.worst_reversal_deg,
        "worst_at": r.worst_at.map(|(face, u, v)| serde_json::json!({"face": face, "u": u, "v": v})),
        "min_relative_jacobian": r.min_relative_jacobian,
        "faces_checked": r.faces_checked,
        "samples": r.samples,
        "samples_per_edge": settings.samples_per_edge,
        "adaptive_depth": settings.adaptive_depth,
    })
}
