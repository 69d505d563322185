//! `profsubd limit MESH.obj [--at POINTS.txt [--domain ptex|bfr]] [--derivs] [--strict]`:
//! exact limit positions (and first derivatives) at the control vertices or at given
//! `(face, u, v)` points.
//!
//! Output: one line per vertex (vertex order) or per point (file order): `x y z`, with
//! `--derivs` followed by `dux duy duz dvx dvy dvz`. Numbers are printed as C's `%.17g`
//! would choose between plain and exponent notation, but with the fewest digits that read
//! back to the same double (so `0.1`, not `0.10000000000000001`). A vertex or point without
//! limit surface (see [`crate::eval::surface`]) prints `nan` for every number, as
//! OpenSubdiv-based tools print it; `--strict` makes it an error instead.

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};

use clap::{Args, ValueEnum};

use super::{read_mesh, SubdivFlags, ThreadsFlag};
use crate::error::{Error, Result};
use crate::eval::{limit_vertex_samples, require_surface, Domain, Evaluator, LimitSample};

/// Arguments of `limit`.
#[derive(Debug, Args)]
pub struct LimitArgs {
    /// The OBJ mesh.
    #[arg(value_name = "MESH.obj")]
    pub input: PathBuf,
    /// Evaluate at the points of this file, one `face u v` per line (`#` comments and blank
    /// lines allowed), in the parameterization given by --domain.
    #[arg(long, value_name = "POINTS.txt")]
    pub at: Option<PathBuf>,
    /// How `face u v` is meant. `ptex` (OpenSubdiv's Far::PtexIndices): on a mesh of quads
    /// the face index, a face with N != 4 vertices counts as N faces, one per corner, u and
    /// v in [0, 1]. `bfr` (Bfr::Parameterization): the control face; a quad has u, v in
    /// [0, 1], any other face N sub-faces of side 1/2 tiled in ceil(sqrt(N)) columns.
    /// Derivatives are in the chosen domain's units.
    #[arg(
        long,
        value_enum,
        value_name = "DOMAIN",
        default_value = "ptex",
        requires = "at"
    )]
    pub domain: DomainArg,
    /// Append the derivatives with respect to u and v (`dux duy duz dvx dvy dvz`).
    #[arg(long)]
    pub derivs: bool,
    /// Fail (exit 1, naming it) at a vertex or point without limit surface instead of
    /// printing `nan` for it.
    #[arg(long)]
    pub strict: bool,
    /// Subdivision options.
    #[command(flatten)]
    pub options: SubdivFlags,
    /// Threads.
    #[command(flatten)]
    pub threads: ThreadsFlag,
}

/// `--domain` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum DomainArg {
    /// OpenSubdiv's Ptex faces (Far::PtexIndices, Far::PatchMap).
    Ptex,
    /// Bfr's base faces with their tiled sub-face domain (Bfr::Parameterization).
    Bfr,
}

/// Run `limit`; returns exit code 0 on success.
pub fn run(args: &LimitArgs) -> Result<i32> {
    let mesh = read_mesh(&args.input)?;
    let options = args.options.partial().over(mesh.options()).resolve();
    let samples: Vec<Option<LimitSample>> = match &args.at {
        None => limit_vertex_samples(&mesh, &options)?
            .into_iter()
            .map(|s| s.has_surface().then_some(s))
            .collect(),
        Some(path) => {
            let domain = match args.domain {
                DomainArg::Ptex => Domain::Ptex,
                DomainArg::Bfr => Domain::Bfr,
            };
            let points = read_points(path)?;
            let control = super::progress::control("building the evaluator");
            let ev = Evaluator::build_on(&mesh, &options, args.threads.threads, &control)?;
            let mut out = Vec::with_capacity(points.len());
            for p in &points {
                let at = |message: String| Error::Parse {
                    path: path.clone(),
                    line: p.line,
                    message,
                };
                let s = ev
                    .evaluate_in(domain, p.face, p.u, p.v)
                    .map_err(|e| at(e.to_string()))?;
                if s.is_none() && args.strict {
                    return Err(at(format!(
                        "face {} has no limit surface (--strict)",
                        p.face
                    )));
                }
                out.push(s);
            }
            out
        }
    };
    if args.strict && args.at.is_none() {
        require_surface(samples.clone(), "vertex")?;
    }
    super::progress::check_interrupted()?;
    print_samples(&samples, args.derivs)?;
    Ok(0)
}

/// Print [`format_samples`] on stdout.
pub(crate) fn print_samples(samples: &[Option<LimitSample>], derivs: bool) -> Result<()> {
    let text = format_samples(samples, derivs);
    std::io::stdout()
        .lock()
        .write_all(text.as_bytes())
        .map_err(|e| Error::Io {
            path: PathBuf::from("<stdout>"),
            message: e.to_string(),
        })
}

/// One `face u v` line of a points file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointLine {
    /// 1-based line number, for messages.
    pub line: usize,
    /// Ptex face.
    pub face: u32,
    /// Parameter u.
    pub u: f64,
    /// Parameter v.
    pub v: f64,
}

/// Read a points file (see [`LimitArgs::at`]).
pub fn read_points(path: &Path) -> Result<Vec<PointLine>> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    parse_points(&text, path)
}

/// Parse the text of a points file; `path` is only used in messages.
pub fn parse_points(text: &str, path: &Path) -> Result<Vec<PointLine>> {
    let mut out = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let err = |message: String| Error::Parse {
            path: path.to_path_buf(),
            line: i + 1,
            message,
        };
        let fields: Vec<&str> = line.split_whitespace().collect();
        if fields.len() != 3 {
            return Err(err(format!(
                "expected `face u v`, found {} fields: `{line}`",
                fields.len()
            )));
        }
        let face = fields[0].parse::<u32>().map_err(|_| {
            err(format!(
                "face must be an integer >= 0, found `{}`",
                fields[0]
            ))
        })?;
        let number = |s: &str, name: &str| {
            s.parse::<f64>()
                .map_err(|_| err(format!("{name} must be a number, found `{s}`")))
        };
        out.push(PointLine {
            line: i + 1,
            face,
            u: number(fields[1], "u")?,
            v: number(fields[2], "v")?,
        });
    }
    Ok(out)
}

/// The output lines for `samples`; `None` (no limit surface) prints `nan` for every number.
pub fn format_samples(samples: &[Option<LimitSample>], derivs: bool) -> String {
    let mut out = String::with_capacity(samples.len() * if derivs { 180 } else { 60 });
    for s in samples {
        let s = s.unwrap_or(LimitSample::NO_SURFACE);
        let p = s.position;
        let _ = write!(out, "{} {} {}", G17(p.x), G17(p.y), G17(p.z));
        if derivs {
            for d in [s.du, s.dv] {
                let _ = write!(out, " {} {} {}", G17(d.x), G17(d.y), G17(d.z));
            }
        }
        out.push('\n');
    }
    out
}

/// `%.17g` notation with shortest round-trip digits: exponent form when the decimal
/// exponent is below -4 or at least 17, plain decimal otherwise.
struct G17(f64);

impl std::fmt::Display for G17 {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let x = self.0;
        if x.is_nan() {
            // C's spelling, which OpenSubdiv-based tools print and C's strtod reads.
            return f.write_str("nan");
        }
        if x.is_infinite() {
            return f.write_str(if x > 0.0 { "inf" } else { "-inf" });
        }
        if x == 0.0 {
            return write!(f, "{x}");
        }
        let sci = format!("{x:e}");
        let exponent: i32 = sci
            .rsplit('e')
            .next()
            .and_then(|e| e.parse().ok())
            .unwrap_or(0);
        if (-4..17).contains(&exponent) {
            write!(f, "{x}")
        } else {
            f.write_str(&sci)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_shortest_round_trip_in_g_notation() {
        let s = |x: f64| G17(x).to_string();
        assert_eq!(s(0.1), "0.1");
        assert_eq!(s(1.0), "1");
        assert_eq!(s(-0.0), "-0");
        assert_eq!(s(1e-4), "0.0001");
        assert_eq!(s(1.5e-5), "1.5e-5");
        assert_eq!(s(12345678901234567.0), "12345678901234568");
        assert_eq!(s(1.2e17), "1.2e17");
        assert_eq!(s(f64::NAN), "nan");
        assert_eq!(s(f64::INFINITY), "inf");
        assert_eq!(s(f64::NEG_INFINITY), "-inf");
        let none = format_samples(&[None, Some(LimitSample::default())], true);
        assert_eq!(
            none,
            "nan nan nan nan nan nan nan nan nan\n0 0 0 0 0 0 0 0 0\n"
        );
        for x in [
            std::f64::consts::PI,
            1.0 / 3.0,
            -2.5e-300,
            6.02e23,
            0.30000000000000004,
        ] {
            assert_eq!(s(x).parse::<f64>().unwrap(), x);
        }
    }

    #[test]
    fn points_files_are_parsed_with_line_numbers_in_errors() {
        let p = Path::new("pts.txt");
        let pts = parse_points("# header\n0 0.5 0.25\n\n3 1 0 # corner\n", p).unwrap();
        assert_eq!(pts.len(), 2);
        assert_eq!(
            pts[1],
            PointLine {
                line: 4,
                face: 3,
                u: 1.0,
                v: 0.0
            }
        );
        let e = parse_points("0 0.5\n", p).unwrap_err().to_string();
        assert_eq!(e, "pts.txt:1: expected `face u v`, found 2 fields: `0 0.5`");
        let e = parse_points("\n-1 0 0\n", p).unwrap_err().to_string();
        assert!(e.starts_with("pts.txt:2: face must be an integer"), "{e}");
        let e = parse_points("1 x 0\n", p).unwrap_err().to_string();
        assert!(e.contains("u must be a number, found `x`"), "{e}");
    }
}
