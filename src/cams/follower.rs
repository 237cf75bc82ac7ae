//! The follower's motion in its own (fixed) frame, for a cam turning clockwise: the roller
//! centre B(φ), its derivatives, the direction it moves on the rise, and the end B′ of the
//! course's velocity-analog segment. A counter-clockwise cam is the mirror image (x → −x),
//! which [`super::Sense`] applies to finished coordinates only.
//!
//! The frame has its origin at B₀, the roller centre at the start of the rise, and the
//! rise's motion there along +y:
//! - translating: B = (0, s), the follower's axis is the y axis;
//! - rocker of length l: the pivot A = (l, 0), B = A + l(−cos β, sin β), so the rocker starts
//!   along −x from A and turns clockwise as β grows.
//!
//! **The analog point.** The course lays the segment ds/dφ (or l·dβ/dφ) from B across the
//! motion, turned 90° in the cam's sense; its end is B′ = B + (ds/dφ, 0) for a translating
//! follower and B′ = B + (dβ/dφ)(A − B) for a rocker. The line from the cam centre O to B′ is
//! parallel to the common normal at the contact (O, B′ and the relative pole P satisfy
//! B′ − O = (1 − k)(B − P), k = ω_follower/ω_cam), so the pressure angle is the angle between
//! OB′ and the motion: [`pressure_angle`]. This is why the nomogram works, and it makes the
//! admissible region of O an intersection of wedges with apexes B′.

use super::laws::Program;
use crate::num::math::{atan2, cos, sin};
use kurbo::Vec2;

/// The follower's kind and size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Follower {
    /// A translating (reciprocating) follower; the lift is the stroke, metres.
    Translating,
    /// A rocker (oscillating follower) of this length (pivot to roller centre), metres; the
    /// lift is the swing, radians.
    Rocker { length: f64 },
}

/// The follower at one cam angle, in the follower frame (metres).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct State {
    /// The roller centre B.
    pub b: Vec2,
    /// dB/dφ and d²B/dφ².
    pub db: Vec2,
    pub ddb: Vec2,
    /// The unit direction B moves in on the rise (tangent of its path).
    pub t: Vec2,
    /// The end of the velocity-analog segment, B′.
    pub analog: Vec2,
}

impl Follower {
    /// The rocker's pivot, when there is one.
    pub fn pivot(self) -> Option<Vec2> {
        match self {
            Follower::Translating => None,
            Follower::Rocker { length } => Some(Vec2::new(length, 0.0)),
        }
    }

    /// The follower at cam angle φ (radians from the start of the rise).
    pub fn state(self, program: &Program, phi: f64) -> State {
        let d = program.at(phi);
        match self {
            Follower::Translating => State {
                b: Vec2::new(0.0, d.s),
                db: Vec2::new(0.0, d.ds),
                ddb: Vec2::new(0.0, d.dds),
                t: Vec2::new(0.0, 1.0),
                analog: Vec2::new(d.ds, d.s),
            },
            Follower::Rocker { length: l } => {
                let (sb, cb) = (sin(d.s), cos(d.s));
                let a = Vec2::new(l, 0.0);
                let b = a + Vec2::new(-cb, sb) * l;
                // dB/dβ = l(sin β, cos β), d²B/dβ² = l(cos β, −sin β).
                let t = Vec2::new(sb, cb);
                let db = t * (l * d.ds);
                let ddb = Vec2::new(cb, -sb) * (l * d.ds * d.ds) + t * (l * d.dds);
                State { b, db, ddb, t, analog: b + (a - b) * d.ds }
            }
        }
    }
}

/// The pressure angle at φ for a cam centred at `o` (follower frame): the signed angle from
/// the rise's direction of motion to the line O→B′, radians. Its magnitude is what the
/// allowed angle limits; a centre on the wrong side gives a magnitude over 90°.
pub fn pressure_angle(s: &State, o: Vec2) -> f64 {
    let n = s.analog - o;
    atan2(s.t.cross(n), s.t.dot(n))
}
