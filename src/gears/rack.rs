//! The generating rack (GOST 13755's cutter) as the course draws it cutting a wheel: its
//! teeth trapezoids of flank angle α, pitch p = πm, reaching (h_a* + c*)·m either side of
//! its datum (middle) line, each corner rounded with ρ = ρ_f*·m. Metres, the rack's frame:
//! X along the rolling line from a cutter tooth's middle, Y up from the rolling line, the
//! wheel below it (its centre at Y = −r); the datum line at Y = x·m (shifted away from the
//! wheel by a positive shift).

use super::wheel::{PairSpec, Wheel};
use crate::num::math::{cos, sin, tan};
use kurbo::Vec2;
use std::f64::consts::{FRAC_PI_2, PI};

/// The cutter that cuts one wheel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cutter {
    /// p = πm.
    pub pitch: f64,
    /// The datum line's height above the rolling line, x·m.
    pub datum: f64,
    /// The teeth's tip line and the spaces' root line (Y).
    pub tip: f64,
    pub root: f64,
    /// The corners' round.
    pub rho: f64,
    pub alpha: f64,
    /// The centre of the tip round on the right side of the tooth whose middle is X = 0.
    pub centre: Vec2,
}

/// A piece of the cutter's outline: a straight line, or an arc (angles counter-clockwise
/// from +X, radians).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Piece {
    Line(Vec2, Vec2),
    Arc { centre: Vec2, radius: f64, start: f64, sweep: f64 },
}

impl Piece {
    /// The piece mirrored in the vertical line X = x0 and run the other way, so that a
    /// right half's pieces, mirrored in reverse order, run on into it from the left.
    fn mirrored(self, x0: f64) -> Piece {
        let m = |v: Vec2| Vec2::new(2.0 * x0 - v.x, v.y);
        match self {
            Piece::Line(a, b) => Piece::Line(m(b), m(a)),
            Piece::Arc { centre, radius, start, sweep } => {
                Piece::Arc { centre: m(centre), radius, start: PI - start - sweep, sweep }
            }
        }
    }
}

impl Cutter {
    pub fn of(spec: &PairSpec, w: &Wheel) -> Cutter {
        let m = spec.module;
        let alpha = spec.pressure_angle;
        let rho = spec.tip_round() * m;
        let datum = w.shift * m;
        let depth = (spec.addendum + spec.clearance) * m;
        let yc = datum - depth + rho;
        // The round touches the tip line below its centre and the flank, which crosses the
        // datum line a quarter pitch from the tooth's middle, along the flank's normal.
        let xc = PI * m / 4.0 + (yc - datum) * tan(alpha) - rho / cos(alpha);
        Cutter { pitch: PI * m, datum, tip: datum - depth, root: datum + depth, rho, alpha, centre: Vec2::new(xc, yc) }
    }

    /// The right half of the tooth whose middle is at X = x0: from the middle of its tip to
    /// the middle of the space after it. The outline is symmetric about the point where the
    /// flank crosses the datum line, so the space's round is the tip's turned half a turn.
    fn right_half(&self, x0: f64) -> [Piece; 5] {
        let (a, rho) = (self.alpha, self.rho);
        let c = Vec2::new(x0 + self.centre.x, self.centre.y);
        let q = Vec2::new(x0 + self.pitch / 4.0, self.datum);
        let c2 = q * 2.0 - c;
        let normal = Vec2::new(cos(a), -sin(a));
        let t = c + normal * rho;
        [
            Piece::Line(Vec2::new(x0, self.tip), Vec2::new(c.x, self.tip)),
            Piece::Arc { centre: c, radius: rho, start: -FRAC_PI_2, sweep: FRAC_PI_2 - a },
            Piece::Line(t, q * 2.0 - t),
            Piece::Arc { centre: c2, radius: rho, start: PI - a, sweep: -(FRAC_PI_2 - a) },
            Piece::Line(Vec2::new(c2.x, self.root), Vec2::new(x0 + self.pitch / 2.0, self.root)),
        ]
    }

    /// The whole tooth whose middle is at X = x0, from the middle of the space before it to
    /// the middle of the space after it: consecutive teeth's pieces join end to end.
    pub fn tooth(&self, x0: f64) -> Vec<Piece> {
        let right = self.right_half(x0);
        right.iter().rev().map(|p| p.mirrored(x0)).chain(right).collect()
    }

    /// The point of the right flank of the tooth at X = x0 on the datum line.
    pub fn flank_on_datum(&self, x0: f64) -> Vec2 {
        Vec2::new(x0 + self.pitch / 4.0, self.datum)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gears::pair::Pair;
    use crate::gears::tooth::{Outline, polar};
    use crate::num::math::{Norm, rotate};

    fn ends(p: Piece) -> (Vec2, Vec2) {
        match p {
            Piece::Line(a, b) => (a, b),
            Piece::Arc { centre, radius, start, sweep } => (
                centre + Vec2::new(cos(start), sin(start)) * radius,
                centre + Vec2::new(cos(start + sweep), sin(start + sweep)) * radius,
            ),
        }
    }

    /// The pieces join end to end, within a tooth and from one tooth to the next.
    #[test]
    fn the_outline_is_continuous() {
        let spec = PairSpec { shift: [0.6, 0.36], ..PairSpec::standard(0.003, [12, 24]) };
        let pair = Pair::new(&spec).unwrap();
        let c = Cutter::of(&pair.spec, &pair.wheels[0]);
        let pieces: Vec<Piece> = (-1..=1).flat_map(|k| c.tooth(f64::from(k) * c.pitch)).collect();
        for w in pieces.windows(2) {
            let (_, b) = ends(w[0]);
            let (a, _) = ends(w[1]);
            assert!((a - b).norm() < 1e-12, "{w:?}");
        }
        assert!(c.centre.x > 0.0);
    }

    /// The cutter's flank touches the wheel's involute where the line of generation (the
    /// normal to the flank through the pole) meets it: the point is on the exact outline.
    #[test]
    fn the_flank_touches_the_involute_on_the_line_of_generation() {
        for (z, x) in [(12, 0.6), (17, 0.0), (30, -0.4), (80, 0.5)] {
            let spec = PairSpec { shift: [x, 0.0], ..PairSpec::standard(0.004, [z, 40]) };
            let pair = Pair::new(&spec).unwrap();
            let w = &pair.wheels[0];
            let c = Cutter::of(&pair.spec, w);
            let o = Outline::new(&pair.spec, w);
            // The wheel's frame: centre at the origin, the pole P at (0, r).
            let on_flank = c.flank_on_datum(0.0) + Vec2::new(0.0, w.pitch);
            let normal = Vec2::new(cos(c.alpha), -sin(c.alpha));
            let pole = Vec2::new(0.0, w.pitch);
            let k = pole + normal * (on_flank - pole).dot(normal);
            // Outline's frame has the tooth on +x; the tooth right of the gap on +y is at
            // π/2 − π/z.
            let turned = rotate(k, -(FRAC_PI_2 - PI / f64::from(z)));
            let r = turned.norm();
            assert!(r > w.base && r < w.tip, "z {z}: {r} outside the flank");
            assert!((polar(turned) - o.involute_angle(r)).abs() < 1e-9, "z {z} x {x}");
        }
    }
}
