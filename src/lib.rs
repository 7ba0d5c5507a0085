//! wearlab: sliding contact with friction and wear — the physics, the preset files and the
//! reports. No terminal code lives here.

pub mod engine;
pub mod explore;
pub mod finite;
pub mod physics;
pub mod preset;
pub mod report;
pub mod spatial_report;
pub mod units;
