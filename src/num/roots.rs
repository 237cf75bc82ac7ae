//! The one root finder: bisection on a sign change, for functions whose evaluation can fail
//! (a mechanism that does not assemble at some angle). On failure it returns why and every
//! iterate, so an error can show how the search went.

/// One evaluation of the search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Iterate {
    pub x: f64,
    pub fx: f64,
}

/// Why a search failed, with its log.
#[derive(Debug, Clone, PartialEq)]
pub enum RootError<E> {
    /// f has the same sign at both ends of the bracket.
    NoSignChange { lo: Iterate, hi: Iterate },
    /// f could not be evaluated at `x`; `log` has the iterates before it.
    Evaluation { x: f64, error: E, log: Vec<Iterate> },
}

impl<E: std::fmt::Display> std::fmt::Display for RootError<E> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RootError::NoSignChange { lo, hi } => {
                write!(f, "no sign change between f({}) = {:e} and f({}) = {:e}", lo.x, lo.fx, hi.x, hi.fx)
            }
            RootError::Evaluation { x, error, log } => {
                write!(f, "f({x}) failed ({error}) after {} iterations", log.len())?;
                for it in log.iter().rev().take(3) {
                    write!(f, "; f({}) = {:e}", it.x, it.fx)?;
                }
                Ok(())
            }
        }
    }
}

/// A root of `f` in [lo, hi], where f(lo) and f(hi) have opposite signs (or one is zero),
/// to within `x_tol` or the resolution of f64, whichever is reached first. Exact zeros end
/// the search early. Returns the last bracket's midpoint.
pub fn bisect<E>(mut f: impl FnMut(f64) -> Result<f64, E>, lo: f64, hi: f64, x_tol: f64) -> Result<f64, RootError<E>> {
    let mut log = Vec::new();
    let mut eval = |x: f64, log: &mut Vec<Iterate>| match f(x) {
        Ok(fx) => {
            log.push(Iterate { x, fx });
            Ok(fx)
        }
        Err(error) => Err(RootError::Evaluation { x, error, log: std::mem::take(log) }),
    };
    let (mut a, mut b) = (lo, hi);
    let fa = eval(a, &mut log)?;
    if fa == 0.0 {
        return Ok(a);
    }
    let fb = eval(b, &mut log)?;
    if fb == 0.0 {
        return Ok(b);
    }
    if fa.signum() == fb.signum() {
        return Err(RootError::NoSignChange { lo: Iterate { x: a, fx: fa }, hi: Iterate { x: b, fx: fb } });
    }
    let sa = fa.signum();
    // 200 halvings exhaust any f64 interval; the loop ends earlier on x_tol or resolution.
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if (b - a).abs() <= x_tol || m == a || m == b {
            break;
        }
        let fm = eval(m, &mut log)?;
        if fm == 0.0 {
            return Ok(m);
        }
        if fm.signum() == sa {
            a = m;
        } else {
            b = m;
        }
    }
    Ok(0.5 * (a + b))
}

/// Golden-section steps at most (0.618⁴⁰⁰ ≈ 1e-84 of the starting interval).
const MAX_GOLDEN_STEPS: usize = 400;

/// The minimum of `f` on [lo, hi] by golden-section search, for a function with one minimum
/// there; `x_tol` as in [`bisect`]. Failed evaluations are returned at once with their `x`.
pub fn minimise<E>(
    mut f: impl FnMut(f64) -> Result<f64, E>,
    lo: f64,
    hi: f64,
    x_tol: f64,
) -> Result<Iterate, (f64, E)> {
    const INV_PHI: f64 = 0.618_033_988_749_894_9; // (√5 − 1)/2
    let mut eval = |x: f64| f(x).map_err(|e| (x, e));
    let (mut a, mut b) = (lo, hi);
    let mut c = b - INV_PHI * (b - a);
    let mut d = a + INV_PHI * (b - a);
    let (mut fc, mut fd) = (eval(c)?, eval(d)?);
    // A tolerance below the spacing of doubles at [a, b] cannot be met: the interval stops
    // shrinking. 400 steps shrink any finite interval below that spacing.
    let mut steps = 0;
    while (b - a).abs() > x_tol && steps < MAX_GOLDEN_STEPS {
        steps += 1;
        if fc < fd {
            b = d;
            d = c;
            fd = fc;
            c = b - INV_PHI * (b - a);
            fc = eval(c)?;
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + INV_PHI * (b - a);
            fd = eval(d)?;
        }
    }
    Ok(if fc < fd { Iterate { x: c, fx: fc } } else { Iterate { x: d, fx: fd } })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bisection_finds_a_root_to_the_last_bit() {
        let r = bisect(|x| Ok::<_, ()>(x * x - 2.0), 0.0, 2.0, 0.0).unwrap();
        assert!((r - std::f64::consts::SQRT_2).abs() <= 2.0 * f64::EPSILON);
    }

    #[test]
    fn failures_keep_their_log() {
        assert!(matches!(bisect(|x| Ok::<_, ()>(x + 5.0), 0.0, 1.0, 0.0), Err(RootError::NoSignChange { .. })));
        let f = |x: f64| if (0.6..0.64).contains(&x) { Err("no assembly") } else { Ok(x - 0.62) };
        let e = bisect(f, 0.0, 1.0, 1e-9).unwrap_err();
        match &e {
            RootError::Evaluation { x, log, .. } => assert!(*x == 0.625 && log.len() == 4, "{x} {log:?}"),
            other => panic!("{other:?}"),
        }
        assert!(e.to_string().contains("failed (no assembly)"), "{e}");
    }

    #[test]
    fn golden_section_finds_a_minimum() {
        let m = minimise(|x| Ok::<_, ()>((x - 0.3).powi(2) + 1.0), -1.0, 1.0, 1e-10).unwrap();
        // Near a minimum f is flat to √ε, which bounds how well any comparison search locates it.
        assert!((m.x - 0.3).abs() < 1e-7 && (m.fx - 1.0).abs() < 1e-14, "{m:?}");
        assert!(minimise(|x| if x > 0.5 { Err(x) } else { Ok(x) }, 0.0, 1.0, 1e-9).unwrap_err().1 > 0.5);
    }
}
