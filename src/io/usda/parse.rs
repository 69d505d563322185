//! The USDA reader: a tokenizer and just enough of the grammar to find the first `def Mesh`
//! prim, its attributes and metadata, and the stage's `upAxis`.

use std::path::Path;

use glam::DVec3;

use super::to_z_up;
use crate::error::{Error, Result};
use crate::io::up_axis::UpAxis;
use crate::mesh::{Corner, Crease, Mesh, MeshParts};
use crate::options::{BoundaryInterpolation, CreaseMethod, PartialOptions, TriangleSubdivision};

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    /// A word: identifier, type name, number, `a:b` namespaced name.
    Word(String),
    /// A quoted string (quotes removed).
    Str(String),
    /// `<path>` or `@asset@`.
    Path,
    /// One of `( ) [ ] { } = ,`.
    Punct(char),
}

/// Tokens with their 1-based line.
fn tokenize(text: &str, path: &Path) -> Result<Vec<(Tok, usize)>> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let (mut i, mut line) = (0, 1);
    let err = |line: usize, m: &str| Error::Parse {
        path: path.to_path_buf(),
        line,
        message: m.to_string(),
    };
    while i < b.len() {
        let c = b[i];
        match c {
            b'\n' => {
                line += 1;
                i += 1;
            }
            b'#' => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'"' | b'\'' => {
                let start_line = line;
                let triple = b[i..].starts_with(&[c, c, c]);
                let q = if triple { 3 } else { 1 };
                i += q;
                let start = i;
                loop {
                    if i >= b.len() {
                        return Err(err(start_line, "unterminated string"));
                    }
                    if b[i] == b'\\' {
                        i += 2;
                        continue;
                    }
                    if b[i] == b'\n' {
                        line += 1;
                    }
                    if b[i] == c && (!triple || b[i..].starts_with(&[c, c, c])) {
                        break;
                    }
                    i += 1;
                }
                out.push((Tok::Str(text[start..i].to_string()), start_line));
                i += q;
            }
            b'<' | b'@' => {
                let close = if c == b'<' { b'>' } else { b'@' };
                i += 1;
                while i < b.len() && b[i] != close {
                    i += 1;
                }
                i += 1;
                out.push((Tok::Path, line));
            }
            b'(' | b')' | b'[' | b']' | b'{' | b'}' | b'=' | b',' | b';' => {
                out.push((Tok::Punct(c as char), line));
                i += 1;
            }
            _ if c.is_ascii_whitespace() => i += 1,
            _ => {
                let start = i;
                while i < b.len()
                    && !b[i].is_ascii_whitespace()
                    && !b"()[]{}=,;\"'#<@".contains(&b[i])
                {
                    i += 1;
                }
                // `int[]`: the brackets belong to the type name.
                if b[i..].starts_with(b"[]") {
                    i += 2;
                }
                out.push((Tok::Word(text[start..i].to_string()), line));
            }
        }
    }
    Ok(out)
}

/// A parsed attribute value.
#[derive(Debug, Clone, PartialEq)]
enum Value {
    Word(String),
    Str(String),
    List(Vec<Value>),
    Other,
}

struct Parser<'a> {
    toks: Vec<(Tok, usize)>,
    pos: usize,
    path: &'a Path,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.pos).map(|t| &t.0)
    }

    fn line(&self) -> usize {
        self.toks
            .get(self.pos.min(self.toks.len().saturating_sub(1)))
            .map_or(0, |t| t.1)
    }

    fn err(&self, m: impl Into<String>) -> Error {
        Error::Parse {
            path: self.path.to_path_buf(),
            line: self.line(),
            message: m.into(),
        }
    }

    fn next(&mut self) -> Result<Tok> {
        let t = self
            .peek()
            .cloned()
            .ok_or_else(|| self.err("unexpected end of file"))?;
        self.pos += 1;
        Ok(t)
    }

    /// Skip a balanced group opened by the current token.
    fn skip_group(&mut self) -> Result<()> {
        let mut depth = 0i32;
        loop {
            match self.next()? {
                Tok::Punct('(' | '[' | '{') => depth += 1,
                Tok::Punct(')' | ']' | '}') => depth -= 1,
                _ => {}
            }
            if depth == 0 {
                return Ok(());
            }
        }
    }

    fn value(&mut self) -> Result<Value> {
        match self.next()? {
            Tok::Word(w) => Ok(Value::Word(w)),
            Tok::Str(s) => Ok(Value::Str(s)),
            Tok::Path => Ok(Value::Other),
            Tok::Punct(open @ ('[' | '(')) => {
                let close = if open == '[' { ']' } else { ')' };
                let mut items = Vec::new();
                loop {
                    match self.peek() {
                        Some(Tok::Punct(c)) if *c == close => {
                            self.pos += 1;
                            return Ok(Value::List(items));
                        }
                        Some(Tok::Punct(',')) => self.pos += 1,
                        _ => items.push(self.value()?),
                    }
                }
            }
            Tok::Punct('{') => {
                self.pos -= 1;
                self.skip_group()?;
                Ok(Value::Other)
            }
            t => Err(self.err(format!("unexpected {t:?}"))),
        }
    }

    /// `key = value` pairs of a metadata group `( ... )` (strings alone, like `doc`, are
    /// skipped); the current token is `(`.
    fn metadata(&mut self) -> Result<Vec<(String, Value)>> {
        self.pos += 1;
        let mut out = Vec::new();
        let mut last_word = None;
        loop {
            match self.peek() {
                None => return Err(self.err("unterminated metadata")),
                Some(Tok::Punct(')')) => {
                    self.pos += 1;
                    return Ok(out);
                }
                Some(Tok::Punct('=')) => {
                    self.pos += 1;
                    let v = self.value()?;
                    if let Some(k) = last_word.take() {
                        out.push((k, v));
                    }
                }
                Some(Tok::Word(w)) => {
                    last_word = Some(w.clone());
                    self.pos += 1;
                }
                Some(Tok::Punct('{' | '(' | '[')) => self.skip_group()?,
                _ => self.pos += 1,
            }
        }
    }
}

/// Parse USDA text (see the [module documentation](super)); `path` names the input in
/// errors.
///
/// Errors: [`Error::Parse`] for malformed text, no `def Mesh`, a left-handed mesh, a
/// subdivision scheme other than Catmull-Clark, an unknown token value or inconsistent
/// crease arrays; [`Error::InvalidMesh`] for a mesh that is not valid.
pub fn parse_usda(text: &str, path: &Path) -> Result<Mesh> {
    let mut p = Parser {
        toks: tokenize(text, path)?,
        pos: 0,
        path,
    };
    let mut up = UpAxis::Z;
    if p.peek() == Some(&Tok::Punct('(')) {
        for (k, v) in p.metadata()? {
            if k == "upAxis" {
                up = match v {
                    Value::Str(s) if s == "Z" => UpAxis::Z,
                    Value::Str(s) if s == "Y" => UpAxis::Y,
                    other => {
                        return Err(p.err(format!("upAxis {other:?}: expected \"Y\" or \"Z\"")))
                    }
                };
            }
        }
    }
    // The first `def Mesh "name"`.
    loop {
        match p.peek() {
            None => return Err(p.err("no `def Mesh` prim in the file")),
            Some(Tok::Word(w)) if w == "def" => {
                p.pos += 1;
                if p.peek() == Some(&Tok::Word("Mesh".into())) {
                    p.pos += 1;
                    break;
                }
            }
            _ => p.pos += 1,
        }
    }
    let Tok::Str(_) = p.next()? else {
        return Err(p.err("expected the prim's name after `def Mesh`"));
    };
    let mut crease_method = None;
    if p.peek() == Some(&Tok::Punct('(')) {
        // customData = { string profsubdCreaseMethod = "chaikin" } is a dictionary; look
        // for the key among its tokens.
        let start = p.pos;
        p.skip_group()?;
        let toks = &p.toks[start..p.pos];
        for w in toks.windows(3) {
            if w[0].0 == Tok::Word("profsubdCreaseMethod".into()) {
                crease_method = match &w[2].0 {
                    Tok::Str(s) if s == "chaikin" => Some(CreaseMethod::Chaikin),
                    Tok::Str(s) if s == "uniform" => Some(CreaseMethod::Uniform),
                    t => return Err(p.err(format!("profsubdCreaseMethod {t:?}"))),
                };
            }
        }
    }
    if p.next()? != Tok::Punct('{') {
        return Err(p.err("expected `{` after the mesh prim"));
    }
    let mut attrs: Vec<(String, Value, usize)> = Vec::new();
    loop {
        match p.peek() {
            None => return Err(p.err("unterminated mesh prim")),
            Some(Tok::Punct('}')) => break,
            Some(Tok::Word(w)) if w == "def" || w == "over" || w == "class" => {
                // A child prim: skip to its body and over it.
                while p.peek() != Some(&Tok::Punct('{')) {
                    if p.peek() == Some(&Tok::Punct('(')) {
                        p.skip_group()?;
                    } else {
                        p.next()?;
                    }
                }
                p.skip_group()?;
            }
            Some(Tok::Word(_)) => {
                let line = p.line();
                let mut name = String::new();
                while let Some(Tok::Word(w)) = p.peek() {
                    if p.toks[p.pos].1 != line {
                        break;
                    }
                    name = w.clone();
                    p.pos += 1;
                }
                if p.peek() == Some(&Tok::Punct('=')) {
                    p.pos += 1;
                    let v = p.value()?;
                    attrs.push((name, v, line));
                }
                if p.peek() == Some(&Tok::Punct('(')) {
                    p.skip_group()?;
                }
            }
            Some(Tok::Punct('(' | '[' | '{')) => p.skip_group()?,
            _ => p.pos += 1,
        }
    }
    build(&p, attrs, up, crease_method)
}

fn build(
    p: &Parser,
    attrs: Vec<(String, Value, usize)>,
    up: UpAxis,
    crease_method: Option<CreaseMethod>,
) -> Result<Mesh> {
    let err = |line: usize, m: String| Error::Parse {
        path: p.path.to_path_buf(),
        line,
        message: m,
    };
    let words = |v: &Value, line: usize, what: &str| -> Result<Vec<String>> {
        match v {
            Value::List(items) => items
                .iter()
                .map(|x| match x {
                    Value::Word(w) => Ok(w.clone()),
                    _ => Err(err(line, format!("{what}: expected numbers"))),
                })
                .collect(),
            _ => Err(err(line, format!("{what}: expected an array"))),
        }
    };
    let ints = |v: &Value, line: usize, what: &str| -> Result<Vec<u32>> {
        words(v, line, what)?
            .iter()
            .map(|w| {
                w.parse::<u32>()
                    .map_err(|_| err(line, format!("{what}: `{w}` is not an index")))
            })
            .collect()
    };
    let floats = |v: &Value, line: usize, what: &str| -> Result<Vec<f32>> {
        words(v, line, what)?
            .iter()
            .map(|w| {
                w.parse::<f32>()
                    .map_err(|_| err(line, format!("{what}: `{w}` is not a number")))
            })
            .collect()
    };
    let token = |v: &Value, line: usize, what: &str| -> Result<String> {
        match v {
            Value::Str(s) => Ok(s.clone()),
            _ => Err(err(line, format!("{what}: expected a quoted token"))),
        }
    };
    let mut parts = MeshParts::default();
    let mut options = PartialOptions {
        crease_method,
        ..PartialOptions::default()
    };
    let (mut crease_idx, mut crease_len, mut crease_sharp) = (Vec::new(), Vec::new(), Vec::new());
    let (mut corner_idx, mut corner_sharp) = (Vec::new(), Vec::new());
    for (name, v, line) in &attrs {
        let line = *line;
        match name.as_str() {
            "faceVertexCounts" => parts.face_sizes = ints(v, line, name)?,
            "faceVertexIndices" => parts.face_indices = ints(v, line, name)?,
            "points" => {
                let Value::List(items) = v else {
                    return Err(err(line, "points: expected an array".into()));
                };
                let mut points = Vec::with_capacity(items.len());
                for item in items {
                    let xs = floats(item, line, "points")?;
                    if xs.len() != 3 {
                        return Err(err(line, "points: expected (x, y, z) tuples".into()));
                    }
                    points.push(DVec3::new(xs[0].into(), xs[1].into(), xs[2].into()));
                }
                parts.positions = to_z_up(points, up);
            }
            "subdivisionScheme" => {
                let s = token(v, line, name)?;
                if s != "catmullClark" {
                    return Err(err(
                        line,
                        format!("subdivisionScheme \"{s}\": only \"catmullClark\" is supported"),
                    ));
                }
            }
            "orientation" => {
                let s = token(v, line, name)?;
                if s != "rightHanded" {
                    return Err(err(
                        line,
                        format!("orientation \"{s}\": only right-handed meshes are supported"),
                    ));
                }
            }
            "interpolateBoundary" => {
                options.boundary = Some(match token(v, line, name)?.as_str() {
                    "none" => BoundaryInterpolation::None,
                    "edgeOnly" => BoundaryInterpolation::EdgeOnly,
                    "edgeAndCorner" => BoundaryInterpolation::EdgeAndCorner,
                    s => return Err(err(line, format!("interpolateBoundary \"{s}\" is unknown"))),
                })
            }
            "triangleSubdivisionRule" => {
                options.triangles = Some(match token(v, line, name)?.as_str() {
                    "catmullClark" => TriangleSubdivision::Catmark,
                    "smooth" => TriangleSubdivision::Smooth,
                    s => {
                        return Err(err(
                            line,
                            format!("triangleSubdivisionRule \"{s}\" is unknown"),
                        ))
                    }
                })
            }
            "creaseIndices" => crease_idx = ints(v, line, name)?,
            "creaseLengths" => crease_len = ints(v, line, name)?,
            "creaseSharpnesses" => crease_sharp = floats(v, line, name)?,
            "cornerIndices" => corner_idx = ints(v, line, name)?,
            "cornerSharpnesses" => corner_sharp = floats(v, line, name)?,
            "holeIndices" => parts.holes = ints(v, line, name)?,
            _ => {}
        }
    }
    let line = p.line();
    let total: usize = crease_len.iter().map(|&l| l as usize).sum();
    let edges: usize = crease_len
        .iter()
        .map(|&l| (l as usize).saturating_sub(1))
        .sum();
    if total != crease_idx.len() || crease_len.iter().any(|&l| l < 2) {
        return Err(err(
            line,
            format!(
                "creaseLengths (sum {total}, each at least 2) do not match the {} creaseIndices",
                crease_idx.len()
            ),
        ));
    }
    let per_chain = crease_sharp.len() == crease_len.len();
    if !per_chain && crease_sharp.len() != edges {
        return Err(err(
            line,
            format!(
                "{} creaseSharpnesses: expected one per crease ({}) or per edge ({edges})",
                crease_sharp.len(),
                crease_len.len()
            ),
        ));
    }
    let (mut start, mut edge) = (0usize, 0usize);
    for (k, &l) in crease_len.iter().enumerate() {
        let chain = &crease_idx[start..start + l as usize];
        for w in chain.windows(2) {
            let sharpness = if per_chain {
                crease_sharp[k]
            } else {
                crease_sharp[edge]
            };
            parts.creases.push(Crease {
                vertices: [w[0], w[1]],
                sharpness,
            });
            edge += 1;
        }
        start += l as usize;
    }
    if corner_idx.len() != corner_sharp.len() {
        return Err(err(
            line,
            format!(
                "{} cornerIndices but {} cornerSharpnesses",
                corner_idx.len(),
                corner_sharp.len()
            ),
        ));
    }
    parts.corners = corner_idx
        .into_iter()
        .zip(corner_sharp)
        .map(|(vertex, sharpness)| Corner { vertex, sharpness })
        .collect();
    parts.options = options;
    Mesh::from_parts(parts)
}
