//! Subcommands of the binary that have a file of their own.

pub mod sweep;
