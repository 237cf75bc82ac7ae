//! How near two numbers are, for the tests: one tolerance type and one macro,
//! [`assert_near!`](crate::assert_near), instead of a `close` or `approx` per test file.

/// How near two numbers must be: `rel` of the larger magnitude plus `abs`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Near {
    /// Relative to max(|a|, |b|).
    pub rel: f64,
    /// Absolute, in the numbers' unit.
    pub abs: f64,
}

impl Near {
    /// Relative only.
    pub const fn rel(rel: f64) -> Near {
        Near { rel, abs: 0.0 }
    }

    /// Absolute only.
    pub const fn abs(abs: f64) -> Near {
        Near { rel: 0.0, abs }
    }

    /// This tolerance with an absolute floor besides: for a quantity that may be zero.
    pub const fn floor(self, abs: f64) -> Near {
        Near { rel: self.rel, abs }
    }

    /// |a − b| ≤ rel·max(|a|, |b|) + abs.
    pub fn holds(self, a: f64, b: f64) -> bool {
        (a - b).abs() <= self.rel * a.abs().max(b.abs()) + self.abs
    }
}

/// A bare number is a relative tolerance.
impl From<f64> for Near {
    fn from(rel: f64) -> Near {
        Near::rel(rel)
    }
}

/// Asserts that two numbers are near: within [`tol::NEAR`](crate::num::tol::NEAR) (relative)
/// by default, or within a given tolerance (a relative one as a bare number, or a [`Near`]),
/// with an optional message.
///
/// ```
/// use tmm_sheets::assert_near;
/// use tmm_sheets::num::Near;
///
/// assert_near!(0.1 + 0.2, 0.3);
/// assert_near!(1000.0, 1000.5, 1e-3);
/// assert_near!(0.0, 1e-13, Near::rel(1e-9).floor(1e-12), "a zero, to {}", "round-off");
/// ```
#[macro_export]
macro_rules! assert_near {
    ($a:expr, $b:expr $(,)?) => {
        $crate::assert_near!($a, $b, $crate::num::tol::NEAR)
    };
    ($a:expr, $b:expr, $tol:expr $(,)?) => {
        $crate::assert_near!($a, $b, $tol, "{} and {}", stringify!($a), stringify!($b))
    };
    ($a:expr, $b:expr, $tol:expr, $($msg:tt)+) => {{
        let (a, b): (f64, f64) = ($a, $b);
        let tol: $crate::num::Near = ($tol).into();
        assert!(
            tol.holds(a, b),
            "{}: {a:e} and {b:e} differ by {:e}, beyond {tol:?}",
            format_args!($($msg)+),
            (a - b).abs()
        );
    }};
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tolerance_is_relative_with_an_absolute_floor() {
        assert!(Near::rel(1e-3).holds(1000.0, 1000.9));
        assert!(!Near::rel(1e-3).holds(1000.0, 1001.1));
        assert!(!Near::rel(1e-3).holds(0.0, 1e-9));
        assert!(Near::rel(1e-3).floor(1e-9).holds(0.0, 1e-9));
        assert!(Near::abs(1e-14).holds(8.0, 8.0 + 7e-15) && !Near::abs(1e-14).holds(8.0, 8.0 + 2e-14));
        crate::assert_near!(0.1 + 0.2, 0.3);
    }

    #[test]
    #[should_panic(expected = "differ by")]
    fn the_macro_says_by_how_much() {
        crate::assert_near!(1.0, 1.1, 1e-3);
    }
}
