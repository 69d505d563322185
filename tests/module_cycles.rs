//! No import cycles between the crate's modules: every path to another module of the crate
//! (`use crate::…`, `use super::…`, `use child::…`, and paths written inline in code such as
//! `crate::io::json::parse_json(…)`) is an edge from the module of the file to the longest
//! module prefix of the path; test code (`#[cfg(test)]` items at the end of a file, the
//! `tests.rs` / `*_tests.rs` / `test_support.rs` files) is left out. The graph must have no
//! cycle inside `construct` and inside `ffi`; cycles elsewhere are listed as they are found.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The module path of a source file (`src/a/b.rs`, `src/a/b/mod.rs` → `a::b`; `src/lib.rs`
/// → ``), or `None` for test-only files and the binary.
fn module_of(src: &Path, file: &Path) -> Option<String> {
    let rel = file.strip_prefix(src).unwrap();
    let name = rel.file_name()?.to_str()?;
    if name == "tests.rs"
        || name.ends_with("_tests.rs")
        || name == "test_support.rs"
        || name == "main.rs"
    {
        return None;
    }
    let mut parts: Vec<String> = rel
        .iter()
        .map(|p| p.to_str().unwrap().to_string())
        .collect();
    let last = parts.pop().unwrap();
    let stem = last.trim_end_matches(".rs");
    if stem != "mod" && stem != "lib" {
        parts.push(stem.to_string());
    }
    Some(parts.join("::"))
}

/// `a::{b, c::{d, e}}` → `a::b`, `a::c::d`, `a::c::e`.
fn expand(tree: &str) -> Vec<String> {
    let tree = tree.trim();
    let Some(open) = tree.find('{') else {
        return vec![tree.to_string()];
    };
    let prefix = &tree[..open];
    let inner = &tree[open + 1..tree.rfind('}').unwrap()];
    let (mut items, mut depth, mut start) = (Vec::new(), 0, 0);
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                items.push(&inner[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    items.push(&inner[start..]);
    items
        .into_iter()
        .filter(|i| !i.trim().is_empty())
        .flat_map(|i| expand(i).into_iter().map(move |e| format!("{prefix}{e}")))
        .collect()
}

/// The code of a file without its comments and its test code.
fn code(text: &str) -> String {
    let mut out = String::new();
    for line in text.lines() {
        if line.starts_with("#[cfg(test)]") {
            break;
        }
        let t = line.trim_start();
        if t.starts_with("//") {
            continue;
        }
        out.push_str(line.split(" // ").next().unwrap());
        out.push('\n');
    }
    out
}

/// The paths a module's code names: its `use` trees, expanded, and inline `crate::` paths.
fn paths(code: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut rest = code;
    while let Some(i) = rest.find("use ") {
        let before = rest[..i].chars().last();
        let after = &rest[i + 4..];
        let end = after.find(';').unwrap_or(after.len());
        if before.map_or(true, |c| c.is_whitespace()) {
            let tree: String = after[..end].split_whitespace().collect();
            found.extend(expand(&tree));
        }
        rest = &after[end..];
    }
    let mut rest = code;
    while let Some(i) = rest.find("crate::") {
        let tail = &rest[i..];
        let end = tail
            .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
            .unwrap_or(tail.len());
        found.push(tail[..end].trim_end_matches(':').to_string());
        rest = &tail[end..];
    }
    found
}

/// The module a path names, relative to module `from`: the longest module prefix.
fn target(path: &str, from: &str, is_dir: bool, modules: &BTreeSet<String>) -> Option<String> {
    let segs: Vec<&str> = path.split("::").map(|s| s.trim()).collect();
    let here: Vec<&str> = if from.is_empty() {
        vec![]
    } else {
        from.split("::").collect()
    };
    // The module a file's own `super`/`self`/child paths start from.
    let (mut base, mut rest): (Vec<&str>, &[&str]) = match segs[0] {
        "crate" => (vec![], &segs[1..]),
        "self" => (here.clone(), &segs[1..]),
        "super" => {
            let mut b = here.clone();
            let mut s = &segs[..];
            while s.first() == Some(&"super") {
                b.pop();
                s = &s[1..];
            }
            (b, s)
        }
        first => {
            let child = if here.is_empty() {
                first.to_string()
            } else {
                format!("{from}::{first}")
            };
            if !(is_dir || from.is_empty()) || !modules.contains(&child) {
                return None;
            }
            (here.clone(), &segs[..])
        }
    };
    // The module the path starts in, then the longest module prefix from there.
    let mut best = base.join("::");
    while let Some((first, tail)) = rest.split_first() {
        base.push(first);
        let m = base.join("::");
        if !modules.contains(&m) {
            break;
        }
        best = m;
        rest = tail;
    }
    Some(best).filter(|m| m != from)
}

/// The strongly connected components of more than one module (Tarjan).
fn cycles(graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    struct State<'a> {
        graph: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on_stack: BTreeSet<&'a str>,
        out: Vec<Vec<String>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a str) {
        let i = s.index.len();
        s.index.insert(v, i);
        s.low.insert(v, i);
        s.stack.push(v);
        s.on_stack.insert(v);
        for w in s.graph.get(v).into_iter().flatten() {
            let w = w.as_str();
            if !s.index.contains_key(w) {
                visit(s, w);
                let l = s.low[w].min(s.low[v]);
                s.low.insert(v, l);
            } else if s.on_stack.contains(w) {
                let l = s.index[w].min(s.low[v]);
                s.low.insert(v, l);
            }
        }
        if s.low[v] == s.index[v] {
            let mut scc = Vec::new();
            while let Some(w) = s.stack.pop() {
                s.on_stack.remove(w);
                scc.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if scc.len() > 1 {
                scc.sort();
                s.out.push(scc);
            }
        }
    }
    let mut s = State {
        graph,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        out: Vec::new(),
    };
    for v in graph.keys() {
        if !s.index.contains_key(v.as_str()) {
            visit(&mut s, v);
        }
    }
    s.out
}

/// The module graph of `src/`, each module with the modules it names.
fn module_graph(src: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let mut files = Vec::new();
    rust_files(src, &mut files);
    let sources: Vec<(String, bool, String)> = files
        .iter()
        .filter_map(|f| {
            let m = module_of(src, f)?;
            let is_dir = f.file_name().unwrap() == "mod.rs" || f.file_name().unwrap() == "lib.rs";
            Some((m, is_dir, std::fs::read_to_string(f).unwrap()))
        })
        .collect();
    let modules: BTreeSet<String> = sources.iter().map(|(m, _, _)| m.clone()).collect();
    let mut graph = BTreeMap::new();
    for (m, is_dir, text) in &sources {
        let edges: BTreeSet<String> = paths(&code(text))
            .iter()
            .filter_map(|p| target(p, m, *is_dir, &modules))
            .collect();
        graph.insert(m.clone(), edges);
    }
    graph
}

/// The graph restricted to the modules under `root`.
fn within(
    graph: &BTreeMap<String, BTreeSet<String>>,
    root: &str,
) -> BTreeMap<String, BTreeSet<String>> {
    let inside = |m: &str| m == root || m.starts_with(&format!("{root}::"));
    graph
        .iter()
        .filter(|(m, _)| inside(m))
        .map(|(m, e)| (m.clone(), e.iter().filter(|t| inside(t)).cloned().collect()))
        .collect()
}

#[test]
fn the_parser_sees_use_trees_and_inline_paths() {
    assert_eq!(
        expand("crate::a::{b,c::{d,e}}"),
        ["crate::a::b", "crate::a::c::d", "crate::a::c::e"]
    );
    let found = paths("use super::x::{Y, z::W};\nfn f() { crate::io::json::parse(1); }\n");
    assert_eq!(
        found,
        ["super::x::Y", "super::x::z::W", "crate::io::json::parse"]
    );
    let modules: BTreeSet<String> = ["a", "a::b", "a::c", "io", "io::json"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let t = |p: &str, from: &str, dir: bool| target(p, from, dir, &modules);
    assert_eq!(t("super::c::Item", "a::b", false).as_deref(), Some("a::c"));
    assert_eq!(
        t("crate::io::json::parse", "a", true).as_deref(),
        Some("io::json")
    );
    assert_eq!(t("b::Item", "a", true).as_deref(), Some("a::b"));
    assert_eq!(t("glam::DVec3", "a", true), None);
    assert_eq!(t("super::Item", "a::b", false).as_deref(), Some("a"));
    // A cycle and its members.
    let g: BTreeMap<String, BTreeSet<String>> = [
        ("a", vec!["a::b"]),
        ("a::b", vec!["a::c"]),
        ("a::c", vec!["a::b"]),
    ]
    .into_iter()
    .map(|(m, e)| (m.to_string(), e.into_iter().map(String::from).collect()))
    .collect();
    assert_eq!(cycles(&g), [vec!["a::b".to_string(), "a::c".to_string()]]);
}

#[test]
fn construct_and_ffi_have_no_import_cycles() {
    let graph = module_graph(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"));
    assert!(graph.contains_key("construct::revolve::wedge"));
    assert!(graph["construct::revolve"].contains("construct::revolve::wedge"));
    for root in ["construct", "ffi"] {
        let found = cycles(&within(&graph, root));
        assert!(found.is_empty(), "import cycles in {root}: {found:?}");
    }
    for c in cycles(&graph) {
        println!("import cycle elsewhere: {c:?}");
    }
}
