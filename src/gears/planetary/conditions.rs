//! Every condition of the course for a set of tooth numbers and K, computed honestly and
//! decided in integers where the condition is one of integers.

use super::scheme::Teeth;
use super::{
    PLANETS_ALLOWED, RATIO_MAX, RING_PLANET_DIFFERENCE, StageError, StageSpec, TOLERANCE_MAX, Z_MAX_ALLOWED,
    Z_MIN_ALLOWED,
};
use crate::num::math::sin;
use std::f64::consts::PI;

/// How a condition compares its value with its limit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Relation {
    /// value = limit.
    Equal,
    /// value > limit.
    Greater,
    /// value ≥ limit.
    AtLeast,
    /// value is an integer; the limit is the nearest integer (so a sheet can print both).
    Integer,
    /// |value − limit| ≤ tolerance·limit (the stage's tolerance).
    Within,
}

/// The conditions a planetary stage must meet.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ConditionKind {
    Ratio,
    Coaxiality,
    Neighbours,
    Assembly,
    NoUndercut,
    RingTeeth,
    RingPlanetDifference,
}

impl ConditionKind {
    /// A stable key: "ratio", "coaxiality", "neighbours", "assembly", "no_undercut",
    /// "ring_teeth", "ring_planet_difference".
    pub const fn key(self) -> &'static str {
        match self {
            ConditionKind::Ratio => "ratio",
            ConditionKind::Coaxiality => "coaxiality",
            ConditionKind::Neighbours => "neighbours",
            ConditionKind::Assembly => "assembly",
            ConditionKind::NoUndercut => "no_undercut",
            ConditionKind::RingTeeth => "ring_teeth",
            ConditionKind::RingPlanetDifference => "ring_planet_difference",
        }
    }

    /// How the condition compares its value with its limit.
    pub const fn relation(self) -> Relation {
        match self {
            ConditionKind::Ratio => Relation::Within,
            ConditionKind::Coaxiality => Relation::Equal,
            ConditionKind::Neighbours | ConditionKind::RingPlanetDifference => Relation::Greater,
            ConditionKind::Assembly => Relation::Integer,
            ConditionKind::NoUndercut | ConditionKind::RingTeeth => Relation::AtLeast,
        }
    }
}

/// One condition of the stage, as the sheet prints it: the two sides and the verdict.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Condition {
    pub name: ConditionKind,
    /// The left side as computed: the ratio found; z1 + z2 + z2' (z1 + 2z2 for the single
    /// row); sin(π/K); (z1·z2' + z2·z3)/(K·gcd(z2, z2')) ((z1 + z3)/K for the single row);
    /// the smallest external z; z3; z3 − z2'.
    pub value: f64,
    /// The right side: the ratio required; z3; (max(z2, z2') + 2h_a*)/(z1 + z2); the nearest
    /// integer to the value; z_min; ring_min; 8.
    pub limit: f64,
    pub relation: Relation,
    /// Decided in integers where the condition is one of integers (coaxiality, assembly, the
    /// tooth counts), so that no rounding can pass a failing set.
    pub ok: bool,
}

pub(super) fn within(ratio: f64, required: f64, tolerance: f64) -> bool {
    (ratio - required).abs() <= tolerance * required
}

fn condition(name: ConditionKind, value: f64, limit: f64, ok: bool) -> Condition {
    Condition { name, value, limit, relation: name.relation(), ok }
}

/// Every condition of a valid `Teeth` and K, computed without validation (the caller has
/// validated), so that the search can confirm a candidate without allocating.
pub(super) fn conditions(spec: &StageSpec, t: Teeth, k: u32) -> [Condition; 7] {
    use ConditionKind::*;
    let ratio = t.ratio();
    let sin_k = sin(PI / f64::from(k));
    let neighbours = t.neighbour_limit(spec.addendum);
    let assembly = t.assembly_number();
    let quotient = assembly as f64 / f64::from(k);
    let smallest = t.smallest_external();
    let difference = t.ring_planet_difference();
    [
        condition(Ratio, ratio, spec.ratio_required, within(ratio, spec.ratio_required, spec.tolerance)),
        condition(Coaxiality, t.coaxial_sum() as f64, f64::from(t.ring), t.coaxial_sum() == u64::from(t.ring)),
        condition(Neighbours, sin_k, neighbours, sin_k > neighbours),
        condition(Assembly, quotient, quotient.round(), assembly.is_multiple_of(u128::from(k))),
        condition(NoUndercut, f64::from(smallest), f64::from(spec.z_min), smallest >= spec.z_min),
        condition(RingTeeth, f64::from(t.ring), f64::from(spec.ring_min), t.ring >= spec.ring_min),
        condition(
            RingPlanetDifference,
            difference as f64,
            f64::from(RING_PLANET_DIFFERENCE),
            difference > i64::from(RING_PLANET_DIFFERENCE),
        ),
    ]
}

/// The numbers every condition needs finite and meaningful.
fn validate_limits(spec: &StageSpec) -> Result<(), StageError> {
    let r = spec.ratio_required;
    if !(r.is_finite() && r > 1.0 && r <= RATIO_MAX) {
        return Err(StageError::BadRatio { ratio: r });
    }
    let t = spec.tolerance;
    if !(t.is_finite() && (0.0..=TOLERANCE_MAX).contains(&t)) {
        return Err(StageError::BadParameter { field: "tolerance", value: t, range: "0…0.5" });
    }
    let h = spec.addendum;
    if !(h.is_finite() && h > 0.0 && h <= 2.0) {
        return Err(StageError::BadParameter { field: "addendum", value: h, range: "(0, 2]" });
    }
    Ok(())
}

/// The search's own limits: they bound its time and keep every tooth number positive.
pub(super) fn validate_search(spec: &StageSpec) -> Result<(), StageError> {
    validate_limits(spec)?;
    if let Some(k) = spec.planets
        && !PLANETS_ALLOWED.contains(&k)
    {
        return Err(StageError::BadPlanets { planets: k });
    }
    if !(Z_MIN_ALLOWED..=Z_MAX_ALLOWED).contains(&spec.z_min) {
        return Err(StageError::BadParameter { field: "z_min", value: f64::from(spec.z_min), range: "5…1000" });
    }
    if !(spec.z_min..=Z_MAX_ALLOWED).contains(&spec.z_max) {
        return Err(StageError::BadParameter { field: "z_max", value: f64::from(spec.z_max), range: "z_min…1000" });
    }
    Ok(())
}

/// Every condition of the set `z` with `planets` planets, honestly computed: the sheet prints
/// them, and a set that fails one (as the guide's 17/68/153, K = 5 fails "neighbours") shows
/// why. `spec.planets` and `spec.z_max` play no part: they only steer [`synthesise`](super::synthesise).
pub fn check(spec: &StageSpec, z: &[u32], planets: u32) -> Result<Vec<Condition>, StageError> {
    validate_limits(spec)?;
    if !PLANETS_ALLOWED.contains(&planets) {
        return Err(StageError::BadPlanets { planets });
    }
    let t = Teeth::of(spec.scheme, z).ok_or_else(|| StageError::BadTeeth {
        scheme: spec.scheme,
        expected: spec.scheme.teeth(),
        got: z.to_vec(),
    })?;
    Ok(conditions(spec, t, planets).to_vec())
}
