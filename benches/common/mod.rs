//! What several benches share.

pub mod cpu_time;
