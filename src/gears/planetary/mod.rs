//! The planetary stage of sheet 2: its tooth numbers and number of planets K chosen for a
//! required ratio, with every condition of the course computed and compared honestly.
//!
//! Two schemes, both with a fixed internal ring 3 and the carrier H as output:
//! - single row ([`Scheme::SunPlanetRing`]), z = [z1, z2, z3]: u_1H = 1 + z3/z1;
//! - two rows with a double planet ([`Scheme::DoublePlanet`]), z = [z1, z2, z2', z3]: sun 1
//!   meshes 2, the planet's second gear 2' meshes the ring; u_1H = 1 + z2·z3/(z1·z2'); one
//!   module for both rows.
//!
//! The single row is the double planet with z2' = z2, so one set of formulas serves both.
//! The guide's own example (17/68/153, K = 5) claims sin 36° = 0.86; it is 0.5878 <
//! 70/85 = 0.8235, so its planets' tips overlap: [`check`] says so, and [`synthesise`] never
//! returns a set with any condition failed.

mod conditions;
mod scheme;
mod search;

pub use conditions::{Condition, ConditionKind, Relation, check};
pub use scheme::Scheme;
pub use search::synthesise;

use crate::num::digits::{fixed, sig};

/// The planets searched when the user does not fix K: fewer than 3 leaves the carrier
/// unbalanced, more than 8 crowds the planets of the course's small sun gears.
pub const PLANETS_SEARCHED: std::ops::RangeInclusive<u32> = 3..=8;

/// The numbers of planets a user may fix: 2 (the least that balances the sun's radial
/// forces) to 12 (beyond any course's drawing).
pub const PLANETS_ALLOWED: std::ops::RangeInclusive<u32> = 2..=12;

/// The largest ratio accepted: one stage of these schemes with at most [`Z_MAX_ALLOWED`]
/// teeth cannot exceed it, so a larger one is a mistake rather than a ratio to search for.
pub const RATIO_MAX: f64 = 1000.0;

/// The largest `z_max` accepted: the search visits about z_max²/2 pairs, so this keeps it
/// within a few milliseconds.
pub const Z_MAX_ALLOWED: u32 = 1000;

/// The smallest `z_min` accepted: a wheel needs at least 5 teeth (as for the pair).
pub const Z_MIN_ALLOWED: u32 = 5;

/// The internal mesh needs z3 − z2 (the ring's planet) above this, or the tips of ring and
/// planet interfere (the course's rule for h_a* = 1 without shift).
pub const RING_PLANET_DIFFERENCE: u32 = 8;

/// A ratio within this relative error of the required one counts as exact (a set's ratio
/// is a quotient of integers, the required one a decimal the user typed).
pub const EXACT_RATIO: f64 = 1e-9;

/// How much larger (its outer size in modules) a reducer giving the required ratio exactly
/// may be than the smallest reducer within the tolerance, and still be preferred.
pub const EXACT_SIZE_ALLOWANCE: f64 = 1.25;

/// The largest relative tolerance of the ratio accepted (±50 %): beyond it any set "fits".
pub const TOLERANCE_MAX: f64 = 0.5;

/// What the stage must do.
#[derive(Debug, Clone, PartialEq)]
pub struct StageSpec {
    pub scheme: Scheme,
    /// u_pl required, > 1.
    pub ratio_required: f64,
    /// Relative, e.g. 0.03 = ±3 %.
    pub tolerance: f64,
    /// h_a*.
    pub addendum: f64,
    /// K fixed by the user, else searched in [`PLANETS_SEARCHED`].
    pub planets: Option<u32>,
    /// The least teeth of an external gear without undercut (no shift).
    pub z_min: u32,
    /// The course's least ring teeth.
    pub ring_min: u32,
    /// The largest tooth number searched.
    pub z_max: u32,
}

impl StageSpec {
    /// The course's rules: ±3 %, h_a* = 1, K searched, z ≥ 17, z3 ≥ 85, z ≤ 400.
    pub fn course(scheme: Scheme, ratio_required: f64) -> StageSpec {
        StageSpec {
            scheme,
            ratio_required,
            tolerance: 0.03,
            addendum: 1.0,
            planets: None,
            z_min: 17,
            ring_min: 85,
            z_max: 400,
        }
    }
}

/// The stage chosen.
#[derive(Debug, Clone, PartialEq)]
pub struct Stage {
    pub scheme: Scheme,
    /// [z1, z2, z3] or [z1, z2, z2', z3].
    pub z: Vec<u32>,
    pub planets: u32,
    pub ratio: f64,
    pub ratio_required: f64,
    pub tolerance: f64,
    /// Every condition, in the order of [`check`], ratio first; all hold.
    pub conditions: Vec<Condition>,
}

/// Why no stage is given.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StageError {
    #[error(
        "the planetary ratio must be a finite number above 1 and at most {}, not {}",
        sig(RATIO_MAX, 6),
        sig(*.ratio, 6)
    )]
    BadRatio { ratio: f64 },
    #[error("{}", no_set_message(*.scheme, *.ratio, *.tolerance, *.reachable, *.planets, *.z_max))]
    NoSet {
        scheme: Scheme,
        ratio: f64,
        tolerance: f64,
        /// The least and the largest ratio of the sets that meet every other condition
        /// within the search's limits; `None` when no set meets them at all.
        reachable: Option<(f64, f64)>,
        /// K as fixed by the user (`None`: searched in [`PLANETS_SEARCHED`]).
        planets: Option<u32>,
        /// The largest tooth number searched.
        z_max: u32,
    },
    #[error("K = {planets} planets: a planetary stage takes 2 to 12")]
    BadPlanets { planets: u32 },
    #[error("the {scheme} scheme takes {expected} tooth numbers, each at least 1; got {got:?}")]
    BadTeeth { scheme: Scheme, expected: usize, got: Vec<u32> },
    #[error("{field} = {} is outside {range}", sig(*.value, 6))]
    BadParameter { field: &'static str, value: f64, range: &'static str },
}

fn percent(tolerance: f64) -> String {
    let text = fixed(tolerance * 100.0, 3);
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// Says what was searched and what the user can change, in the user's terms.
fn no_set_message(
    scheme: Scheme,
    ratio: f64,
    tolerance: f64,
    reachable: Option<(f64, f64)>,
    planets: Option<u32>,
    z_max: u32,
) -> String {
    let k = match planets {
        Some(k) => format!("K = {k}"),
        None => format!("K = {}…{}", PLANETS_SEARCHED.start(), PLANETS_SEARCHED.end()),
    };
    let free_k = if planets.is_some() { "leave the number of planets to the program, " } else { "" };
    let searched = format!(
        "no {scheme} tooth set with z ≤ {z_max} and {k} gives u = {} within ±{} % with every condition met",
        fixed(ratio, 4),
        percent(tolerance)
    );
    let hint = match reachable {
        None => format!("no set of this scheme meets the conditions at all: {free_k}choose the other scheme"),
        Some((lo, hi)) if ratio * (1.0 + tolerance) < lo || ratio * (1.0 - tolerance) > hi => {
            format!(
                "this scheme reaches only u = {}…{}: {free_k}choose the other scheme or another ratio",
                fixed(lo, 3),
                fixed(hi, 3)
            )
        }
        Some((lo, hi)) => format!(
            "the scheme reaches u = {}…{} but no set falls within the tolerance: widen the tolerance, {free_k}or choose the other scheme",
            fixed(lo, 3),
            fixed(hi, 3)
        ),
    };
    format!("{searched}; {hint}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_single_row_is_the_double_planet_with_equal_planet_gears() {
        let spec = StageSpec::course(Scheme::SunPlanetRing, 10.0);
        let one = check(&spec, &[17, 68, 153], 5).unwrap();
        let two = check(&StageSpec { scheme: Scheme::DoublePlanet, ..spec }, &[17, 68, 68, 153], 5).unwrap();
        assert_eq!(one, two);
        assert_eq!(one[3].value, 34.0);
        assert!(!one[2].ok && one.iter().filter(|c| !c.ok).count() == 1);
    }

    #[test]
    fn the_reachable_span_is_found_for_a_ratio_out_of_reach() {
        let err = synthesise(&StageSpec::course(Scheme::SunPlanetRing, 40.0)).unwrap_err();
        let StageError::NoSet { reachable: Some((lo, hi)), .. } = err else { panic!("{err:?}") };
        assert!(lo > 2.0 && hi < 40.0 && lo < hi, "{lo} {hi}");
        assert!(err.to_string().contains("choose the other scheme"), "{err}");
    }

    #[test]
    fn the_tolerance_is_written_in_percent_without_trailing_zeros() {
        assert_eq!(percent(0.03), "3");
        assert_eq!(percent(0.025), "2.5");
    }
}
