//! The `[spatial]` section of a preset file: the mean pressure, speed, times, grid, sweep and the
//! harmonics or height map, each against `physics::limits`, refusals `path:line: reason`.

use toml::Spanned;

use crate::physics::limits;
use crate::physics::spatial::harmonic::Harmonic;
use crate::physics::spatial::partial::grid::check_side;
use crate::physics::spatial::{validate_grid, validate_harmonics};
use crate::preset::check::Checker;
use crate::preset::file::FileSpatial;
use crate::preset::surface_set::grid_beside_map;
use crate::preset::{
    PresetError, SpatialSection, default_pressure_sweep, default_spatial_section, plausible,
};

impl Checker<'_> {
    /// The `[spatial]` section, and whether it gives a duration.
    pub(super) fn spatial(
        &self,
        spatial: &Spanned<FileSpatial>,
    ) -> Result<(SpatialSection, bool), PresetError> {
        let sp = spatial.get_ref();
        let mean_pressure = self.value(
            &sp.mean_pressure,
            "spatial.mean_pressure",
            &limits::MEAN_PRESSURE,
        )?;
        let surface = match &sp.surface {
            Some(s) if !sp.harmonics.is_empty() => {
                return Err(self.error(
                    Some(s.span()),
                    "give spatial.surface or [[spatial.harmonics]], not both: the punch is a \
                     height map or a sum of harmonics",
                ));
            }
            Some(s) => Some(self.surface(s)?),
            None => None,
        };
        let mut harmonics = Vec::new();
        for fh in &sp.harmonics {
            let h = fh.get_ref();
            let harmonic = Harmonic {
                amplitude: self.value(
                    &h.amplitude,
                    "spatial.harmonics.N.amplitude",
                    &limits::AMPLITUDE,
                )?,
                wavenumber_x: self.value(
                    &h.wavenumber_x,
                    "spatial.harmonics.N.wavenumber_x",
                    &limits::WAVENUMBER,
                )?,
                wavenumber_y: self.value(
                    &h.wavenumber_y,
                    "spatial.harmonics.N.wavenumber_y",
                    &limits::WAVENUMBER,
                )?,
                phase_x: self.value(&h.phase_x, "spatial.harmonics.N.phase_x", &limits::PHASE)?,
                phase_y: self.value(&h.phase_y, "spatial.harmonics.N.phase_y", &limits::PHASE)?,
            };
            if let Some((phase, why)) = plausible::vanishes(&harmonic) {
                let at = if phase == "phase_y" {
                    &h.phase_y
                } else {
                    &h.phase_x
                };
                self.warn(Some(at.span()), why);
            }
            harmonics.push(harmonic);
            // the wave-vector rules (nonzero, not repeated) are the solver's
            if let Err(e) = validate_harmonics(&harmonics) {
                let why = e.to_string();
                return Err(self.error(Some(fh.span()), why.trim_start_matches("invalid input: ")));
            }
        }
        if harmonics.is_empty() && surface.is_none() {
            return Err(self.error(
                Some(spatial.span()),
                "[spatial] has no [[spatial.harmonics]]: the punch needs at least one harmonic",
            ));
        }
        let sweep = match &sp.sweep {
            Some(sw) => {
                let s = sw.get_ref();
                self.sweep(
                    [&s.pressure_min, &s.pressure_max],
                    ["spatial.sweep.pressure_min", "spatial.sweep.pressure_max"],
                    &limits::MEAN_PRESSURE,
                    &s.points,
                    s.scale,
                )?
            }
            None => default_pressure_sweep(mean_pressure),
        };
        let (grid, span) = match (&sp.grid, &surface) {
            (Some(grid), Some(map)) => {
                return Err(self.error(Some(grid.span()), grid_beside_map(&map.surface)));
            }
            (Some(grid), None) => (self.count(grid, "grid", &limits::GRID)?, grid.span()),
            (None, _) => (default_spatial_section().grid, spatial.span()),
        };
        (validate_grid(&harmonics, grid))
            .and_then(|()| match surface {
                Some(_) => Ok(()),
                None => check_side(grid),
            })
            .map_err(|e| {
                let why = e.to_string();
                self.error(Some(span), why.trim_start_matches("invalid input: "))
            })?;
        let section = SpatialSection {
            mean_pressure,
            sliding_speed: self.value(
                &sp.sliding_speed,
                "spatial.sliding_speed",
                &limits::SPEED,
            )?,
            time: self.value(&sp.time, "spatial.time", &limits::TIME)?,
            duration: match &sp.duration {
                Some(d) => self.value(d, "spatial.duration", &limits::DURATION)?,
                None => default_spatial_section().duration,
            },
            grid,
            time_tolerance: match &sp.time_tolerance {
                Some(t) => self.value(t, "spatial.time_tolerance", &limits::TIME_TOLERANCE)?,
                None => default_spatial_section().time_tolerance,
            },
            sweep,
            harmonics,
            surface,
        };
        Ok((section, sp.duration.is_some()))
    }
}
