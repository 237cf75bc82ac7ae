//! Kinematic state of points and links, in SI units (m, m/s, m/s², rad, rad/s, rad/s²).

use crate::num::math::Norm;
use kurbo::Vec2;

/// Position, velocity and acceleration of a point.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Kin {
    pub p: Vec2,
    pub v: Vec2,
    pub a: Vec2,
}

impl Kin {
    /// A point of the frame: fixed, no velocity or acceleration.
    pub fn fixed(p: Vec2) -> Self {
        Kin { p, v: Vec2::ZERO, a: Vec2::ZERO }
    }
}

/// A link's reference direction (a unit vector; the angle is computed on demand, which
/// keeps `atan2` off the solver's hot path), its angular velocity ω and acceleration ε
/// (counter-clockwise positive).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LinkKin {
    pub dir: Vec2,
    pub omega: f64,
    pub eps: f64,
}

impl LinkKin {
    /// Angle of the reference direction, radians in (−π, π].
    pub fn angle(&self) -> f64 {
        self.dir.arg()
    }
}

/// Motion of point `x` relative to point `y` of the same link: r = x − y.
/// Returns (v_xy, aⁿ_xy, aᵗ_xy) as vectors.
pub fn relative(r: Vec2, link: &LinkKin) -> (Vec2, Vec2, Vec2) {
    (r.turn_90() * link.omega, -r * (link.omega * link.omega), r.turn_90() * link.eps)
}
