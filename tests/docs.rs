//! The documentation holds together: every relative link in README.md and docs/ points to a file
//! or folder that exists, README.md stays a front door (at most 250 lines) and keeps the two
//! set-up commands.

use std::fs;
use std::path::{Path, PathBuf};

/// README.md and every Markdown file under docs/.
fn pages() -> Vec<PathBuf> {
    let mut pages = vec![PathBuf::from("README.md")];
    let mut folders = vec![PathBuf::from("docs")];
    while let Some(folder) = folders.pop() {
        for entry in fs::read_dir(&folder).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|e| e == "md") {
                pages.push(path);
            }
        }
    }
    pages
}

/// The targets of the Markdown links `[text](target)` in `text`.
fn link_targets(text: &str) -> Vec<&str> {
    text.match_indices("](")
        .filter_map(|(at, _)| {
            let rest = &text[at + 2..];
            rest.find(')').map(|end| &rest[..end])
        })
        .collect()
}

/// Whether a link target is relative to its page (not a web address or an anchor on the page).
fn is_relative(target: &str) -> bool {
    !(target.is_empty()
        || target.starts_with('#')
        || target.contains("://")
        || target.starts_with("mailto:"))
}

#[test]
fn every_relative_link_points_to_an_existing_file() {
    let mut broken = Vec::new();
    let mut checked = 0;
    for page in pages() {
        let text = fs::read_to_string(&page).unwrap();
        let folder = page.parent().unwrap_or(Path::new(""));
        for target in link_targets(&text).into_iter().filter(|t| is_relative(t)) {
            let file = target.split('#').next().unwrap();
            checked += 1;
            if !folder.join(file).exists() {
                broken.push(format!("{}: {target}", page.display()));
            }
        }
    }
    assert!(broken.is_empty(), "links to nothing: {broken:#?}");
    // README.md links to every page of docs/ (guide, presets, cli, models, verification,
    // performance, references): a test that found no link would check nothing
    assert!(checked >= 7, "only {checked} relative links found");
}

#[test]
fn the_readme_is_a_front_door() {
    let readme = fs::read_to_string("README.md").unwrap();
    let lines = readme.lines().count();
    assert!(lines <= 250, "README.md has {lines} lines, at most 250");
    for command in ["cargo run --release ", "cargo test "] {
        assert!(
            readme.lines().any(|l| l.starts_with(command)),
            "README.md does not give the set-up command `{}`",
            command.trim_end()
        );
    }
}
