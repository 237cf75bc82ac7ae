//! The cam's profile by inversion: the follower carried round the cam the other way.
//!
//! In the cam's frame (origin O, axes those of the follower frame at φ = 0, the cam turning
//! clockwise) a point X fixed to the follower frame is at R(φ)(X − O), R the counter-clockwise
//! rotation. The pitch (theoretical) profile is the roller centre's path,
//! P(φ) = R(φ)(B(φ) − O), with P′ = R(JX + X′) and P″ = R(−X + 2JX′ + X″), X = B − O, J the
//! quarter turn: exact derivatives, so the curvature is exact too.
//!
//! The pitch profile runs counter-clockwise round O; where it turns left (κ > 0) it is convex
//! and a roller of radius r needs r < ρ = 1/κ. The working profile is the roller's envelope,
//! the inner offset W = P − r·N (N the outward normal), whose tangent is P′(1 − rκ): parallel
//! to P′ while r < ρ_min, so the envelope is smooth and exactly r from the pitch profile.

use super::follower::{Follower, State};
use super::laws::Program;
use super::radius::sup;
use crate::num::bezier::{self, Fitted};
use crate::num::math::Norm;
use crate::num::math::{atan2, rotate};
use crate::num::tol;
use kurbo::Vec2;
use std::f64::consts::PI;

/// A cam's profiles for a centre O (follower frame).
#[derive(Debug, Clone)]
pub struct Profile {
    pub follower: Follower,
    pub program: Program,
    pub o: Vec2,
}

/// A pitch-profile point with its derivatives in φ (cam frame, metres).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PitchPoint {
    pub p: Vec2,
    pub dp: Vec2,
    pub ddp: Vec2,
}

fn quarter(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// The four parts of a turn: each is smooth, joints may have curvature jumps.
pub fn parts(p: &Program) -> [(f64, f64); 4] {
    let (a, b, c) = (p.rise, p.rise + p.far_dwell, p.rise + p.far_dwell + p.ret);
    [(0.0, a), (a, b), (b, c), (c, 2.0 * PI)]
}

impl Profile {
    pub fn state(&self, phi: f64) -> State {
        self.follower.state(&self.program, phi)
    }

    pub fn pitch(&self, phi: f64) -> PitchPoint {
        let s = self.state(phi);
        let x = s.b - self.o;
        PitchPoint {
            p: rotate(x, phi),
            dp: rotate(quarter(x) + s.db, phi),
            ddp: rotate(-x + quarter(s.db) * 2.0 + s.ddb, phi),
        }
    }

    /// The pitch profile's signed curvature, 1/m (positive where it is convex).
    pub fn curvature(&self, phi: f64) -> f64 {
        let q = self.pitch(phi);
        q.dp.cross(q.ddp) / q.dp.norm().powi(3)
    }

    /// A follower-frame point as the inversion carries it at cam angle φ: cam frame, metres
    /// (the rocker's pivot sweeps the circle of radius a_w, the translating follower's axis
    /// stays tangent to the circle of radius e).
    pub fn carried(&self, x: Vec2, phi: f64) -> Vec2 {
        rotate(x - self.o, phi)
    }

    /// The smallest radius of curvature over the convex parts, and its φ (a turn
    /// with no convex part cannot be: the profile closes round O).
    pub fn min_convex_radius(&self) -> (f64, f64) {
        let (phi, kappa) = parts(&self.program)
            .into_iter()
            .filter(|(a, b)| b > a)
            .map(|span| sup(span, |phi| self.curvature(phi)))
            .fold((0.0, f64::NEG_INFINITY), |m, x| if x.1 > m.1 { x } else { m });
        (phi, 1.0 / kappa)
    }

    /// The working profile's point and tangent at φ for a roller of radius r.
    pub fn working(&self, r: f64, phi: f64) -> (Vec2, Vec2) {
        let q = self.pitch(phi);
        let len = q.dp.norm();
        let tangent = q.dp / len;
        let outward = Vec2::new(tangent.y, -tangent.x);
        let kappa = q.dp.cross(q.ddp) / len.powi(3);
        (q.p - outward * r, q.dp * (1.0 - r * kappa))
    }

    /// The pressure angle read off the finished profile: the pitch profile's normal at φ
    /// taken back to the follower frame, against the follower's motion (radians, magnitude).
    /// Independent of the analog construction the centre was found with.
    pub fn pressure_angle_on_profile(&self, phi: f64) -> f64 {
        let q = self.pitch(phi);
        let normal = rotate(quarter(q.dp), -phi);
        let t = self.state(phi).t;
        let a = atan2(t.cross(normal), t.dot(normal)).abs();
        a.min(PI - a)
    }

    /// Polar coordinates (radius, angle from the start of the rise's radius, radians in
    /// [0, 2π)) of a cam-frame point.
    pub fn polar(&self, p: Vec2) -> (f64, f64) {
        let start = self.state(0.0).b - self.o;
        let a = atan2(start.cross(p), start.dot(p));
        (p.norm(), a.rem_euclid(2.0 * PI))
    }

    /// The pitch (r = 0) or working profile as cubic pieces, part by part, each part within
    /// `tol` metres (measured).
    pub fn cubics(&self, r: f64, tol: f64, max_pieces: usize) -> Vec<Fitted> {
        let exact = |phi: f64| if r == 0.0 { (self.pitch(phi).p, self.pitch(phi).dp) } else { self.working(r, phi) };
        parts(&self.program)
            .into_iter()
            .filter(|(a, b)| b - a > tol::ANGLE_ROUND_OFF)
            .map(|(a, b)| bezier::fit_within(&exact, a, b, tol, max_pieces))
            .collect()
    }
}
