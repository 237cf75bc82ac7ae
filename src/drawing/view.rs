//! World to paper, the one way every drawing maps: the course's scale μ in world units per
//! paper millimetre (m/mm for a mechanism, (m/s)/mm for a velocity plan, N/mm for a force
//! polygon), paper mm = world / μ, the paper's y downward where the world's is up, and for
//! the pictures of a counter-clockwise cam the mirror image (x negated, as
//! `num::Sense::apply`).

use kurbo::{CubicBez, Point, Rect, Vec2};

/// A world-to-paper map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// μ, world units per paper mm.
    pub mu: f64,
    /// Where `anchor` is drawn, paper mm.
    pub origin: Point,
    /// The world point drawn at `origin`: the world's origin, or the centre of a box drawn
    /// centred.
    pub anchor: Vec2,
    /// Whether x is negated.
    pub mirror: bool,
}

impl View {
    /// The world's origin drawn at `origin`, at `mu`.
    pub fn new(origin: Point, mu: f64) -> View {
        View { mu, origin, anchor: Vec2::ZERO, mirror: false }
    }

    /// The world box `world` centred in the paper box `paper`, at `mu`.
    pub fn centred(world: Rect, paper: Rect, mu: f64) -> View {
        View { mu, origin: paper.center(), anchor: world.center().to_vec2(), mirror: false }
    }

    /// The same view, mirrored or not.
    pub fn mirrored(self, mirror: bool) -> View {
        View { mirror, ..self }
    }

    /// A world point on paper.
    pub fn p(&self, v: Vec2) -> Point {
        let d = v - self.anchor;
        let x = if self.mirror { -d.x } else { d.x };
        Point::new(self.origin.x + x / self.mu, self.origin.y - d.y / self.mu)
    }

    /// A world direction on paper, its length kept.
    pub fn dir(&self, v: Vec2) -> Vec2 {
        Vec2::new(if self.mirror { -v.x } else { v.x }, -v.y)
    }

    /// A world length on paper, mm.
    pub fn len(&self, world: f64) -> f64 {
        world / self.mu
    }

    /// A world cubic on paper.
    pub fn cubic(&self, c: &CubicBez) -> CubicBez {
        let p = |q: Point| self.p(q.to_vec2());
        CubicBez::new(p(c.p0), p(c.p1), p(c.p2), p(c.p3))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_world_is_drawn_at_its_scale_with_y_up_and_mirrored_on_request() {
        let v = View::new(Point::new(100.0, 200.0), 0.002);
        assert_eq!(v.p(Vec2::new(0.02, 0.04)), Point::new(110.0, 180.0));
        assert_eq!(v.len(0.02), 10.0);
        assert_eq!(v.dir(Vec2::new(1.0, 2.0)), Vec2::new(1.0, -2.0));
        let m = v.mirrored(true);
        assert_eq!(m.p(Vec2::new(0.02, 0.04)), Point::new(90.0, 180.0));
        assert_eq!(m.dir(Vec2::new(1.0, 2.0)), Vec2::new(-1.0, -2.0));
        let c = View::centred(Rect::new(1.0, 1.0, 3.0, 5.0), Rect::new(0.0, 0.0, 100.0, 100.0), 0.1);
        assert_eq!(c.p(Vec2::new(2.0, 3.0)), Point::new(50.0, 50.0));
        assert_eq!(c.p(Vec2::new(3.0, 5.0)), Point::new(60.0, 30.0));
    }
}
