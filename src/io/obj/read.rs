//! The OBJ reader: one pass over the lines, then the checks that need the whole file
//! (indices in range, creases on edges), reported at the line that caused them.

use std::collections::HashSet;
use std::path::Path;

use glam::DVec3;

use super::ObjRead;
use crate::error::{Error, Result};
use crate::mesh::{Corner, Crease, Mesh, MeshParts};
use crate::options::{BoundaryInterpolation, CreaseMethod, TriangleSubdivision};

/// Parse OBJ text; `path` is used only in messages. See the [module documentation](super).
///
/// Errors: [`Error::Parse`] (file, line, what was expected) for a malformed line, an index
/// out of range or a crease on a vertex pair no face joins; [`Error::InvalidMesh`] (prefixed
/// with the file) for a file without faces.
pub fn parse_obj(text: &str, path: &Path) -> Result<ObjRead> {
    let mut reader = Reader::new(path);
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    for (i, line) in text.lines().enumerate() {
        reader.line(i + 1, line)?;
    }
    reader.finish()
}

/// Tags whose effect is on face-varying data only: OpenSubdiv ignores them for vertex data.
const FACE_VARYING_TAGS: [&str; 2] = [
    "facevaryinginterpolateboundary",
    "facevaryingpropagatecorners",
];
/// Hierarchical edits: not supported by OpenSubdiv 3.
const EDIT_TAGS: [&str; 3] = ["vertexedit", "edgeedit", "faceedit"];
/// Statements that carry nothing for the control mesh.
const IGNORED_STATEMENTS: [&str; 7] = ["vt", "vn", "g", "o", "s", "usemtl", "mtllib"];

/// The arguments of a `t` line after its `ni/nf/ns` counts.
struct TagArgs<'a> {
    ints: Vec<u32>,
    floats: Vec<f32>,
    strings: Vec<&'a str>,
}

struct Reader<'a> {
    path: &'a Path,
    parts: MeshParts,
    warnings: Vec<String>,
    /// Source line of each face, crease, corner and hole, for errors found at the end.
    face_lines: Vec<usize>,
    crease_lines: Vec<usize>,
    corner_lines: Vec<usize>,
    hole_lines: Vec<usize>,
    /// Line of the last `interpolateboundary`, `creasemethod`, `smoothtriangles` tag.
    option_lines: [Option<usize>; 3],
}

impl<'a> Reader<'a> {
    fn new(path: &'a Path) -> Self {
        Reader {
            path,
            parts: MeshParts::default(),
            warnings: Vec::new(),
            face_lines: Vec::new(),
            crease_lines: Vec::new(),
            corner_lines: Vec::new(),
            hole_lines: Vec::new(),
            option_lines: [None; 3],
        }
    }

    fn error(&self, line: usize, message: impl Into<String>) -> Error {
        Error::Parse {
            path: self.path.to_path_buf(),
            line,
            message: message.into(),
        }
    }

    fn warn(&mut self, line: usize, message: impl AsRef<str>) {
        self.warnings.push(format!(
            "{}:{line}: {}",
            self.path.display(),
            message.as_ref()
        ));
    }

    fn line(&mut self, n: usize, line: &str) -> Result<()> {
        let content = line.split('#').next().unwrap_or("");
        let mut tokens = content.split_whitespace();
        let Some(keyword) = tokens.next() else {
            return Ok(());
        };
        let args: Vec<&str> = tokens.collect();
        match keyword {
            "v" => self.vertex(n, &args),
            "f" => self.face(n, &args),
            "t" => self.tag(n, &args),
            k if IGNORED_STATEMENTS.contains(&k) => Ok(()),
            k => {
                self.warn(n, format!("ignored unknown statement `{k}`"));
                Ok(())
            }
        }
    }

    fn vertex(&mut self, n: usize, args: &[&str]) -> Result<()> {
        if args.len() != 3 && args.len() != 4 {
            return Err(self.error(
                n,
                format!(
                    "expected `v x y z` (3 coordinates, optional w), found {} values",
                    args.len()
                ),
            ));
        }
        let mut xyz = [0.0; 3];
        for (c, tok) in xyz.iter_mut().zip(args) {
            *c = match tok.parse::<f64>() {
                Ok(x) if x.is_finite() => x,
                _ => {
                    return Err(self.error(
                        n,
                        format!("expected a finite vertex coordinate, found `{tok}`"),
                    ))
                }
            };
        }
        self.parts.positions.push(DVec3::from_array(xyz));
        Ok(())
    }

    fn face(&mut self, n: usize, args: &[&str]) -> Result<()> {
        if args.len() < 3 {
            return Err(self.error(
                n,
                format!(
                    "expected a face with at least 3 vertex indices, found {}",
                    args.len()
                ),
            ));
        }
        let read_so_far = self.parts.positions.len() as i64;
        for tok in args {
            let vertex = tok.split('/').next().unwrap_or("");
            let index = match vertex.parse::<i64>() {
                Ok(i) if i > 0 => i - 1,
                Ok(i) if i < 0 && read_so_far + i >= 0 => read_so_far + i,
                Ok(i) if i < 0 => {
                    return Err(self.error(
                        n,
                        format!(
                            "relative vertex index {i} reaches before the first vertex \
                             ({read_so_far} read so far)"
                        ),
                    ))
                }
                _ => {
                    return Err(self.error(
                        n,
                        format!(
                            "expected a vertex index (1-based, or negative to count back), \
                             found `{tok}`"
                        ),
                    ))
                }
            };
            let index = u32::try_from(index)
                .map_err(|_| self.error(n, format!("vertex index `{tok}` is too large")))?;
            self.parts.face_indices.push(index);
        }
        self.parts.face_sizes.push(args.len() as u32);
        self.face_lines.push(n);
        Ok(())
    }

    fn tag(&mut self, n: usize, args: &[&str]) -> Result<()> {
        let Some(&name) = args.first() else {
            return Err(self.error(n, "expected a tag name after `t`"));
        };
        if FACE_VARYING_TAGS.contains(&name) {
            self.warn(
                n,
                format!("ignored face-varying tag `{name}` (no effect on vertex data)"),
            );
            return Ok(());
        }
        if EDIT_TAGS.contains(&name) {
            self.warn(
                n,
                format!(
                    "ignored hierarchical edit `{name}` (not supported by OpenSubdiv 3 either)"
                ),
            );
            return Ok(());
        }
        if !matches!(
            name,
            "crease"
                | "corner"
                | "hole"
                | "interpolateboundary"
                | "creasemethod"
                | "smoothtriangles"
        ) {
            self.warn(n, format!("ignored unknown tag `{name}`"));
            return Ok(());
        }
        let tag = self.tag_args(n, name, &args[1..])?;
        let counts = (tag.ints.len(), tag.floats.len(), tag.strings.len());
        match name {
            "crease" => self.crease(n, tag),
            "corner" => self.corner(n, tag),
            "hole" => {
                if counts.1 != 0 || counts.2 != 0 {
                    return Err(self.error(n, "expected `t hole n/0/0 f1 .. fn`"));
                }
                self.hole_lines
                    .extend(std::iter::repeat(n).take(tag.ints.len()));
                self.parts.holes.extend(tag.ints);
                Ok(())
            }
            "interpolateboundary" => {
                let value = match (counts, tag.ints.first()) {
                    ((1, 0, 0), Some(0)) => BoundaryInterpolation::None,
                    ((1, 0, 0), Some(1)) => BoundaryInterpolation::EdgeAndCorner,
                    ((1, 0, 0), Some(2)) => BoundaryInterpolation::EdgeOnly,
                    _ => {
                        return Err(self.error(
                            n,
                            "expected `t interpolateboundary 1/0/0 B` with B = 0 (none), \
                             1 (edge and corner) or 2 (edge only)",
                        ))
                    }
                };
                self.option_line(n, 0, name);
                self.parts.options.boundary = Some(value);
                Ok(())
            }
            "creasemethod" => {
                let value = match (counts, tag.strings.first()) {
                    ((0, 0, 1), Some(&"normal")) => CreaseMethod::Uniform,
                    ((0, 0, 1), Some(&"chaikin")) => CreaseMethod::Chaikin,
                    _ => {
                        return Err(self.error(n, "expected `t creasemethod 0/0/1 normal|chaikin`"))
                    }
                };
                self.option_line(n, 1, name);
                self.parts.options.crease_method = Some(value);
                Ok(())
            }
            _ => {
                let value = match (counts, tag.strings.first()) {
                    ((0, 0, 1), Some(&"catmark")) => TriangleSubdivision::Catmark,
                    ((0, 0, 1), Some(&"smooth")) => TriangleSubdivision::Smooth,
                    _ => {
                        return Err(
                            self.error(n, "expected `t smoothtriangles 0/0/1 catmark|smooth`")
                        )
                    }
                };
                self.option_line(n, 2, name);
                self.parts.options.triangles = Some(value);
                Ok(())
            }
        }
    }

    /// Note that option tag `slot` was set on line `n`, warning if it overrides an earlier one.
    fn option_line(&mut self, n: usize, slot: usize, name: &str) {
        if let Some(earlier) = self.option_lines[slot].replace(n) {
            self.warn(
                n,
                format!("`{name}` tag overrides the one on line {earlier}"),
            );
        }
    }

    /// Parse `ni/nf/ns` and exactly that many integers, floats and strings.
    fn tag_args<'t>(&mut self, n: usize, name: &str, args: &[&'t str]) -> Result<TagArgs<'t>> {
        let counts: Option<Vec<usize>> = args
            .first()
            .map(|c| c.split('/').map(|x| x.parse::<usize>().ok()).collect())
            .unwrap_or_default();
        let (ni, nf, ns) = match counts.as_deref() {
            Some(&[ni, nf, ns]) => (ni, nf, ns),
            _ => {
                return Err(self.error(
                    n,
                    format!(
                    "expected argument counts `ints/floats/strings` after `t {name}`, found `{}`",
                    args.first().copied().unwrap_or("")
                ),
                ))
            }
        };
        let values = &args[1..];
        if values.len() != ni.saturating_add(nf).saturating_add(ns) {
            return Err(self.error(
                n,
                format!(
                    "tag `{name}` announces {ni}/{nf}/{ns} arguments but has {} values",
                    values.len()
                ),
            ));
        }
        let mut ints = Vec::with_capacity(ni);
        for tok in &values[..ni] {
            match tok.parse::<u32>() {
                Ok(i) => ints.push(i),
                Err(_) => {
                    return Err(self.error(
                        n,
                        format!("expected a 0-based index in tag `{name}`, found `{tok}`"),
                    ))
                }
            }
        }
        let mut floats = Vec::with_capacity(nf);
        for tok in &values[ni..ni + nf] {
            match tok.parse::<f32>() {
                Ok(s) if !s.is_nan() && s < 0.0 => {
                    self.warn(
                        n,
                        format!("negative sharpness {tok} in tag `{name}` clamped to 0"),
                    );
                    floats.push(0.0);
                }
                Ok(s) if !s.is_nan() => floats.push(s),
                _ => {
                    return Err(self.error(
                        n,
                        format!("expected a sharpness number in tag `{name}`, found `{tok}`"),
                    ))
                }
            }
        }
        Ok(TagArgs {
            ints,
            floats,
            strings: values[ni + nf..].to_vec(),
        })
    }

    fn crease(&mut self, n: usize, tag: TagArgs) -> Result<()> {
        let edges = tag.ints.len() / 2;
        let well_formed = !tag.ints.is_empty()
            && tag.ints.len() % 2 == 0
            && (tag.floats.len() == 1 || tag.floats.len() == edges)
            && tag.strings.is_empty();
        if !well_formed {
            return Err(self.error(
                n,
                format!(
                    "expected `t crease 2/1/0 v0 v1 s`, `2k/1/0` (k edges, one sharpness) or \
                     `2k/k/0` (one sharpness per edge), found {}/{}/{}",
                    tag.ints.len(),
                    tag.floats.len(),
                    tag.strings.len()
                ),
            ));
        }
        for (k, pair) in tag.ints.chunks_exact(2).enumerate() {
            let sharpness = tag.floats[if tag.floats.len() == 1 { 0 } else { k }];
            self.parts.creases.push(Crease {
                vertices: [pair[0], pair[1]],
                sharpness,
            });
            self.crease_lines.push(n);
        }
        Ok(())
    }

    fn corner(&mut self, n: usize, tag: TagArgs) -> Result<()> {
        let well_formed = !tag.ints.is_empty()
            && (tag.floats.len() == 1 || tag.floats.len() == tag.ints.len())
            && tag.strings.is_empty();
        if !well_formed {
            return Err(self.error(
                n,
                format!(
                    "expected `t corner n/1/0 v1 .. vn s` or `n/n/0 v1 .. vn s1 .. sn`, found {}/{}/{}",
                    tag.ints.len(),
                    tag.floats.len(),
                    tag.strings.len()
                ),
            ));
        }
        for (k, &vertex) in tag.ints.iter().enumerate() {
            let sharpness = tag.floats[if tag.floats.len() == 1 { 0 } else { k }];
            self.parts.corners.push(Corner { vertex, sharpness });
            self.corner_lines.push(n);
        }
        Ok(())
    }

    /// Checks that need the whole file, then the mesh's own validation.
    fn finish(self) -> Result<ObjRead> {
        let nv = self.parts.positions.len();
        let nf = self.parts.face_sizes.len();
        let mut start = 0;
        for (f, &size) in self.parts.face_sizes.iter().enumerate() {
            let face = &self.parts.face_indices[start..start + size as usize];
            if let Some(&v) = face.iter().find(|&&v| v as usize >= nv) {
                return Err(self.error(
                    self.face_lines[f],
                    format!(
                        "face refers to vertex {} but the file has {nv} vertices",
                        v as u64 + 1
                    ),
                ));
            }
            start += size as usize;
        }
        for (c, &line) in self.parts.corners.iter().zip(&self.corner_lines) {
            if c.vertex as usize >= nv {
                return Err(self.error(
                    line,
                    format!(
                        "corner on vertex {} (0-based) but the file has {nv} vertices",
                        c.vertex
                    ),
                ));
            }
        }
        for (&h, &line) in self.parts.holes.iter().zip(&self.hole_lines) {
            if h as usize >= nf {
                return Err(self.error(
                    line,
                    format!("hole on face {h} (0-based) but the file has {nf} faces"),
                ));
            }
        }
        self.check_crease_edges()?;
        let path = self.path.display().to_string();
        let mesh = Mesh::from_parts(self.parts).map_err(|e| match e {
            Error::InvalidMesh(m) => Error::InvalidMesh(format!("{path}: {m}")),
            other => other,
        })?;
        Ok(ObjRead {
            mesh,
            warnings: self.warnings,
        })
    }

    /// Each crease must name two vertices that some face has as neighbours.
    fn check_crease_edges(&self) -> Result<()> {
        if self.parts.creases.is_empty() {
            return Ok(());
        }
        let nv = self.parts.positions.len();
        let mut joined = HashSet::new();
        let mut start = 0;
        for &size in &self.parts.face_sizes {
            let face = &self.parts.face_indices[start..start + size as usize];
            let next = face.iter().cycle().skip(1);
            joined.extend(face.iter().zip(next).map(|(&a, &b)| (a.min(b), a.max(b))));
            start += size as usize;
        }
        for (c, &line) in self.parts.creases.iter().zip(&self.crease_lines) {
            let [a, b] = c.vertices;
            if a as usize >= nv || b as usize >= nv {
                return Err(self.error(
                    line,
                    format!("crease on vertices {a} {b} (0-based) but the file has {nv} vertices"),
                ));
            }
            if !joined.contains(&(a.min(b), a.max(b))) {
                return Err(self.error(
                    line,
                    format!("crease on vertices {a} {b} (0-based), which no face joins by an edge"),
                ));
            }
        }
        Ok(())
    }
}
