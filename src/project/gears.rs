//! The `gears` section: sheet 2's external pair and planetary stage, in the course's terms
//! (module in millimetres, angles in degrees, speeds in rev/min), resolved into the gears
//! domain in SI. Every refusal names its field and line; the pair and the stage are built
//! here once so that a shift that makes a tooth pointed or a ratio no tooth set reaches is
//! an error at its line, not a failed sheet.

use super::text;
use super::values::{Finite, LocalText, Positive};
use super::{Kind, Refusal, Warning, at, invalid, warning};
use crate::gears::pair::{Pair, PairError, PairSpec, PairWarning};
use crate::gears::planetary::{self, Scheme, Stage, StageError, StageSpec};
use crate::num::digits::{fixed, sig, written};
use crate::num::tol;
use crate::num::units::metres;
use serde::Deserialize;
use serde_saphyr::{Location, Spanned};

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GearsSpec {
    pub pair: Spanned<PairFileSpec>,
    /// n_motor, rev/min.
    #[serde(default)]
    pub motor_rpm: Option<Spanned<Positive>>,
    /// n1, rev/min (default: the crank's speed when the project has a mechanism).
    #[serde(default)]
    pub output_rpm: Option<Spanned<Positive>>,
    #[serde(default)]
    pub planetary: Option<Spanned<PlanetaryFileSpec>>,
    /// Printed on the sheet: what was assumed where the source is silent or contradicts itself.
    #[serde(default)]
    /// Each one text, or one per language.
    pub assumptions: Vec<Spanned<LocalText>>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PairFileSpec {
    /// m, millimetres (as the course writes it).
    pub module: Spanned<Positive>,
    pub z: [Spanned<u32>; 2],
    /// [x1, x2] or `auto` (the smallest shifts without undercut); default no shift.
    #[serde(default)]
    pub shift: Option<Spanned<ShiftSpec>>,
    #[serde(default)]
    pub pressure_angle_deg: Option<Spanned<Positive>>,
    #[serde(default)]
    pub addendum: Option<Spanned<Positive>>,
    #[serde(default)]
    pub clearance: Option<Spanned<Positive>>,
}

/// The profile shifts: `[x1, x2]`, or a word (`auto`).
#[derive(Debug, Clone)]
pub enum ShiftSpec {
    Values([Finite; 2]),
    Word(String),
}

/// The largest planetary tolerance accepted, percent.
const TOLERANCE_PERCENT_MAX: f64 = 50.0;

struct ShiftVisitor;

impl<'de> serde::de::Visitor<'de> for ShiftVisitor {
    type Value = ShiftSpec;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("two profile shifts `[x1, x2]` or `auto`")
    }

    fn visit_str<E: serde::de::Error>(self, s: &str) -> Result<ShiftSpec, E> {
        Ok(ShiftSpec::Word(s.to_string()))
    }

    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<ShiftSpec, A::Error> {
        let mut values = Vec::new();
        while let Some(x) = seq.next_element::<Finite>()? {
            values.push(x);
        }
        match values[..] {
            [x1, x2] => Ok(ShiftSpec::Values([x1, x2])),
            _ => Err(serde::de::Error::custom(format!(
                "{} shift(s): give two, `[x1, x2]` (one per wheel), or `auto`",
                values.len()
            ))),
        }
    }
}

impl<'de> Deserialize<'de> for ShiftSpec {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(ShiftVisitor)
    }
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlanetaryFileSpec {
    /// `sun-planet-ring` (single row) or `double-planet` (two rows).
    pub scheme: Spanned<String>,
    /// Module, millimetres.
    pub module: Spanned<Positive>,
    /// K, the number of planets (default: searched, 3…8).
    #[serde(default)]
    pub planets: Option<Spanned<u32>>,
    /// u_pl required (default: n_motor / n1 divided by the pair's ratio).
    #[serde(default)]
    pub ratio: Option<Spanned<Positive>>,
    /// How far the ratio found may be from the one required, percent (default 3).
    #[serde(default)]
    pub tolerance_percent: Option<Spanned<Positive>>,
}

/// The crank's speed, rev/min, and the field it is written in (`mechanism.crank.rpm`, or
/// `mechanism.crank.omega` in 1/s): sheet 2's n1 unless `output_rpm` gives another.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CrankSpeed {
    pub rpm: f64,
    pub field: &'static str,
}

/// Everything sheet 2 needs.
#[derive(Debug, Clone)]
pub struct GearsProject {
    pub pair: Pair,
    /// Whether each wheel's shift was chosen by `auto`.
    pub auto_shift: [bool; 2],
    pub warnings: Vec<PairWarning>,
    pub motor_rpm: Option<f64>,
    pub output_rpm: Option<f64>,
    pub planetary: Option<PlanetaryProject>,
    pub assumptions: Vec<LocalText>,
}

#[derive(Debug, Clone)]
pub struct PlanetaryProject {
    /// Module, metres.
    pub module: f64,
    pub stage: Stage,
    /// Where u_pl came from: given, or n_motor/n1/u_pair.
    pub ratio_given: bool,
}

const FIELD: &str = "gears";

/// Resolves the section; `crank` is the mechanism's crank speed when there is one.
pub fn resolve(
    spec: &Spanned<GearsSpec>,
    crank: Option<CrankSpeed>,
    warnings: &mut Vec<Warning>,
) -> Result<GearsProject, Refusal> {
    let g = &spec.value;
    let (pair_spec, auto_shift) = pair_spec(&g.pair)?;
    let pair = Pair::new(&pair_spec).map_err(|e| pair_error(&g.pair, e))?;
    let pair_warnings = pair.warnings();
    for w in &pair_warnings {
        // The pair notes an undercut by the course's rule (z_min = 17): below it the undercut
        // is real and worth a warning, unless `auto` chose the shift.
        if let PairWarning::Undercut { wheel, x, x_min, exact } = w
            && !auto_shift[wheel - 1]
        {
            warnings.push(warning(
                at(&g.pair),
                "gears.pair.shift",
                format!(
                    "wheel {wheel} (z = {}) is undercut at x = {} (the course's x_min = {}; exactly {}); the sheet draws the undercut (`shift: auto` avoids it)",
                    pair_spec.z[wheel - 1],
                    written(*x),
                    fixed(*x_min, 4),
                    fixed(*exact, 4)
                ),
            ));
        }
    }
    let motor_rpm = g.motor_rpm.as_ref().map(|n| n.value.0);
    if let (Some(n1), Some(crank)) = (&g.output_rpm, crank) {
        warnings.extend(speeds_differ(n1, crank));
    }
    let output_rpm = g.output_rpm.as_ref().map(|n| n.value.0).or(crank.map(|c| c.rpm));
    let planetary = match &g.planetary {
        Some(p) => Some(planetary_project(p, &pair, motor_rpm, output_rpm, spec.referenced)?),
        None => None,
    };
    let assumptions = text::assumptions(FIELD, &g.assumptions)?;
    Ok(GearsProject { pair, auto_shift, warnings: pair_warnings, motor_rpm, output_rpm, planetary, assumptions })
}

/// `output_rpm` written besides a crank that turns at another speed: sheets 1 and 2 would
/// then compute with different speeds of one machine.
fn speeds_differ(n1: &Spanned<Positive>, crank: CrankSpeed) -> Option<Warning> {
    let (n, c) = (n1.value.0, crank.rpm);
    if (n - c).abs() <= tol::SAME_SPEED * n.abs().max(c.abs()) {
        return None;
    }
    Some(warning(
        at(n1),
        "gears.output_rpm",
        format!(
            "n1 = {} rev/min, but the crank turns at {} rev/min ({}): sheets 1 and 2 then use different speeds; leave `output_rpm` out to take the crank's",
            written(n),
            written(c),
            crank.field
        ),
    ))
}

/// The course's undercut limit h_a*·(z_lim − z)/z_lim, z_lim = ⌊2h_a*/sin²α⌋ (17 for the
/// standard rack).
fn pair_spec(p: &Spanned<PairFileSpec>) -> Result<(PairSpec, [bool; 2]), Refusal> {
    let f = &p.value;
    let module = metres(f.module.value.0);
    let z = [f.z[0].value, f.z[1].value];
    for (i, zi) in f.z.iter().enumerate() {
        if zi.value < 5 {
            return Err(invalid(
                at(zi),
                format!("gears.pair.z[{i}]"),
                format!("{} teeth: a wheel needs at least 5", zi.value),
            ));
        }
        if zi.value > 1000 {
            return Err(invalid(at(zi), format!("gears.pair.z[{i}]"), format!("{} teeth: at most 1000", zi.value)));
        }
    }
    if !(0.05..=100.0).contains(&f.module.value.0) {
        return Err(invalid(at(&f.module), "gears.pair.module", "the module is in millimetres: 0.05…100 mm"));
    }
    let mut spec = PairSpec::standard(module, z);
    if let Some(a) = &f.pressure_angle_deg {
        spec.pressure_angle = a.value.0.to_radians();
    }
    if let Some(h) = &f.addendum {
        spec.addendum = h.value.0;
    }
    if let Some(c) = &f.clearance {
        spec.clearance = c.value.0;
    }
    let mut auto = [false, false];
    match f.shift.as_ref().map(|s| (&s.value, s.referenced)) {
        None => {}
        Some((ShiftSpec::Values([x1, x2]), _)) => spec.shift = [x1.0, x2.0],
        Some((ShiftSpec::Word(w), _)) if w == "auto" => {
            // The course's least shift, rounded up to 0.001 as a drawing states it.
            for i in 0..2 {
                let x_min = spec.x_min_course(z[i]);
                if x_min > 0.0 {
                    spec.shift[i] = (x_min * 1e3).ceil() / 1e3;
                    auto[i] = true;
                }
            }
        }
        Some((ShiftSpec::Word(w), loc)) => {
            return Err(invalid(loc, "gears.pair.shift", format!("'{w}': give [x1, x2] or `auto`")));
        }
    }
    Ok((spec, auto))
}

fn pair_error(p: &Spanned<PairFileSpec>, e: PairError) -> Refusal {
    let f = &p.value;
    let (loc, field, kind): (Location, String, Kind) = match &e {
        PairError::TooFewTeeth { wheel, .. } => {
            (at(&f.z[wheel - 1]), format!("gears.pair.z[{}]", wheel - 1), Kind::Value)
        }
        PairError::Module(_) => (at(&f.module), "gears.pair.module".into(), Kind::Value),
        PairError::Parameter { field, .. } => (p.referenced, field.to_string(), Kind::Value),
        PairError::NoWorkingAngle { .. } | PairError::Pointed { .. } | PairError::NotContinuous { .. } => {
            (f.shift.as_ref().map_or(p.referenced, |s| s.referenced), "gears.pair.shift".into(), Kind::Design)
        }
    };
    invalid(loc, field, e.to_string()).kind(kind)
}

fn planetary_project(
    p: &Spanned<PlanetaryFileSpec>,
    pair: &Pair,
    motor: Option<f64>,
    output: Option<f64>,
    section: Location,
) -> Result<PlanetaryProject, Refusal> {
    let f = &p.value;
    let scheme = Scheme::ALL.into_iter().find(|s| s.key() == f.scheme.value).ok_or_else(|| {
        let known: Vec<&str> = Scheme::ALL.iter().map(|s| s.key()).collect();
        invalid(
            at(&f.scheme),
            "gears.planetary.scheme",
            format!("unknown scheme '{}' (known: {})", f.scheme.value, known.join(", ")),
        )
    })?;
    if !(0.05..=100.0).contains(&f.module.value.0) {
        return Err(invalid(at(&f.module), "gears.planetary.module", "the module is in millimetres: 0.05…100 mm"));
    }
    let (ratio, ratio_given) = stage_ratio(f, pair, motor, output, section)?;
    let ratio_loc = f.ratio.as_ref().map_or(p.referenced, |r| r.referenced);
    let mut spec = StageSpec::course(scheme, ratio);
    if let Some(k) = &f.planets {
        spec.planets = Some(k.value);
    }
    if let Some(t) = &f.tolerance_percent {
        // The course accepts a few percent; beyond half the ratio it would not be a ratio.
        if t.value.0 > TOLERANCE_PERCENT_MAX {
            return Err(invalid(
                t.referenced,
                "gears.planetary.tolerance_percent",
                format!(
                    "{} % is outside 0…{TOLERANCE_PERCENT_MAX} % (the course allows a few percent)",
                    sig(t.value.0, 4)
                ),
            ));
        }
        spec.tolerance = t.value.0 / 100.0;
    }
    let stage = planetary::synthesise(&spec).map_err(|e| {
        let (loc, field) = match &e {
            StageError::BadPlanets { .. } => {
                (f.planets.as_ref().map_or(p.referenced, |k| k.referenced), "gears.planetary.planets")
            }
            _ if f.ratio.is_some() => (ratio_loc, "gears.planetary.ratio"),
            _ => (ratio_loc, "gears.planetary"),
        };
        let kind = if matches!(e, StageError::NoSet { .. }) { Kind::Design } else { Kind::Value };
        // Say where a derived ratio came from: a wrong speed is the usual cause.
        let from = match (ratio_given, motor, output) {
            (false, Some(n_m), Some(n_1)) if !matches!(e, StageError::BadPlanets { .. }) => {
                format!(
                    " (u_pl = n_motor / n1 / u_12 = {} / {} / {} = {})",
                    written(n_m),
                    fixed(n_1, 4),
                    fixed(pair.ratio, 4),
                    fixed(ratio, 4)
                )
            }
            _ => String::new(),
        };
        invalid(loc, field, format!("{e}{from}")).kind(kind)
    })?;
    Ok(PlanetaryProject { module: metres(f.module.value.0), stage, ratio_given })
}

/// The stage's ratio: given as `planetary.ratio`, or derived from the speeds as the course
/// does (u_pl = n_motor / n1 / u_12); `true` when given.
fn stage_ratio(
    f: &PlanetaryFileSpec,
    pair: &Pair,
    motor: Option<f64>,
    output: Option<f64>,
    section: Location,
) -> Result<(f64, bool), Refusal> {
    match (&f.ratio, motor, output) {
        (Some(r), _, _) => Ok((r.value.0, true)),
        (None, Some(n_m), Some(n_1)) => Ok((n_m / n_1 / pair.ratio, false)),
        (None, None, _) => Err(invalid(
            section,
            "gears.motor_rpm",
            "the planetary stage needs its ratio: give `motor_rpm` (and `output_rpm` or a mechanism's crank), or `planetary.ratio`",
        )),
        (None, Some(_), None) => Err(invalid(
            section,
            "gears.output_rpm",
            "the planetary stage needs n1: give `output_rpm`, a mechanism whose crank turns at it, or `planetary.ratio`",
        )),
    }
}
