//! The plane problem (Soldatenkov (2007)): every model against independent routes, the energy
//! losses, the validity criteria, the quadrature rules and the dimensionless groups.

#[path = "../common/mod.rs"]
mod common;
mod gauss_jacobi;
mod groups;
#[path = "../limits_strategy/mod.rs"]
mod limits_strategy;
mod plane_energy;
mod plane_fuzz;
mod plane_general;
mod plane_general_strip;
mod plane_general_sweep;
mod plane_narrow;
mod plane_narrow_general;
mod plane_refinement;
mod plane_sharp;
mod plane_sharp_strip;
mod plane_strip;
mod plane_surface;
mod plane_validity;
mod plane_wide;
mod plane_yield;
mod shape_validity;
mod strip_check_words;
mod sweep_verdicts;
mod validity_study;
