//! The colour maps of the pressure map and the regime map, for the terminal and the SVG alike:
//! viridis (perceptually uniform, readable with the common colour-vision deficiencies and in
//! grey); in the terminal the pressure map's few filled bands, one colour each, and the regime
//! map's few dozen levels, so that a slowly changing field redraws few cells; their nearest
//! colours in the 256-colour palette for terminals that do not announce truecolor.

/// Levels of the regime map's quantised map.
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

/// The colour of band `band` of `bands` filled bands over the bar: viridis at the band's centre.
pub fn band_colour(band: usize, bands: usize) -> (u8, u8, u8) {
    viridis((band as f64 + 0.5) / bands.max(1) as f64)
}

/// The 256-colour palette's index of each of `bands` bands: the nearest to its colour among
/// those lighter than the band under it, so that every band keeps a colour of its own and the
/// bands their order in lightness, as viridis has it (the nearest alone can be one index for two
/// bands, 8 bands' second and third, or darker above: 7 bands' third, 0, 95, 135, under their
/// second, 95, 95, 135).
pub fn bands_256(bands: usize) -> Vec<u8> {
    let mut chosen: Vec<u8> = Vec::with_capacity(bands);
    for band in 0..bands {
        let under = chosen.last().map_or(-1.0, |&i| luminance(xterm(i)));
        let lighter = (16..=255u8).filter(|&i| luminance(xterm(i)) > under);
        chosen.push(nearest(band_colour(band, bands), lighter));
    }
    chosen
}

/// Relative luminance (ITU-R BT.709 weights) of a colour, from 0 to 255.
fn luminance((r, g, b): (u8, u8, u8)) -> f64 {
    0.2126 * r as f64 + 0.7152 * g as f64 + 0.0722 * b as f64
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
fn nearest_256(colour: (u8, u8, u8)) -> u8 {
    nearest(colour, 16..=255u8)
}

/// The index among `indices` (of the palette from 16) whose colour is nearest to `colour`.
fn nearest((r, g, b): (u8, u8, u8), indices: impl Iterator<Item = u8>) -> u8 {
    let d = |(p, q, s): (u8, u8, u8)| {
        let sq = |a: u8, b: u8| (a as i32 - b as i32).pow(2);
        sq(p, r) + sq(q, g) + sq(s, b)
    };
    indices.min_by_key(|&i| d(xterm(i))).unwrap_or(16)
}

#[cfg(test)]
mod tests {
    #[test]
    fn bands_in_256_colours_are_distinct_never_the_empty_grey_and_lighten_upwards() {
        // viridis lightens monotonically from its dark purple to its yellow, so that the bands
        // keep their order in grey and to common colour-vision deficiencies; the palette's
        // nearest colours keep that order for every count of bands drawn (1 to 8)
        for n in 1..=8 {
            let indices = super::bands_256(n);
            for (i, &k) in indices.iter().enumerate() {
                assert!(!indices[i + 1..].contains(&k), "{n}: {indices:?}");
                assert_ne!(k, super::EMPTY_256);
            }
            let light: Vec<f64> = indices
                .iter()
                .map(|&k| super::luminance(super::xterm(k)))
                .collect();
            assert!(light.windows(2).all(|p| p[0] < p[1]), "{n}: {light:?}");
        }
    }
}
