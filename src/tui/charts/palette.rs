//! The colour map of the pressure map, for the terminal and the SVG alike: viridis (perceptually
//! uniform, readable with the common colour-vision deficiencies and in grey), quantised to a few
//! dozen levels so that a slowly changing field redraws few cells, and its nearest colours in the
//! 256-colour palette for terminals that do not announce truecolor.

/// Levels of the quantised map.
pub const LEVELS: usize = 24;

/// viridis at t = 0, 0.1, ..., 1 (matplotlib's `viridis` colour map, van der Walt and Smith,
/// 2015), interpolated linearly between.
const VIRIDIS: [(u8, u8, u8); 11] = [
    (68, 1, 84),
    (72, 36, 117),
    (65, 68, 135),
    (53, 95, 141),
    (42, 120, 142),
    (33, 145, 140),
    (34, 168, 132),
    (68, 191, 112),
    (122, 209, 81),
    (189, 223, 38),
    (253, 231, 37),
];

/// The colour of an empty value (no contact on the pressure map): a light grey, which viridis
/// never is.
pub const EMPTY: (u8, u8, u8) = (190, 190, 190);

/// Its nearest colour in the 256-colour palette (grey 250: 188, 188, 188).
pub const EMPTY_256: u8 = 250;

/// The colour of t in [0, 1] (clamped; NaN is the lowest).
pub fn viridis(t: f64) -> (u8, u8, u8) {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let x = t * (VIRIDIS.len() - 1) as f64;
    let i = (x.floor() as usize).min(VIRIDIS.len() - 2);
    let f = x - i as f64;
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    let mix = |p: u8, q: u8| (p as f64 + f * (q as f64 - p as f64)).round() as u8;
    (mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The level (0..LEVELS) of t in [0, 1].
pub fn level(t: f64) -> usize {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    (t * (LEVELS - 1) as f64).round() as usize
}

/// The colour of a level.
pub fn level_colour(level: usize) -> (u8, u8, u8) {
    viridis(level as f64 / (LEVELS - 1) as f64)
}

/// The xterm 256-colour palette's colour of an index from 16 (the 6x6x6 cube, then 24 greys).
fn xterm(index: u8) -> (u8, u8, u8) {
    const STEPS: [u8; 6] = [0, 95, 135, 175, 215, 255];
    if index >= 232 {
        let g = 8 + 10 * (index - 232);
        return (g, g, g);
    }
    let i = index - 16;
    (
        STEPS[(i / 36) as usize],
        STEPS[(i / 6 % 6) as usize],
        STEPS[(i % 6) as usize],
    )
}

/// The 256-colour palette's index of a level (computed once).
pub fn level_256(level: usize) -> u8 {
    static TABLE: std::sync::OnceLock<Vec<u8>> = std::sync::OnceLock::new();
    let table = TABLE.get_or_init(|| (0..LEVELS).map(|l| nearest_256(level_colour(l))).collect());
    table[level.min(LEVELS - 1)]
}

/// The index (16..=255) of the 256-colour palette nearest to a colour.
fn nearest_256((r, g, b): (u8, u8, u8)) -> u8 {
    let d = |(p, q, s): (u8, u8, u8)| {
        let sq = |a: u8, b: u8| (a as i32 - b as i32).pow(2);
        sq(p, r) + sq(q, g) + sq(s, b)
    };
    (16..=255u8).min_by_key(|&i| d(xterm(i))).unwrap_or(16)
}
