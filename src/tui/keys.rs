//! Every key of the explorer in one place: the bindings of the main screen (key, action, help
//! line, footer item) here, the keys of the prompts in `prompt_keys`. Key handling,
//! the `?` help, the footers and docs/guide.md's key table are all drawn from these tables.

use crate::preset::Problem;

pub use crate::tui::cursor_move::CursorMove;
pub use crate::tui::key_scope::{Open, Scope};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use crate::tui::view::theme::RenderOptions;

/// What a key on the main screen does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    /// Select the previous form row (wraps).
    PrevField,
    /// Select the next form row (wraps).
    NextField,
    /// Nudge the selected value down or up, by a small or a large step.
    Nudge { up: bool, large: bool },
    /// Type a value, or pick a choice.
    Edit,
    /// Show the next chart.
    NextChart,
    /// Show the previous chart.
    PrevChart,
    /// Switch between the plane and the spatial problem.
    SwitchProblem,
    /// Cycle the plane model.
    CycleModel,
    /// Play or pause time (spatial).
    PlayPause,
    /// Draw a new seed for the generated surface (spatial).
    NewSeed,
    /// Add a harmonic (spatial).
    AddHarmonic,
    /// Remove the selected harmonic (spatial).
    RemoveHarmonic,
    /// Open a preset.
    Open,
    /// Save the preset.
    Save,
    /// Export the visible chart as CSV.
    Export,
    /// Export the visible chart as an SVG figure.
    ExportSvg,
    /// Show or hide the cursor readout.
    Cursor,
    /// Move the cursor (`[ ] { }`).
    MoveCursor(CursorMove),
    /// Send the chart's cursor to an x typed in the x axis' unit (`g`).
    GoTo,
    /// Pin the visible chart's curves.
    Pin,
    /// Clear the visible chart's pins.
    ClearPins,
    /// Give the chart the whole screen, or give it back.
    Expand,
    /// Toggle the y axis between linear and logarithmic.
    LogY,
    /// Choose the parameter, range and quantity of the sweep chart, and show it.
    Sweep,
    /// Choose the two parameters and the quantity of the regime map, and show it.
    Map,
    /// Toggle the dimensionless view (the problem's dimensionless groups).
    Dimensionless,
    /// Draw a data file over the charts whose axes it matches (`d`).
    Data,
    /// Fit inputs to the data drawn (`F`).
    Fit,
    /// Stop a running fit (Esc).
    StopFit,
    /// Undo the last change.
    Undo,
    /// Show the preset's name and whole description.
    About,
    /// Answer the questions of the preset's lesson.
    Questions,
    /// Show the help.
    Help,
    /// Quit (asks when there are unsaved edits).
    Quit,
}

/// A key with the modifiers that matter: Shift for non-character keys, Ctrl for letters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Key {
    /// The key.
    pub code: KeyCode,
    /// Shift held (only compared for non-character keys; a character carries its own case).
    pub shift: bool,
    /// Ctrl held.
    pub ctrl: bool,
}

pub(crate) const fn key(code: KeyCode) -> Key {
    Key {
        code,
        shift: false,
        ctrl: false,
    }
}

pub(crate) const fn ch(c: char) -> Key {
    key(KeyCode::Char(c))
}

const fn shift(code: KeyCode) -> Key {
    Key {
        code,
        shift: true,
        ctrl: false,
    }
}

/// Ctrl-C: quits from every mode.
pub const CTRL_C: Key = Key {
    code: KeyCode::Char('c'),
    shift: false,
    ctrl: true,
};

impl Key {
    /// Whether a key event is this key.
    pub fn matches(&self, ev: &KeyEvent) -> bool {
        let ctrl = ev.modifiers.contains(KeyModifiers::CONTROL);
        let shift = ev.modifiers.contains(KeyModifiers::SHIFT);
        match (self.code, ev.code) {
            (KeyCode::Char(a), KeyCode::Char(b)) => {
                a.eq_ignore_ascii_case(&b)
                    && (a == b || ctrl)
                    && ctrl == self.ctrl
                    && !ev.modifiers.contains(KeyModifiers::ALT)
            }
            (a, b) => a == b && shift == self.shift && ctrl == self.ctrl,
        }
    }
}

/// One line of the key table: the keys and what they do, the help line and the footer item.
#[derive(Clone, Copy, Debug)]
pub struct Binding {
    /// The keys and their actions.
    pub keys: &'static [(Key, Action)],
    /// How the help and docs/guide.md write the keys.
    pub names: &'static str,
    /// What they do, for the help and docs/guide.md.
    pub help: &'static str,
    /// The footer item: keys, word, a shorter word for narrow terminals, and the order in which
    /// items take their shorter word when the footer does not fit (0: never); no keys: none
    /// (the help and docs/guide.md still list the binding).
    pub footer: (&'static str, &'static str, &'static str, u8),
    /// Where the binding applies (the footer shows it there only; elsewhere the key says why it
    /// does nothing).
    pub only: Scope,
}

const ALL: Scope = Scope::All;
const PLANE: Scope = Scope::Problem(Problem::Plane);
const SPATIAL: Scope = Scope::Problem(Problem::Spatial);

const fn binding(
    keys: &'static [(Key, Action)],
    names: &'static str,
    help: &'static str,
    footer: (&'static str, &'static str, &'static str, u8),
    only: Scope,
) -> Binding {
    Binding {
        keys,
        names,
        help,
        footer,
        only,
    }
}

const fn nudge(up: bool, large: bool) -> Action {
    Action::Nudge { up, large }
}

/// The main screen's key table, in help order.
#[rustfmt::skip]
pub const BINDINGS: [Binding; 26] = [
    binding(
        &[(key(KeyCode::Up), Action::PrevField), (ch('k'), Action::PrevField),
          (key(KeyCode::Down), Action::NextField), (ch('j'), Action::NextField)],
        "Up/Down, k/j", "choose a field",
        ("↑↓", "field", "", 2), ALL,
    ),
    binding(
        &[(key(KeyCode::Left), nudge(false, false)), (ch('h'), nudge(false, false)),
          (key(KeyCode::Right), nudge(true, false)), (ch('l'), nudge(true, false)),
          (shift(KeyCode::Left), nudge(false, true)), (ch('H'), nudge(false, true)),
          (shift(KeyCode::Right), nudge(true, true)), (ch('L'), nudge(true, true))],
        "Left/Right, h/l", "nudge the value (x1.1 or a fixed step; Shift or H/L: x2 or ten steps)",
        ("←→", "nudge (⇧ more)", "nudge", 1), ALL,
    ),
    binding(
        &[(key(KeyCode::Enter), Action::Edit)],
        "Enter", "type a value (3e9, 3 GPa, 50mm, inf) or pick a choice; Esc cancels",
        ("⏎", "type", "", 4), ALL,
    ),
    binding(
        &[(key(KeyCode::Tab), Action::NextChart), (key(KeyCode::BackTab), Action::PrevChart),
          (shift(KeyCode::BackTab), Action::PrevChart)],
        "Tab, Shift-Tab", "next / previous chart",
        ("Tab", "chart", "", 9), ALL,
    ),
    binding(
        &[(ch('p'), Action::SwitchProblem)],
        "p", "switch plane / spatial problem (a preset holds both)",
        ("p", "problem", "", 8), ALL,
    ),
    binding(
        &[(ch('m'), Action::CycleModel)],
        "m", "cycle the plane model (wide, narrow, strip)",
        ("m", "model", "", 6), PLANE,
    ),
    binding(
        &[(ch(' '), Action::PlayPause)],
        "space", "play / pause time",
        ("space", "play", "", 6), SPATIAL,
    ),
    binding(
        &[(ch('+'), Action::AddHarmonic), (ch('-'), Action::RemoveHarmonic)],
        "+ / -", "add a harmonic / remove the selected one, or the last",
        ("+/-", "harmonic", "", 3), SPATIAL,
    ),
    binding(
        &[(ch('r'), Action::NewSeed)],
        "r", "a new seed for the generated surface: the same spectrum and rms, other random phases (u undoes)",
        ("r", "seed", "", 3), Scope::GeneratedSurface,
    ),
    binding(
        &[(ch('x'), Action::Cursor), (ch('['), Action::MoveCursor(CursorMove::Back)),
          (ch(']'), Action::MoveCursor(CursorMove::Forward)), (ch('{'), Action::MoveCursor(CursorMove::LongBack)),
          (ch('}'), Action::MoveCursor(CursorMove::LongForward)), (ch('g'), Action::GoTo)],
        "x, [ ], { }, g", "cursor readout: x shows or hides a cursor on the chart, [ ] move it a data point, { } ten, g sends it to an x you type in the x axis' unit (150um, 20 kN/m; a plain number is in the unit itself: m, N/m); the status gives x and every curve's value there, '(interpolated)' after x where the cursor is between the data points of a curve it reads; on the pressure map x shows a cell cursor X at the map's middle, [ ] move it a grid point along x, { } along y, and the status gives x, y and p there (it stays while time plays, p follows)",
        ("x", "cursor", "", 7), ALL,
    ),
    binding(
        &[(ch('c'), Action::Pin), (ch('C'), Action::ClearPins)],
        "c, C", "pin the chart's curves to compare with later edits (up to three, drawn dim with their number, without colour the number and each curve's own character in turn, 1* 1+; named by what differs); C clears the chart's pins",
        ("c/C", "pin", "", 7), ALL,
    ),
    binding(
        &[(ch('f'), Action::Expand)],
        "f", "give the chart the whole screen (the status stays); f again gives it back",
        ("f", "full", "", 7), ALL,
    ),
    binding(
        &[(ch('y'), Action::LogY)],
        "y", "toggle a log y axis (symmetric log, linear near zero, where values have both signs)",
        ("y", "log", "", 7), ALL,
    ),
    binding(
        &[(ch('v'), Action::Sweep)],
        "v", "sweep chart: a quantity (mu*, mu* - mu, a+b, theta, ...) against any input over a range you type (log or linear); the other models overlaid, dim where a model's validity check fails (spatial: where the contact is partial), the change marked on the x axis",
        ("v", "sweep", "", 6), ALL,
    ),
    binding(
        &[(ch('M'), Action::Map)],
        "M", "regime map: a quantity over two inputs, coarse first then refined, with the lines theta = 0, mu* = mu (finite thickness) and validity of the wide and narrow models (spatial: complete contact); x, [ ] { } move a cursor that reads it",
        ("M", "map", "", 6), ALL,
    ),
    binding(
        &[(ch('D'), Action::Dimensionless)],
        "D", "dimensionless view: the status shows the operating point in the problem's dimensionless groups (plane (a+b)/h, (a+b)/R, P/(m R), k m, mu chi, theta, mu*, mu*-mu; spatial mu*, mu*-mu, sum A/(M pbar) and per harmonic kh, beta t, A/(M pbar), phi; ? defines them), and the sweep and map forms (v, M) offer only pure numbers as the quantity; the sweep chart's x axis becomes the swept input's group, computed at each point (plane h -> (a+b)/h, P -> P/(m R), k -> k m, mu -> mu chi, R -> (a+b)/R; spatial h -> kh1), each model's curve through its own points in the sweep's order, the cursor also reading the input with its unit along the preset's model; an input without a group keeps its unit, the axis title saying '(dimensional: no group)'; the map's axes keep their units; D again goes back",
        ("D", "groups", "", 7), ALL,
    ),
    binding(
        &[(ch('d'), Action::Data)],
        "d", "draw a data file over the charts: type its path (relative to the preset's folder, else to where wearlab started); a CSV with a header of quantities and units such as `load [N/m],mu [-],mu sd [-]` and `#` notes; its points go on every chart whose axes are its columns (mu* against P, contact width against P in the sweep v, mu* against t, ...), with error bars of one sd where it has sd columns, named 'data: file.csv' in the legend, kept across edits and in the exports; an empty path takes it away",
        ("d", "data", "", 6), ALL,
    ),
    binding(
        &[(ch('F'), Action::Fit), (key(KeyCode::Esc), Action::StopFit)],
        "F, Esc", "fit inputs to the data drawn (d): choose the inputs to free (mu and k first; space frees one), Enter fits them while you keep working (Esc or an edit stops it); the best values enter the form as one step (u undoes it) and a window gives each with its 95 % interval, the residual, and in words an input the data do not determine with the measurement that would",
        ("", "", "", 0), ALL,
    ),
    binding(
        &[(ch('o'), Action::Open)],
        "o", "open a preset: bundled, shared (WEARLAB_PRESETS) or yours; type to find one or a path to a file, each with its whole description (PgUp/PgDn scroll it; asks first when there are unsaved edits)",
        ("o", "open", "", 5), ALL,
    ),
    binding(
        &[(ch('s'), Action::Save)],
        "s", "save the preset (asks a name; asks before overwriting)",
        ("s", "save", "", 5), ALL,
    ),
    binding(
        &[(ch('e'), Action::Export), (ch('E'), Action::ExportSvg)],
        "e, E", "export the visible chart: e its data as CSV (parameters in a header, units in the column names), E a figure as SVG (axes, legend, parameters), of the sweep or the regime map too; both ask before overwriting",
        ("e/E", "export", "", 5), ALL,
    ),
    binding(
        &[(ch('u'), Action::Undo)],
        "u", "undo the last change (says what it undid)",
        ("u", "undo", "", 5), ALL,
    ),
    binding(
        &[(ch('i'), Action::About)],
        "i", "about this preset: its name and whole description, the status in full (every value of the point and of the cursor's readout, every validity line) and a crowded chart's legend in full, which the status and the chart count as '+2 more: i' (Up/Down, PgUp/PgDn scroll; Esc closes)",
        ("i", "about", "", 5), ALL,
    ),
    binding(
        &[(ch('a'), Action::Questions)],
        "a", "answer the lesson's questions, in a preset that has them: type an answer with its unit (52 um, 0.39) and Enter says right or not; rows marked = are locked by the lesson",
        ("", "", "", 0), ALL,
    ),
    binding(
        &[(ch('?'), Action::Help)],
        "?", "this help: keys, the chart, the status symbols",
        ("?", "help", "help", 0), ALL,
    ),
    binding(
        &[(ch('q'), Action::Quit), (CTRL_C, Action::Quit)],
        "q, Ctrl-C", "quit (asks when there are unsaved edits; Ctrl-C works everywhere)",
        ("q", "quit", "quit", 0), ALL,
    ),
];

/// The binding of a key event on the main screen, with its action.
pub fn lookup(ev: &KeyEvent) -> Option<(&'static Binding, Action)> {
    BINDINGS.iter().find_map(|b| {
        b.keys
            .iter()
            .find(|(k, _)| k.matches(ev))
            .map(|(_, a)| (b, *a))
    })
}

/// True for Ctrl-C, which quits from every mode.
pub fn is_ctrl_c(ev: &KeyEvent) -> bool {
    CTRL_C.matches(ev)
}

/// The footer of the main screen for what is open (a problem, or a preset's `Open`), fitted to `width` columns: items two spaces
/// apart, else one space apart; while neither fits, items take their shorter word in the order
/// of their rank. Its characters are `style`'s (`RenderOptions::text`), so it is fitted as drawn.
pub fn footer(open: impl Into<Open>, width: usize, style: RenderOptions) -> String {
    let open = open.into();
    let items: Vec<_> = BINDINGS
        .iter()
        .filter(|b| b.only.applies(open) && !b.footer.0.is_empty())
        .map(|b| b.footer)
        .collect();
    let render = |shortened: u8, sep: &str| -> String {
        items
            .iter()
            .map(|&(k, long, short, rank)| {
                let word = if rank > 0 && rank <= shortened {
                    short
                } else {
                    long
                };
                let item = if word.is_empty() {
                    k.to_string()
                } else {
                    format!("{k} {word}")
                };
                style.text(&item).into_owned()
            })
            .collect::<Vec<_>>()
            .join(sep)
    };
    let fits = |s: &String| s.chars().count() <= width;
    (0..=u8::MAX)
        .flat_map(|shortened| [render(shortened, "  "), render(shortened, " ")])
        .find(fits)
        .unwrap_or_else(|| render(u8::MAX, " "))
}
