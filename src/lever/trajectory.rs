//! A point's path over a crank turn as cubic Bézier pieces through exact points with exact
//! tangents (cubic Hermite interpolation in the course angle φ), subdivided until the pieces
//! stay within a stated distance of the exact path.

use super::linkage::{Mechanism, PointId};
use super::motion::{self, Motion, MotionError};
use crate::num::math::Norm;
use crate::num::tol;
use kurbo::{CubicBez, ParamCurve, Point, Vec2};
use std::f64::consts::TAU;

/// Pieces the fit starts from; each is then halved while it strays too far.
const INITIAL_PIECES: usize = 16;
/// Halvings of one piece at most (a piece of 2π/16/2¹² ≈ 1.5·10⁻⁴ rad); reached only at a
/// singular position, where the fit keeps what it has and reports its error.
const MAX_DEPTH: u32 = 12;

/// A fitted path, in world metres (y up).
#[derive(Debug, Clone, PartialEq)]
pub struct Fitted {
    pub cubics: Vec<CubicBez>,
    /// The distance the pieces were asked to keep to, m.
    pub tolerance: f64,
    /// The largest distance found between a piece and the exact point at the same φ
    /// (checked at a quarter, half and three quarters of every piece), m. A bound on the
    /// distance to the path itself, which can only be smaller.
    pub error: f64,
}

/// Fits the path of `point` over a whole turn to within `tol` metres. Pieces are halved until
/// their check points lie within half of `tol`: the error of a cubic Hermite piece is smooth
/// between its check points, so the whole piece then stays within `tol` (the tests check this
/// densely on every fixture).
pub fn fit(m: &Mechanism, motion: &Motion, point: PointId, tol: f64) -> Result<Fitted, MotionError> {
    // d/dφ = (d/dt) / (dφ/dt), and the crank turns at |ω1| in the course angle.
    let rate = m.omega1.abs();
    let exact = |phi: f64| -> Result<(Vec2, Vec2), MotionError> {
        let s = motion::sample_at(m, motion, phi)?;
        let k = s.points[point];
        Ok((k.p, k.v / rate))
    };
    let mut f = Fitted { cubics: Vec::new(), tolerance: tol, error: 0.0 };
    let h = TAU / INITIAL_PIECES as f64;
    let mut start = exact(0.0)?;
    for i in 0..INITIAL_PIECES {
        let b = (i + 1) as f64 * h;
        let end = if i + 1 == INITIAL_PIECES { exact(0.0)? } else { exact(b)? }; // the path closes exactly
        piece(&exact, (i as f64 * h, start), (b, end), tol / 2.0, 0, &mut f)?;
        start = end;
    }
    Ok(f)
}

type Exact<'a> = dyn Fn(f64) -> Result<(Vec2, Vec2), MotionError> + 'a;

/// Fits [a, b], halving it while a check point strays more than `tol`; appends in order.
fn piece(
    exact: &Exact,
    (a, pa): (f64, (Vec2, Vec2)),
    (b, pb): (f64, (Vec2, Vec2)),
    tol: f64,
    depth: u32,
    f: &mut Fitted,
) -> Result<(), MotionError> {
    let h = b - a;
    let c = CubicBez::new(
        pa.0.to_point(),
        (pa.0 + pa.1 * (h / 3.0)).to_point(),
        (pb.0 - pb.1 * (h / 3.0)).to_point(),
        pb.0.to_point(),
    );
    let mut worst: f64 = 0.0;
    let mut mid = None;
    for t in [0.25, 0.5, 0.75] {
        let e = exact(a + t * h)?;
        worst = worst.max((c.eval(t) - e.0.to_point()).norm());
        if t == 0.5 {
            mid = Some(e);
        }
    }
    if worst > tol && depth < MAX_DEPTH {
        let m = (a + b) / 2.0;
        let pm = mid.expect("checked at t = 0.5");
        piece(exact, (a, pa), (m, pm), tol, depth + 1, f)?;
        return piece(exact, (m, pm), (b, pb), tol, depth + 1, f);
    }
    f.error = f.error.max(worst);
    f.cubics.push(c);
    Ok(())
}

/// The point of a cubic nearest to `p` and its distance (for checking a fit densely).
pub fn distance_to(cubics: &[CubicBez], p: Point) -> f64 {
    use kurbo::ParamCurveNearest;
    cubics.iter().map(|c| c.nearest(p, tol::NEAREST).distance_sq).fold(f64::INFINITY, f64::min).sqrt()
}
