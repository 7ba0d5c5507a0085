//! The dimensionless view (`D`): the status in the problem's groups, its title saying so, the help
//! defining each group.

use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::preset::Problem;
use crate::sweeps::quantity::problem_groups;
use crate::tui::view::popups::help_lines;

#[test]
fn d_shows_the_status_in_groups_and_back() {
    let mut app = solved("polymer-coating.toml");
    let plain = screen(&app, 120, 40, PLAIN);
    assert!(plain.contains("operating point") && !plain.contains("dimensionless groups"));
    press(&mut app, KeyCode::Char('D'));
    let groups = screen(&app, 120, 40, PLAIN);
    assert!(groups.contains("operating point in dimensionless groups"));
    for symbol in [
        "(a+b)/h =",
        "(a+b)/R =",
        "P/(m R) =",
        "k m =",
        "mu chi =",
        "mu* =",
        "mu*-mu =",
    ] {
        assert!(groups.contains(symbol), "{symbol}");
    }
    // no dimensional value in the status: no Q2, no psi in N/m
    assert!(!groups.contains("Q2 =") && !groups.contains("psi ="));
    insta::assert_snapshot!("groups_plane_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("groups_plane_120x40", groups);
    // D again: the same screen but for the message line
    press(&mut app, KeyCode::Char('D'));
    let back = screen(&app, 120, 40, PLAIN);
    let status = |s: &str| s.lines().take(38).collect::<Vec<_>>().join("\n");
    assert_eq!(status(&back), status(&plain));
    assert!(back.contains("dimensionless view off"));
}

#[test]
fn the_spatial_status_in_groups() {
    let mut app = solved("dispersion.toml");
    press(&mut app, KeyCode::Char('D'));
    let groups = screen(&app, 120, 40, PLAIN);
    for symbol in [
        "kh",
        "beta t",
        "A/(M pbar)",
        "phi",
        "sum A/(M pbar) =",
        "mu*-mu =",
    ] {
        assert!(groups.contains(symbol), "{symbol}");
    }
    insta::assert_snapshot!("groups_spatial_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("groups_spatial_120x40", groups);
}

#[test]
fn the_help_defines_every_group() {
    for (file, problem) in [
        ("polymer-coating.toml", Problem::Plane),
        ("dispersion.toml", Problem::Spatial),
    ] {
        let app = solved(file);
        let help: Vec<String> = help_lines(&app, PLAIN, 100)
            .iter()
            .map(|l| l.to_string())
            .collect();
        let defined = |symbol: &str| help.iter().any(|l| l.starts_with(&format!("  {symbol} ")));
        for q in problem_groups(problem) {
            assert!(defined(q.symbol), "{file}: {} undefined", q.symbol);
        }
        assert!(defined("D (groups)") && defined("mu*-mu"));
    }
}

#[test]
fn a_quantity_reads_the_same_in_the_status_and_in_groups() {
    // one rule (status::number) for both views: not (a+b)/h = 16.58 in D beside "valid: (a+b)/h =
    // 16.575", nor phi 0.07227 in D against +0.07 in the dimensional harmonics table
    let mut app = solved("thin-strip-winkler.toml");
    let dimensional = screen(&app, 120, 40, PLAIN);
    press(&mut app, KeyCode::Char('D'));
    let groups = screen(&app, 120, 40, PLAIN);
    for s in [&dimensional, &groups] {
        assert!(s.contains("(a+b)/h = 16.58"), "{s}");
        assert!(!s.contains("16.575"), "{s}");
    }
    let mut app = solved("dispersion.toml");
    let dimensional = screen(&app, 120, 40, PLAIN);
    press(&mut app, KeyCode::Char('D'));
    let groups = screen(&app, 120, 40, PLAIN);
    for s in [&dimensional, &groups] {
        assert!(s.contains(" +0.07227"), "{s}");
    }
}
