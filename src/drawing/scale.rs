//! Scale factors. Lengths use the scales of GOST 2.302; diagrams and force drawings use
//! the course's round factors {1, 2, 2.5, 4, 5}·10ⁿ; velocity and acceleration plans, which
//! share one μ across a sheet and so cannot all be tuned to their cells, the finer series
//! {1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 7.5}·10ⁿ (steps of at most a third instead of 1.6×).

use crate::num::math;
use crate::num::tol;
use crate::num::units::mm;

const MANTISSAS: [f64; 5] = [1.0, 2.0, 2.5, 4.0, 5.0];
const PLAN_MANTISSAS: [f64; 10] = [1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 7.5];

/// GOST 2.302 reductions 1:k (k real mm per paper mm).
const REDUCTIONS: [f64; 21] = [
    1.0, 2.0, 2.5, 4.0, 5.0, 10.0, 15.0, 20.0, 25.0, 40.0, 50.0, 75.0, 100.0, 200.0, 400.0, 500.0, 800.0, 1000.0,
    2000.0, 5000.0, 10000.0,
];
/// GOST 2.302 enlargements k:1.
const ENLARGEMENTS: [f64; 9] = [2.0, 2.5, 4.0, 5.0, 10.0, 20.0, 40.0, 50.0, 100.0];

/// Tolerance that keeps an exact value instead of bumping it to the next one (a scale that
/// matches another to within round-off is the same scale: `mu < other * EXACT` is finer).
pub const EXACT: f64 = 1.0 - tol::ROUND_VALUE;

/// The smallest round value ≥ `x`. A scale factor μ (units per mm) chosen this way makes a
/// drawing as large as possible without leaving its region. A drawing of no extent (x ≤ 0,
/// or not finite) fits any scale: it gets 1.
pub fn round_up(x: f64) -> f64 {
    round_up_in(x, &MANTISSAS)
}

/// [`round_up`] in the plans' finer series.
pub fn plan_round_up(x: f64) -> f64 {
    round_up_in(x, &PLAN_MANTISSAS)
}

/// The largest value of the plans' series ≤ `x` (1 for no extent).
pub fn plan_round_down(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let e = math::log10(x).floor() as i32;
    (e - 1..=e)
        .flat_map(|k| PLAN_MANTISSAS.iter().map(move |&m| series_value(m, k)))
        .filter(|&v| v * EXACT <= x)
        .fold(0.0, f64::max)
}

/// The smallest value of two significant digits ≥ `x` (0.027, 0.0035; 1 for no extent): a
/// scale derived where the plans' series would step too far (the acceleration analog's, its
/// pole derived from it), read and multiplied as easily.
pub fn two_digits_up(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let e = math::log10(x).floor() as i32 - 1;
    (e - 1..=e + 1)
        .flat_map(|k| (10..100).map(move |m| series_value(f64::from(m), k)))
        .find(|&v| v >= x * EXACT)
        .unwrap_or_else(|| series_value(10.0, e + 2))
}

/// The next value of two significant digits above `mu`.
pub fn two_digits_next(mu: f64) -> f64 {
    two_digits_up(mu * 1.001)
}

/// The next value of the plans' series above `mu`.
pub fn plan_next_round(mu: f64) -> f64 {
    plan_round_up(mu * 1.001)
}

fn round_up_in(x: f64, mantissas: &[f64]) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let mut e = math::log10(x).floor() as i32 - 1;
    loop {
        for &m in mantissas {
            if series_value(m, e) >= x * EXACT {
                return series_value(m, e);
            }
        }
        e += 1;
    }
}

/// m·10^e as the double nearest it: dividing by 10^|e| keeps 3·10⁻¹ 0.3 (3 × 0.1 is
/// 0.30000000000000004, which a scale line would print).
fn series_value(m: f64, e: i32) -> f64 {
    if e < 0 { m / 10f64.powi(-e) } else { m * 10f64.powi(e) }
}

/// The next value of the round series above `mu`.
pub fn next_round(mu: f64) -> f64 {
    round_up(mu * 1.001)
}

/// Every GOST 2.302 μ_l (m/mm), the largest drawing first.
pub fn length_scales() -> impl Iterator<Item = f64> {
    let enlarge = ENLARGEMENTS.iter().rev().map(|k| 0.001 / k);
    enlarge.chain(REDUCTIONS.iter().map(|k| 0.001 * k))
}

/// The smallest μ_l (m/mm) of a GOST 2.302 scale that is ≥ `x` (1:1 for no extent).
pub fn length_scale(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 0.001;
    }
    let enlarge = ENLARGEMENTS.iter().rev().map(|k| 0.001 / k);
    let reduce = REDUCTIONS.iter().map(|k| 0.001 * k);
    enlarge.chain(reduce).find(|&mu| mu >= x * EXACT).unwrap_or_else(|| round_up(x))
}

/// The largest μ_l (m/mm) of a GOST 2.302 scale strictly below `x`: the coarsest scale that
/// makes a length of x·1 mm on paper longer than 1 mm (a tooth height over 50 mm: `x` = h/50).
/// Below 100:1 it goes on with the (100·n):1 the standard allows where needed, n in the
/// round series (200:1, 400:1, 500:1, 1000:1 …): a 30 µm crank's detail at 100:1 would be
/// drawn no larger than the mechanism it enlarges.
pub fn length_scale_below(x: f64) -> f64 {
    let enlarge = ENLARGEMENTS.iter().rev().map(|k| 0.001 / k);
    let reduce = REDUCTIONS.iter().map(|k| 0.001 * k);
    let all: Vec<f64> = enlarge.chain(reduce).collect();
    all.iter().rev().copied().find(|&mu| mu < x).unwrap_or_else(|| hundredfold_below(x))
}

/// The largest μ_l of a (100·n):1 scale, n ≥ 2 in the round series, strictly below `x`
/// (`x` at most 100:1's 0.00001 m/mm); 100:1 for no extent.
fn hundredfold_below(x: f64) -> f64 {
    const HUNDRED_TO_ONE: f64 = 0.001 / 100.0;
    if !(x.is_finite() && x > 0.0) {
        return HUNDRED_TO_ONE;
    }
    // n the smallest of 2, 4, 5, 10, 20, 40, 50 … (whole numbers, as the standard asks)
    // with 0.00001/n < x.
    (0..300)
        .flat_map(|e| [1.0, 2.0, 4.0, 5.0].map(|m| series_value(m, e)))
        .filter(|&n| n >= 2.0)
        .map(|n| HUNDRED_TO_ONE / n)
        .find(|&mu| mu < x)
        .unwrap_or(HUNDRED_TO_ONE)
}

/// Formats a scale factor with as many significant digits as it has.
pub fn format(mu: f64) -> String {
    let s = format!("{mu:.10}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.to_string()
}

/// A length scale μ_l (m/mm) as a GOST 2.302 ratio: 0.005 m/mm is 1:5, 0.0005 m/mm is 2:1.
pub fn ratio(mu_l: f64) -> String {
    let k = mm(mu_l); // real millimetres per paper millimetre
    if k >= EXACT { format!("1:{}", format(k)) } else { format!("{}:1", format(1.0 / k)) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounds_up_to_the_series() {
        assert_eq!(round_up(0.0042), 0.005);
        assert_eq!(round_up(0.005), 0.005);
        assert_eq!(round_up(0.0051), 0.01);
        assert_eq!(round_up(0.011), 0.02);
        assert_eq!(round_up(0.021975), 0.025);
        assert_eq!(round_up(8.0), 10.0);
        assert_eq!((round_up(0.0), round_up(f64::NAN), length_scale(-1.0)), (1.0, 1.0, 0.001), "no extent, no panic");
    }

    #[test]
    fn next_round_values_step_along_the_series() {
        assert_eq!([next_round(0.02), next_round(0.025), next_round(0.05)], [0.025, 0.04, 0.1]);
        let plans: Vec<f64> = std::iter::successors(Some(0.1), |&m| Some(plan_next_round(m))).take(11).collect();
        assert_eq!(plans, [0.1, 0.125, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.75, 1.0]);
        assert_eq!([plan_round_up(0.031), plan_round_up(0.0061), plan_round_up(7.6)], [0.04, 0.0075, 10.0]);
        assert_eq!(
            [plan_round_down(0.031), plan_round_down(0.0061), plan_round_down(7.6), plan_round_down(0.3)],
            [0.03, 0.006, 7.5, 0.3]
        );
    }

    #[test]
    fn length_scales_are_gost_scales() {
        assert_eq!(length_scale(0.0042), 0.005);
        assert_eq!(length_scale(0.0051), 0.01);
        assert_eq!(length_scale(0.011), 0.015);
        assert_eq!(length_scale(0.06), 0.075);
        assert_eq!(length_scale(0.0007), 0.001);
        assert_eq!(length_scale(0.0003), 0.0004);
        for x in [1e-5, 3e-4, 0.0013, 0.0033, 0.07, 0.9] {
            let r = ratio(length_scale(x));
            assert!(!r.contains('.') || r == "1:2.5" || r == "2.5:1", "{x}: {r}");
        }
    }

    #[test]
    fn finer_than_a_hundredfold_goes_on_in_hundreds() {
        // 100:1 is 0.00001 m/mm; below it (100·n):1 with n round: 200:1, 400:1, 500:1, 1000:1.
        assert_eq!(length_scale_below(0.000011), 0.00001);
        assert_eq!(ratio(length_scale_below(0.00001)), "200:1");
        assert_eq!(ratio(length_scale_below(0.000002)), "1000:1");
        assert_eq!(ratio(length_scale_below(0.0000021)), "500:1");
        assert_eq!(ratio(length_scale_below(0.000003)), "400:1");
        assert_eq!(ratio(length_scale_below(0.0000045)), "400:1");
        for x in [9.9e-6, 4e-6, 1.3e-6, 2e-7, 3.3e-9] {
            let mu = length_scale_below(x);
            assert!(mu < x && mu > x / 2.6, "{x}: {mu}");
        }
    }

    #[test]
    fn gost_ratios() {
        assert_eq!(ratio(0.005), "1:5");
        assert_eq!(ratio(0.001), "1:1");
        assert_eq!(ratio(0.0005), "2:1");
        assert_eq!(ratio(0.0004), "2.5:1");
    }
}
