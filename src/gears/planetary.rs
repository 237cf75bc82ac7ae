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

use crate::num::math::sin;
use std::f64::consts::PI;
use std::fmt;

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

/// The largest relative tolerance of the ratio accepted (±50 %): beyond it any set "fits".
pub const TOLERANCE_MAX: f64 = 0.5;

/// The kinematic scheme of the stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Scheme {
    SunPlanetRing,
    DoublePlanet,
}

impl Scheme {
    pub const ALL: [Scheme; 2] = [Scheme::SunPlanetRing, Scheme::DoublePlanet];

    /// The name the project file uses.
    pub fn key(self) -> &'static str {
        match self {
            Scheme::SunPlanetRing => "sun-planet-ring",
            Scheme::DoublePlanet => "double-planet",
        }
    }

    /// How many tooth numbers the scheme has: [z1, z2, z3] or [z1, z2, z2', z3].
    pub fn teeth(self) -> usize {
        match self {
            Scheme::SunPlanetRing => 3,
            Scheme::DoublePlanet => 4,
        }
    }

    /// u_1H of the tooth numbers `z`; 0.0 (no ratio, since u_1H > 1 always) when `z` has the
    /// wrong count or a zero, so that no input yields a non-finite number ([`check`] refuses
    /// such input with [`StageError::BadTeeth`]).
    pub fn ratio(self, z: &[u32]) -> f64 {
        Teeth::of(self, z).map_or(0.0, Teeth::ratio)
    }
}

impl fmt::Display for Scheme {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

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
    #[error("the planetary ratio must be a finite number above 1 and at most {RATIO_MAX}, not {ratio}")]
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
    #[error("{field} = {value} is outside {range}")]
    BadParameter { field: &'static str, value: f64, range: &'static str },
}

fn percent(tolerance: f64) -> String {
    let text = format!("{:.3}", tolerance * 100.0);
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
        "no {scheme} tooth set with z ≤ {z_max} and {k} gives u = {ratio:.4} within ±{} % with every condition met",
        percent(tolerance)
    );
    let hint = match reachable {
        None => format!("no set of this scheme meets the conditions at all: {free_k}choose the other scheme"),
        Some((lo, hi)) if ratio * (1.0 + tolerance) < lo || ratio * (1.0 - tolerance) > hi => {
            format!("this scheme reaches only u = {lo:.3}…{hi:.3}: {free_k}choose the other scheme or another ratio")
        }
        Some((lo, hi)) => format!(
            "the scheme reaches u = {lo:.3}…{hi:.3} but no set falls within the tolerance: widen the tolerance, {free_k}or choose the other scheme"
        ),
    };
    format!("{searched}; {hint}")
}

/// The teeth by role; the single row has one planet gear, so `planet_sun == planet_ring`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Teeth {
    sun: u32,
    /// z2, meshing the sun.
    planet_sun: u32,
    /// z2' (z2 in the single row), meshing the ring.
    planet_ring: u32,
    ring: u32,
}

impl Teeth {
    fn of(scheme: Scheme, z: &[u32]) -> Option<Teeth> {
        if z.contains(&0) {
            return None;
        }
        match (scheme, z) {
            (Scheme::SunPlanetRing, &[sun, planet, ring]) => {
                Some(Teeth { sun, planet_sun: planet, planet_ring: planet, ring })
            }
            (Scheme::DoublePlanet, &[sun, planet_sun, planet_ring, ring]) => {
                Some(Teeth { sun, planet_sun, planet_ring, ring })
            }
            _ => None,
        }
    }

    fn to_vec(self, scheme: Scheme) -> Vec<u32> {
        match scheme {
            Scheme::SunPlanetRing => vec![self.sun, self.planet_sun, self.ring],
            Scheme::DoublePlanet => vec![self.sun, self.planet_sun, self.planet_ring, self.ring],
        }
    }

    /// u_1H = 1 + z2·z3/(z1·z2'); with one planet gear written as 1 + z3/z1, the guide's form.
    fn ratio(self) -> f64 {
        let [z1, z2, z2b, z3] = [self.sun, self.planet_sun, self.planet_ring, self.ring].map(u64::from);
        if z2 == z2b { 1.0 + z3 as f64 / z1 as f64 } else { 1.0 + (z2 * z3) as f64 / (z1 * z2b) as f64 }
    }

    /// z1 + z2 + z2' (z1 + 2z2): the ring's teeth for equal centre distances in both meshes.
    fn coaxial_sum(self) -> u64 {
        u64::from(self.sun) + u64::from(self.planet_sun) + u64::from(self.planet_ring)
    }

    /// (max(z2, z2') + 2h_a*)/(z1 + z2): the planet's tip diameter over the distance from
    /// the sun's centre, in modules; sin(π/K) must exceed it for the tips of neighbours to
    /// clear each other (their centres are 2a·sin(π/K) apart).
    fn neighbour_limit(self, addendum: f64) -> f64 {
        let largest = self.planet_sun.max(self.planet_ring);
        (f64::from(largest) + 2.0 * addendum) / (u64::from(self.sun) + u64::from(self.planet_sun)) as f64
    }

    /// (z1·z2' + z2·z3)/gcd(z2, z2') (z1 + z3 in the single row): K planets can be put in
    /// evenly spaced only when K divides it.
    fn assembly_number(self) -> u128 {
        let [z1, z2, z2b, z3] = [self.sun, self.planet_sun, self.planet_ring, self.ring].map(u128::from);
        (z1 * z2b + z2 * z3) / u128::from(gcd(self.planet_sun, self.planet_ring))
    }

    /// The reducer's outer diameter in modules (tips aside): the ring, or a double planet's
    /// larger gear z2 reaching past it (2a + z2 = z1 + 2·z2); the single row has z1 + 2z2 = z3.
    fn size(self) -> u32 {
        self.ring.max(self.sun + 2 * self.planet_sun)
    }

    fn smallest_external(self) -> u32 {
        self.sun.min(self.planet_sun).min(self.planet_ring)
    }

    /// z3 − z2', signed: an arbitrary set given to [`check`] may have a smaller ring.
    fn ring_planet_difference(self) -> i64 {
        i64::from(self.ring) - i64::from(self.planet_ring)
    }
}

fn gcd(a: u32, b: u32) -> u32 {
    let (mut a, mut b) = (a, b);
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.max(1)
}

fn within(ratio: f64, required: f64, tolerance: f64) -> bool {
    (ratio - required).abs() <= tolerance * required
}

fn condition(name: ConditionKind, value: f64, limit: f64, relation: Relation, ok: bool) -> Condition {
    Condition { name, value, limit, relation, ok }
}

/// Every condition of a valid `Teeth` and K, computed without validation (the caller has
/// validated), so that the search can confirm a candidate without allocating.
fn conditions(spec: &StageSpec, t: Teeth, k: u32) -> [Condition; 7] {
    use ConditionKind::*;
    use Relation::*;
    let ratio = t.ratio();
    let sin_k = sin(PI / f64::from(k));
    let neighbours = t.neighbour_limit(spec.addendum);
    let assembly = t.assembly_number();
    let quotient = assembly as f64 / f64::from(k);
    let smallest = t.smallest_external();
    let difference = t.ring_planet_difference();
    [
        condition(Ratio, ratio, spec.ratio_required, Within, within(ratio, spec.ratio_required, spec.tolerance)),
        condition(Coaxiality, t.coaxial_sum() as f64, f64::from(t.ring), Equal, t.coaxial_sum() == u64::from(t.ring)),
        condition(Neighbours, sin_k, neighbours, Greater, sin_k > neighbours),
        condition(Assembly, quotient, quotient.round(), Integer, assembly.is_multiple_of(u128::from(k))),
        condition(NoUndercut, f64::from(smallest), f64::from(spec.z_min), AtLeast, smallest >= spec.z_min),
        condition(RingTeeth, f64::from(t.ring), f64::from(spec.ring_min), AtLeast, t.ring >= spec.ring_min),
        condition(
            RingPlanetDifference,
            difference as f64,
            f64::from(RING_PLANET_DIFFERENCE),
            Greater,
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
fn validate_search(spec: &StageSpec) -> Result<(), StageError> {
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
/// why. `spec.planets` and `spec.z_max` play no part: they only steer [`synthesise`].
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

/// A candidate that met every condition.
#[derive(Debug, Clone, Copy)]
struct Found {
    teeth: Teeth,
    planets: u32,
    ratio: f64,
}

/// The search over one spec: the planets it may use with their sin(π/K), computed once.
struct Search<'a> {
    spec: &'a StageSpec,
    planets: Vec<(u32, f64)>,
    /// The largest of the sines: the neighbour condition's most lenient form.
    sin_max: f64,
}

impl<'a> Search<'a> {
    fn new(spec: &'a StageSpec) -> Search<'a> {
        let ks = match spec.planets {
            Some(k) => k..=k,
            None => PLANETS_SEARCHED,
        };
        let planets: Vec<(u32, f64)> = ks.map(|k| (k, sin(PI / f64::from(k)))).collect();
        let sin_max = planets.iter().map(|&(_, sin_k)| sin_k).fold(0.0, f64::max);
        Search { spec, planets, sin_max }
    }

    /// The conditions that do not depend on K or on the ratio, in integers.
    fn fixed_ok(&self, t: Teeth) -> bool {
        let s = self.spec;
        t.coaxial_sum() == u64::from(t.ring)
            && t.smallest_external() >= s.z_min
            && t.ring >= s.ring_min
            && t.ring_planet_difference() > i64::from(RING_PLANET_DIFFERENCE)
    }

    /// The numbers of planets with which `t` meets every condition but the ratio, cheaply
    /// (the sines are tabled); the same formulas as [`conditions`].
    fn planets_for(&self, t: Teeth) -> impl Iterator<Item = u32> + '_ {
        let fits = self.fixed_ok(t);
        let limit = t.neighbour_limit(self.spec.addendum);
        let number = t.assembly_number();
        self.planets
            .iter()
            .filter(move |&&(k, sin_k)| fits && sin_k > limit && number.is_multiple_of(u128::from(k)))
            .map(|&(k, _)| k)
    }

    /// Keeps `t` if it is valid and better than `best`; a set replaces `best` only after the
    /// full [`conditions`] (those of [`check`]) all hold for it.
    fn consider(&self, t: Teeth, best: &mut Option<Found>) {
        let s = self.spec;
        let ratio = t.ratio();
        if !within(ratio, s.ratio_required, s.tolerance) {
            return;
        }
        for planets in self.planets_for(t) {
            let found = Found { teeth: t, planets, ratio };
            if best.is_none_or(|b| self.better(&found, &b)) && conditions(s, t, planets).iter().all(|c| c.ok) {
                *best = Some(found);
            }
        }
    }

    /// The smallest reducer (its outer diameter: the ring, or a double planet's larger gear),
    /// then the closest ratio, then more planets (lighter loaded), then the smallest sun; the
    /// tooth numbers last make the order total.
    fn better(&self, a: &Found, b: &Found) -> bool {
        let error = |f: &Found| (f.ratio - self.spec.ratio_required).abs();
        let key = |f: &Found| (f.teeth.ring, std::cmp::Reverse(f.planets), f.teeth.sun, f.teeth.planet_sun);
        a.teeth.size().cmp(&b.teeth.size()).then(error(a).total_cmp(&error(b))).then(key(a).cmp(&key(b))).is_lt()
    }

    /// The ratio window [u(1 − tol), u(1 + tol)].
    fn window(&self) -> (f64, f64) {
        let s = self.spec;
        (s.ratio_required * (1.0 - s.tolerance), s.ratio_required * (1.0 + s.tolerance))
    }

    /// Single row: for each z1 the rings whose ratio 1 + z3/z1 falls in the window (one
    /// either side to spare the rounding), of the parity that makes z2 = (z3 − z1)/2 whole.
    fn single_row(&self) -> Option<Found> {
        let s = self.spec;
        let (lo, hi) = self.window();
        let mut best: Option<Found> = None;
        for z1 in s.z_min..=s.z_max {
            // No ring larger than the best reducer found can win (its size is at least its ring).
            let ring_max = best.map_or(s.z_max, |b| b.teeth.size());
            let first = floor_u32((lo - 1.0) * f64::from(z1)).saturating_sub(1).max(z1 + 2 * s.z_min).max(s.ring_min);
            let last = ceil_u32((hi - 1.0) * f64::from(z1)).saturating_add(1).min(ring_max);
            for z3 in (first..=last).filter(|z3| (z3 - z1) % 2 == 0) {
                let z2 = (z3 - z1) / 2;
                self.consider(Teeth { sun: z1, planet_sun: z2, planet_ring: z2, ring: z3 }, &mut best);
            }
        }
        best
    }

    /// Double planet: for each z1 and z2', u − 1 = z2·(z1 + z2 + z2')/(z1·z2') is a quadratic
    /// in z2 increasing with it; the z2 between the roots for the window's ends (one either
    /// side to spare the rounding) are the only candidates.
    fn double_planet(&self) -> Option<Found> {
        let s = self.spec;
        let (lo, hi) = self.window();
        let mut best: Option<Found> = None;
        for z1 in s.z_min..=s.z_max {
            // No ring larger than the best reducer found can win (its size is at least its ring).
            let ring_max = best.map_or(s.z_max, |b| b.teeth.size());
            for z2b in s.z_min..=ring_max.saturating_sub(z1 + s.z_min) {
                let room = ring_max - z1 - z2b;
                let b = f64::from(z1 + z2b);
                let c = f64::from(z1) * f64::from(z2b);
                let root = |u: f64| (-b + (b * b + 4.0 * (u - 1.0) * c).sqrt()) / 2.0;
                let (near, far) = self.neighbour_span(z1, Some(z2b));
                let first = floor_u32(root(lo)).saturating_sub(1).max(s.z_min).max(near);
                let last = ceil_u32(root(hi)).saturating_add(1).min(room).min(far);
                for z2 in first..=last {
                    let t = Teeth { sun: z1, planet_sun: z2, planet_ring: z2b, ring: z1 + z2 + z2b };
                    self.consider(t, &mut best);
                }
            }
        }
        best
    }

    /// The z2 for which neighbours can hold with the largest sin(π/K) allowed (padded by
    /// one): z2' + 2h_a* < (z1 + z2)·s and z2 + 2h_a* < (z1 + z2)·s.
    fn neighbour_span(&self, z1: u32, z2b: Option<u32>) -> (u32, u32) {
        let s = self.sin_max;
        let h2 = 2.0 * self.spec.addendum;
        let z1f = f64::from(z1);
        let low = z2b.map_or(0.0, |z| (f64::from(z) + h2) / s - z1f);
        let high = if s < 1.0 { (z1f * s - h2) / (1.0 - s) } else { f64::INFINITY };
        (floor_u32(low), ceil_u32(high))
    }

    /// Widens `span` to the least and the largest ratio among the z2 in `first..=last` that
    /// meet every condition but the ratio. The ratio grows with z2, so only the z2 whose
    /// ratio lies below the span can lower its start (scanned upward to the first valid set),
    /// and only those above it can raise its end.
    fn extremes(&self, first: u32, last: u32, teeth: impl Fn(u32) -> Teeth, span: &mut Option<(f64, f64)>) {
        let valid = |z2: &u32| self.planets_for(teeth(*z2)).next().is_some();
        let (lo, hi) = span.unwrap_or((f64::INFINITY, f64::NEG_INFINITY));
        let low = (first..=last).take_while(|&z2| teeth(z2).ratio() < lo).find(valid);
        let high = (first..=last).rev().take_while(|&z2| teeth(z2).ratio() > hi).find(valid);
        let lo = low.map_or(lo, |z2| teeth(z2).ratio().min(lo));
        let hi = high.map_or(hi, |z2| teeth(z2).ratio().max(hi));
        if lo <= hi {
            *span = Some((lo, hi));
        }
    }

    /// The ratios the scheme reaches within the spec's limits, for the refusal's message.
    fn reachable(&self) -> Option<(f64, f64)> {
        let s = self.spec;
        let mut span = None;
        for z1 in s.z_min..=s.z_max {
            match s.scheme {
                Scheme::SunPlanetRing => {
                    let (low, high) = self.neighbour_span(z1, None);
                    let ring_low = s.ring_min.saturating_sub(z1).div_ceil(2);
                    let first = low.max(s.z_min).max(ring_low);
                    let last = high.min(s.z_max.saturating_sub(z1) / 2);
                    let teeth = |z2| Teeth { sun: z1, planet_sun: z2, planet_ring: z2, ring: z1 + 2 * z2 };
                    self.extremes(first, last, teeth, &mut span);
                }
                Scheme::DoublePlanet => {
                    for z2b in s.z_min..=s.z_max.saturating_sub(z1 + s.z_min) {
                        let (low, high) = self.neighbour_span(z1, Some(z2b));
                        let first = low.max(s.z_min).max(s.ring_min.saturating_sub(z1 + z2b));
                        let last = high.min(s.z_max - z1 - z2b);
                        let teeth = |z2| Teeth { sun: z1, planet_sun: z2, planet_ring: z2b, ring: z1 + z2 + z2b };
                        self.extremes(first, last, teeth, &mut span);
                    }
                }
            }
        }
        span
    }
}

/// ⌊x⌋ as a tooth number: 0 below zero or for NaN, saturated above (Rust's casts saturate).
fn floor_u32(x: f64) -> u32 {
    x.floor() as u32
}

fn ceil_u32(x: f64) -> u32 {
    x.ceil() as u32
}

/// The best valid set: ratio within the tolerance and every condition of [`check`] met;
/// the smallest reducer (the ring z3, or z1 + 2·z2 when a double planet's larger gear reaches
/// past it) first, then the smallest |ratio error|, then more
/// planets, then the smallest z1.
///
/// It runs when a sheet is built and inside property tests, so it visits only the
/// candidates near the ratio (a window of z3 per z1, or of z2 per z1 and z2'), and no ring
/// larger than the best found so far. Measured in a release build (ratios 2–50 in steps of
/// 0.1, the ignored `search_time` test of `tests/planetary.rs`), with the course's limits
/// (z ≤ 400): at most 0.05 ms for the single row and 0.13 ms for the double planet with K
/// searched; with K fixed, when most ratios are refused and the refusal scans for the
/// reachable ratios, at most 0.2 ms and 3 ms; with z ≤ 1000 at most 25 ms.
pub fn synthesise(spec: &StageSpec) -> Result<Stage, StageError> {
    validate_search(spec)?;
    let search = Search::new(spec);
    let found = match spec.scheme {
        Scheme::SunPlanetRing => search.single_row(),
        Scheme::DoublePlanet => search.double_planet(),
    };
    let Some(found) = found else {
        return Err(StageError::NoSet {
            scheme: spec.scheme,
            ratio: spec.ratio_required,
            tolerance: spec.tolerance,
            reachable: search.reachable(),
            planets: spec.planets,
            z_max: spec.z_max,
        });
    };
    let z = found.teeth.to_vec(spec.scheme);
    let conditions = check(spec, &z, found.planets)?;
    Ok(Stage {
        scheme: spec.scheme,
        z,
        planets: found.planets,
        ratio: found.ratio,
        ratio_required: spec.ratio_required,
        tolerance: spec.tolerance,
        conditions,
    })
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
    fn gcd_and_rounding_helpers_do_not_panic() {
        assert_eq!(gcd(12, 18), 6);
        assert_eq!(gcd(0, 0), 1);
        assert_eq!(floor_u32(f64::NAN), 0);
        assert_eq!(ceil_u32(1e300), u32::MAX);
        assert_eq!(percent(0.03), "3");
        assert_eq!(percent(0.025), "2.5");
    }
}
