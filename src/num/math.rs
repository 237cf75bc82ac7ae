//! The mathematical functions whose results reach an output, from the `libm` crate (a port of
//! musl's) rather than the platform's C library, so that a sheet's bytes do not depend on the
//! operating system it is built on. `clippy.toml` forbids the platform versions in `src/`.
//! Square roots need no such care: IEEE 754 rounds them exactly everywhere.

use kurbo::{Point, Rect, Vec2};

pub fn sin_cos(x: f64) -> (f64, f64) {
    libm::sincos(x)
}

pub fn sin(x: f64) -> f64 {
    libm::sin(x)
}

pub fn cos(x: f64) -> f64 {
    libm::cos(x)
}

pub fn asin(x: f64) -> f64 {
    libm::asin(x)
}

pub fn acos(x: f64) -> f64 {
    libm::acos(x)
}

pub fn atan2(y: f64, x: f64) -> f64 {
    libm::atan2(y, x)
}

pub fn tan(x: f64) -> f64 {
    libm::tan(x)
}

pub fn atan(x: f64) -> f64 {
    libm::atan(x)
}

pub fn cbrt(x: f64) -> f64 {
    libm::cbrt(x)
}

pub fn log10(x: f64) -> f64 {
    libm::log10(x)
}

/// The unit vector at `angle` radians from the x axis.
pub fn from_angle(angle: f64) -> Vec2 {
    let (s, c) = sin_cos(angle);
    Vec2::new(c, s)
}

/// `v` turned counter-clockwise by `angle` radians.
pub fn rotate(v: Vec2, angle: f64) -> Vec2 {
    let (s, c) = sin_cos(angle);
    Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

/// The orientations of `a` and `b` about the line `c`–`d`, then of `c` and `d` about `a`–`b`
/// (twice the signed triangles' areas): what decides whether the two segments cross.
pub fn orientations(a: Vec2, b: Vec2, c: Vec2, d: Vec2) -> [f64; 4] {
    let orient = |p: Vec2, q: Vec2, r: Vec2| (q - p).cross(r - p);
    [orient(c, d, a), orient(c, d, b), orient(a, b, c), orient(a, b, d)]
}

/// Whether segments `a`–`b` and `c`–`d` cross strictly: each pair of ends on opposite sides
/// of the other's line (segments that meet end to end, or lie along one line, do not).
pub fn segments_cross_strictly(a: Vec2, b: Vec2, c: Vec2, d: Vec2) -> bool {
    let [d1, d2, d3, d4] = orientations(a, b, c, d);
    d1 * d2 < 0.0 && d3 * d4 < 0.0
}

/// Whether `r` lies inside `outer` (its edges may touch).
pub fn rect_inside(outer: Rect, r: Rect) -> bool {
    r.x0 >= outer.x0 && r.y0 >= outer.y0 && r.x1 <= outer.x1 && r.y1 <= outer.y1
}

/// [`segments_cross_strictly`] for two segments given by their end points (two leaders,
/// a leader and a dimension line).
pub fn lines_cross((a, b): (Point, Point), (c, d): (Point, Point)) -> bool {
    segments_cross_strictly(a.to_vec2(), b.to_vec2(), c.to_vec2(), d.to_vec2())
}

/// Lengths and directions of vectors through an exactly rounded square root.
pub trait Norm {
    /// √(x² + y²): inputs are limited to ±10⁹, so the squares cannot overflow.
    fn norm(self) -> f64;
    /// The vector divided by its length.
    fn unit(self) -> Vec2;
    /// Its angle from the x axis (the argument), radians in (−π, π].
    fn arg(self) -> f64;
}

impl Norm for Vec2 {
    fn norm(self) -> f64 {
        self.hypot2().sqrt()
    }

    fn unit(self) -> Vec2 {
        self / self.norm()
    }

    fn arg(self) -> f64 {
        atan2(self.y, self.x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_functions_agree_with_their_definitions() {
        let v = from_angle(0.3);
        assert!((v.norm() - 1.0).abs() < 1e-16 && (v.arg() - 0.3).abs() < 1e-16);
        assert_eq!(Vec2::new(3.0, 4.0).norm(), 5.0);
        assert_eq!(log10(1000.0), 3.0);
        assert!((asin(sin(0.7)) - 0.7).abs() < 1e-15 && (acos(cos(0.7)) - 0.7).abs() < 1e-15);
        let r = rotate(Vec2::new(2.0, 0.0), std::f64::consts::FRAC_PI_2);
        crate::assert_near!(r.x, 0.0, crate::num::Near::abs(1e-15));
        crate::assert_near!(r.y, 2.0);
    }

    /// `rotate` takes sine and cosine from one `sin_cos`; the rotations it replaced took them
    /// apart. They agree to the bit (libm's sincos runs sin's and cos's kernels), over every
    /// range the argument reduction treats apart.
    #[test]
    fn sin_cos_is_sin_and_cos_to_the_bit() {
        let mut x = 1e-12f64;
        while x < 1e6 {
            for a in [x, -x, x * 1.000_000_1, -x * 0.999_999_7] {
                assert_eq!(sin_cos(a), (sin(a), cos(a)), "{a:e}");
            }
            x *= 1.001;
        }
    }
}
