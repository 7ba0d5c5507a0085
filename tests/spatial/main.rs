//! The spatial problem: complete contact, partial contact on the period cell and the running-in
//! by wear, against independent routes and classical results.

#[path = "../common/mod.rs"]
mod common;
mod hostile_contact;
#[path = "../limits_strategy/mod.rs"]
mod limits_strategy;
mod sie_reference;
mod spatial;
mod spatial_partial;
mod spatial_partial_adhesion;
mod spatial_partial_sie;
mod spatial_props;
mod spatial_running_in;
mod spatial_stop;
mod spatial_time_steps;
mod spatial_wear_law;
mod surface;
mod surface_area_load;
mod surface_egg_box;
mod surface_modes;
mod surface_solve;
