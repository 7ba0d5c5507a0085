//! The shape of `src/`: no import cycles between its files (tests excluded), and no terminal code
//! outside `src/tui`.
//!
//! An edge F -> G when F names G's module through `use crate::...`, `use super::...` or a
//! `crate::a::b::` path in its code (comments and the `#[cfg(test)]` part left out); a `mod.rs`'s
//! edges to its own direct children (declarations, re-exports) are not counted. The cycles are the
//! strongly connected components of that graph with more than one file. The rule is the one of the
//! project's `import_cycles.py`, so both list the same cycles.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use regex::Regex;

/// Cycles that exist today, one line each: the files of one cycle, sorted, separated by spaces.
/// The list only shrinks: the test fails on a cycle not listed here and on a line here that is no
/// longer a cycle (remove the line when you break the cycle).
#[rustfmt::skip]
const KNOWN_CYCLES: &[&str] = &[];

/// The crate's root directory.
fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every `.rs` file under `dir`, with its text, in path order.
fn rust_files(dir: &Path, out: &mut Vec<(PathBuf, String)>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .expect("src/ is readable")
        .map(|e| e.expect("src/ is readable").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let text = String::from_utf8_lossy(&std::fs::read(&path).expect("readable")).into();
            out.push((path, text));
        }
    }
}

/// The path of `file` relative to the crate root, with `/` separators: "src/physics/mod.rs".
fn relative(file: &Path) -> String {
    let rel = file.strip_prefix(root()).expect("under the crate root");
    let parts: Vec<_> = rel
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    parts.join("/")
}

/// The module a file holds, as path segments below the crate: `src/physics/plane/mod.rs` and
/// `src/physics/plane.rs` are both `["physics", "plane"]`; `lib.rs` and `main.rs` are `[]`.
fn module_of(rel: &str) -> Vec<String> {
    let inner = rel.strip_prefix("src/").expect("under src/");
    let mut segs: Vec<String> = inner[..inner.len() - 3]
        .split('/')
        .map(String::from)
        .collect();
    if matches!(
        segs.last().map(String::as_str),
        Some("mod" | "lib" | "main")
    ) {
        segs.pop();
    }
    segs
}

/// Whether a file is the root of a folder module (`mod.rs`, `lib.rs`, `main.rs`).
fn is_dir_mod(rel: &str) -> bool {
    ["mod.rs", "lib.rs", "main.rs"].contains(&rel.rsplit('/').next().unwrap_or(""))
}

/// The text a file's imports are read from: the code before its first `#[cfg(test)]`, without
/// `//` comments.
fn code_of(text: &str) -> String {
    let before_tests = text.find("#[cfg(test)]").map_or(text, |i| &text[..i]);
    Regex::new(r"//[^\n]*")
        .unwrap()
        .replace_all(before_tests, "")
        .into_owned()
}

/// The paths of a use tree's body `a, b::c, d::{e, f}` under `prefix`.
fn expand(prefix: &str, body: &str) -> Vec<String> {
    let nested = Regex::new(r"(?s)^((?:\w+::)*)\{(.*)\}$").unwrap();
    let mut out = Vec::new();
    let (mut depth, mut cur) = (0i32, String::new());
    for ch in body.chars().chain([',']) {
        match ch {
            '{' => depth += 1,
            '}' => depth -= 1,
            _ => {}
        }
        if ch == ',' && depth == 0 {
            let item = cur.trim().to_string();
            cur.clear();
            if item.is_empty() {
                continue;
            }
            match nested.captures(&item) {
                Some(c) => out.extend(expand(&format!("{prefix}{}", &c[1]), &c[2])),
                None => out.push(format!(
                    "{prefix}{}",
                    item.split(" as ").next().unwrap_or("").trim()
                )),
            }
        } else {
            cur.push(ch);
        }
    }
    out
}

/// The module paths (segments below the crate) a file's code names.
fn named_paths(rel: &str, code: &str) -> Vec<Vec<String>> {
    let me = module_of(rel);
    let parent = me[..me.len().saturating_sub(1)].to_vec();
    let here = if is_dir_mod(rel) {
        me.clone()
    } else {
        parent.clone()
    };
    let mut text = code.to_string();
    let tree = Regex::new(r"\buse\s+((?:crate|super|self)(?:::\w+)*)::\{").unwrap();
    for m in tree.captures_iter(code) {
        let start = m.get(0).unwrap().end();
        let bytes = code.as_bytes();
        let (mut depth, mut i) = (1, start);
        while i < bytes.len() && depth > 0 {
            depth += match bytes[i] {
                b'{' => 1,
                b'}' => -1,
                _ => 0,
            };
            i += 1;
        }
        let body = code.get(start..i - 1).unwrap_or(&code[start..]);
        for full in expand(&format!("{}::", &m[1]), body) {
            text.push('\n');
            match full.starts_with("self::") {
                true => text.push_str(&full.replace("self::", "")),
                false => text.push_str(&full),
            }
        }
    }
    let mut paths = Vec::new();
    let named = Regex::new(r"\b(crate|super)((?:::\w+)+)").unwrap();
    for c in named.captures_iter(&text) {
        let mut segs: Vec<String> = c[2].split("::").skip(1).map(String::from).collect();
        if &c[1] == "crate" {
            paths.push(segs);
        } else {
            let mut base = parent.clone();
            while segs.first().is_some_and(|s| s == "super") {
                base.pop();
                segs.remove(0);
            }
            base.extend(segs);
            paths.push(base);
        }
    }
    let self_use =
        Regex::new(r"(?m)^\s*(?:pub(?:\([^)]*\))?\s+)?use\s+self::((?:\w+::)*\w+)").unwrap();
    for c in self_use.captures_iter(&text) {
        let mut path = here.clone();
        path.extend(c[1].split("::").map(String::from));
        paths.push(path);
    }
    paths
}

/// The import graph between the files of `src/` outside test folders and `tests.rs` files: each
/// file (relative path) with the files it imports.
fn import_graph() -> BTreeMap<String, BTreeSet<String>> {
    let mut all = Vec::new();
    rust_files(&root().join("src"), &mut all);
    let files: Vec<(String, String)> = all
        .into_iter()
        .map(|(p, text)| (relative(&p), text))
        .filter(|(rel, _)| {
            let dir = &rel["src".len()..rel.rfind('/').unwrap_or(rel.len())];
            !dir.contains("/tests") && !rel.ends_with("/tests.rs")
        })
        .collect();
    let by_mod: BTreeMap<Vec<String>, &str> = files
        .iter()
        .map(|(rel, _)| (module_of(rel), rel.as_str()))
        .collect();
    let resolve = |segs: &[String]| {
        (1..=segs.len())
            .rev()
            .find_map(|n| by_mod.get(&segs[..n]).copied())
    };
    let mut graph = BTreeMap::new();
    for (rel, text) in &files {
        let me = module_of(rel);
        let mut edges = BTreeSet::new();
        for segs in named_paths(rel, &code_of(text)) {
            let Some(q) = resolve(&segs).filter(|q| q != rel) else {
                continue;
            };
            let qm = module_of(q);
            let own_child = is_dir_mod(rel) && qm.len() == me.len() + 1 && qm.starts_with(&me);
            if !own_child {
                edges.insert(q.to_string());
            }
        }
        graph.insert(rel.clone(), edges);
    }
    graph
}

/// The strongly connected components of more than one file (Tarjan), each as its sorted files
/// joined by spaces.
fn cycles(graph: &BTreeMap<String, BTreeSet<String>>) -> BTreeSet<String> {
    struct Tarjan<'a> {
        graph: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on_stack: BTreeSet<&'a str>,
        found: BTreeSet<String>,
    }
    impl<'a> Tarjan<'a> {
        fn strong(&mut self, v: &'a str) {
            let n = self.index.len();
            self.index.insert(v, n);
            self.low.insert(v, n);
            self.stack.push(v);
            self.on_stack.insert(v);
            for w in &self.graph[v] {
                let w = w.as_str();
                if !self.index.contains_key(w) {
                    self.strong(w);
                    let low = self.low[v].min(self.low[w]);
                    self.low.insert(v, low);
                } else if self.on_stack.contains(w) {
                    let low = self.low[v].min(self.index[w]);
                    self.low.insert(v, low);
                }
            }
            if self.low[v] == self.index[v] {
                let mut comp = Vec::new();
                while let Some(w) = self.stack.pop() {
                    self.on_stack.remove(w);
                    comp.push(w);
                    if w == v {
                        break;
                    }
                }
                if comp.len() > 1 {
                    comp.sort();
                    self.found.insert(comp.join(" "));
                }
            }
        }
    }
    let mut t = Tarjan {
        graph,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        found: BTreeSet::new(),
    };
    for v in graph.keys() {
        if !t.index.contains_key(v.as_str()) {
            t.strong(v);
        }
    }
    t.found
}

#[test]
fn no_new_import_cycles_and_every_known_one_still_exists() {
    let found = cycles(&import_graph());
    let known: BTreeSet<String> = KNOWN_CYCLES.iter().map(|s| s.to_string()).collect();
    let new: Vec<_> = found.difference(&known).collect();
    let gone: Vec<_> = known.difference(&found).collect();
    assert!(
        new.is_empty() && gone.is_empty(),
        "import cycles between files of src/ changed.\nnew cycles (break them): {new:#?}\n\
         listed in KNOWN_CYCLES but no longer cycles (remove their lines): {gone:#?}"
    );
}

#[test]
fn terminal_code_stays_in_src_tui() {
    let mut all = Vec::new();
    rust_files(&root().join("src"), &mut all);
    let offenders: Vec<String> = all
        .iter()
        .map(|(p, text)| (relative(p), code_of_all(text)))
        .filter(|(rel, _)| !rel.starts_with("src/tui/"))
        .flat_map(|(rel, code)| {
            ["crate::tui", "ratatui", "crossterm"]
                .into_iter()
                .filter(move |name| code.contains(name))
                .map(move |name| format!("{rel} names {name}"))
        })
        .collect();
    assert!(offenders.is_empty(), "{offenders:#?}");
}

/// A whole file's code (its tests included) without `//` comments.
fn code_of_all(text: &str) -> String {
    Regex::new(r"//[^\n]*")
        .unwrap()
        .replace_all(text, "")
        .into_owned()
}

#[test]
fn a_cycle_is_found_and_a_mod_rs_naming_its_children_is_not_one() {
    let a = "use crate::b::B;\nuse super::x::{self, Y};\n";
    assert!(named_paths("src/a.rs", a).contains(&vec!["b".into(), "B".into()]));
    assert!(named_paths("src/a.rs", a).contains(&vec!["x".into(), "Y".into()]));
    let graph: BTreeMap<String, BTreeSet<String>> = [
        ("src/a.rs", vec!["src/b/mod.rs"]),
        ("src/b/mod.rs", vec!["src/a.rs"]),
        ("src/c.rs", vec![]),
    ]
    .into_iter()
    .map(|(f, to)| (f.into(), to.into_iter().map(String::from).collect()))
    .collect();
    let want: BTreeSet<String> = ["src/a.rs src/b/mod.rs".to_string()].into();
    assert_eq!(cycles(&graph), want);
}
