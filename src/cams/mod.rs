//! The cam of sheet 3, pure and dimensionless or SI: the follower's laws of motion
//! ([`laws`]). The diagrams, the minimum radius and the profile are later steps of issue 10.

pub mod laws;
